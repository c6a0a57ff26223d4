//! Heat conduction along the wire during a run: the explicit scheme (5.2) of [`crate::heat`] on the
//! wire's nodes (`s_i = i / N`), with a span range held at a fixed temperature, driving the segment
//! temperatures and through them the stress-free lengths (5.5).
//!
//! Time scale. (5.1) is dimensionless, `u_t = u_ss` on `s in [0, 1]`. Physical conduction in the
//! aluminium wire of section 5.4 has diffusivity `k / (rho c) = 209 / (2700 * 900) = 8.6e-5 m^2/s`, so
//! one unit of dimensionless heat time is `S^2 / D = 160^2 / 8.6e-5 = 3.0e8 s` (about ten years): the
//! paper's de-icing sequence, where the heat spreads along the span in 5 s, is not physical (docs/paper_notes.md).
//! The event therefore states `heat_time_per_s` [1/s], the dimensionless heat time per second of the
//! mechanical run; each mechanical step `dt` advances the rod by `dt * heat_time_per_s`, in sub-steps no
//! longer than the scheme's stability limit `h^2 / 2`.
//!
//! Initial nodal temperatures: the mean of the adjacent segments (the end nodes take their segment's).

use crate::heat::{HeatBoundary, HeatRod};
use crate::wire::Wire;

/// Heat conduction running along the wire.
#[derive(Clone, Debug)]
pub struct Conduction {
    rod: HeatRod,
    /// dimensionless heat time per second of the run [1/s]
    per_s: f64,
    scratch: Vec<f64>,
}

impl Conduction {
    /// Start from the wire's segment temperatures, holding `nodes` at `hold_k` [K].
    pub fn start(wire: &Wire, nodes: std::ops::Range<usize>, hold_k: f64, per_s: f64, boundary: HeatBoundary) -> Self {
        let n = wire.segments();
        let t = &wire.temperature_k;
        let u0: Vec<f64> = (0..=n)
            .map(|i| match i {
                0 => t[0],
                i if i == n => t[n - 1],
                i => 0.5 * (t[i - 1] + t[i]),
            })
            .collect();
        let mut rod = HeatRod::new(u0, boundary);
        if nodes.start < nodes.end {
            rod.hold(nodes, hold_k);
        }
        Conduction { rod, per_s, scratch: vec![0.0; n] }
    }

    /// Advance by `dt` [s] of the run and write the segment temperatures and stress-free lengths.
    pub fn advance(&mut self, wire: &mut Wire, dt: f64) {
        let total = dt * self.per_s;
        let max = self.rod.max_stable_step();
        let steps = (total / max).ceil().max(1.0);
        let h = total / steps;
        for _ in 0..steps as usize {
            self.rod.step(h);
        }
        self.rod.segment_temperatures(&mut self.scratch);
        wire.temperature_k.copy_from_slice(&self.scratch);
        wire.update_rest_lengths();
    }
}
