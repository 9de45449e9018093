//! Scene helpers for the frame API's tests, written independently of the frame's clipper: the
//! view frustum's and a box's planes in eye space, a Cyrus–Beck ray test, and the random scene
//! the property tests draw (a camera looking into a receivers' box, a casters' box near it).

use glam::{DMat4, DVec3, DVec4};
use proptest::prelude::*;
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::frame::{Aabb, Camera, CascadeSplits, FrameScheme};
use shadow_aliasing::maps::faces::FaceWarp;
use shadow_aliasing::maps::{TsmOptions, TsmSearch, WarpRule};
use shadow_aliasing::ViewFrustum;

/// The box `[min, max]`.
pub fn aabb(min: [f64; 3], max: [f64; 3]) -> Aabb {
    Aabb::new(DVec3::from(min), DVec3::from(max)).unwrap()
}

/// The six planes `(n, d)` of the view frustum, inside where `n·p + d ≤ 0`.
pub fn frustum_planes(v: &ViewFrustum) -> [DVec4; 6] {
    let t = v.tan_half_fov();
    let ta = t * v.aspect();
    [
        DVec4::new(0.0, 0.0, 1.0, v.near()),
        DVec4::new(0.0, 0.0, -1.0, -v.far()),
        DVec4::new(1.0, 0.0, ta, 0.0),
        DVec4::new(-1.0, 0.0, ta, 0.0),
        DVec4::new(0.0, 1.0, t, 0.0),
        DVec4::new(0.0, -1.0, t, 0.0),
    ]
}

/// The six planes of the world box `b` in the eye space of the world → eye matrix `w2e`.
pub fn box_planes_eye(b: &Aabb, w2e: DMat4) -> [DVec4; 6] {
    let it = w2e.inverse().transpose();
    [
        DVec4::new(1.0, 0.0, 0.0, -b.max.x),
        DVec4::new(-1.0, 0.0, 0.0, b.min.x),
        DVec4::new(0.0, 1.0, 0.0, -b.max.y),
        DVec4::new(0.0, -1.0, 0.0, b.min.y),
        DVec4::new(0.0, 0.0, 1.0, -b.max.z),
        DVec4::new(0.0, 0.0, -1.0, b.min.z),
    ]
    .map(|p| it * p)
}

/// Whether the ray from `c` along the light `l` (t ≥ 0, the way light travels: `c` can shadow
/// what it meets) meets the convex set `{p: πᵢ·(p, 1) ≤ 0}` (Cyrus–Beck on t ∈ [0, ∞)).
pub fn ray_meets(c: DVec3, l: DVec3, planes: &[DVec4], tol: f64) -> bool {
    let (mut lo, mut hi) = (0.0f64, f64::INFINITY);
    for p in planes {
        let n = p.truncate();
        let (num, den) = (n.dot(c) + p.w, n.dot(l));
        if den.abs() < 1e-300 {
            if num > -tol {
                return false;
            }
        } else if den > 0.0 {
            hi = hi.min(-num / den);
        } else {
            lo = lo.max(-num / den);
        }
    }
    lo + tol < hi
}

/// `p` in the clip coordinates of `m` (x/w, y/w, z/w), `None` where w ≤ 0.
pub fn clip_coords(m: DMat4, p: DVec3) -> Option<DVec3> {
    let h = m * p.extend(1.0);
    (h.w > 0.0).then(|| h.truncate() / h.w)
}

/// The sample points of the world box `casters` (`samples` in [0, 1]³ across it), in eye space,
/// whose ray along the light `l` meets the body of `planes`: the caster points that can shadow it.
pub fn shadowing_points<'a>(
    samples: &'a [[f64; 3]],
    casters: &'a Aabb,
    w2e: DMat4,
    l: DVec3,
    planes: &'a [DVec4],
    tol: f64,
) -> impl Iterator<Item = DVec3> + 'a {
    samples
        .iter()
        .map(move |s| {
            w2e.transform_point3(casters.min + (casters.max - casters.min) * DVec3::from(*s))
        })
        .filter(move |p| ray_meets(*p, l, planes, tol))
}

/// A random scene of the property tests.
pub struct RandomScene {
    /// World → eye.
    pub view: DMat4,
    /// The camera.
    pub camera: Camera,
    /// The receivers' box.
    pub receivers: Aabb,
    /// The casters' box.
    pub casters: Aabb,
    /// The light's world direction (not normalised).
    pub light: DVec3,
}

/// The property tests' parameters, drawn by [`scene_params`].
#[derive(Debug, Clone)]
pub struct SceneParams {
    pub eye: [f64; 3],
    pub target: [f64; 3],
    pub near: f64,
    pub ratio: f64,
    pub fov_deg: f64,
    pub aspect: f64,
    pub light: [f64; 3],
    pub rmin: [f64; 3],
    pub rsize: [f64; 3],
    pub cmin: [f64; 3],
    pub csize: [f64; 3],
}

/// The strategy of the property tests' scenes.
pub fn scene_params() -> impl Strategy<Value = SceneParams> {
    let v3 = |a: f64, b: f64| prop::array::uniform3(a..b);
    (
        v3(-20.0, 20.0),
        v3(-20.0, 20.0),
        0.05f64..2.0,
        2.0f64..2000.0,
        10.0f64..70.0,
        0.6f64..2.0,
        v3(-1.0, 1.0),
        v3(-40.0, 40.0),
        v3(0.0, 60.0),
        v3(-40.0, 40.0),
        v3(0.1, 40.0),
    )
        .prop_map(
            |(eye, target, near, ratio, fov_deg, aspect, light, rmin, rsize, cmin, csize)| {
                SceneParams {
                    eye,
                    target,
                    near,
                    ratio,
                    fov_deg,
                    aspect,
                    light,
                    rmin,
                    rsize,
                    cmin,
                    csize,
                }
            },
        )
}

/// The camera looks at a point of the receivers' box, the casters hover around another; `None`
/// for a camera looking straight up or down, or a zero light.
pub fn random_scene(p: &SceneParams) -> Option<RandomScene> {
    let (rmin, rsize) = (DVec3::from(p.rmin), DVec3::from(p.rsize));
    let target = rmin + rsize * DVec3::from(p.target).abs() / 20.0;
    let cmin = rmin + rsize * DVec3::from(p.cmin).abs() / 40.0
        - DVec3::new(0.5, 0.0, 0.5) * DVec3::from(p.csize);
    let eye = target + DVec3::from(p.eye);
    if (target - eye).length() <= 1e-3 || (target - eye).normalize().y.abs() >= 0.999 {
        return None;
    }
    let light = DVec3::from(p.light);
    if light.length() <= 1e-3 {
        return None;
    }
    let view = glam::dcamera::rh::view::look_at_mat4(eye, target, DVec3::Y);
    let camera = Camera::new(
        view,
        p.near,
        p.near * p.ratio,
        p.fov_deg.to_radians(),
        p.aspect,
    )
    .unwrap();
    Some(RandomScene {
        view,
        camera,
        receivers: Aabb::new(rmin, rmin + rsize).unwrap(),
        casters: Aabb::new(cmin, cmin + DVec3::from(p.csize)).unwrap(),
        light,
    })
}

/// Scheme `i` of the seven the bias and lens tests run on every random scene: single LiSPSM,
/// uniform and minimax maps, practical LiSPSM cascades, stable cascades, TSM, face partitions.
pub fn schemes(i: usize) -> FrameScheme<'static> {
    match i {
        0 => FrameScheme::Single(WarpRule::Lispsm),
        1 => FrameScheme::Single(WarpRule::Uniform),
        2 => FrameScheme::Single(WarpRule::Minimax),
        3 => FrameScheme::Cascades {
            splits: CascadeSplits::Scheme {
                scheme: SplitScheme::Practical { lambda: 0.8 },
                k: 3,
                overlap: 0.1,
            },
            rule: WarpRule::Lispsm,
        },
        4 => FrameScheme::Stable(CascadeSplits::Scheme {
            scheme: SplitScheme::Practical { lambda: 0.7 },
            k: 3,
            overlap: 0.0,
        }),
        5 => FrameScheme::Tsm(TsmOptions {
            focus: 10.0,
            search: TsmSearch::EightyPercent,
        }),
        _ => FrameScheme::Faces {
            rule: FaceWarp::Lispsm,
            k: 2,
        },
    }
}
