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

/// The light travels straight down (−Y): overhead.
const OVERHEAD: DVec3 = DVec3::NEG_Y;

/// One column of the figure.
pub(super) struct Column {
    pub title: String,
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
        for c in linspace(-1.0, 1.0, LINES + 1) {
            if let (Some(p), Some(q)) = (to_map(n, c * n * t), to_map(f, c * f * t)) {
                map.push([p, q]);
            }
        }
        // The column's parameters: η (with its scheme's name) and n′, negative η with the
        // minus sign U+2212.
        let name = match np.as_finite() {
            None => "η = −1 (uniform), n′ = ∞".to_string(),
            Some(v) if eta == 0.0 => format!("η = 0 (LiSPSM), n′ = {v:.2}"),
            Some(v) if eta == 1.0 => format!("η = 1 (PSM), n′ = n = {v:.0}"),
            Some(v) => minus(&format!("η = {eta}, n′ = {v:.2}")),
        };
        columns.push(Column {
            title: name,
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

/// The texel grid of the map (panels (a)–(d)): a sweep colour, no scheme's.
const GRID_COLOUR: RGBColor = SWEEP[2];

/// The frustum's planes of constant depth in the map (panels (e)–(h)): solid, the sweep's
/// darkest.
const DEPTH_COLOUR: RGBColor = SWEEP[0];

/// The rays from the eye in the map (panels (e)–(h)): dashed grey, so that in greyscale they
/// differ from the planes of constant depth by more than their shade.
const RAY_COLOUR: RGBColor = SHARED;

/// The dash and gap of a ray, in map units (the map is 1.1 units across).
const RAY_DASH: (f64, f64) = (0.035, 0.025);

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

impl Fig4 {
    fn caption(&self) -> String {
        format!(
            "Lloyd et al. 2006, Fig. 4 (a schematic sketch there), from the warped matrices: \
             n\u{a0}=\u{a0}{n}, f\u{a0}=\u{a0}{f}, θ\u{a0}=\u{a0}{theta:.0}°, light \
             overhead, the plane y\u{a0}=\u{a0}0. (a)–(d): from the light, the map's \
             {LINES}\u{a0}×\u{a0}{LINES} texel grid over the view frustum, pressed to the near \
             plane by the warp. (e)–(h): in the map, s,\u{a0}t\u{a0}∈\u{a0}[0,\u{a0}1], the \
             frustum's planes of constant depth (solid) and rays from the eye (dashed).",
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

    /// Column `k`'s light-space panel on `area`: the map's texel grid over the frustum, with
    /// the equal-aspect axes of `x`, `y` ticked every 5 units.
    fn draw_light<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        k: usize,
        title: &str,
        st: &ChartStyle,
    ) -> Result<(), Fail> {
        let [depth, across, _, _] = self.axes();
        let (n, f, t) = (self.view.near(), self.view.far(), self.view.tan_half_fov());
        let (dx, dy) = equal_aspect(area, title, &depth, &across, st)?;
        let every = |a: Axis, step: f64| Axis::every(a.label, a.min, a.max, 0.0, step);
        let (dx, dy) = (every(dx, 5.0), every(dy, 5.0));
        let mut chart = build_chart_styled(area, title, &dx, &dy, false, st)?;
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
    ) -> Result<(), Fail> {
        let [_, _, u, v] = self.axes();
        let st_of = |(a, b): (f64, f64)| (0.5 * (a + 1.0), 0.5 * (b + 1.0));
        let (ux, vy) = equal_aspect(area, title, &u, &v, st)?;
        let every = |a: Axis, step: f64| Axis::every(a.label, a.min, a.max, 0.0, step);
        let (ux, vy) = (every(ux, 0.5), every(vy, 0.5));
        let mut chart = build_chart_styled(area, title, &ux, &vy, false, st)?;
        chart.draw_series(LineSeries::new(
            UNIT_SQUARE.map(st_of),
            BLACK.stroke_width(2),
        ))?;
        for (i, seg) in self.columns[k].map.iter().enumerate() {
            let ray = i > LINES;
            for piece in clip_polyline(&[Some(seg[0]), Some(seg[1])], (-1.1, 1.1, -1.1, 1.1)) {
                let (a, b) = (st_of(piece[0]), st_of(piece[piece.len() - 1]));
                if ray {
                    for d in dashes(a, b, RAY_DASH) {
                        chart.draw_series(LineSeries::new(d, RAY_COLOUR.stroke_width(1)))?;
                    }
                } else {
                    chart.draw_series(LineSeries::new([a, b], DEPTH_COLOUR.stroke_width(1)))?;
                }
            }
        }
        Ok(())
    }
}

impl Figure for Fig4 {
    fn size(&self) -> (u32, u32) {
        (520, 540)
    }

    /// One column: a row per n′, its light-space panel left of its map panel, the rows sharing
    /// their x axes (labelled under the last row).
    fn single_size(&self) -> Option<(u32, u32)> {
        Some((super::Column::Single.width(), SINGLE_H))
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        if column() == super::Column::Single {
            return self.draw_single(root);
        }
        let caption = self.caption();
        let body = frame(
            root,
            "The warped shadow map's grid as n′ goes from ∞ to n",
            &[caption.as_str()],
        )?;
        let (body, key) = {
            let (_, bh) = body.dim_in_pixel();
            body.split_vertically(bh.saturating_sub(KEY_H))
        };
        // Two rows (the light's view, the map), one column per n′, as in the paper; each column
        // headed by its letter, η and n′ on two lines. The columns share their axes: only the
        // first has the y labels, and it is that much wider, so that every panel has the same
        // scale.
        let (bw, bh) = body.dim_in_pixel();
        let head = 36;
        let label_w = 44;
        let count = self.columns.len() as u32;
        let pw = (bw - label_w) / count;
        let heading =
            TextStyle::from((FONT, 13).into_font()).pos(Pos::new(HPos::Center, VPos::Top));
        for (k, col) in self.columns.iter().enumerate() {
            let kk = k as u32;
            let first = kk == 0;
            let x0 = if first { 0 } else { label_w + kk * pw };
            let cw = pw + if first { label_w } else { 0 };
            let area = body.clone().shrink((x0, 0), (cw, bh));
            let st = ChartStyle {
                title_size: PANEL_TITLE,
                x_label_area: 36,
                y_label_area: if first { label_w } else { 0 },
                tick_size: 13,
                desc_size: 13,
                margin: 7,
            };
            let x_mid = (cw - pw + pw / 2) as i32;
            let letter = |row: u32| format!("({})", char::from(b'a' + (row * count + kk) as u8));
            // "(a) η = −1 (uniform)" over "n′ = ∞".
            let (eta, np) = col.title.split_once(", ").unwrap_or((&col.title, ""));
            for (i, line) in [format!("{} {eta}", letter(0)), np.to_string()]
                .into_iter()
                .enumerate()
            {
                area.draw(&Text::new(line, (x_mid, 16 * i as i32), heading.clone()))?;
            }
            let rest = area.clone().shrink((0, head), (cw, bh - head));
            // The map row a little taller: it has a title and the light row none.
            let (_, rh) = rest.dim_in_pixel();
            let (top, bottom) = rest.split_vertically(rh * 47 / 100);
            let rows = [top, bottom];
            // Equal aspect in both rows: the frustum and the map undistorted.
            self.draw_light(&rows[0], k, "", &st)?;
            self.draw_map(&rows[1], k, &letter(1), &st)?;
        }
        draw_key(&key)
    }
}

/// The one-column figure's height: at most 800 units (640 points printed 240 wide).
const SINGLE_H: u32 = 800;

impl Fig4 {
    /// The one-column layout: a row per column of the two-column figure, headed by its letters,
    /// η and n′ on one line, the light-space panel (a)–(d) left of the map panel (e)–(h); the
    /// rows share their x axes, labelled under the last row only, so every panel of a kind has
    /// the same scale; the key in two rows under them.
    fn draw_single<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let caption = format!(
            "Lloyd et al. 2006, Fig. 4, from the warped matrices: n\u{a0}=\u{a0}{n}, \
             f\u{a0}=\u{a0}{f}, θ\u{a0}=\u{a0}{theta:.0}°, light overhead, plane \
             y\u{a0}=\u{a0}0. (a)–(d): the {LINES}\u{a0}×\u{a0}{LINES} texel grid over the \
             frustum, from the light; (e)–(h): the frustum in the map.",
            n = self.view.near(),
            f = self.view.far(),
            theta = self.view.half_fov().to_degrees(),
        );
        let body = frame(
            root,
            "The warped shadow map's grid as n′ goes from ∞ to n",
            &[caption.as_str()],
        )?;
        let (_, bh) = body.dim_in_pixel();
        let (body, key) = body.split_vertically(bh.saturating_sub(2 * KEY_H));
        let (bw, bh) = body.dim_in_pixel();
        let (head, x_labels) = (24u32, 36u32);
        let count = self.columns.len() as u32;
        let row_h = (bh - x_labels) / count;
        let (light_label, map_label) = (48u32, 48u32);
        // The two panels' plots equally wide: the light panel's area is wider by its y labels'.
        let left_w = (bw + light_label - map_label) / 2;
        let heading =
            TextStyle::from((FONT, 13).into_font()).pos(Pos::new(HPos::Center, VPos::Top));
        for (k, col) in self.columns.iter().enumerate() {
            let kk = k as u32;
            let last = kk + 1 == count;
            let y0 = kk * row_h;
            let h = row_h + if last { x_labels } else { 0 };
            let row = body.clone().shrink((0, y0), (bw, h));
            let letter = |r: u32| char::from(b'a' + (r * count + kk) as u8);
            row.draw(&Text::new(
                format!("({}), ({}): {}", letter(0), letter(1), col.title),
                (bw as i32 / 2, 5),
                heading.clone(),
            ))?;
            let panels = row.clone().shrink((0, head), (bw, h - head));
            let (left, right) = panels.split_horizontally(left_w);
            let st = |y_label_area: u32| ChartStyle {
                title_size: PANEL_TITLE,
                x_label_area: if last { x_labels } else { 0 },
                y_label_area,
                tick_size: 13,
                desc_size: 13,
                margin: 7,
            };
            self.draw_light(&left, k, "", &st(light_label))?;
            self.draw_map(&right, k, "", &st(map_label))?;
        }
        draw_key(&key)
    }
}

/// The height of the key under the panels.
const KEY_H: u32 = 22;

/// The key of the four kinds of line under the panels, in as few rows of [`KEY_H`] as fit the
/// width (one across two columns, two in one), so that a figure without its caption still says
/// what each line is.
fn draw_key<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
    let style = TextStyle::from((FONT, 13).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
    let items: [(&str, RGBColor, u32, bool); 4] = [
        ("texel grid", GRID_COLOUR, 1, false),
        ("frustum, map's square", BLACK, 2, false),
        ("constant depth", DEPTH_COLOUR, 1, false),
        ("ray from the eye", RAY_COLOUR, 1, true),
    ];
    let sample = 22;
    let gap = 14;
    let mut widths = Vec::new();
    for (t, ..) in &items {
        let (w, _) = area
            .estimate_text_size(t, &style)
            .map_err(|e| Fail::Draw(e.to_string()))?;
        widths.push(sample + 4 + w as i32);
    }
    let (aw, _) = area.dim_in_pixel();
    let total = widths.iter().sum::<i32>() + gap * (items.len() as i32 - 1);
    let per_row = if total <= aw as i32 { items.len() } else { 2 };
    for (r, (row, ws)) in items
        .chunks(per_row)
        .zip(widths.chunks(per_row))
        .enumerate()
    {
        let total = ws.iter().sum::<i32>() + gap * (ws.len() as i32 - 1);
        let mut x = (aw as i32 - total).max(0) / 2;
        let y = KEY_H as i32 * r as i32 + KEY_H as i32 / 2;
        for ((t, colour, width, dashed), w) in row.iter().zip(ws) {
            let (a, b) = (
                (f64::from(x), f64::from(y)),
                (f64::from(x + sample), f64::from(y)),
            );
            let pieces = if *dashed {
                dashes(a, b, (4.0, 3.0))
            } else {
                vec![[a, b]]
            };
            for [p, q] in pieces {
                area.draw(&PathElement::new(
                    vec![
                        (p.0.round() as i32, p.1.round() as i32),
                        (q.0.round() as i32, q.1.round() as i32),
                    ],
                    colour.stroke_width(*width),
                ))?;
            }
            area.draw(&Text::new(
                t.to_string(),
                (x + sample + 4, y),
                style.clone(),
            ))?;
            x += w + gap;
        }
    }
    Ok(())
}

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

    /// Figure review 2, in both layouts: the two families of (e)–(h) differ in dash, not only in
    /// hue (orange and green printed as one grey): every ray (13 a panel, 52 in all) is drawn
    /// in dashes, so the grey rays' pieces outnumber them several times, while the planes of
    /// constant depth are whole, solid and darker; the column headings are one with their
    /// letters ("(a) η = −1 (uniform)", no "(a)" row of its own); the caption says what the
    /// black square is and calls the paper's figure a sketch; the key names all four lines in
    /// the bare figure too; and one column has a layout (it was refused) 300 units wide and at
    /// most 800 tall, its x axes shared (one "depth z" and one "map s"), every panel lettered,
    /// its caption at most five lines.
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
        ] {
            let size = match column {
                Page::Double => fig.size(),
                Page::Single => fig.single_size().expect("a one-column layout"),
            };
            assert!(size.1 <= 800, "{size:?}");
            let svg = with_page(bare, column, || {
                draw_svg(size, |area| fig.draw(area).unwrap())
            });
            let lines_of = |hex: &str| {
                svg.lines()
                    .filter(|l| l.starts_with("<polyline") && l.contains(hex))
                    .count()
            };
            let rays = lines_of("stroke=\"#5A5A5A\"");
            let depths = lines_of("stroke=\"#3F007D\"");
            // 13 rays and 13 planes a panel, 4 panels; each ray in at least 5 dashes.
            assert!(rays >= 5 * 52, "{column:?}: {rays} grey pieces");
            assert!(
                (4 * 13..2 * 52).contains(&depths),
                "{column:?}: {depths} depth lines"
            );
            let all: Vec<String> = texts(&svg).into_iter().map(|t| t.1).collect();
            for key in [
                "texel grid",
                "frustum, map",
                "constant depth",
                "ray from the eye",
            ] {
                assert!(
                    all.iter().any(|t| t.starts_with(key)),
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
                assert!(all.iter().any(|t| t == "(a) η = −1 (uniform)"), "{all:?}");
                assert!(!all.iter().any(|t| t == "(a)"), "{all:?}");
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
                assert_eq!(all.iter().filter(|t| *t == "depth z").count(), 1, "{all:?}");
                assert_eq!(all.iter().filter(|t| *t == "map s").count(), 1, "{all:?}");
                for letters in ["(a), (e)", "(b), (f)", "(c), (g)", "(d), (h)"] {
                    assert!(
                        all.iter().any(|t| t.starts_with(letters)),
                        "{letters}: {all:?}"
                    );
                }
            }
        }
    }
}
