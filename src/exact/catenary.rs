//! Elastic catenary in a general 3D orientation (Irvine's parametric solution).
//!
//! Source: H. M. Irvine, "Cable Structures", MIT Press 1981, section 2.3
//! (the elastic catenary, equations for `x(s)`, `z(s)` and the two closure
//! conditions), here written for a load given per unit *unstretched* length.
//!
//! # Problem
//!
//! A perfectly flexible cable of unstretched length `L0` [m] and axial
//! stiffness `EA` [N] (linear elastic: strain `e = T / EA`) carries a uniform
//! load vector `q` [N/m] per unit unstretched length, in a fixed direction
//! (weight, or weight plus a uniform wind force). Its ends are pinned at the
//! supports `A` and `B` [m].
//!
//! # Frame and sign conventions
//!
//! * `w = |q|` [N/m]; "vertical" unit vector `e_v = -q / |q|` (against the
//!   load); "horizontal" unit vector `e_h` = the part of `B - A` normal to
//!   `e_v`, normalised (an error if the chord is parallel to the load).
//! * span `l = (B - A) . e_h > 0`, height difference `h = (B - A) . e_v`
//!   (`h > 0`: `B` is above `A`, i.e. further against the load).
//! * Lagrangian coordinate `s` in `[0, L0]`, measured along the unstretched
//!   cable from `A`.
//! * `H > 0` [N] is the (constant) component of the cable tension along
//!   `e_h`; `V` [N] is the component along `e_v` of the **support reaction at
//!   `A`**, i.e. of the force the support `A` exerts on the cable. `V > 0` is
//!   the usual case: support `A` holds the cable up and the cable leaves `A`
//!   heading *down* (along the load). With `V` so defined, Irvine's
//!   expression for `z(s)` below measures the coordinate *along* the load
//!   (downwards, sag positive); the code uses `eta = -z`, measured along
//!   `e_v` (upwards).
//! * The tension vector (force exerted on the part `[0, s]` by the part
//!   `[s, L0]`) is `T(s) = H e_h + (w s - V) e_v`, so that `dT/ds = -q`, and
//!   the reaction at `B` is `-T(L0)`: its `e_v` component is `W - V` with
//!   `W = w L0` the total load.
//!
//! # Equations (Irvine 1981, eqs. for the elastic catenary)
//!
//! With `a = V / H`, `b(s) = (V - w s) / H`:
//!
//! ```text
//! x(s)   = H s / EA + (H / w) [asinh(a) - asinh(b(s))]
//! z(s)   = (w s / EA) (V / w - s / 2) + (H / w) [sqrt(1 + a^2) - sqrt(1 + b(s)^2)]
//! eta(s) = -z(s)
//! T(s)   = sqrt(H^2 + (V - w s)^2)
//! r(s)   = A + x(s) e_h + eta(s) e_v
//! ```
//!
//! They integrate the equilibrium `dT/ds = -q` together with the
//! constitutive / compatibility relation `dr/ds = (1 + |T| / EA) T / |T|`.
//! `(H, V)` solve the closure conditions `x(L0) = l`, `eta(L0) = h`, here by
//! a 2D Newton iteration with the analytic Jacobian (Irvine's flexibility
//! matrix, which is symmetric):
//!
//! ```text
//! dx/dH   = L0/EA + (1/w) [asinh a - asinh b - a/sqrt(1+a^2) + b/sqrt(1+b^2)]
//! dx/dV   = (1/w) [1/sqrt(1+a^2) - 1/sqrt(1+b^2)]
//! deta/dH = -dx/dV
//! deta/dV = -L0/EA - (1/w) [a/sqrt(1+a^2) - b/sqrt(1+b^2)]
//! ```
//!
//! (`b = b(L0)`). The differences of `asinh` and of square roots are
//! evaluated in cancellation-free forms. The iteration is started from the
//! better (smaller residual) of a parabolic elastic estimate and an
//! inextensible-catenary estimate, and converged to `max(|x(L0) - l|,
//! |eta(L0) - h|) <= 1e-12 S` with `S = max(|B - A|, L0 (1 + T_max / EA))`
//! (`S = |B - A|` up to the strain for any cable not much longer than its
//! chord; for very slack or hugely stretched cables the terms of `x(L0)` and
//! `eta(L0)` reach `S`, and round-off forbids a tighter test), followed by
//! one polishing Newton step; in practice the residual ends near 1e-16.
//! Taut cables (`L0` shorter than the chord: the solution exists,
//! stretched) and very slack cables are both covered.
//!
//! The module also holds the paper's approximate parabolic elastic sag
//! (4.3)-(4.4), see [`paper_parabolic_sag_m`].

use super::roots::{Options1d, Options2d, System2, expand_upper, newton_2d, solve_bracketed};
use super::{ExactError, add3, dot3, norm3, require_finite3, require_positive, scale3, sub3};

/// Converged relative closure residual `max(|x(L0)-l|, |eta(L0)-h|) / S`,
/// `S = max(|B - A|, L0 (1 + T_max / EA))` (see the module documentation).
pub const CLOSURE_TOLERANCE: f64 = 1e-12;

/// Below this ratio `l / |B - A|` the chord counts as parallel to the load.
const MIN_SPAN_OVER_CHORD: f64 = 1e-9;

/// A solved elastic catenary (Irvine 1981), see the module documentation for
/// the frame and the sign conventions.
#[derive(Debug, Clone, PartialEq)]
pub struct ElasticCatenary {
    /// support A, start of the cable (`s = 0`) [m]
    a_m: [f64; 3],
    /// support B, end of the cable (`s = L0`) [m]
    b_m: [f64; 3],
    /// unstretched length L0 [m]
    unstretched_length_m: f64,
    /// load vector per unit unstretched length q [N/m]
    load_n_per_m: [f64; 3],
    /// axial stiffness EA [N]
    axial_stiffness_n: f64,
    /// load magnitude per unit unstretched length w = |q| [N/m]
    w_n_per_m: f64,
    /// "horizontal" unit vector e_h (normal to the load, towards B) [-]
    e_h: [f64; 3],
    /// "vertical" unit vector e_v = -q/|q| [-]
    e_v: [f64; 3],
    /// span l = (B - A) . e_h [m]
    span_m: f64,
    /// height difference h = (B - A) . e_v [m]
    height_m: f64,
    /// horizontal tension component H [N]
    h_n: f64,
    /// support reaction at A along e_v, V [N]
    v_n: f64,
    /// Newton iterations used by the solve [-]
    iterations: usize,
    /// achieved relative closure residual [-]
    residual: f64,
}

/// The dimensionless end quantities of the interval `[0, s]`:
/// `a = V/H`, `b = (V - w s)/H`, `ta = sqrt(1 + a^2)`, `tb = sqrt(1 + b^2)`,
/// `a - b = w s / H` (formed directly, not by subtraction) and
/// `d = sinh(asinh a - asinh b) = a tb - b ta`, evaluated without
/// cancellation.
#[derive(Debug, Clone, Copy)]
struct Ends {
    a: f64,
    b: f64,
    ta: f64,
    tb: f64,
    a_minus_b: f64,
    d: f64,
}

impl Ends {
    fn new(s: f64, h: f64, v: f64, w: f64) -> Self {
        let a = v / h;
        let b = (v - w * s) / h;
        let ta = a.hypot(1.0);
        let tb = b.hypot(1.0);
        let a_minus_b = w * s / h;
        let d = if a * b > 0.0 {
            // Same sign: a tb - b ta = (a^2 - b^2) / (a tb + b ta).
            a_minus_b * (a + b) / (a * tb + b * ta)
        } else {
            a * tb - b * ta
        };
        Self { a, b, ta, tb, a_minus_b, d }
    }
}

/// `asinh(d) - d` without cancellation for small `|d|`.
fn asinh_minus_identity(d: f64) -> f64 {
    if d.abs() >= 0.5 {
        return d.asinh() - d;
    }
    // asinh d = sum_n (-1)^n (2n)! / (4^n (n!)^2 (2n+1)) d^(2n+1); drop n = 0.
    let d2 = d * d;
    let mut coefficient = 1.0_f64; // (-1)^n (2n)! / (4^n (n!)^2)
    let mut power = d; // d^(2n+1)
    let mut sum = 0.0_f64;
    for n in 1..80 {
        let nf = n as f64;
        coefficient *= -(2.0 * nf - 1.0) / (2.0 * nf);
        power *= d2;
        let term = coefficient * power / (2.0 * nf + 1.0);
        sum += term;
        if term.abs() <= 1e-18 * sum.abs() {
            break;
        }
    }
    sum
}

/// In-plane coordinates `(x, eta)` [m] at Lagrangian `s` [m] for given
/// `H`, `V` [N], `w` [N/m], `EA` [N]; see the module documentation.
fn in_plane(s: f64, h: f64, v: f64, w: f64, ea: f64) -> (f64, f64) {
    let e = Ends::new(s, h, v, w);
    let x = h * s / ea + (h / w) * e.d.asinh();
    // (H/w)(ta - tb) = (H/w)(a - b)(a + b)/(ta + tb) with a - b = w s / H.
    let eta = (s / ea) * (0.5 * w * s - v) - s * (e.a + e.b) / (e.ta + e.tb);
    (x, eta)
}

/// The closure system `F(H, V) = (x(L0) - l, eta(L0) - h) / S`, scaled by
/// `S = max(c, L0 (1 + T_max / EA))`, an upper bound of every term of
/// `x(L0)` and `eta(L0)` (so that `1e-12` is attainable in round-off even
/// for cables stretched or slackened far beyond their chord).
struct Closure {
    l0: f64,
    w: f64,
    ea: f64,
    span: f64,
    height: f64,
    chord: f64,
}

impl Closure {
    fn scale(&self, x: [f64; 2]) -> f64 {
        let (h, v) = (x[0], x[1]);
        let t_max = h.hypot(v).max(h.hypot(v - self.w * self.l0));
        self.chord.max(self.l0 * (1.0 + t_max / self.ea))
    }

    /// The unscaled closure `(x(L0) - l, eta(L0) - h)` [m].
    fn unscaled_residual(&self, x: [f64; 2]) -> [f64; 2] {
        let (xe, eta) = in_plane(self.l0, x[0], x[1], self.w, self.ea);
        [xe - self.span, eta - self.height]
    }

    /// Analytic Jacobian of [`Self::unscaled_residual`] [m/N] (Irvine's
    /// flexibility matrix). Every entry is written without cancellation,
    /// which matters for taut, very stiff cables where `a, b ~ w L0 / H` are
    /// tiny.
    fn unscaled_jacobian(&self, x: [f64; 2]) -> [[f64; 2]; 2] {
        let e = Ends::new(self.l0, x[0], x[1], self.w);
        let inv_w = 1.0 / self.w;
        let flex = self.l0 / self.ea;
        let tatb = e.ta * e.tb;
        // 1/ta - 1/tb = (b^2 - a^2) / ((ta + tb) ta tb)
        let inv_diff = -e.a_minus_b * (e.a + e.b) / ((e.ta + e.tb) * tatb);
        // a/ta - b/tb = d / (ta tb)
        let ratio_diff = e.d / tatb;
        // asinh a - asinh b - (a/ta - b/tb) = asinh d - d / (ta tb): for small
        // |d| (both near d) as (asinh d - d) + d (ta tb - 1)/(ta tb), with
        // ta tb - 1 = (a^2 + b^2 + a^2 b^2) / (ta tb + 1); for large |d| the
        // direct form has no cancellation (and the split form would).
        let curvature_term = if e.d.abs() < 0.5 {
            let a2 = e.a * e.a;
            let b2 = e.b * e.b;
            let tatb_minus_1 = (a2 + b2 + a2 * b2) / (tatb + 1.0);
            asinh_minus_identity(e.d) + e.d * tatb_minus_1 / tatb
        } else {
            e.d.asinh() - ratio_diff
        };
        let dx_dh = flex + inv_w * curvature_term;
        let dx_dv = inv_w * inv_diff;
        let deta_dh = -dx_dv;
        let deta_dv = -flex - inv_w * ratio_diff;
        [[dx_dh, dx_dv], [deta_dh, deta_dv]]
    }
}

impl System2 for Closure {
    fn residual(&self, x: [f64; 2]) -> [f64; 2] {
        let f = self.unscaled_residual(x);
        let k = 1.0 / self.scale(x);
        [k * f[0], k * f[1]]
    }

    /// The unscaled Jacobian divided by the scale (the derivative of the
    /// scale multiplies `F` and vanishes at the root).
    fn jacobian(&self, x: [f64; 2]) -> Option<[[f64; 2]; 2]> {
        let j = self.unscaled_jacobian(x);
        let k = 1.0 / self.scale(x);
        Some([[k * j[0][0], k * j[0][1]], [k * j[1][0], k * j[1][1]]])
    }

    fn admissible(&self, x: [f64; 2]) -> bool {
        x[0] > 0.0 && x[0].is_finite() && x[1].is_finite()
    }

    fn typical_x(&self) -> [f64; 2] {
        let t = self.w * self.l0;
        [t, t]
    }
}

impl Closure {
    /// Parabolic elastic estimate: the chord tension `T` solves
    /// `L0 (1 + T/EA) = c + w_n^2 c^3 / (24 T^2)` with `w_n = w l / c` the
    /// load component normal to the chord per unit chord length; then
    /// `H = T l / c` and, by moments about B, `V = W/2 - H h / l`.
    fn parabolic_guess(&self) -> Result<[f64; 2], ExactError> {
        let (l0, c, ea) = (self.l0, self.chord, self.ea);
        let wn = self.w * self.span / c;
        let k = wn * wn * c * c * c / 24.0;
        // G(T) = L0 T^3/EA + (L0 - c) T^2 - K is negative at 0 and positive
        // at hi (see the bound below), with a single positive root.
        let g = |t: f64| (l0 * t * t * t / ea + (l0 - c) * t * t - k, 3.0 * l0 * t * t / ea + 2.0 * (l0 - c) * t);
        let hi = ea * (c - l0).max(0.0) / l0 + (k * ea / l0).cbrt();
        let hi = expand_upper(g, 0.0, hi * (1.0 + 1e-9) + f64::MIN_POSITIVE, 200)?;
        let t = solve_bracketed(g, 0.0, hi, Options1d { x_rel_tol: 1e-10, ..Options1d::default() })?;
        let h = t * self.span / c;
        Ok([h, 0.5 * self.w * l0 - h * self.height / self.span])
    }

    /// Inextensible-catenary estimate for a stretched length `L`, refined
    /// a few times with `L = L0 (1 + T_mean / EA)`. `None` if `L` does not
    /// exceed the chord.
    fn catenary_guess(&self) -> Option<[f64; 2]> {
        let (l, hgt, c) = (self.span, self.height, self.chord);
        let total = self.w * self.l0;
        let mut length = self.l0;
        let mut guess = None;
        for _ in 0..4 {
            if length <= c * (1.0 + 1e-12) {
                return guess;
            }
            // sinh(lam)/lam = sqrt(L^2 - h^2) / l, lam = l / (2 a_c).
            let ratio = ((length - hgt) * (length + hgt)).sqrt() / l;
            let sinhc = |lam: f64| {
                if lam < 1e-4 { 1.0 + lam * lam / 6.0 } else { lam.sinh() / lam }
            };
            let f = |lam: f64| (sinhc(lam) - ratio, lam.cosh() / lam.max(1e-300) - sinhc(lam) / lam.max(1e-300));
            let hi = expand_upper(f, 0.0, 1.0, 200).ok()?;
            let lam = solve_bracketed(f, 0.0, hi, Options1d { x_rel_tol: 1e-10, ..Options1d::default() }).ok()?;
            if lam <= 0.0 {
                return guess;
            }
            let w_eff = total / length;
            let h_n = w_eff * l / (2.0 * lam);
            let m = (-hgt * w_eff / (2.0 * h_n * lam.sinh())).asinh();
            let v_n = h_n * (m + lam).sinh();
            if !(h_n.is_finite() && v_n.is_finite() && h_n > 0.0) {
                return guess;
            }
            guess = Some([h_n, v_n]);
            let t_a = h_n.hypot(v_n);
            let t_b = h_n.hypot(total - v_n);
            length = self.l0 * (1.0 + 0.5 * (t_a + t_b) / self.ea);
        }
        guess
    }
}

impl ElasticCatenary {
    /// Solves the elastic catenary between supports `a` and `b` [m] for an
    /// unstretched length `unstretched_length_m` (L0 [m]), a load vector per
    /// unit unstretched length `load_n_per_m` (q [N/m]) and an axial
    /// stiffness `axial_stiffness_n` (EA [N]).
    pub fn solve(
        a: [f64; 3],
        b: [f64; 3],
        unstretched_length_m: f64,
        load_n_per_m: [f64; 3],
        axial_stiffness_n: f64,
    ) -> Result<Self, ExactError> {
        let a = require_finite3(a, "support A must be finite")?;
        let b = require_finite3(b, "support B must be finite")?;
        let l0 = require_positive(unstretched_length_m, "unstretched length L0 must be positive")?;
        let q = require_finite3(load_n_per_m, "load vector q must be finite")?;
        let ea = require_positive(axial_stiffness_n, "axial stiffness EA must be positive")?;
        let w = require_positive(norm3(q), "load magnitude |q| must be positive")?;
        let chord_vec = sub3(b, a);
        let chord = require_positive(norm3(chord_vec), "supports A and B must be distinct; chord |B - A|")?;

        let e_v = scale3(-1.0 / w, q);
        let height = dot3(chord_vec, e_v);
        let horizontal = sub3(chord_vec, scale3(height, e_v));
        let span = norm3(horizontal);
        if span <= MIN_SPAN_OVER_CHORD * chord {
            return Err(ExactError::InvalidInput {
                what: "chord B - A is parallel to the load; span / chord",
                value: span / chord,
            });
        }
        let e_h = scale3(1.0 / span, horizontal);

        let system = Closure { l0, w, ea, span, height, chord };
        // Both estimates are cheap; a crude one (H = V = W/2) backs them up.
        let total = w * l0;
        let candidates = [system.parabolic_guess().ok(), system.catenary_guess(), Some([0.5 * total, 0.5 * total])];
        let merit = |x: [f64; 2]| {
            let f = system.residual(x);
            let m = f[0].abs().max(f[1].abs());
            if m.is_finite() { m } else { f64::INFINITY }
        };
        // Newton from the best start; should it fail, from the others in turn.
        let mut starts: Vec<[f64; 2]> = candidates.into_iter().flatten().filter(|x| system.admissible(*x)).collect();
        starts.sort_by(|p, q| merit(*p).total_cmp(&merit(*q)));
        let opts = Options2d { residual_tol: CLOSURE_TOLERANCE, ..Options2d::default() };
        let mut outcome = Err(ExactError::NoConvergence {
            method: "elastic catenary initial guess",
            iterations: 0,
            residual: f64::NAN,
        });
        for x0 in starts {
            outcome = newton_2d(&system, x0, opts);
            if outcome.is_ok() {
                break;
            }
        }
        let sol = outcome?;
        Ok(Self {
            a_m: a,
            b_m: b,
            unstretched_length_m: l0,
            load_n_per_m: q,
            axial_stiffness_n: ea,
            w_n_per_m: w,
            e_h,
            e_v,
            span_m: span,
            height_m: height,
            h_n: sol.x[0],
            v_n: sol.x[1],
            iterations: sol.iterations,
            residual: sol.residual,
        })
    }

    /// The classic level span in the project's coordinates: `A = (0, 0, 0)`,
    /// `B = (0, span, 0)` (the span along `x2`), gravity load `q = (0, 0, -w)`
    /// with `w = weight_n_per_m` [N/m]; `span_m` [m], `unstretched_length_m`
    /// L0 [m], `axial_stiffness_n` EA [N].
    pub fn level(
        span_m: f64,
        unstretched_length_m: f64,
        weight_n_per_m: f64,
        axial_stiffness_n: f64,
    ) -> Result<Self, ExactError> {
        let span = require_positive(span_m, "span must be positive")?;
        let w = require_positive(weight_n_per_m, "weight per length must be positive")?;
        Self::solve([0.0, 0.0, 0.0], [0.0, span, 0.0], unstretched_length_m, [0.0, 0.0, -w], axial_stiffness_n)
    }

    /// horizontal tension component H [N] (constant along the cable)
    pub fn horizontal_tension_n(&self) -> f64 {
        self.h_n
    }

    /// support reaction at A along e_v, V [N] (`V > 0`: A holds the cable up)
    pub fn reaction_a_n(&self) -> f64 {
        self.v_n
    }

    /// support reaction at B along e_v, W - V [N], with W = w L0 the total load
    pub fn reaction_b_n(&self) -> f64 {
        self.w_n_per_m * self.unstretched_length_m - self.v_n
    }

    /// support A [m]
    pub fn support_a_m(&self) -> [f64; 3] {
        self.a_m
    }

    /// support B [m]
    pub fn support_b_m(&self) -> [f64; 3] {
        self.b_m
    }

    /// unstretched length L0 [m]
    pub fn unstretched_length_m(&self) -> f64 {
        self.unstretched_length_m
    }

    /// load vector per unit unstretched length q [N/m]
    pub fn load_n_per_m(&self) -> [f64; 3] {
        self.load_n_per_m
    }

    /// load magnitude per unit unstretched length w = |q| [N/m]
    pub fn load_magnitude_n_per_m(&self) -> f64 {
        self.w_n_per_m
    }

    /// axial stiffness EA [N]
    pub fn axial_stiffness_n(&self) -> f64 {
        self.axial_stiffness_n
    }

    /// "horizontal" unit vector e_h [-] (normal to the load, from A towards B)
    pub fn horizontal_unit(&self) -> [f64; 3] {
        self.e_h
    }

    /// "vertical" unit vector e_v = -q/|q| [-]
    pub fn vertical_unit(&self) -> [f64; 3] {
        self.e_v
    }

    /// span l = (B - A) . e_h [m]
    pub fn span_m(&self) -> f64 {
        self.span_m
    }

    /// height difference h = (B - A) . e_v [m]
    pub fn height_difference_m(&self) -> f64 {
        self.height_m
    }

    /// Newton iterations the solve took [-]
    pub fn iterations(&self) -> usize {
        self.iterations
    }

    /// achieved relative closure residual max(|x(L0) - l|, |eta(L0) - h|) / S [-],
    /// S = max(|B - A|, L0 (1 + T_max / EA))
    pub fn closure_residual(&self) -> f64 {
        self.residual
    }

    fn clamp_s(&self, s_m: f64) -> f64 {
        s_m.clamp(0.0, self.unstretched_length_m)
    }

    /// In-plane coordinates `(x(s), eta(s))` [m] relative to A along
    /// `(e_h, e_v)` at the Lagrangian coordinate `s_m` [m] (clamped to
    /// `[0, L0]`).
    pub fn in_plane_position_m(&self, s_m: f64) -> (f64, f64) {
        in_plane(self.clamp_s(s_m), self.h_n, self.v_n, self.w_n_per_m, self.axial_stiffness_n)
    }

    /// 3D position r(s) [m] of the material point at Lagrangian coordinate
    /// `s_m` [m] (clamped to `[0, L0]`).
    pub fn position(&self, s_m: f64) -> [f64; 3] {
        let (x, eta) = self.in_plane_position_m(s_m);
        add3(self.a_m, add3(scale3(x, self.e_h), scale3(eta, self.e_v)))
    }

    /// tension vector T(s) = H e_h + (w s - V) e_v [N], the force exerted on
    /// `[0, s]` by `[s, L0]`, at Lagrangian `s_m` [m] (clamped to `[0, L0]`)
    pub fn tension_vector_n(&self, s_m: f64) -> [f64; 3] {
        let s = self.clamp_s(s_m);
        add3(scale3(self.h_n, self.e_h), scale3(self.w_n_per_m * s - self.v_n, self.e_v))
    }

    /// tension magnitude T(s) = sqrt(H^2 + (V - w s)^2) [N] at Lagrangian
    /// `s_m` [m] (clamped to `[0, L0]`)
    pub fn tension_n(&self, s_m: f64) -> f64 {
        let s = self.clamp_s(s_m);
        self.h_n.hypot(self.v_n - self.w_n_per_m * s)
    }

    /// maximum tension over the cable [N]; `T(s)` is convex in `s`, so this
    /// is at a support (the higher one, along `e_v`)
    pub fn max_tension_n(&self) -> f64 {
        self.tension_n(0.0).max(self.tension_n(self.unstretched_length_m))
    }

    /// stretched length L = L0 + (1/EA) int_0^L0 T ds [m], in closed form
    pub fn stretched_length_m(&self) -> f64 {
        let (h, w) = (self.h_n, self.w_n_per_m);
        // int T ds = (1/w) int_{V-W}^{V} sqrt(H^2 + u^2) du
        let prim = |u: f64| 0.5 * (u * h.hypot(u) + h * h * (u / h).asinh());
        let integral = (prim(self.v_n) - prim(self.v_n - w * self.unstretched_length_m)) / w;
        self.unstretched_length_m + integral / self.axial_stiffness_n
    }

    /// midspan displacement r(L0/2) - (A + B)/2 [m], a 3-vector (for a
    /// level span under gravity, `-x3` of it is the classical midspan sag)
    pub fn midspan_displacement_m(&self) -> [f64; 3] {
        let mid = scale3(0.5, add3(self.a_m, self.b_m));
        sub3(self.position(0.5 * self.unstretched_length_m), mid)
    }
}

/// The paper's parameter (4.3) `gamma = w^2 l^2 / (24 EA^2)` [-] for a span
/// `span_m` l [m], a weight per length `weight_n_per_m` w [N/m] and an axial
/// stiffness `ea_n` EA [N].
pub fn paper_parabolic_gamma(span_m: f64, weight_n_per_m: f64, ea_n: f64) -> Result<f64, ExactError> {
    let l = require_positive(span_m, "span must be positive")?;
    let w = require_positive(weight_n_per_m, "weight per length must be positive")?;
    let ea = require_positive(ea_n, "axial stiffness EA must be positive")?;
    let r = w * l / ea;
    Ok(r * r / 24.0)
}

/// The paper's strain (4.4) `eps` [-]: the positive root of the cubic
/// `eps^3 - gamma eps - gamma = 0` for `gamma` [-] from (4.3).
///
/// The paper prints Cardano's form
/// `eps = cbrt(g/2 + sqrt((g/2)^2 - (g/3)^3)) + cbrt(g/2 - sqrt((g/2)^2 - (g/3)^3))`,
/// which is exactly this cubic; its discriminant is positive for
/// `gamma < 27/4`, but the second cube root suffers cancellation, so the
/// cubic is solved with the safeguarded Newton iteration instead. By
/// Descartes' rule of signs the positive root is unique.
pub fn paper_parabolic_strain(gamma: f64) -> Result<f64, ExactError> {
    let g = require_positive(gamma, "gamma must be positive")?;
    let f = |e: f64| (e * e * e - g * e - g, 3.0 * e * e - g);
    let hi = expand_upper(f, 0.0, g.cbrt(), 200)?;
    solve_bracketed(f, 0.0, hi, Options1d::default())
}

/// The paper's approximate elastic parabolic midspan sag (4.3)-(4.4) [m] of a
/// level span `span_m` l [m] whose unstretched length equals the span, under
/// a weight per length `weight_n_per_m` w [N/m], axial stiffness `ea_n`
/// EA [N]: `sag = l^2 w (1 + eps) / (8 EA eps)` with `eps` from
/// [`paper_parabolic_strain`].
pub fn paper_parabolic_sag_m(span_m: f64, weight_n_per_m: f64, ea_n: f64) -> Result<f64, ExactError> {
    let gamma = paper_parabolic_gamma(span_m, weight_n_per_m, ea_n)?;
    let eps = paper_parabolic_strain(gamma)?;
    Ok(span_m * span_m * weight_n_per_m * (1.0 + eps) / (8.0 * ea_n * eps))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The paper's conductor: 1.0 kg/m, EA = 80734 kgf.
    const G: f64 = 9.81;
    const W: f64 = 1.0 * G;
    const EA: f64 = 80734.0 * G;
    const SPAN: f64 = 160.0;

    /// A test case: (name, A [m], B [m], L0 [m], q [N/m], EA [N]).
    type Case = (&'static str, [f64; 3], [f64; 3], f64, [f64; 3], f64);

    /// A catalogue of cases.
    fn cases() -> Vec<Case> {
        vec![
            ("paper level span", [0.0; 3], [0.0, SPAN, 0.0], SPAN, [0.0, 0.0, -W], EA),
            ("inclined h = 20 m", [0.0; 3], [0.0, SPAN, 20.0], 163.0, [0.0, 0.0, -W], EA),
            ("inclined, B lower", [0.0, 0.0, 30.0], [0.0, SPAN, 0.0], 170.0, [0.0, 0.0, -W], EA),
            ("taut L0 = 0.99 chord", [0.0; 3], [0.0, SPAN, 0.0], 0.99 * SPAN, [0.0, 0.0, -W], EA),
            ("very taut L0 = 0.5 chord, soft", [0.0; 3], [0.0, SPAN, 0.0], 0.5 * SPAN, [0.0, 0.0, -W], 1e4),
            ("very slack L0 = 3 l", [0.0; 3], [0.0, SPAN, 0.0], 3.0 * SPAN, [0.0, 0.0, -W], EA),
            ("extremely slack L0 = 50 l", [0.0; 3], [0.0, 10.0, 0.0], 500.0, [0.0, 0.0, -W], EA),
            ("near-vertical chord", [0.0; 3], [0.0, 1.0, 100.0], 101.0, [0.0, 0.0, -W], EA),
            ("very soft EA", [0.0; 3], [0.0, SPAN, 10.0], SPAN, [0.0, 0.0, -W], 50.0 * W),
            ("wind + weight, level", [0.0; 3], [0.0, SPAN, 0.0], SPAN, [3.805, 0.0, -W], EA),
            ("skew 3D, wind + weight", [1.0, -2.0, 3.0], [20.0, 150.0, 40.0], 175.0, [3.805, -1.0, -W], 2.0e6),
        ]
    }

    fn solve_case(c: &Case) -> ElasticCatenary {
        ElasticCatenary::solve(c.1, c.2, c.3, c.4, c.5).unwrap_or_else(|e| panic!("{}: {e}", c.0))
    }

    /// Classic RK4 on y = (T_vec, r, stretched length) with
    /// dT/ds = -q, dr/ds = (1 + |T|/EA) T/|T|, dL/ds = 1 + |T|/EA.
    fn rk4(cat: &ElasticCatenary, steps: usize) -> ([f64; 3], [f64; 3], f64) {
        let q = cat.load_n_per_m();
        let ea = cat.axial_stiffness_n();
        let rhs = |y: &[f64; 7]| -> [f64; 7] {
            let t = [y[0], y[1], y[2]];
            let tn = norm3(t);
            let k = (1.0 + tn / ea) / tn;
            [-q[0], -q[1], -q[2], k * t[0], k * t[1], k * t[2], 1.0 + tn / ea]
        };
        let t0 = cat.tension_vector_n(0.0);
        let a = cat.support_a_m();
        let mut y = [t0[0], t0[1], t0[2], a[0], a[1], a[2], 0.0];
        let h = cat.unstretched_length_m() / steps as f64;
        let axpy = |y: &[f64; 7], k: f64, d: &[f64; 7]| -> [f64; 7] { std::array::from_fn(|i| y[i] + k * d[i]) };
        for _ in 0..steps {
            let k1 = rhs(&y);
            let k2 = rhs(&axpy(&y, 0.5 * h, &k1));
            let k3 = rhs(&axpy(&y, 0.5 * h, &k2));
            let k4 = rhs(&axpy(&y, h, &k3));
            y = std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
        }
        ([y[0], y[1], y[2]], [y[3], y[4], y[5]], y[6])
    }

    #[test]
    fn closure_residuals_and_end_positions() {
        for c in cases() {
            let cat = solve_case(&c);
            let chord = norm3(sub3(c.2, c.1));
            let (x, eta) = cat.in_plane_position_m(c.3);
            let rx = (x - cat.span_m()).abs() / chord;
            let rz = (eta - cat.height_difference_m()).abs() / chord;
            println!(
                "{:34} H = {:14.6} N  V = {:14.6} N  iters = {:2}  residual = {:.1e}",
                c.0,
                cat.horizontal_tension_n(),
                cat.reaction_a_n(),
                cat.iterations(),
                rx.max(rz)
            );
            // The solve stops at 1e-12 relative; re-evaluation can only differ by round-off.
            assert!(rx <= CLOSURE_TOLERANCE && rz <= CLOSURE_TOLERANCE, "{}: {rx:e} {rz:e}", c.0);
            let end = cat.position(c.3);
            let start = cat.position(0.0);
            // 3D reconstruction adds a few ulps of |B - A| on top of the closure residual.
            assert!(norm3(sub3(end, c.2)) <= 2.0 * CLOSURE_TOLERANCE * chord, "{}", c.0);
            assert!(norm3(sub3(start, c.1)) <= 1e-15 * chord.max(norm3(c.1)), "{}", c.0);
            assert!(cat.horizontal_tension_n() > 0.0);
        }
    }

    #[test]
    fn rk4_integration_of_equilibrium_ode_arrives_at_b() {
        // Independent route: integrate dT/ds = -q, dr/ds = (1 + |T|/EA) T/|T| from A
        // with the solved (H, V) only. The right-hand side is smooth on the scale
        // of the catenary parameter H/w >= ~5 m for the non-extreme cases while the
        // step is L0/20000 <= 0.025 m, so the RK4 truncation error (h^4 * |r^(5)|
        // * L0 ~ 1e-14 relative) is far below the 1e-9 tolerance; round-off over
        // 20000 steps adds ~1e-13. The extremely slack case (H/w ~ 1 m, steps of
        // 2.5 cm) still has truncation ~1e-11.
        for c in cases() {
            let cat = solve_case(&c);
            let chord = norm3(sub3(c.2, c.1));
            let (t_end, r_end, len) = rk4(&cat, 20000);
            let err_r = norm3(sub3(r_end, c.2)) / chord;
            let err_t = norm3(sub3(t_end, cat.tension_vector_n(c.3))) / cat.max_tension_n();
            let err_len = (len - cat.stretched_length_m()).abs() / len;
            println!("{:34} RK4 |r(L0) - B|/c = {err_r:.2e}  stretched length err = {err_len:.1e}", c.0);
            assert!(err_r < 1e-9, "{}: {err_r:e}", c.0);
            assert!(err_t < 1e-12, "{}: {err_t:e}", c.0);
            assert!(err_len < 1e-9, "{}: {err_len:e}", c.0);
            // And the ODE solution passes through the closed-form midpoint.
            let mut half = cat.clone();
            half.unstretched_length_m = 0.5 * c.3;
            let (_, r_mid, _) = rk4(&half, 10000);
            let err_mid = norm3(sub3(r_mid, cat.position(0.5 * c.3))) / chord;
            assert!(err_mid < 1e-9, "{}: midpoint {err_mid:e}", c.0);
        }
    }

    #[test]
    fn tension_height_identity() {
        // Along the cable dT/ds = w T_v/T and d(eta)/ds = (1 + T/EA) T_v/T, so
        // (T_B - T_A) + (T_B^2 - T_A^2)/(2 EA) = w h exactly: an identity that
        // does not use the closure equations. Round-off only: 1e-11 of T_max.
        for c in cases() {
            let cat = solve_case(&c);
            let (ta, tb) = (cat.tension_n(0.0), cat.tension_n(c.3));
            let lhs = (tb - ta) + (tb * tb - ta * ta) / (2.0 * c.5);
            let rhs = cat.load_magnitude_n_per_m() * cat.height_difference_m();
            assert!((lhs - rhs).abs() <= 1e-11 * cat.max_tension_n(), "{}: {lhs} vs {rhs}", c.0);
            // Hence sign(T_B - T_A) = sign(h): the maximum tension sits at the
            // higher support.
            let higher = if cat.height_difference_m() >= 0.0 { tb } else { ta };
            assert_eq!(cat.max_tension_n(), higher, "{}", c.0);
        }
    }

    #[test]
    fn analytic_jacobian_matches_finite_differences() {
        for c in cases() {
            let cat = solve_case(&c);
            let chord = norm3(sub3(c.2, c.1));
            let sys = Closure {
                l0: c.3,
                w: cat.load_magnitude_n_per_m(),
                ea: c.5,
                span: cat.span_m(),
                height: cat.height_difference_m(),
                chord,
            };
            /// The unscaled closure, with the finite-difference Jacobian.
            struct Unscaled<'a>(&'a Closure);
            impl System2 for Unscaled<'_> {
                fn residual(&self, x: [f64; 2]) -> [f64; 2] {
                    self.0.unscaled_residual(x)
                }
                fn admissible(&self, x: [f64; 2]) -> bool {
                    self.0.admissible(x)
                }
            }
            // Evaluate away from the root too.
            let x = [cat.horizontal_tension_n() * 1.1, cat.reaction_a_n() * 0.9 + 1.0];
            let ja = sys.unscaled_jacobian(x);
            let jf = super::super::roots::fd_jacobian(&Unscaled(&sys), x, 1e-6);
            let scale = ja.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
            for i in 0..2 {
                for k in 0..2 {
                    // Central differences with relative step 1e-6: truncation ~1e-12
                    // relative, round-off ~1e-16/1e-6 = 1e-10 relative.
                    assert!((ja[i][k] - jf[i][k]).abs() <= 1e-7 * scale, "{}: J[{i}][{k}]", c.0);
                }
            }
        }
    }

    #[test]
    fn level_span_is_symmetric_with_lowest_point_at_midspan() {
        let cat = ElasticCatenary::level(SPAN, 165.0, W, EA).unwrap();
        let l0 = 165.0;
        // V = W/2 by symmetry; the solve converges the geometry to 1e-12, which
        // pins V to ~1e-11 of W (conditioning of the flexibility matrix ~10).
        assert!((cat.reaction_a_n() - 0.5 * W * l0).abs() <= 1e-10 * W * l0);
        let mid = cat.position(0.5 * l0);
        for k in 1..200 {
            let s = l0 * k as f64 / 200.0;
            let p = cat.position(s);
            let m = cat.position(l0 - s);
            // Mirror symmetry about the midspan plane x2 = l/2.
            assert!((p[1] + m[1] - SPAN).abs() < 1e-9 && (p[2] - m[2]).abs() < 1e-9);
            assert!(p[2] >= mid[2]);
            assert_eq!(p[0], 0.0);
        }
        assert!((mid[1] - 0.5 * SPAN).abs() < 1e-10);
        // The tension is least at midspan and equals H there.
        assert!((cat.tension_n(0.5 * l0) - cat.horizontal_tension_n()).abs() < 1e-9 * cat.horizontal_tension_n());
    }

    /// Classical inextensible catenary: a from L0 = 2 a sinh(l / 2a), sag =
    /// a (cosh(l/2a) - 1), H = w a. Solved on its own with bisection/Newton in
    /// the variable a.
    fn classical_catenary(span: f64, l0: f64, w: f64) -> (f64, f64) {
        let f = |a: f64| {
            let u = span / (2.0 * a);
            (2.0 * a * u.sinh() - l0, 2.0 * u.sinh() - 2.0 * u * u.cosh())
        };
        // f decreases in a; f(small) > 0, f(large) -> span - l0 < 0.
        let a = solve_bracketed(f, 0.05 * span, 1e6 * span, Options1d::default()).unwrap();
        let u = span / (2.0 * a);
        (w * a, 2.0 * a * (0.5 * u).sinh().powi(2))
    }

    #[test]
    fn inextensible_limit_is_the_classical_catenary() {
        let l0 = 165.0;
        let (h_classic, sag_classic) = classical_catenary(SPAN, l0, W);
        // First-order prediction of the elastic correction, from the classical
        // solution alone: the cable lengthens by int T ds / EA, with
        // int T ds = H (l + a sinh(l/a)) / 2 on the classical catenary (a = H/w);
        // the classical sag of that longer cable, minus sag_classic, gives the
        // coefficient of 1/EA. It ignores that the strain (hence the load per
        // stretched length) varies along the cable; it agrees with the elastic
        // solution to 0.03 % here, asserted at 1 %.
        let a = h_classic / W;
        let int_t = 0.5 * h_classic * (SPAN + a * (SPAN / a).sinh());
        let ea_ref = 1e10;
        let (_, sag_longer) = classical_catenary(SPAN, l0 + int_t / ea_ref, W);
        let predicted = (sag_longer - sag_classic) / sag_classic * ea_ref;
        println!(
            "classical catenary: H = {h_classic:.9} N, sag = {sag_classic:.12} m; \
             predicted EA * d_sag = {predicted:.4e} N"
        );
        for ea in [1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16] {
            let cat = ElasticCatenary::level(SPAN, l0, W, ea).unwrap();
            let sag = -cat.midspan_displacement_m()[2];
            let d_sag = (sag - sag_classic) / sag_classic;
            let d_h = (cat.horizontal_tension_n() - h_classic) / h_classic;
            println!(
                "EA = {ea:.0e} N: sag = {sag:.12} m, rel. diff {d_sag:.3e} (EA * diff = {:.4e}), H rel. diff {d_h:.3e}",
                ea * d_sag
            );
            if ea <= 1e15 {
                // Clean first-order convergence: d_sag ~ C / EA with C as predicted.
                assert!((ea * d_sag / predicted - 1.0).abs() < 0.01, "EA = {ea:e}: {d_sag:e}");
                // The longer cable sags more and pulls less: d_H ~ -d_sag.
                assert!(d_h < 0.0 && (-d_h / d_sag - 1.0).abs() < 0.1, "EA = {ea:e}: {d_h:e}");
            } else {
                // Strain ~2e-13: the difference (3e-12) approaches the round-off
                // of the two solves (~1e-15, amplified ~15x by the sensitivity of
                // the sag to the length on this shallow span); check it is small.
                assert!(d_sag.abs() < 1e-11 && d_h.abs() < 1e-11, "EA = {ea:e}: {d_sag:e} {d_h:e}");
            }
        }
    }

    #[test]
    fn wind_load_displacement_is_parallel_to_resultant() {
        let q = [3.805, 0.0, -W];
        let qn = norm3(q);
        let cat = ElasticCatenary::solve([0.0; 3], [0.0, SPAN, 0.0], SPAN, q, EA).unwrap();
        let d = cat.midspan_displacement_m();
        println!("wind + weight midspan displacement = {d:?} m, x1/x3 = {}", d[0] / d[2]);
        // Parallel to q: the x2 component vanishes by symmetry and x1/x3 = q1/q3.
        assert!(d[1].abs() < 1e-10);
        assert!((d[0] / d[2] - q[0] / q[2]).abs() < 1e-12);
        assert!(dot3(d, q) > 0.0);
        // Magnitude = planar catenary under |q|.
        let planar = ElasticCatenary::level(SPAN, SPAN, qn, EA).unwrap();
        let sag = -planar.midspan_displacement_m()[2];
        assert!((norm3(d) - sag).abs() < 1e-12 * sag, "{} vs {sag}", norm3(d));
        let dh = (cat.horizontal_tension_n() - planar.horizontal_tension_n()).abs();
        assert!(dh < 1e-10 * planar.horizontal_tension_n());
    }

    #[test]
    fn paper_parabolic_formula_numbers() {
        let gamma = paper_parabolic_gamma(SPAN, W, EA).unwrap();
        let eps = paper_parabolic_strain(gamma).unwrap();
        let sag = paper_parabolic_sag_m(SPAN, W, EA).unwrap();
        println!("gamma = {gamma:.6e}, eps = {eps:.8}, parabolic sag = {sag:.6} m = {:.6} l", sag / SPAN);
        // The note quotes 5 significant digits.
        assert!((gamma - 1.6365e-7).abs() < 0.00005e-7);
        assert!((eps - 0.0054798).abs() < 0.00000005);
        assert!((sag / SPAN - 0.04546).abs() < 0.000005);
        // The cubic is eps^3 - gamma eps - gamma = 0 (the printed Cardano form):
        assert!((eps.powi(3) - gamma * eps - gamma).abs() < 1e-15 * gamma);
        // Cardano's form with real arithmetic (discriminant (g/2)^2 - (g/3)^3 > 0
        // for gamma < 27/4), its small cube root rationalised to avoid cancellation.
        let disc = (0.5 * gamma).powi(2) - (gamma / 3.0).powi(3);
        assert!(disc > 0.0);
        let big = 0.5 * gamma + disc.sqrt();
        let small = (gamma / 3.0).powi(3) / big; // = g/2 - sqrt(disc)
        let cardano = big.cbrt() + small.cbrt();
        assert!((cardano - eps).abs() < 1e-14 * eps, "{cardano} vs {eps}");
        // The other candidate, eps^3 = gamma (1 + eps)^2, would give 0.00549 not 0.0054798.
        let f = |e: f64| (e * e * e - gamma * (1.0 + e).powi(2), 3.0 * e * e - 2.0 * gamma * (1.0 + e));
        let other = solve_bracketed(f, 1e-4, 1.0, Options1d::default()).unwrap();
        assert!((other - 0.0054798).abs() > 5e-6);
    }

    #[test]
    fn paper_level_span_exact_sag_is_slightly_below_parabolic() {
        let cat = ElasticCatenary::level(SPAN, SPAN, W, EA).unwrap();
        let sag = -cat.midspan_displacement_m()[2];
        let parabolic = paper_parabolic_sag_m(SPAN, W, EA).unwrap();
        let rel = (parabolic - sag) / parabolic;
        println!(
            "exact elastic catenary: H = {:.4} N, V = {:.4} N, T_max = {:.4} N, midspan sag = {sag:.6} m = {:.6} l; \
             parabolic (4.4) = {parabolic:.6} m; exact is {:.3} % smaller",
            cat.horizontal_tension_n(),
            cat.reaction_a_n(),
            cat.max_tension_n(),
            sag / SPAN,
            100.0 * rel
        );
        // Note: "about 0.14 % less" (two significant digits).
        assert!((0.00135..0.00145).contains(&rel), "{rel}");
        assert!((sag / SPAN - 0.045390).abs() < 0.0000005, "{}", sag / SPAN);
        assert!((sag - 7.2623).abs() < 0.00005, "{sag}");
    }

    #[test]
    fn unequal_heights_h20_on_160m() {
        let cat = ElasticCatenary::solve([0.0; 3], [0.0, SPAN, 20.0], 170.0, [0.0, 0.0, -W], EA).unwrap();
        assert!((cat.height_difference_m() - 20.0).abs() < 1e-14);
        // Higher support B carries more of the weight and the larger tension.
        assert!(cat.reaction_b_n() > cat.reaction_a_n());
        assert_eq!(cat.max_tension_n(), cat.tension_n(170.0));
        // The lowest point is where T_v = 0, s* = V / w, and is a minimum of eta.
        let s_low = cat.reaction_a_n() / W;
        let (_, eta_low) = cat.in_plane_position_m(s_low);
        for k in 0..=400 {
            let (_, eta) = cat.in_plane_position_m(170.0 * k as f64 / 400.0);
            assert!(eta >= eta_low - 1e-12);
        }
        println!(
            "h = 20 m, L0 = 170 m: H = {:.6} N, V_A = {:.6} N, V_B = {:.6} N, lowest point at s = {s_low:.6} m",
            cat.horizontal_tension_n(),
            cat.reaction_a_n(),
            cat.reaction_b_n()
        );
    }

    #[test]
    fn taut_cable_is_stretched_beyond_chord() {
        let l0 = 0.99 * SPAN;
        let cat = ElasticCatenary::level(SPAN, l0, W, EA).unwrap();
        // Stretched length exceeds the chord; the mean strain is at least c/L0 - 1.
        assert!(cat.stretched_length_m() > SPAN);
        let h = cat.horizontal_tension_n();
        assert!(h > EA * (SPAN / l0 - 1.0) * 0.99, "{h}");
        println!("taut: H = {h:.3} N vs EA (c/L0 - 1) = {:.3} N", EA * (SPAN / l0 - 1.0));
    }

    #[test]
    fn robustness_sweep() {
        // 3696 cases: L0/c from 0.3 (stretched 230 %) to 100 (very slack), chords
        // from level to almost parallel to the load (h/l = 1e5), EA from 1 N to
        // 1e16 N, w from 1e-3 to 1e3 N/m (strains from ~1e-20 to ~1e7). Every case
        // must converge; the closure residual, the end position and the exact
        // identity (T_B - T_A) + (T_B^2 - T_A^2)/(2 EA) = w h (normalised by its
        // largest term) must hold to round-off; measured worst: ~7e-16.
        let mut count = 0;
        let mut worst_iterations = 0;
        for ratio in
            [0.3, 0.5, 0.9, 0.99, 0.999999, 1.0, 1.0000000001, 1.000001, 1.001, 1.01, 1.1, 1.5, 2.0, 5.0, 20.0, 100.0]
        {
            for hl in [-20.0, -3.0, -1.0, -0.1, 0.0, 0.1, 1.0, 3.0, 20.0, 1000.0, 1e5] {
                for ea in [1e0, 1e2, 1e4, 1e6, 1e8, 1e12, 1e16] {
                    for w in [1e-3, 1.0, 1e3] {
                        let (l, h) = (100.0, hl * 100.0);
                        let chord = f64::hypot(l, h);
                        let l0 = ratio * chord;
                        let b = [0.0, l, h];
                        let cat = ElasticCatenary::solve([0.0; 3], b, l0, [0.0, 0.0, -w], ea)
                            .unwrap_or_else(|e| panic!("L0/c = {ratio}, h/l = {hl}, EA = {ea:e}, w = {w}: {e}"));
                        let case = format!("L0/c = {ratio}, h/l = {hl}, EA = {ea:e}, w = {w}");
                        worst_iterations = worst_iterations.max(cat.iterations());
                        assert!(cat.closure_residual() <= 1e-14, "{case}: {:e}", cat.closure_residual());
                        let scale = chord.max(cat.stretched_length_m());
                        let end_err = norm3(sub3(cat.position(l0), b)) / scale;
                        assert!(end_err <= 1e-14, "{case}: end {end_err:e}");
                        let (ta, tb) = (cat.tension_n(0.0), cat.tension_n(l0));
                        let tm = cat.max_tension_n();
                        let identity =
                            ((tb - ta) + (tb * tb - ta * ta) / (2.0 * ea) - w * h).abs() / (tm + tm * tm / ea);
                        assert!(identity <= 1e-14, "{case}: identity {identity:e}");
                        count += 1;
                    }
                }
            }
        }
        println!("{count} cases, at most {worst_iterations} Newton iterations");
        assert_eq!(count, 3696);
    }

    #[test]
    fn invalid_inputs_are_errors() {
        let ok = |r: Result<ElasticCatenary, ExactError>| r.is_ok();
        let z = [0.0; 3];
        let b = [0.0, SPAN, 0.0];
        let g = [0.0, 0.0, -W];
        assert!(ok(ElasticCatenary::solve(z, b, SPAN, g, EA)));
        assert!(matches!(
            ElasticCatenary::solve(z, [0.0, 0.0, 10.0], 20.0, g, EA),
            Err(ExactError::InvalidInput { .. })
        ));
        assert!(!ok(ElasticCatenary::solve(z, z, SPAN, g, EA)));
        assert!(!ok(ElasticCatenary::solve(z, b, -1.0, g, EA)));
        assert!(!ok(ElasticCatenary::solve(z, b, SPAN, [0.0; 3], EA)));
        assert!(!ok(ElasticCatenary::solve(z, b, SPAN, g, 0.0)));
        assert!(!ok(ElasticCatenary::solve(z, b, f64::NAN, g, EA)));
        assert!(!ok(ElasticCatenary::solve([f64::INFINITY, 0.0, 0.0], b, SPAN, g, EA)));
        assert!(!ok(ElasticCatenary::level(-3.0, SPAN, W, EA)));
        assert!(paper_parabolic_sag_m(0.0, W, EA).is_err());
    }
}
