//! Issue test 3: with eta = mu = 0 and no smoothing or other damping, the total of kinetic, elastic and
//! gravitational energy is conserved by the leapfrog up to an O(dt^2) oscillation (it is symplectic);
//! over 10 s of the weight release it must stay within 0.1 % of the peak kinetic energy.
//!
//! The kinetic energy uses the synchronised velocity `v^n = v^{n-1/2} + dt/2 a^n`; the bound 0.1 % is
//! the issue's. The observed drift is printed so that the margin is visible.

use crate::common;
use common::*;

#[test]
fn total_energy_is_conserved_without_damping() {
    let o = run_in_memory(&format!(
        r#"
        [conductor]
        axial_stiffness_n = {EA_PAPER_N}
        linear_density_kg_per_m = {RHO_PAPER}
        [geometry]
        left_support_m = [0.0, 0.0, 0.0]
        right_support_m = [0.0, {SPAN_M}, 0.0]
        segments = 50
        [numerics]
        courant = 0.9
        smoothing = 0.0
        [duration]
        end_time_s = 10.0
        [output]
        sample_interval_s = 0.01
        "#
    ));
    let s = &o.samples;
    assert!(s.len() > 900, "expected ~1000 samples, got {}", s.len());
    let e0 = s[0].total_j;
    let peak_ke = s.iter().map(|r| r.kinetic_j).fold(0.0, f64::max);
    let drift = s.iter().map(|r| (r.total_j - e0).abs()).fold(0.0, f64::max);
    println!(
        "peak kinetic energy {peak_ke:.6e} J, largest |E(t) - E(0)| {drift:.3e} J ({:.3e} of peak)",
        drift / peak_ke
    );
    // The wire must really have moved: the peak kinetic energy is that of a fall of metres.
    assert!(peak_ke > 1.0e3, "peak kinetic energy {peak_ke} J is implausibly small");
    assert!(drift < 1.0e-3 * peak_ke, "energy drift {:.3e} of peak kinetic energy exceeds 0.1 %", drift / peak_ke);
}
