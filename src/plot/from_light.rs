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

use super::chart::{build_chart, equal_aspect, frame, Axis, ChartStyle, PALETTE};
use super::{Fail, Figure};
use crate::analytic::partition::{z_splits, SplitScheme};
use crate::maps::light_space;
use crate::scheme::ADAPTIVE_RATIO;
use crate::ViewFrustum;
use glam::{DVec2, DVec3};
use plotters::coord::Shift;
use plotters::prelude::*;

/// One panel: a light, its split depths and what it shows.
pub(super) struct Panel {
    pub title: String,
    /// Cross-sections of the frustum at each split depth (4 light-space corners each), near first.
    pub sections: Vec<[DVec2; 4]>,
    /// Each partition's bounding rectangle in light space (min, max).
    pub maps: Vec<(DVec2, DVec2)>,
    pub planes: Vec<f64>,
}

pub(super) struct FromLight {
    pub title: &'static str,
    pub caption: String,
    pub panels: Vec<Panel>,
    pub size: (u32, u32),
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
    let to = |p: DVec3| {
        let l = ls.to_light(p);
        DVec2::new(l.x, l.z)
    };
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
        planes: planes.to_vec(),
    })
}

fn fmt_planes(p: &[f64]) -> String {
    p.iter()
        .map(|z| {
            format!("{z:.3}")
                .trim_end_matches('0')
                .trim_end_matches('.')
                .to_string()
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// Barroso & Celes 2007 Fig 5: k = 4, n = 1, f = 100, φ = 30°, light 45° above, in front.
pub(super) fn barroso_fig5() -> Result<FromLight, Fail> {
    let view = ViewFrustum::new(1.0, 100.0, 30f64.to_radians())?;
    let gamma = 45f64.to_radians();
    let light = DVec3::new(0.0, -gamma.sin(), -gamma.cos());
    let k = 4;
    let ss = z_splits(view.near(), view.far(), k, SplitScheme::SelfSimilar)?;
    let ad = z_splits(
        view.near(),
        view.far(),
        k,
        SplitScheme::Adaptive {
            light_angle: gamma,
            ratio: ADAPTIVE_RATIO,
        },
    )?;
    let panels = vec![
        panel(
            &view,
            light,
            ss.planes(),
            "(a) self-similar partitions, Eq 5".into(),
        )?,
        panel(
            &view,
            light,
            ad.planes(),
            format!("(b) adaptive partitions, Eq 19 (γ = 45°, α = {ADAPTIVE_RATIO})"),
        )?,
    ];
    let caption = format!(
        "Barroso & Celes 2007, Fig. 5: the view frustum as seen by the light with k = 4 z-partitions (n = 1, f = 100, φ = 30°; light 45° above the view direction, from behind the viewer's back: it travels forward and down). Split depths from analytic::partition::z_splits: (a) {}; (b) {}. Solid: the frustum's edges and the split planes' cross-sections; dashed: each partition's orthographic map (its light-space bounding rectangle). Computed; the paper's figure is a sketch. Unlike the paper, whose panels are (a) light perpendicular and (b) light parallel to the view direction, both panels here share one light at 45° and compare self-similar partitions (a) with the adaptive partitions of Eq 19 (b, not in the paper's figure).",
        fmt_planes(panels[0].planes.as_slice()),
        fmt_planes(panels[1].planes.as_slice())
    );
    Ok(FromLight {
        title: "The view frustum seen from the light, with z-partitions",
        caption,
        panels,
        size: (1400, 700),
    })
}

/// Lloyd et al. 2006 Fig 11: the light behind the viewer, k = 3 self-similar partitions.
pub(super) fn lloyd2006_fig11() -> Result<FromLight, Fail> {
    let view = ViewFrustum::new(1.0, 8.0, 30f64.to_radians())?;
    let k = 3;
    let ss = z_splits(view.near(), view.far(), k, SplitScheme::SelfSimilar)?;
    // The light travels along the view direction (−Z): it is behind the viewer.
    let p = panel(
        &view,
        DVec3::NEG_Z,
        ss.planes(),
        "light behind the viewer".into(),
    )?;
    let caption = format!(
        "Lloyd et al. 2006, Fig. 11: the view frustum seen by the light behind the viewer (n = 1, f = 8, θ = 30°): the near face (side 2n tan θ) inside the far face (2f tan θ), the four side faces as trapezoids between them. With k = 3 self-similar z-partitions (planes {}) each partition's map (dashed) is the square of its far plane, so the maps overlap: the nearer ones lie inside the farther ones, the overlap §5.3 blames for ZP's growth behind. A face partitioning gives each side face its own map (FP+ZP+W). The paper's axes mark n, f, 2n, 2f; here f/n = 8 so that the near face shows.",
        fmt_planes(p.planes.as_slice())
    );
    Ok(FromLight {
        title: "The view frustum seen from a light behind the viewer",
        caption,
        panels: vec![p],
        size: (900, 860),
    })
}

impl Figure for FromLight {
    fn size(&self) -> (u32, u32) {
        self.size
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let body = frame(root, self.title, &[self.caption.as_str()])?;
        let cells = body.split_evenly((1, self.panels.len()));
        for (cell, p) in cells.iter().zip(&self.panels) {
            let all = p.sections.iter().flatten();
            let lo = all
                .clone()
                .fold(DVec2::splat(f64::INFINITY), |a, &q| a.min(q));
            let hi = all.fold(DVec2::splat(f64::NEG_INFINITY), |a, &q| a.max(q));
            let span = (hi - lo).max_element() * 1.08;
            let mid = 0.5 * (lo + hi);
            let (lo, hi) = (
                mid - DVec2::splat(span / 2.0),
                mid + DVec2::splat(span / 2.0),
            );
            // Equal aspect: a light-space unit as long across as up.
            let (xa, ya) = equal_aspect(
                cell,
                &p.title,
                &Axis::linear("light x", lo.x, hi.x),
                &Axis::linear("light z (towards the view direction)", lo.y, hi.y),
                &ChartStyle::default(),
            )?;
            let mut chart = build_chart(cell, &p.title, &xa, &ya, false)?;
            for (i, &(a, b)) in p.maps.iter().enumerate() {
                let c = PALETTE[i % PALETTE.len()];
                chart.draw_series(std::iter::once(Rectangle::new(
                    [(a.x, a.y), (b.x, b.y)],
                    c.mix(0.08).filled(),
                )))?;
                chart.draw_series(DashedLineSeries::new(
                    [(a.x, a.y), (b.x, a.y), (b.x, b.y), (a.x, b.y), (a.x, a.y)],
                    7,
                    5,
                    c.stroke_width(2),
                ))?;
            }
            let line = |a: DVec2, b: DVec2| [(a.x, a.y), (b.x, b.y)];
            for s in &p.sections {
                for i in 0..4 {
                    chart.draw_series(LineSeries::new(
                        line(s[i], s[(i + 1) % 4]),
                        BLACK.stroke_width(1),
                    ))?;
                }
            }
            let (first, last) = (p.sections[0], p.sections[p.sections.len() - 1]);
            for i in 0..4 {
                chart.draw_series(LineSeries::new(
                    line(first[i], last[i]),
                    BLACK.stroke_width(2),
                ))?;
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
        // The adaptive planes start at n and end at f, and differ from the self-similar ones.
        let ad = &b.panels[1].planes;
        assert_eq!((ad[0], ad[4]), (1.0, 100.0));
        assert!((ad[1] - b.panels[0].planes[1]).abs() > 1e-3);
    }
}
