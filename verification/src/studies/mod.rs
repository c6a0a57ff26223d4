//! The studies. Adding a study is one module here plus one line in [`STUDIES`].

pub mod energy_budget;
pub mod exact_references;
pub mod implicit_reference;
pub mod line_implicit;
pub mod line_statics;
pub mod manufactured;
pub mod sagtension;
pub mod section_energy;
pub mod section_statics;
pub mod section_transients;
pub mod sensitivity;
pub mod short_circuit;
pub mod static_convergence;
pub mod thermal;

use crate::report::{Budget, StudyReport};
use std::path::Path;

/// A study: its command-line name, a one-line description and its entry point, which writes its CSVs and
/// figures under the given directory and returns its report.
pub struct Study {
    /// command-line name
    pub name: &'static str,
    /// one-line description
    pub about: &'static str,
    /// entry point
    pub run: fn(Budget, &Path) -> Result<StudyReport, String>,
}

/// The registry of studies, in report order.
pub const STUDIES: &[Study] = &[
    Study { name: "exact", about: "exact references, each against an independent route", run: exact_references::run },
    Study {
        name: "static",
        about: "static grid convergence of the settled explicit scheme, GCI",
        run: static_convergence::run,
    },
    Study {
        name: "mms",
        about: "manufactured 3D solution: space-time order, damping lag, smoothing",
        run: manufactured::run,
    },
    Study {
        name: "implicit",
        about: "Newton statics and Newmark dynamics on faer vs the explicit scheme",
        run: implicit_reference::run,
    },
    Study { name: "section_statics", about: "section on strings vs exact statics; limits", run: section_statics::run },
    Study {
        name: "line_statics",
        about: "bundles with spacers and phases on a shared elastic tower vs exact_line",
        run: line_statics::run,
    },
    Study {
        name: "line_implicit",
        about: "explicit line scheme vs Newmark on the whole line: orders in time, rest state vs line statics",
        run: line_implicit::run,
    },
    Study {
        name: "energy",
        about: "discrete energy budget of the weight release, term by term",
        run: energy_budget::run,
    },
    Study {
        name: "sensitivity",
        about: "sweeps over mu, smoothing, Courant number; stability limits",
        run: sensitivity::run,
    },
    Study {
        name: "section_energy",
        about: "energy budget of a section with strings, crossarms, ground and a break, term by term",
        run: section_energy::run,
    },
    Study {
        name: "section_transients",
        about: "grid and time-step convergence of broken-conductor peaks and ice-shedding jumps",
        run: section_transients::run,
    },
    Study {
        name: "thermal",
        about: "IEEE 738 / TB 601 worked examples; steady, transient (RK4 order) and de-icing solvers",
        run: thermal::run,
    },
    Study {
        name: "sagtension",
        about: "sag-tension of Drake (two-material law) vs the CRC handbook's table; knee points",
        run: sagtension::run,
    },
    Study {
        name: "shortcircuit",
        about: "short-circuit response: grid/time convergence of F_t, F_f, b_h; IEC 60865-1 beside it; clashing",
        run: short_circuit::run,
    },
];

/// Find a study by name.
pub fn find(name: &str) -> Option<&'static Study> {
    STUDIES.iter().find(|s| s.name == name)
}

/// Run a study, timing it and writing its tables.
pub fn run_study(study: &Study, budget: Budget, dir: &Path) -> StudyReport {
    let t0 = std::time::Instant::now();
    let mut r = match (study.run)(budget, dir) {
        Ok(r) => r,
        Err(e) => {
            let mut r = StudyReport { name: study.name.into(), title: study.about.into(), ..Default::default() };
            r.check("study ran", "no error", format!("error: {e}"), false);
            r
        }
    };
    r.name = study.name.into();
    r.wall_s = t0.elapsed().as_secs_f64();
    if let Err(e) = r.write_tables(dir) {
        r.check("tables written", "CSV files", format!("error: {e}"), false);
    }
    r
}
