//! A compact SVG backend for plotters whose text is the bundled font's glyph outlines.
//!
//! plotters' own SVG backend writes text as `<text font-family="sans-serif">`, which each viewer draws
//! with whatever font it has, and strokes dashed curves as hundreds of separate elements with fractional
//! coordinates. This backend writes each glyph once as a path in `<defs>` (font units) and places it with
//! `<use>`, so the figure looks the same everywhere and carries no font file; coordinates are the backend's
//! integer pixels. Each line of text keeps its words as the group's `aria-label` (screen readers, search).

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use plotters_backend::{BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingBackend, DrawingErrorKind};

use super::text;

/// Writes an SVG file when presented.
pub(super) struct GlyphSvg {
    path: PathBuf,
    size: (u32, u32),
    body: String,
    /// glyph index -> path data (font units), written once in `<defs>`
    glyphs: BTreeMap<u16, Option<String>>,
}

impl GlyphSvg {
    /// A blank `size` canvas that will be written to `path`.
    pub(super) fn new(path: &Path, size: (u32, u32)) -> Self {
        GlyphSvg { path: path.to_path_buf(), size, body: String::new(), glyphs: BTreeMap::new() }
    }

    /// The document.
    fn document(&self) -> String {
        let (w, h) = self.size;
        let mut s = String::with_capacity(self.body.len() + 4096);
        let _ = write!(
            s,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" \
             width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\">\n<defs>\n"
        );
        for (id, d) in &self.glyphs {
            if let Some(d) = d {
                let _ = writeln!(s, "<path id=\"g{id}\" d=\"{d}\"/>");
            }
        }
        s.push_str("</defs>\n");
        s.push_str(&self.body);
        s.push_str("</svg>\n");
        s
    }
}

/// `s` as XML attribute text.
fn escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// The paint of a filled shape, or of its outline.
fn fill_or_stroke<S: BackendStyle>(style: &S, fill: bool) -> String {
    if fill {
        paint("fill", style.color())
    } else {
        format!("fill=\"none\" {} stroke-width=\"{}\"", paint("stroke", style.color()), style.stroke_width())
    }
}

/// `#rrggbb` plus an opacity attribute when not opaque.
fn paint(attr: &str, c: BackendColor) -> String {
    let (r, g, b) = c.rgb;
    if c.alpha >= 1.0 {
        format!("{attr}=\"#{r:02x}{g:02x}{b:02x}\"")
    } else {
        format!("{attr}=\"#{r:02x}{g:02x}{b:02x}\" {attr}-opacity=\"{:.3}\"", c.alpha)
    }
}

impl DrawingBackend for GlyphSvg {
    type ErrorType = std::io::Error;

    fn get_size(&self) -> (u32, u32) {
        self.size
    }

    fn ensure_prepared(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        Ok(())
    }

    fn present(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        std::fs::write(&self.path, self.document()).map_err(DrawingErrorKind::DrawingError)
    }

    fn draw_pixel(&mut self, p: BackendCoord, c: BackendColor) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        if c.alpha > 0.0 {
            let _ = writeln!(
                self.body,
                "<rect x=\"{}\" y=\"{}\" width=\"1\" height=\"1\" {}/>",
                p.0,
                p.1,
                paint("fill", c)
            );
        }
        Ok(())
    }

    fn draw_line<S: BackendStyle>(
        &mut self,
        a: BackendCoord,
        b: BackendCoord,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        if style.color().alpha > 0.0 {
            let _ = writeln!(
                self.body,
                "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" {} stroke-width=\"{}\"/>",
                a.0,
                a.1,
                b.0,
                b.1,
                paint("stroke", style.color()),
                style.stroke_width()
            );
        }
        Ok(())
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        ul: BackendCoord,
        br: BackendCoord,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        if style.color().alpha > 0.0 {
            let paint = fill_or_stroke(style, fill);
            let _ = writeln!(
                self.body,
                "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" {paint}/>",
                ul.0,
                ul.1,
                br.0 - ul.0,
                br.1 - ul.1
            );
        }
        Ok(())
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        if style.color().alpha > 0.0 {
            let mut pts = String::new();
            let mut last = None;
            for p in path {
                // Consecutive equal pixels add nothing to the drawing.
                if last != Some(p) {
                    let _ = write!(pts, "{},{} ", p.0, p.1);
                    last = Some(p);
                }
            }
            let _ = writeln!(
                self.body,
                "<polyline fill=\"none\" {} stroke-width=\"{}\" stroke-linejoin=\"round\" stroke-linecap=\"round\" points=\"{}\"/>",
                paint("stroke", style.color()),
                style.stroke_width(),
                pts.trim_end()
            );
        }
        Ok(())
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        c: BackendCoord,
        r: u32,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        if style.color().alpha > 0.0 {
            let paint = fill_or_stroke(style, fill);
            let _ = writeln!(self.body, "<circle cx=\"{}\" cy=\"{}\" r=\"{r}\" {paint}/>", c.0, c.1);
        }
        Ok(())
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        if style.color().alpha > 0.0 {
            let mut pts = String::new();
            for p in vert {
                let _ = write!(pts, "{},{} ", p.0, p.1);
            }
            let _ = writeln!(self.body, "<polygon points=\"{}\" {}/>", pts.trim_end(), paint("fill", style.color()));
        }
        Ok(())
    }

    fn draw_text<T: BackendTextStyle>(
        &mut self,
        s: &str,
        style: &T,
        pos: BackendCoord,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        let color = style.color();
        if color.alpha == 0.0 || s.is_empty() {
            return Ok(());
        }
        let line = text::layout(s, style);
        let k = text::units_to_px(line.scale);
        // One group per line of text: anchor, rotation, baseline, then font units (y up); each glyph is a
        // `<use>` at its pen position in font units.
        let rotate = if line.degrees == 0 { String::new() } else { format!(" rotate({})", line.degrees) };
        let baseline = line.glyphs.first().map_or(0.0, |g| g.y);
        let _ = writeln!(
            self.body,
            "<g transform=\"translate({} {}){rotate} translate(0 {baseline:.2}) scale({k:.6} {:.6})\" {} aria-label=\"{}\">",
            pos.0,
            pos.1,
            -k,
            paint("fill", color),
            escape(s)
        );
        for g in &line.glyphs {
            let id = g.id.0;
            let has_path = self.glyphs.entry(id).or_insert_with(|| text::glyph_path(g.id)).is_some();
            if has_path {
                let _ = writeln!(self.body, "<use xlink:href=\"#g{id}\" x=\"{:.0}\"/>", g.x / k);
            }
        }
        self.body.push_str("</g>\n");
        Ok(())
    }
}
