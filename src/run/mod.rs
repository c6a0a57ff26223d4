//! The run: a short loop that steps the solver, applies the events due, and notifies its observers
//! ([`Observer`]) at every time level. Everything a run produces (time series, snapshots, peaks, the
//! settle criterion, the in-memory record, a progress display) is an observer; none of them can change
//! the state, so asking for more output never changes the trajectory.
//!
//! Time handling: steps have the nominal length `dt` of (3.7), except the step that lands exactly on an
//! event time or the end time, which is shortened (the scheme's kick uses the mean of consecutive steps,
//! so this keeps second order). Outputs never shorten a step: they act at the first level at or after
//! their times ([`crate::output::clock`]). Events due at a level are applied on arrival, before the level
//! is observed ([`crate::events`]). A run until settled stops at the first level where the settle
//! criterion holds and no event is pending.

pub mod line;
pub(crate) mod phase_cycles;
pub mod settle;
pub mod short_circuit;
pub mod shortcircuit_case;
pub mod start_up;

use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::events::EventState;
use crate::output::clock::LANDING;
use crate::output::cpu_time::{CpuStopwatch, per_second};
use crate::output::rows::write_atomically;
use crate::output::spans::SpanState;
use crate::output::summary::{
    EquilibriumReport, EventRecord, InstabilityReport, ProbeSummary, SpanSummary, SupportSummary,
};
use crate::output::timeseries::{Columns, LineColumns};
use crate::output::{Peaks, ProbePoint, Recorder, Sample, Snapshots, Summary, Timeseries};
use crate::scenario::Plan;
use crate::scenario::build::Stop;
use crate::scheme::{Explicit, Instability};
use phase_cycles::PhaseClock;

pub use crate::observer::{Control, Ending, Level, Observer, OutputError};
pub use crate::output::{Probe, Shape};
pub use settle::Settle;

/// Run `solver` and its `timeline` until `stop`, notifying `observers` at every time level (`tau_per_s`
/// [1/s] converts time to the paper's `tau`). Returns how the run ended, or the first output error.
pub fn run_loop<'o>(
    solver: &mut Explicit,
    timeline: &mut EventState,
    stop: Stop,
    tau_per_s: f64,
    observers: &mut [&mut (dyn Observer + 'o)],
) -> Result<Ending, OutputError> {
    let (dt, horizon) = (solver.params().dt_s, stop.horizon_s());
    let tol = LANDING * dt;
    // Each observer's time before which it has nothing to do ([`Control::QuietUntil`]).
    let mut quiet_until = vec![f64::NEG_INFINITY; observers.len()];
    // Cycles per phase, with the feature `phase-timing` only ([`phase_cycles`]).
    let fixed = ["forces of a level (segment pass, strings)", "step (node pass, ground contact)"];
    let names = observers.iter().map(|o| format!("observer {}", o.name()));
    let mut phases = PhaseClock::new(fixed.into_iter().map(String::from).chain(names));
    const FORCES: usize = 0;
    const STEP: usize = 1;
    const OBSERVER: usize = 2;
    let ending = loop {
        let t = solver.time_s();
        let applied = timeline.apply_due(solver, t, tol);
        if applied > 0 {
            let what = timeline.log[timeline.log.len() - applied..].iter().map(|(_, w)| w.as_str());
            let what = what.collect::<Vec<_>>().join("; ");
            observers.iter_mut().for_each(|o| o.event(t, &what));
        }
        timeline.before_step(solver, t);
        let from = phases.mark();
        solver.evaluate_forces();
        phases.add(FORCES, from);
        let level = Level { solver, t_s: t, tau_per_s };
        let mut settled = false;
        for (k, (o, quiet)) in observers.iter_mut().zip(&mut quiet_until).enumerate() {
            if t < *quiet {
                continue;
            }
            let from = phases.mark();
            let control = o.observe(&level)?;
            phases.add(OBSERVER + k, from);
            match control {
                Control::Settled => settled = true,
                Control::QuietUntil(until) => *quiet = until,
                Control::Continue => {}
            }
        }
        if settled && timeline.next_time().is_none() {
            break Ending::Settled;
        }
        if t >= horizon - tol {
            break if matches!(stop, Stop::Settled { .. }) { Ending::NotSettled } else { Ending::Completed };
        }
        let target = timeline.next_time().unwrap_or(horizon).min(horizon);
        let h = if target - t <= dt * (1.0 + 1.0e-12) { target - t } else { dt };
        let from = phases.mark();
        let stepped = solver.step(h);
        phases.add(STEP, from);
        phases.count_step();
        if let Err(e) = stepped {
            break Ending::Unstable(e);
        }
        if h < dt {
            solver.land_on(target);
        }
        timeline.after_step(solver, h);
    };
    phases.report();
    if matches!(ending, Ending::Unstable(_)) {
        solver.evaluate_forces();
    }
    let level = Level { solver, t_s: solver.time_s(), tau_per_s };
    for o in observers.iter_mut() {
        o.finish(&level, &ending)?;
    }
    Ok(ending)
}

/// How to run a plan with the standard outputs ([`run`]).
#[derive(Clone, Debug, Default)]
pub struct RunOptions {
    /// directory for `timeseries.csv`, `snapshots.csv` and `summary.json` (none: nothing is written)
    pub out_dir: Option<PathBuf>,
    /// keep the time series in memory in [`Outcome::samples`] (with [`Outcome::probes`]) and the shapes
    /// at the snapshot times in [`Outcome::shapes`]
    pub record: bool,
}

/// What a run produced.
#[derive(Clone, Debug)]
pub struct Outcome {
    /// the summary (also written to `summary.json`)
    pub summary: Summary,
    /// the time series, if [`RunOptions::record`] was set
    pub samples: Vec<Sample>,
    /// recorded with each sample, if [`RunOptions::record`] was set
    pub probes: Vec<Probe>,
    /// the shapes at the snapshot times, if [`RunOptions::record`] was set
    pub shapes: Vec<Shape>,
    /// the events applied: (time [s], what was done)
    pub events: Vec<(f64, String)>,
    /// the solver at the end of the run
    pub solver: Explicit,
}

/// Why a run did not complete.
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    /// An output file could not be written.
    #[error(transparent)]
    Io(#[from] OutputError),
    /// The scheme went unstable; the outcome up to that point is attached (and was written).
    #[error("{instability}")]
    Unstable {
        /// where and why
        instability: Instability,
        /// the run up to the failure
        outcome: Box<Outcome>,
    },
}

/// Run a plan to its end with the standard outputs.
pub fn run(plan: Plan, opts: &RunOptions) -> Result<Outcome, RunError> {
    run_observed(plan, opts, &mut [])
}

/// [`run`] with further observers (a progress display, a custom output) after the standard ones.
pub fn run_observed<'o>(
    plan: Plan,
    opts: &RunOptions,
    extra: &mut [&mut (dyn Observer + 'o)],
) -> Result<Outcome, RunError> {
    let mut solver = plan.solver.clone();
    let wire = &solver.wire();
    let mid = ProbePoint::new(crate::output::probe::MIDSPAN, 0.5, wire);
    let named: Vec<ProbePoint> = plan.probes.iter().map(|(name, at)| ProbePoint::at(name, *at, wire)).collect();
    let all_probes: Vec<ProbePoint> = std::iter::once(mid.clone()).chain(named.iter().cloned()).collect();
    let supports: Vec<(usize, [f64; 3])> = wire.supports();
    let from_s = plan.peaks_from_s.unwrap_or_else(|| plan.events.first().map_or(0.0, |e| e.time_s));
    let mut peaks = Peaks::new(from_s, all_probes.clone(), supports.len(), plan.spans.clone(), plan.ground.clone());
    let mut settle = match plan.stop {
        Stop::Settled { fraction, window_s, .. } => Some(Settle::new(fraction, window_s)),
        Stop::EndTime(_) => None,
    };
    let mut recorder =
        opts.record.then(|| Recorder::new(plan.sample_interval_s, plan.snapshot_times_s.clone(), mid.clone()));
    let (mut series, mut snaps) = match &opts.out_dir {
        Some(d) => {
            std::fs::create_dir_all(d).map_err(OutputError::at(d))?;
            let path = d.join("timeseries.csv");
            let ts = Timeseries::with_columns(&path, plan.sample_interval_s, timeseries_columns(&plan))?;
            (Some(ts), Some(Snapshots::create(&d.join("snapshots.csv"), plan.snapshot_times_s.clone())?))
        }
        None => (None, None),
    };
    let mut timeline = plan.timeline();
    let started = Instant::now();
    let cpu = CpuStopwatch::start();
    let ending = {
        let mut observers: Vec<&mut (dyn Observer + 'o)> = vec![&mut peaks];
        observers.extend(settle.as_mut().map(|o| o as &mut dyn Observer));
        observers.extend(recorder.as_mut().map(|o| o as &mut dyn Observer));
        observers.extend(series.as_mut().map(|o| o as &mut dyn Observer));
        observers.extend(snaps.as_mut().map(|o| o as &mut dyn Observer));
        for o in extra.iter_mut() {
            observers.push(&mut **o);
        }
        run_loop(&mut solver, &mut timeline, plan.stop, plan.tau(1.0), &mut observers)?
    };
    let wall = started.elapsed().as_secs_f64();
    let cpu_s = cpu.elapsed_s();

    let t = solver.time_s();
    let last = Sample::of(&Level { solver: &solver, t_s: t, tau_per_s: plan.tau(1.0) }, &all_probes[0]);
    let mut forces = Vec::new();
    solver.support_forces(&mut forces);
    let n = solver.wire().segments();
    let run_peaks = peaks.run();
    // The peaks the start-up check looks at, with their values at the end.
    let start_up_peaks: Vec<(String, f64, f64, f64)> = std::iter::once((
        "max_tension".to_string(),
        run_peaks.max_tension.value_n,
        run_peaks.max_tension.time_s,
        last.max_tension_n,
    ))
    .chain(supports.iter().zip(&forces).zip(&run_peaks.supports).map(|(((node, _), (_, f)), p)| {
        let end = f.iter().map(|c| c * c).sum::<f64>().sqrt();
        (format!("support {node}"), p.magnitude.value_n, p.magnitude.time_s, end)
    }))
    .collect();
    let summary = Summary {
        name: plan.name.clone(),
        status: ending.status().into(),
        settled: ending == Ending::Settled,
        settled_since_s: settle.as_ref().and_then(|s| s.settled_since_s).filter(|_| ending == Ending::Settled),
        final_time_s: t,
        final_tau: plan.tau(t),
        final_midspan_displacement_m: [last.mid_dx1_m, last.mid_dx2_m, last.mid_dx3_m],
        final_max_tension_n: last.max_tension_n,
        peaks_from_s: peaks.from_s(),
        peak_midspan_displacement_m: run_peaks.probes[0],
        peak_max_tension_n: run_peaks.max_tension.value_n,
        peak_max_tension_time_s: run_peaks.max_tension.time_s,
        final_kinetic_j: last.kinetic_j,
        steps: solver.steps(),
        segments: n,
        dt_s: solver.params().dt_s,
        courant: plan.courant,
        wave_speed_m_per_s: plan.wave_speed_m_per_s,
        wall_time_s: wall,
        node_steps_per_second: per_second((n + 1) as f64 * solver.steps() as f64, wall),
        cpu_time_s: cpu_s,
        cpu_node_steps_per_second: cpu_s.map(|c| per_second((n + 1) as f64 * solver.steps() as f64, c)),
        initial_equilibrium: plan.initial_equilibrium.as_ref().map(|r| EquilibriumReport {
            iterations: r.iterations,
            residual_n: r.residual_n,
            tolerance_n: r.tolerance_n,
        }),
        warnings: plan.warnings.clone(),
        supports: supports
            .iter()
            .zip(&forces)
            .zip(&run_peaks.supports)
            .map(|(((node, position_m), (_, f)), p)| SupportSummary {
                node: *node,
                position_m: *position_m,
                final_force_n: *f,
                peaks: p.clone(),
            })
            .collect(),
        probes: all_probes
            .iter()
            .zip(run_peaks.probes.iter().zip(run_peaks.rises.iter().zip(&run_peaks.falls)).zip(&run_peaks.crossings))
            .map(|(p, ((peak, (rise, fall)), crossings))| ProbeSummary {
                name: p.name.clone(),
                at_fraction: p.at_fraction,
                final_displacement_m: p.displacement(solver.wire()),
                peak_displacement_m: *peak,
                peak_rise_m: *rise,
                peak_fall_m: *fall,
                period_about_chord_s: crossings.map(|c| c.period_s()),
            })
            .collect(),
        spans: plan
            .spans
            .iter()
            .zip(&run_peaks.spans)
            .enumerate()
            .map(|(k, (&(first, last), p))| {
                let state = SpanState::of(&solver, first, last, plan.ground.as_ref());
                SpanSummary {
                    span: k,
                    nodes: [first, last],
                    final_max_tension_n: state.max_tension_n,
                    final_least_clearance_m: state.least_clearance_m,
                    final_sag_m: state.sag_m,
                    final_horizontal_tension_n: state.horizontal_tension_n,
                    peaks: p.clone(),
                }
            })
            .collect(),
        start_up: start_up::check(&plan, &solver, plan.initial_equilibrium.is_some(), &start_up_peaks),
        phases: peaks.phases.clone(),
        events: timeline.log.iter().map(|(t, w)| EventRecord { time_s: *t, what: w.clone() }).collect(),
        instability: match &ending {
            Ending::Unstable(f) => Some(InstabilityReport { time_s: f.time_s, node: f.node, reason: f.to_string() }),
            _ => None,
        },
        thermal: plan.thermal.as_ref().map(|h| thermal_summary(h, t)),
    };
    if let Some(d) = &opts.out_dir {
        write_summary(d, &summary)?;
    }
    let (samples, probes, shapes) = match recorder {
        Some(r) => (r.rows, r.probes, r.shapes),
        None => Default::default(),
    };
    let outcome = Outcome { summary, samples, probes, shapes, events: timeline.log, solver };
    match ending {
        Ending::Unstable(instability) => Err(RunError::Unstable { instability, outcome: Box::new(outcome) }),
        _ => Ok(outcome),
    }
}

/// The columns of the plan's `timeseries.csv` ([`Columns`]): mid-span, the named probes, every support,
/// the suspension strings, the spans and the temperature, as [`run`] writes them.
pub fn timeseries_columns(plan: &Plan) -> Columns {
    let wire = plan.solver.wire();
    let mid = ProbePoint::new(crate::output::probe::MIDSPAN, 0.5, wire);
    let named: Vec<ProbePoint> = plan.probes.iter().map(|(name, at)| ProbePoint::at(name, *at, wire)).collect();
    let supports = wire.supports();
    // Suspension supports: their index among the supports, in the order of the wire's strings.
    let strings: Vec<usize> =
        (wire.insulators.iter()).map(|s| supports.iter().position(|p| p.0 == s.node).unwrap_or(0)).collect();
    let line = LineColumns {
        supports: supports.len(),
        strings,
        spans: plan.spans.clone(),
        ground: plan.ground.clone(),
        temperature: plan.thermal.is_some(),
    };
    Columns::new(mid, named, line)
}

/// The temperature summary of a `[thermal]` history up to the end time `t_end` [s].
fn thermal_summary(h: &crate::scenario::thermal::ThermalHistory, t_end: f64) -> crate::output::summary::ThermalSummary {
    let mut play = crate::events::Heating::new(h.samples.clone());
    let (mut peak, mut peak_t) = (f64::NEG_INFINITY, 0.0);
    for &(t, k) in h.samples.iter().take_while(|p| p.0 <= t_end) {
        if k > peak {
            (peak, peak_t) = (k, t);
        }
    }
    crate::output::summary::ThermalSummary {
        conductor: h.conductor.clone(),
        standard: match h.standard {
            crate::thermal::Standard::Ieee738 => "ieee738".into(),
            crate::thermal::Standard::Cigre601 => "cigre601".into(),
        },
        initial_temperature_k: h.samples[0].1,
        final_temperature_k: play.temperature_at(t_end),
        peak_temperature_k: peak,
        peak_temperature_time_s: peak_t,
        melting_from_s: h.shed.as_ref().map(|s| s.melting_from_s),
        shed_time_s: h.shed.as_ref().map(|s| s.time_s),
        ice_kg_per_m: h.shed.as_ref().map(|s| s.ice_kg_per_m),
    }
}

/// Write `dir/summary.json` whole or not at all.
pub fn write_summary(dir: &Path, s: &Summary) -> Result<(), OutputError> {
    let p = dir.join("summary.json");
    let text = serde_json::to_string_pretty(s).map_err(std::io::Error::other).map_err(OutputError::at(&p))?;
    write_atomically(&p, &(text + "\n")).map_err(OutputError::at(&p))
}

/// Write the residual static state of `ohl run --static-after` to `dir/static.json`, whole or not at all.
pub fn write_residual(dir: &Path, r: &crate::statics::residual::Residual) -> Result<(), OutputError> {
    let p = dir.join("static.json");
    let text = serde_json::to_string_pretty(r).map_err(std::io::Error::other).map_err(OutputError::at(&p))?;
    write_atomically(&p, &(text + "\n")).map_err(OutputError::at(&p))
}
