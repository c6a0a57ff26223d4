//! Force elements, each written once over a [`Scalar`] (`f64` or a dual number), so that the explicit
//! step, the Jacobian of the static solver and the diagnostics evaluate the same formula.
//!
//! - [`link`]: an axial spring-damper between two points (insulator strings, tension strings, spacers
//!   and interphase spacers of a multi-conductor line, [`crate::line`]).
//! - [`pair`]: the least distance between two segments, the geometry of every pair element between two
//!   conductors (clearances now; the electromagnetic forces of a short circuit next).
//!
//! The conductor's own segment pass (tension (3.4) and the distributed loads (2.5)-(2.6)) keeps its fused,
//! vectorised form in [`crate::scheme::explicit`] and its dual-number replica in
//! [`crate::statics::jacobian`] (checked against each other by `jacobian::replica_gap`); the elements here
//! are the ones that join conductors to each other and to their supports.

pub mod link;
pub mod pair;
pub mod scalar;

pub use link::LinkLaw;
pub use scalar::Scalar;
