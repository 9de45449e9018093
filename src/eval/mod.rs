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
//! their [`Error`](crate::Error) message (which names the argument too) becomes the answer's `error`.
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

use serde_json::Value;

mod args;
mod quantity;
mod table;
use args::{describe, suggest};
pub use args::{ArgKind, ArgSpec, Args, Presence, MAX_COUNT};
pub use quantity::{Output, Quantity, ValueKind};
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
    use super::args::{parse_arg, Parsed};
    use super::quantity::json_number;
    use super::table::req;
    use super::ArgKind::{Count, Numbers as NumArray};
    use super::*;
    use crate::frustum::NPrime;

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
