//! The general case (Martin & Tan §6.4): the trapezoidal map of the view frustum restricted to
//! a convex bound.

use super::search::Core;
use super::{validate, ConvexBound, TsmMap, TsmOptions};
use crate::error::{fmt_num, Error, Result};
use crate::frustum::ViewFrustum;
use crate::geom::polytope::{frustum_planes, polytope_vertices};
use crate::maps::lightspace::light_space;
use glam::{DVec3, DVec4};

/// The trapezoidal map of the part of the view frustum inside `bound` (Martin & Tan §6.4; module
/// docs). No heap allocation.
///
/// # Errors
/// As [`super::tsm`]; [`Error::NoSolution`] when the bound does not meet the view frustum in a solid.
///
/// ```
/// # use shadow_aliasing::maps::tsm::{tsm_general, ConvexBound, TsmOptions, TsmSearch};
/// # use shadow_aliasing::ViewFrustum;
/// # use glam::{DMat4, DVec3, DVec4};
/// let view = ViewFrustum::new(1.0, 100.0, 0.5)?;
/// // The scene is a box 40 units deep in front of the camera (world = eye here).
/// let bound = ConvexBound::from_aabb(DVec3::new(-50.0, -5.0, -40.0), DVec3::new(50.0, 5.0, 0.0), DMat4::IDENTITY)?;
/// let opts = TsmOptions { focus: 20.0, search: TsmSearch::EightyPercent };
/// let t = tsm_general(&view, DVec3::new(0.3, -1.0, 0.2), &bound, opts)?;
/// let h = t.shadow.matrix() * DVec4::new(0.0, 0.0, -40.0, 1.0);
/// assert!((h.truncate() / h.w).abs().max_element() <= 1.0 + 1e-9);
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn tsm_general(
    view: &ViewFrustum,
    light_dir: DVec3,
    bound: &ConvexBound,
    opts: TsmOptions,
) -> Result<TsmMap> {
    validate(view, &opts)?;
    let (n, f) = (view.near(), view.far());
    let scale = f * (1.0 + view.tan_half_fov() * (1.0 + view.aspect()));
    let mut planes = [DVec4::ZERO; 13];
    planes[..6].copy_from_slice(&frustum_planes(view, f));
    planes[6..12].copy_from_slice(bound.planes());
    let mut verts = [DVec3::ZERO; 64];
    let count = polytope_vertices(&planes[..12], scale, &mut verts);
    if count < 4 {
        return Err(Error::NoSolution(format!(
            "the bound does not meet the view frustum in a solid region (their intersection \
             has {count} vertices, a solid at least 4): give a bound that overlaps the view"
        )));
    }
    let pts = &verts[..count];
    let e = pts.iter().fold(DVec3::ZERO, |a, p| a + *p) / count as f64;
    let (mut n_i, mut f_i) = (f64::INFINITY, f64::NEG_INFINITY);
    for p in pts {
        n_i = n_i.min(-p.z);
        f_i = f_i.max(-p.z);
    }
    if f_i - n_i <= 1e-12 * scale {
        return Err(Error::NoSolution(format!(
            "the bound meets the view frustum in a region without depth (got depths [{}, {}]): \
             give a bound that overlaps the view in depth",
            fmt_num(n_i),
            fmt_num(f_i)
        )));
    }
    let ls = light_space(light_dir, e)?;
    let focus = opts.focus * (f_i - n_i) / (f - n);
    // The focus point on the centre line (eye → e) at depth n_I + focus.
    let focus_point = e * ((n_i + focus) / -e.z);
    // The focus region: I cut at that depth.
    planes[12] = DVec4::new(0.0, 0.0, -1.0, -(n_i + focus));
    let mut fverts = [DVec3::ZERO; 64];
    let fcount = polytope_vertices(&planes[..13], scale, &mut fverts);
    // The centre line's projected length: from the eye's depth-n_I point to the f_I point on l.
    let dir = e / -e.z;
    let centre_line = (ls.z.dot(dir) * (f_i - n_i)).abs();
    let core = Core {
        ls,
        points: pts,
        focus_region: &fverts[..fcount],
        focus_point,
        centre_line,
    };
    core.build::<64, 128>(opts.search, n_i, f_i)
}
