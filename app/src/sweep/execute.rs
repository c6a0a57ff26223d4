//! Running the cases of a sweep (or of one shard) on a pool of worker threads, and writing its table and
//! manifest.
//!
//! Each case runs on one worker thread from start to end (the scheme is single-threaded, the static solve
//! too), so `--threads N` runs N cases at a time; the results do not depend on N or on the order in which
//! cases finish. Memory stays small for any number of cases: a case keeps no time series in memory
//! (`RunOptions::record` is off) and, without `--keep-runs`, writes no file (`out_dir` is none); only its
//! row is kept.

use std::collections::BTreeMap;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use rayon::prelude::*;

use super::manifest::{FORMAT, Manifest};
use super::shard::{Shard, stem};
use super::table::{self, Row, Status};
use super::{Sweep, SweepError, case};

/// How to run a sweep.
#[derive(Clone, Debug)]
pub struct Options {
    /// worker threads (at least 1)
    pub threads: usize,
    /// run only this shard
    pub shard: Option<Shard>,
    /// write each case's scenario and outputs to `out/cases/<id>/`
    pub keep_runs: bool,
    /// the output directory
    pub out: PathBuf,
}

/// What a sweep did.
#[derive(Clone, Debug)]
pub struct Report {
    /// cases of the whole sweep
    pub cases: usize,
    /// cases run here (this shard's)
    pub ran: usize,
    /// rows per status
    pub statuses: BTreeMap<Status, usize>,
    /// the cases (ids) with a peak from the wind's onset (`start_up_peak` = `yes`)
    pub start_up_cases: Vec<usize>,
    /// wall-clock time of running the cases [s]
    pub wall_time_s: f64,
    /// cases run per second of wall-clock time
    pub cases_per_second: f64,
    /// the table written
    pub table: PathBuf,
    /// the manifest written
    pub manifest: PathBuf,
}

/// Run the cases of `sweep` (or of `opts.shard`) on `opts.threads` threads and write `sweep.csv` and
/// `sweep.json` (`sweep.K-of-N.*` for a shard) to `opts.out`. `progress(done, total)` is called after each
/// case, from the worker that ran it. Failed cases are rows; the error is for files that could not be
/// written and a thread pool that could not start.
pub fn run_sweep(
    sweep: &Sweep,
    opts: &Options,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Report, SweepError> {
    let write_err = |path: &Path| {
        let path = path.to_path_buf();
        move |source| SweepError::Write { path, source }
    };
    std::fs::create_dir_all(&opts.out).map_err(write_err(&opts.out))?;
    let keep = opts.keep_runs.then(|| opts.out.join("cases"));
    let ids: Vec<usize> = match opts.shard {
        Some(s) => s.ids(sweep.spec.cases),
        None => (0..sweep.spec.cases).collect(),
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(opts.threads)
        .thread_name(|k| format!("ohl-sweep-{k}"))
        .build()
        .map_err(|e| SweepError::Threads { threads: opts.threads, message: e.to_string() })?;
    let done = AtomicUsize::new(0);
    let started = Instant::now();
    let rows: Vec<Row> = pool.install(|| {
        ids.par_iter()
            .with_max_len(1)
            .map(|&id| {
                let row = guarded(sweep, id, keep.as_deref());
                progress(done.fetch_add(1, Ordering::Relaxed) + 1, ids.len());
                row
            })
            .collect()
    });
    let wall_time_s = started.elapsed().as_secs_f64();

    let mut statuses = BTreeMap::new();
    for r in &rows {
        *statuses.entry(r.status).or_insert(0) += 1;
    }
    let stem = stem(opts.shard);
    let table_path = opts.out.join(format!("{stem}.csv"));
    let fields: Vec<String> = sweep.spec.fields().map(|f| f.to_string()).collect();
    let results = sweep.result_columns();
    // `start_up_peak`, or a line's `NAME_start_up_peak` per conductor.
    let start_up_columns: Vec<usize> =
        (results.iter().enumerate()).filter(|(_, c)| c.ends_with("start_up_peak")).map(|(k, _)| k).collect();
    let start_up_cases = (rows.iter())
        .filter(|r| {
            let cells = r.results.as_deref().unwrap_or_default();
            start_up_columns.iter().any(|&k| cells.get(k).is_some_and(|c| c == "yes"))
        })
        .map(|r| r.case)
        .collect();
    table::write(&table_path, &table::header(&fields, &results), rows.iter().map(|r| table::cells(r, results.len())))
        .map_err(write_err(&table_path))?;
    let cases_per_second = if wall_time_s > 0.0 { rows.len() as f64 / wall_time_s } else { 0.0 };
    let (base_fnv1a64, spec_fnv1a64) = sweep.fingerprints();
    let manifest = Manifest {
        format: FORMAT.into(),
        ohl_version: env!("CARGO_PKG_VERSION").into(),
        base: sweep.base_path.display().to_string(),
        base_fnv1a64,
        spec_fnv1a64,
        allow_large: sweep.allow_large,
        fields,
        cases: sweep.spec.cases,
        shard: opts.shard,
        table: format!("{stem}.csv"),
        rows: rows.len(),
        statuses: statuses.iter().map(|(s, n)| (s.as_str().to_string(), *n)).collect(),
        threads: Some(opts.threads),
        wall_time_s: Some(wall_time_s),
        cases_per_second: Some(cases_per_second),
        merged_from: Vec::new(),
        axes: serde_json::to_value(&sweep.spec.axes).unwrap_or_default(),
    };
    let manifest_path = opts.out.join(format!("{stem}.json"));
    write_manifest(&manifest_path, &manifest)?;
    Ok(Report {
        cases: sweep.spec.cases,
        ran: rows.len(),
        statuses,
        start_up_cases,
        wall_time_s,
        cases_per_second,
        table: table_path,
        manifest: manifest_path,
    })
}

/// Write a manifest, whole or not at all.
pub fn write_manifest(path: &Path, m: &Manifest) -> Result<(), SweepError> {
    let text = serde_json::to_string_pretty(m).map_err(std::io::Error::other).map(|t| t + "\n");
    text.and_then(|t| table::write_atomically(path, t.as_bytes()))
        .map_err(|source| SweepError::Write { path: path.to_path_buf(), source })
}

/// [`case::run_case`], with a panic (a bug: the library is built not to panic on any input) turned into a
/// `failed` row instead of the end of the sweep.
fn guarded(sweep: &Sweep, id: usize, keep: Option<&Path>) -> Row {
    catch_unwind(AssertUnwindSafe(|| case::run_case(sweep, id, keep))).unwrap_or_else(|payload| {
        let message = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_default();
        Row {
            case: id,
            values: sweep.spec.case(id).into_iter().map(|v| v.unwrap_or_default().to_string()).collect(),
            status: Status::Failed,
            reason: format!("internal error (a panic: {message}); please report it with this case's values"),
            results: None,
            warnings: String::new(),
            loop_timing: None,
            case_wall_s: 0.0,
        }
    })
}
