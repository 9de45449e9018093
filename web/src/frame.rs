//! `frame`: the library's world-space frame (`shadow_aliasing::frame`) from a JSON input, and its
//! maps as JSON; `error_lens`: the per-pixel lens at a list of points.
//!
//! The input object (keys as the library's `FrameInput` and `Camera` name them):
//! `world_to_eye` (16 numbers, column-major: three.js's `camera.matrixWorldInverse.elements`),
//! `near`, `far`, `half_fov` (radians, vertical), `aspect` (1), `light_dir_world` (the direction
//! light travels), `receivers`, `casters` (arrays of boxes `{min: [x, y, z], max: [x, y, z]}`;
//! absent: unbounded), `depth_range` (`[z_min, z_max]`), `depth_clamp` (false), `measure`
//! (true), `map_resolution` (2048), `map_resolutions` (each partition's own texels a side, in slot
//! order; absent: every map at `map_resolution`), `image_height` (2048), `pcf_radius` (0, texels,
//! for the bias),
//! `clip_depth` (`"neg-one-to-one"`, `"zero-to-one"`, `"reversed"`), `centre` (`"rule"`, `"eye"`,
//! `"nearest-vertex"`), `scheme` (module `scheme`; default a single minimax map).

use crate::args::{
    choice, field, mat4, num, numbers, nums, object, opt_bool, opt_number, opt_str, opt_u32,
    req_number, vec3, WebError, WebResult,
};
use crate::scheme::{scheme, Scheme};
use serde_json::{json, Map, Value};
use shadow_aliasing::frame::{
    frame as build_frame, Aabb, Bound, Camera, Frame, FrameInput, FrameMap, WarpCentre,
};
use shadow_aliasing::maps::{ClipDepth, WarpRule};
use shadow_aliasing::Error;

/// The keys of a frame input.
pub const INPUT_KEYS: &[&str] = &[
    "world_to_eye",
    "near",
    "far",
    "half_fov",
    "aspect",
    "light_dir_world",
    "receivers",
    "casters",
    "depth_range",
    "depth_clamp",
    "measure",
    "map_resolution",
    "map_resolutions",
    "image_height",
    "pcf_radius",
    "clip_depth",
    "centre",
    "scheme",
];

/// A frame input read from JSON, owning what the library's [`FrameInput`] borrows.
#[derive(Debug, Clone)]
pub struct FrameArgs {
    /// The camera.
    pub camera: Camera,
    /// The light's world direction.
    pub light: glam::DVec3,
    receivers: Option<Vec<Aabb>>,
    casters: Option<Vec<Aabb>>,
    depth_range: Option<(f64, f64)>,
    depth_clamp: bool,
    measure: bool,
    /// Texels per map side.
    pub map_resolution: u32,
    /// Each partition's texels per side, in slot order (`FrameInput::map_resolutions`).
    pub map_resolutions: Option<Vec<u32>>,
    /// Image height, pixels.
    pub image_height: u32,
    /// The PCF radius of the bias values.
    pub pcf_radius: f64,
    /// The clip-depth convention of the matrices and the depth bias.
    pub clip_depth: ClipDepth,
    centre: WarpCentre,
    /// The scheme.
    pub scheme: Scheme,
}

/// Boxes `[{min, max}, …]`.
fn boxes(name: &str, v: &Value) -> WebResult<Vec<Aabb>> {
    let a = v.as_array().ok_or_else(|| {
        WebError::invalid(
            name,
            "must be an array of boxes {min: [x, y, z], max: [x, y, z]}",
        )
    })?;
    a.iter()
        .enumerate()
        .map(|(i, b)| {
            let at = format!("{name}[{i}]");
            let m = object(&at, b, &["min", "max"])?;
            let get = |k: &str| {
                field(m, k)
                    .ok_or_else(|| WebError::invalid(&at, format!("is missing {k}")))
                    .and_then(|v| vec3(&format!("{at}.{k}"), v))
            };
            let (lo, hi) = (get("min")?, get("max")?);
            Aabb::new(lo, hi).map_err(|_| {
                WebError::invalid(
                    name,
                    format!(
                        "boxes must be finite with min not above max (got min={lo}, max={hi} at \
                         index {i})"
                    ),
                )
            })
        })
        .collect()
}

/// `map_resolutions`: an array of whole numbers (the library checks their count and least
/// value, naming `map_resolutions`).
fn resolutions(v: &Value) -> WebResult<Vec<u32>> {
    let a = v.as_array().ok_or_else(|| {
        WebError::invalid(
            "map_resolutions",
            format!(
                "must be an array of whole numbers, one resolution per partition in slot order \
                 (got {})",
                crate::args::kind(v)
            ),
        )
    })?;
    a.iter()
        .enumerate()
        .map(|(i, x)| {
            // At most u32::MAX: the cast is exact.
            crate::args::whole(&format!("map_resolutions[{i}]"), x, u64::from(u32::MAX))
                .map(|r| r as u32)
        })
        .collect()
}

impl FrameArgs {
    /// Reads a frame input (module docs).
    pub fn read(v: &Value) -> WebResult<Self> {
        let m = object("input", v, INPUT_KEYS)?;
        let view = mat4(
            "world_to_eye",
            field(m, "world_to_eye")
                .ok_or_else(|| WebError::invalid("world_to_eye", "is missing"))?,
        )?;
        let camera = Camera::new(
            view,
            req_number(m, "near")?,
            req_number(m, "far")?,
            req_number(m, "half_fov")?,
            opt_number(m, "aspect")?.unwrap_or(1.0),
        )?;
        let light = vec3(
            "light_dir_world",
            field(m, "light_dir_world")
                .ok_or_else(|| WebError::invalid("light_dir_world", "is missing"))?,
        )?;
        let receivers = field(m, "receivers")
            .map(|v| boxes("receivers", v))
            .transpose()?;
        let casters = field(m, "casters")
            .map(|v| boxes("casters", v))
            .transpose()?;
        let depth_range = match field(m, "depth_range") {
            None => None,
            Some(v) => {
                let a = numbers("depth_range", v)?;
                if a.len() != 2 {
                    return Err(WebError::invalid(
                        "depth_range",
                        format!("must hold two numbers [z_min, z_max] (got {})", a.len()),
                    ));
                }
                Some((a[0], a[1]))
            }
        };
        let clip_depth = match choice(
            "clip_depth",
            &opt_str(m, "clip_depth")?
                .unwrap_or("neg-one-to-one")
                .replace('_', "-"),
            &["neg-one-to-one", "zero-to-one", "reversed"],
        )? {
            "zero-to-one" => ClipDepth::ZeroToOne,
            "reversed" => ClipDepth::Reversed,
            _ => ClipDepth::NegOneToOne,
        };
        let centre = match choice(
            "centre",
            &opt_str(m, "centre")?.unwrap_or("rule").replace('_', "-"),
            &["rule", "eye", "nearest-vertex"],
        )? {
            "eye" => WarpCentre::Eye,
            "nearest-vertex" => WarpCentre::NearestVertex,
            _ => WarpCentre::Rule,
        };
        let light_eye = camera.world_to_eye().transform_vector3(light);
        let scheme = match field(m, "scheme") {
            Some(s) => scheme(s, camera.view(), light_eye)?,
            None => Scheme::Single(WarpRule::Minimax),
        };
        Ok(Self {
            camera,
            light,
            receivers,
            casters,
            depth_range,
            depth_clamp: opt_bool(m, "depth_clamp")?.unwrap_or(false),
            measure: opt_bool(m, "measure")?.unwrap_or(true),
            map_resolution: opt_u32(m, "map_resolution")?.unwrap_or(2048),
            map_resolutions: field(m, "map_resolutions").map(resolutions).transpose()?,
            image_height: opt_u32(m, "image_height")?.unwrap_or(2048),
            pcf_radius: opt_number(m, "pcf_radius")?.unwrap_or(0.0),
            clip_depth,
            centre,
            scheme,
        })
    }

    /// The library's input, borrowing the boxes and splits.
    pub fn input(&self) -> FrameInput<'_> {
        fn bound(b: &Option<Vec<Aabb>>) -> Bound<'_> {
            match b {
                Some(v) => Bound::Boxes(v),
                None => Bound::Unbounded,
            }
        }
        let mut input = FrameInput::new(
            self.camera,
            self.light,
            self.map_resolution,
            self.image_height,
        )
        .receivers(bound(&self.receivers))
        .casters(bound(&self.casters))
        .depth_clamp(self.depth_clamp)
        .measure(self.measure)
        .centre(self.centre)
        .scheme(self.scheme.get());
        if let Some((a, b)) = self.depth_range {
            input = input.depth_range(a, b);
        }
        if let Some(each) = &self.map_resolutions {
            input = input.map_resolutions(each);
        }
        input
    }
}

/// A matrix's 16 entries, column-major.
fn cols(m: &glam::DMat4) -> Value {
    nums(m.to_cols_array())
}

/// One map as JSON.
fn map_json(slot: usize, x: &FrameMap, depth: ClipDepth, pcf_radius: f64) -> WebResult<Value> {
    let b = x.bias(pcf_radius, depth).map_err(|e| match e {
        Error::InvalidArgument { reason, .. } => WebError::invalid("pcf_radius", reason),
        e => e.into(),
    })?;
    let planes = |vol: &shadow_aliasing::frame::CullVolume| {
        nums(vol.planes().iter().flat_map(|q| q.to_array()))
    };
    Ok(json!({
        "slot": slot,
        "world_to_clip": cols(&x.world_to_clip(depth)),
        "world_to_clip_f32": x.to_mat4(depth).to_cols_array().iter().map(|v| num(f64::from(*v))).collect::<Vec<_>>(),
        "eye_to_clip": cols(&x.shadow.with_clip_depth(depth)),
        "n_prime": num(x.shadow.n_prime().value()),
        "depth": nums([x.shadow.near(), x.shadow.far()]),
        "split": nums([x.split.0, x.split.1]),
        "blend": nums([x.blend.0, x.blend.1]),
        "texel_world": num(x.texel_world),
        "max_mx": num(x.max_mx),
        "max_mz": num(x.max_mz),
        "storage_factor": num(x.storage_factor),
        "max_error_pixels": num(x.max_error_pixels),
        "resolution": x.resolution(),
        "bias": {
            "normal_offset": num(b.normal_offset),
            "slope_scaled_depth": num(b.slope_scaled_depth),
            "constant_depth": num(b.constant_depth),
            "texel_extent": nums([b.texel_extent.0, b.texel_extent.1]),
        },
        "focus": x.focus.name(),
        "face": x.face.map(|f| f.name()),
        "clipmap_level": x.clipmap_level,
        "body": nums(x.body().iter().flat_map(|p| p.to_array())),
        "casters_volume": planes(x.casters_volume()),
        "receivers_volume": planes(x.receivers_volume()),
    }))
}

/// A frame as JSON: `focus`, `light`, `light_dir_eye`, `storage_factor` (the frame's, when every
/// map is measured) and `maps` (each map's matrices, column-major, in `depth`'s convention;
/// splits, blend band, texel size, measured errors, bias, focus body and culling volumes).
pub fn frame_json(f: &Frame, depth: ClipDepth, pcf_radius: f64) -> WebResult<Value> {
    let maps = f
        .slots()
        .iter()
        .enumerate()
        .filter_map(|(i, m)| m.as_ref().map(|m| map_json(i, m, depth, pcf_radius)))
        .collect::<WebResult<Vec<_>>>()?;
    Ok(json!({
        "focus": f.focus().name(),
        "light": f.light_case().name(),
        "light_dir_eye": nums(f.light_dir_eye().to_array()),
        "storage_factor": f.storage_factor().map(num),
        "maps": maps,
    }))
}

/// `frame`: the request's `input` built and written out.
pub fn frame(req: &Map<String, Value>) -> WebResult<Value> {
    let a = FrameArgs::read(req.get("input").unwrap_or(&Value::Null))?;
    let f = build_frame(&a.input())?;
    frame_json(&f, a.clip_depth, a.pcf_radius)
}

/// `error_lens`: the lens of map `map` (an index into `frame`'s `maps`) at `points` (3 numbers
/// each, world space) with `normals` (3 numbers each, or 3 for all). Each point gives a value,
/// or, where the library reports it degenerate (behind the camera or the map's centre of
/// projection, edge-on to the light), `null` and its message in `reasons`.
pub fn error_lens(req: &Map<String, Value>) -> WebResult<Value> {
    let a = FrameArgs::read(req.get("input").unwrap_or(&Value::Null))?;
    let points = numbers(
        "points",
        field(req, "points").ok_or_else(|| WebError::invalid("points", "is missing"))?,
    )?;
    let normals = numbers(
        "normals",
        field(req, "normals").ok_or_else(|| WebError::invalid("normals", "is missing"))?,
    )?;
    if points.is_empty() || points.len() % 3 != 0 {
        return Err(WebError::invalid(
            "points",
            format!(
                "must hold 3 numbers per point, at least one point (got {} numbers)",
                points.len()
            ),
        ));
    }
    let n = points.len() / 3;
    if normals.len() != 3 && normals.len() != points.len() {
        return Err(WebError::invalid(
            "normals",
            format!(
                "must hold 3 numbers (one normal for every point) or 3 per point ({} numbers; \
                 got {})",
                points.len(),
                normals.len()
            ),
        ));
    }
    let f = build_frame(&a.input())?;
    let maps: Vec<&FrameMap> = f.maps().iter().collect();
    let index = match field(req, "map") {
        None => 0,
        Some(v) => crate::args::whole("map", v, u64::from(u32::MAX))? as usize,
    };
    let map = maps.get(index).ok_or_else(|| {
        WebError::invalid(
            "map",
            format!(
                "must index one of the frame's {} maps (got {index})",
                maps.len()
            ),
        )
    })?;
    let mut values = Vec::with_capacity(n);
    let mut reasons = Vec::with_capacity(n);
    for i in 0..n {
        let p = [points[3 * i], points[3 * i + 1], points[3 * i + 2]];
        let j = if normals.len() == 3 { 0 } else { 3 * i };
        let q = [normals[j], normals[j + 1], normals[j + 2]];
        match map.error_lens_at(p, q, &a.camera, a.image_height) {
            Ok(v) => {
                values.push(num(v));
                reasons.push(Value::Null);
            }
            Err(Error::Degenerate(m)) => {
                values.push(Value::Null);
                reasons.push(Value::from(format!("degenerate geometry: {m}")));
            }
            Err(Error::InvalidArgument { name, reason }) => {
                let arg = match name {
                    "n" => "normals",
                    "p" => "points",
                    other => other,
                };
                return Err(WebError::invalid(arg, format!("{reason} (at point {i})")));
            }
            Err(e) => return Err(e.into()),
        }
    }
    Ok(json!({ "values": values, "reasons": reasons }))
}

/// `lens_colour`: the lens ramp's sRGB colour of `value` (pixels).
pub fn lens_colour(req: &Map<String, Value>) -> WebResult<Value> {
    let v = req_number(req, "value")?;
    Ok(nums(shadow_aliasing::frame::lens::lens_colour(v)))
}
