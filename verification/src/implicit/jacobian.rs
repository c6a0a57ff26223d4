//! The exact Jacobian of the discrete nodal forces, by dual numbers over each segment's twelve inputs.
//!
//! A replica of the kernel's segment pass (`Explicit::segment_pass`): with `d = r_b - r_a`,
//! `len = |d|`, `t = d / len`, `e = len / l0 - 1`, `edot = (v_b - v_a) . t / l0`, tension `T` from the
//! Kelvin-Voigt law (3.4) (linear or tension-only), the wind load `P` of `ohl::wire::aero` with the mean
//! segment velocity, and the uniform load `q L`: node `a` receives `T t + (P + q L) / 2`, node `b`
//! receives `-T t + (P + q L) / 2`. Gravity and prescribed nodal forces are constant and have no
//! derivative. All nodes are taken as exposed and all segments as intact or broken per `Wire::intact`.

use crate::dual::{D, dot};
use faer::sparse::Pair;
use ohl::scheme::{Explicit, WindGate, WindLoad};
use ohl::wire::tension::LawKind;

/// Indices of the unknowns: `Some(first index)` for a free node, `None` for a support.
pub fn unknown_index(s: &Explicit) -> (Vec<Option<usize>>, usize) {
    let mut idx = Vec::with_capacity(s.wire.nodes());
    let mut n = 0;
    for i in 0..s.wire.nodes() {
        if s.wire.free[i] > 0.0 {
            idx.push(Some(n));
            n += 3;
        } else {
            idx.push(None);
        }
    }
    (idx, n)
}

fn sub(a: &[D; 3], b: &[D; 3]) -> [D; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn wind_force(wind: &WindLoad, scale: f64, t: &[D; 3], len: D, vm: &[D; 3]) -> [D; 3] {
    let (w, mu_over_u) = match wind {
        WindLoad::UniformNormal(u) => (u.direction, u.mu_over_u),
        WindLoad::Aerodynamic(a) => (a.direction, a.mu_over_u),
    };
    let wd = [D::c(w[0]), D::c(w[1]), D::c(w[2])];
    let wt = dot(&wd, t);
    let wp = [wd[0] - wt * t[0], wd[1] - wt * t[1], wd[2] - wt * t[2]];
    let s = dot(&wp, &wp).sqrt();
    let inv_s = D::c(1.0) / s;
    let vn = dot(vm, &wp) * inv_s;
    let f = D::c(1.0) - mu_over_u * vn;
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

/// Forces on the two end nodes of segment `j` with their derivatives with respect to
/// `(x_a, x_b, v_a, v_b)` (slots 0-2, 3-5, 6-8, 9-11).
pub fn segment_forces(s: &Explicit, j: usize) -> ([D; 3], [D; 3]) {
    let w = &s.wire;
    let xa: [D; 3] = std::array::from_fn(|k| D::var(w.x[k][j], k));
    let xb: [D; 3] = std::array::from_fn(|k| D::var(w.x[k][j + 1], 3 + k));
    let va: [D; 3] = std::array::from_fn(|k| D::var(w.v[k][j], 6 + k));
    let vb: [D; 3] = std::array::from_fn(|k| D::var(w.v[k][j + 1], 9 + k));
    let (ea, eta) = (w.axial_stiffness_n[j], w.internal_friction_n_s[j]);
    let l0 = w.rest_length[j];
    let d = sub(&xb, &xa);
    let len = dot(&d, &d).sqrt();
    let inv_len = D::c(1.0) / len;
    let t = [d[0] * inv_len, d[1] * inv_len, d[2] * inv_len];
    let e = (1.0 / l0) * len + (-1.0);
    let dv = sub(&vb, &va);
    let edot = (1.0 / l0) * dot(&dv, &t);
    let raw = ea * e + eta * edot;
    let tension = match w.law {
        LawKind::Linear => raw,
        LawKind::TensionOnly => {
            if e.v > 0.0 {
                raw.max_c(0.0)
            } else {
                D::c(0.0)
            }
        }
    };
    let tension = w.intact[j] * tension;
    let vm: [D; 3] = std::array::from_fn(|k| 0.5 * (va[k] + vb[k]));
    let p = match &s.loads.wind {
        Some(wl) => wind_force(wl, s.loads.wind_scale, &t, len, &vm),
        None => [D::c(0.0); 3],
    };
    let q = s.loads.uniform_load_n_per_m;
    let lref = w.reference_length[j];
    let h = 0.5 * w.intact[j];
    let es: [D; 3] = std::array::from_fn(|k| h * (p[k] + q[k] * lref));
    let fa = std::array::from_fn(|k| tension * t[k] + es[k]);
    let fb = std::array::from_fn(|k| -(tension * t[k]) + es[k]);
    (fa, fb)
}

/// Entries of `dF/dx + cv dF/dv - cm M` over the free nodes (rows and columns as given by
/// [`unknown_index`]), in assembly order: segment by segment the 3x3 blocks of its two end nodes, then the
/// mass diagonal. A position appears once per contribution (the sparse matrix sums them). `pattern` gets
/// the positions, `values` the numbers (both cleared first); the pattern depends only on which nodes are
/// free, so it can be factored symbolically once ([`super::SparseLu`]). Panics (internal misuse) if a wind
/// gate other than `Always` is set.
pub fn assemble(s: &Explicit, cv: f64, cm: f64, pattern: &mut Vec<Pair<usize, usize>>, values: &mut Vec<f64>) {
    assert_eq!(s.loads.wind_gate, WindGate::Always, "the implicit reference does not model the downwind gate");
    let (idx, _) = unknown_index(s);
    pattern.clear();
    values.clear();
    for j in 0..s.wire.segments() {
        let (fa, fb) = segment_forces(s, j);
        for (row_node, f) in [(j, &fa), (j + 1, &fb)] {
            let Some(r0) = idx[row_node] else { continue };
            for (side, col_node) in [(0, j), (1, j + 1)] {
                let Some(c0) = idx[col_node] else { continue };
                for k in 0..3 {
                    for l in 0..3 {
                        pattern.push(Pair::new(r0 + k, c0 + l));
                        values.push(f[k].d[3 * side + l] + cv * f[k].d[6 + 3 * side + l]);
                    }
                }
            }
        }
    }
    for (i, o) in idx.iter().enumerate() {
        if let Some(r0) = o {
            for k in 0..3 {
                pattern.push(Pair::new(r0 + k, r0 + k));
                values.push(-cm * s.wire.mass[i]);
            }
        }
    }
}

/// Largest difference [N] between the replica's nodal forces (plus gravity and prescribed forces) and
/// the library's `net_force` at the solver's current state: rounding level when the replica is faithful.
pub fn replica_gap(s: &mut Explicit) -> f64 {
    let n1 = s.wire.nodes();
    let mut lib = [vec![0.0; n1], vec![0.0; n1], vec![0.0; n1]];
    s.net_force(&mut lib);
    let mut mine = [vec![0.0; n1], vec![0.0; n1], vec![0.0; n1]];
    for j in 0..s.wire.segments() {
        let (fa, fb) = segment_forces(s, j);
        for k in 0..3 {
            mine[k][j] += fa[k].v;
            mine[k][j + 1] += fb[k].v;
        }
    }
    let mut gap: f64 = 0.0;
    for i in 0..n1 {
        mine[2][i] -= s.wire.mass[i] * s.loads.gravity_m_per_s2;
        for k in 0..3 {
            if let Some(f) = &s.nodal_force {
                mine[k][i] += f[k][i];
            }
            gap = gap.max((mine[k][i] - lib[k][i]).abs());
        }
    }
    gap
}
