//! `ohl run SCENARIO --converge`: the scenario on refined levels with every design value's observed
//! order, Richardson extrapolate and GCI ([`ohl_app::converge`]; docs/convergence.md). The finest level's
//! files are written to `--out` as a plain run's, the others under `--out/levels/`, the table to stdout
//! and `--out/convergence.json`.
//!
//! Exit codes: 0 the table was made (whatever the verdicts); 1 a level went unstable or a file could not
//! be written; 2 the scenario or a level is invalid, the options are, or the finest level is above
//! `--budget` (the message quotes the estimate).

use std::path::Path;
use std::process::ExitCode;

use ohl_app::converge::{self, Options, Refine, report};

/// The options of `--converge` (a part of `ohl run`'s arguments).
#[derive(clap::Args, Clone, Debug)]
pub struct ConvergeArgs {
    /// run the scenario on refined levels and report every summary value's observed order, Richardson
    /// extrapolate and GCI (Celik 2008; docs/convergence.md); writes DIR/convergence.json
    #[arg(long)]
    pub converge: bool,
    /// with --converge: refine the grid (segments of every span times the ratio, the step following at
    /// the Courant number) or the time step alone (the Courant number and the smoothing divided by it)
    #[arg(long, value_enum, default_value = "grid", requires = "converge")]
    pub refine: Refine,
    /// with --converge: number of levels, at least 3 (the three finest give the estimate)
    #[arg(long, default_value_t = 3, requires = "converge")]
    pub levels: usize,
    /// with --converge: refinement ratio between levels, a whole number of at least 2
    #[arg(long, default_value_t = 2, requires = "converge")]
    pub ratio: usize,
    /// with --converge: the scenario as written is the finest level and the others are coarser (default:
    /// it is the coarsest and the others finer)
    #[arg(long, requires = "converge")]
    pub coarsen: bool,
    /// with --converge --refine grid: divide the velocity smoothing by the grid factor (b ds / ds0), so
    /// that its numerical viscosity vanishes at second order instead of first
    #[arg(long, requires = "converge")]
    pub scaled_smoothing: bool,
    /// with --converge: a quantity is "converged within rtol" when its fine-level GCI is at most this
    /// fraction of its value [-]
    #[arg(long, default_value_t = 0.01, requires = "converge")]
    pub rtol: f64,
    /// with --converge: refuse when the finest level needs more node-steps than this (default: the budget
    /// of one run, 2e10, about 130 s)
    #[arg(long, default_value_t = ohl::scenario::work::BUDGET_NODE_STEPS, requires = "converge")]
    pub budget: f64,
}

impl ConvergeArgs {
    /// The study's options, or why they are not valid.
    pub fn options(&self) -> Result<Options, String> {
        if !(self.rtol.is_finite() && self.rtol > 0.0) {
            return Err(format!("--rtol {}: must be a positive number (a fraction: 0.01 is 1 %)", self.rtol));
        }
        if !(self.budget.is_finite() && self.budget > 0.0) {
            return Err(format!("--budget {}: must be a positive number of node-steps", self.budget));
        }
        Ok(Options {
            refine: self.refine,
            levels: self.levels,
            ratio: self.ratio,
            coarsen: self.coarsen,
            scaled_smoothing: self.scaled_smoothing,
            rtol: self.rtol,
            budget_node_steps: self.budget,
        })
    }
}

/// Run the study of `path` into `out`.
pub fn main(path: &Path, out: &Path, quiet: bool, dry_run: bool, a: &ConvergeArgs) -> ExitCode {
    let o = match a.options() {
        Ok(o) => o,
        Err(e) => {
            err!("error: {e}");
            return ExitCode::from(2);
        }
    };
    if std::fs::read_to_string(path).is_ok_and(|t| ohl::scenario::line::is_line(&t)) {
        return main_line(path, out, quiet, dry_run, &o);
    }
    let planned = match converge::plan(path, out, &o) {
        Ok(p) => p,
        Err(e) => {
            err!("error: {e}");
            return ExitCode::from(e.exit_code());
        }
    };
    for w in &planned[0].plan.warnings {
        err!("warning: {}: {w}", path.display());
    }
    let n = planned.len();
    if dry_run {
        out!("{}: --converge dry run, nothing run ({n} levels, {:?} refinement)", planned[0].plan.name, a.refine);
        for p in &planned {
            out!("  {} -> {}", level_line(&p.work(), "segments"), shown(&p.out_dir));
        }
        return ExitCode::SUCCESS;
    }
    let result = converge::run(path, planned, |k, p| {
        progress(k, n, &p.work(), "segments");
    });
    let (runs, finest) = match result {
        Ok(r) => r,
        Err(e) => {
            err!("error: {e}");
            return ExitCode::from(e.exit_code());
        }
    };
    report_study(path, out, quiet, &o, &runs, &finest.name, "segments")
}

/// [`main`] for a line scenario ([`converge::line`]).
fn main_line(path: &Path, out: &Path, quiet: bool, dry_run: bool, o: &Options) -> ExitCode {
    let planned = match converge::line::plan_line(path, Some(out), o) {
        Ok(p) => p,
        Err(e) => {
            err!("error: {e}");
            return ExitCode::from(e.exit_code());
        }
    };
    for (p, name) in planned[0].plan.plans.iter().zip(planned[0].plan.line.names()) {
        for w in &p.warnings {
            err!("warning: {}: {name}: {w}", path.display());
        }
    }
    let n = planned.len();
    if dry_run {
        out!("{}: --converge dry run, nothing run ({n} levels, {:?} refinement)", planned[0].plan.name, o.refine);
        for p in &planned {
            out!("  {} -> {}", level_line(&p.work(), "nodes"), shown(&p.out_dir));
        }
        return ExitCode::SUCCESS;
    }
    let result = converge::line::run_line_levels(path, planned, |k, p| {
        progress(k, n, &p.work(), "nodes");
    });
    let (runs, finest) = match result {
        Ok(r) => r,
        Err(e) => {
            err!("error: {e}");
            return ExitCode::from(e.exit_code());
        }
    };
    report_study(path, out, quiet, o, &runs, &finest.name, "nodes")
}

/// One level as the dry run and the progress lines print it (`unit`: what its count counts).
fn level_line(w: &converge::LevelWork, unit: &str) -> String {
    format!(
        "level {:>6}: {} {unit}, dt = {:.4e} s, {:.3e} node-steps, about {:.1} s",
        w.label, w.count, w.dt_s, w.node_steps, w.wall_s
    )
}

/// The line printed before level `k` of `n` runs.
fn progress(k: usize, n: usize, w: &converge::LevelWork, unit: &str) {
    err!(
        "converge: level {} of {n} ({}): {} {unit}, dt = {:.4e} s, about {:.1} s",
        k + 1,
        w.label,
        w.count,
        w.dt_s,
        w.wall_s
    );
}

/// A level's output directory as printed (empty: none).
fn shown(dir: &Option<std::path::PathBuf>) -> String {
    dir.as_ref().map_or(String::new(), |d| d.display().to_string())
}

/// Analyse the levels' runs, write `convergence.json` and print the table (`unit`: what the levels'
/// `segments` count).
fn report_study(
    path: &Path,
    out: &Path,
    quiet: bool,
    o: &Options,
    runs: &[converge::LevelRun],
    name: &str,
    unit: &str,
) -> ExitCode {
    let n = runs.len();
    let quantities = converge::analyse(runs, o.rtol);
    let study = report::Study::new(&path.display().to_string(), name, o, runs, &quantities);
    if let Err(e) = report::write_json(out, &study) {
        err!("error: {}: {e}", out.join("convergence.json").display());
        return ExitCode::from(1);
    }
    if !quiet {
        let levels: Vec<String> =
            runs.iter().map(|r| format!("{} ({} {unit}, dt {:.4e} s)", r.label, r.segments, r.dt_s)).collect();
        out!(
            "{name}: --converge, {:?} refinement, levels {}; Celik's order, Richardson extrapolate and GCI (F_s = 1.25) from the three finest",
            o.refine,
            levels.join(", ")
        );
        for line in report::table(&study) {
            out!("{line}");
        }
        let count = |v: &str| quantities.iter().filter(|q| q.verdict == v).count();
        let hidden = quantities.iter().filter(|q| !report::printed(q)).count();
        out!(
            "  {} quantities: {} converged within rtol, {} not within rtol, {} oscillatory, {} divergent, {} peaks moving between events, {} indeterminate, {} constant, {} constant to rounding, {} zero to rounding, {} unpaired ({hidden} constant, zero or per-phase ones in convergence.json only)",
            quantities.len(),
            count("converged within rtol"),
            count("not within rtol"),
            count("oscillatory"),
            count("divergent"),
            count(converge::PEAK_MOVES),
            count("indeterminate"),
            count("constant"),
            count("constant to rounding"),
            count("zero to rounding"),
            count("unpaired")
        );
        let wall: f64 = runs.iter().map(|r| r.wall_time_s).sum();
        out!(
            "  cost: {wall:.2} s for {n} levels, {:.2} times the scenario as written; the finest level's files in {}, convergence.json there",
            study.cost_relative_to_one_run,
            out.display()
        );
    }
    ExitCode::SUCCESS
}
