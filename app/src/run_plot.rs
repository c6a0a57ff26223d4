//! The figures of one run's output folder (`ohl plot RUN_DIR`): what `ohl run SCENARIO.toml --out DIR`
//! wrote, read back and drawn with [`crate::plot`] to PNG and SVG.
//!
//! - `timeseries`: displacement of the mid-span point (a section: of each span's mid-span point) and of
//!   every named probe from its chord point, vertical always and across or along the line when it moves;
//!   the largest segment tension (a section: per span); the least ground clearance per span (with a
//!   ground); the energy balance from the first sample drawn: kinetic energy, the changes of the elastic
//!   and the potential energy, and the energy dissipated, `-(E_total - E_total(t0))`, so that the four add
//!   up to zero (an event that changes the mass or the temperature adds to the dissipated curve its own
//!   step); the conductor temperature (with a `[thermal]` table);
//! - `reactions`: each support's force components (the force the wire applies to the support: vertical
//!   `F3`, along the line `F2`, across it `F1`), and the swing of each suspension string;
//! - `shapes`: the wire at the snapshot times (at most [`MAX_SHAPES`], evenly chosen), side view `x3`
//!   against `x2`, and plan view `x1` against `x2` when the wire moves across the line. A segment stretched
//!   by more than [`GAP_STRAIN`] (a broken one: no conductor stretches that far) is drawn as a gap.
//!
//! `timeseries.csv` is required; `snapshots.csv` and `summary.json` are optional (a run killed before its
//! end has no `summary.json`): without the summary the scenario is named after the folder. Titles name
//! the scenario (`summary.json`'s `name`) and the conductor when the summary records one (`thermal`).
//! Every sample is handed to the plotting module, which reduces a long series to each pixel column's
//! first, least, greatest and last point (peaks survive, the SVG stays small); a window (`--from`, `--to`)
//! shows the detail.
//!
//! Without a window the transient is drawn readably as well: the vertical displacement gets a second
//! panel over the first [`DETAIL_FRACTION`] of the time from the run's first event (`peaks_from_s`; the
//! start if there is none) to its end, and so do the largest tension and the longitudinal support force
//! where a figure would otherwise leave a quadrant empty.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use crate::plot::{Chart, PlotError, Series, Style, render};

/// Most snapshots drawn in one shape panel (each in its own colour of the palette's 10).
pub const MAX_SHAPES: usize = 8;
/// A segment whose chord exceeds its unstretched length by this fraction is drawn as a gap (broken).
pub const GAP_STRAIN: f64 = 0.1;
/// The detail panels show this fraction of the time from the first event to the end (module doc).
pub const DETAIL_FRACTION: f64 = 0.15;
/// A detail window with fewer samples than this is not drawn (nothing to see in more detail).
const DETAIL_MIN_SAMPLES: usize = 20;
/// A displacement component whose range over the window stays below this [m] gets no panel.
const STILL_M: f64 = 1.0e-6;

/// Panel size [px] of the time-series and reaction figures (two columns).
const PANEL: (u32, u32) = (720, 420);
/// Panel size [px] of the shape figure (one column).
const SHAPE_PANEL: (u32, u32) = (1400, 460);

/// What `ohl plot` draws and where.
#[derive(Clone, Debug, Default)]
pub struct PlotOptions {
    /// folder of the figures (default `RUN_DIR/plots`)
    pub out: Option<PathBuf>,
    /// first time drawn [s] (default: the run's start)
    pub from_s: Option<f64>,
    /// last time drawn [s] (default: the run's end)
    pub to_s: Option<f64>,
}

/// What was drawn.
#[derive(Clone, Debug, Default)]
pub struct PlotReport {
    /// the files written (`.png` and `.svg` of each figure)
    pub files: Vec<PathBuf>,
    /// remarks for the user (a figure left out, and why; a run that went unstable)
    pub notes: Vec<String>,
}

/// `ohl plot` failed.
#[derive(Debug, thiserror::Error)]
pub enum RunPlotError {
    /// RUN_DIR does not exist or is not a folder.
    #[error("{}: not a folder (give the folder `ohl run SCENARIO.toml --out DIR` wrote)", .0.display())]
    NoFolder(PathBuf),
    /// RUN_DIR is the folder of a line run (several conductors): each conductor's files are in a folder
    /// of their own.
    #[error(
        "{dir} is the folder of a line run: plot one conductor's folder, e.g. `ohl plot {example}` (the line's \
         clearances and tower loads are drawn by `ohl cases`, from clearances.csv and towers.csv)",
        dir = .dir.display(),
        example = .example.display()
    )]
    LineRun {
        /// the folder given
        dir: PathBuf,
        /// one conductor's folder in it
        example: PathBuf,
    },
    /// RUN_DIR lacks `timeseries.csv`.
    #[error(
        "{dir} is not a run folder: {missing} is missing (`ohl run SCENARIO.toml --out DIR` writes timeseries.csv, snapshots.csv and summary.json)",
        dir = .dir.display(),
        missing = .missing.display()
    )]
    NotARun {
        /// the folder given
        dir: PathBuf,
        /// the file it lacks
        missing: PathBuf,
    },
    /// A file of the run could not be read or is not what `ohl run` writes.
    #[error("{path}: {message}", path = .path.display())]
    BadFile {
        /// the file
        path: PathBuf,
        /// what is wrong
        message: String,
    },
    /// `--from` / `--to` select nothing or are not a window.
    #[error("{0}")]
    Window(String),
    /// A figure could not be drawn or written.
    #[error(transparent)]
    Plot(#[from] PlotError),
}

impl RunPlotError {
    /// The exit code of `ohl plot`: 1 when a figure could not be written, 2 for the input (the folder,
    /// its files, the window).
    pub fn exit_code(&self) -> u8 {
        match self {
            RunPlotError::Plot(_) => 1,
            _ => 2,
        }
    }
}

/// A CSV file's columns by header position.
struct Table {
    path: PathBuf,
    names: Vec<String>,
    index: HashMap<String, usize>,
    cols: Vec<Vec<f64>>,
}

impl Table {
    fn read(path: &Path) -> Result<Table, RunPlotError> {
        let bad = |message: String| RunPlotError::BadFile { path: path.to_path_buf(), message };
        let mut r = csv::Reader::from_path(path).map_err(|e| bad(e.to_string()))?;
        let names: Vec<String> = r.headers().map_err(|e| bad(e.to_string()))?.iter().map(String::from).collect();
        let mut cols = vec![Vec::new(); names.len()];
        for rec in r.records() {
            let rec = rec.map_err(|e| bad(e.to_string()))?;
            let line = rec.position().map_or(0, |p| p.line());
            for (k, cell) in rec.iter().enumerate() {
                let v: f64 = cell.trim().parse().map_err(|_| {
                    let name = names.get(k).map_or("?", String::as_str);
                    bad(format!("line {line}, column `{name}`: `{cell}` is not a number"))
                })?;
                if let Some(c) = cols.get_mut(k) {
                    c.push(v);
                }
            }
        }
        let index = names.iter().enumerate().map(|(k, n)| (n.clone(), k)).collect();
        Ok(Table { path: path.to_path_buf(), names, index, cols })
    }

    fn col(&self, name: &str) -> Option<&[f64]> {
        self.index.get(name).map(|&k| self.cols[k].as_slice())
    }

    fn require(&self, name: &str) -> Result<&[f64], RunPlotError> {
        self.col(name).ok_or_else(|| RunPlotError::BadFile {
            path: self.path.clone(),
            message: format!("no column `{name}`: not a file of `ohl run`"),
        })
    }
}

/// One snapshot: the wire's nodes at one time.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Snapshot {
    /// its time [s]
    pub t_s: f64,
    /// Lagrangian coordinate of each node [m]
    pub s_m: Vec<f64>,
    /// position of each node [m]
    pub x_m: Vec<[f64; 3]>,
}

/// The snapshots of `snapshots.csv`, one per time (a new one starts at node 0 or at a new time).
fn read_snapshots(path: &Path) -> Result<Vec<Snapshot>, RunPlotError> {
    let tab = Table::read(path)?;
    let (t, node, s) = (tab.require("t_s")?, tab.require("node")?, tab.require("s_m")?);
    let (x1, x2, x3) = (tab.require("x1_m")?, tab.require("x2_m")?, tab.require("x3_m")?);
    let mut out: Vec<Snapshot> = Vec::new();
    for i in 0..t.len() {
        let new = match out.last() {
            Some(last) => node[i] == 0.0 || last.t_s != t[i],
            None => true,
        };
        if new {
            out.push(Snapshot { t_s: t[i], ..Default::default() });
        }
        if let Some(last) = out.last_mut() {
            last.s_m.push(s[i]);
            last.x_m.push([x1[i], x2[i], x3[i]]);
        }
    }
    Ok(out)
}

/// A support as `summary.json` records it.
#[derive(Clone, Debug)]
struct Support {
    position_m: [f64; 3],
}

/// A run folder read back.
struct Run {
    heading: String,
    ts: Table,
    snapshots: Vec<Snapshot>,
    supports: Vec<Support>,
    /// `peaks_from_s` of the summary: the first event's time or the scenario's choice
    events_from_s: Option<f64>,
    notes: Vec<String>,
}

impl Run {
    fn read(dir: &Path) -> Result<Run, RunPlotError> {
        if !dir.is_dir() {
            return Err(RunPlotError::NoFolder(dir.to_path_buf()));
        }
        let ts_path = dir.join("timeseries.csv");
        if !ts_path.is_file() {
            let conductors = dir.join("conductors");
            let first = std::fs::read_dir(&conductors).ok().and_then(|mut d| {
                d.find_map(|e| e.ok().map(|e| e.path()).filter(|p| p.join("timeseries.csv").is_file()))
            });
            if let Some(example) = first {
                return Err(RunPlotError::LineRun { dir: dir.to_path_buf(), example });
            }
            return Err(RunPlotError::NotARun { dir: dir.to_path_buf(), missing: ts_path });
        }
        let ts = Table::read(&ts_path)?;
        ts.require("t_s")?;
        let mut notes = Vec::new();
        let snap_path = dir.join("snapshots.csv");
        let snapshots = if snap_path.is_file() { read_snapshots(&snap_path)? } else { Vec::new() };
        let sum_path = dir.join("summary.json");
        let folder = dir
            .canonicalize()
            .ok()
            .and_then(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
            .unwrap_or_else(|| dir.display().to_string());
        let (mut heading, mut supports, mut events_from_s) = (folder, Vec::new(), None);
        if sum_path.is_file() {
            let text = std::fs::read_to_string(&sum_path)
                .map_err(|e| RunPlotError::BadFile { path: sum_path.clone(), message: e.to_string() })?;
            let v: serde_json::Value = serde_json::from_str(&text)
                .map_err(|e| RunPlotError::BadFile { path: sum_path.clone(), message: e.to_string() })?;
            if let Some(name) = v["name"].as_str().filter(|n| !n.is_empty()) {
                heading = name.to_string();
            }
            if let Some(c) = v["thermal"]["conductor"].as_str() {
                heading = format!("{heading} ({c})");
            }
            supports = v["supports"]
                .as_array()
                .map(|a| {
                    a.iter()
                        .filter_map(|s| {
                            let p = s["position_m"].as_array()?;
                            let x = |k: usize| p.get(k).and_then(|x| x.as_f64());
                            Some(Support { position_m: [x(0)?, x(1)?, x(2)?] })
                        })
                        .collect()
                })
                .unwrap_or_default();
            events_from_s = v["peaks_from_s"].as_f64();
            if let Some(i) = v.get("instability").filter(|i| !i.is_null()) {
                let reason =
                    i["reason"].as_str().map_or_else(|| format!("unstable at t = {} s", i["time_s"]), String::from);
                notes.push(format!("the run stopped: {reason}; the figures end there"));
            }
        } else {
            notes.push(format!(
                "{} is missing (a run stopped early?): titles use the folder's name",
                sum_path.display()
            ));
        }
        Ok(Run { heading, ts, snapshots, supports, events_from_s, notes })
    }

    fn title(&self, what: &str) -> String {
        format!("{}: {what}", self.heading)
    }

    /// Number of supports with force columns.
    fn support_count(&self) -> usize {
        (0..).take_while(|k| self.ts.col(&format!("support{k}_f1_n")).is_some()).count()
    }

    /// Number of spans with columns of their own (0 for one span).
    fn span_count(&self) -> usize {
        (0..).take_while(|k| self.ts.col(&format!("span{k}_max_tension_n")).is_some()).count()
    }

    /// The probes after the fixed columns: names `P` of the triples `P_dx1_m, P_dx2_m, P_dx3_m`.
    fn probe_names(&self) -> Vec<String> {
        let n = &self.ts.names;
        let mut out = Vec::new();
        let mut k = 10.min(n.len());
        while k + 2 < n.len() {
            let Some(p) = n[k].strip_suffix("_dx1_m") else { break };
            if n[k + 1] != format!("{p}_dx2_m") || n[k + 2] != format!("{p}_dx3_m") {
                break;
            }
            out.push(p.to_string());
            k += 3;
        }
        out
    }

    fn support_label(&self, k: usize) -> String {
        match self.supports.get(k) {
            Some(s) if self.supports.len() == self.support_count() => {
                format!("support {k} (x2 = {} m)", short(s.position_m[1]))
            }
            _ => format!("support {k}"),
        }
    }
}

/// Style and palette index of the `k`-th series of a panel: solid for the first 8, dashed for the next.
fn look(k: usize) -> (Style, usize) {
    (if (k / 8).is_multiple_of(2) { Style::Line } else { Style::Dashed }, k)
}

/// A number with about four significant digits, no trailing zeros.
fn short(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let digits = (3 - v.abs().log10().floor() as i32).clamp(0, 6) as usize;
    let s = format!("{v:.digits$}");
    if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.').to_string() } else { s }
}

/// Largest finite magnitude over several columns (0 if none).
fn max_abs<'a>(cols: impl IntoIterator<Item = &'a [f64]>, rows: &[usize]) -> f64 {
    cols.into_iter()
        .flat_map(|c| rows.iter().map(move |&i| c[i]))
        .filter(|v| v.is_finite())
        .fold(0.0, |m, v| m.max(v.abs()))
}

/// Force unit for values up to `m` [N]: (name, factor from N).
fn force_unit(m: f64) -> (&'static str, f64) {
    if m >= 1.0e3 { ("kN", 1.0e-3) } else { ("N", 1.0) }
}

/// Energy unit for values up to `m` [J].
fn energy_unit(m: f64) -> (&'static str, f64) {
    if m >= 1.0e7 {
        ("MJ", 1.0e-6)
    } else if m >= 1.0e4 {
        ("kJ", 1.0e-3)
    } else {
        ("J", 1.0)
    }
}

/// Break a snapshot's polyline `(x2, y)` where a segment is stretched by more than [`GAP_STRAIN`].
pub fn pieces(snap: &Snapshot, y: usize) -> Vec<Vec<(f64, f64)>> {
    let mut out: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
    for i in 0..snap.x_m.len() {
        if i > 0 {
            let (a, b) = (snap.x_m[i - 1], snap.x_m[i]);
            let chord = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2) + (b[2] - a[2]).powi(2)).sqrt();
            let ds = snap.s_m[i] - snap.s_m[i - 1];
            if chord > (1.0 + GAP_STRAIN) * ds.abs() + 1.0e-9 {
                out.push(Vec::new());
            }
        }
        if let Some(p) = out.last_mut() {
            p.push((snap.x_m[i][1], snap.x_m[i][y]));
        }
    }
    out.retain(|p| !p.is_empty());
    out
}

/// Indices of at most `max` of `n` items, evenly spread, first and last included.
pub fn evenly(n: usize, max: usize) -> Vec<usize> {
    if n <= max {
        return (0..n).collect();
    }
    let mut v: Vec<usize> =
        (0..max).map(|k| ((k as f64) * (n - 1) as f64 / (max - 1).max(1) as f64).round() as usize).collect();
    v.dedup();
    v
}

/// Draw the figures of the run in `run_dir`.
pub fn plot_run(run_dir: &Path, opts: &PlotOptions) -> Result<PlotReport, RunPlotError> {
    let (from, to) = (opts.from_s.unwrap_or(f64::NEG_INFINITY), opts.to_s.unwrap_or(f64::INFINITY));
    if from.is_nan() || to.is_nan() || from >= to {
        return Err(RunPlotError::Window(format!(
            "--from {} --to {}: the window must have --from < --to",
            opts.from_s.map_or("(start)".into(), |v| v.to_string()),
            opts.to_s.map_or("(end)".into(), |v| v.to_string())
        )));
    }
    let run = Run::read(run_dir)?;
    let t = run.ts.require("t_s")?;
    let rows: Vec<usize> = (0..t.len()).filter(|&i| t[i] >= from && t[i] <= to).collect();
    if rows.is_empty() {
        let span = match (t.first(), t.last()) {
            (Some(&a), Some(&b)) => format!("its samples run from t = {} s to t = {} s", short(a), short(b)),
            _ => "it has no samples".into(),
        };
        let window = match (opts.from_s, opts.to_s) {
            (Some(a), Some(b)) => format!("between t = {a} s and t = {b} s"),
            (Some(a), None) => format!("from t = {a} s on"),
            (None, Some(b)) => format!("up to t = {b} s"),
            (None, None) => "at all".into(),
        };
        return Err(RunPlotError::Window(format!("{}: no sample {window} ({span})", run.ts.path.display())));
    }
    let out = opts.out.clone().unwrap_or_else(|| run_dir.join("plots"));
    let mut report = PlotReport { notes: run.notes.clone(), ..Default::default() };
    let mut draw = |charts: Vec<Chart>, cols: usize, size: (u32, u32), name: &str| -> Result<(), RunPlotError> {
        let stem = out.join(name);
        render(&charts, cols, size, &stem)?;
        report.files.push(stem.with_extension("png"));
        report.files.push(stem.with_extension("svg"));
        Ok(())
    };
    // The detail window of the transient (module doc), without a window of the user's.
    let detail: Option<(f64, f64, Vec<usize>)> = match (opts.from_s, opts.to_s, t.first(), t.last()) {
        (None, None, Some(&first), Some(&last)) => {
            let a = run.events_from_s.filter(|&e| e > first && e < last).unwrap_or(first);
            let b = a + DETAIL_FRACTION * (last - a);
            let d: Vec<usize> = rows.iter().copied().filter(|&i| t[i] >= a && t[i] <= b).collect();
            (d.len() >= DETAIL_MIN_SAMPLES).then_some((a, b, d))
        }
        _ => None,
    };
    let mut series_charts = timeseries_charts(&run, &rows)?;
    let (mut reactions, mut notes) = reaction_charts(&run, &rows);
    if let Some((a, b, d)) = &detail {
        let retitle = |mut c: Chart| {
            c.title = format!("{}, t = {} to {} s", c.title, short(*a), short(*b));
            c
        };
        let mut fine = timeseries_charts(&run, d)?.into_iter();
        // The vertical displacement is always the first panel; its detail goes beside it.
        if let Some(c) = fine.next() {
            series_charts.insert(1, retitle(c));
        }
        if series_charts.len() % 2 == 1
            && let Some(k) = series_charts.iter().position(|c| c.y_label.starts_with("T_max"))
            && let Some(c) = fine.find(|c| c.y_label.starts_with("T_max"))
        {
            series_charts.insert(k + 1, retitle(c));
        }
        if reactions.len() % 2 == 1
            && let Some(k) = reactions.iter().position(|c| c.y_label.starts_with("F2"))
            && let Some(c) = reaction_charts(&run, d).0.into_iter().find(|c| c.y_label.starts_with("F2"))
        {
            reactions.insert(k + 1, retitle(c));
        }
    }
    draw(series_charts, 2, PANEL, "timeseries")?;
    if !reactions.is_empty() {
        draw(reactions, 2, PANEL, "reactions")?;
    }
    let snaps: Vec<&Snapshot> = run.snapshots.iter().filter(|s| s.t_s >= from && s.t_s <= to).collect();
    let shapes = shape_charts(&run, &snaps);
    if shapes.is_empty() {
        notes.push(if run.snapshots.is_empty() {
            "no snapshots (snapshots.csv missing or empty): no shapes figure".into()
        } else {
            "no snapshot in the time window: no shapes figure".into()
        });
    } else {
        draw(shapes, 1, SHAPE_PANEL, "shapes")?;
    }
    if snaps.len() > MAX_SHAPES {
        notes.push(format!("{} snapshots: the shapes show {MAX_SHAPES} of them, evenly chosen", snaps.len()));
    }
    // A run whose peaks count from late on (the first event, or `output.peaks_from_s`: a de-icing after a
    // long warm-up): say how to see that part in detail.
    if let (Some(e), Some(&last), None) = (run.events_from_s, t.last(), opts.from_s)
        && e > 0.5 * last
    {
        notes.push(format!(
            "the run's peaks count from t = {} s (of {} s): `--from {}` draws that part in detail",
            short(e),
            short(last),
            short(e)
        ));
    }
    report.notes.extend(notes);
    Ok(report)
}

/// The time-series panels.
fn timeseries_charts(run: &Run, rows: &[usize]) -> Result<Vec<Chart>, RunPlotError> {
    let ts = &run.ts;
    let t = ts.require("t_s")?;
    let line = |y: &[f64], scale: f64, label: String, k: usize| {
        let (style, color) = look(k);
        let pts = rows.iter().map(|&i| (t[i], y[i] * scale)).collect();
        Series::new(label, pts, style, color)
    };
    let spans = run.span_count();
    // Displacement probes: mid-span (left out in a section, where each span has its own), span
    // mid-points ("span k"), named probes.
    let mut probes: Vec<(String, String)> = Vec::new();
    if spans == 0 {
        probes.push(("mid".into(), "mid-span".into()));
    }
    for p in run.probe_names() {
        let label = match p.strip_prefix("span").and_then(|r| r.strip_suffix("_mid")) {
            Some(k) if k.parse::<usize>().is_ok() => format!("span {k} mid-span"),
            _ => p.clone(),
        };
        probes.push((p, label));
    }
    let mut charts = Vec::new();
    let components = [
        (3, "vertical displacement from the chord", "dx3 [m]"),
        (1, "displacement across the line (x1)", "dx1 [m]"),
        (2, "displacement along the line (x2)", "dx2 [m]"),
    ];
    for (c, what, label) in components {
        let cols: Vec<(&[f64], &str)> =
            probes.iter().filter_map(|(p, l)| Some((ts.col(&format!("{p}_dx{c}_m"))?, l.as_str()))).collect();
        let (lo, hi) = cols
            .iter()
            .flat_map(|(y, _)| rows.iter().map(|&i| y[i]))
            .filter(|v| v.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
        let moves = hi - lo > STILL_M;
        if cols.is_empty() || (c != 3 && !moves) {
            continue;
        }
        charts.push(Chart {
            title: run.title(what),
            x_label: "t [s]".into(),
            y_label: label.into(),
            series: cols.iter().enumerate().map(|(k, (y, l))| line(y, 1.0, l.to_string(), k)).collect(),
            ..Default::default()
        });
    }
    // Tension: per span in a section, else the wire's largest.
    let tension: Vec<(&[f64], String)> = if spans > 0 {
        (0..spans).filter_map(|k| Some((ts.col(&format!("span{k}_max_tension_n"))?, format!("span {k}")))).collect()
    } else {
        ts.col("max_tension_n").map(|y| (y, "largest segment tension".to_string())).into_iter().collect()
    };
    if !tension.is_empty() {
        let (unit, f) = force_unit(max_abs(tension.iter().map(|c| c.0), rows));
        charts.push(Chart {
            title: run.title(if spans > 0 { "largest tension in each span" } else { "largest tension" }),
            x_label: "t [s]".into(),
            y_label: format!("T_max [{unit}]"),
            series: tension.iter().enumerate().map(|(k, (y, l))| line(y, f, l.clone(), k)).collect(),
            ..Default::default()
        });
    }
    let clearance: Vec<(&[f64], String)> =
        (0..spans).filter_map(|k| Some((ts.col(&format!("span{k}_clearance_m"))?, format!("span {k}")))).collect();
    if !clearance.is_empty() {
        charts.push(Chart {
            title: run.title("least ground clearance"),
            x_label: "t [s]".into(),
            y_label: "clearance [m]".into(),
            series: clearance.iter().enumerate().map(|(k, (y, l))| line(y, 1.0, l.clone(), k)).collect(),
            ..Default::default()
        });
    }
    // The energy balance from the first sample drawn (module doc): E_kin + dE_el + dE_pot + dissipated = 0.
    if let (Some(kin), Some(el), Some(pot), Some(tot), Some(&i0)) =
        (ts.col("kinetic_j"), ts.col("elastic_j"), ts.col("potential_j"), ts.col("total_j"), rows.first())
    {
        let change = |y: &[f64], sign: f64| -> Vec<f64> { y.iter().map(|v| sign * (v - y[i0])).collect() };
        let curves: [(Vec<f64>, &str); 4] = [
            (kin.to_vec(), "kinetic"),
            (change(el, 1.0), "elastic change"),
            (change(pot, 1.0), "potential change"),
            (change(tot, -1.0), "dissipated, -(total change)"),
        ];
        let (unit, f) = energy_unit(max_abs(curves.iter().map(|c| c.0.as_slice()), rows));
        charts.push(Chart {
            title: run.title(&format!("energy balance from t = {} s", short(t[i0]))),
            x_label: "t [s]".into(),
            y_label: format!("E - E(t0) [{unit}]"),
            series: curves.iter().enumerate().map(|(k, (y, l))| line(y, f, l.to_string(), k)).collect(),
            ..Default::default()
        });
    }
    if let Some(y) = ts.col("temperature_k") {
        let pts = rows.iter().map(|&i| (t[i], y[i] - 273.15)).collect();
        charts.push(Chart {
            title: run.title("conductor temperature"),
            x_label: "t [s]".into(),
            y_label: "T_c [°C]".into(),
            series: vec![Series::new("conductor", pts, Style::Line, 0)],
            ..Default::default()
        });
    }
    Ok(charts)
}

/// The support panels: force components (the force the wire applies to each support) and string swings,
/// with notes on the panels left out. Empty without support columns.
fn reaction_charts(run: &Run, rows: &[usize]) -> (Vec<Chart>, Vec<String>) {
    let ts = &run.ts;
    let (Some(t), n) = (ts.col("t_s"), run.support_count()) else { return (Vec::new(), Vec::new()) };
    if n == 0 {
        return (Vec::new(), Vec::new());
    }
    let col = |k: usize, c: &str| ts.col(&format!("support{k}_{c}"));
    let all = (0..n).flat_map(|k| (1..=3).filter_map(move |c| col(k, &format!("f{c}_n"))));
    let (unit, f) = force_unit(max_abs(all, rows));
    let line = |y: &[f64], scale: f64, k: usize| {
        let (style, color) = look(k);
        let pts = rows.iter().map(|&i| (t[i], y[i] * scale)).collect();
        Series::new(run.support_label(k), pts, style, color)
    };
    let mut charts = Vec::new();
    let mut notes = Vec::new();
    let components = [(3, "vertical (+ up)"), (2, "along the line (+ x2)"), (1, "across the line (+ x1)")];
    for (c, what) in components {
        let cols: Vec<&[f64]> = (0..n).filter_map(|k| col(k, &format!("f{c}_n"))).collect();
        // A component that is zero throughout (no load across the line) gets no panel.
        if c == 1 && max_abs(cols.iter().copied(), rows) == 0.0 {
            notes.push("the support forces across the line (F1) are zero throughout: no panel".into());
            continue;
        }
        let series: Vec<Series> = (0..n).filter_map(|k| Some(line(col(k, &format!("f{c}_n"))?, f, k))).collect();
        charts.push(Chart {
            title: run.title(&format!("force on the supports, {what}")),
            x_label: "t [s]".into(),
            y_label: format!("F{c} [{unit}]"),
            series,
            ..Default::default()
        });
    }
    for (c, what) in [("swing_along_deg", "string swing along the line"), ("swing_across_deg", "string swing across")] {
        let cols: Vec<&[f64]> = (0..n).filter_map(|k| col(k, c)).collect();
        if cols.is_empty() || (c == "swing_across_deg" && max_abs(cols.iter().copied(), rows) == 0.0) {
            continue;
        }
        let series: Vec<Series> = (0..n).filter_map(|k| Some(line(col(k, c)?, 1.0, k))).collect();
        charts.push(Chart {
            title: run.title(what),
            x_label: "t [s]".into(),
            y_label: "swing from plumb [deg]".into(),
            series,
            ..Default::default()
        });
    }
    (charts, notes)
}

/// The shape panels: side view, and plan view when the wire moves across the line. Empty without
/// snapshots.
fn shape_charts(run: &Run, snaps: &[&Snapshot]) -> Vec<Chart> {
    if snaps.is_empty() {
        return Vec::new();
    }
    let chosen: Vec<&Snapshot> = evenly(snaps.len(), MAX_SHAPES).into_iter().map(|k| snaps[k]).collect();
    let x1 = chosen.iter().flat_map(|s| s.x_m.iter().map(|x| x[0])).filter(|v| v.is_finite());
    let (lo, hi) = x1.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
    let lateral = hi - lo > STILL_M;
    let panel = |y: usize, what: &str, y_label: &str| {
        let mut series = Vec::new();
        for (k, s) in chosen.iter().enumerate() {
            for (j, p) in pieces(s, y).into_iter().enumerate() {
                // One legend entry per snapshot; the pieces after a gap share its colour.
                let label = if j == 0 { format!("t = {} s", short(s.t_s)) } else { String::new() };
                series.push(Series::new(label, p, look(k).0, look(k).1));
            }
        }
        if !run.supports.is_empty() {
            let pts = run.supports.iter().map(|s| (s.position_m[1], s.position_m[y])).collect();
            series.push(Series::new("supports", pts, Style::Markers, chosen.len()));
        }
        Chart {
            title: run.title(what),
            x_label: "x2, along the line [m]".into(),
            y_label: y_label.into(),
            series,
            ..Default::default()
        }
    };
    let mut charts = vec![panel(2, "shape at the snapshot times, side view", "x3, height [m]")];
    if lateral {
        charts.push(panel(0, "shape at the snapshot times, plan view", "x1, across the line [m]"));
    }
    charts
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_broken_segment_is_a_gap() {
        let s = Snapshot {
            t_s: 1.0,
            s_m: vec![0.0, 1.0, 2.0, 3.0],
            x_m: vec![[0.0, 0.0, 0.0], [0.0, 1.0, -0.1], [0.0, 1.0, -5.0], [0.0, 1.5, -5.5]],
        };
        // Segment 1 (chord 4.9 m for 1 m unstretched) is broken; segment 2 (0.71 m) is slack, not broken.
        assert_eq!(pieces(&s, 2), vec![vec![(0.0, 0.0), (1.0, -0.1)], vec![(1.0, -5.0), (1.5, -5.5)]]);
    }

    #[test]
    fn snapshots_are_chosen_evenly_with_both_ends() {
        assert_eq!(evenly(3, 8), vec![0, 1, 2]);
        let v = evenly(100, 8);
        assert_eq!(v.len(), 8);
        assert_eq!((v[0], v[7]), (0, 99));
    }

    #[test]
    fn short_numbers() {
        assert_eq!(short(0.5004353828386588), "0.5004");
        assert_eq!(short(1963.081822), "1963");
        assert_eq!(short(30.0), "30");
        assert_eq!(short(400.0), "400");
        assert_eq!(short(0.0), "0");
    }
}
