//! A reader that stops reading (`ohl run CASE.toml | head -1`) changes neither what a command does nor its
//! exit code: each command runs with its stdout a pipe whose reading end is closed before the command
//! writes, and must exit as it does with a terminal (0 here) and write the same files. Before, every
//! command but `ohl sweep` panicked on its first line (exit 101) and left its work unfinished.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ohl-closed-pipe-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

/// Exit code of `ohl ARGS` whose stdout is a pipe nobody reads (its reading end closed at once).
fn closed_stdout(args: &[&str]) -> i32 {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut child = Command::new(env!("CARGO_BIN_EXE_ohl"))
        .args(args)
        .current_dir(root)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("start ohl");
    drop(child.stdout.take());
    child.wait().expect("wait for ohl").code().unwrap_or(-1)
}

#[test]
fn every_command_finishes_its_work_when_its_stdout_is_closed() {
    let run = scratch("run");
    let run_s = run.to_str().unwrap();
    assert_eq!(closed_stdout(&["run", "examples/mechanical/drake_level_400m_wind.toml", "--out", run_s]), 0);
    // The run finished (this example ends when it settles): its summary, written at the end, says so.
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(run.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["status"], "settled", "{summary}");

    let plot = scratch("plot");
    assert_eq!(closed_stdout(&["plot", run_s, "--out", plot.to_str().unwrap()]), 0);
    assert!(plot.join("timeseries.png").exists());

    let paper = scratch("paper");
    assert_eq!(closed_stdout(&["paper", "fig2a_wind_arc", "--out", paper.to_str().unwrap()]), 0);
    assert!(paper.join("fig2a_wind_arc.png").exists());

    let thermal = scratch("thermal");
    assert_eq!(
        closed_stdout(&["thermal", "examples/thermal/drake_annex_b.toml", "--out", thermal.to_str().unwrap()]),
        0
    );
    assert!(thermal.join("thermal.json").exists());

    let bench = scratch("bench");
    assert_eq!(closed_stdout(&["bench", "--no-run", "--out", bench.to_str().unwrap()]), 0);
    assert!(bench.join("current.csv").exists());
}
