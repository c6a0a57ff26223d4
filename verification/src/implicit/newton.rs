//! Static equilibrium of the discrete equations by Newton's method: solve `F(x, 0) = 0` on the free
//! nodes, `J dx = -F` with the exact block-tridiagonal Jacobian `J = dF/dx` factored by faer's sparse LU,
//! and a backtracking line search (halve the step while the largest residual does not fall) that is
//! inactive near the solution, where full steps give quadratic convergence.

use super::SparseLu;
use super::jacobian::{assemble, unknown_index};
use crate::setup::max_residual;
use ohl::scheme::Explicit;

/// Outcome of a Newton solve.
#[derive(Clone, Debug)]
pub struct NewtonReport {
    /// largest nodal residual [N] before each iteration and at the end
    pub residual_history: Vec<f64>,
    /// step-length factor of each iteration (1 = full Newton step)
    pub step_factors: Vec<f64>,
}

/// Solve for the static equilibrium in place (velocities are set to zero), from the solver's current
/// positions, until the largest residual is below `tol_n` [N].
pub fn solve_static(s: &mut Explicit, tol_n: f64, max_iterations: usize) -> Result<NewtonReport, String> {
    for v in &mut s.wire.v {
        v.fill(0.0);
    }
    let (idx, n) = unknown_index(s);
    let mut hist = vec![max_residual(s)];
    let mut factors = Vec::new();
    let mut f = [vec![0.0; s.wire.nodes()], vec![0.0; s.wire.nodes()], vec![0.0; s.wire.nodes()]];
    let (mut pattern, mut values) = (Vec::new(), Vec::new());
    let mut lu: Option<SparseLu> = None;
    for _ in 0..max_iterations {
        if *hist.last().unwrap() < tol_n {
            return Ok(NewtonReport { residual_history: hist, step_factors: factors });
        }
        s.net_force(&mut f);
        let mut rhs = vec![0.0; n];
        for (i, o) in idx.iter().enumerate() {
            if let Some(r) = o {
                for k in 0..3 {
                    rhs[r + k] = -f[k][i];
                }
            }
        }
        assemble(s, 0.0, 0.0, &mut pattern, &mut values);
        if lu.is_none() {
            lu = Some(SparseLu::new(n, &pattern)?);
        }
        let dx = lu.as_ref().expect("created above").solve(&values, &rhs)?;
        let x0 = s.wire.x.clone();
        let r0 = *hist.last().unwrap();
        let mut lambda = 1.0;
        loop {
            for (i, o) in idx.iter().enumerate() {
                if let Some(r) = o {
                    for k in 0..3 {
                        s.wire.x[k][i] = x0[k][i] + lambda * dx[r + k];
                    }
                }
            }
            let r1 = max_residual(s);
            if r1 < r0 || lambda < 1e-3 {
                hist.push(r1);
                factors.push(lambda);
                break;
            }
            lambda *= 0.5;
        }
    }
    if *hist.last().unwrap() < tol_n {
        Ok(NewtonReport { residual_history: hist, step_factors: factors })
    } else {
        Err(format!("Newton did not converge: residual history {hist:?}"))
    }
}
