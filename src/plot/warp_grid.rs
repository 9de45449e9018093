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
    build_chart_styled, clip_polyline, equal_aspect, frame, linspace, Axis, ChartStyle, FONT,
    PALETTE, PANEL_TITLE,
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
        // Two heading lines (split at "\n"); negative η with the minus sign U+2212.
        let name = match np.as_finite() {
            None => "η = −1 (uniform)\nn′ = ∞".to_string(),
            Some(v) if eta == 0.0 => format!("η = 0 (LiSPSM)\nn′ = {v:.2}"),
            Some(v) if eta == 1.0 => format!("η = 1 (PSM)\nn′ = n = {v:.0}"),
            Some(v) => minus(&format!("η = {eta}\nn′ = {v:.2}")),
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

impl Figure for Fig4 {
    fn size(&self) -> (u32, u32) {
        (520, 560)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let caption = format!(
            "Lloyd et al. 2006, Fig. 4, from the warped matrices: n = {n}, f = {f}, θ = \
             {theta:.0}°, light overhead, the plane y = 0; one column per n′. (a)–(d): from the light, \
             the map's {LINES} × {LINES} texel grid (blue) over the frustum (black), pressed to \
             the near plane by the warp. (e)–(h): in the map, the frustum's planes of constant depth \
             (orange) and rays from the eye (green). The paper's rows are sketches.",
            n = self.view.near(),
            f = self.view.far(),
            theta = self.view.half_fov().to_degrees(),
        );
        let body = frame(
            root,
            "The warped shadow map's grid as n′ goes from ∞ to n",
            &[caption.as_str()],
        )?;
        // Two rows (the light's view, the map), one column per n′, as in the paper; each column
        // headed by its η and n′ on two lines. The columns share their axes: only the first has
        // the y labels, and it is that much wider, so that every panel has the same scale.
        let (bw, bh) = body.dim_in_pixel();
        let head = 40;
        let label_w = 44;
        let count = self.columns.len() as u32;
        let pw = (bw - label_w) / count;
        let (n, f, t) = (self.view.near(), self.view.far(), self.view.tan_half_fov());
        let depth = Axis::linear("depth z", 0.0, f * 1.05);
        let across = Axis::linear("eye x", -f * t * 1.1, f * t * 1.1);
        // The map in the paper's texture coordinates s, t ∈ [0, 1] (the matrices' normalised
        // u, v ∈ [−1, 1] drawn at s = (u + 1)/2, t = (v + 1)/2).
        let u = Axis::linear("map s", -0.05, 1.05);
        let v = Axis::linear("map t", -0.05, 1.05);
        let st_of = |(a, b): (f64, f64)| (0.5 * (a + 1.0), 0.5 * (b + 1.0));
        // Ticks every 5 eye-space units and every map unit: the panels are narrow.
        let every = |a: Axis, step: f64| Axis::every(a.label, a.min, a.max, 0.0, step);
        let frustum = [
            (n, -n * t),
            (f, -f * t),
            (f, f * t),
            (n, n * t),
            (n, -n * t),
        ];
        let heading =
            TextStyle::from((FONT, 13).into_font()).pos(Pos::new(HPos::Center, VPos::Top));
        for (k, col) in self.columns.iter().enumerate() {
            let k = k as u32;
            let first = k == 0;
            let x0 = if first { 0 } else { label_w + k * pw };
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
            for (i, line) in col.title.split('\n').enumerate() {
                area.draw(&Text::new(
                    line.to_string(),
                    (x_mid, 16 * i as i32),
                    heading.clone(),
                ))?;
            }
            let rest = area.clone().shrink((0, head), (cw, bh - head));
            let rows = rest.split_evenly((2, 1));
            // Equal aspect in both rows: the frustum and the map undistorted.
            // Every panel lettered: (a)–(d) along the top row, (e)–(h) along the bottom.
            let letter = |row: u32| format!("({})", char::from(b'a' + (row * count + k) as u8));
            let (top_letter, bottom_letter) = (letter(0), letter(1));
            let (dx, dy) = equal_aspect(&rows[0], &top_letter, &depth, &across, &st)?;
            let (dx, dy) = (every(dx, 5.0), every(dy, 5.0));
            let mut chart = build_chart_styled(&rows[0], &top_letter, &dx, &dy, false, &st)?;
            let bounds = (0.0, f * 1.05, -f * t * 1.1, f * t * 1.1);
            for seg in &col.light_space {
                for piece in clip_polyline(&[Some(seg[0]), Some(seg[1])], bounds) {
                    chart.draw_series(LineSeries::new(piece, PALETTE[0].stroke_width(1)))?;
                }
            }
            chart.draw_series(LineSeries::new(frustum, BLACK.stroke_width(2)))?;
            let (ux, vy) = equal_aspect(&rows[1], &bottom_letter, &u, &v, &st)?;
            let (ux, vy) = (every(ux, 0.5), every(vy, 0.5));
            let mut chart = build_chart_styled(&rows[1], &bottom_letter, &ux, &vy, false, &st)?;
            chart.draw_series(LineSeries::new(
                UNIT_SQUARE.map(st_of),
                BLACK.stroke_width(2),
            ))?;
            for (i, seg) in col.map.iter().enumerate() {
                let colour = if i < LINES + 1 {
                    PALETTE[1]
                } else {
                    PALETTE[2]
                };
                for piece in clip_polyline(&[Some(seg[0]), Some(seg[1])], (-1.1, 1.1, -1.1, 1.1)) {
                    let piece: Vec<(f64, f64)> = piece.into_iter().map(st_of).collect();
                    chart.draw_series(LineSeries::new(piece, colour.stroke_width(1)))?;
                }
            }
        }
        Ok(())
    }
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
}
