//! The numeric ground rules shared by every layer: NaN-free `fmin`/`fmax` for the inner loops and
//! the tolerances, each a named constant with the reason for its value; `lane`, the lane type
//! the scalar code and the four-direction sweep share.

pub(crate) mod lane;

/// `min(a, b)` for values that are never NaN (finite corner coordinates), in loops that run 8 to
/// 40 times per map (cheaper than `f64::min`: docs/performance.md, "Code-generation notes").
/// Equal to `a.min(b)` whenever neither is NaN (a NaN `b` is returned, so it is not silently
/// dropped either).
#[inline(always)]
pub(crate) fn fmin(a: f64, b: f64) -> f64 {
    if a < b {
        a
    } else {
        b
    }
}

/// `max(a, b)` for values that are never NaN; see [`fmin`].
#[inline(always)]
pub(crate) fn fmax(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

/// √(f n) without overflow or underflow of the product f n (both positive and finite).
#[inline]
pub(crate) fn sqrt_fn(n: f64, f: f64) -> f64 {
    let p = f * n;
    if p.is_normal() {
        p.sqrt()
    } else {
        f.sqrt() * n.sqrt()
    }
}

/// `v.is_finite()` as float operations for vectorised loops (the closed forms' `*_unchecked`
/// twins): v − v is +0 exactly for a finite v and NaN for ±∞ and NaN. (`is_finite` compiles to
/// integer compares of the bits, which SSE2 lacks for 64-bit lanes.)
#[inline(always)]
#[allow(clippy::eq_op)] // v − v is the test.
pub(crate) fn finite_select(v: f64) -> bool {
    v - v == 0.0
}

/// Sorts `keys` ascending and applies the same swaps to `values` (an insertion sort: stable, no
/// allocation, for the few dozen elements of a fixed array). Panics if `values` is shorter than
/// `keys` (a programming error of the caller, never an input).
pub(crate) fn sort_by_keys<K: PartialOrd, T>(keys: &mut [K], values: &mut [T]) {
    for i in 1..keys.len() {
        let mut j = i;
        while j > 0 && keys[j - 1] > keys[j] {
            keys.swap(j - 1, j);
            values.swap(j - 1, j);
            j -= 1;
        }
    }
}

/// How far outside the clip volume rounding may put a point: 10⁻⁶ of its half-width.
pub const CLIP_SLACK: f64 = 1e-6;

/// Below this length of the axis projected perpendicular to the light (the sine of the angle
/// between them), the projection is treated as zero and the fallback axis is used. 1e−12 is far
/// below any angle a renderer distinguishes (2·10⁻¹⁰ degrees) and far above the rounding error of
/// a unit vector's components (≈ 10⁻¹⁶), so the normalised projection is accurate to ≈ 10⁻⁴ in the
/// worst case just above the threshold and exact far from it.
pub const PARALLEL_TOLERANCE: f64 = 1e-12;

/// Faces with `|N·L|` at most this (unit vectors: the sine of the angle between the face's plane
/// and the light) whose area projected along the light is also at most this fraction of the
/// frustum's silhouette are treated as edge-on and skipped (see [`crate::maps::faces`]). 10⁻⁶: the prism
/// of such a face is thinner than a millionth of its own size and of the frustum's shadow (less
/// than a texel of any shadow map up to 10⁶ texels across), while a map fitted to a face seen at
/// a grazing sine s carries rounding of about 10⁻¹⁶/s of its clip range: at 10⁻⁶ that is 10⁻¹⁰,
/// below the clip-volume tolerance the crate's tests hold every map to. (A face kept at a smaller
/// sine because it is large, as with a half field of view near π/2, is fitted and checked like
/// any other; past what f64 can fit the fit is refused with [`Error::Degenerate`](crate::Error::Degenerate).)
///
/// The same tolerance marks a warp axis as undefined: a side edge (for the bisector) or the near
/// edge (for the depth axis) within `EDGE_ON` of parallel to the light.
pub const EDGE_ON: f64 = 1e-6;
