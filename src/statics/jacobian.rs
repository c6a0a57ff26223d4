//! The exact Jacobian of the discrete nodal forces, by dual numbers over each segment's inputs.
//!
//! The kernel's segment pass is the segment element [`crate::element::segment`] on `f64`; here the same
//! element runs on dual numbers: with `d = r_b - r_a`, `len = |d|`, `t = d / len`, `e = len / l0 - 1`,
//! `edot = (v_b - v_a) . t / l0`, tension `T` from the Kelvin-Voigt law (3.4) (linear or tension-only),
//! the wind load `P` of [`crate::element::aero`] with the mean segment velocity (2.5)-(2.6), and the
//! uniform load `q L`: node `a` receives `T t + (P + q L) / 2`, node `b` receives `-T t + (P + q L) / 2`,
//! the distributed part only while the node is exposed (3.1). Gravity and prescribed nodal forces are
//! constant and have no derivative. The insulator strings' stiffness is [`crate::wire::Insulator::stiffness`].
//!
//! The Jacobian `dF/dx` is block-tridiagonal: one 3x3 block row per free node, coupling it with its two
//! neighbours. Its entries are written in a fixed order ([`pattern`] gives the positions once, [`values`]
//! the numbers at each state), so the sparse factorisation can be analysed once ([`super::SparseLu`]).
//!
//! [`values`] can *regularise* the Jacobian for the static solver's globalisation (module doc of
//! [`crate::statics`]): a slack segment of the tension-only law is linearised with the linear law's
//! axial stiffness `EA / l0`, and every segment's geometric (transverse) stiffness `T / len` is taken with
//! at least the tension floor `T_min`. The residual is never changed, only the search direction.

use super::dual::Dual;
use crate::element::segment::evaluate;
use crate::element::tension::{LawKind, Linear, TensionLaw, TensionOnly};
use crate::scheme::Explicit;
use faer::sparse::Pair;

/// Axial stiffness `EA` [N] of segment `j`.
#[inline(always)]
fn segment_ea(s: &Explicit, j: usize) -> f64 {
    s.wire().axial_stiffness_n[j]
}

/// Largest axial stiffness per unit rest length `max_j EA_j / l0_j` [N/m].
pub fn max_axial_stiffness_n_per_m(s: &Explicit) -> f64 {
    (0..s.wire().segments()).map(|j| segment_ea(s, j) / s.wire().rest_length[j]).fold(0.0, f64::max)
}

/// Indices of the unknowns: `Some(first index)` for a free node, `None` for a support; and their count.
pub fn unknown_index(s: &Explicit) -> (Vec<Option<usize>>, usize) {
    let mut idx = Vec::with_capacity(s.wire().nodes());
    let mut n = 0;
    for i in 0..s.wire().nodes() {
        if s.wire().free[i] > 0.0 {
            idx.push(Some(n));
            n += 3;
        } else {
            idx.push(None);
        }
    }
    (idx, n)
}

/// Forces on the two end nodes of segment `j` with their derivatives: with `S = 6` with respect to
/// `(x_a, x_b)` (the velocities enter as constants), with `S = 12` also to `(v_a, v_b)` (slots 6-11).
/// The segment element ([`crate::element::segment::evaluate`]) on dual numbers: its values are the
/// kernel's forces bit for bit (the same expression on `f64`).
///
/// `floor_n`: `None` for the exact forces; `Some(T_min)` [N] regularises the derivatives (module doc):
/// the *values* are then not the kernel's and only the derivatives may be used.
pub fn segment_forces<const S: usize>(s: &Explicit, j: usize, floor_n: Option<f64>) -> ([Dual<S>; 3], [Dual<S>; 3]) {
    let w = &s.wire();
    let var = |v: f64, k: usize| if k < S { Dual::var(v, k) } else { Dual::c(v) };
    let xa: [Dual<S>; 3] = std::array::from_fn(|k| Dual::var(w.x[k][j], k));
    let xb: [Dual<S>; 3] = std::array::from_fn(|k| Dual::var(w.x[k][j + 1], 3 + k));
    let va: [Dual<S>; 3] = std::array::from_fn(|k| var(w.v[k][j], 6 + k));
    let vb: [Dual<S>; 3] = std::array::from_fn(|k| var(w.v[k][j + 1], 9 + k));
    let props = w.segment_props(j);
    let load = s.loads().wind.map(|wl| wl.scaled(s.loads().wind_scale));
    let q = s.loads().uniform_load_n_per_m;
    let mut f = match w.law {
        LawKind::Linear => evaluate::<Dual<S>, Linear, _, true, true>(xa, xb, va, vb, &props, &load, q),
        LawKind::TensionOnly => evaluate::<Dual<S>, TensionOnly, _, true, true>(xa, xb, va, vb, &props, &load, q),
        LawKind::TwoMaterial => {
            // The segment element with the conductor's law in place of (3.4), its history held fixed
            // (the same `Material::tension` the kernel evaluates on f64).
            let mut f = evaluate::<Dual<S>, Linear, _, true, true>(xa, xb, va, vb, &props, &load, q);
            let m = w.material.as_ref().expect("LawKind::TwoMaterial without its material");
            let theta = w.temperature_k[j];
            f.tension = m.tension(j, f.stretch.e, f.stretch.edot, props.internal_friction_n_s, theta) * props.intact;
            f
        }
    };
    if floor_n.is_some() && w.law != LawKind::Linear {
        // Regularised: a slack segment is linearised with the linear law (axial stiffness EA / l0).
        let raw = Linear::tension(props.axial_stiffness_n, props.internal_friction_n_s, f.stretch.e, f.stretch.edot);
        if w.law == LawKind::TensionOnly && (raw.v <= 0.0 || f.stretch.e.v <= 0.0) {
            f.tension = raw * props.intact;
        } else if w.law == LawKind::TwoMaterial && f.tension.v <= 0.0 {
            // Slack two-material segment (its strain below both materials' slack strains): the linear
            // law's derivative at the value zero.
            f.tension = (raw - raw.v) * props.intact;
        }
    }
    // Geometric stiffness with at least the floor: `T t` gains `(T_min - T) t`, a constant times `t`,
    // whose derivative `(T_min - T) (I - t t) / len` adds exactly the missing transverse stiffness.
    let extra = floor_n.map_or(0.0, |fl| (fl - f.tension.v).max(0.0));
    let t = f.stretch.t;
    let tension_dir: [Dual<S>; 3] = std::array::from_fn(|k| f.tension * t[k] + extra * t[k]);
    let (xa_exp, xb_exp) = (w.exposed[j], w.exposed[j + 1]);
    let fa = std::array::from_fn(|k| tension_dir[k] + xa_exp * f.share[k]);
    let fb = std::array::from_fn(|k| -tension_dir[k] + xb_exp * f.share[k]);
    (fa, fb)
}

/// Positions of the Jacobian's entries over the free nodes (rows and columns as given by
/// [`unknown_index`]), in the order [`values`] writes them: segment by segment the 3x3 blocks of its two
/// end nodes, then the diagonal of the free nodes. A position appears once per contribution (the sparse
/// matrix sums them). It depends only on which nodes are free.
pub fn pattern(s: &Explicit) -> Vec<Pair<usize, usize>> {
    let (idx, _) = unknown_index(s);
    let mut out = Vec::with_capacity(36 * s.wire().segments() + 3 * s.wire().nodes());
    for j in 0..s.wire().segments() {
        for row_node in [j, j + 1] {
            let Some(r0) = idx[row_node] else { continue };
            for col_node in [j, j + 1] {
                let Some(c0) = idx[col_node] else { continue };
                for k in 0..3 {
                    for l in 0..3 {
                        out.push(Pair::new(r0 + k, c0 + l));
                    }
                }
            }
        }
    }
    for o in idx.iter().flatten() {
        for k in 0..3 {
            out.push(Pair::new(o + k, o + k));
        }
    }
    // The 3x3 diagonal block of each insulator string on its (free) clamp node.
    for ins in &s.wire().insulators {
        let Some(o) = idx[ins.node] else { continue };
        for k in 0..3 {
            for l in 0..3 {
                out.push(Pair::new(o + k, o + l));
            }
        }
    }
    out
}

/// Entries of `dF/dx + cv dF/dv - cm M` [N/m] in the order of [`pattern`], written into `out` (cleared
/// first), with `M` the lumped masses [kg], `cv` [1/s] and `cm` [1/s^2]. With `cv = 0` only position
/// derivatives are formed (6 dual slots instead of 12). `floor_n` regularises (module doc).
pub fn values(s: &Explicit, cv: f64, cm: f64, floor_n: Option<f64>, out: &mut Vec<f64>) {
    if cv == 0.0 { values_with::<6>(s, 0.0, cm, floor_n, out) } else { values_with::<12>(s, cv, cm, floor_n, out) }
}

fn values_with<const S: usize>(s: &Explicit, cv: f64, cm: f64, floor_n: Option<f64>, out: &mut Vec<f64>) {
    out.clear();
    let free = &s.wire().free;
    for j in 0..s.wire().segments() {
        let (fa, fb) = segment_forces::<S>(s, j, floor_n);
        for (row_node, f) in [(j, &fa), (j + 1, &fb)] {
            if free[row_node] <= 0.0 {
                continue;
            }
            for (side, col_node) in [(0, j), (1, j + 1)] {
                if free[col_node] <= 0.0 {
                    continue;
                }
                for k in 0..3 {
                    for l in 0..3 {
                        let dv = if S > 6 { cv * f[k].d[(6 + 3 * side + l).min(S - 1)] } else { 0.0 };
                        out.push(f[k].d[3 * side + l] + dv);
                    }
                }
            }
        }
    }
    for i in 0..s.wire().nodes() {
        if free[i] > 0.0 {
            for _ in 0..3 {
                out.push(-cm * s.wire().mass[i]);
            }
        }
    }
    for ins in &s.wire().insulators {
        if free[ins.node] > 0.0 {
            out.extend(ins.stiffness(s.wire().position(ins.node), floor_n));
        }
    }
}

/// Largest difference [N] between the replica's nodal forces (plus gravity and prescribed forces) and
/// the library's `net_force` at the solver's current state: rounding level when the replica is faithful.
pub fn replica_gap(s: &mut Explicit) -> f64 {
    let n1 = s.wire().nodes();
    let mut lib = [vec![0.0; n1], vec![0.0; n1], vec![0.0; n1]];
    s.net_force(&mut lib);
    let mut mine = [vec![0.0; n1], vec![0.0; n1], vec![0.0; n1]];
    for j in 0..s.wire().segments() {
        let (fa, fb) = segment_forces::<12>(s, j, None);
        for k in 0..3 {
            mine[k][j] += fa[k].v;
            mine[k][j + 1] += fb[k].v;
        }
    }
    for ins in &s.wire().insulators {
        let f = ins.force_on_clamp(s.wire().position(ins.node));
        for k in 0..3 {
            mine[k][ins.node] += f[k];
        }
    }
    let mut gap: f64 = 0.0;
    for i in 0..n1 {
        mine[2][i] -= s.wire().mass[i] * s.loads().gravity_m_per_s2;
        for k in 0..3 {
            if let Some(f) = &s.nodal_force() {
                mine[k][i] += f[k][i];
            }
            gap = gap.max((mine[k][i] - lib[k][i]).abs());
        }
    }
    gap
}
