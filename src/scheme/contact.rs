//! Ground contact (section 4.4): a level plane `x3 = h`, or a terrain profile `x3 = h(x2)` piecewise
//! linear along the line's horizontal coordinate `x2` (flat beyond its first and last points).
//!
//! After the drift, a node below the surface is projected onto it along the surface normal
//! `n = (0, -h', 1) / sqrt(1 + h'^2)` of the piece it lies over, and if it moves into the surface
//! (`v . n < 0`) its normal velocity is reflected with the restitution coefficient `e`:
//!
//! ```text
//! v_n' = -e v_n,     |v_t'| = max(|v_t| - mu_g (1 + e) |v_n|, 0),
//! ```
//!
//! the second being Coulomb's law for impulses: the normal impulse per unit mass is `(1 + e) |v_n|`, the
//! tangential one at most `mu_g` times that and no more than stops the node (friction never reverses
//! it). From then on no distributed load acts on the node (section 4.4, assumption b). On a level plane
//! (`h' = 0`) the normal is vertical and the update is the same as the plane's, which keeps its exact
//! arithmetic (the paper cases' outputs do not change).
//!
//! Ground clearance, as line engineers state it, is vertical: `x3 - h(x2)` ([`Ground::clearance_m`]).

/// The ground: a level plane or a terrain profile, with its contact law.
#[derive(Clone, Debug, PartialEq)]
pub struct Ground {
    /// height of the level ground `x3` [m] (used where `profile_m` is empty)
    pub height_m: f64,
    /// coefficient of restitution on the normal velocity `e` [-], in [0, 1]
    pub restitution: f64,
    /// Coulomb friction coefficient `mu_g` [-]: the contact's tangential impulse is at most `mu_g` times
    /// its normal impulse (0: frictionless)
    pub friction: f64,
    /// terrain profile: points `[x2, x3]` [m] with strictly increasing `x2`, the ground piecewise linear
    /// between them and level beyond the ends; empty for the level plane `height_m`
    pub profile_m: Vec<[f64; 2]>,
}

impl Ground {
    /// A level plane `x3 = height_m` [m] with restitution `e` [-] and friction `mu_g` [-].
    pub fn level(height_m: f64, restitution: f64, friction: f64) -> Self {
        Ground { height_m, restitution, friction, profile_m: Vec::new() }
    }

    /// The ground height `h(x2)` [m] and its slope `h'(x2)` [-] below the horizontal coordinate `x2` [m].
    #[inline]
    pub fn surface(&self, x2: f64) -> (f64, f64) {
        let p = &self.profile_m;
        match p.len() {
            0 => (self.height_m, 0.0),
            1 => (p[0][1], 0.0),
            n => {
                if x2 <= p[0][0] {
                    return (p[0][1], 0.0);
                }
                if x2 >= p[n - 1][0] {
                    return (p[n - 1][1], 0.0);
                }
                // the piece [p[k], p[k + 1]] with p[k].x2 <= x2 < p[k + 1].x2
                let k = p.partition_point(|q| q[0] <= x2) - 1;
                let (a, b) = (p[k], p[k + 1]);
                let slope = (b[1] - a[1]) / (b[0] - a[0]);
                (a[1] + slope * (x2 - a[0]), slope)
            }
        }
    }

    /// The ground height `h(x2)` [m].
    pub fn height_at(&self, x2: f64) -> f64 {
        self.surface(x2).0
    }

    /// Vertical clearance of the point `x` [m] above the ground, `x3 - h(x2)` [m].
    pub fn clearance_m(&self, x: [f64; 3]) -> f64 {
        x[2] - self.height_at(x[1])
    }

    /// The lowest vertical clearance of nodes `range` of `x` (positions `[x1, x2, x3]` [m]) [m]:
    /// `min_i (x3_i - h(x2_i))` over the range (`+inf` for an empty range or nodes all at NaN).
    ///
    /// Observed at every time level of a section run (per span, for its least clearance), so over the
    /// level plane it is a tight loop over `x3` in [`LANES`] independent minima, vectorised by the
    /// compiler. A minimum of floating-point numbers is exact, so any order gives the same number except
    /// for the sign of a zero (`min(0, -0)`): if the minimum is zero and some clearance is `-0` it is
    /// taken again in node order, so the result is bitwise that of the node-by-node fold
    /// ([`Ground::least_clearance_in_order_m`]; a conductor lying on the ground has clearances `+0`).
    ///
    /// A clearance `z - h` is `-0` only for `z = -0` and `h = +0`: in round to nearest the difference of
    /// equal numbers is `+0`, `-0 - (+0) = -0`, `-0 - (-0) = +0`, and a difference is zero only where the
    /// numbers are equal. So the zeros' signs are looked at only where the minimum is zero over ground at
    /// `+0`, and then as the positions' bits (the clearance is the height itself).
    pub fn least_clearance_m(&self, x: &[Vec<f64>; 3], range: std::ops::RangeInclusive<usize>) -> f64 {
        if !self.profile_m.is_empty() || range.is_empty() {
            return self.least_clearance_in_order_m(x, range);
        }
        let z = &x[2][range.clone()];
        #[cfg(target_arch = "x86_64")]
        let least = if super::explicit::avx2_available() {
            // SAFETY: the processor reports AVX2 (`avx2_available`).
            unsafe { least_above_plane_avx2(z, self.height_m) }
        } else {
            least_above_plane(z, self.height_m)
        };
        #[cfg(not(target_arch = "x86_64"))]
        let least = least_above_plane(z, self.height_m);
        least.unwrap_or_else(|| self.least_clearance_in_order_m(x, range))
    }

    /// [`Ground::least_clearance_m`] node by node, in node order: the definition.
    pub fn least_clearance_in_order_m(&self, x: &[Vec<f64>; 3], range: std::ops::RangeInclusive<usize>) -> f64 {
        range.map(|i| x[2][i] - self.height_at(x[1][i])).fold(f64::INFINITY, f64::min)
    }

    /// A height at or above the ground everywhere: the level plane's height, or the profile's highest
    /// point plus a margin of `1e-6 (1 + max |h|)` m, far above the rounding of the interpolation
    /// `a + s (x2 - a2)` in [`Ground::surface`] (a few units in the last place of `max |h|`), so that a
    /// node at or above it is above the surface wherever it is ([`apply`] skips it).
    fn ceiling_m(&self) -> f64 {
        if self.profile_m.is_empty() {
            return self.height_m;
        }
        let top = self.profile_m.iter().map(|p| p[1]).fold(f64::NEG_INFINITY, f64::max);
        let size = self.profile_m.iter().map(|p| p[1].abs()).fold(0.0, f64::max);
        top + 1.0e-6 * (1.0 + size)
    }
}

/// Independent accumulators of the tight loops over nodes ([`lanes_min`], [`apply`]'s scan): enough for
/// the compiler to keep a vector register of them.
const LANES: usize = 8;

/// `min_i f(z_i)` (`+inf` for an empty slice; a NaN is passed over as [`f64::min`] does), in [`LANES`]
/// independent minima: equal to the fold of [`f64::min`] in order bitwise unless the minimum is zero and
/// some `f(z_i)` is `-0` (a minimum is exact; only the sign of a zero can depend on the order). `if y < m`
/// passes over a NaN as [`f64::min`] does (the lanes start at `+inf` and never hold one).
fn lanes_min(z: &[f64], f: impl Fn(f64) -> f64) -> f64 {
    let mut m = [f64::INFINITY; LANES];
    let chunks = z.chunks_exact(LANES);
    let rest = chunks.remainder();
    for c in chunks {
        for k in 0..LANES {
            let y = f(c[k]);
            m[k] = if y < m[k] { y } else { m[k] };
        }
    }
    let mut least = f64::INFINITY;
    for &v in rest {
        least = least.min(f(v));
    }
    for v in m {
        least = least.min(v);
    }
    least
}

/// The least clearance `min_i (z_i - h)` [m] of heights `z` [m] above the level plane `h` [m] in
/// [`lanes_min`], or `None` where the node-order fold is needed for the sign of a zero: the minimum is
/// zero, the ground at `+0` and some `z_i` is `-0` (its bits compared as an integer, in one pass without
/// early exit, which the compiler vectorises; [`Ground::least_clearance_m`]).
#[inline(always)]
fn least_above_plane(z: &[f64], h: f64) -> Option<f64> {
    let least = lanes_min(z, |z| z - h);
    let negative_zero = || z.iter().fold(false, |any, z| any | (z.to_bits() == (-0.0_f64).to_bits()));
    if least == 0.0 && h.to_bits() == 0 && negative_zero() { None } else { Some(least) }
}

/// [`least_above_plane`] compiled for AVX2 (minima and comparisons are exact: the same result).
///
/// # Safety
/// Only where the processor has AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn least_above_plane_avx2(z: &[f64], h: f64) -> Option<f64> {
    least_above_plane(z, h)
}

/// Apply the contact law to every node of `x`, `v` (positions [m], velocities [m/s]); a node in contact
/// gets `exposed = 0`.
///
/// Called after every drift, so the nodes are first scanned in blocks of [`LANES`] with one branch-free
/// test each: a node at or above [`Ground::ceiling_m`] (`x3 >= ceiling`; over the level plane exactly
/// the negation of the contact test `x3 < h`) is not in contact and is passed over; the others go
/// through the contact law one by one, in node order, as before. Nodes do not interact here, so the
/// result is bitwise that of the loop over every node. The seven arrays are sliced to one length once,
/// so one comparison per node stands for the bounds checks of all of them.
#[allow(clippy::neg_cmp_op_on_partial_ord, reason = "`!(z >= ceiling)` is meant to hold for a NaN too")]
pub fn apply(g: &Ground, x: &mut [Vec<f64>; 3], v: &mut [Vec<f64>; 3], exposed: &mut [f64]) {
    let mut nodes = Nodes::of(x, v, exposed);
    let n = nodes.exposed.len();
    let ceiling = g.ceiling_m();
    let mut start = 0;
    while start < n {
        // One bit per node of the block below the ceiling; `!(z >= ceiling)` also flags a NaN, which the
        // node-by-node law handles as it always did.
        let mut below = 0_u32;
        if start + LANES <= n {
            let block: &[f64; LANES] = nodes.x3[start..start + LANES].try_into().expect("a block of LANES nodes");
            for (k, &z) in block.iter().enumerate() {
                below |= u32::from(!(z >= ceiling)) << k;
            }
        } else {
            for (k, &z) in nodes.x3[start..n].iter().enumerate() {
                below |= u32::from(!(z >= ceiling)) << k;
            }
        }
        let end = (start + LANES).min(n);
        while below != 0 {
            contact_node(g, &mut nodes, start + below.trailing_zeros() as usize);
            below &= below - 1;
        }
        start = end;
    }
}

/// The nodes' positions [m], velocities [m/s] and exposure [-] as slices of one length.
struct Nodes<'a> {
    x2: &'a mut [f64],
    x3: &'a mut [f64],
    v1: &'a mut [f64],
    v2: &'a mut [f64],
    v3: &'a mut [f64],
    exposed: &'a mut [f64],
}

impl<'a> Nodes<'a> {
    fn of(x: &'a mut [Vec<f64>; 3], v: &'a mut [Vec<f64>; 3], exposed: &'a mut [f64]) -> Self {
        let n = exposed.len();
        let [_, x2, x3] = x;
        let [v1, v2, v3] = v;
        Nodes {
            x2: &mut x2[..n],
            x3: &mut x3[..n],
            v1: &mut v1[..n],
            v2: &mut v2[..n],
            v3: &mut v3[..n],
            exposed: &mut exposed[..n],
        }
    }
}

/// The squared horizontal speeds [m^2/s^2] between which [`friction_keep`] decides without `hypot`: the
/// squares neither overflow nor lose more than `2^-1074` to underflow (relative `1e-43` of the sum).
const SQUARES_ABOVE: f64 = 1e-280;
const SQUARES_BELOW: f64 = 1e280;

/// The relative margin by which the friction's impulse must exceed `sqrt(v1^2 + v2^2)` for
/// [`friction_keep`] to stop the node without `hypot`: far above the roundings between that square root
/// and `hypot` (a few units of `u = 2^-53`).
const STOP_MARGIN: f64 = 1e-12;

/// The level plane's friction factor `keep = max(1 - q / |v_t|, 0)`, `|v_t| = hypot(v1, v2)` [m/s] the
/// speed along the plane and `q = mu_g (1 + e) |v_3|` [m/s] the largest tangential impulse per unit
/// mass; `None` where `|v_t| = 0` (the law leaves the node's velocity alone then).
///
/// `hypot` is a library call of a few dozen instructions, taken at every node lying on the ground at
/// every step. Two cases are decided without it, with the same result bit for bit:
/// - `v1 = v2 = 0` (either sign): `hypot` is `+0`, so `None`;
/// - the friction stops the node, `q >= r (1 + 1e-12)` with `r = sqrt(v1^2 + v2^2)`: for squares between
///   [`SQUARES_ABOVE`] and [`SQUARES_BELOW`], `r` is within `(1 + u)^(3/2) (1 + u) - 1 < 3u` of the exact
///   `|v_t|` and `hypot` within a few `u` (glibc states at most one ulp), so `q / hypot(v1, v2)` is above
///   `1 + 1e-12 / 2` and rounds above 1; `1 - q / |v_t|` is then negative, not zero, and its maximum with
///   `+0` is `+0` exactly (no question of the sign of a zero).
///
/// Elsewhere (a sliding node, non-finite or extreme speeds) `hypot` is formed as the law states.
#[inline]
fn friction_keep(v1: f64, v2: f64, q: f64) -> Option<f64> {
    if v1 == 0.0 && v2 == 0.0 {
        return None;
    }
    let s = v1 * v1 + v2 * v2;
    if (SQUARES_ABOVE..=SQUARES_BELOW).contains(&s) && q >= s.sqrt() * (1.0 + STOP_MARGIN) {
        return Some(0.0);
    }
    let vt = v1.hypot(v2);
    (vt > 0.0).then(|| (1.0 - q / vt).max(0.0))
}

/// The contact law at node `i` ([`apply`]).
#[inline]
fn contact_node(g: &Ground, nodes: &mut Nodes, i: usize) {
    let Nodes { x2, x3, v1, v2, v3, exposed } = nodes;
    let e = g.restitution;
    if g.profile_m.is_empty() {
        // The level plane: the normal is x3.
        if x3[i] < g.height_m {
            x3[i] = g.height_m;
            if v3[i] < 0.0 {
                let normal = (1.0 + e) * -v3[i];
                v3[i] *= -e;
                if g.friction > 0.0
                    && let Some(keep) = friction_keep(v1[i], v2[i], g.friction * normal)
                {
                    v1[i] *= keep;
                    v2[i] *= keep;
                }
            }
            exposed[i] = 0.0;
        }
        return;
    }
    let (h, slope) = g.surface(x2[i]);
    if x3[i] >= h {
        return;
    }
    // Unit normal (0, n2, n3) of the piece; the depth below it along the normal.
    let inv = 1.0 / (1.0 + slope * slope).sqrt();
    let (n2, n3) = (-slope * inv, inv);
    let depth = (h - x3[i]) * inv;
    x2[i] += depth * n2;
    x3[i] += depth * n3;
    let vn = v2[i] * n2 + v3[i] * n3;
    if vn < 0.0 {
        let normal = (1.0 + e) * -vn;
        // tangential part before the reflection
        let t = [v1[i], v2[i] - vn * n2, v3[i] - vn * n3];
        let vt = (t[0] * t[0] + t[1] * t[1] + t[2] * t[2]).sqrt();
        let keep = if g.friction > 0.0 && vt > 0.0 { (1.0 - g.friction * normal / vt).max(0.0) } else { 1.0 };
        let vn_after = -e * vn;
        v1[i] = keep * t[0];
        v2[i] = keep * t[1] + vn_after * n2;
        v3[i] = keep * t[2] + vn_after * n3;
    }
    exposed[i] = 0.0;
}

#[cfg(test)]
mod tests {
    use super::*;

    fn terrain() -> Ground {
        Ground { profile_m: vec![[0.0, 0.0], [100.0, 10.0], [200.0, 10.0]], ..Ground::level(0.0, 0.5, 0.3) }
    }

    #[test]
    fn profile_interpolates_and_is_level_beyond_its_ends() {
        let g = terrain();
        assert_eq!(g.surface(-5.0), (0.0, 0.0));
        assert_eq!(g.surface(50.0), (5.0, 0.1));
        assert_eq!(g.surface(100.0), (10.0, 0.0));
        assert_eq!(g.surface(250.0), (10.0, 0.0));
        assert_eq!(g.clearance_m([0.0, 50.0, 12.0]), 7.0);
    }

    /// On a slope the node ends on the surface, its normal velocity is reflected with `e` and its
    /// tangential speed falls by `mu_g (1 + e) |v_n|`.
    #[test]
    fn contact_on_a_slope_reflects_along_the_normal() {
        let g = terrain();
        let mut x = [vec![0.0], vec![50.0], vec![4.0]];
        let v0 = [1.0, 2.0, -3.0];
        let mut v = [vec![v0[0]], vec![v0[1]], vec![v0[2]]];
        let mut exposed = [1.0];
        apply(&g, &mut x, &mut v, &mut exposed);
        let s = 0.1_f64;
        let n = [0.0, -s / (1.0 + s * s).sqrt(), 1.0 / (1.0 + s * s).sqrt()];
        // on the plane x3 = 5 + 0.1 (x2 - 50) through the piece
        assert!((x[2][0] - (5.0 + s * (x[1][0] - 50.0))).abs() < 1e-12);
        let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let vn0 = dot(v0, n);
        let v1 = [v[0][0], v[1][0], v[2][0]];
        assert!((dot(v1, n) + 0.5 * vn0).abs() < 1e-12);
        let tang = |a: [f64; 3]| {
            let an = dot(a, n);
            let t = [a[0] - an * n[0], a[1] - an * n[1], a[2] - an * n[2]];
            dot(t, t).sqrt()
        };
        assert!((tang(v1) - (tang(v0) - 0.3 * 1.5 * -vn0)).abs() < 1e-12);
        assert_eq!(exposed[0], 0.0);
    }

    /// The contact law before its scan: every node in turn, the level plane's friction with `hypot`
    /// formed at every node as the law states it (no [`friction_keep`]).
    fn apply_node_by_node(g: &Ground, x: &mut [Vec<f64>; 3], v: &mut [Vec<f64>; 3], exposed: &mut [f64]) {
        for i in 0..exposed.len() {
            if !g.profile_m.is_empty() {
                contact_node(g, &mut Nodes::of(x, v, exposed), i);
                continue;
            }
            if x[2][i] < g.height_m {
                x[2][i] = g.height_m;
                if v[2][i] < 0.0 {
                    let normal = (1.0 + g.restitution) * -v[2][i];
                    v[2][i] *= -g.restitution;
                    if g.friction > 0.0 {
                        let vt = v[0][i].hypot(v[1][i]);
                        if vt > 0.0 {
                            let keep = (1.0 - g.friction * normal / vt).max(0.0);
                            v[0][i] *= keep;
                            v[1][i] *= keep;
                        }
                    }
                }
                exposed[i] = 0.0;
            }
        }
    }

    /// A state of `n` nodes around the ground (some below it, some exactly on it, one NaN far from it)
    /// from a small deterministic generator.
    fn scattered(n: usize, seed: u64) -> ([Vec<f64>; 3], [Vec<f64>; 3]) {
        let mut r = seed;
        let mut next = move || {
            r = r.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (r >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut x = [vec![0.0; n], vec![0.0; n], vec![0.0; n]];
        let mut v = [vec![0.0; n], vec![0.0; n], vec![0.0; n]];
        for i in 0..n {
            x[0][i] = next() - 0.5;
            x[1][i] = 250.0 * next() - 25.0;
            x[2][i] = match i % 7 {
                0 => 0.0,
                1 => 10.0,
                _ => 14.0 * next() - 2.0,
            };
            for k in 0..3 {
                v[k][i] = 4.0 * next() - 2.0;
            }
        }
        (x, v)
    }

    /// The scanned contact pass changes exactly what the node-by-node law changes, bit for bit, over the
    /// level plane and a terrain profile, for node counts around the block length.
    #[test]
    fn scanned_contact_equals_the_node_by_node_law() {
        for g in [Ground::level(1.0, 0.3, 0.5), Ground::level(0.0, 0.0, 0.0), terrain()] {
            for n in [0, 1, 7, 8, 9, 16, 61] {
                let (x0, v0) = scattered(n, n as u64 + 3);
                let (mut xa, mut va, mut ea) = (x0.clone(), v0.clone(), vec![1.0; n]);
                let (mut xb, mut vb, mut eb) = (x0, v0, vec![1.0; n]);
                apply(&g, &mut xa, &mut va, &mut ea);
                apply_node_by_node(&g, &mut xb, &mut vb, &mut eb);
                let bits = |a: &[Vec<f64>; 3]| a.iter().flatten().map(|x| x.to_bits()).collect::<Vec<_>>();
                assert_eq!(bits(&xa), bits(&xb), "{g:?} {n}");
                assert_eq!(bits(&va), bits(&vb), "{g:?} {n}");
                assert_eq!(ea, eb);
                assert!(n < 9 || ea.contains(&0.0), "some node was in contact");
            }
        }
    }

    /// The friction factor without `hypot` where it is decided equals the law's with it, bit for bit:
    /// impulses a few roundings either side of the speed along the plane (where the factor goes from
    /// positive to zero), both signs of zero, speeds from `1e-200` to `1e200` m/s, NaN and infinities.
    #[test]
    fn friction_factor_equals_the_one_with_hypot() {
        let stated = |v1: f64, v2: f64, q: f64| {
            let vt = v1.hypot(v2);
            (vt > 0.0).then(|| (1.0 - q / vt).max(0.0))
        };
        let bits = |k: Option<f64>| k.map(f64::to_bits);
        let mut checked = 0;
        let mut decided = 0;
        for scale in [1e-200, 1e-150, 1e-3, 0.07, 1.0, 3.3, 1e5, 1e150, 1e200] {
            for (a, b) in [(1.0, 0.0), (0.0, -1.0), (0.6, 0.8), (-0.3, 0.7), (1e-9, 1.0), (1.0, 1.0 - 1e-15)] {
                let (v1, v2): (f64, f64) = (a * scale, b * scale);
                let vt = v1.hypot(v2);
                for q0 in [vt, 0.5 * vt, 2.0 * vt, 0.0, f64::INFINITY] {
                    let mut q = q0;
                    for _ in 0..60 {
                        decided += usize::from(friction_keep(v1, v2, q) == Some(0.0));
                        assert_eq!(bits(friction_keep(v1, v2, q)), bits(stated(v1, v2, q)), "{v1:e} {v2:e} {q:e}");
                        checked += 1;
                        q = q.next_up();
                    }
                    q = q0;
                    for _ in 0..60 {
                        assert_eq!(bits(friction_keep(v1, v2, q)), bits(stated(v1, v2, q)), "{v1:e} {v2:e} {q:e}");
                        q = q.next_down();
                    }
                }
            }
        }
        for (v1, v2) in
            [(0.0, 0.0), (-0.0, 0.0), (0.0, -0.0), (f64::NAN, 0.0), (f64::INFINITY, f64::NAN), (1.0, f64::INFINITY)]
        {
            for q in [0.0, 1.0, f64::INFINITY] {
                assert_eq!(bits(friction_keep(v1, v2, q)), bits(stated(v1, v2, q)), "{v1:e} {v2:e} {q:e}");
            }
        }
        assert!(decided > checked / 4, "the shortcut decided {decided} of {checked}");
    }

    /// The least clearance in lanes is the node-order fold bit for bit, including its zero's sign
    /// (a node on the ground, one at `-0` over ground at `+0`) and a NaN position (passed over).
    #[test]
    fn least_clearance_equals_the_fold_in_node_order() {
        for g in [Ground::level(1.0, 0.3, 0.5), Ground::level(0.0, 0.2, 0.0), terrain()] {
            for n in [1, 7, 8, 9, 33, 61] {
                let (mut x, _) = scattered(n, 11 * n as u64);
                for variant in 0..4 {
                    match variant {
                        1 => x[2][n / 2] = g.height_at(x[1][n / 2]),
                        2 => x[2][n - 1] = -0.0,
                        3 => x[2][0] = f64::NAN,
                        _ => {}
                    }
                    for range in [0..=n - 1, n / 3..=n - 1, 0..=n / 2] {
                        let (a, b) = (g.least_clearance_m(&x, range.clone()), g.least_clearance_in_order_m(&x, range));
                        assert_eq!(a.to_bits(), b.to_bits(), "{g:?} {n} {variant}: {a} vs {b}");
                    }
                }
            }
        }
        // zeros of both signs as the least clearance, in the lanes and in the remainder, over ground at
        // `+0`, `-0` and 2 m (nodes on it, at `+-0` or at its height)
        for h in [0.0, -0.0, 2.0] {
            let g = Ground::level(h, 0.2, 0.0);
            for (plus, minus) in [(3, 12), (12, 3), (3, 18), (18, 3), (17, 19)] {
                let mut z = vec![h + 1.0; 20];
                (z[plus], z[minus]) = (h, -0.0);
                z[(plus + minus) / 2] = 0.0;
                let x = [vec![0.0; 20], vec![0.0; 20], z];
                let (a, b) = (g.least_clearance_m(&x, 0..=19), g.least_clearance_in_order_m(&x, 0..=19));
                assert_eq!(a.to_bits(), b.to_bits(), "{h} {plus} {minus}");
                assert_eq!(a, 0.0_f64.min(h).min(-h));
            }
        }
        // the lowest node by hand
        let x = [vec![0.0; 3], vec![0.0; 3], vec![5.0, 2.5, 3.0]];
        assert_eq!(Ground::level(1.0, 0.0, 0.0).least_clearance_m(&x, 0..=2), 1.5);
    }

    /// A one-point profile and a flat profile behave as the level plane at that height.
    #[test]
    fn flat_profile_matches_the_plane() {
        let plane = Ground::level(2.0, 0.6, 0.4);
        let flat = Ground { profile_m: vec![[0.0, 2.0], [10.0, 2.0]], ..plane.clone() };
        let mk =
            || ([vec![0.0, 1.0], vec![5.0, 6.0], vec![1.5, 2.5]], [vec![0.5, 0.0], vec![1.0, 0.0], vec![-2.0, -1.0]]);
        let (mut xa, mut va) = mk();
        let (mut xb, mut vb) = mk();
        let (mut ea, mut eb) = ([1.0; 2], [1.0; 2]);
        apply(&plane, &mut xa, &mut va, &mut ea);
        apply(&flat, &mut xb, &mut vb, &mut eb);
        for k in 0..3 {
            for i in 0..2 {
                assert!((xa[k][i] - xb[k][i]).abs() < 1e-15 && (va[k][i] - vb[k][i]).abs() < 1e-15);
            }
        }
        assert_eq!(ea, eb);
    }
}
