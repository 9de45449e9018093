//! The drawing backend every figure is drawn on: a thin layer over plotters' bitmap or SVG
//! backend that
//!
//! - draws at `scale` times the figure's pixel size, so that the PNG can be box-filtered down
//!   afterwards ([`downsample`]): plotters' bitmap backend does not anti-alias lines, polygons
//!   or circles, and drawing at 2× and averaging 2 × 2 blocks does;
//! - typesets a little math in every text: `_x` or `_{…}` as a subscript, `^{…}` as a
//!   superscript, and a letter followed by U+0304 (combining macron, as in "S̄") as the letter
//!   with a bar drawn over it. plotters lays out one glyph after the other from its ink box, so
//!   a combining mark lands beside its letter instead of above it, and `_`/`^` would be printed
//!   as they are.
//!
//! A single-character subscript `_c` is recognised only after a one-letter name (`M_x`, `E_p`,
//! `z_i`), so that code names in captions (`n_prime_from_eta`, `distribution_g`) stay as they are.

use plotters::element::{Drawable, PointCollection};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingErrorKind,
};
use std::cell::Cell;

/// Where a backend puts the text it is given (as fractions of plotters' font size `s`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Metrics {
    /// Distance from the top of a top-anchored text to its baseline.
    pub baseline: f64,
    /// The em of the font drawn at size `s`.
    pub em: f64,
    /// Width actually drawn per width estimated by plotters' layout.
    pub advance: f64,
    /// The backend typesets a whole text itself ([`super::svg::Svg`]: one `<text>` with
    /// `<tspan>`s), so the text is handed over in one piece instead of run by run.
    pub whole: bool,
}

/// plotters' bitmap text: ab_glyph at pixel height `s` (DejaVu's ascent − descent is 1.164 em),
/// baseline at `s/2` below the anchor.
pub(crate) const BITMAP_TEXT: Metrics = Metrics {
    baseline: 0.5,
    em: 1.0 / 1.164,
    advance: 1.0,
    whole: false,
};

/// The SVG's text ([`super::svg::Svg`], as plotters' SVG backend): `font-size = s/1.24`,
/// baseline 0.76 em below a top anchor.
pub(crate) const SVG_TEXT: Metrics = Metrics {
    baseline: 0.76 / 1.24,
    em: 1.0 / 1.24,
    advance: 1.164 / 1.24,
    whole: true,
};

/// Height of DejaVu Sans' capitals, in em.
const CAP_HEIGHT: f64 = 0.729;

/// A piece of typeset text.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Run {
    pub text: String,
    /// Size relative to the text's size.
    pub size: f64,
    /// Baseline shift, in units of the text's size, positive downwards.
    pub shift: f64,
    /// A bar is drawn over this run (one letter).
    pub bar: bool,
}

pub(crate) const SUB: (f64, f64) = (0.72, 0.2);
pub(crate) const SUP: (f64, f64) = (0.72, -0.36);
const MACRON: char = '\u{304}';

/// Splits a text into runs of plain text, subscripts, superscripts and barred letters.
pub(crate) fn typeset(text: &str) -> Vec<Run> {
    let chars: Vec<char> = text.chars().collect();
    let mut runs: Vec<Run> = Vec::new();
    let mut plain = String::new();
    let flush = |plain: &mut String, runs: &mut Vec<Run>| {
        if !plain.is_empty() {
            runs.push(Run {
                text: std::mem::take(plain),
                size: 1.0,
                shift: 0.0,
                bar: false,
            });
        }
    };
    let word = |c: Option<&char>| c.is_some_and(|c| c.is_alphanumeric());
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c == MACRON {
            if let Some(letter) = plain.pop() {
                flush(&mut plain, &mut runs);
                runs.push(Run {
                    text: letter.to_string(),
                    size: 1.0,
                    shift: 0.0,
                    bar: true,
                });
            }
            i += 1;
            continue;
        }
        if (c == '_' || c == '^') && chars.get(i + 1) == Some(&'{') {
            if let Some(end) = chars[i + 2..].iter().position(|&d| d == '}') {
                flush(&mut plain, &mut runs);
                let (size, shift) = if c == '_' { SUB } else { SUP };
                runs.push(Run {
                    text: chars[i + 2..i + 2 + end].iter().collect(),
                    size,
                    shift,
                    bar: false,
                });
                i += end + 3;
                continue;
            }
        }
        // `_c` after a one-letter name (a letter, possibly barred, not preceded by a letter).
        let base = i.checked_sub(1).map(|b| {
            if chars[b] == MACRON {
                b.saturating_sub(1)
            } else {
                b
            }
        });
        if c == '_'
            && base.is_some_and(|b| {
                chars[b].is_alphabetic() && !word(b.checked_sub(1).map(|p| &chars[p]))
            })
            && word(chars.get(i + 1))
            && !word(chars.get(i + 2))
        {
            flush(&mut plain, &mut runs);
            runs.push(Run {
                text: chars[i + 1].to_string(),
                size: SUB.0,
                shift: SUB.1,
                bar: false,
            });
            i += 2;
            continue;
        }
        plain.push(c);
        i += 1;
    }
    flush(&mut plain, &mut runs);
    runs
}

/// A stroke of a colour and width.
struct Stroke {
    color: BackendColor,
    width: u32,
}

impl BackendStyle for Stroke {
    fn color(&self) -> BackendColor {
        self.color
    }
    fn stroke_width(&self) -> u32 {
        self.width
    }
}

/// The backend of every figure: `inner` drawn at `scale` times the size the figure sees, with
/// math typeset in text.
/// Where a box of `w` × `h` starts relative to its anchor point: (0, 0) for the top left,
/// (−w/2, −h/2) for the centre, (−w, −h) for the bottom right.
pub(crate) fn anchor_offset(anchor: Pos, w: f64, h: f64) -> (f64, f64) {
    let dx = match anchor.h_pos {
        HPos::Left => 0.0,
        HPos::Center => -w / 2.0,
        HPos::Right => -w,
    };
    let dy = match anchor.v_pos {
        VPos::Top => 0.0,
        VPos::Center => -h / 2.0,
        VPos::Bottom => -h,
    };
    (dx, dy)
}

pub(crate) struct Canvas<B> {
    inner: B,
    scale: i32,
    metrics: Metrics,
    /// `inner` is a vector backend ([`super::svg::Svg`]): a rectangle from `a` to `b` covers
    /// `b − a` units (not `b − a + 1` pixels), and a bitmap is handed on at its own resolution,
    /// not enlarged.
    vector: bool,
}

/// A figure unit is split into this many steps for the shapes drawn with [`Fine`]: plotters
/// hands its backends whole units ([`BackendCoord`] is integer), which shows as steps along a
/// smooth curve; a [`Fine`] shape keeps its positions to 1/`SUBUNIT` of a unit.
pub(crate) const SUBUNIT: i32 = 10;

thread_local! {
    /// Set while a [`Fine`] shape is drawn: coordinates are in 1/[`SUBUNIT`] figure units.
    static FINE: Cell<bool> = const { Cell::new(false) };
    /// Set by a [`Canvas`] that answers [`Fine`]'s probe.
    static FINE_OK: Cell<bool> = const { Cell::new(false) };
    /// Set while a [`FineWidth`] line is drawn: its width in 1/[`SUBUNIT`] figure units.
    static WIDTH: Cell<Option<u32>> = const { Cell::new(None) };
}

/// The pixel [`Fine`] probes its backend with: a [`Canvas`] answers it and draws nothing.
const PROBE: BackendCoord = (i32::MIN, i32::MIN);

impl<B: DrawingBackend> Canvas<B> {
    /// `inner` must be `scale` times the figure's size in both directions.
    pub fn new(inner: B, scale: u32, metrics: Metrics) -> Self {
        Self {
            inner,
            scale: scale.max(1) as i32,
            metrics,
            vector: false,
        }
    }

    /// The same canvas over a vector backend (see the field `vector`).
    pub fn vector(mut self) -> Self {
        self.vector = true;
        self
    }

    /// The inner position of a figure position, or of a [`Fine`] one (in 1/[`SUBUNIT`] units).
    fn up(&self, (x, y): BackendCoord) -> BackendCoord {
        if FINE.get() {
            let k = f64::from(self.scale) / f64::from(SUBUNIT);
            let f = |v: i32| (f64::from(v) * k).round() as i32;
            (f(x), f(y))
        } else {
            (x * self.scale, y * self.scale)
        }
    }

    /// The end of a rectangle's inner extent: `scale − 1` pixels further on a bitmap (its last
    /// pixel), none on a vector backend.
    fn far(&self) -> i32 {
        if self.vector {
            0
        } else {
            self.scale - 1
        }
    }

    fn stroke<S: BackendStyle>(&self, style: &S) -> Stroke {
        // A [`FineWidth`] line: its width to 1/SUBUNIT of a unit, at least one inner unit.
        let width = match WIDTH.get() {
            Some(w) if FINE.get() => {
                ((w as i32 * self.scale + SUBUNIT / 2) / SUBUNIT).max(1) as u32
            }
            _ => style.stroke_width() * self.scale as u32,
        };
        Stroke {
            color: style.color(),
            width,
        }
    }
}

/// The text style of a run: the family, style, colour and rotation of `style` at `size`.
fn run_style<'a, T: BackendTextStyle>(style: &'a T, size: f64) -> TextStyle<'a> {
    let c = style.color();
    let font = FontDesc::new(
        FontFamily::Name(style.family().as_str_static_or_sans()),
        size,
        style.style(),
    );
    TextStyle {
        font: font.transform(style.transform()),
        color: c,
        pos: Pos::new(HPos::Left, VPos::Top),
    }
}

/// plotters' `FontFamily` borrows its name; every figure uses [`super::chart::FONT`], and the
/// few generic families plotters knows are kept.
trait FamilyName {
    fn as_str_static_or_sans(&self) -> &'static str;
}

impl FamilyName for FontFamily<'_> {
    fn as_str_static_or_sans(&self) -> &'static str {
        match self.as_str() {
            "serif" => "serif",
            "monospace" => "monospace",
            _ => super::chart::FONT,
        }
    }
}

type Res<E> = Result<(), DrawingErrorKind<E>>;

fn font_err<E: std::error::Error + Send + Sync, F: std::error::Error + Send + Sync + 'static>(
    e: F,
) -> DrawingErrorKind<E> {
    DrawingErrorKind::FontError(Box::new(e))
}

/// Layout of typeset runs at main size `s` (in the inner backend's pixels): each run's width,
/// and the whole text's width and height.
fn layout<T: BackendTextStyle, E: std::error::Error + Send + Sync>(
    runs: &[Run],
    style: &T,
    s: f64,
    advance: f64,
) -> Result<(Vec<f64>, f64, f64), DrawingErrorKind<E>> {
    let mut widths = Vec::with_capacity(runs.len());
    for r in runs {
        let ((x0, _), (x1, _)) = run_style(style, s * r.size)
            .layout_box(&r.text)
            .map_err(font_err)?;
        widths.push(f64::from(x1 - x0) * advance);
    }
    let ((_, y0), (_, y1)) = run_style(style, s).layout_box("M").map_err(font_err)?;
    let total = widths.iter().sum();
    Ok((widths, total, f64::from(y1 - y0)))
}

fn is_plain(runs: &[Run]) -> bool {
    runs.len() == 1 && runs[0].size == 1.0 && runs[0].shift == 0.0 && !runs[0].bar
}

impl<B: DrawingBackend> DrawingBackend for Canvas<B> {
    type ErrorType = B::ErrorType;

    fn get_size(&self) -> (u32, u32) {
        let (w, h) = self.inner.get_size();
        (w / self.scale as u32, h / self.scale as u32)
    }

    fn ensure_prepared(&mut self) -> Res<B::ErrorType> {
        self.inner.ensure_prepared()
    }

    fn present(&mut self) -> Res<B::ErrorType> {
        self.inner.present()
    }

    fn draw_pixel(&mut self, point: BackendCoord, color: BackendColor) -> Res<B::ErrorType> {
        if point == PROBE && color.alpha == 0.0 {
            FINE_OK.set(true);
            return Ok(());
        }
        let (x, y) = self.up(point);
        let s = if self.vector {
            self.scale
        } else {
            self.scale - 1
        };
        self.inner.draw_rect((x, y), (x + s, y + s), &color, true)
    }

    fn draw_line<S: BackendStyle>(
        &mut self,
        from: BackendCoord,
        to: BackendCoord,
        style: &S,
    ) -> Res<B::ErrorType> {
        let st = self.stroke(style);
        let (a, b) = (self.up(from), self.up(to));
        self.inner.draw_line(a, b, &st)
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        upper_left: BackendCoord,
        bottom_right: BackendCoord,
        style: &S,
        fill: bool,
    ) -> Res<B::ErrorType> {
        let st = self.stroke(style);
        let a = self.up(upper_left);
        let b = self.up(bottom_right);
        let s = self.far();
        self.inner.draw_rect(a, (b.0 + s, b.1 + s), &st, fill)
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Res<B::ErrorType> {
        let st = self.stroke(style);
        let pts: Vec<BackendCoord> = path.into_iter().map(|p| self.up(p)).collect();
        self.inner.draw_path(pts, &st)
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        center: BackendCoord,
        radius: u32,
        style: &S,
        fill: bool,
    ) -> Res<B::ErrorType> {
        let st = self.stroke(style);
        let c = self.up(center);
        self.inner
            .draw_circle(c, radius * self.scale as u32, &st, fill)
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        style: &S,
    ) -> Res<B::ErrorType> {
        let pts: Vec<BackendCoord> = vert.into_iter().map(|p| self.up(p)).collect();
        self.inner.fill_polygon(pts, &style.color())
    }

    fn draw_text<T: BackendTextStyle>(
        &mut self,
        text: &str,
        style: &T,
        pos: BackendCoord,
    ) -> Res<B::ErrorType> {
        if style.color().alpha == 0.0 {
            return Ok(());
        }
        let s = style.size() * f64::from(self.scale);
        let pos = self.up(pos);
        let runs = typeset(text);
        let anchor = style.anchor();
        if is_plain(&runs) || self.metrics.whole {
            let st = run_style(style, s).pos(anchor);
            return self.inner.draw_text(text, &st, pos);
        }
        let m = self.metrics;
        let (widths, total, height) = layout(&runs, style, s, m.advance)?;
        let (dx0, dy0) = anchor_offset(anchor, total, height);
        let trans = style.transform();
        let place = |x: f64, y: f64| -> BackendCoord {
            let (u, v) = trans.transform((dx0 + x).round() as i32, (dy0 + y).round() as i32);
            (pos.0 + u, pos.1 + v)
        };
        let baseline = m.baseline * s;
        let mut x = 0.0;
        for (r, w) in runs.iter().zip(&widths) {
            let size = s * r.size;
            let base = baseline + r.shift * s;
            let top = base - m.baseline * size;
            let st = run_style(style, size);
            self.inner.draw_text(&r.text, &st, place(x, top))?;
            if r.bar {
                let em = m.em * size;
                let thick = (0.065 * em).max(1.0);
                let y1 = base - (CAP_HEIGHT + 0.09) * em;
                let a = place(x + 0.1 * w, y1 - thick);
                let b = place(x + 0.9 * w, y1);
                let c = style.color();
                self.inner.draw_rect(
                    (a.0.min(b.0), a.1.min(b.1)),
                    (a.0.max(b.0), a.1.max(b.1)),
                    &c,
                    true,
                )?;
            }
            x += w;
        }
        Ok(())
    }

    /// The bitmap is enlarged `scale` times (each pixel a block) and handed on whole, so that an
    /// SVG embeds it as one image.
    fn blit_bitmap(
        &mut self,
        pos: BackendCoord,
        (w, h): (u32, u32),
        src: &[u8],
    ) -> Res<B::ErrorType> {
        let s = self.scale as usize;
        let pos = self.up(pos);
        if self.vector {
            // A vector backend at `scale` units per figure unit takes the bitmap as it is, at
            // one pixel per figure unit ([`super::svg::Svg::blit_bitmap`]).
            let k = self.scale as u32;
            return self.inner.blit_bitmap(pos, (w * k, h * k), src);
        }
        let d = super::chart::bitmap_density();
        if d > 1 {
            // A heat map's RGBA raster at `d` pixels per unit, fitted to this bitmap's scale.
            let (rgb, size) = super::chart::fit_to_scale(src, (w, h), d, s as u32);
            return self.inner.blit_bitmap(pos, size, &rgb);
        }
        if s == 1 {
            return self.inner.blit_bitmap(pos, (w, h), src);
        }
        let (w, h) = (w as usize, h as usize);
        let mut big = vec![0u8; w * h * s * s * 3];
        for y in 0..h * s {
            for x in 0..w * s {
                let from = ((y / s) * w + x / s) * 3;
                let to = (y * w * s + x) * 3;
                big[to..to + 3].copy_from_slice(&src[from..from + 3]);
            }
        }
        self.inner
            .blit_bitmap(pos, ((w * s) as u32, (h * s) as u32), &big)
    }

    fn estimate_text_size<T: BackendTextStyle>(
        &self,
        text: &str,
        style: &T,
    ) -> Result<(u32, u32), DrawingErrorKind<B::ErrorType>> {
        let runs = typeset(text);
        let (_, total, height) = layout(&runs, style, style.size(), 1.0)?;
        Ok((total.ceil() as u32, height.ceil() as u32))
    }
}

/// A polyline or a filled polygon at positions finer than a figure unit (plotters' own elements
/// are placed at whole units), in the backend's figure coordinates (absolute, not relative to
/// a drawing area). On a [`Canvas`] its positions are kept to 1/[`SUBUNIT`] of a unit; any other
/// backend gets them rounded.
pub(crate) struct Fine {
    pub points: Vec<(f64, f64)>,
    pub colour: BackendColor,
    /// The stroke width of a polyline; `None` fills the polygon.
    pub stroke: Option<u32>,
}

impl<'a> PointCollection<'a, BackendCoord> for &'a Fine {
    type Point = &'a BackendCoord;
    type IntoIter = [&'a BackendCoord; 0];
    fn point_iter(self) -> Self::IntoIter {
        []
    }
}

impl<DB: DrawingBackend> Drawable<DB> for Fine {
    fn draw<I: Iterator<Item = BackendCoord>>(
        &self,
        _: I,
        backend: &mut DB,
        _: (u32, u32),
    ) -> Result<(), DrawingErrorKind<DB::ErrorType>> {
        FINE_OK.set(false);
        backend.draw_pixel(
            PROBE,
            BackendColor {
                alpha: 0.0,
                rgb: (0, 0, 0),
            },
        )?;
        let fine = FINE_OK.replace(false);
        let k = if fine { f64::from(SUBUNIT) } else { 1.0 };
        let pts: Vec<BackendCoord> = self
            .points
            .iter()
            .map(|&(x, y)| ((x * k).round() as i32, (y * k).round() as i32))
            .collect();
        FINE.set(fine);
        let done = match self.stroke {
            Some(width) => backend.draw_path(
                pts,
                &Stroke {
                    color: self.colour,
                    width,
                },
            ),
            None => backend.fill_polygon(pts, &self.colour),
        };
        FINE.set(false);
        done
    }
}

/// A [`Fine`] polyline whose width is given to 1/[`SUBUNIT`] of a unit (`width` in those
/// steps: 5 is half a unit), for lines narrower than plotters' whole-unit widths allow. On a
/// [`Canvas`] the width is kept to its inner units (at least one); any other backend gets it
/// rounded to whole units, at least one.
pub(crate) struct FineWidth {
    pub points: Vec<(f64, f64)>,
    pub colour: BackendColor,
    pub width: u32,
}

impl<'a> PointCollection<'a, BackendCoord> for &'a FineWidth {
    type Point = &'a BackendCoord;
    type IntoIter = [&'a BackendCoord; 0];
    fn point_iter(self) -> Self::IntoIter {
        []
    }
}

impl<DB: DrawingBackend> Drawable<DB> for FineWidth {
    fn draw<I: Iterator<Item = BackendCoord>>(
        &self,
        _: I,
        backend: &mut DB,
        parent: (u32, u32),
    ) -> Result<(), DrawingErrorKind<DB::ErrorType>> {
        let line = Fine {
            points: self.points.clone(),
            colour: self.colour,
            stroke: Some(((self.width + SUBUNIT as u32 / 2) / SUBUNIT as u32).max(1)),
        };
        WIDTH.set(Some(self.width));
        let done = line.draw(std::iter::empty(), backend, parent);
        WIDTH.set(None);
        done
    }
}

/// Averages `scale × scale` blocks of an RGB image of `(w·scale) × (h·scale)` pixels.
pub(crate) fn downsample(big: &[u8], w: u32, h: u32, scale: u32) -> Vec<u8> {
    let (w, h, s) = (w as usize, h as usize, scale as usize);
    let bw = w * s;
    let mut out = vec![0u8; w * h * 3];
    let n = (s * s) as u32;
    for y in 0..h {
        for x in 0..w {
            for ch in 0..3 {
                let mut sum = 0u32;
                for dy in 0..s {
                    let row = (y * s + dy) * bw;
                    for dx in 0..s {
                        sum += u32::from(big[(row + x * s + dx) * 3 + ch]);
                    }
                }
                out[(y * w + x) * 3 + ch] = ((sum + n / 2) / n) as u8;
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn texts(runs: &[Run]) -> Vec<(&str, bool, bool)> {
        runs.iter()
            .map(|r| (r.text.as_str(), r.shift > 0.0, r.bar))
            .collect()
    }

    #[test]
    fn subscripts_superscripts_and_bars_are_recognised() {
        let r = typeset("S\u{304} = M_x M_z");
        assert_eq!(
            texts(&r),
            vec![
                ("S", false, true),
                (" = M", false, false),
                ("x", true, false),
                (" M", false, false),
                ("z", true, false)
            ]
        );
        let r = typeset("k((f/n)^{1/k} − 1)");
        assert_eq!(r[1].text, "1/k");
        assert!(r[1].shift < 0.0 && r[1].size < 1.0);
        assert_eq!(r[2].text, " − 1)");
        let r = typeset("γ_{lim} = 3");
        assert_eq!(
            texts(&r),
            vec![
                ("γ", false, false),
                ("lim", true, false),
                (" = 3", false, false)
            ]
        );
        // Code names are left alone.
        for code in [
            "warp::n_prime_from_eta",
            "distribution_g, n_from_xi",
            "n_prime_1, x",
        ] {
            let r = typeset(code);
            assert_eq!(r.len(), 1, "{code}");
            assert_eq!(r[0].text, code);
        }
        assert!(is_plain(&typeset("plain text 10⁴")));
    }

    #[test]
    fn downsampling_averages_blocks() {
        // 4 × 2 pixels at scale 2 → 2 × 1: a white and a black block, and a half-grey one.
        let mut big = vec![255u8; 4 * 2 * 3];
        for (x, y) in [(2, 0), (3, 0), (2, 1)] {
            for c in 0..3 {
                big[(y * 4 + x) * 3 + c] = 0;
            }
        }
        let small = downsample(&big, 2, 1, 2);
        assert_eq!(small, vec![255, 255, 255, 64, 64, 64]);
    }
}
