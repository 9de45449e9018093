//! Fig 4's and Fig 7's fifth-review fixes, read back from their SVGs.

use super::*;
/// The points of a polyline element.
fn polyline_points(line: &str) -> Vec<(f64, f64)> {
    crate::plot::chart::read_svg::points(line).unwrap()
}

/// The least distance from `p` to a polyline's segments.
fn distance_to(p: (f64, f64), pts: &[(f64, f64)]) -> f64 {
    pts.windows(2)
        .map(|w| {
            let (a, b) = (w[0], w[1]);
            let (dx, dy) = (b.0 - a.0, b.1 - a.1);
            let l2 = (dx * dx + dy * dy).max(1e-12);
            let t = (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0);
            (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
        })
        .fold(f64::INFINITY, f64::min)
}

/// The fifth figure review on Fig 4, read back from the SVG in both forms: the depth axis
/// is labelled "1" at the near plane (its first label was "2"), centred on the plot's left
/// edge, and named with both planes' values; ξ = −½'s markers (#9589C0) are diamonds, four
/// corners, two on a vertical and two on a horizontal through the centre (they were left
/// triangles, a turn of ξ = 0's ▲ and ξ = −1's ▼); and in one column the label
/// "n′ = 17.325" has its centre nearer its own lilac curve than the orange n′ = ∞ one
/// (it sat under the orange curve).
#[test]
fn fig4_ticks_the_near_plane_marks_xi_minus_half_with_diamonds_and_labels_it_by_its_curve() {
    use super::super::chart::read_svg::{attr, texts};
    let fig = fig4().map_err(|e| e.named("lloyd2005-fig4")).unwrap();
    for column in [Column::Double, Column::Single] {
        let svg = super::super::hemisphere::svg_in(&fig, column);
        let all = texts(&svg);
        assert!(
            all.iter().any(|t| t.1 == "depth z (n = 1, f = 10)"),
            "{column:?}"
        );
        // The plot's left edge: the y axis line, the leftmost vertical black polyline.
        let left = svg
            .lines()
            .filter(|l| l.starts_with("<polyline") && l.contains("stroke=\"#000000\""))
            .map(polyline_points)
            .filter(|p| p.len() == 2 && p[0].0 == p[1].0 && (p[0].1 - p[1].1).abs() > 100.0)
            .map(|p| p[0].0)
            .fold(f64::INFINITY, f64::min);
        let ones: Vec<f64> = all
            .iter()
            .filter(|t| t.1 == "1" && t.0.contains("text-anchor=\"middle\""))
            .map(|t| attr(t.0, "x").unwrap())
            .collect();
        assert!(
            ones.iter().any(|x| (x - left).abs() <= 1.5),
            "{column:?}: no \"1\" under the near plane at {left}: {ones:?}"
        );
        let diamonds: Vec<Vec<(f64, f64)>> = svg
            .lines()
            .filter(|l| l.starts_with("<polygon") && l.contains("fill=\"#9589C0\""))
            .map(polyline_points)
            .collect();
        assert!(diamonds.len() >= 3, "{column:?}: {diamonds:?}");
        for d in &diamonds {
            assert_eq!(d.len(), 4, "{column:?}: {d:?}");
            let (cx, cy) = (
                d.iter().map(|p| p.0).sum::<f64>() / 4.0,
                d.iter().map(|p| p.1).sum::<f64>() / 4.0,
            );
            let on_axes = d
                .iter()
                .filter(|p| (p.0 - cx).abs() < 0.01 || (p.1 - cy).abs() < 0.01)
                .count();
            assert_eq!(on_axes, 4, "{column:?}: {d:?} is no diamond");
        }
        if column == Column::Single {
            // A curve's path: its pieces joined in the order drawn (ξ = −½ is dashed since the
            // nineteenth review, R19-lloyd2005-fig4-1; the eye follows a dashed curve across
            // its gaps).
            let curve = |colour: &str| -> Vec<Vec<(f64, f64)>> {
                vec![svg
                    .lines()
                    .filter(|l| {
                        l.starts_with("<polyline") && l.contains(&format!("stroke=\"{colour}\""))
                    })
                    .flat_map(polyline_points)
                    .collect()]
            };
            let (lilac, orange) = (curve("#9589C0"), curve("#D55E00"));
            let lines: Vec<&str> = svg.lines().collect();
            let k = lines
                .iter()
                .position(|l| l.starts_with("<text") && l.contains(">n′ = 17.325<"))
                .unwrap();
            // Its box: the white rectangle written just before it.
            let rect = lines[..k]
                .iter()
                .rev()
                .find(|l| l.starts_with("<rect"))
                .unwrap();
            let (x, y) = (attr(rect, "x").unwrap(), attr(rect, "y").unwrap());
            let (w, h) = (attr(rect, "width").unwrap(), attr(rect, "height").unwrap());
            let c = (x + 0.5 * w, y + 0.5 * h);
            let near = |pieces: &[Vec<(f64, f64)>]| {
                pieces
                    .iter()
                    .map(|p| distance_to(c, p))
                    .fold(f64::INFINITY, f64::min)
            };
            let (own, other) = (near(&lilac), near(&orange));
            assert!(
                own < other,
                "n′ = 17.325 at {c:?}: {own} from its curve, {other} from n′ = ∞'s"
            );
        }
    }
}

/// Fig 7 (fifth review), read back from the SVG in both forms: no direct label's white
/// box reaches over a panel's x axis line (in one column (b)'s "f/n = 10⁴" box covered it
/// between k ≈ 5.5 and 7), and panel (a)'s axis ends under its least value 0.095
/// (f/n = 10⁴, k = 10) by less than a tenth of its plot's height across two columns (it ran
/// down to 0.035, a third of the plot empty; one column keeps room for the label, under a
/// third): the value's height found from the tick marks at 1 and 10⁻¹ (log scale).
#[test]
fn fig7_labels_clear_the_x_axis_and_panel_a_ends_at_its_data() {
    use super::super::chart::read_svg::attr;
    let fig = fig7().map_err(|e| e.named("lloyd2005-fig7")).unwrap();
    for column in [Column::Double, Column::Single] {
        let svg = super::super::hemisphere::svg_in(&fig, column);
        let black: Vec<Vec<(f64, f64)>> = svg
            .lines()
            .filter(|l| l.starts_with("<polyline") && l.contains("stroke=\"#000000\""))
            .map(polyline_points)
            .collect();
        // The x axes: long horizontal lines; the y axes: long vertical ones.
        let x_axes: Vec<(f64, f64, f64)> = black
            .iter()
            .filter(|p| p.len() == 2 && p[0].1 == p[1].1 && p[1].0 - p[0].0 > 100.0)
            .map(|p| (p[0].0, p[1].0, p[0].1))
            .collect();
        assert_eq!(x_axes.len(), 2, "{column:?}: {x_axes:?}");
        let boxes: Vec<(f64, f64, f64, f64)> = svg
            .lines()
            .filter(|l| l.starts_with("<rect") && l.contains("opacity=\"0.8\""))
            .map(|l| {
                let (x, y) = (attr(l, "x").unwrap(), attr(l, "y").unwrap());
                (
                    x,
                    y,
                    x + attr(l, "width").unwrap(),
                    y + attr(l, "height").unwrap(),
                )
            })
            .collect();
        assert_eq!(boxes.len(), 8, "{column:?}: {boxes:?}");
        for b in &boxes {
            for a in &x_axes {
                let across = b.0 < a.1 && b.2 > a.0;
                assert!(
                    !(across && b.1 <= a.2 + 0.5 && b.3 >= a.2 - 0.5),
                    "{column:?}: label box {b:?} over the x axis {a:?}"
                );
            }
        }
        // Panel (a): its y axis (the upper one) and its ticks, left of it, 5 units long.
        let (ax, top, bottom) = black
            .iter()
            .filter(|p| p.len() == 2 && p[0].0 == p[1].0 && (p[1].1 - p[0].1).abs() > 50.0)
            .map(|p| (p[0].0, p[0].1.min(p[1].1), p[0].1.max(p[1].1)))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap();
        let mut ticks: Vec<f64> = black
            .iter()
            .filter(|p| p.len() == 2 && p[0].1 == p[1].1 && p[1].0 == ax && p[1].0 - p[0].0 == 5.0)
            .map(|p| p[0].1)
            .filter(|&y| y >= top && y <= bottom)
            .collect();
        ticks.sort_by(f64::total_cmp);
        // (a) is labelled at 1, 0.5, 0.2 and 0.1, top to bottom.
        assert_eq!(ticks.len(), 4, "{column:?}: {ticks:?}");
        let per_decade = ticks[3] - ticks[0];
        let least = ticks[3] + per_decade * (0.1f64 / 0.095).log10();
        let empty = (bottom - least) / (bottom - top);
        // One column keeps room under the lowest end for its label (its plot, about 110
        // units tall, has none between the ends): less than a third.
        let most = if column == Column::Double { 0.1 } else { 0.3 };
        assert!(
            empty >= 0.0 && empty < most,
            "{column:?}: {empty} of (a) under 0.095"
        );
    }
}
