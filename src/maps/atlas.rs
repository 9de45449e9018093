//! The partitions of one frame packed into one shadow texture (Lloyd 2006 §6.1, Lloyd 2005 §4.1
//! "Subdivision layout").
//!
//! # Allocation (Lloyd 2005 Eq 6)
//!
//! A shadow map of `r_s` texels along one axis shared by subdivisions of maximum errors `e_i`
//! gives subdivision i
//!
//! ```text
//! r_si = r_s · e_i / Σ_j e_j                                   (Lloyd 2005 Eq 6)
//! ```
//!
//! texels, so that the error after allocation, `e_i / r_si = Σ_j e_j / r_s`, is the same for all.
//! [`allocate_texels`] rounds this to whole texels with the largest-remainder rule, so that the
//! integers sum exactly to `r_s` and each differs from the real share by less than one texel.
//!
//! # The x-then-z split (Lloyd 2005 §4.1)
//!
//! The partitions are grouped (Lloyd 2005: the two subdivisions of opposite frustum faces; the
//! crate lets the caller say which partitions share a group). The texture's width (its s axis,
//! the partitions' x direction) is first split among the groups by Eq 6 applied to each group's
//! largest maximum x error `M_x`; then each group's column is split along the height (t, the
//! partitions' z direction) among its members by Eq 6 applied to their maximum z errors `M_z`.
//! Every partition gets a rectangle [`Viewport`]; the rectangles tile the texture exactly.
//!
//! # Matrices
//!
//! A partition's shadow matrix maps its region to x, y ∈ [−1, 1]. [`Viewport::clip_matrix`] is
//! the affine map of that square onto the partition's rectangle in the atlas's own clip space,
//! so `viewport.clip_matrix() * matrix` renders the partition into its rectangle of the one
//! texture (and, with `s = (x/w + 1)/2`, `t = (y/w + 1)/2`, samples it there).
//!
//! ```
//! use shadow_aliasing::maps::atlas::{layout, AtlasEntry};
//! let entries = [
//!     AtlasEntry { group: 0, max_mx: 1.0, max_mz: 3.0 },
//!     AtlasEntry { group: 0, max_mx: 1.0, max_mz: 1.0 },
//!     AtlasEntry { group: 1, max_mx: 2.0, max_mz: 5.0 },
//! ];
//! let atlas = layout(1200, 800, &entries)?;
//! let v = atlas.viewports();
//! assert_eq!((v[0].width, v[1].width, v[2].width), (400, 400, 800));
//! assert_eq!((v[0].height, v[1].height, v[2].height), (600, 200, 800));
//! # Ok::<(), shadow_aliasing::Error>(())
//! ```

use crate::analytic::partition::MAX_PARTITIONS;
use crate::error::{fmt_num, Error, Result};
use crate::numeric::sort_by_keys;
use glam::DMat4;

/// The largest number of partitions one atlas holds: four side faces of [`MAX_PARTITIONS`]
/// z-partitions each, and the near face.
pub const MAX_ATLAS_ENTRIES: usize = 4 * MAX_PARTITIONS + 1;

/// Texels per subdivision by Lloyd 2005 Eq 6, `r_si = r_s e_i / Σ e_j`, rounded to whole texels
/// by the largest-remainder rule (ties to the lower index): the result sums exactly to `total`
/// and each entry is within one texel of its real share. Written into `out[..errors.len()]`.
///
/// `errors`: the maximum error of each subdivision (any positive unit, only ratios matter);
/// `total`: texels along the axis being shared.
///
/// This is [`crate::analytic::subdivided::allocate_texels_whole`] writing into the first
/// `errors.len()` entries of `out`, for at most [`MAX_ATLAS_ENTRIES`] partitions.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `errors` when empty, longer than `out` (or than
/// [`MAX_ATLAS_ENTRIES`]), or holding a value that is not finite and positive; naming `total`
/// when it is 0.
///
/// ```
/// # use shadow_aliasing::maps::atlas::allocate_texels;
/// let mut out = [0u32; 3];
/// allocate_texels(&[1.0, 1.0, 1.0], 100, &mut out)?;
/// assert_eq!(out, [34, 33, 33]);
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn allocate_texels(errors: &[f64], total: u32, out: &mut [u32]) -> Result<()> {
    let cap = out.len().min(MAX_ATLAS_ENTRIES);
    if errors.is_empty() || errors.len() > cap {
        return Err(Error::invalid(
            "errors",
            format!("must hold 1 to {cap} values (got {})", errors.len()),
        ));
    }
    // One implementation of Eq 6 in whole texels, shared with the closed forms.
    crate::analytic::subdivided::allocate_texels_whole(errors, total, &mut out[..errors.len()])
}

/// One partition to place: its group (partitions of one group share a column) and its maximum
/// errors over its region, M_x and M_z (any common unit, only ratios matter).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AtlasEntry {
    /// Column group; groups are laid out left to right in increasing order.
    pub group: usize,
    /// Maximum error along x (the map's s direction), sizes the column.
    pub max_mx: f64,
    /// Maximum error along z (the map's t direction), sizes the rectangle within the column.
    pub max_mz: f64,
}

/// A rectangle of the atlas texture in texels: `x, y` of its lower-left corner (s and t grow
/// with x and y), `width × height` texels.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Viewport {
    /// First texel column.
    pub x: u32,
    /// First texel row.
    pub y: u32,
    /// Columns.
    pub width: u32,
    /// Rows.
    pub height: u32,
    /// The atlas width in texels.
    pub atlas_width: u32,
    /// The atlas height in texels.
    pub atlas_height: u32,
}

impl Viewport {
    /// The affine map of clip x, y ∈ [−1, 1] onto this rectangle in the atlas's clip space
    /// (x ∈ [−1 + 2x₀/W, −1 + 2(x₀ + w)/W], likewise y), depth and w unchanged:
    ///
    /// ```text
    /// X = a_x x + b_x w,  a_x = w/W,  b_x = (2 x₀ + w)/W − 1   (same for Y with y₀, h, H)
    /// ```
    #[must_use]
    pub fn clip_matrix(&self) -> DMat4 {
        let (w, h) = (f64::from(self.atlas_width), f64::from(self.atlas_height));
        let ax = f64::from(self.width) / w;
        let bx = (2.0 * f64::from(self.x) + f64::from(self.width)) / w - 1.0;
        let ay = f64::from(self.height) / h;
        let by = (2.0 * f64::from(self.y) + f64::from(self.height)) / h - 1.0;
        DMat4::from_cols_array(&[
            ax, 0.0, 0.0, 0.0, //
            0.0, ay, 0.0, 0.0, //
            0.0, 0.0, 1.0, 0.0, //
            bx, by, 0.0, 1.0,
        ])
    }

    /// Number of texels, width × height.
    #[must_use]
    pub fn texels(&self) -> u64 {
        u64::from(self.width) * u64::from(self.height)
    }
}

/// The layout of one frame's partitions in one texture.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Atlas {
    viewports: [Viewport; MAX_ATLAS_ENTRIES],
    len: usize,
    width: u32,
    height: u32,
}

impl Atlas {
    /// The viewports, in the order of the entries given to [`layout`].
    #[must_use]
    pub fn viewports(&self) -> &[Viewport] {
        &self.viewports[..self.len]
    }
    /// Atlas width in texels.
    #[must_use]
    pub fn width(&self) -> u32 {
        self.width
    }
    /// Atlas height in texels.
    #[must_use]
    pub fn height(&self) -> u32 {
        self.height
    }
    /// `viewport(i).clip_matrix() * matrix`: partition i's shadow matrix rendering into its
    /// rectangle of the atlas. `None` when `i` is out of range.
    #[must_use]
    pub fn compose(&self, i: usize, matrix: &DMat4) -> Option<DMat4> {
        self.viewports().get(i).map(|v| v.clip_matrix() * *matrix)
    }
}

/// Packs `entries` into a `width × height` texture by the x-then-z split of the module docs.
///
/// Columns are given to groups in increasing group order, widths by Eq 6 over each group's
/// largest `max_mx`; within a column the members, in the order given, stack bottom to top with
/// heights by Eq 6 over their `max_mz`. With whole texels a partition whose share rounds to zero
/// gets zero texels: give the texture at least one texel per group along x and one per member
/// along y (the function refuses layouts that would leave a partition empty).
///
/// # Errors
/// [`Error::InvalidArgument`] naming `entries` (empty, more than [`MAX_ATLAS_ENTRIES`], an
/// error that is not finite and positive), `width` or `height` (zero, or too small to give every
/// partition at least one texel).
pub fn layout(width: u32, height: u32, entries: &[AtlasEntry]) -> Result<Atlas> {
    if entries.is_empty() || entries.len() > MAX_ATLAS_ENTRIES {
        return Err(Error::invalid(
            "entries",
            format!(
                "must hold 1 to {MAX_ATLAS_ENTRIES} partitions (got {})",
                entries.len()
            ),
        ));
    }
    if width == 0 || height == 0 {
        return Err(Error::invalid(
            if width == 0 { "width" } else { "height" },
            "must be at least 1 texel (got 0)",
        ));
    }
    // Distinct groups in increasing order, each with its largest M_x.
    let mut groups = [0usize; MAX_ATLAS_ENTRIES];
    let mut gx = [0.0f64; MAX_ATLAS_ENTRIES];
    let mut ng = 0;
    for e in entries {
        for (name, v) in [("entries", e.max_mx), ("entries", e.max_mz)] {
            if !(v.is_finite() && v > 0.0) {
                return Err(Error::invalid(
                    name,
                    format!("must have finite, positive errors (got {})", fmt_num(v)),
                ));
            }
        }
        match groups[..ng].iter().position(|&g| g == e.group) {
            Some(i) => gx[i] = gx[i].max(e.max_mx),
            None => {
                groups[ng] = e.group;
                gx[ng] = e.max_mx;
                ng += 1;
            }
        }
    }
    sort_by_keys(&mut groups[..ng], &mut gx[..ng]);
    let mut widths = [0u32; MAX_ATLAS_ENTRIES];
    allocate_texels(&gx[..ng], width, &mut widths)?;
    let mut viewports = [Viewport::default(); MAX_ATLAS_ENTRIES];
    let mut x0 = 0u32;
    for gi in 0..ng {
        if widths[gi] == 0 {
            return Err(Error::invalid(
                "width",
                format!(
                    "is too small: group {} gets no column at {width} texels",
                    groups[gi]
                ),
            ));
        }
        let mut idx = [0usize; MAX_ATLAS_ENTRIES];
        let mut ez = [0.0f64; MAX_ATLAS_ENTRIES];
        let mut nm = 0;
        for (i, e) in entries.iter().enumerate() {
            if e.group == groups[gi] {
                idx[nm] = i;
                ez[nm] = e.max_mz;
                nm += 1;
            }
        }
        let mut heights = [0u32; MAX_ATLAS_ENTRIES];
        allocate_texels(&ez[..nm], height, &mut heights)?;
        let mut y0 = 0u32;
        for m in 0..nm {
            if heights[m] == 0 {
                return Err(Error::invalid(
                    "height",
                    format!(
                        "is too small: partition {} gets no rows at {height} texels",
                        idx[m]
                    ),
                ));
            }
            viewports[idx[m]] = Viewport {
                x: x0,
                y: y0,
                width: widths[gi],
                height: heights[m],
                atlas_width: width,
                atlas_height: height,
            };
            y0 += heights[m];
        }
        x0 += widths[gi];
    }
    Ok(Atlas {
        viewports,
        len: entries.len(),
        width,
        height,
    })
}
