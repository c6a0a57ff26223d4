//! Events of a line section, through the scenario file: a conductor released from a dead-end, slipping
//! out of a suspension clamp, a string failing. Each is checked against what it must do exactly:
//! - release: the dead-end carries nothing from the event on (its force is exactly zero: the node is
//!   free and no longer a support), and the conductor's total mass is unchanged;
//! - clamp slip: the string pulls on its crossarm no more (force exactly zero) and its mass leaves the
//!   conductor (the nodes' total mass falls by exactly the string's 100 kg, to rounding);
//! - string failure: the string carries nothing, but its mass stays with the conductor.

use ohl::run::{RunOptions, run};
use ohl::scenario;

fn section(event: &str) -> String {
    format!(
        "[conductor]\naxial_stiffness_n = 2.9e7\nlinear_density_kg_per_m = 1.628\n[section]\n\
         horizontal_tension_n = 28000.0\nsegments_per_span = 20\nsupports = [\n\
         {{ kind = \"dead_end\", point_m = [0.0, 0.0, 30.0] }},\n\
         {{ kind = \"suspension\", pivot_m = [0.0, 300.0, 33.5], insulator_length_m = 3.5, insulator_mass_kg = 100.0, \
         insulator_stiffness_n = 5.0e7 }},\n{{ kind = \"dead_end\", point_m = [0.0, 600.0, 30.0] }},\n]\n\
         [duration]\nend_time_s = 2.0\n[[events]]\ntime_s = 0.5\n{event}\n"
    )
}

fn node_mass(p: &scenario::Plan) -> f64 {
    p.solver.wire().mass.iter().sum()
}

#[test]
fn release_slip_and_failure_do_exactly_what_they_say() {
    for (event, support, mass_change) in [
        ("action = \"release\"\nsupport = 0", 0, 0.0),
        ("action = \"clamp_slip\"\nsupport = 1", 1, -100.0),
        ("action = \"insulator_failure\"\nsupport = 1", 1, 0.0),
    ] {
        let sc = scenario::parse(&section(event), "section").unwrap();
        let plan = scenario::plan(&sc, "section").unwrap();
        let m0 = node_mass(&plan);
        let o = run(plan, &RunOptions { out_dir: None, record: true }).unwrap();
        let m1: f64 = o.solver.wire().mass.iter().sum();
        let after: Vec<_> = o.probes.iter().filter(|p| p.t_s > 0.5).collect();
        assert!(!after.is_empty());
        let s = &o.summary;
        let phase = s.phases.last().unwrap();
        let f = &phase.peaks.supports[support].magnitude;
        println!(
            "{event:?}: mass change {:+.6} kg, largest force on support {support} after the event {:.3e} N",
            m1 - m0,
            f.value_n
        );
        assert_eq!(f.value_n, 0.0, "{event}");
        assert!((m1 - m0 - mass_change).abs() < 1e-9, "{event}: {m1} - {m0}");
    }
}
