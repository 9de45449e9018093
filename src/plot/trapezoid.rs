//! Martin & Tan 2004 Figs 3–4: the trapezoid against the bounding box. The eye's frustum seen
//! from the light (E, with its convex hull C and the focus region), the trapezoid T of the 80 %
//! rule ([`crate::maps::tsm::tsm`]), the smallest (rotated) bounding box B of the paper's §3 and
//! the axis-aligned box; then C in the trapezoidal space (N_T, the map the trapezoid builds) and
//! in B's space, with the share of the map each leaves unused (the paper's *wastage*).

use super::chart::{
    build_chart_styled, column, dash_pattern, draw_fine_path, equal_aspect, fill_fine_points,
    frame, plot_size, probe_area, to_backend, Axis, ChartStyle, Dash, FONT, PALETTE, SHARED,
};
use super::from_light::seen_from_light;
use super::{Column, Fail, Figure, UNIT_SQUARE};
use crate::maps::tsm::{tsm, TsmOptions, TsmSearch};
use crate::ViewFrustum;
use glam::{DMat3, DVec2, DVec3};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The focus distance δ beyond the near plane (as in Martin–Tan Fig 6).
const FOCUS: f64 = super::zhang::TSM_FOCUS;

/// The frustum's twelve edges as pairs of corner indices ([`ViewFrustum::corners`]: near plane
/// first, then far, each −x−y, +x−y, +x+y, −x+y).
const EDGES: [(usize, usize); 12] = [
    (0, 1),
    (1, 2),
    (2, 3),
    (3, 0),
    (4, 5),
    (5, 6),
    (6, 7),
    (7, 4),
    (0, 4),
    (1, 5),
    (2, 6),
    (3, 7),
];

pub(super) struct Fig3 {
    /// The frustum's and the focus region's corners as the light sees them (light-space −x, z:
    /// [`seen_from_light`]); the trapezoid and the box likewise, and N_T maps these.
    pub eye: Vec<DVec2>,
    pub focus: Vec<DVec2>,
    pub trapezoid: [DVec2; 4],
    /// The bounding box of the frustum's corners: min, max.
    pub bbox: (DVec2, DVec2),
    pub n_t: DMat3,
    /// Share of the map the hull C covers: in the trapezoidal space and in the box's space.
    pub covered_t: f64,
    pub covered_b: f64,
    /// The minimum-area (oriented) bounding rectangle of C and the share of its map C covers.
    pub obox: [DVec2; 4],
    pub covered_o: f64,
}

/// The convex hull of points, counter-clockwise (Andrew's monotone chain).
pub(super) fn hull(points: &[DVec2]) -> Vec<DVec2> {
    let mut p: Vec<DVec2> = points.to_vec();
    p.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let cross = |o: DVec2, a: DVec2, b: DVec2| (a - o).perp_dot(b - o);
    let mut lower: Vec<DVec2> = Vec::new();
    for &q in &p {
        while lower.len() >= 2 && cross(lower[lower.len() - 2], lower[lower.len() - 1], q) <= 0.0 {
            lower.pop();
        }
        lower.push(q);
    }
    let mut upper: Vec<DVec2> = Vec::new();
    for &q in p.iter().rev() {
        while upper.len() >= 2 && cross(upper[upper.len() - 2], upper[upper.len() - 1], q) <= 0.0 {
            upper.pop();
        }
        upper.push(q);
    }
    lower.pop();
    upper.pop();
    lower.extend(upper);
    lower
}

/// The area of a simple polygon (shoelace).
pub(super) fn area(poly: &[DVec2]) -> f64 {
    let n = poly.len();
    0.5 * (0..n)
        .map(|i| poly[i].perp_dot(poly[(i + 1) % n]))
        .sum::<f64>()
        .abs()
}

/// The minimum-area enclosing rectangle of a convex polygon (counter-clockwise, as [`hull`]
/// returns it): one of its sides lies on an edge of the polygon (Freeman & Shapira 1975, the
/// property rotating calipers walk), so trying each edge's direction finds it. Returns the four
/// corners (counter-clockwise) and the area; an empty or degenerate polygon gives area 0.
pub(super) fn min_area_box(c: &[DVec2]) -> ([DVec2; 4], f64) {
    let mut best = ([DVec2::ZERO; 4], f64::INFINITY);
    for i in 0..c.len() {
        let e = c[(i + 1) % c.len()] - c[i];
        let Some(u) = e.try_normalize() else {
            continue;
        };
        let v = u.perp();
        let (mut u0, mut u1, mut v0, mut v1) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for &p in c {
            let (a, b) = (p.dot(u), p.dot(v));
            (u0, u1, v0, v1) = (u0.min(a), u1.max(a), v0.min(b), v1.max(b));
        }
        let a = (u1 - u0) * (v1 - v0);
        if a < best.1 {
            let at = |s: f64, t: f64| s * u + t * v;
            best = ([at(u0, v0), at(u1, v0), at(u1, v1), at(u0, v1)], a);
        }
    }
    if best.1.is_finite() {
        best
    } else {
        ([DVec2::ZERO; 4], 0.0)
    }
}

/// `h (p, 1)` divided by its third coordinate.
pub(super) fn through(h: &DMat3, p: DVec2) -> DVec2 {
    let q = *h * DVec3::new(p.x, p.y, 1.0);
    DVec2::new(q.x / q.z, q.y / q.z)
}

pub(super) fn fig3() -> Result<Fig3, Fail> {
    fig3_at(LIGHT.0, LIGHT.1)
}

/// The light of the figure: elevation and azimuth in degrees (azimuth 0 behind the viewer, 90°
/// to its right, 180° in front).
const LIGHT: (f64, f64) = (80.0, 70.0);

/// The eye's frustum: near, far, half field of view θ in degrees.
const VIEW: (f64, f64, f64) = (1.0, 100.0, 30.0);

/// The figure's data for a light `el_deg` above the horizon at azimuth `az_deg`.
pub(super) fn fig3_at(el_deg: f64, az_deg: f64) -> Result<Fig3, Fail> {
    let view = ViewFrustum::new(VIEW.0, VIEW.1, VIEW.2.to_radians())?;
    let (el, az) = (el_deg.to_radians(), az_deg.to_radians());
    let light = -DVec3::new(el.cos() * az.sin(), el.sin(), el.cos() * az.cos());
    let map = tsm(
        &view,
        light,
        TsmOptions {
            focus: FOCUS,
            search: TsmSearch::EightyPercent,
        },
    )?;
    // As the light sees it (−x, z): the trapezoid and N_T, built in light-space (x, z), are
    // carried over by the mirror image.
    let to_xz = |p: DVec3| seen_from_light(map.light_space.to_light(p));
    let mirror = DMat3::from_diagonal(DVec3::new(-1.0, 1.0, 1.0));
    let trapezoid = map.trapezoid.corners.map(|p| DVec2::new(-p.x, p.y));
    let eye: Vec<DVec2> = view.corners().iter().map(|&c| to_xz(c)).collect();
    let focus_view = ViewFrustum::new(view.near(), view.near() + FOCUS, view.half_fov())?;
    let focus: Vec<DVec2> = focus_view.corners().iter().map(|&c| to_xz(c)).collect();
    let lo = eye
        .iter()
        .fold(DVec2::splat(f64::INFINITY), |a, &p| a.min(p));
    let hi = eye
        .iter()
        .fold(DVec2::splat(f64::NEG_INFINITY), |a, &p| a.max(p));
    let c = hull(&eye);
    let in_t: Vec<DVec2> = c.iter().map(|&p| through(&map.n_t, p)).collect();
    let covered_t = area(&in_t) / 4.0;
    let covered_b = area(&c) / ((hi.x - lo.x) * (hi.y - lo.y));
    let (obox, obox_area) = min_area_box(&c);
    let covered_o = area(&c) / obox_area;
    Ok(Fig3 {
        obox,
        covered_o,
        eye,
        focus,
        trapezoid,
        bbox: (lo, hi),
        n_t: map.n_t * mirror,
        covered_t,
        covered_b,
    })
}

/// The colours and strokes of each shape, the same in every panel and in the legend: none a
/// scheme's colour (those mean shadow-map schemes in every figure), T black, B and the focus
/// region apart by dash where their greys meet.
const EDGE: RGBColor = RGBColor(120, 120, 120);
/// The hull C: a sand no scheme has (the fifth review, X5: PALETTE's sky blue was read as
/// PSM/ZP's blue), filled opaque at CIE L* 79.8 (the sixth review, R6-martin-tan-fig3-3: at
/// 45 % over white, L* 88.5 and 1.35 : 1, it nearly vanished in greyscale).
const HULL: RGBColor = RGBColor(216, 196, 152);
/// The focus region: dark wine, 2 units wide in every panel, so that in greyscale it stands
/// out from the light hull C it lies on (review 3: a thin pink line on light blue).
const FOCUS_C: RGBColor = RGBColor(136, 34, 85);
const TRAP: RGBColor = PALETTE[6];
const MIN_BOX: RGBColor = PALETTE[7];
const AXIS_BOX: RGBColor = SHARED;

/// How a closed outline is stroked.
#[derive(Clone, Copy)]
enum Stroke {
    Solid,
    Dashed,
    Dotted,
}

/// Strokes the closed outline of `corners` (light space, or a map's) 2 units wide, placed to a
/// tenth of a unit (the ninth review, R9-martin-tan-fig3-3: rounded to whole units, (a)'s near
/// plane shrank to 1-unit stubs at the apex); dashes 9 on, 6 off, dots 2 on, 5 off, along the
/// outline's length.
fn outline<DB: DrawingBackend>(
    chart: &super::chart::Chart2d<'_, DB>,
    corners: &[DVec2],
    colour: RGBColor,
    stroke: Stroke,
) -> Result<(), Fail> {
    let to = to_backend(chart);
    let mut pts: Vec<(f64, f64)> = corners.iter().map(|p| to((p.x, p.y))).collect();
    pts.push(pts[0]);
    let pieces = match stroke {
        Stroke::Solid => vec![pts],
        Stroke::Dashed => dash_pattern(&pts, &[9.0, 6.0], 1.0),
        Stroke::Dotted => dash_pattern(&pts, &[2.0, 5.0], 1.0),
    };
    let area = chart.plotting_area().strip_coord_spec();
    for piece in pieces {
        draw_fine_path(&area, &piece, colour, 2, Dash::Solid)?;
    }
    Ok(())
}

impl Fig3 {
    /// The affine map of the minimum-area box onto [−1, 1]² (its first side along s).
    fn box_map(&self) -> DMat3 {
        let [a, b, _, d] = self.obox;
        let (u, v) = (b - a, d - a);
        let centre = 0.5 * (b + d);
        let (su, sv) = (2.0 * u / u.length_squared(), 2.0 * v / v.length_squared());
        DMat3::from_cols(
            DVec3::new(su.x, sv.x, 0.0),
            DVec3::new(su.y, sv.y, 0.0),
            DVec3::new(-su.dot(centre), -sv.dot(centre), 1.0),
        )
    }
}

/// The legend's row height, the padding inside its box, and the strip's height it takes: three
/// rows in a box, [`LEGEND_MARGIN`] over it and under it (so that the box stands apart from
/// the caption).
const LEGEND_ROW: i32 = 20;
const LEGEND_PAD: i32 = 5;
const LEGEND_MARGIN: i32 = 8;
const LEGEND_ROWS: i32 = 3;
fn legend_h() -> u32 {
    (2 * LEGEND_MARGIN + 2 * LEGEND_PAD + LEGEND_ROWS * LEGEND_ROW) as u32
}

/// The figure's one legend, one entry per shape in the colours and strokes of every panel, in
/// a box of two columns centred under all the panels, each column as wide as its widest entry
/// (the box narrower than the panels in both layouts), as the line
/// charts' legends are boxed (issue 25: drawn inside (a), its box covered part of the drawing;
/// R7-MT3-1: an unboxed 3 × 2 grid spread over the page's width did not group its entries).
/// The left column names the eye's shapes (E, its hull C, the focus region), the right one
/// the maps' outlines (T, B, the axis-aligned box).
fn draw_legend<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
    let entries: [(&str, RGBColor, Option<Stroke>); 6] = [
        ("frustum E", EDGE, Some(Stroke::Solid)),
        ("hull C", HULL, None),
        ("focus region", FOCUS_C, Some(Stroke::Solid)),
        ("trapezoid T", TRAP, Some(Stroke::Solid)),
        ("min-area box B", MIN_BOX, Some(Stroke::Dashed)),
        ("axis-aligned box", AXIS_BOX, Some(Stroke::Dotted)),
    ];
    let style = TextStyle::from((FONT, 13).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
    // A column's width: its widest entry's sample (18), gap (4) and text.
    let mut col_w = [0i32; 2];
    for (i, (label, ..)) in entries.iter().enumerate() {
        let (w, _) = area
            .estimate_text_size(label, &style)
            .map_err(|e| Fail::Draw(e.to_string()))?;
        let c = i / LEGEND_ROWS as usize;
        col_w[c] = col_w[c].max(22 + w as i32);
    }
    const COLUMN_GAP: i32 = 16;
    let (aw, _) = area.dim_in_pixel();
    let box_w = 2 * LEGEND_PAD + col_w[0] + COLUMN_GAP + col_w[1];
    let x0 = ((aw as i32 - box_w) / 2).max(0);
    let y0 = LEGEND_MARGIN;
    let box_h = 2 * LEGEND_PAD + LEGEND_ROWS * LEGEND_ROW;
    let corners = [(x0, y0), (x0 + box_w, y0 + box_h)];
    area.draw(&Rectangle::new(corners, WHITE.filled()))?;
    area.draw(&Rectangle::new(corners, LEGEND_FRAME))?;
    for (i, (label, colour, stroke)) in entries.into_iter().enumerate() {
        let (c, r) = (i as i32 / LEGEND_ROWS, i as i32 % LEGEND_ROWS);
        let (x, y) = (
            x0 + LEGEND_PAD + c * (col_w[0] + COLUMN_GAP),
            y0 + LEGEND_PAD + r * LEGEND_ROW + LEGEND_ROW / 2,
        );
        let pieces: [(i32, i32); 4] = match stroke {
            None => [(0, 0); 4],
            Some(Stroke::Solid) => [(0, 18); 4],
            Some(Stroke::Dashed) => [(0, 7), (11, 18), (11, 18), (11, 18)],
            Some(Stroke::Dotted) => [(0, 2), (5, 7), (11, 13), (16, 18)],
        };
        if stroke.is_none() {
            area.draw(&Rectangle::new(
                [(x, y - 6), (x + 18, y + 6)],
                HULL.filled(),
            ))?;
        } else {
            for (a, b) in pieces {
                area.draw(&PathElement::new(
                    vec![(x + a, y), (x + b, y)],
                    colour.stroke_width(2),
                ))?;
            }
        }
        area.draw(&Text::new(label, (x + 22, y), style.clone()))?;
    }
    Ok(())
}

/// The legend box's outline: the line charts' legends' grey.
const LEGEND_FRAME: RGBColor = RGBColor(120, 120, 120);

impl Figure for Fig3 {
    fn size(&self) -> (u32, u32) {
        (520, 590)
    }

    /// One column: the same layout, narrower: (a) on the left, (b) over (c) on the right, the
    /// legend under them.
    fn single_size(&self) -> Option<(u32, u32)> {
        Some((Column::Single.width(), SINGLE_H))
    }

    /// One column's caption names the inset's enlargement (R9-martin-tan-fig3-2: it has no
    /// room for the lines joining the inset to its window), which the layout under the caption
    /// fixes: the page is laid out on a [`probe_area`] first, as often as it takes the
    /// enlargement the caption names to be the one drawn (the caption's lines, not their
    /// words, set the layout, so one round settles it).
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        if column() == Column::Double {
            return self.draw_page(root, None).map(|_| ());
        }
        let mut named = None;
        for _ in 0..4 {
            let drawn = self.draw_page(&probe_area(root.dim_in_pixel()), named)?;
            if named.is_some_and(|k| magnification(k) == magnification(drawn)) {
                let drawn = self.draw_page(root, named)?;
                return match named {
                    Some(k) if magnification(k) == magnification(drawn) => Ok(()),
                    _ => Err(Fail::Draw(format!(
                        "martin-tan-fig3: the caption names the inset {} but it is drawn {}",
                        named.map_or_else(String::new, magnification),
                        magnification(drawn)
                    ))),
                };
            }
            named = Some(drawn);
        }
        Err(Fail::Draw(
            "martin-tan-fig3: the inset's enlargement does not settle with the caption naming it"
                .into(),
        ))
    }
}

impl Fig3 {
    /// The page, its caption in one column naming the inset's enlargement `zoom` where given;
    /// returns the enlargement the inset is drawn at.
    fn draw_page<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        zoom: Option<f64>,
    ) -> Result<f64, Fail> {
        let single = column() == Column::Single;
        let (pct, nb) = (|v: f64| format!("{:.1}\u{a0}%", 100.0 * v), '\u{a0}');
        let caption = if single {
            let inset = zoom.map_or_else(String::new, |k| {
                format!("; inset: (a)'s grey box{nb}{}", magnification(k))
            });
            format!(
                "Martin & Tan 2004, Figs. 3, 4: T (80{nb}% rule, δ{nb}={nb}{FOCUS}), \
                 n{nb}={nb}{}, f{nb}={nb}{}, θ{nb}={nb}{}°, light at elevation {}°, azimuth {}° \
                 from behind to the right{inset}. C covers {} of T's map (b), {} of \
                 B's (c).",
                VIEW.0,
                VIEW.1,
                VIEW.2,
                LIGHT.0,
                LIGHT.1,
                pct(self.covered_t),
                pct(self.covered_o),
            )
        } else {
            format!(
                "Martin & Tan 2004, Figs. 3 and 4: the 80{nb}% rule's trapezoid T \
                 (δ{nb}={nb}{FOCUS}), n{nb}={nb}{}, f{nb}={nb}{}, θ{nb}={nb}{}°, light at \
                 elevation {}°, azimuth {}° from behind towards the viewer's right; the inset \
                 enlarges (a)'s grey box. As in the paper (§3, §5), B is the smallest (rotated) \
                 box; dotted: the axis-aligned one. C covers {} of the map in T's \
                 space (b), {} in B's (c), {} in the axis-aligned box's.",
                VIEW.0,
                VIEW.1,
                VIEW.2,
                LIGHT.0,
                LIGHT.1,
                pct(self.covered_t),
                pct(self.covered_o),
                pct(self.covered_b),
            )
        };
        let body = frame(
            root,
            "The trapezoid against the smallest bounding box",
            &[caption.as_str()],
        )?;
        // The legend in a strip of its own under all the panels, where it covers nothing; (a)
        // on the left, (b) over (c) on the right (issue 35: (a) over (b) and (c) made the figure
        // 960 units tall). Every panel's area is cut to its plot's shape, so that no axis runs
        // past its data (review 3: (b) and (c) ran from −1.9 to 2 for a map on [−1, 1]).
        let (_, bh) = body.dim_in_pixel();
        let (upper, strip) = body.split_vertically(bh.saturating_sub(legend_h()));
        let style = if single {
            ChartStyle {
                y_label_area: 46,
                x_label_area: 34,
                desc_size: 13,
                margin: 5,
                ..ChartStyle::default()
            }
        } else {
            ChartStyle::default()
        };
        // (a)'s y labels reach "150" and "−x in light space" is long: a wider label area.
        let a_style = ChartStyle {
            y_label_area: style.y_label_area,
            ..style
        };
        let (uw, uh) = upper.dim_in_pixel();
        // (b) and (c): equal plots, square; in one column (b) leaves its x labels to (c).
        let b_style = if single {
            ChartStyle {
                x_label_area: 0,
                ..style
            }
        } else {
            style
        };
        let b_h = (uh + b_style.x_label_area - style.x_label_area) / 2;
        // The map on [0, 1]², as in every figure (it was [−1, 1]², the fifth review, X4).
        let square = (
            Axis::linear("map s", -0.05, 1.05),
            Axis::linear("map t", -0.05, 1.05),
        );
        // The same titles in both layouts (R7-MT3-4: "(b) trapezoidal space (N_T)" ended 4
        // units from the bare figure's right edge).
        // "(N_T)" named the paper's map nowhere defined in the figure (the fourteenth review,
        // R14-MT3-1); "T's space" is the caption's.
        let titles = ["(b) T's space", "(c) B's space"];
        let probe = upper.clone().shrink((0, 0), (uw, b_h));
        let (_, side) = plot_size(&probe, titles[0], &square.0, &square.1, &b_style)?;
        let right_w = (side as u32 + style.y_label_area + 3 * style.margin + 1).min(uw / 2);
        let (top, right) = upper.split_horizontally(uw - right_w);
        let (b_area, c_area) = right.split_vertically(b_h);
        // (a) Light space, equal aspect: x symmetric about the apex, y over the data and the
        // window the inset shows; the axis the area leaves over goes under the apex or to both
        // sides.
        let pts: Vec<DVec2> = self
            .eye
            .iter()
            .chain(&self.trapezoid)
            .chain(&self.obox)
            .copied()
            .collect();
        let mut lo = pts
            .iter()
            .fold(DVec2::splat(f64::INFINITY), |a, &p| a.min(p));
        let hi = pts
            .iter()
            .fold(DVec2::splat(f64::NEG_INFINITY), |a, &p| a.max(p));
        // The tallest window the inset shows (its frame at least as wide as tall).
        lo.y = lo.y.min(self.inset_window(1.0).0.y);
        let title = "(a) seen from the light";
        // The data's margin: 4 % of its extent and 3 units of the page (the lines' width).
        let margin = |per_unit: f64| 0.04 * (hi - lo).max_element() + 3.0 / per_unit;
        let axes = |half_x: f64, (y_lo, y_hi): (f64, f64)| {
            (
                Axis::linear(X_LABEL, -half_x, half_x),
                Axis::linear("light-view y", y_lo, y_hi),
            )
        };
        let (mut half_x, mut y_range) = (lo.x.abs().max(hi.x.abs()), (lo.y, hi.y));
        // The inset in a strip of its own under (a)'s axes and their names (the sixth review:
        // inside the axes under y = 0 it read as data): the height (a)'s plot leaves over at
        // the panel's full width, at least a share of the panel.
        let (_, th) = top.dim_in_pixel();
        let (xa, ya) = axes(half_x, y_range);
        let (w, h) = plot_size(&top, title, &xa, &ya, &a_style)?;
        let need = |per_unit: f64| {
            let pad = margin(per_unit);
            (
                2.0 * (lo.x.abs().max(hi.x.abs()) + pad),
                hi.y - lo.y + 2.0 * pad,
            )
        };
        let (need_x, need_y) = need(w / need(f64::INFINITY).0);
        let least = INSET_STRIP[usize::from(single)] * f64::from(th);
        let strip_h = (h - w * need_y / need_x).max(least) as u32;
        let (top, inset_strip) = top.split_vertically(th - strip_h);
        let mut per_unit = f64::INFINITY;
        // The scale, the margins and the tick labels' widths depend on each other: a few
        // rounds settle them.
        for _ in 0..3 {
            let pad = margin(per_unit);
            let y_top = hi.y + pad;
            let y_least = y_top - (lo.y - pad);
            let need_x = 2.0 * (lo.x.abs().max(hi.x.abs()) + pad);
            let (xa, ya) = axes(half_x, y_range);
            let (w, h) = plot_size(&top, title, &xa, &ya, &a_style)?;
            let y_span = if h / w * need_x >= y_least {
                half_x = 0.5 * need_x;
                h / w * need_x
            } else {
                half_x = 0.5 * y_least * w / h;
                y_least
            };
            y_range = (y_top - y_span, y_top);
            per_unit = w / (2.0 * half_x);
        }
        // The y axis labelled over the data only (from 0: under it is the window's margin).
        let (xa, ya) = axes(half_x, y_range);
        let data_ticks: Vec<f64> = ya.ticks().0.into_iter().filter(|&v| v >= 0.0).collect();
        let ya = ya.labelled_at(&data_ticks);
        // The x axis likewise labelled over the data (one column's narrow (a) has no room for
        // "−100" beside "−50").
        let data_ticks: Vec<f64> = xa
            .ticks()
            .0
            .into_iter()
            .filter(|&v| (lo.x..=hi.x).contains(&v))
            .collect();
        let xa = xa.labelled_at(&data_ticks);
        let chart = build_chart_styled(&top, title, &xa, &ya, false, &a_style)?;
        self.draw_contents(&chart, |p| p)?;
        // Units per light-space unit (equal aspect: the same along both axes).
        // Measured across the whole axis: one light-space unit is under one unit of the page in
        // one column, where whole pixels would round it to 0 or 1.
        let (x0, x1) = (xa.min, xa.max);
        let unit = f64::from(chart.backend_coord(&(x1, 0.0)).0 - chart.backend_coord(&(x0, 0.0)).0)
            .abs()
            .max(1.0)
            / (x1 - x0);
        // The boxes at their true outlines, whatever the figure's scale (the fifth review: drawn
        // 4 units outside, true only at the page's size). The axis-aligned box first, under T,
        // which closes it where their sides meet; B last, over T: where B's side lies on T's,
        // its dashes alternate olive with T's black between them.
        let (b0, b1) = self.bbox;
        let axis_box = [b0, DVec2::new(b1.x, b0.y), b1, DVec2::new(b0.x, b1.y)];
        outline(&chart, &axis_box, AXIS_BOX, Stroke::Dotted)?;
        outline(&chart, &self.trapezoid, TRAP, Stroke::Solid)?;
        outline(&chart, &self.obox, MIN_BOX, Stroke::Dashed)?;
        let zoom = self.draw_inset(&inset_strip, &chart, unit, (!single).then_some(&upper))?;
        // (b), (c): the two normalised spaces; the map square in the colour of its shape.
        for (panel, h, title, colour, stroke, st) in [
            (&b_area, self.n_t, titles[0], TRAP, Stroke::Solid, &b_style),
            (
                &c_area,
                self.box_map(),
                titles[1],
                MIN_BOX,
                Stroke::Dashed,
                &style,
            ),
        ] {
            let (ax, ay) = equal_aspect(panel, title, &square.0, &square.1, st)?;
            // The map's ends and centre only.
            let ends = [0.0, 0.5, 1.0];
            let (ax, ay) = (ax.labelled_at(&ends), ay.labelled_at(&ends));
            let chart = build_chart_styled(panel, title, &ax, &ay, false, st)?;
            let h = TO_UNIT * h;
            self.draw_contents(&chart, |p| through(&h, p))?;
            let square: Vec<DVec2> = UNIT_SQUARE[..4]
                .iter()
                .map(|&(x, y)| through(&TO_UNIT, DVec2::new(x, y)))
                .collect();
            outline(&chart, &square, colour, stroke)?;
            if colour == MIN_BOX {
                self.point_to_focus(panel, &chart, &h)?;
            }
        }
        draw_legend(&strip)?;
        Ok(zoom)
    }
}

/// [−1, 1]² onto the map's [0, 1]²: s = (x + 1)/2, t = (y + 1)/2.
const TO_UNIT: DMat3 = DMat3::from_cols_array(&[0.5, 0.0, 0.0, 0.0, 0.5, 0.0, 0.5, 0.5, 1.0]);

impl Fig3 {
    /// In (c), where the focus region is a sliver in the map's corner: its name outside the
    /// map, under and left of the axes' corner, on no box, joined by a grey leader that passes
    /// between the two spines' ends to the middle of the focus region's outline edge facing
    /// the corner (R13-martin-tan-fig3-1: on a white box inside the map square it covered part
    /// of a frustum edge and touched B's dashed side). `h` carries light space into the map.
    fn point_to_focus<DB: DrawingBackend>(
        &self,
        panel: &DrawingArea<DB, Shift>,
        chart: &super::chart::Chart2d<'_, DB>,
        h: &DMat3,
    ) -> Result<(), Fail> {
        let to = to_backend(chart);
        let page = |p: DVec2| DVec2::from(to((p.x, p.y)));
        let focus = hull(
            &self
                .focus
                .iter()
                .map(|&p| page(through(h, p)))
                .collect::<Vec<_>>(),
        );
        let centre = focus.iter().copied().sum::<DVec2>() / focus.len() as f64;
        // The spines' corner: plotters draws the y axis 1 unit left of the plotting area and
        // the x axis 1 unit under it, so that they do not meet there.
        let (xr, yr) = (chart.x_range(), chart.y_range());
        let corner = page(DVec2::new(xr.start, yr.start)) + DVec2::new(-1.0, 1.0);
        // The map square's sides: an edge along one of them would read as B's.
        let (s0, s1) = (page(DVec2::ZERO), page(DVec2::ONE));
        let along_side = |a: DVec2, b: DVec2| {
            [s0.x, s1.x]
                .iter()
                .any(|&x| (a.x - x).abs() < 1.0 && (b.x - x).abs() < 1.0)
                || [s0.y, s1.y]
                    .iter()
                    .any(|&y| (a.y - y).abs() < 1.0 && (b.y - y).abs() < 1.0)
        };
        let mids = (0..focus.len()).filter_map(|i| {
            let (a, b) = (focus[i], focus[(i + 1) % focus.len()]);
            let mid = 0.5 * (a + b);
            // The edge's normal away from the region's centre faces the corner.
            let normal = (b - a).perp();
            let out = if normal.dot(mid - centre) < 0.0 {
                -normal
            } else {
                normal
            };
            (!along_side(a, b) && out.dot(corner - mid) > 0.0).then_some(mid)
        });
        let end = mids
            .min_by(|p, q| p.distance(corner).total_cmp(&q.distance(corner)))
            .ok_or_else(|| {
                Fail::Draw("(c): no edge of the focus region faces the axes' corner".into())
            })?;
        // On beyond the corner, at least 4 units across and 3 down from it, so that the word
        // (1 unit further) stands clear of both spines and of the tick labels 0 by them.
        let u = (corner - end).normalize();
        let d = (4.0 / u.x.abs().max(0.1)).max(3.0 / u.y.max(0.1));
        let start = corner + d * u;
        draw_fine_path(
            &chart.plotting_area().strip_coord_spec(),
            &[(end.x, end.y), (start.x, start.y)],
            LEADER,
            1,
            Dash::Solid,
        )?;
        // The word's top right corner 1 unit across and down from the leader's start, drawn
        // on the panel (the plotting area would pull it inside itself).
        let (bx, by) = panel.get_base_pixel();
        let at = (
            (start.x - 1.0).round() as i32 - bx,
            (start.y + 1.0).round() as i32 - by,
        );
        let ink = super::chart::legible(FOCUS_C);
        let style = TextStyle::from((FONT, FOCUS_SIZE).into_font())
            .color(&ink)
            .pos(Pos::new(HPos::Right, VPos::Top));
        panel.draw(&Text::new("focus", at, style))?;
        Ok(())
    }
}

/// The leader's grey (the inset's frame and connecting lines are drawn in it too).
const LEADER: RGBColor = RGBColor(90, 90, 90);

/// The size (c) names the focus region at: the tick labels'.
const FOCUS_SIZE: u32 = 13;

/// The least height of the strip under (a) that holds its inset, as a share of the panel's
/// (two columns, one column).
const INSET_STRIP: [f64; 2] = [0.2, 0.27];

/// The one-column figure's height: at most 525 units (420 points printed 240 wide).
const SINGLE_H: u32 = 496;

/// The x axis of (a): the light's −x, to the right as the light sees the scene (named as in
/// every figure; its vertical partner is "light-view y").
const X_LABEL: &str = "light-view x";

impl Fig3 {
    /// C filled, E's edges and the focus region's, carried by `f`, placed to a tenth of a unit
    /// (R9-martin-tan-fig3-3, as [`outline`]).
    fn draw_contents<DB: DrawingBackend>(
        &self,
        chart: &super::chart::Chart2d<'_, DB>,
        f: impl Fn(DVec2) -> DVec2,
    ) -> Result<(), Fail> {
        let to = to_backend(chart);
        let at = |p: DVec2| {
            let q = f(p);
            to((q.x, q.y))
        };
        let area = chart.plotting_area().strip_coord_spec();
        fill_fine_points(&area, hull(&self.eye).into_iter().map(at).collect(), HULL)?;
        for (corners, colour, width) in [(&self.eye, EDGE, 1), (&self.focus, FOCUS_C, 2)] {
            for (a, b) in EDGES {
                let line = [at(corners[a]), at(corners[b])];
                draw_fine_path(&area, &line, colour, width, Dash::Solid)?;
            }
        }
        Ok(())
    }
}

/// The label of an inset enlarged `k` times: "×8" (to the nearest whole number; "×2.5" under 3).
pub(super) fn magnification(k: f64) -> String {
    if k < 3.0 {
        format!("×{:.1}", k)
    } else {
        format!("×{:.0}", k)
    }
}

#[path = "trapezoid_inset.rs"]
mod inset;

#[cfg(test)]
#[path = "trapezoid_tests.rs"]
mod tests;
