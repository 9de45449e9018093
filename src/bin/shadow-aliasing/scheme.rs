//! From the command line's names to the library's warp rules and partitions, and the measured
//! error of each partition's matrix (`scheme`).

use crate::args::{PartitionName, SchemeArgs, WarpName};
use clap::ValueEnum;
use glam::{DMat4, DVec3};
use shadow_aliasing::analytic::partition::{z_splits, SplitScheme, Splits, MAX_PARTITIONS};
use shadow_aliasing::maps::{Falloff, WarpRule};
use shadow_aliasing::scheme::sweep::{light_dir_from_angles, SweepGrid};
use shadow_aliasing::scheme::{scheme, Partition, Region, ADAPTIVE_RATIO};
use shadow_aliasing::{Error, LightAngle, NPrime, ViewFrustum};

/// One partition's matrix and its measured error (unit resolutions).
#[derive(Debug, Clone)]
pub struct PartitionReport {
    /// Near end of the view-depth range this matrix covers.
    pub near: f64,
    /// Far end of that range (equal to `near` for the near face).
    pub far: f64,
    /// The warp parameter used.
    pub n_prime: NPrime,
    /// Eye space → light clip space, OpenGL depth [−1, 1].
    pub matrix: DMat4,
    /// M_x over the partition.
    pub max_mx: f64,
    /// M_z over the partition.
    pub max_mz: f64,
    /// S̄ = M_x M_z.
    pub storage_factor: f64,
    /// The face a face partition covers (`bottom`, `right`, `top`, `left`, `near`, `far`).
    pub face: Option<String>,
}

/// `--lambda` when it is not given.
pub const DEFAULT_LAMBDA: f64 = 0.5;

/// The light directions a scheme is evaluated at: one for `warp`, a sweep's grid for `sweep`.
#[derive(Debug, Clone, Copy)]
pub enum Lights {
    /// One eye-space light direction.
    One(DVec3),
    /// Every direction of a hemisphere sweep.
    Sweep(SweepGrid),
}

/// The library's partition for `--partition` (and `--lambda`).
///
/// # Errors
/// `partition` for `equal-error`, whose splits are measured on one light's maps (`warp` only).
pub fn partition(a: &SchemeArgs) -> Result<Partition, Error> {
    Ok(match a.partition {
        PartitionName::Single => Partition::Single,
        PartitionName::Uniform => Partition::Uniform,
        PartitionName::Log => Partition::Log,
        PartitionName::Practical => Partition::Practical(a.lambda.unwrap_or(DEFAULT_LAMBDA)),
        PartitionName::Adaptive => Partition::AdaptiveRatio(ratio(a)),
        PartitionName::Faces => Partition::Faces,
        PartitionName::EqualError => {
            return Err(Error::invalid(
                "partition",
                "equal-error places its splits by measuring one light's maps: use it with warp, \
                 or sweep --partition log (the frustum's own equal-error splits for the rules \
                 whose map scales with its slice)",
            ))
        }
        PartitionName::Clipmap => {
            return Err(Error::invalid(
                "partition",
                "clipmap's levels are the frame API's (FrameScheme::Clipmap): use it with warp",
            ))
        }
    })
}

/// `--ratio`, or Barroso & Celes' α = 2 when it is not given (validated by the library, which
/// names `ratio`).
pub fn ratio(a: &SchemeArgs) -> f64 {
    a.ratio.unwrap_or(ADAPTIVE_RATIO)
}

/// `--k` as the library's count: 1 with `single`, otherwise in [1, 16] (a negative or zero
/// count answered in the library's words, a larger one left to the library, which says the same).
pub fn k(a: &SchemeArgs) -> Result<usize, Error> {
    if a.partition == PartitionName::Single && a.k != 1 {
        return Err(Error::invalid(
            "k",
            format!(
                "is the number of z-partitions and needs a --partition other than single (got {})",
                a.k
            ),
        ));
    }
    match usize::try_from(a.k) {
        Ok(k) if k >= 1 => Ok(k),
        _ => Err(Error::invalid(
            "k",
            format!("must lie in [1, {MAX_PARTITIONS}] (got {})", a.k),
        )),
    }
}

/// The depth range of the shallowest of the adaptive z-partitions (Barroso Eq 19) for one light
/// angle γ and ratio α.
fn shallowest_adaptive(n: f64, f: f64, k: usize, gamma: f64, ratio: f64) -> Result<f64, Error> {
    let s = z_splits(
        n,
        f,
        k,
        SplitScheme::Adaptive {
            light_angle: gamma,
            ratio,
        },
    )?;
    Ok(shallowest(&s))
}

/// The smallest `b − a` over the ranges of `s`.
fn shallowest(s: &Splits) -> f64 {
    (0..s.k())
        .map(|i| {
            let (a, b) = s.range(i);
            b - a
        })
        .fold(f64::INFINITY, f64::min)
}

/// The shallowest depth range among the scheme's z-partitions for these lights (TSM's default
/// focus is half of it, so that the focus point lies inside every partition).
///
/// Only `adaptive` partitions depend on the light (through γ). For a sweep the minimum is taken
/// over every direction the sweep visits, so that one focus distance serves the whole sweep:
/// neither γ = 0 nor γ = π/2 is the shallowest case in general (at n = 1, f = 100, k = 4 the
/// first partition is 11.5 deep at γ = 0 but 100^{1/4} − 1 = 2.16 at γ = π/2). A direction whose
/// partitions do not exist (Eq 19's planes not increasing) is left to the sweep, which reports
/// it with the direction.
fn shallowest_partition(view: &ViewFrustum, lights: Lights, a: &SchemeArgs) -> Result<f64, Error> {
    let (n, f, k, ratio) = (view.near(), view.far(), k(a)?, ratio(a));
    let split = match a.partition {
        PartitionName::Single | PartitionName::Faces | PartitionName::Clipmap => return Ok(f - n),
        PartitionName::Uniform => SplitScheme::Uniform,
        // Equal-error planes are not known before the maps: the logarithmic ones, which they are
        // for the frustum alone, estimate the shallowest.
        PartitionName::Log | PartitionName::EqualError => SplitScheme::SelfSimilar,
        PartitionName::Practical => SplitScheme::Practical {
            lambda: a.lambda.unwrap_or(DEFAULT_LAMBDA),
        },
        PartitionName::Adaptive => {
            return match lights {
                Lights::One(l) => {
                    shallowest_adaptive(n, f, k, LightAngle::from_light_dir(l)?.radians(), ratio)
                }
                Lights::Sweep(grid) => {
                    let mut min = f64::INFINITY;
                    let mut first_error = None;
                    for i in 0..grid.elevations() {
                        for j in 0..grid.azimuths() {
                            let l = light_dir_from_angles(grid.elevation(i), grid.azimuth(j));
                            match LightAngle::from_light_dir(l)
                                .and_then(|g| shallowest_adaptive(n, f, k, g.radians(), ratio))
                            {
                                Ok(d) => min = min.min(d),
                                Err(e) => {
                                    first_error.get_or_insert(e);
                                }
                            }
                        }
                    }
                    match first_error {
                        Some(e) if min == f64::INFINITY => Err(e),
                        _ => Ok(min),
                    }
                }
            };
        }
    };
    Ok(shallowest(&z_splits(n, f, k, split)?))
}

/// The command-line spelling of a value (`lispsm-fixed`).
pub fn value_name<T: ValueEnum>(v: &T) -> String {
    v.to_possible_value()
        .map_or_else(|| "?".to_string(), |p| p.get_name().to_string())
}

/// The library's rule for `--warp` (and its parameters), checking that every parameter given is
/// one the scheme uses.
pub fn rule(view: &ViewFrustum, lights: Lights, a: &SchemeArgs) -> Result<WarpRule, Error> {
    if a.eta.is_some() && a.warp != WarpName::Eta {
        return Err(Error::invalid("eta", "is only used by --warp eta"));
    }
    if a.focus.is_some() && !matches!(a.warp, WarpName::Tsm | WarpName::Trapezoid) {
        return Err(Error::invalid(
            "focus",
            "is only used by --warp tsm and --warp trapezoid",
        ));
    }
    if a.near_hint.is_some() && a.warp != WarpName::Filament {
        return Err(Error::invalid(
            "near_hint",
            "is only used by --warp filament",
        ));
    }
    if a.shadow_distance.is_some() && a.warp != WarpName::OgreOrtho {
        return Err(Error::invalid(
            "shadow_distance",
            "is only used by --warp ogre-ortho",
        ));
    }
    // eval's wording for z_partition's lambda with another scheme.
    for (name, given, owner) in [
        ("lambda", a.lambda.is_some(), PartitionName::Practical),
        ("ratio", a.ratio.is_some(), PartitionName::Adaptive),
    ] {
        if given && a.partition != owner {
            return Err(Error::invalid(
                name,
                format!(
                    "is not an argument of --partition {} (only of --partition {})",
                    value_name(&a.partition),
                    value_name(&owner)
                ),
            ));
        }
    }
    k(a)?;
    Ok(match a.warp {
        WarpName::Uniform => WarpRule::Uniform,
        WarpName::Eta => WarpRule::Eta(a.eta.ok_or_else(|| {
            Error::invalid("eta", "is missing: --warp eta needs --eta in [-1, 1]")
        })?),
        WarpName::Psm => WarpRule::Psm,
        WarpName::Lispsm => WarpRule::Lispsm,
        WarpName::LispsmFixed => WarpRule::LispsmFixed,
        WarpName::Barroso => WarpRule::Barroso(Falloff::Barroso),
        WarpName::BarrosoZhang => WarpRule::Barroso(Falloff::Zhang),
        WarpName::Minimax => WarpRule::Minimax,
        WarpName::MinimaxMz => WarpRule::MinimaxMz,
        WarpName::Tsm => WarpRule::Tsm {
            focus: match a.focus {
                Some(f) => f,
                None => 0.5 * shallowest_partition(view, lights, a)?,
            },
        },
        WarpName::LispsmReference => WarpRule::LispsmReference,
        WarpName::Filament => match (a.near_hint, a.far_hint) {
            (Some(near_hint), Some(far_hint)) => WarpRule::FilamentHints {
                near_hint,
                far_hint,
            },
            _ => WarpRule::Filament,
        },
        WarpName::Ogre => WarpRule::Ogre,
        WarpName::OgreOrtho => WarpRule::OgreOrtho {
            shadow_distance: a.shadow_distance.unwrap_or(300.0 * view.near()),
        },
        WarpName::Trapezoid => {
            return Err(Error::invalid(
                "warp",
                "trapezoid is one trapezoidal map of the scene built by the frame API: use it \
                 with warp alone, or --warp tsm (TSM's n′ rule) here",
            ))
        }
    })
}

/// The scheme's matrices for this camera and light, each with its measured error.
pub fn partitions(
    view: &ViewFrustum,
    light_dir: DVec3,
    a: &SchemeArgs,
) -> Result<Vec<PartitionReport>, Error> {
    let r = rule(view, Lights::One(light_dir), a)?;
    let result = scheme(view, light_dir, r, partition(a)?, k(a)?)?;
    Ok(result
        .partitions()
        .iter()
        .map(|p| PartitionReport {
            near: p.near,
            far: p.far,
            n_prime: p.n_prime,
            matrix: p.matrix,
            max_mx: p.max_mx,
            max_mz: p.max_mz,
            storage_factor: p.storage_factor,
            face: match p.region {
                Region::Frustum => None,
                Region::Face(face) => Some(face.name().to_owned()),
            },
        })
        .collect())
}
