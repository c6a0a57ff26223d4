//! Study `mms`: a manufactured 3D solution for the dynamic equations.
//!
//! The chosen motion (s [m] along the unstretched wire, l = 160 m, k = pi / l):
//!
//! ```text
//! x1 = A sin(k s) sin(w t + 0.3)
//! x2 = (1 + e0) s + B sin(2 k s) cos(w2 t)
//! x3 = -C sin(k s) (1 + 0.3 cos(w t)),     A = 4 m, B = 0.05 m, C = 6 m, e0 = 4e-3, w = 0.8 pi, w2 = 3 pi
//! ```
//!
//! keeps the supports fixed and every segment in tension. The source that makes it exact is the residual
//! of (2.1) with the Kelvin-Voigt law (3.4), gravity and the uniform normal wind pressure with the
//! damping (2.6), per unit unstretched length:
//!
//! ```text
//! S = rho0 r_tt - d/ds(T t) - p lambda f|f| n + rho0 g e3,   lambda = |r_s|, t = r_s / lambda,
//! T = EA (lambda - 1) + eta r_st . t,   n = unit part of e1 normal to t,   f = 1 - mu (r_t . n) / U,
//! d/ds(T t) = T_s t + T t_s,  T_s = EA lambda_s + eta (r_sst . t + r_st . t_s),
//! lambda_s = r_s . r_ss / lambda,  t_s = (r_ss - (t . r_ss) t) / lambda,
//! ```
//!
//! all derivatives of `r` analytic. It enters the kernel as the prescribed nodal force
//! `f_i = ds S(s_i, t_n)` (the lumped-mass integral of `S` over the dual cell to O(ds^3)), set before each
//! step for the time `t_n` of that step's force evaluation; the initial state is the exact `r(s, 0)` and
//! `v(s, 0)`. At a fixed Courant number both `ds` and `dt` are halved together.
//!
//! Variants: (1) no damping: design order 2; (2) Kelvin-Voigt and wind damping, which the kernel evaluates
//! with the velocities of the previous half step (an O(dt) lag): first order asymptotically; (3) velocity
//! smoothing (3.3) at the paper's fixed `beta = 0.02 ds^2` (`b = 0.02`): a numerical viscosity
//! `b ds^2 / dt ~ ds`, first order (docs/paper_notes.md); (4) smoothing with `b = 0.02 (ds / ds_0)`, proportional to
//! `ds`, whose viscosity is O(ds^2): second order restored.

use crate::convergence::{ls_order, pair_orders};
use crate::report::{Budget, StudyReport, Table, sci};
use crate::setup::{
    EA_N, G_M_PER_S2, P_N_PER_M, RHO_KG_PER_M, SPAN_M, WIND_U_M_PER_S, loads, params, uniform_wind, wave_speed,
};
use ohl::element::tension::LawKind;
use ohl::scheme::Explicit;
use ohl::wire::{Conductor, Wire};
use ohl_app::plot::{Chart, Series, Style};
use rayon::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI};
use std::path::Path;

const K: f64 = PI / SPAN_M;
const E0: f64 = 4e-3;
const W1: f64 = 0.8 * PI;
const W2: f64 = 3.0 * PI;

/// One separable term `amp sin(ks s + ps) sin(kt t + pt)` of component `comp`.
struct Term {
    comp: usize,
    amp: f64,
    ks: f64,
    ps: f64,
    kt: f64,
    pt: f64,
}

const TERMS: [Term; 5] = [
    Term { comp: 0, amp: 4.0, ks: K, ps: 0.0, kt: W1, pt: 0.3 },
    Term { comp: 1, amp: 0.05, ks: 2.0 * K, ps: 0.0, kt: W2, pt: FRAC_PI_2 },
    Term { comp: 2, amp: -6.0, ks: K, ps: 0.0, kt: 0.0, pt: FRAC_PI_2 },
    Term { comp: 2, amp: -1.8, ks: K, ps: 0.0, kt: W1, pt: FRAC_PI_2 },
    Term { comp: 1, amp: 0.0, ks: 0.0, ps: 0.0, kt: 0.0, pt: 0.0 },
];

/// `d^ns/ds^ns d^nt/dt^nt r(s, t)`.
fn r(s: f64, t: f64, ns: i32, nt: i32) -> [f64; 3] {
    let mut out = [0.0; 3];
    for term in &TERMS {
        let fs = term.ks.powi(ns) * (term.ks * s + term.ps + ns as f64 * FRAC_PI_2).sin();
        let ft = term.kt.powi(nt) * (term.kt * t + term.pt + nt as f64 * FRAC_PI_2).sin();
        out[term.comp] += term.amp * fs * ft;
    }
    if nt == 0 {
        match ns {
            0 => out[1] += (1.0 + E0) * s,
            1 => out[1] += 1.0 + E0,
            _ => {}
        }
    }
    out
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Physical parameters of a variant.
#[derive(Clone, Copy, Debug)]
struct Physics {
    eta: f64,
    mu: f64,
}

/// The source `S(s, t)` [N/m].
fn source(s: f64, t: f64, ph: Physics) -> [f64; 3] {
    let (rs, rss, rt, rst, rsst, rtt) =
        (r(s, t, 1, 0), r(s, t, 2, 0), r(s, t, 0, 1), r(s, t, 1, 1), r(s, t, 2, 1), r(s, t, 0, 2));
    let lam = dot(rs, rs).sqrt();
    let tv = rs.map(|c| c / lam);
    let lam_s = dot(rs, rss) / lam;
    let trss = dot(tv, rss);
    let ts: [f64; 3] = std::array::from_fn(|k| (rss[k] - trss * tv[k]) / lam);
    let edot = dot(rst, tv);
    let edot_s = dot(rsst, tv) + dot(rst, ts);
    let tension = EA_N * (lam - 1.0) + ph.eta * edot;
    let tension_s = EA_N * lam_s + ph.eta * edot_s;
    let w = [1.0, 0.0, 0.0];
    let wt = dot(w, tv);
    let wp: [f64; 3] = std::array::from_fn(|k| w[k] - wt * tv[k]);
    let sn = dot(wp, wp).sqrt();
    let n = wp.map(|c| c / sn);
    let f = 1.0 - ph.mu / WIND_U_M_PER_S * dot(rt, n);
    let load = P_N_PER_M * lam * f * f.abs();
    std::array::from_fn(|k| {
        RHO_KG_PER_M * rtt[k] - (tension_s * tv[k] + tension * ts[k]) - load * n[k]
            + if k == 2 { RHO_KG_PER_M * G_M_PER_S2 } else { 0.0 }
    })
}

/// A variant of the study.
#[derive(Clone, Copy, Debug)]
struct Variant {
    name: &'static str,
    physics: Physics,
    /// smoothing `b` on the coarsest grid
    b0: f64,
    /// `b` proportional to `ds` (else fixed)
    b_scaled: bool,
    /// design order
    design: f64,
}

const VARIANTS: [Variant; 4] = [
    Variant { name: "undamped", physics: Physics { eta: 0.0, mu: 0.0 }, b0: 0.0, b_scaled: false, design: 2.0 },
    Variant {
        name: "KV + wind damping (lagged)",
        physics: Physics { eta: 200.0, mu: 0.2 },
        b0: 0.0,
        b_scaled: false,
        design: 1.0,
    },
    Variant {
        name: "smoothing b = 0.02 fixed",
        physics: Physics { eta: 0.0, mu: 0.0 },
        b0: 0.02,
        b_scaled: false,
        design: 1.0,
    },
    Variant {
        name: "smoothing b = 0.02 ds/ds0",
        physics: Physics { eta: 0.0, mu: 0.0 },
        b0: 0.02,
        b_scaled: true,
        design: 2.0,
    },
];

/// Courant number of every run (below the friction limit sqrt(1 + z^2) - z = 0.59 at N = 400, eta = 200).
const COURANT: f64 = 0.5;
const DURATION_S: f64 = 1.0;
const SAMPLES: usize = 10;

/// Largest nodal error [m] over the samples of a run on `n` segments with `steps` steps.
fn run_one(v: Variant, n: usize, n0: usize, steps: usize) -> Result<f64, String> {
    let ds = SPAN_M / n as f64;
    let x: [Vec<f64>; 3] = std::array::from_fn(|k| (0..=n).map(|i| r(i as f64 * ds, 0.0, 0, 0)[k]).collect());
    let conductor = Conductor { axial_stiffness_n: EA_N, internal_friction_n_s: v.physics.eta, law: LawKind::Linear };
    let mut wire = Wire::new(conductor, x, vec![ds; n], RHO_KG_PER_M);
    for i in 0..=n {
        let vi = r(i as f64 * ds, 0.0, 0, 1);
        for k in 0..3 {
            wire.v[k][i] = vi[k] * wire.free[i];
        }
    }
    let b = if v.b_scaled { v.b0 * n0 as f64 / n as f64 } else { v.b0 };
    let mut p = params(n, COURANT, b, 0.0);
    p.dt_s = DURATION_S / steps as f64;
    let wind = if v.physics.mu > 0.0 || v.physics.eta > 0.0 { uniform_wind(v.physics.mu) } else { uniform_wind(0.0) };
    let mut s = Explicit::new(wire, loads(G_M_PER_S2, [0.0; 3], Some(wind)), p);
    let mut f: [Vec<f64>; 3] = std::array::from_fn(|_| vec![0.0; n + 1]);
    let mut err: f64 = 0.0;
    for step in 1..=steps {
        let t = s.time_s();
        for i in 1..n {
            let src = source(i as f64 * ds, t, v.physics);
            for k in 0..3 {
                f[k][i] = ds * src[k];
            }
        }
        s.set_nodal_force(Some(f.clone()));
        s.step(p.dt_s).map_err(|e| e.to_string())?;
        if step % (steps / SAMPLES) == 0 {
            let t = step as f64 * p.dt_s;
            for i in 0..=n {
                let e = r(i as f64 * ds, t, 0, 0);
                let q = s.wire().position(i);
                err = err.max(((q[0] - e[0]).powi(2) + (q[1] - e[1]).powi(2) + (q[2] - e[2]).powi(2)).sqrt());
            }
        }
    }
    Ok(err)
}

/// Run the study.
pub fn run(budget: Budget, dir: &Path) -> Result<StudyReport, String> {
    let ns: Vec<usize> = match budget {
        Budget::Coarse => vec![50, 100, 200],
        Budget::Full => vec![25, 50, 100, 200, 400],
    };
    let n0 = ns[0];
    let steps0 =
        ((DURATION_S * wave_speed() / (COURANT * SPAN_M / n0 as f64)) / SAMPLES as f64).ceil() as usize * SAMPLES;
    let jobs: Vec<(usize, usize)> = (0..VARIANTS.len()).flat_map(|v| (0..ns.len()).map(move |g| (v, g))).collect();
    let errs: Vec<f64> =
        jobs.par_iter().map(|&(v, g)| run_one(VARIANTS[v], ns[g], n0, steps0 << g)).collect::<Result<_, _>>()?;
    let mut rep = StudyReport {
        title: "Manufactured solution: space-time order of the dynamic scheme".into(),
        summary: format!(
            "A smooth 3D motion of the whole span (transverse amplitudes 4 m and 6 m, a longitudinal wave, tension \
             always positive) is made exact by a source term including Kelvin-Voigt friction, gravity and the \
             uniform normal wind with damping (2.6). Grids N = {ns:?} at a fixed Courant number {COURANT} \
             (dt halves with ds), t in [0, {DURATION_S}] s; the error is the largest nodal distance to the exact \
             motion over {SAMPLES} sample times."
        ),
        ..Default::default()
    };
    let mut table = Table::new(
        "mms_errors",
        "Largest nodal error [m] of each variant, and observed orders (least squares over the three finest grids)",
        &["variant", "N", "error [m]", "pair order", "observed order (LS)", "design order"],
    );
    let h: Vec<f64> = ns.iter().map(|&n| SPAN_M / n as f64).collect();
    let mut series = vec![];
    for (vi, v) in VARIANTS.iter().enumerate() {
        let e: Vec<f64> = errs[vi * ns.len()..(vi + 1) * ns.len()].to_vec();
        let k = e.len();
        let p = ls_order(&h[k - 3..], &e[k - 3..]);
        let pairs = pair_orders(&h, &e);
        for g in 0..k {
            table.row(vec![
                v.name.into(),
                ns[g].to_string(),
                sci(e[g]),
                if g > 0 { format!("{:.3}", pairs[g - 1]) } else { String::new() },
                if g == k - 1 { format!("{p:.3}") } else { String::new() },
                format!("{}", v.design),
            ]);
        }
        if v.physics.eta > 0.0 {
            // The lag error (first order) hides under the second-order spatial error on coarse grids: the
            // pair orders fall from 2 towards 1 as the grid is refined. On the full budget the last pair must
            // be near 1; on the coarse one (N = 50, 100, 200) only the start of the fall below 2 is asserted.
            let last = pairs[pairs.len() - 1];
            let (expect, pass) = match budget {
                Budget::Full => ("last pair order 1 ± 0.3 (asymptotically first order)", (last - 1.0).abs() < 0.3),
                Budget::Coarse => {
                    ("error above the undamped one, pair order <= 2.1", e[k - 1] > errs[k - 1] && last < 2.1)
                }
            };
            rep.check(format!("{}: order", v.name), expect, format!("pairs {pairs:.3?}, LS {p:.3}"), pass);
        } else {
            let tol = if v.design == 2.0 { 0.1 } else { 0.25 };
            rep.check(
                format!("{}: observed order", v.name),
                format!("{} ± {tol}", v.design),
                format!("{p:.3}"),
                (p - v.design).abs() < tol,
            );
        }
        series.push(Series::new(
            v.name,
            ns.iter().map(|&n| n as f64).zip(e.iter().copied()).collect(),
            Style::LineMarkers,
            vi,
        ));
    }
    let e_ref = errs[0];
    series.push(Series::new(
        "slope -2",
        ns.iter().map(|&n| (n as f64, e_ref * (n0 as f64 / n as f64).powi(2))).collect(),
        Style::Dashed,
        7,
    ));
    series.push(Series::new(
        "slope -1",
        ns.iter().map(|&n| (n as f64, e_ref * (n0 as f64 / n as f64))).collect(),
        Style::Dashed,
        6,
    ));
    rep.figure(
        &[Chart {
            title: format!("Manufactured solution, fixed Courant number {COURANT}"),
            x_label: "segments N [-] (dt proportional to 1/N)".into(),
            y_label: "max nodal error [m]".into(),
            series,
            log_x: true,
            log_y: true,
            ..Default::default()
        }],
        1,
        (760, 520),
        &format!("mms: manufactured 3D solution of the dynamic equations | {}", crate::setup::PAPER_WIRE),
        dir,
        "mms_convergence",
    )?;
    rep.tables.push(table);
    rep.discussion = "Without damping the scheme is second order in space and time together. The Kelvin-Voigt strain \
        rate and the wind damping (2.6) are evaluated with the velocities of the previous half step: the force \
        is then wrong by eta (dt/2) de/dt^2 per unit strain rate, a consistent O(dt) error that makes the damped \
        scheme first order (it would be second order with the velocity extrapolated to t_n, e.g. \
        v^n = (3 v^{n-1/2} - v^{n-3/2}) / 2, at the price of a different stability limit). The paper's smoothing \
        (3.3) with beta = 0.02 ds^2 is a numerical viscosity beta/dt ~ ds: first order, exactly as docs/paper_notes.md \
        predicts. Scaling the coefficient with the grid, b = b0 ds/ds0 (beta ~ ds^3), makes that viscosity \
        O(ds^2) and restores second order while keeping the same damping of the highest modes on the coarsest \
        grid."
        .into();
    Ok(rep)
}
