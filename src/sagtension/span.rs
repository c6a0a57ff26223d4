//! The span of a sag-tension problem: one span, or the ruling span of a tension section.
//!
//! A section of level suspension spans `l_i` strung at one horizontal tension, whose suspension strings
//! swing freely enough to equalise the horizontal tension between spans, behaves under a change of
//! temperature or load like a single level span of the ruling (equivalent) length
//!
//! ```text
//! l_r = sqrt( sum l_i^3 / sum l_i )
//! ```
//!
//! (the parabolic approximation of the section's total slack; Winkelman 1959; Douglass and Thrash,
//! Electric Power Engineering Handbook ch. 14, "ruling span"). Assumptions: level spans, equal
//! horizontal tension, the strings' own stiffness neglected. A span's sag then follows from the ruling
//! span's `H` with its own length ([`super::Strung::section_span`]). The exact whole-section solve with swinging strings is the static
//! solver's ([`crate::statics`]).

use super::SagTensionError;

/// A span: supports `length_m` apart horizontally, B `rise_m` above A.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Span {
    /// horizontal distance between the supports `l` [m], > 0
    pub length_m: f64,
    /// height of support B above support A `h` [m] (0: level)
    pub rise_m: f64,
}

impl Span {
    /// A level span of `length_m` [m].
    pub fn level(length_m: f64) -> Span {
        Span { length_m, rise_m: 0.0 }
    }

    /// The level ruling span of a section of level spans `lengths_m` [m] (module doc).
    pub fn ruling(lengths_m: &[f64]) -> Result<Span, SagTensionError> {
        if lengths_m.is_empty() {
            return Err(SagTensionError::Invalid { what: "number of spans", value: 0.0, allowed: ">= 1" });
        }
        for &l in lengths_m {
            if !(l.is_finite() && l > 0.0) {
                return Err(SagTensionError::Invalid { what: "span length [m]", value: l, allowed: "finite and > 0" });
            }
        }
        let cubes: f64 = lengths_m.iter().map(|l| l * l * l).sum();
        let sum: f64 = lengths_m.iter().sum();
        Ok(Span::level((cubes / sum).sqrt()))
    }

    /// The checks: length finite and > 0, rise finite.
    pub fn validate(&self) -> Result<(), SagTensionError> {
        if !(self.length_m.is_finite() && self.length_m > 0.0) {
            return Err(SagTensionError::Invalid {
                what: "span length [m]",
                value: self.length_m,
                allowed: "finite and > 0",
            });
        }
        if !self.rise_m.is_finite() {
            return Err(SagTensionError::Invalid { what: "span rise [m]", value: self.rise_m, allowed: "finite" });
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ruling_span_of_equal_spans_is_the_span_and_weighs_long_spans() {
        // Equal spans: l_r = l exactly (sum l^3 / sum l = l^2).
        assert_eq!(Span::ruling(&[300.0; 4]).unwrap().length_m, 300.0);
        // 200, 400: sqrt((8e6 + 64e6) / 600) = sqrt(120000) = 346.41..., by hand.
        let r = Span::ruling(&[200.0, 400.0]).unwrap().length_m;
        assert!((r - 120_000f64.sqrt()).abs() < 1e-12 * r);
        assert!(Span::ruling(&[]).is_err() && Span::ruling(&[100.0, -1.0]).is_err());
    }
}
