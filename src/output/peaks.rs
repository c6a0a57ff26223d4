//! Peaks, tracked at every time level (never only at samples), each with its time: the largest segment
//! tension, the largest-magnitude displacement of every probe per component, per support the largest
//! force magnitude and the largest-magnitude component, and for a suspension support the string's
//! largest swing along and across the line; per span of a section its largest segment tension and, with
//! a ground, its least vertical clearance above the ground. Two views are kept:
//!
//! - the run's peaks from `from_s` on ([`Peaks::new`]): by default the time of the first event, so that a
//!   run that settles and then breaks, ices or gusts reports the peaks of what the events do and not the
//!   transient of a start from a shape that is not the equilibrium; 0 for a run without events;
//! - the peaks of every phase: the stretches between events (the first starts at `t = 0`).

use serde::Serialize;

use super::probe::ProbePoint;
use crate::observer::{Control, Level, Observer, OutputError};
use crate::scheme::Ground;

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

/// The least value of a length (a clearance).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct LeastLength {
    /// the least value [m]
    pub value_m: f64,
    /// when it occurred [s]
    pub time_s: f64,
    /// when it occurred, dimensionless `tau = t U / l` [-]
    pub tau: f64,
}

impl Default for LeastLength {
    fn default() -> Self {
        LeastLength { value_m: f64::INFINITY, time_s: 0.0, tau: 0.0 }
    }
}

/// Peaks of one span of a section.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct SpanPeaks {
    /// largest tension of the span's segments [N]
    pub max_tension: PeakForce,
    /// least vertical clearance of the span's nodes above the ground `min (x3 - h(x2))` [m] (with a ground)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub least_clearance: Option<LeastLength>,
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
    /// per span of a section (empty for one span)
    pub spans: Vec<SpanPeaks>,
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
    fn sized(probes: usize, supports: usize, spans: usize) -> Self {
        PeakSet {
            max_tension: PeakForce::default(),
            probes: vec![[Peak::default(); 3]; probes],
            supports: vec![SupportPeaks::default(); supports],
            spans: vec![SpanPeaks::default(); spans],
        }
    }

    fn update(&mut self, c: &Current) {
        let Current { t, tau, tension, ref disp, ref forces, ref swings, ref spans } = *c;
        largest(&mut self.max_tension, tension, t, tau);
        for (p, &(tension, clearance)) in self.spans.iter_mut().zip(spans) {
            largest(&mut p.max_tension, tension, t, tau);
            if let Some(c) = clearance {
                let least = p.least_clearance.get_or_insert_with(Default::default);
                if c < least.value_m {
                    *least = LeastLength { value_m: c, time_s: t, tau };
                }
            }
        }
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
    spans: Vec<(usize, usize)>,
    ground: Option<Ground>,
    /// the run's peaks from `from_s` on
    pub run: PeakSet,
    /// every phase's peaks
    pub phases: Vec<Phase>,
    current: Current,
}

/// The tracked values at one time level.
#[derive(Default)]
struct Current {
    t: f64,
    tau: f64,
    /// largest segment tension [N]
    tension: f64,
    /// probe displacements [m]
    disp: Vec<[f64; 3]>,
    /// support forces [N]
    forces: Vec<(usize, [f64; 3])>,
    /// string swings along and across [deg]
    swings: Vec<Option<[f64; 2]>>,
    /// per span: largest tension [N] and least clearance [m]
    spans: Vec<(f64, Option<f64>)>,
}

impl Peaks {
    /// Track `probes` (the mid-span probe first), `supports` supports and the `spans` of a section (first
    /// and last node of each; empty for one span) with their clearance above `ground`; the run's peaks
    /// count from `from_s` [s].
    pub fn new(
        from_s: f64,
        probes: Vec<ProbePoint>,
        supports: usize,
        spans: Vec<(usize, usize)>,
        ground: Option<Ground>,
    ) -> Self {
        let n = probes.len();
        let k = spans.len();
        Peaks {
            from_s,
            run: PeakSet::sized(n, supports, k),
            phases: vec![Phase { start_s: 0.0, started_by: "start".into(), peaks: PeakSet::sized(n, supports, k) }],
            probes,
            supports,
            spans,
            ground,
            current: Current { disp: vec![[0.0; 3]; n], spans: Vec::with_capacity(k), ..Default::default() },
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
        let c = &mut self.current;
        (c.t, c.tau) = (level.t_s, level.tau());
        for (d, p) in c.disp.iter_mut().zip(&self.probes) {
            *d = p.displacement(s.wire());
        }
        s.support_forces(&mut c.forces);
        let w = s.wire();
        c.swings.clear();
        for &(node, _) in &c.forces {
            let string = w.insulators.iter().find(|i| i.node == node);
            c.swings.push(string.map(|i| i.swing(w.position(node)).map(f64::to_degrees)));
        }
        c.tension = s.max_tension_n();
        c.spans.clear();
        for &(first, last) in &self.spans {
            let clearance = self.ground.as_ref().map(|g| g.least_clearance_m(&w.x, first..=last));
            c.spans.push((s.max_tension_in(first..last), clearance));
        }
        let phase = self.phases.last_mut().expect("the first phase exists from the start");
        phase.peaks.update(c);
        if c.t >= self.from_s - super::clock::LANDING * s.params().dt_s {
            self.run.update(c);
        }
        Ok(Control::Continue)
    }

    fn event(&mut self, t_s: f64, what: &str) {
        let last = self.phases.last_mut().expect("the first phase exists from the start");
        if last.start_s == t_s && last.started_by != "start" {
            last.started_by = format!("{}; {what}", last.started_by);
            return;
        }
        let peaks = PeakSet::sized(self.probes.len(), self.supports, self.spans.len());
        if last.start_s == t_s {
            // events at t = 0: they start the first phase
            *last = Phase { start_s: t_s, started_by: what.to_string(), peaks };
        } else {
            self.phases.push(Phase { start_s: t_s, started_by: what.to_string(), peaks });
        }
    }
}
