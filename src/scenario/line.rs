//! A line scenario: several conductors in one file (`[line]`), on the supports of a section each, sharing
//! towers; phases, earth wires and bundles of sub-conductors with spacers.
//!
//! Each conductor of `[[line.conductors]]` is described as a single-conductor scenario is (its own
//! `conductor` and `section` tables, its own `events`), and is checked and built by the very code of a
//! single-conductor scenario ([`super::build`]), with the file's global `[loads]`, `[numerics]`,
//! `[duration]`, `[output]` and `[ground]`; every message names the field under `line.conductors[k]`. The
//! line then joins them ([`crate::line`]):
//!
//! - `line.towers`: supports shared by several conductors, rigid or elastic (horizontal springs along and
//!   across the line, a mass, a damping: [`crate::line::ElasticSupport`]);
//! - `towers = ["", "T2", ""]` in a conductor: which tower holds each support of its section (`""`: a
//!   support of its own). A suspension string on a tower becomes a string link from the tower (its pivot an
//!   offset from the tower's position) to the clamp; a dead-end on a tower is a fixed node whose reaction
//!   the tower carries (rigid towers only);
//! - `tension_strings`: a dead-end of the section held by a tension (strain) insulator string in line with
//!   the conductor instead of a fixed point: the string hangs from the dead-end's point (on its tower, or
//!   a rigid support of its own) towards the span, the conductor starts at its lower end (its end node is
//!   free, the string's mass lumped there) and is strung from there; the string is a link of the line
//!   ([`crate::line::LinkKind::TensionString`]: length, `EA`, `BA`, tension only);
//! - `bundle`: the conductor is a bundle of `sub_conductors` sub-conductors on a circle of `diameter_m`,
//!   each a copy of the conductor moved by its offset, each on its own string (a bundle's yoke is not
//!   modelled), joined by spacers (every pair of sub-conductors by an arm of `spacer_stiffness_n_per_m`).
//!
//! A conductor whose supports are all its own, without tension strings and without
//! `line.string_damping_n_s`, is, in the line, bit for bit the single-conductor scenario (its strings stay
//! the wire's own, damped by their support's own `insulator_damping_n_s` if given), provided the line's step is
//! its own (the line runs at the smallest step of its conductors, checked against the stable step of every
//! link, [`crate::scheme::line`]) and the other conductors' events fall at its own event times (every
//! conductor lands on every event time). Each conductor keeps its own speed bound.
//!
//! Where a link or an elastic tower is too stiff for the conductors' step (above the line's stable step,
//! Gershgorin's bound of [`crate::scheme::line`]), the line runs at that stable step times
//! `numerics.courant` instead, as a section's clamps and crossarms set a section's step, and the first
//! conductor's warnings say which node or support sets it and how many more steps the run takes (the
//! smoothing, per step, then damps more per second). A step the bound admits is kept as it was.

use serde::Deserialize;

use super::InputError;
use super::build::{Plan, Stop, build};
use super::events::{EventSpec, GroundSpec};
use super::range::{
    INSULATOR_DAMPING_N_S, INSULATOR_LENGTH_M, INSULATOR_MASS_KG, INSULATOR_STIFFNESS_N, Range as Allowed,
};
use super::schema::{
    ConductorSpec, DurationSpec, InitialSpec, LoadsSpec, NumericsSpec, OutputSpec, Scenario, SectionSpec, SupportSpec,
};
use super::validate::{Check, Problem};
use crate::element::LinkLaw;
use crate::events::Action;
use crate::line::contact::{ConductorContact, ContactPair};
use crate::line::{
    DeadEnd, ElasticSupport, Endpoint, LineConductor, Link, LinkKind, Model, NodeRef, PointMass, Role, Support,
};
use crate::scheme::{LineError, LineExplicit, StepParams};

/// A scenario of several conductors.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LineScenario {
    /// short name of the case (free text)
    #[serde(default)]
    pub name: Option<String>,
    /// what the case is and where it comes from (free text)
    #[serde(default)]
    pub description: Option<String>,
    /// the conductors and their towers
    pub line: LineSpec,
    /// gravity, uniform loads and wind, for every conductor (each with its own diameter)
    #[serde(default)]
    pub loads: LoadsSpec,
    /// time step, smoothing and damping
    #[serde(default)]
    pub numerics: NumericsSpec,
    /// when the run ends
    pub duration: DurationSpec,
    /// what is written
    #[serde(default)]
    pub output: OutputSpec,
    /// ground plane, if any (section 4.4)
    #[serde(default)]
    pub ground: Option<GroundSpec>,
    /// the initial state of the line
    #[serde(default)]
    pub initial: LineInitialSpec,
    /// events that act on every conductor (a wind switch, a gust, a temperature), as `[[events]]` of a
    /// single-conductor scenario; a conductor's own events are in its `events`
    #[serde(default)]
    pub events: Vec<EventSpec>,
    /// a short circuit: fault currents in the phases and their electromagnetic forces
    /// ([`super::short_circuit`]); absent: none
    #[serde(default)]
    pub short_circuit: Option<super::short_circuit::ShortCircuitSpec>,
    /// the temperature fields the file gave in degrees Celsius (set by [`parse`], not a key of the file)
    #[serde(skip)]
    pub celsius: super::temperature::Celsius,
}

/// `[initial]` of a line.
#[derive(Clone, Copy, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LineInitialSpec {
    /// `"strung"` (default: each span's elastic catenary between plumb clamps, as a section) or
    /// `"equilibrium"` (at rest on the static equilibrium of the whole line at `t = 0`, spacers, towers and
    /// the ice of events at `t = 0` included: [`crate::statics::solve_line`])
    #[serde(default)]
    pub shape: LineShapeSpec,
}

/// The initial shape of a line.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum LineShapeSpec {
    /// each conductor as strung
    #[default]
    Strung,
    /// the static equilibrium of the line
    Equilibrium,
}

/// `[line]`: towers and conductors.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LineSpec {
    /// supports shared by several conductors
    #[serde(default)]
    pub towers: Vec<TowerSpec>,
    /// axial damping `BA` [N s] of every suspension string, in [0, 1e7]; default 0 (a string rings on its
    /// axial mode, about 100 Hz, after a sudden unloading; 1e4 N s damps it in a few periods). The strings
    /// then become links of the line; not with a support's own `insulator_damping_n_s`, which its
    /// conductor's own string carries
    #[serde(default)]
    pub string_damping_n_s: f64,
    /// the conductors (at least one)
    #[serde(default)]
    pub conductors: Vec<LineConductorSpec>,
}

/// A tower (a support shared by several conductors).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TowerSpec {
    /// its name, unique, used by the conductors' `towers` lists
    pub name: String,
    /// its reference point [m] (the strings' pivots are offsets from it)
    pub position_m: [f64; 3],
    /// springs of an elastic tower top; absent: rigid
    #[serde(default)]
    pub elastic: Option<TowerElasticSpec>,
}

/// The elastic top of a tower: it moves horizontally on springs, rigid vertically.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TowerElasticSpec {
    /// horizontal direction of the line at the tower `e_l` [-] (normalised); default `[0, 1, 0]` (+x2)
    #[serde(default = "default_along")]
    pub along: [f64; 3],
    /// spring along the line `k_l` [N/m], in [1e2, 1e10]
    pub along_n_per_m: f64,
    /// spring across the line `k_t` [N/m], in [1e2, 1e10]
    pub across_n_per_m: f64,
    /// mass moving with the top `M` [kg], in [1, 1e6]
    pub mass_kg: f64,
    /// viscous damping `c_d` [N s/m], in [0, 1e8]; default 0
    #[serde(default)]
    pub damping_n_s_per_m: f64,
}

fn default_along() -> [f64; 3] {
    [0.0, 1.0, 0.0]
}

/// What a conductor is.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum RoleSpec {
    /// a phase conductor (default)
    #[default]
    Phase,
    /// an earth (shield) wire
    EarthWire,
}

/// One conductor of the line.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LineConductorSpec {
    /// its name, unique (outputs are written under it)
    pub name: String,
    /// phase (default) or earth wire
    #[serde(default)]
    pub role: RoleSpec,
    /// the conductor, as `[conductor]` of a single-conductor scenario
    pub conductor: ConductorSpec,
    /// its section, as `[section]` of a single-conductor scenario (none for a dropper)
    #[serde(default = "super::dropper::no_section")]
    pub section: SectionSpec,
    /// a dropper hanging from a node of another conductor ([`super::dropper`]); absent: a conductor
    /// strung as its section
    #[serde(default)]
    pub dropper: Option<super::dropper::DropperToml>,
    /// for each support of the section, the tower that holds it (`""`: a support of its own); empty:
    /// every support its own
    #[serde(default)]
    pub towers: Vec<String>,
    /// dead-ends of the section held by tension (strain) strings in line with the conductor, at most one
    /// per end; empty: every dead-end a fixed point
    #[serde(default)]
    pub tension_strings: Vec<TensionStringSpec>,
    /// a bundle of sub-conductors with spacers; absent: a single conductor
    #[serde(default)]
    pub bundle: Option<BundleToml>,
    /// the conductor's own events, as `[[events]]` of a single-conductor scenario
    #[serde(default)]
    pub events: Vec<EventSpec>,
    /// for a bundle: the sub-conductors (numbered from 1, as their names `NAME.1`, `NAME.2`, ...) that the
    /// events act on; empty: all of them
    #[serde(default)]
    pub events_on: Vec<usize>,
}

/// A tension (dead-end, strain) insulator string: an insulator in line with the conductor between the
/// dead-end's point and the conductor's end.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TensionStringSpec {
    /// the section support it holds: the first (0) or the last, a dead-end; the string hangs from that
    /// dead-end's `point_m` (on the support's tower if `towers` names one, which may be elastic)
    pub support: usize,
    /// unstretched length `L0` [m], in [0.01, 20] (strain strings with their hardware: 2 to 6 m)
    pub length_m: f64,
    /// mass [kg], in [0, 5000], lumped at the conductor's end node (strain strings: 50 to 300 kg)
    pub mass_kg: f64,
    /// axial stiffness `EA` [N], in [1e4, 1e10] (a spring `EA / L0` [N/m]; long-rod strings about 1e8 N)
    pub stiffness_n: f64,
    /// axial damping `BA` [N s], in [0, 1e7] (a damper `BA / L0` [N s/m]); default 0
    #[serde(default)]
    pub damping_n_s: f64,
}

/// The valid tension strings of a conductor: `(support, spec)` for each whose support is an end of the
/// section and a dead-end, and whose length is valid (others are reported by validation).
fn valid_tension_strings(c: &LineConductorSpec) -> Vec<TensionStringSpec> {
    let n = c.section.supports.len();
    c.tension_strings
        .iter()
        .filter(|t| {
            n >= 2
                && (t.support == 0 || t.support == n - 1)
                && matches!(c.section.supports[t.support], SupportSpec::DeadEnd { .. })
                && t.length_m.is_finite()
                && (0.01..=20.0).contains(&t.length_m)
        })
        .copied()
        .collect()
}

/// From the dead-end `support` (an end) of a section to the neighbouring attachment point (the next
/// dead-end's point or suspension string's plumb clamp): the vector [m].
fn towards_span(sec: &SectionSpec, support: usize) -> [f64; 3] {
    let n = sec.supports.len();
    let other = if support == 0 { 1 } else { n - 2 };
    let to = match sec.supports[other] {
        SupportSpec::DeadEnd { point_m } => point_m,
        SupportSpec::Suspension { pivot_m, insulator_length_m, .. } => {
            [pivot_m[0], pivot_m[1], pivot_m[2] - insulator_length_m]
        }
    };
    let from = match sec.supports[support] {
        SupportSpec::DeadEnd { point_m } => point_m,
        SupportSpec::Suspension { pivot_m, .. } => pivot_m,
    };
    [to[0] - from[0], to[1] - from[1], to[2] - from[2]]
}

/// The conductor's section as its single-conductor code builds it: a dead-end held by a tension string
/// moves towards the span, along the line to the neighbouring attachment point, by the string's
/// unstretched length: the conductor starts there (the string's stretch, millimetres, is taken up by the
/// dynamics or by an equilibrium start).
fn conductor_section(c: &LineConductorSpec) -> SectionSpec {
    let mut sec = c.section.clone();
    for t in valid_tension_strings(c) {
        let d = towards_span(&sec, t.support);
        let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        if let SupportSpec::DeadEnd { point_m } = &mut sec.supports[t.support]
            && len.is_finite()
            && len > 2.0 * t.length_m
        {
            *point_m = [0, 1, 2].map(|k| point_m[k] + t.length_m * d[k] / len);
        }
    }
    sec
}

/// A bundle.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BundleToml {
    /// number of sub-conductors, in [2, 8] (twin: side by side; triple: apex up; quad: a square)
    pub sub_conductors: usize,
    /// diameter of the circle through the sub-conductors [m], in [0.05, 3] (a twin's spacing; a quad of
    /// side `a` has `a sqrt(2)`)
    pub diameter_m: f64,
    /// spacer positions: `{ span = k, at_fraction = f }`, `f` in (0, 1) of the span's unstretched length
    pub spacers: Vec<SpacerAt>,
    /// stiffness of each spacer arm [N/m], in [1e3, 1e9]; default 1e6 (rigid spacer frames: 1e6 to 1e7)
    #[serde(default = "default_spacer_stiffness")]
    pub spacer_stiffness_n_per_m: f64,
    /// damping of each spacer arm [N s/m], in [0, 1e6]; default 0 (damping spacers: 1e2 to 1e4)
    #[serde(default)]
    pub spacer_damping_n_s_per_m: f64,
    /// mass of one spacer [kg], in [0, 100], shared by its clamps; default 0 (spacers weigh 1 to 10 kg)
    #[serde(default)]
    pub spacer_mass_kg: f64,
}

fn default_spacer_stiffness() -> f64 {
    1.0e6
}

/// Where a spacer sits.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpacerAt {
    /// span index (0 = the first span of the section)
    pub span: usize,
    /// fraction of the span's unstretched length, in (0, 1)
    pub at_fraction: f64,
}

/// A line ready to run: the solver, each conductor's plan (its event timeline, probes, outputs) and what
/// the line's outputs need.
#[derive(Clone, Debug)]
pub struct LinePlan {
    /// scenario name
    pub name: String,
    /// the solver at `t = 0`
    pub line: LineExplicit,
    /// each conductor's plan, in the order of the line's conductors (a bundle's sub-conductors share
    /// their conductor's plan, with the solver replaced by the sub-conductor's)
    pub plans: Vec<Plan>,
    /// the conductor groups whose clearances are tracked (a phase, an earth wire, a bundle's members)
    pub groups: Vec<Vec<usize>>,
    /// the groups' names
    pub group_names: Vec<String>,
    /// when to stop
    pub stop: Stop,
    /// interval between time-series rows [s]
    pub sample_interval_s: f64,
    /// the static solve of `[initial] shape = "equilibrium"`, if it was asked for
    pub initial_equilibrium: Option<crate::statics::StaticReport>,
    /// the short circuit of `[short_circuit]`, validated, if any
    pub short_circuit: Option<super::short_circuit::ShortCircuitSpec>,
}

/// Parse a line scenario from TOML text (`file` names it in messages). Each conductor's `conductor`
/// table may name a catalogue conductor, as `[conductor]` of a single-conductor scenario.
pub fn parse(text: &str, file: &str) -> Result<LineScenario, InputError> {
    let mut doc = super::locate::parse_table(text, file)?;
    if let Some(toml::Value::Table(line)) = doc.get_mut("line")
        && let Some(toml::Value::Array(cs)) = line.get_mut("conductors")
    {
        for (k, c) in cs.iter_mut().enumerate() {
            if let toml::Value::Table(c) = c
                && let Some(toml::Value::Table(cd)) = c.get_mut("conductor")
            {
                super::fill_from_catalog(cd, file, &format!("line.conductors[{k}].conductor"), None)?;
            }
        }
    }
    let celsius = super::temperature::to_kelvin(&mut doc)
        .map_err(|problems| InputError::Invalid { file: file.to_string(), problems })?;
    let mut s: LineScenario = super::locate::from_table(doc, text, file)?;
    s.celsius = celsius;
    Ok(s)
}

/// Whether a TOML text is a line scenario (it has a `[line]` table).
pub fn is_line(text: &str) -> bool {
    text.parse::<toml::Table>().is_ok_and(|t| is_line_table(&t))
}

/// Whether a parsed TOML document is a line scenario (it has a `line` key).
pub fn is_line_table(t: &toml::Table) -> bool {
    t.contains_key("line")
}

/// Check every field and build the line; every problem is reported with its field.
pub fn plan(s: &LineScenario, file: &str) -> Result<LinePlan, InputError> {
    build_line(s)
        .map_err(|problems| InputError::Invalid { file: file.to_string(), problems: s.celsius.as_written(problems) })
}

/// A conductor's single-conductor scenario: its tables and the file's global ones.
fn single(s: &LineScenario, c: &LineConductorSpec) -> Scenario {
    Scenario {
        name: Some(c.name.clone()),
        description: None,
        conductor: c.conductor.clone(),
        geometry: None,
        section: Some(conductor_section(c)),
        initial: InitialSpec::default(),
        loads: s.loads.clone(),
        numerics: s.numerics.clone(),
        duration: s.duration.clone(),
        output: s.output.clone(),
        ground: s.ground.clone(),
        events: c.events.iter().chain(&s.events).cloned().collect(),
        thermal: None,
        rating: None,
        paper: None,
        celsius: Default::default(),
    }
}

/// The field path of a conductor's own table under `line.conductors[k]`; global tables keep theirs. The
/// conductor's single scenario lists its own `own_events` events first, then the global ones.
fn prefixed(k: usize, field: &str, own_events: usize) -> String {
    if let Some(rest) = field.strip_prefix("events[") {
        let (index, tail) = rest.split_once(']').unwrap_or((rest, ""));
        return match index.parse::<usize>() {
            Ok(j) if j < own_events => format!("line.conductors[{k}].events[{j}]{tail}"),
            Ok(j) => format!("events[{}]{tail}", j - own_events),
            Err(_) => field.to_string(),
        };
    }
    let own = ["conductor", "section", "events"];
    if own.iter().any(|o| field == *o || field.starts_with(&format!("{o}.")) || field.starts_with(&format!("{o}["))) {
        format!("line.conductors[{k}].{field}")
    } else {
        field.to_string()
    }
}

fn build_line(s: &LineScenario) -> Result<LinePlan, Vec<Problem>> {
    let mut c = Check(Vec::new());
    let spec = &s.line;
    if spec.conductors.is_empty() {
        c.fail("line.conductors", "[]", "a line needs at least one conductor");
    }
    c.range("line.string_damping_n_s", spec.string_damping_n_s, &INSULATOR_DAMPING_N_S);
    for (t, tower) in spec.towers.iter().enumerate() {
        let f = |name: &str| format!("line.towers[{t}].{name}");
        if tower.name.is_empty() || spec.towers[..t].iter().any(|o| o.name == tower.name) {
            c.fail(&f("name"), format!("{:?}", tower.name), "must be a non-empty name, unique among the towers");
        }
        c.coordinates(&f("position_m"), tower.position_m);
        if let Some(e) = &tower.elastic {
            let spring = Allowed::closed(1.0e2, 1.0e10, "N/m");
            c.range(&f("elastic.along_n_per_m"), e.along_n_per_m, &spring);
            c.range(&f("elastic.across_n_per_m"), e.across_n_per_m, &spring);
            c.range(&f("elastic.mass_kg"), e.mass_kg, &Allowed::closed(1.0, 1.0e6, "kg"));
            c.range(&f("elastic.damping_n_s_per_m"), e.damping_n_s_per_m, &Allowed::closed(0.0, 1.0e8, "N s/m"));
            let h = (e.along[0] * e.along[0] + e.along[1] * e.along[1]).sqrt();
            if !(h.is_finite() && h > 1e-6 && e.along[2] == 0.0) {
                c.fail(
                    &f("elastic.along"),
                    format!("{:?}", e.along),
                    "must be a horizontal direction [a, b, 0], not zero",
                );
            }
        }
    }
    let mut plans = Vec::new();
    let mut nested: Vec<Problem> = Vec::new();
    for (k, cd) in spec.conductors.iter().enumerate() {
        let f = |name: &str| format!("line.conductors[{k}].{name}");
        if cd.name.is_empty() || spec.conductors[..k].iter().any(|o| o.name == cd.name) {
            c.fail(&f("name"), format!("{:?}", cd.name), "must be a non-empty name, unique among the conductors");
        }
        if let Some(d) = &cd.dropper {
            let p = dropper_checks(&mut c, s, k, d, &plans);
            plans.push(p);
            continue;
        }
        let n_sup = cd.section.supports.len();
        if !cd.towers.is_empty() && cd.towers.len() != n_sup {
            c.fail(
                &f("towers"),
                format!("{} names", cd.towers.len()),
                &format!("must name one tower (or \"\") per support of the section: {n_sup}"),
            );
        }
        for (j, t) in cd.towers.iter().enumerate() {
            if !t.is_empty() && !spec.towers.iter().any(|x| &x.name == t) {
                c.fail(
                    &f(&format!("towers[{j}]")),
                    format!("{t:?}"),
                    "must be \"\" or the name of a tower of line.towers",
                );
            }
        }
        for (j, t) in cd.tension_strings.iter().enumerate() {
            let g = |name: &str| f(&format!("tension_strings[{j}].{name}"));
            let end = n_sup >= 2 && (t.support == 0 || t.support == n_sup - 1);
            if !end || !matches!(cd.section.supports[t.support], SupportSpec::DeadEnd { .. }) {
                c.fail(
                    &g("support"),
                    t.support,
                    &format!(
                        "must be the index of a dead-end at an end of the section: 0 or {}",
                        n_sup.saturating_sub(1)
                    ),
                );
            } else if cd.tension_strings[..j].iter().any(|o| o.support == t.support) {
                c.fail(&g("support"), t.support, "must name each end once: one tension string per dead-end");
            }
            if c.range(&g("length_m"), t.length_m, &INSULATOR_LENGTH_M) && end {
                let d = towards_span(&cd.section, t.support);
                let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                if len.is_finite() && len <= 2.0 * t.length_m {
                    c.fail(
                        &g("length_m"),
                        t.length_m,
                        &format!("must be under half the distance {len} m to the next attachment point"),
                    );
                }
            }
            c.range(&g("mass_kg"), t.mass_kg, &INSULATOR_MASS_KG);
            c.range(
                &g("stiffness_n"),
                t.stiffness_n,
                &INSULATOR_STIFFNESS_N.note(" (strain strings are about 1e7 to 1e8 N)"),
            );
            c.range(&g("damping_n_s"), t.damping_n_s, &INSULATOR_DAMPING_N_S);
        }
        if spec.string_damping_n_s > 0.0 {
            for (j, sp) in cd.section.supports.iter().enumerate() {
                if let SupportSpec::Suspension { insulator_damping_n_s, .. } = sp
                    && *insulator_damping_n_s != 0.0
                {
                    c.fail(
                        &f(&format!("section.supports[{j}].insulator_damping_n_s")),
                        *insulator_damping_n_s,
                        "give either line.string_damping_n_s (every suspension string, as a link of the line) or \
                         the supports' own insulator_damping_n_s, not both",
                    );
                }
            }
        }
        if let Some(b) = &cd.bundle {
            c.range(&f("bundle.diameter_m"), b.diameter_m, &Allowed::closed(0.05, 3.0, "m"));
            let (k_arm, c_arm) = (b.spacer_stiffness_n_per_m, b.spacer_damping_n_s_per_m);
            c.range(&f("bundle.spacer_stiffness_n_per_m"), k_arm, &Allowed::closed(1.0e3, 1.0e9, "N/m"));
            c.range(&f("bundle.spacer_damping_n_s_per_m"), c_arm, &Allowed::closed(0.0, 1.0e6, "N s/m"));
            c.range(&f("bundle.spacer_mass_kg"), b.spacer_mass_kg, &Allowed::closed(0.0, 100.0, "kg"));
            if !(2..=8).contains(&b.sub_conductors) {
                c.fail(&f("bundle.sub_conductors"), b.sub_conductors, "must be in [2, 8]");
            }
            for (j, sp) in b.spacers.iter().enumerate() {
                if sp.span + 1 >= n_sup.max(1) {
                    c.fail(
                        &f(&format!("bundle.spacers[{j}].span")),
                        sp.span,
                        &format!("must be a span of the section: 0 to {}", n_sup.saturating_sub(2)),
                    );
                }
                if !(sp.at_fraction.is_finite() && sp.at_fraction > 0.0 && sp.at_fraction < 1.0) {
                    c.fail(&f(&format!("bundle.spacers[{j}].at_fraction")), sp.at_fraction, "must be in (0, 1)");
                }
            }
        }
        let members = cd.bundle.as_ref().map_or(1, |b| b.sub_conductors);
        for (j, &m) in cd.events_on.iter().enumerate() {
            if m == 0 || m > members || cd.bundle.is_none() {
                c.fail(
                    &f(&format!("events_on[{j}]")),
                    m,
                    &format!("must number a sub-conductor of the bundle: 1 to {members} (a bundle only)"),
                );
            }
        }
        match build(&single(s, cd)) {
            Ok(p) => plans.push(Some(p)),
            Err(ps) => {
                for p in ps {
                    let field = prefixed(k, &p.field, cd.events.len());
                    if !nested.iter().any(|q| q.field == field && q.value == p.value) {
                        nested.push(Problem { field, ..p });
                    }
                }
                plans.push(None);
            }
        }
    }
    if let Some(sc) = &s.short_circuit {
        sc.check(spec, s.duration.end_time_s, &mut c);
    }
    let Check(mut problems) = c;
    problems.extend(nested);
    if !problems.is_empty() {
        return Err(problems);
    }
    let plans: Vec<Plan> = plans.into_iter().flatten().collect();
    // The sub-conductors a bundle's own events do not act on still take the file's global events: their
    // timeline is that of the conductor without its own events (validated above as part of the whole).
    let mut global_only = Vec::with_capacity(plans.len());
    for c in &spec.conductors {
        global_only.push(if c.events_on.is_empty() {
            None
        } else {
            let mut g = single(s, c);
            g.events = s.events.clone();
            Some(build(&g)?)
        });
    }
    assemble(s, plans, global_only)
}

/// The checks of a dropper conductor `k` (its fields and those it may not have) and its plan
/// ([`super::dropper`]); `plans` holds the plans of the conductors before it.
fn dropper_checks(
    c: &mut Check,
    s: &LineScenario,
    k: usize,
    d: &super::dropper::DropperToml,
    plans: &[Option<Plan>],
) -> Option<Plan> {
    let cd = &s.line.conductors[k];
    let f = |name: &str| format!("line.conductors[{k}].{name}");
    let not = [
        ("section", !cd.section.supports.is_empty() || !cd.section.spans.is_empty()),
        ("towers", !cd.towers.is_empty()),
        ("tension_strings", !cd.tension_strings.is_empty()),
        ("bundle", cd.bundle.is_some()),
        ("events_on", !cd.events_on.is_empty()),
    ];
    for (name, given) in not {
        if given {
            c.fail(
                &f(name),
                "(given)",
                "a dropper has none: it hangs from its `dropper.from` conductor (docs/line.md)",
            );
        }
    }
    if let Some(p) = super::dropper::check_from(&s.line.conductors, k) {
        c.0.push(p);
        return None;
    }
    let j = s.line.conductors[..k].iter().position(|o| o.name == d.from)?;
    let joint = plans[j].as_ref().and_then(|p| {
        let node = super::dropper::joint_node(&p.spans, d.span, d.at_fraction)?;
        (d.at_fraction > 0.0 && d.at_fraction < 1.0).then(|| p.solver.wire().position(node))
    });
    let plan = super::dropper::plan(c, &f, d, joint, single(s, cd));
    // A plan only if the conductor it hangs from has one (its problems are its own).
    plan.filter(|_| plans[j].is_some())
}

/// Join the conductors' plans into the line's model and solver.
/// For a start on the line's equilibrium: the ice events at `t = 0` of a conductor's plan applied to its
/// wire now (and taken out of its timeline), so that the equilibrium carries them; `Err` if one leaves a
/// segment without mass.
fn ice_at_start(own: &mut Plan, wire: &mut crate::wire::Wire) -> Result<(), ()> {
    let (now, later): (Vec<_>, Vec<_>) =
        std::mem::take(&mut own.events).into_iter().partition(|e| e.time_s == 0.0 && e.action.is_ice());
    own.events = later;
    for e in now {
        if e.action.apply_ice(wire) == Some(false) {
            return Err(());
        }
    }
    Ok(())
}

fn assemble(s: &LineScenario, plans: Vec<Plan>, global_only: Vec<Option<Plan>>) -> Result<LinePlan, Vec<Problem>> {
    let spec = &s.line;
    let problem = |field: String, value: String, allowed: String| vec![Problem { field, value, allowed }];
    let mut model = Model::new();
    for t in &spec.towers {
        model.add_support(Support {
            name: t.name.clone(),
            position_m: t.position_m,
            elastic: t.elastic.map(|e| {
                let h = (e.along[0] * e.along[0] + e.along[1] * e.along[1]).sqrt();
                ElasticSupport {
                    along: [e.along[0] / h, e.along[1] / h, 0.0],
                    along_n_per_m: e.along_n_per_m,
                    across_n_per_m: e.across_n_per_m,
                    mass_kg: e.mass_kg,
                    damping_n_s_per_m: e.damping_n_s_per_m,
                }
            }),
        });
    }
    let tower_index = |name: &str| spec.towers.iter().position(|t| t.name == name);
    let mut line_plans = Vec::new();
    let (mut groups, mut group_names): (Vec<Vec<usize>>, Vec<String>) = (Vec::new(), Vec::new());
    let mut bundles = 0;
    let mut names_seen: Vec<String> = Vec::new();
    // The model's conductors of each of the file's conductors, and each one's clearance group.
    let mut members_of: Vec<Vec<usize>> = Vec::new();
    let mut group_of: Vec<usize> = Vec::new();
    for (k, (c, plan)) in spec.conductors.iter().zip(&plans).enumerate() {
        let f = |name: &str| format!("line.conductors[{k}].{name}");
        if let Some(d) = &c.dropper {
            let j = spec.conductors[..k].iter().position(|o| o.name == d.from).expect("validated: dropper.from");
            let master = members_of[j][0];
            let node = super::dropper::joint_node(&plans[j].spans, d.span, d.at_fraction).expect("validated");
            let mut own = plan.clone();
            let mut wire = plan.solver.wire().clone();
            if s.initial.shape == LineShapeSpec::Equilibrium {
                ice_at_start(&mut own, &mut wire).map_err(|()| {
                    problem(f("events"), "ice at t = 0".into(), "leaves a segment without mass".into())
                })?;
            }
            let slug = crate::run::line::slug(&c.name);
            if names_seen.contains(&slug) {
                return Err(problem(
                    f("name"),
                    format!("{:?}", c.name),
                    format!(
                        "its outputs would go where another conductor's go (conductors/{slug}/): choose another name"
                    ),
                ));
            }
            names_seen.push(slug);
            let role = model.conductors[master].role;
            let conductor = LineConductor { name: c.name.clone(), role, wire, loads: *plan.solver.loads() };
            let top = Endpoint::Node(NodeRef::new(master, node));
            let (index, _) = crate::line::dropper::add_dropper(&mut model, conductor, top, d.to_m.is_some())
                .map_err(|e| problem(f("dropper"), "(model)".into(), e.to_string()))?;
            line_plans.push(own);
            members_of.push(vec![index]);
            // A dropper is part of its span conductor's phase: its clearance is the phase's.
            groups[group_of[j]].push(index);
            group_of.push(group_of[j]);
            continue;
        }
        let base = plan.solver.wire().clone();
        // A bundle member on a crossarm of its own would carry a crossarm per sub-conductor, its spring
        // preloaded by the member's offset: the elasticity of a bundle's support belongs to a tower.
        if c.bundle.is_some() && base.insulators.iter().any(|i| i.crossarm.is_some()) {
            return Err(problem(
                f("section.supports"),
                "a crossarm".into(),
                "a bundle hangs its sub-conductors on rigid supports or towers: give a tower `elastic` instead of a crossarm".into(),
            ));
        }
        let n_sup = c.section.supports.len();
        // The node of each support of the section.
        let mut support_node: Vec<usize> = plan.spans.iter().map(|&(first, _)| first).collect();
        // `Plan::spans` holds each span's (first node, last node).
        let &(_, last) = plan.spans.last().expect("a section has spans");
        support_node.push(last);
        let offsets: Vec<[f64; 2]> = match &c.bundle {
            Some(b) => {
                crate::line::build::BundleSpec::regular(b.sub_conductors, b.diameter_m, Vec::new(), 1.0).offsets_m
            }
            None => vec![[0.0, 0.0]],
        };
        // Across the line: e_t = e3 x e_l from the section's first to last support.
        let (a, z) = (base.position(support_node[0]), base.position(support_node[n_sup - 1]));
        let h = [z[0] - a[0], z[1] - a[1]];
        let hn = (h[0] * h[0] + h[1] * h[1]).sqrt().max(f64::MIN_POSITIVE);
        let across = [-h[1] / hn, h[0] / hn];
        let role = match c.role {
            RoleSpec::Phase => Role::Phase,
            RoleSpec::EarthWire => Role::EarthWire,
        };
        let mut members = Vec::new();
        for (i, o) in offsets.iter().enumerate() {
            let shift = [o[0] * across[0], o[0] * across[1], o[1]];
            let mut wire = base.clone();
            if shift != [0.0; 3] {
                for kk in 0..3 {
                    for x in &mut wire.x[kk] {
                        *x += shift[kk];
                    }
                }
                for ins in &mut wire.insulators {
                    for kk in 0..3 {
                        ins.pivot_m[kk] += shift[kk];
                    }
                }
            }
            let index = model.conductors.len();
            // The clamp node of each of the wire's strings before any becomes a link (the events name a
            // string by its index among them).
            let string_nodes: Vec<usize> = wire.insulators.iter().map(|i| i.node).collect();
            let member = if offsets.len() > 1 { format!("{}.{}", c.name, i + 1) } else { c.name.clone() };
            // Supports on towers, strings damped by `line.string_damping_n_s` and tension strings become
            // links.
            for (j, &node) in support_node.iter().enumerate() {
                let tower = c.towers.get(j).filter(|t| !t.is_empty()).and_then(|t| tower_index(t));
                if let Some(ts) = c.tension_strings.iter().find(|t| t.support == j) {
                    // The string hangs from the dead-end's point (moved with the member), the conductor's end
                    // node is free and carries the string's mass.
                    let SupportSpec::DeadEnd { point_m } = c.section.supports[j] else {
                        unreachable!("validated: a tension string holds a dead-end")
                    };
                    let top = [point_m[0] + shift[0], point_m[1] + shift[1], point_m[2] + shift[2]];
                    let support = match tower {
                        Some(t) => t,
                        None => model.add_support(Support::rigid(format!("{member} support {j}"), top)),
                    };
                    let p = model.supports[support].position_m;
                    wire.set_constraint(node, crate::wire::Constraint::Free);
                    if ts.mass_kg > 0.0 {
                        model.point_masses.push(PointMass { node: NodeRef::new(index, node), mass_kg: ts.mass_kg });
                    }
                    model.links.push(Link {
                        kind: LinkKind::TensionString,
                        a: Endpoint::Support { support, offset_m: [top[0] - p[0], top[1] - p[1], top[2] - p[2]] },
                        b: Endpoint::Node(NodeRef::new(index, node)),
                        law: LinkLaw::string(ts.length_m, ts.stiffness_n, ts.damping_n_s),
                        intact: true,
                    });
                    continue;
                }
                let ins = wire.insulators.iter().position(|s| s.node == node);
                match (tower, ins) {
                    (Some(t), None) => {
                        if model.supports[t].elastic.is_some() {
                            return Err(problem(
                                f(&format!("towers[{j}]")),
                                format!("{:?}", c.towers[j]),
                                "a dead-end cannot be held by an elastic tower top (hang it on a rigid tower, or give the support a string)".into(),
                            ));
                        }
                        model.dead_ends.push(DeadEnd { node: NodeRef::new(index, node), support: t });
                    }
                    (tower, Some(s)) if tower.is_some() || spec.string_damping_n_s > 0.0 => {
                        let ins = wire.insulators.remove(s);
                        if ins.crossarm.is_some() {
                            return Err(problem(
                                f(&format!("section.supports[{j}].crossarm")),
                                "a crossarm".into(),
                                "a string on a tower, or damped by line.string_damping_n_s, is a link of the line: \
                                 its elasticity is a tower's (`elastic`), not a crossarm of the section (a \
                                 support's own insulator_damping_n_s keeps its crossarm)"
                                    .into(),
                            ));
                        }
                        let support = match tower {
                            Some(t) => t,
                            None => model.add_support(Support::rigid(format!("{member} support {j}"), ins.pivot_m)),
                        };
                        let p = model.supports[support].position_m;
                        let offset_m = [ins.pivot_m[0] - p[0], ins.pivot_m[1] - p[1], ins.pivot_m[2] - p[2]];
                        model.links.push(Link {
                            kind: LinkKind::SuspensionString,
                            a: Endpoint::Support { support, offset_m },
                            b: Endpoint::Node(NodeRef::new(index, node)),
                            // The line's damping, or (validated: not both) the support's own.
                            law: LinkLaw::string(
                                ins.length_m,
                                ins.stiffness_n,
                                spec.string_damping_n_s + ins.damping_n_s,
                            ),
                            intact: true,
                        });
                    }
                    _ => {}
                }
            }
            // The member's own timeline: the conductor's events, if they act on it; with an equilibrium
            // start, the ice of t = 0 applied now (part of the initial state, as for one conductor).
            let mut own = plan.clone();
            if !(c.events_on.is_empty() || c.events_on.contains(&(i + 1))) {
                own.events = global_only[k].as_ref().map_or_else(Vec::new, |g| g.events.clone());
            }
            // A string that failed or slipped is named by its index among the wire's strings: renumber
            // them after the conversion; a string that became a link cannot fail or slip yet.
            for e in &mut own.events {
                if let Action::InsulatorFailure { insulator } | Action::ClampSlip { insulator } = &mut e.action {
                    let node = string_nodes.get(*insulator).copied();
                    match node.and_then(|n| wire.insulators.iter().position(|x| x.node == n)) {
                        Some(now) => *insulator = now,
                        None => {
                            return Err(problem(
                                f("events"),
                                format!("a string failure or slip at node {}", node.unwrap_or(0)),
                                "a string held by a tower, or damped by line.string_damping_n_s, is a link of the \
                                 line and cannot fail or slip yet: give that support no tower, and its string its \
                                 own insulator_damping_n_s instead"
                                    .into(),
                            ));
                        }
                    }
                }
                if let Action::Release { node } = e.action
                    && c.tension_strings.iter().any(|t| support_node.get(t.support) == Some(&node))
                {
                    return Err(problem(
                        f("events"),
                        format!("a release at node {node}"),
                        "a dead-end held by a tension string is a link of the line and cannot be released yet".into(),
                    ));
                }
            }
            if s.initial.shape == LineShapeSpec::Equilibrium {
                ice_at_start(&mut own, &mut wire).map_err(|()| {
                    problem(f("events"), "ice at t = 0".into(), "leaves a segment without mass".into())
                })?;
            }
            line_plans.push(own);
            let name = member;
            // Outputs are written under each name's file form: two names may not share it.
            let slug = crate::run::line::slug(&name);
            if names_seen.contains(&slug) {
                return Err(problem(
                    f("name"),
                    format!("{name:?}"),
                    format!(
                        "its outputs would go where another conductor's go (conductors/{slug}/): choose another name"
                    ),
                ));
            }
            names_seen.push(slug);
            let role = if offsets.len() > 1 { Role::SubConductor { bundle: bundles, index: i } } else { role };
            model.conductors.push(LineConductor { name, role, wire, loads: *plan.solver.loads() });
            members.push(index);
        }
        if let Some(b) = &c.bundle {
            bundles += 1;
            for sp in &b.spacers {
                let (first, last) = plan.spans[sp.span];
                let count = last - first;
                let node = first + ((sp.at_fraction * count as f64).round() as usize).clamp(1, count - 1);
                let arm = (b.spacer_stiffness_n_per_m, b.spacer_damping_n_s_per_m);
                crate::line::build::add_spacer(&mut model, &members, &offsets, node, arm, b.spacer_mass_kg);
            }
        }
        members_of.push(members.clone());
        group_of.push(groups.len());
        groups.push(members);
        group_names.push(c.name.clone());
    }
    // The smallest step of the conductors, the smoothing coefficient per that step.
    let params = plans
        .iter()
        .map(|p| *p.solver.params())
        .min_by(|a, b| a.dt_s.total_cmp(&b.dt_s))
        .expect("at least one conductor");
    let mut params = params;
    let mut step_warning = None;
    let line = match LineExplicit::new(&model, params) {
        // Too stiff for the conductors' step: the line's stable step times the Courant number (module doc).
        Err(LineError::Step { dt_s, limit_s, at, stiffness_n_per_m, damping_n_s_per_m, mass_kg }) => {
            params.dt_s = s.numerics.courant * limit_s;
            let ratio = dt_s / params.dt_s;
            let damping = if params.smoothing > 0.0 {
                format!("; the smoothing acts per step, so it damps {ratio:.2} times as much per second")
            } else {
                String::new()
            };
            step_warning = Some(super::Warning {
                field: "line".into(),
                value: at.clone(),
                reason: format!(
                    "sets the time step: {at} (stiffness {stiffness_n_per_m:.4e} N/m, damping \
                     {damping_n_s_per_m:.4e} N s/m, mass {mass_kg:.4e} kg) is stable below {limit_s:.4e} s \
                     (Gershgorin's bound, docs/line.md), so at numerics.courant = {} the line steps at {:.4e} s \
                     instead of the conductors' {dt_s:.4e} s, {ratio:.2} times as many steps{damping}",
                    s.numerics.courant, params.dt_s
                ),
            });
            LineExplicit::new(&model, params)
        }
        built => built,
    };
    let line = line.map_err(|e| match e {
        LineError::Step { .. } => problem(
            "numerics.courant".into(),
            s.numerics.courant.to_string(),
            format!("{e}: lower the Courant number, or soften the attachment"),
        ),
        LineError::Model(m) => problem("line".into(), "(model)".into(), m.to_string()),
    })?;
    let mut line = line;
    let mut initial_equilibrium = None;
    if s.initial.shape == LineShapeSpec::Equilibrium {
        let report = crate::statics::solve_line(&mut line, &crate::statics::StaticOptions::default()).map_err(|e| {
            problem(
                "initial.shape".into(),
                "\"equilibrium\"".into(),
                format!("the static equilibrium of the line at t = 0 was not found: {e}"),
            )
        })?;
        initial_equilibrium = Some(report);
    }
    // Ground contact, as each conductor's plan has it (switched on after the equilibrium, as for one).
    for (c, p) in line_plans.iter().enumerate() {
        if let Some(g) = p.solver.ground() {
            line.conductor_mut(c).set_ground(Some(g.clone()));
        }
    }
    // Each conductor keeps its own step parameters (its speed bound: its own wave speed), with the line's
    // step.
    for (c, p) in line_plans.iter().enumerate() {
        let own = StepParams { dt_s: params.dt_s, ..*p.solver.params() };
        if own.max_speed_m_per_s != params.max_speed_m_per_s {
            *line.conductor_mut(c).params_mut() = own;
        }
    }
    for (p, c) in line_plans.iter_mut().zip(line.conductors()) {
        p.solver = c.clone();
    }
    if let Some(w) = step_warning {
        line_plans[0].warnings.push(w);
    }
    // The short circuit's electromagnetic load, after the initial equilibrium (the currents flow from
    // `short_circuit.start_s`; without current the step is the one without it).
    if let Some(sc) = &s.short_circuit {
        let spec_of = |g: &String| spec.conductors.iter().find(|c| &c.name == g);
        let radius: Vec<f64> = group_names
            .iter()
            .map(|g| spec_of(g).and_then(|c| c.conductor.diameter_m).map_or(f64::NAN, |d| 0.5 * d))
            .collect();
        let direction: Vec<[f64; 2]> = group_names
            .iter()
            .map(|g| {
                spec_of(g).map_or([0.0, 1.0], |c| {
                    let h = towards_span(&c.section, 0);
                    [h[0], h[1]]
                })
            })
            .collect();
        // The current divides among a bundle's sub-conductors; a dropper carries its phase's whole current
        // (it leads the current from the busbar to the apparatus; the busbar is taken to carry it along its
        // whole length, the conservative choice: docs/short_circuit.md).
        let sharing = crate::line::dropper::without_droppers(&groups, line.links());
        let mut em = sc
            .electromagnetic(&group_names, &sharing, &radius, &direction)
            .map_err(|(field, why)| problem(field, "(short circuit)".into(), why))?;
        for d in crate::line::dropper::droppers(line.links()) {
            let g = groups.iter().position(|g| g.contains(&d)).expect("a dropper has a group");
            let member = sharing[g].first().copied();
            if let Some(c) = em.carriers.iter().find(|c| Some(c.conductor) == member).copied() {
                em.carriers.push(crate::line::electromagnetic::Carrier {
                    conductor: d,
                    phase: c.phase,
                    share: c.share.signum(),
                    core_radius_m: radius[g],
                });
            }
        }
        line.set_electromagnetic(Some(em))
            .map_err(|e| problem("short_circuit".into(), "(carriers)".into(), e.to_string()))?;
        if sc.contact {
            // The sub-conductors of each bundle, and every two conductors of different phases named in
            // `phases`; gap: the two radii (a conductor without a diameter: its group's).
            let group_of = |c: usize| groups.iter().position(|g| g.contains(&c));
            let named: Vec<usize> = sc.phases.iter().filter_map(|p| group_names.iter().position(|g| g == p)).collect();
            let roles = line.roles().to_vec();
            let mut pairs = Vec::new();
            let n = line.conductors().len();
            for a in 0..n {
                for b in a + 1..n {
                    let (Some(ga), Some(gb)) = (group_of(a), group_of(b)) else { continue };
                    let same_bundle = roles[a].bundle().is_some() && roles[a].bundle() == roles[b].bundle();
                    let phases = ga != gb && named.contains(&ga) && named.contains(&gb);
                    let gap = radius[ga] + radius[gb];
                    if (same_bundle || phases) && gap.is_finite() && gap > 0.0 {
                        pairs.push(ContactPair { a, b, gap_m: gap });
                    }
                }
            }
            let contact = ConductorContact {
                pairs,
                restitution: sc.contact_restitution,
                stiffness_n_per_m2: sc.contact_stiffness_n_per_m2,
                ..ConductorContact::default()
            };
            let before = line.params().dt_s;
            line.set_contact(Some(contact))
                .map_err(|e| problem("short_circuit.contact".into(), "(pairs)".into(), e.to_string()))?;
            let after = line.params().dt_s;
            if after < before {
                // A contact stiffer than the step allows: the line steps at the contact's limit.
                for (p, c) in line_plans.iter_mut().zip(line.conductors()) {
                    *p.solver.params_mut() = *c.params();
                }
                line_plans[0].warnings.push(super::Warning {
                    field: "short_circuit.contact_stiffness_n_per_m2".into(),
                    value: format!("{:e}", sc.contact_stiffness_n_per_m2.unwrap_or(f64::NAN)),
                    reason: format!(
                        "sets the time step: the contact is stable below {after:.4e} s (w_c dt <= 0.5, \
                         docs/short_circuit.md), so the line steps at {after:.4e} s instead of {before:.4e} s, \
                         {:.2} times as many steps (the smoothing is scaled to the same viscosity per second)",
                        before / after
                    ),
                });
            }
        }
    }
    Ok(LinePlan {
        name: s.name.clone().unwrap_or_else(|| "line".into()),
        line,
        plans: line_plans,
        groups,
        group_names,
        stop: plans[0].stop,
        sample_interval_s: plans[0].sample_interval_s,
        initial_equilibrium,
        short_circuit: s.short_circuit.clone(),
    })
}
