//! Convex polytopes of eye space bounded by planes: a bound given by planes or by a world box,
//! the view frustum's planes, and the vertices of their intersection.

use crate::error::{fmt_num, Error, Result};
use crate::frustum::ViewFrustum;
use crate::numeric::sort_by_keys;
use glam::{DMat3, DMat4, DVec3, DVec4};

/// A convex region of eye space bounded by up to six planes `a x + b y + c z + d ≤ 0`, stored as
/// `(a, b, c, d)`: the light's volume or a scene box for [`crate::maps::tsm::tsm_general`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ConvexBound {
    planes: [DVec4; 6],
}

impl ConvexBound {
    /// From six eye-space planes `(a, b, c, d)`, inside where `a x + b y + c z + d ≤ 0`.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `planes` for a non-finite plane or a zero normal, with
    /// the plane and its index.
    pub fn from_planes(planes: [DVec4; 6]) -> Result<Self> {
        for (i, p) in planes.iter().enumerate() {
            if !p.is_finite() || p.truncate().length() <= 0.0 {
                return Err(Error::invalid(
                    "planes",
                    format!(
                        "must be finite (a, b, c, d) with a non-zero normal (a, b, c) (got {p} at \
                         index {i})"
                    ),
                ));
            }
        }
        Ok(Self { planes })
    }

    /// A world-space axis-aligned box seen through the camera's view matrix (world → eye).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `min`/`max` (not finite, or min > max on an axis) or
    /// `view_matrix` (not invertible).
    pub fn from_aabb(min: DVec3, max: DVec3, view_matrix: DMat4) -> Result<Self> {
        if !min.is_finite() || !max.is_finite() || min.cmpgt(max).any() {
            return Err(Error::invalid(
                "min",
                format!("must be finite and not above max (got min={min}, max={max})"),
            ));
        }
        let det = view_matrix.determinant();
        if !det.is_finite() || det.abs() < 1e-300 {
            return Err(Error::invalid(
                "view_matrix",
                format!(
                    "must be invertible: a finite world → eye matrix of non-zero determinant \
                     (got determinant {})",
                    fmt_num(det)
                ),
            ));
        }
        // A world plane π (π·(x, 1) ≤ 0) is V⁻ᵀ π in eye space.
        let it = view_matrix.inverse().transpose();
        let world = [
            DVec4::new(1.0, 0.0, 0.0, -max.x),
            DVec4::new(-1.0, 0.0, 0.0, min.x),
            DVec4::new(0.0, 1.0, 0.0, -max.y),
            DVec4::new(0.0, -1.0, 0.0, min.y),
            DVec4::new(0.0, 0.0, 1.0, -max.z),
            DVec4::new(0.0, 0.0, -1.0, min.z),
        ];
        Self::from_planes(world.map(|p| it * p))
    }

    /// The six planes `(a, b, c, d)`, inside where `a x + b y + c z + d ≤ 0`.
    #[must_use]
    pub fn planes(&self) -> &[DVec4; 6] {
        &self.planes
    }
}

/// The planes of the view frustum in the same convention (a x + b y + c z + d ≤ 0).
pub(crate) fn frustum_planes(view: &ViewFrustum, far: f64) -> [DVec4; 6] {
    let t = view.tan_half_fov();
    let ta = t * view.aspect();
    [
        DVec4::new(0.0, 0.0, 1.0, view.near()), // depth ≥ near
        DVec4::new(0.0, 0.0, -1.0, -far),       // depth ≤ far
        DVec4::new(1.0, 0.0, ta, 0.0),          // x ≤ depth · t · a
        DVec4::new(-1.0, 0.0, ta, 0.0),         // −x ≤ depth · t · a
        DVec4::new(0.0, 1.0, t, 0.0),           // y ≤ depth · t
        DVec4::new(0.0, -1.0, t, 0.0),          // −y ≤ depth · t
    ]
}

/// Vertices of the convex polyhedron `{p : πᵢ·(p, 1) ≤ 0}`: every triple of planes whose
/// intersection point satisfies all the constraints (relative tolerance 10⁻⁹ of `scale`),
/// deduplicated. Returns the count written into `out`.
pub(crate) fn polytope_vertices(planes: &[DVec4], scale: f64, out: &mut [DVec3; 64]) -> usize {
    let mut count = 0;
    let tol = 1e-9 * scale;
    let m = planes.len();
    for i in 0..m {
        for j in (i + 1)..m {
            for k in (j + 1)..m {
                let a = DMat3::from_cols(
                    planes[i].truncate(),
                    planes[j].truncate(),
                    planes[k].truncate(),
                )
                .transpose();
                let det = a.determinant();
                let norms = planes[i].truncate().length()
                    * planes[j].truncate().length()
                    * planes[k].truncate().length();
                if det.abs() <= 1e-12 * norms {
                    continue;
                }
                let p = a.inverse() * DVec3::new(-planes[i].w, -planes[j].w, -planes[k].w);
                if !p.is_finite() {
                    continue;
                }
                let inside = planes
                    .iter()
                    .all(|pl| pl.truncate().dot(p) + pl.w <= tol * pl.truncate().length());
                if inside && !out[..count].iter().any(|q| (*q - p).length() <= tol) && count < 64 {
                    out[count] = p;
                    count += 1;
                }
            }
        }
    }
    count
}

/// A convex polyhedron of eye space: its vertices, each stored once, and its faces (convex
/// polygons, each a cyclic list of vertex indices), at most `F` faces of at most `V` vertices and
/// `P` vertices in all, clipped exactly by half-spaces (Sutherland–Hodgman on every face, the cut
/// closed by a cap face), in fixed arrays: no heap allocation. Points within `tol` of a clipping
/// plane count as on it, so a body that only touches a plane keeps its face, edge or vertex there
/// (and no volume). An edge that crosses a plane is cut once, and both of its faces share the
/// point.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ConvexBody<const F: usize, const V: usize, const P: usize> {
    pts: [DVec3; P],
    npts: usize,
    faces: [[u8; V]; F],
    lens: [usize; F],
    count: usize,
}

impl<const F: usize, const V: usize, const P: usize> ConvexBody<F, V, P> {
    /// The hexahedron with corners `c` in [`ViewFrustum::corners`]' order (near face
    /// 0, 1, 2, 3, far face 4, 5, 6, 7, each counter-clockwise about the view direction), which is
    /// also the order of a box's corners given as (min/max x, min/max y) at two z.
    pub(crate) fn hexahedron(c: &[DVec3; 8]) -> Self {
        const { assert!(F >= 6 && V >= 4 && P >= 8 && P <= 256) };
        const QUADS: [[u8; 4]; 6] = [
            [0, 1, 2, 3],
            [4, 7, 6, 5],
            [0, 4, 5, 1],
            [1, 5, 6, 2],
            [2, 6, 7, 3],
            [3, 7, 4, 0],
        ];
        let mut b = Self {
            pts: [DVec3::ZERO; P],
            npts: 8,
            faces: [[0; V]; F],
            lens: [0; F],
            count: QUADS.len(),
        };
        b.pts[..8].copy_from_slice(c);
        for (f, q) in QUADS.iter().enumerate() {
            b.faces[f][..4].copy_from_slice(q);
            b.lens[f] = 4;
        }
        b
    }

    /// Keeps the part where `plane·(p, 1) ≤ tol |n|` (`plane = (n, d)`). Returns `false` when a
    /// fixed array would overflow (the body is then unusable) or the plane is not finite with a
    /// non-zero normal.
    pub(crate) fn clip(&mut self, plane: DVec4, tol: f64) -> bool {
        let n = plane.truncate();
        let len = n.length();
        if len.is_nan() || len <= 0.0 || !plane.is_finite() {
            return false;
        }
        let (n, d) = (n / len, plane.w / len);
        // Quick accept (every vertex inside) and reject (none), before any working array is
        // set up: most planes of a frame cut nothing.
        let mut all_in = true;
        let mut any_in = false;
        for p in &self.pts[..self.npts] {
            let s = n.dot(*p) + d;
            all_in &= s <= tol;
            any_in |= s <= tol;
        }
        if all_in {
            return true;
        }
        if !any_in {
            self.count = 0;
            self.npts = 0;
            return true;
        }
        // Each vertex's signed distance (the same expression as above).
        let mut dist = [0.0f64; P];
        for (s, p) in dist.iter_mut().zip(&self.pts[..self.npts]) {
            *s = n.dot(*p) + d;
        }
        // The kept vertices' new indices, in order; the cut edges' points follow them.
        let mut remap = [0u8; P];
        let mut kept = 0usize;
        for (r, s) in remap.iter_mut().zip(&dist[..self.npts]) {
            if *s <= tol {
                *r = kept as u8;
                kept += 1;
            }
        }
        let mut cut = [DVec3::ZERO; V];
        let mut cut_edge = [(0u8, 0u8); V];
        let mut ncut = 0usize;
        // The cap's vertices (new indices and positions), without repeats within `tol`.
        let mut cap = [0u8; V];
        let mut cap_at = [DVec3::ZERO; V];
        let mut ncap = 0usize;
        let tol2 = tol * tol;
        let mut push_cap = |i: usize, p: DVec3, ncap: &mut usize| -> bool {
            if cap_at[..*ncap]
                .iter()
                .any(|q| (*q - p).length_squared() <= tol2)
            {
                return true;
            }
            if *ncap == V {
                return false;
            }
            cap[*ncap] = i as u8;
            cap_at[*ncap] = p;
            *ncap += 1;
            true
        };
        // In place: face f's clipped polygon goes to slot w ≤ f (faces are only removed), the
        // cap to the end. Each index is stored into its slot as it is found (the face's row read
        // whole first, as slot w may be its own): a row built in a local array and then copied
        // whole is loaded as a vector right after its bytes were stored, which stalls the CPU's
        // store forwarding once per face.
        let mut w = 0usize;
        for f in 0..self.count {
            let fl = self.lens[f];
            let row = self.faces[f];
            let out = &mut self.faces[w];
            let mut m = 0usize;
            for i in 0..fl {
                let ia = usize::from(row[i]);
                let ib = usize::from(row[if i + 1 == fl { 0 } else { i + 1 }]);
                let (da, db) = (dist[ia], dist[ib]);
                if da <= tol {
                    if m == V {
                        return false;
                    }
                    let k = usize::from(remap[ia]);
                    out[m] = k as u8;
                    m += 1;
                    if da >= -tol && !push_cap(k, self.pts[ia], &mut ncap) {
                        return false;
                    }
                }
                if (da < -tol && db > tol) || (da > tol && db < -tol) {
                    // The edge's point, computed by the first face that meets the edge.
                    let key = (ia.min(ib) as u8, ia.max(ib) as u8);
                    let j = match cut_edge[..ncut].iter().position(|e| *e == key) {
                        Some(j) => j,
                        None => {
                            if ncut == V || kept + ncut == P {
                                return false;
                            }
                            let (a, b) = (self.pts[ia], self.pts[ib]);
                            cut[ncut] = a + (b - a) * (da / (da - db));
                            cut_edge[ncut] = key;
                            ncut += 1;
                            ncut - 1
                        }
                    };
                    if m == V {
                        return false;
                    }
                    out[m] = (kept + j) as u8;
                    m += 1;
                    if !push_cap(kept + j, cut[j], &mut ncap) {
                        return false;
                    }
                }
            }
            if m > 0 {
                self.lens[w] = m;
                w += 1;
            }
        }
        self.count = w;
        // The kept vertices move down (a new index is never above the old one), the cut points
        // follow.
        for i in 0..self.npts {
            if dist[i] <= tol {
                self.pts[usize::from(remap[i])] = self.pts[i];
            }
        }
        for (p, c) in self.pts[kept..kept + ncut].iter_mut().zip(&cut) {
            *p = *c;
        }
        self.npts = kept + ncut;
        if ncap >= 3 {
            // The cap is convex: order its points by angle about their centroid in the plane.
            let c = cap_at[..ncap].iter().fold(DVec3::ZERO, |a, p| a + *p) / ncap as f64;
            let u = n.any_orthonormal_vector();
            let v = n.cross(u);
            // A pseudo-angle, monotonic in the angle (no atan2): the position along the diamond
            // |x| + |y| = 1, in [0, 4).
            let mut ang = [0.0f64; V];
            for i in 0..ncap {
                let r = cap_at[i] - c;
                let (x, y) = (r.dot(u), r.dot(v));
                let s = x.abs() + y.abs();
                let t = if s > 0.0 { y / s } else { 0.0 };
                // t ∈ [−1, 1]: `t.rem_euclid(4.0)` without the `fmod` call (−0.0 stays −0.0).
                ang[i] = if x < 0.0 {
                    2.0 - t
                } else if t < 0.0 {
                    t + 4.0
                } else {
                    t
                };
            }
            sort_by_keys(&mut ang[..ncap], &mut cap[..ncap]);
            if self.count == F {
                return false;
            }
            self.faces[self.count] = cap;
            self.lens[self.count] = ncap;
            self.count += 1;
        }
        true
    }

    /// The body's distinct vertices (within `tol`) into `out`, in the order the faces first meet
    /// them; returns their count (0 for an empty body), or `None` when there are more than `out`
    /// holds.
    pub(crate) fn vertices(&self, tol: f64, out: &mut [DVec3]) -> Option<usize> {
        let mut k = 0;
        let tol2 = tol * tol;
        let mut seen = [false; P];
        for f in 0..self.count {
            for &i in &self.faces[f][..self.lens[f]] {
                let i = usize::from(i);
                if std::mem::replace(&mut seen[i], true) {
                    continue;
                }
                let p = self.pts[i];
                if out[..k].iter().any(|q| (*q - p).length_squared() <= tol2) {
                    continue;
                }
                if k == out.len() {
                    return None;
                }
                out[k] = p;
                k += 1;
            }
        }
        Some(k)
    }
}

/// How many dimensions a point set spans, with the sizes that decide it: `(length, width,
/// thickness)`, the distance of the point farthest from the first, of the point farthest from the
/// line through those two, and of the point farthest from the plane through those three. Each is
/// 0 when the previous is 0.
pub(crate) fn extents(points: &[DVec3]) -> (f64, f64, f64) {
    let Some(&p0) = points.first() else {
        return (0.0, 0.0, 0.0);
    };
    let far = |f: &dyn Fn(DVec3) -> f64| {
        points
            .iter()
            .map(|p| (f(*p), *p))
            .fold((0.0f64, p0), |a, b| if b.0 > a.0 { b } else { a })
    };
    let (len, p1) = far(&|p| (p - p0).length());
    if len <= 0.0 {
        return (0.0, 0.0, 0.0);
    }
    let e = (p1 - p0) / len;
    let (width, p2) = far(&|p| {
        let r = p - p0;
        (r - r.dot(e) * e).length()
    });
    if width <= 0.0 {
        return (len, 0.0, 0.0);
    }
    let nrm = e.cross(p2 - p0).normalize();
    let (thick, _) = far(&|p| (p - p0).dot(nrm).abs());
    (len, width, thick)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The unit cube's corners in [`ConvexBody::hexahedron`]'s order.
    fn cube() -> [DVec3; 8] {
        let c = |x: f64, y: f64, z: f64| DVec3::new(x, y, z);
        [
            c(0.0, 0.0, 0.0),
            c(1.0, 0.0, 0.0),
            c(1.0, 1.0, 0.0),
            c(0.0, 1.0, 0.0),
            c(0.0, 0.0, 1.0),
            c(1.0, 0.0, 1.0),
            c(1.0, 1.0, 1.0),
            c(0.0, 1.0, 1.0),
        ]
    }

    fn cube_planes() -> [DVec4; 6] {
        [
            DVec4::new(-1.0, 0.0, 0.0, 0.0),
            DVec4::new(1.0, 0.0, 0.0, -1.0),
            DVec4::new(0.0, -1.0, 0.0, 0.0),
            DVec4::new(0.0, 1.0, 0.0, -1.0),
            DVec4::new(0.0, 0.0, -1.0, 0.0),
            DVec4::new(0.0, 0.0, 1.0, -1.0),
        ]
    }

    /// Every point of `a` within `eps` of a point of `b`.
    fn covered(a: &[DVec3], b: &[DVec3], eps: f64) -> bool {
        a.iter()
            .all(|p| b.iter().any(|q| (*p - *q).length() <= eps))
    }

    #[test]
    fn a_plane_through_two_edges_cuts_the_cube_into_a_prism() {
        // x + y ≤ 1 keeps the prism over the triangle (0,0), (1,0), (0,1): 6 vertices, the two
        // corners (1,1,z) gone, no new point (the plane meets the cube at its vertical edges).
        let mut b = ConvexBody::<8, 8, 16>::hexahedron(&cube());
        assert!(b.clip(DVec4::new(1.0, 1.0, 0.0, -1.0), 1e-12));
        let mut v = [DVec3::ZERO; 16];
        let n = b.vertices(1e-12, &mut v).unwrap();
        assert_eq!(n, 6);
        let want = [
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
            DVec3::new(0.0, 0.0, 1.0),
            DVec3::new(1.0, 0.0, 1.0),
            DVec3::new(0.0, 1.0, 1.0),
        ];
        assert!(covered(&v[..n], &want, 1e-15) && covered(&want, &v[..n], 1e-15));
        // The cap closes the cut; the faces x = 1 and y = 1 keep the two points where the plane
        // touches them (an edge, no area): 7 faces in all.
        assert_eq!(b.count, 7);
    }

    #[test]
    fn a_corner_cut_adds_a_triangle() {
        // x + y + z ≤ 2.5 removes the corner (1,1,1) and adds the three points where its edges
        // meet the plane, (0.5, 1, 1), (1, 0.5, 1), (1, 1, 0.5): 10 vertices, 7 faces.
        let mut b = ConvexBody::<8, 8, 16>::hexahedron(&cube());
        assert!(b.clip(DVec4::new(1.0, 1.0, 1.0, -2.5), 1e-12));
        let mut v = [DVec3::ZERO; 16];
        let n = b.vertices(1e-12, &mut v).unwrap();
        assert_eq!((n, b.count, b.npts), (10, 7, 10));
        for p in [
            DVec3::new(0.5, 1.0, 1.0),
            DVec3::new(1.0, 0.5, 1.0),
            DVec3::new(1.0, 1.0, 0.5),
        ] {
            assert!(covered(&[p], &v[..n], 1e-15), "{p} missing");
        }
        assert!(!covered(&[DVec3::ONE], &v[..n], 1e-3));
    }

    #[test]
    fn a_plane_outside_empties_and_a_plane_beyond_keeps() {
        let mut b = ConvexBody::<8, 8, 16>::hexahedron(&cube());
        assert!(b.clip(DVec4::new(1.0, 0.0, 0.0, 5.0), 1e-12)); // x ≤ −5
        let mut v = [DVec3::ZERO; 16];
        assert_eq!(b.vertices(1e-12, &mut v), Some(0));
        let mut b = ConvexBody::<8, 8, 16>::hexahedron(&cube());
        assert!(b.clip(DVec4::new(1.0, 0.0, 0.0, -5.0), 1e-12)); // x ≤ 5
        assert_eq!(b.vertices(1e-12, &mut v), Some(8));
        // Touching at a face keeps the face (four vertices, no volume).
        assert!(b.clip(DVec4::new(1.0, 0.0, 0.0, 0.0), 1e-12)); // x ≤ 0
        let n = b.vertices(1e-12, &mut v).unwrap();
        assert_eq!(n, 4);
        assert!(v[..n].iter().all(|p| p.x == 0.0));
        // A zero normal is refused.
        assert!(!b.clip(DVec4::new(0.0, 0.0, 0.0, 1.0), 1e-12));
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 256, failure_persistence: None, ..ProptestConfig::default() })]

        /// Clipping the cube by random planes gives the vertices that `polytope_vertices` finds
        /// from every triple of the planes (an independent method), each within 10⁻⁹ of one of
        /// the other's (both empty when the planes leave nothing).
        #[test]
        fn clipped_cube_vertices_are_the_planes_triple_points(
            raw in proptest::collection::vec(
                (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0, 0.0f64..1.0), 1..6)
        ) {
            let mut planes = cube_planes().to_vec();
            let mut b = ConvexBody::<18, 18, 48>::hexahedron(&cube());
            for (x, y, z, t) in raw {
                let nrm = DVec3::new(x, y, z);
                prop_assume!(nrm.length() > 0.1);
                // Through a point of the cube's inner region, so that every plane cuts it.
                let p = DVec3::splat(0.25) + DVec3::splat(0.5 * t);
                let pl = nrm.extend(-nrm.dot(p));
                planes.push(pl);
                prop_assert!(b.clip(pl, 1e-12));
            }
            let mut got = [DVec3::ZERO; 48];
            let n = b.vertices(1e-12, &mut got).unwrap();
            let mut want = [DVec3::ZERO; 64];
            let m = polytope_vertices(&planes, 1.0, &mut want);
            prop_assert!(covered(&got[..n], &want[..m], 1e-9), "clip {:?} vs {:?}", &got[..n], &want[..m]);
            prop_assert!(covered(&want[..m], &got[..n], 1e-9), "triples {:?} vs {:?}", &want[..m], &got[..n]);
        }
    }
}
