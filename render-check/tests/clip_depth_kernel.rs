//! The WGSL module's three clip-depth conventions executed on the GPU (wgpu compute on Vulkan;
//! lavapipe without a GPU) and held to an invariance that needs none of the crate's functions:
//! the same map uploaded as a `ClipDepth::NegOneToOne`, a `ZeroToOne` and a `Reversed` record,
//! each read against a depth map stored in its own convention, must make the same lookups.
//!
//! The stored depths are the test's own, in `f64`: a ground plane (y = 0) found at every texel
//! centre by inverting each convention's `f64` world → clip matrix, then stored as a depth
//! attachment holds it (OpenGL's [−1, 1] as 0.5 z + 0.5, as glDepthRange(0, 1) does; the other
//! two as they are). Where the conventions relate exactly, in stored-depth units, OpenGL's stored
//! depth is the zero-to-one depth and reversed depth is 1 − it, so for every point, normal, bias
//! flag and PCF radius the GPU's projected depth (`sa_project` of the lookup point), the depth
//! bias applied (`sa_depth_bias`: the OpenGL record's bias is in [−1, 1] units and halved) and the
//! lookup point's normal offset (`sa_local_normal_offset`'s OpenGL depth gradient is halved too)
//! must agree across the three, and so must `sa_visibility`'s shaded fraction. Dropping any of the
//! module's OpenGL branches (sa_project's 0.5 z + 0.5, the offset's scale, the bias's halving)
//! breaks it; render-check's plain run uploads no OpenGL record and cannot see them.

mod common;

use glam::{DMat4, DVec3};
use render_check::compute;
use shadow_aliasing::frame::{frame, FrameMap, GpuShadowMap};
use shadow_aliasing::maps::ClipDepth;

/// The texels a side of the map (small: the stored depths travel in the cases buffer).
const RES: u32 = 64;

/// The conventions in the records' order (record i is read against stored layer i).
const DEPTHS: [ClipDepth; 3] = [
    ClipDepth::NegOneToOne,
    ClipDepth::ZeroToOne,
    ClipDepth::Reversed,
];

/// Floats per case in the cases buffer: p (3), n (3), the PCF radius, the bias flags.
const CASE_FLOATS: usize = 8;

/// Floats per case in the results: per convention, the lookup point's projected stored depth, the
/// depth bias applied (0 without SA_DEPTH_BIAS), the normal offset's length and the visibility.
const OUT_FLOATS: usize = 12;

/// The bindings (the stored depths of the three layers first in `cases`, then the cases) and the
/// entry point. `l` is the direction the light travels.
fn harness(l: DVec3) -> String {
    let layer = RES * RES;
    format!(
        "
@group(0) @binding(0) var<storage, read> records: array<GpuShadowMap>;
@group(0) @binding(1) var<storage, read> cases: array<f32>;
@group(0) @binding(2) var<storage, read_write> results: array<f32>;
fn sa_map(i: u32) -> GpuShadowMap {{ return records[i]; }}
fn sa_map_count() -> u32 {{ return arrayLength(&records); }}
fn sa_stored_depth(i: u32, texel: vec2<i32>) -> f32 {{
    return cases[i * {layer}u + u32(texel.y) * {RES}u + u32(texel.x)];
}}
@compute @workgroup_size(1)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {{
    let c = 3u * {layer}u + {CASE_FLOATS}u * id.x;
    let p = vec3<f32>(cases[c], cases[c + 1u], cases[c + 2u]);
    let n = vec3<f32>(cases[c + 3u], cases[c + 4u], cases[c + 5u]);
    let r = i32(cases[c + 6u]);
    let flags = u32(cases[c + 7u]);
    let l = vec3<f32>({lx:e}, {ly:e}, {lz:e});
    for (var i = 0u; i < 3u; i++) {{
        let m = records[i];
        var q = p;
        if ((flags & SA_LOCAL_NORMAL_OFFSET) != 0u) {{
            q = p + n * sa_local_normal_offset(m, p, n, l, r);
        }} else if ((flags & SA_NORMAL_OFFSET) != 0u) {{
            q = sa_offset_point(m, p, n, r);
        }}
        var b = 0.0;
        if ((flags & SA_DEPTH_BIAS) != 0u) {{
            b = sa_depth_bias(m, n, l, r);
        }}
        let o = {OUT_FLOATS}u * id.x + 4u * i;
        results[o] = sa_project(m, q).z;
        results[o + 1u] = b;
        results[o + 2u] = length(q - p);
        results[o + 3u] = sa_visibility(i, p, n, l, r, flags);
    }}
}}
",
        lx = l.x as f32,
        ly = l.y as f32,
        lz = l.z as f32,
    )
}

/// The stored depth of clip position (x, y) ∈ [−1, 1]² on the ground plane y = 0 through the map
/// matrix `clip` of convention `depth`, as the depth attachment holds it; 1 (the far depth,
/// reversed: 0) where the plane is not between the map's near and far planes there.
fn plane_depth(clip: &DMat4, depth: ClipDepth, x: f64, y: f64) -> f64 {
    let point = plane_point(clip, depth, x, y);
    let far = if depth == ClipDepth::Reversed {
        0.0
    } else {
        1.0
    };
    point.map_or(far, |p| stored(clip, depth, p))
}

/// Where the clip ray (x, y) of `clip` meets the plane y = 0 between the near and far depths.
fn plane_point(clip: &DMat4, depth: ClipDepth, x: f64, y: f64) -> Option<DVec3> {
    let inv = clip.inverse();
    let (z0, z1) = match depth {
        ClipDepth::NegOneToOne => (-1.0, 1.0),
        _ => (0.0, 1.0),
    };
    let a = inv.project_point3(DVec3::new(x, y, z0));
    let b = inv.project_point3(DVec3::new(x, y, z1));
    let t = a.y / (a.y - b.y);
    (0.0..=1.0).contains(&t).then(|| a + t * (b - a))
}

/// The depth attachment's value for world point `p` under `clip` of convention `depth`.
fn stored(clip: &DMat4, depth: ClipDepth, p: DVec3) -> f64 {
    let z = clip.project_point3(p).z;
    match depth {
        ClipDepth::NegOneToOne => 0.5 * z + 0.5,
        _ => z,
    }
}

/// A small deterministic generator (xorshift64*), uniform in [0, 1).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The frame's first map: the default scheme's warped (perspective) map of a ground box under an
/// oblique light, at `RES` texels.
fn map(light: DVec3) -> FrameMap {
    let ground = common::ground();
    let input = common::input(&ground, light, RES);
    let f = frame(&input).unwrap();
    f.maps()[0]
}

#[test]
fn the_three_clip_depth_conventions_make_the_same_lookups() {
    let light = DVec3::new(0.3, -0.8, -0.4);
    let l = light.normalize();
    let m = map(light);
    assert_eq!(m.resolution(), RES);
    let records: Vec<GpuShadowMap> = DEPTHS.iter().map(|&d| m.gpu(d)).collect();
    let clips: Vec<DMat4> = DEPTHS.iter().map(|&d| m.world_to_clip(d)).collect();
    // The stored layers: the ground plane at each texel centre (x from s = 0, rows down from t = 1).
    let mut data: Vec<f32> = Vec::new();
    for (clip, &depth) in clips.iter().zip(&DEPTHS) {
        for row in 0..RES {
            for col in 0..RES {
                let s = (f64::from(col) + 0.5) / f64::from(RES);
                let t = 1.0 - (f64::from(row) + 0.5) / f64::from(RES);
                data.push(plane_depth(clip, depth, 2.0 * s - 1.0, 2.0 * t - 1.0) as f32);
            }
        }
    }
    // The cases: points near the plane (within ±0.4 of the map's largest texel, above and below),
    // normals over the hemisphere facing up (some turned away from the light), every flag path.
    let zo = &clips[1];
    let texel = m.texel_world;
    let flag_sets = [0u32, 1, 2, 4, 3, 6];
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let mut cases = 0usize;
    let mut points = 0;
    while points < 300 {
        let (x, y) = (
            0.9 * (2.0 * rng.next() - 1.0),
            0.9 * (2.0 * rng.next() - 1.0),
        );
        let Some(on_plane) = plane_point(zo, ClipDepth::ZeroToOne, x, y) else {
            continue;
        };
        points += 1;
        let p = on_plane + DVec3::Y * (0.8 * rng.next() - 0.4) * texel;
        let n = DVec3::new(
            2.0 * rng.next() - 1.0,
            0.3 + rng.next(),
            2.0 * rng.next() - 1.0,
        )
        .normalize();
        for &flags in &flag_sets {
            for r in 0..3 {
                data.extend([p.x, p.y, p.z, n.x, n.y, n.z].map(|v| v as f32));
                data.extend([r as f32, flags as f32]);
                cases += 1;
            }
        }
    }
    let bytes: Vec<u8> = data.iter().flat_map(|v| v.to_le_bytes()).collect();
    let got = compute::run(
        "clip_depth_kernel",
        &harness(l),
        &records,
        &bytes,
        cases as u32,
        cases * OUT_FLOATS,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    // Stored-depth units of each convention mapped to zero-to-one's: OpenGL's as stored,
    // reversed's 1 − z (its bias −b).
    let mut vis_differ = 0;
    let mut biased = 0;
    let mut shaded_some = 0;
    for (k, out) in got.chunks_exact(OUT_FLOATS).enumerate() {
        let c = 3 * (RES * RES) as usize + CASE_FLOATS * k;
        let (r, flags) = (data[c + 6], data[c + 7] as u32);
        let [gl, z0, rev] = [0, 1, 2].map(|i| {
            let o = &out[4 * i..4 * i + 4];
            (
                f64::from(o[0]),
                f64::from(o[1]),
                f64::from(o[2]),
                f64::from(o[3]),
            )
        });
        let what = format!("case {k} (r = {r}, flags {flags})");
        // The projected depth: f32 products of matrices near depth 1, a few ulps.
        let depth_tol = 4e-6;
        assert!(
            (gl.0 - z0.0).abs() <= depth_tol,
            "{what}: OpenGL's stored depth {} against zero-to-one's {}",
            gl.0,
            z0.0
        );
        assert!(
            (1.0 - rev.0 - z0.0).abs() <= depth_tol,
            "{what}: reversed's 1 − z {} against zero-to-one's {}",
            1.0 - rev.0,
            z0.0
        );
        // The bias: the records' f32 values, in the conventions' ratio but for rounding. The
        // records' allowance for the compared depths' f32 rounding is 8 ulps of stored depth in
        // every convention (OpenGL's record holds 16 of its clip depth; when it held 8, its
        // stored bias was 4.77e-7 × (2r + 1) under the others'); the halving dropped doubles
        // the whole bias (here 3.8e-2 and more).
        let bias_tol = 1e-5 * z0.1.abs() + 1e-8;
        assert!(
            (gl.1 - z0.1).abs() <= bias_tol,
            "{what}: OpenGL's bias {} (stored units) against zero-to-one's {}",
            gl.1,
            z0.1
        );
        assert!(
            (-rev.1 - z0.1).abs() <= bias_tol,
            "{what}: reversed's bias {} against −(zero-to-one's) {}",
            rev.1,
            -z0.1
        );
        if flags & 2 != 0 {
            assert!(z0.1 < 0.0, "{what}: a depth bias of {} is no bias", z0.1);
            biased += 1;
        }
        // The normal offset (world units): the same lookup point.
        let off_tol = 1e-4 * z0.2 + 1e-6 * texel;
        for (name, o) in [("OpenGL", gl.2), ("reversed", rev.2)] {
            assert!(
                (o - z0.2).abs() <= off_tol,
                "{what}: {name}'s normal offset {o} against zero-to-one's {}",
                z0.2
            );
        }
        if gl.3 != z0.3 || rev.3 != z0.3 {
            vis_differ += 1;
        }
        if z0.3 < 1.0 {
            shaded_some += 1;
        }
    }
    assert_eq!(
        vis_differ, 0,
        "{vis_differ} of {cases} lookups' visibility differs between the conventions"
    );
    // The cases decide something: some lookups shaded, some biased.
    assert!(biased > 0 && shaded_some > cases / 10 && shaded_some < cases);
}
