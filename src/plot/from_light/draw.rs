//! Drawing the diagrams seen from the light ([`FromLight`]): each panel at equal aspect with its
//! axes fitted to the drawing (the panel narrowed, not the axes widened, where the drawing is
//! taller than the panel's shape), each labelled split plane joined by a leader from its
//! cross-section's right corner to its label in a gutter right of the plot, and one key under
//! the panels naming the maps' strokes, the frustum's and the split planes'.

use super::super::chart::{
    boxed_text, build_chart_styled, clip_polyline, column, dash_pattern, draw_fine_line,
    equal_aspect, frame, plot_size, Axis, Chart2d, ChartStyle, Dash, FONT, OCHRE, SWEEP, TITLE_GAP,
};
use super::super::{Column, Fail, Figure};
use super::{FromLight, Panel, SEEN_X, SEEN_Y};
use glam::DVec2;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Each partition's map outline, nearest partition first: its dash pattern (lengths on, off,
/// on, off… in units, repeated), one kind per map: dashes, square dots, dash-dot, long dashes.
/// Map i has this kind and [`map_colour`]'s colour in both figures that draw maps
/// (lloyd2006-fig11's wide outlines, barroso-fig5's fine ones, [`maps::FINE_PATTERNS`], these
/// scaled by [`maps::FINE_SCALE`]), so that the key "Maps, nearest first" means one thing in
/// both (the eleventh review, R11-X-1).
pub(in super::super) const PATTERNS: [&[f64]; 4] = [
    &[6.0, 3.0],
    &[4.0, 3.0],
    &[12.0, 3.0, 2.0, 3.0],
    &[14.0, 4.0],
];

/// The colour of partition `i`'s map, the same in both figures (R11-X-1): maps 1, 2 and 4
/// the sweep's darkest (L* 18), lightest (L* 60) and middle (L* 39) steps, each pair at least
/// 20 L* apart, so that they stay apart in grey; map 3 ochre ([`OCHRE`], L* 49, ΔE at least 80
/// from the three purples), as no fourth purple step lies 20 L* from three others above 3 : 1
/// on white (the eleventh review, R11-barroso-fig5-1: maps 1 and 3, #582A92 and #674CA0, 10 L*
/// apart and one hue, could not be told apart; map 3 now differs from map 1 in hue, as from
/// every map it is drawn with in (b), (f)). Every one is at least 3 : 1 on white.
pub(in super::super) fn map_colour(i: usize) -> RGBColor {
    [SWEEP[0], SWEEP[4], OCHRE, SWEEP[2]][i.min(3)]
}

/// The odd maps' outlines (1, 3): narrow lines of their colour; the even ones' (2, 4): wide
/// bands of their colour. Each outline lies exactly on its rectangle (the seventh review,
/// R7-X-3: drawn 2 units outside it, the maps read as larger than the squares they equal),
/// under the frustum's black lines and wider than them, so that where a map's edge lies on a
/// cross-section both show: the black line with the map's dashes on either side of it (figure
/// review 3: dashes drawn over the line hid it in their gaps). lloyd2006-fig11 draws these;
/// barroso-fig5 draws its maps fine ([`maps`]).
/// Two columns' widths; one column's are a unit narrower, its panels half as wide (a band
/// stays [`MAP_BAND`] − 1 = 8 wide, the least of a light band behind lines).
const MAP_NARROW: u32 = 5;
const MAP_BAND: u32 = 9;

/// Map `i`'s outline (0: the nearest): its colour, stroke width and dash pattern.
fn map_stroke(i: usize) -> (RGBColor, u32, &'static [f64]) {
    let c = map_colour(i);
    let pattern = PATTERNS[i % PATTERNS.len()];
    let less = u32::from(column() == Column::Single);
    if i.is_multiple_of(2) {
        (c, MAP_NARROW - less, pattern)
    } else {
        (c, MAP_BAND - less, pattern)
    }
}

/// How far a map's outline reaches outside its rectangle, in units: half the wide outline.
const MAP_REACH: f64 = MAP_BAND as f64 / 2.0;

/// The stroke widths of the frustum's edges (its near and far faces and the side edges) and of
/// the split planes' cross-sections.
const FRUSTUM_WIDTH: u32 = 2;
const PLANE_WIDTH: u32 = 1;

/// Half the length of the bar across each end of a dimension line, in units.
const DIM_BAR: f64 = 4.0;

/// How far below the edge it measures a dimension line with its label in a break is drawn,
/// in units, for `label`-size text: the label's half height, its box's pad and a gap of 2
/// below a map's outline on the edge (reaching [`MAP_REACH`] outside it).
fn dim_clear(label: u32) -> f64 {
    MAP_REACH + 2.0 + 0.65 * f64::from(label) + 2.0 + 2.0
}

/// The least distance between two plane labels of lloyd2006-fig11, in units.
const FIG11_STEP: i32 = 11;

/// A gutter label's distance from the gutter's left edge, in units.
const LABEL_AT: i32 = 13;

/// A panel title's distance from its cell's left edge, in units.
const TITLE_INSET: i32 = 2;

/// The grey of the box marking the region a detail panel enlarges.
const ENLARGED: RGBColor = RGBColor(110, 110, 110);

/// How far outside the detail's limits its grey box runs, in units (1 pt across two columns):
/// the box's half width, a unit of white and the half width of a map's outline on the limit.
const ENLARGED_OUT: f64 = 3.0;

/// The grey of the leaders and their anchor dots (3.05 : 1 on white, the least for lines).
const LEADER: RGBColor = RGBColor(148, 148, 148);
const ANCHOR: RGBColor = RGBColor(90, 90, 90);

#[path = "draw_sizes.rs"]
mod sizes;
use sizes::{sizes, tick_labels, Sizes, OVERVIEW_GUTTER, OVERVIEW_LEAST};
#[path = "draw_labels.rs"]
mod labels;
#[path = "draw_maps.rs"]
mod maps;
pub(super) use labels::{choose_corners, right_corners, short_title, spread};
use maps::{fine_maps, fine_stroke};

#[path = "draw_key.rs"]
mod key_strip;
use key_strip::key;
#[path = "draw_numbers.rs"]
mod numbers;

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
        let title = if single {
            self.single_title
        } else {
            self.title
        };
        let body = frame(root, title, &[caption.as_str()])?;
        let sz = sizes(single, self.panels.len());
        let maps = self.panels.iter().map(|p| p.maps.len()).max().unwrap_or(0);
        let fine = self.panels.iter().any(|p| p.fine);
        let key_h = key(&body, maps, fine, sz.key, false)?;
        let (_, bh) = body.dim_in_pixel();
        let (body, strip) = body.split_vertically(bh - key_h);
        key(&strip, maps, fine, sz.key, true)?;
        // One panel across two columns (lloyd2006-fig11) on the page's full 520 units (the
        // eighteenth review, R18-lloyd2006-fig11-1): its drawing, narrower than the page, is
        // centred in the body by [`fit`]; as much as its gutter keeps blank right of the widest
        // label is taken off the body's left, so that the ink (the y axis's name to the labels'
        // ends), not the drawing's cell with that blank, is centred on the page.
        let body = if !single && self.panels.len() == 1 {
            let label = TextStyle::from((FONT, sz.label).into_font());
            let mut widest = 0;
            for l in &self.panels[0].plane_labels {
                let (w, _) = body
                    .estimate_text_size(l, &label)
                    .map_err(|e| Fail::Draw(e.to_string()))?;
                widest = widest.max(w);
            }
            let unused = sz.gutter.saturating_sub(LABEL_AT as u32 + widest);
            body.margin(0, 0, unused, 0)
        } else {
            body
        };
        let columns = self.panels.len().min(2);
        let rows = self.panels.len().div_ceil(columns);
        // The rows above the last have no x title: the last is taller by the title's room, so
        // that every row's plots have the same height.
        let (bw, bh) = body.dim_in_pixel();
        let extra = sz.style.x_label_area - sz.x_ticks_only;
        let row_h = (bh - if rows > 1 { extra } else { 0 }) / rows as u32;
        // One column's three rows of plots about 75 units tall: the y axis named once, for the
        // column (figure review 5: "light-view y" is longer than one plot, and on each row it
        // ran into the titles).
        let shared_y = single && rows > 2;
        let mut rest = body;
        for r in 0..rows {
            let h = if r + 1 == rows {
                rest.dim_in_pixel().1
            } else {
                row_h
            };
            let (row, below) = rest.split_vertically(h);
            // Two columns of panels: the left one wider by its y axis's name, so that the two
            // plots of a row have the same room. In one column the overview on the left has no
            // gutter and is as wide as its plot is tall (its drawing about square), the detail
            // the rest (figure review 6: each plot was about 40 units wide, 50 narrower than
            // the row's height allowed, with maps 1 to 3 unreadable).
            let head = sz.style.margin + sz.style.title_size + TITLE_GAP;
            let plot_h = row_h.saturating_sub(head + sz.x_ticks_only + 2 * sz.style.margin);
            let cells: Vec<DrawingArea<DB, Shift>> = if columns == 2 {
                let left = if single {
                    (sz.style.y_label_area + plot_h + OVERVIEW_GUTTER)
                        .max(OVERVIEW_LEAST)
                        .min(bw / 2)
                } else {
                    (bw + sz.style.y_label_area - sz.y_ticks_only) / 2
                };
                let (a, b) = row.split_horizontally(left);
                vec![a, b]
            } else {
                row.split_evenly((1, columns))
            };
            // Panel c's chart style, sizes and axis titles.
            let setup = |c: usize| {
                let mut style = sz.style;
                if r + 1 < rows {
                    style.x_label_area = sz.x_ticks_only;
                }
                if c > 0 {
                    style.y_label_area = sz.y_ticks_only;
                }
                let overview = single && columns == 2 && c == 0;
                let panel_sz = Sizes {
                    gutter: if overview { OVERVIEW_GUTTER } else { sz.gutter },
                    labels: !overview,
                    ..sz
                };
                (style, panel_sz, (r + 1 == rows, c == 0 && !shared_y))
            };
            let small = single && self.panels.len() > 1;
            for c in 0..columns {
                let (Some(p), Some(cell)) = (self.panels.get(r * columns + c), cells.get(c)) else {
                    break;
                };
                let (style, panel_sz, titles) = setup(c);
                // An overview's grey box: the range its detail (the next panel, in the next
                // cell) shows, laid out as it will be drawn.
                let detail = (self.panels.get(r * columns + c + 1), cells.get(c + 1));
                let enlarged = match detail {
                    (Some(d), Some(d_cell)) if p.enlarged => {
                        let (d_style, d_sz, d_titles) = setup(c + 1);
                        Some(shown(d_cell, d, small, &d_sz, &d_style, d_titles)?)
                    }
                    _ => None,
                };
                draw_panel(cell, p, small, &panel_sz, &style, titles, enlarged)?;
            }
            // One column's y name, once, centred on the middle row below its title.
            if shared_y && r == rows / 2 {
                let (_, rh) = row.dim_in_pixel();
                let head = sz.style.margin + sz.style.title_size + TITLE_GAP;
                let centre = (head + rh) / 2;
                row.draw(&Text::new(
                    SEEN_Y,
                    (sz.style.margin as i32, centre as i32),
                    TextStyle::from((FONT, sz.style.desc_size).into_font())
                        .transform(FontTransform::Rotate270)
                        .pos(Pos::new(HPos::Center, VPos::Top)),
                ))?;
            }
            rest = below;
        }
        debug_assert!(bw > 0);
        Ok(())
    }
}

/// The two ends of a cross-section seen edge-on (its four corners on one line, within `tol`):
/// the pair of corners furthest apart; `None` for a section with an area.
pub(super) fn edge_on(sec: &[DVec2; 4], tol: f64) -> Option<[DVec2; 2]> {
    let mut ends = [sec[0], sec[0]];
    let mut far = -1.0;
    for (i, &a) in sec.iter().enumerate() {
        for &b in &sec[i + 1..] {
            let d = (b - a).length();
            if d > far {
                far = d;
                ends = [a, b];
            }
        }
    }
    let dir = (ends[1] - ends[0]).normalize_or_zero();
    let flat = sec
        .iter()
        .all(|&q| (q - ends[0]).perp_dot(dir).abs() <= tol.max(1e-9 * far));
    (far > 0.0 && flat).then_some(ends)
}

/// The window a panel shows (min, max), with a margin of 3 % of its larger side.
fn window(p: &Panel) -> (DVec2, DVec2) {
    let (lo, hi) = p.window.unwrap_or_else(|| {
        p.sections.iter().flatten().fold(
            (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
            |(lo, hi), &q| (lo.min(q), hi.max(q)),
        )
    });
    let pad = 0.03 * (hi - lo).max_element();
    (lo - DVec2::splat(pad), hi + DVec2::splat(pad))
}

/// The axes of a panel over the window `lo`–`hi` (titled where `titles` says), labelled at
/// `at` (across, up).
fn axes(lo: DVec2, hi: DVec2, at: &(Vec<f64>, Vec<f64>), titles: (bool, bool)) -> (Axis, Axis) {
    let name = |t: bool, n: &str| if t { n.to_string() } else { String::new() };
    (
        Axis::linear(name(titles.0, SEEN_X), lo.x, hi.x).labelled_at(&at.0),
        Axis::linear(name(titles.1, SEEN_Y), lo.y, hi.y).labelled_at(&at.1),
    )
}

/// The backend pixel of a data point of `chart`.
fn px<DB: DrawingBackend>(chart: &Chart2d<'_, DB>, q: DVec2) -> (i32, i32) {
    chart.backend_coord(&(q.x, q.y))
}

/// Panel `p`'s title (cut to its first clause in one column) and `whole` split into the title's
/// room and the rest.
#[allow(clippy::type_complexity)]
fn split_head<DB: DrawingBackend>(
    whole: &DrawingArea<DB, Shift>,
    p: &Panel,
    small: bool,
    style: &ChartStyle,
) -> (String, DrawingArea<DB, Shift>, DrawingArea<DB, Shift>) {
    // In one column, the titles cut to their first clause ("(c) Eq 19", "(d) detail of (a)"):
    // the full ones are wider than the 150-unit panels.
    let title = if small {
        short_title(&p.title)
    } else {
        p.title.clone()
    };
    // The title at the cell's top left, before the cell is narrowed to the drawing: one baseline
    // across a row and one left edge down a column (figure review 3: centred over narrowed
    // cells, "(a) perpendicular" stood 9 units below "(b) parallel", and "(c) Eq 19, not in the
    // paper" overhung its panel to 3 units from the page's edge).
    let head_h = if title.is_empty() {
        0
    } else {
        style.margin + style.title_size + TITLE_GAP
    };
    let (head, rest) = whole.split_vertically(head_h);
    (title, head, rest)
}

/// A panel laid out: the area it draws in (narrowed to the drawing's shape), its plot's cell,
/// the gutter for its labels and its axes (their limits the data range the plot shows).
struct Fit<DB: DrawingBackend> {
    whole: DrawingArea<DB, Shift>,
    cell: DrawingArea<DB, Shift>,
    gutter: DrawingArea<DB, Shift>,
    xa: Axis,
    ya: Axis,
}

/// Lays panel `p` out in `whole` (below its title): the window, grown for the maps' outlines and
/// the dimension lines, then widened to equal aspect. Draws nothing.
fn fit<DB: DrawingBackend>(
    whole: &DrawingArea<DB, Shift>,
    p: &Panel,
    small: bool,
    sz: &Sizes,
    style: &ChartStyle,
    titles: (bool, bool),
) -> Result<Fit<DB>, Fail> {
    let title = String::new();
    let (lo, hi) = window(p);
    let first = tick_labels(lo, hi, 1e9, 1e9, 1.0);
    let (x0, y0) = axes(lo, hi, &first, titles);
    // The panel narrowed (or shortened) about its centre to the drawing's shape, so that equal
    // aspect leaves no empty axis range: measured on the plot the full cell would have.
    let (cw, ch) = whole.dim_in_pixel();
    let (full, _) = whole.split_horizontally(cw - sz.gutter);
    let (pw, ph) = plot_size(&full, &title, &x0, &y0, style)?;
    let per_px = ((hi.x - lo.x) / pw).max((hi.y - lo.y) / ph);
    // Room for the maps' outlines, reaching [`MAP_REACH`] outside their rectangles:
    // the outermost map's lies outside the drawing (the 3 % margin is 1.4 units in a 46-unit
    // plot).
    let reach = if p.fine {
        0.5 * f64::from(fine_stroke(1).1)
    } else {
        MAP_REACH
    };
    let grow = DVec2::splat(if p.window.is_none() {
        (reach + 0.5) * per_px
    } else {
        0.0
    });
    let (mut lo, mut hi) = (lo - grow, hi + grow);
    let mut per_px = ((hi.x - lo.x) / pw).max((hi.y - lo.y) / ph);
    // Room under each dimension line for its label (bars, the label's boxed line and a gap to
    // the x axis), the window grown alike above, so that the frustum stays centred (figure
    // review 4: in one column "2f tan θ"'s box covered the x axis). The room is in units of
    // the page, so its data height grows with the window: a few rounds settle it.
    let room = |on_line: bool| {
        if on_line {
            dim_clear(sz.label) + 0.65 * f64::from(sz.label) + 3.0
        } else {
            DIM_BAR * 1.6 + 1.3 * f64::from(sz.label) + 6.0
        }
    };
    for _ in 0..4 {
        let low = p
            .dims
            .iter()
            .map(|(a, b, _, on)| a.y.min(b.y) - room(*on) * per_px)
            .fold(lo.y, f64::min);
        let more = lo.y - low;
        if more <= 0.0 {
            break;
        }
        lo.y -= more;
        // lloyd2006-fig11's window grows down only, so that no empty band lies above the
        // frustum (the sixth review, R6-lloyd2006-fig11-2: 2 units above and below).
        if !p.grow_down {
            hi.y += more;
        }
        per_px = ((hi.x - lo.x) / pw).max((hi.y - lo.y) / ph);
    }
    let (dw, dh) = ((hi.x - lo.x) / per_px, (hi.y - lo.y) / per_px);
    // Labelled ticks only over the drawing (a window larger than it, as lloyd2006-fig11's with
    // room for a dimension line, labels none beyond it).
    let (dlo, dhi) = super::bounds(&p.sections);
    let at = tick_labels(
        lo.max(dlo),
        hi.min(dhi),
        dw * (hi.min(dhi) - lo.max(dlo)).x / (hi - lo).x,
        dh * (hi.min(dhi) - lo.max(dlo)).y / (hi - lo).y,
        f64::from(style.tick_size),
    );
    let (x0, y0) = axes(lo, hi, &at, titles);
    let spare_w = (pw - dw).max(0.0).floor() as u32;
    let spare_h = (ph - dh).max(0.0).floor() as u32;
    // The spare height under the plot, so that it stays under its title.
    // One column's plots are as tall as their rows allow (figure review 6): the spare width on
    // the right, so that the y ticks of a column of panels end at one x.
    let left = if small { 0 } else { spare_w / 2 };
    let whole = whole.margin(0, spare_h, left, spare_w - left);
    let (cw, _) = whole.dim_in_pixel();
    debug_assert!(ch > 0 && cw > sz.gutter);
    let (cell, gutter) = whole.split_horizontally(cw - sz.gutter);
    let (xa, ya) = equal_aspect(&cell, &title, &x0, &y0, style)?;
    // equal_aspect's axes are plain linear ones: the labels chosen above, kept.
    let (xa, ya) = axes(
        DVec2::new(xa.min, ya.min),
        DVec2::new(xa.max, ya.max),
        &at,
        titles,
    );
    Ok(Fit {
        whole,
        cell,
        gutter,
        xa,
        ya,
    })
}

/// The data range (min, max) that panel `p` shows when drawn in `whole` (its title included):
/// the limits of its axes, for the grey box that marks it in its overview.
fn shown<DB: DrawingBackend>(
    whole: &DrawingArea<DB, Shift>,
    p: &Panel,
    small: bool,
    sz: &Sizes,
    style: &ChartStyle,
    titles: (bool, bool),
) -> Result<(DVec2, DVec2), Fail> {
    let (_, _, rest) = split_head(whole, p, small, style);
    let f = fit(&rest, p, small, sz, style, titles)?;
    Ok((
        DVec2::new(f.xa.min, f.ya.min),
        DVec2::new(f.xa.max, f.ya.max),
    ))
}

/// Draws panel `p` in `whole`; `titles`: whether its x and y axes carry their titles;
/// `enlarged`: the data range its detail panel shows, outlined in grey.
#[allow(clippy::too_many_arguments)]
fn draw_panel<DB: DrawingBackend>(
    whole: &DrawingArea<DB, Shift>,
    p: &Panel,
    small: bool,
    sz: &Sizes,
    style: &ChartStyle,
    titles: (bool, bool),
    enlarged: Option<(DVec2, DVec2)>,
) -> Result<(), Fail> {
    let (title, head, whole) = split_head(whole, p, small, style);
    if !title.is_empty() {
        head.draw(&Text::new(
            title,
            (TITLE_INSET, style.margin as i32),
            TextStyle::from((FONT, style.title_size).into_font())
                .pos(Pos::new(HPos::Left, VPos::Top)),
        ))?;
    }
    let Fit {
        whole,
        cell,
        gutter,
        xa,
        ya,
        ..
    } = fit(&whole, p, small, sz, style, titles)?;
    let whole = &whole;
    let title = String::new();
    let mut chart = build_chart_styled(&cell, &title, &xa, &ya, false, style)?;
    let inside = |q: DVec2| q.x >= xa.min && q.x <= xa.max && q.y >= ya.min && q.y <= ya.max;
    let bounds = (xa.min, xa.max, ya.min, ya.max);
    let clip = |pts: &[DVec2]| {
        let pts: Vec<Option<(f64, f64)>> = pts.iter().map(|q| Some((q.x, q.y))).collect();
        clip_polyline(&pts, bounds)
    };
    let per_unit =
        f64::from(px(&chart, DVec2::new(xa.max, 0.0)).0 - px(&chart, DVec2::new(xa.min, 0.0)).0)
            / (xa.max - xa.min);
    // No tint inside the maps (figure review 5: the tinted fills were in no key); each map is
    // its dashed outline.
    // The labelled split planes, each with its leader's candidate corners.
    let tol = 1e-9 * (xa.max - xa.min);
    let mut labelled: Vec<(Vec<DVec2>, &String)> = Vec::new();
    for (sec, label) in p.sections.iter().zip(&p.plane_labels) {
        let size = sec
            .iter()
            .fold(0.0f64, |m, q| m.max((*q - sec[0]).length()));
        let corners: Vec<DVec2> = right_corners(sec, tol)
            .into_iter()
            .take(if p.top_leaders { 1 } else { usize::MAX })
            .filter(|&q| inside(q))
            .collect();
        if sz.labels && !label.is_empty() && !corners.is_empty() && size > 0.06 * (xa.max - xa.min)
        {
            labelled.push((corners, label));
        }
    }
    // The notes naming a line (barroso-fig5 (f)'s far face) are labels in the gutter too, each
    // joined by its leader to its point on the line (figure review 5: set above the line, the
    // note read as the band's name, not the line's); in one column in the details' gutters only
    // (the eighth review, R8-barroso-fig5-2: without (f)'s tag, "thick line: the far face" could
    // mean any of the frustum's thick edges), as the planes' labels.
    for (at, text) in p.notes.iter().filter(|_| sz.labels) {
        if inside(*at) {
            labelled.push((vec![*at], text));
        }
    }
    // Bottom to top, as the planes are: a note among them in its place.
    labelled.sort_by(|a, b| a.0[0].y.total_cmp(&b.0[0].y));
    let (gx, gy) = gutter.get_base_pixel();
    let (wx, wy) = whole.get_base_pixel();
    let (_, gh) = gutter.dim_in_pixel();
    // The labels' half heights kept inside the gutter.
    // lloyd2006-fig11's four labels, one line each, as close as their text allows (the
    // seventh review, R7-2006f11-2: spread a row apart, "n = 1"'s leader bent while the others
    // ran straight): 11 units, the digits' height (0.73 of the 10.5-unit type) and a gap of 3.
    let step = if p.top_leaders {
        sz.step.min(FIG11_STEP)
    } else {
        sz.step
    };
    let edge = 8.max(sz.step / 2);
    let range = (edge, gh as i32 - edge);
    let candidates: Vec<Vec<i32>> = labelled
        .iter()
        .map(|(c, _)| c.iter().map(|&q| px(&chart, q).1).collect())
        .collect();
    let pick = choose_corners(&candidates, step, range, gy);
    let anchors: Vec<DVec2> = labelled
        .iter()
        .zip(&pick)
        .map(|((c, _), &k)| c[k])
        .collect();
    let anchor_px: Vec<(i32, i32)> = anchors.iter().map(|&q| px(&chart, q)).collect();
    let ys = spread(
        &anchor_px.iter().map(|a| a.1).collect::<Vec<_>>(),
        step,
        range,
        gy,
    );
    // Leaders first, under every line: from the corner to the gutter.
    for &(ax, ay) in &anchor_px {
        whole.draw(&PathElement::new(
            vec![(ax - wx, ay - wy), (gx - wx, ay - wy)],
            LEADER.stroke_width(1),
        ))?;
    }
    // The maps' outlines first, exactly on their rectangles, the wide ones under the narrow
    // ones (where two maps share an edge, the wide one shows on either side of the narrow), all
    // under the frustum's black lines ([`MAP_NARROW`]); at a tenth of a unit ([`draw_fine_line`]),
    // as the black lines, so that an outline and the line it lies on coincide.
    let mut order: Vec<usize> = (0..p.maps.len()).collect();
    order.sort_by_key(|&i| std::cmp::Reverse(map_stroke(i).1));
    for i in order.into_iter().filter(|_| !p.fine) {
        let (a, b) = p.maps[i];
        let corners = [a, DVec2::new(b.x, a.y), b, DVec2::new(a.x, b.y), a];
        let (colour, width, pattern) = map_stroke(i);
        for piece in clip(&corners) {
            for dash in dash_pattern(&piece, pattern, per_unit) {
                draw_fine_line(&chart, &dash, colour, width, Dash::Solid)?;
            }
        }
    }
    let solid = |pts: &[DVec2], width: u32| -> Result<(), Fail> {
        for piece in clip(pts) {
            draw_fine_line(&chart, &piece, BLACK, width, Dash::Solid)?;
        }
        Ok(())
    };
    // The split planes thin, the near and far faces (the frustum's) as thick as its side edges.
    let last = p.sections.len() - 1;
    for (i, s) in p.sections.iter().enumerate() {
        let width = if i == 0 || i == last {
            FRUSTUM_WIDTH
        } else {
            PLANE_WIDTH
        };
        match edge_on(s, tol) {
            // Seen edge-on (a light perpendicular to the view): one line between its ends, at
            // its weight (figure review 5: the closed outline of a flat quad was drawn as two
            // thin slanted lines).
            Some([a, b]) => solid(&[a, b], width)?,
            None => solid(&[s[0], s[1], s[2], s[3], s[0]], width)?,
        }
    }
    let (first, far) = (p.sections[0], p.sections[last]);
    for i in 0..4 {
        solid(&[first[i], far[i]], FRUSTUM_WIDTH)?;
    }
    // The region a detail panel enlarges, a grey box on top of the drawing: the detail's axis
    // limits (the eighth review, R8-barroso-fig5-1: grown by the maps' reach, (a)'s box was
    // ±17.3 for (b)'s ±6.1), drawn [`ENLARGED_OUT`] units outside them, so that a map's outline
    // on a limit does not hide it (the twelfth review, R12-barroso-fig5-1: (c)'s box lay under
    // map 2's outline, (a)'s and (e)'s shared three sides with map 3's).
    if let Some((a, b)) = enlarged {
        let out = DVec2::splat(ENLARGED_OUT / per_unit);
        let (a, b) = (a - out, b + out);
        let corners = [a, DVec2::new(b.x, a.y), b, DVec2::new(a.x, b.y), a];
        // At a tenth of a unit, as the maps' outlines: the box lies on the detail's limits, not
        // on the pixels next to them.
        for piece in clip(&corners) {
            draw_fine_line(&chart, &piece, ENLARGED, 2, Dash::Solid)?;
        }
    }
    // Fine maps over the lines and the grey box (R9-barroso-fig5-1: (a)'s box, (b)'s limits,
    // lies within a unit of map 3's outline, which drawn under it did not show).
    if p.fine {
        fine_maps(&chart, p, bounds, per_unit)?;
    }
    // Each leader's anchor, a dot on its corner.
    for &q in &anchors {
        chart.draw_series(std::iter::once(Circle::new((q.x, q.y), 2, ANCHOR.filled())))?;
    }
    // The maps' numbers at their corners (R11-barroso-fig5-1), clear of every line.
    if p.numbered {
        let leaders: Vec<numbers::Leader> = anchor_px
            .iter()
            .map(|&(ax, ay)| ((ax, ay), (gx, ay)))
            .collect();
        numbers::numbers(&chart, whole, p, sz.label, &leaders)?;
    }
    for [from, to] in &p.extensions {
        chart.draw_series(LineSeries::new(
            [(from.x, from.y), (to.x, to.y)],
            ANCHOR.stroke_width(1),
        ))?;
    }
    // Dimension lines: the line with a bar at each end, its label centred below.
    for (a, b, text, on_line) in &p.dims {
        let bar = DIM_BAR / per_unit;
        let n = (*b - *a).perp().normalize_or_zero() * bar;
        // The label below the bars' ends, with room for its white margin, or centred on the
        // line, its box breaking it.
        let (a, b) = if *on_line {
            let down = DVec2::new(0.0, dim_clear(sz.label) / per_unit);
            (&(*a - down), &(*b - down))
        } else {
            (a, b)
        };
        // A label in a break of its line: the line in two pieces, a gap of 3 units either
        // side of the label's text.
        let gap = if *on_line {
            let style = TextStyle::from((FONT, sz.label).into_font());
            let (w, _) = chart
                .plotting_area()
                .estimate_text_size(text, &style)
                .map_err(|e| Fail::Draw(e.to_string()))?;
            (0.5 * f64::from(w) + 3.0) / per_unit
        } else {
            0.0
        };
        let mid = 0.5 * (*a + *b);
        let along = (*b - *a).normalize_or_zero() * gap;
        let line: Vec<(DVec2, DVec2)> = if gap > 0.0 {
            vec![(*a, mid - along), (mid + along, *b)]
        } else {
            vec![(*a, *b)]
        };
        for (from, to) in line.into_iter().chain([(*a - n, *a + n), (*b - n, *b + n)]) {
            chart.draw_series(LineSeries::new(
                [(from.x, from.y), (to.x, to.y)],
                BLACK.stroke_width(1),
            ))?;
        }
        let (mid, v) = if *on_line {
            (0.5 * (*a + *b), VPos::Center)
        } else {
            (0.5 * (*a + *b) - 1.2 * n, VPos::Top)
        };
        boxed_text(
            &mut chart,
            (mid.x, mid.y),
            text,
            Pos::new(HPos::Center, v),
            sz.label,
            BLACK,
        )?;
    }
    // The labels in the gutter, each joined to its leader's end (in one column's narrow gutter
    // by a leader 2 units shorter).
    let shorter = if small { 2 } else { 0 };
    let label_style =
        TextStyle::from((FONT, sz.label).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
    for ((&(_, ay), (_, label)), y) in anchor_px.iter().zip(&labelled).zip(ys) {
        let ty = ay - gy;
        gutter.draw(&PathElement::new(
            vec![(0, ty), (5, ty), (11 - shorter, y - gy)],
            LEADER.stroke_width(1),
        ))?;
        // One column: on one line, "=" between thin spaces (figure review 5: the depth alone,
        // "31.62", read as a tick value; review 6: set close, "z=31.62", it differed from the
        // two columns' "z = 31.62").
        let text = if small {
            label.replace(" = ", "\u{2009}=\u{2009}")
        } else {
            (*label).clone()
        };
        gutter.draw(&Text::new(
            text,
            (LABEL_AT - shorter, y - gy),
            label_style.clone(),
        ))?;
    }
    Ok(())
}
