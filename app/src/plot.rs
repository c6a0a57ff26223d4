//! Comparison plots to PNG and SVG, drawn by plotters with the font bundled in `assets/fonts` (the
//! `ab_glyph` backend), so the same figure renders on any machine without a display or system fonts.
//!
//! A [`Chart`] is one panel: labelled axes (quantity and unit), any number of [`Series`] (the computed
//! curve, the analytic or reference curve beside it, markers for paper values), linear or logarithmic
//! axes. [`render`] writes `stem.png` and `stem.svg` with one or more panels on a grid.

use std::path::Path;
use std::sync::Once;

use plotters::coord::Shift;
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::prelude::*;

static FONT: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");
static REGISTER: Once = Once::new();

fn register_font() {
    REGISTER.call_once(|| {
        // The bundled font is a valid TrueType file; failure here is a packaging bug.
        plotters::style::register_font("sans-serif", FontStyle::Normal, FONT)
            .unwrap_or_else(|_| panic!("bundled font assets/fonts/DejaVuSans.ttf is not a valid font"));
    });
}

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Style {
    /// solid line (computed results)
    Line,
    /// dashed line (analytic or reference solutions)
    Dashed,
    /// markers only (paper values, sampled points)
    Markers,
    /// solid line with markers (convergence data)
    LineMarkers,
}

/// One curve.
#[derive(Clone, Debug)]
pub struct Series {
    /// legend text
    pub label: String,
    /// the points `(x, y)`
    pub points: Vec<(f64, f64)>,
    /// how it is drawn
    pub style: Style,
    /// palette index (colours repeat after 8)
    pub color: usize,
}

impl Series {
    /// A series with the given label, points, style and palette colour.
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>, style: Style, color: usize) -> Self {
        Series { label: label.into(), points, style, color }
    }
}

/// One panel.
#[derive(Clone, Debug, Default)]
pub struct Chart {
    /// caption above the panel
    pub title: String,
    /// x-axis label: quantity and unit
    pub x_label: String,
    /// y-axis label: quantity and unit
    pub y_label: String,
    /// the curves
    pub series: Vec<Series>,
    /// logarithmic x axis
    pub log_x: bool,
    /// logarithmic y axis
    pub log_y: bool,
    /// fixed x range (default: the data's, with a margin)
    pub x_range: Option<(f64, f64)>,
    /// fixed y range (default: the data's, with a margin)
    pub y_range: Option<(f64, f64)>,
}

/// Plot failure.
#[derive(Debug, thiserror::Error)]
#[error("cannot draw {path}: {message}")]
pub struct PlotError {
    /// the file
    pub path: String,
    /// what the backend said
    pub message: String,
}

const PALETTE: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
];

fn data_range(values: impl Iterator<Item = f64>, log: bool) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values.filter(|v| v.is_finite() && (!log || *v > 0.0)) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !lo.is_finite() {
        return if log { (0.1, 10.0) } else { (-1.0, 1.0) };
    }
    if log {
        (lo / 1.5, hi * 1.5)
    } else if hi - lo <= f64::EPSILON * hi.abs().max(1.0) {
        let m = hi.abs().max(1.0) * 0.05;
        (lo - m, hi + m)
    } else {
        let m = 0.05 * (hi - lo);
        (lo - m, hi + m)
    }
}

/// Render `panels` on a grid with `cols` columns, `panel_size` pixels each, to `stem.png` and
/// `stem.svg` (the parent directory is created).
pub fn render(panels: &[Chart], cols: usize, panel_size: (u32, u32), stem: &Path) -> Result<(), PlotError> {
    register_font();
    if let Some(dir) = stem.parent() {
        std::fs::create_dir_all(dir)
            .map_err(|e| PlotError { path: dir.display().to_string(), message: e.to_string() })?;
    }
    let cols = cols.max(1);
    let rows = panels.len().div_ceil(cols);
    let size = (panel_size.0 * cols as u32, panel_size.1 * rows as u32);
    let png = stem.with_extension("png");
    let svg = stem.with_extension("svg");
    let err = |p: &Path| {
        let path = p.display().to_string();
        move |e: String| PlotError { path: path.clone(), message: e }
    };
    {
        let root = BitMapBackend::new(&png, size).into_drawing_area();
        draw_all(&root, panels, rows, cols).map_err(err(&png))?;
        root.present().map_err(|e| e.to_string()).map_err(err(&png))?;
    }
    {
        let root = SVGBackend::new(&svg, size).into_drawing_area();
        draw_all(&root, panels, rows, cols).map_err(err(&svg))?;
        root.present().map_err(|e| e.to_string()).map_err(err(&svg))?;
    }
    Ok(())
}

fn draw_all<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    panels: &[Chart],
    rows: usize,
    cols: usize,
) -> Result<(), String> {
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    let areas = root.split_evenly((rows, cols));
    for (chart, area) in panels.iter().zip(areas.iter()) {
        let xs = chart.series.iter().flat_map(|s| s.points.iter().map(|p| p.0));
        let ys = chart.series.iter().flat_map(|s| s.points.iter().map(|p| p.1));
        let xr = chart.x_range.unwrap_or_else(|| data_range(xs, chart.log_x));
        let yr = chart.y_range.unwrap_or_else(|| data_range(ys, chart.log_y));
        let legend = emptiest_corner(chart, xr, yr);
        match (chart.log_x, chart.log_y) {
            (false, false) => draw_panel(area, chart, xr.0..xr.1, yr.0..yr.1, legend),
            (true, false) => draw_panel(area, chart, (xr.0..xr.1).log_scale(), yr.0..yr.1, legend),
            (false, true) => draw_panel(area, chart, xr.0..xr.1, (yr.0..yr.1).log_scale(), legend),
            (true, true) => draw_panel(area, chart, (xr.0..xr.1).log_scale(), (yr.0..yr.1).log_scale(), legend),
        }?;
    }
    Ok(())
}

/// The corner of the plot area where the legend hides the fewest data: each corner box (45 % of the width,
/// 40 % of the height) is scored by the number of points and line crossings in it; ties keep the
/// conventional upper right.
fn emptiest_corner(chart: &Chart, xr: (f64, f64), yr: (f64, f64)) -> SeriesLabelPosition {
    let unit = |v: f64, (lo, hi): (f64, f64), log: bool| {
        if log { (v.ln() - lo.ln()) / (hi.ln() - lo.ln()) } else { (v - lo) / (hi - lo) }
    };
    // (position, x interval, y interval) in unit coordinates, y up.
    let corners = [
        (SeriesLabelPosition::UpperRight, (0.55, 1.0), (0.6, 1.0)),
        (SeriesLabelPosition::UpperLeft, (0.0, 0.45), (0.6, 1.0)),
        (SeriesLabelPosition::LowerRight, (0.55, 1.0), (0.0, 0.4)),
        (SeriesLabelPosition::LowerLeft, (0.0, 0.45), (0.0, 0.4)),
    ];
    let mut count = [0usize; 4];
    for s in &chart.series {
        // Sample each polyline densely enough that a line crossing a box counts even without a vertex in it.
        // Markers are points only: score each as a zero-length segment.
        let segments: Vec<&[(f64, f64)]> = if s.style == Style::Markers {
            s.points.chunks(1).collect()
        } else {
            s.points.windows(2).chain(s.points.last().map(std::slice::from_ref)).collect()
        };
        for w in segments {
            let (a, b) = (w[0], w[w.len() - 1]);
            let (ax, ay, bx, by) = (
                unit(a.0, xr, chart.log_x),
                unit(a.1, yr, chart.log_y),
                unit(b.0, xr, chart.log_x),
                unit(b.1, yr, chart.log_y),
            );
            let n = (((bx - ax).abs() + (by - ay).abs()) * 20.0).ceil().clamp(1.0, 200.0) as usize;
            for k in 0..n {
                let f = k as f64 / n as f64;
                let (x, y) = (ax + f * (bx - ax), ay + f * (by - ay));
                for (c, (_, (x0, x1), (y0, y1))) in corners.iter().enumerate() {
                    if x >= *x0 && x <= *x1 && y >= *y0 && y <= *y1 {
                        count[c] += 1;
                    }
                }
            }
        }
    }
    let best = (0..4).min_by_key(|&c| count[c]).unwrap_or(0);
    corners[best].0.clone()
}

/// Tick label: plain for moderate magnitudes, scientific otherwise, no trailing zeros.
fn tick(v: f64) -> String {
    let a = v.abs();
    // Rounding residue of a tick at zero (e.g. -2.2e-16) prints as 0.
    if a < 1.0e-12 {
        "0".into()
    } else if !(1.0e-3..1.0e5).contains(&a) {
        let s = format!("{v:.2e}");
        match s.split_once('e') {
            Some((m, e)) => format!("{}e{e}", m.trim_end_matches('0').trim_end_matches('.')),
            None => s,
        }
    } else {
        let s = format!("{v:.4}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    }
}

fn draw_panel<DB, X, Y>(
    area: &DrawingArea<DB, Shift>,
    chart: &Chart,
    x: X,
    y: Y,
    legend: SeriesLabelPosition,
) -> Result<(), String>
where
    DB: DrawingBackend,
    X: AsRangedCoord<Value = f64>,
    Y: AsRangedCoord<Value = f64>,
    X::CoordDescType: ValueFormatter<f64>,
    Y::CoordDescType: ValueFormatter<f64>,
{
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let mut cc = ChartBuilder::on(area)
        .caption(&chart.title, ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(42)
        .y_label_area_size(72)
        .build_cartesian_2d(x, y)
        .map_err(e)?;
    cc.configure_mesh()
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| tick(*v))
        .x_desc(chart.x_label.as_str())
        .y_desc(chart.y_label.as_str())
        .label_style(("sans-serif", 13))
        .axis_desc_style(("sans-serif", 15))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(e)?;
    for s in &chart.series {
        let c = PALETTE[s.color % PALETTE.len()];
        let pts = s.points.iter().copied().filter(|p| p.0.is_finite() && p.1.is_finite());
        let legend_style = c.stroke_width(2);
        let anno = match s.style {
            Style::Line => cc.draw_series(LineSeries::new(pts, c.stroke_width(2))).map_err(e)?,
            Style::Dashed => cc.draw_series(DashedLineSeries::new(pts, 8, 5, c.stroke_width(2))).map_err(e)?,
            Style::Markers => cc.draw_series(pts.map(|p| Circle::new(p, 4, c.filled()))).map_err(e)?,
            Style::LineMarkers => {
                let v: Vec<_> = pts.collect();
                cc.draw_series(v.iter().map(|&p| Circle::new(p, 3, c.filled()))).map_err(e)?;
                cc.draw_series(LineSeries::new(v, c.stroke_width(2))).map_err(e)?
            }
        };
        if !s.label.is_empty() {
            anno.label(s.label.as_str())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], legend_style));
        }
    }
    if chart.series.iter().any(|s| !s.label.is_empty()) {
        cc.configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 13))
            .position(legend)
            .draw()
            .map_err(e)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn renders_png_and_svg_with_the_bundled_font() {
        let dir = std::env::temp_dir().join(format!("ohl-plot-{}", std::process::id()));
        let stem = dir.join("demo");
        let line: Vec<(f64, f64)> = (0..50).map(|i| (i as f64 * 0.1, (i as f64 * 0.1).sin())).collect();
        let conv: Vec<(f64, f64)> = [25.0, 50.0, 100.0].iter().map(|&n| (n, 1.0 / (n * n))).collect();
        let a = Chart {
            title: "sine".into(),
            x_label: "t [s]".into(),
            y_label: "x3 [m]".into(),
            series: vec![
                Series::new("computed", line.clone(), Style::Line, 0),
                Series::new("exact", line, Style::Dashed, 1),
            ],
            ..Default::default()
        };
        let b = Chart {
            title: "convergence".into(),
            x_label: "N".into(),
            y_label: "error".into(),
            series: vec![Series::new("error", conv, Style::LineMarkers, 2)],
            log_x: true,
            log_y: true,
            ..Default::default()
        };
        render(&[a, b], 2, (500, 350), &stem).expect("render");
        let png = std::fs::read(stem.with_extension("png")).unwrap();
        assert_eq!(&png[1..4], b"PNG");
        let svg = std::fs::read_to_string(stem.with_extension("svg")).unwrap();
        assert!(svg.contains("<svg") && svg.contains("convergence") && svg.contains("x3 [m]"));
    }
}
