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
linear_density_kg_per_m = 0.3
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
    for (k, (x1, (span, ice))) in [(-4.0, (1, 0.8)), (4.0, (0, 0.3))].into_iter().enumerate() {
        let ice_event =
            format!("[[events]]\ntime_s = 0.7\naction = \"ice\"\nspan = {span}\nlinear_density_kg_per_m = {ice}\n");
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
    // The wind moved them, and more ice went on A.
    let (a, b) = (out.line.conductors()[0].wire(), out.line.conductors()[1].wire());
    assert!(a.x[0][12] > -4.0 + 0.1 && b.x[0][12] > 4.0 + 0.1);
    assert!(a.total_mass() > b.total_mass());
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
        (
            String::new(),
            conductor("A", "[line.conductors.bundle]\nsub_conductors = 2\ndiameter_m = 0.4\nspacer_stiffness_n_per_m = 1e9\nspacers = [{ span = 0, at_fraction = 0.5 }]"),
            "numerics.courant",
        ),
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
        assert!(plan.line.conductors().len() >= 3, "{file}");
    }
    assert_eq!(found, 3, "cases e, f and g");
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
        m.remove("wall_time_s");
        m.remove("node_steps_per_second");
        v
    };
    assert_eq!(json(&files), json(&kept));
    assert!(files.samples.t_s.is_empty(), "nothing kept without record");
    std::fs::remove_dir_all(&dir).unwrap();
}
