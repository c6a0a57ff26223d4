//! Shared helpers of the integration tests.
#![allow(dead_code)]

pub mod doc_ranges;

use ohl::run::{Outcome, RunOptions, run};
use ohl::scenario;

/// The paper's test wire (section 4.1-4.2): axial stiffness "E = 80734 g" [N], wire plus ice
/// 1.0 kg/m, span 160 m, g = 9.81 m/s^2.
pub const EA_PAPER_N: f64 = 80734.0 * 9.81;
/// Linear density of the paper's iced test wire [kg/m].
pub const RHO_PAPER: f64 = 1.0;
/// Span [m].
pub const SPAN_M: f64 = 160.0;
/// Wind line load of section 4.1, `p = rho_air U^2 d / 2` with 1.225 kg/m^3, 20 m/s, d = 0.01553 m [N/m].
pub const P_PAPER_N_PER_M: f64 = 0.5 * 1.225 * 20.0 * 20.0 * 0.01553;

/// Parse and validate a scenario given as TOML text, panicking with the validation message if it is bad.
pub fn scenario(text: &str) -> ohl::scenario::Scenario {
    scenario::parse(text, "<test>").unwrap_or_else(|e| panic!("test scenario rejected: {e}"))
}

/// Run a scenario in memory (no files), recording the time series.
pub fn run_in_memory(text: &str) -> Outcome {
    let plan = scenario::plan(&scenario(text), "<test>").unwrap_or_else(|e| panic!("{e}"));
    run(plan, &RunOptions { out_dir: None, record: true }).unwrap_or_else(|e| panic!("run failed: {e}"))
}

/// Least-squares slope of log(err) against log(N): the observed order is minus this slope.
pub fn observed_order(ns: &[usize], errs: &[f64]) -> f64 {
    let xs: Vec<f64> = ns.iter().map(|&n| (n as f64).ln()).collect();
    let ys: Vec<f64> = errs.iter().map(|e| e.ln()).collect();
    let m = xs.len() as f64;
    let (mx, my) = (xs.iter().sum::<f64>() / m, ys.iter().sum::<f64>() / m);
    let sxy: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = xs.iter().map(|x| (x - mx).powi(2)).sum();
    -sxy / sxx
}

/// Composite 8-point Gauss-Legendre on `[a, b]` in `panels` equal panels (the table of Abramowitz and
/// Stegun 25.4, written here apart from the library's).
pub fn gauss_legendre(f: &dyn Fn(f64) -> f64, a: f64, b: f64, panels: usize) -> f64 {
    let x = [0.183_434_642_495_649_8, 0.525_532_409_916_329, 0.796_666_477_413_626_7, 0.960_289_856_497_536_3];
    let w = [0.362_683_783_378_362, 0.313_706_645_877_887_3, 0.222_381_034_453_374_5, 0.101_228_536_290_376_3];
    let h = (b - a) / panels as f64;
    let mut s = 0.0;
    for p in 0..panels {
        let (m, r) = (a + (p as f64 + 0.5) * h, 0.5 * h);
        for k in 0..4 {
            s += w[k] * r * (f(m - r * x[k]) + f(m + r * x[k]));
        }
    }
    s
}
