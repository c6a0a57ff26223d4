//! Steady state of the heat balance: the conductor temperature for a current, and the ampacity (the current
//! for a temperature).
//!
//! ```text
//! N(T, I) = q_J(T, I) + q_S - q_c(T) - q_r(T) = 0        [W/m]
//! ```
//!
//! (IEEE Std 738-2012 eq. (1a); CIGRE TB 601 eq. (1)).
//!
//! * Temperature for a current: the root of `N(T, I)` in `T`. At the air temperature the cooling terms
//!   vanish and `N >= 0`, so `T >= T_a`; the upper end of the bracket is grown from `T_a + 10 K` by
//!   doubling the excess until `N < 0` (up to `T_a + 2000 K`; beyond that the conductor has no steady state
//!   at that current, a thermal runaway). The bracket is then narrowed by the Illinois variant of regula
//!   falsi ([`bracketed_root`]), which keeps the bracket (robust like bisection) and converges
//!   superlinearly; stopped when the bracket is below `1e-9 K` or `N` is zero.
//! * Ampacity for a maximum temperature `T_m`: closed form, since only `q_J` depends on the current:
//!   `I = sqrt((q_c(T_m) + q_r(T_m) - q_S) / R(T_m))` (IEEE 738 eq. (1b); TB 601 eq. (3)), with `R(T_m)`
//!   the resistance including the magnetic-core factor (`q_J(T_m, 1 A)`). If the sun alone keeps the
//!   conductor above `T_m` (`q_c + q_r <= q_S`) there is no ampacity: an error.

use super::{HeatBalance, HeatTerms};
use crate::exact::roots::illinois;
use std::convert::Infallible;

/// Why a steady-state computation failed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SteadyError {
    /// The net heating stays positive up to the bracket's limit: no steady state (thermal runaway).
    #[error(
        "no steady state for {current_a} A: the conductor still heats at {limit_k:.1} K ({} C), a thermal runaway",
        limit_k - 273.15
    )]
    NoSteadyState {
        /// the current [A]
        current_a: f64,
        /// the highest temperature tried [K]
        limit_k: f64,
    },
    /// The sun alone (no current) heats the conductor above the temperature asked for.
    #[error(
        "no ampacity for {temperature_k:.2} K ({} C): solar heating {solar_w_per_m:.3} W/m exceeds the cooling {cooling_w_per_m:.3} W/m there",
        temperature_k - 273.15
    )]
    SunAlone {
        /// the maximum temperature [K]
        temperature_k: f64,
        /// solar heating [W/m]
        solar_w_per_m: f64,
        /// convective plus radiative cooling at that temperature [W/m]
        cooling_w_per_m: f64,
    },
    /// A term is not finite (an input out of the correlations' range).
    #[error("the heat balance is not finite at {temperature_k} K")]
    NotFinite {
        /// the temperature [K]
        temperature_k: f64,
    },
}

/// A steady state of the heat balance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SteadyState {
    /// conductor temperature `T` [K]
    pub temperature_k: f64,
    /// current `I` [A]
    pub current_a: f64,
    /// the terms at `(T, I)` [W/m] (their net is zero up to the solver's tolerance)
    pub terms: HeatTerms,
    /// evaluations of the heat balance spent [-]
    pub evaluations: usize,
}

/// Highest temperature excess over the air searched for a steady state [K].
const MAX_EXCESS_K: f64 = 2000.0;
/// Width of the final bracket [K].
const BRACKET_TOL_K: f64 = 1e-9;

/// A root of `f` in `[lo, hi]` with `f(lo) >= 0 >= f(hi)` or the reverse (the Illinois variant of regula
/// falsi, [`illinois`], at most 400 evaluations). Returns the root (where `f` vanished, else the midpoint
/// of the last bracket) and the evaluations spent; stops when the bracket is narrower than `tol` or `f`
/// vanishes. `f_lo`, `f_hi` are `f` at the ends, already known to the caller.
pub fn bracketed_root(f: impl FnMut(f64) -> f64, lo: f64, hi: f64, f_lo: f64, f_hi: f64, tol: f64) -> (f64, usize) {
    debug_assert!(f_lo * f_hi <= 0.0, "not a bracket: f({lo}) = {f_lo}, f({hi}) = {f_hi}");
    let mut f = f;
    let end = illinois(|x| Ok::<f64, Infallible>(f(x)), lo, hi, f_lo, f_hi, tol, 400).unwrap_or_else(|e| match e {});
    (end.zero.unwrap_or(0.5 * (end.lo + end.hi)), end.evaluations)
}

/// The steady conductor temperature carrying `current_a` [A] (module doc).
pub fn temperature(model: &dyn HeatBalance, current_a: f64) -> Result<SteadyState, SteadyError> {
    let air = model.air_temperature_k();
    let net = |t: f64| model.terms(t, current_a).net_w_per_m();
    let mut evaluations = 1;
    let f_lo = net(air);
    if !f_lo.is_finite() {
        return Err(SteadyError::NotFinite { temperature_k: air });
    }
    if f_lo == 0.0 {
        return Ok(SteadyState { temperature_k: air, current_a, terms: model.terms(air, current_a), evaluations });
    }
    let mut excess = 10.0;
    // The lower end moves up to the last probe that still heats.
    let (mut lo, mut f_lo) = (air, f_lo);
    let (hi, f_hi) = loop {
        let t = air + excess;
        let f = net(t);
        evaluations += 1;
        if !f.is_finite() {
            return Err(SteadyError::NotFinite { temperature_k: t });
        }
        if f == 0.0 {
            return Ok(SteadyState { temperature_k: t, current_a, terms: model.terms(t, current_a), evaluations });
        }
        if f < 0.0 {
            break (t, f);
        }
        if excess >= MAX_EXCESS_K {
            return Err(SteadyError::NoSteadyState { current_a, limit_k: t });
        }
        (lo, f_lo) = (t, f);
        excess = (2.0 * excess).min(MAX_EXCESS_K);
    };
    let (t, n) = bracketed_root(net, lo, hi, f_lo, f_hi, BRACKET_TOL_K);
    evaluations += n;
    Ok(SteadyState { temperature_k: t, current_a, terms: model.terms(t, current_a), evaluations })
}

/// The steady-state ampacity for the maximum conductor temperature `max_temperature_k` [K] (module doc).
pub fn ampacity(model: &dyn HeatBalance, max_temperature_k: f64) -> Result<SteadyState, SteadyError> {
    let per_amp = model.terms(max_temperature_k, 1.0);
    let cooling = per_amp.convection_w_per_m + per_amp.radiation_w_per_m;
    let available = cooling - per_amp.solar_w_per_m;
    if !(available.is_finite() && per_amp.joule_w_per_m.is_finite()) {
        return Err(SteadyError::NotFinite { temperature_k: max_temperature_k });
    }
    if available <= 0.0 {
        return Err(SteadyError::SunAlone {
            temperature_k: max_temperature_k,
            solar_w_per_m: per_amp.solar_w_per_m,
            cooling_w_per_m: cooling,
        });
    }
    let current_a = (available / per_amp.joule_w_per_m).sqrt();
    Ok(SteadyState {
        temperature_k: max_temperature_k,
        current_a,
        terms: model.terms(max_temperature_k, current_a),
        evaluations: 2,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::thermal::ieee738::Ieee738;
    use crate::thermal::ieee738::annex_b::{drake, weather as annex_b_weather};

    #[test]
    fn ampacity_and_temperature_are_inverse() {
        // IEEE 738 Annex B: Drake at 100 C in its example weather; the ampacity's steady temperature is 100 C.
        let model = Ieee738 { conductor: drake(), weather: annex_b_weather() };
        let t_max = 273.15 + 100.0;
        let a = ampacity(&model, t_max).unwrap();
        let s = temperature(&model, a.current_a).unwrap();
        println!(
            "ampacity {:.3} A; its steady temperature {:.9} K ({} evaluations)",
            a.current_a, s.temperature_k, s.evaluations
        );
        // The bracket closes to 1e-9 K; the root of N is then known to that width.
        assert!((s.temperature_k - t_max).abs() < 1e-8);
        assert!(s.terms.net_w_per_m().abs() < 1e-6, "net {} W/m", s.terms.net_w_per_m());
        assert!(a.terms.net_w_per_m().abs() < 1e-9 * a.terms.joule_w_per_m);
        // The Illinois iteration converges superlinearly: far fewer evaluations than bisection (~40 from
        // a bracket of 100 K to 1e-9 K).
        assert!(s.evaluations < 30, "{} evaluations", s.evaluations);
    }

    #[test]
    fn no_current_no_sun_is_the_air_and_more_current_is_hotter() {
        let mut model = Ieee738 { conductor: drake(), weather: annex_b_weather() };
        model.weather.sun = None;
        let s = temperature(&model, 0.0).unwrap();
        assert_eq!(s.temperature_k, model.weather.air_temperature_k);
        let mut last = s.temperature_k;
        for i in [200.0, 500.0, 1000.0, 1500.0, 2000.0] {
            let t = temperature(&model, i).unwrap().temperature_k;
            assert!(t > last, "{i} A: {t} K");
            last = t;
        }
    }

    #[test]
    fn errors_name_the_cause() {
        let mut model = Ieee738 { conductor: drake(), weather: annex_b_weather() };
        // A thermal runaway: 20 kA in still air.
        model.weather.wind_speed_m_per_s = 0.0;
        let e = temperature(&model, 2.0e4).unwrap_err();
        assert!(matches!(e, SteadyError::NoSteadyState { .. }), "{e}");
        // The sun alone: a maximum temperature below the air's.
        let e = ampacity(&model, model.weather.air_temperature_k - 1.0).unwrap_err();
        assert!(matches!(e, SteadyError::SunAlone { .. }) && e.to_string().contains("solar heating"), "{e}");
    }

    #[test]
    fn illinois_finds_a_cubic_root() {
        let (x, n) = bracketed_root(|x| 2.0 - x * x * x, 0.0, 2.0, 2.0, -6.0, 1e-12);
        assert!((x - 2f64.cbrt()).abs() < 1e-12 && n < 40, "{x} in {n}");
    }
}
