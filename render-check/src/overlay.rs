//! The error lens overlay the GPU drew (`FrameOutput::overlay`: the crate's WGSL `sa_lens_colour`
//! of the lens, 3/4, over the shaded colour, 1/4) against the library's Rust ramp
//! (`frame::lens::lens_colour`, the function the WGSL module's docs say it equals), evaluated here
//! on the lens value the GPU wrote at the same pixel (docs/rendered.md, "What is measured", 14).

use crate::gpu::FrameOutput;
use serde::Serialize;
use shadow_aliasing::frame::lens::lens_colour;

/// The overlay's largest difference from the expected colour in any channel, in 8-bit levels, at
/// a pixel that counts as matching: the shaded colour is read back rounded to 8 bits (a quarter
/// of half a level) and the overlay rounded again (half a level), with the GPU's `f32` besides.
pub const LEVELS: f64 = 1.0;

/// The overlay's pixels compared with the Rust ramp and those that differ.
#[derive(Debug, Clone, Copy, Default, Serialize, PartialEq, Eq)]
pub struct OverlayCheck {
    /// Visible pixels with a map whose overlay was compared.
    pub lens_colour_pixels: usize,
    /// Of those, the pixels whose overlay differs from `0.25 · colour + 0.75 · lens_colour(lens)`
    /// by more than [`LEVELS`] in any channel.
    pub lens_colour_mismatches: usize,
}

/// The expected overlay at a pixel with shaded colour `color` and lens `lens` (8-bit levels).
pub fn expected(color: [u8; 4], lens: f32) -> [f64; 3] {
    let c = lens_colour(f64::from(lens));
    let mix = |k: usize| 0.25 * f64::from(color[k]) + 0.75 * 255.0 * c[k];
    [mix(0), mix(1), mix(2)]
}

/// Compares every visible pixel with a map (of `maps`) in `out`.
pub fn check(out: &FrameOutput, maps: usize) -> OverlayCheck {
    let mut r = OverlayCheck::default();
    for i in 0..out.id.len() {
        let part = out.texel[i][2];
        if out.id[i] == 0 || !(part >= 0.0 && (part as usize) < maps) {
            continue;
        }
        r.lens_colour_pixels += 1;
        let want = expected(out.color[i], out.lens[i][0]);
        let got = out.overlay[i];
        if (0..3).any(|k| (f64::from(got[k]) - want[k]).abs() > LEVELS) {
            r.lens_colour_mismatches += 1;
        }
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One pixel per lens value: 1 pixel is viridis's fifth colour #26828e (38, 130, 142); over a
    /// black pixel the overlay is 3/4 of it: (28.5, 97.5, 106.5).
    #[test]
    fn expected_by_hand() {
        let e = expected([0, 0, 0, 255], 1.0);
        assert!((e[0] - 28.5).abs() < 1e-9 && (e[1] - 97.5).abs() < 1e-9);
        assert!((e[2] - 106.5).abs() < 1e-9);
        // 2 pixels: the sixth colour #1f9e89 (31, 158, 137) over white (255): 0.25·255 + 0.75·c.
        let e = expected([255, 255, 255, 255], 2.0);
        assert!((e[0] - (63.75 + 23.25)).abs() < 1e-9, "{e:?}");
        assert!((e[1] - (63.75 + 118.5)).abs() < 1e-9, "{e:?}");
    }

    fn frame(overlay: [u8; 4], lens: f32) -> FrameOutput {
        FrameOutput {
            texel: vec![[0.0, 0.0, 0.0, 1.0]],
            id: vec![1],
            color: vec![[0, 0, 0, 255]],
            depth: vec![0.5],
            blend: vec![[0.0; 4]],
            lens: vec![[lens, lens]],
            overlay: vec![overlay],
        }
    }

    /// An overlay one octave off (the colour of 2 pixels drawn for 1) is a mismatch; the right
    /// one, rounded, is not; a pixel with no map (part = the map count) is not compared.
    #[test]
    fn an_octave_off_is_a_mismatch() {
        let right = frame([29, 98, 107, 255], 1.0);
        assert_eq!(check(&right, 1).lens_colour_mismatches, 0);
        assert_eq!(check(&right, 1).lens_colour_pixels, 1);
        let c = lens_colour(2.0);
        let shifted = [
            (0.75 * 255.0 * c[0]).round() as u8,
            (0.75 * 255.0 * c[1]).round() as u8,
            (0.75 * 255.0 * c[2]).round() as u8,
            255,
        ];
        assert_eq!(check(&frame(shifted, 1.0), 1).lens_colour_mismatches, 1);
        assert_eq!(check(&right, 0).lens_colour_pixels, 0);
    }
}
