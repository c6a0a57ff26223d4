//! The convergence study of a line scenario (`[line]`: several conductors on shared towers,
//! [`ohl::scenario::line`]): the levels as for a single conductor ([`super::levels`]), made on the file's
//! TOML document (every conductor's `section.segments_per_span`, its spans' `segments` and a dropper's
//! `segments` times the ratio, or `numerics.courant` and `numerics.smoothing` divided by it) and read back
//! by the line parser, so that each level is validated as a whole line; run by
//! [`ohl::run::line::run_line`]; its `summary.json` (conductors, clearances, towers, attachments) paired
//! by path as a single conductor's.

use std::path::{Path, PathBuf};
use std::time::Instant;

use ohl::run::line::{LineRunError, LineSummary, LineWorkEstimate, run_line};
use ohl::scenario::line::LinePlan;
use ohl::scenario::schema::NumericsSpec;
use ohl::scenario::{self, InputError};
use toml::{Table, Value};

use super::levels::{LevelError, Refine, label};
use super::{LevelRun, Options, StudyError, flatten};

/// A level of a line ready to run.
pub struct PlannedLine {
    /// `x2`: relative to the file as written
    pub label: String,
    /// `ratio^k` relative to the file as written [-]
    pub factor: f64,
    /// its plan
    pub plan: LinePlan,
    /// its work
    pub estimate: LineWorkEstimate,
    /// where its files go (none: not written)
    pub out_dir: Option<PathBuf>,
}

impl PlannedLine {
    /// Its work, as the budget check and the command's messages read it (`count`: the line's nodes).
    pub fn work(&self) -> super::LevelWork {
        super::LevelWork {
            label: self.label.clone(),
            factor: self.factor,
            count: self.estimate.nodes as f64,
            dt_s: self.estimate.dt_s,
            node_steps: self.estimate.node_steps,
            wall_s: self.estimate.wall_time_s(),
            resolvable: self.estimate.check_resolvable().is_ok(),
        }
    }
}

/// The segment fields of a line document, as written (`line.conductors[0].section.segments_per_span`).
fn grid_fields(doc: &mut Table) -> Vec<(String, &mut Value)> {
    let mut f = Vec::new();
    let Some(Value::Array(cs)) = doc.get_mut("line").and_then(|l| l.get_mut("conductors")) else { return f };
    for (i, c) in cs.iter_mut().enumerate() {
        let Value::Table(c) = c else { continue };
        for (key, v) in c.iter_mut() {
            match (key.as_str(), v) {
                ("section", Value::Table(sec)) => {
                    for (k2, v2) in sec.iter_mut() {
                        match (k2.as_str(), v2) {
                            ("segments_per_span", v2) => {
                                f.push((format!("line.conductors[{i}].section.segments_per_span"), v2))
                            }
                            ("spans", Value::Array(spans)) => {
                                for (k, sp) in spans.iter_mut().enumerate() {
                                    if let Some(v3) = sp.as_table_mut().and_then(|t| t.get_mut("segments")) {
                                        f.push((format!("line.conductors[{i}].section.spans[{k}].segments"), v3));
                                    }
                                }
                            }
                            _ => {}
                        }
                    }
                }
                ("dropper", Value::Table(d)) => {
                    if let Some(v2) = d.get_mut("segments") {
                        f.push((format!("line.conductors[{i}].dropper.segments"), v2));
                    }
                }
                _ => {}
            }
        }
    }
    f
}

/// The levels of the line file `path` (coarse to fine), planned, with the finest level's work checked
/// against the budget. The finest level writes to `out`, the others to `out/levels/<k>_<label>`.
pub fn plan_line(path: &Path, out: Option<&Path>, o: &Options) -> Result<Vec<PlannedLine>, StudyError> {
    let text = scenario::read_text(path)?;
    plan_line_text(&text, &path.display().to_string(), out, o)
}

/// [`plan_line`] of the line scenario `text`, named `file` in messages (a sweep's case).
pub fn plan_line_text(text: &str, file: &str, out: Option<&Path>, o: &Options) -> Result<Vec<PlannedLine>, StudyError> {
    let file = file.to_string();
    // the file as written must be a valid line first (its own messages, line numbers of its own text)
    scenario::line::parse(text, &file).and_then(|s| scenario::line::plan(&s, &file))?;
    let doc: Table = scenario::from_toml(text, &file)?;
    let (levels, ratio) = (o.levels, o.ratio);
    if levels < 3 || ratio < 2 {
        return Err(LevelError::Shape { levels, ratio }.into());
    }
    let top = ratio.checked_pow(levels as u32 - 1).ok_or(LevelError::Shape { levels, ratio })?;
    let mut probe = doc.clone();
    if o.coarsen && o.refine == Refine::Grid {
        for (field, v) in grid_fields(&mut probe) {
            let n = v.as_integer().unwrap_or(0).max(0) as usize;
            if !n.is_multiple_of(top) || n / top < 2 {
                return Err(LevelError::Indivisible { file, field, value: n, divisor: top }.into());
            }
        }
    }
    let defaults = NumericsSpec::default();
    let n = levels;
    let mut planned = Vec::with_capacity(n);
    for k in 0..n {
        let power = if o.coarsen { k as i32 - (n as i32 - 1) } else { k as i32 };
        let factor = (ratio as f64).powi(power);
        let mut d = doc.clone();
        let scale = |x: i64| {
            if power >= 0 { x * ratio.pow(power as u32) as i64 } else { x / ratio.pow((-power) as u32) as i64 }
        };
        let numerics = |d: &mut Table, key: &str, default: f64, f: f64| {
            let t = d.entry("numerics").or_insert(Value::Table(Table::new()));
            if let Value::Table(t) = t {
                let x = t.get(key).and_then(|v| v.as_float().or(v.as_integer().map(|i| i as f64))).unwrap_or(default);
                t.insert(key.into(), Value::Float(x / f));
            }
        };
        match o.refine {
            Refine::Grid => {
                for (_, v) in grid_fields(&mut d) {
                    if let Some(x) = v.as_integer() {
                        *v = Value::Integer(scale(x));
                    }
                }
                if o.scaled_smoothing {
                    numerics(&mut d, "smoothing", defaults.smoothing, factor);
                }
            }
            Refine::Step => {
                numerics(&mut d, "courant", defaults.courant, factor);
                numerics(&mut d, "smoothing", defaults.smoothing, factor);
            }
        }
        let lbl = label(factor);
        let invalid = |source: InputError| LevelError::Invalid {
            label: lbl.clone(),
            what: match o.refine {
                Refine::Grid => format!("segments times {}", lbl.trim_start_matches('x')),
                Refine::Step => format!("step divided by {}", factor),
            },
            source,
        };
        let level_text = toml::to_string(&d).map_err(|e| {
            invalid(InputError::Parse { file: file.clone(), message: format!("the refined document: {e}") })
        })?;
        let plan =
            scenario::line::parse(&level_text, &file).and_then(|s| scenario::line::plan(&s, &file)).map_err(invalid)?;
        let estimate = LineWorkEstimate::of(&plan);
        let out_dir = super::level_dir(out, k, n, &lbl);
        planned.push(PlannedLine { label: lbl, factor, plan, estimate, out_dir });
    }
    super::check_budget(file, o, &planned.iter().map(PlannedLine::work).collect::<Vec<_>>())?;
    Ok(planned)
}

/// Run the planned levels of a line in order (coarse to fine), `before(k, planned)` called before each.
pub fn run_line_levels(
    path: &Path,
    planned: Vec<PlannedLine>,
    mut before: impl FnMut(usize, &PlannedLine),
) -> Result<(Vec<LevelRun>, LineSummary), StudyError> {
    let file = path.display().to_string();
    let mut runs = Vec::with_capacity(planned.len());
    let mut last = None;
    for (k, p) in planned.into_iter().enumerate() {
        before(k, &p);
        let dir = p.out_dir.as_ref().map_or("(no files written)".to_string(), |d| d.display().to_string());
        let node_steps = p.estimate.node_steps;
        let nodes = p.estimate.nodes;
        let start = Instant::now();
        let outcome = run_line(p.plan, p.out_dir.as_deref()).map_err(|e| match e {
            LineRunError::Unstable { instability, .. } => StudyError::Unstable {
                file: file.clone(),
                label: p.label.clone(),
                message: instability.to_string(),
                dir: dir.clone(),
            },
            e => StudyError::Run { file: file.clone(), label: p.label.clone(), message: e.to_string() },
        })?;
        let wall = start.elapsed().as_secs_f64();
        let s = outcome.summary;
        let value = serde_json::to_value(&s).map_err(|e| StudyError::Run {
            file: file.clone(),
            label: p.label.clone(),
            message: format!("summary: {e}"),
        })?;
        runs.push(LevelRun {
            label: p.label,
            factor: p.factor,
            h_relative: 1.0 / p.factor,
            // the line's nodes (all conductors), for the segments of a single conductor
            segments: nodes,
            dt_s: s.dt_s,
            steps: s.steps,
            node_steps_estimate: node_steps,
            wall_time_s: wall,
            out_dir: dir,
            phases: 0,
            scalars: flatten::scalars(&value),
        });
        last = Some(s);
    }
    Ok((runs, last.expect("at least three levels")))
}
