//! Line sections (`ohl::wire::section`, `ohl::wire::insulator`): three 400 m spans of ACSR Drake on
//! 3.5 m, 100 kg suspension strings, strung at 28 kN (20 % of the 140 kN rated strength).
//!
//! Checks, each against an independent expectation:
//! - the static solver's equilibrium of the section strung at one H0 has plumb strings and the span
//!   tensions H0, up to the discretisation error `O(ds^2)` (observed order asserted over three grids);
//! - undamped explicit runs conserve the total energy of conductor, strings and crossarms: leapfrog is
//!   symplectic, so the energy error stays bounded at `O(dt^2)` (relative drift asserted, and its fall
//!   by about 4 when the step is halved);
//! - ice on the middle span swings the strings toward it (sign), and the Newton state is a rest state of
//!   the explicit scheme (the residual of the kernel's own forces is at the solver's tolerance).
//!
//! Source of the data: Drake 795 kcmil 26/7 ACSR, diameter 28.1 mm, 1.628 kg/m, rated strength 140 kN;
//! EA = 2.9e7 N (the issue's value); strings of 3.5 m and 100 kg with an axial stiffness of 5e7 N (the
//! order of long-rod and cap-and-pin strings; the results depend on it only through millimetres of
//! stretch).

use ohl::element::tension::LawKind;
use ohl::scheme::{Explicit, Loads, StepParams};
use ohl::statics::{self, StaticOptions};
use ohl::wire::section::{self, CrossarmSpec, Layout, Section, Span, Stringing, Support};
use ohl::wire::{Conductor, Wire};

const G: f64 = 9.81;
const EA: f64 = 2.9e7;
const RHO: f64 = 1.628;
const H0: f64 = 28_000.0;

/// Three spans of 350, 450 and 400 m with the ground rising (supports at 30, 33.5, 38.5 and 36 m), so
/// that the spans' discrete tensions differ and the strings' discrete swing is not zero by symmetry.
fn drake_section(segments: usize, crossarm: Option<CrossarmSpec>) -> Section {
    let suspension = |y: f64, z: f64| Support::Suspension {
        pivot_m: [0.0, y, z],
        length_m: 3.5,
        mass_kg: 100.0,
        stiffness_n: 5.0e7,
        crossarm,
    };
    let span = Span {
        conductor: Conductor { axial_stiffness_n: EA, internal_friction_n_s: 0.0, law: LawKind::TensionOnly },
        linear_density_kg_per_m: RHO,
        segments,
        stringing: Stringing::HorizontalTension(H0),
    };
    Section {
        supports: vec![
            Support::DeadEnd { point_m: [0.0, 0.0, 30.0] },
            suspension(350.0, 37.0),
            suspension(800.0, 42.0),
            Support::DeadEnd { point_m: [0.0, 1200.0, 36.0] },
        ],
        spans: vec![span; 3],
        gravity_m_per_s2: G,
    }
}

fn solver(wire: Wire, dt_s: f64) -> Explicit {
    let loads = Loads::gravity_only(G);
    Explicit::new(wire, loads, StepParams { dt_s, smoothing: 0.0, mass_damping_per_s: 0.0, max_speed_m_per_s: 4.2e3 })
}

/// Conductor step at Courant `c` on the section's segments [s].
fn step(layout: &Layout, segments: usize, courant: f64) -> f64 {
    courant * layout.unstretched_length_m[0] / segments as f64 / (EA / RHO).sqrt()
}

/// Longitudinal swing of the string of support `k` [rad] (positive toward +x2).
fn swing(s: &Explicit, layout: &Layout, k: usize) -> f64 {
    let w = s.wire();
    let ins = w.insulators.iter().find(|i| i.node == layout.support_node[k]).unwrap();
    ins.swing_rad(w.position(ins.node), layout.along[k])[0]
}

#[test]
fn a_section_strung_at_one_tension_has_plumb_strings_to_second_order() {
    // The continuous section strung at H0 has plumb strings exactly; the discrete one differs by O(ds^2).
    let mut rows = Vec::new();
    for n in [25, 50, 100] {
        let (wire, layout) = section::build(&drake_section(n, None)).unwrap();
        let mut s = solver(wire, 1e-4);
        let report = statics::solve(&mut s, &StaticOptions::default()).unwrap();
        let end_swing = swing(&s, &layout, 1);
        // Horizontal tension of the middle span: the x2 component of the first segment's tension force.
        let w = s.wire();
        let j = layout.first_node[1];
        let d: Vec<f64> = (0..3).map(|k| w.x[k][j + 1] - w.x[k][j]).collect();
        let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        let h = EA * (len / w.rest_length[j] - 1.0) * d[1] / len;
        println!(
            "N = {n:>3} per span: Newton {} iterations, residual {:.2e} N; swing of string 1 {end_swing:+.3e} rad, \
             H of span 1 {h:.4} N (H0 = {H0})",
            report.iterations, report.residual_n
        );
        rows.push((n, end_swing.abs(), (h - H0).abs()));
    }
    // Observed order of the errors between successive grids (ratio of errors, grids halve ds).
    for (name, pick) in [("swing", 1usize), ("H - H0", 2)] {
        let e: Vec<f64> = rows.iter().map(|r| if pick == 1 { r.1 } else { r.2 }).collect();
        let p1 = (e[0] / e[1]).log2();
        let p2 = (e[1] / e[2]).log2();
        println!("{name}: errors {:.3e} {:.3e} {:.3e}, observed orders {p1:.3} {p2:.3}", e[0], e[1], e[2]);
        assert!((p2 - 2.0).abs() < 0.1, "{name}: order {p2} on the finest pair, expected 2 +- 0.1");
    }
}

#[test]
fn energy_is_conserved_with_strings_and_crossarms() {
    // Undamped (no smoothing, no friction): the first crossarm's pivot is pushed 5 cm along the line (a
    // tower swaying) and let go.
    let arm =
        CrossarmSpec { longitudinal_n_per_m: 2.0e5, transverse_n_per_m: 2.0e5, mass_kg: 500.0, damping_n_s_per_m: 0.0 };
    let mut drifts = Vec::new();
    for courant in [0.8, 0.4] {
        let n = 40;
        let (mut wire, layout) = section::build(&drake_section(n, Some(arm))).unwrap();
        wire.insulators[0].pivot_m[1] += 0.05;
        let dt = step(&layout, n, courant);
        let mut s = solver(wire, dt);
        let total = |s: &mut Explicit| {
            let d = s.diagnostics();
            d.kinetic_j + d.elastic_j + d.potential_j
        };
        let e0 = total(&mut s);
        let (mut drift, mut peak_kinetic): (f64, f64) = (0.0, 0.0);
        let steps = (5.0 / dt) as usize;
        for _ in 0..steps {
            s.step(dt).unwrap();
            drift = drift.max((total(&mut s) - e0).abs());
            peak_kinetic = peak_kinetic.max(s.diagnostics().kinetic_j);
        }
        println!("Courant {courant}: dt {dt:.3e} s, 5 s: |E - E0| <= {drift:.3e} J, peak kinetic {peak_kinetic:.3e} J");
        drifts.push(drift / peak_kinetic);
    }
    // Leapfrog keeps a modified energy exactly: the error of the true energy is O(dt^2) and bounded.
    assert!(drifts[0] < 1e-2, "relative energy error {} at Courant 0.8", drifts[0]);
    let order = (drifts[0] / drifts[1]).log2();
    println!("energy error falls by 2^{order:.2} when dt halves");
    assert!(order > 1.7, "energy error order {order}, expected about 2");
}

#[test]
fn ice_on_the_middle_span_swings_the_strings_toward_it() {
    let n = 40;
    let (mut wire, layout) = section::build(&drake_section(n, None)).unwrap();
    // 25 mm radial glaze ice (900 kg/m^3) on Drake: pi ((d/2 + t)^2 - (d/2)^2) 900 = 3.75 kg/m.
    let d: f64 = 0.0281;
    let ice = std::f64::consts::PI * ((0.5 * d + 0.025).powi(2) - (0.5 * d).powi(2)) * 900.0;
    assert!(wire.add_linear_density(layout.segments(1), ice));
    let mut s = solver(wire, 1e-4);
    let report = statics::solve(&mut s, &StaticOptions::default()).unwrap();
    let (a, b) = (swing(&s, &layout, 1), swing(&s, &layout, 2));
    println!("ice {ice:.3} kg/m on span 1: swings {a:+.4} rad, {b:+.4} rad ({} Newton iterations)", report.iterations);
    assert!(a > 0.01 && b < -0.01, "string 1 swings toward +x2, string 2 toward -x2: {a}, {b}");
    assert!(a * b < 0.0 && (a.abs() / b.abs() - 1.0).abs() < 0.5, "comparable and opposite swings: {a} vs {b}");
    // The Newton state is a rest state of the kernel: its own net force vanishes on free nodes.
    let mut f = [vec![0.0; s.wire().nodes()], vec![0.0; s.wire().nodes()], vec![0.0; s.wire().nodes()]];
    s.net_force(&mut f);
    let worst = (0..s.wire().nodes())
        .filter(|&i| s.wire().free[i] > 0.0)
        .map(|i| (0..3).map(|k| f[k][i].abs()).fold(0.0, f64::max))
        .fold(0.0, f64::max);
    assert!(worst <= report.tolerance_n, "kernel residual {worst} N above {}", report.tolerance_n);
}

#[test]
fn newton_balances_elastic_crossarms_and_equals_rigid_arms_at_the_displaced_pivots() {
    // Crossarms of 5e4 N/m along and across the line, ice on the middle span (longitudinal imbalance) and
    // a uniform transverse load of 10 N/m (a 20 m/s wind on Drake is about 7 N/m): the pivots move along
    // and across the line.
    let arm =
        CrossarmSpec { longitudinal_n_per_m: 5.0e4, transverse_n_per_m: 5.0e4, mass_kg: 200.0, damping_n_s_per_m: 0.0 };
    let n = 40;
    let (mut wire, layout) = section::build(&drake_section(n, Some(arm))).unwrap();
    assert!(wire.add_linear_density(layout.segments(1), 3.75));
    let mut s = solver(wire, 1e-4);
    s.loads_mut().uniform_load_n_per_m = [10.0, 0.0, 0.0];
    let report = statics::solve(&mut s, &StaticOptions::default()).unwrap();
    println!("residual history {:?}", report.residual_history);
    // Every pivot in balance: springs against the string's horizontal pull, at the solver's tolerance.
    for ins in &s.wire().insulators {
        let g = statics::pivots::balance(ins, s.wire().position(ins.node));
        let d = ins.pivot_displacement_m();
        println!(
            "pivot of node {}: moved [{:.5}, {:.5}] m, balance [{:.2e}, {:.2e}] N",
            ins.node, d[0], d[1], g[0], g[1]
        );
        assert!(g[0].abs().max(g[1].abs()) <= report.tolerance_n, "pivot balance {g:?}");
        assert!(
            d[0] > 0.05 && d[1].abs() > 1e-3 && d[2] == 0.0,
            "moved across (load), along (ice), not vertically: {d:?}"
        );
    }
    // Newton's last steps are quadratic only if the pivot blocks of the Jacobian are exact: a wrong
    // block would leave linear convergence, contracting by a fixed factor per step.
    let h = &report.residual_history;
    let k = h.len() - 1;
    assert!(h[k] < 1e-3 * h[k - 1], "last step contracts by 1e3 or more: {} -> {}", h[k - 1], h[k]);
    // The same section on rigid crossarms placed at the displaced pivots has the same equilibrium: the
    // pivot unknowns change where the strings hang from, not the conductor's equations.
    let (mut rigid_wire, _) = section::build(&drake_section(n, None)).unwrap();
    assert!(rigid_wire.add_linear_density(layout.segments(1), 3.75));
    for (r, e) in rigid_wire.insulators.iter_mut().zip(&s.wire().insulators) {
        r.pivot_m = e.pivot_m;
    }
    let mut rigid = solver(rigid_wire, 1e-4);
    rigid.loads_mut().uniform_load_n_per_m = [10.0, 0.0, 0.0];
    statics::solve(&mut rigid, &StaticOptions::default()).unwrap();
    let gap = (0..s.wire().nodes())
        .map(|i| {
            let (a, b) = (s.wire().position(i), rigid.wire().position(i));
            (0..3).map(|k| (a[k] - b[k]).abs()).fold(0.0, f64::max)
        })
        .fold(0.0, f64::max);
    // Both residuals are at the default tolerance (1e-10 of the nodal loads, ~1e-7 N); over the softest
    // stiffness of the chain (a string's pendulum stiffness T / l_i ~ 5e3 N/m) that is 1e-10 m; 1e-8 m.
    println!("largest nodal gap to the rigid section at the displaced pivots: {gap:.3e} m");
    assert!(gap < 1e-8, "gap {gap} m");
}

/// A two-span section (2 x 200 m of Drake at 28 kN, 4 m segments) whose middle string (3.5 m, 100 kg, EA
/// 5e7 N) has the axial damping `insulator_damping_n_s = ba` [N s], at rest on its static equilibrium,
/// in a `[section]` scenario without any other damping (no smoothing, no friction, no mass damping).
fn damped_string_section(ba: f64, courant: f64) -> ohl::scenario::Plan {
    let text = format!(
        r#"[conductor]
axial_stiffness_n = 2.9e7
linear_density_kg_per_m = 1.628
[section]
horizontal_tension_n = 28000.0
segments_per_span = 50
supports = [
  {{ kind = "dead_end", point_m = [0.0, 0.0, 30.0] }},
  {{ kind = "suspension", pivot_m = [0.0, 200.0, 33.5], insulator_length_m = 3.5, insulator_mass_kg = 100.0,
     insulator_stiffness_n = 5.0e7, insulator_damping_n_s = {ba:?} }},
  {{ kind = "dead_end", point_m = [0.0, 400.0, 30.0] }},
]
[initial]
shape = "equilibrium"
[numerics]
courant = {courant:?}
smoothing = 0.0
[duration]
end_time_s = 1.0
"#
    );
    let sc = ohl::scenario::parse(&text, "damped.toml").unwrap();
    ohl::scenario::plan(&sc, "damped.toml").unwrap()
}

/// The clamp pulled down along its plumb string by `delta` [m] and let go: a load `k delta` holding it,
/// removed at once (a sudden unloading). Returns the solver.
fn released_clamp(ba: f64, courant: f64, delta: f64) -> Explicit {
    let mut s = damped_string_section(ba, courant).solver;
    let clamp = s.wire().insulators[0].node;
    s.wire_mut().x[2][clamp] -= delta;
    s
}

/// The string's extension `|c - p| - L_i` [m].
fn extension(s: &Explicit) -> f64 {
    let ins = s.wire().insulators[0];
    let c = s.wire().position(ins.node);
    (0..3).map(|k| (c[k] - ins.pivot_m[k]).powi(2)).sum::<f64>().sqrt() - ins.length_m
}

/// A string's axial damping `BA` (`insulator_damping_n_s` of a `[section]` support) damps the clamp's
/// ringing on the string's axial mode at the rate of a damped oscillator: the clamp of mass `m` (string and
/// conductor share) on the spring `k = EA / L_i` with the damper `c = BA / L_i` rings as
/// `x(t) = x0 e^{-c t / (2 m)} cos(omega_d t)`. Measured: the string's extension about its static value in
/// the explicit run, the rate by a least-squares line through the logarithms of its successive maxima.
///
/// The expectation holds to the neglected couplings, each estimated here: the lagged damper of the
/// leapfrog (the force from `v^{n-1/2}`) decays faster by `gamma dt / 2` (1.3 % at Courant 0.2: the
/// per-step factor is `sqrt(1 - gamma dt)`, `gamma = c / m`); the conductor's axial waves, which the clamp's
/// vertical motion launches through the spans' slope `theta ~ w l / (2 H)` at the clamp, carry off
/// energy like a damper of `2 sin^2(theta) sqrt(EA rho)` (45 N s/m, 0.3 % of `c`) until they come back
/// from the dead-ends (0.095 s later; the fit stops before); the spans' geometric stiffness `2 T / l`
/// (1e-3 of `k`) moves the frequency only. Tolerance 3 %: above their sum (about 1.6 %).
#[test]
fn string_damping_damps_the_clamp_ringing_at_the_oscillator_rate() {
    let (ba, courant, delta) = (5.0e4, 0.2, 2.0e-4);
    let mut s = released_clamp(ba, courant, 0.0);
    let e_static = extension(&s);
    let clamp = s.wire().insulators[0].node;
    let (m, c, k) = (s.wire().mass[clamp], ba / 3.5, 5.0e7 / 3.5);
    // The static extension is that of the load the string carries; the perturbation keeps it taut.
    assert!(e_static > 1.2 * delta, "{e_static}");
    s.wire_mut().x[2][clamp] -= delta;
    let dt = s.params().dt_s;
    let (mut t, mut y) = (vec![0.0], vec![extension(&s) - e_static]);
    while s.time_s() < 0.09 {
        s.step(dt).unwrap();
        t.push(s.time_s());
        y.push(extension(&s) - e_static);
    }
    // The maxima of the ringing, down to 1e-3 of the first.
    let peaks: Vec<(f64, f64)> = (1..y.len() - 1)
        .filter(|&i| y[i] > y[i - 1] && y[i] >= y[i + 1] && y[i] > 1e-3 * delta)
        .map(|i| (t[i], y[i].ln()))
        .collect();
    assert!(peaks.len() >= 4, "{peaks:?}");
    let n = peaks.len() as f64;
    let (mt, my) = (peaks.iter().map(|p| p.0).sum::<f64>() / n, peaks.iter().map(|p| p.1).sum::<f64>() / n);
    let slope = peaks.iter().map(|p| (p.0 - mt) * (p.1 - my)).sum::<f64>()
        / peaks.iter().map(|p| (p.0 - mt).powi(2)).sum::<f64>();
    let measured = -slope;
    let expected = c / (2.0 * m);
    let lagged = -(1.0 - c / m * dt).ln() / (2.0 * dt);
    let period = (peaks[peaks.len() - 1].0 - peaks[0].0) / (n - 1.0);
    let omega_d = (k / m - expected * expected).sqrt();
    eprintln!(
        "clamp {m:.2} kg, k {k:.4e} N/m, c {c:.4e} N s/m, dt {dt:.3e} s: {} maxima, decay rate {measured:.3} /s vs \
         c / (2 m) = {expected:.3} /s (ratio {:.4}; with the lagged damper {lagged:.3} /s); log decrement {:.4} vs \
         {:.4}; period {period:.5e} s vs 2 pi / omega_d = {:.5e} s",
        peaks.len(),
        measured / expected,
        measured * period,
        expected * 2.0 * std::f64::consts::PI / omega_d,
        2.0 * std::f64::consts::PI / omega_d
    );
    assert!((measured / expected - 1.0).abs() < 0.03, "{measured} vs {expected}");
    // With the lagged damper's known bias taken in, what is left is the axial waves' 0.3 % (measured 0.33 %).
    assert!((measured / lagged - 1.0).abs() < 0.01, "{measured} vs {lagged}");
    // Undamped, the same ringing does not decay (the axial waves aside): the damping is the string's.
    let mut u = released_clamp(0.0, courant, delta);
    let mut last = 0.0_f64;
    while u.time_s() < 0.09 {
        u.step(dt).unwrap();
        if u.time_s() > 0.07 {
            last = last.max(extension(&u) - e_static);
        }
    }
    eprintln!("undamped: largest excursion over 0.07-0.09 s {last:.3e} m (released at {delta:.1e} m)");
    assert!(last > 0.5 * delta, "{last}");
}

/// The energy budget of the damped string: the change of the total energy (conductor, string; kinetic,
/// elastic, potential) after the release equals the work of the string's damper, summed step by step as
/// its force of each step (the damper part `BA edot` of the string's law, from the velocities the kernel
/// uses, the string taut throughout) times the clamp's displacement over the step. Nothing else
/// dissipates (no smoothing, no friction, no mass damping), so the closing error is the scheme's: it falls
/// at order 2 as the step is refined.
#[test]
fn the_work_of_the_string_damper_is_the_loss_of_energy() {
    let residual = |courant: f64| {
        let mut s = released_clamp(5.0e4, courant, 2.0e-4);
        let dt = s.params().dt_s;
        let total = |s: &mut Explicit| {
            let d = s.diagnostics();
            d.kinetic_j + d.elastic_j + d.potential_j
        };
        let e0 = total(&mut s);
        let mut work = 0.0;
        while s.time_s() < 0.09 {
            let ins = s.wire().insulators[0];
            let i = ins.node;
            let (c0, v) = (s.wire().position(i), [0, 1, 2].map(|k| s.wire().v[k][i]));
            let damper = ohl::element::LinkLaw { axial_stiffness_n: 0.0, compression: true, ..ins.law() };
            let f = damper.force_on_b(ins.pivot_m, c0, [0.0; 3], v);
            assert!(ins.law().tension_and_force_on_b(ins.pivot_m, c0, [0.0; 3], v).0 > 0.0, "the string is taut");
            s.step(dt).unwrap();
            let c1 = s.wire().position(i);
            work += (0..3).map(|k| f[k] * (c1[k] - c0[k])).sum::<f64>();
        }
        let e1 = total(&mut s);
        eprintln!("Courant {courant}: energy change {:.6e} J, damper work {work:.6e} J", e1 - e0);
        assert!(work < 0.0);
        (((e1 - e0) - work) / work).abs()
    };
    let (r1, r2, r3) = (residual(0.4), residual(0.2), residual(0.1));
    let order = ((r1 / r2).log2() + (r2 / r3).log2()) / 2.0;
    eprintln!("string damper energy budget: closing error {r1:.3e}, {r2:.3e}, {r3:.3e} of the work; order {order:.2}");
    assert!(r3 < 1e-2, "{r3}");
    assert!((order - 2.0).abs() < 0.3, "order {order}");
}
