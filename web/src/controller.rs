//! The per-frame controller (`shadow_aliasing::plan::Controller`, docs/planning.md "An error
//! budget per frame"): controllers live in the module, by handle, between frames.
//!
//! `controller_new` takes `options` (the library's `ControllerOptions` fields: `max_error`,
//! `max_texels` — at least one — `max_maps`, `rounding` (`"whole"`, `"power-of-two"` or
//! `{multiple: m}`), `max_resolution`, `shared_resolution` (true; false: each map its own
//! resolution), `candidates` (schemes, module `scheme`), `patience`, `margin`,
//! `neighbour_every`, `retry_every`, `cut_move`, `cut_turn`, `cut_light`) and answers `{id}`;
//! `controller_frame` takes `id` and a frame `input` (its scheme, `map_resolution` and
//! `map_resolutions` are the controller's to choose: ignored) and answers the decision, with
//! `resolutions` (each slot's texels a side, what a frame input's `map_resolutions` takes to
//! build the same maps); `controller_cut` and `controller_free`
//! take `id`.

use crate::args::{
    choice, field, num, object, opt_bool, opt_number, opt_str, opt_u32, opt_whole, WebError,
    WebResult,
};
use crate::frame::{frame_json, FrameArgs};
use crate::scheme::{scheme, scheme_json};
use serde_json::{json, Map, Value};
use shadow_aliasing::frame::FrameInput;
use shadow_aliasing::plan::allocate::Rounding;
use shadow_aliasing::plan::{Controller, ControllerOptions};
use std::cell::RefCell;

thread_local! {
    /// The live controllers; a freed handle's slot is `None` (handles are never reused).
    static CONTROLLERS: RefCell<Vec<Option<Controller>>> = const { RefCell::new(Vec::new()) };
}

/// The options' keys.
const OPTION_KEYS: &[&str] = &[
    "max_error",
    "max_texels",
    "max_maps",
    "rounding",
    "max_resolution",
    "shared_resolution",
    "candidates",
    "patience",
    "margin",
    "neighbour_every",
    "retry_every",
    "cut_move",
    "cut_turn",
    "cut_light",
];

/// The controller's options from JSON, over the library's defaults.
fn options(v: &Value) -> WebResult<ControllerOptions> {
    let m = object("options", v, OPTION_KEYS)?;
    let max_error = opt_number(m, "max_error")?;
    let max_texels = opt_whole(m, "max_texels", 1 << 53)?;
    let mut o = match (max_error, max_texels) {
        (Some(e), t) => ControllerOptions {
            max_texels: t,
            ..ControllerOptions::new(e)
        },
        (None, Some(t)) => ControllerOptions::budget(t),
        (None, None) => {
            return Err(WebError::invalid(
                "options",
                "need max_error (pixels), max_texels, or both",
            ))
        }
    };
    if let Some(v) = opt_whole(m, "max_maps", 1 << 20)? {
        o.max_maps = v as usize;
    }
    if let Some(v) = field(m, "rounding") {
        o.rounding = match v {
            Value::Object(_) => {
                let r = object("rounding", v, &["multiple"])?;
                Rounding::Multiple(
                    opt_u32(r, "multiple")?
                        .ok_or_else(|| WebError::invalid("rounding", "is missing multiple"))?,
                )
            }
            _ => match choice(
                "rounding",
                &opt_str(m, "rounding")?.unwrap_or("").replace('_', "-"),
                &["whole", "power-of-two"],
            )? {
                "whole" => Rounding::Whole,
                _ => Rounding::PowerOfTwo,
            },
        };
    }
    if let Some(v) = opt_u32(m, "max_resolution")? {
        o.max_resolution = v;
    }
    if let Some(v) = opt_bool(m, "shared_resolution")? {
        o.shared_resolution = v;
    }
    if let Some(v) = opt_u32(m, "patience")? {
        o.patience = v;
    }
    if let Some(v) = opt_number(m, "margin")? {
        o.margin = v;
    }
    if let Some(v) = opt_u32(m, "neighbour_every")? {
        o.neighbour_every = v;
    }
    if let Some(v) = opt_u32(m, "retry_every")? {
        o.retry_every = v;
    }
    if let Some(v) = opt_number(m, "cut_move")? {
        o.cut_move = v;
    }
    if let Some(v) = opt_number(m, "cut_turn")? {
        o.cut_turn = v;
    }
    if let Some(v) = opt_number(m, "cut_light")? {
        o.cut_light = v;
    }
    Ok(o)
}

/// `controller_new`. The candidates' camera-dependent defaults (TSM's focus, the adaptive
/// planes' light angle) need a camera: give candidates' `focus` explicitly, and use the
/// adaptive partition only through the default candidates.
pub fn new(req: &Map<String, Value>) -> WebResult<Value> {
    let opts = req.get("options").unwrap_or(&Value::Null);
    let mut o = options(opts)?;
    if let Some(c) = opts.as_object().and_then(|m| field(m, "candidates")) {
        let list = c
            .as_array()
            .ok_or_else(|| WebError::invalid("candidates", "must be an array of schemes"))?;
        // A camera for the schemes' defaults that need one: none may be used here.
        let view = shadow_aliasing::ViewFrustum::new(1.0, 2.0, 0.5)?;
        let mut schemes = Vec::with_capacity(list.len());
        for (i, s) in list.iter().enumerate() {
            let needs_camera = s.as_object().is_some_and(|m| {
                (m.get("kind").and_then(Value::as_str) == Some("tsm") && !m.contains_key("focus"))
                    || m.get("partition").and_then(Value::as_str) == Some("adaptive")
                    || m.get("rule").is_some_and(|r| {
                        matches!(r.as_str(), Some("tsm" | "ogre-ortho" | "ogre_ortho"))
                    })
            });
            if needs_camera {
                return Err(WebError::invalid(
                    "candidates",
                    format!(
                        "[{i}] needs the camera for a default (TSM's focus, OGRE's shadow \
                         distance, the adaptive partition's light): give the value"
                    ),
                ));
            }
            let light = glam::DVec3::new(0.0, -1.0, 0.0);
            schemes.push(scheme(s, &view, light)?.to_static()?);
        }
        o.candidates = Some(schemes);
    }
    let c = Controller::new(o)?;
    let id = CONTROLLERS.with_borrow_mut(|v| {
        v.push(Some(c));
        v.len() - 1
    });
    Ok(json!({ "id": id }))
}

/// The handle of a request.
fn id(req: &Map<String, Value>) -> WebResult<usize> {
    let v = field(req, "id").ok_or_else(|| WebError::invalid("id", "is missing"))?;
    Ok(crate::args::whole("id", v, u64::from(u32::MAX))? as usize)
}

/// Runs `f` on the controller `id`.
fn with<T>(
    req: &Map<String, Value>,
    f: impl FnOnce(&mut Controller) -> WebResult<T>,
) -> WebResult<T> {
    let id = id(req)?;
    CONTROLLERS.with_borrow_mut(|v| match v.get_mut(id) {
        Some(Some(c)) => f(c),
        _ => Err(WebError::invalid(
            "id",
            format!("names no live controller (got {id}: freed, or never made)"),
        )),
    })
}

/// `controller_frame`: the decision for this frame.
pub fn frame(req: &Map<String, Value>) -> WebResult<Value> {
    let a = FrameArgs::read(req.get("input").unwrap_or(&Value::Null))?;
    // The resolutions are the controller's to choose: the input's are not read.
    let input = FrameInput {
        map_resolutions: None,
        ..a.input()
    };
    with(req, |c| {
        let d = c.frame(&input)?;
        Ok(json!({
            "scheme": scheme_json(&d.scheme),
            "resolution": d.resolution,
            "resolutions": d.resolutions,
            "max_error_pixels": num(d.max_error_pixels),
            "texels": d.texels,
            "meets_target": d.meets_target,
            "within_budget": d.within_budget,
            "switched": d.switched,
            "cut": d.cut,
            "frame": frame_json(d.frame, a.clip_depth, a.pcf_radius)?,
        }))
    })
}

/// `controller_cut`: the next frame searches afresh.
pub fn cut(req: &Map<String, Value>) -> WebResult<Value> {
    with(req, |c| {
        c.cut();
        Ok(Value::Null)
    })
}

/// `controller_free`: the controller is dropped; its handle names none from now on.
pub fn free(req: &Map<String, Value>) -> WebResult<Value> {
    let id = id(req)?;
    CONTROLLERS.with_borrow_mut(|v| match v.get_mut(id) {
        Some(slot @ Some(_)) => {
            *slot = None;
            Ok(Value::Null)
        }
        _ => Err(WebError::invalid(
            "id",
            format!("names no live controller (got {id}: freed, or never made)"),
        )),
    })
}
