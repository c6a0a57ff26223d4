//! Solar heating, CIGRE TB 601 (2014) section 3.3 (pp. 18-20): the position of the sun, the direct, diffuse and
//! ground-reflected radiation, and the power the conductor absorbs.
//!
//! ```text
//! P_S = alpha_s D I_T                                                          [W/m]     eq. (8),  p. 18
//! I_T = I_B (sin eta + (pi/2) F sin H_s) + I_d (1 + (pi/2) F)                  [W/m^2]   eq. (9),  p. 18
//! I_B(0) = N_s 1280 sin H_s / (sin H_s + 0.314)                                [W/m^2]   eq. (10), p. 19
//! I_B(y) = I_B(0) [1 + 1.4e-4 y (1367 / I_B(0) - 1)]                           [W/m^2]   eq. (11), p. 19
//! I_d = (430.5 - 0.3288 I_B) sin H_s                                           [W/m^2]   eq. (13), p. 20
//! eta = arccos[cos H_s cos(gamma_s - gamma_c)]                                 [deg]     eq. (14), p. 20
//! ```
//!
//! `alpha_s` is the absorptivity and `D` the diameter of the conductor, `I_T` the global radiation the conductor
//! receives: the direct beam `I_B` at the angle `eta` to the axis, the diffuse sky radiation `I_d` and both
//! reflected by the ground of albedo `F`. `I_B(0)` is the direct radiation at sea level for the clearness ratio
//! `N_s` (1 for a clear, 0.5 for an industrial atmosphere), `I_B(y)` at the elevation `y` [m] (1367 W/m^2 being the
//! solar constant). `H_s` is the solar altitude, `gamma_s` the azimuth of the sun and `gamma_c` that of the
//! conductor's axis. The position of the sun follows the brochure's solar geometry (section 3.3):
//!
//! ```text
//! delta_s = 23.3 sin[2 pi (284 + N) / 365]                  declination [deg], N the day of the year
//! Z = 15 (t - 12)                                           hour angle [deg], t the solar time [h]
//! sin H_s = sin(phi) sin(delta_s) + cos(phi) cos(delta_s) cos(Z)      phi the latitude
//! ```
//!
//! The brochure writes the sun's azimuth as an arcsine, `gamma_s = arcsin(cos delta_s sin Z / cos H_s)` measured
//! from the south, which is exact only while the sun is south of the east-west line; here the azimuth is taken
//! with its quadrant (clockwise from north, as the conductor's azimuth of [`Sun`]), the same wherever the arcsine
//! is valid. Below the horizon (`H_s <= 0`) there is no solar heating.
//!
//! Measured radiation (section 3.3): where a measured global radiation is given
//! ([`Sun::measured_global_w_per_m2`]) it replaces the computed `I_T` in eq. (8).

use crate::thermal::ThermalConductor;
use crate::thermal::weather::Sun;

/// Solar constant [W/m^2] in eq. (11).
pub const SOLAR_CONSTANT_W_PER_M2: f64 = 1367.0;

/// Solar declination `delta_s` [deg] on the day of the year `day_of_year` [-] (1 = 1 January).
pub fn declination_deg(day_of_year: f64) -> f64 {
    23.3 * (2.0 * std::f64::consts::PI * (284.0 + day_of_year) / 365.0).sin()
}

/// Hour angle of the sun `Z = 15 (t - 12)` [deg] at the local solar time `solar_hour` [h]: negative in the
/// morning, zero at solar noon.
pub fn hour_angle_deg(solar_hour: f64) -> f64 {
    15.0 * (solar_hour - 12.0)
}

/// Sine of the solar altitude `sin H_s = sin(phi) sin(delta_s) + cos(phi) cos(delta_s) cos(Z)` [-] at the latitude
/// `latitude_deg` [deg], declination `declination_deg` [deg] and hour angle `hour_angle_deg` [deg].
pub fn sin_solar_altitude(latitude_deg: f64, declination_deg: f64, hour_angle_deg: f64) -> f64 {
    let (phi, dec, z) = (latitude_deg.to_radians(), declination_deg.to_radians(), hour_angle_deg.to_radians());
    phi.sin() * dec.sin() + phi.cos() * dec.cos() * z.cos()
}

/// Azimuth of the sun `gamma_s` [deg], clockwise from north in `(-180, 180]`, at the latitude `latitude_deg`
/// [deg], declination `declination_deg` [deg] and hour angle `hour_angle_deg` [deg].
pub fn solar_azimuth_deg(latitude_deg: f64, declination_deg: f64, hour_angle_deg: f64) -> f64 {
    let (phi, dec, z) = (latitude_deg.to_radians(), declination_deg.to_radians(), hour_angle_deg.to_radians());
    // cos H_s sin(gamma_s) = -cos(delta_s) sin(Z)
    // cos H_s cos(gamma_s) = sin(delta_s) cos(phi) - cos(delta_s) sin(phi) cos(Z)
    let east = -dec.cos() * z.sin();
    let north = dec.sin() * phi.cos() - dec.cos() * phi.sin() * z.cos();
    let azimuth = east.atan2(north).to_degrees();
    if azimuth <= -180.0 { azimuth + 360.0 } else { azimuth }
}

/// Sine of the angle of incidence `eta` of the sun's rays on the conductor's axis [-], TB 601 eq. (14), from the sine
/// of the solar altitude `sin_altitude` [-], the sun's azimuth `solar_azimuth_deg` [deg] and the azimuth of the
/// conductor's axis `line_azimuth_deg` [deg].
pub fn sin_incidence(sin_altitude: f64, solar_azimuth_deg: f64, line_azimuth_deg: f64) -> f64 {
    let cos_altitude = (1.0 - sin_altitude * sin_altitude).max(0.0).sqrt();
    let cos_eta = cos_altitude * (solar_azimuth_deg - line_azimuth_deg).to_radians().cos();
    (1.0 - cos_eta * cos_eta).max(0.0).sqrt()
}

/// Direct solar radiation at sea level on a surface normal to the beam `I_B(0)` [W/m^2], TB 601 eq. (10), for the
/// sine of the solar altitude `sin_altitude` [-] and the clearness ratio `clearness_ratio` `N_s` [-]; 0 with the
/// sun below the horizon.
pub fn direct_radiation_sea_level_w_per_m2(sin_altitude: f64, clearness_ratio: f64) -> f64 {
    if sin_altitude <= 0.0 {
        return 0.0;
    }
    clearness_ratio * 1280.0 * sin_altitude / (sin_altitude + 0.314)
}

/// Direct solar radiation at the elevation `elevation_m` [m] `I_B(y)` [W/m^2], TB 601 eq. (11), written as
/// `I_B(0) (1 - 1.4e-4 y) + 1367 * 1.4e-4 y` (the same, without dividing by `I_B(0)`); 0 with the sun below the
/// horizon.
pub fn direct_radiation_w_per_m2(sin_altitude: f64, clearness_ratio: f64, elevation_m: f64) -> f64 {
    if sin_altitude <= 0.0 {
        return 0.0;
    }
    let sea_level = direct_radiation_sea_level_w_per_m2(sin_altitude, clearness_ratio);
    let k = 1.4e-4 * elevation_m;
    sea_level * (1.0 - k) + SOLAR_CONSTANT_W_PER_M2 * k
}

/// Diffuse sky radiation on a horizontal surface `I_d = (430.5 - 0.3288 I_B) sin H_s` [W/m^2], TB 601 eq. (13),
/// from the direct radiation `direct_w_per_m2` [W/m^2] and the sine of the solar altitude `sin_altitude` [-];
/// not negative, and 0 with the sun below the horizon.
pub fn diffuse_radiation_w_per_m2(direct_w_per_m2: f64, sin_altitude: f64) -> f64 {
    ((430.5 - 0.3288 * direct_w_per_m2) * sin_altitude.max(0.0)).max(0.0)
}

/// Global radiation on a horizontal surface `I_B sin H_s + I_d` [W/m^2] (what a horizontal pyranometer measures),
/// from the direct radiation [W/m^2], the diffuse radiation [W/m^2] and the sine of the solar altitude [-].
pub fn global_horizontal_w_per_m2(direct_w_per_m2: f64, diffuse_w_per_m2: f64, sin_altitude: f64) -> f64 {
    direct_w_per_m2 * sin_altitude.max(0.0) + diffuse_w_per_m2
}

/// Global radiation received by the conductor `I_T` [W/m^2], TB 601 eq. (9), from the direct radiation
/// `direct_w_per_m2` [W/m^2], the diffuse radiation `diffuse_w_per_m2` [W/m^2], the ground albedo `albedo` `F` [-],
/// the sine of the angle of incidence `sin_eta` [-] and the sine of the solar altitude `sin_altitude` [-]. The
/// ground reflects `F` of the direct and diffuse radiation diffusely, and the conductor receives it over its
/// lower half: the factors `(pi/2) F`.
pub fn global_radiation_w_per_m2(
    direct_w_per_m2: f64,
    diffuse_w_per_m2: f64,
    albedo: f64,
    sin_eta: f64,
    sin_altitude: f64,
) -> f64 {
    let reflected = 0.5 * std::f64::consts::PI * albedo;
    direct_w_per_m2 * (sin_eta + reflected * sin_altitude.max(0.0)) + diffuse_w_per_m2 * (1.0 + reflected)
}

/// Solar heating `P_S = alpha_s D I_T` [W/m], TB 601 eq. (8), of a conductor of absorptivity `absorptivity` [-] and
/// outside diameter `diameter_m` [m] receiving the global radiation `global_w_per_m2` [W/m^2].
pub fn solar_heating_w_per_m(absorptivity: f64, diameter_m: f64, global_w_per_m2: f64) -> f64 {
    absorptivity * diameter_m * global_w_per_m2
}

/// The TB 601 solar heating of one conductor under one sun, with the intermediate quantities of section 3.3.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Solar {
    /// solar declination `delta_s` [deg]
    pub declination_deg: f64,
    /// hour angle `Z` [deg]
    pub hour_angle_deg: f64,
    /// solar altitude `H_s` [deg] (negative below the horizon)
    pub altitude_deg: f64,
    /// azimuth of the sun `gamma_s` [deg], clockwise from north
    pub azimuth_deg: f64,
    /// angle of incidence of the beam on the conductor's axis `eta` [deg] (eq. (14))
    pub incidence_deg: f64,
    /// direct radiation at sea level `I_B(0)` [W/m^2] (eq. (10))
    pub direct_sea_level_w_per_m2: f64,
    /// direct radiation at the conductor's elevation `I_B(y)` [W/m^2] (eq. (11))
    pub direct_w_per_m2: f64,
    /// diffuse sky radiation `I_d` [W/m^2] (eq. (13))
    pub diffuse_w_per_m2: f64,
    /// global radiation on a horizontal surface `I_B sin H_s + I_d` [W/m^2]
    pub global_horizontal_w_per_m2: f64,
    /// global radiation received by the conductor `I_T` [W/m^2] (eq. (9), or the measured value)
    pub global_w_per_m2: f64,
    /// whether `global_w_per_m2` is the measured radiation rather than the computed one
    pub measured: bool,
    /// solar heating `P_S` [W/m] (eq. (8))
    pub heating_w_per_m: f64,
}

impl Solar {
    /// Solar heating of the conductor `conductor` (diameter, absorptivity) under the sun `sun` at the elevation
    /// `elevation_m` [m] above sea level.
    pub fn new(conductor: &ThermalConductor, sun: &Sun, elevation_m: f64) -> Self {
        let dec = declination_deg(sun.day_of_year);
        let z = hour_angle_deg(sun.solar_hour);
        let sin_h = sin_solar_altitude(sun.latitude_deg, dec, z);
        let azimuth = solar_azimuth_deg(sun.latitude_deg, dec, z);
        let sin_eta = sin_incidence(sin_h, azimuth, sun.line_azimuth_deg);
        let cos_eta = (1.0 - sin_h * sin_h).max(0.0).sqrt() * (azimuth - sun.line_azimuth_deg).to_radians().cos();
        let i_b0 = direct_radiation_sea_level_w_per_m2(sin_h, sun.clearness_ratio);
        let i_b = direct_radiation_w_per_m2(sin_h, sun.clearness_ratio, elevation_m);
        let i_d = diffuse_radiation_w_per_m2(i_b, sin_h);
        let computed = global_radiation_w_per_m2(i_b, i_d, sun.albedo, sin_eta, sin_h);
        let (global, measured) = match sun.measured_global_w_per_m2 {
            Some(g) => (g.max(0.0), true),
            None => (computed, false),
        };
        Self {
            declination_deg: dec,
            hour_angle_deg: z,
            altitude_deg: sin_h.clamp(-1.0, 1.0).asin().to_degrees(),
            azimuth_deg: azimuth,
            incidence_deg: cos_eta.clamp(-1.0, 1.0).acos().to_degrees(),
            direct_sea_level_w_per_m2: i_b0,
            direct_w_per_m2: i_b,
            diffuse_w_per_m2: i_d,
            global_horizontal_w_per_m2: global_horizontal_w_per_m2(i_b, i_d, sin_h),
            global_w_per_m2: global,
            measured,
            heating_w_per_m: solar_heating_w_per_m(conductor.absorptivity, conductor.diameter_m, global),
        }
    }
}

/// Solar heating `P_S` [W/m] of the conductor `conductor` under the sun `sun` (`None`: night) at the elevation
/// `elevation_m` [m], TB 601 eq. (8).
pub fn solar_heating(conductor: &ThermalConductor, sun: Option<&Sun>, elevation_m: f64) -> f64 {
    sun.map_or(0.0, |s| Solar::new(conductor, s, elevation_m).heating_w_per_m)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::thermal::cigre601::tests::{example_a, example_b};

    #[test]
    fn example_a_solar_heating() {
        // TB 601 Annex E, Example A (p. 79): Drake (D = 28.1 mm, alpha_s = 0.8), latitude 30 deg N, 10 June
        // (N = 161) at 11:00 solar time, east-west line, clear sky (N_s = 1), albedo 0.1, sea level:
        // P_S = 27.2 W/m (as quoted by statnett/linerate tests/acceptance_tests/test_cigre_ampacity_cases.py).
        let (model, _) = example_a();
        let sun = model.weather.sun.as_ref().unwrap();
        let s = Solar::new(&model.conductor, sun, model.weather.elevation_m);
        // The sun is south-east (114.5 deg), 74.8 deg high; eta = 76.2 deg; I_B = 965.8, I_d = 109.0,
        // I_T = 1210.4 W/m^2.
        assert!((s.altitude_deg - 74.81).abs() < 0.01 && (s.azimuth_deg - 114.47).abs() < 0.01, "{s:?}");
        assert!((s.incidence_deg - 76.20).abs() < 0.01 && (s.global_w_per_m2 - 1210.4).abs() < 0.1, "{s:?}");
        // Printed to three digits: tolerance half a unit, 0.05 W/m (27.211 W/m computed).
        assert!((s.heating_w_per_m - 27.2).abs() <= 0.05, "P_S = {}", s.heating_w_per_m);
    }

    #[test]
    fn example_b_solar_heating() {
        // TB 601 Annex E, Example B (p. 79): Drake (alpha_s = 0.9), latitude 50 deg N, 3 October (N = 276) at
        // 14:00 solar time, north-south line, N_s = 0.5, albedo 0.15, 500 m above sea level: P_S = 13.7 W/m
        // (quoted as for Example A).
        let (model, _) = example_b();
        let sun = model.weather.sun.as_ref().unwrap();
        let s = Solar::new(&model.conductor, sun, model.weather.elevation_m);
        // South-west sun (-145.2 deg = 214.8 deg), 29.2 deg high; the elevation raises I_B from 389.5 to
        // 457.9 W/m^2.
        assert!((s.altitude_deg - 29.22).abs() < 0.01 && (s.azimuth_deg + 145.20).abs() < 0.01, "{s:?}");
        assert!((s.direct_sea_level_w_per_m2 - 389.47).abs() < 0.01 && (s.direct_w_per_m2 - 457.90).abs() < 0.01);
        // 13.678 W/m computed: within half a unit (0.05 W/m) of the printed 13.7. (Day 277, 3 October of a
        // leap year, would give 13.54: the example counts the days of a common year.)
        assert!((s.heating_w_per_m - 13.7).abs() <= 0.05, "P_S = {}", s.heating_w_per_m);
    }

    #[test]
    fn no_sun_below_the_horizon_or_at_night() {
        let (model, _) = example_a();
        let mut sun = model.weather.sun.clone().unwrap();
        for hour in [0.0, 3.0, 4.5, 20.0, 23.5] {
            sun.solar_hour = hour;
            let s = Solar::new(&model.conductor, &sun, 0.0);
            assert!(s.altitude_deg < 0.0, "{hour} h");
            assert_eq!((s.direct_w_per_m2, s.diffuse_w_per_m2, s.global_w_per_m2), (0.0, 0.0, 0.0), "{hour} h");
            assert_eq!(s.heating_w_per_m, 0.0);
            // also high up, where eq. (11) written naively would leave 1367 * 1.4e-4 y
            assert_eq!(Solar::new(&model.conductor, &sun, 3000.0).heating_w_per_m, 0.0);
        }
        assert_eq!(solar_heating(&model.conductor, None, 0.0), 0.0);
        assert_eq!(direct_radiation_w_per_m2(-0.1, 1.0, 1000.0), 0.0);
        assert_eq!(diffuse_radiation_w_per_m2(0.0, -0.3), 0.0);
        // The heating rises continuously from zero at sunrise.
        sun.solar_hour = 12.0;
        let mut last = f64::INFINITY;
        for _ in 0..200 {
            sun.solar_hour -= 0.05;
            let p = Solar::new(&model.conductor, &sun, 0.0).heating_w_per_m;
            assert!(p <= last + 1e-12 && p >= 0.0);
            last = p;
        }
        assert_eq!(last, 0.0);
    }

    #[test]
    fn radiation_formulas() {
        // eq. (10): half of 1280 N_s where sin H_s = 0.314; eq. (11) at sea level is eq. (10), and at
        // y = 1 / 1.4e-4 m it is the solar constant.
        assert!((direct_radiation_sea_level_w_per_m2(0.314, 1.0) - 640.0).abs() < 1e-12);
        assert!((direct_radiation_sea_level_w_per_m2(0.314, 0.5) - 320.0).abs() < 1e-12);
        assert_eq!(direct_radiation_w_per_m2(0.314, 1.0, 0.0), 640.0);
        assert!((direct_radiation_w_per_m2(0.314, 1.0, 1.0 / 1.4e-4) - 1367.0).abs() < 1e-9);
        let i0 = direct_radiation_sea_level_w_per_m2(0.7, 1.0);
        let y = 800.0;
        let printed_form = i0 * (1.0 + 1.4e-4 * y * (1367.0 / i0 - 1.0));
        assert!((direct_radiation_w_per_m2(0.7, 1.0, y) - printed_form).abs() < 1e-9);
        // eq. (13) and eq. (9) by hand.
        assert!((diffuse_radiation_w_per_m2(100.0, 0.5) - (430.5 - 32.88) * 0.5).abs() < 1e-12);
        let it = global_radiation_w_per_m2(800.0, 100.0, 0.2, 0.9, 0.6);
        let f = 0.5 * std::f64::consts::PI * 0.2;
        assert!((it - (800.0 * (0.9 + f * 0.6) + 100.0 * (1.0 + f))).abs() < 1e-9);
        // The albedo term adds the reflected part: more albedo, more heating.
        assert!(global_radiation_w_per_m2(800.0, 100.0, 0.6, 0.9, 0.6) > it);
        assert!((global_radiation_w_per_m2(800.0, 100.0, 0.0, 0.9, 0.6) - (720.0 + 100.0)).abs() < 1e-9);
        assert!((global_horizontal_w_per_m2(800.0, 100.0, 0.6) - 580.0).abs() < 1e-12);
        assert!((solar_heating_w_per_m(0.8, 0.0281, 1000.0) - 22.48).abs() < 1e-12);
    }

    #[test]
    fn sun_position() {
        // Declination: 23.3 deg at the June solstice (N = 172: 23.3 sin(2 pi 456 / 365) = 23.30), about 0 at the
        // equinoxes (N = 81: 284 + 81 = 365) and -23.3 deg in December.
        assert!(declination_deg(81.0).abs() < 1e-12);
        assert!((declination_deg(172.0) - 23.3).abs() < 0.01);
        assert!((declination_deg(355.0) + 23.3).abs() < 0.01);
        assert_eq!(hour_angle_deg(12.0), 0.0);
        assert_eq!(hour_angle_deg(11.0), -15.0);
        // At solar noon the sun stands due south (north of the tropic) at 90 - phi + delta.
        let s = sin_solar_altitude(45.0, 10.0, 0.0);
        assert!((s.asin().to_degrees() - 55.0).abs() < 1e-9);
        assert!((solar_azimuth_deg(45.0, 10.0, 0.0) - 180.0).abs() < 1e-9);
        // Morning east, afternoon west, symmetric about noon.
        let am = solar_azimuth_deg(45.0, 10.0, -30.0);
        let pm = solar_azimuth_deg(45.0, 10.0, 30.0);
        assert!(am > 90.0 && am < 180.0 && (am + pm).abs() < 1e-9);
        // Wherever the brochure's arcsine is valid (sun south of the east-west line) both agree:
        // gamma from south = arcsin(cos delta sin Z / cos H_s), so gamma from north = 180 - that (Z < 0 morning).
        for (lat, dec, z) in [(30.0, 22.86, -15.0), (50.0, -4.98, 30.0), (45.0, 0.0, -45.0)] {
            let h = sin_solar_altitude(lat, dec, z).asin();
            let from_south = (dec.to_radians().cos() * f64::to_radians(z).sin() / h.cos()).asin().to_degrees();
            let ours = solar_azimuth_deg(lat, dec, z);
            let ours_from_south = if ours > 0.0 { ours - 180.0 } else { ours + 180.0 };
            assert!((ours_from_south - from_south).abs() < 1e-9, "{lat} {dec} {z}");
        }
        // Summer morning at 30 deg N, 6:00: the sun rises north of east (azimuth < 90 deg), where the arcsine
        // cannot go.
        let early = solar_azimuth_deg(30.0, 23.0, -90.0);
        assert!(early > 0.0 && early < 90.0, "{early}");
        // eq. (14): the beam along the axis (sun on the horizon in the line's direction) gives sin eta = 0,
        // a beam across it sin eta = 1.
        assert!(sin_incidence(0.0, 90.0, 90.0) < 1e-9);
        assert!((sin_incidence(0.0, 180.0, 90.0) - 1.0).abs() < 1e-12);
        assert!((sin_incidence(1.0, 37.0, 90.0) - 1.0).abs() < 1e-12);
        // The line's direction is an axis: azimuth 90 and 270 are the same line.
        assert!((sin_incidence(0.5, 130.0, 90.0) - sin_incidence(0.5, 130.0, 270.0)).abs() < 1e-12);
    }

    #[test]
    fn measured_global_radiation_replaces_the_computed_one() {
        let (model, _) = example_a();
        let mut sun = model.weather.sun.clone().unwrap();
        sun.measured_global_w_per_m2 = Some(1000.0);
        let s = Solar::new(&model.conductor, &sun, 0.0);
        assert!(s.measured && s.global_w_per_m2 == 1000.0);
        // eq. (8) with the measured radiation: 0.8 * 0.0281 * 1000 = 22.48 W/m.
        assert!((s.heating_w_per_m - 22.48).abs() < 1e-12);
        assert_eq!(solar_heating(&model.conductor, Some(&sun), 0.0), s.heating_w_per_m);
    }

    #[test]
    fn clearness_and_elevation_raise_the_direct_beam() {
        let (model, _) = example_a();
        let mut sun = model.weather.sun.clone().unwrap();
        let clear = Solar::new(&model.conductor, &sun, 0.0);
        sun.clearness_ratio = 0.5;
        let industrial = Solar::new(&model.conductor, &sun, 0.0);
        assert!((industrial.direct_w_per_m2 / clear.direct_w_per_m2 - 0.5).abs() < 1e-12);
        // less direct beam, more diffuse light (eq. (13))
        assert!(industrial.diffuse_w_per_m2 > clear.diffuse_w_per_m2);
        assert!(industrial.heating_w_per_m < clear.heating_w_per_m);
        sun.clearness_ratio = 1.0;
        let high = Solar::new(&model.conductor, &sun, 2000.0);
        assert!(high.direct_w_per_m2 > clear.direct_w_per_m2 && high.direct_w_per_m2 < SOLAR_CONSTANT_W_PER_M2);
    }
}
