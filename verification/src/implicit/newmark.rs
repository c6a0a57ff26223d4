//! Newmark's average-acceleration integrator (beta = 1/4, gamma = 1/2) on the discrete equations
//! `M a = F(x, v)`, with Newton iterations on each step:
//!
//! ```text
//! x_{n+1} = x_n + dt v_n + dt^2/4 (a_n + a_{n+1}),     v_{n+1} = v_n + dt/2 (a_n + a_{n+1}),
//! G(x_{n+1}) = M a_{n+1}(x_{n+1}) - F(x_{n+1}, v_{n+1}(x_{n+1})) = 0,
//! dG/dx = 4/dt^2 M - dF/dx - 2/dt dF/dv.
//! ```
//!
//! Second order in time for smooth problems (trapezoidal rule), energy-conserving for linear undamped
//! ones, and with the velocity-dependent forces (Kelvin-Voigt rate, wind damping (2.6)) taken at the new
//! level, fully implicitly: no lag, unlike the explicit kernel.

use ohl::scheme::Explicit;
use ohl::statics::SparseLu;
use ohl::statics::jacobian::{pattern, unknown_index, values};

/// The integrator state. The wrapped `Explicit` only evaluates forces (its `wire.x` and `wire.v` are
/// overwritten with the Newmark state).
#[derive(Clone, Debug)]
pub struct Newmark {
    /// force evaluator and the current state in `wire.x`, `wire.v`
    pub sys: Explicit,
    /// acceleration at the current level [m/s^2]
    pub a: [Vec<f64>; 3],
    /// simulated time [s]
    pub time_s: f64,
    /// Newton iterations spent so far
    pub newton_iterations: usize,
    /// convergence tolerance on the largest nodal residual [N]
    pub tol_n: f64,
    /// the sparse LU of the iteration matrix, whose pattern stays fixed (created on the first step)
    lu: Option<SparseLu>,
}

impl Newmark {
    /// Start from the solver's current positions and velocities (`a_0 = F / m` on free nodes).
    pub fn new(mut sys: Explicit, tol_n: f64) -> Self {
        let n1 = sys.wire().nodes();
        let mut f = [vec![0.0; n1], vec![0.0; n1], vec![0.0; n1]];
        sys.net_force(&mut f);
        let a = std::array::from_fn(|k| (0..n1).map(|i| sys.wire().free[i] * f[k][i] / sys.wire().mass[i]).collect());
        Newmark { sys, a, time_s: 0.0, newton_iterations: 0, tol_n, lu: None }
    }

    /// One step of length `dt` [s]; returns the Newton iterations used.
    pub fn step(&mut self, dt: f64) -> Result<usize, String> {
        let (idx, n) = unknown_index(&self.sys);
        let n1 = self.sys.wire().nodes();
        let (x0, v0, a0) = (self.sys.wire().x.clone(), self.sys.wire().v.clone(), self.a.clone());
        let mut f = [vec![0.0; n1], vec![0.0; n1], vec![0.0; n1]];
        // Predictor a_{n+1} = a_n.
        let mut anew = a0.clone();
        let set_state = |sys: &mut Explicit, anew: &[Vec<f64>; 3]| {
            for k in 0..3 {
                for i in 0..n1 {
                    let asum = a0[k][i] + anew[k][i];
                    sys.wire_mut().x[k][i] = x0[k][i] + dt * v0[k][i] + 0.25 * dt * dt * asum;
                    sys.wire_mut().v[k][i] = v0[k][i] + 0.5 * dt * asum;
                }
            }
        };
        let mut vals = Vec::new();
        for it in 1..=30 {
            set_state(&mut self.sys, &anew);
            self.sys.net_force(&mut f);
            let mut g = vec![0.0; n];
            let mut gmax: f64 = 0.0;
            for (i, o) in idx.iter().enumerate() {
                if let Some(r) = o {
                    for k in 0..3 {
                        g[r + k] = self.sys.wire().mass[i] * anew[k][i] - f[k][i];
                        gmax = gmax.max(g[r + k].abs());
                    }
                }
            }
            if gmax < self.tol_n {
                self.a = anew;
                self.time_s += dt;
                self.newton_iterations += it - 1;
                return Ok(it - 1);
            }
            // A dx = G with A = dF/dx + 2/dt dF/dv - 4/dt^2 M = -dG/dx; then a_{n+1} += 4/dt^2 dx.
            values(&self.sys, 2.0 / dt, 4.0 / (dt * dt), None, &mut vals);
            let lu = match &mut self.lu {
                Some(lu) => lu,
                None => {
                    self.lu.insert(SparseLu::new(n, &pattern(&self.sys), faer::Par::Seq).map_err(|e| e.to_string())?)
                }
            };
            let mut dx = g;
            lu.solve(&vals, &mut dx).map_err(|e| e.to_string())?;
            for (i, o) in idx.iter().enumerate() {
                if let Some(r) = o {
                    for k in 0..3 {
                        anew[k][i] += 4.0 / (dt * dt) * dx[r + k];
                    }
                }
            }
        }
        Err(format!("Newmark step at t = {:.4} s: Newton did not converge in 30 iterations", self.time_s))
    }
}
