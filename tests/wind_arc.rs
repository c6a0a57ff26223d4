//! Issue test 2: wind only (uniform normal pressure p = 3.805 N/m, no gravity), run until settled; the
//! mid-span deflection against the exact circular arc of an elastic string (`ohl::exact::arc`).
//!
//! Tolerance as for the catenary: the settled polygon under normal pressure is inscribed in a circle with
//! `T = p R cos(delta / 2)` (delta the angle a segment subtends), an O(ds^2) departure; < 0.05 % at
//! N = 50, smaller at N = 100.

use crate::common;
use common::*;
use ohl::exact::arc::ElasticArc;

fn settled_deflection(n: usize) -> [f64; 3] {
    let o = run_in_memory(&format!(
        r#"
        [conductor]
        axial_stiffness_n = {EA_PAPER_N}
        linear_density_kg_per_m = {RHO_PAPER}
        [geometry]
        left_support_m = [0.0, 0.0, 0.0]
        right_support_m = [0.0, {SPAN_M}, 0.0]
        segments = {n}
        [loads]
        gravity_m_per_s2 = 0.0
        wind = {{ law = "uniform_normal", pressure_n_per_m = {P_PAPER_N_PER_M}, speed_m_per_s = 20.0 }}
        [numerics]
        courant = 0.9
        mass_damping_per_s = 0.3
        [duration]
        until_settled = {{ kinetic_energy_fraction = 1e-12, window_s = 2.0, max_time_s = 600.0 }}
        "#
    ));
    assert!(o.summary.settled, "N = {n} did not settle");
    o.summary.final_midspan_displacement_m
}

#[test]
fn settled_deflection_matches_the_exact_arc() {
    let exact = ElasticArc::solve(SPAN_M, SPAN_M, P_PAPER_N_PER_M, EA_PAPER_N).expect("exact arc");
    let f = exact.max_deflection_m();
    let ns = [50, 100];
    let mut errs = Vec::new();
    for &n in &ns {
        let d = settled_deflection(n);
        assert!(d[1].abs() < 1e-9 && d[2].abs() < 1e-9, "left the x1-x2 plane: {d:?}");
        errs.push(((d[0] - f) / f).abs());
    }
    println!("exact arc deflection {f:.9} m ({:.6} l)", f / SPAN_M);
    for (n, e) in ns.iter().zip(&errs) {
        println!("N = {n:4}: relative deflection error {e:.3e}");
    }
    assert!(errs[0] < 5.0e-4, "N = 50: error {:.3e} is not below 0.05 %", errs[0]);
    assert!(errs[1] < errs[0], "refinement did not reduce the error: {errs:?}");
}
