//! Static equilibrium of a line of several conductors ([`crate::scheme::line::LineExplicit`]): the rest
//! state of the very equations the explicit line scheme integrates,
//!
//! ```text
//! F_i(x) = (conductor forces of (3.1) at node i) + sum_links (+-) F_l(x) = 0        every free node
//! S_s(x) = K_s (p0_s - p_s) + sum_links on s  F_l(x), horizontal part = 0           every elastic support
//! ```
//!
//! solved by the same regularised Newton iteration and line search as a single conductor
//! ([`super::newton`], module doc of [`crate::statics`]). The unknowns are numbered by the line's
//! [`DofMap`] (each conductor's free nodes as a contiguous block, then two horizontal translations per
//! elastic support); the Jacobian is assembled from each conductor's own exact Jacobian
//! ([`super::jacobian::values`], shifted to its block), each link's 3x3 blocks from the link element on
//! dual numbers ([`crate::element::link`]: the same function the explicit step evaluates on `f64`), and
//! each support's spring block ([`super::line_jacobian`], shared with the implicit integrator of the
//! verification). The sparsity pattern is built once from the topology and the factorisation
//! analysed once (faer's symbolic/numeric split); only the values change per iteration.
//!
//! Regularisation, as for one conductor: every conductor's segments get the tension floor; a slack
//! tension-only link (a string) is linearised with its linear law. The residual is never changed.

use super::jacobian::{pattern, values};
use super::line_jacobian::{link_block, support_block};
use super::newton::{Equations, Scales, StaticError, StaticOptions, StaticReport, iterate, load_scales};
use crate::element::LinkLaw;
use crate::element::tension::LawKind;
use crate::line::dof::DofMap;
use crate::line::handle::Endpoint;
use crate::scheme::WindGate;
use crate::scheme::line::LineExplicit;
use faer::sparse::Pair;

/// Move the line to its static equilibrium, starting from its current state (velocities set to zero).
///
/// Supported: what [`super::solve`] supports for each conductor (tension-only and linear laws, gravity,
/// uniform load, wind with the gate `Always`, strings on the wire), plus links of every kind and elastic
/// supports. Refused (an error, never a panic): the downwind gate, ground contact, a conductor's own
/// elastic crossarm (use an elastic support of the line), a conductor with a broken segment, a conductor
/// that neither a fixed node nor a link holds.
///
/// A taut start for short, stiff, lightly loaded conductors (a dropper: strain 1e-6 between slack and
/// taut, below the polygon's own chord shortening, so every segment of a strung start is slack): where
/// the iteration does not converge, it is started again from the same state with every tension-only
/// conductor's law made linear (compression allowed, so the residual is smooth and Newton converges at
/// its quadratic rate to the hanging shape, whose segments are all taut), then continued with the
/// tension-only law from there (the same equations at a state where they coincide). A line that
/// converged before takes the first path only, bit for bit as before. The report is the last solve's,
/// with the iterations of both.
pub fn solve_line(line: &mut LineExplicit, opts: &StaticOptions) -> Result<StaticReport, StaticError> {
    check_supported(line)?;
    let wires: Vec<[Vec<f64>; 3]> = line.conductors().iter().map(|c| c.wire().x.clone()).collect();
    let supports: Vec<[f64; 3]> = (0..line.supports().count()).map(|s| line.support_position_m(s)).collect();
    let first = solve_line_once(line, opts);
    let tension_only: Vec<usize> =
        (0..line.conductors().len()).filter(|&c| line.conductors()[c].wire().law == LawKind::TensionOnly).collect();
    let Err(StaticError::NotConverged { .. }) = first else { return first };
    if tension_only.is_empty() {
        return first;
    }
    for (c, x) in wires.into_iter().enumerate() {
        // Copied into the wire's own arrays, which keep their place (`staggered_alloc`).
        for (to, from) in line.conductor_mut(c).wire_mut().x.iter_mut().zip(&x) {
            to.copy_from_slice(from);
        }
    }
    for (s, p) in supports.into_iter().enumerate() {
        line.set_support_position(s, p);
    }
    for &c in &tension_only {
        line.conductor_mut(c).wire_mut().law = LawKind::Linear;
    }
    let linear = solve_line_once(line, opts);
    for &c in &tension_only {
        line.conductor_mut(c).wire_mut().law = LawKind::TensionOnly;
    }
    let linear = linear?;
    let mut report = solve_line_once(line, opts)?;
    report.iterations += linear.iterations;
    Ok(report)
}

fn solve_line_once(line: &mut LineExplicit, opts: &StaticOptions) -> Result<StaticReport, StaticError> {
    line.stop();
    let dofs = line_dofs(line);
    let pat = line_pattern(line, &dofs);
    let scales = line_scales(line, opts);
    let mut eqs = LineEquations { line, dofs, f: Vec::new(), local: Vec::new() };
    let n = eqs.dofs.len();
    iterate(&mut eqs, n, &pat, scales, opts)
}

fn check_supported(line: &LineExplicit) -> Result<(), StaticError> {
    for (c, s) in line.conductors().iter().enumerate() {
        if s.loads().wind.is_some() && s.loads().wind_gate == WindGate::Downwind {
            return Err(StaticError::DownwindGate);
        }
        if s.ground().is_some() {
            return Err(StaticError::GroundContact);
        }
        let w = s.wire();
        if let Some(j) = w.intact.iter().position(|&x| x != 1.0) {
            return Err(StaticError::BrokenSegment { node: j });
        }
        if w.insulators.iter().any(|i| i.crossarm.is_some()) {
            return Err(StaticError::Factorisation(format!(
                "conductor {c} has an elastic crossarm of its own: give the line an elastic support instead"
            )));
        }
        let linked = line
            .links()
            .iter()
            .any(|l| [l.a, l.b].iter().any(|e| matches!(e, Endpoint::Node(n) if n.conductor == c)) && l.intact);
        if !linked && w.free.iter().all(|&f| f > 0.0) && w.insulators.is_empty() {
            return Err(StaticError::BrokenSegment { node: 0 });
        }
    }
    Ok(())
}

/// Tolerance and regularisation scales: the single-conductor rules over all conductors, with the
/// rounding floor of the stiffest link included (a string of 1.4e7 N/m is stiffer than a conductor
/// segment of `EA / l0` ~ 3e6 N/m and sets the floor of its clamp's residual).
fn line_scales(line: &LineExplicit, opts: &StaticOptions) -> Scales {
    let (mut f_max, mut f_sum, mut floor) = (0.0_f64, 0.0_f64, 0.0_f64);
    let mut x_max = 0.0_f64;
    for c in line.conductors() {
        let (m, s) = load_scales(c);
        f_max = f_max.max(m);
        f_sum = f_sum.max(s);
        floor = floor.max(super::rounding_floor_n(c));
        let w = c.wire();
        for i in 0..w.nodes() {
            x_max = x_max.max(w.position(i).iter().map(|v| v * v).sum::<f64>().sqrt());
        }
    }
    let k_max = line.links().iter().map(|l| l.law.stiffness_n_per_m()).fold(0.0, f64::max);
    floor = floor.max(k_max * x_max * f64::EPSILON);
    let tol = opts.tolerance_n.unwrap_or_else(|| (1e-10 * f_max).max(32.0 * floor));
    Scales { tolerance_n: tol, tension_n: f_sum, load_n: if f_max > 0.0 { f_max } else { 1.0 } }
}

/// The unknowns of the line as [`solve_line`] numbers them: each conductor's free nodes, then the two
/// horizontal translations of each elastic support ([`DofMap`]).
pub fn line_dofs(line: &LineExplicit) -> DofMap {
    let free: Vec<&[f64]> = line.conductors().iter().map(|c| &c.wire().free[..]).collect();
    let elastic: Vec<bool> = line.supports().map(|s| s.elastic.is_some()).collect();
    DofMap::new(&free, &elastic)
}

/// The sparsity pattern of the line's Jacobian over the unknowns `dofs` ([`line_dofs`]), in the order
/// [`solve_line`] writes the values, which an implicit integrator may follow with values of its own:
/// each conductor's own pattern ([`pattern`], in the order of [`values`]) shifted to its block; then, for
/// each intact link in model order, the blocks of its ends that move (row end `a` then `b`, and within
/// each the column end `a` then `b`; 3 components for a node, 2 for a support, row-major); then each
/// elastic support's 2x2 block (row-major) in support order. A position appears once per contribution
/// (the sparse matrix sums them). It depends only on the topology: which nodes are free, which links are
/// intact, which supports are elastic.
pub fn line_pattern(line: &LineExplicit, dofs: &DofMap) -> Vec<Pair<usize, usize>> {
    let mut out = Vec::new();
    for (c, s) in line.conductors().iter().enumerate() {
        let base = dofs.conductor_start(c);
        out.extend(pattern(s).into_iter().map(|p| Pair::new(p.row + base, p.col + base)));
    }
    for link in line.links().iter().filter(|l| l.intact) {
        let ends = [dofs.endpoint(&link.a), dofs.endpoint(&link.b)];
        for r in ends {
            let Some(r0) = r.first else { continue };
            for c in ends {
                let Some(c0) = c.first else { continue };
                for k in 0..r.width {
                    for l in 0..c.width {
                        out.push(Pair::new(r0 + k, c0 + l));
                    }
                }
            }
        }
    }
    for s in 0..line.supports().count() {
        if let Some(o) = dofs.support(s) {
            for k in 0..2 {
                for l in 0..2 {
                    out.push(Pair::new(o + k, o + l));
                }
            }
        }
    }
    out
}

struct LineEquations<'a> {
    line: &'a mut LineExplicit,
    dofs: DofMap,
    f: Vec<[Vec<f64>; 3]>,
    local: Vec<f64>,
}

impl Equations for LineEquations<'_> {
    fn residual(&mut self, rhs: &mut [f64]) -> (f64, f64) {
        let line = &mut *self.line;
        // The links' forces on the conductors and supports; each conductor's net force then evaluates its
        // own segment pass once.
        line.evaluate_links();
        let specs: Vec<_> = line.supports().map(|s| (s.position_m, s.elastic)).collect();
        let mut support_rows = Vec::new();
        for (s, (rest, el)) in specs.into_iter().enumerate() {
            let (Some(o), Some(el)) = (self.dofs.support(s), el) else { continue };
            let p = line.support_position_m(s);
            let spring = el.spring_force([p[0] - rest[0], p[1] - rest[1], p[2] - rest[2]], [0.0; 3]);
            let load = line.support_link_loads_n()[s];
            support_rows.push((o, [spring[0] + load[0], spring[1] + load[1]]));
        }
        if self.f.len() != line.conductors().len() {
            self.f = line.conductors().iter().map(|c| std::array::from_fn(|_| vec![0.0; c.wire().nodes()])).collect();
        }
        let (mut max, mut sq) = (0.0_f64, 0.0);
        let mut put = |o: usize, v: f64| {
            rhs[o] = -v;
            max = max.max(v.abs());
            sq += v * v;
        };
        for c in 0..line.conductors().len() {
            // `net_force` includes the links' point forces set by `evaluate_links`.
            line.conductor_mut(c).net_force(&mut self.f[c]);
            for i in 0..self.f[c][0].len() {
                if let Some(o) = self.dofs.node(c, i) {
                    for k in 0..3 {
                        put(o + k, self.f[c][k][i]);
                    }
                }
            }
        }
        for (o, v) in support_rows {
            for k in 0..2 {
                put(o + k, v[k]);
            }
        }
        (if sq.is_finite() { max } else { f64::NAN }, sq.sqrt())
    }

    fn jacobian(&mut self, floor_n: f64, vals: &mut Vec<f64>) {
        vals.clear();
        let line = &*self.line;
        for c in line.conductors() {
            values(c, 0.0, 0.0, Some(floor_n), &mut self.local);
            vals.extend_from_slice(&self.local);
        }
        for link in line.links().iter().filter(|l| l.intact) {
            let (ra, _) = line.endpoint_state(&link.a);
            let (rb, _) = line.endpoint_state(&link.b);
            // A slack string is linearised with its linear law (the regularisation of the module doc).
            let d = [rb[0] - ra[0], rb[1] - ra[1], rb[2] - ra[2]];
            let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            let law = if link.law.compression || len > link.law.rest_length_m {
                link.law
            } else {
                LinkLaw { compression: true, ..link.law }
            };
            // At rest: the velocities are zero and only the position derivatives enter (cv = 0).
            let ends = [self.dofs.endpoint(&link.a), self.dofs.endpoint(&link.b)];
            link_block(&law, (ra, [0.0; 3]), (rb, [0.0; 3]), ends, 0.0, vals);
        }
        for (s, sup) in line.supports().enumerate() {
            let (Some(_), Some(el)) = (self.dofs.support(s), sup.elastic) else { continue };
            support_block(&el, 0.0, 0.0, vals);
        }
    }

    fn gather(&self, x0: &mut [f64]) {
        let line = &*self.line;
        for (c, s) in line.conductors().iter().enumerate() {
            let w = s.wire();
            for i in 0..w.nodes() {
                if let Some(o) = self.dofs.node(c, i) {
                    for k in 0..3 {
                        x0[o + k] = w.x[k][i];
                    }
                }
            }
        }
        for s in 0..line.supports().count() {
            if let Some(o) = self.dofs.support(s) {
                let p = line.support_position_m(s);
                x0[o] = p[0];
                x0[o + 1] = p[1];
            }
        }
    }

    fn place(&mut self, x0: &[f64], dx: &[f64], lambda: f64) {
        let line = &mut *self.line;
        for c in 0..line.conductors().len() {
            let n1 = line.conductors()[c].wire().nodes();
            let w = line.conductor_mut(c).wire_mut();
            for i in 0..n1 {
                if let Some(o) = self.dofs.node(c, i) {
                    for k in 0..3 {
                        w.x[k][i] = x0[o + k] + lambda * dx[o + k];
                    }
                }
            }
        }
        for s in 0..line.supports().count() {
            if let Some(o) = self.dofs.support(s) {
                let mut p = line.support_position_m(s);
                p[0] = x0[o] + lambda * dx[o];
                p[1] = x0[o + 1] + lambda * dx[o + 1];
                line.set_support_position(s, p);
            }
        }
    }
}
