//! `ohl plot RUN_DIR` draws a run's figures: a small two-span section (wind across the line, a
//! `[thermal]` table, a named probe, snapshots, a break) is run with `ohl run`, then plotted. The PNG
//! and SVG files of the time series, support forces and shapes exist and are valid (PNG signature, SVG
//! with the axis labels and the scenario's name); `--out`, `--from` and `--to` work; a folder that is not a
//! run, a missing folder and an empty window are refused with exit code 2 and a message naming the
//! problem, never a panic; a run without `summary.json` (killed) is still drawn.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const SCENARIO: &str = r#"
name = "two-span test section"

[conductor]
axial_stiffness_n = 2.9e7
linear_density_kg_per_m = 1.628
diameter_m = 0.0281
thermal_expansion_per_k = 1.89e-5
reference_temperature_k = 288.15

[initial]
shape = "equilibrium"

[section]
horizontal_tension_n = 28000.0
segments_per_span = 10
supports = [
  { kind = "dead_end", point_m = [0.0, 0.0, 30.0] },
  { kind = "suspension", pivot_m = [0.0, 300.0, 33.5], insulator_length_m = 3.5, insulator_mass_kg = 100.0, insulator_stiffness_n = 5.0e7 },
  { kind = "dead_end", point_m = [0.0, 600.0, 30.0] },
]

[loads.wind]
law = "aerodynamic"
speed_m_per_s = 15.0

[duration]
end_time_s = 3.0

[output]
sample_interval_s = 0.01
snapshot_times_s = [0.5, 1.0, 2.0]
probes = [{ name = "quarter", at_fraction = 0.25 }]

[thermal]
standard = "ieee738"
conductor = "ACSR Drake"
current_a = [[0.0, 1500.0]]
[thermal.weather]
air_temperature_k = 298.15
wind_speed_m_per_s = 2.0
wind_angle_deg = 90.0

[[events]]
time_s = 1.0
action = "break"
span = 1
at_fraction = 0.5
"#;

fn ohl(args: &[&std::ffi::OsStr]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ohl")).args(args).output().unwrap()
}

fn text(o: &Output) -> String {
    format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr))
}

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ohl-plot-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The run folder of [`SCENARIO`].
fn run(dir: &Path) -> PathBuf {
    let file = dir.join("small.toml");
    std::fs::write(&file, SCENARIO).unwrap();
    let out = dir.join("run");
    let o = ohl(&["run".as_ref(), file.as_os_str(), "--out".as_ref(), out.as_os_str(), "--quiet".as_ref()]);
    assert!(o.status.success(), "ohl run: {}", text(&o));
    out
}

fn assert_png(path: &Path) {
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert!(bytes.starts_with(b"\x89PNG\r\n\x1a\n"), "{} is not a PNG", path.display());
    assert!(bytes.len() > 10_000, "{}: {} bytes", path.display(), bytes.len());
}

fn svg(path: &Path, labels: &[&str]) {
    let s = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert!(s.starts_with("<svg") && s.trim_end().ends_with("</svg>"), "{} is not an SVG", path.display());
    for l in labels {
        assert!(s.contains(l), "{} lacks {l:?}", path.display());
    }
}

#[test]
fn plots_a_section_run_and_refuses_what_is_not_a_run() {
    let dir = scratch("section");
    let run_dir = run(&dir);
    let o = ohl(&["plot".as_ref(), run_dir.as_os_str()]);
    println!("{}", text(&o));
    assert!(o.status.success(), "ohl plot: {}", text(&o));
    let plots = run_dir.join("plots");
    for name in ["timeseries", "reactions", "shapes"] {
        assert_png(&plots.join(format!("{name}.png")));
        assert!(text(&o).contains(&format!("{name}.svg")), "the files are listed");
    }
    let name = "two-span test section (ACSR Drake)";
    svg(
        &plots.join("timeseries.svg"),
        &[name, "t [s]", "dx3 [m]", "dx1 [m]", "T_max [kN]", "E - E(t0) [kJ]", "T_c [°C]", "span 1", "quarter"],
    );
    // The energy balance from the first sample, and the transient's detail: the break at t = 1 s
    // (`peaks_from_s`) to 1 + 0.15 (3 - 1) = 1.3 s (DETAIL_FRACTION of the rest of the run).
    svg(
        &plots.join("timeseries.svg"),
        &[
            "energy balance from t = 0 s",
            "dissipated, -(total change)",
            "vertical displacement from the chord, t = 1 to 1.3 s",
        ],
    );
    svg(&plots.join("reactions.svg"), &[name, "t [s]", "F3 [kN]", "F2 [kN]", "F1 [kN]", "swing from plumb [deg]"]);
    svg(&plots.join("shapes.svg"), &[name, "x2, along the line [m]", "x3, height [m]", "x1, across the line [m]"]);

    // --out and a time window.
    let other = dir.join("figures");
    let o = ohl(&[
        "plot".as_ref(),
        run_dir.as_os_str(),
        "--out".as_ref(),
        other.as_os_str(),
        "--from".as_ref(),
        "0.5".as_ref(),
        "--to".as_ref(),
        "2".as_ref(),
        "--quiet".as_ref(),
    ]);
    assert!(o.status.success(), "{}", text(&o));
    for name in ["timeseries", "reactions", "shapes"] {
        assert_png(&other.join(format!("{name}.png")));
        let axis = if name == "shapes" { "x2, along the line [m]" } else { "t [s]" };
        svg(&other.join(format!("{name}.svg")), &[axis]);
    }
    // A window of the user's: no detail panel; the energy balance starts at the window's first sample.
    let series = std::fs::read_to_string(other.join("timeseries.svg")).unwrap();
    assert!(!series.contains(", t = 1 to 1.3 s"), "a detail panel inside a window of the user's");
    // (the first sample at or after 0.5 s: the step of 5.15e-3 s lands at 0.5052 s)
    svg(&other.join("timeseries.svg"), &["energy balance from t = 0.505"]);
    // The snapshot at t = 1 s (an event lands the clock on it) is in the window, the final one is not.
    svg(&other.join("shapes.svg"), &["t = 1 s"]);
    assert!(!std::fs::read_to_string(other.join("shapes.svg")).unwrap().contains("t = 3 s"));

    // A window with no sample, and one that is not a window.
    let o = ohl(&["plot".as_ref(), run_dir.as_os_str(), "--from".as_ref(), "50".as_ref()]);
    assert_eq!(o.status.code(), Some(2), "{}", text(&o));
    assert!(text(&o).contains("no sample from t = 50 s on"), "{}", text(&o));
    let o =
        ohl(&["plot".as_ref(), run_dir.as_os_str(), "--from".as_ref(), "2".as_ref(), "--to".as_ref(), "1".as_ref()]);
    assert_eq!(o.status.code(), Some(2), "{}", text(&o));

    // Not a run folder: the message names the missing file.
    let empty = scratch("empty");
    let o = ohl(&["plot".as_ref(), empty.as_os_str()]);
    assert_eq!(o.status.code(), Some(2), "{}", text(&o));
    let msg = text(&o);
    assert!(msg.contains("is not a run folder") && msg.contains("timeseries.csv is missing"), "{msg}");
    assert!(!msg.contains("panicked"), "{msg}");
    let o = ohl(&["plot".as_ref(), empty.join("nowhere").as_os_str()]);
    assert_eq!(o.status.code(), Some(2), "{}", text(&o));
    assert!(text(&o).contains("not a folder"), "{}", text(&o));
    // A timeseries.csv that is not one of `ohl run`.
    std::fs::write(empty.join("timeseries.csv"), "a,b\n1,x\n").unwrap();
    let o = ohl(&["plot".as_ref(), empty.as_os_str()]);
    assert_eq!(o.status.code(), Some(2), "{}", text(&o));
    assert!(text(&o).contains("timeseries.csv"), "{}", text(&o));

    // A killed run (no summary.json, no snapshots) is still drawn, titled after its folder.
    let killed = dir.join("killed");
    std::fs::create_dir_all(&killed).unwrap();
    std::fs::copy(run_dir.join("timeseries.csv"), killed.join("timeseries.csv")).unwrap();
    let o = ohl(&["plot".as_ref(), killed.as_os_str(), "--quiet".as_ref()]);
    assert!(o.status.success(), "{}", text(&o));
    assert!(text(&o).contains("summary.json is missing") && text(&o).contains("no shapes figure"), "{}", text(&o));
    svg(&killed.join("plots/timeseries.svg"), &["killed: vertical displacement"]);
    assert!(!killed.join("plots/shapes.png").exists());
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&empty);
}
