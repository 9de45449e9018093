//! z-partitions (cascades): where to split the view frustum along its depth, and what each
//! scheme costs in shadow-map storage.
//!
//! # Split planes
//!
//! [`z_splits`] returns the `k + 1` plane depths `near = z₀ < z₁ < … < z_k = far` of a
//! [`SplitScheme`]: the papers' self-similar (logarithmic) scheme (Lloyd 2006 Eq 15, 16;
//! Lloyd 2005 §4 with near = 1, far = α), the uniform one, the practical λ-blend of the two
//! that engines use, Barroso & Celes' adaptive scheme (Eq 19) and Unreal's exponent
//! distribution. All of it lives in a fixed-size [`Splits`] (no heap allocation), so a
//! renderer may call it every frame.
//!
//! ```
//! use shadow_aliasing::analytic::partition::{z_splits, SplitScheme};
//! let s = z_splits(1.0, 1000.0, 3, SplitScheme::SelfSimilar)?;
//! let p = s.planes();
//! assert_eq!(p.len(), 4);
//! assert!((p[1] - 10.0).abs() < 1e-12 && (p[2] - 100.0).abs() < 1e-12);
//! assert_eq!(s.range(0), (1.0, p[1]));
//! # Ok::<(), shadow_aliasing::Error>(())
//! ```

mod splits;
mod storage;

pub use splits::{z_splits, SplitScheme, Splits, MAX_PARTITIONS};
pub use storage::{
    fp_zp_w_overhead_asymptotic, optimal_storage_factor, scheme_storage_factor, shadow_map_count,
    splits_storage_factor, zp_overhead_asymptotic, Scheme, SchemeLight,
};
