//! Forward-mode dual numbers with a fixed number of derivative slots: the exact Jacobian of the segment
//! forces (tension, Kelvin-Voigt friction, wind) with respect to the twelve inputs of a segment (positions
//! and velocities of its two end nodes), without hand-derived formulas.

use std::ops::{Add, Div, Mul, Neg, Sub};

/// number of derivative slots: `x_a, x_b, v_a, v_b` (3 each)
pub const SLOTS: usize = 12;

/// A value and its gradient with respect to the [`SLOTS`] inputs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct D {
    /// value
    pub v: f64,
    /// partial derivatives
    pub d: [f64; SLOTS],
}

impl D {
    /// a constant
    pub fn c(v: f64) -> D {
        D { v, d: [0.0; SLOTS] }
    }
    /// the input in slot `k`
    pub fn var(v: f64, k: usize) -> D {
        let mut d = [0.0; SLOTS];
        d[k] = 1.0;
        D { v, d }
    }
    fn map(self, v: f64, dv: f64) -> D {
        let mut d = self.d;
        for x in &mut d {
            *x *= dv;
        }
        D { v, d }
    }
    /// square root
    pub fn sqrt(self) -> D {
        let r = self.v.sqrt();
        self.map(r, 0.5 / r)
    }
    /// absolute value (derivative `sign(v)`, 0 at 0)
    pub fn abs(self) -> D {
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
    pub fn max_c(self, lo: f64) -> D {
        if self.v >= lo { self } else { D::c(lo) }
    }
}

impl Add for D {
    type Output = D;
    fn add(self, o: D) -> D {
        let mut d = self.d;
        for k in 0..SLOTS {
            d[k] += o.d[k];
        }
        D { v: self.v + o.v, d }
    }
}
impl Sub for D {
    type Output = D;
    fn sub(self, o: D) -> D {
        let mut d = self.d;
        for k in 0..SLOTS {
            d[k] -= o.d[k];
        }
        D { v: self.v - o.v, d }
    }
}
impl Mul for D {
    type Output = D;
    fn mul(self, o: D) -> D {
        let mut d = [0.0; SLOTS];
        for k in 0..SLOTS {
            d[k] = self.d[k] * o.v + self.v * o.d[k];
        }
        D { v: self.v * o.v, d }
    }
}
impl Div for D {
    type Output = D;
    fn div(self, o: D) -> D {
        let inv = 1.0 / o.v;
        let mut d = [0.0; SLOTS];
        for k in 0..SLOTS {
            d[k] = (self.d[k] - self.v * inv * o.d[k]) * inv;
        }
        D { v: self.v * inv, d }
    }
}
impl Neg for D {
    type Output = D;
    fn neg(self) -> D {
        self.map(-self.v, -1.0)
    }
}
impl Mul<D> for f64 {
    type Output = D;
    fn mul(self, o: D) -> D {
        o.map(self * o.v, self)
    }
}
impl Add<f64> for D {
    type Output = D;
    fn add(self, o: f64) -> D {
        D { v: self.v + o, d: self.d }
    }
}

/// dot product of two dual 3-vectors
pub fn dot(a: &[D; 3], b: &[D; 3]) -> D {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn derivatives_match_finite_differences() {
        // f(x, y) = sqrt(x^2 + y^2) / (1 + x y) at (0.7, 1.3), away from the pole at x y = -1
        let f = |x: D, y: D| (x * x + y * y).sqrt() / (D::c(1.0) + x * y);
        let (x, y) = (0.7, 1.3);
        let r = f(D::var(x, 0), D::var(y, 1));
        let g = |x: f64, y: f64| (x * x + y * y).sqrt() / (1.0 + x * y);
        let h = 1e-6;
        let fx = (g(x + h, y) - g(x - h, y)) / (2.0 * h);
        let fy = (g(x, y + h) - g(x, y - h)) / (2.0 * h);
        assert!((r.d[0] - fx).abs() < 1e-8 && (r.d[1] - fy).abs() < 1e-8);
    }
}
