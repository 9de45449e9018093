//! Lloyd, Yoon, Tuft, Manocha 2005, *Subdivided Shadow Maps*: Fig 4 and Fig 7.

use super::chart::{
    column, fmt_times_ten, linspace, sweep, Axis, Charts, LineChart, Look, Marker, Series,
};
use super::{Column, Fail, Figure};
use crate::analytic::subdivided::{distribution_g, g_min, n_from_xi, subdivided_max_error};
use plotters::coord::Shift;
use plotters::prelude::{DrawingArea, DrawingBackend};
use plotters::prelude::{RGBColor, SeriesLabelPosition};

/// The depth ratio f/n of Fig 4 (the report's α, which it does not print; written f/n as in
/// the Lloyd 2006 figures, since barroso-fig5's α is another ratio).
pub(super) const FIG4_ALPHA: f64 = 10.0;

/// ξ with the minus sign U+2212, halves as ½ (as the caption writes them).
fn fmt_signed(v: f64) -> String {
    let s = if v.abs() == 0.5 {
        format!("{}½", if v < 0.0 { "-" } else { "" })
    } else {
        format!("{v}")
    };
    s.replace('-', "\u{2212}")
}

/// Where Fig 4 asks its curves' labels to end: at z = 9.73 (the sample nearest 9.75), so that
/// a label's text ends about 15 units inside the axis end (a label at the end point itself
/// ran to the frame) and reads as its curve's by the far plane, where the five are apart.
const FIG4_LABEL_AT: usize = 193;

/// Where Fig 4's ξ = 0 curve asks its label to end: z = 7.78. Asked at z = 8.87, the label
/// went under the curve by the far plane, its left end under the ▲ at z ≈ 7.1, its text 1.3
/// units from the marker's base (the tenth review, R10-lloyd2005-fig4-1: the prime of "n′"
/// merged with it); asked here, it stands under the curve from z ≈ 6.2 to 9.4 in two columns
/// (6.6 to 9.2 in one), the ▲ at z ≈ 7.1 over its middle, its text at least 3 units from every
/// marker and curve in every form.
const FIG4_XI_0_LABEL_AT: usize = 150;

/// Where Fig 4's ξ = 0 curve asks its label to end in one column: z = 9.37. At z = 7.78 the
/// label's centre stood 15.7 units from its curve and 15.8 from ξ = −½'s, and once labels had to
/// be 3 units nearer their own line (the nineteenth review) it moved to 1.5 units from the ▲ at
/// z ≈ 8.9 (tests/figures_l2005_review10.rs wants 2); here it stands under its curve, 2.5 units
/// from every marker, 13.2 units from its curve and 16.1 from ξ = −½'s.
const FIG4_XI_0_SINGLE_LABEL_AT: usize = 185;

/// Where Fig 4's ξ = −½ curve asks its label to end in one column: z = 8.01.
const FIG4_XI_HALF_LABEL_AT: usize = 155;

/// Fig 4's samples of z ∈ [n, f] = [1, f/n].
const FIG4_SAMPLES: usize = 200;

/// Fig 4's chart. Each curve is labelled directly with its warp parameter n′ (the report's n,
/// written n′ as in the Lloyd 2006 figures, apart from the near plane n = 1): across two
/// columns "n′ = 1.613 (ξ = ½)", the schemes named ("n′ = 1 (ξ = 1, PSM)"); in one column (a
/// plot about 220 units wide, where those labels lay on their own and other curves)
/// "n′ = 1.613", the caption giving the ξ and the schemes.
fn fig4_chart(single: bool) -> Result<LineChart, Fail> {
    let alpha = FIG4_ALPHA;
    let zs = linspace(1.0, alpha, FIG4_SAMPLES);
    let mut c = LineChart::new(
        "",
        // One column: the name alone (the page's width holds no more).
        // Labelled at the near plane z = 1 too (the fifth review: the first label was 2), and
        // named with both planes' values.
        Axis::linear(format!("depth z (n = 1, f = {alpha})"), 1.0, alpha)
            .labelled_at(&[1.0, 2.0, 4.0, 6.0, 8.0, 10.0]),
        // A tick every fifth: 0, 0.2, …, 1 (quarters wrote 1, 0.75, 0.5, 0.25, 0: two formats).
        Axis::every("error distribution g(z)", 0.0, 1.05, 0.0, 0.2),
    );
    c.legend = SeriesLabelPosition::UpperMiddle;
    for (i, xi) in FIG4_XI.into_iter().enumerate() {
        let n = n_from_xi(alpha, xi)?;
        let name = match n.as_finite() {
            Some(v) if v == v.round() => format!("n′ = {v}"),
            Some(v) => format!("n′ = {v:.3}"),
            None => "n′ = ∞".to_string(),
        };
        let scheme = FIG4_SCHEMES[i];
        let label = match (single, scheme) {
            (true, _) => name,
            (false, None) => format!("{name} (ξ = {})", fmt_signed(xi)),
            (false, Some(s)) => format!("{name} (ξ = {}, {s})", fmt_signed(xi)),
        };
        let pts = zs
            .iter()
            .map(|&z| Ok((z, distribution_g(alpha, n, z)?)))
            .collect::<Result<Vec<_>, crate::Error>>()?;
        // Labelled by the curve's right end (the far plane), where the five are apart.
        let mut s = Series::line(label, pts, fig4_colour(i)).direct();
        s.direct_at = Some(zs[FIG4_LABEL_AT]);
        // ξ = −½ a diamond, not the sweep's left triangle: the ξ = 0 and −1 curves carry ▲ and
        // ▼, and three turns of one triangle do not tell the curves apart in greyscale (X6).
        // ξ = 0: under its curve (the g₀ line's label is over it by the far plane), its end
        // asked at z = 7.78, so that it keeps clear of the curve's markers.
        if i == 2 {
            s.direct_at = Some(
                zs[if single {
                    FIG4_XI_0_SINGLE_LABEL_AT
                } else {
                    FIG4_XI_0_LABEL_AT
                }],
            );
        }
        // ξ = ±½, the sweep's two, dashed: each runs by a warp one grey from it, ξ = ½ by PSM
        // (L* 18 and 21) and ξ = −½ by the uniform map (60 and 54), and where ξ = ½ crosses
        // PSM its ★ sat on the crossing (the nineteenth review, R19-lloyd2005-fig4-1).
        if i == 1 || i == 3 {
            s = s.dashed();
        }
        if i == 3 {
            s.shape = Some(Marker::Diamond);
            // One column: its label over its own curve by z = 8, where the lilac curve is
            // alone under the ξ = 0 one (by the far plane it lay nearer the orange curve).
            if single {
                s.direct_at = Some(zs[FIG4_XI_HALF_LABEL_AT]);
            }
        }
        c.series.push(s);
    }
    // The least maximum g₀, a grey dotted reference line named in the figure (the bare form
    // has no caption to say what it is), its label above the line by the far plane (z ≈ 7–9.7),
    // where no curve comes within 3 units of it: the first series, so that its label is placed
    // first and takes that room (the ξ = 0 curve's label then goes under its own curve there).
    // Across two columns it was by the middle of the axis, squeezed between the ξ = ½ and
    // ξ = −1 curves, 1 unit from each (the sixth review, R6-lloyd2005-fig4-1).
    let g0 = g_min(alpha)?;
    let mut s = Series::line(
        "g_0 = 1/√(f/n)",
        zs.iter().map(|&z| (z, g0)).collect(),
        RGBColor(90, 90, 90),
    )
    .dotted()
    .reference()
    .direct();
    s.direct_at = Some(zs[FIG4_LABEL_AT]);
    s.width = 1;
    c.series.insert(0, s);
    Ok(c)
}

/// Fig 4's ξ: PSM, between, LiSPSM, between, the uniform map.
const FIG4_XI: [f64; 5] = [1.0, 0.5, 0.0, -0.5, -1.0];

/// The schemes Fig 4's ξ give, as its labels name them.
const FIG4_SCHEMES: [Option<&str>; 5] = [Some("PSM"), None, Some("LiSPSM"), None, Some("uniform")];

/// Fig 4: the error distribution g(z) over z ∈ [1, f/n] for n′ chosen by ξ = 1, ½, 0, −½, −1.
pub(super) fn fig4() -> Result<Tall, Fail> {
    let alpha = FIG4_ALPHA;
    let c = fig4_chart(false)?;
    let g0 = g_min(alpha)?;
    let head = format!(
        "Lloyd et al. 2005, Fig. 4 (Eq 3, 4), f/n\u{a0}=\u{a0}{alpha}: g for the n′ of \
         ξ\u{a0}=\u{a0}1 (PSM), ½, 0 (LiSPSM, n′\u{a0}=\u{a0}1\u{a0}+\u{a0}√(f/n)), −½ \
         and −1 (uniform, n′\u{a0}=\u{a0}∞); n′: the paper's n, its warp. Dotted: the \
         least maximum \
         g_0\u{a0}=\u{a0}1/√(f/n)\u{a0}=\u{a0}{g0:.3}."
    );
    let tail = "The maximum of g is on the near plane for ξ\u{a0}≤\u{a0}0 and on the far plane \
                for ξ\u{a0}>\u{a0}0.";
    Ok(Tall {
        charts: Charts {
            size: (520, 500),
            title: "Error distribution g for several n′".into(),
            caption: vec![format!("{head} {tail}")],
            charts: vec![c],
        },
        single_height: FIG4_SINGLE_HEIGHT,
        // One column: the same direct labels; the caption keeps only what the figure cannot
        // show.
        single_caption: vec![format!(
            "Lloyd et al. 2005, Fig. 4 (Eq 3, 4), f/n\u{a0}=\u{a0}{alpha}: g \
             for the n′ (its n) of ξ\u{a0}=\u{a0}1 (PSM), ½, 0 (LiSPSM), −½ and −1 \
             (uniform), top to bottom at the far plane. Dotted: least max \
             g_0\u{a0}=\u{a0}{g0:.3}."
        )],
        single_charts: Some(vec![fig4_chart(true)?]),
    })
}

/// Fig 4's one-column height, in units: 480 (384 pt printed), for one line chart (it was 640,
/// a 1 : 2 portrait of one chart; the third figure review asked for about 300 pt, but the
/// chart's six direct labels need a plot about 270 units tall to keep clear of one another
/// and of the curves: at 440 units the g₀ label covered the ξ = 0 curve's).
const FIG4_SINGLE_HEIGHT: u32 = 480;

/// Fig 4's colour of its `i`-th curve (ξ = 1, ½, 0, −½, −1): the schemes' colours for PSM
/// (ξ = 1), LiSPSM (ξ = 0) and the uniform map (ξ = −1), and the parameter sweep's for the two
/// between them (each colour has its own marker, [`super::chart::Marker::of`]).
fn fig4_colour(i: usize) -> RGBColor {
    match i {
        0 => Look::Psm.colour(),
        1 => sweep(0, 2),
        2 => Look::Lispsm.colour(),
        3 => sweep(1, 2),
        _ => Look::Uniform.colour(),
    }
}

/// A figure of line charts with its own one-column height and shorter one-column caption
/// (Fig 4's single chart and Fig 7's two stacked panels keep their direct labels in one
/// column, in plots tall enough for the labels to stay apart).
pub(super) struct Tall {
    pub(super) charts: Charts,
    single_height: u32,
    single_caption: Vec<String>,
    /// The charts drawn in one column, where they differ from the two-column ones.
    single_charts: Option<Vec<LineChart>>,
}

impl Figure for Tall {
    fn size(&self) -> (u32, u32) {
        self.charts.size
    }

    fn single_size(&self) -> Option<(u32, u32)> {
        Some((Column::Single.width(), self.single_height))
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        if column() == Column::Double {
            return self.charts.draw(root);
        }
        let mut one = self.charts.clone();
        one.caption.clone_from(&self.single_caption);
        if let Some(charts) = &self.single_charts {
            one.charts.clone_from(charts);
        }
        one.draw(root)
    }
}

/// Fig 7: the maximum error with k face subdivisions (Eq 7), divided by its value at k = 1, for
/// several depth ratios f/n (the report's α); ξ = 0 and |ξ| = 1, on a logarithmic axis.
pub(super) fn fig7() -> Result<Tall, Fail> {
    let ks: Vec<usize> = (1..=10).collect();
    let theta = 30f64.to_radians();
    let ratio = |alpha: f64, k: usize, xi: f64| -> Result<f64, crate::Error> {
        Ok(subdivided_max_error(alpha, k, xi, theta, 1.0, 1.0)?
            / subdivided_max_error(alpha, 1, xi, theta, 1.0, 1.0)?)
    };
    // One panel per ξ, so that each line's label is its α alone and the four lines of a panel
    // lie far enough apart for a label beside each end (eight lines in one panel came within
    // 15 units of each other, too close for a label clear of the markers).
    let alphas = [10.0, 100.0, 1000.0, 10_000.0];
    let mut charts = Vec::new();
    // (ξ, panel, the panel's y range: to its lines' least value at k = 10, with room above the
    // top line's label).
    // (a) spans 1.3 decades: labelled at 2 and 5 between its two decades as well, so that
    // the caption's values (0.575 at k = 2) can be read off; (b) at its four decades. Both in
    // powers of ten (one format for the quantity).
    // The lower limits: (a) just under its least value, 0.095 (the fifth review: at 0.035 a
    // third of the plot was empty; its lowest label goes over its line; one column keeps
    // room under that end for the label, to 0.05); (b) under its least value, 1.5·10⁻³, with room for the lowest line's label
    // under its end, clear of the x axis (at 5·10⁻⁴ the label's box covered the axis line).
    let panels: [(f64, &str, f64, &[f64]); 2] = [
        (0.0, "(a) ξ = 0", FIG7_A_LOW, &[0.1, 0.2, 0.5, 1.0]),
        (1.0, "(b) |ξ| = 1", FIG7_B_LOW, &[1e-3, 1e-2, 1e-1, 1.0]),
    ];
    for (xi, title, lo, at) in panels {
        let mut c = LineChart::new(
            title,
            // A tick at every k (the paper's k = 1 … 10), the axis from k = 0.6 so that the four
            // k = 1 markers, where every line starts at 1, sit inside the frame (at k = 1 they
            // lay on the y axis and covered its tick 1: the sixth review, R6-lloyd2005-fig7-5).
            Axis::every("number of face subdivisions k", FIG7_K_MIN, 10.0, 1.0, 1.0),
            Axis::log10("m_{max}(k) / m_{max}(1) (log scale)", lo, 1.5)
                .labelled_at(at)
                .in_powers(),
        );
        c.legend = SeriesLabelPosition::LowerLeft;
        // Room for "5×10⁻¹" beside the axis' name (the default 64 units let them touch).
        c.y_label_area = Some(FIG7_Y_LABEL_AREA);
        for (i, alpha) in alphas.into_iter().enumerate() {
            let pts = ks
                .iter()
                .map(|&k| Ok((k as f64, ratio(alpha, k, xi)?)))
                .collect::<Result<Vec<_>, crate::Error>>()?;
            // Labelled directly at the line's end, k = 10; α is a sweep: its colours (and
            // their markers) are no scheme's.
            c.series.push(
                Series::line(
                    format!("f/n = {}", fmt_times_ten(alpha)),
                    pts,
                    sweep(i, alphas.len()),
                )
                .with_markers()
                .direct(),
            );
        }
        charts.push(c);
    }
    // The report's "nearly 5 times" (its Fig 9, α = 100): which ξ gives it.
    let alpha = 100.0_f64;
    let gain = |xi: f64, k: usize| -> Result<f64, crate::Error> { Ok(1.0 / ratio(alpha, k, xi)?) };
    let (g0_2, g1_2) = (gain(0.0, 2)?, gain(1.0, 2)?);
    // The ξ = 0 gain as k → ∞: m(k)/m(1) = k(α^{1/k} − 1)α^{1/2 − 1/(2k)}/(α − 1) (Eq 7) tends to
    // √α ln α/(α − 1), so the gain tends to its inverse.
    let g0_inf = (alpha - 1.0) / (alpha.sqrt() * alpha.ln());
    let charts_double = charts.clone();
    Ok(Tall {
        charts: Charts {
            size: (520, 500),
            title: "Maximum error against subdivisions".into(),
            caption: vec![format!(
                "Lloyd et al. 2005, Fig. 7 (Eq 7): the maximum error with k self-similar face \
                 subdivisions over its value at k\u{a0}=\u{a0}1, (a) for ξ\u{a0}=\u{a0}0 and \
                 (b) for |ξ|\u{a0}=\u{a0}1 (ξ: Eq 4's warp parameter; 0: LiSPSM, \
                 1: PSM, −1: the uniform map). The report's \"nearly 5 times\" at \
                 f/n\u{a0}=\u{a0}{alpha} (its Fig. 9) needs |ξ|\u{a0}=\u{a0}1: \
                 {g1_2:.1}× at k\u{a0}=\u{a0}2; ξ\u{a0}=\u{a0}0 gives {g0_2:.2}×, \
                 and at most (f/n\u{a0}−\u{a0}1)/(√(f/n)\u{a0}ln(f/n))\u{a0}=\u{a0}{g0_inf:.2}×."
            )],
            charts,
        },
        single_height: FIG7_SINGLE_HEIGHT,
        single_caption: vec![format!(
            "Lloyd et al. 2005, Fig. 7; ξ: Eq 4's warp (0: LiSPSM, ±1: PSM, uniform). \
             At f/n\u{a0}=\u{a0}{alpha}, k\u{a0}=\u{a0}2 gains {g1_2:.1}× with \
             |ξ|\u{a0}=\u{a0}1 (the report's \"nearly 5 times\"), {g0_2:.2}× with \
             ξ\u{a0}=\u{a0}0."
        )],
        // One column: the y axes' name without "(log scale)", so that it is no longer than
        // the plots, each about 110 units tall; the panel titles say it instead ("(a) ξ = 0,
        // log scale": every log axis says so in every form, the seventh review's R7-X-1).
        single_charts: Some(
            charts_double
                .into_iter()
                .enumerate()
                .map(|(i, mut c)| {
                    c.y.label = FIG7_SINGLE_Y.into();
                    c.title = format!("{}, log scale", c.title);
                    // (a)'s plot, about 110 units tall, has no room between the lines' ends
                    // for the f/n = 10⁴ label: it keeps room under the lowest end for it.
                    if i == 0 {
                        c.y.min = FIG7_A_LOW_SINGLE;
                    }
                    c
                })
                .collect(),
        ),
    })
}

/// Fig 7's y axes' name in one column: the quotient set tight (with spaces round "/" it
/// was 114 units, longer than the plots' 109).
const FIG7_SINGLE_Y: &str = "m_{max}(k)/m_{max}(1)";

/// Fig 7's x axes' lower end: k = 0.6, 0.4 of a step before the first k (7 units across two
/// columns, more than a marker's radius of 5; at 0.8 the markers still touched the axis).
pub(super) const FIG7_K_MIN: f64 = 0.6;

/// The width left of Fig 7's plots for their tick labels and the y axis' name, in units.
const FIG7_Y_LABEL_AREA: u32 = 70;

/// Fig 7's panels' lower limits: (a) 0.08 under its least value 0.095 (f/n = 10⁴, k = 10)
/// across two columns, 0.05 in one (room under that end for its label); (b) 4·10⁻⁴, under
/// its least 1.5·10⁻³ by room for a label clear of the x axis.
const FIG7_A_LOW: f64 = 0.08;
const FIG7_A_LOW_SINGLE: f64 = 0.05;
const FIG7_B_LOW: f64 = 4e-4;

/// Fig 7's one-column height, in units: 525 (420 pt printed, the one-column cap), its two
/// panels stacked, each plot about 110 units tall (it was 800 units, 640 pt: a whole column).
const FIG7_SINGLE_HEIGHT: u32 = 525;

#[cfg(test)]
mod tests {
    use super::*;

    /// Fig 4's ξ = 0 curve (n = 1 + √α) is g₀ = 1/√α on both planes, and ξ = 1 (n = 1) is z/α,
    /// both by hand from Eq 3.
    #[test]
    fn fig4_curves_by_hand() {
        let fig = fig4()
            .map_err(|e| e.named("lloyd2005-fig4"))
            .unwrap()
            .charts;
        let s = &fig.charts[0].series;
        let g0 = 1.0 / FIG4_ALPHA.sqrt();
        // The g₀ line first (its label placed first), then ξ = 1, ½, 0, −½, −1.
        assert!(s[0].reference);
        assert!((s[3].points[0].1 - g0).abs() < 1e-12);
        assert!((s[3].points.last().unwrap().1 - g0).abs() < 1e-12);
        for &(z, g) in &s[1].points {
            assert!((g - z / FIG4_ALPHA).abs() < 1e-12);
        }
    }

    /// Fig 7 by hand from Eq 7 with ξ = 0: m(k)/m(1) = k(α^{1/k} − 1)α^{1/2 − 1/(2k)}/(α − 1);
    /// at α = 100, k = 2: 2 · 9 · 10^{1/2}/99 = 0.5750.
    #[test]
    fn fig7_ratio_by_hand() {
        let fig = fig7()
            .map_err(|e| e.named("lloyd2005-fig7"))
            .unwrap()
            .charts;
        let alpha100 = &fig.charts[0].series[1].points;
        let want = 2.0 * 9.0 * 10f64.sqrt() / 99.0;
        assert!((alpha100[1].1 - want).abs() < 1e-12, "{}", alpha100[1].1);
        assert_eq!(alpha100[0].1, 1.0);
        // |ξ| = 1: m(k)/m(1) = k(α^{1/k} − 1)/(α − 1) by hand from Eq 7; at α = 100, k = 2:
        // 18/99, the 5.5× that matches the report's "nearly 5 times" (ξ = 0 gives 1.74×).
        let xi1 = &fig.charts[1].series[1].points;
        assert!((xi1[1].1 - 18.0 / 99.0).abs() < 1e-12, "{}", xi1[1].1);
        assert!(
            fig.charts.iter().all(|c| c.x.max <= 10.0),
            "no empty k > 10 area"
        );
        // Formulas keep their spaces unbroken (no-break spaces): "|ξ| =⏎1" broke a line.
        let caption = &fig.caption[0];
        assert!(caption.contains("5.5× at k\u{a0}=\u{a0}2"), "{caption}");
        assert!(caption.contains("gives 1.74×"), "{caption}");
        assert!(caption.contains("|ξ|\u{a0}=\u{a0}1"), "{caption}");
    }

    /// Fig 7 labels each line at its end, k = 10 (issue 35 item 9), and no label's white box
    /// covers a marker (figure review 2: the halos of the eight labels in one panel clipped
    /// the markers at k = 9), in both layouts. Read back from the SVG: each label's nearest
    /// line end (of the polylines of ten points, one a k) lies within 30 units right of the
    /// label's end and 30 units of its height, is a different line's for each label, and is
    /// the line the label names (a panel's lines, top to bottom, are α = 10 … 10⁴); and no
    /// label's text (its box less the pad) overlaps the bounding box of any marker polygon,
    /// the markers drawn after (over) the labels' halos.
    #[test]
    fn fig7_labels_sit_at_the_line_ends_clear_of_the_markers() {
        use super::super::chart::read_svg::{attr, draw_svg, visible};
        use super::super::chart::with_page;
        let fig = fig7().map_err(|e| e.named("lloyd2005-fig7")).unwrap();
        let points = |l: &str| crate::plot::chart::read_svg::points(l).unwrap();
        for (column, size) in [
            (Column::Double, fig.size()),
            (Column::Single, fig.single_size().unwrap()),
        ] {
            let svg = with_page(false, column, || {
                draw_svg(size, |area| fig.draw(area).unwrap())
            });
            let lines: Vec<&str> = svg.lines().collect();
            // The data lines: polylines of ten points (one a k), their ends.
            let ends: Vec<(f64, f64)> = lines
                .iter()
                .filter(|l| l.starts_with("<polyline"))
                .map(|l| points(l))
                .filter(|p| p.len() == 10)
                .map(|p| *p.last().unwrap())
                .collect();
            assert_eq!(ends.len(), 8, "{column:?}: {ends:?}");
            let markers: Vec<(f64, f64, f64, f64)> = lines
                .iter()
                .filter(|l| l.starts_with("<polygon"))
                .map(|l| {
                    let p = points(l);
                    let xs = p.iter().map(|q| q.0);
                    let ys = p.iter().map(|q| q.1);
                    (
                        xs.clone().fold(f64::INFINITY, f64::min),
                        ys.clone().fold(f64::INFINITY, f64::min),
                        xs.fold(f64::NEG_INFINITY, f64::max),
                        ys.fold(f64::NEG_INFINITY, f64::max),
                    )
                })
                .collect();
            assert!(markers.len() >= 80, "{column:?}: {} markers", markers.len());
            // Each label: its text's right end and its box (the white rect just before it).
            let mut labels = Vec::new();
            for (i, l) in lines.iter().enumerate() {
                if l.starts_with("<text") && visible(l).starts_with("f/n =") {
                    assert!(l.contains("text-anchor=\"end\""), "{l}");
                    let r = lines[i - 1];
                    assert!(r.starts_with("<rect"), "{r}");
                    let (x0, y0) = (attr(r, "x").unwrap(), attr(r, "y").unwrap());
                    let (w, h) = (attr(r, "width").unwrap(), attr(r, "height").unwrap());
                    labels.push((
                        visible(l),
                        attr(l, "x").unwrap(),
                        (x0, y0, x0 + w, y0 + h),
                        i,
                    ));
                }
            }
            assert_eq!(labels.len(), 8, "{column:?}");
            // No label's text (its box less the pad of 2) covers a marker, and every marker its
            // halo reaches is drawn (again) after the halo, over it.
            let polygons: Vec<(usize, &str)> = lines
                .iter()
                .enumerate()
                .filter(|(_, l)| l.starts_with("<polygon"))
                .map(|(i, l)| (i, *l))
                .collect();
            let apart = |b: (f64, f64, f64, f64), m: &(f64, f64, f64, f64)| {
                b.2 <= m.0 || m.2 <= b.0 || b.3 <= m.1 || m.3 <= b.1
            };
            for (t, _, b, at) in &labels {
                let text = (b.0 + 2.0, b.1 + 2.0, b.2 - 2.0, b.3 - 2.0);
                for (m, (_, poly)) in markers.iter().zip(&polygons) {
                    assert!(
                        apart(text, m),
                        "{column:?}: {t}'s text covers a marker {m:?}"
                    );
                    let over = polygons.iter().any(|(i, p)| i > at && p == poly);
                    assert!(
                        apart(*b, m) || over,
                        "{column:?}: {t}'s halo covers a marker {m:?} drawn under it"
                    );
                }
            }
            // Each label by its own line's end: the nearest end lies within 30 units (two
            // thirds of a k step) right of the text's end and 30 units of its box's centre height. A panel's lines, top to
            // bottom, are α = 10, 100, 1000, 10⁴ (Eq 7's ratio falls with α), the panels
            // side by side in two columns and stacked in one: so a line is the (rank mod 4)-th
            // α among the ends at its x, sorted by height.
            let names = ["f/n = 10", "f/n = 100", "f/n = 1000", "f/n = 104"];
            let mut taken = Vec::new();
            for (t, x, b, _) in &labels {
                let centre = 0.5 * (b.1 + b.3);
                let near = *ends
                    .iter()
                    .min_by(|p, q| {
                        let d = |e: &&(f64, f64)| (e.0 - x).hypot(e.1 - centre);
                        d(p).total_cmp(&d(q))
                    })
                    .unwrap();
                assert!(
                    near.0 >= *x && near.0 - x <= 30.0,
                    "{column:?}: {t} ends at {x}, its line at {}",
                    near.0
                );
                assert!(
                    (near.1 - centre).abs() <= 30.0,
                    "{column:?}: {t} at height {centre}, its line's end at {}",
                    near.1
                );
                let mut column_ends: Vec<f64> = ends
                    .iter()
                    .filter(|e| (e.0 - near.0).abs() < 1.0)
                    .map(|e| e.1)
                    .collect();
                column_ends.sort_by(f64::total_cmp);
                let rank = column_ends.iter().position(|&y| y == near.1).unwrap();
                assert_eq!(t.as_str(), names[rank % 4], "{column:?}");
                assert!(!taken.contains(&near), "{column:?}: two labels by one line");
                taken.push(near);
            }
        }
    }

    /// Fig 4's PSM curve is "n = 1" (ξ = 1 gives n = 1 exactly, Eq 4), not "n = 1.000".
    #[test]
    fn fig4_names_the_psm_curve_n_1() {
        let f4 = fig4()
            .map_err(|e| e.named("lloyd2005-fig4"))
            .unwrap()
            .charts;
        let labels: Vec<&str> = f4.charts[0]
            .series
            .iter()
            .filter_map(|s| s.label.as_deref())
            .collect();
        assert!(labels.contains(&"n′ = 1 (ξ = 1, PSM)"), "{labels:?}");
    }

    /// Fig 4's y axis is labelled every fifth, 0, 0.2, …, 1 (figure review 2: quarters wrote
    /// "1, 0.75, 0.5, 0.25, 0", two formats on one axis).
    #[test]
    fn fig4_y_ticks_are_fifths() {
        let fig = fig4().map_err(|e| e.named("lloyd2005-fig4")).unwrap();
        let y = &fig.charts.charts[0].y;
        let labels: Vec<String> = y.ticks().0.iter().map(|&a| y.tick_label(a)).collect();
        assert_eq!(labels, ["0", "0.2", "0.4", "0.6", "0.8", "1"]);
    }

    /// Fig 4's colours (issue 35, rule 4): the scheme colours for the schemes (ξ = 1 PSM dark blue
    /// #00306E, ξ = 0 LiSPSM green #00664B, ξ = −1 uniform vermillion #D55E00) and the sweep's
    /// darkest and lightest purples (#3F007D, #9589C0) for ξ = ½ and −½, which are no scheme
    /// (they were vermillion, ZP+W's colour, and pink), written here by hand.
    #[test]
    fn fig4_colours_are_schemes_and_a_sweep() {
        let fig = fig4().map_err(|e| e.named("lloyd2005-fig4")).unwrap();
        let hex: Vec<String> = fig.charts.charts[0]
            .series
            .iter()
            // The curves (the g₀ line is a grey reference).
            .filter(|s| s.label.is_some() && !s.reference)
            .map(|s| format!("#{:02X}{:02X}{:02X}", s.colour.0, s.colour.1, s.colour.2))
            .collect();
        assert_eq!(hex, ["#00306E", "#3F007D", "#00664B", "#9589C0", "#D55E00"]);
    }

    /// Fig 4 in one column keeps the two-column form's direct labels (the third figure review:
    /// its legend box below repeated them and made the figure 512 pt tall): read back from the
    /// SVG, each of the five curves' names once, right-aligned at its label's end and above
    /// the x axis' tick labels (inside the plot, not in a legend below it), with the g₀ line
    /// named too; and each caption at most five lines, as Fig 7's.
    #[test]
    fn fig4_one_column_labels_its_curves_directly_and_has_short_captions() {
        use super::super::chart::read_svg::{draw_svg, visible};
        use super::super::chart::with_page;
        let fig = fig4().map_err(|e| e.named("lloyd2005-fig4")).unwrap();
        let size = fig.single_size().unwrap();
        let svg = with_page(false, Column::Single, || {
            draw_svg(size, |area| fig.draw(area).unwrap())
        });
        let lines: Vec<&str> = svg.lines().filter(|l| l.starts_with("<text")).collect();
        let y_of = |l: &str| -> f64 {
            let at = l.find(" y=\"").unwrap() + 4;
            l[at..at + l[at..].find('"').unwrap()].parse().unwrap()
        };
        let ticks_y = lines
            .iter()
            .filter(|l| visible(l) == "10")
            .map(|l| y_of(l))
            .fold(f64::NEG_INFINITY, f64::max);
        let names: Vec<&&str> = lines
            .iter()
            .filter(|l| visible(l).starts_with("n′ = "))
            .collect();
        assert_eq!(names.len(), 5, "{names:?}");
        for l in &names {
            assert!(l.contains("text-anchor=\"end\""), "{l}");
            assert!(y_of(l) < ticks_y, "{l} below the ticks at {ticks_y}");
        }
        assert!(
            lines
                .iter()
                .any(|l| visible(l).replace('_', "").starts_with("g0 = 1/√(f/n)")),
            "no label on the g₀ line"
        );
        for (name, f) in [
            ("fig4", fig),
            (
                "fig7",
                fig7().map_err(|e| e.named("lloyd2005-fig7")).unwrap(),
            ),
        ] {
            let size = f.single_size().unwrap();
            let svg = with_page(false, Column::Single, || {
                draw_svg(size, |area| f.draw(area).unwrap())
            });
            let lines = svg.matches("fill=\"#323232\"").count();
            assert!((1..=5).contains(&lines), "{name}: {lines} caption lines");
        }
    }
}

#[cfg(test)]
#[path = "lloyd2005_review_tests.rs"]
mod review_tests;
