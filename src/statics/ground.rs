//! Ground contact in the static solver: a frictionless penalty on the nodes below the surface.
//!
//! The explicit scheme projects a node that crosses the ground back onto it (section 4.4,
//! [`crate::scheme::contact`]): a hard, one-sided constraint that Newton's method cannot linearise. At
//! rest the same contact is taken here as a stiff one-sided spring along the surface normal. With the
//! depth of node `i` below the surface, measured along the normal `n = (0, -h', 1) / sqrt(1 + h'^2)` of
//! the piece of ground under it ([`crate::scheme::Ground::surface`]),
//!
//! ```text
//! d_i = (h(x2_i) - x3_i) / sqrt(1 + h'^2),        G_i = k max(d_i, 0) n   [N]
//! ```
//!
//! is added to the net force `F_i` of every free node. `G` is minus the gradient of the energy
//! `k max(d, 0)^2 / 2`, which is continuously differentiable, so the solver's line search on the work of
//! the residual (module doc of [`crate::statics`]) stays an energy descent. Its Jacobian is
//! `dG/dx = -k n n^T` (the kink of a terrain profile between pieces is ignored), taken for every node with
//! `d >= 0`: a node laid exactly on the ground has the contact's stiffness in its first step.
//!
//! The contact is frictionless: a static friction force is not determined by the rest state (it depends
//! on how the wire came to rest, and the explicit run with friction creeps rather than settles:
//! docs/decisions.md, "A broken conductor's residual state on the ground"), and a wire lying on
//! frictionless ground carries no tension along it. Restitution plays no part at rest.
//!
//! # Stiffness
//!
//! `k = max_j EA_j / l0_j`, the axial stiffness of the stiffest segment: a node resting on the ground sinks
//! into it by its weight over `k`, the stretch its own weight gives a segment (about 9e-6 m for a 4 m
//! segment of ACSR Drake, 64 N over 7.3e6 N/m), and the Jacobian's entries stay of the order they have
//! anyway, so its conditioning is unchanged. A support's vertical load changes by the conductor weight over
//! that depth, `w d` (1.4e-4 N for Drake).

use super::jacobian::max_axial_stiffness_n_per_m;
use crate::scheme::{Explicit, Ground};
use faer::sparse::Pair;

/// The penalty contact of a solve.
#[derive(Clone, Debug)]
pub struct GroundPenalty {
    /// the ground surface
    pub ground: Ground,
    /// penalty stiffness `k` [N/m] (module doc)
    pub stiffness_n_per_m: f64,
}

impl GroundPenalty {
    /// The contact with `ground` for the wire of `s`, with the stiffness of the module doc.
    pub fn of(s: &Explicit, ground: &Ground) -> Self {
        GroundPenalty { ground: ground.clone(), stiffness_n_per_m: max_axial_stiffness_n_per_m(s) }
    }

    /// Depth `d` [m] of the point `x` [m] below the surface along its normal, and the unit normal.
    pub fn depth(&self, x: [f64; 3]) -> (f64, [f64; 3]) {
        let (h, slope) = self.ground.surface(x[1]);
        let inv = 1.0 / (1.0 + slope * slope).sqrt();
        ((h - x[2]) * inv, [0.0, -slope * inv, inv])
    }

    /// The contact force `G` [N] on a node at `x` [m] (module doc); zero above the ground.
    pub fn force(&self, x: [f64; 3]) -> [f64; 3] {
        let (d, n) = self.depth(x);
        let g = self.stiffness_n_per_m * d.max(0.0);
        n.map(|c| g * c)
    }

    /// Append the positions of the contact's Jacobian entries: the 3x3 diagonal block of every free node
    /// (`idx` its first unknown, `None` for a fixed node), in the order [`GroundPenalty::values`] writes.
    pub fn pattern(&self, idx: &[Option<usize>], out: &mut Vec<Pair<usize, usize>>) {
        for o in idx.iter().flatten() {
            for k in 0..3 {
                for l in 0..3 {
                    out.push(Pair::new(o + k, o + l));
                }
            }
        }
    }

    /// Append the blocks [`GroundPenalty::block`] of every free node, in the order of
    /// [`GroundPenalty::pattern`].
    pub fn values(&self, s: &Explicit, idx: &[Option<usize>], out: &mut Vec<f64>) {
        for (i, o) in idx.iter().enumerate() {
            if o.is_some() {
                out.extend(self.block(s.wire().position(i)));
            }
        }
    }

    /// `dG/dx = -k n n^T` [N/m] at `x` [m], row by row: the contact's stiffness wherever `d >= 0` (module
    /// doc), zero above the ground.
    pub fn block(&self, x: [f64; 3]) -> [f64; 9] {
        let (d, n) = self.depth(x);
        let k = if d >= 0.0 { self.stiffness_n_per_m } else { 0.0 };
        std::array::from_fn(|e| -k * n[e / 3] * n[e % 3])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The force is the negative gradient of `k max(d, 0)^2 / 2` and `values` its derivative, checked by
    /// central differences on a slope. On one piece the energy is quadratic and the force linear, so the
    /// differences are exact but for rounding: `eps E / h` ~ 1e-8 N for the gradient (tolerance 1e-6 N),
    /// `eps |G| / h` ~ 1e-7 N/m for the derivative (tolerance 1e-4 N/m, 1e-10 of `k`).
    #[test]
    fn the_force_is_the_energy_gradient_and_values_its_derivative() {
        let g = Ground { profile_m: vec![[0.0, 0.0], [100.0, 10.0]], ..Ground::level(0.0, 0.5, 0.3) };
        let p = GroundPenalty { ground: g, stiffness_n_per_m: 1.0e6 };
        let x = [1.0, 50.0, 4.9];
        let energy = |x: [f64; 3]| 0.5 * p.stiffness_n_per_m * p.depth(x).0.max(0.0).powi(2);
        let f = p.force(x);
        let h = 1e-4;
        for k in 0..3 {
            let (mut a, mut b) = (x, x);
            a[k] += h;
            b[k] -= h;
            let grad = (energy(a) - energy(b)) / (2.0 * h);
            assert!((f[k] + grad).abs() <= 1e-6, "k={k}: {} vs {}", f[k], -grad);
            for l in 0..3 {
                let d = (p.force(a)[l] - p.force(b)[l]) / (2.0 * h);
                let j = p.block(x)[3 * l + k];
                assert!((d - j).abs() <= 1e-4, "dG{l}/dx{k}: {d} vs {j}");
            }
        }
        // Above the ground nothing acts.
        assert_eq!(p.force([0.0, 50.0, 5.1]), [0.0; 3]);
        assert_eq!(p.block([0.0, 50.0, 5.1]), [0.0; 9]);
        // On a level ground the force is vertical and k d.
        let level = GroundPenalty { ground: Ground::level(2.0, 0.0, 0.0), stiffness_n_per_m: 1.0e6 };
        assert_eq!(level.force([3.0, 7.0, 1.5]), [0.0, 0.0, 5.0e5]);
    }
}
