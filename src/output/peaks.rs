//! Peaks, tracked at every time level (never only at samples), each with its time: the largest segment
//! tension, the largest-magnitude displacement of every probe per component, and per support the largest
//! force magnitude and the largest-magnitude component, and for a suspension support the string's
//! largest swing along and across the line. Two views are kept:
//!
//! - the run's peaks from `from_s` on ([`Peaks::new`]): by default the time of the first event, so that a
//!   run that settles and then breaks, ices or gusts reports the peaks of what the events do and not the
//!   transient of a start from a shape that is not the equilibrium; 0 for a run without events;
//! - the peaks of every phase: the stretches between events (the first starts at `t = 0`).

use serde::Serialize;

use super::probe::ProbePoint;
use crate::run::{Control, Level, Observer, OutputError};

/// The extreme of one displacement component: the value of largest magnitude, with its sign.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Peak {
    /// the displacement of largest magnitude, with its sign [m]
    pub value_m: f64,
    /// when it occurred [s]
    pub time_s: f64,
    /// when it occurred, dimensionless `tau = t U / l` [-]
    pub tau: f64,
}

/// The extreme of a force: the largest value (tension, force magnitude) or the value of largest
/// magnitude with its sign (a force component).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct PeakForce {
    /// the force [N]
    pub value_n: f64,
    /// when it occurred [s]
    pub time_s: f64,
    /// when it occurred, dimensionless `tau = t U / l` [-]
    pub tau: f64,
}

/// The extreme of an angle: the value of largest magnitude, with its sign.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct PeakAngle {
    /// the angle of largest magnitude, with its sign [deg]
    pub value_deg: f64,
    /// when it occurred [s]
    pub time_s: f64,
    /// when it occurred, dimensionless `tau = t U / l` [-]
    pub tau: f64,
}

/// Peaks of the force the wire applies to one support.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct SupportPeaks {
    /// largest magnitude `|F|` [N]
    pub magnitude: PeakForce,
    /// largest-magnitude value of each component `F1, F2, F3` [N]
    pub components: [PeakForce; 3],
    /// a suspension support's string: largest swing from plumb along and across the line [deg]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub swing: Option<[PeakAngle; 2]>,
}

/// Everything tracked over one stretch of time.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct PeakSet {
    /// largest segment tension [N]
    pub max_tension: PeakForce,
    /// largest-magnitude displacement of each probe per component (the mid-span probe first) [m]
    pub probes: Vec<[Peak; 3]>,
    /// per support (fixed nodes in node order)
    pub supports: Vec<SupportPeaks>,
}

/// One phase: the time between two events.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Phase {
    /// start [s]
    pub start_s: f64,
    /// what started it ("start" or the events applied)
    pub started_by: String,
    /// its peaks
    pub peaks: PeakSet,
}

fn signed(p: &mut Peak, v: f64, t: f64, tau: f64) {
    if v.abs() > p.value_m.abs() {
        *p = Peak { value_m: v, time_s: t, tau };
    }
}

fn signed_force(p: &mut PeakForce, v: f64, t: f64, tau: f64) {
    if v.abs() > p.value_n.abs() {
        *p = PeakForce { value_n: v, time_s: t, tau };
    }
}

fn largest(p: &mut PeakForce, v: f64, t: f64, tau: f64) {
    if v > p.value_n {
        *p = PeakForce { value_n: v, time_s: t, tau };
    }
}

impl PeakSet {
    fn sized(probes: usize, supports: usize) -> Self {
        PeakSet {
            max_tension: PeakForce::default(),
            probes: vec![[Peak::default(); 3]; probes],
            supports: vec![SupportPeaks::default(); supports],
        }
    }

    fn update(
        &mut self,
        t: f64,
        tau: f64,
        tension: f64,
        disp: &[[f64; 3]],
        forces: &[(usize, [f64; 3])],
        swings: &[Option<[f64; 2]>],
    ) {
        largest(&mut self.max_tension, tension, t, tau);
        for (p, d) in self.probes.iter_mut().zip(disp) {
            for k in 0..3 {
                signed(&mut p[k], d[k], t, tau);
            }
        }
        for (s, (_, f)) in self.supports.iter_mut().zip(forces) {
            largest(&mut s.magnitude, (f[0] * f[0] + f[1] * f[1] + f[2] * f[2]).sqrt(), t, tau);
            for k in 0..3 {
                signed_force(&mut s.components[k], f[k], t, tau);
            }
        }
        for (s, sw) in self.supports.iter_mut().zip(swings) {
            if let Some(a) = sw {
                let peaks = s.swing.get_or_insert_with(Default::default);
                for k in 0..2 {
                    if a[k].abs() > peaks[k].value_deg.abs() {
                        peaks[k] = PeakAngle { value_deg: a[k], time_s: t, tau };
                    }
                }
            }
        }
    }
}

/// The peak tracker.
pub struct Peaks {
    from_s: f64,
    probes: Vec<ProbePoint>,
    supports: usize,
    /// the run's peaks from `from_s` on
    pub run: PeakSet,
    /// every phase's peaks
    pub phases: Vec<Phase>,
    disp: Vec<[f64; 3]>,
    forces: Vec<(usize, [f64; 3])>,
    swings: Vec<Option<[f64; 2]>>,
}

impl Peaks {
    /// Track `probes` (the mid-span probe first) and `supports` supports; the run's peaks count from
    /// `from_s` [s].
    pub fn new(from_s: f64, probes: Vec<ProbePoint>, supports: usize) -> Self {
        let n = probes.len();
        Peaks {
            from_s,
            run: PeakSet::sized(n, supports),
            phases: vec![Phase { start_s: 0.0, started_by: "start".into(), peaks: PeakSet::sized(n, supports) }],
            probes,
            supports,
            disp: vec![[0.0; 3]; n],
            forces: Vec::new(),
            swings: Vec::new(),
        }
    }

    /// The time from which the run's peaks count [s].
    pub fn from_s(&self) -> f64 {
        self.from_s
    }
}

impl Observer for Peaks {
    fn observe(&mut self, level: &Level) -> Result<Control, OutputError> {
        let s = level.solver;
        let (t, tau) = (level.t_s, level.tau());
        for (d, p) in self.disp.iter_mut().zip(&self.probes) {
            *d = p.displacement(s.wire());
        }
        s.support_forces(&mut self.forces);
        let w = s.wire();
        self.swings.clear();
        for &(node, _) in &self.forces {
            let string = w.insulators.iter().find(|i| i.node == node);
            self.swings.push(string.map(|i| i.swing(w.position(node)).map(f64::to_degrees)));
        }
        let tension = s.max_tension_n();
        let phase = self.phases.last_mut().expect("the first phase exists from the start");
        phase.peaks.update(t, tau, tension, &self.disp, &self.forces, &self.swings);
        if t >= self.from_s - super::clock::LANDING * s.params().dt_s {
            self.run.update(t, tau, tension, &self.disp, &self.forces, &self.swings);
        }
        Ok(Control::Continue)
    }

    fn event(&mut self, t_s: f64, what: &str) {
        let last = self.phases.last_mut().expect("the first phase exists from the start");
        if last.start_s == t_s && last.started_by != "start" {
            last.started_by = format!("{}; {what}", last.started_by);
            return;
        }
        let peaks = PeakSet::sized(self.probes.len(), self.supports);
        if last.start_s == t_s {
            // events at t = 0: they start the first phase
            *last = Phase { start_s: t_s, started_by: what.to_string(), peaks };
        } else {
            self.phases.push(Phase { start_s: t_s, started_by: what.to_string(), peaks });
        }
    }
}
