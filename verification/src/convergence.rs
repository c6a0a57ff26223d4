//! Grid-convergence arithmetic: least-squares observed order, Richardson extrapolation and the Grid
//! Convergence Index.
//!
//! * Observed order from errors `e_k` on grids of size `h_k`: the least-squares slope `p` of
//!   `ln e = ln C + p ln h`.
//! * From three solutions `phi_1` (fine), `phi_2`, `phi_3` (coarse) with a constant refinement ratio `r`,
//!   Roache's / Celik's order `p = ln |(phi_3 - phi_2) / (phi_2 - phi_1)| / ln r` (no exact answer
//!   needed), the Richardson extrapolate `phi_ext = (r^p phi_1 - phi_2) / (r^p - 1)` and the fine-grid
//!   GCI `= F_s |(phi_1 - phi_2) / phi_1| / (r^p - 1)` with safety factor `F_s = 1.25` (Celik et al.,
//!   "Procedure for estimation and reporting of uncertainty due to discretization in CFD applications",
//!   J. Fluids Eng. 130 (2008) 078001; Roache 1998). The GCI is a relative error band on `phi_1`.

/// Safety factor of the GCI for a three-grid study (Roache 1998; Celik et al. 2008).
pub const GCI_SAFETY_FACTOR: f64 = 1.25;

/// Least-squares slope of `ln e` against `ln h`: the observed order (positive when `e` falls with `h`).
pub fn ls_order(h: &[f64], e: &[f64]) -> f64 {
    assert_eq!(h.len(), e.len());
    let xs: Vec<f64> = h.iter().map(|v| v.ln()).collect();
    let ys: Vec<f64> = e.iter().map(|v| v.ln()).collect();
    let m = xs.len() as f64;
    let (mx, my) = (xs.iter().sum::<f64>() / m, ys.iter().sum::<f64>() / m);
    let sxy: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = xs.iter().map(|x| (x - mx).powi(2)).sum();
    sxy / sxx
}

/// Order of each consecutive pair, `ln(e_k / e_{k+1}) / ln(h_k / h_{k+1})`.
pub fn pair_orders(h: &[f64], e: &[f64]) -> Vec<f64> {
    (1..h.len()).map(|k| (e[k - 1] / e[k]).ln() / (h[k - 1] / h[k]).ln()).collect()
}

/// Result of a three-grid study.
#[derive(Clone, Copy, Debug)]
pub struct Gci {
    /// order used [-]
    pub order: f64,
    /// Richardson extrapolate `phi_ext`
    pub extrapolated: f64,
    /// approximate relative error `|(phi_1 - phi_2) / phi_1|` [-]
    pub approx_rel_error: f64,
    /// fine-grid GCI, a relative error band on `phi_1` [-]
    pub gci_fine: f64,
}

/// Celik's order from three solutions (fine, medium, coarse) with ratio `r`.
pub fn three_grid_order(fine: f64, medium: f64, coarse: f64, r: f64) -> f64 {
    ((coarse - medium) / (medium - fine)).abs().ln() / r.ln()
}

/// Richardson extrapolate and GCI from the two finest solutions, ratio `r` and order `p`.
pub fn gci(fine: f64, medium: f64, r: f64, p: f64) -> Gci {
    let rp = r.powf(p);
    let ea = ((fine - medium) / fine).abs();
    Gci {
        order: p,
        extrapolated: (rp * fine - medium) / (rp - 1.0),
        approx_rel_error: ea,
        gci_fine: GCI_SAFETY_FACTOR * ea / (rp - 1.0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn recovers_order_and_limit_of_a_known_sequence() {
        // phi(h) = 3 + 0.7 h^2 + 0.1 h^3: order -> 2, extrapolate -> 3 up to the h^3 term.
        let f = |h: f64| 3.0 + 0.7 * h * h + 0.1 * h * h * h;
        let h = [0.04, 0.02, 0.01];
        let e: Vec<f64> = h.iter().map(|&x| f(x) - 3.0).collect();
        assert!((ls_order(&h, &e) - 2.0).abs() < 0.01);
        let p = three_grid_order(f(0.01), f(0.02), f(0.04), 2.0);
        assert!((p - 2.0).abs() < 0.02, "{p}");
        let g = gci(f(0.01), f(0.02), 2.0, 2.0);
        // Extrapolation removes the h^2 term: the remainder is O(h^3) = 1e-7 scale.
        assert!((g.extrapolated - 3.0).abs() < 2e-7);
        // The band covers the true error of the fine solution.
        assert!(((f(0.01) - 3.0) / f(0.01)).abs() < g.gci_fine);
    }
}
