//! Culling volumes per map (issue 23, item 4): the world-space convex volumes a renderer tests
//! each object against before drawing it into a map (the casters') or before shading it with the
//! map (the receivers'), as planes in fixed arrays (no heap allocation).
//!
//! - **The casters' volume** is the focus body B swept toward the light, cut by the map's depth
//!   range: the side planes of the prism of B's light-space footprint (the prism
//!   `super::casters` clips the caster boxes by), B's own bounding planes that face away from the
//!   light (the sweep's floor), and the map's near and far depth planes (`w ± z ≥ 0` of the map;
//!   without the near plane under `depth_clamp`, whose map draws casters nearer the light at its
//!   near depth). Every point that can shadow B and that the map's depth range holds lies in it,
//!   and every point of it does (up to the slack below).
//! - **The receivers' volume** is the slice of the frustum (the map's covered depth range) ∩ the
//!   receivers' bound (∩ a face part's prism for face partitions): the planes B is clipped by.
//!
//! Planes that do not touch B (farther than 10⁻⁶ of the frustum's size from each of its vertices)
//! are redundant and left out. Every plane has a unit normal and is pushed outward by 10⁻⁹ of the
//! frustum's size (plus the rounding of its offset in world space), so that B's vertices and the
//! casters' point that fixed the depth range, which lie on the planes, test inside.

use super::casters::Prism;
use super::input::Aabb;
use super::{Ctx, MAX_BODY_VERTICES, MAX_BOUND_PLANES};
use crate::error::{fmt_num, Error, Result};
use crate::frustum::LightDir;
use crate::geom::polytope::frustum_planes;
use crate::maps::fit::FrustumInLight;
use crate::maps::lightspace::{light_space_unit, LightSpace};
use glam::{DMat4, DVec3, DVec4};

/// The most planes a [`CullVolume`] holds: the casters' volume has a side plane per vertex of
/// B's footprint (at most [`MAX_BODY_VERTICES`]), B's bounding planes that face away from the
/// light (the slice's 6, the receivers' [`MAX_BOUND_PLANES`], a face part's 4) and the map's 2
/// depth planes.
pub const MAX_CULL_PLANES: usize = MAX_BODY_VERTICES + 6 + MAX_BOUND_PLANES + 4 + 2;

/// A convex volume of world space: up to [`MAX_CULL_PLANES`] planes `(a, b, c, d)` with unit
/// normals `(a, b, c)`, inside where `a x + b y + c z + d ≤ 0` (the convention of
/// [`Bound::Polytope`](super::Bound::Polytope)). The casters' volume is unbounded toward the light
/// under `depth_clamp`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CullVolume {
    planes: [DVec4; MAX_CULL_PLANES],
    len: usize,
}

impl CullVolume {
    pub(super) const EMPTY: Self = Self {
        planes: [DVec4::ZERO; MAX_CULL_PLANES],
        len: 0,
    };

    /// The planes, world space, unit normals, inside where `n·p + d ≤ 0`.
    #[must_use]
    pub fn planes(&self) -> &[DVec4] {
        &self.planes[..self.len]
    }

    /// Whether the world point `p` lies inside (on a plane counts as inside).
    #[must_use]
    pub fn contains(&self, p: DVec3) -> bool {
        self.planes()
            .iter()
            .all(|pl| pl.truncate().dot(p) + pl.w <= 0.0)
    }

    /// Whether the world box `b` may meet the volume: `false` only when one plane has the whole
    /// box outside it (then the box is certainly outside: cull it). Conservative: a box outside
    /// the volume near one of its edges, with no single plane separating it, gives `true`.
    #[must_use]
    pub fn intersects_aabb(&self, b: &Aabb) -> bool {
        self.planes().iter().all(|pl| {
            // The box's corner farthest inside the plane (smallest n·p).
            let n = pl.truncate();
            let corner = DVec3::select(n.cmpge(DVec3::ZERO), b.min, b.max);
            n.dot(corner) + pl.w <= 0.0
        })
    }

    /// The volume with every plane pushed outward by `distance` world units: a margin for what a
    /// map's lookup reads beyond B's footprint (the texel around a point and a filter's kernel:
    /// `(r + 1) · √2 · texel_world` for a PCF kernel of radius r texels).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `distance` when it is negative or not finite.
    pub fn grown(&self, distance: f64) -> Result<Self> {
        if !(distance.is_finite() && distance >= 0.0) {
            return Err(Error::invalid(
                "distance",
                format!(
                    "must be a finite distance ≥ 0 in world units (got {})",
                    fmt_num(distance)
                ),
            ));
        }
        let mut out = *self;
        for p in &mut out.planes[..out.len] {
            p.w -= distance;
        }
        Ok(out)
    }

    /// Starts the volume over in place (the planes are written by [`CullVolume::push`], the
    /// unused tail zeroed by [`CullVolume::seal`]).
    fn clear(&mut self) {
        self.len = 0;
    }

    /// Zeroes the planes past `len`: the volume is then the one pushed onto [`CullVolume::EMPTY`],
    /// whatever it held before.
    fn seal(&mut self) {
        self.planes[self.len..].fill(DVec4::ZERO);
    }

    fn push(&mut self, p: DVec4) {
        if self.len < MAX_CULL_PLANES && p.is_finite() {
            self.planes[self.len] = p;
            self.len += 1;
        }
    }
}

/// `p` scaled to a unit normal; `None` for a zero or non-finite normal.
fn unit(p: DVec4) -> Option<DVec4> {
    let len = p.truncate().length();
    (len > 0.0 && len.is_finite() && p.is_finite()).then(|| p / len)
}

impl Ctx<'_, '_> {
    /// The light space the casters' volume takes B's footprint in: y toward the light, z the
    /// view direction projected (as most warps' own, `maps::warp::rule_axis`, and the face
    /// partitions' and TSM's casters), so that a caller's prism in it serves the volume too.
    pub(super) fn sweep_space(&self) -> LightSpace {
        light_space_unit(LightDir::from_unit_unchecked(self.l), DVec3::NEG_Z)
    }

    /// The casters' and the receivers' culling volumes (module docs) of the map `eye_to_clip`
    /// (OpenGL depth) of the focus body `pts` (eye space), B being the slice `cover` ∩ the
    /// receivers' bound ∩ `extra`, into `casters` and `receivers` (in place: whatever they held
    /// before, the result is the same). `prism`: the prism of B's footprint in
    /// [`Ctx::sweep_space`] if the caller has built it (the same value this would build).
    pub(super) fn cull_volumes(
        &self,
        pts: &[DVec3],
        eye_to_clip: &DMat4,
        (cover, extra, prism): ((f64, f64), &[DVec4], Option<&Prism>),
        casters: &mut CullVolume,
        receivers: &mut CullVolume,
    ) {
        let scale = self.scale();
        let keep = 1e-6 * scale;
        let slack = 1e-9 * scale;
        let w2e_t = self.input.camera.world_to_eye.transpose();
        // An eye plane π is W2Eᵀ π in world space (π·(W2E p, 1) = (W2Eᵀ π)·(p, 1)), pushed
        // outward by the slack and its offset's rounding.
        let to_world = |p: DVec4| -> Option<DVec4> {
            let p = unit(p)?;
            let w = unit(w2e_t * (p - DVec4::new(0.0, 0.0, 0.0, slack)))?;
            Some(w - DVec4::new(0.0, 0.0, 0.0, 4.0 * f64::EPSILON * w.w.abs()))
        };
        let mut slice = frustum_planes(self.view, cover.1);
        slice[0].w = cover.0;
        let bounds = slice
            .iter()
            .chain(&self.planes.p[..self.planes.n])
            .chain(extra)
            .filter_map(|p| unit(*p));
        casters.clear();
        receivers.clear();
        for p in bounds {
            let n = p.truncate();
            let nearest = pts
                .iter()
                .map(|v| n.dot(*v) + p.w)
                .fold(f64::NEG_INFINITY, f64::max);
            if nearest < -keep {
                continue; // does not touch B: redundant
            }
            let Some(w) = to_world(p) else { continue };
            receivers.push(w);
            // A plane whose outside lies away from the light bounds the sweep too.
            if n.dot(self.l) >= 0.0 {
                casters.push(w);
            }
        }
        // The sweep's sides: the prism of B's footprint, in any light space.
        let own;
        let prism = match prism {
            Some(p) => Some(p),
            None => {
                own = FrustumInLight::<MAX_BODY_VERTICES>::from_points(
                    pts,
                    self.l,
                    self.sweep_space(),
                )
                .map(|fl| Prism::new(&fl, pts.len()));
                own.as_ref()
            }
        };
        for p in prism.map_or(&[][..], Prism::planes) {
            if let Some(w) = to_world(*p) {
                casters.push(w);
            }
        }
        // The map's depth range: w − z ≥ 0 (far) and, unless the device clamps depth, w + z ≥ 0.
        let (r2, r3) = (eye_to_clip.row(2), eye_to_clip.row(3));
        if let Some(w) = to_world(r2 - r3) {
            casters.push(w);
        }
        if !self.input.depth_clamp {
            if let Some(w) = to_world(-(r3 + r2)) {
                casters.push(w);
            }
        }
        casters.seal();
        receivers.seal();
    }
}
