//! Stringing one span: the unstressed length `L0` [m] (at the law's reference temperature, conductor
//! strain 0) for which the span, with a given history, temperature and load, has a given horizontal
//! tension or mid-span sag. `H` falls and the sag grows with `L0`, so each is a root in `L0`, bracketed by
//! widening from the chord and found by the Illinois method ([`super::search::illinois`]) to 1e-14 of the
//! chord, the root [`super::Problem::string`] uses for a sag-tension table. The scenario strings a
//! two-material section's spans with [`unstressed_length_m`] (any history: virgin on the initial or the
//! creep curve).

use super::SagTensionError;
use super::catenary::SpanLaw;
use super::problem::{StringingTarget, root_on_length};

/// The unstressed length [m] of the span `span` (its `unstressed_length_m` is ignored) that has the
/// horizontal tension or the mid-span sag `target` (module doc).
pub fn unstressed_length_m(span: &SpanLaw<'_>, target: StringingTarget) -> Result<f64, SagTensionError> {
    let (value, sign) = match target {
        StringingTarget::HorizontalTension(h) => (h, -1.0),
        StringingTarget::Sag(f) => (f, 1.0),
    };
    let f = |l0: f64| {
        let s = SpanLaw { unstressed_length_m: l0, ..*span };
        let sol = s.solve()?;
        let v = match target {
            StringingTarget::HorizontalTension(_) => sol.horizontal_tension_n,
            StringingTarget::Sag(_) => s.sag_at_x(0.5 * s.span_m, sol.hv())?,
        };
        Ok(sign * (v - value) / value)
    };
    root_on_length(span.span_m.hypot(span.rise_m), f, "stringing condition")
}
