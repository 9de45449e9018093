//! A camera path file (docs/paths.md): a scene, a camera's projection, the image height, the
//! light, and each frame's eye and target, as JSON. Unknown keys are refused, naming the key.

use glam::{DMat4, DVec3, DVec4};
use serde_json::{Map, Value};
use shadow_aliasing::frame::{Aabb, Camera};
use std::path::Path;

/// One frame of a path: the camera (world → eye, `look_at_rh` with +Y up) and the light.
pub struct PathFrame {
    /// The camera.
    pub camera: Camera,
    /// The direction the light travels, world space.
    pub light: DVec3,
}

/// A parsed path.
pub struct PathFile {
    /// The image's height, pixels.
    pub image_height: u32,
    /// The receivers' boxes (at least one).
    pub receivers: Vec<Aabb>,
    /// The casters' boxes (may be empty: the receivers cast).
    pub casters: Vec<Aabb>,
    /// The frames (at least one).
    pub frames: Vec<PathFrame>,
}

/// A message about the file at `at` (a JSON pointer-like place such as `frames[3].eye`).
fn bad(at: &str, reason: impl std::fmt::Display) -> String {
    format!("{at}: {reason}")
}

/// The object at `at`, with only `allowed` keys and every `required` one.
fn object<'v>(
    v: &'v Value,
    at: &str,
    allowed: &[&str],
    required: &[&str],
) -> Result<&'v Map<String, Value>, String> {
    let place = if at.is_empty() { "the top level" } else { at };
    let o = v
        .as_object()
        .ok_or_else(|| bad(place, "must be a JSON object"))?;
    if let Some(k) = o.keys().find(|k| !allowed.contains(&k.as_str())) {
        return Err(format!(
            "unknown key `{k}` in {place} (the keys are {}): remove or rename it",
            allowed.join(", ")
        ));
    }
    if let Some(k) = required.iter().find(|k| !o.contains_key(**k)) {
        return Err(format!("the key `{k}` is missing in {place}"));
    }
    Ok(o)
}

fn join(at: &str, key: &str) -> String {
    if at.is_empty() {
        key.to_string()
    } else {
        format!("{at}.{key}")
    }
}

fn number(v: &Value, at: &str) -> Result<f64, String> {
    v.as_f64()
        .filter(|x| x.is_finite())
        .ok_or_else(|| bad(at, format!("must be a finite number (got {v})")))
}

fn numbers<const N: usize>(v: &Value, at: &str) -> Result<[f64; N], String> {
    let a = v
        .as_array()
        .filter(|a| a.len() == N)
        .ok_or_else(|| bad(at, format!("must be an array of {N} numbers (got {v})")))?;
    let mut out = [0.0; N];
    for (i, x) in a.iter().enumerate() {
        out[i] = number(x, &format!("{at}[{i}]"))?;
    }
    Ok(out)
}

fn boxes(v: &Value, at: &str) -> Result<Vec<Aabb>, String> {
    let a = v.as_array().ok_or_else(|| {
        bad(
            at,
            "must be an array of boxes [minx,miny,minz,maxx,maxy,maxz]",
        )
    })?;
    a.iter()
        .enumerate()
        .map(|(i, b)| {
            let here = format!("{at}[{i}]");
            let b = numbers::<6>(b, &here)?;
            Aabb::new(DVec3::new(b[0], b[1], b[2]), DVec3::new(b[3], b[4], b[5]))
                .map_err(|_| bad(&here, "must have min ≤ max on every axis"))
        })
        .collect()
}

fn direction(v: &Value, at: &str) -> Result<DVec3, String> {
    let d = DVec3::from_array(numbers::<3>(v, at)?);
    if d.length_squared() > 0.0 && d.length_squared().is_finite() {
        Ok(d)
    } else {
        Err(bad(at, "must be a non-zero direction"))
    }
}

/// World → eye of a camera at `eye` looking along the unit `dir`, +Y up (right-handed, looking
/// down −Z): the inverse of the eye → world rigid transform, built transposed.
fn look_at(eye: DVec3, dir: DVec3) -> DMat4 {
    let right = dir.cross(DVec3::Y).normalize();
    let up = right.cross(dir);
    let back = -dir;
    DMat4::from_cols(
        DVec4::new(right.x, up.x, back.x, 0.0),
        DVec4::new(right.y, up.y, back.y, 0.0),
        DVec4::new(right.z, up.z, back.z, 0.0),
        DVec4::new(-right.dot(eye), -up.dot(eye), -back.dot(eye), 1.0),
    )
}

/// Reads and checks the path file at `file`.
pub fn read(file: &Path) -> Result<PathFile, String> {
    let name = file.display();
    let text =
        std::fs::read_to_string(file).map_err(|e| format!("cannot read path file {name}: {e}"))?;
    let v: Value =
        serde_json::from_str(&text).map_err(|e| format!("path file {name} is not JSON: {e}"))?;
    parse(&v).map_err(|e| format!("path file {name}: {e}"))
}

/// Checks a path's JSON and builds its cameras.
pub fn parse(v: &Value) -> Result<PathFile, String> {
    const TOP: [&str; 6] = [
        "description",
        "image_height",
        "camera",
        "scene",
        "light_dir",
        "frames",
    ];
    let top = object(v, "", &TOP, &["image_height", "camera", "scene", "frames"])?;
    if let Some(d) = top.get("description") {
        if !d.is_string() {
            return Err(bad("description", "must be a string"));
        }
    }
    let h = &top["image_height"];
    let image_height = h
        .as_u64()
        .filter(|h| (1..=u64::from(u32::MAX)).contains(h))
        .and_then(|h| u32::try_from(h).ok())
        .ok_or_else(|| {
            bad(
                "image_height",
                format!("must be a whole number ≥ 1 (got {h})"),
            )
        })?;
    let cam = object(
        &top["camera"],
        "camera",
        &["near", "far", "half_fov", "aspect"],
        &["near", "far", "half_fov", "aspect"],
    )?;
    let [near, far, half_fov, aspect] =
        ["near", "far", "half_fov", "aspect"].map(|k| number(&cam[k], &join("camera", k)));
    let (near, far, half_fov, aspect) = (near?, far?, half_fov?, aspect?);
    let scene = object(
        &top["scene"],
        "scene",
        &["receivers", "casters"],
        &["receivers"],
    )?;
    let receivers = boxes(&scene["receivers"], "scene.receivers")?;
    if receivers.is_empty() {
        return Err(bad("scene.receivers", "must hold at least one box"));
    }
    let casters = match scene.get("casters") {
        Some(c) => boxes(c, "scene.casters")?,
        None => Vec::new(),
    };
    let light = top
        .get("light_dir")
        .map(|l| direction(l, "light_dir"))
        .transpose()?;
    let list = top["frames"]
        .as_array()
        .filter(|a| !a.is_empty())
        .ok_or_else(|| bad("frames", "must be a non-empty array of frames"))?;
    let mut frames = Vec::with_capacity(list.len());
    for (i, f) in list.iter().enumerate() {
        let at = format!("frames[{i}]");
        let o = object(f, &at, &["eye", "target", "light_dir"], &["eye", "target"])?;
        let eye = DVec3::from_array(numbers::<3>(&o["eye"], &join(&at, "eye"))?);
        let target = DVec3::from_array(numbers::<3>(&o["target"], &join(&at, "target"))?);
        let dir = (target - eye).normalize_or_zero();
        if dir == DVec3::ZERO || dir.cross(DVec3::Y).length() < 1e-6 {
            return Err(bad(
                &join(&at, "target"),
                "must differ from the eye and not lie straight above or below it (the \
                 camera's up is +Y)",
            ));
        }
        let light = match o.get("light_dir") {
            Some(l) => direction(l, &join(&at, "light_dir"))?,
            None => light.ok_or_else(|| {
                bad(
                    &join(&at, "light_dir"),
                    "is needed: give light_dir at the top level (a constant light) or in \
                     every frame",
                )
            })?,
        };
        let camera = Camera::new(look_at(eye, dir), near, far, half_fov, aspect)
            .map_err(|e| bad("camera", e))?;
        frames.push(PathFrame { camera, light });
    }
    Ok(PathFile {
        image_height,
        receivers,
        casters,
        frames,
    })
}
