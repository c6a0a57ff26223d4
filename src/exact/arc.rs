//! Elastic circular arc: a string under a uniform normal pressure.
//!
//! # Problem
//!
//! A perfectly flexible elastic string (axial stiffness `EA` [N], strain
//! `e = T / EA`) of unstretched length `L0` [m] is pinned at two supports a
//! chord `c` [m] apart. A uniform pressure `p` [N/m] per unit *deformed*
//! length acts normal to the string, in one plane (no gravity) — the
//! paper's steady wind on a weightless wire.
//!
//! # Equations
//!
//! Tangential equilibrium `dT/ds = 0` makes the tension `T` [N] constant;
//! normal equilibrium `T kappa = p` makes the curvature constant, so the string
//! is a circular arc of radius `R = T / p` and half-angle `phi` (the angle
//! between the chord and the tangent at a support; `2 phi` is the central
//! angle). The uniform strain and the geometry give
//!
//! ```text
//! T = p R,    L0 (1 + T / EA) = 2 R phi,    c = 2 R sin(phi),
//! ```
//!
//! hence the single equation for `phi` in `(0, pi)`
//!
//! ```text
//! g(phi) = (phi - sin phi) + (1 - L0/c) sin phi - p L0 / (2 EA) = 0,
//! ```
//!
//! i.e. `c phi - L0 sin phi = p L0 c / (2 EA)`. For `L0 = c` it reduces to
//! `phi - sin phi = p c / (2 EA)`, whose small-angle form
//! `phi^3 / 6 = p c / (2 EA)` is the paper's (4.1), `phi ~ (3 p l / EA)^(1/3)`.
//! Then `R = c / (2 sin phi)`, `T = p R`, and the mid-chord deflection is
//! `f = R (1 - cos phi) = (c / 2) tan(phi / 2)`.
//!
//! `g` is evaluated without cancellation (`phi - sin phi` by its Taylor series
//! for `phi < 1`, `g' = 2 sin^2(phi/2) + (1 - L0/c) cos phi`) and solved by
//! the safeguarded Newton iteration of [`super::roots`] to `1e-15` relative
//! in `phi`. When the root lies in `(pi/2, pi)` the complement
//! `psi = pi - phi` is solved for instead, from
//! `G(psi) = (pi - kappa) - psi - (L0/c) sin psi = 0` with
//! `kappa = p L0 / (2 EA)`, so that `sin phi`, hence `R`, keeps full
//! precision as `phi -> pi`. A root exists in `(0, pi)` iff `kappa < pi`;
//! beyond, the arc inflates without bound (an error). For `L0 > c` the root
//! lies where `g` increases, `phi > acos(c / L0)`; it is unique there.
//!
//! The shape at Lagrangian (unstretched) coordinate `s` from support A: the
//! strain is uniform, so the point lies at the polar angle
//! `alpha = phi (2 s / L0 - 1)` from the arc's axis of symmetry, at
//! `xi = c/2 + R sin(alpha)` along the chord and
//! `zeta = R (cos alpha - cos phi)` off it, positive in the direction the
//! pressure pushes.
//!
//! The module also holds the paper's approximate closed form (4.1),
//! [`paper_arc_deflection_m`].

use super::roots::{Options1d, solve_bracketed};
use super::{ExactError, require_positive};
use std::f64::consts::{FRAC_PI_2, PI};

/// A solved elastic circular arc under uniform normal pressure.
#[derive(Debug, Clone, PartialEq)]
pub struct ElasticArc {
    /// chord between the supports c [m]
    chord_m: f64,
    /// unstretched length L0 [m]
    unstretched_length_m: f64,
    /// normal pressure per unit deformed length p [N/m]
    pressure_n_per_m: f64,
    /// axial stiffness EA [N]
    axial_stiffness_n: f64,
    /// half-angle phi [rad] (0 for a straight string)
    half_angle_rad: f64,
    /// sin(phi) [-], kept to full relative precision also for phi near pi
    sin_half_angle: f64,
    /// tan(phi / 2) [-], kept to full relative precision also for phi near pi
    tan_quarter_angle: f64,
    /// tension T [N] (uniform)
    tension_n: f64,
}

/// `phi - sin(phi)` without cancellation for small `phi` (`phi >= 0`).
pub(crate) fn phi_minus_sin(phi: f64) -> f64 {
    if phi.abs() >= 1.0 {
        return phi - phi.sin();
    }
    // sum_{k>=1} (-1)^(k+1) phi^(2k+1) / (2k+1)!
    let p2 = phi * phi;
    let mut term = phi * p2 / 6.0;
    let mut sum = 0.0_f64;
    let mut k = 1.0_f64;
    while term.abs() > 1e-18 * sum.abs() && k < 40.0 {
        sum += term;
        term *= -p2 / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
        k += 1.0;
    }
    sum
}

/// `(g(phi), g'(phi))` of the module documentation, with `slack = 1 - L0/c`
/// and `kappa = p L0 / (2 EA)`.
fn arc_equation(phi: f64, slack: f64, kappa: f64) -> (f64, f64) {
    let half_sin = (0.5 * phi).sin();
    (phi_minus_sin(phi) + slack * phi.sin() - kappa, 2.0 * half_sin * half_sin + slack * phi.cos())
}

impl ElasticArc {
    /// Solves the arc for a chord `chord_m` c [m], an unstretched length
    /// `unstretched_length_m` L0 [m], a normal pressure per unit deformed
    /// length `pressure_n_per_m` p >= 0 [N/m] and an axial stiffness
    /// `axial_stiffness_n` EA [N].
    ///
    /// `p = 0` gives the straight string (`phi = 0`, `T = EA (c/L0 - 1)`)
    /// when `L0 <= c`, and the limit `p -> 0+` (an inextensible circular arc
    /// of length L0, `T = 0`) when `L0 > c`.
    pub fn solve(
        chord_m: f64,
        unstretched_length_m: f64,
        pressure_n_per_m: f64,
        axial_stiffness_n: f64,
    ) -> Result<Self, ExactError> {
        let c = require_positive(chord_m, "chord must be positive")?;
        let l0 = require_positive(unstretched_length_m, "unstretched length L0 must be positive")?;
        let ea = require_positive(axial_stiffness_n, "axial stiffness EA must be positive")?;
        let p = pressure_n_per_m;
        if !(p.is_finite() && p >= 0.0) {
            return Err(ExactError::InvalidInput { what: "pressure p must be finite and non-negative", value: p });
        }
        let make = |phi: f64, sin_phi: f64, tan_half: f64, tension: f64| Self {
            chord_m: c,
            unstretched_length_m: l0,
            pressure_n_per_m: p,
            axial_stiffness_n: ea,
            half_angle_rad: phi,
            sin_half_angle: sin_phi,
            tan_quarter_angle: tan_half,
            tension_n: tension,
        };
        if p == 0.0 && l0 <= c {
            return Ok(make(0.0, 0.0, 0.0, ea * (c / l0 - 1.0)));
        }
        let kappa = p * l0 / (2.0 * ea);
        if kappa >= PI {
            return Err(ExactError::NoEquilibrium("p L0 / (2 EA) >= pi: the pressure inflates the arc without bound"));
        }
        let slack = 1.0 - l0 / c;
        let opts = Options1d { x_rel_tol: 1e-15, x_abs_tol: 0.0, max_iterations: 400 };
        let (phi, sin_phi, tan_half) = if arc_equation(FRAC_PI_2, slack, kappa).0 >= 0.0 {
            // Root in (0, pi/2]. g decreases on (0, acos(c/L0)) when L0 > c and
            // increases after it.
            let lo = if slack < 0.0 { (c / l0).acos() } else { 0.0 };
            let phi = solve_bracketed(|phi| arc_equation(phi, slack, kappa), lo, FRAC_PI_2, opts)?;
            (phi, phi.sin(), (0.5 * phi).tan())
        } else {
            // Root in (pi/2, pi): solve for the complement psi = pi - phi, so that
            // sin(phi) = sin(psi) keeps its relative precision as phi -> pi:
            // G(psi) = g(pi - psi) = (pi - kappa) - psi - (1 - slack) sin(psi),
            // decreasing in psi, G(0) = pi - kappa > 0 > G(pi/2).
            let big_g = |psi: f64| ((PI - kappa) - psi - (1.0 - slack) * psi.sin(), -1.0 - (1.0 - slack) * psi.cos());
            let psi = solve_bracketed(big_g, 0.0, FRAC_PI_2, opts)?;
            (PI - psi, psi.sin(), 1.0 / (0.5 * psi).tan())
        };
        if !(phi > 0.0 && phi < PI && sin_phi > 0.0) {
            return Err(ExactError::NoEquilibrium("half-angle outside (0, pi)"));
        }
        let radius = c / (2.0 * sin_phi);
        Ok(make(phi, sin_phi, tan_half, p * radius))
    }

    /// chord between the supports c [m]
    pub fn chord_m(&self) -> f64 {
        self.chord_m
    }

    /// unstretched length L0 [m]
    pub fn unstretched_length_m(&self) -> f64 {
        self.unstretched_length_m
    }

    /// normal pressure per unit deformed length p [N/m]
    pub fn pressure_n_per_m(&self) -> f64 {
        self.pressure_n_per_m
    }

    /// axial stiffness EA [N]
    pub fn axial_stiffness_n(&self) -> f64 {
        self.axial_stiffness_n
    }

    /// half-angle phi [rad]: angle between chord and tangent at a support
    pub fn half_angle_rad(&self) -> f64 {
        self.half_angle_rad
    }

    /// radius of curvature R = c / (2 sin phi) [m] (infinite when straight)
    pub fn radius_m(&self) -> f64 {
        if self.half_angle_rad == 0.0 { f64::INFINITY } else { self.chord_m / (2.0 * self.sin_half_angle) }
    }

    /// uniform tension T = p R [N]
    pub fn tension_n(&self) -> f64 {
        self.tension_n
    }

    /// uniform strain e = T / EA [-]
    pub fn strain(&self) -> f64 {
        self.tension_n / self.axial_stiffness_n
    }

    /// stretched length L0 (1 + T/EA) = 2 R phi [m]
    pub fn stretched_length_m(&self) -> f64 {
        self.unstretched_length_m * (1.0 + self.strain())
    }

    /// maximum deflection off the chord f = R (1 - cos phi) = (c/2) tan(phi/2) [m], at mid-chord
    pub fn max_deflection_m(&self) -> f64 {
        0.5 * self.chord_m * self.tan_quarter_angle
    }

    /// Position at Lagrangian (unstretched) coordinate `s_m` [m] (clamped to
    /// `[0, L0]`): (coordinate along the chord from support A xi [m],
    /// deflection off the chord zeta [m], positive along the pressure).
    pub fn position(&self, s_m: f64) -> (f64, f64) {
        let c = self.chord_m;
        let l0 = self.unstretched_length_m;
        let s = s_m.clamp(0.0, l0);
        let phi = self.half_angle_rad;
        if phi == 0.0 {
            return (c * s / l0, 0.0);
        }
        let alpha = phi * (2.0 * s / l0 - 1.0);
        let sin_phi = self.sin_half_angle;
        // xi = c/2 + R sin(alpha), zeta = R (cos alpha - cos phi), R = c / (2 sin phi).
        let xi = 0.5 * c * (1.0 + alpha.sin() / sin_phi);
        let zeta = c * (0.5 * (phi + alpha)).sin() * (0.5 * (phi - alpha)).sin() / sin_phi;
        (xi, zeta)
    }
}

/// The paper's approximate half-angle (4.1) for `L0 = c`:
/// `phi = z^(1/3) [1 + z^(2/3) / 60]` [rad] with `z = 3 p l / EA`, for a chord
/// `chord_m` l [m], a pressure `pressure_n_per_m` p [N/m] and an axial stiffness
/// `ea_n` EA [N]. Its relative error is about `-z^(4/3) / 1400` (next term of
/// the series inversion of `phi - sin phi = p l / (2 EA)`).
pub fn paper_arc_half_angle_rad(chord_m: f64, pressure_n_per_m: f64, ea_n: f64) -> Result<f64, ExactError> {
    let l = require_positive(chord_m, "chord must be positive")?;
    let p = require_positive(pressure_n_per_m, "pressure must be positive")?;
    let ea = require_positive(ea_n, "axial stiffness EA must be positive")?;
    let z = 3.0 * p * l / ea;
    let z13 = z.cbrt();
    Ok(z13 * (1.0 + z13 * z13 / 60.0))
}

/// The paper's approximate arc deflection (4.1) [m] for `L0 = c`: `phi` from
/// [`paper_arc_half_angle_rad`], `r = l / (2 sin phi)`,
/// `x1 = r [1 - sqrt(1 - (l / 2r)^2)]`; chord `chord_m` l [m], pressure
/// `pressure_n_per_m` p [N/m], axial stiffness `ea_n` EA [N].
pub fn paper_arc_deflection_m(chord_m: f64, pressure_n_per_m: f64, ea_n: f64) -> Result<f64, ExactError> {
    let phi = paper_arc_half_angle_rad(chord_m, pressure_n_per_m, ea_n)?;
    let r = chord_m / (2.0 * phi.sin());
    let k = chord_m / (2.0 * r);
    Ok(r * (1.0 - (1.0 - k * k).sqrt()))
}

#[cfg(test)]
mod tests {
    use super::super::roots::{Options2d, System2, newton_2d};
    use super::*;

    const G: f64 = 9.81;
    const EA: f64 = 80734.0 * G;
    const SPAN: f64 = 160.0;
    /// Paper: p = rho v^2 d / 2 with rho = 1.225 kg/m^3, v = 20 m/s, d = 0.01553 m.
    const P: f64 = 1.225 * 20.0 * 20.0 * 0.01553 / 2.0;

    /// (name, chord, L0, p, EA)
    fn cases() -> Vec<(&'static str, f64, f64, f64, f64)> {
        vec![
            ("paper L0 = c", SPAN, SPAN, P, EA),
            ("taut L0 = 0.99 c", SPAN, 0.99 * SPAN, P, EA),
            ("slack L0 = 1.2 c", SPAN, 1.2 * SPAN, P, EA),
            ("tiny pressure", SPAN, SPAN, 1e-9, EA),
            ("soft, past a semicircle", 10.0, 10.0, 2.0, 10.0),
            ("near the inflation limit", 1.0, 1.0, 6.0, 1.0),
        ]
    }

    fn solve_case(c: &(&'static str, f64, f64, f64, f64)) -> ElasticArc {
        ElasticArc::solve(c.1, c.2, c.3, c.4).unwrap_or_else(|e| panic!("{}: {e}", c.0))
    }

    #[test]
    fn phi_minus_sin_series_matches_direct_form() {
        for &x in &[1e-8, 1e-3, 0.1, 0.5, 0.999, 1.0, 2.0] {
            let direct = x - f64::sin(x);
            let series = phi_minus_sin(x);
            // The direct form loses ~ -log10(x^2/6) digits to cancellation.
            let tol = 4.0 * f64::EPSILON * x / series;
            assert!((series - direct).abs() <= tol * series, "{x}: {series} vs {direct}");
        }
        // Deep in the series range the leading term must dominate exactly.
        let x: f64 = 1e-3;
        // Three terms; the fourth, -x^9/9!, is x^6/60480 ~ 2e-23 relative.
        let three_terms = x.powi(3) / 6.0 * (1.0 - x * x / 20.0 + x.powi(4) / 840.0);
        assert!((phi_minus_sin(x) - three_terms).abs() <= 4.0 * f64::EPSILON * three_terms);
    }

    #[test]
    fn geometric_identities_hold() {
        for c in cases() {
            let arc = solve_case(&c);
            let (phi, r, t) = (arc.half_angle_rad(), arc.radius_m(), arc.tension_n());
            println!("{:28} phi = {phi:.15} rad, R = {r:.9} m, T = {t:.9} N, f = {:.9} m", c.0, arc.max_deflection_m());
            // Each identity is one multiplication / sine away from the solve:
            // a few ulps, asserted at 1e-12 as requested.
            assert!((2.0 * r * phi.sin() - c.1).abs() <= 1e-12 * c.1, "{}: chord", c.0);
            assert!((c.2 * (1.0 + t / c.4) - 2.0 * r * phi).abs() <= 1e-12 * c.2, "{}: length", c.0);
            assert!((t - c.3 * r).abs() <= 1e-12 * t, "{}: T = p R", c.0);
            assert!((arc.max_deflection_m() - r * (1.0 - phi.cos())).abs() <= 1e-12 * r.min(1e6 * c.1));
            let (xi_a, z_a) = arc.position(0.0);
            let (xi_b, z_b) = arc.position(c.2);
            let (xi_m, z_m) = arc.position(0.5 * c.2);
            assert!(xi_a.abs() < 1e-14 * c.1 && z_a.abs() < 1e-14 * c.1);
            assert!((xi_b - c.1).abs() < 1e-14 * c.1 && z_b.abs() < 1e-14 * c.1);
            assert!((xi_m - 0.5 * c.1).abs() < 1e-14 * c.1);
            assert!((z_m - arc.max_deflection_m()).abs() < 1e-14 * c.1);
        }
    }

    #[test]
    fn half_angle_is_converged_to_1e_14_relative() {
        // g is evaluated to a few ulps of its largest term, while over a relative
        // change of 1e-14 in phi it moves by g'(phi) phi 1e-14, which for every
        // case exceeds 8 ulps of that term (checked below); so a sign
        // change of g across [phi (1 - 1e-14), phi (1 + 1e-14)] certifies the
        // root to 1e-14 relative.
        for c in cases() {
            let arc = solve_case(&c);
            let phi = arc.half_angle_rad();
            let slack = 1.0 - c.2 / c.1;
            let kappa = c.3 * c.2 / (2.0 * c.4);
            let (g_lo, dg) = arc_equation(phi * (1.0 - 1e-14), slack, kappa);
            let (g_hi, _) = arc_equation(phi * (1.0 + 1e-14), slack, kappa);
            let largest_term = kappa.max(slack.abs() * phi.sin()).max(phi_minus_sin(phi));
            assert!(dg * phi * 1e-14 > 8.0 * f64::EPSILON * largest_term, "{}: test not sharp", c.0);
            assert!(g_lo < 0.0 && g_hi > 0.0, "{}: {g_lo:e} {g_hi:e}", c.0);
        }
    }

    /// RK4 on (xi, zeta, theta) in the unstretched coordinate s0:
    /// d(xi)/ds0 = (1 + e) cos(theta), d(zeta)/ds0 = (1 + e) sin(theta),
    /// d(theta)/ds0 = -p (1 + e) / T, from (0, 0, theta0).
    fn rk4_shape(t: f64, theta0: f64, l0: f64, p: f64, ea: f64, steps: usize) -> [f64; 3] {
        let e = t / ea;
        let rhs = |y: [f64; 3]| [(1.0 + e) * y[2].cos(), (1.0 + e) * y[2].sin(), -p * (1.0 + e) / t];
        let h = l0 / steps as f64;
        let mut y = [0.0, 0.0, theta0];
        let add = |y: [f64; 3], k: f64, d: [f64; 3]| [y[0] + k * d[0], y[1] + k * d[1], y[2] + k * d[2]];
        for _ in 0..steps {
            let k1 = rhs(y);
            let k2 = rhs(add(y, 0.5 * h, k1));
            let k3 = rhs(add(y, 0.5 * h, k2));
            let k4 = rhs(add(y, h, k3));
            y = std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
        }
        y
    }

    #[test]
    fn rk4_shape_from_solved_tension_arrives_at_support_b() {
        // The ODE solution is a circle: the angle is exactly linear (RK4 exact),
        // the coordinates are trigonometric with step h/R <= 2 phi / 4000; RK4's
        // global error ~ L0 (h/R)^4 / 180 is < 1e-13 L0, so 1e-10 is generous.
        for c in cases() {
            let arc = solve_case(&c);
            let y = rk4_shape(arc.tension_n(), arc.half_angle_rad(), c.2, c.3, c.4, 4000);
            let err = (y[0] - c.1).hypot(y[1]) / c.1;
            assert!(err < 1e-10, "{}: {err:e}", c.0);
            assert!((y[2] + arc.half_angle_rad()).abs() < 1e-12, "{}", c.0);
            // Intermediate points agree with the closed-form position.
            for k in [1, 3] {
                let s = c.2 * k as f64 / 4.0;
                let yk = rk4_shape(arc.tension_n(), arc.half_angle_rad(), s, c.3, c.4, 1000);
                let (xi, zeta) = arc.position(s);
                assert!((yk[0] - xi).hypot(yk[1] - zeta) < 1e-10 * c.1, "{}: s = {s}", c.0);
            }
        }
    }

    /// Shooting: unknowns (T, theta0) such that the RK4 shape ends at (c, 0).
    struct Shooting {
        chord: f64,
        l0: f64,
        p: f64,
        ea: f64,
        t_scale: f64,
    }

    impl System2 for Shooting {
        fn residual(&self, x: [f64; 2]) -> [f64; 2] {
            let y = rk4_shape(x[0] * self.t_scale, x[1], self.l0, self.p, self.ea, 2000);
            [(y[0] - self.chord) / self.chord, y[1] / self.chord]
        }
        fn admissible(&self, x: [f64; 2]) -> bool {
            x[0] > 0.0 && x[1].abs() < PI
        }
    }

    #[test]
    fn shooting_on_the_ode_reproduces_the_closed_form() {
        // Fully independent route: Newton (finite-difference Jacobian) on the
        // RK4 shooting map for (T, theta0), started 10 % off. Agreement is
        // limited by the shooting's own closure tolerance 1e-12 amplified by the
        // conditioning (~ 1/phi^2 for T on a shallow arc), hence 1e-8.
        for c in cases().into_iter().filter(|c| c.3 > 1e-6) {
            let arc = solve_case(&c);
            let sys = Shooting { chord: c.1, l0: c.2, p: c.3, ea: c.4, t_scale: arc.tension_n() };
            let sol = newton_2d(&sys, [1.1, 0.9 * arc.half_angle_rad()], Options2d::default())
                .unwrap_or_else(|e| panic!("{}: {e}", c.0));
            let dt = (sol.x[0] - 1.0).abs();
            let dphi = (sol.x[1] - arc.half_angle_rad()).abs() / arc.half_angle_rad();
            println!("{:28} shooting: rel. diff T {dt:.1e}, phi {dphi:.1e}", c.0);
            assert!(dt < 1e-8 && dphi < 1e-8, "{}: {dt:e} {dphi:e}", c.0);
        }
    }

    #[test]
    fn paper_numbers() {
        let arc = ElasticArc::solve(SPAN, SPAN, P, EA).unwrap();
        let z = 3.0 * P * SPAN / EA;
        let phi = arc.half_angle_rad();
        let f = arc.max_deflection_m();
        let phi_paper = paper_arc_half_angle_rad(SPAN, P, EA).unwrap();
        let f_paper = paper_arc_deflection_m(SPAN, P, EA).unwrap();
        println!(
            "p = {P:.6} N/m, 3pl/EA = {z:.6e}, exact phi = {phi:.10} rad, R = {:.6} l, T = {:.4} N, \
             deflection = {f:.6} m = {:.8} l; \
             paper (4.1): phi = {phi_paper:.10}, deflection = {f_paper:.6} m = {:.8} l",
            arc.radius_m() / SPAN,
            arc.tension_n(),
            f / SPAN,
            f_paper / SPAN
        );
        // The note's digits: p ~ 3.805, 3pl/EA = 2.31e-3, phi = 0.1322, r ~ 3.7945 l,
        // deflection ~ 0.033086 l ~ 5.29 m.
        assert!((P - 3.805).abs() < 0.0005);
        assert!((z - 2.31e-3).abs() < 0.005e-3);
        assert!((phi - 0.1322).abs() < 0.00005);
        assert!((arc.radius_m() / SPAN - 3.7945).abs() < 0.00005);
        assert!((f / SPAN - 0.033086).abs() < 0.0000005);
        assert!((f - 5.29).abs() < 0.005);
        assert!((f_paper / SPAN - 0.033086).abs() < 0.0000005);
    }

    #[test]
    fn paper_formula_error_is_the_next_series_term() {
        // Inverting phi^3/6 - phi^5/120 + phi^7/5040 = kappa gives
        // phi = z^(1/3) (1 + z^(2/3)/60 + z^(4/3)/1400 + ...), so (4.1) is low by
        // z^(4/3)/1400 relative; the following term is O(z^2), so for z <= 1e-2
        // the ratio error / (z^(4/3)/1400) lies within 1 +- 5 %.
        for &p in &[0.5, P, 20.0, 50.0] {
            let arc = ElasticArc::solve(SPAN, SPAN, p, EA).unwrap();
            let z = 3.0 * p * SPAN / EA;
            let phi_paper = paper_arc_half_angle_rad(SPAN, p, EA).unwrap();
            let rel = (arc.half_angle_rad() - phi_paper) / arc.half_angle_rad();
            let predicted = z.powf(4.0 / 3.0) / 1400.0;
            println!("p = {p:7.3} N/m: z = {z:.3e}, (4.1) rel. error in phi = {rel:.4e}, predicted {predicted:.4e}");
            assert!((rel / predicted - 1.0).abs() < 0.05, "p = {p}: {rel:e} vs {predicted:e}");
            let f_rel =
                (arc.max_deflection_m() - paper_arc_deflection_m(SPAN, p, EA).unwrap()) / arc.max_deflection_m();
            // f = (c/2) tan(phi/2) ~ c phi / 4: same relative error to first order.
            assert!((f_rel / predicted - 1.0).abs() < 0.1, "p = {p}: {f_rel:e}");
        }
    }

    #[test]
    fn robustness_sweep() {
        // L0/c from 1e-2 to 1e4, p L0 / EA from 1e-12 to just below 2 pi, three
        // stiffnesses: every case must solve, and the length identity
        // L0 (1 + T/EA) = 2 R phi must hold to round-off (1e-13 relative), as
        // must the chord identity where sin(phi) of the rounded phi is still
        // accurate (phi <= 3: relative error of sin ~ 1e-16 / (pi - phi)).
        let mut count = 0;
        for ratio in [0.01, 0.3, 0.9, 0.999999, 1.0, 1.000001, 1.1, 2.0, 10.0, 100.0, 1e4] {
            for load in [1e-12, 1e-6, 1e-3, 1.0, 3.0, 6.0, 0.9995 * std::f64::consts::TAU] {
                for ea in [1.0, 1e3, 1e8] {
                    let c = 2.0;
                    let l0 = ratio * c;
                    let p = load * ea / l0;
                    let arc = ElasticArc::solve(c, l0, p, ea)
                        .unwrap_or_else(|e| panic!("L0/c = {ratio}, pL0/EA = {load}, EA = {ea}: {e}"));
                    let (phi, r, t) = (arc.half_angle_rad(), arc.radius_m(), arc.tension_n());
                    let stretched = l0 * (1.0 + t / ea);
                    assert!((stretched - 2.0 * r * phi).abs() <= 1e-13 * stretched, "{ratio} {load} {ea}");
                    if phi <= 3.0 {
                        assert!((2.0 * r * phi.sin() - c).abs() <= 1e-13 * c, "{ratio} {load} {ea}");
                    }
                    let (xi, zeta) = arc.position(l0);
                    assert!((xi - c).abs() <= 1e-12 * c.max(r) && zeta.abs() <= 1e-12 * c.max(r));
                    assert!(arc.max_deflection_m() > 0.0);
                    count += 1;
                }
            }
        }
        assert_eq!(count, 231);
    }

    #[test]
    fn limits_and_errors() {
        // Straight strings without pressure.
        let taut = ElasticArc::solve(10.0, 9.0, 0.0, 1000.0).unwrap();
        assert_eq!(taut.half_angle_rad(), 0.0);
        assert!((taut.tension_n() - 1000.0 / 9.0).abs() < 1e-12);
        assert_eq!(taut.position(4.5), (5.0, 0.0));
        assert!(taut.radius_m().is_infinite());
        // Slack, p -> 0+: inextensible arc of length L0 (c phi = L0 sin phi).
        let slack = ElasticArc::solve(10.0, 12.0, 0.0, 1000.0).unwrap();
        let phi = slack.half_angle_rad();
        assert!((10.0 * phi - 12.0 * phi.sin()).abs() < 1e-13);
        // Taut with tiny pressure: T -> EA (c/L0 - 1).
        let nearly = ElasticArc::solve(10.0, 9.0, 1e-8, 1000.0).unwrap();
        assert!((nearly.tension_n() / (1000.0 / 9.0) - 1.0).abs() < 1e-9);
        // No equilibrium past p L0 / (2 EA) = pi.
        assert!(matches!(ElasticArc::solve(1.0, 1.0, 7.0, 1.0), Err(ExactError::NoEquilibrium(_))));
        assert!(ElasticArc::solve(-1.0, 1.0, 1.0, 1.0).is_err());
        assert!(ElasticArc::solve(1.0, 1.0, -1.0, 1.0).is_err());
        assert!(ElasticArc::solve(1.0, 1.0, 1.0, f64::NAN).is_err());
        assert!(paper_arc_deflection_m(1.0, 0.0, 1.0).is_err());
    }
}
