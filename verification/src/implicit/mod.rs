//! Implicit reference solvers on the *same discrete equations* as the explicit scheme.
//!
//! The discrete force on free node `i` (module doc of `ohl::scheme::explicit`),
//!
//! ```text
//! F_i(x, v) = T_{i+1/2} t_{i+1/2} - T_{i-1/2} t_{i-1/2} + (P_{i+1/2} + P_{i-1/2}) / 2 + q L - m_i g e3,
//! ```
//!
//! is evaluated by the library itself (`Explicit::net_force`, with the Kelvin-Voigt rate and the wind
//! damping (2.6) taken from the velocities handed to it), so the implicit solvers cannot drift from the
//! kernel's equations. The exact Jacobian (forward-mode dual numbers over a replica of the kernel's
//! segment formulas, checked by `ohl::statics::jacobian::replica_gap`) and the cached sparse LU are the
//! library's (`ohl::statics`), as is the static equilibrium solver (`ohl::statics::solve`).
//!
//! * [`newmark`]: Newmark's average-acceleration rule (trapezoidal, second order, unconditionally stable
//!   for linear problems) with Newton iterations on each step.
//! * [`line_newmark`]: the same rule for a whole line of conductors (`ohl::scheme::LineExplicit` as the
//!   force evaluator: conductors, links, elastic supports), on the line's degree-of-freedom map and
//!   sparsity pattern (`ohl::statics::line`).

pub mod line_newmark;
pub mod newmark;
