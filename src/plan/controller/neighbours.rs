//! A scheme's neighbours for the controller's checks between cuts: the allowed schemes that
//! differ from it only by one cascade (or face partition) more or fewer.

use crate::frame::{CascadeSplits, FrameScheme};

/// The number of cascades (or face partitions per side face) of `s`; `None` for a scheme
/// without such a count (a single map, TSM, planes given as distances or fractions, a clipmap).
pub(crate) fn count(s: &FrameScheme<'_>) -> Option<usize> {
    let of = |splits: &CascadeSplits<'_>| match *splits {
        CascadeSplits::Scheme { k, .. }
        | CascadeSplits::EqualError { k }
        | CascadeSplits::Bevy { k, .. } => Some(k),
        CascadeSplits::Distances { .. } | CascadeSplits::Fractions { .. } => None,
    };
    match s {
        FrameScheme::Cascades { splits, .. } | FrameScheme::Stable(splits) => of(splits),
        FrameScheme::Faces { k, .. } => Some(*k),
        FrameScheme::Single(_) | FrameScheme::Tsm(_) | FrameScheme::Clipmap(_) => None,
    }
}

/// `s` with its count ([`count`]) set to `k`; `None` where it has none.
pub(crate) fn with_count(s: FrameScheme<'static>, k: usize) -> Option<FrameScheme<'static>> {
    let set = |splits: CascadeSplits<'static>| match splits {
        CascadeSplits::Scheme {
            scheme, overlap, ..
        } => Some(CascadeSplits::Scheme { scheme, k, overlap }),
        CascadeSplits::EqualError { .. } => Some(CascadeSplits::EqualError { k }),
        CascadeSplits::Bevy {
            minimum_distance,
            maximum_distance,
            first_far_bound,
            overlap_proportion,
            ..
        } => Some(CascadeSplits::Bevy {
            k,
            minimum_distance,
            maximum_distance,
            first_far_bound,
            overlap_proportion,
        }),
        CascadeSplits::Distances { .. } | CascadeSplits::Fractions { .. } => None,
    };
    match s {
        FrameScheme::Cascades { splits, rule } => {
            set(splits).map(|splits| FrameScheme::Cascades { splits, rule })
        }
        FrameScheme::Stable(splits) => set(splits).map(FrameScheme::Stable),
        FrameScheme::Faces { rule, .. } => Some(FrameScheme::Faces { rule, k }),
        FrameScheme::Single(_) | FrameScheme::Tsm(_) | FrameScheme::Clipmap(_) => None,
    }
}

/// The schemes of `allowed` with one count more or fewer than `kept` and otherwise the same,
/// fewer first.
pub(crate) fn neighbours(
    kept: FrameScheme<'static>,
    allowed: &[FrameScheme<'static>],
) -> Vec<FrameScheme<'static>> {
    let Some(k) = count(&kept) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for want in [k.wrapping_sub(1), k + 1] {
        if let Some(s) = allowed
            .iter()
            .find(|s| count(s) == Some(want) && with_count(**s, k) == Some(kept))
        {
            out.push(*s);
        }
    }
    out
}

/// The interior planes of `k` cascades, as fractions of a depth range, placed where the kept
/// planes `fractions` (k₀ − 1 of them) would put them if their spacing were a curve: the
/// piecewise-linear φ through (i/k₀, φᵢ), with φ(0) = 0 and φ(1) = 1, at j/k for j = 1 … k − 1.
/// The controller measures an equal-error neighbour with these planes (one frame) instead of
/// its search.
pub(crate) fn resampled(fractions: &[f64], k: usize) -> Vec<f64> {
    let k0 = fractions.len() + 1;
    let at = |i: usize| match i {
        0 => 0.0,
        i if i >= k0 => 1.0,
        i => fractions[i - 1],
    };
    (1..k)
        .map(|j| {
            let u = j as f64 * k0 as f64 / k as f64;
            let i = (u.floor() as usize).min(k0 - 1);
            let t = u - i as f64;
            at(i) + t * (at(i + 1) - at(i))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analytic::partition::SplitScheme;
    use crate::maps::WarpRule;

    #[test]
    fn resampled_planes_follow_the_kept_curve() {
        // Kept: 2 planes of 3 cascades at 0.1 and 0.4 (φ(1/3) = 0.1, φ(2/3) = 0.4).
        // 2 cascades: φ(1/2) = 0.1 + 0.5 (0.4 − 0.1) = 0.25 (by hand).
        assert_eq!(resampled(&[0.1, 0.4], 2), vec![0.25]);
        // 4 cascades: u = 3/4 → 0.075, 6/4 → 0.25, 9/4 → 0.4 + 0.25 · 0.6 = 0.55.
        let r = resampled(&[0.1, 0.4], 4);
        let want = [0.075, 0.25, 0.55];
        for (a, b) in r.iter().zip(want) {
            assert!((a - b).abs() < 1e-15, "{r:?}");
        }
        assert_eq!(r.len(), 3);
    }

    #[test]
    fn neighbours_differ_by_one_count_only() {
        let log = |k| FrameScheme::Cascades {
            splits: CascadeSplits::Scheme {
                scheme: SplitScheme::SelfSimilar,
                k,
                overlap: 0.0,
            },
            rule: WarpRule::Lispsm,
        };
        let uni = |k| FrameScheme::Cascades {
            splits: CascadeSplits::Scheme {
                scheme: SplitScheme::SelfSimilar,
                k,
                overlap: 0.0,
            },
            rule: WarpRule::Uniform,
        };
        let allowed = [log(2), log(3), uni(3), log(4), uni(4), log(6)];
        assert_eq!(neighbours(log(3), &allowed), vec![log(2), log(4)]);
        assert_eq!(neighbours(uni(3), &allowed), vec![uni(4)]);
        assert_eq!(neighbours(log(4), &allowed), vec![log(3)]);
        assert!(neighbours(FrameScheme::Single(WarpRule::Lispsm), &allowed).is_empty());
    }
}
