//! One case of a sweep: the base document with the case's values set ([`super::overrides`]), written back
//! to TOML text and read by the same parser, validation and plan as `ohl run` (so a case is exactly the
//! scenario `OUT/cases/<id>/scenario.toml` that `--keep-runs` writes; a line by the line's, run by
//! `run_line`), checked against the work budget, then run on the calling thread. Whatever happens becomes
//! the case's [`Row`]: a value that does not fit its field, an invalid scenario, a refused or unstable run
//! are rows with their status and reason, never the end of the sweep.

use std::path::Path;
use std::time::Instant;

use ohl::run::line::{LineRunError, LineWorkEstimate, run_line};
use ohl::run::{RunError, RunOptions, run};
use ohl::scenario::{self, line};

use super::table::{Row, Status, line_result_cells, result_cells};
use super::{Kind, Sweep};

/// The scenario text of case `id`, or why its values do not fit.
pub fn scenario_text(sweep: &Sweep, id: usize) -> Result<String, String> {
    let mut doc = sweep.base.clone();
    for ((field, place), value) in sweep.spec.fields().zip(&sweep.places).zip(sweep.spec.case(id)) {
        if let Some(v) = value {
            // The place (a name resolved in the base file), named in messages as written.
            super::overrides::apply(&mut doc, place, v).map_err(|e| e.named(field).to_string())?;
        }
    }
    toml::to_string(&doc).map_err(|e| format!("the scenario cannot be written as TOML: {e}"))
}

/// Run case `id`; with `keep` (`OUT/cases`), write its scenario and outputs to `keep/<id>/`.
pub fn run_case(sweep: &Sweep, id: usize, keep: Option<&Path>) -> Row {
    let started = Instant::now();
    let values = sweep.spec.case(id).into_iter().map(|v| v.unwrap_or_default().to_string()).collect();
    let mut row = Row {
        case: id,
        values,
        status: Status::Invalid,
        reason: String::new(),
        results: None,
        warnings: String::new(),
        loop_timing: None,
        case_wall_s: 0.0,
    };
    run_into(sweep, id, keep, &mut row);
    row.reason = row.reason.replace('\n', "; ");
    row.case_wall_s = started.elapsed().as_secs_f64();
    row
}

fn run_into(sweep: &Sweep, id: usize, keep: Option<&Path>, row: &mut Row) {
    let text = match scenario_text(sweep, id) {
        Ok(t) => t,
        Err(reason) => {
            row.reason = reason;
            return;
        }
    };
    let dir = keep.map(|k| k.join(id.to_string()));
    if let Some(d) = &dir {
        let written = std::fs::create_dir_all(d).and_then(|_| std::fs::write(d.join("scenario.toml"), &text));
        if let Err(e) = written {
            (row.status, row.reason) = (Status::Failed, format!("{}: {e}", d.display()));
            return;
        }
    }
    let file = format!("case {id}");
    if let Kind::Line { conductors } = &sweep.kind {
        if let Some(o) = &sweep.converge {
            return converge_line_into(&text, &file, o, conductors, dir.as_deref(), row);
        }
        return run_line_into(sweep, &text, &file, conductors, dir.as_deref(), row);
    }
    if let Some(o) = &sweep.converge {
        return converge_into(&text, &file, o, dir.as_deref(), row);
    }
    let plan = match scenario::parse(&text, &file).and_then(|sc| scenario::plan(&sc, &file)) {
        Ok(p) => p,
        Err(e) => {
            row.reason = input_reason(e);
            return;
        }
    };
    row.warnings = plan.warnings.iter().map(|w| w.to_string()).collect::<Vec<_>>().join("; ");
    let estimate = plan.work_estimate();
    let checked = if sweep.allow_large { estimate.check_resolvable() } else { estimate.check() };
    if let Err(refusal) = checked {
        (row.status, row.reason) = (Status::Refused, refusal.to_string());
        return;
    }
    let opts = RunOptions { out_dir: dir, record: false };
    let summary = match run(plan, &opts) {
        Ok(o) => o.summary,
        Err(RunError::Unstable { instability, outcome }) => {
            row.reason = instability.to_string();
            outcome.summary
        }
        Err(e @ RunError::Io(_)) => {
            (row.status, row.reason) = (Status::Failed, e.to_string());
            return;
        }
    };
    row.status = Status::of_summary(&summary.status);
    if row.status == Status::NotSettled {
        row.reason = "reached duration.until_settled.max_time_s before the wire settled".into();
    }
    row.results = Some(result_cells(&summary));
    row.loop_timing = Some((summary.wall_time_s, summary.node_steps_per_second));
}

/// [`run_into`] with `--converge`: the case's convergence study ([`crate::converge`]); its row holds the
/// finest level's results and [`table::CONVERGE_COLUMNS`]; with `--keep-runs` the levels' files and
/// `convergence.json` go to the case's folder. A study above the budget is `refused`, a level that is no
/// valid scenario `invalid`, a level that went unstable `unstable` (no results).
fn converge_into(text: &str, file: &str, o: &crate::converge::Options, dir: Option<&Path>, row: &mut Row) {
    use crate::converge::{self, report};
    let sc = match scenario::parse(text, file) {
        Ok(s) => s,
        Err(e) => {
            row.reason = input_reason(e);
            return;
        }
    };
    let planned = match converge::plan_scenario(&sc, file, dir, o) {
        Ok(p) => p,
        Err(e) => return study_failed(e, row),
    };
    row.warnings = planned[0].plan.warnings.iter().map(|w| w.to_string()).collect::<Vec<_>>().join("; ");
    let (runs, finest) = match converge::run(Path::new(file), planned, |_, _| {}) {
        Ok(r) => r,
        Err(e) => return study_failed(e, row),
    };
    let quantities = converge::analyse(&runs, o.rtol);
    if !study_written(dir, &report::Study::new(file, &finest.name, o, &runs, &quantities), row) {
        return;
    }
    row.status = Status::of_summary(&finest.status);
    if row.status == Status::NotSettled {
        row.reason = "reached duration.until_settled.max_time_s before the wire settled".into();
    }
    let mut cells = result_cells(&finest);
    cells.extend(super::table::converge_cells(&quantities, &finest));
    row.results = Some(cells);
    row.loop_timing = Some((finest.wall_time_s, finest.node_steps_per_second));
}

/// A study that could not be planned or run: an invalid level is `invalid` (the default status), one
/// above the budget `refused`, one that went unstable `unstable`, anything else `failed`.
fn study_failed(e: crate::converge::StudyError, row: &mut Row) {
    use crate::converge::StudyError;
    match e {
        StudyError::Input(e) => row.reason = input_reason(e),
        e @ StudyError::Budget { .. } => (row.status, row.reason) = (Status::Refused, e.to_string()),
        e @ StudyError::Level(_) => row.reason = e.to_string(),
        e @ StudyError::Unstable { .. } => (row.status, row.reason) = (Status::Unstable, e.to_string()),
        e => (row.status, row.reason) = (Status::Failed, e.to_string()),
    }
}

/// Write the study's `convergence.json` into `dir` (`--keep-runs`); false, with the row `failed`, if it
/// cannot be written.
fn study_written(dir: Option<&Path>, study: &crate::converge::report::Study, row: &mut Row) -> bool {
    let Some(d) = dir else { return true };
    match crate::converge::report::write_json(d, study) {
        Ok(()) => true,
        Err(e) => {
            (row.status, row.reason) = (Status::Failed, format!("{}: {e}", d.join("convergence.json").display()));
            false
        }
    }
}

/// [`converge_into`] for a line ([`crate::converge::line`]): the row holds the finest level's line results
/// and [`super::table::LINE_CONVERGE_COLUMNS`].
fn converge_line_into(
    text: &str,
    file: &str,
    o: &crate::converge::Options,
    conductors: &[String],
    dir: Option<&Path>,
    row: &mut Row,
) {
    use crate::converge::{line as cl, report};
    let planned = match cl::plan_line_text(text, file, dir, o) {
        Ok(p) => p,
        Err(e) => return study_failed(e, row),
    };
    let warnings = planned[0]
        .plan
        .plans
        .iter()
        .zip(planned[0].plan.line.names())
        .flat_map(|(p, name)| p.warnings.iter().map(move |w| format!("{name}: {w}")));
    row.warnings = warnings.collect::<Vec<_>>().join("; ");
    let (runs, finest) = match cl::run_line_levels(Path::new(file), planned, |_, _| {}) {
        Ok(r) => r,
        Err(e) => return study_failed(e, row),
    };
    let quantities = crate::converge::analyse(&runs, o.rtol);
    if !study_written(dir, &report::Study::new(file, &finest.name, o, &runs, &quantities), row) {
        return;
    }
    row.status = Status::of_summary(&finest.status);
    if row.status == Status::NotSettled {
        row.reason = "reached duration.until_settled.max_time_s before every conductor settled".into();
    }
    let mut cells = line_result_cells(&finest, conductors);
    cells.extend(super::table::line_converge_cells(&quantities, &finest));
    row.results = Some(cells);
    row.loop_timing = Some((finest.wall_time_s, finest.node_steps_per_second));
}

/// [`run_into`] for a line: parse, validate and plan it as `ohl run` does, check the line's work budget, run
/// it (into `dir` with `--keep-runs`) and fill the row from its summary.
fn run_line_into(sweep: &Sweep, text: &str, file: &str, conductors: &[String], dir: Option<&Path>, row: &mut Row) {
    let plan = match line::parse(text, file).and_then(|s| line::plan(&s, file)) {
        Ok(p) => p,
        Err(e) => {
            row.reason = input_reason(e);
            return;
        }
    };
    let warnings = plan
        .plans
        .iter()
        .zip(plan.line.names())
        .flat_map(|(p, name)| p.warnings.iter().map(move |w| format!("{name}: {w}")));
    row.warnings = warnings.collect::<Vec<_>>().join("; ");
    let estimate = LineWorkEstimate::of(&plan);
    let checked = if sweep.allow_large { estimate.check_resolvable() } else { estimate.check() };
    if let Err(refusal) = checked {
        (row.status, row.reason) = (Status::Refused, refusal.to_string());
        return;
    }
    let summary = match run_line(plan, dir) {
        Ok(o) => o.summary,
        Err(LineRunError::Unstable { instability, outcome }) => {
            row.reason = instability.to_string();
            outcome.summary
        }
        Err(e @ LineRunError::Io(_)) => {
            (row.status, row.reason) = (Status::Failed, e.to_string());
            return;
        }
    };
    row.status = Status::of_summary(&summary.status);
    if row.status == Status::NotSettled {
        row.reason = "reached duration.until_settled.max_time_s before every conductor settled".into();
    }
    row.results = Some(line_result_cells(&summary, conductors));
    row.loop_timing = Some((summary.wall_time_s, summary.node_steps_per_second));
}

/// The message of a scenario that cannot be used, without the file name (the row names the case): every
/// problem, `; `-separated.
fn input_reason(e: scenario::InputError) -> String {
    match e {
        scenario::InputError::Invalid { problems, .. } => {
            problems.iter().map(|p| p.to_string()).collect::<Vec<_>>().join("; ")
        }
        // The parser's message without its source excerpt (`12 | key = value`, `  |   ^`); its line numbers
        // are those of the case's scenario text (`--keep-runs` writes it).
        scenario::InputError::Parse { message, .. } => {
            let excerpt = |l: &str| {
                let t = l.trim_start_matches(|c: char| c.is_ascii_digit() || c == ' ');
                t.starts_with('|') || l.trim().is_empty()
            };
            message.lines().filter(|l| !excerpt(l)).map(str::trim).collect::<Vec<_>>().join(": ")
        }
        other => other.to_string(),
    }
}
