//! Study `implicit`: the implicit reference on faer.
//!
//! (a) Static equilibrium of the discrete equations by Newton's method with the exact sparse Jacobian
//!     (`ohl::statics::solve`): the iteration history down to rounding, and the agreement of the settled
//!     explicit state with Newton's solution (required: 1e-8 relative to the deflection).
//!
//! History: from the `static` study's start (a parabola through 0.9 of the exact mid-span
//! displacement) the solve is run with a zero tolerance for `k = 0, 1, ..., K` iterations (`K = 8`,
//! three past the floor), which gives the iterates `x_k` themselves: the largest nodal residual `r_k`
//! [N] and the error `e_k = max_i |x_k,i - x_K,i|` [m] against the last iterate. Rounding floors: the
//! residual cannot fall below `R = (EA / l0) X eps` (`ohl::statics::rounding_floor_n`: an ulp of a
//! coordinate of magnitude `X` through a segment's axial stiffness; `EA N eps` here), nor the error
//! below about `X eps` (an ulp of the coordinates, `X` the largest coordinate magnitude).
//!
//! Quadratic convergence is a statement on the error, `e_{k+1} <= C e_k^2` (Newton-Kantorovich;
//! Deuflhard's affine-covariant form has `C = omega / 2`), and is checked on it: the order `p` of the
//! least-squares fit `ln e_{k+1} = ln C + p ln e_k` over the steps whose new error is still 1e3 times
//! above its floor (so that rounding contributes at most 0.1 %) must be within 0.19 of 2, i.e. closer to
//! 2 than to the golden-ratio order 1.618 of a secant-type (superlinear but not quadratic) iteration,
//! the next-best alternative an inexact Jacobian would give; a linearly convergent iteration has
//! order 1. The contractions `e_{k+1} / e_k^2` and the step-wise orders
//! `ln(e_{k+1} / e_k) / ln(e_k / e_{k-1})` are tabulated. The residual max-norm is not affine
//! invariant: it weighs a node's stiff axial balance (`EA / ds`) and its soft transverse balance
//! (`T / ds` and less) alike, so `r_{k+1} / r_k^2` changes by orders of magnitude between iterations
//! while `e_{k+1} / e_k^2` stays steady; it is tabulated too, and the residual is required to reach its
//! floor: `r_K <= 4 R` (a node's residual adds two segment forces, each with a rounding error of
//! about `R`; observed 0.7 to 1.4 `R`).
//! (b) Newmark's average-acceleration integrator with Newton and faer (`implicit::newmark`) on the same
//!     discrete equations: its own time-step convergence (expected order 2), and its difference from the
//!     explicit scheme on the weight release (from straight, weight only) and on the wind step (the settled
//!     catenary suddenly loaded by the aerodynamic wind (2.5) with mu = 0.2), both run with the same step
//!     sequence `dt_k = dt_0 / 2^k` on the same grid, so that the difference is purely temporal and must
//!     vanish as both are refined.

use super::static_convergence::grid;
use crate::convergence::{ls_order, pair_orders};
use crate::implicit::newmark::Newmark;
use crate::report::{Budget, StudyReport, Table, sci};
use crate::setup::{
    Case, G_M_PER_S2, RHO_KG_PER_M, SPAN_M, aerodynamic_wind, loads, params, positions, straight_wire, wave_speed,
};
use ohl::element::tension::LawKind;
use ohl::scheme::Explicit;
use ohl::statics::jacobian::replica_gap;
use ohl::statics::{StaticError, StaticOptions, rounding_floor_n, solve as solve_static};
use ohl_app::plot::{Chart, Series, Style};
use rayon::prelude::*;
use std::path::Path;

/// Node positions at the sample times of a run.
type History = Vec<Vec<[f64; 3]>>;

/// Largest distance between two position histories [m].
fn history_gap(a: &[Vec<[f64; 3]>], b: &[Vec<[f64; 3]>]) -> f64 {
    a.iter().zip(b).map(|(p, q)| crate::setup::max_distance(p, q)).fold(0.0, f64::max)
}

/// The dynamic comparison problems.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dynamic {
    /// straight wire released under its weight
    WeightRelease,
    /// settled catenary, aerodynamic wind switched on at t = 0
    WindStep,
}

/// The initial solver of a dynamic problem on `n` segments with nominal step `dt` [s].
pub fn initial(problem: Dynamic, n: usize, dt: f64) -> Result<Explicit, String> {
    let mut p = params(n, 0.5, 0.0, 0.0);
    p.dt_s = dt;
    match problem {
        Dynamic::WeightRelease => {
            Ok(Explicit::new(straight_wire(n, LawKind::Linear, 0.0), loads(G_M_PER_S2, [0.0; 3], None), p))
        }
        Dynamic::WindStep => {
            let mid = Case::Catenary.exact().position(0.5 * SPAN_M);
            let mut s = Explicit::new(
                crate::setup::parabolic_wire(n, LawKind::Linear, 0.0, [0.0, 0.0, mid[2]]),
                loads(G_M_PER_S2, [0.0; 3], None),
                p,
            );
            solve_static(
                &mut s,
                &StaticOptions {
                    tolerance_n: Some(crate::setup::residual_tolerance(n, RHO_KG_PER_M * G_M_PER_S2)),
                    max_iterations: 40,
                },
            )
            .map_err(|e| e.to_string())?;
            s.loads_mut().wind = Some(aerodynamic_wind(0.2));
            Ok(s)
        }
    }
}

/// Position histories sampled at `samples` equal intervals of a run of `steps` steps of `dt`.
fn run_explicit(problem: Dynamic, n: usize, dt: f64, steps: usize, samples: usize) -> Result<History, String> {
    let mut s = initial(problem, n, dt)?;
    let mut h = vec![positions(s.wire())];
    for k in 1..=steps {
        s.step(dt).map_err(|e| e.to_string())?;
        if k % (steps / samples) == 0 {
            h.push(positions(s.wire()));
        }
    }
    Ok(h)
}

fn run_newmark(problem: Dynamic, n: usize, dt: f64, steps: usize, samples: usize) -> Result<(History, f64), String> {
    let s = initial(problem, n, dt)?;
    let tol = crate::setup::residual_tolerance(n, RHO_KG_PER_M * G_M_PER_S2);
    let mut nm = Newmark::new(s, tol);
    let mut h = vec![positions(nm.sys.wire())];
    for k in 1..=steps {
        nm.step(dt)?;
        if k % (steps / samples) == 0 {
            h.push(positions(nm.sys.wire()));
        }
    }
    Ok((h, nm.newton_iterations as f64 / steps as f64))
}

/// Newton iterations past the rounding floor, for the history.
const NEWTON_ITERATIONS: usize = 8;

/// Newton's iterates on `case` with `n` segments from the `static` study's start.
struct NewtonHistory {
    /// largest nodal residual `r_k` [N], `k = 0..=K`
    residual_n: Vec<f64>,
    /// `e_k = max_i |x_k,i - x_K,i|` [m], `k = 0..=K` (`e_K = 0`)
    error_m: Vec<f64>,
    /// step-length factor of each iteration up to the floor `r <= 4 R` (1 = full Newton step)
    step_factor: Vec<f64>,
    /// residual rounding floor `R` [N] at the solution
    residual_floor_n: f64,
    /// position rounding floor `X eps` [m]
    position_floor_m: f64,
}

fn newton_history(case: Case, n: usize) -> Result<NewtonHistory, String> {
    let mid = case.exact().position(0.5 * SPAN_M);
    let start = crate::setup::explicit_for(case, n, 0.9, 0.0, [0.9 * mid[0], 0.0, 0.9 * mid[2]]);
    let err = |e: StaticError| format!("{} N = {n}: {e}", case.name());
    // `k` iterations with a zero tolerance end at the iteration limit with the solver at the k-th iterate
    // (deterministic: each run repeats the same operations).
    let iterate = |k: usize| -> Result<(Explicit, f64), String> {
        let mut s = start.clone();
        match solve_static(&mut s, &StaticOptions { tolerance_n: Some(0.0), max_iterations: k }) {
            Ok(rep) => Ok((s, rep.residual_n)),
            Err(StaticError::NotConverged { residual_n, .. }) => Ok((s, residual_n)),
            Err(e) => Err(err(e)),
        }
    };
    let runs: Vec<(Explicit, f64)> = (0..=NEWTON_ITERATIONS).map(iterate).collect::<Result<_, _>>()?;
    let last = positions(runs[NEWTON_ITERATIONS].0.wire());
    let floor = rounding_floor_n(&runs[NEWTON_ITERATIONS].0);
    // The step factors up to the floor: a solve with the floor criterion as its tolerance reports them.
    let mut to_floor = start.clone();
    let rep = solve_static(&mut to_floor, &StaticOptions { tolerance_n: Some(4.0 * floor), max_iterations: 40 })
        .map_err(err)?;
    let x_max = last.iter().flat_map(|p| p.iter()).fold(0.0_f64, |m, c| m.max(c.abs()));
    Ok(NewtonHistory {
        residual_n: runs.iter().map(|r| r.1).collect(),
        error_m: runs.iter().map(|r| crate::setup::max_distance(&positions(r.0.wire()), &last)).collect(),
        step_factor: rep.step_factors,
        residual_floor_n: floor,
        position_floor_m: x_max * f64::EPSILON,
    })
}

/// Run the study.
pub fn run(budget: Budget, dir: &Path) -> Result<StudyReport, String> {
    let mut rep = StudyReport {
        title: "Implicit reference on faer: Newton statics, Newmark dynamics".into(),
        summary: "(a) Newton's method on the discrete static equations (residual from the library's `net_force`, \
                  exact Jacobian by forward-mode dual numbers, block-tridiagonal, faer sparse LU), from the \
                  `static` study's start, iterated past the rounding floor: the residual r_k and the error e_k of \
                  each iterate against the last one, with their floors R = (EA/l0) X eps and X eps; quadratic \
                  convergence is asserted on the error (order of e_k+1 = C e_k^p fitted over the steps above \
                  the floor). (b) Newmark \
                  average acceleration with Newton on each step, compared with the explicit scheme with the \
                  same steps on the same grid."
            .into(),
        ..Default::default()
    };
    // (a) Newton statics.
    let n_static = if budget == Budget::Full { 100 } else { 50 };
    let statics: Vec<_> = Case::ALL.par_iter().map(|&c| grid(c, n_static)).collect::<Result<_, _>>()?;
    let histories: Vec<NewtonHistory> =
        Case::ALL.par_iter().map(|&c| newton_history(c, n_static)).collect::<Result<_, _>>()?;
    let mut t_newton = Table::new(
        "implicit_newton",
        &format!(
            "Newton iterates at N = {n_static}: residual r_k (largest nodal force), error e_k = max |x_k - x_K| \
             (K = {NEWTON_ITERATIONS}), their contractions and the step-wise order; 'floor': at the rounding floor \
             (r <= 4 R; e <= 1e3 X eps)"
        ),
        &[
            "case",
            "k",
            "step factor",
            "r_k [N]",
            "r_k / R",
            "r_k / r_k-1^2 [1/N]",
            "e_k [m]",
            "e_k / e_k-1^2 [1/m]",
            "order ln(e_k/e_k-1)/ln(e_k-1/e_k-2)",
        ],
    );
    let mut t_summary = Table::new(
        "implicit_newton_summary",
        &format!(
            "Newton at N = {n_static}: rounding floors, iterations to the floor, fitted order of the error, and the \
             settled explicit state against Newton's"
        ),
        &[
            "case",
            "R = (EA/l0) X eps [N]",
            "X eps [m]",
            "iterations to r <= 4 R",
            "r_K / R",
            "order p (LS of ln e_k+1 on ln e_k)",
            "e_k+1 / e_k^2 [1/m]",
            "max distance DR - Newton / deflection",
        ],
    );
    let mut res_series = vec![];
    let mut err_series = vec![];
    let mut newton_orders = vec![];
    let mut newton_c = (f64::INFINITY, 0.0_f64);
    let mut newton_rc = (f64::INFINITY, 0.0_f64);
    let mut newton_ro = (f64::INFINITY, 0.0_f64);
    let mut newton_e = (0.0_f64, f64::INFINITY);
    for (ci, (r, h)) in statics.iter().zip(&histories).enumerate() {
        let name = r.case.name();
        let (rf, xf) = (h.residual_floor_n, h.position_floor_m);
        let k_last = h.residual_n.len() - 1;
        // Above the floor: the residual with a margin for the few rounding errors it sums (module doc); the
        // error 1e3 times above its floor, so that rounding changes it by at most 0.1 %.
        let r_above = |k: usize| h.residual_n[k] > 4.0 * rf;
        let e_above = |k: usize| k < k_last && h.error_m[k] > 1e3 * xf;
        let order = |k: usize| (h.error_m[k] / h.error_m[k - 1]).ln() / (h.error_m[k - 1] / h.error_m[k - 2]).ln();
        for k in 0..=k_last {
            let (rk, ek) = (h.residual_n[k], h.error_m[k]);
            t_newton.row(vec![
                name.into(),
                k.to_string(),
                if k == 0 { "".into() } else { h.step_factor.get(k - 1).map_or("".into(), |f| format!("{f}")) },
                sci(rk),
                if rk / rf < 100.0 { format!("{:.2}", rk / rf) } else { sci(rk / rf) },
                match k {
                    0 => "".into(),
                    _ if !r_above(k) => "floor".into(),
                    _ => sci(rk / h.residual_n[k - 1].powi(2)),
                },
                if k == k_last { "(reference x_K)".into() } else { sci(ek) },
                match k {
                    0 => "".into(),
                    _ if k == k_last => "".into(),
                    _ if !e_above(k) => "floor".into(),
                    _ => sci(ek / h.error_m[k - 1].powi(2)),
                },
                if k >= 2 && e_above(k) { format!("{:.3}", order(k)) } else { "".into() },
            ]);
        }
        // Quadratic convergence on the steps k -> k+1 whose new error is above its floor (module doc).
        let steps: Vec<usize> = (0..k_last).filter(|&k| e_above(k + 1)).collect();
        let xs: Vec<f64> = steps.iter().map(|&k| h.error_m[k]).collect();
        let ys: Vec<f64> = steps.iter().map(|&k| h.error_m[k + 1]).collect();
        // ls_order fits the slope of ln(y) on ln(x): here the order p of e_k+1 = C e_k^p.
        let p = if steps.len() >= 2 { ls_order(&xs, &ys) } else { f64::NAN };
        let c: Vec<f64> = xs.iter().zip(&ys).map(|(x, y)| y / (x * x)).collect();
        let (c_lo, c_hi) = (c.iter().copied().fold(f64::INFINITY, f64::min), c.iter().copied().fold(0.0, f64::max));
        let k_floor = h.step_factor.len();
        newton_orders.push(p);
        newton_c = (newton_c.0.min(c_lo), newton_c.1.max(c_hi));
        newton_e = (
            newton_e.0.max(xs.first().copied().unwrap_or(0.0)),
            newton_e.1.min(ys.last().copied().unwrap_or(f64::INFINITY)),
        );
        for k in 1..=k_last {
            if r_above(k) {
                let rc = h.residual_n[k] / h.residual_n[k - 1].powi(2);
                newton_rc = (newton_rc.0.min(rc), newton_rc.1.max(rc));
            }
            if k >= 2 && r_above(k) {
                let ro =
                    (h.residual_n[k] / h.residual_n[k - 1]).ln() / (h.residual_n[k - 1] / h.residual_n[k - 2]).ln();
                newton_ro = (newton_ro.0.min(ro), newton_ro.1.max(ro));
            }
        }
        let r_end = h.residual_n[k_last] / rf;
        t_summary.row(vec![
            name.into(),
            sci(rf),
            sci(xf),
            k_floor.to_string(),
            format!("{r_end:.2}"),
            format!("{p:.3} ({} steps)", steps.len()),
            format!("{} .. {}", sci(c_lo), sci(c_hi)),
            sci(r.newton_gap),
        ]);
        rep.check(
            format!("{name}: Newton error order p, e_k+1 = C e_k^p (N = {n_static})"),
            "2 ± 0.19 (closer to 2 than to a secant's 1.618), over >= 3 steps above the floor",
            format!(
                "{p:.3} over {} steps, e {} → {}, C {} .. {} 1/m",
                steps.len(),
                sci(xs.first().copied().unwrap_or(f64::NAN)),
                sci(ys.last().copied().unwrap_or(f64::NAN)),
                sci(c_lo),
                sci(c_hi)
            ),
            steps.len() >= 3 && (p - 2.0).abs() <= 0.19,
        );
        rep.check(
            format!("{name}: Newton residual reaches the rounding floor R = {} N", sci(rf)),
            "r_K <= 4 R",
            format!("r_K = {r_end:.2} R; r <= 4 R after {k_floor} iterations (step factors {:?})", h.step_factor),
            r_end <= 4.0,
        );
        rep.check(
            format!("{name}: settled explicit vs Newton (N = {n_static})"),
            "< 1e-8 relative",
            sci(r.newton_gap),
            r.newton_gap < 1e-8,
        );
        res_series.push(Series::new(
            name,
            h.residual_n.iter().enumerate().map(|(k, &v)| (k as f64, v)).collect(),
            Style::LineMarkers,
            ci,
        ));
        err_series.push(Series::new(
            name,
            h.error_m[..k_last].iter().enumerate().map(|(k, &v)| (k as f64, 1e6 * v)).collect(),
            Style::LineMarkers,
            ci,
        ));
        if ci == 0 {
            res_series.push(Series::new(
                "rounding floor R (every case)",
                vec![(0.0, rf), (k_last as f64, rf)],
                Style::Dashed,
                7,
            ));
            err_series.push(Series::new(
                "X eps (every case)",
                vec![(0.0, 1e6 * xf), (k_last as f64, 1e6 * xf)],
                Style::Dashed,
                7,
            ));
        }
    }
    rep.figure(
        &[
            Chart {
                title: format!("Newton residual, N = {n_static}"),
                x_label: "iteration k [-]".into(),
                y_label: "largest nodal residual r_k [N]".into(),
                series: res_series,
                log_y: true,
                ..Default::default()
            },
            Chart {
                title: format!("Newton error against the last iterate, N = {n_static}"),
                x_label: "iteration k [-]".into(),
                // In micrometres: the floor, about 4e-14 m, stays inside the plot's tick-label range.
                y_label: "max nodal distance e_k = |x_k - x_K| [µm]".into(),
                series: err_series,
                log_y: true,
                y_range: Some((1e-10, 1e7)),
                ..Default::default()
            },
        ],
        2,
        (620, 440),
        &format!("implicit: Newton statics and the implicit reference on faer | {}", crate::setup::PAPER_WIRE),
        dir,
        "newton_convergence",
    )?;
    // Replica check: the Jacobian's function values equal the library's forces (moving, windy state).
    let mut probe = initial(Dynamic::WindStep, 20, 1e-3)?;
    for (i, v) in probe.wire_mut().v[0].iter_mut().enumerate() {
        *v = 0.3 * (i as f64).sin();
    }
    probe.wire_mut().internal_friction_n_s.fill(50.0);
    let gap = replica_gap(&mut probe);
    rep.check("Jacobian replica vs library forces", "< 1e-9 N", sci(gap), gap < 1e-9);

    // (b) Newmark vs explicit.
    let (n, duration, levels) = if budget == Budget::Full { (50, 2.0, 4) } else { (20, 0.5, 3) };
    let samples = 20;
    let ds = SPAN_M / n as f64;
    let steps0 = ((duration * wave_speed() / (0.8 * ds)) / samples as f64).ceil() as usize * samples;
    let dt0 = duration / steps0 as f64;
    let mut t_dyn = Table::new(
        "implicit_newmark",
        &format!(
            "Newmark and explicit on N = {n}, t in [0, {duration}] s, {samples} samples; gaps are max nodal distances [m]"
        ),
        &[
            "problem",
            "dt [s]",
            "Courant",
            "|explicit - Newmark| [m]",
            "Newmark self-gap to dt/2 [m]",
            "explicit self-gap to dt/2 [m]",
            "Newton its/step",
        ],
    );
    let mut charts = vec![];
    for problem in [Dynamic::WeightRelease, Dynamic::WindStep] {
        let runs: Vec<_> = (0..levels)
            .into_par_iter()
            .map(|k| {
                let dt = dt0 / 2f64.powi(k as i32);
                let steps = steps0 << k;
                let e = run_explicit(problem, n, dt, steps, samples)?;
                let (m, its) = run_newmark(problem, n, dt, steps, samples)?;
                Ok((dt, e, m, its))
            })
            .collect::<Result<Vec<_>, String>>()?;
        let name = format!("{problem:?}");
        let diffs: Vec<f64> = runs.iter().map(|r| history_gap(&r.1, &r.2)).collect();
        let nm_self: Vec<f64> = (0..levels - 1).map(|k| history_gap(&runs[k].2, &runs[k + 1].2)).collect();
        let ex_self: Vec<f64> = (0..levels - 1).map(|k| history_gap(&runs[k].1, &runs[k + 1].1)).collect();
        for (k, r) in runs.iter().enumerate() {
            t_dyn.row(vec![
                name.clone(),
                sci(r.0),
                format!("{:.3}", r.0 * wave_speed() / ds),
                sci(diffs[k]),
                nm_self.get(k).map(|v| sci(*v)).unwrap_or_default(),
                ex_self.get(k).map(|v| sci(*v)).unwrap_or_default(),
                format!("{:.2}", r.3),
            ]);
        }
        let dts: Vec<f64> = runs.iter().map(|r| r.0).collect();
        let p_nm = ls_order(&dts[..levels - 1], &nm_self);
        let p_diff = ls_order(&dts, &diffs);
        let shrinking = diffs.windows(2).all(|w| w[1] < w[0]);
        rep.check(
            format!("{name}: Newmark time order (self-convergence)"),
            "2 ± 0.1",
            format!("{p_nm:.3} (pairs {:.2?})", pair_orders(&dts[..levels - 1], &nm_self)),
            (p_nm - 2.0).abs() < 0.1,
        );
        rep.check(
            format!("{name}: explicit-Newmark difference shrinks"),
            "monotone decrease with dt",
            format!("{} → {} (order {p_diff:.2})", sci(diffs[0]), sci(diffs[levels - 1])),
            shrinking,
        );
        charts.push(Chart {
            title: format!("{name}: time-step convergence (N = {n})"),
            x_label: "time step dt [s]".into(),
            y_label: "max nodal distance [m]".into(),
            series: vec![
                Series::new(
                    "|explicit - Newmark|",
                    dts.iter().copied().zip(diffs.iter().copied()).collect(),
                    Style::LineMarkers,
                    0,
                ),
                Series::new(
                    "Newmark dt vs dt/2",
                    dts.iter().copied().zip(nm_self.iter().copied()).collect(),
                    Style::LineMarkers,
                    1,
                ),
                Series::new(
                    "explicit dt vs dt/2",
                    dts.iter().copied().zip(ex_self.iter().copied()).collect(),
                    Style::LineMarkers,
                    2,
                ),
                Series::new(
                    "slope 2",
                    dts.iter().map(|&d| (d, nm_self[0] * (d / dts[0]).powi(2))).collect(),
                    Style::Dashed,
                    7,
                ),
            ],
            log_x: true,
            log_y: true,
            ..Default::default()
        });
        let fine = runs.last().unwrap();
        let mid = n / 2;
        let comp = if problem == Dynamic::WeightRelease { 2 } else { 0 };
        let t = |k: usize| k as f64 * duration / samples as f64;
        charts.push(Chart {
            title: format!("{name}: mid-span x{} (finest dt)", comp + 1),
            x_label: "time t [s]".into(),
            y_label: format!("mid-span x{} [m]", comp + 1),
            series: vec![
                Series::new(
                    "explicit",
                    fine.1.iter().enumerate().map(|(k, p)| (t(k), p[mid][comp])).collect(),
                    Style::Line,
                    0,
                ),
                Series::new(
                    "Newmark (reference)",
                    fine.2.iter().enumerate().map(|(k, p)| (t(k), p[mid][comp])).collect(),
                    Style::Dashed,
                    1,
                ),
            ],
            ..Default::default()
        });
    }
    rep.figure(
        &charts,
        2,
        (620, 440),
        &format!("implicit: Newton statics and the implicit reference on faer | {}", crate::setup::PAPER_WIRE),
        dir,
        "implicit_reference",
    )?;
    rep.tables.push(t_newton);
    rep.tables.push(t_summary);
    rep.tables.push(t_dyn);
    let (p_lo, p_hi) = newton_orders.iter().fold((f64::INFINITY, 0.0_f64), |a, &p| (a.0.min(p), a.1.max(p)));
    rep.discussion = format!(
        "**Newton statics.** {steps_kind}; the residual reaches its floor after {k_floor} iterations, and stays \
         there. The floors: \
         R = (EA/l0) X eps = {r_floor} N at N = {n_static} (an ulp of the coordinates through the axial \
         stiffness, proportional to N) for the residual, X eps = {x_floor} m (X = {x_max:.0} m the largest \
         coordinate) for the error. On the error, the contraction e_k+1 / e_k^2 stays between {c_lo:.2} and \
         {c_hi:.2} 1/m over every step above the floor while e falls from {e_first} m to {e_last} m, and the \
         least-squares order is {p_lo:.3} to {p_hi:.3}: quadratic convergence, which also certifies the \
         Jacobian (an inexact one would give order 1, or about 1.6 for a secant-like update). The residual's \
         contraction r_k+1 / r_k^2 instead ranges over {rc_lo} to {rc_hi} 1/N on the same steps, alternating \
         from one to the next, and its step-wise order ln(r_k+1/r_k)/ln(r_k/r_k-1) over {ro_lo:.2} to \
         {ro_hi:.2}: the largest nodal force weighs a node's stiff axial balance (EA/ds = {axial:.2e} N/m) \
         and its soft transverse balance (T/ds = {transverse:.2e} N/m for one segment of the catenary, less \
         for smooth shapes) alike, and how a residual splits between them changes from step to step. A \
         residual norm is not invariant under a scaling of the equations (Deuflhard, Newton Methods for \
         Nonlinear Problems, 2004, ch. 1-2); the error is, and it is the quantity Newton's theorem bounds. \
         The residual's 'order' is therefore not reported as a convergence order.\n\n\
         **Newmark.** Newmark shows second-order self-convergence. On the weight release (no \
         velocity-dependent forces) the explicit-Newmark gap falls at second order. On the wind step the wind \
         damping (2.6) is evaluated by the explicit kernel with the velocities of the previous half step, an \
         O(dt) lag; the gap still shrinks with dt, with the order shown in the table.",
        k_floor = {
            let (a, b) = histories
                .iter()
                .fold((usize::MAX, 0), |m, h| (m.0.min(h.step_factor.len()), m.1.max(h.step_factor.len())));
            if a == b { format!("{a}") } else { format!("{a} to {b}") }
        },
        steps_kind = if histories.iter().all(|h| h.step_factor.iter().all(|&f| f == 1.0)) {
            "Every iteration down to the floor is a full Newton step (step factor 1)"
        } else {
            "Some iterations before the floor are damped by the line search (step factor below 1, table)"
        },
        r_floor = sci(histories[0].residual_floor_n),
        x_floor = sci(histories[0].position_floor_m),
        x_max = histories[0].position_floor_m / f64::EPSILON,
        c_lo = newton_c.0,
        c_hi = newton_c.1,
        e_first = sci(newton_e.0),
        e_last = sci(newton_e.1),
        rc_lo = sci(newton_rc.0),
        rc_hi = sci(newton_rc.1),
        ro_lo = newton_ro.0,
        ro_hi = newton_ro.1,
        axial = crate::setup::EA_N * n_static as f64 / SPAN_M,
        transverse = Case::Catenary.exact().tension_n(0.5 * SPAN_M) * n_static as f64 / SPAN_M,
    );
    Ok(rep)
}
