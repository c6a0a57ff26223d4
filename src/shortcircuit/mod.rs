//! Short-circuit effects on flexible conductors (issue 25).
//!
//! [`current`]: the fault current of each phase as a function of time (a.c. and decaying d.c. parts, the
//! fault's kind, inception angle, duration and auto-reclose), the source of the electromagnetic load of a
//! line ([`crate::line::electromagnetic`]).
//!
//! [`iec60865`]: the simplified method of IEC 60865-1:2011, clause 6 (flexible conductors): the swing-out
//! of a span under the electromagnetic force of a three- or two-phase short circuit, the tensile forces
//! during the short circuit (`F_t`), at the fall of the span after it (`F_f`), the horizontal displacement
//! `b_h`, the minimum air clearance `a_min` and the bundle pinch force `F_pi` (effective-clash case).
//! docs/short_circuit_iec60865.md lists the equations, their sources and the public worked examples.
//!
//! [`pinch_transition`]: the length of a pinched bundle's transition at a spacer, the grid scale the
//! dynamic pinch tension needs.

pub mod current;
pub mod iec60865;
pub mod pinch_transition;

pub use current::{CurrentError, FaultCurrent, FaultCurrentSpec, FaultKind, Reclose};
