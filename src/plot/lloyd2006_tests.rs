//! Tests of the Lloyd et al. 2006 figures ([`super`]), kept apart so that the figures'
//! file stays under the size rule.

use super::*;
use crate::plot::chart::read_svg::{draw_svg, texts};

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

/// Fig 13's key covers nothing (issue 25: its two boxes lay over the fills) and sits below
/// the chart, where every figure has its key (issue 35 review: it was above): drawn as the
/// figure is, into an SVG, every key text lies below the x axis's title.
#[test]
fn fig13_key_lies_below_the_chart() {
    let fig = fig13().map_err(|e| e.named("lloyd2006-fig13")).unwrap();
    let svg = draw_svg(fig.size(), |area| fig.draw(area).unwrap());
    let texts = texts(&svg);
    // Not the caption's lines (#323232).
    let y_of = |pred: &dyn Fn(&str) -> bool| -> Vec<f64> {
        texts
            .iter()
            .filter(|t| pred(&t.1) && !t.0.contains("#323232"))
            .map(|t| t.2)
            .collect()
    };
    let axis = y_of(&|t| t.starts_with("shadow maps j"));
    assert_eq!(axis.len(), 1, "{svg}");
    for key in ["ZP = ZP+W lowest", "FP+ZP+W lowest", "equal S"] {
        let ys = y_of(&|t| t.contains(key));
        assert_eq!(ys.len(), 1, "{key}");
        assert!(
            ys[0] > axis[0] + 8.0,
            "{key} at y {} above the axis title (y {})",
            ys[0],
            axis[0]
        );
    }
}

/// Fig 13's hatching is coarse enough for print (issue 35 review: lines 10 units apart may
/// moiré under a halftone): in the SVG, the white 45° lines over the first column (5 maps)
/// lie at least 14 units apart along x − y (a line x − y = c each) and are 3 units wide.
#[test]
fn fig13_hatch_is_coarse() {
    let fig = fig13().map_err(|e| e.named("lloyd2006-fig13")).unwrap();
    let svg = draw_svg(fig.size(), |area| fig.draw(area).unwrap());
    let lines: Vec<(f64, f64, f64)> = svg
        .lines()
        .filter(|l| l.starts_with("<polyline") && l.contains("stroke=\"#FFFFFF\""))
        .filter_map(|l| {
            let w = crate::plot::chart::read_svg::attr(l, "stroke-width")?;
            let pts = crate::plot::chart::read_svg::points(l)?;
            let (a, b) = (pts.first()?, pts.last()?);
            // 45°: x − y the same at both ends (within a unit's rounding).
            (((a.0 - a.1) - (b.0 - b.1)).abs() <= 1.5).then_some((a.0.min(b.0), a.0 - a.1, w))
        })
        .collect();
    // The first column of the chart: the lines starting left of its right edge, about 30
    // units right of the leftmost line.
    let left = lines.iter().map(|l| l.0).fold(f64::INFINITY, f64::min);
    let mut c: Vec<f64> = lines
        .iter()
        .filter(|l| l.0 < left + 20.0)
        .map(|l| l.1)
        .collect();
    c.sort_by(f64::total_cmp);
    assert!(c.len() >= 3, "{c:?}");
    for w in c.windows(2) {
        assert!(w[1] - w[0] >= 14.0, "hatch lines {} apart", w[1] - w[0]);
    }
    assert!(
        lines.iter().all(|l| l.2 >= 3.0),
        "a hatch line thinner than 3"
    );
}

/// Fig 5 at LiSPSM's n′ = 1 + √20: the z-error term is equal on the near and far planes,
/// 1/√(f/n) = 0.2236 (Lloyd 2005's g₀), and m_x is f/n · n′/(n′ + f − n) at z = n by hand.
#[test]
fn fig5_lispsm_curve_by_hand() {
    let fig = fig5().map_err(|e| e.named("lloyd2006-fig5")).unwrap();
    // Each n′ has its line and its markers: LiSPSM, the third, is series 4.
    let z_curve = &fig.page.charts[1].series[4].points;
    let g0 = 1.0 / 20f64.sqrt();
    assert!((z_curve[0].1 - g0).abs() < 1e-12);
    assert!((z_curve.last().unwrap().1 - g0).abs() < 1e-12);
    let np = 1.0 + 20f64.sqrt();
    // The left panel is Eq 7's last term (n′ + z − n)/(z(n′ + f − n)), without the factor f:
    // np/(np + 19) at z = n and 1/20 at z = f for every n′.
    let x_curve = &fig.page.charts[0].series[4].points;
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
    // The lines without labels, in the order M_x, M_z, S̄ (each followed by its markers).
    let lines: Vec<&Vec<(f64, f64)>> = fig.page.charts[0]
        .series
        .iter()
        .filter(|s| s.label.is_none() && !s.markers)
        .map(|s| &s.points)
        .collect();
    let (m_x, m_z, s) = (lines[0], lines[1], lines[2]);
    let (first, last) = (m_z[0].1, m_z.last().unwrap().1);
    assert!((first - c).abs() < 1e-9 * c && (last - c).abs() < 1e-9 * c);
    assert!((m_x[0].1 - 100.0).abs() < 1e-9 && m_x[0].1 > first);
    assert!((m_x.last().unwrap().1 - 1.0).abs() < 1e-12);
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
    // M_z linear in η on each side of 0 (App. B defines η by that interpolation): at
    // η = ±0.5 halfway between the minimum c/10 and the end value c.
    for p in m_z {
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
    let series = &fig.page.charts[0].series;
    // The drawn lines (the keys are samples without points; the markers separate series).
    // Behind drawn dashed in the scheme's colour (sixth review).
    let find = |c: RGBColor, label: Option<&str>, dash: crate::plot::chart::Dash| {
        series
            .iter()
            .position(|s| {
                s.colour == c
                    && s.label.as_deref() == label
                    && !s.sample
                    && !s.points.is_empty()
                    && s.dash == dash
            })
            .unwrap()
    };
    use crate::plot::chart::Dash::{Dashed, Solid};
    let zo = find(Look::Zp.colour(), None, Solid);
    let zb = find(Look::Zp.colour(), None, Dashed);
    let zwo = find(Look::ZpW.colour(), None, Solid);
    let fb = find(Look::FpZpW.colour(), Some("FP+ZP+W, behind"), Dashed);
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
    for (j, k) in [(13.0, 3.0), (17.0, 4.0)] {
        assert!((at(zb, j) - zp(j)).abs() < 1e-9 * zp(j), "ZP at {j}");
        assert!((at(fb, j) - fp(k)).abs() < 1e-9 * fp(k), "FP at {j}");
    }
    assert!(at(zb, 13.0) < at(fb, 13.0));
    assert!(at(zb, 17.0) > at(fb, 17.0));
    assert!((fp(4.0) - 37.987).abs() < 0.001 && (zp(17.0) - 38.317).abs() < 0.001);
    // Every ZP curve runs to 40 maps, FP+ZP+W to 4 · 9 + 1 = 37.
    for s in [zo, zb, zwo] {
        assert_eq!(series[s].points.last().unwrap().0, 40.0, "series {s}");
    }
    assert_eq!(series[fb].points.last().unwrap().0, 37.0);
}

/// Fig 12 (issue 25 review): the coincident behind lines ZP and ZP+W are one legend entry,
/// "ZP = ZP+W, behind", drawn at the normal width in (a) (a second entry with a width-5
/// line had an oversized marker); in (b) the ZP line carries no marker (at 17 maps it lay
/// under FP+ZP+W's: 38.32 against 37.99, Eq 20 and 21 by hand in the test above), both
/// values are written, and the x range is padded so that the edge markers are whole.
#[test]
fn fig12_one_entry_for_the_coincident_lines_and_a_visible_crossover() {
    let fig = fig12().map_err(|e| e.named("lloyd2006-fig12")).unwrap();
    // One key for both panels, (a)'s.
    for (chart, key) in fig
        .page
        .charts
        .iter()
        .zip([vec!["ZP = ZP+W, behind"], vec![]])
    {
        let behind: Vec<&str> = chart
            .series
            .iter()
            .filter_map(|s| s.label.as_deref())
            .filter(|l| l.starts_with("ZP") && l.contains("behind"))
            .collect();
        assert_eq!(behind, key, "{}", chart.title);
        assert!(chart.series.iter().all(|s| s.width <= 3), "{}", chart.title);
    }
    // ZP's open markers in (b) only between FP+ZP+W's counts 4k + 1 (sixth review: ZP's
    // curve behind in its own colour, dashed with open markers).
    let zoom = &fig.page.charts[1];
    for s in &zoom.series {
        let zp = s.colour == Look::Zp.colour() && !s.points.is_empty();
        if zp && s.markers {
            for p in s.points.iter().filter(|p| p.1.is_finite()) {
                assert_ne!((p.0 as usize) % 4, 1, "ZP marker at {} maps", p.0);
            }
        }
        assert!(!(zp && s.label.is_some()), "{s:?}");
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
    let zoom = &fig.page.charts[1];
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
    // Series 0 is ZP's line (1 its open markers), the last FP+ZP+W.
    let fp = zoom.series.len() - 1;
    assert!((at(fp, 17.0) - (8.0 * (r.powf(0.25) - 1.0) + 1.0)).abs() < 1e-9);
    assert!(at(0, 13.0) < at(fp, 13.0) && at(0, 17.0) > at(fp, 17.0));
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
    for chart in &fig.page.charts {
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
            } else if chart.title.starts_with("(a)") && s.label.is_some() && !s.sample {
                assert!(!s.markers, "{label}: a marker at each of its counts");
            }
        }
    }
    assert_eq!(fp, 3);
}

/// Fig 10 (issue 35 reviews): one key for both panels, below them (the same five entries were
/// in each panel); each f/n's entry gives App. C's optimum ln(f/n)/(2 tan 30°) (by hand 1.99,
/// 3.99, 5.98, 7.98), and each optimum is drawn dashed in its own curve's colour, at that
/// value (four identical grey dashes could be told apart only by their order); the key has no
/// fifth, grey entry (a row of its own, a third of the box empty).
#[test]
fn fig10_one_key_below_with_each_optimum() {
    let fig = fig10().map_err(|e| e.named("lloyd2006-fig10")).unwrap();
    let svg = draw_svg(fig.size(), |area| fig.draw(area).unwrap());
    let texts = texts(&svg);
    // The x axes' labels: the key lies under both.
    let axis: Vec<f64> = texts
        .iter()
        .filter(|t| t.1 == "number of z-partitions k")
        .map(|t| t.2)
        .collect();
    assert_eq!(axis.len(), 2, "{svg}");
    let tan = 30f64.to_radians().tan();
    let a = &fig.page.charts[0];
    let optima: Vec<_> = a.series.iter().filter(|s| s.reference).collect();
    assert_eq!(optima.len(), 4);
    // 10⁴ written as a power (its superscript 4 read back as a digit).
    for (i, (ratio, written)) in [
        (10f64, "10"),
        (100.0, "100"),
        (1000.0, "1000"),
        (1e4, "104"),
    ]
    .into_iter()
    .enumerate()
    {
        let opt = ratio.ln() / (2.0 * tan);
        let want = format!("f/n\u{a0}=\u{a0}{written}, Sopt\u{a0}=\u{a0}{opt:.2}");
        let found: Vec<f64> = texts.iter().filter(|t| t.1 == want).map(|t| t.2).collect();
        assert_eq!(found.len(), 1, "{want} once in {texts:#?}");
        assert!(
            found[0] > axis[0] && found[0] > axis[1],
            "{want} above an axis"
        );
        let curve = a
            .series
            .iter()
            .find(|s| {
                s.label
                    .as_deref()
                    .is_some_and(|l| l.contains(&format!("{opt:.2}")))
            })
            .unwrap();
        let line = optima[i];
        assert_eq!(line.colour, curve.colour, "f/n = {ratio}");
        assert_eq!(line.dash, crate::plot::chart::Dash::Dashed);
        assert!(
            line.points.iter().all(|p| (p.1 - opt).abs() < 1e-9),
            "{ratio}"
        );
    }
    let colours: Vec<_> = optima.iter().map(|s| s.colour).collect();
    for (i, c) in colours.iter().enumerate() {
        assert!(!colours[..i].contains(c), "{colours:?}");
    }
    let key: Vec<_> = a.series.iter().filter(|s| s.label.is_some()).collect();
    assert_eq!(key.len(), 4);
    let caption = fig.page.caption.join(" ");
    assert!(
        caption.contains("The paper does not state the f/n of its curve."),
        "{caption}"
    );
}

/// Fig 10 (issue 35 review): both panels over the same k (1 to 16: (a) ran to 20, (b) to 16)
/// with the same ticks; the f/n are a sweep, none in a scheme's colour (f/n = 100 was ZP+W's
/// vermillion), each with its own marker shape, on a few k only (a marker on each of the 16 ran
/// into a chain).
#[test]
fn fig10_panels_share_k_and_the_sweep_marks_few_points() {
    use crate::plot::chart::Marker;
    let fig = fig10().map_err(|e| e.named("lloyd2006-fig10")).unwrap();
    let (a, b) = (&fig.page.charts[0], &fig.page.charts[1]);
    assert_eq!((a.x.min, a.x.max), (1.0, 16.0));
    assert_eq!((b.x.min, b.x.max), (1.0, 16.0));
    assert_eq!(a.x.ticks(), b.x.ticks());
    let curves: Vec<_> = a.series.iter().filter(|s| !s.reference).collect();
    assert_eq!(curves.len(), 4);
    let mut shapes = Vec::new();
    for s in &curves {
        assert!(!PALETTE.contains(&s.colour), "{:?}", s.label);
        assert!(!s.markers, "{:?}: a marker on every k", s.label);
        shapes.push(Marker::of(s.colour));
    }
    for (i, m) in shapes.iter().enumerate() {
        assert!(!shapes[..i].contains(m), "{shapes:?}");
    }
}

/// Fig 10 (b) divides each curve by its optimum: at k = 1, Eq 18 over App. C is
/// (f/n − 1)/ln(f/n) (θ cancels: 999/ln 1000 = 144.62 for f/n = 1000), and every ratio falls
/// towards 1 and stays above it.
#[test]
fn fig10_ratio_panel_tends_to_one() {
    let fig = fig10().map_err(|e| e.named("lloyd2006-fig10")).unwrap();
    let ratio = &fig.page.charts[1];
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

/// The centres of every `<polygon>` (a marker) of an SVG.
fn polygon_centres(svg: &str) -> Vec<(f64, f64)> {
    polygon_centres_where(svg, |_| true)
}

/// The centres of the `<polygon>`s (markers) of an SVG whose line passes `keep`.
pub(super) fn polygon_centres_where(svg: &str, keep: impl Fn(&str) -> bool) -> Vec<(f64, f64)> {
    svg.lines()
        .filter(|l| l.starts_with("<polygon") && keep(l))
        .filter_map(|l| {
            let pts = crate::plot::chart::read_svg::points(l)?;
            let n = pts.len() as f64;
            Some((
                pts.iter().map(|p| p.0).sum::<f64>() / n,
                pts.iter().map(|p| p.1).sum::<f64>() / n,
            ))
        })
        .collect()
}

/// Fig 5 (a) (issue 35 review: seven markers piled up at z = 18–19, where all its curves meet
/// 0.05): no marker lies right of z = 15, read in the SVG from (a)'s tick labels 15 and 20.
#[test]
fn fig5_no_markers_where_the_curves_meet() {
    let fig = fig5().map_err(|e| e.named("lloyd2006-fig5")).unwrap();
    let svg = draw_svg(fig.size(), |area| fig.draw(area).unwrap());
    let texts = texts(&svg);
    let tick_x = |label: &str| {
        let mut xs: Vec<f64> = texts
            .iter()
            .filter(|t| t.1 == label)
            .map(|t| crate::plot::chart::read_svg::attr(t.0, "x").unwrap())
            .collect();
        xs.sort_by(f64::total_cmp);
        xs[0]
    };
    let (x15, x20) = (tick_x("15"), tick_x("20"));
    let axis_y = texts.iter().find(|t| t.1 == "15").unwrap().2;
    let late: Vec<_> = polygon_centres(&svg)
        .into_iter()
        .filter(|p| p.0 > x15 + 2.0 && p.0 <= x20 + 6.0 && p.1 < axis_y)
        .collect();
    assert!(late.is_empty(), "markers right of z = 15 in (a): {late:?}");
}

/// Fig 12 gives FP+ZP+W the colour the worst-case figure and Fig 13 give it (issue 35: behind,
/// it was olive), [`Look::FpZpW`], for every FP+ZP+W series of both panels, the two lights
/// told apart by the markers' fill (sixth review: filled overhead, open behind), one shape.
#[test]
fn fig12_fp_zp_w_has_its_colour_for_both_lights() {
    let fig = fig12().map_err(|e| e.named("lloyd2006-fig12")).unwrap();
    let mut fills = Vec::new();
    for chart in &fig.page.charts {
        for s in &chart.series {
            if s.label.as_deref().is_some_and(|l| l.starts_with("FP+ZP+W")) {
                assert_eq!(s.colour, Look::FpZpW.colour(), "{:?}", s.label);
                assert_eq!(s.shape, None, "{:?}", s.label);
                fills.push(s.hollow);
            }
        }
    }
    // (a) behind and overhead (the key's order), (b) behind.
    assert_eq!(fills, [true, false, true]);
}

/// Fig 12 (issue 35 review): (a)'s y axis spans the data from 2 maps on (it ran to 10⁶ for
/// ZP's one map and left the informative data in its bottom third): at most 10⁴, above every
/// point from 2 maps on (ZP behind with 2 maps, Eq 20: 2 · 1000 = 2000, the largest), below
/// the least (ZP+W overhead at 40 maps, above 6); the key is written once, under both panels,
/// and the shared behind curve carries no marker in either panel (circles in (a), none in
/// (b)): no grey marker in the SVG.
#[test]
fn fig12_y_range_to_the_data_and_one_key() {
    let fig = fig12().map_err(|e| e.named("lloyd2006-fig12")).unwrap();
    let a = &fig.page.charts[0];
    assert!(a.y.max <= 1e4 && a.y.min >= 1.0, "{:?}", a.y);
    let mut top: f64 = 0.0;
    for s in &a.series {
        for &(j, v) in s.points.iter().filter(|p| p.1.is_finite() && p.0 >= 2.0) {
            assert!(v > a.y.min && v < a.y.max, "{:?}: {v} at {j} maps", s.label);
            top = top.max(v);
        }
    }
    assert!((top - 2000.0).abs() < 1e-9, "{top}");
    let svg = draw_svg(fig.size(), |area| fig.draw(area).unwrap());
    let texts = texts(&svg);
    let axis: Vec<f64> = texts
        .iter()
        .filter(|t| t.1 == "number of shadow maps")
        .map(|t| t.2)
        .collect();
    assert_eq!(axis.len(), 2);
    for key in ["FP+ZP+W, behind", "ZP = ZP+W, behind", "ZP, overhead"] {
        let ys: Vec<f64> = texts.iter().filter(|t| t.1 == key).map(|t| t.2).collect();
        assert_eq!(ys.len(), 1, "{key}");
        assert!(ys[0] > axis[0] && ys[0] > axis[1], "{key} above an axis");
    }
    assert!(!svg.contains("<polygon fill=\"#5A5A5A\""), "a grey marker");
}

/// Fig 6 (issue 35 reviews): the key names the three quantities only, and the caption gives
/// each maximum one way, by hand M_x's 100 (f at η = −1), M_z's 99/(2 tan 30°) = 85.74 and
/// S̄'s 8574 (the key's "(maximum 8574)" made a box too wide for (a)'s empty corner); no
/// scheme's colour (M_x, M_z and S̄ were the blue, vermillion and green of ZP, ZP+W and
/// FP+ZP+W), and the three differ in dash too.
#[test]
fn fig6_key_in_one_form_and_no_scheme_colours() {
    let fig = fig6().map_err(|e| e.named("lloyd2006-fig6")).unwrap();
    let a = &fig.page.charts[0];
    let labels: Vec<&str> = a.series.iter().filter_map(|s| s.label.as_deref()).collect();
    let c = 99.0 / (2.0 * 30f64.to_radians().tan());
    assert_eq!(labels, ["M_x", "M_z", "S̄ = M_x M_z"]);
    let caption = fig.page.caption.join(" ").replace('\u{a0}', " ");
    for max in [
        "M_x = 100".to_string(),
        format!("M_z = {c:.2}"),
        format!("S̄ = {:.0}", 100.0 * c),
    ] {
        assert!(caption.contains(&max), "{max} not in {caption}");
    }
    let mut dashes = Vec::new();
    for s in a.series.iter().filter(|s| s.label.is_some()) {
        let schemes = [Look::Psm, Look::Lispsm, Look::Uniform, Look::Zp, Look::ZpW];
        assert!(
            schemes.iter().all(|l| l.colour() != s.colour),
            "{:?}",
            s.label
        );
        assert!(!dashes.contains(&s.dash), "{:?}", s.label);
        dashes.push(s.dash);
    }
}
