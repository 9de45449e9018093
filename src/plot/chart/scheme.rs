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
    /// The scheme's colour (Okabe–Ito, [`PALETTE`]; the fall-offs [`SWEEP`] steps).
    pub const fn colour(self) -> RGBColor {
        match self {
            Look::Psm | Look::Zp => PALETTE[0],
            Look::ZpW => PALETTE[1],
            // The two fall-offs r(γ) are one rule's parameter, not schemes: the sweep's darkest
            // and fourth steps, so that no reader takes them for PSM/ZP blue or ZP+W
            // vermillion (figure review 5, X5).
            Look::Barroso => SWEEP[0],
            Look::Zhang => SWEEP[3],
            Look::Lispsm | Look::FpZpW => PALETTE[2],
            Look::Uniform => PALETTE[4],
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

    /// The colours by hand (Okabe–Ito: blue #0072B2, vermillion #D55E00, bluish green #009E73,
    /// orange #E69F00), and the schemes a figure sets side by side apart: PSM, LiSPSM and the
    /// uniform map (lloyd2006-fig5, lloyd2005-fig4), ZP, ZP+W and FP+ZP+W (lloyd2006-fig12,
    /// fig13, worst-case), Barroso, Zhang and LiSPSM (barroso-fig7).
    #[test]
    fn schemes_have_their_colours_and_compared_ones_differ() {
        let hex = |c: RGBColor| format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2);
        assert_eq!(hex(Look::Zp.colour()), "#0072B2");
        assert_eq!(hex(Look::ZpW.colour()), "#D55E00");
        assert_eq!(hex(Look::FpZpW.colour()), "#009E73");
        assert_eq!(hex(Look::Uniform.colour()), "#E69F00");
        for group in [
            [Look::Psm, Look::Lispsm, Look::Uniform],
            [Look::Zp, Look::ZpW, Look::FpZpW],
            [Look::Barroso, Look::Zhang, Look::Lispsm],
        ] {
            for (i, a) in group.iter().enumerate() {
                for b in &group[..i] {
                    assert_ne!(a.colour(), b.colour(), "{a:?} and {b:?}");
                }
                assert_ne!(a.colour(), SHARED);
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
