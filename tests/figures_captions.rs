//! Every number a figure's caption prints, recomputed here from the papers' equations.
//!
//! Each figure's SVG is rendered, its caption (the grey paragraph at the bottom) read back with
//! its superscripts and subscripts, and every number in it listed in order. For each figure this
//! file holds the same list: a number the caption takes as given (a year, a figure, equation or
//! section number, a parameter of the configuration drawn) with the reason, or a value the caption
//! states, computed here from the paper's equation (written out in this file, not the crate's
//! function) and compared to the printed digits. A number added to a caption without its
//! derivation here, a number typed wrong, or a formula whose value is not the printed one, fails.
#![cfg(feature = "plot")]

use shadow_aliasing::plot::{render, Format, FIGURES};
use std::path::{Path, PathBuf};

/// A fresh directory per test and per process.
fn out_dir(sub: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("{sub}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

/// The caption of `name`'s SVG as one line of text: its lines joined by spaces, a superscript
/// written `^{…}`, a subscript `_{…}`, XML entities decoded.
fn caption(name: &str) -> String {
    let dir = out_dir(&format!("captions-{name}"));
    render(name, &dir, Format::Svg).unwrap();
    let svg = std::fs::read_to_string(dir.join(format!("{name}.svg"))).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    let mut lines = Vec::new();
    let mut rest = svg.as_str();
    while let Some(i) = rest.find("<text ") {
        let open_end = i + rest[i..].find('>').unwrap();
        let close = open_end + rest[open_end..].find("</text>").unwrap();
        if rest[i..open_end].contains("fill=\"#323232\"") {
            lines.push(read_text(&rest[open_end + 1..close]));
        }
        rest = &rest[close..];
    }
    assert!(!lines.is_empty(), "{name}: no caption found");
    // A no-break space (inside a formula) reads as a space.
    lines.join(" ").replace('\u{a0}', " ")
}

/// The content of one `<text>`: `<tspan dy="-…" font-size=…>` is a superscript, a positive `dy`
/// with a font size a subscript; the `<tspan dy=…>` without a size that follows returns to the
/// baseline.
fn read_text(inner: &str) -> String {
    let mut out = String::new();
    let mut rest = inner;
    while let Some(i) = rest.find("<tspan") {
        out.push_str(&rest[..i]);
        let tag_end = i + rest[i..].find('>').unwrap();
        let tag = &rest[i..tag_end];
        let close = tag_end + rest[tag_end..].find("</tspan>").unwrap();
        let body = &rest[tag_end + 1..close];
        if tag.contains("font-size") {
            let up = tag.contains("dy=\"-");
            out.push_str(if up { "^{" } else { "_{" });
            out.push_str(body);
            out.push('}');
        } else {
            out.push_str(body);
        }
        rest = &rest[close + "</tspan>".len()..];
    }
    out.push_str(rest);
    out.replace("&apos;", "'")
        .replace("&quot;", "\"")
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&")
}

/// The numbers of `text` in order, as printed: an optional minus sign (U+2212 or `-`) directly
/// before the digits, a decimal part, and a power of ten `×10^{e}` (or a bare `10^{e}`) joined to
/// its mantissa.
fn numbers(text: &str) -> Vec<String> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        if !chars[i].is_ascii_digit() {
            i += 1;
            continue;
        }
        let mut start = i;
        if i > 0 && (chars[i - 1] == '\u{2212}' || chars[i - 1] == '-') {
            // A sign only when the minus is not a binary operator between two operands.
            let before = if i > 1 { chars[i - 2] } else { ' ' };
            if before == ' ' || before == '(' || before == '{' {
                start = i - 1;
            }
        }
        while i < chars.len() && chars[i].is_ascii_digit() {
            i += 1;
        }
        if i + 1 < chars.len() && chars[i] == '.' && chars[i + 1].is_ascii_digit() {
            i += 1;
            while i < chars.len() && chars[i].is_ascii_digit() {
                i += 1;
            }
        }
        // ×10^{e} after a mantissa, or ^{e} after a bare 10.
        let tail: String = chars[i..chars.len().min(i + 12)].iter().collect();
        let mantissa: String = chars[start..i].iter().collect();
        let power = if let Some(t) = tail.strip_prefix("×10^{") {
            Some(("×10^{".chars().count(), t))
        } else if mantissa == "10" {
            tail.strip_prefix("^{").map(|t| (2, t))
        } else {
            None
        };
        if let Some((skip, t)) = power {
            let digits: String = t
                .chars()
                .take_while(|c| c.is_ascii_digit() || *c == '\u{2212}')
                .collect();
            if !digits.is_empty() && t[digits.len()..].starts_with('}') {
                i += skip + digits.chars().count() + 1;
            }
        }
        out.push(chars[start..i].iter().collect());
    }
    out
}

/// The value of a printed number (`numbers`' format).
fn value(printed: &str) -> f64 {
    let s = printed.replace('\u{2212}', "-");
    if let Some((m, e)) = s.split_once("×10^{") {
        return m.parse::<f64>().unwrap() * 10f64.powf(e.trim_end_matches('}').parse().unwrap());
    }
    if let Some(e) = s.strip_prefix("10^{") {
        return 10f64.powf(e.trim_end_matches('}').parse().unwrap());
    }
    s.parse().unwrap()
}

/// Half a unit in the last printed place of `printed`: the most a correctly rounded number is
/// off its value.
fn half_ulp(printed: &str) -> f64 {
    let s = printed.replace('\u{2212}', "-");
    let (m, scale) = match s.split_once("×10^{") {
        Some((m, e)) => (
            m.to_string(),
            10f64.powf(e.trim_end_matches('}').parse().unwrap()),
        ),
        None => (s.clone(), 1.0),
    };
    let decimals = m.split_once('.').map_or(0, |(_, d)| d.len());
    0.5 * 10f64.powi(-(decimals as i32)) * scale
}

/// What a caption's number is.
enum N {
    /// Taken as given: a reference (year, figure, equation, section) or a parameter of the
    /// configuration drawn; the text is the reason.
    Given(&'static str),
    /// A value the caption states, computed in this file.
    Value(f64),
    /// A value the caption prints as `formula = value`: the formula as printed, and its value
    /// computed in this file from the paper's equation (not from the formula's text).
    Formula(&'static str, f64),
    /// A value measured by the figure's own sweep or construction, which this file does not
    /// repeat: listed as printed (so that a change shows here), the text naming the unit test
    /// that checks it against an independent computation where one does.
    Measured(&'static str),
}

/// Checks `name`'s caption against `want`: the same numbers in the same order, each `Given` one
/// printed as listed and each `Value` printed correctly rounded.
fn check(name: &str, want: &[(&str, N)]) {
    let text = caption(name);
    let got = numbers(&text);
    let listed: Vec<&str> = want.iter().map(|(p, _)| *p).collect();
    let why: Vec<String> = want
        .iter()
        .map(|(p, n)| match n {
            N::Given(reason) => format!("{p}: {reason}"),
            N::Value(v) => format!("{p}: computed {v}"),
            N::Formula(f, v) => format!("{p}: {f} = {v}"),
            N::Measured(how) => format!("{p}: measured, {how}"),
        })
        .collect();
    assert_eq!(
        got, listed,
        "{name}: the caption's numbers differ from this file's list\ncaption: {text}\n\
         listed: {why:#?}"
    );
    for (printed, n) in want {
        let v = match n {
            N::Given(_) | N::Measured(_) => continue,
            N::Value(v) => v,
            N::Formula(formula, v) => {
                assert!(
                    text.contains(&format!("{formula} = {printed}")),
                    "{name}: the caption does not print {formula} = {printed}\ncaption: {text}"
                );
                v
            }
        };
        {
            let p = value(printed);
            assert!(
                (p - v).abs() <= half_ulp(printed) * (1.0 + 1e-9),
                "{name}: the caption prints {printed}, the equation gives {v}\ncaption: {text}"
            );
        }
    }
}

/// The reader itself: superscripts join their mantissa, minus signs and operators are told
/// apart, and a number is compared to its printed precision.
#[test]
fn numbers_are_read_as_printed() {
    assert_eq!(
        numbers("S = 8.65×10^{5} to 2×10^{6}; 10^{4}, α^{1/k} − 1, (−0.5) and 1.5×"),
        vec!["8.65×10^{5}", "2×10^{6}", "10^{4}", "1", "1", "−0.5", "1.5"]
    );
    assert_eq!(value("8.65×10^{5}"), 865_000.0);
    assert_eq!(value("10^{4}"), 10_000.0);
    assert_eq!(half_ulp("2.15"), 0.005);
    assert_eq!(half_ulp("8.65×10^{5}"), 500.0);
    assert_eq!(
        read_text("a<tspan dy=\"-4\" font-size=\"8\">i/k</tspan><tspan dy=\"4\">, z</tspan><tspan dy=\"2\" font-size=\"8\">i</tspan><tspan dy=\"-2\"> &amp;</tspan>"),
        "a^{i/k}, z_{i} &"
    );
}

/// Lloyd 2005 Eq 7 normalised at k = 1: m_max(k)/m_max(1) with a = α^{1/k},
/// k (a − 1)(1 + |ξ|(√a − 1))/√a over the same at k = 1 (θ and the resolutions cancel).
fn lloyd2005_eq7_ratio(alpha: f64, k: f64, xi: f64) -> f64 {
    let m = |k: f64| {
        let a = alpha.powf(1.0 / k);
        k * (a - 1.0) * (1.0 + xi.abs() * (a.sqrt() - 1.0)) / a.sqrt()
    };
    m(k) / m(1.0)
}

/// lloyd2005-fig7: the gains at α = f/n = 100 from Eq 7, and the ξ = 0 bound as k → ∞: the
/// caption's formula (f/n − 1)/(√(f/n) ln(f/n)), i.e. (α − 1)/(√α ln α), which must be the limit
/// of Eq 7's gain (here at k = 10⁸; the inverse, √α ln α/(α − 1), is 0.465).
#[test]
fn lloyd2005_fig7() {
    let alpha = 100.0;
    let gain = |k: f64, xi: f64| 1.0 / lloyd2005_eq7_ratio(alpha, k, xi);
    let limit = gain(1e8, 0.0);
    assert!(
        (limit - (alpha - 1.0) / (alpha.sqrt() * alpha.ln())).abs() < 1e-5,
        "{limit}"
    );
    check(
        "lloyd2005-fig7",
        &[
            ("2005", N::Given("the report's year")),
            ("7", N::Given("its figure")),
            ("7", N::Given("its equation")),
            ("1", N::Given("normalised at k = 1")),
            ("0", N::Given("ξ = 0")),
            ("1", N::Given("|ξ| = 1")),
            ("4", N::Given("ξ: Eq 4's warp parameter")),
            ("0", N::Given("ξ = 0: LiSPSM")),
            ("1", N::Given("ξ = 1: PSM")),
            ("−1", N::Given("ξ = −1: the uniform map")),
            (
                "5",
                N::Given("the report's \"nearly 5 times\" (its Fig. 9)"),
            ),
            ("100", N::Given("the f/n (the report's α) of its Fig. 9")),
            ("9", N::Given("the report's Fig. 9")),
            ("1", N::Given("|ξ| = 1")),
            ("5.5", N::Value(gain(2.0, 1.0))),
            ("2", N::Given("k = 2")),
            ("0", N::Given("ξ = 0")),
            ("1.74", N::Value(gain(2.0, 0.0))),
            ("1", N::Given("the 1 of the formula f/n − 1")),
            ("2.15", N::Formula("(f/n − 1)/(√(f/n) ln(f/n))", limit)),
        ],
    );
}

/// lloyd2005-fig4: g₀ = 1/√α (Eq 3 at n = 1 + √α on either plane) at α = 10.
#[test]
fn lloyd2005_fig4() {
    let alpha: f64 = 10.0;
    check(
        "lloyd2005-fig4",
        &[
            ("2005", N::Given("the report's year")),
            ("4", N::Given("its figure")),
            ("3", N::Given("Eq 3")),
            ("4", N::Given("Eq 4")),
            (
                "10",
                N::Given("f/n (the report's α), which the report does not print"),
            ),
            ("1", N::Given("ξ = 1")),
            ("0", N::Given("ξ = 0")),
            ("1", N::Given("n′ = 1 + √(f/n)")),
            ("−1", N::Given("ξ = −1 (½ and −½ are not digits)")),
            ("0", N::Given("g₀")),
            ("1", N::Given("1/√(f/n)")),
            ("0.316", N::Value(1.0 / alpha.sqrt())),
            ("0", N::Given("ξ ≤ 0")),
            ("0", N::Given("ξ > 0")),
        ],
    );
}

/// lloyd2006-fig5 prints only its configuration.
#[test]
fn lloyd2006_fig5() {
    check(
        "lloyd2006-fig5",
        &[
            ("2006", N::Given("the paper's year")),
            ("5", N::Given("its figure")),
            ("7", N::Given("Eq 7")),
            ("8", N::Given("Eq 8")),
            ("1", N::Given("n")),
            ("20", N::Given("f")),
            ("2", N::Given("the formula's 2 tan θ")),
            // LiSPSM's n′ = n + √(fn) at n = 1, f = 20.
            ("5.47", N::Value(1.0 + 20f64.sqrt())),
        ],
    );
}

/// lloyd2006-fig6 prints only its configuration.
#[test]
fn lloyd2006_fig6() {
    check(
        "lloyd2006-fig6",
        &[
            ("2006", N::Given("the paper's year")),
            ("6", N::Given("its figure")),
            ("9", N::Given("Eq 9")),
            ("12", N::Given("to Eq 12")),
            ("1", N::Given("n")),
            ("100", N::Given("f")),
            ("30", N::Given("θ")),
            ("−1", N::Given("η = −1, where all three are largest")),
            // The maxima at η = −1 (n′ = ∞, Eq 9, 10, 12): M_x = f/n, M_z = (f − n)/(2 tan θ),
            // S̄ their product.
            ("100", N::Value(100.0)),
            ("85.74", N::Value(99.0 / (2.0 * 30f64.to_radians().tan()))),
            (
                "8574",
                N::Value(100.0 * 99.0 / (2.0 * 30f64.to_radians().tan())),
            ),
            ("0", N::Given("η ≤ 0")),
            ("4.3", N::Given("§4.3")),
            ("0", N::Given("η = 0")),
        ],
    );
}

/// lloyd2006-fig10: the optimal logarithmic S̄ = ln(f/n)/(2 tan θ) (App. C) at θ = 30°.
#[test]
fn lloyd2006_fig10() {
    let opt = |r: f64| r.ln() / (2.0 * 30f64.to_radians().tan());
    check(
        "lloyd2006-fig10",
        &[
            ("2006", N::Given("the paper's year")),
            ("10", N::Given("its figure")),
            ("18", N::Given("Eq 18")),
            ("30", N::Given("θ")),
            ("1", N::Given("the exponent 1/k")),
            ("1", N::Given("the formula's − 1")),
            ("2", N::Given("the formula's 2 tan θ")),
            ("2", N::Given("the formula's 2 tan θ")),
            ("1.99", N::Value(opt(10.0))),
            ("3.99", N::Value(opt(100.0))),
            ("5.98", N::Value(opt(1000.0))),
            ("7.98", N::Value(opt(10_000.0))),
            ("10", N::Given("the smallest f/n drawn")),
            ("10^{4}", N::Given("the largest f/n drawn")),
        ],
    );
}

/// Lloyd 2006 with the light behind, f/n = `r`: ZP with k maps, k (f/n)^{2/k} (Eq 20), and
/// FP+ZP+W with k z-partitions per face (4k + 1 maps), four faces of ZP+W at 45° plus the near
/// face: 4 k((f/n)^{1/k} − 1)/(2 tan 45°) + 1 (Eq 21 with Eq 18).
fn behind_zp(r: f64, k: f64) -> f64 {
    k * r.powf(2.0 / k)
}

fn behind_fp(r: f64, k: f64) -> f64 {
    4.0 * k * (r.powf(1.0 / k) - 1.0) / (2.0 * 45f64.to_radians().tan()) + 1.0
}

/// lloyd2006-fig12: the light-behind values at 13 and 17 maps (k = 3 and 4 per face).
#[test]
fn lloyd2006_fig12() {
    let r = 1000.0;
    check(
        "lloyd2006-fig12",
        &[
            ("2006", N::Given("the paper's year")),
            ("12", N::Given("its figure")),
            ("17", N::Given("Eq 17")),
            ("21", N::Given("to Eq 21")),
            ("1000", N::Given("f/n")),
            ("30", N::Given("θ")),
            ("4", N::Given("4k + 1 maps")),
            ("1", N::Given("4k + 1 maps")),
            // Seen from behind, a face's triangle has base 2f tan θ and height f tan θ: its
            // sub-frustum's tan θ_eff = (f tan θ)/(f tan θ) = 1, 45°, whatever θ.
            ("1", N::Value(1.0)),
            ("45", N::Value(1f64.atan().to_degrees())),
            ("21", N::Given("Eq 21")),
            // Unwarped, one map overhead: M_x M_z = (f/n)(f/n − 1)/(2 tan θ).
            (
                "8.65×10^{5}",
                N::Value(r * (r - 1.0) / (2.0 * 30f64.to_radians().tan())),
            ),
            ("10^{6}", N::Value(behind_zp(r, 1.0))),
            ("13", N::Value(4.0 * 3.0 + 1.0)),
            ("37.6", N::Value(behind_zp(r, 13.0))),
            ("55.0", N::Value(behind_fp(r, 3.0))),
            ("17", N::Value(4.0 * 4.0 + 1.0)),
            ("37.99", N::Value(behind_fp(r, 4.0))),
            ("38.32", N::Value(behind_zp(r, 17.0))),
        ],
    );
}

/// lloyd2006-fig13: the f/n where ZP with 17 maps and FP+ZP+W with 4 per face are equal behind,
/// by bisection on ln(f/n) here.
#[test]
fn lloyd2006_fig13() {
    let diff = |ln_r: f64| behind_zp(ln_r.exp(), 17.0) - behind_fp(ln_r.exp(), 4.0);
    let (mut a, mut b) = (2f64.ln(), 1e6f64.ln());
    assert!(diff(a).signum() != diff(b).signum());
    for _ in 0..100 {
        let m = 0.5 * (a + b);
        if diff(m).signum() == diff(a).signum() {
            a = m;
        } else {
            b = m;
        }
    }
    check(
        "lloyd2006-fig13",
        &[
            ("2006", N::Given("the paper's year")),
            ("13", N::Given("its figure")),
            ("20", N::Given("Eq 20")),
            ("21", N::Given("Eq 21")),
            ("4", N::Given("j = 4k + 1")),
            ("1", N::Given("j = 4k + 1")),
            ("17", N::Value(4.0 * 4.0 + 1.0)),
            ("1050", N::Value(a.exp())),
            ("20", N::Given("Eq 20")),
            ("21", N::Given("Eq 21")),
            // tan θ_eff of the face sub-frusta, as in lloyd2006_fig12 (by hand: 1).
            ("1", N::Value(1.0)),
        ],
    );
}

/// barroso-fig5: the self-similar split planes z_i = n (f/n)^{i/k} (Eq 5) and the adaptive ones
/// of Eq 19, z_{i−1} = λ n (z_i/n)^{(i−1)/i} + (1 − λ) z_i/α from z_k = f down, λ = γ/(π/2),
/// at n = 1, f = 100, k = 4, γ = 45°, α = 2.
#[test]
fn barroso_fig5() {
    let (n, f, k) = (1.0f64, 100.0f64, 4);
    let ss: Vec<f64> = (0..=k)
        .map(|i| n * (f / n).powf(f64::from(i) / 4.0))
        .collect();
    let (lambda, alpha) = (45.0 / 90.0, 2.0);
    let mut ad = vec![f; k as usize + 1];
    ad[0] = n;
    for i in (2..=k as usize).rev() {
        let zi = ad[i];
        ad[i - 1] =
            lambda * n * (zi / n).powf((i as f64 - 1.0) / i as f64) + (1.0 - lambda) * zi / alpha;
    }
    check(
        "barroso-fig5",
        &[
            ("2007", N::Given("the paper's year")),
            ("5", N::Given("its figure")),
            ("4", N::Given("k")),
            ("1", N::Given("n")),
            ("100", N::Given("f")),
            ("30", N::Given("θ, the half field of view")),
            ("5", N::Given("Eq 5")),
            ("1", N::Value(ss[0])),
            ("3.162", N::Value(ss[1])),
            ("10", N::Value(ss[2])),
            ("31.62", N::Value(ss[3])),
            ("100", N::Value(ss[4])),
            ("45", N::Given("the light's angle γ to the view direction")),
            ("2", N::Given("Eq 19's α, the scheme's ADAPTIVE_RATIO")),
            ("19", N::Given("Eq 19")),
            ("1", N::Value(ad[0])),
            ("6.041", N::Value(ad[1])),
            ("16.13", N::Value(ad[2])),
            ("40.81", N::Value(ad[3])),
            ("100", N::Value(ad[4])),
        ],
    );
}

/// barroso-fig7 prints only its configuration and the window of (b).
#[test]
fn barroso_fig7() {
    check(
        "barroso-fig7",
        &[
            ("2007", N::Given("the paper's year")),
            ("7", N::Given("its figure")),
            ("13", N::Given("Eq 13")),
            ("18", N::Given("to Eq 18")),
            ("1", N::Given("n")),
            ("100", N::Given("f")),
            ("30", N::Given("θ = 30° (the paper's φ_y)")),
            ("1", N::Given("n′₁, Eq 13's first branch")),
            ("2", N::Given("n′₂, its second")),
            ("13", N::Given("Eq 13")),
            ("15", N::Given("γ_lim's Eq 15")),
            ("1", N::Given("n′₁ in Eq 16's n′₁(γ_lim)/r(γ)")),
            ("18", N::Given("Barroso's fall-off, Eq 18")),
            ("17", N::Given("Zhang's, Eq 17")),
            ("1", N::Given("n′₁ above γ_lim")),
            ("18", N::Given("is Eq 18's curve")),
            ("1", N::Given("n′₁, least max m_z along the view axis")),
            ("12", N::Given("Barroso's Eq 12, m_z along the view axis")),
            ("20", N::Given("(b) from γ = 20°")),
            ("45", N::Given("to 45°")),
        ],
    );
}

/// lloyd2005-fig8 prints its configuration and, for (d), the two errors after allocation M_x/w
/// (the sixth review, R6-lloyd2005-fig8-5), both from the figure's own layout.
#[test]
fn lloyd2005_fig8() {
    check(
        "lloyd2005-fig8",
        &[
            ("2005", N::Given("the report's year")),
            ("8", N::Given("its figure")),
            ("2", N::Given("k")),
            (
                "10",
                N::Given("f/n, the report's α (its n is the warp's, n′ here)"),
            ),
            ("30", N::Given("θ")),
            ("35", N::Given("the light's elevation")),
            ("10", N::Given("the light's azimuth from straight behind")),
            ("2", N::Given("the partition R2 of panel (b)")),
            ("6", N::Given("Eq 6")),
            ("1", N::Given("the partition R1 of (d)'s sentence")),
            ("2", N::Given("the partition R2 of (d)'s sentence")),
            (
                "4.09",
                N::Measured(
                    "R1's M_x/w; Eq 6's M_x · Σ/(its column's largest M_x) in \
                     table_after_is_the_sum_of_the_columns_m_x (src/plot/layout/table.rs)",
                ),
            ),
            (
                "4.30",
                N::Measured(
                    "the others' M_x/w, Σ of the columns' largest M_x (1.56 + 1.76 + 0.98) in \
                     table_after_is_the_sum_of_the_columns_m_x (src/plot/layout/table.rs)",
                ),
            ),
        ],
    );
}

/// lloyd2006-fig11: the self-similar planes n (f/n)^{i/k}, f/n = 8, k = 3.
#[test]
fn lloyd2006_fig11() {
    let z = |i: f64| 8f64.powf(i / 3.0);
    check(
        "lloyd2006-fig11",
        &[
            ("2006", N::Given("the paper's year")),
            ("11", N::Given("its figure")),
            ("1", N::Given("n")),
            ("8", N::Given("f")),
            ("30", N::Given("θ")),
            ("3", N::Given("k")),
            ("1", N::Value(z(0.0))),
            ("2", N::Value(z(1.0))),
            ("4", N::Value(z(2.0))),
            ("8", N::Value(z(3.0))),
            ("5.3", N::Given("§5.3")),
            ("2", N::Given("the paper's 2n")),
            ("2", N::Given("the paper's 2f")),
            ("45", N::Given("where 2n tan θ = 2n")),
        ],
    );
}

/// lloyd2006-fig4 prints only its configuration.
#[test]
fn lloyd2006_fig4() {
    check(
        "lloyd2006-fig4",
        &[
            ("2006", N::Given("the paper's year")),
            ("4", N::Given("its figure")),
            ("1", N::Given("n")),
            ("10", N::Given("f")),
            ("30", N::Given("θ")),
            ("0", N::Given("the plane y = 0")),
            ("12", N::Given("grid lines across")),
            ("12", N::Given("grid lines along")),
            ("0", N::Given("the map's s, t from 0")),
            ("1", N::Given("to 1")),
        ],
    );
}

/// lloyd2006-fig7: (a)'s peak and the minimum-area maps' (measured), and LiSPSM's largest
/// factor over (a) near behind.
#[test]
fn lloyd2006_fig7() {
    check(
        "lloyd2006-fig7",
        &[
            ("2006", N::Given("the paper's year")),
            ("7", N::Given("its figure")),
            ("1", N::Given("n")),
            ("1000", N::Given("f")),
            ("30", N::Given("θ")),
            ("5.1", N::Given("§5.1, face partitioning")),
            (
                "1.999×10^{6}",
                N::Measured(
                    "(a)'s largest S̄ (fig7_names_e_and_the_projection_..., src/plot/hemisphere.rs)",
                ),
            ),
            (
                "45",
                N::Given("the turn of the map's side, along the square's diagonal"),
            ),
            ("10^{6}", N::Value(1000.0 * 1000.0)),
            (
                "1.5×10^{6}",
                N::Given("the other contour's level, round (a)'s peak"),
            ),
            (
                "4.3",
                N::Measured(
                    "(b) over (a) near behind, at least 10^(6.63 − 6.01) by the sixth review's \
                     Python (tests/figures_p2_review6.rs)",
                ),
            ),
            ("4.4", N::Given("§4.4")),
        ],
    );
}

/// lloyd2006-worst-case: the ratios are the hemisphere sweep's (not repeated here).
#[test]
fn lloyd2006_worst_case() {
    check(
        "lloyd2006-worst-case",
        &[
            ("2006", N::Given("the paper's year")),
            ("5.3", N::Given("§5.3")),
            ("2", N::Given("the paper's claim, 2–3 times")),
            ("3", N::Given("the paper's claim, 2–3 times")),
            ("20", N::Given("Eq 20")),
            ("21", N::Given("Eq 21")),
            ("1000", N::Given("f/n")),
            ("30", N::Given("θ")),
            ("2", N::Given("the sweep's step in degrees")),
            (
                "1.998",
                N::Measured("ZP's worst case over Eq 20's value behind"),
            ),
            ("2.024", N::Measured("ZP+W's least worst case over behind")),
            (
                "4.735",
                N::Measured(
                    "ZP+W at k = 1, Fig. 7's LiSPSM maximum over 10⁶ \
                     (worst_case_is_fig7s_maximum, src/plot/worst.rs)",
                ),
            ),
            ("1", N::Measured("FP+ZP+W's worst case is its value behind")),
            (
                "2",
                N::Measured(
                    "ZP's worst direction, elevation 2°, checked by hand \
                     (captions_say_where_the_worst_cases_lie, src/plot/worst.rs)",
                ),
            ),
            (
                "2",
                N::Measured("ZP's worst direction, azimuth 2° (the same by-hand check)"),
            ),
            (
                "45",
                N::Given("the map's turn against the frustum's square outline"),
            ),
            (
                "10",
                N::Given("the elevation above behind where ZP+W is compared"),
            ),
            ("1", N::Given("k = 1")),
            (
                "4.2",
                N::Measured("ZP+W's S̄ over ZP's there, from the sweeps (sixth review read 4.3)"),
            ),
        ],
    );
}

/// martin-tan-fig3: the coverages are the figure's construction, counted independently by
/// `coverages_match_a_brute_force_count` (src/plot/trapezoid_tests.rs).
#[test]
fn martin_tan_fig3() {
    let counted = "coverages_match_a_brute_force_count (src/plot/trapezoid_tests.rs)";
    check(
        "martin-tan-fig3",
        &[
            ("2004", N::Given("the paper's year")),
            ("3", N::Given("Fig. 3")),
            ("4", N::Given("and Fig. 4")),
            ("80", N::Given("the 80 % rule")),
            ("10", N::Given("focus δ")),
            ("1", N::Given("n")),
            ("100", N::Given("f")),
            ("30", N::Given("θ")),
            ("80", N::Given("the light's elevation")),
            ("70", N::Given("the light's azimuth")),
            ("3", N::Given("the paper's §3")),
            ("5", N::Given("the paper's §5")),
            ("67.0", N::Measured(counted)),
            ("53.2", N::Measured(counted)),
            ("51.4", N::Measured(counted)),
        ],
    );
}

/// martin-tan-fig6: its configuration, and the share light exactly behind or in front gives.
#[test]
fn martin_tan_fig6() {
    check(
        "martin-tan-fig6",
        &[
            ("2004", N::Given("the paper's year")),
            ("6", N::Given("its figure")),
            ("80", N::Given("(a) the paper's 80 % rule")),
            ("10", N::Given("a ring's elevation")),
            ("20", N::Given("a ring's elevation")),
            ("30", N::Given("a ring's elevation")),
            ("60", N::Given("a ring's elevation")),
            ("0", N::Given("(b)'s elevation behind")),
            ("90", N::Given("(b)'s elevation overhead")),
            ("0", N::Given("(b)'s elevation in front")),
            ("1024", N::Given("the iterative variant's map lines")),
            ("1", N::Given("n")),
            ("100", N::Given("f")),
            ("30", N::Given("θ")),
            ("10", N::Given("δ")),
            // Light exactly behind or in front: the map is the frustum's far face, side
            // 2 f tan θ, and the focus region is seen as its own far face at n + δ, so its
            // share is ((n + δ)/f)².
            ("0.0121", N::Value(((1.0f64 + 10.0) / 100.0).powi(2))),
            ("80", N::Given("the 80 % rule")),
            (
                "28",
                N::Measured(
                    "where the 80 % rule's share rises above 0.0121, bracketed [20, 30) \
                     by the sixth review's Python (tests/figures_p2_review6.rs)",
                ),
            ),
        ],
    );
}

/// zhang-fig3: LiSPSM's n′ (Zhang's λ) = (n + √(fn))/sin γ at n = 1, f = 100, γ = 90°, 60°,
/// 30° (Zhang's θ).
#[test]
fn zhang_fig3() {
    let lambda = |deg: f64| (1.0 + 100f64.sqrt()) / deg.to_radians().sin();
    check(
        "zhang-fig3",
        &[
            ("2009", N::Given("the paper's year")),
            ("3", N::Given("its figure")),
            ("1", N::Given("n")),
            ("100", N::Given("f")),
            ("30", N::Given("θ, the half field of view (Zhang's φ)")),
            ("90", N::Given("the first row's γ")),
            ("60", N::Given("the second row's γ")),
            ("30", N::Given("the third row's γ")),
            (
                "2006",
                N::Given("Lloyd et al.'s year: their m across the light"),
            ),
            ("7", N::Given("Lloyd 2006's Eq 7, m_x")),
            ("8", N::Given("Lloyd 2006's Eq 8, m_z")),
            ("2", N::Given("the factor 2 of E_p = 2 m_z, E_q = 2 m_x")),
            (
                "1",
                N::Given("Zhang's screen and map span [−1, 1] (read unsigned after the bracket)"),
            ),
            ("1", N::Given("Zhang's screen and map span [−1, 1]")),
            ("11.00", N::Value(lambda(90.0))),
            ("12.70", N::Value(lambda(60.0))),
            ("22.00", N::Value(lambda(30.0))),
            ("80", N::Given("the 80 % rule")),
            ("10", N::Given("focus δ")),
        ],
    );
}

/// Every figure's caption is listed in this file.
#[test]
fn every_figure_has_its_caption_listed() {
    let source: String = include_str!("figures_captions.rs")
        .chars()
        .filter(|c| !c.is_whitespace())
        .collect();
    for name in FIGURES {
        assert!(
            source.contains(&format!("check(\"{name}\",")),
            "{name}: no caption list"
        );
    }
}
