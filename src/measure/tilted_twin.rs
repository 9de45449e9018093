//! The numeric twin of the tilted-light closed forms (Barroso & Celes 2007 §3.1, Zhang et al.
//! 2009 §2.4): the warping frustum of a light tilted in the view's vertical plane, built as a
//! matrix, and the two error measurements those papers use that [`point_error`](crate::measure::point_error) does not give.
//!
//! # The geometry (Barroso Fig 6, Zhang Fig 2)
//!
//! The light lies in the view's vertical (YZ) plane at the angle γ ∈ [0, π/2] from the view
//! axis (Barroso's γ, Zhang's θ). Light space (LiSPSM, Lloyd 2006 §4):
//!
//! - `y_l` = ℓ, the unit vector towards the light;
//! - `z_l` = the view direction −Z projected perpendicular to ℓ and normalised (at γ = 0, where
//!   the projection vanishes, its limit γ → 0⁺, a vertical vector: the map is continuous in γ);
//! - `x_l` = X.
//!
//! The warping frustum looks along `z_l`. Its centre of projection lies n′ before the view
//! frustum's nearest extent `z_min` along `z_l`, so a point's warp depth is
//! `z′ = z_l − z_min + n′` (Barroso's z′, Zhang's z_w), its far plane is `f′ = n′ + μ` with μ the
//! frustum's extent along `z_l`, and its half-angle `tan φ_w = max |x_l| / z′` over the eight
//! corners (fitted, so every corner maps inside the map). The shadow-map coordinates are
//! (Zhang Eq 12, Barroso Eq 7):
//!
//! - `s = ½ x_l / (z′ tan φ_w) + ½` (Zhang's t),
//! - `t = ½ + ½ (f′ + n′)/(f′ − n′) − f′ n′ / (z′ (f′ − n′))`, the OpenGL depth of the warping
//!   frustum (Zhang's s = (λ + μ)/μ (1 − λ/z_w), the same function).
//!
//! n′ = ∞ ([`NPrime::UNWARPED`]) is the orthographic map fitted to the same extents.
//!
//! # Which side the light is on
//!
//! [`TiltSide::InFront`] is Zhang's configuration: the light above and in front of the viewer,
//! travelling along `(0, −sin γ, cos γ)` in eye space, so the near-top edge of the frustum is
//! nearest the centre of projection. [`TiltSide::Behind`] is its mirror image `y → −y` (light
//! above and behind, travelling along `(0, −sin γ, −cos γ)`). Both give the same errors on the view
//! axis; off the axis, the error at `(x, y, z)` of one is the error at `(x, −y, z)` of the other.
//!
//! ```
//! use shadow_aliasing::measure::{point_error, tilted_twin::{tilted_warp, TiltSide}};
//! use shadow_aliasing::{LightAngle, NPrime, Resolutions, ViewFrustum};
//! use glam::DVec3;
//! let view = ViewFrustum::new(1.0, 100.0, 30f64.to_radians())?;
//! let warp = tilted_warp(&view, LightAngle::new(1.0)?, TiltSide::InFront, NPrime::finite(5.0)?)?;
//! let e = point_error(&view, &warp.shadow, DVec3::new(0.0, 0.0, -10.0), Resolutions::default())?;
//! assert!(e.mz > 0.0 && e.mx > 0.0);
//! # Ok::<(), shadow_aliasing::Error>(())
//! ```

use crate::error::{finite, finite_result, Error, Result};
use crate::frustum::{LightAngle, NPrime, Resolutions, ViewFrustum};
use crate::measure::{st_gradients, ShadowMap};
use glam::{DMat4, DVec3, DVec4};

/// Which side of the viewer a tilted light is on (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TiltSide {
    /// Above and in front of the viewer (Zhang et al.'s configuration, Fig 2).
    InFront,
    /// Above and behind the viewer: the mirror image `y → −y` of [`TiltSide::InFront`].
    Behind,
}

/// A tilted light's warping frustum as a shadow matrix, with the light-space quantities it was
/// built from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TiltedWarp {
    /// The shadow matrix (eye space → light clip space, OpenGL x, y; clip depth in `[−1, 1]`)
    /// and the direction the light travels.
    pub shadow: ShadowMap,
    /// The warp parameter n′ used.
    pub n_prime: NPrime,
    /// Unit vector towards the light, `y_l`.
    pub toward_light: DVec3,
    /// Unit warp axis `z_l` (the view direction projected perpendicular to the light).
    pub warp_axis: DVec3,
    /// The view frustum's nearest extent along `z_l` (eye-space units).
    pub z_min: f64,
    /// μ = f′ − n′, the view frustum's extent along `z_l` (Barroso Eq 11, Zhang's μ).
    pub depth_range: f64,
    /// tan φ_w, the warping frustum's half-angle in x; for the unwarped map, the half-width
    /// of the orthographic map in x instead.
    pub half_extent_x: f64,
}

/// The unit vector towards a light tilted by γ in the view's vertical plane, and the warp axis
/// `z_l` (module docs).
#[must_use]
pub fn tilted_light_frame(light_angle: LightAngle, side: TiltSide) -> (DVec3, DVec3) {
    let (s, c) = light_angle.radians().sin_cos();
    match side {
        TiltSide::InFront => (DVec3::new(0.0, s, -c), DVec3::new(0.0, -c, -s)),
        TiltSide::Behind => (DVec3::new(0.0, s, c), DVec3::new(0.0, c, -s)),
    }
}

/// Builds the warping frustum of a light tilted by γ (module docs) for the view frustum `view`
/// and warp parameter n′ (any n′ > 0, or [`NPrime::UNWARPED`]).
///
/// # Errors
/// [`Error::Degenerate`] if the fitted matrix is not finite (n′ so large that f′ overflows).
pub fn tilted_warp(
    view: &ViewFrustum,
    light_angle: LightAngle,
    side: TiltSide,
    n_prime: NPrime,
) -> Result<TiltedWarp> {
    let (ell, zl) = tilted_light_frame(light_angle, side);
    let corners = view.corners();
    let (mut zmin, mut zmax) = (f64::INFINITY, f64::NEG_INFINITY);
    let (mut ymin, mut ymax) = (f64::INFINITY, f64::NEG_INFINITY);
    for c in corners {
        let z = c.dot(zl);
        let y = c.dot(ell);
        zmin = zmin.min(z);
        zmax = zmax.max(z);
        ymin = ymin.min(y);
        ymax = ymax.max(y);
    }
    let mu = zmax - zmin;
    let yc = 0.5 * (ymin + ymax);
    let yh = 0.5 * (ymax - ymin);
    let rows: [DVec4; 4];
    let half_x;
    match n_prime.as_finite() {
        Some(np) => {
            let mut tan_w = 0.0f64;
            for c in corners {
                tan_w = tan_w.max(c.x.abs() / (c.dot(zl) - zmin + np));
            }
            half_x = tan_w;
            let fp = np + mu;
            let a = (fp + np) / mu;
            let b = -2.0 * fp * np / mu;
            let w = DVec4::new(zl.x, zl.y, zl.z, np - zmin);
            rows = [
                DVec4::new(1.0 / tan_w, 0.0, 0.0, 0.0),
                a * w + DVec4::new(0.0, 0.0, 0.0, b),
                DVec4::new(
                    -np * ell.x / yh,
                    -np * ell.y / yh,
                    -np * ell.z / yh,
                    np * yc / yh,
                ),
                w,
            ];
        }
        None => {
            let mut hx = 0.0f64;
            for c in corners {
                hx = hx.max(c.x.abs());
            }
            half_x = hx;
            rows = [
                DVec4::new(1.0 / hx, 0.0, 0.0, 0.0),
                DVec4::new(
                    2.0 * zl.x / mu,
                    2.0 * zl.y / mu,
                    2.0 * zl.z / mu,
                    -2.0 * zmin / mu - 1.0,
                ),
                DVec4::new(-ell.x / yh, -ell.y / yh, -ell.z / yh, yc / yh),
                DVec4::new(0.0, 0.0, 0.0, 1.0),
            ];
        }
    }
    let matrix = DMat4::from_cols(rows[0], rows[1], rows[2], rows[3]).transpose();
    if !matrix.is_finite() {
        return Err(Error::Degenerate(format!(
            "the tilted warp for n_prime={} is not finite",
            n_prime.value()
        )));
    }
    Ok(TiltedWarp {
        shadow: ShadowMap::new(matrix, -ell)?,
        n_prime,
        toward_light: ell,
        warp_axis: zl,
        z_min: zmin,
        depth_range: mu,
        half_extent_x: half_x,
    })
}

/// Barroso & Celes's m_z measured as they define it (Eq 6): the width of a texel measured
/// **along the view axis**, `w_tz = 1 / (res_t |∂t/∂z|)` with `∂t/∂z` the exact directional
/// derivative of the map's t along the view direction −Z, over the pixel beam width
/// `w_i = 2 z tan θ / res_i` (z = −p.z the depth).
///
/// For a map whose t depends only on the warp depth z′ (the papers' warps) and a light at γ from
/// the view axis, `∂t/∂z = (dt/dz′) sin γ`, so this is the crate's perpendicular m_z
/// ([`crate::measure::PointError::mz`], the distance between t-isolines in the plane ⊥ light)
/// divided by sin γ. It is infinite for γ = 0 (t does not change along the view axis).
///
/// # Errors
/// As [`crate::measure::point_error`] for the point; [`Error::Degenerate`] when t does not vary
/// along the view axis at `p` (light parallel to the view).
pub fn mz_along_view_axis(
    view: &ViewFrustum,
    shadow: &ShadowMap,
    p: DVec3,
    res: Resolutions,
) -> Result<f64> {
    let z = depth_of(p)?;
    let (_, _, _, gt, _) = st_gradients(&shadow.matrix, p)?;
    let dtdz = -gt.z; // derivative along the view direction (0, 0, −1)
    if dtdz == 0.0 || !dtdz.is_finite() {
        return Err(Error::Degenerate(format!(
            "t does not vary along the view axis at {p}: the light is parallel to the view"
        )));
    }
    let w_tz = 1.0 / (res.t() * dtdz.abs());
    let w_i = 2.0 * z * view.tan_half_fov() / res.image();
    finite_result("m_z along the view axis", w_tz / w_i)
}

/// Zhang et al.'s aliasing functions in full (their Eq 1, 2), from total differentials along a
/// surface direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AliasingFunctions {
    /// E_q = |dq/dt_Z|: screen q (in `[−1, 1]`) per shadow-map coordinate across the light
    /// (Zhang's t, the crate's s, in `[0, 1]`).
    pub e_q: f64,
    /// E_p = |dp/ds_Z|: screen p (in `[−1, 1]`) per shadow-map coordinate along the warp
    /// (Zhang's s, the crate's t, in `[0, 1]`).
    pub e_p: f64,
}

/// Zhang et al.'s full aliasing functions E_q, E_p (Eq 1, 2, 10) at the eye-space point `p` for a
/// small surface element through `p` with tangent `dir` (any non-zero eye-space vector; Zhang's
/// shaft with slopes k_x, k_y is `dir = (k_x, k_y, −1)` in the crate's right-handed eye space):
///
/// `E_q = |∇q · dir| / |∇s · dir|`, `E_p = |∇p · dir| / |∇t · dir|`,
///
/// with the screen coordinates `q = x / (z · aspect · tan θ)`, `p = y / (z tan θ)` (z = −p.z) and
/// the map's s, t from `shadow`, all gradients exact. This includes projection aliasing; Zhang's
/// perspective part is `2 m_x`, `2 m_z` of [`crate::measure::point_error`] (unit resolutions).
///
/// # Errors
/// [`Error::InvalidArgument`] naming `point` (not finite or depth ≤ 0) or `dir` (zero or not
/// finite); [`Error::Degenerate`] when the map is behind its centre of projection at `p`, or
/// when the map coordinate does not change along `dir` (infinite projection aliasing).
pub fn aliasing_functions(
    view: &ViewFrustum,
    shadow: &ShadowMap,
    p: DVec3,
    dir: DVec3,
) -> Result<AliasingFunctions> {
    let z = depth_of(p)?;
    if !dir.is_finite() || dir.length_squared() == 0.0 {
        return Err(Error::invalid(
            "dir",
            format!("must be a finite non-zero vector (got {dir})"),
        ));
    }
    let (_, _, gs, gt, _) = st_gradients(&shadow.matrix, p)?;
    let tq = view.aspect() * view.tan_half_fov();
    let tp = view.tan_half_fov();
    // q = x/(z tq) with z = −p.z: ∂q/∂p = (1/(z tq), 0, x/(z² tq)).
    let grad_q = DVec3::new(1.0 / (z * tq), 0.0, p.x / (z * z * tq));
    let grad_p = DVec3::new(0.0, 1.0 / (z * tp), p.y / (z * z * tp));
    let ds = gs.dot(dir);
    let dt = gt.dot(dir);
    if ds == 0.0 || dt == 0.0 {
        return Err(Error::Degenerate(format!(
            "the shadow map does not change along {dir} at {p}: projection aliasing is infinite"
        )));
    }
    Ok(AliasingFunctions {
        e_q: finite_result("E_q", (grad_q.dot(dir) / ds).abs())?,
        e_p: finite_result("E_p", (grad_p.dot(dir) / dt).abs())?,
    })
}

fn depth_of(p: DVec3) -> Result<f64> {
    if !p.is_finite() {
        return Err(Error::invalid("point", format!("must be finite (got {p})")));
    }
    let z = finite("point", -p.z)?;
    if z <= 0.0 {
        return Err(Error::invalid(
            "point",
            format!("must be in front of the camera, depth −p.z > 0 (got {p})"),
        ));
    }
    Ok(z)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measure::point_error;

    /// Every corner maps into the clip volume, and the corners bounding the fit land on its
    /// edges: s of the nearest corner row is 0 or 1 at the bounding corner, t spans [0, 1].
    #[test]
    fn corners_map_into_the_map() {
        let view = ViewFrustum::new(1.0, 50.0, 0.6).unwrap();
        for g in [0.0, 0.2, 0.6, 1.0, std::f64::consts::FRAC_PI_2] {
            for side in [TiltSide::InFront, TiltSide::Behind] {
                for np in [
                    NPrime::finite(0.3).unwrap(),
                    NPrime::finite(7.0).unwrap(),
                    NPrime::UNWARPED,
                ] {
                    let w = tilted_warp(&view, LightAngle::new(g).unwrap(), side, np).unwrap();
                    let (mut tmin, mut tmax, mut smax) = (1.0f64, 0.0f64, 0.0f64);
                    for c in view.corners() {
                        let h = w.shadow.matrix * c.extend(1.0);
                        assert!(h.w > 0.0);
                        for v in [h.x / h.w, h.y / h.w, h.z / h.w] {
                            assert!(v.abs() <= 1.0 + 1e-12, "{v} at g={g} {np:?}");
                        }
                        tmin = tmin.min(0.5 * (h.y / h.w + 1.0));
                        tmax = tmax.max(0.5 * (h.y / h.w + 1.0));
                        smax = smax.max(0.5 * (h.x / h.w + 1.0));
                    }
                    assert!(tmin.abs() < 1e-12 && (tmax - 1.0).abs() < 1e-12);
                    assert!((smax - 1.0).abs() < 1e-12);
                    // The error measurement accepts the matrix.
                    point_error(
                        &view,
                        &w.shadow,
                        DVec3::new(0.0, 0.0, -3.0),
                        Resolutions::default(),
                    )
                    .unwrap();
                }
            }
        }
    }

    /// Overhead, on the axis, the along-axis width equals the perpendicular one (sin γ = 1).
    #[test]
    fn along_axis_equals_perpendicular_overhead() {
        let view = ViewFrustum::new(1.0, 20.0, 0.5).unwrap();
        let w = tilted_warp(
            &view,
            LightAngle::new(std::f64::consts::FRAC_PI_2).unwrap(),
            TiltSide::InFront,
            NPrime::finite(4.0).unwrap(),
        )
        .unwrap();
        let p = DVec3::new(0.0, 0.0, -5.0);
        let a = mz_along_view_axis(&view, &w.shadow, p, Resolutions::default()).unwrap();
        let b = point_error(&view, &w.shadow, p, Resolutions::default())
            .unwrap()
            .mz;
        assert!((a - b).abs() < 1e-12 * b);
    }
}
