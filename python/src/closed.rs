//! The closed forms of the eval contract (docs/eval.md), element-wise on NumPy arrays.
//!
//! Argument names are the contract's, except Zhang's and Martin–Tan's `lambda`, a Python keyword,
//! spelled `lambda_`. Angles in radians.

use crate::broadcast::{count, map, map_into, OutSpec, N_PRIME, SCALAR};
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

/// The x error at depth z, light overhead (Lloyd 2006 Eq 7; Lloyd 2005 Eq 8).
///
///     m_x = (res_image / res_s) · f (n′ + z − n) / (z (n′ + f − n)),   m_x = (res_image / res_s) f / z for n′ = ∞
///
/// n = near, f = far, n′ = n_prime (≥ near; ``inf`` for the unwarped map), z = depth in [near, far].
#[pyfunction]
#[pyo3(signature = (near, far, n_prime, z, res_image=None, res_s=None))]
pub fn mx<'py>(
    py: Python<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    n_prime: &Any<'py>,
    z: &Any<'py>,
    res_image: Option<&Any<'py>>,
    res_s: Option<&Any<'py>>,
) -> PyResult<Any<'py>> {
    let one = one(py);
    let (ri, rs) = (res_image.unwrap_or(&one), res_s.unwrap_or(&one));
    map(
        py,
        [
            ("near", near),
            ("far", far),
            ("n_prime", n_prime),
            ("z", z),
            ("res_image", ri),
            ("res_s", rs),
        ],
        SCALAR,
        |x| {
            overhead::mx(
                x[0],
                x[1],
                n_prime_arg("n_prime", x[2])?,
                x[3],
                Resolutions::new(x[4], x[5], 1.0)?,
            )
        },
    )
}

/// The z error at depth z, light overhead (Lloyd 2006 Eq 8).
///
///     m_z = (res_image / res_t) · (f − n)/(2 tan θ) · (n′ + z − n)² / (z n′ (n′ + f − n))
///     m_z = (res_image / res_t) · (f − n)/(2 tan θ) · 1/z                 for n′ = ∞
///
/// n = near, f = far, θ = half_fov, n′ = n_prime (≥ near, or ``inf``), z in [near, far].
#[pyfunction]
#[pyo3(signature = (near, far, half_fov, n_prime, z, res_image=None, res_t=None))]
#[allow(clippy::too_many_arguments)]
pub fn mz<'py>(
    py: Python<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    half_fov: &Any<'py>,
    n_prime: &Any<'py>,
    z: &Any<'py>,
    res_image: Option<&Any<'py>>,
    res_t: Option<&Any<'py>>,
) -> PyResult<Any<'py>> {
    let one = one(py);
    let (ri, rt) = (res_image.unwrap_or(&one), res_t.unwrap_or(&one));
    map(
        py,
        [
            ("near", near),
            ("far", far),
            ("half_fov", half_fov),
            ("n_prime", n_prime),
            ("z", z),
            ("res_image", ri),
            ("res_t", rt),
        ],
        SCALAR,
        |x| {
            overhead::mz(
                &view(x)?,
                n_prime_arg("n_prime", x[3])?,
                x[4],
                Resolutions::new(x[5], 1.0, x[6])?,
            )
        },
    )
}

/// The maximum x error over the frustum, light overhead (Lloyd 2006 Eq 9): m_x at z = near,
///
///     M_x = (res_image / res_s) · f n′ / (n (n′ + f − n)),   M_x = (res_image / res_s) f / n for n′ = ∞
#[pyfunction]
#[pyo3(signature = (near, far, n_prime, res_image=None, res_s=None))]
pub fn max_mx<'py>(
    py: Python<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    n_prime: &Any<'py>,
    res_image: Option<&Any<'py>>,
    res_s: Option<&Any<'py>>,
) -> PyResult<Any<'py>> {
    let one = one(py);
    let (ri, rs) = (res_image.unwrap_or(&one), res_s.unwrap_or(&one));
    map(
        py,
        [
            ("near", near),
            ("far", far),
            ("n_prime", n_prime),
            ("res_image", ri),
            ("res_s", rs),
        ],
        SCALAR,
        |x| {
            overhead::max_mx(
                x[0],
                x[1],
                n_prime_arg("n_prime", x[2])?,
                Resolutions::new(x[3], x[4], 1.0)?,
            )
        },
    )
}

/// The maximum z error over the frustum, light overhead (Lloyd 2006 Eq 10):
///
///     M_z = (res_image / res_t) · (f − n)/(2 tan θ) · (n′ + f − n)/(f n′)     n ≤ n′ ≤ n + √(f n)
///     M_z = (res_image / res_t) · (f − n)/(2 tan θ) · n′/((n′ + f − n) n)     n′ > n + √(f n)
///     M_z = (res_image / res_t) · (f − n)/(2 tan θ n)                          n′ = ∞
#[pyfunction]
#[pyo3(signature = (near, far, half_fov, n_prime, res_image=None, res_t=None))]
pub fn max_mz<'py>(
    py: Python<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    half_fov: &Any<'py>,
    n_prime: &Any<'py>,
    res_image: Option<&Any<'py>>,
    res_t: Option<&Any<'py>>,
) -> PyResult<Any<'py>> {
    let one = one(py);
    let (ri, rt) = (res_image.unwrap_or(&one), res_t.unwrap_or(&one));
    map(
        py,
        [
            ("near", near),
            ("far", far),
            ("half_fov", half_fov),
            ("n_prime", n_prime),
            ("res_image", ri),
            ("res_t", rt),
        ],
        SCALAR,
        |x| {
            overhead::max_mz(
                &view(x)?,
                n_prime_arg("n_prime", x[3])?,
                Resolutions::new(x[4], 1.0, x[5])?,
            )
        },
    )
}

/// The storage factor S̄ = M_x M_z, light overhead (Lloyd 2006 Eq 12):
///
///     S̄ = (f/n − 1) / (2 tan θ)                                  n ≤ n′ ≤ n + √(f n)
///     S̄ = (f/n − 1) / (2 tan θ) · n′² f / (n (n′ + f − n)²)      n′ > n + √(f n)
///     S̄ = (f/n − 1) / (2 tan θ) · f / n                          n′ = ∞
#[pyfunction]
pub fn storage_factor<'py>(
    py: Python<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    half_fov: &Any<'py>,
    n_prime: &Any<'py>,
) -> PyResult<Any<'py>> {
    map(
        py,
        [
            ("near", near),
            ("far", far),
            ("half_fov", half_fov),
            ("n_prime", n_prime),
        ],
        SCALAR,
        |x| overhead::storage_factor(&view(x)?, n_prime_arg("n_prime", x[3])?),
    )
}

/// The shadow-map resolution ``[res_s, res_t]`` (last axis) for a texel budget S₀ = budget with
/// the error split equally (Lloyd 2006 Eq 13, 14):
///
///     res_s / res_t = M_x / M_z,   res_s · res_t = S₀
///
/// res_image is validated but does not change the answer (only the ratio enters).
#[pyfunction]
#[pyo3(signature = (near, far, half_fov, n_prime, budget, res_image=None))]
pub fn critical_resolution<'py>(
    py: Python<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    half_fov: &Any<'py>,
    n_prime: &Any<'py>,
    budget: &Any<'py>,
    res_image: Option<&Any<'py>>,
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
    )
}

/// LiSPSM's warp parameter for the light overhead (Lloyd 2006 §4.1; Wimmer et al. 2004):
///
///     n′ = n + √(f n)
#[pyfunction]
pub fn n_prime_lispsm<'py>(py: Python<'py>, near: &Any<'py>, far: &Any<'py>) -> PyResult<Any<'py>> {
    map(py, [("near", near), ("far", far)], SCALAR, |x| {
        eta::n_prime_lispsm(x[0], x[1])
    })
}

/// n′ from η ∈ [−1, 1] (Lloyd 2006 Eq 11), α = f/n; ``inf`` for η = −1 (unwarped):
///
///     n′ = n (√α + 1 − η (α − 1)) / (η + 1)     −1 ≤ η ≤ 0
///     n′ = n (√α + 1) / (η √α + 1)              0 < η ≤ 1
#[pyfunction]
pub fn n_prime_from_eta<'py>(
    py: Python<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    eta: &Any<'py>,
) -> PyResult<Any<'py>> {
    map(
        py,
        [("near", near), ("far", far), ("eta", eta)],
        N_PRIME,
        |x| Ok(eta::n_prime_from_eta(x[0], x[1], x[2])?.value()),
    )
}

/// η from n′, the inverse of Lloyd 2006 Eq 11 (App. B); n_prime ≥ near, ``inf`` gives η = −1.
#[pyfunction]
pub fn eta_from_n_prime<'py>(
    py: Python<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    n_prime: &Any<'py>,
) -> PyResult<Any<'py>> {
    map(
        py,
        [("near", near), ("far", far), ("n_prime", n_prime)],
        SCALAR,
        |x| eta::eta_from_n_prime(x[0], x[1], n_prime_arg("n_prime", x[2])?),
    )
}

/// Lloyd 2005's distribution g(z) with the frustum normalised to near = 1, far = alpha
/// (Lloyd 2005 Eq 3), warp parameter n_warp (``inf``: unwarped), z in [1, alpha]:
///
///     g(z) = (z − 1 + n)² / (z n (n + α − 1)),   g(z) = 1/z for n = ∞   (n = n_warp ≥ 1)
#[pyfunction]
pub fn distribution_g<'py>(
    py: Python<'py>,
    alpha: &Any<'py>,
    n_warp: &Any<'py>,
    z: &Any<'py>,
) -> PyResult<Any<'py>> {
    map(
        py,
        [("alpha", alpha), ("n_warp", n_warp), ("z", z)],
        SCALAR,
        |x| subdivided::distribution_g(x[0], n_prime_arg("n_warp", x[1])?, x[2]),
    )
}

/// The maximum error with k face subdivisions (Lloyd 2005 Eq 7), α = alpha = f/n, ξ = eta:
///
///     m_max = k (res_image / res_s) / (2 tan θ) · (α^{1/k} − 1)/α^{1/2k} · (1 + |ξ| (α^{1/2k} − 1))
///
/// k is a whole number ≥ 1 (an integer array broadcasts like the others).
#[pyfunction]
#[pyo3(signature = (alpha, k, eta, half_fov, res_image=None, res_s=None))]
pub fn subdivided_max_error<'py>(
    py: Python<'py>,
    alpha: &Any<'py>,
    k: &Any<'py>,
    eta: &Any<'py>,
    half_fov: &Any<'py>,
    res_image: Option<&Any<'py>>,
    res_s: Option<&Any<'py>>,
) -> PyResult<Any<'py>> {
    let one = one(py);
    let (ri, rs) = (res_image.unwrap_or(&one), res_s.unwrap_or(&one));
    map(
        py,
        [
            ("alpha", alpha),
            ("k", k),
            ("eta", eta),
            ("half_fov", half_fov),
            ("res_image", ri),
            ("res_s", rs),
        ],
        SCALAR,
        |x| subdivided::subdivided_max_error(x[0], count("k", x[1])?, x[2], x[3], x[4], x[5]),
    )
}

/// Texels per subdivision (along the split direction) in proportion to each subdivision's
/// maximum error (Lloyd 2005 Eq 6):
///
///     r_si = total · e_i / Σ_j e_j
///
/// errors: a 1-D array (each > 0); total: a number > 0. Returns a 1-D float64 array.
#[pyfunction]
pub fn allocate_texels<'py>(py: Python<'py>, errors: &Any<'py>, total: f64) -> PyResult<Any<'py>> {
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
            a.as_array().iter().copied().collect()
        }
    };
    if let Some((i, v)) = values.iter().enumerate().find(|(_, v)| !v.is_finite()) {
        return Err(PyValueError::new_err(format!(
            "errors must hold finite numbers (errors[{i}] is {v})"
        )));
    }
    let mut out = vec![0.0; values.len()];
    subdivided::allocate_texels(&values, total, &mut out)
        .map_err(|e| crate::broadcast::value_error(&e))?;
    crate::broadcast::to_python(py, vec![out.len()], out)
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
#[pyo3(signature = (near, far, k, scheme, lambda_=None, light_angle=None, ratio=None))]
#[allow(clippy::too_many_arguments)]
pub fn z_partition<'py>(
    py: Python<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    k: f64,
    scheme: &str,
    lambda_: Option<&Any<'py>>,
    light_angle: Option<&Any<'py>>,
    ratio: Option<&Any<'py>>,
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
    )
}

/// The storage factor of a partitioning scheme (Lloyd 2006 Eq 17–21, App. C), summed over its
/// maps; scheme "zp", "zp_w", "fp_zp_w" or "optimal", light "overhead" or "behind". E.g. ZP+W
/// overhead (Eq 18): S̄ = k (α^{1/k} − 1)/(2 tan θ); optimal (App. C): S̄ = ln α/(2 tan θ).
/// Where the paper gives no closed form for a pair, ValueError says so. k broadcasts.
#[pyfunction]
pub fn scheme_storage_factor<'py>(
    py: Python<'py>,
    scheme: &str,
    light: &str,
    near: &Any<'py>,
    far: &Any<'py>,
    half_fov: &Any<'py>,
    k: &Any<'py>,
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
    )
}

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
#[pyfunction]
#[pyo3(signature = (near, far, half_fov, n_prime, light_angle, z, res_image=None, res_t=None))]
#[allow(clippy::too_many_arguments)]
pub fn tilted_mz<'py>(
    py: Python<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    half_fov: &Any<'py>,
    n_prime: &Any<'py>,
    light_angle: &Any<'py>,
    z: &Any<'py>,
    res_image: Option<&Any<'py>>,
    res_t: Option<&Any<'py>>,
) -> PyResult<Any<'py>> {
    let one = one(py);
    let (ri, rt) = (res_image.unwrap_or(&one), res_t.unwrap_or(&one));
    map(
        py,
        [
            ("near", near),
            ("far", far),
            ("half_fov", half_fov),
            ("n_prime", n_prime),
            ("light_angle", light_angle),
            ("z", z),
            ("res_image", ri),
            ("res_t", rt),
        ],
        SCALAR,
        |x| {
            tilted::tilted_mz(
                &view(x)?,
                n_prime_arg("n_prime", x[3])?,
                LightAngle::new(x[4])?,
                x[5],
                Resolutions::new(x[6], 1.0, x[7])?,
            )
        },
    )
}

/// Barroso & Celes' generalised n′ for a tilted light (Barroso Eq 13–18): n′₁(γ) for
/// γ ≥ γ_lim, else n′₁(γ_lim)/r(γ) with the fall-off r of Eq 18 ("barroso") or Eq 17 ("zhang");
/// ``inf`` at γ = 0.
#[pyfunction]
pub fn generalized_n_prime<'py>(
    py: Python<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    half_fov: &Any<'py>,
    light_angle: &Any<'py>,
    falloff: &str,
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
    )
}

/// The light angle below which Barroso's n′₁ is replaced by the fall-off (Barroso Eq 15):
///
///     γ_lim = atan((f + n) tan θ / (f − n))   radians
#[pyfunction]
pub fn gamma_lim<'py>(
    py: Python<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    half_fov: &Any<'py>,
) -> PyResult<Any<'py>> {
    map(
        py,
        [("near", near), ("far", far), ("half_fov", half_fov)],
        SCALAR,
        |x| Ok(tilted::gamma_lim(&view(x)?)),
    )
}

/// TSM's η (Martin–Tan §6.2): the distance of the projection centre q from the top line that
/// maps the focus point, δ′ below the top line of a trapezoid of height λ, to the line ξ
/// (ξ = −0.6 is the 80 % line):
///
///     η = λ δ′ (1 + ξ) / (λ (1 − ξ) − 2 δ′)
///
/// ``inf`` on the unwarped line ξ = 1 − 2δ′/λ; ValueError above it (no solution).
#[pyfunction]
pub fn tsm_eta<'py>(
    py: Python<'py>,
    lambda_: &Any<'py>,
    delta_prime: &Any<'py>,
    xi: &Any<'py>,
) -> PyResult<Any<'py>> {
    map(
        py,
        [
            ("lambda", lambda_),
            ("delta_prime", delta_prime),
            ("xi", xi),
        ],
        N_PRIME,
        |x| Ok(tsm::tsm_eta(x[0], x[1], x[2])?.value()),
    )
}

macro_rules! zhang_global {
    ($name:ident, $f:path, $doc:literal) => {
        #[doc = $doc]
        #[pyfunction]
        #[allow(clippy::too_many_arguments)]
        pub fn $name<'py>(
            py: Python<'py>,
            near: &Any<'py>,
            far: &Any<'py>,
            half_fov: &Any<'py>,
            lambda_: &Any<'py>,
            light_angle: &Any<'py>,
            y: &Any<'py>,
            z: &Any<'py>,
        ) -> PyResult<Any<'py>> {
            map(
                py,
                [
                    ("near", near),
                    ("far", far),
                    ("half_fov", half_fov),
                    ("lambda", lambda_),
                    ("light_angle", light_angle),
                    ("y", y),
                    ("z", z),
                ],
                SCALAR,
                |x| {
                    $f(
                        &view(x)?,
                        n_prime_arg("lambda", x[3])?,
                        LightAngle::new(x[4])?,
                        x[5],
                        x[6],
                    )
                },
            )
        }
    };
}

zhang_global!(
    zhang_eq,
    global::zhang_eq,
    "Zhang's E_q, the perspective part of the aliasing along s, in the global representation \
     (Zhang Eq 13 and Appendix), at eye-space (y, z) for light angle θ, warp parameter λ \
     (`lambda_`; ``inf`` unwarped), |y| ≤ z tan φ:\n\n    E_q = 2 tan φ_w z_w / (tan φ z) = F_q (z + G)/z,   \
     E_q = 2 f / z for λ = ∞\n\n\
     On a [−1, 1] screen: twice the m_x the crate measures."
);
zhang_global!(
    zhang_ep,
    global::zhang_ep,
    "Zhang's E_p, the perspective part of the aliasing along t, in the global representation \
     (Zhang Eq 14 and Appendix), at eye-space (y, z) for light angle θ, warp parameter λ \
     (`lambda_`; ``inf`` unwarped), |y| ≤ z tan φ:\n\n    E_p = μ z_w² / (tan φ (λ + μ) λ z) = F_p (z + G)²/z,   \
     E_p = μ / (tan φ z) for λ = ∞\n\n\
     On a [−1, 1] screen: twice the m_z the crate measures."
);

macro_rules! zhang_local {
    ($name:ident, $f:path, $doc:literal) => {
        #[doc = $doc]
        #[pyfunction]
        pub fn $name<'py>(
            py: Python<'py>,
            near: &Any<'py>,
            far: &Any<'py>,
            half_fov: &Any<'py>,
            lambda_: &Any<'py>,
            z: &Any<'py>,
        ) -> PyResult<Any<'py>> {
            map(
                py,
                [
                    ("near", near),
                    ("far", far),
                    ("half_fov", half_fov),
                    ("lambda", lambda_),
                    ("z", z),
                ],
                SCALAR,
                |x| $f(&view(x)?, n_prime_arg("lambda", x[3])?, x[4]),
            )
        }
    };
}

zhang_local!(
    zhang_eq_local,
    global::zhang_eq_local,
    "Zhang's E_q in the local representation, light perpendicular to the view, on the view \
     axis (Zhang Eq 8):\n\n    E_q = 2 f (z − n + λ) / ((f − n + λ) z)   for λ ≥ n\n    \
     E_q = 2 n (z − n + λ) / (λ z)             for λ < n\n    E_q = 2 f / z for λ = ∞"
);
zhang_local!(
    zhang_ep_local,
    global::zhang_ep_local,
    "Zhang's E_p in the local representation, light perpendicular to the view, on the view \
     axis (Zhang Eq 9):\n\n    E_p = (f − n)(z − n + λ)² / ((f − n + λ) λ tan φ z)   \
     (twice Lloyd 2006 Eq 8),   E_p = (f − n)/(tan φ z) for λ = ∞"
);

/// The Python float 1.0, the default of the resolutions.
fn one(py: Python<'_>) -> Bound<'_, PyAny> {
    1f64.into_pyobject(py)
        .map(|f| f.into_any())
        .unwrap_or_else(|e| match e {})
}
