//! Issue test 4: invalid scenarios are refused before anything runs, with a message that names the
//! file, the field, the value and what is allowed, and exit code 2; never a panic. Plus the control
//! case (a valid file runs with exit 0) and a run stopped by the instability check (exit 1, files kept).
//!
//! The scenarios are the files in `tests/bad_inputs/`, each a valid base case with one thing broken.

use std::path::{Path, PathBuf};
use std::process::Command;

/// (file stem, substrings the error message must contain besides the file name)
const CASES: &[(&str, &[&str])] = &[
    ("courant_above_one", &["field `numerics.courant` = 1.5", "must be in (0, 1]"]),
    ("courant_above_friction_limit", &["field `numerics.courant` = 0.9", "sqrt(1 + z^2) - z = 0.519680"]),
    ("negative_stiffness", &["field `conductor.axial_stiffness_n` = -5", "> 0"]),
    ("zero_density", &["field `conductor.linear_density_kg_per_m` = 0", "> 0"]),
    ("nan_density", &["field `conductor.linear_density_kg_per_m` = NaN", "finite"]),
    ("one_segment", &["field `geometry.segments` = 1", "[2, 10000000]"]),
    ("negative_segments", &["line 9, column 12", "invalid value: integer `-4`"]),
    ("coincident_supports", &["field `geometry.right_support_m` = [0.0, 0.0, 0.0]", "apart"]),
    ("stiffness_twice", &["field `conductor.youngs_modulus_pa`", "not both"]),
    ("stiffness_missing", &["field `conductor.axial_stiffness_n` = (missing)"]),
    ("modulus_without_diameter", &["field `conductor.diameter_m` = (missing)", "youngs_modulus_pa"]),
    ("misspelt_field", &["line 12, column 1", "unknown field `courrant`"]),
    ("syntax_error", &["line 9, column 12"]),
    ("smoothing_too_large", &["field `numerics.smoothing` = 0.5", "[0, 0.25]"]),
    ("mu_out_of_range", &["field `numerics.mu` = 2", "[0, 1]"]),
    ("no_duration", &["field `duration` = (empty)"]),
    ("two_durations", &["field `duration.end_time_s` = 0.5", "not both"]),
    ("settle_fraction_above_one", &["kinetic_energy_fraction` = 2", "(0, 1)"]),
    ("pressure_missing", &["field `loads.wind.pressure_n_per_m` = (missing)"]),
    ("aerodynamic_without_diameter", &["field `conductor.diameter_m` = (missing)", "aerodynamic"]),
    ("zero_wind_direction", &["field `loads.wind.direction` = [0.0, 0.0, 0.0]", "non-zero"]),
    ("parabola_without_sag", &["field `initial.sag_m` = (missing)"]),
    ("negative_sag", &["field `initial.sag_m` = -3", "> 0"]),
    ("unknown_tension_law", &["line 5, column 15", "unknown variant `plastic`"]),
    ("snapshot_after_end", &["field `output.snapshot_times_s[1]` = 3", "end time"]),
    ("negative_sample_interval", &["field `output.sample_interval_s` = -0.1", "> 0"]),
    ("mass_damping_too_large", &["field `numerics.mass_damping_per_s` = 1000000", "zeta dt < 1"]),
    (
        "ground_above_support",
        &["field `ground.height_m` = 5", "below both supports", "field `ground.restitution` = 1.5"],
    ),
    ("event_after_end", &["field `events[0].time_s` = 2", "end time"]),
    ("ice_range_out_of_bounds", &["field `events[0].range` = [0.5, 1.5]", "0 <= a < b <= 1"]),
];

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad_inputs")
}

fn ohl(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_ohl")).args(args).output().expect("run ohl");
    (
        out.status.code().expect("ohl was killed by a signal"),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ohl-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

#[test]
fn every_invalid_scenario_is_refused_with_a_precise_message() {
    assert!(CASES.len() >= 12);
    let out = tmp("bad");
    for (stem, needles) in CASES {
        let file = dir().join(format!("{stem}.toml"));
        let (code, _, err) = ohl(&["run", file.to_str().unwrap(), "--out", out.to_str().unwrap()]);
        assert_eq!(code, 2, "{stem}: exit code {code}, stderr:\n{err}");
        assert!(err.contains(&format!("{stem}.toml")), "{stem}: message does not name the file:\n{err}");
        for n in *needles {
            assert!(err.contains(n), "{stem}: message lacks `{n}`:\n{err}");
        }
        assert!(!err.contains("panicked"), "{stem}: panicked:\n{err}");
        assert!(!out.join("timeseries.csv").exists(), "{stem}: a refused scenario must not start a run");
    }
}

#[test]
fn the_valid_control_case_runs() {
    let out = tmp("valid");
    let file = dir().join("valid.toml");
    let (code, stdout, err) = ohl(&["run", file.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(code, 0, "stderr:\n{err}");
    assert!(stdout.contains("completed"));
    for f in ["timeseries.csv", "snapshots.csv", "summary.json"] {
        assert!(out.join(f).exists(), "{f} missing");
    }
}

#[test]
fn a_missing_file_is_refused_with_exit_code_2() {
    let (code, _, err) = ohl(&["run", "no/such/scenario.toml", "--out", tmp("missing").to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("no/such/scenario.toml") && err.contains("cannot read"), "{err}");
}

#[test]
fn an_instability_stops_the_run_with_time_node_and_reason_and_keeps_the_output() {
    // A free fall under gravity passes 2 m/s after about 0.2 s: with the speed bound set to 2 m/s the
    // run must stop there (exit 1), name the node and the reason, and leave readable files.
    let out = tmp("unstable");
    let text = std::fs::read_to_string(dir().join("valid.toml"))
        .unwrap()
        .replace("courant = 0.9", "courant = 0.9\nmax_speed_m_per_s = 2.0");
    let file = out.with_extension("toml");
    std::fs::write(&file, text).unwrap();
    let (code, _, err) = ohl(&["run", file.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(code, 1, "stderr:\n{err}");
    assert!(err.contains("unstable at t = ") && err.contains("node ") && err.contains("exceeds the bound"), "{err}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["status"], "unstable");
    let t_fail = summary["instability"]["time_s"].as_f64().unwrap();
    // Free fall: v = g t reaches 2 m/s at t = 0.204 s; the first node to exceed it does so within a few
    // steps of that (the mid-span falls freely until the support waves arrive).
    assert!((0.19..0.25).contains(&t_fail), "failed at {t_fail} s");
    let series = std::fs::read_to_string(out.join("timeseries.csv")).unwrap();
    assert!(series.lines().count() >= 4, "time series so far was not kept:\n{series}");
}

#[test]
fn a_heat_case_is_refused_by_run_with_a_pointer_to_paper() {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../paper_cases/heat_two_halves.toml");
    let out = tmp("heat");
    let (code, _, err) = ohl(&["run", file.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(code, 2, "stderr:\n{err}");
    assert!(err.contains("heat_two_halves.toml") && err.contains("`ohl paper heat_two_halves`"), "{err}");
    assert!(!out.exists(), "nothing is written for a refused case");
}
