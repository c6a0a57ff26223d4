//! A component's virgin loading curve: its force as a fourth-degree polynomial of its mechanical strain
//! (the Aluminum Association / IEEE Std 1283 stress-strain form),
//!
//! ```text
//! F(e) = a0 + a1 e + a2 e^2 + a3 e^3 + a4 e^4        for e_z <= e <= e_lim
//! F(e) = F(e_lim) + F'(e_lim) (e - e_lim)             for e > e_lim   (tangent extension)
//! ```
//!
//! with `F` [N] the force the component carries and `e` [-] its mechanical strain (a fraction, not
//! percent). `e_z` is the curve's first zero at or above zero strain: a published curve has `a0 < 0` (the
//! strands settle before they carry load), so the force is zero up to `e_z` (a curve with a small
//! `a0 > 0`, as steel creep curves have, has its zero within 0.1 % below zero strain). Beyond the fitted range
//! `e_lim` the curve continues along its tangent (the published polynomials are not meant to be used
//! there, and a quartic can turn down). A linear material is the curve `a1 = EA`, the rest zero.
//!
//! Published coefficients give the stress in psi (or Pa) on the WHOLE conductor's area as a function of
//! the strain in percent; [`Curve::from_percent`] converts them: `a_k [N] = A_total a_k[Pa] 100^k`.

use crate::element::scalar::Scalar;

/// The largest strain [-] at which a loading curve may start to carry load: 0.5 %. Published curves do
/// at a few hundredths of a percent (Drake's aluminium: 0.028 %); a later start is a mistyped coefficient.
pub const MAX_ZERO_STRAIN: f64 = 0.005;

/// A virgin loading curve `F(e)` (module doc).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Curve {
    /// coefficients `a_k` [N] of `F(e) = sum a_k e^k`, `e` the mechanical strain [-]
    pub coefficients_n: [f64; 5],
    /// upper end of the fitted range `e_lim` [-] (`f64::INFINITY`: no limit)
    pub limit_strain: f64,
    /// the curve's zero `e_z` [-] (computed by the constructors)
    zero_strain: f64,
}

impl Curve {
    /// The linear curve `F = stiffness e` (stiffness `EA` [N]).
    pub fn linear(stiffness_n: f64) -> Curve {
        Curve { coefficients_n: [0.0, stiffness_n, 0.0, 0.0, 0.0], limit_strain: f64::INFINITY, zero_strain: 0.0 }
    }

    /// A polynomial curve from coefficients `a_k` [N] (strain as a fraction) and its fitted range's upper
    /// end `limit_strain` [-]. Returns `None` when the curve has no zero in `[-0.001, 0.005]` below the limit
    /// ([`MAX_ZERO_STRAIN`]) or is not
    /// increasing on `[e_z, limit]` (checked at 200 points: a loading curve must be).
    pub fn polynomial(coefficients_n: [f64; 5], limit_strain: f64) -> Option<Curve> {
        let mut c = Curve { coefficients_n, limit_strain, zero_strain: 0.0 };
        c.zero_strain = c.find_zero()?;
        if c.zero_strain > MAX_ZERO_STRAIN {
            return None;
        }
        let hi = if limit_strain.is_finite() { limit_strain } else { c.zero_strain + 0.02 };
        let n = 200;
        for k in 0..=n {
            let e = c.zero_strain + (hi - c.zero_strain) * k as f64 / n as f64;
            if c.raw_slope(e) <= 0.0 {
                return None;
            }
        }
        Some(c)
    }

    /// A polynomial curve from the published form: stress `a_k` [Pa] on the whole conductor's area
    /// `total_area_m2` [m^2] against the strain in percent, fitted up to the stress `limit_pa` [Pa]
    /// (`None`: no stated limit). See [`Curve::polynomial`] for `None`.
    pub fn from_percent(a_pa_percent: [f64; 5], total_area_m2: f64, limit_pa: Option<f64>) -> Option<Curve> {
        let mut a = [0.0; 5];
        for (k, ak) in a.iter_mut().enumerate() {
            *ak = a_pa_percent[k] * total_area_m2 * 100f64.powi(k as i32);
        }
        let probe = Curve { coefficients_n: a, limit_strain: f64::INFINITY, zero_strain: 0.0 };
        let limit_strain = match limit_pa {
            None => f64::INFINITY,
            Some(s) => probe.first_crossing(s * total_area_m2, 0.05)?,
        };
        Curve::polynomial(a, limit_strain)
    }

    /// The strain `e_z` [-] below which the virgin curve carries nothing.
    pub fn zero_strain(&self) -> f64 {
        self.zero_strain
    }

    /// The polynomial itself, without the zero or the extension.
    fn raw<S: Scalar>(&self, e: S) -> S {
        let a = &self.coefficients_n;
        (((e * a[4] + a[3]) * e + a[2]) * e + a[1]) * e + a[0]
    }

    fn raw_slope(&self, e: f64) -> f64 {
        let a = &self.coefficients_n;
        ((4.0 * a[4] * e + 3.0 * a[3]) * e + 2.0 * a[2]) * e + a[1]
    }

    /// The force `F(e)` [N] for `e >= e_z` (the polynomial, or its tangent beyond `e_lim`).
    #[inline]
    pub fn force<S: Scalar>(&self, e: S) -> S {
        if e.value() <= self.limit_strain {
            self.raw(e)
        } else {
            let l = self.limit_strain;
            (e - l) * self.raw_slope(l) + self.raw(l)
        }
    }

    /// The slope `dF/de` [N] at `e >= e_z`.
    pub fn slope(&self, e: f64) -> f64 {
        self.raw_slope(e.min(self.limit_strain))
    }

    /// The strain on the curve at the force `f` [N] `>= 0` (the curve is increasing from `e_z`).
    pub fn strain_at(&self, f: f64) -> f64 {
        if f <= 0.0 {
            return self.zero_strain;
        }
        if self.limit_strain.is_finite() && f >= self.raw(self.limit_strain) {
            let l = self.limit_strain;
            return l + (f - self.raw(l)) / self.raw_slope(l);
        }
        let hi = if self.limit_strain.is_finite() { self.limit_strain } else { self.grow_bracket(f) };
        self.raw_inverse(f, self.zero_strain, hi).expect("an increasing curve has one root in its bracket")
    }

    fn grow_bracket(&self, f: f64) -> f64 {
        let mut hi = self.zero_strain + 1e-3;
        while self.raw(hi) < f {
            hi = self.zero_strain + 2.0 * (hi - self.zero_strain);
        }
        hi
    }

    /// The root of `raw(e) = f` in `[lo, hi]` by bisection polished with Newton (to a few ulps).
    fn raw_inverse(&self, f: f64, mut lo: f64, mut hi: f64) -> Option<f64> {
        let g = |e: f64| self.raw(e) - f;
        if g(lo) > 0.0 || g(hi) < 0.0 {
            return None;
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if g(mid) < 0.0 { lo = mid } else { hi = mid }
        }
        Some(if g(lo).abs() <= g(hi).abs() { lo } else { hi })
    }

    fn find_zero(&self) -> Option<f64> {
        if self.coefficients_n[0] == 0.0 {
            return Some(0.0);
        }
        if self.coefficients_n[0] > 0.0 {
            // A curve that starts above zero (a small positive a0, as steel creep curves have) has its zero
            // just below zero strain: within 0.1 % of it.
            return (self.raw(-1.0e-3) < 0.0).then(|| self.raw_inverse(0.0, -1.0e-3, 0.0)).flatten();
        }
        // a0 < 0: the first sign change above 0, scanning up to the limit (or 5 % strain).
        let hi = if self.limit_strain.is_finite() { self.limit_strain } else { 0.05 };
        self.first_crossing(0.0, hi)
    }

    /// The smallest strain in `(0, hi]` where the polynomial reaches `f` (from below), scanning 2000 steps
    /// and then bisecting the first step that crosses: a fitted quartic may turn down and up again beyond
    /// its range, so a plain bisection over `[0, hi]` could find a later root.
    fn first_crossing(&self, f: f64, hi: f64) -> Option<f64> {
        let n = 2000;
        let mut prev = 0.0;
        for k in 1..=n {
            let e = hi * k as f64 / n as f64;
            if self.raw(e) >= f {
                return self.raw_inverse(f, prev, e);
            }
            prev = e;
        }
        None
    }
}
