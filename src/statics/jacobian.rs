//! The exact Jacobian of the discrete nodal forces, by dual numbers over each segment's inputs.
//!
//! A replica of the kernel's segment pass (`Explicit::segment_pass`): with `d = r_b - r_a`,
//! `len = |d|`, `t = d / len`, `e = len / l0 - 1`, `edot = (v_b - v_a) . t / l0`, tension `T` from the
//! Kelvin-Voigt law (3.4) (linear or tension-only), the wind load `P` of [`crate::wire::aero`] with the
//! mean segment velocity (2.5)-(2.6), and the uniform load `q L`: node `a` receives `T t + (P + q L) / 2`,
//! node `b` receives `-T t + (P + q L) / 2`, the distributed part only while the node is exposed (3.1).
//! Gravity and prescribed nodal forces are constant and have no derivative.
//!
//! The Jacobian `dF/dx` is block-tridiagonal: one 3x3 block row per free node, coupling it with its two
//! neighbours. Its entries are written in a fixed order ([`pattern`] gives the positions once, [`values`]
//! the numbers at each state), so the sparse factorisation can be analysed once ([`super::SparseLu`]).
//!
//! [`values`] can *regularise* the Jacobian for the static solver's globalisation (module doc of
//! [`crate::statics`]): a slack segment of the tension-only law is linearised with the linear law's
//! axial stiffness `EA / l0`, and every segment's geometric (transverse) stiffness `T / len` is taken with
//! at least the tension floor `T_min`. The residual is never changed, only the search direction.

use super::dual::{Dual, dot};
use crate::scheme::{Explicit, WindLoad};
use crate::wire::tension::LawKind;
use faer::sparse::Pair;

/// Axial stiffness `EA` [N] of segment `j`.
#[inline(always)]
fn segment_ea(s: &Explicit, j: usize) -> f64 {
    s.wire().axial_stiffness_n[j]
}

/// Internal friction `eta` [N s] of segment `j` (see [`segment_ea`]).
#[inline(always)]
fn segment_eta(s: &Explicit, j: usize) -> f64 {
    s.wire().internal_friction_n_s[j]
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

#[inline(always)]
fn sub<const S: usize>(a: &[Dual<S>; 3], b: &[Dual<S>; 3]) -> [Dual<S>; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

#[inline(always)]
fn wind_force<const S: usize>(
    wind: &WindLoad,
    scale: f64,
    t: &[Dual<S>; 3],
    len: Dual<S>,
    vm: &[Dual<S>; 3],
) -> [Dual<S>; 3] {
    let (w, mu_over_u) = match wind {
        WindLoad::UniformNormal(u) => (u.direction, u.mu_over_u),
        WindLoad::Aerodynamic(a) => (a.direction, a.mu_over_u),
    };
    let wd = [Dual::c(w[0]), Dual::c(w[1]), Dual::c(w[2])];
    let wt = dot(&wd, t);
    let wp = [wd[0] - wt * t[0], wd[1] - wt * t[1], wd[2] - wt * t[2]];
    // The kernel's guard (`aero::TINY_SIN`): a segment along the wind has no normal direction.
    let s = dot(&wp, &wp).sqrt();
    let inv_s = Dual::c(1.0) / s.max_c(1.0e-300);
    let vn = dot(vm, &wp) * inv_s;
    let f = Dual::c(1.0) - mu_over_u * vn;
    let damp = f * f.abs();
    match wind {
        WindLoad::UniformNormal(u) => {
            let k = (u.pressure_n_per_m * scale) * (len * damp * inv_s);
            [k * wp[0], k * wp[1], k * wp[2]]
        }
        WindLoad::Aerodynamic(a) => {
            let kn = (a.qd_cn * scale * s + a.qd_ct * scale) * damp * len;
            let kt = (a.qd_ct * scale) * (wt * wt.abs() * len);
            [kn * wp[0] + kt * t[0], kn * wp[1] + kt * t[1], kn * wp[2] + kt * t[2]]
        }
    }
}

/// Forces on the two end nodes of segment `j` with their derivatives: with `S = 6` with respect to
/// `(x_a, x_b)` (the velocities enter as constants), with `S = 12` also to `(v_a, v_b)` (slots 6-11).
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
    let (ea, eta) = (segment_ea(s, j), segment_eta(s, j));
    let l0 = w.rest_length[j];
    let d = sub(&xb, &xa);
    let len = dot(&d, &d).sqrt();
    let inv_len = Dual::c(1.0) / len;
    let t = [d[0] * inv_len, d[1] * inv_len, d[2] * inv_len];
    let e = (1.0 / l0) * len + (-1.0);
    let dv = sub(&vb, &va);
    let edot = (1.0 / l0) * dot(&dv, &t);
    let raw = ea * e + eta * edot;
    let tension = match (w.law, floor_n) {
        (LawKind::Linear, _) => raw,
        // Regularised: a slack segment is linearised with the linear law (axial stiffness EA / l0).
        (LawKind::TensionOnly, Some(_)) if raw.v <= 0.0 || e.v <= 0.0 => raw,
        (LawKind::TensionOnly, _) => {
            if e.v > 0.0 {
                raw.max_c(0.0)
            } else {
                Dual::c(0.0)
            }
        }
    };
    let tension = w.intact[j] * tension;
    // Geometric stiffness with at least the floor: `T t` gains `(T_min - T) t`, a constant times `t`,
    // whose derivative `(T_min - T) (I - t t) / len` adds exactly the missing transverse stiffness.
    let extra = floor_n.map_or(0.0, |f| (f - tension.v).max(0.0));
    let tension_dir: [Dual<S>; 3] = std::array::from_fn(|k| tension * t[k] + extra * t[k]);
    let vm: [Dual<S>; 3] = std::array::from_fn(|k| 0.5 * (va[k] + vb[k]));
    let p = match &s.loads().wind {
        Some(wl) => wind_force(wl, s.loads().wind_scale, &t, len, &vm),
        None => [Dual::c(0.0); 3],
    };
    let q = s.loads().uniform_load_n_per_m;
    let lref = w.reference_length[j];
    let h = 0.5 * w.intact[j];
    let es: [Dual<S>; 3] = std::array::from_fn(|k| h * (p[k] + q[k] * lref));
    let (xa_exp, xb_exp) = (w.exposed[j], w.exposed[j + 1]);
    let fa = std::array::from_fn(|k| tension_dir[k] + xa_exp * es[k]);
    let fb = std::array::from_fn(|k| -tension_dir[k] + xb_exp * es[k]);
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
