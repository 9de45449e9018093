//! The view frustum as seen from the light, with its z-partitions: Barroso & Celes 2007 Fig 5
//! (a light above and in front, self-similar partitions of their Eq 5 and the adaptive ones of
//! their Eq 19) and Lloyd et al. 2006 Fig 11 (the light behind the viewer: the frustum looks
//! square, the near face inside the far one, and the side faces are trapezoids).
//!
//! The frustum's edges and the split planes' cross-sections are projected along the light with
//! the crate's light space ([`crate::maps::light_space`], the view direction as its axis); the
//! split depths come from [`crate::analytic::partition::z_splits`]. Each partition's orthographic
//! map (ZP) is the light-space bounding rectangle of its corners, drawn dashed, so that the
//! overlap of the maps shows.

use super::chart::column;
use super::chart::{
    boxed_text, build_chart_styled, clip_polyline, equal_aspect, frame, Axis, ChartStyle, FONT,
    PALETTE,
};
use super::{Column, Fail, Figure};
use crate::analytic::partition::{z_splits, SplitScheme};
use crate::maps::light_space;
use crate::scheme::ADAPTIVE_RATIO;
use crate::ViewFrustum;
use glam::{DVec2, DVec3};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// One panel: a light, its split depths and what it shows.
pub(super) struct Panel {
    pub title: String,
    /// Cross-sections of the frustum at each split depth (4 light-space corners each), near first.
    pub sections: Vec<[DVec2; 4]>,
    /// Each partition's bounding rectangle in light space (min, max).
    pub maps: Vec<(DVec2, DVec2)>,
    pub planes: Vec<f64>,
    /// The light-space window shown (min, max); `None`: the whole frustum.
    pub window: Option<(DVec2, DVec2)>,
    /// Each split plane's label (its depth z by default).
    pub plane_labels: Vec<String>,
    /// Dimension lines: from, to, the label (centred under the line).
    pub dims: Vec<(DVec2, DVec2, String)>,
    /// Extension lines from the measured feature to its dimension line.
    pub extensions: Vec<[DVec2; 2]>,
}

pub(super) struct FromLight {
    pub title: &'static str,
    pub caption: String,
    /// The caption of the one-column layout (at most five lines 300 units wide).
    pub single_caption: String,
    pub panels: Vec<Panel>,
    pub size: (u32, u32),
    /// The size of the one-column layout.
    pub single_size: (u32, u32),
}

/// The cross-section of the (square) view frustum at eye depth z, projected along the light.
fn section(view: &ViewFrustum, to: &impl Fn(DVec3) -> DVec2, z: f64) -> [DVec2; 4] {
    let t = view.tan_half_fov();
    let s = z * t;
    [
        to(DVec3::new(-s, -s, -z)),
        to(DVec3::new(s, -s, -z)),
        to(DVec3::new(s, s, -z)),
        to(DVec3::new(-s, s, -z)),
    ]
}

fn panel(view: &ViewFrustum, light: DVec3, planes: &[f64], title: String) -> Result<Panel, Fail> {
    let ls = light_space(light, DVec3::NEG_Z)?;
    let to = |p: DVec3| seen_from_light(ls.to_light(p));
    let sections: Vec<[DVec2; 4]> = planes.iter().map(|&z| section(view, &to, z)).collect();
    let maps = sections
        .windows(2)
        .map(|w| {
            let pts = w[0].iter().chain(&w[1]);
            let lo = pts
                .clone()
                .fold(DVec2::splat(f64::INFINITY), |a, &p| a.min(p));
            let hi = pts.fold(DVec2::splat(f64::NEG_INFINITY), |a, &p| a.max(p));
            (lo, hi)
        })
        .collect();
    Ok(Panel {
        title,
        sections,
        maps,
        plane_labels: planes.iter().map(|&z| fmt_planes(&[z])).collect(),
        planes: planes.to_vec(),
        window: None,
        dims: Vec::new(),
        extensions: Vec::new(),
    })
}

/// A light-space point as the light sees it: `(−x, z)`, right and up in the light's view.
///
/// Light space's `x = y × z` with `y` toward the light, so an observer at the light looking
/// along `−y` with `z` up has `z × y = −x` on their right: drawing `x` to the right would show
/// the mirror image (figure review 2). Every diagram "seen from the light" draws this.
pub(super) fn seen_from_light(l: DVec3) -> DVec2 {
    DVec2::new(-l.x, l.z)
}

/// The label of the horizontal axis of a diagram drawn by [`seen_from_light`].
pub(super) const SEEN_X: &str = "light −x";

/// Depths to 4 significant figures, trailing zeros dropped (31.62, 3.162, 1, 100).
/// The light-space bounding box (min, max) of some cross-sections.
fn bounds(sections: &[[DVec2; 4]]) -> (DVec2, DVec2) {
    sections.iter().flatten().fold(
        (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
        |(lo, hi), &p| (lo.min(p), hi.max(p)),
    )
}

fn fmt_planes(p: &[f64]) -> String {
    p.iter()
        .map(|&z| {
            let digits = 3 - z.abs().max(1e-300).log10().floor().clamp(-20.0, 3.0) as i32;
            let d = digits.max(0) as usize;
            let s = format!("{z:.d$}");
            if s.contains('.') {
                s.trim_end_matches('0').trim_end_matches('.').to_string()
            } else {
                s
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// Barroso & Celes 2007 Fig 5: k = 4 self-similar z-partitions (Eq 5) of n = 1, f = 100,
/// φ = 30°, seen by (a) a light perpendicular to the view direction (overhead) and (b) one
/// parallel to it (behind the viewer); (c) the adaptive partitions of Eq 19 for a light 45°
/// above the view direction, which the paper's figure does not have; (d) the near partitions of
/// (a) enlarged.
pub(super) fn barroso_fig5() -> Result<FromLight, Fail> {
    let view = ViewFrustum::new(1.0, 100.0, 30f64.to_radians())?;
    let k = 4;
    let ss = z_splits(view.near(), view.far(), k, SplitScheme::SelfSimilar)?;
    let gamma = 45f64.to_radians();
    let ad = z_splits(
        view.near(),
        view.far(),
        k,
        SplitScheme::Adaptive {
            light_angle: gamma,
            ratio: ADAPTIVE_RATIO,
        },
    )?;
    // Light directions are the direction light travels; the view looks down −Z.
    let overhead = DVec3::NEG_Y;
    let behind = DVec3::NEG_Z;
    let tilted = DVec3::new(0.0, -gamma.sin(), -gamma.cos());
    let perpendicular = panel(
        &view,
        overhead,
        ss.planes(),
        "(a) perpendicular light".into(),
    )?;
    // (d): the two nearest partitions of (a), enlarged.
    let (lo, hi) = bounds(&perpendicular.sections[..3]);
    let mut zoom = panel(
        &view,
        overhead,
        ss.planes(),
        "(d) detail of (a): z ≤ 10".into(),
    )?;
    zoom.window = Some((lo, hi));
    let parallel = panel(&view, behind, ss.planes(), "(b) parallel light".into())?;
    let eq19 = panel(
        &view,
        tilted,
        ad.planes(),
        "(c) Eq 19, not in the paper".into(),
    )?;
    // (e), (f): (b) and (c) near the eye, where their inner partitions are sub-pixel or their
    // maps overlap in a tangle (figure review 2): the windows round the nearest three and four
    // planes (z ≤ 10 and z ≤ 40.81).
    let mut zoom_b = panel(
        &view,
        behind,
        ss.planes(),
        "(e) detail of (b): z ≤ 10".into(),
    )?;
    zoom_b.window = Some(bounds(&parallel.sections[..3]));
    let mut zoom_c = panel(
        &view,
        tilted,
        ad.planes(),
        format!("(f) detail of (c): z ≤ {}", fmt_planes(&ad.planes()[3..4])),
    )?;
    zoom_c.window = Some(bounds(&eq19.sections[..4]));
    let panels = vec![perpendicular, parallel, eq19, zoom, zoom_b, zoom_c];
    let caption = format!(
        "Barroso & Celes 2007, Fig. 5: the frustum seen from the light, k = {k} \
         z-partitions, n = {n}, f = {f}, φ = {phi:.0}°. (a) Light perpendicular to the view, (b) \
         parallel: Eq 5's self-similar partitions, z = {}. (c), not in the paper: Eq 19's adaptive \
         ones for a light {gamma_deg:.0}° from the view (α = {ADAPTIVE_RATIO}), z = {}. (d)–(f) \
         enlarge (a)–(c) near the eye. Dashed and dotted: the maps.",
        fmt_planes(ss.planes()),
        fmt_planes(ad.planes()),
        n = view.near(),
        f = view.far(),
        phi = view.half_fov().to_degrees(),
        gamma_deg = gamma.to_degrees(),
    );
    let single_caption = format!(
        "Barroso & Celes 2007, Fig. 5: k = {k} z-partitions, n = {n}, f = {f}, φ = {phi:.0}°. \
         (a) Light perpendicular, (b) parallel: Eq 5. (c) Eq 19 (not in the paper), light at \
         {gamma_deg:.0}°, α = {ADAPTIVE_RATIO}. (d)–(f) enlarge (a)–(c). Dashed, dotted: maps.",
        n = view.near(),
        f = view.far(),
        phi = view.half_fov().to_degrees(),
        gamma_deg = gamma.to_degrees(),
    );
    Ok(FromLight {
        title: "The view frustum seen from the light, with z-partitions",
        caption,
        single_caption,
        panels,
        size: (520, 640),
        single_size: (300, 600),
    })
}

/// Lloyd et al. 2006 Fig 11: the light behind the viewer, k = 3 self-similar partitions.
pub(super) fn lloyd2006_fig11() -> Result<FromLight, Fail> {
    let view = ViewFrustum::new(1.0, 8.0, 30f64.to_radians())?;
    let k = 3;
    let ss = z_splits(view.near(), view.far(), k, SplitScheme::SelfSimilar)?;
    // The light travels along the view direction (−Z): it is behind the viewer.
    // No panel title: the figure's title says it.
    let mut p = panel(&view, DVec3::NEG_Z, ss.planes(), String::new())?;
    // The paper's labels: the near and far planes by name, the middle ones by depth, and the
    // near and far faces' sides 2n tan θ and 2f tan θ as dimension lines under them.
    let last = p.planes.len() - 1;
    for (i, label) in p.plane_labels.iter_mut().enumerate() {
        let z = fmt_planes(&[p.planes[i]]);
        *label = match i {
            0 => format!("n = {z}"),
            i if i == last => format!("f = {z}"),
            _ => format!("z = {z}"),
        };
    }
    let (sn, sf) = (
        view.near() * view.tan_half_fov(),
        view.far() * view.tan_half_fov(),
    );
    // The near face's dimension line lies in the band between the planes z = 2 and z = 4,
    // carried there by extension lines from the face's corners, so that its label covers no
    // line (issue 25: under the face it sat on the frustum's edges and the nearest map).
    let near_dim = -1.35;
    p.extensions = vec![
        [DVec2::new(-sn, -sn), DVec2::new(-sn, near_dim)],
        [DVec2::new(sn, -sn), DVec2::new(sn, near_dim)],
    ];
    p.dims = vec![
        (
            DVec2::new(-sn, near_dim),
            DVec2::new(sn, near_dim),
            "2n tan θ".into(),
        ),
        (
            DVec2::new(-sf, -sf - 0.35),
            DVec2::new(sf, -sf - 0.35),
            "2f tan θ".into(),
        ),
    ];
    p.window = Some((DVec2::new(-sf, -sf - 1.2), DVec2::new(sf, sf)));
    let caption = format!(
        "Lloyd et al. 2006, Fig. 11: the frustum seen from a light behind the viewer, \
         n = {n}, f = {f}, θ = {theta:.0}°, to scale. With \
         k = {k} self-similar z-partitions (planes {}) each map (dashed) is the square of its far \
         plane, so the nearer maps lie inside the farther ones: the overlap §5.3 blames for ZP's \
         growth behind. The paper's sketch writes the sides 2n and 2f, their values at θ = 45°.",
        fmt_planes(p.planes.as_slice()),
        n = view.near(),
        f = view.far(),
        theta = view.half_fov().to_degrees(),
    );
    let single_caption = format!(
        "Lloyd et al. 2006, Fig. 11: from a light behind the viewer, n = {n}, f = {f}, \
         θ = {theta:.0}°, k = {k} self-similar z-partitions. Each map (dashed) is the square of \
         its far plane, so the nearer maps lie inside the farther ones.",
        n = view.near(),
        f = view.far(),
        theta = view.half_fov().to_degrees(),
    );
    Ok(FromLight {
        title: "The view frustum seen from a light behind the viewer",
        caption,
        single_caption,
        panels: vec![p],
        size: (520, 480),
        single_size: (300, 450),
    })
}

/// A panel's title up to its first colon or comma, without the word "light": "(c) Eq 19,
/// not in the paper" is "(c) Eq 19", "(a) perpendicular light" is "(a) perpendicular".
fn short_title(t: &str) -> String {
    let cut = t.find([':', ',']).unwrap_or(t.len());
    t[..cut].trim_end_matches(" light").to_string()
}

/// The width of the gutter right of each panel that holds the split planes' labels.
const GUTTER: u32 = 50;

/// Each partition's map outline: dash and gap lengths in units, by partition (nearest first).
/// The map colours print as nearly one grey (CIE L* 46, 54, 58, 61 for blue, vermillion, green,
/// pink), so each map also has its own dash: long, dotted, longest, short.
pub(super) const DASHES: [(u32, u32); 4] = [(8, 4), (2, 3), (16, 4), (4, 4)];

/// The least vertical distance between two labels in the gutter, in pixels.
const LABEL_STEP: i32 = 16;

/// The labels' heights (backend pixels, `wanted`, any order) moved apart so that neighbours are
/// at least `step` apart, each as close to its wanted height as that allows, all within
/// `range` (relative to `base`, the gutter's top): the wanted heights are clamped, then pushed
/// down from the top and back up from the bottom.
fn spread(wanted: &[i32], step: i32, range: (i32, i32), base: i32) -> Vec<i32> {
    let mut order: Vec<usize> = (0..wanted.len()).collect();
    order.sort_by_key(|&i| wanted[i]);
    let (lo, hi) = (base + range.0, base + range.1);
    let mut ys: Vec<i32> = order.iter().map(|&i| wanted[i].clamp(lo, hi)).collect();
    for k in 1..ys.len() {
        ys[k] = ys[k].max(ys[k - 1] + step);
    }
    for k in (0..ys.len()).rev() {
        let cap = if k + 1 < ys.len() {
            ys[k + 1] - step
        } else {
            hi
        };
        ys[k] = ys[k].min(cap);
    }
    let mut out = vec![0; wanted.len()];
    for (k, &i) in order.iter().enumerate() {
        out[i] = ys[k];
    }
    out
}

impl Figure for FromLight {
    fn size(&self) -> (u32, u32) {
        self.size
    }

    fn single_size(&self) -> Option<(u32, u32)> {
        Some(self.single_size)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let single = column() == Column::Single;
        let caption = if single {
            &self.single_caption
        } else {
            &self.caption
        };
        let body = frame(root, self.title, &[caption.as_str()])?;
        // A single panel is drawn about as wide as it is high, centred.
        let body = if self.panels.len() == 1 {
            let (bw, bh) = body.dim_in_pixel();
            let side = (bh + 40 + GUTTER).min(bw);
            body.margin(0, 0, (bw - side) / 2, (bw - side) / 2)
        } else {
            body
        };
        let columns = self.panels.len().min(2);
        let cells = body.split_evenly((self.panels.len().div_ceil(columns), columns));
        // In one column the six-panel figure's panels are 150 units wide: smaller text
        // (10 units, 8 pt printed) and margins.
        let small = single && self.panels.len() > 1;
        let style = if small {
            ChartStyle {
                title_size: 12,
                x_label_area: 34,
                y_label_area: 36,
                tick_size: 10,
                desc_size: 11,
                margin: 4,
            }
        } else {
            ChartStyle {
                y_label_area: 50,
                ..ChartStyle::default()
            }
        };
        let (gutter_w, label_size, label_step) = if small {
            (36, 10, 12)
        } else {
            (GUTTER, 13, LABEL_STEP)
        };
        for (whole, p) in cells.iter().zip(&self.panels) {
            // The split planes' labels go in a gutter right of the plot, where they cover no
            // line (issue 25: at the sections' ends they sat on the frustum's edges and the
            // maps' outlines).
            let (cw, _) = whole.dim_in_pixel();
            let (cell, gutter) = whole.split_horizontally(cw - gutter_w);
            let cell = &cell;
            let (lo, hi) = p.window.unwrap_or_else(|| {
                p.sections.iter().flatten().fold(
                    (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
                    |(lo, hi), &q| (lo.min(q), hi.max(q)),
                )
            });
            let span = (hi - lo).max_element() * 1.12;
            let mid = 0.5 * (lo + hi);
            let (lo, hi) = (
                mid - DVec2::splat(span / 2.0),
                mid + DVec2::splat(span / 2.0),
            );
            // In one column, the titles cut to their first clause ("(c) Eq 19", "(d) detail of
            // (a)"): the full ones are wider than the 150-unit panels.
            let title = if small {
                short_title(&p.title)
            } else {
                p.title.clone()
            };
            // Equal aspect: a light-space unit as long across as up.
            let (xa, ya) = equal_aspect(
                cell,
                &title,
                &Axis::linear(SEEN_X, lo.x, hi.x),
                &Axis::linear("light z", lo.y, hi.y),
                &style,
            )?;
            let mut chart = build_chart_styled(cell, &title, &xa, &ya, false, &style)?;
            let inside =
                |q: DVec2| q.x >= xa.min && q.x <= xa.max && q.y >= ya.min && q.y <= ya.max;
            // Everything clipped to the window (plotters would draw points outside it on the
            // border).
            let bounds = (xa.min, xa.max, ya.min, ya.max);
            let clip = |pts: &[DVec2]| {
                let pts: Vec<Option<(f64, f64)>> = pts.iter().map(|q| Some((q.x, q.y))).collect();
                clip_polyline(&pts, bounds)
            };
            // A map's tint only where the whole map is in the window: a map larger than a
            // detail panel's window would tint its whole background.
            for (i, &(a, b)) in p.maps.iter().enumerate() {
                let c = PALETTE[i % PALETTE.len()];
                let (ca, cb) = (
                    a.max(DVec2::new(xa.min, ya.min)),
                    b.min(DVec2::new(xa.max, ya.max)),
                );
                if ca == a && cb == b && ca.x < cb.x && ca.y < cb.y {
                    chart.draw_series(std::iter::once(Rectangle::new(
                        [(ca.x, ca.y), (cb.x, cb.y)],
                        c.mix(0.08).filled(),
                    )))?;
                }
            }
            let mut solid = |pts: &[DVec2], width: u32| -> Result<(), Fail> {
                for piece in clip(pts) {
                    chart.draw_series(LineSeries::new(piece, BLACK.stroke_width(width)))?;
                }
                Ok(())
            };
            for s in &p.sections {
                solid(&[s[0], s[1], s[2], s[3], s[0]], 1)?;
            }
            let (first, last) = (p.sections[0], p.sections[p.sections.len() - 1]);
            for i in 0..4 {
                solid(&[first[i], last[i]], 2)?;
            }
            // The maps' outlines on top of the frustum's, so that a map whose edge coincides
            // with a cross-section (every map of a light behind) still shows.
            for (i, &(a, b)) in p.maps.iter().enumerate() {
                let c = PALETTE[i % PALETTE.len()];
                let corners = [a, DVec2::new(b.x, a.y), b, DVec2::new(a.x, b.y), a];
                let (dash, gap) = DASHES[i % DASHES.len()];
                for piece in clip(&corners) {
                    chart.draw_series(DashedLineSeries::new(
                        piece,
                        dash,
                        gap,
                        c.stroke_width(2),
                    ))?;
                }
            }
            // Each split plane labelled in the gutter at the height of its cross-section's
            // right end (its top-right corner where two ends tie), marked by a tick on the
            // plot's right edge; labels too close are spread apart, each joined to its tick.
            let mut marks = Vec::new();
            for (sec, label) in p.sections.iter().zip(&p.plane_labels) {
                let right = sec.iter().copied().fold(sec[0], |a, q| {
                    if q.x > a.x || (q.x == a.x && q.y > a.y) {
                        q
                    } else {
                        a
                    }
                });
                let size = sec
                    .iter()
                    .fold(0.0f64, |m, q| m.max((*q - sec[0]).length()));
                if inside(right) && size > 0.06 * (xa.max - xa.min) {
                    marks.push((chart.backend_coord(&(xa.max, right.y)).1, label.clone()));
                }
            }
            // Where the drawing ends on the right: a light leader runs from there to each tick,
            // through empty space.
            let drawn = p
                .sections
                .iter()
                .flatten()
                .map(|q| q.x)
                .chain(p.maps.iter().map(|m| m.1.x))
                .fold(f64::NEG_INFINITY, f64::max)
                .min(xa.max);
            let (gx, gy) = gutter.get_base_pixel();
            let (wx, wy) = whole.get_base_pixel();
            let (_, gh) = gutter.dim_in_pixel();
            let ys = spread(
                &marks.iter().map(|m| m.0).collect::<Vec<_>>(),
                label_step,
                (8, gh as i32 - 8),
                gy,
            );
            let label_style = TextStyle::from((FONT, label_size).into_font())
                .pos(Pos::new(HPos::Left, VPos::Center));
            let grey = RGBColor(90, 90, 90);
            for ((tick_y, label), y) in marks.iter().zip(ys) {
                let ty = tick_y - gy;
                let from = chart.backend_coord(&(drawn, ya.min)).0 + 4;
                if from < gx {
                    whole.draw(&PathElement::new(
                        vec![(from - wx, tick_y - wy), (gx - wx, tick_y - wy)],
                        RGBColor(175, 175, 175).stroke_width(1),
                    ))?;
                }
                gutter.draw(&PathElement::new(
                    vec![(0, ty), (5, ty), (11, y - gy)],
                    grey.stroke_width(1),
                ))?;
                gutter.draw(&Text::new(label.clone(), (13, y - gy), label_style.clone()))?;
            }
            for [from, to] in &p.extensions {
                chart.draw_series(LineSeries::new(
                    [(from.x, from.y), (to.x, to.y)],
                    RGBColor(90, 90, 90).stroke_width(1),
                ))?;
            }
            // Dimension lines: the line with a bar at each end, its label centred below.
            for (a, b, text) in &p.dims {
                let bar = 0.12 * (xa.max - xa.min) / 10.0;
                let n = (*b - *a).perp().normalize_or_zero() * bar;
                for (from, to) in [(*a, *b), (*a - n, *a + n), (*b - n, *b + n)] {
                    chart.draw_series(LineSeries::new(
                        [(from.x, from.y), (to.x, to.y)],
                        BLACK.stroke_width(1),
                    ))?;
                }
                // The label below the bars' ends, with room for its white margin.
                let mid = 0.5 * (*a + *b) - 1.6 * n;
                boxed_text(
                    &mut chart,
                    (mid.x, mid.y),
                    text,
                    Pos::new(HPos::Center, VPos::Top),
                    13,
                    BLACK,
                )?;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Light behind: the cross-sections are centred squares of side 2 z tan θ (Lloyd Fig 11:
    /// 2n and 2f up to the factor tan θ), and each partition's map is the square of its far plane,
    /// so every map contains the nearer ones. Barroso's planes are Eq 5's n (f/n)^{i/k} in (a).
    #[test]
    fn sections_and_planes_by_hand() {
        let fig = lloyd2006_fig11()
            .map_err(|e| e.named("lloyd2006-fig11"))
            .unwrap();
        let p = &fig.panels[0];
        let t = 30f64.to_radians().tan();
        for (s, &z) in p.sections.iter().zip(&p.planes) {
            for c in s {
                assert!((c.x.abs() - z * t).abs() < 1e-9, "{c} at z = {z}");
            }
        }
        for w in p.maps.windows(2) {
            assert!(w[1].0.x <= w[0].0.x + 1e-12 && w[1].1.x >= w[0].1.x - 1e-12);
        }
        let b = barroso_fig5().map_err(|e| e.named("barroso-fig5")).unwrap();
        for (i, &z) in b.panels[0].planes.iter().enumerate() {
            let want = 100f64.powf(i as f64 / 4.0);
            assert!((z - want).abs() < 1e-9 * want, "{z} vs {want}");
        }
        // The paper's panels: (a) light perpendicular to the view (overhead): each split
        // plane's cross-section is seen edge-on, a segment at light depth ∝ z, half as long as
        // 2 z tan φ; (b) light parallel (behind): centred squares of half-side z tan φ.
        let t = 30f64.to_radians().tan();
        for (s, &z) in b.panels[0].sections.iter().zip(&b.panels[0].planes) {
            let ys: Vec<f64> = s.iter().map(|c| c.y).collect();
            let xs: Vec<f64> = s.iter().map(|c| c.x.abs()).collect();
            assert!(
                ys.iter().all(|&y| (y.abs() - z).abs() < 1e-9),
                "{ys:?} at z = {z}"
            );
            assert!(
                xs.iter().all(|&x| (x - z * t).abs() < 1e-9),
                "{xs:?} at z = {z}"
            );
        }
        for (s, &z) in b.panels[1].sections.iter().zip(&b.panels[1].planes) {
            for c in s {
                assert!((c.x.abs() - z * t).abs() < 1e-9 && (c.y.abs() - z * t).abs() < 1e-9);
            }
        }
        assert_eq!(b.panels[0].planes, b.panels[1].planes);
        // (c): the adaptive planes start at n and end at f, and differ from the self-similar
        // ones; (d) is (a) shown in a window around the three nearest planes (z ≤ 10).
        let ad = &b.panels[2].planes;
        assert_eq!((ad[0], ad[4]), (1.0, 100.0));
        assert!((ad[1] - b.panels[0].planes[1]).abs() > 1e-3);
        let (lo, hi) = b.panels[3].window.unwrap();
        assert!(
            (hi.y.abs().max(lo.y.abs()) - 10.0).abs() < 1e-9,
            "{lo} {hi}"
        );
        assert!((hi.x - 10.0 * t).abs() < 1e-9);
    }

    /// Lloyd Fig 11's labels (issue 25): the near and far planes by name and the middle split
    /// planes by depth (self-similar: 1, 2, 4, 8 for f/n = 8, k = 3), and dimension lines as
    /// long as the near and far faces' sides, 2n tan θ = 1.1547 and 2f tan θ = 9.2376 (by hand,
    /// tan 30° = 0.57735), each under its face.
    #[test]
    fn fig11_labels_name_n_f_and_the_faces_sides() {
        let fig = lloyd2006_fig11()
            .map_err(|e| e.named("lloyd2006-fig11"))
            .unwrap();
        let p = &fig.panels[0];
        assert_eq!(p.plane_labels, ["n = 1", "z = 2", "z = 4", "f = 8"]);
        let dims: Vec<(f64, f64, &str)> = p
            .dims
            .iter()
            .map(|(a, b, t)| ((*b - *a).length(), a.y, t.as_str()))
            .collect();
        assert_eq!(dims.len(), 2);
        assert!((dims[0].0 - 1.1547).abs() < 1e-4 && dims[0].2 == "2n tan θ");
        assert!((dims[1].0 - 9.2376).abs() < 1e-4 && dims[1].2 == "2f tan θ");
        // Under their faces: below the near face's lower edge (−0.577) and the far face's
        // (−4.619), and inside the window.
        assert!(dims[0].1 < -0.5774 && dims[1].1 < -4.6188);
        let (lo, _) = p.window.unwrap();
        assert!(lo.y < dims[1].1 - 0.5);
    }

    /// The light's view is not mirrored (figure review 2): for a light behind, right of and
    /// above the eye, travelling along (−1, −1, −1), an observer at the light looking along it
    /// with the view direction −Z up has d × up ∝ (−1, −1, −1) × (1, 1, −2) = (3, −3, 0) on
    /// their right, by hand. So the far section's corner (s, −s, −z) lies √2 s right of the
    /// centre and (−s, s, −z) √2 s left (s = z tan θ); the old (x, z) drawing had them swapped.
    #[test]
    fn the_light_sees_the_eyes_right_on_its_right() {
        let view = ViewFrustum::new(1.0, 10.0, 30f64.to_radians()).unwrap();
        let p = panel(
            &view,
            DVec3::new(-1.0, -1.0, -1.0),
            &[1.0, 10.0],
            String::new(),
        )
        .map_err(|e| e.named("panel"))
        .unwrap();
        let s = 10.0 * 30f64.to_radians().tan();
        let far = p.sections[1];
        assert!((far[1].x - 2f64.sqrt() * s).abs() < 1e-9, "{far:?}");
        assert!((far[3].x + 2f64.sqrt() * s).abs() < 1e-9, "{far:?}");
    }

    /// Barroso Fig 5's split depths to 4 significant figures (figure review 2): Eq 5's
    /// 100^{i/4} = 3.162, 10, 31.62 and Eq 19's (the paper's f₁..f₃ by hand: 6.0405, 16.1297,
    /// 40.8114); and (e), (f) enlarge (b) and (c) near the eye, to z ≤ 10 and z ≤ 40.81.
    #[test]
    fn barroso_split_labels_have_four_significant_figures() {
        let b = barroso_fig5().map_err(|e| e.named("barroso-fig5")).unwrap();
        assert_eq!(
            b.panels[0].plane_labels,
            ["1", "3.162", "10", "31.62", "100"]
        );
        assert_eq!(
            b.panels[2].plane_labels,
            ["1", "6.041", "16.13", "40.81", "100"]
        );
        assert_eq!(b.panels.len(), 6);
        let t = 30f64.to_radians().tan();
        let (lo, hi) = b.panels[4].window.unwrap();
        assert!((hi.x - 10.0 * t).abs() < 1e-9 && (lo.y + 10.0 * t).abs() < 1e-9);
        // (f): light z of the corner (z tan θ, z tan θ, −z) at z = 40.8114 is
        // z (1 + tan θ)/√2 = 45.519 (light 45° up: light z = (Y + z)/√2).
        let (_, hi) = b.panels[5].window.unwrap();
        assert!(
            (hi.y - 40.8114 * (1.0 + t) / 2f64.sqrt()).abs() < 1e-3,
            "{hi}"
        );
    }
}
