//! `ohl run SCENARIO.toml --out DIR`: run one scenario and write its output files.
//!
//! Before it runs, the work is estimated ([`ohl::scenario::work`]): `--dry-run` prints the estimate and
//! exits 0; a scenario above the budget (2e10 node-steps, about 130 s, or 2 GB of output) is refused with
//! exit 2 unless `--allow-large` is given. When stderr is not a terminal (no progress bar) and the run is
//! long, one line `running: N steps, about T s` goes to stderr before it starts. Warnings (valid but
//! doubtful values, [`ohl::scenario::warnings`]) go to stderr first, one line each, and into `summary.json`.

use std::path::PathBuf;
use std::process::ExitCode;

use ohl::run::{RunError, RunOptions, run_observed};

use ohl::scenario::{self, WorkEstimate};
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
    /// print the work estimate (steps, node-steps, output rows and bytes, wall time) and exit 0 without
    /// running
    #[arg(long)]
    dry_run: bool,
    /// run a scenario above the work budget (2e10 node-steps or 2 GB of output)
    #[arg(long)]
    allow_large: bool,
}

/// Above this many node-steps a run announces itself on stderr when no progress bar is drawn.
const ANNOUNCE_NODE_STEPS: f64 = 1.0e9;

/// Run the command; exit 0 on success, 1 if unstable or output failed, 2 on invalid input.
pub fn main(args: RunArgs) -> ExitCode {
    let RunArgs { scenario: path, out, quiet, dry_run, allow_large } = args;
    if let Some(message) = heat_case_refusal(&path) {
        err!("error: {}: {message}", path.display());
        return ExitCode::from(2);
    }
    if std::fs::read_to_string(&path).is_ok_and(|t| scenario::line::is_line(&t)) {
        return run_line(&path, &out, quiet, dry_run, allow_large);
    }
    let plan = match scenario::load(&path).and_then(|sc| scenario::plan(&sc, &path.display().to_string())) {
        Ok(p) => p,
        Err(e) => {
            err!("error: {e}");
            return ExitCode::from(2);
        }
    };
    for w in &plan.warnings {
        err!("warning: {}: {w}", path.display());
    }
    let estimate = plan.work_estimate();
    if dry_run {
        print_estimate(&plan.name, &estimate);
        return ExitCode::SUCCESS;
    }
    let checked = if allow_large { estimate.check_resolvable() } else { estimate.check() };
    if let Err(refusal) = checked {
        err!("error: {}: {refusal}", path.display());
        return ExitCode::from(2);
    }
    let opts = RunOptions { out_dir: Some(out.clone()), record: false };
    let mut bar = Bar::for_plan(&plan);
    // No bar: stderr is not a terminal (a script, a log file).
    if bar.is_none() && estimate.work_node_steps() > ANNOUNCE_NODE_STEPS {
        err!("running: {:.0} steps, about {:.0} s", estimate.steps, estimate.wall_time_s());
    }
    let mut extra: Vec<&mut dyn ohl::run::Observer> =
        bar.iter_mut().map(|b| b as &mut dyn ohl::run::Observer).collect();
    match run_observed(plan, &opts, &mut extra) {
        Ok(o) => {
            if !quiet {
                let s = &o.summary;
                let d = s.final_midspan_displacement_m;
                out!(
                    "{}: {} at t = {:.4} s (tau = {:.4}) after {} steps of {:.4e} s",
                    s.name,
                    s.status,
                    s.final_time_s,
                    s.final_tau,
                    s.steps,
                    s.dt_s
                );
                out!("  mid-span displacement [m]: x1 = {:.6}, x2 = {:.6}, x3 = {:.6}", d[0], d[1], d[2]);
                out!(
                    "  max tension: {:.2} N; throughput {:.3e} node-steps/s",
                    s.final_max_tension_n,
                    s.node_steps_per_second
                );
                out!(
                    "  peak tension: {:.2} N at {:.3} s (peaks from {} s){}",
                    s.peak_max_tension_n,
                    s.peak_max_tension_time_s,
                    s.peaks_from_s,
                    match &s.start_up {
                        Some(u) if !u.flagged.is_empty() => " [start-up overshoot]",
                        _ => "",
                    }
                );
                out!("  written to {}", out.display());
            }
            // A peak that comes from the start (ohl::output::start_up) is no design value: said on stderr.
            for w in s_start_up_lines(&o.summary) {
                err!("warning: {}: {w}", path.display());
            }
            ExitCode::SUCCESS
        }
        Err(RunError::Unstable { instability, .. }) => {
            err!("error: {}: {instability}; output so far is in {}", path.display(), out.display());
            ExitCode::from(1)
        }
        Err(e) => {
            err!("error: {e}");
            ExitCode::from(1)
        }
    }
}

/// The estimate of `--dry-run`, one quantity a line.
fn print_estimate(name: &str, e: &WorkEstimate) {
    use ohl::scenario::work::{BUDGET_NODE_STEPS, BUDGET_OUTPUT_BYTES, THROUGHPUT_NODE_STEPS_PER_S};
    let within = if e.check().is_ok() { "within the budget" } else { "ABOVE the budget: needs --allow-large" };
    out!("{name}: dry run, nothing run ({within})");
    out!("  segments: {}, time step: {:.6e} s, end (or time cap): {} s", e.segments, e.dt_s, e.horizon_s);
    out!("  steps: {:.6e}", e.steps);
    out!("  node-steps: {:.6e} (budget {BUDGET_NODE_STEPS:.1e})", e.node_steps);
    if e.heat_substeps > 0.0 {
        out!("  heat conduction: {:.6e} sub-steps, {:.6e} node updates", e.heat_substeps, e.heat_node_updates);
    }
    out!("  timeseries.csv: {:.6e} rows of {} numbers", e.timeseries_rows, e.timeseries_columns);
    out!("  snapshots.csv: {:.6e} rows", e.snapshot_rows);
    out!("  output: at most {:.3e} bytes (budget {BUDGET_OUTPUT_BYTES:.1e})", e.output_bytes);
    out!("  wall time: about {:.3e} s at {THROUGHPUT_NODE_STEPS_PER_S:.1e} node-steps/s (one core)", e.wall_time_s());
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

/// `ohl run` on a line scenario (a file with `[line]`: several conductors, [`ohl::scenario::line`]).
fn run_line(path: &std::path::Path, out: &std::path::Path, quiet: bool, dry_run: bool, allow_large: bool) -> ExitCode {
    use ohl::run::line::{LineRunError, LineWorkEstimate, run_line};
    use ohl::scenario::work::{BUDGET_NODE_STEPS, BUDGET_OUTPUT_BYTES, THROUGHPUT_NODE_STEPS_PER_S};
    let file = path.display().to_string();
    let plan = match scenario::read_text(path)
        .and_then(|t| scenario::line::parse(&t, &file))
        .and_then(|s| scenario::line::plan(&s, &file))
    {
        Ok(p) => p,
        Err(e) => {
            err!("error: {e}");
            return ExitCode::from(2);
        }
    };
    for (p, name) in plan.plans.iter().zip(plan.line.names()) {
        for w in &p.warnings {
            err!("warning: {file}: {name}: {w}");
        }
    }
    let work = LineWorkEstimate::of(&plan);
    if let Err(refusal) = work.check_resolvable() {
        err!("error: {file}: {refusal}");
        return ExitCode::from(2);
    }
    if dry_run {
        out!("{}: dry run, nothing run", plan.name);
        out!("  conductors: {}, nodes: {}, time step: {:.6e} s", work.conductors, work.nodes, work.dt_s);
        out!("  steps: {:.6e}, node-steps: {:.6e} (budget {BUDGET_NODE_STEPS:.1e})", work.steps, work.node_steps);
        out!("  output: at most {:.3e} bytes (budget {BUDGET_OUTPUT_BYTES:.1e})", work.output_bytes);
        out!("  wall time: about {:.3e} s at {THROUGHPUT_NODE_STEPS_PER_S:.1e} node-steps/s", work.wall_time_s());
        return ExitCode::SUCCESS;
    }
    if !allow_large && let Err(refusal) = work.check() {
        err!("error: {file}: {refusal}");
        return ExitCode::from(2);
    }
    match run_line(plan, Some(out)) {
        Ok(o) => {
            if !quiet {
                print_line_summary(&o.summary, out);
            }
            ExitCode::SUCCESS
        }
        Err(LineRunError::Unstable { instability, .. }) => {
            err!("error: {file}: {instability}; output so far is in {}", out.display());
            ExitCode::from(1)
        }
        Err(e) => {
            err!("error: {e}");
            ExitCode::from(1)
        }
    }
}

/// The summary of a line run, a few lines per conductor, pair and tower.
fn print_line_summary(s: &ohl::run::line::LineSummary, out: &std::path::Path) {
    out!("{}: {} at t = {:.4} s after {} steps of {:.4e} s", s.name, s.status, s.final_time_s, s.steps, s.dt_s);
    for c in &s.conductors {
        out!(
            "  {} ({}): peak tension {:.1} N at {:.3} s, final {:.1} N{}",
            c.name,
            c.role,
            c.peak_max_tension_n,
            c.peak_max_tension_time_s,
            c.final_max_tension_n,
            match &c.start_up {
                Some(u) if !u.flagged.is_empty() => " [start-up overshoot]",
                _ => "",
            }
        );
        // A peak that comes from the start (ohl::output::start_up) is no design value: said on stderr.
        for w in c.start_up.as_ref().map(|u| u.describe()).unwrap_or_default() {
            err!("warning: {}: {w}", c.name);
        }
    }
    // A distance, or why there is none (a conductor broken in every segment).
    let metres = |x: Option<f64>| x.map_or_else(|| "none (no segment left)".to_string(), |x| format!("{x:.3} m"));
    for c in &s.clearances {
        out!(
            "  clearance {} - {}: least {:.3} m at {:.3} s ({} at {:.3}, {} at {:.3} of their lengths); initial {}, final {}",
            c.between[0],
            c.between[1],
            c.least_m,
            c.time_s,
            c.conductors[0],
            c.at_fraction[0],
            c.conductors[1],
            c.at_fraction[1],
            metres(c.initial_m),
            metres(c.final_m)
        );
    }
    for t in &s.towers {
        let f = t.final_force_n;
        out!(
            "  tower {}: peak |F| {:.1} N at {:.3} s; final F = [{:.1}, {:.1}, {:.1}] N",
            t.name,
            t.peak_force_magnitude_n,
            t.peak_force_time_s,
            f[0],
            f[1],
            f[2]
        );
    }
    for a in &s.attachments {
        out!(
            "  {} x {}: largest tension {:.1} N at {:.3} s ({} - {})",
            a.count,
            a.kind,
            a.peak_tension_n,
            a.time_s,
            a.ends[0],
            a.ends[1]
        );
    }
    out!("  throughput {:.3e} node-steps/s; written to {}", s.node_steps_per_second, out.display());
}

/// The start-up warnings of a summary (empty when no peak comes from the start).
fn s_start_up_lines(s: &ohl::output::Summary) -> Vec<String> {
    s.start_up.as_ref().map(|u| u.describe()).unwrap_or_default()
}
