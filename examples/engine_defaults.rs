//! The engines' default directional shadows against the planner, on the same scenes (issue 24
//! item 5; the table in docs/planning.md, "The engines' defaults against the plan").
//!
//! Each engine's default set-up is built by the frame API and its error measured over the focus
//! body B (the largest texel-to-pixel ratio over every map, 1080 pixels high):
//!
//! - Bevy 0.19: `CascadeShadowConfigBuilder::default()` (4 cascades, minimum distance 0.1, first
//!   far bound 10, maximum distance 150, overlap proportion 0.2) with `DirectionalLightShadowMap`'s
//!   2048² texels; each cascade a world-fixed square around its slice's bounding sphere, snapped
//!   to texels, as `calculate_cascade` builds it (`FrameScheme::Stable` with `CascadeSplits::Bevy`);
//! - Filament: `ShadowOptions` defaults, one cascade of 1024² with LiSPSM (`WarpRule::Filament`);
//! - three.js `CSM` (examples/jsm/csm): 3 cascades, `practical` splits (λ = 0.5), 2048² each,
//!   squares around each slice (`FrameScheme::Stable`);
//! - Unreal 5 virtual shadow maps: the clipmap with Unreal's defaults for a world in metres
//!   (`ClipmapOptions::UNREAL`: levels 6–22, LOD bias −0.5, 16 384² virtual levels of 128² pages);
//!   its texels are the pages its levels' footprints touch (`plan::clipmap`), 128² each.
//!
//! Then the planner gives the fewest texels that reach the same error, and the error that the same
//! texels (at most 4 maps) reach. Run with `cargo run --release --example engine_defaults`.

use glam::DVec3;
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::frame::{
    frame, Aabb, Bound, Camera, CascadeSplits, ClipmapOptions, FrameInput, FrameScheme,
};
use shadow_aliasing::maps::WarpRule;
use shadow_aliasing::plan::allocate::Rounding;
use shadow_aliasing::plan::candidates::label;
use shadow_aliasing::plan::clipmap::plan_clipmap;
use shadow_aliasing::plan::{plan, Goal};
use shadow_aliasing::Result;

const IMAGE_HEIGHT: u32 = 1080;

struct Engine {
    name: &'static str,
    scheme: FrameScheme<'static>,
    resolution: u32,
}

fn engines() -> [Engine; 4] {
    [
        Engine {
            name: "Bevy 0.19 (4 cascades, 2048²)",
            scheme: FrameScheme::Stable(CascadeSplits::Bevy {
                k: 4,
                minimum_distance: 0.1,
                maximum_distance: 150.0,
                first_far_bound: 10.0,
                overlap_proportion: 0.2,
            }),
            resolution: 2048,
        },
        Engine {
            name: "Filament (1 LiSPSM map, 1024²)",
            scheme: FrameScheme::Single(WarpRule::Filament),
            resolution: 1024,
        },
        Engine {
            name: "three.js CSM (3 cascades, 2048²)",
            scheme: FrameScheme::Stable(CascadeSplits::Scheme {
                scheme: SplitScheme::Practical { lambda: 0.5 },
                k: 3,
                overlap: 0.0,
            }),
            resolution: 2048,
        },
        Engine {
            name: "Unreal 5 VSM (clipmap, 128² pages)",
            scheme: FrameScheme::Clipmap(ClipmapOptions::UNREAL),
            resolution: 16_384,
        },
    ]
}

fn main() -> Result<()> {
    // A camera 1.8 m above a 300 m × 150 m ground with a few buildings and a pole, looking
    // slightly down; Bevy's default projection (45° vertical field of view, near 0.1, far 1000),
    // 16:9. The ground receives (the receivers' bound must not hold the camera, or B reaches the
    // near plane at 0.1 and every error is set there); everything casts.
    let eye = DVec3::new(0.0, 1.8, 0.0);
    let view = glam::dcamera::rh::view::look_at_mat4(eye, DVec3::new(0.0, 0.0, -60.0), DVec3::Y);
    let camera = Camera::new(view, 0.1, 1000.0, 22.5f64.to_radians(), 16.0 / 9.0)?;
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
        "| sun elevation | engine default | maps | texels | max error (px) | plan: texels for that error | plan: error with those texels (≤ 4 maps) |"
    );
    println!("|---|---|---|---|---|---|---|");
    for elevation in [20.0f64, 45.0, 70.0] {
        // The sun 30° to the side of the view direction, travelling down at `elevation`.
        let (e, a) = (elevation.to_radians(), 30f64.to_radians());
        let light = DVec3::new(-a.sin() * e.cos(), -e.sin(), a.cos() * e.cos());
        for engine in engines() {
            let input = FrameInput::new(camera, light, engine.resolution, IMAGE_HEIGHT)
                .receivers(Bound::Boxes(&boxes[..1]))
                .casters(Bound::Boxes(&boxes))
                .scheme(engine.scheme);
            let f = frame(&input)?;
            let error = f
                .maps()
                .iter()
                .map(|m| m.max_error_pixels)
                .fold(0.0, f64::max);
            let texels = match engine.scheme {
                FrameScheme::Clipmap(o) => {
                    plan_clipmap(&input, &o)?.pages() * u64::from(o.page_texels).pow(2)
                }
                _ => f.len() as u64 * u64::from(engine.resolution).pow(2),
            };
            let same_error = plan(&input, Goal::MaxError(error), Rounding::Whole)?;
            let same_texels = plan(
                &input,
                Goal::Budget {
                    texels,
                    max_maps: 4,
                },
                Rounding::Whole,
            )?;
            println!(
                "| {elevation}° | {} | {} | {:.2} M | {:.2} | {:.3} M ({}) | {:.2} ({}) |",
                engine.name,
                f.len(),
                texels as f64 / 1e6,
                error,
                same_error.texels as f64 / 1e6,
                label(&same_error.candidates[same_error.chosen].scheme),
                same_texels.max_error_pixels,
                label(&same_texels.candidates[same_texels.chosen].scheme),
            );
        }
        let one_px = plan(
            &FrameInput::new(camera, light, 2048, IMAGE_HEIGHT)
                .receivers(Bound::Boxes(&boxes[..1]))
                .casters(Bound::Boxes(&boxes)),
            Goal::MaxError(1.0),
            Rounding::Whole,
        )?;
        println!(
            "| {elevation}° | the plan for 1 px | {} | {:.1} M | {:.2} | ({}) | |",
            one_px.resolutions.len(),
            one_px.texels as f64 / 1e6,
            one_px.max_error_pixels,
            label(&one_px.candidates[one_px.chosen].scheme),
        );
    }
    Ok(())
}
