//! PNG output: the shaded frame, and the error heat maps (rendered beside predicted, log scale,
//! viridis, with a colour bar labelled in pixels per texel).

use image::{Rgb, RgbImage};

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

/// Viridis at `t` ∈ [0, 1].
pub fn viridis(t: f64) -> Rgb<u8> {
    let t = t.clamp(0.0, 1.0) * 8.0;
    let i = (t.floor() as usize).min(7);
    let f = t - i as f64;
    let c = |k: usize| (VIRIDIS[i][k] * (1.0 - f) + VIRIDIS[i + 1][k] * f).round() as u8;
    Rgb([c(0), c(1), c(2)])
}

/// The log10 range of the heat maps: 10⁻² to 10² pixels per texel.
pub const LOG_RANGE: (f64, f64) = (-2.0, 2.0);

/// 3×5 bitmap glyphs for the colour bar's labels.
fn glyph(c: char) -> [u8; 5] {
    match c {
        '0' => [7, 5, 5, 5, 7],
        '1' => [2, 6, 2, 2, 7],
        '2' => [7, 1, 7, 4, 7],
        '3' => [7, 1, 7, 1, 7],
        '4' => [5, 5, 7, 1, 1],
        '5' => [7, 4, 7, 1, 7],
        '6' => [7, 4, 7, 5, 7],
        '7' => [7, 1, 1, 1, 1],
        '8' => [7, 5, 7, 5, 7],
        '9' => [7, 5, 7, 1, 7],
        '.' => [0, 0, 0, 0, 2],
        '-' => [0, 0, 7, 0, 0],
        'p' => [0, 7, 5, 7, 4],
        'x' => [0, 5, 2, 5, 0],
        '/' => [1, 1, 2, 4, 4],
        't' => [2, 7, 2, 2, 3],
        'e' => [0, 7, 7, 4, 7],
        'l' => [6, 2, 2, 2, 7],
        'r' => [0, 6, 5, 4, 4],
        'd' => [1, 1, 7, 5, 7],
        'i' => [2, 0, 2, 2, 2],
        'c' => [0, 7, 4, 4, 7],
        'n' => [0, 6, 5, 5, 5],
        'a' => [0, 7, 1, 7, 7],
        ' ' => [0; 5],
        _ => [7, 7, 7, 7, 7],
    }
}

/// Draws `text` at `(x, y)` with glyph pixels `scale` wide.
pub fn text(img: &mut RgbImage, x: u32, y: u32, s: &str, scale: u32, col: Rgb<u8>) {
    for (k, c) in s.chars().enumerate() {
        let g = glyph(c);
        for (r, bits) in g.iter().enumerate() {
            for b in 0..3u32 {
                if bits & (4 >> b) != 0 {
                    for dy in 0..scale {
                        for dx in 0..scale {
                            let px = x + (k as u32 * 4 + b) * scale + dx;
                            let py = y + r as u32 * scale + dy;
                            if px < img.width() && py < img.height() {
                                img.put_pixel(px, py, col);
                            }
                        }
                    }
                }
            }
        }
    }
}

/// The heat map: rendered error (left), predicted error (right), colour bar (far right).
/// Pixels not compared are dark grey.
pub fn heat_map(rendered: &[f64], predicted: &[f64], w: u32, h: u32) -> RgbImage {
    let bar = 70;
    let top = 14;
    let mut img = RgbImage::from_pixel(2 * w + 8 + bar, h + top, Rgb([255, 255, 255]));
    let (lo, hi) = LOG_RANGE;
    let col = |e: f64| {
        if e.is_finite() && e > 0.0 {
            viridis((e.log10() - lo) / (hi - lo))
        } else {
            Rgb([60, 60, 60])
        }
    };
    for y in 0..h {
        for x in 0..w {
            let i = (y * w + x) as usize;
            img.put_pixel(x, y + top, col(rendered[i]));
            img.put_pixel(w + 8 + x, y + top, col(predicted[i]));
        }
    }
    let black = Rgb([0, 0, 0]);
    text(&mut img, 2, 2, "rendered", 2, black);
    text(&mut img, w + 10, 2, "predicted", 2, black);
    // Colour bar.
    let x0 = 2 * w + 16;
    for y in 0..h {
        let t = 1.0 - f64::from(y) / f64::from(h - 1);
        for x in x0..x0 + 14 {
            img.put_pixel(x, y + top, viridis(t));
        }
    }
    for (k, label) in ["0.01", "0.1", "1", "10", "100"].iter().enumerate() {
        let y = top + ((h - 1) as f64 * (1.0 - k as f64 / 4.0)) as u32;
        for x in x0 + 14..x0 + 18 {
            img.put_pixel(x, y, black);
        }
        text(
            &mut img,
            x0 + 20,
            y.saturating_sub(5).clamp(top, top + h - 10),
            label,
            2,
            black,
        );
    }
    text(&mut img, x0 - 2, 2, "px/texel", 1, black);
    img
}

/// The shaded frame as an image.
pub fn shaded(color: &[[u8; 4]], w: u32, h: u32) -> RgbImage {
    RgbImage::from_fn(w, h, |x, y| {
        let c = color[(y * w + x) as usize];
        Rgb([c[0], c[1], c[2]])
    })
}
