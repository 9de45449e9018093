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
    Grid, Ticked, COLOUR_BAR_TICK, FONT, PANEL_TITLE,
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
    caption: Vec<String>,
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
    let caption = vec![format!(
        "Zhang et al. 2009, Fig. 3: E_p\u{a0}=\u{a0}2\u{a0}m_z and E_q\u{a0}=\u{a0}2\u{a0}m_x \
         measured in the frustum's vertical plane (z depth, y height); n\u{a0}=\u{a0}{n}, \
         f\u{a0}=\u{a0}{f}, φ\u{a0}=\u{a0}π/6; light above and in front at \
         θ\u{a0}=\u{a0}{}. LiSPSM: \
         λ\u{a0}=\u{a0}(n\u{a0}+\u{a0}√(fn))/sin\u{a0}θ\u{a0}=\u{a0}{}; TSM: 80\u{a0}% rule, \
         focus δ\u{a0}=\u{a0}{TSM_FOCUS}. Unlike the paper, a colour bar per quantity (ticks at \
         powers of 5) and no scene insets.",
        angles.join(", "),
        lispsm.join(", "),
    )];
    Ok(Fig3 {
        rows,
        row_angles,
        scheme_labels,
        scales,
        caption,
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

/// The layout, in pixels: the row labels' column (θ, left of the first panel), the z labels'
/// row under the last row of panels, the gaps between panels and between blocks, each block's
/// title and the schemes' headings, and the horizontal colour bar under each block.
const ROW_LABEL: u32 = 46;
const X_LABELS: u32 = 33;
const GAP: u32 = 4;
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

/// The page's size: three blocks of 3 × 3 panels side by side (landscape drawing), the caption
/// under them.
pub(super) const SIZE: (u32, u32) = (520, 452);

/// The labelled ticks of a base-5 colour bar (axis space, that is log₅ of the value) with their
/// labels, all plain numbers: both ends of its range to three significant digits, and every
/// power of 5 (0.04, 0.2, 1, 5, 25, …) at least 7 % of the bar from either end.
fn bar_ticks(axis: &Axis) -> Vec<(f64, String)> {
    let (lo, hi) = axis.range();
    let clear = 0.07 * (hi - lo);
    let three = |v: f64| {
        let p = 10f64.powf(v.log10().floor() - 2.0);
        fmt_plain((v / p).round() * p)
    };
    let mut ticks = vec![(lo, three(axis.min))];
    let first = lo.ceil() as i32;
    let last = hi.floor() as i32;
    for e in first..=last {
        let a = f64::from(e);
        if a - lo >= clear && hi - a >= clear {
            ticks.push((a, fmt_plain(5f64.powi(e))));
        }
    }
    ticks.push((hi, three(axis.max)));
    ticks
}

/// Draws a colour bar for `scale` into `area`, horizontal (its labels under it) or
/// `vertical` (its labels right of it, low values at the bottom): the bands, an outline, tick
/// marks with the labels of [`bar_ticks`] (its ends and the powers of 5), thinned so that no
/// two labels touch, and the quantity's name beyond them.
fn draw_bar<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    scale: &ColourScale,
    vertical: bool,
) -> Result<(), Fail> {
    let (lo, hi) = scale.axis.range();
    let all = bar_ticks(&scale.axis);
    let (w, h) = area.dim_in_pixel();
    let span = f64::from(if vertical { h } else { w } - 2 * BAR_MARGIN);
    let px = |a: f64| f64::from(BAR_MARGIN) + (a - lo) / (hi - lo) * span;
    let style = TextStyle::from((FONT, 13).into_font());
    // Half a label's extent along the bar: its width across a horizontal bar, its height up
    // a vertical one.
    let half = |t: &str| -> Result<f64, Fail> {
        let (tw, th) = area
            .estimate_text_size(t, &style)
            .map_err(|e| Fail::Draw(e.to_string()))?;
        Ok(0.5 * f64::from(if vertical { th } else { tw }))
    };
    // The ends first, then each decade that keeps 6 pixels from the labels kept so far.
    let mut kept: Vec<(f64, String, f64)> = Vec::new();
    let order = [0, all.len() - 1]
        .into_iter()
        .chain(1..all.len().saturating_sub(1));
    for i in order {
        let (a, t) = &all[i];
        let (x, hw) = (px(*a), half(t)?);
        if kept.iter().all(|k| (k.0 - x).abs() >= k.2 + hw + 6.0) {
            kept.push((x, t.clone(), hw));
        }
    }
    let ticks: Vec<(f64, String)> = all
        .iter()
        .filter(|(a, _)| kept.iter().any(|k| (k.0 - px(*a)).abs() < 1e-9))
        .cloned()
        .collect();
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
        .axis_desc_style((FONT, 13))
        .label_style((FONT, 13));
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

impl Figure for Fig3 {
    fn size(&self) -> (u32, u32) {
        SIZE
    }

    /// One column: the three blocks stacked.
    fn single_size(&self) -> Option<(u32, u32)> {
        Some((Column::Single.width(), 800))
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let caption: Vec<&str> = self.caption.iter().map(String::as_str).collect();
        let body = frame(
            root,
            "Side views of the aliasing error inside the view frustum",
            &caption,
        )?;
        let (w, h) = body.dim_in_pixel();
        // Two columns: three blocks side by side, one per quantity, each with its colour bar
        // under it; one column: the blocks stacked, each bar right of its block, the schemes'
        // headings over the first block and the z labels under the last only. In each block a
        // row per angle θ and a column per scheme (the paper's arrangement), panels sharing
        // their axes: θ and y left of each row, z labels under a block's first column.
        let single = column() == Column::Single;
        let pw = if single {
            let across = (w - ROW_LABEL - 2 * GAP - VBAR) / 3;
            let fixed = 3 * (BLOCK_TITLE + 2 * GAP) + HEADINGS + X_LABELS + 2 * BLOCK_GAP;
            let down = f64::from(h.saturating_sub(fixed)) / (9.0 * PANEL_RATIO);
            across.min(down.floor() as u32)
        } else {
            (w - ROW_LABEL - 6 * GAP - 2 * BLOCK_GAP) / 9
        };
        let ph = (f64::from(pw) * PANEL_RATIO).round() as u32;
        let block_w = 3 * pw + 2 * GAP;
        let block_h = BLOCK_TITLE + 3 * ph + 2 * GAP + BLOCK_GAP;
        // Labels at 0 and 50 only: "50" and "100" collided under a panel, and "100", centred
        // on the panel's right end, ran into the next panel.
        let z = Axis::every("z (eye depth)", -5.0, 105.0, 0.0, 50.0).labelled_at(&[0.0, 50.0]);
        // No tick inside the range: the first would be at 500.
        let blank = Axis::every("", -5.0, 105.0, 500.0, 1000.0);
        let half = 0.5 * (z.max - z.min) * f64::from(ph) / f64::from(pw);
        let text = |size: u32| TextStyle::from((FONT, size).into_font());
        for (q, scale) in self.scales.iter().enumerate() {
            let q32 = q as u32;
            // The block's left edge and top, and the top of its panels.
            let (bx, by) = if single {
                (ROW_LABEL, q32 * block_h + if q > 0 { HEADINGS } else { 0 })
            } else {
                (ROW_LABEL + q32 * (block_w + BLOCK_GAP), 0)
            };
            let headings = !single || q == 0;
            let z_labels = !single || q + 1 == self.scales.len();
            let grid_top = by + BLOCK_TITLE + if headings { HEADINGS } else { 0 };
            body.draw(&Text::new(
                format!(
                    "({}) {}",
                    ['a', 'b', 'c'][q],
                    ["E_p = 2 m_z", "E_q = 2 m_x", "E_p × E_q"][q]
                ),
                ((bx + block_w / 2) as i32, by as i32 + 2),
                text(13).pos(Pos::new(HPos::Center, VPos::Top)),
            ))?;
            if headings {
                for (s, name) in self.scheme_labels.iter().enumerate() {
                    let x = bx + s as u32 * (pw + GAP) + pw / 2;
                    body.draw(&Text::new(
                        name.clone(),
                        (x as i32, (grid_top - 2) as i32),
                        text(13).pos(Pos::new(HPos::Center, VPos::Bottom)),
                    ))?;
                }
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
                        .shrink((x0, grid_top + r as u32 * (ph + GAP)), (cw, ch));
                    let style = ChartStyle {
                        title_size: PANEL_TITLE,
                        x_label_area: if last_row { X_LABELS } else { 0 },
                        y_label_area: if row_label { ROW_LABEL } else { 0 },
                        tick_size: 13,
                        desc_size: 13,
                        margin: 0,
                    };
                    // θ as the first panel's y description (in one column its value only:
                    // "θ = 90°" is longer than a row is high), with the height y at −40, 0
                    // and 40 (one y scale for every row; ±50 of two rows touched); z labelled
                    // under each block's first column only.
                    let y = if row_label {
                        let angle = if single {
                            self.row_angles[r].trim_start_matches("θ = ")
                        } else {
                            self.row_angles[r].as_str()
                        };
                        Axis::every(angle, -half, half, -40.0, 40.0)
                    } else {
                        Axis::every("", -half, half, 500.0, 1000.0)
                    };
                    let x = if s == 0 { &z } else { &blank };
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
                }
            }
            if single {
                let bar = body
                    .clone()
                    .shrink((bx + block_w + GAP, grid_top), (VBAR, 3 * ph + 2 * GAP));
                draw_bar(&bar, scale, true)?;
            } else {
                let bar_top = grid_top + 3 * ph + 2 * GAP + X_LABELS + 6;
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

    /// The z ticks under each block's first column are labelled 0 and 50 only ("50" and
    /// "100" were about a unit apart and collided, and "100", centred on the panel's right
    /// end, ran into the next panel): each block's z axis is labelled "0", "50" only; and the
    /// first column of each row has a y scale, −40, 0, 40 (the frustum's far plane reaches
    /// ±100 tan 30° = ±57.7).
    #[test]
    fn z_ticks_are_zero_and_fifty_and_rows_have_a_y_scale() {
        use super::super::chart::read_svg::{draw_svg, texts};
        let fig = fig3().map_err(|e| e.named("zhang-fig3")).unwrap();
        let svg = draw_svg(SIZE, |area| fig.draw(area).unwrap());
        let labels: Vec<String> = texts(&svg).into_iter().map(|t| t.1).collect();
        // Each block's z axis: its description, then its tick labels.
        let mut blocks = 0;
        for (i, t) in labels.iter().enumerate() {
            if t == "z (eye depth)" {
                // Up to the block's colour bar: the z labels, in the first block after the
                // last row's y labels.
                let end = i + labels[i..]
                    .iter()
                    .position(|t| t.ends_with("(log scale)"))
                    .unwrap();
                let axis = &labels[i + 1..end];
                assert!(axis.windows(2).any(|w| w == ["0", "50"]), "{axis:?}");
                blocks += 1;
            }
        }
        assert_eq!(blocks, 3);
        assert!(!labels.iter().any(|t| t == "100"), "{labels:?}");
        for tick in ["−40", "0", "40"] {
            let n = labels.iter().filter(|t| *t == tick).count();
            assert!(n >= 3, "{tick}: {n} in {labels:?}");
        }
    }

    /// The colour bars' ticks are plain numbers at powers of 5 (issue 35 item 9: they read
    /// 5⁰, 5¹, 5²): for E over 0.028 to 128, log₅ runs from −2.22 to 3.01; the powers 5^−1
    /// to 5² are at least 7 % of the bar (0.37) from its ends, 5^−2 = 0.04 and 5³ = 125 are
    /// not, and the ends are written to three digits.
    #[test]
    fn colour_bar_ticks_are_plain_powers_of_five() {
        let axis = Axis::log_base("E", 0.028, 128.0, 5.0);
        let labels: Vec<String> = bar_ticks(&axis).into_iter().map(|t| t.1).collect();
        assert_eq!(labels, ["0.028", "0.2", "1", "5", "25", "128"]);
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
