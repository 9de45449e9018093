//! The frame API (issue 9): focus bodies against hand-computed vertices, the uniform map's S̄ over
//! B by hand, minimax over B never above uniform over B, the frustum-only matrices reproduced, the
//! typed outcomes, Bevy's splits, and random scenes (every B vertex and every caster point that can
//! shadow B inside the clip volume; no NaN, no panic).

use glam::{DMat4, DVec3, DVec4};
use proptest::prelude::*;
use shadow_aliasing::analytic::partition::{z_splits, SplitScheme};
use shadow_aliasing::frame::{
    frame, Aabb, Bound, Camera, CascadeSplits, Focus, FrameInput, FrameScheme, LightCase,
    WarpCentre,
};
use shadow_aliasing::maps::cascades::cascades;
use shadow_aliasing::maps::{tsm, warp, ClipDepth, Falloff, TsmOptions, TsmSearch, WarpRule};
use shadow_aliasing::measure::{point_error, ShadowMap};
use shadow_aliasing::{Resolutions, ViewFrustum};

mod common;
use common::scene::{
    aabb, box_planes_eye, clip_coords, frustum_planes, random_scene, scene_params, shadowing_points,
};

/// Every rule, the engines' included.
fn rules() -> Vec<WarpRule> {
    vec![
        WarpRule::Uniform,
        WarpRule::Eta(0.3),
        WarpRule::Psm,
        WarpRule::Lispsm,
        WarpRule::LispsmFixed,
        WarpRule::Barroso(Falloff::Zhang),
        WarpRule::Tsm { focus: 3.0 },
        WarpRule::LispsmReference,
        WarpRule::Filament,
        WarpRule::FilamentHints {
            near_hint: 2.0,
            far_hint: 50.0,
        },
        WarpRule::Ogre,
        WarpRule::OgreOrtho {
            shadow_distance: 30.0,
        },
        WarpRule::Minimax,
        WarpRule::MinimaxMz,
    ]
}

/// Camera at the world origin looking down −Z: world = eye, n = 1, f = 10, tan θ = 1, square.
fn identity_camera() -> Camera {
    Camera::new(DMat4::IDENTITY, 1.0, 10.0, std::f64::consts::FRAC_PI_4, 1.0).unwrap()
}

fn same_points(got: &[DVec3], want: &[DVec3], tol: f64) {
    assert_eq!(got.len(), want.len(), "got {got:?}, want {want:?}");
    for w in want {
        assert!(
            got.iter().any(|g| (*g - *w).length() <= tol),
            "missing {w} in {got:?}"
        );
    }
}

#[test]
fn body_of_a_box_inside_the_frustum_is_the_box() {
    let boxes = [aabb([-1.0, -0.5, -6.0], [1.0, 0.5, -3.0])];
    let input = FrameInput::new(identity_camera(), DVec3::new(0.2, -1.0, 0.3), 1024, 1024)
        .receivers(Bound::Boxes(&boxes))
        .scheme(FrameScheme::Single(WarpRule::Uniform));
    let f = frame(&input).unwrap();
    assert_eq!(f.focus(), Focus::Body);
    let mut want = Vec::new();
    for x in [-1.0, 1.0] {
        for y in [-0.5, 0.5] {
            for z in [-6.0, -3.0] {
                want.push(DVec3::new(x, y, z));
            }
        }
    }
    same_points(f.maps()[0].body(), &want, 1e-12);
}

#[test]
fn body_of_a_box_across_the_frustum_by_hand() {
    // The lower half (y ≤ 0) between depths 2 and 5: with tan θ = 1 the frustum's cross-section at
    // depth d is |x|, |y| ≤ d, so B's vertices are (±d, −d, −d) and (±d, 0, −d) for d = 2, 5.
    let boxes = [aabb([-100.0, -100.0, -5.0], [100.0, 0.0, -2.0])];
    let input = FrameInput::new(identity_camera(), DVec3::new(0.0, -1.0, 0.0), 1024, 1024)
        .receivers(Bound::Boxes(&boxes))
        .scheme(FrameScheme::Single(WarpRule::Uniform));
    let f = frame(&input).unwrap();
    let mut want = Vec::new();
    for d in [2.0, 5.0] {
        for x in [-d, d] {
            want.push(DVec3::new(x, -d, -d));
            want.push(DVec3::new(x, 0.0, -d));
        }
    }
    let m = &f.maps()[0];
    same_points(m.body(), &want, 1e-9);
    // The uniform map over B by hand, light straight down: s spans x ∈ [−5, 5] (one unit texel of
    // width 10), t spans depth [2, 5] (width 3); the image beam width is 2 z tan θ = 2z, so
    // M_x = 10/(2·2) = 2.5, M_z = 3/(2·2) = 0.75 at the nearest depth, S̄ = 1.875.
    assert!((m.max_mx - 2.5).abs() < 1e-9, "{}", m.max_mx);
    assert!((m.max_mz - 0.75).abs() < 1e-9, "{}", m.max_mz);
    assert!((m.storage_factor - 1.875).abs() < 1e-9);
    assert_eq!(f.storage_factor(), Some(m.storage_factor));
    // Texel size: the larger edge, 10/1024 along s.
    assert!((m.texel_world - 10.0 / 1024.0).abs() < 1e-9);
    // Predicted error at 1024 image rows and a 1024 map: max(M_x, M_z) = 2.5 pixels.
    assert!((m.max_error_pixels - 2.5).abs() < 1e-9);
}

#[test]
fn boxes_outside_or_touching_give_no_map() {
    let cases = [
        // Behind the camera.
        aabb([-1.0, -1.0, 1.0], [1.0, 1.0, 3.0]),
        // Beyond the far plane.
        aabb([-1.0, -1.0, -30.0], [1.0, 1.0, -11.0]),
        // Touching the near plane's face from the eye's side (depth ≤ 1).
        aabb([-5.0, -5.0, -1.0], [5.0, 5.0, 0.0]),
        // Touching the far face from beyond.
        aabb([-50.0, -50.0, -20.0], [50.0, 50.0, -10.0]),
        // Touching the right side plane x = d along the edge at y = 0..: the box x ≥ d for all d
        // is not axis-aligned, so use the corner edge: x ≥ 10, y ≥ 10, depth 10 touches only the
        // far top-right corner (10, 10, −10).
        aabb([10.0, 10.0, -12.0], [12.0, 12.0, -10.0]),
        // Touching along the far face's top edge: y ≥ 10 at depth exactly 10 and beyond.
        aabb([-5.0, 10.0, -12.0], [5.0, 12.0, -10.0]),
    ];
    for b in cases {
        let boxes = [b];
        let input = FrameInput::new(identity_camera(), DVec3::new(0.3, -1.0, 0.2), 1024, 1024)
            .receivers(Bound::Boxes(&boxes));
        let f = frame(&input).unwrap();
        assert_eq!(f.focus(), Focus::Empty, "{b:?}");
        assert!(f.is_empty());
        assert_eq!(f.storage_factor(), None);
    }
}

#[test]
fn a_box_containing_the_frustum_reproduces_the_frustum_only_matrices() {
    let eye = DVec3::new(3.0, 2.0, 5.0);
    let view = glam::dcamera::rh::view::look_at_mat4(eye, DVec3::new(-4.0, 0.5, -20.0), DVec3::Y);
    let cam = Camera::new(view, 0.5, 60.0, 0.6, 1.5).unwrap();
    let vf = *cam.view();
    let huge = [aabb([-1e4, -1e4, -1e4], [1e4, 1e4, 1e4])];
    let lw = DVec3::new(0.3, -0.8, -0.4);
    for rule in rules() {
        for centre in [WarpCentre::Rule, WarpCentre::Eye] {
            if centre == WarpCentre::Eye
                && matches!(rule, WarpRule::Ogre | WarpRule::OgreOrtho { .. })
            {
                continue;
            }
            let input = FrameInput::new(cam, lw, 2048, 1080)
                .receivers(Bound::Boxes(&huge))
                .scheme(FrameScheme::Single(rule))
                .centre(centre);
            let f = frame(&input).unwrap();
            let l = f.light_dir_eye();
            let want = warp(&vf, l, rule).unwrap();
            let got = &f.maps()[0];
            if centre == WarpCentre::Rule {
                // The frustum-only builder itself: bit for bit.
                assert_eq!(got.shadow.matrix(), want.matrix(), "{rule:?}");
            } else {
                // The general path over B's vertices (the corners): to 1e-12.
                let d = (got.shadow.matrix() - want.matrix()).abs().to_cols_array();
                let scale = want
                    .matrix()
                    .abs()
                    .to_cols_array()
                    .into_iter()
                    .fold(0.0, f64::max);
                let worst = d.into_iter().fold(0.0, f64::max);
                assert!(worst <= 1e-12 * scale, "{rule:?}: {worst:e}");
            }
            assert_eq!(got.world_to_clip, got.shadow.matrix() * view);
            // The [0, 1] form is a function of `world_to_clip` alone (depth row (M₂ + M₃)/2, so
            // that a map `unchanged` is so in every form), the eye-space form's to rounding.
            let zo = got.world_to_clip(ClipDepth::ZeroToOne);
            let w = got.world_to_clip;
            for r in [0, 1, 3] {
                assert_eq!(zo.row(r), w.row(r));
            }
            assert_eq!(zo.row(2), 0.5 * (w.row(2) + w.row(3)));
            let eye = got.shadow.with_clip_depth(ClipDepth::ZeroToOne) * view;
            let d = (zo - eye)
                .abs()
                .to_cols_array()
                .into_iter()
                .fold(0.0, f64::max);
            assert!(d <= 1e-12 * eye.abs().to_cols_array().into_iter().fold(0.0, f64::max));
        }
    }
    // Cascades: the crate's cascades, bit for bit.
    let splits = z_splits(0.5, 60.0, 4, SplitScheme::Practical { lambda: 0.7 }).unwrap();
    let input = FrameInput::new(cam, lw, 2048, 1080)
        .receivers(Bound::Boxes(&huge))
        .scheme(FrameScheme::Cascades {
            splits: CascadeSplits::Scheme {
                scheme: SplitScheme::Practical { lambda: 0.7 },
                k: 4,
                overlap: 0.1,
            },
            rule: WarpRule::Lispsm,
        });
    let f = frame(&input).unwrap();
    let c = cascades(&vf, f.light_dir_eye(), &splits, WarpRule::Lispsm, 0.1).unwrap();
    assert_eq!(f.maps().len(), 4);
    for (got, want) in f.maps().iter().zip(c.iter()) {
        assert_eq!(got.shadow.matrix(), want.shadow.matrix());
        assert_eq!(got.split, (want.split_near, want.split_far));
        assert_eq!(got.blend, (want.split_far, want.shadow.far()));
        assert!((got.storage_factor - want.storage_factor()).abs() <= 1e-12 * got.storage_factor);
    }
}

#[test]
fn minimax_over_the_body_is_never_above_uniform_over_it() {
    let boxes = [
        aabb([-3.0, -2.0, -8.0], [4.0, 0.0, -1.5]),
        aabb([-20.0, -1.0, -9.0], [20.0, 0.5, -0.5]),
        aabb([0.0, -5.0, -6.0], [9.0, 5.0, -4.0]),
    ];
    for b in boxes {
        for lw in [
            DVec3::new(0.3, -1.0, 0.2),
            DVec3::new(0.0, -1.0, 0.0),
            DVec3::new(0.1, -0.3, -1.0),
            DVec3::new(-0.5, -0.2, 1.0),
            DVec3::new(0.9, -0.1, 0.0),
        ] {
            let bb = [b];
            let sf = |rule| {
                let input = FrameInput::new(identity_camera(), lw, 1024, 1024)
                    .receivers(Bound::Boxes(&bb))
                    .scheme(FrameScheme::Single(rule));
                frame(&input).unwrap().storage_factor().unwrap()
            };
            let (u, m) = (sf(WarpRule::Uniform), sf(WarpRule::Minimax));
            assert!(
                m <= u * (1.0 + 1e-9),
                "{b:?} {lw}: minimax {m} > uniform {u}"
            );
        }
    }
}

/// With the centre on B's vertex nearest the camera (OGRE's and the LiSPSM reference code's),
/// minimax chooses n′ for the map that is built around that centre, so it is never above the
/// uniform map either. (It used to choose n′ for the eye's centre: up to 6.2× uniform's S̄.)
/// Random boxes in and around a frustum with f/n = 100 and random lights.
#[test]
fn minimax_around_the_nearest_vertex_is_never_above_uniform() {
    let cam = Camera::new(DMat4::IDENTITY, 1.0, 100.0, 0.5, 1.0).unwrap();
    let mut rng = common::Lcg(0x9e37_79b9_7f4a_7c15);
    let mut rnd = || rng.next();
    let mut checked = 0;
    for _ in 0..400 {
        let c = DVec3::new(60.0 * rnd() - 30.0, 40.0 * rnd() - 20.0, -100.0 * rnd());
        let h = DVec3::new(1.0 + 30.0 * rnd(), 0.1 + 10.0 * rnd(), 1.0 + 40.0 * rnd());
        let b = [Aabb::new(c - h, c + h).unwrap()];
        let lw = DVec3::new(2.0 * rnd() - 1.0, -rnd() - 0.05, 2.0 * rnd() - 1.0);
        let sf = |rule| {
            let input = FrameInput::new(cam, lw, 1024, 1024)
                .receivers(Bound::Boxes(&b))
                .centre(WarpCentre::NearestVertex)
                .scheme(FrameScheme::Single(rule));
            frame(&input).unwrap().storage_factor()
        };
        let (Some(u), Some(m)) = (sf(WarpRule::Uniform), sf(WarpRule::Minimax)) else {
            continue;
        };
        checked += 1;
        assert!(
            m <= u * (1.0 + 1e-9),
            "{b:?} {lw}: minimax {m} > uniform {u} ({:.3}×)",
            m / u
        );
    }
    assert!(checked > 100, "only {checked} boxes in view");
}

/// The vertices carry the maximum: a dense sample of B (convex combinations of its vertices) never
/// exceeds the vertex maxima, measured point by point with `point_error`.
#[test]
fn body_maxima_lie_at_its_vertices() {
    let boxes = [aabb([-3.0, -2.0, -8.0], [4.0, 0.0, -1.5])];
    for rule in [WarpRule::Uniform, WarpRule::Lispsm, WarpRule::Minimax] {
        let input = FrameInput::new(identity_camera(), DVec3::new(0.3, -1.0, 0.2), 1024, 1024)
            .receivers(Bound::Boxes(&boxes))
            .scheme(FrameScheme::Single(rule));
        let f = frame(&input).unwrap();
        let m = &f.maps()[0];
        let body = m.body();
        let view = *identity_camera().view();
        let sm = ShadowMap::new(m.shadow.matrix(), f.light_dir_eye()).unwrap();
        let mut rng = common::Lcg(12345);
        let mut rnd = || rng.next();
        for _ in 0..2000 {
            let mut w = [0.0; 32];
            let mut sum = 0.0;
            for wi in w.iter_mut().take(body.len()) {
                *wi = rnd().powi(3);
                sum += *wi;
            }
            let p = body
                .iter()
                .zip(w)
                .fold(DVec3::ZERO, |a, (v, wi)| a + *v * (wi / sum));
            let e = point_error(&view, &sm, p, Resolutions::default()).unwrap();
            assert!(e.mx <= m.max_mx * (1.0 + 1e-9), "{rule:?}");
            assert!(e.mz <= m.max_mz * (1.0 + 1e-9), "{rule:?}");
        }
    }
}

#[test]
fn casters_extend_only_the_depth_range() {
    // Ground y ∈ [−1, 0]; a caster box high above the middle of the view.
    let ground = [aabb([-20.0, -1.0, -9.0], [20.0, 0.0, -1.0])];
    let tower = [aabb([-1.0, 0.0, -6.0], [1.0, 30.0, -4.0])];
    // The tower's top (0, 30, −5) shadows the ground at (1.5, 0, −3.5), inside the frustum.
    let lw = DVec3::new(0.05, -1.0, 0.05);
    let base = FrameInput::new(identity_camera(), lw, 1024, 1024)
        .receivers(Bound::Boxes(&ground))
        .scheme(FrameScheme::Single(WarpRule::Lispsm));
    let without = frame(&base).unwrap();
    let with = frame(&base.casters(Bound::Boxes(&tower))).unwrap();
    let clamp = frame(&base.casters(Bound::Boxes(&tower)).depth_clamp(true)).unwrap();
    let (a, b, c) = (&without.maps()[0], &with.maps()[0], &clamp.maps()[0]);
    // s, t rows (0, 1, 3) unchanged; S̄ unchanged.
    for r in [0, 1, 3] {
        let d = (a.shadow.matrix().row(r) - b.shadow.matrix().row(r))
            .abs()
            .max_element();
        assert!(d < 1e-12, "row {r}: {d:e}");
    }
    assert!((a.storage_factor - b.storage_factor).abs() < 1e-12 * a.storage_factor);
    assert_eq!(a.shadow.matrix(), c.shadow.matrix());
    // The tower's top, which shadows the ground, is inside the depth range with casters, below
    // depth −1 (clamped) without.
    let top = DVec3::new(0.0, 30.0, -5.0);
    let h = b.shadow.matrix() * top.extend(1.0);
    assert!((h.z / h.w).abs() <= 1.0 + 1e-9);
    let h = c.shadow.matrix() * top.extend(1.0);
    assert!(h.z / h.w < -1.0);
}

#[test]
fn degenerate_bodies_and_lights_have_typed_outcomes() {
    let cam = identity_camera();
    // A ground plane of zero thickness: flat, mapped.
    let plane = [aabb([-20.0, -1.0, -9.0], [20.0, -1.0, -1.0])];
    let f = frame(
        &FrameInput::new(cam, DVec3::new(0.2, -1.0, 0.1), 1024, 1024)
            .receivers(Bound::Boxes(&plane)),
    )
    .unwrap();
    assert_eq!(f.focus(), Focus::Flat);
    assert!(f.maps()[0].world_to_clip.is_finite());
    // The same plane with the light along it: edge-on, no map.
    let f = frame(
        &FrameInput::new(cam, DVec3::new(1.0, 0.0, 0.0), 1024, 1024)
            .receivers(Bound::Boxes(&plane)),
    )
    .unwrap();
    assert_eq!(f.focus(), Focus::EdgeOn);
    assert!(f.is_empty());
    // Stable cascades fit a world-fixed square (the slice's bounding sphere), not B: the same
    // edge-on plane is mapped (Flat), and its corners and centre land inside every map built.
    let f = frame(
        &FrameInput::new(cam, DVec3::new(1.0, 0.0, 0.0), 1024, 1024)
            .receivers(Bound::Boxes(&plane))
            .scheme(FrameScheme::Stable(CascadeSplits::Scheme {
                scheme: SplitScheme::Practical { lambda: 0.5 },
                k: 2,
                overlap: 0.0,
            })),
    )
    .unwrap();
    assert_eq!(f.focus(), Focus::Flat);
    assert!(!f.is_empty());
    for m in f.maps().iter() {
        assert_eq!(m.focus, Focus::Flat);
        // Points of the plane inside the slice (half field of view 45°: |x| ≤ depth).
        let (a, b) = (m.split.0.max(1.0), m.split.1.min(9.0));
        for d in [a, 0.5 * (a + b), b] {
            for x in [-0.9 * d, 0.0, 0.9 * d] {
                let h = m.world_to_clip * DVec3::new(x, -1.0, -d).extend(1.0);
                let (s, t) = (h.x / h.w, h.y / h.w);
                assert!(
                    s.abs() <= 1.0 && t.abs() <= 1.0,
                    "({x}, −1, {}): {s} {t}",
                    -d
                );
            }
        }
    }
    // A wall facing the camera at depth 5: zero depth, mapped unwarped.
    let wall = [aabb([-2.0, -2.0, -5.0], [2.0, 2.0, -5.0])];
    let f = frame(
        &FrameInput::new(cam, DVec3::new(0.2, -1.0, 0.1), 1024, 1024)
            .receivers(Bound::Boxes(&wall))
            .scheme(FrameScheme::Single(WarpRule::Lispsm)),
    )
    .unwrap();
    assert_eq!(f.focus(), Focus::ZeroDepth);
    assert_eq!(
        f.maps()[0].shadow.n_prime(),
        shadow_aliasing::NPrime::UNWARPED
    );
    // Sun straight down, camera looking horizontally: said so, finite.
    let f = frame(&FrameInput::new(
        cam,
        DVec3::new(0.0, -1.0, 0.0),
        1024,
        1024,
    ))
    .unwrap();
    assert_eq!(f.light_case(), LightCase::SunStraightDown);
    assert!(f.maps()[0].world_to_clip.is_finite());
    // Sun straight down, camera looking straight down: parallel to the view (that takes
    // precedence), uniform map, finite.
    let down = glam::dcamera::rh::view::look_at_mat4(
        DVec3::new(0.0, 10.0, 0.0),
        DVec3::ZERO,
        DVec3::NEG_Z,
    );
    let cam_down = Camera::new(down, 1.0, 10.0, 0.5, 1.0).unwrap();
    for rule in rules() {
        let f = frame(
            &FrameInput::new(cam_down, DVec3::new(0.0, -1.0, 0.0), 1024, 1024)
                .scheme(FrameScheme::Single(rule)),
        )
        .unwrap();
        assert_eq!(f.light_case(), LightCase::ParallelToView);
        assert!(f.maps()[0].world_to_clip.is_finite(), "{rule:?}");
    }
    // Bad input is a typed error.
    assert!(frame(&FrameInput::new(cam, DVec3::ZERO, 1024, 1024)).is_err());
    assert!(frame(&FrameInput::new(cam, DVec3::NEG_Y, 2, 1024)).is_err());
    assert!(frame(&FrameInput::new(cam, DVec3::NEG_Y, 1024, 1024).depth_range(5.0, 4.0)).is_err());
    assert!(Camera::new(DMat4::from_scale(DVec3::splat(2.0)), 1.0, 2.0, 0.5, 1.0).is_err());
    let none: [Aabb; 0] = [];
    assert!(
        frame(&FrameInput::new(cam, DVec3::NEG_Y, 1024, 1024).receivers(Bound::Boxes(&none)))
            .is_err()
    );
}

#[test]
fn visible_depth_range_cuts_the_body() {
    let f = frame(
        &FrameInput::new(identity_camera(), DVec3::new(0.2, -1.0, 0.1), 1024, 1024)
            .depth_range(2.0, 4.0)
            .scheme(FrameScheme::Single(WarpRule::Lispsm)),
    )
    .unwrap();
    let m = &f.maps()[0];
    assert_eq!(m.split, (2.0, 4.0));
    let view = ViewFrustum::new(2.0, 4.0, std::f64::consts::FRAC_PI_4).unwrap();
    assert_eq!(
        m.shadow.matrix(),
        warp(&view, f.light_dir_eye(), WarpRule::Lispsm)
            .unwrap()
            .matrix()
    );
}

#[test]
fn bevy_splits_by_hand() {
    // Bevy's defaults: 4 cascades, minimum 0.1, maximum 150, first far bound 10, overlap 0.2:
    // far bounds 10 · 15^{i/3}; cascade i > 0 starts at 0.8 × the previous far bound.
    let cam = Camera::new(DMat4::IDENTITY, 0.1, 1000.0, 0.6, 1.0).unwrap();
    let f = frame(
        &FrameInput::new(cam, DVec3::new(0.3, -1.0, 0.2), 2048, 1080).scheme(
            FrameScheme::Cascades {
                splits: CascadeSplits::Bevy {
                    k: 4,
                    minimum_distance: 0.1,
                    maximum_distance: 150.0,
                    first_far_bound: 10.0,
                    overlap_proportion: 0.2,
                },
                rule: WarpRule::Uniform,
            },
        ),
    )
    .unwrap();
    let fars = [
        10.0,
        10.0 * 15f64.cbrt(),
        10.0 * 15f64.cbrt().powi(2),
        150.0,
    ];
    assert_eq!(f.maps().len(), 4);
    for (i, m) in f.maps().iter().enumerate() {
        let near = if i == 0 { 0.1 } else { 0.8 * fars[i - 1] };
        assert!((m.shadow.near() - near).abs() < 1e-9 * fars[i], "{i}");
        assert!((m.shadow.far() - fars[i]).abs() < 1e-9 * fars[i], "{i}");
        let sel = if i == 0 { 0.1 } else { fars[i - 1] };
        assert!(
            (m.split.0 - sel).abs() < 1e-9 * fars[i]
                && (m.split.1 - fars[i]).abs() < 1e-9 * fars[i]
        );
        if i < 3 {
            assert!((m.blend.0 - 0.8 * fars[i]).abs() < 1e-9 * fars[i]);
        }
    }
    // Absolute distances and fractions give the same planes.
    let planes = [0.1, 1.0, 10.0, 100.0, 1000.0];
    let fr = [0.9 / 999.9, 9.9 / 999.9, 99.9 / 999.9];
    let a = frame(
        &FrameInput::new(cam, DVec3::new(0.3, -1.0, 0.2), 2048, 1080).scheme(
            FrameScheme::Cascades {
                splits: CascadeSplits::Distances {
                    planes: &planes,
                    overlap: 0.0,
                },
                rule: WarpRule::Lispsm,
            },
        ),
    )
    .unwrap();
    let b = frame(
        &FrameInput::new(cam, DVec3::new(0.3, -1.0, 0.2), 2048, 1080).scheme(
            FrameScheme::Cascades {
                splits: CascadeSplits::Fractions {
                    fractions: &fr,
                    overlap: 0.0,
                },
                rule: WarpRule::Lispsm,
            },
        ),
    )
    .unwrap();
    for (x, y) in a.maps().iter().zip(b.maps().iter()) {
        assert!((x.split.1 - y.split.1).abs() < 1e-9 * x.split.1);
    }
}

#[test]
fn stable_cascades_with_scene_bounds() {
    let ground = [aabb([-100.0, -1.0, -100.0], [100.0, 0.0, 100.0])];
    let view = glam::dcamera::rh::view::look_at_mat4(
        DVec3::new(0.0, 3.0, 0.0),
        DVec3::new(0.0, 2.0, -10.0),
        DVec3::Y,
    );
    let cam = Camera::new(view, 0.5, 500.0, 0.6, 16.0 / 9.0).unwrap();
    let input = FrameInput::new(cam, DVec3::new(0.3, -1.0, 0.2), 2048, 1080)
        .receivers(Bound::Boxes(&ground))
        .casters(Bound::Boxes(&ground))
        .scheme(FrameScheme::Stable(CascadeSplits::Scheme {
            scheme: SplitScheme::Practical { lambda: 0.8 },
            k: 4,
            overlap: 0.0,
        }));
    let f = frame(&input).unwrap();
    assert!(!f.is_empty());
    for m in f.maps().iter() {
        for p in m.body() {
            let h = m.shadow.matrix() * p.extend(1.0);
            assert!((h.truncate() / h.w).abs().max_element() <= 1.0 + 1e-9);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, failure_persistence: None, ..ProptestConfig::default() })]

    /// Random cameras, lights and boxes: every B vertex maps inside the clip volume, and every
    /// sampled caster point that can shadow B (its ray along the light meets B, by Cyrus–Beck on
    /// B's planes, not the frame's clipper) inside it too (nearer the light than depth 0 allowed
    /// with depth clamp); no NaN, no panic. About 7 600 caster points per run can shadow B.
    #[test]
    fn random_scenes_map_inside(
        params in scene_params(),
        rule_i in 0usize..14,
        clamp in any::<bool>(),
        cascaded in any::<bool>(),
        samples in prop::collection::vec(prop::array::uniform3(0.0f64..1.0), 100),
    ) {
        let Some(sc) = random_scene(&params) else {
            return Ok(());
        };
        let (view, cam, l) = (sc.view, sc.camera, sc.light);
        let (r, c) = ([sc.receivers], [sc.casters]);
        let rule = rules()[rule_i];
        // TSM's focus within the smallest slice (the first of three self-similar cascades).
        let rule = match rule { WarpRule::Tsm { .. } => WarpRule::Tsm { focus: 0.3 * params.near * (params.ratio.cbrt() - 1.0) }, r => r };
        let scheme = if let (false, WarpRule::Tsm { focus }) = (cascaded, rule) {
            // The trapezoidal map itself (not only its n′ rule) on B.
            FrameScheme::Tsm(TsmOptions { focus, search: TsmSearch::EightyPercent })
        } else if cascaded {
            FrameScheme::Cascades { splits: CascadeSplits::Scheme { scheme: SplitScheme::SelfSimilar, k: 3, overlap: 0.1 }, rule }
        } else {
            FrameScheme::Single(rule)
        };
        let input = FrameInput::new(cam, l, 1024, 1024)
            .receivers(Bound::Boxes(&r))
            .casters(Bound::Boxes(&c))
            .depth_clamp(clamp)
            .scheme(scheme);
        let f = match frame(&input) {
            Ok(f) => f,
            // A typed refusal (a map f64 cannot hold) is allowed; a panic or NaN is not.
            Err(e) => { prop_assert!(!e.to_string().is_empty()); return Ok(()); }
        };
        let le = f.light_dir_eye();
        prop_assert!(le.is_finite());
        let vf = *cam.view();
        for m in f.maps().iter() {
            prop_assert!(m.world_to_clip.is_finite() && m.storage_factor.is_finite() && m.storage_factor > 0.0);
            prop_assert!(m.texel_world.is_finite() && m.texel_world > 0.0);
            for p in m.body() {
                let q = clip_coords(m.shadow.matrix(), *p);
                prop_assert!(q.is_some_and(|q| q.abs().max_element() <= 1.0 + 1e-7), "B vertex {p} → {q:?}");
            }
            // The slice ∩ receivers as planes, for the ray test.
            let sub = vf.with_depth_range(m.shadow.near().max(vf.near()), m.shadow.far().min(vf.far()));
            let Ok(sub) = sub else { continue };
            let mut planes = Vec::new();
            planes.extend_from_slice(&frustum_planes(&sub));
            planes.extend_from_slice(&box_planes_eye(&r[0], view));
            let scale = vf.far();
            for pe in shadowing_points(&samples, &c[0], view, le, &planes, 1e-9 * scale) {
                let q = clip_coords(m.shadow.matrix(), pe);
                prop_assert!(q.is_some(), "caster {pe} behind the map");
                let q = q.unwrap();
                prop_assert!(q.x.abs() <= 1.0 + 1e-6 && q.y.abs() <= 1.0 + 1e-6, "caster {pe} → {q}");
                if clamp {
                    prop_assert!(q.z <= 1.0 + 1e-6);
                } else {
                    prop_assert!(q.z.abs() <= 1.0 + 1e-6, "caster depth {pe} → {q}");
                }
            }
        }
    }
}

/// A polytope bound with a box's six planes gives the box's maps, as receivers and as casters;
/// an unbounded caster polytope is a typed error.
#[test]
fn polytope_bounds_agree_with_boxes() {
    let ground = aabb([-20.0, -1.0, -9.0], [20.0, 0.0, -1.0]);
    let tower = aabb([-1.0, 0.0, -6.0], [1.0, 30.0, -4.0]);
    // World = eye (identity camera): the boxes' planes are the same in both spaces.
    let planes = |b: &Aabb| box_planes_eye(b, DMat4::IDENTITY);
    let (gp, tp) = (planes(&ground), planes(&tower));
    let (gb, tb) = ([ground], [tower]);
    let lw = DVec3::new(0.05, -1.0, 0.05);
    let base = FrameInput::new(identity_camera(), lw, 1024, 1024)
        .scheme(FrameScheme::Single(WarpRule::Lispsm));
    let a = frame(&base.receivers(Bound::Boxes(&gb)).casters(Bound::Boxes(&tb))).unwrap();
    let b = frame(
        &base
            .receivers(Bound::Polytope(&gp))
            .casters(Bound::Polytope(&tp)),
    )
    .unwrap();
    let (ma, mb) = (a.maps()[0].shadow.matrix(), b.maps()[0].shadow.matrix());
    let d = (ma - mb)
        .abs()
        .to_cols_array()
        .into_iter()
        .fold(0.0, f64::max);
    assert!(d < 1e-9, "{d:e}");
    // The tower reaches into the depth range in both (the casters moved depth).
    let plain = frame(&base.receivers(Bound::Boxes(&gb))).unwrap();
    assert_ne!(plain.maps()[0].shadow.matrix().row(2), mb.row(2));
    // A flat ground (zero thickness) as a box and as its six planes: both flat, the same map.
    let flat = aabb([-20.0, 0.0, -9.0], [20.0, 0.0, -1.0]);
    let fp = planes(&flat);
    let fa = frame(&base.receivers(Bound::Boxes(&[flat]))).unwrap();
    let fb = frame(&base.receivers(Bound::Polytope(&fp))).unwrap();
    assert_eq!(fa.focus(), Focus::Flat);
    assert_eq!(fb.focus(), Focus::Flat);
    let d = (fa.maps()[0].shadow.matrix() - fb.maps()[0].shadow.matrix())
        .abs()
        .to_cols_array()
        .into_iter()
        .fold(0.0, f64::max);
    assert!(d < 1e-9, "{d:e}");
    // Half-space casters (y ≥ 0): unbounded toward the light, a typed error.
    let half = [DVec4::new(0.0, -1.0, 0.0, 0.0)];
    assert!(frame(
        &base
            .receivers(Bound::Boxes(&gb))
            .casters(Bound::Polytope(&half))
    )
    .is_err());
}

/// TSM on a B that is the whole frustum is Martin & Tan's map of the frustum (s, t and w rows;
/// the depth row is refitted); on a scene box every B vertex lands in the clip volume.
#[test]
fn tsm_on_the_body() {
    let huge = [aabb([-1e4, -1e4, -1e4], [1e4, 1e4, 1e4])];
    let lw = DVec3::new(0.3, -0.8, -0.4);
    let opts = TsmOptions {
        focus: 3.0,
        search: TsmSearch::EightyPercent,
    };
    let f = frame(
        &FrameInput::new(identity_camera(), lw, 1024, 1024)
            .receivers(Bound::Boxes(&huge))
            .scheme(FrameScheme::Tsm(opts)),
    )
    .unwrap();
    let want = tsm(identity_camera().view(), f.light_dir_eye(), opts).unwrap();
    let got = f.maps()[0].shadow.matrix();
    for r in [0, 1, 3] {
        let d = (got.row(r) - want.shadow.matrix().row(r))
            .abs()
            .max_element();
        let scale = want.shadow.matrix().row(r).abs().max_element();
        assert!(d <= 1e-9 * scale, "row {r}: {d:e}");
    }
    let ground = [aabb([-20.0, -1.0, -9.0], [20.0, 0.0, -1.0])];
    let f = frame(
        &FrameInput::new(identity_camera(), lw, 1024, 1024)
            .receivers(Bound::Boxes(&ground))
            .scheme(FrameScheme::Tsm(opts)),
    )
    .unwrap();
    let m = &f.maps()[0];
    for p in m.body() {
        let h = m.shadow.matrix() * p.extend(1.0);
        assert!(h.w > 0.0 && (h.truncate() / h.w).abs().max_element() <= 1.0 + 1e-9);
    }
}
