//! Clearances: the least distance between two conductors (phase to phase, phase to earth wire, bundle to
//! bundle), at every time level, with where and when its minimum occurs.
//!
//! Each conductor is the polyline of its nodes (its intact segments); the least distance of two
//! polylines is the least of the segment-to-segment distances ([`crate::element::pair::closest_points`]).
//! The polyline is the scheme's own picture of the conductor: it converges to the continuous curve at
//! `O(ds^2)` (chords of a smooth curve deviate from it by `ds^2 kappa / 8`), so the clearance does too.
//!
//! Cost. Not all `N_a N_b` pairs: the segments of `b` are sorted by their projection on the horizontal
//! direction of `a`'s chord, and a segment of `a` is compared only with the segments of `b` whose
//! projection lies within the best distance found so far (a distance can only be smaller than `best` if
//! its projection on any unit vector is). Starting from the distance of a few corresponding nodes, the
//! window holds a few segments for conductors along the same span: `O(N log N)` per pair and level. The
//! window's ends are found by walking from the previous segment's, and within it a pair whose bounding
//! boxes are farther apart than the best distance so far is passed over uncomputed (it could not be
//! taken): for parallel conductors about one segment pair of `b` per segment of `a` is computed.

use crate::element::pair::closest_points;
use crate::scheme::Explicit;
use crate::wire::Wire;

/// A conductor as the tracker reads it: its wire. A `&Wire`, or the solver itself, so that a run passes
/// its conductors (`LineExplicit::conductors`) without collecting their wires into a new vector at every
/// level.
pub trait ConductorWire {
    /// The conductor's wire.
    fn conductor_wire(&self) -> &Wire;
}

impl ConductorWire for &Wire {
    fn conductor_wire(&self) -> &Wire {
        self
    }
}

impl ConductorWire for Explicit {
    fn conductor_wire(&self) -> &Wire {
        self.wire()
    }
}

/// The closest points of two conductors at one time level.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Closest {
    /// the least distance [m]
    pub distance_m: f64,
    /// segment of the first conductor that holds its closest point
    pub segment_a: usize,
    /// fraction along that segment [-]
    pub fraction_a: f64,
    /// segment of the second conductor
    pub segment_b: usize,
    /// fraction along it [-]
    pub fraction_b: f64,
    /// the closest point of the first conductor [m]
    pub point_a_m: [f64; 3],
    /// the closest point of the second conductor [m]
    pub point_b_m: [f64; 3],
}

impl Closest {
    /// Lagrangian coordinate of the closest point of the first conductor, as a fraction of its
    /// unstretched length from its first node [-].
    pub fn arc_fraction_a(&self, a: &Wire) -> f64 {
        arc_fraction(a, self.segment_a, self.fraction_a)
    }
    /// The same for the second conductor [-].
    pub fn arc_fraction_b(&self, b: &Wire) -> f64 {
        arc_fraction(b, self.segment_b, self.fraction_b)
    }
}

fn arc_fraction(w: &Wire, j: usize, f: f64) -> f64 {
    let before: f64 = w.reference_length[..j].iter().sum();
    (before + f * w.reference_length[j]) / w.reference_length.iter().sum::<f64>()
}

/// Reusable buffers of [`least_distance`] for one pair of conductors (no allocation once grown). Kept
/// from one call to the next, they make the next call cheaper: the segment order of the last call is
/// re-sorted by insertion (linear when the conductors have moved little), and the closest segment pair of
/// the last call gives the first bound.
#[derive(Clone, Debug, Default)]
pub struct Scratch {
    order: Vec<usize>,
    lo: Vec<f64>,
    hi: Vec<f64>,
    last: Option<(usize, usize)>,
    /// bounding box of each segment of `b` ([`segment_box`])
    boxes: Vec<[f64; 6]>,
    /// the intact segments of `b` in `order`, with their `lo`, `hi` and box side by side
    cand: Vec<Candidate>,
    /// their `lo` in that order (the windows' keys)
    cand_lo: Vec<f64>,
}

/// A segment of `b` in the sorted order of [`least_distance`]: its index, the interval of its projection
/// and its bounding box, read together in the window.
#[derive(Clone, Copy, Debug, Default)]
struct Candidate {
    j: usize,
    lo: f64,
    hi: f64,
    bx: [f64; 6],
}

/// The least distance between the intact segments of conductors `a` and `b`; `None` if either has none.
pub fn least_distance(a: &Wire, b: &Wire, scratch: &mut Scratch) -> Option<Closest> {
    let (na, nb) = (a.segments(), b.segments());
    // Horizontal direction of a's chord (x2 if the chord is vertical).
    let (pa, pz) = (a.position(0), a.position(na));
    let h = [pz[0] - pa[0], pz[1] - pa[1]];
    let hn = (h[0] * h[0] + h[1] * h[1]).sqrt();
    let e = if hn > 0.0 { [h[0] / hn, h[1] / hn] } else { [0.0, 1.0] };
    let proj = |w: &Wire, i: usize| e[0] * w.x[0][i] + e[1] * w.x[1][i];
    let Scratch { order, lo, hi, last, boxes, cand, cand_lo } = scratch;
    lo.clear();
    hi.clear();
    boxes.clear();
    boxes.extend((0..nb).map(|j| segment_box(b.position(j), b.position(j + 1))));
    let mut ext_b = 0.0_f64;
    for j in 0..nb {
        let (p, q) = (proj(b, j), proj(b, j + 1));
        lo.push(p.min(q));
        hi.push(p.max(q));
        ext_b = ext_b.max((p - q).abs());
    }
    // The intact segments sorted by `lo`: insertion sort from the last order (nearly sorted after one
    // step: linear time), rebuilt when the segments changed (a break).
    let intact = (0..nb).filter(|&j| b.intact[j] > 0.0).count();
    if order.len() != intact || order.iter().any(|&j| j >= nb || b.intact[j] <= 0.0) {
        order.clear();
        order.extend((0..nb).filter(|&j| b.intact[j] > 0.0));
    }
    for i in 1..order.len() {
        let (v, key) = (order[i], lo[order[i]]);
        let mut k = i;
        while k > 0 && lo[order[k - 1]].total_cmp(&key).is_gt() {
            order[k] = order[k - 1];
            k -= 1;
        }
        order[k] = v;
    }
    if order.is_empty() || a.intact.iter().all(|&x| x <= 0.0) {
        return None;
    }
    cand.clear();
    cand.extend(order.iter().map(|&j| Candidate { j, lo: lo[j], hi: hi[j], bx: boxes[j] }));
    cand_lo.clear();
    cand_lo.extend(cand.iter().map(|c| c.lo));
    // Upper bound: the distance between a few corresponding nodes.
    let mut best2 = f64::INFINITY;
    let mut found: Option<Closest> = None;
    let dist2 = |p: [f64; 3], q: [f64; 3]| (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2);
    // Only points of the polylines may bound: nodes on an intact segment, and the last closest pair if
    // both its segments are still intact (a chord across a break is not part of the conductor).
    let on_intact = |w: &Wire, i: usize| (i > 0 && w.intact[i - 1] > 0.0) || (i < w.segments() && w.intact[i] > 0.0);
    for k in 0..=8 {
        let (i, j) = (k * na / 8, k * nb / 8);
        if on_intact(a, i) && on_intact(b, j) {
            best2 = best2.min(dist2(a.position(i), b.position(j)));
        }
    }
    if let Some((i, j)) = *last
        && i < na
        && j < nb
        && a.intact[i] > 0.0
        && b.intact[j] > 0.0
    {
        let (d2, _, _) = closest_points(a.position(i), a.position(i + 1), b.position(j), b.position(j + 1));
        best2 = best2.min(d2);
    }
    // Slightly above the bound so that the pair that attains it is visited.
    let mut best = best2.sqrt() * (1.0 + 1e-12) + 1e-300;
    // Where the two windows of `order` started for the last segment of `a`; `lo` without a NaN (else
    // the windows are found by binary search, as `partition_point` did).
    let (mut first_at, mut last_at) = (0, 0);
    let sorted = !lo.iter().any(|v| v.is_nan());
    // The box bound's margin ([`box_gap2`]), from the largest coordinate magnitude of both conductors.
    let largest = |w: &Wire| w.x.iter().flatten().fold(0.0_f64, |m, &v| if v.abs() > m { v.abs() } else { m });
    let slack = 1.0e-9 * (1.0 + largest(a).max(largest(b)));
    for i in 0..na {
        if a.intact[i] <= 0.0 {
            continue;
        }
        let (p, q) = (proj(a, i), proj(a, i + 1));
        let (alo, ahi) = (p.min(q), p.max(q));
        // The same indices as `order.partition_point`, found by walking from the previous segment's
        // (`lo` is sorted along `order`, so each predicate holds on a prefix: its partition point is
        // unique): a few steps where `a` runs along the chord, a binary search beyond.
        let (below, above) = (alo - best - ext_b, ahi + best);
        let first = walk_partition(cand_lo, |v| v < below, &mut first_at, sorted);
        let last = walk_partition(cand_lo, |v| v <= above, &mut last_at, sorted);
        let (p0, p1) = (a.position(i), a.position(i + 1));
        let p_box = segment_box(p0, p1);
        for c in &cand[first..last.max(first)] {
            if c.lo > ahi + best || c.hi < alo - best {
                continue;
            }
            // A pair whose computed distance cannot be below the best so far would not be taken: passed
            // over without computing it.
            if found.is_some() && box_gap2(&p_box, &c.bx, slack) > best2 {
                continue;
            }
            let j = c.j;
            let (q0, q1) = (b.position(j), b.position(j + 1));
            let (d2, s, u) = closest_points(p0, p1, q0, q1);
            if found.is_none() || d2 < best2 {
                best2 = d2;
                best = d2.sqrt();
                let at = |x: [f64; 3], y: [f64; 3], f: f64| [0, 1, 2].map(|k| x[k] + f * (y[k] - x[k]));
                found = Some(Closest {
                    distance_m: best,
                    segment_a: i,
                    fraction_a: s,
                    segment_b: j,
                    fraction_b: u,
                    point_a_m: at(p0, p1, s),
                    point_b_m: at(q0, q1, u),
                });
            }
        }
    }
    *last = found.map(|c| (c.segment_a, c.segment_b));
    found
}

/// A lower bound of the squared distance [`closest_points`] computes for the segments `p0 p1` and
/// `q0 q1` [m^2] from their bounding boxes `p`, `q` ([`segment_box`]): the squared gap between them,
/// each axis's gap shortened by `slack` [m] and the sum by a factor `1 - 1e-9`, with
/// `slack = 1e-9 (1 + M)` for `M` at least every coordinate magnitude ([`least_distance`]: the largest
/// of both conductors). The points `closest_points` compares, `p0 + s (p1 - p0)` with `s` in `[0, 1]`,
/// are computed within a few units in the last place of `M` (`2.2e-16 M` each) of their segment's box,
/// and their squared distance within a few rounding errors of its value, both far inside those margins. Plain comparisons (one instruction each): with a NaN
/// coordinate the bound is some number, and the pair's computed distance is NaN, which is never taken
/// once a pair has been ([`least_distance`] only passes over pairs then).
#[inline]
fn box_gap2(p: &[f64; 6], q: &[f64; 6], slack: f64) -> f64 {
    let mut g2 = 0.0;
    for k in 0..3 {
        let (plo, phi, qlo, qhi) = (p[2 * k], p[2 * k + 1], q[2 * k], q[2 * k + 1]);
        let (after, before) = (qlo - phi, plo - qhi);
        let gap = if after > before { after } else { before } - slack;
        // Branch-free: a gap not above zero (or NaN) adds +0, which leaves the sum (>= +0) unchanged.
        let gap = if gap > 0.0 { gap } else { 0.0 };
        g2 += gap * gap;
    }
    g2 * (1.0 - 1.0e-9)
}

/// The bounding box of the segment `p0 p1`: `[lo1, hi1, lo2, hi2, lo3, hi3]` [m] ([`box_gap2`]).
#[inline]
fn segment_box(p0: [f64; 3], p1: [f64; 3]) -> [f64; 6] {
    let mut b = [0.0; 6];
    for k in 0..3 {
        (b[2 * k], b[2 * k + 1]) = if p0[k] < p1[k] { (p0[k], p1[k]) } else { (p1[k], p0[k]) };
    }
    b
}

/// `keys.partition_point(|&v| pred(v))` for a predicate that holds on a prefix of `keys` (when `sorted`):
/// by walking from the previous answer `at` when the answer is within a few places of it, by binary
/// search otherwise (and always if not `sorted`); `at` becomes the answer.
#[inline]
fn walk_partition(keys: &[f64], pred: impl Fn(f64) -> bool, at: &mut usize, sorted: bool) -> usize {
    const STEPS: usize = 8;
    let n = keys.len();
    let mut k = (*at).min(n);
    if sorted {
        if k < n && pred(keys[k]) {
            // forwards: the answer is after k
            let stop = (k + STEPS).min(n);
            k += 1;
            while k < stop && pred(keys[k]) {
                k += 1;
            }
            if k < n && k == stop && pred(keys[k]) {
                k = keys.partition_point(|&v| pred(v));
            }
        } else {
            // backwards: the answer is k or before
            let stop = k.saturating_sub(STEPS);
            while k > stop && !pred(keys[k - 1]) {
                k -= 1;
            }
            if k > 0 && k == stop && !pred(keys[k - 1]) {
                k = keys.partition_point(|&v| pred(v));
            }
        }
    } else {
        k = keys.partition_point(|&v| pred(v));
    }
    *at = k;
    k
}

/// The least distance of a pair of conductor groups over a run: its value, when and where.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LeastClearance {
    /// the conductors of the pair at the least distance (one of each group)
    pub conductors: (usize, usize),
    /// the closest points then
    pub closest: Closest,
    /// time of the least distance [s]
    pub time_s: f64,
}

/// Tracks the clearance between every pair of conductor groups at every level. A group is a phase or an
/// earth wire (one conductor) or a bundle (its sub-conductors); the clearance of two groups is the least
/// distance between any of their conductors.
#[derive(Clone, Debug)]
pub struct ClearanceTracker {
    /// the conductors of each group
    groups: Vec<Vec<usize>>,
    /// the group pairs `(g, h)`, `g < h`
    pairs: Vec<(usize, usize)>,
    /// the clearance of each pair at the last level observed
    current: Vec<Option<LeastClearance>>,
    /// the least clearance of each pair so far
    least: Vec<Option<LeastClearance>>,
    /// one scratch per pair of conductors, kept between levels
    scratch: std::collections::HashMap<(usize, usize), Scratch>,
    /// each conductor's node positions at the last exact measurement [m]
    reference: Vec<[Vec<f64>; 3]>,
    /// each pair's distance at the last exact measurement [m]
    measured: Vec<f64>,
    /// each conductor's largest node displacement since then [m] (scratch of `observe_bounded`)
    moved: Vec<f64>,
    /// exact measurements made and levels observed [-]
    pub counts: (u64, u64),
}

impl ClearanceTracker {
    /// A tracker for the given groups of conductors (indices into the model's conductors).
    pub fn new(groups: Vec<Vec<usize>>) -> Self {
        let g = groups.len();
        let pairs: Vec<(usize, usize)> = (0..g).flat_map(|a| (a + 1..g).map(move |b| (a, b))).collect();
        let n = pairs.len();
        let scratch = Default::default();
        let (reference, measured) = (Vec::new(), vec![f64::NAN; n]);
        ClearanceTracker {
            groups,
            pairs,
            current: vec![None; n],
            least: vec![None; n],
            scratch,
            reference,
            measured,
            moved: Vec::new(),
            counts: (0, 0),
        }
    }

    /// The groups.
    pub fn groups(&self) -> &[Vec<usize>] {
        &self.groups
    }

    /// The group pairs, in the order of [`ClearanceTracker::current`] and [`ClearanceTracker::least`].
    pub fn pairs(&self) -> &[(usize, usize)] {
        &self.pairs
    }

    /// Track every pair at time `t_s` [s] without missing a new least distance, measuring only where one
    /// is possible: no node of conductor `c` has moved more than `delta_c` since the last measurement
    /// (the largest distance of a node from its position then, computed over the nodes: `O(N)`), so the
    /// distance of a pair measured `d` then is at least `d - delta_a - delta_b` now. Every pair is measured
    /// when that bound of some pair is not above its least so far, or when `force` (a sample, the end);
    /// otherwise [`ClearanceTracker::current`] keeps the last measurement. The least distances, their
    /// times and places are those of measuring every level (a level skipped cannot hold a smaller one).
    pub fn observe_bounded<W: ConductorWire>(&mut self, wires: &[W], t_s: f64, force: bool) {
        self.counts.1 += 1;
        if self.pairs.is_empty() {
            // No pair to bound (one group: a single phase with its droppers, case k): the displacements
            // would decide nothing. A forced level measures as below (the counts are the same).
            if force {
                self.observe(wires, t_s);
            }
            return;
        }
        let moved = &mut self.moved;
        moved.clear();
        if self.reference.len() == wires.len() {
            moved.extend(wires.iter().zip(&self.reference).map(|(w, r)| {
                let w = w.conductor_wire();
                let mut m2 = 0.0_f64;
                for i in 0..w.nodes() {
                    let d = [w.x[0][i] - r[0][i], w.x[1][i] - r[1][i], w.x[2][i] - r[2][i]];
                    m2 = m2.max(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                }
                m2.sqrt()
            }));
        } else {
            moved.resize(wires.len(), f64::INFINITY);
        }
        let group_moved = |g: &[usize]| g.iter().map(|&c| moved[c]).fold(0.0, f64::max);
        let possible = self.pairs.iter().enumerate().any(|(p, &(g, h))| {
            let bound = self.measured[p] - group_moved(&self.groups[g]) - group_moved(&self.groups[h]);
            // NaN (never measured, or a pair without segments) measures.
            let least = self.least[p].map_or(f64::INFINITY, |l| l.closest.distance_m);
            bound.partial_cmp(&least) != Some(std::cmp::Ordering::Greater)
        });
        if force || possible {
            self.observe(wires, t_s);
        }
    }

    /// Measure every pair at time `t_s` [s] for the conductors' wires.
    pub fn observe<W: ConductorWire>(&mut self, wires: &[W], t_s: f64) {
        self.counts.0 += 1;
        self.reference.resize_with(wires.len(), Default::default);
        for (r, w) in self.reference.iter_mut().zip(wires) {
            for k in 0..3 {
                r[k].clear();
                r[k].extend_from_slice(&w.conductor_wire().x[k]);
            }
        }
        for (p, &(g, h)) in self.pairs.iter().enumerate() {
            let mut best: Option<LeastClearance> = None;
            for &a in &self.groups[g] {
                for &b in &self.groups[h] {
                    let scratch = self.scratch.entry((a, b)).or_default();
                    if let Some(c) = least_distance(wires[a].conductor_wire(), wires[b].conductor_wire(), scratch)
                        && best.is_none_or(|x| c.distance_m < x.closest.distance_m)
                    {
                        best = Some(LeastClearance { conductors: (a, b), closest: c, time_s: t_s });
                    }
                }
            }
            self.current[p] = best;
            self.measured[p] = best.map_or(f64::NAN, |b| b.closest.distance_m);
            if let Some(c) = best
                && self.least[p].is_none_or(|x| c.closest.distance_m < x.closest.distance_m)
            {
                self.least[p] = Some(c);
            }
        }
    }

    /// Each pair's clearance at the last level observed.
    pub fn current(&self) -> &[Option<LeastClearance>] {
        &self.current
    }

    /// Each pair's least clearance so far (every level observed, not samples).
    pub fn least(&self) -> &[Option<LeastClearance>] {
        &self.least
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::element::tension::LawKind;
    use crate::wire::Conductor;

    fn straight(x1: f64, x3: f64, n: usize, len: f64, shift: f64) -> Wire {
        let xs = [vec![x1; n + 1], (0..=n).map(|i| shift + len * i as f64 / n as f64).collect(), vec![x3; n + 1]];
        let c = Conductor { axial_stiffness_n: 1e6, internal_friction_n_s: 0.0, law: LawKind::TensionOnly };
        Wire::new(c, xs, vec![len / n as f64; n], 1.0)
    }

    /// [`least_distance`] as it was before its candidates were stored side by side and the box bound made
    /// branch-free (commit 6ea28af), for the bitwise test below.
    #[derive(Default)]
    struct ScratchBefore {
        order: Vec<usize>,
        lo: Vec<f64>,
        hi: Vec<f64>,
        last: Option<(usize, usize)>,
        boxes: Vec<[f64; 6]>,
    }

    fn least_distance_before(a: &Wire, b: &Wire, scratch: &mut ScratchBefore) -> Option<Closest> {
        let (na, nb) = (a.segments(), b.segments());
        // Horizontal direction of a's chord (x2 if the chord is vertical).
        let (pa, pz) = (a.position(0), a.position(na));
        let h = [pz[0] - pa[0], pz[1] - pa[1]];
        let hn = (h[0] * h[0] + h[1] * h[1]).sqrt();
        let e = if hn > 0.0 { [h[0] / hn, h[1] / hn] } else { [0.0, 1.0] };
        let proj = |w: &Wire, i: usize| e[0] * w.x[0][i] + e[1] * w.x[1][i];
        let ScratchBefore { order, lo, hi, last, boxes } = scratch;
        lo.clear();
        hi.clear();
        boxes.clear();
        boxes.extend((0..nb).map(|j| segment_box(b.position(j), b.position(j + 1))));
        let mut ext_b = 0.0_f64;
        for j in 0..nb {
            let (p, q) = (proj(b, j), proj(b, j + 1));
            lo.push(p.min(q));
            hi.push(p.max(q));
            ext_b = ext_b.max((p - q).abs());
        }
        // The intact segments sorted by `lo`: insertion sort from the last order (nearly sorted after one
        // step: linear time), rebuilt when the segments changed (a break).
        let intact = (0..nb).filter(|&j| b.intact[j] > 0.0).count();
        if order.len() != intact || order.iter().any(|&j| j >= nb || b.intact[j] <= 0.0) {
            order.clear();
            order.extend((0..nb).filter(|&j| b.intact[j] > 0.0));
        }
        for i in 1..order.len() {
            let (v, key) = (order[i], lo[order[i]]);
            let mut k = i;
            while k > 0 && lo[order[k - 1]].total_cmp(&key).is_gt() {
                order[k] = order[k - 1];
                k -= 1;
            }
            order[k] = v;
        }
        if order.is_empty() || a.intact.iter().all(|&x| x <= 0.0) {
            return None;
        }
        // Upper bound: the distance between a few corresponding nodes.
        let mut best2 = f64::INFINITY;
        let mut found: Option<Closest> = None;
        let dist2 = |p: [f64; 3], q: [f64; 3]| (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2);
        // Only points of the polylines may bound: nodes on an intact segment, and the last closest pair if
        // both its segments are still intact (a chord across a break is not part of the conductor).
        let on_intact =
            |w: &Wire, i: usize| (i > 0 && w.intact[i - 1] > 0.0) || (i < w.segments() && w.intact[i] > 0.0);
        for k in 0..=8 {
            let (i, j) = (k * na / 8, k * nb / 8);
            if on_intact(a, i) && on_intact(b, j) {
                best2 = best2.min(dist2(a.position(i), b.position(j)));
            }
        }
        if let Some((i, j)) = *last
            && i < na
            && j < nb
            && a.intact[i] > 0.0
            && b.intact[j] > 0.0
        {
            let (d2, _, _) = closest_points(a.position(i), a.position(i + 1), b.position(j), b.position(j + 1));
            best2 = best2.min(d2);
        }
        // Slightly above the bound so that the pair that attains it is visited.
        let mut best = best2.sqrt() * (1.0 + 1e-12) + 1e-300;
        // Where the two windows of `order` started for the last segment of `a`; `lo` without a NaN (else
        // the windows are found by binary search, as `partition_point` did).
        let (mut first_at, mut last_at) = (0, 0);
        let sorted = !lo.iter().any(|v| v.is_nan());
        // The box bound's margin ([`box_gap2`]), from the largest coordinate magnitude of both conductors.
        let largest = |w: &Wire| w.x.iter().flatten().fold(0.0_f64, |m, &v| if v.abs() > m { v.abs() } else { m });
        let slack = 1.0e-9 * (1.0 + largest(a).max(largest(b)));
        for i in 0..na {
            if a.intact[i] <= 0.0 {
                continue;
            }
            let (p, q) = (proj(a, i), proj(a, i + 1));
            let (alo, ahi) = (p.min(q), p.max(q));
            // The same indices as `order.partition_point`, found by walking from the previous segment's
            // (`lo` is sorted along `order`, so each predicate holds on a prefix: its partition point is
            // unique): a few steps where `a` runs along the chord, a binary search beyond.
            let (below, above) = (alo - best - ext_b, ahi + best);
            let first = walk_partition_before(order, |j| lo[j] < below, &mut first_at, sorted);
            let last = walk_partition_before(order, |j| lo[j] <= above, &mut last_at, sorted);
            let (p0, p1) = (a.position(i), a.position(i + 1));
            let p_box = segment_box(p0, p1);
            for &j in &order[first..last.max(first)] {
                if lo[j] > ahi + best || hi[j] < alo - best {
                    continue;
                }
                // A pair whose computed distance cannot be below the best so far would not be taken: passed
                // over without computing it.
                if found.is_some() && box_gap2_before(&p_box, &boxes[j], slack) > best2 {
                    continue;
                }
                let (q0, q1) = (b.position(j), b.position(j + 1));
                let (d2, s, u) = closest_points(p0, p1, q0, q1);
                if found.is_none() || d2 < best2 {
                    best2 = d2;
                    best = d2.sqrt();
                    let at = |x: [f64; 3], y: [f64; 3], f: f64| [0, 1, 2].map(|k| x[k] + f * (y[k] - x[k]));
                    found = Some(Closest {
                        distance_m: best,
                        segment_a: i,
                        fraction_a: s,
                        segment_b: j,
                        fraction_b: u,
                        point_a_m: at(p0, p1, s),
                        point_b_m: at(q0, q1, u),
                    });
                }
            }
        }
        *last = found.map(|c| (c.segment_a, c.segment_b));
        found
    }

    #[inline]
    fn box_gap2_before(p: &[f64; 6], q: &[f64; 6], slack: f64) -> f64 {
        let mut g2 = 0.0;
        for k in 0..3 {
            let (plo, phi, qlo, qhi) = (p[2 * k], p[2 * k + 1], q[2 * k], q[2 * k + 1]);
            let (after, before) = (qlo - phi, plo - qhi);
            let gap = if after > before { after } else { before } - slack;
            if gap > 0.0 {
                g2 += gap * gap;
            }
        }
        g2 * (1.0 - 1.0e-9)
    }

    #[inline]
    fn walk_partition_before(order: &[usize], pred: impl Fn(usize) -> bool, at: &mut usize, sorted: bool) -> usize {
        const STEPS: usize = 8;
        let n = order.len();
        let mut k = (*at).min(n);
        if sorted {
            if k < n && pred(order[k]) {
                // forwards: the answer is after k
                let stop = (k + STEPS).min(n);
                k += 1;
                while k < stop && pred(order[k]) {
                    k += 1;
                }
                if k < n && k == stop && pred(order[k]) {
                    k = order.partition_point(|&j| pred(j));
                }
            } else {
                // backwards: the answer is k or before
                let stop = k.saturating_sub(STEPS);
                while k > stop && !pred(order[k - 1]) {
                    k -= 1;
                }
                if k > 0 && k == stop && !pred(order[k - 1]) {
                    k = order.partition_point(|&j| pred(j));
                }
            }
        } else {
            k = order.partition_point(|&j| pred(j));
        }
        *at = k;
        k
    }

    /// The pruned search gives the bits of the one it replaced (the same pairs computed in the same
    /// order): two conductors of 30 to 130 segments, parallel, crossing, sagging and swinging over 300
    /// levels with the scratch kept, segments broken on the way, at coordinates up to 1e4 m.
    #[test]
    fn least_distance_is_bitwise_the_previous_search() {
        let mut rnd = crate::test_rng::symmetric(0x9e37_79b9_7f4a_7c15_u64);
        let mut compared = 0;
        for case in 0..24 {
            let (na, nb) = (30 + 17 * (case % 6), 30 + 23 * (case % 5));
            let offset = [1e-3, 0.5, 7.0, 1e4][case % 4];
            let mut a = straight(0.0, 10.0, na, 400.0, 0.0);
            let mut b = straight(offset, 10.0 + 0.3 * offset, nb, 400.0, 3.0 * rnd());
            let (mut new, mut before) = (Scratch::default(), ScratchBefore::default());
            for level in 0..300 {
                let t = level as f64 * 0.01;
                for (w, n, amp) in [(&mut a, na, 1.0), (&mut b, nb, 1.7)] {
                    for i in 0..=n {
                        let s = i as f64 / n as f64;
                        let bump = 4.0 * s * (1.0 - s);
                        w.x[0][i] += amp * 0.02 * bump * (3.0 * t + s).sin() + 1e-4 * rnd();
                        w.x[2][i] -= amp * 0.01 * bump * (2.0 * t).cos() + 1e-4 * rnd();
                        if case % 3 == 2 {
                            // crossing: b turns across a
                            w.x[1][i] += 0.05 * amp * (s - 0.5) * (t + s).sin();
                        }
                    }
                }
                if level == 150 && case % 2 == 1 {
                    b.break_segment(nb / 3);
                    a.break_segment(na / 2);
                }
                let got = least_distance(&a, &b, &mut new);
                let want = least_distance_before(&a, &b, &mut before);
                let bits = |c: Option<Closest>| {
                    c.map(|c| {
                        let f = [c.distance_m, c.fraction_a, c.fraction_b].map(f64::to_bits);
                        (f, c.segment_a, c.segment_b, c.point_a_m.map(f64::to_bits), c.point_b_m.map(f64::to_bits))
                    })
                };
                assert_eq!(bits(got), bits(want), "case {case}, level {level}");
                compared += 1;
            }
        }
        assert_eq!(compared, 24 * 300);
    }

    /// Every pair of segments, for comparison.
    fn brute(a: &Wire, b: &Wire) -> f64 {
        let mut best = f64::INFINITY;
        for i in 0..a.segments() {
            for j in 0..b.segments() {
                let (d2, _, _) = closest_points(a.position(i), a.position(i + 1), b.position(j), b.position(j + 1));
                best = best.min(d2.sqrt());
            }
        }
        best
    }

    #[test]
    fn pruned_search_equals_all_pairs() {
        let mut scratch = Scratch::default();
        // Parallel, offset and with different segment counts; then one sagging and swinging.
        let a = straight(0.0, 10.0, 40, 300.0, 0.0);
        let mut b = straight(6.0, 12.0, 33, 300.0, 5.0);
        let c = least_distance(&a, &b, &mut scratch).unwrap();
        assert!((c.distance_m - brute(&a, &b)).abs() < 1e-12);
        for i in 0..=33 {
            let s = i as f64 / 33.0;
            b.x[2][i] -= 9.0 * 4.0 * s * (1.0 - s);
            b.x[0][i] -= 5.5 * 4.0 * s * (1.0 - s) + 0.3 * (7.0 * s).sin();
        }
        let c = least_distance(&a, &b, &mut scratch).unwrap();
        assert!((c.distance_m - brute(&a, &b)).abs() < 1e-12, "{} vs {}", c.distance_m, brute(&a, &b));
        let (pa, pb) = (c.point_a_m, c.point_b_m);
        let d = ((pa[0] - pb[0]).powi(2) + (pa[1] - pb[1]).powi(2) + (pa[2] - pb[2]).powi(2)).sqrt();
        assert!((d - c.distance_m).abs() < 1e-12);
        // A broken segment is no longer part of the conductor.
        b.break_segment(c.segment_b);
        let c2 = least_distance(&a, &b, &mut scratch).unwrap();
        assert!(c2.distance_m >= c.distance_m);
    }

    /// The box bound never exceeds the squared distance `closest_points` computes, over pseudo-random
    /// segment pairs near and far, at coordinates up to 1e5 m, parallel and crossing, and it is close to
    /// it for segments apart along one axis.
    #[test]
    fn box_gap_is_below_the_computed_distance() {
        let mut rnd = crate::test_rng::uniform(0x9e37_79b9_7f4a_7c15_u64);
        for n in 0..20000 {
            let scale = [1.0, 1e3, 1e5][n % 3];
            let spread = [1e-6, 1.0, 30.0][(n / 3) % 3];
            let base = [rnd() * scale, rnd() * scale, rnd() * scale];
            let mut pt = || [0, 1, 2].map(|k| base[k] + spread * (rnd() - 0.5));
            let (p0, p1, q0) = (pt(), pt(), pt());
            let q1 = if n % 5 == 0 { [0, 1, 2].map(|k| q0[k] + p1[k] - p0[k]) } else { pt() };
            let (d2, _, _) = closest_points(p0, p1, q0, q1);
            let size = [p0, p1, q0, q1].iter().flatten().fold(0.0_f64, |m, v| m.max(v.abs()));
            let bound = box_gap2(&segment_box(p0, p1), &segment_box(q0, q1), 1e-9 * (1.0 + size));
            assert!(bound <= d2, "{p0:?} {p1:?} {q0:?} {q1:?}");
        }
        let (p0, p1, q0, q1) = ([0.0, 0.0, 10.0], [0.0, 10.0, 10.0], [0.0, 13.0, 10.0], [0.0, 23.0, 10.0]);
        assert!((box_gap2(&segment_box(p0, p1), &segment_box(q0, q1), 1e-9 * 24.0) - 9.0).abs() < 1e-6);
        assert_eq!(closest_points(p0, p1, q0, q1).0, 9.0);
    }

    /// The walk finds `partition_point`'s index from any previous answer, over sorted keys with ties and
    /// for thresholds below, inside and above them (and by binary search where not `sorted`).
    #[test]
    fn walk_partition_is_partition_point() {
        let keys = [-3.0, -1.0, -1.0, 0.0, 0.5, 2.0, 2.0, 2.0, 7.0, 9.0, 9.5, 10.0, 11.0, 30.0, 31.0, 40.0, 41.0];
        for x in [-10.0, -3.0, -1.0, 0.25, 2.0, 8.0, 10.0, 10.5, 35.0, 41.0, 100.0] {
            for at in 0..=keys.len() + 2 {
                let want = keys.partition_point(|&v| v < x);
                let mut a = at;
                assert_eq!(walk_partition(&keys, |v| v < x, &mut a, true), want, "{x} from {at}");
                assert_eq!(a, want);
                let want = keys.partition_point(|&v| v <= x);
                let mut a = at;
                assert_eq!(walk_partition(&keys, |v| v <= x, &mut a, false), want);
                let mut a = at;
                assert_eq!(walk_partition(&keys, |v| v <= x, &mut a, true), want, "{x} from {at}");
            }
        }
    }

    /// The bounded tracker finds the same least distance, time and place as measuring every level, over
    /// an oscillation that comes back near its minimum many times, and measures fewer levels.
    #[test]
    fn bounded_tracking_misses_no_minimum() {
        let a = straight(0.0, 10.0, 30, 300.0, 0.0);
        let mut b = straight(3.0, 10.0, 30, 300.0, 0.0);
        let (mut every, mut bounded) =
            (ClearanceTracker::new(vec![vec![0], vec![1]]), ClearanceTracker::new(vec![vec![0], vec![1]]));
        for step in 0..4000 {
            let t = step as f64 * 1e-3;
            for i in 0..=30 {
                let s = i as f64 / 30.0;
                // a swing of slowly decaying amplitude with a faster ripple
                let amp = (1.0 + 0.5 * (t * 0.7).sin()) * (-(t * 0.2)).exp();
                b.x[0][i] =
                    3.0 - 2.0 * amp * (4.0 * s * (1.0 - s)) * (t * 9.0).cos().abs() + 0.01 * (37.0 * t).sin() * s;
            }
            every.observe(&[&a, &b], t);
            bounded.observe_bounded(&[&a, &b], t, step % 500 == 0);
        }
        let (e, g) = (every.least()[0].unwrap(), bounded.least()[0].unwrap());
        assert_eq!(e.time_s, g.time_s);
        assert_eq!(e.closest, g.closest);
        assert!(bounded.counts.0 < bounded.counts.1, "measured {} of {} levels", bounded.counts.0, bounded.counts.1);
    }

    #[test]
    fn tracker_keeps_the_least_and_its_time() {
        let a = straight(0.0, 10.0, 20, 200.0, 0.0);
        let mut b = straight(3.0, 10.0, 20, 200.0, 0.0);
        let mut t = ClearanceTracker::new(vec![vec![0], vec![1]]);
        t.observe(&[&a, &b], 0.0);
        b.x[0][10] = 1.0;
        t.observe(&[&a, &b], 0.5);
        b.x[0][10] = 2.0;
        t.observe(&[&a, &b], 1.0);
        let least = t.least()[0].unwrap();
        assert_eq!(least.time_s, 0.5);
        assert!((least.closest.distance_m - 1.0).abs() < 1e-12);
        assert!((least.closest.arc_fraction_a(&a) - 0.5).abs() < 1e-12);
        assert!((t.current()[0].unwrap().closest.distance_m - 2.0).abs() < 1e-12);
    }
}
