//! The shadow-map storage of partitioning schemes (Lloyd 2006 Eq 17–23, App. C) and of given
//! splits.

use super::Splits;
use crate::error::{finite_result, Error, Result};
use crate::frustum::ViewFrustum;

/// A partitioning scheme of Lloyd et al. 2006 §5.3.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scheme {
    /// ZP: k self-similar z-partitions, each with an unwarped (orthographic) map.
    Zp,
    /// ZP+W: k self-similar z-partitions, each warped with n′ ≤ n′_LSPSM of its own depth range.
    ZpW,
    /// FP+ZP+W: face partitions, each z-partitioned k times and warped.
    FpZpW,
    /// The optimal logarithmic parameterisation (Lloyd 2006 App. C), the limit k → ∞ of ZP+W.
    Optimal,
}

/// The light direction of Lloyd et al. 2006 §5.3's two analysed cases.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SchemeLight {
    /// Light perpendicular to the view direction (travelling −Y in eye space).
    Overhead,
    /// Light travelling along the view direction, from behind the viewer.
    Behind,
}

/// α^{1/k} − 1 without cancellation.
#[inline]
fn ratio_m1(alpha: f64, k: usize) -> f64 {
    (alpha.ln() / k as f64).exp_m1()
}

fn k_ok(k: usize) -> Result<f64> {
    if k == 0 {
        Err(Error::invalid("k", "must be at least 1 (got 0)"))
    } else {
        Ok(k as f64)
    }
}

/// The storage factor S̄ of a partitioning scheme, summed over its shadow maps, for the light
/// overhead or behind (Lloyd 2006 Eq 17–21, App. C).
///
/// a = (f/n)^{1/k} is every self-similar partition's depth ratio (Eq 15, 16), θ = half_fov:
///
/// | scheme | overhead | behind |
/// |---|---|---|
/// | ZP | k a (a − 1) / (2 tan θ) (Eq 17) | k a² (Eq 20) |
/// | ZP+W | k (a − 1) / (2 tan θ) (Eq 18) | k a² (§5.3: a square frustum cannot be warped, so ZP+W = ZP) |
/// | FP+ZP+W | k (a − 1) / (2 tan θ) (Eq 19) | 4 k (a − 1)/2 + 1 (Eq 21) |
/// | optimal | ln(f/n) / (2 tan θ) (App. C) | no closed form |
///
/// Eq 21 prints "4 S̄_overhead^{ZP+W} + 1, with θ = 45°". Seen from behind, each side face is the
/// overhead problem with a half field of view of 45° whatever θ (its half-width equals its
/// distance from the view axis, and the pixel width there is twice that distance / res_i), so the
/// crate evaluates S̄_overhead^{ZP+W} at 45° for every θ; the twin test
/// `eq21_fp_zp_w_behind_matches_face_twin_for_any_fov` measures it (docs/errata.md). The near face
/// adds 1 (one uniform map at the image's own texel spacing).
///
/// n = `view.near()`, f = `view.far()`; k = number of z-partitions (≥ 1; ignored by `Optimal`).
/// Dimensionless. A square image is assumed, as in the paper.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `k` (≥ 1); [`Error::NoClosedForm`] for the optimal
/// parameterisation with the light behind, which Lloyd 2006 does not analyse;
/// [`Error::Degenerate`] when f/n is so large that the value overflows.
///
/// ```
/// # use shadow_aliasing::analytic::partition::{scheme_storage_factor, Scheme, SchemeLight};
/// # use shadow_aliasing::ViewFrustum;
/// let v = ViewFrustum::new(1.0, 100.0, std::f64::consts::FRAC_PI_4)?;
/// // Behind, ZP, k = 2: 2 · 100^{2/2} = 200.
/// let s = scheme_storage_factor(Scheme::Zp, SchemeLight::Behind, &v, 2)?;
/// assert!((s - 200.0).abs() < 1e-9);
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn scheme_storage_factor(
    scheme: Scheme,
    light: SchemeLight,
    view: &ViewFrustum,
    k: usize,
) -> Result<f64> {
    let kf = k_ok(k)?;
    let alpha = view.alpha();
    let two_tan = 2.0 * view.tan_half_fov();
    let am1 = ratio_m1(alpha, k);
    let a = 1.0 + am1;
    let v =
        match (scheme, light) {
            (Scheme::Zp, SchemeLight::Overhead) => kf * a * am1 / two_tan,
            (Scheme::ZpW | Scheme::FpZpW, SchemeLight::Overhead) => kf * am1 / two_tan,
            (Scheme::Zp | Scheme::ZpW, SchemeLight::Behind) => kf * a * a,
            (Scheme::FpZpW, SchemeLight::Behind) => 4.0 * (kf * am1 / 2.0) + 1.0,
            (Scheme::Optimal, SchemeLight::Overhead) => optimal_storage_factor(view)?,
            (Scheme::Optimal, SchemeLight::Behind) => return Err(Error::NoClosedForm(
                "Lloyd 2006 derives the optimal logarithmic storage factor (App. C) only for the \
                 light overhead; there is none for the light behind"
                    .into(),
            )),
        };
    finite_result("storage factor", v)
}

/// The number of shadow maps a scheme uses with k z-partitions (Lloyd 2006 §5.3, the x axis of
/// Fig 12): k, or 4k + 1 for FP+ZP+W with the light behind (four side faces and the near face;
/// overhead the light sees one face).
/// `Optimal` counts as one (continuous) map.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `k` (≥ 1, and 4k + 1 must fit in a `usize`).
pub fn shadow_map_count(scheme: Scheme, light: SchemeLight, k: usize) -> Result<usize> {
    k_ok(k)?;
    match (scheme, light) {
        (Scheme::Optimal, _) => Ok(1),
        (Scheme::FpZpW, SchemeLight::Behind) => k
            .checked_mul(4)
            .and_then(|v| v.checked_add(1))
            .ok_or_else(|| {
                Error::invalid("k", format!("is too large: 4k + 1 overflows (got {k})"))
            }),
        _ => Ok(k),
    }
}

/// The storage factor of the optimal logarithmic parameterisation for the light overhead
/// (Lloyd 2006 App. C):
///
/// ```text
/// S̄_optimal = ln(f/n) / (2 tan θ)
/// ```
///
/// n = near, f = far, θ = half_fov. It is the k → ∞ limit of Eq 18, and a true lower bound: a
/// map with m_x, m_z ≤ 1 needs at least one texel per pixel footprint,
/// ∫ₙᶠ 2 z tan θ / (2 z tan θ)² dz = ln(f/n) / (2 tan θ) texels per image pixel².
///
/// # Errors
/// [`Error::Degenerate`] when f/n overflows (near so small and far so large that f/n = ∞).
#[inline]
pub fn optimal_storage_factor(view: &ViewFrustum) -> Result<f64> {
    finite_result(
        "storage factor",
        view.alpha().ln() / (2.0 * view.tan_half_fov()),
    )
}

/// The large-f/n behaviour of ZP with the light overhead, with j shadow maps (Lloyd 2006
/// Eq 22, with the constant the printed line drops):
///
/// ```text
/// S̄_ZP,overhead ≈ j (f/n)^{2/j} / (2 tan θ)      (printed: j (f/n)^{2/j})
/// ```
///
/// The ratio to Eq 17 tends to 1 as f/n → ∞ for fixed j.
///
/// Dimensionless.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `shadow_maps` (≥ 1).
pub fn zp_overhead_asymptotic(view: &ViewFrustum, shadow_maps: usize) -> Result<f64> {
    if shadow_maps == 0 {
        return Err(Error::invalid("shadow_maps", "must be at least 1 (got 0)"));
    }
    let j = shadow_maps as f64;
    finite_result(
        "storage factor",
        j * (2.0 * view.alpha().ln() / j).exp() / (2.0 * view.tan_half_fov()),
    )
}

/// The large-f/n behaviour of FP+ZP+W with the light overhead, with j shadow maps, i.e. j/4
/// z-partitions per face (Lloyd 2006 Eq 23, with the constant the printed line drops):
///
/// ```text
/// S̄_FP+ZP+W,overhead ≈ j (f/n)^{4/j} / (8 tan θ)      (printed: j (f/n)^{4/j})
/// ```
///
/// It is Eq 18 with k = j/4 for large f/n. The scheme has "one z-partitioning for every four
/// shadow maps", so j counts the four side faces' maps of k z-partitions, j = 4k (the near
/// face's map, which [`shadow_map_count`] adds with the light behind, is not among them); any
/// other j describes no scheme (docs/errata.md, Lloyd 2006 #19).
///
/// Dimensionless.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `shadow_maps` (a positive multiple of 4).
pub fn fp_zp_w_overhead_asymptotic(view: &ViewFrustum, shadow_maps: usize) -> Result<f64> {
    if shadow_maps == 0 || !shadow_maps.is_multiple_of(4) {
        return Err(Error::invalid(
            "shadow_maps",
            format!(
                "must be a positive multiple of 4: Eq 23 counts four face maps per \
                 z-partition (got {shadow_maps})"
            ),
        ));
    }
    let j = shadow_maps as f64;
    finite_result(
        "storage factor",
        j * (4.0 * view.alpha().ln() / j).exp() / (8.0 * view.tan_half_fov()),
    )
}

/// The storage factor of any z-partition, summed over its partitions, from the per-partition
/// closed forms: Lloyd 2006 Eq 12 with n′ = ∞ (`warped = false`) or n′ ≤ n′_LSPSM
/// (`warped = true`) for the light overhead; (f_i/n_i)² (Eq 20's k = 1 form) for the light
/// behind, where warping is impossible and `warped` is ignored.
///
/// ```text
/// overhead, unwarped: Σ (a_i − 1) a_i / (2 tan θ);  warped: Σ (a_i − 1) / (2 tan θ);
/// behind: Σ a_i²;   a_i = z_{i+1} / z_i
/// ```
///
/// For self-similar splits these are Eq 17, 18, 20. θ = `half_fov` (radians).
///
/// # Errors
/// [`Error::InvalidArgument`] naming `half_fov` (∈ (0, π/2)); [`Error::Degenerate`] if the sum
/// overflows.
pub fn splits_storage_factor(
    splits: &Splits,
    half_fov: f64,
    light: SchemeLight,
    warped: bool,
) -> Result<f64> {
    let t = crate::error::in_open("half_fov", half_fov, 0.0, std::f64::consts::FRAC_PI_2)?.tan();
    let p = splits.planes();
    let mut sum = 0.0;
    for w in p.windows(2) {
        let am1 = (w[1] - w[0]) / w[0];
        let a = w[1] / w[0];
        sum += match (light, warped) {
            (SchemeLight::Overhead, false) => am1 * a / (2.0 * t),
            (SchemeLight::Overhead, true) => am1 / (2.0 * t),
            (SchemeLight::Behind, _) => a * a,
        };
    }
    finite_result("storage factor", sum)
}
