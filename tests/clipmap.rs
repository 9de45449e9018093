//! Clipmaps (issue 24 item 4): the level choice against hand calculations, each level's map
//! against its own measured error and geometry, the levels needed, the pages against brute force,
//! the storage against Lloyd 2006's closed forms, and bad input.

use glam::{DMat4, DVec2, DVec3};
use proptest::prelude::*;
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::frame::{
    frame, Aabb, Bound, Camera, CascadeSplits, ClipmapOptions, FrameInput, FrameMap, FrameScheme,
    LevelChoice,
};
use shadow_aliasing::maps::{ClipDepth, WarpRule};
use shadow_aliasing::plan::clipmap::{clipmap_for_pool, pages_touched, plan_clipmap};
use shadow_aliasing::Error;

/// Levels −40 to 40 of radius 2^{i+1}, LOD bias `b`, pages of `p` texels: no first or last level
/// clamps at the depths of these tests.
fn open(b: f64, p: u32) -> ClipmapOptions {
    ClipmapOptions {
        first_level: -40,
        last_level: 40,
        lod_bias: b,
        unit: 1.0,
        page_texels: p,
    }
}

/// Camera at the origin looking down −Z, light overhead (straight down, across the view):
/// Lloyd 2006's set-up.
fn overhead(alpha: f64, tan: f64, aspect: f64, res: u32, h: u32) -> FrameInput<'static> {
    let cam = Camera::new(DMat4::IDENTITY, 1.0, alpha, tan.atan(), aspect).unwrap();
    FrameInput::new(cam, DVec3::new(0.0, -1.0, 0.0), res, h)
}

fn arg_name(e: Error) -> &'static str {
    match e {
        Error::InvalidArgument { name, .. } => name,
        e => panic!("not an argument error: {e:?}"),
    }
}

/// tan θ = 1, R = 16384, H = 1024, unit 1, bias 0: by hand L = log₂(1 · 16384 / (4 · 1024)) = 2,
/// and the coverage bound log₂ √3 = 0.79 is below it, so level(z) = ⌊log₂ z + 2⌋; at z = 1 level
/// 2, whose texel 2^5/16384 = 1/512 equals the pixel 2 · 1 · 1/1024.
#[test]
fn level_choice_by_hand() {
    let view = overhead(100.0, 1.0, 1.0, 16384, 1024);
    let c = LevelChoice::new(view.camera.view(), 1024, 16384, &open(0.0, 128)).unwrap();
    assert!((c.offset - 2.0).abs() < 1e-15, "{}", c.offset);
    assert!(c.bias.abs() < 1e-15);
    for (z, level) in [
        (1.001, 2),
        (1.999, 2),
        (2.001, 3),
        (0.51, 1),
        (0.26, 0),
        (96.0, 8),
    ] {
        assert_eq!(c.level(z), level, "z = {z}");
    }
    assert!((c.texel(2) - 1.0 / 512.0).abs() < 1e-18);
    assert!((c.error_at(2, 1.0) - 1.0).abs() < 1e-15);
    assert!((c.level_start(3) - 2.0).abs() < 1e-14);
    // Bias −3 asks for L = −1, below the coverage bound log₂ √3: the bias in effect is
    // log₂ √3 − 2.
    let c = LevelChoice::new(view.camera.view(), 1024, 16384, &open(-3.0, 128)).unwrap();
    let cov = 3f64.sqrt().log2();
    assert!((c.offset - cov).abs() < 1e-15 && (c.bias - (cov - 2.0)).abs() < 1e-15);
    // Unreal's defaults in metres: levels 6..=22, so a depth of 1 mm is level 6 and 10⁶ m is 22.
    let c = LevelChoice::new(view.camera.view(), 1024, 16384, &ClipmapOptions::UNREAL).unwrap();
    assert_eq!((c.level(1e-3), c.level(1e6)), (6, 22));
    assert!((ClipmapOptions::UNREAL.radius(6) - 1.28).abs() < 1e-15);
    assert!((ClipmapOptions::UNREAL.half_width(22) - 167_772.16).abs() < 1e-9);
}

/// A random camera (position, yaw, pitch), light and ground box: a scene with general light.
fn ground_scene(
    eye: DVec3,
    yaw: f64,
    pitch: f64,
    light: DVec3,
    tan: f64,
    far: f64,
) -> (Camera, [Aabb; 1]) {
    let dir = DVec3::new(
        yaw.sin() * pitch.cos(),
        pitch.sin(),
        -yaw.cos() * pitch.cos(),
    );
    let view = glam::dcamera::rh::view::look_at_mat4(eye, eye + dir, DVec3::Y);
    let cam = Camera::new(view, 0.5, far, tan.atan(), 16.0 / 9.0).unwrap();
    let _ = light;
    let ground = [Aabb::new(
        DVec3::new(eye.x - 2.0 * far, -1.0, eye.z - 2.0 * far),
        DVec3::new(eye.x + 2.0 * far, 0.0, eye.z + 2.0 * far),
    )
    .unwrap()];
    (cam, ground)
}

/// Every level's map: its measured error equals its texel over the pixel at its body's nearest
/// depth (an orthographic map's M_x = M_z), lies in (2^{b−1}, 2^b] where no clamp applies, its
/// texel is 2^{i+3} unit / R, its square holds its body and is centred on the camera to half a
/// page, and it has culling volumes and a bias.
fn check_levels(input: &FrameInput<'_>, opts: &ClipmapOptions) {
    let f = frame(&input.scheme(FrameScheme::Clipmap(*opts))).unwrap();
    let view = input.camera.view();
    let c = LevelChoice::new(view, input.image_height, input.map_resolution, opts).unwrap();
    let res = f64::from(input.map_resolution);
    let h = f64::from(input.image_height);
    let mut prev_end: Option<f64> = None;
    for m in f.maps().iter() {
        let i = m.clipmap_level.expect("a clipmap level");
        let texel = opts.unit * f64::from(i + 3).exp2() / res;
        assert!((m.texel_world - texel).abs() <= 1e-12 * texel, "level {i}");
        let z_near = m.body().iter().map(|p| -p.z).fold(f64::INFINITY, f64::min);
        let hand = texel * h / (2.0 * z_near * view.tan_half_fov());
        let e = m.error().unwrap().max_error_pixels;
        assert!((e - hand).abs() <= 1e-9 * hand, "level {i}: {e} vs {hand}");
        assert!((m.max_mx - m.max_mz).abs() <= 1e-9 * m.max_mx);
        let (a, b) = m.split;
        if a >= c.level_start(i) * (1.0 - 1e-12) {
            assert!(
                e <= c.bias.exp2() * (1.0 + 1e-9) && e > (c.bias - 1.0).exp2() * (1.0 - 1e-9),
                "level {i} [{a}, {b}]: {e} outside (2^(b−1), 2^b], b = {}",
                c.bias
            );
        }
        if let Some(end) = prev_end {
            assert!((a - end).abs() <= 1e-12 * a, "levels abut");
        }
        prev_end = Some(b);
        // The square: every vertex inside, the camera within half a page of its centre.
        let w2c = m.world_to_clip(ClipDepth::NegOneToOne);
        let eye_to_world = input.camera.world_to_eye().inverse();
        for p in m.body() {
            let q = w2c.project_point3(eye_to_world.transform_point3(*p));
            assert!(q.x.abs() <= 1.0 + 1e-9 && q.y.abs() <= 1.0 + 1e-9, "{q}");
        }
        let cam = w2c.project_point3(eye_to_world.w_axis.truncate());
        let half_page = f64::from(opts.page_texels) / res;
        assert!(
            cam.x.abs() <= half_page * (1.0 + 1e-9) && cam.y.abs() <= half_page * (1.0 + 1e-9),
            "camera at {cam}"
        );
        assert!(m.casters_volume().planes().len() >= 4);
        assert!(m.bias(1.0, ClipDepth::ZeroToOne).unwrap().normal_offset > 0.0);
    }
    assert!(!f.is_empty());
}

#[test]
fn levels_of_the_overhead_frustum() {
    for (alpha, tan) in [(1000.0, 0.577), (100.0, 1.0), (1e4, 0.4)] {
        for b in [-0.5, 0.0, 0.7] {
            check_levels(&overhead(alpha, tan, 1.0, 16384, 1080), &open(b, 128));
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    /// The same over a ground plane with a general light and camera.
    #[test]
    fn levels_of_random_ground_scenes(
        ex in -50.0f64..50.0, ez in -50.0f64..50.0, ey in 1.0f64..20.0,
        yaw in -3.0f64..3.0, pitch in -0.6f64..0.2,
        lx in -1.0f64..1.0, lz in -1.0f64..1.0,
        tan in 0.3f64..1.2, far in 50.0f64..2000.0, b in -0.5f64..1.5,
    ) {
        let light = DVec3::new(lx, -1.0, lz);
        let (cam, ground) = ground_scene(DVec3::new(ex, ey, ez), yaw, pitch, light, tan, far);
        let input = FrameInput::new(cam, light, 16384, 1080)
            .receivers(Bound::Boxes(&ground))
            .casters(Bound::Boxes(&ground));
        check_levels(&input, &ClipmapOptions { unit: 0.01, ..ClipmapOptions::UNREAL });
        check_levels(&input, &ClipmapOptions { lod_bias: b, ..open(0.0, 128) });
    }
}

/// About log₂(f/n) + 1 levels: ⌊log₂(f/n)⌋ + 1 or ⌈log₂(f/n)⌉ + 1 (the depth range's ends fall
/// anywhere within their levels), each interior level covering a depth ratio of exactly 2.
#[test]
fn levels_needed() {
    for alpha in [3.0, 10.0, 64.0, 100.0, 1000.0, 5000.0] {
        for b in [-0.5, -0.2, 0.0, 0.3] {
            let input = overhead(alpha, 0.7, 1.5, 16384, 1080);
            let p = plan_clipmap(&input, &open(b, 128)).unwrap();
            let n = p.levels().count() as f64;
            let d = f64::log2(alpha);
            assert!(
                n == d.floor() + 1.0 || n == d.ceil() + 1.0,
                "α {alpha}: {n} levels"
            );
            let (first, last) = p.level_range();
            assert_eq!(f64::from(last - first + 1), n);
            let levels: Vec<_> = p.levels().collect();
            for l in &levels[1..levels.len() - 1] {
                assert!((l.depths.1 / l.depths.0 - 2.0).abs() < 1e-12);
            }
        }
    }
}

/// The pages of a level by brute force: every cell of the page grid tested against the convex
/// footprint by separating axes (the cell's two, the footprint's edge normals).
fn pages_brute(m: &FrameMap, per_side: u32) -> u32 {
    let mat = m.shadow.matrix();
    let s = 0.5 * f64::from(per_side);
    let pts: Vec<DVec2> = m
        .body()
        .iter()
        .map(|p| {
            let q = mat.project_point3(*p);
            DVec2::new((q.x + 1.0) * s, (q.y + 1.0) * s)
        })
        .collect();
    // Gift wrapping, independent of the library's hull.
    let start = (0..pts.len())
        .min_by(|&a, &b| pts[a].x.total_cmp(&pts[b].x))
        .unwrap();
    let mut hull = vec![];
    let mut cur = start;
    loop {
        hull.push(pts[cur]);
        let mut next = (cur + 1) % pts.len();
        for (j, p) in pts.iter().enumerate() {
            if (pts[next] - pts[cur]).perp_dot(*p - pts[cur]) < 0.0 {
                next = j;
            }
        }
        cur = next;
        if cur == start || hull.len() > pts.len() {
            break;
        }
    }
    let mut axes = vec![DVec2::X, DVec2::Y];
    for i in 0..hull.len() {
        let e = hull[(i + 1) % hull.len()] - hull[i];
        if e.length() > 1e-12 {
            axes.push(e.perp());
        }
    }
    let mut count = 0;
    for r in 0..per_side {
        for c in 0..per_side {
            let cell = [
                DVec2::new(f64::from(c), f64::from(r)),
                DVec2::new(f64::from(c + 1), f64::from(r)),
                DVec2::new(f64::from(c + 1), f64::from(r + 1)),
                DVec2::new(f64::from(c), f64::from(r + 1)),
            ];
            let apart = axes.iter().any(|a| {
                let (p0, p1) = hull
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |m, p| {
                        (m.0.min(a.dot(*p)), m.1.max(a.dot(*p)))
                    });
                let (c0, c1) = cell
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |m, p| {
                        (m.0.min(a.dot(*p)), m.1.max(a.dot(*p)))
                    });
                p1 <= c0 || c1 <= p0
            });
            count += u32::from(!apart);
        }
    }
    count
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(8))]
    #[test]
    fn pages_match_brute_force(
        ex in -50.0f64..50.0, ez in -50.0f64..50.0, ey in 1.0f64..20.0,
        yaw in -3.0f64..3.0, pitch in -0.6f64..0.2,
        lx in -1.0f64..1.0, lz in -1.0f64..1.0, tan in 0.3f64..1.2,
    ) {
        let light = DVec3::new(lx, -1.0, lz);
        let (cam, ground) = ground_scene(DVec3::new(ex, ey, ez), yaw, pitch, light, tan, 300.0);
        // 64 pages a side keep the brute force quick; the counting is the same at 128.
        let input = FrameInput::new(cam, light, 8192, 1080)
            .receivers(Bound::Boxes(&ground))
            .casters(Bound::Boxes(&ground));
        let opts = open(0.0, 128);
        let f = frame(&input.scheme(FrameScheme::Clipmap(opts))).unwrap();
        for m in f.maps().iter() {
            prop_assert_eq!(pages_touched(m, 64), pages_brute(m, 64));
        }
        let p = plan_clipmap(&input, &opts).unwrap();
        let total: u32 = f.maps().iter().map(|m| pages_brute(m, 64)).sum();
        prop_assert_eq!(p.pages(), u64::from(total));
    }
}

/// Pages per level do not depend on the level: with the camera at the origin the levels are
/// self-similar (footprint and pages both double), so every level whose depths are a whole
/// ratio of 2 needs the same pages.
#[test]
fn pages_per_level_do_not_depend_on_the_level() {
    for (alpha, tan) in [(1000.0, 0.577), (1e4, 0.4)] {
        let p = plan_clipmap(&overhead(alpha, tan, 1.0, 16384, 1080), &open(0.0, 128)).unwrap();
        let levels: Vec<_> = p.levels().collect();
        let inner = &levels[1..levels.len() - 1];
        assert!(inner.iter().all(|l| l.pages == inner[0].pages), "{inner:?}");
    }
}

/// Storage. With light overhead and aspect 1, the footprint of depths [a, b] is a trapezoid of
/// area (b² − a²) tan θ; at bias 0 a level holds it in area / t² texels. With pages of 4 texels
/// the pages come within 3 % of that hand area, and the storage factor Σ texels · E² / H²
/// approaches 1.5/ln 2 × Lloyd 2006's optimal ln(f/n) / (2 tan θ) (App. C) over whole levels;
/// z-partitions at ratio 2 store 2/ln 2 (Eq 17) and warped ones 1/ln 2 (Eq 18), as the frame's
/// own uniform and LiSPSM cascades measure.
#[test]
fn storage_against_lloyd() {
    let (alpha, tan) = (1024.0, 0.5);
    let input = overhead(alpha, tan, 1.0, 16384, 1080);
    let p = plan_clipmap(&input, &open(0.0, 4)).unwrap();
    let c = p.choice;
    let mut hand_texels = 0.0;
    for l in p.levels() {
        let (a, b) = l.depths;
        hand_texels += (b * b - a * a) * tan / (c.texel(l.level) * c.texel(l.level));
    }
    let texels = p.pages() as f64 * 16.0;
    assert!(
        texels >= hand_texels && texels <= 1.03 * hand_texels,
        "{texels} vs {hand_texels}"
    );
    let e = p.max_error_pixels();
    let optimal = alpha.ln() / (2.0 * tan);
    let ratio = texels * e * e / (1080.0 * 1080.0) / optimal;
    assert!((ratio - 1.5 / 2f64.ln()).abs() < 0.1, "{ratio}");
    // Z-partitions at ratio 2: k = 10.
    for (rule, hand) in [(WarpRule::Uniform, 2.0), (WarpRule::Lispsm, 1.0)] {
        let f = frame(&input.scheme(FrameScheme::Cascades {
            splits: CascadeSplits::Scheme {
                scheme: SplitScheme::SelfSimilar,
                k: 10,
                overlap: 0.0,
            },
            rule,
        }))
        .unwrap();
        let r = f.storage_factor().unwrap() / optimal;
        assert!((r - hand / 2f64.ln()).abs() < 1e-6, "{rule:?}: {r}");
    }
}

/// The pool's bias fits the pool, a bias 10⁻⁵ below it does not, and no bias of the grid
/// `least + k/64` below it does (the pages fall with the bias but not monotonically, so a finer
/// scan could find a bias between two grid points that fits; docs/planning.md).
#[test]
fn lod_bias_for_a_page_pool() {
    for (alpha, tan) in [(1000.0, 0.577), (100.0, 1.0), (1e4, 0.4)] {
        let input = overhead(alpha, tan, 1.0, 16384, 1080);
        let opts = open(0.0, 128);
        let least = LevelChoice::new(input.camera.view(), 1080, 16384, &open(-32.0, 128))
            .unwrap()
            .bias;
        for pool in [300u64, 700, 1140, 2000, 2500] {
            let Ok(p) = clipmap_for_pool(&input, &opts, pool) else {
                continue;
            };
            assert!(p.pages() <= pool);
            let found = p.choice.bias;
            let at = |b: f64| {
                plan_clipmap(
                    &input,
                    &ClipmapOptions {
                        lod_bias: b,
                        ..opts
                    },
                )
                .unwrap()
                .pages()
            };
            if found > least + 1e-5 {
                assert!(at(found - 1e-5) > pool, "α {alpha}, pool {pool}");
            }
            let mut k = 1.0;
            while least + k / 64.0 < found - 1e-9 {
                let b = least + k / 64.0;
                assert!(
                    at(b) > pool,
                    "α {alpha}: bias {b} fits {pool}, found {found}"
                );
                k += 1.0;
            }
        }
    }
    let input = overhead(1000.0, 0.577, 1.0, 16384, 1080);
    let opts = open(0.0, 128);
    // A pool below the pages of the coarsest bias that the last level allows, 0, and a last
    // level that no bias lets cover the far plane.
    let e = clipmap_for_pool(&input, &opts, 1).unwrap_err();
    assert!(
        e.to_string().contains("raise the pool or last_level"),
        "{e}"
    );
    assert_eq!(arg_name(e), "pool");
    let small = ClipmapOptions {
        last_level: 4,
        ..opts
    };
    assert_eq!(
        arg_name(clipmap_for_pool(&input, &small, 100).unwrap_err()),
        "last_level"
    );
    assert_eq!(
        arg_name(clipmap_for_pool(&input, &opts, 0).unwrap_err()),
        "pool"
    );
}

#[test]
fn bad_input_names_the_argument() {
    let input = overhead(1000.0, 0.577, 1.0, 16384, 1080);
    let bad = |o: ClipmapOptions| {
        let e = frame(&input.scheme(FrameScheme::Clipmap(o))).unwrap_err();
        let msg = e.to_string();
        (arg_name(e), msg)
    };
    let o = open(0.0, 128);
    for (opts, name) in [
        (
            ClipmapOptions {
                first_level: 5,
                last_level: 4,
                ..o
            },
            "first_level",
        ),
        (
            ClipmapOptions {
                first_level: -65,
                ..o
            },
            "first_level",
        ),
        (
            ClipmapOptions {
                last_level: 99,
                ..o
            },
            "last_level",
        ),
        (
            ClipmapOptions {
                lod_bias: f64::NAN,
                ..o
            },
            "lod_bias",
        ),
        (
            ClipmapOptions {
                lod_bias: 40.0,
                ..o
            },
            "lod_bias",
        ),
        (ClipmapOptions { unit: 0.0, ..o }, "unit"),
        (
            ClipmapOptions {
                unit: f64::INFINITY,
                ..o
            },
            "unit",
        ),
        (
            ClipmapOptions {
                page_texels: 0,
                ..o
            },
            "page_texels",
        ),
        (
            ClipmapOptions {
                page_texels: 100,
                ..o
            },
            "page_texels",
        ),
        (
            ClipmapOptions {
                page_texels: 16384,
                ..o
            },
            "page_texels",
        ),
        // The far plane needs level 11: last level 5 cannot cover it.
        (ClipmapOptions { last_level: 5, ..o }, "last_level"),
    ] {
        let (n, msg) = bad(opts);
        assert_eq!(n, name, "{msg}");
    }
    let (_, msg) = bad(ClipmapOptions { last_level: 5, ..o });
    assert!(msg.contains("raise last_level to 11"), "{msg}");
    // More levels than a frame holds: f/n = 10⁶ at bias 0 needs 21.
    let deep = overhead(1e6, 0.577, 1.0, 16384, 1080);
    let e = frame(&deep.scheme(FrameScheme::Clipmap(o))).unwrap_err();
    assert_eq!(arg_name(e), "depth_range");
}
