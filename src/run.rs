//! The driver: steps a [`Plan`] to its end, samples the time series, writes snapshots, detects that the
//! wire has settled, tracks peaks and measures throughput.
//!
//! Time handling: steps have the nominal length `dt` of (3.7) except the step that lands exactly on a
//! snapshot time, an event time or the end time, which is shortened (the scheme's kick uses the mean of
//! consecutive steps, so this keeps second order). Events due at a time are applied on arrival, before
//! that time's sample ([`crate::events`]); after an event the settle detection starts afresh (the peak
//! kinetic energy is measured again from the event on). Time-series rows are taken at the first step at
//! or after each multiple of the sample interval and record the actual time. The mid-span peaks are
//! tracked every step.

use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Instant;

use crate::events::EventState;
use crate::output::summary::InstabilityReport;
use crate::output::{Peak, Sample, SnapshotWriter, Summary, TimeseriesWriter};
use crate::scenario::Plan;
use crate::scenario::build::Stop;
use crate::scheme::{Explicit, Instability};

/// A progress hook: called at every time-series sample with the simulated time `t` [s] and the run's
/// horizon [s] (its end time, or the longest it may run when it stops on settling).
pub type Progress = Arc<dyn Fn(f64, f64) + Send + Sync>;

/// How to run.
#[derive(Clone, Default)]
pub struct RunOptions {
    /// directory for `timeseries.csv`, `snapshots.csv` and `summary.json` (none: nothing is written)
    pub out_dir: Option<PathBuf>,
    /// called as the run advances (the applications draw a progress bar with it); none: silent
    pub progress: Option<Progress>,
    /// keep the time series in memory in [`Outcome::samples`] (with [`Outcome::probes`]) and the shapes
    /// at the snapshot times in [`Outcome::shapes`]
    pub record: bool,
}

impl fmt::Debug for RunOptions {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("RunOptions")
            .field("out_dir", &self.out_dir)
            .field("progress", &self.progress.as_ref().map(|_| "hook"))
            .field("record", &self.record)
            .finish()
    }
}

/// Quantities recorded beside each time-series sample (in memory only, with [`RunOptions::record`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Probe {
    /// time `t` [s]
    pub t_s: f64,
    /// tension of the segment at the left and at the right support [N]
    pub support_tension_n: [f64; 2],
    /// mean segment temperature [K]
    pub mean_temperature_k: f64,
    /// total stress-free length `sum l0` [m]
    pub rest_length_m: f64,
    /// total unstretched length at the reference temperature `sum L` [m]
    pub reference_length_m: f64,
    /// total mass [kg]
    pub mass_kg: f64,
    /// multiplier on the wind load [-]
    pub wind_scale: f64,
}

/// The wire's shape at a snapshot time (in memory only, with [`RunOptions::record`]).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Shape {
    /// time `t` [s]
    pub t_s: f64,
    /// dimensionless time `tau` [-]
    pub tau: f64,
    /// node positions [m]
    pub x: [Vec<f64>; 3],
    /// 1 for an intact segment, 0 for a broken one [-]
    pub intact: Vec<f64>,
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
    #[error("cannot write {path}: {source}")]
    Io {
        /// the file
        path: String,
        /// the I/O error
        source: std::io::Error,
    },
    /// The scheme went unstable; the outcome up to that point is attached (and was written).
    #[error("{instability}")]
    Unstable {
        /// where and why
        instability: Instability,
        /// the run up to the failure
        outcome: Box<Outcome>,
    },
}

struct Writers {
    dir: PathBuf,
    series: TimeseriesWriter,
    snaps: SnapshotWriter,
}

fn io_err(path: &Path) -> impl FnOnce(std::io::Error) -> RunError + '_ {
    move |source| RunError::Io { path: path.display().to_string(), source }
}

impl Writers {
    fn open(dir: &Path, segments: usize) -> Result<Self, RunError> {
        std::fs::create_dir_all(dir).map_err(io_err(dir))?;
        let ts = dir.join("timeseries.csv");
        let sn = dir.join("snapshots.csv");
        Ok(Writers {
            series: TimeseriesWriter::create(&ts).map_err(io_err(&ts))?,
            snaps: SnapshotWriter::create(&sn, segments).map_err(io_err(&sn))?,
            dir: dir.to_path_buf(),
        })
    }
    fn summary(&self, s: &Summary) -> Result<(), RunError> {
        let p = self.dir.join("summary.json");
        let text = serde_json::to_string_pretty(s).map_err(std::io::Error::other).map_err(io_err(&p))?;
        std::fs::write(&p, text + "\n").map_err(io_err(&p))
    }
}

impl Probe {
    /// The probe of the solver's current state.
    pub fn of(solver: &Explicit) -> Probe {
        let w = &solver.wire;
        let n = w.segments();
        Probe {
            t_s: solver.time_s,
            support_tension_n: [solver.segment_tension(0), solver.segment_tension(n - 1)],
            mean_temperature_k: w.temperature_k.iter().sum::<f64>() / n as f64,
            rest_length_m: w.total_rest_length(),
            reference_length_m: w.reference_length.iter().sum(),
            mass_kg: w.total_mass(),
            wind_scale: solver.loads.wind_scale,
        }
    }
}

/// Run a plan to its end.
pub fn run(plan: Plan, opts: &RunOptions) -> Result<Outcome, RunError> {
    let Plan { solver, .. } = &plan;
    let mut solver = solver.clone();
    let n = solver.wire.segments();
    let mut writers = match &opts.out_dir {
        Some(d) => Some(Writers::open(d, n)?),
        None => None,
    };
    let mid0 = plan.chord_midpoint();
    let dt = solver.params.dt_s;
    let horizon = plan.stop.horizon_s();
    // Landing tolerance: a target closer than this is taken as reached.
    let tol = 1.0e-9 * dt;

    let mut samples = Vec::new();
    let mut probes = Vec::new();
    let mut shapes = Vec::new();
    let mut events = EventState::new(&plan);
    let mut peaks = [Peak::default(); 3];
    let (mut peak_tension, mut peak_tension_t) = (0.0_f64, 0.0_f64);
    let mut peak_ke = 0.0_f64;
    let mut below_since: Option<f64> = None;
    let mut settled = false;
    let mut next_sample = 0.0_f64;
    let mut snap_idx = 0usize;
    let mut last = Sample::default();
    let started = Instant::now();
    let mut failure: Option<Instability> = None;

    loop {
        let t = solver.time_s;
        if events.apply_due(&mut solver, t, tol) > 0 {
            peak_ke = 0.0;
            below_since = None;
        }
        let m = solver.wire.midspan();
        for k in 0..3 {
            let d = m[k] - mid0[k];
            if d.abs() > peaks[k].value_m.abs() {
                peaks[k] = Peak { value_m: d, time_s: t, tau: plan.tau(t) };
            }
        }
        let at_end = t >= horizon - tol;
        if t >= next_sample - tol || at_end {
            let d = solver.diagnostics();
            last = Sample {
                t_s: t,
                tau: plan.tau(t),
                mid_dx1_m: m[0] - mid0[0],
                mid_dx2_m: m[1] - mid0[1],
                mid_dx3_m: m[2] - mid0[2],
                max_tension_n: d.max_tension_n,
                kinetic_j: d.kinetic_j,
                elastic_j: d.elastic_j,
                potential_j: d.potential_j,
                total_j: d.kinetic_j + d.elastic_j + d.potential_j,
            };
            if t >= next_sample - tol {
                if let Some(w) = writers.as_mut() {
                    w.series.write(&last).map_err(io_err(&w.dir.join("timeseries.csv")))?;
                }
                if opts.record {
                    samples.push(last);
                    probes.push(Probe::of(&solver));
                }
                while next_sample <= t + tol {
                    next_sample += plan.sample_interval_s;
                }
            }
            if d.max_tension_n > peak_tension {
                peak_tension = d.max_tension_n;
                peak_tension_t = t;
            }
            peak_ke = peak_ke.max(d.kinetic_j);
            if let Stop::Settled { fraction, window_s, .. } = plan.stop {
                if d.kinetic_j <= fraction * peak_ke {
                    let since = *below_since.get_or_insert(t);
                    settled = t - since >= window_s;
                } else {
                    below_since = None;
                }
            }
            if let Some(p) = &opts.progress {
                p(t, horizon);
            }
        }
        while snap_idx < plan.snapshot_times_s.len() && plan.snapshot_times_s[snap_idx] <= t + tol {
            if let Some(w) = writers.as_mut() {
                w.snaps.write(&solver, plan.tau(t)).map_err(io_err(&w.dir.join("snapshots.csv")))?;
            }
            if opts.record {
                let w = &solver.wire;
                shapes.push(Shape { t_s: t, tau: plan.tau(t), x: w.x.clone(), intact: w.intact.clone() });
            }
            snap_idx += 1;
        }
        if settled || at_end {
            break;
        }
        let target = plan
            .snapshot_times_s
            .get(snap_idx)
            .copied()
            .unwrap_or(horizon)
            .min(events.next_time().unwrap_or(horizon))
            .min(horizon);
        let step = if target - t <= dt * (1.0 + 1.0e-12) { target - t } else { dt };
        events.before_step(&mut solver, t);
        if let Err(e) = solver.step(step) {
            failure = Some(e);
            break;
        }
        if step < dt {
            solver.time_s = target;
        }
        events.after_step(&mut solver, step);
    }
    let wall = started.elapsed().as_secs_f64();

    let t = solver.time_s;
    let status = match (&failure, plan.stop, settled) {
        (Some(_), _, _) => "unstable",
        (None, Stop::EndTime(_), _) => "completed",
        (None, Stop::Settled { .. }, true) => "settled",
        (None, Stop::Settled { .. }, false) => "not_settled",
    };
    let summary = Summary {
        name: plan.name.clone(),
        status: status.into(),
        settled,
        final_time_s: t,
        final_tau: plan.tau(t),
        final_midspan_displacement_m: [last.mid_dx1_m, last.mid_dx2_m, last.mid_dx3_m],
        final_max_tension_n: last.max_tension_n,
        peak_midspan_displacement_m: peaks,
        peak_max_tension_n: peak_tension,
        peak_max_tension_time_s: peak_tension_t,
        final_kinetic_j: last.kinetic_j,
        steps: solver.steps,
        segments: n,
        dt_s: dt,
        courant: plan.courant,
        wave_speed_m_per_s: plan.wave_speed_m_per_s,
        wall_time_s: wall,
        node_steps_per_second: if wall > 0.0 { (n + 1) as f64 * solver.steps as f64 / wall } else { 0.0 },
        instability: failure.as_ref().map(|f| InstabilityReport {
            time_s: f.time_s,
            node: f.node,
            reason: f.to_string(),
        }),
    };
    if let Some(w) = &writers {
        w.summary(&summary)?;
    }
    let outcome = Outcome { summary, samples, probes, shapes, events: events.log, solver };
    match failure {
        Some(instability) => Err(RunError::Unstable { instability, outcome: Box::new(outcome) }),
        None => Ok(outcome),
    }
}
