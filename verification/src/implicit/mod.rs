//! Implicit reference solvers on the *same discrete equations* as the explicit scheme.
//!
//! The discrete force on free node `i` (module doc of `ohl::scheme::explicit`),
//!
//! ```text
//! F_i(x, v) = T_{i+1/2} t_{i+1/2} - T_{i-1/2} t_{i-1/2} + (P_{i+1/2} + P_{i-1/2}) / 2 + q L - m_i g e3,
//! ```
//!
//! is evaluated by the library itself (`Explicit::net_force`, with the Kelvin-Voigt rate and the wind
//! damping (2.6) taken from the velocities handed to it), so the implicit solvers cannot drift from the
//! kernel's equations. Only the Jacobian is assembled here, exactly, by forward-mode differentiation
//! ([`crate::dual`]) of a segment-by-segment replica of the kernel's formulas ([`jacobian`]); a wrong
//! replica would show up as lost quadratic convergence of Newton's method, and [`jacobian::replica_gap`]
//! checks the replica's values against the library to rounding. The Jacobian is block-tridiagonal (3x3
//! blocks, one block row per free node) and is factored by faer's sparse LU.
//!
//! * [`newton`]: static equilibrium `F(x, 0) = 0` by Newton's method with a backtracking line search.
//! * [`newmark`]: Newmark's average-acceleration rule (trapezoidal, second order, unconditionally stable
//!   for linear problems) with Newton iterations on each step.

pub mod jacobian;
pub mod newmark;
pub mod newton;

use faer::Mat;
use faer::linalg::solvers::Solve;
use faer::sparse::{SparseColMat, Triplet};
use std::collections::BTreeMap;

/// Solve the sparse system given by accumulated entries `(row, col) -> value` with right side `b`.
pub fn sparse_solve(n: usize, entries: &BTreeMap<(usize, usize), f64>, b: &[f64]) -> Result<Vec<f64>, String> {
    let trips: Vec<Triplet<usize, usize, f64>> = entries.iter().map(|(&(r, c), &v)| Triplet::new(r, c, v)).collect();
    let a = SparseColMat::<usize, f64>::try_new_from_triplets(n, n, &trips).map_err(|e| format!("{e:?}"))?;
    let lu = a.sp_lu().map_err(|e| format!("sparse LU failed: {e:?}"))?;
    let rhs = Mat::from_fn(n, 1, |i, _| b[i]);
    let x = lu.solve(&rhs);
    let out: Vec<f64> = (0..n).map(|i| x[(i, 0)]).collect();
    if out.iter().all(|v| v.is_finite()) { Ok(out) } else { Err("singular Jacobian".into()) }
}
