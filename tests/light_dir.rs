//! `LightDir::new` normalises every finite, non-zero light direction, however large or
//! small its components; expected values are hand calculations (1/√2, 1/√3, 3-4-5 triangles).

mod common;
use common::config;
use glam::DVec3;
use proptest::prelude::*;
use shadow_aliasing::analytic::partition::{z_splits, SplitScheme};
use shadow_aliasing::maps::cascades::cascades;
use shadow_aliasing::maps::faces::{face_partitions, FaceWarp};
use shadow_aliasing::maps::{warp, WarpRule};
use shadow_aliasing::scheme::{scheme, Partition};
use shadow_aliasing::{Error, LightAngle, LightDir, ViewFrustum};

fn unit_light_dir(l: DVec3) -> shadow_aliasing::Result<DVec3> {
    LightDir::new(l).map(LightDir::as_dvec3)
}

/// Every builder normalises the light direction once, at its entry: the unit vector each map
/// reports is `l / |l|` bit for bit (computed here by hand), not a re-normalised unit vector. These
/// directions are ones where normalising `l / |l|` again changes the last bit (issue 12 counted
/// five normalisations on the way from the command line to a map; the cascades, the schemes and
/// the face partitions reported the twice-normalised vector).
#[test]
fn builders_normalise_the_light_once() {
    let view = ViewFrustum::new(1.0, 100.0, 0.5).unwrap();
    let splits = z_splits(1.0, 100.0, 3, SplitScheme::SelfSimilar).unwrap();
    for l in [
        DVec3::new(-1.0, -1.0, 0.3),
        DVec3::new(-1.0, -0.7, 0.2),
        DVec3::new(-1.0, -0.3, 0.5),
    ] {
        let once = l / (l.x * l.x + l.y * l.y + l.z * l.z).sqrt();
        let twice = once / once.length();
        assert_ne!(once, twice, "{l}: not a direction that tells the two apart");
        assert_eq!(LightDir::new(l).unwrap().as_dvec3(), once);
        assert_eq!(warp(&view, l, WarpRule::Lispsm).unwrap().light_dir(), once);
        let c = cascades(&view, l, &splits, WarpRule::Lispsm, 0.0).unwrap();
        assert!(
            c.iter().all(|c| c.shadow.light_dir() == once),
            "{l}: cascades"
        );
        let f = face_partitions(&view, l, FaceWarp::Lispsm, 2).unwrap();
        assert!(f.iter().all(|p| p.shadow.light_dir() == once), "{l}: faces");
        for partition in [Partition::Single, Partition::Log, Partition::Faces] {
            let r = scheme(&view, l, WarpRule::Lispsm, partition, 3).unwrap();
            assert_eq!(r.light_dir(), once, "{l}: {partition:?}");
        }
    }
}

fn within_4_eps(a: DVec3, b: DVec3) -> bool {
    (a - b).abs().max_element() <= 4.0 * f64::EPSILON
}

#[test]
fn huge_components_normalise_instead_of_overflowing() {
    // |l|² overflows for all of these; each is a multiple of a vector whose unit vector is known.
    let r3 = 1.0 / 3f64.sqrt();
    let r2 = std::f64::consts::FRAC_1_SQRT_2;
    for (l, want) in [
        (DVec3::splat(1e308), DVec3::splat(r3)),
        (DVec3::new(-1e308, 1e308, -1e308), DVec3::new(-r3, r3, -r3)),
        (DVec3::new(f64::MAX, 0.0, 0.0), DVec3::X),
        (
            DVec3::new(-f64::MAX, f64::MAX, 0.0),
            DVec3::new(-r2, r2, 0.0),
        ),
        (DVec3::new(3e200, 0.0, -4e200), DVec3::new(0.6, 0.0, -0.8)),
    ] {
        let u = unit_light_dir(l).unwrap_or_else(|e| panic!("{l}: {e}"));
        assert!(within_4_eps(u, want), "{l}: {u} want {want}");
    }
    // The axis of the largest component is exact.
    assert_eq!(
        unit_light_dir(DVec3::new(0.0, -f64::MAX, 0.0)),
        Ok(DVec3::NEG_Y)
    );
    // γ of a light at 45° to the view axis, from components near the top of the range.
    let g = LightAngle::from_light_dir(DVec3::new(1e308, 0.0, 1e308)).unwrap();
    assert!((g.radians() - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
}

#[test]
fn tiny_components_normalise_accurately() {
    let r2 = std::f64::consts::FRAC_1_SQRT_2;
    for (l, want) in [
        // |l|² = 2e-320 is subnormal (a dozen significant bits): l/|l| computed from it is off
        // in the fourth digit.
        (DVec3::new(1e-160, 1e-160, 0.0), DVec3::new(r2, r2, 0.0)),
        (DVec3::new(0.0, -3e-310, 4e-310), DVec3::new(0.0, -0.6, 0.8)),
        (DVec3::new(5e-324, 0.0, 0.0), DVec3::X),
        (DVec3::new(0.0, 0.0, -5e-324), DVec3::NEG_Z),
    ] {
        let u = unit_light_dir(l).unwrap_or_else(|e| panic!("{l}: {e}"));
        assert!(within_4_eps(u, want), "{l}: {u} want {want}");
    }
}

#[test]
fn ordinary_vectors_are_l_over_its_length_bit_for_bit() {
    for l in [
        DVec3::new(1.0, 2.0, 3.0),
        DVec3::new(0.0, -1.0, 0.0),
        DVec3::new(-0.3, -0.9, 0.1),
        DVec3::new(1e-100, 2e-100, -3e-100),
        DVec3::new(1e100, -2e100, 3e100),
    ] {
        // What it always computed for these (the sweep's lanes mirror it bit for bit).
        assert_eq!(unit_light_dir(l), Ok(l / l.length()), "{l}");
    }
}

#[test]
fn zero_and_non_finite_vectors_are_errors_with_short_numbers() {
    let msg = |l: DVec3| match unit_light_dir(l) {
        Err(e @ Error::InvalidArgument { .. }) => e.to_string(),
        other => panic!("{l}: {other:?}"),
    };
    assert_eq!(
        msg(DVec3::ZERO),
        "light_dir must be a non-zero vector (got [0, 0, 0])"
    );
    assert_eq!(
        msg(DVec3::new(-0.0, 0.0, -0.0)),
        "light_dir must be a non-zero vector (got [-0, 0, -0])"
    );
    assert_eq!(
        msg(DVec3::new(1e300, f64::NAN, 0.0)),
        "light_dir must be finite (got [1e300, NaN, 0])"
    );
    assert_eq!(
        msg(DVec3::new(f64::INFINITY, 1.0, 0.0)),
        "light_dir must be finite (got [inf, 1, 0])"
    );
}

proptest! {
    #![proptest_config(config(256))]

    /// A direction scaled by any power of two anywhere in the range has the direction's unit
    /// vector (the scaling is exact, so only the normalisation may differ, by a few ulps).
    #[test]
    fn scale_does_not_change_the_unit_vector(
        x in -1.0f64..1.0, y in -1.0f64..1.0, z in -1.0f64..1.0, e in -1000i32..=1020,
    ) {
        let v = DVec3::new(x, y, z);
        prop_assume!(v.abs().max_element() > 0.1);
        let want = v.normalize();
        let scaled = v * 2f64.powi(e);
        let u = unit_light_dir(scaled).unwrap();
        prop_assert!(within_4_eps(u, want), "{scaled}: {u} want {want}");
    }
}
