//! Drawing helpers shared by the figures: axes with linear or logarithmic scales and chosen tick
//! marks, line charts that clip their data to the axes (plotters draws points outside an axis
//! range on the border, so nothing is handed to it unclipped), heat maps on rectangular and
//! hemispherical grids with a quantised colour scale, colour bars, and the page frame (title on
//! top, the caption naming the paper and figure at the bottom).
//!
//! Everything here works in *axis space*: a logarithmic axis is drawn as a linear plotters axis
//! over log_b of the data, with tick marks placed and labelled by [`Axis`]. That keeps one
//! concrete chart type for every combination of linear and logarithmic axes.

mod aspect;
mod axis;
mod bar;
mod colour_map;
mod fine;
mod heat;
mod hemisphere_key;
mod label;
mod legend;
mod line;
mod marker;
mod page;
mod probe;
mod raster;
#[cfg(test)]
pub(crate) mod read_svg;
mod scheme;

pub(crate) use aspect::*;
pub(crate) use axis::*;
pub(crate) use bar::*;
pub(crate) use colour_map::ColourMap;
pub(crate) use fine::{
    clip_to_rect, dash_pattern, draw_fine_line, draw_fine_path, fill_fine_points, to_backend,
};
pub(crate) use heat::*;
// lloyd2006-fig7's thin grey rings under its contours (R11-lloyd2006-fig7-1).
pub(crate) use hemisphere_key::RINGS_GREY;
pub(crate) use label::*;
pub(crate) use line::*;
pub(crate) use marker::Marker;
pub(crate) use page::*;
pub(crate) use probe::probe_area;
pub(crate) use raster::{bitmap_density, fit_to_scale};
pub(crate) use scheme::{Look, SHARED};
// The figures' parameter sweeps (α, ξ, f/n, partitions) take their colours from these.
pub(crate) use scheme::{sweep, SWEEP};
// The third z-partition map: a hue apart from the sweep's (R11-barroso-fig5-1).
pub(crate) use scheme::OCHRE;

/// The font family every figure uses; registered from the compiled-in DejaVu Sans.
pub(crate) const FONT: &str = "sans-serif";

/// Evenly spaced samples of `[a, b]`, both ends included.
pub(crate) fn linspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| a + (b - a) * i as f64 / (n - 1).max(1) as f64)
        .collect()
}
