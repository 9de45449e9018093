//! `measure::surface_footprint` against computations that share none of its code: a closed form
//! derived by hand, central finite differences of the whole pipeline (unproject the pixel,
//! intersect the plane, project into the map), and `point_error` through the relation of the
//! module docs.

use glam::{DMat2, DMat4, DVec2, DVec3, DVec4};
use shadow_aliasing::maps::{warp, WarpRule};
use shadow_aliasing::measure::{point_error, surface_footprint, Grids, ShadowMap};
use shadow_aliasing::{Error, Resolutions, ViewFrustum};

mod common;
use common::Lcg;

fn rel_mat(a: DMat2, b: DMat2) -> f64 {
    let d = a - b;
    let n = |m: DMat2| (m.x_axis.length_squared() + m.y_axis.length_squared()).sqrt();
    n(d) / n(b)
}

/// The uniform (orthographic) map of the light straight down onto a ground plane y = −h seen
/// from a camera looking along −Z (eye space = world space): every entry of J by hand.
///
/// A ground point at depth d = −z has NDC `x_n = x/(d tanθ a)`, `y_n = −h/(d tanθ)`; its pixel is
/// `u = (x_n + 1) W/2`, `v = (1 − y_n) H/2`. Inverting: `d = h/(q tanθ)` with
/// `q = 2v/H − 1`, `x = x_n d tanθ a`. So `∂d/∂v = −(2/H) d² tanθ/h`, `∂d/∂u = 0`,
/// `∂x/∂u = (2/W) d tanθ a`, `∂x/∂v = x_n tanθ a ∂d/∂v`. The map has
/// `s = (x − x₀)/W_x`, `t = (d − z₀)/W_z`.
#[test]
fn overhead_uniform_ground_matches_closed_form() {
    let (theta, w, h_px) = (0.5f64, 640u32, 480u32);
    let a = f64::from(w) / f64::from(h_px);
    let tan = theta.tan();
    let camera = glam::dcamera::rh::proj::directx::perspective(2.0 * theta, a, 0.5, 200.0);
    let (x0, wx, z0, wz, res_s, res_t) = (-40.0, 80.0, 0.5, 100.0, 1024u32, 512u32);
    // clip x = 2(x − x0)/Wx − 1, clip y = 2(−z − z0)/Wz − 1, w = 1.
    let light = DMat4::from_cols(
        DVec4::new(2.0 / wx, 0.0, 0.0, 0.0),
        DVec4::new(0.0, 0.0, 1.0, 0.0),
        DVec4::new(0.0, -2.0 / wz, 0.0, 0.0),
        DVec4::new(-2.0 * x0 / wx - 1.0, -2.0 * z0 / wz - 1.0, 0.0, 1.0),
    );
    let g = Grids::new(w, h_px, res_s, res_t).unwrap();
    let h = 1.7;
    for (x, d) in [(0.0, 3.0), (2.5, 10.0), (-7.0, 40.0), (20.0, 90.0)] {
        let p = DVec3::new(x, -h, -d);
        let f = surface_footprint(&camera, &light, g, p, DVec3::Y).unwrap();
        let xn = x / (d * tan * a);
        let dd_dv = -(2.0 / f64::from(h_px)) * d * d * tan / h;
        let dx_du = (2.0 / f64::from(w)) * d * tan * a;
        let dx_dv = xn * tan * a * dd_dv;
        let (rs, rt) = (f64::from(res_s), f64::from(res_t));
        let expect = DMat2::from_cols(
            DVec2::new(rs / wx * dx_du, 0.0),
            DVec2::new(rs / wx * dx_dv, rt / wz * dd_dv),
        );
        assert!(
            rel_mat(f.jacobian, expect) < 1e-12,
            "{:?} vs {:?}",
            f.jacobian,
            expect
        );
        // The pixel and texel the point lands in.
        let u = (xn + 1.0) * f64::from(w) / 2.0;
        let v = (1.0 + h / (d * tan)) * f64::from(h_px) / 2.0;
        assert!((f.pixel - DVec2::new(u, v)).length() < 1e-9);
        let texel = DVec2::new((x - x0) / wx * rs, (d - z0) / wz * rt);
        assert!((f.texel - texel).length() < 1e-9);
        // The error: 1/σ_min of this triangular J.
        let (s1, s2) = f.singular_values();
        assert!((s1 * s2 - expect.determinant().abs()).abs() < 1e-12 * s1 * s1);
        assert!((f.error().unwrap() - 1.0 / s2).abs() < 1e-12 / s2);
    }
}

/// Unproject pixel `(u, v)` through `camera`, intersect the plane `(p0, n)`, project with
/// `light`: the texel coordinates, the pipeline a renderer runs.
fn pipeline(camera: &DMat4, light: &DMat4, g: &Grids, p0: DVec3, n: DVec3, uv: DVec2) -> DVec2 {
    let xn = 2.0 * uv.x / g.width() - 1.0;
    let yn = 1.0 - 2.0 * uv.y / g.height();
    let inv = camera.inverse();
    let a = inv * DVec4::new(xn, yn, 0.0, 1.0);
    let b = inv * DVec4::new(xn, yn, 0.5, 1.0);
    let (a, b) = (a.truncate() / a.w, b.truncate() / b.w);
    let dir = b - a;
    let t = n.dot(p0 - a) / n.dot(dir);
    let q = a + t * dir;
    let h = *light * q.extend(1.0);
    DVec2::new(
        (h.x / h.w + 1.0) * 0.5 * g.res_s(),
        (h.y / h.w + 1.0) * 0.5 * g.res_t(),
    )
}

/// A general camera (look-at from an arbitrary eye), perspective light matrices (LiSPSM and
/// minimax warps composed with the world → eye matrix) and arbitrary planes: J against central
/// differences of [`pipeline`] with a step of 10⁻³ pixel (truncation O(10⁻⁶) relative).
#[test]
fn matches_finite_differences_of_the_pipeline() {
    let eye = DVec3::new(3.0, 4.0, 12.0);
    let view_m = glam::dcamera::rh::view::look_at_mat4(eye, DVec3::new(-2.0, 0.5, -20.0), DVec3::Y);
    let (w, hp) = (800u32, 600u32);
    let camera =
        glam::dcamera::rh::proj::directx::perspective(1.0, 800.0 / 600.0, 0.5, 150.0) * view_m;
    let view = ViewFrustum::with_aspect(0.5, 150.0, 0.5, 800.0 / 600.0).unwrap();
    let g = Grids::new(w, hp, 2048, 1024).unwrap();
    let mut rng = Lcg(7);
    let mut checked = 0;
    for rule in [WarpRule::Lispsm, WarpRule::Minimax, WarpRule::Uniform] {
        for _ in 0..40 {
            let l_world = DVec3::new(rng.next() - 0.5, -1.0, rng.next() - 0.5).normalize();
            let l_eye = view_m.transform_vector3(l_world);
            let Ok(s) = warp(&view, l_eye, rule) else {
                continue;
            };
            let light = s.matrix() * view_m;
            // A point inside the frustum and a plane through it.
            let depth = 1.0 + 100.0 * rng.next();
            let pe = DVec3::new(
                (rng.next() - 0.5) * depth * 0.6,
                (rng.next() - 0.5) * depth * 0.5,
                -depth,
            );
            let p = view_m.inverse().transform_point3(pe);
            let n = rng.unit();
            let Ok(f) = surface_footprint(&camera, &light, g, p, n) else {
                continue;
            };
            let d = 1e-3;
            let c0 = (pipeline(&camera, &light, &g, p, n, f.pixel + DVec2::new(d, 0.0))
                - pipeline(&camera, &light, &g, p, n, f.pixel - DVec2::new(d, 0.0)))
                / (2.0 * d);
            let c1 = (pipeline(&camera, &light, &g, p, n, f.pixel + DVec2::new(0.0, d))
                - pipeline(&camera, &light, &g, p, n, f.pixel - DVec2::new(0.0, d)))
                / (2.0 * d);
            let fd = DMat2::from_cols(c0, c1);
            // Grazing planes amplify the differences' rounding: skip the worst-conditioned.
            let cam_ray = (p - eye).normalize();
            if n.dot(cam_ray).abs() < 0.05 {
                continue;
            }
            assert!(
                rel_mat(f.jacobian, fd) < 1e-5,
                "{rule:?}: {:?} vs {:?} (rel {})",
                f.jacobian,
                fd,
                rel_mat(f.jacobian, fd)
            );
            // The texel of the pixel's centre is the point's.
            let t = pipeline(&camera, &light, &g, p, n, f.pixel);
            assert!((t - f.texel).length() < 1e-6 * (1.0 + f.texel.length()));
            checked += 1;
        }
    }
    assert!(checked >= 60, "only {checked} cases checked");
}

/// The relation of the module docs with `point_error` (perspective factor only), for the plane
/// of constant eye depth (normal = view axis): `|det J| m_x m_z = |f̂·L|`, and with the light
/// along the view axis a one-texel step along s covers `m_x` pixels.
#[test]
fn relates_to_point_error_for_the_view_axis_plane() {
    let (w, hp) = (960u32, 540u32);
    let aspect = f64::from(w) / f64::from(hp);
    let view = ViewFrustum::with_aspect(1.0, 80.0, 0.45, aspect).unwrap();
    let camera = glam::dcamera::rh::proj::directx::perspective(0.9, aspect, 1.0, 80.0);
    let (rs, rt) = (1024u32, 2048u32);
    let g = Grids::new(w, hp, rs, rt).unwrap();
    let res = Resolutions::new(f64::from(hp), f64::from(rs), f64::from(rt)).unwrap();
    for (l, rule) in [
        (DVec3::new(0.2, -1.0, 0.3), WarpRule::Lispsm),
        (DVec3::new(-0.4, -0.7, -0.5), WarpRule::Uniform),
        (DVec3::new(0.1, -0.3, -1.0), WarpRule::Lispsm),
        (DVec3::new(0.0, -1.0, 0.2), WarpRule::Minimax),
    ] {
        let s = warp(&view, l, rule).unwrap();
        let sm = ShadowMap::new(s.matrix(), s.light_dir()).unwrap();
        for p in [
            DVec3::new(0.3, -0.2, -2.0),
            DVec3::new(-5.0, 3.0, -20.0),
            DVec3::new(10.0, -8.0, -60.0),
        ] {
            let e = point_error(&view, &sm, p, res).unwrap();
            let f = surface_footprint(&camera, &s.matrix(), g, p, DVec3::Z).unwrap();
            let lhs = f.jacobian.determinant().abs() * e.mx * e.mz;
            let rhs = s.light_dir().z.abs();
            assert!(
                (lhs - rhs).abs() < 1e-9 * rhs,
                "{rule:?} {p}: {lhs} vs {rhs}"
            );
        }
    }
    // Light along the view axis: the plane is perpendicular to the light.
    let s = warp(&view, DVec3::NEG_Z, WarpRule::Uniform).unwrap();
    let sm = ShadowMap::new(s.matrix(), s.light_dir()).unwrap();
    for p in [DVec3::new(0.5, 0.2, -3.0), DVec3::new(-10.0, 6.0, -40.0)] {
        let e = point_error(&view, &sm, p, res).unwrap();
        let f = surface_footprint(&camera, &s.matrix(), g, p, DVec3::Z).unwrap();
        let step = f.jacobian.inverse() * DVec2::X;
        assert!(
            (step.length() - e.mx).abs() < 1e-9 * e.mx,
            "{step} vs {}",
            e.mx
        );
        let step_t = f.jacobian.inverse() * DVec2::Y;
        assert!((step_t.length() - e.mz).abs() < 1e-9 * e.mz);
    }
}

#[test]
fn bad_input_is_a_typed_error() {
    let camera = glam::dcamera::rh::proj::directx::perspective(1.0, 1.0, 0.1, 100.0);
    let light = glam::dcamera::rh::proj::directx::orthographic(-10.0, 10.0, -10.0, 10.0, 0.0, 20.0);
    let g = Grids::new(64, 64, 64, 64).unwrap();
    let p = DVec3::new(0.0, -1.0, -5.0);
    fn invalid<T: std::fmt::Debug>(r: Result<T, Error>, name: &str) {
        match r {
            Err(Error::InvalidArgument { name: n, .. }) => assert_eq!(n, name),
            other => panic!("expected InvalidArgument({name}), got {other:?}"),
        }
    }
    invalid(
        surface_footprint(&camera, &light, g, p, DVec3::ZERO),
        "normal",
    );
    invalid(
        surface_footprint(&camera, &light, g, p, DVec3::new(f64::NAN, 1.0, 0.0)),
        "normal",
    );
    invalid(
        surface_footprint(
            &camera,
            &light,
            g,
            DVec3::new(0.0, f64::INFINITY, -1.0),
            DVec3::Y,
        ),
        "point",
    );
    let mut bad = camera;
    bad.x_axis.x = f64::NAN;
    invalid(surface_footprint(&bad, &light, g, p, DVec3::Y), "camera");
    invalid(surface_footprint(&camera, &bad, g, p, DVec3::Y), "light");
    invalid(Grids::new(0, 64, 64, 64), "width");
    invalid(Grids::new(64, 64, 64, 0), "res_t");
    // Behind the camera.
    assert!(matches!(
        surface_footprint(&camera, &light, g, DVec3::new(0.0, -1.0, 5.0), DVec3::Y),
        Err(Error::Degenerate(_))
    ));
    // Edge-on to the camera: the plane contains the view ray through the point.
    let ray = p.normalize();
    let n = ray.cross(DVec3::X);
    let r = surface_footprint(&camera, &light, g, p, n);
    assert!(matches!(r, Err(Error::Degenerate(_))), "{r:?}");
    // Edge-on to the light (a wall under an overhead orthographic light): a valid J, singular,
    // whose error is reported as degenerate rather than infinite.
    let overhead = DMat4::from_cols(
        DVec4::new(0.1, 0.0, 0.0, 0.0),
        DVec4::new(0.0, 0.0, 0.1, 0.0),
        DVec4::new(0.0, 0.1, 0.0, 0.0),
        DVec4::new(0.0, 0.0, 0.0, 1.0),
    );
    let f = surface_footprint(&camera, &overhead, g, p, DVec3::new(1.0, 0.0, 1.0)).unwrap();
    assert!(f.jacobian.determinant().abs() < 1e-12);
    assert!(matches!(f.error(), Err(Error::Degenerate(_))));
}
