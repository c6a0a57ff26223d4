//! Linear thermal expansion of the wire and the force it would cause if the length were held, (5.5)-(5.6).
//!
//! (5.5) `eps_t = (l_2 - l_1) / l_1 = alpha_t du`: the relative elongation of a free wire for a temperature
//! rise `du`. (5.6) `T = E eps_t pi d^2 / 4`: the axial force that suppresses this elongation in a wire of
//! modulus `E` and diameter `d` (the "temperature tension" of section 5.6). The wire itself applies the
//! expansion to its rest lengths (`Wire::set_temperature`); these helpers give the paper's check numbers.

/// Thermal strain (5.5) `eps_t = alpha_t du` [-], for the expansion coefficient `alpha_per_k` [1/K] and the
/// temperature rise `rise_k` [K].
pub fn thermal_strain(alpha_per_k: f64, rise_k: f64) -> f64 {
    alpha_per_k * rise_k
}

/// Force (5.6) `T = E eps pi d^2 / 4` [N] for the modulus `modulus_pa` [Pa], the strain `strain` [-] and the
/// wire diameter `diameter_m` [m].
pub fn thermal_force(modulus_pa: f64, strain: f64, diameter_m: f64) -> f64 {
    modulus_pa * strain * std::f64::consts::PI * diameter_m * diameter_m / 4.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paper_section_5_5_numbers() {
        // Paper 5.4-5.5: alpha_t = 23.8e-6 1/K, E = 6.25e10 Pa, d = 0.0147 m. The rise (docs/paper_notes.md) is from
        // -5 C to the equalisation temperature (200 C + (-5 C)) / 2 = 97.5 C: 102.5 K.
        let rise = (200.0 + -5.0) / 2.0 - -5.0;
        assert_eq!(rise, 102.5);
        let eps = thermal_strain(23.8e-6, rise);
        // Printed to three digits, 24.4e-4: half a unit in the last digit.
        assert!((eps - 24.4e-4).abs() <= 0.05e-4, "eps_t = {eps:e}");
        let force = thermal_force(6.25e10, eps, 0.0147);
        // Printed 25.9 kN, three digits.
        assert!((force - 25.9e3).abs() <= 50.0, "T = {force} N");
    }
}
