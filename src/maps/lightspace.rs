//! Light space: the orthonormal frame every warp is built in (Lloyd 2006 §4, Fig 3; Wimmer et
//! al. 2004's LiSPSM light space with s and t swapped as Lloyd does).
//!
//! - `y` points toward the light (against the direction light travels);
//! - `z` is the warp axis: a chosen axis (the view direction for a single map, a face bisector
//!   for a face partition) projected perpendicular to `y`;
//! - `x = y × z`, so that (x, y, z) is right-handed.
//!
//! The shadow map's s runs along `x`, t along `z`, and depth along `−y`.
//!
//! # When the axis is parallel to the light
//!
//! The projection of the axis vanishes and its direction is undefined. No choice can be continuous
//! over every way of approaching that configuration (the projected axis turns by 180° as the light
//! passes through the axis, and by any angle depending on the side it approaches from: a tangent
//! field on the sphere must vanish somewhere). The crate's choice: when the projected axis is
//! shorter than [`PARALLEL_TOLERANCE`] (sine of the angle between axis and light), `z` is the
//! eye-space up vector +Y projected perpendicular to the light, or +X if that is parallel too.
//! For the view direction −Z this is the limit of the light sweeping through the view axis in the
//! eye's vertical plane, and it gives the same orthographic storage factor as the limit in the
//! horizontal plane (the frustum's cross-section is an axis-aligned rectangle). All the crate's
//! n′ rules go to [`crate::NPrime::UNWARPED`] there, so the map is the orthographic fit.

use crate::error::{Error, Result};
use crate::frustum::LightDir;
use crate::numeric::lane::{Lane, V3};
use crate::numeric::PARALLEL_TOLERANCE;
use glam::{DMat4, DVec3, DVec4};

/// An orthonormal, right-handed light-space frame in eye space (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LightSpace {
    /// s direction of the shadow map, `y × z`.
    pub x: DVec3,
    /// Toward the light: `−light_dir`.
    pub y: DVec3,
    /// The warp axis (t direction), perpendicular to `y`.
    pub z: DVec3,
}

impl LightSpace {
    /// Light-space coordinates `(x·p, y·p, z·p)` of an eye-space point (the frame shares the eye's
    /// origin).
    #[inline]
    #[must_use]
    pub fn to_light(&self, p: DVec3) -> DVec3 {
        DVec3::new(self.x.dot(p), self.y.dot(p), self.z.dot(p))
    }

    /// The rotation eye space → light space as a matrix (rows x, y, z).
    #[must_use]
    pub fn rotation(&self) -> DMat4 {
        DMat4::from_cols(
            self.x.extend(0.0),
            self.y.extend(0.0),
            self.z.extend(0.0),
            DVec4::W,
        )
        .transpose()
    }

    /// The direction light travels, `−y`.
    #[inline]
    #[must_use]
    pub fn light_dir(&self) -> DVec3 {
        -self.y
    }

    /// [`LightSpace::light_dir`] as the validated type (`y` is a unit vector by construction).
    #[inline]
    pub(crate) fn light(&self) -> LightDir {
        LightDir::from_unit_unchecked(-self.y)
    }
}

/// Builds light space for a directional light travelling along `light_dir` (eye space, any
/// length) with warp axis `axis` (eye space, any length; the view direction `(0, 0, −1)` for a
/// single map).
///
/// `y = −light_dir/|light_dir|`, `z = (a − (a·y) y)/|a − (a·y) y|` with `a = axis/|axis|`,
/// `x = y × z`. When `|a − (a·y) y| <` [`PARALLEL_TOLERANCE`] the fallback of the module docs is
/// used. The result is continuous in `light_dir` and `axis` everywhere except exactly there.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `light_dir` or `axis` for a zero or non-finite vector.
///
/// ```
/// # use shadow_aliasing::maps::light_space;
/// # use glam::DVec3;
/// // Light straight down, view along −Z: z is the view direction, y is up.
/// let ls = light_space(DVec3::new(0.0, -1.0, 0.0), DVec3::new(0.0, 0.0, -1.0))?;
/// assert!((ls.z - DVec3::new(0.0, 0.0, -1.0)).length() < 1e-15);
/// assert!((ls.y - DVec3::Y).length() < 1e-15);
/// assert!((ls.x.cross(ls.y) - ls.z).length() < 1e-15);
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn light_space(light_dir: DVec3, axis: DVec3) -> Result<LightSpace> {
    // Both vectors are scaled to a largest component of 1 before they are normalised: the sum
    // of squares of a vector with components near 10⁻¹⁵⁸ is subnormal (a light direction of
    // length 1 + 8·10⁻⁹ came out of it), and one near 10¹⁵⁵ overflows.
    let l = LightDir::new(scaled(light_dir))?;
    light_space_dir(l, axis)
}

/// [`light_space`] for a light direction already validated (the axis is validated here).
///
/// # Errors
/// [`Error::InvalidArgument`] naming `axis` for a zero or non-finite vector.
#[inline]
pub(crate) fn light_space_dir(l: LightDir, axis: DVec3) -> Result<LightSpace> {
    let a = unit_axis(scaled(axis))?;
    Ok(light_space_unit(l, a))
}

/// `v / max|vᵢ|` for a finite, non-zero `v` (the same direction, largest component ±1); any other
/// `v` unchanged, for the validators to name.
#[inline]
fn scaled(v: DVec3) -> DVec3 {
    let m = v.abs().max_element();
    if v.is_finite() && m > 0.0 {
        v / m
    } else {
        v
    }
}

/// [`light_space`] for a unit light direction `l` and a unit axis `a`, already validated.
#[inline]
pub(crate) fn light_space_unit(l: LightDir, a: DVec3) -> LightSpace {
    let y = V3::from(-l.as_dvec3());
    let (mut z, mut len) = project_axis(y, V3::from(a));
    if len < PARALLEL_TOLERANCE {
        let y = DVec3::from(y);
        let mut zf = DVec3::Y - y.y * y;
        len = zf.length();
        if len < 0.5 {
            zf = DVec3::X - y.x * y;
            len = zf.length();
        }
        z = V3::from(zf);
    }
    let (x, z) = frame_from_projected(y, z, len);
    LightSpace {
        x: x.into(),
        y: y.into(),
        z: z.into(),
    }
}

/// The axis `a` projected perpendicular to `y`, `a − (a·y) y`, and its length: the warp axis of
/// [`light_space_unit`] before the parallel test (the scalar builders and the sweep's lanes).
#[inline(always)]
pub(crate) fn project_axis<T: Lane>(y: V3<T>, a: V3<T>) -> (V3<T>, T) {
    let z = a.perp(y);
    (z, z.length())
}

/// The frame's x and z from `y` and the projected axis `z` of length `len`: `z · (1/|z|)` (glam's
/// `normalize` without its second square root), `x = (y × z)` normalised, and z re-orthogonalised
/// as `x × y` so the frame is orthonormal to rounding.
#[inline(always)]
pub(crate) fn frame_from_projected<T: Lane>(y: V3<T>, z: V3<T>, len: T) -> (V3<T>, V3<T>) {
    let one = T::splat(1.0);
    let z = z.scale(one / len);
    let x = y.cross(z);
    let x = x.scale(one / x.length());
    (x, x.cross(y))
}

fn unit_axis(axis: DVec3) -> Result<DVec3> {
    if !axis.is_finite() {
        return Err(Error::invalid(
            "axis",
            format!("must be finite (got {axis})"),
        ));
    }
    let len = axis.length();
    if len.is_nan() || len <= 1e-300 || !len.is_finite() {
        return Err(Error::invalid(
            "axis",
            format!("must be a non-zero vector (got {axis})"),
        ));
    }
    Ok(axis / len)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_is_orthonormal_and_right_handed() {
        for l in [
            DVec3::new(0.3, -1.0, 0.2),
            DVec3::new(0.0, 0.0, -1.0),
            DVec3::new(0.0, 0.0, 1.0),
            DVec3::new(1e-14, 0.0, 1.0),
            DVec3::new(0.0, 1.0, 0.0),
        ] {
            let ls = light_space(l, DVec3::NEG_Z).unwrap();
            for v in [ls.x, ls.y, ls.z] {
                assert!((v.length() - 1.0).abs() < 1e-14);
            }
            assert!(ls.x.dot(ls.y).abs() < 1e-14);
            assert!(ls.x.dot(ls.z).abs() < 1e-14);
            assert!(ls.y.dot(ls.z).abs() < 1e-14);
            assert!((ls.x.cross(ls.y) - ls.z).length() < 1e-14);
            assert!((ls.light_dir() - l.normalize()).length() < 1e-14);
        }
        // Parallel: the fallback is eye up projected, the limit from a light tilted toward −Y.
        let ls = light_space(DVec3::new(0.0, 0.0, -1.0), DVec3::NEG_Z).unwrap();
        let near = light_space(DVec3::new(0.0, -1e-6, -1.0), DVec3::NEG_Z).unwrap();
        assert!((ls.z - near.z).length() < 1e-5);
        assert!(light_space(DVec3::ZERO, DVec3::NEG_Z).is_err());
        assert!(light_space(DVec3::Y, DVec3::new(f64::NAN, 0.0, 0.0)).is_err());
    }
}
