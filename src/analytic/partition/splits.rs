//! The split planes of z-partitions: [`z_splits`] for every [`SplitScheme`], in a fixed-size
//! [`Splits`].

use crate::analytic::eta::near_far_ratio;
use crate::error::{fmt_num, in_closed, positive, Error, Result};

/// The largest number of z-partitions a [`Splits`] holds.
pub const MAX_PARTITIONS: usize = 16;

/// The depths of the planes that cut `[near, far]` into `k` z-partitions, near to far.
///
/// Invariant: `1 ≤ k ≤ MAX_PARTITIONS`, and `planes()` holds `k + 1` finite, positive,
/// strictly increasing depths. Stored in a fixed array: no heap allocation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Splits {
    planes: [f64; MAX_PARTITIONS + 1],
    k: usize,
}

impl Splits {
    /// Splits from explicit plane depths, near to far (for instance a renderer's own fractions
    /// scaled to its depth range).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `planes` unless there are 2 to `MAX_PARTITIONS + 1`
    /// values, each finite and positive, strictly increasing, with finite ratios of neighbours.
    ///
    /// ```
    /// # use shadow_aliasing::analytic::partition::Splits;
    /// let s = Splits::from_planes(&[1.0, 5.0, 20.0])?;
    /// assert_eq!(s.k(), 2);
    /// assert!(Splits::from_planes(&[1.0, 1.0]).is_err());
    /// # Ok::<(), shadow_aliasing::Error>(())
    /// ```
    pub fn from_planes(planes: &[f64]) -> Result<Splits> {
        if planes.len() < 2 || planes.len() > MAX_PARTITIONS + 1 {
            return Err(Error::invalid(
                "planes",
                format!(
                    "must hold 2 to {} depths (got {})",
                    MAX_PARTITIONS + 1,
                    planes.len()
                ),
            ));
        }
        let mut out = [0.0; MAX_PARTITIONS + 1];
        for (i, &z) in planes.iter().enumerate() {
            if !(z.is_finite() && z > 0.0) {
                return Err(Error::invalid(
                    "planes",
                    format!(
                        "must be finite and positive (got {} at index {i})",
                        fmt_num(z)
                    ),
                ));
            }
            if i > 0 && !(z / planes[i - 1]).is_finite() {
                return Err(Error::invalid(
                    "planes",
                    format!(
                        "adjacent depth ratios must be finite (got {} after {} at index {i})",
                        fmt_num(z),
                        fmt_num(planes[i - 1])
                    ),
                ));
            }
            if i > 0 && z <= planes[i - 1] {
                return Err(Error::invalid(
                    "planes",
                    format!(
                        "must be strictly increasing (got {} after {} at index {i})",
                        fmt_num(z),
                        fmt_num(planes[i - 1])
                    ),
                ));
            }
            out[i] = z;
        }
        Ok(Splits {
            planes: out,
            k: planes.len() - 1,
        })
    }

    /// The number of partitions k.
    #[inline]
    #[must_use]
    pub fn k(&self) -> usize {
        self.k
    }

    /// The `k + 1` plane depths, near to far.
    #[inline]
    #[must_use]
    pub fn planes(&self) -> &[f64] {
        &self.planes[..=self.k]
    }

    /// The depth range `(z_i, z_{i+1})` of partition `i ∈ 0..k` (0 nearest the viewer).
    ///
    /// Never panics: an index `i ≥ k` is clamped to the last partition `k − 1`.
    #[inline]
    #[must_use]
    pub fn range(&self, i: usize) -> (f64, f64) {
        let i = i.min(self.k - 1);
        (self.planes[i], self.planes[i + 1])
    }

    /// The depth ratios `z_{i+1}/z_i` of the partitions, as a fixed array (entries `k..` are 0).
    #[must_use]
    pub fn ratios(&self) -> [f64; MAX_PARTITIONS] {
        let mut r = [0.0; MAX_PARTITIONS];
        for (i, ri) in r.iter_mut().enumerate().take(self.k) {
            *ri = self.planes[i + 1] / self.planes[i];
        }
        r
    }
}

/// How to place the split planes of [`z_splits`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SplitScheme {
    /// Equal depth intervals: z_i = n + (f − n) i/k.
    Uniform,
    /// Equal depth ratios (logarithmic): z_i = n (f/n)^{i/k} (Lloyd 2006 Eq 15, 16; Lloyd 2005 §4
    /// z_i = α^{i/k} with n = 1, f = α). It minimises the largest per-partition ratio f_i/n_i.
    SelfSimilar,
    /// The "practical" split engines use: z_i = λ n (f/n)^{i/k} + (1 − λ)(n + (f − n) i/k),
    /// λ ∈ [0, 1] (0 uniform, 1 self-similar).
    Practical {
        /// Blend weight λ ∈ [0, 1].
        lambda: f64,
    },
    /// Barroso & Celes 2007 Eq 19, computed backwards from z_k = f:
    /// z_{i−1} = λ n (z_i/n)^{(i−1)/i} + (1 − λ) z_i/α for i = k, …, 2, with λ = γ/(π/2) and
    /// z₀ = n. γ = π/2 gives the self-similar planes; γ = 0 gives partitions 2..k of ratio α.
    Adaptive {
        /// γ ∈ [0, π/2], the angle between light and view directions (radians).
        light_angle: f64,
        /// α > 1, the depth ratio f_i/n_i of the far partitions when the light is parallel.
        ratio: f64,
    },
    /// Unreal Engine's cascade distribution exponent e > 0:
    /// z_i = n + (f − n)(e^i − 1)/(e^k − 1), uniform at e = 1 (each partition e times as deep
    /// as the one before it).
    Exponent {
        /// The exponent e > 0 (Unreal clamps it to [1, 4]).
        exponent: f64,
    },
}

/// The `k + 1` split-plane depths of `[near, far]` for `scheme`.
///
/// | scheme | z_i, i = 0..k |
/// |---|---|
/// | `Uniform` | n + (f − n) i/k |
/// | `SelfSimilar` | n (f/n)^{i/k} (Lloyd 2006 Eq 15, 16) |
/// | `Practical { λ }` | λ n (f/n)^{i/k} + (1 − λ)(n + (f − n) i/k) |
/// | `Adaptive { γ, α }` | Barroso & Celes 2007 Eq 19 (see [`SplitScheme::Adaptive`]) |
/// | `Exponent { e }` | n + (f − n)(e^i − 1)/(e^k − 1) |
///
/// n = `near`, f = `far` (eye-space depths, any length unit), k partitions. The first and last
/// planes are exactly `near` and `far`.
///
/// Barroso's Eq 19 prints the far ratio as "α_i" and says "f_1 = f_2"; the crate reads a single
/// α (his text: every partition but the first gets "a small value α"; with α^i the ratios at
/// γ = 0 would be α^k, …, α², not α) and f_1 = n_2 (partitions are contiguous; f_1 = f_2 would
/// make the first partition cover the second). At γ = π/2 the α term vanishes and the planes are
/// Eq 5's self-similar ones, as he states.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `near`, `far` (0 < near < far, finite, f/n finite), `k`
/// (1 ≤ k ≤ [`MAX_PARTITIONS`]), `lambda` (∈ [0, 1]), `light_angle` (∈ [0, π/2]), `ratio`
/// (finite, > 1) or `exponent` (finite, > 0); [`Error::NoSolution`] when the adaptive planes are
/// not strictly increasing (α^{k−1} too large for f/n at this γ), [`Error::Degenerate`] when
/// f/n is so close to 1 that adjacent planes round to the same `f64`.
pub fn z_splits(near: f64, far: f64, k: usize, scheme: SplitScheme) -> Result<Splits> {
    let (n, f, alpha) = near_far_ratio(near, far)?;
    if k == 0 || k > MAX_PARTITIONS {
        return Err(Error::invalid(
            "k",
            format!("must lie in [1, {MAX_PARTITIONS}] (got {k})"),
        ));
    }
    let kf = k as f64;
    let mut p = [0.0; MAX_PARTITIONS + 1];
    let uniform = |i: usize| n + (f - n) * (i as f64 / kf);
    match scheme {
        SplitScheme::Uniform => {
            for (i, z) in p[1..k].iter_mut().enumerate() {
                *z = uniform(i + 1);
            }
        }
        SplitScheme::SelfSimilar => {
            // Self-similar planes n r^i, r = (f/n)^{1/k}: one root, then products (error ≤ k
            // ulps).
            let r = root_k(alpha, k);
            if k == 4 {
                let z1 = n * r;
                let z2 = z1 * r;
                return planes4(n, z1, z2, z2 * r, f, scheme);
            }
            let mut zl = n;
            for z in &mut p[1..k] {
                zl *= r;
                *z = zl;
            }
        }
        SplitScheme::Practical { lambda } => {
            let l = in_closed("lambda", lambda, 0.0, 1.0)?;
            let r = root_k(alpha, k);
            let mut zl = n;
            for (i, z) in p[1..k].iter_mut().enumerate() {
                zl *= r;
                *z = l * zl + (1.0 - l) * uniform(i + 1);
            }
        }
        SplitScheme::Adaptive { light_angle, ratio } => {
            let g = in_closed("light_angle", light_angle, 0.0, std::f64::consts::FRAC_PI_2)?;
            let a = positive("ratio", ratio)?;
            if a <= 1.0 {
                return Err(Error::invalid(
                    "ratio",
                    format!("must be greater than 1 (got {})", fmt_num(a)),
                ));
            }
            // λ = γ/(π/2) and 1 − λ = (π/2 − γ)/(π/2), each one correctly rounded division:
            // π/2 − γ is exact for γ ∈ [π/4, π/2] (Sterbenz), so 1 − λ keeps full precision as
            // γ → π/2, where 1 − (γ/(π/2)) would amplify λ's rounding by λ/(1 − λ) (33–57×
            // near γ = 1.52; `FRAC_2_PI` as a product is one more ulp off).
            let half_pi = std::f64::consts::FRAC_PI_2;
            let l = g / half_pi;
            let one_minus_l = (half_pi - g) / half_pi;
            // In units of n: u_{i−1} = λ u_i^{(i−1)/i} + ((1 − λ)/α) u_i, u_k = f/n, and
            // z_{i−1} = n u_{i−1}. One division at the start of the chain (the per-step
            // divisions by n and α are off it).
            let c = one_minus_l / a;
            let mut u = alpha;
            if k == 4 {
                // The loop below unrolled, each product arranged off the chain u → u3 → u2 →
                // z1 where it can be (λ √u beside the second root, λ u3 beside the cube root,
                // n λ and n c beforehand): a few ulps from the loop's values.
                let r = u.sqrt();
                let u3 = (l * r) * r.sqrt() + c * u;
                let (y, b) = inv_cbrt_parts(u3);
                let u2 = ((l * u3) * y) * b + c * u3;
                let z1 = (n * l) * u2.sqrt() + (n * c) * u2;
                return planes4(n, z1, n * u2, n * u3, f, scheme);
            }
            for i in (2..=k).rev() {
                u = l * pow_i_minus_1_over_i(u, i) + c * u;
                p[i - 1] = n * u;
            }
        }
        SplitScheme::Exponent { exponent } => {
            let e = positive("exponent", exponent)?;
            let ln_e = e.ln();
            let denom = (kf * ln_e).exp_m1();
            for (i0, z) in p[1..k].iter_mut().enumerate() {
                let i = i0 + 1;
                let frac = if ln_e == 0.0 || denom == 0.0 {
                    i as f64 / kf
                } else if !denom.is_finite() {
                    // e^k overflows: e^{i−k} is the fraction up to e^{−k} corrections.
                    ((i as f64 - kf) * ln_e).exp()
                } else {
                    (i as f64 * ln_e).exp_m1() / denom
                };
                *z = n + (f - n) * frac;
            }
        }
    }
    p[0] = n;
    p[k] = f;
    for i in 1..=k {
        if !p[i].is_finite() || p[i] <= p[i - 1] {
            return Err(planes_not_increasing(scheme, i, p[i - 1], p[i], n, f, k));
        }
    }
    Ok(Splits { planes: p, k })
}

/// Four partitions (the usual cascade count) from their planes: the checks on the values and
/// the result built in place (a run-time k would index a stack array and copy it, ≈ 8 ns).
#[inline(always)]
fn planes4(n: f64, z1: f64, z2: f64, z3: f64, f: f64, scheme: SplitScheme) -> Result<Splits> {
    // n, f are finite, so a strictly increasing chain is finite too (NaN fails every compare).
    if !(n < z1 && z1 < z2 && z2 < z3 && z3 < f) {
        return Err(first_not_increasing(scheme, &[n, z1, z2, z3, f]));
    }
    let mut planes = [0.0; MAX_PARTITIONS + 1];
    planes[0] = n;
    planes[1] = z1;
    planes[2] = z2;
    planes[3] = z3;
    planes[4] = f;
    Ok(Splits { planes, k: 4 })
}

/// The error for the first plane of `p` (near to far) that is not finite or not above the
/// one before it.
#[cold]
#[inline(never)]
fn first_not_increasing(scheme: SplitScheme, p: &[f64]) -> Error {
    let k = p.len() - 1;
    let i = (1..=k)
        .find(|&i| !p[i].is_finite() || p[i] <= p[i - 1])
        .unwrap_or(k);
    planes_not_increasing(scheme, i, p[i - 1], p[i], p[0], p[k], k)
}

/// The error for planes i − 1, i out of order: [`Error::NoSolution`] for Barroso's adaptive
/// scheme (α^{k−1} too deep for f/n), [`Error::Degenerate`] for the others (f/n too close to 1).
#[cold]
#[inline(never)]
fn planes_not_increasing(
    scheme: SplitScheme,
    i: usize,
    prev: f64,
    z: f64,
    n: f64,
    f: f64,
    k: usize,
) -> Error {
    match scheme {
        SplitScheme::Adaptive { light_angle, ratio } => Error::NoSolution(format!(
            "adaptive z-partitioning (Barroso & Celes Eq 19) with ratio={}, light_angle={}, \
             k={k} puts plane {i} at {} but plane {} at {} over near={}, far={}: lower the \
             ratio or k",
            fmt_num(ratio),
            fmt_num(light_angle),
            fmt_num(z),
            i - 1,
            fmt_num(prev),
            fmt_num(n),
            fmt_num(f)
        )),
        _ => Error::Degenerate(format!(
            "split planes {} and {i} coincide ({} and {}): far/near={} is too close to 1 for \
             k={k}",
            i - 1,
            fmt_num(prev),
            fmt_num(z),
            fmt_num(f / n)
        )),
    }
}

/// x^{1/k} for x > 1: square roots for k = 1, 2, 4, 8, 16 (each correctly rounded, so within
/// a few ulps of `powf`, and several times cheaper), `powf` otherwise.
#[inline]
fn root_k(x: f64, k: usize) -> f64 {
    match k {
        1 => x,
        2 => x.sqrt(),
        4 => x.sqrt().sqrt(),
        8 => x.sqrt().sqrt().sqrt(),
        16 => x.sqrt().sqrt().sqrt().sqrt(),
        _ => x.powf(1.0 / k as f64),
    }
}

/// x^{(i−1)/i} for x > 0, i ≥ 2 (Barroso & Celes Eq 19's exponent), within a few ulps of
/// `powf` and cheaper: √x for i = 2, x · x^{−1/3} for i = 3 ([`inv_cbrt`]), √x · ⁴√x for i = 4,
/// `powf` otherwise.
#[inline]
fn pow_i_minus_1_over_i(x: f64, i: usize) -> f64 {
    match i {
        2 => x.sqrt(),
        3 => x * inv_cbrt(x),
        4 => {
            let r = x.sqrt();
            r * r.sqrt()
        }
        _ => x.powf((i - 1) as f64 / i as f64),
    }
}

/// x^{−1/3} for finite x > 0, within ≈ 2 ulps, without a division or a libm call: a guess from
/// the bits of x (the exponent divided by −3; relative error ≤ 3.5 %), scaled by a 64-entry
/// table indexed by the guess's leading mantissa bits (≤ 3.4·10⁻³), then three Newton steps
/// y ← y (4/3 − (x/3) y³), each squaring the error (≤ 2.3·10⁻⁵, 1.1·10⁻⁹, 2·10⁻¹⁸, then
/// rounding). Subnormal x (no such guess) goes to `powf`.
#[inline]
fn inv_cbrt(x: f64) -> f64 {
    let (y, b) = inv_cbrt_parts(x);
    y * b
}

/// [`inv_cbrt`] as y and the last Newton step's factor b (x^{−1/3} = y b), so a caller can
/// multiply y into its own factors while b is computed.
#[inline]
fn inv_cbrt_parts(x: f64) -> (f64, f64) {
    if !(f64::MIN_POSITIVE..=f64::MAX).contains(&x) {
        return (x.powf(-1.0 / 3.0), 1.0);
    }
    let yb = INV_CBRT_K - x.to_bits() / 3;
    let mut y = f64::from_bits(yb) * INV_CBRT_SCALE[((yb >> 46) & 63) as usize];
    let x3 = x * (1.0 / 3.0);
    // (x/3 · y)(y²): two products side by side, not y² · y · x/3 in a row.
    for _ in 0..2 {
        y *= 4.0 / 3.0 - (x3 * y) * (y * y);
    }
    (y, 4.0 / 3.0 - (x3 * y) * (y * y))
}

/// For x = 2^E (1 + m), bits/2^52 ≈ E + 1023 + m, so K − bits/3 puts −E/3 in the exponent
/// (K tuned for the least largest error over three binades).
const INV_CBRT_K: u64 = 0x553e_f0ed_3d85_9c8c;

/// The guess's error x^{−1/3}/y₀ depends only on y₀'s mantissa (three binades of x map onto
/// one of y₀): per bucket of its leading 6 bits, the factor 2 r_min r_max/(r_min + r_max) of
/// that ratio r over 65 points of the bucket (the least largest relative error), computed at
/// compile time.
const INV_CBRT_SCALE: [f64; 64] = inv_cbrt_scale();

const fn inv_cbrt_scale() -> [f64; 64] {
    let mut t = [0.0; 64];
    let mut b = 0u64;
    while b < 64 {
        let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
        let mut j = 0u64;
        while j <= 64 {
            // y₀ ∈ [1, 2) with leading mantissa bits b, and the x that gives it.
            let yb = (0x3ff << 52) | (b << 46) | (j * ((1 << 46) - 1) / 64);
            let x = f64::from_bits(3 * (INV_CBRT_K - yb));
            let y0 = f64::from_bits(yb);
            // x^{−1/3} by Newton from y₀ (converged to an ulp or two after six steps).
            let mut y = y0;
            let mut i = 0;
            while i < 6 {
                y *= 4.0 / 3.0 - (x / 3.0) * (y * y * y);
                i += 1;
            }
            let r = y / y0;
            if r < lo {
                lo = r;
            }
            if r > hi {
                hi = r;
            }
            j += 1;
        }
        t[b as usize] = 2.0 * lo * hi / (lo + hi);
        b += 1;
    }
    t
}

/// The plain reference of [`z_splits`]'s self-similar and adaptive planes: Lloyd 2006 Eq 15
/// (n (f/n)^{i/k}) and Barroso & Celes Eq 19 (u_{i−1} = λ u_i^{(i−1)/i} + ((1 − λ)/α) u_i,
/// u_k = f/n, z = n u) as written, with `powf`, one plane at a time: no k = 4 path, no root
/// shortcuts, no bit-trick cube root. The fast paths are tested against it.
#[cfg(test)]
fn z_splits_reference(n: f64, f: f64, k: usize, scheme: SplitScheme) -> Vec<f64> {
    let kf = k as f64;
    match scheme {
        SplitScheme::SelfSimilar => (0..=k).map(|i| n * (f / n).powf(i as f64 / kf)).collect(),
        SplitScheme::Adaptive { light_angle, ratio } => {
            let l = light_angle / std::f64::consts::FRAC_PI_2;
            let mut p = vec![0.0; k + 1];
            let mut u = f / n;
            p[k] = f;
            for i in (2..=k).rev() {
                u = l * u.powf((i - 1) as f64 / i as f64) + (1.0 - l) / ratio * u;
                p[i - 1] = n * u;
            }
            p[0] = n;
            p
        }
        _ => unreachable!("the reference covers the schemes with fast paths"),
    }
}

#[cfg(test)]
mod reference_tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]
        /// The bit-trick x^{−1/3} is the plain 1/∛x within 4 ulps over every binade of normal
        /// f64 (and `powf` below them).
        #[test]
        fn inv_cbrt_is_the_plain_form(e in -1021i32..1023, m in 1.0f64..2.0) {
            let x = m * 2f64.powi(e);
            let plain = 1.0 / x.cbrt();
            let fast = inv_cbrt(x);
            prop_assert!((fast - plain).abs() <= 4.0 * f64::EPSILON * plain, "x={x}: {fast} vs {plain}");
        }

        /// The self-similar and adaptive planes (the k = 4 paths, the square-root shortcuts and
        /// the bit-trick cube root included) are the plain formulas' within 10⁻¹³, relative, for
        /// every k, over f/n from 1.01 to 10¹², γ over [0, π/2] and α over (1, 10].
        #[test]
        fn z_splits_fast_paths_are_the_plain_formulas(
            ln_n in -10.0f64..10.0,
            ln_alpha in 0.01f64..27.6,
            k in 1usize..=MAX_PARTITIONS,
            gamma in 0.0f64..=std::f64::consts::FRAC_PI_2,
            ratio in 1.01f64..10.0,
            adaptive in any::<bool>(),
        ) {
            let n = ln_n.exp();
            let f = n * ln_alpha.exp();
            let scheme = if adaptive {
                SplitScheme::Adaptive { light_angle: gamma, ratio }
            } else {
                SplitScheme::SelfSimilar
            };
            let Ok(s) = z_splits(n, f, k, scheme) else {
                return Ok(());
            };
            let plain = z_splits_reference(n, f, k, scheme);
            for (a, b) in s.planes().iter().zip(&plain) {
                prop_assert!((a - b).abs() <= 1e-13 * b, "k={k} {scheme:?}: {a} vs {b}");
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hand_values() {
        let s = z_splits(1.0, 100.0, 2, SplitScheme::SelfSimilar).unwrap();
        assert_eq!(s.planes(), &[1.0, 10.0, 100.0]);
        let u = z_splits(1.0, 101.0, 4, SplitScheme::Uniform).unwrap();
        assert_eq!(u.planes(), &[1.0, 26.0, 51.0, 76.0, 101.0]);
        // Practical λ = 0.5, k = 2 over [1, 100]: (10 + 50.5)/2 = 30.25.
        let p = z_splits(1.0, 100.0, 2, SplitScheme::Practical { lambda: 0.5 }).unwrap();
        assert!((p.planes()[1] - 30.25).abs() < 1e-12);
        // Exponent e = 2, k = 3 over [0, 7] shifted to [1, 8]: fractions 1/7, 3/7.
        let e = z_splits(1.0, 8.0, 3, SplitScheme::Exponent { exponent: 2.0 }).unwrap();
        assert!((e.planes()[1] - 2.0).abs() < 1e-12);
        assert!((e.planes()[2] - 4.0).abs() < 1e-12);
        // Adaptive γ = 0, α = 2, k = 3 over [1, 100]: 100, 50, 25.
        let a = z_splits(
            1.0,
            100.0,
            3,
            SplitScheme::Adaptive {
                light_angle: 0.0,
                ratio: 2.0,
            },
        )
        .unwrap();
        assert_eq!(a.planes(), &[1.0, 25.0, 50.0, 100.0]);
        assert_eq!(a.range(7), (50.0, 100.0));
    }

    #[test]
    fn bad_inputs() {
        assert!(z_splits(1.0, 100.0, 0, SplitScheme::Uniform).is_err());
        assert!(z_splits(1.0, 100.0, 17, SplitScheme::Uniform).is_err());
        assert!(z_splits(2.0, 1.0, 2, SplitScheme::Uniform).is_err());
        assert!(z_splits(1.0, 100.0, 2, SplitScheme::Practical { lambda: 1.5 }).is_err());
        assert!(z_splits(1.0, 100.0, 2, SplitScheme::Exponent { exponent: 0.0 }).is_err());
        let too_deep = SplitScheme::Adaptive {
            light_angle: 0.0,
            ratio: 4.0,
        };
        assert!(matches!(
            z_splits(1.0, 10.0, 4, too_deep),
            Err(Error::NoSolution(_))
        ));
        assert!(Splits::from_planes(&[1.0]).is_err());
        assert!(Splits::from_planes(&[1.0, f64::NAN]).is_err());
        assert!(Splits::from_planes(&[0.0, 1.0]).is_err());
    }
}
