//! The footprint of one screen pixel in a shadow map, on a surface of given orientation: the
//! exact Jacobian of screen pixel → surface point → shadow texel.
//!
//! # What is computed
//!
//! Two projective maps act on the same 3D space (any space: world, eye, …):
//!
//! - the **camera** `C` (any 4×4 projection to clip space; x, y ∈ [−1, 1] after the divide span
//!   the screen), with the pixel of a point `p` at
//!   `u = (x_c/w_c + 1) W/2`, `v = (1 − y_c/w_c) H/2` (`W × H` pixels, rows counted from the top,
//!   the wgpu / Vulkan / Direct3D / Metal framebuffer convention: NDC y up, pixel rows down);
//! - the **light** `M` (any 4×4 matrix to light clip space, the crate's convention of
//!   [`crate::maps::ShadowMatrix`]: `s = (x/w + 1)/2`, `t = (y/w + 1)/2`), with the texel
//!   coordinates `(s·res_s, t·res_t)`.
//!
//! The surface is the plane through `p` with normal `n`. Restricted to that plane both maps are
//! 2D → 2D. With `(e₁, e₂)` any basis of the plane and the exact gradients of a projective map,
//! `∇(h.x/h.w) = (M₀ − (h.x/h.w) M₃)/h.w` (`Mᵢ` the first three entries of row i; no finite
//! differences), the chain rule gives
//!
//! ```text
//! F = ∂(u, v)/∂(e₁, e₂) = diag(W/2, −H/2) · [∇(x_c/w_c); ∇(y_c/w_c)] · [e₁ e₂]
//! G = ∂(s·res_s, t·res_t)/∂(e₁, e₂) = diag(res_s, res_t) · [∇s; ∇t] · [e₁ e₂]
//! J = ∂(texel)/∂(pixel) = G F⁻¹
//! ```
//!
//! independent of the basis (a change of basis `B` gives `G B (F B)⁻¹ = G F⁻¹`). `J` maps a
//! one-pixel step on the screen to the texel step it makes on the surface: texels per pixel.
//! Its inverse maps a one-texel step to pixels; the **aliasing error** is the largest stretch of
//! that inverse, `1/σ_min(J)` pixels per texel (> 1: a texel covers more than one pixel, the
//! shadow's edges are blocky; [`Footprint::error`]).
//!
//! # Relation to the papers and to [`crate::measure::point_error`]
//!
//! Lloyd 2006 §4.4 writes the error as `m = (w_l/w_i) · (cos φ_i / cos φ_l)`: the *perspective
//! factor* (light beam width over image beam width, measured perpendicular to the beams, which
//! is what [`crate::measure::point_error`] measures) times the *projection factor* of the
//! surface (φ_i, φ_l the angles between the surface normal and the image and light beams); Zhang
//! et al. factorise their local aliasing the same way (perspective × projection aliasing, their
//! Eq 8–9). `J` contains both: it is the surface's full, per-direction version.
//!
//! For the crate's symmetric camera (half field of view θ, aspect `W/H`), a surface whose normal
//! is the view axis `f̂` (the plane of constant eye depth, perpendicular to the view ray at the
//! centre of the screen) and `point_error` with `Resolutions::new(H, res_s, res_t)`: a pixel
//! covers `w_i²` of that plane, `w_i² |f̂·L|` of the plane Π ⊥ L, and a texel covers `w_ls w_lt`
//! of Π, so
//!
//! ```text
//! |det J| · m_x · m_z = |f̂·L|
//! ```
//!
//! and when the light travels along the view axis (`L = ±f̂`, the surface is Π) a one-texel step
//! along s is `m_x` pixels: `|J⁻¹ (1, 0)ᵀ| = m_x`. `tests/footprint.rs` checks both.
//!
//! # Domain and units
//!
//! Pixels and texels are the units of `J`; the space of `p` and `n` is whatever `C` and `M` take.
//! The point must be in front of the camera (`w_c > 0`) and of the light's centre of projection
//! (`w > 0`), and the plane must not be edge-on to the camera (`F` singular: a pixel then covers
//! an unbounded strip of the surface). A plane edge-on to the *light* is valid: `J` is singular,
//! and [`Footprint::error`] reports that the texel is unbounded on the screen.
//!
//! ```
//! use shadow_aliasing::measure::footprint::{surface_footprint, Grids};
//! use glam::{DMat4, DVec3};
//! // Camera and light both straight down onto the ground plane y = 0 from 10 units up:
//! // an orthographic light whose map spans 20 units with 100 texels, a 90° camera with 200
//! // pixels across 20 units at that depth: half a texel per pixel.
//! let camera = glam::dcamera::rh::proj::directx::perspective(90f64.to_radians(), 1.0, 1.0, 100.0)
//!     * glam::dcamera::rh::view::look_at_mat4(DVec3::new(0.0, 10.0, 0.0), DVec3::ZERO, DVec3::NEG_Z);
//! let light = glam::dcamera::rh::proj::directx::orthographic(-10.0, 10.0, -10.0, 10.0, 0.0, 20.0)
//!     * glam::dcamera::rh::view::look_at_mat4(DVec3::new(0.0, 10.0, 0.0), DVec3::ZERO, DVec3::NEG_Z);
//! let g = Grids::new(200, 200, 100, 100)?;
//! let f = surface_footprint(&camera, &light, g, DVec3::ZERO, DVec3::Y)?;
//! assert!((f.jacobian.x_axis.x - 0.5).abs() < 1e-12);
//! assert!((f.error()? - 2.0).abs() < 1e-12); // two pixels per texel
//! # Ok::<(), shadow_aliasing::Error>(())
//! ```

use crate::error::{Error, Result};
use glam::{DMat2, DMat4, DVec2, DVec3, DVec4};

/// The two pixel grids: the screen (`width × height` pixels) and the shadow map
/// (`res_s × res_t` texels).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grids {
    width: f64,
    height: f64,
    res_s: f64,
    res_t: f64,
}

impl Grids {
    /// Validates the sizes.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `width`, `height`, `res_s` or `res_t` when zero.
    pub fn new(width: u32, height: u32, res_s: u32, res_t: u32) -> Result<Self> {
        for (name, v) in [
            ("width", width),
            ("height", height),
            ("res_s", res_s),
            ("res_t", res_t),
        ] {
            if v == 0 {
                return Err(Error::invalid(name, "must be at least 1 (got 0)"));
            }
        }
        Ok(Self {
            width: f64::from(width),
            height: f64::from(height),
            res_s: f64::from(res_s),
            res_t: f64::from(res_t),
        })
    }
    /// Screen width in pixels.
    #[must_use]
    pub fn width(&self) -> f64 {
        self.width
    }
    /// Screen height in pixels.
    #[must_use]
    pub fn height(&self) -> f64 {
        self.height
    }
    /// Map texels along s.
    #[must_use]
    pub fn res_s(&self) -> f64 {
        self.res_s
    }
    /// Map texels along t.
    #[must_use]
    pub fn res_t(&self) -> f64 {
        self.res_t
    }
}

/// A pixel's footprint in the shadow map (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Footprint {
    /// `J = ∂(s·res_s, t·res_t)/∂(u, v)`, texels per pixel; column 0 is the derivative along
    /// the pixel column index u, column 1 along the row index v (rows from the top).
    pub jacobian: DMat2,
    /// The point's pixel coordinates `(u, v)` (pixel centres at half-integers).
    pub pixel: DVec2,
    /// The point's texel coordinates `(s·res_s, t·res_t)`.
    pub texel: DVec2,
}

impl Footprint {
    /// The singular values of `J`, largest first: the most and fewest texels one pixel step
    /// crosses.
    #[must_use]
    pub fn singular_values(&self) -> (f64, f64) {
        let j = self.jacobian;
        let a = j.x_axis.length_squared() + j.y_axis.length_squared();
        let d = j.determinant().abs();
        // σ₁² + σ₂² = a, σ₁ σ₂ = |det|: σ₁² = (a + √(a² − 4 d²))/2, σ₂ = d/σ₁ (no cancellation).
        let disc = ((a - 2.0 * d) * (a + 2.0 * d)).max(0.0).sqrt();
        let s1 = (0.5 * (a + disc)).sqrt();
        let s2 = if s1 > 0.0 { d / s1 } else { 0.0 };
        (s1, s2)
    }

    /// The aliasing error: the largest number of pixels one texel step covers, `1/σ_min(J)`.
    ///
    /// # Errors
    /// [`Error::Degenerate`] when `J` is singular (the surface is edge-on to the light: one
    /// texel covers an unbounded strip of it).
    pub fn error(&self) -> Result<f64> {
        let (_, s2) = self.singular_values();
        let e = 1.0 / s2;
        if e.is_finite() {
            Ok(e)
        } else {
            Err(Error::Degenerate(format!(
                "the footprint at pixel {} is singular: the surface is edge-on to the light, a \
                 texel covers an unbounded strip of it",
                self.pixel
            )))
        }
    }
}

/// The gradients of `(x/w, y/w)` of `m (p, 1)` and the projected `(x/w, y/w)`, or the reason
/// the point has none.
fn projected_gradients(m: &DMat4, p: DVec3, what: &str) -> Result<(DVec2, DVec3, DVec3)> {
    let h = *m * DVec4::new(p.x, p.y, p.z, 1.0);
    if !h.is_finite() || h.w <= 0.0 {
        return Err(Error::Degenerate(format!(
            "the point {p} maps to w = {} (behind the {what}'s centre of projection)",
            h.w
        )));
    }
    let (r0, r1, r3) = (
        m.row(0).truncate(),
        m.row(1).truncate(),
        m.row(3).truncate(),
    );
    let (x, y) = (h.x / h.w, h.y / h.w);
    Ok((DVec2::new(x, y), (r0 - x * r3) / h.w, (r1 - y * r3) / h.w))
}

/// The exact footprint of the pixel at surface point `point` (normal `normal`, any length) in
/// the shadow map `light` seen through `camera` (module docs: conventions, math, domain).
///
/// # Errors
/// [`Error::InvalidArgument`] naming `camera` or `light` (non-finite entries), `point`
/// (non-finite) or `normal` (zero or non-finite); [`Error::Degenerate`] when the point is
/// behind the camera or the light's centre of projection, or the plane is edge-on to the camera
/// (or `J` is not finite).
pub fn surface_footprint(
    camera: &DMat4,
    light: &DMat4,
    grids: Grids,
    point: DVec3,
    normal: DVec3,
) -> Result<Footprint> {
    if !camera.is_finite() {
        return Err(Error::invalid("camera", "must have finite entries"));
    }
    if !light.is_finite() {
        return Err(Error::invalid("light", "must have finite entries"));
    }
    if !point.is_finite() {
        return Err(Error::invalid(
            "point",
            format!("must be finite (got {point})"),
        ));
    }
    let len = normal.length();
    if !normal.is_finite() || len <= 0.0 || !len.is_finite() {
        return Err(Error::invalid(
            "normal",
            format!("must be a finite, non-zero vector (got {normal})"),
        ));
    }
    let n = normal / len;
    let (ndc, gx, gy) = projected_gradients(camera, point, "camera")?;
    let (st, gs, gt) = projected_gradients(light, point, "light")?;
    // An orthonormal basis of the plane.
    let e1 = n.any_orthonormal_vector();
    let e2 = n.cross(e1);
    let (hw, hh) = (0.5 * grids.width, 0.5 * grids.height);
    let f = DMat2::from_cols(
        DVec2::new(hw * gx.dot(e1), -hh * gy.dot(e1)),
        DVec2::new(hw * gx.dot(e2), -hh * gy.dot(e2)),
    );
    let det = f.determinant();
    // |det F| / |F|²_F = σ₁σ₂/(σ₁² + σ₂²) ≈ 1/cond(F): edge-on to the camera, the map of lengths
    // to pixels loses rank (to rounding, which makes it ~10⁻¹⁶ there).
    let scale = f.x_axis.length_squared() + f.y_axis.length_squared();
    if !det.is_finite() || det.abs() <= 1e-12 * scale {
        return Err(Error::Degenerate(format!(
            "the surface through {point} with normal {n} is edge-on to the camera: a pixel \
             covers an unbounded strip of it"
        )));
    }
    let (ss, st_) = (0.5 * grids.res_s, 0.5 * grids.res_t);
    let g = DMat2::from_cols(
        DVec2::new(ss * gs.dot(e1), st_ * gt.dot(e1)),
        DVec2::new(ss * gs.dot(e2), st_ * gt.dot(e2)),
    );
    let jacobian = g * f.inverse();
    if !jacobian.is_finite() {
        return Err(Error::Degenerate(format!(
            "the footprint at {point} overflows f64"
        )));
    }
    Ok(Footprint {
        jacobian,
        pixel: DVec2::new((ndc.x + 1.0) * hw, (1.0 - ndc.y) * hh),
        texel: DVec2::new((st.x + 1.0) * ss, (st.y + 1.0) * st_),
    })
}
