//! The contract's table: one row per quantity, holding its name, arguments, what it answers,
//! its source and the code that computes it (../shared/eval-contract.md). A quantity's name is
//! spelled once, in its row.

use super::{ArgKind, ArgSpec, Output, Presence, Quantity, ValueKind};
use crate::analytic::{eta, global, overhead, subdivided, tilted, tsm};
use crate::error::Error;
use crate::frustum::LightAngle;

pub(super) const fn req(name: &'static str, kind: ArgKind) -> ArgSpec {
    ArgSpec {
        name,
        kind,
        presence: Presence::Required,
    }
}
const fn res(name: &'static str) -> ArgSpec {
    ArgSpec {
        name,
        kind: ArgKind::Number,
        presence: Presence::Default(1.0),
    }
}
const fn opt(name: &'static str, kind: ArgKind) -> ArgSpec {
    ArgSpec {
        name,
        kind,
        presence: Presence::Optional,
    }
}

use ArgKind::{Count, Number as Num, Numbers as NumArray};
const NEAR: ArgSpec = req("near", Num);
const FAR: ArgSpec = req("far", Num);
const HALF_FOV: ArgSpec = req("half_fov", Num);
const N_PRIME: ArgSpec = req("n_prime", ArgKind::NPrime);
const Z: ArgSpec = req("z", Num);
const RES_IMAGE: ArgSpec = res("res_image");
const RES_S: ArgSpec = res("res_s");
const RES_T: ArgSpec = res("res_t");
const LIGHT_ANGLE: ArgSpec = req("light_angle", Num);
const LAMBDA_NP: ArgSpec = req("lambda", ArgKind::NPrime);
/// Zhang's global aliasing functions' arguments (`zhang_eq`, `zhang_ep`).
const ZHANG_GLOBAL: &[ArgSpec] = &[
    NEAR,
    FAR,
    HALF_FOV,
    LAMBDA_NP,
    LIGHT_ANGLE,
    req("y", Num),
    Z,
];

/// `z_partition` schemes.
pub const Z_PARTITION_SCHEMES: &[&str] = &["self_similar", "uniform", "practical", "adaptive"];
/// `scheme_storage_factor` schemes.
pub const STORAGE_SCHEMES: &[&str] = &["zp", "zp_w", "fp_zp_w", "optimal"];
/// `scheme_storage_factor` light positions.
pub const LIGHTS: &[&str] = &["overhead", "behind"];
/// `generalized_n_prime` fall-offs r(γ).
pub const FALLOFFS: &[&str] = &["barroso", "zhang"];

/// Every quantity of the contract, in its order.
pub const QUANTITIES: &[Quantity] = &[
    Quantity {
        name: "mx",
        args: &[NEAR, FAR, N_PRIME, Z, RES_IMAGE, RES_S],
        value: ValueKind::Number,
        source: "Lloyd 2006 Eq 7 (Lloyd 2005 Eq 8)",
        compute: |a| {
            let v = overhead::mx(
                a.num("near")?,
                a.num("far")?,
                a.n_prime("n_prime")?,
                a.num("z")?,
                a.res_s()?,
            )?;
            Ok(Output::Number(v))
        },
    },
    Quantity {
        name: "mz",
        args: &[NEAR, FAR, HALF_FOV, N_PRIME, Z, RES_IMAGE, RES_T],
        value: ValueKind::Number,
        source: "Lloyd 2006 Eq 8",
        compute: |a| {
            let v = overhead::mz(&a.view()?, a.n_prime("n_prime")?, a.num("z")?, a.res_t()?)?;
            Ok(Output::Number(v))
        },
    },
    Quantity {
        name: "max_mx",
        args: &[NEAR, FAR, N_PRIME, RES_IMAGE, RES_S],
        value: ValueKind::Number,
        source: "Lloyd 2006 Eq 9",
        compute: |a| {
            let v = overhead::max_mx(
                a.num("near")?,
                a.num("far")?,
                a.n_prime("n_prime")?,
                a.res_s()?,
            )?;
            Ok(Output::Number(v))
        },
    },
    Quantity {
        name: "max_mz",
        args: &[NEAR, FAR, HALF_FOV, N_PRIME, RES_IMAGE, RES_T],
        value: ValueKind::Number,
        source: "Lloyd 2006 Eq 10",
        compute: |a| {
            let v = overhead::max_mz(&a.view()?, a.n_prime("n_prime")?, a.res_t()?)?;
            Ok(Output::Number(v))
        },
    },
    Quantity {
        name: "storage_factor",
        args: &[NEAR, FAR, HALF_FOV, N_PRIME],
        value: ValueKind::Number,
        source: "Lloyd 2006 Eq 12",
        compute: |a| {
            let v = overhead::storage_factor(&a.view()?, a.n_prime("n_prime")?)?;
            Ok(Output::Number(v))
        },
    },
    Quantity {
        name: "critical_resolution",
        args: &[NEAR, FAR, HALF_FOV, N_PRIME, req("budget", Num), RES_IMAGE],
        value: ValueKind::Numbers,
        source: "Lloyd 2006 Eq 13, 14",
        compute: |a| {
            let view = a.view()?;
            let n_prime = a.n_prime("n_prime")?;
            // Eq 13, 14 use only the ratio res*_s / res*_t = M_x / M_z, which does not depend on
            // the image resolution: res_image is validated but does not change the answer.
            crate::error::positive("res_image", a.num("res_image")?)?;
            let r = overhead::budget_resolution(&view, n_prime, a.num("budget")?)?;
            Ok(Output::Numbers(vec![r.res_s, r.res_t]))
        },
    },
    Quantity {
        name: "n_prime_lispsm",
        args: &[NEAR, FAR],
        value: ValueKind::Number,
        source: "Lloyd 2006 §4.1",
        compute: |a| {
            Ok(Output::Number(eta::n_prime_lispsm(
                a.num("near")?,
                a.num("far")?,
            )?))
        },
    },
    Quantity {
        name: "n_prime_from_eta",
        args: &[NEAR, FAR, req("eta", Num)],
        value: ValueKind::NPrime,
        source: "Lloyd 2006 Eq 11",
        compute: |a| {
            Ok(Output::NPrime(eta::n_prime_from_eta(
                a.num("near")?,
                a.num("far")?,
                a.num("eta")?,
            )?))
        },
    },
    Quantity {
        name: "eta_from_n_prime",
        args: &[NEAR, FAR, N_PRIME],
        value: ValueKind::Number,
        source: "Lloyd 2006 App. B",
        compute: |a| {
            Ok(Output::Number(eta::eta_from_n_prime(
                a.num("near")?,
                a.num("far")?,
                a.n_prime("n_prime")?,
            )?))
        },
    },
    Quantity {
        name: "distribution_g",
        args: &[req("alpha", Num), req("n_warp", ArgKind::NPrime), Z],
        value: ValueKind::Number,
        source: "Lloyd 2005 Eq 3",
        compute: |a| {
            Ok(Output::Number(subdivided::distribution_g(
                a.num("alpha")?,
                a.n_prime("n_warp")?,
                a.num("z")?,
            )?))
        },
    },
    Quantity {
        name: "subdivided_max_error",
        args: &[
            req("alpha", Num),
            req("k", Count),
            req("eta", Num),
            HALF_FOV,
            RES_IMAGE,
            RES_S,
        ],
        value: ValueKind::Number,
        source: "Lloyd 2005 Eq 7",
        compute: |a| {
            // The library's argument names are the contract's (Lloyd 2005's ξ is `eta`, r_s is
            // `res_s`): its errors need no renaming.
            let v = subdivided::subdivided_max_error(
                a.num("alpha")?,
                a.count("k")?,
                a.num("eta")?,
                a.num("half_fov")?,
                a.num("res_image")?,
                a.num("res_s")?,
            )?;
            Ok(Output::Number(v))
        },
    },
    Quantity {
        name: "allocate_texels",
        args: &[req("errors", NumArray), req("total", Num)],
        value: ValueKind::Numbers,
        source: "Lloyd 2005 Eq 6",
        compute: |a| {
            let errors = a.numbers("errors")?;
            let mut out = vec![0.0; errors.len()];
            subdivided::allocate_texels(errors, a.num("total")?, &mut out)?;
            Ok(Output::Numbers(out))
        },
    },
    Quantity {
        name: "z_partition",
        args: &[
            NEAR,
            FAR,
            req("k", Count),
            req("scheme", ArgKind::Choice(Z_PARTITION_SCHEMES)),
            opt("lambda", Num),
            opt("light_angle", Num),
            opt("ratio", Num),
        ],
        value: ValueKind::Numbers,
        source: "Lloyd 2006 Eq 15, 16; Barroso Eq 19",
        compute: |a| {
            use crate::analytic::partition::{z_splits, SplitScheme};
            let scheme = a.choice("scheme")?;
            // Each optional argument belongs to one scheme: present with another is a mistake.
            let owner = |arg: &'static str| match arg {
                "lambda" => "practical",
                _ => "adaptive",
            };
            for arg in ["lambda", "light_angle", "ratio"] {
                let needed = owner(arg) == scheme;
                match (a.opt_num(arg).is_some(), needed) {
                    (true, false) => {
                        return Err(Error::invalid(
                            arg,
                            format!(
                                "is not an argument of z_partition with scheme \"{scheme}\" \
                                 (only of scheme \"{}\")",
                                owner(arg)
                            ),
                        ))
                    }
                    (false, true) => {
                        return Err(Error::invalid(
                            arg,
                            format!("is missing (scheme \"{scheme}\" needs it)"),
                        ))
                    }
                    _ => {}
                }
            }
            let scheme = match scheme {
                "self_similar" => SplitScheme::SelfSimilar,
                "uniform" => SplitScheme::Uniform,
                "practical" => SplitScheme::Practical {
                    lambda: a.num("lambda")?,
                },
                _ => SplitScheme::Adaptive {
                    light_angle: a.num("light_angle")?,
                    ratio: a.num("ratio")?,
                },
            };
            let splits = z_splits(a.num("near")?, a.num("far")?, a.count("k")?, scheme)?;
            Ok(Output::Numbers(splits.planes().to_vec()))
        },
    },
    Quantity {
        name: "scheme_storage_factor",
        args: &[
            req("scheme", ArgKind::Choice(STORAGE_SCHEMES)),
            req("light", ArgKind::Choice(LIGHTS)),
            NEAR,
            FAR,
            HALF_FOV,
            req("k", Count),
        ],
        value: ValueKind::Number,
        source: "Lloyd 2006 Eq 17–21, App. C",
        compute: |a| {
            use crate::analytic::partition::{self, Scheme, SchemeLight};
            let scheme = match a.choice("scheme")? {
                "zp" => Scheme::Zp,
                "zp_w" => Scheme::ZpW,
                "fp_zp_w" => Scheme::FpZpW,
                _ => Scheme::Optimal,
            };
            let light = match a.choice("light")? {
                "overhead" => SchemeLight::Overhead,
                _ => SchemeLight::Behind,
            };
            let v = partition::scheme_storage_factor(scheme, light, &a.view()?, a.count("k")?)?;
            Ok(Output::Number(v))
        },
    },
    Quantity {
        name: "tilted_mz",
        args: &[
            NEAR,
            FAR,
            HALF_FOV,
            N_PRIME,
            LIGHT_ANGLE,
            Z,
            RES_IMAGE,
            RES_T,
        ],
        value: ValueKind::Number,
        source: "Barroso Eq 10–12",
        compute: |a| {
            let v = tilted::tilted_mz(
                &a.view()?,
                a.n_prime("n_prime")?,
                LightAngle::new(a.num("light_angle")?)?,
                a.num("z")?,
                a.res_t()?,
            )?;
            Ok(Output::Number(v))
        },
    },
    Quantity {
        name: "generalized_n_prime",
        args: &[
            NEAR,
            FAR,
            HALF_FOV,
            LIGHT_ANGLE,
            req("falloff", ArgKind::Choice(FALLOFFS)),
        ],
        value: ValueKind::NPrime,
        source: "Barroso Eq 13–18",
        compute: |a| {
            let falloff = match a.choice("falloff")? {
                "barroso" => tilted::Falloff::Barroso,
                _ => tilted::Falloff::Zhang,
            };
            let gamma = LightAngle::new(a.num("light_angle")?)?;
            Ok(Output::NPrime(tilted::generalized_n_prime(
                &a.view()?,
                gamma,
                falloff,
            )))
        },
    },
    Quantity {
        name: "gamma_lim",
        args: &[NEAR, FAR, HALF_FOV],
        value: ValueKind::Number,
        source: "Barroso Eq 15",
        compute: |a| Ok(Output::Number(tilted::gamma_lim(&a.view()?))),
    },
    Quantity {
        name: "tsm_eta",
        args: &[req("lambda", Num), req("delta_prime", Num), req("xi", Num)],
        value: ValueKind::NPrime,
        source: "Martin–Tan §6.2",
        compute: |a| {
            let eta = tsm::tsm_eta(a.num("lambda")?, a.num("delta_prime")?, a.num("xi")?)?;
            Ok(Output::NPrime(eta))
        },
    },
    Quantity {
        name: "zhang_eq",
        args: ZHANG_GLOBAL,
        value: ValueKind::Number,
        source: "Zhang Eq 13 and Appendix",
        compute: |a| zhang_global(a, global::zhang_eq),
    },
    Quantity {
        name: "zhang_ep",
        args: ZHANG_GLOBAL,
        value: ValueKind::Number,
        source: "Zhang Eq 14 and Appendix",
        compute: |a| zhang_global(a, global::zhang_ep),
    },
    Quantity {
        name: "zhang_eq_local",
        args: &[NEAR, FAR, HALF_FOV, LAMBDA_NP, Z],
        value: ValueKind::Number,
        source: "Zhang Eq 8",
        compute: |a| {
            let v = global::zhang_eq_local(&a.view()?, a.n_prime("lambda")?, a.num("z")?)?;
            Ok(Output::Number(v))
        },
    },
    Quantity {
        name: "zhang_ep_local",
        args: &[NEAR, FAR, HALF_FOV, LAMBDA_NP, Z],
        value: ValueKind::Number,
        source: "Zhang Eq 9",
        compute: |a| {
            let v = global::zhang_ep_local(&a.view()?, a.n_prime("lambda")?, a.num("z")?)?;
            Ok(Output::Number(v))
        },
    },
];

/// The row of [`QUANTITIES`] named `name`.
#[must_use]
pub fn quantity(name: &str) -> Option<&'static Quantity> {
    QUANTITIES.iter().find(|q| q.name == name)
}

/// `zhang_eq` and `zhang_ep`: the same arguments into one of Zhang's global aliasing functions.
fn zhang_global(
    a: &super::Args,
    f: fn(&crate::ViewFrustum, crate::NPrime, LightAngle, f64, f64) -> crate::Result<f64>,
) -> crate::Result<Output> {
    let v = f(
        &a.view()?,
        a.n_prime("lambda")?,
        LightAngle::new(a.num("light_angle")?)?,
        a.num("y")?,
        a.num("z")?,
    )?;
    Ok(Output::Number(v))
}
