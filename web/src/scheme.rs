//! Schemes as JSON: read into the library's [`FrameScheme`], and written back in the same form
//! (the controller's decision is a scheme a later `frame` call can take).
//!
//! A scheme is an object with `kind`:
//! - `"single"`: `rule`;
//! - `"cascades"`: `rule` and one of `partition` with `k` (`"log"`, `"uniform"`, `"practical"`
//!   with `lambda`, `"adaptive"`, `"exponent"` with `exponent`, `"equal-error"`), `splits` (the
//!   planes z₀ … z_k), `fractions`, `bevy` (Bevy's `CascadeShadowConfigBuilder` fields); `overlap`;
//! - `"stable"`: the same splits, no rule;
//! - `"tsm"`: `focus` (default half the view depth), `xi` or `iterative` (map lines, with
//!   `exhaustive`);
//! - `"faces"`: `rule` (`"uniform"`, `"psm"`, `"lispsm"`) and `k`;
//! - `"clipmap"`: `first_level`, `last_level`, `lod_bias`, `unit`, `page_texels` (Unreal's
//!   defaults where absent).
//!
//! A rule is a name (`"uniform"`, `"psm"`, `"lispsm"`, `"lispsm-fixed"`, `"lispsm-reference"`,
//! `"barroso"`, `"barroso-zhang"`, `"minimax"`, `"minimax-mz"`, `"filament"`, `"ogre"`) or an
//! object `{name, …}` with the rule's parameter (`{name: "eta", eta}`, `{name: "tsm", focus}`,
//! `{name: "filament", near_hint, far_hint}`, `{name: "ogre-ortho", shadow_distance}`).
//! Underscores spell hyphens (`"equal_error"`).

use crate::args::{
    choice, field, num, numbers, object, opt_number, opt_str, opt_whole, req_number, WebError,
    WebResult,
};
use serde_json::{json, Map, Value};
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::analytic::tilted::Falloff;
use shadow_aliasing::frame::{CascadeSplits, ClipmapOptions, FrameScheme};
use shadow_aliasing::maps::faces::FaceWarp;
use shadow_aliasing::maps::{TsmOptions, TsmSearch, WarpRule};
use shadow_aliasing::plan::candidates::{face_rule_name, rule_name};
use shadow_aliasing::scheme::ADAPTIVE_RATIO;
use shadow_aliasing::{LightAngle, ViewFrustum};

/// The rules by name.
pub const RULES: &[&str] = &[
    "uniform",
    "eta",
    "psm",
    "lispsm",
    "lispsm-fixed",
    "lispsm-reference",
    "barroso",
    "barroso-zhang",
    "minimax",
    "minimax-mz",
    "tsm",
    "filament",
    "ogre",
    "ogre-ortho",
];

/// Splits owned (the library's [`CascadeSplits`] borrows its planes).
#[derive(Debug, Clone, PartialEq)]
pub enum Splits {
    /// A split scheme and k.
    Scheme(SplitScheme, usize, f64),
    /// Planes z₀ … z_k.
    Distances(Vec<f64>, f64),
    /// Fractions of the view depth.
    Fractions(Vec<f64>, f64),
    /// Bevy's builder.
    Bevy([f64; 4], usize),
    /// Equal error, k cascades.
    EqualError(usize),
}

impl Splits {
    /// The library's splits, borrowing the planes.
    pub fn get(&self) -> CascadeSplits<'_> {
        match self {
            Splits::Scheme(scheme, k, overlap) => CascadeSplits::Scheme {
                scheme: *scheme,
                k: *k,
                overlap: *overlap,
            },
            Splits::Distances(planes, overlap) => CascadeSplits::Distances {
                planes,
                overlap: *overlap,
            },
            Splits::Fractions(fractions, overlap) => CascadeSplits::Fractions {
                fractions,
                overlap: *overlap,
            },
            Splits::Bevy(v, k) => CascadeSplits::Bevy {
                k: *k,
                minimum_distance: v[0],
                maximum_distance: v[1],
                first_far_bound: v[2],
                overlap_proportion: v[3],
            },
            Splits::EqualError(k) => CascadeSplits::EqualError { k: *k },
        }
    }
}

/// A scheme owned.
#[derive(Debug, Clone, PartialEq)]
pub enum Scheme {
    /// One map.
    Single(WarpRule),
    /// Cascades.
    Cascades(Splits, WarpRule),
    /// Stable cascades.
    Stable(Splits),
    /// Trapezoidal.
    Tsm(TsmOptions),
    /// Face partitions.
    Faces(FaceWarp, usize),
    /// A clipmap.
    Clipmap(ClipmapOptions),
}

impl Scheme {
    /// The library's scheme.
    pub fn get(&self) -> FrameScheme<'_> {
        match self {
            Scheme::Single(r) => FrameScheme::Single(*r),
            Scheme::Cascades(s, rule) => FrameScheme::Cascades {
                splits: s.get(),
                rule: *rule,
            },
            Scheme::Stable(s) => FrameScheme::Stable(s.get()),
            Scheme::Tsm(o) => FrameScheme::Tsm(*o),
            Scheme::Faces(rule, k) => FrameScheme::Faces { rule: *rule, k: *k },
            Scheme::Clipmap(o) => FrameScheme::Clipmap(*o),
        }
    }

    /// The scheme with no borrowed planes, for the controller's candidates.
    pub fn to_static(&self) -> WebResult<FrameScheme<'static>> {
        let splits = |s: &Splits| -> WebResult<CascadeSplits<'static>> {
            match s {
                Splits::Distances(..) | Splits::Fractions(..) => Err(WebError::invalid(
                    "candidates",
                    "cannot hold splits or fractions (give partition with k, or bevy)",
                )),
                Splits::Scheme(scheme, k, overlap) => Ok(CascadeSplits::Scheme {
                    scheme: *scheme,
                    k: *k,
                    overlap: *overlap,
                }),
                Splits::Bevy(v, k) => Ok(CascadeSplits::Bevy {
                    k: *k,
                    minimum_distance: v[0],
                    maximum_distance: v[1],
                    first_far_bound: v[2],
                    overlap_proportion: v[3],
                }),
                Splits::EqualError(k) => Ok(CascadeSplits::EqualError { k: *k }),
            }
        };
        Ok(match self {
            Scheme::Single(r) => FrameScheme::Single(*r),
            Scheme::Cascades(s, rule) => FrameScheme::Cascades {
                splits: splits(s)?,
                rule: *rule,
            },
            Scheme::Stable(s) => FrameScheme::Stable(splits(s)?),
            Scheme::Tsm(o) => FrameScheme::Tsm(*o),
            Scheme::Faces(rule, k) => FrameScheme::Faces { rule: *rule, k: *k },
            Scheme::Clipmap(o) => FrameScheme::Clipmap(*o),
        })
    }
}

/// `_` spelled `-`.
fn hyphens(s: &str) -> String {
    s.replace('_', "-")
}

/// A warp rule (module docs); `view` gives the defaults that depend on the camera.
pub fn rule(name: &str, v: &Value, view: &ViewFrustum) -> WebResult<WarpRule> {
    let (rule_name, m) = match v {
        Value::String(s) => (hyphens(s), None),
        Value::Object(_) => {
            let m = object(
                name,
                v,
                &[
                    "name",
                    "eta",
                    "focus",
                    "near_hint",
                    "far_hint",
                    "shadow_distance",
                ],
            )?;
            let n = opt_str(m, "name")?
                .ok_or_else(|| WebError::invalid(name, "needs a name (one of the rules)"))?;
            (hyphens(n), Some(m))
        }
        _ => {
            return Err(WebError::invalid(
                name,
                "must be a rule's name or an object {name, …}",
            ))
        }
    };
    let r = choice(name, &rule_name, RULES)?;
    let empty = Map::new();
    let m = m.unwrap_or(&empty);
    let allowed: &[&str] = match r {
        "eta" => &["eta"],
        "tsm" => &["focus"],
        "filament" => &["near_hint", "far_hint"],
        "ogre-ortho" => &["shadow_distance"],
        _ => &[],
    };
    if let Some(k) = m
        .keys()
        .find(|k| k.as_str() != "name" && !allowed.contains(&k.as_str()))
    {
        return Err(WebError::invalid(
            name,
            format!("has {k:?}, which rule {r:?} does not use"),
        ));
    }
    Ok(match r {
        "uniform" => WarpRule::Uniform,
        "eta" => WarpRule::Eta(req_number(m, "eta")?),
        "psm" => WarpRule::Psm,
        "lispsm" => WarpRule::Lispsm,
        "lispsm-fixed" => WarpRule::LispsmFixed,
        "lispsm-reference" => WarpRule::LispsmReference,
        "barroso" => WarpRule::Barroso(Falloff::Barroso),
        "barroso-zhang" => WarpRule::Barroso(Falloff::Zhang),
        "minimax" => WarpRule::Minimax,
        "minimax-mz" => WarpRule::MinimaxMz,
        "tsm" => WarpRule::Tsm {
            focus: opt_number(m, "focus")?.unwrap_or(0.5 * (view.far() - view.near())),
        },
        "filament" => match (opt_number(m, "near_hint")?, opt_number(m, "far_hint")?) {
            (None, None) => WarpRule::Filament,
            (Some(near_hint), Some(far_hint)) => WarpRule::FilamentHints {
                near_hint,
                far_hint,
            },
            _ => {
                return Err(WebError::invalid(
                    name,
                    "needs near_hint and far_hint together (rule \"filament\")",
                ))
            }
        },
        "ogre" => WarpRule::Ogre,
        _ => WarpRule::OgreOrtho {
            shadow_distance: opt_number(m, "shadow_distance")?.unwrap_or(300.0 * view.near()),
        },
    })
}

/// A rule as JSON, in the form [`rule`] reads.
pub fn rule_json(r: WarpRule) -> Value {
    match r {
        WarpRule::Eta(eta) => json!({"name": "eta", "eta": num(eta)}),
        WarpRule::Tsm { focus } => json!({"name": "tsm", "focus": num(focus)}),
        WarpRule::FilamentHints {
            near_hint,
            far_hint,
        } => json!({"name": "filament", "near_hint": num(near_hint), "far_hint": num(far_hint)}),
        WarpRule::OgreOrtho { shadow_distance } => {
            json!({"name": "ogre-ortho", "shadow_distance": num(shadow_distance)})
        }
        r => Value::from(rule_name(r)),
    }
}

/// The cascades' splits from a scheme object's fields.
fn splits(m: &Map<String, Value>, light_dir_eye: glam::DVec3) -> WebResult<Splits> {
    let given: Vec<&str> = ["partition", "splits", "fractions", "bevy"]
        .into_iter()
        .filter(|k| field(m, k).is_some())
        .collect();
    if given.len() > 1 {
        return Err(WebError::invalid(
            given[1],
            format!("is an alternative to {}: give one", given[0]),
        ));
    }
    let overlap = opt_number(m, "overlap")?;
    let k = opt_whole(m, "k", 64)?.map(|k| k as usize);
    let lambda = opt_number(m, "lambda")?;
    let exponent = opt_number(m, "exponent")?;
    let only = |given: bool, arg: &str, owner: &str| -> WebResult<()> {
        if given {
            Err(WebError::invalid(arg, format!("is only used with {owner}")))
        } else {
            Ok(())
        }
    };
    if given.first() != Some(&"partition") {
        only(k.is_some(), "k", "partition")?;
        only(lambda.is_some(), "lambda", "partition \"practical\"")?;
        only(exponent.is_some(), "exponent", "partition \"exponent\"")?;
    }
    match given.first().copied() {
        Some("splits") => Ok(Splits::Distances(
            numbers("splits", &m["splits"])?,
            overlap.unwrap_or(0.0),
        )),
        Some("fractions") => Ok(Splits::Fractions(
            numbers("fractions", &m["fractions"])?,
            overlap.unwrap_or(0.0),
        )),
        Some("bevy") => {
            only(
                overlap.is_some(),
                "overlap",
                "partition, splits or fractions (bevy has overlap_proportion)",
            )?;
            let keys = [
                "num_cascades",
                "minimum_distance",
                "maximum_distance",
                "first_cascade_far_bound",
                "overlap_proportion",
            ];
            let b = object("bevy", &m["bevy"], &keys)?;
            let k = opt_whole(b, "num_cascades", 64)?
                .ok_or_else(|| WebError::invalid("num_cascades", "is missing (bevy)"))?;
            let mut v = [0.0; 4];
            for (slot, key) in v.iter_mut().zip(&keys[1..]) {
                *slot = req_number(b, key)?;
            }
            Ok(Splits::Bevy(v, k as usize))
        }
        _ => {
            let p = hyphens(opt_str(m, "partition")?.unwrap_or("log"));
            let p = choice(
                "partition",
                &p,
                &[
                    "log",
                    "self-similar",
                    "uniform",
                    "practical",
                    "adaptive",
                    "exponent",
                    "equal-error",
                ],
            )?;
            let k = k.ok_or_else(|| {
                WebError::invalid(
                    "k",
                    "is missing: cascades need k with partition (or splits, fractions or bevy)",
                )
            })?;
            only(
                lambda.is_some() && p != "practical",
                "lambda",
                "partition \"practical\"",
            )?;
            only(
                exponent.is_some() && p != "exponent",
                "exponent",
                "partition \"exponent\"",
            )?;
            let scheme = match p {
                "equal-error" => {
                    only(
                        overlap.is_some(),
                        "overlap",
                        "the other partitions (equal-error maps cover exactly their splits)",
                    )?;
                    return Ok(Splits::EqualError(k));
                }
                "uniform" => SplitScheme::Uniform,
                "practical" => SplitScheme::Practical {
                    lambda: lambda.ok_or_else(|| {
                        WebError::invalid("lambda", "is missing (partition \"practical\")")
                    })?,
                },
                "exponent" => SplitScheme::Exponent {
                    exponent: exponent.ok_or_else(|| {
                        WebError::invalid("exponent", "is missing (partition \"exponent\")")
                    })?,
                },
                "adaptive" => SplitScheme::Adaptive {
                    light_angle: LightAngle::from_light_dir(light_dir_eye)?.radians(),
                    ratio: ADAPTIVE_RATIO,
                },
                _ => SplitScheme::SelfSimilar,
            };
            Ok(Splits::Scheme(scheme, k, overlap.unwrap_or(0.0)))
        }
    }
}

/// A scheme (module docs). `view` and `light_dir_eye` give the defaults that depend on the
/// camera and the light (TSM's focus, the adaptive planes' light angle).
pub fn scheme(v: &Value, view: &ViewFrustum, light_dir_eye: glam::DVec3) -> WebResult<Scheme> {
    let kind = v
        .as_object()
        .and_then(|m| m.get("kind"))
        .and_then(Value::as_str)
        .ok_or_else(|| {
            WebError::invalid(
                "scheme",
                "must be an object with kind \"single\", \"cascades\", \"stable\", \"tsm\", \
                 \"faces\" or \"clipmap\"",
            )
        })?;
    let kind = choice(
        "scheme",
        kind,
        &["single", "cascades", "stable", "tsm", "faces", "clipmap"],
    )?;
    const SPLITS: [&str; 8] = [
        "partition",
        "k",
        "lambda",
        "exponent",
        "splits",
        "fractions",
        "bevy",
        "overlap",
    ];
    let rule_of = |m: &Map<String, Value>| -> WebResult<WarpRule> {
        match field(m, "rule") {
            Some(r) => rule("rule", r, view),
            None => Ok(WarpRule::Minimax),
        }
    };
    Ok(match kind {
        "single" => Scheme::Single(rule_of(object("scheme", v, &["kind", "rule"])?)?),
        "cascades" => {
            let mut keys = vec!["kind", "rule"];
            keys.extend(SPLITS);
            let m = object("scheme", v, &keys)?;
            Scheme::Cascades(splits(m, light_dir_eye)?, rule_of(m)?)
        }
        "stable" => {
            let mut keys = vec!["kind"];
            keys.extend(SPLITS);
            Scheme::Stable(splits(object("scheme", v, &keys)?, light_dir_eye)?)
        }
        "tsm" => {
            let m = object(
                "scheme",
                v,
                &["kind", "focus", "xi", "iterative", "exhaustive"],
            )?;
            let exhaustive = crate::args::opt_bool(m, "exhaustive")?;
            let lines = opt_whole(m, "iterative", u64::from(u32::MAX))?;
            if exhaustive.is_some() && lines.is_none() {
                return Err(WebError::invalid(
                    "exhaustive",
                    "is only used with iterative",
                ));
            }
            let search = match (opt_number(m, "xi")?, lines) {
                (None, None) => TsmSearch::EightyPercent,
                (Some(xi), None) => TsmSearch::Line(xi),
                (None, Some(l)) if exhaustive == Some(true) => TsmSearch::IterativeExhaustive {
                    map_lines: l as u32,
                },
                (None, Some(l)) => TsmSearch::Iterative {
                    map_lines: l as u32,
                },
                _ => {
                    return Err(WebError::invalid(
                        "iterative",
                        "is an alternative to xi: give at most one",
                    ))
                }
            };
            Scheme::Tsm(TsmOptions {
                focus: opt_number(m, "focus")?.unwrap_or(0.5 * (view.far() - view.near())),
                search,
            })
        }
        "faces" => {
            let m = object("scheme", v, &["kind", "rule", "k"])?;
            let r = hyphens(opt_str(m, "rule")?.unwrap_or("lispsm"));
            let rule = match choice("rule", &r, &["uniform", "psm", "lispsm"])? {
                "uniform" => FaceWarp::Uniform,
                "psm" => FaceWarp::Psm,
                _ => FaceWarp::Lispsm,
            };
            let k = opt_whole(m, "k", 64)?
                .ok_or_else(|| WebError::invalid("k", "is missing (faces need k)"))?;
            Scheme::Faces(rule, k as usize)
        }
        _ => {
            let m = object(
                "scheme",
                v,
                &[
                    "kind",
                    "first_level",
                    "last_level",
                    "lod_bias",
                    "unit",
                    "page_texels",
                ],
            )?;
            let mut o = ClipmapOptions::UNREAL;
            let level = |key: &str, d: i32| -> WebResult<i32> {
                match opt_number(m, key)? {
                    None => Ok(d),
                    Some(x) if x.fract() == 0.0 && x.abs() <= 64.0 => Ok(x as i32),
                    Some(x) => Err(WebError::invalid(
                        key,
                        format!("must be a whole number in [-64, 64] (got {x})"),
                    )),
                }
            };
            o.first_level = level("first_level", o.first_level)?;
            o.last_level = level("last_level", o.last_level)?;
            o.lod_bias = opt_number(m, "lod_bias")?.unwrap_or(o.lod_bias);
            o.unit = opt_number(m, "unit")?.unwrap_or(o.unit);
            if let Some(p) = opt_whole(m, "page_texels", u64::from(u32::MAX))? {
                o.page_texels = p as u32;
            }
            Scheme::Clipmap(o)
        }
    })
}

/// Splits as JSON fields of a scheme object.
fn splits_json(s: &CascadeSplits<'_>, m: &mut Map<String, Value>) {
    let mut put = |k: &str, v: Value| {
        m.insert(k.to_string(), v);
    };
    match *s {
        CascadeSplits::Scheme { scheme, k, overlap } => {
            let p = match scheme {
                SplitScheme::Uniform => "uniform",
                SplitScheme::SelfSimilar => "log",
                SplitScheme::Practical { lambda } => {
                    put("lambda", num(lambda));
                    "practical"
                }
                SplitScheme::Adaptive { .. } => "adaptive",
                SplitScheme::Exponent { exponent } => {
                    put("exponent", num(exponent));
                    "exponent"
                }
            };
            put("partition", Value::from(p));
            put("k", Value::from(k));
            put("overlap", num(overlap));
        }
        CascadeSplits::Distances { planes, overlap } => {
            put("splits", crate::args::nums(planes.iter().copied()));
            put("overlap", num(overlap));
        }
        CascadeSplits::Fractions { fractions, overlap } => {
            put("fractions", crate::args::nums(fractions.iter().copied()));
            put("overlap", num(overlap));
        }
        CascadeSplits::Bevy {
            k,
            minimum_distance,
            maximum_distance,
            first_far_bound,
            overlap_proportion,
        } => put(
            "bevy",
            json!({
                "num_cascades": k,
                "minimum_distance": num(minimum_distance),
                "maximum_distance": num(maximum_distance),
                "first_cascade_far_bound": num(first_far_bound),
                "overlap_proportion": num(overlap_proportion),
            }),
        ),
        CascadeSplits::EqualError { k } => {
            put("partition", Value::from("equal-error"));
            put("k", Value::from(k));
        }
    }
}

/// A scheme as JSON, in the form [`scheme`] reads (the adaptive partition's light angle is
/// recomputed from the light when read back).
pub fn scheme_json(s: &FrameScheme<'_>) -> Value {
    let mut m = Map::new();
    match s {
        FrameScheme::Single(r) => {
            m.insert("kind".into(), "single".into());
            m.insert("rule".into(), rule_json(*r));
        }
        FrameScheme::Cascades { splits, rule } => {
            m.insert("kind".into(), "cascades".into());
            m.insert("rule".into(), rule_json(*rule));
            splits_json(splits, &mut m);
        }
        FrameScheme::Stable(splits) => {
            m.insert("kind".into(), "stable".into());
            splits_json(splits, &mut m);
        }
        FrameScheme::Tsm(o) => {
            m.insert("kind".into(), "tsm".into());
            m.insert("focus".into(), num(o.focus));
            match o.search {
                TsmSearch::EightyPercent => {}
                TsmSearch::Line(xi) => {
                    m.insert("xi".into(), num(xi));
                }
                TsmSearch::Iterative { map_lines } => {
                    m.insert("iterative".into(), Value::from(map_lines));
                }
                TsmSearch::IterativeExhaustive { map_lines } => {
                    m.insert("iterative".into(), Value::from(map_lines));
                    m.insert("exhaustive".into(), Value::from(true));
                }
            }
        }
        FrameScheme::Faces { rule, k } => {
            m.insert("kind".into(), "faces".into());
            m.insert("rule".into(), face_rule_name(*rule).into());
            m.insert("k".into(), Value::from(*k));
        }
        FrameScheme::Clipmap(o) => {
            m.insert("kind".into(), "clipmap".into());
            m.insert("first_level".into(), Value::from(o.first_level));
            m.insert("last_level".into(), Value::from(o.last_level));
            m.insert("lod_bias".into(), num(o.lod_bias));
            m.insert("unit".into(), num(o.unit));
            m.insert("page_texels".into(), Value::from(o.page_texels));
        }
    }
    Value::Object(m)
}
