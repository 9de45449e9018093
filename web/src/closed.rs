//! Closed forms for the papers' curves (`shadow_aliasing::analytic`), the light overhead:
//! `mx`, `mz` (Lloyd 2006 Eq 7, 8) at one depth `z` or an array of depths, `storage_factor`
//! (Eq 12), `n_prime_lispsm`, `n_prime_from_eta` and `eta_from_n_prime` (Eq 11). n′ is a
//! number, `Infinity` for the uniform map.

use crate::args::{
    field, num, number, numbers, nums, object, opt_number, req_number, WebError, WebResult,
};
use serde_json::{Map, Value};
use shadow_aliasing::analytic::{eta, overhead};
use shadow_aliasing::{NPrime, Resolutions, ViewFrustum};

/// The names `closed` answers.
pub const NAMES: &[&str] = &[
    "mx",
    "mz",
    "storage_factor",
    "n_prime_lispsm",
    "n_prime_from_eta",
    "eta_from_n_prime",
];

/// `z`: a number (answered by a number) or an array (answered by an array).
fn depths(m: &Map<String, Value>) -> WebResult<(Vec<f64>, bool)> {
    let v = field(m, "z").ok_or_else(|| WebError::invalid("z", "is missing"))?;
    match v {
        Value::Array(_) => Ok((numbers("z", v)?, true)),
        v => Ok((vec![number("z", v)?], false)),
    }
}

/// The values at each depth, as one number or an array like `z`.
fn over(
    m: &Map<String, Value>,
    f: impl Fn(f64) -> shadow_aliasing::Result<f64>,
) -> WebResult<Value> {
    let (z, array) = depths(m)?;
    let v = z
        .into_iter()
        .map(f)
        .collect::<shadow_aliasing::Result<Vec<_>>>()?;
    Ok(if array { nums(v) } else { num(v[0]) })
}

/// `closed`: the closed form `name` with its `args`.
pub fn closed(req: &Map<String, Value>) -> WebResult<Value> {
    let name = crate::args::opt_str(req, "name")?
        .ok_or_else(|| WebError::invalid("name", "is missing (one of the closed forms)"))?;
    let name = crate::args::choice("name", name, NAMES)?;
    let keys: &[&str] = match name {
        "mx" => &["near", "far", "n_prime", "z", "res_image", "res_s"],
        "mz" => &[
            "near",
            "far",
            "half_fov",
            "n_prime",
            "z",
            "res_image",
            "res_t",
        ],
        "storage_factor" => &["near", "far", "half_fov", "n_prime"],
        "n_prime_lispsm" => &["near", "far"],
        "n_prime_from_eta" => &["near", "far", "eta"],
        _ => &["near", "far", "n_prime"],
    };
    let m = object("args", req.get("args").unwrap_or(&Value::Null), keys)?;
    let (near, far) = (req_number(m, "near")?, req_number(m, "far")?);
    let n_prime = || -> WebResult<NPrime> { Ok(NPrime::new(req_number(m, "n_prime")?)?) };
    let view = || -> WebResult<ViewFrustum> {
        Ok(ViewFrustum::new(near, far, req_number(m, "half_fov")?)?)
    };
    let res_image = opt_number(m, "res_image")?.unwrap_or(1.0);
    Ok(match name {
        "mx" => {
            let res = Resolutions::new(res_image, opt_number(m, "res_s")?.unwrap_or(1.0), 1.0)?;
            let np = n_prime()?;
            over(m, |z| overhead::mx(near, far, np, z, res))?
        }
        "mz" => {
            let res = Resolutions::new(res_image, 1.0, opt_number(m, "res_t")?.unwrap_or(1.0))?;
            let (v, np) = (view()?, n_prime()?);
            over(m, |z| overhead::mz(&v, np, z, res))?
        }
        "storage_factor" => num(overhead::storage_factor(&view()?, n_prime()?)?),
        "n_prime_lispsm" => num(eta::n_prime_lispsm(near, far)?),
        "n_prime_from_eta" => num(eta::n_prime_from_eta(near, far, req_number(m, "eta")?)?.value()),
        _ => num(eta::eta_from_n_prime(near, far, n_prime()?)?),
    })
}
