//! The SVG writer every figure's SVG is drawn with (in place of plotters' own SVG backend):
//!
//! - each text is ONE `<text>` element with `xml:space="preserve"`: subscripts and superscripts
//!   are `<tspan>`s moved by `dy` and smaller, a barred letter (`S̄`) is a `<tspan>` with
//!   `text-decoration="overline"`, so the text stays one flow whatever font the viewer
//!   substitutes;
//! - the family is a list, [`FAMILY`], led by the DejaVu Sans whose metrics the layout uses;
//! - a bitmap ([`DrawingBackend::blit_bitmap`], used for heat maps) is one embedded PNG
//!   `<image>`, not one rectangle per pixel;
//! - it can be drawn at `k` units per unit of its view box ([`Svg::units`]): positions, sizes
//!   and stroke widths are written divided by `k`, so that shapes placed finer than a unit
//!   ([`super::canvas::Fine`]) keep their positions.

use super::canvas::{typeset, Run, SUB, SUP};
use image::ImageEncoder;
use plotters::style::text_anchor::{HPos, VPos};
use plotters::style::{FontStyle, FontTransform};
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingBackend, DrawingErrorKind,
};
use std::fmt::Write;

/// The font families an SVG asks for, first the one its layout was measured with.
pub(crate) const FAMILY: &str = "'DejaVu Sans', 'Liberation Sans', Arial, Helvetica, sans-serif";

/// plotters' text size `s` is drawn as `font-size = s / 1.24` (DejaVu's line height), as
/// plotters' own SVG backend does, so that the layout measured with DejaVu fits.
const FONT_SIZE: f64 = 1.0 / 1.24;

/// Why an SVG could not be written.
#[derive(Debug)]
pub(crate) struct SvgError(String);

impl std::fmt::Display for SvgError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for SvgError {}

/// An SVG document drawn into a string.
pub(crate) struct Svg<'a> {
    out: &'a mut String,
    size: (u32, u32),
    /// The document's `width` and `height` are `zoom` times its view box, in points (one unit of
    /// the view box a point at `zoom` 1).
    zoom: u32,
    /// Backend units per unit of the view box.
    k: u32,
    body: String,
}

impl<'a> Svg<'a> {
    pub fn new(out: &'a mut String, size: (u32, u32), zoom: u32) -> Self {
        Self {
            out,
            size,
            zoom,
            k: 1,
            body: String::new(),
        }
    }

    /// The same document drawn at `k` backend units per unit of its view box: its size as a
    /// backend is `k` times `size`, and everything is written divided by `k`.
    pub fn units(mut self, k: u32) -> Self {
        self.k = k.max(1);
        self
    }

    /// A length or position in view-box units (to 1/1000).
    fn u(&self, v: i32) -> f64 {
        round(f64::from(v) / f64::from(self.k))
    }

    /// A list of points as `x,y x,y …` in view-box units.
    fn points(&self, pts: impl IntoIterator<Item = BackendCoord>) -> String {
        let mut s = String::new();
        for (x, y) in pts {
            let _ = write!(s, "{},{} ", self.u(x), self.u(y));
        }
        s.truncate(s.trim_end().len());
        s
    }

    /// A shape's fill or outline attributes: filled without a stroke, or stroked without a fill.
    fn paint<S: BackendStyle>(&self, st: &S, fill: bool) -> String {
        let c = colour(st.color());
        if fill {
            format!("fill=\"{c}\" stroke=\"none\"")
        } else {
            format!(
                "fill=\"none\" stroke=\"{c}\" stroke-width=\"{}\"",
                self.width(st)
            )
        }
    }

    /// A style's stroke width in view-box units.
    fn width<S: BackendStyle>(&self, st: &S) -> f64 {
        self.u(st.stroke_width() as i32)
    }
}

fn colour(c: BackendColor) -> String {
    let (r, g, b) = c.rgb;
    format!("#{r:02X}{g:02X}{b:02X}")
}

fn opacity(c: BackendColor) -> String {
    if c.alpha >= 1.0 {
        String::new()
    } else {
        format!(" opacity=\"{}\"", c.alpha)
    }
}

/// Escapes text for XML character data and attribute values.
pub(crate) fn escape(text: &str) -> String {
    let mut s = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => s.push_str("&amp;"),
            '<' => s.push_str("&lt;"),
            '>' => s.push_str("&gt;"),
            '"' => s.push_str("&quot;"),
            '\'' => s.push_str("&apos;"),
            c => s.push(c),
        }
    }
    s
}

/// Standard base64 (RFC 4648, with padding), for the data URLs of embedded images.
pub(crate) fn base64(bytes: &[u8]) -> String {
    const A: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut s = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            chunk.get(1).copied().unwrap_or(0),
            chunk.get(2).copied().unwrap_or(0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                s.push(A[((n >> (18 - 6 * k)) & 63) as usize] as char);
            } else {
                s.push('=');
            }
        }
    }
    s
}

/// The digit or sign a Unicode superscript or subscript character stands for, and which.
fn unscript(c: char) -> Option<(char, (f64, f64))> {
    const DIGITS: &str = "0123456789";
    if let Some(i) = "⁰¹²³⁴⁵⁶⁷⁸⁹".chars().position(|d| d == c) {
        return DIGITS.chars().nth(i).map(|d| (d, SUP));
    }
    if let Some(i) = "₀₁₂₃₄₅₆₇₈₉".chars().position(|d| d == c) {
        return DIGITS.chars().nth(i).map(|d| (d, SUB));
    }
    match c {
        '⁻' => Some(('\u{2212}', SUP)),
        '⁺' => Some(('+', SUP)),
        '₋' => Some(('\u{2212}', SUB)),
        '₊' => Some(('+', SUB)),
        _ => None,
    }
}

/// The runs with every Unicode superscript or subscript digit (10⁴, 10⁻⁶, 5², log₁₀, g₀)
/// written as a raised or lowered, smaller plain digit or sign: Liberation Sans and Arial,
/// which a viewer without DejaVu Sans substitutes, have no glyphs for ⁰, ⁴–⁹ or the subscripts.
pub(crate) fn plain_scripts(runs: Vec<Run>) -> Vec<Run> {
    let mut out: Vec<Run> = Vec::with_capacity(runs.len());
    for r in runs {
        if r.bar || !r.text.chars().any(|c| unscript(c).is_some()) {
            out.push(r);
            continue;
        }
        // Pieces of the run: the script of each (none for plain text) and its text.
        let mut cur: Option<(Option<(f64, f64)>, String)> = None;
        let flush = |cur: &mut Option<(Option<(f64, f64)>, String)>, out: &mut Vec<Run>| {
            if let Some((script, text)) = cur.take() {
                let (size, shift) = match script {
                    Some((size, shift)) => (r.size * size, r.shift + shift * r.size),
                    None => (r.size, r.shift),
                };
                out.push(Run {
                    text,
                    size,
                    shift,
                    bar: false,
                });
            }
        };
        for c in r.text.chars() {
            let (script, c) = match unscript(c) {
                Some((d, s)) => (Some(s), d),
                None => (None, c),
            };
            match &mut cur {
                Some((s, text)) if *s == script => text.push(c),
                _ => {
                    flush(&mut cur, &mut out);
                    cur = Some((script, c.to_string()));
                }
            }
        }
        flush(&mut cur, &mut out);
    }
    out
}

/// The `<tspan>`s of typeset runs at font size `f`: each shifted run moves the baseline by `dy`
/// and the next run moves it back.
pub(crate) fn tspans(runs: &[Run], f: f64) -> String {
    let mut s = String::new();
    let mut shift = 0.0;
    for r in runs {
        let plain = r.size == 1.0 && r.shift == 0.0 && !r.bar;
        let dy = (r.shift - shift) * f;
        shift = r.shift;
        if plain && dy == 0.0 {
            s.push_str(&escape(&r.text));
            continue;
        }
        s.push_str("<tspan");
        if dy != 0.0 {
            let _ = write!(s, " dy=\"{}\"", round(dy));
        }
        if r.size != 1.0 {
            let _ = write!(s, " font-size=\"{}\"", round(f * r.size));
        }
        if r.bar {
            s.push_str(" text-decoration=\"overline\"");
        }
        let _ = write!(s, ">{}</tspan>", escape(&r.text));
    }
    s
}

fn round(v: f64) -> f64 {
    (v * 1000.0).round() / 1000.0
}

type Res = Result<(), DrawingErrorKind<SvgError>>;

impl DrawingBackend for Svg<'_> {
    type ErrorType = SvgError;

    fn get_size(&self) -> (u32, u32) {
        (self.size.0 * self.k, self.size.1 * self.k)
    }

    fn ensure_prepared(&mut self) -> Res {
        Ok(())
    }

    fn present(&mut self) -> Res {
        let (w, h) = self.size;
        // A bare page keeps only its box (`chart::bare_crop`): the view box is that box.
        let [left, top, right, bottom] = super::chart::bare_crop().unwrap_or([0, 0, w, h]);
        let (right, bottom) = (right.min(w), bottom.min(h));
        let (left, top) = (left.min(right), top.min(bottom));
        let (cols, rows) = (right - left, bottom - top);
        // In points: `zoom` times the view box at the column's points per unit.
        let pt = f64::from(self.zoom) * super::chart::column().points_per_unit();
        let (zw, zh) = (round(f64::from(cols) * pt), round(f64::from(rows) * pt));
        self.out.clear();
        let _ = write!(
            self.out,
            "<svg width=\"{zw}pt\" height=\"{zh}pt\" viewBox=\"{left} {top} {cols} {rows}\" \
             xmlns=\"http://www.w3.org/2000/svg\">\n{}</svg>\n",
            self.body
        );
        Ok(())
    }

    fn draw_pixel(&mut self, (x, y): BackendCoord, c: BackendColor) -> Res {
        if c.alpha == 0.0 {
            return Ok(());
        }
        let _ = writeln!(
            self.body,
            "<rect x=\"{}\" y=\"{}\" width=\"1\" height=\"1\" fill=\"{}\"{}/>",
            self.u(x),
            self.u(y),
            colour(c),
            opacity(c)
        );
        Ok(())
    }

    fn draw_line<S: BackendStyle>(&mut self, a: BackendCoord, b: BackendCoord, st: &S) -> Res {
        let c = st.color();
        let _ = writeln!(
            self.body,
            "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" stroke-width=\"{}\"{}/>",
            self.u(a.0),
            self.u(a.1),
            self.u(b.0),
            self.u(b.1),
            colour(c),
            self.width(st),
            opacity(c)
        );
        Ok(())
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        a: BackendCoord,
        b: BackendCoord,
        st: &S,
        fill: bool,
    ) -> Res {
        let c = st.color();
        let paint = self.paint(st, fill);
        let _ = writeln!(
            self.body,
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" {paint}{}/>",
            self.u(a.0),
            self.u(a.1),
            self.u(b.0 - a.0),
            self.u(b.1 - a.1),
            opacity(c)
        );
        Ok(())
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        st: &S,
    ) -> Res {
        let c = st.color();
        let pts = self.points(path);
        let _ = writeln!(
            self.body,
            "<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"{} points=\"{pts}\"/>",
            colour(c),
            self.width(st),
            opacity(c),
        );
        Ok(())
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        (x, y): BackendCoord,
        r: u32,
        st: &S,
        fill: bool,
    ) -> Res {
        let c = st.color();
        let paint = self.paint(st, fill);
        let _ = writeln!(
            self.body,
            "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" {paint}{}/>",
            self.u(x),
            self.u(y),
            self.u(r as i32),
            opacity(c)
        );
        Ok(())
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        st: &S,
    ) -> Res {
        let c = st.color();
        let pts = self.points(vert);
        let _ = writeln!(
            self.body,
            "<polygon fill=\"{}\"{} points=\"{pts}\"/>",
            colour(c),
            opacity(c),
        );
        Ok(())
    }

    fn draw_text<T: BackendTextStyle>(&mut self, text: &str, st: &T, (x, y): BackendCoord) -> Res {
        let c = st.color();
        if c.alpha == 0.0 {
            return Ok(());
        }
        let anchor = st.anchor();
        let h = match anchor.h_pos {
            HPos::Left => "start",
            HPos::Center => "middle",
            HPos::Right => "end",
        };
        let dy = match anchor.v_pos {
            VPos::Top => "0.76em",
            VPos::Center => "0.5ex",
            VPos::Bottom => "-0.5ex",
        };
        let f = round(st.size() / f64::from(self.k) * FONT_SIZE);
        let (x, y) = (self.u(x), self.u(y));
        let mut attrs = format!(
            "x=\"{x}\" y=\"{y}\" dy=\"{dy}\" text-anchor=\"{h}\" font-family=\"{FAMILY}\" \
             font-size=\"{f}\" fill=\"{}\"{}",
            colour(c),
            opacity(c)
        );
        match st.style() {
            FontStyle::Normal => {}
            FontStyle::Bold => attrs.push_str(" font-weight=\"bold\""),
            other => {
                let _ = write!(attrs, " font-style=\"{}\"", other.as_str());
            }
        }
        let angle = match st.transform() {
            FontTransform::Rotate90 => 90,
            FontTransform::Rotate180 => 180,
            FontTransform::Rotate270 => 270,
            _ => 0,
        };
        if angle != 0 {
            let _ = write!(attrs, " transform=\"rotate({angle}, {x}, {y})\"");
        }
        let _ = writeln!(
            self.body,
            "<text xml:space=\"preserve\" {attrs}>{}</text>",
            tspans(&plain_scripts(typeset(text)), f)
        );
        Ok(())
    }

    /// The bitmap's pixels are view-box units: at `k` units per view-box unit, `(w, h)` is `k`
    /// times the bitmap's size in pixels (as [`super::canvas::Canvas`] hands it on).
    fn blit_bitmap(&mut self, (x, y): BackendCoord, (w, h): (u32, u32), src: &[u8]) -> Res {
        let (w, h) = (w / self.k, h / self.k);
        // A heat map's raster: RGBA at `d` pixels per view-box unit
        // (super::chart::bitmap_density); any other bitmap RGB at one.
        let d = super::chart::bitmap_density();
        let (bytes, kind) = if d > 1 {
            (4, image::ExtendedColorType::Rgba8)
        } else {
            (3, image::ExtendedColorType::Rgb8)
        };
        if src.len() != (w * h * bytes) as usize {
            return Err(DrawingErrorKind::DrawingError(SvgError(format!(
                "a bitmap of {} bytes is not {w} × {h} pixels of {bytes} bytes",
                src.len()
            ))));
        }
        let (x, y) = (self.u(x), self.u(y));
        let mut png = Vec::new();
        image::codecs::png::PngEncoder::new(&mut png)
            .write_image(src, w, h, kind)
            .map_err(|e| DrawingErrorKind::DrawingError(SvgError(e.to_string())))?;
        let _ = writeln!(
            self.body,
            "<image x=\"{x}\" y=\"{y}\" width=\"{}\" height=\"{}\" \
             preserveAspectRatio=\"none\" href=\"data:image/png;base64,{}\"/>",
            round(f64::from(w) / f64::from(d)),
            round(f64::from(h) / f64::from(d)),
            base64(&png)
        );
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_matches_rfc4648_examples() {
        // RFC 4648 §10 test vectors.
        for (plain, coded) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(plain.as_bytes()), coded, "{plain}");
        }
    }

    #[test]
    fn subscripts_and_bars_are_tspans_of_one_text() {
        let s = tspans(&typeset("S\u{304} = M_x M_z"), 10.0);
        assert_eq!(
            s,
            "<tspan text-decoration=\"overline\">S</tspan> = M<tspan dy=\"2\" \
             font-size=\"7.2\">x</tspan><tspan dy=\"-2\"> M</tspan><tspan dy=\"2\" \
             font-size=\"7.2\">z</tspan>"
        );
        assert_eq!(tspans(&typeset("a < b & c"), 10.0), "a &lt; b &amp; c");
    }

    /// Unicode superscripts and subscripts are raised or lowered plain digits (Liberation Sans
    /// has no ⁰, ⁴–⁹ or ₀–₉: rendered with rsvg-convert under a fontconfig holding only
    /// Liberation, they showed as boxes).
    #[test]
    fn scripts_are_raised_or_lowered_plain_digits() {
        let s = tspans(&plain_scripts(typeset("α = 10⁴, 10⁻⁶ of 2")), 10.0);
        assert_eq!(
            s,
            "α = 10<tspan dy=\"-3.6\" font-size=\"7.2\">4</tspan><tspan dy=\"3.6\">, \
             10</tspan><tspan dy=\"-3.6\" font-size=\"7.2\">\u{2212}6</tspan><tspan \
             dy=\"3.6\"> of 2</tspan>"
        );
        // Inside a subscript, raised from the subscript's baseline at its size.
        let r = plain_scripts(typeset("x_{a²}"));
        assert_eq!(r.last().unwrap().text, "2");
        assert!((r.last().unwrap().shift - (0.2 - 0.36 * 0.72)).abs() < 1e-12);
        assert!(!tspans(&plain_scripts(typeset("10⁰ ⁹")), 10.0).contains('⁰'));
        // Subscript digits are lowered plain digits.
        assert_eq!(
            tspans(&plain_scripts(typeset("log₁₀ S")), 10.0),
            "log<tspan dy=\"2\" font-size=\"7.2\">10</tspan><tspan dy=\"-2\"> S</tspan>"
        );
    }
}
