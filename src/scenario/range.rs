//! The allowed range of a numeric field, stated once: the validator checks a value against it
//! ([`super::validate::Check::range`]) and the message says what is allowed by writing it ([`Range`]'s
//! `Display`), so the check and its text cannot drift apart. `tests/scenario_reference.rs` checks the same
//! ranges against the *Allowed* column of `docs/scenario.md`, `tests/line_reference.rs` against
//! `docs/line.md`.
//!
//! A range is an interval `lo <= x <= hi` with either end open (`lo < x`, `x < hi`); a value must also be
//! finite. An open lower end at 0 also refuses the subnormal numbers (below `f64::MIN_POSITIVE` =
//! 2.2e-308): a time, step or tension that small is no physical value, and the ratios formed from it
//! overflow (this is how the validators compared before the ranges were values). A number only bounded
//! below stays [`super::validate::Check::positive`] (`must be a finite number > 0`).
//!
//! The text, as the messages have always written it:
//!
//! - `must be in [0.01, 20] m`, `must be in (0, 1e3] m`, `must be in (0, 1)` (the default form),
//! - `must be a finite number > 0, in [1e-3, 1e3] kg/m` ([`Range::finite`]),
//! - `must be a finite number >= 0, at most 1e4 N/m` ([`Range::at_most`]),
//!
//! followed by an optional note (`" (section 4.1: 3.805 N/m)"`, [`Range::note`]). The ends are written by
//! [`bound`]: a power of ten from 1e3 up or 1e-3 down as `1e3`, `1e-3`, anything else as
//! [`super::validate::number`] writes it (`0.01`, `20`, `5000`, `173.15`).

use std::fmt;

use super::temperature::ZERO_CELSIUS_K;
use super::validate::{MIN_REFERENCE_TEMPERATURE_K, number};

/// How the text of a [`Range`] begins.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Form {
    /// `<words> [lo, hi] unit`; the words are `must be in` unless stated otherwise.
    Interval(&'static str),
    /// `must be a finite number > 0, in [lo, hi] unit` (a range above 0).
    FiniteInterval,
    /// `must be a finite number >= lo, at most hi unit` (`> lo` for an open lower end).
    AtMost,
}

/// An allowed range of a number, with its unit and an optional note.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Range {
    /// lower end
    pub lo: f64,
    /// upper end
    pub hi: f64,
    /// `lo` itself is excluded
    pub lo_open: bool,
    /// `hi` itself is excluded
    pub hi_open: bool,
    /// unit as the reference writes it (`m`, `N s`, `kg/m^3`); empty for a pure number
    pub unit: &'static str,
    /// written after the range and unit, with its own separator (`" (aluminium: 23.8e-6)"`, `": ..."`)
    pub note: &'static str,
    /// how the text begins
    pub form: Form,
}

impl Range {
    const fn new(lo: f64, hi: f64, lo_open: bool, hi_open: bool, unit: &'static str) -> Self {
        Range { lo, hi, lo_open, hi_open, unit, note: "", form: Form::Interval("must be in") }
    }
    /// `[lo, hi]`.
    pub const fn closed(lo: f64, hi: f64, unit: &'static str) -> Self {
        Self::new(lo, hi, false, false, unit)
    }
    /// `(lo, hi]`.
    pub const fn open_closed(lo: f64, hi: f64, unit: &'static str) -> Self {
        Self::new(lo, hi, true, false, unit)
    }
    /// `(lo, hi)`.
    pub const fn open(lo: f64, hi: f64, unit: &'static str) -> Self {
        Self::new(lo, hi, true, true, unit)
    }
    /// The same range with a note after it.
    pub const fn note(self, note: &'static str) -> Self {
        Range { note, ..self }
    }
    /// The same range written `must be a finite number > 0, in [lo, hi] unit`.
    pub const fn finite(self) -> Self {
        Range { form: Form::FiniteInterval, ..self }
    }
    /// The same range written `must be a finite number >= lo, at most hi unit`.
    pub const fn at_most(self) -> Self {
        Range { form: Form::AtMost, ..self }
    }
    /// The same range written `<words> [lo, hi] unit` (e.g. `current must be in`).
    pub const fn words(self, words: &'static str) -> Self {
        Range { form: Form::Interval(words), ..self }
    }
    /// The same range of a temperature in kelvin written in degrees Celsius: the ends less
    /// [`ZERO_CELSIUS_K`] (rounded to 1e-9 C, so that 173.15 K is -100 C and not -100.00000000000003), the
    /// unit `C`, no note (the notes of the kelvin ranges are about kelvin); any other range as it is.
    pub fn celsius(self) -> Self {
        if !self.unit.eq("K") {
            return self;
        }
        let c = |k: f64| ((k - ZERO_CELSIUS_K) * 1e9).round() / 1e9;
        Range { lo: c(self.lo), hi: c(self.hi), unit: "C", note: "", ..self }
    }
    /// Whether `x` is allowed: finite and within the ends (see the module doc for an open end at 0).
    pub fn contains(&self, x: f64) -> bool {
        let lo_ok = if self.lo_open { x > self.lo && (self.lo != 0.0 || x >= f64::MIN_POSITIVE) } else { x >= self.lo };
        let hi_ok = if self.hi_open { x < self.hi } else { x <= self.hi };
        x.is_finite() && lo_ok && hi_ok
    }
    /// The interval in brackets: `[0.01, 20]`, `(0, 1e3]`.
    pub fn brackets(&self) -> String {
        format!(
            "{}{}, {}{}",
            if self.lo_open { '(' } else { '[' },
            bound(self.lo),
            bound(self.hi),
            if self.hi_open { ')' } else { ']' }
        )
    }
}

/// An end of a range as the messages write it: `1e3`, `1e-7`, `-1e3` for a power of ten at least 1e3 or at
/// most 1e-3 in magnitude, else as [`number`] writes it (`0.01`, `20`, `5000`, `0.25`).
pub fn bound(x: f64) -> String {
    let k = x.abs().log10().round();
    if x != 0.0 && x.is_finite() && k.abs() >= 3.0 && x.abs() == format!("1e{k}").parse::<f64>().unwrap_or(f64::NAN) {
        format!("{}1e{k}", if x < 0.0 { "-" } else { "" })
    } else {
        number(x)
    }
}

impl fmt::Display for Range {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let sign = if self.lo_open { ">" } else { ">=" };
        match self.form {
            Form::Interval(words) => write!(f, "{words} {}", self.brackets())?,
            Form::FiniteInterval => write!(f, "must be a finite number > 0, in {}", self.brackets())?,
            Form::AtMost => write!(f, "must be a finite number {sign} {}, at most {}", bound(self.lo), bound(self.hi))?,
        }
        if !self.unit.is_empty() {
            write!(f, " {}", self.unit)?;
        }
        f.write_str(self.note)
    }
}

// Ranges used in more than one place.

/// Linear density of a conductor [kg/m]: bare conductors weigh 0.1 to 5 kg/m, heavily iced ones up to about
/// 30 kg/m; the bounds leave two decades either side. `[conductor]`, `[[section.spans]]`, catalogue entries.
pub const LINEAR_DENSITY_KG_PER_M: Range = Range::closed(1.0e-3, 1.0e3, "kg/m");

/// Axial stiffness `EA` of a conductor [N]: the paper's section 4 uses 7.9e5 N; conductors are 1e6 to 1e9 N.
/// `[conductor]`, `[[section.spans]]`, catalogue entries.
pub const AXIAL_STIFFNESS_N: Range = Range::closed(1.0, 1.0e10, "N");

/// Rated tensile strength of a conductor [N] (ACSR Drake: about 140 kN).
pub const RATED_TENSILE_STRENGTH_N: Range = Range::open_closed(0.0, 1.0e7, "N").note(" (ACSR Drake: about 140 kN)");

/// Linear thermal expansion coefficient [1/K] (aluminium 23.8e-6, the paper's section 5.4).
pub const THERMAL_EXPANSION_PER_K: Range = Range::closed(0.0, 1.0e-3, "1/K");

/// Unstretched length of an insulator string [m]: suspension and strain strings are about 1 to 10 m long.
/// `[section]` suspension supports and a `[line]`'s tension strings.
pub const INSULATOR_LENGTH_M: Range = Range::closed(0.01, 20.0, "m");

/// Mass of an insulator string [kg] (suspension and tension strings).
pub const INSULATOR_MASS_KG: Range = Range::closed(0.0, 5000.0, "kg");

/// Axial stiffness of an insulator string [N]: strings are about 1e7 to 1e8 N.
pub const INSULATOR_STIFFNESS_N: Range = Range::closed(1.0e4, 1.0e10, "N");

/// Axial damping of an insulator string [N s]: 1e4 N s damps a string's ringing in a few periods.
/// `[section]` suspension supports, `[line]`'s `string_damping_n_s` and tension strings.
pub const INSULATOR_DAMPING_N_S: Range = Range::closed(0.0, 1.0e7, "N s");

/// A conductor temperature of the heat balance [K]: the initial temperature of a transient and the low
/// reference temperature of a resistance (-73 to 227 C).
pub const CONDUCTOR_TEMPERATURE_K: Range = Range::closed(200.0, 500.0, "K");

/// The longest RK4 step of a heat-balance transient [s] (`[thermal]`, a thermal case's `[transient]` and
/// `[deicing]`).
pub const HEAT_STEP_S: Range = Range::closed(1.0e-3, 600.0, "s");

/// Radial thickness of an ice shell [m] (0.1 mm to 10 cm).
pub const ICE_THICKNESS_M: Range = Range::closed(1.0e-4, 0.1, "m");

/// Radial ice thickness of an `ice` event [m]: 0 (shed) to 0.2 m, four times the thickest design glaze of
/// the codes (about 50 mm) and the size of the largest rime and wet-snow sleeves; thicker deposits are no
/// longer concentric shells.
pub const RADIAL_ICE_M: Range = Range::closed(0.0, 0.2, "m");

/// Ice density [kg/m^3]: rime about 100 to 600, glaze 900 (pure ice 917).
pub const ICE_DENSITY_KG_PER_M3: Range = Range::closed(100.0, 1000.0, "kg/m^3");

/// A conductor current [A]: the largest overhead conductors carry a few kA.
pub const CURRENT_A: Range = Range::closed(0.0, 1.0e5, "A");

/// A temperature of a temperature or heat-conduction event [K].
pub const EVENT_TEMPERATURE_K: Range = Range::open_closed(0.0, 5000.0, "K");

/// The temperature at which a conductor is stress-free at its unstretched length `u_ref` [K]
/// (`conductor.reference_temperature_k`), from [`MIN_REFERENCE_TEMPERATURE_K`] (-100 C).
pub const REFERENCE_TEMPERATURE_K: Range = Range::closed(MIN_REFERENCE_TEMPERATURE_K, 5000.0, "K").note(
    ": a temperature in kelvin, not Celsius (15 C is 288.15 K); the floor -100 C is below the coldest air measured \
     on Earth (-89.2 C)",
);

/// The stringing temperature of a section [K] (`section.stringing_temperature_k`): -50 to 100 C.
pub const STRINGING_TEMPERATURE_K: Range = Range::closed(223.15, 373.15, "K");

/// The low reference temperature of a conductor's resistance [K] (a `[thermal.conductor]` table).
pub const RESISTANCE_TEMPERATURE_K: Range = CONDUCTOR_TEMPERATURE_K.note(" (kelvin, not Celsius)");

/// The ambient air temperature of a weather [K] (`weather.air_temperature_k`).
pub const AIR_TEMPERATURE_K: Range = Range::closed(200.0, 350.0, "K").note(" (-73 to 77 C)");

/// The conductor's maximum temperature of a rating [K] (`rating.max_temperature_k`): 0 to 327 C.
pub const RATING_TEMPERATURE_K: Range = Range::closed(273.15, 600.0, "K");

/// A maximum conductor temperature of a thermal case's ampacities [K] (`max_temperature_k`).
pub const AMPACITY_TEMPERATURE_K: Range = Range::closed(250.0, 600.0, "K");

/// The temperature limit of a thermal case's transient [K] (`transient.limit_k`).
pub const TRANSIENT_LIMIT_K: Range = Range::closed(200.0, 600.0, "K");

/// Every range of a temperature field, in kelvin: a problem stated with one of these about a field written
/// in degrees Celsius is shown in Celsius ([`super::temperature::Celsius::as_written`]).
pub const TEMPERATURE_RANGES: &[Range] = &[
    REFERENCE_TEMPERATURE_K,
    STRINGING_TEMPERATURE_K,
    EVENT_TEMPERATURE_K,
    CONDUCTOR_TEMPERATURE_K,
    RESISTANCE_TEMPERATURE_K,
    AIR_TEMPERATURE_K,
    RATING_TEMPERATURE_K,
    AMPACITY_TEMPERATURE_K,
    TRANSIENT_LIMIT_K,
    SAG_TEMPERATURE_K,
];

/// Conductor temperature of a sag-tension condition [K]: -100 C (the lowest stringing temperature of the
/// scenarios, [`super::validate::MIN_REFERENCE_TEMPERATURE_K`]) to 300 C (above the 250 C emergency limit of
/// high-temperature conductors such as ACSS).
pub const SAG_TEMPERATURE_K: Range = Range::closed(173.15, 573.15, "K");

/// Specific heat of a conductor's layer at 20 C [J/(kg K)] (aluminium 897, steel 481).
pub const SPECIFIC_HEAT_J_PER_KG_K: Range =
    Range::closed(100.0, 5000.0, "J/(kg K)").note(" (aluminium 897, steel 481)");

/// Temperature coefficient of a specific heat [1/K] (TB 601 section 4.3: aluminium 3.8e-4, steel 1.0e-4).
pub const SPECIFIC_HEAT_COEFFICIENT_PER_K: Range =
    Range::closed(0.0, 1.0e-3, "1/K").note(" (TB 601 section 4.3: aluminium 3.8e-4, steel 1.0e-4)");

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_text_is_the_messages_text() {
        assert_eq!(INSULATOR_LENGTH_M.to_string(), "must be in [0.01, 20] m");
        assert_eq!(Range::open_closed(0.0, 1.0e3, "m").to_string(), "must be in (0, 1e3] m");
        assert_eq!(Range::open(0.0, 1.0, "").to_string(), "must be in (0, 1)");
        assert_eq!(
            LINEAR_DENSITY_KG_PER_M.finite().note(" (x)").to_string(),
            "must be a finite number > 0, in [1e-3, 1e3] kg/m (x)"
        );
        assert_eq!(
            Range::closed(0.0, 1.0e4, "N/m").at_most().to_string(),
            "must be a finite number >= 0, at most 1e4 N/m"
        );
        assert_eq!(CURRENT_A.words("current must be in").to_string(), "current must be in [0, 1e5] A");
        assert_eq!(Range::closed(-1.0e3, 5000.0, "").to_string(), "must be in [-1e3, 5000]");
        assert_eq!(Range::closed(1.0e-7, 173.15, "").to_string(), "must be in [1e-7, 173.15]");
        assert_eq!(Range::closed(0.01, 0.25, "").to_string(), "must be in [0.01, 0.25]");
    }

    #[test]
    fn a_kelvin_range_in_celsius() {
        assert_eq!(REFERENCE_TEMPERATURE_K.celsius().to_string(), "must be in [-100, 4726.85] C");
        assert_eq!(EVENT_TEMPERATURE_K.celsius().to_string(), "must be in (-273.15, 4726.85] C");
        assert_eq!(AIR_TEMPERATURE_K.celsius().to_string(), "must be in [-73.15, 76.85] C");
        assert_eq!(CURRENT_A.celsius(), CURRENT_A);
    }

    #[test]
    fn the_ends_are_honoured() {
        let r = Range::open_closed(0.0, 1.0, "");
        assert!(!r.contains(0.0) && !r.contains(1.0e-310) && r.contains(f64::MIN_POSITIVE) && r.contains(1.0));
        assert!(!r.contains(1.0 + f64::EPSILON) && !r.contains(f64::NAN));
        let r = Range::open(0.0, 1.0, "");
        assert!(!r.contains(1.0) && r.contains(1.0 - f64::EPSILON / 2.0));
        let r = Range::closed(-1.0, 1.0, "");
        assert!(r.contains(-1.0) && r.contains(1.0) && !r.contains(f64::INFINITY) && !r.contains(-1.0 - 1e-15));
    }
}
