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
//! EA = 2.9e7 N (the value); strings of 3.5 m and 100 kg with an axial stiffness of 5e7 N (the
//! order of long-rod and cap-and-pin strings; the results depend on it only through millimetres of
//! stretch).

use ohl::element::tension::LawKind;
use ohl::scheme::{Explicit, Loads, StepParams, WindGate};
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
    let loads = Loads {
        gravity_m_per_s2: G,
        uniform_load_n_per_m: [0.0; 3],
        wind: None,
        wind_scale: 1.0,
        wind_gate: WindGate::Always,
    };
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
