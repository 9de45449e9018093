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
