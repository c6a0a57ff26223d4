//! `ohl plot RUN_DIR`: draw a run's time series, support forces and shapes to PNG and SVG
//! ([`ohl_app::run_plot`]), into `RUN_DIR/plots/` or `--out DIR`.
//!
//! Exit codes: 0 drawn; 1 a figure could not be written; 2 RUN_DIR is not a run folder (the message names
//! the missing file), a file of it is malformed, or `--from`/`--to` select no sample.

use std::path::PathBuf;
use std::process::ExitCode;

use ohl_app::run_plot::{PlotOptions, plot_run};

/// Arguments of `ohl plot`.
#[derive(clap::Args)]
pub struct PlotArgs {
    /// the folder `ohl run SCENARIO.toml --out DIR` wrote (timeseries.csv, snapshots.csv, summary.json)
    run_dir: PathBuf,
    /// folder of the figures (created if missing; default RUN_DIR/plots)
    #[arg(long)]
    out: Option<PathBuf>,
    /// first time drawn [s] (default: the run's start)
    #[arg(long, allow_negative_numbers = true)]
    from: Option<f64>,
    /// last time drawn [s] (default: the run's end)
    #[arg(long, allow_negative_numbers = true)]
    to: Option<f64>,
    /// do not list the files written
    #[arg(long)]
    quiet: bool,
}

/// Run the command; exit 0 on success, 1 if a figure could not be written, 2 on bad input.
pub fn main(args: PlotArgs) -> ExitCode {
    let PlotArgs { run_dir, out, from, to, quiet } = args;
    match plot_run(&run_dir, &PlotOptions { out, from_s: from, to_s: to }) {
        Ok(report) => {
            for n in &report.notes {
                err!("note: {n}");
            }
            if !quiet {
                out!("{}: {} files written", run_dir.display(), report.files.len());
                for f in &report.files {
                    out!("  {}", f.display());
                }
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            err!("error: {e}");
            ExitCode::from(e.exit_code())
        }
    }
}
