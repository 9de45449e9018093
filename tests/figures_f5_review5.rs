//! The fifth figure review's remaining items (§4.4.1, §4.7.3, §4.10.3, §4.16.3, §4.3.3, X2,
//! §4.13.1, §4.14.5), read back from the figures' SVGs in the forms they change in.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read as read;
use figures_style_read::forms;

/// The box [x min, y min, x max, y max] of some points.
fn bounds(p: &[(f64, f64)]) -> [f64; 4] {
    p.iter()
        .fold([f64::MAX, f64::MAX, f64::MIN, f64::MIN], |b, q| {
            [b[0].min(q.0), b[1].min(q.1), b[2].max(q.0), b[3].max(q.1)]
        })
}

/// The stroked polylines of `colour`: (width, points).
fn strokes(svg: &str, colour: &str) -> Vec<(f64, Vec<(f64, f64)>)> {
    svg.lines()
        .filter(|l| l.starts_with("<polyline") && read::attr_str(l, "stroke") == Some(colour))
        .map(|l| {
            (
                read::attr(l, "stroke-width").unwrap_or(1.0),
                read::points(l),
            )
        })
        .collect()
}

/// §4.4.1: in PSM's map (one column's (f), two columns' (h)) the planes of constant depth near
/// t = 1 ran into one dark block (neighbours 0 or 1 unit apart, 1 or 2 units wide). In every map
/// panel (the dark grey squares, #404040), neighbouring planes (#3F007D) are at least their
/// width and a unit of white apart; the near and far planes (the square's bottom and top) stay
/// drawn, and each panel keeps at least 7 of its 13 planes.
#[test]
fn lloyd2006_fig4_depth_planes_do_not_merge() {
    for (form, opts) in forms() {
        let svg = read::render_svg("lloyd2006-fig4", &opts);
        let squares: Vec<[f64; 4]> = strokes(&svg, "#404040")
            .into_iter()
            .filter(|(_, p)| p.len() >= 4)
            .map(|(_, p)| bounds(&p))
            .collect();
        assert!(squares.len() >= 3, "{form}: {} map squares", squares.len());
        let planes = strokes(&svg, "#3F007D");
        for sq in &squares {
            let mut ys: Vec<(f64, f64)> = planes
                .iter()
                .filter(|(_, p)| {
                    p.iter().all(|q| {
                        q.0 >= sq[0] - 1.0
                            && q.0 <= sq[2] + 1.0
                            && q.1 >= sq[1] - 1.0
                            && q.1 <= sq[3] + 1.0
                    })
                })
                .map(|(w, p)| (0.5 * (p[0].1 + p[p.len() - 1].1), *w))
                .collect();
            ys.sort_by(|a, b| a.0.total_cmp(&b.0));
            assert!(ys.len() >= 7, "{form} {sq:?}: {} planes", ys.len());
            assert!(
                (ys[0].0 - sq[1]).abs() <= 1.0 && (ys[ys.len() - 1].0 - sq[3]).abs() <= 1.0,
                "{form} {sq:?}: near or far plane missing: {ys:?}"
            );
            for w in ys.windows(2) {
                assert!(
                    w[1].0 - w[0].0 >= w[0].1 + 1.0 - 1e-9,
                    "{form} {sq:?}: planes at {} and {} (width {}) merge",
                    w[0].0,
                    w[1].0,
                    w[0].1
                );
            }
        }
    }
}
