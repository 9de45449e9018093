//! Every built-in set-up and every scene file in render-check/scenes/, rendered for real (wgpu on
//! Vulkan; lavapipe without a GPU) at a reduced size, held to every target of
//! `render_check::targets` (the binary's exit status holds the full run to the same). With no
//! Vulkan adapter these tests fail, naming `mesa-vulkan-drivers`; they never skip.

use glam::DVec3;
use render_check::analysis::pixel_point;
use render_check::gpu::{Gpu, Lookup};
use render_check::run::{
    case_clip_depth, draws, run_case, run_full, CaseSummary, Render, Sizes, Upload,
};
use render_check::scene::{Mesh, Scene};
use render_check::schemes::{build, clipmap_options, setups, Built, Options, Scheme, View};
use render_check::targets::violations;
use shadow_aliasing::frame::LevelChoice;
use shadow_aliasing::maps::ClipDepth;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The tests' size: 240 × 180 pixels, each scene's own map resolution, 16 shimmer frames.
const SIZES: Sizes = Sizes {
    width: 240,
    height: 180,
    res: None,
    frames: 16,
    shimmer_points: 1500,
    fault: None,
    render: Render::DEFAULT,
};

fn gpu() -> Gpu {
    Gpu::new().unwrap_or_else(|e| panic!("{e}"))
}

/// Every scheme of `scene` at `sizes`, asserting that no target is violated; the summaries.
/// With the default rendering each case takes the clip depth the binary gives it
/// (`case_clip_depth`: reversed depth for about half the schemes of every set-up).
fn meets_every_target(gpu: &Gpu, name: &str, scene: &Scene, sizes: Sizes) -> Vec<CaseSummary> {
    let si = setups().iter().position(|s| s.name == name).unwrap_or(0);
    render_check::schemes::schemes_for(name)
        .into_iter()
        .map(|scheme| {
            let mut sizes = sizes;
            if sizes.render == Render::DEFAULT {
                sizes.render.clip_depth = case_clip_depth(si, scheme);
            }
            let r = run_full(gpu, name, scene, scheme, sizes)
                .unwrap_or_else(|e| panic!("{name}/{}: {e}", scheme.name()));
            let v = violations(&r.summary);
            assert!(
                v.is_empty(),
                "{name}/{} at {} × {}: {v:?}\n{:?}",
                scheme.name(),
                sizes.width,
                sizes.height,
                r.summary
            );
            if setups().iter().any(|s| s.name == name) {
                papers_measured(&r.summary);
            }
            r.summary
        })
        .collect()
}

/// The schemes whose maps a paper fixes have their rendered error compared with the paper's map
/// (render_check::paper_error), and only those: no measurement is no pass.
fn papers_measured(c: &CaseSummary) {
    let paper = matches!(
        c.scheme.as_str(),
        "uniform" | "psm" | "lispsm" | "minimax" | "tsm" | "cascades4_lispsm" | "cascades4_blend"
    );
    let m = &c.measured;
    assert_eq!(m.paper_error_rel_diff.is_some(), paper, "{c:?}");
    assert_eq!(m.paper_frame_rel_diff.is_some(), paper, "{c:?}");
    assert_eq!(
        m.minimax_storage_ratio.is_some(),
        c.scheme == "minimax",
        "{c:?}"
    );
}

/// `scheme` built for `scene` at [`SIZES`]' screen, the scene's resolution, depth \[0, 1\], no
/// fault, the default options.
fn built_at_sizes(scene: &Scene, scheme: Scheme) -> (View, Built) {
    let view = View::new(&scene.camera, scene.light(), SIZES.width, SIZES.height).unwrap();
    let (res, zo) = (scene.map_resolution, ClipDepth::ZeroToOne);
    let built = build(scheme, &view, scene, res, None, zo, &Options::default()).unwrap();
    (view, built)
}

fn setup(name: &str) -> Scene {
    setups()
        .into_iter()
        .find(|s| s.name == name)
        .unwrap_or_else(|| panic!("no built-in set-up {name}"))
        .scene
}

/// One test per built-in set-up (run in parallel): every scheme meets every target.
macro_rules! every_target {
    ($($test:ident: $setup:literal,)*) => {$(
        #[test]
        fn $test() {
            meets_every_target(&gpu(), $setup, &setup($setup), SIZES);
        }
    )*};
}

// `behind_5`: the tower behind the camera, outside the view frustum, shadows the view (a depth
// range cut at the frustum loses it: the fault suite's no-casters). `thin_casters`: its long thin
// shadow and the poles' shadows are compared with the ray cast (at least 80 % of the shadowed
// pixels, a target), where eroding the screen image compared none of a 2-pixel shadow.
every_target! {
    overhead_meets_every_target: "overhead",
    tilted_45_meets_every_target: "tilted_45",
    behind_5_meets_every_target: "behind_5",
    front_5_meets_every_target: "front_5",
    grazing_10_meets_every_target: "grazing_10",
    parallel_1_meets_every_target: "parallel_1",
    thin_casters_meet_every_target: "thin_casters",
    far_tilted_meets_every_target: "far_tilted",
}

/// Issue 23's relative upload path: the thin-caster scene moved 10⁵ from the world origin, its
/// positions uploaded relative to the camera and its maps as `FrameMap::gpu_relative` gives them,
/// meets every target, and its numbers are the same scene's at the origin to within the GPU's
/// rounding (the plain world matrix fails there: tests/faults.rs).
#[test]
fn far_from_the_origin_meets_every_target_as_at_the_origin() {
    let gpu = gpu();
    let far = meets_every_target(&gpu, "far_1e5", &setup("far_1e5"), SIZES);
    // The same scene at the origin (its targets: thin_casters_meet_every_target).
    let near: Vec<CaseSummary> = Scheme::ALL
        .iter()
        .map(|&scheme| {
            run_case(&gpu, "thin_casters", &setup("thin_casters"), scheme, SIZES)
                .unwrap()
                .summary
        })
        .collect();
    let eye = DVec3::from_array(setup("far_1e5").camera.eye);
    assert!(
        (eye.length() - 1e5).abs() < 1e3,
        "the set-up is 10^5 from the origin"
    );
    // A camera f32 cannot hold (an upload origin rounded through f32 moves every texel:
    // tests/faults.rs).
    assert_ne!(eye.as_vec3().as_dvec3(), eye, "far_1e5's camera is an f32");
    for (f, n) in far.iter().zip(&near) {
        let (a, b) = (&f.measured, &n.measured);
        // The same pixels are visible and shadowed, up to 0.1 % (the exact tests lift a point off
        // its surface by 10⁻⁶ of its distance from the camera: with 10⁻⁶ of its world coordinates,
        // 0.1 unit there, 0.9 % of the shadowed pixels changed).
        let close = |x: usize, y: usize| x.abs_diff(y) <= 2 + y / 1000;
        assert!(close(a.visible_pixels, b.visible_pixels), "{f:?}\n{n:?}");
        assert!(close(a.shadow_pixels, b.shadow_pixels), "{f:?}\n{n:?}");
        // As many shadowed pixels compared as at the origin, to 2 % (the stable cascades' and the
        // clipmap's texel grids are fixed in the world, so they fall differently there): with the
        // lift of the world coordinates, 4 % fewer (93.7 % of them against 96.8 %, uniform).
        assert!(
            a.shadow_pixels_checked as f64 >= 0.98 * b.shadow_pixels_checked as f64,
            "{f:?}\n{n:?}"
        );
        assert!(
            (a.max_rendered_error / b.max_rendered_error - 1.0).abs() < 1e-3,
            "{f:?}\n{n:?}"
        );
    }
}

/// Every scheme of `name` with `render` at the tests' size meets every target; the summaries.
fn meets_with(gpu: &Gpu, name: &str, render: Render) -> Vec<CaseSummary> {
    let sizes = Sizes { render, ..SIZES };
    meets_every_target(gpu, name, &setup(name), sizes)
}

/// Issue 23's reversed depth: the records in `ClipDepth::Reversed` (depth 1 nearest the light),
/// the shadow pass cleared to 0 and compared greater-equal, the crate's module comparing the
/// lookup greater-equal: every target met.
#[test]
fn reversed_depth_meets_every_target() {
    let gpu = gpu();
    let reversed = Render {
        clip_depth: ClipDepth::Reversed,
        ..Render::DEFAULT
    };
    for name in ["tilted_45", "thin_casters"] {
        for c in meets_with(&gpu, name, reversed) {
            assert!(c.measured.shadow_pixels_checked > 0, "{c:?}");
        }
    }
}

/// Issue 23's bias: ordinary first-surface maps (every face stored, no rasterizer bias), looked
/// up at the crate's normal offset (`FrameMap::bias` in the record, the module's
/// `SA_NORMAL_OFFSET`). The orthographic maps (uniform, 4 stable cascades) and the LiSPSM
/// cascades meet every target: no acne (no false shadow on a compared lit pixel, at least 90 % of
/// the lit pixels compared) and no missing contact shadow (no miss, at least 80 % of the shadowed
/// pixels compared, with no contact band: the shadows at the feet of the poles and boxes are
/// compared). The single warped maps and face partitions have no miss and no false shadow
/// either, but their offset (the maximum over the map's body, set by its coarsest texels) moves
/// the lookup many of their finest texels, so fewer shadowed pixels are decidable
/// (docs/rendered.md).
#[test]
fn first_surface_maps_with_the_crates_bias_meet_every_target() {
    let gpu = gpu();
    let sizes = Sizes {
        render: Render {
            lookup: Lookup::FirstSurface,
            ..Render::DEFAULT
        },
        ..SIZES
    };
    for name in ["thin_casters", "grazing_10"] {
        let scene = setup(name);
        for scheme in Scheme::ALL {
            let every = matches!(
                scheme,
                Scheme::Uniform | Scheme::Cascades | Scheme::StableCascades
            );
            // The shimmer test (a target of the stable cascades) only where every target is held.
            let run = if every { run_full } else { run_case };
            let r = run(&gpu, name, &scene, scheme, sizes)
                .unwrap_or_else(|e| panic!("{name}/{}: {e}", scheme.name()));
            let m = &r.summary.measured;
            // Every target (80 % of the shadowed pixels checked included) for every scheme: the
            // warped maps and face partitions at the per-point normal offset
            // (`sa_local_normal_offset`); at the record's maximum offset 21 of 36 such cases
            // fell below 80 %.
            let v = violations(&r.summary);
            assert!(v.is_empty(), "{name}/{}: {v:?}", scheme.name());
            if every {
                assert!(
                    m.lit_pixels_checked as f64 >= 0.9 * m.lit_pixels as f64,
                    "{:?}",
                    r.summary
                );
            }
            assert_eq!(
                (m.shadow_misses, m.false_shadows),
                (0, 0),
                "{:?}",
                r.summary
            );
            assert!(
                m.shadow_pixels_checked > m.shadow_pixels / 10,
                "{:?}",
                r.summary
            );
        }
    }
}

/// Issue 23's culling: drawing each object only into the maps whose casters' volume
/// (`FrameMap::casters_volume`) it may meet changes no pixel (every output of the camera pass
/// bit for bit), in set-ups whose shadows come from casters outside the view; the tower behind
/// the camera is culled from every map under the overhead light (its footprint lies behind the
/// camera, the light straight down: a hand check) and drawn under the light from behind, whose
/// long shadow it casts.
#[test]
fn culling_by_the_casters_volume_changes_no_pixel() {
    let gpu = gpu();
    let tower = Scene::builtin().boxes.len(); // the last object (the ground is object 0)
    for (name, tower_culled) in [
        ("overhead", true),
        ("behind_5", false),
        ("thin_casters", false),
    ] {
        let scene = setup(name);
        let mesh = Mesh::build(&scene);
        for scheme in Scheme::ALL {
            let (view, built) = built_at_sizes(&scene, scheme);
            let res = scene.map_resolution;
            let render = |cull: bool| {
                let sizes = Sizes {
                    render: Render {
                        cull,
                        ..Render::DEFAULT
                    },
                    ..SIZES
                };
                let up = Upload::new(&built, &mesh, sizes);
                let out = gpu
                    .render(&up.input(&view, &mesh, &built, res, sizes))
                    .unwrap();
                (out, draws(&built, &mesh, sizes))
            };
            let (all, drawn_all) = render(false);
            let (culled, drawn) = render(true);
            let objects = mesh.objects.len();
            assert!(drawn_all.iter().all(|d| d.len() == objects));
            let culled_count: usize = drawn.iter().map(|d| objects - d.len()).sum();
            if name != "thin_casters" {
                let has_tower =
                    |d: &Vec<std::ops::Range<u32>>| d.contains(&mesh.objects[tower].vertices);
                if tower_culled {
                    assert!(
                        drawn.iter().all(|d| !has_tower(d)),
                        "{name}/{}",
                        scheme.name()
                    );
                } else {
                    assert!(drawn.iter().any(has_tower), "{name}/{}", scheme.name());
                }
            }
            assert!(
                culled_count > 0 || !tower_culled,
                "{name}/{}: nothing culled",
                scheme.name()
            );
            let same = all
                .texel
                .iter()
                .zip(&culled.texel)
                .all(|(a, b)| a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits()))
                && all.id == culled.id
                && all.color == culled.color
                && all
                    .depth
                    .iter()
                    .zip(&culled.depth)
                    .all(|(x, y)| x.to_bits() == y.to_bits());
            assert!(same, "{name}/{}: culling changed a pixel", scheme.name());
        }
    }
}

/// Lloyd 2006's overhead case: the rendered m_x, m_z over the ground equal Eq 7–8 at every
/// compared ground pixel and Eq 9–10 at their maxima (M_z where Eq 10 puts it on the near
/// plane), within 1 % (a target), for the schemes that are Lloyd's warps (PSM's n′ = n among
/// them); the others are not held to it.
#[test]
fn level_overhead_meets_lloyd_2006() {
    let cases = meets_every_target(&gpu(), "level_overhead", &setup("level_overhead"), SIZES);
    for c in &cases {
        let lloyd = matches!(
            c.scheme.as_str(),
            "uniform" | "psm" | "lispsm" | "minimax" | "cascades4_lispsm"
        );
        assert_eq!(c.measured.lloyd_rel_diff.is_some(), lloyd, "{c:?}");
        // The near end of the ground is visible: the frame's worst point is reached.
        assert!(
            c.measured.frame_error_ratio_worst_visible.is_some(),
            "{c:?}"
        );
    }
}

/// `level_side`: `level_overhead`'s camera under a light 45° high from the side (γ = 90°, not
/// straight down): each map's error depends on the eye depth alone, so its worst body point is
/// on the near plane, where the nearest ground is seen, and the two-sided checks
/// (`frame_error_ratio_worst_visible`, `lens_frame_ratio_worst_visible` ≥ 0.95) run for every
/// scheme, the lens's but for PSM: below n′_LSPSM its largest error is m_z on the far plane
/// (Lloyd 2006 Eq 10), and the lens's worst vertex there is off the ground drawn.
#[test]
fn level_side_reaches_every_schemes_worst_point() {
    let cases = meets_every_target(&gpu(), "level_side", &setup("level_side"), SIZES);
    assert_eq!(cases.len(), Scheme::ALL.len());
    for c in &cases {
        assert!(
            c.measured.frame_error_ratio_worst_visible.is_some()
                && (c.measured.lens_frame_ratio_worst_visible.is_some() || c.scheme == "psm"),
            "{c:?}"
        );
    }
}

/// Martin & Tan §6.4: where the focus body is shorter than the frustum (steps on a ground that
/// ends 14 from the camera's foot, the far plane at 60), the focus region is δ f′/f beyond the
/// body's near end (f′, f the body's and the frustum's depths), as the crate builds it. TSM's
/// focus line fitted from the GPU's texels is then at 80 % of the map and its error is the
/// paper's map's; with δ unscaled (render-check's former expectation) the focus fraction was off
/// by 0.13 and the paper's map by 1.6 at 320 × 240.
#[test]
fn tsm_focus_follows_a_body_shorter_than_the_frustum() {
    let scene: Scene = serde_json::from_str(
        r#"{"ground_y": 0.0, "ground_half_extent": 14.0,
            "boxes": [{"min": [-5, 0, -12], "max": [5, 0.6, -9]},
                      {"min": [-5, 0, -9], "max": [5, 1.2, -6]},
                      {"min": [-5, 0, -6], "max": [5, 1.8, -3]},
                      {"min": [2, 0, -20], "max": [3, 4, -19]}],
            "camera": {"eye": [0, 5, 6], "target": [0, 0, -10], "up": [0, 1, 0],
                       "near": 0.5, "far": 60, "fov_y_deg": 55},
            "light_dir": [0.4, -1.0, -0.3], "map_resolution": 1024}"#,
    )
    .unwrap();
    scene.validate().unwrap();
    let r = run_case(&gpu(), "stairs", &scene, Scheme::Tsm, SIZES).unwrap();
    let v = violations(&r.summary);
    assert!(v.is_empty(), "{v:?}");
    let m = &r.summary.measured;
    let f = m.tsm_focus_fraction.unwrap();
    assert!((f - 0.8).abs() <= 1e-3, "{f}");
    assert!(m.paper_error_rel_diff.is_some(), "{m:?}");
}

/// The GPU's texel positions at 4096 texels a side: `f32` rounds the light clip position to a
/// fixed fraction of the map, so the error in texels grows with the resolution (here 4 ×, within
/// [3, 5], from 1024 to 4096 in `overhead`'s face partitions, which put 5.15·10⁻³ texel at the
/// 99th percentile at 240 × 180, over the 5·10⁻³ that holds up to 1024), and the case meets every
/// target with the limit scaled by res / 1024 (`targets::texel_position_limit`).
#[test]
fn texel_positions_scale_with_the_resolution() {
    let gpu = gpu();
    let scene = setup("overhead");
    let p99 = |res: u32| {
        let sizes = Sizes {
            res: Some(res),
            ..SIZES
        };
        let r = run_case(&gpu, "overhead", &scene, Scheme::Faces, sizes).unwrap();
        let v = violations(&r.summary);
        assert!(v.is_empty(), "{res}: {v:?}");
        assert_eq!(r.summary.map_resolution, res);
        r.summary.measured.texel_position_p99
    };
    let (coarse, fine) = (p99(1024), p99(4096));
    let ratio = fine / coarse;
    assert!((3.0..=5.0).contains(&ratio), "{coarse} {fine}");
}

/// The clipmap (issue 24 item 4): the level the shader picks (`sa_clipmap_level` in `f32`) is the
/// library's (`LevelChoice::level`) at every visible pixel's exact depth, away from a level's
/// boundary; and where no clamp applies, the level's texel is at most 2^b and more than 2^(b−1)
/// pixels wide there (b the level choice's bias), computed by hand from the level's half-width
/// 2^(i+2) · unit.
#[test]
fn clipmap_levels_are_the_level_choice() {
    let gpu = gpu();
    let scene = setup("tilted_45");
    let (w, h) = (SIZES.width, SIZES.height);
    let (view, built) = built_at_sizes(&scene, Scheme::Clipmap);
    let res = scene.map_resolution;
    let mesh = Mesh::build(&scene);
    let up = Upload::new(&built, &mesh, SIZES);
    let out = gpu
        .render(&up.input(&view, &mesh, &built, res, SIZES))
        .unwrap();
    let opts = clipmap_options(res);
    let choice = LevelChoice::new(&view.frustum, h, res, &opts).unwrap();
    let (first, last) = (built.clipmap[1] as i32, built.clipmap[2] as i32);
    let tan = view.frustum.tan_half_fov();
    let mut levels = std::collections::BTreeSet::new();
    let mut checked = 0;
    for (i, &id) in out.id.iter().enumerate() {
        if id == 0 {
            continue;
        }
        let surf = mesh.surfaces[(id - 1) as usize];
        let n = view.world_to_eye.transform_vector3(surf.normal);
        let p0 = view.world_to_eye.transform_point3(surf.point);
        let (x, y) = (i % w as usize, i / w as usize);
        let Some(p) = pixel_point(&view, w, h, x, y, n, p0) else {
            continue;
        };
        let z = -p.z;
        let u = z.log2() + choice.offset;
        if (u - u.round()).abs() < 1e-4 {
            continue; // on a level's boundary: f32 may pick either
        }
        let level = choice.level(z);
        assert_eq!(
            out.texel[i][2] as i32,
            level - first,
            "pixel ({x}, {y}) at depth {z}"
        );
        if level > opts.first_level && level < last {
            let texel = 2.0 * opts.unit * f64::from(level + 2).exp2() / f64::from(res);
            let pixel = 2.0 * z * tan / f64::from(h);
            let e = (texel / pixel).log2();
            assert!(
                e <= choice.bias + 1e-9 && e > choice.bias - 1.0 - 1e-9,
                "level {level} at depth {z}: texel / pixel 2^{e}, bias {}",
                choice.bias
            );
        }
        levels.insert(level);
        checked += 1;
    }
    assert!(levels.len() >= 4, "{levels:?}");
    assert!(*levels.first().unwrap() >= first && *levels.last().unwrap() <= last);
    assert!(checked > (w * h / 2) as usize, "{checked}");
}

/// The scene files in render-check/scenes/ (there is at least one).
fn scene_files() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    files.sort();
    assert!(!files.is_empty(), "no scene file in {}", dir.display());
    files
}

/// Every scene file at 320 × 240, and at 640 × 480: the rendered-error statistics use exact
/// derivatives, so a scene that passes at one size passes at the other (before, finite
/// differences below the horizon put a thin-caster scene's p99 at 8.9 % at 320 × 240).
#[test]
fn every_scene_file_meets_every_target_at_two_sizes() {
    let gpu = gpu();
    for f in scene_files() {
        let scene = Scene::load(&f).unwrap();
        let name = f.file_stem().unwrap().to_string_lossy().into_owned();
        for (width, height) in [(320, 240), (640, 480)] {
            let sizes = Sizes {
                width,
                height,
                ..SIZES
            };
            meets_every_target(&gpu, &name, &scene, sizes);
        }
    }
}

/// A staircase of boxes, each resting on the step below (its bottom face, which a second-depth
/// map stores, lies in the plane of the step's top face), under a light from the front left. The
/// shadow of each step on the one below reaches the box's foot, where the texel's ray passes
/// below the receiving face (inside its own box) and the depth bias lets light leak past the
/// resting face: the contact band must hold those pixels too. When the band was skipped there,
/// the clipmap compared 9 such pixels at 320 × 240 and found them lit (shadow misses).
#[test]
fn a_box_resting_on_a_step_keeps_its_contact_band() {
    let scene: Scene = serde_json::from_str(
        r#"{"ground_y": 0.0, "ground_half_extent": 80.0,
            "boxes": [{"min": [-3, 0, -14], "max": [3, 0.5, -10]},
                      {"min": [-3, 0.5, -15], "max": [3, 1.0, -11]},
                      {"min": [-3, 1.0, -16], "max": [3, 1.5, -12]},
                      {"min": [-3, 1.5, -17], "max": [3, 2.0, -13]}],
            "camera": {"eye": [0, 4, 0], "target": [0, 0, -20], "up": [0, 1, 0],
                       "near": 0.5, "far": 60, "fov_y_deg": 55},
            "light_dir": [0.5, -1.0, 0.6], "map_resolution": 1024}"#,
    )
    .unwrap();
    scene.validate().unwrap();
    let sizes = Sizes {
        width: 320,
        height: 240,
        ..SIZES
    };
    let r = run_case(&gpu(), "stairs", &scene, Scheme::Clipmap, sizes).unwrap();
    let m = &r.summary.measured;
    assert!(m.shadow_pixels_checked > 500, "{m:?}");
    assert_eq!(m.shadow_misses, 0, "{m:?}");
    assert_eq!(violations(&r.summary), Vec::<String>::new());
}

/// Eight slats 0.05 wide, 1.5 above the ground, under a sun 8° high behind them: their shadows
/// on the ground are thin stripes, a few of the cascades' and the clipmap's texels across. Each
/// shadowed pixel is compared with the verdict of the texel rays its lookup reads (the pixel's
/// own state, or the texel's where the stripe's edge passes between the pixel and the texel's
/// centre), so at least 80 % of them are decided. When a pixel was compared only where its
/// texel's state was its own, the stable cascades decided 68 % and the clipmap 63 % at
/// 320 × 240 (inconclusive).
#[test]
fn thin_shadows_under_a_low_sun_are_decided() {
    let mut boxes: Vec<String> = (0..8)
        .map(|i| {
            let z = -14.0 + 0.2 * f64::from(i);
            format!(
                r#"{{"min": [-6, 1.5, {z}], "max": [6, 1.6, {}]}}"#,
                z + 0.05
            )
        })
        .collect();
    boxes.push(r#"{"min": [-6.2, 0, -14.2], "max": [-6, 1.6, -12.4]}"#.into());
    boxes.push(r#"{"min": [6, 0, -14.2], "max": [6.2, 1.6, -12.4]}"#.into());
    let scene: Scene = serde_json::from_str(&format!(
        r#"{{"ground_y": 0.0, "ground_half_extent": 80.0, "boxes": [{}],
            "camera": {{"eye": [0, 4, 0], "target": [0, 0, -20], "up": [0, 1, 0],
                        "near": 0.5, "far": 60, "fov_y_deg": 55}},
            "light_dir": [0.0, -0.1405, -1.0], "map_resolution": 1024}}"#,
        boxes.join(", ")
    ))
    .unwrap();
    scene.validate().unwrap();
    let sizes = Sizes {
        width: 320,
        height: 240,
        ..SIZES
    };
    let gpu = gpu();
    for scheme in [Scheme::StableCascades, Scheme::Clipmap] {
        let r = run_case(&gpu, "slats", &scene, scheme, sizes).unwrap();
        let m = &r.summary.measured;
        assert!(m.shadow_pixels > 300, "{}: {m:?}", scheme.name());
        // The shadow targets (the shimmer test is run_full's, not run_case's).
        assert_eq!(
            (m.shadow_misses, m.false_shadows),
            (0, 0),
            "{}",
            scheme.name()
        );
        let decided = m.shadow_pixels_checked as f64 / m.shadow_pixels as f64;
        assert!(decided >= 0.8, "{}: {decided}", scheme.name());
        let lit = m.lit_pixels_checked as f64 / m.lit_pixels as f64;
        assert!(lit >= 0.8, "{}: {lit}", scheme.name());
    }
}

fn scene_file_text() -> &'static str {
    r#"{"ground_y": 0.0, "ground_half_extent": 100.0,
        "boxes": [{"min": [-2, 0, -12], "max": [2, 3, -8]}, {"min": [3, 0, -20], "max": [4, 6, -19]}],
        "camera": {"eye": [0, 4, 0], "target": [0, 0, -20], "up": [0, 1, 0],
                   "near": 0.5, "far": 60, "fov_y_deg": 55},
        "light_dir": [0.4, -1.0, -0.3], "map_resolution": 1024}"#
}

/// The binary with a scene file: exit 0, summary.json has exactly the documented fields, the
/// images are written.
#[test]
fn scene_file_run_writes_the_summary_with_exactly_the_fields() {
    let dir = std::env::temp_dir().join(format!("render-check-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("small.json");
    std::fs::write(&scene, scene_file_text()).unwrap();
    let out = dir.join("out");
    let o = Command::new(env!("CARGO_BIN_EXE_render-check"))
        .args([
            "--out",
            out.to_str().unwrap(),
            "--scene",
            scene.to_str().unwrap(),
        ])
        .args(["--width", "160", "--height", "120", "--frames", "4"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let top: Vec<&String> = summary.as_object().unwrap().keys().collect();
    assert_eq!(top, ["cases", "device", "options"]);
    // A scene file has no option cases ("What is measured", 15).
    assert_eq!(summary["options"].as_array().unwrap().len(), 0);
    let cases = summary["cases"].as_array().unwrap();
    assert_eq!(cases.len(), Scheme::ALL.len());
    let mut keys: Vec<&str> = cases[0]
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    keys.sort_unstable();
    let mut expect = [
        "setup",
        "scheme",
        "width",
        "height",
        "map_resolution",
        "map_texels",
        "visible_pixels",
        "pixels_compared",
        "pixels_not_compared",
        "median_rel_diff",
        "p99_rel_diff",
        "max_rendered_error",
        "max_predicted_error",
        "shadow_pixels",
        "shadow_pixels_checked",
        "lit_pixels",
        "lit_pixels_checked",
        "shadow_misses",
        "false_shadows",
        "band_mismatch_fraction",
        "uncovered_pixels",
        "frame_error_ratio",
        "frame_error_ratio_worst_visible",
        "lloyd_rel_diff",
        "blend_pixels",
        "blend_mismatches",
        "lens_pixels_compared",
        "lens_median_rel_diff",
        "lens_p99_rel_diff",
        "max_lens",
        "lens_frame_ratio",
        "lens_frame_ratio_worst_visible",
        "max_texel_shear",
        "texel_position_p99",
        "texel_position_max",
        "warp_rel_diff",
        "tsm_focus_fraction",
        "split_mismatches",
        "paper_error_rel_diff",
        "paper_frame_rel_diff",
        "minimax_storage_ratio",
        "shimmer_changed_fraction",
        "shimmer_points",
        "stable_grid_texels",
        "clip_depth",
        "body_rel_diff",
        "window_fill",
        "stable_half_width_rel_diff",
        "stable_centre_texels",
        "clipmap_rel_diff",
        "normal_offset_ratio",
        "depth_bias_ratio",
        "texel_world_ratio",
        "receivers_volume_rel_diff",
        "casters_volume_rel_diff",
        "split_rel_diff",
        "depth_clamp_fill",
        "lens_colour_pixels",
        "lens_colour_mismatches",
        "paths",
    ];
    expect.sort_unstable();
    assert_eq!(keys, expect);
    for c in cases {
        assert_eq!(c["setup"], "small");
        assert_eq!(c["shadow_misses"], 0, "{c}");
        assert_eq!(c["false_shadows"], 0, "{c}");
        assert_eq!(c["uncovered_pixels"], 0, "{c}");
        // The shader paths run only in the built-in cases of render_check::paths::CASES.
        assert!(c["paths"].is_null(), "{c}");
        // The shimmer test runs for the plain and the stable cascades.
        let cascaded = matches!(
            c["scheme"].as_str().unwrap(),
            "cascades4_lispsm" | "stable_cascades4"
        );
        let blended = c["scheme"] == "cascades4_blend";
        assert_eq!(c["blend_pixels"].is_null(), !blended, "{c}");
        if blended {
            assert!(c["blend_pixels"].as_u64().unwrap() > 0, "{c}");
            assert_eq!(c["blend_mismatches"], 0, "{c}");
        }
        for k in ["shimmer_changed_fraction", "shimmer_points"] {
            assert_eq!(c[k].is_null(), !cascaded, "{k}: {c}");
        }
        let stem = format!("small_{}", c["scheme"].as_str().unwrap());
        assert!(out.join(format!("{stem}.png")).is_file());
        assert!(out.join(format!("{stem}_error.png")).is_file());
        assert!(out.join(format!("{stem}_lens.png")).is_file());
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A violated target makes the binary fail, naming the case and the target: here the casters
/// left out of the depth range (`--fault no-casters`) lose the shadows of the boxes nearer the
/// light than the focus body.
#[test]
fn a_violated_target_fails_the_binary_naming_it() {
    let dir = std::env::temp_dir().join(format!("render-check-fail-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/thin_casters.json");
    let o = Command::new(env!("CARGO_BIN_EXE_render-check"))
        .args([
            "--out",
            dir.join("o").to_str().unwrap(),
            "--scene",
            scene.to_str().unwrap(),
        ])
        .args(["--width", "160", "--height", "120", "--frames", "4"])
        .args(["--fault", "no-casters"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success(), "{err}");
    assert!(err.contains("TARGET VIOLATED thin_casters_"), "{err}");
    assert!(err.contains("shadow_misses"), "{err}");
    assert!(err.contains("cases violate a target"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Without a Vulkan driver the binary fails and names the package.
#[test]
fn no_adapter_fails_naming_the_package() {
    let o = Command::new(env!("CARGO_BIN_EXE_render-check"))
        .args([
            "--out",
            std::env::temp_dir()
                .join("render-check-none")
                .to_str()
                .unwrap(),
        ])
        .env("VK_ICD_FILENAMES", "/nonexistent/icd.json")
        .env("VK_DRIVER_FILES", "/nonexistent/icd.json")
        .output()
        .unwrap();
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("mesa-vulkan-drivers"), "{err}");
}

/// A bad scene file is an error naming the file, not a panic.
#[test]
fn bad_scene_file_is_an_error() {
    let dir = std::env::temp_dir().join(format!("render-check-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("bad.json");
    std::fs::write(&scene, r#"{"ground_y": 0.0}"#).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_render-check"))
        .args([
            "--out",
            dir.join("o").to_str().unwrap(),
            "--scene",
            scene.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("bad.json"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}
