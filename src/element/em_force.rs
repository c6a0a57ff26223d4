//! The electromagnetic pair element of a short circuit (issue 25): the force on a straight current
//! filament `B` (end points `b0`, `b1`, current `i_b` [A] flowing from `b0` to `b1`) due to a straight
//! filament `A` (`a0` to `a1`, current `i_a` [A]) in vacuum, and its split to `B`'s two end nodes.
//!
//! # Equations
//!
//! The field of the finite straight filament `A` at a point `r` (Biot-Savart integrated along a straight
//! line; e.g. Jackson, "Classical Electrodynamics", 3rd ed., section 5.3, problem 5.1; Grover,
//! "Inductance Calculations", 1946, chapter 1), written in the form that stays finite on `A`'s axis:
//!
//! ```text
//! L = a1 - a0,  r1 = r - a0,  r2 = r - a1,
//! B(r) = mu0 i_a / (4 pi) (|r1| + |r2|) / (|r1| |r2| (|r1| |r2| + r1.r2)) (L x r1)
//! ```
//!
//! which equals the textbook `mu0 i_a / (4 pi rho) (cos a1 - cos a2)` in the azimuthal direction (`rho` the
//! distance from `A`'s axis, `a1`, `a2` the angles `r1`, `r2` make with `L`). On `A`'s axis outside `A`
//! `L x r1 = 0` and the denominator is `2 |r1|^2 |r2|^2 > 0`: the field is exactly zero, with no NaN.
//!
//! The force on `B` (Grassmann / Lorentz force on a current element, `dF = i_b dl x B`) and its first
//! moment, with `b(u) = b0 + u (b1 - b0)`, `u` in `[0, 1]`:
//!
//! ```text
//! f(u) = i_b (b1 - b0) x B(b(u)),   F = int_0^1 f(u) du,
//! F_b0 = int_0^1 (1 - u) f(u) du,   F_b1 = int_0^1 u f(u) du.
//! ```
//!
//! The split conserves the force (`F_b0 + F_b1 = F`) and its moment about any point `o`:
//! `(b0 - o) x F_b0 + (b1 - o) x F_b1 = int (b(u) - o) x f(u) du`, the moment of the distributed force; it
//! is the consistent nodal load of linear shape functions, what the explicit kernel will apply.
//!
//! # Quadrature
//!
//! Gauss-Legendre with [`GAUSS_POINTS`] = 8 points per piece of `B`. `B` is cut into `m` equal pieces no
//! longer than the least distance `d` between the segments (`m = ceil(|B| / d)`, at most [`MAX_PIECES`]):
//! the field is analytic in a complex neighbourhood of each piece reaching at least `d`, twice the piece's
//! half-length, so the Bernstein ellipse of the piece has `rho >= 2 + sqrt(5)` and the error of 8 points is
//! of order `rho^(-16) ~ 1e-10` of the integrand's size (Trefethen, "Approximation Theory and Approximation
//! Practice", theorem 19.3). The tests observe at most 5.2e-12 of `mu0 i_a i_b / (4 pi)` (or of the force)
//! against the closed forms (`tests/em_force.rs`).
//!
//! # Singular cases
//!
//! - Segments sharing an end node (a dropper joining a busbar, two segments of a bundle's spacer): the
//!   force of two filaments meeting at an angle diverges logarithmically at the corner (Grover; for the
//!   L-shape, [`crate::exact::em_filaments::perpendicular_force`] with `y0 -> 0`). The part of `B`
//!   closer than `core_radius_m` to the shared node is left out (the conductor's radius: inside it a
//!   filament is no model of the current), and the rest is integrated on pieces graded geometrically
//!   (ratio 2) toward the node, each at least as far from `A` as half its length for a right angle. For the
//!   perpendicular L this is exactly the closed form with `y0 = core_radius_m`. Adjacent segments of one
//!   conductor are excluded by the caller (a straight continuation gives zero force anyway).
//! - Collinear segments that do not overlap: every point of `B` is on `A`'s axis outside `A`, the force is
//!   exactly zero.
//! - Segments that cross, overlap, or touch away from a shared end node: the filament force is infinite;
//!   [`EmForceError::Intersecting`].
//! - A segment of zero length: [`EmForceError::Degenerate`].
//!
//! Inputs are finite (checked by `debug_assert!` only: the caller, the line model, validates the
//! scenario); the result is finite for every `Ok`.
//!
//! Written for `f64` only, not over [`super::Scalar`]: the short-circuit force acts in the explicit step
//! (no static solver takes currents), and its Jacobian would never be asked for.

// Units in brackets, `[N]`, `[m]`, `[A]`, would otherwise be taken for intra-doc links.
#![allow(rustdoc::broken_intra_doc_links)]

use super::pair::closest_points;

/// The magnetic constant `mu0` [H/m]: `4 pi 1e-7`, the value IEC 60865-1:2011 (short-circuit currents,
/// calculation of effects) writes its force formulas with. The CODATA 2018 value, 1.25663706212e-6,
/// differs by 5.5e-10 relative: far below every other uncertainty of a short-circuit calculation, and the
/// standard's own numbers are reproduced with `4 pi 1e-7`.
pub const MU0_H_PER_M: f64 = 4.0 * std::f64::consts::PI * 1e-7;

/// Gauss-Legendre points per piece of `B`.
pub const GAUSS_POINTS: usize = 8;

/// The most pieces a segment `B` is cut into (non-touching pairs closer than `|B| / MAX_PIECES`
/// lose accuracy gradually; they are a near-crossing, not a mesh configuration).
pub const MAX_PIECES: usize = 64;

/// Nodes on `[-1, 1]` of the 8-point Gauss-Legendre rule (Abramowitz and Stegun, table 25.4): the positive
/// half, the rule is symmetric.
pub(crate) const GL_X: [f64; 4] =
    [0.183_434_642_495_649_8, 0.525_532_409_916_329, 0.796_666_477_413_626_7, 0.960_289_856_497_536_3];
/// Weights of the 8-point Gauss-Legendre rule (Abramowitz and Stegun, table 25.4), of the nodes `GL_X`.
pub(crate) const GL_W: [f64; 4] =
    [0.362_683_783_378_362, 0.313_706_645_877_887_3, 0.222_381_034_453_374_5, 0.101_228_536_290_376_3];

/// Why the force of a pair cannot be formed.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum EmForceError {
    /// A segment has zero length.
    #[error("a segment of the electromagnetic pair has zero length")]
    Degenerate,
    /// The filaments cross, overlap, or touch other than at a shared end node: the force is infinite.
    #[error("the two current filaments intersect (least distance {distance_m:e} m) other than at a shared end node")]
    Intersecting {
        /// least distance between the segments [m]
        distance_m: f64,
    },
}

/// The force on segment `B` and its split to `B`'s end nodes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairForce {
    /// total force on `B` [N]
    pub total_n: [f64; 3],
    /// the share of node `b0` [N]
    pub at_b0_n: [f64; 3],
    /// the share of node `b1` [N]
    pub at_b1_n: [f64; 3],
}

#[inline(always)]
fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
#[inline(always)]
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
#[inline(always)]
fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// The field of the straight filament `a0 a1` (current 1 A) at `r`, without the factor `mu0 / (4 pi)`
/// [1/m]. Zero on the filament's axis outside it; infinite on the filament itself (the caller keeps
/// away from it).
#[inline(always)]
pub fn unit_field(a0: [f64; 3], a1: [f64; 3], r: [f64; 3]) -> [f64; 3] {
    let l = sub(a1, a0);
    let (r1, r2) = (sub(r, a0), sub(r, a1));
    let (n1, n2) = (dot(r1, r1).sqrt(), dot(r2, r2).sqrt());
    let c = cross(l, r1);
    let k = (n1 + n2) / (n1 * n2 * (n1 * n2 + dot(r1, r2)));
    [k * c[0], k * c[1], k * c[2]]
}

/// The force [N] on filament `B = b0 b1` (current `i_b_a` [A] from `b0` to `b1`) due to filament
/// `A = a0 a1` (current `i_a_a` [A] from `a0` to `a1`), points in [m], and its split to `b0` and `b1`
/// (see the module docs). `core_radius_m` [m] (the conductor's radius, > 0) is the length of `B` left out
/// next to a node the two share.
///
/// The eight points of a piece are evaluated side by side ([`piece`]), in the AVX2 copy where the
/// processor has it (`OHL_NO_AVX2` unset, as the kernel's passes): the same operations on each point in
/// the same order, correctly rounded in every lane, so both copies give the same bits as one point after
/// the other (tested against the point-by-point loop they replace).
pub fn pair_force(
    a0: [f64; 3],
    a1: [f64; 3],
    i_a_a: f64,
    b0: [f64; 3],
    b1: [f64; 3],
    i_b_a: f64,
    core_radius_m: f64,
) -> Result<PairForce, EmForceError> {
    #[cfg(target_arch = "x86_64")]
    if avx2() {
        // SAFETY: only where the processor reports AVX2 (`avx2`).
        return unsafe { pair_force_avx2(a0, a1, i_a_a, b0, b1, i_b_a, core_radius_m) };
    }
    pair_force_lanes(a0, a1, i_a_a, b0, b1, i_b_a, core_radius_m)
}

/// Whether the AVX2 copy may run: the processor reports AVX2 and `OHL_NO_AVX2` is not set (read once).
#[cfg(target_arch = "x86_64")]
fn avx2() -> bool {
    static AVX2: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *AVX2.get_or_init(crate::scheme::avx2_available)
}

/// [`pair_force_lanes`] compiled for AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn pair_force_avx2(
    a0: [f64; 3],
    a1: [f64; 3],
    i_a_a: f64,
    b0: [f64; 3],
    b1: [f64; 3],
    i_b_a: f64,
    core_radius_m: f64,
) -> Result<PairForce, EmForceError> {
    pair_force_lanes(a0, a1, i_a_a, b0, b1, i_b_a, core_radius_m)
}

/// One piece `[u_lo, u_hi]` of `B`: its [`GAUSS_POINTS`] Gauss-Legendre points evaluated lane by lane,
/// then added to `tot` (`F`) and `mom` (`int u f du`) point after point in the rule's order (for `k`,
/// `mid - half x_k` then `mid + half x_k`), `w f` and `(w u) f` as one point at a time would.
#[inline(always)]
fn piece(
    a0: [f64; 3],
    a1: [f64; 3],
    b0: [f64; 3],
    db: [f64; 3],
    [u_lo, u_hi]: [f64; 2],
    tot: &mut [f64; 3],
    mom: &mut [f64; 3],
) {
    const P: usize = GAUSS_POINTS;
    let (mid, half) = (0.5 * (u_lo + u_hi), 0.5 * (u_hi - u_lo));
    let (mut u, mut w) = ([0.0; P], [0.0; P]);
    for k in 0..P / 2 {
        (u[2 * k], u[2 * k + 1]) = (mid - half * GL_X[k], mid + half * GL_X[k]);
        (w[2 * k], w[2 * k + 1]) = (half * GL_W[k], half * GL_W[k]);
    }
    // The integrand db x B(b(u)) per point ([`unit_field`]'s operations, lane by lane).
    let l = sub(a1, a0);
    let mut v = [[0.0; P]; 3];
    for p in 0..P {
        let r = [b0[0] + u[p] * db[0], b0[1] + u[p] * db[1], b0[2] + u[p] * db[2]];
        let (r1, r2) = (sub(r, a0), sub(r, a1));
        let (n1, n2) = (dot(r1, r1).sqrt(), dot(r2, r2).sqrt());
        let c = cross(l, r1);
        let k = (n1 + n2) / (n1 * n2 * (n1 * n2 + dot(r1, r2)));
        let f = cross(db, [k * c[0], k * c[1], k * c[2]]);
        for j in 0..3 {
            v[j][p] = f[j];
        }
    }
    for p in 0..P {
        for j in 0..3 {
            tot[j] += w[p] * v[j][p];
            mom[j] += w[p] * u[p] * v[j][p];
        }
    }
}

/// [`pair_force`]'s body, the pieces by [`piece`].
#[inline(always)]
fn pair_force_lanes(
    a0: [f64; 3],
    a1: [f64; 3],
    i_a_a: f64,
    b0: [f64; 3],
    b1: [f64; 3],
    i_b_a: f64,
    core_radius_m: f64,
) -> Result<PairForce, EmForceError> {
    debug_assert!(a0.iter().chain(&a1).chain(&b0).chain(&b1).all(|x| x.is_finite()), "non-finite point");
    debug_assert!(i_a_a.is_finite() && i_b_a.is_finite(), "non-finite current");
    debug_assert!(core_radius_m.is_finite() && core_radius_m > 0.0, "core radius must be positive");
    let (la, lb) = (dot(sub(a1, a0), sub(a1, a0)).sqrt(), dot(sub(b1, b0), sub(b1, b0)).sqrt());
    if la <= 0.0 || lb <= 0.0 {
        return Err(EmForceError::Degenerate);
    }
    let tol = 1e-12 * (la + lb);
    let near = |p: [f64; 3], q: [f64; 3]| dot(sub(p, q), sub(p, q)).sqrt() <= tol;
    // A node of B shared with A: (which end of B, A's other end).
    let shared = if near(b0, a0) || near(b0, a1) {
        Some(0.0)
    } else if near(b1, a0) || near(b1, a1) {
        Some(1.0)
    } else {
        None
    };
    let db = sub(b1, b0);
    let mut tot = [0.0; 3];
    let mut mom = [0.0; 3];
    let mut piece = |u_lo: f64, u_hi: f64| piece(a0, a1, b0, db, [u_lo, u_hi], &mut tot, &mut mom);
    match shared {
        Some(end) => {
            // The rest of the pair must stay clear of A: B folding back along A overlaps it.
            let cut = (core_radius_m / lb).min(1.0);
            let (lo, hi) = if end == 0.0 { (cut, 1.0) } else { (0.0, 1.0 - cut) };
            if hi > lo {
                let (bq0, bq1) = ([0, 1, 2].map(|j| b0[j] + lo * db[j]), [0, 1, 2].map(|j| b0[j] + hi * db[j]));
                let (d2, _, _) = closest_points(a0, a1, bq0, bq1);
                if d2.sqrt() <= tol {
                    return Err(EmForceError::Intersecting { distance_m: d2.sqrt() });
                }
                // graded pieces [x, 2x] in the distance x (fraction of B) from the shared node
                let mut x = cut;
                while x < 1.0 {
                    let y = (2.0 * x).min(1.0);
                    if end == 0.0 {
                        piece(x, y)
                    } else {
                        piece(1.0 - y, 1.0 - x)
                    }
                    x = y;
                }
            }
        }
        None => {
            let (d2, _, _) = closest_points(a0, a1, b0, b1);
            let d = d2.sqrt();
            if d <= tol {
                return Err(EmForceError::Intersecting { distance_m: d });
            }
            let m = ((lb / d).ceil() as usize).clamp(1, MAX_PIECES);
            for p in 0..m {
                piece(p as f64 / m as f64, (p + 1) as f64 / m as f64);
            }
        }
    }
    let k = MU0_H_PER_M / (4.0 * std::f64::consts::PI) * i_a_a * i_b_a;
    let total_n = tot.map(|x| k * x);
    let at_b1_n = mom.map(|x| k * x);
    let at_b0_n = [0, 1, 2].map(|j| total_n[j] - at_b1_n[j]);
    Ok(PairForce { total_n, at_b0_n, at_b1_n })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The 8-point rule integrates polynomials of degree 15 exactly: x^14 over [-1, 1] is 2/15, and the
    /// weights sum to 2 (to rounding, 1e-15).
    #[test]
    fn gauss_legendre_table_is_exact_to_degree_15() {
        let (mut w, mut m14, mut m15) = (0.0, 0.0, 0.0);
        for k in 0..4 {
            for x in [-GL_X[k], GL_X[k]] {
                w += GL_W[k];
                m14 += GL_W[k] * x.powi(14);
                m15 += GL_W[k] * x.powi(15);
            }
        }
        assert!((w - 2.0).abs() < 1e-15, "{w}");
        assert!((m14 - 2.0 / 15.0).abs() < 1e-15, "{m14}");
        assert!(m15.abs() < 1e-15, "{m15}");
    }

    /// The field against the textbook form mu0 i / (4 pi rho) (cos a1 - cos a2) off the axis, and exactly
    /// zero on the axis outside the filament.
    #[test]
    fn field_matches_the_angle_form_and_vanishes_on_the_axis() {
        let (a0, a1) = ([0.0, 0.0, 0.0], [3.0, 0.0, 0.0]);
        let r = [1.0, 2.0, 0.0];
        let (c1, c2) = (1.0 / 5f64.sqrt(), -2.0 / 8f64.sqrt());
        let b = unit_field(a0, a1, r);
        let want = (c1 - c2) / 2.0; // along +z
        assert!((b[2] - want).abs() < 1e-15 && b[0] == 0.0 && b[1] == 0.0, "{b:?}");
        assert_eq!(unit_field(a0, a1, [5.0, 0.0, 0.0]), [0.0; 3]);
        assert_eq!(unit_field(a0, a1, [-2.0, 0.0, 0.0]), [0.0; 3]);
    }

    #[test]
    fn singular_configurations_are_typed() {
        let z = [0.0; 3];
        let x = [1.0, 0.0, 0.0];
        // crossing at the middle of both
        let e = pair_force([-1.0, 0.0, 0.0], x, 1.0, [0.0, -1.0, 0.0], [0.0, 1.0, 0.0], 1.0, 0.01);
        assert!(matches!(e, Err(EmForceError::Intersecting { .. })));
        // overlapping collinear
        let e = pair_force(z, [2.0, 0.0, 0.0], 1.0, x, [3.0, 0.0, 0.0], 1.0, 0.01);
        assert!(matches!(e, Err(EmForceError::Intersecting { .. })));
        // folding back along A from a shared node
        let e = pair_force(z, [2.0, 0.0, 0.0], 1.0, [2.0, 0.0, 0.0], x, 1.0, 0.01);
        assert!(matches!(e, Err(EmForceError::Intersecting { .. })));
        assert_eq!(pair_force(z, z, 1.0, x, [1.0, 1.0, 0.0], 1.0, 0.01), Err(EmForceError::Degenerate));
        // collinear continuation: exactly zero
        let f = pair_force(z, x, 1e4, x, [2.0, 0.0, 0.0], 1e4, 0.01).unwrap();
        assert_eq!(f.total_n, [0.0; 3]);
        // collinear apart: exactly zero
        let f = pair_force(z, x, 1e4, [3.0, 0.0, 0.0], [5.0, 0.0, 0.0], 1e4, 0.01).unwrap();
        assert_eq!(f.total_n, [0.0; 3]);
    }

    /// The point-by-point loop [`piece`] replaced (the integrand as a closure over [`unit_field`], each
    /// point added as it is evaluated), for the bitwise test below.
    fn pair_force_point_by_point(
        a0: [f64; 3],
        a1: [f64; 3],
        i_a_a: f64,
        b0: [f64; 3],
        b1: [f64; 3],
        i_b_a: f64,
        core_radius_m: f64,
    ) -> Result<PairForce, EmForceError> {
        let (la, lb) = (dot(sub(a1, a0), sub(a1, a0)).sqrt(), dot(sub(b1, b0), sub(b1, b0)).sqrt());
        if la <= 0.0 || lb <= 0.0 {
            return Err(EmForceError::Degenerate);
        }
        let tol = 1e-12 * (la + lb);
        let near = |p: [f64; 3], q: [f64; 3]| dot(sub(p, q), sub(p, q)).sqrt() <= tol;
        let shared = if near(b0, a0) || near(b0, a1) {
            Some(0.0)
        } else if near(b1, a0) || near(b1, a1) {
            Some(1.0)
        } else {
            None
        };
        let db = sub(b1, b0);
        let f = |u: f64| {
            let r = [b0[0] + u * db[0], b0[1] + u * db[1], b0[2] + u * db[2]];
            cross(db, unit_field(a0, a1, r))
        };
        let mut tot = [0.0; 3];
        let mut mom = [0.0; 3];
        let mut piece = |u_lo: f64, u_hi: f64| {
            let (mid, half) = (0.5 * (u_lo + u_hi), 0.5 * (u_hi - u_lo));
            for k in 0..GAUSS_POINTS / 2 {
                for u in [mid - half * GL_X[k], mid + half * GL_X[k]] {
                    let v = f(u);
                    let w = half * GL_W[k];
                    for j in 0..3 {
                        tot[j] += w * v[j];
                        mom[j] += w * u * v[j];
                    }
                }
            }
        };
        match shared {
            Some(end) => {
                let cut = (core_radius_m / lb).min(1.0);
                let (lo, hi) = if end == 0.0 { (cut, 1.0) } else { (0.0, 1.0 - cut) };
                if hi > lo {
                    let (bq0, bq1) = ([0, 1, 2].map(|j| b0[j] + lo * db[j]), [0, 1, 2].map(|j| b0[j] + hi * db[j]));
                    let (d2, _, _) = closest_points(a0, a1, bq0, bq1);
                    if d2.sqrt() <= tol {
                        return Err(EmForceError::Intersecting { distance_m: d2.sqrt() });
                    }
                    let mut x = cut;
                    while x < 1.0 {
                        let y = (2.0 * x).min(1.0);
                        if end == 0.0 {
                            piece(x, y)
                        } else {
                            piece(1.0 - y, 1.0 - x)
                        }
                        x = y;
                    }
                }
            }
            None => {
                let (d2, _, _) = closest_points(a0, a1, b0, b1);
                let d = d2.sqrt();
                if d <= tol {
                    return Err(EmForceError::Intersecting { distance_m: d });
                }
                let m = ((lb / d).ceil() as usize).clamp(1, MAX_PIECES);
                for p in 0..m {
                    piece(p as f64 / m as f64, (p + 1) as f64 / m as f64);
                }
            }
        }
        let k = MU0_H_PER_M / (4.0 * std::f64::consts::PI) * i_a_a * i_b_a;
        let total_n = tot.map(|x| k * x);
        let at_b1_n = mom.map(|x| k * x);
        let at_b0_n = [0, 1, 2].map(|j| total_n[j] - at_b1_n[j]);
        Ok(PairForce { total_n, at_b0_n, at_b1_n })
    }

    /// The lane-wise pieces (the baseline copy and, where the processor has AVX2, the AVX2 copy) give
    /// the same bits as the point-by-point loop: pseudo-random pairs at coordinates up to 1e3 m, a
    /// quarter sharing a node (graded pieces), a quarter close (up to 64 pieces), a quarter collinear.
    #[test]
    fn lanes_are_bitwise_the_point_by_point_loop() {
        let mut rnd = crate::test_rng::symmetric(0x2545_f491_4f6c_dd1d_u64);
        let bits = |r: &Result<PairForce, EmForceError>| match r {
            Ok(f) => Ok([f.total_n, f.at_b0_n, f.at_b1_n].map(|v| v.map(f64::to_bits))),
            Err(e) => Err(*e),
        };
        let (mut compared, mut avx2_compared) = (0, 0);
        for case in 0..20000 {
            let scale = [1.0, 30.0, 1e3][case % 3];
            let mut pt = || [rnd() * scale, rnd() * scale, rnd() * scale];
            let (a0, a1, mut b0, mut b1) = (pt(), pt(), pt(), pt());
            match (case / 3) % 4 {
                0 => b0 = if case % 2 == 0 { a0 } else { a1 },
                1 => {
                    // nearly parallel, close: many pieces
                    let gap = 10f64.powf(-3.0 * (rnd() + 1.0)) * scale;
                    b0 = [a0[0] + gap, a0[1] + rnd() * gap, a0[2]];
                    b1 = [a1[0] + gap, a1[1], a1[2] + rnd() * gap];
                }
                2 => {
                    let (s, t) = (3.0 * rnd(), 3.0 * rnd());
                    b0 = [0, 1, 2].map(|j| a0[j] + s * (a1[j] - a0[j]));
                    b1 = [0, 1, 2].map(|j| a0[j] + t * (a1[j] - a0[j]));
                }
                _ => {}
            }
            let (ia, ib, core) = (1e4 * rnd(), -2e4 * rnd(), 0.01 * (rnd() + 1.5));
            let want = bits(&pair_force_point_by_point(a0, a1, ia, b0, b1, ib, core));
            assert_eq!(bits(&pair_force_lanes(a0, a1, ia, b0, b1, ib, core)), want, "case {case}");
            assert_eq!(bits(&pair_force(a0, a1, ia, b0, b1, ib, core)), want, "case {case}");
            compared += 1;
            #[cfg(target_arch = "x86_64")]
            if std::is_x86_feature_detected!("avx2") {
                // SAFETY: the processor reports AVX2.
                let f = unsafe { pair_force_avx2(a0, a1, ia, b0, b1, ib, core) };
                assert_eq!(bits(&f), want, "case {case} (AVX2)");
                avx2_compared += 1;
            }
        }
        println!("{compared} pairs compared, {avx2_compared} with the AVX2 copy");
        assert_eq!(compared, 20000);
    }

    /// No NaN: pseudo-random pairs, a third sharing a node, a third collinear or on each other's axes;
    /// every `Ok` is finite, its shares add up to the total, and only intersecting or degenerate pairs
    /// are refused.
    #[test]
    fn random_pairs_give_finite_forces_or_typed_errors() {
        let mut rnd = crate::test_rng::symmetric(0x9e37_79b9_7f4a_7c15_u64);
        let (mut ok, mut refused) = (0, 0);
        for case in 0..3000 {
            let mut pt = || [rnd(), rnd(), rnd()];
            let (a0, a1, mut b0, mut b1) = (pt(), pt(), pt(), pt());
            match case % 3 {
                0 => b0 = if case % 2 == 0 { a0 } else { a1 },
                1 => {
                    // on A's line: collinear, apart or overlapping
                    let (s, t) = (3.0 * rnd(), 3.0 * rnd());
                    b0 = [0, 1, 2].map(|j| a0[j] + s * (a1[j] - a0[j]));
                    b1 = [0, 1, 2].map(|j| a0[j] + t * (a1[j] - a0[j]));
                }
                _ => {}
            }
            match pair_force(a0, a1, 1e4, b0, b1, -2e4, 0.01) {
                Ok(f) => {
                    ok += 1;
                    let all = f.total_n.iter().chain(&f.at_b0_n).chain(&f.at_b1_n);
                    assert!(all.clone().all(|x| x.is_finite()), "case {case}: {f:?}");
                    for j in 0..3 {
                        let sum = f.at_b0_n[j] + f.at_b1_n[j];
                        assert!((sum - f.total_n[j]).abs() <= 1e-12 * f.total_n[j].abs().max(1.0), "case {case}");
                    }
                }
                Err(e) => {
                    // only the collinear third can overlap A
                    assert!(case % 3 == 1 && matches!(e, EmForceError::Intersecting { .. }), "case {case}: {e}");
                    refused += 1;
                }
            }
        }
        println!("{ok} finite, {refused} refused (collinear and overlapping)");
        assert!(ok > 2000 && refused > 100, "{ok} ok, {refused} refused");
    }
}
