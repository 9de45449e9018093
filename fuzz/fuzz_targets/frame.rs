//! Random cameras, lights, scene bounds and schemes into the world-space frame API
//! (`shadow_aliasing::frame`). Every `Ok` is finite and valid: every map's matrices finite, its
//! error figures and texel size finite and positive, every vertex of its focus body inside the
//! clip volume within the crate's slack (10⁻⁶, `verify_clip`) in both depth conventions, the
//! frame's bookkeeping consistent (`len`, `storage_factor`, `focus`, `face`, ordered splits);
//! every `Err` is the crate's typed error with a message. Never a panic.
#![no_main]

use arbitrary::{Result, Unstructured};
use glam::{DMat3, DMat4, DQuat, DVec3, DVec4, Mat4};
use libfuzzer_sys::fuzz_target;
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::frame::{
    frame, frame_into, Aabb, Bound, Camera, CascadeSplits, Focus, Frame, FrameInput, FrameScheme,
    WarpCentre, MAX_BOUND_PLANES, MAX_FACE_K,
};
use shadow_aliasing::maps::faces::FaceWarp;
use shadow_aliasing::maps::{ClipDepth, TsmOptions, TsmSearch, WarpRule};

mod input;

use input::{fov, in_clip, num, rule, typed};

/// A fraction in [0, 1] (16 bits; 0 and 1 reachable).
fn frac(u: &mut Unstructured) -> Result<f64> {
    Ok(f64::from(u.arbitrary::<u16>()?) / 65535.0)
}

/// Mostly `lo + (hi − lo)·frac`, sometimes `num`.
fn between(u: &mut Unstructured, lo: f64, hi: f64) -> Result<f64> {
    if u.ratio(1u8, 8)? {
        num(u)
    } else {
        Ok(lo + (hi - lo) * frac(u)?)
    }
}

/// The η of `WarpRule::Eta`: half the time inside [−1, 1] (mostly), half any number.
fn eta(u: &mut Unstructured) -> Result<f64> {
    if u.arbitrary()? {
        between(u, -1.0, 1.0)
    } else {
        num(u)
    }
}

fn split_scheme(u: &mut Unstructured) -> Result<SplitScheme> {
    Ok(match u.int_in_range(0u8..=4)? {
        0 => SplitScheme::Uniform,
        1 => SplitScheme::SelfSimilar,
        2 => SplitScheme::Practical {
            lambda: between(u, 0.0, 1.0)?,
        },
        3 => SplitScheme::Adaptive {
            light_angle: between(u, 0.0, std::f64::consts::FRAC_PI_2)?,
            ratio: between(u, 1.0, 100.0)?,
        },
        _ => SplitScheme::Exponent {
            exponent: between(u, 0.0, 4.0)?,
        },
    })
}

fn overlap(u: &mut Unstructured) -> Result<f64> {
    between(u, 0.0, 0.999)
}

/// Cascade splits; `planes` holds the slices' storage.
fn splits<'a>(
    u: &mut Unstructured,
    near: f64,
    far: f64,
    planes: &'a mut Vec<f64>,
) -> Result<CascadeSplits<'a>> {
    Ok(match u.int_in_range(0u8..=3)? {
        0 => CascadeSplits::Scheme {
            scheme: split_scheme(u)?,
            k: usize::from(u.int_in_range(0u8..=17)?),
            overlap: overlap(u)?,
        },
        1 => {
            let k = usize::from(u.int_in_range(0u8..=17)?);
            if u.ratio(1u8, 6)? {
                for _ in 0..=k {
                    planes.push(num(u)?);
                }
            } else {
                // Increasing fractions of [near, far] (a repeat is possible: must be refused).
                let mut f = Vec::with_capacity(k + 1);
                for _ in 0..=k {
                    f.push(frac(u)?);
                }
                f.sort_by(f64::total_cmp);
                if u.arbitrary()? && !f.is_empty() {
                    f[0] = 0.0;
                    let last = f.len() - 1;
                    f[last] = 1.0;
                }
                planes.extend(f.iter().map(|t| near + (far - near) * t));
            }
            CascadeSplits::Distances {
                planes,
                overlap: overlap(u)?,
            }
        }
        2 => {
            let k = usize::from(u.int_in_range(0u8..=16)?);
            for _ in 0..k {
                planes.push(if u.ratio(1u8, 8)? { num(u)? } else { frac(u)? });
            }
            if u.ratio(7u8, 8)? {
                planes.sort_by(f64::total_cmp);
            }
            CascadeSplits::Fractions {
                fractions: planes,
                overlap: overlap(u)?,
            }
        }
        _ => {
            let maximum_distance = between(u, near, 2.0 * far)?;
            let minimum_distance = between(u, 0.0, maximum_distance)?;
            let first_far_bound = between(u, minimum_distance, maximum_distance)?;
            CascadeSplits::Bevy {
                k: usize::from(u.int_in_range(0u8..=17)?),
                minimum_distance,
                maximum_distance,
                first_far_bound,
                overlap_proportion: overlap(u)?,
            }
        }
    })
}

fn tsm_options(u: &mut Unstructured, near: f64, far: f64) -> Result<TsmOptions> {
    let search = match u.int_in_range(0u8..=3)? {
        0 => TsmSearch::EightyPercent,
        1 => TsmSearch::Line(between(u, -1.0, 1.0)?),
        2 => TsmSearch::Iterative {
            map_lines: u.int_in_range(0u32..=4096)?,
        },
        _ => TsmSearch::IterativeExhaustive {
            map_lines: u.int_in_range(0u32..=512)?,
        },
    };
    Ok(TsmOptions {
        focus: between(u, 0.0, far - near)?,
        search,
    })
}

/// A rotation: identity, a signed axis permutation (exact: boxes can touch the frustum exactly),
/// or a unit quaternion of arbitrary numbers.
fn rotation(u: &mut Unstructured) -> Result<DMat3> {
    Ok(match u.int_in_range(0u8..=3)? {
        0 => DMat3::IDENTITY,
        1 => {
            let perms = [
                [0, 1, 2],
                [1, 2, 0],
                [2, 0, 1],
                [1, 0, 2],
                [0, 2, 1],
                [2, 1, 0],
            ];
            let p = perms[u.choose_index(6)?];
            let mut cols = [DVec3::ZERO; 3];
            for (i, c) in cols.iter_mut().enumerate() {
                let mut v = [0.0; 3];
                v[p[i]] = if u.arbitrary()? { 1.0 } else { -1.0 };
                *c = DVec3::from_array(v);
            }
            let m = DMat3::from_cols(cols[0], cols[1], cols[2]);
            if m.determinant() < 0.0 {
                DMat3::from_cols(-cols[0], cols[1], cols[2])
            } else {
                m
            }
        }
        _ => {
            let q = DQuat::from_xyzw(
                between(u, -1.0, 1.0)?,
                between(u, -1.0, 1.0)?,
                between(u, -1.0, 1.0)?,
                between(u, -1.0, 1.0)?,
            );
            let q = if q.is_finite() && q.length() > 1e-3 {
                q.normalize()
            } else {
                DQuat::IDENTITY
            };
            DMat3::from_quat(q)
        }
    })
}

/// World → eye: mostly rigid (rotation + translation), sometimes 16 arbitrary numbers, sometimes
/// through `Camera::from_mat4` in single precision. Returns the camera or `None` (refused).
fn camera(u: &mut Unstructured) -> Result<Option<Camera>> {
    let (near, far) = if u.ratio(1u8, 8)? {
        (num(u)?, num(u)?)
    } else {
        let e = i32::from(u.int_in_range(-3i8..=2)?);
        let n = (0.1 + 9.9 * frac(u)?) * 10f64.powi(e);
        let ratio = 10f64.powf(0.01 + 6.0 * frac(u)?);
        (n, n * ratio)
    };
    let half_fov = fov(u, 8)?;
    let aspect = match u.int_in_range(0u8..=3)? {
        0 => 1.0,
        1 => num(u)?,
        _ => 0.25 + 3.75 * frac(u)?,
    };
    let r = rotation(u)?;
    let t = match u.int_in_range(0u8..=3)? {
        0 => DVec3::ZERO,
        1 => DVec3::new(num(u)?, num(u)?, num(u)?),
        _ => DVec3::new(
            f64::from(u.int_in_range(-100i16..=100)?),
            f64::from(u.int_in_range(-100i16..=100)?),
            f64::from(u.int_in_range(-100i16..=100)?),
        ),
    };
    let rigid = DMat4::from_cols(
        r.x_axis.extend(0.0),
        r.y_axis.extend(0.0),
        r.z_axis.extend(0.0),
        t.extend(1.0),
    );
    let cam = match u.int_in_range(0u8..=9)? {
        0 => {
            let mut a = [0.0; 16];
            for x in &mut a {
                *x = num(u)?;
            }
            Camera::new(DMat4::from_cols_array(&a), near, far, half_fov, aspect)
        }
        1 => Camera::from_mat4(rigid.as_mat4(), near, far, half_fov, aspect),
        2 => {
            let mut a = rigid.as_mat4().to_cols_array();
            let i = u.choose_index(16)?;
            a[i] = num(u)? as f32;
            Camera::from_mat4(Mat4::from_cols_array(&a), near, far, half_fov, aspect)
        }
        _ => Camera::new(rigid, near, far, half_fov, aspect),
    };
    match cam {
        Ok(c) => Ok(Some(c)),
        Err(e) => {
            typed(&e);
            Ok(None)
        }
    }
}

/// The world AABB of an eye-space box (exact for the axis-permuting rotations).
fn eye_box_to_world(cam: &Camera, lo: DVec3, hi: DVec3) -> (DVec3, DVec3) {
    let e2w = cam.world_to_eye().inverse();
    let (mut a, mut b) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
    for i in 0..8 {
        let p = DVec3::new(
            if i & 1 == 0 { lo.x } else { hi.x },
            if i & 2 == 0 { lo.y } else { hi.y },
            if i & 4 == 0 { lo.z } else { hi.z },
        );
        let w = e2w.transform_point3(p);
        a = a.min(w);
        b = b.max(w);
    }
    (a, b)
}

/// A box: across the frustum, touching it at a face, an edge or a vertex, outside it, flat,
/// containing it, or of arbitrary numbers (refused when invalid: only valid ones are pushed).
fn scene_box(u: &mut Unstructured, cam: &Camera) -> Result<Option<Aabb>> {
    let v = cam.view();
    let (n, f) = (v.near(), v.far());
    let (ty, tx) = (v.tan_half_fov(), v.tan_half_fov() * v.aspect());
    let kind = u.int_in_range(0u8..=9)?;
    let (lo, hi) = match kind {
        0..=3 => {
            // Across the frustum: a centre in view, half-sizes a fraction of the depth.
            let d = n + (f - n) * frac(u)?;
            let c = DVec3::new(
                (3.0 * frac(u)? - 1.5) * d * tx,
                (3.0 * frac(u)? - 1.5) * d * ty,
                -d,
            );
            let mut h = DVec3::new(frac(u)?, frac(u)?, frac(u)?) * d;
            if u.ratio(1u8, 3)? {
                // Flat: zero thickness on one axis.
                match u.choose_index(3)? {
                    0 => h.x = 0.0,
                    1 => h.y = 0.0,
                    _ => h.z = 0.0,
                }
            }
            (c - h, c + h)
        }
        4 | 5 => {
            // Touching from outside: beyond the far face or before the near face, and/or beyond
            // a side at that depth (a face, an edge or a vertex).
            let far_side = u.arbitrary::<bool>()?;
            let depth = if far_side { f } else { n };
            let s = DVec3::splat(depth * (0.1 + frac(u)?));
            let (mut lo, mut hi) = if far_side {
                (DVec3::new(-s.x, -s.y, -f - s.z), DVec3::new(s.x, s.y, -f))
            } else {
                (
                    DVec3::new(-s.x, -s.y, -n),
                    DVec3::new(s.x, s.y, -n + s.z.min(n)),
                )
            };
            match u.int_in_range(0u8..=3)? {
                0 => {}
                1 => {
                    lo.x = depth * tx;
                    hi.x = lo.x + s.x;
                }
                2 => {
                    hi.y = -depth * ty;
                    lo.y = hi.y - s.y;
                }
                _ => {
                    lo.x = depth * tx;
                    hi.x = lo.x + s.x;
                    lo.y = depth * ty;
                    hi.y = lo.y + s.y;
                }
            }
            if u.arbitrary()? {
                // A side face only: beyond x = d tan at every depth in [n, f] is outside the
                // frustum from the far edge's x on.
                lo = DVec3::new(f * tx, -f * ty, -f);
                hi = DVec3::new(f * tx + s.x, f * ty, -n);
            }
            (lo, hi)
        }
        6 => {
            // Outside: behind the camera, beyond far, or far to a side.
            let s = f * (0.1 + frac(u)?);
            match u.int_in_range(0u8..=2)? {
                0 => (DVec3::new(-s, -s, s * 0.01), DVec3::new(s, s, s)),
                1 => (
                    DVec3::new(-s, -s, -f - 2.0 * s),
                    DVec3::new(s, s, -f * 1.01),
                ),
                _ => (
                    DVec3::new(2.0 * f * tx + s, -s, -f),
                    DVec3::new(3.0 * f * tx + s, s, -n),
                ),
            }
        }
        7 => {
            // Containing the frustum (or nearly).
            let m = 1.0 + 2.0 * frac(u)? - 0.5;
            (
                DVec3::new(-f * tx * m, -f * ty * m, -f * m),
                DVec3::new(f * tx * m, f * ty * m, -n * (2.0 - m).max(0.0)),
            )
        }
        _ => {
            let lo = DVec3::new(num(u)?, num(u)?, num(u)?);
            let hi = if u.arbitrary()? {
                DVec3::new(num(u)?, num(u)?, num(u)?)
            } else {
                lo + DVec3::new(frac(u)?, frac(u)?, frac(u)?) * f
            };
            // World coordinates directly: no transform.
            return Ok(match Aabb::new(lo, hi) {
                Ok(b) => Some(b),
                Err(e) => {
                    typed(&e);
                    None
                }
            });
        }
    };
    let (a, b) = eye_box_to_world(cam, lo, hi);
    Ok(match Aabb::new(a, b) {
        Ok(b) => Some(b),
        Err(e) => {
            typed(&e);
            None
        }
    })
}

/// World planes of a polytope: a (possibly flat) box's six, cut by more planes through points in
/// view, or arbitrary planes (possibly unbounded).
fn polytope(u: &mut Unstructured, cam: &Camera, out: &mut Vec<DVec4>) -> Result<()> {
    let v = cam.view();
    let (n, f) = (v.near(), v.far());
    let e2w = cam.world_to_eye().inverse();
    if u.ratio(3u8, 4)? {
        if let Some(b) = scene_box(u, cam)? {
            out.extend([
                DVec4::new(1.0, 0.0, 0.0, -b.max.x),
                DVec4::new(-1.0, 0.0, 0.0, b.min.x),
                DVec4::new(0.0, 1.0, 0.0, -b.max.y),
                DVec4::new(0.0, -1.0, 0.0, b.min.y),
                DVec4::new(0.0, 0.0, 1.0, -b.max.z),
                DVec4::new(0.0, 0.0, -1.0, b.min.z),
            ]);
        }
    }
    let extra = u.int_in_range(0u8..=8)?;
    for _ in 0..extra {
        if u.ratio(1u8, 6)? {
            out.push(DVec4::new(num(u)?, num(u)?, num(u)?, num(u)?));
        } else {
            let d = n + (f - n) * frac(u)?;
            let pe = DVec3::new((2.0 * frac(u)? - 1.0) * d, (2.0 * frac(u)? - 1.0) * d, -d);
            let nrm = DVec3::new(
                2.0 * frac(u)? - 1.0,
                2.0 * frac(u)? - 1.0,
                2.0 * frac(u)? - 1.0,
            );
            let pw = e2w.transform_point3(pe);
            let nw = e2w.transform_vector3(nrm);
            out.push(nw.extend(-nw.dot(pw)));
            if u.ratio(1u8, 8)? {
                // The opposite plane at the same place: zero thickness.
                out.push((-nw).extend(nw.dot(pw)));
            }
        }
    }
    if out.is_empty() || u.ratio(1u8, 32)? {
        out.push(DVec4::new(num(u)?, num(u)?, num(u)?, num(u)?));
    }
    out.truncate(MAX_BOUND_PLANES + usize::from(u.ratio(1u8, 16)?));
    Ok(())
}

#[derive(Default)]
struct BoundStore {
    boxes: Vec<Aabb>,
    planes: Vec<DVec4>,
}

/// 0 unbounded, 1 boxes, 2 polytope.
fn bound_kind(u: &mut Unstructured, cam: &Camera, s: &mut BoundStore) -> Result<u8> {
    let kind = u.int_in_range(0u8..=4)?;
    Ok(match kind {
        0 => 0,
        1..=3 => {
            let k = u.int_in_range(1u8..=3)?;
            for _ in 0..k {
                if let Some(b) = scene_box(u, cam)? {
                    s.boxes.push(b);
                }
            }
            if s.boxes.is_empty() && u.ratio(1u8, 4)? {
                // An empty list: must be refused for receivers.
                return Ok(1);
            }
            if s.boxes.is_empty() {
                0
            } else {
                1
            }
        }
        _ => {
            polytope(u, cam, &mut s.planes)?;
            2
        }
    })
}

fn make_bound(kind: u8, s: &BoundStore) -> Bound<'_> {
    match kind {
        0 => Bound::Unbounded,
        1 => Bound::Boxes(&s.boxes),
        _ => Bound::Polytope(&s.planes),
    }
}

/// The input, formatted only when an assertion fails.
struct What<'i, 'a>(&'i FrameInput<'a>);

impl std::fmt::Display for What<'_, '_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{:?}", self.0)
    }
}

fn pos(x: f64, what: &What, i: usize, name: &str) {
    assert!(
        x.is_finite() && x > 0.0,
        "{what} map {i}: {name} = {x}, not finite and positive"
    );
}

// `len() == 0` on purpose: `is_empty` and `storage_factor` are checked against `len`.
#[allow(clippy::len_zero)]
fn check(input: &FrameInput<'_>, f: &Frame) {
    let what = &What(input);
    let maps = f.maps();
    assert_eq!(f.len(), maps.len(), "{what}: len");
    assert_eq!(f.is_empty(), f.len() == 0, "{what}: is_empty");
    assert_eq!(f.slots().iter().flatten().count(), f.len(), "{what}: slots");
    assert_eq!(
        f.storage_factor().is_some(),
        f.len() > 0,
        "{what}: storage_factor {:?} with {} maps",
        f.storage_factor(),
        f.len()
    );
    if let Some(s) = f.storage_factor() {
        assert!(s.is_finite() && s > 0.0, "{what}: frame storage_factor {s}");
    }
    let l = f.light_dir_eye();
    assert!(
        l.is_finite() && (l.length() - 1.0).abs() < 1e-9,
        "{what}: light_dir_eye {l}"
    );
    match maps.iter().next() {
        Some(m) => assert_eq!(f.focus(), m.focus, "{what}: frame focus"),
        None => assert!(
            matches!(f.focus(), Focus::Empty | Focus::EdgeOn),
            "{what}: no map but focus {:?}",
            f.focus()
        ),
    }
    let faces = matches!(input.scheme, FrameScheme::Faces { .. });
    let cascades = matches!(
        input.scheme,
        FrameScheme::Cascades { .. } | FrameScheme::Stable(_)
    );
    let single = matches!(input.scheme, FrameScheme::Single(_) | FrameScheme::Tsm(_));
    if single {
        assert!(f.slots().len() <= 1, "{what}: {} slots", f.slots().len());
    }
    let view = input.camera.world_to_eye();
    let mut prev_split: Option<(f64, f64)> = None;
    for (i, m) in maps.iter().enumerate() {
        assert!(
            matches!(m.focus, Focus::Body | Focus::Flat | Focus::ZeroDepth),
            "{what} map {i}: built map with focus {:?}",
            m.focus
        );
        assert_eq!(m.face.is_some(), faces, "{what} map {i}: face");
        for d in [ClipDepth::NegOneToOne, ClipDepth::ZeroToOne] {
            let w = m.world_to_clip(d);
            assert!(w.is_finite(), "{what} map {i}: world_to_clip({d:?}) {w:?}");
            // `to_mat4` is documented only as the f32 form: asserted finite where the f64 matrix
            // fits f32 (finding 1: a camera far from the world origin overflows it, undocumented).
            let fits = w
                .abs()
                .to_cols_array()
                .iter()
                .all(|x| *x <= f64::from(f32::MAX) * 0.5);
            let g = m.to_mat4(d);
            assert!(
                !fits || g.is_finite(),
                "{what} map {i}: to_mat4({d:?}) {g:?}"
            );
        }
        assert_eq!(
            m.world_to_clip,
            m.shadow.matrix() * view,
            "{what} map {i}: world_to_clip"
        );
        assert_eq!(
            m.world_to_clip(ClipDepth::ZeroToOne),
            m.shadow.with_clip_depth(ClipDepth::ZeroToOne) * view,
            "{what} map {i}: world_to_clip(ZeroToOne)"
        );
        pos(m.max_mx, what, i, "max_mx");
        pos(m.max_mz, what, i, "max_mz");
        pos(m.storage_factor, what, i, "storage_factor");
        pos(m.max_error_pixels, what, i, "max_error_pixels");
        pos(m.texel_world, what, i, "texel_world");
        let body = m.body();
        assert!(!body.is_empty(), "{what} map {i}: empty body");
        for p in body {
            assert!(p.is_finite(), "{what} map {i}: body vertex {p}");
        }
        in_clip(
            &m.shadow.matrix(),
            body,
            -1.0,
            format_args!("{what} map {i}"),
        );
        in_clip(
            &m.shadow.with_clip_depth(ClipDepth::ZeroToOne),
            body,
            0.0,
            format_args!("{what} map {i}"),
        );
        assert!(
            m.split.0 <= m.split.1,
            "{what} map {i}: split {:?}",
            m.split
        );
        assert!(
            m.blend.0 <= m.blend.1,
            "{what} map {i}: blend {:?}",
            m.blend
        );
        if cascades {
            if let Some(p) = prev_split {
                assert!(
                    p.0 <= m.split.0 && p.1 <= m.split.1,
                    "{what} map {i}: splits out of order {p:?} then {:?}",
                    m.split
                );
            }
            prev_split = Some(m.split);
        }
    }
}

fn run(u: &mut Unstructured) -> Result<()> {
    let Some(cam) = camera(u)? else {
        return Ok(());
    };
    let v = *cam.view();
    let (near, far) = (v.near(), v.far());
    let e2w = cam.world_to_eye().inverse();
    let light = match u.int_in_range(0u8..=5)? {
        0 => DVec3::new(num(u)?, num(u)?, num(u)?),
        1 => DVec3::NEG_Y,
        2 => e2w.transform_vector3(DVec3::NEG_Z), // along the view
        3 => e2w.transform_vector3(DVec3::Z),     // toward the eye
        _ => DVec3::new(
            2.0 * frac(u)? - 1.0,
            2.0 * frac(u)? - 1.0,
            2.0 * frac(u)? - 1.0,
        ),
    };
    let mut rs = BoundStore::default();
    let mut cs = BoundStore::default();
    let rk = bound_kind(u, &cam, &mut rs)?;
    let ck = if u.ratio(1u8, 4)? {
        // The casters are the receivers (a ground plane that also casts).
        cs.boxes.clone_from(&rs.boxes);
        cs.planes.clone_from(&rs.planes);
        rk
    } else {
        bound_kind(u, &cam, &mut cs)?
    };
    let depth_range = match u.int_in_range(0u8..=5)? {
        0 => Some((num(u)?, num(u)?)),
        1 => {
            let (a, b) = (frac(u)?, frac(u)?);
            Some((
                near + (far - near) * a.min(b),
                near + (far - near) * a.max(b),
            ))
        }
        _ => None,
    };
    let depth_clamp = u.arbitrary::<bool>()?;
    let centre = match u.int_in_range(0u8..=2)? {
        0 => WarpCentre::Rule,
        1 => WarpCentre::Eye,
        _ => WarpCentre::NearestVertex,
    };
    let res = |u: &mut Unstructured| -> Result<u32> {
        Ok(match u.int_in_range(0u8..=7)? {
            0 => u.arbitrary()?,
            1 => u.int_in_range(0u32..=4)?,
            _ => 1 << u.int_in_range(2u32..=14)?,
        })
    };
    let map_resolution = res(u)?;
    let image_height = res(u)?;
    let mut planes = Vec::new();
    let scheme = match u.int_in_range(0u8..=5)? {
        0 | 1 => FrameScheme::Single(rule(u, eta)?),
        2 => {
            let r = rule(u, eta)?;
            FrameScheme::Cascades {
                splits: splits(u, near, far, &mut planes)?,
                rule: r,
            }
        }
        3 => FrameScheme::Stable(splits(u, near, far, &mut planes)?),
        4 => FrameScheme::Tsm(tsm_options(u, near, far)?),
        _ => FrameScheme::Faces {
            rule: match u.int_in_range(0u8..=2)? {
                0 => FaceWarp::Uniform,
                1 => FaceWarp::Psm,
                _ => FaceWarp::Lispsm,
            },
            k: usize::from(u.int_in_range(0u8..=(MAX_FACE_K as u8 + 1))?),
        },
    };
    let mut input = FrameInput::new(cam, light, map_resolution, image_height)
        .receivers(make_bound(rk, &rs))
        .casters(make_bound(ck, &cs))
        .depth_clamp(depth_clamp)
        .centre(centre)
        .scheme(scheme);
    input.depth_range = depth_range;
    let what = What(&input);
    // FRAME_FUZZ_PRINT=1: print the decoded input (for a panic inside the crate).
    static PRINT: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    if *PRINT.get_or_init(|| std::env::var_os("FRAME_FUZZ_PRINT").is_some()) {
        eprintln!("{what}");
    }
    let r = frame(&input);
    match &r {
        Ok(f) => check(&input, f),
        Err(e) => typed(e),
    }
    // frame_into into a reused (dirty) frame gives the same answer.
    if u.ratio(1u8, 8)? {
        let mut out = Frame::default();
        let first = frame_into(
            &input.scheme(FrameScheme::Single(WarpRule::Uniform)),
            &mut out,
        );
        if let Err(e) = &first {
            typed(e);
        }
        let second = frame_into(&input, &mut out);
        match (&r, &second) {
            (Ok(a), Ok(())) => {
                // The public views (slots beyond `slots()` may keep the earlier frame's maps).
                assert_eq!(a.slots(), out.slots(), "{what}: frame_into's maps differ");
                assert_eq!(
                    (a.len(), a.focus(), a.light_case(), a.light_dir_eye()),
                    (
                        out.len(),
                        out.focus(),
                        out.light_case(),
                        out.light_dir_eye()
                    ),
                    "{what}: frame_into differs from frame"
                );
            }
            (Err(a), Err(b)) => assert_eq!(a.to_string(), b.to_string(), "{what}: errors differ"),
            _ => panic!("{what}: frame {r:?} but frame_into {second:?}"),
        }
    }
    Ok(())
}

fuzz_target!(|data: &[u8]| {
    let mut u = Unstructured::new(data);
    let _ = run(&mut u);
});
