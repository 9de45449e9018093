//! The planner's candidates (issue 24 item 3): every scheme it measures, in a fixed order, and
//! their names.
//!
//! Each candidate is a [`FrameScheme`] that the frame builds and measures over B. The list:
//!
//! 1. a single map with each warp rule that has no parameter ([`SINGLE_RULES`]), TSM's n′ rule
//!    with the focus at half the camera's depth range, and the trapezoidal map
//!    ([`FrameScheme::Tsm`], the 80 % rule, the same focus);
//! 2. cascades of k = 2 … [`MAX_CASCADES`] for each split scheme ([`split_schemes`]: uniform,
//!    logarithmic, practical λ = [`PRACTICAL_LAMBDA`], Barroso's adaptive with α =
//!    [`ADAPTIVE_RATIO`], equal-error), unwarped and warped ([`CASCADE_RULES`]); one cascade is
//!    the single map above;
//! 3. stable cascades: k = 1, and k = 2 … [`MAX_CASCADES`] for each split scheme;
//! 4. face partitions with each face rule and k = 1 … [`MAX_FACE_K`];
//! 5. the clipmap ([`FrameScheme::Clipmap`], [`ClipmapOptions::UNREAL`]'s layout, levels of
//!    [`CLIPMAP_RESOLUTION`] texels): its knob is the LOD bias, which the planner chooses for the
//!    goal ([`clipmap_for_error`](super::clipmap::clipmap_for_error),
//!    [`clipmap_for_pool`](super::clipmap::clipmap_for_pool)); its texels are its pages × the
//!    page's texels.
//!
//! Adding a candidate is one entry in [`candidates`] and one arm in [`label`].

use crate::analytic::partition::SplitScheme;
use crate::frame::{CascadeSplits, ClipmapOptions, FrameInput, FrameScheme, MAX_FACE_K};
use crate::maps::faces::FaceWarp;
use crate::maps::{Falloff, TsmOptions, TsmSearch, WarpRule};
use crate::scheme::ADAPTIVE_RATIO;
use crate::LightAngle;

/// The single-map warp rules without a parameter, in the order they are tried.
pub const SINGLE_RULES: [WarpRule; 11] = [
    WarpRule::Uniform,
    WarpRule::Psm,
    WarpRule::Lispsm,
    WarpRule::LispsmFixed,
    WarpRule::Barroso(Falloff::Barroso),
    WarpRule::Barroso(Falloff::Zhang),
    WarpRule::Minimax,
    WarpRule::MinimaxMz,
    WarpRule::LispsmReference,
    WarpRule::Filament,
    WarpRule::Ogre,
];

/// The cascades' rules: without warping, and warped with LiSPSM (the engines' warp; the minimax
/// rule, whose n′ search makes equal-error cascades 2 to 4 times as slow, is among the single
/// maps).
pub const CASCADE_RULES: [WarpRule; 2] = [WarpRule::Uniform, WarpRule::Lispsm];

/// The most cascades tried.
pub const MAX_CASCADES: usize = 8;

/// The λ of the practical split scheme tried (the command line's default).
pub const PRACTICAL_LAMBDA: f64 = 0.5;

/// The clipmap candidate's levels' resolution (Unreal's 16k² virtual levels).
pub const CLIPMAP_RESOLUTION: u32 = 16384;

/// The face rules tried.
pub const FACE_RULES: [FaceWarp; 3] = [FaceWarp::Uniform, FaceWarp::Psm, FaceWarp::Lispsm];

/// The split schemes of k cascades for the light angle `gamma` (radians between the light and
/// the view direction, for Barroso's adaptive planes): uniform, logarithmic, practical,
/// adaptive, equal-error.
#[must_use]
pub fn split_schemes(k: usize, gamma: f64) -> [CascadeSplits<'static>; 5] {
    let scheme = |scheme| CascadeSplits::Scheme {
        scheme,
        k,
        overlap: 0.0,
    };
    [
        scheme(SplitScheme::Uniform),
        scheme(SplitScheme::SelfSimilar),
        scheme(SplitScheme::Practical {
            lambda: PRACTICAL_LAMBDA,
        }),
        scheme(SplitScheme::Adaptive {
            light_angle: gamma,
            ratio: ADAPTIVE_RATIO,
        }),
        CascadeSplits::EqualError { k },
    ]
}

/// The focus distance of the TSM candidates: half the camera's depth range (the command line's
/// default for a single `--warp tsm` map).
#[must_use]
pub fn tsm_focus(input: &FrameInput<'_>) -> f64 {
    let v = input.camera.view();
    0.5 * (v.far() - v.near())
}

/// Every candidate for `input`, in the planner's order (module docs). Only the camera and the
/// light are read: the focus of TSM and the light angle of the adaptive splits (a light that is
/// not a direction gets γ = π/2 here and is refused by the frame).
#[must_use]
pub fn candidates(input: &FrameInput<'_>) -> Vec<FrameScheme<'static>> {
    let eye_light = input
        .camera
        .world_to_eye()
        .transform_vector3(input.light_dir_world);
    let gamma = LightAngle::from_light_dir(eye_light)
        .map_or(std::f64::consts::FRAC_PI_2, LightAngle::radians);
    let focus = tsm_focus(input);
    let mut c: Vec<FrameScheme<'static>> = SINGLE_RULES.map(FrameScheme::Single).to_vec();
    c.push(FrameScheme::Single(WarpRule::Tsm { focus }));
    c.push(FrameScheme::Tsm(TsmOptions {
        focus,
        search: TsmSearch::EightyPercent,
    }));
    for rule in CASCADE_RULES {
        for k in 2..=MAX_CASCADES {
            for splits in split_schemes(k, gamma) {
                c.push(FrameScheme::Cascades { splits, rule });
            }
        }
    }
    c.push(FrameScheme::Stable(CascadeSplits::Scheme {
        scheme: SplitScheme::SelfSimilar,
        k: 1,
        overlap: 0.0,
    }));
    for k in 2..=MAX_CASCADES {
        c.extend(split_schemes(k, gamma).map(FrameScheme::Stable));
    }
    for rule in FACE_RULES {
        for k in 1..=MAX_FACE_K {
            c.push(FrameScheme::Faces { rule, k });
        }
    }
    c.push(FrameScheme::Clipmap(ClipmapOptions::UNREAL));
    c
}

/// Whether the frame places the scheme's splits by a root search on the measured error
/// (equal-error cascades that follow the camera): such a candidate costs a few hundred slice
/// maps, the others one frame (docs/planning.md, "Cost"). Stable equal-error cascades are not
/// searched (their planes are a closed form on a grid, docs/renderer.md). Filter the searched
/// ones out of [`candidates`] for a plan within about 2 ms.
#[must_use]
pub fn is_searched(s: &FrameScheme<'_>) -> bool {
    matches!(
        s,
        FrameScheme::Cascades {
            splits: CascadeSplits::EqualError { .. },
            ..
        }
    )
}

/// A warp rule's name as the command line's `--warp` and Python's `rule` spell it (`lispsm-fixed`).
#[must_use]
pub fn rule_name(rule: WarpRule) -> &'static str {
    match rule {
        WarpRule::Uniform => "uniform",
        WarpRule::Eta(_) => "eta",
        WarpRule::Psm => "psm",
        WarpRule::Lispsm => "lispsm",
        WarpRule::LispsmFixed => "lispsm-fixed",
        WarpRule::Barroso(Falloff::Barroso) => "barroso",
        WarpRule::Barroso(Falloff::Zhang) => "barroso-zhang",
        WarpRule::Minimax => "minimax",
        WarpRule::MinimaxMz => "minimax-mz",
        WarpRule::Tsm { .. } => "tsm",
        WarpRule::LispsmReference => "lispsm-reference",
        WarpRule::Filament | WarpRule::FilamentHints { .. } => "filament",
        WarpRule::Ogre => "ogre",
        WarpRule::OgreOrtho { .. } => "ogre-ortho",
    }
}

/// A face rule's name, as the command line's `--warp` spells the rule that gives it.
#[must_use]
pub fn face_rule_name(rule: FaceWarp) -> &'static str {
    match rule {
        FaceWarp::Uniform => "uniform",
        FaceWarp::Psm => "psm",
        FaceWarp::Lispsm => "lispsm",
    }
}

/// A split scheme's name (the command line's `--partition`): `uniform`, `log`, `practical`,
/// `adaptive`, `equal-error`, or `splits` for planes given otherwise; and its k.
#[must_use]
pub fn splits_name(s: &CascadeSplits<'_>) -> (&'static str, usize) {
    match s {
        CascadeSplits::Scheme { scheme, k, .. } => (
            match scheme {
                SplitScheme::Uniform => "uniform",
                SplitScheme::SelfSimilar => "log",
                SplitScheme::Practical { .. } => "practical",
                SplitScheme::Adaptive { .. } => "adaptive",
                SplitScheme::Exponent { .. } => "exponent",
            },
            *k,
        ),
        CascadeSplits::EqualError { k } => ("equal-error", *k),
        CascadeSplits::Distances { planes, .. } => ("splits", planes.len().saturating_sub(1)),
        CascadeSplits::Fractions { fractions, .. } => ("fractions", fractions.len() + 1),
        CascadeSplits::Bevy { k, .. } => ("bevy", *k),
    }
}

/// A scheme in words, for tables: `single minimax`, `tsm`, `cascades log k=4 minimax`,
/// `stable equal-error k=3`, `faces lispsm k=2`.
#[must_use]
pub fn label(s: &FrameScheme<'_>) -> String {
    match s {
        FrameScheme::Single(rule) => format!("single {}", rule_name(*rule)),
        FrameScheme::Tsm(_) => "trapezoid".to_string(),
        FrameScheme::Cascades { splits, rule } => {
            let (name, k) = splits_name(splits);
            format!("cascades {name} k={k} {}", rule_name(*rule))
        }
        FrameScheme::Stable(splits) => {
            let (name, k) = splits_name(splits);
            format!("stable {name} k={k}")
        }
        FrameScheme::Faces { rule, k } => format!("faces {} k={k}", face_rule_name(*rule)),
        FrameScheme::Clipmap(o) => format!("clipmap bias={}", num(o.lod_bias)),
    }
}

/// A number as the command line reads it back exactly (Rust's shortest round-trip form).
fn num(v: f64) -> String {
    format!("{v}")
}

/// `--partition`, `--k` and the splits' parameter of cascades' splits.
fn splits_args(s: &CascadeSplits<'_>) -> Option<Vec<String>> {
    let (name, k) = splits_name(s);
    let mut v = vec![
        "--partition".into(),
        name.into(),
        "--k".into(),
        k.to_string(),
    ];
    match s {
        CascadeSplits::Scheme {
            scheme: SplitScheme::Practical { lambda },
            ..
        } => v.extend(["--lambda".into(), num(*lambda)]),
        CascadeSplits::Scheme {
            scheme: SplitScheme::Adaptive { ratio, .. },
            ..
        } => v.extend(["--ratio".into(), num(*ratio)]),
        CascadeSplits::Scheme {
            scheme: SplitScheme::Uniform | SplitScheme::SelfSimilar,
            ..
        }
        | CascadeSplits::EqualError { .. } => {}
        _ => return None,
    }
    Some(v)
}

/// The command line's `warp` flags that build `s` (besides the camera, light and scene flags:
/// `--warp`, `--partition`, `--k`, `--lambda`, `--ratio`, `--focus`, `--stable`; for a clipmap
/// its layout, `--virtual-resolution` [`CLIPMAP_RESOLUTION`] and `--image-height`
/// `image_height`, which choose its levels); `None` for a scheme that `warp` cannot name.
/// Numbers are written in the shortest form that reads back exactly.
pub fn warp_args(s: &FrameScheme<'_>, image_height: u32) -> Option<Vec<String>> {
    let warp = |r: &str| vec!["--warp".to_string(), r.to_string()];
    Some(match s {
        FrameScheme::Single(WarpRule::Tsm { focus }) => {
            let mut v = warp("tsm");
            v.extend(["--focus".into(), num(*focus)]);
            v
        }
        FrameScheme::Single(r) => warp(rule_name(*r)),
        FrameScheme::Tsm(o) => {
            let mut v = warp("trapezoid");
            v.extend(["--focus".into(), num(o.focus)]);
            v
        }
        FrameScheme::Cascades { splits, rule } => {
            let mut v = warp(rule_name(*rule));
            v.extend(splits_args(splits)?);
            v
        }
        FrameScheme::Stable(splits) => {
            let mut v = warp("uniform");
            v.push("--stable".into());
            if splits_name(splits).1 > 1 {
                v.extend(splits_args(splits)?);
            }
            v
        }
        FrameScheme::Faces { rule, k } => {
            let mut v = warp(face_rule_name(*rule));
            v.extend([
                "--partition".into(),
                "faces".into(),
                "--k".into(),
                k.to_string(),
            ]);
            v
        }
        FrameScheme::Clipmap(o) => {
            let mut v = warp("uniform");
            v.extend([
                "--partition".into(),
                "clipmap".into(),
                "--lod-bias".into(),
                num(o.lod_bias),
                "--levels".into(),
                format!("{},{}", o.first_level, o.last_level),
                "--level-unit".into(),
                num(o.unit),
                "--page-texels".into(),
                o.page_texels.to_string(),
                "--virtual-resolution".into(),
                CLIPMAP_RESOLUTION.to_string(),
                "--image-height".into(),
                image_height.to_string(),
            ]);
            v
        }
        #[allow(unreachable_patterns)]
        _ => return None,
    })
}
