//! A closed form that is strictly positive on its domain and proportional to res_image/res_s (or
//! /res_t, /res_x) never answers 0 or a subnormal when the resolutions scale it below f64's
//! normal range (issue 21, item 8): it is `InvalidArgument` naming `res_image` and the map's
//! resolution, with the true value estimated and the remedy. Every such form of the library.
//!
//! The expected values are Lloyd's and Barroso's formulas evaluated by hand at unit resolutions
//! (near 1, far 100, n′ = 11, z = 10, θ = π/4): the error's estimate must be that value times
//! res_image/res_map.

use shadow_aliasing::analytic::{overhead, subdivided, tilted};
use shadow_aliasing::{Error, LightAngle, NPrime, Resolutions, ViewFrustum};
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4};

/// res_image = 10⁻³⁰⁰ over a map resolution of 10³⁰⁰: a ratio of 10⁻⁶⁰⁰, 0 in f64.
const TINY: f64 = 1e-300;
const HUGE: f64 = 1e300;

fn view() -> ViewFrustum {
    ViewFrustum::new(1.0, 100.0, FRAC_PI_4).unwrap()
}

fn np11() -> NPrime {
    NPrime::finite(11.0).unwrap()
}

fn overhead_light() -> LightAngle {
    LightAngle::new(FRAC_PI_2).unwrap()
}

/// The error of an underflow: `InvalidArgument` naming `res_image`, the message naming `map`
/// with both values, the form's name, what it would have been returned as, and an estimate whose
/// base-10 logarithm is `log10_true` to 3 significant digits; the remedy at unit resolutions
/// quotes `unit`.
fn assert_underflow(
    r: Result<f64, Error>,
    what: &str,
    map: &str,
    (image, map_res): (f64, f64),
    unit: f64,
    returned_as: &str,
) {
    let e = match r {
        Err(
            e @ Error::InvalidArgument {
                name: "res_image", ..
            },
        ) => e.to_string(),
        other => panic!("{what}: expected an underflow naming res_image, got {other:?}"),
    };
    let log10_true = unit.log10() + image.log10() - map_res.log10();
    // Numbers as the crate's messages print them: positional in [1e-5, 1e16), else exponent.
    let num = |v: f64| {
        if (1e-5..1e16).contains(&v) {
            format!("{v}")
        } else {
            format!("{v:e}")
        }
    };
    for part in [
        format!("res_image and {map} make {what} underflow f64"),
        format!(
            "res_image/{map} (res_image={}, {map}={})",
            num(image),
            num(map_res)
        ),
        format!("returned as {returned_as}"),
        format!("evaluate it at res_image={map}=1 ({what} = "),
        format!("scale by res_image/{map} yourself"),
    ] {
        assert!(e.contains(&part), "{part:?} not in {e}");
    }
    // "about 1.818e-600": mantissa and exponent.
    let about = e.split("about ").nth(1).expect("an estimate");
    let about = about.split([',', ';', ' ']).next().unwrap();
    let (m, x) = about.split_once('e').expect("mantissa e exponent");
    let (m, x): (f64, f64) = (m.parse().unwrap(), x.parse().unwrap());
    assert!((1.0..10.0).contains(&m), "{e}");
    // Three decimals: a relative error of at most 5e-4, 2.2e-4 in the logarithm.
    assert!(
        (m.log10() + x - log10_true).abs() < 2.5e-4,
        "estimate {about}, want 10^{log10_true}: {e}"
    );
    // The value quoted at unit resolutions is the form's, to rounding.
    let quoted = e.split(&format!("({what} = ")).nth(1).unwrap();
    let quoted: f64 = quoted.split(')').next().unwrap().parse().unwrap();
    assert!(
        (quoted - unit).abs() <= 1e-12 * unit,
        "{quoted} vs {unit}: {e}"
    );
}

/// [`assert_underflow`] at res_image = 10⁻³⁰⁰ over a map resolution of 10³⁰⁰: returned as 0.
fn refused(r: Result<f64, Error>, what: &str, map: &str, unit: f64) {
    assert_underflow(r, what, map, (TINY, HUGE), unit, "0");
}

/// m_x = f (n′ + z − n)/(z (n′ + f − n)) = 100·20/(10·110) (Lloyd 2006 Eq 7).
const MX: f64 = 2000.0 / 1100.0;
/// m_z = (f − n)/(2 tan θ) · (n′ + z − n)²/(z n′ (n′ + f − n)) = 99/2 · 400/(10·11·110) (Eq 8).
const MZ: f64 = 49.5 * 400.0 / 12100.0;
/// M_x = f n′/(n (n′ + f − n)) = 1100/110 (Eq 9).
const MAX_MX: f64 = 10.0;
/// M_z at n′ = n′_LSPSM = 11 (far plane): (f − n)/(2 tan θ) · (n′ + f − n)/(f n′) (Eq 10).
const MAX_MZ: f64 = 49.5 * 110.0 / 1100.0;

#[test]
fn overhead_mx_and_max_mx() {
    let res = Resolutions::new(TINY, HUGE, 1.0).unwrap();
    refused(
        overhead::mx(1.0, 100.0, np11(), 10.0, res),
        "m_x",
        "res_s",
        MX,
    );
    refused(
        overhead::max_mx(1.0, 100.0, np11(), res),
        "m_x",
        "res_s",
        MAX_MX,
    );
    // A subnormal result (1.8e-310, about 3 significant digits left) is refused too.
    let sub = Resolutions::new(TINY, 1e10, 1.0).unwrap();
    assert_underflow(
        overhead::mx(1.0, 100.0, np11(), 10.0, sub),
        "m_x",
        "res_s",
        (TINY, 1e10),
        MX,
        "the subnormal 1.818",
    );
    // A small normal value is answered: 1.8181…e-305.
    let small = Resolutions::new(TINY, 1e5, 1.0).unwrap();
    let v = overhead::mx(1.0, 100.0, np11(), 10.0, small).unwrap();
    assert!((v - MX * 1e-305).abs() <= 1e-12 * MX * 1e-305, "{v:e}");
}

/// The ratio res_image/res_s alone underflows (10⁻³³⁰ is 0 in f64) while the value, f/z ·
/// 10⁻³³⁰ = 10⁻³⁰ unwarped at z = near = 1, f = 10³⁰⁰, is a normal number: refused, saying so.
#[test]
fn overhead_mx_when_only_the_ratio_underflows() {
    let res = Resolutions::new(TINY, 1e30, 1.0).unwrap();
    let r = overhead::mx(1.0, 1e300, NPrime::UNWARPED, 1.0, res);
    assert_underflow(r.clone(), "m_x", "res_s", (TINY, 1e30), 1e300, "0");
    let e = r.unwrap_err().to_string();
    assert!(e.contains("a ratio below the smallest normal f64"), "{e}");
    assert!(
        e.contains("multiplying by res_image before dividing by res_s"),
        "{e}"
    );
}

#[test]
fn overhead_mz_and_max_mz() {
    let res = Resolutions::new(TINY, 1.0, HUGE).unwrap();
    refused(overhead::mz(&view(), np11(), 10.0, res), "m_z", "res_t", MZ);
    refused(
        overhead::max_mz(&view(), np11(), res),
        "M_z",
        "res_t",
        MAX_MZ,
    );
}

/// Overhead (γ = π/2) Barroso's m_z and the perpendicular one are Lloyd's m_z (Eq 8), and
/// ξ = m_z z / ψ² with ψ = n′ + z − n = 20 (Eq 12).
#[test]
fn tilted_mz_perpendicular_and_xi() {
    let res = Resolutions::new(TINY, 1.0, HUGE).unwrap();
    let (v, up) = (view(), overhead_light());
    refused(
        tilted::tilted_mz(&v, np11(), up, 10.0, res),
        "m_z",
        "res_t",
        MZ,
    );
    refused(
        tilted::tilted_mz_perpendicular(&v, np11(), up, 10.0, res),
        "m_z",
        "res_t",
        MZ,
    );
    refused(
        tilted::tilted_xi(&v, 11.0, up, res),
        "xi",
        "res_t",
        MZ * 10.0 / 400.0,
    );
}

/// Lloyd 2005's forms with near = 1, far = α = 100: m (Eq 2) is Lloyd 2006's m_z, m_max (Eq 5)
/// at ξ = 0 is (α − 1)/(2 tan θ)/√α, Eq 7 with k = 2 is 2 (√α − 1)/(2 tan θ)/α^{1/4}, m_x
/// (Eq 8) is Lloyd 2006's m_x, m_x,max (Eq 9) at ξ = 0 is √α.
#[test]
fn subdivided_forms() {
    let t = FRAC_PI_4;
    let unit_eq7 = 2.0 * 9.0 / 2.0 / 10f64.sqrt();
    refused(
        subdivided::error_m(100.0, t, np11(), 10.0, TINY, HUGE),
        "m",
        "res_s",
        MZ,
    );
    refused(
        subdivided::max_error(100.0, t, 0.0, TINY, HUGE),
        "m_max",
        "res_s",
        99.0 / 2.0 / 10.0,
    );
    refused(
        subdivided::subdivided_max_error(100.0, 2, 0.0, t, TINY, HUGE),
        "m_max",
        "res_s",
        unit_eq7,
    );
    // Lloyd 2005 calls the x resolution r_t, `res_x` here: the message uses its name.
    refused(
        subdivided::mx_normalised(100.0, np11(), 10.0, TINY, HUGE),
        "m_x",
        "res_x",
        MX,
    );
    refused(
        subdivided::max_mx_normalised(100.0, 0.0, TINY, HUGE),
        "m_x,max",
        "res_x",
        10.0,
    );
}
