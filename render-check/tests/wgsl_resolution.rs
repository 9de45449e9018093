//! Each map's own resolution (`FrameInput::map_resolutions`), read by the WGSL module from the
//! map's record, executed on the GPU (wgpu compute on Vulkan; lavapipe without a GPU): the texel
//! a point falls in and the PCF kernel's clamp to the map's last texel, for two maps of one frame
//! at 16 and 64 texels a side, against the texel computed by hand from the point's map position.
//! The harness declares no `sa_map_resolution` (the module needs none), and its stored depth is
//! an occluder outside the map's own texels, as a smaller map drawn into a larger texture layer
//! leaves the rest of the layer: a kernel clamped to any other resolution reads it.

mod common;

use glam::{DMat4, DVec3, DVec4};
use render_check::compute;
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::frame::{frame, CascadeSplits, FrameScheme};
use shadow_aliasing::maps::{ClipDepth, WarpRule};

const EACH: [u32; 2] = [16, 64];

/// The harness: records, cases (a world point and the map to look it up in, with the PCF
/// radius), results (the texel's x and y, and the lit fraction). Stored depths: the farthest
/// (lit) inside map i's own `resolution` texels, the nearest (an occluder) outside them.
const HARNESS: &str = "
struct Case { p: vec4<f32>, map: u32, r: i32, pad0: u32, pad1: u32 }
@group(0) @binding(0) var<storage, read> records: array<GpuShadowMap>;
@group(0) @binding(1) var<storage, read> cases: array<Case>;
@group(0) @binding(2) var<storage, read_write> results: array<f32>;
fn sa_map(i: u32) -> GpuShadowMap { return records[i]; }
fn sa_map_count() -> u32 { return arrayLength(&records); }
fn sa_stored_depth(i: u32, t: vec2<i32>) -> f32 {
    let n = i32(records[i].resolution);
    if (all(t >= vec2<i32>(0)) && all(t < vec2<i32>(n))) { return 1.0; }
    return 0.0;
}
@compute @workgroup_size(1)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let c = cases[id.x];
    let m = records[c.map];
    let t = sa_texel(m, sa_project(m, c.p.xyz).xy);
    results[3u * id.x] = f32(t.x);
    results[3u * id.x + 1u] = f32(t.y);
    results[3u * id.x + 2u] = sa_visibility(c.map, c.p.xyz, vec3<f32>(0.0, 1.0, 0.0),
        vec3<f32>(0.0, -1.0, 0.0), c.r, 0u);
}
";

#[test]
fn each_map_is_looked_up_at_its_own_resolution() {
    let ground = common::ground();
    let input = common::input(&ground, DVec3::new(0.3, -0.8, -0.4), 1024)
        .scheme(FrameScheme::Cascades {
            splits: CascadeSplits::Scheme {
                scheme: SplitScheme::Practical { lambda: 0.5 },
                k: 2,
                overlap: 0.0,
            },
            rule: WarpRule::Uniform,
        })
        .map_resolutions(&EACH);
    let f = frame(&input).unwrap();
    assert_eq!(f.maps().len(), 2);
    let depth = ClipDepth::ZeroToOne;
    let records: Vec<_> = f.maps().iter().map(|m| m.gpu(depth)).collect();
    // Per map: texel centres across the map, the last column and row among them, each at the
    // middle of the map's depth range; the world point by the f64 inverse of the map.
    let mut cases = Vec::new();
    let mut want = Vec::new();
    for (i, m) in f.maps().iter().enumerate() {
        let res = EACH[i];
        let inv: DMat4 = m.world_to_clip(depth).inverse();
        for (tx, ty) in [
            (0, 0),
            (res / 3, res / 2),
            (res - 1, 2),
            (5, res - 1),
            (res - 1, res - 1),
        ] {
            // Texel (tx, ty): rows run down from t = 1.
            let s = (f64::from(tx) + 0.5) / f64::from(res);
            let t = 1.0 - (f64::from(ty) + 0.5) / f64::from(res);
            let h = inv * DVec4::new(2.0 * s - 1.0, 2.0 * t - 1.0, 0.5, 1.0);
            let p = h.truncate() / h.w;
            for r in [0i32, 2] {
                cases.push((p, i as u32, r));
                want.push((tx, ty));
            }
        }
    }
    let mut bytes = Vec::new();
    for (p, i, r) in &cases {
        for v in [p.x as f32, p.y as f32, p.z as f32, 1.0] {
            bytes.extend(v.to_le_bytes());
        }
        bytes.extend(i.to_le_bytes());
        bytes.extend(r.to_le_bytes());
        bytes.extend([0u8; 8]);
    }
    let out = compute::run(
        "wgsl_resolution",
        HARNESS,
        &records,
        &bytes,
        cases.len() as u32,
        3 * cases.len(),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    for (k, ((p, i, r), (tx, ty))) in cases.iter().zip(&want).enumerate() {
        let got = (out[3 * k], out[3 * k + 1]);
        assert_eq!(
            got,
            (*tx as f32, *ty as f32),
            "map {i} at {} texels, point {p}: texel",
            EACH[*i as usize]
        );
        // Every tap of the kernel clamped inside the map's own texels: lit.
        assert_eq!(
            out[3 * k + 2],
            1.0,
            "map {i} r {r} at texel ({tx}, {ty}): lit fraction"
        );
    }
}
