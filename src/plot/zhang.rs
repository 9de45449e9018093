//! Zhang, Zhao & Sun 2009 Fig 3: side views of the perspective aliasing E_p, E_q and E_p×E_q
//! inside the view frustum for SSM, LiSPSM and TSM at light angles θ = 90°, 60°, 30°.
//!
//! Every value is measured: the renderer-facing matrix of each scheme is built by
//! [`crate::maps::warp`] for a light above and in front of the viewer (Zhang's Fig 2), and
//! [`crate::measure::point_error`] gives m_x and m_z at each point of the frustum's vertical
//! plane x = 0, so that E_q = 2 m_x and E_p = 2 m_z (Zhang's screen in [−1, 1], texture in
//! [0, 1]; unit resolutions).

use super::chart::{
    build_chart_styled, column, draw_bar_bands, fmt_plain, frame, Axis, ChartStyle, ColourScale,
    Grid, Ticked, COLOUR_BAR_TICK, FONT, PANEL_TITLE, TICK,
};
use super::{Column, Fail, Figure};
use crate::maps::{warp, WarpRule};
use crate::measure::{point_error, ShadowMap};
use crate::{NPrime, Resolutions, ViewFrustum};
use glam::DVec3;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::f64::consts::FRAC_PI_6;

/// TSM's focus distance δ beyond the near plane (the 80 % rule maps the point n + δ on the view
/// axis to the 80 % line). Zhang does not state his; this one gives λ_TSM < λ_LiSPSM at
/// θ = 90° and 60°, as his §3.1 says of his.
pub(super) const TSM_FOCUS: f64 = 10.0;

/// Grid cells along the depth axis (from the near to the far plane) and across it.
const NZ: usize = 99;
const NY: usize = 60;

/// One side view.
struct Panel {
    grid: Grid,
}

/// The 3 × 9 panels, their labels and a colour scale per quantity.
pub(super) struct Fig3 {
    /// rows[θ][scheme][quantity]
    rows: Vec<Vec<Vec<Panel>>>,
    /// "θ = 90°" per row.
    row_angles: Vec<String>,
    scheme_labels: Vec<String>,
    /// One scale per quantity (E_p, E_q, E_p × E_q), over its range in all nine panels.
    scales: Vec<ColourScale>,
    /// The caption across two columns, and the shorter one of a single column.
    caption: String,
    single_caption: String,
    far: f64,
    tan_phi: f64,
}

const QUANTITIES: [&str; 3] = ["E_p", "E_q", "E_p × E_q"];

pub(super) fn fig3() -> Result<Fig3, Fail> {
    let view = ViewFrustum::new(1.0, 100.0, FRAC_PI_6)?;
    let (n, f) = (view.near(), view.far());
    let tan_phi = view.tan_half_fov();
    let res = Resolutions::default();
    let rules = [
        ("SSM", WarpRule::Uniform),
        ("LiSPSM", WarpRule::Lispsm),
        ("TSM", WarpRule::Tsm { focus: TSM_FOCUS }),
    ];
    let mut rows = Vec::new();
    let mut row_angles = Vec::new();
    let mut lambdas_all = Vec::new();
    let mut scheme_labels: Vec<String> = Vec::new();
    let mut ranges = [(f64::INFINITY, 0.0f64); 3];
    for (r, theta_deg) in [90.0f64, 60.0, 30.0].into_iter().enumerate() {
        let theta = theta_deg.to_radians();
        // Source above and in front of the viewer: light travels along (0, −sin θ, cos θ).
        // (TiltSide::InFront of measure::tilted_twin).
        let light = DVec3::new(0.0, -theta.sin(), theta.cos());
        let mut row = Vec::new();
        let mut lambdas = Vec::new();
        for (name, rule) in rules {
            let m = warp(&view, light, rule)?;
            let shadow: ShadowMap = m.shadow_map();
            lambdas.push(fmt_lambda(m.n_prime()));
            if r == 0 {
                scheme_labels.push(name.to_string());
            }
            let mut fields = [Vec::new(), Vec::new(), Vec::new()];
            let grid = frustum_grid(n, f, tan_phi);
            let nx = grid.x_edges.len() - 1;
            for k in 0..grid.values.len() {
                let e = match grid.sample_point(k % nx, k / nx) {
                    None => None,
                    Some((z, y)) => {
                        let e = point_error(&view, &shadow, DVec3::new(0.0, y, -z), res)?;
                        Some((2.0 * e.mz, 2.0 * e.mx))
                    }
                };
                let ep = e.map(|e| e.0);
                let eq = e.map(|e| e.1);
                let epq = e.map(|e| e.0 * e.1);
                for ((field, val), range) in fields.iter_mut().zip([ep, eq, epq]).zip(&mut ranges) {
                    if let Some(v) = val {
                        range.0 = range.0.min(v);
                        range.1 = range.1.max(v);
                    }
                    field.push(val);
                }
            }
            let panels = fields
                .into_iter()
                .map(|values| Panel {
                    grid: Grid {
                        x_edges: grid.x_edges.clone(),
                        y_edges: grid.y_edges.clone(),
                        values,
                        clip: grid.clip.clone(),
                    },
                })
                .collect();
            row.push(panels);
        }
        rows.push(row);
        row_angles.push(format!("θ = {theta_deg:.0}°"));
        lambdas_all.push(lambdas);
    }
    // Each quantity's colour bar spans exactly its measured range over its nine panels.
    let scales: Vec<ColourScale> = QUANTITIES
        .iter()
        .zip(ranges)
        .map(|(q, (lo, hi))| {
            ColourScale::smooth(Axis::log_base(format!("{q} (log scale)"), lo, hi, 5.0))
        })
        .collect();
    // LiSPSM's λ (its built matrix's n′) per angle θ, for the caption.
    let lispsm: Vec<&str> = lambdas_all.iter().map(|ls| ls[1].as_str()).collect();
    let angles: Vec<&str> = row_angles
        .iter()
        .map(|a| a.trim_start_matches("θ = "))
        .collect();
    let caption = format!(
        "Zhang et al. 2009, Fig. 3, measured in the frustum's vertical plane: \
         n\u{a0}=\u{a0}{n}, f\u{a0}=\u{a0}{f}, \
         φ\u{a0}=\u{a0}π/6, light above and in front at θ\u{a0}=\u{a0}{}. LiSPSM's \
         λ\u{a0}=\u{a0}(n\u{a0}+\u{a0}√(fn))/sin\u{a0}θ: {}; TSM: 80\u{a0}% rule, \
         δ\u{a0}=\u{a0}{TSM_FOCUS}. Unlike the paper, a colour bar per quantity (ticks at \
         powers of 5), no scene insets.",
        angles.join(", "),
        lispsm.join(", "),
    );
    let single_caption = format!(
        "Zhang et al. 2009, Fig. 3, measured: n\u{a0}=\u{a0}{n}, f\u{a0}=\u{a0}{f}, \
         φ\u{a0}=\u{a0}π/6, light above and in front. LiSPSM: \
         λ\u{a0}=\u{a0}(n\u{a0}+\u{a0}√(fn))/sin\u{a0}θ; TSM: 80\u{a0}% rule, \
         δ\u{a0}=\u{a0}{TSM_FOCUS}. Unlike the paper, a colour bar per quantity.",
    );
    Ok(Fig3 {
        rows,
        row_angles,
        scheme_labels,
        scales,
        caption,
        single_caption,
        far: f,
        tan_phi,
    })
}

/// The grid of a side view: depth z from n to f, height y over the far plane's extent, every
/// cell cut to the frustum |y| ≤ z tan φ.
fn frustum_grid(n: f64, f: f64, tan_phi: f64) -> Grid {
    Grid::sample_clipped(
        (n, f, NZ),
        (-f * tan_phi, f * tan_phi, NY),
        vec![(-tan_phi, 1.0, 0.0), (-tan_phi, -1.0, 0.0)],
        |_, _| Some(0.0),
    )
}

fn fmt_lambda(n: NPrime) -> String {
    match n.as_finite() {
        None => "∞".to_string(),
        Some(v) => format!("{v:.2}"),
    }
}

/// The layout, in pixels: the row labels' column (θ and the y ticks, left of the first panel,
/// the height's name over them), the z labels' row under the last row
/// of panels, the gaps between panels across and between rows, between blocks, each block's
/// title and the schemes' headings, and the horizontal colour bar under each block.
const ROW_LABEL: u32 = 46;
const X_LABELS: u32 = 33;
const GAP: u32 = 4;
/// Rows 10 units apart: at 4 one row's "−40" and the next one's "40" touched.
const ROW_GAP: u32 = 10;
const BLOCK_GAP: u32 = 16;
const BLOCK_TITLE: u32 = 22;
const HEADINGS: u32 = 18;
const BAR: u32 = 52;
/// The colour bar's margins at its ends (room for the end labels).
const BAR_MARGIN: u32 = 14;
/// One column: the width of a vertical colour bar's column, and of its bar alone.
const VBAR: u32 = 86;
const VBAR_WIDTH: u32 = 14;
/// A panel's height over its width: the z range [−5, 105] across and y over ±0.535 of it up
/// (the frustum's far plane reaches ±57.7).
const PANEL_RATIO: f64 = 1.07;
/// The size of the figure's text (labels, ticks, headings); θ in one column is smaller, so
/// that "θ = 90°" fits along a row.
const TEXT: u32 = 13;
const THETA_SINGLE: u32 = 11;

/// The page's size: three blocks of 3 × 3 panels side by side (landscape drawing), the caption
/// under them; as tall as the blocks, their bars and the caption need.
pub(super) const SIZE: (u32, u32) = (520, 424);

/// A double-column panel's width: the body (the page less 6 units each side) less the left
/// strips, the gaps, shared by nine panels.
const fn double_panel_w() -> u32 {
    (SIZE.0 - 12 - ROW_LABEL - 6 * GAP - 2 * BLOCK_GAP) / 9
}

/// The length along a double-column (horizontal) colour bar of its range, in units.
fn double_bar_span() -> f64 {
    f64::from(3 * double_panel_w() + 2 * GAP - 2 * BAR_MARGIN)
}

/// The width of a plain number written at `size`: DejaVu Sans' digits advance 1303 of its 2048
/// units an em (0.636 em), its point 651 (0.318 em).
fn number_width(t: &str, size: u32) -> f64 {
    t.chars()
        .map(|c| if c == '.' { 651.0 } else { 1303.0 })
        .sum::<f64>()
        / 2048.0
        * f64::from(size)
}

/// The labelled ticks of a base-5 colour bar (axis space, that is log₅ of the value) with their
/// labels, plain numbers: the powers 5^{ks} in its range (k whole, so that 5⁰ = 1 is one where
/// it is in range), with the least stride s whose labels keep 6 units apart along the
/// double-column bar (`span` units long), in both layouts: the same ticks in both.
fn bar_ticks(axis: &Axis, span: f64) -> Vec<(f64, String)> {
    let (lo, hi) = axis.range();
    let per = span / (hi - lo);
    let first = lo.ceil() as i32;
    let last = hi.floor() as i32;
    let at = |stride: i32| -> Vec<(f64, String)> {
        (first..=last)
            .filter(|e| e.rem_euclid(stride) == 0)
            .map(|e| (f64::from(e), fmt_plain(5f64.powi(e))))
            .collect()
    };
    for stride in 1..=(last - first).max(1) {
        let ticks = at(stride);
        let apart = ticks.windows(2).all(|w| {
            let half = 0.5 * (number_width(&w[0].1, TEXT) + number_width(&w[1].1, TEXT));
            (w[1].0 - w[0].0) * per >= half + 6.0
        });
        if apart && !ticks.is_empty() {
            return ticks;
        }
    }
    at(1).into_iter().take(1).collect()
}

/// Draws a colour bar for `scale` into `area`, horizontal (its labels under it) or
/// `vertical` (its labels right of it, low values at the bottom): the bands, an outline, tick
/// marks with the labels of [`bar_ticks`] and the quantity's name beyond them.
fn draw_bar<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    scale: &ColourScale,
    vertical: bool,
) -> Result<(), Fail> {
    let (lo, hi) = scale.axis.range();
    let ticks = bar_ticks(&scale.axis, double_bar_span());
    let (w, _) = area.dim_in_pixel();
    let at: Vec<f64> = ticks.iter().map(|t| t.0).collect();
    // The labels of exactly the ticks handed to the axis.
    let label = |v: &f64| {
        ticks
            .iter()
            .find(|t| (t.0 - v).abs() < 1e-9)
            .map(|t| t.1.clone())
            .unwrap_or_default()
    };
    let mut builder = ChartBuilder::on(area);
    let mut chart = if vertical {
        builder
            .margin_top(BAR_MARGIN)
            .margin_bottom(BAR_MARGIN)
            .margin_right(4)
            .x_label_area_size(0)
            .y_label_area_size(0)
            .right_y_label_area_size(w.saturating_sub(VBAR_WIDTH))
            .build_cartesian_2d(
                Ticked::new(0.0, 1.0, vec![], vec![]),
                Ticked::new(lo, hi, at, vec![]),
            )?
    } else {
        builder
            .margin_left(BAR_MARGIN)
            .margin_right(BAR_MARGIN)
            .x_label_area_size(BAR - 14)
            .y_label_area_size(0)
            .build_cartesian_2d(
                Ticked::new(lo, hi, at, vec![]),
                Ticked::new(0.0, 1.0, vec![], vec![]),
            )?
    };
    let mut mesh = chart.configure_mesh();
    mesh.disable_mesh()
        .axis_desc_style((FONT, TEXT))
        .label_style((FONT, TEXT));
    if vertical {
        mesh.disable_x_axis()
            .y_desc(scale.axis.label.as_str())
            .y_label_formatter(&label)
            .set_tick_mark_size(LabelAreaPosition::Right, COLOUR_BAR_TICK);
    } else {
        mesh.disable_y_axis()
            .x_desc(scale.axis.label.as_str())
            .x_label_formatter(&label)
            .set_tick_mark_size(LabelAreaPosition::Bottom, COLOUR_BAR_TICK);
    }
    mesh.draw()?;
    // The bands, low to high, as one raster (no seams).
    draw_bar_bands(&chart, scale, vertical)?;
    let outline = if vertical {
        [(0.0, lo), (1.0, hi)]
    } else {
        [(lo, 0.0), (hi, 1.0)]
    };
    chart.draw_series(std::iter::once(Rectangle::new(
        outline,
        RGBColor(60, 60, 60).stroke_width(1),
    )))?;
    Ok(())
}

/// The depth axis's ticks (0, 50 and 100, the near plane at 1 and the far plane at 100) and
/// labels under the panel drawn by `chart` in `cell`: "0" centred on its tick, "100" ending at
/// its tick (centred, it ran under the next panel).
fn draw_z_labels<DB: DrawingBackend>(
    cell: &DrawingArea<DB, Shift>,
    chart: &super::chart::Chart2d<'_, DB>,
    bottom: f64,
) -> Result<(), Fail> {
    let base = cell.get_base_pixel();
    let ink = RGBColor(0, 0, 0);
    let style = TextStyle::from((FONT, TEXT).into_font());
    for (z, text, h) in [
        (0.0, "0", HPos::Center),
        (50.0, "", HPos::Center),
        (100.0, "100", HPos::Right),
    ] {
        let (x, y) = chart.backend_coord(&(z, bottom));
        let (x, y) = (x - base.0, y - base.1);
        cell.draw(&PathElement::new(
            vec![(x, y), (x, y + TICK as i32)],
            ink.stroke_width(1),
        ))?;
        if !text.is_empty() {
            let dx = i32::from(text.len() > 1);
            cell.draw(&Text::new(
                text,
                (x + dx, y + TICK as i32 + 3),
                style.pos(Pos::new(h, VPos::Top)),
            ))?;
        }
    }
    Ok(())
}

impl Figure for Fig3 {
    fn size(&self) -> (u32, u32) {
        SIZE
    }

    /// One column: the three blocks stacked.
    fn single_size(&self) -> Option<(u32, u32)> {
        Some((Column::Single.width(), 800))
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let single = column() == Column::Single;
        let caption = if single {
            self.single_caption.as_str()
        } else {
            self.caption.as_str()
        };
        let body = frame(
            root,
            "Side views of the aliasing error inside the view frustum",
            &[caption],
        )?;
        let (w, h) = body.dim_in_pixel();
        // Two columns: three blocks side by side, one per quantity, each with its colour bar
        // under it; one column: the blocks stacked, each bar right of its block. In each block
        // a row per angle θ and a column per scheme (the paper's arrangement) under the
        // schemes' headings, panels sharing their axes: the height y named over its axis, θ
        // and the y ticks left of each row, z labels under a block's first column (in
        // one column under the last block only).
        let left = ROW_LABEL;
        let pw = if single {
            let across = (w - left - 2 * GAP - VBAR) / 3;
            let fixed = 3 * (BLOCK_TITLE + HEADINGS + 2 * ROW_GAP) + X_LABELS + 2 * BLOCK_GAP;
            let down = f64::from(h.saturating_sub(fixed)) / (9.0 * PANEL_RATIO);
            across.min(down.floor() as u32)
        } else {
            double_panel_w()
        };
        let ph = (f64::from(pw) * PANEL_RATIO).round() as u32;
        let block_w = 3 * pw + 2 * GAP;
        let rows_h = 3 * ph + 2 * ROW_GAP;
        let block_h = BLOCK_TITLE + HEADINGS + rows_h + BLOCK_GAP;
        // No tick inside the range: the first would be at 500; the depth's ticks and labels
        // are drawn by [`draw_z_labels`].
        let z = Axis::every("z (eye depth)", -5.0, 105.0, 500.0, 1000.0);
        let blank = Axis::every("", -5.0, 105.0, 500.0, 1000.0);
        let half = 0.5 * (z.max - z.min) * f64::from(ph) / f64::from(pw);
        let text = |size: u32| TextStyle::from((FONT, size).into_font());
        for (q, scale) in self.scales.iter().enumerate() {
            let q32 = q as u32;
            // The block's left edge and top.
            let (bx, by) = if single {
                (left, q32 * block_h)
            } else {
                (left + q32 * (block_w + BLOCK_GAP), 0)
            };
            let z_labels = !single || q + 1 == self.scales.len();
            let grid_top = by + BLOCK_TITLE + HEADINGS;
            body.draw(&Text::new(
                format!(
                    "({}) {}",
                    ['a', 'b', 'c'][q],
                    ["E_p = 2 m_z", "E_q = 2 m_x", "E_p × E_q"][q]
                ),
                ((bx + block_w / 2) as i32, by as i32 + 2),
                text(TEXT).pos(Pos::new(HPos::Center, VPos::Top)),
            ))?;
            for (s, name) in self.scheme_labels.iter().enumerate() {
                let x = bx + s as u32 * (pw + GAP) + pw / 2;
                body.draw(&Text::new(
                    name.clone(),
                    (x as i32, (grid_top - 2) as i32),
                    text(TEXT).pos(Pos::new(HPos::Center, VPos::Bottom)),
                ))?;
            }
            // The height's name over its axis, in the headings' row left of the first
            // scheme's, of the first block (of every block in one column).
            if single || q == 0 {
                body.draw(&Text::new(
                    "height y",
                    (bx as i32 - 2, (grid_top - 2) as i32),
                    text(TEXT).pos(Pos::new(HPos::Right, VPos::Bottom)),
                ))?;
            }
            for (r, row) in self.rows.iter().enumerate() {
                for (s, scheme) in row.iter().enumerate() {
                    let row_label = (single || q == 0) && s == 0;
                    let last_row = z_labels && r + 1 == self.rows.len();
                    let x0 = bx + s as u32 * (pw + GAP) - if row_label { ROW_LABEL } else { 0 };
                    let cw = pw + if row_label { ROW_LABEL } else { 0 };
                    let ch = ph + if last_row { X_LABELS } else { 0 };
                    let cell = body
                        .clone()
                        .shrink((x0, grid_top + r as u32 * (ph + ROW_GAP)), (cw, ch));
                    let style = ChartStyle {
                        title_size: PANEL_TITLE,
                        x_label_area: if last_row { X_LABELS } else { 0 },
                        y_label_area: if row_label { ROW_LABEL } else { 0 },
                        tick_size: TEXT,
                        desc_size: if single { THETA_SINGLE } else { TEXT },
                        margin: 0,
                    };
                    // θ as the first panel's y description, with the height y at −40, 0 and
                    // 40 (one y scale for every row).
                    let y = if row_label {
                        Axis::every(self.row_angles[r].as_str(), -half, half, -40.0, 40.0)
                    } else {
                        Axis::every("", -half, half, 500.0, 1000.0)
                    };
                    let x = if s == 0 && last_row { &z } else { &blank };
                    let mut chart = build_chart_styled(&cell, "", x, &y, false, &style)?;
                    super::chart::draw_grid(&mut chart, &scheme[q].grid, scale)?;
                    // The frustum's outline and the panel's frame.
                    let (n, f, t) = (1.0, self.far, self.tan_phi);
                    chart.draw_series(std::iter::once(PathElement::new(
                        vec![
                            (n, -n * t),
                            (f, -f * t),
                            (f, f * t),
                            (n, n * t),
                            (n, -n * t),
                        ],
                        RGBColor(40, 40, 40).stroke_width(1),
                    )))?;
                    // The frame at the data's extent: depth n to f, height ± f tan φ.
                    chart.draw_series(std::iter::once(Rectangle::new(
                        [(n, -f * t), (f, f * t)],
                        RGBColor(150, 150, 150).stroke_width(1),
                    )))?;
                    if s == 0 && last_row {
                        draw_z_labels(&cell, &chart, -half)?;
                    }
                }
            }
            if single {
                let bar = body
                    .clone()
                    .shrink((bx + block_w + GAP, grid_top), (VBAR, rows_h));
                draw_bar(&bar, scale, true)?;
            } else {
                let bar_top = grid_top + rows_h + X_LABELS + 6;
                let bar = body.clone().shrink((bx, bar_top), (block_w, BAR));
                draw_bar(&bar, scale, false)?;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analytic::global::{zhang_ep, zhang_eq};
    use crate::LightAngle;

    /// The measured side view at θ = 90° and 60° (LiSPSM row) equals Zhang's global
    /// representation (Eq 13, 14 with the corrected Appendix, `analytic::global`) at every
    /// cell centre inside the frustum; E_p × E_q is their product.
    /// A horizontal colour bar is one embedded image (abutting rectangles left seams, issue
    /// 25), its lowest band at the left and its highest at the right.
    #[test]
    fn colour_bar_is_one_seamless_raster() {
        use super::super::chart::read_svg::{draw_svg, embedded_images};
        use super::super::chart::SMOOTH_LEVELS;
        let scale = ColourScale::smooth(Axis::log10("E", 2.0, 16400.0));
        let svg = draw_svg((160, BAR), |area| draw_bar(area, &scale, false).unwrap());
        assert!(!svg
            .lines()
            .any(|l| l.starts_with("<rect") && !l.contains("fill=\"none\"")));
        let images = embedded_images(&svg);
        assert_eq!(images.len(), 1);
        let img = &images[0].rgba;
        let (w, h) = img.dimensions();
        let at = |x: u32| {
            let p = img.get_pixel(x, h / 2).0;
            RGBColor(p[0], p[1], p[2])
        };
        assert_eq!(at(0), scale.level_colour(0));
        assert_eq!(at(w - 1), scale.level_colour(SMOOTH_LEVELS - 1));
    }

    /// The depth axis under each block's first column reads 0 and 100 (the far plane f, review:
    /// "0, 50" left f unreadable), "0" centred on its tick and "100" ending at the panel's right
    /// edge (centred, it ran under the next panel); the height has its axis title, "height y",
    /// once; every row's first panel of (a) has a y scale, −40, 0, 40; and rows are apart: a
    /// row's "−40" and the next row's "40" (13 units tall) keep at least 9 units between them
    /// (review: about 4 pt, touching).
    #[test]
    fn depth_reads_0_to_100_the_height_is_named_and_rows_are_apart() {
        use super::super::chart::read_svg::{attr, draw_svg, texts};
        let fig = fig3().map_err(|e| e.named("zhang-fig3")).unwrap();
        let svg = draw_svg(SIZE, |area| fig.draw(area).unwrap());
        let all = texts(&svg);
        let named = |t: &str| all.iter().filter(|x| x.1 == t).count();
        assert_eq!(named("z (eye depth)"), 3);
        assert_eq!(named("height y"), 1);
        assert_eq!(named("50"), 0);
        // The panels' grey frames (n to f across): their right edges.
        let frames: Vec<f64> = svg
            .lines()
            .filter(|l| l.starts_with("<rect") && l.contains("stroke=\"#969696\""))
            .map(|l| attr(l, "x").unwrap() + attr(l, "width").unwrap())
            .collect();
        assert_eq!(frames.len(), 27);
        let hundreds: Vec<&(&str, String, f64)> = all.iter().filter(|x| x.1 == "100").collect();
        assert_eq!(hundreds.len(), 3, "{hundreds:?}");
        for (line, _, _) in hundreds {
            assert!(line.contains("text-anchor=\"end\""), "{line}");
            let x = attr(line, "x").unwrap();
            assert!(
                frames.iter().any(|r| (x - r).abs() <= 2.0),
                "\"100\" ends at {x}, no frame edge there: {frames:?}"
            );
        }
        assert!(named("0") >= 3 + 3);
        // The y scale: in the first block's rows, by height.
        let at = |t: &str| -> Vec<f64> {
            let mut v: Vec<f64> = all.iter().filter(|x| x.1 == t).map(|x| x.2).collect();
            v.sort_by(f64::total_cmp);
            v
        };
        let (top, bottom) = (at("40"), at("−40"));
        assert_eq!((top.len(), bottom.len()), (3, 3), "{top:?} {bottom:?}");
        for r in 0..2 {
            // A tick label's y is its middle: the next row's "40" at least 22 units under this
            // row's "−40", their 13-unit boxes 9 apart (with rows 4 units apart, 18.7 and 5.7).
            assert!(top[r + 1] - bottom[r] >= 22.0, "{top:?} {bottom:?}");
        }
    }

    /// The colour bars' ticks are plain powers of 5 (issue 35 item 9: they read 5⁰, 5¹, 5²),
    /// every power where the labels keep 6 units apart on the double-column bar, else every
    /// second or third (5^{ks}, so that 1 = 5⁰ is one), the same ticks in both layouts. By
    /// hand, on a bar 100 units long (DejaVu digits 8.27 units at 13, the point 4.13): E over
    /// 0.028 to 128 spans log₅ −2.22 to 3.01, 19.1 units a power: "0.04" (28.9 wide) and "0.2"
    /// (20.7) need 30.8, so every second power, 0.04, 1, 25 (38.2 apart); E over 2 to 230,
    /// log₅ 0.43 to 3.38, 33.9 units a power: 5, 25 and 125 fit (25 and 125 need 26.7).
    #[test]
    fn colour_bar_ticks_are_plain_powers_of_five() {
        let labels = |lo: f64, hi: f64| -> Vec<String> {
            bar_ticks(&Axis::log_base("E", lo, hi, 5.0), 100.0)
                .into_iter()
                .map(|t| t.1)
                .collect()
        };
        assert_eq!(labels(0.028, 128.0), ["0.04", "1", "25"]);
        assert_eq!(labels(2.0, 230.0), ["5", "25", "125"]);
        // 0.06 to 16400: log₅ −1.75 to 6.03, 12.85 units a power: every third puts "125" (24.8)
        // and "15625" (41.3) 38.6 apart, short of 39.1; every fourth, 1 and 625.
        assert_eq!(labels(0.06, 16400.0), ["1", "625"]);
    }

    /// The single column's bars carry the double column's ticks (review: the sets differed):
    /// read back from both SVGs, the labels of each bar, by quantity, are the same.
    #[test]
    fn both_layouts_label_their_bars_alike() {
        use super::super::chart::read_svg::{draw_svg, texts};
        use super::super::chart::with_page;
        let fig = fig3().map_err(|e| e.named("zhang-fig3")).unwrap();
        let numbers = |column: Column, size: (u32, u32)| -> Vec<String> {
            let svg = with_page(false, column, || {
                draw_svg(size, |area| fig.draw(area).unwrap())
            });
            let mut v: Vec<String> = texts(&svg)
                .into_iter()
                .map(|t| t.1)
                .filter(|t| {
                    !t.is_empty()
                        && t.chars().all(|c| c.is_ascii_digit() || c == '.')
                        && !["0", "40", "100"].contains(&t.as_str())
                })
                .collect();
            v.sort();
            v
        };
        let double = numbers(Column::Double, SIZE);
        let single = numbers(Column::Single, fig.single_size().unwrap());
        assert!(double.len() >= 9, "{double:?}");
        assert_eq!(double, single);
    }

    #[test]
    fn lispsm_cells_equal_zhangs_global_representation() {
        let fig = fig3().map_err(|e| e.named("zhang-fig3")).unwrap();
        let view = ViewFrustum::new(1.0, 100.0, FRAC_PI_6).unwrap();
        for (r, theta_deg) in [(0usize, 90.0f64), (1, 60.0)] {
            let theta = LightAngle::new(theta_deg.to_radians()).unwrap();
            // LiSPSM's λ = (n + √(fn))/sin θ.
            let lambda = NPrime::finite(11.0 / theta_deg.to_radians().sin()).unwrap();
            let panels = &fig.rows[r][1];
            let g = &panels[0].grid;
            let nx = g.x_edges.len() - 1;
            let mut checked = 0;
            for (k, v) in g.values.iter().enumerate() {
                let Some(ep) = *v else { continue };
                let (z, y) = g.sample_point(k % nx, k / nx).unwrap();
                let want_p = zhang_ep(&view, lambda, theta, y, z).unwrap();
                let want_q = zhang_eq(&view, lambda, theta, y, z).unwrap();
                let eq = panels[1].grid.values[k].unwrap();
                let epq = panels[2].grid.values[k].unwrap();
                assert!(
                    (ep - want_p).abs() < 1e-9 * want_p,
                    "E_p at ({y}, {z}): {ep} vs {want_p}"
                );
                assert!(
                    (eq - want_q).abs() < 1e-9 * want_q,
                    "E_q at ({y}, {z}): {eq} vs {want_q}"
                );
                assert!((epq - ep * eq).abs() < 1e-12 * epq);
                checked += 1;
            }
            assert!(checked > 1000, "{checked} cells");
        }
    }

    /// The side views sample the near plane: the first column of cells is [n, n + 1] (99 cells
    /// over [1, 100]), its (cut) cells are sampled inside it, where
    /// the old grid over [0, f] first sampled z = 1.875; the cells along the slanted sides end
    /// on the frustum's border |y| = z tan φ.
    #[test]
    fn side_view_cells_start_at_the_near_plane_and_follow_the_border() {
        let t = FRAC_PI_6.tan();
        let g = frustum_grid(1.0, 100.0, t);
        assert_eq!(g.x_edges[0], 1.0);
        let nx = g.x_edges.len() - 1;
        let first: Vec<(f64, f64)> = (0..g.y_edges.len() - 1)
            .filter_map(|j| g.sample_point(0, j))
            .collect();
        assert!(!first.is_empty());
        for &(z, y) in &first {
            assert!(z > 1.0 && z < 2.0, "z = {z}");
            assert!(y.abs() <= z * t);
        }
        for j in 0..g.y_edges.len() - 1 {
            for i in 0..nx {
                let (poly, _) = g.cell(i, j);
                for p in poly {
                    assert!(p.1.abs() <= p.0 * t * (1.0 + 1e-12) + 1e-12, "{p:?}");
                }
            }
        }
    }
}
