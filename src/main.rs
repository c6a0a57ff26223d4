//! `ohl`: the command line of the wire solver.
//!
//! `ohl run SCENARIO.toml --out DIR` runs a scenario and writes `DIR/timeseries.csv`,
//! `DIR/snapshots.csv` and `DIR/summary.json`.
//!
//! Exit codes: 0 success; 1 the run went unstable (or an output file could not be written), and what
//! was written so far stays readable; 2 the scenario is invalid (the message names the file, the field,
//! the value and what is allowed) or the command line is wrong.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use ohl::run::{RunError, RunOptions, run};
use ohl::scenario;

#[derive(Parser)]
#[command(name = "ohl", version, about = "Dynamics of overhead power-line wires (explicit staggered-grid scheme)")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run a scenario file and write timeseries.csv, snapshots.csv and summary.json.
    Run {
        /// the scenario (TOML, SI units)
        scenario: PathBuf,
        /// output directory (created if missing)
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// do not print the summary
        #[arg(long)]
        quiet: bool,
    },
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Command::Run { scenario: path, out, quiet } => {
            let sc = match scenario::load(&path) {
                Ok(s) => s,
                Err(e) => {
                    eprintln!("error: {e}");
                    return ExitCode::from(2);
                }
            };
            let plan = scenario::build(&sc);
            let opts = RunOptions { out_dir: Some(out.clone()), progress: true, record: false };
            match run(plan, &opts) {
                Ok(o) => {
                    if !quiet {
                        let s = &o.summary;
                        let d = s.final_midspan_displacement_m;
                        println!(
                            "{}: {} at t = {:.4} s (tau = {:.4}) after {} steps of {:.4e} s",
                            s.name, s.status, s.final_time_s, s.final_tau, s.steps, s.dt_s
                        );
                        println!("  mid-span displacement [m]: x1 = {:.6}, x2 = {:.6}, x3 = {:.6}", d[0], d[1], d[2]);
                        println!(
                            "  max tension: {:.2} N; throughput {:.3e} node-steps/s",
                            s.final_max_tension_n, s.node_steps_per_second
                        );
                        println!("  written to {}", out.display());
                    }
                    ExitCode::SUCCESS
                }
                Err(RunError::Unstable { instability, .. }) => {
                    eprintln!("error: {}: {instability}; output so far is in {}", path.display(), out.display());
                    ExitCode::from(1)
                }
                Err(e) => {
                    eprintln!("error: {e}");
                    ExitCode::from(1)
                }
            }
        }
    }
}
