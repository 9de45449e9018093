//! The colour maps of the heat maps: viridis for a quantity (dark blue low, yellow high), and a
//! diverging map for a ratio, neutral at its centre value (blue below, red above).

use plotters::prelude::RGBColor;

/// Which colours a [`super::ColourScale`] paints its bands with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum ColourMap {
    /// matplotlib's viridis over the whole range (perceptually uniform, readable in grey and
    /// by colour-blind readers).
    Viridis,
    /// ColorBrewer's RdBu, reversed, neutral at `centre` (in the axis's space, e.g. log₁₀ 1 = 0
    /// for a ratio): the range below it takes the blue half of the map and the range above
    /// it the red half, each side over its own length, so that the neutral grey marks the
    /// centre wherever it falls in the range.
    Diverging { centre: f64 },
}

/// ColorBrewer's eleven-class RdBu from its blue end (#053061) through the neutral #f7f7f7 to
/// its red end (#67001f).
const RDBU: [(u8, u8, u8); 11] = [
    (0x05, 0x30, 0x61),
    (0x21, 0x66, 0xac),
    (0x43, 0x93, 0xc3),
    (0x92, 0xc5, 0xde),
    (0xd1, 0xe5, 0xf0),
    (0xf7, 0xf7, 0xf7),
    (0xfd, 0xdb, 0xc7),
    (0xf4, 0xa5, 0x82),
    (0xd6, 0x60, 0x4d),
    (0xb2, 0x18, 0x2b),
    (0x67, 0x00, 0x1f),
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

/// The diverging map at u ∈ [0, 1]: blue at 0, neutral at ½, red at 1.
pub(crate) fn rdbu(u: f64) -> RGBColor {
    interpolate(&RDBU, u)
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
    /// 10⁴ ↦ 1. The map's ends and middle are ColorBrewer's published colours.
    #[test]
    fn diverging_map_is_neutral_at_its_centre() {
        let c = 0.2;
        for (t, want) in [(0.0, 0.0), (0.1, 0.25), (0.2, 0.5), (0.6, 0.75), (1.0, 1.0)] {
            assert!((diverging_position(t, c) - want).abs() < 1e-12, "{t}");
        }
        assert_eq!(rdbu(0.0), RGBColor(0x05, 0x30, 0x61));
        assert_eq!(rdbu(0.5), RGBColor(0xf7, 0xf7, 0xf7));
        assert_eq!(rdbu(1.0), RGBColor(0x67, 0x00, 0x1f));
    }
}
