//! Lloyd, Yoon, Tuft, Manocha 2005, *Subdivided Shadow Maps*: Fig 4 and Fig 7.

use super::chart::{fmt_times_ten, linspace, Axis, Charts, LineChart, Series, PALETTE};
use super::{Column, Fail, Figure};
use crate::analytic::subdivided::{distribution_g, g_min, n_from_xi, subdivided_max_error};
use plotters::coord::Shift;
use plotters::prelude::{DrawingArea, DrawingBackend};
use plotters::prelude::{RGBColor, SeriesLabelPosition};

/// α of Fig 4 (the paper does not print it).
pub(super) const FIG4_ALPHA: f64 = 10.0;

/// ξ with the minus sign U+2212.
fn fmt_signed(v: f64) -> String {
    format!("{v}").replace('-', "\u{2212}")
}

/// Fig 4: the error distribution g(z) over z ∈ [1, α] for n chosen by ξ = 1, ½, 0, −½, −1.
pub(super) fn fig4() -> Result<Tall, Fail> {
    let alpha = FIG4_ALPHA;
    let zs = linspace(1.0, alpha, 200);
    let mut c = LineChart::new(
        "",
        Axis::linear("depth z (near plane 1, far plane α)", 1.0, alpha),
        // A tick every quarter.
        Axis::every("error distribution g(z)", 0.0, 1.05, 0.0, 0.25),
    );
    c.legend = SeriesLabelPosition::UpperMiddle;
    for (i, xi) in [1.0, 0.5, 0.0, -0.5, -1.0].into_iter().enumerate() {
        let n = n_from_xi(alpha, xi)?;
        let label = match n.as_finite() {
            Some(v) if v == v.round() => format!("n = {v} (ξ = {})", fmt_signed(xi)),
            Some(v) => format!("n = {v:.3} (ξ = {})", fmt_signed(xi)),
            None => format!("n = ∞ (ξ = {})", fmt_signed(xi)),
        };
        let pts = zs
            .iter()
            .map(|&z| Ok((z, distribution_g(alpha, n, z)?)))
            .collect::<Result<Vec<_>, crate::Error>>()?;
        // Labelled at the curve's right end (the far plane), where the five are apart.
        c.series.push(Series::line(label, pts, PALETTE[i]).direct());
    }
    let g0 = g_min(alpha)?;
    let grey = RGBColor(90, 90, 90);
    let mut s = Series::line(String::new(), vec![(1.0, g0), (alpha, g0)], grey).dotted();
    s.label = None;
    s.width = 1;
    c.series.push(s);
    Ok(Tall(
        Charts {
            size: (520, 500),
            title: "Error distribution function g for several warp distances n".into(),
            caption: vec![format!(
                "Lloyd et al. 2005, Fig. 4 (Eq 3, 4), α\u{a0}=\u{a0}{alpha}: g for the n of \
                 ξ\u{a0}=\u{a0}1 (PSM), ½, 0 (LiSPSM, n\u{a0}=\u{a0}1\u{a0}+\u{a0}√α), −½ and \
                 −1 (the uniform map, n\u{a0}=\u{a0}∞). Dotted: the least maximum \
                 g_0\u{a0}=\u{a0}1/√α\u{a0}=\u{a0}{g0:.3}. The maximum of g is on the near \
                 plane for ξ\u{a0}≤\u{a0}0 and on the far plane for ξ\u{a0}>\u{a0}0."
            )],
            charts: vec![c],
        },
        640,
    ))
}

/// A figure of one chart whose one-column layout is `.1` units tall: about as tall as in two
/// columns, so that its direct labels keep the room they have there (Fig 4's five and Fig 7's
/// eight line-end labels covered other lines in a chart 290 units tall).
pub(super) struct Tall(pub(super) Charts, u32);

impl Figure for Tall {
    fn size(&self) -> (u32, u32) {
        self.0.size
    }

    fn single_size(&self) -> Option<(u32, u32)> {
        Some((Column::Single.width(), self.1))
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        self.0.draw(root)
    }
}

/// Fig 7: the maximum error with k face subdivisions (Eq 7), divided by its value at k = 1, for
/// several α; ξ = 0 (solid) and |ξ| = 1 (dashed), on a logarithmic axis.
pub(super) fn fig7() -> Result<Tall, Fail> {
    let ks: Vec<usize> = (1..=10).collect();
    let theta = 30f64.to_radians();
    let ratio = |alpha: f64, k: usize, xi: f64| -> Result<f64, crate::Error> {
        Ok(subdivided_max_error(alpha, k, xi, theta, 1.0, 1.0)?
            / subdivided_max_error(alpha, 1, xi, theta, 1.0, 1.0)?)
    };
    // No subtitle: the labels and the caption say which line is which ξ.
    let mut c = LineChart::new(
        "",
        // A tick at every k (the paper's k = 1 … 10).
        Axis::every("number of face subdivisions k", 1.0, 10.0, 1.0, 1.0),
        // Up to 2, so that the top curve's label fits above it (the curves are too close for a
        // label between them).
        Axis::log10("m_{max}(k) / m_{max}(1) (log scale)", 1e-3, 2.0),
    );
    c.legend = SeriesLabelPosition::LowerLeft;
    let alphas = [10.0, 100.0, 1000.0, 10_000.0];
    for (i, alpha) in alphas.into_iter().enumerate() {
        for (xi, dashed) in [(0.0, false), (1.0, true)] {
            let pts = ks
                .iter()
                .map(|&k| Ok((k as f64, ratio(alpha, k, xi)?)))
                .collect::<Result<Vec<_>, crate::Error>>()?;
            let label = if dashed {
                format!("α = {}, |ξ| = 1", fmt_times_ten(alpha))
            } else {
                format!("α = {}, ξ = 0", fmt_times_ten(alpha))
            };
            // Labelled directly at the line's end, k = 10 (a legend covered the dashed
            // curves; labels along the lines named none where every curve meets).
            let s = Series::line(label, pts, PALETTE[i]).with_markers().direct();
            c.series.push(if dashed { s.dashed() } else { s });
        }
    }
    // The report's "nearly 5 times" (its Fig 9, α = 100): which ξ gives it.
    let alpha = 100.0_f64;
    let gain = |xi: f64, k: usize| -> Result<f64, crate::Error> { Ok(1.0 / ratio(alpha, k, xi)?) };
    let (g0_2, g1_2) = (gain(0.0, 2)?, gain(1.0, 2)?);
    // The ξ = 0 gain as k → ∞: m(k)/m(1) = k(α^{1/k} − 1)α^{1/2 − 1/(2k)}/(α − 1) (Eq 7) tends to
    // √α ln α/(α − 1), so the gain tends to its inverse.
    let g0_inf = (alpha - 1.0) / (alpha.sqrt() * alpha.ln());
    Ok(Tall(
        Charts {
            size: (520, 620),
            title: "Maximum error against the number of face subdivisions".into(),
            caption: vec![format!(
                "Lloyd et al. 2005, Fig. 7 (Eq 7): the maximum error with k self-similar face \
             subdivisions over its value at k\u{a0}=\u{a0}1; solid: ξ\u{a0}=\u{a0}0, dashed: \
             |ξ|\u{a0}=\u{a0}1. The report's \"nearly 5 times\" at α\u{a0}=\u{a0}{alpha} \
             (its Fig. 9) needs |ξ|\u{a0}=\u{a0}1: {g1_2:.1}× at k\u{a0}=\u{a0}2; \
             ξ\u{a0}=\u{a0}0 gives {g0_2:.2}×, and at most \
             (α\u{a0}−\u{a0}1)/(√α\u{a0}ln\u{a0}α)\u{a0}=\u{a0}{g0_inf:.2}×."
            )],
            charts: vec![c],
        },
        780,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Fig 4's ξ = 0 curve (n = 1 + √α) is g₀ = 1/√α on both planes, and ξ = 1 (n = 1) is z/α,
    /// both by hand from Eq 3.
    #[test]
    fn fig4_curves_by_hand() {
        let fig = fig4().map_err(|e| e.named("lloyd2005-fig4")).unwrap().0;
        let s = &fig.charts[0].series;
        let g0 = 1.0 / FIG4_ALPHA.sqrt();
        assert!((s[2].points[0].1 - g0).abs() < 1e-12);
        assert!((s[2].points.last().unwrap().1 - g0).abs() < 1e-12);
        for &(z, g) in &s[0].points {
            assert!((g - z / FIG4_ALPHA).abs() < 1e-12);
        }
    }

    /// Fig 7 by hand from Eq 7 with ξ = 0: m(k)/m(1) = k(α^{1/k} − 1)α^{1/2 − 1/(2k)}/(α − 1);
    /// at α = 100, k = 2: 2 · 9 · 10^{1/2}/99 = 0.5750.
    #[test]
    fn fig7_ratio_by_hand() {
        let fig = fig7().map_err(|e| e.named("lloyd2005-fig7")).unwrap().0;
        let alpha100 = &fig.charts[0].series[2].points;
        let want = 2.0 * 9.0 * 10f64.sqrt() / 99.0;
        assert!((alpha100[1].1 - want).abs() < 1e-12, "{}", alpha100[1].1);
        assert_eq!(alpha100[0].1, 1.0);
        // |ξ| = 1: m(k)/m(1) = k(α^{1/k} − 1)/(α − 1) by hand from Eq 7; at α = 100, k = 2:
        // 18/99, the 5.5× that matches the report's "nearly 5 times" (ξ = 0 gives 1.74×).
        let xi1 = &fig.charts[0].series[3].points;
        assert!((xi1[1].1 - 18.0 / 99.0).abs() < 1e-12, "{}", xi1[1].1);
        assert!(fig.charts[0].x.max <= 10.0, "no empty k > 10 area");
        // Formulas keep their spaces unbroken (no-break spaces): "|ξ| =⏎1" broke a line.
        let caption = &fig.caption[0];
        assert!(caption.contains("5.5× at k\u{a0}=\u{a0}2"), "{caption}");
        assert!(caption.contains("gives 1.74×"), "{caption}");
        assert!(caption.contains("|ξ|\u{a0}=\u{a0}1"), "{caption}");
    }

    /// Fig 7 labels each of its eight lines at the line's end, k = 10 (issue 35 item 9; the
    /// labels were spread along the lines, where they named none near k ≤ 3), in both
    /// layouts: read back from the SVG, every label ends within 12 units of the plot's right
    /// edge (the largest x of any line), and the labels run top to bottom in the order of the
    /// lines' values at k = 10 (Eq 7, found here from the series' own last points), so that
    /// each sits by its own line's end.
    #[test]
    fn fig7_labels_sit_at_the_line_ends() {
        use super::super::chart::read_svg::{attr, draw_svg, visible};
        use super::super::chart::with_page;
        let fig = fig7().map_err(|e| e.named("lloyd2005-fig7")).unwrap();
        let series = &fig.0.charts[0].series;
        let mut by_end: Vec<(&str, f64)> = series
            .iter()
            .map(|s| (s.label.as_deref().unwrap(), s.points.last().unwrap().1))
            .collect();
        by_end.sort_by(|a, b| b.1.total_cmp(&a.1));
        // As the SVG reads: no spaces, superscript digits as digits.
        let plain = |t: &str| -> String {
            t.chars()
                .filter(|c| *c != ' ')
                .map(|c| match "⁰¹²³⁴⁵⁶⁷⁸⁹".chars().position(|s| s == c) {
                    Some(d) => char::from(b'0' + d as u8),
                    None => c,
                })
                .collect()
        };
        let want: Vec<String> = by_end.iter().map(|l| plain(l.0)).collect();
        for (column, size) in [
            (Column::Double, fig.size()),
            (Column::Single, fig.single_size().unwrap()),
        ] {
            let svg = with_page(false, column, || {
                draw_svg(size, |area| fig.draw(area).unwrap())
            });
            let right = svg
                .lines()
                .filter(|l| l.starts_with("<polyline"))
                .flat_map(|l| {
                    let at = l.find("points=\"").unwrap() + 8;
                    l[at..at + l[at..].find('"').unwrap()]
                        .split_whitespace()
                        .map(|p| p.split_once(',').unwrap().0.parse::<f64>().unwrap())
                        .collect::<Vec<_>>()
                })
                .fold(f64::NEG_INFINITY, f64::max);
            let mut labels: Vec<(String, f64, f64)> = svg
                .lines()
                .filter(|l| l.starts_with("<text") && visible(l).starts_with("α ="))
                .map(|l| {
                    let (x, y) = (attr(l, "x").unwrap(), attr(l, "y").unwrap());
                    assert!(l.contains("text-anchor=\"end\""), "{l}");
                    (plain(&visible(l)), x, y)
                })
                .collect();
            assert_eq!(labels.len(), 8, "{column:?}");
            for (t, x, _) in &labels {
                assert!(
                    x <= &right && right - x <= 12.0,
                    "{column:?}: {t} ends at {x}, line at {right}"
                );
            }
            labels.sort_by(|a, b| a.2.total_cmp(&b.2));
            let got: Vec<String> = labels.into_iter().map(|l| l.0).collect();
            assert_eq!(got, want, "{column:?}");
        }
    }

    /// Fig 4's PSM curve is "n = 1" (ξ = 1 gives n = 1 exactly, Eq 4), not "n = 1.000".
    #[test]
    fn fig4_names_the_psm_curve_n_1() {
        let f4 = fig4().map_err(|e| e.named("lloyd2005-fig4")).unwrap().0;
        let labels: Vec<&str> = f4.charts[0]
            .series
            .iter()
            .filter_map(|s| s.label.as_deref())
            .collect();
        assert!(labels.contains(&"n = 1 (ξ = 1)"), "{labels:?}");
    }
}
