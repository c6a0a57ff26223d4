//! The run of a line of several conductors ([`crate::scenario::line::LinePlan`]): one short loop over the
//! line's time levels that applies each conductor's events, steps the line ([`LineExplicit`]) and notifies
//! the observers.
//!
//! Each conductor gets the standard outputs of a single-conductor run (its own `timeseries.csv`,
//! `snapshots.csv` and peaks, tracked every level, under `conductors/NAME/`); the line adds, every level:
//!
//! - the least distance between every pair of conductor groups (phase to phase, phase to earth wire, bundle
//!   to bundle: [`crate::line::clearance`]) with its minimum, where (the Lagrangian coordinates of the two
//!   closest points, as fractions of each conductor's unstretched length) and when, in `summary.json`, and
//!   sampled in `clearances.csv`;
//! - each tower's resultant (the force of every attachment on it) with its largest magnitude and when, and
//!   its displacement, sampled in `towers.csv`.
//!
//! Asking for more output never changes the trajectory: samples are taken at the first level at or after
//! their time; only events land the clock. [`run_line_observed`] takes further observers per conductor and
//! can keep the line's samples in memory ([`LineSamples`]: the numbers of `clearances.csv` and
//! `towers.csv`), for a caller that wants arrays rather than files (the Python package).

use std::path::{Path, PathBuf};
use std::time::Instant;

use serde::Serialize;

use crate::element::scalar::dot3;
use crate::events::EventState;
use crate::line::clearance::{ClearanceTracker, LeastClearance};
use crate::line::{LinkKind, Role};
use crate::output::clock::{LANDING, SampleClock};
use crate::output::cpu_time::{CpuStopwatch, per_second};
use crate::output::peaks::Peak;
use crate::output::rows::{RowFile, write_atomically};
use crate::output::{Peaks, ProbePoint, Snapshots, Timeseries};
use crate::run::phase_cycles::PhaseClock;
use crate::scenario::build::Stop;
use crate::scenario::line::LinePlan;
use crate::scenario::work::{
    BUDGET_NODE_STEPS, BUDGET_OUTPUT_BYTES, BYTES_PER_NUMBER, CLEARANCE_MEASURED_SHARE, CLEARANCE_NS_PER_PAIR_NODE,
    CONTACT_NS_PER_PAIR_NODE, EM_NS_PER_NEAR_PAIR, EM_NS_PER_PAIR_NODE, EM_NS_PER_PAIR_PRODUCT, LINE_NS_PER_NODE_STEP,
};
use crate::scheme::{LineExplicit, LineInstability};

use super::{Control, Ending, Level, Observer, OutputError, Settle, timeseries_columns};

/// The summary of a conductor of the line.
#[derive(Clone, Debug, Serialize)]
pub struct ConductorSummary {
    /// its name
    pub name: String,
    /// "phase", "earth_wire" or "sub_conductor"
    pub role: String,
    /// largest segment tension over the run [N]
    pub peak_max_tension_n: f64,
    /// when [s]
    pub peak_max_tension_time_s: f64,
    /// largest segment tension at the end [N]
    pub final_max_tension_n: f64,
    /// mid-span displacement from the chord midpoint at the end [m]
    pub final_midspan_displacement_m: [f64; 3],
    /// largest-magnitude mid-span displacement per component over the run [m]
    pub peak_midspan_displacement_m: [Peak; 3],
    /// largest increase of the mid-span displacement per component from its value at the start of the
    /// peaks' window, `>= 0` (the jump of a conductor shedding its ice is component 3) [m]
    pub peak_midspan_rise_m: [Peak; 3],
    /// largest decrease likewise, `<= 0` [m]
    pub peak_midspan_fall_m: [Peak; 3],
    /// mean period of each mid-span component's oscillation about the chord point, from its sign changes
    /// (`crate::output::peaks`); `null` without two crossings in the same direction [s]
    pub midspan_period_about_chord_s: [Option<f64>; 3],
    /// whether its peak tension comes from the wind's onset ([`crate::output::start_up`]): present when
    /// the wind is raised during the run or acts from `t = 0` on a line not started from its equilibrium
    #[serde(skip_serializing_if = "Option::is_none")]
    pub start_up: Option<crate::output::start_up::StartUp>,
}

/// The least clearance of a pair of conductor groups.
#[derive(Clone, Debug, Serialize)]
pub struct ClearanceSummary {
    /// the two groups (phases, earth wires, bundles) by name
    pub between: [String; 2],
    /// the least distance over the run, every level [m]
    pub least_m: f64,
    /// when [s]
    pub time_s: f64,
    /// the two conductors at the least distance
    pub conductors: [String; 2],
    /// where on each: fraction of its unstretched length from its first node [-]
    pub at_fraction: [f64; 2],
    /// the two closest points then [m]
    pub points_m: [[f64; 3]; 2],
    /// the distance at the start [m]; none (`null` in `summary.json`) if no pair of segments was left to
    /// measure (a conductor broken in every segment)
    pub initial_m: Option<f64>,
    /// the distance at the end [m]; none as for `initial_m`
    pub final_m: Option<f64>,
}

/// The loads on a tower.
#[derive(Clone, Debug, Serialize)]
pub struct TowerSummary {
    /// its name
    pub name: String,
    /// resultant of all attachments at the end [N]
    pub final_force_n: [f64; 3],
    /// the resultant of largest magnitude over the run [N]
    pub peak_force_n: [f64; 3],
    /// its magnitude [N]
    pub peak_force_magnitude_n: f64,
    /// when [s]
    pub peak_force_time_s: f64,
    /// displacement of an elastic top at the end [m] (0 for a rigid tower)
    pub final_displacement_m: [f64; 3],
}

/// The largest force in the attachments of one kind (strings, spacer arms, ...).
#[derive(Clone, Debug, Serialize)]
pub struct AttachmentSummary {
    /// "suspension_string", "tension_string", "spacer" or "interphase_spacer"
    pub kind: String,
    /// how many of this kind
    pub count: usize,
    /// the attachment with the largest tension magnitude (its index in the line's links)
    pub link: usize,
    /// its two ends, e.g. "A.1 node 63" and "A.2 node 63", or "T2"
    pub ends: [String; 2],
    /// its tension of largest magnitude, with its sign (negative: a spacer arm in compression) [N]
    pub peak_tension_n: f64,
    /// when [s]
    pub time_s: f64,
}

/// An event as applied.
#[derive(Clone, Debug, Serialize)]
pub struct LineEventRecord {
    /// when [s]
    pub time_s: f64,
    /// the conductor
    pub conductor: String,
    /// what
    pub what: String,
}

/// `summary.json` of a line run.
#[derive(Clone, Debug, Serialize)]
pub struct LineSummary {
    /// scenario name
    pub name: String,
    /// "completed", "settled", "not_settled" or "unstable"
    pub status: String,
    /// time reached [s]
    pub final_time_s: f64,
    /// steps taken
    pub steps: u64,
    /// nominal step [s]
    pub dt_s: f64,
    /// wall time of the loop [s]
    pub wall_time_s: f64,
    /// node-steps (all conductors) per wall second (falls when other processes share the processor)
    pub node_steps_per_second: f64,
    /// CPU time of the loop, the thread's ([`crate::output::cpu_time`]) [s]; absent where the system has
    /// no thread clock
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cpu_time_s: Option<f64>,
    /// node-steps (all conductors) per CPU second: nearly independent of the machine's load
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cpu_node_steps_per_second: Option<f64>,
    /// per conductor
    pub conductors: Vec<ConductorSummary>,
    /// per pair of conductor groups
    pub clearances: Vec<ClearanceSummary>,
    /// levels at which the clearances were measured, and levels in all: a level is measured when a new
    /// least distance is possible there ([`ClearanceTracker::observe_bounded`]) or a sample is due
    pub clearance_levels_measured: [u64; 2],
    /// per tower
    pub towers: Vec<TowerSummary>,
    /// per kind of attachment, its largest force (every level)
    pub attachments: Vec<AttachmentSummary>,
    /// the events applied
    pub events: Vec<LineEventRecord>,
    /// why the run stopped early, if it did: time, conductor, node and reason
    pub instability: Option<String>,
    /// the short circuit's results ([`super::short_circuit`]); absent without `[short_circuit]`
    #[serde(skip_serializing_if = "Option::is_none")]
    pub short_circuit: Option<super::short_circuit::ShortCircuitSummary>,
}

/// What a line run leaves.
#[derive(Clone, Debug)]
pub struct LineOutcome {
    /// its summary
    pub summary: LineSummary,
    /// the line's samples, if [`LineRunOptions::record`] was set (else empty)
    pub samples: LineSamples,
    /// the line at the end
    pub line: LineExplicit,
}

/// How to run a line ([`run_line_observed`]).
#[derive(Clone, Debug, Default)]
pub struct LineRunOptions {
    /// directory for the line's files (none: nothing is written)
    pub out_dir: Option<PathBuf>,
    /// keep the line's samples in memory ([`LineOutcome::samples`])
    pub record: bool,
}

/// The line's samples kept in memory: the rows of `clearances.csv` and `towers.csv`, the same numbers
/// at the same levels (the first level at or after each multiple of the sample interval).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LineSamples {
    /// the pairs of conductor groups, by name, in the order of the clearance columns
    pub pairs: Vec<[String; 2]>,
    /// the towers' names, in the order of their columns
    pub towers: Vec<String>,
    /// sample times [s]
    pub t_s: Vec<f64>,
    /// the least distance of each pair [m] (NaN where none can be measured), row-major `(samples, pairs)`
    pub clearance_m: Vec<f64>,
    /// each tower's resultant `f1, f2, f3` [N], row-major `(samples, towers, 3)`
    pub tower_force_n: Vec<f64>,
    /// each tower top's horizontal displacement `u1, u2` [m], row-major `(samples, towers, 2)`
    pub tower_displacement_m: Vec<f64>,
}

/// Why a line run failed.
#[derive(Debug, thiserror::Error)]
pub enum LineRunError {
    /// an output could not be written
    #[error(transparent)]
    Io(#[from] OutputError),
    /// the scheme went unstable (the files hold what was written so far)
    #[error("{instability}")]
    Unstable {
        /// when, which conductor, which node, why
        instability: LineInstability,
        /// the state at that time
        outcome: Box<LineOutcome>,
    },
}

/// The sizes of a line's elements that set the cost of one of its levels beyond the kernel's node-steps
/// (the cost model of [`crate::scenario::work`], "A line"): sums over pairs of conductors of their node
/// counts `n_a + n_b` (and products `n_a n_b`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LineElementSizes {
    /// the contact's pairs ([`crate::line::contact`], evaluated every level): sum of `n_a + n_b` [nodes]
    pub contact_pair_nodes: f64,
    /// the clearance tracker's conductor pairs (every two conductors of two different groups, measured
    /// at some levels, [`crate::line::clearance`]): sum of `n_a + n_b` [nodes]
    pub clearance_pair_nodes: f64,
    /// the short circuit's carrier pairs of two phases (by chords, evaluated while current flows,
    /// [`crate::scheme::electromagnetic`]): sum of `n_a + n_b` [nodes]
    pub em_pair_nodes: f64,
    /// the same pairs' sum of `n_a n_b`, times `k0^2 M0 / (k^2 M)` (the chords' `k` segments and refresh
    /// every `M` steps against the defaults `k0 = 4`, `M0 = 8` that `ohl bench --costs` measures) [nodes^2]
    pub em_pair_products: f64,
    /// the near field of two carriers of one phase (segment against segment, every level): the sum over
    /// the ordered pairs of `n_b min(2 w + 1, n_a)`, `w` the near window [segment pairs]
    pub em_near_products: f64,
}

impl LineElementSizes {
    /// The sizes of `line`'s contact and electromagnetic load (as set on it) and of the clearance
    /// tracking of `groups` (the conductor groups of [`LinePlan::groups`]).
    pub fn of(line: &LineExplicit, groups: &[Vec<usize>]) -> LineElementSizes {
        let nodes = |c: usize| line.conductors()[c].wire().nodes() as f64;
        let mut z = LineElementSizes::default();
        if let Some(ct) = line.contact() {
            z.contact_pair_nodes = ct.spec().pairs.iter().map(|p| nodes(p.a) + nodes(p.b)).sum();
        }
        for (g, ga) in groups.iter().enumerate() {
            for gb in &groups[g + 1..] {
                for &a in ga {
                    for &b in gb {
                        z.clearance_pair_nodes += nodes(a) + nodes(b);
                    }
                }
            }
        }
        if let Some(em) = line.electromagnetic() {
            let (k, m) = (em.numerics.chord_segments as f64, em.numerics.refresh_steps as f64);
            let chords = 4.0 * 4.0 * 8.0 / (k * k * m);
            let window = 2.0 * line.em_near_window().unwrap_or(0) as f64 + 1.0;
            for (i, ca) in em.carriers.iter().enumerate() {
                for cb in &em.carriers[i + 1..] {
                    let (na, nb) = (nodes(ca.conductor), nodes(cb.conductor));
                    if ca.phase != cb.phase {
                        z.em_pair_nodes += na + nb;
                        z.em_pair_products += chords * na * nb;
                    } else if ca.conductor != cb.conductor {
                        z.em_near_products += nb * window.min(na) + na * window.min(nb);
                    }
                }
            }
        }
        z
    }

    /// CPU time of one level's contact and clearances at the constants of [`crate::scenario::work`] [s].
    pub fn every_level_s(&self) -> (f64, f64) {
        (
            1e-9 * CONTACT_NS_PER_PAIR_NODE * self.contact_pair_nodes,
            1e-9 * CLEARANCE_MEASURED_SHARE * CLEARANCE_NS_PER_PAIR_NODE * self.clearance_pair_nodes,
        )
    }

    /// CPU time of one level's pair forces while current flows [s].
    pub fn em_level_s(&self) -> f64 {
        1e-9 * (EM_NS_PER_PAIR_NODE * self.em_pair_nodes
            + EM_NS_PER_PAIR_PRODUCT * self.em_pair_products
            + EM_NS_PER_NEAR_PAIR * self.em_near_products)
    }
}

/// The work of a line run, estimated before it runs as for one conductor ([`crate::scenario::work`]):
/// every conductor's nodes at every step of the line, `steps = ceil(T / dt) + 1`; the output is every
/// conductor's time series and snapshots, the clearances and the towers, at most
/// [`BYTES_PER_NUMBER`] bytes a number. Its CPU time is the cost model of [`crate::scenario::work`]
/// ("A line"): the kernel's node-steps, the contact and the clearances every level, the pair forces at
/// the levels while current flows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineWorkEstimate {
    /// conductors of the line (a bundle's sub-conductors each) [-]
    pub conductors: usize,
    /// nodes of all the conductors [-]
    pub nodes: usize,
    /// the line's time step [s]
    pub dt_s: f64,
    /// the latest time the run may reach [s]
    pub horizon_s: f64,
    /// time steps [-]
    pub steps: f64,
    /// node-steps of all the conductors [node-steps]
    pub node_steps: f64,
    /// bytes of all the output files (upper bound) [bytes]
    pub output_bytes: f64,
    /// levels at which short-circuit current flows (within the horizon) [-]
    pub current_steps: f64,
    /// the sizes of the line's contact, clearances and pair forces
    pub sizes: LineElementSizes,
}

/// Why a line run is refused before it starts.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum LineRefusal {
    /// The step does not advance the clock: the run could never end (no flag allows it).
    #[error("the time step {:e} s does not advance the clock at the end time {:e} s", .0.dt_s, .0.horizon_s)]
    TimeStalls(LineWorkEstimate),
    /// Above [`BUDGET_NODE_STEPS`] or [`BUDGET_OUTPUT_BYTES`].
    #[error(
        "the run needs {:.3e} node-steps (budget {BUDGET_NODE_STEPS:.1e}) and up to {:.3e} bytes of output \
         (budget {BUDGET_OUTPUT_BYTES:.1e}): use coarser grids, a shorter end time or a longer sample interval, \
         or pass --allow-large",
        .0.node_steps,
        .0.output_bytes
    )]
    Budget(LineWorkEstimate),
}

impl LineWorkEstimate {
    /// The estimate of a run of `plan`.
    pub fn of(plan: &LinePlan) -> LineWorkEstimate {
        let nodes: usize = plan.line.conductors().iter().map(|c| c.wire().nodes()).sum();
        let (dt, horizon) = (plan.line.params().dt_s, plan.stop.horizon_s());
        let steps = (horizon / dt).ceil() + 1.0;
        let rows = (horizon / plan.sample_interval_s).ceil() + 2.0;
        let mut numbers = 0.0;
        for p in &plan.plans {
            let columns = timeseries_columns(p).header().len() as f64;
            numbers += rows * columns + (p.snapshot_times_s.len() + 1) as f64 * p.solver.wire().nodes() as f64 * 11.0;
        }
        let pairs = plan.groups.len() * plan.groups.len().saturating_sub(1) / 2;
        numbers += rows * (1 + pairs + 5 * plan.line.supports().count()) as f64;
        // The levels in the flow intervals [start, end) up to the horizon: one per step of dt.
        let current_steps = plan.line.electromagnetic().map_or(0.0, |em| {
            em.current
                .intervals_s()
                .iter()
                .map(|&(a, b)| ((b.min(horizon) - a.min(horizon)) / dt).ceil().max(0.0))
                .sum()
        });
        LineWorkEstimate {
            conductors: plan.line.conductors().len(),
            nodes,
            dt_s: dt,
            horizon_s: horizon,
            steps,
            node_steps: nodes as f64 * steps,
            output_bytes: BYTES_PER_NUMBER * numbers,
            current_steps,
            sizes: LineElementSizes::of(&plan.line, &plan.groups),
        }
    }

    /// The estimated CPU time of the run on one core, per element [s]: the kernel's node-steps (with the
    /// conductors' observers), the contact, the clearances, the pair forces ([`crate::scenario::work`]).
    pub fn cpu_time_parts_s(&self) -> [f64; 4] {
        let (contact, clearance) = self.sizes.every_level_s();
        [
            1e-9 * LINE_NS_PER_NODE_STEP * self.node_steps,
            contact * self.steps,
            clearance * self.steps,
            self.sizes.em_level_s() * self.current_steps,
        ]
    }

    /// Estimated time on one core [s]: the sum of [`LineWorkEstimate::cpu_time_parts_s`].
    pub fn wall_time_s(&self) -> f64 {
        self.cpu_time_parts_s().iter().sum()
    }

    /// `Err` if the run cannot end: its step does not advance the clock at the horizon.
    pub fn check_resolvable(&self) -> Result<(), LineRefusal> {
        let (dt, horizon) = (self.dt_s, self.horizon_s);
        if dt > 0.0 && horizon.is_finite() && horizon + dt > horizon {
            Ok(())
        } else {
            Err(LineRefusal::TimeStalls(*self))
        }
    }

    /// `Err` if the run cannot end, or is above [`BUDGET_NODE_STEPS`] or [`BUDGET_OUTPUT_BYTES`].
    pub fn check(&self) -> Result<(), LineRefusal> {
        self.check_resolvable()?;
        if self.node_steps > BUDGET_NODE_STEPS || self.output_bytes > BUDGET_OUTPUT_BYTES {
            return Err(LineRefusal::Budget(*self));
        }
        Ok(())
    }
}

/// A conductor's name as a file or column name: letters, digits, '-' and '.', the rest '_'.
pub fn slug(name: &str) -> String {
    name.chars().map(|c| if c.is_ascii_alphanumeric() || c == '-' || c == '.' { c } else { '_' }).collect()
}

/// The standard observers of one conductor.
struct ConductorOutputs {
    peaks: Peaks,
    settle: Option<Settle>,
    series: Option<Timeseries>,
    snaps: Option<Snapshots>,
    mid: ProbePoint,
}

impl ConductorOutputs {
    /// The observers in their order (peaks, settle, series, snapshots), from an array on the stack: no
    /// allocation (this was a `Vec` built at every level).
    fn each(&mut self) -> impl Iterator<Item = &mut dyn Observer> {
        let ConductorOutputs { peaks, settle, series, snaps, .. } = self;
        [
            Some(peaks as &mut dyn Observer),
            settle.as_mut().map(|o| o as &mut dyn Observer),
            series.as_mut().map(|o| o as &mut dyn Observer),
            snaps.as_mut().map(|o| o as &mut dyn Observer),
        ]
        .into_iter()
        .flatten()
    }

    /// Every observer's [`Observer::observe`] of the level, in the order of [`ConductorOutputs::each`]
    /// (each one called, whatever the others answer), called directly rather than through `dyn`: whether
    /// any of them answered [`Control::Settled`].
    fn observe(&mut self, level: &Level) -> Result<bool, OutputError> {
        let mut settled = self.peaks.observe(level)? == Control::Settled;
        if let Some(o) = self.settle.as_mut() {
            settled |= o.observe(level)? == Control::Settled;
        }
        if let Some(o) = self.series.as_mut() {
            settled |= o.observe(level)? == Control::Settled;
        }
        if let Some(o) = self.snaps.as_mut() {
            settled |= o.observe(level)? == Control::Settled;
        }
        Ok(settled)
    }
}

/// Run the line to its end (or until every conductor has settled after the last event), writing into
/// `out_dir` if given.
pub fn run_line(plan: LinePlan, out_dir: Option<&Path>) -> Result<LineOutcome, LineRunError> {
    let opts = LineRunOptions { out_dir: out_dir.map(Path::to_path_buf), record: false };
    run_line_observed(plan, &opts, &mut [])
}

/// [`run_line`] with further observers of each conductor (`extra[c]` after conductor `c`'s standard
/// outputs; `extra` may be shorter than the line) and, with [`LineRunOptions::record`], the line's samples
/// kept in memory. Observers cannot change the state: the run is the same with or without them.
pub fn run_line_observed<'o>(
    plan: LinePlan,
    opts: &LineRunOptions,
    extra: &mut [Vec<&mut (dyn Observer + 'o)>],
) -> Result<LineOutcome, LineRunError> {
    let out_dir = opts.out_dir.as_deref();
    let mut line = plan.line.clone();
    let n = line.conductors().len();
    let names: Vec<String> = line.names().to_vec();
    let mut timelines: Vec<EventState> = plan.plans.iter().map(|p| p.timeline()).collect();
    if let Some(d) = out_dir {
        std::fs::create_dir_all(d).map_err(OutputError::at(d))?;
    }
    let mut outputs = Vec::with_capacity(n);
    for (c, p) in plan.plans.iter().enumerate() {
        let wire = line.conductors()[c].wire();
        let mid = ProbePoint::new(crate::output::probe::MIDSPAN, 0.5, wire);
        let from_s = p.peaks_from_s.unwrap_or_else(|| p.events.first().map_or(0.0, |e| e.time_s));
        let peaks = Peaks::new(from_s, vec![mid.clone()], wire.supports().len(), p.spans.clone(), p.ground.clone());
        let settle = match p.stop {
            Stop::Settled { fraction, window_s, .. } => Some(Settle::new(fraction, window_s)),
            Stop::EndTime(_) => None,
        };
        let (series, snaps) = match out_dir {
            Some(d) => {
                let dir = d.join("conductors").join(slug(&names[c]));
                std::fs::create_dir_all(&dir).map_err(OutputError::at(&dir))?;
                let ts =
                    Timeseries::with_columns(&dir.join("timeseries.csv"), p.sample_interval_s, timeseries_columns(p))?;
                (Some(ts), Some(Snapshots::create(&dir.join("snapshots.csv"), p.snapshot_times_s.clone())?))
            }
            None => (None, None),
        };
        outputs.push(ConductorOutputs { peaks, settle, series, snaps, mid });
    }
    let mut clearance = ClearanceTracker::new(plan.groups.clone());
    let pair_names: Vec<[String; 2]> =
        clearance.pairs().iter().map(|&(a, b)| [plan.group_names[a].clone(), plan.group_names[b].clone()]).collect();
    let towers: Vec<String> = line.supports().map(|s| s.name.clone()).collect();
    let mut resultants: Vec<[f64; 3]> = Vec::with_capacity(towers.len());
    // Scratch of `support_resultant_into`: a conductor's support reactions, kept between levels.
    let mut reactions: Vec<(usize, [f64; 3])> = Vec::new();
    let mut files = match out_dir {
        Some(d) => {
            let mut head = vec!["t_s".to_string()];
            head.extend(pair_names.iter().map(|[a, b]| format!("clearance_{}_{}_m", slug(a), slug(b))));
            let cl = RowFile::create(&d.join("clearances.csv"), &head)
                .map_err(OutputError::at(&d.join("clearances.csv")))?;
            let mut head = vec!["t_s".to_string()];
            for t in &towers {
                let t = slug(t);
                head.extend(["f1_n", "f2_n", "f3_n", "u1_m", "u2_m"].map(|q| format!("{t}_{q}")));
            }
            let tw = RowFile::create(&d.join("towers.csv"), &head).map_err(OutputError::at(&d.join("towers.csv")))?;
            Some((cl, tw))
        }
        None => None,
    };
    // A phase's members for its tension and swing: its conductor or its bundle's sub-conductors, not its
    // droppers.
    let members = crate::line::dropper::without_droppers(&plan.groups, line.links());
    let mut short = match &plan.short_circuit {
        Some(sc) if line.electromagnetic().is_some() => Some(super::short_circuit::ShortCircuitTracker::new(
            &line,
            &sc.phases,
            &plan.group_names,
            &members,
            out_dir,
        )?),
        _ => None,
    };
    let mut clock = SampleClock::new(plan.sample_interval_s);
    let mut samples = opts.record.then(|| LineSamples {
        pairs: pair_names.clone(),
        towers: towers.clone(),
        ..LineSamples::default()
    });
    // The largest tension magnitude of each link kind: (link, tension, time).
    let kinds = [
        LinkKind::SuspensionString,
        LinkKind::TensionString,
        LinkKind::Spacer,
        LinkKind::InterphaseSpacer,
        LinkKind::Clamp,
    ];
    let mut link_peak: Vec<Option<(usize, f64, f64)>> = vec![None; kinds.len()];
    let mut tower_peak: Vec<([f64; 3], f64, f64)> = vec![([0.0; 3], 0.0, 0.0); towers.len()];
    let mut initial_clearance: Vec<Option<f64>> = Vec::new();
    let mut log: Vec<LineEventRecord> = Vec::new();
    let (dt, horizon) = (line.params().dt_s, plan.stop.horizon_s());
    let tol = LANDING * dt;
    let started = Instant::now();
    let cpu = CpuStopwatch::start();
    let mut failure: Option<LineInstability> = None;
    // Cycles per phase, with the feature `phase-timing` only ([`super::phase_cycles`]).
    let mut phases = PhaseClock::new(
        [
            "forces of a level (every conductor's segment pass, the links, the short-circuit pair forces)",
            "short-circuit observer (the IEC 60865 quantities)",
            "every conductor's outputs (peaks, time series, settle, ...)",
            "clearances between conductors",
            "links' and towers' peaks, line samples",
            "step (every conductor's node pass, ground contact, links)",
        ]
        .into_iter()
        .map(String::from),
    );
    const FORCES: usize = 0;
    const SHORT_CIRCUIT: usize = 1;
    const OUTPUTS: usize = 2;
    const CLEARANCES: usize = 3;
    const LINKS_TOWERS: usize = 4;
    const STEP: usize = 5;
    let ending = loop {
        let t = line.time_s();
        for c in 0..n {
            let applied = timelines[c].apply_due(line.conductor_mut(c), t, tol);
            if applied > 0 {
                let tl = &timelines[c].log;
                let what = tl[tl.len() - applied..].iter().map(|(_, w)| w.as_str()).collect::<Vec<_>>().join("; ");
                outputs[c].each().for_each(|o| o.event(t, &what));
                if let Some(x) = extra.get_mut(c) {
                    x.iter_mut().for_each(|o| o.event(t, &what));
                }
                log.push(LineEventRecord { time_s: t, conductor: names[c].clone(), what });
            }
            timelines[c].before_step(line.conductor_mut(c), t);
        }
        let from = phases.mark();
        line.evaluate_forces();
        phases.add(FORCES, from);
        let from = phases.mark();
        if let Some(sc) = short.as_mut() {
            sc.observe(&line, t)?;
        }
        phases.add(SHORT_CIRCUIT, from);
        let from = phases.mark();
        let mut all_settled = true;
        for c in 0..n {
            let level = Level { solver: &line.conductors()[c], t_s: t, tau_per_s: plan.plans[c].tau(1.0) };
            let mut settled = outputs[c].observe(&level)?;
            for o in extra.get_mut(c).into_iter().flatten() {
                settled |= o.observe(&level)? == Control::Settled;
            }
            all_settled &= settled;
        }
        phases.add(OUTPUTS, from);
        let from = phases.mark();
        let sampling = files.is_some() || samples.is_some();
        let sample_due = sampling && clock.next_s() <= t + tol;
        let first = line.steps() == 0;
        clearance.observe_bounded(line.conductors(), t, sample_due || first);
        phases.add(CLEARANCES, from);
        let from = phases.mark();
        if first {
            initial_clearance = clearance.current().iter().map(|c| c.map(|c| c.closest.distance_m)).collect();
        }
        for l in 0..line.links().len() {
            let k = kinds.iter().position(|&k| k == line.links()[l].kind).unwrap_or(0);
            let tl = line.link_tension_n(l);
            if link_peak[k].is_none_or(|(_, v, _)| tl.abs() > v.abs()) {
                link_peak[k] = Some((l, tl, t));
            }
        }
        // Each tower's resultant, once a level: for its peak, and for the sample if one is due.
        resultants.clear();
        resultants.extend((0..towers.len()).map(|s| line.support_resultant_into(s, &mut reactions)));
        for (s, &f) in resultants.iter().enumerate() {
            let m = dot3(f, f).sqrt();
            if m > tower_peak[s].1 {
                tower_peak[s] = (f, m, t);
            }
        }
        if sampling && clock.due(t, tol) {
            let distance = |c: &Option<LeastClearance>| c.map_or(f64::NAN, |c| c.closest.distance_m);
            if let Some((cl, tw)) = files.as_mut() {
                cl.number(t);
                for c in clearance.current() {
                    cl.number(distance(c));
                }
                cl.end_row();
                tw.number(t);
                for (s, &f) in resultants.iter().enumerate() {
                    let u = line.support_displacement_m(s);
                    for v in [f[0], f[1], f[2], u[0], u[1]] {
                        tw.number(v);
                    }
                }
                tw.end_row();
                cl.commit().map_err(OutputError::at(&out_dir.unwrap_or(Path::new(".")).join("clearances.csv")))?;
                tw.commit().map_err(OutputError::at(&out_dir.unwrap_or(Path::new(".")).join("towers.csv")))?;
            }
            if let Some(r) = samples.as_mut() {
                r.t_s.push(t);
                r.clearance_m.extend(clearance.current().iter().map(distance));
                for (s, f) in resultants.iter().enumerate() {
                    let u = line.support_displacement_m(s);
                    r.tower_force_n.extend_from_slice(f);
                    r.tower_displacement_m.extend_from_slice(&u[..2]);
                }
            }
        }
        phases.add(LINKS_TOWERS, from);
        let pending = timelines.iter().any(|tl| tl.next_time().is_some());
        if all_settled && !pending {
            break Ending::Settled;
        }
        if t >= horizon - tol {
            break if matches!(plan.stop, Stop::Settled { .. }) { Ending::NotSettled } else { Ending::Completed };
        }
        let next = timelines.iter().filter_map(|tl| tl.next_time()).fold(horizon, f64::min);
        let target = next.min(horizon);
        let h = if target - t <= dt * (1.0 + 1.0e-12) { target - t } else { dt };
        let from = phases.mark();
        let stepped = line.step(h);
        phases.add(STEP, from);
        phases.count_step();
        if let Err(e) = stepped {
            let source = e.source.clone();
            failure = Some(e);
            break Ending::Unstable(source);
        }
        if h < dt {
            line.land_on(target);
        }
        for c in 0..n {
            timelines[c].after_step(line.conductor_mut(c), h);
        }
    };
    phases.report();
    line.evaluate_forces();
    if failure.is_none() {
        // The final values are measured (the last level may have been skipped by the bound).
        clearance.observe(line.conductors(), line.time_s());
    }
    for c in 0..n {
        let level = Level { solver: &line.conductors()[c], t_s: line.time_s(), tau_per_s: plan.plans[c].tau(1.0) };
        for o in outputs[c].each() {
            o.finish(&level, &ending)?;
        }
        for o in extra.get_mut(c).into_iter().flatten() {
            o.finish(&level, &ending)?;
        }
    }
    if let Some((cl, tw)) = files.as_mut() {
        let d = out_dir.unwrap_or(Path::new("."));
        cl.finish().map_err(OutputError::at(&d.join("clearances.csv")))?;
        tw.finish().map_err(OutputError::at(&d.join("towers.csv")))?;
    }
    let short_circuit = match short {
        Some(sc) => {
            let least: Vec<([String; 2], f64, f64)> = clearance
                .least()
                .iter()
                .zip(&pair_names)
                .filter_map(|(l, between)| l.map(|l| (between.clone(), l.closest.distance_m, l.time_s)))
                .collect();
            Some(sc.finish(&line, &least)?)
        }
        None => None,
    };
    let wall = started.elapsed().as_secs_f64();
    let cpu_s = cpu.elapsed_s();
    let nodes: usize = line.conductors().iter().map(|c| c.wire().nodes()).sum();
    let summary = LineSummary {
        name: plan.name.clone(),
        status: ending.status().into(),
        final_time_s: line.time_s(),
        steps: line.steps(),
        dt_s: dt,
        wall_time_s: wall,
        node_steps_per_second: per_second(nodes as f64 * line.steps() as f64, wall),
        cpu_time_s: cpu_s,
        cpu_node_steps_per_second: cpu_s.map(|c| per_second(nodes as f64 * line.steps() as f64, c)),
        conductors: (0..n)
            .map(|c| {
                let s = &line.conductors()[c];
                let run = outputs[c].peaks.run();
                ConductorSummary {
                    name: names[c].clone(),
                    role: match line.roles()[c] {
                        Role::Phase => "phase",
                        Role::EarthWire => "earth_wire",
                        Role::SubConductor { .. } => "sub_conductor",
                    }
                    .into(),
                    peak_max_tension_n: run.max_tension.value_n,
                    peak_max_tension_time_s: run.max_tension.time_s,
                    final_max_tension_n: s.max_tension_n(),
                    final_midspan_displacement_m: outputs[c].mid.displacement(s.wire()),
                    peak_midspan_displacement_m: run.probes[0],
                    peak_midspan_rise_m: run.rises[0],
                    peak_midspan_fall_m: run.falls[0],
                    midspan_period_about_chord_s: run.crossings[0].map(|c| c.period_s()),
                    start_up: super::start_up::check(
                        &plan.plans[c],
                        s,
                        plan.initial_equilibrium.is_some(),
                        &[("max_tension".into(), run.max_tension.value_n, run.max_tension.time_s, s.max_tension_n())],
                    ),
                }
            })
            .collect(),
        clearance_levels_measured: [clearance.counts.0, clearance.counts.1],
        clearances: clearance
            .least()
            .iter()
            .zip(clearance.current())
            .zip(&pair_names)
            .zip(&initial_clearance)
            .filter_map(|(((least, now), between), &initial_m)| {
                let l = (*least)?;
                let (a, b) = l.conductors;
                let wires = line.wires();
                Some(ClearanceSummary {
                    between: between.clone(),
                    least_m: l.closest.distance_m,
                    time_s: l.time_s,
                    conductors: [names[a].clone(), names[b].clone()],
                    at_fraction: [l.closest.arc_fraction_a(wires[a]), l.closest.arc_fraction_b(wires[b])],
                    points_m: [l.closest.point_a_m, l.closest.point_b_m],
                    initial_m,
                    final_m: now.map(|c| c.closest.distance_m),
                })
            })
            .collect(),
        towers: (0..towers.len())
            .map(|s| TowerSummary {
                name: towers[s].clone(),
                final_force_n: line.support_resultant_n(s),
                peak_force_n: tower_peak[s].0,
                peak_force_magnitude_n: tower_peak[s].1,
                peak_force_time_s: tower_peak[s].2,
                final_displacement_m: line.support_displacement_m(s),
            })
            .collect(),
        attachments: kinds
            .iter()
            .zip(&link_peak)
            .filter_map(|(kind, peak)| {
                let (l, v, t) = (*peak)?;
                let end = |e: &crate::line::Endpoint| match *e {
                    crate::line::Endpoint::Node(n) => format!("{} node {}", names[n.conductor], n.node),
                    crate::line::Endpoint::Support { support, .. } => towers[support].clone(),
                };
                let link = &line.links()[l];
                Some(AttachmentSummary {
                    kind: match kind {
                        LinkKind::SuspensionString => "suspension_string",
                        LinkKind::TensionString => "tension_string",
                        LinkKind::Spacer => "spacer",
                        LinkKind::InterphaseSpacer => "interphase_spacer",
                        LinkKind::Clamp => "dropper_clamp",
                    }
                    .into(),
                    count: line.links().iter().filter(|x| x.kind == *kind).count(),
                    link: l,
                    ends: [end(&link.a), end(&link.b)],
                    peak_tension_n: v,
                    time_s: t,
                })
            })
            .collect(),
        events: log,
        instability: failure.as_ref().map(|f| f.to_string()),
        short_circuit,
    };
    if let Some(d) = out_dir {
        let text = serde_json::to_string_pretty(&summary).expect("the summary serialises") + "\n";
        let path = d.join("summary.json");
        write_atomically(&path, &text).map_err(OutputError::at(&path))?;
    }
    let outcome = LineOutcome { summary, samples: samples.unwrap_or_default(), line };
    match failure {
        Some(instability) => Err(LineRunError::Unstable { instability, outcome: Box::new(outcome) }),
        None => Ok(outcome),
    }
}
