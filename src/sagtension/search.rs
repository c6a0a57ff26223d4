//! Searches on a strung span: the knee-point temperature and the temperature of a given sag, each a
//! root in temperature of a function that is monotone across it, by the Illinois variant of regula
//! falsi (Dowell and Jarratt, BIT 11, 1971: bracketing like bisection, superlinear near a root).
//!
//! - knee: `g(theta) = e_max(theta) - e_slack(theta)`, the conductor strain at the more tensioned support
//!   less the strain below which the outer layers carry nothing ([`TwoMaterial::outer_slack_strain`]);
//!   positive while the aluminium carries load everywhere, negative once the whole span hangs on the
//!   core. Bare conductor, still air.
//! - sag: `sag_mid(theta) - sag`, increasing with temperature (a longer conductor sags more). Bare, still air.
//!
//! [`TwoMaterial::outer_slack_strain`]: crate::conductor::TwoMaterial::outer_slack_strain

use super::{SagTensionError, State, Strung, Weather};
use crate::exact::roots;

/// The searched temperature range [K]: -73 C to 527 C (beyond any conductor's rating).
pub const TEMPERATURE_RANGE_K: (f64, f64) = (200.0, 800.0);

/// A root of `f` in `[lo, hi]` with `f(lo) = f_lo`, `f(hi) = f_hi` of opposite signs (module doc;
/// [`crate::exact::roots::illinois`], at most 200 evaluations), to a bracket of `x_tol` or an exact zero:
/// the end of the last bracket with the smaller value.
pub fn illinois<F>(f: F, lo: f64, hi: f64, f_lo: f64, f_hi: f64, x_tol: f64) -> Result<f64, SagTensionError>
where
    F: FnMut(f64) -> Result<f64, SagTensionError>,
{
    if f_lo == 0.0 {
        return Ok(lo);
    }
    if f_hi == 0.0 {
        return Ok(hi);
    }
    if f_lo.signum() == f_hi.signum() {
        return Err(SagTensionError::NoSolution {
            what: "bracketed root",
            detail: format!("f({lo}) = {f_lo} and f({hi}) = {f_hi} have one sign"),
        });
    }
    let end = roots::illinois(f, lo, hi, f_lo, f_hi, x_tol, 200)?;
    match (end.zero, end.converged) {
        (Some(x), _) => Ok(x),
        (None, true) => Ok(if end.f_lo.abs() < end.f_hi.abs() { end.lo } else { end.hi }),
        (None, false) => Err(SagTensionError::NoSolution {
            what: "bracketed root",
            detail: format!("no convergence in [{}, {}]", end.lo, end.hi),
        }),
    }
}

impl Strung {
    /// The temperature [K] at which the outer layers of the bare span in `state` go slack everywhere: the
    /// knee point (module doc), to 1e-10 K.
    pub fn knee_temperature_k(&self, state: State) -> Result<f64, SagTensionError> {
        if self.problem.conductor.law.core.is_none() {
            return Err(SagTensionError::NotInRange {
                what: "knee point",
                low_k: TEMPERATURE_RANGE_K.0,
                high_k: TEMPERATURE_RANGE_K.1,
                detail: "a conductor of one material has none".into(),
            });
        }
        let law = &self.problem.conductor.law;
        let g = |theta: f64| -> Result<f64, SagTensionError> {
            let r = self.solve(&Weather::bare(theta), state)?;
            let (h, _) = self.histories.get(state)?;
            Ok(r.strain_max - law.outer_slack_strain(theta, &h))
        };
        self.root_in_temperature("knee point", g, 1e-10)
    }

    /// The temperature [K] at which the bare span in `state` reaches the mid-span sag `sag_m` [m] (a
    /// clearance `c` below a chord point at height `y` above ground is the sag `y - c`), to 1e-10 K.
    pub fn temperature_at_sag_k(&self, state: State, sag_m: f64) -> Result<f64, SagTensionError> {
        if !(sag_m.is_finite() && sag_m > 0.0) {
            return Err(SagTensionError::Invalid { what: "sag [m]", value: sag_m, allowed: "finite and > 0" });
        }
        let g = |theta: f64| -> Result<f64, SagTensionError> {
            Ok(sag_m - self.solve(&Weather::bare(theta), state)?.sag_midspan_m)
        };
        self.root_in_temperature("temperature at that sag", g, 1e-10)
    }

    fn root_in_temperature<F>(&self, what: &'static str, mut g: F, tol: f64) -> Result<f64, SagTensionError>
    where
        F: FnMut(f64) -> Result<f64, SagTensionError>,
    {
        let (lo, hi) = TEMPERATURE_RANGE_K;
        let (g_lo, g_hi) = (g(lo)?, g(hi)?);
        if g_lo < 0.0 || g_hi > 0.0 {
            return Err(SagTensionError::NotInRange {
                what,
                low_k: lo,
                high_k: hi,
                detail: format!("the function is {g_lo:e} and {g_hi:e} there (needs >= 0 and <= 0)"),
            });
        }
        illinois(g, lo, hi, g_lo, g_hi, tol)
    }
}
