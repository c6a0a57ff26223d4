//! Sparse LU of matrices that share one pattern (the Jacobian's, which depends only on which nodes are
//! free), on faer.
//!
//! [`SparseLu::new`] does everything that depends on the pattern alone, once: the compressed column
//! structure, the slot of each pattern entry in it (repeated positions are summed), the symbolic
//! factorisation (fill-reducing column ordering, elimination structure) and the workspace.
//! [`SparseLu::solve`] then only scatters the values, factors numerically into storage kept from the
//! previous call, and solves: no allocation after the first call.

use faer::dyn_stack::{MemBuffer, MemStack, StackReq};
use faer::linalg::lu::partial_pivoting::factor::PartialPivLuParams;
use faer::sparse::linalg::lu::{LuSymbolicParams, NumericLu, SymbolicLu, factorize_symbolic_lu};
use faer::sparse::linalg::{LuError, SupernodalThreshold};
use faer::sparse::{Pair, SparseColMatRef, SymbolicSparseColMatRef};
use faer::{Conj, MatMut, Par, Spec};

/// Why a sparse factorisation or solve failed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SparseLuError {
    /// The pattern is malformed (an index out of range) or the symbolic analysis failed.
    #[error("sparse pattern rejected: {0}")]
    Pattern(String),
    /// A pivot vanished or the solution is not finite: the matrix is singular to working precision.
    #[error("matrix is singular to working precision")]
    Singular,
}

/// The cached factorisation; see the module doc.
pub struct SparseLu {
    n: usize,
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
    /// slot in the compressed values of each pattern entry
    slot: Vec<usize>,
    csc: Vec<f64>,
    symbolic: SymbolicLu<usize>,
    numeric: NumericLu<usize, f64>,
    mem: MemBuffer,
    req: StackReq,
    par: Par,
}

impl std::fmt::Debug for SparseLu {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SparseLu").field("n", &self.n).field("nnz", &self.row_idx.len()).finish_non_exhaustive()
    }
}

impl Clone for SparseLu {
    fn clone(&self) -> Self {
        SparseLu {
            n: self.n,
            col_ptr: self.col_ptr.clone(),
            row_idx: self.row_idx.clone(),
            slot: self.slot.clone(),
            csc: self.csc.clone(),
            symbolic: self.symbolic.clone(),
            numeric: self.numeric.clone(),
            mem: MemBuffer::new(self.req),
            req: self.req,
            par: self.par,
        }
    }
}

impl SparseLu {
    /// The solver for `n x n` matrices with entries at `pattern` (in assembly order; repeated positions
    /// are summed), factored with the parallelism `par` (`Par::Seq` for one thread).
    pub fn new(n: usize, pattern: &[Pair<usize, usize>], par: Par) -> Result<Self, SparseLuError> {
        if let Some(p) = pattern.iter().find(|p| p.row >= n || p.col >= n) {
            return Err(SparseLuError::Pattern(format!("entry ({}, {}) outside {n} x {n}", p.row, p.col)));
        }
        // Order the entries by (column, row) in linear time: a counting sort by column, then a sort of
        // each column's few entries by row; merge repeats and remember where each entry went.
        let mut start = vec![0usize; n + 1];
        for p in pattern {
            start[p.col + 1] += 1;
        }
        for c in 0..n {
            start[c + 1] += start[c];
        }
        let mut order = vec![0usize; pattern.len()];
        let mut next = start.clone();
        for (e, p) in pattern.iter().enumerate() {
            order[next[p.col]] = e;
            next[p.col] += 1;
        }
        let mut col_ptr = vec![0usize; n + 1];
        let mut row_idx = Vec::with_capacity(pattern.len());
        let mut slot = vec![0usize; pattern.len()];
        for c in 0..n {
            let entries = &mut order[start[c]..start[c + 1]];
            entries.sort_unstable_by_key(|&e| pattern[e].row);
            let mut last = None;
            for &e in entries.iter() {
                if last != Some(pattern[e].row) {
                    row_idx.push(pattern[e].row);
                    last = Some(pattern[e].row);
                }
                slot[e] = row_idx.len() - 1;
            }
            col_ptr[c + 1] = row_idx.len();
        }
        let structure = SymbolicSparseColMatRef::new_checked(n, n, &col_ptr, None, &row_idx);
        // Simplicial (column-by-column) factorisation: the Jacobian is banded with 3x3 blocks, too thin
        // for supernodes to pay for their symbolic analysis and dense-block overhead.
        let params = LuSymbolicParams {
            supernodal_flop_ratio_threshold: SupernodalThreshold::FORCE_SIMPLICIAL,
            ..Default::default()
        };
        let symbolic = factorize_symbolic_lu(structure, params)
            .map_err(|e| SparseLuError::Pattern(format!("symbolic LU failed: {e:?}")))?;
        let params: Spec<PartialPivLuParams, f64> = Default::default();
        let req = StackReq::any_of(&[
            symbolic.factorize_numeric_lu_scratch::<f64>(par, params),
            symbolic.solve_in_place_scratch::<f64>(1, par),
        ]);
        let mem = MemBuffer::try_new(req).map_err(|_| SparseLuError::Pattern("out of memory".into()))?;
        let csc = vec![0.0; row_idx.len()];
        Ok(SparseLu { n, col_ptr, row_idx, slot, csc, symbolic, numeric: NumericLu::new(), mem, req, par })
    }

    /// Number of unknowns.
    pub fn size(&self) -> usize {
        self.n
    }

    /// Solve `A x = b` in place (`b` in, `x` out), where `values` are the entries of `A` in the order of
    /// the pattern.
    ///
    /// # Panics
    /// If `values` or `b` do not match the pattern and the size (internal misuse).
    pub fn solve(&mut self, values: &[f64], b: &mut [f64]) -> Result<(), SparseLuError> {
        assert_eq!(values.len(), self.slot.len(), "one value per pattern entry");
        assert_eq!(b.len(), self.n, "one right-hand side per unknown");
        self.csc.fill(0.0);
        for (v, &k) in values.iter().zip(&self.slot) {
            self.csc[k] += *v;
        }
        // SAFETY: `col_ptr` and `row_idx` are the arrays `new` built and checked (`new_checked`, which
        // panics on a malformed structure) and nothing changes them since: checking them again at every
        // solve (a pass over the pattern) would find what it found then.
        let structure =
            unsafe { SymbolicSparseColMatRef::new_unchecked(self.n, self.n, &self.col_ptr, None, &self.row_idx) };
        let a = SparseColMatRef::new(structure, &self.csc);
        let stack = MemStack::new(&mut self.mem);
        let lu = self
            .symbolic
            .factorize_numeric_lu(&mut self.numeric, a, self.par, stack, Default::default())
            .map_err(|e| match e {
                LuError::SymbolicSingular { .. } => SparseLuError::Singular,
                LuError::Generic(g) => SparseLuError::Pattern(format!("{g:?}")),
            })?;
        let rhs = MatMut::from_column_major_slice_mut(b, self.n, 1);
        lu.solve_in_place_with_conj(Conj::No, rhs, self.par, MemStack::new(&mut self.mem));
        if b.iter().all(|v| v.is_finite()) { Ok(()) } else { Err(SparseLuError::Singular) }
    }
}
