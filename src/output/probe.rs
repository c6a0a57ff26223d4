//! Probes: named points of the wire at a fixed Lagrangian coordinate `s = f S` (a fraction `f` of the
//! unstretched length from the first node), followed through the run.
//!
//! A probe between nodes `a` and `a + 1` at the local fraction `w` of segment `a` is at
//! `r = (1 - w) r_a + w r_{a+1}`, exactly at node `a` when `w = 0` (mid-span of an even grid) and the mean
//! of the two middle nodes for an odd grid. Its displacement is measured from the point at the same
//! fraction of the chord between the first and the last node, `(1 - f) A + f B` (for mid-span the chord
//! midpoint, the paper's reference in every figure).

use crate::wire::Wire;

/// Name of the probe every run has: the mid-span point `f = 1/2`.
pub const MIDSPAN: &str = "mid";

/// Where a probe is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ProbeAt {
    /// a fraction of the whole line's unstretched length [-]
    Line(f64),
    /// a fraction [-] of the span between nodes `first` and `last` (a span of a section)
    Span {
        /// the span's first node
        first: usize,
        /// its last node
        last: usize,
        /// fraction of its unstretched length [-]
        fraction: f64,
    },
}

/// A named Lagrangian point.
#[derive(Clone, Debug, PartialEq)]
pub struct ProbePoint {
    /// name, used in column names (`NAME_dx1_m`, ...)
    pub name: String,
    /// fraction `f` of the unstretched length from the first node [-], in [0, 1]
    pub at_fraction: f64,
    /// segment holding the point
    segment: usize,
    /// local fraction `w` in that segment [-]
    weight: f64,
    /// the chord point the displacement is measured from [m]
    reference_m: [f64; 3],
}

impl ProbePoint {
    /// The probe at fraction `f` of the wire's unstretched length, for a wire whose end nodes are at
    /// `a` and `b` [m] at the start.
    pub fn new(name: &str, f: f64, wire: &Wire) -> Self {
        Self::between(name, f, 0, wire.segments(), wire)
    }

    /// The probe of [`ProbeAt`].
    pub fn at(name: &str, at: ProbeAt, wire: &Wire) -> Self {
        match at {
            ProbeAt::Line(f) => Self::new(name, f, wire),
            ProbeAt::Span { first, last, fraction } => Self::between(name, fraction, first, last, wire),
        }
    }

    /// The probe at fraction `f` of the unstretched length between nodes `first` and `last` (a span of a
    /// section), its displacement measured from the chord between those two nodes at the start.
    pub fn between(name: &str, f: f64, first: usize, last: usize, wire: &Wire) -> Self {
        let n = last - first;
        let lengths = &wire.reference_length[first..last];
        let (segment, weight) = if lengths.iter().all(|l| l.to_bits() == lengths[0].to_bits()) {
            // Equal segments: exact integer arithmetic on f N (f = 1/2 lands on node N/2 for even N).
            let fn_ = f * n as f64;
            let j = (fn_.floor() as usize).min(n - 1);
            (j, fn_ - j as f64)
        } else {
            let target = f * lengths.iter().sum::<f64>();
            let mut s = 0.0;
            let mut found = (n - 1, 1.0);
            for (j, l) in lengths.iter().enumerate() {
                if target <= s + l {
                    found = (j, ((target - s) / l).clamp(0.0, 1.0));
                    break;
                }
                s += l;
            }
            found
        };
        let (a, b) = (wire.position(first), wire.position(last));
        let reference_m = [0, 1, 2].map(|k| (1.0 - f) * a[k] + f * b[k]);
        ProbePoint { name: name.to_string(), at_fraction: f, segment: first + segment, weight, reference_m }
    }

    /// The chord point the displacement is measured from [m].
    pub fn reference_m(&self) -> [f64; 3] {
        self.reference_m
    }

    /// Position of the point [m].
    pub fn position(&self, wire: &Wire) -> [f64; 3] {
        self.position_in(Self::coordinates(wire))
    }

    /// Displacement from the chord point at the same fraction [m].
    pub fn displacement(&self, wire: &Wire) -> [f64; 3] {
        self.displacement_in(Self::coordinates(wire))
    }

    /// The wire's node coordinates `x_1, x_2, x_3` [m], each sliced to the nodes: a caller that follows
    /// several probes slices them once, and one test of a node's index bounds its reads in all three.
    #[inline(always)]
    pub fn coordinates(wire: &Wire) -> [&[f64]; 3] {
        let n = wire.nodes();
        [&wire.x[0][..n], &wire.x[1][..n], &wire.x[2][..n]]
    }

    /// [`ProbePoint::position`] from the coordinates `x` ([`ProbePoint::coordinates`]).
    #[inline(always)]
    pub fn position_in(&self, x: [&[f64]; 3]) -> [f64; 3] {
        let (j, w) = (self.segment, self.weight);
        let [x1, x2, x3] = x;
        let a = [x1[j], x2[j], x3[j]];
        if w == 0.0 {
            return a;
        }
        let b = [x1[j + 1], x2[j + 1], x3[j + 1]];
        [(1.0 - w) * a[0] + w * b[0], (1.0 - w) * a[1] + w * b[1], (1.0 - w) * a[2] + w * b[2]]
    }

    /// [`ProbePoint::displacement`] from the coordinates `x` ([`ProbePoint::coordinates`]).
    #[inline(always)]
    pub fn displacement_in(&self, x: [&[f64]; 3]) -> [f64; 3] {
        let p = self.position_in(x);
        [0, 1, 2].map(|k| p[k] - self.reference_m[k])
    }
}
