//! Lloyd et al. 2005 Fig 8(c): the texture layout of a face-partitioned, z-partitioned scheme.
//! The crate's scheme ([`crate::scheme::scheme`], face partitions with k z-partitions
//! each, LiSPSM-warped) is measured per partition and packed into one texture by
//! [`crate::scheme::SchemeResult::atlas`] (Lloyd 2005 Eq 6: the width split among the
//! face pairs by their largest M_x, each column's height among its members by M_z).

use super::chart::{build_chart, frame, Axis, FONT, PALETTE};
use super::{Fail, Figure};
use crate::maps::atlas::Viewport;
use crate::maps::WarpRule;
use crate::scheme::{scheme, Partition, Region};
use crate::ViewFrustum;
use glam::DVec3;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Texture size in texels.
pub(super) const SIZE: u32 = 2048;

pub(super) struct Fig8 {
    /// (viewport, label, M_x, M_z) per partition.
    pub cells: Vec<(Viewport, String, f64, f64)>,
    pub k: usize,
}

fn face_name(r: Region) -> &'static str {
    match r {
        Region::Frustum => "frustum",
        Region::Face(f) => f.name(),
    }
}

pub(super) fn fig8() -> Result<Fig8, Fail> {
    let view = ViewFrustum::new(1.0, 100.0, 30f64.to_radians())?;
    // A light in general position: 35° above the horizon, 60° to the viewer's right of straight
    // behind.
    let (el, az) = (35f64.to_radians(), 60f64.to_radians());
    let light = -DVec3::new(el.cos() * az.sin(), el.sin(), el.cos() * az.cos());
    let k = 2;
    let s = scheme(&view, light, WarpRule::Lispsm, Partition::Faces, k)?;
    let atlas = s.atlas(SIZE, SIZE)?;
    let cells = s
        .partitions()
        .iter()
        .zip(atlas.viewports())
        .map(|(p, v)| {
            let depth = if p.far > p.near {
                format!("z {:.3}–{:.3}", p.near, p.far).replace(".000", "")
            } else {
                String::new()
            };
            (
                *v,
                format!("{} {depth}", face_name(p.region)),
                p.max_mx,
                p.max_mz,
            )
        })
        .collect();
    Ok(Fig8 { cells, k })
}

impl Figure for Fig8 {
    fn size(&self) -> (u32, u32) {
        (520, 640)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let caption = format!(
            "Lloyd et al. 2005, Fig. 8(c): the texture layout of face partitioning with k = {} z-partitions per face, LiSPSM-warped (n = 1, f = 100, θ = 30°; light 35° above the horizon, 60° to the right of straight behind), from scheme::scheme and SchemeResult::atlas ({SIZE} × {SIZE} texels). Eq 6: the width is shared among the face pairs (left/right, bottom/top, near) by their largest M_x, each column's height among its partitions by M_z, so that the error after allocation is equal. Each rectangle gives its face, depth range, M_x and M_z (unit resolutions), its share of the texture's width × height and the error after allocation, M_x and M_z over those shares: the x error is equal in every rectangle, the z error within each column. Unlike the paper, the self-similar z-partitions of a face have equal M_z, so a column's heights are equal here. Panels (a) and (b) of the paper are sketches; the frustum seen from the light is drawn in barroso-fig5 and lloyd2006-fig11, the warped grids in lloyd2006-fig4.",
            self.k
        );
        let body = frame(
            root,
            "Texture layout of the subdivisions",
            &[caption.as_str()],
        )?;
        let n = f64::from(SIZE);
        let mut chart = build_chart(
            &body,
            "",
            &Axis::linear("s (texels)", 0.0, n),
            &Axis::linear("t (texels)", 0.0, n),
            false,
        )?;
        for (i, (v, label, mx, mz)) in self.cells.iter().enumerate() {
            let (x0, y0) = (f64::from(v.x), f64::from(v.y));
            let (x1, y1) = (x0 + f64::from(v.width), y0 + f64::from(v.height));
            let c = PALETTE[i % PALETTE.len()];
            chart.draw_series([
                Rectangle::new([(x0, y0), (x1, y1)], c.mix(0.25).filled()),
                Rectangle::new([(x0, y0), (x1, y1)], BLACK.stroke_width(1)),
            ])?;
            // The error after allocation: each partition's M_x and M_z over its share of the
            // texture's width and height (Eq 6 makes the first equal across columns and the
            // second within a column).
            let (sw, sh) = ((x1 - x0) / n, (y1 - y0) / n);
            let mut lines = vec![
                label.clone(),
                format!("M_x {mx:.2}, M_z {mz:.2}"),
                format!("share {:.0} % × {:.0} %", 100.0 * sw, 100.0 * sh),
                format!("after: {:.2} × {:.2}", mx / sw, mz / sh),
            ];
            // A narrow column's text runs up it, in two lines.
            let narrow = sw < 0.25;
            if narrow {
                lines = vec![
                    format!("{}: M_x {mx:.2}, M_z {mz:.2}", label.trim()),
                    format!(
                        "share {:.0} % × {:.0} %, after: {:.2} × {:.2}",
                        100.0 * sw,
                        100.0 * sh,
                        mx / sw,
                        mz / sh
                    ),
                ];
            }
            let mut style =
                TextStyle::from((FONT, 13).into_font()).pos(Pos::new(HPos::Center, VPos::Center));
            if narrow {
                style = style.transform(FontTransform::Rotate270);
            }
            let (cx, cy) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
            let step = 0.045 * n;
            for (j, line) in lines.iter().enumerate() {
                let off = (0.5 * (lines.len() - 1) as f64 - j as f64) * step;
                let at = if narrow {
                    // Rotated: successive lines step to the right.
                    (cx - off * 0.8, cy)
                } else {
                    (cx, cy + off)
                };
                chart.draw_series(std::iter::once(Text::new(line.clone(), at, style.clone())))?;
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
            .map(|c| u64::from(c.0.width) * u64::from(c.0.height))
            .sum();
        assert_eq!(total, u64::from(SIZE) * u64::from(SIZE));
        let mut columns: std::collections::BTreeMap<u32, Vec<(u32, f64)>> = Default::default();
        for (v, _, _, mz) in &fig.cells {
            columns.entry(v.x).or_default().push((v.height, *mz));
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
        for (v, _, mx, mz) in &fig.cells {
            let e = columns.entry(v.x).or_insert((0.0, Vec::new()));
            e.0 = e.0.max(*mx);
            e.1.push(mz / (f64::from(v.height) / n));
        }
        let want_x: f64 = columns.values().map(|c| c.0).sum();
        for (v, _, mx, _) in &fig.cells {
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
}
