//! Real conductors: the axial law of a conductor of one or two materials (aluminium layers on a steel
//! core), with the Aluminum Association / IEEE Std 1283 stress-strain polynomials, unloading along the final
//! modulus (permanent set), creep as a second curve, and each material's thermal strain: the knee point.
//!
//! - [`curve`]: a material's virgin loading curve `F(e)` (a quartic in the strain, or a line);
//! - [`component`]: one material and its loading/unloading path with the largest strain it has reached;
//! - [`two_material`]: the conductor, its components strained together, `T(e, theta)`;
//! - [`data`]: the stress-strain data of a catalogue entry (`[conductor.stress_strain]`) and their checks.
//!
//! The paper's conductor (one axial stiffness `EA`, one expansion coefficient, section 2 and (5.5)) is the
//! special case of one linear material; runs that give no material keep the paper's law, bit for bit.

pub mod component;
pub mod curve;
pub mod data;
pub mod two_material;

pub use component::{Component, CurveKind};
pub use curve::Curve;
pub use two_material::{History, TwoMaterial};
