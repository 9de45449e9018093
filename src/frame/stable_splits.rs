//! The equal-error planes of stable cascades
//! ([`FrameScheme::Stable`](super::FrameScheme::Stable)`(`[`CascadeSplits::EqualError`](super::CascadeSplits::EqualError)`)`):
//! the logarithmic splits of B's depth range, its ends moved outward onto a grid fixed to the
//! camera's near plane, so that a camera move keeps every plane bit for bit until an end of B's
//! range crosses a grid line.
//!
//! # Why logarithmic
//!
//! A stable cascade of the slice `[a, b]` is an orthographic map (world-fixed light space, fixed
//! light) on a square of half-width `R(a, b) res/(res − 2)`, `R` the radius of the slice's
//! bounding sphere ([`bounding_sphere`](crate::maps::cascades::bounding_sphere)). For an
//! orthographic map `h.w = 1` and the gradients `G_s`, `G_t` of
//! [`vertex_max`](crate::measure::vertex::vertex_max) are constant rows proportional to
//! 1/half-width, so its `m_x = |G_t⊥| / (|D| z tan θ)` and `m_z = 1 / (|G_t⊥| z tan θ)` are the
//! same constants, proportional to the half-width, over `z`, the vertex's depth: the measured
//! error of the cascade is
//!
//! ```text
//! e(a, b) = C R(a, b) / max(a, lo)        (C fixed by the light, the camera's θ and res)
//! ```
//!
//! where `[lo, hi]` is B's depth range: `max(a, lo)` is the least depth of B ∩ `[a, b]`. `R` is
//! homogeneous, `R(λa, λb) = λ R(a, b)`, so for `a ≥ lo`, `e = C ρ(b/a)` with `ρ(x) = R(1, x)`
//! rising in `x`, and the first cascade, `a = lo`, has the same `e = C ρ(b/lo)`. Equal errors
//! are therefore equal depth ratios: the planes `lo x^i`, `x = (hi/lo)^(1/k)`, Lloyd 2006
//! Eq 15–16 over B's range. The measured search of [`super::equal_error`] converges to these
//! planes (to its tolerance, about 10⁻¹¹); here they are computed directly, with no map built.
//!
//! # The grid
//!
//! `lo` and `hi` move with the camera's pose, and every plane with them. They are moved outward
//! onto the grid `z_j = zn 2^(j/64)` (`zn` the visible range's near end, a fixed quantity of the
//! camera): `lo′` the largest grid depth ≤ `lo`, `hi′` the least ≥ `hi` (at most `zf`), and the
//! planes are `lo′ x′^i`, `x′ = (hi′/lo′)^(1/k)`. They are a function of the two grid indices
//! alone: a move that keeps `lo` and `hi` within their grid cells keeps every plane, and with
//! the snapped squares every stable cascade, bit for bit. No state is kept between frames (no
//! hysteresis), as for the squares' texel snapping: a frame is a function of its input, and a
//! plane changes with the same likelihood as a square, its end's motion over the grid's step.
//!
//! # What the grid costs
//!
//! `lo/lo′` and `hi′/hi` are each below `2^(1/64)`, so `x′/x < 2^(2/(64k))`, and every quantised
//! cascade's error is at most `C ρ(x′)` (for `a ≥ lo`, `e = C R(a, b)/max(a, lo) ≤ C ρ(b/a)`;
//! the first is `C ρ(x′) lo′/lo`). The elasticity `d ln ρ / d ln x` is 1 where the sphere's
//! centre is the far face's (`ρ = xK`, `K = tan θ √(1 + aspect²)`, always so for K ≥ 1), and
//! `1 + β(αx − β)/ρ²` with `α = (1 − K²)/2`, `β = (1 + K²)/2` elsewhere, at most
//! `1 + α/(2K)` (with `ρ² = (αx − β)² + K²x²` and `Kx ≥ Kβ/α`, the AM–GM inequality). So the
//! largest error of the quantised planes is at most
//!
//! ```text
//! E* · 2^((2/(64k)) (1 + max(0, (1 − K²)/(4K))))
//! ```
//!
//! `E*` the largest error of the unquantised equal-error planes: for K ≥ 1 at most 1.09 % more
//! at k = 2, 0.72 % at k = 3, 0.54 % at k = 4. Where B's depth ratio `hi/lo` is below
//! `2^(k/64)` a cascade at an end of the range can hold no part of B (its slot is then empty:
//! no map needed).

use crate::analytic::partition::{z_splits, SplitScheme, MAX_PARTITIONS};
use crate::error::Result;

/// Grid steps per doubling of depth.
const STEPS_PER_OCTAVE: f64 = 64.0;

/// The grid's step in ln z.
const STEP: f64 = std::f64::consts::LN_2 / STEPS_PER_OCTAVE;

/// The grid depth `j` steps beyond `zn` (`zn` itself for `j = 0`).
fn grid(zn: f64, j: f64) -> f64 {
    if j <= 0.0 {
        zn
    } else {
        (zn.ln() + j * STEP).exp()
    }
}

/// B's depth range `[lo, hi]` (within the visible range `[zn, zf]`, `lo < hi`) moved outward onto
/// the grid: the largest grid depth ≤ `lo`, and the least ≥ `hi` or `zf`.
fn outward(zn: f64, zf: f64, lo: f64, hi: f64) -> (f64, f64) {
    let ln_n = zn.ln();
    // ln and exp round by an ulp or so: a grid depth on the wrong side is stepped past (once,
    // in practice); the final min/max keep B covered whatever the rounding.
    let mut j = ((lo.ln() - ln_n) / STEP).floor().max(0.0);
    for _ in 0..4 {
        if j > 0.0 && grid(zn, j) > lo {
            j -= 1.0;
        }
    }
    let lo_q = grid(zn, j).min(lo);
    let mut j = ((hi.ln() - ln_n) / STEP).ceil().max(0.0);
    for _ in 0..4 {
        if grid(zn, j) < hi {
            j += 1.0;
        }
    }
    let hi_q = grid(zn, j).min(zf).max(hi);
    (lo_q, hi_q)
}

/// The stable cascades' equal-error planes (module docs) of B's depth range `[lo, hi]` within
/// the visible range `[zn, zf]`, into `planes[..=k]`.
pub(super) fn stable_planes(
    (zn, zf): (f64, f64),
    (lo, hi): (f64, f64),
    k: usize,
    planes: &mut [f64; MAX_PARTITIONS + 1],
) -> Result<()> {
    let (lo_q, hi_q) = outward(zn, zf, lo, hi);
    let s = z_splits(lo_q, hi_q, k, SplitScheme::SelfSimilar)?;
    planes[..=k].copy_from_slice(s.planes());
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The grid by hand: zn 2^(j/64); the ends move outward to the neighbouring grid depths.
    #[test]
    fn ends_move_outward_onto_the_grid() {
        let (zn, zf) = (0.5, 300.0);
        let g = |j: f64| 0.5 * 2f64.powf(j / 64.0);
        // lo = 3.8: ln(3.8/0.5)/(ln 2/64) = 187.27…, so grid 187; hi = 133.8: 516.09… → 517.
        let (lo_q, hi_q) = outward(zn, zf, 3.8, 133.8);
        assert!((lo_q - g(187.0)).abs() <= 1e-12 * lo_q, "{lo_q}");
        assert!((hi_q - g(517.0)).abs() <= 1e-12 * hi_q, "{hi_q}");
        assert!(lo_q <= 3.8 && 3.8 < g(188.0) && hi_q >= 133.8 && 133.8 > g(516.0));
        // Moved within their cells: the same bits.
        assert_eq!(outward(zn, zf, 3.8001, 133.79), (lo_q, hi_q));
        // At the visible range's ends: zn itself, and zf where the grid passes it (299.9: 590.61…
        // → 591, beyond zf = 300 at 590.64…).
        assert_eq!(outward(zn, zf, zn, 299.9), (zn, zf));
    }
}
