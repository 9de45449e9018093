//! The per-pixel error lens ([`FrameMap::error_lens_at`], the WGSL module's `sa_error_lens`) and
//! its colour ramp ([`lens_colour`], `sa_lens_colour`).
//!
//! # The quantity
//!
//! At a shaded point p with unit normal n, the lens is the size of the map's shadow texel in
//! screen pixels on that surface: the largest number of pixels a one-texel step covers, the
//! aliasing error `1/σ_min(J)` of [`crate::measure::footprint`] (perspective factor times the
//! surface's projection factor, Lloyd 2006 §4.4), taken from the map matrix's local Jacobian:
//!
//! - the texel's edge vectors `T_e = (2/res) E_e` (e = s, t; [`super::bias`]'s `E_s`, `E_t` in the
//!   plane ⊥ l, l the direction the light travels);
//! - projected along the light onto the surface, `P(v) = v − ((n · v)/(n · l)) l`: this is the
//!   projection factor (a surface at grazing light, n · l → 0, stretches the texel without bound);
//! - seen by the camera: a world vector v at p moves the pixel by `(k/z) (v − ((v · f)/z) d)`,
//!   d = p − eye, f the unit view axis, z = d · f the view depth, k = H/(2 tan θ) for an image of
//!   H pixels and half vertical field of view θ (square pixels: a vector in the plane ⊥ f is as
//!   long in pixels as in the screen's axes);
//! - the lens is the larger singular value of the two pixel vectors a, b of the two texel
//!   steps: `√((|a|² + |b|² + √((|a|² − |b|²)² + 4 (a · b)²)) / 2)`.
//!
//! It is a property of the surface, not of the map alone: the frame's
//! [`FrameMap::max_error_pixels`] is Lloyd's perspective factor (texel and pixel each measured
//! across its own beam, M_x and M_z over B's vertices), which the projection factor
//! `cos φ_i / cos φ_l` multiplies (φ_i, φ_l the angles of the normal to the view and light
//! beams). A surface facing the camera at grazing light has a lens far above the frame's maximum;
//! `a_grazing_lit_surface_exceeds_the_perspective_maximum` (tests/lens.rs) shows one.
//!
//! # The ramp
//!
//! [`lens_colour`] maps a lens value to viridis (matplotlib's ten-colour table, colour-blind
//! safe, lightness rising monotonically) on a log₂ scale: the ten colours at 1/16, 1/8, …, 32
//! pixels, linear in log₂ between them, clamped at both ends; 1 pixel is the fifth colour,
//! `#26828e` (teal). Not finite (an unbounded texel) is the last colour. docs/renderer.md ("The
//! error lens") shows the legend.

use super::input::Camera;
use super::output::{texel_vectors, FrameMap};
use crate::error::{Error, Result};
use glam::DVec3;

/// matplotlib's viridis at t = 0, 1/9, …, 1 (its ten-colour table, #440154 … #fde725), the lens
/// ramp's colours at 2⁻⁴ … 2⁵ pixels.
pub const LENS_RAMP: [[u8; 3]; 10] = [
    [0x44, 0x01, 0x54],
    [0x48, 0x28, 0x78],
    [0x3e, 0x49, 0x89],
    [0x31, 0x68, 0x8e],
    [0x26, 0x82, 0x8e],
    [0x1f, 0x9e, 0x89],
    [0x35, 0xb7, 0x79],
    [0x6e, 0xce, 0x58],
    [0xb5, 0xde, 0x2b],
    [0xfd, 0xe7, 0x25],
];

/// log₂ of the pixels at [`LENS_RAMP`]'s first colour.
pub const LENS_RAMP_LOG2_MIN: f64 = -4.0;

/// The lens ramp's colour (sRGB components in [0, 1]) for a lens value in pixels (module docs):
/// [`LENS_RAMP`] at `log₂ value − LENS_RAMP_LOG2_MIN`, linear between its colours, clamped at its
/// ends; 1 pixel is `#26828e`; a value that is not finite (or NaN) the last colour, 0 or less the
/// first. The WGSL module's `sa_lens_colour` is the same in `f32`.
#[must_use]
pub fn lens_colour(value: f64) -> [f64; 3] {
    let last = (LENS_RAMP.len() - 1) as f64;
    let x = if value < f64::MAX {
        (value.max(1e-30).log2() - LENS_RAMP_LOG2_MIN).clamp(0.0, last)
    } else {
        last
    };
    let i = (x.floor() as usize).min(LENS_RAMP.len() - 2);
    let f = x - i as f64;
    let (a, b) = (LENS_RAMP[i], LENS_RAMP[i + 1]);
    let mix = |k: usize| (f64::from(a[k]) + f * (f64::from(b[k]) - f64::from(a[k]))) / 255.0;
    [mix(0), mix(1), mix(2)]
}

impl FrameMap {
    /// The error lens at the world point `p` with surface normal `n` (any length): the size in
    /// screen pixels of this map's texel on that surface, seen by `camera` on an image
    /// `image_height` pixels high (module [`crate::frame::lens`]; the WGSL module's
    /// `sa_error_lens` in `f32`). It includes the surface's projection factor: a surface at
    /// grazing light gets a large value, whichever way it faces.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `p` (not finite), `n` (not a finite non-zero vector) or
    /// `image_height` (0); [`Error::Degenerate`] where `p` is not in front of the camera or of
    /// the map's centre of projection, or the surface is edge-on to the light (the texel covers
    /// an unbounded strip of it).
    pub fn error_lens_at(
        &self,
        p: impl Into<DVec3>,
        n: impl Into<DVec3>,
        camera: &Camera,
        image_height: u32,
    ) -> Result<f64> {
        let (p, n) = (p.into(), n.into());
        if !p.is_finite() {
            return Err(Error::invalid("p", "the surface point must be finite"));
        }
        let n = n.try_normalize().ok_or_else(|| {
            Error::invalid("n", "the surface normal must be a finite, non-zero vector")
        })?;
        if image_height == 0 {
            return Err(Error::invalid(
                "image_height",
                "the image must be at least 1 pixel high",
            ));
        }
        let eye = camera.eye_to_world.transform_point3(DVec3::ZERO);
        let forward = camera
            .eye_to_world
            .transform_vector3(DVec3::NEG_Z)
            .normalize();
        let d = p - eye;
        let z = d.dot(forward);
        if z.is_nan() || z <= 0.0 {
            return Err(Error::Degenerate(format!(
                "the point {p} is not in front of the camera (view depth {z})"
            )));
        }
        let l = self
            .world_to_eye
            .inverse()
            .transform_vector3(self.shadow.light_dir())
            .normalize();
        let (es, et) = texel_vectors(&self.world_to_clip, l, p).ok_or_else(|| {
            Error::Degenerate(format!(
                "the point {p} is behind the map's centre of projection, or the map is singular \
                 there"
            ))
        })?;
        let texel = 2.0 / f64::from(self.resolution);
        let nl = n.dot(l);
        let k = f64::from(image_height) / (2.0 * camera.view.tan_half_fov() * z);
        // A world vector at p in pixels: along the view ray onto the plane ⊥ f, scaled.
        let pixels = |e: DVec3| {
            let v = texel * e;
            let v = v - (n.dot(v) / nl) * l;
            k * (v - (v.dot(forward) / z) * d)
        };
        let (a, b) = (pixels(es), pixels(et));
        let (aa, bb, ab) = (a.length_squared(), b.length_squared(), a.dot(b));
        let lens = (0.5 * (aa + bb + ((aa - bb) * (aa - bb) + 4.0 * ab * ab).sqrt())).sqrt();
        if lens.is_finite() {
            Ok(lens)
        } else {
            Err(Error::Degenerate(format!(
                "the surface through {p} with normal {n} is edge-on to the light: a texel covers \
                 an unbounded strip of it"
            )))
        }
    }
}
