//! The closed forms of the eval contract (docs/eval.md), element-wise on NumPy arrays.
//!
//! Argument names are the contract's, except Zhang's and Martin–Tan's `lambda`, a Python keyword,
//! spelled `lambda_`. Angles in radians.

use crate::args;
use crate::broadcast::finite;
use crate::broadcast::{count, map, map_fast, map_into, OutSpec, N_PRIME, POSITIVE, SCALAR};
use numpy::PyUntypedArrayMethods;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use shadow_aliasing::analytic::eta;
use shadow_aliasing::analytic::partition::{self, Scheme, SchemeLight, SplitScheme};
use shadow_aliasing::analytic::{global, overhead, subdivided, tilted, tsm};
use shadow_aliasing::{Error, LightAngle, NPrime, Resolutions, ViewFrustum};

type Any<'py> = Bound<'py, PyAny>;

/// n′ from a float: +∞ is the unwarped map; anything else must be finite and > 0.
pub fn n_prime_arg(name: &'static str, v: f64) -> Result<NPrime, Error> {
    NPrime::named(name, v)
}

/// One of a fixed set of strings, in the eval contract's words.
pub fn choice<'a>(name: &str, value: &str, options: &[&'a str]) -> PyResult<&'a str> {
    options
        .iter()
        .find(|o| **o == value)
        .copied()
        .ok_or_else(|| {
            let list: Vec<String> = options.iter().map(|o| format!("\"{o}\"")).collect();
            PyValueError::new_err(format!(
                "{name} must be one of {} (got \"{value}\")",
                list.join(", ")
            ))
        })
}

fn view(x: &[f64]) -> Result<ViewFrustum, Error> {
    ViewFrustum::new(x[0], x[1], x[2])
}

// The domain checks of the fast kernels: the crate's validation as comparisons combined with `&`
// (no branch, no `Result`), each mirroring the check it names. An element they admit is one the
// validated form accepts; the tests compare both paths (`_set_fast_path`).

/// `positive`: finite and > 0.
#[inline(always)]
fn pos(v: f64) -> bool {
    finite(v) & (v > 0.0)
}

/// `analytic::eta::near_far`: 0 < n < f, both finite, f/n finite.
#[inline(always)]
fn near_far_ok(n: f64, f: f64) -> bool {
    pos(n) & pos(f) & (f > n) & finite(f / n)
}

/// `NPrime::new` then `n_prime_at_least`: ∞, or finite with near ≤ n′.
#[inline(always)]
fn n_prime_ok(np: f64, n: f64) -> bool {
    (np == f64::INFINITY) | (pos(np) & (np >= n))
}

/// `depth_in`: z finite in [n, f].
#[inline(always)]
fn depth_ok(z: f64, n: f64, f: f64) -> bool {
    finite(z) & (z >= n) & (z <= f)
}

/// `ViewFrustum::new(n, f, θ)` (`with_aspect` at aspect 1), given t = tan θ: whether the
/// frustum is in the type's domain.
#[inline(always)]
fn view_ok(n: f64, f: f64, th: f64, t: f64) -> bool {
    pos(n)
        & pos(f)
        & (f > n)
        & finite(th)
        & (th > 0.0)
        & (th < std::f64::consts::FRAC_PI_2)
        & normal(t)
        & (t > 0.0)
        & finite(f * t)
        & finite(f / n)
        // n + √(f n) finite; f·n normal also lets the twins take √(f n) as one square root.
        & normal(f * n)
        & normal(n * t)
}

/// A conservative subset of [`view_ok`]'s domain that needs no tan θ (for the forms whose value
/// does not use it): every frustum it admits, `ViewFrustum::new` accepts. tan θ ≥ θ on (0, π/2),
/// so θ ≥ 1e-300 and n θ ≥ 1e-290 keep tan θ and n tan θ normal; tan θ < 1.7e16 for every f64
/// below π/2, so f ≤ 1e290 keeps f tan θ and n + √(f n) finite.
#[inline(always)]
fn view_ok_no_tan(n: f64, f: f64, th: f64) -> bool {
    pos(n)
        & pos(f)
        & (f > n)
        & (f <= 1e290)
        & finite(f / n)
        & (1e-300..std::f64::consts::FRAC_PI_2).contains(&th)
        & (n * th >= 1e-290)
}

/// `NPrime::named`: ∞, or finite and > 0 (Zhang's λ, a tilted light's n′: no bound by near).
#[inline(always)]
fn warp_ok(v: f64) -> bool {
    (v == f64::INFINITY) | pos(v)
}

/// `LightAngle::new`: γ finite in [0, π/2].
#[inline(always)]
fn angle_ok(g: f64) -> bool {
    finite(g) & (0.0..=std::f64::consts::FRAC_PI_2).contains(&g)
}

/// `point_in_view` of `analytic::global` given t = tan θ: z in [n, f], y finite with
/// |y| ≤ z tan θ (1 + 1e-12), the same product as the check.
#[inline(always)]
fn point_ok(y: f64, z: f64, n: f64, f: f64, t: f64) -> bool {
    depth_ok(z, n, f) & finite(y) & (y.abs() <= z * t * (1.0 + 1e-12))
}

/// `v.is_normal()` with float compares only (see `broadcast::finite`).
#[inline(always)]
fn normal(v: f64) -> bool {
    let a = v.abs();
    finite(a) & (a >= f64::MIN_POSITIVE)
}

/// The argument's name in messages: a Rust parameter `lambda_` is the contract's `lambda`.
fn arg_name(rust: &'static str) -> &'static str {
    rust.strip_suffix('_').unwrap_or(rust)
}

/// One element-wise closed form as a Python function: its float arguments (required, then the
/// optional resolutions defaulting to 1), the output spec, the validated form (`checked`, over
/// the arguments in order) and optionally the fast kernel (`fast`, see `broadcast::map_fast`).
macro_rules! elementwise {
    (
        $(#[$meta:meta])*
        fn $name:ident($($req:ident),+ $(; $($opt:ident),+)?) -> $spec:expr;
        checked = $checked:expr;
        $(fast $(($($tan:tt)+))? = $fast:expr;)?
    ) => {
        $(#[$meta])*
        #[pyfunction]
        #[pyo3(signature = ($($req),+ $(, $($opt = None),+)?, *, out = None))]
        #[allow(clippy::too_many_arguments)]
        pub fn $name<'py>(
            py: Python<'py>,
            $($req: &Any<'py>,)+
            $($($opt: Option<&Any<'py>>,)+)?
            out: Option<&Any<'py>>,
        ) -> PyResult<Any<'py>> {
            #[allow(unused_variables)]
            let one = one(py);
            $($(let $opt = $opt.unwrap_or(&one);)+)?
            let args = [
                $((arg_name(stringify!($req)), $req),)+
                $($((arg_name(stringify!($opt)), $opt),)+)?
            ];
            elementwise!(@call py, args, out, $spec, $checked $(, $fast, tan_of!($($($tan)+)?))?)
        }
    };
    (@call $py:ident, $args:ident, $out:ident, $spec:expr, $checked:expr) => {
        map($py, $args, $spec, $checked, $out)
    };
    (@call $py:ident, $args:ident, $out:ident, $spec:expr, $checked:expr, $fast:expr, $tan:expr) => {
        map_fast($py, $args, $spec, $checked, $fast, $tan, $out)
    };
}

/// `fast(half_fov)`: the kernel receives tan θ of argument 2 (every form with a `ViewFrustum`
/// has near, far, half_fov first); `fast(half_fov at i)`: of argument i; `fast`: it receives 0.
macro_rules! tan_of {
    () => {
        None
    };
    (half_fov) => {
        Some(2)
    };
    (half_fov at $i:literal) => {
        Some($i)
    };
}

elementwise! {
    /// The x error at depth z, light overhead (Lloyd 2006 Eq 7; Lloyd 2005 Eq 8).
    ///
    ///     m_x = (res_image / res_s) · f (n′ + z − n) / (z (n′ + f − n)),   m_x = (res_image / res_s) f / z for n′ = ∞
    ///
    /// n = near, f = far, n′ = n_prime (≥ near; ``inf`` for the unwarped map), z = depth in [near, far].
    fn mx(near, far, n_prime, z; res_image, res_s) -> POSITIVE;
    checked = |&[n, f, np, z, ri, rs]: &[f64; 6]| {
        overhead::mx(n, f, n_prime_arg("n_prime", np)?, z, Resolutions::new(ri, rs, 1.0)?)
    };
    fast = |&[n, f, np, z, ri, rs]: &[f64; 6], _: f64| {
        let ok = near_far_ok(n, f) & n_prime_ok(np, n) & depth_ok(z, n, f) & pos(ri) & pos(rs);
        (overhead::mx_unchecked(n, f, np, z, ri, rs), ok)
    };
}

elementwise! {
    /// The z error at depth z, light overhead (Lloyd 2006 Eq 8).
    ///
    ///     m_z = (res_image / res_t) · (f − n)/(2 tan θ) · (n′ + z − n)² / (z n′ (n′ + f − n))
    ///     m_z = (res_image / res_t) · (f − n)/(2 tan θ) · 1/z                 for n′ = ∞
    ///
    /// n = near, f = far, θ = half_fov, n′ = n_prime (≥ near, or ``inf``), z in [near, far].
    fn mz(near, far, half_fov, n_prime, z; res_image, res_t) -> POSITIVE;
    checked = |&[n, f, th, np, z, ri, rt]: &[f64; 7]| {
        overhead::mz(
            &view(&[n, f, th])?,
            n_prime_arg("n_prime", np)?,
            z,
            Resolutions::new(ri, 1.0, rt)?,
        )
    };
    fast(half_fov) = |&[n, f, th, np, z, ri, rt]: &[f64; 7], t: f64| {
        let vok = view_ok(n, f, th, t);
        let ok = vok & n_prime_ok(np, n) & depth_ok(z, n, f) & pos(ri) & pos(rt);
        (overhead::mz_unchecked(n, f, t, np, z, ri, rt), ok)
    };
}

elementwise! {
    /// The maximum x error over the frustum, light overhead (Lloyd 2006 Eq 9): m_x at z = near,
    ///
    ///     M_x = (res_image / res_s) · f n′ / (n (n′ + f − n)),   M_x = (res_image / res_s) f / n for n′ = ∞
    fn max_mx(near, far, n_prime; res_image, res_s) -> POSITIVE;
    checked = |&[n, f, np, ri, rs]: &[f64; 5]| {
        overhead::max_mx(n, f, n_prime_arg("n_prime", np)?, Resolutions::new(ri, rs, 1.0)?)
    };
    fast = |&[n, f, np, ri, rs]: &[f64; 5], _: f64| {
        // max_mx is mx at z = near, which depth_in always admits.
        let ok = near_far_ok(n, f) & n_prime_ok(np, n) & pos(ri) & pos(rs);
        (overhead::mx_unchecked(n, f, np, n, ri, rs), ok)
    };
}

elementwise! {
    /// The maximum z error over the frustum, light overhead (Lloyd 2006 Eq 10):
    ///
    ///     M_z = (res_image / res_t) · (f − n)/(2 tan θ) · (n′ + f − n)/(f n′)     n ≤ n′ ≤ n + √(f n)
    ///     M_z = (res_image / res_t) · (f − n)/(2 tan θ) · n′/((n′ + f − n) n)     n′ > n + √(f n)
    ///     M_z = (res_image / res_t) · (f − n)/(2 tan θ n)                          n′ = ∞
    fn max_mz(near, far, half_fov, n_prime; res_image, res_t) -> POSITIVE;
    checked = |&[n, f, th, np, ri, rt]: &[f64; 6]| {
        overhead::max_mz(
            &view(&[n, f, th])?,
            n_prime_arg("n_prime", np)?,
            Resolutions::new(ri, 1.0, rt)?,
        )
    };
    fast(half_fov) = |&[n, f, th, np, ri, rt]: &[f64; 6], t: f64| {
        let vok = view_ok(n, f, th, t);
        let ok = vok & n_prime_ok(np, n) & pos(ri) & pos(rt);
        (overhead::max_mz_unchecked(n, f, t, np, ri, rt), ok)
    };
}

elementwise! {
    /// The storage factor S̄ = M_x M_z, light overhead (Lloyd 2006 Eq 12):
    ///
    ///     S̄ = (f/n − 1) / (2 tan θ)                                  n ≤ n′ ≤ n + √(f n)
    ///     S̄ = (f/n − 1) / (2 tan θ) · n′² f / (n (n′ + f − n)²)      n′ > n + √(f n)
    ///     S̄ = (f/n − 1) / (2 tan θ) · f / n                          n′ = ∞
    fn storage_factor(near, far, half_fov, n_prime) -> SCALAR;
    checked = |&[n, f, th, np]: &[f64; 4]| {
        overhead::storage_factor(&view(&[n, f, th])?, n_prime_arg("n_prime", np)?)
    };
    fast(half_fov) = |&[n, f, th, np]: &[f64; 4], t: f64| {
        let vok = view_ok(n, f, th, t);
        (overhead::storage_factor_unchecked(n, f, t, np), vok & n_prime_ok(np, n))
    };
}

/// The shadow-map resolution ``[res_s, res_t]`` (last axis) for a texel budget S₀ = budget with
/// the error split equally (Lloyd 2006 Eq 13, 14):
///
///     res_s / res_t = M_x / M_z,   res_s · res_t = S₀
///
/// res_image is validated but does not change the answer (only the ratio enters).
#[pyfunction]
#[pyo3(signature = (near, far, half_fov, n_prime, budget, res_image=None, *, out=None))]
#[allow(clippy::too_many_arguments)]
pub fn critical_resolution<'py>(
    py: Python<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    half_fov: &Any<'py>,
    n_prime: &Any<'py>,
    budget: &Any<'py>,
    res_image: Option<&Any<'py>>,
    out: Option<&Any<'py>>,
) -> PyResult<Any<'py>> {
    let one = one(py);
    let ri = res_image.unwrap_or(&one);
    map_into(
        py,
        [
            ("near", near),
            ("far", far),
            ("half_fov", half_fov),
            ("n_prime", n_prime),
            ("budget", budget),
            ("res_image", ri),
        ],
        OutSpec {
            width: Some(2),
            allow_inf: false,
            positive: false,
        },
        |x, o| {
            let v = view(x)?;
            let np = n_prime_arg("n_prime", x[3])?;
            Resolutions::new(x[5], 1.0, 1.0)?;
            let r = overhead::budget_resolution(&v, np, x[4])?;
            o[0] = r.res_s;
            o[1] = r.res_t;
            Ok(())
        },
        out,
    )
}

elementwise! {
    /// LiSPSM's warp parameter for the light overhead (Lloyd 2006 §4.1; Wimmer et al. 2004):
    ///
    ///     n′ = n + √(f n)
    fn n_prime_lispsm(near, far) -> SCALAR;
    checked = |&[n, f]: &[f64; 2]| eta::n_prime_lispsm(n, f);
    fast = |&[n, f]: &[f64; 2], _: f64| {
        // The twin's precondition: f·n normal.
        (eta::n_prime_lispsm_unchecked(n, f), near_far_ok(n, f) & normal(f * n))
    };
}

elementwise! {
    /// n′ from η ∈ [−1, 1] (Lloyd 2006 Eq 11), α = f/n; ``inf`` for η = −1 (unwarped):
    ///
    ///     n′ = n (√α + 1 − η (α − 1)) / (η + 1)     −1 ≤ η ≤ 0
    ///     n′ = n (√α + 1) / (η √α + 1)              0 < η ≤ 1
    fn n_prime_from_eta(near, far, eta) -> N_PRIME;
    checked = |&[n, f, e]: &[f64; 3]| Ok(eta::n_prime_from_eta(n, f, e)?.value());
    fast = |&[n, f, e]: &[f64; 3], _: f64| {
        let v = eta::n_prime_from_eta_unchecked(n, f, e);
        // in_closed("eta", −1, 1); for η > 0 an overflow to ∞ is an error, not the unwarped map.
        let ok = near_far_ok(n, f)
            & finite(e)
            & (-1.0..=1.0).contains(&e)
            & ((e <= 0.0) | finite(v));
        (v, ok)
    };
}

elementwise! {
    /// η from n′, the inverse of Lloyd 2006 Eq 11 (App. B); n_prime ≥ near, ``inf`` gives η = −1.
    fn eta_from_n_prime(near, far, n_prime) -> SCALAR;
    checked = |&[n, f, np]: &[f64; 3]| eta::eta_from_n_prime(n, f, n_prime_arg("n_prime", np)?);
    fast = |&[n, f, np]: &[f64; 3], _: f64| {
        (eta::eta_from_n_prime_unchecked(n, f, np), near_far_ok(n, f) & n_prime_ok(np, n))
    };
}

elementwise! {
    /// Lloyd 2005's distribution g(z) with the frustum normalised to near = 1, far = alpha
    /// (Lloyd 2005 Eq 3), warp parameter n_warp (``inf``: unwarped), z in [1, alpha]:
    ///
    ///     g(z) = (z − 1 + n)² / (z n (n + α − 1)),   g(z) = 1/z for n = ∞   (n = n_warp ≥ 1)
    fn distribution_g(alpha, n_warp, z) -> SCALAR;
    checked = |&[a, nw, z]: &[f64; 3]| {
        subdivided::distribution_g(a, n_prime_arg("n_warp", nw)?, z)
    };
    fast = |&[a, nw, z]: &[f64; 3], _: f64| {
        let ok = pos(a)
            & (a > 1.0)
            & ((nw == f64::INFINITY) | (pos(nw) & (nw >= 1.0)))
            & finite(z)
            & (z >= 1.0)
            & (z <= a);
        (subdivided::distribution_g_unchecked(a, nw, z), ok)
    };
}

elementwise! {
    /// The maximum error with k face subdivisions (Lloyd 2005 Eq 7), α = alpha = f/n, ξ = eta:
    ///
    ///     m_max = k (res_image / res_s) / (2 tan θ) · (α^{1/k} − 1)/α^{1/2k} · (1 + |ξ| (α^{1/2k} − 1))
    ///
    /// k is a whole number ≥ 1 (an integer array broadcasts like the others).
    fn subdivided_max_error(alpha, k, eta, half_fov; res_image, res_s) -> POSITIVE;
    checked = |&[a, k, e, th, ri, rs]: &[f64; 6]| {
        subdivided::subdivided_max_error(a, count("k", k)?, e, th, ri, rs)
    };
    fast(half_fov at 3) = |&[a, k, e, th, ri, rs]: &[f64; 6], t: f64| {
        // `count`: k whole in [1, 10⁶] (the cast is exact there and truncates a fraction).
        let ku = k as usize;
        let ok = pos(a)
            & (a > 1.0)
            & (1.0..=1e6).contains(&k)
            & (ku as f64 == k)
            & finite(th)
            & (th > 0.0)
            & (th < std::f64::consts::FRAC_PI_2)
            & finite(e)
            & (-1.0..=1.0).contains(&e)
            & pos(ri)
            & pos(rs);
        (subdivided::subdivided_max_error_unchecked(a, ku, e, t, ri, rs), ok)
    };
}

/// Texels per subdivision (along the split direction) in proportion to each subdivision's
/// maximum error (Lloyd 2005 Eq 6):
///
///     r_si = total · e_i / Σ_j e_j
///
/// errors: a 1-D array (each > 0); total: a number > 0. Returns a 1-D float64 array.
#[pyfunction]
#[pyo3(signature = (errors, total, *, out=None))]
pub fn allocate_texels<'py>(
    py: Python<'py>,
    errors: &Any<'py>,
    #[pyo3(from_py_with = args::total)] total: f64,
    out: Option<&Any<'py>>,
) -> PyResult<Any<'py>> {
    let e = crate::broadcast::FloatArg::extract("errors", errors)?;
    let values: Vec<f64> = match &e {
        crate::broadcast::FloatArg::Number(_) => {
            return Err(PyValueError::new_err(
                "errors must be a 1-D array of numbers (got a number)",
            ))
        }
        crate::broadcast::FloatArg::Array(a) => {
            if a.ndim() != 1 {
                return Err(PyValueError::new_err(format!(
                    "errors must be a 1-D array (got shape {})",
                    crate::broadcast::fmt_shape(a.shape())
                )));
            }
            crate::broadcast::values_of(a)?
        }
    };
    let target = crate::out::Out::new(out, &[values.len()], false)?;
    if let Some((i, v)) = values.iter().enumerate().find(|(_, v)| !v.is_finite()) {
        return Err(PyValueError::new_err(format!(
            "errors must hold finite numbers (errors[{i}] is {v})"
        )));
    }
    let mut out = crate::broadcast::buffer(values.len(), &[values.len()])?;
    out.resize(values.len(), 0.0);
    // On a thread of its own, Ctrl-C seen while it runs (a billion errors take seconds).
    let out = crate::interrupt::off_thread(py, move || {
        subdivided::allocate_texels(&values, total, &mut out).map(|()| out)
    })?
    .map_err(|e| crate::broadcast::value_error(&e))?;
    drop(e);
    target.deliver(py, vec![out.len()], out)
}

/// The k + 1 split planes from near to far (last axis), near and far broadcast:
///
///     "self_similar":  z_i = n (f/n)^{i/k}                                  (Lloyd 2006 Eq 15, 16)
///     "uniform":       z_i = n + (f − n) i/k
///     "practical":     z_i = λ n (f/n)^{i/k} + (1 − λ)(n + (f − n) i/k)      (lambda_ ∈ [0, 1])
///     "adaptive":      Barroso Eq 19 with light_angle γ ∈ [0, π/2] and ratio α > 1
///
/// k (a whole number ≥ 1, at most 16) is one number, since it sets the length of the last axis.
#[pyfunction]
#[pyo3(signature = (near, far, k, scheme, lambda_=None, light_angle=None, ratio=None, *, out=None))]
#[allow(clippy::too_many_arguments)]
pub fn z_partition<'py>(
    py: Python<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    #[pyo3(from_py_with = args::k_real)] k: f64,
    #[pyo3(from_py_with = args::scheme)] scheme: &str,
    lambda_: Option<&Any<'py>>,
    light_angle: Option<&Any<'py>>,
    ratio: Option<&Any<'py>>,
    out: Option<&Any<'py>>,
) -> PyResult<Any<'py>> {
    let scheme = choice(
        "scheme",
        scheme,
        &["self_similar", "uniform", "practical", "adaptive"],
    )?;
    let k = count("k", k).map_err(|e| crate::broadcast::value_error(&e))?;
    let owner = |arg: &str| {
        if arg == "lambda_" {
            "practical"
        } else {
            "adaptive"
        }
    };
    for (arg, given) in [
        ("lambda_", lambda_.is_some()),
        ("light_angle", light_angle.is_some()),
        ("ratio", ratio.is_some()),
    ] {
        let needed = owner(arg) == scheme;
        if given && !needed {
            return Err(PyValueError::new_err(format!(
                "{arg} is not an argument of z_partition with scheme \"{scheme}\" (only of scheme \"{}\")",
                owner(arg)
            )));
        }
        if needed && !given {
            return Err(PyValueError::new_err(format!(
                "{arg} is missing (scheme \"{scheme}\" needs it)"
            )));
        }
    }
    let zero = 0f64.into_pyobject(py)?.into_any();
    let spec = OutSpec {
        width: Some(k + 1),
        allow_inf: false,
        positive: false,
    };
    let a = lambda_.or(light_angle).unwrap_or(&zero);
    let b = ratio.unwrap_or(&zero);
    let (na, nb) = match scheme {
        "practical" => ("lambda", "unused"),
        "adaptive" => ("light_angle", "ratio"),
        _ => ("unused", "unused"),
    };
    map_into(
        py,
        [("near", near), ("far", far), (na, a), (nb, b)],
        spec,
        move |x, o| {
            let s = match scheme {
                "self_similar" => SplitScheme::SelfSimilar,
                "uniform" => SplitScheme::Uniform,
                "practical" => SplitScheme::Practical { lambda: x[2] },
                _ => SplitScheme::Adaptive {
                    light_angle: x[2],
                    ratio: x[3],
                },
            };
            let splits = partition::z_splits(x[0], x[1], k, s)?;
            o.copy_from_slice(splits.planes());
            Ok(())
        },
        out,
    )
}

/// The storage factor of a partitioning scheme (Lloyd 2006 Eq 17–21, App. C), summed over its
/// maps; scheme "zp", "zp_w", "fp_zp_w" or "optimal", light "overhead" or "behind". E.g. ZP+W
/// overhead (Eq 18): S̄ = k (α^{1/k} − 1)/(2 tan θ); optimal (App. C): S̄ = ln α/(2 tan θ).
/// Where the paper gives no closed form for a pair, ValueError says so. k broadcasts.
#[pyfunction]
#[pyo3(signature = (scheme, light, near, far, half_fov, k, *, out=None))]
#[allow(clippy::too_many_arguments)]
pub fn scheme_storage_factor<'py>(
    py: Python<'py>,
    #[pyo3(from_py_with = args::scheme)] scheme: &str,
    #[pyo3(from_py_with = args::light)] light: &str,
    near: &Any<'py>,
    far: &Any<'py>,
    half_fov: &Any<'py>,
    k: &Any<'py>,
    out: Option<&Any<'py>>,
) -> PyResult<Any<'py>> {
    let scheme = match choice("scheme", scheme, &["zp", "zp_w", "fp_zp_w", "optimal"])? {
        "zp" => Scheme::Zp,
        "zp_w" => Scheme::ZpW,
        "fp_zp_w" => Scheme::FpZpW,
        _ => Scheme::Optimal,
    };
    let light = match choice("light", light, &["overhead", "behind"])? {
        "overhead" => SchemeLight::Overhead,
        _ => SchemeLight::Behind,
    };
    map(
        py,
        [
            ("near", near),
            ("far", far),
            ("half_fov", half_fov),
            ("k", k),
        ],
        SCALAR,
        move |x| partition::scheme_storage_factor(scheme, light, &view(x)?, count("k", x[3])?),
        out,
    )
}

elementwise! {
    /// m_z for a tilted light (Barroso Eq 10–12), the texel width measured along the view axis
    /// (his Eq 6), light_angle γ ∈ (0, π/2] between light and view direction:
    ///
    ///     m_z(z, n′, γ) = (res_image/res_t) · (f′ − n′) ψ² / (2 tan θ · n′ f′ · z · sin γ)
    ///
    /// with ψ the warp depth of the point (Barroso Eq 10), f′ − n′ = μ the warp's depth range
    /// (Eq 11); unwarped (n′ = ∞): (res_image/res_t) μ / (2 tan θ z sin γ). At γ = π/2 it is
    /// Lloyd 2006 Eq 8.
    ///
    /// n_prime > 0 (any, since a tilted light can put the centre closer than near).
    fn tilted_mz(near, far, half_fov, n_prime, light_angle, z; res_image, res_t) -> POSITIVE;
    checked = |&[n, f, th, np, g, z, ri, rt]: &[f64; 8]| {
        tilted::tilted_mz(
            &view(&[n, f, th])?,
            n_prime_arg("n_prime", np)?,
            LightAngle::new(g)?,
            z,
            Resolutions::new(ri, 1.0, rt)?,
        )
    };
    fast(half_fov) = |&[n, f, th, np, g, z, ri, rt]: &[f64; 8], t: f64| {
        // sin γ > 0 for γ > 0 (`positive_sin`); an overflow of μ makes the value non-finite,
        // which sends the block to the validated form.
        let ok = view_ok(n, f, th, t)
            & warp_ok(np)
            & angle_ok(g)
            & (g > 0.0)
            & depth_ok(z, n, f)
            & pos(ri)
            & pos(rt);
        (tilted::tilted_mz_unchecked(n, f, th, t, np, g, z, ri, rt), ok)
    };
}

/// Barroso & Celes' generalised n′ for a tilted light (Barroso Eq 13–18): n′₁(γ) for
/// γ ≥ γ_lim, else n′₁(γ_lim)/r(γ) with the fall-off r of Eq 18 ("barroso") or Eq 17 ("zhang");
/// ``inf`` at γ = 0.
#[pyfunction]
#[pyo3(signature = (near, far, half_fov, light_angle, falloff, *, out=None))]
pub fn generalized_n_prime<'py>(
    py: Python<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    half_fov: &Any<'py>,
    light_angle: &Any<'py>,
    #[pyo3(from_py_with = args::falloff)] falloff: &str,
    out: Option<&Any<'py>>,
) -> PyResult<Any<'py>> {
    let falloff = match choice("falloff", falloff, &["barroso", "zhang"])? {
        "barroso" => tilted::Falloff::Barroso,
        _ => tilted::Falloff::Zhang,
    };
    map(
        py,
        [
            ("near", near),
            ("far", far),
            ("half_fov", half_fov),
            ("light_angle", light_angle),
        ],
        N_PRIME,
        move |x| {
            Ok(tilted::generalized_n_prime(&view(x)?, LightAngle::new(x[3])?, falloff).value())
        },
        out,
    )
}

elementwise! {
    /// The light angle below which Barroso's n′₁ is replaced by the fall-off (Barroso Eq 15):
    ///
    ///     γ_lim = atan((f + n) tan θ / (f − n))   radians
    fn gamma_lim(near, far, half_fov) -> SCALAR;
    checked = |x: &[f64; 3]| Ok(tilted::gamma_lim(&view(x)?));
    fast(half_fov) = |&[n, f, th]: &[f64; 3], t: f64| {
        (tilted::gamma_lim_unchecked(n, f, t), view_ok(n, f, th, t))
    };
}

elementwise! {
    /// TSM's η (Martin–Tan §6.2): the distance of the projection centre q from the top line that
    /// maps the focus point, δ′ below the top line of a trapezoid of height λ, to the line ξ
    /// (ξ = −0.6 is the 80 % line):
    ///
    ///     η = λ δ′ (1 + ξ) / (λ (1 − ξ) − 2 δ′)
    ///
    /// ``inf`` on the unwarped line ξ = 1 − 2δ′/λ; ValueError above it (no solution).
    fn tsm_eta(lambda_, delta_prime, xi) -> N_PRIME;
    checked = |&[l, d, xi]: &[f64; 3]| Ok(tsm::tsm_eta(l, d, xi)?.value());
    fast = |&[l, d, xi]: &[f64; 3], _: f64| {
        let v = tsm::tsm_eta_unchecked(l, d, xi);
        // λ finite > 0, δ′ in (0, λ), ξ in (−1, 1), and a finite η > 0: the unwarped line (∞)
        // and no solution (η < 0) are left to the validated form.
        let ok = pos(l) & (d > 0.0) & (d < l) & (xi > -1.0) & (xi < 1.0) & pos(v);
        (v, ok)
    };
}

elementwise! {
    /// Zhang's E_q, the perspective part of the aliasing along s, in the global representation
    /// (Zhang Eq 13 and Appendix), at eye-space (y, z) for light angle θ, warp parameter λ
    /// (`lambda_`; ``inf`` unwarped), |y| ≤ z tan φ:
    ///
    ///     E_q = 2 tan φ_w z_w / (tan φ z) = F_q (z + G)/z,   E_q = 2 f / z for λ = ∞
    ///
    /// On a [−1, 1] screen: twice the m_x the crate measures.
    fn zhang_eq(near, far, half_fov, lambda_, light_angle, y, z) -> SCALAR;
    checked = |&[n, f, th, l, g, y, z]: &[f64; 7]| {
        global::zhang_eq(&view(&[n, f, th])?, n_prime_arg("lambda", l)?, LightAngle::new(g)?, y, z)
    };
    fast(half_fov) = |&[n, f, th, l, g, y, z]: &[f64; 7], t: f64| {
        let ok = view_ok(n, f, th, t) & warp_ok(l) & angle_ok(g) & point_ok(y, z, n, f, t);
        (global::zhang_eq_unchecked(n, f, th, t, l, g, y, z), ok)
    };
}

elementwise! {
    /// Zhang's E_p, the perspective part of the aliasing along t, in the global representation
    /// (Zhang Eq 14 and Appendix), at eye-space (y, z) for light angle θ, warp parameter λ
    /// (`lambda_`; ``inf`` unwarped), |y| ≤ z tan φ:
    ///
    ///     E_p = μ z_w² / (tan φ (λ + μ) λ z) = F_p (z + G)²/z,   E_p = μ / (tan φ z) for λ = ∞
    ///
    /// On a [−1, 1] screen: twice the m_z the crate measures.
    fn zhang_ep(near, far, half_fov, lambda_, light_angle, y, z) -> SCALAR;
    checked = |&[n, f, th, l, g, y, z]: &[f64; 7]| {
        global::zhang_ep(&view(&[n, f, th])?, n_prime_arg("lambda", l)?, LightAngle::new(g)?, y, z)
    };
    fast(half_fov) = |&[n, f, th, l, g, y, z]: &[f64; 7], t: f64| {
        // An overflow of μ makes the value non-finite: the validated form then reports it.
        let ok = view_ok(n, f, th, t) & warp_ok(l) & angle_ok(g) & point_ok(y, z, n, f, t);
        (global::zhang_ep_unchecked(n, f, th, t, l, g, y, z), ok)
    };
}

elementwise! {
    /// Zhang's E_q in the local representation, light perpendicular to the view, on the view
    /// axis (Zhang Eq 8):
    ///
    ///     E_q = 2 f (z − n + λ) / ((f − n + λ) z)   for λ ≥ n
    ///     E_q = 2 n (z − n + λ) / (λ z)             for λ < n
    ///     E_q = 2 f / z for λ = ∞
    fn zhang_eq_local(near, far, half_fov, lambda_, z) -> SCALAR;
    checked = |&[n, f, th, l, z]: &[f64; 5]| {
        global::zhang_eq_local(&view(&[n, f, th])?, n_prime_arg("lambda", l)?, z)
    };
    fast = |&[n, f, th, l, z]: &[f64; 5], _: f64| {
        // The value does not use tan θ: the frustum is checked without it (conservatively).
        let ok = view_ok_no_tan(n, f, th) & warp_ok(l) & depth_ok(z, n, f);
        (global::zhang_eq_local_unchecked(n, f, l, z), ok)
    };
}

elementwise! {
    /// Zhang's E_p in the local representation, light perpendicular to the view, on the view
    /// axis (Zhang Eq 9):
    ///
    ///     E_p = (f − n)(z − n + λ)² / ((f − n + λ) λ tan φ z)   (twice Lloyd 2006 Eq 8),   E_p = (f − n)/(tan φ z) for λ = ∞
    fn zhang_ep_local(near, far, half_fov, lambda_, z) -> SCALAR;
    checked = |&[n, f, th, l, z]: &[f64; 5]| {
        global::zhang_ep_local(&view(&[n, f, th])?, n_prime_arg("lambda", l)?, z)
    };
    fast(half_fov) = |&[n, f, th, l, z]: &[f64; 5], t: f64| {
        let ok = view_ok(n, f, th, t) & warp_ok(l) & depth_ok(z, n, f);
        (global::zhang_ep_local_unchecked(n, f, t, l, z), ok)
    };
}

/// The Python float 1.0, the default of the resolutions.
fn one(py: Python<'_>) -> Bound<'_, PyAny> {
    1f64.into_pyobject(py)
        .map(|f| f.into_any())
        .unwrap_or_else(|e| match e {})
}
