//! One colour per scheme in every figure: the shadow-map schemes, warps and parameter rules the
//! figures compare are drawn in the colour this table gives them (and so with the marker of
//! that colour, [`super::Marker::of`]), whichever figure shows them.

use plotters::style::RGBColor;

use super::line::PALETTE;

/// A scheme, warp or rule that more than one figure shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Look {
    /// Perspective shadow maps: the warp parameter n′ = n.
    Psm,
    /// Light-space perspective shadow maps: n′ = n + √(fn) (Wimmer et al.), 1/sin γ for other
    /// lights.
    Lispsm,
    /// No warp: n′ = ∞, the uniform (standard) shadow map.
    Uniform,
    /// z-partitioning (Lloyd 2006 §5).
    Zp,
    /// z-partitioning with warping.
    ZpW,
    /// Face partitioning with warped z-partitions per face.
    FpZpW,
    /// Zhang's fall-off of n′ with the light angle.
    Zhang,
    /// Barroso and Celes' fall-off of n′ with the light angle.
    Barroso,
}

impl Look {
    /// The scheme's colour, from two sets of three ([`PALETTE`] holds them all): the warps
    /// (n′ rules) PSM dark blue, LiSPSM green and the uniform map vermillion; the schemes
    /// (partitionings) ZP teal, ZP+W rose and FP+ZP+W brown, hues none of the warps has, so that
    /// no colour means a warp in one figure and a scheme in another (sixth figure review, X-3).
    /// Within each set the CIE L* are at least 15 apart (warps 21, 38, 54; schemes 59, 40, 22),
    /// so that the three stay apart in greyscale, and every one has at least 3 : 1
    /// against white. The fall-offs take [`SWEEP`] steps.
    pub const fn colour(self) -> RGBColor {
        match self {
            Look::Psm => PALETTE[0],
            Look::Uniform => PALETTE[1],
            Look::Lispsm => PALETTE[2],
            Look::Zp => PALETTE[4],
            Look::ZpW => PALETTE[5],
            Look::FpZpW => PALETTE[8],
            // The two fall-offs r(γ) are one rule's parameter, not schemes: the sweep's darkest
            // and fourth steps, so that no reader takes them for a warp or a scheme (figure
            // review 5, X5).
            Look::Barroso => SWEEP[0],
            Look::Zhang => SWEEP[3],
        }
    }
}

/// The neutral colour of a curve two schemes share (ZP and ZP+W with the light behind) and of
/// reference lines (optima), so that it is neither scheme's colour.
pub(crate) const SHARED: RGBColor = RGBColor(90, 90, 90);

/// The colours of a parameter sweep (α, f/n, k, ξ, partition or depth levels, the quantities
/// M_x, M_z, S̄ of one scheme), darkest first: one purple family, apart from every scheme's hue
/// and from [`SHARED`], so that a sweep never reads as a set of schemes. Each step is about
/// 10 CIE L* lighter than the one before (18, 29, 39, 50, 60), so that neighbours stay apart in
/// greyscale, and the lightest still has 3 : 1 against white (WCAG's least for lines); labels
/// in these colours go through [`super::legible`], which darkens the two lightest to 4.5 : 1.
/// Each colour has its own marker shape ([`super::Marker::of`]), none a scheme colour's.
pub(crate) const SWEEP: [RGBColor; 5] = [
    RGBColor(63, 0, 125),
    RGBColor(88, 42, 146),
    RGBColor(103, 76, 160),
    RGBColor(123, 109, 180),
    RGBColor(149, 137, 192),
];

/// Ochre, Okabe and Ito's orange #E69F00 darkened (each channel × 0.67; L* 49, 4.7 : 1 on
/// white): a hue no scheme, warp or sweep step has, for the one item of a sweep that its
/// purple steps cannot set apart: the third z-partition map of barroso-fig5 and
/// lloyd2006-fig11 (the sweep has only three steps 20 L* apart above 3 : 1 on white; the
/// eleventh review, R11-barroso-fig5-1).
pub(crate) const OCHRE: RGBColor = RGBColor(154, 106, 0);

/// The colour of the `i`-th of `n` values of a swept parameter (`i` from 0, darkest first):
/// the `n` values spread over [`SWEEP`] as evenly as its steps allow, the first the darkest and
/// (for `n` ≥ 2) the last the lightest, so that a sweep of two or three values keeps the
/// greatest contrast between its lines.
///
/// # Panics
///
/// Where `n` is 0 or more than [`SWEEP`]'s length, or `i` ≥ `n`: a figure's sweep is fixed by
/// its code, so that is a mistake in the figure (its tests fail), never a user's input.
pub(crate) fn sweep(i: usize, n: usize) -> RGBColor {
    assert!(
        (1..=SWEEP.len()).contains(&n) && i < n,
        "sweep({i}, {n}): a sweep has 1 to {} values and i < n",
        SWEEP.len()
    );
    if n == 1 {
        return SWEEP[0];
    }
    // The nearest step to i·(N − 1)/(n − 1), rounding halves up, in whole numbers.
    let last = SWEEP.len() - 1;
    SWEEP[(2 * i * last + (n - 1)) / (2 * (n - 1))]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The CIE L* of a relative luminance (CIE 1976: 116·Y^(1/3) − 16 above (6/29)³).
    fn lightness(y: f64) -> f64 {
        if y > 216.0 / 24389.0 {
            116.0 * y.cbrt() - 16.0
        } else {
            y * 24389.0 / 27.0
        }
    }

    /// The colour table by hand (docs/figures.md): each colour's hex and its WCAG luminance
    /// worked out by hand from the sRGB formula (e.g. ZP+W #A82E66: 168/255 →
    /// ((0.6588 + 0.055)/1.055)^2.4 = 0.3916, 46/255 → 0.0273, 102/255 → 0.1329;
    /// 0.2126·0.3916 + 0.7152·0.0273 + 0.0722·0.1329 = 0.1124, L* 40.0, 6.47 : 1 on white).
    /// Every colour has at least 3 : 1 against white (sixth figure review, X-11), the three of
    /// each set are at least 15 L* apart, the sets share no colour, and none is a
    /// sweep step or [`SHARED`]; the schemes a figure sets side by side differ (barroso-fig7:
    /// Barroso, Zhang and LiSPSM).
    #[test]
    fn warps_and_schemes_are_two_sets_apart_in_greyscale() {
        let hex = |c: RGBColor| format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2);
        let warps = [
            (Look::Psm, "#00306E", 0.0324),
            (Look::Lispsm, "#00664B", 0.1001),
            (Look::Uniform, "#D55E00", 0.2215),
        ];
        let schemes = [
            (Look::Zp, "#009CA6", 0.2653),
            (Look::ZpW, "#A82E66", 0.1124),
            (Look::FpZpW, "#4D2E00", 0.0353),
        ];
        for set in [warps, schemes] {
            for (look, h, y) in set {
                assert_eq!(hex(look.colour()), h, "{look:?}");
                let l = super::super::luminance(look.colour());
                assert!((l - y).abs() < 5e-4, "{look:?}: {l}");
                assert!(1.05 / (y + 0.05) >= 3.0, "{look:?} below 3 : 1");
                assert!(!SWEEP.contains(&look.colour()) && look.colour() != SHARED);
            }
            for (i, a) in set.iter().enumerate() {
                for b in &set[..i] {
                    let d = (lightness(a.2) - lightness(b.2)).abs();
                    assert!(d >= 15.0, "{:?} and {:?}: {d} L* apart", a.0, b.0);
                }
            }
        }
        for w in warps {
            assert!(schemes.iter().all(|s| s.0.colour() != w.0.colour()));
        }
        // By hand: the uniform map's L* = 116·0.2215^(1/3) − 16 = 54.2, LiSPSM's
        // 116·0.1001^(1/3) − 16 = 37.9: 16.3 apart.
        assert!((lightness(0.2215) - 54.2).abs() < 0.05);
        assert!((lightness(0.1001) - 37.9).abs() < 0.05);
        for (i, a) in [Look::Barroso, Look::Zhang, Look::Lispsm]
            .iter()
            .enumerate()
        {
            for b in &[Look::Barroso, Look::Zhang, Look::Lispsm][..i] {
                assert_ne!(a.colour(), b.colour(), "{a:?} and {b:?}");
            }
        }
    }

    /// The sweep's colours by hand: #3F007D, #582A92, #674CA0, #7B6DB4, #9589C0, with their WCAG
    /// luminances worked out by hand from the sRGB formula (e.g. #3F007D: 63/255 = 0.2471 →
    /// ((0.2471 + 0.055)/1.055)^2.4 = 0.0497, 125/255 → 0.2051; 0.2126·0.0497 + 0.0722·0.2051 =
    /// 0.0254). Neighbours differ by a luminance ratio (L + 0.05) of at least 1.4 (so they stay
    /// apart in greyscale), the lightest line has 3 : 1 against white, and no step is a scheme
    /// colour, [`SHARED`] or any other colour of the line palette.
    #[test]
    fn sweep_steps_stay_apart_in_greyscale_and_from_the_schemes() {
        let hex = |c: RGBColor| format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2);
        let by_hand = [
            ("#3F007D", 0.0254),
            ("#582A92", 0.0581),
            ("#674CA0", 0.1059),
            ("#7B6DB4", 0.1844),
            ("#9589C0", 0.2809),
        ];
        for (c, (h, l)) in SWEEP.iter().zip(by_hand) {
            assert_eq!(hex(*c), h);
            assert!(
                (super::super::luminance(*c) - l).abs() < 5e-4,
                "{h}: {}",
                super::super::luminance(*c)
            );
        }
        for w in by_hand.windows(2) {
            let ratio = (w[1].1 + 0.05) / (w[0].1 + 0.05);
            assert!(ratio >= 1.4, "{} and {}: {ratio}", w[0].0, w[1].0);
        }
        // The lightest against white: 1.05 / (0.2809 + 0.05) = 3.17.
        assert!(1.05 / (by_hand[4].1 + 0.05) >= 3.0);
        for c in SWEEP {
            assert_ne!(c, SHARED);
            assert!(!PALETTE.contains(&c), "{}", hex(c));
        }
    }

    /// A sweep's labels reach 4.5 : 1 on white: the three darkest as they are (13.9, 9.7 and
    /// 6.7 : 1 from the luminances above), the two lightest (4.48 and 3.17 : 1) darkened by
    /// [`super::super::legible`] to a colour of at least 4.5 : 1 that is no darker than needed
    /// (one 1/256 step less dark falls short).
    #[test]
    fn sweep_labels_are_legible() {
        use super::super::{legible, luminance};
        let contrast = |c: RGBColor| 1.05 / (luminance(c) + 0.05);
        for (k, c) in SWEEP.iter().enumerate() {
            let ink = legible(*c);
            assert!(contrast(ink) >= 4.5, "step {k}: {}", contrast(ink));
            if k < 3 {
                assert_eq!(ink, *c, "step {k} needs no darkening");
            } else {
                assert_ne!(ink, *c, "step {k} is below 4.5 : 1 as it is");
            }
        }
    }

    /// The spread by hand: i·4/(n − 1) rounded, halves up: n = 2 → steps 0, 4; n = 3 → 0, 2, 4;
    /// n = 4 → 0, 1.33, 2.67, 4 → 0, 1, 3, 4; n = 5 → every step; n = 1 → the darkest.
    #[test]
    fn sweep_spreads_its_values_darkest_first() {
        let steps = |n: usize| -> Vec<usize> {
            (0..n)
                .map(|i| SWEEP.iter().position(|&c| c == sweep(i, n)).unwrap())
                .collect()
        };
        assert_eq!(steps(1), vec![0]);
        assert_eq!(steps(2), vec![0, 4]);
        assert_eq!(steps(3), vec![0, 2, 4]);
        assert_eq!(steps(4), vec![0, 1, 3, 4]);
        assert_eq!(steps(5), vec![0, 1, 2, 3, 4]);
    }

    /// Past the palette, or an index past the count: a panic naming the call, not a colour
    /// repeated in silence.
    #[test]
    #[should_panic(expected = "sweep(0, 6)")]
    fn a_sweep_of_six_is_refused() {
        let _ = sweep(0, 6);
    }
}
