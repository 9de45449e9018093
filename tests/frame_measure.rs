//! Measurement optional per frame (issue 23 item 7): `FrameInput::measure(false)` skips the
//! error's measurement and changes no matrix; the figures are then `None` (and +∞ in the fields),
//! except where the scheme measured anyway to build the map.
use glam::{DMat4, DVec3};
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::frame::{
    frame, Aabb, Bound, Camera, CascadeSplits, FrameInput, FrameScheme, MapError,
};
use shadow_aliasing::maps::faces::FaceWarp;
use shadow_aliasing::maps::{ClipDepth, TsmOptions, TsmSearch, WarpRule};
use shadow_aliasing::measure::vertex::vertex_max;

fn bits(m: &DMat4) -> [u64; 16] {
    m.to_cols_array().map(f64::to_bits)
}

fn schemes() -> Vec<FrameScheme<'static>> {
    vec![
        FrameScheme::Single(WarpRule::Lispsm),
        FrameScheme::Single(WarpRule::Minimax),
        FrameScheme::Single(WarpRule::Uniform),
        FrameScheme::Cascades {
            splits: CascadeSplits::Scheme {
                scheme: SplitScheme::Practical { lambda: 0.8 },
                k: 4,
                overlap: 0.1,
            },
            rule: WarpRule::Lispsm,
        },
        FrameScheme::Stable(CascadeSplits::Scheme {
            scheme: SplitScheme::Practical { lambda: 0.8 },
            k: 3,
            overlap: 0.0,
        }),
        FrameScheme::Tsm(TsmOptions {
            focus: 30.0,
            search: TsmSearch::EightyPercent,
        }),
    ]
}

/// Unmeasured: every matrix bit for bit the measured frame's, `error()` None, the fields +∞
/// (never NaN), the frame's Σ S̄ None; measured: `error()` is the fields, and is what the
/// measurement of the map's own matrix over its body gives.
#[test]
fn unmeasured_frames_keep_the_matrices_and_report_no_error() {
    let ground = [Aabb::new([-80.0, -1.0, -150.0], [80.0, 0.0, 5.0]).unwrap()];
    let casters = [
        Aabb::new([-5.0, 0.0, -40.0], [5.0, 12.0, -30.0]).unwrap(),
        ground[0],
    ];
    let mut maps = 0;
    for (i, light) in [
        DVec3::new(0.3, -0.8, -0.4),
        DVec3::new(-0.6, -0.5, 0.6),
        DVec3::new(0.0, -1.0, 0.0),
    ]
    .into_iter()
    .enumerate()
    {
        let eye = DVec3::new(3.0 * i as f64, 4.0, 10.0);
        let view = DMat4::from_rotation_x(0.3) * DMat4::from_translation(-eye);
        let cam = Camera::new(view, 0.5, 200.0, 0.6, 16.0 / 9.0).unwrap();
        for scheme in schemes() {
            let input = FrameInput::new(cam, light, 2048, 1080)
                .receivers(Bound::Boxes(&ground))
                .casters(Bound::Boxes(&casters))
                .scheme(scheme);
            let on = frame(&input).unwrap();
            let off = frame(&input.measure(false)).unwrap();
            assert!(on.storage_factor().is_some());
            assert_eq!(off.storage_factor(), None, "{scheme:?}");
            assert_eq!(on.len(), off.len());
            for (a, b) in on.maps().iter().zip(off.maps().iter()) {
                maps += 1;
                for d in ClipDepth::ALL {
                    assert_eq!(bits(&a.world_to_clip(d)), bits(&b.world_to_clip(d)));
                }
                assert_eq!(bits(&a.shadow.matrix()), bits(&b.shadow.matrix()));
                assert_eq!(a.texel_world.to_bits(), b.texel_world.to_bits());
                assert_eq!(b.error(), None, "{scheme:?}");
                for v in [b.max_mx, b.max_mz, b.storage_factor, b.max_error_pixels] {
                    assert_eq!(v, f64::INFINITY);
                }
                let g = b.gpu(ClipDepth::ZeroToOne);
                assert_eq!(g.max_error_pixels, f32::INFINITY);
                let e = a.error().expect("measured");
                assert_eq!(
                    e,
                    MapError {
                        max_mx: a.max_mx,
                        max_mz: a.max_mz,
                        storage_factor: a.storage_factor,
                        max_error_pixels: a.max_error_pixels,
                    }
                );
                // Independently: the measurement of the map's own matrix over its body (eye
                // space), with the frame's light and tan θ.
                let l = on.light_dir_eye();
                let m =
                    vertex_max(&a.shadow.matrix(), l, cam.view().tan_half_fov(), a.body()).unwrap();
                assert_eq!(m.max_mx, e.max_mx);
                assert_eq!(m.max_mz, e.max_mz);
                assert!(
                    (e.max_error_pixels - m.max_mx.max(m.max_mz) * 1080.0 / 2048.0).abs()
                        < 1e-12 * e.max_error_pixels
                );
            }
        }
    }
    assert!(maps > 20, "{maps} maps compared");
}

/// Face partitions measure each candidate to fit it, and equal-error splits are placed by the
/// measured error: both report their figures with measurement off too, the same as with it on.
#[test]
fn schemes_that_measure_to_build_report_their_figures() {
    let cam = Camera::new(DMat4::IDENTITY, 1.0, 300.0, 0.6, 1.5).unwrap();
    let light = DVec3::new(0.3, -0.8, -0.4);
    for scheme in [
        FrameScheme::Faces {
            rule: FaceWarp::Lispsm,
            k: 2,
        },
        FrameScheme::Cascades {
            splits: CascadeSplits::EqualError { k: 3 },
            rule: WarpRule::Lispsm,
        },
    ] {
        let input = FrameInput::new(cam, light, 1024, 720).scheme(scheme);
        let on = frame(&input).unwrap();
        let off = frame(&input.measure(false)).unwrap();
        assert!(!off.is_empty());
        for (a, b) in on.maps().iter().zip(off.maps().iter()) {
            assert!(b.error().is_some(), "{scheme:?}");
            assert_eq!(a.error(), b.error());
            assert_eq!(bits(&a.world_to_clip), bits(&b.world_to_clip));
        }
    }
}
