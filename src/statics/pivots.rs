//! Elastic crossarm pivots as unknowns of the static solver.
//!
//! An elastic crossarm ([`crate::wire::insulator`]) lets the pivot `p` of a suspension string move
//! horizontally on springs `k_l` (along the line, `e_l`) and `k_t` (across it, `e_t = e3 x e_l`); it is
//! rigid vertically. At rest (pivot velocity zero, so no crossarm damping) its horizontal balance is
//!
//! ```text
//! G(p, c) = -k_l ((p - p0) . e_l) e_l - k_t ((p - p0) . e_t) e_t - F_s(c - p)|_h = 0   [N]
//! ```
//!
//! with `F_s(c - p)` the string's force on its clamp `c` (so `-F_s` is its pull on the pivot) and `|_h`
//! the two horizontal components. Each pivot adds the two unknowns `(p1, p2)` after the nodes' `3 (N + 1)`
//! (free nodes only). With `K = dF_s/dc` (the string's 3x3 stiffness, [`Insulator::stiffness`]) and
//! `dF_s/dp = -K`, the Jacobian gains, per pivot,
//!
//! ```text
//! dG/dp = -(k_l e_l e_l^T + k_t e_t e_t^T)|_hh + K|_hh      (2 x 2)
//! dG/dc = -K|_h.                                             (2 x 3)
//! dF_c/dp = -K|_.h                                           (3 x 2, the clamp node's rows)
//! ```
//!
//! `K` is taken with the solver's tension floor like every other string and segment, so the regularised
//! Jacobian stays that of a positive definite stiffness: the springs add `k_l`, `k_t > 0` to its diagonal.
//! A failed string (`intact = false`) exerts nothing: its pivot rests at `p0`, and the block is the
//! springs' alone.

use crate::scheme::Explicit;
use crate::wire::Insulator;
use faer::sparse::Pair;

/// The elastic crossarms of a wire and the index of their first unknown.
#[derive(Clone, Debug)]
pub struct Pivots {
    /// `(insulator index, first unknown)` of each elastic crossarm: unknowns `o` and `o + 1` are the
    /// pivot's `x1`, `x2` [m]
    pub unknowns: Vec<(usize, usize)>,
}

impl Pivots {
    /// The elastic crossarms of `s`, numbered from unknown `first` on; returns them and the new count.
    pub fn of(s: &Explicit, first: usize) -> (Pivots, usize) {
        let mut n = first;
        let mut unknowns = Vec::new();
        for (k, ins) in s.wire().insulators.iter().enumerate() {
            if ins.crossarm.is_some() {
                unknowns.push((k, n));
                n += 2;
            }
        }
        (Pivots { unknowns }, n)
    }

    /// Whether there is none.
    pub fn is_empty(&self) -> bool {
        self.unknowns.is_empty()
    }

    /// Append the positions of the pivots' Jacobian entries, in the order [`Pivots::values`] writes them;
    /// `idx` is the nodes' unknown index (`None` for a fixed node).
    pub fn pattern(&self, s: &Explicit, idx: &[Option<usize>], out: &mut Vec<Pair<usize, usize>>) {
        for &(k, o) in &self.unknowns {
            for a in 0..2 {
                for b in 0..2 {
                    out.push(Pair::new(o + a, o + b));
                }
            }
            let Some(r) = idx[s.wire().insulators[k].node] else { continue };
            for a in 0..2 {
                for l in 0..3 {
                    out.push(Pair::new(o + a, r + l));
                }
            }
            for l in 0..3 {
                for b in 0..2 {
                    out.push(Pair::new(r + l, o + b));
                }
            }
        }
    }

    /// Append the entries of the blocks of the module doc in the order of [`Pivots::pattern`], the
    /// strings' stiffness taken with the tension floor `floor_n` [N] (`None`: exact).
    pub fn values(&self, s: &Explicit, idx: &[Option<usize>], floor_n: Option<f64>, out: &mut Vec<f64>) {
        for &(k, _) in &self.unknowns {
            let ins = &s.wire().insulators[k];
            let arm = ins.crossarm.as_ref().expect("a pivot unknown has a crossarm");
            let kk = ins.stiffness(s.wire().position(ins.node), floor_n);
            let (el, et) = (arm.longitudinal, arm.transverse());
            for a in 0..2 {
                for b in 0..2 {
                    let spring = arm.longitudinal_n_per_m * el[a] * el[b] + arm.transverse_n_per_m * et[a] * et[b];
                    out.push(kk[3 * a + b] - spring);
                }
            }
            if idx[ins.node].is_none() {
                continue;
            }
            for a in 0..2 {
                for l in 0..3 {
                    out.push(-kk[3 * a + l]);
                }
            }
            for l in 0..3 {
                for b in 0..2 {
                    out.push(-kk[3 * l + b]);
                }
            }
        }
    }

    /// The pivots' residuals `G` (module doc) [N]: `-G` into `rhs` at their unknowns; returns the
    /// largest `|G_a|` and the sum of squares.
    pub fn residual(&self, s: &Explicit, rhs: &mut [f64]) -> (f64, f64) {
        let (mut max, mut sq) = (0.0_f64, 0.0);
        for &(k, o) in &self.unknowns {
            let g = balance(&s.wire().insulators[k], s.wire().position(s.wire().insulators[k].node));
            for a in 0..2 {
                rhs[o + a] = -g[a];
                max = max.max(g[a].abs());
                sq += g[a] * g[a];
            }
        }
        (max, sq)
    }

    /// Write the pivots' horizontal positions into `x` at their unknowns [m].
    pub fn gather(&self, s: &Explicit, x: &mut [f64]) {
        for &(k, o) in &self.unknowns {
            let p = s.wire().insulators[k].pivot_m;
            x[o] = p[0];
            x[o + 1] = p[1];
        }
    }

    /// Move the pivots to `x0 + lambda dx` at their unknowns [m].
    pub fn scatter(&self, s: &mut Explicit, x0: &[f64], dx: &[f64], lambda: f64) {
        for &(k, o) in &self.unknowns {
            let p = &mut s.wire_mut().insulators[k].pivot_m;
            p[0] = x0[o] + lambda * dx[o];
            p[1] = x0[o + 1] + lambda * dx[o + 1];
        }
    }

    /// Zero the pivots' velocities (a static state; the crossarm damping then exerts nothing).
    pub fn stop(&self, s: &mut Explicit) {
        for &(k, _) in &self.unknowns {
            if let Some(arm) = s.wire_mut().insulators[k].crossarm.as_mut() {
                arm.velocity_m_per_s = [0.0; 3];
            }
        }
    }
}

/// Horizontal balance of a pivot at rest `G = spring - F_s|_h` [N] (module doc); `clamp` [m].
pub fn balance(ins: &Insulator, clamp: [f64; 3]) -> [f64; 2] {
    let arm = ins.crossarm.expect("a pivot balance needs a crossarm");
    let mut still = arm;
    still.velocity_m_per_s = [0.0; 3];
    let spring = still.spring_force(ins.pivot_m);
    let pull = ins.force_on_clamp(clamp);
    [spring[0] - pull[0], spring[1] - pull[1]]
}
