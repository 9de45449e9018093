//! Reading a request's JSON arguments, each checked by name, and the error a call returns.
//!
//! Numbers arrive as JSON numbers, or as the strings `"NaN"`, `"Infinity"` and `"-Infinity"`
//! (JSON has no non-finite numbers; the JavaScript side writes them so), so that the library
//! sees a NaN and names it, instead of a `null` that hides it.

use serde_json::{Map, Value};
use shadow_aliasing::Error;

/// A call's error as JavaScript receives it: the library's error kind, the argument it names
/// (if any) and the message, the library's own text (`"{name} {reason}"`).
#[derive(Debug, Clone, PartialEq)]
pub struct WebError {
    /// `InvalidArgument`, `NoSolution`, `NoClosedForm`, `Degenerate` or `Request` (a request
    /// the module cannot read: not JSON, an unknown function).
    pub kind: &'static str,
    /// The argument named, for `InvalidArgument`.
    pub name: Option<String>,
    /// The message.
    pub message: String,
}

impl WebError {
    /// An invalid argument `name`, with the library's message form `"{name} {reason}"`.
    pub fn invalid(name: &str, reason: impl std::fmt::Display) -> Self {
        Self {
            kind: "InvalidArgument",
            name: Some(name.to_string()),
            message: format!("{name} {reason}"),
        }
    }

    /// A request the module cannot read.
    pub fn request(message: impl Into<String>) -> Self {
        Self {
            kind: "Request",
            name: None,
            message: message.into(),
        }
    }

    /// The error as JSON: `{"error": {"kind", "name", "message"}}`.
    pub fn to_json(&self) -> String {
        serde_json::json!({
            "error": { "kind": self.kind, "name": self.name, "message": self.message }
        })
        .to_string()
    }
}

impl From<Error> for WebError {
    fn from(e: Error) -> Self {
        let message = e.to_string();
        match e {
            Error::InvalidArgument { name, .. } => Self {
                kind: "InvalidArgument",
                name: Some(name.to_string()),
                message,
            },
            Error::NoSolution(_) => Self {
                kind: "NoSolution",
                name: None,
                message,
            },
            Error::NoClosedForm(_) => Self {
                kind: "NoClosedForm",
                name: None,
                message,
            },
            _ => Self {
                kind: "Degenerate",
                name: None,
                message,
            },
        }
    }
}

/// A call's result.
pub type WebResult<T> = Result<T, WebError>;

/// What a JSON value is, for messages.
pub fn kind(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// An object's fields, every key one of `allowed` (an unknown key is refused by name, so that a
/// misspelt option is never silently ignored).
pub fn object<'a>(name: &str, v: &'a Value, allowed: &[&str]) -> WebResult<&'a Map<String, Value>> {
    let m = v
        .as_object()
        .ok_or_else(|| WebError::invalid(name, format!("must be an object (got {})", kind(v))))?;
    if let Some(k) = m.keys().find(|k| !allowed.contains(&k.as_str())) {
        return Err(WebError::invalid(
            name,
            format!(
                "has an unknown key {k:?} (the keys: {})",
                allowed.join(", ")
            ),
        ));
    }
    Ok(m)
}

/// A field, absent or `null` as `None`.
pub fn field<'a>(m: &'a Map<String, Value>, key: &str) -> Option<&'a Value> {
    m.get(key).filter(|v| !v.is_null())
}

/// A number (any value, finite or not: the library checks domains and names them).
pub fn number(name: &str, v: &Value) -> WebResult<f64> {
    match v {
        Value::Number(n) => n
            .as_f64()
            .ok_or_else(|| WebError::invalid(name, "must be a number")),
        Value::String(s) if s == "NaN" => Ok(f64::NAN),
        Value::String(s) if s == "Infinity" => Ok(f64::INFINITY),
        Value::String(s) if s == "-Infinity" => Ok(f64::NEG_INFINITY),
        _ => Err(WebError::invalid(
            name,
            format!("must be a number (got {})", kind(v)),
        )),
    }
}

/// An optional number field.
pub fn opt_number(m: &Map<String, Value>, key: &str) -> WebResult<Option<f64>> {
    field(m, key).map(|v| number(key, v)).transpose()
}

/// A required number field.
pub fn req_number(m: &Map<String, Value>, key: &str) -> WebResult<f64> {
    opt_number(m, key)?.ok_or_else(|| WebError::invalid(key, "is missing"))
}

/// A whole number in `[0, max]`.
pub fn whole(name: &str, v: &Value, max: u64) -> WebResult<u64> {
    let x = number(name, v)?;
    if x.fract() == 0.0 && (0.0..=max as f64).contains(&x) {
        Ok(x as u64)
    } else {
        Err(WebError::invalid(
            name,
            format!("must be a whole number in [0, {max}] (got {x})"),
        ))
    }
}

/// An optional whole-number field in `[0, max]`.
pub fn opt_whole(m: &Map<String, Value>, key: &str, max: u64) -> WebResult<Option<u64>> {
    field(m, key).map(|v| whole(key, v, max)).transpose()
}

/// An optional `u32` field.
pub fn opt_u32(m: &Map<String, Value>, key: &str) -> WebResult<Option<u32>> {
    Ok(opt_whole(m, key, u64::from(u32::MAX))?.map(|v| v as u32))
}

/// An optional boolean field.
pub fn opt_bool(m: &Map<String, Value>, key: &str) -> WebResult<Option<bool>> {
    field(m, key)
        .map(|v| {
            v.as_bool().ok_or_else(|| {
                WebError::invalid(key, format!("must be a boolean (got {})", kind(v)))
            })
        })
        .transpose()
}

/// An optional string field.
pub fn opt_str<'a>(m: &'a Map<String, Value>, key: &str) -> WebResult<Option<&'a str>> {
    field(m, key)
        .map(|v| {
            v.as_str().ok_or_else(|| {
                WebError::invalid(key, format!("must be a string (got {})", kind(v)))
            })
        })
        .transpose()
}

/// A string that is one of `choices`.
pub fn choice<'c>(name: &str, s: &str, choices: &[&'c str]) -> WebResult<&'c str> {
    choices.iter().find(|c| **c == s).copied().ok_or_else(|| {
        WebError::invalid(
            name,
            format!("must be one of {} (got {s:?})", choices.join(", ")),
        )
    })
}

/// An array of numbers.
pub fn numbers(name: &str, v: &Value) -> WebResult<Vec<f64>> {
    let a = v.as_array().ok_or_else(|| {
        WebError::invalid(
            name,
            format!("must be an array of numbers (got {})", kind(v)),
        )
    })?;
    a.iter()
        .enumerate()
        .map(|(i, x)| number(&format!("{name}[{i}]"), x))
        .collect()
}

/// An array of exactly `n` numbers.
pub fn numbers_n(name: &str, v: &Value, n: usize) -> WebResult<Vec<f64>> {
    let a = numbers(name, v)?;
    if a.len() != n {
        return Err(WebError::invalid(
            name,
            format!("must hold {n} numbers (got {})", a.len()),
        ));
    }
    Ok(a)
}

/// Three numbers.
pub fn vec3(name: &str, v: &Value) -> WebResult<glam::DVec3> {
    let a = numbers_n(name, v, 3)?;
    Ok(glam::DVec3::new(a[0], a[1], a[2]))
}

/// A 4 × 4 matrix from 16 numbers in column-major order (three.js's `Matrix4.elements`).
pub fn mat4(name: &str, v: &Value) -> WebResult<glam::DMat4> {
    let a = numbers_n(name, v, 16)?;
    let mut c = [0.0; 16];
    c.copy_from_slice(&a);
    Ok(glam::DMat4::from_cols_array(&c))
}

/// A number for JSON: finite numbers as numbers, the others as the strings JavaScript's side
/// turns back into numbers.
pub fn num(x: f64) -> Value {
    if x.is_finite() {
        Value::from(x)
    } else if x.is_nan() {
        Value::from("NaN")
    } else if x > 0.0 {
        Value::from("Infinity")
    } else {
        Value::from("-Infinity")
    }
}

/// Numbers for JSON, each by [`num`].
pub fn nums(xs: impl IntoIterator<Item = f64>) -> Value {
    Value::Array(xs.into_iter().map(num).collect())
}
