//! Closed-form forces between straight current filaments in vacuum: the references of the electromagnetic
//! pair element ([`crate::element::em_force`]).
//!
//! Constants: `k = mu0 i_a i_b / (4 pi)` [N], with `mu0` = [`crate::element::em_force::MU0_H_PER_M`].
//!
//! # Parallel filaments (Grover, "Inductance Calculations", 1946, chapter 2, the mutual inductance of
//! parallel filaments with four end distances)
//!
//! `A` from `x = 0` to `x = La` on the line `y = 0`, `B` from `x = p` to `x = p + Lb` on `y = d`, currents
//! both along `+x`. The field of `A` on `B`'s line is `k_a / d (x / R(x) - (x - La) / R(x - La))` along `z`
//! with `R(x) = sqrt(x^2 + d^2)`; `i_b dx x B` integrates, with `d/dx R(x) = x / R(x)`, to the attraction
//! toward `A` (force along `-y` for currents in the same sense)
//!
//! ```text
//! F = k / d (R(p + Lb) - R(p + Lb - La) - R(p) + R(p - La)),
//! ```
//!
//! which is `d/dd` of Grover's mutual inductance of parallel filaments (`F = i_a i_b dM/dd`). Aligned and
//! equal (`p = 0`, `La = Lb = L`): `F = mu0 i_a i_b / (2 pi d) (sqrt(L^2 + d^2) - d)`, whose ratio to `L`
//! tends to the infinite conductors' `mu0 i_a i_b / (2 pi d)` as `L / d -> infinity` (end effect
//! `-d / L` relative).
//!
//! # Perpendicular filaments
//!
//! `A` from `x = a0` to `x = a1` on the `x` axis, current along `+x`; `B` the segment `x = c`, `z = h`,
//! `y` from `y0` to `y1` (current along `+y` for `y1 > y0`). With `u1 = c - a0`, `u2 = c - a1`,
//! `rho(y) = sqrt(y^2 + h^2)`, the field of `A` at `(c, y, h)` is `k_a (u1 / |r1| - u2 / |r2|) / rho^2
//! (0, -h, y)`; `dl x B` with `dl = dy e_y` points along `e_x` only (the force on `B` is parallel to `A`),
//! and with `s = sqrt(u^2 + rho^2)`, `s ds = y dy`, the integrand `y u / (rho^2 s)` integrates to
//! `-asinh(u / rho)`:
//!
//! ```text
//! F_x = k (Phi(y1) - Phi(y0)),    Phi(y) = asinh(u2 / rho(y)) - asinh(u1 / rho(y)).
//! ```
//!
//! The L-shape touching at a corner (`a0 = c = 0`, `h = 0`, `y0 -> 0`) diverges like `k ln(2 La / y0)`:
//! the force of filaments meeting at an angle is infinite, which the element regularises by leaving out
//! the core radius next to the shared node; the closed form with `y0` = that radius is its reference.
//!
//! Sources for the elementary integrals: the field of a finite straight filament, Jackson, "Classical
//! Electrodynamics", 3rd ed., problem 5.1 / section 5.3 (Biot-Savart); Grover, chapters 1-2 for the mutual
//! inductance of parallel and of inclined filaments.

use super::ExactError;
use crate::element::em_force::MU0_H_PER_M;
use std::f64::consts::PI;

fn check(value: f64, what: &'static str) -> Result<f64, ExactError> {
    if value.is_finite() { Ok(value) } else { Err(ExactError::InvalidInput { what, value }) }
}

/// The attraction [N] between parallel filaments (see the module docs): `A` of length `la_m` [m] from
/// `x = 0`, `B` of length `lb_m` [m] from `x = offset_m` [m], a distance `d_m` [m] apart, currents
/// `i_a_a`, `i_b_a` [A] in the same sense for positive values. Positive: toward the other conductor.
pub fn parallel_force(
    la_m: f64,
    lb_m: f64,
    offset_m: f64,
    d_m: f64,
    i_a_a: f64,
    i_b_a: f64,
) -> Result<f64, ExactError> {
    super::require_positive(la_m, "length of A")?;
    super::require_positive(lb_m, "length of B")?;
    super::require_positive(d_m, "distance")?;
    check(offset_m, "offset")?;
    check(i_a_a * i_b_a, "currents")?;
    let r = |x: f64| x.hypot(d_m);
    let k = MU0_H_PER_M * i_a_a * i_b_a / (4.0 * PI);
    Ok(k / d_m * (r(offset_m + lb_m) - r(offset_m + lb_m - la_m) - r(offset_m) + r(offset_m - la_m)))
}

/// The aligned, equal case `mu0 i_a i_b / (2 pi d) (sqrt(L^2 + d^2) - d)` [N], written without the
/// cancellation of `sqrt(L^2 + d^2) - d` for `L << d`.
pub fn aligned_parallel_force(l_m: f64, d_m: f64, i_a_a: f64, i_b_a: f64) -> Result<f64, ExactError> {
    super::require_positive(l_m, "length")?;
    super::require_positive(d_m, "distance")?;
    check(i_a_a * i_b_a, "currents")?;
    Ok(MU0_H_PER_M * i_a_a * i_b_a / (2.0 * PI * d_m) * (l_m * l_m / (l_m.hypot(d_m) + d_m)))
}

/// The force [N] along `+x` (along `A`) on the perpendicular filament `B` (see the module docs): `A` from
/// `x = a0_m` to `x = a1_m` [m], `B` at `x = c_m`, height `h_m` [m], from `y = y0_m` to `y = y1_m` [m];
/// currents `i_a_a` along `+x` and `i_b_a` from `y0` to `y1` [A]. `B` must stay off `A`'s axis
/// (`rho > 0` at both ends, and not crossing `A` itself).
#[allow(clippy::too_many_arguments)]
pub fn perpendicular_force(
    a0_m: f64,
    a1_m: f64,
    c_m: f64,
    h_m: f64,
    y0_m: f64,
    y1_m: f64,
    i_a_a: f64,
    i_b_a: f64,
) -> Result<f64, ExactError> {
    for (v, w) in [(a0_m, "a0"), (a1_m, "a1"), (c_m, "c"), (h_m, "h"), (y0_m, "y0"), (y1_m, "y1")] {
        check(v, w)?;
    }
    check(i_a_a * i_b_a, "currents")?;
    let (u1, u2) = (c_m - a0_m, c_m - a1_m);
    let phi = |y: f64| -> Result<f64, ExactError> {
        let rho = y.hypot(h_m);
        super::require_positive(rho, "distance of an end of B from the axis of A")?;
        Ok((u2 / rho).asinh() - (u1 / rho).asinh())
    };
    if h_m == 0.0 && y0_m.signum() != y1_m.signum() && u1.signum() != u2.signum() {
        return Err(ExactError::InvalidInput { what: "B crosses A", value: c_m });
    }
    let k = MU0_H_PER_M * i_a_a * i_b_a / (4.0 * PI);
    Ok(k * (phi(y1_m)? - phi(y0_m)?))
}

/// The first moment `int y f_x(y) dy` [N m] of the force on the perpendicular filament `B` in `A`'s plane
/// (`h = 0`; arguments as [`perpendicular_force`]): with `y f_x(y) = k (u1 / |r1| - u2 / |r2|)` and
/// `int u / sqrt(u^2 + y^2) dy = u asinh(y / |u|)` (0 for `u = 0`),
///
/// ```text
/// int_y0^y1 y f_x dy = k (Psi(y1) - Psi(y0)),   Psi(y) = u1 asinh(y / |u1|) - u2 asinh(y / |u2|).
/// ```
///
/// The share of `B`'s end `y1` is `(int (y - y0) f_x dy) / (y1 - y0)`.
#[allow(clippy::too_many_arguments)]
pub fn perpendicular_first_moment(
    a0_m: f64,
    a1_m: f64,
    c_m: f64,
    y0_m: f64,
    y1_m: f64,
    i_a_a: f64,
    i_b_a: f64,
) -> Result<f64, ExactError> {
    for (v, w) in [(a0_m, "a0"), (a1_m, "a1"), (c_m, "c"), (y0_m, "y0"), (y1_m, "y1")] {
        check(v, w)?;
    }
    let (u1, u2) = (c_m - a0_m, c_m - a1_m);
    let term = |u: f64, y: f64| if u == 0.0 { 0.0 } else { u * (y / u.abs()).asinh() };
    let psi = |y: f64| term(u1, y) - term(u2, y);
    let k = MU0_H_PER_M * i_a_a * i_b_a / (4.0 * PI);
    Ok(k * (psi(y1_m) - psi(y0_m)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The general formula at `p = 0`, `La = Lb` against the aligned form, and the infinite limit.
    #[test]
    fn aligned_case_and_infinite_limit() {
        let (l, d) = (40.0, 5.0);
        let g = parallel_force(l, l, 0.0, d, 1e4, 1e4).unwrap();
        let a = aligned_parallel_force(l, d, 1e4, 1e4).unwrap();
        assert!((g - a).abs() <= 1e-14 * a, "{g} {a}");
        // F / L -> mu0 i^2 / (2 pi d): (sqrt(L^2 + d^2) - d) / L = 1 - d / L + d^2 / (2 L^2) - O(d^4 / L^4)
        let inf = MU0_H_PER_M * 1e8 / (2.0 * PI * d);
        let big = 1e4;
        let f = aligned_parallel_force(big, d, 1e4, 1e4).unwrap() / big;
        let series = -d / big + d * d / (2.0 * big * big);
        assert!(((f - inf) / inf - series).abs() < 1e-13, "{f} {inf}");
    }
}
