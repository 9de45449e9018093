//! Hatching for lloyd2005-fig8's partitions: the pastel fills of the seven partitions print as
//! nearly one grey (CIE L* 80–89), so each partition also gets its own hatch, a family of thin
//! parallel lines (or two crossed families) clipped to its outline.

use glam::DVec2;

/// The line families of a partition's hatch, as angles in degrees from the horizontal.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Hatch {
    /// No lines: the fill alone (the near face's grey, darker than every pastel).
    Plain,
    /// Lines rising to the right (45°).
    Rising,
    /// Lines falling to the right (135°).
    Falling,
    /// Horizontal lines.
    Level,
    /// Vertical lines.
    Upright,
    /// Both diagonals.
    Diamonds,
    /// Horizontal and vertical lines.
    Squares,
}

/// The hatch of the partition drawn in [`super::super::chart::PALETTE`]`[i]`: `HATCHES[i % 7]`.
/// Index 6 is the palette's black (the near face, a mid grey once mixed with white): plain.
pub(crate) const HATCHES: [Hatch; 7] = [
    Hatch::Rising,
    Hatch::Falling,
    Hatch::Level,
    Hatch::Upright,
    Hatch::Diamonds,
    Hatch::Squares,
    Hatch::Plain,
];

impl Hatch {
    /// The angles (degrees) of its line families.
    pub(crate) fn angles(self) -> &'static [f64] {
        match self {
            Hatch::Plain => &[],
            Hatch::Rising => &[45.0],
            Hatch::Falling => &[135.0],
            Hatch::Level => &[0.0],
            Hatch::Upright => &[90.0],
            Hatch::Diamonds => &[45.0, 135.0],
            Hatch::Squares => &[0.0, 90.0],
        }
    }
}

/// The segments of the lines at `angle_deg` through the points `c · normal` for every multiple
/// `c` of `step` (so that neighbouring outlines continue one another's lines), clipped to the
/// convex polygon `poly` (either orientation). Empty for `step` ≤ 0 or a degenerate polygon.
pub(crate) fn segments(poly: &[DVec2], angle_deg: f64, step: f64) -> Vec<(DVec2, DVec2)> {
    if poly.len() < 3 || step.is_nan() || step <= 0.0 || !step.is_finite() {
        return Vec::new();
    }
    let a = angle_deg.to_radians();
    let dir = DVec2::new(a.cos(), a.sin());
    let normal = dir.perp();
    let (lo, hi) = poly
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            let c = normal.dot(*p);
            (lo.min(c), hi.max(c))
        });
    let mut out = Vec::new();
    let first = (lo / step).floor() as i64 + 1;
    let last = (hi / step).ceil() as i64 - 1;
    for k in first..=last {
        let c = k as f64 * step;
        // Where the line normal·p = c crosses each edge, as a position along `dir`.
        let mut along: Vec<f64> = Vec::new();
        for i in 0..poly.len() {
            let (p, q) = (poly[i], poly[(i + 1) % poly.len()]);
            let (dp, dq) = (normal.dot(p) - c, normal.dot(q) - c);
            if (dp <= 0.0 && dq > 0.0) || (dq <= 0.0 && dp > 0.0) {
                let t = dp / (dp - dq);
                along.push(dir.dot(p + (q - p) * t));
            }
        }
        if along.len() >= 2 {
            let s0 = along.iter().copied().fold(f64::INFINITY, f64::min);
            let s1 = along.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            if s1 - s0 > 1e-12 {
                out.push((normal * c + dir * s0, normal * c + dir * s1));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The square [0, 4]² hatched horizontally every 1: the lines y = 1, 2, 3, each from
    /// x = 0 to 4 (by hand); at 45° every √2: the diagonals y − x = 0, ±2, of lengths
    /// √2 (4 − |y − x|).
    #[test]
    fn square_hatched_by_hand() {
        let sq = [
            DVec2::new(0.0, 0.0),
            DVec2::new(4.0, 0.0),
            DVec2::new(4.0, 4.0),
            DVec2::new(0.0, 4.0),
        ];
        let h = segments(&sq, 0.0, 1.0);
        assert_eq!(h.len(), 3);
        for (i, (a, b)) in h.iter().enumerate() {
            let y = (i + 1) as f64;
            assert!((a.y - y).abs() < 1e-9 && (b.y - y).abs() < 1e-9, "{a} {b}");
            assert!((a.x.min(b.x)).abs() < 1e-9 && (a.x.max(b.x) - 4.0).abs() < 1e-9);
        }
        // 45°: normal (−1/√2, 1/√2); offsets c = k√2 for y − x = 2k, k = −1, 0, 1 inside.
        let d = segments(&sq, 45.0, 2f64.sqrt());
        let mut lens: Vec<f64> = d.iter().map(|(a, b)| (*b - *a).length()).collect();
        lens.sort_by(f64::total_cmp);
        let want = [2.0 * 2f64.sqrt(), 2.0 * 2f64.sqrt(), 4.0 * 2f64.sqrt()];
        assert_eq!(lens.len(), 3, "{d:?}");
        for (l, w) in lens.iter().zip(want) {
            assert!((l - w).abs() < 1e-9, "{lens:?}");
        }
        for (a, b) in &d {
            assert!(
                ((b.y - a.y) - (b.x - a.x)).abs() < 1e-9,
                "not at 45°: {a} {b}"
            );
        }
    }

    #[test]
    fn degenerate_input_gives_no_lines() {
        let sq = [DVec2::ZERO, DVec2::X, DVec2::ONE];
        assert!(segments(&sq, 0.0, 0.0).is_empty());
        assert!(segments(&sq, 0.0, f64::NAN).is_empty());
        assert!(segments(&sq[..2], 0.0, 0.1).is_empty());
    }

    /// Every partition colour of the palette's first seven has its own hatch.
    #[test]
    fn hatches_are_distinct() {
        for (i, a) in HATCHES.iter().enumerate() {
            for b in &HATCHES[i + 1..] {
                assert_ne!(a, b);
            }
        }
    }
}
