//! Convective cooling, IEEE Std 738-2012 eqs. (2c), (3a), (3b), (4a) and (5a) (pp. 10-12).
//!
//! Forced convection has two correlations, each multiplied by the wind direction factor `K_angle`:
//!
//! ```text
//! N_Re    = D rho_f V_w / mu_f                                                  eq. (2c)
//! q_c1    = K_angle [1.01 + 1.35 N_Re^0.52] k_f (T_s - T_a)                     eq. (3a), low winds
//! q_c2    = K_angle 0.754 N_Re^0.6 k_f (T_s - T_a)                              eq. (3b), high winds
//! K_angle = 1.194 - cos(phi) + 0.194 cos(2 phi) + 0.368 sin(2 phi)              eq. (4a)
//! ```
//!
//! with `phi` the angle between the wind and the conductor's axis. Eq. (3a) is correct at low winds and
//! underestimates at high winds, eq. (3b) the reverse; the standard takes the larger of the two at any wind speed.
//! They cross where `1.01 + 1.35 N_Re^0.52 = 0.754 N_Re^0.6`, at `N_Re = 1757.25`: eq. (3a) is the larger below,
//! eq. (3b) above. Natural convection (zero wind) is
//!
//! ```text
//! q_cn = 3.645 rho_f^0.5 D^0.75 (T_s - T_a)^1.25                                eq. (5a)
//! ```
//!
//! and the standard's rule (p. 11) is to compute forced and natural convection and use the larger. The air properties are those of [`super::air`]
//! at the film temperature. `D` in metres, `T_s - T_a` the same in kelvin as in degrees Celsius.
//!
//! When the surface is colder than the air the rates are negative (heat flows into the conductor): the forced
//! correlations are linear in `T_s - T_a`, the natural one is applied to `|T_s - T_a|` with its sign, and "the
//! largest" is the largest in magnitude.

use super::air::Air;

/// Wind direction factor `K_angle` [-] (eq. (4a)) for the angle `wind_angle_deg` [deg] between the wind direction and
/// the conductor's axis (90: perpendicular, `K_angle = 1`; 0: parallel, `K_angle = 0.388`). The angle is first
/// folded into [0, 90] deg, since a wind and its reverse, or its mirror image about the perpendicular, cool alike.
pub fn wind_direction_factor(wind_angle_deg: f64) -> f64 {
    let a = wind_angle_deg.rem_euclid(180.0);
    let phi = (if a > 90.0 { 180.0 - a } else { a }).to_radians();
    1.194 - phi.cos() + 0.194 * (2.0 * phi).cos() + 0.368 * (2.0 * phi).sin()
}

/// Reynolds number `N_Re = D rho_f V_w / mu_f` [-] (eq. (2c)) for the diameter `diameter_m` [m], the wind speed
/// `wind_speed_m_per_s` [m/s] and the boundary-layer air `air`.
pub fn reynolds_number(diameter_m: f64, wind_speed_m_per_s: f64, air: &Air) -> f64 {
    diameter_m * air.density_kg_per_m3 * wind_speed_m_per_s / air.dynamic_viscosity_kg_per_m_s
}

/// Forced convection for low winds `q_c1 = K_angle [1.01 + 1.35 N_Re^0.52] k_f (T_s - T_a)` [W/m] (eq. (3a)), for the
/// wind direction factor `k_angle` [-], the Reynolds number `reynolds` [-], the air's thermal conductivity
/// `conductivity_w_per_m_k` [W/(m K)] and the surface's excess temperature `excess_k = T_s - T_a` [K].
pub fn forced_low_wind_w_per_m(k_angle: f64, reynolds: f64, conductivity_w_per_m_k: f64, excess_k: f64) -> f64 {
    k_angle * (1.01 + 1.35 * reynolds.powf(0.52)) * conductivity_w_per_m_k * excess_k
}

/// Forced convection for high winds `q_c2 = K_angle 0.754 N_Re^0.6 k_f (T_s - T_a)` [W/m] (eq. (3b)); the arguments
/// as for [`forced_low_wind_w_per_m`].
pub fn forced_high_wind_w_per_m(k_angle: f64, reynolds: f64, conductivity_w_per_m_k: f64, excess_k: f64) -> f64 {
    k_angle * 0.754 * reynolds.powf(0.6) * conductivity_w_per_m_k * excess_k
}

/// Natural convection `q_cn = 3.645 rho_f^0.5 D^0.75 (T_s - T_a)^1.25` [W/m] (eq. (5a)) for the air density
/// `density_kg_per_m3` [kg/m^3], the diameter `diameter_m` [m] and the excess temperature `excess_k = T_s - T_a`
/// [K] (negative excess: the same magnitude, negative).
pub fn natural_w_per_m(density_kg_per_m3: f64, diameter_m: f64, excess_k: f64) -> f64 {
    (3.645 * density_kg_per_m3.sqrt() * diameter_m.powf(0.75) * excess_k.abs().powf(1.25)).copysign(excess_k)
}

/// The one of two rates larger in magnitude (both have the sign of `T_s - T_a`).
fn larger(a: f64, b: f64) -> f64 {
    if a.abs() >= b.abs() { a } else { b }
}

/// The three convective rates of one conductor in one wind, per unit length [W/m].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Convection {
    /// forced convection for low winds `q_c1` [W/m] (eq. (3a))
    pub forced_low_wind_w_per_m: f64,
    /// forced convection for high winds `q_c2` [W/m] (eq. (3b))
    pub forced_high_wind_w_per_m: f64,
    /// natural convection `q_cn` [W/m] (eq. (5a))
    pub natural_w_per_m: f64,
}

impl Convection {
    /// The rates for a conductor of diameter `diameter_m` [m] at the surface temperature `surface_k` [K] in air at
    /// `ambient_k` [K] and the elevation `elevation_m` [m], in a wind of `wind_speed_m_per_s` [m/s] at the angle
    /// `wind_angle_deg` [deg] to its axis.
    pub fn new(
        diameter_m: f64,
        surface_k: f64,
        ambient_k: f64,
        elevation_m: f64,
        wind_speed_m_per_s: f64,
        wind_angle_deg: f64,
    ) -> Self {
        let air = Air::at(surface_k, ambient_k, elevation_m);
        let excess = surface_k - ambient_k;
        let k_angle = wind_direction_factor(wind_angle_deg);
        let reynolds = reynolds_number(diameter_m, wind_speed_m_per_s, &air);
        let k_f = air.thermal_conductivity_w_per_m_k;
        Convection {
            forced_low_wind_w_per_m: forced_low_wind_w_per_m(k_angle, reynolds, k_f, excess),
            forced_high_wind_w_per_m: forced_high_wind_w_per_m(k_angle, reynolds, k_f, excess),
            natural_w_per_m: natural_w_per_m(air.density_kg_per_m3, diameter_m, excess),
        }
    }

    /// Forced convection `q_c` [W/m]: the larger of eqs. (3a) and (3b).
    pub fn forced_w_per_m(&self) -> f64 {
        larger(self.forced_low_wind_w_per_m, self.forced_high_wind_w_per_m)
    }

    /// The convective cooling the standard uses [W/m]: the largest of forced and natural convection.
    pub fn w_per_m(&self) -> f64 {
        larger(self.forced_w_per_m(), self.natural_w_per_m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const C_TO_K: f64 = 273.15;
    /// IEEE 738-2012 Annex B: Drake, D = 28.14 mm.
    const D: f64 = 28.14e-3;
    /// Annex B: V_w = 0.61 m/s (2 ft/s), perpendicular to the conductor.
    const V_W: f64 = 0.61;

    /// Annex B: T_s = 100 C in T_a = 40 C at sea level (see air.rs for the elevation), wind at 90 deg.
    fn annex_b() -> Convection {
        Convection::new(D, 100.0 + C_TO_K, 40.0 + C_TO_K, 0.0, V_W, 90.0)
    }

    // The Annex B intermediates as printed (quoted by pylinerating tests/test_ieee.py): rho_f = 1.029 kg/m^3,
    // mu_f = 2.043e-5 kg/(m s), k_f = 0.02945 W/(m C), N_Re = 865, K_angle = 1, T_s - T_a = 60 C. The standard
    // computes each result from these rounded intermediates, so a result from our full-precision chain may differ
    // from the printed one by the effect of that rounding as well as by half a unit of its own last digit.
    const RHO_PRINTED: f64 = 1.029;
    const MU_PRINTED: f64 = 2.043e-5;
    const K_F_PRINTED: f64 = 0.02945;
    const N_RE_PRINTED: f64 = 865.0;

    /// Largest relative change of N_Re from the 4-digit rounding of rho_f and mu_f before eq. (2c): 0.0005/1.029 +
    /// 0.0005e-5/2.043e-5 = 7.3e-4; with the half unit of the printed N_Re (0.5/865) it is 1.31e-3.
    fn reynolds_rounding() -> f64 {
        0.0005 / RHO_PRINTED + 0.0005e-5 / MU_PRINTED + 0.5 / N_RE_PRINTED
    }

    #[test]
    fn wind_direction_factor_limits() {
        // Eq. (4a) at phi = 90 deg: 1.194 - 0 + 0.194 * (-1) + 0 = 1 (the correlations are for perpendicular wind).
        assert!((wind_direction_factor(90.0) - 1.0).abs() < 1e-12);
        // Parallel wind: 1.194 - 1 + 0.194 = 0.388.
        assert!((wind_direction_factor(0.0) - 0.388).abs() < 1e-12);
        // Folding: the reverse wind and the mirror image cool alike.
        for phi in [10.0, 37.0, 60.0, 89.0] {
            let k = wind_direction_factor(phi);
            for same in [180.0 - phi, phi + 180.0, -phi, 360.0 - phi] {
                assert!((wind_direction_factor(same) - k).abs() < 1e-12, "{phi} vs {same}");
            }
        }
        // Between parallel and perpendicular the factor rises monotonically.
        let mut last = 0.0;
        for phi in 0..=90 {
            let k = wind_direction_factor(f64::from(phi));
            assert!(k > last, "K_angle not rising at {phi} deg");
            last = k;
        }
    }

    #[test]
    fn annex_b_reynolds_number() {
        let air = Air::at(100.0 + C_TO_K, 40.0 + C_TO_K, 0.0);
        // Eq. (2c) with the printed rho_f and mu_f: 864.57, printed N_Re = 865 (half unit 0.5).
        let air_printed = Air { density_kg_per_m3: RHO_PRINTED, dynamic_viscosity_kg_per_m_s: MU_PRINTED, ..air };
        let from_printed = reynolds_number(D, V_W, &air_printed);
        assert!((from_printed - N_RE_PRINTED).abs() <= 0.5, "N_Re(printed rho, mu) = {from_printed}");
        // Full precision: 864.44; within the rounding of rho_f, mu_f and N_Re (1.13).
        let n_re = reynolds_number(D, V_W, &air);
        assert!((n_re - N_RE_PRINTED).abs() <= reynolds_rounding() * N_RE_PRINTED, "N_Re = {n_re}");
    }

    #[test]
    fn annex_b_forced_convection_high_wind_correlation() {
        // IEEE 738-2012 Annex B: q_c2 = 77.06 W/m (eq. (3b)), four digits.
        // From the printed intermediates: 77.058, within half a unit (0.005).
        let q2_printed_inputs = forced_high_wind_w_per_m(1.0, N_RE_PRINTED, K_F_PRINTED, 60.0);
        assert!((q2_printed_inputs - 77.06).abs() <= 0.005, "q_c2(printed inputs) = {q2_printed_inputs}");
        // Full precision: 77.034. Tolerance: half a unit plus the rounding of the intermediates propagated through
        // q_c2 ~ N_Re^0.6 k_f: 0.6 * 1.31e-3 + 0.000005/0.02945 relative, i.e. 0.074 W/m.
        let q2 = annex_b().forced_high_wind_w_per_m;
        let tol = 0.005 + 77.06 * (0.6 * reynolds_rounding() + 0.000005 / K_F_PRINTED);
        assert!((q2 - 77.06).abs() <= tol, "q_c2 = {q2}, tolerance {tol}");
    }

    #[test]
    fn annex_b_forced_convection_low_wind_correlation() {
        // IEEE 738-2012 Annex B prints q_c1 = 81.93 W/m (eq. (3a)) and uses it as q_c (quoted by thermohl
        // test/test_ieee.py and pylinerating tests/test_ieee.py). Eq. (3a) evaluated at the Annex's own printed
        // intermediates gives 82.10 W/m, and no rounding of them reaches 81.93: the printed value is 0.2 % below
        // its own equation. pylinerating ("a little bit off compared to the standard") and thermohl (rtol 0.002)
        // meet the same gap. We test our value against eq. (3a) at the printed intermediates, with their rounding
        // propagated (q_c1 ~ N_Re^0.509 k_f here), and bound the unexplained gap to the printed value separately.
        let q1_printed_inputs = forced_low_wind_w_per_m(1.0, N_RE_PRINTED, K_F_PRINTED, 60.0);
        let exponent = {
            let a = 1.35 * N_RE_PRINTED.powf(0.52);
            0.52 * a / (1.01 + a)
        };
        let rounding = q1_printed_inputs * (exponent * reynolds_rounding() + 0.000005 / K_F_PRINTED);
        let q1 = annex_b().forced_low_wind_w_per_m;
        assert!((q1 - q1_printed_inputs).abs() <= rounding, "q_c1 = {q1} vs {q1_printed_inputs} +- {rounding}");
        // The printed 81.93 lies outside what rounding explains (documents the discrepancy) ...
        assert!((q1_printed_inputs - 81.93).abs() > rounding + 0.005);
        // ... and within 0.25 % of our 82.08 (the size of that discrepancy, not a rounding tolerance).
        assert!((q1 / 81.93 - 1.0).abs() < 2.5e-3, "q_c1 = {q1}");
    }

    #[test]
    fn annex_b_natural_convection_and_choice() {
        // IEEE 738-2012 Annex B: q_cn = 42.4 W/m (eq. (5a); quoted by pylinerating tests/test_ieee.py), three
        // digits. From the printed rho_f = 1.029: 42.42.
        let from_printed = natural_w_per_m(RHO_PRINTED, D, 60.0);
        assert!((from_printed - 42.4).abs() <= 0.05, "q_cn(printed rho_f) = {from_printed}");
        // Full precision 42.416; tolerance half a unit plus the rho_f rounding through rho^0.5 (0.010 W/m).
        let c = annex_b();
        let tol = 0.05 + 42.4 * 0.5 * 0.0005 / RHO_PRINTED;
        assert!((c.natural_w_per_m - 42.4).abs() <= tol, "q_cn = {}", c.natural_w_per_m);
        // The standard's choice: q_c = q_c1 > q_c2 > q_cn at 0.61 m/s.
        assert!(c.forced_low_wind_w_per_m > c.forced_high_wind_w_per_m);
        assert!(c.forced_high_wind_w_per_m > c.natural_w_per_m);
        assert_eq!(c.w_per_m(), c.forced_low_wind_w_per_m);
    }

    #[test]
    fn forced_correlations_cross_at_the_stated_reynolds_number() {
        // Bisection on 1.01 + 1.35 N^0.52 - 0.754 N^0.6 (positive below the crossing, negative above).
        let gap = |n: f64| forced_low_wind_w_per_m(1.0, n, 1.0, 1.0) - forced_high_wind_w_per_m(1.0, n, 1.0, 1.0);
        let (mut lo, mut hi) = (100.0, 1e5);
        assert!(gap(lo) > 0.0 && gap(hi) < 0.0);
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if gap(mid) > 0.0 { lo = mid } else { hi = mid }
        }
        // The module doc states 1757.25 (six digits): half a unit is 0.005.
        assert!((lo - 1757.25).abs() <= 0.005, "crossing at N_Re = {lo}");
        // The larger of the two is continuous there and switches from (3a) to (3b).
        let q = |n: f64| larger(forced_low_wind_w_per_m(1.0, n, 1.0, 1.0), forced_high_wind_w_per_m(1.0, n, 1.0, 1.0));
        assert!((q(lo * (1.0 + 1e-9)) - q(lo * (1.0 - 1e-9))).abs() < 1e-6);
        for n in [10.0, 100.0, 865.0, 1700.0] {
            assert!(gap(n) > 0.0, "eq. (3a) should be the larger at N_Re = {n}");
        }
        for n in [1800.0, 5000.0, 5e4, 5e5] {
            assert!(gap(n) < 0.0, "eq. (3b) should be the larger at N_Re = {n}");
        }
    }

    #[test]
    fn zero_wind_is_natural_convection() {
        let calm = Convection::new(D, 100.0 + C_TO_K, 40.0 + C_TO_K, 0.0, 0.0, 90.0);
        // At V_w = 0, eq. (3b) vanishes and eq. (3a) keeps only its conduction term 1.01 k_f (T_s - T_a) (1.8 W/m),
        // so the largest rate is natural convection, the same number as in the windy case (it has no wind in it).
        assert_eq!(calm.forced_high_wind_w_per_m, 0.0);
        assert!(calm.forced_low_wind_w_per_m > 0.0 && calm.forced_low_wind_w_per_m < calm.natural_w_per_m);
        assert_eq!(calm.w_per_m(), calm.natural_w_per_m);
        assert_eq!(calm.natural_w_per_m, annex_b().natural_w_per_m);
    }

    #[test]
    fn sign_follows_the_temperature_excess() {
        let ta = 30.0 + C_TO_K;
        assert_eq!(Convection::new(D, ta, ta, 0.0, 2.0, 90.0).w_per_m(), 0.0);
        let warm = Convection::new(D, ta + 5.0, ta, 0.0, 2.0, 45.0);
        let cold = Convection::new(D, ta - 5.0, ta, 0.0, 2.0, 45.0);
        assert!(warm.w_per_m() > 0.0 && cold.w_per_m() < 0.0);
        // Nearly antisymmetric (only the film temperature differs, by 5 K).
        assert!((warm.w_per_m() + cold.w_per_m()).abs() < 0.05 * warm.w_per_m());
        let calm_cold = Convection::new(D, ta - 5.0, ta, 0.0, 0.0, 45.0);
        assert!(calm_cold.natural_w_per_m < 0.0 && calm_cold.w_per_m() == calm_cold.natural_w_per_m);
    }
}
