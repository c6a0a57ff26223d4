//! Line-section cases of `cases/`: real-line studies, each one scenario file, run into
//! `figures/cases/<case>/` (the run's `timeseries.csv`, `snapshots.csv`, `summary.json`) with figures and
//! a table drawn from the files the run wrote:
//!
//! - `<case>_loads.png/.svg`: the force of the conductor on every support along the line (`f2`) and
//!   vertically (`f3`) [kN], the strings' swing along the line [deg] and each span's mid-span height
//!   relative to its chord midpoint [m] (negative: below the chord), against time [s] (every panel in
//!   seconds, the temperature of a thermal case too: over the whole run, and over the load panels' time);
//! - `<case>_shapes.png/.svg`: the section (height `x3` against the distance along the line `x2`) at the
//!   snapshot times, and the ground under it where the case has one;
//! - `<case>_table.csv` and the printed table: per support, the longitudinal load at the start, its peak
//!   (largest magnitude, from `output.peaks_from_s` on, tracked every time step: `summary.json`) and
//!   time, the residual static load, the ratio of peak to residual and the string's largest swing along
//!   the line (every step too); per span the jump of its mid-span point (highest rise above its height at
//!   `peaks_from_s`, tracked every step: the probe's `peak_rise_m[2]` in `summary.json`). The ratio is left empty
//!   (`-` in the printed table) where the support carries no residual longitudinal load: a residual below
//!   [`NO_RESIDUAL`] of the peak is zero to the static solver's tolerance (a support that symmetry or a
//!   break unloads), and the ratio would be rounding over rounding (it printed `4.7e15`, `inf`, `NaN`).
//!
//! With `--converge` ([`converge_case`]) the case is also run on two refined grids (segments per span
//! times 2 and 4, the step following at the case's Courant number; no files written) and the table gains,
//! for every peak load and jump, the Richardson extrapolate and the fine-level GCI (Celik et al. 2008,
//! `F_s = 1.25`; docs/convergence.md), or the verdict where there is none (oscillatory, divergent, a peak
//! moving between events); the whole study is written to `<case>/convergence.json`.
//!
//! The residual static load is the static equilibrium after the event, solved by Newton from the run's
//! final state ([`ohl::statics::residual`], the solve of `ohl run --static-after`): the design quantity
//! of a broken-conductor or ice-shedding load case (the residual static load of ASCE 74). A broken piece
//! is re-hung below its clamp and laid on the ground where it reaches it, the ground a frictionless
//! contact of the solve, so the support carries the weight of the hanging part only (the ground the rest:
//! `residual_ground_n`, printed with the table). Why frictionless, and why re-hung: the module doc of
//! [`ohl::statics::residual`]. With a frictionless ground, the damped run without smoothing comes to rest
//! at this state (`app/tests/cases.rs`). Should the solve fail, the table uses the last sample and says
//! so.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// A residual longitudinal load below this fraction of the peak counts as none (module doc): the static
/// solve's residual is about 1e-10 of the largest load, so anything this small is no load at all.
pub const NO_RESIDUAL: f64 = 1e-6;

/// The ratio of peak to residual load, or `None` where there is no residual load ([`NO_RESIDUAL`]).
pub fn peak_over_residual(peak_n: f64, residual_n: f64) -> Option<f64> {
    let ratio = peak_n / residual_n;
    (residual_n.abs() >= NO_RESIDUAL * peak_n.abs() && residual_n != 0.0 && ratio.is_finite()).then_some(ratio)
}

use ohl::run::{RunOptions, run};
use ohl::scenario;
use ohl::scheme::Explicit;
use ohl::statics;

use crate::plot::{Chart, Series, Style, render_titled};

/// One support's loads.
#[derive(Clone, Debug, PartialEq)]
pub struct SupportRow {
    /// support index along the line
    pub support: usize,
    /// longitudinal load at t = 0 [N]
    pub initial_n: f64,
    /// largest-magnitude longitudinal load [N]
    pub peak_n: f64,
    /// when [s]
    pub peak_time_s: f64,
    /// longitudinal load at the end [N]
    pub residual_n: f64,
    /// vertical load at the end [N]
    pub residual_vertical_n: f64,
    /// largest-magnitude swing along the line [deg] (suspension supports)
    pub peak_swing_deg: Option<f64>,
    /// the peak's grid study (`--converge`)
    pub peak_converged: Option<Converged>,
}

/// A value's grid study ([`converge_case`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Converged {
    /// Richardson extrapolate (none unless converging)
    pub extrapolate: Option<f64>,
    /// fine-level GCI [-] (none unless converging)
    pub gci_fine: Option<f64>,
    /// the study's verdict
    pub verdict: String,
    /// the spread of the three finest levels' values relative to the finest [-]
    pub spread_rel: Option<f64>,
}

impl Converged {
    fn of(q: &crate::converge::Quantity) -> Self {
        let e = q.estimate.as_ref();
        Converged {
            extrapolate: e.and_then(|e| e.extrapolate),
            gci_fine: e.and_then(|e| e.gci_fine),
            verdict: q.verdict.to_string(),
            spread_rel: e.zip(q.values.last().copied().flatten()).map(|(e, fine)| e.spread / fine.abs()),
        }
    }

    /// `58.101 (0.05 %)` in the unit `scale` (1e3: kN), or the verdict with the levels' spread.
    fn shown(c: &Option<Converged>, scale: f64, digits: usize) -> String {
        match c {
            None => "-".into(),
            Some(Converged { extrapolate: Some(x), gci_fine: Some(g), .. }) => {
                format!("{:.digits$} ({:.2} %)", x / scale, g * 100.0)
            }
            Some(c) => match c.spread_rel {
                Some(s) if s.is_finite() => format!("{} (levels within {:.2} %)", c.verdict, s * 100.0),
                _ => c.verdict.clone(),
            },
        }
    }
}

/// What a case produced.
#[derive(Clone, Debug)]
pub struct CaseOutcome {
    /// case name
    pub name: String,
    /// how the run ended (`completed`, `settled`, `not_settled`)
    pub status: String,
    /// simulated time [s]
    pub final_time_s: f64,
    /// wall time of the time loop [s]
    pub wall_s: f64,
    /// node-steps per second of the time loop
    pub node_steps_per_second: f64,
    /// per support
    pub supports: Vec<SupportRow>,
    /// per span: jump of the mid-span point (highest rise above its start) [m] and when [s]
    pub jumps: Vec<(f64, f64)>,
    /// per span: the jump's grid study (`--converge`)
    pub jumps_converged: Vec<Option<Converged>>,
    /// where the files are
    pub dir: PathBuf,
    /// how the residual loads were obtained
    pub residual: String,
    /// the ground's vertical reaction on the wire in the residual static state [N] (zero without a ground,
    /// or where the static solve failed)
    pub residual_ground_n: f64,
}

/// The loads of the residual static state [N].
#[derive(Clone, Debug, PartialEq)]
pub struct Residual {
    /// force of the conductor on each support, in support order [N]
    pub supports: Vec<[f64; 3]>,
    /// the ground's total reaction on the wire [N] (zero without a ground or where nothing lies on it)
    pub ground_n: [f64; 3],
}

/// The residual static loads after the run: the library's residual static state
/// ([`ohl::statics::residual`]: Newton from the final state, broken pieces re-hung and, where the run has a
/// ground, laid on it, the ground a frictionless contact of the solve).
pub fn residual_loads(final_state: &Explicit) -> Result<Residual, String> {
    let r = statics::residual::residual(final_state, &[]).map_err(|e| e.to_string())?;
    Ok(Residual { supports: r.supports.iter().map(|s| s.force_n).collect(), ground_n: r.ground_reaction_n })
}

/// A case failed.
#[derive(Debug, thiserror::Error)]
pub enum CaseError {
    /// invalid scenario
    #[error("{0}")]
    Input(#[from] scenario::InputError),
    /// the run failed
    #[error("{0}")]
    Run(#[from] Box<ohl::run::RunError>),
    /// the run of a line failed
    #[error("{0}")]
    LineRun(#[from] Box<ohl::run::line::LineRunError>),
    /// a file could not be read or written
    #[error("{0}")]
    Io(String),
    /// the grid study (`--converge`) could not be made or run
    #[error("{0}")]
    Converge(String),
}

/// The columns of a CSV file by name.
pub(crate) fn read_columns(path: &Path) -> Result<HashMap<String, Vec<f64>>, CaseError> {
    let io = |e: &dyn std::fmt::Display| CaseError::Io(format!("{}: {e}", path.display()));
    let mut r = csv::Reader::from_path(path).map_err(|e| io(&e))?;
    let names: Vec<String> = r.headers().map_err(|e| io(&e))?.iter().map(String::from).collect();
    let mut cols: HashMap<String, Vec<f64>> = names.iter().map(|n| (n.clone(), Vec::new())).collect();
    for rec in r.records() {
        let rec = rec.map_err(|e| io(&e))?;
        for (n, v) in names.iter().zip(rec.iter()) {
            if let Some(c) = cols.get_mut(n) {
                c.push(v.trim().parse().unwrap_or(f64::NAN));
            }
        }
    }
    Ok(cols)
}

/// Run the case file `path` into `<out>/<case>/` and draw its figures and table.
/// Run the case `path` into `out/<case>/`; with `converge`, also its grid study ([`converge_case`]).
pub fn run_case(path: &Path, out: &Path, converge: bool) -> Result<CaseOutcome, CaseError> {
    let name = path.file_stem().and_then(|s| s.to_str()).unwrap_or("case").to_string();
    let file = path.display().to_string();
    let sc = scenario::load(path)?;
    let plan = scenario::plan(&sc, &file)?;
    for w in &plan.warnings {
        {
            use std::io::Write as _;
            // Dropped if stderr is closed, as every line of the `ohl` commands.
            let _ = writeln!(std::io::stderr(), "warning: {file}: {w}");
        }
    }
    let dir = out.join(&name);
    let ground = plan.ground.clone();
    let start = std::time::Instant::now();
    let o = run(plan, &RunOptions { out_dir: Some(dir.clone()), record: false }).map_err(Box::new)?;
    let wall_time_s = start.elapsed().as_secs_f64();
    let residual = residual_loads(&o.solver);
    let ts = read_columns(&dir.join("timeseries.csv"))?;
    let t = ts.get("t_s").cloned().unwrap_or_default();
    let col = |n: &str| ts.get(n).cloned().unwrap_or_default();
    let n_sup = (0..).take_while(|k| ts.contains_key(&format!("support{k}_f2_n"))).count();
    let n_span = (0..).take_while(|k| ts.contains_key(&format!("span{k}_mid_dx3_m"))).count();
    let mut supports = Vec::new();
    for k in 0..n_sup {
        let f2 = col(&format!("support{k}_f2_n"));
        let f3 = col(&format!("support{k}_f3_n"));
        // The peaks are the run's, tracked every time step from `peaks_from_s` on (summary.json), not the
        // largest of the samples in timeseries.csv, which miss a peak between two samples.
        let peaks = o.summary.supports.get(k).map(|s| &s.peaks);
        supports.push(SupportRow {
            support: k,
            initial_n: f2.first().copied().unwrap_or(f64::NAN),
            peak_n: peaks.map_or(f64::NAN, |p| p.components[1].value_n),
            peak_time_s: peaks.map_or(f64::NAN, |p| p.components[1].time_s),
            residual_n: residual.as_ref().map_or(f2.last().copied().unwrap_or(f64::NAN), |r| r.supports[k][1]),
            residual_vertical_n: residual.as_ref().map_or(f3.last().copied().unwrap_or(f64::NAN), |r| r.supports[k][2]),
            peak_swing_deg: peaks.and_then(|p| p.swing.as_ref()).map(|[along, _]| along.value_deg),
            peak_converged: None,
        });
    }
    // The jump of each span's mid-span: its probe's rise above its height at `peaks_from_s`, every step.
    let jump_probe = |k: usize| o.summary.probes.iter().position(|p| p.name == format!("span{k}_mid"));
    let jumps: Vec<(f64, f64)> = (0..n_span)
        .map(|k| {
            jump_probe(k).map_or((f64::NAN, f64::NAN), |i| {
                let r = o.summary.probes[i].peak_rise_m[2];
                (r.value_m, r.time_s)
            })
        })
        .collect();
    let mut jumps_converged = vec![None; n_span];
    if converge {
        // The study's first level is this run (the case as written): not run again.
        let first = crate::converge::FirstRun { summary: o.summary.clone(), wall_time_s };
        let qs = converge_case(path, &dir, Some(first))?;
        let find = |p: &str| qs.iter().find(|q| q.path == p).map(Converged::of);
        for s in &mut supports {
            s.peak_converged = find(&format!("supports[{}].peaks.components[1].value_n", s.support));
        }
        for (k, c) in jumps_converged.iter_mut().enumerate() {
            *c = jump_probe(k).and_then(|i| find(&format!("probes[{i}].peak_rise_m[2].value_m")));
        }
    }
    // A thermal case (de-icing) runs for many minutes before the event: its load charts start where its
    // peaks do (`output.peaks_from_s`), and the conductor temperature gets a chart over the whole run.
    let from = if ts.contains_key("temperature_k") { o.summary.peaks_from_s } else { f64::NEG_INFINITY };
    // The figures' heading names the case and its conductor.
    let c = &sc.conductor;
    let heading = format!(
        "{name}: {} | conductor {} kg/m{}{}",
        sc.description.as_deref().unwrap_or(""),
        c.linear_density_kg_per_m,
        c.diameter_m.map_or(String::new(), |d| format!(", d = {:.1} mm", d * 1e3)),
        c.axial_stiffness_n.map_or(String::new(), |ea| format!(", EA = {:.0} kN", ea / 1e3)),
    );
    draw(&name, &heading, &dir, &t, &ts, n_sup, n_span, from, ground.as_ref())?;
    write_table(&dir.join(format!("{name}_table.csv")), &supports, &jumps, &jumps_converged)?;
    let s = &o.summary;
    Ok(CaseOutcome {
        residual_ground_n: residual.as_ref().map_or(0.0, |r| r.ground_n[2]),
        residual: match &residual {
            Ok(_) => "static (Newton)".into(),
            Err(e) => format!("last sample (static solve failed: {e})"),
        },
        name,
        status: s.status.clone(),
        final_time_s: s.final_time_s,
        wall_s: s.wall_time_s,
        node_steps_per_second: s.node_steps_per_second,
        supports,
        jumps,
        jumps_converged,
        dir,
    })
}

/// The grid study of a case: the case as written and on segments per span times 2 and 4 (the step at its
/// Courant number), no files written; every summary value paired across the levels and estimated
/// ([`crate::converge::analyse`], rtol 1 %); `dir/convergence.json` written. `first`: the case as written
/// already run (its summary and wall time), the study's first level, which is then not run again.
pub fn converge_case(
    path: &Path,
    dir: &Path,
    first: Option<crate::converge::FirstRun>,
) -> Result<Vec<crate::converge::Quantity>, CaseError> {
    use crate::converge::{self, Options, Refine, report};
    let o = Options {
        refine: Refine::Grid,
        levels: 3,
        ratio: 2,
        coarsen: false,
        scaled_smoothing: false,
        rtol: 0.01,
        budget_node_steps: ohl::scenario::work::BUDGET_NODE_STEPS,
    };
    let file = path.display().to_string();
    let study = |e: converge::StudyError| match e {
        converge::StudyError::Input(e) => CaseError::Input(e),
        e => CaseError::Converge(e.to_string()),
    };
    let sc = scenario::load(path)?;
    let planned = converge::plan_scenario(&sc, &file, None, &o).map_err(study)?;
    let (runs, finest) = converge::run_with_first(path, planned, first, |_, _| {}).map_err(study)?;
    let quantities = converge::analyse(&runs, o.rtol);
    report::write_json(dir, &report::Study::new(&file, &finest.name, &o, &runs, &quantities))
        .map_err(|e| CaseError::Io(format!("{}: {e}", dir.join("convergence.json").display())))?;
    Ok(quantities)
}

#[allow(clippy::too_many_arguments)]
fn draw(
    name: &str,
    heading: &str,
    dir: &Path,
    t: &[f64],
    ts: &HashMap<String, Vec<f64>>,
    n_sup: usize,
    n_span: usize,
    from_s: f64,
    ground: Option<&ohl::scheme::Ground>,
) -> Result<(), CaseError> {
    let series = |col: String, label: String, k: usize, scale: f64| {
        let y = ts.get(&col).cloned().unwrap_or_default();
        let pts = t.iter().zip(&y).filter(|p| *p.0 >= from_s).map(|(&a, &b)| (a, b * scale)).collect();
        Series::new(label, pts, Style::Line, k)
    };
    let mut charts = vec![
        Chart {
            title: "Longitudinal load on each support".into(),
            x_label: "time t [s]".into(),
            y_label: "force along the line f2 [kN]".into(),
            series: (0..n_sup).map(|k| series(format!("support{k}_f2_n"), format!("support {k}"), k, 1e-3)).collect(),
            ..Default::default()
        },
        Chart {
            title: "Vertical load on each support".into(),
            x_label: "time t [s]".into(),
            y_label: "vertical force f3 [kN]".into(),
            series: (0..n_sup).map(|k| series(format!("support{k}_f3_n"), format!("support {k}"), k, 1e-3)).collect(),
            ..Default::default()
        },
    ];
    let swings: Vec<Series> = (0..n_sup)
        .filter(|k| ts.contains_key(&format!("support{k}_swing_along_deg")))
        .map(|k| series(format!("support{k}_swing_along_deg"), format!("support {k}"), k, 1.0))
        .collect();
    if !swings.is_empty() {
        charts.push(Chart {
            title: "Insulator swing along the line".into(),
            x_label: "time t [s]".into(),
            y_label: "swing from plumb [deg]".into(),
            series: swings,
            ..Default::default()
        });
    }
    charts.push(Chart {
        title: "Mid-span height relative to the chord midpoint, each span".into(),
        x_label: "time t [s]".into(),
        y_label: "mid-span x3 - chord-midpoint x3 [m]".into(),
        series: (0..n_span).map(|k| series(format!("span{k}_mid_dx3_m"), format!("span {k}"), k, 1.0)).collect(),
        ..Default::default()
    });
    if let Some(temp) = ts.get("temperature_k") {
        // The figure's one time unit is the second (the load panels'); the temperature in Celsius.
        let (unit, convert): (&str, fn(f64) -> f64) = ("conductor temperature [C]", |k| k - 273.15);
        let pts: Vec<(f64, f64)> = t.iter().zip(temp).map(|(&a, &b)| (a, convert(b))).collect();
        let mut series = vec![Series::new("conductor", pts.clone(), Style::Line, 0)];
        // Where the load panels start, so that the two time ranges read together.
        let (lo, hi) = pts.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.1), b.max(p.1)));
        if from_s.is_finite() && lo.is_finite() {
            let label = format!("start of the load panels (t = {from_s} s)");
            series.push(Series::new(label, vec![(from_s, lo), (from_s, hi)], Style::Dotted, 7));
        }
        charts.push(Chart {
            title: "Conductor temperature (whole run)".into(),
            x_label: "time t [s]".into(),
            y_label: unit.into(),
            series,
            ..Default::default()
        });
        // The quadrant beside it: the temperature over the load panels' time range (the shedding).
        if charts.len() % 2 == 1 && from_s.is_finite() {
            let window: Vec<(f64, f64)> = pts.iter().copied().filter(|p| p.0 >= from_s).collect();
            charts.push(Chart {
                title: "Conductor temperature over the load panels' time".into(),
                x_label: "time t [s]".into(),
                y_label: unit.into(),
                series: vec![Series::new("conductor", window, Style::Line, 0)],
                ..Default::default()
            });
        }
    }
    let plot_err = |e: crate::plot::PlotError| CaseError::Io(e.to_string());
    render_titled(&charts, 2, (680, 440), heading, &dir.join(format!("{name}_loads"))).map_err(plot_err)?;
    // Shapes at the snapshot times.
    let snaps = read_columns(&dir.join("snapshots.csv"))?;
    let (st, x2, x3) = (snaps.get("t_s"), snaps.get("x2_m"), snaps.get("x3_m"));
    if let (Some(st), Some(x2), Some(x3)) = (st, x2, x3) {
        let mut times: Vec<f64> = st.clone();
        times.dedup();
        let mut shapes: Vec<Series> = times
            .iter()
            .enumerate()
            .map(|(k, &tk)| {
                let pts = (0..st.len()).filter(|&i| st[i] == tk).map(|i| (x2[i], x3[i])).collect();
                Series::new(format!("t = {tk:.2} s"), pts, Style::Line, k)
            })
            .collect();
        if let Some(g) = ground {
            let (lo, hi) = x2.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
            if lo.is_finite() {
                let mut xs = vec![lo, hi];
                xs.extend(g.profile_m.iter().map(|p| p[0]).filter(|&x| x > lo && x < hi));
                xs.sort_by(f64::total_cmp);
                let label = if g.profile_m.is_empty() {
                    format!("ground, x3 = {} m", g.height_m)
                } else {
                    "ground profile".into()
                };
                shapes.push(Series::new(label, xs.iter().map(|&x| (x, g.height_at(x))).collect(), Style::Dashed, 7));
            }
        }
        let chart = Chart {
            title: "The section at the snapshot times".into(),
            x_label: "distance along the line x2 [m]".into(),
            y_label: "height x3 [m]".into(),
            series: shapes,
            ..Default::default()
        };
        render_titled(&[chart], 1, (1200, 480), heading, &dir.join(format!("{name}_shapes"))).map_err(plot_err)?;
    }
    Ok(())
}

fn write_table(
    path: &Path,
    supports: &[SupportRow],
    jumps: &[(f64, f64)],
    jumps_converged: &[Option<Converged>],
) -> Result<(), CaseError> {
    let io = |e: &dyn std::fmt::Display| CaseError::Io(format!("{}: {e}", path.display()));
    let mut w = csv::Writer::from_path(path).map_err(|e| io(&e))?;
    w.write_record([
        "item",
        "initial_f2_n",
        "peak_f2_n",
        "peak_time_s",
        "residual_f2_n",
        "peak_over_residual",
        "residual_f3_n",
        "peak_swing_deg",
        "jump_m",
        "jump_time_s",
        "extrapolate",
        "gci_fine",
        "verdict",
    ])
    .map_err(|e| io(&e))?;
    // the grid study's columns (`--converge`): the extrapolate of the row's peak (N) or jump (m)
    let study = |c: &Option<Converged>| match c {
        None => [String::new(), String::new(), String::new()],
        Some(c) => [
            c.extrapolate.map_or(String::new(), |x| format!("{x:.4}")),
            c.gci_fine.map_or(String::new(), |g| format!("{g:.3e}")),
            c.verdict.clone(),
        ],
    };
    for s in supports {
        let ratio = peak_over_residual(s.peak_n, s.residual_n).map_or(String::new(), |r| format!("{r:.4}"));
        let swing = s.peak_swing_deg.map_or(String::new(), |v| format!("{v:.3}"));
        let mut rec = vec![
            format!("support {}", s.support),
            format!("{:.3}", s.initial_n),
            format!("{:.3}", s.peak_n),
            format!("{:.4}", s.peak_time_s),
            format!("{:.3}", s.residual_n),
            ratio,
            format!("{:.3}", s.residual_vertical_n),
            swing,
            String::new(),
            String::new(),
        ];
        rec.extend(study(&s.peak_converged));
        w.write_record(rec).map_err(|e| io(&e))?;
    }
    for (k, (j, tj)) in jumps.iter().enumerate() {
        let mut rec = vec![format!("span {k}")];
        rec.extend(std::iter::repeat_n(String::new(), 7));
        rec.extend([format!("{j:.4}"), format!("{tj:.4}")]);
        rec.extend(study(jumps_converged.get(k).unwrap_or(&None)));
        w.write_record(rec).map_err(|e| io(&e))?;
    }
    w.flush().map_err(|e| io(&e))
}

/// The printed table of a case.
pub fn format_table(c: &CaseOutcome) -> String {
    let mut s = String::new();
    s.push_str(&format!(
        "== {}: {} at t = {:.2} s, time loop {:.2} s ({:.3e} node-steps/s); files in {}\n   residual loads: {}{}\n",
        c.name,
        c.status,
        c.final_time_s,
        c.wall_s,
        c.node_steps_per_second,
        c.dir.display(),
        c.residual,
        if c.residual_ground_n != 0.0 {
            format!("; the ground carries {:.2} kN (frictionless)", c.residual_ground_n / 1e3)
        } else {
            String::new()
        }
    ));
    let study = c.supports.iter().any(|r| r.peak_converged.is_some());
    let (head, rule) = if study { (" converged peak f2 [kN] (GCI) |", "---|") } else { ("", "") };
    s.push_str(&format!(
        "| support | f2 at t=0 [kN] | peak f2 [kN] | at [s] |{head} residual f2 [kN] | peak/residual | residual f3 [kN] | peak swing [deg] |\n"
    ));
    s.push_str(&format!("|---|---|---|---|{rule}---|---|---|---|\n"));
    for r in &c.supports {
        let swing = r.peak_swing_deg.map_or("-".into(), |v| format!("{v:.1}"));
        let conv = if study { format!(" {} |", Converged::shown(&r.peak_converged, 1e3, 3)) } else { String::new() };
        s.push_str(&format!(
            "| {} | {:.2} | {:.2} | {:.2} |{conv} {:.2} | {} | {:.2} | {} |\n",
            r.support,
            r.initial_n / 1e3,
            r.peak_n / 1e3,
            r.peak_time_s,
            r.residual_n / 1e3,
            peak_over_residual(r.peak_n, r.residual_n).map_or("-".into(), |v| format!("{v:.2}")),
            r.residual_vertical_n / 1e3,
            swing
        ));
    }
    s.push_str(&format!(
        "| span | mid-span jump [m] | at [s] |{}\n|---|---|---|{rule}\n",
        if study { " converged jump [m] (GCI) |" } else { "" }
    ));
    for (k, (j, t)) in c.jumps.iter().enumerate() {
        let conv = if study {
            format!(" {} |", Converged::shown(c.jumps_converged.get(k).unwrap_or(&None), 1.0, 4))
        } else {
            String::new()
        };
        s.push_str(&format!("| {k} | {j:.3} | {t:.2} |{conv}\n"));
    }
    if study {
        s.push_str("   converged: the Richardson extrapolate of the case on 1, 2 and 4 times its segments per span, with the finest grid's GCI (F_s = 1.25), or why there is none (docs/convergence.md); convergence.json in the case's folder\n");
    }
    s
}
