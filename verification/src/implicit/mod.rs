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
use faer::sparse::linalg::solvers::{Lu, SymbolicLu};
use faer::sparse::{Argsort, Pair, SparseColMat, SymbolicSparseColMat};

/// Sparse LU of matrices that share one pattern (the Jacobian's, which depends only on which nodes are
/// free): the compressed structure, the order that sums duplicate entries, and the symbolic factorisation
/// (fill-reducing ordering, elimination structure) are computed once by [`SparseLu::new`]; each
/// [`SparseLu::solve`] only fills the values and factors numerically.
#[derive(Clone, Debug)]
pub struct SparseLu {
    n: usize,
    entries: usize,
    structure: SymbolicSparseColMat<usize>,
    order: Argsort<usize>,
    symbolic: SymbolicLu<usize>,
}

impl SparseLu {
    /// The solver for `n x n` matrices with entries at `pattern` (in assembly order; repeated positions
    /// are summed).
    pub fn new(n: usize, pattern: &[Pair<usize, usize>]) -> Result<Self, String> {
        let (structure, order) =
            SymbolicSparseColMat::try_new_from_indices(n, n, pattern).map_err(|e| format!("{e:?}"))?;
        let symbolic = SymbolicLu::try_new(structure.as_ref()).map_err(|e| format!("symbolic LU failed: {e:?}"))?;
        Ok(SparseLu { n, entries: pattern.len(), structure, order, symbolic })
    }

    /// Solve `A x = b` where `values` are the entries of `A` in the order of the pattern.
    ///
    /// # Panics
    /// If `values` or `b` do not match the pattern and the size (internal misuse).
    pub fn solve(&self, values: &[f64], b: &[f64]) -> Result<Vec<f64>, String> {
        assert_eq!(values.len(), self.entries, "one value per pattern entry");
        assert_eq!(b.len(), self.n, "one right-hand side per unknown");
        let a = SparseColMat::new_from_argsort(self.structure.clone(), &self.order, values)
            .map_err(|e| format!("{e:?}"))?;
        let lu = Lu::try_new_with_symbolic(self.symbolic.clone(), a.as_ref())
            .map_err(|e| format!("sparse LU failed: {e:?}"))?;
        let x = lu.solve(Mat::from_fn(self.n, 1, |i, _| b[i]));
        let out: Vec<f64> = (0..self.n).map(|i| x[(i, 0)]).collect();
        if out.iter().all(|v| v.is_finite()) { Ok(out) } else { Err("singular Jacobian".into()) }
    }
}
