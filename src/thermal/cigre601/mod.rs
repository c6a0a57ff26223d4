//! CIGRE Technical Brochure 601 (2014), "Guide for thermal rating calculations of overhead lines", WG B2.43: the
//! steady-state heat balance of a bare conductor,
//!
//! ```text
//! P_J + P_S = P_c + P_r                                          [W/m]
//! P_J = I^2 R(T)                                                 Joule heating ([`crate::thermal::joule`])
//! P_S = alpha_s D I_T                                            solar heating, eq. (8) ([`solar`])
//! P_c = pi lambda_f (T_s - T_a) Nu                               convective cooling, eq. (17) ([`convection`])
//! P_r = pi D sigma_B eps [(T_s + 273)^4 - (T_a + 273)^4]         radiative cooling, eq. (27), p. 30
//! ```
//!
//! (the film air of the convection is [`air`]; the radiation is [`crate::thermal::radiation`]).
//!
//! The magnetic, corona and evaporative terms of the brochure's general balance are left out (the magnetic heating
//! of ACSR enters through the resistance's magnetic-core factor). The radiation is exchanged with surroundings at
//! the ambient air temperature `T_a` (eq. (27) takes the surroundings at `T_a`), which is the formula IEEE Std 738
//! uses as well; the shared [`crate::thermal::radiation`] evaluates it with the exact kelvin (the
//! brochure converts with `+ 273`, a difference of about 0.1 % of `P_r` that the tests quantify). The Joule term is
//! the shared linear interpolation of the AC resistance between two reference temperatures.
//!
//! The brochure's worked examples (Annex E, Examples A and B, p. 79) are reproduced in the tests of this module and
//! of [`convection`] and [`solar`].

pub mod air;
pub mod convection;
pub mod solar;

use super::{HeatBalance, HeatTerms, ThermalConductor, Weather};

/// The TB 601 heat balance of one conductor in one weather.
#[derive(Clone, Debug, PartialEq)]
pub struct Cigre601 {
    /// the conductor's thermal data
    pub conductor: ThermalConductor,
    /// the ambient conditions: air temperature, wind, elevation, sun
    pub weather: Weather,
    /// inclination of the conductor to the horizontal `beta` [deg] (TB 601 eq. (24): it lowers natural convection);
    /// not part of the shared [`Weather`] or [`ThermalConductor`], 0 for a level span
    pub inclination_deg: f64,
}

impl Cigre601 {
    /// The heat balance of `conductor` in `weather`, on a level span (inclination 0).
    pub fn new(conductor: ThermalConductor, weather: Weather) -> Self {
        Self { conductor, weather, inclination_deg: 0.0 }
    }

    /// Convective cooling with every intermediate quantity of TB 601 section 3.5 at the surface temperature
    /// `temperature_k` [K].
    pub fn convection(&self, temperature_k: f64) -> convection::Convection {
        convection::Convection::new(&self.conductor, &self.weather, self.inclination_deg, temperature_k)
    }

    /// Solar heating with the intermediate quantities of TB 601 section 3.3; `None` at night (no sun given).
    pub fn solar(&self) -> Option<solar::Solar> {
        self.weather.sun.as_ref().map(|s| solar::Solar::new(&self.conductor, s, self.weather.elevation_m))
    }
}

impl HeatBalance for Cigre601 {
    /// The TB 601 terms at the conductor (surface) temperature `temperature_k` [K] and the current `current_a` [A].
    /// The convective and radiative terms are negative when the conductor is colder than the air.
    fn terms(&self, temperature_k: f64, current_a: f64) -> HeatTerms {
        let air_k = self.weather.air_temperature_k;
        HeatTerms {
            joule_w_per_m: super::joule::joule_w_per_m(&self.conductor, temperature_k, current_a),
            solar_w_per_m: solar::solar_heating(&self.conductor, self.weather.sun.as_ref(), self.weather.elevation_m),
            convection_w_per_m: self.convection(temperature_k).cooling_w_per_m,
            radiation_w_per_m: super::radiation::radiation_w_per_m(
                self.conductor.diameter_m,
                self.conductor.emissivity,
                temperature_k,
                air_k,
            ),
        }
    }

    fn heat_capacity_j_per_m_k(&self, temperature_k: f64) -> f64 {
        self.conductor.heat_capacity_at_j_per_m_k(temperature_k)
    }

    fn air_temperature_k(&self) -> f64 {
        self.weather.air_temperature_k
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::air::CELSIUS_OFFSET_K as K;
    use super::*;
    pub(crate) use crate::thermal::examples::tb601::{
        drake, example_a, example_b, radiation_plus_273, transient as transient_example,
    };

    /// The steady-state ampacity at the temperature `t` [K]: `I = sqrt((P_c + P_r - P_S) / R(T))`, with
    /// `R(T) = P_J(T, 1 A)`.
    fn ampacity(model: &Cigre601, t: f64) -> f64 {
        let q = model.terms(t, 1.0);
        ((q.convection_w_per_m + q.radiation_w_per_m - q.solar_w_per_m) / q.joule_w_per_m).sqrt()
    }

    /// The conductor temperature [K] at which `net(T) = 0`, by bisection between the air temperature and 500 C.
    fn steady_temperature_k(net: impl Fn(f64) -> f64, air_k: f64) -> f64 {
        let (mut lo, mut hi) = (air_k, K + 500.0);
        assert!(net(lo) > 0.0 && net(hi) < 0.0);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if net(mid) > 0.0 { lo = mid } else { hi = mid }
        }
        0.5 * (lo + hi)
    }

    #[test]
    fn example_a_heat_balance_and_rating() {
        // TB 601 Annex E, Example A (p. 79), printed (as quoted by statnett/linerate
        // tests/acceptance_tests/test_cigre_ampacity_cases.py): P_c = 77.6, P_r = 39.1, P_S = 27.2 W/m,
        // R_ac(100 C) = 9.3905e-5 ohm/m, I = 976 A.
        let (model, t) = example_a();
        let q = model.terms(t, 1.0);
        // R(100 C) = 7.283e-5 + 1.405e-5 * 75 / 50, printed to five digits: half a unit 0.00005e-5 ohm/m.
        assert!((q.joule_w_per_m - 9.3905e-5).abs() <= 0.00005e-5, "R = {:e}", q.joule_w_per_m);
        // P_c: 77.668 W/m at full precision, tolerance as in convection::tests (half unit + 0.1 % for the
        // brochure's rounded intermediate values).
        let tol_c = 0.05 + 1e-3 * 77.6;
        assert!((q.convection_w_per_m - 77.6).abs() <= tol_c, "P_c = {}", q.convection_w_per_m);
        // P_r, eq. (27) with the ambient temperature: 39.076 W/m as the brochure converts (+273), 39.127 W/m with
        // the exact kelvin; both within half a unit (0.05 W/m) of the printed 39.1.
        assert!((radiation_plus_273(&model, t) - 39.1).abs() <= 0.05);
        assert!((q.radiation_w_per_m - 39.1).abs() <= 0.05, "P_r = {}", q.radiation_w_per_m);
        // P_S: 27.211 W/m, half a unit 0.05 W/m.
        assert!((q.solar_w_per_m - 27.2).abs() <= 0.05, "P_S = {}", q.solar_w_per_m);
        // The rating: 976.72 A. The brochure's 976 A follows from its printed terms, sqrt(89.5 / 9.3905e-5) =
        // 976.27 A. Tolerance: half a unit (0.5 A) plus the terms' tolerances propagated,
        // dI = I/2 * (tol_c + 0.05 + 0.05) / 89.5 = 1.24 A.
        let i = ampacity(&model, t);
        let tol_i = 0.5 + 0.5 * 976.0 * (tol_c + 0.05 + 0.05) / 89.5;
        assert!((i - 976.0).abs() <= tol_i, "I = {i}");
        // At that current the heat balance closes at 100 C.
        let back = steady_temperature_k(|x| model.terms(x, i).net_w_per_m(), model.weather.air_temperature_k);
        assert!((back - t).abs() < 1e-6);
    }

    #[test]
    fn example_b_heat_balance_and_rating() {
        // TB 601 Annex E, Example B (p. 79), printed (quoted as for Example A): P_c = 172.1, P_r = 54, P_S = 13.7
        // W/m, R_ac(100 C) = 9.3905e-5 ohm/m, I = 1504 A. (The brochure's text has 1054 A, a transposition:
        // its own terms give sqrt((172.1 + 54 - 13.7) / 9.3905e-5) = 1504 A, as linerate notes.)
        let (model, t) = example_b();
        let q = model.terms(t, 1.0);
        assert!((q.joule_w_per_m - 9.3905e-5).abs() <= 0.00005e-5);
        let tol_c = 0.05 + 1e-3 * 172.1;
        assert!((q.convection_w_per_m - 172.1).abs() <= tol_c, "P_c = {}", q.convection_w_per_m);
        // P_r printed as 54 (half a unit 0.5 W/m): 53.996 W/m with +273 (which also rounds to 54.0), 54.068 W/m
        // with the exact kelvin.
        let tol_r = 0.5;
        assert!((radiation_plus_273(&model, t) - 54.0).abs() <= 0.05);
        assert!((q.radiation_w_per_m - 54.0).abs() <= tol_r, "P_r = {}", q.radiation_w_per_m);
        assert!((q.solar_w_per_m - 13.7).abs() <= 0.05, "P_S = {}", q.solar_w_per_m);
        // 1504.56 A; tolerance half a unit plus the propagated term tolerances (2.7 A).
        let i = ampacity(&model, t);
        let tol_i = 0.5 + 0.5 * 1504.0 * (tol_c + tol_r + 0.05) / 212.4;
        assert!((i - 1504.0).abs() <= tol_i, "I = {i}");
    }

    #[test]
    fn transient_example_initial_steady_state() {
        // TB 601's transient worked example starts from the steady state of Drake (D = 28.143 mm, d = 4.4 mm,
        // R_ac(25 C) = 0.0727e-3, R_ac(75 C) = 0.0872e-3 ohm/m, emissivity = absorptivity = 0.8) carrying 802 A at
        // night (latitude 50 deg N, 10 June, 00:00) in air at 24 C with a wind of 1.9 m/s at 55 deg to the
        // axis: T = 42.01 C (as quoted by statnett/linerate tests/acceptance_tests/test_cigre_transient_cases.py,
        // there with the wind at 35 deg to an east-west span's azimuth, an angle of attack of 55 deg).
        let model = transient_example(24.0, 1.9, 55.0);
        let air = model.weather.air_temperature_k;
        // The sun is below the horizon at midnight.
        assert_eq!(model.terms(K + 42.0, 802.0).solar_w_per_m, 0.0);
        let exact = steady_temperature_k(|t| model.terms(t, 802.0).net_w_per_m(), air);
        let plus_273 = steady_temperature_k(
            |t| {
                let q = model.terms(t, 802.0);
                q.net_w_per_m() + q.radiation_w_per_m - radiation_plus_273(&model, t)
            },
            air,
        );
        // Printed to 0.01 C: half a unit 0.005 K. As the brochure converts (+273 in eq. (27)): 42.0066 C. With the
        // exact kelvin the radiation is 0.012 W/m larger and the temperature 0.0047 K lower, 42.0019 C: tolerance
        // half a unit plus that computed shift.
        assert!((plus_273 - K - 42.01).abs() <= 0.005, "T = {} C", plus_273 - K);
        assert!((exact - K - 42.01).abs() <= 0.005 + (plus_273 - exact).abs(), "T = {} C", exact - K);
        // Forced convection decides at 1.9 m/s (Re = 3290, second stranded row of Table 4, R_s > 0.05).
        let conv = model.convection(exact);
        assert!(conv.nusselt == conv.nusselt_forced && conv.reynolds > 2650.0);
    }

    #[test]
    fn terms_are_the_modules_and_shared_functions() {
        let (model, t) = example_a();
        let q = model.terms(t, 900.0);
        assert_eq!(q.convection_w_per_m, model.convection(t).cooling_w_per_m);
        assert_eq!(q.solar_w_per_m, model.solar().unwrap().heating_w_per_m);
        assert_eq!(q.joule_w_per_m, crate::thermal::joule::joule_w_per_m(&model.conductor, t, 900.0));
        // Radiation to the ambient air temperature (eq. (27)).
        let c = &model.conductor;
        let r = crate::thermal::radiation::radiation_w_per_m(
            c.diameter_m,
            c.emissivity,
            t,
            model.weather.air_temperature_k,
        );
        assert_eq!(q.radiation_w_per_m, r);
        assert_eq!(model.heat_capacity_j_per_m_k(293.15), 1.116 * 897.0 + 0.5119 * 481.0);
        // No current, no Joule heating; no sun, no solar heating; at the air temperature no cooling.
        assert_eq!(model.terms(t, 0.0).joule_w_per_m, 0.0);
        let mut night = model.clone();
        night.weather.sun = None;
        assert_eq!(night.terms(t, 900.0).solar_w_per_m, 0.0);
        assert!(night.solar().is_none());
        let at_air = model.terms(model.weather.air_temperature_k, 0.0);
        assert_eq!((at_air.convection_w_per_m, at_air.radiation_w_per_m), (0.0, 0.0));
        // The net heating falls with the temperature (cooling grows faster than the resistance).
        let mut last = f64::INFINITY;
        for k in 0..100 {
            let net = model.terms(K + 40.0 + k as f64, 900.0).net_w_per_m();
            assert!(net < last);
            last = net;
        }
    }
}
