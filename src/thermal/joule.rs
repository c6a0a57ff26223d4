//! Joule heating `q_J = I^2 R(T)` with the AC resistance linear in temperature.
//!
//! IEEE Std 738-2012 eq. (10) takes the AC resistance at the conductor's average temperature by
//! linear interpolation, and beyond the two tabulated points by linear extrapolation, between the resistances
//! `R(T_low)` and `R(T_high)` at two reference temperatures:
//!
//! ```text
//! R(T) = R(T_low) + (R(T_high) - R(T_low)) / (T_high - T_low) * (T - T_low)          IEEE 738 eq. (10)
//! ```
//!
//! CIGRE TB 601 (2014) uses the same straight line between two catalogue values and multiplies it by a magnetic-core
//! factor for ACSR with an odd number of aluminium layers (see [`ThermalConductor::magnetic_core_factor`]); here both
//! standards share it:
//! `R(T) = k_m [R(T_low) + ...]` with `k_m = ThermalConductor::magnetic_core_factor` (1 for the IEEE example).
//! A temperature difference is the same in kelvin and in degrees Celsius, so the line needs no conversion.

use super::ThermalConductor;

/// AC resistance per unit length `k_m R(T)` [ohm/m] at the conductor temperature `temperature_k` [K]: IEEE 738
/// eq. (10), linear through `(T_low, R(T_low))` and `(T_high, R(T_high))` (extrapolated outside them), times the
/// magnetic-core factor `k_m`.
pub fn resistance_ohm_per_m(c: &ThermalConductor, temperature_k: f64) -> f64 {
    let slope =
        (c.resistance_high_ohm_per_m - c.resistance_low_ohm_per_m) / (c.temperature_high_k - c.temperature_low_k);
    c.magnetic_core_factor * (c.resistance_low_ohm_per_m + slope * (temperature_k - c.temperature_low_k))
}

/// Joule heating per unit length `q_J = I^2 R(T)` [W/m] for the RMS current `current_a` [A] at the conductor
/// temperature `temperature_k` [K] (IEEE 738 eq. (1a)'s `I^2 R(T_avg)` term).
pub fn joule_w_per_m(c: &ThermalConductor, temperature_k: f64, current_a: f64) -> f64 {
    current_a * current_a * resistance_ohm_per_m(c, temperature_k)
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::thermal::ieee738::annex_b::{self, C_TO_K};

    fn drake() -> ThermalConductor {
        annex_b::drake()
    }

    #[test]
    fn annex_b_resistance_at_100_c() {
        // IEEE 738-2012 Annex B: R(100 C) = 9.390e-5 ohm/m, printed to four digits (quoted so by thermohl
        // test/test_ieee.py, pylinerating tests/test_ieee.py). Eq. (10) gives exactly 7.283e-5 + 1.405e-5 * 75/50 =
        // 9.3905e-5: on the rounding tie, so the printed 9.390e-5 is within half a unit (0.0005e-5) of it. The
        // tolerance is that half unit plus the floating-point rounding of the kelvin conversions (1e-18 ohm/m).
        let r = resistance_ohm_per_m(&drake(), 100.0 + C_TO_K);
        assert!((r - 9.390e-5).abs() <= 0.0005e-5 + 1e-18, "R(100 C) = {r:e}");
    }

    #[test]
    fn line_passes_through_both_reference_points_and_extrapolates() {
        let c = drake();
        let lo = resistance_ohm_per_m(&c, c.temperature_low_k);
        let hi = resistance_ohm_per_m(&c, c.temperature_high_k);
        assert!((lo - 7.283e-5).abs() < 1e-18 && (hi - 8.688e-5).abs() < 1e-18);
        // Equal steps in temperature give equal steps in resistance, inside and outside [T_low, T_high].
        let step = |t: f64| resistance_ohm_per_m(&c, t + 10.0) - resistance_ohm_per_m(&c, t);
        let inside = step(c.temperature_low_k + 5.0);
        for t in [C_TO_K - 40.0, C_TO_K + 150.0, C_TO_K + 250.0] {
            assert!((step(t) - inside).abs() < 1e-17, "not linear at {t} K");
        }
        // Below T_low the line continues downwards (extrapolation, not clamping).
        assert!(resistance_ohm_per_m(&c, C_TO_K) < lo);
    }

    #[test]
    fn magnetic_core_factor_scales_and_joule_is_i_squared_r() {
        let mut c = drake();
        let t = 100.0 + C_TO_K;
        let r1 = resistance_ohm_per_m(&c, t);
        c.magnetic_core_factor = 1.04;
        let r2 = resistance_ohm_per_m(&c, t);
        assert!((r2 / r1 - 1.04).abs() < 1e-14);
        assert_eq!(joule_w_per_m(&c, t, 0.0), 0.0);
        let q = joule_w_per_m(&c, t, 1000.0);
        assert!((q - 1.0e6 * r2).abs() < 1e-12 * q);
        // Doubling the current quadruples the heating.
        assert!((joule_w_per_m(&c, t, 2000.0) / q - 4.0).abs() < 1e-14);
    }
}
