//! The uniform (orthographic) map, and every map with a caster bound: fitted to the view frustum
//! with casters nearer the light clamped to depth zero (Lloyd 2006 §6.4), or enclosing the bound.
//!
//! Only occluders between the light and the view frustum need a depth in the map. Lloyd 2006 §6.4
//! (after Brabec et al. 2002): "It is sufficient to clamp the depth of occluders between the view
//! frustum and the light to zero … The warping frustum need only be fit to the view frustum."
//! With [`CasterDepth::Clamp`] the builder does exactly that, and the renderer enables depth
//! clamping (OpenGL `GL_DEPTH_CLAMP`, Vulkan `depthClampEnable`, wgpu `unclipped_depth`, Direct3D
//! `DepthClipEnable = FALSE`) so that casters with clip depth below the near end land at depth 0
//! (clip z = −1 in [`crate::maps::ClipDepth::NegOneToOne`], 0 in `ZeroToOne`). Casters outside
//! the light's extrusion of the frustum fall outside the map in x or y; they cannot shadow any
//! visible point. With [`CasterDepth::Enclose`] the map is fitted around the frustum and the
//! caster bound together (every caster point inside the clip volume, no depth clamp needed), at
//! the resolution cost the measurement shows.

use crate::error::{Error, Result};
use crate::frustum::{NPrime, ViewFrustum};
use crate::maps::lightspace::LightSpace;
use crate::maps::matrix::ShadowMatrix;
use crate::maps::warp::{
    rule_frame, rule_n_prime, verify_clip, warp_matrix, FrustumInLight, Ranges, WarpRule,
};
use glam::{DMat4, DVec3};

/// What the map does with a caster bound.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum CasterDepth {
    /// Fit to the view frustum only; casters nearer the light than the frustum get clip depth
    /// below the near end, which the renderer clamps to 0 (Lloyd 2006 §6.4).
    #[default]
    Clamp,
    /// Fit around the view frustum and the caster bound together: every caster point maps into
    /// the clip volume.
    Enclose,
}

/// The uniform map: orthographic, tightly fitted to the view frustum in the light space of
/// [`crate::maps::light_space`] (s along x, t along the view direction projected, depth along the
/// light). Equal to `warp(view, light_dir, WarpRule::Uniform)`.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `light_dir` for a zero or non-finite vector.
///
/// ```
/// # use shadow_aliasing::maps::uniform::uniform;
/// # use shadow_aliasing::measure::frustum_max;
/// # use shadow_aliasing::ViewFrustum;
/// # use glam::DVec3;
/// let view = ViewFrustum::new(1.0, 10.0, 0.5)?;
/// // Light from behind: S̄ = (f/n)² (Lloyd 2006 Eq 20, k = 1).
/// let s = uniform(&view, DVec3::new(0.0, 0.0, -1.0))?;
/// let e = frustum_max(&view, &s.shadow_map())?;
/// assert!((e.storage_factor - 100.0).abs() < 1e-9);
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn uniform(view: &ViewFrustum, light_dir: DVec3) -> Result<ShadowMatrix> {
    crate::maps::warp::warp(view, light_dir, WarpRule::Uniform)
}

/// The map of `rule` with a caster bound (eye-space points, for instance the eight corners of the
/// scene's bounding box transformed by the view matrix), handled as `depth` says.
///
/// With [`CasterDepth::Clamp`] the casters only need to be finite: the map is the frustum-only
/// map of [`crate::maps::warp()`]. With [`CasterDepth::Enclose`] the warp is fitted around the
/// frustum corners and the casters together, with the rule's n′ (chosen for the frustum, in the
/// rule's frame) measured from where that union starts along the warp axis, and the centre of
/// projection on the eye's light-space line for every rule (OGRE's near-camera-point centre is
/// [`crate::maps::warp()`]'s, for the frustum alone).
///
/// # Errors
/// As [`crate::maps::warp()`], and [`Error::InvalidArgument`] naming `casters` for a non-finite
/// point.
///
/// ```
/// # use shadow_aliasing::maps::uniform::{with_casters, CasterDepth};
/// # use shadow_aliasing::maps::WarpRule;
/// # use shadow_aliasing::ViewFrustum;
/// # use glam::{DVec3, DVec4};
/// let view = ViewFrustum::new(1.0, 30.0, 0.5)?;
/// let light = DVec3::new(0.0, -1.0, 0.2);
/// // A caster hovering 40 units above the frustum's middle.
/// let caster = [DVec3::new(0.0, 40.0, -10.0)];
/// let clamp = with_casters(&view, light, WarpRule::Uniform, &caster, CasterDepth::Clamp)?;
/// let h = clamp.matrix() * DVec4::new(0.0, 40.0, -10.0, 1.0);
/// assert!(h.z / h.w < -1.0); // nearer the light than the frustum: the renderer clamps it to 0
/// let enclose = with_casters(&view, light, WarpRule::Uniform, &caster, CasterDepth::Enclose)?;
/// let h = enclose.matrix() * DVec4::new(0.0, 40.0, -10.0, 1.0);
/// assert!((h.z / h.w).abs() <= 1.0 + 1e-12);
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn with_casters(
    view: &ViewFrustum,
    light_dir: DVec3,
    rule: WarpRule,
    casters: &[DVec3],
    depth: CasterDepth,
) -> Result<ShadowMatrix> {
    for c in casters {
        if !c.is_finite() {
            return Err(Error::invalid(
                "casters",
                format!("must be finite points (got {c})"),
            ));
        }
    }
    match depth {
        CasterDepth::Clamp => crate::maps::warp::warp(view, light_dir, rule),
        CasterDepth::Enclose => {
            let fl = FrustumInLight::new(view, light_dir)?;
            // The rule's own frame (Filament's near the parallel light), as `warp()` uses.
            let fl = rule_frame(view, &fl, rule).unwrap_or(fl);
            let n_prime = rule_n_prime(view, &fl, rule)?;
            let corners = view.corners();
            let matrix = fit_two(&corners, casters, &fl.ls, n_prime)?;
            Ok(fl.shadow_matrix(view, matrix, n_prime))
        }
    }
}

/// [`crate::maps::fit_warp`] over the union of two point sets, without allocating.
fn fit_two(a: &[DVec3], b: &[DVec3], ls: &LightSpace, n_prime: NPrime) -> Result<DMat4> {
    let rho = n_prime.recip();
    let (mut z0, mut z1) = (f64::INFINITY, f64::NEG_INFINITY);
    let mut extent = 0.0f64;
    for p in a.iter().chain(b) {
        let z = ls.z.dot(*p);
        z0 = z0.min(z);
        z1 = z1.max(z);
        extent = extent.max(p.abs().max_element());
    }
    let mut r = Ranges::new();
    for p in a.iter().chain(b) {
        let q = ls.to_light(*p);
        let w = 1.0 + rho * (q.z - z0);
        r.add(q.x / w, q.y / w);
    }
    let m = warp_matrix(ls, z0, z1 - z0, rho, &r, extent)?;
    verify_clip(&m, a.iter().chain(b))?;
    Ok(m)
}
