//! PNG output, every image titled with its case: the shaded frame; the rendered error (log scale,
//! viridis) beside the ratio rendered / predicted (diverging, ±1 %), each with its colour bar and
//! the "not compared" swatch; and the close-up of a shadow edge (the jaggies beside the predicted
//! error, as Lloyd 2006 Fig 1); the error lens the GPU drew over the scene, with the ramp's
//! legend. Text is DejaVu Sans (compiled in), rasterized by `ab_glyph`.

use ab_glyph::{point, Font, FontRef, PxScale, ScaleFont};
use image::{Rgb, RgbImage};
use std::sync::OnceLock;

/// matplotlib's viridis at 9 evenly spaced stops (perceptually uniform), interpolated linearly.
const VIRIDIS: [[f64; 3]; 9] = [
    [68.0, 1.0, 84.0],
    [71.0, 44.0, 122.0],
    [59.0, 81.0, 139.0],
    [44.0, 113.0, 142.0],
    [33.0, 144.0, 141.0],
    [39.0, 173.0, 129.0],
    [92.0, 200.0, 99.0],
    [170.0, 220.0, 50.0],
    [253.0, 231.0, 37.0],
];

/// A diverging map (Moreland's cool–warm end points, white centre) for the ratio.
const DIVERGING: [[f64; 3]; 3] = [
    [59.0, 76.0, 192.0],
    [247.0, 247.0, 247.0],
    [180.0, 4.0, 38.0],
];

/// Pixels not compared (sky, discontinuities, no prediction).
pub const NOT_COMPARED: Rgb<u8> = Rgb([110, 110, 110]);

/// The log10 range of the error maps: 10⁻² to 10² pixels per texel.
pub const LOG_RANGE: (f64, f64) = (-2.0, 2.0);

/// Half the range of the ratio map around 1 (the targets' 1 %).
pub const RATIO_HALF_RANGE: f64 = 0.01;

const WHITE: Rgb<u8> = Rgb([255, 255, 255]);
const BLACK: Rgb<u8> = Rgb([0, 0, 0]);
/// Heights of the title bar, the caption row and the legend row; width of a colour-bar column.
const TITLE: u32 = 30;
const CAPTION: u32 = 24;
const LEGEND: u32 = 28;
const BAR: u32 = 100;

fn ramp(stops: &[[f64; 3]], t: f64) -> Rgb<u8> {
    let n = stops.len() - 1;
    let t = t.clamp(0.0, 1.0) * n as f64;
    let i = (t.floor() as usize).min(n - 1);
    let f = t - i as f64;
    let c = |k: usize| (stops[i][k] * (1.0 - f) + stops[i + 1][k] * f).round() as u8;
    Rgb([c(0), c(1), c(2)])
}

/// Viridis at `t` ∈ [0, 1].
pub fn viridis(t: f64) -> Rgb<u8> {
    ramp(&VIRIDIS, t)
}

/// The error colour of `e` pixels per texel (log scale, [`LOG_RANGE`]), [`NOT_COMPARED`] when
/// not a positive number.
pub fn error_colour(e: f64) -> Rgb<u8> {
    let (lo, hi) = LOG_RANGE;
    if e.is_finite() && e > 0.0 {
        viridis((e.log10() - lo) / (hi - lo))
    } else {
        NOT_COMPARED
    }
}

/// The ratio colour of `r` (1 white, ±[`RATIO_HALF_RANGE`] saturated), [`NOT_COMPARED`] when not
/// a number.
pub fn ratio_colour(r: f64) -> Rgb<u8> {
    if r.is_finite() {
        ramp(&DIVERGING, 0.5 + 0.5 * (r - 1.0) / RATIO_HALF_RANGE)
    } else {
        NOT_COMPARED
    }
}

fn font() -> &'static FontRef<'static> {
    static FONT: OnceLock<FontRef<'static>> = OnceLock::new();
    FONT.get_or_init(|| {
        // The compiled-in font parses (a build problem otherwise, not an input error).
        FontRef::try_from_slice(dejavu::sans::regular()).expect("DejaVu Sans is a valid font")
    })
}

/// Draws `s` with its top left at `(x, y)`, `px` pixels high, anti-aliased over the image.
pub fn text(img: &mut RgbImage, x: i32, y: i32, px: f32, s: &str, col: Rgb<u8>) {
    let f = font();
    let scaled = f.as_scaled(PxScale::from(px));
    let mut caret = point(x as f32, y as f32 + scaled.ascent());
    let mut prev = None;
    for c in s.chars() {
        let id = scaled.glyph_id(c);
        if let Some(p) = prev {
            caret.x += scaled.kern(p, id);
        }
        prev = Some(id);
        let g = id.with_scale_and_position(px, caret);
        caret.x += scaled.h_advance(id);
        let Some(o) = f.outline_glyph(g) else {
            continue;
        };
        let b = o.px_bounds();
        o.draw(|gx, gy, cov| {
            let (px_, py_) = (b.min.x as i32 + gx as i32, b.min.y as i32 + gy as i32);
            if px_ < 0 || py_ < 0 || px_ >= img.width() as i32 || py_ >= img.height() as i32 {
                return;
            }
            let p = img.get_pixel_mut(px_ as u32, py_ as u32);
            for k in 0..3 {
                p[k] = (f32::from(p[k]) * (1.0 - cov) + f32::from(col[k]) * cov).round() as u8;
            }
        });
    }
}

/// The width of `s` at `px` pixels high.
fn text_width(px: f32, s: &str) -> f32 {
    let scaled = font().as_scaled(PxScale::from(px));
    s.chars()
        .map(|c| scaled.h_advance(scaled.glyph_id(c)))
        .sum()
}

fn title_bar(img: &mut RgbImage, title: &str) {
    for y in 0..TITLE {
        for x in 0..img.width() {
            img.put_pixel(x, y, Rgb([32, 32, 40]));
        }
    }
    text(img, 8, 6, 17.0, title, WHITE);
}

/// A vertical colour bar at `(x, y)`, `h` high, with labels at the given fractions (0 bottom).
fn colour_bar(
    img: &mut RgbImage,
    (x, y, h): (u32, u32, u32),
    colour: impl Fn(f64) -> Rgb<u8>,
    ticks: &[(f64, &str)],
) {
    for dy in 0..h {
        let t = 1.0 - f64::from(dy) / f64::from(h - 1);
        for dx in 0..16 {
            img.put_pixel(x + dx, y + dy, colour(t));
        }
    }
    for &(t, label) in ticks {
        let ty = y + ((1.0 - t) * f64::from(h - 1)).round() as u32;
        for dx in 16..21 {
            img.put_pixel(x + dx, ty, BLACK);
        }
        let ly = (ty as i32 - 8).clamp(y as i32, (y + h) as i32 - 16);
        text(img, (x + 24) as i32, ly, 13.0, label, BLACK);
    }
}

/// The "not compared" swatch and its words at `(x, y)`.
fn not_compared_swatch(img: &mut RgbImage, x: u32, y: u32) {
    for dy in 0..14 {
        for dx in 0..22 {
            img.put_pixel(x + dx, y + dy, NOT_COMPARED);
        }
    }
    text(
        img,
        (x + 28) as i32,
        y as i32 - 2,
        14.0,
        "not compared",
        BLACK,
    );
}

/// The shaded frame with a title bar (partitions faintly tinted by the shader).
pub fn shaded(color: &[[u8; 4]], w: u32, h: u32, title: &str) -> RgbImage {
    let mut img = RgbImage::from_pixel(w, h + TITLE, WHITE);
    for y in 0..h {
        for x in 0..w {
            let c = color[(y * w + x) as usize];
            img.put_pixel(x, y + TITLE, Rgb([c[0], c[1], c[2]]));
        }
    }
    title_bar(&mut img, title);
    img
}

const ERROR_TICKS: [(f64, &str); 5] = [
    (0.0, "0.01"),
    (0.25, "0.1"),
    (0.5, "1"),
    (0.75, "10"),
    (1.0, "100"),
];

/// The rendered error (left, pixels per texel, log scale) beside the ratio rendered / predicted
/// (right, 1 ± 1 %), each with its colour bar, under a title bar; the legend row has the
/// "not compared" swatch.
pub fn error_panels(rendered: &[f64], predicted: &[f64], w: u32, h: u32, title: &str) -> RgbImage {
    let top = TITLE + CAPTION;
    let mut img = RgbImage::from_pixel(2 * (w + BAR), top + h + LEGEND, WHITE);
    let x2 = w + BAR;
    for y in 0..h {
        for x in 0..w {
            let i = (y * w + x) as usize;
            let (r, p) = (rendered[i], predicted[i]);
            img.put_pixel(x, y + top, error_colour(r));
            let ratio = if r.is_finite() && p.is_finite() && p > 0.0 {
                r / p
            } else {
                f64::NAN
            };
            img.put_pixel(x2 + x, y + top, ratio_colour(ratio));
        }
    }
    title_bar(&mut img, title);
    text(
        &mut img,
        4,
        TITLE as i32 + 3,
        15.0,
        "rendered error, pixels per texel (log)",
        BLACK,
    );
    text(
        &mut img,
        x2 as i32 + 4,
        TITLE as i32 + 3,
        15.0,
        "rendered / predicted error",
        BLACK,
    );
    colour_bar(&mut img, (w + 8, top, h), viridis, &ERROR_TICKS);
    let d = RATIO_HALF_RANGE;
    let labels = [
        format!("{:.3}", 1.0 - d),
        format!("{:.3}", 1.0 - d / 2.0),
        "1".to_string(),
        format!("{:.3}", 1.0 + d / 2.0),
        format!("{:.3}", 1.0 + d),
    ];
    let ticks: Vec<(f64, &str)> = labels
        .iter()
        .enumerate()
        .map(|(k, l)| (k as f64 / 4.0, l.as_str()))
        .collect();
    colour_bar(
        &mut img,
        (x2 + w + 8, top, h),
        |t| ramp(&DIVERGING, t),
        &ticks,
    );
    not_compared_swatch(&mut img, 6, top + h + 8);
    text(
        &mut img,
        200,
        (top + h + 6) as i32,
        14.0,
        "ratios beyond the bar's ends are drawn at its end colours",
        BLACK,
    );
    img
}

/// A rectangle of the screen: left, top, width, height (pixels).
pub type Crop = (u32, u32, u32, u32);

/// The close-up of a shadow edge: the shaded crop (left) beside the predicted error over the same
/// pixels (right), each pixel drawn `zoom × zoom`, with the error's colour bar, under a title bar.
pub fn close_up(
    color: &[[u8; 4]],
    predicted: &[f64],
    w: u32,
    crop: Crop,
    zoom: u32,
    title: &str,
) -> RgbImage {
    let (cx, cy, cw, ch) = crop;
    let (pw, ph) = (cw * zoom, ch * zoom);
    let top = TITLE + CAPTION;
    let gap = 12;
    let mut img = RgbImage::from_pixel(2 * pw + gap + BAR, top + ph + LEGEND, WHITE);
    for y in 0..ph {
        for x in 0..pw {
            let i = ((cy + y / zoom) * w + cx + x / zoom) as usize;
            let c = color[i];
            img.put_pixel(x, y + top, Rgb([c[0], c[1], c[2]]));
            img.put_pixel(pw + gap + x, y + top, error_colour(predicted[i]));
        }
    }
    title_bar(&mut img, title);
    let cap = format!(
        "shaded, pixels {cx}..{} × {cy}..{}, each drawn {zoom}×{zoom}",
        cx + cw,
        cy + ch
    );
    text(&mut img, 4, TITLE as i32 + 3, 15.0, &cap, BLACK);
    text(
        &mut img,
        (pw + gap + 4) as i32,
        TITLE as i32 + 3,
        15.0,
        "predicted error, pixels per texel (log)",
        BLACK,
    );
    colour_bar(&mut img, (2 * pw + gap + 8, top, ph), viridis, &ERROR_TICKS);
    not_compared_swatch(&mut img, pw + gap + 6, top + ph + 8);
    let note = "an error of e pixels per texel: one texel covers up to e pixels";
    let nx = (pw as f32 - text_width(14.0, note)).max(0.0) as i32 / 2;
    text(&mut img, nx, (top + ph + 6) as i32, 14.0, note, BLACK);
    img
}

/// The height of the lens image's legend row.
const LENS_LEGEND: u32 = 64;

/// The lens ramp's colour (`shadow_aliasing::frame::lens::lens_colour`, the colours
/// `sa_lens_colour` draws) of `value` pixels, as 8-bit sRGB.
pub fn lens_ramp(value: f64) -> Rgb<u8> {
    let c = shadow_aliasing::frame::lens::lens_colour(value);
    Rgb(c.map(|x| (x * 255.0).round() as u8))
}

/// The error lens as the GPU drew it over the scene (`overlay`: `sa_lens_colour` of the lens,
/// 3/4, over the shaded colour, 1/4), under a title bar and a caption, with the ramp's legend
/// below: a bar from 1/16 to 32 pixels (log₂, one colour per doubling) and the 1-pixel colour
/// marked; `note` is written beside the legend.
pub fn lens_overlay(overlay: &[[u8; 4]], w: u32, h: u32, title: &str, note: &str) -> RgbImage {
    let top = TITLE + CAPTION;
    let mut img = RgbImage::from_pixel(w.max(560), top + h + LENS_LEGEND, WHITE);
    for y in 0..h {
        for x in 0..w {
            let c = overlay[(y * w + x) as usize];
            img.put_pixel(x, y + top, Rgb([c[0], c[1], c[2]]));
        }
    }
    title_bar(&mut img, title);
    text(
        &mut img,
        4,
        TITLE as i32 + 3,
        15.0,
        "error lens: the shadow texel's size on screen, pixels (sa_error_lens)",
        BLACK,
    );
    // The bar: 2⁻⁴ … 2⁵ pixels across `bw` pixels, log₂.
    let (bx, by, bw) = (12u32, top + h + 8, 360u32);
    let (lo, hi) = (
        shadow_aliasing::frame::lens::LENS_RAMP_LOG2_MIN,
        shadow_aliasing::frame::lens::LENS_RAMP_LOG2_MIN + 9.0,
    );
    for dx in 0..bw {
        let v = (lo + (hi - lo) * f64::from(dx) / f64::from(bw - 1)).exp2();
        for dy in 0..16 {
            img.put_pixel(bx + dx, by + dy, lens_ramp(v));
        }
    }
    let labels = [
        "1/16", "1/8", "1/4", "1/2", "1 px", "2", "4", "8", "16", "32",
    ];
    for (k, label) in labels.iter().enumerate() {
        let tx = bx + (k as u32 * (bw - 1)) / 9;
        for dy in 16..21 {
            img.put_pixel(tx, by + dy, BLACK);
        }
        let px = if k == 4 { 13.0 } else { 12.0 };
        let lx = tx as i32 - (text_width(px, label) / 2.0) as i32;
        text(&mut img, lx.max(0), (by + 22) as i32, px, label, BLACK);
    }
    // The 1-pixel colour, boxed.
    let one = bx + 4 * (bw - 1) / 9;
    for dx in 0..9 {
        for dy in [0u32, 17] {
            img.put_pixel(one + dx - 4, by + dy, BLACK);
        }
    }
    for dy in 0..18 {
        img.put_pixel(one - 4, by + dy, BLACK);
        img.put_pixel(one + 4, by + dy, BLACK);
    }
    text(
        &mut img,
        (bx + bw + 12) as i32,
        (by - 2) as i32,
        13.0,
        "1 px = #26828e; ends clamped",
        BLACK,
    );
    text(
        &mut img,
        (bx + bw + 12) as i32,
        (by + 16) as i32,
        13.0,
        note,
        BLACK,
    );
    img
}
