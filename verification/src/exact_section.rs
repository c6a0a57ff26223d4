//! Independent exact reference for the static equilibrium of a line section: several spans of an elastic
//! catenary hung on suspension insulator strings between two dead-ends, in the vertical plane of the line.
//!
//! This module is deliberately self-contained: it uses no solver code of the `ohl` crate (no `ohl::statics`,
//! `ohl::scheme`, `ohl::exact`), only `std` and `f64`, with its own dense Gaussian elimination and its own
//! damped Newton iteration, so that it can serve as the independent check of those solvers.
//!
//! # Coordinates and conventions (SI)
//!
//! `x` \[m\] runs along the line, `z` \[m\] points **up**. A span runs from its left clamp `P_k` to its right
//! clamp `P_{k+1}`; `s` \[m\] is the unstretched arc coordinate from the left clamp, `0 <= s <= L`. `H > 0` \[N\]
//! is the horizontal component of the tension, constant along a span; `V` \[N\] is the **upward** vertical
//! force the left clamp exerts on the cable (positive for a normally hanging span, `V = wL/2` for a level
//! one). The right clamp exerts the upward force `V_r = wL - V`.
//!
//! # The elastic catenary (H. M. Irvine, *Cable Structures*, MIT Press 1981, ch. 1)
//!
//! Derivation. Free body of the cable piece `[0, s]`: the left clamp pushes with `(-H, V)`, the weight is
//! `(0, -w s)` (`w` \[N/m\] per *unstretched* metre), so the tension carried across the section at `s` is
//! `T(s) (dx/dp, dz/dp) = (H, w s - V)`, `T(s) = sqrt(H^2 + (V - w s)^2)`, `p` the stretched arc length. Hooke's
//! law `dp/ds = 1 + T/EA` then gives `dx/ds = H/EA + H/T` and `dz/ds = (w s - V)(1/EA + 1/T)`; with
//! `u = (V - w s)/H` both integrate in closed form:
//!
//! ```text
//! x(s) = H s/EA + (H/w) [asinh(V/H) - asinh((V - w s)/H)]
//! z(s) = -(V s - w s^2/2)/EA - (H/w) [sqrt(1 + (V/H)^2) - sqrt(1 + ((V - w s)/H)^2)]
//! ```
//!
//! These are Irvine's elastic-catenary equations (his equation numbers are not quoted here: not checked
//! against the book). Irvine writes `z` with both terms positive, which is the same curve with the vertical
//! coordinate measured downward. `T(s)^2` is a quadratic in `s`, so the tension is largest at an end:
//! `T_max = max(sqrt(H^2 + V^2), sqrt(H^2 + V_r^2))`.
//!
//! Cancellation-free evaluation (a discrete solver converging at order two is compared with this module down
//! to 1e-6 m, so the closed form must be accurate to ~1e-12 relative). With `a = V/H`, `b = (V - w s)/H`,
//! `d = a - b = w s/H` (computed as `w s/H`, not as a difference), `a + b = (2V - w s)/H` (computed directly),
//! `S_a = sqrt(1 + a^2)`, `S_b = sqrt(1 + b^2)`:
//!
//! ```text
//! (H/w)(S_a - S_b) = s (a + b)/(S_a + S_b)                       (so z never subtracts two large numbers)
//! asinh a - asinh b = asinh(a S_b - b S_a)                         (sinh(A - B) = sinh A cosh B - cosh A sinh B)
//!                   = asinh(d (a + b)/(a S_b + b S_a))             when a b > 0 (both ends slope the same way)
//! z(s) = -s (a + b) [H/(2 EA) + 1/(S_a + S_b)]
//! ```
//!
//! When `a b <= 0` the two `asinh` have opposite signs and their difference is a sum (no cancellation).
//!
//! # Insulator strings
//!
//! A suspension string hangs from the crossarm pivot `Q` to the clamp. It carries tension `T >= 0` only, its
//! length under tension is `l_e = l (1 + T/k)` (`k` \[N\] its axial stiffness `EA`, `f64::INFINITY` =
//! inextensible), its mass `m` is lumped at the clamp. The unknowns of a string are its swing `theta` from
//! plumb (positive toward `+x`) and its tension `T`; the clamp is `P = Q + l (1 + T/k) (sin theta, -cos theta)`.
//! This is the length law `T = k (|Q - P|/l - 1)` inverted, written so that it stays smooth and also holds for
//! `k = INFINITY` (where `T` becomes a reaction). The smooth law lets `T` go negative (a compressed string); a
//! converged `T <= 0` means the string is slack in equilibrium, which [`solve`] reports as an error.
//!
//! An elastic crossarm (a tower's longitudinal flexibility) is a horizontal spring `k_a` \[N/m\] on the pivot:
//! the string pulls the pivot toward the clamp with `T (sin theta, -cos theta)`, the crossarm is rigid
//! vertically, so the pivot rests at `Q = Q_0 + (T sin theta / k_a, 0)`. This adds no unknown: the clamp is
//! `P = Q_0 + (T sin theta / k_a, 0) + l (1 + T/k) (sin theta, -cos theta)`, and `k_a = INFINITY` is the rigid
//! crossarm. The clamp's force balance is unchanged (the string's direction is still `theta`).
//!
//! # Equations
//!
//! Unknowns: `(H_k, V_k)` for each intact span, `(theta_i, T_i)` for each suspension string. Equations:
//!
//! * closure of each intact span: `[x(L), z(L)] = P_{k+1} - P_k`;
//! * force balance of each suspension clamp `i` (a point): the left span pulls it with `(-H_{i-1}, -V_r)`, the
//!   right span with `(H_i, -V_i)`, the string with `T (-sin theta, cos theta)`, the lumped weight is
//!   `(0, -m g)`; the sum vanishes.
//!
//! A broken span (`Span::broken = Some(f)`) transmits no horizontal force: each piece hangs straight down
//! from its clamp, the left piece (unstretched length `f L`) loads its clamp with `w f L` downward, the right
//! piece with `w (1 - f) L`. Its lower end lies `f L + w (f L)^2/(2 EA)` below the clamp (stretched length of
//! a wire hanging from one point: `T = w s` from the free end, `integral (1 + w s/EA) ds`).
//!
//! Start: strings plumb with the tension of the adjacent half-span weights, each span solved alone between
//! those clamps from the Peyrot-Goulois starting estimate (A. H. Peyrot, A. M. Goulois, "Analysis of cable
//! structures", Computers & Structures 10, 1979), then the strings' tensions recomputed from the vertical
//! balance of the plumb clamps. Damped Newton with the analytic Jacobian, backtracking (Armijo) on the
//! scaled residual norm; converged when every force residual is below `1e-9 N` and every closure below
//! `1e-11 m` (raised to `16 eps` times the section's force / coordinate scale for very large sections, where
//! rounding alone exceeds them), then polished by up to two further Newton steps kept only when they reduce
//! the residual.
//! Each swing may change by at most 0.5 rad per step. Errors: a converged string with `T <= 0` (slack) or
//! swung above the horizontal (both mean uplift), and a failed iteration, whose message names the least
//! tensioned string of the last iterate (uplift usually shows there as a string driven below zero tension).

/// A support of the section, ordered left to right along `x`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Support {
    /// The conductor is fixed at `point = [x, z]` \[m\].
    DeadEnd {
        /// attachment point `[x, z]` \[m\]
        point: [f64; 2],
    },
    /// A suspension insulator string hanging from the crossarm pivot to the conductor clamp.
    Suspension {
        /// crossarm pivot `[x, z]` \[m\]
        pivot: [f64; 2],
        /// unstretched string length, pivot to clamp \[m\]
        length_m: f64,
        /// string mass, lumped at the clamp \[kg\]
        mass_kg: f64,
        /// axial stiffness `EA` of the string \[N\]: its length under tension `T` is `length_m (1 + T/stiffness_n)`;
        /// `f64::INFINITY` = inextensible
        stiffness_n: f64,
        /// longitudinal spring of an elastic crossarm \[N/m\]: the pivot moves along `x` until the spring
        /// balances the string's horizontal pull; `f64::INFINITY` = rigid crossarm
        crossarm_n_per_m: f64,
    },
}

/// One span of conductor between two consecutive supports (clamp to clamp).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Span {
    /// axial stiffness `EA` \[N\] (`f64::INFINITY` = inextensible)
    pub ea_n: f64,
    /// weight per unit *unstretched* length \[N/m\] (linear density times `g`; ice increases it)
    pub w_n_per_m: f64,
    /// unstretched length \[m\]
    pub length_m: f64,
    /// `Some(f)`: the span is broken at the fraction `f` in `[0, 1]` of its unstretched length from the left
    /// clamp; `None`: intact
    pub broken: Option<f64>,
}

/// A line section: `spans.len() + 1` supports, the first and the last dead-ends.
#[derive(Debug, Clone, PartialEq)]
pub struct Section {
    /// supports, left to right (strictly increasing `x` of the dead-end points / pivots)
    pub supports: Vec<Support>,
    /// spans; span `k` joins support `k` and support `k + 1`
    pub spans: Vec<Span>,
    /// gravitational acceleration \[m/s^2\] (weighs the insulator masses; the span weights are given in N/m)
    pub g_m_per_s2: f64,
}

/// Equilibrium state of one span.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpanState {
    /// horizontal tension `H` \[N\] (0 for a broken span)
    pub h_n: f64,
    /// upward force of the left clamp on the cable \[N\] (broken span: weight of the left piece)
    pub v_left_n: f64,
    /// upward force of the right clamp on the cable, `wL - v_left_n` \[N\] (broken span: weight of the right piece)
    pub v_right_n: f64,
    /// left clamp `[x, z]` \[m\]
    pub left_clamp: [f64; 2],
    /// right clamp `[x, z]` \[m\]
    pub right_clamp: [f64; 2],
    /// largest tension along the span \[N\] (at one of its ends)
    pub max_tension_n: f64,
}

/// Equilibrium state of one support.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SupportState {
    /// conductor clamp `[x, z]` \[m\] (the dead-end point itself for a dead-end)
    pub clamp: [f64; 2],
    /// tension of the insulator string \[N\] (0 for a dead-end)
    pub insulator_tension_n: f64,
    /// swing of the string from plumb \[rad\], positive when the clamp lies toward `+x` of the pivot (0 for a
    /// dead-end)
    pub swing_rad: f64,
    /// force `[F_x, F_z]` \[N\] the conductor and the insulator apply to the crossarm pivot / dead-end point
    pub force_on_support_n: [f64; 2],
    /// crossarm pivot `[x, z]` \[m\], displaced by an elastic crossarm (the dead-end point for a dead-end)
    pub pivot: [f64; 2],
}

/// Equilibrium of a [`Section`].
#[derive(Debug, Clone, PartialEq)]
pub struct SectionSolution {
    /// one state per span
    pub spans: Vec<SpanState>,
    /// one state per support
    pub supports: Vec<SupportState>,
    /// Newton iterations taken (polishing steps included)
    pub iterations: usize,
}

/// The result of [`string_span`]: a span strung between two points with a given horizontal tension.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StrungSpan {
    /// unstretched length \[m\]
    pub length_m: f64,
    /// upward force of the left point on the cable \[N\]
    pub v_left_n: f64,
}

/// The result of [`ruling_span_tension`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RulingSpan {
    /// ruling span `L_r = sqrt(sum l^3 / sum l)` \[m\]
    pub length_m: f64,
    /// horizontal tension of the whole section in the new state \[N\]
    pub h_n: f64,
}

/// Machine epsilon.
const EPS: f64 = f64::EPSILON;
/// Force tolerance of the Newton iterations \[N\].
const FORCE_TOL_N: f64 = 1e-9;
/// Closure tolerance of the Newton iterations \[m\].
const LENGTH_TOL_M: f64 = 1e-11;
/// Newton iterations allowed before giving up.
const MAX_NEWTON: usize = 200;
/// Largest change of a swing angle in one Newton step \[rad\].
const MAX_SWING_STEP_RAD: f64 = 0.5;

/// The closed-form elastic catenary of one span (see the module doc).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Catenary {
    /// axial stiffness \[N\]
    pub(crate) ea: f64,
    /// weight per unstretched length \[N/m\]
    pub(crate) w: f64,
}

impl Catenary {
    fn of(span: &Span) -> Self {
        Self { ea: span.ea_n, w: span.w_n_per_m }
    }

    /// Offset `[x(s), z(s)]` \[m\] of the point `s` from the left end, for horizontal tension `h` and upward
    /// left-end force `v`.
    pub(crate) fn offset(self, h: f64, v: f64, s: f64) -> [f64; 2] {
        let w = self.w;
        let a = v / h;
        let b = (v - w * s) / h;
        let d = w * s / h;
        let sum = (2.0 * v - w * s) / h;
        let sa = a.hypot(1.0);
        let sb = b.hypot(1.0);
        let dasinh = if a * b <= 0.0 { a.asinh() - b.asinh() } else { (d * sum / (a * sb + b * sa)).asinh() };
        let x = h * s / self.ea + (h / w) * dasinh;
        let z = -s * sum * (0.5 * h / self.ea + 1.0 / (sa + sb));
        [x, z]
    }

    /// Derivatives of `[x(s), z(s)]` with respect to `[h, v, s]`.
    pub(crate) fn jacobian(self, h: f64, v: f64, s: f64) -> [[f64; 3]; 2] {
        let w = self.w;
        let a = v / h;
        let b = (v - w * s) / h;
        let sa = a.hypot(1.0);
        let sb = b.hypot(1.0);
        let f = |u: f64| u.asinh() - u / u.hypot(1.0);
        [
            [s / self.ea + (f(a) - f(b)) / w, (1.0 / sa - 1.0 / sb) / w, h / self.ea + 1.0 / sb],
            [(1.0 / sb - 1.0 / sa) / w, -s / self.ea - (a / sa - b / sb) / w, -b * (h / self.ea + 1.0 / sb)],
        ]
    }

    /// Tension \[N\] at `s`.
    fn tension(self, h: f64, v: f64, s: f64) -> f64 {
        h.hypot(v - self.w * s)
    }
}

/// Solves `a x = b` (`a` row-major `n x n`, overwritten) by Gaussian elimination with partial pivoting.
fn gauss_solve(a: &mut [f64], b: &mut [f64]) -> Result<Vec<f64>, String> {
    let n = b.len();
    for col in 0..n {
        let mut piv = col;
        for row in col + 1..n {
            if a[row * n + col].abs() > a[piv * n + col].abs() {
                piv = row;
            }
        }
        let p = a[piv * n + col];
        if p == 0.0 || !p.is_finite() {
            return Err(format!("singular Jacobian (column {col})"));
        }
        if piv != col {
            for j in 0..n {
                a.swap(piv * n + j, col * n + j);
            }
            b.swap(piv, col);
        }
        for row in col + 1..n {
            let factor = a[row * n + col] / p;
            if factor != 0.0 {
                for j in col..n {
                    a[row * n + j] -= factor * a[col * n + j];
                }
                b[row] -= factor * b[col];
            }
        }
    }
    let mut x = vec![0.0; n];
    for row in (0..n).rev() {
        let mut acc = b[row];
        for j in row + 1..n {
            acc -= a[row * n + j] * x[j];
        }
        x[row] = acc / a[row * n + row];
    }
    Ok(x)
}

/// Result of [`damped_newton`].
pub(crate) struct NewtonOutcome {
    pub(crate) x: Vec<f64>,
    pub(crate) iterations: usize,
}

/// Failure of [`damped_newton`]: why, and the last iterate.
pub(crate) struct NewtonFailure {
    pub(crate) message: String,
    pub(crate) x: Vec<f64>,
}

/// Half the sum of squares of `r / tol`, and the largest `|r / tol|`.
fn merit(r: &[f64], tol: &[f64]) -> (f64, f64) {
    r.iter().zip(tol).fold((0.0, 0.0), |(m, mx), (ri, ti)| {
        let q = ri / ti;
        (m + 0.5 * q * q, f64::max(mx, q.abs()))
    })
}

/// Damped Newton iteration for `residual(x) = 0`, converged when every `|residual_i| <= tol_i`.
///
/// `residual` returns `None` where `x` is inadmissible; `jacobian` returns the row-major Jacobian. A step
/// is first shortened so that no `|dx_i|` exceeds `max_step_i`, then halved until the Armijo condition on
/// the merit `sum (r_i/tol_i)^2 / 2` holds. After convergence up to two polishing steps are kept if they
/// reduce the merit.
pub(crate) fn damped_newton(
    mut x: Vec<f64>,
    tol: &[f64],
    max_step: &[f64],
    residual: impl Fn(&[f64]) -> Option<Vec<f64>>,
    jacobian: impl Fn(&[f64]) -> Vec<f64>,
) -> Result<NewtonOutcome, NewtonFailure> {
    let n = x.len();
    let Some(mut r) = residual(&x) else {
        return Err(NewtonFailure { message: "the starting guess is inadmissible".into(), x });
    };
    let (mut m, mut worst) = merit(&r, tol);
    if !m.is_finite() {
        return Err(NewtonFailure { message: "the residual at the starting guess is not finite".into(), x });
    }
    let mut polish = 0;
    let mut iterations = 0;
    while iterations < MAX_NEWTON {
        if worst <= 1.0 {
            if polish == 2 {
                break;
            }
            polish += 1;
        }
        let mut jac = jacobian(&x);
        let mut rhs: Vec<f64> = r.iter().zip(tol).map(|(ri, ti)| -ri / ti).collect();
        for i in 0..n {
            for j in 0..n {
                jac[i * n + j] /= tol[i];
            }
        }
        let mut dx = match gauss_solve(&mut jac, &mut rhs) {
            Ok(dx) => dx,
            Err(_) if worst <= 1.0 => break,
            Err(e) => return Err(NewtonFailure { message: format!("{e} at Newton iteration {iterations}"), x }),
        };
        let shrink = dx.iter().zip(max_step).fold(1.0_f64, |c, (d, lim)| c.min(lim / d.abs()));
        if shrink < 1.0 {
            dx.iter_mut().for_each(|d| *d *= shrink);
        }
        let mut lambda = 1.0;
        let accepted = loop {
            let trial: Vec<f64> = x.iter().zip(&dx).map(|(xi, di)| xi + lambda * di).collect();
            if let Some(rt) = residual(&trial) {
                let (mt, wt) = merit(&rt, tol);
                let armijo = if worst <= 1.0 { mt < m } else { mt <= m * (1.0 - 2e-4 * lambda) };
                if mt.is_finite() && armijo {
                    break Some((trial, rt, mt, wt));
                }
            }
            lambda *= 0.5;
            if lambda < 1e-12 || (worst <= 1.0 && lambda < 0.5) {
                break None;
            }
        };
        iterations += 1;
        match accepted {
            Some((xt, rt, mt, wt)) => {
                x = xt;
                r = rt;
                m = mt;
                worst = wt;
            }
            None if worst <= 1.0 => break,
            None => {
                let message =
                    format!("line search failed at Newton iteration {iterations}: largest scaled residual {worst:.3e}");
                return Err(NewtonFailure { message, x });
            }
        }
    }
    if worst <= 1.0 {
        Ok(NewtonOutcome { x, iterations })
    } else {
        let message = format!("no convergence in {MAX_NEWTON} Newton iterations: largest scaled residual {worst:.3e}");
        Err(NewtonFailure { message, x })
    }
}

fn check_positive(what: &str, value: f64, allow_infinite: bool) -> Result<(), String> {
    if value > 0.0 && (allow_infinite || value.is_finite()) {
        Ok(())
    } else {
        Err(format!("{what} must be positive{}, got {value}", if allow_infinite { "" } else { " and finite" }))
    }
}

fn check_point(what: &str, p: [f64; 2]) -> Result<(), String> {
    if p.iter().all(|c| c.is_finite()) { Ok(()) } else { Err(format!("{what} must be finite, got {p:?}")) }
}

/// Closure tolerance \[m\] for coordinates of magnitude up to `scale_m`.
pub(crate) fn length_tol(scale_m: f64) -> f64 {
    LENGTH_TOL_M.max(16.0 * EPS * scale_m)
}

/// Force tolerance \[N\] for forces of magnitude up to `scale_n`.
pub(crate) fn force_tol(scale_n: f64) -> f64 {
    FORCE_TOL_N.max(16.0 * EPS * scale_n)
}

/// Peyrot-Goulois starting estimate `(H, V)` for a span of unstretched length `length` spanning `delta`.
fn starting_estimate(w: f64, length: f64, delta: [f64; 2]) -> (f64, f64) {
    let [l, h] = delta;
    let chord2 = l * l + h * h;
    let lambda =
        if length * length <= chord2 { 0.2 } else { (3.0 * ((length * length - h * h) / (l * l) - 1.0)).sqrt() };
    let lambda = lambda.max(1e-6);
    (w * l / (2.0 * lambda), 0.5 * w * (length - h / lambda.tanh()))
}

/// Solves one span of unstretched length `length` between clamps `delta = P_right - P_left` apart: `(H, V)`.
pub(crate) fn solve_span(cat: Catenary, length: f64, delta: [f64; 2]) -> Result<(f64, f64), String> {
    let (h0, v0) = starting_estimate(cat.w, length, delta);
    let tol = length_tol(delta[0].abs() + delta[1].abs() + length);
    let out = damped_newton(
        vec![h0, v0],
        &[tol, tol],
        &[f64::INFINITY, f64::INFINITY],
        |x| {
            (x[0] > 0.0).then(|| {
                let o = cat.offset(x[0], x[1], length);
                vec![o[0] - delta[0], o[1] - delta[1]]
            })
        },
        |x| {
            let j = cat.jacobian(x[0], x[1], length);
            vec![j[0][0], j[0][1], j[1][0], j[1][1]]
        },
    )
    .map_err(|f| f.message)?;
    Ok((out.x[0], out.x[1]))
}

/// Strings a span between `left` and `right` \[m\] with horizontal tension `h_n` \[N\]: its unstretched length
/// and the upward force of the left point, from the closure `[x(L), z(L)] = right - left` solved for `(L, V)`
/// (elastic catenary of axial stiffness `ea_n` \[N\] and weight `w_n_per_m` \[N/m\] per unstretched metre).
pub fn string_span(ea_n: f64, w_n_per_m: f64, left: [f64; 2], right: [f64; 2], h_n: f64) -> Result<StrungSpan, String> {
    check_positive("EA", ea_n, true)?;
    check_positive("w", w_n_per_m, false)?;
    check_positive("H", h_n, false)?;
    check_point("left point", left)?;
    check_point("right point", right)?;
    let delta = [right[0] - left[0], right[1] - left[1]];
    if delta[0] <= 0.0 {
        return Err(format!("the right point must lie at larger x than the left point, got {left:?} -> {right:?}"));
    }
    let cat = Catenary { ea: ea_n, w: w_n_per_m };
    // parabolic start: slack q^2 l^6 / (24 H^2 c^3) with q = w c / l the load per horizontal metre, less the
    // elastic stretch under the mean tension H c / l
    let chord = delta[0].hypot(delta[1]);
    let q = w_n_per_m * chord / delta[0];
    let stretched = chord + q * q * delta[0].powi(6) / (24.0 * h_n * h_n * chord.powi(3));
    let l0 = stretched / (1.0 + h_n * chord / (delta[0] * ea_n));
    let v0 = 0.5 * w_n_per_m * l0 - h_n * delta[1] / delta[0];
    let tol = length_tol(delta[0].abs() + delta[1].abs() + chord);
    let out = damped_newton(
        vec![l0, v0],
        &[tol, tol],
        &[0.5 * chord, f64::INFINITY],
        |x| {
            (x[0] > 0.0).then(|| {
                let o = cat.offset(h_n, x[1], x[0]);
                vec![o[0] - delta[0], o[1] - delta[1]]
            })
        },
        |x| {
            let j = cat.jacobian(h_n, x[1], x[0]);
            vec![j[0][2], j[0][1], j[1][2], j[1][1]]
        },
    )
    .map_err(|f| format!("stringing a span: {}", f.message))?;
    Ok(StrungSpan { length_m: out.x[0], v_left_n: out.x[1] })
}

/// The unstretched length \[m\] of a span strung between two given points `left`, `right` \[m\] with horizontal
/// tension `h_n` \[N\] (each span's stringing: "H0 with insulators plumb"); elastic catenary of axial stiffness
/// `ea_n` \[N\] and weight `w_n_per_m` \[N/m\] per unstretched metre. See [`string_span`].
pub fn unstretched_length_for_tension(
    ea_n: f64,
    w_n_per_m: f64,
    left: [f64; 2],
    right: [f64; 2],
    h_n: f64,
) -> Result<f64, String> {
    string_span(ea_n, w_n_per_m, left, right, h_n).map(|s| s.length_m)
}

/// A section strung with the common horizontal tension `h0_n` \[N\] with every insulator plumb.
///
/// `supports` are taken as given (dead-end points, pivots, strings); every span gets axial stiffness `ea_n`
/// \[N\], weight `w_n_per_m` \[N/m\] and the unstretched length that makes the plumb state with `H = h0_n` in
/// every span an equilibrium: each clamp hangs plumb `length (1 + T/k)` below its pivot, with `T` the string
/// tension of that state (the weights the two adjacent spans hang on the clamp plus the string's own weight),
/// found by fixed-point iteration (it converges at the rate `l/k` times the span's vertical stiffness, i.e. in
/// a few passes for real strings; one pass for inextensible ones).
pub fn string_section(
    supports: Vec<Support>,
    ea_n: f64,
    w_n_per_m: f64,
    h0_n: f64,
    g_m_per_s2: f64,
) -> Result<Section, String> {
    let n = supports.len();
    if n < 2 {
        return Err("a section needs at least two supports".into());
    }
    let mut tension: Vec<f64> = vec![0.0; n];
    for i in 0..n {
        if let Support::Suspension { mass_kg, .. } = supports[i] {
            let left = if i > 0 { support_x(&supports[i]) - support_x(&supports[i - 1]) } else { 0.0 };
            let right = if i + 1 < n { support_x(&supports[i + 1]) - support_x(&supports[i]) } else { 0.0 };
            tension[i] = mass_kg * g_m_per_s2 + 0.5 * w_n_per_m * (left + right);
        }
    }
    let clamp_of = |i: usize, t: f64| match supports[i] {
        Support::DeadEnd { point } => point,
        Support::Suspension { pivot, length_m, stiffness_n, .. } => {
            [pivot[0], pivot[1] - length_m * (1.0 + t / stiffness_n)]
        }
    };
    for _pass in 0..100 {
        let clamps: Vec<[f64; 2]> = (0..n).map(|i| clamp_of(i, tension[i])).collect();
        let strung: Vec<StrungSpan> = (0..n - 1)
            .map(|k| string_span(ea_n, w_n_per_m, clamps[k], clamps[k + 1], h0_n))
            .collect::<Result<_, _>>()?;
        let spans: Vec<Span> =
            strung.iter().map(|s| Span { ea_n, w_n_per_m, length_m: s.length_m, broken: None }).collect();
        let mut moved: f64 = 0.0;
        for i in 0..n {
            if let Support::Suspension { mass_kg, .. } = supports[i] {
                let mut t = mass_kg * g_m_per_s2;
                if i > 0 {
                    t += w_n_per_m * strung[i - 1].length_m - strung[i - 1].v_left_n;
                }
                if i + 1 < n {
                    t += strung[i].v_left_n;
                }
                let before = clamp_of(i, tension[i]);
                tension[i] = t;
                moved = moved.max((clamp_of(i, t)[1] - before[1]).abs());
            }
        }
        if moved == 0.0 || moved < 1e-3 * LENGTH_TOL_M {
            return Ok(Section { supports, spans, g_m_per_s2 });
        }
    }
    Err("the stringing fixed point did not settle in 100 passes".into())
}

fn support_x(s: &Support) -> f64 {
    match *s {
        Support::DeadEnd { point } => point[0],
        Support::Suspension { pivot, .. } => pivot[0],
    }
}

/// Where the unknowns of a section live in the Newton vector.
struct Layout {
    /// index of `H_k` (then `V_k`) of each intact span
    span_var: Vec<Option<usize>>,
    /// index of `theta_i` (then `T_i`) of each suspension string
    support_var: Vec<Option<usize>>,
    /// number of unknowns
    n: usize,
}

impl Layout {
    fn of(section: &Section) -> Self {
        let mut n = 0;
        let span_var = section
            .spans
            .iter()
            .map(|s| {
                s.broken.is_none().then(|| {
                    n += 2;
                    n - 2
                })
            })
            .collect();
        let support_var = section
            .supports
            .iter()
            .map(|s| {
                matches!(s, Support::Suspension { .. }).then(|| {
                    n += 2;
                    n - 2
                })
            })
            .collect();
        Self { span_var, support_var, n }
    }
}

/// Clamp of support `i` for the unknowns `x`, with its derivatives with respect to `theta` and `T`.
fn clamp(section: &Section, layout: &Layout, x: &[f64], i: usize) -> ([f64; 2], [f64; 2], [f64; 2]) {
    match (section.supports[i], layout.support_var[i]) {
        (Support::Suspension { pivot, length_m, stiffness_n, crossarm_n_per_m, .. }, Some(j)) => {
            let (theta, t) = (x[j], x[j + 1]);
            let (sin, cos) = theta.sin_cos();
            let le = length_m * (1.0 + t / stiffness_n);
            let dl = length_m / stiffness_n;
            // The pivot, displaced by the string's horizontal pull over the crossarm spring.
            let c = 1.0 / crossarm_n_per_m;
            let px = pivot[0] + c * t * sin;
            ([px + le * sin, pivot[1] - le * cos], [(le + c * t) * cos, le * sin], [(dl + c) * sin, -dl * cos])
        }
        (Support::DeadEnd { point }, _) => (point, [0.0; 2], [0.0; 2]),
        (Support::Suspension { .. }, None) => unreachable!("every suspension has unknowns"),
    }
}

/// Weights \[N\] of the left and right pieces of a broken span.
fn piece_weights(span: &Span, fraction: f64) -> (f64, f64) {
    let total = span.w_n_per_m * span.length_m;
    (total * fraction, total * (1.0 - fraction))
}

fn validate(section: &Section) -> Result<(), String> {
    let n = section.supports.len();
    if n < 2 || section.spans.len() + 1 != n {
        return Err(format!(
            "a section needs spans.len() + 1 >= 2 supports, got {n} supports and {} spans",
            section.spans.len()
        ));
    }
    check_positive("g", section.g_m_per_s2, false)?;
    if !matches!(section.supports[0], Support::DeadEnd { .. })
        || !matches!(section.supports[n - 1], Support::DeadEnd { .. })
    {
        return Err("the first and the last supports must be dead-ends".into());
    }
    for (i, s) in section.supports.iter().enumerate() {
        match *s {
            Support::DeadEnd { point } => check_point(&format!("dead-end point of support {i}"), point)?,
            Support::Suspension { pivot, length_m, mass_kg, stiffness_n, crossarm_n_per_m } => {
                check_point(&format!("pivot of support {i}"), pivot)?;
                check_positive(&format!("crossarm spring of support {i}"), crossarm_n_per_m, true)?;
                check_positive(&format!("string length of support {i}"), length_m, false)?;
                check_positive(&format!("string stiffness of support {i}"), stiffness_n, true)?;
                if !(mass_kg >= 0.0 && mass_kg.is_finite()) {
                    return Err(format!("string mass of support {i} must be >= 0 and finite, got {mass_kg}"));
                }
            }
        }
        if i > 0 && support_x(s) <= support_x(&section.supports[i - 1]) {
            return Err(format!("support {i} does not lie at larger x than support {}", i - 1));
        }
    }
    for (k, s) in section.spans.iter().enumerate() {
        check_positive(&format!("EA of span {k}"), s.ea_n, true)?;
        check_positive(&format!("w of span {k}"), s.w_n_per_m, false)?;
        check_positive(&format!("length of span {k}"), s.length_m, false)?;
        if let Some(f) = s.broken
            && !(0.0..=1.0).contains(&f)
        {
            return Err(format!("break fraction of span {k} must lie in [0, 1], got {f}"));
        }
    }
    Ok(())
}

/// Static equilibrium of a line section (see the module doc for the model and the method).
///
/// Errors: invalid input, no convergence of the Newton iteration, or a slack insulator string (`T <= 0`)
/// in the equilibrium found.
pub fn solve(section: &Section) -> Result<SectionSolution, String> {
    validate(section)?;
    let layout = Layout::of(section);
    let g = section.g_m_per_s2;
    let n_sup = section.supports.len();

    // starting guess: strings plumb carrying the adjacent half-span weights, each span solved alone between
    // those clamps, then the string tensions updated from the spans' end forces
    let mut x0 = vec![0.0; layout.n];
    for i in 0..n_sup {
        if let (Support::Suspension { mass_kg, .. }, Some(j)) = (section.supports[i], layout.support_var[i]) {
            let mut t = mass_kg * g;
            if i > 0 {
                let s = &section.spans[i - 1];
                t += s.broken.map_or(0.5 * s.w_n_per_m * s.length_m, |f| piece_weights(s, f).1);
            }
            if i + 1 < n_sup {
                let s = &section.spans[i];
                t += s.broken.map_or(0.5 * s.w_n_per_m * s.length_m, |f| piece_weights(s, f).0);
            }
            x0[j] = 0.0;
            x0[j + 1] = t;
        }
    }
    let mut force_scale: f64 = 0.0;
    let mut coord_scale: f64 = 0.0;
    for (k, span) in section.spans.iter().enumerate() {
        let pl = clamp(section, &layout, &x0, k).0;
        let pr = clamp(section, &layout, &x0, k + 1).0;
        coord_scale = coord_scale.max(pl[0].abs() + pl[1].abs()).max(pr[0].abs() + pr[1].abs() + span.length_m);
        force_scale += span.w_n_per_m * span.length_m;
        if let Some(j) = layout.span_var[k] {
            let cat = Catenary::of(span);
            let delta = [pr[0] - pl[0], pr[1] - pl[1]];
            let (h, v) = solve_span(cat, span.length_m, delta)
                .unwrap_or_else(|_| starting_estimate(cat.w, span.length_m, delta));
            x0[j] = h;
            x0[j + 1] = v;
            force_scale = force_scale.max(h);
        }
    }
    // the strings' tensions from the vertical balance of the plumb clamps under the spans just solved
    for i in 0..n_sup {
        if let (Support::Suspension { mass_kg, .. }, Some(j)) = (section.supports[i], layout.support_var[i]) {
            force_scale += mass_kg * g;
            let mut t = mass_kg * g;
            let left = &section.spans[i - 1];
            t += match (layout.span_var[i - 1], left.broken) {
                (Some(js), _) => left.w_n_per_m * left.length_m - x0[js + 1],
                (None, frac) => piece_weights(left, frac.unwrap_or(0.5)).1,
            };
            let right = &section.spans[i];
            t += match (layout.span_var[i], right.broken) {
                (Some(js), _) => x0[js + 1],
                (None, frac) => piece_weights(right, frac.unwrap_or(0.5)).0,
            };
            x0[j + 1] = t;
        }
    }
    let mut tol = vec![0.0; layout.n];
    let mut max_step = vec![f64::INFINITY; layout.n];
    for j in layout.span_var.iter().flatten() {
        tol[*j] = length_tol(coord_scale);
        tol[*j + 1] = length_tol(coord_scale);
    }
    for j in layout.support_var.iter().flatten() {
        tol[*j] = force_tol(force_scale);
        tol[*j + 1] = force_tol(force_scale);
        max_step[*j] = MAX_SWING_STEP_RAD;
    }

    let residual = |x: &[f64]| -> Option<Vec<f64>> {
        let mut r = vec![0.0; layout.n];
        for (k, span) in section.spans.iter().enumerate() {
            if let Some(j) = layout.span_var[k] {
                let (h, v) = (x[j], x[j + 1]);
                if h.is_nan() || h <= 0.0 {
                    return None;
                }
                let o = Catenary::of(span).offset(h, v, span.length_m);
                let pl = clamp(section, &layout, x, k).0;
                let pr = clamp(section, &layout, x, k + 1).0;
                r[j] = o[0] - (pr[0] - pl[0]);
                r[j + 1] = o[1] - (pr[1] - pl[1]);
            }
        }
        for i in 0..n_sup {
            if let (Support::Suspension { mass_kg, stiffness_n, .. }, Some(j)) =
                (section.supports[i], layout.support_var[i])
            {
                let (theta, t) = (x[j], x[j + 1]);
                if t.is_nan() || 1.0 + t / stiffness_n <= 0.0 {
                    return None;
                }
                let (sin, cos) = theta.sin_cos();
                let mut f = [-t * sin, t * cos - mass_kg * g];
                let left = &section.spans[i - 1];
                match (layout.span_var[i - 1], left.broken) {
                    (Some(js), _) => {
                        f[0] -= x[js];
                        f[1] -= left.w_n_per_m * left.length_m - x[js + 1];
                    }
                    (None, Some(frac)) => f[1] -= piece_weights(left, frac).1,
                    (None, None) => unreachable!("an intact span has unknowns"),
                }
                let right = &section.spans[i];
                match (layout.span_var[i], right.broken) {
                    (Some(js), _) => {
                        f[0] += x[js];
                        f[1] -= x[js + 1];
                    }
                    (None, Some(frac)) => f[1] -= piece_weights(right, frac).0,
                    (None, None) => unreachable!("an intact span has unknowns"),
                }
                r[j] = f[0];
                r[j + 1] = f[1];
            }
        }
        Some(r)
    };

    let jacobian = |x: &[f64]| -> Vec<f64> {
        let n = layout.n;
        let mut jac = vec![0.0; n * n];
        for (k, span) in section.spans.iter().enumerate() {
            if let Some(j) = layout.span_var[k] {
                let d = Catenary::of(span).jacobian(x[j], x[j + 1], span.length_m);
                for row in 0..2 {
                    jac[(j + row) * n + j] = d[row][0];
                    jac[(j + row) * n + j + 1] = d[row][1];
                }
                // closure residual = offset - (P_{k+1} - P_k)
                for (i, sign) in [(k, 1.0), (k + 1, -1.0)] {
                    if let Some(js) = layout.support_var[i] {
                        let (_, dtheta, dt) = clamp(section, &layout, x, i);
                        for row in 0..2 {
                            jac[(j + row) * n + js] += sign * dtheta[row];
                            jac[(j + row) * n + js + 1] += sign * dt[row];
                        }
                    }
                }
            }
        }
        for i in 0..n_sup {
            if let Some(j) = layout.support_var[i] {
                let (theta, t) = (x[j], x[j + 1]);
                let (sin, cos) = theta.sin_cos();
                jac[j * n + j] = -t * cos;
                jac[(j + 1) * n + j] = -t * sin;
                jac[j * n + j + 1] = -sin;
                jac[(j + 1) * n + j + 1] = cos;
                if let Some(js) = layout.span_var[i - 1] {
                    jac[j * n + js] = -1.0;
                    jac[(j + 1) * n + js + 1] = 1.0;
                }
                if let Some(js) = layout.span_var[i] {
                    jac[j * n + js] = 1.0;
                    jac[(j + 1) * n + js + 1] = -1.0;
                }
            }
        }
        jac
    };

    let out = damped_newton(x0, &tol, &max_step, residual, jacobian).map_err(|f| {
        // name the weakest string at the last iterate: a string driven toward zero or negative tension means
        // uplift, for which no equilibrium with taut strings exists
        let weakest = layout
            .support_var
            .iter()
            .enumerate()
            .filter_map(|(i, j)| j.map(|j| (i, f.x[j + 1], f.x[j])))
            .min_by(|a, b| a.1.total_cmp(&b.1));
        match weakest {
            Some((i, t, theta)) => format!(
                "no equilibrium found: {}; at the last iterate the least tensioned string is support {i}'s \
                 (T = {t:.6e} N, swing {:.3} deg): a string near or below zero tension means uplift",
                f.message,
                theta.to_degrees()
            ),
            None => format!("no equilibrium found: {}", f.message),
        }
    })?;
    let x = out.x;

    let clamps: Vec<[f64; 2]> = (0..n_sup).map(|i| clamp(section, &layout, &x, i).0).collect();
    let spans: Vec<SpanState> = section
        .spans
        .iter()
        .enumerate()
        .map(|(k, span)| match (layout.span_var[k], span.broken) {
            (Some(j), _) => {
                let cat = Catenary::of(span);
                let (h, v) = (x[j], x[j + 1]);
                SpanState {
                    h_n: h,
                    v_left_n: v,
                    v_right_n: span.w_n_per_m * span.length_m - v,
                    left_clamp: clamps[k],
                    right_clamp: clamps[k + 1],
                    max_tension_n: cat.tension(h, v, 0.0).max(cat.tension(h, v, span.length_m)),
                }
            }
            (None, frac) => {
                let (wl, wr) = piece_weights(span, frac.unwrap_or(0.5));
                SpanState {
                    h_n: 0.0,
                    v_left_n: wl,
                    v_right_n: wr,
                    left_clamp: clamps[k],
                    right_clamp: clamps[k + 1],
                    max_tension_n: wl.max(wr),
                }
            }
        })
        .collect();
    let mut supports = Vec::with_capacity(n_sup);
    for i in 0..n_sup {
        let state = match (section.supports[i], layout.support_var[i]) {
            (Support::Suspension { pivot, crossarm_n_per_m, .. }, Some(j)) => {
                let (theta, t) = (x[j], x[j + 1]);
                if t.is_nan() || t <= 0.0 {
                    return Err(format!(
                        "insulator string of support {i} is slack in the equilibrium found (tension {t:.6e} N)"
                    ));
                }
                let (sin, cos) = theta.sin_cos();
                if cos <= 0.0 {
                    return Err(format!(
                        "insulator string of support {i} is swung above the horizontal in the equilibrium found \
                         (swing {:.3} deg): uplift",
                        sin.atan2(cos).to_degrees()
                    ));
                }
                SupportState {
                    clamp: clamps[i],
                    insulator_tension_n: t,
                    swing_rad: sin.atan2(cos),
                    force_on_support_n: [t * sin, -t * cos],
                    pivot: [pivot[0] + t * sin / crossarm_n_per_m, pivot[1]],
                }
            }
            _ => {
                let mut f = [0.0, 0.0];
                if i > 0 {
                    f[0] -= spans[i - 1].h_n;
                    f[1] -= spans[i - 1].v_right_n;
                }
                if i + 1 < n_sup {
                    f[0] += spans[i].h_n;
                    f[1] -= spans[i].v_left_n;
                }
                SupportState {
                    clamp: clamps[i],
                    insulator_tension_n: 0.0,
                    swing_rad: 0.0,
                    force_on_support_n: f,
                    pivot: clamps[i],
                }
            }
        };
        supports.push(state);
    }
    Ok(SectionSolution { spans, supports, iterations: out.iterations })
}

impl SectionSolution {
    /// Position `[x, z]` \[m\] of the material point at unstretched arc coordinate `s_m` \[m\] (measured from the
    /// left clamp) of the intact span `k`. Returns `[NaN, NaN]` for a broken span.
    pub fn point(&self, section: &Section, k: usize, s_m: f64) -> [f64; 2] {
        let span = &section.spans[k];
        if span.broken.is_some() {
            return [f64::NAN, f64::NAN];
        }
        let st = &self.spans[k];
        let o = Catenary::of(span).offset(st.h_n, st.v_left_n, s_m);
        [st.left_clamp[0] + o[0], st.left_clamp[1] + o[1]]
    }

    /// Sag \[m\] of span `k`: the largest vertical distance between the chord of its clamps and the wire.
    ///
    /// Closed form: the wire's slope `(w s - V)/H` equals the chord slope `m` at `s* = (V + H m)/w` (clamped to
    /// `[0, L]`; the wire is convex so this is the maximum). Returns NaN for a broken span.
    pub fn sag(&self, section: &Section, k: usize) -> f64 {
        let span = &section.spans[k];
        if span.broken.is_some() {
            return f64::NAN;
        }
        let st = &self.spans[k];
        let m = (st.right_clamp[1] - st.left_clamp[1]) / (st.right_clamp[0] - st.left_clamp[0]);
        let s = ((st.v_left_n + st.h_n * m) / span.w_n_per_m).clamp(0.0, span.length_m);
        let o = Catenary::of(span).offset(st.h_n, st.v_left_n, s);
        m * o[0] - o[1]
    }

    /// Lower ends `[left piece, right piece]`, each `[x, z]` \[m\], of the two pieces of the broken span `k`,
    /// hanging straight down from their clamps (stretched length `f L + w (f L)^2 / (2 EA)` for the left piece,
    /// likewise for the right one); `None` for an intact span. The ground is not modelled: the ends may lie
    /// below it.
    pub fn broken_piece_ends(&self, section: &Section, k: usize) -> Option<[[f64; 2]; 2]> {
        let span = &section.spans[k];
        let f = span.broken?;
        let st = &self.spans[k];
        let hang = |len: f64| len + span.w_n_per_m * len * len / (2.0 * span.ea_n);
        Some([
            [st.left_clamp[0], st.left_clamp[1] - hang(f * span.length_m)],
            [st.right_clamp[0], st.right_clamp[1] - hang((1.0 - f) * span.length_m)],
        ])
    }
}

/// Ruling-span approximation of a suspension section after a change of weight on all spans.
///
/// The line designer's method: the insulators are assumed to equalise the horizontal tension, so one
/// horizontal tension `H` holds in every span, and it follows the change-of-state equation of a single level
/// span of the ruling length `L_r = sqrt(sum l^3 / sum l)` (`l` the horizontal span lengths, \[m\]). The
/// change-of-state equation (parabolic sag, tension taken equal to `H`, the same unstretched length before
/// and after, no temperature change) reads
///
/// ```text
/// (H2 - H1)/EA = (L_r^2 / 24) (w2^2/H2^2 - w1^2/H1^2),
/// equivalently H2^2 [H2 - H1 + EA w1^2 L_r^2/(24 H1^2)] = EA w2^2 L_r^2 / 24,
/// ```
///
/// from the slack `S - l = w^2 l^3/(24 H^2)` and the stretch `dS = l dH/EA`. It has one positive root
/// `H2` (the left side increases with `H2`, the right side decreases), found here by bisection to rounding.
///
/// `ea_n` \[N\]: axial stiffness; `w1_n_per_m`, `h1_n`: weight \[N/m\] and horizontal tension \[N\] of the known
/// state; `w2_n_per_m`: weight of the new state.
pub fn ruling_span_tension(
    span_lengths_m: &[f64],
    ea_n: f64,
    w1_n_per_m: f64,
    h1_n: f64,
    w2_n_per_m: f64,
) -> Result<RulingSpan, String> {
    if span_lengths_m.is_empty() {
        return Err("no spans".into());
    }
    for (k, l) in span_lengths_m.iter().enumerate() {
        check_positive(&format!("length of span {k}"), *l, false)?;
    }
    check_positive("EA", ea_n, true)?;
    check_positive("w1", w1_n_per_m, false)?;
    check_positive("w2", w2_n_per_m, false)?;
    check_positive("H1", h1_n, false)?;
    let cube: f64 = span_lengths_m.iter().map(|l| l * l * l).sum();
    let sum: f64 = span_lengths_m.iter().sum();
    let lr = (cube / sum).sqrt();
    let c = lr * lr / 24.0;
    let g =
        |h: f64| (h - h1_n) / ea_n - c * (w2_n_per_m * w2_n_per_m / (h * h) - w1_n_per_m * w1_n_per_m / (h1_n * h1_n));
    let (mut lo, mut hi) = (h1_n, h1_n);
    while g(lo) > 0.0 {
        lo *= 0.5;
    }
    while g(hi) < 0.0 {
        hi *= 2.0;
    }
    for _ in 0..2000 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if g(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(RulingSpan { length_m: lr, h_n: 0.5 * (lo + hi) })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// g \[m/s^2\]
    const G: f64 = 9.81;
    /// ACSR Drake: weight per metre \[N/m\] (1.628 kg/m)
    const DRAKE_W: f64 = 1.628 * G;
    /// ACSR Drake: axial stiffness \[N\]
    const DRAKE_EA: f64 = 2.9e7;
    /// span \[m\]
    const SPAN: f64 = 400.0;
    /// stringing tension: 20 % of the rated tensile strength 140 kN \[N\]
    const H0: f64 = 0.2 * 140e3;
    /// suspension string length \[m\]
    const INS_LEN: f64 = 3.5;
    /// suspension string mass \[kg\]
    const INS_MASS: f64 = 100.0;
    /// suspension string axial stiffness \[N\]
    const INS_EA: f64 = 5e7;
    /// crossarm pivot height \[m\]
    const PIVOT_Z: f64 = 30.0;

    fn bisect(mut lo: f64, mut hi: f64, f: impl Fn(f64) -> f64) -> f64 {
        let flo = f(lo);
        assert!(flo * f(hi) < 0.0, "no sign change on [{lo}, {hi}]");
        for _ in 0..400 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if (f(mid) < 0.0) == (flo < 0.0) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    /// Composite 5-point Gauss-Legendre quadrature of `dx/ds = H/EA + H/T`, `dz/ds = (w s - V)(1/EA + 1/T)`
    /// over `[0, L]`: the end offset of a span without the closed-form integrals.
    fn quadrature_offset(span: &Span, h: f64, v: f64) -> [f64; 2] {
        const NODES: [f64; 5] =
            [-0.906_179_845_938_664, -0.538_469_310_105_683, 0.0, 0.538_469_310_105_683, 0.906_179_845_938_664];
        const WEIGHTS: [f64; 5] = [
            0.236_926_885_056_189_1,
            0.478_628_670_499_366_5,
            0.568_888_888_888_888_9,
            0.478_628_670_499_366_5,
            0.236_926_885_056_189_1,
        ];
        let panels = 400;
        let ds = span.length_m / panels as f64;
        let (mut x, mut z) = (0.0, 0.0);
        for p in 0..panels {
            let mid = (p as f64 + 0.5) * ds;
            let (mut px, mut pz) = (0.0, 0.0);
            for (t, wt) in NODES.iter().zip(WEIGHTS) {
                let s = mid + 0.5 * ds * t;
                let tension = h.hypot(v - span.w_n_per_m * s);
                px += wt * (h / span.ea_n + h / tension);
                pz += wt * (span.w_n_per_m * s - v) * (1.0 / span.ea_n + 1.0 / tension);
            }
            x += 0.5 * ds * px;
            z += 0.5 * ds * pz;
        }
        [x, z]
    }

    fn dead_end_span(left: [f64; 2], right: [f64; 2], span: Span) -> Section {
        Section {
            supports: vec![Support::DeadEnd { point: left }, Support::DeadEnd { point: right }],
            spans: vec![span],
            g_m_per_s2: G,
        }
    }

    fn suspension(x: f64, z: f64, length: f64, mass: f64, stiffness: f64) -> Support {
        Support::Suspension {
            pivot: [x, z],
            length_m: length,
            mass_kg: mass,
            stiffness_n: stiffness,
            crossarm_n_per_m: f64::INFINITY,
        }
    }

    /// Three level Drake spans of 400 m: dead-ends at the plumb clamp height of the suspensions, strung at H0.
    fn three_level_spans(length: f64, mass: f64, stiffness: f64) -> Section {
        let l = unstretched_length_for_tension(DRAKE_EA, DRAKE_W, [0.0, 0.0], [SPAN, 0.0], H0).unwrap();
        let t = DRAKE_W * l + mass * G;
        let clamp_z = PIVOT_Z - length * (1.0 + t / stiffness);
        let supports = vec![
            Support::DeadEnd { point: [0.0, clamp_z] },
            suspension(SPAN, PIVOT_Z, length, mass, stiffness),
            suspension(2.0 * SPAN, PIVOT_Z, length, mass, stiffness),
            Support::DeadEnd { point: [3.0 * SPAN, clamp_z] },
        ];
        string_section(supports, DRAKE_EA, DRAKE_W, H0, G).unwrap()
    }

    fn print_solution(label: &str, section: &Section, sol: &SectionSolution) {
        println!("{label}: {} Newton iterations", sol.iterations);
        for (k, st) in sol.spans.iter().enumerate() {
            let sag = if section.spans[k].broken.is_some() { f64::NAN } else { sol.sag(section, k) };
            println!(
                "  span {k}: L = {:.9} m, w = {:.6} N/m, H = {:.9} N, V_left = {:.9} N, V_right = {:.9} N, \
                 T_max = {:.6} N, sag = {:.9} m",
                section.spans[k].length_m,
                section.spans[k].w_n_per_m,
                st.h_n,
                st.v_left_n,
                st.v_right_n,
                st.max_tension_n,
                sag
            );
        }
        for (i, st) in sol.supports.iter().enumerate() {
            println!(
                "  support {i}: clamp = [{:.9}, {:.9}] m, T_ins = {:.9} N, swing = {:.6e} rad ({:.6} deg), \
                 force on support = [{:.9}, {:.9}] N",
                st.clamp[0],
                st.clamp[1],
                st.insulator_tension_n,
                st.swing_rad,
                st.swing_rad.to_degrees(),
                st.force_on_support_n[0],
                st.force_on_support_n[1]
            );
        }
    }

    /// Horizontal and vertical force balance of each suspension clamp from the reported states \[N\].
    fn clamp_imbalance(section: &Section, sol: &SectionSolution, i: usize) -> [f64; 2] {
        let Support::Suspension { mass_kg, .. } = section.supports[i] else { panic!("not a suspension") };
        let (l, r, s) = (&sol.spans[i - 1], &sol.spans[i], &sol.supports[i]);
        let (sin, cos) = s.swing_rad.sin_cos();
        [
            -l.h_n + r.h_n - s.insulator_tension_n * sin,
            -l.v_right_n - r.v_left_n + s.insulator_tension_n * cos - mass_kg * section.g_m_per_s2,
        ]
    }

    #[test]
    fn catenary_jacobian_matches_finite_differences() {
        let cat = Catenary { ea: DRAKE_EA, w: DRAKE_W };
        for (h, v, s) in [(H0, 3000.0, 400.0), (5000.0, -2000.0, 300.0), (28000.0, 9000.0, 350.0)] {
            let j = cat.jacobian(h, v, s);
            let steps = [h * 1e-6, 1e-6 * h, 1e-6 * s];
            for c in 0..3 {
                let mut p = [h, v, s];
                let mut m = [h, v, s];
                p[c] += steps[c];
                m[c] -= steps[c];
                let op = cat.offset(p[0], p[1], p[2]);
                let om = cat.offset(m[0], m[1], m[2]);
                for row in 0..2 {
                    let fd = (op[row] - om[row]) / (2.0 * steps[c]);
                    // central difference: truncation ~ step^2 |f'''| plus rounding eps |f| / step, both far
                    // below 1e-6 of the largest entry
                    let scale = j[row].iter().map(|e| e.abs()).fold(0.0, f64::max);
                    assert!((fd - j[row][c]).abs() < 1e-6 * scale, "d{row}/d{c}: fd {fd} analytic {}", j[row][c]);
                }
            }
        }
    }

    /// Test 1: one span between two dead-ends.
    #[test]
    fn single_span_against_classical_catenary_and_quadrature() {
        let l = 400.0;
        let length = 401.0;
        let w = DRAKE_W;
        // classical (inextensible) catenary of a level span: length = (2H/w) sinh(w l/(2H)),
        // sag = (H/w)(cosh(w l/(2H)) - 1)
        let h_from_length = bisect(1e3, 1e6, |h| 2.0 * h / w * (w * l / (2.0 * h)).sinh() - length);
        for ea in [1e15, f64::INFINITY] {
            let section =
                dead_end_span([0.0, 10.0], [l, 10.0], Span { ea_n: ea, w_n_per_m: w, length_m: length, broken: None });
            let sol = solve(&section).unwrap();
            let h = sol.spans[0].h_n;
            let sag = sol.sag(&section, 0);
            let h_from_sag = bisect(1e3, 1e6, |h| h / w * ((w * l / (2.0 * h)).cosh() - 1.0) - sag);
            // EA = 1e15 stretches the wire by L H/EA = 1.1e-8 m; with the slack e = L - l = 1 m and H ~ e^(-1/2)
            // that moves H by (L H/EA)/(2 e) = 5.6e-9 relative: tolerance 2 (L H/EA)/(2 e) + 1e-12 (rounding of
            // the closed form and the bisection); EA = INFINITY: 1e-12
            let elastic = if ea.is_finite() { 2.0 * length * h / ea / (2.0 * (length - l)) } else { 0.0 };
            let tol = elastic + 1e-12;
            let rel_l = (h - h_from_length).abs() / h_from_length;
            let rel_s = (h - h_from_sag).abs() / h_from_sag;
            println!(
                "test 1, EA = {ea:e} N: H = {h:.9} N, H(classical length) = {h_from_length:.9} N (rel {rel_l:.2e}), \
                 sag = {sag:.12} m, H(classical sag) = {h_from_sag:.9} N (rel {rel_s:.2e}), tol {tol:.2e}, \
                 {} iterations",
                sol.iterations
            );
            assert!(rel_l < tol && rel_s < tol);
        }

        // elastic spans, level and inclined
        for (right, length) in [([400.0, 10.0], 400.5), ([400.0, 70.0], 405.5), ([300.0, -40.0], 302.0)] {
            let span = Span { ea_n: DRAKE_EA, w_n_per_m: w, length_m: length, broken: None };
            let section = dead_end_span([0.0, 10.0], right, span);
            let sol = solve(&section).unwrap();
            let st = sol.spans[0];
            let fl = sol.supports[0].force_on_support_n;
            let fr = sol.supports[1].force_on_support_n;
            // total vertical reaction = w L: exact force balance, rounding only (1e-10 relative)
            let vertical = -(fl[1] + fr[1]);
            let rel_v = (vertical - w * length).abs() / (w * length);
            // end point by Gauss quadrature of the tangent: 5-point Gauss on 400 panels of 1 m has error
            // ~ (1 m / 2)^10 |f^(10)| / ..., far below rounding (1e-13 m over ~2000 evaluations): 1e-10 m
            let q = quadrature_offset(&section.spans[0], st.h_n, st.v_left_n);
            let err = ((q[0] - right[0]).abs()).max((q[1] - (right[1] - 10.0)).abs());
            println!(
                "test 1, elastic span to {right:?}, L = {length}: H = {:.9} N, V_left = {:.9} N, V_right = {:.9} N, \
                 vertical reaction rel err {rel_v:.2e}, quadrature closure error {err:.2e} m, sag {:.9} m, \
                 horizontal reactions {:.9} / {:.9} N",
                st.h_n,
                st.v_left_n,
                st.v_right_n,
                sol.sag(&section, 0),
                fl[0],
                fr[0]
            );
            assert!(rel_v < 1e-10);
            assert!(err < 1e-10);
            assert!((fl[0] + fr[0]).abs() < 1e-9);
        }

        // a taut span (unstretched length shorter than the chord) still converges, and matches quadrature
        let section = dead_end_span(
            [0.0, 0.0],
            [400.0, 0.0],
            Span { ea_n: DRAKE_EA, w_n_per_m: w, length_m: 399.8, broken: None },
        );
        let sol = solve(&section).unwrap();
        let q = quadrature_offset(&section.spans[0], sol.spans[0].h_n, sol.spans[0].v_left_n);
        println!("test 1, taut span L = 399.8 m: H = {:.6} N, closure by quadrature {q:?}", sol.spans[0].h_n);
        assert!((q[0] - 400.0).abs() < 1e-10 && q[1].abs() < 1e-10);
    }

    /// Test 2: three equal level spans strung at H0 stay plumb with H = H0.
    #[test]
    fn strung_level_section_is_plumb() {
        for stiffness in [f64::INFINITY, INS_EA] {
            let section = three_level_spans(INS_LEN, INS_MASS, stiffness);
            let sol = solve(&section).unwrap();
            print_solution(&format!("test 2, string stiffness {stiffness:e} N"), &section, &sol);
            // H: closure to 1e-11 m on spans of horizontal stiffness <= EA/l = 7.3e4 N/m gives 7e-7 N = 3e-11
            // relative; 1e-9 leaves a margin for the stringing's own closure
            for st in &sol.spans {
                assert!((st.h_n - H0).abs() / H0 < 1e-9, "H = {}", st.h_n);
            }
            for i in [1, 2] {
                let s = &sol.supports[i];
                // swing = (H_right - H_left)/T: 1e-6 N / 7e3 N, well below 1e-10 rad
                assert!(s.swing_rad.abs() < 1e-10, "swing {}", s.swing_rad);
                let expected =
                    0.5 * DRAKE_W * (section.spans[i - 1].length_m + section.spans[i].length_m) + INS_MASS * G;
                // vertical force balance to 1e-9 N of a 7e3 N tension, and V = wL/2 exactly by symmetry
                assert!(
                    (s.insulator_tension_n - expected).abs() / expected < 1e-9,
                    "T = {}, expected {expected}",
                    s.insulator_tension_n
                );
                println!("  support {i}: T_ins - (w (L_l + L_r)/2 + m g) = {:.3e} N", s.insulator_tension_n - expected);
            }
        }
    }

    /// Test 3: ice on the middle span.
    #[test]
    fn iced_middle_span_pulls_the_strings() {
        for stiffness in [INS_EA, f64::INFINITY] {
            let mut section = three_level_spans(INS_LEN, INS_MASS, stiffness);
            section.spans[1].w_n_per_m *= 2.0;
            let sol = solve(&section).unwrap();
            print_solution(
                &format!("test 3, middle span iced (w x 2), string stiffness {stiffness:e} N"),
                &section,
                &sol,
            );
            assert!(sol.supports[1].swing_rad > 0.0 && sol.supports[2].swing_rad < 0.0, "strings swing toward the ice");
            assert!(sol.spans[1].h_n > sol.spans[0].h_n);
            for i in [1, 2] {
                let f = clamp_imbalance(&section, &sol, i);
                println!("  clamp {i} imbalance [{:.3e}, {:.3e}] N", f[0], f[1]);
                // the Newton tolerance on the forces
                assert!(f[0].abs() < 1e-9 && f[1].abs() < 1e-9);
            }
            // symmetry of the section: equal and opposite swings (rounding of the Newton solution: force
            // residuals ~1e-11 N over T ~ 1e4 N, closures ~1e-13 m times 1e4 N/m over T; 1e-12 rad)
            assert!((sol.supports[1].swing_rad + sol.supports[2].swing_rad).abs() < 1e-12);
        }

        // rigid-support limit: strings of 1e-9 m without mass
        let tiny = 1e-9;
        let mut rigid = three_level_spans(tiny, 0.0, INS_EA);
        rigid.spans[1].w_n_per_m *= 2.0;
        let sol = solve(&rigid).unwrap();
        print_solution("test 3, rigid limit (strings 1e-9 m, massless)", &rigid, &sol);
        for k in 0..3 {
            // each span alone between the pivots; the clamps lie within ~1e-9 m of them, and a span's horizontal
            // stiffness is below EA/l = 7.3e4 N/m, so H moves by < 2 * 7.3e4 * 1e-9 N = 1.5e-4 N: 1e-8 relative
            let left = if k == 0 { [0.0, PIVOT_Z - tiny] } else { [k as f64 * SPAN, PIVOT_Z] };
            let right = if k == 2 { [3.0 * SPAN, PIVOT_Z - tiny] } else { [(k + 1) as f64 * SPAN, PIVOT_Z] };
            let alone = solve(&dead_end_span(left, right, rigid.spans[k])).unwrap();
            let rel = (alone.spans[0].h_n - sol.spans[k].h_n).abs() / alone.spans[0].h_n;
            println!(
                "  span {k}: H = {:.9} N, rigid span alone H = {:.9} N, rel {rel:.2e}",
                sol.spans[k].h_n, alone.spans[0].h_n
            );
            assert!(rel < 1e-8);
        }
        assert!(sol.spans[1].h_n > 1.01 * sol.spans[0].h_n, "H differs between spans with rigid supports");
    }

    /// Elastic crossarms: the displaced pivot carries the string's horizontal pull on its spring, and a
    /// section with rigid pivots placed at the displaced positions has the same equilibrium.
    #[test]
    fn elastic_crossarms_move_the_pivots() {
        let k_arm = 2.0e4;
        let mut section = three_level_spans(INS_LEN, INS_MASS, INS_EA);
        section.spans[1].w_n_per_m *= 2.0;
        let rigid = solve(&section).unwrap();
        for s in &mut section.supports {
            if let Support::Suspension { crossarm_n_per_m, .. } = s {
                *crossarm_n_per_m = k_arm;
            }
        }
        let sol = solve(&section).unwrap();
        print_solution("elastic crossarms (2e4 N/m), middle span iced", &section, &sol);
        let mut moved = section.clone();
        for i in [1, 2] {
            let st = sol.supports[i];
            let Support::Suspension { pivot, .. } = section.supports[i] else { panic!("not a suspension") };
            let d = st.pivot[0] - pivot[0];
            // spring balance: k d = T sin(theta) (the reference's force tolerance 1e-9 N)
            assert!((k_arm * d - st.force_on_support_n[0]).abs() < 1e-9, "support {i}");
            // the pivots move toward the iced span, which lets the strings swing less than on rigid arms
            assert!(d * rigid.supports[i].swing_rad > 0.0 && st.swing_rad.abs() < rigid.supports[i].swing_rad.abs());
            println!(
                "  support {i}: pivot moved {d:.6} m, swing {:.6} rad (rigid {:.6})",
                st.swing_rad, rigid.supports[i].swing_rad
            );
            if let Support::Suspension { pivot, crossarm_n_per_m, .. } = &mut moved.supports[i] {
                *pivot = st.pivot;
                *crossarm_n_per_m = f64::INFINITY;
            }
        }
        let same = solve(&moved).unwrap();
        for i in 0..4 {
            let (a, b) = (sol.supports[i].clamp, same.supports[i].clamp);
            // both solved to 1e-11 m closures and 1e-9 N forces
            assert!((a[0] - b[0]).abs() < 1e-9 && (a[1] - b[1]).abs() < 1e-9, "clamp {i}: {a:?} vs {b:?}");
        }
    }

    /// Test 4: broken middle span.
    #[test]
    fn broken_middle_span() {
        let intact = three_level_spans(INS_LEN, INS_MASS, INS_EA);
        let before = solve(&intact).unwrap();
        let mut section = intact.clone();
        section.spans[1].broken = Some(0.5);
        let sol = solve(&section).unwrap();
        print_solution("test 4, middle span broken at 0.5", &section, &sol);
        let ends = sol.broken_piece_ends(&section, 1).unwrap();
        println!("  broken piece lower ends: {ends:?}");
        assert!(
            sol.supports[1].swing_rad < 0.0 && sol.supports[2].swing_rad > 0.0,
            "strings swing away from the break"
        );
        let h = sol.spans[0].h_n;
        // residual static load on the dead-ends = H of the remaining span (exact force balance; 1e-9 N)
        assert!((sol.supports[0].force_on_support_n[0] - h).abs() < 1e-9);
        assert!((sol.supports[3].force_on_support_n[0] + sol.spans[2].h_n).abs() < 1e-9);
        // symmetric section: both remaining spans carry the same H (Newton tolerance, 1e-9 relative)
        assert!((sol.spans[2].h_n - h).abs() / h < 1e-9);
        for i in [1, 2] {
            let f = clamp_imbalance(&section, &sol, i);
            assert!(f[0].abs() < 1e-9 && f[1].abs() < 1e-9);
        }
        // independent: the span alone between its dead-end and the clamp found carries the same H (closure
        // tolerance 1e-11 m times the span's horizontal stiffness < 7.3e4 N/m: 1e-9 relative)
        let alone = solve(&dead_end_span(sol.supports[0].clamp, sol.supports[1].clamp, section.spans[0])).unwrap();
        assert!((alone.spans[0].h_n - h).abs() / h < 1e-9);
        let s = &sol.supports[1];
        println!(
            "  residual static load {:.6} N = {:.4} H0; clamp moved {:.6} m toward the dead-end; \
             sag {:.6} m -> {:.6} m; string tension {:.6} N, swing {:.4} deg",
            h,
            h / H0,
            before.supports[1].clamp[0] - s.clamp[0],
            before.sag(&intact, 0),
            sol.sag(&section, 0),
            s.insulator_tension_n,
            s.swing_rad.to_degrees()
        );
    }

    /// Test 5: an inclined section.
    #[test]
    fn inclined_section() {
        let supports = vec![
            Support::DeadEnd { point: [0.0, 20.0] },
            suspension(350.0, 45.0, INS_LEN, INS_MASS, INS_EA),
            suspension(770.0, 30.0, INS_LEN, INS_MASS, INS_EA),
            suspension(1150.0, 75.0, INS_LEN, INS_MASS, INS_EA),
            Support::DeadEnd { point: [1450.0, 50.0] },
        ];
        let section = string_section(supports, DRAKE_EA, DRAKE_W, H0, G).unwrap();
        let sol = solve(&section).unwrap();
        print_solution("test 5, inclined section strung at H0", &section, &sol);
        for (k, st) in sol.spans.iter().enumerate() {
            // as test 2
            assert!((st.h_n - H0).abs() / H0 < 1e-9);
            // closure by quadrature (see test 1): 1e-10 m
            let q = quadrature_offset(&section.spans[k], st.h_n, st.v_left_n);
            let d = [st.right_clamp[0] - st.left_clamp[0], st.right_clamp[1] - st.left_clamp[1]];
            assert!((q[0] - d[0]).abs() < 1e-10 && (q[1] - d[1]).abs() < 1e-10, "span {k}: {q:?} vs {d:?}");
            // sag: closed form against a brute-force maximum over 20001 points refined by golden section
            let chord = |p: [f64; 2]| st.left_clamp[1] + d[1] / d[0] * (p[0] - st.left_clamp[0]) - p[1];
            let l = section.spans[k].length_m;
            let best = (0..=20000).map(|i| l * i as f64 / 20000.0).fold(0.0, |b: f64, s| {
                if chord(sol.point(&section, k, s)) > chord(sol.point(&section, k, b)) { s } else { b }
            });
            let (mut a, mut b) = ((best - l / 20000.0).max(0.0), (best + l / 20000.0).min(l));
            let phi = 0.5 * (5f64.sqrt() - 1.0);
            for _ in 0..100 {
                let c = b - phi * (b - a);
                let e = a + phi * (b - a);
                if chord(sol.point(&section, k, c)) > chord(sol.point(&section, k, e)) { b = e } else { a = c }
            }
            let brute = chord(sol.point(&section, k, 0.5 * (a + b)));
            // a smooth maximum found to sqrt(eps) in s changes the value by ~eps: 1e-9 m
            println!("  span {k}: sag {:.9} m, brute force {brute:.9} m", sol.sag(&section, k));
            assert!((brute - sol.sag(&section, k)).abs() < 1e-9);
            // the material point s = L is the right clamp (closure tolerance 1e-11 m plus rounding)
            let end = sol.point(&section, k, l);
            assert!((end[0] - st.right_clamp[0]).abs() < 1e-10 && (end[1] - st.right_clamp[1]).abs() < 1e-10);
        }
        for i in 1..4 {
            assert!(sol.supports[i].swing_rad.abs() < 1e-10);
        }

        // ice (w x 1.5) on span 2: swings and global balance
        let mut iced = section.clone();
        iced.spans[2].w_n_per_m *= 1.5;
        let sol = solve(&iced).unwrap();
        print_solution("test 5, inclined section, span 2 iced (w x 1.5)", &iced, &sol);
        let weight: f64 = iced.spans.iter().map(|s| s.w_n_per_m * s.length_m).sum::<f64>() + 3.0 * INS_MASS * G;
        let total = sol
            .supports
            .iter()
            .fold([0.0, 0.0], |a, s| [a[0] + s.force_on_support_n[0], a[1] + s.force_on_support_n[1]]);
        println!("  sum of support forces [{:.3e}, {:.9}] N, total weight {weight:.9} N", total[0], total[1]);
        // global balance: sum of reactions = total weight (rounding of ~10 terms of 3e4 N: 1e-10 relative), the
        // horizontal ones cancel to the Newton tolerance (3 clamps x 1e-9 N)
        assert!((total[1] + weight).abs() / weight < 1e-10);
        assert!(total[0].abs() < 3e-9);
        assert!(sol.supports[2].swing_rad > 0.0 && sol.supports[3].swing_rad < 0.0, "strings swing toward the ice");
    }

    /// Ruling span against the exact section under ice on all spans.
    #[test]
    fn ruling_span_against_exact_section() {
        for lengths in [[400.0, 400.0, 400.0], [300.0, 400.0, 500.0]] {
            let mut x = 0.0;
            let mut supports = vec![Support::DeadEnd { point: [0.0, PIVOT_Z - INS_LEN] }];
            for l in &lengths[..2] {
                x += l;
                supports.push(suspension(x, PIVOT_Z, INS_LEN, INS_MASS, INS_EA));
            }
            supports.push(Support::DeadEnd { point: [x + lengths[2], PIVOT_Z - INS_LEN] });
            let mut section = string_section(supports, DRAKE_EA, DRAKE_W, H0, G).unwrap();
            for s in &mut section.spans {
                s.w_n_per_m *= 2.0;
            }
            let sol = solve(&section).unwrap();
            let ruling = ruling_span_tension(&lengths, DRAKE_EA, DRAKE_W, H0, 2.0 * DRAKE_W).unwrap();
            let hs: Vec<f64> = sol.spans.iter().map(|s| s.h_n).collect();
            println!(
                "ruling span, spans {lengths:?}, ice w x 2 on all: L_r = {:.6} m, H_ruling = {:.6} N, \
                 exact H = {hs:.6?} N, swings {:?} rad",
                ruling.length_m,
                ruling.h_n,
                sol.supports.iter().map(|s| s.swing_rad).collect::<Vec<_>>()
            );
            // the ruling-span method assumes strings that equalise H exactly; the exact section does not (its H
            // spread is the check's own scale), and its change-of-state equation neglects (w l/H)^2/24-order
            // terms (parabola, T = H), which cost 1.1e-3 relative on the equal spans: the ruling H must lie
            // within the exact spread widened by 2e-3 relative
            let (lo, hi) = hs.iter().fold((f64::INFINITY, 0.0_f64), |(a, b), h| (a.min(*h), b.max(*h)));
            println!(
                "  exact spread {:.3e} relative, ruling H - mean exact H = {:.3e} relative",
                (hi - lo) / lo,
                ruling.h_n / (hs.iter().sum::<f64>() / 3.0) - 1.0
            );
            assert!(ruling.h_n > lo * (1.0 - 2e-3) && ruling.h_n < hi * (1.0 + 2e-3));
        }
    }

    /// An insulator pushed up by the conductor is an error, not an equilibrium.
    #[test]
    fn slack_insulator_is_an_error() {
        // pull the middle pivots down below the dead-ends: the taut wire lifts the strings. At 150 m the smooth
        // extension of the string law has an equilibrium with compressed strings (reported as slack); at 100 m
        // it has none near plumb (the strings cannot take up the end spans' slack deficit) and the Newton
        // iteration fails, naming the least tensioned string
        for (depth, expect) in [(150.0, "slack"), (100.0, "uplift")] {
            let mut section = three_level_spans(INS_LEN, INS_MASS, INS_EA);
            for s in &mut section.supports[1..3] {
                if let Support::Suspension { pivot, .. } = s {
                    pivot[1] -= depth;
                }
            }
            let err = solve(&section).unwrap_err();
            println!("uplift, pivots {depth} m down: {err}");
            assert!(err.contains(expect));
        }
        // 40 m down is still an equilibrium with taut strings (T = 282 N)
        let mut section = three_level_spans(INS_LEN, INS_MASS, INS_EA);
        for s in &mut section.supports[1..3] {
            if let Support::Suspension { pivot, .. } = s {
                pivot[1] -= 40.0;
            }
        }
        let sol = solve(&section).unwrap();
        println!("pivots 40 m down: string tension {:.6} N", sol.supports[1].insulator_tension_n);
        assert!(sol.supports[1].insulator_tension_n > 0.0);
    }
}
