//! The time step from the Courant number, eq. (3.7), and the stability limit with internal friction.
//!
//! In SI units (3.7) reads `dt = C ds / c` with the longitudinal wave speed `c = sqrt(EA / rho0)` [m/s],
//! `rho0` [kg/m] the linear density and `ds` [m] the stress-free segment length; `C` is the Courant
//! number ("alpha_k" in the paper). For a non-uniform wire the smallest `ds / c` over the segments
//! sets the step.
//!
//! With the Kelvin-Voigt term `eta de/dt` evaluated explicitly (at the previous half step), the
//! highest longitudinal mode of the leapfrog obeys
//! `u^{n+1} - 2u^n + u^{n-1} = -4 C^2 u^n - 4 C z (u^n - u^{n-1})` with `z = eta c / (EA ds)`, whose
//! roots stay in the unit disc iff `C^2 + 2 z C <= 1`, i.e.
//!
//! ```text
//! C <= C_max(z) = sqrt(1 + z^2) - z.
//! ```
//!
//! Internal friction therefore lowers the stable Courant number of the explicit scheme (docs/paper_notes.md,
//! "Internal friction and the time step"); validation rejects a Courant number above `C_max`.

/// Longitudinal wave speed `c = sqrt(EA / rho0)` [m/s] for axial stiffness `EA` [N] and linear density
/// `rho0` [kg/m].
pub fn wave_speed(axial_stiffness_n: f64, linear_density_kg_per_m: f64) -> f64 {
    (axial_stiffness_n / linear_density_kg_per_m).sqrt()
}

/// Dimensionless internal-friction number `z = eta c / (EA ds)` [-].
pub fn friction_number(axial_stiffness_n: f64, eta_n_s: f64, wave_speed_m_per_s: f64, ds_m: f64) -> f64 {
    eta_n_s * wave_speed_m_per_s / (axial_stiffness_n * ds_m)
}

/// Largest stable Courant number `sqrt(1 + z^2) - z` of the explicit scheme with explicit
/// Kelvin-Voigt friction number `z` (1 without friction).
pub fn stable_courant(z: f64) -> f64 {
    // Written as 1 / (sqrt(1 + z^2) + z) to avoid cancellation for large z.
    1.0 / ((1.0 + z * z).sqrt() + z)
}

/// Time step `dt = C ds / c` [s] of (3.7).
pub fn time_step(courant: f64, ds_m: f64, wave_speed_m_per_s: f64) -> f64 {
    courant * ds_m / wave_speed_m_per_s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Amplification of the highest mode: spectral radius of the companion matrix of
    /// `z^2 - (2 - a - b) z + (1 - b) = 0`, `a = 4 C^2`, `b = 4 C z`.
    fn spectral_radius(c: f64, z: f64) -> f64 {
        let (a, b) = (4.0 * c * c, 4.0 * c * z);
        let p = 2.0 - a - b;
        let q = 1.0 - b;
        let disc = p * p - 4.0 * q;
        if disc >= 0.0 {
            let r1 = (p + disc.sqrt()) / 2.0;
            let r2 = (p - disc.sqrt()) / 2.0;
            r1.abs().max(r2.abs())
        } else {
            q.abs().sqrt()
        }
    }

    #[test]
    fn limit_is_where_the_highest_mode_turns_unstable() {
        for z in [0.0, 0.05, 0.3, 1.0, 3.0] {
            let c = stable_courant(z);
            assert!(spectral_radius(0.999 * c, z) <= 1.0 + 1e-12, "z = {z}");
            assert!(spectral_radius(1.001 * c, z) > 1.0, "z = {z}");
        }
        assert_eq!(stable_courant(0.0), 1.0);
    }

    #[test]
    fn paper_wire_step() {
        // EA = 80734 g N, rho0 = 1 kg/m (section 4.1): c = 889.944 m/s; ds = 3.2 m at N = 50.
        let c = wave_speed(80734.0 * 9.81, 1.0);
        assert!((c - 889.944).abs() < 1e-3);
        assert!((time_step(1.0, 3.2, c) - 3.5958e-3).abs() < 1e-6);
    }
}
