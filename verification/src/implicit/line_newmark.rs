//! Newmark's average-acceleration integrator (beta = 1/4, gamma = 1/2) for a whole line of conductors
//! (`ohl::line::Model`), on the discrete equations of the explicit line scheme (`ohl::scheme::LineExplicit`,
//! which it consumes as its force evaluator), with Newton iterations on each step.
//!
//! Unknowns `y`, numbered by the line's degree-of-freedom map (`ohl::statics::line::line_dofs`, the
//! numbering of the line's Newton statics): the three translations of each conductor's free nodes,
//! conductor by conductor, then the two horizontal translations of each elastic support (rigid vertically).
//! The mass `M` is diagonal: a node's lumped mass (its conductor's, with the point masses that
//! `LineExplicit::new` lumps into it), a support's moving mass `M_s`. The forces, with `v` the velocities
//! of the same level (not of a half step):
//!
//! ```text
//! node i:     F_i = net_force of its conductor (segments with the Kelvin-Voigt rate from v, gravity,
//!                   uniform load, wind) + sum of its links' forces (element::link, axial damping BA on the
//!                   rate of stretch from v) - zeta m_i v_i                       (zeta: the line's mass damping)
//! support s:  S_s = -k_l ((p - p0).e_l) e_l - k_t ((p - p0).e_t) e_t - c_d u + sum of its links' forces,
//!                   horizontal components
//! ```
//!
//! evaluated by the library (`LineExplicit::evaluate_links`, `Explicit::net_force`,
//! `ElasticSupport::spring_force`) from the state written into the line, so they are the explicit
//! scheme's forces, the only difference being where the velocities are taken. The step is the
//! trapezoidal rule on `(y, v)`:
//!
//! ```text
//! y_{n+1} = y_n + dt v_n + dt^2/4 (a_n + a_{n+1}),     v_{n+1} = v_n + dt/2 (a_n + a_{n+1}),
//! G(a_{n+1}) = M a_{n+1} - F(y_{n+1}, v_{n+1}) = 0,
//! Newton: A dy = G,  a_{n+1} += 4/dt^2 dy,   A = dF/dy + (2/dt) dF/dv - (4/dt^2) M = -(4/dt^2) dG/da.
//! ```
//!
//! `A` is assembled in the line's sparsity pattern (`ohl::statics::line::line_pattern`, fixed once;
//! faer's symbolic factorisation once, `ohl::statics::SparseLu`), entry by entry in that pattern's order:
//!
//! - each conductor's block: `ohl::statics::jacobian::values(c, 2/dt, 4/dt^2 + (2/dt) zeta, None)`, its
//!   exact position and velocity derivatives (dual numbers over each segment's two ends) and `-cm m` on
//!   the diagonal, where the mass damping `-zeta m v` adds `-(2/dt) zeta m`;
//! - each intact link's blocks (`ohl::statics::line_jacobian::link_block`, as the line statics):
//!   `LinkLaw::force_on_b` on `Dual<12>` over `(r_a, r_b, v_a, v_b)`, the entry `d/dr + (2/dt) d/dv` (the
//!   velocity part is the link's axial damping `BA`), with the sign of the row's end (`+` for `b`, `-` for
//!   `a`); a support end's columns are its two horizontal components;
//! - each elastic support's 2x2 block (`ohl::statics::line_jacobian::support_block`):
//!   `-k_l e_l e_l^T - k_t e_t e_t^T - ((2/dt) c_d + (4/dt^2) M_s) I`.
//!
//! Second order in time for smooth motions (the trapezoidal rule is symmetric, so its global error
//! expands in even powers of `dt`), with every velocity-dependent force taken at the new level: no lag,
//! unlike the explicit scheme. Refused at construction (an error, never a panic): ground contact (an
//! inequality), a conductor's own elastic crossarm (a state outside the unknowns), the downwind wind gate
//! (not differentiable). The topology must not change during a run (a link that breaks would change the
//! pattern): a step refuses it.

use faer::sparse::Pair;
use ohl::line::dof::DofMap;
use ohl::scheme::{LineExplicit, WindGate};
use ohl::statics::SparseLu;
use ohl::statics::jacobian::{max_axial_stiffness_n_per_m, values};
use ohl::statics::line::{line_dofs, line_pattern};
use ohl::statics::line_jacobian::{link_block, support_block};

/// Newton iterations allowed per step.
const MAX_ITERATIONS: usize = 30;

/// The integrator: the line (force evaluator, holding the state of the current level) and the
/// accelerations.
#[derive(Clone, Debug)]
pub struct LineNewmark {
    /// force evaluator; its conductors' `wire.x`, `wire.v` and its supports' positions and velocities are
    /// the Newmark state at the current level (velocities of the level, not of a half step)
    line: LineExplicit,
    dofs: DofMap,
    /// the line's sparsity pattern (fixed at construction)
    pattern: Vec<Pair<usize, usize>>,
    /// intact flag of each link at construction (the pattern's topology)
    intact: Vec<bool>,
    /// mass of each unknown [kg]
    mass: Vec<f64>,
    /// positions, velocities and accelerations of the unknowns at the current level
    y: Vec<f64>,
    v: Vec<f64>,
    a: Vec<f64>,
    /// mass damping `zeta` [1/s] of the line's step parameters
    zeta: f64,
    /// simulated time [s]
    time_s: f64,
    /// Newton iterations spent so far
    newton_iterations: usize,
    /// largest residual left by a converged step so far [N]
    worst_residual_n: f64,
    /// convergence tolerance on the largest residual `max |G|` [N]
    tol_n: f64,
    lu: Option<SparseLu>,
    /// scratch: each conductor's nodal forces, the forces on the unknowns, the values of `A`
    f: Vec<[Vec<f64>; 3]>,
    force: Vec<f64>,
    vals: Vec<f64>,
    local: Vec<f64>,
}

/// Rounding floor of the line's residual [N]: an ulp of the largest coordinate through the stiffest
/// element (a conductor segment's `EA / l0`, a link's `EA / L0`, a support's spring). A converged residual
/// cannot be expected below a few times this.
pub fn rounding_floor_n(line: &LineExplicit) -> f64 {
    let mut k_max = line.links().iter().map(|l| l.law.stiffness_n_per_m()).fold(0.0, f64::max);
    let mut x_max = 0.0_f64;
    for c in line.conductors() {
        k_max = k_max.max(max_axial_stiffness_n_per_m(c));
        let w = c.wire();
        for i in 0..w.nodes() {
            x_max = x_max.max(w.position(i).iter().map(|v| v * v).sum::<f64>().sqrt());
        }
    }
    for (s, sup) in line.supports().enumerate() {
        if let Some(e) = sup.elastic {
            k_max = k_max.max(e.along_n_per_m.max(e.across_n_per_m));
        }
        let p = line.support_position_m(s);
        x_max = x_max.max((p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt());
    }
    k_max * x_max * f64::EPSILON
}

impl LineNewmark {
    /// Start from the line's current positions and velocities (the velocities taken as those of the
    /// level), with `a_0 = F / M`, and the Newton tolerance `tol_n` [N] on the largest residual.
    pub fn new(line: LineExplicit, tol_n: f64) -> Result<Self, String> {
        for (c, s) in line.conductors().iter().enumerate() {
            let name = &line.names()[c];
            if s.ground().is_some() {
                return Err(format!("line Newmark: conductor '{name}' has ground contact (not supported)"));
            }
            if s.wire().insulators.iter().any(|i| i.crossarm.is_some()) {
                return Err(format!(
                    "line Newmark: conductor '{name}' has an elastic crossarm of its own (use an elastic support)"
                ));
            }
            if s.loads().wind.is_some() && s.loads().wind_gate == WindGate::Downwind {
                return Err(format!("line Newmark: conductor '{name}' has the downwind wind gate (not smooth)"));
            }
        }
        if tol_n.is_nan() || tol_n <= 0.0 {
            return Err(format!("line Newmark: tolerance {tol_n} N must be positive"));
        }
        let dofs = line_dofs(&line);
        let pattern = line_pattern(&line, &dofs);
        let n = dofs.len();
        let mut mass = vec![0.0; n];
        let mut y = vec![0.0; n];
        let mut v = vec![0.0; n];
        for (c, s) in line.conductors().iter().enumerate() {
            let w = s.wire();
            for i in 0..w.nodes() {
                if let Some(o) = dofs.node(c, i) {
                    for k in 0..3 {
                        mass[o + k] = w.mass[i];
                        y[o + k] = w.x[k][i];
                        v[o + k] = w.v[k][i];
                    }
                }
            }
        }
        for (s, sup) in line.supports().enumerate() {
            if let (Some(o), Some(e)) = (dofs.support(s), sup.elastic) {
                let (p, u) = (line.support_position_m(s), line.support_velocity_m_per_s(s));
                for k in 0..2 {
                    mass[o + k] = e.mass_kg;
                    y[o + k] = p[k];
                    v[o + k] = u[k];
                }
            }
        }
        let zeta = line.params().mass_damping_per_s;
        let intact = line.links().iter().map(|l| l.intact).collect();
        let f = line.conductors().iter().map(|c| std::array::from_fn(|_| vec![0.0; c.wire().nodes()])).collect();
        let mut nm = LineNewmark {
            line,
            dofs,
            pattern,
            intact,
            mass,
            y,
            v,
            a: vec![0.0; n],
            zeta,
            time_s: 0.0,
            newton_iterations: 0,
            worst_residual_n: 0.0,
            tol_n,
            lu: None,
            f,
            force: vec![0.0; n],
            vals: Vec::new(),
            local: Vec::new(),
        };
        let (y, v) = (nm.y.clone(), nm.v.clone());
        nm.place(&y, &v);
        nm.forces(&v);
        if let Some(i) = nm.force.iter().position(|f| !f.is_finite()) {
            return Err(format!("line Newmark: initial force on unknown {i} is not finite"));
        }
        nm.a = nm.force.iter().zip(&nm.mass).map(|(f, m)| f / m).collect();
        Ok(nm)
    }

    /// The line at the current level (positions and velocities of the level).
    pub fn line(&self) -> &LineExplicit {
        &self.line
    }

    /// Simulated time [s].
    pub fn time_s(&self) -> f64 {
        self.time_s
    }

    /// Newton iterations spent so far (one factorisation each).
    pub fn newton_iterations(&self) -> usize {
        self.newton_iterations
    }

    /// Largest residual `max |G|` [N] that a converged step has left so far.
    pub fn worst_residual_n(&self) -> f64 {
        self.worst_residual_n
    }

    /// Write positions `y` and velocities `v` of the unknowns into the line.
    fn place(&mut self, y: &[f64], v: &[f64]) {
        let dofs = &self.dofs;
        for c in 0..self.line.conductors().len() {
            let w = self.line.conductor_mut(c).wire_mut();
            for i in 0..w.nodes() {
                if let Some(o) = dofs.node(c, i) {
                    for k in 0..3 {
                        w.x[k][i] = y[o + k];
                        w.v[k][i] = v[o + k];
                    }
                }
            }
        }
        for s in 0..self.line.supports().count() {
            if let Some(o) = dofs.support(s) {
                let mut p = self.line.support_position_m(s);
                p[0] = y[o];
                p[1] = y[o + 1];
                self.line.set_support_position(s, p);
                self.line.set_support_velocity(s, [v[o], v[o + 1], 0.0]);
            }
        }
    }

    /// The forces `F` on the unknowns at the state placed in the line (velocities `v`), into `self.force`.
    fn forces(&mut self, v: &[f64]) {
        let line = &mut self.line;
        // The links' forces, set on the conductors as point forces and summed on the supports; then each
        // conductor's net force (segments, loads, gravity, point forces).
        line.evaluate_links();
        for c in 0..line.conductors().len() {
            line.conductor_mut(c).net_force(&mut self.f[c]);
            let w = line.conductors()[c].wire();
            for i in 0..w.nodes() {
                if let Some(o) = self.dofs.node(c, i) {
                    for k in 0..3 {
                        self.force[o + k] = self.f[c][k][i] - self.zeta * w.mass[i] * v[o + k];
                    }
                }
            }
        }
        let specs: Vec<_> = line.supports().map(|s| (s.position_m, s.elastic)).collect();
        for (s, (rest, el)) in specs.into_iter().enumerate() {
            let (Some(o), Some(el)) = (self.dofs.support(s), el) else { continue };
            let p = line.support_position_m(s);
            let spring = el.spring_force([p[0] - rest[0], p[1] - rest[1], p[2] - rest[2]], [v[o], v[o + 1], 0.0]);
            let load = line.support_link_loads_n()[s];
            for k in 0..2 {
                self.force[o + k] = spring[k] + load[k];
            }
        }
    }

    /// The values of `A = dF/dy + cv dF/dv - cm M` at the state placed in the line, in the pattern's
    /// order, into `self.vals`.
    fn jacobian(&mut self, cv: f64, cm: f64) {
        let line = &self.line;
        self.vals.clear();
        for c in line.conductors() {
            values(c, cv, cm + cv * self.zeta, None, &mut self.local);
            self.vals.extend_from_slice(&self.local);
        }
        for link in line.links().iter().filter(|l| l.intact) {
            let ends = [self.dofs.endpoint(&link.a), self.dofs.endpoint(&link.b)];
            link_block(&link.law, line.endpoint_state(&link.a), line.endpoint_state(&link.b), ends, cv, &mut self.vals);
        }
        for (s, sup) in line.supports().enumerate() {
            let (Some(_), Some(el)) = (self.dofs.support(s), sup.elastic) else { continue };
            support_block(&el, cv, cm, &mut self.vals);
        }
    }

    /// One step of length `dt` [s]; returns the Newton iterations used. On failure (Newton not converged,
    /// a singular matrix, a non-finite residual, a changed topology) the state stays at the current level
    /// and the error names the time, the step and the reason.
    pub fn step(&mut self, dt: f64) -> Result<usize, String> {
        let at = |t: f64, why: String| format!("line Newmark step from t = {t:.6} s (dt = {dt:.4e} s): {why}");
        if self.line.links().iter().map(|l| l.intact).ne(self.intact.iter().copied()) {
            return Err(at(self.time_s, "a link broke or was restored: the sparsity pattern is fixed".into()));
        }
        let n = self.dofs.len();
        let (cv, cm) = (2.0 / dt, 4.0 / (dt * dt));
        let (y0, v0, a0) = (self.y.clone(), self.v.clone(), self.a.clone());
        let (mut y, mut v) = (vec![0.0; n], vec![0.0; n]);
        // Predictor a_{n+1} = a_n.
        let mut anew = a0.clone();
        let mut g = vec![0.0; n];
        let mut history = Vec::new();
        let mut failure = None;
        for it in 0..=MAX_ITERATIONS {
            for i in 0..n {
                let s = a0[i] + anew[i];
                y[i] = y0[i] + dt * v0[i] + 0.25 * dt * dt * s;
                v[i] = v0[i] + 0.5 * dt * s;
            }
            self.place(&y, &v);
            self.forces(&v);
            let mut gmax = 0.0_f64;
            for i in 0..n {
                g[i] = self.mass[i] * anew[i] - self.force[i];
                gmax = gmax.max(g[i].abs());
            }
            if !g.iter().all(|x| x.is_finite()) {
                failure = Some(format!("residual not finite at Newton iteration {it}"));
                break;
            }
            history.push(gmax);
            if gmax <= self.tol_n {
                self.y = y;
                self.v = v;
                self.a = anew;
                self.time_s += dt;
                self.newton_iterations += it;
                self.worst_residual_n = self.worst_residual_n.max(gmax);
                return Ok(it);
            }
            if it == MAX_ITERATIONS {
                break;
            }
            self.jacobian(cv, cm);
            if self.vals.len() != self.pattern.len() {
                failure = Some(format!("{} values for {} pattern entries", self.vals.len(), self.pattern.len()));
                break;
            }
            let lu = match &mut self.lu {
                Some(lu) => lu,
                None => match SparseLu::new(n, &self.pattern, faer::Par::Seq) {
                    Ok(lu) => self.lu.insert(lu),
                    Err(e) => {
                        failure = Some(format!("sparse pattern: {e}"));
                        break;
                    }
                },
            };
            let mut dy = g.clone();
            if let Err(e) = lu.solve(&self.vals, &mut dy) {
                failure = Some(format!("iteration matrix at Newton iteration {it}: {e}"));
                break;
            }
            for i in 0..n {
                anew[i] += cm * dy[i];
            }
        }
        // Back to the current level.
        self.place(&y0, &v0);
        let why = failure.unwrap_or_else(|| {
            format!(
                "Newton did not converge in {MAX_ITERATIONS} iterations (largest residual {:.3e} N > tolerance {:.3e} N; \
                 residuals by iteration: {})",
                history.last().copied().unwrap_or(f64::NAN),
                self.tol_n,
                history.iter().map(|r| format!("{r:.2e}")).collect::<Vec<_>>().join(", ")
            )
        });
        Err(at(self.time_s, why))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::implicit::newmark::Newmark;
    use crate::setup::{G_M_PER_S2, loads, params, straight_wire};
    use ohl::element::tension::LawKind;
    use ohl::line::{LineConductor, Model, Role};
    use ohl::scheme::Explicit;

    /// On a line of one conductor without links or elastic supports, the line Newmark is the
    /// single-conductor Newmark (`super::super::newmark`): the same forces (`net_force`), the same
    /// unknowns in the same order, the same Jacobian entries (`values` with the same `cv`, `cm`), the same
    /// residual and update, so the two agree bit for bit. A wire with internal friction, released under
    /// its weight: the velocity derivatives enter.
    #[test]
    fn one_conductor_is_the_single_conductor_newmark_bit_for_bit() {
        let n = 20;
        let (wire, l, p) =
            (straight_wire(n, LawKind::Linear, 30.0), loads(G_M_PER_S2, [0.0; 3], None), params(n, 0.5, 0.0, 0.0));
        let mut model = Model::new();
        model.add_conductor(LineConductor { name: "c".into(), role: Role::Phase, wire: wire.clone(), loads: l });
        let line = LineExplicit::new(&model, p).unwrap();
        let tol = 1e-6;
        let mut single = Newmark::new(Explicit::new(wire, l, p), tol);
        let mut nm = LineNewmark::new(line, tol).unwrap();
        for _ in 0..50 {
            let a = single.step(2.0 * p.dt_s).unwrap();
            let b = nm.step(2.0 * p.dt_s).unwrap();
            assert_eq!(a, b);
        }
        let (ws, wl) = (single.sys.wire(), nm.line().conductors()[0].wire());
        assert!(ws.x[2][n / 2] < -0.1, "the wire fell: {}", ws.x[2][n / 2]);
        assert_eq!(ws.x, wl.x);
        assert_eq!(ws.v, wl.v);
    }

    /// A step that cannot converge (a tolerance below rounding) returns an error naming the time, the step
    /// and the reason, and leaves the state at the current level; a link broken during the run is refused.
    #[test]
    fn a_failing_step_is_an_error_and_keeps_the_state() {
        let built = crate::studies::line_implicit::build(true).unwrap();
        let p = ohl::scheme::StepParams { dt_s: 1e-3, smoothing: 0.0, mass_damping_per_s: 0.0, max_speed_m_per_s: 1e3 };
        let line = LineExplicit::new(&built.model, p).unwrap();
        let mut nm = LineNewmark::new(line.clone(), 1e-30).unwrap();
        let before = nm.line().conductors()[0].wire().x.clone();
        let e = nm.step(1e-3).unwrap_err();
        assert!(e.contains("t = 0.000000 s") && e.contains("did not converge in 30 iterations"), "{e}");
        assert_eq!(nm.line().conductors()[0].wire().x, before);
        assert_eq!(nm.time_s(), 0.0);
        let mut broken = line;
        broken.break_link(0);
        let mut nm = LineNewmark::new(broken, 1.0).unwrap();
        assert!(nm.step(1e-3).is_ok());
        nm.line.break_link(1);
        let e = nm.step(1e-3).unwrap_err();
        assert!(e.contains("t = 0.001000 s") && e.contains("pattern is fixed"), "{e}");
    }

    /// The iteration matrix is the derivative of the forces: on the `line_implicit` line (a phase and a
    /// twin bundle with damped spacer arms, damped strings to a damped elastic tower top, conductors with
    /// internal friction, and mass damping), at a moving state, `A + cm M = dF/dy + cv dF/dv` column by
    /// column against central differences of the forces along `(e_j, cv e_j)`. With steps of 1e-6 m the
    /// truncation error is O(h^2) times third derivatives (~1e-12 of the entries) and the rounding error
    /// ~1e-16 |F| / h ~ 1e-5 N/m for forces of 3e4 N; the tolerance 1e-6 of the largest entry (~1e7 N/m)
    /// is above both and far below any missing term (a spacer's damping is 500 N s/m x cv = 1e5 N/m).
    #[test]
    fn iteration_matrix_is_the_derivative_of_the_forces() {
        let built = crate::studies::line_implicit::build(true).unwrap();
        let p = ohl::scheme::StepParams { dt_s: 1e-3, smoothing: 0.0, mass_damping_per_s: 1.5, max_speed_m_per_s: 1e3 };
        let line = LineExplicit::new(&built.model, p).unwrap();
        let mut nm = LineNewmark::new(line, 1.0).unwrap();
        let n = nm.dofs.len();
        // A moving state near the strung one (the strings stay taut: their stretch is ~6e-4 m).
        let y: Vec<f64> = nm.y.iter().enumerate().map(|(i, y)| y + 1e-4 * (i as f64).sin()).collect();
        let v: Vec<f64> = (0..n).map(|i| 0.3 * (0.7 * i as f64).cos()).collect();
        let cv = 200.0;
        nm.place(&y, &v);
        nm.jacobian(cv, 0.0);
        let mut a = vec![vec![0.0; n]; n];
        for (p, x) in nm.pattern.iter().zip(&nm.vals) {
            a[p.row][p.col] += x;
        }
        let scale = a.iter().flatten().fold(0.0_f64, |m, x| m.max(x.abs()));
        let h = 1e-6;
        let mut worst = 0.0_f64;
        for j in 0..n {
            let mut shifted = |s: f64| {
                let (mut yy, mut vv) = (y.clone(), v.clone());
                yy[j] += s * h;
                vv[j] += s * cv * h;
                nm.place(&yy, &vv);
                nm.forces(&vv);
                nm.force.clone()
            };
            let (fp, fm) = (shifted(1.0), shifted(-1.0));
            for i in 0..n {
                worst = worst.max(((fp[i] - fm[i]) / (2.0 * h) - a[i][j]).abs());
            }
        }
        assert!(worst < 1e-6 * scale, "largest difference {worst:e} N/m of {scale:e} N/m");
        // The test exercises every kind of block: links with a support end and the support's own.
        assert!(nm.dofs.support(built.tower).is_some() && n > 100);
    }
}
