//! Constitutive law of a segment: the Kelvin-Voigt relation (3.4),
//!
//! ```text
//! T_{i+1/2} = EA e_{i+1/2} + eta de_{i+1/2}/dt,      e = |r_{i+1} - r_i| / l0_{i+1/2} - 1,
//! ```
//!
//! where `EA` [N] is the axial stiffness, `eta` [N s] the internal-friction coefficient and `l0` [m] the
//! stress-free length of the segment (which thermal strain scales). A conductor cannot carry compression,
//! so the default law is tension-only: a slack segment (`e <= 0`) carries nothing, and the viscous part may
//! reduce the tension to zero but never make it negative (paper section 2: "e >= 0 under tension";
//! docs/paper_notes.md, "Compression"). The linear law, compression allowed, exists for analytic tests.
//!
//! The law is a type parameter of the time step, so the choice is made once per run and the node loop
//! has no branch on it. It is written once over a [`Scalar`]: the kernel evaluates it on `f64`, the static
//! solver's Jacobian on dual numbers ([`super::segment`]).

use super::scalar::Scalar;

/// A segment's constitutive law, evaluated inside the hot loop (so: `#[inline(always)]`, branch-free).
pub trait TensionLaw: Copy {
    /// Tension `T` [N] for strain `e` [-] and strain rate `edot` [1/s], with axial stiffness `ea` [N]
    /// and internal friction `eta` [N s].
    fn tension<S: Scalar>(ea: f64, eta: f64, e: S, edot: S) -> S;
    /// Stored elastic energy per unit stress-free length [J/m] at strain `e`.
    fn energy_density(ea: f64, e: f64) -> f64;
    /// An integer that orders tensions of this law like the numbers (for the kernel's largest-tension
    /// reduction, which vectorises over integers, not over floats). Inverse: [`from_order_key`].
    fn order_key(t: f64) -> i64 {
        order_key(t)
    }
}

/// An integer whose order is the order of the `f64` `x` (total order: `-0 < +0`, NaN above infinity for
/// a positive-signed NaN): the bits, with the magnitude bits flipped for negative numbers.
#[inline(always)]
pub fn order_key(x: f64) -> i64 {
    let b = x.to_bits() as i64;
    b ^ (((b >> 63) as u64) >> 1) as i64
}

/// The inverse of [`order_key`] (and of every [`TensionLaw::order_key`]).
#[inline(always)]
pub fn from_order_key(k: i64) -> f64 {
    f64::from_bits((k ^ (((k >> 63) as u64) >> 1) as i64) as u64)
}

/// Tension-only Kelvin-Voigt law: `T = max(EA e + eta edot, 0)` for `e > 0`, `T = 0` for `e <= 0`.
#[derive(Clone, Copy, Debug, Default)]
pub struct TensionOnly;

/// Linear Kelvin-Voigt law `T = EA e + eta edot`, compression allowed (for analytic tests).
#[derive(Clone, Copy, Debug, Default)]
pub struct Linear;

impl TensionLaw for TensionOnly {
    #[inline(always)]
    fn tension<S: Scalar>(ea: f64, eta: f64, e: S, edot: S) -> S {
        let t = (e * ea + edot * eta).positive_part();
        if e.value() > 0.0 { t } else { S::c(0.0) }
    }
    #[inline(always)]
    fn energy_density(ea: f64, e: f64) -> f64 {
        let ep = e.max(0.0);
        0.5 * ea * ep * ep
    }
    /// A tension-only tension is `+0`, `-0` or positive: its bits order it as they are (`-0` has the
    /// smallest key, and the key of a non-negative number is its [`order_key`]).
    #[inline(always)]
    fn order_key(t: f64) -> i64 {
        t.to_bits() as i64
    }
}

impl TensionLaw for Linear {
    #[inline(always)]
    fn tension<S: Scalar>(ea: f64, eta: f64, e: S, edot: S) -> S {
        e * ea + edot * eta
    }
    #[inline(always)]
    fn energy_density(ea: f64, e: f64) -> f64 {
        0.5 * ea * e * e
    }
}

/// Which law a run uses; the time step dispatches on it once per step, outside the node loop.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LawKind {
    /// [`TensionOnly`]: slack segments carry nothing (default; a conductor cannot be compressed).
    TensionOnly,
    /// [`Linear`]: compression allowed.
    Linear,
    /// the two-material law of a real conductor with each segment's history
    /// ([`crate::wire::material`]; the wire holds it, [`crate::wire::Wire::set_two_material`])
    TwoMaterial,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tension_only_is_zero_when_slack_and_never_negative() {
        assert_eq!(TensionOnly::tension(1.0e6, 10.0, -1.0e-3, 0.0), 0.0);
        // Stretched but relaxing fast: the viscous part cannot push.
        assert_eq!(TensionOnly::tension(1.0e6, 10.0, 1.0e-4, -1.0e3), 0.0);
        assert_eq!(TensionOnly::tension(1.0e6, 10.0, 1.0e-3, 2.0), 1.0e3 + 20.0);
        assert_eq!(Linear::tension(1.0e6, 0.0, -1.0e-3, 0.0), -1.0e3);
    }

    #[test]
    fn energy_density_is_the_integral_of_the_elastic_tension() {
        // W(e) = int_0^e EA e' de' = EA e^2 / 2 ; check by the midpoint rule with 1000 panels (exact for
        // a linear integrand up to rounding).
        let (ea, e) = (7.9e5, 4.0e-3);
        let n = 1000;
        let h = e / n as f64;
        let w: f64 = (0..n).map(|k| TensionOnly::tension(ea, 0.0, (k as f64 + 0.5) * h, 0.0) * h).sum();
        assert!((w - TensionOnly::energy_density(ea, e)).abs() < 1e-12 * w);
        assert_eq!(TensionOnly::energy_density(ea, -e), 0.0);
        assert_eq!(Linear::energy_density(ea, -e), Linear::energy_density(ea, e));
    }
}
