//! `ohl sweep BASE.toml --vary FIELD=VALUES ... [--cases CASES.csv]`: run the cases of a parameter sweep in
//! parallel into one table (`OUT/sweep.csv`, `OUT/sweep.json`); `--shard K/N` runs one slice of it, and
//! `ohl sweep merge` joins the slices. The work is in [`ohl_app::sweep`]; `docs/sweeps.md` is the
//! reference.
//!
//! Exit codes: 0 every case ran (whatever its status: the summary line counts the invalid, refused and
//! unstable ones); 1 a file could not be written (the table, the manifest, a case's files of
//! `--keep-runs`); 2 bad arguments (a malformed `--vary`, range, cases file, `--shard`, a field that has no
//! place in the base file, a base file that is not TOML) or, for `merge`, tables that cannot be merged.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use ohl_app::sweep::table::Status;
use ohl_app::sweep::{Options, Shard, Spec, Sweep, merge, run_sweep};

/// Arguments of `ohl sweep`.
#[derive(clap::Args)]
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
pub struct SweepArgs {
    #[command(subcommand)]
    command: Option<SweepCommand>,
    #[command(flatten)]
    run: RunArgs,
}

#[derive(clap::Subcommand)]
enum SweepCommand {
    /// Join the tables of a sweep's shards (sweep.K-of-N.csv with their .json) into one sweep.csv sorted by
    /// case id; refuses tables of different sweeps and lists missing or duplicated cases.
    Merge(MergeArgs),
}

#[derive(clap::Args)]
struct RunArgs {
    /// the base scenario (TOML: one conductor, or a line with [line]); every case is this file with the
    /// varied fields set
    #[arg(required = true, value_name = "BASE.toml")]
    base: Option<PathBuf>,
    /// a field and its values: FIELD=V1,V2,... or FIELD=START:STOP:STEP (inclusive); FIELD is a path such
    /// as loads.wind.speed_m_per_s, events[0].time_s, geometry.right_support_m[1], or in a line
    /// line.conductors[name=A].section.tension_fraction_of_rts (a conductor by name or index); repeat for a
    /// product
    #[arg(long, value_name = "FIELD=VALUES")]
    vary: Vec<String>,
    /// a CSV file of cases: a header of field paths, one row per case (combined with --vary as one more
    /// axis of the product)
    #[arg(long, value_name = "CASES.csv")]
    cases: Option<PathBuf>,
    /// output directory: sweep.csv and sweep.json (sweep.K-of-N.* for a shard), cases/ID/ with
    /// --keep-runs
    #[arg(long, default_value = "sweep")]
    out: PathBuf,
    /// worker threads, each running one case at a time (default: all cores)
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..), allow_negative_numbers = true)]
    threads: Option<u16>,
    /// run only the cases i with i mod N = K (K from 0: 0/N to N-1/N)
    #[arg(long, value_name = "K/N", allow_hyphen_values = true)]
    shard: Option<String>,
    /// write each case's scenario.toml and outputs (timeseries.csv, snapshots.csv, summary.json) to
    /// OUT/cases/ID/
    #[arg(long)]
    keep_runs: bool,
    /// run cases above the work budget (2e10 node-steps or 2 GB of output each) instead of marking them
    /// refused
    #[arg(long)]
    allow_large: bool,
    /// print only errors
    #[arg(long)]
    quiet: bool,
    /// run every case as a convergence study (`ohl run --converge`, docs/convergence.md): its row holds the
    /// finest level's results and the extrapolate, GCI and verdict of its design values
    #[command(flatten)]
    converge: super::converge::ConvergeArgs,
}

#[derive(clap::Args)]
struct MergeArgs {
    /// directories holding sweep.K-of-N.csv tables, or the tables themselves
    #[arg(required = true, value_name = "OUT_DIR|TABLE.csv")]
    inputs: Vec<PathBuf>,
    /// where to write sweep.csv and sweep.json (default: the first directory given, else the directory of
    /// the first table)
    #[arg(long)]
    out: Option<PathBuf>,
}

/// Run the command.
pub fn main(args: SweepArgs) -> ExitCode {
    match args.command {
        Some(SweepCommand::Merge(m)) => main_merge(m),
        None => main_run(args.run),
    }
}

fn fail(message: impl std::fmt::Display, code: u8) -> ExitCode {
    err!("error: {message}");
    ExitCode::from(code)
}

fn main_run(a: RunArgs) -> ExitCode {
    let Some(base) = a.base else { return fail("give the base scenario: ohl sweep BASE.toml --vary ...", 2) };
    let shard = match a.shard.as_deref().map(str::parse::<Shard>).transpose() {
        Ok(s) => s,
        Err(e) => return fail(e, 2),
    };
    let spec = match Spec::new(a.cases.as_deref(), &a.vary) {
        Ok(s) => s,
        Err(e) => return fail(e, 2),
    };
    let sweep = match Sweep::new(&base, spec, a.allow_large) {
        Ok(s) => s,
        Err(e) => return fail(&e, e.exit_code()),
    };
    let mut sweep = sweep;
    if a.converge.converge {
        if a.allow_large {
            return fail("--converge with --allow-large: give --budget", 2);
        }
        match a.converge.options() {
            Ok(o) => sweep.converge = Some(o),
            Err(e) => return fail(e, 2),
        }
    }
    let threads = a.threads.map_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()), usize::from);
    let opts = Options { threads, shard, keep_runs: a.keep_runs, out: a.out };
    let cases = sweep.spec.cases;
    let mine = shard.map_or(cases, |s| s.ids(cases).len());
    let what = shard.map_or_else(|| format!("{cases} cases"), |s| format!("shard {s}: {mine} of {cases} cases"));
    if !a.quiet {
        let fields: Vec<String> = sweep.spec.fields().map(|f| f.to_string()).collect();
        let plural = if threads == 1 { "" } else { "s" };
        err!("sweep: {what} varying {} on {threads} thread{plural} into {}", fields.join(", "), opts.out.display());
    }
    let started = Instant::now();
    let quiet = a.quiet;
    let progress = move |done: usize, total: usize| {
        // One line at every tenth of the cases, for logs (a Slurm job's output) as well as terminals.
        if !quiet && total >= 20 && (done * 10 / total) > ((done - 1) * 10 / total) {
            err!("  {done}/{total} cases, {:.1} s", started.elapsed().as_secs_f64());
        }
    };
    let report = match run_sweep(&sweep, &opts, &progress) {
        Ok(r) => r,
        Err(e) => return fail(&e, e.exit_code()),
    };
    let counts: Vec<String> = report.statuses.iter().map(|(s, n)| format!("{n} {}", s.as_str())).collect();
    let all_fine = report.statuses.keys().all(|s| matches!(s, Status::Completed | Status::Settled));
    let note = if all_fine { "" } else { " (see the status and reason columns)" };
    if !a.quiet {
        out!(
            "sweep: {what} in {:.3} s on {threads} thread{}: {:.3} cases/s; {}{note}",
            report.wall_time_s,
            if threads == 1 { "" } else { "s" },
            report.cases_per_second,
            counts.join(", ")
        );
        out!("  table: {}, manifest: {}", report.table.display(), report.manifest.display());
    }
    if !report.start_up_cases.is_empty() {
        let ids: Vec<String> = report.start_up_cases.iter().map(|c| c.to_string()).collect();
        err!(
            "warning: case(s) {} have a peak from the wind's onset (column start_up_peak = yes): the overshoot of \
             the start, not a design value; start from the equilibrium under the wind or ramp it over several \
             periods of the span's first mode (docs/sweeps.md)",
            ids.join(", ")
        );
    }
    let failed = report.statuses.get(&Status::Failed).copied().unwrap_or(0);
    if failed > 0 {
        return fail(format!("{failed} case(s) failed: files could not be written (see the reason column)"), 1);
    }
    ExitCode::SUCCESS
}

fn main_merge(m: MergeArgs) -> ExitCode {
    match merge(&m.inputs, m.out.as_deref()) {
        Ok(r) => {
            let counts: Vec<String> = r.statuses.iter().map(|(s, n)| format!("{n} {s}")).collect();
            out!("merged {} tables: {} cases ({}) into {}", r.tables, r.cases, counts.join(", "), r.table.display());
            ExitCode::SUCCESS
        }
        Err(e) => fail(&e, e.exit_code()),
    }
}
