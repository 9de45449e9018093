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
    let caption = format!(
        "Zhang et al. 2009, Fig. 3: n\u{a0}=\u{a0}{n}, f\u{a0}=\u{a0}{f}, half field of \
         view θ\u{a0}=\u{a0}{phi:.0}° (Zhang's φ); light above and in front at \
         γ\u{a0}=\u{a0}{} from the view direction (Zhang's θ). The factor 2: Zhang's screen \
         and map span [−1,\u{a0}1]. LiSPSM's warp parameter \
         n′\u{a0}=\u{a0}(n\u{a0}+\u{a0}√(fn))/sin\u{a0}γ (Zhang's λ): {}; TSM: \
         80\u{a0}% rule, δ\u{a0}=\u{a0}{TSM_FOCUS}. Unlike the paper, a bar per quantity, \
         no scene insets.",
        angles.join(", "),
        lispsm.join(", "),
    );
    let single_caption = format!(
        "Zhang et al. 2009, Fig. 3: n\u{a0}=\u{a0}{n}, f\u{a0}=\u{a0}{f}, half field of \
         view θ\u{a0}=\u{a0}{phi:.0}°; light above and in front at γ\u{a0}=\u{a0}{} from the \
         view direction. The factor 2: Zhang's screen and map span [−1,\u{a0}1]. TSM: \
         80\u{a0}% rule, δ\u{a0}=\u{a0}{TSM_FOCUS}.",
        angles.join(", "),
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
const BLOCK_TITLE_1: u32 = 17;
const BLOCK_GAP_1: u32 = 6;
const VBAR: u32 = 78;
/// A double-column panel's height over its width: the z range [−5, 105] across and y over
/// ±0.535 of it up (the frustum's far plane reaches ±57.7), drawn to scale.
const PANEL_RATIO: f64 = 1.07;
/// The size of the figure's text (labels, ticks, headings), in both layouts.
const TEXT: u32 = 13;

/// The page's size: three blocks of 3 × 3 panels side by side (landscape drawing), the caption
/// under them; as tall as the blocks, their bars and the caption need.
pub(super) const SIZE: (u32, u32) = (520, 440);

/// A double-column panel's width: the body (the page less 6 units each side) less the left
/// strips, the gaps, shared by nine panels.
const fn double_panel_w() -> u32 {
    (SIZE.0 - 12 - ROW_LABEL - 6 * GAP - 2 * BLOCK_GAP) / 9
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
    /// first column's panels carry γ (`row_name` of it) and the y ticks from `y_first` every
    /// `y_step`; the rows of
    /// `z_under` columns of the last row the depth's ticks, the `z_named` one its name.
    #[allow(clippy::too_many_arguments)]
    fn draw_block<DB: DrawingBackend>(
        &self,
        body: &DrawingArea<DB, Shift>,
        q: usize,
        b: Block,
        (row_label, half, y_first, y_step): (u32, f64, f64, f64),
        row_name: &dyn Fn(&str) -> String,
        z_under: &[usize],
        z_named: Option<usize>,
    ) -> Result<(), Fail> {
        let z = Axis::every("z (eye depth)", -5.0, 105.0, 500.0, 1000.0);
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
                let y = if labelled {
                    Axis::every(row_name(&self.row_angles[r]), -half, half, y_first, y_step)
                } else {
                    Axis::every("", -half, half, 500.0, 1000.0)
                };
                let x = if last_row && z_named == Some(s) {
                    &z
                } else {
                    &blank
                };
                let mut chart = build_chart_styled(&cell, "", x, &y, false, &style)?;
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
                    draw_z_labels(&cell, &chart, -half)?;
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
        for (q, (name, scale)) in BLOCK_NAMES.iter().zip(&self.scales).enumerate() {
            let b = Block {
                x: ROW_LABEL + q as u32 * (3 * pw + 2 * GAP + BLOCK_GAP),
                top: BLOCK_TITLE + HEADINGS,
                pw,
                ph,
                gap: GAP,
                row_gap: ROW_GAP,
            };
            body.draw(&Text::new(
                *name,
                ((b.x + b.width() / 2) as i32, 2),
                style.pos(Pos::new(HPos::Center, VPos::Top)),
            ))?;
            self.draw_headings(body, b, b.top - 2)?;
            if q == 0 {
                body.draw(&Text::new(
                    "height y",
                    (b.x as i32 - 2, (b.top - 2) as i32),
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
        let pw = (w.saturating_sub(ROW_LABEL_1 + 2 * GAP_1 + VBAR + 4)) / 3;
        let fixed = HEADINGS + 3 * (BLOCK_TITLE_1 + 2 * ROW_GAP_1) + 2 * BLOCK_GAP_1 + X_LABELS;
        let ph = h.saturating_sub(fixed) / 9;
        // The frustum's height ±57.7 within ±58.85, as in two columns.
        let half = 0.5 * 110.0 * PANEL_RATIO;
        let style = TextStyle::from((FONT, TEXT).into_font());
        let pitch = BLOCK_TITLE_1 + 3 * ph + 2 * ROW_GAP_1 + BLOCK_GAP_1;
        for (q, (name, scale)) in BLOCK_NAMES.iter().zip(&self.scales).enumerate() {
            let b = Block {
                x: ROW_LABEL_1,
                top: HEADINGS + q as u32 * pitch + BLOCK_TITLE_1,
                pw,
                ph,
                gap: GAP_1,
                row_gap: ROW_GAP_1,
            };
            if q == 0 {
                self.draw_headings(body, b, HEADINGS - 2)?;
                // The row labels' column: γ turned, then the height's ticks.
                for (text, x) in [("γ", 7), ("y", ROW_LABEL_1 as i32 - 12)] {
                    body.draw(&Text::new(
                        text,
                        (x, HEADINGS as i32 - 2),
                        style.pos(Pos::new(HPos::Center, VPos::Bottom)),
                    ))?;
                }
            }
            body.draw(&Text::new(
                *name,
                (
                    (b.x + b.width() / 2) as i32,
                    (b.top - BLOCK_TITLE_1 + 2) as i32,
                ),
                style.pos(Pos::new(HPos::Center, VPos::Top)),
            ))?;
            let last = q + 1 == self.scales.len();
            let under: &[usize] = if last { &[0, 1, 2] } else { &[] };
            self.draw_block(
                body,
                q,
                b,
                (ROW_LABEL_1, half, -30.0, 60.0),
                &|a| a.trim_start_matches("γ = ").to_string(),
                under,
                Some(1),
            )?;
            // The bar as tall as the block's rows (its chart keeps 30 units at each end).
            let bar = body.clone().shrink(
                (w - VBAR, b.top.saturating_sub(30)),
                (VBAR, b.height() + 60),
            );
            draw_colour_bar(&bar, scale)?;
        }
        Ok(())
    }
}

/// The blocks' titles.
const BLOCK_NAMES: [&str; 3] = ["(a) E_p = 2 m_z", "(b) E_q = 2 m_x", "(c) E_p × E_q"];

impl Figure for Fig3 {
    fn size(&self) -> (u32, u32) {
        SIZE
    }

    /// One column: the three blocks stacked.
    fn single_size(&self) -> Option<(u32, u32)> {
        Some((Column::Single.width(), 524))
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
mod tests {
    use super::*;
    use crate::analytic::global::{zhang_ep, zhang_eq};
    use crate::LightAngle;

    /// The measured side view at γ = 90° and 60° (LiSPSM row) equals Zhang's global
    /// representation (Eq 13, 14 with the corrected Appendix, `analytic::global`) at every
    /// cell centre inside the frustum; E_p × E_q is their product.
    /// A horizontal colour bar is one embedded image (abutting rectangles left seams, issue
    /// 25), its lowest band at the left and its highest at the right.
    #[test]
    fn colour_bar_is_one_seamless_raster() {
        use super::super::chart::read_svg::{draw_svg, embedded_images};
        use super::super::chart::SMOOTH_LEVELS;
        let scale = ColourScale::smooth(Axis::log10("E", 2.0, 16400.0));
        let svg = draw_svg((160, BAR), |area| {
            draw_colour_bar_across(area, &scale).unwrap()
        });
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
        // The depth's "100", not a bar's 10⁰ (read as 100 with its raised 0).
        let hundreds: Vec<&(&str, String, f64)> = all
            .iter()
            .filter(|x| x.1 == "100" && !x.0.contains("<tspan"))
            .collect();
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

    /// The colour bars are ticked at whole powers of ten, in both layouts (review X3: they
    /// read 0.04, 1, 25 and 1, 125, 15625, powers of 5), and each bar's range holds every
    /// value of its nine panels, its ends whole decades (review: SSM's E_p at the apex,
    /// (f − n)/(n tan φ) = 99/tan 30° = 171.5 by Zhang's Eq 9, stood above the top tick of
    /// (a)'s bar, its end unlabelled): read back from both SVGs, every number written is a
    /// power of ten 10<sup>n</sup> or one of the axes' 0, ±40 (two columns), ±30 (one), 100;
    /// E_p's bar reaches 10³ ≥ 171.5.
    #[test]
    fn colour_bars_are_ticked_at_powers_of_ten_and_hold_every_value() {
        use super::super::chart::read_svg::texts;
        let fig = fig3().map_err(|e| e.named("zhang-fig3")).unwrap();
        for (q, scale) in fig.scales.iter().enumerate() {
            let (lo, hi) = scale.axis.range();
            let whole = |a: f64| (a - a.round()).abs() < 1e-9;
            assert!(whole(lo) && whole(hi), "{q}: {lo} {hi}");
            for row in &fig.rows {
                for scheme in row {
                    for v in scheme[q].grid.values.iter().flatten() {
                        let a = v.log10();
                        assert!(a >= lo - 1e-9 && a <= hi + 1e-9, "{q}: {v} outside");
                    }
                }
            }
        }
        let apex = 99.0 / 30f64.to_radians().tan();
        assert!((apex - 171.47).abs() < 0.01);
        assert!(10f64.powf(fig.scales[0].axis.range().1) >= apex);
        for column in [Column::Double, Column::Single] {
            let svg = super::super::hemisphere::svg_in(&fig, column);
            let mut powers = 0;
            for (line, text, _) in texts(&svg) {
                if !text.chars().any(|c| c.is_ascii_digit())
                    || text.chars().any(|c| c.is_alphabetic() || c == '°')
                {
                    continue;
                }
                if line.contains(">10<tspan dy=\"-") {
                    let exp = text.trim_start_matches("10").replace('−', "-");
                    assert!(exp.parse::<i32>().is_ok(), "{column:?}: {text}");
                    powers += 1;
                } else {
                    assert!(
                        ["0", "40", "−40", "30", "−30", "100"].contains(&text.as_str()),
                        "{column:?}: {text} is no power of ten"
                    );
                }
            }
            assert!(powers >= 9, "{column:?}: {powers} powers of ten");
        }
    }

    /// One column keeps the text of the other figures' one-column forms (review X9: the angle
    /// and "z (eye depth)" were 8.871 units, 7.1 pt printed, against 10.48, 8.4 pt): read from
    /// its SVG, no text of the figure is set smaller than 10.48 units but its sub- and
    /// superscripts; the captions give the light–view angle's values as γ, the crate's symbol
    /// (the fourth review: Zhang's θ clashed with the other figures' half field of view θ),
    /// and say what θ is (X2); the two-column one names Zhang's symbols and defines the n′ it
    /// prints (review: λ undefined), and both explain the factor 2 of E_p = 2 m_z.
    #[test]
    fn one_column_text_is_full_size_and_the_caption_defines_its_symbols() {
        use super::super::chart::read_svg::attr;
        let fig = fig3().map_err(|e| e.named("zhang-fig3")).unwrap();
        let svg = super::super::hemisphere::svg_in(&fig, Column::Single);
        let smallest = svg
            .lines()
            .filter(|l| l.starts_with("<text"))
            .filter_map(|l| attr(l, "font-size"))
            .fold(f64::INFINITY, f64::min);
        assert!(smallest >= 10.48, "{smallest}");
        for c in [&fig.caption, &fig.single_caption] {
            assert!(
                c.contains("γ\u{a0}=\u{a0}90°, 60°, 30° from the view direction"),
                "{c}"
            );
            assert!(c.contains("half field of view θ\u{a0}=\u{a0}30°"), "{c}");
            assert!(c.contains("span [−1,\u{a0}1]"), "{c}");
            assert!(!c.contains("π/6"), "{c}");
            assert_eq!(
                c.matches('θ').count(),
                1 + c.matches("Zhang's θ").count(),
                "{c}"
            );
        }
        for symbol in [
            "(Zhang's φ)",
            "(Zhang's θ)",
            "warp parameter n′",
            "(Zhang's λ)",
        ] {
            assert!(fig.caption.contains(symbol), "{symbol}: {}", fig.caption);
        }
        assert_eq!(fig.caption.matches('λ').count(), 1, "{}", fig.caption);
    }

    #[test]
    fn lispsm_cells_equal_zhangs_global_representation() {
        let fig = fig3().map_err(|e| e.named("zhang-fig3")).unwrap();
        let view = ViewFrustum::new(1.0, 100.0, FRAC_PI_6).unwrap();
        for (r, theta_deg) in [(0usize, 90.0f64), (1, 60.0)] {
            let theta = LightAngle::new(theta_deg.to_radians()).unwrap();
            // LiSPSM's n′ (Zhang's λ) = (n + √(fn))/sin γ.
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
