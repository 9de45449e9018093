//! The colour maps of the heat maps: viridis for a quantity (dark blue low, yellow high), and a
//! diverging map for a ratio, neutral grey at its centre value (pale blue below, red above),
//! darker all the way from its low end to its high end, so that it reads in greyscale too.

use plotters::prelude::RGBColor;

/// Which colours a [`super::ColourScale`] paints its bands with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum ColourMap {
    /// matplotlib's viridis over the whole range (perceptually uniform, readable in grey and
    /// by colour-blind readers).
    Viridis,
    /// [`DIVERGING`], neutral at `centre` (in the axis's space, e.g. log₁₀ 1 = 0 for a ratio):
    /// the range below it takes the blue half of the map and the range above it the red half,
    /// each side over its own length, so that the neutral grey marks the centre wherever it
    /// falls in the range.
    Diverging { centre: f64 },
}

/// The diverging map from its blue end through the neutral grey #c6c6c6 (its middle entry) to
/// its dark red end. Its CIE L* falls monotonically, 91.4 → 79.9 → 16.7, so that the two
/// halves differ in lightness and every grey stands for one value (ColorBrewer's RdBu, blue
/// and red both dark at the ends and white in the middle, read the same grey on either side
/// in greyscale); the red half, which carries a ratio's large values, spans most of the
/// lightness.
pub(crate) const DIVERGING: [(u8, u8, u8); 13] = [
    (0xd6, 0xe9, 0xfa),
    (0xd0, 0xe2, 0xf4),
    (0xca, 0xda, 0xeb),
    (0xc6, 0xd2, 0xdf),
    (0xc6, 0xcc, 0xd4),
    (0xc6, 0xc9, 0xcc),
    (0xc6, 0xc6, 0xc6),
    (0xd6, 0xad, 0x9c),
    (0xdd, 0x8c, 0x74),
    (0xd0, 0x60, 0x4c),
    (0xb2, 0x3a, 0x36),
    (0x8a, 0x1a, 0x2a),
    (0x5a, 0x00, 0x18),
];

/// The table `table` at t ∈ [0, 1], linear between its samples.
pub(crate) fn interpolate(table: &[(u8, u8, u8)], t: f64) -> RGBColor {
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    let x = t * (table.len() - 1) as f64;
    let i = (x.floor() as usize).min(table.len() - 2);
    let f = x - i as f64;
    let (a, b) = (table[i], table[i + 1]);
    let mix = |p: u8, q: u8| (f64::from(p) + f * (f64::from(q) - f64::from(p))).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// The diverging map at u ∈ [0, 1]: pale blue at 0, neutral grey at ½, dark red at 1.
pub(crate) fn diverging(u: f64) -> RGBColor {
    interpolate(&DIVERGING, u)
}

/// Where the fraction `t` of a range lands on a diverging map whose neutral point lies at the
/// fraction `c` of the range: [0, c] onto [0, ½], [c, 1] onto [½, 1].
pub(crate) fn diverging_position(t: f64, c: f64) -> f64 {
    let c = c.clamp(0.0, 1.0);
    if t < c {
        0.5 * t / c
    } else if c < 1.0 {
        0.5 + 0.5 * (t - c) / (1.0 - c)
    } else {
        0.5
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The neutral point lands on ½ whatever its place in the range, and each side maps
    /// linearly onto its half: a range from 10⁻¹ to 10⁴ on a log axis with the centre at
    /// 10⁰ has c = 1/5; 10⁻¹ ↦ 0, 10^−½ ↦ ¼, 10⁰ ↦ ½, 10² ↦ ½ + ½·(3/5 − 1/5)/(4/5) = ¾,
    /// 10⁴ ↦ 1. The map's ends and middle are its table's first, middle and last entries.
    #[test]
    fn diverging_map_is_neutral_at_its_centre() {
        let c = 0.2;
        for (t, want) in [(0.0, 0.0), (0.1, 0.25), (0.2, 0.5), (0.6, 0.75), (1.0, 1.0)] {
            assert!((diverging_position(t, c) - want).abs() < 1e-12, "{t}");
        }
        assert_eq!(diverging(0.0), RGBColor(0xd6, 0xe9, 0xfa));
        assert_eq!(diverging(0.5), RGBColor(0xc6, 0xc6, 0xc6));
        assert_eq!(diverging(1.0), RGBColor(0x5a, 0x00, 0x18));
    }

    /// CIE L* of an sRGB colour (D65): the sRGB transfer function undone, the luminance
    /// Y = 0.2126 R + 0.7152 G + 0.0722 B, L* = 116 Y^⅓ − 16 (above the linear toe).
    fn lightness(RGBColor(r, g, b): RGBColor) -> f64 {
        let lin = |c: u8| {
            let c = f64::from(c) / 255.0;
            if c <= 0.04045 {
                c / 12.92
            } else {
                ((c + 0.055) / 1.055).powf(2.4)
            }
        };
        let y = 0.2126 * lin(r) + 0.7152 * lin(g) + 0.0722 * lin(b);
        if y > 0.008856 {
            116.0 * y.cbrt() - 16.0
        } else {
            903.3 * y
        }
    }

    /// Greyscale-safe (the fourth figure review: RdBu's blue and red ends printed as the same
    /// dark grey): sampled at 201 points, the map's L* never rises (equal only where two
    /// neighbouring samples round to one 8-bit colour), so no grey stands for two values; the blue half spans at least 10 and the red half at least 50 units of
    /// L* (the neutral grey near 80, the ends near 91 and 17, by the formula above), and the
    /// blue end is bluer than it is red, the red end redder than it is blue.
    #[test]
    fn diverging_map_darkens_monotonically() {
        let l: Vec<f64> = (0..=200)
            .map(|k| lightness(diverging(k as f64 / 200.0)))
            .collect();
        for (k, w) in l.windows(2).enumerate() {
            assert!(w[1] <= w[0], "L* rises at {k}: {} then {}", w[0], w[1]);
        }
        assert!(l[0] - l[100] >= 10.0 && l[100] - l[200] >= 50.0, "{l:?}");
        let (RGBColor(r0, _, b0), RGBColor(r1, _, b1)) = (diverging(0.0), diverging(1.0));
        assert!(b0 > r0 + 20 && r1 > b1 + 40, "{r0} {b0} {r1} {b1}");
    }
}
