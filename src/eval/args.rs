//! The arguments of a request: their specification in the contract's table, and the checks of
//! their JSON types (with the messages that name the argument and suggest a likely spelling).

use crate::error::{fmt_num, Error, Result};
use crate::frustum::{NPrime, Resolutions, ViewFrustum};
use serde_json::Value;

/// The type of one argument, as read from JSON.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ArgKind {
    /// A finite number.
    Number,
    /// A warp parameter: a finite number greater than 0, or the string `"inf"` (unwarped map).
    NPrime,
    /// A whole number ≥ 1 (a count of partitions or subdivisions).
    Count,
    /// One of a fixed set of strings.
    Choice(&'static [&'static str]),
    /// An array of finite numbers.
    Numbers,
}

/// Whether an argument must be present.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Presence {
    /// The request must give it.
    Required,
    /// It may be absent; this value is used then (resolutions default to 1).
    Default(f64),
    /// It may be absent; whether it is needed depends on another argument (for instance
    /// `lambda` of `z_partition` is needed only by the `"practical"` scheme).
    Optional,
}

/// One argument of a quantity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArgSpec {
    /// Its name in the request.
    pub name: &'static str,
    /// Its JSON type.
    pub kind: ArgKind,
    /// Whether it must be given.
    pub presence: Presence,
}

/// An argument after its JSON type was checked.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum Parsed {
    Number(f64),
    NPrime(NPrime),
    Count(usize),
    Choice(&'static str),
    Numbers(Vec<f64>),
}

/// The arguments of one request, checked against its [`Quantity::args`](super::Quantity::args).
#[derive(Debug, Clone, PartialEq)]
pub struct Args {
    pub(super) values: Vec<(&'static str, Parsed)>,
}

impl Args {
    pub(super) fn get(&self, name: &'static str) -> Option<&Parsed> {
        self.values.iter().find(|(n, _)| *n == name).map(|(_, p)| p)
    }
    pub(super) fn missing(name: &'static str) -> Error {
        Error::invalid(name, "is missing")
    }
    pub(super) fn num(&self, name: &'static str) -> Result<f64> {
        match self.get(name) {
            Some(Parsed::Number(v)) => Ok(*v),
            _ => Err(Self::missing(name)),
        }
    }
    pub(super) fn opt_num(&self, name: &'static str) -> Option<f64> {
        match self.get(name) {
            Some(Parsed::Number(v)) => Some(*v),
            _ => None,
        }
    }
    pub(super) fn n_prime(&self, name: &'static str) -> Result<NPrime> {
        match self.get(name) {
            Some(Parsed::NPrime(v)) => Ok(*v),
            _ => Err(Self::missing(name)),
        }
    }
    pub(super) fn count(&self, name: &'static str) -> Result<usize> {
        match self.get(name) {
            Some(Parsed::Count(v)) => Ok(*v),
            _ => Err(Self::missing(name)),
        }
    }
    pub(super) fn choice(&self, name: &'static str) -> Result<&'static str> {
        match self.get(name) {
            Some(Parsed::Choice(v)) => Ok(v),
            _ => Err(Self::missing(name)),
        }
    }
    pub(super) fn numbers(&self, name: &'static str) -> Result<&[f64]> {
        match self.get(name) {
            Some(Parsed::Numbers(v)) => Ok(v),
            _ => Err(Self::missing(name)),
        }
    }
    /// Resolutions with `res_t` given (`res_s` unused, 1).
    pub(super) fn res_t(&self) -> Result<Resolutions> {
        Resolutions::new(self.num("res_image")?, 1.0, self.num("res_t")?)
    }
    /// Resolutions with `res_s` given (`res_t` unused, 1).
    pub(super) fn res_s(&self) -> Result<Resolutions> {
        Resolutions::new(self.num("res_image")?, self.num("res_s")?, 1.0)
    }
    /// The view frustum of `near`, `far`, `half_fov`.
    pub(super) fn view(&self) -> Result<ViewFrustum> {
        ViewFrustum::new(self.num("near")?, self.num("far")?, self.num("half_fov")?)
    }
}

/// The largest count accepted (a guard against requests that would allocate without bound;
/// the closed forms have their own, smaller limits where they need one).
pub const MAX_COUNT: usize = 1_000_000;

pub(super) fn describe(v: &Value) -> String {
    let text = v.to_string();
    let short = if text.chars().count() > 40 {
        let mut s: String = text.chars().take(37).collect();
        s.push_str("...");
        s
    } else {
        text
    };
    let kind = match v {
        Value::Null => return "null".into(),
        Value::Bool(_) => "boolean",
        Value::Number(_) => "number",
        Value::String(_) => "string",
        Value::Array(_) => "array",
        Value::Object(_) => "object",
    };
    format!("{kind} {short}")
}

/// The non-finite spellings accepted as numbers, so that NaN and infinity can be sent (and are
/// then rejected with a message naming the argument, or accepted as n′ = ∞).
fn non_finite_word(s: &str) -> Option<f64> {
    match s.trim().to_ascii_lowercase().as_str() {
        "inf" | "+inf" | "infinity" | "+infinity" => Some(f64::INFINITY),
        "-inf" | "-infinity" => Some(f64::NEG_INFINITY),
        "nan" => Some(f64::NAN),
        _ => None,
    }
}

/// Reads a number, or one of the non-finite words; anything else is a type error.
fn read_number(name: &str, v: &Value) -> std::result::Result<f64, String> {
    match v {
        Value::Number(n) => n
            .as_f64()
            .ok_or_else(|| format!("{name} must be a number (got {})", describe(v))),
        Value::String(s) => non_finite_word(s).ok_or_else(|| {
            format!(
                "{name} must be a number (got {}{})",
                describe(v),
                if s.trim().parse::<f64>().is_ok() {
                    "; write it without quotes"
                } else {
                    ""
                }
            )
        }),
        _ => Err(format!("{name} must be a number (got {})", describe(v))),
    }
}

fn finite_number(name: &str, v: &Value) -> std::result::Result<f64, String> {
    let x = read_number(name, v)?;
    if x.is_finite() {
        Ok(x)
    } else {
        Err(format!(
            "{name} must be a finite number (got {})",
            fmt_num(x)
        ))
    }
}

pub(super) fn parse_arg(spec: &ArgSpec, v: &Value) -> std::result::Result<Parsed, String> {
    let name = spec.name;
    match spec.kind {
        ArgKind::Number => finite_number(name, v).map(Parsed::Number),
        ArgKind::NPrime => {
            let x = read_number(name, v).map_err(|_| {
                format!(
                    "{name} must be a number greater than 0 or the string \"inf\" (got {})",
                    describe(v)
                )
            })?;
            if let Ok(n) = NPrime::new(x) {
                Ok(Parsed::NPrime(n))
            } else {
                Err(format!(
                    "{name} must be a number greater than 0 or the string \"inf\" (got {})",
                    fmt_num(x)
                ))
            }
        }
        ArgKind::Count => {
            let x = finite_number(name, v)?;
            if x.fract() != 0.0 || x < 1.0 {
                Err(format!(
                    "{name} must be a whole number of at least 1 (got {})",
                    fmt_num(x)
                ))
            } else if x > MAX_COUNT as f64 {
                Err(format!(
                    "{name} must be at most {MAX_COUNT} (got {})",
                    fmt_num(x)
                ))
            } else {
                // Whole, in [1, MAX_COUNT]: the conversion is exact.
                Ok(Parsed::Count(x as usize))
            }
        }
        ArgKind::Choice(options) => {
            let list = options
                .iter()
                .map(|o| format!("\"{o}\""))
                .collect::<Vec<_>>()
                .join(", ");
            match v {
                Value::String(s) => match options.iter().find(|o| **o == s.as_str()) {
                    Some(o) => Ok(Parsed::Choice(o)),
                    None => {
                        let hint = suggest(s, options.iter().copied())
                            .map(|h| format!("; did you mean \"{h}\"?"))
                            .unwrap_or_default();
                        Err(format!(
                            "{name} must be one of {list} (got {}{hint})",
                            describe(v)
                        ))
                    }
                },
                _ => Err(format!(
                    "{name} must be one of the strings {list} (got {})",
                    describe(v)
                )),
            }
        }
        ArgKind::Numbers => match v {
            Value::Array(items) => items
                .iter()
                .enumerate()
                .map(|(i, item)| {
                    let x = read_number(name, item).map_err(|_| {
                        format!(
                            "{name} must be an array of numbers ({name}[{i}] is {})",
                            describe(item)
                        )
                    })?;
                    if x.is_finite() {
                        Ok(x)
                    } else {
                        Err(format!(
                            "{name} must hold finite numbers ({name}[{i}] is {})",
                            fmt_num(x)
                        ))
                    }
                })
                .collect::<std::result::Result<Vec<f64>, String>>()
                .map(Parsed::Numbers),
            _ => Err(format!(
                "{name} must be an array of numbers (got {})",
                describe(v)
            )),
        },
    }
}

/// Levenshtein distance, for "did you mean" hints.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = vec![i + 1; b.len() + 1];
        for (j, cb) in b.iter().enumerate() {
            let sub = prev[j] + usize::from(ca != *cb);
            cur[j + 1] = sub.min(prev[j + 1] + 1).min(cur[j] + 1);
        }
        prev = cur;
    }
    prev[b.len()]
}

/// The closest candidate, if it is close enough to be a likely typo.
pub(super) fn suggest<'a>(
    word: &str,
    candidates: impl Iterator<Item = &'a str>,
) -> Option<&'a str> {
    if word.chars().count() > 64 {
        return None;
    }
    candidates
        .map(|c| (edit_distance(word, c), c))
        .filter(|(d, c)| *d <= 2.max(c.len() / 4) && *d < c.len())
        .min_by_key(|(d, _)| *d)
        .map(|(_, c)| c)
}

/// A key as it appears in a message: bare when it looks like a name, JSON-quoted otherwise.
pub(super) fn quote_key(key: &str) -> String {
    let plain = !key.is_empty()
        && key.len() <= 40
        && key.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if plain {
        key.to_string()
    } else {
        let s = Value::String(key.chars().take(40).collect()).to_string();
        if key.chars().count() > 40 {
            format!("{s}...")
        } else {
            s
        }
    }
}
