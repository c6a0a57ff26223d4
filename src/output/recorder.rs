//! In-memory record of a run (for the paper cases, the verification harness and library users): the
//! time-series samples with extra quantities beside each, and the shapes at the snapshot times, on the
//! same clocks as the files ([`super::timeseries`], [`super::snapshots`]).

use super::clock::{LANDING, ListClock, SampleClock};
use super::probe::ProbePoint;
use super::timeseries::Sample;
use crate::observer::{Control, Level, Observer, OutputError};
use crate::scheme::Explicit;

/// Quantities recorded beside each time-series sample.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Probe {
    /// time `t` [s]
    pub t_s: f64,
    /// tension of the segment at the first and at the last node [N]
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

impl Probe {
    /// The probe of the solver's current state.
    pub fn of(solver: &Explicit) -> Probe {
        let w = &solver.wire();
        let n = w.segments();
        Probe {
            t_s: solver.time_s(),
            support_tension_n: [solver.segment_tension(0), solver.segment_tension(n - 1)],
            mean_temperature_k: w.temperature_k.iter().sum::<f64>() / n as f64,
            rest_length_m: w.total_rest_length(),
            reference_length_m: w.reference_length.iter().sum(),
            mass_kg: w.total_mass(),
            wind_scale: solver.loads().wind_scale,
        }
    }
}

/// The wire's shape at a snapshot time.
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

/// Records samples, probes and shapes in memory.
pub struct Recorder {
    samples: SampleClock,
    snapshots: ListClock,
    mid: ProbePoint,
    /// the time series
    pub rows: Vec<Sample>,
    /// beside each sample
    pub probes: Vec<Probe>,
    /// the shapes at the snapshot times
    pub shapes: Vec<Shape>,
}

impl Recorder {
    /// Record every `interval_s` [s] and at `snapshot_times_s` [s].
    pub fn new(interval_s: f64, snapshot_times_s: Vec<f64>, mid: ProbePoint) -> Self {
        Recorder {
            samples: SampleClock::new(interval_s),
            snapshots: ListClock::new(snapshot_times_s),
            mid,
            rows: Vec::new(),
            probes: Vec::new(),
            shapes: Vec::new(),
        }
    }
}

impl Observer for Recorder {
    fn observe(&mut self, level: &Level) -> Result<Control, OutputError> {
        let tol = LANDING * level.solver.params().dt_s;
        if self.samples.due(level.t_s, tol) {
            self.rows.push(Sample::of(level, &self.mid));
            self.probes.push(Probe::of(level.solver));
        }
        if self.snapshots.due(level.t_s, tol) {
            let w = &level.solver.wire();
            self.shapes.push(Shape { t_s: level.t_s, tau: level.tau(), x: w.x.clone(), intact: w.intact.clone() });
        }
        Ok(Control::Continue)
    }
}
