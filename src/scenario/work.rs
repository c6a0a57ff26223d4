//! How much work a run is, before it runs: steps, node-steps, heat sub-steps, output rows and bytes,
//! estimated from a built [`Plan`], and a budget that refuses runs far beyond what a scenario normally
//! asks (an end time of 1e12 s, or `EA = 1e30 N` giving a time step of 1e-15 s, would otherwise run for
//! years or fill the disk). Every number is an `f64`, so no input can overflow or panic here; an
//! infinite or NaN estimate is over any budget.
//!
//! # Derivation (units in brackets)
//!
//! With `N` segments (`N + 1` nodes), the nominal step `dt` [s] of (3.7), the horizon `T` [s]
//! ([`Stop::horizon_s`](super::build::Stop::horizon_s): the end time, or the time cap of a run until
//! settled, which may stop earlier: the estimate is an upper bound) and `E` events:
//!
//! - `steps = ceil(T / dt) + E` [-]: the run takes steps of `dt`, and each event may add one shortened
//!   step that lands on its time ([`crate::run`]);
//! - `node_steps = (N + 1) steps` [node-steps]: one step of the explicit kernel costs one segment pass
//!   and one node pass, so its cost is proportional to the node count;
//! - heat conduction (the `heat_conduction` event, [`crate::events::conduction`]) runs from its event to
//!   the next `heat_conduction`, `heat_conduction_off` or `temperature` event (or the horizon); over
//!   each run step it advances the rod by `dt * heat_time_per_s` units of dimensionless heat time in
//!   `ceil(dt * heat_time_per_s / (h^2 / 2))` sub-steps with `h = 1 / N` (at least one);
//!   `heat_substeps` [-] sums them over the steps of each stretch (`duration / dt + 1` steps), and
//!   `heat_node_updates = (N + 1) heat_substeps` [node-updates]; a heat node update (a three-point
//!   stencil) is cheaper than a kernel node-step, but the budget counts it as one (upper bound);
//! - `timeseries_rows = min(floor(T / interval) + 1, steps + 1)` [rows]: one row per sample interval,
//!   at most one per time level ([`crate::output::clock`]); a row has `10 + 3 probes + 3 supports`
//!   numbers;
//! - `snapshot_rows = (N + 1) (min(S, steps + 1) + 1)` [rows] for `S` snapshot times in `[0, T]`: a
//!   snapshot is one row per node, at most one per level, plus the final state; a row has 11 numbers;
//! - `output_bytes = 25 (numbers in all rows)` [bytes]: a number is written in its shortest
//!   round-trip form (`ryu`), at most 24 characters (`-1.2345678901234567e-300`), plus its separator.
//!
//! The time is `work_node_steps / throughput` [s] with the throughput of whole runs of the kind of
//! scenario on one core (kernel, observers and outputs together, per CPU second: `cpu_node_steps_per_second`
//! of `summary.json`, measured on the scenarios of the repository, issue 27):
//!
//! - one span, [`RUN_THROUGHPUT_SPAN`] = 1.2e8 node-steps/s: the paper cases ran at 1.2e8 to 2.6e8 on
//!   a Zen 5 (AVX-512 copies) and at about half that on a Zen 3 (fig2b at N = 50: 2.1e8 and 9.6e7), so
//!   the rate is the geometric middle of the two machines (figures/bench/README.md, issue 27, twelfth
//!   round; the first rate, 6e7, was the Zen 3's before the kernel's later rounds);
//! - a section (`[section]`), [`RUN_THROUGHPUT_SECTION`] = 2e8 node-steps/s: the mechanical examples
//!   and cases a-d (strings, spans, a ground) ran at 1.9e8 to 6.6e8 on the Zen 5 and 1.0e8 to 2.2e8 on
//!   the Zen 3 (whole-process CPU time there), the middle again;
//! - a line (`[line]`, [`crate::run::line::LineWorkEstimate`]): no single rate fits, since the elements
//!   a line adds cost more than its kernel and scale differently (whole runs of cases e-l ran at 1.2e6
//!   to 3.9e7 node-steps per CPU second). Its time is a sum per element, each an amount of work times
//!   a cost measured by `ohl bench --costs` (below):
//!
//!   ```text
//!   t = node_steps k_node                                         kernel, links, conductors' observers
//!     + steps k_contact sum_contact_pairs (n_a + n_b)             contact, every level
//!     + steps s k_clear sum_clearance_pairs (n_a + n_b)           clearances, a share s of the levels
//!     + current_steps sum_carrier_pairs (k_em1 (n_a + n_b) + k_em2 n_a n_b 128 / (k^2 M))  pair forces
//!     + current_steps k_near sum_near_pairs (n_b min(2 w + 1, n_a) + n_a min(2 w + 1, n_b))  near field
//!   ```
//!
//!   with `n_a` a conductor's nodes, the contact's pairs those of [`crate::line::contact`] (every two
//!   phases and a bundle's sub-conductors, set with a short circuit), the clearance pairs every two
//!   conductors of two different groups, the carrier pairs every two current carriers of different
//!   phases (by chords of `k` segments refreshed every `M` steps; the defaults 4 and 8 give the factor
//!   1), the near pairs two carriers of one phase on different conductors (a bundle's sub-conductors, a
//!   dropper and its busbar: segment against segment within the near window `w`, every level), and
//!   `current_steps` the levels inside the fault's flow intervals (the pair forces are evaluated only
//!   while current flows, [`crate::scheme::electromagnetic`]). The constants
//!   ([`LINE_NS_PER_NODE_STEP`], [`CONTACT_NS_PER_PAIR_NODE`], [`CLEARANCE_NS_PER_PAIR_NODE`],
//!   [`EM_NS_PER_PAIR_NODE`], [`EM_NS_PER_PAIR_PRODUCT`]) are the medians over N = 50, 100, 200 of
//!   `ohl bench --costs` on case j's three phases (the differences of a bare line, the line with the
//!   contact, with the contact and the pair forces, and with the clearances measured every level; the
//!   pair forces fitted to `k_em1 (n_a + n_b) + k_em2 n_a n_b`), measured on an AMD EPYC Zen 3 (family 25
//!   model 1) at load 3-5 and rounded; the measurements are in `figures/bench/README.md` (issue 27,
//!   third round). The clearance tracker measures a pair only when its distance may have become a new
//!   least ([`crate::line::clearance`]), which cannot be known before the run: cases e, j and l measured
//!   26 %, 38 % and 51 % of their levels, so [`CLEARANCE_MEASURED_SHARE`] = 0.35. The near field's
//!   constant [`EM_NS_PER_NEAR_PAIR`] is derived from the chords' (no workload of `ohl bench` has a near
//!   pair) and checked on case l, whose droppers are near pairs of their busbars. The estimate was within
//!   a factor 2 of the measured CPU time of cases e, j and l and of a paper case on the Zen 3 where the
//!   constants were measured; on a Zen 5 the lines' estimates are 1.5-2.1 times their CPU time (the
//!   constants were not measured again: an overestimate), and `app/tests/dry_run.rs` asserts a factor 3.
//!
//! The explicit kernel alone runs faster: [`THROUGHPUT_NODE_STEPS_PER_S`] = 1.5e8 node-steps/s on one
//! core for the 3D configurations with wind or internal friction at N >= 200 (`figures/bench/README.md`:
//! 1.3e8 to 1.6e8; the plane case without wind reaches 3.6e8, small N 1.0e8); the budget's time
//! ([`BUDGET_WALL_S`]) is stated at that rate.
//!
//! # The budget
//!
//! [`BUDGET_NODE_STEPS`] = 2e10 node-steps is about 130 s at that throughput (2-3 minutes on one
//! core): the largest paper case (`fig6_deicing`) needs 3.2e7 (`ohl run paper_cases/X.toml --dry-run`
//! prints each), so the budget is 600 times what the paper needs and still refuses a mistyped end time or stiffness before it
//! runs for hours. [`BUDGET_OUTPUT_BYTES`] = 2e9 bytes (2 GB) bounds the files of one run (the paper
//! cases are estimated at 8.3 MB at most). A scenario above either is refused ([`Refusal`]) unless the caller
//! allows large runs (`ohl run --allow-large`); a library caller decides by calling
//! [`WorkEstimate::check`] or not. A run whose time step is below the resolution of its time (`t + dt
//! == t` at the horizon) can never end and is refused even then ([`WorkEstimate::check_resolvable`]).

use std::fmt;

use super::build::Plan;
use crate::events::Action;

/// Node-steps (and heat node updates) a run may take without `--allow-large` [node-steps]: about 130 s
/// at [`THROUGHPUT_NODE_STEPS_PER_S`] (module documentation).
pub const BUDGET_NODE_STEPS: f64 = 2.0e10;

/// Bytes of output files a run may write without `--allow-large` [bytes] (2 GB).
pub const BUDGET_OUTPUT_BYTES: f64 = 2.0e9;

/// Throughput assumed for the wall-time estimate [node-steps/s] (one core; module documentation).
pub const THROUGHPUT_NODE_STEPS_PER_S: f64 = 1.5e8;

/// Throughput of whole runs of one span for the time estimate [node-steps/s] (CPU, one core; module
/// documentation).
pub const RUN_THROUGHPUT_SPAN: f64 = 1.2e8;

/// Throughput of whole runs of a section for the time estimate [node-steps/s] (module documentation).
pub const RUN_THROUGHPUT_SECTION: f64 = 2.0e8;

/// A line's kernel (with its links and the conductors' observers) [CPU ns per node-step] (module
/// documentation, "a line").
pub const LINE_NS_PER_NODE_STEP: f64 = 6.2;

/// The contact between conductors, every level [CPU ns per node of a contact pair] (module documentation).
pub const CONTACT_NS_PER_PAIR_NODE: f64 = 68.0;

/// The clearances, at a measured level [CPU ns per node of a conductor pair] (module documentation).
pub const CLEARANCE_NS_PER_PAIR_NODE: f64 = 86.0;

/// Share of the levels at which the clearances are measured, assumed [-] (module documentation).
pub const CLEARANCE_MEASURED_SHARE: f64 = 0.35;

/// The short circuit's pair forces while current flows, per node of a carrier pair [CPU ns] (module
/// documentation).
pub const EM_NS_PER_PAIR_NODE: f64 = 27.0;

/// The short circuit's pair forces while current flows, per product `n_a n_b` of a carrier pair [CPU ns]
/// (module documentation).
pub const EM_NS_PER_PAIR_PRODUCT: f64 = 2.5;

/// The near field of two carriers of one phase, per segment pair and level [CPU ns]: the force of one
/// filament on another, which a chord pair costs once per refresh in both directions,
/// [`EM_NS_PER_PAIR_PRODUCT`] `k0^2 M0 / 2` = 2.5 x 128 / 2 = 160 (module documentation).
pub const EM_NS_PER_NEAR_PAIR: f64 = 160.0;

/// [`BUDGET_NODE_STEPS`] at [`THROUGHPUT_NODE_STEPS_PER_S`] [s].
pub const BUDGET_WALL_S: f64 = BUDGET_NODE_STEPS / THROUGHPUT_NODE_STEPS_PER_S;

/// Upper bound of the bytes of one number in an output file, separator included [bytes].
pub const BYTES_PER_NUMBER: f64 = 25.0;

/// Numbers in a time-series row without named probes and supports [-].
const TIMESERIES_FIXED_COLUMNS: f64 = 10.0;

/// Numbers in a snapshot row [-].
const SNAPSHOT_COLUMNS: f64 = 11.0;

/// The work of a run, estimated before it runs (derivations in the module documentation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WorkEstimate {
    /// segments `N` [-]
    pub segments: f64,
    /// nominal time step `dt` [s]
    pub dt_s: f64,
    /// the latest time the run may reach `T` [s]
    pub horizon_s: f64,
    /// time steps, `ceil(T / dt) + events` [-]
    pub steps: f64,
    /// kernel node-steps, `(N + 1) steps` [node-steps]
    pub node_steps: f64,
    /// heat-conduction sub-steps [-]
    pub heat_substeps: f64,
    /// heat-conduction node updates, `(N + 1) heat_substeps` [node-updates]
    pub heat_node_updates: f64,
    /// rows of `timeseries.csv` [rows]
    pub timeseries_rows: f64,
    /// numbers per row of `timeseries.csv` [-]
    pub timeseries_columns: f64,
    /// rows of `snapshots.csv` [rows]
    pub snapshot_rows: f64,
    /// bytes of `timeseries.csv` and `snapshots.csv` together (upper bound) [bytes]
    pub output_bytes: f64,
    /// the `[[events]]` index of the `heat_conduction` event whose stretch takes the most heat sub-steps
    /// (`None` without heat conduction) [-]
    pub heat_event: Option<usize>,
    /// whether the scenario is a section of several spans (else one span) [-]
    pub sections: bool,
}

impl WorkEstimate {
    /// The estimate of a run of `plan` as it stands (its stop, sample interval, snapshots and events).
    pub fn of(plan: &Plan) -> WorkEstimate {
        let n = plan.solver.wire().segments() as f64;
        let nodes = n + 1.0;
        let dt = plan.solver.params().dt_s;
        let horizon = plan.stop.horizon_s();
        let events = plan.events.len() as f64;
        let steps = (horizon / dt).ceil().max(0.0) + events;
        let (heat_substeps, heat_event) = heat_substeps(plan, n, dt, horizon);
        let supports = plan.solver.wire().supports().len() as f64;
        let strings = plan.solver.wire().insulators.len() as f64;
        let span_columns = plan.spans.len() as f64 * if plan.ground.is_some() { 2.0 } else { 1.0 };
        let timeseries_columns =
            TIMESERIES_FIXED_COLUMNS + 3.0 * plan.probes.len() as f64 + 3.0 * supports + 4.0 * strings + span_columns;
        let grid = (horizon / plan.sample_interval_s).floor() + 1.0;
        let timeseries_rows = nan_is_inf(grid).min(steps + 1.0);
        let snapshots = plan.snapshot_times_s.iter().filter(|&&t| t <= horizon).count() as f64;
        let snapshot_rows = nodes * (snapshots.min(steps + 1.0) + 1.0);
        let output_bytes = BYTES_PER_NUMBER * (timeseries_rows * timeseries_columns + snapshot_rows * SNAPSHOT_COLUMNS);
        WorkEstimate {
            segments: n,
            dt_s: dt,
            horizon_s: horizon,
            steps: nan_is_inf(steps),
            node_steps: nan_is_inf(nodes * steps),
            heat_substeps,
            heat_node_updates: nan_is_inf(nodes * heat_substeps),
            timeseries_rows,
            timeseries_columns,
            snapshot_rows: nan_is_inf(snapshot_rows),
            output_bytes: nan_is_inf(output_bytes),
            heat_event,
            sections: !plan.spans.is_empty(),
        }
    }

    /// The work the budget counts: kernel node-steps plus heat node updates [node-steps].
    pub fn work_node_steps(&self) -> f64 {
        self.node_steps + self.heat_node_updates
    }

    /// The throughput the time estimate assumes: [`RUN_THROUGHPUT_SECTION`] for a section,
    /// [`RUN_THROUGHPUT_SPAN`] for one span [node-steps/s].
    pub fn throughput_node_steps_per_s(&self) -> f64 {
        if self.sections { RUN_THROUGHPUT_SECTION } else { RUN_THROUGHPUT_SPAN }
    }

    /// Estimated time on one core at [`WorkEstimate::throughput_node_steps_per_s`] [s].
    pub fn wall_time_s(&self) -> f64 {
        self.work_node_steps() / self.throughput_node_steps_per_s()
    }

    /// Whether the run's clock advances by a step at its horizon (`T + dt > T`); if not, the run could
    /// never reach its end.
    pub fn time_resolves(&self) -> bool {
        self.dt_s > 0.0 && self.horizon_s + self.dt_s > self.horizon_s
    }

    /// `Err` if the run is above [`BUDGET_NODE_STEPS`] or [`BUDGET_OUTPUT_BYTES`] (or cannot end).
    pub fn check(&self) -> Result<(), Refusal> {
        self.check_resolvable()?;
        // `is_le`: a NaN estimate fails the check.
        if !self.work_node_steps().partial_cmp(&BUDGET_NODE_STEPS).is_some_and(|o| o.is_le()) {
            return Err(Refusal::NodeSteps(*self));
        }
        if !self.output_bytes.partial_cmp(&BUDGET_OUTPUT_BYTES).is_some_and(|o| o.is_le()) {
            return Err(Refusal::OutputBytes(*self));
        }
        Ok(())
    }

    /// `Err` if the run cannot end: its step does not advance the clock at the horizon
    /// ([`WorkEstimate::time_resolves`]). No flag allows such a run.
    pub fn check_resolvable(&self) -> Result<(), Refusal> {
        if self.time_resolves() { Ok(()) } else { Err(Refusal::TimeStalls(*self)) }
    }
}

impl fmt::Display for WorkEstimate {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{:.3e} node-steps ({} nodes x {:.3e} steps of dt = {:.4e} s to t = {:.6e} s",
            self.work_node_steps(),
            self.segments + 1.0,
            self.steps,
            self.dt_s,
            self.horizon_s
        )?;
        if self.heat_node_updates > 0.0 {
            write!(f, ", plus {:.3e} heat node updates", self.heat_node_updates)?;
        }
        write!(
            f,
            "), about {:.3e} s at {:.1e} node-steps/s; output {:.3e} bytes",
            self.wall_time_s(),
            self.throughput_node_steps_per_s(),
            self.output_bytes
        )
    }
}

/// Why a run is refused before it starts.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum Refusal {
    /// More node-steps than [`BUDGET_NODE_STEPS`].
    #[error(
        "the run is estimated at {0}: above the budget of {BUDGET_NODE_STEPS:.1e} node-steps \
         (ohl::scenario::work::BUDGET_NODE_STEPS, about {BUDGET_WALL_S:.0} s); {hint}, or allow it with \
         --allow-large",
        hint = node_steps_hint(.0)
    )]
    NodeSteps(WorkEstimate),
    /// More output than [`BUDGET_OUTPUT_BYTES`].
    #[error(
        "the run is estimated at {0}: above the budget of {BUDGET_OUTPUT_BYTES:.1e} bytes of output \
         (ohl::scenario::work::BUDGET_OUTPUT_BYTES); check output.sample_interval_s and \
         output.snapshot_times_s, or allow it with --allow-large"
    )]
    OutputBytes(WorkEstimate),
    /// The step does not advance the clock: the run could never end (no flag allows it).
    #[error(
        "the time step dt = {:.4e} s is below the resolution of the end time {:.6e} s (t + dt == t): \
         the run could never end; check the conductor stiffness and geometry.segments",
        .0.dt_s,
        .0.horizon_s
    )]
    TimeStalls(WorkEstimate),
}

impl Refusal {
    /// The estimate refused.
    pub fn estimate(&self) -> &WorkEstimate {
        match self {
            Refusal::NodeSteps(e) | Refusal::OutputBytes(e) | Refusal::TimeStalls(e) => e,
        }
    }
}

impl Plan {
    /// The work of running this plan as it stands ([`WorkEstimate::of`]).
    pub fn work_estimate(&self) -> WorkEstimate {
        WorkEstimate::of(self)
    }

    /// The estimate if it is within the budget ([`WorkEstimate::check`]), else why not.
    pub fn check_budget(&self) -> Result<WorkEstimate, Refusal> {
        let e = self.work_estimate();
        e.check().map(|()| e)
    }
}

/// What drives a node-step refusal, in the fields that set it: the heat conduction where its sub-steps
/// are most of the work, else the duration and the kernel's time step.
fn node_steps_hint(e: &WorkEstimate) -> String {
    if e.heat_node_updates > e.node_steps {
        format!(
            "most of it is heat conduction ({:.3e} heat node updates): each run step of the heat_conduction events \
             takes ceil(dt heat_time_per_s / (h^2 / 2)) sub-steps with h = 1 / geometry.segments, so lower \
             events[{}].heat_time_per_s (or the segments, or the time the conduction runs)",
            e.heat_node_updates,
            e.heat_event.map_or(String::new(), |k| k.to_string())
        )
    } else {
        "check the duration and the time step (conductor stiffness, numerics.courant, geometry.segments)".into()
    }
}

fn nan_is_inf(x: f64) -> f64 {
    if x.is_nan() { f64::INFINITY } else { x }
}

/// Heat sub-steps of the plan's conduction stretches, and the `[[events]]` index of the `heat_conduction`
/// event whose stretch takes the most ([`Plan::heat_conduction_events`]).
fn heat_substeps(plan: &Plan, n: f64, dt: f64, horizon: f64) -> (f64, Option<usize>) {
    let max_step = 0.5 / (n * n);
    let mut total = 0.0;
    let mut most: Option<(f64, usize)> = None; // (sub-steps, ordinal among the heat_conduction events)
    let mut running: Option<(f64, f64, usize)> = None; // (start [s], heat time per second [1/s], ordinal)
    let mut close = |from: f64, per_s: f64, to: f64, ordinal: usize| {
        let d = (to.min(horizon) - from).max(0.0);
        if d > 0.0 {
            let per_step = (dt * per_s / max_step).ceil().max(1.0);
            let substeps = ((d / dt).ceil() + 1.0) * per_step;
            total += substeps;
            // NaN counts as the most (it is over any budget).
            if most.is_none_or(|(m, _)| !substeps.partial_cmp(&m).is_some_and(|o| o.is_le())) {
                most = Some((substeps, ordinal));
            }
        }
    };
    let mut ordinal = 0;
    for e in &plan.events {
        let stops =
            matches!(e.action, Action::HeatConduction { .. } | Action::HeatConductionOff | Action::Temperature { .. });
        if stops && let Some((from, per_s, k)) = running.take() {
            close(from, per_s, e.time_s, k);
        }
        if let Action::HeatConduction { heat_time_per_s, .. } = e.action {
            running = Some((e.time_s, heat_time_per_s, ordinal));
            ordinal += 1;
        }
    }
    if let Some((from, per_s, k)) = running {
        close(from, per_s, horizon, k);
    }
    (nan_is_inf(total), most.and_then(|(_, k)| plan.heat_conduction_events.get(k).copied()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::{parse, plan};

    const BASE: &str = "[conductor]\naxial_stiffness_n = 792000.0\nlinear_density_kg_per_m = 1.0\n\
        [geometry]\nleft_support_m = [0.0, 0.0, 0.0]\nright_support_m = [0.0, 160.0, 0.0]\nsegments = 20\n";

    fn plan_of(extra: &str) -> Plan {
        let text = format!("{BASE}{extra}");
        plan(&parse(&text, "test").unwrap(), "test").unwrap()
    }

    #[test]
    fn counts_steps_rows_and_bytes() {
        let p = plan_of("[duration]\nend_time_s = 1.0\n[output]\nsample_interval_s = 0.1\nsnapshot_times_s = [0.5]\n");
        let e = p.work_estimate();
        let dt = p.solver.params().dt_s;
        assert_eq!(e.steps, (1.0 / dt).ceil());
        assert_eq!(e.node_steps, 21.0 * e.steps);
        assert_eq!(e.timeseries_rows, 11.0);
        assert_eq!(e.timeseries_columns, 16.0);
        assert_eq!(e.snapshot_rows, 42.0);
        assert_eq!(e.output_bytes, 25.0 * (11.0 * 16.0 + 42.0 * 11.0));
        assert_eq!(e.heat_substeps, 0.0);
        assert!(p.check_budget().is_ok());
        // The run takes exactly the estimated steps (no events: no shortened step but the last).
        let o = crate::run::run(p, &Default::default()).unwrap();
        assert_eq!(o.summary.steps as f64, e.steps);
    }

    #[test]
    fn absurd_inputs_are_refused_without_overflow() {
        // The longest end time validation accepts (1e8 s) at N = 20: 3e11 node-steps, refused.
        let p = plan_of("[duration]\nend_time_s = 1e8\n");
        let err = p.check_budget().unwrap_err();
        assert!(matches!(err, Refusal::NodeSteps(_)), "{err}");
        let text = err.to_string();
        assert!(text.contains("--allow-large") && text.contains("2.0e10"), "{text}");
        // A time step of 1e-300 s (validation bounds EA and the density, so set it on the plan): steps
        // ~ 1e308, still finite in f64, and the clock cannot advance: refused even with --allow-large.
        let mut p = plan_of("[duration]\nend_time_s = 1e8\n");
        p.solver.params_mut().dt_s = 1e-300;
        let e = p.work_estimate();
        assert!(e.steps > 1e300 || e.steps.is_infinite());
        assert!(matches!(e.check(), Err(Refusal::TimeStalls(_))));
        // A sample interval of 1e-300 s: at most one row per time level.
        let p = plan_of("[duration]\nend_time_s = 100.0\n[output]\nsample_interval_s = 1e-300\n");
        let e = p.check_budget().unwrap();
        assert_eq!(e.timeseries_rows, e.steps + 1.0);
        // Snapshots of a long, fine wire: refused on output bytes.
        let big = BASE.replace("segments = 20", "segments = 10000");
        let times: Vec<String> = (0..2000).map(|k| format!("{}", k as f64 * 1e-3)).collect();
        let text = format!("{big}[duration]\nend_time_s = 2.0\n[output]\nsnapshot_times_s = [{}]\n", times.join(", "));
        let p = plan(&parse(&text, "t").unwrap(), "t").unwrap();
        assert!(matches!(p.check_budget(), Err(Refusal::OutputBytes(_))), "{:?}", p.check_budget());
    }

    #[test]
    fn heat_conduction_counts_its_substeps() {
        // Heat conduction needs thermal expansion (validation refuses it without).
        let text = format!(
            "{BASE}[duration]\nend_time_s = 2.0\n[[events]]\ntime_s = 0.5\naction = \"heat_conduction\"\n\
             hold_range = [0.4, 0.6]\nhold_temperature_k = 400.0\nheat_time_per_s = 1000.0\n\
             [[events]]\ntime_s = 1.5\naction = \"heat_conduction_off\"\n"
        )
        .replace(
            "linear_density_kg_per_m = 1.0\n",
            "linear_density_kg_per_m = 1.0\nthermal_expansion_per_k = 2.38e-5\n",
        );
        let p = plan(&parse(&text, "test").unwrap(), "test").unwrap();
        let e = p.work_estimate();
        let dt = p.solver.params().dt_s;
        let per_step = (dt * 1000.0 / (0.5 / 400.0)).ceil();
        assert_eq!(e.heat_substeps, ((1.0 / dt).ceil() + 1.0) * per_step);
        assert_eq!(e.heat_node_updates, 21.0 * e.heat_substeps);
        assert_eq!(e.steps, (2.0 / dt).ceil() + 2.0);
        assert_eq!(e.heat_event, Some(0));
    }

    #[test]
    fn a_heat_refusal_names_the_event_that_drives_it() {
        // Two conduction stretches written out of time order: events[0] (t = 10 s to the end at 20 s, 1 per
        // second) and events[2] (t = 0.1 s until the temperature event events[1] at 5 s, 1000 per second).
        // Sub-steps of a stretch: (ceil(d / dt) + 1) ceil(dt r / (h^2 / 2)); at N = 2000 (dt about 8e-5 s,
        // h^2 / 2 = 1.25e-7) events[2]'s are about 3e2 times events[0]'s, and 2001 times their sum is above
        // the budget.
        let text = format!(
            "{}[duration]\nend_time_s = 20.0\n\
             [[events]]\ntime_s = 10.0\naction = \"heat_conduction\"\nhold_range = [0.4, 0.6]\n\
             hold_temperature_k = 400.0\nheat_time_per_s = 1.0\n\
             [[events]]\ntime_s = 5.0\naction = \"temperature\"\ntemperature_k = 300.0\n\
             [[events]]\ntime_s = 0.1\naction = \"heat_conduction\"\nhold_range = [0.4, 0.6]\n\
             hold_temperature_k = 400.0\nheat_time_per_s = 1000.0\n",
            BASE.replace("segments = 20", "segments = 2000")
        )
        .replace(
            "linear_density_kg_per_m = 1.0\n",
            "linear_density_kg_per_m = 1.0\nthermal_expansion_per_k = 2.38e-5\n",
        );
        let p = plan(&parse(&text, "test").unwrap(), "test").unwrap();
        assert_eq!(p.heat_conduction_events, vec![2, 0]);
        let err = p.check_budget().unwrap_err();
        assert_eq!(err.estimate().heat_event, Some(2));
        let text = err.to_string();
        assert!(text.contains("so lower events[2].heat_time_per_s (or"), "{text}");
    }
}
