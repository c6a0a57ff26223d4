//! Natural frequencies of a taut elastic string: transverse and longitudinal modes.
//!
//! A string of unstretched length `L0` [m], linear density `rho0` [kg/m] per unit unstretched length and
//! axial stiffness `EA` [N], pinned at both ends and pre-stretched to the length `L = L0 (1 + e0)`, carries
//! the uniform tension `T = EA e0`. Linearising (2.1) about this straight state in the Lagrangian
//! coordinate `s` (unstretched arc length) gives two uncoupled wave equations,
//!
//! ```text
//! rho0 u_tt = (T / lambda) u_ss      transverse,   lambda = 1 + e0   (T / lambda from d/ds (T/lambda r_s))
//! rho0 w_tt = EA w_ss                 longitudinal (tangent stiffness dT/de = EA)
//! ```
//!
//! with fixed ends, hence the mode frequencies
//!
//! ```text
//! f_n^T = n / (2 L0) sqrt(T / (rho0 lambda)) = n / (2 L) sqrt(T / rho),   rho = rho0 / lambda,
//! f_n^L = n / (2 L0) sqrt(EA / rho0),                                     n = 1, 2, ...
//! ```
//!
//! The lumped-mass chain of the explicit scheme (`N` segments of length `ds = L0 / N`, node mass
//! `rho0 ds`) has, for the same linearisation, the exact discrete frequencies
//!
//! ```text
//! omega_n = (2 c / ds) sin(n pi / (2 N)),   c = sqrt(T / (rho0 lambda)) or sqrt(EA / rho0),
//! ```
//!
//! which tend to the continuous ones as `1 - (n pi / N)^2 / 24`: second order in `ds`.

use super::{ExactError, require_positive};
use std::f64::consts::PI;

/// A taut string pinned at both ends (see the module documentation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TautString {
    /// unstretched length `L0` [m]
    pub unstretched_length_m: f64,
    /// linear density per unit unstretched length `rho0` [kg/m]
    pub linear_density_kg_per_m: f64,
    /// axial stiffness `EA` [N]
    pub axial_stiffness_n: f64,
    /// pre-strain `e0 > 0` [-] (the supports are `L0 (1 + e0)` apart)
    pub prestrain: f64,
}

impl TautString {
    /// A string of unstretched length `L0` [m], density `rho0` [kg/m], stiffness `EA` [N] and pre-strain
    /// `e0` [-]; every input must be finite and positive.
    pub fn new(
        unstretched_length_m: f64,
        linear_density_kg_per_m: f64,
        axial_stiffness_n: f64,
        prestrain: f64,
    ) -> Result<Self, ExactError> {
        Ok(TautString {
            unstretched_length_m: require_positive(unstretched_length_m, "unstretched length L0 must be positive")?,
            linear_density_kg_per_m: require_positive(linear_density_kg_per_m, "linear density must be positive")?,
            axial_stiffness_n: require_positive(axial_stiffness_n, "axial stiffness EA must be positive")?,
            prestrain: require_positive(prestrain, "pre-strain e0 must be positive")?,
        })
    }

    /// tension `T = EA e0` [N]
    pub fn tension_n(&self) -> f64 {
        self.axial_stiffness_n * self.prestrain
    }

    /// distance between the supports `L = L0 (1 + e0)` [m]
    pub fn stretched_length_m(&self) -> f64 {
        self.unstretched_length_m * (1.0 + self.prestrain)
    }

    /// transverse wave speed in the Lagrangian coordinate `sqrt(T / (rho0 (1 + e0)))` [m/s]
    pub fn transverse_wave_speed_m_per_s(&self) -> f64 {
        (self.tension_n() / (self.linear_density_kg_per_m * (1.0 + self.prestrain))).sqrt()
    }

    /// longitudinal wave speed `sqrt(EA / rho0)` [m/s]
    pub fn longitudinal_wave_speed_m_per_s(&self) -> f64 {
        (self.axial_stiffness_n / self.linear_density_kg_per_m).sqrt()
    }

    /// frequency of transverse mode `n >= 1` [Hz]
    pub fn transverse_frequency_hz(&self, n: usize) -> f64 {
        n as f64 * self.transverse_wave_speed_m_per_s() / (2.0 * self.unstretched_length_m)
    }

    /// frequency of longitudinal mode `n >= 1` [Hz]
    pub fn longitudinal_frequency_hz(&self, n: usize) -> f64 {
        n as f64 * self.longitudinal_wave_speed_m_per_s() / (2.0 * self.unstretched_length_m)
    }

    /// frequency of transverse mode `n` of the lumped chain with `segments` equal segments [Hz]
    pub fn discrete_transverse_frequency_hz(&self, n: usize, segments: usize) -> f64 {
        discrete(self.transverse_wave_speed_m_per_s(), self.unstretched_length_m, n, segments)
    }

    /// frequency of longitudinal mode `n` of the lumped chain with `segments` equal segments [Hz]
    pub fn discrete_longitudinal_frequency_hz(&self, n: usize, segments: usize) -> f64 {
        discrete(self.longitudinal_wave_speed_m_per_s(), self.unstretched_length_m, n, segments)
    }
}

fn discrete(c: f64, l0: f64, n: usize, segments: usize) -> f64 {
    let ds = l0 / segments as f64;
    (2.0 * c / ds) * (n as f64 * PI / (2.0 * segments as f64)).sin() / (2.0 * PI)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Number of eigenvalues of the symmetric tridiagonal matrix (diag `a`, off-diagonal `b`) below `x`,
    /// by the Sturm sequence (LDL^T pivot signs).
    fn count_below(a: &[f64], b: f64, x: f64) -> usize {
        let mut count = 0;
        let mut d = 1.0;
        for (k, &ak) in a.iter().enumerate() {
            let off = if k == 0 { 0.0 } else { b * b / d };
            d = ak - x - off;
            if d == 0.0 {
                d = -1e-300;
            }
            if d < 0.0 {
                count += 1;
            }
        }
        count
    }

    /// The `n`-th smallest eigenvalue of the chain's `M^-1 K` by bisection on the Sturm count.
    fn chain_eigenvalue(stiffness: f64, mass: f64, nodes: usize, n: usize) -> f64 {
        let a = vec![2.0 * stiffness / mass; nodes];
        let b = -stiffness / mass;
        let (mut lo, mut hi) = (0.0, 4.0 * stiffness / mass * 1.01);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if count_below(&a, b, mid) >= n { hi = mid } else { lo = mid }
        }
        0.5 * (lo + hi)
    }

    #[test]
    fn discrete_frequencies_match_the_chain_eigenvalues_and_converge_at_second_order() {
        // Independent route: assemble the lumped chain (spring T/(lambda ds) transverse, EA/ds longitudinal,
        // node mass rho0 ds) and find its eigenvalues by Sturm bisection; compare with the closed forms.
        let s = TautString::new(160.0, 1.0, 80734.0 * 9.81, 5.0e-3).unwrap();
        let mut prev_err = f64::NAN;
        for segments in [20, 40, 80] {
            let ds = 160.0 / segments as f64;
            let kt = s.tension_n() / ((1.0 + s.prestrain) * ds);
            let kl = s.axial_stiffness_n / ds;
            let m = ds;
            for n in 1..=3 {
                let ft = chain_eigenvalue(kt, m, segments - 1, n).sqrt() / (2.0 * PI);
                let fl = chain_eigenvalue(kl, m, segments - 1, n).sqrt() / (2.0 * PI);
                let (et, el) = (
                    s.discrete_transverse_frequency_hz(n, segments),
                    s.discrete_longitudinal_frequency_hz(n, segments),
                );
                assert!((ft - et).abs() < 1e-10 * et, "transverse n={n}, N={segments}: {ft} vs {et}");
                assert!((fl - el).abs() < 1e-10 * el, "longitudinal n={n}, N={segments}: {fl} vs {el}");
            }
            // Second order: error of mode 1 against the continuous frequency falls by 4 per halving.
            let err = (s.discrete_transverse_frequency_hz(1, segments) - s.transverse_frequency_hz(1)).abs();
            if prev_err.is_finite() {
                let ratio = prev_err / err;
                assert!((ratio - 4.0).abs() < 0.02, "ratio {ratio}");
            }
            prev_err = err;
        }
        // Continuous values by hand: T = 3960 N, c_T = sqrt(3960/1.005) = 62.77 m/s, f1 = 0.19616 Hz.
        assert!((s.transverse_frequency_hz(1) - 62.7716 / 320.0).abs() < 1e-5);
        assert!((s.longitudinal_frequency_hz(2) - 2.0 * 889.944 / 320.0).abs() < 1e-4);
    }

    #[test]
    fn rejects_bad_input() {
        assert!(TautString::new(160.0, 1.0, 1e5, 0.0).is_err());
        assert!(TautString::new(f64::NAN, 1.0, 1e5, 1e-3).is_err());
    }
}
