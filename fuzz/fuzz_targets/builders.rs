//! Random frusta, lights, warp rules and partitions into the builders and the measurement.
//! Every `Ok` is finite and valid: the matrix finite, every frustum (or partition) corner mapped
//! inside the clip volume within the crate's slack (10⁻⁶, `verify_clip`), the measured maxima
//! finite and positive; every `Err` is the crate's typed error with a message. Never a panic.
#![no_main]

use arbitrary::{Result, Unstructured};
use glam::DVec3;
use libfuzzer_sys::fuzz_target;
use shadow_aliasing::analytic::partition::{z_splits, SplitScheme};
use shadow_aliasing::maps::cascades::{bounding_sphere, cascades};
use shadow_aliasing::maps::faces::{face_partitions, FaceWarp};
use shadow_aliasing::maps::minimax::{minimax_mz_n_prime, minimax_n_prime};
use shadow_aliasing::maps::{light_space, tsm, warp, ClipDepth, TsmOptions, TsmSearch};
use shadow_aliasing::measure::{frustum_max, FrustumError, ShadowMap};
use shadow_aliasing::ViewFrustum;

mod input;

use input::{fov, in_clip, num, rule, typed};

fn finite_error(e: &FrustumError, what: &str) {
    for x in [e.max_mx, e.max_mz, e.storage_factor] {
        assert!(x.is_finite() && x > 0.0, "{what}: {e:?}");
    }
}

fn run(u: &mut Unstructured) -> Result<()> {
    let (near, far, half_fov) = (num(u)?, num(u)?, fov(u, 4)?);
    let aspect = if u.arbitrary()? { 1.0 } else { num(u)? };
    let view = match ViewFrustum::with_aspect(near, far, half_fov, aspect) {
        Ok(v) => v,
        Err(e) => {
            typed(&e);
            return Ok(());
        }
    };
    let light = DVec3::new(num(u)?, num(u)?, num(u)?);
    let corners = view.corners();
    let what = format!("view {view:?} light {light}");
    for x in [view.alpha(), view.tan_half_fov(), view.n_prime_lispsm()] {
        assert!(x.is_finite() && x > 0.0, "{what}: accessor {x}");
    }
    match u.int_in_range(0u8..=5)? {
        0 | 1 => {
            let r = rule(u, num)?;
            let what = format!("{what} {r:?}");
            match warp(&view, light, r) {
                Ok(s) => {
                    in_clip(&s.matrix(), &corners, -1.0, &what);
                    let z01 = format!("{what} [0, 1] depth");
                    in_clip(
                        &s.with_clip_depth(ClipDepth::ZeroToOne),
                        &corners,
                        0.0,
                        &z01,
                    );
                    match frustum_max(&view, &s.shadow_map()) {
                        Ok(e) => finite_error(&e, &what),
                        Err(e) => typed(&e),
                    }
                }
                Err(e) => typed(&e),
            }
        }
        2 => {
            for r in [
                minimax_n_prime(&view, light),
                minimax_mz_n_prime(&view, light),
            ] {
                match r {
                    Ok(o) => {
                        for x in [o.max_mx, o.max_mz, o.storage_factor()] {
                            assert!(x.is_finite() && x > 0.0, "{what}: minimax {o:?}");
                        }
                    }
                    Err(e) => typed(&e),
                }
            }
            let axis = DVec3::new(num(u)?, num(u)?, num(u)?);
            match light_space(light, axis) {
                Ok(ls) => {
                    for v in [ls.x, ls.y, ls.z] {
                        assert!(
                            (v.length() - 1.0).abs() < 1e-12,
                            "{what} axis {axis}: {ls:?}"
                        );
                    }
                    assert!((ls.x.cross(ls.y) - ls.z).length() < 1e-12, "{what}: {ls:?}");
                }
                Err(e) => typed(&e),
            }
            let (a, b) = (num(u)?, num(u)?);
            match bounding_sphere(&view, a, b) {
                Ok((c, r)) => {
                    assert!(
                        c.is_finite() && r.is_finite() && r > 0.0,
                        "{what}: sphere {c} {r}"
                    );
                    let sub = view
                        .with_depth_range(a, b)
                        .expect("sphere of an invalid range");
                    // In units of r: the distance itself can overflow where r does not.
                    for p in sub.corners() {
                        let d = (p / r - DVec3::new(0.0, 0.0, -c / r)).length();
                        assert!(d <= 1.0 + 1e-9, "{what} [{a}, {b}]: {p} at {d} r > r = {r}");
                    }
                }
                Err(e) => typed(&e),
            }
        }
        3 => {
            let k = usize::from(u.int_in_range(0u8..=9)?);
            let scheme = match u.int_in_range(0u8..=3)? {
                0 => SplitScheme::Uniform,
                1 => SplitScheme::SelfSimilar,
                2 => SplitScheme::Practical { lambda: num(u)? },
                _ => SplitScheme::Adaptive {
                    light_angle: num(u)?,
                    ratio: num(u)?,
                },
            };
            let r = rule(u, num)?;
            let overlap = num(u)?;
            let splits = match z_splits(view.near(), view.far(), k, scheme) {
                Ok(s) => s,
                Err(e) => {
                    typed(&e);
                    return Ok(());
                }
            };
            match cascades(&view, light, &splits, r, overlap) {
                Ok(cs) => {
                    assert!(cs.k() > 0, "{what}: empty cascades");
                    for c in cs.iter() {
                        let what =
                            format!("{what} {r:?} cascade [{}, {}]", c.split_near, c.split_far);
                        let sub = view
                            .with_depth_range(c.split_near, c.split_far)
                            .expect("cascade of an invalid range");
                        in_clip(&c.shadow.matrix(), &sub.corners(), -1.0, &what);
                        for x in [c.error.max_mx, c.error.max_mz, c.storage_factor()] {
                            assert!(x.is_finite() && x > 0.0, "{what}: {:?}", c.error);
                        }
                    }
                }
                Err(e) => typed(&e),
            }
        }
        4 => {
            let k = usize::from(u.int_in_range(0u8..=9)?);
            let fw = match u.int_in_range(0u8..=2)? {
                0 => FaceWarp::Uniform,
                1 => FaceWarp::Psm,
                _ => FaceWarp::Lispsm,
            };
            match face_partitions(&view, light, fw, k) {
                Ok(fp) => {
                    // An empty result is never a success (the finding at n = 2.2e-308,
                    // f = θ = π/2 − 1 ulp, light (π/2 − 1 ulp, π/2 − 1 ulp, −0), now fixed).
                    assert!(!fp.is_empty(), "{what} {fw:?}: Ok with no partitions");
                    for p in fp.iter() {
                        let what = format!("{what} {fw:?} face {:?}", p.face);
                        in_clip(&p.shadow.matrix(), &p.vertices, -1.0, &what);
                        for x in [p.error.max_mx, p.error.max_mz, p.storage_factor()] {
                            assert!(x.is_finite() && x > 0.0, "{what}: {:?}", p.error);
                        }
                    }
                }
                Err(e) => typed(&e),
            }
        }
        _ => {
            let search = match u.int_in_range(0u8..=2)? {
                0 => TsmSearch::EightyPercent,
                1 => TsmSearch::Line(num(u)?),
                _ => TsmSearch::Iterative {
                    map_lines: u.int_in_range(0u32..=4096)?,
                },
            };
            let focus = num(u)?;
            match tsm(&view, light, TsmOptions { focus, search }) {
                Ok(t) => {
                    let what = format!("{what} TSM {search:?} focus {focus}");
                    in_clip(&t.shadow.matrix(), &corners, -1.0, &what);
                    match ShadowMap::new(t.shadow.matrix(), t.shadow.light_dir())
                        .and_then(|sm| frustum_max(&view, &sm))
                    {
                        Ok(e) => finite_error(&e, &what),
                        Err(e) => typed(&e),
                    }
                }
                Err(e) => typed(&e),
            }
        }
    }
    Ok(())
}

fuzz_target!(|data: &[u8]| {
    let mut u = Unstructured::new(data);
    let _ = run(&mut u);
});
