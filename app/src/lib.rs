//! `ohl_app`: the applications of the `ohl` wire model, which the library itself does not carry.
//!
//! - [`paper`]: the paper's cases of `paper_cases/` (the `[paper]` checks of a case file, the heat-case
//!   file format, running, extracting, references, tables and figures);
//! - [`plot`]: PNG and SVG charts (plotters);
//! - [`cases`]: the line-section cases of `cases/` (runs, load figures, peak-to-residual tables);
//! - [`converge`]: `ohl run --converge`, a scenario on refined levels with Celik's order, Richardson
//!   extrapolate and GCI of every summary value;
//! - [`bench`]: the kernel benchmark (measurements, machine description, CSV tables, throughput plot);
//! - [`progress`]: the terminal progress bar of `ohl run`, an observer of the library's run loop;
//! - [`run_plot`]: the figures of a run's output folder (`ohl plot RUN_DIR`).
//! - [`sagtension`]: the files and the figure of `ohl sagtension` (sag-tension tables).
//! - [`sweep`]: parameter sweeps (`ohl sweep`): cases from a base scenario, run in parallel into one table.
//! - [`stamp`]: the provenance line (commit, date, compiler, CPU) of the generated reports.
//!
//! The binary `ohl` (`src/main.rs`, `src/cli/`) is the command line over these.

pub mod bench;
pub mod cases;
pub mod converge;
pub mod line_cases;
pub mod paper;
pub mod plot;
pub mod progress;
pub mod run_plot;
pub mod sagtension;
pub mod stamp;
pub mod sweep;

/// The repository the default paths (`paper_cases/`, `cases/`, `figures/`) are relative to: the current
/// directory if it holds `paper_cases/`, else the workspace the binary was built from (so that `ohl paper
/// all` works from any directory of a checkout), else the current directory.
pub fn repository_root() -> std::path::PathBuf {
    let here = std::path::PathBuf::from(".");
    if here.join("paper_cases").is_dir() {
        return here;
    }
    let built = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    if built.join("paper_cases").is_dir() { built } else { here }
}

/// `path` as given, unless it is the command's default `default` (a path relative to the repository),
/// which is then taken from [`repository_root`].
pub fn rooted_default(path: std::path::PathBuf, default: &str) -> std::path::PathBuf {
    if path == std::path::Path::new(default) { repository_root().join(default) } else { path }
}
