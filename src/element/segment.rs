//! The conductor's own segment `i+1/2` between nodes `a = i` and `b = i + 1`: its stretch, its
//! Kelvin-Voigt tension (3.4) and its distributed loads (2.5)-(2.6), as the segment pass of the scheme
//! (3.1) forms them.
//!
//! ```text
//! d = r_b - r_a,  len = |d|,  t = d (1 / len),  e = len (1 / l0) - 1,  edot = ((v_b - v_a) . t) (1 / l0)
//! T = intact L(EA, eta, e, edot)                     (the law L: tension-only or linear, (3.4))
//! E = intact / 2 (P(t, len, (v_a + v_b) / 2; k) + q lref)  (wind law P (2.5)-(2.6), uniform load q)
//! force on a:  +T t + exposed_a E,      force on b:  -T t + exposed_b E                     (3.1)
//! ```
//!
//! `k` [-] is the segment's wind diameter factor (radial ice: `(d + 2 t) / d`, 1 bare; see
//! [`super::aero`]), `l0` [m] is the stress-free length (thermal strain scales it), `lref` [m] the reference length the
//! uniform load `q` [N/m] is given per, `intact` 1 or 0 (a broken segment carries nothing) and the
//! velocities the half-step `v^{n-1/2}` of (3.1). The reciprocals are formed once and multiplied, as the
//! vectorised kernel needs.
//!
//! Written once over a [`Scalar`]: the explicit kernel calls [`evaluate`] on `f64` for every segment of
//! its fused pass (`Explicit::segment_pass_body`, the same operations in the same order, so the same
//! bits), the static solver's Jacobian on dual numbers (`statics::jacobian::segment_forces`), and the
//! diagnostics ([`stretch`] and the law for a segment's tension; the loads alone for the static
//! solver's load scale).

use super::aero::SegmentLoad;
use super::scalar::{Scalar, dot3, sub3};
use super::tension::TensionLaw;

/// The per-segment constants of a conductor segment (each segment keeps its own: a line may join
/// conductors of different kinds).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SegmentProps {
    /// axial stiffness `EA` [N]
    pub axial_stiffness_n: f64,
    /// internal friction `eta` [N s] (Kelvin-Voigt)
    pub internal_friction_n_s: f64,
    /// stress-free length `l0` [m]
    pub rest_length_m: f64,
    /// reference length `lref` [m] of the uniform load
    pub reference_length_m: f64,
    /// 1 for an intact segment, 0 for a broken one [-]
    pub intact: f64,
    /// the diameter the wind acts on over the conductor's [-] (radial ice `t`: `(d + 2 t) / d`; 1 bare)
    pub wind_diameter_factor: f64,
}

/// The geometry and strain of a segment.
#[derive(Clone, Copy, Debug)]
pub struct Stretch<S> {
    /// deformed length `len = |r_b - r_a|` [m]
    pub len: S,
    /// unit tangent `t` [-]
    pub t: [S; 3],
    /// strain `e = len / l0 - 1` [-]
    pub e: S,
    /// strain rate `edot = (v_b - v_a) . t / l0` [1/s]
    pub edot: S,
}

/// The segment pass's result for one segment.
#[derive(Clone, Copy, Debug)]
pub struct SegmentForce<S> {
    /// geometry and strain
    pub stretch: Stretch<S>,
    /// tension `T` [N] (times `intact`)
    pub tension: S,
    /// each end's share of the distributed load `E = intact (P + q lref) / 2` [N] (applied at an end
    /// only while that node is exposed)
    pub share: [S; 3],
}

impl<S: Scalar> SegmentForce<S> {
    /// The tension force `T t` [N] (on end `a`; end `b` receives its negative).
    #[inline(always)]
    pub fn tension_force(&self) -> [S; 3] {
        let t = self.stretch.t;
        [self.tension * t[0], self.tension * t[1], self.tension * t[2]]
    }
}

/// Geometry and strain of the segment from end positions `xa, xb` [m] and velocities `va, vb` [m/s].
#[inline(always)]
pub fn stretch<S: Scalar>(xa: [S; 3], xb: [S; 3], va: [S; 3], vb: [S; 3], rest_length_m: f64) -> Stretch<S> {
    stretch_by_inverse(xa, xb, va, vb, 1.0 / rest_length_m)
}

/// [`stretch`] given the inverse of the stress-free length `1 / l0` [1/m] (the same number, so the same
/// bits, when it is `1.0 / l0` computed beforehand: the explicit kernel keeps them between steps).
#[inline(always)]
pub fn stretch_by_inverse<S: Scalar>(xa: [S; 3], xb: [S; 3], va: [S; 3], vb: [S; 3], inv_l0: f64) -> Stretch<S> {
    let d = sub3(xb, xa);
    let len = dot3(d, d).sqrt();
    let inv_len = S::c(1.0) / len;
    let t = [d[0] * inv_len, d[1] * inv_len, d[2] * inv_len];
    let e = len * inv_l0 - 1.0;
    let dv = sub3(vb, va);
    let edot = dot3(dv, t) * inv_l0;
    Stretch { len, t, e, edot }
}

/// One end's share of the distributed load `intact (P + q lref) / 2` [N] of a segment of the given
/// stretch (tangent `t`, length `len` [m]), end velocities `va, vb` [m/s], reference length `lref` [m],
/// `intact` (1 or 0) and wind diameter factor `k` [-]. `UNIFORM = false` (all of `q` zero) skips `q lref`:
/// `P + 0` can differ from `P` only in the sign of a zero.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub fn share<S: Scalar, W: SegmentLoad, const UNIFORM: bool>(
    load: &W,
    stretch: &Stretch<S>,
    va: [S; 3],
    vb: [S; 3],
    q: [f64; 3],
    reference_length_m: f64,
    intact: f64,
    wind_diameter_factor: f64,
) -> [S; 3] {
    let vm = [(va[0] + vb[0]) * 0.5, (va[1] + vb[1]) * 0.5, (va[2] + vb[2]) * 0.5];
    let p = load.force_with_diameter_factor(stretch.t, stretch.len, vm, wind_diameter_factor);
    let h = 0.5 * intact;
    if UNIFORM {
        let lref = reference_length_m;
        [(p[0] + q[0] * lref) * h, (p[1] + q[1] * lref) * h, (p[2] + q[2] * lref) * h]
    } else {
        [p[0] * h, p[1] * h, p[2] * h]
    }
}

/// The segment's tension and load share (module doc). `VISCOUS = false` (no internal friction anywhere)
/// evaluates the law with a zero strain rate, `L(EA, 0, e, 0)`: it differs from `L(EA, 0, e, edot)` only
/// in the sign of a zero tension, and the strain rate is then not needed.
#[inline(always)]
pub fn evaluate<S: Scalar, L: TensionLaw, W: SegmentLoad, const UNIFORM: bool, const VISCOUS: bool>(
    xa: [S; 3],
    xb: [S; 3],
    va: [S; 3],
    vb: [S; 3],
    props: &SegmentProps,
    load: &W,
    q: [f64; 3],
) -> SegmentForce<S> {
    let st = stretch(xa, xb, va, vb, props.rest_length_m);
    let tension = if VISCOUS {
        L::tension(props.axial_stiffness_n, props.internal_friction_n_s, st.e, st.edot) * props.intact
    } else {
        L::tension(props.axial_stiffness_n, 0.0, st.e, S::c(0.0)) * props.intact
    };
    let share = share::<S, W, UNIFORM>(
        load,
        &st,
        va,
        vb,
        q,
        props.reference_length_m,
        props.intact,
        props.wind_diameter_factor,
    );
    SegmentForce { stretch: st, tension, share }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::element::aero::{Aerodynamic, NoWind};
    use crate::element::tension::{Linear, TensionOnly};
    use crate::statics::dual::Dual;

    const PROPS: SegmentProps = SegmentProps {
        axial_stiffness_n: 2.9e7,
        internal_friction_n_s: 3.0e3,
        rest_length_m: 2.0,
        reference_length_m: 2.0,
        intact: 1.0,
        wind_diameter_factor: 1.0,
    };
    const WIND: Aerodynamic = Aerodynamic { direction: [1.0, 0.0, 0.0], qd_cn: 8.1, qd_ct: 0.24, mu_over_u: 0.01 };

    /// The force on end `b` of the segment (`-T t + E`) as a function of the six end positions.
    fn force_b(x: [f64; 6], v: [f64; 6]) -> [f64; 3] {
        let f = evaluate::<f64, TensionOnly, Aerodynamic, true, true>(
            [x[0], x[1], x[2]],
            [x[3], x[4], x[5]],
            [v[0], v[1], v[2]],
            [v[3], v[4], v[5]],
            &PROPS,
            &WIND,
            [0.0, 0.3, -1.2],
        );
        let tf = f.tension_force();
        [-tf[0] + f.share[0], -tf[1] + f.share[1], -tf[2] + f.share[2]]
    }

    #[test]
    fn a_straight_segment_under_its_own_strain_has_the_law_s_tension() {
        // Along x2, stretched by 0.1 %, the ends moving apart at 0.02 m/s: e = 1e-3, edot = 0.01 1/s.
        let f = evaluate::<f64, Linear, NoWind, false, true>(
            [0.0; 3],
            [0.0, 2.002, 0.0],
            [0.0; 3],
            [0.0, 0.02, 0.0],
            &PROPS,
            &NoWind,
            [0.0; 3],
        );
        let expect = 2.9e7 * 1.0e-3 + 3.0e3 * 0.01;
        // The strain is formed as 2.002 * (1 / 2) - 1: relative rounding of a few ulps of 1 in e.
        assert!((f.tension - expect).abs() < 1e-12 * 2.9e7, "{} vs {expect}", f.tension);
        assert_eq!(f.stretch.t, [0.0, 1.0, 0.0]);
    }

    #[test]
    fn dual_derivatives_match_finite_differences() {
        // The element on Dual<12> gives the exact derivatives of the f64 element: compare them with
        // central differences, whose truncation error is h^2 f''' / 6 ~ 1e-12 of the derivative at h = 1e-6
        // m on this 2 m segment, below the rounding error eps |f| / h ~ 1e-9 N/m relative to the
        // stiffness EA / l0 = 1.45e7 N/m: tolerance 1e-6 of it.
        let x = [0.1, -0.2, 0.05, 0.3, 1.95, -0.4];
        let v = [0.2, 0.0, -0.1, -0.3, 0.05, 0.4];
        let xd: [Dual<12>; 6] = std::array::from_fn(|k| Dual::var(x[k], k));
        let vd: [Dual<12>; 6] = std::array::from_fn(|k| Dual::var(v[k], 6 + k));
        let f = evaluate::<Dual<12>, TensionOnly, Aerodynamic, true, true>(
            [xd[0], xd[1], xd[2]],
            [xd[3], xd[4], xd[5]],
            [vd[0], vd[1], vd[2]],
            [vd[3], vd[4], vd[5]],
            &PROPS,
            &WIND,
            [0.0, 0.3, -1.2],
        );
        let tf = f.tension_force();
        let fb: [Dual<12>; 3] = std::array::from_fn(|k| -tf[k] + f.share[k]);
        let plain = force_b(x, v);
        let scale = PROPS.axial_stiffness_n / PROPS.rest_length_m;
        for k in 0..3 {
            assert_eq!(fb[k].v, plain[k], "the dual value is the f64 value, bit for bit");
            for slot in 0..12 {
                let h = 1.0e-6;
                let (mut xp, mut xm, mut vp, mut vm) = (x, x, v, v);
                if slot < 6 {
                    xp[slot] += h;
                    xm[slot] -= h;
                } else {
                    vp[slot - 6] += h;
                    vm[slot - 6] -= h;
                }
                let fd = (force_b(xp, vp)[k] - force_b(xm, vm)[k]) / (2.0 * h);
                assert!(
                    (fb[k].d[slot] - fd).abs() < 1e-6 * scale,
                    "component {k}, slot {slot}: {} vs {fd}",
                    fb[k].d[slot]
                );
            }
        }
    }
}
