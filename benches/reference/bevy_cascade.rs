//! A Rust port of Bevy's directional-light cascades, for side-by-side benchmarks (issue 23 item 9).
//!
//! Follows Bevy **0.19.1** (tag `v0.19.1`; unchanged on `main` at 0.20.0-dev, August 2026):
//!
//! - `crates/bevy_light/src/cascade.rs`, `calculate_cascade` (ported line for line, f32 glam
//!   `Vec3A`/`Mat4` as Bevy), and the per-view body of `build_directional_light_cascades` (the
//!   light's `Mat4::from_quat`, its transpose, `light_from_world * world_from_view`, the near
//!   bounds `[minimum_distance, (1 − overlap) · bounds…]`);
//! - `crates/bevy_camera/src/projection.rs`, `PerspectiveProjection::get_frustum_corners`;
//! - `calculate_cascade_bounds` (bevy_light's cascade.rs), the far bounds of
//!   `CascadeShadowConfigBuilder` (examples/engine_defaults.rs builds Bevy's default config).
//!
//! Differences, none of which changes a value: the ECS queries are gone (one light, one view);
//! the light's rotation is passed as Bevy's `GlobalTransform::rotation()` would return it; the
//! cascades are written into a fixed array where Bevy collects a `Vec` per view (one heap
//! allocation per light per view per frame that this port does not pay).
//!
//! Bevy fits each *bare* frustum slice: no focus on receivers or casters, no error measurement.
//! The light looks down its local −Z; cascade clip depth is reversed (near the light → 1).

use glam::{Mat4, Quat, Vec3A, Vec4};

/// Bevy's `Cascade`.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Cascade {
    /// The transform of the light, i.e. the view to world matrix.
    pub world_from_cascade: Mat4,
    /// The orthographic projection for this cascade.
    pub clip_from_cascade: Mat4,
    /// World → light clip.
    pub clip_from_world: Mat4,
    /// Size of each shadow map texel in world units.
    pub texel_size: f32,
}

/// The fields of Bevy's `PerspectiveProjection` that the cascades read.
#[derive(Debug, Clone, Copy)]
pub struct PerspectiveProjection {
    /// Full vertical field of view, radians.
    pub fov: f32,
    /// Width / height.
    pub aspect_ratio: f32,
}

impl PerspectiveProjection {
    /// Bevy's `get_frustum_corners(z_near, z_far)` (z negative: −z is forward): near plane
    /// bottom right, top right, top left, bottom left, then the far plane in the same order.
    pub fn get_frustum_corners(&self, z_near: f32, z_far: f32) -> [Vec3A; 8] {
        let tan_half_fov = (self.fov / 2.).tan();
        let a = z_near.abs() * tan_half_fov;
        let b = z_far.abs() * tan_half_fov;
        let aspect_ratio = self.aspect_ratio;
        [
            Vec3A::new(a * aspect_ratio, -a, z_near),
            Vec3A::new(a * aspect_ratio, a, z_near),
            Vec3A::new(-a * aspect_ratio, a, z_near),
            Vec3A::new(-a * aspect_ratio, -a, z_near),
            Vec3A::new(b * aspect_ratio, -b, z_far),
            Vec3A::new(b * aspect_ratio, b, z_far),
            Vec3A::new(-b * aspect_ratio, b, z_far),
            Vec3A::new(-b * aspect_ratio, -b, z_far),
        ]
    }
}

/// Bevy's `CascadeShadowConfig` with at most four cascades (Bevy's default count).
#[derive(Debug, Clone, Copy)]
pub struct CascadeShadowConfig {
    /// The (positive) distance to the far boundary of each cascade; `bounds[..count]` are used.
    pub bounds: [f32; 4],
    /// How many cascades (1..=4).
    pub count: usize,
    /// The proportion of overlap each cascade has with the previous cascade.
    pub overlap_proportion: f32,
    /// The (positive) distance to the near boundary of the first cascade.
    pub minimum_distance: f32,
}

/// Bevy's `calculate_cascade_bounds(num_cascades, nearest_bound, shadow_maximum_distance)`
/// (`crates/bevy_light/src/cascade.rs`, used by `CascadeShadowConfigBuilder::build`): far bounds
/// `nearest_bound · base^i`, `base = (maximum/nearest)^{1/(n−1)}`, in f32 (`ops::powf` is
/// `f32::powf` without Bevy's `libm` feature); `[maximum]` for one cascade. Into a fixed array
/// (Bevy collects a `Vec`); `num_cascades` is 1..=4.
pub fn calculate_cascade_bounds(
    num_cascades: usize,
    nearest_bound: f32,
    shadow_maximum_distance: f32,
) -> [f32; 4] {
    let mut bounds = [0.0; 4];
    if num_cascades == 1 {
        bounds[0] = shadow_maximum_distance;
        return bounds;
    }
    let base = (shadow_maximum_distance / nearest_bound).powf(1.0 / (num_cascades - 1) as f32);
    for (i, b) in bounds.iter_mut().enumerate().take(num_cascades) {
        *b = nearest_bound * base.powf(i as f32);
    }
    bounds
}

/// The per-view body of `build_directional_light_cascades` for one light: fills
/// `out[..config.count]`.
pub fn build_directional_light_cascades(
    light_rotation: Quat,
    world_from_view: Mat4,
    projection: &PerspectiveProjection,
    config: &CascadeShadowConfig,
    shadow_map_size: u32,
    out: &mut [Cascade; 4],
) {
    let world_from_light = Mat4::from_quat(light_rotation);
    let light_from_world = world_from_light.transpose();
    let light_view_from_camera = light_from_world * world_from_view;
    let overlap_factor = 1.0 - config.overlap_proportion;
    let far_bounds = &config.bounds[..config.count];
    let mut near_bound = config.minimum_distance;
    for (slot, &far_bound) in out.iter_mut().zip(far_bounds) {
        // Negate bounds as -z is camera forward direction.
        let corners = projection.get_frustum_corners(-near_bound, -far_bound);
        *slot = calculate_cascade(
            corners,
            shadow_map_size as f32,
            world_from_light,
            light_view_from_camera,
        );
        near_bound = overlap_factor * far_bound;
    }
}

/// Bevy's `calculate_cascade`: the cascade of the frustum slice `frustum_corners` (camera space,
/// [`PerspectiveProjection::get_frustum_corners`]'s order).
pub fn calculate_cascade(
    frustum_corners: [Vec3A; 8],
    cascade_texture_size: f32,
    world_from_light: Mat4,
    light_from_camera: Mat4,
) -> Cascade {
    let mut min = Vec3A::splat(f32::MAX);
    let mut max = Vec3A::splat(f32::MIN);
    for corner_camera_view in frustum_corners {
        let corner_light_view = light_from_camera.transform_point3a(corner_camera_view);
        min = min.min(corner_light_view);
        max = max.max(corner_light_view);
    }

    // The larger of the body diagonal and the far plane diagonal, from the camera-space corners,
    // rounded up to an integer (a size that does not change while the camera moves).
    let body_diagonal = (frustum_corners[0] - frustum_corners[6]).length_squared();
    let far_plane_diagonal = (frustum_corners[4] - frustum_corners[6]).length_squared();
    let cascade_diameter = body_diagonal.max(far_plane_diagonal).sqrt().ceil();

    let cascade_texel_size = cascade_diameter / cascade_texture_size;
    // The near plane centre at whole multiples of the texel size (shadow stability).
    let near_plane_center = Vec3A::new(
        (0.5 * (min.x + max.x) / cascade_texel_size).floor() * cascade_texel_size,
        (0.5 * (min.y + max.y) / cascade_texel_size).floor() * cascade_texel_size,
        // max.z is the near plane for right-handed y-up
        max.z,
    );

    // `cascade_from_world` formed directly (not by inverting `world_from_cascade`).
    let world_from_light_transpose = world_from_light.transpose();
    let cascade_from_world = Mat4::from_cols(
        world_from_light_transpose.x_axis,
        world_from_light_transpose.y_axis,
        world_from_light_transpose.z_axis,
        (-near_plane_center).extend(1.0),
    );
    let world_from_cascade = Mat4::from_cols(
        world_from_light.x_axis,
        world_from_light.y_axis,
        world_from_light.z_axis,
        world_from_light * near_plane_center.extend(1.0),
    );

    // Right-handed orthographic projection centred at `near_plane_center`, reversed depth.
    let r = (max.z - min.z).recip();
    let clip_from_cascade = Mat4::from_cols(
        Vec4::new(2.0 / cascade_diameter, 0.0, 0.0, 0.0),
        Vec4::new(0.0, 2.0 / cascade_diameter, 0.0, 0.0),
        Vec4::new(0.0, 0.0, r, 0.0),
        Vec4::new(0.0, 0.0, 1.0, 1.0),
    );

    let clip_from_world = clip_from_cascade * cascade_from_world;
    Cascade {
        world_from_cascade,
        clip_from_cascade,
        clip_from_world,
        texel_size: cascade_texel_size,
    }
}

/// The rotation of a light whose local −Z is `direction` (Bevy's `Transform::looking_to` with
/// `Vec3::Y` up, the usual way a Bevy scene aims a directional light). Not per frame.
pub fn light_rotation_looking_to(direction: glam::Vec3) -> Quat {
    let back = -direction.normalize();
    let up = glam::Vec3::Y;
    let right = up
        .cross(back)
        .try_normalize()
        .unwrap_or_else(|| up.any_orthonormal_vector());
    let up = back.cross(right);
    Quat::from_mat3(&glam::Mat3::from_cols(right, up, back))
}
