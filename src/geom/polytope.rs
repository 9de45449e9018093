//! Convex polytopes of eye space bounded by planes: a bound given by planes or by a world box,
//! the view frustum's planes, and the vertices of their intersection.

use crate::error::{Error, Result};
use crate::frustum::ViewFrustum;
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
    /// [`Error::InvalidArgument`] naming `planes` for a non-finite plane or a zero normal.
    pub fn from_planes(planes: [DVec4; 6]) -> Result<Self> {
        for p in &planes {
            if !p.is_finite() || p.truncate().length() <= 0.0 {
                return Err(Error::invalid(
                    "planes",
                    format!("must be finite with a non-zero normal (got {p})"),
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
            return Err(Error::invalid("view_matrix", "must be invertible"));
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

/// A convex polyhedron of eye space as its faces (convex polygons, each vertex list cyclic), at
/// most `F` faces of at most `V` vertices, clipped exactly by half-spaces (Sutherland–Hodgman on
/// every face, the cut closed by a cap face), in fixed arrays: no heap allocation. Points within
/// `tol` of a clipping plane count as on it, so a body that only touches a plane keeps its face,
/// edge or vertex there (and no volume).
#[derive(Debug, Clone, Copy)]
pub(crate) struct ConvexBody<const F: usize, const V: usize> {
    faces: [[DVec3; V]; F],
    lens: [usize; F],
    count: usize,
}

impl<const F: usize, const V: usize> ConvexBody<F, V> {
    /// The hexahedron with corners `c` in [`ViewFrustum::corners`]' order (near face
    /// 0, 1, 2, 3, far face 4, 5, 6, 7, each counter-clockwise about the view direction), which is
    /// also the order of a box's corners given as (min/max x, min/max y) at two z.
    pub(crate) fn hexahedron(c: &[DVec3; 8]) -> Self {
        const { assert!(F >= 6 && V >= 4) };
        let mut b = Self {
            faces: [[DVec3::ZERO; V]; F],
            lens: [0; F],
            count: 0,
        };
        let quads = [
            [0, 1, 2, 3],
            [4, 7, 6, 5],
            [0, 4, 5, 1],
            [1, 5, 6, 2],
            [2, 6, 7, 3],
            [3, 7, 4, 0],
        ];
        for q in quads {
            b.faces[b.count][..4].copy_from_slice(&q.map(|i| c[i]));
            b.lens[b.count] = 4;
            b.count += 1;
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
        let dist = |p: DVec3| n.dot(p) + d;
        // Quick accept (every vertex inside) and reject (none).
        let mut all_in = true;
        let mut any_in = false;
        for f in 0..self.count {
            for p in &self.faces[f][..self.lens[f]] {
                let s = dist(*p);
                all_in &= s <= tol;
                any_in |= s <= tol;
            }
        }
        if all_in {
            return true;
        }
        if !any_in {
            self.count = 0;
            return true;
        }
        // In place: face f's clipped polygon goes to slot w ≤ f (faces are only removed), the
        // cap to the end.
        let mut w = 0usize;
        let mut cap = [DVec3::ZERO; V];
        let mut ncap = 0usize;
        let tol2 = tol * tol;
        let mut push_cap = |p: DVec3, ncap: &mut usize| -> bool {
            if cap[..*ncap]
                .iter()
                .any(|q| (*q - p).length_squared() <= tol2)
            {
                return true;
            }
            if *ncap == V {
                return false;
            }
            cap[*ncap] = p;
            *ncap += 1;
            true
        };
        let mut poly = [DVec3::ZERO; V];
        for f in 0..self.count {
            let fl = self.lens[f];
            let mut m = 0usize;
            for i in 0..fl {
                let a = self.faces[f][i];
                let b = self.faces[f][if i + 1 == fl { 0 } else { i + 1 }];
                let (da, db) = (dist(a), dist(b));
                if da <= tol {
                    if m == V {
                        return false;
                    }
                    poly[m] = a;
                    m += 1;
                    if da >= -tol && !push_cap(a, &mut ncap) {
                        return false;
                    }
                }
                if (da < -tol && db > tol) || (da > tol && db < -tol) {
                    let t = da / (da - db);
                    let p = a + (b - a) * t;
                    if m == V {
                        return false;
                    }
                    poly[m] = p;
                    m += 1;
                    if !push_cap(p, &mut ncap) {
                        return false;
                    }
                }
            }
            if m > 0 {
                self.faces[w][..m].copy_from_slice(&poly[..m]);
                self.lens[w] = m;
                w += 1;
            }
        }
        self.count = w;
        if ncap >= 3 {
            // The cap is convex: order its points by angle about their centroid in the plane.
            let c = cap[..ncap].iter().fold(DVec3::ZERO, |a, p| a + *p) / ncap as f64;
            let u = n.any_orthonormal_vector();
            let v = n.cross(u);
            // A pseudo-angle, monotonic in the angle (no atan2): the position along the diamond
            // |x| + |y| = 1, in [0, 4).
            let mut ang = [0.0f64; V];
            for i in 0..ncap {
                let r = cap[i] - c;
                let (x, y) = (r.dot(u), r.dot(v));
                let s = x.abs() + y.abs();
                let t = if s > 0.0 { y / s } else { 0.0 };
                ang[i] = if x >= 0.0 { t.rem_euclid(4.0) } else { 2.0 - t };
            }
            // Insertion sort by angle (a few dozen points at most).
            for i in 1..ncap {
                let mut j = i;
                while j > 0 && ang[j - 1] > ang[j] {
                    ang.swap(j - 1, j);
                    cap.swap(j - 1, j);
                    j -= 1;
                }
            }
            if self.count == F {
                return false;
            }
            self.faces[self.count][..ncap].copy_from_slice(&cap[..ncap]);
            self.lens[self.count] = ncap;
            self.count += 1;
        }
        true
    }

    /// The body's distinct vertices (within `tol`) into `out`; returns their count (0 for an
    /// empty body), or `None` when there are more than `out` holds.
    pub(crate) fn vertices(&self, tol: f64, out: &mut [DVec3]) -> Option<usize> {
        let mut k = 0;
        let tol2 = tol * tol;
        for f in 0..self.count {
            for p in &self.faces[f][..self.lens[f]] {
                if out[..k].iter().any(|q| (*q - *p).length_squared() <= tol2) {
                    continue;
                }
                if k == out.len() {
                    return None;
                }
                out[k] = *p;
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
