//! Martin & Tan 2004 Figs 3–4: the trapezoid against the bounding box. The eye's frustum seen
//! from the light (E, with its convex hull C and the focus region), the trapezoid T of the 80 %
//! rule ([`crate::maps::tsm::tsm`]) and the smallest axis-aligned bounding box B; then C in the
//! trapezoidal space (N_T, the map the trapezoid builds) and in the bounding box's space, with
//! the share of the map each leaves unused (the paper's *wastage*).

use super::chart::{build_chart, frame, Axis, PALETTE};
use super::{Fail, Figure, UNIT_SQUARE};
use crate::maps::tsm::{tsm, TsmOptions, TsmSearch};
use crate::ViewFrustum;
use glam::{DMat3, DVec2, DVec3};
use plotters::coord::Shift;
use plotters::prelude::*;

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
    /// Light-space (x, z) of the frustum's and the focus region's corners.
    pub eye: Vec<DVec2>,
    pub focus: Vec<DVec2>,
    pub trapezoid: [DVec2; 4],
    /// The bounding box of the frustum's corners: min, max.
    pub bbox: (DVec2, DVec2),
    pub n_t: DMat3,
    /// Share of the map the hull C covers: in the trapezoidal space and in the box's space.
    pub covered_t: f64,
    pub covered_b: f64,
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

/// `h (p, 1)` divided by its third coordinate.
pub(super) fn through(h: &DMat3, p: DVec2) -> DVec2 {
    let q = *h * DVec3::new(p.x, p.y, 1.0);
    DVec2::new(q.x / q.z, q.y / q.z)
}

pub(super) fn fig3() -> Result<Fig3, Fail> {
    let view = ViewFrustum::new(1.0, 100.0, 30f64.to_radians())?;
    // The source 40° above the horizon, in front of the viewer and 30° to the right.
    let (el, az) = (40f64.to_radians(), 150f64.to_radians());
    let light = -DVec3::new(el.cos() * az.sin(), el.sin(), el.cos() * az.cos());
    let map = tsm(
        &view,
        light,
        TsmOptions {
            focus: FOCUS,
            search: TsmSearch::EightyPercent,
        },
    )?;
    let to_xz = |p: DVec3| {
        let l = map.light_space.to_light(p);
        DVec2::new(l.x, l.z)
    };
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
    Ok(Fig3 {
        eye,
        focus,
        trapezoid: map.trapezoid.corners,
        bbox: (lo, hi),
        n_t: map.n_t,
        covered_t,
        covered_b,
    })
}

impl Figure for Fig3 {
    fn size(&self) -> (u32, u32) {
        (520, 1300)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let caption = format!(
            "Martin & Tan 2004, Figs. 3 and 4, from maps::tsm::tsm (80 % rule, focus δ = {FOCUS}; n = 1, f = 100, θ = 30°; light 40° above the horizon, in front and 30° to the right). Top: the eye's frustum E seen from the light (grey edges), its hull C, the focus region (orange), the trapezoid T (blue) and the smallest axis-aligned bounding box B (dashed). Middle: C in the trapezoidal space N_T: it covers {:.1} % of the map. Bottom: C in the bounding box's space: {:.1} %. The unused rest is the paper's wastage. The paper's figures are sketches for a chosen view; ours are computed. Unlike the paper, whose smallest bounding box may be rotated, B here is the axis-aligned box of the light's view, and the light is ours, not the paper's, so the two coverages can be close.",
            100.0 * self.covered_t,
            100.0 * self.covered_b
        );
        let body = frame(
            root,
            "Trapezoidal approximation against the bounding box",
            &[caption.as_str()],
        )?;
        let panels = body.split_evenly((3, 1));
        // Left: light space.
        let pts: Vec<DVec2> = self.eye.iter().chain(&self.trapezoid).copied().collect();
        let lo = pts
            .iter()
            .fold(DVec2::splat(f64::INFINITY), |a, &p| a.min(p));
        let hi = pts
            .iter()
            .fold(DVec2::splat(f64::NEG_INFINITY), |a, &p| a.max(p));
        let pad = 0.05 * (hi - lo).max_element();
        let (lo, hi) = (lo - pad, hi + pad);
        // Equal scales on both axes: widen the shorter range.
        let span = (hi - lo).max_element();
        let mid = 0.5 * (lo + hi);
        let (lo, hi) = (
            mid - DVec2::splat(span / 2.0),
            mid + DVec2::splat(span / 2.0),
        );
        let mut chart = build_chart(
            &panels[0],
            "seen from the light",
            &Axis::linear("light x", lo.x, hi.x),
            &Axis::linear("light z (warp axis)", lo.y, hi.y),
            false,
        )?;
        let tup = |p: DVec2| (p.x, p.y);
        self.draw_frustum(&mut chart, &self.eye, |p| p, RGBColor(120, 120, 120))?;
        self.draw_frustum(&mut chart, &self.focus, |p| p, PALETTE[1])?;
        let mut t: Vec<(f64, f64)> = self.trapezoid.iter().map(|&p| tup(p)).collect();
        t.push(t[0]);
        chart.draw_series(LineSeries::new(t, PALETTE[0].stroke_width(2)))?;
        let (b0, b1) = self.bbox;
        chart.draw_series(DashedLineSeries::new(
            [
                (b0.x, b0.y),
                (b1.x, b0.y),
                (b1.x, b1.y),
                (b0.x, b1.y),
                (b0.x, b0.y),
            ],
            8,
            5,
            PALETTE[6].stroke_width(2),
        ))?;
        // Middle and right: the two normalised spaces.
        let box_map = DMat3::from_cols(
            DVec3::new(2.0 / (b1.x - b0.x), 0.0, 0.0),
            DVec3::new(0.0, 2.0 / (b1.y - b0.y), 0.0),
            DVec3::new(
                -(b1.x + b0.x) / (b1.x - b0.x),
                -(b1.y + b0.y) / (b1.y - b0.y),
                1.0,
            ),
        );
        for (panel, h, title) in [
            (&panels[1], self.n_t, "trapezoidal space (N_T)"),
            (&panels[2], box_map, "bounding box space"),
        ] {
            let ax = Axis::linear("map s", -1.1, 1.1);
            let ay = Axis::linear("map t", -1.1, 1.1);
            let mut chart = build_chart(panel, title, &ax, &ay, false)?;
            let c = hull(&self.eye);
            let poly: Vec<(f64, f64)> = c.iter().map(|&p| tup(through(&h, p))).collect();
            chart.draw_series(std::iter::once(Polygon::new(
                poly,
                PALETTE[5].mix(0.35).filled(),
            )))?;
            self.draw_frustum(
                &mut chart,
                &self.eye,
                |p| through(&h, p),
                RGBColor(120, 120, 120),
            )?;
            self.draw_frustum(&mut chart, &self.focus, |p| through(&h, p), PALETTE[1])?;
            chart.draw_series(LineSeries::new(UNIT_SQUARE, BLACK.stroke_width(2)))?;
        }
        Ok(())
    }
}

impl Fig3 {
    fn draw_frustum<DB: DrawingBackend>(
        &self,
        chart: &mut super::chart::Chart2d<'_, DB>,
        corners: &[DVec2],
        f: impl Fn(DVec2) -> DVec2,
        colour: RGBColor,
    ) -> Result<(), Fail> {
        for (a, b) in EDGES {
            let (p, q) = (f(corners[a]), f(corners[b]));
            chart.draw_series(LineSeries::new(
                [(p.x, p.y), (q.x, q.y)],
                colour.stroke_width(1),
            ))?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// N_T sends the trapezoid's corners to the unit square's (top-left (−1, 1), top-right
    /// (1, 1), base-right (1, −1), base-left (−1, −1), Martin & Tan §3), every corner of E lies
    /// inside both T and B, and the shares are areas: C's in the box space is its light-space area
    /// over the box's (shoelace, computed here from the corners).
    #[test]
    fn trapezoid_and_box_contain_the_frustum() {
        let fig = fig3().map_err(|e| e.named("martin-tan-fig3")).unwrap();
        let want = [
            DVec2::new(-1.0, 1.0),
            DVec2::new(1.0, 1.0),
            DVec2::new(1.0, -1.0),
            DVec2::new(-1.0, -1.0),
        ];
        for (c, w) in fig.trapezoid.iter().zip(want) {
            let s = through(&fig.n_t, *c);
            assert!((s - w).length() < 1e-9, "{s} vs {w}");
        }
        let (b0, b1) = fig.bbox;
        for &p in &fig.eye {
            let s = through(&fig.n_t, p);
            assert!(s.abs().max_element() <= 1.0 + 1e-9, "{s}");
            assert!(p.x >= b0.x && p.y >= b0.y && p.x <= b1.x && p.y <= b1.y);
        }
        // A unit square's hull and area by hand.
        let sq = hull(&[
            DVec2::ZERO,
            DVec2::X,
            DVec2::ONE,
            DVec2::Y,
            DVec2::splat(0.5),
        ]);
        assert_eq!(sq.len(), 4);
        assert!((area(&sq) - 1.0).abs() < 1e-15);
        assert!(fig.covered_t > 0.0 && fig.covered_t <= 1.0 + 1e-9);
        assert!(fig.covered_b > 0.0 && fig.covered_b <= 1.0 + 1e-9);
    }
}
