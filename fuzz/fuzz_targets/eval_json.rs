//! Arbitrary bytes into `shadow_aliasing::eval::eval_json`: never a panic, and the output obeys
//! /work/shared/eval-contract.md (docs/eval.md): exit 2 with nothing on stdout and one line on
//! stderr, or JSON answers (an object for an object, an array of the same length for an array),
//! each `{"quantity": NAME, "value": V}` or `{"quantity": NAME, "error": MESSAGE}`, V a finite
//! number, the string "inf", or an array of those; exit 1 exactly when some answer is an error.
#![no_main]

use libfuzzer_sys::fuzz_target;
use serde_json::Value;
use shadow_aliasing::eval::eval_json;

fn check_value(v: &Value) {
    match v {
        Value::Number(n) => {
            let x = n.as_f64().expect("a number that is not an f64");
            assert!(x.is_finite(), "non-finite number {x}");
        }
        Value::String(s) => assert_eq!(s, "inf", "a string value other than \"inf\""),
        Value::Array(items) => {
            for i in items {
                assert!(!i.is_array(), "nested array value");
                check_value(i);
            }
        }
        other => panic!("value of the wrong type: {other}"),
    }
}

/// Checks one answer; returns whether it is an error.
fn check_answer(a: &Value) -> bool {
    let obj = a.as_object().expect("an answer that is not an object");
    assert!(obj.contains_key("quantity"), "answer without quantity: {a}");
    assert!(
        matches!(obj["quantity"], Value::String(_) | Value::Null),
        "quantity not a string: {a}"
    );
    assert_eq!(obj.len(), 2, "answer with other keys: {a}");
    match (obj.get("value"), obj.get("error")) {
        (Some(v), None) => {
            check_value(v);
            false
        }
        (None, Some(Value::String(m))) => {
            assert!(!m.is_empty(), "empty error message");
            true
        }
        _ => panic!("answer with neither one value nor one error: {a}"),
    }
}

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let out = eval_json(text);
    match out.exit_code {
        2 => {
            assert!(out.stdout.is_empty(), "exit 2 with output");
            assert!(!out.stderr.trim().is_empty(), "exit 2 without a message");
            assert_eq!(out.stderr.trim_end().lines().count(), 1, "{}", out.stderr);
        }
        0 | 1 => {
            assert!(out.stderr.is_empty(), "stderr on exit {}", out.exit_code);
            let v: Value = serde_json::from_str(&out.stdout)
                .unwrap_or_else(|e| panic!("output is not JSON ({e}): {}", out.stdout));
            let input: Value = serde_json::from_str(text.trim_start_matches('\u{feff}'))
                .expect("answered input that is not JSON");
            let any_error = match (&input, &v) {
                (Value::Object(_), Value::Object(_)) => check_answer(&v),
                (Value::Array(items), Value::Array(answers)) => {
                    assert_eq!(
                        items.len(),
                        answers.len(),
                        "answers for {} requests",
                        items.len()
                    );
                    answers.iter().fold(false, |e, a| check_answer(a) | e)
                }
                _ => panic!("output shape does not match the input's: {}", out.stdout),
            };
            assert_eq!(out.exit_code, i32::from(any_error), "exit code vs errors");
        }
        c => panic!("exit code {c}"),
    }
});
