//! The uploaded record's texel extents, read back from the bytes a renderer uploads
//! (`GpuShadowMap::to_bytes`, decoded by docs/renderer.md's layout: `texel_extent` at byte 112,
//! s then t, little-endian `f32`s) and held to render-check's own measurement: the texel's
//! world-space edges along s and along t, from the exact derivatives of the map's `f64` world →
//! clip matrix at every vertex of the map's body B (the vectors perpendicular to the light that
//! move s, t by one texel, as render-check's geometry measures `texel_world`), each largest over
//! B. The record states the largest over B, rounded up to `f32`: each measured edge lies at or
//! under it, within its rounding. A warped map (the default scheme) has texels of different s and
//! t edges, so extents written in the wrong order fail.

mod common;

use glam::{DMat4, DVec3};
use shadow_aliasing::frame::{frame, FrameScheme};
use shadow_aliasing::maps::ClipDepth;
use shadow_aliasing::maps::WarpRule;

/// The world-space vectors ⊥ `l` that move clip s and t by one unit each at `p` under `m`
/// (render-check's own derivatives, as the plain run measures the texel).
fn edges(m: &DMat4, l: DVec3, p: DVec3) -> (DVec3, DVec3) {
    render_check::geometry::texel_edges(m, l, p).expect("a map that is not degenerate at p")
}

/// Little-endian `f32` at byte `at`.
fn f32_at(bytes: &[u8], at: usize) -> f64 {
    f64::from(f32::from_le_bytes([
        bytes[at],
        bytes[at + 1],
        bytes[at + 2],
        bytes[at + 3],
    ]))
}

#[test]
fn the_uploaded_texel_extents_are_the_measured_s_and_t_edges() {
    let ground = common::ground();
    let eye_to_world = common::view().inverse();
    let light = DVec3::new(0.3, -0.8, -0.4);
    let l = light.normalize();
    let mut anisotropic = 0;
    for scheme in [
        FrameScheme::Single(WarpRule::Lispsm),
        FrameScheme::Single(WarpRule::Uniform),
    ] {
        let input = common::input(&ground, light, 1024).scheme(scheme);
        let f = frame(&input).unwrap();
        for (k, m) in f.maps().iter().enumerate() {
            for depth in [
                ClipDepth::ZeroToOne,
                ClipDepth::Reversed,
                ClipDepth::NegOneToOne,
            ] {
                let bytes = m.gpu(depth).to_bytes();
                let uploaded = [f32_at(&bytes, 112), f32_at(&bytes, 116)];
                let clip = m.world_to_clip(depth);
                let texel = 2.0 / f64::from(m.resolution());
                let mut measured = [0.0f64; 2];
                for &p in m.body() {
                    let (es, et) = edges(&clip, l, eye_to_world.transform_point3(p));
                    measured[0] = measured[0].max(es.length() * texel);
                    measured[1] = measured[1].max(et.length() * texel);
                }
                for (axis, (u, w)) in ["s", "t"]
                    .into_iter()
                    .zip(uploaded.into_iter().zip(measured))
                {
                    assert!(
                        w > 0.0 && (u / w - 1.0).abs() <= 1e-5,
                        "{scheme:?} map {k}, {depth:?}: uploaded texel extent along {axis} {u} \
                         against the measured {w}"
                    );
                }
                if (measured[0] / measured[1] - 1.0).abs() > 0.01 {
                    anisotropic += 1;
                }
            }
        }
    }
    // The check can tell s from t: some map's texels differ along them by over 1 %.
    assert!(anisotropic > 0, "no map with distinct s and t edges");
}
