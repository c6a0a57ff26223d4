//! The electromagnetic load of a line during a short circuit (issue 25): which conductor carries which
//! phase's fault current and its share, and the numerics of the force evaluation
//! ([`crate::scheme::electromagnetic`] evaluates it in the explicit line scheme).
//!
//! # Model
//!
//! Every segment of a carrier is a straight current filament carrying `share * i_L(t)` (the phase current
//! of [`crate::shortcircuit::current`], `1/n` of it in each sub-conductor of a bundle of `n`), flowing
//! from node 0 to node N of its wire. All conductors of a span should therefore be numbered the same way
//! (the builders of [`crate::line::build`] string every conductor from the same support to the other); a
//! carrier numbered the other way takes a negative `share`. The force on a carrier's segment `B` is the
//! sum over every segment `A` of the other carriers and of its own carrier except `B` and its two
//! neighbours of the Biot-Savart pair force ([`crate::element::em_force::pair_force`], the core cut where
//! `A` and `B` share a node), split to `B`'s nodes by its first moment:
//!
//! ```text
//! F_B(t) = i_B(t) sum_A i_A(t) G_AB(r),   i_A = share_A i_{L(A)}(t),
//! ```
//!
//! `G_AB` the force between unit currents on the present geometry `r`. In vacuum; no skin or proximity
//! effect (a conductor is a filament on its axis), no current in earth wires (a line-to-earth fault's
//! return is not modelled).
//!
//! # Numerics ([`EmNumerics`])
//!
//! - Chords: the filaments are chords of `chord_segments = k` mechanical segments (node 0 to node k, k to
//!   2k, ...; the last chord takes what is left). A chord's force and first moment give a linear force
//!   density along it, `q(u) = (4F - 6M) + (12M - 6F) u` (`F = int q`, `M = int u q`, `u` in `[0, 1]` the
//!   rest-length fraction along the chord), which is spread to the mechanical nodes inside it by their
//!   linear shape functions (`int phi_j q du`): force and moment are kept, and `k = 1` is exactly the
//!   pair element's split. The error is that of the chord approximation of the curved conductor, second
//!   order in the chord length (docs/short_circuit.md).
//! - Refresh: the geometric factors `G_AB`, summed per target chord and source phase, are recomputed every
//!   `refresh_steps = M` steps of current flow and multiplied by the currents at every step; with
//!   `extrapolate` they are extrapolated linearly in time from their last two evaluations (second order
//!   in `M dt`). `M = 1`, `k = 1` is the all-pairs evaluation at every step.
//!
//! The measured errors of both against the all-pairs, every-step evaluation and the defaults' sources:
//! docs/short_circuit.md and `tests/short_circuit_line.rs`.

// Units in brackets, `[N]`, `[m]`, `[A]`, would otherwise be taken for intra-doc links.
#![allow(rustdoc::broken_intra_doc_links)]

use crate::shortcircuit::current::FaultCurrent;

/// A conductor that carries a share of a phase's fault current.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Carrier {
    /// the conductor's index in the line model
    pub conductor: usize,
    /// the phase whose current it carries: 0, 1, 2 for L1, L2, L3
    pub phase: usize,
    /// its share of the phase current [-]: `1/n` in a bundle of `n` sub-conductors; negative if the wire
    /// is numbered against the direction of the current (module docs); `0 < |share| <= 1`
    pub share: f64,
    /// radius of the conductor [m], > 0: the length of a filament left out next to a node it shares
    /// with another ([`crate::element::em_force`])
    pub core_radius_m: f64,
}

/// The numerics of the electromagnetic force (module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EmNumerics {
    /// `k`: mechanical segments per electromagnetic chord, >= 1 (1: every segment is a filament)
    pub chord_segments: usize,
    /// `M`: recompute the geometric factors every `M` steps, >= 1 (1: every step)
    pub refresh_steps: usize,
    /// extrapolate the geometric factors linearly in time from their last two evaluations between
    /// refreshes (second order); false: hold the last evaluation (first order)
    pub extrapolate: bool,
}

impl Default for EmNumerics {
    /// `k = 4`, `M = 8`, extrapolated: on the swinging three-phase span of `tests/short_circuit_line.rs`
    /// (phases 1.5 m apart, 0.83 m segments) the swing differs from the all-pairs, every-step evaluation
    /// by 6.4e-5 of its amplitude and the force resultants by 2.7e-3; 1/128 of the all-pairs cost
    /// (docs/short_circuit.md, "Fast evaluation"). For phases: keep the chord (`k` segments) no longer
    /// than about twice the least distance between carriers (a bundle's sub-conductors need `k` = 1 or 2).
    fn default() -> Self {
        EmNumerics { chord_segments: 4, refresh_steps: 8, extrapolate: true }
    }
}

/// The electromagnetic load of a line: the carriers, the fault current, the numerics.
#[derive(Clone, Debug, PartialEq)]
pub struct Electromagnetic {
    /// the conductors that carry current (each at most once)
    pub carriers: Vec<Carrier>,
    /// the phase currents as functions of time
    pub current: FaultCurrent,
    /// chords and refresh
    pub numerics: EmNumerics,
}

/// An electromagnetic load that does not fit the line.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum EmError {
    /// a value outside its range
    #[error("{what} = {value} must be {allowed}")]
    Value {
        /// which value, e.g. `carriers[2].share`
        what: String,
        /// the value
        value: f64,
        /// the allowed range
        allowed: String,
    },
    /// a carrier names a conductor that does not exist, or a conductor twice
    #[error("{what}: {detail}")]
    Carrier {
        /// which carrier
        what: String,
        /// what is wrong
        detail: String,
    },
}

impl Electromagnetic {
    /// Check the carriers against a line of `conductors` conductors and the numerics.
    pub fn check(&self, conductors: usize) -> Result<(), EmError> {
        let value = |what: String, value: f64, allowed: &str| EmError::Value { what, value, allowed: allowed.into() };
        for (k, c) in self.carriers.iter().enumerate() {
            if c.conductor >= conductors {
                return Err(EmError::Carrier {
                    what: format!("carriers[{k}]"),
                    detail: format!("conductor {} does not exist ({conductors} conductors)", c.conductor),
                });
            }
            if self.carriers[..k].iter().any(|o| o.conductor == c.conductor) {
                return Err(EmError::Carrier {
                    what: format!("carriers[{k}]"),
                    detail: format!("conductor {} carries current twice", c.conductor),
                });
            }
            if c.phase > 2 {
                return Err(value(format!("carriers[{k}].phase"), c.phase as f64, "0, 1 or 2 (L1, L2, L3)"));
            }
            if !(c.share.is_finite() && c.share != 0.0 && c.share.abs() <= 1.0) {
                return Err(value(format!("carriers[{k}].share"), c.share, "a finite number with 0 < |share| <= 1"));
            }
            if !(c.core_radius_m.is_finite() && c.core_radius_m > 0.0) {
                return Err(value(format!("carriers[{k}].core_radius_m"), c.core_radius_m, "a finite number > 0 [m]"));
            }
        }
        if self.numerics.chord_segments < 1 {
            return Err(value("numerics.chord_segments".into(), 0.0, "an integer >= 1"));
        }
        if self.numerics.refresh_steps < 1 {
            return Err(value("numerics.refresh_steps".into(), 0.0, "an integer >= 1"));
        }
        Ok(())
    }
}
