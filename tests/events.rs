//! Events: the run lands exactly on event times and applies them there; a ground plane with
//! restitution 0.6 returns 36 % of the vertical impact energy; the downwind-gated gust of section 4.5
//! pumps energy into the swing (its amplitude far exceeds the ungated gust's).

use crate::common;
use common::*;

const WIRE: &str = r#"
    [conductor]
    axial_stiffness_n = 792000.54
    linear_density_kg_per_m = 1.0
    [geometry]
    left_support_m = [0.0, 0.0, 0.0]
    right_support_m = [0.0, 160.0, 0.0]
    segments = 20
    [numerics]
    courant = 0.5
    smoothing = 0.02
"#;

#[test]
fn events_are_applied_exactly_at_their_time() {
    let o = run_in_memory(&format!(
        "{WIRE}\n[duration]\nend_time_s = 1.0\n[[events]]\ntime_s = 0.123456789\naction = \"ice\"\nlinear_density_kg_per_m = 0.5\n"
    ));
    assert_eq!(o.events.len(), 1);
    assert!((o.events[0].0 - 0.123456789).abs() < 1e-12, "applied at {}", o.events[0].0);
    // Mass 1.5 kg/m over 160 m after the event.
    assert!((o.solver.wire().total_mass() - 240.0).abs() < 1e-9);
}

#[test]
fn restitution_returns_the_square_of_the_coefficient_of_the_vertical_energy() {
    // A slack wire (unstretched length 3x the chord: no tension before it lands) falls 1 m onto a ground
    // plane. Every node hits with v = sqrt(2 g h) and must leave with 0.6 of it: the largest upward speed
    // after impact, squared, over the impact speed squared is 0.36.
    let o = run_in_memory(&format!(
        r#"{}
        [ground]
        height_m = -1.0
        restitution = 0.6
        [duration]
        end_time_s = 0.5
        [output]
        sample_interval_s = 0.001
        "#,
        WIRE.replace("smoothing = 0.02", "smoothing = 0.0")
            .replace("segments = 20", "segments = 20\nunstretched_length_m = 480.0")
    ));
    let s = &o.solver;
    let mid = s.wire().segments() / 2;
    // Impact at t_i = sqrt(2 h / g); since then gravity has slowed the rebound by g (t - t_i).
    let t_impact = (2.0 * 1.0 / 9.81_f64).sqrt();
    let v_up = s.wire().v[2][mid] + 9.81 * (s.time_s() - t_impact);
    let v_impact = (2.0 * 9.81 * 1.0_f64).sqrt();
    let ratio = (v_up / v_impact).powi(2);
    // The step that crosses the plane reflects the velocity of that step: the impact speed is sampled
    // within one step (dt ~ 4e-3 s) of contact, a relative error of about g dt / v = 1 %, squared 2 %.
    println!("rebound energy fraction {ratio:.4}");
    assert!((ratio - 0.36).abs() < 0.36 * 0.03, "rebound energy fraction {ratio}");
}

#[test]
fn the_downwind_gust_pumps_the_swing() {
    let amp = |gate: &str| {
        let o = run_in_memory(&format!(
            r#"{WIRE}
            [loads]
            wind = {{ law = "uniform_normal", pressure_n_per_m = 3.805, speed_m_per_s = 20.0, direction = [-1.0, 0.0, 0.0], initial_scale = 0.0 }}
            [duration]
            end_time_s = 60.0
            [[events]]
            time_s = 10.0
            action = "gust"
            period_s = 1.0
            gate = "{gate}"
            "#
        ));
        let late: Vec<f64> = o.samples.iter().filter(|s| s.t_s > 40.0).map(|s| s.mid_dx1_m).collect();
        let (lo, hi) = late.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| (a.min(x), b.max(x)));
        0.5 * (hi - lo)
    };
    let (always, downwind) = (amp("always"), amp("downwind"));
    println!("x1 amplitude: always {always:.4} m, downwind {downwind:.4} m");
    assert!(downwind > 5.0 * always, "always {always}, downwind {downwind}");
}
