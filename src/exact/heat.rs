//! Exact solution of the insulated rod whose two halves start at different temperatures.
//!
//! # Problem
//!
//! The dimensionless heat equation (5.1) without sources, `u_t = u_ss` on `0 < s < 1`, with insulated
//! (zero-flux) ends `u_s(0, t) = u_s(1, t) = 0` and the step initial condition of the paper's test 5.4:
//! `u(s, 0) = u_left` for `s < 1/2`, `u_right` for `s > 1/2`. Temperatures are in any unit (the problem is
//! linear and invariant under an affine change of unit); `s` and `t` are dimensionless (`s` = arc length /
//! span, `t` = physical time * diffusivity / span^2).
//!
//! # Two independent routes
//!
//! * Fourier (cosine) series, the eigenfunction expansion for Neumann ends:
//!   ```text
//!   u(s, t) = (uL + uR)/2 + sum_{k >= 1} a_k cos(k pi s) exp(-k^2 pi^2 t),
//!   a_k = 2 (uL - uR) sin(k pi / 2) / (k pi)
//!   ```
//!   (`a_k = 0` for even `k`; for odd `k`, `sin(k pi/2) = (-1)^((k-1)/2)` is used exactly). The series is cut
//!   where the tail bound `sum_{k > K} |a_k| e^{-k^2 pi^2 t} <= 2|uL - uR| / ((K+1) pi) * e^{-(K+1)^2 pi^2 t}
//!   / (1 - e^{-2 (K+1) pi^2 t})` drops below `1e-15 (|uL| + |uR|)`, at `K` about `2 / sqrt(t)` (half of the terms
//!   vanish), so it is used for `t >= T_SWITCH`.
//! * Method of images: the even reflections of the initial data about `s = 0` and `s = 1` make a square
//!   wave of period 2 (`uL` on `(2n - 1/2, 2n + 1/2)`, `uR` elsewhere); convolving with the heat kernel of
//!   variance `2t` gives
//!   ```text
//!   u(s, t) = uR + (uL - uR)/2 sum_n [ erf((s - 2n + 1/2) / (2 sqrt t)) - erf((s - 2n - 1/2) / (2 sqrt t)) ],
//!   ```
//!   summed over `|n| <= M` with `(2M - 3/2) / (2 sqrt t) >= 6.2` (`erfc(6.2) = 1.8e-18`). A handful of images
//!   suffice for `t < 1`; used for `t < T_SWITCH`. `erf` is computed here (see [`erf`]) to about `1e-16`.
//!
//! The tests check each route against the other where both are cheap, and against known values of
//! `erf`; the solver's own convergence to this solution is tested in `crate::heat`.
//!
//! At `t = 0` the step itself is returned, with the mean `(uL + uR)/2` at `s = 1/2`. Any `s` is accepted:
//! the solution is continued evenly about `s = 0` and `s = 1` (so `s` a rounding error outside `[0, 1]`
//! is harmless). A negative or non-finite `t`, or non-finite input, gives `NaN`.

use std::f64::consts::PI;

/// Below this dimensionless time the images are summed, above it the Fourier series (both are exact
/// to rounding on either side; this only keeps the number of terms small: at most about 10 non-zero
/// Fourier terms or 5 images).
pub const T_SWITCH: f64 = 0.01;

/// Spread `max u - min u` of the two-halves solution carried by its slowest Fourier mode,
/// `a_1 cos(pi s) e^{-pi^2 t}` with `a_1 = 2 (u_left - u_right) / pi`: `2 |a_1| e^{-pi^2 t}`. Once the next
/// mode (`k = 3`, decaying as `e^{-9 pi^2 t}`) has died out this is the spread of the solution itself.
pub fn slowest_mode_spread(u_left: f64, u_right: f64, t: f64) -> f64 {
    4.0 * (u_left - u_right).abs() / PI * (-PI * PI * t).exp()
}

/// The time at which [`slowest_mode_spread`] falls to `spread`: the exact time to equalise to within
/// `spread` (for `spread` well below the initial difference).
pub fn equalisation_time(u_left: f64, u_right: f64, spread: f64) -> f64 {
    (4.0 * (u_left - u_right).abs() / (PI * spread)).ln() / (PI * PI)
}

/// Temperature `u(s, t)` of the insulated rod of unit length whose left half starts at `u_left` and right
/// half at `u_right` (any temperature unit), at dimensionless position `s` and dimensionless time `t >= 0`.
/// Accurate to about `1e-15 (|u_left| + |u_right|)` for every `t > 0`.
pub fn two_halves(u_left: f64, u_right: f64, s: f64, t: f64) -> f64 {
    if t < T_SWITCH { two_halves_images(u_left, u_right, s, t) } else { two_halves_fourier(u_left, u_right, s, t) }
}

/// Reflects `s` into `[0, 1]` by the even continuation about `0` and `1` (period 2).
fn fold(s: f64) -> f64 {
    let p = s.rem_euclid(2.0);
    if p > 1.0 { 2.0 - p } else { p }
}

/// The step initial condition, with the mean at the jump.
fn step_value(u_left: f64, u_right: f64, s: f64) -> f64 {
    if s < 0.5 {
        u_left
    } else if s > 0.5 {
        u_right
    } else {
        0.5 * (u_left + u_right)
    }
}

fn invalid(u_left: f64, u_right: f64, s: f64, t: f64) -> bool {
    !(u_left.is_finite() && u_right.is_finite() && s.is_finite() && t.is_finite()) || t < 0.0
}

/// [`two_halves`] by the cosine (Fourier) series; exact for every `t > 0`, with about `1 / sqrt(t)` non-zero
/// terms.
pub fn two_halves_fourier(u_left: f64, u_right: f64, s: f64, t: f64) -> f64 {
    if invalid(u_left, u_right, s, t) {
        return f64::NAN;
    }
    let s = fold(s);
    if t == 0.0 {
        return step_value(u_left, u_right, s);
    }
    let mean = 0.5 * (u_left + u_right);
    let jump = u_left - u_right;
    let target = 1e-15 * (u_left.abs() + u_right.abs());
    let decay = PI * PI * t;
    let mut sum = 0.0;
    let mut k: u64 = 1;
    loop {
        let kf = k as f64;
        // sin(k pi / 2) for odd k, exactly.
        let sign = if (k / 2).is_multiple_of(2) { 1.0 } else { -1.0 };
        sum += sign * 2.0 * jump / (kf * PI) * (kf * PI * s).cos() * (-kf * kf * decay).exp();
        let next = kf + 1.0;
        let tail = 2.0 * jump.abs() / (next * PI) * (-next * next * decay).exp() / -(-2.0 * next * decay).exp_m1();
        if tail <= target {
            break;
        }
        k += 2;
    }
    mean + sum
}

/// [`two_halves`] by the method of images; exact for every `t > 0`, with `2M + 1` images, `M` about
/// `6 sqrt(t) + 1`.
pub fn two_halves_images(u_left: f64, u_right: f64, s: f64, t: f64) -> f64 {
    if invalid(u_left, u_right, s, t) {
        return f64::NAN;
    }
    let s = fold(s);
    if t == 0.0 {
        return step_value(u_left, u_right, s);
    }
    let w = 2.0 * t.sqrt();
    // For s in [0, 1] the image n (|n| >= 1) contributes at most erfc((2|n| - 3/2) / w); erfc(6.2) = 1.8e-18.
    let m = ((6.2 * w + 1.5) / 2.0).ceil() as i64;
    let mut sum = 0.0;
    for n in -m..=m {
        let c = 2.0 * n as f64;
        sum += erf((s - c + 0.5) / w) - erf((s - c - 0.5) / w);
    }
    u_right + 0.5 * (u_left - u_right) * sum
}

/// The error function, to about `1e-16` absolute.
///
/// * `|x| < 1`: the series without cancellation (Abramowitz & Stegun 7.1.6)
///   `erf x = (2/sqrt(pi)) e^{-x^2} sum_{n >= 0} 2^n x^{2n+1} / (1 * 3 * ... * (2n+1))`, all terms of the sign of
///   `x`;
/// * `|x| >= 1`: `erf x = sign(x) (1 - erfc |x|)` with the continued fraction (A&S 7.1.14)
///   `erfc x = e^{-x^2}/sqrt(pi) * 1/(x + (1/2)/(x + 1/(x + (3/2)/(x + 2/(x + ...)))))`, evaluated from a depth
///   of 200 backwards (converged to rounding for `x >= 1`; the series is less accurate than this above 1,
///   by rounding in `e^{-x^2}` times a large sum). Worst error against the C library over `0 < x <= 6`:
///   3.3e-16.
pub fn erf(x: f64) -> f64 {
    if x.is_nan() {
        return f64::NAN;
    }
    let a = x.abs();
    if a < 1.0 {
        let x2 = x * x;
        let mut term = x;
        let mut sum = x;
        let mut n = 0.0;
        loop {
            n += 1.0;
            term *= 2.0 * x2 / (2.0 * n + 1.0);
            sum += term;
            if term.abs() <= 1e-17 * sum.abs() {
                break;
            }
        }
        2.0 / PI.sqrt() * (-x2).exp() * sum
    } else {
        x.signum() * (1.0 - erfc_large(a))
    }
}

/// `erfc(x)` for `x >= 1` by the continued fraction of [`erf`].
fn erfc_large(x: f64) -> f64 {
    if x > 27.0 {
        return 0.0; // below the smallest subnormal
    }
    let mut f = x;
    for k in (1..=200).rev() {
        f = x + 0.5 * k as f64 / f;
    }
    (-x * x).exp() / PI.sqrt() / f
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equalisation_time_is_where_the_series_spread_reaches_the_threshold() {
        // Independent route: the full series' spread u(0, t) - u(1, t) at the predicted time.
        let (ul, ur) = (473.15 / 273.15, 268.15 / 273.15);
        for spread in [1e-3, 1e-6, 1e-9] {
            let t = equalisation_time(ul, ur, spread);
            let series = two_halves(ul, ur, 0.0, t) - two_halves(ul, ur, 1.0, t);
            // The k = 3 mode adds a relative e^{-8 pi^2 t} / 3 (below 1e-24 here); the series itself is
            // accurate to about 1e-15 (|uL| + |uR|) per value (module doc), twice that for the difference.
            let bound = 1e-12 * spread + 2e-15 * (ul + ur);
            assert!((series - spread).abs() < bound, "spread {spread}: series gives {series:e} at t = {t}");
            assert!((slowest_mode_spread(ul, ur, t) / spread - 1.0).abs() < 1e-12);
        }
    }

    /// Dimensionless temperatures of test 5.4: 473.15 K / 273.15 K and 268.15 K / 273.15 K.
    const UL: f64 = 473.15 / 273.15;
    const UR: f64 = 268.15 / 273.15;

    #[test]
    fn erf_matches_reference_values() {
        // Values of CPython's math.erf / math.erfc (the C library's, an independent implementation), 17 digits.
        let cases = [
            (0.1, 0.1124629160182849),
            (0.5, 0.5204998778130465),
            (1.0, 0.8427007929497149),
            (2.0, 0.9953222650189527),
            (2.9, 0.9999589021219005),
            (3.0, 0.9999779095030014),
            (-1.5, -0.9661051464753108),
        ];
        for (x, want) in cases {
            // Tolerance: a few units in the last place (1.1e-16) of O(1) numbers.
            assert!((erf(x) - want).abs() < 5e-16, "erf({x}) = {:e}, want {want:e}", erf(x));
        }
        // erfc in the continued-fraction range, relative to its own size.
        for (x, want) in [(3.0, 2.2090496998585438e-05), (4.0, 1.541725790028002e-08), (6.0, 2.1519736712498916e-17)] {
            let got = erfc_large(x);
            assert!((got / want - 1.0).abs() < 1e-13, "erfc({x}) = {got:e}, want {want:e}");
        }
        assert_eq!(erf(0.0), 0.0);
        assert_eq!(erf(40.0), 1.0);
    }

    #[test]
    fn fourier_and_images_agree() {
        // The two routes share nothing but the problem: agreement to 1e-14 over t from 1e-3 (where the
        // Fourier series needs 30 non-zero terms) to 0.5 (where the images need 6 on each side) checks both.
        let mut worst: f64 = 0.0;
        for &t in &[1e-3, 4e-3, 0.01, 0.03, 0.1, 0.25, 0.5] {
            for i in 0..=40 {
                let s = i as f64 / 40.0;
                let f = two_halves_fourier(UL, UR, s, t);
                let g = two_halves_images(UL, UR, s, t);
                worst = worst.max((f - g).abs());
            }
        }
        assert!(worst < 1e-14, "Fourier and images differ by {worst:e}");
    }

    #[test]
    fn limits_and_symmetries() {
        let mean = 0.5 * (UL + UR);
        // t = 0: the step itself, the mean at the jump.
        assert_eq!(two_halves(UL, UR, 0.2, 0.0), UL);
        assert_eq!(two_halves(UL, UR, 0.8, 0.0), UR);
        assert_eq!(two_halves(UL, UR, 0.5, 0.0), mean);
        // The centre stays at the mean for all t (u - mean is odd about s = 1/2).
        for t in [1e-6, 1e-3, 0.1, 1.0] {
            assert!((two_halves(UL, UR, 0.5, t) - mean).abs() < 1e-15);
            let (a, b) = (two_halves(UL, UR, 0.3, t), two_halves(UL, UR, 0.7, t));
            assert!((a + b - 2.0 * mean).abs() < 1e-14, "odd symmetry about s = 1/2 at t = {t}");
        }
        // Zero flux: the even continuation about s = 0 is smooth, so a centred difference vanishes.
        let d = (two_halves(UL, UR, 1e-4, 0.05) - two_halves(UL, UR, -1e-4, 0.05)) / 2e-4;
        assert!(d.abs() < 1e-12);
        // Late time: only the first mode is left, a_1 = 2 (uL - uR) / pi.
        let t = 2.0;
        let first = mean + 2.0 * (UL - UR) / PI * (-PI * PI * t).exp();
        assert!((two_halves(UL, UR, 0.0, t) - first).abs() < 1e-15);
        // Early time: far from the jump (and its images) the ends still hold their initial value.
        assert!((two_halves(UL, UR, 0.0, 1e-4) - UL).abs() < 1e-15);
        // A short-time check of the images route against the one-erf solution of the infinite line.
        let (s, t): (f64, f64) = (0.49, 1e-4);
        let line = mean + 0.5 * (UL - UR) * erf((0.5 - s) / (2.0 * t.sqrt()));
        assert!((two_halves(UL, UR, s, t) - line).abs() < 1e-15);
        // Bad input gives NaN, never a panic.
        assert!(two_halves(UL, UR, 0.5, -1.0).is_nan());
        assert!(two_halves(f64::NAN, UR, 0.5, 1.0).is_nan());
    }
}
