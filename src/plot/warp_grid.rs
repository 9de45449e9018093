//! Lloyd et al. 2006 Fig 4: the perspective warp's grid as n′ decreases from ∞ to n, light
//! overhead. Top: in light space (seen from the light), the shadow map's texel grid over the
//! view frustum. Right: in the shadow map, the view frustum's own grid (planes of constant
//! depth and rays of constant x/z), stretched to fill the map.
//!
//! Both come from the crate's built matrix ([`crate::maps::warp`] with [`WarpRule::Eta`]): on
//! the plane y = 0 of eye space the matrix is a 2D projective map (x, z) ↦ (u, v), so every grid
//! line is straight and maps to a straight line; its ends are carried over with the map or its
//! inverse.

use super::chart::{
    build_chart_styled, clip_polyline, column, equal_aspect, frame, linspace, Axis, ChartStyle,
    FONT, PANEL_TITLE, SHARED, SWEEP,
};
use super::{Fail, Figure, UNIT_SQUARE};
use crate::analytic::eta::n_prime_from_eta;
use crate::maps::{warp, WarpRule};
use crate::ViewFrustum;
use glam::{DMat3, DVec3};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Grid lines per direction.
const LINES: usize = 12;

/// Rays from the eye drawn in the map, less one: every second of [`LINES`], so that where they
/// converge on the near plane (t = 0, s = ½ for the uniform map) they stay apart.
const RAYS: usize = LINES / 2;

/// The least distance between neighbouring rays in the map, in its s, t units, where they are
/// drawn (see [`fig4`]).
const RAY_GAP: f64 = 0.04;

/// The light travels straight down (−Y): overhead.
const OVERHEAD: DVec3 = DVec3::NEG_Y;

/// One column of the figure.
pub(super) struct Column {
    /// "η = −1", its scheme's name where it has one ("uniform"), and "n′ = ∞".
    pub eta: String,
    pub scheme: Option<&'static str>,
    pub n_prime: String,
    /// Segments in eye space (z, x): the map's lines of constant u (across) and v (depth).
    pub light_space: Vec<[(f64, f64); 2]>,
    /// Segments in the map (u, v): the frustum's planes of constant depth and rays.
    pub map: Vec<[(f64, f64); 2]>,
    /// The map's (u, v) → eye-space (x, z) on y = 0 (kept for the checks).
    #[cfg_attr(not(test), allow(dead_code))]
    pub to_eye: DMat3,
}

pub(super) struct Fig4 {
    pub view: ViewFrustum,
    pub columns: Vec<Column>,
}

/// The homography of `m` restricted to eye-space y = 0: (x, z, 1) ↦ (clip x, clip y, w).
fn plane_map(m: &glam::DMat4) -> DMat3 {
    let r = |row: usize, col: usize| m.col(col)[row];
    DMat3::from_cols(
        DVec3::new(r(0, 0), r(1, 0), r(3, 0)),
        DVec3::new(r(0, 2), r(1, 2), r(3, 2)),
        DVec3::new(r(0, 3), r(1, 3), r(3, 3)),
    )
}

fn apply(h: &DMat3, a: f64, b: f64) -> Option<(f64, f64)> {
    let p = *h * DVec3::new(a, b, 1.0);
    (p.z.abs() > 1e-300 && p.is_finite()).then(|| (p.x / p.z, p.y / p.z))
}

pub(super) fn fig4() -> Result<Fig4, Fail> {
    let view = ViewFrustum::new(1.0, 10.0, 30f64.to_radians())?;
    let (n, f, t) = (view.near(), view.far(), view.tan_half_fov());
    let mut columns = Vec::new();
    for eta in [-1.0, -0.6, 0.0, 1.0] {
        let np = n_prime_from_eta(n, f, eta)?;
        let s = warp(&view, OVERHEAD, WarpRule::Eta(eta))?;
        let h = plane_map(&s.matrix());
        let inv = h.inverse();
        if !inv.is_finite() {
            return Err(Fail::Data(crate::Error::Degenerate(format!(
                "the map of η = {eta} is singular on the plane y = 0"
            ))));
        }
        // (u, v) → (x, z) → plotted as (depth −z, x).
        let to_eye = |u: f64, v: f64| apply(&inv, u, v).map(|(x, z)| (-z, x));
        let mut light_space = Vec::new();
        for c in linspace(-1.0, 1.0, LINES + 1) {
            for (a, b) in [((c, -1.0), (c, 1.0)), ((-1.0, c), (1.0, c))] {
                if let (Some(p), Some(q)) = (to_eye(a.0, a.1), to_eye(b.0, b.1)) {
                    light_space.push([p, q]);
                }
            }
        }
        let to_map = |depth: f64, x: f64| apply(&h, x, -depth);
        let mut map = Vec::new();
        for z in linspace(n, f, LINES + 1) {
            if let (Some(p), Some(q)) = (to_map(z, -z * t), to_map(z, z * t)) {
                map.push([p, q]);
            }
        }
        // The rays far end first, so that their dashes start together at the far plane; the
        // frustum's sides (c = ±1) run to the near plane, the rays between them to the nearest
        // plane of constant depth where neighbours are still [`RAY_GAP`] apart in the map (in
        // the uniform map they would otherwise run together into one grey patch round t = 0,
        // s = ½; in PSM's they are parallel and reach the near plane).
        let step = 2.0 / RAYS as f64;
        let apart = |z: f64| match (to_map(z, 0.0), to_map(z, step * z * t)) {
            (Some(p), Some(q)) => 0.5 * (q.0 - p.0).hypot(q.1 - p.1) >= RAY_GAP,
            _ => false,
        };
        let first = linspace(n, f, LINES + 1)
            .into_iter()
            .find(|&z| apart(z))
            .unwrap_or(f);
        for c in linspace(-1.0, 1.0, RAYS + 1) {
            let end = if c.abs() == 1.0 { n } else { first };
            if let (Some(p), Some(q)) = (to_map(f, c * f * t), to_map(end, c * end * t)) {
                map.push([p, q]);
            }
        }
        // The column's parameters: η (with its scheme's name) and n′, negative η with the
        // minus sign U+2212.
        let (scheme, n_prime) = match np.as_finite() {
            None => (Some("uniform"), "n′ = ∞".to_string()),
            Some(v) if eta == 0.0 => (Some("LiSPSM"), format!("n′ = {v:.2}")),
            Some(v) if eta == 1.0 => (Some("PSM"), format!("n′ = n = {v:.0}")),
            Some(v) => (None, format!("n′ = {v:.2}")),
        };
        columns.push(Column {
            eta: minus(&format!("η = {eta}")),
            scheme,
            n_prime,
            light_space,
            map,
            to_eye: inv,
        });
    }
    Ok(Fig4 { view, columns })
}

/// The figure's text with every hyphen-minus before a digit written as the minus sign U+2212.
pub(super) fn minus(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        if c == '-' && chars.peek().is_some_and(char::is_ascii_digit) {
            out.push('−');
        } else {
            out.push(c);
        }
    }
    out
}

/// The texel grid of the map (panels (a)–(d)): thin, a light sweep colour, no scheme's.
const GRID_COLOUR: RGBColor = SWEEP[3];

/// The frustum's planes of constant depth in the map (panels (e)–(h)): solid, the sweep's
/// darkest and twice as thick as the texel grid, so that in greyscale the two differ in weight
/// and shade, not only in hue.
const DEPTH_COLOUR: RGBColor = SWEEP[0];

/// The planes' width: 2 units across two columns; 1 in one column's small panels, where 2
/// would run the crowded planes near t = 1 into one dark block (there they differ from the
/// texel grid by shade alone: about 32 CIE L* apart).
fn depth_width(narrow: bool) -> u32 {
    if narrow {
        1
    } else {
        2
    }
}

/// The shadow map's square [0, 1]² in panels (e)–(h): half as wide as the frustum of (a)–(d), so
/// that the key names the two apart (figure review 4: one key entry, "frustum, map's square",
/// stood for both), and dark grey, not the frustum's black (figure review 5).
const SQUARE_WIDTH: u32 = 1;
const SQUARE_COLOUR: RGBColor = RGBColor(64, 64, 64);

/// The rays from the eye in the map (panels (e)–(h)): dashed grey, so that in greyscale they
/// differ from the planes of constant depth by more than their shade.
const RAY_COLOUR: RGBColor = SHARED;

/// The dash and gap of a ray, in units of the page.
const RAY_DASH: (f64, f64) = (4.0, 3.0);

/// The pieces of the segment `a`–`b` that a dash pattern of `on`, `off` (data units of an
/// equal-aspect chart) draws, starting with a dash at `a`.
pub(super) fn dashes(a: (f64, f64), b: (f64, f64), (on, off): (f64, f64)) -> Vec<[(f64, f64); 2]> {
    let len = (b.0 - a.0).hypot(b.1 - a.1);
    let at = |t: f64| (a.0 + (b.0 - a.0) * t / len, a.1 + (b.1 - a.1) * t / len);
    let mut out = Vec::new();
    let mut t = 0.0;
    while t < len {
        out.push([at(t), at((t + on).min(len))]);
        t += on + off;
    }
    out
}

/// The lines of a panel's heading, in both layouts: its letter and η ("(a) η = −1"), n′, and
/// the scheme's name where there is one ("uniform"), each line narrower than a panel (R7-X-7:
/// across two columns at the common title size "(a) η = −1 (uniform)" on one line came within
/// 9 units of "(b) η = −0.6").
fn heading(letter: char, col: &Column) -> Vec<String> {
    [format!("({letter}) {}", col.eta), col.n_prime.clone()]
        .into_iter()
        .chain(col.scheme.map(str::to_string))
        .collect()
}

impl Fig4 {
    fn caption(&self) -> String {
        format!(
            "Lloyd et al. 2006, Fig. 4 (a schematic sketch there), from the warped matrices: \
             n\u{a0}=\u{a0}{n}, f\u{a0}=\u{a0}{f}, θ\u{a0}=\u{a0}{theta:.0}°, the plane \
             y\u{a0}=\u{a0}0, light overhead (eye x\u{a0}=\u{a0}light-view x). (a)–(d): from \
             the light, the map's \
             {LINES}\u{a0}×\u{a0}{LINES} texel grid over the view frustum, pressed to the near \
             plane by the warp. (e)–(h): the same in the map, s,\u{a0}t\u{a0}∈\u{a0}[0,\u{a0}1]: \
             the frustum's planes of constant depth and rays from the eye.",
            n = self.view.near(),
            f = self.view.far(),
            theta = self.view.half_fov().to_degrees(),
        )
    }

    /// The axes of the top row (depth, eye x) and the bottom row (map s, t) before equal aspect.
    fn axes(&self) -> [Axis; 4] {
        let (f, t) = (self.view.far(), self.view.tan_half_fov());
        [
            Axis::linear("depth z", 0.0, f * 1.05),
            Axis::linear("eye x", -f * t * 1.1, f * t * 1.1),
            // The map in the paper's texture coordinates s, t ∈ [0, 1] (the matrices'
            // normalised u, v ∈ [−1, 1] drawn at s = (u + 1)/2, t = (v + 1)/2).
            Axis::linear("map s", -0.05, 1.05),
            Axis::linear("map t", -0.05, 1.05),
        ]
    }

    /// A panel's chart on `area`: the axes `x`, `y` widened to equal aspect and ticked every
    /// `step` (along x, along y) from 0.
    fn equal_chart<'a, DB: DrawingBackend>(
        area: &'a DrawingArea<DB, Shift>,
        title: &str,
        (x, y): (&Axis, &Axis),
        step: (f64, f64),
        st: &ChartStyle,
    ) -> Result<super::chart::Chart2d<'a, DB>, Fail> {
        let (x, y) = equal_aspect(area, title, x, y, st)?;
        let every = |a: Axis, step: f64| Axis::every(a.label, a.min, a.max, 0.0, step);
        build_chart_styled(area, title, &every(x, step.0), &every(y, step.1), false, st)
    }

    /// The x ticks' steps of the light's and the map's panels: every 5 units of depth and every
    /// ½ of the map, in both layouts (one column sets [`GAP`] between its panels, so that one
    /// panel's "10" and the next one's "0" stand apart).
    fn x_steps(&self) -> (f64, f64) {
        (5.0, 0.5)
    }

    /// Column `k`'s light-space panel on `area`: the map's texel grid over the frustum, with
    /// the equal-aspect axes ticked every 5 units.
    fn draw_light<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        k: usize,
        title: &str,
        st: &ChartStyle,
    ) -> Result<(), Fail> {
        let [depth, across, _, _] = self.axes();
        let (n, f, t) = (self.view.near(), self.view.far(), self.view.tan_half_fov());
        let step = (self.x_steps().0, 5.0);
        let mut chart = Self::equal_chart(area, title, (&depth, &across), step, st)?;
        let bounds = (0.0, f * 1.05, -f * t * 1.1, f * t * 1.1);
        for seg in &self.columns[k].light_space {
            for piece in clip_polyline(&[Some(seg[0]), Some(seg[1])], bounds) {
                chart.draw_series(LineSeries::new(piece, GRID_COLOUR.stroke_width(1)))?;
            }
        }
        let frustum = [
            (n, -n * t),
            (f, -f * t),
            (f, f * t),
            (n, n * t),
            (n, -n * t),
        ];
        chart.draw_series(LineSeries::new(frustum, BLACK.stroke_width(2)))?;
        Ok(())
    }

    /// Column `k`'s map panel on `area`: the unit square and the frustum's planes of constant
    /// depth (solid) and rays from the eye (dashed).
    fn draw_map<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        k: usize,
        title: &str,
        st: &ChartStyle,
        narrow: bool,
    ) -> Result<(), Fail> {
        let [_, _, u, v] = self.axes();
        let st_of = |(a, b): (f64, f64)| (0.5 * (a + 1.0), 0.5 * (b + 1.0));
        let step = (self.x_steps().1, 0.5);
        let mut chart = Self::equal_chart(area, title, (&u, &v), step, st)?;
        chart.draw_series(LineSeries::new(
            UNIT_SQUARE.map(st_of),
            SQUARE_COLOUR.stroke_width(SQUARE_WIDTH),
        ))?;
        // The dash pattern in map units: the page's units per map unit, measured.
        let per_unit = f64::from(
            (chart.backend_coord(&(1.0, 0.0)).0 - chart.backend_coord(&(0.0, 0.0)).0).abs(),
        )
        .max(1e-9);
        let dash = (RAY_DASH.0 / per_unit, RAY_DASH.1 / per_unit);
        // From the far plane to the near, a plane of constant depth less than its width and a
        // unit of white from the last one drawn (midpoints on the page) is left out: PSM's near
        // t = 1 ran into one dark block (figure review 5, §4.4.1).
        let segs = &self.columns[k].map;
        let mid = |s: &[(f64, f64); 2]| {
            let (a, b) = (st_of(s[0]), st_of(s[1]));
            let m = chart.backend_coord(&(0.5 * (a.0 + b.0), 0.5 * (a.1 + b.1)));
            (f64::from(m.0), f64::from(m.1))
        };
        let mut last: Option<(f64, f64)> = None;
        let mut drawn = [false; LINES + 1];
        for i in (0..=LINES.min(segs.len() - 1)).rev() {
            let m = mid(&segs[i]);
            let gap = f64::from(depth_width(narrow)) + 1.0;
            drawn[i] = last.is_none_or(|l| (m.0 - l.0).hypot(m.1 - l.1) >= gap);
            last = if drawn[i] { Some(m) } else { last };
        }
        for (i, seg) in segs.iter().enumerate() {
            let ray = i > LINES;
            if !ray && !drawn[i] {
                continue;
            }
            for piece in clip_polyline(&[Some(seg[0]), Some(seg[1])], (-1.1, 1.1, -1.1, 1.1)) {
                let (a, b) = (st_of(piece[0]), st_of(piece[piece.len() - 1]));
                if ray {
                    for d in dashes(a, b, dash) {
                        chart.draw_series(LineSeries::new(d, RAY_COLOUR.stroke_width(1)))?;
                    }
                } else {
                    chart.draw_series(LineSeries::new(
                        [a, b],
                        DEPTH_COLOUR.stroke_width(depth_width(narrow)),
                    ))?;
                }
            }
        }
        Ok(())
    }

    /// The columns drawn: all four across two columns; in one, η = −1, 0 and 1 (uniform,
    /// LiSPSM, PSM), so that each panel is a third of the column, not a quarter (figure review
    /// 4: at four a row the panels printed about 40 pt wide).
    fn shown(&self, narrow: bool) -> Vec<usize> {
        if narrow {
            self.columns
                .iter()
                .enumerate()
                .filter(|(_, c)| c.scheme.is_some())
                .map(|(k, _)| k)
                .collect()
        } else {
            (0..self.columns.len()).collect()
        }
    }

    /// The two rows of panels on `body`: a column per n′ headed by its letter, η and n′ (and
    /// its scheme's name), the light's view over the map, titled "(e) map of (a)" (in one
    /// column "(d) map of (a)"), every title at [`heading_size`]. The
    /// columns share their axes: only the first has the y labels, and it is that much wider,
    /// so that every panel of a row has the same scale; in one column [`GAP`] units lie between
    /// neighbouring panels, so that one panel's last x tick label and the next one's first do
    /// not read as one number.
    fn draw_panels<DB: DrawingBackend>(
        &self,
        body: &DrawingArea<DB, Shift>,
        narrow: bool,
    ) -> Result<(), Fail> {
        let (bw, bh) = body.dim_in_pixel();
        let (label_w, line_h, margin, x_labels, gap) = if narrow {
            (42u32, 14u32, 4u32, 32u32, GAP)
        } else {
            (46, 18, 7, 38, 0)
        };
        let shown = self.shown(narrow);
        let count = shown.len() as u32;
        let pw = (bw - label_w - gap * (count - 1)) / count;
        let heading_style = TextStyle::from((FONT, heading_size(narrow)).into_font())
            .pos(Pos::new(HPos::Center, VPos::Top));
        let lines = shown
            .iter()
            .zip('a'..)
            .map(|(&k, l)| heading(l, &self.columns[k]).len())
            .max()
            .unwrap_or(1) as u32;
        let head = lines * line_h + 4;
        // One size for every panel's title, the headings' (the sixth review,
        // R6-lloyd2006-fig4-1: the maps' titles were 12.1 units, the headings 10.5).
        let st = |first: bool| ChartStyle {
            title_size: heading_size(narrow),
            x_label_area: x_labels,
            y_label_area: if first { label_w } else { 0 },
            tick_size: 13,
            desc_size: heading_size(narrow),
            margin,
        };
        // The rows' heights, each its equal-aspect plot's with nothing to spare: the light's
        // panel is 2.2 f tan θ high to 1.05 f deep, the map's square.
        let t = self.view.tan_half_fov();
        let plot_w = f64::from(pw - 3 * margin);
        let light_h = (plot_w * 2.2 * t / 1.05).ceil() as u32 + x_labels + 2 * margin;
        let map_title = heading_size(narrow) + super::chart::TITLE_GAP + 2;
        let map_h = plot_w.ceil() as u32 + x_labels + 2 * margin + map_title;
        let spare = bh.saturating_sub(head + light_h + map_h);
        let (y_light, y_map) = (head + spare / 2, head + spare / 2 + light_h);
        let letter = |row: u32, i: u32| char::from(b'a' + (row * count + i) as u8);
        for (i, &k) in shown.iter().enumerate() {
            let col = &self.columns[k];
            let ii = i as u32;
            let first = ii == 0;
            let x0 = if first { 0 } else { label_w + ii * (pw + gap) };
            let cw = pw + if first { label_w } else { 0 };
            let x_mid = (cw - pw + pw / 2) as i32;
            let column = body.clone().shrink((x0, 0), (cw, bh));
            for (j, line) in heading(letter(0, ii), col).into_iter().enumerate() {
                column.draw(&Text::new(
                    line,
                    (x_mid, (spare / 2 + line_h * j as u32) as i32),
                    heading_style.clone(),
                ))?;
            }
            let light = body.clone().shrink((x0, y_light), (cw, light_h));
            let map = body.clone().shrink((x0, y_map), (cw, map_h));
            // "(d) map of (a)" in both layouts (the sixth review, R6-lloyd2006-fig4-3: one
            // column's "(d)" under a row label "(d)–(f): (a)–(c) in the map (s, t)").
            let title = format!("({}) map of ({})", letter(1, ii), letter(0, ii));
            self.draw_light(&light, k, "", &st(first))?;
            self.draw_map(&map, k, &title, &st(first), narrow)?;
        }
        Ok(())
    }
}

/// The size of every panel's title, the columns' headings and the maps' titles, and of the axis
/// names: across two columns the other figures' panel title size (12.1 units in the SVG;
/// R7-X-7: they were 10.5 here, 12.1 in fifteen figures); in one column 10.5 units, as the
/// other one-column figures' axis names, since at 12.1 "(e) map of (b)" is wider than a panel
/// and its neighbour's title runs into it.
fn heading_size(narrow: bool) -> u32 {
    if narrow {
        13
    } else {
        PANEL_TITLE
    }
}

/// The room between neighbouring panels of a row in one column, in units.
const GAP: u32 = 16;

impl Figure for Fig4 {
    /// Two columns: the two rows of four, the key under them in two rows (its five entries are
    /// wider than the page).
    fn size(&self) -> (u32, u32) {
        (520, 566 + KEY_H)
    }

    /// One column: the two rows, three panels each (η = −1, 0, 1), the headings on three lines.
    fn single_size(&self) -> Option<(u32, u32)> {
        Some((super::Column::Single.width(), SINGLE_H))
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let narrow = column() == super::Column::Single;
        let caption = if narrow {
            format!(
                "Lloyd et al. 2006, Fig. 4, from the warped matrices: n\u{a0}=\u{a0}{n}, \
                 f\u{a0}=\u{a0}{f}, θ\u{a0}=\u{a0}{theta:.0}°, plane y\u{a0}=\u{a0}0, \
                 light overhead (eye x\u{a0}=\u{a0}light-view x). (a)–(c): the \
                 {LINES}\u{a0}×\u{a0}{LINES} texel grid from the light; (d)–(f): the \
                 frustum in the map, s,\u{a0}t\u{a0}∈\u{a0}[0,\u{a0}1].",
                n = self.view.near(),
                f = self.view.far(),
                theta = self.view.half_fov().to_degrees(),
            )
        } else {
            self.caption()
        };
        let body = frame(
            root,
            "The warped shadow map's grid as n′ goes from ∞ to n",
            &[caption.as_str()],
        )?;
        let (_, bh) = body.dim_in_pixel();
        let key_rows = draw_key(&body, narrow, false)?;
        let (body, key) = body.split_vertically(bh.saturating_sub(key_rows * KEY_H));
        self.draw_panels(&body, narrow)?;
        draw_key(&key, narrow, true).map(|_| ())
    }
}

/// The one-column figure's height: at most 525 units (420 points printed 240 wide).
const SINGLE_H: u32 = 500;

/// The height of a row of the key under the panels.
const KEY_H: u32 = 22;

/// The key's entries: text, colour, width, dashed. One per kind of line drawn: the frustum of
/// (a)–(d) and the map's square of (e)–(h) each have their own (figure review 4).
fn key_items(narrow: bool) -> [(&'static str, RGBColor, u32, bool); 5] {
    [
        ("texel grid", GRID_COLOUR, 1, false),
        ("frustum", BLACK, 2, false),
        ("map's square", SQUARE_COLOUR, SQUARE_WIDTH, false),
        ("constant depth", DEPTH_COLOUR, depth_width(narrow), false),
        ("ray from the eye", RAY_COLOUR, 1, true),
    ]
}

/// The key of the five kinds of line under the panels, in as few rows of [`KEY_H`] as fit the
/// width, each row centred, so that a figure without its caption still says what each line
/// is; returns its rows (drawing nothing when `draw` is false).
fn draw_key<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    narrow: bool,
    draw: bool,
) -> Result<u32, Fail> {
    let style = TextStyle::from((FONT, 13).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
    let items = key_items(narrow);
    let (sample, gap) = (20, 12);
    let mut widths = Vec::new();
    for (t, ..) in &items {
        let (w, _) = area
            .estimate_text_size(t, &style)
            .map_err(|e| Fail::Draw(e.to_string()))?;
        widths.push(sample + 4 + w as i32);
    }
    let (aw, _) = area.dim_in_pixel();
    // Greedy rows: each item on the current row while the row fits the width.
    let mut rows: Vec<Vec<usize>> = vec![Vec::new()];
    let mut used = 0;
    for (i, w) in widths.iter().enumerate() {
        let row = rows.last_mut().expect("a row");
        let need = if row.is_empty() { *w } else { used + gap + w };
        if !row.is_empty() && need > aw as i32 {
            rows.push(vec![i]);
            used = *w;
        } else {
            row.push(i);
            used = need;
        }
    }
    // The same number of rows, balanced (3 and 2, not 4 and 1) where the longer rows fit.
    let per = items.len().div_ceil(rows.len());
    let row_w =
        |r: &[usize]| r.iter().map(|&i| widths[i]).sum::<i32>() + gap * (r.len() as i32 - 1);
    let even: Vec<Vec<usize>> = (0..items.len())
        .collect::<Vec<_>>()
        .chunks(per)
        .map(<[usize]>::to_vec)
        .collect();
    if even.len() == rows.len() && even.iter().all(|r| row_w(r) <= aw as i32) {
        rows = even;
    }
    if !draw {
        return Ok(rows.len() as u32);
    }
    for (r, row) in rows.iter().enumerate() {
        let total = row_w(row);
        let mut x = (aw as i32 - total).max(0) / 2;
        let y = KEY_H as i32 * r as i32 + KEY_H as i32 / 2;
        for &i in row {
            let (t, colour, width, dashed) = items[i];
            let (a, b) = (
                (f64::from(x), f64::from(y)),
                (f64::from(x + sample), f64::from(y)),
            );
            let pieces = if dashed {
                dashes(a, b, RAY_DASH)
            } else {
                vec![[a, b]]
            };
            for [p, q] in pieces {
                area.draw(&PathElement::new(
                    vec![
                        (p.0.round() as i32, p.1.round() as i32),
                        (q.0.round() as i32, q.1.round() as i32),
                    ],
                    colour.stroke_width(width),
                ))?;
            }
            area.draw(&Text::new(
                t.to_string(),
                (x + sample + 4, y),
                style.clone(),
            ))?;
            x += widths[i] + gap;
        }
    }
    Ok(rows.len() as u32)
}

#[cfg(test)]
#[path = "warp_grid_tests.rs"]
mod review7_tests;

#[cfg(test)]
mod tests {
    use super::*;

    /// The warp's middle texel row, by hand: a perspective map along depth with its centre n′
    /// before the near plane puts t = ½ where 1/z′ = (1/n′ + 1/f′)/2, z′ = n′ + z − n,
    /// f′ = n′ + f − n. For LiSPSM (n′ = 1 + √10 at n = 1, f = 10) that is z = √(fn) = 3.162;
    /// unwarped it is the middle, z = 5.5. The map's ends, v = ±1 or u = ±1 along depth, are the
    /// near and far planes.
    #[test]
    fn middle_row_by_hand() {
        let fig = fig4().map_err(|e| e.named("lloyd2006-fig4")).unwrap();
        for (col, want) in [(0usize, 5.5f64), (2, 10f64.sqrt())] {
            let inv = fig.columns[col].to_eye;
            // Find which map axis runs along depth: the one whose ends are n and f at centre.
            let depth_at = |u: f64, v: f64| -apply(&inv, u, v).unwrap().1;
            let along_v = (depth_at(0.0, -1.0) - depth_at(0.0, 1.0)).abs();
            let along_u = (depth_at(-1.0, 0.0) - depth_at(1.0, 0.0)).abs();
            let (lo, mid, hi) = if along_v > along_u {
                (depth_at(0.0, -1.0), depth_at(0.0, 0.0), depth_at(0.0, 1.0))
            } else {
                (depth_at(-1.0, 0.0), depth_at(0.0, 0.0), depth_at(1.0, 0.0))
            };
            let (near, far) = (lo.min(hi), lo.max(hi));
            assert!(
                (near - 1.0).abs() < 1e-9 && (far - 10.0).abs() < 1e-9,
                "{near} {far}"
            );
            assert!(
                (mid - want).abs() < 1e-9,
                "column {col}: middle row at z = {mid}, want {want}"
            );
        }
    }

    /// A dash pattern by hand: a segment 0.1 long with dashes 0.035 on, 0.025 off gives dashes
    /// at [0, 0.035] and [0.06, 0.095].
    #[test]
    fn dashes_by_hand() {
        let d = dashes((0.0, 0.0), (0.0, 0.1), (0.035, 0.025));
        assert_eq!(d.len(), 2);
        assert!((d[0][1].1 - 0.035).abs() < 1e-12 && (d[1][0].1 - 0.06).abs() < 1e-12);
        assert!((d[1][1].1 - 0.095).abs() < 1e-12);
    }

    /// Figure reviews 2 and 3, in both layouts: the two families of (e)–(h) differ in dash, not
    /// only in hue (orange and green printed as one grey): every ray (7 a panel, 28 in all) is
    /// drawn in dashes, so the grey rays' pieces outnumber them several times, while the planes
    /// of constant depth are whole, solid, darker and twice as thick as the texel grid (review
    /// 3: the two were solid purples of one weight, and the key's swatches likewise); the
    /// column headings are one with their letters ("(a) η = −1" over "n′ = ∞" over "uniform",
    /// no "(a)" row of its own); the map panels say whose map they are ("(e) map of (a)", in one column "(d) map of
    /// (a)": review 3, the bare form's lower row had no stated relation to the upper; review 6,
    /// R6-lloyd2006-fig4-3, one column's row label was an in-figure caption); the
    /// caption calls the paper's figure a sketch; the key names all four lines in the bare
    /// figure too, one entry per kind of line (review 4); and one column has a layout 300 units
    /// wide and at most 525 tall, its panels in two rows of three (η = −1, 0, 1; review 4: four
    /// a row printed 40 pt wide), every panel lettered, its caption at most five lines.
    #[test]
    fn families_differ_in_dash_headings_merged_and_one_column_exists() {
        use super::super::chart::read_svg::{draw_svg, texts};
        use super::super::chart::with_page;
        use super::super::Column as Page;
        let fig = fig4().map_err(|e| e.named("lloyd2006-fig4")).unwrap();
        for (column, bare) in [
            (Page::Double, false),
            (Page::Double, true),
            (Page::Single, false),
            (Page::Single, true),
        ] {
            let size = match column {
                Page::Double => fig.size(),
                Page::Single => fig.single_size().expect("a one-column layout"),
            };
            assert!(
                size.1 <= if column == Page::Single { 525 } else { 800 },
                "{size:?}"
            );
            let svg = with_page(bare, column, || {
                draw_svg(size, |area| fig.draw(area).unwrap())
            });
            let lines_of = |hex: &str| {
                svg.lines()
                    .filter(|l| l.starts_with("<polyline") && l.contains(hex))
                    .count()
            };
            let width_of = |hex: &str| {
                let l = svg
                    .lines()
                    .find(|l| l.starts_with("<polyline") && l.contains(hex))
                    .unwrap_or_else(|| panic!("no line in {hex}"));
                let at = l.find("stroke-width=\"").unwrap() + "stroke-width=\"".len();
                l[at..at + l[at..].find('"').unwrap()]
                    .parse::<f64>()
                    .unwrap()
            };
            let rays = lines_of("stroke=\"#5A5A5A\"");
            let depths = lines_of("stroke=\"#3F007D\"");
            // 7 rays and 7 to 13 planes a panel (PSM's crowded ones left out), 4 panels (3 in
            // one column) and the key's; each ray in at least 5 dashes.
            let panels = if column == Page::Double { 4 } else { 3 };
            assert!(rays >= 5 * 7 * panels, "{column:?}: {rays} grey pieces");
            assert!(
                (7 * panels..=13 * panels + 1).contains(&depths),
                "{column:?}: {depths} depth lines"
            );
            // The depth planes (and their key swatch) twice the texel grid's width across two
            // columns; darker (#3F007D against #7B6DB4) in both.
            let want = if column == Page::Double { 2.0 } else { 1.0 };
            assert_eq!(width_of("stroke=\"#3F007D\""), want);
            assert_eq!(width_of("stroke=\"#7B6DB4\""), 1.0);
            // The map's square dark grey (#404040), not the frustum's black: one in each map
            // panel and the key's sample (figure review 5).
            assert_eq!(lines_of("stroke=\"#404040\""), panels + 1, "{column:?}");
            assert_eq!(width_of("stroke=\"#404040\""), 1.0);
            let all: Vec<String> = texts(&svg).into_iter().map(|t| t.1).collect();
            // One key entry per kind of line (figure review 4: "frustum, map's square" was one
            // entry for two).
            for key in [
                "texel grid",
                "frustum",
                "map's square",
                "constant depth",
                "ray from the eye",
            ] {
                assert!(
                    all.iter().any(|t| t.replace("&apos;", "'") == key),
                    "{column:?} {bare}: no key {key}"
                );
            }
            let caption: Vec<&String> = svg
                .lines()
                .filter(|l| l.contains("fill=\"#323232\""))
                .map(|_| &all[0])
                .collect();
            assert!(
                caption.len() <= 5,
                "{column:?}: {} caption lines",
                caption.len()
            );
            if column == Page::Double {
                // The scheme's name on a line of its own (R7-X-7: at the common title size
                // "(a) η = −1 (uniform)" on one line came within 9 units of "(b) η = −0.6").
                assert!(all.iter().any(|t| t == "(a) η = −1"), "{all:?}");
                assert!(all.iter().any(|t| t == "uniform"), "{all:?}");
                assert!(!all.iter().any(|t| t == "(a)"), "{all:?}");
                for title in ["(e) map of (a)", "(f) map of (b)", "(h) map of (d)"] {
                    assert!(all.iter().any(|t| t == title), "{title}: {all:?}");
                }
                if !bare {
                    let text: String = svg
                        .lines()
                        .filter(|l| l.contains("fill=\"#323232\""))
                        .map(|l| super::super::chart::read_svg::visible(l) + " ")
                        .collect();
                    assert!(text.contains("s,\u{a0}t\u{a0}∈\u{a0}[0,\u{a0}1]"), "{text}");
                    assert!(text.contains("schematic sketch"), "{text}");
                }
            } else {
                assert_eq!(size.0, 300);
                for title in ["(d) map of (a)", "(e) map of (b)", "(f) map of (c)"] {
                    assert!(all.iter().any(|t| t == title), "{title}: {all:?}");
                }
                for line in [
                    "(a) η = −1",
                    "n′ = ∞",
                    "uniform",
                    "(b) η = 0",
                    "n′ = 4.16",
                    "LiSPSM",
                    "(c) η = 1",
                    "PSM",
                ] {
                    assert!(all.iter().any(|t| t == line), "{line}: {all:?}");
                }
                assert!(!all.iter().any(|t| t.contains("−0.6")), "{all:?}");
            }
        }
    }
}
