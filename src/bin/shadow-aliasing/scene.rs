//! `warp` with a scene (`--receivers`, `--casters`, `--depth-range`, `--splits`, `--fractions`,
//! `--bevy`): the library's frame API with the camera at the origin of eye space (world = eye),
//! a square image, maps measured over each focus body B.

use crate::args::{BoundsArgs, CameraArgs, ClipmapArgs, PartitionName, WarpArgs, WarpName};
use crate::output::{json_n_prime, json_num, sig, sig_n_prime};
use crate::scheme::{k, ratio, rule, value_name, Lights, DEFAULT_LAMBDA};
use glam::{DMat4, DVec3};
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::analytic::partition::MAX_PARTITIONS;
use shadow_aliasing::error::fmt_num;
use shadow_aliasing::frame::{
    frame, Aabb, Bound, Camera, CascadeSplits, ClipmapOptions, FrameInput, FrameScheme, LevelChoice,
};
use shadow_aliasing::maps::{TsmOptions, TsmSearch};
use shadow_aliasing::plan::candidates::CLIPMAP_RESOLUTION;
use shadow_aliasing::scheme::face_rule;
use shadow_aliasing::{Error, LightAngle, ViewFrustum};
use std::fmt::Write as _;

/// The map resolution and image height the frame API is given (the measured M_x, M_z, S̄ are
/// for unit resolutions, as everywhere in `warp`).
pub const RESOLUTION: u32 = 2048;

fn boxes(list: &[[f64; 6]], name: &'static str) -> Result<Vec<Aabb>, Error> {
    list.iter()
        .map(|b| {
            Aabb::new(DVec3::new(b[0], b[1], b[2]), DVec3::new(b[3], b[4], b[5])).map_err(|_| {
                Error::invalid(
                    name,
                    format!(
                        "boxes must have MINX ≤ MAXX, MINY ≤ MAXY, MINZ ≤ MAXZ (got {})",
                        b.map(fmt_num).join(",")
                    ),
                )
            })
        })
        .collect()
}

/// `--splits`, `--fractions` or `--bevy` give the cascades, their count included: refused with
/// `--partition` (other than single) or `--k`, naming both flags and which to drop.
fn cascades_given_once(a: &WarpArgs) -> Result<(), Error> {
    let (sc, sch) = (&a.scene, &a.scheme);
    let flag = if sc.splits.is_some() {
        "--splits"
    } else if sc.fractions.is_some() {
        "--fractions"
    } else if sc.bevy.is_some() {
        "--bevy"
    } else {
        return Ok(());
    };
    if sch.partition != PartitionName::Single {
        return Err(Error::invalid(
            "partition",
            format!(
                "{} cannot be combined with {flag}, which gives the cascades itself: drop \
                 --partition (and --k), or drop {flag}",
                value_name(&sch.partition)
            ),
        ));
    }
    if sch.k != 1 {
        return Err(Error::invalid(
            "k",
            format!(
                "{} cannot be combined with {flag}, which gives the number of cascades itself: \
                 drop --k, or drop {flag}",
                sch.k
            ),
        ));
    }
    Ok(())
}

/// The scene's boxes, owned (the frame input borrows them).
pub struct Boxes {
    receivers: Vec<Aabb>,
    casters: Vec<Aabb>,
}

impl Boxes {
    /// `--receivers` and `--casters` as boxes, each checked.
    pub fn new(b: &BoundsArgs) -> Result<Self, Error> {
        Ok(Self {
            receivers: boxes(&b.receivers, "receivers")?,
            casters: boxes(&b.casters, "casters")?,
        })
    }
}

/// The frame input of the camera (world = eye), the light and the bounds, with [`RESOLUTION`]
/// texels per map and an image `image_height` pixels high; its scheme is set by the caller.
pub fn frame_input<'a>(
    c: &CameraArgs,
    light: DVec3,
    b: &BoundsArgs,
    boxes: &'a Boxes,
    image_height: u32,
) -> Result<FrameInput<'a>, Error> {
    let cam = Camera::new(
        DMat4::IDENTITY,
        c.near,
        c.far,
        c.half_fov,
        b.aspect.unwrap_or(1.0),
    )?;
    let mut input =
        FrameInput::new(cam, light, RESOLUTION, image_height).depth_clamp(b.depth_clamp);
    if !boxes.receivers.is_empty() {
        input = input.receivers(Bound::Boxes(&boxes.receivers));
    }
    if !boxes.casters.is_empty() {
        input = input.casters(Bound::Boxes(&boxes.casters));
    }
    if let Some([z0, z1]) = b.depth_range {
        input = input.depth_range(z0, z1);
    }
    Ok(input)
}

/// `--warp trapezoid`: the frame's trapezoidal map, which takes `--focus` alone.
fn trapezoid(a: &WarpArgs) -> Result<FrameScheme<'static>, Error> {
    let (sc, sch) = (&a.scene, &a.scheme);
    let extra = [
        (sch.eta.is_some(), "eta"),
        (sch.near_hint.is_some(), "near_hint"),
        (sch.shadow_distance.is_some(), "shadow_distance"),
        (sch.lambda.is_some(), "lambda"),
        (sch.ratio.is_some(), "ratio"),
        (sch.partition != PartitionName::Single, "partition"),
        (sch.k != 1, "k"),
        (sc.stable, "stable"),
        (sc.splits.is_some(), "splits"),
        (sc.fractions.is_some(), "fractions"),
        (sc.bevy.is_some(), "bevy"),
        (sc.overlap.is_some(), "overlap"),
    ];
    if let Some((_, name)) = extra.iter().find(|(given, _)| *given) {
        return Err(Error::invalid(
            name,
            "is not used by --warp trapezoid, one trapezoidal map (its only parameter is \
             --focus): drop it",
        ));
    }
    Ok(FrameScheme::Tsm(TsmOptions {
        focus: sch.focus.unwrap_or(0.5 * (a.camera.far - a.camera.near)),
        search: TsmSearch::EightyPercent,
    }))
}

/// The text or JSON of `warp` with a scene.
pub fn warp_scene(a: &WarpArgs) -> Result<String, Error> {
    let c = &a.camera;
    let view = ViewFrustum::new(c.near, c.far, c.half_fov)?;
    let light = DVec3::from_array(a.light_dir);
    let sc = &a.scene;
    let sch = &a.scheme;
    let boxes = Boxes::new(&sc.bounds)?;
    if sch.warp == WarpName::Trapezoid {
        let input = frame_input(c, light, &sc.bounds, &boxes, RESOLUTION)?.scheme(trapezoid(a)?);
        let f = frame(&input)?;
        return Ok(if a.json { json(a, &f) } else { text(a, &f) });
    }
    cascades_given_once(a)?;
    if sc.stable && sch.warp != WarpName::Uniform {
        return Err(Error::invalid(
            "stable",
            format!(
                "cascades are unwarped (world-fixed squares): give --warp uniform (got --warp {})",
                value_name(&sch.warp)
            ),
        ));
    }
    if sch.partition == PartitionName::Clipmap && sch.warp != WarpName::Uniform {
        return Err(Error::invalid(
            "partition",
            format!(
                "clipmap levels are unwarped (camera-centred orthographic squares): give --warp \
                 uniform (got --warp {})",
                value_name(&sch.warp)
            ),
        ));
    }
    let r = rule(&view, Lights::One(light), sch)?;
    let k = k(sch)?;
    let overlap = sc.overlap.unwrap_or(0.0);
    let scheme_of = |s: SplitScheme| CascadeSplits::Scheme {
        scheme: s,
        k,
        overlap,
    };
    let bevy;
    let splits = if let Some(planes) = &sc.splits {
        Some(CascadeSplits::Distances {
            planes: &planes.0,
            overlap,
        })
    } else if let Some(fractions) = &sc.fractions {
        Some(CascadeSplits::Fractions {
            fractions: &fractions.0,
            overlap,
        })
    } else if let Some(b) = &sc.bevy {
        let [kb, min, first, max, o] = <[f64; 5]>::try_from(b.0.as_slice()).map_err(|_| {
            Error::invalid(
                "bevy",
                "needs K,MINIMUM_DISTANCE,FIRST_FAR_BOUND,MAXIMUM_DISTANCE,OVERLAP_PROPORTION",
            )
        })?;
        if !((1.0..=16.0).contains(&kb) && kb.fract() == 0.0) {
            return Err(Error::invalid(
                "bevy",
                format!(
                    "needs a whole number of cascades K in [1, 16] first (got {})",
                    fmt_num(kb)
                ),
            ));
        }
        bevy = CascadeSplits::Bevy {
            k: kb as usize,
            minimum_distance: min,
            maximum_distance: max,
            first_far_bound: first,
            overlap_proportion: o,
        };
        Some(bevy)
    } else {
        None
    };
    let fs = match (splits, sch.partition) {
        (Some(s), _) => FrameScheme::Cascades { splits: s, rule: r },
        (None, PartitionName::Single) => {
            if sc.overlap.is_some() {
                return Err(Error::invalid(
                    "overlap",
                    "needs cascades (--partition, --splits or --fractions)",
                ));
            }
            FrameScheme::Single(r)
        }
        (None, PartitionName::Uniform) => FrameScheme::Cascades {
            splits: scheme_of(SplitScheme::Uniform),
            rule: r,
        },
        (None, PartitionName::Log) => FrameScheme::Cascades {
            splits: scheme_of(SplitScheme::SelfSimilar),
            rule: r,
        },
        (None, PartitionName::Practical) => FrameScheme::Cascades {
            splits: scheme_of(SplitScheme::Practical {
                lambda: sch.lambda.unwrap_or(DEFAULT_LAMBDA),
            }),
            rule: r,
        },
        (None, PartitionName::Adaptive) => FrameScheme::Cascades {
            splits: scheme_of(SplitScheme::Adaptive {
                light_angle: LightAngle::from_light_dir(light)?.radians(),
                ratio: ratio(sch),
            }),
            rule: r,
        },
        (None, PartitionName::Faces) => FrameScheme::Faces {
            rule: face_rule(r),
            k,
        },
        (None, PartitionName::Clipmap) => {
            if sc.overlap.is_some() {
                return Err(Error::invalid(
                    "overlap",
                    "is not used by --partition clipmap, whose levels cover exactly the depths \
                     they are chosen for: drop --overlap",
                ));
            }
            FrameScheme::Clipmap(clipmap(&sc.clipmap)?.0)
        }
        (None, PartitionName::EqualError) => {
            if sc.overlap.is_some() {
                return Err(Error::invalid(
                    "overlap",
                    "is not used by --partition equal-error, whose maps cover exactly their \
                     splits: drop --overlap",
                ));
            }
            FrameScheme::Cascades {
                splits: CascadeSplits::EqualError { k },
                rule: r,
            }
        }
    };
    let fs = match (sc.stable, fs) {
        (false, fs) => fs,
        (true, FrameScheme::Cascades { splits, .. }) => FrameScheme::Stable(splits),
        (true, FrameScheme::Single(_)) => FrameScheme::Stable(CascadeSplits::Scheme {
            scheme: SplitScheme::SelfSimilar,
            k: 1,
            overlap: 0.0,
        }),
        (true, _) => {
            return Err(Error::invalid(
                "stable",
                "needs cascades (--partition other than faces, --splits, --fractions or \
                 --bevy) or none: drop --stable or --partition faces",
            ))
        }
    };
    let mut input = frame_input(c, light, &sc.bounds, &boxes, RESOLUTION)?.scheme(fs);
    if let FrameScheme::Clipmap(_) = fs {
        (_, input.map_resolution, input.image_height) = clipmap(&sc.clipmap)?;
    }
    // The cascades' planes are the user's --splits, the clipmap's levels its --levels: named so.
    let f = frame(&input).map_err(|e| match e {
        Error::InvalidArgument {
            name: "planes",
            reason,
        } if sc.splits.is_some() => Error::invalid("splits", reason),
        Error::InvalidArgument {
            name: "last_level", ..
        } => match input.scheme {
            FrameScheme::Clipmap(opts) => levels_too_few(&input, &opts),
            _ => e,
        },
        e => e,
    })?;
    Ok(if a.json { json(a, &f) } else { text(a, &f) })
}

fn json(a: &WarpArgs, f: &shadow_aliasing::frame::Frame) -> String {
    let mut s = format!(
        "{{\n  \"focus\": \"{}\",\n  \"light\": \"{}\",\n",
        f.focus().name(),
        f.light_case().name()
    );
    let maps: Vec<_> = f.maps().iter().collect();
    if let Some(total) = f.storage_factor() {
        let mx = maps.iter().map(|m| m.max_mx).fold(0.0, f64::max);
        let mz = maps.iter().map(|m| m.max_mz).fold(0.0, f64::max);
        let _ = writeln!(s, "  \"storage_factor\": {},", json_num(total));
        let _ = writeln!(s, "  \"max_mx\": {},", json_num(mx));
        let _ = writeln!(s, "  \"max_mz\": {},", json_num(mz));
        if maps.len() == 1 {
            let _ = writeln!(
                s,
                "  \"n_prime\": {},",
                json_n_prime(maps[0].shadow.n_prime())
            );
        }
    }
    s.push_str("  \"partitions\": [\n");
    for (i, m) in maps.iter().enumerate() {
        let mat: Vec<String> = m
            .shadow
            .with_clip_depth(a.clip_depth.depth())
            .to_cols_array()
            .iter()
            .map(|v| json_num(*v))
            .collect();
        let _ = writeln!(
            s,
            "    {{{}\"near\": {}, \"far\": {}, \"split\": [{}, {}], \"blend\": [{}, {}], \"n_prime\": {}, \"max_mx\": {}, \"max_mz\": {}, \"storage_factor\": {}, \"texel_world\": {}, \"body_vertices\": {}, \"matrix\": [{}]}}{}",
            m.face
                .map_or(String::new(), |f| format!("\"face\": \"{}\", ", f.name()))
                + &m.clipmap_level
                    .map_or(String::new(), |l| format!("\"clipmap_level\": {l}, ")),
            json_num(m.shadow.near()),
            json_num(m.shadow.far()),
            json_num(m.split.0),
            json_num(m.split.1),
            json_num(m.blend.0),
            json_num(m.blend.1),
            json_n_prime(m.shadow.n_prime()),
            json_num(m.max_mx),
            json_num(m.max_mz),
            json_num(m.storage_factor),
            json_num(m.texel_world),
            m.body().len(),
            mat.join(", "),
            if i + 1 < maps.len() { "," } else { "" }
        );
    }
    s.push_str("  ]\n}\n");
    s
}

fn text(a: &WarpArgs, f: &shadow_aliasing::frame::Frame) -> String {
    let mut s = String::new();
    let [lx, ly, lz] = a.light_dir;
    let _ = writeln!(
        s,
        "camera: near {}, far {}, half_fov {} rad; light travels along ({}, {}, {}) in eye space ({})",
        sig(a.camera.near),
        sig(a.camera.far),
        sig(a.camera.half_fov),
        sig(lx),
        sig(ly),
        sig(lz),
        f.light_case().name()
    );
    let _ = writeln!(s, "focus: {}", f.focus().name());
    let Some(total) = f.storage_factor() else {
        s.push_str("no map needed: the receivers are out of view (or edge-on to the light)\n");
        return s;
    };
    let _ = writeln!(
        s,
        "storage factor S̄ over B = {} (summed over {} map{}, unit resolutions)",
        sig(total),
        f.len(),
        if f.len() == 1 { "" } else { "s" }
    );
    for (i, m) in f.maps().iter().enumerate() {
        let _ = writeln!(
            s,
            "\nmap {} of {}{}: B's depth [{}, {}] ({} vertices), split [{}, {}], n′ = {}",
            i + 1,
            f.len(),
            m.face
                .map_or(String::new(), |f| format!(" ({} face)", f.name()))
                + &m.clipmap_level
                    .map_or(String::new(), |l| format!(" (clipmap level {l})")),
            sig(m.shadow.near()),
            sig(m.shadow.far()),
            m.body().len(),
            sig(m.split.0),
            sig(m.split.1),
            sig_n_prime(m.shadow.n_prime())
        );
        let _ = writeln!(
            s,
            "  M_x = {}   M_z = {}   S̄ = {}",
            sig(m.max_mx),
            sig(m.max_mz),
            sig(m.storage_factor)
        );
        let _ = writeln!(
            s,
            "  matrix (eye space → light clip space, {}), by rows:",
            a.clip_depth.label()
        );
        let matrix = m.shadow.with_clip_depth(a.clip_depth.depth());
        for r in 0..4 {
            let row = matrix.row(r);
            let _ = writeln!(
                s,
                "    [ {:>10} {:>10} {:>10} {:>10} ]",
                sig(row.x),
                sig(row.y),
                sig(row.z),
                sig(row.w)
            );
        }
    }
    s
}

/// `--levels FIRST,LAST` whose LAST is too fine for the visible depths: the error names the
/// flag and what to change, each remedy checked before it is advised: the `--levels` that cover
/// the depths (the frame built with them), or a far depth that LAST covers, rounded down to six
/// digits so that giving it works, and only where it stays beyond the near depth. Where neither
/// works, a larger `--level-unit` (each level's radius scales with it).
fn levels_too_few(input: &FrameInput<'_>, opts: &ClipmapOptions) -> Error {
    let (first, last) = (opts.first_level, opts.last_level);
    let view = input.camera.view();
    let (zn, zf) = match input.depth_range {
        Some((a, b)) => (a.max(view.near()), b.min(view.far())),
        None => (view.near(), view.far()),
    };
    let choice = |o: &ClipmapOptions| {
        LevelChoice::new(view, input.image_height, input.map_resolution, o).ok()
    };
    let builds = |first_level: i32, last_level: i32| {
        let o = ClipmapOptions {
            first_level,
            last_level,
            ..*opts
        };
        frame(&input.scheme(FrameScheme::Clipmap(o))).is_ok()
    };
    // The coarsest level the depths need (offset does not depend on LAST), then FIRST raised
    // where the levels would be more than a frame holds.
    let wide = ClipmapOptions {
        last_level: MAX_LEVEL,
        ..*opts
    };
    let levels = choice(&wide)
        .and_then(|c| c.levels_needed(zn, zf).ok())
        .and_then(|(_, l)| {
            let most = i32::try_from(MAX_PARTITIONS).unwrap_or(i32::MAX);
            [first, first.max(l - most + 1)]
                .into_iter()
                .find(|&f| builds(f, l))
                .map(|f| format!("give --levels {f},{l}"))
        });
    // The deepest far depth LAST covers, rounded down to six significant digits.
    let cut = choice(opts)
        .map(|c| round_down_6(c.deepest_covered()))
        .filter(|&z| z > zn && z > view.near())
        .map(|z| {
            format!(
                "cut the visible depths to {} with --far or --depth-range",
                fmt_num(z)
            )
        });
    let remedy = match (levels, cut) {
        (Some(l), Some(c)) => format!("{l}, or {c}"),
        (Some(l), None) => format!(
            "{l} (cutting the visible depths cannot help: LAST covers no depth beyond the near \
             one, {})",
            fmt_num(zn)
        ),
        (None, Some(c)) => c,
        (None, None) => format!(
            "no --levels within [-{MAX_LEVEL}, {MAX_LEVEL}] covers them: raise --level-unit \
             (level i covers radius 2^(i+1) units; got {})",
            fmt_num(opts.unit)
        ),
    };
    Error::invalid(
        "--levels",
        format!(
            "has LAST = {last}, too fine to cover the visible depths (each level covers twice the \
             depths of the one before): {remedy}"
        ),
    )
}

/// The largest number of six significant digits at most `z` (finite, positive): advice that
/// rounds up would be refused again when followed.
fn round_down_6(z: f64) -> f64 {
    let nearest: f64 = format!("{z:.5e}").parse().unwrap_or(z);
    if nearest <= z {
        return nearest;
    }
    // Rounded up: one unit of the sixth digit less (its f64 is at most z, as rounding is
    // monotonic and the decimal lies below z).
    let text = format!("{z:.5e}");
    let Some((mantissa, exponent)) = text.split_once('e') else {
        return z;
    };
    let digits = mantissa.replace('.', "").parse::<i64>().unwrap_or(0) - 1;
    let exponent = exponent.parse::<i32>().unwrap_or(0) - 5;
    format!("{digits}e{exponent}").parse().unwrap_or(z)
}

/// `--image-height` of `--partition clipmap` when it is not given.
const CLIPMAP_IMAGE_HEIGHT: u32 = 1080;

/// The clipmap's options (`--lod-bias`, `--levels`, …) given without `--partition clipmap`:
/// refused by name, as every other option that the scheme does not use.
///
/// # Errors
/// [`Error::InvalidArgument`] naming the first such option.
pub fn clipmap_options_unused(a: &WarpArgs) -> Result<(), Error> {
    if a.scheme.partition == PartitionName::Clipmap {
        return Ok(());
    }
    match a.scene.clipmap.given().iter().find(|(_, given)| *given) {
        Some((name, _)) => Err(Error::invalid(
            name,
            format!(
                "is only used by --partition clipmap: drop it, or give --partition clipmap (got \
                 --partition {})",
                value_name(&a.scheme.partition)
            ),
        )),
        None => Ok(()),
    }
}

/// The largest |level| that `--levels` accepts.
const MAX_LEVEL: i32 = 64;

/// `--partition clipmap`'s options: the layout, the levels' resolution and the image's height.
fn clipmap(a: &ClipmapArgs) -> Result<(ClipmapOptions, u32, u32), Error> {
    let whole = |name: &'static str, v: i64, min: i64| -> Result<u32, Error> {
        u32::try_from(v)
            .ok()
            .filter(|&u| i64::from(u) >= min)
            .ok_or_else(|| {
                Error::invalid(
                    name,
                    format!(
                        "must be a whole number from {min} to {} (got {v})",
                        u32::MAX
                    ),
                )
            })
    };
    let (first_level, last_level) = match &a.levels {
        None => (
            ClipmapOptions::UNREAL.first_level,
            ClipmapOptions::UNREAL.last_level,
        ),
        Some(l) => match l.0.as_slice() {
            [f, t]
                if f.fract() == 0.0
                    && t.fract() == 0.0
                    && f.abs() <= f64::from(MAX_LEVEL)
                    && t.abs() <= f64::from(MAX_LEVEL)
                    && f <= t =>
            {
                (*f as i32, *t as i32)
            }
            _ => {
                return Err(Error::invalid(
                    "--levels",
                    format!(
                        "needs FIRST,LAST, two whole numbers in [-{MAX_LEVEL}, {MAX_LEVEL}], FIRST \
                         no larger than LAST (Unreal 6,22; got {})",
                        l.0.iter().map(|v| fmt_num(*v)).collect::<Vec<_>>().join(",")
                    ),
                ))
            }
        },
    };
    let unreal = ClipmapOptions::UNREAL;
    let opts = ClipmapOptions {
        first_level,
        last_level,
        lod_bias: a.lod_bias.unwrap_or(unreal.lod_bias),
        unit: a.level_unit.unwrap_or(unreal.unit),
        page_texels: match a.page_texels {
            Some(p) => whole("page_texels", p, 1)?,
            None => unreal.page_texels,
        },
    };
    Ok((
        opts,
        match a.virtual_resolution {
            Some(r) => whole("virtual_resolution", r, 3)?,
            None => CLIPMAP_RESOLUTION,
        },
        match a.image_height {
            Some(h) => whole("image_height", h, 1)?,
            None => CLIPMAP_IMAGE_HEIGHT,
        },
    ))
}
