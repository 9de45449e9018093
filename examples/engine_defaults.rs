//! The engines' default directional shadows against the planner, on the same scenes (issue 24
//! item 5, issue 31 item 9; the table in docs/planning.md, "The engines' defaults against the
//! plan").
//!
//! Each engine's own matrices come from the faithful ports of `benches/reference/` and are
//! measured with the crate's exact measurement (`measure::vertex::vertex_max`, the kernel the
//! frame's own `max_error_pixels` uses) over the focus body B of the slice each map serves, 1080
//! pixels high, at the resolution the engine's map spans:
//!
//! - Bevy 0.19 (`bevy_cascade.rs`): `CascadeShadowConfigBuilder::default()` (4 cascades, minimum
//!   distance 0.1, first far bound 10, maximum distance 150, overlap proportion 0.2) with
//!   `DirectionalLightShadowMap`'s 2048² texels: `calculate_cascade`'s square, the larger
//!   diagonal of the slice rounded up, over 2048 texels;
//! - Filament (`filament_directional.rs`): `ShadowOptions` defaults, one cascade, `mapSize` 1024
//!   with LiSPSM: `updateCascadeShadowMaps`' map, whose clip square spans the 1022² texels inside
//!   the one-texel border (1024² allocated);
//! - three.js `CSM` (`threejs_csm.rs`): 3 cascades, `practical` breaks, 2048² each: each square
//!   the larger of the slice's far-plane and body diagonals; all three maps are rendered, the
//!   slices beyond B hold nothing of it;
//! - Unreal 5 virtual shadow maps (no port: the crate's clipmap model): `ClipmapOptions::UNREAL`
//!   (levels 6–22, LOD bias −0.5, 16 384² virtual levels of 128² pages); its texels are the pages
//!   its levels' footprints touch (`plan::clipmap`), 128² each.
//!
//! Beside each engine's error the table prints the crate's model of it, built by the frame API
//! (`FrameScheme::Stable` with `CascadeSplits::Bevy` or three.js's split distances: a square
//! around each slice's bounding sphere plus a texel; `WarpRule::Filament` on a 1024² map). Then
//! the planner gives the fewest texels that reach the engine's error, and the error that the
//! engine's texels (at most 4 maps) reach. Run with
//! `cargo run --release --example engine_defaults`.

#[allow(dead_code)]
#[path = "../benches/reference/bevy_cascade.rs"]
mod bevy_cascade;
#[allow(dead_code)]
#[path = "../benches/reference/filament_directional.rs"]
mod filament_directional;
#[allow(dead_code)]
#[path = "../benches/reference/threejs_csm.rs"]
mod threejs_csm;

use glam::{DMat4, DVec3};
use shadow_aliasing::frame::{
    frame, Aabb, Bound, Camera, CascadeSplits, ClipmapOptions, Frame, FrameInput, FrameScheme,
};
use shadow_aliasing::maps::WarpRule;
use shadow_aliasing::measure::vertex::vertex_max;
use shadow_aliasing::plan::allocate::Rounding;
use shadow_aliasing::plan::candidates::label;
use shadow_aliasing::plan::clipmap::plan_clipmap;
use shadow_aliasing::plan::{plan, Goal};
use shadow_aliasing::{Error, Result};

const IMAGE_HEIGHT: u32 = 1080;
/// Bevy's default projection: 45° vertical field of view, near 0.1, far 1000, 16:9.
const FOV_DEG: f64 = 45.0;
const ASPECT: f64 = 16.0 / 9.0;
const NEAR: f64 = 0.1;
const FAR: f64 = 1000.0;

/// What one engine's default costs and its largest error over B.
struct Row {
    name: &'static str,
    maps: usize,
    texels: u64,
    /// The engine's own matrices, measured.
    error: f64,
    /// The crate's model of the engine (the frame API), measured.
    model: f64,
}

/// The largest error (pixels) of a world → light clip matrix over the focus body `body` (eye
/// space) of the frame's camera, with `texels` texels across the matrix's clip square.
fn engine_error(
    world_to_clip: DMat4,
    view: DMat4,
    light: DVec3,
    body: &[DVec3],
    texels: f64,
) -> Result<f64> {
    let eye_to_clip = world_to_clip * view.inverse();
    let l = view.transform_vector3(light).normalize();
    let tan = (FOV_DEG / 2.0).to_radians().tan();
    let e = vertex_max(&eye_to_clip, l, tan, body)
        .ok_or_else(|| Error::Degenerate("an engine's map cannot be measured over B".into()))?;
    // Every vertex of B inside the map's clip square: the engine's map holds the body.
    for p in body {
        let h = eye_to_clip * p.extend(1.0);
        if h.w <= 0.0 || (h.x / h.w).abs() > 1.0 + 1e-6 || (h.y / h.w).abs() > 1.0 + 1e-6 {
            return Err(Error::Degenerate(format!(
                "B's vertex {p} is outside an engine's map"
            )));
        }
    }
    Ok(e.max_mx.max(e.max_mz) * f64::from(IMAGE_HEIGHT) / texels)
}

/// The largest error of `f`'s maps (the crate's measurement of its own matrices).
fn model_error(f: &Frame) -> f64 {
    f.maps()
        .iter()
        .map(|m| m.max_error_pixels)
        .fold(0.0, f64::max)
}

/// The frame map whose selection range ends nearest `far` (each engine map is measured over the
/// body of the crate's map for the same slice).
fn body_ending_at(f: &Frame, far: f64) -> Option<&[DVec3]> {
    f.maps()
        .iter()
        .filter(|m| (m.split.1 - far).abs() < 1e-6 * far)
        .map(|m| m.body())
        .next()
}

fn engines(input: &FrameInput<'_>, view: DMat4, light: DVec3, boxes: &[Aabb]) -> Result<[Row; 3]> {
    // Bevy: 4 cascades of 2048², the builder's far bounds.
    let bevy_bounds = bevy_cascade::calculate_cascade_bounds(4, 10.0, 150.0);
    let bevy_model = frame(&input.scheme(FrameScheme::Stable(CascadeSplits::Bevy {
        k: 4,
        minimum_distance: 0.1,
        maximum_distance: 150.0,
        first_far_bound: 10.0,
        overlap_proportion: 0.2,
    })))?;
    let config = bevy_cascade::CascadeShadowConfig {
        bounds: bevy_bounds,
        count: 4,
        overlap_proportion: 0.2,
        minimum_distance: 0.1,
    };
    let projection = bevy_cascade::PerspectiveProjection {
        fov: FOV_DEG.to_radians() as f32,
        aspect_ratio: ASPECT as f32,
    };
    let mut cascades = [bevy_cascade::Cascade::default(); 4];
    bevy_cascade::build_directional_light_cascades(
        bevy_cascade::light_rotation_looking_to(light.as_vec3()),
        view.inverse().as_mat4(),
        &projection,
        &config,
        2048,
        &mut cascades,
    );
    let mut bevy = 0.0f64;
    for (c, far) in cascades.iter().zip(bevy_bounds) {
        if let Some(body) = body_ending_at(&bevy_model, f64::from(far)) {
            bevy = bevy.max(engine_error(
                c.clip_from_world.as_dmat4(),
                view,
                light,
                body,
                2048.0,
            )?);
        }
    }

    // Filament: one LiSPSM map of 1024² (1022² inside the border).
    use filament_directional as fl;
    // The model on Filament's own 1024² map (the caller's input is Bevy's and three.js's 2048²).
    let mut filament_input = input.scheme(FrameScheme::Single(WarpRule::Filament));
    filament_input.map_resolution = 1024;
    let filament_model = frame(&filament_input)?;
    let camera = fl::CameraInfo::perspective(
        view.inverse().as_mat4(),
        FOV_DEG as f32,
        ASPECT as f32,
        NEAR as f32,
        FAR as f32,
    );
    let renderables: Vec<fl::Renderable> = boxes
        .iter()
        .enumerate()
        .map(|(i, b)| fl::Renderable {
            aabb: fl::Aabb {
                min: b.min.as_vec3(),
                max: b.max.as_vec3(),
            },
            cast_shadows: true,
            receive_shadows: i == 0,
        })
        .collect();
    let mut maps = [None; 4];
    fl::update_cascade_shadow_maps(
        light.as_vec3().normalize(),
        &camera,
        &fl::ShadowOptions::default(),
        &fl::ShadowMapInfo::new(1024),
        &renderables,
        &[],
        true,
        false,
        &mut maps,
    );
    let map = maps[0].ok_or_else(|| Error::Degenerate("Filament built no map".into()))?;
    let body = filament_model
        .maps()
        .iter()
        .next()
        .map(|m| m.body())
        .unwrap_or(&[]);
    let filament = engine_error(map.s.as_dmat4(), view, light, body, 1022.0)?;

    // three.js: 3 cascades of 2048² at its own break depths.
    use threejs_csm as tj;
    let camera = tj::PerspectiveCamera {
        fov: FOV_DEG,
        aspect: ASPECT,
        near: NEAR,
        far: FAR,
        matrix_world: view.inverse(),
    };
    let options = tj::CsmOptions::default();
    let mut csm = [tj::Cascade::default(); tj::MAX_CASCADES];
    tj::update(&camera, light, &options, &mut csm);
    let planes: Vec<f64> = std::iter::once(csm[0].depths.0)
        .chain(csm[..options.cascades].iter().map(|c| c.depths.1))
        .collect();
    let three_model = frame(&input.scheme(FrameScheme::Stable(CascadeSplits::Distances {
        planes: &planes,
        overlap: 0.0,
    })))?;
    let mut three = 0.0f64;
    for c in &csm[..options.cascades] {
        if let Some(body) = body_ending_at(&three_model, c.depths.1) {
            three = three.max(engine_error(c.clip_from_world, view, light, body, 2048.0)?);
        }
    }
    Ok([
        Row {
            name: "Bevy 0.19 (4 cascades, 2048²)",
            maps: 4,
            texels: 4 * 2048 * 2048,
            error: bevy,
            model: model_error(&bevy_model),
        },
        Row {
            name: "Filament (1 LiSPSM map, 1024²)",
            maps: 1,
            texels: 1024 * 1024,
            error: filament,
            model: model_error(&filament_model),
        },
        Row {
            name: "three.js CSM (3 cascades, 2048²)",
            maps: options.cascades,
            texels: options.cascades as u64 * 2048 * 2048,
            error: three,
            model: model_error(&three_model),
        },
    ])
}

fn main() -> Result<()> {
    // A camera 1.8 m above a 300 m × 150 m ground with a few buildings and a pole, looking
    // slightly down; Bevy's default projection, 16:9. The ground receives (the receivers' bound
    // must not hold the camera, or B reaches the near plane at 0.1 and every error is set there);
    // everything casts.
    let eye = DVec3::new(0.0, 1.8, 0.0);
    let view = glam::dcamera::rh::view::look_at_mat4(eye, DVec3::new(0.0, 0.0, -60.0), DVec3::Y);
    let camera = Camera::new(view, NEAR, FAR, (FOV_DEG / 2.0).to_radians(), ASPECT)?;
    let ground = Aabb::new(
        DVec3::new(-150.0, -1.0, -145.0),
        DVec3::new(150.0, 0.0, 5.0),
    )?;
    let boxes = [
        ground,
        Aabb::new(DVec3::new(-12.0, 0.0, -40.0), DVec3::new(-4.0, 15.0, -30.0))?,
        Aabb::new(DVec3::new(6.0, 0.0, -90.0), DVec3::new(20.0, 30.0, -70.0))?,
        Aabb::new(DVec3::new(-0.2, 0.0, -12.0), DVec3::new(0.2, 8.0, -11.6))?,
    ];
    println!(
        "| sun elevation | engine default | maps | texels | max error (px) | the crate's model of it (px) | plan: texels for that error | plan: error with those texels (≤ 4 maps) |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    for elevation in [20.0f64, 45.0, 70.0] {
        // The sun 30° to the side of the view direction, travelling down at `elevation`.
        let (e, a) = (elevation.to_radians(), 30f64.to_radians());
        let light = DVec3::new(-a.sin() * e.cos(), -e.sin(), a.cos() * e.cos());
        let input = FrameInput::new(camera, light, 2048, IMAGE_HEIGHT)
            .receivers(Bound::Boxes(&boxes[..1]))
            .casters(Bound::Boxes(&boxes));
        let mut rows: Vec<Row> = engines(&input, view, light, &boxes)?.into();
        // Unreal: the crate's clipmap (no port).
        let unreal = ClipmapOptions::UNREAL;
        let clip_input = FrameInput::new(camera, light, 16_384, IMAGE_HEIGHT)
            .receivers(Bound::Boxes(&boxes[..1]))
            .casters(Bound::Boxes(&boxes))
            .scheme(FrameScheme::Clipmap(unreal));
        let f = frame(&clip_input)?;
        rows.push(Row {
            name: "Unreal 5 VSM (clipmap, 128² pages)",
            maps: f.len(),
            texels: plan_clipmap(&clip_input, &unreal)?.pages()
                * u64::from(unreal.page_texels).pow(2),
            error: model_error(&f),
            model: model_error(&f),
        });
        for r in &rows {
            let same_error = plan(&input, Goal::MaxError(r.error), Rounding::Whole)?;
            let same_texels = plan(
                &input,
                Goal::Budget {
                    texels: r.texels,
                    max_maps: 4,
                },
                Rounding::Whole,
            )?;
            println!(
                "| {elevation}° | {} | {} | {:.2} M | {:.3} | {:.3} | {:.3} M ({}) | {:.2} ({}) |",
                r.name,
                r.maps,
                r.texels as f64 / 1e6,
                r.error,
                r.model,
                same_error.texels as f64 / 1e6,
                label(&same_error.candidates[same_error.chosen].scheme),
                same_texels.max_error_pixels,
                label(&same_texels.candidates[same_texels.chosen].scheme),
            );
        }
        let one_px = plan(&input, Goal::MaxError(1.0), Rounding::Whole)?;
        println!(
            "| {elevation}° | the plan for 1 px | {} | {:.1} M | {:.2} | | ({}) | |",
            one_px.resolutions.len(),
            one_px.texels as f64 / 1e6,
            one_px.max_error_pixels,
            label(&one_px.candidates[one_px.chosen].scheme),
        );
    }
    Ok(())
}
