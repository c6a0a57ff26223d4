//! Text drawn from the bundled font's own glyph outlines, the same way in the PNG and the SVG.
//!
//! Both backends receive text through plotters' `draw_text(text, style, anchor point)`. Left to
//! themselves, the bitmap backend rasterises glyphs without their side bearings and the SVG backend writes
//! `<text>` elements whose look depends on the fonts of the viewer. Here a line of text is laid out once
//! ([`layout`]: advances, kerning and bearings of `assets/fonts/DejaVuSans.ttf` at the style's pixel size,
//! the anchor box of plotters' own size estimate, baseline at the font's ascent below the box's top), and
//! each backend draws the placed glyphs: the raster one by coverage, the SVG one as outline paths.

use std::sync::LazyLock;

use ab_glyph::{Font, FontRef, GlyphId, OutlineCurve, PxScale, ScaleFont, point};
use plotters_backend::text_anchor::{HPos, VPos};
use plotters_backend::{BackendTextStyle, FontTransform};

/// The bundled font's bytes (DejaVu Sans, see `assets/fonts/LICENSE`).
pub(super) static FONT_BYTES: &[u8] = include_bytes!("../../../assets/fonts/DejaVuSans.ttf");

/// The bundled font, parsed once. It is a valid TrueType file; failure here is a packaging bug.
pub(super) static FONT: LazyLock<FontRef<'static>> = LazyLock::new(|| {
    FontRef::try_from_slice(FONT_BYTES)
        .unwrap_or_else(|_| panic!("bundled font assets/fonts/DejaVuSans.ttf is not a valid font"))
});

/// Height of the capitals of DejaVu Sans [em] (729 of 2048 units): a box's text is centred on them.
const CAP_HEIGHT_EM: f32 = 0.729;

/// One glyph placed in the text's own frame (x right, y down, origin at the anchor point before the
/// rotation of the style's transform).
#[derive(Clone, Copy, Debug)]
pub(super) struct Placed {
    /// the glyph
    pub id: GlyphId,
    /// pen position on the baseline [px]
    pub x: f32,
    /// baseline [px]
    pub y: f32,
}

/// A laid-out line of text.
#[derive(Clone, Debug)]
pub(super) struct Line {
    /// the glyphs
    pub glyphs: Vec<Placed>,
    /// pixel size (ascent minus descent) [px]
    pub scale: f32,
    /// rotation of the text frame [deg], clockwise on screen as in SVG's `rotate`
    pub degrees: i32,
}

/// Lays out `text` in `style` so that its anchor box sits at the anchor point, as plotters positions its
/// text (box width: the sum of advances and kerning; box height: plotters' estimate `size / 1.24`).
pub(super) fn layout<S: BackendTextStyle>(text: &str, style: &S) -> Line {
    let size = style.size() as f32;
    let font = FONT.as_scaled(PxScale::from(size));
    let mut glyphs = Vec::with_capacity(text.len());
    let width = pen_positions(text, size, |id, x| glyphs.push(Placed { id, x, y: 0.0 }));
    let height = size / 1.24;
    let dx = match style.anchor().h_pos {
        HPos::Left => 0.0,
        HPos::Center => -width / 2.0,
        HPos::Right => -width,
    };
    // The box's top is at `dy`; the glyphs of the box (cap height ~ 0.73 em) are centred in it.
    let top = match style.anchor().v_pos {
        VPos::Top => 0.0,
        VPos::Center => -height / 2.0,
        VPos::Bottom => -height,
    };
    let em = font.h_scale_factor() * FONT.units_per_em().unwrap_or(2048.0);
    let baseline = top + 0.5 * height + CAP_HEIGHT_EM / 2.0 * em;
    for g in &mut glyphs {
        g.x += dx;
        g.y = baseline;
    }
    let degrees = match style.transform() {
        FontTransform::None => 0,
        FontTransform::Rotate90 => 90,
        FontTransform::Rotate180 => 180,
        FontTransform::Rotate270 => 270,
    };
    Line { glyphs, scale: size, degrees }
}

/// Maps a point of the text frame to the backend, rotating about the anchor point `pos`.
pub(super) fn to_backend(degrees: i32, pos: (i32, i32), x: i32, y: i32) -> (i32, i32) {
    let (x, y) = match degrees {
        90 => (-y, x),
        180 => (-x, -y),
        270 => (y, -x),
        _ => (x, y),
    };
    (pos.0 + x, pos.1 + y)
}

/// Rasterises `line` anchored at `pos`: calls `put(x, y, coverage)` for every covered pixel.
pub(super) fn rasterise(line: &Line, pos: (i32, i32), mut put: impl FnMut(i32, i32, f32)) {
    let scale = PxScale::from(line.scale);
    for g in &line.glyphs {
        let glyph = g.id.with_scale_and_position(scale, point(g.x, g.y));
        if let Some(outlined) = FONT.outline_glyph(glyph) {
            let b = outlined.px_bounds();
            outlined.draw(|x, y, c| {
                let (bx, by) = to_backend(line.degrees, pos, b.min.x as i32 + x as i32, b.min.y as i32 + y as i32);
                put(bx, by, c);
            });
        }
    }
}

/// SVG path data of a glyph's outline in font units (y up), or `None` for a blank glyph.
pub(super) fn glyph_path(id: GlyphId) -> Option<String> {
    use std::fmt::Write;
    let outline = FONT.outline(id)?;
    let mut d = String::new();
    let mut last: Option<ab_glyph::Point> = None;
    // Whole font units (1/2048 em): the outline's own grid, the implied midpoints rounded.
    let f = |v: f32| format!("{}", v.round() as i64);
    for c in &outline.curves {
        let start = match c {
            OutlineCurve::Line(a, _) | OutlineCurve::Quad(a, _, _) | OutlineCurve::Cubic(a, _, _, _) => *a,
        };
        if last != Some(start) {
            if last.is_some() {
                d.push('Z');
            }
            let _ = write!(d, "M{} {}", f(start.x), f(start.y));
        }
        let end = match c {
            OutlineCurve::Line(_, b) => {
                let _ = write!(d, "L{} {}", f(b.x), f(b.y));
                *b
            }
            OutlineCurve::Quad(_, c1, b) => {
                let _ = write!(d, "Q{} {} {} {}", f(c1.x), f(c1.y), f(b.x), f(b.y));
                *b
            }
            OutlineCurve::Cubic(_, c1, c2, b) => {
                let _ = write!(d, "C{} {} {} {} {} {}", f(c1.x), f(c1.y), f(c2.x), f(c2.y), f(b.x), f(b.y));
                *b
            }
        };
        last = Some(end);
    }
    if last.is_some() {
        d.push('Z');
    }
    (!d.is_empty()).then_some(d)
}

/// Font units to pixels at pixel size `scale`.
pub(super) fn units_to_px(scale: f32) -> f32 {
    FONT.as_scaled(PxScale::from(scale)).h_scale_factor()
}

/// Calls `each(glyph, pen position [px])` for the glyphs of `s` at pixel size `size` (advances and
/// kerning) and returns the width [px].
fn pen_positions(s: &str, size: f32, mut each: impl FnMut(GlyphId, f32)) -> f32 {
    let font = FONT.as_scaled(PxScale::from(size));
    let mut pen = 0.0;
    let mut prev: Option<GlyphId> = None;
    for c in s.chars() {
        let id = font.glyph_id(c);
        if let Some(p) = prev {
            pen += font.kern(p, id);
        }
        each(id, pen);
        pen += font.h_advance(id);
        prev = Some(id);
    }
    pen
}

/// Width of `s` at pixel size `size` [px] (advances and kerning).
pub(super) fn width(s: &str, size: f32) -> f32 {
    pen_positions(s, size, |_, _| {})
}
