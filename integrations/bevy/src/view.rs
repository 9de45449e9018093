//! A Bevy camera and directional light as the crate's frame inputs.

use crate::convert::{mat4_to_crate, vec3_to_crate};
use bevy::camera::{Camera, Projection};
use bevy::prelude::*;
use shadow_aliasing::frame::Camera as FrameCamera;

/// A camera as the crate sees it: world → eye and its perspective projection, and the image
/// height in pixels that the error is counted in.
#[derive(Debug, Clone, Copy)]
pub(crate) struct View {
    pub(crate) camera: FrameCamera,
    pub(crate) image_height: u32,
}

/// The crate's camera for a Bevy camera. Bevy's `PerspectiveProjection::fov` is the full vertical
/// field of view, the crate takes half of it. The image height is the camera's physical viewport
/// height, or `fallback_height` before the render target is known (no renderer, first frame).
///
/// # Errors
/// A message naming what is not supported: a projection other than perspective, or a camera
/// transform that is not rigid (scaled), as the crate's `Camera::new` reports it.
pub(crate) fn view(
    transform: &GlobalTransform,
    projection: &Projection,
    camera: &Camera,
    fallback_height: u32,
) -> Result<View, String> {
    let Projection::Perspective(p) = projection else {
        return Err(
            "only perspective cameras are measured (the error is a perspective one)".into(),
        );
    };
    let world_to_eye = mat4_to_crate(&transform.to_matrix()).inverse();
    let camera_f = FrameCamera::new(
        world_to_eye,
        f64::from(p.near),
        f64::from(p.far),
        0.5 * f64::from(p.fov),
        f64::from(p.aspect_ratio),
    )
    .map_err(|e| format!("camera: {e}"))?;
    let image_height = camera
        .physical_viewport_size()
        .map_or(fallback_height, |s| s.y)
        .max(1);
    Ok(View {
        camera: camera_f,
        image_height,
    })
}

/// The direction a Bevy `DirectionalLight` travels, world space: its transform's forward (−Z), as
/// `build_directional_light_cascades` (bevy_light/src/cascade.rs) builds light space from the
/// rotation alone.
pub(crate) fn light_dir(transform: &GlobalTransform) -> [f64; 3] {
    vec3_to_crate(*transform.forward())
}
