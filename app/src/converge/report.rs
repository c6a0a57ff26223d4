//! The study's table on stdout and `convergence.json`.
//!
//! The table has one row per quantity that is not constant (or zero to rounding) across the levels and is not a phase's copy
//! of a run peak (`phases[...]`, which `convergence.json` keeps): the quantity's path, its value on each
//! level (coarse to fine), the observed order `p`, the Richardson extrapolate, the fine-level GCI in
//! percent of the finest value, and the verdict. An oscillatory, divergent or indeterminate quantity has
//! no extrapolate and no GCI (`-`): it is no number with an error bar; nor is a peak whose time does not
//! converge (its extrapolate and GCI stay in `convergence.json`, its verdict says the peak moves).

use std::io::Write as _;
use std::path::Path;

use super::{LevelRun, Options, Quantity};

/// Everything `convergence.json` holds.
#[derive(serde::Serialize)]
pub struct Study<'a> {
    /// the scenario file
    pub scenario: String,
    /// the scenario's name
    pub name: String,
    /// how the study was made
    pub options: &'a Options,
    /// Roache's factor of safety of the GCI [-]
    pub safety_factor: f64,
    /// the levels, coarse to fine
    pub levels: &'a [LevelRun],
    /// wall time of the study over that of the scenario as written [-]
    pub cost_relative_to_one_run: f64,
    /// every quantity
    pub quantities: &'a [Quantity],
}

impl<'a> Study<'a> {
    /// The study of `scenario` (its file, named `name`) made with `options` on `levels`, giving
    /// `quantities`; the factor of safety is that of three grids.
    pub fn new(
        scenario: &str,
        name: &str,
        options: &'a Options,
        levels: &'a [LevelRun],
        quantities: &'a [Quantity],
    ) -> Self {
        Study {
            scenario: scenario.to_string(),
            name: name.to_string(),
            options,
            safety_factor: ohl::verify::gci::SAFETY_FACTOR_THREE_GRIDS,
            levels,
            cost_relative_to_one_run: cost(levels),
            quantities,
        }
    }
}

/// Wall time of all levels over that of the level as written (NaN without it).
pub fn cost(levels: &[LevelRun]) -> f64 {
    let total: f64 = levels.iter().map(|l| l.wall_time_s).sum();
    levels.iter().find(|l| l.factor == 1.0).map_or(f64::NAN, |l| total / l.wall_time_s)
}

/// Write `convergence.json` into `dir` (whole or not at all: a temporary file renamed).
pub fn write_json(dir: &Path, study: &Study) -> std::io::Result<()> {
    let text = serde_json::to_string_pretty(study).map_err(std::io::Error::other)?;
    std::fs::create_dir_all(dir)?;
    let tmp = dir.join("convergence.json.tmp");
    {
        let mut f = std::fs::File::create(&tmp)?;
        f.write_all(text.as_bytes())?;
        f.write_all(b"\n")?;
    }
    std::fs::rename(tmp, dir.join("convergence.json"))
}

/// A number in 7 significant digits, or `-`.
fn num(x: Option<f64>) -> String {
    match x {
        None => "-".into(),
        Some(0.0) => "0".into(),
        Some(v) if (1e-3..1e7).contains(&v.abs()) => {
            let digits = (6 - v.abs().log10().floor() as i32).clamp(0, 9) as usize;
            format!("{v:.digits$}")
        }
        Some(v) => format!("{v:.6e}"),
    }
}

/// Whether a quantity goes into the printed table (module doc).
pub fn printed(q: &Quantity) -> bool {
    !q.path.starts_with("phases[") && !matches!(q.verdict, "constant" | "constant to rounding" | "zero to rounding")
}

/// The table's lines.
pub fn table(study: &Study) -> Vec<String> {
    let levels = study.levels;
    let width = study.quantities.iter().filter(|q| printed(q)).map(|q| q.path.len()).max().unwrap_or(8).max(8);
    let mut lines = Vec::new();
    let heads: Vec<String> = levels.iter().map(|l| format!("{:>14}", l.label)).collect();
    lines.push(format!(
        "{:<width$} {} {:>7} {:>14} {:>9}  verdict (rtol {})",
        "quantity",
        heads.join(" "),
        "p",
        "extrapolate",
        "GCI [%]",
        study.options.rtol
    ));
    for q in study.quantities.iter().filter(|q| printed(q)) {
        let vals: Vec<String> = q.values.iter().map(|v| format!("{:>14}", num(*v))).collect();
        let e = q.estimate.as_ref();
        let shows_band = e.is_some_and(|e| e.extrapolate.is_some()) && q.verdict != super::PEAK_MOVES;
        let p = e.and_then(|e| e.order).map_or("-".into(), |p| format!("{p:.3}"));
        let ext = if shows_band { num(e.and_then(|e| e.extrapolate)) } else { "-".into() };
        let g = e.and_then(|e| e.gci_fine).filter(|_| shows_band).map_or("-".into(), |g| format!("{:.3}", 100.0 * g));
        lines.push(format!("{:<width$} {} {:>7} {:>14} {:>9}  {}", q.path, vals.join(" "), p, ext, g, q.verdict));
    }
    lines
}
