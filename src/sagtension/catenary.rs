//! The exact catenary of one span with a nonlinear axial law, by quadrature.
//!
//! A conductor of unstressed length `L0` [m] (its length at the law's reference temperature with no
//! tension: conductor strain `e = 0` of [`TwoMaterial`]) carries a uniform load `w` [N/m] per unit
//! UNSTRESSED length, in a fixed direction (the resultant of weight, ice and wind, plus the NESC constant).
//! In the plane of the load the supports are a distance `l` [m] apart normal to the load ("horizontal")
//! and `h` [m] apart against the load ("vertical", `h > 0`: B above A). With `s` the unstressed arc length
//! from A, `H` [N] the horizontal tension and `V` [N] the reaction of A against the load, equilibrium
//! gives (Irvine, "Cable Structures", 1981, section 2.3: the same equations as
//! [`crate::exact::catenary`], with the strain from the law instead of `T / EA`)
//!
//! ```text
//! u(s) = w s - V,      T(s) = sqrt(H^2 + u^2),      e(s) = e(T(s); theta, history)   (T(e) inverted)
//! dx/ds   = (1 + e) H / T,        deta/ds = (1 + e) u / T
//! closure:  x(L0) = l,  eta(L0) = h
//! ```
//!
//! `e(T)` inverts the law's `T(e, theta)` ([`TwoMaterial::tension`], nondecreasing in `e`) by Newton with
//! a bisection safeguard. The integrals are composite Gauss-Legendre: `[0, L0]` is split at every `s`
//! where the law has a kink (a component's largest strain, its permanent set, its curve's zero or fitted
//! limit: there `T` is a known tension `T_k`, reached at `u = +-sqrt(T_k^2 - H^2)`), and each piece into
//! `panels` equal panels of `GAUSS_POINTS` points. Between kinks the integrand is analytic, so the rule
//! converges exponentially (tests: 1e-14 relative between 4 and 32 panels). `(H, V)` solve the closure by
//! Newton with the Jacobian integrated by the same rule (`de/dT = 1 / k`, `k` the law's tangent stiffness),
//! started from Irvine's closed form for the law linearised at an estimated tension.

use super::error::SagTensionError;
use crate::conductor::{History, TwoMaterial};
use crate::exact::catenary::ElasticCatenary;
use crate::exact::roots::{Options2d, System2, newton_2d};
use std::sync::OnceLock;

/// Gauss-Legendre points per panel.
pub const GAUSS_POINTS: usize = 12;

/// Default number of panels between kinks (tests: the integrals agree with 32 panels to 1e-14).
pub const DEFAULT_PANELS: usize = 4;

/// The closure tolerance, relative to `max(chord, L0)` (as [`crate::exact::catenary::CLOSURE_TOLERANCE`]).
pub const CLOSURE_TOLERANCE: f64 = 1e-12;

/// Nodes and weights of the `GAUSS_POINTS`-point Gauss-Legendre rule on `[-1, 1]` (Newton on the
/// Legendre polynomial from Tricomi's estimate; Golub-Welsch would give the same to round-off).
fn gauss() -> &'static ([f64; GAUSS_POINTS], [f64; GAUSS_POINTS]) {
    static RULE: OnceLock<([f64; GAUSS_POINTS], [f64; GAUSS_POINTS])> = OnceLock::new();
    RULE.get_or_init(|| {
        let n = GAUSS_POINTS;
        let mut x = [0.0; GAUSS_POINTS];
        let mut w = [0.0; GAUSS_POINTS];
        for i in 0..n {
            let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, z);
                for k in 2..=n {
                    let p2 = ((2 * k - 1) as f64 * z * p1 - (k - 1) as f64 * p0) / k as f64;
                    p0 = p1;
                    p1 = p2;
                }
                dp = n as f64 * (z * p1 - p0) / (z * z - 1.0);
                let dz = p1 / dp;
                z -= dz;
                if dz.abs() < 1e-16 {
                    break;
                }
            }
            x[i] = z;
            w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
        }
        (x, w)
    })
}

/// One span's data for the quadrature: the law, its history and temperature, the load, the geometry.
#[derive(Clone, Copy, Debug)]
pub struct SpanLaw<'a> {
    /// the axial law
    pub law: &'a TwoMaterial,
    /// the components' history (curve and largest strains)
    pub history: History,
    /// conductor temperature `theta` [K]
    pub temperature_k: f64,
    /// load per unit unstressed length `w` [N/m]
    pub load_n_per_m: f64,
    /// in-plane span `l` [m] (normal to the load)
    pub span_m: f64,
    /// in-plane height of B over A against the load `h` [m]
    pub rise_m: f64,
    /// unstressed length `L0` [m] (at the reference temperature)
    pub unstressed_length_m: f64,
    /// panels per piece between kinks (module doc; [`DEFAULT_PANELS`])
    pub panels: usize,
}

/// A point of the span: `s`, `u = w s - V`, `T`, `e`, the tangent stiffness `k`.
#[derive(Clone, Copy, Debug)]
struct Point {
    u: f64,
    t: f64,
    e: f64,
    k: f64,
}

impl SpanLaw<'_> {
    /// The conductor strain [-] at the tension `t` [N] `> 0` (Newton on the law, bisection safeguard).
    pub fn strain(&self, t: f64) -> Result<f64, SagTensionError> {
        strain_of(self.law, t, self.temperature_k, &self.history)
    }

    /// The tensions [N] at which the law has a kink at this temperature and history.
    fn kink_tensions(&self) -> Vec<f64> {
        let d = self.temperature_k - self.law.reference_temperature_k;
        let h = &self.history;
        let mut out = Vec::with_capacity(8);
        let mut add = |c: &crate::conductor::Component, m: f64| {
            let curve = c.curve(h.curve);
            let mut strains = vec![m.max(curve.zero_strain()), c.permanent_set(h.curve, m), curve.zero_strain()];
            if curve.limit_strain.is_finite() {
                strains.push(curve.limit_strain);
            }
            for em in strains {
                let t = self.law.tension(em + c.expansion_per_k * d, self.temperature_k, h);
                if t.is_finite() && t > 0.0 {
                    out.push(t);
                }
            }
        };
        add(&self.law.outer, h.max_strain[0]);
        if let Some(c) = &self.law.core {
            add(c, h.max_strain[1]);
        }
        out
    }

    /// The quadrature pieces' ends in `[a, b]` for `(H, V)`: `a`, the kinks inside, `b`.
    fn pieces(&self, a: f64, b: f64, hv: [f64; 2]) -> Vec<f64> {
        let (hh, v, w) = (hv[0], hv[1], self.load_n_per_m);
        let mut cuts = vec![a, b];
        for tk in self.kink_tensions() {
            if tk > hh {
                let r = (tk * tk - hh * hh).sqrt();
                for s in [(v - r) / w, (v + r) / w] {
                    if s > a && s < b {
                        cuts.push(s);
                    }
                }
            }
        }
        cuts.sort_by(f64::total_cmp);
        cuts.dedup();
        cuts
    }

    fn point(&self, s: f64, hv: [f64; 2]) -> Result<Point, SagTensionError> {
        let u = self.load_n_per_m * s - hv[1];
        let t = hv[0].hypot(u);
        let e = self.strain(t)?;
        let k = self.law.stiffness(e, self.temperature_k, &self.history);
        Ok(Point { u, t, e, k })
    }

    /// `int_a^b f(point) ds` by the composite rule (module doc).
    fn integrate<const N: usize>(
        &self,
        a: f64,
        b: f64,
        hv: [f64; 2],
        f: impl Fn(&Point) -> [f64; N],
    ) -> Result<[f64; N], SagTensionError> {
        let (x, wq) = gauss();
        let mut sum = [0.0; N];
        let cuts = self.pieces(a, b, hv);
        let panels = self.panels.max(1);
        for pair in cuts.windows(2) {
            let step = (pair[1] - pair[0]) / panels as f64;
            for p in 0..panels {
                let lo = pair[0] + step * p as f64;
                let half = 0.5 * step;
                let mid = lo + half;
                for q in 0..GAUSS_POINTS {
                    let pt = self.point(mid + half * x[q], hv)?;
                    let v = f(&pt);
                    for i in 0..N {
                        sum[i] += half * wq[q] * v[i];
                    }
                }
            }
        }
        Ok(sum)
    }

    /// `(x(s), eta(s))` [m] of the point at unstressed arc length `s` [m] for `(H, V)`.
    pub fn position(&self, s: f64, hv: [f64; 2]) -> Result<[f64; 2], SagTensionError> {
        let hh = hv[0];
        self.integrate(0.0, s, hv, |p| [(1.0 + p.e) * hh / p.t, (1.0 + p.e) * p.u / p.t])
    }

    /// The closure integrals `[x(L0), eta(L0)]` and their Jacobian `d/d(H, V)` (module doc).
    fn closure(&self, hv: [f64; 2]) -> Result<[f64; 6], SagTensionError> {
        let hh = hv[0];
        self.integrate(0.0, self.unstressed_length_m, hv, |p| {
            let (u, t, g) = (p.u, p.t, 1.0 + p.e);
            let de = 1.0 / p.k;
            let (t2, t3) = (t * t, t * t * t);
            [
                g * hh / t,
                g * u / t,
                de * hh * hh / t2 + g * u * u / t3,
                -de * hh * u / t2 + g * hh * u / t3,
                de * hh * u / t2 - g * u * hh / t3,
                -de * u * u / t2 - g * hh * hh / t3,
            ]
        })
    }

    /// An estimate of `(H, V)`: Irvine's closed form for the law linearised at an estimated tension,
    /// three times (module doc).
    fn estimate(&self) -> [f64; 2] {
        let w = self.load_n_per_m;
        let l0 = self.unstressed_length_m;
        let mut t_est = w * l0;
        let mut hv = [0.5 * w * l0, 0.5 * w * l0];
        for _ in 0..4 {
            let Ok(e) = self.strain(t_est) else { break };
            let k = self.law.stiffness(e, self.temperature_k, &self.history);
            let c = e - t_est / k;
            if !(k > 0.0 && c > -0.5) {
                break;
            }
            let Ok(cat) = ElasticCatenary::solve(
                [0.0, 0.0, 0.0],
                [0.0, self.span_m, self.rise_m],
                l0 * (1.0 + c),
                [0.0, 0.0, -w / (1.0 + c)],
                k * (1.0 + c),
            ) else {
                break;
            };
            hv = [cat.horizontal_tension_n(), cat.reaction_a_n()];
            t_est = 0.5 * (cat.horizontal_tension_n() + cat.max_tension_n());
        }
        hv
    }

    /// Solves the closure for `(H, V)` (module doc).
    pub fn solve(&self) -> Result<SpanSolution, SagTensionError> {
        for (what, v) in [
            ("load per length w [N/m]", self.load_n_per_m),
            ("span l [m]", self.span_m),
            ("unstressed length L0 [m]", self.unstressed_length_m),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(SagTensionError::Invalid { what, value: v, allowed: "finite and > 0" });
            }
        }
        if !self.rise_m.is_finite() {
            return Err(SagTensionError::Invalid { what: "rise h [m]", value: self.rise_m, allowed: "finite" });
        }
        let system = Closure { span: self, scale: self.span_m.hypot(self.rise_m).max(self.unstressed_length_m) };
        let x0 = self.estimate();
        // a law that cannot carry the estimate's tensions: its own error, not a NaN residual
        self.closure(x0)?;
        let opts = Options2d { residual_tol: CLOSURE_TOLERANCE, max_iterations: 100, ..Options2d::default() };
        let sol = newton_2d(&system, x0, opts)
            .map_err(|e| SagTensionError::NoSolution { what: "span closure (H, V)", detail: e.to_string() })?;
        let hv = sol.x;
        Ok(SpanSolution { horizontal_tension_n: hv[0], reaction_a_n: hv[1], residual: sol.residual })
    }

    /// Tension [N] at `s` [m] for `(H, V)`.
    pub fn tension_at(&self, s: f64, hv: [f64; 2]) -> f64 {
        hv[0].hypot(self.load_n_per_m * s - hv[1])
    }

    /// The length-weighted means over the unstressed length of `[T, F_o, F_c, e]` [N, N, N, -] and the
    /// stretched length [m].
    pub fn means(&self, hv: [f64; 2]) -> Result<([f64; 4], f64), SagTensionError> {
        let l0 = self.unstressed_length_m;
        let r = self.integrate(0.0, l0, hv, |p| {
            let f = self.law.forces(p.e, self.temperature_k, &self.history);
            [p.t, f[0], f[1], p.e]
        })?;
        Ok(([r[0] / l0, r[1] / l0, r[2] / l0, r[3] / l0], l0 + r[3]))
    }

    /// The sag [m] below the chord, measured against the load, at the point whose `x` is `x_target`
    /// [m]: `h x / l - eta(x)` (`s` from `x(s) = x_target` by Newton, `dx/ds = (1 + e) H / T`).
    pub fn sag_at_x(&self, x_target: f64, hv: [f64; 2]) -> Result<f64, SagTensionError> {
        let l0 = self.unstressed_length_m;
        let mut s = l0 * x_target / self.span_m;
        let mut pos = self.position(s, hv)?;
        for _ in 0..50 {
            let p = self.point(s, hv)?;
            let ds = (x_target - pos[0]) / ((1.0 + p.e) * hv[0] / p.t);
            s = (s + ds).clamp(0.0, l0);
            pos = self.position(s, hv)?;
            if ds.abs() <= 1e-14 * l0 {
                break;
            }
        }
        Ok(self.rise_m * pos[0] / self.span_m - pos[1])
    }

    /// The largest sag [m] below the chord (against the load): at `s* = (V + H h / l) / w`, where the
    /// conductor is parallel to the chord (`deta/dx = u / H = h / l`), clamped to the span.
    pub fn max_sag(&self, hv: [f64; 2]) -> Result<f64, SagTensionError> {
        let s = ((hv[1] + hv[0] * self.rise_m / self.span_m) / self.load_n_per_m).clamp(0.0, self.unstressed_length_m);
        let pos = self.position(s, hv)?;
        Ok(self.rise_m * pos[0] / self.span_m - pos[1])
    }
}

/// A solved span: `H` and `V` (see [`SpanLaw`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpanSolution {
    /// horizontal tension `H` [N]
    pub horizontal_tension_n: f64,
    /// reaction of A against the load `V` [N]
    pub reaction_a_n: f64,
    /// the closure residual reached, relative to `max(chord, L0)` [-]
    pub residual: f64,
}

impl SpanSolution {
    /// `[H, V]` [N].
    pub fn hv(&self) -> [f64; 2] {
        [self.horizontal_tension_n, self.reaction_a_n]
    }
}

struct Closure<'a, 'b> {
    span: &'a SpanLaw<'b>,
    scale: f64,
}

impl System2 for Closure<'_, '_> {
    fn residual(&self, x: [f64; 2]) -> [f64; 2] {
        match self.span.closure(x) {
            Ok(c) => [(c[0] - self.span.span_m) / self.scale, (c[1] - self.span.rise_m) / self.scale],
            Err(_) => [f64::NAN, f64::NAN],
        }
    }

    fn jacobian(&self, x: [f64; 2]) -> Option<[[f64; 2]; 2]> {
        let c = self.span.closure(x).ok()?;
        let s = self.scale;
        Some([[c[2] / s, c[3] / s], [c[4] / s, c[5] / s]])
    }

    fn admissible(&self, x: [f64; 2]) -> bool {
        x[0] > 0.0 && x[0].is_finite() && x[1].is_finite()
    }

    fn typical_x(&self) -> [f64; 2] {
        let w = self.span.load_n_per_m * self.span.unstressed_length_m;
        [w, w]
    }
}

/// The conductor strain [-] at the tension `t` [N] `> 0` at `theta` [K] with the history `h`: Newton on
/// the nondecreasing `T(e)` inside a bracket, bisecting when a step leaves it. An error when no strain up
/// to 100 % carries `t` (a conductor that cannot carry the load).
pub fn strain_of(law: &TwoMaterial, t: f64, temperature_k: f64, h: &History) -> Result<f64, SagTensionError> {
    if !(t.is_finite() && t > 0.0) {
        return Err(SagTensionError::Invalid { what: "tension [N]", value: t, allowed: "finite and > 0" });
    }
    let f = |e: f64| law.tension(e, temperature_k, h) - t;
    let (mut lo, mut hi) = (-0.01, 0.01);
    while f(hi) < 0.0 {
        hi *= 2.0;
        if hi > 1.0 {
            return Err(SagTensionError::NoSolution {
                what: "conductor strain at a tension",
                detail: format!("no strain up to 100 % carries {t} N at {temperature_k} K"),
            });
        }
    }
    while f(lo) >= 0.0 {
        lo *= 2.0;
        if lo < -1.0 {
            return Err(SagTensionError::NoSolution {
                what: "conductor strain at a tension",
                detail: format!("the law carries {t} N at every strain above -100 % at {temperature_k} K"),
            });
        }
    }
    let mut e = 0.5 * (lo + hi);
    for _ in 0..200 {
        let r = f(e);
        if r == 0.0 {
            return Ok(e);
        }
        if r < 0.0 {
            lo = e
        } else {
            hi = e
        }
        let k = law.stiffness(e, temperature_k, h);
        let mut next = e - r / k;
        if !(k > 0.0 && next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        if (next - e).abs() <= 4.0 * f64::EPSILON * e.abs().max(1e-3) || hi - lo <= 4.0 * f64::EPSILON * hi.abs() {
            return Ok(next);
        }
        e = next;
    }
    Ok(e)
}
