//! The provenance line of a generated report: commit (with `+dirty` when tracked files differ), date,
//! compiler and CPU, so that a reader can tell whether the report is current. Used by the verification
//! report (`figures/verification/REPORT.md`) and the paper table (`figures/paper_table.md`).

/// Where and when the report was made: the commit (with `+dirty` if the tree had changes), the UTC date,
/// the compiler and the CPU, each `unknown` where it cannot be read (no git, no rustc on the path).
pub fn stamp() -> String {
    let run = |cmd: &str, args: &[&str]| {
        std::process::Command::new(cmd)
            .args(args)
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .output()
            .ok()
            .filter(|o| o.status.success())
            .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
    };
    let commit = run("git", &["rev-parse", "--short=12", "HEAD"]).map_or("unknown".into(), |c| {
        let dirty = run("git", &["status", "--porcelain", "--untracked-files=no"]).is_some_and(|s| !s.is_empty());
        if dirty { format!("{c}+dirty") } else { c }
    });
    let date = run("date", &["-u", "+%Y-%m-%d %H:%M UTC"]).unwrap_or_else(|| "unknown".into());
    let rustc = run("rustc", &["-V"]).unwrap_or_else(|| "unknown".into());
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|t| {
            t.lines()
                .find(|l| l.starts_with("model name"))
                .map(|l| l.split(':').nth(1).unwrap_or("").trim().to_string())
        })
        .unwrap_or_else(|| "unknown".into());
    let cores = std::thread::available_parallelism().map_or(0, |n| n.get());
    format!("Commit `{commit}`, {date}, {rustc}, {cpu} ({cores} threads).")
}
