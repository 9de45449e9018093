//! The engines' rules as their shipped code builds them (issue 11): OGRE's centre of projection
//! at the near camera point, OGRE 13.6's orthographic light space (n′ scaled by shadowDist),
//! Filament's light frame once |cos γ| ≥ 0.9997. Expected values are the engines' formulas by
//! hand and properties of a perspective map, not the builders' arithmetic.

#[allow(dead_code)]
#[path = "../benches/reference/bevy_cascade.rs"]
mod bevy_cascade;
#[allow(dead_code)]
#[path = "../benches/reference/threejs_csm.rs"]
mod threejs_csm;

use glam::DVec3;
use shadow_aliasing::maps::{light_space, n_prime_for, warp, WarpRule};
use shadow_aliasing::measure::frustum_max;
use shadow_aliasing::{Error, NPrime, ViewFrustum};

fn view() -> ViewFrustum {
    ViewFrustum::new(1.0, 100.0, 30f64.to_radians()).unwrap()
}

/// s = x_c/w of a map at an eye-space point.
fn s_of(m: &glam::DMat4, p: DVec3) -> f64 {
    let h = *m * p.extend(1.0);
    h.x / h.w
}

/// OGRE's `C_start = (e_ls.x, e_ls.y, z_max)` + n′ along the warp axis, e the near camera point
/// (the top-right near vertex (w, h, −n) for the bare frustum): every point on a ray from that
/// centre has the same s (a perspective map's lines through its centre of projection). A
/// centre on the eye's light-space x, as the builders use for the other rules, does not.
#[test]
fn ogre_centre_of_projection_is_the_near_camera_point() {
    let view = view();
    let l = DVec3::new(0.3, -0.5, -0.8).normalize();
    let ls = light_space(l, DVec3::NEG_Z).unwrap();
    let n_prime = n_prime_for(&view, l, WarpRule::Ogre).unwrap().value();
    // |cos γ| = 0.808 < 0.9: no ramp, n′ = (n + √(n f)) · 0.1 = 1.1.
    assert!((n_prime - 1.1).abs() < 1e-12, "{n_prime}");
    let corners = view.corners();
    let z0 = corners
        .iter()
        .map(|c| ls.z.dot(*c))
        .fold(f64::INFINITY, f64::min);
    let t = view.tan_half_fov();
    let e = ls.to_light(DVec3::new(t, t, -1.0));
    let centre = ls.x * e.x + ls.y * e.y + ls.z * (z0 - n_prime);
    let eye_centre = ls.z * (z0 - n_prime);
    let ogre = warp(&view, l, WarpRule::Ogre).unwrap().matrix();
    let p = DVec3::new(-20.0, 5.0, -60.0);
    for h in [0.3, 0.7] {
        let q = centre + h * (p - centre);
        assert!(
            (s_of(&ogre, p) - s_of(&ogre, q)).abs() < 1e-12,
            "{} vs {}",
            s_of(&ogre, p),
            s_of(&ogre, q)
        );
        let q_eye = eye_centre + h * (p - eye_centre);
        assert!((s_of(&ogre, p) - s_of(&ogre, q_eye)).abs() > 1e-4);
    }
    // The map covers the frustum: every corner inside the clip volume.
    for c in corners {
        let h = ogre * c.extend(1.0);
        assert!(h.w > 0.0 && (h.truncate() / h.w).abs().max_element() <= 1.0 + 1e-9);
    }
}

/// OGRE ≥ 13.6: n_opt applied in the orthographic camera's space, 2 shadowDist wide, so the
/// effective n′ is n_opt · shadowDist: 1.1 · 300 = 330 here, and with the ramp on the axis
/// (|cos γ| = 1, factor 21) 23.1 · 300 = 6930.
#[test]
fn ogre_13_6_scales_n_prime_by_the_shadow_distance() {
    let view = view();
    let l = DVec3::new(0.3, -0.5, -0.8);
    let rule = WarpRule::OgreOrtho {
        shadow_distance: 300.0,
    };
    let got = n_prime_for(&view, l, rule).unwrap().value();
    assert!((got - 330.0).abs() < 1e-9, "{got}");
    let got = n_prime_for(&view, DVec3::NEG_Z, rule).unwrap().value();
    assert!((got - 21.0 * 1.1 * 300.0).abs() < 1e-9, "{got}");
    // A larger n′ warps less: 13.6's map, nearer the uniform map, has a different S̄.
    let sbar = |r| {
        frustum_max(&view, &warp(&view, l, r).unwrap().shadow_map())
            .unwrap()
            .storage_factor
    };
    assert!((sbar(rule) - sbar(WarpRule::Ogre)).abs() > 1.0);
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let r = n_prime_for(
            &view,
            l,
            WarpRule::OgreOrtho {
                shadow_distance: bad,
            },
        );
        assert!(
            matches!(&r, Err(Error::InvalidArgument { name, .. }) if *name == "shadow_distance"),
            "{bad}: {r:?}"
        );
    }
}

/// OGRE's "in case n_opt is null, uniform shadow mapping will be done": an n′ that underflows to
/// 0 is the uniform map, never n′ = 0 (which no fit can use).
#[test]
fn ogre_null_n_prime_is_the_uniform_map() {
    // n = 5e-324 (the least subnormal), f = 1e-310: √(n f) underflows to 0 and n · 0.1 rounds
    // to 0. A frustum the crate accepts gets OGRE's fallback; one it refuses never reaches it.
    if let Ok(view) = ViewFrustum::new(5e-324, 1e-310, 0.5) {
        let r = n_prime_for(&view, DVec3::new(0.0, -1.0, -0.1), WarpRule::Ogre);
        assert_eq!(r.unwrap(), NPrime::UNWARPED);
    }
}

/// Filament's switch at |cos γ| = 0.9997 (γ = 1.4035°), n = 1, f = 100, θ = 30°, light tilted
/// up from behind. Just past it (γ = 1.4030°) the warp runs along eye x and d is the frustum's
/// width 2 f tan θ = 115.47; just before it (γ = 1.4035°) along the view, d = the frustum's depth
/// extent. Filament's n′ = (z₀ + √(vz₀ vz₁))/sin γ on each side, by hand.
#[test]
fn filament_switches_frames_at_cos_0_9997() {
    let view = view();
    let at = |deg: f64| {
        let g = deg.to_radians();
        DVec3::new(0.0, -g.sin(), -g.cos())
    };
    let nopt = |deg: f64, d: f64| {
        let s = f64::to_radians(deg).sin();
        (1.0 + (1.0 + d * s).min(100.0).sqrt()) / s
    };
    // Inside: d along eye x.
    let width = 2.0 * 100.0 * 30f64.to_radians().tan();
    let inside = n_prime_for(&view, at(1.4030), WarpRule::Filament)
        .unwrap()
        .value();
    assert!(
        (inside - nopt(1.4030, width)).abs() < 1e-9 * inside,
        "{inside}"
    );
    // Outside: d along the view axis projected ⊥ the light, the corners' extent on that axis.
    let l = at(1.4036);
    let ls = light_space(l, DVec3::NEG_Z).unwrap();
    let z: Vec<f64> = view.corners().iter().map(|c| ls.z.dot(*c)).collect();
    let depth = z.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
        - z.iter().cloned().fold(f64::INFINITY, f64::min);
    let outside = n_prime_for(&view, l, WarpRule::Filament).unwrap().value();
    assert!(
        (outside - nopt(1.4036, depth)).abs() < 1e-9 * outside,
        "{outside}"
    );
    // The jump in S̄ at the switch: 16 665 inside, 15 997 outside (docs/builders.md).
    let sbar = |l: DVec3| {
        frustum_max(
            &view,
            &warp(&view, l, WarpRule::Filament).unwrap().shadow_map(),
        )
        .unwrap()
        .storage_factor
    };
    assert!((sbar(at(1.4030)) - 16664.963).abs() < 1e-2);
    assert!((sbar(at(1.40352)) - 15997.223).abs() < 1e-2);
}

/// Filament's hints are distances in front of the eye with the far one beyond the near one;
/// anything else is refused by name (the command line's `--near-hint -1 --far-hint -0.5` was
/// accepted and gave n′ = z₀/sin γ, its virtual far plane clamped to 0).
#[test]
fn filament_hints_must_be_ordered_distances() {
    let view = view();
    let l = DVec3::new(0.0, -0.6, -0.8);
    for (near_hint, far_hint, name) in [
        (-1.0, -0.5, "near_hint"),
        (0.0, 10.0, "near_hint"),
        (1.0, f64::NAN, "far_hint"),
        (5.0, 5.0, "far_hint"),
        (5.0, 2.0, "far_hint"),
    ] {
        let r = n_prime_for(
            &view,
            l,
            WarpRule::FilamentHints {
                near_hint,
                far_hint,
            },
        );
        assert!(
            matches!(&r, Err(Error::InvalidArgument { name: got, .. }) if *got == name),
            "({near_hint}, {far_hint}): {r:?}"
        );
    }
    // The defaults as explicit hints are `Filament`.
    let hints = WarpRule::FilamentHints {
        near_hint: 1.0,
        far_hint: 100.0,
    };
    assert_eq!(
        n_prime_for(&view, l, hints).unwrap(),
        n_prime_for(&view, l, WarpRule::Filament).unwrap()
    );
}

/// `with_casters` (`CasterDepth::Enclose`) chooses the rule's n′ in the rule's own frame, as
/// `warp()` does: with Filament near the parallel light (γ = 1.3°, inside the switch), and a
/// caster inside the frustum (so the union is the frustum), the n′ is `warp()`'s, and the map's
/// t depends on eye x alone.
#[test]
fn enclosing_casters_keep_filaments_frame() {
    use shadow_aliasing::maps::{with_casters, CasterDepth};
    let view = view();
    let g = 1.3f64.to_radians();
    let l = DVec3::new(0.0, -g.sin(), -g.cos());
    let inside = [DVec3::new(0.0, 0.0, -50.0)];
    let s = with_casters(&view, l, WarpRule::Filament, &inside, CasterDepth::Enclose).unwrap();
    assert_eq!(
        s.n_prime(),
        n_prime_for(&view, l, WarpRule::Filament).unwrap()
    );
    let t = |p: DVec3| {
        let h = s.matrix() * p.extend(1.0);
        h.y / h.w
    };
    let (a, b) = (DVec3::new(7.0, -3.0, -40.0), DVec3::new(7.0, 9.0, -80.0));
    assert!((t(a) - t(b)).abs() < 1e-12, "{} vs {}", t(a), t(b));
}

/// Fuzz finding: OGRE 13.6 with a shadowDist of 2.2·10⁻³⁰⁸ makes n′ so small that 1/n′ overflows
/// and the map sends the far corners to infinity, which the clip check let through (∞ ≤ ∞). It is
/// now `Degenerate`; a finite map is never replaced by an infinite one.
#[test]
fn ogre_ortho_with_a_vanishing_shadow_distance_is_degenerate() {
    let view = ViewFrustum::new(1.5707963267948963, 815078735.3515625, 0.3018346884663106).unwrap();
    let l = DVec3::new(
        -0.004197235107421875,
        4.2755126953125,
        -0.0000000001678466796875,
    );
    let rule = WarpRule::OgreOrtho {
        shadow_distance: 2.2250738585072014e-308,
    };
    match warp(&view, l, rule) {
        Err(Error::Degenerate(_)) => {}
        Ok(s) => {
            for c in view.corners() {
                assert!((s.matrix() * c.extend(1.0)).is_finite(), "{c}");
            }
        }
        Err(e) => panic!("{e:?}"),
    }
}

/// The world-space size of a texel of `m` (eye → light clip, `res` texels across) at `p`,
/// measured in the plane perpendicular to the light `l` as Filament's `texelSizeWorldSpace`
/// does: the columns of the inverse Jacobian of that plane → (s, t), the longer one, times
/// 2/res (clip spans 2 over the map). Written from the map's rows here, not from the crate's
/// kernel.
fn texel_at(m: &glam::DMat4, l: DVec3, res: f64, p: DVec3) -> f64 {
    let (_, j) = plane_jacobian(m, l, p);
    let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
    // Inverse of [[a, b], [c, d]] (rows s, t; columns e1, e2): [[d, −b], [−c, a]] / det; its
    // columns are the plane displacement per unit s and per unit t.
    let col_s = (j[1][1].hypot(-j[1][0])) / det.abs();
    let col_t = ((-j[0][1]).hypot(j[0][0])) / det.abs();
    col_s.max(col_t) * 2.0 / res
}

/// (s, t) at `p` and the Jacobian rows ∂(s, t)/∂(e1, e2) in an orthonormal basis of the plane
/// perpendicular to `l`.
fn plane_jacobian(m: &glam::DMat4, l: DVec3, p: DVec3) -> ((f64, f64), [[f64; 2]; 2]) {
    let r = |i: usize| m.row(i);
    let h = *m * p.extend(1.0);
    let grad = |i: usize| {
        (r(i).truncate() * h.w - r(3).truncate() * r(i).dot(p.extend(1.0))) / (h.w * h.w)
    };
    let e1 = l.any_orthonormal_vector();
    let e2 = l.cross(e1);
    let (gs, gt) = (grad(0), grad(1));
    (
        (h.x / h.w, h.y / h.w),
        [[gs.dot(e1), gs.dot(e2)], [gt.dot(e1), gt.dot(e2)]],
    )
}

/// Filament's `ShadowMap::texelSizeWorldSpace(Wp, MbMtF, dim)` evaluates the LiSPSM map's
/// Jacobian once, at the texture centre (0.5, 0.5), and the shader scales every fragment's
/// normal-offset bias by that one number. The texel of a warped map is not that size over B:
/// smaller near the camera, larger far away. docs/errata.md (Engines, Filament 1) quotes these
/// numbers; the crate's `FrameMap::texel_world` is the largest over B.
#[test]
fn filaments_centre_texel_size_is_not_the_texel_size_over_b() {
    use shadow_aliasing::frame::{frame, Aabb, Bound, Camera, FrameInput, FrameScheme};
    let cam = Camera::new(glam::DMat4::IDENTITY, 1.0, 1000.0, 30f64.to_radians(), 1.0).unwrap();
    let ground = Aabb::new(DVec3::new(-50.0, -5.0, -100.0), DVec3::new(50.0, 0.0, 0.0)).unwrap();
    let tower = Aabb::new(DVec3::new(-10.0, 0.0, -60.0), DVec3::new(10.0, 20.0, -40.0)).unwrap();
    let (receivers, casters) = ([ground], [ground, tower]);
    let res = 2048.0;
    for rule in [WarpRule::Filament, WarpRule::Uniform] {
        let input = FrameInput::new(cam, DVec3::new(0.3, -0.8, -0.4), 2048, 1080)
            .receivers(Bound::Boxes(&receivers))
            .casters(Bound::Boxes(&casters))
            .scheme(FrameScheme::Single(rule));
        let f = frame(&input).unwrap();
        let map = &f.maps()[0];
        let m = map.shadow.matrix();
        let l = f.light_dir_eye();
        // The texture centre: s = t = 0 where rows 0 and 1 of M vanish, on the plane through
        // B's centroid perpendicular to l (three linear equations).
        let b = map.body();
        let c = b.iter().fold(DVec3::ZERO, |a, q| a + *q) / b.len() as f64;
        let (r0, r1) = (m.row(0), m.row(1));
        let a = glam::DMat3::from_cols(r0.truncate(), r1.truncate(), l).transpose();
        let p = a.inverse() * DVec3::new(-r0.w, -r1.w, c.dot(l));
        let ((s, t), _) = plane_jacobian(&m, l, p);
        assert!(
            s.abs() < 1e-12 && t.abs() < 1e-12,
            "centre not found: {s} {t}"
        );
        let centre = texel_at(&m, l, res, p);
        // Constant along the light ray (a texel is a light ray's cross-section).
        let along = texel_at(&m, l, res, p + 7.0 * l);
        assert!((along - centre).abs() <= 1e-9 * centre);
        let (lo, hi) = b
            .iter()
            .map(|q| texel_at(&m, l, res, *q))
            .fold((f64::INFINITY, 0.0f64), |(lo, hi), t| {
                (lo.min(t), hi.max(t))
            });
        // The crate's texel size is the largest edge over B (by its own code).
        assert!(
            (map.texel_world - hi).abs() <= 1e-12 * hi,
            "{rule:?}: texel_world {} against {hi}",
            map.texel_world
        );
        match rule {
            // One texel size everywhere: the centre is every point's.
            WarpRule::Uniform => {
                assert!((hi - lo).abs() <= 1e-12 * hi && (centre - hi).abs() <= 1e-12 * hi);
                assert_eq!(format!("{centre:.4e}"), "4.7568e-2");
            }
            // docs/errata.md's numbers.
            _ => {
                assert_eq!(format!("{centre:.3e}"), "1.648e-2");
                assert_eq!(format!("{lo:.3e}"), "6.103e-3");
                assert_eq!(format!("{hi:.3e}"), "4.891e-1");
                assert_eq!(format!("{:.1}", hi / centre), "29.7");
                assert_eq!(format!("{:.2}", centre / lo), "2.70");
            }
        }
    }
}

/// docs/planning.md's engines' table measures each engine's own matrices (the ports), not the
/// crate's model of them (examples/engine_defaults.rs). Its scene: a camera 1.8 m above the
/// ground looking at (0, 0, −60) (pitch φ = atan(1.8/60)), 45° vertical field of view (t =
/// tan 22.5°), 16:9 (a), near 0.1, far 1000, 1080 pixels; B = the ground box ∩ the frustum,
/// whose nearest view depth is where the frustum's bottom plane meets the ground,
/// z₀ = 1.8/(sin φ + t cos φ) = 4.0539. An orthographic square of side w over N texels has the
/// error (w/N) · 1080/(2 z t) at view depth z, largest at the slice's nearest point of B. By hand:
///
/// - Bevy (cascades ending at 10 · 15^{i/3}, the next starting at 0.8 of the previous end): the
///   second cascade, [8, 24.662], has `calculate_cascade`'s square ⌈2 · 24.662 t √(1 + a²)⌉ = 42
///   (the far-plane diagonal 41.67, rounded up), so (42/2048) · 1080/(2 · 8 t) = 3.342 px; the
///   others give 2.67, 3.32, 3.32. The crate's model (a bounding sphere plus a texel) gave 3.319.
/// - three.js (3 practical cascades): the first ends at 0.1 + 999.9 b₁,
///   b₁ = ((0.1 + 999.9/3)/1000 + 0.1 · 10⁴ᐟ³/1000)/2, and holds all of B (the ground ends at
///   145); its square is its far-plane diagonal 2 D₁ t √(1 + a²) = 283.6, unrounded, so
///   (283.6/2048) · 1080/(2 z₀ t) = 44.54 px. The crate's model gave 45.21.
///
/// The errors are measured from the ports' matrices with the crate's kernel
/// (`measure::vertex::vertex_max`) over the crate's B of each slice, as the example does.
#[test]
fn engine_defaults_are_the_engines_own_squares() {
    use shadow_aliasing::frame::{
        frame, Aabb, Bound, Camera, CascadeSplits, FrameInput, FrameScheme,
    };
    use shadow_aliasing::measure::vertex::vertex_max;
    let eye = DVec3::new(0.0, 1.8, 0.0);
    let view = glam::dcamera::rh::view::look_at_mat4(eye, DVec3::new(0.0, 0.0, -60.0), DVec3::Y);
    let (t, a) = (22.5f64.to_radians().tan(), 16.0 / 9.0);
    let camera = Camera::new(view, 0.1, 1000.0, 22.5f64.to_radians(), a).unwrap();
    let ground = Aabb::new(
        DVec3::new(-150.0, -1.0, -145.0),
        DVec3::new(150.0, 0.0, 5.0),
    )
    .unwrap();
    // The example's sun at 45°, 30° to the side (an orthographic square's error does not depend
    // on the light).
    let (e, s) = (45f64.to_radians(), 30f64.to_radians());
    let light = DVec3::new(-s.sin() * e.cos(), -e.sin(), s.cos() * e.cos());
    let input = FrameInput::new(camera, light, 2048, 1080)
        .receivers(Bound::Boxes(std::slice::from_ref(&ground)))
        .casters(Bound::Boxes(std::slice::from_ref(&ground)));
    let l_eye = view.transform_vector3(light).normalize();
    let measure = |world_to_clip: glam::DMat4, body: &[DVec3]| {
        let m = world_to_clip * view.inverse();
        let e = vertex_max(&m, l_eye, t, body).unwrap();
        e.max_mx.max(e.max_mz) * 1080.0 / 2048.0
    };
    let phi = (1.8f64 / 60.0).atan();
    let z0 = 1.8 / (phi.sin() + t * phi.cos());
    assert!((z0 - 4.0539).abs() < 1e-4, "{z0}");

    // Bevy.
    let bounds = bevy_cascade::calculate_cascade_bounds(4, 10.0, 150.0);
    let model = frame(&input.scheme(FrameScheme::Stable(CascadeSplits::Bevy {
        k: 4,
        minimum_distance: 0.1,
        maximum_distance: 150.0,
        first_far_bound: 10.0,
        overlap_proportion: 0.2,
    })))
    .unwrap();
    let mut cascades = [bevy_cascade::Cascade::default(); 4];
    bevy_cascade::build_directional_light_cascades(
        bevy_cascade::light_rotation_looking_to(light.as_vec3()),
        view.inverse().as_mat4(),
        &bevy_cascade::PerspectiveProjection {
            fov: 45f32.to_radians(),
            aspect_ratio: a as f32,
        },
        &bevy_cascade::CascadeShadowConfig {
            bounds,
            count: 4,
            overlap_proportion: 0.2,
            minimum_distance: 0.1,
        },
        2048,
        &mut cascades,
    );
    assert_eq!(model.len(), 4);
    let diameter = (2.0 * f64::from(bounds[1]) * t * (1.0 + a * a).sqrt()).ceil();
    assert_eq!(diameter, 42.0);
    let hand = diameter / 2048.0 * 1080.0 / (2.0 * 8.0 * t);
    assert!((hand - 3.342).abs() < 5e-4, "{hand}");
    let bevy = model
        .maps()
        .iter()
        .zip(&cascades)
        .map(|(m, c)| measure(c.clip_from_world.as_dmat4(), m.body()))
        .fold(0.0, f64::max);
    assert!((bevy - hand).abs() < 1e-5 * hand, "Bevy {bevy} vs {hand}");
    assert!(
        (model_error(&model) - bevy).abs() > 0.01,
        "the model is not the engine"
    );

    // three.js.
    use threejs_csm as tj;
    let mut csm = [tj::Cascade::default(); tj::MAX_CASCADES];
    tj::update(
        &tj::PerspectiveCamera {
            fov: 45.0,
            aspect: a,
            near: 0.1,
            far: 1000.0,
            matrix_world: view.inverse(),
        },
        light,
        &tj::CsmOptions::default(),
        &mut csm,
    );
    let b1 = 0.5 * ((0.1 + 999.9 / 3.0) / 1000.0 + 0.1 * 1e4f64.powf(1.0 / 3.0) / 1000.0);
    let d1 = 0.1 + 999.9 * b1;
    let width = 2.0 * d1 * t * (1.0 + a * a).sqrt();
    assert!(
        (csm[0].width - width).abs() < 1e-9 * width,
        "{} vs {width}",
        csm[0].width
    );
    let hand = width / 2048.0 * 1080.0 / (2.0 * z0 * t);
    assert!((hand - 44.54).abs() < 5e-3, "{hand}");
    let planes = [0.1, d1, csm[1].depths.1, csm[2].depths.1];
    let model = frame(&input.scheme(FrameScheme::Stable(CascadeSplits::Distances {
        planes: &planes,
        overlap: 0.0,
    })))
    .unwrap();
    assert_eq!(model.len(), 1, "B lies in the first cascade");
    let three = measure(csm[0].clip_from_world, model.maps()[0].body());
    assert!(
        (three - hand).abs() < 1e-6 * hand,
        "three.js {three} vs {hand}"
    );
    assert!(
        (model_error(&model) - three).abs() > 0.5,
        "the model is not the engine"
    );
}

/// The largest error of a frame's maps (the crate's model of an engine).
fn model_error(f: &shadow_aliasing::frame::Frame) -> f64 {
    f.maps()
        .iter()
        .map(|m| m.max_error_pixels)
        .fold(0.0, f64::max)
}
