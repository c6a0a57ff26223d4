//! The number type of a force element: `f64` for the explicit kernel and the diagnostics, forward-mode
//! dual numbers ([`crate::statics::dual::Dual`]) for the exact Jacobian of the static solver. A force
//! element written once over [`Scalar`] serves all three, so they cannot drift apart.

use crate::statics::dual::Dual;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A real number with the operations the force elements need.
///
/// Mixed operations with an `f64` constant (`x * k`, `x + k`, `x - k`) are part of the trait, so that a
/// formula written once costs no derivative work for its constants on dual numbers and, on `f64`, is the
/// very expression the kernel evaluates (same operations in the same order, hence the same bits).
pub trait Scalar:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + Mul<f64, Output = Self>
    + Add<f64, Output = Self>
    + Sub<f64, Output = Self>
{
    /// a constant (no derivative)
    fn c(v: f64) -> Self;
    /// the value
    fn value(self) -> f64;
    /// square root
    fn sqrt(self) -> Self;
    /// `max(self, 0)` (derivative 0 where the value is not positive)
    fn positive_part(self) -> Self;
    /// `|self|` (derivative `sign(self)`, 0 at 0)
    fn abs(self) -> Self;
    /// `max(self, lo)` for a constant `lo` (derivative 0 where the constant is taken)
    fn max_c(self, lo: f64) -> Self;
    /// A zero with the sign of the product `self * o` (a constant: no derivative), which is what the
    /// product of `self`, `+0` and `o` is for finite numbers, without the multiplications.
    fn zero_signed_by(self, o: Self) -> Self;
}

impl Scalar for f64 {
    #[inline(always)]
    fn c(v: f64) -> Self {
        v
    }
    #[inline(always)]
    fn value(self) -> f64 {
        self
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        f64::sqrt(self)
    }
    #[inline(always)]
    fn positive_part(self) -> Self {
        self.max(0.0)
    }
    #[inline(always)]
    fn abs(self) -> Self {
        f64::abs(self)
    }
    #[inline(always)]
    fn max_c(self, lo: f64) -> Self {
        self.max(lo)
    }
    #[inline(always)]
    fn zero_signed_by(self, o: Self) -> Self {
        f64::from_bits((self.to_bits() ^ o.to_bits()) & (1 << 63))
    }
}

impl<const S: usize> Scalar for Dual<S> {
    #[inline(always)]
    fn c(v: f64) -> Self {
        Dual::c(v)
    }
    #[inline(always)]
    fn value(self) -> f64 {
        self.v
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        Dual::sqrt(self)
    }
    #[inline(always)]
    fn positive_part(self) -> Self {
        if self.v > 0.0 { self } else { Dual::c(0.0) }
    }
    #[inline(always)]
    fn abs(self) -> Self {
        Dual::abs(self)
    }
    #[inline(always)]
    fn max_c(self, lo: f64) -> Self {
        Dual::max_c(self, lo)
    }
    #[inline(always)]
    fn zero_signed_by(self, o: Self) -> Self {
        Dual::c(self.v.zero_signed_by(o.v))
    }
}

/// `a - b` componentwise.
#[inline(always)]
pub fn sub3<S: Scalar>(a: [S; 3], b: [S; 3]) -> [S; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `a . b`.
#[inline(always)]
pub fn dot3<S: Scalar>(a: [S; 3], b: [S; 3]) -> S {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
