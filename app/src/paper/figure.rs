//! The figure of a case and the CSV it is drawn from.
//!
//! Panel kinds (generic, chosen in the case file; see [`crate::paper::spec::PanelKind`]): the history
//! of a mid-span component in the paper's dimensionless units (displacement / l against `tau = t U /
//! l`; the axis labels give the conversion to metres and seconds), a mid-span trajectory, the shapes at
//! the snapshot times, tension histories and the mean temperature. The paper's values are drawn as
//! markers at the time the paper prints them, the independent reference as a dashed line beside the
//! computed curve. A panel whose legend would list more than [`LEGEND_MAX`] entries (one reference and
//! one paper value per stage of a case: own weight, iced, ...) draws its references in one colour under
//! one legend entry, and the paper's values likewise: each stands at the time it belongs to, so the
//! legend needs to say only what they are.

use std::io::Write;
use std::path::Path;

use super::extract::Series as Columns;
use super::table::Row;
use crate::paper::spec::{ExtractKind, PanelKind, PanelSpec, PaperSpec, ReferenceKind, UnitSpec};
use crate::plot::{Chart, PlotError, Series, Style, TopAxis, render_titled};
use ohl::run::Outcome;
use ohl::scenario::Plan;

/// Time axis of a panel: physical time `t` [s] along the bottom and, for panels in the paper's units, its
/// dimensionless time `tau = t U / l` along the top.
fn time_axis(plan: &Plan, unit: UnitSpec) -> Option<TopAxis> {
    match unit {
        UnitSpec::S => None,
        _ => Some(TopAxis { label: "tau = t U / l [-]".into(), scale: plan.tau_speed_m_per_s / plan.chord_m }),
    }
}

fn in_window(t: f64, w: Option<[f64; 2]>) -> bool {
    w.is_none_or(|[a, b]| t >= a - 1e-9 && t <= b + 1e-9)
}

/// The unit of the temperature panels: its axis label and the conversion from kelvin.
const TEMPERATURE_UNIT: (&str, fn(f64) -> f64) =
    ("mean temperature [C]", |k| k - ohl::scenario::temperature::ZERO_CELSIUS_K);

/// What a reference is, for a legend.
fn describe(r: ReferenceKind) -> &'static str {
    match r {
        ReferenceKind::ExactArc => "exact arc",
        ReferenceKind::PaperArc => "paper's arc (4.1)",
        ReferenceKind::ExactCatenary => "exact catenary",
        ReferenceKind::ExactCatenaryWithWind => "exact catenary with wind",
        ReferenceKind::PaperParabola => "paper's parabola (4.3)-(4.4)",
        ReferenceKind::ThermalStrain => "thermal strain (5.5)",
        ReferenceKind::ThermalForce => "thermal force (5.6)",
    }
}

/// Most legend entries of a panel before its references (and paper values) share one entry.
const LEGEND_MAX: usize = 4;

/// A panel of more than [`LEGEND_MAX`] legend entries whose references are one kind of reference at
/// successive stages (the same `kind_of` each, on time ranges that do not overlap) draws them in one
/// colour (the first one's) under one legend entry, and its paper values likewise. `kind_of` gives the
/// kind of reference of a reference series' label.
fn group_legend(chart: &mut Chart, kind_of: impl Fn(&str) -> Option<ReferenceKind>, section: &str) {
    if chart.series.iter().filter(|s| !s.label.is_empty()).count() <= LEGEND_MAX {
        return;
    }
    let members = |chart: &Chart, prefix: &str, style: Style| -> Vec<usize> {
        (0..chart.series.len())
            .filter(|&i| chart.series[i].style == style && chart.series[i].label.starts_with(prefix))
            .collect()
    };
    let refs = members(chart, "reference: ", Style::Dashed);
    let kinds: Vec<Option<ReferenceKind>> = refs.iter().map(|&i| kind_of(&chart.series[i].label)).collect();
    let Some(Some(kind)) = kinds.first().copied() else { return };
    let mut spans: Vec<(f64, f64)> = refs
        .iter()
        .map(|&i| {
            chart.series[i].points.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.0), b.max(p.0)))
        })
        .collect();
    spans.sort_by(|a, b| a.0.total_cmp(&b.0));
    let stages = spans.windows(2).all(|w| w[0].1 <= w[1].0 + 1e-9);
    if refs.len() < 2 || !stages || kinds.iter().any(|k| *k != Some(kind)) {
        return;
    }
    let paper = members(chart, "paper: ", Style::Markers);
    let groups = [
        (refs, format!("reference: {} at each stage", describe(kind))),
        (paper, format!("paper (section {section}): its values at their times")),
    ];
    for (idx, label) in groups {
        if idx.len() < 2 {
            continue;
        }
        let color = chart.series[idx[0]].color;
        for (n, &i) in idx.iter().enumerate() {
            chart.series[i].color = color;
            chart.series[i].label = if n == 0 { label.clone() } else { String::new() };
        }
    }
}

/// Build the panels of a case.
pub fn charts(spec: &PaperSpec, plan: &Plan, o: &Outcome, cols: &Columns, rows: &[Row]) -> Vec<Chart> {
    let l = spec.length_scale_m;
    let mut out = Vec::new();
    for p in &spec.panels {
        let mut c = chart(p, spec, plan, o, cols, rows, l);
        let kind_of = |label: &str| {
            spec.checks.iter().find(|ch| label == format!("reference: {}", ch.quantity)).and_then(|ch| ch.reference)
        };
        group_legend(&mut c, kind_of, &spec.section);
        out.push(c);
    }
    out
}

fn chart(p: &PanelSpec, spec: &PaperSpec, plan: &Plan, o: &Outcome, c: &Columns, rows: &[Row], l: f64) -> Chart {
    // Time axes are in seconds (`tf = 1`); the paper's tau is the top axis.
    let tf = 1.0;
    let top_axis = time_axis(plan, p.time_unit.unwrap_or(UnitSpec::Tau));
    let idx: Vec<usize> = (0..c.t.len()).filter(|&i| in_window(c.t[i], p.window_s)).collect();
    let mut chart = Chart { x_label: "t [s]".into(), ..Default::default() };
    if matches!(p.kind, PanelKind::Midspan | PanelKind::MaxTension | PanelKind::SupportTension | PanelKind::Temperature)
    {
        chart.top_axis = top_axis;
    }
    match p.kind {
        PanelKind::Midspan => {
            let comp = p.component.map_or(2, |c| c.index());
            let name = ["x1", "x2", "x3"][comp];
            chart.title = p.title.clone().unwrap_or_else(|| format!("mid-span {name}"));
            chart.y_label = format!("mid-span {name} / l [-]   ({name} [m] = {l} {name}/l)");
            let pts = idx.iter().map(|&i| (c.t[i] * tf, c.mid[comp][i] / l)).collect();
            chart.series.push(Series::new("computed", pts, Style::Line, 0));
            let (t0, t1) = (idx.first().map_or(0.0, |&i| c.t[i]) * tf, idx.last().map_or(0.0, |&i| c.t[i]) * tf);
            // Reference lines and paper markers of the rows on this component. Rows in metres are converted
            // to the panel's l units. A reference that belongs to a time `at_s` (an equilibrium between two
            // events) is drawn from the event before it (or the window's start) to that time.
            for (k, (r, ch)) in rows.iter().zip(&spec.checks).enumerate() {
                let to_span = match r.unit {
                    UnitSpec::Span => 1.0,
                    UnitSpec::M => 1.0 / l,
                    _ => continue,
                };
                if ch.extract.component.map(|c| c.index()) != Some(comp) {
                    continue;
                }
                if ch.extract.kind == ExtractKind::Midspan
                    && let Some(e) = r.exact
                {
                    let (a, b) = match ch.extract.at_s {
                        Some(at) => {
                            let start =
                                o.events.iter().map(|(te, _)| *te).filter(|&te| te < at).fold(t0 / tf, f64::max);
                            (start * tf, at * tf)
                        }
                        None => {
                            let start = o.events.iter().map(|(te, _)| *te).fold(t0 / tf, f64::max);
                            (start * tf, t1)
                        }
                    };
                    let label = format!("reference: {}", ch.quantity);
                    chart.series.push(Series::new(
                        label,
                        vec![(a, e * to_span), (b, e * to_span)],
                        Style::Dashed,
                        1 + k % 3,
                    ));
                }
                let paper_t = match (ch.paper_tau, ch.extract.at_s) {
                    (Some(tau), _) => Some(if tf == 1.0 { tau * plan.chord_m / plan.tau_speed_m_per_s } else { tau }),
                    (None, Some(at)) if ch.extract.kind == ExtractKind::Midspan => Some(at * tf),
                    _ => None,
                };
                if let (Some(tx), Some(pv)) = (paper_t, r.paper)
                    && tx >= t0 - 1e-9
                    && tx <= t1 + 1e-9
                {
                    chart.series.push(Series::new(
                        format!("paper: {}", ch.quantity),
                        vec![(tx, pv * to_span)],
                        Style::Markers,
                        4 + k % 3,
                    ));
                }
            }
        }
        PanelKind::Trajectory => {
            let [a, b] = p.plane.map_or([0, 2], |q| [q[0].index(), q[1].index()]);
            let (na, nb) = (["x1", "x2", "x3"][a], ["x1", "x2", "x3"][b]);
            chart.title = p.title.clone().unwrap_or_else(|| format!("mid-span trajectory in the {na}-{nb} plane"));
            chart.x_label = format!("mid-span {na} / l [-]   ({na} [m] = {l} {na}/l)");
            chart.y_label = format!("mid-span {nb} / l [-]");
            let pts = idx.iter().map(|&i| (c.mid[a][i] / l, c.mid[b][i] / l)).collect();
            chart.series.push(Series::new("computed", pts, Style::Line, 0));
        }
        PanelKind::Shapes => {
            let [a, b] = p.plane.map_or([1, 2], |q| [q[0].index(), q[1].index()]);
            let (na, nb) = (["x1", "x2", "x3"][a], ["x1", "x2", "x3"][b]);
            chart.title = p.title.clone().unwrap_or_else(|| format!("shapes in the {na}-{nb} plane"));
            chart.x_label = format!("{na} / l [-]   ({na} [m] = {l} {na}/l)");
            chart.y_label = format!("{nb} / l [-]");
            for (k, s) in o.shapes.iter().enumerate() {
                // Split the polyline at broken segments.
                let mut part: Vec<(f64, f64)> = Vec::new();
                let mut part_no = 0;
                for i in 0..s.x[0].len() {
                    part.push((s.x[a][i] / l, s.x[b][i] / l));
                    let cut = i + 1 == s.x[0].len() || s.intact[i] == 0.0;
                    if cut {
                        // One legend entry per snapshot: the parts of a broken wire share its colour.
                        let label = if part_no == 0 {
                            format!("t = {:.2} s (tau = {:.2})", s.t_s, s.tau)
                        } else {
                            String::new()
                        };
                        chart.series.push(Series::new(label, std::mem::take(&mut part), Style::Line, k));
                        part_no += 1;
                    }
                }
            }
            if let (Some(g), 2) = (&plan.ground, b) {
                let xs: Vec<f64> = o.shapes.iter().flat_map(|s| s.x[a].iter().map(|v| v / l)).collect();
                let (lo, hi) = xs.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(p, q), &v| (p.min(v), q.max(v)));
                if lo.is_finite() && g.profile_m.is_empty() {
                    chart.series.push(Series::new(
                        format!("ground, x3 = {} m", g.height_m),
                        vec![(lo, g.height_m / l), (hi, g.height_m / l)],
                        Style::Dashed,
                        7,
                    ));
                } else if lo.is_finite() && a == 1 {
                    // the terrain profile under the line, with its corners
                    let mut x2: Vec<f64> = vec![lo * l, hi * l];
                    x2.extend(g.profile_m.iter().map(|p| p[0]).filter(|&x| x > lo * l && x < hi * l));
                    x2.sort_by(f64::total_cmp);
                    let pts = x2.iter().map(|&x| (x / l, g.height_at(x) / l)).collect();
                    chart.series.push(Series::new("ground profile", pts, Style::Dashed, 7));
                }
            }
        }
        PanelKind::MaxTension | PanelKind::SupportTension => {
            let support = p.kind == PanelKind::SupportTension;
            chart.title = p.title.clone().unwrap_or_else(|| {
                if support { "tension at the supports".into() } else { "largest segment tension".into() }
            });
            chart.y_label = "tension [kN]".into();
            if support {
                for (side, name) in [(0, "left support"), (1, "right support")] {
                    let pts = idx.iter().map(|&i| (c.t[i] * tf, c.probes[i].support_tension_n[side] / 1e3)).collect();
                    chart.series.push(Series::new(name, pts, Style::Line, side));
                }
            } else {
                let pts = idx.iter().map(|&i| (c.t[i] * tf, c.max_tension[i] / 1e3)).collect();
                chart.series.push(Series::new("computed", pts, Style::Line, 0));
            }
            let kinds: &[ExtractKind] = if support {
                &[ExtractKind::SupportTension]
            } else {
                &[ExtractKind::MaxTension, ExtractKind::MaxTensionPeak]
            };
            let (t0, t1) = (idx.first().map_or(0.0, |&i| c.t[i]) * tf, idx.last().map_or(0.0, |&i| c.t[i]) * tf);
            for (k, (r, ch)) in rows.iter().zip(&spec.checks).enumerate() {
                if !kinds.contains(&ch.extract.kind) || r.unit != UnitSpec::Kn {
                    continue;
                }
                if let Some(e) = r.exact {
                    let te = ch.extract.at_s.map_or(t1, |t| t * tf);
                    let ts = ch.extract.at_s.map_or(t0, |t| (t * tf - 0.1 * (t1 - t0)).max(t0));
                    chart.series.push(Series::new(
                        format!("reference: {}", ch.quantity),
                        vec![(ts, e), (te, e)],
                        Style::Dashed,
                        1 + k % 3,
                    ));
                }
                if let (Some(tau), Some(pv)) = (ch.paper_tau, r.paper) {
                    let tx = if tf == 1.0 { tau * plan.chord_m / plan.tau_speed_m_per_s } else { tau };
                    chart.series.push(Series::new(
                        format!("paper: {}", ch.quantity),
                        vec![(tx, pv)],
                        Style::Markers,
                        4 + k % 3,
                    ));
                }
            }
        }
        PanelKind::Temperature => {
            chart.title = p.title.clone().unwrap_or_else(|| "mean wire temperature".into());
            let (label, convert) = TEMPERATURE_UNIT;
            chart.y_label = label.into();
            let pts = idx.iter().map(|&i| (c.t[i] * tf, convert(c.probes[i].mean_temperature_k))).collect();
            chart.series.push(Series::new("computed", pts, Style::Line, 0));
        }
    }
    chart
}

/// Render the case's figure under `heading` to `stem.png` and `stem.svg`.
pub fn draw(charts: &[Chart], heading: &str, stem: &Path) -> Result<(), PlotError> {
    let cols = if charts.len() >= 4 { 2 } else { charts.len().max(1) };
    render_titled(charts, cols, (680, 440), heading, stem)
}

/// Write the time series (`stem.csv`) and, if any, the shapes (`stem_shapes.csv`) the figure is drawn from.
pub fn write_csv(o: &Outcome, c: &Columns, plan: &Plan, l: f64, stem: &Path) -> std::io::Result<()> {
    let mut f = std::io::BufWriter::new(std::fs::File::create(stem.with_extension("csv"))?);
    writeln!(
        f,
        "t_s,tau,mid_dx1_m,mid_dx2_m,mid_dx3_m,mid_dx1_l,mid_dx2_l,mid_dx3_l,max_tension_n,\
         support_left_n,support_right_n,mean_temperature_k,wind_scale"
    )?;
    for i in 0..c.t.len() {
        let p = &c.probes[i];
        writeln!(
            f,
            "{},{},{},{},{},{},{},{},{},{},{},{},{}",
            c.t[i],
            plan.tau(c.t[i]),
            c.mid[0][i],
            c.mid[1][i],
            c.mid[2][i],
            c.mid[0][i] / l,
            c.mid[1][i] / l,
            c.mid[2][i] / l,
            c.max_tension[i],
            p.support_tension_n[0],
            p.support_tension_n[1],
            p.mean_temperature_k,
            p.wind_scale
        )?;
    }
    f.flush()?;
    if !o.shapes.is_empty() {
        let name = format!("{}_shapes.csv", stem.file_name().and_then(|s| s.to_str()).unwrap_or("case"));
        let mut f = std::io::BufWriter::new(std::fs::File::create(stem.with_file_name(name))?);
        writeln!(f, "t_s,tau,node,x1_m,x2_m,x3_m")?;
        for s in &o.shapes {
            for i in 0..s.x[0].len() {
                writeln!(f, "{},{},{},{},{},{}", s.t_s, s.tau, i, s.x[0][i], s.x[1][i], s.x[2][i])?;
            }
        }
        f.flush()?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn several_references_and_paper_values_share_one_legend_entry_each() {
        let seg = |a: f64| vec![(a, 1.0), (a + 1.0, 1.0)];
        let mut chart = Chart {
            series: vec![
                Series::new("computed", seg(0.0), Style::Line, 0),
                Series::new("reference: own weight", seg(0.0), Style::Dashed, 1),
                Series::new("paper: own weight", vec![(1.0, 1.0)], Style::Markers, 4),
                Series::new("reference: iced", seg(2.0), Style::Dashed, 2),
                Series::new("paper: iced", vec![(3.0, 1.0)], Style::Markers, 5),
                Series::new("reference: final", seg(4.0), Style::Dashed, 3),
            ],
            ..Default::default()
        };
        let catenary = |_: &str| Some(ReferenceKind::ExactCatenary);
        // References of unknown kind are kept apart.
        let mut unknown = chart.clone();
        group_legend(&mut unknown, |_| None, "5.6");
        assert_eq!(unknown.series[5].label, "reference: final");
        // Two kinds of reference (an exact one and the paper's formula) at one time are kept apart.
        let mut two = chart.clone();
        let arcs = |l: &str| Some(if l.ends_with("iced") { ReferenceKind::PaperArc } else { ReferenceKind::ExactArc });
        group_legend(&mut two, arcs, "5.6");
        assert_eq!(two.series[3].label, "reference: iced");
        // Overlapping references are not stages: kept apart.
        let mut overlapping = chart.clone();
        overlapping.series[3].points = seg(0.5);
        group_legend(&mut overlapping, catenary, "5.6");
        assert_eq!(overlapping.series[3].label, "reference: iced");
        assert_eq!(overlapping.series[2].label, "paper: own weight");
        group_legend(&mut chart, catenary, "5.6");
        let labels: Vec<&str> = chart.series.iter().map(|s| s.label.as_str()).filter(|l| !l.is_empty()).collect();
        assert_eq!(
            labels,
            ["computed", "reference: exact catenary at each stage", "paper (section 5.6): its values at their times"]
        );
        // One colour per group: the first member's.
        assert!(chart.series[1..].iter().filter(|s| s.style == Style::Dashed).all(|s| s.color == 1));
        assert!(chart.series.iter().filter(|s| s.style == Style::Markers).all(|s| s.color == 4));
        // A legend of at most LEGEND_MAX entries keeps them apart.
        let seg2 = seg(2.0);
        let mut few = Chart {
            series: vec![
                Series::new("computed", seg(0.0), Style::Line, 0),
                Series::new("reference: own weight", seg(0.0), Style::Dashed, 1),
                Series::new("reference: iced", seg2, Style::Dashed, 2),
                Series::new("paper: iced", vec![(3.0, 1.0)], Style::Markers, 5),
            ],
            ..Default::default()
        };
        group_legend(&mut few, catenary, "5.6");
        assert_eq!(few.series[2].label, "reference: iced");
        assert_eq!(few.series[3].label, "paper: iced");
    }
}
