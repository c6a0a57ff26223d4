//! The state of one span at one time level: its sag, its horizontal tension, its largest tension and its
//! least clearance above the ground, the design quantities of a span (sag and tension: IEEE Std 524 and
//! CIGRE TB 324, "sag-tension"; clearance to ground: the safety codes' minimum clearances).
//!
//! For a span between its end nodes `a` and `b` (the dead-end points or the string clamps, where they are
//! at this level), with `h = (b1 - a1, b2 - a2)` the horizontal chord and `f(x) = (x - a)_h . h / |h|^2`
//! the horizontal fraction of a point:
//!
//! ```text
//! sag      d = (a3 + b3) / 2 - x3(f = 1/2)                                              [m]
//! tension  H = T_j (x_{j+1} - x_j)_h . h / (|h| |x_{j+1} - x_j|),  j the segment at f = 1/2  [N]
//! ```
//!
//! `d` is the vertical distance from the chord down to the conductor at the horizontal middle of the
//! span (the sag of [`crate::wire::section::midspan_sag_m`], the definition of a span's stringing
//! `sag_m`), with `x3(f = 1/2)` interpolated linearly on the segment that crosses the middle (the first,
//! from `a`). `H` is the tension's component along the horizontal chord direction on that segment: at
//! rest under loads normal to the chord direction (gravity, a wind across the line) it is the same on
//! every segment of the span, the catenary's `H` ([`crate::exact::ElasticCatenary::horizontal_tension_n`]);
//! in motion it is its value at the middle. Both are `None` for a span with a broken segment (the pieces
//! have no mid-span) or a vertical chord (`|h| = 0`).

use serde::Serialize;

use crate::scheme::{Explicit, Ground};

/// One span's state at one time level (module doc).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SpanState {
    /// vertical distance from the chord down to the conductor at the horizontal middle of the span [m]
    /// (none for a broken span)
    pub sag_m: Option<f64>,
    /// the tension's component along the horizontal chord direction at the middle of the span [N] (none
    /// for a broken span)
    pub horizontal_tension_n: Option<f64>,
    /// largest segment tension of the span [N]
    pub max_tension_n: f64,
    /// least vertical clearance of the span's nodes above the ground `min (x3 - h(x2))` [m] (with a
    /// ground)
    pub least_clearance_m: Option<f64>,
}

impl SpanState {
    /// The state of the span from node `first` to node `last` of `s` at its current level, with the
    /// clearance above `ground` if there is one. Requires [`Explicit::evaluate_forces`] at this level (for
    /// the largest tension; panics otherwise: internal misuse).
    pub fn of(s: &Explicit, first: usize, last: usize, ground: Option<&Ground>) -> Self {
        let w = s.wire();
        let middle = if (first..last).all(|j| w.intact[j] == 1.0) { middle_segment(s, first, last) } else { None };
        SpanState {
            sag_m: middle.map(|m| m.sag_m),
            horizontal_tension_n: middle.map(|m| m.horizontal_tension_n),
            max_tension_n: s.max_tension_in(first..last),
            least_clearance_m: ground.map(|g| g.least_clearance_m(&w.x, first..=last)),
        }
    }
}

/// Sag and horizontal tension at the horizontal middle of an intact span.
#[derive(Clone, Copy)]
struct Middle {
    sag_m: f64,
    horizontal_tension_n: f64,
}

fn middle_segment(s: &Explicit, first: usize, last: usize) -> Option<Middle> {
    let w = s.wire();
    let (a, b) = (w.position(first), w.position(last));
    let h = [b[0] - a[0], b[1] - a[1]];
    let h2 = h[0] * h[0] + h[1] * h[1];
    if h2 <= 0.0 {
        return None;
    }
    let fraction = |p: [f64; 3]| ((p[0] - a[0]) * h[0] + (p[1] - a[1]) * h[1]) / h2;
    let j = (first..last).find(|&j| fraction(w.position(j)) <= 0.5 && fraction(w.position(j + 1)) > 0.5)?;
    let (p, q) = (w.position(j), w.position(j + 1));
    let (fp, fq) = (fraction(p), fraction(q));
    let x3 = p[2] + (q[2] - p[2]) * (0.5 - fp) / (fq - fp);
    let d = [q[0] - p[0], q[1] - p[1], q[2] - p[2]];
    let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    let along = (d[0] * h[0] + d[1] * h[1]) / (h2.sqrt() * len);
    Some(Middle { sag_m: 0.5 * (a[2] + b[2]) - x3, horizontal_tension_n: s.segment_tension(j) * along })
}
