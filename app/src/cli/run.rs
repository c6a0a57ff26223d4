//! `ohl run SCENARIO.toml --out DIR`: run one scenario and write its output files.

use std::path::PathBuf;
use std::process::ExitCode;

use ohl::run::{RunError, RunOptions, run_observed};

use ohl::scenario;
use ohl_app::paper::heat_spec;
use ohl_app::progress::Bar;

/// Arguments of `ohl run`.
#[derive(clap::Args)]
pub struct RunArgs {
    /// the scenario (TOML, SI units)
    scenario: PathBuf,
    /// output directory (created if missing)
    #[arg(long, default_value = "out")]
    out: PathBuf,
    /// do not print the summary
    #[arg(long)]
    quiet: bool,
}

/// Run the command; exit 0 on success, 1 if unstable or output failed, 2 on invalid input.
pub fn main(args: RunArgs) -> ExitCode {
    let RunArgs { scenario: path, out, quiet } = args;
    if let Some(message) = heat_case_refusal(&path) {
        eprintln!("error: {}: {message}", path.display());
        return ExitCode::from(2);
    }
    let plan = match scenario::load(&path).and_then(|sc| scenario::plan(&sc, &path.display().to_string())) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let opts = RunOptions { out_dir: Some(out.clone()), record: false };
    let mut bar = Bar::for_plan(&plan);
    let mut extra: Vec<&mut dyn ohl::run::Observer> =
        bar.iter_mut().map(|b| b as &mut dyn ohl::run::Observer).collect();
    match run_observed(plan, &opts, &mut extra) {
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

/// A heat-conduction case (a file with a `[rod]` section) is not a wire scenario: the message points to
/// `ohl paper`. None for anything else (including a file that cannot be read: `scenario::load` says so).
fn heat_case_refusal(path: &std::path::Path) -> Option<String> {
    let text = std::fs::read_to_string(path).ok()?;
    heat_spec::is_heat_case(&text).then(|| {
        let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("CASE");
        format!("a heat-conduction case (it has a [rod] section), not a wire scenario: run it with `ohl paper {stem}`")
    })
}
