//! `ohl sweep`: parameter sweeps of a small single span (10 to 12 segments, 2 s), run through the binary.
//!
//! - a row's values are bitwise those of `ohl run` on the same scenario with the field set by hand, and the
//!   `--keep-runs` summary.json of the case is that run's summary, number for number;
//! - a value that does not fit (out of range, wrong type) is a row `invalid` with the field, the value and
//!   what is allowed; an unstable case is a row `unstable` with its reason; the sweep exits 0;
//! - the shards 0/3, 1/3, 2/3 on one thread, merged, are the unsharded sweep on two threads, bitwise in every
//!   column but the timings; a cases file and `--vary` make one product;
//! - merge refuses tables of different sweeps and lists missing and duplicated cases (exit 2);
//! - malformed arguments exit 2 with a message naming the problem;
//! - a line base (`[line]`, a phase and a twin bundle on a shared tower): a conductor named by its name
//!   (`line.conductors[name=B phase]`) or its index sets the same field; a row's per-conductor columns, least
//!   clearance and largest tower load are bitwise those of `ohl run`'s summary.json on the same scenario
//!   with the fields set by hand; an unknown name, a varied name and one field named twice (by name and by
//!   index) exit 2 naming the file, the field and the names there are.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const BASE: &str = r#"
name = "sweep test span"

[conductor]
axial_stiffness_n = 792000.5
linear_density_kg_per_m = 1.0
diameter_m = 0.01553

[geometry]
left_support_m = [0.0, 0.0, 0.0]
right_support_m = [0.0, 160.0, 0.0]
segments = 10

[initial]
shape = "parabola"
sag_m = 7.0

[loads.wind]
law = "aerodynamic"
speed_m_per_s = 20.0
initial_scale = 0.0

[numerics]
mu = 0.15

[duration]
end_time_s = 2.0

[output]
sample_interval_s = 0.1

[[events]]
time_s = 0.5
action = "wind"
scale = 1.0
"#;

/// The timing columns (differ from run to run).
const TIMINGS: [&str; 3] = ["wall_time_s", "node_steps_per_s", "case_wall_s"];

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ohl_sweep_test_{}_{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn base(d: &Path) -> PathBuf {
    let p = d.join("base.toml");
    std::fs::write(&p, BASE).unwrap();
    p
}

fn ohl(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ohl")).args(args).output().unwrap()
}

fn text(o: &Output) -> String {
    format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr))
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// A table as rows of column name -> cell.
fn table(path: &Path) -> Vec<BTreeMap<String, String>> {
    let mut r = csv::Reader::from_path(path).unwrap();
    let header: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    r.records().map(|rec| header.iter().cloned().zip(rec.unwrap().iter().map(String::from)).collect()).collect()
}

fn bits(cell: &str) -> u64 {
    cell.parse::<f64>().unwrap_or_else(|_| panic!("{cell:?} is not a number")).to_bits()
}

/// Every number of a JSON text by its path (`a.b[2].c`), as written: a minimal reader, so that numbers
/// are compared from their text with Rust's exact parser.
fn json_numbers(text: &str) -> BTreeMap<String, String> {
    fn value(b: &[u8], i: &mut usize, path: String, out: &mut BTreeMap<String, String>) {
        skip(b, i);
        match b[*i] {
            b'{' => {
                *i += 1;
                loop {
                    skip(b, i);
                    if b[*i] == b'}' {
                        *i += 1;
                        return;
                    }
                    let key = string(b, i);
                    skip(b, i);
                    assert_eq!(b[*i], b':');
                    *i += 1;
                    let p = if path.is_empty() { key } else { format!("{path}.{key}") };
                    value(b, i, p, out);
                    skip(b, i);
                    if b[*i] == b',' {
                        *i += 1;
                    }
                }
            }
            b'[' => {
                *i += 1;
                let mut k = 0;
                loop {
                    skip(b, i);
                    if b[*i] == b']' {
                        *i += 1;
                        return;
                    }
                    value(b, i, format!("{path}[{k}]"), out);
                    k += 1;
                    skip(b, i);
                    if b[*i] == b',' {
                        *i += 1;
                    }
                }
            }
            b'"' => {
                string(b, i);
            }
            _ => {
                let start = *i;
                while !matches!(b[*i], b',' | b'}' | b']' | b' ' | b'\n') {
                    *i += 1;
                }
                let token = std::str::from_utf8(&b[start..*i]).unwrap();
                if !matches!(token, "true" | "false" | "null") {
                    out.insert(path, token.to_string());
                }
            }
        }
    }
    fn skip(b: &[u8], i: &mut usize) {
        while b[*i].is_ascii_whitespace() {
            *i += 1;
        }
    }
    fn string(b: &[u8], i: &mut usize) -> String {
        *i += 1;
        let start = *i;
        while b[*i] != b'"' {
            *i += if b[*i] == b'\\' { 2 } else { 1 };
        }
        *i += 1;
        String::from_utf8_lossy(&b[start..*i - 1]).into_owned()
    }
    let mut out = BTreeMap::new();
    value(text.as_bytes(), &mut 0, String::new(), &mut out);
    out
}

/// The summary.json of `ohl run` on `scenario`, by number path.
fn single_run(d: &Path, name: &str, scenario: &str) -> BTreeMap<String, String> {
    let file = d.join(format!("{name}.toml"));
    std::fs::write(&file, scenario).unwrap();
    let out = d.join(name);
    let o = ohl(&["run", s(&file), "--out", s(&out), "--quiet"]);
    assert!(o.status.success(), "{}", text(&o));
    json_numbers(&std::fs::read_to_string(out.join("summary.json")).unwrap())
}

#[test]
fn a_row_is_bitwise_the_single_run_of_its_scenario() {
    let d = dir("single");
    let b = base(&d);
    let out = d.join("sweep");
    let o = ohl(&[
        "sweep",
        s(&b),
        "--vary",
        "loads.wind.speed_m_per_s=10,20.5",
        "--vary",
        "geometry.segments=8:12:2",
        "--out",
        s(&out),
        "--keep-runs",
        "--threads",
        "2",
    ]);
    assert!(o.status.success(), "{}", text(&o));
    assert!(text(&o).contains("6 cases in") && text(&o).contains("cases/s; 6 completed"), "{}", text(&o));
    let rows = table(&out.join("sweep.csv"));
    assert_eq!(rows.len(), 6);
    // case 5: the last of both axes (the last axis varies fastest)
    let row = &rows[5];
    assert_eq!((row["case"].as_str(), row["status"].as_str()), ("5", "completed"));
    assert_eq!((row["loads.wind.speed_m_per_s"].as_str(), row["geometry.segments"].as_str()), ("20.5", "12"));
    let by_hand =
        BASE.replace("speed_m_per_s = 20.0", "speed_m_per_s = 20.5").replace("segments = 10", "segments = 12");
    let run = single_run(&d, "by_hand", &by_hand);
    let k = row["peak_support_force_support"].clone();
    for (column, key) in [
        ("final_time_s", "final_time_s".to_string()),
        ("steps", "steps".into()),
        ("dt_s", "dt_s".into()),
        ("segments", "segments".into()),
        ("peaks_from_s", "peaks_from_s".into()),
        ("peak_max_tension_n", "peak_max_tension_n".into()),
        ("peak_max_tension_time_s", "peak_max_tension_time_s".into()),
        ("peak_mid_dx1_m", "peak_midspan_displacement_m[0].value_m".into()),
        ("peak_mid_dx1_time_s", "peak_midspan_displacement_m[0].time_s".into()),
        ("peak_mid_dx2_m", "peak_midspan_displacement_m[1].value_m".into()),
        ("peak_mid_dx3_m", "peak_midspan_displacement_m[2].value_m".into()),
        ("peak_mid_dx3_time_s", "peak_midspan_displacement_m[2].time_s".into()),
        ("final_mid_dx1_m", "final_midspan_displacement_m[0]".into()),
        ("final_mid_dx2_m", "final_midspan_displacement_m[1]".into()),
        ("final_mid_dx3_m", "final_midspan_displacement_m[2]".into()),
        ("final_max_tension_n", "final_max_tension_n".into()),
        ("final_kinetic_j", "final_kinetic_j".into()),
        ("peak_support_force_n", format!("supports[{k}].peaks.magnitude.value_n")),
        ("peak_support_force_time_s", format!("supports[{k}].peaks.magnitude.time_s")),
    ] {
        assert_eq!(bits(&row[column]), bits(&run[&key]), "{column}: sweep {} and run {}", row[column], run[&key]);
    }
    assert_eq!(row["settled_since_s"], "");
    // The case's own summary.json (--keep-runs) is the single run's, number for number (but the timings).
    let kept = json_numbers(&std::fs::read_to_string(out.join("cases/5/summary.json")).unwrap());
    let timing = |k: &String| {
        ["wall_time_s", "node_steps_per_second", "cpu_time_s", "cpu_node_steps_per_second"].contains(&k.as_str())
    };
    assert_eq!(kept.keys().collect::<Vec<_>>(), run.keys().collect::<Vec<_>>());
    for (key, v) in kept.iter().filter(|(k, _)| !timing(k)) {
        assert_eq!(bits(v), bits(&run[key]), "{key}");
    }
    // and its scenario.toml runs to the same numbers
    let again = single_run(&d, "kept", &std::fs::read_to_string(out.join("cases/5/scenario.toml")).unwrap());
    for (key, v) in again.iter().filter(|(k, _)| !timing(k)) {
        assert_eq!(bits(v), bits(&run[key]), "{key}");
    }
    // integers stay integers: the kept scenario says segments = 12, not 12.0
    assert!(std::fs::read_to_string(out.join("cases/5/scenario.toml")).unwrap().contains("segments = 12\n"));
    assert!(!out.join("cases/6").exists());
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_temperature_varied_in_celsius_is_the_run_with_the_kelvin_value() {
    // Issue 23: `--vary conductor.reference_temperature_c=...` on a base that gives the temperature in
    // kelvin replaces it; each row is bitwise the single run of the scenario with the kelvin value written
    // by hand (-20 C = 253.15 K, 40 C = 313.15 K: the conversion gives the decimal kelvin values exactly).
    // A heating event to 300 K makes the reference temperature matter (thermal strain (5.5)).
    let d = dir("celsius");
    let warm = BASE.replace(
        "diameter_m = 0.01553",
        "diameter_m = 0.01553\nthermal_expansion_per_k = 23.8e-6\nreference_temperature_k = 288.15",
    ) + "\n[[events]]\ntime_s = 1.0\naction = \"temperature\"\ntemperature_k = 300.0\nrange = [0.0, 1.0]\n";
    let b = d.join("base.toml");
    std::fs::write(&b, &warm).unwrap();
    let out = d.join("sweep");
    let o = ohl(&["sweep", s(&b), "--vary", "conductor.reference_temperature_c=-20,40", "--out", s(&out)]);
    assert!(o.status.success(), "{}", text(&o));
    let rows = table(&out.join("sweep.csv"));
    assert_eq!(rows.len(), 2);
    for (row, kelvin) in rows.iter().zip(["253.15", "313.15"]) {
        assert_eq!(row["status"], "completed", "{row:?}");
        let by_hand = warm.replace("reference_temperature_k = 288.15", &format!("reference_temperature_k = {kelvin}"));
        let run = single_run(&d, &format!("k{kelvin}"), &by_hand);
        for (column, key) in
            [("final_max_tension_n", "final_max_tension_n"), ("peak_max_tension_n", "peak_max_tension_n")]
        {
            assert_eq!(
                bits(&row[column]),
                bits(&run[key]),
                "{kelvin} K, {column}: sweep {} and run {}",
                row[column],
                run[key]
            );
        }
    }
    assert_ne!(rows[0]["final_max_tension_n"], rows[1]["final_max_tension_n"], "the temperature matters");
}

#[test]
fn bad_values_and_unstable_runs_are_rows_with_their_reason() {
    let d = dir("bad");
    let b = base(&d);
    let out = d.join("sweep");
    let o = ohl(&[
        "sweep",
        s(&b),
        "--vary",
        "loads.wind.speed_m_per_s=20,500,fast",
        "--vary",
        "geometry.segments=10,12.5",
        "--vary",
        "numerics.max_speed_m_per_s=1000,0.01",
        "--out",
        s(&out),
    ]);
    assert!(o.status.success(), "exit 0 even with invalid cases: {}", text(&o));
    assert!(text(&o).contains("12 cases in"), "{}", text(&o));
    assert!(
        text(&o).contains("1 completed, 1 unstable, 10 invalid (see the status and reason columns)"),
        "{}",
        text(&o)
    );
    let rows = table(&out.join("sweep.csv"));
    let reason = |id: usize| (rows[id]["status"].as_str(), rows[id]["reason"].as_str());
    assert_eq!(reason(0), ("completed", ""));
    // max_speed 0.01 m/s: the first node faster than that stops the run
    let (status, why) = reason(1);
    assert_eq!(status, "unstable");
    assert!(why.contains("0.01"), "{why}");
    assert!(!rows[1]["final_time_s"].is_empty(), "an unstable row has the values up to the failure");
    let (status, why) = reason(2);
    assert_eq!(status, "invalid");
    assert_eq!(
        why,
        "field `geometry.segments` = 12.5 is not allowed: expected a whole number (the base file has one here)"
    );
    let (status, why) = reason(4);
    assert_eq!(status, "invalid");
    assert!(why.contains("field `loads.wind.speed_m_per_s` = 500 is not allowed") && why.contains("[0, 100]"), "{why}");
    assert_eq!(rows[4]["final_time_s"], "");
    let (_, why) = reason(8);
    assert!(why.contains("field `loads.wind.speed_m_per_s` = fast is not allowed: expected a number"), "{why}");
    std::fs::remove_dir_all(&d).unwrap();
}

/// Every column but the timings.
fn without_timings(rows: Vec<BTreeMap<String, String>>) -> Vec<BTreeMap<String, String>> {
    rows.into_iter()
        .map(|mut r| {
            TIMINGS.iter().for_each(|t| assert!(r.remove(*t).is_some()));
            r
        })
        .collect()
}

#[test]
fn shards_merged_are_the_whole_sweep_and_merge_checks_its_inputs() {
    let d = dir("shards");
    let b = base(&d);
    let cases = d.join("cases.csv");
    std::fs::write(&cases, "# mu and the event time, together\nnumerics.mu,events[0].time_s\n0.15,\n0.5,1.0\n")
        .unwrap();
    let vary = ["--cases", s(&cases), "--vary", "loads.wind.speed_m_per_s=10:14:2"];
    let whole = d.join("whole");
    let o = ohl(&[&["sweep", s(&b)], &vary[..], &["--out", s(&whole), "--threads", "2", "--quiet"]].concat());
    assert!(o.status.success(), "{}", text(&o));
    let rows = table(&whole.join("sweep.csv"));
    assert_eq!(rows.len(), 6);
    assert_eq!((rows[4]["numerics.mu"].as_str(), rows[4]["events[0].time_s"].as_str()), ("0.5", "1.0"));
    assert_eq!(rows[4]["loads.wind.speed_m_per_s"], "12");
    assert_eq!((rows[1]["events[0].time_s"].as_str(), rows[1]["peaks_from_s"].as_str()), ("", "0.5"));
    assert_eq!(rows[4]["peaks_from_s"], "1.0");

    let parts = d.join("parts");
    for k in 0..3 {
        let shard = format!("{k}/3");
        let o =
            ohl(&[&["sweep", s(&b)], &vary[..], &["--out", s(&parts), "--shard", &shard, "--threads", "1"]].concat());
        assert!(o.status.success(), "{}", text(&o));
        assert!(text(&o).contains(&format!("shard {k}/3: 2 of 6 cases")), "{}", text(&o));
        assert!(parts.join(format!("sweep.{k}-of-3.csv")).exists());
    }
    let o = ohl(&["sweep", "merge", s(&parts)]);
    assert!(o.status.success(), "{}", text(&o));
    assert!(text(&o).contains("merged 3 tables: 6 cases (6 completed)"), "{}", text(&o));
    let merged = table(&parts.join("sweep.csv"));
    assert_eq!(without_timings(merged), without_timings(rows));
    let manifest = std::fs::read_to_string(parts.join("sweep.json")).unwrap();
    assert!(manifest.contains("\"shard\": null") && manifest.contains("merged_from"), "{manifest}");

    // a missing shard: its cases are listed
    let two = d.join("two");
    std::fs::create_dir_all(&two).unwrap();
    for k in [0, 2] {
        for ext in ["csv", "json"] {
            let name = format!("sweep.{k}-of-3.{ext}");
            std::fs::copy(parts.join(&name), two.join(&name)).unwrap();
        }
    }
    let o = ohl(&["sweep", "merge", s(&two)]);
    assert_eq!(o.status.code(), Some(2), "{}", text(&o));
    assert!(
        text(&o).contains("2 of the sweep's 6 cases are in no table (run their shards, then merge again): 1, 4"),
        "{}",
        text(&o)
    );

    // a duplicated table
    let o = ohl(&["sweep", "merge", s(&parts), s(&parts.join("sweep.1-of-3.csv")), "--out", s(&d.join("dup"))]);
    assert_eq!(o.status.code(), Some(2), "{}", text(&o));
    assert!(text(&o).contains("2 cases are in more than one row: case 1 in"), "{}", text(&o));

    // a shard of another sweep (other values) in its place
    let other = d.join("other");
    let o = ohl(&[
        &["sweep", s(&b), "--cases", s(&cases), "--vary", "loads.wind.speed_m_per_s=10:16:3"][..],
        &["--out", s(&other), "--shard", "1/3", "--quiet"],
    ]
    .concat());
    assert!(o.status.success(), "{}", text(&o));
    for ext in ["csv", "json"] {
        let name = format!("sweep.1-of-3.{ext}");
        std::fs::copy(other.join(&name), two.join(&name)).unwrap();
    }
    let o = ohl(&["sweep", "merge", s(&two)]);
    assert_eq!(o.status.code(), Some(2), "{}", text(&o));
    assert!(
        text(&o).contains("are not tables of the same sweep; they differ in: varied fields and values"),
        "{}",
        text(&o)
    );
    // a shard of a sweep of another base file
    std::fs::write(&b, BASE.replace("sag_m = 7.0", "sag_m = 6.0")).unwrap();
    let o = ohl(&[&["sweep", s(&b)], &vary[..], &["--out", s(&other), "--shard", "1/3", "--quiet"]].concat());
    assert!(o.status.success(), "{}", text(&o));
    for ext in ["csv", "json"] {
        let name = format!("sweep.1-of-3.{ext}");
        std::fs::copy(other.join(&name), two.join(&name)).unwrap();
    }
    let o = ohl(&["sweep", "merge", s(&two)]);
    assert_eq!(o.status.code(), Some(2), "{}", text(&o));
    assert!(text(&o).contains("the base scenarios differ"), "{}", text(&o));
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn bad_arguments_exit_2_with_the_reason() {
    let d = dir("args");
    let b = base(&d);
    let out = d.join("out");
    for (args, expected) in [
        (vec!["--vary", "numerics.mu=0.1", "--shard", "3/3"], "--shard 3/3: K counts from 0 and must be below N"),
        (
            vec!["--vary", "loads.wind.speed=10"],
            "field `loads.wind.speed`: the base file does not set it and the scenario format has no such field",
        ),
        (vec!["--vary", "ground.height_m=-20"], "field `ground.height_m`: the base file has no `ground`"),
        (vec!["--vary", "events[1].time_s=1"], "index 1 is beyond `events`, which has 1 entry, index 0"),
        (vec!["--vary", "numerics.mu=0:1"], "a range is START:STOP:STEP (three numbers)"),
        (vec!["--vary", "numerics.mu"], "expected FIELD=VALUES"),
        (vec!["--vary", "numerics.mu=1", "--vary", "numerics.mu=2"], "are both varied"),
        (vec![], "nothing to vary"),
        (vec!["--cases", "no_such_cases.csv"], "no_such_cases.csv: cannot read the cases file"),
    ] {
        let o = ohl(&[&["sweep", s(&b), "--out", s(&out)][..], &args].concat());
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", text(&o));
        assert!(text(&o).contains(expected), "{args:?}: {}", text(&o));
        assert!(!text(&o).contains("panicked"), "{}", text(&o));
    }
    assert!(!out.join("sweep.csv").exists());
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn the_example_sweep_runs() {
    let d = dir("example");
    let repo = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let base = repo.join("examples/sweep/drake_400m_wind.toml");
    let cases = repo.join("examples/sweep/cases.csv");
    // 6 s instead of 60: the example's cases, shortened
    let o = ohl(&["sweep", s(&base), "--cases", s(&cases), "--vary", "duration.end_time_s=6", "--out", s(&d)]);
    assert!(o.status.success(), "{}", text(&o));
    assert!(text(&o).contains("5 cases in") && text(&o).contains("5 completed"), "{}", text(&o));
    let rows = table(&d.join("sweep.csv"));
    assert_eq!(rows[4]["events[0].time_s"], "5");
    assert_eq!(rows[4]["peaks_from_s"], "5.0", "the peaks count from the (first) event");
    assert_eq!(rows[0]["peaks_from_s"], "1.0");
    std::fs::remove_dir_all(&d).unwrap();
}

/// Issue 23: a wind sweep from still air (0 m/s is allowed). The example's wind, switched on at once at
/// 1 s, overshoots at 35 m/s (its peak tension in the first swing is 1.49 times the end value): the
/// `start_up_peak` column says `yes` and the sweep warns on stderr with the case id; at 0 m/s nothing
/// moves (`no`). Started from the equilibrium under the wind (`initial_scale = 1`, the event then
/// changes nothing) there is no onset (an empty cell) and every peak tension is the tension at the end to
/// 1e-9 relative (the run stays at rest: `tests/equilibrium.rs` bounds the drift by the static solve's
/// residual, ~1e-11 relative here).
#[test]
fn a_wind_sweep_from_still_air_flags_the_start_up_peaks() {
    let d = dir("still_air");
    let base = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/sweep/drake_400m_wind.toml");
    let speeds = "loads.wind.speed_m_per_s=0,35";
    let o = ohl(&["sweep", s(&base), "--vary", speeds, "--vary", "duration.end_time_s=20", "--out", s(&d)]);
    assert!(o.status.success(), "{}", text(&o));
    assert!(text(&o).contains("warning: case(s) 1 have a peak from the wind's onset"), "{}", text(&o));
    let rows = table(&d.join("sweep.csv"));
    assert_eq!((rows[0]["start_up_peak"].as_str(), rows[1]["start_up_peak"].as_str()), ("no", "yes"));
    let e = dir("still_air_eq");
    let o = ohl(&[
        "sweep",
        s(&base),
        "--vary",
        speeds,
        "--vary",
        "loads.wind.initial_scale=1",
        "--vary",
        "events[0].scale=1",
        "--vary",
        "duration.end_time_s=20",
        "--out",
        s(&e),
    ]);
    assert!(o.status.success() && !text(&o).contains("warning"), "{}", text(&o));
    for r in table(&e.join("sweep.csv")) {
        assert_eq!(r["start_up_peak"], "");
        let (peak, end): (f64, f64) =
            (r["peak_max_tension_n"].parse().unwrap(), r["final_max_tension_n"].parse().unwrap());
        assert!((peak - end).abs() < 1e-9 * end, "{peak} vs {end}");
    }
    std::fs::remove_dir_all(&d).unwrap();
    std::fs::remove_dir_all(&e).unwrap();
}

const LINE_BASE: &str = r#"
name = "sweep test line"

[line]
towers = [{ name = "T", position_m = [0.0, 380.0, 30.0] }]

[[line.conductors]]
name = "A"
conductor = { axial_stiffness_n = 2.9e7, linear_density_kg_per_m = 1.628, diameter_m = 0.0281 }
towers = ["", "T", ""]
section = { horizontal_tension_n = 28000.0, segments_per_span = 12, supports = [
  { kind = "dead_end", point_m = [-4.0, 0.0, 26.5] },
  { kind = "suspension", pivot_m = [-4.0, 380.0, 30.0], insulator_length_m = 3.5, insulator_mass_kg = 100.0, insulator_stiffness_n = 5.0e7 },
  { kind = "dead_end", point_m = [-4.0, 800.0, 28.0] } ] }

[[line.conductors]]
name = "B phase"
conductor = { axial_stiffness_n = 2.9e7, linear_density_kg_per_m = 1.628, diameter_m = 0.0281 }
towers = ["", "T", ""]
section = { horizontal_tension_n = 27000.0, segments_per_span = 12, supports = [
  { kind = "dead_end", point_m = [4.0, 0.0, 26.5] },
  { kind = "suspension", pivot_m = [4.0, 380.0, 30.0], insulator_length_m = 3.5, insulator_mass_kg = 100.0, insulator_stiffness_n = 5.0e7 },
  { kind = "dead_end", point_m = [4.0, 800.0, 28.0] } ] }
bundle = { sub_conductors = 2, diameter_m = 0.4, spacers = [{ span = 0, at_fraction = 0.5 }, { span = 1, at_fraction = 0.5 }] }

[loads.wind]
law = "aerodynamic"
direction = [1.0, 0.0, 0.0]
speed_m_per_s = 20.0
initial_scale = 0.0

[numerics]
courant = 0.5
smoothing = 0.01
eta_n_s = 5000.0
mu = 1.0

[duration]
end_time_s = 1.0

[output]
sample_interval_s = 0.1

[[events]]
time_s = 0.3
action = "wind"
scale = 1.0
"#;

/// The line's conductors in the order of its summary (the file's order, a bundle's sub-conductors each)
/// and their column prefixes.
const LINE_CONDUCTORS: [&str; 3] = ["A", "B_phase.1", "B_phase.2"];

#[test]
fn a_line_row_is_bitwise_the_run_summary_of_its_scenario() {
    let d = dir("line");
    let b = d.join("line.toml");
    std::fs::write(&b, LINE_BASE).unwrap();
    let out = d.join("sweep");
    let tension = "line.conductors[name=B phase].section.horizontal_tension_n";
    let o = ohl(&[
        "sweep",
        s(&b),
        "--vary",
        &format!("{tension}=26000,30000"),
        "--vary",
        "loads.wind.speed_m_per_s=20,25.5",
        "--out",
        s(&out),
        "--keep-runs",
        "--threads",
        "2",
    ]);
    assert!(o.status.success(), "{}", text(&o));
    assert!(text(&o).contains("4 cases in") && text(&o).contains("4 completed"), "{}", text(&o));
    let rows = table(&out.join("sweep.csv"));
    let row = &rows[3];
    assert_eq!((row[tension].as_str(), row["loads.wind.speed_m_per_s"].as_str()), ("30000", "25.5"));
    let by_hand = LINE_BASE
        .replace("horizontal_tension_n = 27000.0", "horizontal_tension_n = 30000.0")
        .replace("speed_m_per_s = 20.0", "speed_m_per_s = 25.5");
    let run = single_run(&d, "by_hand", &by_hand);
    let mut compared = 0;
    for (column, key) in [("final_time_s", "final_time_s"), ("steps", "steps"), ("dt_s", "dt_s")] {
        assert_eq!(bits(&row[column]), bits(&run[key]), "{column}");
        compared += 1;
    }
    for (i, c) in LINE_CONDUCTORS.iter().enumerate() {
        let mut pairs = vec![
            ("peak_max_tension_n".to_string(), "peak_max_tension_n".to_string()),
            ("peak_max_tension_time_s".into(), "peak_max_tension_time_s".into()),
            ("final_max_tension_n".into(), "final_max_tension_n".into()),
        ];
        for k in 0..3 {
            pairs.push((format!("peak_mid_dx{}_m", k + 1), format!("peak_midspan_displacement_m[{k}].value_m")));
            pairs.push((format!("peak_mid_dx{}_time_s", k + 1), format!("peak_midspan_displacement_m[{k}].time_s")));
            pairs.push((format!("final_mid_dx{}_m", k + 1), format!("final_midspan_displacement_m[{k}]")));
        }
        for (column, key) in pairs {
            let (column, key) = (format!("{c}_{column}"), format!("conductors[{i}].{key}"));
            assert_eq!(bits(&row[&column]), bits(&run[&key]), "{column}: sweep {} and run {}", row[&column], run[&key]);
            compared += 1;
        }
    }
    // The least clearance: the least over the pairs of summary.json (here the one pair, A and B phase).
    let number = |v: &String| v.parse::<f64>().unwrap();
    let leasts = run.iter().filter(|(p, _)| p.starts_with("clearances[") && p.ends_with(".least_m"));
    let (key, value) = leasts.min_by(|a, b| number(a.1).total_cmp(&number(b.1))).unwrap();
    assert_eq!(bits(&row["least_clearance_m"]), bits(value));
    let at = key.replace(".least_m", ".time_s");
    assert_eq!(bits(&row["least_clearance_time_s"]), bits(&run[&at]));
    assert_eq!(row["least_clearance_between"], "A - B phase");
    // The largest tower load: the largest peak over the towers (here the one tower, T).
    let peaks = run.iter().filter(|(p, _)| p.starts_with("towers[") && p.ends_with(".peak_force_magnitude_n"));
    let (key, value) = peaks.max_by(|a, b| number(a.1).total_cmp(&number(b.1))).unwrap();
    assert_eq!(bits(&row["peak_tower_force_n"]), bits(value));
    assert_eq!(bits(&row["peak_tower_force_time_s"]), bits(&run[&key.replace("magnitude_n", "time_s")]));
    assert_eq!(row["peak_tower_force_tower"], "T");
    println!(
        "case 3: {compared} columns bitwise those of ohl run, least clearance {} m, tower load {} N",
        row["least_clearance_m"], row["peak_tower_force_n"]
    );
    // The case's own summary.json (--keep-runs) is the run's, number for number (but the timings).
    let kept = json_numbers(&std::fs::read_to_string(out.join("cases/3/summary.json")).unwrap());
    let timing = |k: &String| {
        ["wall_time_s", "node_steps_per_second", "cpu_time_s", "cpu_node_steps_per_second"].contains(&k.as_str())
    };
    assert_eq!(kept.keys().collect::<Vec<_>>(), run.keys().collect::<Vec<_>>());
    for (key, v) in kept.iter().filter(|(k, _)| !timing(k)) {
        assert_eq!(bits(v), bits(&run[key]), "{key}");
    }
    assert!(out.join("cases/3/conductors/B_phase.2/timeseries.csv").exists());

    // The same conductor by its index, from a cases file: the same row (but the field's column name and the
    // timings).
    let cases = d.join("cases.csv");
    std::fs::write(&cases, "line.conductors[1].section.horizontal_tension_n,loads.wind.speed_m_per_s\n30000,25.5\n")
        .unwrap();
    let by_index = d.join("by_index");
    let o = ohl(&["sweep", s(&b), "--cases", s(&cases), "--out", s(&by_index), "--quiet"]);
    assert!(o.status.success(), "{}", text(&o));
    let mut again = table(&by_index.join("sweep.csv")).remove(0);
    let mut row = row.clone();
    again.remove("line.conductors[1].section.horizontal_tension_n");
    row.remove(tension);
    row.insert("case".into(), "0".into());
    assert_eq!(without_timings(vec![again]), without_timings(vec![row]));
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_line_base_refuses_unknown_names_varied_names_and_a_field_named_twice() {
    let d = dir("line_args");
    let b = d.join("line.toml");
    std::fs::write(&b, LINE_BASE).unwrap();
    let out = d.join("out");
    for (args, expected) in [
        (
            vec!["--vary", "line.conductors[name=C].section.horizontal_tension_n=26000"],
            "line.toml: field `line.conductors[name=C].section.horizontal_tension_n`: no entry of `line.conductors` \
             is named \"C\": its names in the base file are \"A\", \"B phase\"",
        ),
        (
            vec!["--vary", "line.towers[name=T9].position_m[2]=31"],
            "no entry of `line.towers` is named \"T9\": its names in the base file are \"T\"",
        ),
        (
            vec!["--vary", "line.conductors[0].name=X,Y"],
            "field `line.conductors[0].name`: sets `line.conductors[0].name`, which names the table's columns",
        ),
        (
            vec!["--vary", "line.conductors[name=B phase].bundle.sub_conductors=3"],
            "sets `line.conductors[1].bundle.sub_conductors`, which names the table's columns",
        ),
        (
            vec![
                "--vary",
                "line.conductors[name=A].section.segments_per_span=10",
                "--vary",
                "line.conductors[0].section=1",
            ],
            "field `line.conductors[0].section`: is `line.conductors[0].section` in the base file, and field \
             `line.conductors[name=A].section.segments_per_span` is `line.conductors[0].section.segments_per_span`",
        ),
        (
            vec!["--vary", "line.conductors[name=A].section.segments_per_spam=10"],
            "the base file does not set it and the scenario format has no such field (field \
             `line.conductors[0].section.segments_per_spam`: unknown field `segments_per_spam`",
        ),
        (
            vec!["--vary", "line.conductors[nom=A].x=1"],
            "index [nom=A] is not a whole number >= 0 (nor a name, [name=NAME])",
        ),
    ] {
        let o = ohl(&[&["sweep", s(&b), "--out", s(&out)][..], &args].concat());
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", text(&o));
        assert!(text(&o).contains(expected), "{args:?}: {}", text(&o));
        assert!(!text(&o).contains("panicked"), "{}", text(&o));
    }
    assert!(!out.join("sweep.csv").exists());
    std::fs::remove_dir_all(&d).unwrap();
}
