//! Error-equalising cascade splits ([`CascadeSplits::EqualError`](super::CascadeSplits::EqualError)): the k − 1 planes placed so
//! that every cascade's measured maximum error over its focus body is the same.
//!
//! # The search
//!
//! Let e(a, b) be the measured maximum error max(M_x, M_z) of the map the frame builds for the
//! slice `[a, b]` (its focus body B ∩ the slice, its rule, its light; 0 where no map is needed).
//! A map of a larger slice covers a larger body, so e grows with b and falls with a. The search
//! runs on the depth range of B itself, `[lo, hi]` = the visible depth range ∩ B's eye-depth
//! extent (SDSM: nothing outside it needs texels):
//!
//! - *Sweep* (a target error E): from `a = lo`, each cascade but the last ends at the b where
//!   e(a, b) = E (a root of a function monotone in b, bracketed from the previous sweep's plane
//!   by [`bracket`] and found by [`itp`] on ln b), and the next starts there. The sweep says *too small* when a cascade's error exceeds E even at the least
//!   depth (10⁻⁷ of its near distance, at least 10⁻⁸ of the frustum's size), *too large* when a cascade before the last already reaches
//!   `hi` within E, and otherwise gives the last cascade's error e(b_{k−1}, hi).
//! - *Equalise*: h(E) = ln e_last(E) − ln E (+∞ for too small, −∞ for too large) falls with E; its
//!   root, found by [`itp`] on ln E, makes every cascade's error E. The bracket starts at the
//!   least and largest cascade errors of the logarithmic splits (for monotone errors the equal
//!   error lies between the least and largest cascade errors of *any* splits), widened by factors
//!   of 2 when it does not bracket.
//!
//! - *Best found*: every complete sweep (reaching the far end: [`Sweep::Last`], or
//!   [`Sweep::TooLarge`] with its logarithmic tail measured) has a measured largest cascade error;
//!   the answer is the least of them and of the logarithmic splits'. A sweep's planes depend on
//!   where its root searches start (the previous sweep's planes), so where h jumps from +∞ to −∞
//!   (a cascade's error with a floor equal to the target: a box's near edge fixing the first
//!   cascade's error) the converged E swept again can fall on the other side; the best complete
//!   sweep is kept instead, and a search without a bracket keeps it too.
//!
//! With monotone errors the equal-error splits minimise the largest cascade error over all splits
//! of k cascades (any other splits have a cascade that contains an equal-error cascade). The
//! frame's first cascade starts at the visible range's near end and its last ends at the far end
//! (the maps cover the same bodies).
//!
//! For a frustum-only body the error of a slice depends only on its depth ratio b/a (the slice
//! scaled is the same map), so equal errors are equal ratios: the logarithmic splits of Lloyd
//! 2006 Eq 15–16, `z_i = n (f/n)^{i/k}` (tests/equal_error.rs).
//!
//! Every search is bounded ([`MAX_ITERATIONS`] evaluations per root); a split's root search that
//! does not converge (a NaN error) is [`Error::NoSolution`]. The result is never worse than the
//! logarithmic splits. No heap allocation on success.
//!
//! Stable cascades ([`SliceMap::Stable`]) are not searched: their equal-error planes are the
//! logarithmic splits of B's range in closed form, its ends on a grid that keeps them fixed
//! under small camera moves ([`super::stable_splits`]).

use super::{Built, Ctx, Slice};
use crate::analytic::partition::{z_splits, SplitScheme, MAX_PARTITIONS};
use crate::error::{Error, Result};
use crate::maps::WarpRule;

/// The most function evaluations of one root search (the splits' or the equal error's).
pub const MAX_ITERATIONS: usize = 100;

/// The least depth of a cascade in the sweep, relative to its near distance and to the
/// frustum's size: below it a slice's body is too thin to measure (the frame maps a body of
/// relative depth 10⁻⁹ unwarped, and one thinner than 10⁻⁹ of the frustum's size not at all).
const MIN_RELATIVE_DEPTH: f64 = 1e-7;
const MIN_DEPTH_OF_SIZE: f64 = 1e-8;

/// Convergence of the splits (in ln z) and of the equal error (in ln E): 10⁻¹¹ relative to
/// 1 + |x|, below the 10⁻⁹ to which the logarithmic splits are reproduced.
const LOG_TOLERANCE: f64 = 1e-11;

/// A split is found once its cascade's ln error is within 10⁻¹² of ln E (the error to 10⁻¹²).
const SPLIT_MATCH: f64 = 1e-12;

/// The equal error is found once the last cascade's ln error is within 10⁻¹⁰ of ln E: the
/// splits' own tolerance leaves h about that uncertain, so a tighter match would only stall.
const EQUAL_MATCH: f64 = 1e-10;

/// How a slice is mapped: a warp rule ([`FrameScheme::Cascades`](super::FrameScheme::Cascades))
/// or the stable cascade ([`FrameScheme::Stable`](super::FrameScheme::Stable)).
#[derive(Debug, Clone, Copy)]
pub(super) enum SliceMap {
    Rule(WarpRule),
    Stable,
}

/// A sweep's outcome for a target error.
enum Sweep {
    /// A cascade's error exceeds the target at its least depth.
    TooSmall,
    /// A cascade before the last reaches the far end within the target (the planes after it
    /// split it logarithmically): the largest measured error of those logarithmic cascades.
    TooLarge(f64),
    /// The last cascade's error.
    Last(f64),
}

impl Ctx<'_, '_> {
    /// The measured maximum error max(M_x, M_z) of the slice `[a, b]`'s map (unit resolutions
    /// aside: the frame's), 0 where no map is needed.
    fn slice_error(&self, a: f64, b: f64, rule: WarpRule) -> Result<f64> {
        let s = Slice {
            cover: (a, b),
            split: (a, b),
            blend: (b, b),
            res: self.input.map_resolution,
        };
        let mut map = None;
        let built = self.map(&s, rule, &mut map)?;
        Ok(match (built, map) {
            (Built::Map, Some(m)) => m.max_mx.max(m.max_mz),
            _ => 0.0,
        })
    }

    /// The least depth of a cascade starting at `a` (see [`MIN_RELATIVE_DEPTH`]).
    fn least_depth(&self, a: f64) -> f64 {
        (MIN_RELATIVE_DEPTH * a).max(MIN_DEPTH_OF_SIZE * self.scale())
    }

    /// The sweep for the target error `e` (module docs), writing its planes into `planes[..=k]`
    /// (from `lo` to `hi`; complete for [`Sweep::Last`] and [`Sweep::TooLarge`]).
    fn sweep(
        &self,
        e: f64,
        k: usize,
        (lo, hi): (f64, f64),
        rule: WarpRule,
        planes: &mut [f64; MAX_PARTITIONS + 1],
    ) -> Result<Sweep> {
        let ln_e = e.ln();
        let mut a = lo;
        planes[0] = lo;
        planes[k] = hi;
        for i in 0..k - 1 {
            let b_min = a + self.least_depth(a);
            if b_min >= hi {
                return Ok(Sweep::TooSmall);
            }
            let g = |u: f64| Ok(self.slice_error(a, u.exp(), rule)?.ln() - ln_e);
            // The previous sweep's plane (the logarithmic one at first) is the first guess.
            let found = bracket(g, planes[i + 1].ln(), (b_min.ln(), hi.ln()))?;
            let (lo_pt, hi_pt) = match found {
                Bracket::Below => return Ok(Sweep::TooSmall),
                Bracket::Above => {
                    // Cascade i reaches the far end within E: the rest split it logarithmically
                    // (slices of it, whose errors are no larger with monotone errors).
                    let m = (k - i) as f64;
                    for (j, plane) in planes.iter_mut().enumerate().take(k).skip(i + 1) {
                        *plane = a * (hi / a).powf((j - i) as f64 / m);
                    }
                    let mut tail = 0.0f64;
                    for j in i..k {
                        tail = tail.max(self.slice_error(planes[j], planes[j + 1], rule)?);
                    }
                    return Ok(Sweep::TooLarge(tail));
                }
                Bracket::Between(lo_pt, hi_pt) => (lo_pt, hi_pt),
            };
            let ln_b = itp(g, lo_pt, hi_pt, SPLIT_MATCH, "the cascade splits")?;
            a = ln_b.exp().clamp(b_min, hi);
            planes[i + 1] = a;
        }
        Ok(Sweep::Last(self.slice_error(a, hi, rule)?))
    }

    /// h(E) of the module docs for ln E = `v`; a complete sweep's planes replace `best`'s when
    /// their largest cascade error (the target, or the last cascade's if larger) is less.
    fn imbalance(
        &self,
        v: f64,
        k: usize,
        range: (f64, f64),
        rule: WarpRule,
        planes: &mut [f64; MAX_PARTITIONS + 1],
        best: &mut Best,
    ) -> Result<f64> {
        let e = v.exp();
        let (h, largest) = match self.sweep(e, k, range, rule, planes)? {
            Sweep::TooSmall => return Ok(f64::INFINITY),
            Sweep::TooLarge(tail) => (f64::NEG_INFINITY, tail.max(e)),
            Sweep::Last(last) => (last.ln() - v, last.max(e)),
        };
        if largest < best.largest {
            best.largest = largest;
            best.planes = *planes;
        }
        Ok(h)
    }

    /// The equal-error slices of the visible range `[zn, zf]` (module docs; for stable cascades
    /// the closed form of [`super::stable_splits`]); returns k.
    pub(super) fn equal_error_slices(
        &self,
        k: usize,
        how: SliceMap,
        zn: f64,
        zf: f64,
        out: &mut [Slice; MAX_PARTITIONS],
    ) -> Result<usize> {
        let body = self.body(zn, zf, &[])?;
        let (mut lo, mut hi) = (zn, zf);
        if body.n > 0 {
            let (n_b, f_b) = super::body::depth_extent(&body.v[..body.n]);
            (lo, hi) = (n_b.max(zn), f_b.min(zf));
        }
        let deep = hi - lo > 2.0 * k as f64 * self.least_depth(hi);
        if !deep {
            // B has no depth to split (or is empty): the visible range's logarithmic splits.
            (lo, hi) = (zn, zf);
        }
        let mut planes = [0.0; MAX_PARTITIONS + 1];
        match how {
            SliceMap::Stable if deep => {
                super::stable_splits::stable_planes((zn, zf), (lo, hi), k, &mut planes)?;
            }
            _ => {
                // The logarithmic splits: the answer where no map is needed anywhere.
                let log = z_splits(lo, hi, k, SplitScheme::SelfSimilar)?;
                planes[..=k].copy_from_slice(log.planes());
                if let (SliceMap::Rule(rule), true) = (how, k > 1 && deep) {
                    self.equalise(k, (lo, hi), rule, &mut planes)?;
                }
            }
        }
        // Each map covers its measured slice of B's range; the shader's selection ranges reach
        // the visible range's ends.
        for (i, slot) in out.iter_mut().enumerate().take(k) {
            let cover = (planes[i], planes[i + 1]);
            let split = (
                if i == 0 { zn } else { cover.0 },
                if i + 1 == k { zf } else { cover.1 },
            );
            *slot = Slice {
                cover,
                split,
                blend: (split.1, split.1),
                res: self.input.map_resolution,
            };
        }
        Ok(k)
    }

    /// The root of h on ln E, its planes in `planes[1..k]`.
    fn equalise(
        &self,
        k: usize,
        (lo, hi): (f64, f64),
        rule: WarpRule,
        planes: &mut [f64; MAX_PARTITIONS + 1],
    ) -> Result<()> {
        // The bracket: the least and largest cascade errors of the logarithmic splits of B's range.
        let log = z_splits(lo, hi, k, SplitScheme::SelfSimilar)?;
        let (mut e_lo, mut e_hi) = (f64::INFINITY, 0.0f64);
        let log_planes = *planes;
        for i in 0..k {
            let (a, b) = log.range(i);
            let e = self.slice_error(a, b, rule)?;
            e_lo = e_lo.min(e);
            e_hi = e_hi.max(e);
        }
        let whole = self.slice_error(lo, hi, rule)?;
        if !(whole > 0.0 && whole.is_finite()) {
            // No map is needed anywhere (or none can be measured): any splits do.
            return Ok(());
        }
        e_lo = e_lo.clamp(f64::MIN_POSITIVE, whole);
        // The logarithmic splits themselves are the first candidate.
        let mut best = Best {
            largest: e_hi,
            planes: log_planes,
        };
        e_hi = e_hi.clamp(e_lo, whole);
        let mut h = |v: f64, planes: &mut [f64; MAX_PARTITIONS + 1]| {
            self.imbalance(v, k, (lo, hi), rule, planes, &mut best)
        };
        // v0: E too small (h > 0); v1: E large enough (h ≤ 0).
        let (mut v0, mut v1) = (e_lo.ln(), e_hi.ln());
        let mut h0 = h(v0, planes)?;
        let mut h1 = f64::NAN;
        let mut widen = 0;
        while h0 <= 0.0 && widen < MAX_ITERATIONS {
            if h0 == 0.0 {
                break;
            }
            (v1, h1) = (v0, h0);
            v0 -= std::f64::consts::LN_2;
            h0 = h(v0, planes)?;
            widen += 1;
        }
        if h0 > 0.0 {
            if h1.is_nan() {
                h1 = h(v1, planes)?;
            }
            while h1 > 0.0 && v1 < whole.ln() && widen < MAX_ITERATIONS {
                (v0, h0) = (v1, h1);
                v1 = (v1 + std::f64::consts::LN_2).min(whole.ln());
                h1 = h(v1, planes)?;
                widen += 1;
            }
        }
        // Without a bracket (h > 0 even for the whole range's error: the sweep's planes from
        // its root searches leave the last cascade no depth) the best sweep run is the answer.
        if h0 > 0.0 && h1 <= 0.0 {
            itp(
                |v| h(v, planes),
                (v1, h1),
                (v0, h0),
                EQUAL_MATCH,
                "the equal error",
            )?;
        }
        // The answer is the best complete sweep that the search ran (every sweep's planes depend
        // on its bracket's start, the previous sweep's planes: where h jumps from +∞ to −∞, as
        // where a cascade's error has a floor equal to the target, the sweep at the converged E
        // run again can fall on the other side; issue 24). With monotone errors it is the
        // converged E's; it is never worse than the logarithmic splits.
        *planes = best.planes;
        Ok(())
    }
}

/// The planes of the least largest cascade error among the sweeps run (and the logarithmic
/// splits'), with that error (the target where the sweep reached the far end early: its
/// logarithmic tail is no worse with monotone errors).
struct Best {
    largest: f64,
    planes: [f64; MAX_PARTITIONS + 1],
}

/// Where a rising `g` crosses 0 on `[x_min, x_max]`, seen from a guess.
enum Bracket {
    /// `g > 0` already at `x_min`.
    Below,
    /// `g ≤ 0` still at `x_max`.
    Above,
    /// `(x, g(x))` with `g ≤ 0`, then `(x, g(x))` with `g > 0`.
    Between((f64, f64), (f64, f64)),
}

/// The bracket of `g`'s crossing nearest the guess `x` (clamped to `[x_min, x_max]`): steps away
/// from it, a thousandth of the interval first and four times longer each time (at most 6
/// steps before an end), toward larger x where `g ≤ 0` and smaller x where `g > 0`. A guess near
/// the root (the previous sweep's plane) gives a bracket a few steps of [`itp`] close.
fn bracket(
    mut g: impl FnMut(f64) -> Result<f64>,
    x: f64,
    (x_min, x_max): (f64, f64),
) -> Result<Bracket> {
    let x = if x.is_finite() {
        x.clamp(x_min, x_max)
    } else {
        0.5 * (x_min + x_max)
    };
    let mut step = 1e-3 * (x_max - x_min);
    let mut last = (x, g(x)?);
    if last.1 <= 0.0 {
        loop {
            if last.0 >= x_max {
                return Ok(Bracket::Above);
            }
            let x = (last.0 + step).min(x_max);
            let next = (x, g(x)?);
            if next.1 > 0.0 {
                return Ok(Bracket::Between(last, next));
            }
            last = next;
            step *= 4.0;
        }
    }
    loop {
        if last.0 <= x_min {
            return Ok(Bracket::Below);
        }
        let x = (last.0 - step).max(x_min);
        let next = (x, g(x)?);
        if next.1 <= 0.0 {
            return Ok(Bracket::Between(next, last));
        }
        last = next;
        step *= 4.0;
    }
}

/// A root of `g` between `x0` (where `g ≤ 0`) and `x1` (where `g > 0`), either order, by the ITP
/// method (Oliveira & Takahashi 2020: interpolation, truncation, projection): regula falsi's
/// point where `g` is smooth, never more evaluations than bisection's plus one, whatever `g` is
/// (a kink, a jump, a flat part, infinite values). Returns the bracket's end where `g ≤ 0` once
/// the bracket is narrower than [`LOG_TOLERANCE`] (relative to 1 + |x|), or a point where
/// `|g| ≤ ytol`: so a flat part at the root gives the end of it nearest `x1`.
///
/// # Errors
/// Those of `g`; [`Error::NoSolution`] naming `what` if `g` is NaN, or after [`MAX_ITERATIONS`]
/// evaluations (bisection needs about 50 for the widest bracket, so it is not reached).
fn itp(
    mut g: impl FnMut(f64) -> Result<f64>,
    (x0, g0): (f64, f64),
    (x1, g1): (f64, f64),
    ytol: f64,
    what: &str,
) -> Result<f64> {
    // Oriented so that y = s·g is ≤ 0 at `a` and > 0 at `b`, a < b.
    let s = if x0 < x1 { 1.0 } else { -1.0 };
    let (mut a, mut ya, mut b, mut yb) = if x0 < x1 {
        (x0, g0, x1, g1)
    } else {
        (x1, -g1, x0, -g0)
    };
    let eps = 0.5 * LOG_TOLERANCE * (1.0 + a.abs().max(b.abs()));
    let n_half = ((b - a) / (2.0 * eps)).log2().ceil().max(0.0);
    let n_max = n_half + 1.0;
    let k1 = 0.2 / (b - a);
    let mut j = 0.0;
    for _ in 0..MAX_ITERATIONS {
        if b - a <= 2.0 * eps {
            return Ok(if s > 0.0 { a } else { b });
        }
        let half = 0.5 * (a + b);
        let r = (eps * (n_max - j).exp2() - 0.5 * (b - a)).max(0.0);
        let delta = k1 * (b - a) * (b - a);
        let falsi = (yb * a - ya * b) / (yb - ya);
        let x = if falsi.is_finite() && falsi > a && falsi < b {
            let sigma = (half - falsi).signum();
            let t = if delta <= (half - falsi).abs() {
                falsi + sigma * delta
            } else {
                half
            };
            if (t - half).abs() <= r {
                t
            } else {
                half - sigma * r
            }
        } else {
            half
        };
        let y = s * g(x)?;
        if y.is_nan() {
            return Err(no_convergence(what));
        }
        if y.abs() <= ytol {
            return Ok(x);
        }
        if y > 0.0 {
            (b, yb) = (x, y);
        } else {
            (a, ya) = (x, y);
        }
        j += 1.0;
    }
    Err(no_convergence(what))
}

#[cold]
#[inline(never)]
fn no_convergence(what: &str) -> Error {
    Error::NoSolution(format!(
        "the search for {what} of equal-error cascades did not converge in {MAX_ITERATIONS} \
         steps (the cascades' errors are not monotone in their depth here): use splits of a \
         SplitScheme (CascadeSplits::Scheme) instead"
    ))
}
