//! The upload boundary (issue 23 item 1): `GpuShadowMap`'s layout against the WGSL and std140
//! rules computed here from the WGSL text, its bytes, and every upload value's array form
//! against the glam value it stands for.

use glam::{DVec3, Mat4};
use shadow_aliasing::frame::{
    frame, Aabb, Bound, Camera, FrameInput, FrameScheme, GpuShadowMap, GPU_SHADOW_MAP_WGSL,
};
use shadow_aliasing::maps::faces::{Face, FaceWarp};
use shadow_aliasing::maps::{ClipDepth, WarpRule};
use std::mem::{offset_of, size_of};

/// The Rust record's fields and their offsets, by name.
fn rust_offsets() -> Vec<(&'static str, usize)> {
    vec![
        ("world_to_clip", offset_of!(GpuShadowMap, world_to_clip)),
        ("split", offset_of!(GpuShadowMap, split)),
        ("blend", offset_of!(GpuShadowMap, blend)),
        ("texel_world", offset_of!(GpuShadowMap, texel_world)),
        (
            "max_error_pixels",
            offset_of!(GpuShadowMap, max_error_pixels),
        ),
        ("max_mx", offset_of!(GpuShadowMap, max_mx)),
        ("max_mz", offset_of!(GpuShadowMap, max_mz)),
        ("face", offset_of!(GpuShadowMap, face)),
        ("clip_depth", offset_of!(GpuShadowMap, clip_depth)),
        ("normal_offset", offset_of!(GpuShadowMap, normal_offset)),
        (
            "slope_scaled_depth",
            offset_of!(GpuShadowMap, slope_scaled_depth),
        ),
        ("texel_extent", offset_of!(GpuShadowMap, texel_extent)),
        ("constant_depth", offset_of!(GpuShadowMap, constant_depth)),
        ("bias_radius", offset_of!(GpuShadowMap, bias_radius)),
        ("resolution", offset_of!(GpuShadowMap, resolution)),
        (
            "normal_offset_growth",
            offset_of!(GpuShadowMap, normal_offset_growth),
        ),
        ("reserved1", offset_of!(GpuShadowMap, reserved1)),
        ("reserved2", offset_of!(GpuShadowMap, reserved2)),
    ]
}

/// The members of `struct GpuShadowMap { … }` in the WGSL text: (name, type).
fn wgsl_members() -> Vec<(String, String)> {
    let body = GPU_SHADOW_MAP_WGSL
        .split("struct GpuShadowMap {")
        .nth(1)
        .and_then(|s| s.split('}').next())
        .expect("the WGSL text declares struct GpuShadowMap");
    body.split(',')
        .map(str::trim)
        .filter(|m| !m.is_empty())
        .map(|m| {
            let (n, t) = m.split_once(':').expect("name: type");
            (n.trim().to_string(), t.trim().to_string())
        })
        .collect()
}

/// (alignment, size) of a WGSL type in the uniform address space (WGSL §14.4.1, "Alignment and
/// Size"), and of the std140 type it corresponds to (GLSL 4.6 §7.6.2.2, rules 1–5: a
/// column-major mat4 is an array of 4 vec4, each aligned to 16).
fn layout(ty: &str, std140: bool) -> (usize, usize) {
    match (ty, std140) {
        ("f32" | "u32" | "i32", _) => (4, 4),
        ("vec2<f32>" | "vec2<u32>", _) => (8, 8),
        ("vec4<f32>", _) => (16, 16),
        ("mat4x4<f32>", false) => (16, 64),
        // std140 rule 5: an array of 4 column vectors of 4 components, stride 16.
        ("mat4x4<f32>", true) => (16, 4 * 16),
        _ => panic!("type {ty} not in the table"),
    }
}

fn round_up(a: usize, x: usize) -> usize {
    x.div_ceil(a) * a
}

/// Offsets and size of the struct by the rules: each member at the next multiple of its
/// alignment; the struct's alignment the largest member's, rounded up to 16 in the uniform
/// address space (WGSL) and to a vec4's in std140 (rule 9); its size the end rounded up to it.
fn struct_layout(std140: bool) -> (Vec<(String, usize)>, usize) {
    let (mut at, mut align, mut out) = (0, 0, vec![]);
    for (name, ty) in wgsl_members() {
        let (a, s) = layout(&ty, std140);
        at = round_up(a, at);
        out.push((name, at));
        at += s;
        align = align.max(a);
    }
    let align = round_up(16, align);
    (out, round_up(align, at))
}

#[test]
fn record_layout_is_the_wgsl_and_std140_layout() {
    let rust = rust_offsets();
    for std140 in [false, true] {
        let (offsets, size) = struct_layout(std140);
        assert_eq!(size, 144);
        assert_eq!(size_of::<GpuShadowMap>(), size, "std140 {std140}");
        assert_eq!(GpuShadowMap::SIZE, size);
        assert_eq!(offsets.len(), rust.len(), "every field in the WGSL struct");
        for ((wn, wo), (rn, ro)) in offsets.iter().zip(&rust) {
            assert_eq!((wn.as_str(), *wo), (*rn, *ro), "std140 {std140}");
        }
    }
    // An array element's stride is its size in both layouts: a multiple of 16.
    assert_eq!(size_of::<[GpuShadowMap; 3]>(), 3 * 144);
    // Every field is made of 4-byte words, so `#[repr(C)]` adds no padding of its own.
    assert_eq!(std::mem::align_of::<GpuShadowMap>(), 4);
}

#[test]
fn wgsl_constants_match_the_codes() {
    for (name, depth) in [
        ("CLIP_DEPTH_NEG_ONE_TO_ONE", ClipDepth::NegOneToOne),
        ("CLIP_DEPTH_ZERO_TO_ONE", ClipDepth::ZeroToOne),
        ("CLIP_DEPTH_REVERSED", ClipDepth::Reversed),
    ] {
        let decl = format!(
            "const {name}: u32 = {}u;",
            GpuShadowMap::clip_depth_code(depth)
        );
        assert!(GPU_SHADOW_MAP_WGSL.contains(&decl), "{decl}");
    }
    assert!(GPU_SHADOW_MAP_WGSL.contains("const NO_FACE: u32 = 0xffffffffu;"));
    assert_eq!(GpuShadowMap::NO_FACE, 0xffff_ffff);
}

fn camera() -> Camera {
    let view = glam::dcamera::rh::view::look_at_mat4(
        DVec3::new(3.0, 4.0, 10.0),
        DVec3::new(3.5, 3.0, -5.0),
        DVec3::Y,
    );
    Camera::new(view, 0.5, 300.0, 0.55, 1.6).unwrap()
}

fn ground() -> [Aabb; 2] {
    [
        Aabb::new([-80.0, -1.0, -250.0], [80.0, 0.0, 20.0]).unwrap(),
        Aabb::new(DVec3::new(-5.0, 0.0, -20.0), DVec3::new(5.0, 12.0, -10.0)).unwrap(),
    ]
}

/// Reads the little-endian word at `offset`.
fn word(b: &[u8], offset: usize) -> u32 {
    u32::from_le_bytes(b[offset..offset + 4].try_into().unwrap())
}

#[test]
fn record_and_arrays_carry_the_maps_values() {
    let boxes = ground();
    let schemes = [
        FrameScheme::Single(WarpRule::Lispsm),
        FrameScheme::Faces {
            rule: FaceWarp::Lispsm,
            k: 2,
        },
    ];
    let mut faces_seen = 0;
    for scheme in schemes {
        let input = FrameInput::new(camera(), [0.3, -1.0, -0.4], 2048, 1080)
            .receivers(Bound::Boxes(&boxes[..1]))
            .casters(Bound::Boxes(&boxes))
            .scheme(scheme);
        let f = frame(&input).unwrap();
        assert!(!f.is_empty());
        for m in f.maps().iter() {
            for depth in ClipDepth::ALL {
                let mat: Mat4 = m.world_to_clip(depth).as_mat4();
                let cols = m.world_to_clip_cols(depth);
                assert_eq!(cols, mat.to_cols_array_2d());
                // Column-major: column 3 holds the translation, so a world point p maps to
                // Σ_c cols[c] · (p, 1)[c].
                let p = DVec3::new(1.0, 0.5, -30.0);
                let h = m.world_to_clip(depth) * p.extend(1.0);
                for r in 0..4 {
                    let by_cols: f64 = (0..4)
                        .map(|c| f64::from(cols[c][r]) * [p.x, p.y, p.z, 1.0][c])
                        .sum();
                    assert!((by_cols - h[r]).abs() <= 1e-5 * (1.0 + h[r].abs()));
                }
                let g = m.gpu(depth);
                assert_eq!(g.world_to_clip, cols);
                assert_eq!(g.split, [m.split.0 as f32, m.split.1 as f32]);
                assert_eq!(g.blend, [m.blend.0 as f32, m.blend.1 as f32]);
                assert_eq!(g.texel_world, m.texel_world as f32);
                assert_eq!(g.max_error_pixels, m.max_error_pixels as f32);
                assert_eq!((g.max_mx, g.max_mz), (m.max_mx as f32, m.max_mz as f32));
                assert_eq!(g.clip_depth, GpuShadowMap::clip_depth_code(depth));
                let face = match m.face {
                    None => GpuShadowMap::NO_FACE,
                    Some(f) => {
                        faces_seen += 1;
                        Face::ALL.iter().position(|a| *a == f).unwrap() as u32
                    }
                };
                assert_eq!(g.face, face);
                // The bytes: each field at its offset, little-endian.
                let b = g.to_bytes();
                for (c, col) in cols.iter().enumerate() {
                    for (r, v) in col.iter().enumerate() {
                        assert_eq!(word(&b, 16 * c + 4 * r), v.to_bits());
                    }
                }
                assert_eq!(f32::from_bits(word(&b, 64)), g.split[0]);
                assert_eq!(f32::from_bits(word(&b, 76)), g.blend[1]);
                assert_eq!(f32::from_bits(word(&b, 80)), g.texel_world);
                assert_eq!(f32::from_bits(word(&b, 92)), g.max_mz);
                assert_eq!(word(&b, 96), face);
                assert_eq!(word(&b, 100), g.clip_depth);
                // The bias values (issue 23 item 5): r = 0's, and r = 2's from `gpu_with_pcf`.
                let bias = m.bias(0.0, depth).unwrap();
                assert_eq!(g.normal_offset, bias.normal_offset as f32);
                assert_eq!(g.slope_scaled_depth, bias.slope_scaled_depth as f32);
                assert_eq!(
                    g.texel_extent,
                    [bias.texel_extent.0 as f32, bias.texel_extent.1 as f32]
                );
                assert_eq!(g.constant_depth, bias.constant_depth as f32);
                let g2 = m.gpu_with_pcf(depth, 2.0).unwrap();
                let b2 = m.bias(2.0, depth).unwrap();
                assert_eq!(g2.normal_offset, b2.normal_offset as f32);
                assert_eq!(g2.constant_depth, b2.constant_depth as f32);
                // The record says which kernel its bias values are for, so that the shader's
                // `sa_kernel_scale` does not count a `gpu_with_pcf` kernel twice.
                assert_eq!(g.bias_radius, 0.0);
                assert_eq!(g2.bias_radius, 2.0);
                assert_eq!(f32::from_bits(word(&g2.to_bytes(), 124)), 2.0);
                // Camera-relative with PCF: gpu_relative's matrix, gpu_with_pcf's bias values.
                let o = DVec3::new(3.0, -2.0, 7.5);
                let g3 = m.gpu_relative_with_pcf(o, depth, 2.0).unwrap();
                assert_eq!(
                    g3,
                    GpuShadowMap {
                        world_to_clip: m.gpu_relative(o, depth).world_to_clip,
                        ..g2
                    }
                );
                assert!(m.gpu_relative_with_pcf(o, depth, -1.0).is_err());
                // The depth bias ∝ r + ½ (docs/renderer.md): the record for r = 2 is the r = 0
                // record times 5 = (2r + 1)/(2·0 + 1), the factor `sa_kernel_scale(m, 2)` applies
                // to an r = 0 record and that it does not apply again to an r = 2 record. The
                // normal offset grows faster than r + ½ where the map's w varies (the offset
                // point's own footprint, `frame::bias`): at least 5 times, exactly for an
                // orthographic map.
                let (s0, s2) = (bias.slope_scaled_depth, b2.slope_scaled_depth);
                assert!(
                    (s2 - 5.0 * s0).abs() <= 1e-9 * s2.abs(),
                    "{s2} against 5 × {s0}"
                );
                let (n0, n2) = (bias.normal_offset, b2.normal_offset);
                assert!(n2 >= 5.0 * n0 * (1.0 - 1e-9), "{n2} against 5 × {n0}");
                if m.shadow.n_prime().value().is_infinite() {
                    assert!((n2 - 5.0 * n0).abs() <= 1e-9 * n2, "{n2} against 5 × {n0}");
                }
                assert_eq!(f32::from_bits(word(&b, 104)), g.normal_offset);
                assert_eq!(f32::from_bits(word(&b, 108)), g.slope_scaled_depth);
                assert_eq!(f32::from_bits(word(&b, 112)), g.texel_extent[0]);
                assert_eq!(f32::from_bits(word(&b, 116)), g.texel_extent[1]);
                assert_eq!(f32::from_bits(word(&b, 120)), g.constant_depth);
                // bias_radius 0.0; the map's resolution (the frame's, here); the normal offset's
                // growth τ rounded up to f32 (0 for an orthographic map); two zero words.
                assert_eq!(&b[124..128], &[0u8; 4]);
                assert_eq!(word(&b, 128), 2048, "the frame's map_resolution");
                let tau = f32::from_bits(word(&b, 132));
                assert_eq!(tau, g.normal_offset_growth);
                assert!(f64::from(tau) >= bias.normal_offset_growth, "{tau}");
                assert_eq!(tau < 1.0, bias.normal_offset.is_finite(), "{tau}");
                assert!(
                    f64::from(tau) <= bias.normal_offset_growth * (1.0 + 1e-6),
                    "{tau}"
                );
                if m.shadow.n_prime().value().is_infinite() {
                    assert_eq!(tau, 0.0, "an orthographic map's offset grows as its reach");
                }
                assert_eq!(&b[136..], &[0u8; 8]);
                #[cfg(feature = "bytemuck")]
                if cfg!(target_endian = "little") {
                    assert_eq!(bytemuck::bytes_of(&g), &b[..]);
                }
            }
        }
    }
    assert!(faces_seen > 0, "the face partition's maps name their faces");
}

#[cfg(feature = "mint")]
#[test]
fn mint_in_and_out_is_glams_own_value() {
    use glam::DMat4;
    use shadow_aliasing::mint;
    let view = camera().world_to_eye();
    let via_mint = Camera::new(mint::ColumnMatrix4::from(view), 0.5, 300.0, 0.55, 1.6).unwrap();
    assert_eq!(via_mint, camera());
    let boxes = ground();
    let sun = mint::Vector3::from([0.3, -1.0, -0.4]);
    let input = FrameInput::new(via_mint, sun, 1024, 720).receivers(Bound::Boxes(&boxes[..1]));
    let a = frame(&input).unwrap();
    let b = frame(
        &FrameInput::new(camera(), DVec3::new(0.3, -1.0, -0.4), 1024, 720)
            .receivers(Bound::Boxes(&boxes[..1])),
    )
    .unwrap();
    assert_eq!(a, b);
    let m = &a.maps()[0];
    let out: mint::ColumnMatrix4<f32> = m.to_mint(ClipDepth::ZeroToOne);
    assert_eq!(Mat4::from(out), m.to_mat4(ClipDepth::ZeroToOne));
    let out64: mint::ColumnMatrix4<f64> = m.world_to_clip_mint(ClipDepth::NegOneToOne);
    assert_eq!(DMat4::from(out64), m.world_to_clip);
    // mint's columns are the arrays' columns.
    assert_eq!(out.w.x, m.world_to_clip_cols(ClipDepth::ZeroToOne)[3][0]);
}
