//! Findings of an adversarial review of the frame API (random and targeted scenes, checked with
//! independent projections), each reduced to its exact input and fixed.

use glam::DVec3;
use shadow_aliasing::frame::{frame, Aabb, Bound, Camera, Focus, FrameInput, FrameScheme};
use shadow_aliasing::maps::{ClipDepth, WarpRule};

/// Clip coordinates of world point `x` under `m`.
fn clip(m: glam::DMat4, x: DVec3) -> DVec3 {
    let h = m * x.extend(1.0);
    h.truncate() / h.w
}

/// Finding 1: under a straight-down sun, B's vertical edges project to pairs of footprint points
/// within about 10⁻¹³ of each other; the footprint's hull kept such a pair, and the prism plane on
/// that 10⁻¹³ edge had an arbitrary direction and cut the caster box away. The caster straight
/// above a receiver point in view then fell outside the depth range (depth −2.50 for the uniform
/// map): its shadow was lost. Every caster point on a light ray through B must map into the depth
/// range [−1, 1] (no depth clamp).
#[test]
fn a_caster_straight_above_a_receiver_is_in_the_depth_range_under_a_straight_down_sun() {
    let fwd = DVec3::new(
        0.12746366285390098,
        0.9715520998941238,
        -0.19959842645468318,
    );
    let view = glam::dcamera::rh::view::look_at_mat4(DVec3::ZERO, fwd, DVec3::Y);
    let cam = Camera::new(
        view,
        0.001405102089547934,
        2.445867614299156,
        0.6596634737675636,
        1.9504262083092652,
    )
    .unwrap();
    let receivers = [Aabb::new(
        DVec3::new(-0.7443082482518892, 0.5444537182031517, -1.095598418164235),
        DVec3::new(1.8851246617816764, 2.496381896546428, 0.1646221493321658),
    )
    .unwrap()];
    let casters = [Aabb::new(
        DVec3::new(-0.8268296552613466, 3.862888655882152, -0.23780576416019852),
        DVec3::new(-0.6304291395529902, 4.059289171590509, -0.04140524845184215),
    )
    .unwrap()];
    // A receiver point in view (inside the frustum and the receivers' box), and the caster point
    // straight above it.
    let p = DVec3::new(
        -0.6749249233213821,
        0.7763362949301359,
        -0.09976768104562919,
    );
    let q = DVec3::new(p.x, 3.96, p.z);
    let e = view.transform_point3(p);
    assert!(
        -e.z > 0.001405102089547934 && -e.z < 2.445867614299156,
        "p in view: {e}"
    );
    for rule in [WarpRule::Uniform, WarpRule::Lispsm, WarpRule::Minimax] {
        let input = FrameInput::new(cam, DVec3::NEG_Y, 2048, 1080)
            .receivers(Bound::Boxes(&receivers))
            .casters(Bound::Boxes(&casters))
            .scheme(FrameScheme::Single(rule));
        let f = frame(&input).unwrap();
        let m = f.maps()[0].world_to_clip(ClipDepth::NegOneToOne);
        let (cp, cq) = (clip(m, p), clip(m, q));
        assert!(cp.abs().max_element() <= 1.0 + 1e-6, "{rule:?}: p -> {cp}");
        assert!(
            cq.z >= -1.0 - 1e-6 && cq.z < cp.z,
            "{rule:?}: caster q -> {cq}, p -> {cp}"
        );
    }
}

/// Finding 2: a receivers' box counted as flat only below 10⁻¹² of its own size, while B counted
/// as empty below 10⁻⁹ of the frustum's size. A ground box in view of a thickness in between
/// (10⁻⁸, 10⁻⁶ here: what a float-rounded mesh bound of a ground plane has) gave `Focus::Empty`,
/// "out of view", and no shadow map. Every thickness must give a map, with the S̄ of the
/// zero-thickness ground (they are the same ground to 10⁻⁶ relative).
#[test]
fn a_thin_ground_in_view_is_mapped_whatever_its_thickness() {
    let view = glam::dcamera::rh::view::look_at_mat4(
        DVec3::new(0.0, 2.0, 0.0),
        DVec3::new(0.0, 2.0, -1.0),
        DVec3::Y,
    );
    let camera = Camera::new(view, 0.1, 1000.0, 30f64.to_radians(), 16.0 / 9.0).unwrap();
    let sbar = |th: f64| {
        let ground =
            [Aabb::new(DVec3::new(-50.0, -th, -100.0), DVec3::new(50.0, 0.0, 0.0)).unwrap()];
        let input = FrameInput::new(camera, DVec3::new(0.3, -1.0, -0.2), 2048, 1080)
            .receivers(Bound::Boxes(&ground))
            .scheme(FrameScheme::Single(WarpRule::Lispsm));
        let f = frame(&input).unwrap();
        assert!(
            !f.is_empty() && matches!(f.focus(), Focus::Flat | Focus::Body),
            "thickness {th:e}: {:?}, {} maps",
            f.focus(),
            f.len()
        );
        f.storage_factor().unwrap()
    };
    let flat = sbar(0.0);
    for th in [1e-12, 1e-10, 1e-8, 1e-6, 3e-6, 1e-5] {
        let s = sbar(th);
        assert!(
            (s - flat).abs() <= 1e-6 * flat,
            "thickness {th:e}: S̄ {s} against {flat}"
        );
    }
}

/// Finding 3: a wall of zero thickness lit straight down is a line segment to the light, but
/// along a diagonal of the map (the camera turned), so neither its extent across nor along the
/// warp axis vanished: it was mapped as `Focus::Flat`, and `WarpRule::Minimax` (which put the
/// centre of projection on the segment's line) failed with "no extent across the warp axis"
/// where `Uniform` built a map. Its footprint has no area: every rule must say `Focus::EdgeOn`
/// (no map needed), with no error, for the wall and for a wall 10⁻¹² thick.
#[test]
fn a_wall_seen_edge_on_along_a_diagonal_is_edge_on_for_every_rule() {
    let fwd = DVec3::new(
        0.44386681492589997,
        -0.07887130145701045,
        -0.8926150169104339,
    );
    let view = glam::dcamera::rh::view::look_at_mat4(DVec3::ZERO, fwd, DVec3::Y);
    let cam = Camera::new(
        view,
        0.016337416071001577,
        35.17620801991576,
        1.075507340923025,
        1.7671325050002888,
    )
    .unwrap();
    for th in [0.0, 1e-12] {
        let z = -4.969247159826888;
        let wall = [Aabb::new(
            DVec3::new(-10.042282828794841, -0.3317972217681957, z),
            DVec3::new(12.784994574556945, 2.7691201563350587, z + th),
        )
        .unwrap()];
        for rule in [
            WarpRule::Uniform,
            WarpRule::Minimax,
            WarpRule::MinimaxMz,
            WarpRule::Lispsm,
        ] {
            for fractions in [&[0.5][..], &[][..]] {
                let input = FrameInput::new(cam, DVec3::NEG_Y, 1024, 1080)
                    .receivers(Bound::Boxes(&wall))
                    .depth_range(0.023971319929335103, 12.169599008573467)
                    .scheme(FrameScheme::Cascades {
                        splits: shadow_aliasing::frame::CascadeSplits::Fractions {
                            fractions,
                            overlap: 0.0,
                        },
                        rule,
                    });
                let f =
                    frame(&input).unwrap_or_else(|e| panic!("{th:e} {rule:?} {fractions:?}: {e}"));
                assert!(
                    f.is_empty() && f.focus() == Focus::EdgeOn,
                    "{th:e} {rule:?} {fractions:?}: {:?}, {} maps",
                    f.focus(),
                    f.len()
                );
            }
        }
    }
}

/// Finding 4: with no receivers' bound (B is the frustum) the frame's TSM map must be the
/// frustum-only `warp` bit for bit, as for every other rule; it scaled the focus distance by
/// (f_B − n_B)/(slice depth), a ratio that is 1 but does not round-trip, and differed by 10⁻¹⁶.
#[test]
fn the_tsm_rule_without_a_bound_is_the_frustum_only_map_bit_for_bit() {
    let cam = Camera::new(glam::DMat4::IDENTITY, 1.0, 100.0, 0.5, 1.0).unwrap();
    let rule = WarpRule::Tsm { focus: 7.3 };
    let f = frame(
        &FrameInput::new(cam, DVec3::new(0.2, -0.5, -0.6), 2048, 1080)
            .scheme(FrameScheme::Single(rule)),
    )
    .unwrap();
    let view = shadow_aliasing::ViewFrustum::new(1.0, 100.0, 0.5).unwrap();
    let want = shadow_aliasing::maps::warp(&view, f.light_dir_eye(), rule).unwrap();
    assert_eq!(f.maps()[0].shadow.matrix(), want.matrix());
}
