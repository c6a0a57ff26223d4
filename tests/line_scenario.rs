//! Line scenarios (`[line]`, `ohl::scenario::line`, `ohl::run::line`): several conductors in one file.
//!
//! - A line whose conductors hang on supports of their own (no shared tower, no string damping) runs, bit
//!   for bit, as the single-conductor scenarios of its conductors: the line adds nothing to uncoupled
//!   conductors (the expectation is the single-conductor code, itself verified by the other tests).
//! - Every invalid field is reported with its path under `line.`, its value and what is allowed, never a
//!   panic; a single-conductor problem of a conductor is named under `line.conductors[k]`.
//! - The line cases of `cases/` parse, validate and build.

use ohl::run::line::run_line;
use ohl::run::{RunOptions, run};
use ohl::scenario::{self, line};

const CONDUCTOR: &str = r#"{ axial_stiffness_n = 2.9e7, linear_density_kg_per_m = 1.628, diameter_m = 0.0281 }"#;

fn section(x1: f64) -> String {
    format!(
        r#"{{ horizontal_tension_n = 28000.0, segments_per_span = 24, supports = [
  {{ kind = "dead_end", point_m = [{x1}, 0.0, 26.5] }},
  {{ kind = "suspension", pivot_m = [{x1}, 380.0, 30.0], insulator_length_m = 3.5, insulator_mass_kg = 100.0, insulator_stiffness_n = 5.0e7 }},
  {{ kind = "dead_end", point_m = [{x1}, 800.0, 28.0] }} ] }}"#
    )
}

const GLOBAL: &str = r#"
[loads.wind]
law = "aerodynamic"
direction = [1.0, 0.0, 0.0]
speed_m_per_s = 25.0
normal_coefficient = 1.0
tangential_coefficient = 0.0
initial_scale = 0.0

[numerics]
courant = 0.5
smoothing = 0.01
eta_n_s = 5000.0
mu = 1.0

[duration]
end_time_s = 3.0

[output]
sample_interval_s = 0.1
"#;

#[test]
fn a_line_of_own_supports_runs_as_its_single_conductor_scenarios() {
    let text = format!(
        r#"name = "two phases"
[line]
[[line.conductors]]
name = "A"
conductor = {CONDUCTOR}
section = {}
[[line.conductors.events]]
time_s = 0.7
action = "ice"
span = 1
linear_density_kg_per_m = 0.8
[[line.conductors]]
name = "B"
conductor = {CONDUCTOR}
section = {}
[[line.conductors.events]]
time_s = 0.7
action = "ice"
span = 0
radial_thickness_m = 0.005
density_kg_per_m3 = 900.0
{GLOBAL}
[[events]]
time_s = 0.5
action = "wind"
scale = 1.0
"#,
        section(-4.0),
        section(4.0)
    );
    let sc = line::parse(&text, "two.toml").unwrap();
    let plan = line::plan(&sc, "two.toml").unwrap();
    let out = run_line(plan, None).unwrap();
    // The line steps all its conductors together and lands every one on every event time: each conductor
    // here has an event at 0.7 s, so each single run lands there too.
    // A's ice is a change of linear density, B's a radial shell (5 mm glaze, the wind on d + 2 t).
    let forms = [
        (-4.0, (1, "linear_density_kg_per_m = 0.8")),
        (4.0, (0, "radial_thickness_m = 0.005\ndensity_kg_per_m3 = 900.0")),
    ];
    for (k, (x1, (span, ice))) in forms.into_iter().enumerate() {
        let ice_event = format!("[[events]]\ntime_s = 0.7\naction = \"ice\"\nspan = {span}\n{ice}\n");
        // The same conductor as a single-conductor scenario: its tables as top-level inline tables.
        let single = format!(
            "conductor = {CONDUCTOR}\nsection = {}\n{GLOBAL}\n{ice_event}[[events]]\ntime_s = 0.5\naction = \"wind\"\nscale = 1.0\n",
            section(x1)
        );
        let s = scenario::parse(&single, "single.toml").unwrap_or_else(|e| panic!("{e}\n{single}"));
        let p = scenario::plan(&s, "single.toml").unwrap();
        let o = run(p, &RunOptions::default()).unwrap();
        let (a, b) = (out.line.conductors()[k].wire(), o.solver.wire());
        assert_eq!(out.line.conductors()[k].steps(), o.solver.steps());
        for c in 0..3 {
            for i in 0..a.nodes() {
                assert_eq!(a.x[c][i].to_bits(), b.x[c][i].to_bits(), "conductor {k} x{c}[{i}]");
                assert_eq!(a.v[c][i].to_bits(), b.v[c][i].to_bits(), "conductor {k} v{c}[{i}]");
            }
        }
    }
    // The wind moved them, and more ice went on A (0.8 kg/m on span 1; B: 900 pi t (d + t) = 0.468 kg/m
    // on span 0, whose segments alone have the iced wind diameter).
    let (a, b) = (out.line.conductors()[0].wire(), out.line.conductors()[1].wire());
    assert_eq!(b.wind_diameter_factor[0], (0.0281 + 0.01) / 0.0281);
    assert_eq!(b.wind_diameter_factor[b.segments() - 1], 1.0);
    assert!(a.wind_diameter_factor.iter().all(|&k| k == 1.0));
    assert!(a.x[0][12] > -4.0 + 0.1 && b.x[0][12] > 4.0 + 0.1);
    assert!(a.total_mass() > b.total_mass());
}

/// A support's own `insulator_damping_n_s` stays with the conductor's own string in a line: the line of
/// one conductor on supports of its own runs bit for bit as its single-conductor scenario with the same
/// damped string (the expectation is the single-conductor code; `tests/section.rs` checks the damping's
/// rate and energy).
#[test]
fn a_string_damped_by_its_support_runs_in_a_line_as_in_its_section() {
    let damped = section(0.0)
        .replace("insulator_stiffness_n = 5.0e7 }", "insulator_stiffness_n = 5.0e7, insulator_damping_n_s = 2.0e4 }");
    let ice = "time_s = 0.7\naction = \"ice\"\nspan = 1\nlinear_density_kg_per_m = 0.8\n";
    let text = format!(
        "[line]\n[[line.conductors]]\nname = \"A\"\nconductor = {CONDUCTOR}\nsection = {damped}\n\
         [[line.conductors.events]]\n{ice}{GLOBAL}"
    );
    let plan = line::parse(&text, "damped.toml").and_then(|s| line::plan(&s, "damped.toml")).unwrap();
    assert!(plan.line.links().is_empty(), "the damped string stays the conductor's own");
    assert_eq!(plan.line.conductors()[0].wire().insulators[0].damping_n_s, 2.0e4);
    let out = run_line(plan, None).unwrap();
    let single = format!("conductor = {CONDUCTOR}\nsection = {damped}\n{GLOBAL}\n[[events]]\n{ice}");
    let s = scenario::parse(&single, "single.toml").unwrap_or_else(|e| panic!("{e}\n{single}"));
    let o = run(scenario::plan(&s, "single.toml").unwrap(), &RunOptions::default()).unwrap();
    let (a, b) = (out.line.conductors()[0].wire(), o.solver.wire());
    assert_eq!(out.line.conductors()[0].steps(), o.solver.steps());
    for c in 0..3 {
        for i in 0..a.nodes() {
            assert_eq!(a.x[c][i].to_bits(), b.x[c][i].to_bits(), "x{c}[{i}]");
            assert_eq!(a.v[c][i].to_bits(), b.v[c][i].to_bits(), "v{c}[{i}]");
        }
    }
}

/// A line scenario with `conductor` and `extra` substituted, and its problems (or a parse error's text).
fn problems(line_table: &str, conductors: &str) -> String {
    let text = format!("[line]\n{line_table}\n{conductors}\n{GLOBAL}");
    match line::parse(&text, "bad.toml").and_then(|s| line::plan(&s, "bad.toml")) {
        Ok(_) => "accepted".into(),
        Err(e) => e.to_string(),
    }
}

fn conductor(name: &str, extra: &str) -> String {
    format!("[[line.conductors]]\nname = \"{name}\"\nconductor = {CONDUCTOR}\nsection = {}\n{extra}\n", section(0.0))
}

#[test]
fn invalid_fields_are_named_with_their_path() {
    let cases: Vec<(String, String, &str)> = vec![
        (String::new(), conductor("A", "towers = [\"\", \"T9\", \"\"]"), "line.conductors[0].towers[1]"),
        (String::new(), conductor("A", "towers = [\"\"]"), "line.conductors[0].towers"),
        (
            String::new(),
            conductor("A", "") + &conductor("B", "").replace("2.9e7", "-2.9e7"),
            "line.conductors[1].conductor.axial_stiffness_n",
        ),
        (String::new(), conductor("A", "") + &conductor("A", ""), "line.conductors[1].name"),
        (
            String::new(),
            conductor("A", "[line.conductors.bundle]\nsub_conductors = 1\ndiameter_m = 0.4\nspacers = []"),
            "line.conductors[0].bundle.sub_conductors",
        ),
        (
            String::new(),
            conductor("A", "[line.conductors.bundle]\nsub_conductors = 2\ndiameter_m = 0.4\nspacers = [{ span = 3, at_fraction = 0.5 }]"),
            "line.conductors[0].bundle.spacers[0].span",
        ),
        (String::new(), conductor("A", "events_on = [1]"), "line.conductors[0].events_on[0]"),
        (
            "towers = [{ name = \"T\", position_m = [0.0, 0.0, 26.5], elastic = { along_n_per_m = 1e5, across_n_per_m = 1e5, mass_kg = 500.0 } }]".into(),
            conductor("A", "towers = [\"T\", \"\", \"\"]"),
            "line.conductors[0].towers[0]",
        ),
        (
            "towers = [{ name = \"T\", position_m = [0.0, 0.0, 26.5], elastic = { along_n_per_m = -1.0, across_n_per_m = 1e5, mass_kg = 500.0 } }]".into(),
            conductor("A", ""),
            "line.towers[0].elastic.along_n_per_m",
        ),
        ("string_damping_n_s = -3.0".into(), conductor("A", ""), "line.string_damping_n_s"),
        (String::new(), conductor("A", "colour = \"red\""), "unknown field `colour`"),
        // A string on a tower cannot fail yet (it is a link of the line).
        (
            "towers = [{ name = \"T\", position_m = [0.0, 380.0, 30.0] }]".into(),
            conductor("A", "towers = [\"\", \"T\", \"\"]\n[[line.conductors.events]]\ntime_s = 0.1\naction = \"insulator_failure\"\nsupport = 1"),
            "line.conductors[0].events",
        ),
        // Two names whose outputs would share a folder.
        (String::new(), conductor("A B", "") + &conductor("A_B", ""), "line.conductors[1].name"),
        // A bundle on a crossarm of its own.
        (
            String::new(),
            conductor("A", "[line.conductors.bundle]\nsub_conductors = 2\ndiameter_m = 0.4\nspacers = [{ span = 0, at_fraction = 0.5 }]")
                .replace("insulator_stiffness_n = 5.0e7 }", "insulator_stiffness_n = 5.0e7, crossarm = { longitudinal_n_per_m = 2e5, transverse_n_per_m = 2e5, mass_kg = 500.0 } }"),
            "line.conductors[0].section.supports",
        ),
        (String::new(), String::new(), "line.conductors"),
        // Tension strings: an end's dead-end only, once, with valid values.
        (
            String::new(),
            conductor("A", "tension_strings = [{ support = 1, length_m = 3.0, mass_kg = 60.0, stiffness_n = 8.0e7 }]"),
            "line.conductors[0].tension_strings[0].support` = 1",
        ),
        (
            String::new(),
            conductor("A", "tension_strings = [{ support = 0, length_m = 3.0, mass_kg = 60.0, stiffness_n = 8.0e7 }, { support = 0, length_m = 3.0, mass_kg = 60.0, stiffness_n = 8.0e7 }]"),
            "line.conductors[0].tension_strings[1].support` = 0",
        ),
        (
            String::new(),
            conductor("A", "tension_strings = [{ support = 0, length_m = 30.0, mass_kg = 60.0, stiffness_n = 8.0e7 }]"),
            "line.conductors[0].tension_strings[0].length_m` = 30 is not allowed: must be in [0.01, 20] m",
        ),
        (
            String::new(),
            conductor("A", "tension_strings = [{ support = 2, length_m = 3.0, mass_kg = 60.0, stiffness_n = 8.0e7, damping_n_s = -1.0 }]"),
            "line.conductors[0].tension_strings[0].damping_n_s` = -1 is not allowed: must be in [0, 1e7] N s",
        ),
        (
            String::new(),
            conductor("A", "tension_strings = [{ support = 2, length_m = 3.0, mass_kg = 60.0, stiffness_n = 1.0 }]"),
            "line.conductors[0].tension_strings[0].stiffness_n` = 1",
        ),
        // A dead-end on a tension string cannot be released.
        (
            String::new(),
            conductor("A", "tension_strings = [{ support = 2, length_m = 3.0, mass_kg = 60.0, stiffness_n = 8.0e7 }]\n[[line.conductors.events]]\ntime_s = 0.1\naction = \"release\"\nsupport = 2"),
            "line.conductors[0].events` = a release at node",
        ),
        // A string damped by the line and by its support.
        (
            "string_damping_n_s = 1e4".into(),
            conductor("A", "").replace("insulator_stiffness_n = 5.0e7 }", "insulator_stiffness_n = 5.0e7, insulator_damping_n_s = 1e4 }"),
            "line.conductors[0].section.supports[1].insulator_damping_n_s` = 10000",
        ),
        (
            String::new(),
            conductor("A", "").replace("insulator_stiffness_n = 5.0e7 }", "insulator_stiffness_n = 5.0e7, insulator_damping_n_s = -2.0 }"),
            "line.conductors[0].section.supports[1].insulator_damping_n_s` = -2",
        ),
        // Issue 23: a conductor's temperature in degrees Celsius, refused in Celsius, and not in both units.
        (
            String::new(),
            conductor("B", "").replace("diameter_m = 0.0281 }", "diameter_m = 0.0281, reference_temperature_c = -300.0 }"),
            "line.conductors[0].conductor.reference_temperature_c` = -300 is not allowed: must be in [-100, 4726.85] C",
        ),
        (
            String::new(),
            conductor("B", "").replace(
                "diameter_m = 0.0281 }",
                "diameter_m = 0.0281, reference_temperature_c = 15.0, reference_temperature_k = 288.15 }",
            ),
            "line.conductors[0].conductor.reference_temperature_c` = 15.0 is not allowed: \
             `line.conductors[0].conductor.reference_temperature_k` is given too",
        ),
    ];
    for (line_table, conductors, field) in cases {
        let msg = problems(&line_table, &conductors);
        assert!(msg.contains(field), "expected {field:?} in:\n{msg}");
        assert!(msg.starts_with("bad.toml"), "the file is named: {msg}");
    }
}

#[test]
fn the_line_cases_parse_validate_and_build() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("cases");
    let mut found = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let text = std::fs::read_to_string(&path).unwrap();
        if !line::is_line(&text) {
            continue;
        }
        found += 1;
        let file = path.display().to_string();
        let plan = line::parse(&text, &file).and_then(|s| line::plan(&s, &file)).unwrap_or_else(|e| panic!("{e}"));
        // Case k: a busbar and its dropper.
        let least = if file.ends_with("k_slack_span_dropper.toml") { 2 } else { 3 };
        assert!(plan.line.conductors().len() >= least, "{file}");
    }
    assert_eq!(found, 8, "cases e, f, g, k and the short-circuit cases h, i, j, l");
}

/// The file's `[[events]]` act on every sub-conductor of a bundle, `events_on` selects only which take the
/// conductor's own events: with `events_on = [1]`, ice of the conductor's own goes on sub-conductor 1 only,
/// and the global wind switch blows every sub-conductor across the line.
#[test]
fn events_on_selects_the_own_events_and_keeps_the_global_ones() {
    let text = format!(
        r#"[line]
{}
events_on = [1]
[line.conductors.bundle]
sub_conductors = 2
diameter_m = 0.4
spacers = [{{ span = 0, at_fraction = 0.5 }}, {{ span = 1, at_fraction = 0.5 }}]
[[line.conductors.events]]
time_s = 0.2
action = "ice"
span = 1
linear_density_kg_per_m = 0.8
{GLOBAL}
[[events]]
time_s = 0.5
action = "wind"
scale = 1.0
"#,
        conductor("A", "").trim_end()
    );
    let sc = line::parse(&text, "events_on.toml").unwrap();
    let plan = line::plan(&sc, "events_on.toml").unwrap();
    let out = run_line(plan, None).unwrap();
    let (a, b) = (out.line.conductors()[0].wire(), out.line.conductors()[1].wire());
    assert!(a.total_mass() > b.total_mass() + 0.7 * 380.0, "the ice went on sub-conductor 1 only");
    let moved = |w: &ohl::wire::Wire, x0: f64| w.x[0][w.nodes() / 4] - x0;
    assert!(moved(a, -0.2) > 0.1 && moved(b, 0.2) > 0.1, "the wind blew both: {} {}", moved(a, -0.2), moved(b, 0.2));
    assert_eq!(out.summary.events.iter().filter(|e| e.what.contains("wind")).count(), 2);
}

/// A level 400 m span of Drake between two strain towers, its dead-ends held by tension strings in line
/// with the conductor (`tension_strings`: 3 m, EA 8e7 N, 0 or 60 kg at the conductor's end), the
/// conductor 394.45 m unstretched between the strings' lower ends.
fn dead_end_span(segments: usize, string_mass_kg: f64, courant: f64, initial: &str, zeta: f64) -> String {
    format!(
        r#"[line]
[[line.conductors]]
name = "A"
conductor = {CONDUCTOR}
section = {{ segments_per_span = {segments}, spans = [{{ unstretched_length_m = 394.45 }}], supports = [
  {{ kind = "dead_end", point_m = [0.0, 0.0, 30.0] }},
  {{ kind = "dead_end", point_m = [0.0, 400.0, 30.0] }} ] }}
tension_strings = [
  {{ support = 0, length_m = 3.0, mass_kg = {string_mass_kg:?}, stiffness_n = 8.0e7 }},
  {{ support = 1, length_m = 3.0, mass_kg = {string_mass_kg:?}, stiffness_n = 8.0e7, damping_n_s = 0.0 }},
]
[initial]
shape = "{initial}"
[numerics]
courant = {courant:?}
smoothing = 0.0
mass_damping_per_s = {zeta:?}
[duration]
end_time_s = 1.0
"#
    )
}

/// The exact statics of the span on its two tension strings, from the elastic catenary (Irvine) of the
/// conductor between the strings' lower ends: by symmetry each end carries `V = w S / 2` of the
/// conductor and the string's weight `m g`, the horizontal tension is the catenary's `H` for the chord
/// `400 - 2 a`, and each string is straight, in balance with both: tension `T = sqrt(H^2 + (V + m g)^2)`,
/// length `L0 (1 + T / EA)`, along `(H, V + m g) / T`, so that its horizontal reach is `a = L H / T`.
/// Solved by iterating on `a` (the chord's change moves `H` by far too little to change `a` much: the
/// iteration contracts at about 1e-3 per sweep). Returns `(a, drop b, T, H)`.
fn exact_dead_end_span(string_mass_kg: f64) -> (f64, f64, f64, f64) {
    let (l0, ea_s, s, w) = (3.0, 8.0e7, 394.45, 1.628 * 9.81);
    let mut a = 3.0;
    for _ in 0..100 {
        let cat = ohl::exact::catenary::ElasticCatenary::solve(
            [0.0, a, 0.0],
            [0.0, 400.0 - a, 0.0],
            s,
            [0.0, 0.0, -w],
            2.9e7,
        )
        .unwrap();
        let (h, v) = (cat.horizontal_tension_n(), w * s / 2.0 + string_mass_kg * 9.81);
        let t = h.hypot(v);
        let len = l0 * (1.0 + t / ea_s);
        let next = len * h / t;
        if (next - a).abs() < 1e-15 {
            return (next, len * v / t, t, h);
        }
        a = next;
    }
    panic!("the reference did not converge");
}

/// Tension (dead-end) strings of a `[line]` conductor, against the exact statics of a string in line with
/// the catenary ([`exact_dead_end_span`]), on three grids, with and without the string's mass:
/// - exact on every grid (the discrete balance, whatever `ds`): the string's horizontal pull equals the
///   horizontal tension `H` of every segment, and the string's extension times `EA / L0` is the force the
///   conductor's end applies to it (its end segment's tension and the end node's weight), to Newton's
///   tolerance;
/// - converging at order 2 to the continuum: the string's lower end (its reach `a` and drop `b`), its
///   extension `L0 T / EA` and its angle `atan((V + m g) / H)` (without a mass: the conductor's end
///   tangent `atan(V / H)`, the string in line with the catenary);
/// - the explicit line started strung (strings unstretched) and relaxed by mass damping settles on the
///   Newton state.
#[test]
fn tension_strings_lie_in_line_with_the_catenary_at_their_exact_stretch() {
    let g = 9.81;
    for mass in [0.0, 60.0] {
        let (a, b, t_exact, h_exact) = exact_dead_end_span(mass);
        let mut errors = Vec::new();
        for n in [16, 32, 64] {
            // Without a mass the end node is light (its share of a segment): a shorter step.
            let text = dead_end_span(n, mass, 0.2, "equilibrium", 0.0);
            let plan = line::parse(&text, "dead_end.toml").and_then(|s| line::plan(&s, "dead_end.toml")).unwrap();
            let w = plan.line.conductors()[0].wire();
            assert_eq!(plan.line.links().len(), 2);
            let (r0, rn) = (w.position(0), w.position(n));
            let (top0, top1) = ([0.0, 0.0, 30.0], [0.0, 400.0, 30.0]);
            let dist = |p: [f64; 3], q: [f64; 3]| (0..3).map(|k| (p[k] - q[k]).powi(2)).sum::<f64>().sqrt();
            let (len0, len1) = (dist(r0, top0), dist(rn, top1));
            let tension = 8.0e7 / 3.0 * (len0 - 3.0);
            // Exact discrete statics: H of the string (its pull along x2) against every segment's.
            let h_string = tension * (r0[1] - top0[1]) / len0;
            let seg = |j: usize| {
                let (p, q) = (w.position(j), w.position(j + 1));
                let l = dist(p, q);
                let t = w.axial_stiffness_n[j] * (l / w.rest_length[j] - 1.0);
                [0, 1, 2].map(|k| t * (q[k] - p[k]) / l)
            };
            let h_worst = (0..n).map(|j| (seg(j)[1] - h_string).abs()).fold(0.0, f64::max);
            // The conductor's pull on the string's end: its end segment's tension and the end node's weight.
            let f0 = seg(0);
            let pull = f0[1].hypot(f0[2] - w.mass[0] * g);
            assert!(h_worst < 1e-6 * h_string, "n {n}: H of the segments vs the string's: {h_worst:e} N");
            assert!((pull - tension).abs() < 1e-6 * tension, "n {n}: {pull} vs {tension}");
            assert!((len0 - len1).abs() < 1e-9, "symmetric");
            // Against the continuum.
            let angle = (30.0 - r0[2]).atan2(r0[1]);
            let e_pos = (r0[1] - a).abs().max((30.0 - r0[2] - b).abs());
            let e_ext = ((len0 - 3.0) / (3.0 * t_exact / 8.0e7) - 1.0).abs();
            let e_angle = (angle - ((9.81 * 1.628 * 394.45 / 2.0 + mass * g) / h_exact).atan()).abs();
            eprintln!(
                "mass {mass} kg, N = {n}: string end ({:.6}, {:.6}) m vs exact ({a:.6}, {b:.6}); extension {:.6e} m \
                 vs exact {:.6e} m; angle {angle:.8} rad; errors: end {e_pos:.3e} m, extension {e_ext:.3e}, angle \
                 {e_angle:.3e} rad; H {h_string:.3} N (exact {h_exact:.3}), segments within {h_worst:.2e} N",
                r0[1],
                30.0 - r0[2],
                len0 - 3.0,
                3.0 * t_exact / 8.0e7,
            );
            errors.push([e_pos, e_ext, e_angle]);
        }
        for q in 0..3 {
            let (o1, o2) = ((errors[0][q] / errors[1][q]).log2(), (errors[1][q] / errors[2][q]).log2());
            eprintln!("mass {mass} kg, quantity {q}: observed orders {o1:.3}, {o2:.3}");
            assert!((o2 - 2.0).abs() < 0.15, "order {o2} of quantity {q}");
            assert!(errors[2][q] < [1e-4, 1e-3, 1e-4][q], "{:?}", errors[2]);
        }
    }
    // The explicit line, started strung with unstretched strings, relaxed by mass damping (3 /s, about
    // twice the span's lowest frequency), settles on the Newton state.
    let newton = dead_end_span(16, 60.0, 0.5, "equilibrium", 3.0);
    let newton = line::parse(&newton, "n.toml").and_then(|s| line::plan(&s, "n.toml")).unwrap();
    let strung = dead_end_span(16, 60.0, 0.5, "strung", 3.0);
    let mut relaxed = line::parse(&strung, "r.toml").and_then(|s| line::plan(&s, "r.toml")).unwrap().line;
    let dt = relaxed.params().dt_s;
    let steps = (120.0 / dt) as usize;
    for _ in 0..steps {
        relaxed.step(dt).unwrap();
    }
    let (a, b) = (newton.line.conductors()[0].wire(), relaxed.conductors()[0].wire());
    let worst =
        (0..a.nodes()).map(|i| (0..3).map(|k| (a.x[k][i] - b.x[k][i]).abs()).fold(0.0, f64::max)).fold(0.0, f64::max);
    eprintln!("Newton vs settled explicit ({steps} steps, {:.0} s): {worst:.3e} m", steps as f64 * dt);
    assert!(worst < 1e-6, "Newton vs settled: {worst:e} m");
}

/// `run_line_observed` with `record` keeps the numbers `clearances.csv` and `towers.csv` hold (the same
/// levels, the same bits), and recording changes nothing else: the summary is that of the run writing the
/// files, field for field but the wall-clock timings.
#[test]
fn recorded_samples_are_the_files_numbers() {
    use ohl::run::line::{LineRunOptions, run_line_observed};
    let text = format!("[line]\n{}{}{GLOBAL}", conductor("A", ""), conductor("B", "").replace("[0, ", "[6, "));
    let plan = line::plan(&line::parse(&text, "two.toml").unwrap(), "two.toml").unwrap();
    let dir = std::env::temp_dir().join(format!("ohl-line-record-{}", std::process::id()));
    let files = run_line(plan.clone(), Some(&dir)).unwrap();
    let opts = LineRunOptions { out_dir: None, record: true };
    let kept = run_line_observed(plan, &opts, &mut []).unwrap();
    let s = &kept.samples;
    let read = |name: &str| -> Vec<Vec<f64>> {
        let t = std::fs::read_to_string(dir.join(name)).unwrap();
        t.lines().skip(1).map(|l| l.split(',').map(|x| x.parse().unwrap()).collect()).collect()
    };
    let (cl, tw) = (read("clearances.csv"), read("towers.csv"));
    assert_eq!((cl.len(), tw.len()), (s.t_s.len(), s.t_s.len()));
    assert_eq!((s.pairs.len(), s.towers.len()), (1, 0));
    for (k, row) in cl.iter().enumerate() {
        assert_eq!(row[0].to_bits(), s.t_s[k].to_bits());
        assert_eq!(row[1].to_bits(), s.clearance_m[k].to_bits(), "row {k}");
    }
    let json = |o: &ohl::run::line::LineOutcome| {
        let mut v = serde_json::to_value(&o.summary).unwrap();
        let m = v.as_object_mut().unwrap();
        for timing in ["wall_time_s", "node_steps_per_second", "cpu_time_s", "cpu_node_steps_per_second"] {
            m.remove(timing);
        }
        v
    };
    assert_eq!(json(&files), json(&kept));
    assert!(files.samples.t_s.is_empty(), "nothing kept without record");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A spacer too stiff for the conductors' step (1e9 N/m between the clamps of a twin bundle, which the
/// validation allows) no longer refuses the line (it was refused under `numerics.courant`): the line
/// steps at its stable step (Gershgorin's bound of `ohl::scheme::line`, the bound `LineExplicit::new`
/// checks) times `numerics.courant` = 0.5, below the conductors' own Courant step; the first conductor's
/// warnings name the node that sets it; the run is stable over its 3 s.
#[test]
fn a_stiff_spacer_sets_the_lines_step() {
    let spacer = "[line.conductors.bundle]\nsub_conductors = 2\ndiameter_m = 0.4\nspacer_stiffness_n_per_m = 1e9\nspacers = [{ span = 0, at_fraction = 0.5 }]";
    let text = format!("[line]\n{}\n{GLOBAL}", conductor("A", spacer));
    let plan = line::parse(&text, "stiff.toml").and_then(|s| line::plan(&s, "stiff.toml")).unwrap();
    let dt = plan.line.params().dt_s;
    // The conductors' own step: Courant 0.5 on the shortest segment at Drake's wave speed.
    let w = plan.line.conductors()[0].wire();
    let l0 = (0..w.segments()).map(|j| w.rest_length[j]).fold(f64::INFINITY, f64::min);
    let own = 0.5 * l0 / (2.9e7f64 / 1.628).sqrt();
    let warnings: Vec<String> = plan.plans[0].warnings.iter().map(|w| w.to_string()).collect();
    println!("dt {dt:.6e} s (conductors {own:.6e} s); {warnings:?}");
    assert!(dt < own, "{dt} vs {own}");
    let w = warnings.iter().find(|w| w.contains("sets the time step")).expect("a warning names the limit");
    assert!(w.starts_with("field `line` = conductor 'A"), "{w}");
    assert!(w.contains(&format!("the line steps at {dt:.4e} s instead of the conductors' {own:.4e} s")), "{w}");
    let o = run_line(plan, None).unwrap();
    println!("{} steps to t = {} s", o.summary.steps, o.summary.final_time_s);
    assert!((o.summary.final_time_s - 3.0).abs() < 1e-9, "{}", o.summary.final_time_s);
}

/// Issue 23: a line started from its static equilibrium with the wind on (`[initial] shape =
/// "equilibrium"`, `[loads.wind] initial_scale = 1`) stays at rest: the line's static solve
/// (`ohl::statics::solve_line`) includes each conductor's wind at its initial scale with the kernel's own
/// aerodynamic element. Case (e) of `cases/` (three Drake phases and an earth wire on shared towers, 30 m/s
/// across) with the wind on from the start; its event at 1 s (scale 1) then changes nothing. Each
/// conductor's peak tension from 1 s on and its tension at the end lie within `nodes tol` of the tension
/// at the start, `tol` the static solve's force tolerance (the bound of `tests/equilibrium.rs`: the
/// residual forces of all nodes added up).
#[test]
fn a_line_from_its_equilibrium_under_a_steady_wind_stays_at_rest() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/e_three_phases_wind.toml");
    let text = std::fs::read_to_string(&path)
        .unwrap()
        .replace("initial_scale = 0.0", "initial_scale = 1.0")
        .replace("end_time_s = 40.0", "end_time_s = 4.0")
        .replace("snapshot_times_s = [1.0, 5.0, 20.0]", "snapshot_times_s = [1.0]");
    let sc = line::parse(&text, "e_wind_on.toml").unwrap();
    let plan = line::plan(&sc, "e_wind_on.toml").unwrap();
    let tol = plan.initial_equilibrium.as_ref().expect("solved").tolerance_n;
    let starts: Vec<(f64, f64)> = plan
        .line
        .conductors()
        .iter()
        .map(|c| {
            let mut c = c.clone();
            c.evaluate_forces();
            (c.max_tension_n(), c.wire().nodes() as f64)
        })
        .collect();
    let nodes: f64 = starts.iter().map(|s| s.1).sum();
    let out = run_line(plan, None).unwrap();
    for (c, &(t0, _)) in out.summary.conductors.iter().zip(&starts) {
        let drift = (c.peak_max_tension_n - t0).abs().max((c.final_max_tension_n - t0).abs());
        println!(
            "{}: T0 = {t0:.4} N, peak {:.4} N, end {:.4} N, drift {drift:.3e} N",
            c.name, c.peak_max_tension_n, c.final_max_tension_n
        );
        assert!(drift <= nodes * tol, "{}: drift {drift} N above {} N", c.name, nodes * tol);
        assert!(c.start_up.is_none(), "{}: no onset, no start-up check", c.name);
    }
    // The case as shipped, its wind switched on at once at 1 s: every conductor's peak tension (in the
    // first swing, by 5.9 s) is its start's overshoot, 33 % above the end value for the phases.
    let text = std::fs::read_to_string(&path)
        .unwrap()
        .replace("snapshot_times_s = [1.0, 5.0, 20.0]", "snapshot_times_s = [1.0]");
    let plan = line::plan(&line::parse(&text, "e.toml").unwrap(), "e.toml").unwrap();
    let out = run_line(plan, None).unwrap();
    for c in &out.summary.conductors {
        let u = c.start_up.as_ref().expect("an onset at 1 s");
        println!(
            "{}: peak {:.1} N at {:.3} s, end {:.1} N, T1 {:.3} s",
            c.name, c.peak_max_tension_n, c.peak_max_tension_time_s, c.final_max_tension_n, u.first_mode_period_s
        );
        assert!(u.assessed && u.flagged.len() == 1, "{}: {u:?}", c.name);
    }
}
