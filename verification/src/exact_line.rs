//! Independent exact references for the statics of multi-conductor lines in three dimensions: a bundle of
//! sub-conductors joined by spacers ([`solve_bundle`]), and several phases hung on one elastic tower top
//! ([`solve_shared_tower`]).
//!
//! Like [`crate::exact_section`], this module uses no solver code of the `ohl` crate (no `ohl::statics`,
//! `ohl::scheme`, `ohl::exact`), only `std`, `f64` and the closed-form catenary, the dense Gaussian
//! elimination and the damped Newton iteration of [`crate::exact_section`].
//!
//! # Coordinates, units and sign conventions (SI)
//!
//! `x1` \[m\] is horizontal **across** the line, `x2` \[m\] horizontal **along** the line, `x3` \[m\] vertical
//! **up**; gravity acts along `-x3`. Forces are in N, stiffnesses of springs in N/m, axial stiffnesses `EA` in
//! N, weights per length in N per *unstretched* metre.
//!
//! A conductor ("chain") runs from its start point (`s = 0`) to its end point (`s = S`); `s` \[m\] is the
//! unstretched arc coordinate, `S` the unstretched length. The **tension vector** `N(s)` \[N\] is the force
//! that the part of the chain beyond `s` exerts on the part `[0, s]`: `N = T t` with `T >= 0` the tension and
//! `t` the unit tangent toward increasing `s`. The force the chain applies to its start support is `N(0)`,
//! to its end support `-N(S)` (for a level span `N(0) = (H e, -V)`: the chain pulls the left support toward
//! the span and down).
//!
//! # The equations
//!
//! Free body of a piece of chain without point loads between `s_a` and `s`: `N(s) = N(s_a) + w (s - s_a) e3`.
//! A point load `P` \[N\] (a force **on** the chain) at `s_p` makes the tension vector jump:
//! `N(s_p+) = N(s_p-) - P`.
//!
//! Between point loads the horizontal part `N_h = (N1, N2)` is constant, so the piece lies in the vertical
//! plane through its start spanned by `e = N_h/H`, `H = |N_h| > 0`, and `e3`. In that plane the elastic
//! catenary (linear Hooke's law `dp/ds = 1 + T/EA`, `p` the stretched arc length) has the closed form of
//! [`crate::exact_section`] (Irvine's elastic catenary, evaluated without cancellation) with `V = -N3(s_a)`
//! (the upward force the start of the piece receives from what lies before it):
//!
//! ```text
//! r(s) = r(s_a) + x(s - s_a) e + z(s - s_a) e3
//! x(s) = H s/EA + (H/w) [asinh(V/H) - asinh((V - w s)/H)]
//! z(s) = -(V s - w s^2/2)/EA - (H/w) [sqrt(1 + (V/H)^2) - sqrt(1 + ((V - w s)/H)^2)]
//! ```
//!
//! The derivative of the end offset `o = x e + z e3` with respect to the tension vector `N(s_a)` (the 3x3
//! block used by the Newton Jacobians) follows from `dx/dH, dx/dV, dz/dH, dz/dV` of the plane closed form,
//! `dH/dN_h = e`, `de/dN_h = (I - e e^T)/H`, `dV/dN3 = -1`.
//!
//! ## Bundle ([`solve_bundle`])
//!
//! Sub-conductors `c = 0..n` and spacers at arc coordinates `s_1 < ... < s_m` (the same on every
//! sub-conductor; given in any order, sorted here). Each spacer carries a clamp on every sub-conductor, a
//! point weight `W` on every clamp, and links: linear two-way springs between the clamps `r_a`, `r_b` of two
//! sub-conductors, of tension `T_l = k (|r_b - r_a| - L0)` (negative in compression). A link pulls clamp `a`
//! with `f = T_l (r_b - r_a)/|r_b - r_a|` and clamp `b` with `-f`. The clamp load on sub-conductor `c` at
//! spacer `i` is `P_ci = -W e3 + sum of its link forces`.
//!
//! ## Shared tower ([`solve_shared_tower`])
//!
//! Phase `p`: span 0 from the fixed left dead-end `L_p` to the clamp `C_p`, span 1 from `C_p` to the fixed right
//! dead-end `R_p`. A suspension string joins the pivot `Q_p = tower rest point + u + pivot offset` to `C_p`,
//! `u = (u1, u2, 0)` the horizontal displacement of the rigid tower top. The string is a tension-only elastic
//! link: `T_s = EA_s max(|C - Q|/L_s - 1, 0)`; it pulls the pivot with `g = T_s (C - Q)/|C - Q|` and the clamp
//! with `-g`. The clamp also carries the point weight `W` (the string's mass), so
//! `N_1 = N_0 + w_0 S_0 e3 + W e3 + g` (tension vector at the start of span 1 from the one at the left
//! dead-end). The tower top is in balance horizontally: `k_across u1 = sum_p g_p1`, `k_along u2 = sum_p g_p2`;
//! its vertical reaction takes `sum_p g_p3`.
//!
//! # The method: shooting with the stiff elements' forces as unknowns
//!
//! Plain shooting from the left ends with the left-end tension vectors as the only unknowns, the link and
//! string forces computed from the positions reached, is **numerically unstable** here: a spring of stiffness
//! `k` turns a position error `e` at its clamp into a force error `k e`, which moves the end of the next bay
//! (length `l_b`, tension `H`) by `~ k e l_b/H`. For `k = 1e6 N/m`, `l_b = 75 m`, `H = 3e4 N` that is a factor
//! ~5e3 per bay (the differential mode of two sub-conductors), ~1e11 over three spacers: the rounding of one
//! clamp coordinate (~3e-14 m) becomes ~1e-3 m at the far end, and no closure near 1e-11 m can be met. A
//! `EA_s/L_s = 1.4e7 N/m` string does the same over one span (~1e5). The remedy used here keeps the shooting
//! but makes the stiff elements' **forces** unknowns, so that no force is ever computed from positions:
//!
//! * Bundle unknowns: per sub-conductor the tension vector `N_c(0)` at its start (3); per spacer and link its
//!   tension `T` and the two angles `(a, b)` of its direction `u = (cos b cos a, sin b, cos b sin a)` from clamp
//!   `a` to clamp `b` (`a` turns in the cross-section plane `x1, x3`, `b` toward the line direction `x2`, which
//!   a link never takes). The loads `P_ci` follow from the unknowns, the tension vector of bay `j` is
//!   `N_cj = N_c(0) + w_c s_j e3 - sum_{i < j} P_ci` (`s_j` the start of the bay), and every sub-conductor is
//!   integrated bay by bay from its start (its clamps `r_c(s_i)` and its end `r_c(S_c)`). Residuals \[m\]: each
//!   sub-conductor's end `r_c(S_c) - end_c` (3), and each link's compatibility
//!   `r_b(s_i) - r_a(s_i) - (L0 + T/k) u` (3): the link vector has the length of the spring law and the
//!   direction of the force. Angles as unknowns also keep a turning link from being stretched by a linearised
//!   rotation (which with `k = 1e6 N/m` would stall the Newton iteration when a partly iced bundle rolls).
//! * Tower unknowns: per phase `N_p(0)` (3) and the string force vector `g_p` (3: force on the pivot); the
//!   tower's `(u1, u2)`. The clamp follows from the string law, `C = Q + (L_s + |g| L_s/EA_s) g/|g|` (string
//!   tension `T_s = |g|`), and span 1 starts there with `N_1`. Residuals \[m\]: the closures of span 0
//!   (`L + o_0(N_0) - C`) and span 1 (`C + o_1(N_1) - R`), and the tower balances written as displacements,
//!   `u1 - sum_p g_p1 / k_across` and `u2 - sum_p g_p2 / k_along` (so that `k = f64::INFINITY`, a rigid tower, is
//!   allowed and gives `u = 0`). A string is taut by construction in this parametrisation: an equilibrium that
//!   needs a slack string (uplift) makes the iteration fail (`|g| -> 0`) and is reported as an error.
//!
//! Jacobian: analytic (the catenary block above, chained through the bays: a load changed at spacer `i` moves
//! the point at the end of bay `j > i` by `-(D_{i+1} + ... + D_j) dP`; a string's
//! `dC/dg = (L_s/EA_s) n n^T + (L_s/|g| + L_s/EA_s)(I - n n^T)`, `n = g/|g|`), checked against central
//! differences in the tests. Newton: the damped iteration of [`crate::exact_section`] (Gaussian elimination
//! with partial pivoting on the row-scaled Jacobian, Armijo backtracking on the scaled residual, up to two
//! polishing steps), converged when every residual is below `1e-11 m` (raised to `16 eps` times the
//! coordinate scale for very large coordinates).
//! Start: every conductor (every span 0) hung alone as a plain elastic catenary between its fixed ends; the
//! bundle's links unloaded and pointing along `(start_b - start_a) + (end_b - end_a)` (the spacer geometry at
//! the ends), each link angle changing by at most 0.5 rad per Newton step; the tower at `u = 0` with plumb
//! strings carrying half the adjacent span weights plus the clamp weight. If the bundle iteration fails from
//! there, it is repeated by continuation: first in the load (every sub-conductor at the mean weight, then the
//! weights moved to their values in steps of 1/8), then in the link stiffnesses (factor 1e-6 to 1 in steps of
//! one decade); a failed step is halved (down to 1/64 of the step). In the tests every case converges directly
//! (7-13 iterations). Non-convergence is returned as an `Err`, never a panic.

use crate::exact_section::{Catenary, NewtonFailure, NewtonOutcome, damped_newton, length_tol, solve_span};

type V3 = [f64; 3];
type M3 = [[f64; 3]; 3];

/// Largest change of a link angle in one Newton step \[rad\].
const MAX_ANGLE_STEP_RAD: f64 = 0.5;

fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn norm(a: V3) -> f64 {
    a[0].hypot(a[1]).hypot(a[2])
}

fn mat_mul(a: &M3, b: &M3) -> M3 {
    let mut m = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            m[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
        }
    }
    m
}

fn get3(x: &[f64], i: usize) -> V3 {
    [x[i], x[i + 1], x[i + 2]]
}

fn set3(x: &mut [f64], i: usize, v: V3) {
    x[i..i + 3].copy_from_slice(&v);
}

/// Adds `factor * block` to the 3x3 block of the row-major `n x n` matrix `jac` at `(row, col)`.
fn add_block(jac: &mut [f64], n: usize, row: usize, col: usize, block: &M3, factor: f64) {
    for i in 0..3 {
        for j in 0..3 {
            jac[(row + i) * n + col + j] += factor * block[i][j];
        }
    }
}

/// The end offset `o = x e + z e3` \[m\] of a piece of unstretched length `len` whose tension vector at its start
/// is `n`; `None` when the piece has no horizontal tension (`H = 0`: the plane is undefined) or `n` is not finite.
fn piece_offset(cat: Catenary, n: V3, len: f64) -> Option<V3> {
    let h = n[0].hypot(n[1]);
    if !(h > 0.0 && h.is_finite() && n[2].is_finite()) {
        return None;
    }
    let [x, z] = cat.offset(h, -n[2], len);
    Some([x * n[0] / h, x * n[1] / h, z])
}

/// `d o / d n` (row = component of `o`, column = component of `n`) for [`piece_offset`].
fn piece_jacobian(cat: Catenary, n: V3, len: f64) -> M3 {
    let h = n[0].hypot(n[1]);
    let e = [n[0] / h, n[1] / h];
    let x = cat.offset(h, -n[2], len)[0];
    let j = cat.jacobian(h, -n[2], len);
    let mut d = [[0.0; 3]; 3];
    for a in 0..2 {
        for b in 0..2 {
            let delta = if a == b { 1.0 } else { 0.0 };
            d[a][b] = j[0][0] * e[a] * e[b] + x / h * (delta - e[a] * e[b]);
        }
        d[a][2] = -j[0][1] * e[a];
        d[2][a] = j[1][0] * e[a];
    }
    d[2][2] = -j[1][1];
    d
}

/// The tension vector `N(0)` \[N\] of a lone elastic catenary of unstretched length `length` from `from` to `to`.
fn lone_span(cat: Catenary, length: f64, from: V3, to: V3) -> Result<V3, String> {
    let dh = [to[0] - from[0], to[1] - from[1]];
    let hl = dh[0].hypot(dh[1]);
    if hl == 0.0 || !hl.is_finite() {
        return Err(format!("the ends {from:?} and {to:?} lie on one vertical: no catenary plane"));
    }
    let (h, v) = solve_span(cat, length, [hl, to[2] - from[2]])?;
    Ok([h * dh[0] / hl, h * dh[1] / hl, -v])
}

fn check_positive(what: &str, value: f64, allow_infinite: bool) -> Result<(), String> {
    if value > 0.0 && (allow_infinite || value.is_finite()) {
        Ok(())
    } else {
        Err(format!("{what} must be positive{}, got {value}", if allow_infinite { "" } else { " and finite" }))
    }
}

fn check_non_negative(what: &str, value: f64) -> Result<(), String> {
    if value >= 0.0 && value.is_finite() { Ok(()) } else { Err(format!("{what} must be >= 0 and finite, got {value}")) }
}

fn check_point(what: &str, p: V3) -> Result<(), String> {
    if p.iter().all(|c| c.is_finite()) { Ok(()) } else { Err(format!("{what} must be finite, got {p:?}")) }
}

// ------------------------------------------------------------------------------------------------------------
// Problem 1: a bundle with spacers
// ------------------------------------------------------------------------------------------------------------

/// One sub-conductor of a bundle: an elastic catenary between two fixed points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Chain {
    /// fixed point at `s = 0` \[m\]
    pub start_m: [f64; 3],
    /// fixed point at `s = S` \[m\]
    pub end_m: [f64; 3],
    /// unstretched length `S` \[m\]
    pub unstretched_length_m: f64,
    /// axial stiffness `EA` \[N\] (`f64::INFINITY` = inextensible)
    pub axial_stiffness_n: f64,
    /// weight per unstretched metre \[N/m\] (ice included)
    pub weight_n_per_m: f64,
}

/// A linear two-way spring (tension AND compression) between the clamps of sub-conductors `a` and `b` at one
/// spacer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpacerLink {
    /// first sub-conductor (index into [`Bundle::chains`])
    pub a: usize,
    /// second sub-conductor
    pub b: usize,
    /// length at zero force \[m\]
    pub rest_length_m: f64,
    /// stiffness \[N/m\]
    pub stiffness_n_per_m: f64,
}

/// A spacer at unstretched arc coordinate `s_m` (the same on every sub-conductor); `clamp_weight_n` \[N\] is a
/// point weight at each sub-conductor's clamp (the spacer's weight divided by the number of clamps).
#[derive(Debug, Clone, PartialEq)]
pub struct Spacer {
    /// unstretched arc coordinate of the clamps \[m\], `0 < s_m < S` of every sub-conductor
    pub s_m: f64,
    /// the springs between the clamps
    pub links: Vec<SpacerLink>,
    /// point weight on every clamp \[N\]
    pub clamp_weight_n: f64,
}

/// A bundle: sub-conductors and spacers (spacers in any order of `s_m`, at distinct `s_m`).
#[derive(Debug, Clone, PartialEq)]
pub struct Bundle {
    /// the sub-conductors
    pub chains: Vec<Chain>,
    /// the spacers
    pub spacers: Vec<Spacer>,
}

/// Equilibrium of a [`Bundle`].
#[derive(Debug, Clone, PartialEq)]
pub struct BundleSolution {
    /// spacer indices in increasing `s_m` (bay `j > 0` starts at spacer `order[j - 1]`)
    order: Vec<usize>,
    /// per chain, per bay: tension vector at the start of the bay \[N\]
    bay_tension: Vec<Vec<V3>>,
    /// per chain, per sorted spacer: clamp position \[m\]
    clamps: Vec<Vec<V3>>,
    /// per spacer (input order), per link: tension \[N\]
    link_tensions: Vec<Vec<f64>>,
    /// per chain: force on the start support, force on the end support \[N\]
    end_forces: Vec<[V3; 2]>,
    /// Newton iterations (summed over continuation stages)
    iterations: usize,
}

/// Spacers sorted by `s` and the layout of the Newton vector.
struct BundleLayout {
    order: Vec<usize>,
    /// sorted spacer arc coordinates
    s: Vec<f64>,
    nc: usize,
    ns: usize,
    /// index of the first link unknown of every sorted spacer (then 3 per link)
    link_start: Vec<usize>,
    /// number of unknowns
    n: usize,
}

impl BundleLayout {
    /// `[start, end)` arc coordinates of bay `j` of a chain of length `total`
    fn bay(&self, j: usize, total: f64) -> (f64, f64) {
        (if j == 0 { 0.0 } else { self.s[j - 1] }, if j == self.ns { total } else { self.s[j] })
    }
}

/// Unit vector `(cos b cos a, sin b, cos b sin a)` of the link angles `a` (in the cross-section plane `x1, x3`,
/// from `x1` toward `x3`) and `b` (toward `x2`, along the line), with its derivatives by `a` and `b`.
fn link_direction(a: f64, b: f64) -> (V3, V3, V3) {
    let (sa, ca) = a.sin_cos();
    let (sb, cb) = b.sin_cos();
    ([cb * ca, sb, cb * sa], [-cb * sa, 0.0, cb * ca], [-sb * ca, cb, -sb * sa])
}

/// The angles `(a, b)` of the direction of `d` (see [`link_direction`]).
fn link_angles(d: V3) -> (f64, f64) {
    (d[2].atan2(d[0]), (d[1] / norm(d)).asin())
}

/// One link at the unknowns: tension `T`, direction `u` and its derivatives, link vector `d = (L0 + T/k) u`.
struct LinkState {
    t: f64,
    u: V3,
    ua: V3,
    ub: V3,
    /// `L0 + T/k`
    length: f64,
    /// `1/k`
    compliance: f64,
}

/// Everything the residual and the Jacobian of a bundle need at the unknowns `x`.
struct BundleState {
    /// per sorted spacer, per link
    links: Vec<Vec<LinkState>>,
    /// per chain, per bay: tension vector at the start of the bay
    tensions: Vec<Vec<V3>>,
    /// per chain: the clamps (per sorted spacer) and then the far end, integrated from the start
    points: Vec<Vec<V3>>,
}

fn chain_catenary(ch: &Chain) -> Catenary {
    Catenary { ea: ch.axial_stiffness_n, w: ch.weight_n_per_m }
}

/// The state at `x`, the link stiffnesses multiplied by `link_factor`; `None` where a piece loses its horizontal
/// tension, a link's length `L0 + T/k` is not positive, or a value is not finite.
fn bundle_state(b: &Bundle, lay: &BundleLayout, x: &[f64], link_factor: f64) -> Option<BundleState> {
    let mut links = Vec::with_capacity(lay.ns);
    let mut loads = Vec::with_capacity(lay.ns);
    for (i, &sp) in lay.order.iter().enumerate() {
        let spacer = &b.spacers[sp];
        let mut p = vec![[0.0, 0.0, -spacer.clamp_weight_n]; lay.nc];
        let mut states = Vec::with_capacity(spacer.links.len());
        for (l, link) in spacer.links.iter().enumerate() {
            let q = get3(x, lay.link_start[i] + 3 * l);
            let (u, ua, ub) = link_direction(q[1], q[2]);
            let compliance = 1.0 / (link_factor * link.stiffness_n_per_m);
            let length = link.rest_length_m + q[0] * compliance;
            if !(length > 0.0 && length.is_finite() && q[0].is_finite()) {
                return None;
            }
            let f = [q[0] * u[0], q[0] * u[1], q[0] * u[2]];
            p[link.a] = add(p[link.a], f);
            p[link.b] = sub(p[link.b], f);
            states.push(LinkState { t: q[0], u, ua, ub, length, compliance });
        }
        links.push(states);
        loads.push(p);
    }
    let mut tensions = Vec::with_capacity(lay.nc);
    let mut points = Vec::with_capacity(lay.nc);
    for (c, ch) in b.chains.iter().enumerate() {
        let cat = chain_catenary(ch);
        let mut n = get3(x, 3 * c);
        let mut r = ch.start_m;
        let mut t = Vec::with_capacity(lay.ns + 1);
        let mut pts = Vec::with_capacity(lay.ns + 1);
        for j in 0..=lay.ns {
            if j > 0 {
                let ds = lay.s[j - 1] - if j == 1 { 0.0 } else { lay.s[j - 2] };
                let p = loads[j - 1][c];
                n = [n[0] - p[0], n[1] - p[1], n[2] + ch.weight_n_per_m * ds - p[2]];
            }
            let (s0, s1) = lay.bay(j, ch.unstretched_length_m);
            r = add(r, piece_offset(cat, n, s1 - s0)?);
            t.push(n);
            pts.push(r);
        }
        tensions.push(t);
        points.push(pts);
    }
    Some(BundleState { links, tensions, points })
}

fn bundle_residual(b: &Bundle, lay: &BundleLayout, x: &[f64], link_factor: f64) -> Option<Vec<f64>> {
    let st = bundle_state(b, lay, x, link_factor)?;
    let mut r = vec![0.0; lay.n];
    for (c, ch) in b.chains.iter().enumerate() {
        set3(&mut r, 3 * c, sub(st.points[c][lay.ns], ch.end_m));
    }
    for (i, &sp) in lay.order.iter().enumerate() {
        for (l, (link, ls)) in b.spacers[sp].links.iter().zip(&st.links[i]).enumerate() {
            let d = sub(st.points[link.b][i], st.points[link.a][i]);
            let e = [d[0] - ls.length * ls.u[0], d[1] - ls.length * ls.u[1], d[2] - ls.length * ls.u[2]];
            set3(&mut r, lay.link_start[i] + 3 * l, e);
        }
    }
    Some(r)
}

fn mat_add(a: &M3, b: &M3) -> M3 {
    let mut m = *a;
    for i in 0..3 {
        for j in 0..3 {
            m[i][j] += b[i][j];
        }
    }
    m
}

fn mat_sub(a: &M3, b: &M3) -> M3 {
    let mut m = *a;
    for i in 0..3 {
        for j in 0..3 {
            m[i][j] -= b[i][j];
        }
    }
    m
}

fn bundle_jacobian(b: &Bundle, lay: &BundleLayout, x: &[f64], link_factor: f64) -> Vec<f64> {
    let n = lay.n;
    let mut jac = vec![0.0; n * n];
    let Some(st) = bundle_state(b, lay, x, link_factor) else { return jac };
    // prefix[c][i] = sum_{j <= i} D_cj: d r_c(end of bay i) / d N_c(0); a load changed at spacer i' moves the point
    // at the end of bay i > i' by -(prefix[i] - prefix[i']) dP
    let prefix: Vec<Vec<M3>> = b
        .chains
        .iter()
        .enumerate()
        .map(|(c, ch)| {
            let cat = chain_catenary(ch);
            let mut acc = [[0.0; 3]; 3];
            (0..=lay.ns)
                .map(|j| {
                    let (s0, s1) = lay.bay(j, ch.unstretched_length_m);
                    acc = mat_add(&acc, &piece_jacobian(cat, st.tensions[c][j], s1 - s0));
                    acc
                })
                .collect()
        })
        .collect();
    // d P / d (T, a, b) of a link at its clamp `a` (columns); at clamp `b` the opposite
    let load_block = |ls: &LinkState| -> M3 {
        let mut m = [[0.0; 3]; 3];
        for k in 0..3 {
            m[k] = [ls.u[k], ls.t * ls.ua[k], ls.t * ls.ub[k]];
        }
        m
    };
    // adds to row block `row` the derivative of r_c(end of bay i) by every unknown, times `sign`
    let point_derivative = |jac: &mut [f64], row: usize, c: usize, i: usize, sign: f64| {
        add_block(jac, n, row, 3 * c, &prefix[c][i], sign);
        for i2 in 0..i.min(lay.ns) {
            let moved = mat_sub(&prefix[c][i], &prefix[c][i2]);
            for (l2, (link2, ls2)) in b.spacers[lay.order[i2]].links.iter().zip(&st.links[i2]).enumerate() {
                let at = if c == link2.a {
                    1.0
                } else if c == link2.b {
                    -1.0
                } else {
                    continue;
                };
                let block = mat_mul(&moved, &load_block(ls2));
                add_block(jac, n, row, lay.link_start[i2] + 3 * l2, &block, -sign * at);
            }
        }
    };
    for c in 0..lay.nc {
        point_derivative(&mut jac, 3 * c, c, lay.ns, 1.0);
    }
    for (i, &sp) in lay.order.iter().enumerate() {
        for (l, (link, ls)) in b.spacers[sp].links.iter().zip(&st.links[i]).enumerate() {
            let row = lay.link_start[i] + 3 * l;
            point_derivative(&mut jac, row, link.b, i, 1.0);
            point_derivative(&mut jac, row, link.a, i, -1.0);
            let mut own = [[0.0; 3]; 3];
            for k in 0..3 {
                own[k] = [ls.compliance * ls.u[k], ls.length * ls.ua[k], ls.length * ls.ub[k]];
            }
            add_block(&mut jac, n, row, row, &own, -1.0);
        }
    }
    jac
}

fn validate_bundle(b: &Bundle) -> Result<(), String> {
    if b.chains.is_empty() {
        return Err("a bundle needs at least one sub-conductor".into());
    }
    let mut shortest = f64::INFINITY;
    for (c, ch) in b.chains.iter().enumerate() {
        check_point(&format!("start of chain {c}"), ch.start_m)?;
        check_point(&format!("end of chain {c}"), ch.end_m)?;
        check_positive(&format!("unstretched length of chain {c}"), ch.unstretched_length_m, false)?;
        check_positive(&format!("EA of chain {c}"), ch.axial_stiffness_n, true)?;
        check_positive(&format!("weight of chain {c}"), ch.weight_n_per_m, false)?;
        shortest = shortest.min(ch.unstretched_length_m);
    }
    for (i, sp) in b.spacers.iter().enumerate() {
        if !(sp.s_m > 0.0 && sp.s_m < shortest) {
            return Err(format!("spacer {i}: s = {} must lie strictly inside (0, {shortest})", sp.s_m));
        }
        check_non_negative(&format!("clamp weight of spacer {i}"), sp.clamp_weight_n)?;
        for (l, link) in sp.links.iter().enumerate() {
            if link.a >= b.chains.len() || link.b >= b.chains.len() || link.a == link.b {
                return Err(format!("spacer {i}, link {l}: sub-conductors {} and {} invalid", link.a, link.b));
            }
            check_non_negative(&format!("rest length of spacer {i}, link {l}"), link.rest_length_m)?;
            check_positive(&format!("stiffness of spacer {i}, link {l}"), link.stiffness_n_per_m, false)?;
        }
    }
    Ok(())
}

fn bundle_layout(b: &Bundle) -> Result<BundleLayout, String> {
    let mut order: Vec<usize> = (0..b.spacers.len()).collect();
    order.sort_by(|&i, &j| b.spacers[i].s_m.total_cmp(&b.spacers[j].s_m));
    let s: Vec<f64> = order.iter().map(|&i| b.spacers[i].s_m).collect();
    if let Some(w) = s.windows(2).find(|w| w[1] <= w[0]) {
        return Err(format!("two spacers at the same arc coordinate s = {}", w[0]));
    }
    let mut n = 3 * b.chains.len();
    let link_start = order
        .iter()
        .map(|&i| {
            n += 3 * b.spacers[i].links.len();
            n - 3 * b.spacers[i].links.len()
        })
        .collect();
    Ok(BundleLayout { order, s, nc: b.chains.len(), ns: b.spacers.len(), link_start, n })
}

/// Starting guess and the coordinate scale \[m\]: every chain a lone catenary between its ends, every link
/// unloaded (`T = 0`) and pointing as the bundle does at its ends: along `(start_b - start_a) + (end_b - end_a)`
/// (the spacer geometry; the lone catenaries' clamps are a poor guess of it when the sub-conductors' weights
/// differ), or, if that vanishes, from the lone catenary's clamp `a` to its clamp `b`.
fn bundle_start(b: &Bundle, lay: &BundleLayout) -> Result<(Vec<f64>, f64), String> {
    let mut x0 = vec![0.0; lay.n];
    let mut coord_scale: f64 = 0.0;
    let mut clamps = Vec::with_capacity(lay.nc);
    for (c, ch) in b.chains.iter().enumerate() {
        let cat = chain_catenary(ch);
        let n0 = lone_span(cat, ch.unstretched_length_m, ch.start_m, ch.end_m)
            .map_err(|e| format!("starting guess of chain {c}: {e}"))?;
        set3(&mut x0, 3 * c, n0);
        let mut pts = Vec::with_capacity(lay.ns);
        for i in 0..lay.ns {
            let o =
                piece_offset(cat, n0, lay.s[i]).ok_or("starting guess: lone catenary without horizontal tension")?;
            pts.push(add(ch.start_m, o));
        }
        clamps.push(pts);
        let l1 = |p: V3| p[0].abs() + p[1].abs() + p[2].abs();
        coord_scale = coord_scale.max(l1(ch.start_m)).max(l1(ch.end_m) + ch.unstretched_length_m);
    }
    for (i, &sp) in lay.order.iter().enumerate() {
        for (l, link) in b.spacers[sp].links.iter().enumerate() {
            let (ca, cb) = (&b.chains[link.a], &b.chains[link.b]);
            let mut d = add(sub(cb.start_m, ca.start_m), sub(cb.end_m, ca.end_m));
            if norm(d) == 0.0 {
                d = sub(clamps[link.b][i], clamps[link.a][i]);
            }
            if norm(d) == 0.0 {
                return Err(format!("spacer {sp}, link {l}: its two sub-conductors coincide"));
            }
            let (a, bb) = link_angles(d);
            set3(&mut x0, lay.link_start[i] + 3 * l, [0.0, a, bb]);
        }
    }
    Ok((x0, coord_scale))
}

/// The bundle with every sub-conductor's weight `w_mean + t (w_c - w_mean)` (`t = 0`: all at the mean weight).
fn equal_weights(b: &Bundle, t: f64) -> Bundle {
    let mean = b.chains.iter().map(|c| c.weight_n_per_m).sum::<f64>() / b.chains.len() as f64;
    let mut staged = b.clone();
    for ch in &mut staged.chains {
        ch.weight_n_per_m = mean + t * (ch.weight_n_per_m - mean);
    }
    staged
}

/// Follows a solution `x` of the problem at parameter 0 to parameter 1: steps of `first`, halved after a
/// failure (down to `first / 64`), doubled again (up to `first`) after a success.
fn follow(
    mut x: Vec<f64>,
    first: f64,
    solve_at: impl Fn(Vec<f64>, f64) -> Result<NewtonOutcome, NewtonFailure>,
) -> Result<NewtonOutcome, String> {
    let (mut p, mut step, mut iterations) = (0.0_f64, first, 0);
    while p < 1.0 {
        let target = (p + step).min(1.0);
        match solve_at(x.clone(), target) {
            Ok(stage) => {
                x = stage.x;
                iterations += stage.iterations;
                p = target;
                step = (2.0 * step).min(first);
            }
            Err(_) if step > first / 64.0 => step *= 0.5,
            Err(f) => return Err(format!("failed at parameter {target:.4}: {}", f.message)),
        }
    }
    Ok(NewtonOutcome { x, iterations })
}

/// Static equilibrium of a bundle of sub-conductors with spacers (see the module doc for the model and the
/// method). Errors: invalid input, or no convergence of the Newton iteration (also after continuation).
pub fn solve_bundle(b: &Bundle) -> Result<BundleSolution, String> {
    validate_bundle(b)?;
    let lay = bundle_layout(b)?;
    let (x0, coord_scale) = bundle_start(b, &lay)?;
    let (x_equal, _) = bundle_start(&equal_weights(b, 0.0), &lay)?;
    let tol = vec![length_tol(coord_scale); lay.n];
    // a link's direction may turn by at most 0.5 rad per Newton step
    let mut max_step = vec![f64::INFINITY; lay.n];
    for (i, &sp) in lay.order.iter().enumerate() {
        for l in 0..b.spacers[sp].links.len() {
            max_step[lay.link_start[i] + 3 * l + 1] = MAX_ANGLE_STEP_RAD;
            max_step[lay.link_start[i] + 3 * l + 2] = MAX_ANGLE_STEP_RAD;
        }
    }
    // the problem at link stiffness factor `k` and load factor `t`
    let run = |x: Vec<f64>, k: f64, t: f64| {
        let staged = if t < 1.0 { equal_weights(b, t) } else { b.clone() };
        damped_newton(
            x,
            &tol,
            &max_step,
            |x| bundle_residual(&staged, &lay, x, k),
            |x| bundle_jacobian(&staged, &lay, x, k),
        )
    };
    let out: NewtonOutcome = match run(x0.clone(), 1.0, 1.0) {
        Ok(out) => out,
        Err(direct) => {
            // load continuation from equal weights, then stiffness continuation (log scale, 1e-6 -> 1)
            let by_load = run(x_equal, 1.0, 0.0).map_err(|f| format!("equal weights: {}", f.message)).and_then(|eq| {
                let more = follow(eq.x, 0.125, |x, t| run(x, 1.0, t))
                    .map_err(|e| format!("load continuation from equal weights {e}"))?;
                Ok(NewtonOutcome { x: more.x, iterations: eq.iterations + more.iterations })
            });
            match by_load {
                Ok(out) => out,
                Err(load_message) => {
                    let soft = run(x0, 1e-6, 1.0).map_err(|f| {
                        format!(
                            "bundle: no equilibrium found (direct: {}; {load_message}; link stiffness factor 1e-6: {})",
                            direct.message, f.message
                        )
                    })?;
                    let more =
                        follow(soft.x, 1.0 / 6.0, |x, p| run(x, 10f64.powf(6.0 * (p - 1.0)), 1.0)).map_err(|e| {
                            format!(
                                "bundle: no equilibrium found (direct: {}; {load_message}; link stiffness \
                                 continuation {e})",
                                direct.message
                            )
                        })?;
                    NewtonOutcome { x: more.x, iterations: soft.iterations + more.iterations }
                }
            }
        }
    };
    let x = out.x;
    let st = bundle_state(b, &lay, &x, 1.0).ok_or("bundle: degenerate state at the equilibrium found")?;
    let mut end_forces = Vec::with_capacity(lay.nc);
    for (c, ch) in b.chains.iter().enumerate() {
        let last = st.tensions[c][lay.ns];
        let (s0, s1) = lay.bay(lay.ns, ch.unstretched_length_m);
        end_forces.push([st.tensions[c][0], [-last[0], -last[1], -(last[2] + ch.weight_n_per_m * (s1 - s0))]]);
    }
    let mut link_tensions = vec![Vec::new(); b.spacers.len()];
    for (i, &sp) in lay.order.iter().enumerate() {
        link_tensions[sp] = st.links[i].iter().map(|ls| ls.t).collect();
    }
    let clamps = st.points.iter().map(|p| p[..lay.ns].to_vec()).collect();
    Ok(BundleSolution {
        order: lay.order,
        bay_tension: st.tensions,
        clamps,
        link_tensions,
        end_forces,
        iterations: out.iterations,
    })
}

impl BundleSolution {
    /// Bay of `s` (the number of spacers at or before `s`) and its start arc coordinate.
    fn bay_of(&self, b: &Bundle, s_m: f64) -> (usize, f64) {
        let j = self.order.iter().take_while(|&&i| b.spacers[i].s_m <= s_m).count();
        (j, if j == 0 { 0.0 } else { b.spacers[self.order[j - 1]].s_m })
    }

    /// Point \[m\] of sub-conductor `chain` at unstretched arc coordinate `s_m` \[m\] (`0 <= s_m <= S`; at a
    /// spacer's `s` it is that clamp). Computed from the start of the bay containing `s_m` by the closed form.
    pub fn position(&self, b: &Bundle, chain: usize, s_m: f64) -> [f64; 3] {
        let ch = &b.chains[chain];
        let (j, s0) = self.bay_of(b, s_m);
        let from = if j == 0 { ch.start_m } else { self.clamps[chain][j - 1] };
        piece_offset(chain_catenary(ch), self.bay_tension[chain][j], s_m - s0).map_or([f64::NAN; 3], |o| add(from, o))
    }

    /// Tension `k (|r_b - r_a| - L0)` \[N\] of link `link` of spacer `spacer` (input indices), positive in tension.
    pub fn link_tension_n(&self, spacer: usize, link: usize) -> f64 {
        self.link_tensions[spacer][link]
    }

    /// Forces \[N\] the sub-conductor `chain` applies to its start support (`N(0)`) and to its end support
    /// (`-N(S)`).
    pub fn end_forces_n(&self, chain: usize) -> [[f64; 3]; 2] {
        self.end_forces[chain]
    }

    /// Clamp position \[m\] of sub-conductor `chain` at spacer `spacer` (input index).
    pub fn clamp_m(&self, spacer: usize, chain: usize) -> [f64; 3] {
        let i = self.order.iter().position(|&k| k == spacer).expect("spacer index out of range");
        self.clamps[chain][i]
    }

    /// Tension vector `N(s)` \[N\] of sub-conductor `chain` (the force the part beyond `s` exerts on `[0, s]`);
    /// at a spacer's `s` the value just after the clamp.
    pub fn tension_vector_n(&self, b: &Bundle, chain: usize, s_m: f64) -> [f64; 3] {
        let (j, s0) = self.bay_of(b, s_m);
        let n = self.bay_tension[chain][j];
        [n[0], n[1], n[2] + b.chains[chain].weight_n_per_m * (s_m - s0)]
    }

    /// Newton iterations taken.
    pub fn iterations(&self) -> usize {
        self.iterations
    }
}

// ------------------------------------------------------------------------------------------------------------
// Problem 2: phases on one shared elastic tower top
// ------------------------------------------------------------------------------------------------------------

/// One span of a phase.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpanLoad {
    /// unstretched length \[m\]
    pub unstretched_length_m: f64,
    /// axial stiffness `EA` \[N\] (`f64::INFINITY` = inextensible)
    pub axial_stiffness_n: f64,
    /// weight per unstretched metre \[N/m\] (ice included)
    pub weight_n_per_m: f64,
}

/// One phase: a two-span section from a fixed left dead-end through a suspension string at the middle tower
/// to a fixed right dead-end.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TowerPhase {
    /// left dead-end point (`s = 0` of span 0) \[m\]
    pub left_m: [f64; 3],
    /// right dead-end point (`s = S` of span 1) \[m\]
    pub right_m: [f64; 3],
    /// span 0 (left dead-end to clamp) and span 1 (clamp to right dead-end)
    pub spans: [SpanLoad; 2],
    /// pivot of the string relative to the tower's reference point \[m\]
    pub pivot_offset_m: [f64; 3],
    /// unstretched string length \[m\]
    pub string_length_m: f64,
    /// string axial stiffness `EA_s` \[N\] (finite)
    pub string_stiffness_n: f64,
    /// point weight at the clamp (the string's weight) \[N\]
    pub clamp_weight_n: f64,
}

/// The tower top: a rigid body that moves horizontally only, its reference point at rest at `rest_m`; pivot of
/// phase `p` = tower position + `pivot_offset_m`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tower {
    /// reference point at rest \[m\]
    pub rest_m: [f64; 3],
    /// spring along `x2` \[N/m\] (`f64::INFINITY` = rigid)
    pub along_n_per_m: f64,
    /// spring across `x1` \[N/m\] (`f64::INFINITY` = rigid)
    pub across_n_per_m: f64,
}

/// Equilibrium of phases on a shared tower ([`solve_shared_tower`]).
#[derive(Debug, Clone, PartialEq)]
pub struct TowerSolution {
    /// tower displacement `(u1, u2)` \[m\]
    u: [f64; 2],
    /// per phase: tension vectors at the start of span 0 and of span 1 \[N\]
    tension: Vec<[V3; 2]>,
    /// per phase: clamp \[m\]
    clamps: Vec<V3>,
    /// per phase: string tension \[N\]
    string_tension: Vec<f64>,
    /// per phase: force of the string on the pivot \[N\]
    pivot_forces: Vec<V3>,
    /// per phase: forces on the left and right dead-ends \[N\]
    dead_end_forces: Vec<[V3; 2]>,
    /// Newton iterations
    iterations: usize,
}

/// The state of one phase at the unknowns `x`.
struct PhaseState {
    n0: V3,
    n1: V3,
    clamp: V3,
    /// force of the string on the pivot (an unknown)
    g: V3,
    tension: f64,
    /// `dC/dg`
    a: M3,
}

fn span_catenary(s: &SpanLoad) -> Catenary {
    Catenary { ea: s.axial_stiffness_n, w: s.weight_n_per_m }
}

fn tower_u(x: &[f64], np: usize) -> V3 {
    [x[6 * np], x[6 * np + 1], 0.0]
}

/// The phases' states at the unknowns `x`; `None` where a string force vanishes (a slack string has no
/// direction in this parametrisation) or is not finite.
fn phase_states(phases: &[TowerPhase], tower: &Tower, x: &[f64]) -> Option<Vec<PhaseState>> {
    let u = tower_u(x, phases.len());
    phases
        .iter()
        .enumerate()
        .map(|(p, ph)| {
            let n0 = get3(x, 6 * p);
            let g = get3(x, 6 * p + 3);
            let t = norm(g);
            if !(t > 0.0 && t.is_finite()) {
                return None;
            }
            // C - Q = (L_s + T L_s/EA_s) g/T: the string's stretched length along the direction of g
            let (stretch, inv_k) = (ph.string_length_m / t, ph.string_length_m / ph.string_stiffness_n);
            let c = stretch + inv_k;
            let pivot = add(add(tower.rest_m, u), ph.pivot_offset_m);
            let clamp = add(pivot, [c * g[0], c * g[1], c * g[2]]);
            let mut a = [[0.0; 3]; 3];
            for i in 0..3 {
                for j in 0..3 {
                    let (gi, gj) = (g[i] / t, g[j] / t);
                    a[i][j] = inv_k * gi * gj + c * (if i == j { 1.0 } else { 0.0 } - gi * gj);
                }
            }
            let s0 = &ph.spans[0];
            let n1 = [
                n0[0] + g[0],
                n0[1] + g[1],
                n0[2] + s0.weight_n_per_m * s0.unstretched_length_m + ph.clamp_weight_n + g[2],
            ];
            Some(PhaseState { n0, n1, clamp, g, tension: t, a })
        })
        .collect()
}

fn tower_residual(phases: &[TowerPhase], tower: &Tower, x: &[f64]) -> Option<Vec<f64>> {
    let np = phases.len();
    let states = phase_states(phases, tower, x)?;
    let mut r = vec![0.0; x.len()];
    let mut pull = [0.0; 2];
    for (p, (ph, st)) in phases.iter().zip(&states).enumerate() {
        let o0 = piece_offset(span_catenary(&ph.spans[0]), st.n0, ph.spans[0].unstretched_length_m)?;
        let o1 = piece_offset(span_catenary(&ph.spans[1]), st.n1, ph.spans[1].unstretched_length_m)?;
        set3(&mut r, 6 * p, sub(add(ph.left_m, o0), st.clamp));
        set3(&mut r, 6 * p + 3, sub(add(st.clamp, o1), ph.right_m));
        pull[0] += st.g[0];
        pull[1] += st.g[1];
    }
    let u = tower_u(x, np);
    r[6 * np] = u[0] - pull[0] / tower.across_n_per_m;
    r[6 * np + 1] = u[1] - pull[1] / tower.along_n_per_m;
    Some(r)
}

fn tower_jacobian(phases: &[TowerPhase], tower: &Tower, x: &[f64]) -> Vec<f64> {
    let n = x.len();
    let np = phases.len();
    let mut jac = vec![0.0; n * n];
    let Some(states) = phase_states(phases, tower, x) else { return jac };
    let spring_k = [tower.across_n_per_m, tower.along_n_per_m];
    for k in 0..2 {
        jac[(6 * np + k) * n + 6 * np + k] = 1.0;
    }
    for (p, (ph, st)) in phases.iter().zip(&states).enumerate() {
        let d0 = piece_jacobian(span_catenary(&ph.spans[0]), st.n0, ph.spans[0].unstretched_length_m);
        let d1 = piece_jacobian(span_catenary(&ph.spans[1]), st.n1, ph.spans[1].unstretched_length_m);
        let (r0, r1, cn, cg) = (6 * p, 6 * p + 3, 6 * p, 6 * p + 3);
        // span 0 closure L + o0(N0) - C(g, u)
        add_block(&mut jac, n, r0, cn, &d0, 1.0);
        add_block(&mut jac, n, r0, cg, &st.a, -1.0);
        // span 1 closure C(g, u) + o1(N1) - R, N1 = N0 + (w0 S0 + W) e3 + g
        add_block(&mut jac, n, r1, cn, &d1, 1.0);
        add_block(&mut jac, n, r1, cg, &st.a, 1.0);
        add_block(&mut jac, n, r1, cg, &d1, 1.0);
        for k in 0..2 {
            // dC/du_k = e_k
            jac[(r0 + k) * n + 6 * np + k] -= 1.0;
            jac[(r1 + k) * n + 6 * np + k] += 1.0;
            // tower rows u_k - sum g_k / k_k
            jac[(6 * np + k) * n + cg + k] -= 1.0 / spring_k[k];
        }
    }
    jac
}

fn validate_tower(phases: &[TowerPhase], tower: &Tower) -> Result<(), String> {
    if phases.is_empty() {
        return Err("at least one phase is needed".into());
    }
    check_point("tower rest point", tower.rest_m)?;
    check_positive("tower spring along", tower.along_n_per_m, true)?;
    check_positive("tower spring across", tower.across_n_per_m, true)?;
    for (p, ph) in phases.iter().enumerate() {
        check_point(&format!("left dead-end of phase {p}"), ph.left_m)?;
        check_point(&format!("right dead-end of phase {p}"), ph.right_m)?;
        check_point(&format!("pivot offset of phase {p}"), ph.pivot_offset_m)?;
        check_positive(&format!("string length of phase {p}"), ph.string_length_m, false)?;
        check_positive(&format!("string stiffness of phase {p}"), ph.string_stiffness_n, false)?;
        check_non_negative(&format!("clamp weight of phase {p}"), ph.clamp_weight_n)?;
        for (k, s) in ph.spans.iter().enumerate() {
            check_positive(&format!("length of span {k} of phase {p}"), s.unstretched_length_m, false)?;
            check_positive(&format!("EA of span {k} of phase {p}"), s.axial_stiffness_n, true)?;
            check_positive(&format!("weight of span {k} of phase {p}"), s.weight_n_per_m, false)?;
        }
    }
    Ok(())
}

/// Starting guess (`u = 0`, strings plumb with tension `t`, span 0 a lone catenary to the plumb clamp) and the coordinate
/// scale \[m\].
fn tower_start(phases: &[TowerPhase], tower: &Tower) -> Result<(Vec<f64>, f64), String> {
    let np = phases.len();
    let mut x0 = vec![0.0; 6 * np + 2];
    let mut coord_scale: f64 = 0.0;
    let l1 = |p: V3| p[0].abs() + p[1].abs() + p[2].abs();
    for (p, ph) in phases.iter().enumerate() {
        let [s0, s1] = ph.spans;
        let t = ph.clamp_weight_n
            + 0.5 * (s0.weight_n_per_m * s0.unstretched_length_m)
            + 0.5 * (s1.weight_n_per_m * s1.unstretched_length_m);
        let pivot = add(tower.rest_m, ph.pivot_offset_m);
        let clamp = [pivot[0], pivot[1], pivot[2] - ph.string_length_m * (1.0 + t / ph.string_stiffness_n)];
        let n0 = lone_span(span_catenary(&s0), s0.unstretched_length_m, ph.left_m, clamp)
            .map_err(|e| format!("starting guess of phase {p}, span 0: {e}"))?;
        set3(&mut x0, 6 * p, n0);
        set3(&mut x0, 6 * p + 3, [0.0, 0.0, -t]);
        coord_scale = coord_scale
            .max(l1(ph.left_m) + s0.unstretched_length_m)
            .max(l1(ph.right_m) + s1.unstretched_length_m)
            .max(l1(clamp));
    }
    Ok((x0, coord_scale))
}

/// Static equilibrium of several phases, each a two-span section with a suspension string on one shared
/// elastic tower top (see the module doc for the model and the method). Errors: invalid input, or no
/// convergence of the Newton iteration (also when the equilibrium would need a slack string).
pub fn solve_shared_tower(phases: &[TowerPhase], tower: &Tower) -> Result<TowerSolution, String> {
    validate_tower(phases, tower)?;
    let np = phases.len();
    let (x0, coord_scale) = tower_start(phases, tower)?;
    let tol = vec![length_tol(coord_scale); x0.len()];
    let max_step = vec![f64::INFINITY; x0.len()];
    let out =
        damped_newton(x0, &tol, &max_step, |x| tower_residual(phases, tower, x), |x| tower_jacobian(phases, tower, x))
            .map_err(|f| format!("shared tower: no equilibrium found: {}", f.message))?;
    let x = out.x;
    let states = phase_states(phases, tower, &x).ok_or("shared tower: slack string in the equilibrium found")?;
    let u = tower_u(&x, np);
    let mut sol = TowerSolution {
        u: [u[0], u[1]],
        tension: Vec::with_capacity(np),
        clamps: Vec::with_capacity(np),
        string_tension: Vec::with_capacity(np),
        pivot_forces: Vec::with_capacity(np),
        dead_end_forces: Vec::with_capacity(np),
        iterations: out.iterations,
    };
    for (ph, st) in phases.iter().zip(&states) {
        let s1 = &ph.spans[1];
        let n_end = [st.n1[0], st.n1[1], st.n1[2] + s1.weight_n_per_m * s1.unstretched_length_m];
        sol.tension.push([st.n0, st.n1]);
        sol.clamps.push(st.clamp);
        sol.string_tension.push(st.tension);
        sol.pivot_forces.push(st.g);
        sol.dead_end_forces.push([st.n0, [-n_end[0], -n_end[1], -n_end[2]]]);
    }
    Ok(sol)
}

impl TowerSolution {
    /// Tower displacement `(u1, u2, 0)` \[m\].
    pub fn tower_displacement_m(&self) -> [f64; 3] {
        [self.u[0], self.u[1], 0.0]
    }

    /// String tension `T_s` \[N\] of phase `phase`.
    pub fn string_tension_n(&self, phase: usize) -> f64 {
        self.string_tension[phase]
    }

    /// Clamp (conductor end of the string, `s = S_0` of span 0 and `s = 0` of span 1) \[m\].
    pub fn clamp_m(&self, phase: usize) -> [f64; 3] {
        self.clamps[phase]
    }

    /// Point \[m\] of span `span` (0: left dead-end to clamp, 1: clamp to right dead-end) of phase `phase` at
    /// unstretched arc coordinate `s_m` measured from the start of that span (`0 <= s_m <= S_span`).
    pub fn position(&self, phases: &[TowerPhase], phase: usize, span: usize, s_m: f64) -> [f64; 3] {
        let ph = &phases[phase];
        let from = if span == 0 { ph.left_m } else { self.clamps[phase] };
        piece_offset(span_catenary(&ph.spans[span]), self.tension[phase][span], s_m)
            .map_or([f64::NAN; 3], |o| add(from, o))
    }

    /// Force \[N\] the string applies to its pivot (the opposite acts on the clamp).
    pub fn pivot_force_n(&self, phase: usize) -> [f64; 3] {
        self.pivot_forces[phase]
    }

    /// Forces \[N\] phase `phase` applies to its left dead-end (`N(0)` of span 0) and its right dead-end
    /// (`-N(S)` of span 1).
    pub fn dead_end_forces_n(&self, phase: usize) -> [[f64; 3]; 2] {
        self.dead_end_forces[phase]
    }

    /// Tension vector \[N\] of span `span` of phase `phase` at arc coordinate `s_m` from the start of the span.
    pub fn tension_vector_n(&self, phases: &[TowerPhase], phase: usize, span: usize, s_m: f64) -> [f64; 3] {
        let n = self.tension[phase][span];
        [n[0], n[1], n[2] + phases[phase].spans[span].weight_n_per_m * s_m]
    }

    /// Newton iterations taken.
    pub fn iterations(&self) -> usize {
        self.iterations
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact_section::{Section, Span, Support, unstretched_length_for_tension};

    /// g \[m/s^2\]
    const G: f64 = 9.80665;
    /// ACSR Drake: weight \[N/m\] (1.628 kg/m)
    const DRAKE_W: f64 = 1.628 * G;
    /// ACSR Drake with 10 mm radial glaze ice (917 kg/m^3 on a 28.1 mm conductor: +1.10 kg/m) \[N/m\]
    const ICED_W: f64 = (1.628 + 1.10) * G;
    /// ACSR Drake: axial stiffness \[N\]
    const DRAKE_EA: f64 = 2.9e7;
    /// span \[m\]
    const SPAN: f64 = 300.0;
    /// stringing tension \[N\] (20 % of 140 kN): sag w l^2/(8 H) = 6.4 m on 300 m
    const H0: f64 = 28e3;
    /// spacer link stiffness \[N/m\]
    const SPACER_K: f64 = 1e6;
    /// suspension string: length \[m\], axial stiffness \[N\], weight \[N\] (100 kg)
    const STRING_L: f64 = 3.5;
    const STRING_EA: f64 = 5e7;
    const STRING_W: f64 = 100.0 * G;
    /// attachment height \[m\]
    const Z: f64 = 30.0;

    fn drake_length(delta: [f64; 2]) -> f64 {
        unstretched_length_for_tension(DRAKE_EA, DRAKE_W, [0.0, 0.0], delta, H0).unwrap()
    }

    fn max_abs(v: V3) -> f64 {
        v.iter().fold(0.0, |m, c| f64::max(m, c.abs()))
    }

    /// A bundle whose sub-conductor `c` is displaced by `offsets[c]` (x1, x3) from the reference chain
    /// `(0, 0, Z) -> (0, SPAN, Z + rise)`, with the given links on every spacer at `spacer_s`.
    fn bundle(offsets: &[[f64; 2]], rise: f64, links: &[(usize, usize)], spacer_s: &[f64], clamp_w: f64) -> Bundle {
        let length = drake_length([SPAN, rise]);
        let chains = offsets
            .iter()
            .map(|o| Chain {
                start_m: [o[0], 0.0, Z + o[1]],
                end_m: [o[0], SPAN, Z + rise + o[1]],
                unstretched_length_m: length,
                axial_stiffness_n: DRAKE_EA,
                weight_n_per_m: DRAKE_W,
            })
            .collect();
        let spacers = spacer_s
            .iter()
            .map(|s| Spacer {
                s_m: *s,
                links: links
                    .iter()
                    .map(|&(a, b)| SpacerLink {
                        a,
                        b,
                        rest_length_m: (offsets[b][0] - offsets[a][0]).hypot(offsets[b][1] - offsets[a][1]),
                        stiffness_n_per_m: SPACER_K,
                    })
                    .collect(),
                clamp_weight_n: clamp_w,
            })
            .collect();
        Bundle { chains, spacers }
    }

    const TWIN: [[f64; 2]; 2] = [[-0.2, 0.0], [0.2, 0.0]];
    const TWIN_LINKS: [(usize, usize); 1] = [(0, 1)];
    const QUAD: [[f64; 2]; 4] = [[-0.225, -0.225], [0.225, -0.225], [0.225, 0.225], [-0.225, 0.225]];
    const QUAD_LINKS: [(usize, usize); 6] = [(0, 1), (1, 2), (2, 3), (3, 0), (0, 2), (1, 3)];
    const SPACERS: [f64; 3] = [75.0, 150.0, 225.0];

    /// Largest `|fd - analytic|` relative to the largest entry of its row, over all entries.
    fn jacobian_mismatch(
        x: &[f64],
        steps: &[f64],
        residual: impl Fn(&[f64]) -> Vec<f64>,
        jacobian: impl Fn(&[f64]) -> Vec<f64>,
    ) -> f64 {
        let n = x.len();
        let jac = jacobian(x);
        let mut worst: f64 = 0.0;
        for col in 0..n {
            let mut p = x.to_vec();
            let mut m = x.to_vec();
            p[col] += steps[col];
            m[col] -= steps[col];
            let (rp, rm) = (residual(&p), residual(&m));
            for row in 0..n {
                let fd = (rp[row] - rm[row]) / (2.0 * steps[col]);
                let scale = (0..n).map(|j| (jac[row * n + j] * steps[j]).abs()).fold(0.0, f64::max) / steps[col];
                worst = worst.max((fd - jac[row * n + col]).abs() / scale);
            }
        }
        worst
    }

    #[test]
    fn jacobians_match_finite_differences() {
        // the catenary block
        let cat = Catenary { ea: DRAKE_EA, w: DRAKE_W };
        for (n, len) in [([1e4, 2.5e4, -3e3], 300.0), ([-2e4, 5e3, 1e3], 120.0), ([3e3, -1e3, -9e3], 400.0)] {
            let d = piece_jacobian(cat, n, len);
            for c in 0..3 {
                let step = 1e-6 * max_abs(n);
                let (mut p, mut m) = (n, n);
                p[c] += step;
                m[c] -= step;
                let (op, om) = (piece_offset(cat, p, len).unwrap(), piece_offset(cat, m, len).unwrap());
                for r in 0..3 {
                    let fd = (op[r] - om[r]) / (2.0 * step);
                    // central difference: truncation step^2 |o'''| and rounding eps |o| / step, both < 1e-7 of
                    // the largest entry (1e-2 m/N)
                    let scale = d[r].iter().fold(0.0, |a: f64, e| a.max(e.abs()));
                    assert!((fd - d[r][c]).abs() < 1e-6 * scale, "d o{r}/d n{c}: fd {fd}, analytic {}", d[r][c]);
                }
            }
        }
        // the bundle system, at the starting guess of an iced quad with the links loaded and turned
        let mut b = bundle(&QUAD, 10.0, &QUAD_LINKS, &SPACERS, 10.0);
        b.chains[2].weight_n_per_m = ICED_W;
        let lay = bundle_layout(&b).unwrap();
        let (mut x, _) = bundle_start(&b, &lay).unwrap();
        for i in 3 * lay.nc..lay.n {
            let wiggle = (i * 7 % 11) as f64 / 11.0 - 0.5;
            x[i] += if (i - 3 * lay.nc).is_multiple_of(3) { 500.0 * wiggle } else { 0.2 * wiggle };
        }
        // forces: 1e-6 relative (>= 1e-3 N); angles 1e-6 rad
        let steps: Vec<f64> =
            (0..lay.n)
                .map(|i| {
                    if i < 3 * lay.nc || (i - 3 * lay.nc).is_multiple_of(3) { 1e-6 * x[i].abs().max(1e3) } else { 1e-6 }
                })
                .collect();
        let worst = jacobian_mismatch(
            &x,
            &steps,
            |x| bundle_residual(&b, &lay, x, 1.0).unwrap(),
            |x| bundle_jacobian(&b, &lay, x, 1.0),
        );
        println!("bundle Jacobian: largest relative mismatch with central differences {worst:.2e}");
        assert!(worst < 1e-5);
        // the tower system, at its starting guess and moved off it (strings swung, tower displaced)
        let (phases, tower) = two_phase_tower(5e5);
        let (mut x, _) = tower_start(&phases, &tower).unwrap();
        x[3] += 300.0;
        x[10] -= 200.0;
        x[12] = 0.05;
        x[13] = -0.04;
        let steps: Vec<f64> = (0..x.len()).map(|i| if i < 12 { 1e-6 * x[i].abs().max(1e3) } else { 1e-7 }).collect();
        let worst = jacobian_mismatch(
            &x,
            &steps,
            |x| tower_residual(&phases, &tower, x).unwrap(),
            |x| tower_jacobian(&phases, &tower, x),
        );
        println!("tower Jacobian: largest relative mismatch with central differences {worst:.2e}");
        assert!(worst < 1e-5);
    }

    /// Spacers at rest: every sub-conductor is the lone elastic catenary of `exact_section`.
    #[test]
    fn bundle_at_rest_is_the_single_catenary() {
        for (name, offsets, links) in [("twin", &TWIN[..], &TWIN_LINKS[..]), ("quad", &QUAD[..], &QUAD_LINKS[..])] {
            let rise = 10.0;
            let b = bundle(offsets, rise, links, &SPACERS, 0.0);
            let sol = solve_bundle(&b).unwrap();
            let length = b.chains[0].unstretched_length_m;
            let section = Section {
                supports: vec![Support::DeadEnd { point: [0.0, Z] }, Support::DeadEnd { point: [SPAN, Z + rise] }],
                spans: vec![Span { ea_n: DRAKE_EA, w_n_per_m: DRAKE_W, length_m: length, broken: None }],
                g_m_per_s2: G,
            };
            let single = crate::exact_section::solve(&section).unwrap();
            let mut worst: f64 = 0.0;
            for (c, o) in offsets.iter().enumerate() {
                for k in 0..=600 {
                    let s = length * k as f64 / 600.0;
                    let p = sol.position(&b, c, s);
                    let q = single.point(&section, 0, s);
                    worst = worst.max(max_abs(sub(p, [o[0], q[0], q[1] + o[1]])));
                }
            }
            let tmax = (0..3)
                .flat_map(|i| (0..links.len()).map(move |l| (i, l)))
                .fold(0.0, |m: f64, (i, l)| m.max(sol.link_tension_n(i, l).abs()));
            println!(
                "{name} bundle at rest: {} iterations, largest distance to the single catenary {worst:.2e} m, \
                 largest |link tension| {tmax:.2e} N",
                sol.iterations()
            );
            // both references close their spans to 1e-11 m; the positions inside a span then agree to ~1e-11 m
            // (the span's end offset is the most sensitive to (H, V)): 1e-9 m
            assert!(worst < 1e-9);
            // the links stay unloaded: their compatibility is solved to 1e-11 m, times k = 1e6 N/m: 1e-5 N
            assert!(tmax < 1e-5);

            // equal nonzero clamp weights (1 kg per clamp): no longer a single catenary, but the sub-conductors
            // stay translates of each other and the links unloaded
            let b = bundle(offsets, rise, links, &SPACERS, G);
            let sol = solve_bundle(&b).unwrap();
            let mut worst: f64 = 0.0;
            for (c, o) in offsets.iter().enumerate() {
                for k in 0..=600 {
                    let s = length * k as f64 / 600.0;
                    let p = sub(sol.position(&b, c, s), [o[0], 0.0, o[1]]);
                    let q = sub(sol.position(&b, 0, s), [offsets[0][0], 0.0, offsets[0][1]]);
                    worst = worst.max(max_abs(sub(p, q)));
                }
            }
            let tmax = (0..3)
                .flat_map(|i| (0..links.len()).map(move |l| (i, l)))
                .fold(0.0, |m: f64, (i, l)| m.max(sol.link_tension_n(i, l).abs()));
            println!(
                "{name} bundle, 1 kg clamps: sub-conductors differ from translates by {worst:.2e} m, \
                 largest |link tension| {tmax:.2e} N"
            );
            // the closure tolerance 1e-11 m (with margin), and the link tension 1e6 N/m times it
            assert!(worst < 1e-9);
            assert!(tmax < 1e-5);
        }
    }

    /// Tension vector from the geometry alone: central difference `q` of the position at `s` (step `h`), then
    /// `|q| = 1 + T/EA` and `N = T q/|q|`.
    fn kinematic_tension(pos: impl Fn(f64) -> V3, ea: f64, s: f64, h: f64) -> V3 {
        let (a, b) = (pos(s + h), pos(s - h));
        let q = [(a[0] - b[0]) / (2.0 * h), (a[1] - b[1]) / (2.0 * h), (a[2] - b[2]) / (2.0 * h)];
        let ql = norm(q);
        let t = ea * (ql - 1.0);
        [t * q[0] / ql, t * q[1] / ql, t * q[2] / ql]
    }

    /// Checks the force balance of every clamp (from the geometry) and the global balance; returns the largest
    /// clamp imbalance \[N\] and the largest link tension \[N\].
    fn check_bundle_balance(name: &str, b: &Bundle, sol: &BundleSolution) -> (f64, f64) {
        let h = 0.01;
        let mut worst: f64 = 0.0;
        let mut tmax: f64 = 0.0;
        for (i, sp) in b.spacers.iter().enumerate() {
            // loads from the clamp positions the solution reports
            let mut p = vec![[0.0, 0.0, -sp.clamp_weight_n]; b.chains.len()];
            for (l, link) in sp.links.iter().enumerate() {
                let d = sub(sol.position(b, link.b, sp.s_m), sol.position(b, link.a, sp.s_m));
                let t = link.stiffness_n_per_m * (norm(d) - link.rest_length_m);
                // the reported tension (a Newton unknown) and the one recomputed from position(): they differ by
                // k times the link's compatibility residual (1e-11 m): 1e-5 N
                assert!(
                    (t - sol.link_tension_n(i, l)).abs() < 1e-4,
                    "link tension {t} vs {}",
                    sol.link_tension_n(i, l)
                );
                assert!(max_abs(sub(sol.position(b, link.a, sp.s_m), sol.clamp_m(i, link.a))) < 1e-12);
                tmax = tmax.max(t.abs());
                let f = [t * d[0] / norm(d), t * d[1] / norm(d), t * d[2] / norm(d)];
                p[link.a] = add(p[link.a], f);
                p[link.b] = sub(p[link.b], f);
            }
            for (c, ch) in b.chains.iter().enumerate() {
                let pos = |s: f64| sol.position(b, c, s);
                let w2h = ch.weight_n_per_m * 2.0 * h;
                let before = add(kinematic_tension(pos, ch.axial_stiffness_n, sp.s_m - 2.0 * h, h), [0.0, 0.0, w2h]);
                let after = sub(kinematic_tension(pos, ch.axial_stiffness_n, sp.s_m + 2.0 * h, h), [0.0, 0.0, w2h]);
                // N(s+) = N(s-) - P
                let imbalance = sub(sub(before, after), p[c]);
                worst = worst.max(max_abs(imbalance));
                // the solution's own tension vectors (a consistency check of tension_vector_n)
                let own = sub(sub(sol.tension_vector_n(b, c, sp.s_m - 1e-9), sol.tension_vector_n(b, c, sp.s_m)), p[c]);
                assert!(max_abs(own) < 1e-3, "{own:?}");
            }
        }
        let weight: f64 = b.chains.iter().map(|c| c.weight_n_per_m * c.unstretched_length_m).sum::<f64>()
            + b.spacers.iter().map(|s| s.clamp_weight_n).sum::<f64>() * b.chains.len() as f64;
        let total = (0..b.chains.len()).fold([0.0; 3], |a, c| {
            let f = sol.end_forces_n(c);
            add(a, add(f[0], f[1]))
        });
        println!(
            "{name}: {} iterations; largest clamp imbalance from the geometry {worst:.2e} N, largest |link tension| \
             {tmax:.3} N; sum of end forces [{:.2e}, {:.2e}, {:.9}] N, total weight {weight:.9} N",
            sol.iterations(),
            total[0],
            total[1],
            total[2]
        );
        // global balance: rounding of sums of ~3e4 N terms (1e-10 relative vertically, 1e-8 N horizontally)
        assert!((total[2] + weight).abs() < 1e-10 * weight);
        assert!(total[0].abs() < 1e-8 && total[1].abs() < 1e-8);
        // the geometric tension: central difference with h = 0.01 m has truncation h^2 |r''|^2/6 ~ 6e-12 (|r''| =
        // w/H ~ 6e-4 /m, or ~2e-3 /m on the iced bays) and rounding 2 ulp(300 m)/(2h) ~ 6e-12 in |q|, each giving EA
        // times that ~ 3e-4 N in T; four such estimates enter a balance: 1e-2 N
        assert!(worst < 1e-2, "clamp imbalance {worst} N");
        (worst, tmax)
    }

    #[test]
    fn twin_bundle_with_ice_on_one_sub_conductor() {
        let mut b = bundle(&TWIN, 0.0, &TWIN_LINKS, &SPACERS, 1.0 * G);
        b.chains[0].weight_n_per_m = ICED_W;
        let sol = solve_bundle(&b).unwrap();
        let (_, tmax) = check_bundle_balance("twin bundle, sub-conductor 0 iced", &b, &sol);
        for i in 0..3 {
            let (a, c) = (sol.clamp_m(i, 0), sol.clamp_m(i, 1));
            println!("  spacer {i}: clamps {a:.6?} / {c:.6?}, link tension {:.6} N", sol.link_tension_n(i, 0));
        }
        let mid = b.chains[0].unstretched_length_m / 2.0;
        let (p0, p1) = (sol.position(&b, 0, mid), sol.position(&b, 1, mid));
        println!("  midspan: iced {p0:.6?}, bare {p1:.6?}");
        // the spacers hold the sub-conductors together: the iced one pulls its neighbour down at the spacers
        assert!(tmax > 1.0);
        assert!(p0[2] < p1[2]);
        // spacer order is irrelevant: the same bundle with the spacers listed in reverse
        let mut rev = b.clone();
        rev.spacers.reverse();
        let sol_rev = solve_bundle(&rev).unwrap();
        for i in 0..3 {
            // identical equations, only the unknowns' order differs: rounding (1e-11 m closures, 1e6 N/m)
            assert!((sol_rev.link_tension_n(2 - i, 0) - sol.link_tension_n(i, 0)).abs() < 1e-4);
        }
    }

    #[test]
    fn quad_bundle_with_ice_on_one_sub_conductor() {
        // a lower corner (the bundle rolls a little) and an upper one (the iced sub-conductor rolls down)
        for (iced, name) in [(0, "lower left"), (2, "upper right")] {
            let mut b = bundle(&QUAD, 10.0, &QUAD_LINKS, &SPACERS, 1.0 * G);
            b.chains[iced].weight_n_per_m = ICED_W;
            let sol = solve_bundle(&b).unwrap();
            let (_, tmax) = check_bundle_balance(&format!("quad bundle, sub-conductor {iced} ({name}) iced"), &b, &sol);
            for i in 0..3 {
                let t: Vec<f64> = (0..6).map(|l| sol.link_tension_n(i, l)).collect();
                let c: Vec<V3> = (0..4).map(|c| sol.clamp_m(i, c)).collect();
                println!("  spacer {i}: link tensions {t:.6?} N, clamps {c:.6?}");
            }
            assert!(tmax > 1.0);
        }
    }

    /// Two phases at `x1 = +-4 m` on a tower at `x2 = SPAN`, dead-ends at `x2 = 0` and `2 SPAN` at the height of
    /// the plumb clamps, unstretched lengths for `H0` on level spans.
    fn two_phase_tower(k_along: f64) -> (Vec<TowerPhase>, Tower) {
        let length = drake_length([SPAN, 0.0]);
        let t = STRING_W + DRAKE_W * length;
        let zc = Z - STRING_L * (1.0 + t / STRING_EA);
        let span = SpanLoad { unstretched_length_m: length, axial_stiffness_n: DRAKE_EA, weight_n_per_m: DRAKE_W };
        let phases = [4.0, -4.0]
            .iter()
            .map(|&x1| TowerPhase {
                left_m: [x1, 0.0, zc],
                right_m: [x1, 2.0 * SPAN, zc],
                spans: [span; 2],
                pivot_offset_m: [x1, 0.0, 0.0],
                string_length_m: STRING_L,
                string_stiffness_n: STRING_EA,
                clamp_weight_n: STRING_W,
            })
            .collect();
        (phases, Tower { rest_m: [0.0, SPAN, Z], along_n_per_m: k_along, across_n_per_m: 5e5 })
    }

    /// Global balance of a tower solution; returns the sums for printing.
    fn check_tower_balance(phases: &[TowerPhase], tower: &Tower, sol: &TowerSolution) {
        let weight: f64 = phases
            .iter()
            .map(|p| p.clamp_weight_n + p.spans.iter().map(|s| s.weight_n_per_m * s.unstretched_length_m).sum::<f64>())
            .sum();
        let mut dead = [0.0; 3];
        let mut pivots = [0.0; 3];
        for p in 0..phases.len() {
            let f = sol.dead_end_forces_n(p);
            dead = add(dead, add(f[0], f[1]));
            pivots = add(pivots, sol.pivot_force_n(p));
        }
        let u = sol.tower_displacement_m();
        let spring = [tower.across_n_per_m * u[0], tower.along_n_per_m * u[1]];
        println!(
            "  dead-end loads [{:.6e}, {:.6e}, {:.6}] N, string loads on the tower [{:.6e}, {:.6e}, {:.6}] N, \
             spring forces k u [{:.6e}, {:.6e}] N, total weight {weight:.6} N",
            dead[0], dead[1], dead[2], pivots[0], pivots[1], pivots[2], spring[0], spring[1]
        );
        // vertical: dead-ends + the tower's vertical reaction carry the weight (rounding of ~1e4 N terms)
        assert!((dead[2] + pivots[2] + weight).abs() < 1e-10 * weight);
        for k in 0..2 {
            // horizontal: the strings' pull on the tower is its spring force (the balance is solved to 1e-11 m
            // times k <= 1e6 N/m: 1e-5 N), and the dead-end loads cancel it (rounding, 1e-8 N)
            if spring[k].is_finite() {
                assert!((pivots[k] - spring[k]).abs() < 1e-5, "{} vs {}", pivots[k], spring[k]);
            }
            assert!((dead[k] + pivots[k]).abs() < 1e-8, "{} vs {}", dead[k], pivots[k]);
        }
    }

    #[test]
    fn shared_tower_symmetric_loads_stay_plumb() {
        let (phases, tower) = two_phase_tower(5e5);
        let sol = solve_shared_tower(&phases, &tower).unwrap();
        let u = sol.tower_displacement_m();
        println!("symmetric tower: {} iterations, u = {u:?} m", sol.iterations());
        check_tower_balance(&phases, &tower, &sol);
        // u = 0 by symmetry; the closures and the tower balance are solved to 1e-11 m: 1e-10 m
        assert!(u[0].abs() < 1e-10 && u[1].abs() < 1e-10);
        for (p, ph) in phases.iter().enumerate() {
            let pivot = add(add(tower.rest_m, u), ph.pivot_offset_m);
            let d = sub(sol.clamp_m(p), pivot);
            let expected = STRING_W + DRAKE_W * ph.spans[0].unstretched_length_m;
            println!(
                "  phase {p}: clamp - pivot {d:?} m, string tension {:.9} N (level spans: W + w S = {expected:.9} N)",
                sol.string_tension_n(p)
            );
            // plumb: the same 1e-10 m
            assert!(d[0].abs() < 1e-10 && d[1].abs() < 1e-10);
            // level spans hanging from the clamp: V = w S/2 each side; string force residual ~ EA_s/L_s times
            // 1e-11 m = 1.4e-4 N: 1e-7 relative
            assert!((sol.string_tension_n(p) - expected).abs() < 1e-7 * expected);
        }
    }

    #[test]
    fn shared_tower_ice_on_one_span_moves_the_tower() {
        for span in [1, 0] {
            let (mut phases, tower) = two_phase_tower(5e5);
            phases[0].spans[span].weight_n_per_m = ICED_W;
            let sol = solve_shared_tower(&phases, &tower).unwrap();
            let u = sol.tower_displacement_m();
            println!(
                "ice on span {span} of phase 0: {} iterations, tower displacement {u:.9?} m, string tensions \
                 {:.6} / {:.6} N",
                sol.iterations(),
                sol.string_tension_n(0),
                sol.string_tension_n(1)
            );
            check_tower_balance(&phases, &tower, &sol);
            // the tower moves toward the iced span: span 1 lies at larger x2 than the tower, span 0 at smaller
            assert!(if span == 1 { u[1] > 1e-4 } else { u[1] < -1e-4 });
            // both phases stay in their vertical planes x1 = +-4 m: no across force (rounding)
            assert!(u[0].abs() < 1e-10);
            // the points of the spans close on the clamp and the dead-ends (closure tolerance)
            for (p, ph) in phases.iter().enumerate() {
                let e0 = sub(sol.position(&phases, p, 0, ph.spans[0].unstretched_length_m), sol.clamp_m(p));
                let e1 = sub(sol.position(&phases, p, 1, ph.spans[1].unstretched_length_m), ph.right_m);
                assert!(max_abs(e0) < 1e-10 && max_abs(e1) < 1e-10);
            }
        }

        // stiffer and stiffer tower: u -> 0 and k u -> the rigid tower's unbalanced pull
        let mut rigid_phases = two_phase_tower(f64::INFINITY).0;
        rigid_phases[0].spans[1].weight_n_per_m = ICED_W;
        let (_, rigid_tower) = two_phase_tower(f64::INFINITY);
        let rigid = solve_shared_tower(&rigid_phases, &rigid_tower).unwrap();
        let pull = rigid.pivot_force_n(0)[1] + rigid.pivot_force_n(1)[1];
        println!("rigid tower: u = {:?}, unbalanced pull along {pull:.9} N", rigid.tower_displacement_m());
        assert_eq!(rigid.tower_displacement_m(), [0.0; 3]);
        let mut last = f64::INFINITY;
        for k in [1e5, 1e6, 1e8, 1e10, 1e12] {
            let (mut phases, tower) = two_phase_tower(k);
            phases[0].spans[1].weight_n_per_m = ICED_W;
            let sol = solve_shared_tower(&phases, &tower).unwrap();
            let u2 = sol.tower_displacement_m()[1];
            println!("  k_along = {k:.0e} N/m: u2 = {u2:.6e} m, k u2 = {:.9} N", k * u2);
            assert!(u2 > 0.0 && u2 < last);
            last = u2;
            // linear response: k u = pull - K_sys u, K_sys the stiffness of the rest of the system seen by the
            // tower (strings as pendulums, T/L_s ~ 2e3 N/m per phase, in series with the spans): |k u - pull| must
            // stay below 1e4 |u|, plus the balance tolerance (1e-11 m times k)
            assert!((k * u2 - pull).abs() < 1e4 * u2 + 1e-11 * k, "k {k}");
        }
        assert!(last < 1e-8);
    }

    /// One phase on an elastic tower against `exact_section` with an elastic crossarm (a different formulation:
    /// string swing and tension as unknowns, two-dimensional).
    #[test]
    fn single_phase_tower_matches_exact_section() {
        let k_along = 2e5;
        let (mut phases, mut tower) = two_phase_tower(k_along);
        phases.truncate(1);
        phases[0].spans[0].weight_n_per_m = ICED_W;
        tower.across_n_per_m = f64::INFINITY;
        let sol = solve_shared_tower(&phases, &tower).unwrap();
        let ph = phases[0];
        let pivot = add(tower.rest_m, ph.pivot_offset_m);
        let section = Section {
            supports: vec![
                Support::DeadEnd { point: [ph.left_m[1], ph.left_m[2]] },
                Support::Suspension {
                    pivot: [pivot[1], pivot[2]],
                    length_m: STRING_L,
                    mass_kg: STRING_W / G,
                    stiffness_n: STRING_EA,
                    crossarm_n_per_m: k_along,
                },
                Support::DeadEnd { point: [ph.right_m[1], ph.right_m[2]] },
            ],
            spans: ph
                .spans
                .iter()
                .map(|s| Span {
                    ea_n: s.axial_stiffness_n,
                    w_n_per_m: s.weight_n_per_m,
                    length_m: s.unstretched_length_m,
                    broken: None,
                })
                .collect(),
            g_m_per_s2: G,
        };
        let reference = crate::exact_section::solve(&section).unwrap();
        let st = &reference.supports[1];
        let c = sol.clamp_m(0);
        let du = sol.tower_displacement_m()[1] - (st.pivot[0] - pivot[1]);
        let dc = (c[1] - st.clamp[0]).abs().max((c[2] - st.clamp[1]).abs());
        let dt = (sol.string_tension_n(0) - st.insulator_tension_n).abs() / st.insulator_tension_n;
        let mut worst: f64 = 0.0;
        for k in 0..2 {
            for i in 0..=300 {
                let s = ph.spans[k].unstretched_length_m * i as f64 / 300.0;
                let p = sol.position(&phases, 0, k, s);
                let q = reference.point(&section, k, s);
                worst = worst.max((p[1] - q[0]).abs()).max((p[2] - q[1]).abs()).max((p[0] - ph.left_m[0]).abs());
            }
        }
        println!(
            "single phase, span 0 iced, k_along {k_along:e} N/m: u2 = {:.9} m (exact_section {:.9} m, diff {du:.2e}), \
             clamp diff {dc:.2e} m, string tension {:.6} N (rel diff {dt:.2e}), largest point diff {worst:.2e} m",
            sol.tower_displacement_m()[1],
            st.pivot[0] - pivot[1],
            sol.string_tension_n(0)
        );
        // both solved to 1e-11 m closures (exact_section also to 1e-9 N forces, which over its crossarm spring
        // 2e5 N/m and the string pendulum ~2e3 N/m move points by < 1e-12 m): 1e-9 m; the string tension, EA_s/L_s
        // = 1.4e7 N/m times 2e-11 m over 7e3 N: 1e-7 relative
        assert!(du.abs() < 1e-9 && dc < 1e-9 && worst < 1e-9);
        assert!(dt < 1e-7);
    }

    #[test]
    fn invalid_input_is_an_error() {
        let mut b = bundle(&TWIN, 0.0, &TWIN_LINKS, &SPACERS, 0.0);
        b.spacers[1].s_m = 1e4;
        assert!(solve_bundle(&b).unwrap_err().contains("strictly inside"));
        let mut b = bundle(&TWIN, 0.0, &TWIN_LINKS, &[100.0, 100.0], 0.0);
        assert!(solve_bundle(&b).unwrap_err().contains("same arc coordinate"));
        b.spacers[1].s_m = 200.0;
        b.spacers[0].links[0].b = 0;
        assert!(solve_bundle(&b).is_err());
        let (mut phases, tower) = two_phase_tower(5e5);
        phases[1].string_length_m = 0.0;
        assert!(solve_shared_tower(&phases, &tower).is_err());
        assert!(solve_shared_tower(&[], &tower).is_err());
    }
}
