//! The static solver: regularised Newton iterations with a backtracking line search (module doc of
//! [`crate::statics`] for the equations and the globalisation).

use super::ground::GroundPenalty;
use super::jacobian::{max_axial_stiffness_n_per_m, pattern, unknown_index, values};
use super::pivots::Pivots;
use super::sparse_lu::{SparseLu, SparseLuError};
use crate::element::segment;
use crate::scheme::{Explicit, WindGate};
use faer::sparse::Pair;

/// Options of [`solve`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StaticOptions {
    /// Convergence tolerance on the largest nodal residual `max_i |F_i|` over the free nodes [N]. `None`
    /// derives it from the problem ([`default_tolerance_n`]): `1e-10` of the largest nodal load, but never
    /// below 32 times the rounding floor of the residual.
    pub tolerance_n: Option<f64>,
    /// Largest number of Newton iterations (linear solves) [-].
    pub max_iterations: usize,
}

impl Default for StaticOptions {
    fn default() -> Self {
        StaticOptions { tolerance_n: None, max_iterations: 100 }
    }
}

/// Outcome of a converged [`solve`].
#[derive(Clone, Debug, PartialEq)]
pub struct StaticReport {
    /// Newton iterations taken (one Jacobian factorisation each) [-]
    pub iterations: usize,
    /// final largest nodal residual `max_i |F_i|` over the free nodes [N]
    pub residual_n: f64,
    /// the tolerance it met [N]
    pub tolerance_n: f64,
    /// largest nodal residual [N] at the start and after each iteration (`iterations + 1` values)
    pub residual_history: Vec<f64>,
    /// step-length factor of each iteration (1 = full Newton step; 0 = step rejected, regularisation
    /// raised) [-]
    pub step_factors: Vec<f64>,
    /// tension floor `T_min` of the regularisation in each iteration [N] (module doc; it changes nothing
    /// where the tension exceeds it)
    pub tension_floors_n: Vec<f64>,
    /// residual evaluations spent, line-search trials included [-]
    pub residual_evaluations: usize,
}

/// Why [`solve`] failed. The solver's positions are then those of the last accepted iterate.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum StaticError {
    /// The iteration limit was reached first.
    #[error(
        "static solve did not converge in {iterations} iterations: residual {residual_n:.3e} N > {tolerance_n:.3e} N"
    )]
    NotConverged {
        /// iterations taken [-]
        iterations: usize,
        /// largest nodal residual reached [N]
        residual_n: f64,
        /// the tolerance [N]
        tolerance_n: f64,
    },
    /// The regularised Jacobian stayed singular (or the step not finite) at the largest regularisation.
    #[error("Jacobian singular at iteration {iteration}")]
    Singular {
        /// iteration at which it happened [-]
        iteration: usize,
    },
    /// The residual is not finite (coincident nodes, or non-finite positions or loads).
    #[error("residual not finite at iteration {iteration}")]
    NonFinite {
        /// iteration at which it happened [-]
        iteration: usize,
    },
    /// A piece of the wire, cut off by broken segments, hangs from no support: it has no static
    /// equilibrium (it falls). Pieces that hang from a support or a string are solved.
    #[error("node {node} belongs to a piece of the wire that no support holds (broken segments cut it off)")]
    BrokenSegment {
        /// a node of the detached piece
        node: usize,
    },
    /// The downwind wind gate depends on the direction of motion, which a static state does not have.
    #[error("the downwind wind gate has no static meaning")]
    DownwindGate,
    /// Ground contact is an inequality constraint that the static solver does not model.
    #[error("ground contact is not supported by the static solver")]
    GroundContact,
    /// The wire has no free node.
    #[error("the wire has no free node")]
    NoFreeNode,
    /// The sparse pattern was rejected (internal error).
    #[error("sparse factorisation: {0}")]
    Factorisation(String),
}

/// Line-search trials after the full step before the step is rejected.
const MAX_TRIALS: usize = 12;

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// External load on every node [N] at the current positions (velocities taken as zero): gravity
/// `-m_i g e3`, half of each adjacent segment's distributed load `(P + q L) / 2` while the node is
/// exposed, and the prescribed nodal forces. Three arrays of length `N + 1`.
pub fn nodal_loads(s: &Explicit) -> [Vec<f64>; 3] {
    let w = &s.wire();
    let n1 = w.nodes();
    let mut out = [vec![0.0; n1], vec![0.0; n1], vec![0.0; n1]];
    for i in 0..n1 {
        out[2][i] = -w.mass[i] * s.loads().gravity_m_per_s2;
        if let Some(f) = &s.nodal_force() {
            for k in 0..3 {
                out[k][i] += f[k][i];
            }
        }
    }
    let q = s.loads().uniform_load_n_per_m;
    let load = s.loads().wind.map(|wl| wl.scaled(s.loads().wind_scale));
    let zero = [0.0; 3];
    for j in 0..w.segments() {
        // The segment element's load share at rest (the tension is not a load).
        let props = w.segment_props(j);
        let st = segment::stretch(w.position(j), w.position(j + 1), zero, zero, props.rest_length_m);
        let e = segment::share::<f64, _, true>(
            &load,
            &st,
            zero,
            zero,
            q,
            props.reference_length_m,
            props.intact,
            props.wind_diameter_factor,
        );
        for k in 0..3 {
            out[k][j] += e[k] * w.exposed[j];
            out[k][j + 1] += e[k] * w.exposed[j + 1];
        }
    }
    out
}

/// Largest external load on a free node `max_i |f_i|` [N] ([`nodal_loads`]) and their sum of magnitudes
/// over the free nodes `sum_i |f_i|` [N].
pub(crate) fn load_scales(s: &Explicit) -> (f64, f64) {
    let f = nodal_loads(s);
    let (mut max, mut sum) = (0.0_f64, 0.0);
    for i in 0..s.wire().nodes() {
        if s.wire().free[i] > 0.0 {
            let m = (f[0][i] * f[0][i] + f[1][i] * f[1][i] + f[2][i] * f[2][i]).sqrt();
            max = max.max(m);
            sum += m;
        }
    }
    (max, sum)
}

/// Rounding floor of the residual [N]: positions of magnitude `X = max_i |r_i|` carry an absolute
/// rounding error `X eps`, which a segment's axial stiffness `EA / l0` turns into a tension error
/// `(EA / l0) X eps`; below this no iteration can push the largest nodal force.
pub fn rounding_floor_n(s: &Explicit) -> f64 {
    let w = &s.wire();
    let x = (0..w.nodes()).map(|i| w.position(i).iter().map(|c| c * c).sum::<f64>().sqrt()).fold(0.0, f64::max);
    max_axial_stiffness_n_per_m(s) * x.max(w.total_rest_length()) * f64::EPSILON
}

/// The default tolerance [N]: `max(1e-10 f_max, 32 R)` with `f_max` the largest nodal load and `R` the
/// [`rounding_floor_n`]. The first term asks for positions good to about 1e-10 of the deflection the loads
/// cause; on fine grids of stiff wires that is below rounding, and the second term (32 times the floor:
/// the residual of a converged solve is observed at 1 to 2 times `R`) then governs.
pub fn default_tolerance_n(s: &Explicit) -> f64 {
    let (f_max, _) = load_scales(s);
    (1e-10 * f_max).max(32.0 * rounding_floor_n(s))
}

/// A free node of a piece (nodes joined by intact segments) with no fixed node and no insulator string.
fn detached_node(s: &Explicit) -> Option<usize> {
    let w = s.wire();
    let held = |i: usize| w.is_held(i);
    let mut start = 0;
    for j in 0..=w.segments() {
        // A piece ends at a broken segment or at the last node.
        if j == w.segments() || w.intact[j] != 1.0 {
            if !(start..=j).any(held) {
                return Some(start);
            }
            start = j + 1;
        }
    }
    None
}

fn check_supported(s: &Explicit) -> Result<(), StaticError> {
    if s.loads().wind.is_some() && s.loads().wind_gate == WindGate::Downwind {
        return Err(StaticError::DownwindGate);
    }
    if let Some(node) = detached_node(s) {
        return Err(StaticError::BrokenSegment { node });
    }
    if s.ground().is_some() {
        return Err(StaticError::GroundContact);
    }
    if !s.wire().free.iter().any(|&f| f > 0.0) {
        return Err(StaticError::NoFreeNode);
    }
    Ok(())
}

/// Residual of the free nodes and of the elastic crossarms' pivots: `-F` into `rhs` (the Newton
/// right-hand side), and the largest `|F_i|` and the Euclidean norm `|F|` [N].
fn residual(
    s: &mut Explicit,
    idx: &[Option<usize>],
    pivots: &Pivots,
    ground: Option<&GroundPenalty>,
    f: &mut [Vec<f64>; 3],
    rhs: &mut [f64],
) -> (f64, f64) {
    s.net_force(f);
    if let Some(g) = ground {
        for (i, o) in idx.iter().enumerate() {
            if o.is_some() {
                let c = g.force(s.wire().position(i));
                for k in 0..3 {
                    f[k][i] += c[k];
                }
            }
        }
    }
    let (mut max, mut sq) = pivots.residual(s, rhs);
    for (i, o) in idx.iter().enumerate() {
        if let Some(r) = o {
            for k in 0..3 {
                let v = f[k][i];
                rhs[r + k] = -v;
                max = max.max(v.abs());
                sq += v * v;
            }
        }
    }
    // NaN anywhere makes the norm NaN, which the caller tests.
    (if sq.is_finite() { max } else { f64::NAN }, sq.sqrt())
}

/// Move the free nodes and the pivots to `x0 + lambda dx` [m].
fn place(s: &mut Explicit, idx: &[Option<usize>], pivots: &Pivots, x0: &[f64], dx: &[f64], lambda: f64) {
    for (i, o) in idx.iter().enumerate() {
        if let Some(q) = o {
            for k in 0..3 {
                s.wire_mut().x[k][i] = x0[q + k] + lambda * dx[q + k];
            }
        }
    }
    pivots.scatter(s, x0, dx, lambda);
}

/// Move the free nodes of `s` to the static equilibrium of its loads, `F_i(x) = 0` (module doc of
/// [`crate::statics`]), starting from its current positions; the velocities are set to zero. The
/// fixed nodes, the loads and the rest lengths are those of `s`. Linear solves run on one thread.
///
/// Supported: tension-only and linear laws, gravity, uniform load, wind (both laws, gate
/// [`WindGate::Always`]), prescribed nodal forces, suspension strings, and elastic crossarms (their pivots
/// are unknowns too, [`crate::statics::pivots`]; their velocities are set to zero as well). Errors (never panics) on a broken segment, the downwind
/// gate, ground contact (a frictionless contact is [`solve_on_ground`]), a wire without free nodes,
/// non-finite residuals, or no convergence.
pub fn solve(s: &mut Explicit, opts: &StaticOptions) -> Result<StaticReport, StaticError> {
    check_supported(s)?;
    solve_checked(s, None, opts)
}

/// [`solve`] with the solver's ground, if it has one, as a frictionless contact
/// ([`super::ground`]: a penalty along the surface normal on every free node below it); without a
/// ground it is [`solve`]. The rest state of a wire lying partly on the ground, such as a broken
/// conductor's piece hanging from its support with the rest of it on the ground. The ground stays on
/// the solver. Errors as [`solve`] (a piece that no support holds is refused even if it lies on the
/// ground: it could slide along it).
pub fn solve_on_ground(s: &mut Explicit, opts: &StaticOptions) -> Result<StaticReport, StaticError> {
    let Some(ground) = s.ground().cloned() else { return solve(s, opts) };
    s.set_ground(None);
    let checked = check_supported(s);
    let out = checked.and_then(|()| {
        let penalty = GroundPenalty::of(s, &ground);
        solve_checked(s, Some(penalty), opts)
    });
    s.set_ground(Some(ground));
    out
}

fn solve_checked(
    s: &mut Explicit,
    ground: Option<GroundPenalty>,
    opts: &StaticOptions,
) -> Result<StaticReport, StaticError> {
    for v in &mut s.wire_mut().v {
        v.fill(0.0);
    }
    let (idx, n_nodes) = unknown_index(s);
    let (pivots, n) = Pivots::of(s, n_nodes);
    pivots.stop(s);
    let n1 = s.wire().nodes();
    let mut pat = pattern(s);
    pivots.pattern(s, &idx, &mut pat);
    if let Some(g) = &ground {
        g.pattern(&idx, &mut pat);
    }
    let (f_max, f_sum) = load_scales(s);
    let tol = opts.tolerance_n.unwrap_or_else(|| (1e-10 * f_max).max(32.0 * rounding_floor_n(s)));
    let mut eqs = Single { s, idx, pivots, ground, f: [vec![0.0; n1], vec![0.0; n1], vec![0.0; n1]] };
    // Tension scale of the regularisation: the sum of the nodal loads, the tension of a wire whose sag is
    // an eighth of its span (`H = w l^2 / (8 f)`); a node load scale for its decay.
    let scales = Scales { tolerance_n: tol, tension_n: f_sum, load_n: if f_max > 0.0 { f_max } else { 1.0 } };
    iterate(&mut eqs, n, &pat, scales, opts)
}

/// The discrete equations of one conductor (its free nodes and its crossarms' pivots).
struct Single<'a> {
    s: &'a mut Explicit,
    idx: Vec<Option<usize>>,
    pivots: Pivots,
    ground: Option<GroundPenalty>,
    f: [Vec<f64>; 3],
}

impl Equations for Single<'_> {
    fn residual(&mut self, rhs: &mut [f64]) -> (f64, f64) {
        residual(self.s, &self.idx, &self.pivots, self.ground.as_ref(), &mut self.f, rhs)
    }
    fn jacobian(&mut self, floor_n: f64, vals: &mut Vec<f64>) {
        values(self.s, 0.0, 0.0, Some(floor_n), vals);
        self.pivots.values(self.s, &self.idx, Some(floor_n), vals);
        if let Some(g) = &self.ground {
            g.values(self.s, &self.idx, vals);
        }
    }
    fn gather(&self, x0: &mut [f64]) {
        for (i, o) in self.idx.iter().enumerate() {
            if let Some(q) = o {
                for k in 0..3 {
                    x0[q + k] = self.s.wire().x[k][i];
                }
            }
        }
        self.pivots.gather(self.s, x0);
    }
    fn place(&mut self, x0: &[f64], dx: &[f64], lambda: f64) {
        place(self.s, &self.idx, &self.pivots, x0, dx, lambda);
    }
}

/// A system of static equations `F(x) = 0` that [`iterate`] solves: its residual, the regularised Jacobian
/// in the order of a sparsity pattern fixed at the start (faer's symbolic analysis done once), and the
/// unknowns' values.
pub(crate) trait Equations {
    /// `-F` into `rhs`; returns the largest `|F_i|` (NaN if any is not finite) and `|F|` [N].
    fn residual(&mut self, rhs: &mut [f64]) -> (f64, f64);
    /// The Jacobian `dF/dx` regularised with the tension floor `floor_n` [N], in the pattern's order.
    fn jacobian(&mut self, floor_n: f64, vals: &mut Vec<f64>);
    /// The unknowns into `x0`.
    fn gather(&self, x0: &mut [f64]);
    /// Set the unknowns to `x0 + lambda dx`.
    fn place(&mut self, x0: &[f64], dx: &[f64], lambda: f64);
}

/// The scales of a solve [N]: its tolerance, the tension scale of the regularisation and the nodal load
/// scale of its decay (module doc of [`crate::statics`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Scales {
    pub tolerance_n: f64,
    pub tension_n: f64,
    pub load_n: f64,
}

/// Newton's method with the tension-floor regularisation and the line search of the module doc, on any
/// [`Equations`] of `n` unknowns whose Jacobian has the sparsity pattern `pat`.
pub(crate) fn iterate<E: Equations>(
    eqs: &mut E,
    n: usize,
    pat: &[Pair<usize, usize>],
    scales: Scales,
    opts: &StaticOptions,
) -> Result<StaticReport, StaticError> {
    let mut lu = SparseLu::new(n, pat, faer::Par::Seq).map_err(|e| StaticError::Factorisation(e.to_string()))?;
    let mut vals = Vec::with_capacity(pat.len());
    let mut rhs = vec![0.0; n];
    let mut dx = vec![0.0; n];
    let mut x0 = vec![0.0; n];
    let Scales { tolerance_n: tol, tension_n: tension_scale, load_n: load_scale } = scales;

    let (mut r, mut r2) = eqs.residual(&mut rhs);
    let mut report = StaticReport {
        iterations: 0,
        residual_n: r,
        tolerance_n: tol,
        residual_history: vec![r],
        step_factors: Vec::new(),
        tension_floors_n: Vec::new(),
        residual_evaluations: 1,
    };
    let mut boost = 1.0_f64;
    for it in 0..opts.max_iterations {
        if !r.is_finite() {
            return Err(StaticError::NonFinite { iteration: it });
        }
        if r <= tol {
            return Ok(report);
        }
        report.iterations = it + 1;
        // The floor decays with the residual (Levenberg-Marquardt-like), so the last iterations are pure
        // Newton steps where every segment is taut.
        let floor = boost * tension_scale * (r / load_scale).min(1.0);
        eqs.jacobian(floor, &mut vals);
        dx.copy_from_slice(&rhs);
        match lu.solve(&vals, &mut dx) {
            Ok(()) => {}
            Err(SparseLuError::Singular) => {
                // More regularisation makes the matrix definite for a wire under gravity; give up only
                // at absurd levels.
                if boost > 1e12 {
                    return Err(StaticError::Singular { iteration: it });
                }
                boost *= 10.0;
                report.step_factors.push(0.0);
                report.tension_floors_n.push(floor);
                report.residual_history.push(r);
                continue;
            }
            Err(e) => return Err(StaticError::Factorisation(e.to_string())),
        }
        eqs.gather(&mut x0);
        // Line search (module doc): along the step, the work of the residual `g(lambda) = F(x + lambda
        // dx) . dx` is the energy's slope for conservative loads. While `g(0) > 0`, accept the first trial
        // that has not overshot the minimum along the line by much, `g >= -g(0) / 2`, and otherwise jump
        // to the secant root of `g`; if `g(0) <= 0`, halve until the residual's norm falls.
        let g0 = -dot(&rhs, &dx);
        let mut lambda = 1.0;
        let mut accepted = false;
        for _ in 0..=MAX_TRIALS {
            eqs.place(&x0, &dx, lambda);
            let (rt, r2t) = eqs.residual(&mut rhs);
            report.residual_evaluations += 1;
            let g = -dot(&rhs, &dx);
            if !r2t.is_finite() {
                lambda *= 0.5;
            } else if g0 > 0.0 && g.is_finite() {
                if g >= -0.5 * g0 {
                    (r, r2) = (rt, r2t);
                    accepted = true;
                    break;
                }
                lambda *= (g0 / (g0 - g)).max(0.1);
            } else if r2t < r2 {
                (r, r2) = (rt, r2t);
                accepted = true;
                break;
            } else {
                lambda *= 0.5;
            }
        }
        if accepted {
            boost = (boost / 10.0).max(1.0);
        } else {
            // No trial lowered the residual: back to the last iterate, regularise more.
            eqs.place(&x0, &dx, 0.0);
            (r, r2) = eqs.residual(&mut rhs);
            report.residual_evaluations += 1;
            boost *= 10.0;
            lambda = 0.0;
        }
        report.step_factors.push(lambda);
        report.tension_floors_n.push(floor);
        report.residual_history.push(r);
        report.residual_n = r;
    }
    if r <= tol {
        return Ok(report);
    }
    Err(StaticError::NotConverged { iterations: report.iterations, residual_n: r, tolerance_n: tol })
}
