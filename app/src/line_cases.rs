//! Line cases of `cases/` (a scenario with `[line]`: several conductors on shared towers,
//! [`ohl::scenario::line`]): run into `figures/cases/<case>/` (`summary.json`, `clearances.csv`,
//! `towers.csv`, `conductors/NAME/`), with a figure and a table drawn from the files the run wrote:
//!
//! - `<case>_line.png/.svg`: the least distance between every pair of phases, earth wires and bundles
//!   against time; each tower's horizontal and vertical load; each conductor's mid-span point (the middle
//!   of its unstretched length) in the plane across the line, as a path from its start, and its height
//!   against time; each conductor's largest tension against time;
//! - the printed table (and `<case>_table.md`): per pair the least distance, when and where (fractions of each conductor's
//!   length), per conductor the peak tension, per tower the peak load, per kind of attachment the largest
//!   force.

use std::path::{Path, PathBuf};

use ohl::run::line::{LineSummary, run_line};
use ohl::scenario::{self, line as line_scenario};

use crate::cases::{CaseError, read_columns};
use crate::plot::{Chart, Series, Style, render_titled};

/// What a line case produced.
#[derive(Clone, Debug)]
pub struct LineCaseOutcome {
    /// case name
    pub name: String,
    /// the run's summary (also in `summary.json`)
    pub summary: LineSummary,
    /// where the files are
    pub dir: PathBuf,
}

/// Whether the case file `path` is a line scenario.
pub fn is_line_case(path: &Path) -> bool {
    std::fs::read_to_string(path).is_ok_and(|t| line_scenario::is_line(&t))
}

/// Run the line case file `path` into `<out>/<case>/` and draw its figure.
pub fn run_line_case(path: &Path, out: &Path) -> Result<LineCaseOutcome, CaseError> {
    let name = path.file_stem().and_then(|s| s.to_str()).unwrap_or("case").to_string();
    let file = path.display().to_string();
    let text = scenario::read_text(path)?;
    let sc = line_scenario::parse(&text, &file)?;
    let plan = line_scenario::plan(&sc, &file)?;
    // The chord point each conductor's mid-span displacement is measured from (its own first and last node).
    let mids: Vec<[f64; 3]> =
        plan.plans.iter().map(|p| ohl::output::ProbePoint::new("mid", 0.5, p.solver.wire()).reference_m()).collect();
    let dir = out.join(&name);
    let o = run_line(plan, Some(&dir)).map_err(Box::new)?;
    let heading = format!("{name}: {}", sc.description.clone().unwrap_or_default());
    draw(&name, &heading, &dir, &o.summary, &mids)?;
    let outcome = LineCaseOutcome { name, summary: o.summary, dir };
    // The table, without the line that names the machine's speed and the output folder.
    let table: String = format_line_table(&outcome).lines().skip(1).map(|l| format!("{l}\n")).collect();
    let path = outcome.dir.join(format!("{}_table.md", outcome.name));
    std::fs::write(&path, table).map_err(|e| CaseError::Io(format!("{}: {e}", path.display())))?;
    Ok(outcome)
}

fn draw(name: &str, heading: &str, dir: &Path, s: &LineSummary, mids: &[[f64; 3]]) -> Result<(), CaseError> {
    let cl = read_columns(&dir.join("clearances.csv"))?;
    let tw = read_columns(&dir.join("towers.csv"))?;
    let t = cl.get("t_s").cloned().unwrap_or_default();
    let tt = tw.get("t_s").cloned().unwrap_or_default();
    let slug = ohl::run::line::slug;
    let pairs: Vec<Series> = s
        .clearances
        .iter()
        .enumerate()
        .map(|(k, c)| {
            let col = format!("clearance_{}_{}_m", slug(&c.between[0]), slug(&c.between[1]));
            let y = cl.get(&col).cloned().unwrap_or_default();
            Series::new(
                format!("{} - {}", c.between[0], c.between[1]),
                t.iter().copied().zip(y).collect(),
                Style::Line,
                k,
            )
        })
        .collect();
    let mut charts = Vec::new();
    if !pairs.is_empty() {
        charts.push(Chart {
            title: "Least distance between each pair (sampled; the least of every step in the table)".into(),
            x_label: "time t [s]".into(),
            y_label: "least distance [m]".into(),
            series: pairs,
            ..Default::default()
        });
    }
    let tower_series = |q: &str, scale: f64, label: &str| -> Vec<Series> {
        s.towers
            .iter()
            .enumerate()
            .filter_map(|(k, tower)| {
                let y = tw.get(&format!("{}_{q}", slug(&tower.name)))?;
                let pts = tt.iter().copied().zip(y.iter().map(|v| v * scale)).collect();
                Some(Series::new(format!("{} {label}", tower.name), pts, Style::Line, k))
            })
            .collect()
    };
    let mut horizontal = tower_series("f1_n", 1e-3, "across f1");
    horizontal.extend(tower_series("f2_n", 1e-3, "along f2").into_iter().map(|mut x| {
        x.style = Style::Dashed;
        x
    }));
    if !horizontal.is_empty() {
        charts.push(Chart {
            title: "Horizontal load of all attachments on each tower".into(),
            x_label: "time t [s]".into(),
            y_label: "force [kN]".into(),
            series: horizontal,
            ..Default::default()
        });
        charts.push(Chart {
            title: "Vertical load of all attachments on each tower".into(),
            x_label: "time t [s]".into(),
            y_label: "vertical force f3 [kN]".into(),
            series: tower_series("f3_n", 1e-3, "f3"),
            ..Default::default()
        });
    }
    // Each conductor's middle point: its path across the line, and its height against time; its tension.
    let (mut paths, mut heights, mut tensions) = (Vec::new(), Vec::new(), Vec::new());
    for (k, c) in s.conductors.iter().enumerate() {
        let ts = read_columns(&dir.join("conductors").join(slug(&c.name)).join("timeseries.csv"))?;
        let (ct, d1, d3) = (ts.get("t_s"), ts.get("mid_dx1_m"), ts.get("mid_dx3_m"));
        if let (Some(ct), Some(d1), Some(d3)) = (ct, d1, d3) {
            let m = mids[k];
            paths.push(Series::new(
                c.name.clone(),
                d1.iter().zip(d3).map(|(a, b)| (m[0] + a, m[2] + b)).collect(),
                Style::Line,
                k,
            ));
            heights.push(Series::new(
                c.name.clone(),
                ct.iter().zip(d3).map(|(a, b)| (*a, m[2] + b)).collect(),
                Style::Line,
                k,
            ));
        }
        if let (Some(ct), Some(tn)) = (ts.get("t_s"), ts.get("max_tension_n")) {
            tensions.push(Series::new(
                c.name.clone(),
                ct.iter().zip(tn).map(|(a, b)| (*a, b * 1e-3)).collect(),
                Style::Line,
                k,
            ));
        }
    }
    charts.push(Chart {
        title: "Middle of each conductor, seen along the line".into(),
        x_label: "across the line x1 [m]".into(),
        y_label: "height x3 [m]".into(),
        series: paths,
        ..Default::default()
    });
    charts.push(Chart {
        title: "Height of the middle of each conductor".into(),
        x_label: "time t [s]".into(),
        y_label: "height x3 [m]".into(),
        series: heights,
        ..Default::default()
    });
    charts.push(Chart {
        title: "Largest tension in each conductor".into(),
        x_label: "time t [s]".into(),
        y_label: "largest segment tension [kN]".into(),
        series: tensions,
        ..Default::default()
    });
    let plot_err = |e: crate::plot::PlotError| CaseError::Io(e.to_string());
    render_titled(&charts, 2, (680, 440), heading, &dir.join(format!("{name}_line"))).map_err(plot_err)
}

/// The table of a line case, as markdown.
pub fn format_line_table(c: &LineCaseOutcome) -> String {
    let s = &c.summary;
    let mut out = format!(
        "== {}: {} at t = {:.2} s, time loop {:.2} s ({:.3e} node-steps/s); files in {}\n",
        c.name,
        s.status,
        s.final_time_s,
        s.wall_time_s,
        s.node_steps_per_second,
        c.dir.display()
    );
    if !s.clearances.is_empty() {
        out.push_str("| pair | initial [m] | least [m] | at [s] | where (fractions of length) | final [m] |\n|---|---|---|---|---|---|\n");
        // A distance, or a dash where none was left to measure (a conductor broken in every segment).
        let metres = |x: Option<f64>| x.map_or_else(|| "-".to_string(), |x| format!("{x:.3}"));
        for p in &s.clearances {
            out.push_str(&format!(
                "| {} - {} | {} | {:.3} | {:.3} | {} {:.3}, {} {:.3} | {} |\n",
                p.between[0],
                p.between[1],
                metres(p.initial_m),
                p.least_m,
                p.time_s,
                p.conductors[0],
                p.at_fraction[0],
                p.conductors[1],
                p.at_fraction[1],
                metres(p.final_m)
            ));
        }
    }
    out.push_str(
        "| conductor | peak tension [kN] | at [s] | final [kN] | peak mid-span dx3 [m] |\n|---|---|---|---|---|\n",
    );
    for k in &s.conductors {
        out.push_str(&format!(
            "| {} | {:.2} | {:.3} | {:.2} | {:.3} |\n",
            k.name,
            k.peak_max_tension_n / 1e3,
            k.peak_max_tension_time_s,
            k.final_max_tension_n / 1e3,
            k.peak_midspan_displacement_m[2].value_m
        ));
    }
    out.push_str("| tower | peak load [kN] | at [s] | final f1, f2, f3 [kN] |\n|---|---|---|---|\n");
    for t in &s.towers {
        let f = t.final_force_n;
        out.push_str(&format!(
            "| {} | {:.2} | {:.3} | {:.2}, {:.2}, {:.2} |\n",
            t.name,
            t.peak_force_magnitude_n / 1e3,
            t.peak_force_time_s,
            f[0] / 1e3,
            f[1] / 1e3,
            f[2] / 1e3
        ));
    }
    for a in &s.attachments {
        out.push_str(&format!(
            "{} x {}: largest tension {:.2} kN at {:.3} s ({} - {})\n",
            a.count,
            a.kind,
            a.peak_tension_n / 1e3,
            a.time_s,
            a.ends[0],
            a.ends[1]
        ));
    }
    out
}
