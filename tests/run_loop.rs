//! The run loop (issue 9): outputs observe without perturbing, peaks and settling are tracked every
//! step, a run until settled does not end before its events, and the peaks of a settle-then-break run
//! are the break's.

use crate::common;
use common::*;

use ohl::run::{RunOptions, run};
use ohl::scenario;

/// The paper's test wire (EA = 80734 g N, 1 kg/m, 160 m) with strong mass damping so that it settles
/// within seconds of the straight-chord release.
fn damped_wire(segments: usize) -> String {
    format!(
        r#"
        [conductor]
        axial_stiffness_n = 792000.54
        linear_density_kg_per_m = 1.0
        [geometry]
        left_support_m = [0.0, 0.0, 0.0]
        right_support_m = [0.0, 160.0, 0.0]
        segments = {segments}
        [numerics]
        courant = 0.9
        mass_damping_per_s = 1.5
        "#
    )
}

const SETTLE: &str =
    "[duration]\nuntil_settled = { kinetic_energy_fraction = 1e-8, window_s = 1.0, max_time_s = 300.0 }\n";

#[test]
fn a_run_until_settled_applies_a_later_break_and_reports_the_breaks_peaks() {
    // The wire settles from the straight start well before 60 s; the break at 60 s must still happen,
    // the run must then settle again, and the summary's peaks must be those from the break on.
    let text = format!("{}{SETTLE}[[events]]\ntime_s = 60.0\naction = \"break\"\nat_fraction = 0.5\n", damped_wire(20));
    let dir = std::env::temp_dir().join(format!("ohl_settle_break_{}", std::process::id()));
    let plan = scenario::plan(&common::scenario(&text), "<test>").expect("valid");
    let o = run(plan, &RunOptions { out_dir: Some(dir.clone()), record: true }).expect("stable");
    let s = &o.summary;
    println!(
        "status {}, final t {} s, events {:?}, peak tension {} N at {} s; phase peaks {:?}",
        s.status,
        s.final_time_s,
        o.events,
        s.peak_max_tension_n,
        s.peak_max_tension_time_s,
        s.phases
            .iter()
            .map(|p| (p.start_s, p.peaks.max_tension.value_n, p.peaks.max_tension.time_s))
            .collect::<Vec<_>>()
    );
    assert_eq!(o.events.len(), 1, "the break must be applied");
    assert_eq!(o.events[0].0, 60.0);
    assert_eq!(s.status, "settled");
    assert!(s.final_time_s > 61.0, "settled again after the break, at {}", s.final_time_s);
    assert_eq!(s.peaks_from_s, 60.0);
    assert!(s.peak_max_tension_time_s >= 60.0, "the peak must be the break's, not the start's");
    assert_eq!(s.phases.len(), 2);
    assert_eq!(s.phases[1].start_s, 60.0);
    assert!(s.phases[1].started_by.contains("break"));
    assert_eq!(s.peak_max_tension_n.to_bits(), s.phases[1].peaks.max_tension.value_n.to_bits());
    // The straight start's transient is the larger one: the run peak excludes it.
    assert!(s.phases[0].peaks.max_tension.value_n > s.peak_max_tension_n);
    // Snapshots: none requested, but the final state is always written.
    let snaps = std::fs::read_to_string(dir.join("snapshots.csv")).expect("snapshots.csv");
    assert_eq!(snaps.lines().count(), 1 + 21, "header plus one final snapshot of 21 nodes");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn snapshots_every_5_ms_leave_the_trajectory_bitwise_unchanged() {
    // N = 100 at Courant 0.9, undamped, tension-only: before issue 9, snapshot times shortened steps and
    // made this run unstable at 2.13 s. Outputs must observe without perturbing.
    let base = r#"
        [conductor]
        axial_stiffness_n = 792000.54
        linear_density_kg_per_m = 1.0
        [geometry]
        left_support_m = [0.0, 0.0, 0.0]
        right_support_m = [0.0, 160.0, 0.0]
        segments = 100
        [numerics]
        courant = 0.9
        [duration]
        end_time_s = 5.0
        "#
    .to_string();
    let times: Vec<String> = (1..1000).map(|k| format!("{}", 0.005 * k as f64)).collect();
    let with = format!("{base}\n[output]\nsnapshot_times_s = [{}]\n", times.join(", "));
    let plain = run_in_memory(&base);
    let snapped = run_in_memory(&with);
    assert_eq!(snapped.shapes.len(), 999);
    assert_eq!(plain.solver.steps(), snapped.solver.steps());
    for k in 0..3 {
        for i in 0..=100 {
            assert_eq!(plain.solver.wire().x[k][i].to_bits(), snapped.solver.wire().x[k][i].to_bits(), "x{k}[{i}]");
            assert_eq!(plain.solver.wire().v[k][i].to_bits(), snapped.solver.wire().v[k][i].to_bits(), "v{k}[{i}]");
        }
    }
    // A snapshot is taken at the first level at or after its time, never before, and within one step.
    let dt = snapped.summary.dt_s;
    for (k, s) in snapped.shapes.iter().enumerate() {
        let asked = 0.005 * (k + 1) as f64;
        assert!(s.t_s >= asked - 1e-9 * dt && s.t_s < asked + dt, "snapshot {k} at {} for {asked}", s.t_s);
    }
}

#[test]
fn peak_tension_and_settle_time_do_not_depend_on_the_sample_interval() {
    let mut seen: Vec<(f64, f64, f64, f64)> = Vec::new();
    for interval in [0.05, 0.01, 0.001] {
        let text = format!("{}{SETTLE}[output]\nsample_interval_s = {interval}\n", damped_wire(50));
        let o = run_in_memory(&text);
        let s = &o.summary;
        println!(
            "interval {interval} s: peak tension {} N at {} s, settled since {:?} s, final {} s",
            s.peak_max_tension_n, s.peak_max_tension_time_s, s.settled_since_s, s.final_time_s
        );
        assert_eq!(s.status, "settled");
        seen.push((s.peak_max_tension_n, s.peak_max_tension_time_s, s.settled_since_s.unwrap(), s.final_time_s));
    }
    for w in seen.windows(2) {
        assert_eq!(w[0].0.to_bits(), w[1].0.to_bits(), "peak tension");
        assert_eq!(w[0].1.to_bits(), w[1].1.to_bits(), "time of the peak tension");
        assert_eq!(w[0].2.to_bits(), w[1].2.to_bits(), "settle time");
        assert_eq!(w[0].3.to_bits(), w[1].3.to_bits(), "final time");
    }
}

#[test]
fn probes_follow_lagrangian_points_and_midspan_is_the_default() {
    let text = format!(
        "{}[duration]\nend_time_s = 2.0\n[output]\nprobes = [{{ name = \"quarter\", at_fraction = 0.25 }}, {{ name = \"left\", at_fraction = 0.0 }}]\n",
        damped_wire(20)
    );
    let o = run_in_memory(&text);
    let s = &o.summary;
    assert_eq!(s.probes.len(), 3);
    assert_eq!(s.probes[0].name, "mid");
    assert_eq!(s.probes[0].final_displacement_m, s.final_midspan_displacement_m);
    // At the support the point does not move; at a quarter it is node 5 of 20, displaced from the chord
    // point at a quarter, (0, 40, 0).
    assert_eq!(s.probes[2].final_displacement_m, [0.0; 3]);
    let w = &o.solver.wire();
    assert_eq!(s.probes[1].final_displacement_m, [w.x[0][5], w.x[1][5] - 40.0, w.x[2][5]]);
    // The support forces of a symmetric sagging span: equal vertical shares, opposite pulls along x2.
    let (a, b) = (&s.supports[0], &s.supports[1]);
    assert_eq!((a.node, b.node), (0, 20));
    assert!((a.final_force_n[1] + b.final_force_n[1]).abs() < 1e-6 * a.final_force_n[1].abs());
    assert!((a.final_force_n[2] - b.final_force_n[2]).abs() < 1e-6 * a.final_force_n[2].abs());
}
