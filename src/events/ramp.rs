//! A temperature ramp on a span range: each segment goes linearly from its temperature at the start
//! `u_j(t0)` to the target `u*` over the ramp time `R`,
//!
//! ```text
//! u_j(t) = u_j(t0) + (u* - u_j(t0)) min(1, (t - t0) / R),
//! ```
//!
//! and its stress-free length follows through the thermal strain (5.5) (`Wire::update_rest_lengths`).
//! Section 5.6 cools the wire back to the ambient temperature "within one second".

use crate::wire::Wire;

/// A running ramp.
#[derive(Clone, Debug, PartialEq)]
pub struct Ramp {
    /// start time `t0` [s]
    pub start_s: f64,
    /// ramp time `R` [s], > 0
    pub duration_s: f64,
    /// first segment
    pub first: usize,
    /// segment temperatures at the start `u_j(t0)` [K], from `first` on
    pub from_k: Vec<f64>,
    /// target temperature `u*` [K]
    pub to_k: f64,
}

impl Ramp {
    /// Write the temperatures at time `t` into the wire (without updating rest lengths); returns true
    /// once the ramp is complete.
    pub fn apply(&self, wire: &mut Wire, t_s: f64) -> bool {
        let f = ((t_s - self.start_s) / self.duration_s).clamp(0.0, 1.0);
        for (k, &u0) in self.from_k.iter().enumerate() {
            wire.temperature_k[self.first + k] = u0 + (self.to_k - u0) * f;
        }
        f >= 1.0
    }
}
