//! Issue test 1: weight only, released from straight and run until settled (dynamic relaxation);
//! the mid-span sag against the exact elastic catenary with the same unstretched length (Irvine's
//! parametric solution, solved by Newton in `ohl::exact`), not the paper's parabola (4.3)-(4.4).
//!
//! Tolerance: the scheme's settled state is the equilibrium of a lumped-mass chain, which differs from
//! the continuous catenary by O(ds^2); the issue asks for < 0.05 % at N = 50 and a smaller error at
//! N = 100. Settling to a kinetic energy of 1e-12 of its peak leaves a residual motion of order
//! sqrt(2 KE / M) / omega ~ 1e-6 m, i.e. 1e-7 relative: negligible against both.

use crate::common;
use common::*;
use ohl::exact::catenary::ElasticCatenary;

fn settled_sag(n: usize) -> f64 {
    let o = run_in_memory(&format!(
        r#"
        [conductor]
        axial_stiffness_n = {EA_PAPER_N}
        linear_density_kg_per_m = {RHO_PAPER}
        [geometry]
        left_support_m = [0.0, 0.0, 0.0]
        right_support_m = [0.0, {SPAN_M}, 0.0]
        segments = {n}
        [numerics]
        courant = 0.9
        mass_damping_per_s = 0.3
        [duration]
        until_settled = {{ kinetic_energy_fraction = 1e-12, window_s = 2.0, max_time_s = 600.0 }}
        "#
    ));
    assert!(o.summary.settled, "N = {n} did not settle: {:?}", o.summary);
    let d = o.summary.final_midspan_displacement_m;
    assert!(d[0].abs() < 1e-9 && d[1].abs() < 1e-9, "plane problem left its plane: {d:?}");
    d[2]
}

#[test]
fn settled_sag_matches_the_exact_elastic_catenary() {
    let exact = ElasticCatenary::level(SPAN_M, SPAN_M, RHO_PAPER * 9.81, EA_PAPER_N).expect("exact catenary");
    let sag = exact.midspan_displacement_m()[2];
    let ns = [50, 100];
    let errs: Vec<f64> = ns.iter().map(|&n| ((settled_sag(n) - sag) / sag).abs()).collect();
    println!("exact elastic catenary mid-span x3 = {sag:.9} m");
    for (n, e) in ns.iter().zip(&errs) {
        println!("N = {n:4}: relative sag error {e:.3e}");
    }
    assert!(errs[0] < 5.0e-4, "N = 50: error {:.3e} is not below 0.05 %", errs[0]);
    assert!(errs[1] < errs[0], "refinement did not reduce the error: {errs:?}");
}
