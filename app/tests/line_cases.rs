//! The line cases of `cases/` (e, f, g: several conductors on shared towers) run through `ohl cases`'s
//! library function, and their results pass independent checks:
//! - (e) at the start (the line's static equilibrium) the towers' loads and the dead-ends' reactions
//!   balance the total weight of conductors and strings (Newton's tolerance, 1e-10 of the nodal loads,
//!   bounds the imbalance: asserted at 1e-6 of the weight); the phases are alike, so the least distances
//!   A-B and B-C are equal (to 1e-9 m: the same arithmetic on translated coordinates, up to rounding);
//! - (f) the lower phase's jump lies between the static rise of its mid-span (the equilibrium without the
//!   middle span's ice minus the equilibrium with it, both solved by Newton on the line) and twice it (an
//!   undamped linear oscillator released from a static deflection overshoots by exactly its amplitude,
//!   a damped one by less; measured 1.925: the conductor's geometric softening as it rises does not
//!   overturn the bound here);
//! - (g) at the start the quad bundle is symmetric under its weight, so its spacers carry nothing (Newton's
//!   tolerance: asserted below 1e-3 N, against a broken-conductor peak of tens of kN); after the break, the
//!   broken sub-conductor's middle lies on the ground.

use std::path::{Path, PathBuf};

use ohl::line::LinkKind;
use ohl::scenario::events::EventSpec;
use ohl::scenario::line::{self as line_scenario, LineShapeSpec};
use ohl_app::line_cases::{LineCaseOutcome, format_line_table, run_line_case};

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_path_buf()
}

fn case(name: &str) -> LineCaseOutcome {
    let out = std::env::temp_dir().join(format!("ohl-line-cases-test-{}", std::process::id()));
    let c = run_line_case(&repo().join("cases").join(format!("{name}.toml")), &out).unwrap();
    print!("{}", format_line_table(&c));
    c
}

fn parsed(name: &str) -> line_scenario::LineScenario {
    let path = repo().join("cases").join(format!("{name}.toml"));
    let text = std::fs::read_to_string(&path).unwrap();
    line_scenario::parse(&text, name).unwrap()
}

#[test]
fn e_weight_balances_and_alike_phases_keep_alike_clearances() {
    let sc = parsed("e_three_phases_wind");
    let mut plan = line_scenario::plan(&sc, "e").unwrap();
    let line = &mut plan.line;
    line.evaluate_forces();
    let g = 9.81;
    let mut weight = 0.0;
    let mut vertical = 0.0;
    for c in line.conductors() {
        let w = c.wire();
        weight += (w.total_mass() + w.point_mass_kg.iter().sum::<f64>()) * g;
        let mut f = Vec::new();
        c.support_forces(&mut f);
        vertical += f.iter().map(|(_, v)| v[2]).sum::<f64>();
    }
    for s in 0..line.supports().count() {
        vertical += line.support_resultant_n(s)[2];
    }
    println!("weight {weight:.6} N, loads on supports {vertical:.6} N");
    assert!((vertical + weight).abs() < 1e-6 * weight, "{vertical} + {weight}");

    let c = case("e_three_phases_wind");
    let pair =
        |a: &str, b: &str| c.summary.clearances.iter().find(|p| p.between == [a.to_string(), b.to_string()]).unwrap();
    let (ab, bc) = (pair("A", "B"), pair("B", "C"));
    assert!((ab.least_m - bc.least_m).abs() < 1e-9, "{} vs {}", ab.least_m, bc.least_m);
    assert!(
        ab.least_m <= 7.0
            && pair("A", "earth wire").least_m < pair("A", "earth wire").initial_m.expect("measured at the start")
    );
}

/// The mid-span height of the lower phase at the equilibrium of case (f) with or without the middle
/// span's ice (the lower phase alone, on the same towers: the phases are not coupled).
fn lower_midspan_height(with_middle_ice: bool) -> f64 {
    let mut sc = parsed("f_vertical_ice_shedding");
    sc.line.conductors.retain(|c| c.name == "lower");
    let events = &mut sc.line.conductors[0].events;
    events.retain(|e| match e {
        EventSpec::Ice { time_s, span, .. } => *time_s == 0.0 && (with_middle_ice || *span != Some(1)),
        _ => true,
    });
    assert_eq!(sc.initial.shape, LineShapeSpec::Equilibrium);
    let plan = line_scenario::plan(&sc, "f").unwrap();
    let w = plan.line.conductors()[0].wire();
    w.position(w.nodes() / 2)[2]
}

#[test]
fn f_the_jump_lies_between_the_static_rise_and_twice_it() {
    let rise = lower_midspan_height(false) - lower_midspan_height(true);
    let c = case("f_vertical_ice_shedding");
    let lower = c.summary.conductors.iter().find(|k| k.name == "lower").unwrap();
    // The peak of the mid-span displacement is its largest magnitude: read the highest point from the file.
    let ts = std::fs::read_to_string(c.dir.join("conductors/lower/timeseries.csv")).unwrap();
    let mut rows = ts.lines();
    let head: Vec<&str> = rows.next().unwrap().split(',').collect();
    let col = head.iter().position(|h| *h == "mid_dx3_m").unwrap();
    let dz: Vec<f64> = rows.map(|r| r.split(',').nth(col).unwrap().parse().unwrap()).collect();
    let jump = dz.iter().copied().fold(f64::MIN, f64::max) - dz[0];
    println!("static rise {rise:.3} m, dynamic jump {jump:.3} m, ratio {:.3}", jump / rise);
    assert!(jump > rise && jump < 2.0 * rise, "jump {jump} for a static rise {rise}");
    assert!(lower.peak_max_tension_n > 0.0);
    let least = c.summary.clearances.iter().find(|p| p.between == ["middle".to_string(), "lower".to_string()]).unwrap();
    assert!(least.least_m < least.initial_m.expect("measured at the start") && least.time_s > 1.0);
}

#[test]
fn g_spacers_start_unloaded_and_the_broken_sub_conductor_reaches_the_ground() {
    let sc = parsed("g_quad_bundle_break");
    let mut plan = line_scenario::plan(&sc, "g").unwrap();
    plan.line.evaluate_forces();
    let mut worst = 0.0_f64;
    for (l, link) in plan.line.links().iter().enumerate() {
        if link.kind == LinkKind::Spacer {
            worst = worst.max(plan.line.link_tension_n(l).abs());
        }
    }
    println!("largest spacer force at the start: {worst:.3e} N");
    assert!(worst < 1e-3, "{worst}");
    let c = case("g_quad_bundle_break");
    let broken = &c.summary.conductors[0];
    // Its middle (the break) started 18.5 m up (30 m dead-ends less the sag, +0.225 m for the upper row).
    let peak = broken.peak_midspan_displacement_m[2].value_m;
    assert!(broken.final_midspan_displacement_m[2] < -29.0 && peak < -29.0, "{peak}");
    let spacer = c.summary.attachments.iter().find(|a| a.kind == "spacer").unwrap();
    assert!(spacer.peak_tension_n.abs() > 1e4, "the spacers carry the broken sub-conductor's tension");
}

/// `ohl run --quiet` on a line prints no summary but still warns, per conductor, of a peak that comes
/// from the start (case e: the wind switched on at once at 1 s). The percentage it states is the
/// conductor's peak over its final tension in `summary.json`, minus one (printed to 0.1 %).
#[test]
fn a_quiet_line_run_still_warns_of_start_up_peaks() {
    let out = std::env::temp_dir().join(format!("ohl-line-quiet-{}", std::process::id()));
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_ohl"))
        .args(["run", "--quiet", "--out"])
        .arg(&out)
        .arg(repo().join("cases/e_three_phases_wind.toml"))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(o.stdout.is_empty(), "--quiet printed: {}", String::from_utf8_lossy(&o.stdout));
    let stderr = String::from_utf8_lossy(&o.stderr);
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let a = &summary["conductors"][0];
    assert_eq!(a["name"], "A");
    let percent =
        100.0 * (a["peak_max_tension_n"].as_f64().unwrap() / a["final_max_tension_n"].as_f64().unwrap() - 1.0);
    let expected =
        format!("e_three_phases_wind.toml: A: max_tension peak {:.1} N", a["peak_max_tension_n"].as_f64().unwrap());
    assert!(stderr.contains(&expected), "no `{expected}` in:\n{stderr}");
    assert!(stderr.contains(&format!("{percent:.1} % above its end value")), "{percent:.1} % not in:\n{stderr}");
}
