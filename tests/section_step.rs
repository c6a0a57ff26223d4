//! The time step of a section accounts for every spring and mass of its supports: a stiff elastic
//! crossarm on a light pivot sets the step (`ohl::scenario::section`, `ohl::wire::insulator`), and the run
//! says so in a warning.
//!
//! The section: two 400 m spans of ACSR Drake (EA = 2.9e7 N, 1.628 kg/m, 100 segments each, strung at
//! 28 kN) on a 3.5 m, 100 kg string (EA_i = 5e7 N) whose crossarm is 1e10 N/m along and across on a
//! 500 kg pivot, a value the validation allows; the conductor breaks next to the first dead-end at t = 0
//! (case (a) of `cases/` on two spans). The conductor's Courant step is 8.54e-4 s at Courant 0.9; the
//! pivot rings at `sqrt(1e10 / 500)` = 4.47e3 rad/s, whose leapfrog limit `2 / omega` = 4.47e-4 s is
//! about half of it.

use ohl::run::{RunError, RunOptions, run};
use ohl::scenario::{self, Plan};

fn section(courant: f64) -> String {
    format!(
        r#"name = "stiff crossarm"
[conductor]
axial_stiffness_n = 2.9e7
linear_density_kg_per_m = 1.628
diameter_m = 0.0281

[section]
horizontal_tension_n = 28000.0
segments_per_span = 100
supports = [
  {{ kind = "dead_end", point_m = [0.0, 0.0, 30.0] }},
  {{ kind = "suspension", pivot_m = [0.0, 400.0, 33.5], insulator_length_m = 3.5, insulator_mass_kg = 100.0,
     insulator_stiffness_n = 5.0e7,
     crossarm = {{ longitudinal_n_per_m = 1.0e10, transverse_n_per_m = 1.0e10, mass_kg = 500.0 }} }},
  {{ kind = "dead_end", point_m = [0.0, 800.0, 30.0] }},
]

[numerics]
courant = {courant:?}

[duration]
end_time_s = 2.0

[output]
sample_interval_s = 0.01

[[events]]
time_s = 0.0
action = "break"
span = 0
at_fraction = 0.001
"#
    )
}

fn plan(courant: f64) -> Plan {
    let sc = scenario::parse(&section(courant), "stiff.toml").unwrap();
    scenario::plan(&sc, "stiff.toml").unwrap()
}

/// The pivot's Gershgorin bound, written out: `omega^2 <= (k_arm + 2 EA_i / L_i) / M`.
fn pivot_bound_s() -> f64 {
    2.0 / ((1.0e10 + 2.0 * 5.0e7 / 3.5) / 500.0f64).sqrt()
}

/// The largest total energy of a run over its first [J]: kinetic, elastic (conductor, strings,
/// crossarm springs) and potential. With the smoothing and the break only removing energy, a stable run
/// never gains any: asserted to 1e-9 of it (rounding of a sum of 1e6 J).
fn energy_gain(plan: Plan) -> Result<f64, RunError> {
    let o = run(plan, &RunOptions { out_dir: None, record: true })?;
    let first = o.samples[0].total_j;
    let top = o.samples.iter().map(|s| s.total_j).fold(f64::NEG_INFINITY, f64::max);
    println!(
        "{} samples to t = {} s: total energy {first:.3} J at t = 0, largest {top:.3} J",
        o.samples.len(),
        o.summary.final_time_s
    );
    Ok((top - first) / first.abs())
}

/// The crossarm, not the conductor, sets the step: `0.9 x` the pivot's bound, with a warning naming the
/// crossarm; at that step the run is stable and gains no energy, at the conductor's own Courant step (the
/// step taken before the crossarm was counted) it goes unstable within a few hundred steps.
#[test]
fn a_stiff_crossarm_sets_the_step_and_the_run_is_stable() {
    let p = plan(0.9);
    let dt = p.solver.params().dt_s;
    let conductor_step = {
        let w = p.solver.wire();
        let l0 = (0..w.segments()).map(|j| w.rest_length[j]).fold(f64::INFINITY, f64::min);
        0.9 * l0 / (2.9e7f64 / 1.628).sqrt()
    };
    println!("dt {dt:.6e} s, pivot bound {:.6e} s, conductor step {conductor_step:.6e} s", pivot_bound_s());
    assert!((dt - 0.9 * pivot_bound_s()).abs() <= 1e-15 * dt, "{dt}");
    assert!(dt < 0.5 * conductor_step);
    let w: Vec<String> = p.warnings.iter().map(|w| w.to_string()).collect();
    assert!(
        w.iter().any(|w| w.starts_with("field `section.supports[1].crossarm`") && w.contains("sets the time step")),
        "{w:?}"
    );
    let gain = energy_gain(p).unwrap();
    assert!(gain <= 1e-9, "energy gained: {gain:e} of the initial");
    // The step as it was chosen before: the conductor's alone.
    let mut before = plan(0.9);
    before.solver.params_mut().dt_s = conductor_step;
    match energy_gain(before) {
        Err(RunError::Unstable { instability, .. }) => println!("at the conductor's step: {instability}"),
        other => panic!("the conductor's step should be unstable here: {:?}", other.map(|_| ())),
    }
}

/// At Courant 1 the step is the pivot's bound itself, and the run is stable; 1 % above it the run goes
/// unstable. The bound is that close to the pivot's true limit here: its highest frequency is at least
/// `sqrt(k_arm / M)` (the Rayleigh quotient of the pivot's own motion), so 1.01 times the bound is at least
/// `1.01 x 2 sqrt(2e7 / 2.0057e7)` = 2.017 > 2 in `omega dt`, beyond the leapfrog's limit of 2.
#[test]
fn the_step_sits_at_the_pivots_limit() {
    let p = plan(1.0);
    let dt = p.solver.params().dt_s;
    assert!((dt - pivot_bound_s()).abs() <= 1e-15 * dt, "{dt}");
    let gain = energy_gain(p).unwrap();
    assert!(gain <= 1e-9, "energy gained at the limit: {gain:e} of the initial");
    let mut above = plan(1.0);
    above.solver.params_mut().dt_s = 1.01 * dt;
    assert!(matches!(energy_gain(above), Err(RunError::Unstable { .. })), "1 % above the limit should be unstable");
}
