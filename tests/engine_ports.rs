//! The engine ports of `benches/reference/` (issue 23 item 9) against values derived by hand and
//! against the engines' documented properties, not against their own arithmetic: Bevy's cascade
//! holds its whole frustum slice in its clip volume (reversed depth), its size is the slice's
//! larger diagonal rounded up, its centre lies on whole texels; Filament's frustum–box
//! intersection yields the hull's vertices, its LiSPSM n_opt is (z₀ + √(z₀ z₁))/sin γ, its
//! focused map holds every visible receiver point, and the current revision's light view, depth
//! range and two-edge texel size match hand values the earlier revision does not; three.js's
//! CSM splits its frustum where its breaks say (as lerp factors), its squares are the slices'
//! larger diagonals, unrounded, and they hold their slices on a world-anchored texel grid.

#[allow(dead_code)]
#[path = "../benches/reference/bevy_cascade.rs"]
mod bevy_cascade;
#[allow(dead_code)]
#[path = "../benches/reference/filament_directional.rs"]
mod filament_directional;
#[allow(dead_code)]
#[path = "../benches/reference/threejs_csm.rs"]
mod threejs_csm;

use bevy_cascade::{
    build_directional_light_cascades, light_rotation_looking_to, Cascade, CascadeShadowConfig,
    PerspectiveProjection,
};
use filament_directional::{
    intersect_frustum_with_box, update_cascade_shadow_maps, Aabb, CameraInfo, DirectionalMap,
    Renderable, ShadowMapInfo, ShadowOptions,
};
use glam::{DMat4, DVec3, Mat4, Vec3};
use shadow_aliasing::frame::{self, Bound, Camera, FrameInput, FrameScheme};
use shadow_aliasing::maps::WarpRule;

/// The eight corners of the frustum slice [near, far] of a camera at the origin looking down −Z
/// (half field of view 30°, square), in f64.
fn slice_corners(near: f64, far: f64) -> Vec<DVec3> {
    let t = 30f64.to_radians().tan();
    let mut v = Vec::new();
    for z in [near, far] {
        for (sx, sy) in [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)] {
            v.push(DVec3::new(sx * z * t, sy * z * t, -z));
        }
    }
    v
}

fn clip(m: &Mat4, p: DVec3) -> Vec3 {
    let h = *m * p.as_vec3().extend(1.0);
    h.truncate() / h.w
}

/// Bevy: each cascade's clip volume holds its slice (x, y in [−1, 1], reversed depth in [0, 1]
/// with the slice's extreme points at 0 and 1), the first cascade's diameter is the hand value,
/// and the cascade's centre lies on whole texels of the light's frame.
#[test]
fn bevy_cascades_hold_their_slices_and_snap_to_texels() {
    let projection = PerspectiveProjection {
        fov: 60f32.to_radians(),
        aspect_ratio: 1.0,
    };
    let config = CascadeShadowConfig {
        bounds: [100.0, 200.0, 400.0, 1000.0],
        count: 4,
        overlap_proportion: 0.2,
        minimum_distance: 1.0,
    };
    let dir = Vec3::new(0.3, -0.8, -0.4);
    let rot = light_rotation_looking_to(dir);
    let mut out = [Cascade::default(); 4];
    build_directional_light_cascades(rot, Mat4::IDENTITY, &projection, &config, 2048, &mut out);
    // Slice [1, 100] at half field of view 30° (tan = 0.57735): body diagonal² = 2 (0.57735 +
    // 57.735)² + 99² = 16 601.7, far-plane diagonal² = 2 (2 · 57.735)² = 26 666.7: diameter
    // ⌈163.30⌉ = 164, texel 164 / 2048.
    assert_eq!(out[0].texel_size, 164.0 / 2048.0);
    let nears = [1.0, 80.0, 160.0, 320.0];
    let fars = [100.0, 200.0, 400.0, 1000.0];
    let world_from_light = Mat4::from_quat(rot);
    for (i, c) in out.iter().enumerate() {
        let pts = slice_corners(nears[i], fars[i]);
        let (mut zmin, mut zmax) = (f32::INFINITY, f32::NEG_INFINITY);
        for p in &pts {
            let q = clip(&c.clip_from_world, *p);
            assert!(
                q.x.abs() <= 1.0 + 1e-5 && q.y.abs() <= 1.0 + 1e-5,
                "cascade {i}: {q}"
            );
            zmin = zmin.min(q.z);
            zmax = zmax.max(q.z);
        }
        assert!(
            zmin.abs() < 1e-4 && (zmax - 1.0).abs() < 1e-4,
            "cascade {i}: depth {zmin}..{zmax}"
        );
        // The light travels along the cascade's −Z: a point further along the light is deeper
        // (smaller reversed depth).
        let p = DVec3::new(0.0, 0.0, -0.5 * (nears[i] + fars[i]));
        let d = (0.1 * dir.normalize()).as_dvec3();
        assert!(clip(&c.clip_from_world, p + d).z < clip(&c.clip_from_world, p).z);
        // The centre in the light's frame, in texels: a whole number (stability).
        let centre = world_from_light.transpose() * c.world_from_cascade.w_axis;
        for v in [centre.x, centre.y] {
            let t = v / c.texel_size;
            assert!(
                (t - t.round()).abs() < 1e-3,
                "cascade {i}: centre {v} = {t} texels"
            );
        }
    }
}

/// Filament's `intersectFrustumWithBox`: a thin box through the near plane gives its four far
/// corners (step b) and its four edges' crossings of the near plane (step c), and nothing else.
#[test]
fn filament_frustum_box_intersection_is_the_hull_by_hand() {
    let cam = CameraInfo::perspective(Mat4::IDENTITY, 60.0, 1.0, 1.0, 100.0);
    let projection = cam.culling_projection * cam.view;
    let bx = Aabb {
        min: Vec3::new(-0.1, -0.1, -2.0),
        max: Vec3::new(0.1, 0.1, 0.5),
    };
    let mut out = [Vec3::ZERO; 64];
    let n = intersect_frustum_with_box(&mut out, &projection, &bx);
    let mut expected = Vec::new();
    for z in [-2.0, -1.0] {
        for (x, y) in [(0.1, 0.1), (0.1, -0.1), (-0.1, 0.1), (-0.1, -0.1)] {
            expected.push(Vec3::new(x, y, z));
        }
    }
    assert_eq!(n, 8, "{:?}", &out[..n]);
    for e in &expected {
        assert!(
            out[..n].iter().any(|p| (*p - *e).length() < 1e-5),
            "{e} missing: {:?}",
            &out[..n]
        );
    }
}

/// Filament's whole directional path on a hand case: light straight down (sin γ = 1), a box
/// [−2, 2] × [−2, 0] × [−20, −10] inside the frustum as receiver and caster, camera n = 1,
/// f = 100, default hints (1, 100). Then dzn = dzf = 0, z₀ = 10, z₁ = z₀ + d sin γ = 20 (d = 10,
/// the box's depth along the view) and n_opt = z₀ + √(z₀ z₁) = 10 + √200 (Filament's
/// `applyLISPSM`, Wimmer et al.'s formula). The crate's `WarpRule::Filament` gives the same n′ on
/// the same focus body. The focused map holds the box's corners in clip range and touches its
/// x and y edges; the texture matrix puts them inside the 1-texel border.
#[test]
fn filament_lispsm_by_hand() {
    let cam = CameraInfo::perspective(Mat4::IDENTITY, 60.0, 1.0, 1.0, 100.0);
    let bx = Aabb {
        min: Vec3::new(-2.0, -2.0, -20.0),
        max: Vec3::new(2.0, 0.0, -10.0),
    };
    let scene = [Renderable {
        aabb: bx,
        cast_shadows: true,
        receive_shadows: true,
    }];
    let info = ShadowMapInfo::new(2048);
    let mut out: [Option<DirectionalMap>; 4] = [None; 4];
    let dir = Vec3::new(0.0, -1.0, 0.0);
    let visible = update_cascade_shadow_maps(
        dir,
        &cam,
        &ShadowOptions::default(),
        &info,
        &scene,
        &[],
        true,
        false,
        &mut out,
    );
    assert_eq!(visible, 1);
    let m = out[0].unwrap();
    let n_opt = 10.0 + 200f32.sqrt();
    assert!(
        (m.wp.x_axis.x - n_opt).abs() < 1e-4 * n_opt,
        "{} vs {n_opt}",
        m.wp.x_axis.x
    );

    // The crate's Filament rule on the same body (B = the box: it lies inside the frustum).
    let camera = Camera::new(DMat4::IDENTITY, 1.0, 100.0, 30f64.to_radians(), 1.0).unwrap();
    let boxes =
        [frame::Aabb::new(DVec3::new(-2.0, -2.0, -20.0), DVec3::new(2.0, 0.0, -10.0)).unwrap()];
    let input = FrameInput::new(camera, DVec3::new(0.0, -1.0, 0.0), 2048, 1080)
        .receivers(Bound::Boxes(&boxes))
        .casters(Bound::Boxes(&boxes))
        .scheme(FrameScheme::Single(WarpRule::Filament));
    let f = frame::frame(&input).unwrap();
    let crate_n = f.maps().iter().next().unwrap().shadow.n_prime().value();
    assert!(
        (crate_n - f64::from(n_opt)).abs() < 1e-9 * crate_n,
        "{crate_n}"
    );

    let (mut mx, mut my) = (0f32, 0f32);
    let border = 1.0 / 2048.0;
    for c in bx.corners() {
        let q = m.s * c.extend(1.0);
        let q = q.truncate() / q.w;
        assert!(q.abs().max_element() <= 1.0 + 1e-5, "{c}: {q}");
        mx = mx.max(q.x.abs());
        my = my.max(q.y.abs());
        let t = m.light_space * c.extend(1.0);
        let t = t.truncate() / t.w;
        for u in [t.x, t.y] {
            assert!(
                (border - 1e-6..=1.0 - border + 1e-6).contains(&u),
                "{c}: {t}"
            );
        }
        assert!((-1e-6..=1.0 + 1e-6).contains(&t.z), "{c}: {t}");
    }
    assert!(
        (mx - 1.0).abs() < 1e-4 && (my - 1.0).abs() < 1e-4,
        "{mx} {my}"
    );
}

/// Filament on the benchmark scene (a ground box 100 × 5 × 100 in front of the camera, a tower,
/// camera n = 1, f = 1000): every point of the ground that the camera sees lies in the focused
/// map's clip range, for one map and for four cascades (those with visible shadows).
#[test]
fn filament_focus_holds_the_visible_receivers() {
    let cam = CameraInfo::perspective(Mat4::IDENTITY, 60.0, 1.0, 1.0, 1000.0);
    let ground = Aabb {
        min: Vec3::new(-50.0, -5.0, -100.0),
        max: Vec3::new(50.0, 0.0, 0.0),
    };
    let tower = Aabb {
        min: Vec3::new(-10.0, 0.0, -60.0),
        max: Vec3::new(10.0, 20.0, -40.0),
    };
    let scene = [
        Renderable {
            aabb: ground,
            cast_shadows: true,
            receive_shadows: true,
        },
        Renderable {
            aabb: tower,
            cast_shadows: true,
            receive_shadows: false,
        },
    ];
    let info = ShadowMapInfo::new(2048);
    let dir = Vec3::new(0.3, -0.8, -0.4).normalize();
    let t = 30f32.to_radians().tan();
    for splits in [&[][..], &[0.05, 0.125, 0.3][..]] {
        let mut out: [Option<DirectionalMap>; 4] = [None; 4];
        let visible = update_cascade_shadow_maps(
            dir,
            &cam,
            &ShadowOptions::default(),
            &info,
            &scene,
            splits,
            true,
            false,
            &mut out,
        );
        assert!(visible >= 1);
        let bounds: Vec<f32> = std::iter::once(1.0)
            .chain(splits.iter().map(|s| 1.0 + 999.0 * s))
            .chain(std::iter::once(1000.0))
            .collect();
        let mut checked = 0;
        for (i, m) in out.iter().enumerate().take(splits.len() + 1) {
            let (zn, zf) = (bounds[i], bounds[i + 1]);
            let Some(m) = m else {
                // No shadows only where the slice misses the ground (beyond z = −100).
                assert!(zn > 100.0, "slice {zn}..{zf} has no map");
                continue;
            };
            for ix in 0..=20 {
                for iy in 0..=5 {
                    for iz in 0..=40 {
                        let p = Vec3::new(
                            -50.0 + 5.0 * ix as f32,
                            -(iy as f32),
                            -(zn + (zf.min(100.0) - zn) * iz as f32 / 40.0),
                        );
                        let d = -p.z;
                        if d < zn || d > zf || p.x.abs() > d * t || p.y.abs() > d * t {
                            continue;
                        }
                        let q = m.s * p.extend(1.0);
                        let q = q.truncate() / q.w;
                        assert!(
                            q.x.abs() <= 1.0 + 1e-4
                                && q.y.abs() <= 1.0 + 1e-4
                                && q.z.abs() <= 1.0 + 1e-4,
                            "slice {zn}..{zf}: {p} maps to {q}"
                        );
                        checked += 1;
                    }
                }
            }
        }
        assert!(checked > 1000, "{checked}");
    }
}

/// Filament's `applyLISPSM` takes its hints' dzn, dzf from the (cascade) camera's planes but
/// everything else from the shadow volume's depth range [zn, zf] (the receivers' clamped to the
/// camera's): the orthographic test 3 dzn/(zf − zn) < 2, nopt1 = dzn/(2 − 3 dzn/(zf − zn)) and
/// the virtual far plane. Two hand cases with the light straight down (sin γ = 1), camera near
/// 0.1, far 100 (dzf = 0), a box [−2, 2] × [−2, 0] × [−10, −1.2] as receiver and caster (its
/// depth range [1.2, 10] within the frustum):
///
/// - near hint 5: dzn = 4.9, 3 dzn/(zf − zn) = 14.7/8.8 < 2, nopt1 = 4.9/(2 − 14.7/8.8)
///   = 14.8686…, nopt0 = z₀ + √(vz₀ vz₁) = 1.2 + √(5 · 10) = 8.271…, so n′ = nopt1. (With the
///   camera's range in the test and nopt1, as the crate had it, n′ was nopt0.)
/// - default hints and the box cut to z ∈ [−10, −9.2]: dzn = 0.9, 3 dzn/0.8 ≥ 2, so Filament
///   draws an orthographic map (the crate had warped it).
///
/// The crate's rule agrees with the hand values and with the port; so do four cascades at
/// Filament's linear split positions, whose cameras' near planes differ (dzn > 0 only in the
/// first).
#[test]
fn filament_rule_takes_zn_zf_from_the_shadow_volume() {
    let run = |near_hint: f32, zmax: f64, splits: &[f32]| {
        let cam = CameraInfo::perspective(Mat4::IDENTITY, 60.0, 1.0, 0.1, 100.0);
        let bx = Aabb {
            min: Vec3::new(-2.0, -2.0, -10.0),
            max: Vec3::new(2.0, 0.0, zmax as f32),
        };
        let scene = [Renderable {
            aabb: bx,
            cast_shadows: true,
            receive_shadows: true,
        }];
        let options = ShadowOptions {
            shadow_near_hint: near_hint,
            ..ShadowOptions::default()
        };
        let mut out: [Option<DirectionalMap>; 4] = [None; 4];
        update_cascade_shadow_maps(
            Vec3::new(0.0, -1.0, 0.0),
            &cam,
            &options,
            &ShadowMapInfo::new(2048),
            &scene,
            splits,
            true,
            false,
            &mut out,
        );
        // The port's n′ per cascade: None where LiSPSM was cancelled (Wp the identity).
        let port: Vec<Option<f64>> = out[..=splits.len()]
            .iter()
            .map(|m| {
                let m = m.expect("every cascade holds part of the box");
                (m.wp.w_axis.y != 0.0).then_some(f64::from(m.wp.x_axis.x))
            })
            .collect();

        let camera = Camera::new(DMat4::IDENTITY, 0.1, 100.0, 30f64.to_radians(), 1.0).unwrap();
        let boxes = [
            frame::Aabb::new(DVec3::new(-2.0, -2.0, -10.0), DVec3::new(2.0, 0.0, zmax)).unwrap(),
        ];
        let rule = WarpRule::FilamentHints {
            near_hint: f64::from(near_hint),
            far_hint: 100.0,
        };
        let fractions: Vec<f64> = splits.iter().map(|&p| f64::from(p)).collect();
        let scheme = if splits.is_empty() {
            FrameScheme::Single(rule)
        } else {
            FrameScheme::Cascades {
                splits: frame::CascadeSplits::Fractions {
                    fractions: &fractions,
                    overlap: 0.0,
                },
                rule,
            }
        };
        let input = FrameInput::new(camera, DVec3::new(0.0, -1.0, 0.0), 2048, 1080)
            .receivers(Bound::Boxes(&boxes))
            .casters(Bound::Boxes(&boxes))
            .scheme(scheme);
        let f = frame::frame(&input).unwrap();
        let ours: Vec<Option<f64>> = f
            .maps()
            .iter()
            .map(|m| m.shadow.n_prime().as_finite())
            .collect();
        (port, ours)
    };

    let nopt1 = 4.9 / (2.0 - 3.0 * 4.9 / 8.8);
    assert!(nopt1 > 1.2 + 50f64.sqrt());
    let (port, ours) = run(5.0, -1.2, &[]);
    let (p, o) = (port[0].unwrap(), ours[0].unwrap());
    assert!((p - nopt1).abs() < 1e-4 * nopt1, "port {p} vs {nopt1}");
    assert!((o - nopt1).abs() < 1e-9 * nopt1, "crate {o} vs {nopt1}");

    let (port, ours) = run(1.0, -9.2, &[]);
    assert_eq!(port, vec![None], "Filament: orthographic");
    assert_eq!(ours, vec![None], "the crate: orthographic");

    let (port, ours) = run(5.0, -1.2, &[0.02, 0.05, 0.09]);
    assert_eq!(port.len(), ours.len());
    for (i, (p, o)) in port.iter().zip(&ours).enumerate() {
        match (p, o) {
            (Some(p), Some(o)) => assert!((p - o).abs() < 2e-4 * o, "cascade {i}: {p} vs {o}"),
            _ => assert_eq!(
                p.is_some(),
                o.is_some(),
                "cascade {i}: {port:?} vs {ours:?}"
            ),
        }
    }
}

/// One map of Filament's port for the light straight down (0, −1, 0) on a box [−2, 2] × `y` ×
/// [−20, −10] inside the camera's frustum (camera at the origin looking down −Z, 60° vertical
/// field of view, n = 1, f = 100), receiver and caster, 2048² (shadowDimension 2046).
fn filament_down_on_box(y: (f32, f32), lispsm: bool) -> DirectionalMap {
    let cam = CameraInfo::perspective(Mat4::IDENTITY, 60.0, 1.0, 1.0, 100.0);
    let scene = [Renderable {
        aabb: Aabb {
            min: Vec3::new(-2.0, y.0, -20.0),
            max: Vec3::new(2.0, y.1, -10.0),
        },
        cast_shadows: true,
        receive_shadows: true,
    }];
    let options = ShadowOptions {
        lispsm,
        ..ShadowOptions::default()
    };
    let mut out: [Option<DirectionalMap>; 4] = [None; 4];
    let visible = update_cascade_shadow_maps(
        Vec3::new(0.0, -1.0, 0.0),
        &cam,
        &options,
        &ShadowMapInfo::new(2048),
        &scene,
        &[],
        true,
        false,
        &mut out,
    );
    assert_eq!(visible, 1);
    out[0].unwrap()
}

/// Filament's current `ShadowMap.cpp` (commit 0362f36e) keeps the light's view at the world
/// origin: near and far are −max z and −min z of the light-space bounds, and the shadow camera's
/// model matrix holds only the constant bias. The light straight down with the x axis as up puts
/// light z = world y, so a box between heights 1 and 3 gives znear = −3, zfar = −1 and the
/// model's translation (0, 0.001, 0) (the bias 0.001 against the light's travel). The earlier
/// revision the port followed moved the view to −max z · direction and shifted the vertices:
/// znear = 0, zfar = 2, the model's translation (0, 3.001, 0).
#[test]
fn filament_current_revision_keeps_the_light_view_at_the_origin() {
    let m = filament_down_on_box((1.0, 3.0), true);
    assert!(
        (m.znear - -3.0).abs() < 1e-6 && (m.zfar - -1.0).abs() < 1e-6,
        "znear {} zfar {}",
        m.znear,
        m.zfar
    );
    let t = m.model.w_axis.truncate();
    assert!((t - DVec3::new(0.0, 0.001, 0.0)).length() < 1e-9, "{t}");
}

/// Filament's current texel size, `texelSizeWorldSpaceAt(S, {0, 0, 0}, shadowDimension)`: both
/// edges of one texel, at the world origin's place in the map, from the Jacobian of inverse(S).
/// Hand values for the light straight down on the box [−2, 2] × [−2, 0] × [−20, −10]
/// (`filament_lispsm_by_hand`'s scene). In the aligned light space X = world x,
/// Y = −world z ∈ [10, 20] (the warp axis, n = 10, d = 10), Z = −world y − 1 (znear 0, zfar 2).
///
/// - LiSPSM: n_opt = 10 + √200, Y′ = Y − n + n_opt; u = n_opt X/(2 Y′) (the focus halves x),
///   v = A + B/Y′ (B = −2 n_opt (n_opt + d)/d), depth n_opt Z/Y′. The world origin has
///   Y′ = √200, u = 0; there ∂world/∂u = 2 Y′/n_opt and |∂world/∂v| = (Y′²/|B|) √(1 + 1/Y′²), times
///   one texel 2/2046: (1.145233·10⁻³, 1.188888·10⁻³).
/// - Orthographic (`lispsm` false): u = X/2, v = (Y − 15)/5: (4/2046, 10/2046).
///
/// With LiSPSM the world origin (the camera) lies at clip v = A − |B|/√200 = −5.83, A =
/// (2 n_opt + d)/d: outside the map, where Filament's comment says "in the middle of the
/// shadowmap" (docs/errata.md, Filament 2).
///
/// Recomputed independently with NumPy (the matrices Mv, L, Mp, W, F written out from the
/// derivation above, inverse(S) differentiated by central differences at the origin's NDC):
/// 1.1452325·10⁻³, 1.1888882·10⁻³ and 1.9550342·10⁻³, 4.8875855·10⁻³. The earlier revision's
/// `texelSizeWorldSpace`, which the port followed before, gives one number: the longer edge at
/// the texture's centre, 4.752·10⁻³ for LiSPSM, and 10 · 2048/2046² = 4.8924·10⁻³ (texture
/// units over 1/shadowDimension) for the orthographic map.
#[test]
fn filament_texel_size_is_both_edges_at_the_world_origin() {
    let map = filament_down_on_box((-2.0, 0.0), true);
    let lispsm = map.texel_size_at_one_meter_ws;
    let n_opt = 10f64 + 200f64.sqrt();
    let yp = 200f64.sqrt();
    let b = 2.0 * n_opt * (n_opt + 10.0) / 10.0;
    // The world origin (the camera) is not in the map: v = A + B/Y′ with A = (2 n_opt + d)/d,
    // B = −b: −5.8284 (docs/errata.md, Filament 2).
    let v = (2.0 * n_opt + 10.0) / 10.0 - b / yp;
    assert!((v - -5.828_427).abs() < 1e-6, "{v}");
    let o = map.s * glam::Vec4::W;
    assert!(
        (f64::from(o.y / o.w) - v).abs() < 1e-4 * v.abs(),
        "{} vs {v}",
        o.y / o.w
    );
    let texel = 2.0 / 2046.0;
    let hand = [
        2.0 * yp / n_opt * texel,
        yp * yp / b * (1.0 + 1.0 / (yp * yp)).sqrt() * texel,
    ];
    assert!((hand[0] - 1.145_233e-3).abs() < 1e-9 && (hand[1] - 1.188_888e-3).abs() < 1e-9);
    for (got, want) in [lispsm.x, lispsm.y].into_iter().zip(hand) {
        assert!(
            (f64::from(got) - want).abs() < 1e-4 * want,
            "LiSPSM {lispsm} vs {hand:?}"
        );
    }
    let ortho = filament_down_on_box((-2.0, 0.0), false).texel_size_at_one_meter_ws;
    for (got, want) in [ortho.x, ortho.y]
        .into_iter()
        .zip([4.0 / 2046.0, 10.0 / 2046.0])
    {
        assert!(
            (f64::from(got) - want).abs() < 1e-5 * want,
            "orthographic {ortho} vs ({}, {})",
            4.0 / 2046.0,
            10.0 / 2046.0
        );
    }
}

/// three.js's CSM (`threejs_csm`) on a camera at the origin looking down −Z, near 1, far 100,
/// three practical cascades (CSM.js's defaults). By hand: uniform breaks (1 + 99 i/3)/100 = 0.34,
/// 0.67, logarithmic 100^{i/3}/100 = 0.046416, 0.215443, practical their mean 0.193208, 0.442722.
/// `CSMFrustum.split` lerps the frustum's edges by them, so the cascades end at view depths
/// 1 + 99 b = 20.127 6 and 44.829 5 (not b · far = 19.32, 44.27), then 100. `updateShadowBounds`'
/// square is the larger of the far-plane diagonal 2 √2 D tan θ and the body diagonal from near[2]
/// to far[0], √(2 tan²θ (n + D)² + (D − n)²), unrounded (Bevy rounds up; the crate's model was a
/// bounding sphere): at 60° the far-plane diagonal, 32.868 2 for the first cascade and 163.299 3
/// for the last; at 20° (tan θ = 0.176 327) the body diagonal, 19.839 9 for the first.
#[test]
fn threejs_csm_breaks_and_squares_by_hand() {
    use threejs_csm::{update, Cascade, CsmOptions, PerspectiveCamera, MAX_CASCADES};
    let run = |fov: f64| {
        let camera = PerspectiveCamera {
            fov,
            aspect: 1.0,
            near: 1.0,
            far: 100.0,
            matrix_world: DMat4::IDENTITY,
        };
        let mut out = [Cascade::default(); MAX_CASCADES];
        update(
            &camera,
            DVec3::new(0.3, -0.8, -0.4),
            &CsmOptions::default(),
            &mut out,
        );
        out
    };
    let b1 = 0.5 * (0.34 + 100f64.powf(1.0 / 3.0) / 100.0);
    let b2 = 0.5 * (0.67 + 100f64.powf(2.0 / 3.0) / 100.0);
    assert!((b1 - 0.193_208).abs() < 1e-6 && (b2 - 0.442_722).abs() < 1e-6);
    let (d1, d2) = (1.0 + 99.0 * b1, 1.0 + 99.0 * b2);
    let out = run(60.0);
    let want = [(1.0, d1), (d1, d2), (d2, 100.0)];
    for (c, w) in out.iter().zip(want) {
        assert!(
            (c.depths.0 - w.0).abs() < 1e-9 && (c.depths.1 - w.1).abs() < 1e-9,
            "{:?} vs {w:?}",
            c.depths
        );
    }
    assert!((d1 - 20.127_6).abs() < 1e-4, "{d1}");
    let t = 30f64.to_radians().tan();
    let far_diagonal = |d: f64| 2.0 * 2f64.sqrt() * d * t;
    assert!(
        (out[0].width - far_diagonal(d1)).abs() < 1e-9 * d1,
        "{}",
        out[0].width
    );
    assert!((out[0].width - 32.868_2).abs() < 1e-4, "{}", out[0].width);
    assert!((out[2].width - 163.299_3).abs() < 1e-4, "{}", out[2].width);
    // At 20°: the body diagonal is the longer.
    let t = 10f64.to_radians().tan();
    let body = (2.0 * t * t * (1.0 + d1).powi(2) + (d1 - 1.0).powi(2)).sqrt();
    assert!(body > 2.0 * 2f64.sqrt() * d1 * t);
    let out = run(20.0);
    assert!(
        (out[0].width - body).abs() < 1e-9 * body,
        "{} vs {body}",
        out[0].width
    );
    assert!((body - 19.839_9).abs() < 1e-4, "{body}");
}

/// three.js's CSM: each cascade's square holds its whole frustum slice (clip x, y in [−1, 1]),
/// its depth range is [lightNear, lightFar] = [1, 2000] from a light `lightMargin` = 200 beyond
/// the slice's light-space box, the light travels along the shadow camera's −Z, and the square's
/// centre lies on whole texels of the light's frame anchored at the world origin
/// (`updateBefore`'s floor).
#[test]
fn threejs_csm_squares_hold_their_slices_and_snap_to_texels() {
    use threejs_csm::{look_at_rotation, update, Cascade, CsmOptions, PerspectiveCamera};
    let camera = PerspectiveCamera {
        fov: 45.0,
        aspect: 16.0 / 9.0,
        near: 0.1,
        far: 1000.0,
        matrix_world: glam::dcamera::rh::view::look_at_mat4(
            DVec3::new(3.0, 1.8, 2.0),
            DVec3::new(0.0, 0.0, -60.0),
            DVec3::Y,
        )
        .inverse(),
    };
    let dir = DVec3::new(-0.47, -0.34, 0.81).normalize();
    let mut out = [Cascade::default(); 4];
    let options = CsmOptions::default();
    update(&camera, dir, &options, &mut out);
    let t = 22.5f64.to_radians().tan();
    let orientation = look_at_rotation(DVec3::ZERO, dir, DVec3::Y);
    for c in &out[..3] {
        let (zn, zf) = c.depths;
        for z in [zn, zf] {
            for (sx, sy) in [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)] {
                let eye = DVec3::new(sx * z * t * 16.0 / 9.0, sy * z * t, -z);
                let world = camera.matrix_world.transform_point3(eye);
                let q = c.clip_from_world * world.extend(1.0);
                let q = q.truncate() / q.w;
                assert!(
                    q.x.abs() <= 1.0 + 1e-9 && q.y.abs() <= 1.0 + 1e-9 && q.z.abs() < 1.0,
                    "{:?}: {q}",
                    c.depths
                );
                // 200 beyond the slice's light-space box, within 2000 of the light.
                let depth = (c.view * world.extend(1.0)).z;
                assert!((-2000.0..=-200.0 + 1e-9).contains(&depth), "{depth}");
            }
        }
        let p = c.clip_from_world * DVec3::ZERO.extend(1.0);
        let q = c.clip_from_world * dir.extend(1.0);
        assert!(q.z / q.w > p.z / p.w, "deeper along the light");
        let texel = c.width / 2048.0;
        let centre = orientation.transpose().transform_point3(c.position);
        for v in [centre.x, centre.y] {
            let n = v / texel;
            assert!((n - n.round()).abs() < 1e-6, "{v} is {n} texels");
        }
    }
}
