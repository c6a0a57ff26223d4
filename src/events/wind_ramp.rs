//! A linear ramp of the wind multiplier: from its value `s0` at the start `t0` to the target `s*` over the
//! ramp time `R`,
//!
//! ```text
//! s(t) = s0 + (s* - s0) min(1, (t - t0) / R),      t >= t0,
//! ```
//!
//! evaluated once per step at the step's start time ([`super::EventState::before_step`]), never per node.
//! A wind switched on at once (`R = 0`) excites the span's swing: a linear oscillator of period `T` under a
//! step load overshoots its static deflection by 100 % (dynamic amplification 2, less the damping). Under
//! a linear ramp of duration `R` the largest deflection after the ramp is, undamped,
//!
//! ```text
//! x_max / x_static = 1 + |sin(pi R / T)| / (pi R / T)
//! ```
//!
//! (the ramp-load response of an undamped oscillator: Biggs, *Introduction to Structural Dynamics*, 1964,
//! ch. 2, "rise time"; Chopra, *Dynamics of Structures*, section 4.4, step force with finite rise time). The
//! overshoot is at most `T / (pi R)`: a ramp of three periods keeps it below 11 %, of ten below 3.2 %, and
//! it vanishes at whole numbers of periods. docs/scenario.md gives this as guidance for `ramp_s`.

/// A running ramp of the wind multiplier.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WindRamp {
    /// start time `t0` [s]
    pub start_s: f64,
    /// ramp time `R` [s], > 0
    pub duration_s: f64,
    /// multiplier at the start `s0` [-]
    pub from: f64,
    /// target multiplier `s*` [-]
    pub to: f64,
}

impl WindRamp {
    /// The multiplier at time `t` [s] (`s0` before the start, exactly `s*` from `t0 + R` on) and whether
    /// the ramp is complete.
    pub fn scale(&self, t_s: f64) -> (f64, bool) {
        let f = ((t_s - self.start_s) / self.duration_s).clamp(0.0, 1.0);
        if f >= 1.0 { (self.to, true) } else { (self.from + (self.to - self.from) * f, false) }
    }
}

/// The dynamic amplification of the ramp-load response of an undamped linear oscillator of period `T`
/// [s] under a linear ramp of duration `R` [s] to a constant load: `1 + |sin(pi R / T)| / (pi R / T)`
/// (module doc); 2 for a step (`R = 0`).
pub fn ramp_amplification(ramp_s: f64, period_s: f64) -> f64 {
    let x = std::f64::consts::PI * ramp_s / period_s;
    if x == 0.0 { 2.0 } else { 1.0 + x.sin().abs() / x }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn goes_linearly_to_the_target_and_stays() {
        let r = WindRamp { start_s: 2.0, duration_s: 4.0, from: 0.5, to: 1.5 };
        assert_eq!(r.scale(1.0), (0.5, false));
        assert_eq!(r.scale(3.0), (0.75, false));
        assert_eq!(r.scale(6.0), (1.5, true));
        assert_eq!(r.scale(60.0), (1.5, true));
    }

    /// The amplification against a direct integration of `x'' + w^2 x = w^2 f(t)` with the ramp `f`
    /// (an independent computation: the exact solution of the oscillator, piecewise, by its Duhamel
    /// integral). During the ramp `x = (t - sin(w t) / w) / R`; after it the free oscillation about 1
    /// from the state at `R`; the maximum of `x` after the ramp is `1 + A` with `A` the amplitude.
    #[test]
    fn amplification_is_the_exact_oscillator_response() {
        let period = 2.0;
        let w = 2.0 * std::f64::consts::PI / period;
        for &r in &[0.3, 1.0, 2.5, 3.7, 6.0, 10.1] {
            let x = (r - (w * r).sin() / w) / r;
            let v = (1.0 - (w * r).cos()) / r;
            let amplitude = ((x - 1.0).powi(2) + (v / w).powi(2)).sqrt();
            let exact = 1.0 + amplitude;
            let formula = ramp_amplification(r, period);
            // Both are closed forms of the same response: equal to rounding (1e-12 relative).
            assert!((exact - formula).abs() < 1e-12, "R = {r}: {exact} vs {formula}");
        }
        assert_eq!(ramp_amplification(0.0, 1.0), 2.0);
    }
}
