//! An axial link between two points `a` and `b`: the Kelvin-Voigt law (3.4) of a conductor segment,
//! applied to a single element that joins a conductor node to another conductor's node or to a support.
//!
//! ```text
//! d = r_b - r_a,   L = |d|,   t = d / L,   e = L / L0 - 1,   edot = (v_b - v_a) . t / L0,
//! T = EA e + BA edot           (linear: spacers, which also push)
//! T = max(EA e + BA edot, 0)   for e > 0, else 0 (tension only: insulator strings)
//! F_b = -T t,   F_a = +T t,    W = EA L0 e^2 / 2   (for e > 0 only under the tension-only law)
//! ```
//!
//! `L0` [m] is the unstretched length, `EA` [N] the axial stiffness (a spring of `k = EA / L0` [N/m]) and
//! `BA` [N s] the axial damping (MoorDyn's `BA`: a damper of `c = BA / L0` [N s/m] along the link). The
//! velocities are the kernel's half-step `v^{n-1/2}`, as for the conductor's own Kelvin-Voigt rate.
//!
//! The same function computes the force for the explicit step (`f64`) and for the static Jacobian (dual
//! numbers over the two end positions): [`LinkLaw::force_on_b`].

use super::scalar::{Scalar, dot3, sub3};

/// Axial law of a link.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinkLaw {
    /// unstretched length `L0` [m]
    pub rest_length_m: f64,
    /// axial stiffness `EA` [N] (spring `EA / L0` [N/m])
    pub axial_stiffness_n: f64,
    /// axial damping `BA` [N s] (damper `BA / L0` [N s/m])
    pub axial_damping_n_s: f64,
    /// whether the link also pushes (a spacer) or only pulls (a string)
    pub compression: bool,
}

impl LinkLaw {
    /// A spring of stiffness `k` [N/m] and damper `c` [N s/m] of unstretched length `L0` [m] that pushes
    /// as well as pulls (a spacer arm).
    pub fn spring(rest_length_m: f64, stiffness_n_per_m: f64, damping_n_s_per_m: f64) -> Self {
        LinkLaw {
            rest_length_m,
            axial_stiffness_n: stiffness_n_per_m * rest_length_m,
            axial_damping_n_s: damping_n_s_per_m * rest_length_m,
            compression: true,
        }
    }

    /// A tension-only string of length `L0` [m], axial stiffness `EA` [N] and axial damping `BA` [N s].
    pub fn string(rest_length_m: f64, axial_stiffness_n: f64, axial_damping_n_s: f64) -> Self {
        LinkLaw { rest_length_m, axial_stiffness_n, axial_damping_n_s, compression: false }
    }

    /// Spring constant `k = EA / L0` [N/m].
    pub fn stiffness_n_per_m(&self) -> f64 {
        self.axial_stiffness_n / self.rest_length_m
    }

    /// Damping constant `c = BA / L0` [N s/m].
    pub fn damping_n_s_per_m(&self) -> f64 {
        self.axial_damping_n_s / self.rest_length_m
    }

    /// Tension `T` [N] and length `L` [m] for the separation `d = r_b - r_a` and the relative velocity
    /// `dv = v_b - v_a`.
    #[inline(always)]
    pub fn tension<S: Scalar>(&self, d: [S; 3], dv: [S; 3]) -> (S, S) {
        let len = dot3(d, d).sqrt();
        let l0 = S::c(self.rest_length_m);
        let e = len / l0 - S::c(1.0);
        let edot = dot3(dv, d) / len / l0;
        let t = S::c(self.axial_stiffness_n) * e + S::c(self.axial_damping_n_s) * edot;
        if self.compression {
            (t, len)
        } else if e.value() > 0.0 {
            (t.positive_part(), len)
        } else {
            (S::c(0.0), len)
        }
    }

    /// Force on end `b` [N] (the force on `a` is its negative) for the end positions `ra, rb` [m] and
    /// velocities `va, vb` [m/s]. A link of zero length exerts nothing (its direction is undefined).
    #[inline(always)]
    pub fn force_on_b<S: Scalar>(&self, ra: [S; 3], rb: [S; 3], va: [S; 3], vb: [S; 3]) -> [S; 3] {
        self.tension_and_force_on_b(ra, rb, va, vb).1
    }

    /// The tension `T` [N] and the force on end `b` [N] together ([`LinkLaw::force_on_b`]).
    #[inline(always)]
    pub fn tension_and_force_on_b<S: Scalar>(&self, ra: [S; 3], rb: [S; 3], va: [S; 3], vb: [S; 3]) -> (S, [S; 3]) {
        let d = sub3(rb, ra);
        let (t, len) = self.tension(d, sub3(vb, va));
        if len.value() == 0.0 {
            return (t, [S::c(0.0); 3]);
        }
        // Written as a suspension string's force on its clamp (`wire::insulator`), operation for operation,
        // so that a string modelled as a link gives the same numbers.
        (t, [-t * d[0] / len, -t * d[1] / len, -t * d[2] / len])
    }

    /// Elastic energy `EA L0 e^2 / 2` [J] at length `len` [m] (none in compression for a string).
    pub fn energy_j(&self, len: f64) -> f64 {
        let e = len / self.rest_length_m - 1.0;
        if !self.compression && e <= 0.0 {
            return 0.0;
        }
        0.5 * self.axial_stiffness_n * self.rest_length_m * e * e
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::statics::dual::Dual;

    #[test]
    fn a_spring_pulls_when_stretched_and_pushes_when_compressed() {
        let s = LinkLaw::spring(0.4, 1.0e6, 0.0);
        let f = s.force_on_b([0.0; 3], [0.41, 0.0, 0.0], [0.0; 3], [0.0; 3]);
        assert!((f[0] + 1.0e6 * 0.01).abs() < 1e-6, "{f:?}");
        let f = s.force_on_b([0.0; 3], [0.39, 0.0, 0.0], [0.0; 3], [0.0; 3]);
        assert!((f[0] - 1.0e6 * 0.01).abs() < 1e-6, "{f:?}");
        // A string carries nothing when slack.
        let st = LinkLaw::string(4.0, 5.0e7, 1.0e4);
        assert_eq!(st.force_on_b([0.0; 3], [0.0, 0.0, -3.99], [0.0; 3], [0.0; 3]), [0.0; 3]);
    }

    #[test]
    fn axial_damping_acts_on_the_rate_of_stretch_only() {
        // c = BA / L0; a relative velocity across the link does not change its length.
        let st = LinkLaw::string(4.0, 5.0e7, 2.0e4);
        let (ra, rb) = ([0.0; 3], [0.0, 0.0, -4.001]);
        let still = st.force_on_b(ra, rb, [0.0; 3], [0.0; 3]);
        let across = st.force_on_b(ra, rb, [0.0; 3], [0.3, 0.0, 0.0]);
        let opening = st.force_on_b(ra, rb, [0.0; 3], [0.0, 0.0, -0.1]);
        assert!((across[2] - still[2]).abs() < 1e-9 * still[2].abs());
        // edot = (dL/dt) / L0 and T = BA edot: the damper c = BA / L0 times the opening speed 0.1 m/s.
        let expected = st.damping_n_s_per_m() * 0.1;
        assert!((opening[2] - still[2] - expected).abs() < 1e-9 * expected, "{} vs {expected}", opening[2] - still[2]);
    }

    /// The dual-number derivative of the force is the derivative of the `f64` force: central differences
    /// with step h = 1e-6 m have truncation error O(h^2 k / L) ~ 1e-6 of k and rounding ~ 1e-16 |F| / h;
    /// the tolerance 1e-6 relative to the stiffness is above both.
    #[test]
    fn dual_derivative_matches_finite_differences() {
        let law = LinkLaw::spring(0.45, 2.0e6, 0.0);
        let (ra, rb) = ([0.1, -0.2, 0.05], [0.5, 0.1, -0.3]);
        let var = |r: [f64; 3], off: usize| [0, 1, 2].map(|k| Dual::<6>::var(r[k], off + k));
        let z = [Dual::<6>::c(0.0); 3];
        let f = law.force_on_b(var(ra, 0), var(rb, 3), z, z);
        let h = 1.0e-6;
        for slot in 0..6 {
            let shifted = |sign: f64| {
                let (mut a, mut b) = (ra, rb);
                if slot < 3 {
                    a[slot] += sign * h
                } else {
                    b[slot - 3] += sign * h
                }
                law.force_on_b(a, b, [0.0; 3], [0.0; 3])
            };
            let (p, m) = (shifted(1.0), shifted(-1.0));
            for k in 0..3 {
                let fd = (p[k] - m[k]) / (2.0 * h);
                assert!((f[k].d[slot] - fd).abs() < 1e-6 * law.stiffness_n_per_m(), "slot {slot} k {k}");
            }
        }
    }

    #[test]
    fn energy_is_the_work_of_the_tension() {
        let st = LinkLaw::string(3.5, 4.0e7, 0.0);
        let (l1, l2) = (3.5005, 3.502);
        let n = 2000;
        let h = (l2 - l1) / n as f64;
        let work: f64 = (0..n).map(|k| st.tension([0.0, 0.0, l1 + (k as f64 + 0.5) * h], [0.0; 3]).0 * h).sum();
        let de = st.energy_j(l2) - st.energy_j(l1);
        assert!((work - de).abs() < 1e-9 * de, "{work} vs {de}");
    }
}
