//! The table of a sweep, `sweep.csv`: one row per case.
//!
//! Columns: `case` (the id, from 0), one column per varied field named by its path (the value as written;
//! empty where a cases file left the base value), `status`, `reason`, then the scalar results of the run's
//! summary ([`RESULT_COLUMNS`], units in the names, the last `start_up_peak` ([`start_up_cell`]); for a line, [`line_columns`]: each conductor's peaks
//! prefixed by its name, the least clearance and the largest tower load), `warnings`, and last the timings
//! ([`TIMING_COLUMNS`],
//! which differ from run to run; every other column is the same for the same case on any thread count,
//! shard or machine with the same build). Numbers are written in the shortest form that reads back to the
//! same `f64` (ryu), so a table's values are bitwise those of the runs. A cell is empty where the run has
//! no such value (a case that did not run, `settled_since_s` of a run that did not settle,
//! `peak_temperature_k` without a `[thermal]` table).

use std::io::Write;
use std::path::Path;

use ohl::output::Summary;
use ohl::run::line::{ClearanceSummary, LineSummary, TowerSummary, slug};

/// Status of a case.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Status {
    /// ran to its end time
    Completed,
    /// ran until the wire settled
    Settled,
    /// reached `max_time_s` without settling (the results are those at that time)
    NotSettled,
    /// the scheme went unstable (the results are those up to the failure)
    Unstable,
    /// the overridden scenario is not valid (parse or validation message in `reason`); not run
    Invalid,
    /// above the work budget (`--allow-large` runs it); not run
    Refused,
    /// an output file of `--keep-runs` could not be written, or an internal error
    Failed,
}

impl Status {
    /// The word in the table.
    pub fn as_str(self) -> &'static str {
        match self {
            Status::Completed => "completed",
            Status::Settled => "settled",
            Status::NotSettled => "not_settled",
            Status::Unstable => "unstable",
            Status::Invalid => "invalid",
            Status::Refused => "refused",
            Status::Failed => "failed",
        }
    }

    /// The status of a summary's `status` word.
    pub fn of_summary(word: &str) -> Status {
        match word {
            "settled" => Status::Settled,
            "not_settled" => Status::NotSettled,
            "unstable" => Status::Unstable,
            _ => Status::Completed,
        }
    }
}

/// The result columns, in order: the summary's scalar values ([`result_cells`]).
pub const RESULT_COLUMNS: [&str; 24] = [
    "final_time_s",
    "steps",
    "dt_s",
    "segments",
    "peaks_from_s",
    "peak_max_tension_n",
    "peak_max_tension_time_s",
    "peak_mid_dx1_m",
    "peak_mid_dx1_time_s",
    "peak_mid_dx2_m",
    "peak_mid_dx2_time_s",
    "peak_mid_dx3_m",
    "peak_mid_dx3_time_s",
    "final_mid_dx1_m",
    "final_mid_dx2_m",
    "final_mid_dx3_m",
    "final_max_tension_n",
    "final_kinetic_j",
    "settled_since_s",
    "peak_support_force_n",
    "peak_support_force_time_s",
    "peak_support_force_support",
    "peak_temperature_k",
    "start_up_peak",
];

/// The `start_up_peak` cell ([`ohl::output::start_up`]): `yes` when a peak (the largest tension or a
/// support's largest force) comes from the wind's onset, `no` when none does, `not_assessed` when events
/// after the onset change the loads, empty when the wind is never raised.
pub fn start_up_cell(s: &Summary) -> &'static str {
    start_up_word(s.start_up.as_ref())
}

/// The `start_up_peak` word of a start-up check ([`start_up_cell`]).
pub fn start_up_word(u: Option<&ohl::output::start_up::StartUp>) -> &'static str {
    match u {
        None => "",
        Some(u) if !u.assessed => "not_assessed",
        Some(u) if u.flagged.is_empty() => "no",
        Some(_) => "yes",
    }
}

/// The timing columns, last: time loop [s], its throughput [node-steps/s], and the whole case with its
/// parse, validation, static solve and outputs [s].
pub const TIMING_COLUMNS: [&str; 3] = ["wall_time_s", "node_steps_per_s", "case_wall_s"];

/// One case's row.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// the case id
    pub case: usize,
    /// each varied field's value as written (empty: the base file's)
    pub values: Vec<String>,
    /// how the case ended
    pub status: Status,
    /// why it did not complete (empty when it did)
    pub reason: String,
    /// the summary's values, one per result column (none when the case did not run)
    pub results: Option<Vec<String>>,
    /// the plan's warnings (valid but doubtful values), `; `-separated
    pub warnings: String,
    /// time loop [s] and node-steps per second, from the summary
    pub loop_timing: Option<(f64, f64)>,
    /// the whole case [s]
    pub case_wall_s: f64,
}

/// A number as the table writes it: shortest round-trip form.
pub fn number(x: f64) -> String {
    ryu::Buffer::new().format(x).to_string()
}

/// The values of [`RESULT_COLUMNS`] from a run's summary.
pub fn result_cells(s: &Summary) -> Vec<String> {
    let n = number;
    let opt = |x: Option<f64>| x.map(number).unwrap_or_default();
    let p = &s.peak_midspan_displacement_m;
    let d = &s.final_midspan_displacement_m;
    // The support with the largest peak force magnitude (the first of equal ones).
    let support = s.supports.iter().enumerate().fold(None, |best: Option<(usize, f64, f64)>, (k, sp)| {
        let m = &sp.peaks.magnitude;
        match best {
            Some((_, v, _)) if m.value_n.partial_cmp(&v) != Some(std::cmp::Ordering::Greater) => best,
            _ => Some((k, m.value_n, m.time_s)),
        }
    });
    let cells = vec![
        n(s.final_time_s),
        s.steps.to_string(),
        n(s.dt_s),
        s.segments.to_string(),
        n(s.peaks_from_s),
        n(s.peak_max_tension_n),
        n(s.peak_max_tension_time_s),
        n(p[0].value_m),
        n(p[0].time_s),
        n(p[1].value_m),
        n(p[1].time_s),
        n(p[2].value_m),
        n(p[2].time_s),
        n(d[0]),
        n(d[1]),
        n(d[2]),
        n(s.final_max_tension_n),
        n(s.final_kinetic_j),
        opt(s.settled_since_s),
        opt(support.map(|b| b.1)),
        opt(support.map(|b| b.2)),
        support.map(|b| b.0.to_string()).unwrap_or_default(),
        opt(s.thermal.as_ref().map(|t| t.peak_temperature_k)),
        start_up_cell(s).to_string(),
    ];
    debug_assert_eq!(cells.len(), RESULT_COLUMNS.len());
    cells
}

/// The columns `--converge` adds after [`RESULT_COLUMNS`] (`ohl sweep --converge`, docs/convergence.md):
/// the Richardson extrapolate, the fine-level GCI (a fraction of the finest value) and the verdict of the
/// largest tension and of the largest support force (the support of `peak_support_force_support`), then how
/// many quantities of the summary are converged within rtol, converging but not within it, and without a
/// converging limit (oscillatory, divergent, a peak moving between events, indeterminate). The other
/// result columns are the finest level's.
pub const CONVERGE_COLUMNS: [&str; 9] = [
    "peak_max_tension_extrapolate_n",
    "peak_max_tension_gci",
    "peak_max_tension_verdict",
    "peak_support_force_extrapolate_n",
    "peak_support_force_gci",
    "peak_support_force_verdict",
    "quantities_converged_within_rtol",
    "quantities_not_within_rtol",
    "quantities_without_limit",
];

/// The extrapolate, GCI and verdict cells of the quantity `path` of a study (empty where it has none; no
/// extrapolate and GCI for a peak moving between events).
fn estimate_cells(q: &[crate::converge::Quantity], path: &str) -> [String; 3] {
    match q.iter().find(|x| x.path == path) {
        None => Default::default(),
        Some(x) => {
            let e = x.estimate.as_ref();
            let shown = e.is_some_and(|e| e.extrapolate.is_some()) && x.verdict != crate::converge::PEAK_MOVES;
            let cell = |v: Option<f64>| v.filter(|_| shown).map(number).unwrap_or_default();
            [cell(e.and_then(|e| e.extrapolate)), cell(e.and_then(|e| e.gci_fine)), x.verdict.to_string()]
        }
    }
}

/// How many quantities are converged within rtol, converging but not within it, and without a
/// converging limit (the last three of [`CONVERGE_COLUMNS`] and [`LINE_CONVERGE_COLUMNS`]).
fn verdict_counts(q: &[crate::converge::Quantity]) -> [String; 3] {
    let count = |f: &dyn Fn(&str) -> bool| q.iter().filter(|x| f(x.verdict)).count().to_string();
    [
        count(&|v| v == "converged within rtol"),
        count(&|v| v == "not within rtol"),
        count(&|v| matches!(v, "oscillatory" | "divergent" | "indeterminate") || v == crate::converge::PEAK_MOVES),
    ]
}

/// The columns `--converge` adds to a line's ([`line_columns`]): the Richardson extrapolate, the fine-level
/// GCI and the verdict of the largest peak tension of any conductor (the conductor that has it on the
/// finest level), of the least clearance between any two groups (the pair that has it on the finest
/// level) and of the largest tower load (the tower that has it on the finest level), then the counts of
/// verdicts as [`CONVERGE_COLUMNS`]. The other result columns are the finest level's.
pub const LINE_CONVERGE_COLUMNS: [&str; 12] = [
    "peak_max_tension_extrapolate_n",
    "peak_max_tension_gci",
    "peak_max_tension_verdict",
    "least_clearance_extrapolate_m",
    "least_clearance_gci",
    "least_clearance_verdict",
    "peak_tower_force_extrapolate_n",
    "peak_tower_force_gci",
    "peak_tower_force_verdict",
    "quantities_converged_within_rtol",
    "quantities_not_within_rtol",
    "quantities_without_limit",
];

/// The index of the first largest (`sign` 1) or least (`sign` -1) value, NaNs never chosen.
fn extreme(values: impl Iterator<Item = f64>, sign: f64) -> Option<usize> {
    values
        .enumerate()
        .fold(None, |best: Option<(usize, f64)>, (k, v)| match best {
            Some((_, b)) if (sign * v).partial_cmp(&(sign * b)) != Some(std::cmp::Ordering::Greater) => best,
            _ if v.is_nan() => best,
            _ => Some((k, v)),
        })
        .map(|b| b.0)
}

/// The values of [`LINE_CONVERGE_COLUMNS`] from a line study's quantities and its finest level's summary.
pub fn line_converge_cells(q: &[crate::converge::Quantity], finest: &LineSummary) -> Vec<String> {
    let mut cells = Vec::with_capacity(LINE_CONVERGE_COLUMNS.len());
    let at = |k: Option<usize>, path: &dyn Fn(usize) -> String| {
        k.map_or_else(Default::default, |k| estimate_cells(q, &path(k)))
    };
    cells.extend(at(extreme(finest.conductors.iter().map(|c| c.peak_max_tension_n), 1.0), &|k| {
        format!("conductors[{k}].peak_max_tension_n")
    }));
    cells.extend(at(extreme(finest.clearances.iter().map(|c| c.least_m), -1.0), &|k| {
        format!("clearances[{k}].least_m")
    }));
    cells.extend(at(extreme(finest.towers.iter().map(|t| t.peak_force_magnitude_n), 1.0), &|k| {
        format!("towers[{k}].peak_force_magnitude_n")
    }));
    cells.extend(verdict_counts(q));
    debug_assert_eq!(cells.len(), LINE_CONVERGE_COLUMNS.len());
    cells
}

/// The values of [`CONVERGE_COLUMNS`] from a study's quantities and its finest level's summary.
pub fn converge_cells(q: &[crate::converge::Quantity], finest: &Summary) -> Vec<String> {
    let estimate = |path: &str| estimate_cells(q, path);
    // the support with the largest peak force on the finest level, as `peak_support_force_support`
    let support = (finest.supports.iter().enumerate())
        .fold(None, |best: Option<(usize, f64)>, (k, sp)| match best {
            Some((_, v)) if sp.peaks.magnitude.value_n.partial_cmp(&v) != Some(std::cmp::Ordering::Greater) => best,
            _ => Some((k, sp.peaks.magnitude.value_n)),
        })
        .map(|b| b.0);
    let mut cells: Vec<String> = estimate("peak_max_tension_n").into();
    cells
        .extend(support.map_or_else(Default::default, |k| estimate(&format!("supports[{k}].peaks.magnitude.value_n"))));
    cells.extend(verdict_counts(q));
    debug_assert_eq!(cells.len(), CONVERGE_COLUMNS.len());
    cells
}

/// A line's quantities per conductor, each column `NAME_QUANTITY` ([`line_columns`]).
pub const LINE_CONDUCTOR_COLUMNS: [&str; 13] = [
    "peak_max_tension_n",
    "peak_max_tension_time_s",
    "peak_mid_dx1_m",
    "peak_mid_dx1_time_s",
    "peak_mid_dx2_m",
    "peak_mid_dx2_time_s",
    "peak_mid_dx3_m",
    "peak_mid_dx3_time_s",
    "final_max_tension_n",
    "final_mid_dx1_m",
    "final_mid_dx2_m",
    "final_mid_dx3_m",
    "start_up_peak",
];

/// The result columns of a line whose conductors (a bundle's sub-conductors each: `A.1`, `A.2`) are
/// `conductors`: `final_time_s`, `steps`, `dt_s`; per conductor [`LINE_CONDUCTOR_COLUMNS`], each prefixed
/// by the conductor's name as its output folder writes it (`earth wire` -> `earth_wire_peak_max_tension_n`);
/// the least distance between any two conductor groups and when and which (`least_clearance_m`,
/// `least_clearance_time_s`, `least_clearance_between`); the largest tower load and when and where
/// (`peak_tower_force_n`, `peak_tower_force_time_s`, `peak_tower_force_tower`).
pub fn line_columns(conductors: &[String]) -> Vec<String> {
    let mut h: Vec<String> = ["final_time_s", "steps", "dt_s"].map(String::from).to_vec();
    for c in conductors {
        let c = slug(c);
        h.extend(LINE_CONDUCTOR_COLUMNS.iter().map(|q| format!("{c}_{q}")));
    }
    h.extend(
        [
            "least_clearance_m",
            "least_clearance_time_s",
            "least_clearance_between",
            "peak_tower_force_n",
            "peak_tower_force_time_s",
            "peak_tower_force_tower",
        ]
        .map(String::from),
    );
    h
}

/// The values of [`line_columns`] from a line run's summary (a conductor missing from it: empty cells).
pub fn line_result_cells(s: &LineSummary, conductors: &[String]) -> Vec<String> {
    let n = number;
    let mut cells = vec![n(s.final_time_s), s.steps.to_string(), n(s.dt_s)];
    for name in conductors {
        match s.conductors.iter().find(|c| c.name == *name) {
            Some(c) => {
                let (p, d) = (&c.peak_midspan_displacement_m, &c.final_midspan_displacement_m);
                cells.extend([n(c.peak_max_tension_n), n(c.peak_max_tension_time_s)]);
                for k in 0..3 {
                    cells.extend([n(p[k].value_m), n(p[k].time_s)]);
                }
                cells.extend([n(c.final_max_tension_n), n(d[0]), n(d[1]), n(d[2])]);
                cells.push(start_up_word(c.start_up.as_ref()).into());
            }
            None => cells.extend(LINE_CONDUCTOR_COLUMNS.map(|_| String::new())),
        }
    }
    // The least of the pairs' least distances, and the tower of the largest peak load (the first of equal
    // ones).
    let least = s.clearances.iter().fold(None, |best: Option<&ClearanceSummary>, c| match best {
        Some(b) if c.least_m.partial_cmp(&b.least_m) != Some(std::cmp::Ordering::Less) => best,
        _ => Some(c),
    });
    match least {
        Some(c) => cells.extend([n(c.least_m), n(c.time_s), format!("{} - {}", c.between[0], c.between[1])]),
        None => cells.extend(["", "", ""].map(String::from)),
    }
    let tower = s.towers.iter().fold(None, |best: Option<&TowerSummary>, t| match best {
        Some(b)
            if t.peak_force_magnitude_n.partial_cmp(&b.peak_force_magnitude_n) != Some(std::cmp::Ordering::Greater) =>
        {
            best
        }
        _ => Some(t),
    });
    match tower {
        Some(t) => cells.extend([n(t.peak_force_magnitude_n), n(t.peak_force_time_s), t.name.clone()]),
        None => cells.extend(["", "", ""].map(String::from)),
    }
    debug_assert_eq!(cells.len(), line_columns(conductors).len());
    cells
}

/// The header of a table varying `fields`, with the result columns `results` ([`RESULT_COLUMNS`] for a
/// single-conductor base, [`line_columns`] for a line).
pub fn header(fields: &[String], results: &[String]) -> Vec<String> {
    let mut h = vec!["case".to_string()];
    h.extend(fields.iter().cloned());
    h.extend(["status", "reason"].map(String::from));
    h.extend(results.iter().cloned());
    h.push("warnings".into());
    h.extend(TIMING_COLUMNS.map(String::from));
    h
}

/// The cells of a row, in [`header`] order, with `results` result columns.
pub fn cells(row: &Row, results: usize) -> Vec<String> {
    let mut c = vec![row.case.to_string()];
    c.extend(row.values.iter().cloned());
    c.push(row.status.as_str().into());
    c.push(row.reason.clone());
    match &row.results {
        Some(r) => c.extend(r.iter().cloned()),
        None => c.extend((0..results).map(|_| String::new())),
    }
    c.push(row.warnings.clone());
    match row.loop_timing {
        Some((wall, rate)) => c.extend([number(wall), number(rate)]),
        None => c.extend([String::new(), String::new()]),
    }
    c.push(number(row.case_wall_s));
    c
}

/// Write a table with `header` and `records` to `path`, whole or not at all (a temporary file renamed).
pub fn write<I, R>(path: &Path, header: &[String], records: I) -> std::io::Result<()>
where
    I: IntoIterator<Item = R>,
    R: IntoIterator<Item = String>,
{
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(header)?;
    for r in records {
        w.write_record(r)?;
    }
    let bytes = w.into_inner().map_err(|e| e.into_error())?;
    write_atomically(path, &bytes)
}

/// Write `bytes` to `path` through a temporary file in the same directory, renamed into place.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let tmp = path.with_file_name(format!(".{name}.{}.tmp", std::process::id()));
    let mut f = std::fs::File::create(&tmp)?;
    f.write_all(bytes)?;
    f.sync_all()?;
    drop(f);
    std::fs::rename(&tmp, path)
}

/// A table as read back: its header and its records (as text, unchanged).
pub struct Table {
    /// the header
    pub header: Vec<String>,
    /// the records
    pub records: Vec<Vec<String>>,
}

/// Read a table written by [`write`](fn@write).
pub fn read(path: &Path) -> Result<Table, csv::Error> {
    let mut r = csv::ReaderBuilder::new().flexible(false).from_path(path)?;
    let header = r.headers()?.iter().map(String::from).collect();
    let records = r.records().map(|rec| rec.map(|r| r.iter().map(String::from).collect())).collect::<Result<_, _>>()?;
    Ok(Table { header, records })
}
