//! `measure_map`: the crate's measurement of any world → clip matrix (another engine's cascade,
//! three.js's own) over a slice of the view, as the Bevy integration measures Bevy's cascades
//! (integrations/bevy/src/measure.rs `measure_cascade`): B = the slice `cover` = [z₀, z₁] of the
//! camera's frustum ∩ the receivers (the frame's exact clipping), and M_x, M_z, S̄ of the matrix
//! at B's vertices (`measure::vertex::vertex_max`); the largest error in pixels is
//! max(M_x, M_z) · image_height / map_resolution. The depth row does not enter the error, so any
//! depth convention is measured alike.

use crate::args::{field, mat4, num, numbers, WebError, WebResult};
use crate::frame::FrameArgs;
use serde_json::{json, Map, Value};
use shadow_aliasing::frame::{frame as build_frame, FrameInput, FrameScheme};
use shadow_aliasing::maps::WarpRule;
use shadow_aliasing::measure::vertex::vertex_max;

/// `measure_map`: `input` (a frame input: camera, light, receivers, the matrix's resolution as
/// `map_resolution` — its `map_resolutions` are not read —, image height), `cover` ([z₀, z₁],
/// view depths) and `world_to_clip` (16 numbers, column-major).
/// Answers `{max_error_pixels, max_mx, max_mz, storage_factor}`, or `null` where B is empty (the
/// slice misses the receivers or the camera's [near, far]).
pub fn measure_map(req: &Map<String, Value>) -> WebResult<Value> {
    let a = FrameArgs::read(req.get("input").unwrap_or(&Value::Null))?;
    let cover = numbers(
        "cover",
        field(req, "cover").ok_or_else(|| WebError::invalid("cover", "is missing"))?,
    )?;
    let [z0, z1] = cover[..] else {
        return Err(WebError::invalid(
            "cover",
            format!(
                "must hold two view depths [z0, z1] (got {} numbers)",
                cover.len()
            ),
        ));
    };
    if !(z0.is_finite() && z1.is_finite() && z0 < z1) {
        return Err(WebError::invalid(
            "cover",
            format!("must be finite with z0 < z1 (got [{z0}, {z1}])"),
        ));
    }
    let m = mat4(
        "world_to_clip",
        field(req, "world_to_clip")
            .ok_or_else(|| WebError::invalid("world_to_clip", "is missing"))?,
    )?;
    if !m.is_finite() {
        return Err(WebError::invalid(
            "world_to_clip",
            "must have finite entries",
        ));
    }
    let view = *a.camera.view();
    if z0 >= view.far() || z1 <= view.near() {
        return Ok(Value::Null);
    }
    // One map, of `map_resolution` texels: the input's resolutions per partition are not read.
    let input = FrameInput {
        map_resolutions: None,
        ..a.input()
    }
    .depth_range(z0, z1)
    .scheme(FrameScheme::Single(WarpRule::Uniform))
    .measure(false);
    let f = build_frame(&input)?;
    let Some(map) = f.maps().iter().next() else {
        return Ok(Value::Null);
    };
    let eye_to_clip = m * a.camera.world_to_eye().inverse();
    let e = vertex_max(
        &eye_to_clip,
        f.light_dir_eye(),
        view.tan_half_fov(),
        map.body(),
    )
    .ok_or_else(|| {
        WebError::invalid(
            "world_to_clip",
            "is singular or behind its centre of projection at a vertex of the slice",
        )
    })?;
    Ok(json!({
        "max_error_pixels": num(e.max_mx.max(e.max_mz) * f64::from(a.image_height) / f64::from(a.map_resolution)),
        "max_mx": num(e.max_mx),
        "max_mz": num(e.max_mz),
        "storage_factor": num(e.storage_factor),
    }))
}
