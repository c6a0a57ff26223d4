//! Small safeguarded root finders for the exact reference solutions.
//!
//! * [`solve_bracketed`]: a scalar equation `f(x) = 0` on an interval
//!   `[lo, hi]` with `f(lo) f(hi) <= 0`. Newton steps `x <- x - f(x)/f'(x)` are
//!   taken while they stay strictly inside the current bracket and shrink it
//!   fast enough; otherwise the iteration falls back to bisection, so it
//!   always converges (at worst linearly, like bisection) and converges
//!   quadratically near a simple root. The bracket is updated from the sign of
//!   `f` at every iterate.
//! * [`expand_upper`]: grows the upper end of an interval geometrically until
//!   the function changes sign, to build a bracket for [`solve_bracketed`].
//! * [`newton_2d`]: a system `F(x) = 0`, `x, F` in R^2, by Newton's method
//!   `J(x) dx = -F(x)` with the Jacobian `J` supplied analytically by the
//!   [`System2`] or else by central finite differences, globalised by a
//!   backtracking (Armijo) line search on the merit function `|F|^2 / 2`
//!   that also keeps the iterate inside the system's admissible set (e.g. a
//!   tension that must stay positive).
//!
//! * [`illinois`]: a bracketed root without derivatives by the Illinois variant of regula falsi
//!   (Dowell and Jarratt, BIT 11, 1971): the secant point of the bracket (the midpoint where it falls
//!   outside), the retained end's value halved when the same end is kept twice in a row; robust like
//!   bisection, superlinear near a simple root. The thermal ratings' steady state and the sag-tension
//!   searches both use it.
//!
//! These are textbook methods (e.g. Press et al., "Numerical Recipes",
//! 3rd ed., sections 9.4 and 9.7; Dennis & Schnabel, "Numerical Methods for
//! Unconstrained Optimization and Nonlinear Equations", 1983, chapter 6).

use super::ExactError;

/// Where an [`illinois`] iteration stopped: the last bracket `[lo, hi]` (either order) with the values
/// there (the retained ends' values as the method halved them), the evaluations spent, and how it ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IllinoisEnd {
    /// one end of the last bracket
    pub lo: f64,
    /// the other end
    pub hi: f64,
    /// the (possibly halved) value at `lo`
    pub f_lo: f64,
    /// the (possibly halved) value at `hi`
    pub f_hi: f64,
    /// evaluations of `f` spent
    pub evaluations: usize,
    /// an iterate at which `f` vanished exactly
    pub zero: Option<f64>,
    /// whether the bracket became narrower than the tolerance (or `f` vanished)
    pub converged: bool,
}

/// A root of `f` in the bracket `[lo, hi]` with values `f_lo`, `f_hi` of opposite signs (module doc):
/// iterates until the bracket is narrower than `tol`, `f` vanishes, or `max_evaluations` are spent, and
/// returns where it stopped; the caller picks the root from the last bracket (its midpoint, or the end of
/// smaller value). An error of `f` ends the iteration with that error.
pub fn illinois<E, F>(
    mut f: F,
    mut lo: f64,
    mut hi: f64,
    mut f_lo: f64,
    mut f_hi: f64,
    tol: f64,
    max_evaluations: usize,
) -> Result<IllinoisEnd, E>
where
    F: FnMut(f64) -> Result<f64, E>,
{
    let mut evaluations = 0;
    let mut side = 0i8;
    let mut converged = (hi - lo).abs() <= tol;
    while !converged && evaluations < max_evaluations {
        let mut x = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        if !x.is_finite() || x <= lo.min(hi) || x >= lo.max(hi) {
            x = 0.5 * (lo + hi);
        }
        let fx = f(x)?;
        evaluations += 1;
        if fx == 0.0 {
            return Ok(IllinoisEnd { lo, hi, f_lo, f_hi, evaluations, zero: Some(x), converged: true });
        }
        if (fx > 0.0) == (f_lo > 0.0) {
            lo = x;
            f_lo = fx;
            if side == -1 {
                f_hi *= 0.5;
            }
            side = -1;
        } else {
            hi = x;
            f_hi = fx;
            if side == 1 {
                f_lo *= 0.5;
            }
            side = 1;
        }
        converged = (hi - lo).abs() <= tol;
    }
    Ok(IllinoisEnd { lo, hi, f_lo, f_hi, evaluations, zero: None, converged })
}

/// Options of the 1D safeguarded Newton iteration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options1d {
    /// Stop when a step (or the bracket width) is at most
    /// `x_rel_tol * |x| + x_abs_tol`.
    pub x_rel_tol: f64,
    /// Absolute part of the step tolerance, in the units of `x`.
    pub x_abs_tol: f64,
    /// Iteration cap; exceeding it is an [`ExactError::NoConvergence`].
    pub max_iterations: usize,
}

impl Default for Options1d {
    fn default() -> Self {
        Self { x_rel_tol: 1e-15, x_abs_tol: 0.0, max_iterations: 300 }
    }
}

/// Root of `f` in `[lo, hi]` by safeguarded Newton / bisection.
///
/// `f` returns the value and the derivative `(f(x), f'(x))`. The end values
/// must differ in sign (or one must vanish). A non-finite or zero derivative
/// only forces a bisection step; a non-finite function value inside the
/// interval is an [`ExactError::NoConvergence`]. Returns the root estimate;
/// near a simple root the last step is at most `x_rel_tol * |x| + x_abs_tol`.
/// Panics (internal misuse) unless `lo < hi`, both finite.
pub fn solve_bracketed<F>(mut f: F, lo: f64, hi: f64, opts: Options1d) -> Result<f64, ExactError>
where
    F: FnMut(f64) -> (f64, f64),
{
    assert!(lo.is_finite() && hi.is_finite() && lo < hi, "solve_bracketed: bad interval [{lo}, {hi}]");
    let (f_lo, _) = f(lo);
    let (f_hi, _) = f(hi);
    if f_lo == 0.0 {
        return Ok(lo);
    }
    if f_hi == 0.0 {
        return Ok(hi);
    }
    if !(f_lo.is_finite() && f_hi.is_finite()) || f_lo.signum() == f_hi.signum() {
        return Err(ExactError::NotBracketed { lo, hi, f_lo, f_hi });
    }
    // Orient the bracket so that f(neg) < 0 < f(pos).
    let (mut neg, mut pos) = if f_lo < 0.0 { (lo, hi) } else { (hi, lo) };
    let tol = |x: f64| opts.x_rel_tol * x.abs() + opts.x_abs_tol;

    let mut x = 0.5 * (lo + hi);
    // Step before last: a Newton step is accepted only while it lands inside
    // the bracket and is at most half of it (rtsafe criterion, Numerical
    // Recipes 9.4), which guarantees at least bisection-like progress.
    let mut step_before_last = (hi - lo).abs();
    let mut last_step = step_before_last;
    for _ in 0..opts.max_iterations {
        let (fx, dfx) = f(x);
        if fx == 0.0 {
            return Ok(x);
        }
        if !fx.is_finite() {
            return Err(ExactError::NoConvergence {
                method: "safeguarded 1D Newton (non-finite function value)",
                iterations: 0,
                residual: fx,
            });
        }
        if fx < 0.0 {
            neg = x;
        } else {
            pos = x;
        }
        let (a, b) = if neg < pos { (neg, pos) } else { (pos, neg) };
        if b - a <= tol(x) {
            return Ok(x);
        }
        let newton = (dfx.is_finite() && dfx != 0.0).then(|| x - fx / dfx);
        let next = match newton {
            Some(xn) if xn > a && xn < b && (xn - x).abs() <= 0.5 * step_before_last => xn,
            _ => 0.5 * (a + b),
        };
        step_before_last = last_step;
        last_step = (next - x).abs();
        x = next;
        if last_step <= tol(x) {
            return Ok(x);
        }
    }
    let (fx, _) = f(x);
    Err(ExactError::NoConvergence {
        method: "safeguarded 1D Newton",
        iterations: opts.max_iterations,
        residual: fx.abs(),
    })
}

/// Grows `hi` geometrically (`hi <- lo + 2 (hi - lo)`) until `f(hi)` has the
/// sign opposite to `f(lo)`, at most `max_doublings` times. Returns the new
/// `hi`. `f` returns `(value, derivative)` like in [`solve_bracketed`]; only
/// the value is used.
pub fn expand_upper<F>(mut f: F, lo: f64, mut hi: f64, max_doublings: usize) -> Result<f64, ExactError>
where
    F: FnMut(f64) -> (f64, f64),
{
    assert!(lo < hi, "expand_upper: need lo < hi");
    let f_lo = f(lo).0;
    let mut f_hi = f(hi).0;
    for _ in 0..max_doublings {
        if f_hi.is_finite() && (f_hi == 0.0 || f_hi.signum() != f_lo.signum()) {
            return Ok(hi);
        }
        hi = lo + 2.0 * (hi - lo);
        f_hi = f(hi).0;
    }
    if f_hi.is_finite() && (f_hi == 0.0 || f_hi.signum() != f_lo.signum()) {
        return Ok(hi);
    }
    Err(ExactError::NotBracketed { lo, hi, f_lo, f_hi })
}

/// A square 2x2 nonlinear system `F(x) = 0` for [`newton_2d`].
pub trait System2 {
    /// The residual `F(x)`, already scaled so that its components are
    /// comparable (the convergence test is on `max |F_i|`).
    fn residual(&self, x: [f64; 2]) -> [f64; 2];

    /// The Jacobian `J[i][j] = dF_i / dx_j`, or `None` to have it computed
    /// by central finite differences.
    fn jacobian(&self, _x: [f64; 2]) -> Option<[[f64; 2]; 2]> {
        None
    }

    /// Whether `x` lies in the domain where `F` is defined; the line search
    /// shortens steps that leave it.
    fn admissible(&self, _x: [f64; 2]) -> bool {
        true
    }

    /// A typical magnitude of each unknown, used for the finite-difference
    /// step when `x_j` itself is near zero.
    fn typical_x(&self) -> [f64; 2] {
        [1.0, 1.0]
    }
}

/// Options of [`newton_2d`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options2d {
    /// Converged when `max |F_i(x)| <= residual_tol`.
    pub residual_tol: f64,
    /// Newton iteration cap (the final polishing step included).
    pub max_iterations: usize,
    /// Maximum number of step halvings in one line search.
    pub max_halvings: usize,
    /// Relative step of the central-difference Jacobian.
    pub fd_relative_step: f64,
}

impl Default for Options2d {
    fn default() -> Self {
        Self { residual_tol: 1e-12, max_iterations: 200, max_halvings: 60, fd_relative_step: 1e-6 }
    }
}

/// Outcome of a converged [`newton_2d`] run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Solution2d {
    /// The root.
    pub x: [f64; 2],
    /// `max |F_i(x)|` at the root.
    pub residual: f64,
    /// Newton iterations used.
    pub iterations: usize,
}

fn max_abs(f: [f64; 2]) -> f64 {
    f[0].abs().max(f[1].abs())
}

fn finite2(f: [f64; 2]) -> bool {
    f[0].is_finite() && f[1].is_finite()
}

/// Central-difference Jacobian of `system` at `x`.
pub fn fd_jacobian<S: System2 + ?Sized>(system: &S, x: [f64; 2], relative_step: f64) -> [[f64; 2]; 2] {
    let typical = system.typical_x();
    let mut jac = [[0.0; 2]; 2];
    for j in 0..2 {
        let h = relative_step * x[j].abs().max(typical[j].abs());
        let mut xp = x;
        let mut xm = x;
        xp[j] += h;
        xm[j] -= h;
        // One-sided difference if the backward point is not admissible.
        let (fp, fm, den) = if system.admissible(xm) {
            (system.residual(xp), system.residual(xm), xp[j] - xm[j])
        } else {
            (system.residual(xp), system.residual(x), xp[j] - x[j])
        };
        for i in 0..2 {
            jac[i][j] = (fp[i] - fm[i]) / den;
        }
    }
    jac
}

/// The Newton direction `dx = -J(x)^{-1} F(x)`, `None` if `J` is singular.
fn newton_direction<S: System2 + ?Sized>(system: &S, x: [f64; 2], f: [f64; 2], opts: &Options2d) -> Option<[f64; 2]> {
    let j = system.jacobian(x).unwrap_or_else(|| fd_jacobian(system, x, opts.fd_relative_step));
    let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
    if !(det.is_finite() && det != 0.0) {
        return None;
    }
    // Cramer's rule for J dx = -F.
    let dx = [(-f[0] * j[1][1] + f[1] * j[0][1]) / det, (-f[1] * j[0][0] + f[0] * j[1][0]) / det];
    finite2(dx).then_some(dx)
}

/// Solves `F(x) = 0` by damped Newton from `x0` (which must be admissible).
///
/// Once `max |F_i| <= residual_tol`, one more full Newton step is tried
/// ("polish") and kept if it does not increase the residual, so that a
/// starting guess that already meets the tolerance is still refined to the
/// round-off level.
pub fn newton_2d<S: System2 + ?Sized>(system: &S, x0: [f64; 2], opts: Options2d) -> Result<Solution2d, ExactError> {
    assert!(system.admissible(x0), "newton_2d: initial guess {x0:?} is not admissible");
    let mut x = x0;
    let mut f = system.residual(x);
    if !finite2(f) {
        return Err(ExactError::NoConvergence {
            method: "2D Newton (non-finite residual at the initial guess)",
            iterations: 0,
            residual: f64::NAN,
        });
    }
    let mut r = max_abs(f);
    for it in 0..opts.max_iterations {
        let direction = newton_direction(system, x, f, &opts);
        if r <= opts.residual_tol {
            if let Some(dx) = direction {
                let xp = [x[0] + dx[0], x[1] + dx[1]];
                if system.admissible(xp) {
                    let fp = system.residual(xp);
                    if finite2(fp) && max_abs(fp) <= r {
                        x = xp;
                        r = max_abs(fp);
                    }
                }
            }
            return Ok(Solution2d { x, residual: r, iterations: it + 1 });
        }
        let Some(dx) = direction else {
            return Err(ExactError::NoConvergence {
                method: "2D Newton (singular Jacobian)",
                iterations: it,
                residual: r,
            });
        };
        // Backtracking on m(x) = |F|^2 / 2; along the Newton direction
        // m'(0) = -|F|^2, so Armijo reads m(t) <= (1 - 2 c t) m(0).
        let m0 = 0.5 * (f[0] * f[0] + f[1] * f[1]);
        let mut t = 1.0;
        let mut accepted = None;
        for _ in 0..=opts.max_halvings {
            let xt = [x[0] + t * dx[0], x[1] + t * dx[1]];
            if system.admissible(xt) {
                let ft = system.residual(xt);
                if finite2(ft) && xt != x {
                    let mt = 0.5 * (ft[0] * ft[0] + ft[1] * ft[1]);
                    if mt < (1.0 - 2.0e-4 * t) * m0 {
                        accepted = Some((xt, ft));
                        break;
                    }
                }
            }
            t *= 0.5;
        }
        let Some((xt, ft)) = accepted else {
            return Err(ExactError::NoConvergence {
                method: "2D Newton (line search failed)",
                iterations: it,
                residual: r,
            });
        };
        x = xt;
        f = ft;
        r = max_abs(f);
    }
    if r <= opts.residual_tol {
        Ok(Solution2d { x, residual: r, iterations: opts.max_iterations })
    } else {
        Err(ExactError::NoConvergence { method: "2D Newton", iterations: opts.max_iterations, residual: r })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bracketed_newton_finds_cube_root_of_two() {
        // x^3 - 2 on [0, 2]: simple root 2^(1/3); Newton converges quadratically,
        // so the result is within a couple of ulps.
        let x = solve_bracketed(|x| (x * x * x - 2.0, 3.0 * x * x), 0.0, 2.0, Options1d::default()).unwrap();
        assert!((x - 2f64.cbrt()).abs() <= 4.0 * f64::EPSILON * x, "{x}");
    }

    #[test]
    fn bracketed_newton_survives_a_flat_start() {
        // f'(x) = 0 at the midpoint of [-1, 3] and Newton from x = 1 would leave
        // the bracket: bisection must take over. Root of x^3 - 3x^2 + 3x - 1 - 1e-3.
        let g = |x: f64| ((x - 1.0).powi(3) - 1e-3, 3.0 * (x - 1.0).powi(2));
        let x = solve_bracketed(g, -1.0, 3.0, Options1d::default()).unwrap();
        assert!((x - 1.1).abs() < 1e-13, "{x}");
    }

    #[test]
    fn bracketed_newton_rejects_unbracketed_interval() {
        let err = solve_bracketed(|x| (x * x + 1.0, 2.0 * x), -1.0, 1.0, Options1d::default()).unwrap_err();
        assert!(matches!(err, ExactError::NotBracketed { .. }));
    }

    #[test]
    fn expand_upper_builds_a_bracket() {
        let hi = expand_upper(|x| (x.exp() - 1e6, x.exp()), 0.0, 1.0, 60).unwrap();
        assert!(hi.exp() >= 1e6);
        let x = solve_bracketed(|x| (x.exp() - 1e6, x.exp()), 0.0, hi, Options1d::default()).unwrap();
        assert!((x - 1e6f64.ln()).abs() < 1e-13);
    }

    /// Intersection of the circle x^2 + y^2 = 4 with the hyperbola x y = 1,
    /// first-quadrant branch with x > y: x = sqrt(2 + sqrt 3), y = 1/x.
    struct CircleHyperbola {
        analytic: bool,
    }

    impl System2 for CircleHyperbola {
        fn residual(&self, x: [f64; 2]) -> [f64; 2] {
            [x[0] * x[0] + x[1] * x[1] - 4.0, x[0] * x[1] - 1.0]
        }
        fn jacobian(&self, x: [f64; 2]) -> Option<[[f64; 2]; 2]> {
            self.analytic.then_some([[2.0 * x[0], 2.0 * x[1]], [x[1], x[0]]])
        }
    }

    #[test]
    fn newton_2d_analytic_and_finite_difference_jacobians_agree() {
        let exact = [(2.0 + 3f64.sqrt()).sqrt(), 1.0 / (2.0 + 3f64.sqrt()).sqrt()];
        for analytic in [true, false] {
            let sys = CircleHyperbola { analytic };
            // A distant start exercises the line search.
            let sol = newton_2d(&sys, [10.0, 0.1], Options2d::default()).unwrap();
            for (got, want) in sol.x.iter().zip(exact) {
                assert!((got - want).abs() < 1e-12, "analytic={analytic}: {sol:?}");
            }
            let j_fd = fd_jacobian(&sys, sol.x, 1e-6);
            let j_an = CircleHyperbola { analytic: true }.jacobian(sol.x).unwrap();
            for i in 0..2 {
                for k in 0..2 {
                    // Central differences: error ~ h^2 f''' ~ 1e-12 here.
                    assert!((j_fd[i][k] - j_an[i][k]).abs() < 1e-8);
                }
            }
        }
    }

    #[test]
    fn newton_2d_reports_failure_without_root() {
        // x^2 + 1 = 0, y = 0 has no real root.
        struct NoRoot;
        impl System2 for NoRoot {
            fn residual(&self, x: [f64; 2]) -> [f64; 2] {
                [x[0] * x[0] + 1.0, x[1]]
            }
        }
        let opts = Options2d { max_iterations: 50, ..Options2d::default() };
        assert!(newton_2d(&NoRoot, [0.3, 1.0], opts).is_err());
    }
}
