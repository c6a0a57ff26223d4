//! The residual static state after a run: the static equilibrium (Newton, [`super::solve_on_ground`]) of
//! the run's final configuration, with the broken segments, failed strings, slipped clamps, ice and
//! temperatures as they are at the end, and the ground kept as a frictionless contact
//! ([`super::ground`]). It is the design quantity of a broken-conductor or ice-shedding load case: the
//! residual static load (ASCE Manual 74, "longitudinal loads": the static load after the event, as
//! against its dynamic peak).
//!
//! # Broken pieces re-hung
//!
//! A broken span's pieces are first re-hung below the clamps they hang from (10 degrees off vertical,
//! unstretched): from a piece lying on the ground Newton would have to swing it through 90 degrees,
//! outside its basin (`tests/statics.rs`, `a_broken_span_hangs_straight_down_from_its_supports`). Where
//! the run has a ground, the re-hung line stops where it reaches the ground and the rest of the piece is
//! laid on the ground towards its free end: the piece hangs from its support down to the ground and lies
//! on it beyond, so the support carries the weight of the hanging part only and the ground the rest
//! (`ground_reaction_n`).
//!
//! # Frictionless ground
//!
//! The tension a frictional ground holds in a lying piece depends on how it came to rest, and the
//! explicit run does not settle on one: case (a) of `cases/` continued with mass damping from its end
//! creeps from 5.20 to 5.06 kN of vertical load on support 1 over 770 s, towards the frictionless 4.81 kN
//! (docs/decisions.md, "A broken conductor's residual state on the ground"). With a frictionless ground
//! the damped run without smoothing comes to rest at this state (`app/tests/cases.rs`).

use serde::Serialize;

use super::ground::GroundPenalty;
use super::{StaticError, StaticOptions, solve_on_ground};
use crate::output::spans::SpanState;
use crate::scheme::Explicit;

/// Newton iterations allowed to the residual solve: from re-hung pieces a section's solve takes tens to
/// a hundred or so; ten times the library's default (100) leaves room for a long section (measured: 127 for case (a)
/// of `cases/` at 100 segments per span).
pub const MAX_ITERATIONS: usize = 1000;

/// One support in the residual static state.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ResidualSupport {
    /// its node
    pub node: usize,
    /// the point the force acts on: a fixed node's position, a suspension string's crossarm pivot [m]
    pub position_m: [f64; 3],
    /// force of the conductor on the support `[F1, F2, F3]` [N] (`F2` along the line, `F3` up)
    pub force_n: [f64; 3],
}

/// One span in the residual static state ([`SpanState`]).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ResidualSpan {
    /// span index (0 first)
    pub span: usize,
    /// its first and last node
    pub nodes: [usize; 2],
    /// its state at rest
    #[serde(flatten)]
    pub state: SpanState,
}

/// The residual static state (`static.json` of `ohl run --static-after`).
#[derive(Clone, Debug, Serialize)]
pub struct Residual {
    /// the time of the run's final state it was solved from [s]
    pub after_time_s: f64,
    /// Newton iterations
    pub iterations: usize,
    /// largest nodal force residual at the end [N]
    pub residual_n: f64,
    /// the tolerance it met [N]
    pub tolerance_n: f64,
    /// the supports, in node order
    pub supports: Vec<ResidualSupport>,
    /// the spans (a single span: the whole wire)
    pub spans: Vec<ResidualSpan>,
    /// the ground's total reaction on the wire `[G1, G2, G3]` [N] (zero without a ground or where nothing
    /// lies on it)
    pub ground_reaction_n: [f64; 3],
    /// the solved state
    #[serde(skip)]
    pub solver: Explicit,
}

/// The residual static state after a run whose final state is `final_state` (module doc), reported per
/// span of `spans` (first and last node of each; empty: the whole wire as one span).
pub fn residual(final_state: &Explicit, spans: &[(usize, usize)]) -> Result<Residual, StaticError> {
    let mut s = final_state.clone();
    rehang_broken_pieces(&mut s);
    let opts = StaticOptions { max_iterations: MAX_ITERATIONS, ..StaticOptions::default() };
    let report = solve_on_ground(&mut s, &opts)?;
    s.evaluate_forces();
    let mut forces = Vec::new();
    s.support_forces(&mut forces);
    let positions = s.wire().supports();
    let supports = forces
        .iter()
        .zip(&positions)
        .map(|(&(node, force_n), &(_, position_m))| ResidualSupport { node, position_m, force_n })
        .collect();
    let mut ground_reaction_n = [0.0; 3];
    if let Some(g) = s.ground() {
        let contact = GroundPenalty::of(&s, g);
        let w = s.wire();
        for i in (0..w.nodes()).filter(|&i| w.free[i] > 0.0) {
            let r = contact.force(w.position(i));
            for k in 0..3 {
                ground_reaction_n[k] += r[k];
            }
        }
    }
    let whole = [(0, s.wire().segments())];
    let spans = if spans.is_empty() { &whole[..] } else { spans };
    let spans = spans
        .iter()
        .enumerate()
        .map(|(k, &(first, last))| ResidualSpan {
            span: k,
            nodes: [first, last],
            state: SpanState::of(&s, first, last, s.ground()),
        })
        .collect();
    Ok(Residual {
        after_time_s: final_state.time_s(),
        iterations: report.iterations,
        residual_n: report.residual_n,
        tolerance_n: report.tolerance_n,
        supports,
        spans,
        ground_reaction_n,
        solver: s,
    })
}

/// Each piece cut by a broken segment is put on a line 10 degrees off the vertical below the node that
/// holds it (a fixed node or a string's clamp), unstretched, on the side of its free end; where that line
/// reaches the solver's ground, if it has one, the rest of the piece is laid on the ground, straight
/// along the line (`x2`) towards the free end.
fn rehang_broken_pieces(s: &mut Explicit) {
    let w = s.wire();
    let n = w.segments();
    let held = |i: usize| w.is_held(i);
    let ground = s.ground();
    let mut moves: Vec<(usize, [f64; 3])> = Vec::new();
    let tilt = 10f64.to_radians();
    for j in (0..n).filter(|&j| w.intact[j] != 1.0) {
        // The piece left of the break ends at node j; the one right of it starts at node j + 1.
        for (end, step) in [(j, -1i64), (j + 1, 1i64)] {
            let mut path = vec![end];
            let mut i = end as i64;
            while !held(i as usize) {
                let next = i + step;
                let seg = if step < 0 { next } else { i } as usize;
                if next < 0 || next > n as i64 || w.intact[seg] != 1.0 {
                    path.clear();
                    break;
                }
                i = next;
                path.push(i as usize);
            }
            let Some(&top) = path.last() else { continue };
            let p = w.position(top);
            let side = -step as f64; // the free end lies on this side of the holding node (along x2)
            let (mut d, mut q, mut on_ground) = (0.0, p, false);
            for pair in path.windows(2).rev() {
                let (below, above) = (pair[0], pair[1]);
                let l = w.rest_length[below.min(above)];
                d += l;
                let hang = [p[0], p[1] + side * d * tilt.sin(), p[2] - d * tilt.cos()];
                q = match ground {
                    Some(g) if on_ground || g.clearance_m(hang) < 0.0 => {
                        // On the ground: a step of length `l` along its slope towards the free end.
                        on_ground = true;
                        let slope = g.surface(q[1]).1;
                        let x2 = q[1] + side * l / (1.0 + slope * slope).sqrt();
                        [q[0], x2, g.height_at(x2)]
                    }
                    _ => hang,
                };
                moves.push((below, q));
            }
        }
    }
    let w = s.wire_mut();
    for (i, x) in moves {
        for k in 0..3 {
            w.x[k][i] = x[k];
        }
    }
}
