//! Exact static reference solutions the dynamic solver is verified against.
//!
//! The sub-modules solve, to near machine precision, the classical static
//! problems that a damped dynamic run of the wire must settle onto:
//!
//! * [`catenary`]: the elastic catenary of Irvine ("Cable Structures", MIT
//!   Press 1981, section 2.3), a cable of unstretched length `L0`, axial
//!   stiffness `EA` and a uniform load per unit *unstretched* length, hung
//!   between two arbitrary points in 3D. Unknowns: the horizontal tension
//!   `H` and the support reaction `V`, found from the two closure equations
//!   `x(L0) = l`, `eta(L0) = h` by a 2D Newton iteration with an analytic
//!   Jacobian.
//! * [`arc`]: an elastic string under a uniform pressure per unit *deformed*
//!   length acting normal to it (no gravity): a circular arc of constant
//!   tension `T = p R`. One unknown, the half-angle `phi`, from
//!   `c phi - L0 sin(phi) = p L0 c / (2 EA)`. The module also holds the
//!   approximate closed forms of the paper, (4.1) for the arc and
//!   (4.3)-(4.4) for the parabolic elastic sag, so that the solver's output
//!   can be compared with both.
//! * [`em_filaments`]: closed-form forces between straight current filaments
//!   (parallel with any offset, perpendicular), the references of the
//!   electromagnetic pair element [`crate::element::em_force`].
//! * [`roots`]: the small safeguarded root finders used by both (1D Newton
//!   with bisection fallback, 2D damped Newton with line search).
//!
//! Coordinates follow the rest of the crate: `x1` horizontal across the line
//! (the wind direction), `x2` along the span, `x3` vertical up; gravity acts
//! along `-x3`. All quantities are SI: metres, newtons, radians.
//!
//! Bad physical input (non-finite numbers, non-positive lengths or
//! stiffnesses, a chord parallel to the load, a load for which no
//! equilibrium exists) is reported as an [`ExactError`], never a panic.

// Doc comments name units in brackets, `[N]`, `[m]`, `[N/m]`, which rustdoc
// would otherwise try to resolve as intra-doc links.
#![allow(rustdoc::broken_intra_doc_links)]

pub mod arc;
pub mod catenary;
pub mod em_filaments;
pub mod heat;
pub mod modes;
pub mod roots;

pub use arc::{ElasticArc, paper_arc_deflection_m, paper_arc_half_angle_rad};
pub use catenary::{ElasticCatenary, paper_parabolic_gamma, paper_parabolic_sag_m, paper_parabolic_strain};

/// Errors of the exact reference solutions.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ExactError {
    /// An input is non-finite, out of its physical range, or degenerate.
    #[error("invalid input: {what} (got {value})")]
    InvalidInput {
        /// What is wrong, in words.
        what: &'static str,
        /// The offending value (NaN where it is not a single number).
        value: f64,
    },
    /// The inputs are valid but admit no static equilibrium of the model.
    #[error("no equilibrium exists: {0}")]
    NoEquilibrium(&'static str),
    /// A root finder was handed an interval whose end values do not differ in sign.
    #[error("root not bracketed: f({lo}) = {f_lo}, f({hi}) = {f_hi}")]
    NotBracketed {
        /// Lower end of the interval.
        lo: f64,
        /// Upper end of the interval.
        hi: f64,
        /// Function value at `lo`.
        f_lo: f64,
        /// Function value at `hi`.
        f_hi: f64,
    },
    /// An iteration stopped before reaching its tolerance.
    #[error("{method} did not converge in {iterations} iterations (residual {residual:e})")]
    NoConvergence {
        /// Which iteration failed.
        method: &'static str,
        /// Iterations spent.
        iterations: usize,
        /// Best residual reached (in the method's own scaled measure).
        residual: f64,
    },
}

/// Checks that `value` is finite and strictly positive.
pub(crate) fn require_positive(value: f64, what: &'static str) -> Result<f64, ExactError> {
    if value.is_finite() && value > 0.0 { Ok(value) } else { Err(ExactError::InvalidInput { what, value }) }
}

/// Checks that every component of `v` is finite.
pub(crate) fn require_finite3(v: [f64; 3], what: &'static str) -> Result<[f64; 3], ExactError> {
    match v.iter().find(|c| !c.is_finite()) {
        None => Ok(v),
        Some(&value) => Err(ExactError::InvalidInput { what, value }),
    }
}

// Small 3-vector helpers shared by the sub-modules.

pub(crate) fn sub3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub(crate) fn add3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

pub(crate) fn scale3(k: f64, a: [f64; 3]) -> [f64; 3] {
    [k * a[0], k * a[1], k * a[2]]
}

pub(crate) fn dot3(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(crate) fn norm3(a: [f64; 3]) -> f64 {
    // hypot-style scaling is unnecessary for the magnitudes met here.
    dot3(a, a).sqrt()
}
