//! Comparison plots to PNG and SVG in one shared style, drawn by plotters with the font bundled in
//! `assets/fonts`, so the same figure renders on any machine without a display or system fonts.
//!
//! A [`Chart`] is one panel: labelled axes (quantity and unit), any number of [`Series`] (the computed
//! curve, the analytic or reference curve beside it, markers for paper values), linear or logarithmic
//! axes, optionally a second time axis on top (the paper's dimensionless time beside physical time).
//! [`render`] writes `stem.png` and `stem.svg` with one or more panels on a grid. The style, for every
//! figure of the project:
//! - the legend sits outside the data area (to the right of the plot, or below it when the labels are
//!   long) and shows each series as drawn: colour, dash pattern, markers;
//! - within a panel no two labelled series look alike: two solid lines (or two dashed, or two marker
//!   sets) never share a colour (a repeated palette index moves to the next free colour), while a computed
//!   solid line and its dashed reference may; solid lines are drawn first, dashed and dotted references over them, markers last;
//! - every line has the same width (a wider line would read as emphasis): a solid line that runs over an
//!   earlier one is drawn in long dashes, so that the one beneath shows in its gaps, and its legend entry
//!   says which lines it covers ("coincides with" where it covers nearly all of them);
//! - tick labels are chosen by measuring them ([`ticks`]), so they never collide or repeat;
//! - the PNG is anti-aliased by supersampling ([`raster`]); lines longer than a few points per pixel
//!   column are reduced to each column's first, least, greatest and last point, which draws the same
//!   picture (envelopes included) with far fewer points;
//! - the SVG carries its text as glyph outlines of the bundled font ([`svg`]), so every viewer shows it
//!   alike.

mod raster;
mod svg;
mod text;
mod ticks;

use std::path::Path;

use plotters::coord::Shift;
use plotters::coord::ranged1d::Ranged;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use ticks::{Along, Ticks};

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Style {
    /// solid line (computed results)
    Line,
    /// dashed line (analytic or reference solutions)
    Dashed,
    /// dotted line (a second reference, an envelope, a limit)
    Dotted,
    /// markers only (paper values, sampled points)
    Markers,
    /// solid line with markers (convergence data)
    LineMarkers,
}

impl Style {
    /// Drawing class: 0 solid lines, 1 dashed and dotted lines, 2 markers. Classes are drawn in this
    /// order; within a class a later series can hide an earlier one, and a colour may be shared only across
    /// classes (a computed solid line and its dashed reference).
    fn class(self) -> usize {
        match self {
            Style::Line | Style::LineMarkers => 0,
            Style::Dashed | Style::Dotted => 1,
            Style::Markers => 2,
        }
    }
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
    /// palette index (10 colours; labelled series of one panel drawn alike never share one)
    pub color: usize,
}

impl Series {
    /// A series with the given label, points, style and palette colour.
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>, style: Style, color: usize) -> Self {
        Series { label: label.into(), points, style, color }
    }
}

/// A second x axis along the top of a panel, a fixed multiple of the bottom one (the paper's
/// dimensionless time `tau = t / t_ref` above physical time `t`).
#[derive(Clone, Debug)]
pub struct TopAxis {
    /// axis label: quantity and unit
    pub label: String,
    /// top value per bottom value
    pub scale: f64,
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
    /// a second x axis on top
    pub top_axis: Option<TopAxis>,
    /// a categorical x axis: category `k` sits at `x = k` and is labelled with `x_categories[k]`
    pub x_categories: Option<Vec<String>>,
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

/// Ten distinguishable colours (the "tab10" palette of matplotlib, a common reference for line plots).
const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

/// Sizes of the style at output scale 1 [px].
mod size {
    pub const HEADING: f64 = 19.0;
    pub const TITLE: f64 = 16.0;
    pub const TICK: f64 = 13.0;
    pub const AXIS: f64 = 14.0;
    pub const LEGEND: f64 = 13.0;
    pub const MARGIN: f64 = 10.0;
    pub const LINE: f64 = 2.0;
    /// dash and gap of a solid line drawn over one earlier line, and over two or more
    pub const COVER_DASH: [(f64, f64); 2] = [(8.0, 8.0), (4.0, 12.0)];
    pub const MARKER: f64 = 3.5;
    pub const SAMPLE: f64 = 30.0;
}

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
        let r = (hi / lo).powf(0.04).max(1.05);
        (lo / r, hi * r)
    } else if hi - lo <= f64::EPSILON * hi.abs().max(1.0) {
        let m = hi.abs().max(1.0) * 0.05;
        (lo - m, hi + m)
    } else {
        let m = 0.04 * (hi - lo);
        (lo - m, hi + m)
    }
}

/// Render `panels` on a grid with `cols` columns, `panel_size` pixels each, to `stem.png` and
/// `stem.svg` (the parent directory is created).
pub fn render(panels: &[Chart], cols: usize, panel_size: (u32, u32), stem: &Path) -> Result<(), PlotError> {
    render_titled(panels, cols, panel_size, "", stem)
}

/// [`render`] under a figure title (the case and its conductor), one line above the panels.
pub fn render_titled(
    panels: &[Chart],
    cols: usize,
    panel_size: (u32, u32),
    title: &str,
    stem: &Path,
) -> Result<(), PlotError> {
    plotters::style::register_font("sans-serif", FontStyle::Normal, text::FONT_BYTES)
        .unwrap_or_else(|_| panic!("bundled font assets/fonts/DejaVuSans.ttf is not a valid font"));
    if let Some(dir) = stem.parent() {
        std::fs::create_dir_all(dir)
            .map_err(|e| PlotError { path: dir.display().to_string(), message: e.to_string() })?;
    }
    let cols = cols.max(1);
    let rows = panels.len().div_ceil(cols);
    let width = panel_size.0 * cols as u32;
    let heading = heading_lines(title, f64::from(width));
    let heading_h = heading_height(&heading);
    let size = (width, panel_size.1 * rows as u32 + heading_h);
    let planned: Vec<Panel> = panels.iter().map(Panel::new).collect();
    let png = stem.with_extension("png");
    let svg = stem.with_extension("svg");
    let err = |p: &Path| {
        let path = p.display().to_string();
        move |e: String| PlotError { path: path.clone(), message: e }
    };
    {
        let k = raster::SUPERSAMPLE;
        let big = (size.0 * k, size.1 * k);
        let mut buffer = vec![0u8; big.0 as usize * big.1 as usize * 3];
        {
            let root = raster::GlyphBitmap::new(&mut buffer, big).into_drawing_area();
            draw_all(&root, &planned, rows, cols, &heading, f64::from(k)).map_err(err(&png))?;
            root.present().map_err(|e| e.to_string()).map_err(err(&png))?;
        }
        raster::downsample_to_png(&buffer, size, &png).map_err(err(&png))?;
    }
    {
        let root = svg::GlyphSvg::new(&svg, size).into_drawing_area();
        draw_all(&root, &planned, rows, cols, &heading, 1.0).map_err(err(&svg))?;
        root.present().map_err(|e| e.to_string()).map_err(err(&svg))?;
    }
    Ok(())
}

/// A panel ready to draw on either backend: its chart, axis ranges and prepared series, computed once.
struct Panel<'a> {
    chart: &'a Chart,
    xr: (f64, f64),
    yr: (f64, f64),
    prepared: Vec<Prepared<'a>>,
}

impl<'a> Panel<'a> {
    fn new(chart: &'a Chart) -> Self {
        let xs = chart.series.iter().flat_map(|s| s.points.iter().map(|p| p.0));
        let ys = chart.series.iter().flat_map(|s| s.points.iter().map(|p| p.1));
        let categories = chart.x_categories.as_ref().map(|c| (-0.5, c.len().max(1) as f64 - 0.5));
        let xr = chart.x_range.or(categories).unwrap_or_else(|| data_range(xs, chart.log_x));
        let yr = chart.y_range.unwrap_or_else(|| data_range(ys, chart.log_y));
        Panel { chart, xr, yr, prepared: prepare(chart, xr, yr) }
    }
}

/// A series ready to draw: its effective colour, legend text and dash pattern.
struct Prepared<'a> {
    series: &'a Series,
    color: RGBColor,
    /// the legend text: the series' label, and the lines it covers
    label: String,
    /// for a solid line drawn over earlier ones: dash and gap [px at scale 1]
    cover_dash: Option<(f64, f64)>,
}

/// Effective colours (unique among labelled series), and the lines that cover others: a line mostly
/// covered by a later line of its drawing class is named in that line's legend entry, and a solid
/// covering line is dashed so that the one beneath shows in its gaps.
fn prepare<'a>(chart: &'a Chart, xr: (f64, f64), yr: (f64, f64)) -> Vec<Prepared<'a>> {
    // A colour may be shared only by series drawn differently (a computed solid line and its dashed
    // reference): the key is (colour, drawing class).
    let mut used = [[false; PALETTE.len()]; 3];
    let mut colors = Vec::with_capacity(chart.series.len());
    for s in &chart.series {
        let mut c = s.color % PALETTE.len();
        if !s.label.is_empty() {
            let u = &mut used[s.style.class()];
            if u[c] {
                c = (0..PALETTE.len()).map(|i| (c + i) % PALETTE.len()).find(|&i| !u[i]).unwrap_or(c);
            }
            u[c] = true;
        }
        colors.push(c);
    }
    // Lines only: markers are drawn over everything.
    let class = |s: &Series| Some(s.style.class()).filter(|&c| c < 2);
    let unit = |p: (f64, f64)| {
        let u = |v: f64, (lo, hi): (f64, f64), log: bool| {
            if log { (v.ln() - lo.ln()) / (hi.ln() - lo.ln()) } else { (v - lo) / (hi - lo) }
        };
        (u(p.0, xr, chart.log_x), u(p.1, yr, chart.log_y))
    };
    let n = chart.series.len();
    let drawn = |s: &Series| -> Vec<(f64, f64)> {
        decimate(&s.points, xr, chart.log_x, CHECK_COLUMNS).into_iter().map(unit).collect()
    };
    let lines: Vec<Option<Vec<(f64, f64)>>> = chart.series.iter().map(|s| class(s).map(|_| drawn(s))).collect();
    // Line i is covered by a later line j of its class if j runs within 0.6 % of the axes
    // (`HIDDEN_DISTANCE`) of most of i's points (of its points as decimated for drawing, `CHECK_COLUMNS`).
    // covers[j]: the labels of the lines j covers, and whether it covers all of them nearly everywhere.
    let mut covers: Vec<(Vec<String>, bool)> = vec![(Vec::new(), true); n];
    let mut depth = vec![0_usize; n];
    for j in 0..n {
        let Some(b) = &lines[j] else { continue };
        let grid = SegmentGrid::new(b, HIDDEN_DISTANCE);
        for i in 0..j {
            let Some(a) = &lines[i] else { continue };
            if class(&chart.series[i]) != class(&chart.series[j]) || a.is_empty() {
                continue;
            }
            let near = a.iter().filter(|p| grid.within(**p, b)).count();
            if near * 2 > a.len() {
                depth[j] = depth[j].max(depth[i] + 1);
                let label = &chart.series[i].label;
                if !label.is_empty() {
                    // The short form of a label: "t = 59.99 s" of "t = 59.99 s (tau = 7.50)".
                    let short = label.split(" (").next().unwrap_or(label).to_string();
                    if !covers[j].0.contains(&short) {
                        covers[j].0.push(short);
                    }
                    covers[j].1 &= near * 20 >= a.len() * 19;
                }
            }
        }
    }
    chart
        .series
        .iter()
        .zip(colors)
        .enumerate()
        .map(|(j, (series, c))| {
            let (names, all) = &covers[j];
            let label = if series.label.is_empty() || names.is_empty() {
                series.label.clone()
            } else {
                let how = if *all { "coincides with" } else { "largely over" };
                format!("{} ({how} {})", series.label, names.join(", "))
            };
            let cover_dash =
                (depth[j] > 0 && chart.series[j].style.class() == 0).then(|| size::COVER_DASH[(depth[j] - 1).min(1)]);
            Prepared { series, color: PALETTE[c], label, cover_dash }
        })
        .collect()
}

/// A line runs over another where it passes within this distance [fraction of the axes].
const HIDDEN_DISTANCE: f64 = 0.006;

/// Columns of the decimation ([`decimate`]) the hidden-line check works on: at most four points per column
/// of this many (more than any panel has pixels at the drawing scale), so that its cost does not grow
/// with the number of rows; a series of fewer than `4 CHECK_COLUMNS` points is checked whole.
const CHECK_COLUMNS: f64 = 2000.0;

/// Distance of `p` to the segment from `a` to `b` (unit coordinates; a point if `a = b`).
fn distance_to_segment(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 { (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0) } else { 0.0 };
    ((a.0 + t * dx - p.0).powi(2) + (a.1 + t * dy - p.1).powi(2)).sqrt()
}

/// Distance of `p` to the polyline `line` (both in unit coordinates), segment by segment: the reference
/// that [`SegmentGrid::within`] must agree with.
#[cfg(test)]
fn distance_to_polyline(p: (f64, f64), line: &[(f64, f64)]) -> f64 {
    match line.len() {
        0 => f64::INFINITY,
        1 => distance_to_segment(p, line[0], line[0]),
        _ => line.windows(2).map(|w| distance_to_segment(p, w[0], w[1])).fold(f64::INFINITY, f64::min),
    }
}

/// The segments of a polyline binned on a square grid of cells of about `h` (unit coordinates), so that
/// "is `p` within `h` of the polyline" looks at the segments of the 3 x 3 cells around `p` only: linear
/// in the number of points instead of their product (a figure of a million rows in seconds).
///
/// Exact: if a segment passes within `h` of `p`, its point nearest to `p` lies in its bounding box and
/// less than one cell from `p`'s cell in each direction, and the segment is binned in every cell of its
/// bounding box. A segment whose box spans more than [`SegmentGrid::MAX_CELLS`] cells (or has a
/// coordinate that is not finite) is kept aside and checked for every point, as before.
struct SegmentGrid {
    h: f64,
    cell: f64,
    cells: std::collections::HashMap<(i64, i64), Vec<usize>>,
    /// segments checked for every point
    wide: Vec<usize>,
}

impl SegmentGrid {
    const MAX_CELLS: i64 = 64;

    /// Segment `k` joins `line[k]` and `line[k + 1]` (a single point is segment 0 from it to itself).
    fn new(line: &[(f64, f64)], h: f64) -> Self {
        // Cells a little wider than `h`: the cell indices of two points less than `h` apart then differ by
        // at most one even after the rounding of `v / cell`.
        let mut g = SegmentGrid { h, cell: 1.001 * h, cells: std::collections::HashMap::new(), wide: Vec::new() };
        let segments = line.len().saturating_sub(1).max(usize::from(line.len() == 1));
        for k in 0..segments {
            let (a, b) = (line[k], line[(k + 1).min(line.len() - 1)]);
            let finite = [a.0, a.1, b.0, b.1].iter().all(|v| v.is_finite());
            let (x0, x1) = (g.cell(a.0.min(b.0)), g.cell(a.0.max(b.0)));
            let (y0, y1) = (g.cell(a.1.min(b.1)), g.cell(a.1.max(b.1)));
            if !finite || (x1 - x0 + 1) * (y1 - y0 + 1) > Self::MAX_CELLS {
                g.wide.push(k);
                continue;
            }
            for cx in x0..=x1 {
                for cy in y0..=y1 {
                    g.cells.entry((cx, cy)).or_default().push(k);
                }
            }
        }
        g
    }

    /// The cell of a coordinate, clamped far outside the axes so that the index arithmetic cannot overflow.
    fn cell(&self, v: f64) -> i64 {
        (v / self.cell).floor().clamp(-1.0e12, 1.0e12) as i64
    }

    /// Whether `p` lies within `h` of the polyline `line` (the one the grid was built from).
    fn within(&self, p: (f64, f64), line: &[(f64, f64)]) -> bool {
        let near = |k: usize| distance_to_segment(p, line[k], line[(k + 1).min(line.len() - 1)]) < self.h;
        if self.wide.iter().any(|&k| near(k)) {
            return true;
        }
        if !(p.0.is_finite() && p.1.is_finite()) {
            return false;
        }
        let (cx, cy) = (self.cell(p.0), self.cell(p.1));
        (cx - 1..=cx + 1)
            .flat_map(|x| (cy - 1..=cy + 1).map(move |y| (x, y)))
            .filter_map(|c| self.cells.get(&c))
            .any(|ks| ks.iter().any(|&k| near(k)))
    }
}

/// Keeps, of each run of points falling in one of `columns` equal columns of the x range, the first, the
/// least, the greatest and the last (in their order), when x is monotone and the series has more than
/// four points per column; otherwise returns the points unchanged.
fn decimate(points: &[(f64, f64)], xr: (f64, f64), log: bool, columns: f64) -> Vec<(f64, f64)> {
    let pts: Vec<(f64, f64)> = points.iter().copied().filter(|p| p.0.is_finite() && p.1.is_finite()).collect();
    let monotone = pts.windows(2).all(|w| w[1].0 >= w[0].0);
    if !monotone || (pts.len() as f64) < 4.0 * columns {
        return pts;
    }
    let col = |x: f64| {
        let u = if log { (x.ln() - xr.0.ln()) / (xr.1.ln() - xr.0.ln()) } else { (x - xr.0) / (xr.1 - xr.0) };
        (u * columns).floor() as i64
    };
    let mut out = Vec::with_capacity((4.0 * columns) as usize + 4);
    let mut i = 0;
    while i < pts.len() {
        let c = col(pts[i].0);
        let mut j = i;
        let (mut lo, mut hi) = (i, i);
        while j < pts.len() && col(pts[j].0) == c {
            if pts[j].1 < pts[lo].1 {
                lo = j;
            }
            if pts[j].1 > pts[hi].1 {
                hi = j;
            }
            j += 1;
        }
        let mut keep = [i, lo, hi, j - 1];
        keep.sort_unstable();
        let mut last = usize::MAX;
        for k in keep {
            if k != last {
                out.push(pts[k]);
                last = k;
            }
        }
        i = j;
    }
    out
}

/// Where the legend goes and how big it is [px at the drawing scale].
enum LegendPlace {
    None,
    Right(u32),
    Below(u32, usize),
}

fn legend_place(prepared: &[Prepared], panel_w: f64, s: f64) -> LegendPlace {
    let labels: Vec<&str> = prepared.iter().filter(|x| !x.label.is_empty()).map(|x| x.label.as_str()).collect();
    // One labelled series needs no legend: the axis label says what it is.
    if labels.len() < 2 {
        return LegendPlace::None;
    }
    let widest = labels.iter().map(|l| text::width(l, size::LEGEND as f32) as f64).fold(0.0, f64::max);
    let right = size::SAMPLE + 8.0 + widest + 2.0 * size::MARGIN;
    if right <= 0.34 * panel_w / s {
        return LegendPlace::Right((right * s).ceil() as u32);
    }
    // Below: entries flow in columns of equal width.
    let entry = size::SAMPLE + 8.0 + widest + 2.0 * size::MARGIN;
    let per_row = ((panel_w / s - 2.0 * size::MARGIN - 60.0) / entry).floor().max(1.0) as usize;
    let rows = labels.len().div_ceil(per_row);
    LegendPlace::Below(((rows as f64 * 1.5 * size::LEGEND + size::MARGIN) * s).ceil() as u32, per_row)
}

/// A figure heading: its lines and font size [px at scale 1].
struct Heading {
    lines: Vec<String>,
    font: f64,
}

/// Lays out a heading in `width` pixels: one line if it fits, else broken at its " | " separators, and
/// the font reduced (down to 70 %) until the longest line fits.
fn heading_lines(title: &str, width: f64) -> Heading {
    if title.is_empty() {
        return Heading { lines: Vec::new(), font: size::HEADING };
    }
    let room = width - 2.0 * size::MARGIN;
    let fits = |l: &str, f: f64| f64::from(text::width(l, f as f32)) <= room;
    let lines: Vec<String> = if fits(title, size::HEADING) {
        vec![title.to_string()]
    } else {
        title.split(" | ").map(str::to_string).collect()
    };
    let mut font = size::HEADING;
    while font > 0.7 * size::HEADING && !lines.iter().all(|l| fits(l, font)) {
        font -= 0.5;
    }
    Heading { lines, font }
}

/// Height of a heading [px at scale 1].
fn heading_height(h: &Heading) -> u32 {
    if h.lines.is_empty() { 0 } else { (1.2 * h.font + 1.4 * h.font * h.lines.len() as f64).ceil() as u32 }
}

fn draw_all<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    panels: &[Panel],
    rows: usize,
    cols: usize,
    heading: &Heading,
    s: f64,
) -> Result<(), String> {
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    let body = if heading.lines.is_empty() {
        root.clone()
    } else {
        let (w, _) = root.dim_in_pixel();
        let (head, body) = root.split_vertically((f64::from(heading_height(heading)) * s).round() as u32);
        let style = TextStyle::from(("sans-serif", heading.font * s).into_font())
            .color(&BLACK)
            .pos(Pos::new(HPos::Center, VPos::Center));
        for (i, line) in heading.lines.iter().enumerate() {
            let y = (0.6 * heading.font + (i as f64 + 0.5) * 1.4 * heading.font) * s;
            head.draw(&Text::new(line.clone(), (w as i32 / 2, y as i32), style.clone())).map_err(|e| e.to_string())?;
        }
        body
    };
    let areas = body.split_evenly((rows, cols));
    for (panel, area) in panels.iter().zip(areas.iter()) {
        draw_panel(area, panel, s)?;
    }
    Ok(())
}

fn draw_panel<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, panel: &Panel, s: f64) -> Result<(), String> {
    let Panel { chart, xr, yr, prepared } = panel;
    let (chart, xr, yr) = (*chart, *xr, *yr);
    let (w, h) = area.dim_in_pixel();
    let (plot_area, legend_area) = match legend_place(prepared, f64::from(w), s) {
        LegendPlace::None => (area.clone(), None),
        LegendPlace::Right(lw) => {
            let (a, b) = area.split_horizontally(w.saturating_sub(lw));
            (a, Some((b, None)))
        }
        LegendPlace::Below(lh, per_row) => {
            let (a, b) = area.split_vertically(h.saturating_sub(lh));
            (a, Some((b, Some(per_row))))
        }
    };
    // Label areas from the measured labels: the y axis's widest tick label, the x axis's text height.
    let (pw, ph) = plot_area.dim_in_pixel();
    let top = if chart.top_axis.is_some() { 1.1 * size::TICK + 1.3 * size::AXIS + 12.0 } else { 0.0 };
    let x_area = 1.0 * size::TICK + 1.6 * size::AXIS + 8.0;
    let title_h = if chart.title.is_empty() { 0.0 } else { 1.6 * size::TITLE };
    let plot_h = f64::from(ph) / s - x_area - top - title_h - 2.0 * size::MARGIN;
    let y_ticks =
        axis_ticks(yr, chart.log_y, plot_h, Along::Y, chart.series.iter().flat_map(|s| s.points.iter().map(|p| p.1)));
    let widest_y = y_ticks.labels.iter().map(|l| text::width(l, size::TICK as f32) as f64).fold(0.0, f64::max);
    let y_area = widest_y + 1.5 * size::AXIS + 12.0;
    let plot_w = f64::from(pw) / s - y_area - 2.0 * size::MARGIN;
    let x_ticks = match &chart.x_categories {
        Some(names) => {
            Ticks { at: (0..names.len()).map(|k| k as f64).collect(), labels: names.clone(), minor: Vec::new() }
        }
        None => axis_ticks(
            xr,
            chart.log_x,
            plot_w,
            Along::X,
            chart.series.iter().flat_map(|s| s.points.iter().map(|p| p.0)),
        ),
    };
    let geometry = Geometry { title: title_h, x_area, y_area, top, plot_w };
    match (chart.log_x, chart.log_y) {
        (false, false) => {
            draw_chart(&plot_area, panel, lin(xr, &x_ticks), lin(yr, &y_ticks), (&x_ticks, &y_ticks), &geometry, s)
        }
        (true, false) => {
            draw_chart(&plot_area, panel, logc(xr, &x_ticks), lin(yr, &y_ticks), (&x_ticks, &y_ticks), &geometry, s)
        }
        (false, true) => {
            draw_chart(&plot_area, panel, lin(xr, &x_ticks), logc(yr, &y_ticks), (&x_ticks, &y_ticks), &geometry, s)
        }
        (true, true) => {
            draw_chart(&plot_area, panel, logc(xr, &x_ticks), logc(yr, &y_ticks), (&x_ticks, &y_ticks), &geometry, s)
        }
    }?;
    if let Some((legend_area, below)) = legend_area {
        draw_legend(&legend_area, prepared, below, title_h, s)?;
    }
    Ok(())
}

fn axis_ticks(r: (f64, f64), log: bool, length: f64, along: Along, data: impl Iterator<Item = f64>) -> Ticks {
    if log {
        let data: Vec<f64> = if along == Along::X { data.collect() } else { Vec::new() };
        ticks::log(r.0, r.1, length, size::TICK, along, &data)
    } else {
        ticks::linear(r.0, r.1, length, size::TICK, along)
    }
}

/// A coordinate whose grid lines and labels are the given ticks (plotters' own `WithKeyPoints` offers no
/// label formatting, which the mesh needs).
struct Keyed<R: Ranged<ValueType = f64>> {
    inner: R,
    bold: Vec<f64>,
    light: Vec<f64>,
}

impl<R: Ranged<ValueType = f64>> Ranged for Keyed<R> {
    type FormatOption = plotters::coord::ranged1d::DefaultFormatting;
    type ValueType = f64;
    fn range(&self) -> std::ops::Range<f64> {
        self.inner.range()
    }
    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        self.inner.map(value, limit)
    }
    fn key_points<H: plotters::coord::ranged1d::KeyPointHint>(&self, hint: H) -> Vec<f64> {
        if hint.weight().allow_light_points() { self.light.clone() } else { self.bold.clone() }
    }
    fn axis_pixel_range(&self, limit: (i32, i32)) -> std::ops::Range<i32> {
        self.inner.axis_pixel_range(limit)
    }
}

fn lin(r: (f64, f64), t: &Ticks) -> Keyed<RangedCoordf64> {
    Keyed { inner: (r.0..r.1).into(), bold: t.at.clone(), light: t.minor.clone() }
}

fn logc(r: (f64, f64), t: &Ticks) -> Keyed<plotters::coord::combinators::LogCoord<f64>> {
    use plotters::coord::combinators::IntoLogRange;
    Keyed { inner: (r.0..r.1).log_scale().into(), bold: t.at.clone(), light: t.minor.clone() }
}

struct Geometry {
    title: f64,
    x_area: f64,
    y_area: f64,
    top: f64,
    plot_w: f64,
}

/// The label of tick `v` among `t`'s.
fn label_of(t: &Ticks, v: f64) -> String {
    t.at.iter()
        .position(|a| (a - v).abs() <= 1e-9 * a.abs().max(1e-300))
        .map(|i| t.labels[i].clone())
        .unwrap_or_default()
}

fn draw_chart<DB, X, Y>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    x: X,
    y: Y,
    (xt, yt): (&Ticks, &Ticks),
    g: &Geometry,
    s: f64,
) -> Result<(), String>
where
    DB: DrawingBackend,
    X: Ranged<ValueType = f64, FormatOption = plotters::coord::ranged1d::DefaultFormatting>,
    Y: Ranged<ValueType = f64, FormatOption = plotters::coord::ranged1d::DefaultFormatting>,
{
    let (chart, xr, yr) = (panel.chart, panel.xr, panel.yr);
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let px = |v: f64| (v * s).round() as i32;
    let font = |v: f64| ("sans-serif", v * s);
    let mut builder = ChartBuilder::on(area);
    builder.margin(px(size::MARGIN)).x_label_area_size(px(g.x_area)).y_label_area_size(px(g.y_area));
    // The title is drawn by hand above the top axis (a caption would sit below a top margin).
    builder.margin_top(px(size::MARGIN + g.title + g.top));
    if !chart.title.is_empty() {
        let (w, _) = area.dim_in_pixel();
        // A long title shrinks (down to 60 %) to fit the panel.
        let room = f64::from(w) / s - 2.0 * size::MARGIN;
        let mut title_px = size::TITLE;
        while title_px > 0.6 * size::TITLE && f64::from(text::width(&chart.title, title_px as f32)) > room {
            title_px -= 0.5;
        }
        let style = TextStyle::from(font(title_px).into_font()).color(&BLACK).pos(Pos::new(HPos::Center, VPos::Top));
        area.draw(&Text::new(chart.title.clone(), (w as i32 / 2, px(size::MARGIN)), style)).map_err(e)?;
    }
    let mut cc = builder.build_cartesian_2d(x, y).map_err(e)?;
    let x_fmt = |v: &f64| label_of(xt, *v);
    let y_fmt = |v: &f64| label_of(yt, *v);
    cc.configure_mesh()
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .x_desc(chart.x_label.as_str())
        .y_desc(chart.y_label.as_str())
        .label_style(font(size::TICK))
        .axis_desc_style(font(size::AXIS))
        .bold_line_style(RGBColor(225, 225, 225).stroke_width(px(1.0).max(1) as u32))
        .light_line_style(RGBColor(242, 242, 242).stroke_width(px(1.0).max(1) as u32))
        .axis_style(BLACK.stroke_width(px(1.0).max(1) as u32))
        .set_all_tick_mark_size(px(4.0))
        .draw()
        .map_err(e)?;
    if let Some(top) = &chart.top_axis {
        // The top axis is drawn by hand: plotters' secondary axes would repeat the primary labels there.
        let t2 = ticks::linear(xr.0 * top.scale, xr.1 * top.scale, g.plot_w, size::TICK, Along::X);
        let base = area.get_base_pixel();
        let rel = |p: (i32, i32)| (p.0 - base.0, p.1 - base.1);
        let (left, y_top) = rel(cc.backend_coord(&(xr.0, yr.1)));
        let (right, _) = rel(cc.backend_coord(&(xr.1, yr.1)));
        let axis = BLACK.stroke_width(px(1.0).max(1) as u32);
        area.draw(&PathElement::new(vec![(left, y_top), (right, y_top)], axis)).map_err(e)?;
        let tick_style =
            TextStyle::from(font(size::TICK).into_font()).color(&BLACK).pos(Pos::new(HPos::Center, VPos::Bottom));
        for (v, label) in t2.at.iter().zip(&t2.labels) {
            let (x, _) = rel(cc.backend_coord(&(v / top.scale, yr.1)));
            area.draw(&PathElement::new(vec![(x, y_top), (x, y_top - px(4.0))], axis)).map_err(e)?;
            area.draw(&Text::new(label.clone(), (x, y_top - px(6.0)), tick_style.clone())).map_err(e)?;
        }
        let desc_style =
            TextStyle::from(font(size::AXIS).into_font()).color(&BLACK).pos(Pos::new(HPos::Center, VPos::Bottom));
        let desc_y = y_top - px(10.0 + 1.1 * size::TICK);
        area.draw(&Text::new(top.label.clone(), ((left + right) / 2, desc_y), desc_style)).map_err(e)?;
    }
    draw_series(&mut cc, panel, g, s)
}

/// Draws the series: solid lines first, dashed and dotted references over them, markers last.
fn draw_series<DB, X, Y>(
    cc: &mut ChartContext<DB, Cartesian2d<X, Y>>,
    panel: &Panel,
    g: &Geometry,
    s: f64,
) -> Result<(), String>
where
    DB: DrawingBackend,
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let px = |v: f64| (v * s).round() as i32;
    let (chart, xr) = (panel.chart, panel.xr);
    let columns = g.plot_w * s;
    let mut order: Vec<&Prepared> = panel.prepared.iter().collect();
    order.sort_by_key(|p| p.series.style.class());
    for p in order {
        let c = p.color;
        let stroke = c.stroke_width(px(size::LINE).max(1) as u32);
        match (p.series.style, p.cover_dash) {
            (Style::Line, Some((on, off))) => {
                let pts = decimate(&p.series.points, xr, chart.log_x, columns);
                cc.draw_series(DashedLineSeries::new(pts, px(on) as u32, px(off) as u32, stroke)).map_err(e)?;
            }
            (Style::Line, None) => {
                let pts = decimate(&p.series.points, xr, chart.log_x, columns);
                cc.draw_series(LineSeries::new(pts, stroke)).map_err(e)?;
            }
            (Style::Dashed, _) => {
                let pts = decimate(&p.series.points, xr, chart.log_x, columns);
                cc.draw_series(DashedLineSeries::new(pts, px(7.0) as u32, px(4.0) as u32, stroke)).map_err(e)?;
            }
            (Style::Dotted, _) => {
                let pts = decimate(&p.series.points, xr, chart.log_x, columns);
                cc.draw_series(DashedLineSeries::new(pts, px(2.0) as u32, px(3.0) as u32, stroke)).map_err(e)?;
            }
            (Style::Markers, _) => {
                let pts = p.series.points.iter().copied().filter(|q| q.0.is_finite() && q.1.is_finite());
                cc.draw_series(pts.map(|q| Circle::new(q, px(size::MARKER) as u32, c.filled()))).map_err(e)?;
            }
            (Style::LineMarkers, dash) => {
                let pts: Vec<_> =
                    p.series.points.iter().copied().filter(|q| q.0.is_finite() && q.1.is_finite()).collect();
                match dash {
                    Some((on, off)) => cc
                        .draw_series(DashedLineSeries::new(pts.clone(), px(on) as u32, px(off) as u32, stroke))
                        .map_err(e)?,
                    None => cc.draw_series(LineSeries::new(pts.clone(), stroke)).map_err(e)?,
                };
                cc.draw_series(pts.iter().map(|&q| Circle::new(q, px(size::MARKER) as u32, c.filled()))).map_err(e)?;
            }
        }
    }
    Ok(())
}

/// Draws the legend entries (labelled series, in their order) in `area`: a column level with the plot's
/// top edge (`below = None`, the legend to the right of the plot), or rows of `below` entries under it.
fn draw_legend<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    prepared: &[Prepared],
    below: Option<usize>,
    title_h: f64,
    s: f64,
) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let px = |v: f64| (v * s).round() as i32;
    let entries: Vec<&Prepared> = prepared.iter().filter(|p| !p.label.is_empty()).collect();
    let widest = entries.iter().map(|p| text::width(&p.label, size::LEGEND as f32) as f64).fold(0.0, f64::max);
    let entry_w = size::SAMPLE + 8.0 + widest + 2.0 * size::MARGIN;
    let line_h = 1.5 * size::LEGEND;
    let per_row = below.unwrap_or(1);
    let (x0, y0) = match below {
        None => (0.0, size::MARGIN + title_h + 4.0),
        Some(_) => (size::MARGIN + 60.0, 0.0),
    };
    let style = TextStyle::from(("sans-serif", size::LEGEND * s).into_font())
        .color(&BLACK)
        .pos(Pos::new(HPos::Left, VPos::Center));
    for (i, p) in entries.iter().enumerate() {
        let (r, c) = (i / per_row, i % per_row);
        let x = x0 + c as f64 * entry_w;
        let y = y0 + (r as f64 + 0.5) * line_h;
        let (xa, xb, yy) = (px(x), px(x + size::SAMPLE), px(y));
        let stroke = p.color.stroke_width(px(size::LINE).max(1) as u32);
        let dash = match p.series.style {
            Style::Line | Style::LineMarkers => p.cover_dash,
            Style::Dashed => Some((7.0, 4.0)),
            Style::Dotted => Some((2.0, 3.0)),
            Style::Markers => None,
        };
        match (p.series.style, dash) {
            (Style::Markers, _) => {}
            (_, None) => {
                area.draw(&PathElement::new(vec![(xa, yy), (xb, yy)], stroke)).map_err(e)?;
            }
            (_, Some((on, off))) => {
                let mut t = 0.0;
                while t < size::SAMPLE {
                    let a = px(x + t);
                    let b = px(x + (t + on).min(size::SAMPLE));
                    area.draw(&PathElement::new(vec![(a, yy), (b, yy)], stroke)).map_err(e)?;
                    t += on + off;
                }
            }
        }
        if matches!(p.series.style, Style::Markers | Style::LineMarkers) {
            area.draw(&Circle::new((px(x + 0.5 * size::SAMPLE), yy), px(size::MARKER) as u32, p.color.filled()))
                .map_err(e)?;
        }
        area.draw(&Text::new(p.label.clone(), (px(x + size::SAMPLE + 8.0), yy), style.clone())).map_err(e)?;
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
            top_axis: Some(TopAxis { label: "tau [-]".into(), scale: 2.0 }),
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
        // Text is glyph outlines: no <text> element, no font family, glyphs defined once and used.
        assert!(svg.contains("<svg") && svg.contains("<use") && svg.contains("<path id=\"g"));
        assert!(!svg.contains("<text") && !svg.contains("font-family"));
        // The words stay searchable as labels of the glyph groups.
        assert!(svg.contains("aria-label=\"convergence\"") && svg.contains("aria-label=\"x3 [m]\""));
    }

    #[test]
    fn labelled_series_of_a_panel_get_distinct_colours() {
        let pts = vec![(0.0, 0.0), (1.0, 1.0)];
        let chart = Chart {
            series: vec![
                Series::new("a", pts.clone(), Style::Line, 3),
                Series::new("b", pts.clone(), Style::Dashed, 3),
                Series::new("c", pts.clone(), Style::Line, 13),
            ],
            ..Default::default()
        };
        let p = prepare(&chart, (0.0, 1.0), (0.0, 1.0));
        // Two solid lines never share a colour; a solid line and a dashed one may.
        assert!(p[0].color != p[2].color);
        assert!(p[0].color == p[1].color);
        // "a" lies under the identical solid "c": "c" is dashed and says so in its legend entry, "a" is not.
        assert_eq!(p[2].cover_dash, Some(size::COVER_DASH[0]));
        assert_eq!(p[2].label, "c (coincides with a)");
        assert_eq!((p[0].cover_dash, p[0].label.as_str()), (None, "a"));
        // The dashed "b" is of another drawing class: it covers nothing.
        assert_eq!(p[1].label, "b");
    }

    #[test]
    fn the_segment_grid_agrees_with_the_distance_to_every_segment() {
        // Points and polylines of every kind the figures have: a smooth curve, a noisy one, long jumps
        // (segments binned in many cells, or kept aside), repeated points, a single point, points
        // outside the axes and non-finite coordinates. The grid must answer exactly as the direct check.
        let mut seed = 7_u64;
        let mut rnd = move || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let smooth: Vec<(f64, f64)> =
            (0..400).map(|k| (k as f64 / 399.0, 0.5 + 0.4 * (k as f64 / 30.0).sin())).collect();
        let noisy: Vec<(f64, f64)> = (0..400).map(|k| (k as f64 / 399.0, 0.5 + 0.02 * (rnd() - 0.5))).collect();
        let jumps: Vec<(f64, f64)> = (0..40).map(|k| (k as f64 / 39.0, if k % 2 == 0 { -0.2 } else { 1.3 })).collect();
        let odd = vec![(0.2, 0.2), (0.2, 0.2), (f64::NAN, 0.3), (0.5, f64::INFINITY), (0.6, 0.6), (3.0, -2.0)];
        let single = vec![(0.5, 0.5)];
        let lines = [smooth, noisy, jumps, odd, single, Vec::new()];
        let mut points: Vec<(f64, f64)> = (0..3000).map(|_| (1.6 * rnd() - 0.3, 1.6 * rnd() - 0.3)).collect();
        points.extend(lines.iter().flatten().copied());
        points.extend([(f64::NAN, 0.5), (0.5, f64::NEG_INFINITY)]);
        let mut agreed_near = 0;
        for line in &lines {
            let grid = SegmentGrid::new(line, HIDDEN_DISTANCE);
            for &p in &points {
                let direct = distance_to_polyline(p, line) < HIDDEN_DISTANCE;
                assert_eq!(grid.within(p, line), direct, "point {p:?}, line of {} points", line.len());
                agreed_near += usize::from(direct);
            }
        }
        // The comparison must have exercised both answers.
        assert!(agreed_near > 100, "only {agreed_near} near points");
    }

    #[test]
    fn decimation_keeps_the_envelope() {
        let pts: Vec<(f64, f64)> = (0..100_000).map(|i| (i as f64 * 1e-3, (i as f64 * 0.7).sin())).collect();
        let d = decimate(&pts, (0.0, 100.0), false, 500.0);
        assert!(d.len() <= 4 * 501, "{}", d.len());
        let max = d.iter().map(|p| p.1).fold(f64::MIN, f64::max);
        let min = d.iter().map(|p| p.1).fold(f64::MAX, f64::min);
        let true_max = pts.iter().map(|p| p.1).fold(f64::MIN, f64::max);
        assert_eq!(max, true_max);
        assert!(min < -0.9999);
    }
}
