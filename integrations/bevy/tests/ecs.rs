//! The plugin in Bevy's ECS without a renderer: MinimalPlugins, transforms, Bevy's own
//! `build_directional_light_cascades` and the plugin. The published figures are checked against
//! the crate's measurement of the same matrices computed here by another path (the frustum
//! slice's corners, `measure::frustum_max`), and replace mode's cascades against the frame API
//! called here with the same inputs.

mod scene;

use bevy::camera::primitives::Aabb;
use bevy::camera::{Camera, PerspectiveProjection, Projection};
use bevy::diagnostic::DiagnosticsStore;
use bevy::light::cascade::build_directional_light_cascades;
use bevy::light::{
    CascadeShadowConfig, Cascades, DirectionalLight, DirectionalLightShadowMap, NotShadowCaster,
    NotShadowReceiver, ShadowFilteringMethod, SimulationLightSystems,
};
use bevy::mesh::Mesh3d;
use bevy::prelude::*;
use bevy::transform::TransformSystems;
use scene::{camera_transform, centre_size, sun_transform, BOXES, FAR, FOV, NEAR};
use shadow_aliasing::frame::{self as sa_frame, Bound, CascadeSplits, FrameInput, FrameScheme};
use shadow_aliasing::frustum::ViewFrustum;
use shadow_aliasing::glam::{DMat4, DVec3, Mat4 as SaMat4};
use shadow_aliasing::maps::{ClipDepth, WarpRule};
use shadow_aliasing::measure::{frustum_max, ShadowMap};
use shadow_aliasing_bevy::{
    budget_path, Budget, BudgetState, CascadeErrors, CascadeMode, CascadeSource, ErrorLens,
    ErrorLensMaps, Fit, Replace, ReplacedCascades, SceneBounds, ShadowAliasingPlugin,
    ShadowAliasingSettings, Splits, ViewCascadeErrors,
};

const ASPECT: f32 = 16.0 / 9.0;

/// A headless app with the scene's boxes (or `boxes` given), one camera and the sun.
fn app(mode: Option<CascadeMode>, boxes: &[scene::SceneBox]) -> (App, Entity, Entity) {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin, ShadowAliasingPlugin))
        .init_resource::<DirectionalLightShadowMap>()
        .add_systems(
            PostUpdate,
            build_directional_light_cascades
                .in_set(SimulationLightSystems::UpdateDirectionalLightCascades)
                .after(TransformSystems::Propagate),
        );
    let world = app.world_mut();
    let camera = world
        .spawn((
            Camera::default(),
            Projection::Perspective(PerspectiveProjection {
                fov: FOV,
                aspect_ratio: ASPECT,
                near: NEAR,
                far: FAR,
                ..default()
            }),
            camera_transform(),
        ))
        .id();
    for bx in boxes {
        let (c, size) = centre_size(bx);
        let mut e = world.spawn((
            Mesh3d::default(),
            Aabb::from_min_max(-0.5 * size, 0.5 * size),
            Transform::from_translation(c),
        ));
        if bx.pole {
            e.insert(NotShadowReceiver);
        }
    }
    let mut light = world.spawn((
        DirectionalLight {
            shadow_maps_enabled: true,
            ..default()
        },
        sun_transform(),
    ));
    if let Some(m) = mode {
        light.insert(m);
    }
    let light = light.id();
    app.update();
    (app, camera, light)
}

fn errors(app: &App, light: Entity, camera: Entity) -> ViewCascadeErrors {
    app.world().get::<CascadeErrors>(light).unwrap().views[&camera].clone()
}

/// The camera's world → eye (from its `GlobalTransform` as Bevy holds it), the crate's view
/// frustum from the scene's constants, and the sun's direction (its `GlobalTransform`'s forward).
fn eye(app: &App, camera: Entity, light: Entity) -> (DMat4, ViewFrustum, DVec3) {
    let t = app
        .world()
        .get::<GlobalTransform>(camera)
        .unwrap()
        .to_matrix();
    let to_world = SaMat4::from_cols_array_2d(&t.to_cols_array_2d()).as_dmat4();
    let view = ViewFrustum::with_aspect(
        f64::from(NEAR),
        f64::from(FAR),
        0.5 * f64::from(FOV),
        f64::from(ASPECT),
    )
    .unwrap();
    let sun = app.world().get::<GlobalTransform>(light).unwrap().forward();
    (
        to_world.inverse(),
        view,
        DVec3::from_array(sun.as_dvec3().to_array()),
    )
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn measure_mode_publishes_the_crates_measurement_of_bevys_cascades() {
    // Receivers: one box holding every Bevy cascade's slice, so that B is the slice itself and
    // its corners are the frustum's at the slice's depths.
    let all = [scene::SceneBox {
        min: [-1000.0; 3],
        max: [1000.0; 3],
        pole: false,
    }];
    let (app, camera, light) = app(None, &all);
    let got = errors(&app, light, camera);
    assert_eq!(got.source, CascadeSource::Bevy);
    assert_eq!(got.error, None);
    assert_eq!((got.map_resolution, got.image_height), (2048, 1080));
    let cascades = &app.world().get::<Cascades>(light).unwrap().cascades[&camera];
    assert_eq!(cascades.len(), 4);
    assert_eq!(got.cascades.len(), 4);
    // Bevy's defaults by hand (CascadeShadowConfigBuilder::default): far bounds 10·15^(i/3),
    // cascade 0 from 0.1, cascade i from 0.8 × the previous far bound.
    let far: Vec<f64> = (0..4).map(|i| 10.0 * 15f64.powf(i as f64 / 3.0)).collect();
    let near = [0.1, 0.8 * far[0], 0.8 * far[1], 0.8 * far[2]];
    let (world_to_eye, view, sun) = eye(&app, camera, light);
    let l_eye = world_to_eye.transform_vector3(sun).normalize();
    for (i, (c, e)) in cascades.iter().zip(&got.cascades).enumerate() {
        let e = e.expect("every slice holds receivers");
        assert!(
            rel(e.cover.0, near[i]) < 1e-6 && rel(e.cover.1, far[i]) < 1e-6,
            "{i}: {:?} vs [{}, {}]",
            e.cover,
            near[i],
            far[i]
        );
        let m = SaMat4::from_cols_array_2d(&c.clip_from_world.to_cols_array_2d()).as_dmat4()
            * world_to_eye.inverse();
        let slice = view.with_depth_range(e.cover.0, e.cover.1).unwrap();
        let want = frustum_max(&slice, &ShadowMap::new(m, l_eye).unwrap()).unwrap();
        assert!(
            rel(e.max_mx, want.max_mx) < 1e-9,
            "{i}: {} {}",
            e.max_mx,
            want.max_mx
        );
        assert!(
            rel(e.max_mz, want.max_mz) < 1e-9,
            "{i}: {} {}",
            e.max_mz,
            want.max_mz
        );
        assert!(rel(e.storage_factor, want.storage_factor) < 1e-9);
        let px = want.max_mx.max(want.max_mz) * 1080.0 / 2048.0;
        assert!(rel(e.max_error_pixels, px) < 1e-9);
        assert_eq!(e.texel_size, c.texel_size);
    }
}

#[test]
fn receivers_and_casters_honour_the_markers() {
    let (mut app, camera, light) = app(None, &BOXES);
    let b = app.world().resource::<SceneBounds>().clone();
    // The pole is NotShadowReceiver: 6 receivers, 7 casters.
    assert_eq!((b.receivers.len(), b.casters.len()), (6, 7));
    let before = errors(&app, light, camera);
    // A huge box that neither receives nor casts changes nothing.
    app.world_mut().spawn((
        Mesh3d::default(),
        Aabb::from_min_max(Vec3::splat(-500.0), Vec3::splat(500.0)),
        Transform::default(),
        NotShadowReceiver,
        NotShadowCaster,
    ));
    app.update();
    let b = app.world().resource::<SceneBounds>().clone();
    assert_eq!((b.receivers.len(), b.casters.len()), (6, 7));
    assert_eq!(errors(&app, light, camera), before);
    // The same box as a receiver grows B to the whole slices: the error can only grow.
    app.world_mut().spawn((
        Mesh3d::default(),
        Aabb::from_min_max(Vec3::splat(-500.0), Vec3::splat(500.0)),
        Transform::default(),
    ));
    app.update();
    let after = errors(&app, light, camera);
    let (a, b) = (
        after.max_error_pixels().unwrap(),
        before.max_error_pixels().unwrap(),
    );
    assert!(a > b, "{a} {b}");
}

/// The frame API called here with the scene's boxes, as replace mode must call it.
fn crate_frame(
    app: &App,
    camera: Entity,
    light: Entity,
    scheme: FrameScheme<'_>,
) -> sa_frame::Frame {
    let (world_to_eye, _, sun) = eye(app, camera, light);
    let boxes: Vec<_> = BOXES
        .iter()
        .map(|b| sa_frame::Aabb::new(b.min, b.max).unwrap())
        .collect();
    let receivers: Vec<_> = BOXES
        .iter()
        .zip(&boxes)
        .filter(|(b, _)| !b.pole)
        .map(|(_, a)| *a)
        .collect();
    let cam = sa_frame::Camera::new(
        world_to_eye,
        f64::from(NEAR),
        f64::from(FAR),
        0.5 * f64::from(FOV),
        f64::from(ASPECT),
    )
    .unwrap();
    let input = FrameInput::new(cam, sun, 2048, 1080)
        .receivers(Bound::Boxes(&receivers))
        .casters(Bound::Boxes(&boxes))
        .scheme(scheme);
    sa_frame::frame(&input).unwrap()
}

/// Bevy's default splits, from the `f32` values its default configuration holds (its last far
/// bound is `10 · (15^⅓)³` in `f32`, not exactly 150).
fn bevy_default_splits() -> CascadeSplits<'static> {
    let c = CascadeShadowConfig::default();
    CascadeSplits::Bevy {
        k: 4,
        minimum_distance: f64::from(c.minimum_distance),
        maximum_distance: f64::from(c.bounds[3]),
        first_far_bound: f64::from(c.bounds[0]),
        overlap_proportion: f64::from(c.overlap_proportion),
    }
}

#[test]
fn replace_mode_writes_the_frame_apis_cascades_and_measures_them() {
    let mode = CascadeMode::Replace(Replace::default());
    let (app, camera, light) = app(Some(mode), &BOXES);
    let f = crate_frame(
        &app,
        camera,
        light,
        FrameScheme::Cascades {
            splits: bevy_default_splits(),
            rule: WarpRule::Uniform,
        },
    );
    let cascades = &app.world().get::<Cascades>(light).unwrap().cascades[&camera];
    let config = app.world().get::<CascadeShadowConfig>(light).unwrap();
    let state = app.world().get::<ReplacedCascades>(light).unwrap();
    assert!(state.errors.is_empty(), "{:?}", state.errors);
    assert_eq!(cascades.len(), f.len());
    assert_eq!(config.bounds.len(), f.len());
    assert_eq!(config.overlap_proportion, 0.2);
    let got = errors(&app, light, camera);
    assert_eq!(got.source, CascadeSource::ShadowAliasing);
    for ((c, map), (bound, e)) in cascades
        .iter()
        .zip(f.maps().iter())
        .zip(config.bounds.iter().zip(&got.cascades))
    {
        assert_eq!(
            c.clip_from_world.to_cols_array_2d(),
            map.world_to_clip_cols(ClipDepth::Reversed)
        );
        assert_eq!(c.texel_size, map.texel_world as f32);
        assert_eq!(*bound, map.split.1 as f32);
        // Measured from Bevy's f32 matrix over the map's own body: the frame's own figures
        // to f32 rounding.
        let (e, want) = (e.unwrap(), map.error().unwrap());
        assert!(
            rel(e.max_mx, want.max_mx) < 1e-5,
            "{} {}",
            e.max_mx,
            want.max_mx
        );
        assert!(
            rel(e.max_mz, want.max_mz) < 1e-5,
            "{} {}",
            e.max_mz,
            want.max_mz
        );
        assert!(rel(e.max_error_pixels, want.max_error_pixels) < 1e-5);
    }
}

#[test]
fn replaced_cascades_measure_below_bevys_and_measure_mode_restores_bevys() {
    let (bevy_app, camera, light) = app(None, &BOXES);
    let bevy_e = errors(&bevy_app, light, camera);
    let bevy = bevy_e.max_error_pixels().unwrap();
    let per: Vec<_> = bevy_e
        .cascades
        .iter()
        .map(|c| c.map(|c| (c.max_error_pixels, c.cover)))
        .collect();
    println!("Bevy: {per:?}");
    let bevy_cascades = bevy_app.world().get::<Cascades>(light).unwrap().cascades[&camera].clone();
    for (fit, splits) in [
        (Fit::Focused(WarpRule::Uniform), Splits::Bevy),
        (Fit::Stable, Splits::Bevy),
        (Fit::Focused(WarpRule::Uniform), Splits::EqualError { k: 4 }),
        (Fit::Focused(WarpRule::Lispsm), Splits::EqualError { k: 4 }),
    ] {
        let mode = CascadeMode::Replace(Replace {
            fit,
            splits,
            depth_range: None,
        });
        let (mut app, camera, light) = app(Some(mode), &BOXES);
        let e = errors(&app, light, camera);
        let ours = e.max_error_pixels().unwrap();
        let per: Vec<_> = e
            .cascades
            .iter()
            .map(|c| c.map(|c| (c.max_error_pixels, c.cover)))
            .collect();
        println!("{fit:?} {splits:?}: {ours:.4} px, Bevy's {bevy:.4} px: {per:?}");
        // Stable cascades cover the slice's bounding sphere (no focusing), as Bevy's cover the
        // slice's diagonal: not below Bevy's, within a few per cent of it.
        if fit == Fit::Stable {
            assert!(
                ours < 1.05 * bevy,
                "{fit:?} {splits:?}: {ours} vs Bevy's {bevy}"
            );
        } else {
            assert!(ours < bevy, "{fit:?} {splits:?}: {ours} vs Bevy's {bevy}");
        }
        // Back to measure mode: Bevy's configuration and cascades again.
        *app.world_mut().get_mut::<CascadeMode>(light).unwrap() = CascadeMode::Measure;
        app.update();
        let config = app.world().get::<CascadeShadowConfig>(light).unwrap();
        assert_eq!(config.bounds, CascadeShadowConfig::default().bounds);
        assert_eq!(config.overlap_proportion, 0.2);
        let back = errors(&app, light, camera);
        assert_eq!(back.source, CascadeSource::Bevy);
        let cascades = &app.world().get::<Cascades>(light).unwrap().cascades[&camera];
        for (a, b) in cascades.iter().zip(&bevy_cascades) {
            assert_eq!(a.clip_from_world, b.clip_from_world);
        }
        assert_eq!(back.max_error_pixels().unwrap(), bevy);
    }
}

#[test]
fn too_many_cascades_is_an_error_and_keeps_bevys() {
    let (bevy_app, camera, light) = app(None, &BOXES);
    let want = bevy_app.world().get::<Cascades>(light).unwrap().cascades[&camera].clone();
    let mode = CascadeMode::Replace(Replace {
        splits: Splits::EqualError { k: 5 },
        ..default()
    });
    let (app, camera, light) = app(Some(mode), &BOXES);
    let state = app.world().get::<ReplacedCascades>(light).unwrap();
    let e = &state.errors[&camera];
    assert!(
        e.contains("k must be in 1..=4") && e.contains("got 5"),
        "{e}"
    );
    let got = &app.world().get::<Cascades>(light).unwrap().cascades[&camera];
    assert_eq!(got.len(), want.len());
    for (a, b) in got.iter().zip(&want) {
        assert_eq!(a.clip_from_world, b.clip_from_world);
    }
    assert_eq!(errors(&app, light, camera).source, CascadeSource::Bevy);
}

#[test]
fn world_box_of_a_rotated_scaled_mesh() {
    // Half extents (1, 2, 3) turned 90° about Y and scaled by 2: (6, 4, 2) about (5, 0, 0).
    let t = GlobalTransform::from(
        Transform::from_xyz(5.0, 0.0, 0.0)
            .with_rotation(Quat::from_rotation_y(std::f32::consts::FRAC_PI_2))
            .with_scale(Vec3::splat(2.0)),
    );
    let aabb = Aabb::from_min_max(Vec3::new(-1.0, -2.0, -3.0), Vec3::new(1.0, 2.0, 3.0));
    let w = shadow_aliasing_bevy::world_box(&aabb, &t).unwrap();
    let want_min = DVec3::new(-1.0, -4.0, -2.0);
    let want_max = DVec3::new(11.0, 4.0, 2.0);
    assert!((w.min - want_min).abs().max_element() < 1e-5, "{}", w.min);
    assert!((w.max - want_max).abs().max_element() < 1e-5, "{}", w.max);
}

#[test]
fn automatic_bias_is_the_texel_diagonal_bevy_needs_and_the_user_gets_theirs_back() {
    // Derived here from the matrices Bevy holds: for an orthographic cascade (w = 1, depth along
    // the light) a lit plane stays lit for every texel a PCF kernel of radius r reads when the
    // lookup point is lifted by (r + ½) texel diagonals, the diagonal of the texel's world
    // edges E_s, E_t in the plane perpendicular to the light (r₀ · E_s = 2/res, r₁ · E_s = 0,
    // L · E_s = 0, and likewise E_t). Bevy moves the point by shadow_normal_bias · √2 ·
    // texel_size, so each cascade needs (r + ½) · |diagonal| / (√2 · texel_size).
    let (mut app, camera, light) = app(None, &BOXES);
    {
        let mut l = app.world_mut().get_mut::<DirectionalLight>(light).unwrap();
        l.shadow_normal_bias = 0.7;
        l.shadow_depth_bias = 0.05;
    }
    let user = |app: &App| {
        let l = app.world().get::<DirectionalLight>(light).unwrap();
        (l.shadow_depth_bias, l.shadow_normal_bias)
    };
    let mode = CascadeMode::Replace(Replace {
        fit: Fit::Focused(WarpRule::Uniform),
        splits: Splits::EqualError { k: 4 },
        depth_range: None,
    });
    // No filter component: Bevy's default, Gaussian (r = 2½); then the 2 × 2 hardware filter.
    for (filter, r) in [(None, 2.5), (Some(ShadowFilteringMethod::Hardware2x2), 0.5)] {
        if let Some(f) = filter {
            app.world_mut().entity_mut(camera).insert(f);
        }
        app.world_mut().entity_mut(light).insert(mode.clone());
        app.update();
        let w = app.world();
        let res = w.resource::<DirectionalLightShadowMap>().size as f64;
        let fwd = w.get::<GlobalTransform>(light).unwrap().forward();
        let l = DVec3::from_array(fwd.as_dvec3().to_array()).normalize();
        let mut want = Vec::new();
        for c in &w.get::<Cascades>(light).unwrap().cascades[&camera] {
            let m = SaMat4::from_cols_array_2d(&c.clip_from_world.to_cols_array_2d()).as_dmat4();
            let row = |i: usize| m.row(i).truncate();
            assert!(
                row(2).normalize().cross(l).length() < 1e-5,
                "depth along the light"
            );
            assert!(m.row(3).abs_diff_eq(shadow_aliasing::glam::DVec4::W, 1e-12));
            let es = row(1).cross(l) / row(0).dot(row(1).cross(l));
            let et = l.cross(row(0)) / row(1).dot(l.cross(row(0)));
            let diag = (es + et).length().max((es - et).length());
            let offset = (r + 0.5) * 2.0 / res * diag;
            want.push(offset / (std::f64::consts::SQRT_2 * f64::from(c.texel_size)));
        }
        assert_eq!(want.len(), 4);
        let state = w.get::<ReplacedCascades>(light).unwrap();
        let applied = state.bias.clone().unwrap().unwrap();
        assert_eq!(applied.pcf_radius, r);
        for (got, want) in applied.needed.iter().zip(&want) {
            assert!(rel(f64::from(*got), *want) < 1e-4, "{got} {want}");
        }
        let most = want.iter().copied().fold(0.0, f64::max);
        let (depth, normal) = user(&app);
        assert!(rel(f64::from(normal), most) < 1e-4, "{normal} {most}");
        assert_eq!(depth, 0.0);
    }
    // Opting out gives the user's bias back; so does the return to measure mode.
    app.world_mut()
        .resource_mut::<ShadowAliasingSettings>()
        .auto_bias = false;
    app.update();
    assert_eq!(user(&app), (0.05, 0.7));
    assert!(app
        .world()
        .get::<ReplacedCascades>(light)
        .unwrap()
        .bias
        .is_none());
    app.world_mut()
        .resource_mut::<ShadowAliasingSettings>()
        .auto_bias = true;
    app.update();
    assert_ne!(user(&app), (0.05, 0.7));
    *app.world_mut().get_mut::<CascadeMode>(light).unwrap() = CascadeMode::Measure;
    app.update();
    assert_eq!(user(&app), (0.05, 0.7));
    // Temporal filtering: not derived, the user's bias kept, the reason recorded.
    app.world_mut()
        .entity_mut(camera)
        .insert(ShadowFilteringMethod::Temporal);
    app.world_mut().entity_mut(light).insert(mode);
    app.update();
    assert_eq!(user(&app), (0.05, 0.7));
    let state = app.world().get::<ReplacedCascades>(light).unwrap();
    let e = state.bias.clone().unwrap().unwrap_err();
    assert!(e.contains("Temporal"), "{e}");
}

#[test]
fn budget_lights_share_the_largest_map_size_and_the_app_size_comes_back() {
    let budget = |target| {
        CascadeMode::Budget(Budget {
            max_map_size: Some(8192),
            ..Budget::new(target)
        })
    };
    // The strict light alone: the size it chooses.
    let (mut alone, _, _) = app(Some(budget(1.0)), &BOXES);
    alone.update();
    let strict_size = alone.world().resource::<DirectionalLightShadowMap>().size;
    // With a lax second light (another sun), which alone would take a smaller map.
    let (mut lax_alone, _, lax_light) = app(Some(budget(8.0)), &BOXES);
    let other_sun = Transform::default().looking_to(Vec3::new(-0.4, -0.7, -0.5), Vec3::Y);
    *lax_alone
        .world_mut()
        .get_mut::<Transform>(lax_light)
        .unwrap() = other_sun;
    lax_alone.update();
    lax_alone.update();
    let lax_size = lax_alone
        .world()
        .resource::<DirectionalLightShadowMap>()
        .size;
    assert!(lax_size < strict_size, "{lax_size} {strict_size}");
    let (mut app, camera, strict) = app(Some(budget(1.0)), &BOXES);
    let lax = app
        .world_mut()
        .spawn((
            DirectionalLight {
                shadow_maps_enabled: true,
                ..default()
            },
            other_sun,
            budget(8.0),
        ))
        .id();
    app.update();
    app.update();
    let size = app.world().resource::<DirectionalLightShadowMap>().size;
    assert_eq!(size, strict_size, "the largest chosen");
    for (light, target) in [(strict, 1.0), (lax, 8.0)] {
        let s = app.world().get::<BudgetState>(light).unwrap();
        let c = s.choice.unwrap_or_else(|| panic!("{:?}", s.error));
        assert_eq!(c.resolution as usize, size);
        assert_eq!(c.texels, c.cascades as u64 * (size * size) as u64);
        // The lax light's maps were built again at the shared size: its reported error is the
        // measurement of what Bevy holds, and within its target.
        let measured = errors(&app, light, camera).max_error_pixels().unwrap();
        assert!(rel(measured, c.max_error_pixels) < 1e-3, "{measured} {c:?}");
        assert!(c.meets_target && measured <= target * (1.0 + 1e-3), "{c:?}");
    }
    // The diagnostics: the shared size, and the larger of the two lights' errors.
    let store = app.world().resource::<DiagnosticsStore>();
    let value = |f: &str| store.get(&budget_path(f)).and_then(|d| d.value()).unwrap();
    assert_eq!(value("resolution"), size as f64);
    let worst = [strict, lax]
        .map(|l| {
            let s = app.world().get::<BudgetState>(l).unwrap();
            s.choice.unwrap().max_error_pixels
        })
        .into_iter()
        .fold(0.0, f64::max);
    assert_eq!(value("max_error_pixels"), worst);
    assert_eq!(value("meets_target"), 1.0);
    let most = [strict, lax]
        .map(|l| {
            app.world()
                .get::<BudgetState>(l)
                .unwrap()
                .choice
                .unwrap()
                .cascades
        })
        .into_iter()
        .max()
        .unwrap();
    assert_eq!(value("cascades"), most as f64);
    for light in [strict, lax] {
        *app.world_mut().get_mut::<CascadeMode>(light).unwrap() = CascadeMode::Measure;
    }
    app.update();
    assert_eq!(
        app.world().resource::<DirectionalLightShadowMap>().size,
        DirectionalLightShadowMap::default().size,
        "the app's size back"
    );
    assert!(app
        .world()
        .get::<BudgetState>(strict)
        .unwrap()
        .choice
        .is_none());
}

#[test]
fn a_bad_budget_is_refused_by_name_and_keeps_bevys_cascades() {
    for (budget, named) in [
        (Budget::new(-1.0), "max_error"),
        (Budget::new(f64::NAN), "max_error"),
        (
            Budget {
                margin: 1.5,
                ..Budget::new(1.0)
            },
            "margin",
        ),
        (
            Budget {
                max_map_size: Some(3000),
                ..Budget::new(1.0)
            },
            "max_map_size",
        ),
    ] {
        let (app, camera, light) = app(Some(CascadeMode::Budget(budget)), &BOXES);
        let s = app.world().get::<BudgetState>(light).unwrap();
        let e = s
            .error
            .clone()
            .unwrap_or_else(|| panic!("{budget:?} accepted"));
        assert!(e.contains(named), "{budget:?}: {e}");
        assert!(s.choice.is_none());
        assert_eq!(errors(&app, light, camera).source, CascadeSource::Bevy);
        assert_eq!(
            app.world().resource::<DirectionalLightShadowMap>().size,
            DirectionalLightShadowMap::default().size
        );
    }
}

/// The error lens's records are the cascades Bevy holds, in measure and replace mode: Bevy's
/// matrices bit for bit, the far bounds Bevy's shader picks by, reversed depth, the map size,
/// Bevy's texel size and measure mode's figures; the uniform block is laid out by WGSL's uniform
/// rules (four 144-byte records at a stride of 144, then the light's `vec3` on a multiple of 16,
/// the count, the opacity and the legend flag, the struct rounded up to 16 bytes); removing the
/// lens removes the records.
#[test]
fn the_error_lens_records_the_cascades_bevy_holds() {
    let replace = CascadeMode::Replace(Replace {
        fit: Fit::Focused(WarpRule::Uniform),
        splits: Splits::EqualError { k: 4 },
        depth_range: None,
    });
    for mode in [None, Some(replace)] {
        let (mut app, camera, light) = app(mode, &BOXES);
        app.world_mut()
            .entity_mut(camera)
            .insert(ErrorLens::default());
        app.update();
        let w = app.world();
        let maps = w.get::<ErrorLensMaps>(camera).unwrap();
        let cascades = &w.get::<Cascades>(light).unwrap().cascades[&camera];
        let config = w.get::<CascadeShadowConfig>(light).unwrap();
        let size = w.resource::<DirectionalLightShadowMap>().size;
        let measured = errors(&app, light, camera);
        assert_eq!(maps.light, Some(light));
        assert_eq!(maps.maps.len(), 4);
        assert_eq!(cascades.len(), 4);
        for (i, m) in maps.maps.iter().enumerate() {
            assert_eq!(
                m.world_to_clip,
                cascades[i].clip_from_world.to_cols_array_2d()
            );
            assert_eq!(m.split[1], config.bounds[i]);
            assert_eq!(m.clip_depth, 2, "reversed depth");
            assert_eq!(m.resolution as usize, size);
            assert_eq!(m.texel_world, cascades[i].texel_size);
            let e = measured.cascades[i].expect("every cascade measured");
            assert_eq!(m.max_error_pixels, e.max_error_pixels as f32);
        }
        let bytes = maps.uniform_bytes();
        let word = |at: usize| u32::from_le_bytes(bytes[at..at + 4].try_into().unwrap());
        assert_eq!(bytes.len(), 608);
        assert_eq!(&bytes[144..208], &maps.maps[1].to_bytes()[..64]);
        let sun = scene::sun_dir().normalize();
        for (k, v) in [sun.x, sun.y, sun.z].into_iter().enumerate() {
            assert!((f32::from_bits(word(576 + 4 * k)) - v).abs() < 1e-6);
        }
        assert_eq!(word(588), 4);
        assert_eq!(f32::from_bits(word(592)), 0.7);
        assert_eq!(word(596), 1);
        app.world_mut().entity_mut(camera).remove::<ErrorLens>();
        app.update();
        assert!(app.world().get::<ErrorLensMaps>(camera).is_none());
    }
    // An opacity outside [0, 1] is the nearer end, NaN 0 (the scene alone).
    let opacity = |o: f32| {
        let b = ErrorLensMaps {
            opacity: o,
            ..default()
        }
        .uniform_bytes();
        f32::from_bits(u32::from_le_bytes(b[592..596].try_into().unwrap()))
    };
    assert_eq!(
        [
            opacity(f32::NAN),
            opacity(-1.0),
            opacity(2.0),
            opacity(0.25)
        ],
        [0.0, 0.0, 1.0, 0.25]
    );
}
