//! Lloyd et al. 2005 Fig 8: (a) the face partitions seen from the light, (b) one partition's
//! warped map over it, (c) the texture layout. The crate's scheme ([`crate::scheme::scheme`], face
//! partitions with k z-partitions each, LiSPSM-warped) is measured per partition and packed into
//! one texture by [`crate::scheme::SchemeResult::atlas`] (Lloyd 2005 Eq 6: the width split among
//! the face pairs by their largest M_x, each column's height among its members by M_z).

mod faces;
mod hatch;
mod leaders;
mod table;
mod texture;

use super::chart::{
    boxed_text, build_chart_styled, column, equal_aspect, frame, linspace, Axis, Chart2d,
    ChartStyle, PANEL_TITLE, SWEEP,
};
use super::from_light::seen_from_light;
use super::warp_grid::minus;
use super::Column;
use super::{Fail, Figure};
use crate::maps::atlas::Viewport;
use crate::maps::faces::Face;
use crate::maps::{light_space, WarpRule};
use crate::scheme::{scheme, Partition, Region};
use crate::ViewFrustum;
use glam::{DMat3, DMat4, DVec2, DVec3};
use hatch::HATCHES;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use table::{table_step, TABLE_TOP, TITLE_EXTRA};

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

/// Panels (a) and (b)'s axes: the light's view, light-space −x to the right and z up, named
/// as in every figure (the fifth review, X3: "z in light space" clashed with the eye depth z).
const X_NAME: &str = "light-view x";
const Z_NAME: &str = "light-view y";

/// The one-column page's height, in units (420 pt printed at 0.8 pt a unit).
const SINGLE_HEIGHT: u32 = 525;

/// The height of the strip under (a) for its inset across two columns, in units.
const INSET_ROW: u32 = 110;

/// The same in one column.
const SINGLE_INSET_ROW: u32 = 80;

/// The partitions' tags' font size (the least a figure's text may have across two columns).
const TAG: u32 = 13;

/// The distance between a hatch's lines, in pixels.
const HATCH_STEP: f64 = 5.0;

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
    /// Partition `i`'s fill, by its face: the parameter sweep's purples for the right, left
    /// and top faces (the darkest, middle and lightest) and black (a mid grey once mixed with
    /// white) for the near face. No scheme's colour: the partitions are no schemes. Each
    /// partition also has its own hatch ([`HATCHES`]`[i]`), which tells apart the two parts
    /// of a face and every pair that prints as one grey.
    pub(super) fn fill(&self, i: usize) -> RGBColor {
        match self.cells[i].tag.chars().next() {
            Some('R') => SWEEP[0],
            Some('L') => SWEEP[2],
            Some('T') => SWEEP[4],
            _ => BLACK,
        }
    }

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
pub(super) fn inside(poly: &[DVec2], p: DVec2) -> bool {
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
    /// Across two columns 520 units wide and 520 tall with the inset's strip under (a).
    fn size(&self) -> (u32, u32) {
        (520, 520 + INSET_ROW)
    }

    /// One column: (a) and (b) side by side, (c) and a key under them, the table last; 525
    /// units tall (420 pt printed, the one-column cap; it was 700).
    fn single_size(&self) -> Option<(u32, u32)> {
        Some((Column::Single.width(), SINGLE_HEIGHT))
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let single = column() == Column::Single;
        let shown = &self.cells[self.shown];
        let caption = if single {
            // What the tags and the table's columns mean, here (a paragraph beside (a) was body
            // text inside the figure: the sixth review, R6-lloyd2005-fig8-4).
            format!(
                "Lloyd et al. 2005, Fig. 8: LiSPSM, f/n\u{a0}=\u{a0}{}, \
                 θ\u{a0}=\u{a0}{THETA_DEG}°, light {}° high, {}° right of behind. R, L, T, N: \
                 right, left, top, near face; parts 1, 2: {}, {}. M_x, M_z: max error \
                 across, in depth, at image resolution.",
                FAR / NEAR,
                LIGHT.0,
                LIGHT.1,
                self.depths('1'),
                self.depths('2').trim_start_matches("z\u{a0}"),
            )
        } else {
            format!(
                "Lloyd et al. 2005, Fig. 8: k\u{a0}=\u{a0}{} z-partitions a face, LiSPSM, f/n\u{a0}=\u{a0}{}, \
                 θ\u{a0}=\u{a0}{THETA_DEG}°, light {}° high, {}° right of behind. (a) Tags as in \
                 (d). (b) {}'s texels reach past it (a larger frustum). (c) Eq\u{a0}6 splits s \
                 by M_x, t by M_z (the paper transposes), the largest errors across and in depth, \
                 one map at image resolution. {}",
                self.k,
                FAR / NEAR,
                LIGHT.0,
                LIGHT.1,
                shown.tag,
                self.lower_after_sentence().unwrap_or_default(),
            )
        };
        let body = frame(
            root,
            "Partitions, warp and texture layout",
            &[caption.as_str()],
        )?;
        let (bw, bh) = body.dim_in_pixel();
        let style = ChartStyle {
            title_size: PANEL_TITLE,
            x_label_area: 40,
            y_label_area: 44,
            tick_size: 13,
            // Axis names at the size of the other two-column figures' (eighth review, R8-X-3:
            // 10.5 pt here against 12.1 in lloyd2006-fig11, martin-tan-fig3 and barroso-fig5);
            // one column keeps 13, as martin-tan-fig3's and lloyd2006-fig4's do ((b)'s "light-view
            // y" at 15 ran past its 67-unit axis).
            desc_size: if single { 13 } else { 15 },
            margin: 6,
        };
        // Room for four-digit tick labels beside the texture's t axis.
        let texture_style = ChartStyle {
            y_label_area: 58,
            ..style
        };
        let table_h = TABLE_TOP
            + self.table_lines(single) * table_step(single)
            + if single { 0 } else { TITLE_EXTRA };
        if single {
            // (a) with its inset under it on the left (the tags' paragraph that stood beside
            // (a) is in the caption: R6-lloyd2005-fig8-4), (b) over (c) on the right; the
            // table last.
            let panels = bh.saturating_sub(table_h);
            let (top, table) = body.split_vertically(panels);
            let (a, right) = top.split_horizontally(bw * 50 / 100);
            let (b, c) = right.split_vertically(panels * 52 / 100);
            self.draw_faces(&a, &style, SINGLE_INSET_ROW)?;
            self.draw_warp(&b, &ChartStyle { margin: 3, ..style })?;
            self.draw_texture(
                &c,
                &ChartStyle {
                    margin: 3,
                    ..texture_style
                },
            )?;
            self.draw_table(&table, single)
        } else {
            // (a) with the inset's strip under it, (b) and (c) beside (a).
            let (top, table) = body.split_vertically(bh.saturating_sub(table_h));
            let (a, rest) = top.split_horizontally(bw * 40 / 100);
            let (rest, _) = rest.split_vertically(top.dim_in_pixel().1.saturating_sub(INSET_ROW));
            let (b, c) = rest.split_horizontally(bw * 25 / 100);
            self.draw_faces(&a, &style, INSET_ROW)?;
            self.draw_warp(&b, &style)?;
            self.draw_texture(&c, &texture_style)?;
            self.draw_table(&table, single)
        }
    }
}

impl Fig8 {
    /// The bounding box of some light-space points, widened by 6 % on each side.
    pub(super) fn window(points: impl Iterator<Item = DVec2>) -> (DVec2, DVec2) {
        let (lo, hi) = points.fold(
            (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
            |(lo, hi), p| (lo.min(p), hi.max(p)),
        );
        let pad = 0.06 * (hi - lo).max_element();
        (lo - pad, hi + pad)
    }

    /// The convex outline `poly` (data units of `chart`, equal aspect: `per_px` data units a
    /// pixel both ways) filled in partition `i`'s pastel ([`Fig8::fill`]) and hatched in its
    /// colour ([`HATCHES`]), so that partitions whose pastels print as one grey still differ.
    pub(super) fn fill_hatched<DB: DrawingBackend>(
        &self,
        chart: &mut Chart2d<'_, DB>,
        poly: &[DVec2],
        i: usize,
        per_px: f64,
    ) -> Result<(), Fail> {
        let colour = self.fill(i);
        let pts: Vec<(f64, f64)> = poly.iter().map(|p| (p.x, p.y)).collect();
        chart.draw_series(std::iter::once(Polygon::new(
            pts,
            colour.mix(0.35).filled(),
        )))?;
        for &angle in HATCHES[i % HATCHES.len()].angles() {
            for (a, b) in hatch::segments(poly, angle, HATCH_STEP * per_px) {
                chart.draw_series(LineSeries::new(
                    [(a.x, a.y), (b.x, b.y)],
                    colour.mix(0.8).stroke_width(1),
                ))?;
            }
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
        // The title names the grid (the bare figure has no caption to), the part's tag inside
        // its thick outline names the part.
        let title = format!("(b) {}'s texel grid", cell.tag);
        let z_name = Z_NAME;
        let (xa, ya) = equal_aspect(
            area,
            &title,
            &Axis::linear(X_NAME, lo.x, hi.x),
            &Axis::linear(z_name, lo.y, hi.y),
            style,
        )?;
        let mut chart = build_chart_styled(area, &title, &xa, &ya, false, style)?;
        let pts: Vec<(f64, f64)> = cell.outline.iter().map(|p| (p.x, p.y)).collect();
        // The part in its pastel only: the map's grid is the pattern drawn over it here.
        chart.draw_series(std::iter::once(Polygon::new(
            pts.clone(),
            self.fill(self.shown).mix(0.35).filled(),
        )))?;
        for c in linspace(-1.0, 1.0, GRID) {
            for (a, b) in [((c, -1.0), (c, 1.0)), ((-1.0, c), (1.0, c))] {
                let (p, q) = (
                    apply(&to_light, DVec2::new(a.0, a.1)),
                    apply(&to_light, DVec2::new(b.0, b.1)),
                );
                // A sweep colour: the grid is no scheme (PSM's blue).
                chart.draw_series(LineSeries::new(
                    [(p.x, p.y), (q.x, q.y)],
                    SWEEP[1].stroke_width(1),
                ))?;
            }
        }
        let mut closed = pts;
        closed.push(closed[0]);
        chart.draw_series(LineSeries::new(closed, BLACK.stroke_width(2)))?;
        let mid = cell.outline.iter().copied().sum::<DVec2>() / cell.outline.len() as f64;
        boxed_text(
            &mut chart,
            (mid.x, mid.y),
            &cell.tag,
            Pos::new(HPos::Center, VPos::Center),
            TAG,
            BLACK,
        )?;
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

    /// Figure review 2: the two-column caption names all four panels, saying why (b)'s map
    /// reaches past R2 and why (d)'s errors after allocation differ within a column (the
    /// one-column figure says what its panels are in its key); read back from the SVGs'
    /// caption lines (#323232), at most five in each.
    #[test]
    fn captions_explain_b_and_d() {
        use super::super::chart::read_svg::{draw_svg, visible};
        use super::super::chart::with_page;
        let fig = fig8().map_err(|e| e.named("lloyd2005-fig8")).unwrap();
        for column in [Column::Double, Column::Single] {
            let size = match column {
                Column::Double => fig.size(),
                Column::Single => fig.single_size().unwrap(),
            };
            let svg = with_page(false, column, || {
                draw_svg(size, |area| fig.draw(area).unwrap())
            });
            let lines: Vec<String> = svg
                .lines()
                .filter(|l| l.contains("fill=\"#323232\""))
                .map(visible)
                .collect();
            assert!((1..=5).contains(&lines.len()), "{column:?}: {lines:?}");
            let text = lines.join(" ").replace('\u{a0}', " ");
            // One column names the panels in the figure (its key says what (d) is).
            if column == Column::Double {
                for p in ["(a)", "(b)", "(c)", "(d)"] {
                    assert!(text.contains(p), "{column:?}: no {p} in {text}");
                }
                assert!(text.contains("larger frustum"), "{text}");
                assert!(text.contains("larger M"), "{text}");
            }
        }
    }
}
