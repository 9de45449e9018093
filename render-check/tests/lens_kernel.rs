//! The WGSL module's error lens and its colour ramp executed on the GPU (wgpu compute on Vulkan;
//! lavapipe without a GPU): `sa_error_lens` agrees with the library's `f64`
//! `FrameMap::error_lens_at` to `f32` rounding (relative 10⁻⁴) on points of B with random normals,
//! for several schemes, with the records uploaded relative to the camera
//! (`FrameMap::gpu_relative`), and `sa_lens_colour` with `frame::lens::lens_colour` to 10⁻⁵.

use glam::{DMat4, DVec3};
use render_check::compute;
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::frame::lens::lens_colour;
use shadow_aliasing::frame::{
    frame, Aabb, Bound, Camera, CascadeSplits, FrameInput, FrameScheme, GpuShadowMap,
};
use shadow_aliasing::maps::faces::FaceWarp;
use shadow_aliasing::maps::{ClipDepth, WarpRule};

/// The entry point after `compute::harness_prelude("f32")`: it writes, per case, the lens and
/// the colour of a value.
const MAIN: &str = "
@compute @workgroup_size(1)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    let c = 16u * i;
    let p = vec3<f32>(cases[c], cases[c + 1u], cases[c + 2u]);
    let n = vec3<f32>(cases[c + 3u], cases[c + 4u], cases[c + 5u]);
    let l = vec3<f32>(cases[c + 6u], cases[c + 7u], cases[c + 8u]);
    let forward = vec3<f32>(cases[c + 9u], cases[c + 10u], cases[c + 11u]);
    let m = records[u32(cases[c + 13u])];
    results[4u * i] = sa_error_lens(m, p, n, l, vec3<f32>(0.0), forward, cases[c + 12u]);
    let colour = sa_lens_colour(cases[c + 14u]);
    results[4u * i + 1u] = colour.x;
    results[4u * i + 2u] = colour.y;
    results[4u * i + 3u] = colour.z;
}
";

/// Runs the harness: per case (16 `f32`s: p, n, l, forward, focal pixels, record index, colour
/// value, unused), (lens, r, g, b).
fn run(records: &[GpuShadowMap], cases: &[[f32; 16]]) -> Vec<[f32; 4]> {
    let harness = format!("{}{MAIN}", compute::harness_prelude("f32"));
    let bytes: Vec<u8> = cases
        .iter()
        .flatten()
        .flat_map(|x| x.to_le_bytes())
        .collect();
    compute::run(
        "lens harness",
        &harness,
        records,
        &bytes,
        cases.len() as u32,
        cases.len() * 4,
    )
    .unwrap_or_else(|e| panic!("{e}"))
    .chunks_exact(4)
    .map(|c| [c[0], c[1], c[2], c[3]])
    .collect()
}

/// Knuth's MMIX LCG: a number in [0, 1).
fn next(state: &mut u64) -> f64 {
    *state = state
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    (*state >> 11) as f64 / (1u64 << 53) as f64
}

#[test]
fn the_gpu_lens_is_the_library_lens_to_f32_rounding() {
    let ground = [Aabb::new([-60.0, -1.0, -80.0], [60.0, 0.5, 60.0]).unwrap()];
    let eye = DVec3::new(3.0, 6.0, 20.0);
    let view = glam::dcamera::rh::view::look_at_mat4(eye, DVec3::new(2.0, 0.0, -10.0), DVec3::Y);
    let (half_fov, image_h) = (0.6f64, 720u32);
    let camera = Camera::new(view, 0.5, 120.0, half_fov, 1.5).unwrap();
    let light = DVec3::new(0.3, -0.8, -0.4);
    let l = light.normalize();
    let eye_to_world: DMat4 = view.inverse();
    let forward = eye_to_world.transform_vector3(DVec3::NEG_Z).normalize();
    let focal = f64::from(image_h) / (2.0 * half_fov.tan());
    let schemes = [
        FrameScheme::Single(WarpRule::Lispsm),
        FrameScheme::Single(WarpRule::Uniform),
        FrameScheme::Cascades {
            splits: CascadeSplits::Scheme {
                scheme: SplitScheme::Practical { lambda: 0.8 },
                k: 3,
                overlap: 0.0,
            },
            rule: WarpRule::Lispsm,
        },
        FrameScheme::Faces {
            rule: FaceWarp::Lispsm,
            k: 2,
        },
    ];
    let mut records = Vec::new();
    let mut cases = Vec::new();
    let mut want = Vec::new();
    let mut state = 7u64;
    for scheme in schemes {
        let input = FrameInput::new(camera, light, 1024, image_h)
            .receivers(Bound::Boxes(&ground))
            .casters(Bound::Boxes(&ground))
            .scheme(scheme);
        let f = frame(&input).unwrap();
        for m in f.maps().iter() {
            let index = records.len();
            records.push(m.gpu_relative(eye, ClipDepth::ZeroToOne));
            let body: Vec<DVec3> = m
                .body()
                .iter()
                .map(|p| eye_to_world.transform_point3(*p))
                .collect();
            for _ in 0..24 {
                let w: Vec<f64> = body.iter().map(|_| next(&mut state) + 1e-3).collect();
                let sum: f64 = w.iter().sum();
                let p: DVec3 = body.iter().zip(&w).map(|(p, w)| *p * (*w / sum)).sum();
                let n = DVec3::new(
                    next(&mut state) - 0.5,
                    next(&mut state) - 0.5,
                    next(&mut state) - 0.5,
                )
                .normalize();
                if n.dot(l).abs() < 0.1 || n.dot((eye - p).normalize()).abs() < 0.1 {
                    continue;
                }
                let lens = m.error_lens_at(p, n, &camera, image_h).unwrap();
                // A colour value over the ramp and beyond its ends: 2^-6 … 2^7 pixels.
                let value = (2f64).powf(-6.0 + 13.0 * next(&mut state));
                let q = p - eye;
                let case = [
                    q.x,
                    q.y,
                    q.z,
                    n.x,
                    n.y,
                    n.z,
                    l.x,
                    l.y,
                    l.z,
                    forward.x,
                    forward.y,
                    forward.z,
                    focal,
                    index as f64,
                    value,
                    0.0,
                ];
                cases.push(case.map(|x| x as f32));
                want.push((lens, lens_colour(f64::from(value as f32))));
            }
        }
    }
    assert!(cases.len() >= 100, "only {} cases", cases.len());
    let got = run(&records, &cases);
    let mut worst = 0.0f64;
    for (k, (g, (lens, colour))) in got.iter().zip(&want).enumerate() {
        let rel = (f64::from(g[0]) - lens).abs() / lens;
        worst = worst.max(rel);
        assert!(rel <= 1e-4, "case {k}: GPU lens {} against {lens}", g[0]);
        for c in 0..3 {
            assert!(
                (f64::from(g[c + 1]) - colour[c]).abs() <= 1e-5,
                "case {k}: GPU colour {:?} against {colour:?}",
                &g[1..]
            );
        }
    }
    eprintln!(
        "{} cases, largest relative difference {worst:.2e}",
        got.len()
    );
}
