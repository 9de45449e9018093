//! From the command line's names to the library's warp rules and partitions, and the measured
//! error of each partition's matrix.

use crate::args::{PartitionName, SchemeArgs, WarpName};
use glam::{DMat4, DVec3};
use shadow_aliasing::build::{warp, Falloff, WarpRule};
use shadow_aliasing::measure::frustum_max;
use shadow_aliasing::{Error, NPrime, ViewFrustum};

/// One partition's matrix and its measured error (unit resolutions).
#[derive(Debug, Clone)]
pub struct PartitionReport {
    /// Near end of the view-depth range this matrix covers.
    pub near: f64,
    /// Far end of that range.
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
}

/// The library's rule for the command line's `--warp` (and its parameters) on a frustum whose
/// depth range is `[near, far]`.
pub fn rule(a: &SchemeArgs, near: f64, far: f64) -> Result<WarpRule, Error> {
    Ok(match a.warp {
        WarpName::Uniform => WarpRule::Uniform,
        WarpName::Eta => WarpRule::Eta(a.eta.ok_or_else(|| {
            Error::invalid("eta", "is missing: --warp eta needs --eta in [-1, 1]")
        })?),
        WarpName::Psm => WarpRule::Psm,
        WarpName::Lispsm => WarpRule::Lispsm,
        WarpName::LispsmSin => WarpRule::LispsmSin,
        WarpName::Barroso => WarpRule::Barroso(Falloff::Barroso),
        WarpName::BarrosoZhang => WarpRule::Barroso(Falloff::Zhang),
        WarpName::Minimax => WarpRule::Minimax,
        WarpName::MinimaxMz => WarpRule::MinimaxMz,
        WarpName::Tsm => {
            if !(a.focus > 0.0 && a.focus <= 1.0) {
                return Err(Error::invalid(
                    "focus",
                    format!("must lie in (0, 1] (got {})", a.focus),
                ));
            }
            WarpRule::Tsm {
                focus: a.focus * (far - near),
            }
        }
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

/// Checks that `--eta` is only given with `--warp eta`, and the hints only with `filament`.
pub fn check_flags(a: &SchemeArgs) -> Result<(), Error> {
    if a.eta.is_some() && a.warp != WarpName::Eta {
        return Err(Error::invalid("eta", "is only used by --warp eta"));
    }
    if a.near_hint.is_some() && a.warp != WarpName::Filament {
        return Err(Error::invalid(
            "near_hint",
            "is only used by --warp filament",
        ));
    }
    Ok(())
}

/// The scheme's matrices for this camera and light, each with its measured error.
pub fn partitions(
    view: &ViewFrustum,
    light_dir: DVec3,
    a: &SchemeArgs,
) -> Result<Vec<PartitionReport>, Error> {
    check_flags(a)?;
    if a.k == 0 {
        return Err(Error::invalid("k", "must be at least 1 (got 0)"));
    }
    match a.partition {
        PartitionName::Single => {
            if a.k != 1 {
                return Err(Error::invalid(
                    "k",
                    format!(
                        "must be 1 with --partition single (got {}); choose a partition scheme",
                        a.k
                    ),
                ));
            }
            let r = rule(a, view.near(), view.far())?;
            let s = warp(view, light_dir, r)?;
            let e = frustum_max(view, &s.shadow_map())?;
            Ok(vec![PartitionReport {
                near: s.near,
                far: s.far,
                n_prime: s.n_prime,
                matrix: s.matrix,
                max_mx: e.max_mx,
                max_mz: e.max_mz,
                storage_factor: e.storage_factor,
            }])
        }
        other => Err(Error::NoClosedForm(format!(
            "--partition {other:?} is not available in this build yet"
        ))),
    }
}
