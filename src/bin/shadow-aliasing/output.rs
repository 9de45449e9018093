//! Number formatting shared by the subcommands.

use shadow_aliasing::NPrime;

/// JSON text of a finite number: the shortest form that parses back to the same `f64`.
pub fn json_num(v: f64) -> String {
    if v.is_finite() {
        serde_json::to_string(&v).unwrap_or_else(|_| format!("{v:?}"))
    } else if v == f64::INFINITY {
        "\"inf\"".to_string()
    } else if v == f64::NEG_INFINITY {
        "\"-inf\"".to_string()
    } else {
        "\"nan\"".to_string()
    }
}

/// JSON text of n′: a number, or `"inf"` for the unwarped map.
pub fn json_n_prime(n: NPrime) -> String {
    json_num(n.value())
}

/// A number for people: six significant digits, no trailing zeros.
pub fn sig(v: f64) -> String {
    if !v.is_finite() {
        return if v == f64::INFINITY {
            "∞".into()
        } else {
            format!("{v}")
        };
    }
    let rounded: f64 = format!("{v:.5e}").parse().unwrap_or(v);
    if rounded == 0.0 {
        // No "-0" for people.
        return "0".into();
    }
    let a = rounded.abs();
    if a != 0.0 && !(1e-4..1e9).contains(&a) {
        // Very large or small: keep the exponent form, trimmed.
        let s = format!("{rounded:e}");
        s.replace("e", "·10^")
    } else {
        format!("{rounded}")
    }
}

/// n′ for people.
pub fn sig_n_prime(n: NPrime) -> String {
    match n.as_finite() {
        Some(v) => sig(v),
        None => "∞ (unwarped)".into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats() {
        assert_eq!(json_num(0.1), "0.1");
        assert_eq!(json_num(11.0), "11.0");
        assert_eq!(json_num(f64::INFINITY), "\"inf\"");
        assert_eq!(sig(85.738683464316), "85.7387");
        assert_eq!(sig(11.0), "11");
        assert_eq!(sig(-0.0), "0");
        assert_eq!(sig(-0.000123456789), "-0.000123457");
        assert_eq!(sig(1.5e12), "1.5·10^12");
        assert_eq!(sig_n_prime(NPrime::UNWARPED), "∞ (unwarped)");
    }
}
