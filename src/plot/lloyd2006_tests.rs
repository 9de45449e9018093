//! Tests of the Lloyd et al. 2006 figures ([`super`]), kept apart so that the figures'
//! file stays under the size rule.

use super::*;
use crate::plot::chart::read_svg::{draw_svg, texts};
use crate::plot::chart::Scale;

/// Fig 13's first point: with one partition per face (5 maps) Eq 20 gives 5 r^{2/5} and
/// Eq 21 gives 2(r − 1) + 1; the plotted crossover is where they are equal (by hand:
/// r ≈ 5.41, both ≈ 9.82).
#[test]
fn fig13_crossover_equalises_eq20_and_eq21() {
    let fig = fig13().map_err(|e| e.named("lloyd2006-fig13")).unwrap();
    let (maps, r) = fig.crossover[0];
    assert_eq!(maps, 5.0);
    let zp = 5.0 * r.powf(0.4);
    let fp = 2.0 * (r - 1.0) + 1.0;
    assert!((zp - fp).abs() < 1e-9 * zp, "{zp} vs {fp}");
    assert!((r - 5.4124).abs() < 1e-4, "{r}");
    // At 17 maps the crossover is just above f/n = 1000: Fig 12 (f/n = 1000) has FP+ZP+W
    // lowest there (37.987 against 38.317, see the Fig 12 test).
    let (j, r17) = fig.crossover[3];
    assert_eq!(j, 17.0);
    assert!(r17 > 1000.0 && r17 < 1500.0, "{r17}");
    let zp = 17.0 * r17.powf(2.0 / 17.0);
    let fp = 8.0 * (r17.powf(0.25) - 1.0) + 1.0;
    assert!((zp - fp).abs() < 1e-9 * zp);
    // Only the 4k + 1 map counts are drawn, inside the axes.
    for &(maps, _) in &fig.crossover {
        assert_eq!((maps as usize - 1) % 4, 0);
        assert!(maps >= fig.x.min && maps <= fig.x.max);
    }
    // The crossover depth ratio grows with the number of maps.
    assert!(fig
        .crossover
        .windows(2)
        .all(|w| w[1].1 > w[0].1 && w[1].0 > w[0].0));
}

/// Fig 13's key covers nothing (issue 25: its two boxes lay over the fills): drawn as the
/// figure is, into an SVG, every key text lies above the chart's top, the y of its top tick
/// label 10⁶, and left of nothing drawn in the chart.
#[test]
fn fig13_key_lies_above_the_chart() {
    let fig = fig13().map_err(|e| e.named("lloyd2006-fig13")).unwrap();
    let svg = draw_svg(fig.size(), |area| fig.draw(area).unwrap());
    let texts = texts(&svg);
    let y_of = |pred: &dyn Fn(&str) -> bool| -> Vec<f64> {
        texts.iter().filter(|t| pred(&t.1)).map(|t| t.2).collect()
    };
    let top = y_of(&|t| t == "106");
    assert_eq!(top.len(), 1, "{svg}");
    for key in ["ZP lowest", "FP+ZP+W lowest"] {
        let ys = y_of(&|t| t.contains(key));
        assert_eq!(ys.len(), 1, "{key}");
        assert!(
            ys[0] < top[0] - 8.0,
            "{key} at y {} in the chart (top {})",
            ys[0],
            top[0]
        );
    }
}

/// Fig 5 at LiSPSM's n′ = 1 + √20: the z-error term is equal on the near and far planes,
/// 1/√(f/n) = 0.2236 (Lloyd 2005's g₀), and m_x is f/n · n′/(n′ + f − n) at z = n by hand.
#[test]
fn fig5_lispsm_curve_by_hand() {
    let fig = fig5().map_err(|e| e.named("lloyd2006-fig5")).unwrap();
    let z_curve = &fig.charts[1].series[2].points;
    let g0 = 1.0 / 20f64.sqrt();
    assert!((z_curve[0].1 - g0).abs() < 1e-12);
    assert!((z_curve.last().unwrap().1 - g0).abs() < 1e-12);
    let np = 1.0 + 20f64.sqrt();
    // The left panel is Eq 7's last term (n′ + z − n)/(z(n′ + f − n)), without the factor f:
    // np/(np + 19) at z = n and 1/20 at z = f for every n′.
    let x_curve = &fig.charts[0].series[2].points;
    assert!((x_curve[0].1 - np / (np + 19.0)).abs() < 1e-12);
    assert!((x_curve.last().unwrap().1 - 0.05).abs() < 1e-12);
}

/// Fig 6, by hand from Eq 8 (n = 1, α = f/n = 100, c = (α − 1)/(2 tan θ) = 85.74 at
/// θ = 30°): at η = −1 (n′ = ∞) M_z = m_z(n) = c, at η = 1 (n′ = n) M_z = m_z(f) = c, and
/// at η = 0 (n′ = 1 + √α) M_z = c (1 + √α)/(√α + α) = c/√α. M_x (Eq 9) is f = 100 at
/// η = −1, so it lies above M_z there, not under it, and 1 at η = 1 (PSM). S̄ = M_x M_z is
/// constant for η ≥ 0: at η = 0, M_x = f n′/(n′ + f − n) = 100 · 11/110 = 10 and
/// M_z = c/10, at η = 1, M_x = 1 and M_z = c; both S̄ = c.
#[test]
fn fig6_m_z_is_smallest_at_eta_zero_and_equal_at_both_ends() {
    let fig = fig6().map_err(|e| e.named("lloyd2006-fig6")).unwrap();
    let c = 99.0 / (2.0 * 30f64.to_radians().tan());
    let m_z = &fig.charts[0].series[1].points;
    let (first, last) = (m_z[0].1, m_z.last().unwrap().1);
    assert!((first - c).abs() < 1e-9 * c && (last - c).abs() < 1e-9 * c);
    let m_x = &fig.charts[0].series[0].points;
    assert!((m_x[0].1 - 100.0).abs() < 1e-9 && m_x[0].1 > first);
    assert!((m_x.last().unwrap().1 - 1.0).abs() < 1e-12);
    let s = &fig.charts[0].series[2].points;
    let mid = s.len() / 2;
    assert!(s[mid].0.abs() < 1e-12);
    assert!((s[mid].1 - s.last().unwrap().1).abs() < 1e-9 * s[mid].1);
    assert!((s[mid].1 - c).abs() < 1e-9 * c, "{}", s[mid].1);
    let min = m_z
        .iter()
        .copied()
        .fold((0.0, f64::INFINITY), |a, p| if p.1 < a.1 { p } else { a });
    assert!(min.0.abs() < 1e-12, "minimum at η = {}", min.0);
    assert!((min.1 - c / 10.0).abs() < 1e-9 * c, "{}", min.1);
    // (b), the V on a linear axis: M_z linear in η on each side of 0 (App. B defines η by
    // that interpolation): at η = ±0.5 halfway between the minimum c/10 and the end value c.
    let v = &fig.charts[1];
    assert_eq!(v.y.scale, Scale::Linear);
    for p in &v.series[0].points {
        if (p.0.abs() - 0.5).abs() < 1e-12 {
            let want = 0.5 * (c / 10.0 + c);
            assert!(
                (p.1 - want).abs() < 1e-6 * c,
                "η = {}: {} vs {want}",
                p.0,
                p.1
            );
        }
    }
}

/// Fig 12 reaches 40 maps and so shows the light-behind crossover (§5.3, Fig 13), by hand
/// from Eq 20 (ZP with j maps: j · 1000^{2/j}) and Eq 21 (FP+ZP+W with j = 4k + 1 maps:
/// 4k(1000^{1/k} − 1)/(2 tan 45°) + 1): at 13 maps ZP is lower (13 · 1000^{2/13} = 37.6
/// against 6 · 9 + 1 = 55), at 17 maps FP+ZP+W is (8(1000^{1/4} − 1) + 1 = 37.987 against
/// 17 · 1000^{2/17} = 38.317), so the curves cross between 13 and 17 maps, near 17.
#[test]
fn fig12_reaches_the_light_behind_crossover() {
    let fig = fig12().map_err(|e| e.named("lloyd2006-fig12")).unwrap();
    let series = &fig.charts[0].series;
    let at = |s: usize, maps: f64| {
        series[s]
            .points
            .iter()
            .find(|p| p.0 == maps)
            .map(|p| p.1)
            .unwrap_or_else(|| panic!("series {s} has no point at {maps} maps"))
    };
    let r = 1000f64;
    let zp = |j: f64| j * r.powf(2.0 / j);
    let fp = |k: f64| 4.0 * k * (r.powf(1.0 / k) - 1.0) / 2.0 + 1.0;
    // Series 3 is ZP (= ZP+W) behind, 4 FP+ZP+W behind.
    for (j, k) in [(13.0, 3.0), (17.0, 4.0)] {
        assert!((at(3, j) - zp(j)).abs() < 1e-9 * zp(j), "ZP at {j}");
        assert!((at(4, j) - fp(k)).abs() < 1e-9 * fp(k), "FP at {j}");
    }
    assert!(at(3, 13.0) < at(4, 13.0));
    assert!(at(3, 17.0) > at(4, 17.0));
    assert!((fp(4.0) - 37.987).abs() < 0.001 && (zp(17.0) - 38.317).abs() < 0.001);
    // Every ZP curve runs to 40 maps, FP+ZP+W to 4 · 9 + 1 = 37.
    for s in [0, 1, 3] {
        assert_eq!(series[s].points.last().unwrap().0, 40.0, "series {s}");
    }
    assert_eq!(series[4].points.last().unwrap().0, 37.0);
}

/// Fig 6 (b) has no legend (its one entry, "M_z", repeated the panel's title): no series of
/// it is labelled.
#[test]
fn fig6_linear_panel_has_no_legend() {
    let fig = fig6().map_err(|e| e.named("lloyd2006-fig6")).unwrap();
    let b = &fig.charts[1];
    assert!(b.title.contains("M_z"));
    assert!(b.series.iter().all(|s| s.label.is_none()), "{:?}", b.series);
}

/// Fig 12 (issue 25 review): the coincident behind lines ZP and ZP+W are one legend entry,
/// "ZP = ZP+W, behind", drawn at the normal width in (a) (a second entry with a width-5
/// line had an oversized marker); in (b) the ZP line carries no marker (at 17 maps it lay
/// under FP+ZP+W's: 38.32 against 37.99, Eq 20 and 21 by hand in the test above), both
/// values are written, and the x range is padded so that the edge markers are whole.
#[test]
fn fig12_one_entry_for_the_coincident_lines_and_a_visible_crossover() {
    let fig = fig12().map_err(|e| e.named("lloyd2006-fig12")).unwrap();
    for chart in &fig.charts {
        let behind: Vec<&str> = chart
            .series
            .iter()
            .filter_map(|s| s.label.as_deref())
            .filter(|l| l.starts_with("ZP") && l.contains("behind"))
            .collect();
        assert_eq!(behind, ["ZP = ZP+W, behind"], "{}", chart.title);
        assert!(chart.series.iter().all(|s| s.width <= 3), "{}", chart.title);
    }
    let zoom = &fig.charts[1];
    for s in &zoom.series {
        let zp_line = s.colour == PALETTE[0] && !s.points.is_empty();
        assert!(!(zp_line && (s.markers || s.label.is_some())), "{s:?}");
    }
    let notes: String = zoom.notes.iter().map(|n| n.text.as_str()).collect();
    assert!(
        notes.contains("37.99") && notes.contains("38.32"),
        "{notes}"
    );
    assert!(zoom.x.min <= 10.5 && zoom.x.max >= 23.5);
}

/// Fig 12 (b) (issue 25: an inset around the 17-map crossover): its window holds 13 and 17
/// maps, and its curves are Eq 20 and 21 by hand there (ZP behind j (f/n)^{2/j}, FP+ZP+W
/// 4k((f/n)^{1/k} − 1)/2 + 1), crossing between them.
#[test]
fn fig12_enlarges_the_crossover() {
    let fig = fig12().map_err(|e| e.named("lloyd2006-fig12")).unwrap();
    let zoom = &fig.charts[1];
    assert!(zoom.x.min <= 13.0 && zoom.x.max >= 17.0);
    let r = 1000f64;
    let at = |s: usize, maps: f64| {
        zoom.series[s]
            .points
            .iter()
            .find(|p| p.0 == maps)
            .unwrap()
            .1
    };
    assert!((at(0, 17.0) - 17.0 * r.powf(2.0 / 17.0)).abs() < 1e-9);
    // Series 0 is ZP's line, 1 its legend key, 2 FP+ZP+W.
    assert!((at(2, 17.0) - (8.0 * (r.powf(0.25) - 1.0) + 1.0)).abs() < 1e-9);
    assert!(at(0, 13.0) < at(2, 13.0) && at(0, 17.0) > at(2, 17.0));
    for s in &zoom.series {
        for &(_, v) in s.points.iter().filter(|p| p.1.is_finite()) {
            assert!(v > zoom.y.min && v < zoom.y.max, "{v} outside the window");
        }
    }
}

/// Fig 12 (issue 25: marker clutter, and FP+ZP+W's points joined by a line across the
/// counts where it has no value): FP+ZP+W has values only at 4k + 1 maps and is drawn as
/// markers with a gap between each two (a line chart joins no non-finite point), in both
/// panels; the ZP and ZP+W lines of (a), defined at every count, carry no marker per point.
#[test]
fn fig12_face_partitions_are_unjoined_markers() {
    let fig = fig12().map_err(|e| e.named("lloyd2006-fig12")).unwrap();
    let mut fp = 0;
    for chart in &fig.charts {
        for s in &chart.series {
            let label = s.label.as_deref().unwrap_or("");
            let finite: Vec<f64> = s
                .points
                .iter()
                .filter(|p| p.1.is_finite())
                .map(|p| p.0)
                .collect();
            if label.starts_with("FP+ZP+W") {
                fp += 1;
                assert!(s.markers, "{label}");
                assert!(
                    finite.iter().all(|&j| (j as usize - 1).is_multiple_of(4)),
                    "{label}"
                );
                for w in s.points.windows(2) {
                    assert!(
                        !(w[0].1.is_finite() && w[1].1.is_finite()),
                        "{label}: {:?} joined to {:?}",
                        w[0],
                        w[1]
                    );
                }
            } else if chart.title.starts_with("(a)") {
                assert!(!s.markers, "{label}: a marker at each of its counts");
            }
        }
    }
    assert_eq!(fp, 3);
}

/// Fig 10 (a) labels each curve's optimum (issue 25): drawn into an SVG, the value of
/// App. C's ln(f/n)/(2 tan 30°) for f/n = 10, 100, 1000, 10⁴ (by hand: 1.99, 3.99, 5.98,
/// 7.98) is written once in its curve's text colour, level with its dashed line (within 20
/// units, the label's box, on the panel's log axis read from its 10⁰ and 10⁴ labels).
#[test]
fn fig10_labels_each_optimum() {
    let fig = fig10().map_err(|e| e.named("lloyd2006-fig10")).unwrap();
    let svg = draw_svg(fig.size(), |area| fig.draw(area).unwrap());
    let texts = texts(&svg);
    let first_y = |content: &str| texts.iter().find(|t| t.1 == content).unwrap().2;
    let (y0, y4) = (first_y("100"), first_y("104"));
    let tan = 30f64.to_radians().tan();
    for (i, ratio) in [10f64, 100.0, 1000.0, 10_000.0].into_iter().enumerate() {
        let opt = ratio.ln() / (2.0 * tan);
        let text = format!("{opt:.2}");
        // Its curve's colour as text: darkened where the line's is too light to read on white.
        let colour = {
            let c = crate::plot::chart::legible(PALETTE[i]);
            format!("fill=\"#{:02X}{:02X}{:02X}\"", c.0, c.1, c.2)
        };
        let found: Vec<f64> = texts
            .iter()
            .filter(|t| t.1 == text && t.0.contains(&colour))
            .map(|t| t.2)
            .collect();
        assert_eq!(found.len(), 1, "{text} in {colour}");
        let line = y0 + (y4 - y0) * opt.log10() / 4.0;
        assert!(
            (found[0] - line).abs() < 20.0,
            "{text} at {} for a line at {line}",
            found[0]
        );
    }
}

/// Fig 10 (b) divides each curve by its optimum: at k = 1, Eq 18 over App. C is
/// (f/n − 1)/ln(f/n) (θ cancels: 999/ln 1000 = 144.62 for f/n = 1000), and every ratio falls
/// towards 1 and stays above it.
#[test]
fn fig10_ratio_panel_tends_to_one() {
    let fig = fig10().map_err(|e| e.named("lloyd2006-fig10")).unwrap();
    let ratio = &fig.charts[1];
    let f1000 = &ratio.series[2].points;
    assert!(
        (f1000[0].1 - 999.0 / 1000f64.ln()).abs() < 1e-9,
        "{}",
        f1000[0].1
    );
    for s in &ratio.series[..4] {
        assert!(s.points.windows(2).all(|w| w[1].1 < w[0].1 && w[1].1 > 1.0));
    }
}

/// Fig 5's lower panel (issue 25: its curves had neither legend nor markers) labels each
/// curve directly with the n′ of the upper panel's legend entry of the same colour.
#[test]
fn fig5_lower_panel_labels_its_curves() {
    let fig = fig5().map_err(|e| e.named("lloyd2006-fig5")).unwrap();
    let (upper, lower) = (&fig.charts[0].series, &fig.charts[1].series);
    assert_eq!(upper.len(), lower.len());
    for (u, l) in upper.iter().zip(lower) {
        let (ul, ll) = (u.label.as_deref().unwrap(), l.label.as_deref().unwrap());
        assert!(
            l.direct && ul.starts_with(ll) && u.colour == l.colour,
            "{ul} / {ll}"
        );
    }
}

/// Fig 12 gives FP+ZP+W the colour the worst-case figure and Fig 13 give it (issue 35: behind,
/// it was olive): Okabe–Ito's bluish green #009E73 for every FP+ZP+W series of both panels, the
/// two lights told apart by shape instead (triangles overhead, hexagons behind).
#[test]
fn fig12_fp_zp_w_is_green_for_both_lights() {
    use crate::plot::chart::Marker;
    let fig = fig12().map_err(|e| e.named("lloyd2006-fig12")).unwrap();
    let mut shapes = Vec::new();
    for chart in &fig.charts {
        for s in &chart.series {
            if s.label.as_deref().is_some_and(|l| l.starts_with("FP+ZP+W")) {
                assert_eq!(s.colour, RGBColor(0, 158, 115), "{:?}", s.label);
                shapes.push(s.shape.unwrap_or_else(|| Marker::of(s.colour)));
            }
        }
    }
    // (a) overhead and behind, (b) behind.
    assert_eq!(
        shapes,
        [Marker::TriangleUp, Marker::Hexagon, Marker::Hexagon]
    );
}
