//! The workloads of `ohl bench`: the library's kernel configurations ([`Config`]) and, around the same
//! kernel, the elements a section or a line adds, each built by the library from a committed case file
//! (so the bench times what `ohl run` and `ohl shortcircuit` step), with its grid set by `N` and its
//! events, initial static solve and output left out (the timed part is the step alone):
//!
//! - `ground_contact`: [`Config::PlaneWeight`] on a level ground at the chord's height (restitution 0.2,
//!   friction 0.5, as case a): every node is on the ground from the first step, the contact pass
//!   ([`ohl::scheme::contact`]) acts on every node;
//! - `section_strings`: case b's 5 x 400 m Drake section with its 4 suspension insulator strings
//!   (`cases/b_ice_shedding.toml`), `N` segments per span;
//! - `bundle_spacers` / `bundle_bare`: case g's quad bundle of Drake over 3 x 400 m with its 18 spacers
//!   (six arms each) and its strings (`cases/g_quad_bundle_break.toml`), and the same without spacers;
//! - `short_circuit` / `short_circuit_bare`: case j's three distribution phases with the short circuit's
//!   pair forces (`cases/j_distribution_reclose.toml`, [`ohl::line::electromagnetic`]) on from `t = 0`
//!   for 10 s (the longest the scenario allows, longer than any timed episode), and the same line
//!   without the short circuit;
//!
//! Two more workloads are not in the throughput tables but time the elements of the `--dry-run` cost
//! model of a line ([`ohl::scenario::work`], `ohl bench --costs`), on case j's three phases as well:
//!
//! - `short_circuit_contact`: the short circuit set but its current starting at 900 s, after every timed
//!   episode: the contact between the phases ([`ohl::scheme::conductor_contact`], set with a short
//!   circuit) acts at every level, the pair forces never;
//! - `line_clearances`: the bare line with the clearance tracker ([`ohl::line::clearance`]) measuring
//!   every pair of phases at every level, as `ohl run` does at a level where a new least is possible.
//!
//! Interphase spacers are links of the library's model ([`ohl::line::LinkKind::InterphaseSpacer`]) that
//! the line scenarios do not offer, so no committed case has one; they are not timed here.
//!
//! The difference of a pair's times per node-step is the element's cost per node-step.

use ohl::line::clearance::ClearanceTracker;
use ohl::scenario;
pub use ohl::scheme::configs::Config;
use ohl::scheme::{Explicit, Ground, LineExplicit};

/// A workload of `ohl bench`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Workload {
    /// a kernel configuration of the library, `N` segments
    Kernel(Config),
    /// plane_weight lying on a level ground
    GroundContact,
    /// case b's section with suspension strings, `N` segments per span
    SectionStrings,
    /// case g's quad bundle, with its spacers or without
    Bundle {
        /// with the spacers
        spacers: bool,
    },
    /// case j's three phases, with the short circuit's pair forces or without
    ShortCircuit {
        /// with the short circuit
        forces: bool,
    },
    /// case j's three phases with the short circuit's contact but no current in the timed steps
    ShortCircuitContact,
    /// case j's bare three phases with their clearances measured every level
    LineClearances,
}

/// The workloads of `ohl bench --costs`, in the order they are subtracted.
pub const COSTS: [Workload; 4] = [
    Workload::ShortCircuit { forces: false },
    Workload::ShortCircuitContact,
    Workload::ShortCircuit { forces: true },
    Workload::LineClearances,
];

/// The workloads with `N` the segments of one wire, in table order.
pub const WIRE: [Workload; 5] = [
    Workload::Kernel(Config::PlaneWeight),
    Workload::Kernel(Config::Wind3d),
    Workload::Kernel(Config::ViscousSmoothed),
    Workload::Kernel(Config::TwoMaterialPlane),
    Workload::GroundContact,
];

/// The workloads with `N` the segments per span of a section or line, in table order.
pub const LINE: [Workload; 5] = [
    Workload::SectionStrings,
    Workload::Bundle { spacers: true },
    Workload::Bundle { spacers: false },
    Workload::ShortCircuit { forces: true },
    Workload::ShortCircuit { forces: false },
];

impl Workload {
    /// Short name used in tables and files.
    pub fn name(self) -> &'static str {
        match self {
            Workload::Kernel(c) => c.name(),
            Workload::GroundContact => "ground_contact",
            Workload::SectionStrings => "section_strings",
            Workload::Bundle { spacers: true } => "bundle_spacers",
            Workload::Bundle { spacers: false } => "bundle_bare",
            Workload::ShortCircuit { forces: true } => "short_circuit",
            Workload::ShortCircuit { forces: false } => "short_circuit_bare",
            Workload::ShortCircuitContact => "short_circuit_contact",
            Workload::LineClearances => "line_clearances",
        }
    }

    /// Parse a name given by [`Workload::name`].
    pub fn from_name(s: &str) -> Option<Workload> {
        WIRE.into_iter().chain(LINE).chain(COSTS).find(|w| w.name() == s)
    }

    /// The solver of this workload at `n` segments (per span for a section or line), at `t = 0`.
    pub fn solver(self, n: usize) -> Solver {
        match self {
            Workload::Kernel(c) => Solver::Wire(c.solver(n)),
            Workload::GroundContact => {
                let mut s = Config::PlaneWeight.solver(n);
                s.set_ground(Some(Ground::level(0.0, 0.2, 0.5)));
                Solver::Wire(s)
            }
            Workload::SectionStrings => {
                let mut t = case_table(include_str!("../../../cases/b_ice_shedding.toml"));
                set(&mut t, &["section"], "segments_per_span", n);
                let text = toml::to_string(&t).expect("a TOML table serialises");
                let sc = scenario::parse(&text, "section_strings").unwrap_or_else(|e| panic!("{e}"));
                Solver::Wire(scenario::plan(&sc, "section_strings").unwrap_or_else(|e| panic!("{e}")).solver)
            }
            Workload::Bundle { spacers } => {
                let mut t = case_table(include_str!("../../../cases/g_quad_bundle_break.toml"));
                for_conductors(&mut t, |c| {
                    set(c, &["section"], "segments_per_span", n);
                    if !spacers {
                        let b = c.get_mut("bundle").and_then(|b| b.as_table_mut()).expect("case g has a bundle");
                        b.insert("spacers".into(), toml::Value::Array(Vec::new()));
                    }
                });
                Solver::Line(line(&t, self.name()))
            }
            Workload::ShortCircuit { .. } | Workload::ShortCircuitContact | Workload::LineClearances => {
                let mut t = case_table(include_str!("../../../cases/j_distribution_reclose.toml"));
                for_conductors(&mut t, |c| set(c, &["section"], "segments_per_span", n));
                let start = match self {
                    Workload::ShortCircuit { forces: true } => Some(0.0),
                    Workload::ShortCircuitContact => Some(900.0),
                    _ => None,
                };
                if let Some(start) = start {
                    let sc = t.get_mut("short_circuit").and_then(|s| s.as_table_mut()).expect("case j's fault");
                    sc.remove("reclose");
                    sc.insert("start_s".into(), toml::Value::Float(start));
                    sc.insert("duration_s".into(), toml::Value::Float(10.0));
                } else {
                    t.remove("short_circuit");
                }
                let plan = line_plan(&t, self.name());
                if self == Workload::LineClearances {
                    Solver::LineClearances(plan.line, ClearanceTracker::new(plan.groups))
                } else {
                    Solver::Line(plan.line)
                }
            }
        }
    }
}

/// A case file's table without what the timed steps do not use: its events, its initial static solve
/// (the run starts from the strung shape), its snapshot times.
fn case_table(text: &str) -> toml::Table {
    let mut t: toml::Table = text.parse().expect("a committed case file is TOML");
    for k in ["events", "initial"] {
        t.remove(k);
    }
    if let Some(o) = t.get_mut("output").and_then(|o| o.as_table_mut()) {
        o.remove("snapshot_times_s");
    }
    t.insert("duration".into(), toml::Value::Table(toml::Table::from_iter([("end_time_s".into(), 1.0e3.into())])));
    t
}

fn set(t: &mut toml::Table, path: &[&str], key: &str, n: usize) {
    let mut at = t;
    for p in path {
        at = at.get_mut(*p).and_then(|v| v.as_table_mut()).unwrap_or_else(|| panic!("no table {p}"));
    }
    at.insert(key.into(), toml::Value::Integer(n as i64));
}

fn for_conductors(t: &mut toml::Table, mut f: impl FnMut(&mut toml::Table)) {
    let line = t.get_mut("line").and_then(|l| l.as_table_mut()).expect("a line case");
    let cs = line.get_mut("conductors").and_then(|c| c.as_array_mut()).expect("conductors");
    for c in cs {
        let c = c.as_table_mut().expect("a conductor table");
        c.remove("events");
        f(c);
    }
}

fn line(t: &toml::Table, name: &str) -> LineExplicit {
    line_plan(t, name).line
}

fn line_plan(t: &toml::Table, name: &str) -> scenario::line::LinePlan {
    let text = toml::to_string(t).expect("a TOML table serialises");
    let s = scenario::line::parse(&text, name).unwrap_or_else(|e| panic!("{e}"));
    scenario::line::plan(&s, name).unwrap_or_else(|e| panic!("{e}"))
}

/// The solver of a workload: one wire or a line.
#[derive(Clone, Debug)]
#[allow(clippy::large_enum_variant)] // two per measurement, cloned per episode: the size does not matter
pub enum Solver {
    /// one wire (a conductor or a section)
    Wire(Explicit),
    /// a line of several conductors
    Line(LineExplicit),
    /// a line whose clearances are measured after every step
    LineClearances(LineExplicit, ClearanceTracker),
}

impl Solver {
    /// Nodes stepped per step (every conductor's).
    pub fn nodes(&self) -> usize {
        match self {
            Solver::Wire(s) => s.wire().nodes(),
            Solver::Line(l) | Solver::LineClearances(l, _) => l.conductors().iter().map(|c| c.wire().nodes()).sum(),
        }
    }

    /// The nominal step [s].
    pub fn dt_s(&self) -> f64 {
        match self {
            Solver::Wire(s) => s.params().dt_s,
            Solver::Line(l) | Solver::LineClearances(l, _) => l.params().dt_s,
        }
    }

    /// One nominal step; panics if it goes unstable (for these workloads a bug).
    pub fn step(&mut self, what: &str) {
        self.try_step().unwrap_or_else(|e| panic!("{what}: {e}"));
    }

    /// One nominal step, or the instability's message.
    pub fn try_step(&mut self) -> Result<(), String> {
        let dt = self.dt_s();
        match self {
            Solver::Wire(s) => s.step(dt).map_err(|e| e.to_string()),
            Solver::Line(l) => l.step(dt).map_err(|e| e.to_string()),
            Solver::LineClearances(l, c) => {
                l.step(dt).map_err(|e| e.to_string())?;
                c.observe(&l.wires(), l.time_s());
                Ok(())
            }
        }
    }

    /// Time reached [s].
    pub fn time_s(&self) -> f64 {
        match self {
            Solver::Wire(s) => s.time_s(),
            Solver::Line(l) | Solver::LineClearances(l, _) => l.time_s(),
        }
    }

    /// Steps taken.
    pub fn steps(&self) -> u64 {
        match self {
            Solver::Wire(s) => s.steps(),
            Solver::Line(l) | Solver::LineClearances(l, _) => l.steps(),
        }
    }

    /// The wires stepped, in order (one, or every conductor's).
    pub fn wires(&self) -> Vec<&ohl::wire::Wire> {
        match self {
            Solver::Wire(s) => vec![s.wire()],
            Solver::Line(l) | Solver::LineClearances(l, _) => l.wires(),
        }
    }

    /// The line and its element sizes for the cost model (None for one wire): the clearance pairs only
    /// where the clearances are measured.
    pub fn line_sizes(&self) -> Option<ohl::run::line::LineElementSizes> {
        match self {
            Solver::Wire(_) => None,
            Solver::Line(l) => Some(ohl::run::line::LineElementSizes::of(l, &[])),
            Solver::LineClearances(l, c) => Some(ohl::run::line::LineElementSizes::of(l, c.groups())),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each workload is the grid it claims (nodes from the case files' spans and conductors: case b one
    /// conductor over 5 spans, case g four sub-conductors over 3, case j three phases over 1), steps
    /// stably, and the element a pair differs by acts: the spacers and the short circuit's forces move
    /// the conductors away from the bare line's motion, the ground holds every node at its height.
    #[test]
    fn workloads_are_their_grids_and_their_elements_act() {
        let n = 10;
        let expected = [
            (Workload::SectionStrings, 5 * n + 1),
            (Workload::Bundle { spacers: true }, 4 * (3 * n + 1)),
            (Workload::Bundle { spacers: false }, 4 * (3 * n + 1)),
            (Workload::ShortCircuit { forces: true }, 3 * (n + 1)),
            (Workload::ShortCircuit { forces: false }, 3 * (n + 1)),
            (Workload::GroundContact, n + 1),
            (Workload::ShortCircuitContact, 3 * (n + 1)),
            (Workload::LineClearances, 3 * (n + 1)),
        ];
        let mut states = Vec::new();
        for (w, nodes) in expected {
            let mut s = w.solver(n);
            assert_eq!(s.nodes(), nodes, "{}", w.name());
            for _ in 0..200 {
                s.step(w.name());
            }
            assert_eq!(Workload::from_name(w.name()), Some(w));
            states.push(s);
        }
        let wires = |s: &Solver| -> Vec<Vec<f64>> {
            match s {
                Solver::Wire(w) => vec![w.wire().x[2].clone()],
                Solver::Line(l) | Solver::LineClearances(l, _) => {
                    l.conductors().iter().map(|c| c.wire().x[2].clone()).collect()
                }
            }
        };
        assert_ne!(wires(&states[1]), wires(&states[2]), "the spacers change the bundle's motion");
        assert_ne!(wires(&states[3]), wires(&states[4]), "the pair forces change the phases' motion");
        let ground = &wires(&states[5])[0];
        assert!(ground.iter().all(|&x| x >= 0.0), "on the ground at 0 m: {ground:?}");
        // The cost workloads: the contact and the clearances do not change case j's bare motion before
        // the phases come near (no contact force, the tracker only reads); the sizes are those counted.
        assert_eq!(wires(&states[6]), wires(&states[4]), "no current, no contact force yet");
        assert_eq!(wires(&states[7]), wires(&states[4]), "the clearance tracker only reads");
        let contact = states[6].line_sizes().unwrap();
        assert_eq!(contact.contact_pair_nodes, 3.0 * 2.0 * (n + 1) as f64);
        assert_eq!(contact.em_pair_products, 3.0 * ((n + 1) * (n + 1)) as f64);
        assert_eq!(states[7].line_sizes().unwrap().clearance_pair_nodes, 3.0 * 2.0 * (n + 1) as f64);
    }
}
