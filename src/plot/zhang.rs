//! Zhang, Zhao & Sun 2009 Fig 3: side views of the perspective aliasing E_p, E_q and E_p×E_q
//! inside the view frustum for SSM, LiSPSM and TSM at light–view angles γ = 90°, 60°, 30°
//! (Zhang's θ; γ as in the crate's other figures, whose θ is the half field of view).
//!
//! Every value is measured: the renderer-facing matrix of each scheme is built by
//! [`crate::maps::warp`] for a light above and in front of the viewer (Zhang's Fig 2), and
//! [`crate::measure::point_error`] gives m_x and m_z at each point of the frustum's vertical
//! plane x = 0, so that E_q = 2 m_x and E_p = 2 m_z (Zhang's screen in [−1, 1], texture in
//! [0, 1]; unit resolutions).

use super::chart::{
    build_chart_styled, column, decades, draw_colour_bar, draw_colour_bar_across, frame, Axis,
    ChartStyle, ColourScale, Grid, FONT, PANEL_TITLE, TICK,
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
/// γ = 90° and 60° (his θ), as his §3.1 says of his.
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
    /// rows[γ][scheme][quantity]
    rows: Vec<Vec<Vec<Panel>>>,
    /// "γ = 90°" per row.
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
        // Source above and in front of the viewer: light travels along (0, −sin γ, cos γ).
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
        row_angles.push(format!("γ = {theta_deg:.0}°"));
        lambdas_all.push(lambdas);
    }
    // Each quantity's colour bar spans the whole decades round its measured range over its
    // nine panels: its ends are round powers of ten and nothing is clipped (SSM's E_p reaches
    // (f − n)/(n tan φ) = 171 at the apex, Zhang's Eq 9).
    let scales: Vec<ColourScale> = QUANTITIES
        .iter()
        .zip(ranges)
        .map(|(q, (lo, hi))| {
            let (lo, hi) = decades(lo, hi);
            ColourScale::smooth(Axis::log10(format!("{q} (log scale)"), lo, hi))
        })
        .collect();
    // LiSPSM's n′ (Zhang's λ, its built matrix's) per angle γ, for the caption.
    let lispsm: Vec<&str> = lambdas_all.iter().map(|ls| ls[1].as_str()).collect();
    let angles: Vec<&str> = row_angles
        .iter()
        .map(|a| a.trim_start_matches("γ = "))
        .collect();
    let phi = view.half_fov().to_degrees();
    // What m_z and m_x are, once in each caption (the seventh review, R7-Z3-1: the blocks'
    // titles' "(⊥ light)" was unexplained notation; the eleventh, R11-zhang-fig3-1: written out,
    // not "m: Lloyd 2006's"): Lloyd 2006's errors (Eq 7, 8), a texel's width measured
    // perpendicular to the light over a pixel's ([`crate::measure::point_error`]), that is on a
    // surface facing the light; ×2 because Zhang's screen and map span [−1, 1].
    let caption = format!(
        "Zhang et al. 2009, Fig. 3: n\u{a0}=\u{a0}{n}, f\u{a0}=\u{a0}{f}, half field of \
         view θ\u{a0}=\u{a0}{phi:.0}° (Zhang's φ); light at \
         γ\u{a0}=\u{a0}{} from the view (Zhang's θ). E_p, E_q: aliasing along \
         screen y, x; m: Lloyd 2006's error (Eq 7, 8) facing the light; \
         ×2 for Zhang's span \
         [−1,\u{a0}1]. SSM: n′\u{a0}=\u{a0}∞; LiSPSM's \
         n′\u{a0}=\u{a0}(n\u{a0}+\u{a0}√(fn))/sin\u{a0}γ (Zhang's λ): {}; TSM: \
         80\u{a0}% rule, focus depth δ\u{a0}=\u{a0}{TSM_FOCUS}. Unlike the paper: no scene \
         insets.",
        angles.join(", "),
        lispsm.join(", "),
    );
    // One column: n, f and the LiSPSM and TSM columns' rules as in two columns (the eighth
    // review, R8-zhang-fig3-1: without them the columns were undefined); γ's values and E_p,
    // E_q = 2 m left to the rows' and blocks' labels, the half scale to the axis' name
    // ("height y (drawn at ½ the scale of z)", R11-zhang-fig3-3); m and the factor 2 written out (R11-zhang-fig3-1).
    let single_caption = format!(
        "Zhang et al. 2009, Fig. 3: f/n\u{a0}=\u{a0}{f}, half field of view \
         θ\u{a0}=\u{a0}{phi:.0}°, light at γ from the view. m: Lloyd 2006's error \
         facing the light, ×2 for [−1,\u{a0}1]. n′: SSM ∞, LiSPSM \
         (n\u{a0}+\u{a0}√(fn))/sin\u{a0}γ; TSM: \
         80\u{a0}% rule, focus depth δ\u{a0}=\u{a0}{TSM_FOCUS}."
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

/// The layout, in units: the row labels' column (γ and the y ticks, left of the first panel,
/// the height's name over them), the z labels' row under the last row of panels, the gaps
/// between panels across and between rows, between blocks, each block's title and the
/// schemes' headings, and the colour bar under each block (two columns) or beside it (one).
const ROW_LABEL: u32 = 46;
/// The turned name of the height's axis, left of the row labels' column, in both layouts.
const Y_NAME: u32 = 15;
const X_LABELS: u32 = 33;
const GAP: u32 = 4;
/// Rows 10 units apart: at 4 one row's "−40" and the next one's "40" touched.
const ROW_GAP: u32 = 10;
const BLOCK_GAP: u32 = 16;
const BLOCK_TITLE: u32 = 22;
const HEADINGS: u32 = 18;
const BAR: u32 = 52;
/// One column: the row labels' column (γ turned, the ticks ±30), the gaps between panels
/// across (room for a column's "100" and the next one's "0") and between rows, a block's
/// title, the gap between blocks, and the upright colour bar's column.
const ROW_LABEL_1: u32 = 46;
const GAP_1: u32 = 10;
const ROW_GAP_1: u32 = 3;
const BLOCK_TITLE_1: u32 = 20;
const BLOCK_GAP_1: u32 = 12;
const VBAR: u32 = 78;
/// A double-column panel's height over its width: the z range [−5, 105] across and y over
/// ±0.535 of it up (the frustum's far plane reaches ±57.7), drawn to scale.
const PANEL_RATIO: f64 = 1.07;
/// The size of the figure's text (labels, ticks, headings), in both layouts.
const TEXT: u32 = 13;

/// The page's size: three blocks of 3 × 3 panels side by side (landscape drawing), the caption
/// under them; as tall as the blocks, their bars and the caption need.
pub(super) const SIZE: (u32, u32) = (520, 462);

/// A double-column panel's width: the body (the page less 6 units each side) less the left
/// strips, the gaps, shared by nine panels.
const fn double_panel_w() -> u32 {
    (SIZE.0 - 12 - Y_NAME - ROW_LABEL - 6 * GAP - 2 * BLOCK_GAP) / 9
}

/// The depth axis's ticks (0, 50 and 100, the near plane at 1 and the far plane at 100) under
/// the panel drawn by `chart` in `cell`, and where `numbered` their labels "0" and "100", each
/// centred on its tick (the nineteenth review, R19-zhang-fig3-1: "100" ending at its tick
/// stood under the unlabelled 50; it was so since it ran under the next panel centred, which
/// is white there, the depth being numbered under one panel of a row only).
fn draw_z_labels<DB: DrawingBackend>(
    cell: &DrawingArea<DB, Shift>,
    chart: &super::chart::Chart2d<'_, DB>,
    bottom: f64,
    numbered: bool,
) -> Result<(), Fail> {
    let base = cell.get_base_pixel();
    let ink = RGBColor(0, 0, 0);
    let style = TextStyle::from((FONT, TEXT).into_font());
    for (z, text) in [(0.0, "0"), (50.0, ""), (100.0, "100")] {
        let (x, y) = chart.backend_coord(&(z, bottom));
        let (x, y) = (x - base.0, y - base.1);
        cell.draw(&PathElement::new(
            vec![(x, y), (x, y + TICK as i32)],
            ink.stroke_width(1),
        ))?;
        if numbered && !text.is_empty() {
            cell.draw(&Text::new(
                text,
                (x, y + TICK as i32 + 3),
                style.pos(Pos::new(HPos::Center, VPos::Top)),
            ))?;
        }
    }
    Ok(())
}

/// Where one block of 3 × 3 panels goes: its left edge and top (the first row's), the panels'
/// size and the gaps between them.
#[derive(Debug, Clone, Copy)]
struct Block {
    x: u32,
    top: u32,
    pw: u32,
    ph: u32,
    gap: u32,
    row_gap: u32,
}

impl Block {
    fn width(&self) -> u32 {
        3 * self.pw + 2 * self.gap
    }

    fn height(&self) -> u32 {
        3 * self.ph + 2 * self.row_gap
    }
}

impl Fig3 {
    /// Draws the panels of quantity `q` into `block` on `body`: a row per angle γ, a column
    /// per scheme, each panel's frustum outline and grey frame at the data's extent; the
    /// first column's panels carry γ (`row_name` of it), and those of the rows `ticked` the y
    /// ticks from `y_first` every `y_step`; the panels of the `z_under` columns of the last
    /// row the depth's ticks, the first of them its numbers and the `z_named` one its name.
    #[allow(clippy::too_many_arguments)]
    fn draw_block<DB: DrawingBackend>(
        &self,
        body: &DrawingArea<DB, Shift>,
        q: usize,
        b: Block,
        (row_label, half, y_first, y_step): (u32, f64, f64, f64),
        row_name: &dyn Fn(&str) -> String,
        ticked: &[usize],
        z_under: &[usize],
        z_named: Option<usize>,
    ) -> Result<(), Fail> {
        let z = Axis::every("depth z", -5.0, 105.0, 500.0, 1000.0);
        let blank = Axis::every("", -5.0, 105.0, 500.0, 1000.0);
        for (r, row) in self.rows.iter().enumerate() {
            for (s, scheme) in row.iter().enumerate() {
                let labelled = s == 0 && row_label > 0;
                let last_row = r + 1 == self.rows.len() && z_under.contains(&s);
                let x0 = b.x + s as u32 * (b.pw + b.gap) - if labelled { row_label } else { 0 };
                let cw = b.pw + if labelled { row_label } else { 0 };
                let ch = b.ph + if last_row { X_LABELS } else { 0 };
                let cell = body
                    .clone()
                    .shrink((x0, b.top + r as u32 * (b.ph + b.row_gap)), (cw, ch));
                let style = ChartStyle {
                    title_size: PANEL_TITLE,
                    x_label_area: if last_row { X_LABELS } else { 0 },
                    y_label_area: if labelled { row_label } else { 0 },
                    tick_size: TEXT,
                    desc_size: TEXT,
                    margin: 0,
                };
                // γ as the first panel's y description, with the height y at −40, 0 and 40 in
                // two columns, at −30 and 30 in one (its rows are too low for 0 between them,
                // and ±40 stood 4 units from the next row's): one y scale for every row.
                let y = if labelled && ticked.contains(&r) {
                    Axis::every(row_name(&self.row_angles[r]), -half, half, y_first, y_step)
                } else if labelled {
                    Axis::every(row_name(&self.row_angles[r]), -half, half, 500.0, 1000.0)
                } else {
                    Axis::every("", -half, half, 500.0, 1000.0)
                };
                let x = if last_row && z_named == Some(s) {
                    &z
                } else {
                    &blank
                };
                let mut chart = build_chart_styled(&cell, "", x, &y, false, &style)?;
                // The rows not `ticked` get the same tick marks, unlabelled: every row's axis
                // is ticked (the seventh review, R7-Z3-2: bare axis bars beside the rows
                // without numbers).
                if labelled && !ticked.contains(&r) {
                    let base = cell.get_base_pixel();
                    let mut v = y_first;
                    while v <= half {
                        if v >= -half {
                            let (px, py) = chart.backend_coord(&(-5.0, v));
                            let (px, py) = (px - base.0 - 1, py - base.1);
                            cell.draw(&PathElement::new(
                                vec![(px - TICK as i32, py), (px, py)],
                                RGBColor(0, 0, 0).stroke_width(1),
                            ))?;
                        }
                        v += y_step;
                    }
                }
                super::chart::draw_grid(&mut chart, &scheme[q].grid, &self.scales[q])?;
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
                if last_row {
                    draw_z_labels(&cell, &chart, -half, z_under.first() == Some(&s))?;
                }
            }
        }
        Ok(())
    }

    /// The schemes' names over the columns of `b`, their baseline at `y`.
    fn draw_headings<DB: DrawingBackend>(
        &self,
        body: &DrawingArea<DB, Shift>,
        b: Block,
        y: u32,
    ) -> Result<(), Fail> {
        let style = TextStyle::from((FONT, TEXT).into_font());
        for (s, name) in self.scheme_labels.iter().enumerate() {
            let x = b.x + s as u32 * (b.pw + b.gap) + b.pw / 2;
            body.draw(&Text::new(
                name.clone(),
                (x as i32, y as i32),
                style.pos(Pos::new(HPos::Center, VPos::Bottom)),
            ))?;
        }
        Ok(())
    }

    /// Two columns: three blocks side by side, one per quantity, each under its title and the
    /// schemes' headings, with its colour bar across under it; γ and the y ticks left of the
    /// first block's rows, the height's name over them, z labels under each block's first
    /// column. Panels to scale.
    fn draw_double<DB: DrawingBackend>(&self, body: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let pw = double_panel_w();
        let ph = (f64::from(pw) * PANEL_RATIO).round() as u32;
        let half = 0.5 * 110.0 * f64::from(ph) / f64::from(pw);
        let style = TextStyle::from((FONT, TEXT).into_font());
        // The blocks' titles at every figure's panel-title size (eighth review, R8-X-3: 10.5 pt).
        let title = TextStyle::from((FONT, PANEL_TITLE).into_font());
        for (q, (name, scale)) in BLOCK_NAMES.iter().zip(&self.scales).enumerate() {
            let b = Block {
                x: Y_NAME + ROW_LABEL + q as u32 * (3 * pw + 2 * GAP + BLOCK_GAP),
                top: BLOCK_TITLE + HEADINGS,
                pw,
                ph,
                gap: GAP,
                row_gap: ROW_GAP,
            };
            body.draw(&Text::new(
                *name,
                ((b.x + b.width() / 2) as i32, 2),
                title.pos(Pos::new(HPos::Center, VPos::Top)),
            ))?;
            self.draw_headings(body, b, b.top - 2)?;
            if q == 0 {
                // The height's name over its ticks' column, level with the schemes' names (the
                // sixth review, R6-zhang-fig3-4: turned beside the turned "γ = 60°" it read as
                // one label "height y γ = 60°").
                body.draw(&Text::new(
                    "height y",
                    ((b.x - 4) as i32, (b.top - 2) as i32),
                    style.pos(Pos::new(HPos::Right, VPos::Bottom)),
                ))?;
            }
            let row_label = if q == 0 { ROW_LABEL } else { 0 };
            self.draw_block(
                body,
                q,
                b,
                (row_label, half, -40.0, 40.0),
                &|a| a.to_string(),
                &[0, 1, 2],
                &[0],
                Some(0),
            )?;
            let bar_top = b.top + b.height() + X_LABELS + 6;
            let bar = body.clone().shrink((b.x, bar_top), (b.width(), BAR));
            draw_colour_bar_across(&bar, scale)?;
        }
        Ok(())
    }

    /// One column: the three blocks stacked under one row of the schemes' headings, each under
    /// its title with its colour bar upright beside it (its name turned, reading upwards);
    /// γ (the light–view angle, Zhang's θ) turned left of each row with the y ticks ±30; the
    /// depth's ticks under every column of the last block, named under the middle one. The panels
    /// are as wide as the column allows and as high as the page's 420 pt allow, so that
    /// their heights are drawn at about half the scale of their depths (the y ticks say so).
    fn draw_single<DB: DrawingBackend>(&self, body: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let (w, h) = body.dim_in_pixel();
        let pw = (w.saturating_sub(Y_NAME + ROW_LABEL_1 + 2 * GAP_1 + VBAR + 4)) / 3;
        let fixed = HEADINGS + 3 * (BLOCK_TITLE_1 + 2 * ROW_GAP_1) + 2 * BLOCK_GAP_1 + X_LABELS;
        // Heights at exactly half the scale of depths (the caption and the axis' name say so;
        // the fifth review: "about half", unstated): the panel half as high as to scale, or
        // lower where the page has not the room.
        let ph = ((f64::from(pw) * PANEL_RATIO * HEIGHT_SCALE).round() as u32)
            .min(h.saturating_sub(fixed) / 9);
        // Where the page's height, not the width, sets the panels: as wide as half scale asks.
        let pw = pw.min((f64::from(ph) / (PANEL_RATIO * HEIGHT_SCALE)).round() as u32);
        // The frustum's height ±57.7 within ±58.85, as in two columns, over a panel drawn at
        // ph / (pw · PANEL_RATIO) of the depth's scale.
        let half = 0.5 * 110.0 * PANEL_RATIO;
        let style = TextStyle::from((FONT, TEXT).into_font());
        let title = TextStyle::from((FONT, PANEL_TITLE).into_font());
        let pitch = BLOCK_TITLE_1 + 3 * ph + 2 * ROW_GAP_1 + BLOCK_GAP_1;
        for (q, (name, scale)) in SINGLE_BLOCK_NAMES.iter().zip(&self.scales).enumerate() {
            let b = Block {
                x: Y_NAME + ROW_LABEL_1,
                top: HEADINGS + q as u32 * pitch + BLOCK_TITLE_1,
                pw,
                ph,
                gap: GAP_1,
                row_gap: ROW_GAP_1,
            };
            if q == 0 {
                self.draw_headings(body, b, HEADINGS - 2)?;
                // The row labels' column: γ turned over its values.
                body.draw(&Text::new(
                    "γ",
                    ((Y_NAME + 7) as i32, HEADINGS as i32 - 2),
                    style.pos(Pos::new(HPos::Center, VPos::Bottom)),
                ))?;
            }
            body.draw(&Text::new(
                *name,
                (
                    (b.x + b.width() / 2) as i32,
                    (b.top - BLOCK_TITLE_1 + 2) as i32,
                ),
                title.pos(Pos::new(HPos::Center, VPos::Top)),
            ))?;
            if q == 1 {
                draw_height_name(body, "height y (drawn at ½ the scale of z)", b)?;
            }
            let last = q + 1 == self.scales.len();
            let under: &[usize] = if last { &[0, 1, 2] } else { &[] };
            self.draw_block(
                body,
                q,
                b,
                (ROW_LABEL_1, half, -40.0, 80.0),
                &|a| a.trim_start_matches("γ = ").to_string(),
                // The y ticks' numbers, ±40, on each block's middle row only (the sixth review,
                // R6-zhang-fig3-3: ±30 on all nine rows, 2.7 pt apart, read as one column of
                // numbers); the other rows' ticks unlabelled (R7-Z3-2).
                &[1],
                under,
                Some(1),
            )?;
            // The bar as tall as the block's rows (its chart keeps 30 units at each end).
            let bar = body.clone().shrink(
                (w - VBAR, b.top.saturating_sub(30)),
                (VBAR, b.height() + 60),
            );
            // Named without "(log scale)" (its powers of ten say it): the turned names of the
            // lower blocks' bars, as long as their rows with heights at half scale, ran together.
            let mut scale = scale.clone();
            scale.axis.label = QUANTITIES[q].to_string();
            draw_colour_bar(&bar, &scale)?;
        }
        Ok(())
    }
}

/// The one-column page's height, in units (420 pt printed, the cap): the panels' rows at
/// [`HEIGHT_SCALE`] and the caption's five lines.
const SINGLE_H: u32 = 495;

/// The share of the depth's scale at which one column draws heights: one half.
const HEIGHT_SCALE: f64 = 0.5;

/// The height's axis name `name`, turned (reading upwards), in the [`Y_NAME`] strip at the
/// page's left, centred on the rows of block `b` (the fifth review: "height y" stood in the
/// row of scheme names, read as a column heading).
fn draw_height_name<DB: DrawingBackend>(
    body: &DrawingArea<DB, Shift>,
    name: &str,
    b: Block,
) -> Result<(), Fail> {
    let style = TextStyle::from((FONT, TEXT).into_font())
        .transform(FontTransform::Rotate270)
        .pos(Pos::new(HPos::Center, VPos::Center));
    body.draw(&Text::new(
        name.to_string(),
        ((Y_NAME / 2) as i32 - 2, (b.top + b.height() / 2) as i32),
        style,
    ))?;
    Ok(())
}

/// The blocks' titles.
/// m_z and m_x are measured across the light, as Lloyd 2006 §4.4 and
/// [`crate::measure::point_error`] do (figure review 6: Barroso's m_z, along the view axis, is
/// 1/sin γ larger, and barroso-fig7 also writes m_z); the captions say so (the titles' "(⊥
/// light)" was unexplained: the seventh review, R7-Z3-1).
const BLOCK_NAMES: [&str; 3] = ["(a) E_p = 2 m_z", "(b) E_q = 2 m_x", "(c) E_p × E_q"];

/// One column's: the caption's five lines have no room to say what E_p and E_q are, which the
/// two-column caption says, so the titles do (the fourteenth review, R14-Z3-1).
const SINGLE_BLOCK_NAMES: [&str; 3] = [
    "(a) E_p = 2 m_z, along screen y",
    "(b) E_q = 2 m_x, along screen x",
    "(c) E_p × E_q",
];

impl Figure for Fig3 {
    fn size(&self) -> (u32, u32) {
        SIZE
    }

    /// One column: the three blocks stacked.
    fn single_size(&self) -> Option<(u32, u32)> {
        Some((Column::Single.width(), SINGLE_H))
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let single = column() == Column::Single;
        let (title, caption) = if single {
            (
                "Side views of the aliasing error",
                self.single_caption.as_str(),
            )
        } else {
            (
                "Side views of the aliasing error inside the view frustum",
                self.caption.as_str(),
            )
        };
        let body = frame(root, title, &[caption])?;
        if single {
            self.draw_single(&body)
        } else {
            self.draw_double(&body)
        }
    }
}

#[cfg(test)]
#[path = "zhang_tests.rs"]
mod tests;
