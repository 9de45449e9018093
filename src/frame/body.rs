//! The focus body B: the receivers' bound as eye-space planes, the slice of the frustum cut by
//! them (exact convex clipping), and B in light space.

use super::input::{bad_box, validate_polytope, Bound, Camera};
use super::output::Focus;
use super::{Ctx, MAX_BODY_VERTICES, MAX_BOUND_PLANES};
use crate::error::{Error, Result};
use crate::frustum::ViewFrustum;
use crate::geom::polytope::{extents, ConvexBody};
use crate::maps::fit::FrustumInLight;
use crate::maps::lightspace::LightSpace;
use glam::{DVec3, DVec4};

/// A clipped B whose far depth is below this fraction of its slice's is cut again from the slice
/// ended just past it ([`Ctx::body`]).
const REFINE: f64 = 1e-3;

/// The receivers' body: 6 frustum faces + 12 bound planes, a face at most 4 + 12 vertices, at
/// most 2·18 − 4 = 32 vertices (a margin for points that coincide within the tolerance).
pub(super) type BodyClip = ConvexBody<18, 18, 48>;

/// The receivers' bound as eye-space planes.
#[derive(Debug, Clone, Copy)]
pub(super) struct Planes {
    pub(super) p: [DVec4; MAX_BOUND_PLANES],
    pub(super) n: usize,
    /// The bound itself has no volume (a flat box).
    pub(super) flat: bool,
}

/// The frustum's size.
fn frustum_scale(v: &ViewFrustum) -> f64 {
    v.far() * (1.0 + v.tan_half_fov() * (1.0 + v.aspect()))
}

/// 10⁻⁹ of the size of the frustum's slice that ends at depth `far`: the unit of the frame's
/// "no extent" tests on that slice's focus body, 10 times the clipper's tolerance. Relative to
/// the slice, not to the whole frustum: at far/near = 10¹⁰ the nearest cascades are smaller
/// than 10⁻⁹ of the frustum. Computed as (10⁻⁹ far)(…), finite for every far a frustum holds.
fn slice_unit(v: &ViewFrustum, far: f64) -> f64 {
    (1e-9 * far) * (1.0 + v.tan_half_fov() * (1.0 + v.aspect()))
}

/// The receivers' bound as eye-space planes; `n = 0` for no bound. The bound is flat when it is
/// no thicker than 10⁻⁹ of the frustum's size (B's own "no thickness", so that a thin bound in
/// view is mapped as flat, never taken for one that only touches the frustum) or 10⁻¹² of its own
/// size.
pub(super) fn receiver_planes(cam: &Camera, b: &Bound<'_>) -> Result<Planes> {
    let small = 1e-9 * frustum_scale(&cam.view);
    let mut out = Planes {
        p: [DVec4::ZERO; MAX_BOUND_PLANES],
        n: 0,
        flat: false,
    };
    let it = cam.eye_to_world.transpose(); // a world plane π is (V⁻¹)ᵀ π in eye space
    match b {
        Bound::Unbounded => {}
        Bound::Boxes(boxes) => {
            let Some(first) = boxes.first() else {
                return Err(Error::invalid("receivers", "must hold at least one box"));
            };
            let (mut lo, mut hi) = (first.min, first.max);
            for bx in *boxes {
                bx.check().map_err(|_| bad_box("receivers", bx))?;
                lo = lo.min(bx.min);
                hi = hi.max(bx.max);
            }
            let world = [
                DVec4::new(1.0, 0.0, 0.0, -hi.x),
                DVec4::new(-1.0, 0.0, 0.0, lo.x),
                DVec4::new(0.0, 1.0, 0.0, -hi.y),
                DVec4::new(0.0, -1.0, 0.0, lo.y),
                DVec4::new(0.0, 0.0, 1.0, -hi.z),
                DVec4::new(0.0, 0.0, -1.0, lo.z),
            ];
            for (k, w) in world.iter().enumerate() {
                out.p[k] = it * *w;
            }
            out.n = 6;
            let size = (hi - lo).abs().max_element().max(1.0);
            out.flat = (hi - lo).min_element() <= small.max(1e-12 * size);
        }
        Bound::Polytope(planes) => {
            validate_polytope("receivers", planes)?;
            for (k, p) in planes.iter().enumerate() {
                out.p[k] = it * *p;
            }
            out.n = planes.len();
            out.flat = has_zero_thickness(planes, small);
        }
    }
    Ok(out)
}

/// Whether two of a polytope's planes bound it to zero thickness: opposite unit normals at the
/// same place (within `small` or 10⁻¹² relative to the offsets), as a flat box's top and bottom
/// planes.
fn has_zero_thickness(planes: &[DVec4], small: f64) -> bool {
    let unit = |p: &DVec4| *p / p.truncate().length();
    planes.iter().enumerate().any(|(i, a)| {
        let a = unit(a);
        planes[i + 1..].iter().any(|b| {
            let b = unit(b);
            let scale = 1.0 + a.w.abs().max(b.w.abs());
            (a.truncate() + b.truncate()).length() <= 1e-12
                && (a.w + b.w).abs() <= small.max(1e-12 * scale)
        })
    })
}

/// The focus body of one slice.
pub(super) struct Body {
    pub(super) v: [DVec3; MAX_BODY_VERTICES],
    pub(super) n: usize,
    /// B is the slice itself (no receivers' plane cut it).
    pub(super) whole: bool,
    pub(super) focus: Focus,
    /// The unit of the "no extent" tests on B: 10⁻⁹ of its slice's size (`slice_unit`).
    pub(super) unit: f64,
}

impl Ctx<'_, '_> {
    /// B's vertices `pts` in the light space `ls`, into `fl` (in place: a 2 KB value); `false`
    /// when B is edge-on to the light (no extent across the map or along the warp axis beyond
    /// `small`, B's [`Body::unit`]).
    pub(super) fn in_light(
        &self,
        pts: &[DVec3],
        small: f64,
        ls: LightSpace,
        fl: &mut FrustumInLight<MAX_BODY_VERTICES>,
    ) -> Result<bool> {
        if !fl.set_points(pts, self.l, ls) {
            return Err(Error::Degenerate("the focus body has no vertices".into()));
        }
        // `fl.q` past the body's vertices repeats the first (`FrustumInLight::from_points`), which
        // changes no minimum, maximum or extent: only the vertices are read.
        let q = &fl.q[..pts.len()];
        let (mut xl, mut xh) = (f64::INFINITY, f64::NEG_INFINITY);
        for q in q {
            xl = xl.min(q.x);
            xh = xh.max(q.x);
        }
        if xh - xl <= small || fl.delta <= small {
            return Ok(false);
        }
        // A footprint with no area in any direction (a flat B seen edge-on along a diagonal of
        // the map: a vertical wall under a sun straight down, the camera turned) is edge-on too.
        let mut foot = [DVec3::ZERO; MAX_BODY_VERTICES];
        for (f, q) in foot.iter_mut().zip(q) {
            *f = DVec3::new(q.x, 0.0, q.z);
        }
        let (_, width, _) = extents(&foot[..q.len()]);
        Ok(width > small)
    }

    pub(super) fn scale(&self) -> f64 {
        frustum_scale(self.view)
    }

    /// B for the slice `[a, b]`, cut by the planes `extra` as well.
    pub(super) fn body(&self, a: f64, b: f64, extra: &[DVec4]) -> Result<Body> {
        let sub = self.view.with_depth_range(a, b)?;
        let corners = sub.corners();
        let tol = self.clip_tol(b);
        let planes = &self.planes.p[..self.planes.n];
        let inside = |p: &DVec3| {
            planes
                .iter()
                .all(|pl| pl.truncate().dot(*p) + pl.w <= tol * pl.truncate().length())
        };
        if extra.is_empty() && corners.iter().all(inside) {
            let mut body = Body {
                v: [DVec3::ZERO; MAX_BODY_VERTICES],
                n: 8,
                whole: true,
                focus: Focus::Body,
                unit: slice_unit(self.view, b),
            };
            body.v[..8].copy_from_slice(&corners);
            return Ok(body);
        }
        let mut body = self.body_cut(self.receivers_clip(&corners)?, b, extra)?;
        // A B far smaller than its slice (a ground box near the camera, far/near = 10¹⁰) is cut
        // again from the slice ended just past it, at that slice's tolerance and unit: the
        // clipper's tolerance, 10⁻¹⁰ of the whole slice, would exceed B itself and judge it
        // empty. Each cut ends the slice at least 1/REFINE nearer: a few cuts at most.
        let mut end = b;
        while body.n > 0 {
            let far = depth_extent(&body.v[..body.n]).1 + 10.0 * self.clip_tol(end);
            if !(far < REFINE * end && far > a) {
                break;
            }
            end = far;
            let sub = self.view.with_depth_range(a, end)?;
            body = self.body_cut(self.receivers_clip(&sub.corners())?, end, extra)?;
        }
        Ok(body)
    }

    /// The clipper's tolerance on the slice that ends at depth `far`: 10⁻¹⁰ of its size.
    fn clip_tol(&self, far: f64) -> f64 {
        0.1 * slice_unit(self.view, far)
    }

    /// The hexahedron `corners` (a slice of the frustum: near face, then far face) cut by the
    /// receivers' planes.
    pub(super) fn receivers_clip(&self, corners: &[DVec3; 8]) -> Result<BodyClip> {
        let mut cb = BodyClip::hexahedron(corners);
        let tol = self.clip_tol(-corners[4].z);
        for pl in &self.planes.p[..self.planes.n] {
            if !cb.clip(*pl, tol) {
                return Err(too_many_faces());
            }
        }
        Ok(cb)
    }

    /// B from the slice that ends at depth `far` already cut by the receivers' planes
    /// (`Ctx::receivers_clip`), cut by `extra` as well: the same cuts in the same order as
    /// [`Ctx::body`] makes.
    pub(super) fn body_cut(&self, mut cb: BodyClip, far: f64, extra: &[DVec4]) -> Result<Body> {
        let tol = self.clip_tol(far);
        for pl in extra {
            if !cb.clip(*pl, tol) {
                return Err(too_many_faces());
            }
        }
        let mut body = Body {
            v: [DVec3::ZERO; MAX_BODY_VERTICES],
            n: 0,
            whole: false,
            focus: Focus::Body,
            unit: slice_unit(self.view, far),
        };
        let n = cb.vertices(tol, &mut body.v).ok_or_else(|| {
            Error::Degenerate("the focus body has more vertices than the frame holds".into())
        })?;
        body.n = n;
        let (len, width, thick) = extents(&body.v[..n]);
        let small = body.unit;
        body.focus = if self.planes.flat {
            if width <= small || len <= small {
                Focus::Empty
            } else {
                Focus::Flat
            }
        } else if thick <= small {
            Focus::Empty
        } else {
            Focus::Body
        };
        Ok(body)
    }
}

/// The focus body's clipper overflowed (more faces than it holds).
fn too_many_faces() -> Error {
    Error::Degenerate("the focus body has more faces than the clipper holds".into())
}

/// B's vertex nearest the camera (smallest eye depth; ties within 10⁻¹² relative go to the
/// largest x + y, OGRE's top-right near corner of the frustum).
pub(super) fn nearest_vertex<const N: usize>(fl: &FrustumInLight<N>, n: usize) -> usize {
    let dmin = fl.depth[..n].iter().copied().fold(f64::INFINITY, f64::min);
    let tol = 1e-12 * dmin.abs().max(f64::MIN_POSITIVE);
    let mut best = 0;
    let mut key = f64::NEG_INFINITY;
    for i in 0..n {
        if fl.depth[i] <= dmin + tol {
            let k = fl.corners[i].x + fl.corners[i].y;
            if k > key {
                key = k;
                best = i;
            }
        }
    }
    best
}

/// The nearest and farthest eye depth −z of a body's vertices.
pub(super) fn depth_extent(pts: &[DVec3]) -> (f64, f64) {
    let (mut near, mut far) = (f64::INFINITY, f64::NEG_INFINITY);
    for p in pts {
        near = near.min(-p.z);
        far = far.max(-p.z);
    }
    (near, far)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::frame::{Aabb, FrameInput, FrameScheme};
    use crate::geom::polytope::{frustum_planes, polytope_vertices};
    use crate::maps::WarpRule;
    use glam::DMat4;

    #[test]
    fn frustum_planes_agree_with_the_body() {
        // The frustum's own planes keep every corner of the frustum body.
        let v = ViewFrustum::new(1.0, 10.0, 0.5).unwrap();
        for p in frustum_planes(&v, v.far()) {
            for c in v.corners() {
                assert!(p.truncate().dot(c) + p.w <= 1e-12 * 10.0);
            }
        }
    }

    /// The clipper's vertices against the triple-plane enumeration of `polytope_vertices` (an
    /// independent algorithm), for random boxes across, inside and around random frusta.
    #[test]
    fn clipped_body_matches_plane_triples() {
        let mut seed = 99u64;
        let mut rnd = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut nonempty = 0;
        for _ in 0..500 {
            let near = 0.1 + rnd();
            let view = ViewFrustum::with_aspect(
                near,
                near * (2.0 + 50.0 * rnd()),
                0.2 + rnd(),
                0.5 + rnd(),
            )
            .unwrap();
            let f = view.far();
            let lo = DVec3::new((rnd() - 0.7) * f, (rnd() - 0.7) * f, -rnd() * 1.2 * f);
            let hi = lo + DVec3::new(rnd(), rnd(), rnd()) * f;
            let cam = Camera::new(
                DMat4::IDENTITY,
                view.near(),
                view.far(),
                view.half_fov(),
                view.aspect(),
            )
            .unwrap();
            let boxes = [Aabb::new(lo, hi).unwrap()];
            let input = FrameInput::new(cam, DVec3::new(0.3, -1.0, 0.2), 1024, 1024)
                .receivers(Bound::Boxes(&boxes))
                .scheme(FrameScheme::Single(WarpRule::Uniform));
            let planes = receiver_planes(&cam, &input.receivers).unwrap();
            let ctx = Ctx {
                input: &input,
                view: &view,
                l: DVec3::NEG_Y,
                lw: DVec3::NEG_Y,
                planes,
            };
            let body = ctx.body(view.near(), view.far(), &[]).unwrap();
            let mut all = [DVec4::ZERO; 12];
            all[..6].copy_from_slice(&frustum_planes(&view, f));
            all[6..].copy_from_slice(&planes.p[..6]);
            let scale = ctx.scale();
            let mut want = [DVec3::ZERO; 64];
            let n = polytope_vertices(&all, scale, &mut want);
            if body.focus == Focus::Empty {
                // No solid: the enumeration finds no body with volume either.
                let (_, _, thick) = extents(&want[..n]);
                assert!(thick <= 1e-6 * scale, "{lo} {hi}");
                continue;
            }
            nonempty += 1;
            let got = &body.v[..body.n];
            for w in &want[..n] {
                assert!(
                    got.iter().any(|g| (*g - *w).length() <= 1e-7 * scale),
                    "missing {w}"
                );
            }
            for g in got {
                assert!(
                    want[..n].iter().any(|w| (*g - *w).length() <= 1e-7 * scale),
                    "extra {g}"
                );
            }
        }
        assert!(nonempty > 100, "{nonempty}");
    }
}
