//! The error lens as the GPU draws it, against render-check's own measurement (docs/rendered.md,
//! "The error lens").
//!
//! The camera pass calls the crate's `sa_error_lens` (the WGSL module, `frame::SHADOW_WGSL`) for
//! the map each pixel selected and writes two numbers per pixel ([`FrameOutput::lens`]):
//!
//! - the **lens**, `sa_error_lens(map, p, n, l, eye, forward, focal_pixels)`: the size on screen,
//!   in pixels, of the map's texel on the pixel's surface;
//! - the lens with the **projection factor 1**, `sa_error_lens(map, p, −l, l, p − z l, l,
//!   focal_pixels)` with `z` the pixel's view depth: the same texel on a surface facing the
//!   light, seen along the light from the same depth, i.e. the texel measured across the light
//!   beam over the pixel measured across the view beam (Lloyd 2006's perspective factor).
//!
//! The reference for the first is measured from the GPU's texel coordinates alone, without the
//! crate's lens code: the rendered Jacobian `J` (texel ← pixel, exact three-sample derivatives,
//! [`crate::perspective`]) inverted, `J⁻¹` (pixel ← texel) holding the screen steps of one texel
//! step along s and t on the surface; the lens is the larger singular value of `J⁻¹`,
//! [`pixels_per_texel`]. That is the projection factor included, as the lens defines it: a texel
//! step moves along the surface (texel coordinates are constant along the light), and the
//! pixels it spans are what `J⁻¹` holds.
//!
//! The second is held to the frame's reported maximum (`FrameMap::max_error_pixels`, Lloyd's
//! perspective factor over the focus body's vertices): the lens itself is not bounded by it,
//! because the projection factor multiplies it without bound at grazing light (docs/renderer.md,
//! "The error lens").

use crate::gpu::FrameOutput;
use glam::DMat2;

/// The pixels one texel step spans at most on the surface: the larger singular value of `J⁻¹`
/// for `j` the Jacobian texel ← pixel, `σ_max(J)/|det J|` (a 2 × 2 matrix's singular values are
/// `σ_max σ_min = |det|`, `σ_max² = (‖J‖_F² + √(‖J‖_F⁴ − 4 det²))/2`). `None` where `J` is singular
/// or not finite.
pub fn pixels_per_texel(j: DMat2) -> Option<f64> {
    let det = j.determinant().abs();
    let f2 = j.x_axis.length_squared() + j.y_axis.length_squared();
    let disc = (f2 * f2 - 4.0 * det * det).max(0.0).sqrt();
    let smax = (0.5 * (f2 + disc)).sqrt();
    let v = smax / det;
    (det > 0.0 && v.is_finite()).then_some(v)
}

/// The GPU's lens at pixel `i` (a positive, finite pixel count), or `None` where it flagged the
/// pixel (no map: −2; behind the camera or the map's centre of projection: −1; edge-on to the
/// light: 3.4·10³⁸) or it is the sky (0).
pub fn gpu_lens(out: &FrameOutput, i: usize) -> Option<f64> {
    value(out.lens[i][0])
}

/// The GPU's lens at pixel `i` with the projection factor 1, as [`gpu_lens`].
pub fn gpu_perspective_lens(out: &FrameOutput, i: usize) -> Option<f64> {
    value(out.lens[i][1])
}

fn value(v: f32) -> Option<f64> {
    (v > 0.0 && v < 3.0e38).then_some(f64::from(v))
}

/// The lens's relative difference from the reference at one pixel: `|lens / reference − 1|`, or
/// +∞ where the GPU flagged a pixel the reference measures (a lens that is missing is as wrong
/// as one that is off).
pub fn rel_diff(out: &FrameOutput, i: usize, reference: f64) -> f64 {
    gpu_lens(out, i).map_or(f64::INFINITY, |v| (v / reference - 1.0).abs())
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    /// The larger singular value of the inverse against a hand calculation: J = diag(2, 0.25)
    /// maps one pixel to 2 and 0.25 texels, so one texel step spans 0.5 and 4 pixels: 4. A
    /// rotation keeps it; a shear by hand: J = [[1, 1], [0, 1]] has J⁻¹ = [[1, −1], [0, 1]],
    /// whose singular values are the golden ratio φ = (1 + √5)/2 and 1/φ.
    #[test]
    fn pixels_per_texel_by_hand() {
        let d = DMat2::from_cols(DVec2::new(2.0, 0.0), DVec2::new(0.0, 0.25));
        assert!((pixels_per_texel(d).unwrap() - 4.0).abs() < 1e-12);
        let r = DMat2::from_angle(0.7);
        assert!((pixels_per_texel(r * d).unwrap() - 4.0).abs() < 1e-12);
        let shear = DMat2::from_cols(DVec2::new(1.0, 0.0), DVec2::new(1.0, 1.0));
        let phi = 0.5 * (1.0 + 5f64.sqrt());
        assert!((pixels_per_texel(shear).unwrap() - phi).abs() < 1e-12);
        assert_eq!(pixels_per_texel(DMat2::from_cols(DVec2::X, DVec2::X)), None);
    }
}
