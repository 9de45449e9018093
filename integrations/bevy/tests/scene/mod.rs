//! The test scene (docs/bevy.md): a ground slab, boxes on it, a tall thin pole behind the camera
//! (outside the view) whose shadow falls into it, a sun 20° above the horizon. Shared by the
//! tests and the example (`#[path]`), so that the figures in docs/bevy.md are the scene the
//! example shows.
#![allow(dead_code)] // each user takes what it needs

use bevy::prelude::*;

/// A box of the scene: world min and max corners, and whether it is the pole (a caster that
/// is not a receiver: `NotShadowReceiver`).
#[derive(Debug, Clone, Copy)]
pub struct SceneBox {
    // Every coordinate is a multiple of 1/4: exact in f32, so that the ray casts see the boxes
    // Bevy renders.
    pub min: [f64; 3],
    pub max: [f64; 3],
    pub pole: bool,
}

const fn b(min: [f64; 3], max: [f64; 3]) -> SceneBox {
    SceneBox {
        min,
        max,
        pole: false,
    }
}

/// Ground, boxes and the pole (the last).
pub const BOXES: [SceneBox; 7] = [
    b([-60.0, -0.5, -160.0], [60.0, 0.0, 20.0]),
    b([-3.0, 0.0, -4.0], [-1.0, 2.0, -2.0]),
    b([2.0, 0.0, -10.0], [4.0, 3.0, -7.0]),
    b([-6.0, 0.0, -22.0], [-3.0, 4.0, -18.0]),
    b([5.0, 0.0, -40.0], [9.0, 6.0, -34.0]),
    b([-14.0, 0.0, -75.0], [-8.0, 8.0, -65.0]),
    SceneBox {
        min: [-2.5, 0.0, 13.5],
        max: [-1.5, 12.0, 14.5],
        pole: true,
    },
];

/// The camera's position and the point it looks at: above every receiver (the receivers' merged
/// box reaches y = 8), as a game camera over a ground is, so that the focus body starts where
/// the view meets the receivers, not at the near plane.
pub const EYE: [f32; 3] = [0.0, 10.0, 12.0];
pub const TARGET: [f32; 3] = [0.0, 0.0, -25.0];
/// The vertical field of view (Bevy's default, 45°), near and far.
pub const FOV: f32 = std::f32::consts::FRAC_PI_4;
pub const NEAR: f32 = 0.1;
pub const FAR: f32 = 1000.0;

/// The direction sunlight travels: 20° below the horizon, 20° to the right of −Z (from behind the
/// camera, so the pole behind it shadows the view).
pub fn sun_dir() -> Vec3 {
    let (e, a) = (20f32.to_radians(), 20f32.to_radians());
    Vec3::new(a.sin() * e.cos(), -e.sin(), -a.cos() * e.cos())
}

/// The camera's transform.
pub fn camera_transform() -> Transform {
    Transform::from_translation(Vec3::from(EYE)).looking_at(Vec3::from(TARGET), Vec3::Y)
}

/// The sun's transform (a `DirectionalLight` shines along its forward, −Z).
pub fn sun_transform() -> Transform {
    Transform::default().looking_to(sun_dir(), Vec3::Y)
}

/// A box's centre and size, as a Bevy `Cuboid` at a translation.
pub fn centre_size(bx: &SceneBox) -> (Vec3, Vec3) {
    let (lo, hi) = (
        Vec3::new(bx.min[0] as f32, bx.min[1] as f32, bx.min[2] as f32),
        Vec3::new(bx.max[0] as f32, bx.max[1] as f32, bx.max[2] as f32),
    );
    (0.5 * (lo + hi), hi - lo)
}

/// Bevy's `DefaultPlugins` for a headless test. With the feature `window` (CI builds the example
/// `toggle` in the tests' build, docs/bevy.md "CI") they hold Bevy's window, winit and logger:
/// here no primary window, and neither winit (its event loop needs a display) nor the logger
/// (one global logger per process, and the tests build several apps).
#[cfg(feature = "window")]
pub fn headless_plugins() -> bevy::app::PluginGroupBuilder {
    DefaultPlugins
        .build()
        .disable::<bevy::winit::WinitPlugin>()
        .disable::<bevy::log::LogPlugin>()
        .set(bevy::window::WindowPlugin {
            primary_window: None,
            exit_condition: bevy::window::ExitCondition::DontExit,
            ..default()
        })
}

/// Bevy's `DefaultPlugins` for a headless test (without the feature `window`: no window, winit
/// or logger to leave out).
#[cfg(not(feature = "window"))]
pub fn headless_plugins() -> bevy::app::PluginGroupBuilder {
    DefaultPlugins.build()
}
