//! Warnings: values that are valid (inside the documented ranges that [`super::validate`] enforces) but
//! physically implausible or numerically risky. A warning never stops a run; the `ohl` binary prints each
//! one on stderr before the run and `summary.json` lists them under `warnings`, so a result computed from
//! a doubtful input carries the doubt with it.
//!
//! The checks, each with the reason it gives:
//! - no damping at all with the tension-only law (`numerics.smoothing = 0`, `eta_n_s = 0`,
//!   `mass_damping_per_s = 0`): the leapfrog scheme is energy-stable for a smooth force, but a segment that
//!   goes slack and snaps taut again crosses the kink of `T = max(EA e, 0)` within a step, and the scheme
//!   gains energy there. Measured on the weight release of a 160 m span (EA = 792 kN, 1 kg/m, N = 50): it
//!   goes unstable after 36 s at Courant 0.9 and after 216 s at Courant 0.5, and a slack start
//!   (S = 170 m) after 4 s and 81 s. With the default smoothing `b = 0.02` (paper (3.3)) 48 such
//!   configurations (N = 50 and 200, EA = 0.79 and 30 MN, S/l = 1, 1.03, 1.25, with and without a 30 m/s
//!   wind, Courant 0.9 and 1) all ran 600 s (docs/architecture.md, "stable defaults").
//! - wind faster than 70 m/s (above design wind speeds: IEC 60826 reference winds stay below about 50 m/s
//!   at 10 m);
//! - air density outside [0.9, 1.5] kg/m^3 (ISA: 0.91 at 3000 m altitude; 1.5 in air at -50 C);
//! - a conductor temperature (reference, event or hold) below 223.15 K (-50 C) or above 523.15 K (250 C,
//!   above the rated maximum of high-temperature conductors, 210 C for ZTACIR);
//! - a sky descriptor of `[thermal.weather.sun]` the chosen standard does not read
//!   ([`super::thermal::unused_weather_inputs`]).
//!
//! One more is not about a doubtful value but about the run's cost and its damping: a section's clamp or
//! elastic crossarm whose stable step is below the conductor's Courant step sets the time step
//! ([`step_limit`]; module doc of [`super::section`]). The run then takes more steps, and the smoothing,
//! applied per step, damps more per second.

use std::fmt;

use super::events::EventSpec;
use super::schema::{Scenario, TensionLawSpec};
use super::section::StepLimit;
use super::validate::number;

/// A valid but doubtful value.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Warning {
    /// dotted path of the field, e.g. `loads.wind.speed_m_per_s`
    pub field: String,
    /// the value found
    pub value: String,
    /// why it is doubtful, and what is usual
    pub reason: String,
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "field `{}` = {}: {}", self.field, self.value, self.reason)
    }
}

/// Wind speed above which a warning is given [m/s].
pub const PLAUSIBLE_WIND_M_PER_S: f64 = 70.0;

/// Plausible air density [kg/m^3]: 0.9 (3000 m altitude) to 1.5 (-50 C).
pub const PLAUSIBLE_AIR_DENSITY_KG_PER_M3: [f64; 2] = [0.9, 1.5];

/// Plausible conductor temperature [K]: -50 C to 250 C.
pub const PLAUSIBLE_TEMPERATURE_K: [f64; 2] = [223.15, 523.15];

/// The warnings of a scenario that passed validation.
pub fn warnings(s: &Scenario) -> Vec<Warning> {
    let mut w = Vec::new();
    let mut warn = |field: &str, x: f64, reason: &str| {
        w.push(Warning { field: field.into(), value: number(x), reason: reason.into() })
    };
    let n = &s.numerics;
    if matches!(s.conductor.tension_law, TensionLawSpec::TensionOnly | TensionLawSpec::TwoMaterial)
        && n.smoothing == 0.0
        && n.eta_n_s == 0.0
        && n.mass_damping_per_s == 0.0
    {
        warn(
            "numerics.smoothing",
            n.smoothing,
            "no damping at all (smoothing, eta_n_s and mass_damping_per_s are 0) with the tension-only law: \
             slack segments snapping taut make the explicit scheme gain energy, and long runs can go unstable \
             (a 160 m weight release did after 36 s at Courant 0.9); the default smoothing 0.02 (paper 3.3) or \
             internal friction keeps it stable",
        );
    }
    if let Some(wind) = &s.loads.wind {
        if wind.speed_m_per_s > PLAUSIBLE_WIND_M_PER_S {
            warn(
                "loads.wind.speed_m_per_s",
                wind.speed_m_per_s,
                "above 70 m/s, faster than design winds (reference winds of IEC 60826 are below about 50 m/s)",
            );
        }
        let [lo, hi] = PLAUSIBLE_AIR_DENSITY_KG_PER_M3;
        if !(lo..=hi).contains(&wind.air_density_kg_per_m3) {
            warn(
                "loads.wind.air_density_kg_per_m3",
                wind.air_density_kg_per_m3,
                "outside [0.9, 1.5] kg/m^3, the density of air between 3000 m altitude and -50 C (sea level: 1.225)",
            );
        }
    }
    let mut temperature = |field: &str, t_k: f64| {
        let [lo, hi] = PLAUSIBLE_TEMPERATURE_K;
        if !(lo..=hi).contains(&t_k) {
            warn(
                field,
                t_k,
                "outside [223.15, 523.15] K (-50 C to 250 C): colder than any service condition or hotter than \
                 the rated maximum of high-temperature conductors (210 C); temperatures are in kelvin",
            );
        }
    };
    if s.conductor.thermal_expansion_per_k > 0.0 {
        temperature("conductor.reference_temperature_k", s.conductor.reference_temperature_k);
    }
    for (k, e) in s.events.iter().enumerate() {
        match e {
            EventSpec::Temperature { temperature_k, .. } => {
                temperature(&format!("events[{k}].temperature_k"), *temperature_k)
            }
            EventSpec::HeatConduction { hold_temperature_k, .. } => {
                temperature(&format!("events[{k}].hold_temperature_k"), *hold_temperature_k)
            }
            _ => {}
        }
    }
    if let Some(t) = &s.thermal {
        w.extend(super::thermal::unused_weather_inputs("thermal.weather", &t.weather, t.standard));
    }
    w
}

/// The warning that the section element `limit` ([`StepLimit`]), not the conductor, sets the time step
/// `dt_s` [s] (its stable step times the Courant number `courant`), below the conductor's Courant step
/// `conductor_step_s` [s]; `None` where the conductor's step is the run's. `smoothing` is the smoothing per
/// step `b`.
pub(crate) fn step_limit(
    limit: &StepLimit,
    courant: f64,
    conductor_step_s: f64,
    dt_s: f64,
    smoothing: f64,
) -> Option<Warning> {
    if dt_s >= conductor_step_s {
        return None;
    }
    let ratio = conductor_step_s / dt_s;
    let damping = if smoothing > 0.0 {
        format!(
            "; the smoothing b = {} acts per step, so it damps {ratio:.2} times as much per second",
            number(smoothing)
        )
    } else {
        String::new()
    };
    Some(Warning {
        field: limit.field.clone(),
        value: limit.value.clone(),
        reason: format!(
            "sets the time step: {} is stable below {:.4e} s (Gershgorin's bound, docs/scenario.md), so at \
             numerics.courant = {} the run steps at {dt_s:.4e} s instead of the conductor's {conductor_step_s:.4e} \
             s, {ratio:.2} times as many steps{damping}",
            limit.what,
            limit.step_s,
            number(courant)
        ),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const BASE: &str = "[conductor]\naxial_stiffness_n = 792000.0\nlinear_density_kg_per_m = 1.0\n\
        [geometry]\nleft_support_m = [0.0, 0.0, 0.0]\nright_support_m = [0.0, 160.0, 0.0]\nsegments = 20\n\
        [duration]\nend_time_s = 0.5\n";

    fn fields(extra: &str) -> Vec<String> {
        let s: Scenario = toml::from_str(&format!("{BASE}{extra}")).unwrap();
        warnings(&s).into_iter().map(|w| w.field).collect::<Vec<_>>()
    }

    #[test]
    fn defaults_give_no_warning() {
        assert!(fields("").is_empty());
    }

    #[test]
    fn each_doubtful_value_is_named() {
        assert_eq!(fields("[numerics]\nsmoothing = 0.0\n"), ["numerics.smoothing"]);
        // Any damping, or the linear law, silences the damping warning.
        assert!(fields("[numerics]\nsmoothing = 0.0\neta_n_s = 100.0\ncourant = 0.5\n").is_empty());
        assert!(fields("[numerics]\nsmoothing = 0.0\nmass_damping_per_s = 0.1\n").is_empty());
        assert_eq!(
            fields("[loads.wind]\nlaw = \"aerodynamic\"\nspeed_m_per_s = 80.0\nair_density_kg_per_m3 = 0.5\n"),
            ["loads.wind.speed_m_per_s", "loads.wind.air_density_kg_per_m3"]
        );
        assert_eq!(
            fields("[[events]]\ntime_s = 1.0\naction = \"temperature\"\ntemperature_k = 90.0\nrange = [0.0, 1.0]\n"),
            ["events[0].temperature_k"]
        );
        // A sky descriptor the chosen standard does not read (the table parses; validation is not run here).
        let thermal = |standard: &str, sky: &str| {
            format!(
                "[thermal]\nstandard = \"{standard}\"\nconductor = \"ACSR Drake\"\ncurrent_a = [[0.0, 500.0]]\n\
                 [thermal.weather]\nair_temperature_k = 293.15\nwind_speed_m_per_s = 1.0\n[thermal.weather.sun]\n\
                 latitude_deg = 45.0\nday_of_year = 172\nsolar_hour = 12.0\nline_azimuth_deg = 90.0\n{sky}"
            )
        };
        assert_eq!(fields(&thermal("ieee738", "albedo = 0.2\n")), ["thermal.weather.sun.albedo"]);
        assert_eq!(fields(&thermal("cigre601", "atmosphere = \"industrial\"\n")), ["thermal.weather.sun.atmosphere"]);
        assert!(fields(&thermal("cigre601", "albedo = 0.2\nclearness_ratio = 0.8\n")).is_empty());
        assert!(fields(&thermal("ieee738", "atmosphere = \"industrial\"\n")).is_empty());
    }
}
