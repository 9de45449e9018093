//! From the command line's names to the library's warp rules and partitions, and the measured
//! error of each partition's matrix (`build::scheme`).

use crate::args::{PartitionName, SchemeArgs, WarpName};
use glam::{DMat4, DVec3};
use shadow_aliasing::analytic::partition::{z_splits, SplitScheme};
use shadow_aliasing::build::scheme::{scheme, Partition, Region, ADAPTIVE_RATIO};
use shadow_aliasing::build::{Falloff, WarpRule};
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

/// The library's partition for `--partition` (and `--lambda`).
pub fn partition(a: &SchemeArgs) -> Partition {
    match a.partition {
        PartitionName::Single => Partition::Single,
        PartitionName::Uniform => Partition::Uniform,
        PartitionName::Log => Partition::Log,
        PartitionName::Practical => Partition::Practical(a.lambda),
        PartitionName::Adaptive => Partition::Adaptive,
        PartitionName::Faces => Partition::Faces,
    }
}

/// The shallowest depth range among the scheme's z-partitions for this light (TSM's default
/// focus is half of it, so that the focus point lies inside every partition).
fn shallowest_partition(
    view: &ViewFrustum,
    light_dir: Option<DVec3>,
    a: &SchemeArgs,
) -> Result<f64, Error> {
    let (n, f, k) = (view.near(), view.far(), a.k);
    let split = match a.partition {
        PartitionName::Single | PartitionName::Faces => return Ok(f - n),
        PartitionName::Uniform => SplitScheme::Uniform,
        PartitionName::Log => SplitScheme::SelfSimilar,
        PartitionName::Practical => SplitScheme::Practical { lambda: a.lambda },
        PartitionName::Adaptive => SplitScheme::Adaptive {
            light_angle: match light_dir {
                Some(l) => LightAngle::from_light_dir(l)?.radians(),
                // A sweep: the light parallel to the view gives the shallowest far partitions.
                None => 0.0,
            },
            ratio: ADAPTIVE_RATIO,
        },
    };
    let s = z_splits(n, f, k, split)?;
    Ok((0..s.k())
        .map(|i| {
            let (a, b) = s.range(i);
            b - a
        })
        .fold(f64::INFINITY, f64::min))
}

/// The library's rule for `--warp` (and its parameters). `light_dir` is `None` for a sweep.
pub fn rule(
    view: &ViewFrustum,
    light_dir: Option<DVec3>,
    a: &SchemeArgs,
) -> Result<WarpRule, Error> {
    if a.eta.is_some() && a.warp != WarpName::Eta {
        return Err(Error::invalid("eta", "is only used by --warp eta"));
    }
    if a.focus.is_some() && a.warp != WarpName::Tsm {
        return Err(Error::invalid("focus", "is only used by --warp tsm"));
    }
    if a.near_hint.is_some() && a.warp != WarpName::Filament {
        return Err(Error::invalid(
            "near_hint",
            "is only used by --warp filament",
        ));
    }
    if a.partition != PartitionName::Single && a.k == 0 {
        return Err(Error::invalid("k", "must be at least 1 (got 0)"));
    }
    if a.partition == PartitionName::Single && a.k != 1 {
        return Err(Error::invalid(
            "k",
            format!(
                "is the number of z-partitions and needs a --partition other than single (got {})",
                a.k
            ),
        ));
    }
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
                None => 0.5 * shallowest_partition(view, light_dir, a)?,
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
    })
}

/// The scheme's matrices for this camera and light, each with its measured error.
pub fn partitions(
    view: &ViewFrustum,
    light_dir: DVec3,
    a: &SchemeArgs,
) -> Result<Vec<PartitionReport>, Error> {
    let r = rule(view, Some(light_dir), a)?;
    let result = scheme(view, light_dir, r, partition(a), a.k)?;
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
                Region::Face(face) => Some(format!("{face:?}").to_ascii_lowercase()),
            },
        })
        .collect())
}
