//! A run killed with SIGKILL at any moment leaves output files that parse: CSVs of whole rows, and
//! either a whole `summary.json` or none (issue 9). Rows reach the files one page at a time, each page
//! in a write the kernel completes or drops whole (`ohl::output::rows`).

use std::path::Path;
use std::process::Command;
use std::time::Duration;

/// 2000 segments, a snapshot (2001 rows) every 0.4 ms of simulated time, i.e. about every 5 steps: the
/// run spends most of its time writing snapshots, so a kill lands inside or between writes.
const SCENARIO: &str = r#"
[conductor]
axial_stiffness_n = 792000.54
linear_density_kg_per_m = 1.0
[geometry]
left_support_m = [0.0, 0.0, 0.0]
right_support_m = [0.0, 160.0, 0.0]
segments = 2000
[numerics]
courant = 0.9
mass_damping_per_s = 1.0
[duration]
end_time_s = 60.0
"#;

fn check_csv(path: &Path) -> usize {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert!(text.ends_with('\n'), "{}: the last row is not whole", path.display());
    let mut lines = text.lines();
    let header = lines.next().unwrap_or_else(|| panic!("{}: no header", path.display()));
    let columns = header.split(',').count();
    let mut rows = 0;
    for (k, line) in lines.enumerate() {
        let fields: Vec<&str> = line.split(',').collect();
        assert_eq!(fields.len(), columns, "{} row {k}: {line}", path.display());
        for f in fields {
            f.parse::<f64>().unwrap_or_else(|_| panic!("{} row {k}: `{f}` is not a number", path.display()));
        }
        rows += 1;
    }
    rows
}

#[test]
fn a_killed_run_leaves_whole_rows_and_a_whole_summary_or_none() {
    let dir = std::env::temp_dir().join(format!("ohl-killed-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let scenario = dir.join("killed.toml");
    let times: Vec<String> = (1..20000).map(|k| format!("{:.4}", 4.0e-4 * k as f64)).collect();
    std::fs::write(&scenario, format!("{SCENARIO}[output]\nsnapshot_times_s = [{}]\n", times.join(","))).unwrap();
    let mut killed_with_rows = 0;
    for (k, delay_ms) in [150_u64, 230, 310, 390, 470, 550, 630, 710, 790, 870, 950, 1030].into_iter().enumerate() {
        let out = dir.join(format!("out{k}"));
        let mut child = Command::new(env!("CARGO_BIN_EXE_ohl"))
            // 20000 snapshots of 2001 nodes (11 GB if it ran to the end) are above the output budget.
            .args(["run", scenario.to_str().unwrap(), "--out", out.to_str().unwrap(), "--quiet", "--allow-large"])
            .spawn()
            .expect("start ohl");
        std::thread::sleep(Duration::from_millis(delay_ms));
        child.kill().expect("SIGKILL");
        let status = child.wait().expect("wait");
        assert!(!status.success(), "the run must have been killed, not finished");
        for f in ["timeseries.csv", "snapshots.csv"] {
            let p = out.join(f);
            if p.exists() {
                let rows = check_csv(&p);
                if f == "snapshots.csv" && rows > 0 {
                    killed_with_rows += 1;
                }
            }
        }
        let summary = out.join("summary.json");
        if summary.exists() {
            let text = std::fs::read_to_string(&summary).unwrap();
            serde_json::from_str::<serde_json::Value>(&text).expect("a summary.json that exists is whole");
        }
    }
    println!("{killed_with_rows} of 12 kills landed after snapshots had been written");
    assert!(killed_with_rows >= 6, "the kills must land while snapshots are being written");
    let _ = std::fs::remove_dir_all(&dir);
}
