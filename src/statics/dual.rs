//! Forward-mode dual numbers with a fixed number `S` of derivative slots: the exact derivatives of the
//! segment forces (tension, Kelvin-Voigt friction, wind) with respect to the inputs of a segment, without
//! hand-derived formulas. The static Jacobian needs the six positions of a segment's two end nodes
//! ([`D6`]); an implicit integrator also needs their six velocities ([`D12`]).

use std::ops::{Add, Div, Mul, Neg, Sub};

/// A value and its gradient with respect to `S` inputs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dual<const S: usize> {
    /// value
    pub v: f64,
    /// partial derivatives
    pub d: [f64; S],
}

/// Derivatives with respect to the positions `x_a, x_b` of a segment's end nodes (slots 0-2, 3-5).
pub type D6 = Dual<6>;
/// Derivatives with respect to `x_a, x_b, v_a, v_b` (slots 0-2, 3-5, 6-8, 9-11).
pub type D12 = Dual<12>;

impl<const S: usize> Dual<S> {
    /// a constant
    #[inline(always)]
    pub fn c(v: f64) -> Self {
        Dual { v, d: [0.0; S] }
    }
    /// the input in slot `k`
    #[inline(always)]
    pub fn var(v: f64, k: usize) -> Self {
        let mut d = [0.0; S];
        d[k] = 1.0;
        Dual { v, d }
    }
    #[inline(always)]
    fn map(self, v: f64, dv: f64) -> Self {
        let mut d = self.d;
        for x in &mut d {
            *x *= dv;
        }
        Dual { v, d }
    }
    /// square root
    #[inline(always)]
    pub fn sqrt(self) -> Self {
        let r = self.v.sqrt();
        self.map(r, 0.5 / r)
    }
    /// absolute value (derivative `sign(v)`, 0 at 0)
    #[inline(always)]
    pub fn abs(self) -> Self {
        let s = if self.v > 0.0 {
            1.0
        } else if self.v < 0.0 {
            -1.0
        } else {
            0.0
        };
        self.map(self.v.abs(), s)
    }
    /// `max(self, lo)` for a constant `lo`
    #[inline(always)]
    pub fn max_c(self, lo: f64) -> Self {
        if self.v >= lo { self } else { Self::c(lo) }
    }
}

impl<const S: usize> Add for Dual<S> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        let mut d = self.d;
        for k in 0..S {
            d[k] += o.d[k];
        }
        Dual { v: self.v + o.v, d }
    }
}
impl<const S: usize> Sub for Dual<S> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        let mut d = self.d;
        for k in 0..S {
            d[k] -= o.d[k];
        }
        Dual { v: self.v - o.v, d }
    }
}
impl<const S: usize> Mul for Dual<S> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        let mut d = [0.0; S];
        for k in 0..S {
            d[k] = self.d[k] * o.v + self.v * o.d[k];
        }
        Dual { v: self.v * o.v, d }
    }
}
impl<const S: usize> Div for Dual<S> {
    type Output = Self;
    #[inline(always)]
    fn div(self, o: Self) -> Self {
        let inv = 1.0 / o.v;
        let mut d = [0.0; S];
        for k in 0..S {
            d[k] = (self.d[k] - self.v * inv * o.d[k]) * inv;
        }
        Dual { v: self.v * inv, d }
    }
}
impl<const S: usize> Neg for Dual<S> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        self.map(-self.v, -1.0)
    }
}
impl<const S: usize> Mul<Dual<S>> for f64 {
    type Output = Dual<S>;
    #[inline(always)]
    fn mul(self, o: Dual<S>) -> Dual<S> {
        o.map(self * o.v, self)
    }
}
impl<const S: usize> Add<f64> for Dual<S> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: f64) -> Self {
        Dual { v: self.v + o, d: self.d }
    }
}
impl<const S: usize> Sub<f64> for Dual<S> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: f64) -> Self {
        Dual { v: self.v - o, d: self.d }
    }
}
impl<const S: usize> Mul<f64> for Dual<S> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, o: f64) -> Self {
        self.map(self.v * o, o)
    }
}

/// dot product of two dual 3-vectors
#[inline(always)]
pub fn dot<const S: usize>(a: &[Dual<S>; 3], b: &[Dual<S>; 3]) -> Dual<S> {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn derivatives_match_finite_differences() {
        // f(x, y) = sqrt(x^2 + y^2) / (1 + x y) at (0.7, 1.3), away from the pole at x y = -1
        let f = |x: Dual<2>, y: Dual<2>| (x * x + y * y).sqrt() / (Dual::c(1.0) + x * y);
        let (x, y) = (0.7, 1.3);
        let r = f(Dual::var(x, 0), Dual::var(y, 1));
        let g = |x: f64, y: f64| (x * x + y * y).sqrt() / (1.0 + x * y);
        let h = 1e-6;
        let fx = (g(x + h, y) - g(x - h, y)) / (2.0 * h);
        let fy = (g(x, y + h) - g(x, y - h)) / (2.0 * h);
        // Central differences with h = 1e-6: truncation ~h^2 f''' ~ 1e-12, rounding ~eps/h ~ 1e-10.
        assert!((r.d[0] - fx).abs() < 1e-8 && (r.d[1] - fy).abs() < 1e-8);
    }
}
