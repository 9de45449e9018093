//! One row of the contract's table ([`Quantity`]): evaluating it on a request's arguments, and
//! its answer ([`Output`]) as JSON.

use super::args::{parse_arg, quote_key, suggest, ArgSpec, Args, Parsed, Presence};
use crate::error::{fmt_num, Result};
use crate::frustum::NPrime;
use serde_json::{Map, Value};

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
    pub(super) compute: fn(&Args) -> Result<Output>,
}

impl Quantity {
    /// Evaluates this quantity on a request's arguments (the object, `"quantity"` included or
    /// not), checking every argument first.
    ///
    /// # Errors
    /// A message naming the argument that is missing, unknown, of the wrong type, NaN or
    /// infinite, or outside the closed form's domain; or the closed form's own error, which for
    /// a quantity with resolution arguments names them when they scale its (positive) value
    /// below f64's normal range (it would print as 0 or lose its digits).
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
pub(super) fn json_number(v: f64) -> String {
    if v.is_finite() {
        // serde_json prints finite f64 with ryu: the shortest round-trip form.
        serde_json::to_string(&v).unwrap_or_else(|_| format!("{v:?}"))
    } else {
        format!("\"{}\"", fmt_num(v))
    }
}
