//! The casters that can shadow B: each caster box (or the casters' polytope) clipped by the prism
//! of B's light-space footprint, and its point nearest the light.

use super::input::{Aabb, Bound};
use super::{Ctx, MAX_BODY_VERTICES};
use crate::error::{fmt_num, Error, Result};
use crate::geom::polytope::ConvexBody;
use crate::maps::fit::FrustumInLight;
use crate::numeric::fmax;
use glam::{DVec2, DVec3, DVec4};

/// A caster box cut by the prism of B's footprint (at most 20 edges): 26 faces of at most 24,
/// at most 48 vertices.
type CasterClip = ConvexBody<28, 28, 64>;
/// A caster polytope: a box, 12 planes and the prism.
type PolytopeClip = ConvexBody<40, 40, 96>;

impl Ctx<'_, '_> {
    /// The point that can shadow B nearest the light in the warp's depth (largest (y − y₀)/w),
    /// over every caster; `None` when there is none or casters are not needed. `prism` holds
    /// the prism of `fl`'s footprint once built (here, where a caster needs it, or by the caller
    /// before), so that the caller can use it again.
    pub(super) fn caster_extreme<const N: usize>(
        &self,
        fl: &FrustumInLight<N>,
        body_len: usize,
        w_of: impl Fn(DVec3) -> f64,
        y0: f64,
        prism: &mut Option<Prism>,
    ) -> Result<Option<DVec3>> {
        if self.input.depth_clamp {
            return Ok(None);
        }
        let boxes: &[Aabb] = match self.input.casters {
            Bound::Unbounded => return Ok(None),
            Bound::Boxes(b) => b,
            Bound::Polytope(_) => &[],
        };
        let tol = 1e-10 * self.scale();
        let depth_of = |p: DVec3| (fl.ls.y.dot(p) - y0) / w_of(p);
        // Only a point nearer the light than every point of B extends the range.
        let top = (0..body_len)
            .map(|i| depth_of(fl.corners[i]))
            .fold(f64::NEG_INFINITY, f64::max);
        let mut best: Option<(f64, DVec3)> = None;
        let mut consider = |v: &[DVec3]| {
            for p in v {
                let d = depth_of(*p);
                if best.is_none_or(|(b, _)| d > b) {
                    best = Some((d, *p));
                }
            }
        };
        let w2e = self.input.camera.world_to_eye;
        for bx in boxes {
            let c = bx.corners().map(|p| w2e.transform_point3(p));
            // The depth is linear-fractional: its maximum over the box (and over any part of it)
            // is at most its maximum over the corners. A box no nearer the light than B is skipped.
            // (Only where w > 0 at every corner, hence over the whole box.)
            let w_pos = |p: &DVec3| w_of(*p) > 0.0;
            if c.iter().all(|p| w_pos(p) && depth_of(*p) <= top) {
                continue;
            }
            let prism = prism.get_or_insert_with(|| Prism::new(fl, body_len));
            if c.iter().all(|p| prism.contains(*p, tol)) {
                consider(&c);
                continue;
            }
            let mut cb = CasterClip::hexahedron(&c);
            if !prism.clip(&mut cb, tol) {
                return Err(Error::Degenerate(
                    "a caster's clipped body has more faces than the clipper holds".into(),
                ));
            }
            let mut v = [DVec3::ZERO; 64];
            let n = cb.vertices(tol, &mut v).ok_or_else(|| {
                Error::Degenerate("a caster's clipped body has too many vertices".into())
            })?;
            consider(&v[..n]);
        }
        if let Bound::Polytope(world) = self.input.casters {
            // Start from the prism capped far beyond the body toward the light, then cut by the
            // casters' planes: a result that reaches the cap is unbounded toward the light.
            let reach = 1e6 * self.scale();
            let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
            for q in &fl.q {
                lo = lo.min(*q);
                hi = hi.max(*q);
            }
            let ls = fl.ls;
            let to_eye = |x: f64, y: f64, z: f64| ls.x * x + ls.y * y + ls.z * z;
            let (ya, yb) = (lo.y - 1.0, hi.y + reach);
            let c = [
                to_eye(lo.x, ya, lo.z),
                to_eye(hi.x, ya, lo.z),
                to_eye(hi.x, yb, lo.z),
                to_eye(lo.x, yb, lo.z),
                to_eye(lo.x, ya, hi.z),
                to_eye(hi.x, ya, hi.z),
                to_eye(hi.x, yb, hi.z),
                to_eye(lo.x, yb, hi.z),
            ];
            let mut cb = PolytopeClip::hexahedron(&c);
            let it = self.input.camera.eye_to_world.transpose();
            let mut ok = true;
            for p in world {
                ok &= cb.clip(it * *p, tol);
            }
            ok &= prism
                .get_or_insert_with(|| Prism::new(fl, body_len))
                .clip(&mut cb, tol);
            if !ok {
                return Err(Error::Degenerate(
                    "the casters' clipped body has more faces than the clipper holds".into(),
                ));
            }
            let mut v = [DVec3::ZERO; 64];
            let n = cb.vertices(tol, &mut v).unwrap_or(0);
            if v[..n].iter().any(|p| ls.y.dot(*p) >= hi.y + 0.5 * reach) {
                return Err(Error::invalid(
                    "casters",
                    "the polytope is unbounded toward the light",
                ));
            }
            consider(&v[..n]);
        }
        Ok(best.and_then(|(d, p)| (d > top).then_some(p)))
    }
}

/// The prism of B's light-space footprint: the side planes through the edges of the convex hull
/// of B's vertices' (x, z), parallel to the light (also the side of the casters' culling volume,
/// `super::culling`).
pub(super) struct Prism {
    planes: [DVec4; 2 * MAX_BODY_VERTICES],
    n: usize,
}

impl Prism {
    pub(super) fn new<const N: usize>(fl: &FrustumInLight<N>, n: usize) -> Self {
        let mut pts = [DVec2::ZERO; MAX_BODY_VERTICES];
        for (p, q) in pts.iter_mut().zip(&fl.q).take(n) {
            *p = DVec2::new(q.x, q.z);
        }
        let mut hull = [DVec2::ZERO; 2 * MAX_BODY_VERTICES];
        let h = crate::geom::hull::convex_hull(&mut pts[..n], &mut hull);
        // Vertices of B on one light ray (a vertical edge under a sun straight down) project to
        // points within rounding of each other, and the hull can keep both: a plane on such an
        // edge (10⁻¹³ long) has an arbitrary direction and cuts the casters away. Hull vertices
        // within 10⁻⁹ of the footprint's size of the previous one are dropped (the prism moves
        // by no more than that).
        let size = hull[..h]
            .iter()
            .fold(0.0f64, |m, v| fmax(m, fmax(v.x.abs(), v.y.abs())));
        let eps = 1e-9 * size;
        let mut k = 0;
        for i in 0..h {
            if k == 0 || (hull[i] - hull[k - 1]).length() > eps {
                hull[k] = hull[i];
                k += 1;
            }
        }
        while k > 1 && (hull[k - 1] - hull[0]).length() <= eps {
            k -= 1;
        }
        let h = k;
        let mut planes = [DVec4::ZERO; 2 * MAX_BODY_VERTICES];
        let ls = fl.ls;
        for i in 0..h {
            let (a, b) = (hull[i], hull[(i + 1) % h]);
            let e = b - a;
            // Counter-clockwise hull: the outside is to the right, normal (e.y, −e.x).
            let n2 = DVec2::new(e.y, -e.x);
            let n3 = ls.x * n2.x + ls.z * n2.y;
            planes[i] = n3.extend(-n2.dot(a));
        }
        Self { planes, n: h }
    }

    /// The side planes `(n, d)` (normals as long as their hull edge), outside where
    /// `n·p + d > 0`.
    pub(super) fn planes(&self) -> &[DVec4] {
        &self.planes[..self.n]
    }

    fn clip<const F: usize, const V: usize, const P: usize>(
        &self,
        cb: &mut ConvexBody<F, V, P>,
        tol: f64,
    ) -> bool {
        self.planes[..self.n].iter().all(|p| cb.clip(*p, tol))
    }

    /// Whether `p` lies inside the prism (within `tol` of its planes, which have unit normals
    /// up to the hull edge's length).
    fn contains(&self, p: DVec3, tol: f64) -> bool {
        self.planes[..self.n]
            .iter()
            .all(|pl| pl.truncate().dot(p) + pl.w <= tol * pl.truncate().length())
    }
}

/// The casters' point `p` that extends the depth range is so far from the focus body `pts` that
/// the map cannot be fitted with it, while it can without: the error names the casters, the
/// distances and the remedies.
#[cold]
#[inline(never)]
pub(super) fn casters_too_far(pts: &[DVec3], p: DVec3) -> Error {
    let centre = pts.iter().fold(DVec3::ZERO, |a, q| a + *q) / pts.len().max(1) as f64;
    let size = pts
        .iter()
        .fold(0.0f64, |m, q| m.max((*q - centre).length()));
    Error::invalid(
        "casters",
        format!(
            "reach {} from the focus body (of radius {}), beyond what the map's fit resolves in \
             f64 (the depth range they add is {:.0e} times the body's size): bound the casters \
             to the region that can shadow the visible receivers, or let the device clamp depth \
             (depth_clamp, `--depth-clamp`) so that casters nearer the light are not needed",
            fmt_num((p - centre).length()),
            fmt_num(size),
            (p - centre).length() / size.max(f64::MIN_POSITIVE)
        ),
    )
}
