//! One colour per scheme in every figure: the shadow-map schemes, warps and parameter rules the
//! figures compare are drawn in the colour this table gives them (and so with the marker of
//! that colour, [`super::Marker::of`]), whichever figure shows them.

use super::line::PALETTE;
use plotters::style::RGBColor;

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
    /// The scheme's colour (Okabe–Ito, [`PALETTE`]).
    pub const fn colour(self) -> RGBColor {
        match self {
            Look::Psm | Look::Zp | Look::Barroso => PALETTE[0],
            Look::ZpW | Look::Zhang => PALETTE[1],
            Look::Lispsm | Look::FpZpW => PALETTE[2],
            Look::Uniform => PALETTE[4],
        }
    }
}

/// The neutral colour of a curve two schemes share (ZP and ZP+W with the light behind) and of
/// reference lines (optima), so that it is neither scheme's colour.
pub(crate) const SHARED: RGBColor = RGBColor(90, 90, 90);

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
}
