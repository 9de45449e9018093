//! The numeric twin of Lloyd et al. 2005/2006: the coordinate maps their closed forms come
//! from, written as eye-space → light-clip [`DMat4`]s so that [`crate::measure::point_error`]
//! measures them.
//!
//! # The warping frustum (Lloyd 2006 §4.1, Eq 5, 6; Lloyd 2005 §3.1)
//!
//! Light space for the light overhead: the light travels −Y (eye space), x is the eye's X and the
//! warp axis is the view direction, with depth z = −p.z. The warping frustum has its centre of
//! projection a distance n′ in front of the near plane, its near plane at the view near plane and
//! its far plane at the view far plane; with z′ = n′ + z − n, f′ = n′ + f − n and
//! tan θ′ = (f / f′) tan θ (the frustum's half-width at z′ = f′ is the view frustum's f tan θ):
//!
//! ```text
//! s(x, z′) = x / (2 z′ tan θ′) + ½
//! t(z′)    = (f′ + n′) / (2 (f′ − n′)) − f′ n′ / (z′ (f′ − n′)) + ½
//! ```
//!
//! (t is the OpenGL frustum depth mapped to [0, 1]: 0 on the near plane, 1 on the far plane. The
//! printed Eq 5 lacks the ½ in s, prints tan θ′ = (f′/f) tan θ, and Eq 6 prints + before f′n′; see
//! docs/errata.md.) As a matrix: clip x = x / tan θ′, clip y = A (z − n) − n′ with
//! A = (f′ + n′)/(f′ − n′), w = z′. The unwarped map (n′ = ∞) is orthographic:
//! s = x / (2 f tan θ) + ½, t = (z − n)/(f − n).
//!
//! The same map, with x and z replaced by any two orthonormal directions ⊥ the light, is the
//! warp of one face partition seen from behind ([`behind_face_map`]).
//!
//! ```
//! use shadow_aliasing::measure::{frustum_max, twin::overhead_map};
//! use shadow_aliasing::analytic::overhead::storage_factor;
//! use shadow_aliasing::{NPrime, ViewFrustum};
//! let v = ViewFrustum::new(1.0, 100.0, 0.5)?;
//! let n = NPrime::finite(v.n_prime_lispsm())?;
//! let measured = frustum_max(&v, &overhead_map(&v, n)?)?.storage_factor;
//! let closed = storage_factor(&v, n)?;
//! assert!((measured - closed).abs() < 1e-10 * closed);
//! # Ok::<(), shadow_aliasing::Error>(())
//! ```

use crate::analytic::eta::{n_prime_at_least, n_prime_from_eta};
use crate::analytic::partition::{Splits, MAX_PARTITIONS};
use crate::error::{finite_result, fmt_num, Error, Result};
use crate::frustum::{NPrime, Resolutions, ViewFrustum};
use crate::measure::{frustum_max, point_error, FrustumError, ShadowMap};
use crate::numeric::sqrt_fn;
use glam::{DMat4, DVec3, DVec4};

/// The eye-space direction the light travels when it is overhead.
pub const LIGHT_OVERHEAD: DVec3 = DVec3::new(0.0, -1.0, 0.0);
/// The eye-space direction the light travels when it is behind the viewer.
pub const LIGHT_BEHIND: DVec3 = DVec3::new(0.0, 0.0, -1.0);

/// The warping-frustum matrix in a light-space frame: `a` the map's s axis, `b` the warp axis
/// (both unit, ⊥ the light), `light` the light direction. The warped region spans
/// u = b·p ∈ [u_near, u_far] and |a·p| ≤ `half_width_far` · u / u_far (a trapezoid whose sides
/// meet on the view axis); the warping frustum touches its far corners. The depth row is
/// `depth_scale` times the light coordinate (divided by w like the others).
#[allow(clippy::too_many_arguments)]
fn warp_matrix(
    a: DVec3,
    b: DVec3,
    light: DVec3,
    u_near: f64,
    u_far: f64,
    half_width_far: f64,
    n_prime: Option<f64>,
    depth_scale: f64,
) -> DMat4 {
    let row2 = DVec4::new(light.x, light.y, light.z, 0.0) * depth_scale;
    let (row0, row1, row3) = match n_prime {
        None => {
            let row0 = DVec4::new(a.x, a.y, a.z, 0.0) / half_width_far;
            let k = 2.0 / (u_far - u_near);
            let row1 = DVec4::new(b.x * k, b.y * k, b.z * k, -k * u_near - 1.0);
            (row0, row1, DVec4::new(0.0, 0.0, 0.0, 1.0))
        }
        Some(np) => {
            let fp = np + u_far - u_near;
            // tan θ′ = half_width_far / f′.
            let tan_p = half_width_far / fp;
            let row0 = DVec4::new(a.x, a.y, a.z, 0.0) / tan_p;
            let big_a = (fp + np) / (u_far - u_near);
            // clip y = A (u − u_near) − n′.
            let row1 = DVec4::new(b.x * big_a, b.y * big_a, b.z * big_a, -big_a * u_near - np);
            // w = z′ = n′ + u − u_near.
            let row3 = DVec4::new(b.x, b.y, b.z, np - u_near);
            (row0, row1, row3)
        }
    };
    DMat4::from_cols_array_2d(&[
        [row0.x, row1.x, row2.x, row3.x],
        [row0.y, row1.y, row2.y, row3.y],
        [row0.z, row1.z, row2.z, row3.z],
        [row0.w, row1.w, row2.w, row3.w],
    ])
}

/// Lloyd 2006's warped shadow map for the light overhead ([`LIGHT_OVERHEAD`]), fitted to
/// `view` (its near, far and half_fov; square image assumed by the closed forms), with warp
/// parameter n′ (`NPrime::UNWARPED` for the orthographic map). Eye space → light clip space.
///
/// For a square image (`aspect = 1`) its measured m_x, m_z are Lloyd 2006 Eq 7, 8 (to a relative
/// 10⁻¹²); M_x, M_z, S̄ at the frustum vertices are Eq 9, 10, 12. The depth row is the light
/// coordinate −y divided by tan θ (and by w): inside [−1, 1] over the view frustum and monotone
/// along each light ray.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `n_prime` when n′ < near (the warping frustum would not
/// contain the view frustum).
pub fn overhead_map(view: &ViewFrustum, n_prime: NPrime) -> Result<ShadowMap> {
    let (n, f) = (view.near(), view.far());
    let np = n_prime_at_least(n_prime, n)?;
    let t = view.tan_half_fov();
    let half = f * t * view.aspect();
    let m = warp_matrix(
        DVec3::X,
        DVec3::NEG_Z,
        LIGHT_OVERHEAD,
        n,
        f,
        half,
        np,
        1.0 / t,
    );
    ShadowMap::new(m, LIGHT_OVERHEAD)
}

/// The uniform (orthographic) map for the light behind the viewer ([`LIGHT_BEHIND`]), fitted to
/// the view frustum's far-plane rectangle (Lloyd 2006 Fig 11): s = x / (2 f tan θ · aspect) + ½,
/// t = y / (2 f tan θ) + ½, depth (z − n)/(f − n) mapped to [−1, 1].
///
/// Its measured S̄ over a square-image frustum is (f/n)², Lloyd 2006 Eq 20 with k = 1.
///
/// # Errors
/// Never for a valid `view`; the `Result` is [`ShadowMap::new`]'s.
pub fn behind_map(view: &ViewFrustum) -> Result<ShadowMap> {
    let (n, f) = (view.near(), view.far());
    let h = f * view.tan_half_fov();
    let w = h * view.aspect();
    let k = 2.0 / (f - n);
    let m = DMat4::from_cols_array_2d(&[
        [1.0 / w, 0.0, 0.0, 0.0],
        [0.0, 1.0 / h, 0.0, 0.0],
        [0.0, 0.0, -k, 0.0],
        [0.0, 0.0, -k * n - 1.0, 1.0],
    ]);
    ShadowMap::new(m, LIGHT_BEHIND)
}

/// A side face of the view frustum, as seen by a light behind the viewer.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SideFace {
    /// y = +z tan θ.
    Top,
    /// y = −z tan θ.
    Bottom,
    /// x = +z tan θ · aspect.
    Right,
    /// x = −z tan θ · aspect.
    Left,
}

impl SideFace {
    /// All four side faces.
    pub const ALL: [SideFace; 4] = [
        SideFace::Top,
        SideFace::Bottom,
        SideFace::Right,
        SideFace::Left,
    ];

    /// (a, b, slope_u, slope_x): the face's s axis, its outward warp axis, and the rates at which
    /// the face's distance from the view axis and its half-width grow with depth.
    fn frame(self, view: &ViewFrustum) -> (DVec3, DVec3, f64, f64) {
        let t = view.tan_half_fov();
        let ta = t * view.aspect();
        match self {
            SideFace::Top => (DVec3::X, DVec3::Y, t, ta),
            SideFace::Bottom => (DVec3::X, DVec3::NEG_Y, t, ta),
            SideFace::Right => (DVec3::Y, DVec3::X, ta, t),
            SideFace::Left => (DVec3::Y, DVec3::NEG_X, ta, t),
        }
    }

    /// The face's four corners over the depth range of `view`: near edge, then far edge.
    ///
    /// # Errors
    /// [`Error::Degenerate`] when a corner is not finite (f tan θ beyond about 1e308).
    pub fn corners(self, view: &ViewFrustum) -> Result<[DVec3; 4]> {
        let (a, b, su, sx) = self.frame(view);
        let mut out = [DVec3::ZERO; 4];
        for (i, z) in [view.near(), view.far()].into_iter().enumerate() {
            for (j, sign) in [-1.0, 1.0].into_iter().enumerate() {
                let (u, x) = (su * z, sign * sx * z);
                // Component-wise, so that no 0 · ∞ appears.
                let c = DVec3::new(b.x * u + a.x * x, b.y * u + a.y * x, -z);
                if !c.is_finite() {
                    return Err(Error::Degenerate(format!(
                        "a corner of the {self:?} face is not finite ({c})"
                    )));
                }
                out[2 * i + j] = c;
            }
        }
        Ok(out)
    }
}

/// The warped map of one side face of `view` for the light behind (Lloyd 2006 §5.1, §5.3):
/// the warping frustum of [`overhead_map`] laid in the plane ⊥ the light, its axis along the
/// face's outward direction b, over the face's distances from the view axis
/// u ∈ [n tan θ, f tan θ]. `n_prime` is in those same units (the distance from the warp's centre
/// of projection to the face's near edge, ≥ n tan θ); n′ = u_n + √(u_n u_f) is LiSPSM's.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `n_prime` when n′ < n tan θ.
pub fn behind_face_map(view: &ViewFrustum, face: SideFace, n_prime: NPrime) -> Result<ShadowMap> {
    let (a, b, su, sx) = face.frame(view);
    let (un, uf) = (view.near() * su, view.far() * su);
    let np = match n_prime.as_finite() {
        None => None,
        Some(v) if v >= un => Some(v),
        Some(v) => {
            return Err(Error::invalid(
                "n_prime",
                format!(
                    "must be at least the face's near distance n tan θ = {} (got {})",
                    fmt_num(un),
                    fmt_num(v)
                ),
            ))
        }
    };
    let m = warp_matrix(
        a,
        b,
        LIGHT_BEHIND,
        un,
        uf,
        view.far() * sx,
        np,
        1.0 / view.far(),
    );
    ShadowMap::new(m, LIGHT_BEHIND)
}

/// M_x, M_z, S̄ of a face map over its face (the four corners: along each light ray the face is
/// the frustum point nearest the eye, where the pixel beam is narrowest, and along the face the
/// maxima are at the ends as in the overhead case).
///
/// # Errors
/// As [`point_error`]; [`Error::Degenerate`] when a maximum or their product overflows.
pub fn face_max(view: &ViewFrustum, face: SideFace, map: &ShadowMap) -> Result<FrustumError> {
    crate::measure::max_over(view, map, face.corners(view)?.into_iter())
}

/// How each partition of a twin cascade chooses its warp.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TwinWarp {
    /// n′ = ∞ (ZP).
    Unwarped,
    /// n′ = n_i + √(n_i f_i) of each partition (ZP+W with LiSPSM).
    Lispsm,
    /// n′ = n′(η) of Lloyd 2006 Eq 11 over each partition's own depth range.
    Eta(f64),
}

impl TwinWarp {
    fn n_prime(self, near: f64, far: f64) -> Result<NPrime> {
        match self {
            TwinWarp::Unwarped => Ok(NPrime::UNWARPED),
            TwinWarp::Lispsm => NPrime::new(near + sqrt_fn(near, far)),
            TwinWarp::Eta(eta) => n_prime_from_eta(near, far, eta),
        }
    }
}

/// A cascade of twin maps, one per z-partition, each with its partition's sub-frustum.
/// Fixed-size storage (no heap allocation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwinCascade {
    views: [Option<ViewFrustum>; MAX_PARTITIONS],
    maps: [Option<ShadowMap>; MAX_PARTITIONS],
    k: usize,
}

impl TwinCascade {
    /// Number of partitions.
    #[must_use]
    pub fn k(&self) -> usize {
        self.k
    }

    /// Partition `i`'s sub-frustum and map (`None` for `i ≥ k`).
    #[must_use]
    pub fn get(&self, i: usize) -> Option<(ViewFrustum, ShadowMap)> {
        match (
            self.views.get(i).copied().flatten(),
            self.maps.get(i).copied().flatten(),
        ) {
            (Some(v), Some(m)) => Some((v, m)),
            _ => None,
        }
    }

    /// The measured storage factor summed over partitions: Σ_i M_x,i M_z,i, each measured at its
    /// sub-frustum's vertices by [`frustum_max`].
    ///
    /// # Errors
    /// As [`frustum_max`]; [`Error::Degenerate`] when the sum is not finite.
    pub fn measured_storage_factor(&self) -> Result<f64> {
        let mut sum = 0.0;
        for i in 0..self.k {
            if let Some((v, m)) = self.get(i) {
                sum += frustum_max(&v, &m)?.storage_factor;
            }
        }
        finite_result("storage factor", sum)
    }
}

fn cascade_with(
    view: &ViewFrustum,
    splits: &Splits,
    mut make: impl FnMut(&ViewFrustum) -> Result<ShadowMap>,
) -> Result<TwinCascade> {
    let mut c = TwinCascade {
        views: [None; MAX_PARTITIONS],
        maps: [None; MAX_PARTITIONS],
        k: splits.k(),
    };
    for i in 0..splits.k() {
        let (zn, zf) = splits.range(i);
        let v = view.with_depth_range(zn, zf)?;
        c.maps[i] = Some(make(&v)?);
        c.views[i] = Some(v);
    }
    Ok(c)
}

/// A z-partitioned cascade of [`overhead_map`]s over `splits` (Lloyd 2006 §5.2, ZP or ZP+W).
///
/// # Errors
/// As [`ViewFrustum::with_depth_range`] and [`overhead_map`].
pub fn overhead_cascade(
    view: &ViewFrustum,
    splits: &Splits,
    warp: TwinWarp,
) -> Result<TwinCascade> {
    cascade_with(view, splits, |v| {
        overhead_map(v, warp.n_prime(v.near(), v.far())?)
    })
}

/// A z-partitioned cascade of [`behind_map`]s over `splits` (Lloyd 2006 §5.3, ZP behind).
///
/// # Errors
/// As [`ViewFrustum::with_depth_range`].
pub fn behind_cascade(view: &ViewFrustum, splits: &Splits) -> Result<TwinCascade> {
    cascade_with(view, splits, behind_map)
}

/// The measured storage factor of FP+ZP+W with the light behind (Lloyd 2006 §5.3, Eq 21): each
/// of the four side faces split by `splits` and warped with `warp` (η and LiSPSM taken over the
/// face's own u range, n tan θ to f tan θ per partition), measured over the face with
/// [`face_max`], plus the near face: one uniform map of the near rectangle, whose measured S̄ is
/// added too.
///
/// # Errors
/// As [`behind_face_map`] and [`point_error`]; [`Error::Degenerate`] when the sum is not finite.
pub fn measured_fp_zp_w_behind(view: &ViewFrustum, splits: &Splits, warp: TwinWarp) -> Result<f64> {
    let mut sum = 0.0;
    for face in SideFace::ALL {
        for i in 0..splits.k() {
            let (zn, zf) = splits.range(i);
            let v = view.with_depth_range(zn, zf)?;
            let (_, _, su, _) = face.frame(&v);
            let np = warp.n_prime(zn * su, zf * su)?;
            let map = behind_face_map(&v, face, np)?;
            sum += face_max(&v, face, &map)?.storage_factor;
        }
    }
    // Near face: the rectangle |x| ≤ n tan θ aspect, |y| ≤ n tan θ, mapped uniformly.
    let n = view.near();
    let h = n * view.tan_half_fov();
    let w = h * view.aspect();
    let m = DMat4::from_cols_array_2d(&[
        [1.0 / w, 0.0, 0.0, 0.0],
        [0.0, 1.0 / h, 0.0, 0.0],
        [0.0, 0.0, -1.0 / view.far(), 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]);
    let near_map = ShadowMap::new(m, LIGHT_BEHIND)?;
    let (mut mx, mut mz) = (0.0f64, 0.0f64);
    for p in &view.corners()[..4] {
        let e = point_error(view, &near_map, *p, Resolutions::default())?;
        mx = mx.max(e.mx);
        mz = mz.max(e.mz);
    }
    finite_result("storage factor", sum + mx * mz)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The overhead map sends the view frustum's corners into [0, 1]², the far ones onto its
    /// edges, with t = 0 on the near plane and t = 1 on the far plane (Eq 6 with the sign
    /// corrected).
    #[test]
    fn overhead_map_fits_the_frustum() {
        let v = ViewFrustum::new(2.0, 50.0, 0.6).unwrap();
        for np in [
            NPrime::finite(2.0).unwrap(),
            NPrime::finite(12.0).unwrap(),
            NPrime::UNWARPED,
        ] {
            let m = overhead_map(&v, np).unwrap();
            for (i, c) in v.corners().into_iter().enumerate() {
                let (s, t, ..) = crate::measure::st_gradients(&m.matrix, c).unwrap();
                assert!((-1e-12..=1.0 + 1e-12).contains(&s), "s={s}");
                if i >= 4 {
                    // The warping frustum touches the view frustum's far edges.
                    assert!(s.abs() < 1e-12 || (s - 1.0).abs() < 1e-12, "s={s}");
                }
                let want_t = if i < 4 { 0.0 } else { 1.0 };
                assert!((t - want_t).abs() < 1e-12, "t={t}");
            }
        }
        for face in SideFace::ALL {
            let fm = behind_face_map(
                &v,
                face,
                NPrime::finite(v.near() * 0.6f64.tan() * 3.0).unwrap(),
            )
            .unwrap();
            for (i, c) in face.corners(&v).unwrap().into_iter().enumerate() {
                let (s, t, ..) = crate::measure::st_gradients(&fm.matrix, c).unwrap();
                assert!((-1e-12..=1.0 + 1e-12).contains(&s), "{face:?} s={s}");
                let want_t = if i < 2 { 0.0 } else { 1.0 };
                assert!((t - want_t).abs() < 1e-12, "{face:?} t={t}");
                // Deeper along the same light ray (−Z): the same texel.
                let (s2, t2, ..) =
                    crate::measure::st_gradients(&fm.matrix, c - DVec3::Z * 3.0).unwrap();
                assert!((s2 - s).abs() < 1e-12 && (t2 - t).abs() < 1e-12);
            }
        }
        let b = behind_map(&v).unwrap();
        let (s, t, ..) = crate::measure::st_gradients(&b.matrix, v.corners()[6]).unwrap();
        assert!((s - 1.0).abs() < 1e-12 && (t - 1.0).abs() < 1e-12);
    }
}
