//! A window on the test scene (docs/bevy.md): Space cycles the sun's cascades between Bevy's own
//! and the plugin's replacements and budget mode (1 px, the map size chosen up to 4096²); L
//! switches the error lens (the per-pixel error heat map with its legend) on and off; the window
//! title shows the measured error of what is drawn.
//!
//! ```text
//! cargo run --release --features window --example toggle
//! ```
//!
//! Not run in CI (it needs a display); feature `window` adds Bevy's window and winit.

#[path = "../tests/scene/mod.rs"]
mod scene;

use bevy::light::NotShadowReceiver;
use bevy::prelude::*;
use scene::{camera_transform, centre_size, sun_transform, BOXES};
use shadow_aliasing::maps::WarpRule;
use shadow_aliasing_bevy::{
    Budget, CascadeErrors, CascadeMode, ErrorLens, Fit, Replace, ShadowAliasingPlugin, Splits,
};

/// The modes Space cycles through, with their names.
fn modes() -> Vec<(&'static str, CascadeMode)> {
    let replace = |fit, splits| {
        CascadeMode::Replace(Replace {
            fit,
            splits,
            depth_range: None,
        })
    };
    vec![
        ("Bevy's cascades", CascadeMode::Measure),
        (
            "focused (Bevy's splits)",
            replace(Fit::Focused(WarpRule::Uniform), Splits::Bevy),
        ),
        ("stable (Bevy's splits)", replace(Fit::Stable, Splits::Bevy)),
        (
            "focused, equal-error splits",
            replace(Fit::Focused(WarpRule::Uniform), Splits::EqualError { k: 4 }),
        ),
        (
            "LiSPSM, equal-error splits",
            replace(Fit::Focused(WarpRule::Lispsm), Splits::EqualError { k: 4 }),
        ),
        (
            "budget: 1 px, map size up to 4096²",
            CascadeMode::Budget(Budget {
                max_map_size: Some(4096),
                ..Budget::new(1.0)
            }),
        ),
    ]
}

#[derive(Resource, Default)]
struct Current(usize);

fn main() {
    App::new()
        .add_plugins((DefaultPlugins, ShadowAliasingPlugin))
        .init_resource::<Current>()
        .add_systems(Startup, setup)
        .add_systems(Update, (toggle, toggle_lens, show))
        .run();
}

fn setup(
    mut commands: Commands,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
) {
    let material = materials.add(StandardMaterial {
        base_color: Color::srgb(0.8, 0.8, 0.8),
        perceptual_roughness: 1.0,
        ..default()
    });
    for bx in &BOXES {
        let (c, size) = centre_size(bx);
        let mut e = commands.spawn((
            Mesh3d(meshes.add(Cuboid::from_size(size))),
            MeshMaterial3d(material.clone()),
            Transform::from_translation(c),
        ));
        if bx.pole {
            e.insert(NotShadowReceiver);
        }
    }
    commands.spawn((Camera3d::default(), camera_transform()));
    commands.spawn((
        DirectionalLight {
            illuminance: 10_000.0,
            shadow_maps_enabled: true,
            ..default()
        },
        sun_transform(),
        CascadeMode::Measure,
    ));
}

fn toggle(
    keys: Res<ButtonInput<KeyCode>>,
    mut current: ResMut<Current>,
    mut lights: Query<&mut CascadeMode>,
) {
    if keys.just_pressed(KeyCode::Space) {
        let modes = modes();
        current.0 = (current.0 + 1) % modes.len();
        for mut m in &mut lights {
            *m = modes[current.0].1.clone();
        }
    }
}

/// L: the error lens on the camera, or off.
fn toggle_lens(
    mut commands: Commands,
    keys: Res<ButtonInput<KeyCode>>,
    cameras: Query<(Entity, Has<ErrorLens>), With<Camera3d>>,
) {
    if keys.just_pressed(KeyCode::KeyL) {
        for (camera, on) in &cameras {
            if on {
                commands.entity(camera).remove::<ErrorLens>();
            } else {
                commands.entity(camera).insert(ErrorLens::default());
            }
        }
    }
}

fn show(current: Res<Current>, lights: Query<&CascadeErrors>, mut windows: Query<&mut Window>) {
    let Some(view) = lights.iter().flat_map(|e| e.views.values()).next() else {
        return;
    };
    let per: Vec<String> = view
        .cascades
        .iter()
        .map(|c| c.map_or("-".into(), |c| format!("{:.2}", c.max_error_pixels)))
        .collect();
    let title = format!(
        "{} [Space: next, L: error lens]: max error {:.2} px (cascades {}) at {}² texels, {} px high",
        modes()[current.0].0,
        view.max_error_pixels().unwrap_or(f64::NAN),
        per.join(" / "),
        view.map_resolution,
        view.image_height
    );
    for mut w in &mut windows {
        if w.title != title {
            w.title = title.clone();
        }
    }
}
