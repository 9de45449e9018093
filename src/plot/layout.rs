//! Lloyd et al. 2005 Fig 8: (a) the face partitions seen from the light, (b) one partition's
//! warped map over it, (c) the texture layout. The crate's scheme ([`crate::scheme::scheme`], face
//! partitions with k z-partitions each, LiSPSM-warped) is measured per partition and packed into
//! one texture by [`crate::scheme::SchemeResult::atlas`] (Lloyd 2005 Eq 6: the width split among
//! the face pairs by their largest M_x, each column's height among its members by M_z).

use super::chart::{
    build_chart_styled, equal_aspect, frame, linspace, Axis, ChartStyle, FONT, PALETTE, PANEL_TITLE,
};
use super::from_light::{seen_from_light, SEEN_X};
use super::warp_grid::minus;
use super::{Fail, Figure};
use crate::maps::atlas::Viewport;
use crate::maps::faces::Face;
use crate::maps::{light_space, WarpRule};
use crate::scheme::{scheme, Partition, Region};
use crate::ViewFrustum;
use glam::{DMat3, DMat4, DVec2, DVec3};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Texture size in texels.
pub(super) const SIZE: u32 = 2048;

/// The light: elevation above the horizon and azimuth round from straight behind the viewer
/// towards its right, in degrees. Nearly behind, so that the left and right faces are both seen
/// and have different M_z (the paper's "trade off between opposite sides").
pub(super) const LIGHT: (f64, f64) = (35.0, 10.0);

/// The far plane (n = 1): f/n = 10, so that the near z-partitions, a factor √10 smaller than
/// the far ones, still show in panel (a).
const FAR: f64 = 10.0;

/// The eye's near plane and half field of view θ (degrees).
const NEAR: f64 = 1.0;
const THETA_DEG: f64 = 30.0;

/// Lines of the map's texel grid drawn in panel (b), per direction.
const GRID: usize = 9;

/// One partition: where it lies in the texture and seen from the light.
pub(super) struct Cell {
    pub viewport: Viewport,
    /// Its short tag (R1, L2, N: face initial and z-partition) and its face and depth range.
    pub tag: String,
    pub label: String,
    pub mx: f64,
    pub mz: f64,
    /// Its face part's corners seen from the light (light-space −x, z: [`seen_from_light`]).
    pub outline: Vec<DVec2>,
    /// Its map (eye → light clip).
    pub matrix: DMat4,
}

pub(super) struct Fig8 {
    pub cells: Vec<Cell>,
    pub k: usize,
    /// The light-space frame of panels (a) and (b): eye-space x, y (toward the light), z axes.
    pub frame: [DVec3; 3],
    /// The partition whose map panel (b) draws.
    pub shown: usize,
}

/// A depth with at most two decimals, trailing zeros dropped.
fn fmt_depth(z: f64) -> String {
    let s = format!("{z:.2}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

fn face_name(r: Region) -> &'static str {
    match r {
        Region::Frustum => "frustum",
        Region::Face(f) => f.name(),
    }
}

pub(super) fn fig8() -> Result<Fig8, Fail> {
    let view = ViewFrustum::new(NEAR, FAR, THETA_DEG.to_radians())?;
    let (el, az) = (LIGHT.0.to_radians(), LIGHT.1.to_radians());
    let light = -DVec3::new(el.cos() * az.sin(), el.sin(), el.cos() * az.cos());
    let k = 2;
    let s = scheme(&view, light, WarpRule::Lispsm, Partition::Faces, k)?;
    let atlas = s.atlas(SIZE, SIZE)?;
    let ls = light_space(light, DVec3::NEG_Z)?;
    let mut count = std::collections::HashMap::new();
    let mut cells = Vec::new();
    for (p, v) in s.partitions().iter().zip(atlas.viewports()) {
        let face = match p.region {
            Region::Face(f) => f,
            Region::Frustum => Face::Near,
        };
        let name = face_name(p.region);
        let (tag, label) = if p.far > p.near {
            let i = count.entry(name).or_insert(0);
            *i += 1;
            (
                format!("{}{i}", name[..1].to_uppercase()),
                minus(&format!(
                    "{name}, z {}–{}",
                    fmt_depth(p.near),
                    fmt_depth(p.far)
                )),
            )
        } else {
            ("N".to_string(), format!("{name} face"))
        };
        let outline = face
            .vertices(&view, p.near, p.far)
            .iter()
            .map(|&c| seen_from_light(ls.to_light(c)))
            .collect();
        cells.push(Cell {
            viewport: *v,
            tag,
            label,
            mx: p.max_mx,
            mz: p.max_mz,
            outline,
            matrix: p.matrix,
        });
    }
    // Panel (b) shows the far part of the right face.
    let shown = cells.iter().position(|c| c.tag == "R2").unwrap_or(0);
    Ok(Fig8 {
        cells,
        k,
        frame: [ls.x, ls.y, ls.z],
        shown,
    })
}

impl Fig8 {
    /// The map of partition `i` on the light's view: the light's (right, up) = light-space
    /// (−x, z) of [`seen_from_light`] ↦ its map's (u, v), a 2D projective map (the map's u and
    /// v are constant along the light, so any light-space height gives the same one; the eye's,
    /// 0, is used).
    pub(super) fn light_to_map(&self, i: usize) -> DMat3 {
        let m = self.cells[i].matrix;
        let [x, _, z] = self.frame;
        let x = -x;
        let col = |v: glam::DVec4| DVec3::new(v.x, v.y, v.w);
        DMat3::from_cols(
            col(m * x.extend(0.0)),
            col(m * z.extend(0.0)),
            col(m * glam::DVec4::W),
        )
    }
}

/// Whether `p` lies inside the convex polygon `poly` (either orientation).
fn inside(poly: &[DVec2], p: DVec2) -> bool {
    let n = poly.len();
    let sides: Vec<f64> = (0..n)
        .map(|i| (poly[(i + 1) % n] - poly[i]).perp_dot(p - poly[i]))
        .collect();
    sides.iter().all(|&s| s >= 0.0) || sides.iter().all(|&s| s <= 0.0)
}

fn apply(h: &DMat3, p: DVec2) -> DVec2 {
    let q = *h * p.extend(1.0);
    DVec2::new(q.x / q.z, q.y / q.z)
}

impl Figure for Fig8 {
    fn size(&self) -> (u32, u32) {
        (520, 874)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let shown = &self.cells[self.shown];
        let caption = format!(
            "Lloyd et al. 2005, Fig. 8: face partitions with k = {} z-partitions each, \
             LiSPSM-warped, n = {NEAR}, f = {FAR}, θ = {THETA_DEG}°, light {}° high, {}° right of \
             behind. (a) From the light (R, L, T, N: right, left, top, near face; 1 near, 2 far). \
             (b) {} and its map's texel grid. (c) The texture by Eq 6: \"share\" is a partition's \
             part of its width × height, \"after\" its M_x and M_z over those parts.",
            self.k, LIGHT.0, LIGHT.1, shown.tag,
        );
        let body = frame(
            root,
            "Partitions, warp and texture layout",
            &[caption.as_str()],
        )?;
        let (bw, _) = body.dim_in_pixel();
        let (top, bottom) = body.split_vertically(bw / 2);
        let halves = top.split_evenly((1, 2));
        let style = ChartStyle {
            title_size: PANEL_TITLE,
            x_label_area: 40,
            y_label_area: 48,
            tick_size: 13,
            desc_size: 13,
            margin: 6,
        };
        self.draw_faces(&halves[0], &style)?;
        self.draw_warp(&halves[1], &style)?;
        self.draw_texture(&bottom)
    }
}

impl Fig8 {
    /// The bounding box of some light-space points, widened by 6 % on each side.
    fn window(points: impl Iterator<Item = DVec2>) -> (DVec2, DVec2) {
        let (lo, hi) = points.fold(
            (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
            |(lo, hi), p| (lo.min(p), hi.max(p)),
        );
        let pad = 0.06 * (hi - lo).max_element();
        (lo - pad, hi + pad)
    }

    /// (a): every partition's face part seen from the light, filled in its colour, with its tag.
    fn draw_faces<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        style: &ChartStyle,
    ) -> Result<(), Fail> {
        let (lo, hi) = Self::window(self.cells.iter().flat_map(|c| c.outline.iter().copied()));
        // Room under the drawing for the tags of parts too small to hold them.
        let lo = lo - DVec2::new(0.0, 0.1 * (hi.y - lo.y));
        let title = "(a) seen from the light";
        let (xa, ya) = equal_aspect(
            area,
            title,
            &Axis::linear(SEEN_X, lo.x, hi.x),
            &Axis::linear("light z", lo.y, hi.y),
            style,
        )?;
        let mut chart = build_chart_styled(area, title, &xa, &ya, false, style)?;
        for (i, c) in self.cells.iter().enumerate() {
            let pts: Vec<(f64, f64)> = c.outline.iter().map(|p| (p.x, p.y)).collect();
            let colour = PALETTE[i % PALETTE.len()];
            chart.draw_series(std::iter::once(Polygon::new(
                pts.clone(),
                colour.mix(0.35).filled(),
            )))?;
            let mut closed = pts;
            closed.push(closed[0]);
            chart.draw_series(LineSeries::new(closed, BLACK.stroke_width(1)))?;
        }
        // Tags at the parts' centres where they fit inside the part (with a margin), last so
        // that no fill covers them; a part too small for its tag gets it outside the drawing,
        // away from the drawing's centre, joined to the part by a leader.
        let tag_style =
            TextStyle::from((FONT, 13).into_font()).pos(Pos::new(HPos::Center, VPos::Center));
        let (pw, _) = chart.plotting_area().dim_in_pixel();
        let per_px = (xa.max - xa.min) / f64::from(pw);
        // The row under the drawing for the tags that do not fit.
        let bottom = self
            .cells
            .iter()
            .flat_map(|c| c.outline.iter().map(|p| p.y))
            .fold(f64::INFINITY, f64::min);
        let mut outside: Vec<(DVec2, f64, &str)> = Vec::new();
        for c in &self.cells {
            let mid = c.outline.iter().copied().sum::<DVec2>() / c.outline.len() as f64;
            let (tw, th) = area
                .estimate_text_size(&c.tag, &tag_style)
                .map_err(|e| Fail::Draw(e.to_string()))?;
            let half = DVec2::new(f64::from(tw) + 4.0, f64::from(th) + 2.0) * 0.5 * per_px;
            let fits = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
                .iter()
                .all(|&(sx, sy)| inside(&c.outline, mid + DVec2::new(sx * half.x, sy * half.y)));
            if fits {
                chart.draw_series(std::iter::once(Text::new(
                    c.tag.clone(),
                    (mid.x, mid.y),
                    tag_style.clone(),
                )))?;
            } else {
                outside.push((mid, half.x, c.tag.as_str()));
            }
        }
        // Left to right under the drawing, each at least its width from the one before,
        // joined to its part by a leader.
        outside.sort_by(|a, b| a.0.x.total_cmp(&b.0.x));
        let y = bottom - 12.0 * per_px;
        let mut next = f64::NEG_INFINITY;
        for (mid, hw, tag) in outside {
            let x = mid.x.max(next + hw);
            next = x + hw + 6.0 * per_px;
            chart.draw_series(LineSeries::new(
                [(mid.x, mid.y), (x, y + 6.0 * per_px)],
                RGBColor(90, 90, 90).stroke_width(1),
            ))?;
            chart.draw_series(std::iter::once(Text::new(
                tag.to_string(),
                (x, y),
                tag_style.pos(Pos::new(HPos::Center, VPos::Top)),
            )))?;
        }
        Ok(())
    }

    /// (b): one partition with its map's texel grid and border, in the light's view.
    fn draw_warp<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        style: &ChartStyle,
    ) -> Result<(), Fail> {
        let cell = &self.cells[self.shown];
        let to_map = self.light_to_map(self.shown);
        let to_light = to_map.inverse();
        let border: Vec<DVec2> = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
            .iter()
            .map(|&(u, v)| apply(&to_light, DVec2::new(u, v)))
            .collect();
        let (lo, hi) = Self::window(cell.outline.iter().chain(&border).copied());
        let title = format!("(b) the map of {}", cell.tag);
        let (xa, ya) = equal_aspect(
            area,
            &title,
            &Axis::linear(SEEN_X, lo.x, hi.x),
            &Axis::linear("light z", lo.y, hi.y),
            style,
        )?;
        let mut chart = build_chart_styled(area, &title, &xa, &ya, false, style)?;
        let pts: Vec<(f64, f64)> = cell.outline.iter().map(|p| (p.x, p.y)).collect();
        chart.draw_series(std::iter::once(Polygon::new(
            pts.clone(),
            PALETTE[self.shown % PALETTE.len()].mix(0.35).filled(),
        )))?;
        for c in linspace(-1.0, 1.0, GRID) {
            for (a, b) in [((c, -1.0), (c, 1.0)), ((-1.0, c), (1.0, c))] {
                let (p, q) = (
                    apply(&to_light, DVec2::new(a.0, a.1)),
                    apply(&to_light, DVec2::new(b.0, b.1)),
                );
                chart.draw_series(LineSeries::new(
                    [(p.x, p.y), (q.x, q.y)],
                    PALETTE[0].stroke_width(1),
                ))?;
            }
        }
        let mut closed = pts;
        closed.push(closed[0]);
        chart.draw_series(LineSeries::new(closed, BLACK.stroke_width(2)))?;
        Ok(())
    }

    /// (c): the texture, square, each partition's rectangle with its numbers.
    fn draw_texture<DB: DrawingBackend>(&self, body: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let n = f64::from(SIZE);
        let style = ChartStyle {
            title_size: PANEL_TITLE,
            ..ChartStyle::default()
        };
        let title = "(c) the texture layout by Eq 6";
        // Equal aspect: the square texture drawn square.
        let (xa, ya) = equal_aspect(
            body,
            title,
            &Axis::linear("s (texels)", 0.0, n),
            &Axis::linear("t (texels)", 0.0, n),
            &style,
        )?;
        let mut chart = build_chart_styled(body, title, &xa, &ya, false, &style)?;
        for (i, c) in self.cells.iter().enumerate() {
            let v = c.viewport;
            let (mx, mz) = (c.mx, c.mz);
            let (x0, y0) = (f64::from(v.x), f64::from(v.y));
            let (x1, y1) = (x0 + f64::from(v.width), y0 + f64::from(v.height));
            let colour = PALETTE[i % PALETTE.len()];
            chart.draw_series([
                Rectangle::new([(x0, y0), (x1, y1)], colour.mix(0.35).filled()),
                Rectangle::new([(x0, y0), (x1, y1)], BLACK.stroke_width(1)),
            ])?;
            // The error after allocation: each partition's M_x and M_z over its share of the
            // texture's width and height (Eq 6 makes the first equal across columns and the
            // second within a column).
            let (sw, sh) = ((x1 - x0) / n, (y1 - y0) / n);
            let mut lines = vec![
                format!("{}: {}", c.tag, c.label),
                format!("M_x {mx:.2}, M_z {mz:.2}"),
                format!("share {:.0} % × {:.0} %", 100.0 * sw, 100.0 * sh),
                format!("after: {:.2} × {:.2}", mx / sw, mz / sh),
            ];
            // A narrow column's text runs up it, in two lines.
            let narrow = sw < 0.25;
            if narrow {
                lines = vec![
                    format!("{}: {}, M_x {mx:.2}, M_z {mz:.2}", c.tag, c.label),
                    format!(
                        "share {:.0} % × {:.0} %, after: {:.2} × {:.2}",
                        100.0 * sw,
                        100.0 * sh,
                        mx / sw,
                        mz / sh
                    ),
                ];
            }
            let mut text =
                TextStyle::from((FONT, 13).into_font()).pos(Pos::new(HPos::Center, VPos::Center));
            if narrow {
                text = text.transform(FontTransform::Rotate270);
            }
            let (cx, cy) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
            // Lines 16 units apart, in texels of the axis drawn across them (the axes' ranges,
            // widened for the equal aspect, not the texture's size).
            let (pw, ph) = chart.plotting_area().dim_in_pixel();
            let step = if narrow {
                16.0 * (xa.max - xa.min) / f64::from(pw)
            } else {
                16.0 * (ya.max - ya.min) / f64::from(ph)
            };
            for (j, line) in lines.iter().enumerate() {
                let off = (0.5 * (lines.len() - 1) as f64 - j as f64) * step;
                let at = if narrow {
                    (cx - off, cy)
                } else {
                    (cx, cy + off)
                };
                chart.draw_series(std::iter::once(Text::new(minus(line), at, text.clone())))?;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rectangles tile the texture, and Eq 6 holds within a texel: in a column the heights are
    /// SIZE · M_z / Σ M_z of its members (Lloyd 2005 Eq 6, computed here from the partitions'
    /// errors).
    #[test]
    fn layout_tiles_the_texture_by_eq6() {
        let fig = fig8().map_err(|e| e.named("lloyd2005-fig8")).unwrap();
        let total: u64 = fig
            .cells
            .iter()
            .map(|c| u64::from(c.viewport.width) * u64::from(c.viewport.height))
            .sum();
        assert_eq!(total, u64::from(SIZE) * u64::from(SIZE));
        let mut columns: std::collections::BTreeMap<u32, Vec<(u32, f64)>> = Default::default();
        for c in &fig.cells {
            columns
                .entry(c.viewport.x)
                .or_default()
                .push((c.viewport.height, c.mz));
        }
        assert!(columns.len() >= 2);
        for members in columns.values() {
            let sum: f64 = members.iter().map(|m| m.1).sum();
            for &(h, mz) in members {
                let want = f64::from(SIZE) * mz / sum;
                assert!((f64::from(h) - want).abs() < 1.0, "{h} vs {want}");
            }
        }
    }

    /// The errors written after allocation (issue 25): M_x over the width share is one value in
    /// every rectangle (Eq 6 shares the width by M_x: the error is Σ M_x over the columns' largest
    /// M_x, computed here), and M_z over the height share one value within each column.
    #[test]
    fn errors_after_allocation_are_equalised() {
        let fig = fig8().map_err(|e| e.named("lloyd2005-fig8")).unwrap();
        let n = f64::from(SIZE);
        let mut columns: std::collections::BTreeMap<u32, (f64, Vec<f64>)> = Default::default();
        for c in &fig.cells {
            let e = columns.entry(c.viewport.x).or_insert((0.0, Vec::new()));
            e.0 = e.0.max(c.mx);
            e.1.push(c.mz / (f64::from(c.viewport.height) / n));
        }
        let want_x: f64 = columns.values().map(|c| c.0).sum();
        for c in &fig.cells {
            let (v, mx) = (&c.viewport, &c.mx);
            let col_max = columns[&v.x].0;
            let after = col_max / (f64::from(v.width) / n);
            assert!(
                (after - want_x).abs() < 0.01 * want_x,
                "{after} vs {want_x}"
            );
            assert!(*mx <= col_max);
        }
        for (_, zs) in columns.values() {
            assert!(
                zs.iter().all(|z| (z - zs[0]).abs() < 0.01 * zs[0]),
                "{zs:?}"
            );
        }
    }

    /// Issue 25: the paper's rule (heights by each partition's error) shows: the light sees the
    /// left and right faces, whose M_z differ, so the left/right column's heights differ by
    /// more than a third, and each column's heights still sum to the texture (Eq 6's shares).
    #[test]
    fn heights_differ_where_m_z_differs() {
        let fig = fig8().map_err(|e| e.named("lloyd2005-fig8")).unwrap();
        let mut columns: std::collections::BTreeMap<u32, Vec<&Cell>> = Default::default();
        for c in &fig.cells {
            columns.entry(c.viewport.x).or_default().push(c);
        }
        let pair = columns
            .values()
            .find(|m| {
                m.iter().any(|c| c.tag.starts_with('L')) && m.iter().any(|c| c.tag.starts_with('R'))
            })
            .expect("a column with the left and right faces");
        let (l, r) = (
            pair.iter().find(|c| c.tag == "L1").unwrap(),
            pair.iter().find(|c| c.tag == "R1").unwrap(),
        );
        let (hl, hr) = (f64::from(l.viewport.height), f64::from(r.viewport.height));
        assert!(hr > 1.33 * hl, "right {hr} vs left {hl}");
        // Eq 6 by hand: height ∝ M_z within the column.
        assert!((hr / hl - r.mz / l.mz).abs() < 0.01 * r.mz / l.mz);
        for members in columns.values() {
            let sum: u32 = members.iter().map(|c| c.viewport.height).sum();
            assert_eq!(sum, SIZE);
        }
        let widths: u32 = columns.values().map(|m| m[0].viewport.width).sum();
        assert_eq!(widths, SIZE);
    }

    /// Panel (a) is not mirrored (figure review 2): the light is behind the viewer, 10° round
    /// towards its right and 35° up, so an observer at the light faces roughly along the view
    /// direction and sees the eye's right face (R1, R2) right of its left face (L1, L2), by
    /// hand; the old (x, z) drawing put R left of L.
    #[test]
    fn the_right_face_is_on_the_lights_right() {
        let fig = fig8().map_err(|e| e.named("lloyd2005-fig8")).unwrap();
        let mean_x = |face: char| {
            let xs: Vec<f64> = fig
                .cells
                .iter()
                .filter(|c| c.tag.starts_with(face))
                .flat_map(|c| c.outline.iter().map(|p| p.x))
                .collect();
            assert!(!xs.is_empty(), "no {face} cells");
            xs.iter().sum::<f64>() / xs.len() as f64
        };
        assert!(
            mean_x('R') > 0.0 && mean_x('L') < 0.0,
            "{} {}",
            mean_x('R'),
            mean_x('L')
        );
    }

    /// Panel (b)'s map of the light's view (−x, z) to (u, v) is the partition's matrix: a point and
    /// the same point moved along the light map to one (u, v) (computed with the matrix here),
    /// the map equals the matrix's at the part's corners, and the part lies inside the map.
    #[test]
    fn panel_b_map_is_the_partitions_matrix() {
        let fig = fig8().map_err(|e| e.named("lloyd2005-fig8")).unwrap();
        let view = ViewFrustum::new(1.0, FAR, 30f64.to_radians()).unwrap();
        let h = fig.light_to_map(fig.shown);
        let cell = &fig.cells[fig.shown];
        assert_eq!(cell.tag, "R2");
        let [x, y, z] = fig.frame;
        for corner in Face::Right.vertices(&view, FAR.sqrt(), FAR) {
            let clip = |p: DVec3| {
                let c = cell.matrix * p.extend(1.0);
                DVec2::new(c.x / c.w, c.y / c.w)
            };
            let along = clip(corner - 5.0 * y);
            let direct = clip(corner);
            assert!((along - direct).length() < 1e-9, "{along} vs {direct}");
            let via = apply(&h, DVec2::new(-x.dot(corner), z.dot(corner)));
            assert!((via - direct).length() < 1e-9, "{via} vs {direct}");
            assert!(direct.abs().max_element() <= 1.0 + 1e-9);
        }
    }

    /// The text in each rectangle of (c) keeps its lines 16 units apart whatever the panel's
    /// shape: on a tall panel the equal aspect widens the t axis and on a wide one the s axis
    /// beyond the texture (a spacing computed from the texture's size instead of the axis drawn
    /// printed the lines over each other there).
    #[test]
    fn texture_text_lines_are_16_units_apart_on_any_panel() {
        use crate::plot::chart::read_svg::{attr, draw_svg, texts};
        let fig = fig8().map_err(|e| e.named("lloyd2005-fig8")).unwrap();
        for size in [(500, 1200), (1200, 420), (520, 560)] {
            let svg = draw_svg(size, |area| fig.draw_texture(area).unwrap());
            let lines = texts(&svg);
            let rotated = |l: &str| l.contains("transform=\"rotate");
            // Each rectangle's lines: the one naming it ("R1: right, …") and those that follow.
            let mut checked = 0;
            for (i, (line, text, y)) in lines.iter().enumerate() {
                if !text.contains(": ") || !text.contains(", z ") && !text.contains("near") {
                    continue;
                }
                let n = if rotated(line) { 2 } else { 4 };
                for (a, b) in lines[i..i + n].iter().zip(&lines[i + 1..i + n]) {
                    let gap = if rotated(line) {
                        attr(b.0, "x").unwrap() - attr(a.0, "x").unwrap()
                    } else {
                        b.2 - a.2
                    };
                    assert!(
                        (gap - 16.0).abs() <= 1.0,
                        "{size:?}: {:?} and {:?} are {gap} apart (at y = {y})",
                        a.1,
                        b.1
                    );
                    checked += 1;
                }
            }
            // Six rectangles of four lines (L, R, T, 1 and 2) and the near face's two.
            assert_eq!(checked, 6 * 3 + 1, "{size:?}");
        }
    }
}
