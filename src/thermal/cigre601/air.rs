//! Properties of the air film around the conductor, CIGRE TB 601 (2014) section 3.5.1 (pp. 24-25).
//!
//! The convective correlations of [`super::convection`] take the air at the film temperature, the mean of the
//! conductor surface and the ambient temperature,
//!
//! ```text
//! T_f = (T_s + T_a) / 2                                                         (section 3.5.1, p. 24)
//! lambda_f = 2.368e-2 + 7.23e-5 T_f - 2.763e-8 T_f^2          [W/(m K)]           eq. (18), p. 24
//! mu_f     = (17.239 + 4.635e-2 T_f - 2.03e-5 T_f^2) 1e-6     [kg/(m s)]          eq. (19), p. 25
//! gamma    = (1.293 - 1.525e-4 y + 6.379e-9 y^2) / (1 + 0.00367 T_f)  [kg/m^3]    eq. (20), p. 25
//! nu_f     = mu_f / gamma                                      [m^2/s]             (text, p. 25)
//! Pr       = c_f mu_f / lambda_f,   c_f = 1005 J/(kg K)        [-]                 (nomenclature)
//! ```
//!
//! with `T_f` in degrees Celsius and `y` the elevation of the conductor above sea level in metres. The brochure's
//! fits are in degrees Celsius; here the interface is in kelvin and the conversion is the exact `T - 273.15`.
//! `gamma(y, T_f) / gamma(0, T_f) = 1 - 1.1794e-4 y + 4.9335e-9 y^2` is the density ratio with elevation (the
//! quadratic numerator of eq. (20) divided by its sea-level value `1.293 kg/m^3`).

/// Offset between the kelvin and the degree Celsius scales [K] (exact).
pub const CELSIUS_OFFSET_K: f64 = 273.15;

/// Specific heat capacity of air at constant pressure `c_f` [J/(kg K)], the value TB 601 uses in the Prandtl
/// number `Pr = c_f mu_f / lambda_f`.
pub const SPECIFIC_HEAT_J_PER_KG_K: f64 = 1005.0;

/// Density of dry air at sea level and 0 degrees Celsius [kg/m^3], the constant term of eq. (20).
pub const SEA_LEVEL_DENSITY_KG_PER_M3: f64 = 1.293;

/// Film temperature `T_f = (T_s + T_a) / 2` [K] from the surface temperature `surface_k` [K] and the ambient air
/// temperature `air_k` [K] (TB 601 section 3.5.1).
pub fn film_temperature_k(surface_k: f64, air_k: f64) -> f64 {
    0.5 * (surface_k + air_k)
}

/// Thermal conductivity of air `lambda_f` [W/(m K)] at the film temperature `film_k` [K], TB 601 eq. (18).
pub fn thermal_conductivity_w_per_m_k(film_k: f64) -> f64 {
    let t = film_k - CELSIUS_OFFSET_K;
    2.368e-2 + 7.23e-5 * t - 2.763e-8 * t * t
}

/// Dynamic viscosity of air `mu_f` [kg/(m s)] at the film temperature `film_k` [K], TB 601 eq. (19).
pub fn dynamic_viscosity_kg_per_m_s(film_k: f64) -> f64 {
    let t = film_k - CELSIUS_OFFSET_K;
    (17.239 + 4.635e-2 * t - 2.03e-5 * t * t) * 1e-6
}

/// Density ratio `gamma(y) / gamma(0)` [-] of the air at the elevation `elevation_m` [m] above sea level to that
/// at sea level, at the same temperature: the numerator of TB 601 eq. (20) over `1.293 kg/m^3`.
pub fn relative_density(elevation_m: f64) -> f64 {
    let y = elevation_m;
    (SEA_LEVEL_DENSITY_KG_PER_M3 - 1.525e-4 * y + 6.379e-9 * y * y) / SEA_LEVEL_DENSITY_KG_PER_M3
}

/// Density of air `gamma` [kg/m^3] at the film temperature `film_k` [K] and the elevation `elevation_m` [m] above
/// sea level, TB 601 eq. (20).
pub fn density_kg_per_m3(film_k: f64, elevation_m: f64) -> f64 {
    let t = film_k - CELSIUS_OFFSET_K;
    SEA_LEVEL_DENSITY_KG_PER_M3 * relative_density(elevation_m) / (1.0 + 0.00367 * t)
}

/// Kinematic viscosity of air `nu_f = mu_f / gamma` [m^2/s] at the film temperature `film_k` [K] and the
/// elevation `elevation_m` [m] (TB 601 p. 25, from eqs. (19) and (20)).
pub fn kinematic_viscosity_m2_per_s(film_k: f64, elevation_m: f64) -> f64 {
    dynamic_viscosity_kg_per_m_s(film_k) / density_kg_per_m3(film_k, elevation_m)
}

/// Prandtl number of air `Pr = c_f mu_f / lambda_f` [-] at the film temperature `film_k` [K] (TB 601 nomenclature,
/// with eqs. (18) and (19) and `c_f` = [`SPECIFIC_HEAT_J_PER_KG_K`]).
pub fn prandtl_number(film_k: f64) -> f64 {
    SPECIFIC_HEAT_J_PER_KG_K * dynamic_viscosity_kg_per_m_s(film_k) / thermal_conductivity_w_per_m_k(film_k)
}

/// The air film around a conductor: its properties at the film temperature (TB 601 eqs. (18)-(20)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilmAir {
    /// film temperature `T_f = (T_s + T_a) / 2` [K]
    pub film_temperature_k: f64,
    /// thermal conductivity `lambda_f` [W/(m K)] (eq. (18))
    pub thermal_conductivity_w_per_m_k: f64,
    /// dynamic viscosity `mu_f` [kg/(m s)] (eq. (19))
    pub dynamic_viscosity_kg_per_m_s: f64,
    /// density `gamma` [kg/m^3] (eq. (20))
    pub density_kg_per_m3: f64,
    /// kinematic viscosity `nu_f = mu_f / gamma` [m^2/s]
    pub kinematic_viscosity_m2_per_s: f64,
    /// Prandtl number `Pr = c_f mu_f / lambda_f` [-]
    pub prandtl: f64,
}

impl FilmAir {
    /// The film around a surface at `surface_k` [K] in air at `air_k` [K], at the elevation `elevation_m` [m]
    /// above sea level.
    pub fn new(surface_k: f64, air_k: f64, elevation_m: f64) -> Self {
        let film_k = film_temperature_k(surface_k, air_k);
        let thermal_conductivity = thermal_conductivity_w_per_m_k(film_k);
        let dynamic_viscosity = dynamic_viscosity_kg_per_m_s(film_k);
        let density = density_kg_per_m3(film_k, elevation_m);
        Self {
            film_temperature_k: film_k,
            thermal_conductivity_w_per_m_k: thermal_conductivity,
            dynamic_viscosity_kg_per_m_s: dynamic_viscosity,
            density_kg_per_m3: density,
            kinematic_viscosity_m2_per_s: dynamic_viscosity / density,
            prandtl: SPECIFIC_HEAT_J_PER_KG_K * dynamic_viscosity / thermal_conductivity,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const K: f64 = CELSIUS_OFFSET_K;

    #[test]
    fn constant_terms_at_zero_celsius_and_sea_level() {
        // At T_f = 0 C and y = 0 each fit reduces to its constant term, printed in eqs. (18)-(20).
        assert!((thermal_conductivity_w_per_m_k(K) - 2.368e-2).abs() < 1e-15);
        assert!((dynamic_viscosity_kg_per_m_s(K) - 17.239e-6).abs() < 1e-18);
        assert!((density_kg_per_m3(K, 0.0) - 1.293).abs() < 1e-14);
        assert_eq!(relative_density(0.0), 1.0);
        let air = FilmAir::new(K + 10.0, K - 10.0, 0.0);
        assert!((air.film_temperature_k - K).abs() < 1e-12);
        assert!((air.kinematic_viscosity_m2_per_s - 17.239e-6 / 1.293).abs() < 1e-18);
    }

    #[test]
    fn fits_are_the_printed_polynomials() {
        // One step of 10 C from 0 C, by hand from the printed coefficients of eqs. (18)-(20).
        let t = K + 10.0;
        assert!((thermal_conductivity_w_per_m_k(t) - (2.368e-2 + 7.23e-4 - 2.763e-6)).abs() < 1e-15);
        assert!((dynamic_viscosity_kg_per_m_s(t) - (17.239 + 0.4635 - 2.03e-3) * 1e-6).abs() < 1e-18);
        let y = 1000.0;
        let gamma = (1.293 - 0.1525 + 6.379e-3) / 1.0367;
        assert!((density_kg_per_m3(t, y) - gamma).abs() < 1e-14);
        // The density ratio with elevation does not depend on the temperature.
        assert!((density_kg_per_m3(t, y) / density_kg_per_m3(t, 0.0) - relative_density(y)).abs() < 1e-15);
        assert!((relative_density(y) - (1.0 - 1.525e-1 / 1.293 + 6.379e-3 / 1.293)).abs() < 1e-15);
    }

    #[test]
    fn close_to_tabulated_air_properties() {
        // The brochure presents eqs. (18)-(20) as fits to tabulated air properties. Dry air at 1 atm, Incropera &
        // DeWitt, Fundamentals of Heat and Mass Transfer, Table A.4: 300 K: lambda = 26.3e-3 W/(m K),
        // mu = 184.6e-7 kg/(m s), nu = 15.89e-6 m^2/s, Pr = 0.707; 350 K: 30.0e-3, 208.2e-7, 20.92e-6, 0.700.
        // Tolerance 3.5 % for lambda, nu and Pr, 1 % for mu: the fits depart from the table by -2.7 % and -3.1 %
        // (lambda), +0.05 % and -0.7 % (mu), -1.3 % and -2.0 % (nu; the density of eq. (20) is 1.3 % over the table
        // at 300 K) and +2.5 % and +2.1 % (Pr) at 300 K and 350 K.
        for (t, lambda, mu, nu, pr) in
            [(300.0, 26.3e-3, 184.6e-7, 15.89e-6, 0.707), (350.0, 30.0e-3, 208.2e-7, 20.92e-6, 0.700)]
        {
            let air = FilmAir::new(t, t, 0.0);
            assert!((air.thermal_conductivity_w_per_m_k / lambda - 1.0).abs() < 0.035, "lambda at {t} K");
            assert!((air.dynamic_viscosity_kg_per_m_s / mu - 1.0).abs() < 0.01, "mu at {t} K");
            assert!((air.kinematic_viscosity_m2_per_s / nu - 1.0).abs() < 0.035, "nu at {t} K");
            assert!((air.prandtl / pr - 1.0).abs() < 0.035, "Pr at {t} K");
        }
    }

    #[test]
    fn thinner_air_higher_up_and_consistent_struct() {
        // Density falls with elevation (at 2000 m: 1 - 0.2359 + 0.0197 = 0.784 of sea level), so the kinematic
        // viscosity, and with it the Reynolds number's denominator, grows.
        assert!((relative_density(2000.0) - (1.293 - 0.305 + 0.025516) / 1.293).abs() < 1e-14);
        let low = FilmAir::new(K + 100.0, K + 40.0, 0.0);
        let high = FilmAir::new(K + 100.0, K + 40.0, 2000.0);
        assert!(high.density_kg_per_m3 < low.density_kg_per_m3);
        assert!(high.kinematic_viscosity_m2_per_s > low.kinematic_viscosity_m2_per_s);
        assert_eq!(high.thermal_conductivity_w_per_m_k, low.thermal_conductivity_w_per_m_k);
        let f = low.film_temperature_k;
        assert_eq!(low.thermal_conductivity_w_per_m_k, thermal_conductivity_w_per_m_k(f));
        assert_eq!(low.kinematic_viscosity_m2_per_s, kinematic_viscosity_m2_per_s(f, 0.0));
        assert!((low.prandtl - prandtl_number(f)).abs() < 1e-15);
    }
}
