//! The error-budget controller's neighbours (`plan::Controller`, issue 32 item 1) over two
//! recorded camera paths of `paths/` (read with the command line's path reader, so feature
//! `cli`): switched to only when cheaper or forced by a miss of the kept set-up, never sooner
//! than `patience` frames after the last switch unless forced, and fewer texels than without
//! them.
#![cfg(feature = "cli")]

use shadow_aliasing::frame::{frame, Bound, CascadeSplits, FrameInput, FrameScheme};
use shadow_aliasing::plan::{Controller, ControllerOptions};

const TARGET: f64 = 2.0;

#[allow(dead_code)]
#[path = "../src/bin/shadow-aliasing/path_file.rs"]
mod path_file;

/// A recorded path's inputs.
fn path_inputs(p: &path_file::PathFile) -> Vec<FrameInput<'_>> {
    p.frames
        .iter()
        .map(|f| {
            FrameInput::new(f.camera, f.light, 2048, p.image_height)
                .receivers(Bound::Boxes(&p.receivers))
                .casters(Bound::Boxes(&p.casters))
        })
        .collect()
}

/// Between cuts, a switch to another scheme (a neighbour) is either forced (the kept set-up,
/// built again by the frame at its resolution on this frame's input, misses the target) or
/// cheaper (fewer texels), always meets the target, and, when not forced, comes at least
/// `patience + 1` frames after the last switch; over the turn in place and the sun sweep of
/// `paths/`, at 2 px with every candidate, the neighbours find such switches, and take fewer
/// texels on average than the same controller without them.
#[test]
fn neighbours_are_switched_to_only_when_cheaper_or_forced() {
    let mut scheme_switches = 0;
    for name in ["turn", "sun_sweep"] {
        let file = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("paths")
            .join(format!("{name}.json"));
        let p = path_file::read(&file).unwrap();
        let inputs = path_inputs(&p);
        let mut mean = [0.0; 2];
        for (slot, every) in [(0, 4), (1, 0)] {
            let o = ControllerOptions {
                neighbour_every: every,
                ..ControllerOptions::new(TARGET)
            };
            let patience = o.patience as usize;
            let mut c = Controller::new(o).unwrap();
            let mut last: Option<(FrameScheme<'static>, u32, u64)> = None;
            // Equal-error cascades are kept with their planes as fractions of the visible
            // depth range (docs/planning.md): the last frame's, from its maps' splits.
            let mut fractions: Vec<f64> = Vec::new();
            let mut since = 0;
            for (i, inp) in inputs.iter().enumerate() {
                let d = c.frame(inp).unwrap();
                mean[slot] += d.texels as f64 / inputs.len() as f64;
                since += 1;
                let (scheme, res, texels) = (d.scheme, d.resolution, d.texels);
                assert!(d.meets_target && d.max_error_pixels <= TARGET, "{name} {i}");
                if let Some((s0, r0, t0)) = last.filter(|l| !d.cut && l.0 != scheme) {
                    assert!(every > 0, "{name} {i}: a scheme switch without neighbours");
                    let s0 = match s0 {
                        FrameScheme::Cascades {
                            splits: CascadeSplits::EqualError { .. },
                            rule,
                        } => FrameScheme::Cascades {
                            splits: CascadeSplits::Fractions {
                                fractions: &fractions,
                                overlap: 0.0,
                            },
                            rule,
                        },
                        s => s,
                    };
                    let mut again = inp.scheme(s0);
                    again.map_resolution = r0;
                    let kept = frame(&again).unwrap();
                    let e = kept
                        .maps()
                        .iter()
                        .map(|m| m.max_error_pixels)
                        .fold(0.0, f64::max);
                    let forced = e > TARGET;
                    assert!(forced || texels < t0, "{name} {i}: {texels} after {t0}");
                    assert!(forced || since > patience, "{name} {i}: {since} frames");
                    scheme_switches += 1;
                }
                if d.switched || d.cut {
                    since = 0;
                }
                last = Some((scheme, res, texels));
                let splits: Vec<(f64, f64)> = d.frame.maps().iter().map(|m| m.split).collect();
                let (z0, zk) = (splits[0].0, splits[splits.len() - 1].1);
                fractions.clear();
                fractions.extend(splits[1..].iter().map(|s| (s.0 - z0) / (zk - z0)));
            }
        }
        assert!(mean[0] <= mean[1], "{name}: {mean:?} texels");
    }
    assert!(scheme_switches >= 1, "no neighbour was switched to");
}

/// A texel budget without a target over the fly-over played backwards (the camera descending
/// from 200 to 2 units, so the scheme chosen high up drifts far from the best one): with a
/// shared resolution and with one per map, no frame over the budget, and the mean error (every
/// 10th frame) within 3 times that of a search in the same frame (every candidate, the least
/// error within the budget; 2.5 and 2.7 times measured), where without the searches of a set-up
/// whose error has doubled (`retry_every`) it reached 42 times.
#[test]
fn a_budget_follows_a_descent() {
    const BUDGET: u64 = 16 << 20;
    let file = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("paths/flyover.json");
    let p = path_file::read(&file).unwrap();
    let mut inputs = path_inputs(&p);
    inputs.reverse();
    for shared in [true, false] {
        let o = ControllerOptions {
            shared_resolution: shared,
            ..ControllerOptions::budget(BUDGET)
        };
        let (mut kept, mut eager) = (
            Controller::new(o.clone()).unwrap(),
            Controller::new(o).unwrap(),
        );
        let (mut mean, mut best) = (0.0, 0.0);
        for (i, inp) in inputs.iter().enumerate() {
            let d = kept.frame(inp).unwrap();
            assert!(
                d.within_budget && d.texels <= BUDGET,
                "shared {shared} frame {i}"
            );
            // Every 10th frame against a search.
            if i % 10 == 0 {
                mean += d.max_error_pixels;
                eager.cut();
                best += eager.frame(inp).unwrap().max_error_pixels;
            }
        }
        assert!(
            mean <= 3.0 * best,
            "shared {shared}: mean {mean} px, searched {best} px"
        );
    }
}
