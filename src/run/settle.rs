//! "Until settled": the run may stop once the kinetic energy has stayed at or below a fraction of its
//! peak for a time window, checked at every time level (so the settle time does not depend on the sample
//! interval). The kinetic energy is that of the half-step velocities, `sum m_i |v_i^{n-1/2}|^2 / 2`
//! ([`crate::scheme::Explicit::kinetic_energy_half_step`]): the scheme's own velocities, one pass over the
//! nodes. The sum in node order is formed only where bounds on it
//! ([`crate::scheme::Explicit::kinetic_energy_half_step_bounds`], a vectorised sum of the same terms)
//! leave the peak or the verdict open: the peak and every verdict are those of the node-order sum.
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
}

impl Settle {
    /// Settled when the kinetic energy stays at or below `fraction` of its peak for `window_s` [s].
    pub fn new(fraction: f64, window_s: f64) -> Self {
        Settle { fraction, window_s, peak_j: 0.0, below_since_s: None, settled_since_s: None }
    }
}

impl Observer for Settle {
    fn observe(&mut self, level: &Level) -> Result<Control, OutputError> {
        // Bounds on the kinetic energy first (a vectorised sum, without the node-order sum's chain of
        // dependent additions): where they decide both questions below, as at nearly every level of a
        // decay, the node-order sum would leave the peak and the verdict as they are.
        let (lo, hi) = level.solver.kinetic_energy_half_step_bounds();
        let threshold = self.fraction * self.peak_j;
        let below = if hi < self.peak_j && hi <= threshold {
            true
        } else if hi < self.peak_j && lo > threshold {
            false
        } else {
            let ke = level.solver.kinetic_energy_half_step();
            self.peak_j = self.peak_j.max(ke);
            ke <= self.fraction * self.peak_j
        };
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
