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

    /// The lowest vertical clearance of nodes `range` of `x` (positions `[x1, x2, x3]` [m]) [m].
    pub fn least_clearance_m(&self, x: &[Vec<f64>; 3], range: std::ops::RangeInclusive<usize>) -> f64 {
        range.map(|i| x[2][i] - self.height_at(x[1][i])).fold(f64::INFINITY, f64::min)
    }
}

/// Apply the contact law to every node of `x`, `v` (positions [m], velocities [m/s]); a node in contact
/// gets `exposed = 0`.
pub fn apply(g: &Ground, x: &mut [Vec<f64>; 3], v: &mut [Vec<f64>; 3], exposed: &mut [f64]) {
    let e = g.restitution;
    for i in 0..exposed.len() {
        if g.profile_m.is_empty() {
            // The level plane: the normal is x3.
            if x[2][i] < g.height_m {
                x[2][i] = g.height_m;
                if v[2][i] < 0.0 {
                    let normal = (1.0 + e) * -v[2][i];
                    v[2][i] *= -e;
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
            continue;
        }
        let (h, slope) = g.surface(x[1][i]);
        if x[2][i] >= h {
            continue;
        }
        // Unit normal (0, n2, n3) of the piece; the depth below it along the normal.
        let inv = 1.0 / (1.0 + slope * slope).sqrt();
        let (n2, n3) = (-slope * inv, inv);
        let depth = (h - x[2][i]) * inv;
        x[1][i] += depth * n2;
        x[2][i] += depth * n3;
        let vn = v[1][i] * n2 + v[2][i] * n3;
        if vn < 0.0 {
            let normal = (1.0 + e) * -vn;
            // tangential part before the reflection
            let t = [v[0][i], v[1][i] - vn * n2, v[2][i] - vn * n3];
            let vt = (t[0] * t[0] + t[1] * t[1] + t[2] * t[2]).sqrt();
            let keep = if g.friction > 0.0 && vt > 0.0 { (1.0 - g.friction * normal / vt).max(0.0) } else { 1.0 };
            let vn_after = -e * vn;
            v[0][i] = keep * t[0];
            v[1][i] = keep * t[1] + vn_after * n2;
            v[2][i] = keep * t[2] + vn_after * n3;
        }
        exposed[i] = 0.0;
    }
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
