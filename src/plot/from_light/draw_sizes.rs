//! The sizes of the diagrams seen from the light in each layout, and their axes' labelled
//! ticks (moved out of draw.rs, which stays under 800 lines).

use super::super::super::chart::{ChartStyle, PANEL_TITLE};
use glam::DVec2;

/// Sizes of one layout: label and key text, the gutter's width, the least distance between two
/// labels in the gutter, the gap kept right of the gutter's text (before the next panel).
#[derive(Clone, Copy)]
pub(super) struct Sizes {
    pub(super) style: ChartStyle,
    /// The label areas of a panel without the axis's title (its ticks only): the x title is
    /// written under the bottom row only, the y title left of the left column only.
    pub(super) x_ticks_only: u32,
    pub(super) y_ticks_only: u32,
    pub(super) label: u32,
    pub(super) gutter: u32,
    pub(super) step: i32,
    pub(super) key: u32,
    /// Whether the planes are labelled in the gutter (one column's overviews: not, figure
    /// review 6: their gutter left the plots 40 units wide; the caption gives the depths).
    pub(super) labels: bool,
}

/// The gutter of one column's overview panels: no labels, a gap before the detail's y ticks.
pub(super) const OVERVIEW_GUTTER: u32 = 10;

/// The least width of one column's overview cell: its title, "(a) light ⊥ view" (94 units at
/// the titles' 12.1; "(a) perpendicular", 105, set it), and a gap to the detail's title.
pub(super) const OVERVIEW_LEAST: u32 = 124;

pub(super) fn sizes(single: bool, panels: usize) -> Sizes {
    if single && panels > 1 {
        // One column, two panels a row of 144 units: the type of every other one-column figure
        // (ticks and labels 13, 10.5 units, 8.4 pt printed; titles and axis names 15), y ticks
        // on every panel and each plane's label on one line (figure review 4: without y ticks
        // and with "f =" over "100" the panels graded C): a label is set close, "z=31.62"
        // (figure review 5: the depth alone read as a tick value), in a gutter of 58 units.
        Sizes {
            style: ChartStyle {
                title_size: PANEL_TITLE,
                x_label_area: 42,
                y_label_area: 46,
                tick_size: 13,
                desc_size: 15,
                margin: 2,
            },
            x_ticks_only: 26,
            y_ticks_only: 30,
            label: 13,
            gutter: 66,
            step: 15,
            key: 13,
            labels: true,
        }
    } else {
        Sizes {
            style: ChartStyle {
                y_label_area: 46,
                ..ChartStyle::default()
            },
            x_ticks_only: 26,
            y_ticks_only: 34,
            label: 13,
            gutter: 78,
            step: 16,
            key: 13,
            labels: true,
        }
    }
}

/// The labelled ticks of an axis over `lo`–`hi`, `room` long, with `tick`-size labels each
/// needing `need(label)` of it: the multiples of the least step of 1, 2 or 5 × 10ⁿ whose labels
/// fit, or where there are three, the two ends (−50 and 50 where −50, 0, 50 would touch); at
/// least two.
pub(super) fn ticks_fitting(lo: f64, hi: f64, room: f64, need: impl Fn(f64) -> f64) -> Vec<f64> {
    let span = hi - lo;
    let fits = |v: &[f64]| {
        v.len() >= 2
            && v.windows(2)
                .all(|w| w[1] - w[0] >= (need(w[0]) + need(w[1])) * 0.5 * span / room)
    };
    // The coarsest choice with two labels, should none fit.
    let mut fallback = Vec::new();
    let mut base = 10f64.powf((span / 20.0).log10().floor());
    while base <= 10.0 * span {
        for m in [1.0, 2.0, 5.0] {
            let s = m * base;
            let all: Vec<f64> = ((lo / s).ceil() as i64..=(hi / s).floor() as i64)
                .map(|k| k as f64 * s)
                .collect();
            let ends: Vec<f64> = all.iter().copied().step_by(2).collect();
            for v in [all.clone(), ends] {
                if fits(&v) && (v.len() == all.len() || all.len() == 3) {
                    return v;
                }
                if v.len() >= 2 {
                    fallback = v;
                }
            }
        }
        base *= 10.0;
    }
    fallback
}

/// The labelled ticks of a panel showing `lo`–`hi` in a `w` × `h` plot with `tick`-size
/// labels: across, each label as wide as its digits and sign plus a gap; up, 1.8 text heights
/// apart.
pub(super) fn tick_labels(lo: DVec2, hi: DVec2, w: f64, h: f64, tick: f64) -> (Vec<f64>, Vec<f64>) {
    // A label's advance: DejaVu's digits 0.636 em and minus sign 0.838 em, its em the size
    // ÷ 1.24 in the SVG and 7 % larger in the PNG (0.859 of the size), and a gap of 0.3 of the
    // size (the eleventh review, R11-barroso-fig5-2: measured as 1.24 times wider, −10, 0, 10
    // did not fit (b)'s 74 units and (b) showed −10 and 10 without 0).
    let wide = |v: f64| {
        let digits = format!("{}", v.abs()).len() as f64;
        (digits * 0.636 + if v < 0.0 { 0.838 } else { 0.0 }) * 0.859 * tick + 0.3 * tick
    };
    (
        ticks_fitting(lo.x, hi.x, w, wide),
        ticks_fitting(lo.y, hi.y, h, |_| 1.8 * tick),
    )
}
