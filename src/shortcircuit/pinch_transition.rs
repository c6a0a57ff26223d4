//! The transition of a pinched bundle at a spacer: how long it is, and how much length it takes from a
//! sub-conductor. It sets the grid a dynamic run needs for the pinch tension `F_pi`.
//!
//! # Model
//!
//! Under the pinch, two sub-conductors carrying `i` [A] each attract with `f'(d) = mu0 i^2 / (2 pi d)` per
//! unit length at the axis distance `d`. Between spacers they clash and lie in contact, `d = 2 r` (`r` the
//! radius); at a spacer they are held at `a_s`. Between the two, each sub-conductor (tension `T` [N]) is
//! a string pulled towards the other: with `y = d / 2` the half-distance and `x` along the span,
//!
//! ```text
//! T y'' = mu0 i^2 / (4 pi y),    y(0) = r, y'(0) = 0 (tangent where they touch),
//! y'^2 = K ln(y / r),            K = mu0 i^2 / (2 pi T)        (the first integral)
//! ```
//!
//! With `y = r e^{s^2}` (`s = sqrt(ln(y / r))`, `dy = 2 r s e^{s^2} ds`) the singularity at the contact
//! goes away and, with `S = sqrt(ln(a_s / (2 r)))`,
//!
//! ```text
//! l  = int dy / y'               = (2 r / sqrt K) int_0^S e^{s^2} ds     (= (r / sqrt K) sqrt(pi) erfi(S))
//! dL = int (sqrt(1 + y'^2) - 1) dx = (2 r / sqrt K) int_0^S (sqrt(1 + K s^2) - 1) e^{s^2} ds
//! ```
//!
//! `l` [m] is the length of one transition (each spacer has two, one each side; the ends of a strained
//! span held apart by their yokes have one), `dL` [m] the extra length of the sub-conductor in it.
//!
//! # What it is for
//!
//! A grid whose segments are longer than `l` cannot hold the transition: it spreads over a segment and
//! takes only about `(a_s / 2 - r)^2 / (2 ds)` of length instead of `dL`, so the pinch stretches the
//! sub-conductors less and the dynamic `F_pi` comes out low, rising under refinement until `ds` is well
//! below `l` (docs/short_circuit.md, "The pinch needs a fine grid"). This is a quasi-static estimate at the
//! current's peak and the static tension: the dynamic transition is shorter while the tension is still low
//! and lengthens as it rises (`l ~ sqrt(T) / i`), so it is a length scale, not a prediction of `F_pi`.
//! Its integrals are evaluated by composite Gauss-Legendre (the integrands are smooth in `s`); the tests
//! check them against the series of `erfi` and the small-slope limit.

use crate::element::em_force::{GL_W, GL_X, MU0_H_PER_M};

/// The transition of a pinched bundle at a spacer ([module doc](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PinchTransition {
    /// `K = mu0 i^2 / (2 pi T)` [-]
    pub k: f64,
    /// length `l` of one transition along the span [m]
    pub length_m: f64,
    /// extra length `dL` of one sub-conductor in one transition [m]
    pub extra_length_m: f64,
}

/// `int_0^b g(s) ds` by 8-point Gauss-Legendre (the pair element's rule) on 64 equal pieces.
fn integrate(b: f64, g: impl Fn(f64) -> f64) -> f64 {
    const PIECES: usize = 64;
    let h = b / PIECES as f64;
    (0..PIECES)
        .map(|p| {
            let mid = (p as f64 + 0.5) * h;
            GL_X.iter().zip(&GL_W).map(|(&x, &w)| w * (g(mid - 0.5 * h * x) + g(mid + 0.5 * h * x))).sum::<f64>()
                * 0.5
                * h
        })
        .sum()
}

/// The transition for sub-conductors `a_s` [m] apart at the spacer, of diameter `d` [m], carrying `i` [A]
/// each, at the tension `T` [N] each. `None` unless `0 < d < a_s`, `i != 0` and `T > 0` (all finite).
pub fn pinch_transition(a_s: f64, d: f64, i: f64, t: f64) -> Option<PinchTransition> {
    let ok = |x: f64| x.is_finite() && x > 0.0;
    if !(ok(a_s) && ok(d) && ok(t) && i.is_finite() && i != 0.0 && d < a_s) {
        return None;
    }
    let r = 0.5 * d;
    let k = MU0_H_PER_M * i * i / (2.0 * std::f64::consts::PI * t);
    let s_max = (a_s / d).ln().sqrt();
    let scale = 2.0 * r / k.sqrt();
    let length_m = scale * integrate(s_max, |s| (s * s).exp());
    // sqrt(1 + K s^2) - 1 written as K s^2 / (sqrt(1 + K s^2) + 1): no cancellation for small K s^2.
    let extra_length_m = scale * integrate(s_max, |s| k * s * s / ((1.0 + k * s * s).sqrt() + 1.0) * (s * s).exp());
    Some(PinchTransition { k, length_m, extra_length_m })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `int_0^S e^{s^2} ds = sum_n S^(2n+1) / (n! (2n+1))`, summed to 1e-17.
    fn erfi_integral(s: f64) -> f64 {
        let (mut term, mut sum, mut n) = (s, s, 0.0);
        while term.abs() > 1e-17 * sum.abs() {
            n += 1.0;
            term *= s * s / n;
            sum += term / (2.0 * n + 1.0);
        }
        sum
    }

    /// Case h's twin (a_s = 0.1 m, d = 43 mm) at the first peak, 80.6 kA a sub-conductor, 9 kN: the length
    /// against the series of erfi, to 1e-12 (the quadrature of a smooth integrand on 64 pieces of 8 points
    /// is exact to rounding).
    #[test]
    fn length_matches_the_erfi_series() {
        let (a_s, d, i, t) = (0.1, 0.043, 80_631.0, 9000.0);
        let p = pinch_transition(a_s, d, i, t).unwrap();
        let s = (a_s / d).ln().sqrt();
        let expected = 2.0 * (0.5 * d) / p.k.sqrt() * erfi_integral(s);
        println!("K = {:.6}, l = {:.6} m (series {expected:.6} m), dL = {:.4e} m", p.k, p.length_m, p.extra_length_m);
        assert!((p.length_m - expected).abs() < 1e-12 * expected);
    }

    /// Small slopes (`K -> 0`, a very high tension): `dL -> (sqrt K / 2) int_r^{a_s/2} sqrt(ln(y / r)) dy`,
    /// evaluated here in `y` by the midpoint rule (an independent quadrature; its error at the square-root
    /// end is about 1e-6 with 2e5 intervals); the relative difference is `O(K)` (the next term of `sqrt(1 +
    /// K s^2)`): asserted below 5 K plus the quadrature's 1e-5.
    #[test]
    fn small_slope_limit() {
        let (a_s, d, i, t) = (0.1, 0.043, 1000.0, 1.0e6);
        let p = pinch_transition(a_s, d, i, t).unwrap();
        let r = 0.5 * d;
        let n = 200_000;
        let h = (0.5 * a_s - r) / n as f64;
        let integral: f64 = (0..n).map(|k| ((r + (k as f64 + 0.5) * h) / r).ln().sqrt()).sum::<f64>() * h;
        let expected = 0.5 * p.k.sqrt() * integral;
        let rel = (p.extra_length_m - expected).abs() / expected;
        println!("K = {:.3e}: dL = {:.6e} m, limit {expected:.6e} m, relative {rel:.2e}", p.k, p.extra_length_m);
        assert!(rel < 5.0 * p.k + 1e-5, "{rel}");
    }

    /// `l ~ sqrt(T) / |i|` exactly (K enters `l` only as `1 / sqrt K`).
    #[test]
    fn length_scales_with_tension_and_current() {
        let base = pinch_transition(0.1, 0.043, 50_000.0, 10_000.0).unwrap();
        let more = pinch_transition(0.1, 0.043, -100_000.0, 40_000.0).unwrap();
        assert!((more.length_m - base.length_m).abs() < 1e-14 * base.length_m);
        assert!(pinch_transition(0.04, 0.043, 50_000.0, 1e4).is_none());
        assert!(pinch_transition(0.1, 0.043, 0.0, 1e4).is_none());
        assert!(pinch_transition(0.1, 0.043, 5e4, -1.0).is_none());
    }
}
