//! Celik's three-grid procedure: observed order, Richardson extrapolate and Grid Convergence Index.
//!
//! Source: I. B. Celik, U. Ghia, P. J. Roache, C. J. Freitas, H. Coleman, P. E. Raad, "Procedure for
//! estimation and reporting of uncertainty due to discretization in CFD applications", J. Fluids Eng. 130
//! (2008) 078001, steps 1-5; the factor of safety is Roache's (P. J. Roache, *Verification and Validation
//! in Computational Science and Engineering*, Hermosa 1998): `F_s = 1.25` for three or more grids,
//! `F_s = 3` for two.
//!
//! Three solutions `phi_1` (fine), `phi_2`, `phi_3` (coarse) on grids of representative size
//! `h_1 < h_2 < h_3` (here the segment length or the time step), `r_21 = h_2 / h_1`, `r_32 = h_3 / h_2`,
//! `eps_21 = phi_2 - phi_1`, `eps_32 = phi_3 - phi_2`, `s = sign(eps_32 / eps_21)`:
//!
//! ```text
//! p = [ ln|eps_32 / eps_21| + q(p) ] / ln r_21,   q(p) = ln( (r_21^p - s) / (r_32^p - s) )   (fixed point)
//! phi_ext = (r_21^p phi_1 - phi_2) / (r_21^p - 1)
//! e_a = |(phi_1 - phi_2) / phi_1|,   e_ext = |(phi_ext - phi_1) / phi_ext|
//! GCI_fine = F_s e_a / (r_21^p - 1)                                   (a relative band on phi_1)
//! ```
//!
//! With `r_21 = r_32` the iteration ends at once (`q = 0`). Celik writes `p = |...| / ln r_21`; the
//! absolute value hides a sequence whose differences grow under refinement, so the signed value is
//! kept and `p <= 0` (or an iteration that does not settle) is reported as [`Behaviour::Divergent`].
//! A negative ratio `eps_32 / eps_21 < 0` is oscillatory (Celik, step 4): no extrapolate and no GCI are
//! given, only the spread of the three values. Neither case is a number with an error bar.

use serde::Serialize;

/// Roache's factor of safety for a study of three or more grids (Roache 1998; Celik et al. 2008).
pub const SAFETY_FACTOR_THREE_GRIDS: f64 = 1.25;
/// Roache's factor of safety for two grids with an assumed order (Roache 1998).
pub const SAFETY_FACTOR_TWO_GRIDS: f64 = 3.0;

/// Iterations of the fixed-point order equation before it is declared unsettled (a settling iteration
/// takes fewer than 50 at any ratio above 1.1; the contraction factor is about `ln(r_32) / ln(r_21)`).
const MAX_ITERATIONS: usize = 500;
/// Relative change of `p` at which the iteration has settled.
const ORDER_TOLERANCE: f64 = 1e-12;

/// How a quantity behaves under refinement.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Behaviour {
    /// monotone with a positive observed order: extrapolate and GCI are given
    Converging,
    /// the differences change sign (`eps_32 / eps_21 < 0`): no extrapolate, the spread is the band
    Oscillatory,
    /// the differences grow under refinement (`p <= 0`) or the order equation has no settled root
    Divergent,
    /// the same value on every level (bitwise): a constant or an exact zero
    Constant,
    /// exactly one of the two differences is zero: no order can be observed
    Indeterminate,
}

impl Behaviour {
    /// The word of the tables.
    pub fn word(self) -> &'static str {
        match self {
            Behaviour::Converging => "converging",
            Behaviour::Oscillatory => "oscillatory",
            Behaviour::Divergent => "divergent",
            Behaviour::Constant => "constant",
            Behaviour::Indeterminate => "indeterminate",
        }
    }
}

/// Inputs that are no grid study.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum GciError {
    /// the sizes are not positive, finite and strictly increasing from fine to coarse
    #[error("grid sizes must be positive, finite and increase from the fine to the coarse level: {0:?}")]
    Sizes([f64; 3]),
    /// a solution is NaN or infinite
    #[error("a solution is not finite: {0:?}")]
    NotFinite([f64; 3]),
}

/// The estimate of one quantity from three levels.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Estimate {
    /// what the sequence does
    pub behaviour: Behaviour,
    /// the convergence ratio `eps_21 / eps_32` [-] (between 0 and 1: monotone convergence; negative:
    /// oscillatory; above 1: divergent); absent when `eps_32 = 0`
    pub ratio: Option<f64>,
    /// observed order `p` [-] (signed: negative is divergent); absent when it cannot be formed
    pub order: Option<f64>,
    /// Richardson extrapolate `phi_ext` (converging, or the constant)
    pub extrapolate: Option<f64>,
    /// `e_a = |(phi_1 - phi_2) / phi_1|` [-] (absent when `phi_1 = 0`)
    pub approx_rel_error: Option<f64>,
    /// `e_ext = |(phi_ext - phi_1) / phi_ext|` [-]
    pub extrapolated_rel_error: Option<f64>,
    /// fine-grid GCI, a relative band on `phi_1` [-] (converging or constant; absent when `phi_1 = 0`)
    pub gci_fine: Option<f64>,
    /// the same band in the quantity's unit: `F_s |phi_1 - phi_2| / (r_21^p - 1)`
    pub gci_fine_abs: Option<f64>,
    /// the factor of safety used [-]
    pub safety_factor: f64,
    /// largest minus least of the three values, in the quantity's unit (the band of an oscillatory one)
    pub spread: f64,
}

/// Celik's procedure on three levels: `h = [h_1, h_2, h_3]` fine to coarse, `phi` their solutions.
pub fn three_grid(h: [f64; 3], phi: [f64; 3]) -> Result<Estimate, GciError> {
    if !(h.iter().all(|x| x.is_finite() && *x > 0.0) && h[0] < h[1] && h[1] < h[2]) {
        return Err(GciError::Sizes(h));
    }
    if !phi.iter().all(|x| x.is_finite()) {
        return Err(GciError::NotFinite(phi));
    }
    let (r21, r32) = (h[1] / h[0], h[2] / h[1]);
    let (e21, e32) = (phi[1] - phi[0], phi[2] - phi[1]);
    let spread =
        phi.iter().cloned().fold(f64::NEG_INFINITY, f64::max) - phi.iter().cloned().fold(f64::INFINITY, f64::min);
    let none = |behaviour, ratio, order| Estimate {
        behaviour,
        ratio,
        order,
        extrapolate: None,
        approx_rel_error: relative(e21, phi[0]),
        extrapolated_rel_error: None,
        gci_fine: None,
        gci_fine_abs: None,
        safety_factor: SAFETY_FACTOR_THREE_GRIDS,
        spread,
    };
    if e21 == 0.0 && e32 == 0.0 {
        return Ok(Estimate {
            extrapolate: Some(phi[0]),
            extrapolated_rel_error: relative(0.0, phi[0]),
            gci_fine: relative(0.0, phi[0]),
            gci_fine_abs: Some(0.0),
            ..none(Behaviour::Constant, None, None)
        });
    }
    if e21 == 0.0 || e32 == 0.0 {
        return Ok(none(Behaviour::Indeterminate, (e32 != 0.0).then(|| e21 / e32), None));
    }
    let ratio = e21 / e32;
    if ratio < 0.0 {
        return Ok(none(Behaviour::Oscillatory, Some(ratio), order(r21, r32, e21, e32, -1.0)));
    }
    match order(r21, r32, e21, e32, 1.0) {
        Some(p) if p > 0.0 => Ok(with_order(phi[0], phi[1], r21, p, SAFETY_FACTOR_THREE_GRIDS, Some(ratio), spread)),
        p => Ok(none(Behaviour::Divergent, Some(ratio), p)),
    }
}

/// Two levels with an assumed (formal) order `p`: Richardson and the GCI with `F_s = 3` (Roache 1998).
pub fn two_grid(fine: f64, coarse: f64, r: f64, p: f64) -> Estimate {
    with_order(fine, coarse, r, p, SAFETY_FACTOR_TWO_GRIDS, None, (fine - coarse).abs())
}

/// Extrapolate and GCI of a converging quantity with order `p`.
fn with_order(phi1: f64, phi2: f64, r21: f64, p: f64, fs: f64, ratio: Option<f64>, spread: f64) -> Estimate {
    let rp1 = r21.powf(p) - 1.0;
    let ext = phi1 + (phi1 - phi2) / rp1;
    let abs = fs * (phi1 - phi2).abs() / rp1;
    Estimate {
        behaviour: Behaviour::Converging,
        ratio,
        order: Some(p),
        extrapolate: Some(ext),
        approx_rel_error: relative(phi1 - phi2, phi1),
        extrapolated_rel_error: relative(ext - phi1, ext),
        gci_fine: relative(abs, phi1),
        gci_fine_abs: Some(abs),
        safety_factor: fs,
        spread,
    }
}

/// `|num / den|`, absent for a zero denominator.
fn relative(num: f64, den: f64) -> Option<f64> {
    (den != 0.0).then(|| (num / den).abs())
}

/// The signed observed order by Celik's fixed point with sign `s`, or None if it does not settle.
fn order(r21: f64, r32: f64, e21: f64, e32: f64, s: f64) -> Option<f64> {
    let lead = (e32 / e21).abs().ln();
    let mut p = lead / r21.ln();
    if (r21 - r32).abs() <= 1e-12 * r21 {
        return Some(p);
    }
    for _ in 0..MAX_ITERATIONS {
        let (a, b) = (r21.powf(p) - s, r32.powf(p) - s);
        if !(a > 0.0 && b > 0.0) {
            return None;
        }
        let next = (lead + (a / b).ln()) / r21.ln();
        if !next.is_finite() {
            return None;
        }
        if (next - p).abs() <= ORDER_TOLERANCE * p.abs().max(1.0) {
            return Some(next);
        }
        p = next;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Celik et al. (2008), Table 1, first column (dimensionless reattachment length on 2D grids of
    /// 18000, 8000, 4500 cells, `h = N^(-1/2)`): printed p = 1.53, phi_ext = 6.1685, e_a = 1.5 %,
    /// e_ext = 1.7 %, GCI = 2.2 %. Tolerances: half a unit of the last printed digit.
    #[test]
    fn celik_table_1_first_column() {
        let h = [18000.0_f64, 8000.0, 4500.0].map(|n| n.powf(-0.5));
        let e = three_grid(h, [6.063, 5.972, 5.863]).unwrap();
        assert_eq!(e.behaviour, Behaviour::Converging);
        let p = e.order.unwrap();
        assert!((p - 1.53).abs() <= 0.005, "p = {p}");
        let ext = e.extrapolate.unwrap();
        assert!((ext - 6.1685).abs() <= 0.00005, "phi_ext = {ext}");
        let pct = |x: Option<f64>| 100.0 * x.unwrap();
        assert!((pct(e.approx_rel_error) - 1.5).abs() <= 0.05);
        assert!((pct(e.extrapolated_rel_error) - 1.7).abs() <= 0.05);
        assert!((pct(e.gci_fine) - 2.2).abs() <= 0.05);
        assert_eq!(e.safety_factor, 1.25);
    }

    /// f = f0 + C h^2 exactly: p = 2 and the extrapolate f0 to rounding (relative 1e-12: a few ulps of the
    /// differences, amplified by 1 / (r^p - 1) = 1/3), at equal and at unequal ratios (the fixed point).
    #[test]
    fn manufactured_second_order_sequence() {
        let f = |h: f64| 7.5 - 3.0 * h * h;
        for h in [[0.1, 0.2, 0.4], [0.1, 0.15, 0.2]] {
            let e = three_grid(h, h.map(f)).unwrap();
            assert_eq!(e.behaviour, Behaviour::Converging);
            assert!((e.order.unwrap() - 2.0).abs() < 1e-9, "{:?}", e.order);
            assert!((e.extrapolate.unwrap() - 7.5).abs() < 1e-12 * 7.5);
            // the band holds the true error of the fine level: here it is F_s = 1.25 times it
            let true_err = ((f(h[0]) - 7.5) / f(h[0])).abs();
            assert!((e.gci_fine.unwrap() / true_err - 1.25).abs() < 1e-9);
        }
    }

    /// A first-order sequence with a second-order remainder: the observed order tends to 1 as h falls.
    #[test]
    fn first_order_with_remainder() {
        let f = |h: f64| 1.0 + 0.5 * h + 0.05 * h * h;
        let e = three_grid([0.01, 0.02, 0.04], [0.01, 0.02, 0.04].map(f)).unwrap();
        // three-grid order of a + b h + c h^2: log2((1 + 6 beta)/(1 + 3 beta)), beta = c h_1 / a = 1e-3
        let expected = ((1.0 + 6e-3) / (1.0 + 3e-3_f64)).log2() + 1.0;
        assert!((e.order.unwrap() - expected).abs() < 1e-9);
    }

    #[test]
    fn oscillatory_sequence_has_no_error_bar() {
        let e = three_grid([1.0, 2.0, 4.0], [10.0, 10.4, 9.9]).unwrap();
        assert_eq!(e.behaviour, Behaviour::Oscillatory);
        assert!(e.extrapolate.is_none() && e.gci_fine.is_none());
        assert!((e.spread - 0.5).abs() < 1e-12);
        assert!(e.ratio.unwrap() < 0.0);
    }

    #[test]
    fn divergent_sequence_is_said() {
        // differences growing under refinement: 0.1 then 0.4
        let e = three_grid([1.0, 2.0, 4.0], [10.5, 10.1, 10.0]).unwrap();
        assert_eq!(e.behaviour, Behaviour::Divergent);
        assert!((e.order.unwrap() + 2.0).abs() < 1e-12, "{:?}", e.order);
        assert!(e.extrapolate.is_none() && e.gci_fine.is_none());
        // the same at unequal ratios (through the iteration)
        let e = three_grid([1.0, 1.5, 2.0], [10.5, 10.1, 10.0]).unwrap();
        assert_eq!(e.behaviour, Behaviour::Divergent);
    }

    #[test]
    fn constant_indeterminate_and_bad_input() {
        let e = three_grid([1.0, 2.0, 4.0], [0.0; 3]).unwrap();
        assert_eq!(e.behaviour, Behaviour::Constant);
        assert_eq!(e.gci_fine_abs, Some(0.0));
        assert_eq!(e.gci_fine, None, "no relative band on an exact zero");
        let e = three_grid([1.0, 2.0, 4.0], [3.0, 3.0, 2.0]).unwrap();
        assert_eq!(e.behaviour, Behaviour::Indeterminate);
        assert!(three_grid([2.0, 1.0, 4.0], [1.0, 2.0, 3.0]).is_err());
        assert!(three_grid([1.0, 2.0, 4.0], [1.0, f64::NAN, 3.0]).is_err());
    }

    /// Two grids: the assumed order with F_s = 3 (Roache).
    #[test]
    fn two_grid_uses_safety_factor_three() {
        let e = two_grid(1.01, 1.04, 2.0, 2.0);
        assert!((e.extrapolate.unwrap() - 1.0).abs() < 1e-12);
        assert!((e.gci_fine_abs.unwrap() - 3.0 * 0.03 / 3.0).abs() < 1e-12);
    }
}
