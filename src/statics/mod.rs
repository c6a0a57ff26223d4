//! Static equilibrium of the discrete wire: the explicit scheme (3.1), (3.6) at rest.
//!
//! At rest (`v = 0`, so no Kelvin-Voigt rate and no aerodynamic damping (2.6)) the kick of (3.6)
//! vanishes when the net force on every free node does:
//!
//! ```text
//! F_i(x) = T_{i+1/2} t_{i+1/2} - T_{i-1/2} t_{i-1/2} + (P_{i+1/2} + P_{i-1/2}) / 2 - m_i g e3 = 0   [N]
//! ```
//!
//! for the free nodes `i` (the supports stay where they are), with `t_{i+1/2} = (r_{i+1} - r_i) /
//! |r_{i+1} - r_i|`, the tension `T_{i+1/2} = EA e_{i+1/2}` of (3.4) (tension-only or linear law),
//! `P_{i+1/2}` the segment's distributed load (wind (2.5) or a uniform normal pressure, plus a uniform
//! load `q L`) and `m_i` the lumped node mass. The residual is the library's own
//! [`Explicit::net_force`], so the static solution is the rest state of the very equations the explicit
//! scheme integrates; its error against the continuous wire is the grid's `O(ds^2)`.
//!
//! Ground contact, which the explicit scheme enforces by projection, is refused by [`solve`]; with
//! [`solve_on_ground`] it is a frictionless penalty contact ([`ground`]).
//!
//! After a run, [`residual`] solves the residual static state of its final configuration (broken pieces
//! re-hung, the ground kept) for `ohl run --static-after` and `ohl cases`.
//!
//! A suspension string adds its force to its clamp node ([`crate::wire::insulator`]); an elastic
//! crossarm adds its pivot's two horizontal coordinates as unknowns, with the pivot's balance of springs
//! and string pull as their equations ([`pivots`]).
//!
//! # Method
//!
//! Newton's method on `F(x) = 0`: `J dx = -F` with the exact Jacobian `J = dF/dx` ([`jacobian`]:
//! forward-mode dual numbers ([`dual`]) over the segment element the kernel evaluates on `f64`
//! ([`crate::element::segment`]; [`jacobian::replica_gap`] checks the whole nodal force, strings and
//! gravity included), block-tridiagonal with 3x3 blocks, factored by faer's sparse
//! LU with the symbolic analysis done once ([`sparse_lu`]).
//!
//! # Globalisation: tension-floor regularisation of the Jacobian, and a line search
//!
//! A wire has no transverse stiffness of its own: the geometric stiffness of a segment across its
//! tangent is `T / len`, and a slack segment of the tension-only law has no stiffness at all. From the
//! straight chord with an unstretched length at least the chord, every segment is slack or exactly
//! unstretched, and `J` is singular (zero for the tension-only law). The Jacobian, and only the Jacobian,
//! is therefore regularised ([`jacobian::values`]):
//!
//! * a slack tension-only segment is linearised with the linear law (axial stiffness `EA / l0`);
//! * every segment's geometric stiffness is taken with at least the tension floor
//!   `T_min = T_s min(1, max|F_i| / f_max)`, where `T_s = sum_i |f_i|` is the total load (the horizontal
//!   tension of a wire whose sag is an eighth of its span) and `f_max` the largest nodal load.
//!
//! From the straight chord the first step is then the deflection of a string under the tension `T_s`: a
//! parabola through the supports of sag about an eighth of the span, after which the segments are taut
//! and the iteration is Newton's. The floor shrinks with the residual (a Levenberg-Marquardt-like
//! choice, `O(|F|)`), and at the solution of a loaded wire every segment carries a positive tension, so
//! the final iterations are exact Newton steps and converge quadratically. Where the true tension exceeds
//! the floor (a taut wire, or any start near the solution) nothing is changed at all.
//!
//! This was preferred to pseudo-transient continuation (`(J - M / h^2) dx = -F`): the mass shift is
//! diagonal, so from a slack start every node free-falls by `g h^2` independently of its neighbours
//! while only the segments at the supports stretch, and the information that the wire hangs from its
//! supports spreads only a few nodes per iteration; the tension floor couples neighbours (a discrete
//! Laplacian) and moves the whole wire into a sagging shape in one solve.
//!
//! Each step `dx` is followed by a line search on the work of the residual along it, `g(lambda) =
//! F(x + lambda dx) . dx`, which for conservative loads (gravity, uniform load) is minus the slope of the
//! potential energy along the step, and positive at `lambda = 0` when the (regularised, positive
//! definite) stiffness `-J` defines the step. A norm of the residual is a poor merit function here: from
//! the straight chord any sagging shape must stretch the wire, and the axial forces `EA e` that
//! appear exceed the weight that drives the motion, so a norm-based search takes tiny steps. The search
//! accepts the first trial that has not overshot the minimum along the line by much, `g >= -g(0) / 2`
//! (the full step near the solution, one residual evaluation), else jumps to the secant root of `g`
//! (at least a tenth of the trial). If `g(0) <= 0` (a step that is not an energy descent, possible with
//! compression in the linear law or with wind), it halves the step until the residual's Euclidean norm
//! falls. If the full step and 12 further trials fail, the step is rejected and the floor multiplied by 10 (divided by 10 again,
//! down to 1, after each accepted step).
//!
//! # Cost
//!
//! Per iteration: one assembly (dual numbers with 6 slots per segment), one numeric sparse LU into
//! storage kept from the previous iteration, one solve, and usually one residual evaluation. The
//! pattern, its compressed structure and the symbolic factorisation are computed once per solve.

pub mod dual;
pub mod ground;
pub mod jacobian;
pub mod line;
pub mod line_jacobian;
mod newton;
pub mod pivots;
pub mod residual;
pub mod sparse_lu;

pub use line::solve_line;
pub use newton::{
    StaticError, StaticOptions, StaticReport, default_tolerance_n, nodal_loads, rounding_floor_n, solve,
    solve_on_ground,
};
pub use sparse_lu::{SparseLu, SparseLuError};

use crate::scheme::Explicit;

/// The reaction of each support at the solver's current state: `(node, R)` for every fixed node, where
/// `R` [N] is the force the support exerts on the node, `R = -F_i` with `F_i` the net force of the
/// adjacent segments' tension, the node's own lumped loads and any prescribed force
/// ([`Explicit::support_forces`] with the sign turned). At a static equilibrium the reactions balance the
/// total external load: `sum R + sum_i f_i = 0` over all nodes.
pub fn support_reactions(s: &mut Explicit) -> Vec<(usize, [f64; 3])> {
    s.evaluate_forces();
    let mut f = Vec::new();
    s.support_forces(&mut f);
    f.into_iter().map(|(i, g)| (i, g.map(|c| -c))).collect()
}
