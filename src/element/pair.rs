//! Geometry of a pair element: the closest points of two straight segments, `p(s) = p0 + s (p1 - p0)` and
//! `q(u) = q0 + u (q1 - q0)` with `s, u` in `[0, 1]`,
//!
//! ```text
//! minimise |p(s) - q(u)|^2 over the unit square:
//!   a = d1.d1, b = d1.d2, e = d2.d2, c = d1.r, f = d2.r,   d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0,
//!   interior stationary point  s = (b f - c e) / (a e - b^2),  u = (b s + f) / e,
//! ```
//!
//! clamped to the square edge by edge (`u` outside `[0, 1]` fixes `u` at the edge and re-solves for `s`).
//! Parallel segments (`a e - b^2 = 0`) take `s = 0` and the `u` that follows: one of the equally close pairs.
//! Degenerate (point) segments are handled. The least distance between two polylines (two conductors) is
//! the least of these over the segment pairs ([`crate::line::clearance`]).

/// Closest points of the segments `p0 p1` and `q0 q1` [m]: `(distance^2 [m^2], s, u)` with the points
/// `p0 + s (p1 - p0)` and `q0 + u (q1 - q0)`.
pub fn closest_points(p0: [f64; 3], p1: [f64; 3], q0: [f64; 3], q1: [f64; 3]) -> (f64, f64, f64) {
    let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let clamp01 = |x: f64| x.clamp(0.0, 1.0);
    let (d1, d2, r) = (sub(p1, p0), sub(q1, q0), sub(p0, q0));
    let (a, e, f) = (dot(d1, d1), dot(d2, d2), dot(d2, r));
    let (s, u) = if a <= 0.0 && e <= 0.0 {
        (0.0, 0.0)
    } else if a <= 0.0 {
        (0.0, clamp01(f / e))
    } else {
        let c = dot(d1, r);
        if e <= 0.0 {
            (clamp01(-c / a), 0.0)
        } else {
            let b = dot(d1, d2);
            let denom = a * e - b * b;
            let s = if denom > 0.0 { clamp01((b * f - c * e) / denom) } else { 0.0 };
            let u = (b * s + f) / e;
            if u < 0.0 {
                (clamp01(-c / a), 0.0)
            } else if u > 1.0 {
                (clamp01((b - c) / a), 1.0)
            } else {
                (s, u)
            }
        }
    };
    let p = [p0[0] + s * d1[0], p0[1] + s * d1[1], p0[2] + s * d1[2]];
    let q = [q0[0] + u * d2[0], q0[1] + u * d2[1], q0[2] + u * d2[2]];
    let g = sub(p, q);
    (dot(g, g), s, u)
}

/// The nearest point of the segment `q0 q1` to the point `x` [m]: `(distance^2 [m^2], u)` with the point
/// `q0 + u (q1 - q0)`; for a finite `x` the same bits as [`closest_points`]`(x, x, q0, q1)` (its first
/// segment of zero length: `d1 = x - x = 0`, `a = 0`, so `s = 0` and `u = clamp(f / e)`, or 0 for a point
/// `q0 = q1`; its `p = x + 0 * 0` differs from `x` at most in the sign of a zero, which the square
/// removes). A non-finite `x` is passed to [`closest_points`] itself.
#[inline(always)]
pub fn point_segment(x: [f64; 3], q0: [f64; 3], q1: [f64; 3]) -> (f64, f64) {
    if !(x[0].is_finite() && x[1].is_finite() && x[2].is_finite()) {
        let (d2, _, u) = closest_points(x, x, q0, q1);
        return (d2, u);
    }
    let d2 = [q1[0] - q0[0], q1[1] - q0[1], q1[2] - q0[2]];
    let r = [x[0] - q0[0], x[1] - q0[1], x[2] - q0[2]];
    let e = d2[0] * d2[0] + d2[1] * d2[1] + d2[2] * d2[2];
    let f = d2[0] * r[0] + d2[1] * r[1] + d2[2] * r[2];
    let u = if e <= 0.0 { 0.0 } else { (f / e).clamp(0.0, 1.0) };
    let g = [x[0] - (q0[0] + u * d2[0]), x[1] - (q0[1] + u * d2[1]), x[2] - (q0[2] + u * d2[2])];
    (g[0] * g[0] + g[1] * g[1] + g[2] * g[2], u)
}

#[cfg(test)]
mod tests {
    use super::*;
    /// The point version gives the bits of the segment version with a zero-length first segment, over
    /// pseudo-random points and segments (near, far, at coordinates up to 1e5 m, degenerate segments,
    /// zeros of either sign, infinities and NaN).
    #[test]
    fn point_segment_is_closest_points_of_a_point() {
        let mut rnd = crate::test_rng::symmetric(0x9e37_79b9_7f4a_7c15_u64);
        let specials = [0.0, -0.0, f64::INFINITY, f64::NEG_INFINITY, f64::NAN];
        for case in 0..50000 {
            let scale = [1e-3, 1.0, 30.0, 1e5][case % 4];
            let mut pt = || [rnd() * scale, rnd() * scale, rnd() * scale];
            let (mut x, q0, mut q1) = (pt(), pt(), pt());
            match (case / 4) % 5 {
                0 => q1 = q0,
                1 => x = [0, 1, 2].map(|k| q0[k] + 0.5 * (q1[k] - q0[k])),
                2 => x[case % 3] = specials[(case / 20) % specials.len()],
                _ => {}
            }
            let (d2, _, u) = closest_points(x, x, q0, q1);
            let (e2, v) = point_segment(x, q0, q1);
            assert_eq!((e2.to_bits(), v.to_bits()), (d2.to_bits(), u.to_bits()), "case {case}: {x:?} {q0:?} {q1:?}");
        }
    }

    /// Brute force over a 201 x 201 grid of (s, u): the exact minimum is at most the grid's, and the grid's
    /// exceeds it by at most the distance moved by half a grid step on each segment (|d1| + |d2|) / 400.
    #[test]
    fn agrees_with_brute_force_on_pseudo_random_segments() {
        let mut rnd = crate::test_rng::symmetric(0x2545_f491_4f6c_dd1d_u64);
        for case in 0..300 {
            let mut pt = || [rnd(), rnd(), rnd()];
            let (p0, p1, q0, mut q1) = (pt(), pt(), pt(), pt());
            if case % 10 == 0 {
                // parallel
                q1 = [q0[0] + p1[0] - p0[0], q0[1] + p1[1] - p0[1], q0[2] + p1[2] - p0[2]];
            }
            let (d2, s, u) = closest_points(p0, p1, q0, q1);
            assert!((0.0..=1.0).contains(&s) && (0.0..=1.0).contains(&u));
            let at = |a: [f64; 3], b: [f64; 3], x: f64| [0, 1, 2].map(|k| a[k] + x * (b[k] - a[k]));
            let dist = |s: f64, u: f64| {
                let (p, q) = (at(p0, p1, s), at(q0, q1, u));
                ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
            };
            assert!((dist(s, u) - d2.sqrt()).abs() < 1e-12);
            let mut best = f64::INFINITY;
            for i in 0..=200 {
                for j in 0..=200 {
                    best = best.min(dist(i as f64 / 200.0, j as f64 / 200.0));
                }
            }
            let len = |a: [f64; 3], b: [f64; 3]| dist_pts(a, b);
            let slack = (len(p0, p1) + len(q0, q1)) / 400.0;
            assert!(d2.sqrt() <= best + 1e-12, "case {case}: {} > grid {best}", d2.sqrt());
            assert!(best - d2.sqrt() <= slack + 1e-12, "case {case}: grid {best} vs {}", d2.sqrt());
        }
    }

    fn dist_pts(a: [f64; 3], b: [f64; 3]) -> f64 {
        ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
    }

    #[test]
    fn crossing_parallel_and_point_segments() {
        // Two skew lines crossing at a vertical distance 1.
        let (d2, s, u) = closest_points([-1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, -1.0, 1.0], [0.0, 1.0, 1.0]);
        assert_eq!((d2, s, u), (1.0, 0.5, 0.5));
        // Parallel conductors 0.4 m apart.
        let (d2, _, _) = closest_points([0.0; 3], [0.0, 10.0, 0.0], [0.4, 3.0, 0.0], [0.4, 13.0, 0.0]);
        assert!((d2.sqrt() - 0.4).abs() < 1e-15);
        // A point and a segment.
        let (d2, s, u) = closest_points([0.0, 0.0, 2.0], [0.0, 0.0, 2.0], [-1.0, 0.0, 0.0], [3.0, 0.0, 0.0]);
        assert_eq!((d2, s, u), (4.0, 0.0, 0.25));
    }
}
