//! Lloyd et al. 2006 Fig 7: the storage factor S̄ over the hemisphere of light directions, from
//! the crate's measurement of each scheme's own matrices ([`crate::scheme::sweep::sweep`]).

use super::chart::{
    column, decades, draw_colour_bar, draw_colour_bar_across, draw_hemisphere_ringed, fmt_power,
    fmt_times_ten, frame, Axis, ColourScale, PolarGrid, FONT, RINGS_GREY,
};
use super::{Column, Fail, Figure};
use crate::maps::WarpRule;
use crate::scheme::sweep::{sweep, Sweep, SweepGrid};
use crate::scheme::Partition;
use crate::ViewFrustum;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::f64::consts::{FRAC_PI_2, TAU};

use super::grids::{FIG7_AZIMUTHS, FIG7_ELEVATIONS};

#[path = "hemisphere_contour.rs"]
mod contour;
use contour::{contour, draw_contour_key, draw_contours, Contour};

/// The levels of (a)'s contour lines (the sixth review, R6-lloyd2006-fig7-2: under the shared
/// bar (a) was one flat green): 10⁶, S̄ straight behind (Eq 20, k = 1), and 1.5×10⁶, round its
/// peak.
pub(super) const A_CONTOURS: [f64; 2] = [1e6, 1.5e6];

/// The cells of a sweep: each sample owns the band of elevations and azimuths halfway to its
/// neighbours (the horizon and zenith rows half bands).
pub(super) fn polar_grid(s: &Sweep, values: Vec<Option<f64>>) -> PolarGrid {
    let e = s.grid.elevations();
    let a = s.grid.azimuths();
    let de = if e > 1 {
        FRAC_PI_2 / (e - 1) as f64
    } else {
        FRAC_PI_2
    };
    let elev_edges = (0..=e)
        .map(|i| (i as f64 * de - 0.5 * de).clamp(0.0, FRAC_PI_2))
        .collect();
    let da = TAU / a as f64;
    let az_edges = (0..=a).map(|j| j as f64 * da - 0.5 * da).collect();
    PolarGrid {
        elev_edges,
        az_edges,
        values,
    }
}

/// (e)'s title: what it divides, by name (the fifth review: "(e) (b) ÷ (c)" was cryptic,
/// above all in the bare form).
const E_TITLE: &str = "(e) LiSPSM ÷ faces";

/// The title of the two-column form's key disk (rings and centre labelled, no data).
const KEY_TITLE: &str = "key: elevation";

/// One panel: its title and its field.
struct Panel {
    title: String,
    grid: PolarGrid,
    max: f64,
    min: f64,
}

/// Fig 7 with four panels on one log₁₀ colour scale, as in the paper.
pub(super) struct Fig7 {
    panels: Vec<Panel>,
    /// The one colour scale of every panel: log₁₀, from the smallest to the largest S̄ of all
    /// four.
    scale: ColourScale,
    /// (e), not in the paper: LiSPSM's S̄ over face partitioning's at each direction, on its own
    /// log₁₀ scale.
    ratio: Panel,
    ratio_scale: ColourScale,
    caption: Vec<String>,
    single_caption: String,
    /// (a)'s contour lines at [`A_CONTOURS`].
    contours: Vec<Contour>,
}

/// The frustum of Fig 7 (the paper does not state it; these are its Fig 12's parameters).
pub(super) fn fig7_view() -> Result<ViewFrustum, crate::Error> {
    ViewFrustum::new(1.0, 1000.0, 30f64.to_radians())
}

pub(super) fn fig7() -> Result<Fig7, Fail> {
    let view = fig7_view()?;
    let grid = SweepGrid::new(FIG7_ELEVATIONS, FIG7_AZIMUTHS)?;
    let schemes = [
        ("(a) no warping", WarpRule::Uniform, Partition::Single),
        ("(b) LiSPSM", WarpRule::Lispsm, Partition::Single),
        ("(c) LiSPSM per face", WarpRule::Lispsm, Partition::Faces),
        ("(d) least S̄ over n′", WarpRule::Minimax, Partition::Single),
    ];
    let mut panels = Vec::new();
    for (title, rule, partition) in schemes {
        let s = sweep(&view, rule, partition, 1, grid)?;
        let values: Vec<Option<f64>> = s
            .storage_factor
            .iter()
            .map(|&v| (v.is_finite() && v > 0.0).then_some(v))
            .collect();
        let (min, max) = extent(values.iter().flatten().copied()).ok_or_else(|| {
            Fail::Data(crate::Error::Degenerate(format!(
                "the sweep of {title} has no finite storage factor"
            )))
        })?;
        panels.push(Panel {
            title: title.to_string(),
            grid: polar_grid(&s, values),
            max,
            min,
        });
    }
    // (e): how many times more texels LiSPSM needs than face partitioning, direction by direction.
    let contours = A_CONTOURS
        .iter()
        .map(|&level| contour(&panels[0].grid.values, grid, level))
        .collect();
    let ratios: Vec<Option<f64>> = panels[1]
        .grid
        .values
        .iter()
        .zip(&panels[2].grid.values)
        .map(|(b, c)| Some(b.as_ref()? / c.as_ref()?))
        .collect();
    let (rmin, rmax) = extent(ratios.iter().flatten().copied()).ok_or_else(|| {
        Fail::Data(crate::Error::Degenerate(
            "LiSPSM over face partitioning has no finite value".into(),
        ))
    })?;
    let ratio = Panel {
        title: E_TITLE.into(),
        grid: PolarGrid {
            values: ratios,
            ..panels[1].grid.clone()
        },
        max: rmax,
        min: rmin,
    };
    // (e)'s own scale: diverging, neutral grey where LiSPSM and face partitioning need the
    // same, red where LiSPSM needs more; over the whole decades round its values.
    let (r0, r1) = decades(rmin, rmax);
    let ratio_scale = ColourScale::diverging(Axis::log10("(e) (b) ÷ (c) (log scale)", r0, r1), 1.0);
    let lo = panels.iter().map(|p| p.min).fold(f64::INFINITY, f64::min);
    let hi = panels.iter().map(|p| p.max).fold(0.0, f64::max);
    let (lo, hi) = decades(lo, hi);
    let scale = ColourScale::smooth(Axis::log10(FIG7_S_BAR, lo, hi));
    // (a)'s brightest cells (fifth review, §4.7.5): the unwarped map's rectangle has a side
    // along the projected view direction; its largest S̄ (minimum-area rectangles peak at
    // 1.224·10⁶ over the same grid: docs/figures.md, `min_area`'s tests; the caption's five
    // lines went to (c)–(e), the ninth review, R9-lloyd2006-fig7-1).
    // (a)'s peak and the rule that sets it, in words, as the worst-case figure words it (the
    // seventh review, R7-2006f7-1: "the orientation rule's (the worst-case figure)" named no
    // rule): the unwarped map keeps a side along the view direction projected into the light's
    // view, which just off behind and in front (elevation and azimuth 1°) runs along the
    // diagonal of the frustum's square outline, so that the map stands at 45° to it and
    // doubles.
    // Both of (a)'s contours run along the behind–front diameter, where S̄ dips to 8.7·10⁵ in
    // a valley a few degrees wide, and there they meet in one black line (the eighth review,
    // R8-lloyd2006-fig7-3): the caption says so.
    let band = format!(
        "(a) peaks at {} just off behind, with its map turned 45° to the frustum; its contours \
         {} and {} run along the behind–front line.",
        fmt_times_ten(panels[0].max),
        fmt_power(A_CONTOURS[0]),
        fmt_power(A_CONTOURS[1]),
    );
    // Near behind LiSPSM needs more than no warping (the sixth review, R6-lloyd2006-fig7-6):
    // the n′ rule used does not revert to an orthogonal map for γ < θ, as Lloyd 2006 §4.4
    // says warping does there. Its largest factor over the grid, printed in the caption.
    let worse = lispsm_over_unwarped(&panels[1].grid, &panels[0].grid);
    let (n, f) = (view.near(), view.far());
    let caption = vec![format!(
        "Lloyd et al. 2006, Fig. 7: S̄ (texels per image pixel), azimuthal \
         equidistant (top: viewer's left); n\u{a0}=\u{a0}{n}, f\u{a0}=\u{a0}{f}, \
         θ\u{a0}=\u{a0}{theta:.0}°. (c) LiSPSM per face (§5.1), S̄ summed; \
         (e)\u{a0}=\u{a0}(b)\u{a0}÷\u{a0}(c); (d), (e) not in the paper. {band} Near behind (b) \
         is up to {worse:.1}× (a): n′ does not revert (§4.4).",
        theta = view.half_fov().to_degrees(),
    )];
    // One column: four lines, so that the disks keep the size at which (a)'s ring key covers
    // at most a sixth of its disk ((a)'s peak is left to the two columns' caption); it says
    // which panels the paper does not have, as two columns do (the sixteenth review,
    // R16-lloyd2006-fig7-1).
    let single_caption = format!(
        "Lloyd et al. 2006, Fig. 7: S̄, azimuthal equidistant (top: viewer's left); \
         f/n\u{a0}=\u{a0}{ratio}, θ\u{a0}=\u{a0}{theta:.0}°; (c) face partitioning; (d), \
         (e) not in the paper; near behind (b) up to {worse:.1}× (a).",
        ratio = f / n,
        theta = view.half_fov().to_degrees(),
    );
    Ok(Fig7 {
        panels,
        scale,
        ratio,
        ratio_scale,
        caption,
        single_caption,
        contours,
    })
}

/// The largest factor by which LiSPSM's S̄ exceeds the unwarped map's, over the cells both have.
fn lispsm_over_unwarped(lispsm: &PolarGrid, unwarped: &PolarGrid) -> f64 {
    lispsm
        .values
        .iter()
        .zip(&unwarped.values)
        .filter_map(|(b, a)| Some(b.as_ref()? / a.as_ref()?))
        .fold(0.0, f64::max)
}

impl Fig7 {
    /// The caption, one paragraph.
    #[cfg(test)]
    pub(super) fn caption_text(&self) -> String {
        self.caption.join(" ")
    }

    /// The largest S̄ of panel `k` ((a) 0 … (d) 3).
    #[cfg(test)]
    pub(super) fn panel_max(&self, k: usize) -> f64 {
        self.panels[k].max
    }
}

impl Figure for Fig7 {
    fn size(&self) -> (u32, u32) {
        (520, 540)
    }

    /// One column: three rows of two hemispheres, the bars in the sixth cell.
    fn single_size(&self) -> Option<(u32, u32)> {
        Some((Column::Single.width(), 520))
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let single = column() == Column::Single;
        // One column sets a title that keeps one line.
        let body = frame_by_column(
            root,
            [
                "Storage factor over the hemisphere of light directions",
                "Storage factor over light directions",
            ],
            &self.caption,
            &self.single_caption,
        )?;
        let (w, h) = body.dim_in_pixel();
        let (a, b, c, d) = (
            &self.panels[0],
            &self.panels[1],
            &self.panels[2],
            &self.panels[3],
        );
        let (e, s) = (&self.ratio, &self.scale);
        // Cells of one size, so that every disk is as large as the others; (a) carries the
        // key (the rings' elevations, overhead). Two columns: cells as wide as a disk needs
        // (its square, under a 28-unit title, and 8 units) and leave room for a bar right of
        // the first row.
        let (cols, rows) = if single { (2, 3) } else { (3, 2) };
        let row_gap = if single { 2 * ROW_GAP } else { ROW_GAP };
        let ch = h / rows;
        let cw = if single {
            w / 2
        } else {
            (ch.saturating_sub(row_gap + 28) + 8).min(w.saturating_sub(BAR_WIDTH) / 3)
        };
        let cell = |k: u32| {
            body.clone().shrink(
                ((k % cols) * cw, (k / cols) * ch),
                (cw, ch.saturating_sub(row_gap)),
            )
        };
        let order = [(a, s), (b, s), (c, s), (d, s), (e, &self.ratio_scale)];
        let mut disk_rows = Vec::new();
        for (k, (p, scale)) in order.iter().enumerate() {
            // One column keys (a): its sixth cell holds both bars. Two columns key an empty
            // disk in the sixth cell instead (the fifth review: the key's boxes covered (a)'s
            // data, and the sixth cell was empty).
            let keyed = single && k == 0;
            // Every disk's rings thin and grey, (a)'s under its contours (R11-lloyd2006-fig7-1),
            // the others' alike: one ring style in the figure.
            let r = draw_hemisphere_ringed(
                &cell(k as u32),
                &p.title,
                &p.grid,
                scale,
                keyed,
                false,
                RINGS_GREY,
            )?;
            // (a)'s contours in two columns (and bare); one column's disks, about 38 units across
            // the radius, hold the ring key in (a), and there the contours' labels ran into it.
            if k == 0 && !single {
                draw_contours(&cell(0), &self.contours)?;
            }
            disk_rows.push(r);
        }
        if single {
            // The sixth cell, right of (e): the bar of (a)–(d) over (e)'s, in the panels'
            // order, both across, each named under its ticks.
            let last = body.clone().shrink((cw, 2 * ch), (w - cw, ch));
            let (_, lh) = last.dim_in_pixel();
            let half = (lh.saturating_sub(ROW_GAP)) / 2;
            let (top, bottom) = last.split_vertically(half);
            // The across bar's name under it has no room for S̄'s unit: the unit over the bar,
            // as a bar's title (the eighteenth review, R18-lloyd2006-fig7-1).
            let mut across = s.clone();
            across.axis.label = FIG7_S_BAR_ACROSS.into();
            draw_colour_bar_across(&top.margin(ROW_GAP, 0, 4, 4), &across)?;
            let (tw, _) = top.dim_in_pixel();
            top.draw(&Text::new(
                S_UNIT,
                ((tw / 2) as i32, ROW_GAP as i32 - 2),
                TextStyle::from((FONT, 13).into_font()).pos(Pos::new(HPos::Center, VPos::Bottom)),
            ))?;
            draw_colour_bar_across(&bottom.margin(ROW_GAP, 0, 4, 4), &self.ratio_scale)?;
        } else {
            // Upright, as tall as the disks: S̄'s right of (c), ending the row of (a)–(c)
            // with (d) under (a); (e)'s right of (e).
            let bar = body.clone().shrink((3 * cw, 0), (w - 3 * cw, ch));
            draw_bar(&bar, s, disk_rows[2])?;
            let ratio_bar = body.clone().shrink((2 * cw, ch), (BAR_WIDTH, ch));
            draw_bar(&ratio_bar, &self.ratio_scale, disk_rows[4])?;
            // The key: a disk with no data, right of (e)'s bar, over the key of (a)'s contour
            // lines ([`CONTOUR_KEY`] units: the seventh review, R7-2006f7-1).
            let x = 2 * cw + BAR_WIDTH;
            let key_h = ch.saturating_sub(row_gap + CONTOUR_KEY);
            let key = body.clone().shrink((x, ch), (cw.min(w - x), key_h));
            let lines = body.clone().shrink(
                (x + CONTOUR_KEY_INDENT, ch + key_h),
                (
                    cw.min(w - x).saturating_sub(CONTOUR_KEY_INDENT),
                    CONTOUR_KEY,
                ),
            );
            draw_contour_key(&lines, &self.contours)?;
            let empty = PolarGrid {
                elev_edges: vec![0.0, FRAC_PI_2],
                az_edges: vec![0.0, TAU],
                values: vec![None],
            };
            draw_hemisphere_ringed(&key, KEY_TITLE, &empty, s, true, false, RINGS_GREY)?;
        }
        Ok(())
    }
}

/// The body of a figure framed by its title and caption in the page's column: two columns set
/// `titles[0]` and `caption`, one column the shorter `titles[1]` (one line) and
/// `single_caption`.
pub(super) fn frame_by_column<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    titles: [&str; 2],
    caption: &[String],
    single_caption: &str,
) -> Result<DrawingArea<DB, Shift>, Fail> {
    if column() == Column::Single {
        frame(root, titles[1], &[single_caption])
    } else {
        let lines: Vec<&str> = caption.iter().map(String::as_str).collect();
        frame(root, titles[0], &lines)
    }
}

/// Draws `fig` into an SVG in `column`'s layout, captioned, and returns the SVG's text.
#[cfg(test)]
pub(super) fn svg_in<F: Figure>(fig: &F, column: Column) -> String {
    use super::chart::read_svg::draw_svg;
    use super::chart::with_page;
    let size = match column {
        Column::Double => fig.size(),
        Column::Single => fig.single_size().expect("a one-column layout"),
    };
    with_page(false, column, || {
        draw_svg(size, |area| fig.draw(area).expect("the figure draws"))
    })
}

/// The space under each row of hemispheres, in units (twice that in one column, where the
/// disks are smaller and "viewer's right" reaches lower under its square): a disk's "viewer's
/// right" and the next row's titles stand apart.
const ROW_GAP: u32 = 8;

/// S̄'s unit (res_t = 1: Lloyd 2006 §4.2).
const S_UNIT: &str = "texels per image pixel";

/// The name of the upright bar of (a)–(d) (two columns and bare), with S̄'s unit as the other
/// figures' S̄ axes give it (the eighteenth review, R18-lloyd2006-fig7-1: "(a)–(d) S̄ (log
/// scale)" gave none); longer than the bar, it runs into the bar's chart's ends, where nothing
/// else is. Its powers of ten say the scale.
const FIG7_S_BAR: &str = "(a)–(d) S̄ (texels per image pixel)";

/// The name under one column's bar of (a)–(d), across a cell too narrow for the unit, which
/// stands over the bar ([`S_UNIT`]).
const FIG7_S_BAR_ACROSS: &str = "(a)–(d) S̄ (log scale)";

/// Two columns: the height under the key disk for the key of (a)'s contour lines (two rows of
/// [`draw_contour_key`]), and its indent from the key cell's left.
const CONTOUR_KEY: u32 = 37;
const CONTOUR_KEY_INDENT: u32 = 10;

/// The width of a colour bar's column: the bar, its tick labels and its name.
pub(super) const BAR_WIDTH: u32 = 84;

/// A colour bar in `area` as tall as the disks whose top and bottom rows (in `area`) are
/// `rows` (the bar's chart keeps 30 units at each end for its end labels).
pub(super) fn draw_bar<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    scale: &ColourScale,
    (top, bottom): (u32, u32),
) -> Result<(), Fail> {
    let (_, h) = area.dim_in_pixel();
    let bar = area.margin(top.saturating_sub(30), h.saturating_sub(bottom + 30), 0, 0);
    draw_colour_bar(&bar, scale)
}

/// The minimum and maximum of positive finite values.
fn extent(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    values
        .filter(|v| v.is_finite() && *v > 0.0)
        .fold(None, |acc, v| match acc {
            None => Some((v, v)),
            Some((lo, hi)) => Some((f64::min(lo, v), f64::max(hi, v))),
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashSet;

    /// The plotted sweeps hit the paper's closed forms where the paper has them: LiSPSM overhead
    /// is Lloyd 2006 Eq 12, (f/n − 1)/(2 tan θ) = 999/(2 tan 30°) = 865.159; the unwarped map
    /// behind is Eq 20 with k = 1, (f/n)² = 10⁶; face partitions behind are Eq 21 at 45°,
    /// 4 · 999/2 + 1 = 1999.
    #[test]
    fn fig7_panels_match_the_closed_forms_at_the_analysed_directions() {
        let fig = fig7().map_err(|e| e.named("lloyd2006-fig7")).unwrap();
        let (e, a) = (FIG7_ELEVATIONS, FIG7_AZIMUTHS);
        let at =
            |panel: usize, i: usize, j: usize| fig.panels[panel].grid.values[i * a + j].unwrap();
        let overhead = 999.0 / (2.0 * 30f64.to_radians().tan());
        for j in [0, 17, 90, 179] {
            let v = at(1, e - 1, j);
            assert!((v - overhead).abs() < 1e-9 * overhead, "{v}");
        }
        let behind = at(0, 0, 0);
        assert!((behind - 1e6).abs() < 1e-6, "{behind}");
        let front = at(0, 0, a / 2);
        assert!((front - 1e6).abs() < 1e-6, "{front}");
        let faces = at(2, 0, 0);
        assert!((faces - 1999.0).abs() < 1e-6, "{faces}");
        // The cells tile the hemisphere: elevations from the horizon to the zenith, azimuths a
        // full turn.
        let g = &fig.panels[0].grid;
        assert_eq!(g.elev_edges.first(), Some(&0.0));
        assert_eq!(g.elev_edges.last(), Some(&FRAC_PI_2));
        let turn = g.az_edges[a] - g.az_edges[0];
        assert!((turn - TAU).abs() < 1e-12);
        // One colour scale for all four panels (issue 25): its range is the smallest and the
        // largest S̄ of any panel, found here from the sweeps' values; the extremes fall in the
        // first and last band. The smallest is LiSPSM overhead (Eq 12, 865), the largest the
        // 1/sin γ rule near the horizon (errata item 11: 4.7·10⁶).
        let vals: Vec<f64> = fig
            .panels
            .iter()
            .flat_map(|p| p.grid.values.iter().flatten().copied())
            .collect();
        let lo = vals.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = vals.iter().copied().fold(0.0, f64::max);
        // The bar spans the whole decades round them (X3: its ends are round powers of ten,
        // not the computed 8.65×10² and 4.74×10⁶): log₁₀ 865 = 2.94 → 10², log₁₀ 4.7·10⁶ =
        // 6.68 → 10⁷.
        let (a, b) = fig.scale.axis.range();
        assert!(
            (a - 2.0).abs() < 1e-12 && (b - 7.0).abs() < 1e-12,
            "{a} {b}"
        );
        assert!((lo - overhead).abs() < 1e-9 * overhead, "{lo}");
        assert!((4.6e6..4.8e6).contains(&hi), "{hi}");
        // Face partitioning (865 … 1999) spans far fewer bands than LiSPSM: the paper's point.
        let bands = |k: usize| -> HashSet<usize> {
            fig.panels[k]
                .grid
                .values
                .iter()
                .flatten()
                .filter_map(|&v| fig.scale.level(v))
                .collect()
        };
        // (e) is (b) ÷ (c) at every direction: behind, LiSPSM falls back to the orthographic
        // map, (f/n)² = 10⁶ (Eq 20, k = 1), and face partitioning is Eq 21's 1999, so 500.25;
        // overhead both are Eq 12's 865.159, so 1.
        let r = &fig.ratio.grid.values;
        assert!((r[0].unwrap() - 1e6 / 1999.0).abs() < 1e-6, "{:?}", r[0]);
        let top = r[(FIG7_ELEVATIONS - 1) * FIG7_AZIMUTHS].unwrap();
        assert!((top - 1.0).abs() < 1e-9, "{top}");
        assert_eq!(r.len(), fig.panels[1].grid.values.len());
        assert!(fig.ratio.min > 0.9 && fig.ratio.max > 2000.0);
        // (e)'s scale is its own, diverging and neutral at 1 (the review: on viridis it read
        // as S̄): 0.907 … 2430 within 10⁻¹ … 10⁴, the centre log₁₀ 1 = 0; a ratio of 1 takes
        // ColorBrewer's neutral #f7f7f7 (to within the band's width), 10⁻¹ its blue end and 10⁴
        // its red end.
        let (r0, r1) = fig.ratio_scale.axis.range();
        assert!(
            (r0 + 1.0).abs() < 1e-9 && (r1 - 4.0).abs() < 1e-9,
            "{r0} {r1}"
        );
        assert_eq!(
            fig.ratio_scale.map,
            super::super::chart::ColourMap::Diverging { centre: 0.0 }
        );
        let colour = |v: f64| {
            fig.ratio_scale
                .level_colour(fig.ratio_scale.level(v).unwrap())
        };
        // The neutral grey #c6c6c6 at a ratio of 1 (grey: its channels within 4 of each other
        // and of 0xc6, to within the band's width), bluish at 10⁻¹ and dark red at 10⁴.
        let RGBColor(r, g, b) = colour(1.0);
        assert!(
            [r, g, b].iter().all(|c| c.abs_diff(0xc6) <= 4),
            "{r:x} {g:x} {b:x}"
        );
        let (RGBColor(r0, _, b0), RGBColor(r1, _, b1)) = (colour(0.1), colour(1e4));
        assert!(b0 > r0 + 20 && r1 > b1 + 40, "{r0} {b0} {r1} {b1}");
        assert_eq!(fig.scale.map, super::super::chart::ColourMap::Viridis);
        assert!(
            bands(2).len() * 3 < bands(1).len(),
            "{} vs {}",
            bands(2).len(),
            bands(1).len()
        );
    }

    /// The rings' grey (R11-lloyd2006-fig7-1: thin grey rings under (a)'s contours; the first
    /// review: rings must show on the dark colours) against the darkest and the lightest
    /// colour of every panel (the colours of its least and largest value, on its own scale),
    /// by WCAG's contrast ratio computed here: at least 1.9 : 1 on each, and at least 3 : 1 on
    /// the white of the key disk, as every line on white. No one grey does better than 1.98 : 1
    /// on both (a)'s darkest green (8.65×10⁵, relative luminance 0.49) and (c)'s lightest blue
    /// (1999, 0.09): #808080 has 2.0 and 1.93 : 1 there. The old near-black rings had 1.77 : 1
    /// on (b)'s darkest navy.
    #[test]
    fn fig7_rings_show_on_every_panels_darkest_and_lightest_colour() {
        use super::super::chart::RINGS_GREY;
        let fig = fig7().map_err(|e| e.named("lloyd2006-fig7")).unwrap();
        let lum = |RGBColor(r, g, b): RGBColor| {
            let lin = |u: u8| {
                let v = f64::from(u) / 255.0;
                if v <= 0.04045 {
                    v / 12.92
                } else {
                    ((v + 0.055) / 1.055).powf(2.4)
                }
            };
            0.2126 * lin(r) + 0.7152 * lin(g) + 0.0722 * lin(b)
        };
        let (r, g, b) = RINGS_GREY.rgb;
        let ring = lum(RGBColor(r, g, b));
        let contrast = |l: f64| (ring.max(l) + 0.05) / (ring.min(l) + 0.05);
        assert!(contrast(1.0) >= 3.0, "{} on white", contrast(1.0));
        let panels = fig.panels.iter().map(|p| (p, &fig.scale));
        for (p, scale) in panels.chain([(&fig.ratio, &fig.ratio_scale)]) {
            for v in [p.min, p.max] {
                let colour = scale.level_colour(scale.level(v).unwrap());
                let c = contrast(lum(colour));
                assert!(c >= 1.9, "{}: {v} in {colour:?}, {c:.2} : 1", p.title);
            }
        }
    }

    /// The figure as drawn, in both layouts (review X3, X5, X8 and its Fig 7 items), read back
    /// from its SVG: every colour-bar label is a whole power of ten (a label of the form
    /// 10<sup>n</sup>, none with a mantissa such as 9.07×10⁻¹ or 2.43×10³); both bars' names are
    /// turned 270° (anticlockwise, as a y axis's name) in two columns; the key of the rings
    /// (10°, 20°, 30°, 60°, "overhead") is written once, in (a); and the caption names (e).
    #[test]
    fn fig7_bars_are_round_decades_and_the_rings_are_keyed() {
        use super::super::chart::fmt_power;
        use super::super::chart::read_svg::texts;
        let fig = fig7().map_err(|e| e.named("lloyd2006-fig7")).unwrap();
        for column in [Column::Double, Column::Single] {
            let svg = svg_in(&fig, column);
            let all = texts(&svg);
            let powers: Vec<&str> = all
                .iter()
                .filter(|t| t.0.contains(">10<tspan dy=\"-"))
                .map(|t| t.0)
                .collect();
            assert!(powers.len() >= 6, "{column:?}: {powers:?}");
            assert!(
                // Not the caption's lines (#323232), which print (a)'s peak as m×10ⁿ, nor
                // (a)'s contour label 1.5×10⁶ and its key "(a) S̄ = 1.5×10⁶".
                !all.iter().any(|t| t.1.contains("×10")
                    && !t.0.contains("#323232")
                    && !t.1.starts_with("(a) S")
                    && !t
                        .1
                        .starts_with(fmt_power(A_CONTOURS[1]).trim_end_matches('⁶'))),
                "{column:?}: a mantissa on a bar"
            );
            for key in ["10°", "20°", "30°", "60°", "90°"] {
                let n = all.iter().filter(|t| t.1 == key).count();
                assert_eq!(n, 1, "{column:?}: {key} written {n} times");
            }
            if column == Column::Double {
                // S̄'s bar is written S with an overlined tspan.
                for name in [
                    "(a)–(d) S (texels per image pixel)",
                    "(e) (b) ÷ (c) (log scale)",
                ] {
                    let line = all.iter().find(|t| t.1 == name).unwrap().0;
                    assert!(line.contains("rotate(270"), "{line}");
                }
            }
        }
    }

    /// The fifth review's items on lloyd2006-fig7, read from the drawn SVG in both forms: (e)'s
    /// title names what it divides ("LiSPSM ÷ faces", not "(b) ÷ (c)"); the captions name the
    /// azimuthal equidistant projection; in two columns the ring key is written in a disk of
    /// its own (every ring label nearer the key's title than any data panel's title), not over
    /// (a)'s data; and the caption gives (a)'s brightest value (twice S̄ behind, 10⁶, Eq 20) and
    /// the rule that sets it in words. The ninth review (R9-lloyd2006-fig7-1, -2): the panels
    /// not in the paper are defined, (c) in both captions and (e) in the two-column one, and
    /// (d) is titled by what its colour shows, S̄.
    #[test]
    fn fig7_names_e_and_the_projection_and_keys_the_rings_apart_from_the_data() {
        use super::super::chart::fmt_times_ten;
        use super::super::chart::read_svg::{attr, texts};
        let fig = fig7().map_err(|e| e.named("lloyd2006-fig7")).unwrap();
        for column in [Column::Double, Column::Single] {
            let svg = svg_in(&fig, column);
            let all = texts(&svg);
            assert!(
                all.iter().any(|t| t.1 == "(e) LiSPSM ÷ faces"),
                "{column:?}: no (e) title"
            );
            assert!(!all.iter().any(|t| t.1 == "(e) (b) ÷ (c)"), "{column:?}");
            let caption = if column == Column::Double {
                fig.caption_text()
            } else {
                fig.single_caption.clone()
            };
            assert!(
                caption.contains("azimuthal equidistant"),
                "{column:?}: {caption}"
            );
            if column == Column::Double {
                let at = |t: &(&str, String, f64)| (attr(t.0, "x").unwrap(), t.2);
                let titles: Vec<(f64, f64)> = all
                    .iter()
                    // Not the caption's lines (#323232): one starts "(b), (c) overhead".
                    .filter(|t| {
                        t.1.starts_with('(')
                            && t.1.len() > 4
                            && !t.1.contains("log")
                            && !t.1.contains("texels")
                            && !t.1.contains(" = ")
                            && !t.0.contains("#323232")
                    })
                    .map(at)
                    .collect();
                assert_eq!(titles.len(), 5, "{titles:?}");
                let key = all.iter().find(|t| t.1 == KEY_TITLE).map(at).unwrap();
                let d = |p: (f64, f64), q: (f64, f64)| (p.0 - q.0).hypot(p.1 - q.1);
                for label in ["10°", "20°", "30°", "60°", "90°"] {
                    let p = all.iter().find(|t| t.1 == label).map(at).unwrap();
                    for &t in &titles {
                        assert!(d(p, key) < d(p, t), "{label} at {p:?}: nearer {t:?}");
                    }
                }
            }
        }
        // (a)'s brightest cell is twice S̄ behind, (f/n)² = 10⁶: the orientation rule.
        let peak = fig.panel_max(0);
        assert!((1.99e6..2.0e6).contains(&peak), "{peak}");
        let text = fig.caption_text();
        // The rule itself, in words, not a reference to the worst-case figure (the seventh
        // review, R7-2006f7-1: "the orientation rule's (the worst-case figure)"), and the two
        // contours' meeting along the behind–front line (the eighth, R8-lloyd2006-fig7-3).
        let want = format!(
            "(a) peaks at {} just off behind, with its map turned 45° to the frustum; its \
             contours 10⁶ and 1.5×10⁶ run along the behind–front line.",
            fmt_times_ten(peak),
        );
        assert!(text.contains(&want), "{want:?} in {text}");
        assert!(!text.contains("orientation rule"), "{text}");
        // The panels the paper does not have, defined (R9-lloyd2006-fig7-1).
        for clause in [
            "(c) LiSPSM per face (§5.1), S̄ summed",
            "(e)\u{a0}=\u{a0}(b)\u{a0}÷\u{a0}(c); (d), (e) not in the paper",
        ] {
            assert!(text.contains(clause), "{clause:?} in {text}");
        }
        assert!(
            fig.single_caption.contains("(c) face partitioning"),
            "{}",
            fig.single_caption
        );
        // (d)'s title names the quantity its colour shows and how it is chosen
        // (R9-lloyd2006-fig7-2: "n′ of least S̄" read as a map of n′; R11-lloyd2006-fig7-2: "S̄
        // at the best n′" left "best" undefined).
        for column in [Column::Double, Column::Single] {
            let svg = svg_in(&fig, column);
            let all = texts(&svg);
            assert!(
                all.iter()
                    .any(|t| t.1.starts_with("(d) least ") && t.1.ends_with(" over n′")),
                "{column:?}: no (d) title"
            );
        }
        // No γ, which no figure of Lloyd 2006 defines (R8-lloyd2006-fig7-1): the captions say
        // where n′ should revert in words ("near behind").
        for caption in [&text, &fig.single_caption] {
            assert!(!caption.contains("lloyd2006-"), "{caption}");
            assert!(!caption.contains('γ'), "{caption}");
            assert!(caption.contains("ear behind (b)"), "{caption}");
            assert!(caption.contains("up to 4.3× (a)"), "{caption}");
        }
    }
}
