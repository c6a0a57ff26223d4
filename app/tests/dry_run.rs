//! `ohl run --dry-run`'s time estimate against the measured CPU time of the same run (`cpu_time_s` of
//! `summary.json`: the time loop's thread CPU time, which waiting for a processor does not inflate).
//!
//! The estimate is a cost model with constants measured once (`ohl::scenario::work`: per element for a
//! line, one rate for a single span or section); it must stay within a factor [`FACTOR`] of the run for
//! cases e (a line, clearances), j (a short circuit with a reclose: contact every level, pair forces
//! while current flows) and l (a short circuit with droppers) and for a paper case (fig2b, one span), on
//! shortened copies (the same per-step costs, a test-sized run). Why 3: the model's constants are medians
//! of `ohl bench --costs` on case j's grid on one machine (a Zen 3) and the clearances' share of measured
//! levels is assumed (0.35; the cases measure 0.26-0.51), which leaves these four runs at 0.94-1.27 of the
//! measured time on that machine (figures/bench/README.md, issue 27 third round); the CPU time of one run
//! varied by up to 14 % between repetitions on the shared machine (load 5-9); and a machine of another
//! generation runs the same loops faster: on a Zen 5 (AVX-512) the lines' estimates are 1.5-2.1 times
//! their CPU time, and a single span runs about twice as fast as on the Zen 3, so its rate is the middle
//! of the two machines (`ohl::scenario::work`; fig2b 1.7 times on the Zen 5, about 0.8 on the Zen 3). A
//! factor 3 holds all of that, and still fails the model this replaced (a fixed 1e6 node-steps/s for a
//! short circuit: 3.5 times the shortened case j's time), and the single span's first rate on the Zen 5
//! (3.4).

use std::path::{Path, PathBuf};
use std::process::Command;

/// The largest ratio, either way, between the estimate and the measured CPU time.
const FACTOR: f64 = 3.0;

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_path_buf()
}

fn ohl(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_ohl")).args(args).output().expect("run ohl");
    assert!(out.status.success(), "ohl {args:?}: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The case with its end time replaced, written to a scratch directory; returns its path.
fn shortened(rel: &str, end_time_s: f64, dir: &Path) -> PathBuf {
    let text = std::fs::read_to_string(repo().join(rel)).unwrap();
    let mut done = 0;
    let text: Vec<String> = text
        .lines()
        .map(|l| {
            if l.starts_with("end_time_s") {
                done += 1;
                format!("end_time_s = {end_time_s:?}")
            } else {
                l.to_string()
            }
        })
        .collect();
    assert_eq!(done, 1, "{rel}: one end_time_s");
    let path = dir.join(Path::new(rel).file_name().unwrap());
    std::fs::write(&path, text.join("\n")).unwrap();
    path
}

/// The number after `about` on the estimate's time line.
fn estimated_s(dry_run: &str) -> f64 {
    let line = dry_run
        .lines()
        .find(|l| l.trim_start().starts_with("CPU time: about") || l.trim_start().starts_with("wall time: about"))
        .unwrap_or_else(|| panic!("no time estimate in:\n{dry_run}"));
    let after = line.split("about ").nth(1).unwrap();
    after.split_whitespace().next().unwrap().parse().unwrap()
}

fn measured_cpu_s(out: &Path) -> f64 {
    let s = std::fs::read_to_string(out.join("summary.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&s).unwrap();
    v["cpu_time_s"].as_f64().unwrap()
}

#[test]
fn dry_run_estimates_cpu_time_within_a_factor_of_three() {
    let dir = std::env::temp_dir().join(format!("ohl-test-dry-run-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let mut failures = Vec::new();
    for (rel, end) in [
        ("cases/e_three_phases_wind.toml", 20.0),
        ("cases/j_distribution_reclose.toml", 2.0),
        ("cases/l_slack_droppers_short_circuit.toml", 0.6),
        ("paper_cases/fig2b_catenary.toml", 100.0),
    ] {
        let path = shortened(rel, end, &dir);
        let p = path.to_str().unwrap();
        let estimate = estimated_s(&ohl(&["run", p, "--dry-run"]));
        let out = dir.join(path.file_stem().unwrap());
        ohl(&["run", p, "--out", out.to_str().unwrap(), "--quiet"]);
        let measured = measured_cpu_s(&out);
        let ratio = estimate / measured;
        println!("{rel} to {end} s: estimate {estimate:.3e} s, measured {measured:.3e} s CPU, ratio {ratio:.2}");
        if !(1.0 / FACTOR..=FACTOR).contains(&ratio) {
            failures.push(format!("{rel}: estimate {estimate:.3e} s against {measured:.3e} s (ratio {ratio:.2})"));
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(failures.is_empty(), "estimate off by more than {FACTOR}: {failures:?}");
}
