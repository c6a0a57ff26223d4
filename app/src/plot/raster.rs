//! Anti-aliased PNG: the figure is drawn by plotters' bitmap backend at [`SUPERSAMPLE`] times the
//! resolution, then each `SUPERSAMPLE x SUPERSAMPLE` block is averaged into one pixel (a box filter), so
//! lines and curves are drawn with sub-pixel accuracy instead of stair steps. Text is rasterised from the
//! bundled font's outlines by [`super::text`], with its coverage as alpha.

use std::path::Path;

use plotters::prelude::BitMapBackend;
use plotters_backend::{BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingBackend, DrawingErrorKind};

use super::text;

/// Linear supersampling factor of the PNG.
pub(super) const SUPERSAMPLE: u32 = 3;

/// plotters' bitmap backend with the project's text.
pub(super) struct GlyphBitmap<'a> {
    inner: BitMapBackend<'a>,
}

impl<'a> GlyphBitmap<'a> {
    /// Draws into `buffer` (RGB, `size.0 * size.1 * 3` bytes).
    pub(super) fn new(buffer: &'a mut [u8], size: (u32, u32)) -> Self {
        GlyphBitmap { inner: BitMapBackend::with_buffer(buffer, size) }
    }
}

type Error<'a> = DrawingErrorKind<<BitMapBackend<'a> as DrawingBackend>::ErrorType>;

impl<'a> DrawingBackend for GlyphBitmap<'a> {
    type ErrorType = <BitMapBackend<'a> as DrawingBackend>::ErrorType;

    fn get_size(&self) -> (u32, u32) {
        self.inner.get_size()
    }
    fn ensure_prepared(&mut self) -> Result<(), Error<'a>> {
        self.inner.ensure_prepared()
    }
    fn present(&mut self) -> Result<(), Error<'a>> {
        self.inner.present()
    }
    fn draw_pixel(&mut self, p: BackendCoord, c: BackendColor) -> Result<(), Error<'a>> {
        self.inner.draw_pixel(p, c)
    }
    fn draw_line<S: BackendStyle>(&mut self, a: BackendCoord, b: BackendCoord, s: &S) -> Result<(), Error<'a>> {
        self.inner.draw_line(a, b, s)
    }
    fn draw_rect<S: BackendStyle>(
        &mut self,
        ul: BackendCoord,
        br: BackendCoord,
        s: &S,
        fill: bool,
    ) -> Result<(), Error<'a>> {
        self.inner.draw_rect(ul, br, s, fill)
    }
    /// Thick lines with round joins: each segment a quadrilateral, each inner vertex a disc. (plotters'
    /// own polygon outline of a thick path makes miter spikes far outside the data at the hairpin turns of
    /// an oscillating signal.)
    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        s: &S,
    ) -> Result<(), Error<'a>> {
        let w = s.stroke_width();
        if w <= 1 {
            return self.inner.draw_path(path, s);
        }
        let color = s.color();
        let half = f64::from(w) / 2.0;
        let pts: Vec<BackendCoord> = path.into_iter().collect();
        for (k, seg) in pts.windows(2).enumerate() {
            let (a, b) = (seg[0], seg[1]);
            let (dx, dy) = (f64::from(b.0 - a.0), f64::from(b.1 - a.1));
            let len = (dx * dx + dy * dy).sqrt();
            if len > 0.0 {
                let (nx, ny) = (-dy / len * half, dx / len * half);
                let q = |p: BackendCoord, sgn: f64| {
                    ((f64::from(p.0) + sgn * nx).round() as i32, (f64::from(p.1) + sgn * ny).round() as i32)
                };
                self.inner.fill_polygon(vec![q(a, 1.0), q(b, 1.0), q(b, -1.0), q(a, -1.0)], &color)?;
            }
            if k > 0 {
                self.inner.draw_circle(a, (half - 0.5).max(1.0) as u32, &color, true)?;
            }
        }
        Ok(())
    }
    fn draw_circle<S: BackendStyle>(&mut self, c: BackendCoord, r: u32, s: &S, fill: bool) -> Result<(), Error<'a>> {
        self.inner.draw_circle(c, r, s, fill)
    }
    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        s: &S,
    ) -> Result<(), Error<'a>> {
        self.inner.fill_polygon(vert, s)
    }
    fn draw_text<T: BackendTextStyle>(&mut self, s: &str, style: &T, pos: BackendCoord) -> Result<(), Error<'a>> {
        let color = style.color();
        if color.alpha == 0.0 || s.is_empty() {
            return Ok(());
        }
        let line = text::layout(s, style);
        let (w, h) = self.get_size();
        let mut result = Ok(());
        text::rasterise(&line, pos, |x, y, coverage| {
            if result.is_ok() && x >= 0 && y >= 0 && (x as u32) < w && (y as u32) < h && coverage > 0.0 {
                let c = BackendColor { alpha: color.alpha * f64::from(coverage.min(1.0)), rgb: color.rgb };
                result = self.inner.draw_pixel((x, y), c);
            }
        });
        result
    }
}

/// Averages `SUPERSAMPLE x SUPERSAMPLE` blocks of the RGB buffer `big` (`size * SUPERSAMPLE` pixels) and
/// writes the result to `path` as PNG.
pub(super) fn downsample_to_png(big: &[u8], size: (u32, u32), path: &Path) -> Result<(), String> {
    let k = SUPERSAMPLE as usize;
    let (w, h) = (size.0 as usize, size.1 as usize);
    let big_w = w * k;
    let mut out = vec![0u8; w * h * 3];
    let n = (k * k) as u32;
    for y in 0..h {
        for x in 0..w {
            let mut acc = [0u32; 3];
            for dy in 0..k {
                let row = ((y * k + dy) * big_w + x * k) * 3;
                for px in big[row..row + 3 * k].chunks_exact(3) {
                    acc[0] += u32::from(px[0]);
                    acc[1] += u32::from(px[1]);
                    acc[2] += u32::from(px[2]);
                }
            }
            let o = (y * w + x) * 3;
            for c in 0..3 {
                out[o + c] = ((acc[c] + n / 2) / n) as u8;
            }
        }
    }
    image::save_buffer(path, &out, size.0, size.1, image::ColorType::Rgb8).map_err(|e| e.to_string())
}
