//! The gust law (4.5), written with a physical period.
//!
//! The paper writes `p(tau) = q0 d |sin(pi n / delta)|` with `n = tau / dtau` the step counter, so the
//! gust's period is `delta` steps and changes when the grid is refined (docs/paper_notes.md). Written with the
//! period `P` [s] of the pulsation, `|sin(pi n / delta)| = |sin(pi (t - t0) / P)|` with `P = delta dt`:
//!
//! ```text
//! p(t) = A q0 d |sin(pi (t - t0) / P)|,      t >= t0,
//! ```
//!
//! where `q0 d` is the scenario's wind load (the multiplier 1), `A` the amplitude and `t0` the start.

/// A running gust.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gust {
    /// start time `t0` [s]
    pub start_s: f64,
    /// period `P` of the pulsation [s]
    pub period_s: f64,
    /// peak multiplier `A` on the wind load [-]
    pub amplitude: f64,
}

impl Gust {
    /// Multiplier on the wind load at time `t` [s]: `A |sin(pi (t - t0) / P)|` (0 before the start).
    pub fn scale(&self, t_s: f64) -> f64 {
        if t_s < self.start_s {
            return 0.0;
        }
        self.amplitude * (std::f64::consts::PI * (t_s - self.start_s) / self.period_s).sin().abs()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zeros_every_period_and_full_load_half_way() {
        let g = Gust { start_s: 32.0, period_s: 2.0, amplitude: 1.0 };
        for k in 0..5 {
            assert!(g.scale(32.0 + 2.0 * k as f64).abs() < 1e-12);
            assert!((g.scale(33.0 + 2.0 * k as f64) - 1.0).abs() < 1e-12);
        }
        assert_eq!(g.scale(31.0), 0.0);
        // The step-counted law of the paper with delta steps of dt is the same function with P = delta dt.
        let (dt, delta) = (0.01, 200.0);
        let n = 137.0;
        let paper = (std::f64::consts::PI * n / delta).sin().abs();
        let ours = Gust { start_s: 0.0, period_s: delta * dt, amplitude: 1.0 }.scale(n * dt);
        assert!((paper - ours).abs() < 1e-12);
    }
}
