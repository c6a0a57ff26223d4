//! Study `section_transients`: grid and time-step refinement of the two transient design quantities of
//! the line-section cases, and the long-time state of the ice-shedding run against Newton's statics.
//!
//! # Cases and quantities
//!
//! The cases are read from `cases/a_broken_conductor.toml` and `cases/b_ice_shedding.toml` (five 400 m
//! spans of Drake on 3.5 m, 100 kg strings, strung at 28 kN) and run through the library's own scenario
//! build and run loop (`ohl::scenario::plan`, `ohl::run::run_observed`); only the segments per span, the
//! Courant number, the damping and the end time are changed. The quantities are tracked at every time
//! level (not at samples), by an observer:
//!
//! * (a) the largest longitudinal load (`x2` component, the line's direction) on the first suspension
//!   support, `max_t |F_2(t)|`, after the conductor breaks at the first dead-end at `t = 0`;
//! * (b) the jump of the middle span's mid-span node, `max_t x3(t) - x3(0)`, after its 25 mm glaze ice is
//!   shed at once at `t = 1 s` from the iced Newton equilibrium.
//!
//! # What the orders should be
//!
//! The smoothing (3.3) `vbar_i = v_i + b (v_{i+1} - 2 v_i + v_{i-1})` (mass-weighted where node masses
//! differ, `ohl::scheme::smoothing`) with a fixed `b` per step is a
//! numerical viscosity `nu = b ds^2 / dt = b ds c / C` [m^2/s]. Refining `N` at a fixed Courant number `C`
//! therefore refines towards the inviscid limit with an `O(nu) = O(ds)` error: the cases' default
//! (`b = 0.02`, `C = 0.9`) predicts **order 1 in ds**. Refining `dt` at a fixed grid with `b` proportional
//! to `C` keeps `nu` fixed, so the limit is the fixed-grid semi-discrete problem with that viscosity; the
//! smoothing is applied as a separate explicit substep after the kick (a first-order splitting of the
//! viscous term), so this predicts **order 1 in dt**. Without any damping the scheme is the centred chain
//! with the leapfrog: **order 2** (undamped control, case (b) only: case (a) is unstable undamped). With
//! Kelvin-Voigt internal friction `eta` and no smoothing (physical damping, case (a)) the chain is centred
//! in space (`O(ds^2)`) but the strain rate is taken at the previous half step (an `O(dt)` lag, first order
//! in time), so at a fixed `C` the grid order lies **between 1 and 2**, tending to 1.
//!
//! Observed orders: Celik's three-grid order `p = ln|(phi_3 - phi_2)/(phi_2 - phi_1)| / ln 2` over the last
//! three refinements, the least-squares slope of the successive differences over the last three
//! differences (full budget), and each pair's order; Richardson extrapolate and fine-grid GCI
//! (`crate::convergence`, `F_s = 1.25`) with the predicted order. Tolerances: `± 0.15` on the order where
//! the prediction is a single number: the next term of the expansion `phi = phi_0 + a h + b h^2` shifts the
//! three-grid order of a first-order method by `log2((1 + 6 beta) / (1 + 3 beta)) ~ 4.3 beta`
//! (`beta = b h / a` on the finest grid), so the allowance admits a second-order remainder of 3.5 % of the
//! first-order error; for order 2 it admits the third-order remainder likewise.
//!
//! # Rounding sensitivity of case (a)
//!
//! Case (a) is run as a small ensemble on every grid: the unperturbed run and runs with one node of the
//! first intact span lifted by 1e-9 m (far below any physical or discretisation scale). Its members differ
//! by far more than 1e-9 (slack segments snapping taut, the heavy clamps on their stiff strings): the table
//! gives the ensemble mean, minimum and maximum, and the orders use the means. For the Kelvin-Voigt variant
//! the standard error of the means is propagated into the three-grid order,
//! `sigma_p = sqrt((s_c/d_c)^2 + (s_f/d_f)^2) / ln 2` (`d` the differences of the means, `s` their standard
//! errors), and the check admits the predicted interval `[1, 2]` widened by the remainder allowance 0.15
//! and by `2 sigma_p`.
//!
//! # Long-time state of case (b)
//!
//! After the transient (6 s after the shedding) the run is continued with mass damping
//! `zeta = 2 omega_min` (near-critical on the slowest mode) until the equilibrium error bound below is under
//! ten times that of Newton's solution (which sits at the rounding floor of the residual), and compared
//! with `ohl::statics::solve` started from the state at the end of the transient. With
//! the stiffness `K = -dF/dx` at the Newton solution and its smallest generalised eigenvalue
//! `omega_min^2` (`K phi = omega^2 M phi`, found by inverse iteration with the library's Jacobian and
//! sparse LU), a state with residual force `F` lies within `|dx|_M <= |M^{-1/2} F| / omega_min^2` of the
//! equilibrium, so every node within `|M^{-1/2} F| / (omega_min^2 sqrt(m_min))`. The check asserts the
//! largest nodal distance between the relaxed run and Newton below the sum of the two states' bounds.

use crate::convergence::{Gci, gci, ls_order, pair_orders, three_grid_order};
use crate::report::{Budget, StudyReport, Table, sci};
use faer::Par;
use ohl::run::{Control, Level, Observer, OutputError, RunOptions, run_observed};
use ohl::scenario::{self, Scenario};
use ohl::scheme::Explicit;
use ohl::statics::jacobian::{pattern, unknown_index, values};
use ohl::statics::{SparseLu, StaticOptions, solve as solve_static};
use ohl_app::plot::{Chart, Series, Style};
use rayon::prelude::*;
use std::path::Path;

const CASE_A: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../cases/a_broken_conductor.toml");
const CASE_B: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../cases/b_ice_shedding.toml");
/// The cases' default smoothing per step at Courant 0.9.
const B_DEFAULT: f64 = 0.02;
const C_DEFAULT: f64 = 0.9;
/// Kelvin-Voigt variant of case (a): internal friction [N s] and Courant number (below the explicit
/// friction limit `sqrt(1 + z^2) - z` = 0.45 at N = 800, `z = eta c / (EA ds)`).
const ETA_KV: f64 = 3000.0;
const C_KV: f64 = 0.4;
/// Case (a) window [s] (its peak is at 1.5 to 1.8 s) and case (b) window (shedding at 1 s, jump at 3 s).
const END_A: f64 = 3.0;
const END_B: f64 = 7.0;
/// Perturbation of the ensemble members [m].
const PERTURB_M: f64 = 1.0e-9;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Case {
    /// (a): broken conductor, load on the first suspension support
    Break,
    /// (b): ice shedding, jump of the middle span
    Shed,
}

/// The damping of a run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Damping {
    /// the cases' default smoothing, `b = 0.02 C / 0.9` (fixed `nu` in a time refinement)
    Smoothing,
    /// none (case (b) control)
    Undamped,
    /// Kelvin-Voigt internal friction, no smoothing (case (a))
    KelvinVoigt,
}

impl Damping {
    fn name(self) -> &'static str {
        match self {
            Damping::Smoothing => "smoothing b = 0.02 (case default)",
            Damping::Undamped => "undamped",
            Damping::KelvinVoigt => "Kelvin-Voigt eta = 3000 N s",
        }
    }
}

/// One run.
#[derive(Clone, Copy, Debug)]
struct Spec {
    case: Case,
    damping: Damping,
    n: usize,
    courant: f64,
    /// ensemble member: 0 unperturbed, `k > 0` lifts node `3 k` of the first intact span
    member: usize,
}

impl Spec {
    fn smoothing(&self) -> f64 {
        match self.damping {
            Damping::Smoothing => B_DEFAULT * self.courant / C_DEFAULT,
            _ => 0.0,
        }
    }
    fn eta(&self) -> f64 {
        if self.damping == Damping::KelvinVoigt { ETA_KV } else { 0.0 }
    }
}

/// The tracked quantity at every level.
struct Track {
    case: Case,
    node: usize,
    z0: Option<f64>,
    forces: Vec<(usize, [f64; 3])>,
    series: Vec<(f64, f64)>,
}

impl Observer for Track {
    fn observe(&mut self, level: &Level) -> Result<Control, OutputError> {
        let s = level.solver;
        let v = match self.case {
            Case::Break => {
                s.support_forces(&mut self.forces);
                self.forces.iter().find(|f| f.0 == self.node).map_or(f64::NAN, |f| f.1[1])
            }
            Case::Shed => {
                let z = s.wire().x[2][self.node];
                z - *self.z0.get_or_insert(z)
            }
        };
        self.series.push((level.t_s, v));
        Ok(Control::Continue)
    }
}

/// What one run gave.
struct Outcome {
    spec: Spec,
    /// the design quantity (signed; largest magnitude) and its time
    value: f64,
    time_s: f64,
    dt_s: f64,
    wall_s: f64,
    /// the tracked signal, thinned
    series: Vec<(f64, f64)>,
    /// the solver at the end (case (b), member 0 only)
    solver: Option<Explicit>,
}

fn plan(spec: &Spec) -> Result<(ohl::scenario::Plan, usize), String> {
    let path = if spec.case == Case::Break { CASE_A } else { CASE_B };
    let mut sc: Scenario = scenario::load(Path::new(path)).map_err(|e| e.to_string())?;
    let sec = sc.section.as_mut().ok_or("the case has no [section]")?;
    sec.segments_per_span = Some(spec.n);
    sc.numerics.courant = spec.courant;
    sc.numerics.smoothing = spec.smoothing();
    sc.numerics.eta_n_s = spec.eta();
    sc.duration.end_time_s = Some(if spec.case == Case::Break { END_A } else { END_B });
    sc.duration.until_settled = None;
    sc.output.snapshot_times_s.clear();
    let mut plan = scenario::plan(&sc, path).map_err(|e| e.to_string())?;
    if spec.member > 0 {
        let i = plan.spans[1].0 + 3 * spec.member;
        plan.solver.wire_mut().x[2][i] += PERTURB_M;
    }
    let node = match spec.case {
        Case::Break => plan.spans[1].0,
        Case::Shed => (plan.spans[2].0 + plan.spans[2].1) / 2,
    };
    Ok((plan, node))
}

fn run_one(spec: Spec) -> Result<Outcome, String> {
    let (plan, node) = plan(&spec)?;
    let dt_s = plan.solver.params().dt_s;
    let mut track = Track { case: spec.case, node, z0: None, forces: Vec::new(), series: Vec::new() };
    let t0 = std::time::Instant::now();
    let out = run_observed(plan, &RunOptions::default(), &mut [&mut track])
        .map_err(|e| format!("{:?} {:?} N = {} C = {}: {e}", spec.case, spec.damping, spec.n, spec.courant))?;
    let wall_s = t0.elapsed().as_secs_f64();
    let (value, time_s) = match spec.case {
        Case::Break => {
            track.series.iter().fold((0.0, 0.0), |b, &(t, v)| if v.abs() > f64::abs(b.0) { (v, t) } else { b })
        }
        Case::Shed => smooth_peak(&track.series),
    };
    let k = track.series.len().div_ceil(1500).max(1);
    let series = track.series.iter().step_by(k).copied().collect();
    let solver = (spec.case == Case::Shed && spec.member == 0).then_some(out.solver);
    Ok(Outcome { spec, value, time_s, dt_s, wall_s, series, solver })
}

/// The largest-magnitude value of a smooth signal sampled at every time level, and its time: the vertex of
/// the parabola through the discrete extreme and its two neighbours. The discrete maximum alone misses the
/// continuous one by up to `|x''| dt^2 / 8` (2e-6 m for the jump at Courant 0.9), which at the jump's
/// tiny time-step error (below 1e-5 m with the mass-weighted smoothing) would be the whole difference;
/// the vertex leaves an `O(dt^3)` remainder.
fn smooth_peak(series: &[(f64, f64)]) -> (f64, f64) {
    let k = (0..series.len()).fold(0, |b, i| if series[i].1.abs() > series[b].1.abs() { i } else { b });
    if k == 0 || k + 1 >= series.len() {
        return (series.get(k).map_or(0.0, |p| p.1), series.get(k).map_or(0.0, |p| p.0));
    }
    let ((t0, y0), (t1, y1), (t2, y2)) = (series[k - 1], series[k], series[k + 1]);
    // Newton form: y = y0 + d0 (t - t0) + c (t - t0)(t - t1)
    let d1 = (y2 - y1) / (t2 - t1);
    let d0 = (y1 - y0) / (t1 - t0);
    let c = (d1 - d0) / (t2 - t0);
    if c == 0.0 {
        return (y1, t1);
    }
    // y'(t) = d0 + c (2 t - t0 - t1) = 0 (with d0 the slope of the first pair)
    let t = 0.5 * (t0 + t1) - d0 / (2.0 * c);
    let t = t.clamp(t0, t2);
    let y = y0 + d0 * (t - t0) + c * (t - t0) * (t - t1);
    (y, t)
}

/// Ensemble statistics of one refinement level.
#[derive(Clone, Debug)]
struct Level1 {
    n: usize,
    courant: f64,
    dt_s: f64,
    mean: f64,
    min: f64,
    max: f64,
    /// standard error of the mean (0 for a single member)
    sem: f64,
    time_s: f64,
    wall_s: f64,
    members: usize,
}

fn level_of(outs: &[&Outcome]) -> Level1 {
    let m = outs.len() as f64;
    let vals: Vec<f64> = outs.iter().map(|o| o.value).collect();
    let mean = vals.iter().sum::<f64>() / m;
    let var = if outs.len() > 1 { vals.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (m - 1.0) } else { 0.0 };
    Level1 {
        n: outs[0].spec.n,
        courant: outs[0].spec.courant,
        dt_s: outs[0].dt_s,
        mean,
        min: vals.iter().copied().fold(f64::INFINITY, f64::min),
        max: vals.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        sem: (var / m).sqrt(),
        time_s: outs[0].time_s,
        wall_s: outs.iter().map(|o| o.wall_s).sum::<f64>() / m,
        members: outs.len(),
    }
}

/// A refinement sequence (grid or time) of one quantity and damping, ordered coarse to fine (ratio 2).
struct Sequence {
    label: String,
    case: Case,
    damping: Damping,
    /// refinement in the grid (`true`) or in the time step
    grid: bool,
    predicted: &'static str,
    levels: Vec<Level1>,
}

/// Orders and extrapolation of a sequence.
struct Analysis {
    pairs: Vec<f64>,
    celik: f64,
    /// least-squares order of the last three successive differences (NaN with fewer than four levels)
    ls: f64,
    /// standard error of the Celik order from the ensemble noise
    sigma_p: f64,
    /// Richardson and GCI with the predicted order, and with the observed one
    with_predicted: Gci,
    with_observed: Gci,
}

fn analyse(seq: &Sequence, p_predicted: f64) -> Analysis {
    let v: Vec<f64> = seq.levels.iter().map(|l| l.mean).collect();
    let h: Vec<f64> = seq.levels.iter().map(|l| if seq.grid { 1.0 / l.n as f64 } else { l.courant }).collect();
    let k = v.len();
    let diffs: Vec<f64> = (1..k).map(|i| (v[i] - v[i - 1]).abs()).collect();
    let hd: Vec<f64> = (1..k).map(|i| h[i]).collect();
    let pairs = pair_orders(&hd, &diffs);
    let (f1, f2, f3) = (v[k - 1], v[k - 2], v[k - 3]);
    let celik = three_grid_order(f1, f2, f3, 2.0);
    let ls = if diffs.len() >= 3 { ls_order(&hd[hd.len() - 3..], &diffs[diffs.len() - 3..]) } else { f64::NAN };
    let s: Vec<f64> = seq.levels.iter().map(|l| l.sem).collect();
    let (dc, df) = (f2 - f3, f1 - f2);
    let (sc, sf) = ((s[k - 2].powi(2) + s[k - 3].powi(2)).sqrt(), (s[k - 1].powi(2) + s[k - 2].powi(2)).sqrt());
    let sigma_p = ((sc / dc).powi(2) + (sf / df).powi(2)).sqrt() / std::f64::consts::LN_2;
    let p_obs = if celik.is_finite() && celik > 0.0 { celik } else { p_predicted };
    Analysis {
        pairs,
        celik,
        ls,
        sigma_p,
        with_predicted: gci(f1, f2, 2.0, p_predicted),
        with_observed: gci(f1, f2, 2.0, p_obs),
    }
}

/// Smallest generalised eigenvalue `omega_min^2` of `K phi = omega^2 M phi` at the solver's state, by
/// inverse iteration (`K = -dF/dx` from the library's Jacobian, factored once).
fn omega_min_sq(s: &Explicit) -> Result<f64, String> {
    let (idx, n) = unknown_index(s);
    let pat = pattern(s);
    let mut vals = Vec::new();
    values(s, 0.0, 0.0, None, &mut vals);
    let mut lu = SparseLu::new(n, &pat, Par::Seq).map_err(|e| e.to_string())?;
    let mut mass = vec![0.0; n];
    for (i, o) in idx.iter().enumerate() {
        if let Some(r) = o {
            mass[*r..r + 3].fill(s.wire().mass[i]);
        }
    }
    let mut x = vec![1.0; n];
    let mut lambda = f64::NAN;
    for _ in 0..200 {
        // y = K^{-1} M x = -J^{-1} M x
        let mut y: Vec<f64> = x.iter().zip(&mass).map(|(a, m)| -a * m).collect();
        lu.solve(&vals, &mut y).map_err(|e| e.to_string())?;
        let xmx: f64 = x.iter().zip(&mass).map(|(a, m)| a * a * m).sum();
        let xmy: f64 = x.iter().zip(&y).zip(&mass).map(|((a, b), m)| a * b * m).sum();
        let next = xmx / xmy;
        let norm = y.iter().zip(&mass).map(|(a, m)| a * a * m).sum::<f64>().sqrt();
        x = y.iter().map(|a| a / norm).collect();
        if (next - lambda).abs() <= 1e-12 * next.abs() {
            return Ok(next);
        }
        lambda = next;
    }
    Ok(lambda)
}

/// The equilibrium error bound [m]: `|M^{-1/2} F| / (omega^2 sqrt(m_min))` over the free nodes.
fn equilibrium_bound(s: &mut Explicit, omega_sq: f64) -> f64 {
    let n1 = s.wire().nodes();
    let mut f = [vec![0.0; n1], vec![0.0; n1], vec![0.0; n1]];
    s.net_force(&mut f);
    let w = s.wire();
    let mut sum = 0.0;
    let mut m_min = f64::INFINITY;
    for i in 0..n1 {
        if w.free[i] > 0.0 {
            sum += (0..3).map(|k| f[k][i] * f[k][i]).sum::<f64>() / w.mass[i];
            m_min = m_min.min(w.mass[i]);
        }
    }
    sum.sqrt() / (omega_sq * m_min.sqrt())
}

/// The long-time state of case (b) against Newton.
struct LongTime {
    n: usize,
    omega_min: f64,
    zeta: f64,
    relax_s: f64,
    bound_relaxed: f64,
    bound_newton: f64,
    target: f64,
    newton_iterations: usize,
    gap_m: f64,
    mid_relaxed: f64,
    mid_newton: f64,
    history: Vec<(f64, f64)>,
}

fn long_time(end: &Explicit, n: usize, mid: usize) -> Result<LongTime, String> {
    let mut newton = end.clone();
    let rep = solve_static(&mut newton, &StaticOptions { max_iterations: 200, ..StaticOptions::default() })
        .map_err(|e| format!("Newton: {e}"))?;
    let omega_sq = omega_min_sq(&newton)?;
    let bound_newton = equilibrium_bound(&mut newton, omega_sq);
    let mut s = end.clone();
    let zeta = 2.0 * omega_sq.sqrt();
    s.params_mut().mass_damping_per_s = zeta;
    let dt = s.params().dt_s;
    let t0 = s.time_s();
    let check_every = ((0.2 / dt) as usize).max(1);
    let mut history = vec![(0.0, equilibrium_bound(&mut s, omega_sq))];
    // Ten times the bound of Newton's state, which sits at the rounding floor of the residual.
    let target = 10.0 * bound_newton;
    while history.last().is_some_and(|h| h.1 > target) && s.time_s() - t0 < 400.0 {
        for _ in 0..check_every {
            s.step(dt).map_err(|e| e.to_string())?;
        }
        history.push((s.time_s() - t0, equilibrium_bound(&mut s, omega_sq)));
    }
    let bound_relaxed = history.last().map_or(f64::NAN, |h| h.1);
    let (a, b) = (s.wire(), newton.wire());
    let gap_m =
        (0..a.nodes()).map(|i| (0..3).map(|k| (a.x[k][i] - b.x[k][i]).powi(2)).sum::<f64>().sqrt()).fold(0.0, f64::max);
    Ok(LongTime {
        n,
        omega_min: omega_sq.sqrt(),
        zeta,
        relax_s: s.time_s() - t0,
        bound_relaxed,
        bound_newton,
        target,
        newton_iterations: rep.iterations,
        gap_m,
        mid_relaxed: a.x[2][mid],
        mid_newton: b.x[2][mid],
        history,
    })
}

/// Run the study.
pub fn run(budget: Budget, dir: &Path) -> Result<StudyReport, String> {
    let full = budget == Budget::Full;
    let grids_b: &[usize] = if full { &[25, 50, 100, 200, 400] } else { &[100, 200, 400] };
    // Four levels at both budgets: with the mass-weighted smoothing the jump's dt-error is 3e-6 m at C = 0.9, and
    // the first pair still carries its higher-order part (pair order 1.16).
    let courants_b: &[f64] = &[0.9, 0.45, 0.225, 0.1125];
    let grids_a: &[usize] = if full { &[25, 50, 100, 200, 400] } else { &[25, 50, 100] };
    let grids_kv: &[usize] = if full { &[100, 200, 400, 800] } else { &[200, 400, 800] };
    let courants_kv: &[f64] = if full { &[0.4, 0.2, 0.1] } else { &[] };
    let n_time = 100;
    let members = if full { 6 } else { 2 };
    let members_kv = if full { 4 } else { 2 };
    let mut specs = Vec::new();
    let sp = |case, damping, n, courant, member| Spec { case, damping, n, courant, member };
    for &n in grids_b {
        specs.push(sp(Case::Shed, Damping::Smoothing, n, C_DEFAULT, 0));
        specs.push(sp(Case::Shed, Damping::Undamped, n, C_DEFAULT, 0));
    }
    for &c in &courants_b[1..] {
        specs.push(sp(Case::Shed, Damping::Smoothing, n_time, c, 0));
    }
    for m in 0..members {
        for &n in grids_a {
            specs.push(sp(Case::Break, Damping::Smoothing, n, C_DEFAULT, m));
        }
        for &c in &courants_b[1..] {
            specs.push(sp(Case::Break, Damping::Smoothing, n_time, c, m));
        }
    }
    for m in 0..members_kv {
        for &n in grids_kv {
            specs.push(sp(Case::Break, Damping::KelvinVoigt, n, C_KV, m));
        }
        for &c in courants_kv.iter().skip(1) {
            specs.push(sp(Case::Break, Damping::KelvinVoigt, n_time, c, m));
        }
    }
    let t0 = std::time::Instant::now();
    let outs: Vec<Outcome> = specs.par_iter().map(|&s| run_one(s)).collect::<Result<_, _>>()?;
    let runs_wall = t0.elapsed().as_secs_f64();
    let pick = |case: Case, damping: Damping, n: usize, c: f64| -> Level1 {
        let v: Vec<&Outcome> = outs
            .iter()
            .filter(|o| o.spec.case == case && o.spec.damping == damping && o.spec.n == n && o.spec.courant == c)
            .collect();
        level_of(&v)
    };
    let seq = |label: &str, case, damping, grid: bool, predicted, ns: &[usize], cs: &[f64]| Sequence {
        label: label.into(),
        case,
        damping,
        grid,
        predicted,
        levels: if grid {
            ns.iter().map(|&n| pick(case, damping, n, cs[0])).collect()
        } else {
            cs.iter().map(|&c| pick(case, damping, ns[0], c)).collect()
        },
    };
    let mut seqs = vec![
        seq("(b) jump, grid", Case::Shed, Damping::Smoothing, true, "1", grids_b, &[C_DEFAULT]),
        seq("(b) jump, time step", Case::Shed, Damping::Smoothing, false, "1", &[n_time], courants_b),
        seq("(b) jump, grid", Case::Shed, Damping::Undamped, true, "2", grids_b, &[C_DEFAULT]),
        seq("(a) peak load, grid", Case::Break, Damping::Smoothing, true, "1 (smooth solution)", grids_a, &[C_DEFAULT]),
        seq(
            "(a) peak load, time step",
            Case::Break,
            Damping::Smoothing,
            false,
            "1 (smooth solution)",
            &[n_time],
            courants_b,
        ),
        seq("(a) peak load, grid", Case::Break, Damping::KelvinVoigt, true, "between 1 and 2", grids_kv, &[C_KV]),
    ];
    if full {
        seqs.push(seq(
            "(a) peak load, time step",
            Case::Break,
            Damping::KelvinVoigt,
            false,
            "1",
            &[n_time],
            courants_kv,
        ));
    }

    let mut rep = StudyReport {
        title: "Transients of the line-section cases: grid and time-step convergence".into(),
        summary: format!(
            "Case (a) (`cases/a_broken_conductor.toml`: largest longitudinal load on the first suspension \
             support after the break at the first dead-end) and case (b) (`cases/b_ice_shedding.toml`: jump of \
             the middle span's mid-span node after the ice is shed) on their five 400 m spans, refined in N per \
             span at a fixed Courant number and in the time step at N = {n_time} with a fixed smoothing viscosity \
             (b = 0.02 C / 0.9). Damping: the cases' default smoothing (predicted order 1 in ds and in dt), an \
             undamped control for (b) (order 2), and Kelvin-Voigt friction eta = {ETA_KV} N s without smoothing \
             for (a) at Courant {C_KV} (order between 1 and 2). Case (a) runs as an ensemble of {members} \
             members ({members_kv} with Kelvin-Voigt), {PERTURB_M} m apart in one node. The long-time state of \
             (b) is relaxed with mass damping and compared with Newton's static solution."
        ),
        ..Default::default()
    };
    let mut runs_table = Table::new(
        "section_transients_runs",
        "Every refinement level: the design quantity (ensemble mean, minimum, maximum for case (a)), when it \
         occurs, and the wall time of one run",
        &[
            "quantity",
            "damping",
            "N per span",
            "Courant",
            "dt [s]",
            "value (mean)",
            "min",
            "max",
            "members",
            "at t [s]",
            "wall per run [s]",
        ],
    );
    let mut order_table = Table::new(
        "section_transients_orders",
        "Observed orders (pairs; Celik over the last three levels; least squares over the last three \
         differences), Richardson extrapolates and fine-level GCI (with the predicted and with the observed order)",
        &[
            "sequence",
            "damping",
            "predicted order",
            "pair orders",
            "Celik order",
            "LS order (last three)",
            "finest value",
            "Richardson (predicted p)",
            "GCI (predicted p)",
            "Richardson (observed p)",
            "GCI (observed p)",
        ],
    );
    let unit = |c: Case| if c == Case::Break { "N" } else { "m" };
    let mut analyses = Vec::new();
    for s in &seqs {
        for l in &s.levels {
            runs_table.row(vec![
                format!("{} [{}]", s.label, unit(s.case)),
                s.damping.name().into(),
                l.n.to_string(),
                format!("{}", l.courant),
                sci(l.dt_s),
                format!("{:.6}", l.mean),
                format!("{:.6}", l.min),
                format!("{:.6}", l.max),
                l.members.to_string(),
                format!("{:.4}", l.time_s),
                format!("{:.3}", l.wall_s),
            ]);
        }
        let p_pred = match (s.damping, s.case) {
            (Damping::Undamped, _) => 2.0,
            _ => 1.0,
        };
        let a = analyse(s, p_pred);
        let fin = s.levels.last().map_or(f64::NAN, |l| l.mean);
        // Roache: an observed order outside [0.5, 3] is not used for extrapolation.
        let reasonable = a.celik > 0.5 && a.celik < 3.0;
        order_table.row(vec![
            s.label.clone(),
            s.damping.name().into(),
            s.predicted.into(),
            a.pairs.iter().map(|p| format!("{p:.3}")).collect::<Vec<_>>().join(" "),
            format!("{:.3}", a.celik),
            if a.ls.is_finite() { format!("{:.3}", a.ls) } else { "-".into() },
            format!("{fin:.6}"),
            format!("{:.6}", a.with_predicted.extrapolated),
            sci(a.with_predicted.gci_fine),
            if reasonable { format!("{:.6}", a.with_observed.extrapolated) } else { "- (order unreasonable)".into() },
            if reasonable { sci(a.with_observed.gci_fine) } else { "-".into() },
        ]);
        analyses.push(a);
    }
    // Checks on the orders.
    let tol = 0.15;
    for (s, a) in seqs.iter().zip(&analyses) {
        let what = format!("{}, {}: observed order", s.label, s.damping.name());
        match (s.case, s.damping) {
            (Case::Shed, Damping::Smoothing) => rep.check(
                what,
                format!("Celik order 1 ± {tol} (nu = b ds c / C)"),
                format!("{:.3}", a.celik),
                (a.celik - 1.0).abs() < tol,
            ),
            (Case::Shed, Damping::Undamped) => rep.check(
                what,
                format!("Celik order 2 ± {tol} (centred chain, leapfrog)"),
                format!("{:.3}", a.celik),
                (a.celik - 2.0).abs() < tol,
            ),
            (Case::Break, Damping::KelvinVoigt) if s.grid => {
                let w = tol + 2.0 * a.sigma_p;
                rep.check(
                    what,
                    format!("Celik order in [1, 2] widened by {tol} + 2 sigma_p = {w:.3} (remainder, ensemble noise)"),
                    format!("{:.3}", a.celik),
                    a.celik > 1.0 - w && a.celik < 2.0 + w,
                )
            }
            _ => {}
        }
    }
    // The two (b) grid sequences approximate the same inviscid limit: the undamped extrapolate must lie in
    // the case default's fine-grid GCI band.
    let (smooth_b, undamped_b) = (&analyses[0], &analyses[2]);
    let fine_b = seqs[0].levels.last().map_or(f64::NAN, |l| l.mean);
    let band = smooth_b.with_predicted.gci_fine * fine_b.abs();
    let gap = (undamped_b.with_predicted.extrapolated - fine_b).abs();
    rep.check(
        "(b) jump: undamped extrapolate inside the smoothed fine-grid GCI band",
        "|phi_ext(undamped) - phi_fine(smoothing)| <= GCI phi_fine (same inviscid limit)",
        format!("{} m <= {} m", sci(gap), sci(band)),
        gap <= band,
    );
    // Case (a) with the default smoothing: reported, not asserted (see the discussion).
    let a_smooth = &analyses[3];
    let spread = seqs[3].levels.iter().map(|l| (l.max - l.min) / l.mean.abs()).fold(0.0, f64::max);

    // Long-time state of case (b).
    let n_long = n_time;
    let end_state = outs
        .iter()
        .find(|o| {
            o.spec.case == Case::Shed
                && o.spec.damping == Damping::Smoothing
                && o.spec.n == n_long
                && o.spec.courant == C_DEFAULT
        })
        .and_then(|o| o.solver.clone())
        .ok_or("case (b): no final state at N = 100")?;
    let (_, mid) = plan(&sp(Case::Shed, Damping::Smoothing, n_long, C_DEFAULT, 0))?;
    let lt = long_time(&end_state, n_long, mid)?;
    let mut static_table = Table::new(
        "section_transients_static",
        "Case (b): long-time state (mass damping zeta = 2 omega_min after the transient) against Newton's \
         static solution from the state at the end of the transient",
        &[
            "N per span",
            "omega_min [rad/s]",
            "zeta [1/s]",
            "relaxation time [s]",
            "bound relaxed [m]",
            "bound Newton [m]",
            "Newton iterations",
            "max nodal gap [m]",
            "mid-span x3 relaxed [m]",
            "mid-span x3 Newton [m]",
        ],
    );
    static_table.row(vec![
        lt.n.to_string(),
        format!("{:.4}", lt.omega_min),
        format!("{:.4}", lt.zeta),
        format!("{:.1}", lt.relax_s),
        sci(lt.bound_relaxed),
        sci(lt.bound_newton),
        lt.newton_iterations.to_string(),
        sci(lt.gap_m),
        format!("{:.9}", lt.mid_relaxed),
        format!("{:.9}", lt.mid_newton),
    ]);
    rep.check(
        "(b) long-time state vs Newton statics",
        "relaxed to bound <= 10 bound(Newton); max nodal distance <= bound(relaxed) + bound(Newton), \
         bound = |M^-1/2 F| / (omega_min^2 sqrt(m_min))",
        format!("{} m <= {} m", sci(lt.gap_m), sci(lt.bound_relaxed + lt.bound_newton)),
        lt.gap_m <= lt.bound_relaxed + lt.bound_newton && lt.bound_relaxed <= lt.target,
    );

    // Figures.
    let mut charts = Vec::new();
    let series_of = |case: Case, damping: Damping, n: usize, c: f64, scale: f64| -> Vec<(f64, f64)> {
        outs.iter()
            .find(|o| {
                o.spec.case == case
                    && o.spec.damping == damping
                    && o.spec.n == n
                    && o.spec.courant == c
                    && o.spec.member == 0
            })
            .map(|o| o.series.iter().map(|p| (p.0, p.1 * scale)).collect())
            .unwrap_or_default()
    };
    let mut sb: Vec<Series> = grids_b
        .iter()
        .enumerate()
        .map(|(i, &n)| {
            Series::new(
                format!("N = {n}"),
                series_of(Case::Shed, Damping::Smoothing, n, C_DEFAULT, 1.0),
                Style::Line,
                i,
            )
        })
        .collect();
    let n_fine = *grids_b.last().unwrap_or(&100);
    sb.push(Series::new(
        format!("undamped N = {n_fine} (reference)"),
        series_of(Case::Shed, Damping::Undamped, n_fine, C_DEFAULT, 1.0),
        Style::Dashed,
        7,
    ));
    charts.push(Chart {
        title: "(b) mid-span rise of the shedding span".into(),
        x_label: "time t [s]".into(),
        y_label: "x3(t) - x3(0) [m]".into(),
        series: sb,
        ..Default::default()
    });
    let err_series = |idx: usize, label: &str, color: usize| -> Series {
        let s = &seqs[idx];
        let ext = analyses[idx].with_predicted.extrapolated;
        Series::new(
            label,
            s.levels
                .iter()
                .map(|l| (if s.grid { l.n as f64 } else { l.courant }, (l.mean - ext).abs().max(1e-300)))
                .collect(),
            Style::LineMarkers,
            color,
        )
    };
    let slope = |xs: &[f64], y0: f64, p: f64, label: &str, color: usize, grid: bool| -> Series {
        let x0 = xs[0];
        Series::new(
            label,
            xs.iter().map(|&x| (x, y0 * if grid { (x0 / x).powf(p) } else { (x / x0).powf(p) })).collect(),
            Style::Dashed,
            color,
        )
    };
    let nb: Vec<f64> = grids_b.iter().map(|&n| n as f64).collect();
    let e0 = (seqs[0].levels[0].mean - analyses[0].with_predicted.extrapolated).abs();
    let e0u = (seqs[2].levels[0].mean - analyses[2].with_predicted.extrapolated).abs().max(1e-12);
    charts.push(Chart {
        title: "(b) jump: grid convergence".into(),
        x_label: "segments per span N [-]".into(),
        y_label: "|jump - Richardson extrapolate| [m]".into(),
        series: vec![
            err_series(0, "smoothing (default)", 0),
            err_series(2, "undamped", 1),
            slope(&nb, e0, 1.0, "slope -1", 7, true),
            slope(&nb, e0u, 2.0, "slope -2", 5, true),
        ],
        log_x: true,
        log_y: true,
        ..Default::default()
    });
    let cb: Vec<f64> = courants_b.to_vec();
    let e0t = (seqs[1].levels[0].mean - analyses[1].with_predicted.extrapolated).abs();
    charts.push(Chart {
        title: format!("(b) jump: time-step convergence, N = {n_time}"),
        x_label: "Courant number C (dt = C ds / c) [-]".into(),
        y_label: "|jump - Richardson extrapolate| [m]".into(),
        series: vec![err_series(1, "smoothing, b = 0.02 C / 0.9", 0), slope(&cb, e0t, 1.0, "slope 1", 7, false)],
        log_x: true,
        log_y: true,
        ..Default::default()
    });
    let mut sa: Vec<Series> = grids_a
        .iter()
        .enumerate()
        .map(|(i, &n)| {
            Series::new(
                format!("N = {n}"),
                series_of(Case::Break, Damping::Smoothing, n, C_DEFAULT, 1e-3),
                Style::Line,
                i,
            )
        })
        .collect();
    let n_kv = *grids_kv.last().unwrap_or(&200);
    sa.push(Series::new(
        format!("Kelvin-Voigt N = {n_kv} (reference)"),
        series_of(Case::Break, Damping::KelvinVoigt, n_kv, C_KV, 1e-3),
        Style::Dashed,
        7,
    ));
    charts.push(Chart {
        title: "(a) longitudinal load on the first suspension support".into(),
        x_label: "time t [s]".into(),
        y_label: "F2 [kN]".into(),
        series: sa,
        ..Default::default()
    });
    let band = |idx: usize, color: usize, label: &str| -> Vec<Series> {
        let s = &seqs[idx];
        vec![
            Series::new(
                format!("{label} mean"),
                s.levels.iter().map(|l| (l.n as f64, l.mean * 1e-3)).collect(),
                Style::LineMarkers,
                color,
            ),
            Series::new(
                format!("{label} min / max"),
                s.levels.iter().flat_map(|l| [(l.n as f64, l.min * 1e-3), (l.n as f64, l.max * 1e-3)]).collect(),
                Style::Markers,
                color,
            ),
        ]
    };
    let mut pa = band(3, 0, "smoothing");
    pa.extend(band(5, 1, "Kelvin-Voigt"));
    let kv_ext = analyses[5].with_predicted.extrapolated * 1e-3;
    pa.push(Series::new(
        "Kelvin-Voigt Richardson (p = 1)",
        grids_kv.iter().map(|&n| (n as f64, kv_ext)).collect(),
        Style::Dashed,
        7,
    ));
    charts.push(Chart {
        title: "(a) peak longitudinal load vs grid".into(),
        x_label: "segments per span N [-]".into(),
        y_label: "max |F2| [kN]".into(),
        series: pa,
        log_x: true,
        ..Default::default()
    });
    charts.push(Chart {
        title: format!("(b) relaxation to the static state, N = {}", lt.n),
        x_label: "time after the transient [s]".into(),
        y_label: "equilibrium error bound [m]".into(),
        series: vec![
            Series::new("bound of the relaxed state", lt.history.clone(), Style::Line, 0),
            Series::new(
                "target: 10 x Newton's bound",
                vec![(0.0, lt.target), (lt.history.last().map_or(1.0, |h| h.0), lt.target)],
                Style::Dashed,
                7,
            ),
            Series::new(
                "Newton's bound",
                vec![
                    (0.0, lt.bound_newton.max(1e-16)),
                    (lt.history.last().map_or(1.0, |h| h.0), lt.bound_newton.max(1e-16)),
                ],
                Style::Dashed,
                1,
            ),
        ],
        log_y: true,
        ..Default::default()
    });
    rep.figure(
        &charts,
        3,
        (560, 420),
        "section_transients: cases (a) broken conductor and (b) ice shedding, 5 x 400 m ACSR Drake on strings",
        dir,
        "section_transients",
    )?;
    rep.tables.push(runs_table);
    rep.tables.push(order_table);
    rep.tables.push(static_table);
    rep.discussion = format!(
        "Case (b), the jump after ice shedding, behaves as the theory says: with the default smoothing it \
         converges at first order in ds (Celik {:.3}) and in dt at a fixed viscosity (Celik {:.3}), and without \
         damping at second order (Celik {:.3}); the undamped extrapolate lies inside the smoothed run's GCI \
         band, and the relaxed long-time state is Newton's static solution to its error bound.\n\n\
         Case (a), the peak longitudinal load after the break, does not converge with the default smoothing on \
         N = {} per span: its observed orders ({}) and its peak time jump between two load pulses (about 1.6 s \
         and 1.8 s) whose heights move in opposite directions as N grows, and the ensemble members, 1e-9 m apart \
         at the start, differ by up to {:.2} % of the peak (sensitivity to rounding: slack conductor snapping \
         taut next to the heavy clamps). At a fixed grid (N = {n_time}) the time-step sequence at a fixed \
         viscosity settles (pair orders {}). No grid order is asserted: the smoothing is mass-weighted (it \
         conserves momentum, and study `section_energy` shows its force on a 100 kg clamp falling with the \
         grid; the unweighted form's grew like N), so the clamp is not the cause; the cause is the limit the \
         grid sequence approaches. The smoothing's viscosity vanishes like ds, and the inviscid limit of a \
         tension-only conductor snapping taut carries kinks at the wave speed whose tension peaks are one cell \
         wide: its peak support load is not a functional that converges. With physical Kelvin-Voigt friction \
         instead of the smoothing the peak converges (Celik {:.3} on N = {:?}), the ensemble spread falls below \
         the grid differences, and the Richardson extrapolate is {:.0} N. Wall time of all runs: \
         {runs_wall:.1} s.",
        analyses[0].celik,
        analyses[1].celik,
        analyses[2].celik,
        grids_a.iter().map(|n| n.to_string()).collect::<Vec<_>>().join(", "),
        a_smooth.pairs.iter().map(|p| format!("{p:.2}")).collect::<Vec<_>>().join(", "),
        100.0 * spread,
        analyses[4].pairs.iter().map(|p| format!("{p:.2}")).collect::<Vec<_>>().join(", "),
        analyses[5].celik,
        grids_kv,
        analyses[5].with_predicted.extrapolated,
    );
    Ok(rep)
}
