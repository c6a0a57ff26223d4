//! The paper's cases: run a case file of `paper_cases/`, extract the values it checks, compute their
//! independent references, and write the figure, its CSV and the comparison table.
//!
//! A case file is a scenario (so `ohl run paper_cases/<case>.toml` works too) with a `[paper]` section
//! ([`spec`]): each checked value names the paper's number, where it is printed, how
//! the computed value is extracted ([`extract`]), an optional reference ([`reference`]), a tolerance with
//! its justification, and whether a miss means "not reproduced" (equilibria) or is only reported
//! (transients, which depend on damping the paper does not give). Nothing here is specific to a case.
//!

pub mod extract;
pub mod figure;
pub mod heat_case;
pub mod heat_spec;
pub mod reference;
pub mod spec;
pub mod table;

use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::paper::spec::UnitSpec;
use ohl::run::{RunError, RunOptions, run};
use ohl::scenario::{self, InputError, Plan, WorkEstimate};

pub use table::Row;

/// What a case produced.
#[derive(Clone, Debug)]
pub struct CaseReport {
    /// case name (the file stem)
    pub name: String,
    /// section of the paper
    pub section: String,
    /// figure title
    pub title: String,
    /// one row per checked value
    pub rows: Vec<Row>,
    /// the case's notes
    pub notes: Vec<String>,
    /// the events applied: (time [s], what)
    pub events: Vec<(f64, String)>,
    /// run status ("completed", "settled", ...)
    pub status: String,
    /// wall time of the case [s]
    pub wall_s: f64,
    /// the figure's stem (`.png`, `.svg`, `.csv` beside it), if written
    pub figure: Option<PathBuf>,
    /// the work estimate of the run before it ran (none for a heat-conduction case); paper cases are not
    /// held to the budget of `ohl run` (they are far below it)
    pub estimate: Option<WorkEstimate>,
}

/// Why a case could not be run.
#[derive(Debug, thiserror::Error)]
pub enum PaperError {
    /// The case file is not a valid scenario.
    #[error("{0}")]
    Input(#[from] InputError),
    /// The case file has no `[paper]` section.
    #[error("{0}: no [paper] section: not a paper case")]
    NotACase(String),
    /// The run failed (instability or output).
    #[error("{file}: {source}")]
    Run {
        /// the case file
        file: String,
        /// what failed
        source: Box<RunError>,
    },
    /// A figure or CSV could not be written.
    #[error("{0}")]
    Output(String),
}

/// Convert an SI value to the unit the paper prints.
pub fn to_unit(si: f64, unit: UnitSpec, plan: &Plan, length_scale_m: f64) -> f64 {
    match unit {
        UnitSpec::Span => si / length_scale_m,
        UnitSpec::Kn => si / 1e3,
        UnitSpec::Tau => plan.tau(si),
        UnitSpec::M | UnitSpec::S | UnitSpec::One => si,
    }
}

/// The case files `*.toml` of a directory, sorted by name.
pub fn case_files(dir: &Path) -> std::io::Result<Vec<PathBuf>> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    v.sort();
    Ok(v)
}

/// Run one case file; with `out_dir`, write `<out_dir>/<case>.png`, `.svg`, `.csv` (and
/// `<case>_shapes.csv` when the case takes snapshots).
pub fn run_case(path: &Path, out_dir: Option<&Path>) -> Result<CaseReport, PaperError> {
    let started = Instant::now();
    let file = path.display().to_string();
    let name = path.file_stem().and_then(|s| s.to_str()).unwrap_or("case").to_string();
    let text = scenario::read_text(path)?;
    if heat_spec::is_heat_case(&text) {
        return heat_case::run_heat_case(&text, &file, &name, out_dir);
    }
    let sc = scenario::parse(&text, &file)?;
    let plan = scenario::plan(&sc, &file)?;
    for w in &plan.warnings {
        {
            use std::io::Write as _;
            // Dropped if stderr is closed, as every line of the `ohl` commands.
            let _ = writeln!(std::io::stderr(), "warning: {file}: {w}");
        }
    }
    let Some(spec) = spec::parse(&text, &file, plan.stop.horizon_s())? else {
        return Err(PaperError::NotACase(file));
    };
    let estimate = Some(plan.work_estimate());
    let opts = RunOptions { out_dir: None, record: true };
    let o = run(plan.clone(), &opts).map_err(|e| PaperError::Run { file: file.clone(), source: Box::new(e) })?;
    let cols = extract::Series::of(&o);
    let ea = plan.solver.wire().axial_stiffness_n[0];
    let l = spec.length_scale_m;
    let rows: Vec<Row> = spec
        .checks
        .iter()
        .map(|ch| {
            let computed = extract::extract(&cols, &ch.extract, ea).map_or(f64::NAN, |v| to_unit(v, ch.unit, &plan, l));
            let probe = cols.probe_at(ch.extract.at_s);
            let exact = ch
                .reference
                .and_then(|k| reference::reference(k, &plan, &ch.extract, &probe))
                .map(|v| to_unit(v, ch.unit, &plan, l));
            Row::from_check(&name, ch, computed, exact)
        })
        .collect();
    let mut figure_stem = None;
    if let Some(dir) = out_dir {
        let stem = dir.join(&name);
        let charts = figure::charts(&spec, &plan, &o, &cols, &rows);
        if !charts.is_empty() {
            // The heading names the case and its wire (the paper's: mass, stiffness, span, grid).
            let heading = format!(
                "{name}: {} | wire {} kg/m, EA = {:.0} kN, span {} m, N = {}",
                spec.title,
                sc.conductor.linear_density_kg_per_m,
                ea / 1e3,
                plan.chord_m,
                plan.solver.wire().axial_stiffness_n.len()
            );
            figure::draw(&charts, &heading, &stem).map_err(|e| PaperError::Output(e.to_string()))?;
        }
        figure::write_csv(&o, &cols, &plan, l, &stem)
            .map_err(|e| PaperError::Output(format!("{}: {e}", stem.with_extension("csv").display())))?;
        figure_stem = Some(stem);
    }
    Ok(CaseReport {
        name,
        section: spec.section,
        title: spec.title,
        rows,
        notes: spec.notes,
        events: o.events,
        status: o.summary.status,
        wall_s: started.elapsed().as_secs_f64(),
        figure: figure_stem,
        estimate,
    })
}

/// Run several case files on parallel threads (at most `threads` at a time), in the given order.
pub fn run_cases(paths: &[PathBuf], out_dir: Option<&Path>, threads: usize) -> Vec<Result<CaseReport, PaperError>> {
    let threads = threads.max(1);
    let mut results: Vec<Option<Result<CaseReport, PaperError>>> = (0..paths.len()).map(|_| None).collect();
    let next = std::sync::atomic::AtomicUsize::new(0);
    let slots: Vec<std::sync::Mutex<Option<Result<CaseReport, PaperError>>>> =
        (0..paths.len()).map(|_| std::sync::Mutex::new(None)).collect();
    std::thread::scope(|s| {
        for _ in 0..threads.min(paths.len()) {
            s.spawn(|| {
                loop {
                    let k = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                    if k >= paths.len() {
                        break;
                    }
                    let r = run_case(&paths[k], out_dir);
                    *slots[k].lock().unwrap_or_else(|e| e.into_inner()) = Some(r);
                }
            });
        }
    });
    for (k, m) in slots.into_iter().enumerate() {
        results[k] = m.into_inner().unwrap_or_else(|e| e.into_inner());
    }
    results.into_iter().map(|r| r.expect("every case ran")).collect()
}
