//! The factor `psi` of the tensile force `F_t = F_st (1 + phi psi)` (eq. (33)): the root in `[0, 1]` of
//!
//! ```text
//! p(psi) = phi^2 psi^3 + phi (2 + zeta) psi^2 + (1 + 2 zeta) psi - zeta (2 + phi) = 0
//! ```
//!
//! (IEC 60865-1:2011 gives `psi(phi, zeta)` as a figure and this equation in its Annex A; the same
//! equation is in the 1993 edition, Meyer, Herold & Zeitler 1994, and in the public implementation
//! Kalandoros/Kurzschlussfestigkeit). For `phi, zeta >= 0` every coefficient of a positive power of `psi`
//! is non-negative, so `p` is increasing on `[0, 1]`, with `p(0) = -zeta (2 + phi) <= 0` and
//! `p(1) = (1 + phi)^2 > 0`: exactly one root, found by the safeguarded Newton / bisection of
//! [`crate::exact::roots::solve_bracketed`]. `zeta = 0` (a rigid span) gives `psi = 0`.

use crate::exact::roots::{Options1d, solve_bracketed};

/// `psi` in `[0, 1)` for `phi >= 0`, `zeta >= 0` (both finite); `None` only if the root finder fails,
/// which the bracket rules out.
pub fn psi(phi: f64, zeta: f64) -> Option<f64> {
    let p = |x: f64| {
        let value = ((phi * phi * x + phi * (2.0 + zeta)) * x + (1.0 + 2.0 * zeta)) * x - zeta * (2.0 + phi);
        let slope = (3.0 * phi * phi * x + 2.0 * phi * (2.0 + zeta)) * x + (1.0 + 2.0 * zeta);
        (value, slope)
    };
    if zeta == 0.0 {
        return Some(0.0);
    }
    let opts = Options1d { x_rel_tol: 1e-15, x_abs_tol: 1e-16, max_iterations: 300 };
    solve_bracketed(p, 0.0, 1.0, opts).ok()
}

#[cfg(test)]
mod tests {
    use super::psi;

    /// The root satisfies the cubic to rounding, lies in (0, 1), and for `phi -> 0` tends to the root of
    /// the linear remainder `(1 + 2 zeta) psi = 2 zeta`, i.e. `2 zeta / (1 + 2 zeta)` (exact).
    #[test]
    fn root_of_the_cubic() {
        for &(phi, zeta) in &[(9.72, 3.84), (1.495, 2.04), (0.01, 0.5), (20.0, 0.001), (3.0, 100.0)] {
            let x = psi(phi, zeta).unwrap();
            assert!(x > 0.0 && x < 1.0, "psi({phi}, {zeta}) = {x}");
            let r = phi * phi * x.powi(3) + phi * (2.0 + zeta) * x * x + (1.0 + 2.0 * zeta) * x - zeta * (2.0 + phi);
            assert!(r.abs() < 1e-12 * (1.0 + zeta * (2.0 + phi)), "residual {r}");
        }
        let zeta = 0.7;
        assert!((psi(0.0, zeta).unwrap() - 2.0 * zeta / (1.0 + 2.0 * zeta)).abs() < 1e-14);
        assert_eq!(psi(5.0, 0.0), Some(0.0));
    }

    /// `psi` grows with `zeta` (a softer span takes more of the swing energy into tension) and falls with
    /// `phi`, which the bracketed root must reproduce on a grid.
    #[test]
    fn monotone_in_zeta_and_phi() {
        let mut last = 0.0;
        for k in 1..50 {
            let x = psi(2.0, 0.1 * k as f64).unwrap();
            assert!(x > last);
            last = x;
        }
        let mut last = 1.0;
        for k in 1..50 {
            let x = psi(0.2 * k as f64, 1.0).unwrap();
            assert!(x < last);
            last = x;
        }
    }
}
