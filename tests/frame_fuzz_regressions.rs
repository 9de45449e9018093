//! Findings of the `frame` fuzz target (fuzz/fuzz_targets/frame.rs, docs/fuzzing.md), decoded
//! into plain calls of the public API, each fixed: a typed refusal or the right value.

use glam::{DMat4, DVec3};
use shadow_aliasing::frame::{frame, Bound, Camera, CascadeSplits, FrameInput, FrameScheme};
use shadow_aliasing::maps::{ClipDepth, WarpRule};

/// Finding 2: `CascadeSplits::Bevy` with a far bound beyond the camera's far plane builds a
/// cascade whose selection range `split` is inverted. Cascade 1 covers [(1 − 0.9)·200, 100] =
/// [20, 100] (its far bound 400 clamped to far = 100), but its selection starts at the previous
/// far bound 200, which is not clamped: `split = (200, 100)`. (The fuzzer's input: near 4.60,
/// far 2526.4, Bevy k = 5, minimum 2309.2, maximum 5052.8, first far bound 4875.5, overlap
/// 0.936, `FrameScheme::Stable`: map 1's split (4875.5, 2526.4).)
#[test]

fn bevy_split_beyond_the_far_plane_is_not_inverted() {
    let cam = Camera::new(DMat4::IDENTITY, 1.0, 100.0, 0.7, 1.0).unwrap();
    let splits = CascadeSplits::Bevy {
        k: 2,
        minimum_distance: 50.0,
        maximum_distance: 400.0,
        first_far_bound: 200.0,
        overlap_proportion: 0.9,
    };
    for scheme in [
        FrameScheme::Cascades {
            splits,
            rule: WarpRule::Uniform,
        },
        FrameScheme::Stable(splits),
    ] {
        let input = FrameInput::new(cam, DVec3::new(0.3, -1.0, 0.2), 2048, 1080)
            .receivers(Bound::Unbounded)
            .scheme(scheme);
        let f = frame(&input).unwrap();
        for m in f.maps().iter() {
            // Fails: the second map's split is (200.0, 100.0).
            assert!(
                m.split.0 <= m.split.1,
                "{scheme:?}: split {:?} (cover {} to {})",
                m.split,
                m.shadow.near(),
                m.shadow.far()
            );
        }
    }
}

/// Finding 1: a camera far from the world origin (translation 10¹⁵⁰, a valid rigid transform)
/// gives an `Ok` map whose f64 `world_to_clip` is finite but whose GPU form `to_mat4` has an
/// infinite entry (the translation column times the map's scale exceeds `f32::MAX`); neither
/// `Camera::new` nor `to_mat4` documents a limit. (The fuzzer's input: translation
/// (π/2 − 1 ulp, π/2 − 1 ulp, 10¹⁵⁰), near 570.75, far 170 320, half FOV 1.5585, light
/// (0, 0, 1), `Single(Uniform)`.)
#[test]

fn to_mat4_of_a_camera_far_from_the_origin_is_finite_or_refused() {
    let view = DMat4::from_translation(DVec3::new(0.0, 0.0, 1e150));
    let cam = Camera::new(view, 1.0, 100.0, 0.5, 1.0).unwrap();
    let input = FrameInput::new(cam, DVec3::new(0.3, -1.0, 0.2), 2048, 1080)
        .scheme(FrameScheme::Single(WarpRule::Uniform));
    // A typed refusal is a fix too.
    if let Ok(f) = frame(&input) {
        let m = &f.maps()[0];
        assert!(m.world_to_clip(ClipDepth::NegOneToOne).is_finite());
        // Fails: an entry of the translation column is inf in f32.
        let g = m.to_mat4(ClipDepth::NegOneToOne);
        assert!(g.is_finite(), "{g:?}");
    }
}

/// Finding 3: a rigid camera far from the world origin gives an `Ok` map whose f64
/// `world_to_clip` has an infinite entry (the frame's `shadow.matrix() * world_to_eye` overflows;
/// `frame` documents `Error::Degenerate` "when a map cannot be represented in f64"). The eye-space
/// map is finite; only the world form overflows: translation 10³⁰⁵ times the map's scale (its s
/// row ~ 1/(frustum width)). (The fuzzer's input: translation (1.8e-10, −5.83e303, −0), near
/// 0.0058232, far 0.0059589, half FOV 2.3968e-5, light (0, 0, 1), 4 texels, depth clamp,
/// `Single(Uniform)`: world_to_clip's w column (0.0012, −inf, 86.9, 1).)
#[test]

fn world_to_clip_of_a_camera_far_from_the_origin_is_finite_or_refused() {
    let view = DMat4::from_translation(DVec3::new(0.0, 1e305, 0.0));
    let cam = Camera::new(view, 0.001, 0.002, 1e-4, 1.0).unwrap();
    let input = FrameInput::new(cam, DVec3::new(0.3, -1.0, 0.2), 2048, 1080)
        .scheme(FrameScheme::Single(WarpRule::Uniform));
    // Fails: Ok, with an infinite entry in world_to_clip.
    if let Ok(f) = frame(&input) {
        let m = &f.maps()[0];
        assert!(m.shadow.matrix().is_finite());
        assert!(m.world_to_clip.is_finite(), "{:?}", m.world_to_clip);
    }
}

/// Finding 4: `FrameScheme::Stable` with a camera far from the world origin maps vertices of its
/// focus body outside the clip volume (`Ok`, no error). `stable_map` snaps the slice's centre in
/// world light space and composes `ortho · light rotation · eye_to_world`: the world position's
/// rounding (ulp(|t|)) is amplified by 1/half-width, and the map is not checked against B
/// (`verify_clip`) as the other builders' are. (The fuzzer's input: translation (−1e-7, 1.9e-10,
/// −4.39e304), near 10, far 1920.35, half FOV 0.00611, light (0, −1, 0), depth clamp,
/// `Stable(Scheme { SelfSimilar, k: 8, overlap: 0.173 })`: map 0 sends the B vertex
/// (−0.0611, −0.0611, −10) to (0.011, 1.83, 0.48). Here the translation is −10²⁰: the vertex
/// goes to y = −2046; at 10¹² it passes.)
#[test]

fn stable_cascades_of_a_camera_far_from_the_origin_cover_their_body() {
    let splits = CascadeSplits::Scheme {
        scheme: shadow_aliasing::analytic::partition::SplitScheme::SelfSimilar,
        k: 8,
        overlap: 0.17268134584573128,
    };
    // At 10¹² the maps are built and cover B; at 10²⁰ the rounding of the world position is
    // larger than the cascade and the frame refuses it (it mapped B to y = −2046 before).
    for (t, built) in [(-1e12, true), (-1e20, false)] {
        let view = DMat4::from_translation(DVec3::new(0.0, 0.0, t));
        let cam = Camera::new(view, 10.0, 1920.3510901774164, 0.006111954701731852, 1.0).unwrap();
        let input = FrameInput::new(cam, DVec3::new(0.0, -1.0, 0.0), 1024, 1024)
            .depth_clamp(true)
            .scheme(FrameScheme::Stable(splits));
        match frame(&input) {
            Ok(f) => {
                assert!(built, "translation {t}: built");
                for (i, m) in f.maps().iter().enumerate() {
                    for p in m.body() {
                        let h = m.shadow.matrix() * p.extend(1.0);
                        let c = h.truncate() / h.w;
                        assert!(
                            h.w > 0.0 && c.abs().max_element() <= 1.0 + 1e-6,
                            "map {i}: {p} -> {c}"
                        );
                    }
                }
            }
            Err(e) => {
                assert!(!built, "translation {t}: {e}");
                assert!(matches!(e, shadow_aliasing::Error::Degenerate(_)), "{e}");
            }
        }
    }
}

/// Finding 5: `FrameScheme::Stable` over a frustum reaching `f64::MAX` builds a non-finite matrix
/// in `stable_map` and hands it to `ShadowMatrix::new` unchecked: a panic inside the crate in a
/// debug build (`debug_assert!(matrix.is_finite())`, src/measure/mod.rs), an `Ok` with a
/// non-finite matrix in release; `frame` documents `Error::Degenerate` instead. (The fuzzer's
/// input: translation (−24, 51, 51), near 3.06e201, far f64::MAX, half FOV 0.290, light
/// (0, 0, 1), 128 texels, depth clamp, `Stable(Distances { planes: [2.08e305, 5.38e307,
/// 1.06e308, 1.51e308], overlap: 0.0078 })`.)
#[test]

fn stable_cascades_reaching_f64_max_are_finite_or_refused() {
    let view = DMat4::from_translation(DVec3::new(-24.0, 51.0, 51.0));
    let cam = Camera::new(
        view,
        3.063596093810738e201,
        f64::MAX,
        0.29020999030811473,
        1.0,
    )
    .unwrap();
    let planes = [
        2.084758957038773e305,
        5.37840379877095e307,
        1.0645163269184692e308,
        1.5139464683937753e308,
    ];
    let splits = CascadeSplits::Distances {
        planes: &planes,
        overlap: 0.007789562829022659,
    };
    let input = FrameInput::new(cam, DVec3::new(0.0, 0.0, 1.0), 128, 128)
        .depth_clamp(true)
        .scheme(FrameScheme::Stable(splits));
    // Fails: panics inside `frame` (debug build), or an Ok with a non-finite matrix.
    if let Ok(f) = frame(&input) {
        for m in f.maps().iter() {
            assert!(m.shadow.matrix().is_finite(), "{:?}", m.shadow.matrix());
        }
    }
}
