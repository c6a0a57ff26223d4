//! `ohl run SCENARIO.toml --out DIR`: run one scenario and write its output files.
//!
//! Before it runs, the work is estimated ([`ohl::scenario::work`]): `--dry-run` prints the estimate and
//! exits 0; a scenario above the budget (2e10 node-steps, about 130 s, or 2 GB of output) is refused with
//! exit 2 unless `--allow-large` is given. When stderr is not a terminal (no progress bar) and the run is
//! long, one line `running: N steps, about T s` goes to stderr before it starts. Warnings (valid but
//! doubtful values, [`ohl::scenario::warnings`]) go to stderr first, one line each, and into `summary.json`.
//!
//! The printed summary: for one span its mid-span displacement and largest tension; for a section per
//! support its peak and final loads and per span its final sag, clearance and tensions (kN, from
//! `summary.json`); for a line per conductor, clearance pair and tower. `--static-after` then solves the
//! residual static state of the final configuration ([`ohl::statics::residual`]), prints it and writes
//! `static.json` (exit 1 if that solve fails; refused for a line, exit 2).

use std::path::PathBuf;
use std::process::ExitCode;

use ohl::run::{RunError, RunOptions, run_observed};

use ohl::scenario::{self, WorkEstimate};
use ohl_app::cases::peak_over_residual;
use ohl_app::paper::heat_spec;
use ohl_app::progress::Bar;

/// Arguments of `ohl run`.
#[derive(clap::Args)]
pub struct RunArgs {
    /// the scenario (TOML, SI units)
    scenario: PathBuf,
    /// output directory (created if missing)
    #[arg(long, default_value = "out")]
    out: PathBuf,
    /// do not print the summary
    #[arg(long)]
    quiet: bool,
    /// print the work estimate (steps, node-steps, output rows and bytes, CPU time on one core: for a line
    /// per element, `ohl::scenario::work`) and exit 0 without running
    #[arg(long)]
    dry_run: bool,
    /// run a scenario above the work budget (2e10 node-steps or 2 GB of output)
    #[arg(long)]
    allow_large: bool,
    /// after the run, solve the residual static state of its final configuration (Newton; broken pieces,
    /// failed strings, ice and temperatures as at the end; a fallen piece lies on the ground), print its
    /// support loads and span sags and write it to DIR/static.json
    #[arg(long)]
    static_after: bool,
    /// the convergence study (`--converge` and its options)
    #[command(flatten)]
    converge: super::converge::ConvergeArgs,
}

/// Above this many node-steps a run announces itself on stderr when no progress bar is drawn.
const ANNOUNCE_NODE_STEPS: f64 = 1.0e9;

/// Run the command; exit 0 on success, 1 if unstable or output failed, 2 on invalid input.
pub fn main(args: RunArgs) -> ExitCode {
    let RunArgs { scenario: path, out, quiet, dry_run, allow_large, static_after, converge } = args;
    if let Some(message) = heat_case_refusal(&path) {
        err!("error: {}: {message}", path.display());
        return ExitCode::from(2);
    }
    if converge.converge {
        if static_after || allow_large {
            let what = if static_after { "--static-after" } else { "--allow-large (give --budget)" };
            err!("error: {}: --converge is not available with {what}", path.display());
            return ExitCode::from(2);
        }
        return super::converge::main(&path, &out, quiet, dry_run, &converge);
    }
    if std::fs::read_to_string(&path).is_ok_and(|t| scenario::line::is_line(&t)) {
        if static_after {
            err!(
                "error: {}: --static-after is not available for a [line] scenario yet (a single conductor or a [section] only)",
                path.display()
            );
            return ExitCode::from(2);
        }
        return run_line(&path, &out, quiet, dry_run, allow_large);
    }
    let plan = match scenario::load(&path).and_then(|sc| scenario::plan(&sc, &path.display().to_string())) {
        Ok(p) => p,
        Err(e) => {
            err!("error: {e}");
            return ExitCode::from(2);
        }
    };
    for w in &plan.warnings {
        err!("warning: {}: {w}", path.display());
    }
    let estimate = plan.work_estimate();
    if dry_run {
        print_estimate(&plan.name, &estimate);
        return ExitCode::SUCCESS;
    }
    let checked = if allow_large { estimate.check_resolvable() } else { estimate.check() };
    if let Err(refusal) = checked {
        err!("error: {}: {refusal}", path.display());
        return ExitCode::from(2);
    }
    let opts = RunOptions { out_dir: Some(out.clone()), record: false };
    let mut bar = Bar::for_plan(&plan);
    // No bar: stderr is not a terminal (a script, a log file).
    if bar.is_none() && estimate.work_node_steps() > ANNOUNCE_NODE_STEPS {
        err!("running: {:.0} steps, about {:.0} s", estimate.steps, estimate.wall_time_s());
    }
    let mut extra: Vec<&mut dyn ohl::run::Observer> =
        bar.iter_mut().map(|b| b as &mut dyn ohl::run::Observer).collect();
    let spans = plan.spans.clone();
    let outcome = match run_observed(plan, &opts, &mut extra) {
        Ok(o) => o,
        Err(RunError::Unstable { instability, .. }) => {
            err!("error: {}: {instability}; output so far is in {}", path.display(), out.display());
            return ExitCode::from(1);
        }
        Err(e) => {
            err!("error: {e}");
            return ExitCode::from(1);
        }
    };
    if !quiet {
        print_summary(&outcome.summary);
    }
    // A peak that comes from the start (ohl::output::start_up) is no design value: said on stderr.
    for w in s_start_up_lines(&outcome.summary) {
        err!("warning: {}: {w}", path.display());
    }
    if static_after {
        let solved = ohl::statics::residual::residual(&outcome.solver, &spans);
        let r = match solved {
            Ok(r) => r,
            Err(e) => {
                err!("error: {}: residual static state after the run: {e}", path.display());
                return ExitCode::from(1);
            }
        };
        if let Err(e) = ohl::run::write_residual(&out, &r) {
            err!("error: {e}");
            return ExitCode::from(1);
        }
        if !quiet {
            print_residual(&r, &outcome.summary);
        }
    }
    if !quiet {
        out!("  written to {}", out.display());
    }
    ExitCode::SUCCESS
}

/// Kilonewtons, for the printed tables.
fn kn(f_n: f64) -> f64 {
    f_n / 1e3
}

/// The summary of a run: for one span its mid-span displacement and largest tension; for a section the
/// loads on every support (peak and final) and the state of every span at the end.
fn print_summary(s: &ohl::output::Summary) {
    if s.spans.is_empty() {
        // One span: its mid-span is the probe `mid`; tau is the paper's dimensionless time.
        let d = s.final_midspan_displacement_m;
        out!(
            "{}: {} at t = {:.4} s (tau = t U / l = {:.4}) after {} steps of {:.4e} s",
            s.name,
            s.status,
            s.final_time_s,
            s.final_tau,
            s.steps,
            s.dt_s
        );
        out!("  mid-span displacement [m]: x1 = {:.6}, x2 = {:.6}, x3 = {:.6}", d[0], d[1], d[2]);
        out!("  max tension: {:.2} N; throughput {:.3e} node-steps/s", s.final_max_tension_n, s.node_steps_per_second);
        out!(
            "  peak tension: {:.2} N at {:.3} s (peaks from {} s){}",
            s.peak_max_tension_n,
            s.peak_max_tension_time_s,
            s.peaks_from_s,
            match &s.start_up {
                Some(u) if !u.flagged.is_empty() => " [start-up overshoot]",
                _ => "",
            }
        );
        return;
    }
    out!("{}: {} at t = {:.4} s after {} steps of {:.4e} s", s.name, s.status, s.final_time_s, s.steps, s.dt_s);
    out!(
        "  support loads [kN], force of the conductor on the support (f2 along the line, f3 up; peaks from t = {:.4} s, every step):",
        s.peaks_from_s
    );
    out!(
        "    {:>7} {:>9} | {:>9} {:>8} | {:>9} {:>8} | {:>9} {:>8} | {:>9} {:>9} {:>9}",
        "support",
        "x2 [m]",
        "peak |F|",
        "at [s]",
        "peak f2",
        "at [s]",
        "peak f3",
        "at [s]",
        "final |F|",
        "final f2",
        "final f3"
    );
    for (k, sup) in s.supports.iter().enumerate() {
        let (p, f) = (&sup.peaks, sup.final_force_n);
        out!(
            "    {:>7} {:>9.1} | {:>9.2} {:>8.3} | {:>9.2} {:>8.3} | {:>9.2} {:>8.3} | {:>9.2} {:>9.2} {:>9.2}",
            k,
            sup.position_m[1],
            kn(p.magnitude.value_n),
            p.magnitude.time_s,
            kn(p.components[1].value_n),
            p.components[1].time_s,
            kn(p.components[2].value_n),
            p.components[2].time_s,
            magnitude_kn(f),
            kn(f[1]),
            kn(f[2])
        );
    }
    out!("  spans at the end (sag: chord to conductor at the horizontal middle; H: horizontal tension):");
    out!("{} | {:>12} {:>8}", SPAN_HEADER, "peak T [kN]", "at [s]");
    for sp in &s.spans {
        out!(
            "{} | {:>12.2} {:>8.3}",
            span_row(
                sp.span,
                sp.final_sag_m,
                sp.final_least_clearance_m,
                sp.final_horizontal_tension_n,
                sp.final_max_tension_n
            ),
            kn(sp.peaks.max_tension.value_n),
            sp.peaks.max_tension.time_s
        );
    }
    out!("  max tension: {:.2} kN; throughput {:.3e} node-steps/s", kn(s.final_max_tension_n), s.node_steps_per_second);
}

/// The magnitude of a force `[F1, F2, F3]` [N] in kN.
fn magnitude_kn(f: [f64; 3]) -> f64 {
    kn((f[0] * f[0] + f[1] * f[1] + f[2] * f[2]).sqrt())
}

/// A span quantity scaled by `scale` with `digits` decimals, or "broken" where the span has none.
fn or_broken(x: Option<f64>, digits: usize, scale: f64) -> String {
    x.map_or("broken".into(), |v| format!("{:.*}", digits, v * scale))
}

/// The columns of a span's state, the same at the end of the run and in the residual static state
/// ([`span_row`]).
const SPAN_HEADER: &str = "       span   sag [m]  clearance [m]    H [kN]  max T [kN]";

/// One span's row under [`SPAN_HEADER`]: sag [m], least clearance [m] (`-` without a ground), horizontal
/// and largest tension [kN]; "broken" where a broken span has no sag or horizontal tension.
fn span_row(span: usize, sag_m: Option<f64>, clearance_m: Option<f64>, h_n: Option<f64>, max_t_n: f64) -> String {
    format!(
        "    {:>7} {:>9} {:>14} {:>9} {:>11.2}",
        span,
        or_broken(sag_m, 3, 1.0),
        clearance_m.map_or("-".into(), |c| format!("{c:.3}")),
        or_broken(h_n, 2, 1e-3),
        kn(max_t_n)
    )
}

/// The residual static state of `--static-after`, beside the run's peaks.
fn print_residual(r: &ohl::statics::residual::Residual, s: &ohl::output::Summary) {
    let ground = r.ground_reaction_n[2];
    out!(
        "  residual static state (Newton from the state at t = {:.4} s: {} iterations, residual {:.2e} N){}; static.json:",
        r.after_time_s,
        r.iterations,
        r.residual_n,
        if ground != 0.0 { format!("; the ground carries {:.2} kN (frictionless)", kn(ground)) } else { String::new() }
    );
    out!(
        "    {:>7} {:>9} | {:>9} {:>9} {:>9} | {:>13}",
        "support",
        "x2 [m]",
        "|F| [kN]",
        "f2 [kN]",
        "f3 [kN]",
        "peak/static f2"
    );
    for (k, sup) in r.supports.iter().enumerate() {
        let f = sup.force_n;
        // The ratio where the support carries a static longitudinal load (`ohl cases`' table, NO_RESIDUAL).
        let ratio = (s.supports.get(k))
            .and_then(|p| peak_over_residual(p.peaks.components[1].value_n, f[1]))
            .map_or("-".into(), |v| format!("{v:.2}"));
        out!(
            "    {:>7} {:>9.1} | {:>9.2} {:>9.2} {:>9.2} | {:>13}",
            k,
            sup.position_m[1],
            magnitude_kn(f),
            kn(f[1]),
            kn(f[2]),
            ratio
        );
    }
    out!("{SPAN_HEADER}");
    for sp in &r.spans {
        let st = &sp.state;
        out!("{}", span_row(sp.span, st.sag_m, st.least_clearance_m, st.horizontal_tension_n, st.max_tension_n));
    }
}

/// The estimate of `--dry-run`, one quantity a line.
fn print_estimate(name: &str, e: &WorkEstimate) {
    use ohl::scenario::work::{BUDGET_NODE_STEPS, BUDGET_OUTPUT_BYTES};
    let within = if e.check().is_ok() { "within the budget" } else { "ABOVE the budget: needs --allow-large" };
    out!("{name}: dry run, nothing run ({within})");
    out!("  segments: {}, time step: {:.6e} s, end (or time cap): {} s", e.segments, e.dt_s, e.horizon_s);
    out!("  steps: {:.6e}", e.steps);
    out!("  node-steps: {:.6e} (budget {BUDGET_NODE_STEPS:.1e})", e.node_steps);
    if e.heat_substeps > 0.0 {
        out!("  heat conduction: {:.6e} sub-steps, {:.6e} node updates", e.heat_substeps, e.heat_node_updates);
    }
    out!("  timeseries.csv: {:.6e} rows of {} numbers", e.timeseries_rows, e.timeseries_columns);
    out!("  snapshots.csv: {:.6e} rows", e.snapshot_rows);
    out!("  output: at most {:.3e} bytes (budget {BUDGET_OUTPUT_BYTES:.1e})", e.output_bytes);
    out!(
        "  wall time: about {:.3e} s at {:.1e} node-steps/s (one core, {})",
        e.wall_time_s(),
        e.throughput_node_steps_per_s(),
        if e.sections { "whole runs of a section" } else { "whole runs of one span" }
    );
}

/// A heat-conduction case (a file with a `[rod]` section) is not a wire scenario: the message points to
/// `ohl paper`. None for anything else (including a file that cannot be read: `scenario::load` says so).
fn heat_case_refusal(path: &std::path::Path) -> Option<String> {
    let text = std::fs::read_to_string(path).ok()?;
    heat_spec::is_heat_case(&text).then(|| {
        let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("CASE");
        format!("a heat-conduction case (it has a [rod] section), not a wire scenario: run it with `ohl paper {stem}`")
    })
}

/// `ohl run` on a line scenario (a file with `[line]`: several conductors, [`ohl::scenario::line`]).
fn run_line(path: &std::path::Path, out: &std::path::Path, quiet: bool, dry_run: bool, allow_large: bool) -> ExitCode {
    use ohl::run::line::{LineRunError, LineWorkEstimate, run_line};
    use ohl::scenario::work::{
        BUDGET_NODE_STEPS, BUDGET_OUTPUT_BYTES, CLEARANCE_MEASURED_SHARE, LINE_NS_PER_NODE_STEP,
    };
    let file = path.display().to_string();
    let plan = match scenario::read_text(path)
        .and_then(|t| scenario::line::parse(&t, &file))
        .and_then(|s| scenario::line::plan(&s, &file))
    {
        Ok(p) => p,
        Err(e) => {
            err!("error: {e}");
            return ExitCode::from(2);
        }
    };
    for (p, name) in plan.plans.iter().zip(plan.line.names()) {
        for w in &p.warnings {
            err!("warning: {file}: {name}: {w}");
        }
    }
    let work = LineWorkEstimate::of(&plan);
    if let Err(refusal) = work.check_resolvable() {
        err!("error: {file}: {refusal}");
        return ExitCode::from(2);
    }
    if dry_run {
        out!("{}: dry run, nothing run", plan.name);
        out!("  conductors: {}, nodes: {}, time step: {:.6e} s", work.conductors, work.nodes, work.dt_s);
        out!("  steps: {:.6e}, node-steps: {:.6e} (budget {BUDGET_NODE_STEPS:.1e})", work.steps, work.node_steps);
        out!("  output: at most {:.3e} bytes (budget {BUDGET_OUTPUT_BYTES:.1e})", work.output_bytes);
        if plan.short_circuit.is_some() {
            out!("  steps with short-circuit current: {:.6e}", work.current_steps);
        }
        let [kernel, contact, clearances, forces] = work.cpu_time_parts_s();
        out!("  CPU time: about {:.3e} s on one core (ohl::scenario::work, \"a line\"), of which", work.wall_time_s());
        out!("    kernel and observers: {kernel:.3e} s ({:.1} ns per node-step)", LINE_NS_PER_NODE_STEP);
        if work.sizes.contact_pair_nodes > 0.0 {
            out!("    contact, every step: {contact:.3e} s");
        }
        if work.sizes.clearance_pair_nodes > 0.0 {
            out!("    clearances, {:.0} % of the steps: {clearances:.3e} s", 100.0 * CLEARANCE_MEASURED_SHARE);
        }
        if plan.short_circuit.is_some() {
            out!("    pair forces, the steps with current: {forces:.3e} s");
        }
        return ExitCode::SUCCESS;
    }
    if !allow_large && let Err(refusal) = work.check() {
        err!("error: {file}: {refusal}");
        return ExitCode::from(2);
    }
    match run_line(plan, Some(out)) {
        Ok(o) => {
            if !quiet {
                print_line_summary(&o.summary, out);
            }
            // A peak that comes from the start (ohl::output::start_up) is no design value: said on stderr,
            // with --quiet too (as for a single conductor).
            for c in &o.summary.conductors {
                for w in c.start_up.as_ref().map(|u| u.describe()).unwrap_or_default() {
                    err!("warning: {file}: {}: {w}", c.name);
                }
            }
            ExitCode::SUCCESS
        }
        Err(LineRunError::Unstable { instability, .. }) => {
            err!("error: {file}: {instability}; output so far is in {}", out.display());
            ExitCode::from(1)
        }
        Err(e) => {
            err!("error: {e}");
            ExitCode::from(1)
        }
    }
}

/// The summary of a line run, a few lines per conductor, pair and tower.
fn print_line_summary(s: &ohl::run::line::LineSummary, out: &std::path::Path) {
    out!("{}: {} at t = {:.4} s after {} steps of {:.4e} s", s.name, s.status, s.final_time_s, s.steps, s.dt_s);
    for c in &s.conductors {
        out!(
            "  {} ({}): peak tension {:.1} N at {:.3} s, final {:.1} N{}",
            c.name,
            c.role,
            c.peak_max_tension_n,
            c.peak_max_tension_time_s,
            c.final_max_tension_n,
            match &c.start_up {
                Some(u) if !u.flagged.is_empty() => " [start-up overshoot]",
                _ => "",
            }
        );
    }
    // A distance, or why there is none (a conductor broken in every segment).
    let metres = |x: Option<f64>| x.map_or_else(|| "none (no segment left)".to_string(), |x| format!("{x:.3} m"));
    for c in &s.clearances {
        out!(
            "  clearance {} - {}: least {:.3} m at {:.3} s ({} at {:.3}, {} at {:.3} of their lengths); initial {}, final {}",
            c.between[0],
            c.between[1],
            c.least_m,
            c.time_s,
            c.conductors[0],
            c.at_fraction[0],
            c.conductors[1],
            c.at_fraction[1],
            metres(c.initial_m),
            metres(c.final_m)
        );
    }
    if !s.towers.is_empty() {
        out!("  tower loads [kN], resultant of every attachment on the tower (f1 across, f2 along the line, f3 up):");
        out!(
            "    {:>10} | {:>9} {:>8} {:>8} {:>8} {:>8} | {:>9} {:>8} {:>8} {:>8}",
            "tower",
            "peak |F|",
            "at [s]",
            "f1",
            "f2",
            "f3",
            "final |F|",
            "f1",
            "f2",
            "f3"
        );
    }
    for t in &s.towers {
        let (p, f) = (t.peak_force_n, t.final_force_n);
        out!(
            "    {:>10} | {:>9.2} {:>8.3} {:>8.2} {:>8.2} {:>8.2} | {:>9.2} {:>8.2} {:>8.2} {:>8.2}",
            t.name,
            kn(t.peak_force_magnitude_n),
            t.peak_force_time_s,
            kn(p[0]),
            kn(p[1]),
            kn(p[2]),
            magnitude_kn(f),
            kn(f[0]),
            kn(f[1]),
            kn(f[2])
        );
    }
    for a in &s.attachments {
        out!(
            "  {} x {}: largest tension {:.1} N at {:.3} s ({} - {})",
            a.count,
            a.kind,
            a.peak_tension_n,
            a.time_s,
            a.ends[0],
            a.ends[1]
        );
    }
    out!("  throughput {:.3e} node-steps/s; written to {}", s.node_steps_per_second, out.display());
}

/// The start-up warnings of a summary (empty when no peak comes from the start).
fn s_start_up_lines(s: &ohl::output::Summary) -> Vec<String> {
    s.start_up.as_ref().map(|u| u.describe()).unwrap_or_default()
}
