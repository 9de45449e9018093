//! A renderer's frame loop: camera in, this frame's shadow matrix out, as `Mat4` for the GPU,
//! with the aliasing error of what was built.
//!
//! Copy the body of `shadow_for_frame` into your renderer. Conventions: world and eye space
//! right-handed, the camera's view matrix maps world → eye with the camera looking down −Z
//! (glam `dcamera::rh::view::look_at_mat4`); the light direction is the direction light travels.
//!
//! Run with `cargo run --example frame_loop`.

use glam::{DMat4, DVec3, Mat4};
use shadow_aliasing::maps::{warp, ClipDepth, WarpRule};
use shadow_aliasing::measure::frustum_max;
use shadow_aliasing::{Result, ViewFrustum};

/// What a renderer uploads for one directional light this frame.
struct FrameShadow {
    /// World → light clip space, depth in [0, 1] (Vulkan, wgpu, Direct3D, Metal).
    world_to_light: Mat4,
    /// The same for eye-space positions (if your shaders work in view space).
    eye_to_light: Mat4,
    /// Maximum aliasing error over the view frustum with a 1 × 1 map and a 1-pixel image:
    /// multiply by (image pixels / map texels) along each axis for your resolutions.
    max_mx: f64,
    max_mz: f64,
    /// Texels needed per image pixel² for maximum error 1 (Lloyd 2006 §4.2).
    storage_factor: f64,
}

fn shadow_for_frame(
    view_matrix: DMat4,
    near: f64,
    far: f64,
    half_fov_y: f64,
    aspect: f64,
    light_dir_world: DVec3,
) -> Result<FrameShadow> {
    // 1. The camera's frustum (validated: near > 0, far > near, 0 < fov/2 < 90°).
    let frustum = ViewFrustum::with_aspect(near, far, half_fov_y, aspect)?;
    // 2. The light in eye space: rotate by the view matrix (a direction ignores translation).
    let light_eye = view_matrix.transform_vector3(light_dir_world);
    // 3. The warp. `WarpRule::default()` is the crate's minimax n′ (never worse than the
    //    uniform map); `WarpRule::Lispsm`, `WarpRule::Filament`, … reproduce other rules.
    let shadow = warp(&frustum, light_eye, WarpRule::default())?;
    // 4. What it costs: exact maximum error over the frustum.
    let err = frustum_max(&frustum, &shadow.shadow_map())?;
    Ok(FrameShadow {
        world_to_light: shadow
            .world_to_clip(view_matrix, ClipDepth::ZeroToOne)
            .as_mat4(),
        eye_to_light: shadow.to_mat4(ClipDepth::ZeroToOne),
        max_mx: err.max_mx,
        max_mz: err.max_mz,
        storage_factor: err.storage_factor,
    })
}

fn main() -> Result<()> {
    let sun = DVec3::new(0.3, -1.0, 0.2); // travelling down and slightly sideways
    for frame in 0..8 {
        // The camera orbits a point, looking at it from 20 units away, 5 up.
        let a = frame as f64 * std::f64::consts::TAU / 8.0;
        let eye = DVec3::new(20.0 * a.cos(), 5.0, 20.0 * a.sin());
        let view = glam::dcamera::rh::view::look_at_mat4(eye, DVec3::ZERO, DVec3::Y);
        let s = shadow_for_frame(view, 0.5, 200.0, 30f64.to_radians(), 16.0 / 9.0, sun)?;
        // For a 1920 × 1080 image and a 2048² map, the maximum texel-to-pixel ratios:
        let (img, map) = (1080.0, 2048.0);
        println!(
            "frame {frame}: S̄ = {:9.2}  max error x {:5.2}, z {:5.2} (1080p, 2048² map)  first row {:?}",
            s.storage_factor,
            s.max_mx * img / map,
            s.max_mz * img / map,
            s.world_to_light.row(0).to_array()
        );
        // A GPU upload would copy `s.world_to_light.to_cols_array()` (column-major).
        assert!(s.eye_to_light.is_finite());
    }
    Ok(())
}
