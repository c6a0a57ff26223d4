//! `ohl run SCENARIO --converge`: error bars on a run's own numbers. The scenario is run on three or more
//! systematically refined levels ([`levels`]), every scalar of its summary is paired across them by its
//! path ([`flatten`]) and each is given Celik's observed order, Richardson extrapolate and GCI
//! ([`ohl::verify::gci`], the three finest levels) and a verdict against the user's tolerance `rtol`
//! ([`report`]). docs/convergence.md explains the method and its sources.
//!
//! Before anything runs, the work of every level is estimated ([`ohl::scenario::WorkEstimate`]) and the
//! study is refused when its finest level is above the budget (node-steps, default the single run's
//! 2e10), quoting the estimate.

pub mod flatten;
pub mod levels;
pub mod line;
pub mod report;

use std::path::{Path, PathBuf};
use std::time::Instant;

use ohl::run::{RunError, RunOptions, run_observed};
use ohl::scenario::{self, InputError, Plan, Scenario, WorkEstimate};
use ohl::verify::gci::{self, Estimate};

pub use levels::{Level, LevelError, Refine};

/// How the study is made.
#[derive(Clone, Copy, Debug, serde::Serialize)]
pub struct Options {
    /// what is refined
    pub refine: Refine,
    /// number of levels (at least 3)
    pub levels: usize,
    /// refinement ratio between levels (a whole number, at least 2)
    pub ratio: usize,
    /// the scenario as written is the finest level (else the coarsest)
    pub coarsen: bool,
    /// divide the smoothing `b` by the grid factor (`b ds / ds0`)
    pub scaled_smoothing: bool,
    /// relative tolerance of "converged within rtol" (on the fine-level GCI) [-]
    pub rtol: f64,
    /// largest work of the finest level [node-steps]
    pub budget_node_steps: f64,
}

/// Why a study did not give its table.
#[derive(Debug, thiserror::Error)]
pub enum StudyError {
    /// the scenario is invalid
    #[error(transparent)]
    Input(#[from] InputError),
    /// a level cannot be made
    #[error(transparent)]
    Level(#[from] LevelError),
    /// the finest level is above the budget
    #[error(
        "{file}: --converge: the finest level ({label}, {segments} segments, dt = {dt_s:.3e} s) needs {node_steps:.3e} \
         node-steps (about {wall_s:.0} s), above the budget {budget:.1e} node-steps; the {levels} levels together \
         {total:.3e} node-steps, {ratio:.1} times the scenario as written. Use --coarsen (the written grid as the \
         finest), a smaller --ratio or fewer --levels, or raise --budget"
    )]
    Budget {
        /// the scenario file
        file: String,
        /// the finest level
        label: String,
        /// its segments
        segments: f64,
        /// its step [s]
        dt_s: f64,
        /// its work [node-steps]
        node_steps: f64,
        /// its estimated wall time [s]
        wall_s: f64,
        /// the budget [node-steps]
        budget: f64,
        /// number of levels
        levels: usize,
        /// work of all levels [node-steps]
        total: f64,
        /// total over the written level's work [-]
        ratio: f64,
    },
    /// a level went unstable
    #[error("{file}: --converge: level {label}: {message}; its output so far is in {dir}")]
    Unstable {
        /// the scenario file
        file: String,
        /// the level
        label: String,
        /// the instability
        message: String,
        /// its output directory
        dir: String,
    },
    /// a level failed otherwise (an output file)
    #[error("{file}: --converge: level {label}: {message}")]
    Run {
        /// the scenario file
        file: String,
        /// the level
        label: String,
        /// what failed
        message: String,
    },
}

impl StudyError {
    /// The exit code: 2 for what is refused before anything runs, 1 for a failed run.
    pub fn exit_code(&self) -> u8 {
        match self {
            StudyError::Input(_) | StudyError::Level(_) | StudyError::Budget { .. } => 2,
            StudyError::Unstable { .. } | StudyError::Run { .. } => 1,
        }
    }
}

/// A level ready to run.
pub struct Planned {
    /// the level
    pub level: Level,
    /// its plan
    pub plan: Plan,
    /// its work
    pub estimate: WorkEstimate,
    /// where its files go (none: not written)
    pub out_dir: Option<PathBuf>,
}

impl Planned {
    /// Its work, as the budget check and the command's messages read it.
    pub fn work(&self) -> LevelWork {
        LevelWork {
            label: self.level.label(),
            factor: self.level.factor,
            count: self.estimate.segments,
            dt_s: self.estimate.dt_s,
            node_steps: self.estimate.work_node_steps(),
            wall_s: self.estimate.wall_time_s(),
            resolvable: self.estimate.check_resolvable().is_ok(),
        }
    }
}

/// A level's work, whatever the scenario's kind (one conductor or a line).
pub struct LevelWork {
    /// its label (`x2`)
    pub label: String,
    /// its grid (or step) relative to the scenario as written [-]
    pub factor: f64,
    /// its segments (one conductor) or nodes (a line)
    pub count: f64,
    /// its step [s]
    pub dt_s: f64,
    /// its work [node-steps]
    pub node_steps: f64,
    /// its estimated wall time [s]
    pub wall_s: f64,
    /// whether the run's clock resolves its step (the estimate's `check_resolvable`)
    pub resolvable: bool,
}

/// Where level `k` of `n` writes its files (none without `out`): the finest to `out`, the others to
/// `out/levels/<k>_<label>`.
pub(crate) fn level_dir(out: Option<&Path>, k: usize, n: usize, label: &str) -> Option<PathBuf> {
    out.map(|out| {
        if k + 1 == n { out.to_path_buf() } else { out.join("levels").join(format!("{k}_{}", label.replace('/', "_"))) }
    })
}

/// Refuse the study of `levels` (coarse to fine) when its finest level is above the budget or its step is
/// below what the run's clock resolves.
pub(crate) fn check_budget(file: String, o: &Options, levels: &[LevelWork]) -> Result<(), StudyError> {
    let total: f64 = levels.iter().map(|l| l.node_steps).sum();
    let written = levels.iter().find(|l| l.factor == 1.0).map_or(f64::NAN, |l| l.node_steps);
    let finest = levels.last().expect("at least three levels");
    let within = finest.node_steps.partial_cmp(&o.budget_node_steps).is_some_and(|c| c.is_le());
    if within && finest.resolvable {
        return Ok(());
    }
    Err(StudyError::Budget {
        file,
        label: finest.label.clone(),
        segments: finest.count,
        dt_s: finest.dt_s,
        node_steps: finest.node_steps,
        wall_s: finest.wall_s,
        budget: o.budget_node_steps,
        levels: levels.len(),
        total,
        ratio: total / written,
    })
}

/// Read `path`, make the levels, plan them and check the budget. The finest level writes to `out`, the
/// others to `out/levels/<k>_<label>`.
pub fn plan(path: &Path, out: &Path, o: &Options) -> Result<Vec<Planned>, StudyError> {
    let sc = scenario::load(path)?;
    plan_scenario(&sc, &path.display().to_string(), Some(out), o)
}

/// [`plan`] for a parsed scenario `sc` (named `file` in messages); with `out` none, nothing is written.
pub fn plan_scenario(sc: &Scenario, file: &str, out: Option<&Path>, o: &Options) -> Result<Vec<Planned>, StudyError> {
    let file = file.to_string();
    let lv = levels::levels(sc, &file, o.refine, o.levels, o.ratio, o.coarsen, o.scaled_smoothing)?;
    let n = lv.len();
    let planned = lv
        .into_iter()
        .enumerate()
        .map(|(k, level)| {
            let plan = scenario::plan(&level.scenario, &file).map_err(|e| LevelError::Invalid {
                label: level.label(),
                what: "its plan".into(),
                source: e,
            })?;
            let estimate = plan.work_estimate();
            let out_dir = level_dir(out, k, n, &level.label());
            Ok(Planned { level, plan, estimate, out_dir })
        })
        .collect::<Result<Vec<_>, StudyError>>()?;
    check_budget(file, o, &planned.iter().map(Planned::work).collect::<Vec<_>>())?;
    Ok(planned)
}

/// What one level gave.
#[derive(Clone, Debug, serde::Serialize)]
pub struct LevelRun {
    /// `x2`: the grid (or step) relative to the scenario as written
    pub label: String,
    /// `ratio^k` relative to the scenario as written [-]
    pub factor: f64,
    /// representative size relative to the scenario as written [-]
    pub h_relative: f64,
    /// segments (all spans)
    pub segments: usize,
    /// time step [s]
    pub dt_s: f64,
    /// steps run
    pub steps: u64,
    /// estimated work [node-steps]
    pub node_steps_estimate: f64,
    /// wall time of the level (build, run and files) [s]
    pub wall_time_s: f64,
    /// its output directory (or that none was written)
    pub out_dir: String,
    /// the phases of its run (between events)
    pub phases: usize,
    /// its scalars by path
    #[serde(skip)]
    pub scalars: Vec<(String, f64)>,
}

/// Run the planned levels in order (coarse to fine), `before(k, planned)` called before each.
pub fn run(
    path: &Path,
    planned: Vec<Planned>,
    before: impl FnMut(usize, &Planned),
) -> Result<(Vec<LevelRun>, ohl::output::Summary), StudyError> {
    run_with_first(path, planned, None, before)
}

/// The first level already run: its summary and its wall time [s] (build, run and files).
pub struct FirstRun {
    /// the summary of the run of the first level's plan
    pub summary: ohl::output::Summary,
    /// its wall time [s]
    pub wall_time_s: f64,
}

/// [`run`], the first level's run given by `first` when the caller has run that level's plan already (`ohl
/// cases --converge` runs the case as written for its files and its table, which is the study's first
/// level): its summary is taken instead of running the same plan again, which would give the same
/// summary (a run is deterministic, bit for bit) but for its timings.
pub fn run_with_first(
    path: &Path,
    planned: Vec<Planned>,
    mut first: Option<FirstRun>,
    mut before: impl FnMut(usize, &Planned),
) -> Result<(Vec<LevelRun>, ohl::output::Summary), StudyError> {
    let file = path.display().to_string();
    let mut runs = Vec::with_capacity(planned.len());
    let mut last = None;
    for (k, p) in planned.into_iter().enumerate() {
        before(k, &p);
        let label = p.level.label();
        let opts = RunOptions { out_dir: p.out_dir.clone(), record: false };
        let dir = p.out_dir.as_ref().map_or("(no files written)".to_string(), |d| d.display().to_string());
        let (summary, wall) = match first.take() {
            Some(f) => (f.summary, f.wall_time_s),
            None => {
                let start = Instant::now();
                let outcome = run_observed(p.plan, &opts, &mut []).map_err(|e| match e {
                    RunError::Unstable { instability, .. } => StudyError::Unstable {
                        file: file.clone(),
                        label: label.clone(),
                        message: instability.to_string(),
                        dir: dir.clone(),
                    },
                    e => StudyError::Run { file: file.clone(), label: label.clone(), message: e.to_string() },
                })?;
                (outcome.summary, start.elapsed().as_secs_f64())
            }
        };
        let s = &summary;
        let value = serde_json::to_value(s).map_err(|e| StudyError::Run {
            file: file.clone(),
            label: label.clone(),
            message: format!("summary: {e}"),
        })?;
        runs.push(LevelRun {
            label,
            factor: p.level.factor,
            h_relative: p.level.h,
            segments: s.segments,
            dt_s: s.dt_s,
            steps: s.steps,
            node_steps_estimate: p.estimate.work_node_steps(),
            wall_time_s: wall,
            out_dir: dir,
            phases: s.phases.len(),
            scalars: flatten::scalars(&value),
        });
        last = Some(summary);
    }
    Ok((runs, last.expect("at least three levels")))
}

/// One quantity across the levels.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Quantity {
    /// its path in `summary.json`
    pub path: String,
    /// its value on each level, coarse to fine (null where the level has none)
    pub values: Vec<Option<f64>>,
    /// Celik's estimate from the three finest levels (absent for an unpaired quantity)
    pub estimate: Option<Estimate>,
    /// the verdict ([`verdict`])
    pub verdict: &'static str,
}

/// A quantity is zero to rounding when every level's value is below this fraction of the largest value
/// of the same unit (the path's last key, e.g. `_m`, `_n`) on the finest level: rounding of double
/// precision (1.1e-16) accumulated over up to 1e6 steps stays below 1e-10 of the scale, a discretisation
/// error of a physical quantity does not fall that low.
pub const ROUNDING_ZERO: f64 = 1e-10;

/// A quantity is constant to rounding when its values differ by at most this fraction of their magnitude:
/// an equilibrium load solved by Newton to 1e-10 of the nodal loads (`initial.shape = "equilibrium"`)
/// differs between grids by about that much (case (b)'s iced support load: 1.0e-10); ten times it is
/// still far below any discretisation error of a design value.
pub const CONSTANT_TO_ROUNDING: f64 = 1e-9;

/// The verdict of an estimate against `rtol`: "converged within rtol" (converging, fine-level GCI at most
/// `rtol`), "not within rtol" (converging, a wider band), or what the sequence does instead
/// ("oscillatory", "divergent", "indeterminate", "constant"); a quantity that is zero to rounding on
/// every level ([`ROUNDING_ZERO`]) is "zero to rounding" whatever its sequence does, and a peak whose time
/// does not converge is [`PEAK_MOVES`] ([`analyse`]); one whose values differ by at most
/// [`CONSTANT_TO_ROUNDING`] of their magnitude (an equilibrium to Newton's tolerance) is "constant to
/// rounding".
pub fn verdict(e: &Estimate, rtol: f64) -> &'static str {
    use gci::Behaviour::*;
    match e.behaviour {
        Converging if e.gci_fine.is_some_and(|g| g <= rtol) => "converged within rtol",
        Converging => "not within rtol",
        b => b.word(),
    }
}

/// Pair the levels' scalars by path (in the finest level's order, then any path the finest lacks) and
/// estimate each from the three finest levels. The per-phase peaks are left out when the levels do not
/// have the same number of phases (an event per segment, as a progressive shedding front, has as many
/// phases as segments): they are not the same phases.
pub fn analyse(runs: &[LevelRun], rtol: f64) -> Vec<Quantity> {
    use std::collections::HashMap;
    // the phases are paired only where every level has as many (a progressive event has one per segment)
    let same_phases = runs.windows(2).all(|w| w[0].phases == w[1].phases);
    let mut paths: Vec<&str> = Vec::new();
    let mut by_level: Vec<HashMap<&str, f64>> = Vec::with_capacity(runs.len());
    let mut seen = std::collections::HashSet::new();
    for r in runs.iter().rev() {
        for (p, _) in &r.scalars {
            if (same_phases || !p.starts_with("phases[")) && seen.insert(p.as_str()) {
                paths.push(p);
            }
        }
    }
    for r in runs {
        by_level.push(r.scalars.iter().map(|(p, v)| (p.as_str(), *v)).collect());
    }
    let n = runs.len();
    // the unit of a path: its last key's suffix after the last `_` (`value_n` -> `n`), and its scale
    let unit = |p: &str| {
        let key = p.rsplit('.').next().unwrap_or("");
        let key = key.split('[').next().unwrap_or("");
        key.rsplit('_').next().unwrap_or("").to_string()
    };
    let mut scale: std::collections::HashMap<String, f64> = std::collections::HashMap::new();
    for (p, v) in &runs[n - 1].scalars {
        let s = scale.entry(unit(p)).or_insert(0.0);
        *s = s.max(v.abs());
    }
    let mut quantities: Vec<Quantity> = paths
        .into_iter()
        .map(|path| {
            let values: Vec<Option<f64>> = by_level.iter().map(|m| m.get(path).copied()).collect();
            let h = [runs[n - 1].h_relative, runs[n - 2].h_relative, runs[n - 3].h_relative];
            let phi = (values[n - 1], values[n - 2], values[n - 3]);
            let estimate = match phi {
                (Some(a), Some(b), Some(c)) => gci::three_grid(h, [a, b, c]).ok(),
                _ => None,
            };
            let floor = ROUNDING_ZERO * scale.get(&unit(path)).copied().unwrap_or(0.0);
            let zero = values.iter().all(|v| v.is_some_and(|v| v.abs() <= floor)) && floor > 0.0;
            let verdict = match &estimate {
                None => "unpaired",
                Some(_) if zero && values.iter().any(|v| v.is_some_and(|v| v != 0.0)) => "zero to rounding",
                Some(e)
                    if e.behaviour != gci::Behaviour::Constant
                        && e.spread <= CONSTANT_TO_ROUNDING * phi_scale(&values) =>
                {
                    "constant to rounding"
                }
                Some(e) => verdict(e, rtol),
            };
            Quantity { path: path.to_string(), values, estimate, verdict }
        })
        .collect();
    // the time of a peak whose value is zero to rounding is the time of rounding noise
    let zero: Vec<String> = quantities
        .iter()
        .filter(|q| q.verdict == "zero to rounding")
        .filter_map(|q| q.path.rsplit_once('.').map(|(head, _)| format!("{head}.time_s")))
        .collect();
    for q in &mut quantities {
        if zero.contains(&q.path) {
            q.verdict = "zero to rounding";
        }
    }
    // a peak whose time does not converge and spreads over more than rtol of itself is not the same event
    // on every level (the largest of several pulses changes with the grid): its value is no design value
    // with an error bar, whatever its own three numbers do. (The time of a smooth maximum converges
    // slowly and noisily while its value converges fast: a spread within rtol is that, not a new pulse.)
    let moving: Vec<String> = quantities
        .iter()
        .filter(|q| {
            q.path.ends_with(".time_s")
                && !matches!(
                    q.verdict,
                    "converged within rtol" | "not within rtol" | "constant" | "constant to rounding"
                )
                && moved(q, rtol)
        })
        .filter_map(|q| q.path.strip_suffix(".time_s").map(str::to_string))
        .collect();
    for q in &mut quantities {
        let head = q.path.rsplit_once('.').map(|(h, _)| h);
        let is_value = !q.path.ends_with(".time_s");
        if is_value
            && head.is_some_and(|h| moving.iter().any(|m| m == h))
            && !matches!(q.verdict, "zero to rounding" | "constant" | "constant to rounding")
        {
            q.verdict = PEAK_MOVES;
        }
    }
    quantities
}

/// Whether a peak time `q` spreads over more than `rtol` of its finest value (or has no estimate).
fn moved(q: &Quantity, rtol: f64) -> bool {
    let fine = q.values.last().copied().flatten().unwrap_or(0.0);
    q.estimate.as_ref().is_none_or(|e| e.spread > rtol * fine.abs())
}

/// The largest magnitude of a quantity's values.
fn phi_scale(values: &[Option<f64>]) -> f64 {
    values.iter().flatten().fold(0.0, |m: f64, v| m.max(v.abs()))
}

/// The verdict of a peak value whose time is oscillatory, divergent or indeterminate under refinement.
pub const PEAK_MOVES: &str = "peak moves between events";
