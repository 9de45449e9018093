//! Behaviour of the single-map builders: every frustum corner in the clip volume for random
//! cameras and lights, Lloyd 2006's closed forms reproduced by the measurement of the built
//! matrices with the light overhead and behind, continuity through the parallel configuration.

mod common;
use common::config;
use glam::{DMat4, DVec3, DVec4};
use proptest::prelude::*;
use shadow_aliasing::maps::{
    fit_warp, light_space, n_prime_for, warp, ClipDepth, Falloff, WarpRule,
};
use shadow_aliasing::measure::{frustum_max, frustum_max_sampled, point_error};
use shadow_aliasing::{NPrime, Resolutions, ViewFrustum};

const ALL_RULES: [WarpRule; 14] = [
    WarpRule::Uniform,
    WarpRule::Eta(0.5),
    WarpRule::Psm,
    WarpRule::Lispsm,
    WarpRule::Lispsm,
    WarpRule::Barroso(Falloff::Barroso),
    WarpRule::Barroso(Falloff::Zhang),
    WarpRule::Tsm { focus: 0.0 }, // replaced by a valid focus per frustum
    WarpRule::LispsmReference,
    WarpRule::Filament,
    WarpRule::Ogre,
    WarpRule::Minimax,
    WarpRule::MinimaxMz,
    WarpRule::Eta(-0.5),
];

fn rule_for(view: &ViewFrustum, r: WarpRule) -> WarpRule {
    match r {
        WarpRule::Tsm { .. } => WarpRule::Tsm {
            focus: 0.3 * (view.far() - view.near()),
        },
        other => other,
    }
}

/// Light clip coordinates of p, asserting w > 0.
fn clip(m: &DMat4, p: DVec3) -> DVec3 {
    let h = *m * DVec4::new(p.x, p.y, p.z, 1.0);
    assert!(h.w > 0.0, "w = {} at {p}", h.w);
    h.truncate() / h.w
}

/// Rounding: with f/n = 10⁶ and PSM's n′ = n, w spans six decades and the extreme corners land
/// within about 10⁻⁹ of the faces; 10⁻⁸ is far below a GPU's f32 resolution (6·10⁻⁸).
fn assert_in_clip(m: &DMat4, p: DVec3, lo_z: f64, ctx: &str) {
    let c = clip(m, p);
    let tol = 1e-8;
    assert!(
        c.x.abs() <= 1.0 + tol && c.y.abs() <= 1.0 + tol && c.z >= lo_z - tol && c.z <= 1.0 + tol,
        "{ctx}: {p} maps to {c}"
    );
    assert!(c.is_finite());
}

fn light_from_angles(elev: f64, azim: f64) -> DVec3 {
    // Elevation 0 at the horizon, π/2 overhead; azimuth 0 behind the viewer (light travelling
    // along −Z, the view direction), π in front.
    let (se, ce) = elev.sin_cos();
    DVec3::new(ce * azim.sin(), -se, -ce * azim.cos())
}

fn check_all_rules(view: &ViewFrustum, l: DVec3) {
    use shadow_aliasing::maps::tsm::{tsm, TsmOptions, TsmSearch};
    use shadow_aliasing::maps::uniform::{with_casters, CasterDepth};
    // A caster box reaching from the camera to twice the far plane and far up.
    let f = view.far();
    let casters: [DVec3; 8] = std::array::from_fn(|i| {
        DVec3::new(
            if i & 1 == 0 { -f } else { f },
            if i & 2 == 0 { -0.5 * f } else { 3.0 * f },
            if i & 4 == 0 { -2.0 * f } else { 0.0 },
        )
    });
    for search in [
        TsmSearch::EightyPercent,
        TsmSearch::Iterative { map_lines: 128 },
    ] {
        let t = tsm(
            view,
            l,
            TsmOptions {
                focus: 0.25 * (f - view.near()),
                search,
            },
        )
        .unwrap_or_else(|e| panic!("TSM {l}: {e}"));
        for c in view.corners() {
            assert_in_clip(
                &t.shadow.matrix(),
                c,
                -1.0,
                &format!("TSM {search:?} light {l}"),
            );
        }
    }
    for r in ALL_RULES {
        let r = rule_for(view, r);
        let s = warp(view, l, r).unwrap_or_else(|e| panic!("{r:?} {l}: {e}"));
        assert!(s.matrix().is_finite(), "{r:?}");
        for c in view.corners() {
            assert_in_clip(&s.matrix(), c, -1.0, &format!("{r:?} light {l}"));
            let z01 = s.with_clip_depth(ClipDepth::ZeroToOne);
            assert_in_clip(&z01, c, 0.0, &format!("{r:?} [0,1] light {l}"));
        }
        let e = frustum_max(view, &s.shadow_map()).unwrap();
        assert!(e.storage_factor.is_finite() && e.storage_factor > 0.0);
        let enc = with_casters(view, l, r, &casters, CasterDepth::Enclose)
            .unwrap_or_else(|e| panic!("{r:?} casters {l}: {e}"));
        for c in view.corners().iter().chain(casters.iter()) {
            assert_in_clip(&enc.matrix(), *c, -1.0, &format!("{r:?} enclose light {l}"));
        }
    }
}

proptest! {
    #![proptest_config(config(1024))]

    /// Random cameras (f/n from 1.01 to 10⁶, half fov 1° to 80°, aspect 0.5 to 2.5) and random
    /// lights over the whole sphere: every rule maps the eight corners into the clip volume, in
    /// both depth conventions, and every corner and caster point when fitted around a caster box;
    /// TSM (80 % and iterative) too. 1024 cameras × 14 rules.
    #[test]
    fn corners_in_clip_volume(
        log_ratio in (1.01f64).ln()..(1e6f64).ln(),
        near in 0.01f64..10.0,
        fov_deg in 1.0f64..80.0,
        aspect in 0.5f64..2.5,
        elev in -std::f64::consts::FRAC_PI_2..std::f64::consts::FRAC_PI_2,
        azim in 0.0f64..std::f64::consts::TAU,
    ) {
        let view = ViewFrustum::with_aspect(near, near * log_ratio.exp(), fov_deg.to_radians(), aspect).unwrap();
        check_all_rules(&view, light_from_angles(elev, azim));
    }
}

/// The special directions: parallel, antiparallel, perpendicular, and tiny tilts off parallel.
#[test]
fn corners_in_clip_volume_special_directions() {
    for (n, f, fov) in [
        (1.0, 1.01, 1.0f64),
        (0.1, 1e5, 80.0),
        (1.0, 1e6, 30.0),
        (2.0, 50.0, 45.0),
    ] {
        let view = ViewFrustum::new(n, f, fov.to_radians()).unwrap();
        for l in [
            DVec3::NEG_Z,
            DVec3::Z,
            DVec3::NEG_Y,
            DVec3::Y,
            DVec3::X,
            DVec3::new(1e-13, 0.0, -1.0),
            DVec3::new(0.0, 1e-9, 1.0),
            DVec3::new(1e-7, -1e-7, -1.0),
            DVec3::new(0.02, 0.0, -1.0),
        ] {
            check_all_rules(&view, l);
        }
    }
}

/// Lloyd 2006 Eq 7 and 8 (light overhead), written out here independently of the crate.
fn lloyd_mx(n: f64, f: f64, np: f64, z: f64) -> f64 {
    f * (np + z - n) / (z * (np + f - n))
}
fn lloyd_mz(n: f64, f: f64, th: f64, np: f64, z: f64) -> f64 {
    (f - n) / (2.0 * th.tan()) * (np + z - n).powi(2) / (z * np * (np + f - n))
}
/// Lloyd 2006 Eq 11.
fn lloyd_n_prime(n: f64, f: f64, eta: f64) -> f64 {
    let a = f / n;
    if eta <= 0.0 {
        n * (a.sqrt() + 1.0 - eta * (a - 1.0)) / (eta + 1.0)
    } else {
        n * (a.sqrt() + 1.0) / (eta * a.sqrt() + 1.0)
    }
}

proptest! {
    #![proptest_config(config(128))]

    /// Light overhead: the measured m_x, m_z of the built warp on the view axis equal Lloyd 2006
    /// Eq 7, 8 for n′ from η ∈ (−1, 1] (Eq 11), and the measured S̄ equals Eq 12.
    #[test]
    fn overhead_matches_lloyd_eq_7_8_12(
        n in 0.05f64..5.0,
        ratio in 1.5f64..1e4,
        fov_deg in 5.0f64..75.0,
        eta in -0.999f64..1.0,
        zf in 0.0f64..1.0,
    ) {
        let f = n * ratio;
        let th = fov_deg.to_radians();
        let view = ViewFrustum::new(n, f, th).unwrap();
        let s = warp(&view, DVec3::NEG_Y, WarpRule::Eta(eta)).unwrap();
        let np = lloyd_n_prime(n, f, eta);
        prop_assert!((s.n_prime().value() - np).abs() <= 1e-12 * np);
        let z = n + zf * (f - n);
        let e = point_error(&view, &s.shadow_map(), DVec3::new(0.0, 0.0, -z), Resolutions::default()).unwrap();
        let (mx, mz) = (lloyd_mx(n, f, np, z), lloyd_mz(n, f, th, np, z));
        prop_assert!((e.mx - mx).abs() <= 1e-9 * mx, "m_x {} vs Eq 7 {}", e.mx, mx);
        prop_assert!((e.mz - mz).abs() <= 1e-9 * mz, "m_z {} vs Eq 8 {}", e.mz, mz);
        let fm = frustum_max(&view, &s.shadow_map()).unwrap();
        let n_lsp = n + (f * n).sqrt();
        let sbar = (f / n - 1.0) / (2.0 * th.tan())
            * if np <= n_lsp { 1.0 } else { np * np * f / (n * (np + f - n).powi(2)) };
        prop_assert!((fm.storage_factor - sbar).abs() <= 1e-9 * sbar, "S̄ {} vs Eq 12 {}", fm.storage_factor, sbar);
        // Eq 9, 10.
        prop_assert!((fm.max_mx - lloyd_mx(n, f, np, n)).abs() <= 1e-9 * fm.max_mx);
        let mz_max = if np <= n_lsp { lloyd_mz(n, f, th, np, f) } else { lloyd_mz(n, f, th, np, n) };
        prop_assert!((fm.max_mz - mz_max).abs() <= 1e-9 * mz_max);
    }

    /// Light behind the viewer: the uniform map's S̄ is (f/n)² (Lloyd 2006 Eq 20 with k = 1).
    #[test]
    fn behind_uniform_is_alpha_squared(n in 0.05f64..5.0, ratio in 1.01f64..1e5, fov_deg in 1.0f64..80.0) {
        let view = ViewFrustum::new(n, n * ratio, fov_deg.to_radians()).unwrap();
        let s = warp(&view, DVec3::NEG_Z, WarpRule::Uniform).unwrap();
        let e = frustum_max(&view, &s.shadow_map()).unwrap();
        prop_assert!((e.storage_factor - ratio * ratio).abs() <= 1e-9 * ratio * ratio);
    }
}

/// The vertices carry the maximum: a dense 9³ sample never exceeds them (Lloyd 2006 §4.4).
#[test]
fn vertex_maxima_hold_for_tilted_lights() {
    let view = ViewFrustum::with_aspect(0.5, 80.0, 0.6, 1.6).unwrap();
    for l in [
        DVec3::new(0.3, -0.7, 0.2),
        DVec3::new(-0.5, -0.3, -0.8),
        DVec3::new(0.1, -0.2, 0.9),
    ] {
        for r in [
            WarpRule::Lispsm,
            WarpRule::Minimax,
            WarpRule::Uniform,
            WarpRule::Psm,
        ] {
            let s = warp(&view, l, r).unwrap();
            let v = frustum_max(&view, &s.shadow_map()).unwrap();
            let d = frustum_max_sampled(&view, &s.shadow_map(), 9).unwrap();
            assert!(d.max_mx <= v.max_mx * (1.0 + 1e-9), "{r:?} {l}");
            assert!(d.max_mz <= v.max_mz * (1.0 + 1e-9), "{r:?} {l}");
        }
    }
}

/// fit_warp with n′ → ∞ tends to the orthographic fit entry by entry.
#[test]
fn warp_tends_to_uniform_as_n_prime_grows() {
    let view = ViewFrustum::new(1.0, 30.0, 0.5).unwrap();
    let ls = light_space(DVec3::new(0.2, -0.5, -0.6), DVec3::NEG_Z).unwrap();
    let ortho = fit_warp(&view.corners(), &ls, NPrime::UNWARPED).unwrap();
    let mut prev = f64::INFINITY;
    for k in 2..12 {
        let np = 10f64.powi(k);
        let m = fit_warp(&view.corners(), &ls, NPrime::finite(np).unwrap()).unwrap();
        let diff = (m - ortho)
            .to_cols_array()
            .iter()
            .fold(0.0f64, |a, b| a.max(b.abs()));
        assert!(diff < prev, "n′ = {np}: {diff}");
        assert!(diff < 1e3 / np, "n′ = {np}: {diff}");
        prev = diff;
    }
}

/// S̄ is continuous as the light sweeps through the view axis in the eye's vertical and
/// horizontal planes, for the rules that tend to the uniform map there.
#[test]
fn storage_factor_continuous_through_parallel() {
    let view = ViewFrustum::new(1.0, 100.0, 0.5).unwrap();
    for rule in [
        WarpRule::Uniform,
        WarpRule::Lispsm,
        WarpRule::Barroso(Falloff::Barroso),
        WarpRule::LispsmReference,
        WarpRule::Minimax,
        WarpRule::MinimaxMz,
    ] {
        for plane in [DVec3::Y, DVec3::X] {
            for dir in [DVec3::NEG_Z, DVec3::Z] {
                let at = |t: f64| {
                    let l = dir + t * plane;
                    let s = warp(&view, l, rule).unwrap();
                    frustum_max(&view, &s.shadow_map()).unwrap().storage_factor
                };
                let s0 = at(0.0);
                for t in [1e-12, -1e-12, 1e-9, -1e-9, 1e-6, -1e-6] {
                    let s = at(t);
                    assert!(
                        (s - s0).abs() <= 1e-3 * s0,
                        "{rule:?} {plane} {dir}: S̄({t}) = {s} vs S̄(0) = {s0}"
                    );
                }
            }
        }
    }
}

/// The minimax n′ with the light overhead is n + √(f n), and for every light its M_z is no
/// larger than that of any other rule's n′ for the same light (it is the minimum over n′).
#[test]
fn minimax_minimises_mz() {
    let view = ViewFrustum::new(0.5, 300.0, 0.7).unwrap();
    let m = n_prime_for(&view, DVec3::NEG_Y, WarpRule::MinimaxMz).unwrap();
    assert!((m.value() - view.n_prime_lispsm()).abs() < 1e-9 * view.n_prime_lispsm());
    for l in [
        DVec3::new(0.3, -0.7, 0.2),
        DVec3::new(-0.5, -0.3, -0.8),
        DVec3::new(0.1, -0.2, 0.9),
        DVec3::new(0.0, -0.05, -1.0),
    ] {
        let best = warp(&view, l, WarpRule::MinimaxMz).unwrap();
        let best_mz = frustum_max(&view, &best.shadow_map()).unwrap().max_mz;
        for k in -40..=40 {
            let np = NPrime::finite(view.near() * 10f64.powf(k as f64 / 8.0)).unwrap();
            let ls = light_space(l, DVec3::NEG_Z).unwrap();
            let m = fit_warp(&view.corners(), &ls, np).unwrap();
            let sm = shadow_aliasing::measure::ShadowMap::new(m, l).unwrap();
            let mz = frustum_max(&view, &sm).unwrap().max_mz;
            assert!(
                best_mz <= mz * (1.0 + 1e-9),
                "{l}: minimax {best_mz} > {mz} at {np:?}"
            );
        }
    }
}

/// Renderer conventions: [0, 1] depth keeps the texel and maps depth by (z + 1)/2; world_to_clip
/// is S · View.
#[test]
fn clip_depth_conventions() {
    let view = ViewFrustum::new(1.0, 40.0, 0.6).unwrap();
    let s = warp(&view, DVec3::new(0.4, -1.0, 0.3), WarpRule::Lispsm).unwrap();
    let gl = s.with_clip_depth(ClipDepth::NegOneToOne);
    let vk = s.with_clip_depth(ClipDepth::ZeroToOne);
    for c in view.corners() {
        let a = clip(&gl, c);
        let b = clip(&vk, c);
        assert!((a.x - b.x).abs() < 1e-12 && (a.y - b.y).abs() < 1e-12);
        assert!((b.z - 0.5 * (a.z + 1.0)).abs() < 1e-12);
    }
    let cam = glam::dcamera::rh::view::look_at_mat4(
        DVec3::new(3.0, 2.0, 1.0),
        DVec3::new(0.0, 0.0, -5.0),
        DVec3::Y,
    );
    let world = DVec3::new(1.0, 0.5, -7.0);
    let eye = cam.project_point3(world);
    let w2c = s.world_to_clip(cam, ClipDepth::NegOneToOne);
    assert!((clip(&w2c, world) - clip(&gl, eye)).length() < 1e-12);
    let f32m = s.to_mat4(ClipDepth::ZeroToOne);
    assert!((f32m.as_dmat4() - vk)
        .to_cols_array()
        .iter()
        .all(|d| d.abs() < 1e-5 * 1e3));
}

/// Invalid inputs are typed errors naming the argument.
#[test]
fn invalid_inputs_are_errors() {
    let view = ViewFrustum::new(1.0, 40.0, 0.6).unwrap();
    assert!(warp(&view, DVec3::ZERO, WarpRule::Lispsm).is_err());
    assert!(warp(&view, DVec3::new(f64::NAN, 1.0, 0.0), WarpRule::Lispsm).is_err());
    let e = warp(&view, DVec3::NEG_Y, WarpRule::Eta(1.5)).unwrap_err();
    assert!(e.to_string().starts_with("eta "), "{e}");
    let e = warp(&view, DVec3::NEG_Y, WarpRule::Tsm { focus: 100.0 }).unwrap_err();
    assert!(e.to_string().starts_with("focus "), "{e}");
    let ls = light_space(DVec3::NEG_Y, DVec3::NEG_Z).unwrap();
    assert!(fit_warp(&[], &ls, NPrime::UNWARPED).is_err());
    assert!(NPrime::finite(-1.0)
        .and_then(|n| fit_warp(&view.corners(), &ls, n))
        .is_err());
    // All points on one light ray: no extent across the map.
    let p = [DVec3::new(0.0, 1.0, -2.0), DVec3::new(0.0, 3.0, -2.0)];
    assert!(fit_warp(&p, &ls, NPrime::UNWARPED).is_err());
}

/// Caster bound, Lloyd 2006 §6.4: with `Clamp` the map is the frustum's and casters nearer the
/// light than the frustum get clip depth below −1 (clamped to depth 0 by the renderer) while
/// keeping their texel; with `Enclose` every caster point lands in the clip volume. Clamping
/// never costs storage: S̄ of the clamped map is at most that of the enclosing one.
#[test]
fn caster_bound_clamp_and_enclose() {
    use shadow_aliasing::maps::uniform::{with_casters, CasterDepth};
    let view = ViewFrustum::with_aspect(0.5, 60.0, 0.6, 1.5).unwrap();
    // A scene box in eye space, 100 wide, reaching 80 above the camera.
    let (lo, hi) = (DVec3::new(-50.0, -3.0, -70.0), DVec3::new(50.0, 80.0, 5.0));
    let casters: [DVec3; 8] = std::array::from_fn(|i| {
        DVec3::new(
            if i & 1 == 0 { lo.x } else { hi.x },
            if i & 2 == 0 { lo.y } else { hi.y },
            if i & 4 == 0 { lo.z } else { hi.z },
        )
    });
    for l in [
        DVec3::new(0.2, -1.0, 0.1),
        DVec3::new(-0.6, -0.5, -0.3),
        DVec3::NEG_Y,
    ] {
        for rule in [WarpRule::Uniform, WarpRule::Lispsm, WarpRule::Minimax] {
            let c = with_casters(&view, l, rule, &casters, CasterDepth::Clamp).unwrap();
            let e = with_casters(&view, l, rule, &casters, CasterDepth::Enclose).unwrap();
            assert_eq!(c, warp(&view, l, rule).unwrap());
            for p in view.corners() {
                assert_in_clip(&c.matrix(), p, -1.0, "clamp");
                assert_in_clip(&e.matrix(), p, -1.0, "enclose");
            }
            for p in casters {
                assert_in_clip(&e.matrix(), p, -1.0, "enclose caster");
            }
            // A caster straight up the light ray from a frustum point, far toward the light: same
            // texel as that point, depth below the near end.
            let inside = DVec3::new(1.0, -2.0, -20.0);
            let up = inside - 500.0 * l.normalize();
            let (a, b) = (clip(&c.matrix(), inside), clip(&c.matrix(), up));
            assert!((a.x - b.x).abs() < 1e-9 && (a.y - b.y).abs() < 1e-9);
            assert!(b.z < -1.0, "{rule:?} {l}: {b}");
            let sc = frustum_max(&view, &c.shadow_map()).unwrap().storage_factor;
            let se = frustum_max(&view, &e.shadow_map()).unwrap().storage_factor;
            assert!(
                sc <= se * (1.0 + 1e-9),
                "{rule:?} {l}: clamp {sc} > enclose {se}"
            );
        }
    }
    let bad = [DVec3::new(f64::NAN, 0.0, 0.0)];
    assert!(with_casters(
        &view,
        DVec3::NEG_Y,
        WarpRule::Uniform,
        &bad,
        CasterDepth::Clamp
    )
    .is_err());
}

#[path = "common/counting_alloc.rs"]
mod no_alloc;

#[test]
fn per_frame_builders_do_not_allocate() {
    use shadow_aliasing::maps::tsm::{tsm, TsmOptions, TsmSearch};
    let view = ViewFrustum::new(0.3, 500.0, 0.7).unwrap();
    let l = DVec3::new(0.3, -0.8, -0.4);
    // Warm up anything lazily initialised.
    let _ = warp(&view, l, WarpRule::Minimax).unwrap();
    for rule in ALL_RULES {
        let rule = rule_for(&view, rule);
        let (s, n) = no_alloc::allocations(|| warp(&view, l, rule));
        assert!(s.is_ok());
        assert_eq!(n, 0, "{rule:?} allocated {n} times");
    }
    for search in [
        TsmSearch::EightyPercent,
        TsmSearch::Iterative { map_lines: 512 },
    ] {
        let (t, n) = no_alloc::allocations(|| {
            tsm(
                &view,
                l,
                TsmOptions {
                    focus: 50.0,
                    search,
                },
            )
        });
        assert!(t.is_ok());
        assert_eq!(n, 0, "TSM {search:?} allocated {n} times");
    }
    {
        use shadow_aliasing::maps::tsm::{tsm_general, ConvexBound};
        use shadow_aliasing::maps::uniform::{with_casters, CasterDepth};
        let bound = ConvexBound::from_aabb(
            DVec3::new(-100.0, -5.0, -300.0),
            DVec3::new(100.0, 50.0, 0.0),
            DMat4::IDENTITY,
        )
        .unwrap();
        let opts = TsmOptions {
            focus: 50.0,
            search: TsmSearch::Iterative { map_lines: 1024 },
        };
        let (t, n) = no_alloc::allocations(|| tsm_general(&view, l, &bound, opts));
        assert!(t.is_ok());
        assert_eq!(n, 0, "tsm_general allocated {n} times");
        let casters = [DVec3::new(0.0, 80.0, -30.0), DVec3::new(10.0, 60.0, -90.0)];
        for depth in [CasterDepth::Clamp, CasterDepth::Enclose] {
            let (s, n) = no_alloc::allocations(|| {
                with_casters(&view, l, WarpRule::Minimax, &casters, depth)
            });
            assert!(s.is_ok());
            assert_eq!(n, 0, "with_casters {depth:?} allocated {n} times");
        }
    }
    // The counter counts: a Vec allocates.
    let (_, n) = no_alloc::allocations(|| vec![1u8; 16]);
    assert!(n >= 1);
}

proptest! {
    #![proptest_config(config(128))]

    /// A light tilted by γ in the view's vertical plane (from behind or in front): the measured
    /// m_z of the built warp on the view axis equals Barroso & Celes Eq 12 measured perpendicular
    /// to the light (`tilted_mz_perpendicular`), and 2 m_z, 2 m_x equal Zhang et al.'s global
    /// E_p, E_q (Eq 13, 14), for any n′ and for Barroso's own n′.
    #[test]
    fn tilted_matches_barroso_and_zhang(
        n in 0.05f64..5.0,
        ratio in 1.5f64..1e4,
        fov_deg in 5.0f64..75.0,
        gamma in 0.01f64..std::f64::consts::FRAC_PI_2,
        behind in proptest::bool::ANY,
        log_np in -2.0f64..3.0,
        zf in 0.0f64..1.0,
        barroso_rule in proptest::bool::ANY,
    ) {
        use shadow_aliasing::analytic::global::{zhang_ep, zhang_eq};
        use shadow_aliasing::analytic::tilted::tilted_mz_perpendicular;
        use shadow_aliasing::LightAngle;
        let f = n * ratio;
        let view = ViewFrustum::new(n, f, fov_deg.to_radians()).unwrap();
        let (s, c) = gamma.sin_cos();
        let l = if behind { DVec3::new(0.0, -s, -c) } else { DVec3::new(0.0, -s, c) };
        let (map, n_prime) = if barroso_rule {
            let sm = warp(&view, l, WarpRule::Barroso(Falloff::Barroso)).unwrap();
            (sm.shadow_map(), sm.n_prime())
        } else {
            let ls = light_space(l, DVec3::NEG_Z).unwrap();
            let np = NPrime::finite(n * 10f64.powf(log_np)).unwrap();
            let m = fit_warp(&view.corners(), &ls, np).unwrap();
            (shadow_aliasing::measure::ShadowMap::new(m, l).unwrap(), np)
        };
        let z = n + zf * (f - n);
        let g = LightAngle::new(gamma).unwrap();
        let e = point_error(&view, &map, DVec3::new(0.0, 0.0, -z), Resolutions::default()).unwrap();
        let b = tilted_mz_perpendicular(&view, n_prime, g, z, Resolutions::default()).unwrap();
        prop_assert!((e.mz - b).abs() <= 1e-9 * b, "m_z {} vs Barroso {}", e.mz, b);
        let ep = zhang_ep(&view, n_prime, g, 0.0, z).unwrap();
        let eq = zhang_eq(&view, n_prime, g, 0.0, z).unwrap();
        prop_assert!((2.0 * e.mz - ep).abs() <= 1e-9 * ep, "2 m_z {} vs Zhang E_p {}", 2.0 * e.mz, ep);
        prop_assert!((2.0 * e.mx - eq).abs() <= 1e-9 * eq, "2 m_x {} vs Zhang E_q {}", 2.0 * e.mx, eq);
    }
}

/// Sweeping through the view axis along a diagonal plane: the two sides agree and S̄ is
/// continuous up to the axis, but the limit (the bounding rectangle turned 45°, S̄ = 2 (f/n)² for
/// a square image) differs from the value exactly on the axis ((f/n)², the rectangle aligned
/// with the image): the warp axis has no continuous extension there (docs/builders.md).
#[test]
fn diagonal_sweep_through_parallel() {
    let view = ViewFrustum::new(1.0, 100.0, 0.5).unwrap();
    let diag = DVec3::new(1.0, 1.0, 0.0).normalize();
    for rule in [WarpRule::Uniform, WarpRule::Minimax, WarpRule::Lispsm] {
        let at = |t: f64| {
            let s = warp(&view, DVec3::NEG_Z + t * diag, rule).unwrap();
            frustum_max(&view, &s.shadow_map()).unwrap().storage_factor
        };
        let s6 = at(1e-6);
        for t in [-1e-6, 1e-9, -1e-9, 1e-11, -1e-11] {
            assert!(
                (at(t) - s6).abs() <= 1e-4 * s6,
                "{rule:?} at {t}: {} vs {s6}",
                at(t)
            );
        }
        assert!((s6 - 2e4).abs() <= 1e-3 * 2e4, "{rule:?}: {s6}");
        assert!((at(0.0) - 1e4).abs() <= 1e-6 * 1e4);
    }
}

/// Engine rules as shipped: Filament switches to the orthographic map below sin γ = 0.02, a jump
/// from S̄ = 15 068 (its warp, 1.51× the uniform map) to 9 998 (n = 1, f = 100, θ = 30°, light
/// from behind); OGRE's ramp never reaches the uniform map: on the axis its n′ = 2.1 (n + √(f n))
/// gives S̄ = 72 976, 7.3× the uniform map's 10 000.
#[test]
fn engine_rules_near_parallel() {
    let view = ViewFrustum::new(1.0, 100.0, 30f64.to_radians()).unwrap();
    let sbar = |l: DVec3, r: WarpRule| {
        frustum_max(&view, &warp(&view, l, r).unwrap().shadow_map())
            .unwrap()
            .storage_factor
    };
    let at = |s: f64| DVec3::new(0.0, -s, -(1.0 - s * s).sqrt());
    let below = sbar(at(0.0199999), WarpRule::Filament);
    let above = sbar(at(0.0200001), WarpRule::Filament);
    assert_eq!(
        n_prime_for(&view, at(0.0199999), WarpRule::Filament).unwrap(),
        NPrime::UNWARPED
    );
    assert!((below - 9997.9998).abs() < 1e-3, "{below}");
    // sin γ = 0.0200001 is γ = 1.1459° < 1.4037°: |cos γ| ≥ 0.9997, so Filament keeps the light's
    // frame with the camera's right vector as up (`computeLightRotation` returns identity) and
    // warps along eye x. By hand (`applyLISPSM`): d = 2 f tan θ = 115.47 along x, z₀ = n = 1,
    // z₁ = 1 + d sin γ, vz₀ = 1, vz₁ = min(f, z₁), n′ = (z₀ + √(vz₀ vz₁))/sin γ = 140.95825.
    let sg = 0.0200001f64;
    let d = 2.0 * 100.0 * 30f64.to_radians().tan();
    let nopt = (1.0 + (1.0 + d * sg).min(100.0).sqrt()) / sg;
    let got = n_prime_for(&view, at(sg), WarpRule::Filament)
        .unwrap()
        .value();
    assert!((got - nopt).abs() <= 1e-12 * nopt, "{got} vs {nopt}");
    assert!((nopt - 140.95825).abs() < 1e-5, "{nopt}");
    // The warp runs along eye x: t depends on x alone (two points differing in y and z only).
    let m = warp(&view, at(sg), WarpRule::Filament).unwrap().matrix();
    let t = |p: DVec3| {
        let h = m * p.extend(1.0);
        h.y / h.w
    };
    let (a, b) = (DVec3::new(10.0, -3.0, -40.0), DVec3::new(10.0, 5.0, -70.0));
    assert!((t(a) - t(b)).abs() < 1e-12, "{} vs {}", t(a), t(b));
    // S̄ of that map (15 068 with the warp wrongly along the view axis).
    assert!((above - 15527.303).abs() < 1e-2, "{above}");
    let ogre = n_prime_for(&view, DVec3::NEG_Z, WarpRule::Ogre)
        .unwrap()
        .value();
    assert!((ogre - 2.1 * 11.0).abs() < 1e-12);
    let s = sbar(DVec3::NEG_Z, WarpRule::Ogre);
    assert!((s - 72975.648).abs() < 1e-2, "{s}");
    // The reference code's general n′ = Δ/(√(z₁/z₀) − 1) is Wimmer's "old" (n + √(n(n + Δ sin γ)))/sin γ
    // with d = Δ: check the identity at a tilted light.
    let l = DVec3::new(0.3, -0.5, -0.8);
    let fl_delta = {
        let ls = light_space(l, DVec3::NEG_Z).unwrap();
        let z: Vec<f64> = view.corners().iter().map(|c| ls.z.dot(*c)).collect();
        z.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
            - z.iter().cloned().fold(f64::INFINITY, f64::min)
    };
    let sg = l.normalize().cross(DVec3::NEG_Z).length();
    let old = (1.0 + (1.0 * (1.0 + fl_delta * sg)).sqrt()) / sg;
    let r = n_prime_for(&view, l, WarpRule::LispsmReference)
        .unwrap()
        .value();
    assert!((r - old).abs() <= 1e-12 * old, "{r} vs {old}");
    let by_def = fl_delta / (((1.0 + fl_delta * sg) / 1.0).sqrt() - 1.0);
    assert!((r - by_def).abs() <= 1e-9 * by_def);
}

proptest! {
    #![proptest_config(config(512))]

    /// Any valid frustum, however extreme (near from 10⁻³⁰⁰ to 10³⁰⁰, f/n up to 10⁶⁰⁰), any light
    /// (components from 10⁻³⁰⁰ to 10³⁰⁰, zeros, NaN): every builder answers a finite matrix whose
    /// corners are in the clip volume, or a typed error; never a panic, never NaN.
    #[test]
    fn any_input_never_nan(
        log_near in -300.0f64..300.0,
        log_ratio in 1e-9f64..600.0,
        fov in 1e-6f64..std::f64::consts::FRAC_PI_2,
        log_aspect in -6.0f64..6.0,
        lx in prop_oneof![Just(0.0), Just(f64::NAN), -1e3f64..1e3, Just(1e-300), Just(1e300)],
        ly in prop_oneof![Just(0.0), -1e3f64..1e3, Just(-1e-300), Just(-1e300)],
        lz in prop_oneof![Just(0.0), -1e3f64..1e3, Just(1e-300), Just(f64::INFINITY)],
        rule_ix in 0usize..14,
    ) {
        use shadow_aliasing::maps::tsm::{tsm, TsmOptions, TsmSearch};
        let near = 10f64.powf(log_near);
        let far = near * 10f64.powf(log_ratio);
        let Ok(view) = ViewFrustum::with_aspect(near, far, fov, 10f64.powf(log_aspect)) else { return Ok(()); };
        let l = DVec3::new(lx, ly, lz);
        let rule = rule_for(&view, ALL_RULES[rule_ix]);
        if let Ok(s) = warp(&view, l, rule) {
            prop_assert!(s.matrix().is_finite());
            prop_assert!(s.n_prime().value() > 0.0 && !s.n_prime().value().is_nan());
            for c in view.corners() {
                let h = s.matrix() * DVec4::new(c.x, c.y, c.z, 1.0);
                prop_assert!(h.is_finite() && h.w > 0.0, "{rule:?}: {c} → {h}");
                prop_assert!((h.truncate() / h.w).abs().max_element() <= 1.0 + 1e-6, "{rule:?}: {c} → {}", h.truncate() / h.w);
            }
        }
        let focus = 0.3 * (far - near);
        if focus.is_finite() && focus > 0.0 {
            if let Ok(t) = tsm(&view, l, TsmOptions { focus, search: TsmSearch::Iterative { map_lines: 64 } }) {
                prop_assert!(t.shadow.matrix().is_finite() && t.light_depth.is_finite() && t.focus_area.is_finite());
            }
        }
    }
}

/// The condition number of a 4 × 4 matrix (ratio of extreme singular values).
fn cond(m: &DMat4) -> f64 {
    let n = nalgebra::Matrix4::from_column_slice(&m.to_cols_array());
    let sv = n.singular_values();
    sv.max() / sv.min()
}

/// Through parallel (light from behind, tilted up by t in the eye's vertical plane): the rules
/// that tend to the uniform map give matrices converging entry by entry to the uniform map's on
/// the axis, with the same condition number: no blow-up, no ill-conditioning.
#[test]
fn matrices_converge_and_stay_conditioned_through_parallel() {
    let view = ViewFrustum::new(1.0, 100.0, 0.5).unwrap();
    let on_axis = warp(&view, DVec3::NEG_Z, WarpRule::Uniform)
        .unwrap()
        .matrix();
    let c0 = cond(&on_axis);
    assert!(c0.is_finite() && c0 < 1e6, "{c0}");
    for rule in [
        WarpRule::Lispsm,
        WarpRule::LispsmReference,
        WarpRule::Barroso(Falloff::Barroso),
        WarpRule::Barroso(Falloff::Zhang),
        WarpRule::Uniform,
    ] {
        let mut prev = f64::INFINITY;
        for t in [1e-3, 1e-5, 1e-7, 1e-9, 1e-11] {
            let m = warp(&view, DVec3::new(0.0, -t, -1.0), rule)
                .unwrap()
                .matrix();
            let diff = (m - on_axis)
                .to_cols_array()
                .iter()
                .fold(0.0f64, |a, d| a.max(d.abs()));
            let scale = on_axis
                .to_cols_array()
                .iter()
                .fold(0.0f64, |a, d| a.max(d.abs()));
            assert!(
                diff <= prev * 1.0001 + 1e-12,
                "{rule:?} t = {t}: {diff} after {prev}"
            );
            prev = diff;
            let c = cond(&m);
            assert!(
                c <= 2.0 * c0 && c >= 0.5 * c0,
                "{rule:?} t = {t}: cond {c} vs {c0}"
            );
            if t <= 1e-9 {
                assert!(diff <= 1e-6 * scale, "{rule:?} t = {t}: {diff}");
            }
        }
    }
}

/// η's ends (Lloyd 2006 Eq 11): η = −1 is the uniform map (n′ = ∞: M_x = f/n,
/// M_z = (f − n)/(2 n tan θ) by hand), η = 1 is PSM (n′ = n: M_x = 1, S̄ = (f/n − 1)/(2 tan θ)).
#[test]
fn eta_ends_are_uniform_and_psm() {
    let (n, f, th) = (2.0, 300.0, 0.6f64);
    let view = ViewFrustum::new(n, f, th).unwrap();
    let u = warp(&view, DVec3::NEG_Y, WarpRule::Eta(-1.0)).unwrap();
    assert!(u.n_prime().is_unwarped());
    let e = frustum_max(&view, &u.shadow_map()).unwrap();
    assert!((e.max_mx - f / n).abs() <= 1e-12 * f / n);
    assert!((e.max_mz - (f - n) / (2.0 * n * th.tan())).abs() <= 1e-12 * e.max_mz);
    let p = warp(&view, DVec3::NEG_Y, WarpRule::Eta(1.0)).unwrap();
    assert_eq!(p.n_prime(), NPrime::finite(n).unwrap());
    let e = frustum_max(&view, &p.shadow_map()).unwrap();
    assert!((e.max_mx - 1.0).abs() <= 1e-12);
    let sbar = (f / n - 1.0) / (2.0 * th.tan());
    assert!((e.storage_factor - sbar).abs() <= 1e-12 * sbar);
}

/// The depth ratios from which the builders refuse a warp, as docs/builders.md and `warp()`'s
/// docs state them (measured by bisection on f/n; issue 21, item 12): near 1, half field of view
/// 0.5 rad, light (0, −1, −0.3): PSM from f/n = 6.1·10¹¹, LiSPSM from 4.1·10²³. Each is accepted
/// at half its threshold and refused (`Degenerate`, with a remedy) at twice it.
#[test]
fn degenerate_from_the_documented_depth_ratios() {
    let docs = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/builders.md"))
        .expect("docs/builders.md");
    let l = DVec3::new(0.0, -1.0, -0.3);
    for (rule, threshold, written) in [
        (WarpRule::Psm, 6.1e11, "PSM is refused from f/n = 6.1·10¹¹"),
        (WarpRule::Lispsm, 4.1e23, "LiSPSM from 4.1·10²³"),
    ] {
        assert!(
            docs.contains(written),
            "docs/builders.md states {written:?}"
        );
        let at = |ratio: f64| warp(&ViewFrustum::new(1.0, ratio, 0.5).unwrap(), l, rule);
        assert!(
            at(0.5 * threshold).is_ok(),
            "{rule:?} at f/n = {:e}",
            0.5 * threshold
        );
        assert!(
            at(0.98 * threshold).is_ok(),
            "{rule:?} at f/n = {:e}",
            0.98 * threshold
        );
        match at(2.0 * threshold) {
            Err(shadow_aliasing::Error::Degenerate(m)) => {
                assert!(m.contains("reduce far/near"), "{rule:?}: {m}");
            }
            other => panic!("{rule:?} at f/n = {:e}: {other:?}", 2.0 * threshold),
        }
        assert!(
            at(1.03 * threshold).is_err(),
            "{rule:?} at f/n = {:e}",
            1.03 * threshold
        );
    }
}
