//! What the `builders` and `frame` targets share: the numbers they draw from the fuzzer's bytes
//! and the checks of a result. Each function consumes the bytes exactly as the targets' own
//! copies did, so the committed corpora keep their meaning.

use arbitrary::{Result, Unstructured};
use glam::DMat4;
use glam::DVec3;
use shadow_aliasing::maps::{Falloff, WarpRule};
use shadow_aliasing::Error;
use std::fmt::Display;

/// The crate's clip slack (`verify_clip`).
pub const SLACK: f64 = 1e-6;

/// A number: often a raw bit pattern, often an edge, mostly a "reasonable" value.
pub fn num(u: &mut Unstructured) -> Result<f64> {
    const EDGES: [f64; 16] = [
        0.0,
        -0.0,
        5e-324,
        1e-310,
        f64::MIN_POSITIVE,
        1e-300,
        1e-150,
        1.0,
        std::f64::consts::FRAC_PI_2,
        1.5707963267948963, // π/2 − 1 ulp
        1e150,
        1e300,
        f64::MAX,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
    ];
    Ok(match u.int_in_range(0u8..=7)? {
        0 => f64::from_bits(u.arbitrary()?),
        1 => EDGES[u.choose_index(EDGES.len())?],
        _ => {
            let m = f64::from(u.arbitrary::<u16>()?) / 65536.0 * 10.0;
            let e = i32::from(u.int_in_range(-8i8..=8)?);
            let s = if u.arbitrary::<bool>()? { -1.0 } else { 1.0 };
            s * m * 10f64.powi(e)
        }
    })
}

/// A half field of view: once in `any` draws [`num`], otherwise inside (0, π/2), by a fraction
/// of it.
pub fn fov(u: &mut Unstructured, any: u8) -> Result<f64> {
    if u.ratio(1u8, any)? {
        num(u)
    } else {
        Ok(f64::from(u.arbitrary::<u16>()?.max(1)) / 65536.0 * std::f64::consts::FRAC_PI_2)
    }
}

/// A warp rule, every one reachable; `eta` draws the η of `WarpRule::Eta`, the other parameters
/// are [`num`]s.
pub fn rule(
    u: &mut Unstructured,
    eta: impl FnOnce(&mut Unstructured) -> Result<f64>,
) -> Result<WarpRule> {
    Ok(match u.int_in_range(0u8..=14)? {
        0 => WarpRule::Uniform,
        1 => WarpRule::Eta(eta(u)?),
        2 => WarpRule::Psm,
        3 => WarpRule::LispsmFixed,
        4 => WarpRule::Lispsm,
        5 => WarpRule::Barroso(Falloff::Barroso),
        6 => WarpRule::Barroso(Falloff::Zhang),
        7 => WarpRule::Tsm { focus: num(u)? },
        8 => WarpRule::LispsmReference,
        9 => WarpRule::Filament,
        10 => WarpRule::FilamentHints {
            near_hint: num(u)?,
            far_hint: num(u)?,
        },
        11 => WarpRule::Ogre,
        12 => WarpRule::Minimax,
        13 => WarpRule::OgreOrtho {
            shadow_distance: num(u)?,
        },
        _ => WarpRule::MinimaxMz,
    })
}

/// An error is the crate's typed error with a message.
pub fn typed(e: &Error) {
    assert!(
        !e.to_string().is_empty(),
        "an error without a message: {e:?}"
    );
}

/// Every point maps inside the clip volume (x, y ∈ [−1, 1], z ∈ [lo_z, 1]) within the slack,
/// with w > 0.
pub fn in_clip(m: &DMat4, points: &[DVec3], lo_z: f64, what: impl Display) {
    assert!(m.is_finite(), "{what}: matrix not finite {m:?}");
    for p in points {
        let h = *m * p.extend(1.0);
        assert!(
            h.is_finite() && h.w > 0.0,
            "{what}, depth from {lo_z}: {p} maps to {h}"
        );
        let c = h.truncate() / h.w;
        let s = 1.0 + SLACK;
        assert!(
            c.x.abs() <= s && c.y.abs() <= s && c.z >= lo_z - SLACK && c.z <= s,
            "{what}, depth from {lo_z}: {p} maps to {c} (outside the clip volume)"
        );
    }
}
