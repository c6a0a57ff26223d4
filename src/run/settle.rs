//! "Until settled": the run may stop once the kinetic energy has stayed at or below a fraction of its
//! peak for a time window, checked at every time level (so the settle time does not depend on the sample
//! interval). The kinetic energy is that of the half-step velocities, `sum m_i |v_i^{n-1/2}|^2 / 2`
//! ([`crate::scheme::Explicit::kinetic_energy_half_step`]): the scheme's own velocities, one pass over the
//! nodes. The sum in node order is formed only where bounds on it leave the peak or the verdict open:
//! first the wide bounds from the largest speed the step formed
//! ([`crate::scheme::Explicit::kinetic_energy_quick_bounds`], no pass over the nodes), then the close
//! ones of a vectorised sum of the same terms
//! ([`crate::scheme::Explicit::kinetic_energy_half_step_bounds`]). The peak and every verdict are those
//! of the node-order sum.
//! After events the peak is measured afresh, and the loop stops only when no event is pending
//! ([`super::run_loop`]), so a wire that settles before a later break still breaks.

use super::{Control, Level, Observer, OutputError};

/// The settle detector.
#[derive(Clone, Debug)]
pub struct Settle {
    fraction: f64,
    window_s: f64,
    peak_j: f64,
    below_since_s: Option<f64>,
    /// the start of the window that completed (the time from which the wire was settled) [s]
    pub settled_since_s: Option<f64>,
    /// levels left that take the node-order sum without trying the bounds first
    exact_for: u32,
}

/// Levels that take the node-order sum after the bounds left one open (a choice of cost only: every
/// verdict is the node-order sum's either way).
const RETRY: u32 = 16;

impl Settle {
    /// Settled when the kinetic energy stays at or below `fraction` of its peak for `window_s` [s].
    pub fn new(fraction: f64, window_s: f64) -> Self {
        Settle { fraction, window_s, peak_j: 0.0, below_since_s: None, settled_since_s: None, exact_for: 0 }
    }
}

/// The verdict (at or below the threshold) that every energy in `[lo, hi]` [J] gives, where none of them
/// passes the peak `peak` [J] (which it would then raise): `None` where that is not so, or a bound is NaN.
fn verdict(lo: f64, hi: f64, peak: f64, threshold: f64) -> Option<bool> {
    if hi < peak && hi <= threshold {
        Some(true)
    } else if hi < peak && lo > threshold {
        Some(false)
    } else {
        None
    }
}

impl Observer for Settle {
    fn observe(&mut self, level: &Level) -> Result<Control, OutputError> {
        // Bounds on the kinetic energy first: where they decide both questions below, as at nearly every
        // level of a decay, the node-order sum would leave the peak and the verdict as they are. The wide
        // bounds from the step's largest speed cost nothing; where they leave a question open, the close
        // bounds of a vectorised sum (without the node-order sum's chain of dependent additions).
        // After a level the close bounds left open (the energy rising to a new peak, or at the threshold),
        // the next `RETRY` levels go from the wide bounds straight to the node-order sum: the close bounds
        // would most likely be open again.
        let threshold = self.fraction * self.peak_j;
        let (lo, hi) = level.solver.kinetic_energy_quick_bounds();
        let mut below = verdict(lo, hi, self.peak_j, threshold);
        if below.is_none() {
            let (lo, hi) = if self.exact_for == 0 {
                level.solver.kinetic_energy_half_step_bounds()
            } else {
                self.exact_for -= 1;
                (f64::NAN, f64::NAN)
            };
            below = verdict(lo, hi, self.peak_j, threshold);
            if below.is_none() && !hi.is_nan() {
                self.exact_for = RETRY;
            }
        }
        let below = below.unwrap_or_else(|| {
            let ke = level.solver.kinetic_energy_half_step();
            self.peak_j = self.peak_j.max(ke);
            ke <= self.fraction * self.peak_j
        });
        if below {
            let since = *self.below_since_s.get_or_insert(level.t_s);
            if level.t_s - since >= self.window_s {
                self.settled_since_s = Some(since);
                return Ok(Control::Settled);
            }
        } else {
            self.below_since_s = None;
        }
        self.settled_since_s = None;
        Ok(Control::Continue)
    }

    fn event(&mut self, _t_s: f64, _what: &str) {
        self.peak_j = 0.0;
        self.below_since_s = None;
        self.settled_since_s = None;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scheme::configs::Config;

    /// The detector as first written: the node-order sum at every level.
    struct Reference {
        fraction: f64,
        window_s: f64,
        peak_j: f64,
        below_since_s: Option<f64>,
    }

    impl Reference {
        fn observe(&mut self, ke: f64, t_s: f64) -> (bool, Option<f64>) {
            self.peak_j = self.peak_j.max(ke);
            if ke <= self.fraction * self.peak_j {
                let since = *self.below_since_s.get_or_insert(t_s);
                if t_s - since >= self.window_s {
                    return (true, Some(since));
                }
            } else {
                self.below_since_s = None;
            }
            (false, None)
        }
    }

    /// Level by level, the detector's verdict and settle time are the reference's, on wires that fall
    /// from the straight chord and swing (the kinetic energy rises, peaks, oscillates and, with internal
    /// friction, decays), with a reset part way (an event); and the bounds decided most levels alone (here
    /// the close bounds 19776 of 24000, the rest while the energy rises to a new peak or sits at the
    /// threshold; the wide bounds alone 5397 of them: the tests' fractions 0.05 to 1 put the threshold
    /// within a factor 20 of the peak, where bounds a factor 80 apart are mostly open).
    #[test]
    fn verdicts_are_those_of_the_node_order_sum() {
        let (mut decided, mut open, mut settled, mut quick) = (0, 0, 0, 0);
        for config in [Config::PlaneWeight, Config::ViscousSmoothed] {
            for (fraction, windows) in [(0.5, 0.0), (0.05, 3.0), (0.9, 10.0), (1.0, 0.0)] {
                let mut s = config.solver(40);
                let dt = s.params().dt_s;
                let window_s = windows * dt;
                let mut settle = Settle::new(fraction, window_s);
                let mut reference = Reference { fraction, window_s, peak_j: 0.0, below_since_s: None };
                for n in 0..3000 {
                    if n == 1700 {
                        settle.event(s.time_s(), "event");
                        (reference.peak_j, reference.below_since_s) = (0.0, None);
                    }
                    s.evaluate_forces();
                    let t = s.time_s();
                    let peak = settle.peak_j;
                    if verdict_given(s.kinetic_energy_half_step_bounds(), peak, fraction) {
                        decided += 1;
                    } else {
                        open += 1;
                    }
                    quick += usize::from(verdict_given(s.kinetic_energy_quick_bounds(), peak, fraction));
                    let got = settle.observe(&Level { solver: &s, t_s: t, tau_per_s: 1.0 }).unwrap();
                    let (want, since) = reference.observe(s.kinetic_energy_half_step(), t);
                    assert_eq!(got == Control::Settled, want, "{config:?} {fraction} level {n}");
                    assert_eq!(settle.settled_since_s, since, "{config:?} {fraction} level {n}");
                    assert_eq!(settle.peak_j.to_bits(), reference.peak_j.to_bits(), "{config:?} {fraction} level {n}");
                    settled += usize::from(want);
                    s.step(dt).unwrap();
                }
            }
        }
        assert!(decided > 2 * open && open > 0 && settled > 0, "{decided} decided, {open} open, {settled} settled");
        assert!(quick > decided / 5 && quick < decided, "{quick} decided by the wide bounds of {decided}");
    }

    fn verdict_given((lo, hi): (f64, f64), peak: f64, fraction: f64) -> bool {
        verdict(lo, hi, peak, fraction * peak).is_some()
    }
}
