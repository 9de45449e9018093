//! The one place where Bevy's math types meet the crate's: through the crate's version-free
//! boundary, plain column-major arrays (`[[f32; 4]; 4]`, `m[column][row]`) and `[f64; 3]`.
//!
//! Bevy 0.19 uses glam 0.32, the crate glam 0.34 (re-exported as `shadow_aliasing::glam`). Both
//! read and write the same arrays bit for bit, so no element is copied by hand. Moving to Bevy 0.20
//! (glam 0.33) changes nothing in this file: arrays are the same in every glam version.

use bevy::math::{Mat4, Quat, Vec3, Vec3A};
use shadow_aliasing::glam as sa;

/// A Bevy matrix as the crate's `f64` matrix (exact: every `f32` is an `f64`).
pub(crate) fn mat4_to_crate(m: &Mat4) -> sa::DMat4 {
    sa::Mat4::from_cols_array_2d(&m.to_cols_array_2d()).as_dmat4()
}

/// The crate's column arrays (`FrameMap::world_to_clip_cols`) as a Bevy matrix.
pub(crate) fn mat4_from_cols(cols: [[f32; 4]; 4]) -> Mat4 {
    Mat4::from_cols_array_2d(&cols)
}

/// A crate `f64` matrix rounded once to `f32`, as a Bevy matrix.
pub(crate) fn dmat4_to_bevy(m: &sa::DMat4) -> Mat4 {
    mat4_from_cols(m.as_mat4().to_cols_array_2d())
}

/// A Bevy vector as the `[f64; 3]` the crate's constructors take.
pub(crate) fn vec3_to_crate(v: Vec3) -> [f64; 3] {
    v.as_dvec3().to_array()
}

/// A Bevy SIMD vector as `[f64; 3]`.
pub(crate) fn vec3a_to_crate(v: Vec3A) -> [f64; 3] {
    v.as_dvec3().to_array()
}

/// A Bevy rotation as the crate's `f64` quaternion.
pub(crate) fn quat_to_crate(q: Quat) -> sa::DQuat {
    sa::DQuat::from_array(q.as_dquat().to_array())
}
