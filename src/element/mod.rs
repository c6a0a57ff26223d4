//! Force elements, each written once over a [`Scalar`] (`f64` or a dual number), so that the explicit
//! step, the Jacobian of the static solver and the diagnostics evaluate the same formula.
//!
//! - [`tension`]: the Kelvin-Voigt law (3.4) of a conductor segment (tension-only or linear).
//! - [`aero`]: the distributed wind loads (2.5)-(2.6) and the uniform normal pressure of section 4.1.
//! - [`segment`]: a conductor's own segment, composing the two with its stretch and its uniform load:
//!   the segment pass of (3.1), which the fused, vectorised kernel ([`crate::scheme::explicit`]) calls
//!   on `f64` for every segment and the static solver's Jacobian ([`crate::statics::jacobian`]) on dual
//!   numbers.
//! - [`link`]: an axial spring-damper between two points (insulator strings, tension strings, spacers
//!   and interphase spacers of a multi-conductor line, [`crate::line`]).
//! - [`pair`]: the least distance between two segments, the geometry of every pair element between two
//!   conductors (clearances now; the electromagnetic forces of a short circuit next).
//! - [`em_force`]: the electromagnetic force between two straight current filaments (Biot-Savart),
//!   the pair element of a short circuit (issue 25; `f64` only, not yet used by the line model).
//!
//! The single-conductor insulator string ([`crate::wire::insulator`]) takes its force from the link
//! element; its stiffness for the static solver is still written out by hand (checked against the force
//! by finite differences), as are its crossarm spring and the ground contact of the node pass.

pub mod aero;
pub mod em_force;
pub mod link;
pub mod pair;
pub mod scalar;
pub mod segment;
pub mod tension;

pub use link::LinkLaw;
pub use scalar::Scalar;
