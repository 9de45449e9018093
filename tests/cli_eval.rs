//! `shadow-aliasing eval`: the real binary on valid requests, on every kind of bad request and on
//! malformed JSON, and `eval_json` in-process on random JSON and garbage (never a panic, always
//! the contract's shape).
#![cfg(feature = "cli")]

use proptest::prelude::*;
use serde_json::{json, Value};
use shadow_aliasing::eval::{eval_json, ArgKind, Presence, QUANTITIES};

mod common;
use common::cli::run_with_stdin as run;
use common::cli::{run_failing, view_args, warp_args};
use common::config;

fn eval_stdin(input: &str) -> (i32, Value, String) {
    let (code, out, err) = run(&["eval"], input);
    let v = serde_json::from_str(&out).unwrap_or_else(|e| panic!("stdout {out:?} is JSON: {e}"));
    (code, v, err)
}

/// `eval` on one array of the requests `cases` (each the first of its pair); returns (exit code,
/// the answers, stderr), after checking that there is one answer a request.
fn eval_cases<T>(cases: &[(&str, T)]) -> (i32, Vec<Value>, String) {
    let input = Value::Array(
        cases
            .iter()
            .map(|(req, _)| serde_json::from_str(req).unwrap())
            .collect(),
    );
    let (code, v, err) = eval_stdin(&input.to_string());
    let answers = v.as_array().unwrap_or_else(|| panic!("{v} is an array"));
    assert_eq!(answers.len(), cases.len(), "{v}");
    (code, answers.clone(), err)
}

fn error_of(v: &Value) -> &str {
    v["error"]
        .as_str()
        .unwrap_or_else(|| panic!("{v} has an error"))
}

fn value_of(v: &Value) -> f64 {
    v["value"]
        .as_f64()
        .unwrap_or_else(|| panic!("{v} has a value"))
}

#[test]
fn one_object_in_one_object_out() {
    // n + √(f n) = 1 + √100 = 11.
    let (code, v, err) = eval_stdin(r#"{"quantity": "n_prime_lispsm", "near": 1, "far": 100}"#);
    assert_eq!(code, 0);
    assert!(err.is_empty());
    assert_eq!(v, json!({"quantity": "n_prime_lispsm", "value": 11.0}));
}

#[test]
fn infinity_is_the_string_inf_in_and_out() {
    let (code, v, _) = eval_stdin(
        r#"[{"quantity": "n_prime_from_eta", "near": 1, "far": 100, "eta": -1},
            {"quantity": "eta_from_n_prime", "near": 1, "far": 100, "n_prime": "inf"},
            {"quantity": "generalized_n_prime", "near": 1, "far": 100, "half_fov": 0.5, "light_angle": 0, "falloff": "barroso"}]"#,
    );
    assert_eq!(code, 0);
    assert_eq!(v[0]["value"], "inf");
    assert_eq!(v[1]["value"], -1.0);
    // Light parallel to the view: every warp converges to the standard map (Barroso Eq 14).
    assert_eq!(v[2]["value"], "inf");
}

#[test]
fn a_value_beyond_f64_is_an_error_never_a_number() {
    // (f − n)/(2 tan θ) = 10¹⁰/(2·10⁻³⁰⁰) is beyond the largest f64.
    let (code, v, _) = eval_stdin(
        r#"{"quantity": "mz", "near": 1, "far": 1e10, "half_fov": 1e-300, "n_prime": 11, "z": 10}"#,
    );
    assert_eq!(code, 1);
    let e = error_of(&v);
    assert!(
        e.contains("could not be computed in f64") || e.starts_with("degenerate geometry"),
        "{e}"
    );
}

#[test]
fn array_in_array_out_same_order_and_exit_1_on_any_error() {
    let input = r#"[
        {"quantity": "n_prime_lispsm", "near": 4, "far": 9},
        {"quantity": "n_prime_lispsm", "near": 2, "far": 1},
        {"quantity": "n_prime_lispsm", "near": 1, "far": 4}
    ]"#;
    let (code, v, err) = eval_stdin(input);
    assert_eq!(code, 1);
    assert!(err.is_empty(), "{err}");
    let a = v.as_array().expect("an array");
    assert_eq!(a.len(), 3);
    // 4 + √36 = 10; 1 + √4 = 3.
    assert_eq!(value_of(&a[0]), 10.0);
    assert_eq!(
        error_of(&a[1]),
        "far must be greater than near (got near=2, far=1)"
    );
    assert_eq!(value_of(&a[2]), 3.0);
    for x in a {
        assert_eq!(x["quantity"], "n_prime_lispsm");
    }
}

#[test]
fn file_argument_and_dash_for_stdin() {
    let dir = std::env::temp_dir().join(format!("sa-cli-eval-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("req.json");
    std::fs::write(
        &file,
        r#"{"quantity": "n_prime_lispsm", "near": 1, "far": 9}"#,
    )
    .unwrap();
    let (code, out, _) = run(&["eval", file.to_str().unwrap()], "");
    assert_eq!(code, 0);
    assert_eq!(out.trim(), r#"{"quantity":"n_prime_lispsm","value":4.0}"#);
    let (code, out, _) = run(
        &["eval", "-"],
        r#"{"quantity": "n_prime_lispsm", "near": 1, "far": 9}"#,
    );
    assert_eq!(code, 0);
    assert_eq!(out.trim(), r#"{"quantity":"n_prime_lispsm","value":4.0}"#);
    let (code, out, err) = run(&["eval", dir.join("missing.json").to_str().unwrap()], "");
    assert_eq!(code, 2);
    assert!(out.is_empty());
    assert!(err.starts_with("error: cannot read"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn example_request_file_is_answered_with_values_only() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/eval-request.json");
    let (code, out, err) = run(&["eval", path], "");
    let v: Value = serde_json::from_str(&out).expect("JSON");
    let answers = v.as_array().expect("an array");
    for a in answers {
        assert!(a.get("value").is_some(), "{a}");
    }
    assert_eq!(code, 0, "{err}");
    // Every quantity of the contract appears in the example.
    for q in QUANTITIES {
        assert!(
            answers.iter().any(|a| a["quantity"] == q.name),
            "{} missing from examples/eval-request.json",
            q.name
        );
    }
}

/// Barroso & Celes' Eq 10–12 for φ_y ≤ γ ≤ π/2, written out from the paper (unit resolutions).
fn barroso_mz(n: f64, f: f64, phi: f64, np: f64, g: f64, z: f64) -> f64 {
    let (a, b) = (n * phi.tan(), f * phi.tan());
    let fp = np + (a + b) * g.cos() + (f - n) * g.sin();
    let xi = 1.0 / (2.0 * phi.tan()) * (fp - np) / (np * fp) / g.sin();
    let psi = np + a * g.cos() + (z - n) * g.sin();
    xi * psi * psi / z
}

/// Hand-calculated values of each wired quantity (relative 1e-12).
#[test]
fn values_match_hand_calculations() {
    #[allow(clippy::approx_constant)] // the requests' 0.5236, not π/6
    let phi = 0.5236f64;
    let t = phi.tan();
    let (a, b) = (t, 100.0 * t);
    let gamma_lim = ((a + b) / 99.0).atan();
    let owned: Vec<(String, Vec<f64>)> = vec![
        // Barroso Eq 12 at γ = 1.2, n′ = 11, z = 10.
        (
            r#"{"quantity": "tilted_mz", "near": 1, "far": 100, "half_fov": 0.5236, "n_prime": 11, "light_angle": 1.2, "z": 10}"#.into(),
            vec![barroso_mz(1.0, 100.0, phi, 11.0, 1.2, 10.0)],
        ),
        // A tilted light accepts n′ below near (the contract): n′ = 0.5.
        (
            r#"{"quantity": "tilted_mz", "near": 1, "far": 100, "half_fov": 0.5236, "n_prime": 0.5, "light_angle": 1.2, "z": 10}"#.into(),
            vec![barroso_mz(1.0, 100.0, phi, 0.5, 1.2, 10.0)],
        ),
        // res_t = 2 res_image halves it.
        (
            r#"{"quantity": "tilted_mz", "near": 1, "far": 100, "half_fov": 0.5236, "n_prime": 11, "light_angle": 1.2, "z": 10, "res_image": 512, "res_t": 1024}"#.into(),
            vec![0.5 * barroso_mz(1.0, 100.0, phi, 11.0, 1.2, 10.0)],
        ),
        // Eq 15: γ_lim = atan((a + b)/(f − n)), a, b the half heights of near and far planes.
        (
            r#"{"quantity": "gamma_lim", "near": 1, "far": 100, "half_fov": 0.5236}"#.into(),
            vec![gamma_lim],
        ),
        // Eq 16 above γ_lim: n′₁ = (n + √(fn)) sin γ − a cos γ.
        (
            r#"{"quantity": "generalized_n_prime", "near": 1, "far": 100, "half_fov": 0.5236, "light_angle": 1.2, "falloff": "barroso"}"#.into(),
            vec![11.0 * 1.2f64.sin() - a * 1.2f64.cos()],
        ),
        // Below γ_lim: n′₁(γ_lim)/r(γ), Zhang's r = sin(γ/γ_lim · π/2) (Eq 17).
        (
            r#"{"quantity": "generalized_n_prime", "near": 1, "far": 100, "half_fov": 0.5236, "light_angle": 0.3, "falloff": "zhang"}"#.into(),
            vec![(11.0 * gamma_lim.sin() - a * gamma_lim.cos()) / (0.3 / gamma_lim * std::f64::consts::FRAC_PI_2).sin()],
        ),
        // Martin & Tan §6.2: η = λδ′(1 + ξ)/(λ(1 − ξ) − 2δ′) = 0.08/1.2.
        (
            r#"{"quantity": "tsm_eta", "lambda": 1, "delta_prime": 0.2, "xi": -0.6}"#.into(),
            vec![0.08 / 1.2],
        ),
        // Zhang Eq 8 with λ ≥ n: 2 f (z − n + λ)/((f − n + λ) z) = 2·100·20/(110·10).
        (
            r#"{"quantity": "zhang_eq_local", "near": 1, "far": 100, "half_fov": 0.5236, "lambda": 11, "z": 10}"#.into(),
            vec![4000.0 / 1100.0],
        ),
        // Zhang Eq 9: (f − n)(z − n + λ)²/((f − n + λ) λ tan φ z) = 99·400/(110·11·t·10).
        (
            r#"{"quantity": "zhang_ep_local", "near": 1, "far": 100, "half_fov": 0.5236, "lambda": 11, "z": 10}"#.into(),
            vec![99.0 * 400.0 / (110.0 * 11.0 * t * 10.0)],
        ),
        // λ = ∞ (orthographic): (f − n)/(tan φ z).
        (
            r#"{"quantity": "zhang_ep_local", "near": 1, "far": 100, "half_fov": 0.5236, "lambda": "inf", "z": 10}"#.into(),
            vec![99.0 / (t * 10.0)],
        ),
        // The global representation at light angle π/2 on the view axis is the local one.
        (
            r#"{"quantity": "zhang_eq", "near": 1, "far": 100, "half_fov": 0.5236, "lambda": 11, "light_angle": 1.5707963267948966, "y": 0, "z": 10}"#.into(),
            vec![4000.0 / 1100.0],
        ),
        (
            r#"{"quantity": "zhang_ep", "near": 1, "far": 100, "half_fov": 0.5236, "lambda": 11, "light_angle": 1.5707963267948966, "y": 0, "z": 10}"#.into(),
            vec![99.0 * 400.0 / (110.0 * 11.0 * t * 10.0)],
        ),
    ];
    // Lloyd 2006 Eq 7, 8, 12 and Lloyd 2005 Eq 3, 5–7 at n = 1, f = 100, θ = 0.5236, n′ = 11.
    let base = 99.0 / (2.0 * t); // (f/n − 1)/(2 tan θ)
    let sqrt3 = 100f64.powf(1.0 / 3.0);
    let lloyd: Vec<(String, Vec<f64>)> = vec![
        // m_x = f (n′ + z − n)/(z (n′ + f − n)) = 100·20/(10·110).
        (r#"{"quantity": "mx", "near": 1, "far": 100, "n_prime": 11, "z": 10}"#.into(), vec![2000.0 / 1100.0]),
        // times res_i/res_s = 1/2.
        (r#"{"quantity": "mx", "near": 1, "far": 100, "n_prime": 11, "z": 10, "res_image": 1024, "res_s": 2048}"#.into(), vec![1000.0 / 1100.0]),
        // m_z = (f − n)/(2 tan θ) (n′ + z − n)²/(z n′ (n′ + f − n)).
        (r#"{"quantity": "mz", "near": 1, "far": 100, "half_fov": 0.5236, "n_prime": 11, "z": 10}"#.into(), vec![base * 400.0 / (10.0 * 11.0 * 110.0)]),
        // n′ = ∞: (f − n)/(2 tan θ)/z, times res_i/res_t = 1/2.
        (r#"{"quantity": "mz", "near": 1, "far": 100, "half_fov": 0.5236, "n_prime": "inf", "z": 10, "res_image": 1024, "res_t": 2048}"#.into(), vec![0.5 * base / 10.0]),
        // M_x = m_x(n) = f n′/(n (n′ + f − n)) = 1100/110.
        (r#"{"quantity": "max_mx", "near": 1, "far": 100, "n_prime": 11}"#.into(), vec![10.0]),
        // M_x unwarped: f/n.
        (r#"{"quantity": "max_mx", "near": 1, "far": 100, "n_prime": "inf"}"#.into(), vec![100.0]),
        // At n′_LSPSM M_z = m_z(f) = m_z(n) = base (n′ + f − n)/(f n′) = base·110/1100.
        (r#"{"quantity": "max_mz", "near": 1, "far": 100, "half_fov": 0.5236, "n_prime": 11}"#.into(), vec![base * 0.1]),
        // S̄ = base for n′ ≤ n′_LSPSM (PSM n′ = n too), base·f/n unwarped,
        // base·n′² f/(n (n′ + f − n)²) above n′_LSPSM.
        (r#"{"quantity": "storage_factor", "near": 1, "far": 100, "half_fov": 0.5236, "n_prime": 1}"#.into(), vec![base]),
        (r#"{"quantity": "storage_factor", "near": 1, "far": 100, "half_fov": 0.5236, "n_prime": "inf"}"#.into(), vec![base * 100.0]),
        (r#"{"quantity": "storage_factor", "near": 1, "far": 100, "half_fov": 0.5236, "n_prime": 50}"#.into(), vec![base * 2500.0 * 100.0 / (149.0 * 149.0)]),
        // Eq 13, 14 with M_x/M_z = 10/(base/10): res_s = √(S₀ M_x/M_z), res_t = √(S₀ M_z/M_x).
        (
            r#"{"quantity": "critical_resolution", "near": 1, "far": 100, "half_fov": 0.5236, "n_prime": 11, "budget": 4194304, "res_image": 1024}"#.into(),
            vec![(4194304.0 * 100.0 / base).sqrt(), (4194304.0 * base / 100.0).sqrt()],
        ),
        // Eq 11: η = 0 → n + √(fn); η = 1 → n; η = −1 → ∞ (checked as a string elsewhere);
        // η = −0.5 → n (√α + 1 + (α − 1)/2)/(1/2) = 2·(11 + 49.5).
        (r#"{"quantity": "n_prime_from_eta", "near": 1, "far": 100, "eta": 0}"#.into(), vec![11.0]),
        (r#"{"quantity": "n_prime_from_eta", "near": 1, "far": 100, "eta": 1}"#.into(), vec![1.0]),
        (r#"{"quantity": "n_prime_from_eta", "near": 1, "far": 100, "eta": -0.5}"#.into(), vec![121.0]),
        (r#"{"quantity": "eta_from_n_prime", "near": 1, "far": 100, "n_prime": 121}"#.into(), vec![-0.5]),
        (r#"{"quantity": "eta_from_n_prime", "near": 1, "far": 100, "n_prime": "inf"}"#.into(), vec![-1.0]),
        // Lloyd 2005 Eq 3: (z − 1 + n)²/(z n (n + α − 1)) = 400/(10·11·110); n = ∞: 1/z.
        (r#"{"quantity": "distribution_g", "alpha": 100, "n_warp": 11, "z": 10}"#.into(), vec![400.0 / 12100.0]),
        (r#"{"quantity": "distribution_g", "alpha": 100, "n_warp": "inf", "z": 10}"#.into(), vec![0.1]),
        // Eq 7: k (α^{1/k} − 1)/(2 tan θ) (1 + |ξ|(√α^{1/k} − 1))/√α^{1/k}, k = 3, ξ = 0 and 1.
        (
            r#"{"quantity": "subdivided_max_error", "alpha": 100, "k": 3, "eta": 0, "half_fov": 0.5236}"#.into(),
            vec![3.0 * (sqrt3 - 1.0) / (2.0 * t) / sqrt3.sqrt()],
        ),
        (
            r#"{"quantity": "subdivided_max_error", "alpha": 100, "k": 3, "eta": 1, "half_fov": 0.5236, "res_image": 2, "res_s": 1}"#.into(),
            vec![2.0 * 3.0 * (sqrt3 - 1.0) / (2.0 * t) * sqrt3.sqrt() / sqrt3.sqrt()],
        ),
        // Eq 6: r_s e_i / Σ e_j.
        (r#"{"quantity": "allocate_texels", "errors": [1, 2, 1], "total": 1024}"#.into(), vec![256.0, 512.0, 256.0]),
        // Lloyd 2006 Eq 17–20 and App. C at n = 1, f = 1000, k = 3, a = 10.
        (r#"{"quantity": "scheme_storage_factor", "scheme": "zp", "light": "overhead", "near": 1, "far": 1000, "half_fov": 0.5236, "k": 3}"#.into(), vec![3.0 * 10.0 * 9.0 / (2.0 * t)]),
        (r#"{"quantity": "scheme_storage_factor", "scheme": "zp_w", "light": "overhead", "near": 1, "far": 1000, "half_fov": 0.5236, "k": 3}"#.into(), vec![27.0 / (2.0 * t)]),
        (r#"{"quantity": "scheme_storage_factor", "scheme": "zp", "light": "behind", "near": 1, "far": 1000, "half_fov": 0.5236, "k": 3}"#.into(), vec![300.0]),
        (r#"{"quantity": "scheme_storage_factor", "scheme": "optimal", "light": "overhead", "near": 1, "far": 1000, "half_fov": 0.5236, "k": 1}"#.into(), vec![1000f64.ln() / (2.0 * t)]),
    ];
    let mut cases: Vec<(&str, &[f64])> = owned
        .iter()
        .chain(&lloyd)
        .map(|(r, v)| (r.as_str(), v.as_slice()))
        .collect();
    cases.extend_from_slice(&[
        // 1 + √100.
        (
            r#"{"quantity": "n_prime_lispsm", "near": 1, "far": 100}"#,
            &[11.0],
        ),
        // n (f/n)^{i/k}: 1, 10, 100, 1000.
        (
            r#"{"quantity": "z_partition", "near": 1, "far": 1000, "k": 3, "scheme": "self_similar"}"#,
            &[1.0, 10.0, 100.0, 1000.0],
        ),
        // n + (f − n) i/k: 1, 334, 667, 1000.
        (
            r#"{"quantity": "z_partition", "near": 1, "far": 1000, "k": 3, "scheme": "uniform"}"#,
            &[1.0, 334.0, 667.0, 1000.0],
        ),
        // The mean of the two above at λ = 0.5.
        (
            r#"{"quantity": "z_partition", "near": 1, "far": 1000, "k": 3, "scheme": "practical", "lambda": 0.5}"#,
            &[1.0, 172.0, 383.5, 1000.0],
        ),
        // γ = π/2: Barroso's adaptive planes are the self-similar ones.
        (
            r#"{"quantity": "z_partition", "near": 2, "far": 32, "k": 4, "scheme": "adaptive", "light_angle": 1.5707963267948966, "ratio": 3}"#,
            &[2.0, 4.0, 8.0, 16.0, 32.0],
        ),
        // γ = 0: the last partitions have ratio α = 2 (32 → 16 → 8), the first takes the rest.
        (
            r#"{"quantity": "z_partition", "near": 1, "far": 32, "k": 3, "scheme": "adaptive", "light_angle": 0, "ratio": 2}"#,
            &[1.0, 8.0, 16.0, 32.0],
        ),
    ]);
    let (code, answers, err) = eval_cases(&cases);
    for ((req, want), got) in cases.iter().zip(&answers) {
        let values: Vec<f64> = match &got["value"] {
            Value::Array(xs) => xs.iter().map(|x| x.as_f64().unwrap()).collect(),
            Value::Number(n) => vec![n.as_f64().unwrap()],
            other => panic!("{req}: no value ({other}): {got}"),
        };
        assert_eq!(values.len(), want.len(), "{req}: {got}");
        for (g, w) in values.iter().zip(*want) {
            assert!(
                (g - w).abs() <= 1e-12 * w.abs().max(1.0),
                "{req}: got {g}, want {w}"
            );
        }
    }
    assert_eq!(code, 0, "{err}");
}

/// The json blocks of a markdown file, in order.
fn json_blocks(md: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur: Option<String> = None;
    for line in md.lines() {
        match (&mut cur, line.trim_end()) {
            (None, "```json") => cur = Some(String::new()),
            (Some(_), "```") => out.push(cur.take().unwrap_or_default()),
            (Some(b), l) => {
                b.push_str(l);
                b.push('\n');
            }
            _ => {}
        }
    }
    out
}

/// Equal JSON, numbers to a relative 1e-12.
fn same_answers(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => {
            let (x, y) = (
                x.as_f64().unwrap_or(f64::NAN),
                y.as_f64().unwrap_or(f64::NAN),
            );
            (x - y).abs() <= 1e-12 * x.abs().max(y.abs())
        }
        (Value::Array(x), Value::Array(y)) => {
            x.len() == y.len() && x.iter().zip(y).all(|(p, q)| same_answers(p, q))
        }
        (Value::Object(x), Value::Object(y)) => {
            x.len() == y.len()
                && x.iter()
                    .all(|(k, v)| y.get(k).is_some_and(|w| same_answers(v, w)))
        }
        _ => a == b,
    }
}

#[test]
fn docs_show_the_binarys_answers() {
    let root = env!("CARGO_MANIFEST_DIR");
    let md = std::fs::read_to_string(format!("{root}/docs/eval.md")).unwrap();
    let blocks = json_blocks(&md);
    let n = blocks.len();
    assert!(n >= 2);
    let request = std::fs::read_to_string(format!("{root}/examples/eval-request.json")).unwrap();
    assert_eq!(
        blocks[n - 2],
        request,
        "docs/eval.md shows examples/eval-request.json"
    );
    let (code, out, _) = run(&["eval", &format!("{root}/examples/eval-request.json")], "");
    assert_eq!(code, 0);
    // The same answers, to a relative 1e-12 (a closed form rearranged for accuracy may move the
    // last bit; anything more means the page is stale).
    let shown: Value = serde_json::from_str(&blocks[n - 1]).expect("docs block is JSON");
    let now: Value = serde_json::from_str(&out).unwrap();
    assert!(
        same_answers(&shown, &now),
        "docs/eval.md's answers are stale; the binary prints:\n{out}"
    );
    // The single examples near the top are real answers too.
    let (_, out, _) = run(
        &["eval"],
        r#"{"quantity": "storage_factor", "near": 1, "far": 100, "half_fov": 0.5236, "n_prime": 0.5}"#,
    );
    assert!(md.contains(out.trim()), "{out}");
    let (_, out, _) = run(
        &["eval"],
        r#"{"quantity": "storage_factor", "near": 1, "far": 100, "half_fov": 0.5236, "n_prime": 11}"#,
    );
    assert!(md.contains(out.trim()), "{out}");
}

#[test]
fn every_kind_of_bad_request_is_an_error_naming_the_argument() {
    let cases: &[(&str, &str)] = &[
        (
            r#"{"quantity": "n_prime_lipsm", "near": 1, "far": 2}"#,
            "quantity \"n_prime_lipsm\" is unknown (did you mean n_prime_lispsm?",
        ),
        (r#"{"near": 1, "far": 2}"#, "quantity is missing"),
        (r#"{"quantity": 3}"#, "quantity must be a string"),
        (
            r#"{"quantity": "n_prime_lispsm", "near": 1}"#,
            "far is missing (n_prime_lispsm takes near, far)",
        ),
        (
            r#"{"quantity": "n_prime_lispsm", "near": 1, "far": 2, "fov": 1}"#,
            "fov is not an argument of n_prime_lispsm",
        ),
        (
            r#"{"quantity": "n_prime_lispsm", "near": "1", "far": 2}"#,
            "near must be a number (got string \"1\"",
        ),
        (
            r#"{"quantity": "n_prime_lispsm", "near": [1], "far": 2}"#,
            "near must be a number (got array [1])",
        ),
        (
            r#"{"quantity": "n_prime_lispsm", "near": null, "far": 2}"#,
            "near must be a number (got null)",
        ),
        (
            r#"{"quantity": "n_prime_lispsm", "near": "NaN", "far": 2}"#,
            "near must be a finite number (got NaN)",
        ),
        (
            r#"{"quantity": "n_prime_lispsm", "near": 1, "far": "inf"}"#,
            "far must be a finite number (got inf)",
        ),
        (
            r#"{"quantity": "n_prime_lispsm", "near": -1, "far": 2}"#,
            "near must be greater than 0 (got -1)",
        ),
        (
            r#"{"quantity": "n_prime_lispsm", "near": 2, "far": 2}"#,
            "far must be greater than near (got near=2, far=2)",
        ),
        (
            r#"{"quantity": "storage_factor", "near": 1, "far": 100, "half_fov": 0.5, "n_prime": "-inf"}"#,
            "n_prime must be a number greater than 0 or the string \"inf\" (got -inf)",
        ),
        (
            r#"{"quantity": "storage_factor", "near": 1, "far": 100, "half_fov": 0.5, "n_prime": 0}"#,
            "n_prime must be a number greater than 0 or the string \"inf\" (got 0)",
        ),
        (
            r#"{"quantity": "z_partition", "near": 1, "far": 100, "k": 2.5, "scheme": "uniform"}"#,
            "k must be a whole number of at least 1 (got 2.5)",
        ),
        (
            r#"{"quantity": "z_partition", "near": 1, "far": 100, "k": 2, "scheme": "log"}"#,
            "scheme must be one of \"self_similar\", \"uniform\", \"practical\", \"adaptive\" (got string \"log\")",
        ),
        (
            r#"{"quantity": "z_partition", "near": 1, "far": 100, "k": 2, "scheme": "practical"}"#,
            "lambda is missing (scheme \"practical\" needs it)",
        ),
        (
            r#"{"quantity": "z_partition", "near": 1, "far": 100, "k": 2, "scheme": "uniform", "ratio": 2}"#,
            "ratio is not an argument of z_partition with scheme \"uniform\"",
        ),
        (
            r#"{"quantity": "z_partition", "near": 1, "far": 100, "k": 2, "scheme": "practical", "lambda": 1.5}"#,
            "lambda must lie in [0, 1] (got 1.5)",
        ),
        (
            r#"{"quantity": "tilted_mz", "near": 1, "far": 100, "half_fov": 0.5236, "n_prime": 11, "light_angle": 2, "z": 10}"#,
            "light_angle must lie in [0, 1.5707963267948966] (got 2)",
        ),
        (
            r#"{"quantity": "tsm_eta", "lambda": 1, "delta_prime": 0.2, "xi": 0.9}"#,
            "no solution: ",
        ),
        (
            r#"{"quantity": "generalized_n_prime", "near": 1, "far": 100, "half_fov": 0.5, "light_angle": 1, "falloff": "wimmer"}"#,
            "falloff must be one of \"barroso\", \"zhang\" (got string \"wimmer\")",
        ),
        (
            r#"{"quantity": "zhang_eq_local", "near": 1, "far": 100, "half_fov": 0.5, "lambda": 11, "z": 200}"#,
            "z must ",
        ),
        (
            r#"{"quantity": "storage_factor", "near": 1, "far": 100, "half_fov": 0.5, "n_prime": 0.5}"#,
            "n_prime must be at least near",
        ),
        (
            r#"{"quantity": "mx", "near": 1, "far": 100, "n_prime": 11, "z": 0.5}"#,
            "z must ",
        ),
        (
            r#"{"quantity": "mz", "near": 1, "far": 100, "half_fov": 1.6, "n_prime": 11, "z": 5}"#,
            "half_fov must lie in (0, 1.5707963267948966) (got 1.6)",
        ),
        (
            r#"{"quantity": "n_prime_from_eta", "near": 1, "far": 100, "eta": 1.5}"#,
            "eta must lie in [-1, 1] (got 1.5)",
        ),
        (
            r#"{"quantity": "subdivided_max_error", "alpha": 100, "k": 3, "eta": -2, "half_fov": 0.5}"#,
            "eta must lie in [-1, 1] (got -2)",
        ),
        (
            r#"{"quantity": "subdivided_max_error", "alpha": 100, "k": 3, "eta": 0, "half_fov": 0.5, "res_s": -1}"#,
            "res_s must be greater than 0 (got -1)",
        ),
        (
            r#"{"quantity": "mx", "near": 1, "far": 100, "n_prime": 11, "z": 5, "res_s": 0}"#,
            "res_s must be greater than 0 (got 0)",
        ),
        (
            r#"{"quantity": "critical_resolution", "near": 1, "far": 100, "half_fov": 0.5, "n_prime": 11, "budget": -4}"#,
            "budget must be greater than 0 (got -4)",
        ),
        (
            r#"{"quantity": "scheme_storage_factor", "scheme": "optimal", "light": "behind", "near": 1, "far": 100, "half_fov": 0.5, "k": 1}"#,
            "no closed form: ",
        ),
        (
            r#"{"quantity": "allocate_texels", "errors": [], "total": 10}"#,
            "errors ",
        ),
        (
            r#"{"quantity": "allocate_texels", "errors": [1, "x"], "total": 10}"#,
            "errors must be an array of numbers (errors[1] is string \"x\")",
        ),
        (
            r#"{"quantity": "allocate_texels", "errors": 1, "total": 10}"#,
            "errors must be an array of numbers (got number 1)",
        ),
    ];
    let (code, answers, err) = eval_cases(cases);
    assert_eq!(code, 1);
    assert!(err.is_empty(), "{err}");
    for ((req, want), got) in cases.iter().zip(&answers) {
        let msg = error_of(got);
        assert!(
            msg.starts_with(want),
            "{req}\n  got:  {msg}\n  want: {want}…"
        );
        assert!(got.get("value").is_none());
    }
}

#[test]
fn malformed_input_exits_2_with_one_line_and_no_stdout() {
    for input in [
        "",
        "   ",
        "{",
        "{\"quantity\": \"mx\",}",
        "[1, 2",
        "3",
        "\"mx\"",
        "null",
        "true",
        "NaN",
        "{\"near\": 1e400}",
        "{} {}",
    ] {
        let (code, err) = run_failing(&["eval"], input);
        assert_eq!(code, 2, "{input:?}: {err}");
        assert!(err.starts_with("error: "), "{input:?}: {err}");
    }
}

#[test]
fn numbers_round_trip_through_the_binary() {
    // n + √(f n) with f = 2: 1 + √2, whose shortest form has 17 digits.
    let (_, v, _) = eval_stdin(r#"{"quantity": "n_prime_lispsm", "near": 1, "far": 2}"#);
    assert_eq!(value_of(&v).to_bits(), (1.0 + 2f64.sqrt()).to_bits());
    let (_, out, _) = run(
        &["eval"],
        r#"{"quantity": "n_prime_lispsm", "near": 1e-300, "far": 4e-300}"#,
    );
    // n + √(f n) = 1e-300 + √(4e-600) = 3e-300 (f n itself underflows to 0 in f64), printed with
    // an exponent.
    let v: Value = serde_json::from_str(&out).unwrap();
    assert!((value_of(&v) - 3e-300).abs() <= 1e-15 * 3e-300, "{out}");
    assert!(out.contains("e-300"), "{out}");
}

// ---------------------------------------------------------------------------------------------
// Never a panic: random JSON, random requests, garbage text.

fn finite_number() -> impl Strategy<Value = f64> {
    prop_oneof![
        -10.0..200.0f64,
        0.0..2.0f64,
        (1u32..20).prop_map(f64::from),
        Just(0.0),
        Just(-0.0),
        Just(1.0),
        Just(std::f64::consts::FRAC_PI_2),
        Just(1e-300),
        Just(1e300),
        Just(-1e300),
        Just(f64::MAX),
        Just(f64::MIN_POSITIVE),
        any::<f64>().prop_filter("finite", |x| x.is_finite()),
    ]
}

fn json_number(x: f64) -> Value {
    serde_json::Number::from_f64(x).map_or(Value::Null, Value::Number)
}

fn leaf() -> impl Strategy<Value = Value> {
    prop_oneof![
        Just(Value::Null),
        any::<bool>().prop_map(Value::Bool),
        finite_number().prop_map(json_number),
        any::<i64>().prop_map(Value::from),
        any::<u64>().prop_map(Value::from),
        "[a-z_]{0,14}".prop_map(Value::String),
        prop_oneof![
            Just("inf"),
            Just("-inf"),
            Just("nan"),
            Just("Infinity"),
            Just("1")
        ]
        .prop_map(|s| Value::String(s.into())),
        any::<String>().prop_map(Value::String),
    ]
}

fn arb_json() -> impl Strategy<Value = Value> {
    leaf().prop_recursive(4, 48, 6, |inner| {
        let key = prop_oneof![
            "[a-z_]{0,12}",
            Just("quantity".to_string()),
            Just("near".to_string())
        ];
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..6).prop_map(Value::Array),
            prop::collection::vec((key, inner), 0..6)
                .prop_map(|kv| Value::Object(kv.into_iter().collect())),
        ]
    })
}

/// A request for a real quantity whose arguments are mostly of the right type and mostly in a
/// plausible range, sometimes wrong, missing or extra: it reaches the closed forms.
fn arb_request() -> impl Strategy<Value = Value> {
    let n = QUANTITIES.len();
    (
        0..n,
        prop::collection::vec((0u8..10, finite_number(), leaf(), 0usize..8), 8),
        prop::option::weighted(0.1, ("[a-z_]{1,8}", leaf())),
    )
        .prop_map(|(qi, picks, extra)| {
            let q = &QUANTITIES[qi];
            let mut m = serde_json::Map::new();
            m.insert("quantity".into(), Value::from(q.name));
            for (spec, (mode, x, junk, pick)) in q.args.iter().zip(picks) {
                let optional = spec.presence != Presence::Required;
                let v = match mode {
                    0 => continue,
                    1 if optional => continue,
                    1 | 2 => junk,
                    _ => match spec.kind {
                        ArgKind::Number | ArgKind::Count => json_number(x),
                        ArgKind::NPrime => {
                            if pick == 0 {
                                Value::from("inf")
                            } else {
                                json_number(x)
                            }
                        }
                        ArgKind::Choice(options) => Value::from(options[pick % options.len()]),
                        ArgKind::Numbers => Value::Array(
                            (0..pick).map(|i| json_number(x * (i + 1) as f64)).collect(),
                        ),
                    },
                };
                m.insert(spec.name.into(), v);
            }
            if let Some((k, v)) = extra {
                m.insert(k, v);
            }
            Value::Object(m)
        })
}

/// The contract's shape: exit 2 with nothing on stdout and one line on stderr, or the answers.
fn check_shape(input: &str, parsed: Option<&Value>) {
    let out = eval_json(input);
    match out.exit_code {
        2 => {
            assert!(out.stdout.is_empty());
            assert_eq!(out.stderr.lines().count(), 1, "{}", out.stderr);
            if let Some(v) = parsed {
                assert!(!v.is_object() && !v.is_array(), "{input}");
            }
        }
        0 | 1 => {
            assert!(out.stderr.is_empty());
            let got: Value = serde_json::from_str(&out.stdout)
                .unwrap_or_else(|e| panic!("{input}\n→ {}\nnot JSON: {e}", out.stdout));
            let answers: Vec<&Value> = match (&got, parsed) {
                (Value::Array(a), Some(Value::Array(req))) => {
                    assert_eq!(a.len(), req.len());
                    a.iter().collect()
                }
                (Value::Object(_), Some(Value::Object(_))) => vec![&got],
                (g, p) => panic!("shape mismatch: {p:?} → {g}"),
            };
            let mut any_error = false;
            for a in answers {
                let o = a.as_object().expect("each answer is an object");
                assert_eq!(o.len(), 2, "{a}");
                assert!(o["quantity"].is_string() || o["quantity"].is_null());
                match (o.get("value"), o.get("error")) {
                    (Some(v), None) => match v {
                        Value::Number(n) => assert!(n.as_f64().unwrap().is_finite()),
                        Value::String(s) => assert_eq!(s, "inf"),
                        Value::Array(xs) => assert!(xs.iter().all(|x| x.is_number())),
                        _ => panic!("bad value {v}"),
                    },
                    (None, Some(Value::String(e))) => {
                        assert!(!e.is_empty());
                        any_error = true;
                    }
                    _ => panic!("neither value nor error: {a}"),
                }
            }
            assert_eq!(out.exit_code, i32::from(any_error));
        }
        c => panic!("exit code {c}"),
    }
}

proptest! {
    #![proptest_config(config(256))]

    #[test]
    fn random_json_never_panics(v in arb_json()) {
        check_shape(&v.to_string(), Some(&v));
    }

    #[test]
    fn random_requests_never_panic(reqs in prop::collection::vec(arb_request(), 1..6), single in any::<bool>()) {
        let v = if single { reqs[0].clone() } else { Value::Array(reqs) };
        check_shape(&v.to_string(), Some(&v));
    }

    #[test]
    fn garbage_text_never_panics(s in any::<String>()) {
        let parsed = serde_json::from_str::<Value>(&s).ok();
        check_shape(&s, parsed.as_ref());
    }

    #[test]
    fn mangled_valid_requests_never_panic(cut in 0usize..200, byte in any::<u8>()) {
        let text = r#"[{"quantity": "storage_factor", "near": 1, "far": 100, "half_fov": 0.5236, "n_prime": "inf"}]"#;
        let mut b = text.as_bytes().to_vec();
        let i = cut % b.len();
        b[i] = byte;
        if let Ok(s) = String::from_utf8(b) {
            let parsed = serde_json::from_str::<Value>(&s).ok();
            check_shape(&s, parsed.as_ref());
        }
    }
}

/// The README's promises: exactly two commands under "Two commands" (the main job and the tests,
/// `scripts/test.sh`),
/// and every relative link resolves to a file of the repository.
#[test]
fn readme_two_commands_and_links() {
    let root = env!("CARGO_MANIFEST_DIR");
    let md = std::fs::read_to_string(format!("{root}/README.md")).unwrap();
    let start = md.find("## Two commands").expect("a Two commands heading");
    let section = &md[start..];
    let end = section[3..].find("\n## ").map_or(section.len(), |i| i + 3);
    let commands: Vec<&str> = section[..end]
        .split("```sh\n")
        .skip(1)
        .map(|b| b.split("```").next().unwrap_or("").trim())
        .collect();
    assert_eq!(
        commands,
        [
            "cargo run --release --locked --features cli -- figures",
            "scripts/test.sh"
        ]
    );
    // The test command is the script, which runs every workspace member's tests.
    let script = std::fs::read_to_string(format!("{root}/scripts/test.sh")).unwrap();
    assert!(script.contains("cargo test --locked --workspace --all-features"));
    assert!(script.contains("apt-get install -y mesa-vulkan-drivers"));
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = std::fs::metadata(format!("{root}/scripts/test.sh"))
            .unwrap()
            .permissions()
            .mode();
        assert!(mode & 0o111 != 0, "scripts/test.sh must be executable");
    }
    for (i, _) in md.match_indices("](") {
        let target = md[i + 2..].split(')').next().unwrap_or("");
        if target.starts_with("http") || target.starts_with('#') {
            continue;
        }
        assert!(
            std::path::Path::new(root).join(target).exists(),
            "README links to {target}, which does not exist"
        );
    }
}

/// A failing standard output is exit status 1 with a message, as for `warp` and `sweep` (2 is
/// malformed input); it used to be status 2 and silence.
#[cfg(target_os = "linux")]
#[test]
fn a_write_error_is_status_1_with_a_message() {
    use common::cli::run_to_full;
    let want = "error: cannot write to standard output: No space left on device (os error 28)\n";
    let request = r#"{"quantity": "n_prime_lispsm", "near": 1, "far": 100}"#;
    let sweep = ["--warp", "lispsm", "--elevations", "2", "--azimuths", "2"];
    for args in [
        vec!["eval"],
        warp_args("0.5", "0,-1,0", "lispsm", &[]),
        view_args("sweep", "0.5", &sweep),
    ] {
        let (code, err) = run_to_full(&args, request);
        assert_eq!((code, err.as_str()), (1, want), "{args:?}");
    }
    // Malformed input is still status 2 (nothing reaches standard output).
    let (code, err) = run_to_full(&["eval"], "{not json");
    assert_eq!(code, 2);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.starts_with("error: "), "{err}");
}

#[test]
fn error_messages_name_each_argument_once_with_short_numbers() {
    let (code, v, _) = eval_stdin(
        r#"[{"quantity": "n_prime_lispsm", "near": 1e-300, "far": 1e300},
            {"quantity": "n_prime_lispsm", "near": -1e300, "far": 1},
            {"quantity": "n_prime_lispsm", "near": 1, "far": 1.7976931348623157e308}]"#,
    );
    assert_eq!(code, 1);
    assert_eq!(
        error_of(&v[0]),
        "far must be small enough that far/near is finite (got near=1e-300, far=1e300)"
    );
    assert_eq!(error_of(&v[1]), "near must be greater than 0 (got -1e300)");
    // f64::MAX/1 is finite: a value, not an error.
    assert!(value_of(&v[2]).is_finite());
}

/// A nonzero value that the resolutions scale below f64's normal range is an error naming the
/// resolutions, never 0 or a subnormal (issue 21, item 8). m_x at z = 10 of near 1, far 100,
/// n′ = 11 is (res_i/res_s) · 100 · 20/(10 · 110) = (res_i/res_s) · 1.8181…, by hand: 1.818e-600
/// for res_i = 10⁻³⁰⁰, res_s = 10³⁰⁰.
#[test]
fn a_value_the_resolutions_scale_below_f64_is_an_error() {
    let issue = r#"{"quantity":"mx","near":1,"far":100,"n_prime":11,"z":10,"res_image":1e-300,"res_s":1e300}"#;
    let (code, v, _) = eval_stdin(issue);
    assert_eq!(code, 1, "{v}");
    let e = error_of(&v);
    for part in [
        "res_image and res_s make m_x underflow f64",
        "res_image/res_s (res_image=1e-300, res_s=1e300)",
        "about 1.818e-600",
        "returned as 0",
        "evaluate it at res_image=res_s=1 (m_x = 1.8181818181818183)",
        "scale by res_image/res_s yourself, in logarithms",
    ] {
        assert!(e.contains(part), "{part:?} not in {e}");
    }
    // Every quantity that scales with the resolutions, the map's along s or t.
    let scaled = [
        r#"{"quantity":"mz","near":1,"far":100,"half_fov":0.5,"n_prime":11,"z":10,"res_image":1e-300,"res_t":1e300}"#,
        r#"{"quantity":"max_mx","near":1,"far":100,"n_prime":11,"res_image":1e-300,"res_s":1e300}"#,
        r#"{"quantity":"max_mz","near":1,"far":100,"half_fov":0.5,"n_prime":11,"res_image":1e-300,"res_t":1e300}"#,
        r#"{"quantity":"tilted_mz","near":1,"far":100,"half_fov":0.5,"n_prime":11,"light_angle":1,"z":10,"res_image":1e-300,"res_t":1e300}"#,
        r#"{"quantity":"subdivided_max_error","alpha":100,"k":2,"eta":0,"half_fov":0.5,"res_image":1e-300,"res_s":1e300}"#,
    ];
    for req in scaled {
        let out = eval_json(req);
        assert_eq!(out.exit_code, 1, "{req}: {}", out.stdout);
        let v: Value = serde_json::from_str(&out.stdout).unwrap();
        let e = error_of(&v);
        let map = if req.contains("res_t") {
            "res_t"
        } else {
            "res_s"
        };
        assert!(
            e.contains("underflow f64") && e.contains(&format!("res_image/{map}")),
            "{req}: {e}"
        );
    }
    // A subnormal result (1.8e-310, with about 3 digits left) is refused as well.
    let out = eval_json(
        r#"{"quantity":"mx","near":1,"far":100,"n_prime":11,"z":10,"res_image":1e-300,"res_s":1e10}"#,
    );
    assert_eq!(out.exit_code, 1, "{}", out.stdout);
    assert!(out.stdout.contains("about 1.818e-310") && out.stdout.contains("subnormal"));
    // A small normal value is answered: 1.8181…e-305.
    let out = eval_json(
        r#"{"quantity":"mx","near":1,"far":100,"n_prime":11,"z":10,"res_image":1e-300,"res_s":1e5}"#,
    );
    assert_eq!(out.exit_code, 0, "{}", out.stdout);
    let v: Value = serde_json::from_str(&out.stdout).unwrap();
    let x = value_of(&v);
    assert!((x - 2000.0 / 1100.0 * 1e-305).abs() <= 1e-12 * x, "{x}");
}
