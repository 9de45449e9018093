//! The headless harness of the render tests (tests/render.rs, tests/lens.rs): the test scene
//! ([`crate::scene`]) in an app on Vulkan (lavapipe without a GPU) drawn into a [`W`] × [`H`]
//! image that is read back each frame, and the exact ray cast against the scene's boxes.
#![allow(dead_code)] // each user takes what it needs

use crate::scene::{
    camera_transform, centre_size, headless_plugins, sun_transform, SceneBox, BOXES, FAR, FOV, NEAR,
};
use bevy::app::PluginsState;
use bevy::camera::{PerspectiveProjection, Projection, RenderTarget};
use bevy::core_pipeline::tonemapping::{DebandDither, Tonemapping};
use bevy::image::Image;
use bevy::light::{
    DirectionalLightShadowMap, GlobalAmbientLight, NotShadowReceiver, ShadowFilteringMethod,
};
use bevy::prelude::*;
use bevy::render::gpu_readback::{Readback, ReadbackComplete};
use bevy::render::render_resource::{TextureFormat, TextureUsages};
use bevy::render::view::Msaa;
use bevy::render::RenderPlugin;
use shadow_aliasing::glam::DVec3;
use shadow_aliasing_bevy::{CascadeMode, ShadowAliasingPlugin};
use std::sync::{Arc, Mutex};

/// The rendered image's size in pixels.
pub const W: u32 = 640;
pub const H: u32 = 360;

type Slot = Arc<Mutex<Option<Vec<u8>>>>;

/// The scene in an app: its sun (`light`, a `DirectionalLight` with [`CascadeMode::Measure`])
/// and its camera, which draws into an image read back each frame.
pub struct Harness {
    pub app: App,
    pub light: Entity,
    pub camera: Entity,
    slot: Slot,
}

impl Harness {
    /// The scene with the plugin, `render` (Bevy's `RenderPlugin`, pipelines compiled
    /// synchronously) and `res`² shadow maps, no ambient light, the camera without MSAA,
    /// tonemapping or dither and with Bevy's 2 × 2 hardware PCF.
    pub fn new(render: RenderPlugin, res: usize) -> Self {
        let mut app = App::new();
        app.add_plugins((
            headless_plugins().set(RenderPlugin {
                synchronous_pipeline_compilation: true,
                ..render
            }),
            ShadowAliasingPlugin,
        ))
        .insert_resource(DirectionalLightShadowMap { size: res })
        .insert_resource(GlobalAmbientLight {
            brightness: 0.0,
            ..default()
        });
        while app.plugins_state() == PluginsState::Adding {
            bevy::tasks::tick_global_task_pools_on_main_thread();
        }
        app.finish();
        app.cleanup();
        let world = app.world_mut();
        let mut image = Image::new_target_texture(W, H, TextureFormat::Rgba8UnormSrgb, None);
        image.texture_descriptor.usage |= TextureUsages::COPY_SRC;
        let target = world.resource_mut::<Assets<Image>>().add(image);
        let material = world
            .resource_mut::<Assets<StandardMaterial>>()
            .add(StandardMaterial {
                base_color: Color::srgb(0.8, 0.8, 0.8),
                perceptual_roughness: 1.0,
                reflectance: 0.0,
                ..default()
            });
        for bx in &BOXES {
            let (c, size) = centre_size(bx);
            let mesh = world
                .resource_mut::<Assets<Mesh>>()
                .add(Cuboid::from_size(size));
            let mut e = world.spawn((
                Mesh3d(mesh),
                MeshMaterial3d(material.clone()),
                Transform::from_translation(c),
            ));
            if bx.pole {
                e.insert(NotShadowReceiver);
            }
        }
        let camera = world
            .spawn((
                Camera3d::default(),
                Camera {
                    clear_color: ClearColorConfig::Custom(Color::BLACK),
                    ..default()
                },
                RenderTarget::Image(target.clone().into()),
                Projection::Perspective(PerspectiveProjection {
                    fov: FOV,
                    aspect_ratio: W as f32 / H as f32,
                    near: NEAR,
                    far: FAR,
                    ..default()
                }),
                Msaa::Off,
                Tonemapping::None,
                DebandDither::Disabled,
                ShadowFilteringMethod::Hardware2x2,
                camera_transform(),
            ))
            .id();
        let light = world
            .spawn((
                DirectionalLight {
                    illuminance: 2000.0,
                    shadow_maps_enabled: true,
                    ..default()
                },
                sun_transform(),
                CascadeMode::Measure,
            ))
            .id();
        let slot: Slot = Arc::default();
        let s = slot.clone();
        world
            .spawn(Readback::texture(target))
            .observe(move |ev: On<ReadbackComplete>| {
                *s.lock().unwrap() = Some(ev.data.clone());
            });
        Self {
            app,
            light,
            camera,
            slot,
        }
    }

    /// Three frames, then frames until two consecutive read-backs agree: the image (RGBA8,
    /// unpadded rows). Panics after 30 frames without agreement.
    pub fn settle(&mut self) -> Vec<u8> {
        for _ in 0..3 {
            self.app.update();
        }
        *self.slot.lock().unwrap() = None;
        let mut prev: Option<Vec<u8>> = None;
        for _ in 0..30 {
            self.app.update();
            let Some(d) = self.slot.lock().unwrap().take() else {
                continue;
            };
            assert_eq!(d.len(), (W * H * 4) as usize, "unpadded RGBA8 rows");
            if prev.as_ref() == Some(&d) {
                return d;
            }
            prev = Some(d);
        }
        panic!("no two consecutive read-back frames agreed within 30 frames");
    }
}

/// Where the ray `o + t d` (t > 0) enters box `b`: t, the entered face's axis and the sign of
/// its outward normal; `None` if it misses.
pub fn ray_box(o: DVec3, d: DVec3, b: &SceneBox) -> Option<(f64, usize, f64)> {
    let (mut t0, mut t1, mut axis, mut sign) = (f64::NEG_INFINITY, f64::INFINITY, 0, 0.0);
    for k in 0..3 {
        if d[k].abs() < 1e-300 {
            if o[k] < b.min[k] || o[k] > b.max[k] {
                return None;
            }
            continue;
        }
        let (a, e) = ((b.min[k] - o[k]) / d[k], (b.max[k] - o[k]) / d[k]);
        let (lo, hi, s) = if a < e { (a, e, -1.0) } else { (e, a, 1.0) };
        if lo > t0 {
            (t0, axis, sign) = (lo, k, s);
        }
        t1 = t1.min(hi);
    }
    (t0 <= t1 && t0 > 0.0).then_some((t0, axis, sign))
}
