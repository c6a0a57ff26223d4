//! The time scale of heat conduction: dimensionless time `t = kappa t_phys / l^2` of (5.1).
//!
//! Making `u_t = kappa u_xx` (x in metres, t in seconds) dimensionless with the span `l` gives (5.1) with
//! `s = x / l` and `t = kappa t_phys / l^2`, where `kappa = k / (rho c)` is the thermal diffusivity.

/// Thermal diffusivity `kappa = k / (rho c)` [m^2/s] for the conductivity `conductivity` [W/(m K)], the
/// density `density` [kg/m^3] and the specific heat `specific_heat` [J/(kg K)].
pub fn thermal_diffusivity(conductivity: f64, density: f64, specific_heat: f64) -> f64 {
    conductivity / (density * specific_heat)
}

/// Physical time [s] per unit of dimensionless heat time, `l^2 / kappa`, for the length `length_m` [m] and the
/// diffusivity `diffusivity` [m^2/s].
pub fn conduction_time_scale_s(length_m: f64, diffusivity: f64) -> f64 {
    length_m * length_m / diffusivity
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paper_aluminium() {
        // Paper 5.4: k = 209 W/(m K), rho = 2700 kg/m^3, c = 0.9 kJ/(kg K); docs/paper_notes.md: kappa ~ 8.6e-5 m^2/s.
        let kappa = thermal_diffusivity(209.0, 2700.0, 900.0);
        assert!((kappa - 8.6008e-5).abs() < 1e-9, "kappa = {kappa:e}");
        // Over the 160 m span one unit of dimensionless time is l^2 / kappa = 2.976e8 s (about 9.4 years).
        let scale = conduction_time_scale_s(160.0, kappa);
        assert!((scale / 2.9765e8 - 1.0).abs() < 1e-4, "scale = {scale:e} s");
    }
}
