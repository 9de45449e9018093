//! WebAssembly bindings of shadow-aliasing for JavaScript (docs/web.md).
//!
//! The module takes one JSON request per call and answers JSON ([`call`]): no wasm-bindgen, so
//! no CLI whose version must match; four raw exports over linear memory (module `abi`) carry
//! the bytes, and web/npm/index.js wraps them in a typed JavaScript API (index.d.ts). A request
//! is `{"fn": NAME, …}` with NAME one of [`FUNCTIONS`]; the answer is `{"ok": VALUE}` or
//! `{"error": {"kind", "name", "message"}}` with the library's message, which the JavaScript
//! side throws as a `ShadowAliasingError`.

pub mod abi;
pub mod args;
pub mod closed;
pub mod controller;
pub mod frame;
pub mod measure;
pub mod scheme;

use args::{WebError, WebResult};
use serde_json::Value;

/// The functions a request may name.
pub const FUNCTIONS: &[&str] = &[
    "frame",
    "error_lens",
    "measure_map",
    "lens_colour",
    "closed",
    "controller_new",
    "controller_frame",
    "controller_cut",
    "controller_free",
    "version",
];

/// One request answered: `Ok` with the answer's JSON, `Err` with the error's JSON.
pub fn call(request: &str) -> Result<String, String> {
    answer(request)
        .map(|v| serde_json::json!({ "ok": v }).to_string())
        .map_err(|e| e.to_json())
}

/// [`call`]'s value.
fn answer(request: &str) -> WebResult<Value> {
    let v: Value = serde_json::from_str(request)
        .map_err(|e| WebError::request(format!("the request is not JSON: {e}")))?;
    let m = v
        .as_object()
        .ok_or_else(|| WebError::request("the request must be a JSON object {\"fn\": …}"))?;
    let name = m.get("fn").and_then(Value::as_str).ok_or_else(|| {
        WebError::request(format!(
            "the request needs \"fn\", one of {}",
            FUNCTIONS.join(", ")
        ))
    })?;
    match name {
        "frame" => frame::frame(m),
        "error_lens" => frame::error_lens(m),
        "measure_map" => measure::measure_map(m),
        "lens_colour" => frame::lens_colour(m),
        "closed" => closed::closed(m),
        "controller_new" => controller::new(m),
        "controller_frame" => controller::frame(m),
        "controller_cut" => controller::cut(m),
        "controller_free" => controller::free(m),
        "version" => Ok(Value::from(env!("CARGO_PKG_VERSION"))),
        other => Err(WebError::request(format!(
            "unknown function {other:?} (one of {})",
            FUNCTIONS.join(", ")
        ))),
    }
}
