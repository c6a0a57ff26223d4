//! Study `exact`: each exact reference built by one function and checked against an independent route.
//!
//! * Elastic catenary, unequal support heights (Irvine, `ohl::exact::catenary`, closure solved to 1e-12):
//!   integrate the equilibrium ODE `dT/ds = -q`, `dr/ds = (1 + |T|/EA) T/|T|` by RK4 from support A with
//!   the solution's end tension, and compare the path with the closed form and its end with support B.
//! * Elastic arc under uniform normal pressure (`ohl::exact::arc`): integrate `dtheta/ds = p lambda / T`,
//!   `dr/ds = lambda (cos theta, sin theta)` by RK4 from the support angle and compare.
//! * Combined wind-and-weight catenary: the same ODE route, plus the check that the cable lies in the plane
//!   of the chord and the resultant load.
//! * Taut-string modes (`ohl::exact::modes`): run the explicit scheme on a taut string started in the
//!   first transverse mode (and separately the first longitudinal mode) and measure the frequency from the
//!   zero crossings; compare with the lumped chain's exact frequency and the continuous one.
//! * Heat equation for the two insulated halves (`ohl::exact::heat`): the Fourier series against the
//!   method of images, and the equalisation temperature 1.35695 of section 5.4.

use crate::report::{Budget, StudyReport, Table, sci};
use crate::setup::{EA_N, G_M_PER_S2, P_N_PER_M, RHO_KG_PER_M, SPAN_M, loads, params};
use ohl::element::tension::LawKind;
use ohl::exact::modes::TautString;
use ohl::exact::{ElasticArc, ElasticCatenary};
use ohl::scheme::Explicit;
use ohl::wire::{Conductor, Wire};
use ohl_app::plot::{Chart, Series, Style};
use std::path::Path;

/// RK4 route for a catenary: largest distance of the path from the closed form and of the end from B [m].
fn catenary_route(c: &ElasticCatenary, b: [f64; 3], steps: usize) -> (f64, f64) {
    let q = c.load_n_per_m();
    let l0 = c.unstretched_length_m();
    let t0 = c.tension_vector_n(0.0);
    let tension = |s: f64| [t0[0] - q[0] * s, t0[1] - q[1] * s, t0[2] - q[2] * s];
    let f = |s: f64| {
        let t = tension(s);
        let m = (t[0] * t[0] + t[1] * t[1] + t[2] * t[2]).sqrt();
        let k = (1.0 + m / EA_N) / m;
        [k * t[0], k * t[1], k * t[2]]
    };
    let h = l0 / steps as f64;
    let mut r = c.position(0.0);
    let mut worst: f64 = 0.0;
    for i in 0..steps {
        let s = i as f64 * h;
        let (k1, k2, k4) = (f(s), f(s + 0.5 * h), f(s + h));
        for k in 0..3 {
            r[k] += h / 6.0 * (k1[k] + 4.0 * k2[k] + k4[k]);
        }
        let e = c.position(s + h);
        worst = worst.max(((r[0] - e[0]).powi(2) + (r[1] - e[1]).powi(2) + (r[2] - e[2]).powi(2)).sqrt());
    }
    let end = ((r[0] - b[0]).powi(2) + (r[1] - b[1]).powi(2) + (r[2] - b[2]).powi(2)).sqrt();
    (worst, end)
}

/// Frequency [Hz] of the explicit scheme's free vibration of a taut string (N segments) started in mode 1
/// of the given component (0: transverse x1, 1: longitudinal x2), from zero crossings of node `N/2` (or
/// `N/4` for the longitudinal mode, whose mode-1 displacement is maximal at mid-span too).
fn measured_frequency(string: &TautString, n: usize, comp: usize) -> f64 {
    let l0 = string.unstretched_length_m;
    let ds = l0 / n as f64;
    let amp = if comp == 0 { 0.01 } else { 1e-4 };
    let x: [Vec<f64>; 3] = std::array::from_fn(|k| {
        (0..=n)
            .map(|i| {
                let s = i as f64 * ds;
                let base = if k == 1 { s * (1.0 + string.prestrain) } else { 0.0 };
                base + if k == comp { amp * (std::f64::consts::PI * s / l0).sin() } else { 0.0 }
            })
            .collect()
    });
    let conductor = Conductor { axial_stiffness_n: EA_N, internal_friction_n_s: 0.0, law: LawKind::Linear };
    let wire = Wire::new(conductor, x, vec![ds; n], RHO_KG_PER_M);
    let mut s = Explicit::new(wire, loads(0.0, [0.0; 3], None), params(n, 0.5, 0.0, 0.0));
    let dt = s.params().dt_s;
    let mid = n / 2;
    let rest = if comp == 1 { mid as f64 * ds * (1.0 + string.prestrain) } else { 0.0 };
    let period_guess =
        1.0 / string.discrete_transverse_frequency_hz(1, n).min(string.discrete_longitudinal_frequency_hz(1, n));
    let period_guess = if comp == 0 {
        1.0 / string.discrete_transverse_frequency_hz(1, n)
    } else {
        period_guess.min(1.0 / string.discrete_longitudinal_frequency_hz(1, n))
    };
    let mut crossings = vec![];
    let mut prev = s.wire().x[comp][mid] - rest;
    while s.time_s() < 3.2 * period_guess {
        let t0 = s.time_s();
        if s.step(dt).is_err() {
            return f64::NAN;
        }
        let cur = s.wire().x[comp][mid] - rest;
        if prev * cur < 0.0 {
            crossings.push(t0 + dt * prev / (prev - cur));
        }
        prev = cur;
    }
    let k = crossings.len();
    if k < 2 {
        return f64::NAN;
    }
    (k - 1) as f64 / (2.0 * (crossings[k - 1] - crossings[0]))
}

/// Run the study.
pub fn run(budget: Budget, dir: &Path) -> Result<StudyReport, String> {
    let mut rep = StudyReport {
        title: "Exact references and their independent checks".into(),
        summary: "Each exact reference is computed by one library function and checked here against a different \
                  route (ODE integration, a free-vibration run, a second series)."
            .into(),
        ..Default::default()
    };
    let mut table = Table::new(
        "exact_references",
        "Reference vs independent route",
        &["reference", "quantity", "value", "independent route", "difference"],
    );
    let err = |e: ohl::exact::ExactError| e.to_string();
    // 1. Unequal heights.
    let b = [0.0, SPAN_M, 20.0];
    let cat = ElasticCatenary::solve([0.0; 3], b, 168.0, [0.0, 0.0, -RHO_KG_PER_M * G_M_PER_S2], EA_N).map_err(err)?;
    let (path, end) = catenary_route(&cat, b, 4000);
    table.row(vec![
        "catenary, B 20 m higher, L0 = 168 m".into(),
        "closure residual [-]".into(),
        sci(cat.closure_residual()),
        "RK4 path / end [m]".into(),
        format!("{} / {}", sci(path), sci(end)),
    ]);
    rep.check(
        "catenary (unequal heights): closure",
        "<= 1e-12",
        sci(cat.closure_residual()),
        cat.closure_residual() <= 1e-12,
    );
    rep.check(
        "catenary (unequal heights): RK4 route",
        "path and end within 1e-9 m",
        format!("{} / {}", sci(path), sci(end)),
        path < 1e-9 && end < 1e-9,
    );
    // 2. Arc.
    let arc = ElasticArc::solve(SPAN_M, SPAN_M, P_N_PER_M, EA_N).map_err(err)?;
    let (phi, t, lam) = (arc.half_angle_rad(), arc.tension_n(), 1.0 + arc.strain());
    let steps = 4000;
    let h = SPAN_M / steps as f64;
    // State (xi, zeta, theta): theta the tangent angle from the chord towards the pressure side.
    let f = |y: [f64; 3]| [lam * y[2].cos(), lam * y[2].sin(), -P_N_PER_M * lam / t];
    let mut y = [0.0, 0.0, phi];
    let mut worst: f64 = 0.0;
    for i in 0..steps {
        let k1 = f(y);
        let y2: [f64; 3] = std::array::from_fn(|k| y[k] + 0.5 * h * k1[k]);
        let k2 = f(y2);
        let y3: [f64; 3] = std::array::from_fn(|k| y[k] + 0.5 * h * k2[k]);
        let k3 = f(y3);
        let y4: [f64; 3] = std::array::from_fn(|k| y[k] + h * k3[k]);
        let k4 = f(y4);
        for k in 0..3 {
            y[k] += h / 6.0 * (k1[k] + 2.0 * k2[k] + 2.0 * k3[k] + k4[k]);
        }
        let (xi, zeta) = arc.position((i + 1) as f64 * h);
        worst = worst.max(((y[0] - xi).powi(2) + (y[1] - zeta).powi(2)).sqrt());
    }
    table.row(vec![
        "arc (section 4.1)".into(),
        "mid-span deflection [m]".into(),
        format!("{:.9}", arc.max_deflection_m()),
        "RK4 path [m]".into(),
        sci(worst),
    ]);
    rep.check("arc: RK4 route", "path within 1e-9 m", sci(worst), worst < 1e-9);
    // 3. Combined.
    let q = [P_N_PER_M, 0.0, -RHO_KG_PER_M * G_M_PER_S2];
    let comb = ElasticCatenary::solve([0.0; 3], [0.0, SPAN_M, 0.0], SPAN_M, q, EA_N).map_err(err)?;
    let (path, end) = catenary_route(&comb, [0.0, SPAN_M, 0.0], 4000);
    // Plane of chord e2 and q: normal (q x e2) / |.|.
    let nrm = [-q[2], 0.0, q[0]];
    let nn = (nrm[0] * nrm[0] + nrm[2] * nrm[2]).sqrt();
    let off = (0..=100)
        .map(|i| {
            let p = comb.position(i as f64 * SPAN_M / 100.0);
            ((p[0] * nrm[0] + p[2] * nrm[2]) / nn).abs()
        })
        .fold(0.0, f64::max);
    let d = comb.midspan_displacement_m();
    table.row(vec![
        "combined wind + weight".into(),
        "mid-span x1, x3 [m]".into(),
        format!("{:.6}, {:.6}", d[0], d[2]),
        "RK4 path / end; out of plane [m]".into(),
        format!("{} / {}; {}", sci(path), sci(end), sci(off)),
    ]);
    rep.check(
        "combined: RK4 route and plane of the resultant",
        "within 1e-9 m",
        format!("{} / {} / {}", sci(path), sci(end), sci(off)),
        path < 1e-9 && end < 1e-9 && off < 1e-9,
    );
    // 4. Modes.
    let string = TautString::new(SPAN_M, RHO_KG_PER_M, EA_N, 5e-3).map_err(err)?;
    let ns: Vec<usize> = if budget == Budget::Full { vec![20, 40, 80] } else { vec![20, 40] };
    let mut ser = [vec![], vec![], vec![]];
    for &n in &ns {
        for comp in [0, 1] {
            let fm = measured_frequency(&string, n, comp);
            let (fd, fc, name) = if comp == 0 {
                (string.discrete_transverse_frequency_hz(1, n), string.transverse_frequency_hz(1), "transverse")
            } else {
                (string.discrete_longitudinal_frequency_hz(1, n), string.longitudinal_frequency_hz(1), "longitudinal")
            };
            let rel = (fm - fd).abs() / fd;
            table.row(vec![
                format!("taut string, {name} mode 1, N = {n}"),
                "frequency [Hz] (continuous)".into(),
                format!("{fc:.6}"),
                format!("explicit run {fm:.6} vs chain {fd:.6}"),
                sci(rel),
            ]);
            // Tolerance: the leapfrog's own dispersion (omega dt)^2/24 plus the zero-crossing interpolation;
            // 2e-3 covers both at Courant 0.5 for the longitudinal mode and is far tighter for the transverse one.
            rep.check(
                format!("{name} mode 1 (N = {n}): explicit run vs exact chain frequency"),
                "< 2e-3 relative",
                sci(rel),
                rel < 2e-3,
            );
            if comp == 0 {
                ser[0].push((n as f64, fm));
                ser[1].push((n as f64, fd));
                ser[2].push((n as f64, fc));
            }
        }
    }
    // 5. Heat.
    let mut worst_heat: f64 = 0.0;
    for &t in &[1e-3, 5e-3, 0.02, 0.1, 0.5] {
        for i in 0..=20 {
            let s = i as f64 / 20.0;
            let a = ohl::exact::heat::two_halves_fourier(1.7322, 0.9817, s, t);
            let b = ohl::exact::heat::two_halves_images(1.7322, 0.9817, s, t);
            worst_heat = worst_heat.max((a - b).abs());
        }
    }
    let late = ohl::exact::heat::two_halves(1.7322, 0.9817, 0.3, 5.0);
    table.row(vec![
        "heat, two insulated halves (5.1)".into(),
        "u(0.3, t = 5)".into(),
        format!("{late:.6}"),
        "Fourier vs images, max diff".into(),
        sci(worst_heat),
    ]);
    rep.check("heat: Fourier series vs method of images", "< 1e-12", sci(worst_heat), worst_heat < 1e-12);
    rep.check(
        "heat: equalisation temperature",
        "1.35695 (section 5.4)",
        format!("{late:.6}"),
        (late - 1.35695).abs() < 1e-6,
    );
    rep.figure(
        &[Chart {
            title: "Taut string, transverse mode 1".into(),
            x_label: "segments N [-]".into(),
            y_label: "frequency [Hz]".into(),
            series: vec![
                Series::new("explicit run", ser[0].clone(), Style::Markers, 0),
                Series::new("lumped chain (exact)", ser[1].clone(), Style::Dashed, 1),
                Series::new("continuous string", ser[2].clone(), Style::Line, 2),
            ],
            ..Default::default()
        }],
        1,
        (640, 440),
        &format!("exact: the exact references against independent routes | {}", crate::setup::PAPER_WIRE),
        dir,
        "exact_references",
    )?;
    rep.tables.push(table);
    Ok(rep)
}
