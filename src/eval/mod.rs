//! `shadow-aliasing eval`: every closed form of the crate, evaluated from JSON.
//!
//! This is the language-neutral contract of `docs/eval.md`: a renderer's CI in any language
//! sends requests by name and checks its own numbers against the papers' mathematics.
//!
//! # Shape
//!
//! The input is one JSON object or a JSON array of objects. Each object names a `quantity` and
//! its arguments by name; the answer is `{"quantity": NAME, "value": V}` or
//! `{"quantity": NAME, "error": MESSAGE}`, one answer for an object, an array in the same order
//! for an array. `V` is a number or an array of numbers, printed in the shortest form that
//! parses back to the same `f64`; an infinite value (n′ of an unwarped map) is the string
//! `"inf"`, which is also accepted wherever n′ (or Zhang's λ) is an argument.
//!
//! Exit status ([`EvalOutcome::exit_code`]): 0 when every request was answered with a value,
//! 1 when at least one was answered with an error, 2 when the input is not JSON of this shape at
//! all (message on standard error, nothing on standard output).
//!
//! Every argument is checked against the table [`QUANTITIES`] before any closed form runs:
//! unknown quantities, missing or unknown arguments, wrong types and NaN or infinite values are
//! answered with an error naming the argument; the closed forms then check their own domains and
//! their [`Error`] message (which names the argument too) becomes the answer's `error`.
//!
//! ```
//! use shadow_aliasing::eval::eval_json;
//! let out = eval_json(r#"{"quantity": "n_prime_lispsm", "near": 1, "far": 100}"#);
//! assert_eq!(out.exit_code, 0);
//! assert_eq!(out.stdout, "{\"quantity\":\"n_prime_lispsm\",\"value\":11.0}\n");
//!
//! let out = eval_json(r#"[{"quantity": "n_prime_lispsm", "near": 2, "far": 1}]"#);
//! assert_eq!(out.exit_code, 1);
//! assert!(out.stdout.contains("far must be greater than near (got near=2, far=1)"));
//!
//! assert_eq!(eval_json("not json").exit_code, 2);
//! ```

use crate::error::{fmt_num, Error, Result};
use crate::frustum::{NPrime, Resolutions, ViewFrustum};
use serde_json::{Map, Value};

mod table;
pub use table::{quantity, FALLOFFS, LIGHTS, QUANTITIES, STORAGE_SCHEMES, Z_PARTITION_SCHEMES};

/// What `shadow-aliasing eval` prints and how it exits.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct EvalOutcome {
    /// Standard output: the answers as JSON followed by a newline, or empty when the input is
    /// not JSON of the contract's shape.
    pub stdout: String,
    /// 0: every request answered with a value; 1: at least one answered with an error;
    /// 2: the input is not JSON of the contract's shape.
    pub exit_code: i32,
    /// Standard error: one line saying why the input was rejected (exit 2), otherwise empty.
    pub stderr: String,
}

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

/// What a quantity answers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ValueKind {
    /// One number.
    Number,
    /// One number that may be `"inf"` (an n′).
    NPrime,
    /// An array of numbers.
    Numbers,
}

/// One row of the contract's table: a quantity, its arguments and how it is computed.
#[derive(Debug, Clone, Copy)]
pub struct Quantity {
    /// The name in `"quantity"`.
    pub name: &'static str,
    /// Its arguments, in the order the contract lists them.
    pub args: &'static [ArgSpec],
    /// What it answers.
    pub value: ValueKind,
    /// The paper and equation it implements.
    pub source: &'static str,
    compute: fn(&Args) -> Result<Output>,
}

impl Quantity {
    /// Evaluates this quantity on a request's arguments (the object, `"quantity"` included or
    /// not), checking every argument first.
    ///
    /// # Errors
    /// A message naming the argument that is missing, unknown, of the wrong type, NaN or
    /// infinite, or outside the closed form's domain.
    pub fn evaluate(&self, request: &Map<String, Value>) -> std::result::Result<Output, String> {
        let args = self.parse_args(request)?;
        let out = (self.compute)(&args).map_err(|e| e.to_string())?;
        out.check(self.name)
    }

    fn parse_args(&self, request: &Map<String, Value>) -> std::result::Result<Args, String> {
        for key in request.keys() {
            if key != "quantity" && !self.args.iter().any(|a| a.name == key) {
                let hint = suggest(key, self.args.iter().map(|a| a.name))
                    .map(|s| format!("did you mean {s}? "))
                    .unwrap_or_default();
                return Err(format!(
                    "{} is not an argument of {} ({hint}{} takes {})",
                    quote_key(key),
                    self.name,
                    self.name,
                    self.signature()
                ));
            }
        }
        let mut values = Vec::with_capacity(self.args.len());
        for spec in self.args {
            match request.get(spec.name) {
                None => match spec.presence {
                    Presence::Required => {
                        return Err(format!(
                            "{} is missing ({} takes {})",
                            spec.name,
                            self.name,
                            self.signature()
                        ))
                    }
                    Presence::Default(d) => values.push((spec.name, Parsed::Number(d))),
                    Presence::Optional => {}
                },
                Some(v) => values.push((spec.name, parse_arg(spec, v)?)),
            }
        }
        Ok(Args { values })
    }

    /// The arguments as the contract writes them: `near, far, n_prime, z, [res_image, res_s]`.
    #[must_use]
    pub fn signature(&self) -> String {
        let req: Vec<&str> = self
            .args
            .iter()
            .filter(|a| a.presence == Presence::Required)
            .map(|a| a.name)
            .collect();
        let opt: Vec<&str> = self
            .args
            .iter()
            .filter(|a| a.presence != Presence::Required)
            .map(|a| a.name)
            .collect();
        let mut s = req.join(", ");
        if !opt.is_empty() {
            if !s.is_empty() {
                s.push_str(", ");
            }
            s.push('[');
            s.push_str(&opt.join(", "));
            s.push(']');
        }
        s
    }
}

/// A computed answer.
#[derive(Debug, Clone, PartialEq)]
pub enum Output {
    /// One number.
    Number(f64),
    /// A warp parameter n′, possibly unwarped (printed `"inf"`).
    NPrime(NPrime),
    /// An array of numbers.
    Numbers(Vec<f64>),
}

impl Output {
    /// A value that is not finite is reported, never printed (except n′ = ∞ as `"inf"`).
    fn check(self, quantity: &str) -> std::result::Result<Output, String> {
        let bad = match &self {
            Output::Number(v) => !v.is_finite(),
            // Valid by construction: finite and positive, or ∞.
            Output::NPrime(_) => false,
            Output::Numbers(vs) => vs.iter().any(|v| !v.is_finite()),
        };
        if bad {
            Err(format!(
                "{quantity} could not be computed in f64 for these arguments: the computation \
                 gave {} (an overflow or cancellation, reported rather than printed)",
                self.to_json()
            ))
        } else {
            Ok(self)
        }
    }

    /// The value as JSON text: shortest round-trip numbers, `"inf"` for n′ = ∞.
    #[must_use]
    pub fn to_json(&self) -> String {
        match self {
            Output::Number(v) => json_number(*v),
            Output::NPrime(n) => json_number(n.value()),
            Output::Numbers(vs) => {
                let parts: Vec<String> = vs.iter().map(|v| json_number(*v)).collect();
                format!("[{}]", parts.join(","))
            }
        }
    }
}

/// Shortest representation that parses back to the same `f64`; `"inf"`/`"-inf"`/`"nan"` strings
/// for the non-finite values (only `"inf"` is ever printed in an answer's value).
fn json_number(v: f64) -> String {
    if v.is_finite() {
        // serde_json prints finite f64 with ryu: the shortest round-trip form.
        serde_json::to_string(&v).unwrap_or_else(|_| format!("{v:?}"))
    } else {
        format!("\"{}\"", fmt_num(v))
    }
}

/// An argument after its JSON type was checked.
#[derive(Debug, Clone, PartialEq)]
enum Parsed {
    Number(f64),
    NPrime(NPrime),
    Count(usize),
    Choice(&'static str),
    Numbers(Vec<f64>),
}

/// The arguments of one request, checked against its [`Quantity::args`].
#[derive(Debug, Clone, PartialEq)]
pub struct Args {
    values: Vec<(&'static str, Parsed)>,
}

impl Args {
    fn get(&self, name: &'static str) -> Option<&Parsed> {
        self.values.iter().find(|(n, _)| *n == name).map(|(_, p)| p)
    }
    fn missing(name: &'static str) -> Error {
        Error::invalid(name, "is missing")
    }
    fn num(&self, name: &'static str) -> Result<f64> {
        match self.get(name) {
            Some(Parsed::Number(v)) => Ok(*v),
            _ => Err(Self::missing(name)),
        }
    }
    fn opt_num(&self, name: &'static str) -> Option<f64> {
        match self.get(name) {
            Some(Parsed::Number(v)) => Some(*v),
            _ => None,
        }
    }
    fn n_prime(&self, name: &'static str) -> Result<NPrime> {
        match self.get(name) {
            Some(Parsed::NPrime(v)) => Ok(*v),
            _ => Err(Self::missing(name)),
        }
    }
    fn count(&self, name: &'static str) -> Result<usize> {
        match self.get(name) {
            Some(Parsed::Count(v)) => Ok(*v),
            _ => Err(Self::missing(name)),
        }
    }
    fn choice(&self, name: &'static str) -> Result<&'static str> {
        match self.get(name) {
            Some(Parsed::Choice(v)) => Ok(v),
            _ => Err(Self::missing(name)),
        }
    }
    fn numbers(&self, name: &'static str) -> Result<&[f64]> {
        match self.get(name) {
            Some(Parsed::Numbers(v)) => Ok(v),
            _ => Err(Self::missing(name)),
        }
    }
    /// Resolutions with `res_t` given (`res_s` unused, 1).
    fn res_t(&self) -> Result<Resolutions> {
        Resolutions::new(self.num("res_image")?, 1.0, self.num("res_t")?)
    }
    /// Resolutions with `res_s` given (`res_t` unused, 1).
    fn res_s(&self) -> Result<Resolutions> {
        Resolutions::new(self.num("res_image")?, self.num("res_s")?, 1.0)
    }
    /// The view frustum of `near`, `far`, `half_fov`.
    fn view(&self) -> Result<ViewFrustum> {
        ViewFrustum::new(self.num("near")?, self.num("far")?, self.num("half_fov")?)
    }
}

/// The largest count accepted (a guard against requests that would allocate without bound;
/// the closed forms have their own, smaller limits where they need one).
pub const MAX_COUNT: usize = 1_000_000;

fn describe(v: &Value) -> String {
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

fn parse_arg(spec: &ArgSpec, v: &Value) -> std::result::Result<Parsed, String> {
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
fn suggest<'a>(word: &str, candidates: impl Iterator<Item = &'a str>) -> Option<&'a str> {
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
fn quote_key(key: &str) -> String {
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

// ---------------------------------------------------------------------------------------------
// Requests and answers.

/// The answer to one request.
#[derive(Debug, Clone, PartialEq)]
pub struct Answer {
    /// The requested quantity's name as given, or `None` when the request named none.
    pub quantity: Option<String>,
    /// The value, or the error message.
    pub result: std::result::Result<Output, String>,
}

impl Answer {
    /// `{"quantity":NAME,"value":V}` or `{"quantity":NAME,"error":MESSAGE}`.
    #[must_use]
    pub fn to_json(&self) -> String {
        let q = match &self.quantity {
            Some(name) => Value::String(name.clone()).to_string(),
            None => "null".to_string(),
        };
        match &self.result {
            Ok(v) => format!("{{\"quantity\":{q},\"value\":{}}}", v.to_json()),
            Err(e) => format!(
                "{{\"quantity\":{q},\"error\":{}}}",
                Value::String(e.clone())
            ),
        }
    }
}

fn names_list() -> String {
    QUANTITIES
        .iter()
        .map(|q| q.name)
        .collect::<Vec<_>>()
        .join(", ")
}

/// Answers one request (one JSON value of the input).
#[must_use]
pub fn answer(request: &Value) -> Answer {
    let Value::Object(map) = request else {
        return Answer {
            quantity: None,
            result: Err(format!(
                "each request must be a JSON object naming a quantity (got {})",
                describe(request)
            )),
        };
    };
    let name = match map.get("quantity") {
        None => {
            return Answer {
                quantity: None,
                result: Err(format!(
                    "quantity is missing (name one of: {})",
                    names_list()
                )),
            }
        }
        Some(Value::String(s)) => s.clone(),
        Some(other) => {
            return Answer {
                quantity: None,
                result: Err(format!(
                    "quantity must be a string naming one of: {} (got {})",
                    names_list(),
                    describe(other)
                )),
            }
        }
    };
    let result = match quantity(&name) {
        Some(q) => q.evaluate(map),
        None => {
            let hint = suggest(&name, QUANTITIES.iter().map(|q| q.name))
                .map(|s| format!("did you mean {s}? "))
                .unwrap_or_default();
            Err(format!(
                "quantity {} is unknown ({hint}known: {})",
                Value::String(name.chars().take(60).collect()),
                names_list()
            ))
        }
    };
    Answer {
        quantity: Some(name),
        result,
    }
}

fn rejected(message: String) -> EvalOutcome {
    EvalOutcome {
        stdout: String::new(),
        exit_code: 2,
        stderr: format!("error: {message}\n"),
    }
}

/// Evaluates the text of a request file: the whole of `shadow-aliasing eval`.
///
/// Never panics. An object gives one answer, an array an array of answers in the same order
/// (an element that is not an object is answered with an error); any other input, or text that
/// is not JSON, gives exit status 2 with one line on standard error.
///
/// JSON numbers too large for an `f64` (such as `1e400`) cannot be represented and make the
/// input malformed (exit 2); write `"inf"` for an infinite value. A leading UTF-8 byte-order
/// mark is ignored.
#[must_use]
pub fn eval_json(input: &str) -> EvalOutcome {
    // A byte-order mark (as some editors on Windows write) is not part of the JSON text.
    let input = input.strip_prefix('\u{feff}').unwrap_or(input);
    let value: Value = match serde_json::from_str(input) {
        Ok(v) => v,
        Err(e) => {
            let what = if input.trim().is_empty() {
                "the input is empty: expected a JSON object or an array of objects".to_string()
            } else {
                format!("the input is not valid JSON: {e}")
            };
            return rejected(what);
        }
    };
    match &value {
        Value::Object(_) => {
            let a = answer(&value);
            EvalOutcome {
                stdout: format!("{}\n", a.to_json()),
                exit_code: i32::from(a.result.is_err()),
                stderr: String::new(),
            }
        }
        Value::Array(items) => {
            let answers: Vec<Answer> = items.iter().map(answer).collect();
            let failed = answers.iter().any(|a| a.result.is_err());
            let stdout = if answers.is_empty() {
                "[]\n".to_string()
            } else {
                let lines: Vec<String> = answers
                    .iter()
                    .map(|a| format!("  {}", a.to_json()))
                    .collect();
                format!("[\n{}\n]\n", lines.join(",\n"))
            };
            EvalOutcome {
                stdout,
                exit_code: i32::from(failed),
                stderr: String::new(),
            }
        }
        other => rejected(format!(
            "the input must be a JSON object or an array of objects (got {})",
            describe(other)
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::table::req;
    use super::ArgKind::{Count, Numbers as NumArray};
    use super::*;

    fn one(input: &str) -> (i32, Value) {
        let out = eval_json(input);
        let v: Value = serde_json::from_str(&out.stdout).expect("answer is JSON");
        (out.exit_code, v)
    }

    #[test]
    fn every_quantity_has_distinct_arguments_and_a_source() {
        for q in QUANTITIES {
            assert!(!q.source.is_empty());
            for (i, a) in q.args.iter().enumerate() {
                assert_ne!(a.name, "quantity");
                assert!(
                    q.args[i + 1..].iter().all(|b| b.name != a.name),
                    "{}",
                    q.name
                );
            }
        }
    }

    #[test]
    fn value_kinds_match_what_each_quantity_answers() {
        let reqs: Value =
            serde_json::from_str(include_str!("../../examples/eval-request.json")).unwrap();
        for r in reqs.as_array().unwrap() {
            let map = r.as_object().unwrap();
            let q = quantity(map["quantity"].as_str().unwrap()).unwrap();
            let out = q.evaluate(map).unwrap();
            let kind = match out {
                Output::Number(_) => ValueKind::Number,
                Output::NPrime(_) => ValueKind::NPrime,
                Output::Numbers(_) => ValueKind::Numbers,
            };
            assert_eq!(kind, q.value, "{}", q.name);
        }
    }

    #[test]
    fn numbers_print_shortest_round_trip() {
        for v in [0.1, 1.0 / 3.0, 1e300, 5e-324, -0.0, 11.0, 123456789.0125] {
            let s = json_number(v);
            assert_eq!(s.parse::<f64>().unwrap().to_bits(), v.to_bits(), "{s}");
        }
        assert_eq!(json_number(0.1), "0.1");
        assert_eq!(json_number(f64::INFINITY), "\"inf\"");
    }

    #[test]
    fn argument_errors_name_the_argument() {
        let (code, v) = one(r#"{"quantity":"n_prime_lispsm","near":1}"#);
        assert_eq!(code, 1);
        assert_eq!(
            v["error"],
            "far is missing (n_prime_lispsm takes near, far)"
        );
        let (_, v) = one(r#"{"quantity":"n_prime_lispsm","near":1,"far":2,"nera":3}"#);
        assert_eq!(
            v["error"],
            "nera is not an argument of n_prime_lispsm (did you mean near? n_prime_lispsm takes near, far)"
        );
        let (_, v) = one(r#"{"quantity":"n_prime_lispsm","near":"1","far":2}"#);
        assert_eq!(
            v["error"],
            "near must be a number (got string \"1\"; write it without quotes)"
        );
        let (_, v) = one(r#"{"quantity":"n_prime_lispsm","near":"nan","far":2}"#);
        assert_eq!(v["error"], "near must be a finite number (got NaN)");
        let (_, v) = one(r#"{"quantity":"n_prime_lispsm","near":1,"far":"inf"}"#);
        assert_eq!(v["error"], "far must be a finite number (got inf)");
    }

    #[test]
    fn count_and_choice_and_array_arguments() {
        let spec = req("k", Count);
        assert_eq!(parse_arg(&spec, &Value::from(3.0)), Ok(Parsed::Count(3)));
        assert!(parse_arg(&spec, &Value::from(2.5))
            .unwrap_err()
            .contains("whole"));
        assert!(parse_arg(&spec, &Value::from(0)).is_err());
        assert!(parse_arg(&spec, &Value::from(1e12))
            .unwrap_err()
            .contains("at most"));
        let spec = req("scheme", ArgKind::Choice(Z_PARTITION_SCHEMES));
        assert_eq!(
            parse_arg(&spec, &Value::from("unifrom")).unwrap_err(),
            "scheme must be one of \"self_similar\", \"uniform\", \"practical\", \"adaptive\" \
             (got string \"unifrom\"; did you mean \"uniform\"?)"
        );
        let spec = req("errors", NumArray);
        assert_eq!(
            parse_arg(&spec, &serde_json::json!([1, 2.5])),
            Ok(Parsed::Numbers(vec![1.0, 2.5]))
        );
        assert_eq!(
            parse_arg(&spec, &serde_json::json!([1, "x"])).unwrap_err(),
            "errors must be an array of numbers (errors[1] is string \"x\")"
        );
        let spec = req("n_prime", ArgKind::NPrime);
        assert_eq!(
            parse_arg(&spec, &Value::from("inf")),
            Ok(Parsed::NPrime(NPrime::UNWARPED))
        );
        assert!(parse_arg(&spec, &Value::from(-1.0)).is_err());
        assert!(parse_arg(&spec, &Value::from("-inf")).is_err());
    }

    #[test]
    fn a_byte_order_mark_is_ignored() {
        let out = eval_json("\u{feff}{\"quantity\":\"n_prime_lispsm\",\"near\":1,\"far\":4}");
        assert_eq!(out.exit_code, 0, "{}", out.stderr);
    }

    #[test]
    fn shapes_and_exit_codes() {
        let out = eval_json("[]");
        assert_eq!((out.exit_code, out.stdout.as_str()), (0, "[]\n"));
        let out = eval_json("3");
        assert_eq!(out.exit_code, 2);
        assert!(out.stdout.is_empty());
        assert!(out.stderr.starts_with("error: "));
        let out = eval_json(
            r#"[{"quantity":"n_prime_lispsm","near":1,"far":4}, 7, {"quantity":"nope"}]"#,
        );
        assert_eq!(out.exit_code, 1);
        let v: Value = serde_json::from_str(&out.stdout).unwrap();
        assert_eq!(v[0]["value"], 3.0);
        assert!(v[1]["quantity"].is_null());
        assert!(v[2]["error"]
            .as_str()
            .unwrap()
            .starts_with("quantity \"nope\" is unknown"));
    }
}
