//! The frame API side by side with the engine ports of `benches/reference/` (issue 23 item 9),
//! on the scenes of `builders/frame_*_scene`, in one run (`engines/NAME`):
//!
//! - `frame_lispsm`, `frame_lispsm_unmeasured`: one LiSPSM map (`builders/frame_lispsm_scene`);
//!   `filament_lispsm`: Filament's `updateCascadeShadowMaps` with one cascade (its culling pass
//!   over the frustum, then the map), `filament_lispsm_map`: the map alone (`updateDirectional`);
//!   `bevy_single`: Bevy's one cascade over [1, 1000];
//! - `frame_practical4`, `frame_practical4_unmeasured`: four LiSPSM cascades, practical λ = 0.8
//!   (`builders/frame_practical4_scene`); `filament_practical4` and `filament_practical4_maps`:
//!   Filament's four cascades at the same split distances, with and without the culling pass;
//!   `bevy_cascades4`: Bevy's four cascades at the same distances, no overlap;
//! - `frame_stable4`, `frame_stable4_unmeasured`: four stable cascades
//!   (`builders/frame_cascades4_scene`), Bevy's counterpart (`bevy_cascades4`).
//!
//! Run it with the unit (docs/performance.md):
//!
//! ```text
//! cargo bench --bench reference --bench engines -- --warm-up-time 1 --measurement-time 3
//! ```

// The ports also serve examples/engine_defaults.rs and the tests: not every item is benched.
#[allow(dead_code)]
#[path = "reference/bevy_cascade.rs"]
mod bevy_cascade;
#[path = "reference/filament_directional.rs"]
mod filament_directional;

use criterion::{criterion_group, criterion_main, Criterion};
use glam::{DMat4, DVec3, Mat4};
use shadow_aliasing::analytic::partition::{z_splits, SplitScheme};
use shadow_aliasing::frame::{
    frame_into, Aabb, Bound, Camera, CascadeSplits, Frame, FrameInput, FrameScheme,
};
use shadow_aliasing::maps::WarpRule;
use std::hint::black_box as bb;

fn engines(c: &mut Criterion) {
    // The scene of `builders/frame_*_scene`: camera at the world origin looking down −Z, n = 1,
    // f = 1000, half field of view 30°, square; light (0.3, −0.8, −0.4); receivers a ground box
    // [−50, 50] × [−5, 0] × [−100, 0]; casters that box and a tower [−10, 10] × [0, 20] × [−60, −40];
    // 2048² maps.
    let light = DVec3::new(0.3, -0.8, -0.4);
    let cam = Camera::new(DMat4::IDENTITY, 1.0, 1000.0, 30f64.to_radians(), 1.0).unwrap();
    let ground = Aabb::new(DVec3::new(-50.0, -5.0, -100.0), DVec3::new(50.0, 0.0, 0.0)).unwrap();
    let tower = Aabb::new(DVec3::new(-10.0, 0.0, -60.0), DVec3::new(10.0, 20.0, -40.0)).unwrap();
    let receivers = [ground];
    let casters = [ground, tower];
    let scene = FrameInput::new(cam, light, 2048, 1080)
        .receivers(Bound::Boxes(&receivers))
        .casters(Bound::Boxes(&casters));
    let practical = CascadeSplits::Scheme {
        scheme: SplitScheme::Practical { lambda: 0.8 },
        k: 4,
        overlap: 0.0,
    };
    let single = scene.scheme(FrameScheme::Single(WarpRule::Lispsm));
    let cascades = scene.scheme(FrameScheme::Cascades {
        splits: practical,
        rule: WarpRule::Lispsm,
    });
    let stable = scene.scheme(FrameScheme::Stable(practical));
    let planes = z_splits(1.0, 1000.0, 4, SplitScheme::Practical { lambda: 0.8 }).unwrap();
    let planes = planes.planes();

    // Filament: the same camera (vertical field of view 60°), light, boxes and map size.
    use filament_directional as fl;
    let fcam = fl::CameraInfo::perspective(Mat4::IDENTITY, 60.0, 1.0, 1.0, 1000.0);
    let fbox = |a: &Aabb, cast, receive| fl::Renderable {
        aabb: fl::Aabb {
            min: a.min.as_vec3(),
            max: a.max.as_vec3(),
        },
        cast_shadows: cast,
        receive_shadows: receive,
    };
    let renderables = [fbox(&ground, true, true), fbox(&tower, true, false)];
    let fdir = light.as_vec3().normalize();
    let fopts = fl::ShadowOptions::default();
    let finfo = fl::ShadowMapInfo::new(2048);
    // Filament's split positions are fractions of [near, far].
    let fractions: Vec<f32> = planes[1..4]
        .iter()
        .map(|p| ((p - 1.0) / 999.0) as f32)
        .collect();

    // Bevy: the same camera and light, the same split distances.
    use bevy_cascade as bv;
    let projection = bv::PerspectiveProjection {
        fov: 60f32.to_radians(),
        aspect_ratio: 1.0,
    };
    let rot = bv::light_rotation_looking_to(light.as_vec3());
    let bevy_single = bv::CascadeShadowConfig {
        bounds: [1000.0, 0.0, 0.0, 0.0],
        count: 1,
        overlap_proportion: 0.0,
        minimum_distance: 1.0,
    };
    let bevy4 = bv::CascadeShadowConfig {
        bounds: [
            planes[1] as f32,
            planes[2] as f32,
            planes[3] as f32,
            planes[4] as f32,
        ],
        count: 4,
        overlap_proportion: 0.0,
        minimum_distance: 1.0,
    };

    let mut out = Frame::default();
    let mut fout: [Option<fl::DirectionalMap>; 4] = [None; 4];
    let mut bout = [bv::Cascade::default(); 4];
    // What each produces on these scenes (maps with shadows), for the report.
    for (name, input) in [
        ("single", &single),
        ("practical4", &cascades),
        ("stable4", &stable),
    ] {
        frame_into(input, &mut out).unwrap();
        eprintln!("frame {name}: {} maps", out.maps().len());
    }
    for (name, f) in [("single", &[][..]), ("practical4", &fractions[..])] {
        let n = fl::update_cascade_shadow_maps(
            fdir,
            &fcam,
            &fopts,
            &finfo,
            &renderables,
            f,
            true,
            false,
            &mut fout,
        );
        eprintln!("filament {name}: {n} maps");
    }

    let mut g = c.benchmark_group("engines");
    g.bench_function("frame_lispsm", |b| {
        b.iter(|| frame_into(bb(&single), &mut out))
    });
    let unmeasured = single.measure(false);
    g.bench_function("frame_lispsm_unmeasured", |b| {
        b.iter(|| frame_into(bb(&unmeasured), &mut out))
    });
    g.bench_function("filament_lispsm", |b| {
        b.iter(|| {
            let n = fl::update_cascade_shadow_maps(
                bb(fdir),
                bb(&fcam),
                &fopts,
                &finfo,
                bb(&renderables),
                bb(&[]),
                true,
                false,
                &mut fout,
            );
            bb(&fout);
            n
        })
    });
    g.bench_function("filament_lispsm_map", |b| {
        b.iter(|| {
            let n = fl::update_cascade_shadow_maps(
                bb(fdir),
                bb(&fcam),
                &fopts,
                &finfo,
                bb(&renderables),
                bb(&[]),
                false,
                false,
                &mut fout,
            );
            bb(&fout);
            n
        })
    });
    g.bench_function("bevy_single", |b| {
        b.iter(|| {
            bv::build_directional_light_cascades(
                bb(rot),
                bb(Mat4::IDENTITY),
                bb(&projection),
                bb(&bevy_single),
                bb(2048),
                &mut bout,
            );
            bb(&bout);
        })
    });
    g.bench_function("frame_practical4", |b| {
        b.iter(|| frame_into(bb(&cascades), &mut out))
    });
    let cascades_unmeasured = cascades.measure(false);
    g.bench_function("frame_practical4_unmeasured", |b| {
        b.iter(|| frame_into(bb(&cascades_unmeasured), &mut out))
    });
    g.bench_function("filament_practical4", |b| {
        b.iter(|| {
            let n = fl::update_cascade_shadow_maps(
                bb(fdir),
                bb(&fcam),
                &fopts,
                &finfo,
                bb(&renderables),
                bb(&fractions),
                true,
                false,
                &mut fout,
            );
            bb(&fout);
            n
        })
    });
    g.bench_function("filament_practical4_maps", |b| {
        b.iter(|| {
            let n = fl::update_cascade_shadow_maps(
                bb(fdir),
                bb(&fcam),
                &fopts,
                &finfo,
                bb(&renderables),
                bb(&fractions),
                false,
                false,
                &mut fout,
            );
            bb(&fout);
            n
        })
    });
    g.bench_function("bevy_cascades4", |b| {
        b.iter(|| {
            bv::build_directional_light_cascades(
                bb(rot),
                bb(Mat4::IDENTITY),
                bb(&projection),
                bb(&bevy4),
                bb(2048),
                &mut bout,
            );
            bb(&bout);
        })
    });
    g.bench_function("frame_stable4", |b| {
        b.iter(|| frame_into(bb(&stable), &mut out))
    });
    let stable_unmeasured = stable.measure(false);
    g.bench_function("frame_stable4_unmeasured", |b| {
        b.iter(|| frame_into(bb(&stable_unmeasured), &mut out))
    });
    g.finish();
}

criterion_group!(benches, engines);
criterion_main!(benches);
