//! `ohl run --converge` (issue 26): the table's observed order, Richardson extrapolate and GCI on a
//! problem with an exact answer, the refusal of a study above its budget, and the section case's table
//! against the `section_transients` study's numbers.

use std::path::{Path, PathBuf};
use std::process::Command;

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ohl_converge_{name}_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The quantity `path` of `convergence.json`.
fn quantity<'a>(json: &'a serde_json::Value, path: &str) -> &'a serde_json::Value {
    json["quantities"].as_array().unwrap().iter().find(|q| q["path"] == path).unwrap_or_else(|| panic!("{path}"))
}

/// The catenary of paper case fig2b (160 m, 1 kg/m, EA = 792000.54 N) run to rest by dynamic relaxation
/// (mass damping 2 /s: the slowest mode, about 1.2 rad/s, decays at zeta / 2 = 1 /s, so after 150 s the
/// state is e^-150 from rest, far below the discretisation error) on N = 20, 40, 80. The lumped chain is a
/// second-order discretisation with an even error expansion `a h^2 + b h^4` (static study: order 2.000),
/// so the three-grid order is `2 + log2((1 + 20 beta) / (1 + 5 beta))`, `beta = b h_1^2 / a`: the
/// tolerance 0.02 on `p` admits `|beta| <= 9e-4`, a fourth-order part below 0.1 % of the error on the
/// finest grid. The exact elastic catenary (`ohl::exact`) must lie in the extrapolate's own GCI band.
#[test]
fn converge_on_the_settled_catenary_recovers_order_two_and_the_exact_sag() {
    let dir = tmp("catenary");
    let text = std::fs::read_to_string(repo().join("paper_cases/fig2b_catenary.toml")).unwrap();
    let text = text
        .replace("segments = 50", "segments = 20")
        .replace("end_time_s = 260.8", "end_time_s = 150.0")
        .replace("eta_n_s = 316.76", "eta_n_s = 316.76\nmass_damping_per_s = 2.0")
        .replace("sample_interval_s = 0.02", "sample_interval_s = 1.0");
    let file = dir.join("catenary.toml");
    std::fs::write(&file, text).unwrap();
    let out = dir.join("out");
    let o = Command::new(env!("CARGO_BIN_EXE_ohl"))
        .args(["run", file.to_str().unwrap(), "--out", out.to_str().unwrap(), "--converge", "--rtol", "1e-3"])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{stdout}\n{}", String::from_utf8_lossy(&o.stderr));
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("convergence.json")).unwrap()).unwrap();
    let sag = quantity(&json, "final_midspan_displacement_m[2]");
    let e = &sag["estimate"];
    assert_eq!(e["behaviour"], "converging", "{sag}");
    let p = e["order"].as_f64().unwrap();
    assert!((p - 2.0).abs() <= 0.02, "observed order {p}");
    let exact = ohl::exact::catenary::ElasticCatenary::level(160.0, 160.0, 9.81, 792000.54).unwrap();
    let z = exact.midspan_displacement_m()[2];
    let ext = e["extrapolate"].as_f64().unwrap();
    let band = e["gci_fine_abs"].as_f64().unwrap();
    assert!((ext - z).abs() <= band, "extrapolate {ext} exact {z} band {band}");
    // and the fine value itself lies within its band of the exact value (what the GCI claims)
    let fine = sag["values"][2].as_f64().unwrap();
    assert!((fine - z).abs() <= band, "fine {fine} exact {z} band {band}");
    assert_eq!(sag["verdict"], "converged within rtol");
    assert!(stdout.contains("final_midspan_displacement_m[2]"), "{stdout}");
    // the finest level's files are the plain run's, in --out
    assert!(out.join("summary.json").is_file() && out.join("levels").is_dir());
    let _ = std::fs::remove_dir_all(&dir);
}

/// A study whose finest level is above --budget is refused before anything runs, exit 2, with the estimate.
#[test]
fn converge_above_the_budget_is_refused_with_the_estimate() {
    let dir = tmp("budget");
    let o = Command::new(env!("CARGO_BIN_EXE_ohl"))
        .args(["run", "paper_cases/fig2b_catenary.toml", "--out"])
        .arg(dir.join("out"))
        .args(["--converge", "--budget", "1e6"])
        .current_dir(repo())
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    // finest level x4: 200 segments, 4.4947e-4 s; 260.8 s -> 580 240 steps of 201 nodes = 1.166e8
    assert!(
        stderr.contains("paper_cases/fig2b_catenary.toml: --converge: the finest level (x4, 200 segments"),
        "{stderr}"
    );
    assert!(stderr.contains("needs 1.166e8 node-steps") && stderr.contains("above the budget 1.0e6"), "{stderr}");
    assert!(!dir.join("out").exists(), "nothing may run");
    let _ = std::fs::remove_dir_all(&dir);
}
