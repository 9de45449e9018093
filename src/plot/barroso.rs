//! Barroso & Celes 2007 Fig 7: the generalised LiSPSM parameter n′ against the angle γ between
//! the light and view directions (n = 1, f = 100, half field of view θ = 30°, the paper's φ_y,
//! written θ as in the Lloyd figures), with both fall-offs r(γ), the branches of their Eq 13,
//! LiSPSM's 1/sin γ rule and the crate's n′ that minimises M_z over the whole frustum (`WarpRule::MinimaxMz`, the frustum-wide version of Barroso's objective).

use super::chart::{
    column, draw_line_chart_over, fmt_power, frame, legend_below, linspace, Axis, Charts,
    LineChart, Look, Marker, Note, Series, PALETTE, SHARED,
};
use super::{Column, Fail, Figure};
use crate::analytic::tilted::{gamma_lim, generalized_n_prime, n_prime_1, n_prime_2, Falloff};
use crate::maps::{n_prime_for, WarpRule};
use crate::{LightAngle, NPrime, ViewFrustum};
use glam::DVec3;
use plotters::coord::Shift;
use plotters::prelude::*;

/// The light travelling at angle γ to the view direction, above and in front of the viewer.
fn light_at(gamma: f64) -> DVec3 {
    DVec3::new(0.0, -gamma.sin(), gamma.cos())
}

/// The window (b) enlarges, γ in degrees: where the curves separate, with room right of
/// γ_lim for its label.
const WINDOW: (f64, f64) = (20.0, 45.0);
/// (b)'s n′ range: Eq 13's n′₂ falls to 0 at 27.69°; the largest n′ in the window is
/// LiSPSM's 11/sin 20° = 32.2.
const WINDOW_N: (f64, f64) = (0.3, 100.0);

/// Where (a)'s note on the curves clipped at its top starts (γ in degrees, n′): right of where
/// they leave the frame (γ < 5°), in the top decade, which no curve crosses right of 10°.
const CLIPPED_NOTE: (f64, f64) = (7.0, 5000.0);

/// The key's labels, the same in both layouts, short enough for two columns of entries under
/// the one-column page: the six curves, then (b)'s two angle lines (the sixth review,
/// R6-barroso-fig7-4: their labels in (b) pressed against lines 0.5° apart; named in the key).
/// The lines' labels are written with their values in [`magnified`].
const LABELS: [&str; 6] = [
    "Eq 18 (Barroso)",
    "Eq 17 (Zhang's r)",
    "LiSPSM",
    "n′ of least max m_{z}",
    "n′_{1}, Eq 13",
    "n′_{2}, Eq 13",
];

/// The figure's title, in both layouts (the sixth review, R6-X-5: one title).
const TITLE: &str = "Generalised LiSPSM n′ against γ";

/// Barroso & Celes' Fig 7: panels (a) and (b) with one legend, and the caption for each page
/// width.
pub(super) struct Fig7 {
    pub charts: Charts,
    single_caption: String,
}

pub(super) fn fig7() -> Result<Fig7, Fail> {
    let (n, f) = (1.0, 100.0);
    let view = ViewFrustum::new(n, f, 30f64.to_radians())?;
    // In degrees, as every figure gives its angles (figure review 3, X2: "π/6" here only).
    let phi_deg = view.half_fov().to_degrees();
    let gl = gamma_lim(&view);
    let degrees = linspace(0.0, 90.0, 361);
    let finite = |n: NPrime| n.as_finite();
    let mut barroso = Vec::new();
    let mut zhang = Vec::new();
    let mut lispsm = Vec::new();
    let mut minimax = Vec::new();
    let mut n1 = Vec::new();
    let mut n2 = Vec::new();
    for &d in &degrees {
        let g = d.to_radians();
        let angle = LightAngle::new(g)?;
        if let Some(v) = finite(generalized_n_prime(&view, angle, Falloff::Barroso)) {
            barroso.push((d, v));
        }
        if let Some(v) = finite(generalized_n_prime(&view, angle, Falloff::Zhang)) {
            zhang.push((d, v));
        }
        if let Some(v) = finite(n_prime_for(&view, light_at(g), WarpRule::Lispsm)?) {
            lispsm.push((d, v));
        }
        if let Some(v) = finite(n_prime_for(&view, light_at(g), WarpRule::MinimaxMz)?) {
            minimax.push((d, v));
        }
        // Eq 13's branches, each on its own domain (n′₁ for θ ≤ γ ≤ π/2, n′₂ for
        // 0 < γ < θ) and where it is positive (the plot is logarithmic).
        let (a, b) = (n_prime_1(&view, angle), n_prime_2(&view, angle)?);
        let phi = view.half_fov();
        n1.push((
            d,
            if g >= phi - 1e-12 && a > 0.0 {
                a
            } else {
                f64::NAN
            },
        ));
        n2.push((
            d,
            if g < phi - 1e-12 && b > 0.0 {
                b
            } else {
                f64::NAN
            },
        ));
    }
    let gamma = "light–view angle γ (°)";
    let n_axis = "n′ (log scale)";
    let mut c = LineChart::new(
        "(a) γ from 0° to 90°",
        // Ticks every 15° to 90° (the ninth review, R9-barroso-fig7-3: 0, 20 … 80 left 90°,
        // the axis' end and the light overhead, unlabelled; 30° is θ).
        Axis::every(gamma, 0.0, 90.0, 0.0, 15.0),
        Axis::log10(n_axis, 1.0, 1e4),
    );
    // The paper's curve, bold.
    let mut paper = Series::line(LABELS[0], barroso, Look::Barroso.colour());
    paper.width = 4;
    c.series.push(paper);
    c.series
        .push(Series::line(LABELS[1], zhang, Look::Zhang.colour()));
    c.series
        .push(Series::line(LABELS[2], lispsm, Look::Lispsm.colour()).dashed());
    // Dotted, not dashed: in greyscale its colour is LiSPSM's grey, and the two meet.
    // The n′ that minimises the largest m_z over the frustum (the sixth review,
    // R6-barroso-fig7-1: "least M_z" did not say which m_z is least).
    let mut least = Series::line(LABELS[3], minimax, PALETTE[3]).dotted();
    least.width = 3;
    c.series.push(least);
    // n′₁ with a small square (its colour's own marker, a tall bar, read as part of the line);
    // above γ_lim it is Barroso's curve (its fall-off is 1 there), drawn over it (the caption
    // says so).
    c.series.push(Series {
        shape: Some(Marker::Square),
        ..Series::line(LABELS[4], n1, PALETTE[6]).dotted()
    });
    // Dashed: olive prints as least M_z's (pink, dotted) grey and meets it at γ ≈ 28° (figure
    // review 5, X6); LiSPSM's dashes run an order of magnitude above it there.
    let mut s2 = Series::line(LABELS[5], n2, PALETTE[7]).dashed();
    s2.width = 3;
    c.series.push(s2);
    // (a) has no angle lines: θ = 30° and γ_lim = 30.5° lie under a point apart there and
    // read as one line; (b) draws them apart. Its key is (b)'s, below the panels.
    c.show_legend = false;
    // Three curves run off the top of (a) as γ → 0 (each n′ → ∞ there): the note says so, its
    // arrow towards them (figure review 3: a marker sat on the frame, nothing said they go on).
    c.notes.push(Note {
        at: (CLIPPED_NOTE.0, CLIPPED_NOTE.1),
        text: format!("← clipped at {}", fmt_power(c.y.max)),
        colour: RGBColor(90, 90, 90),
    });
    // A marker at the top of the range (Barroso's curve at γ ≈ 4°, n′ ≈ 9·10³) is cut at the
    // frame, not drawn across it (figure review 5).
    c.clip_markers = true;
    let zoom = magnified(&c, gl.to_degrees(), view.half_fov().to_degrees());
    let charts = Charts {
        size: (520, 540),
        title: TITLE.into(),
        caption: vec![format!(
            "Barroso & Celes 2007, Fig. 7 (Eq 13–18), n\u{a0}=\u{a0}{n}, f\u{a0}=\u{a0}{f}, \
             half field of view θ\u{a0}=\u{a0}{phi_deg:.0}°. n′_{{1}}, n′_{{2}}: Eq\u{a0}13's n′ for \
             γ\u{a0}≥\u{a0}θ, γ\u{a0}<\u{a0}θ; below γ_{{lim}} (Eq\u{a0}15) \
             n′\u{a0}=\u{a0}n′_{{1}}(γ_{{lim}})/r(γ), r: Eq\u{a0}18 (bold) \
             or Zhang's Eq\u{a0}17; n′_{{1}} is Eq\u{a0}18's curve above γ_{{lim}}. \
             LiSPSM's n′\u{a0}=\u{a0}(n\u{a0}+\u{a0}√(fn))/sin\u{a0}γ and the n′ of \
             least max m_z over the whole frustum, not only \
             along the view axis as n′_{{1}} (Eq\u{a0}12). (b): γ {}°–{}°, \
             n′ turns near γ\u{a0}=\u{a0}θ.",
            WINDOW.0, WINDOW.1
        )],
        charts: vec![c, zoom],
    };
    // One column: the paper's figure, (a), alone and unlettered (the sixth review,
    // R6-barroso-fig7-2: (a)'s four decades in 70 pt merged five curves, and the page's 420 pt
    // leave no room for both panels at 110 pt; the eighth, R8-barroso-fig7-1: drawing (b) alone
    // dropped the paper's own panel and left an orphan letter); its caption describes only what
    // it draws (the eleventh, R11-barroso-fig7-1, R11-X-3: no "(b) … left out"), and gives
    // γ_lim's value, which two columns key in (b); every symbol the key and the caption use
    // defined (figure review 5, X7).
    let single_caption = format!(
        "Barroso & Celes 2007, Fig. 7: f/n\u{a0}=\u{a0}{f}, half field of view \
         θ\u{a0}=\u{a0}{phi_deg:.0}°. \
         n′_{{1}}, n′_{{2}}: Eq\u{a0}13 for γ\u{a0}≥\u{a0}θ, γ\u{a0}<\u{a0}θ; below \
         γ_{{lim}}\u{a0}=\u{a0}{:.1}° (Eq\u{a0}15), n′_{{1}}(γ_{{lim}})/r(γ), r as \
         keyed. Least max m_z: whole frustum; LiSPSM: \
         n′\u{a0}=\u{a0}(n\u{a0}+\u{a0}√(fn))/sin\u{a0}γ.",
        gl.to_degrees()
    );
    Ok(Fig7 {
        charts,
        single_caption,
    })
}

/// Where (b)'s name of the two angle lines starts: degrees right of the right line, and n′
/// (the top of the window, [`WINDOW_N`], is 100).
const ANGLES_NOTE: (f64, f64) = (0.6, 90.0);

/// `c` magnified to γ in [`WINDOW`] and n′ in [`WINDOW_N`], where the curves separate (issue
/// 25): the same series, each cut to the window (so that its markers fall inside it), the
/// figure's one legend, and the two angles as vertical lines named in it.
fn magnified(c: &LineChart, gl_deg: f64, phi_deg: f64) -> LineChart {
    let (x, y) = (WINDOW, WINDOW_N);
    let mut z = LineChart::new(
        format!("(b) γ from {:.0}° to {:.0}°", x.0, x.1),
        Axis::linear(c.x.label.clone(), x.0, x.1),
        // n′ in (a)'s format (powers of ten there), not plain numbers for this range.
        if c.y.writes_plain() {
            Axis::log10(c.y.label.clone(), y.0, y.1)
        } else {
            Axis::log10(c.y.label.clone(), y.0, y.1).in_powers()
        },
    );
    z.series = c
        .series
        .iter()
        .map(|s| {
            let mut s = s.clone();
            s.points.retain(|p| p.0 >= x.0 && p.0 <= x.1);
            s
        })
        .collect();
    // The two angles as lines named in the key (the sixth review, R6-barroso-fig7-4: labels
    // in the plot pressed against lines 0.5° apart).
    for (at, colour, dashed, label) in [
        (phi_deg, SHARED, false, format!("θ = {phi_deg:.0}°")),
        (
            gl_deg,
            PALETTE[6],
            true,
            format!("γ_{{lim}} = {gl_deg:.1}°"),
        ),
    ] {
        let line = Series::line(label, vec![(at, y.0), (at, y.1)], colour);
        let mut line = if dashed { line.dashed() } else { line.dotted() };
        line.width = 1;
        line.reference = true;
        z.series.push(line);
    }
    // One name for the pair at their top, right of the right one (R7-B7-1: 0.5° apart, two
    // units on the page, they read as one line; the key tells them apart).
    z.notes.push(Note {
        at: (gl_deg.max(phi_deg) + ANGLES_NOTE.0, ANGLES_NOTE.1),
        text: "θ, γ_{lim}".to_string(),
        colour: RGBColor(90, 90, 90),
    });
    // The figure's one key, under both panels.
    z.legend_below = true;
    z
}

impl Figure for Fig7 {
    fn size(&self) -> (u32, u32) {
        self.charts.size
    }

    /// One column: (a) alone, its key under it: 525 units, 420 pt printed.
    fn single_size(&self) -> Option<(u32, u32)> {
        Some((Column::Single.width(), 525))
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        if column() == Column::Double {
            return self.charts.draw(root);
        }
        // One column: (a) alone, the paper's figure, without its letter, its key (its curves';
        // (b)'s angle lines are not in it) in a strip as wide as the page (two columns of
        // entries) under it.
        let body = frame(root, TITLE, &[self.single_caption.as_str()])?;
        let (w, h) = body.dim_in_pixel();
        let mut a = self.charts.charts[0].clone();
        a.title = a.title.trim_start_matches("(a) ").to_string();
        a.show_legend = true;
        a.legend_below = true;
        let strip_h = legend_below((w, h / 2), &a, f64::from(w))?;
        let (plot, strip) = body.split_vertically(h.saturating_sub(strip_h));
        draw_line_chart_over(&plot, &a, Some(&strip))?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// With the light overhead (γ = 90°) every rule is LiSPSM's n + √(fn) = 1 + 10 = 11; both
    /// fall-offs meet n′₁(γ_lim) at γ_lim; at γ = 0 no finite n′ is plotted.
    #[test]
    fn fig7_curves_meet_lispsm_overhead() {
        let fig = fig7().map_err(|e| e.named("barroso-fig7")).unwrap();
        let s = &fig.charts.charts[0].series;
        for curve in &s[..4] {
            let (d, v) = *curve.points.last().unwrap();
            assert_eq!(d, 90.0);
            assert!((v - 11.0).abs() < 1e-6, "{v}");
        }
        assert!(s[0].points[0].0 > 0.0 && s[1].points[0].0 > 0.0);
    }

    /// The n′ of least max m_z is defined in both captions as taken over the whole frustum
    /// (the tenth review, R10-barroso-fig7-1: "over the frustum" left it undefined, and as
    /// drawn it lies above Eq 13's n′₁, which minimises m_z along the view axis only); and
    /// so it does: above γ_lim it is at least n′₁ everywhere, 1.5 × at 45° (the review read
    /// 11.4 against 7.37 off the SVG).
    #[test]
    fn least_max_m_z_is_over_the_whole_frustum_and_lies_above_n1() {
        let fig = fig7().map_err(|e| e.named("barroso-fig7")).unwrap();
        assert!(
            fig.charts.caption[0].contains("over the whole frustum, not only along the view axis"),
            "{}",
            fig.charts.caption[0]
        );
        assert!(
            fig.single_caption.contains("Least max m_z: whole frustum"),
            "{}",
            fig.single_caption
        );
        // LiSPSM's curve is defined in both captions (the thirteenth review, R13-barroso-fig7-1).
        for c in [&fig.charts.caption[0], &fig.single_caption] {
            assert!(
                c.contains("LiSPSM")
                    && c.contains("n′\u{a0}=\u{a0}(n\u{a0}+\u{a0}√(fn))/sin\u{a0}γ"),
                "{c}"
            );
        }
        let s = &fig.charts.charts[0].series;
        let (least, n1) = (&s[3], &s[4]);
        assert_eq!(least.label.as_deref(), Some(LABELS[3]));
        assert_eq!(n1.label.as_deref(), Some(LABELS[4]));
        let at = |c: &Series, g: f64| {
            c.points
                .iter()
                .find(|p| (p.0 - g).abs() < 1e-9)
                .map(|p| p.1)
        };
        let mut compared = 0;
        // n′₁'s drawn points (its gaps, γ < θ, are NaN).
        for p in n1.points.iter().filter(|p| p.1.is_finite()) {
            if let Some(v) = at(least, p.0) {
                assert!(v >= p.1 - 1e-6, "γ = {}: {v} under n′₁ = {}", p.0, p.1);
                compared += 1;
            }
        }
        assert!(compared >= 10, "{compared} angles compared");
        let (l45, n45) = (at(least, 45.0).unwrap(), at(n1, 45.0).unwrap());
        assert!(l45 > 1.4 * n45, "{l45} against {n45}");
    }

    /// Eq 13's branches are drawn only on their domains: n′₁ for θ = 30° ≤ γ, n′₂ for γ < 30°
    /// and, being positive only above atan(b/(f + √(fn))) = atan(57.735/110) = 27.69° (by
    /// hand), only between 27.69° and 30°.
    #[test]
    fn eq13_branches_only_on_their_domains() {
        let fig = fig7().map_err(|e| e.named("barroso-fig7")).unwrap();
        let s = &fig.charts.charts[0].series;
        let finite = |k: usize| -> Vec<f64> {
            s[k].points
                .iter()
                .filter(|p| p.1.is_finite())
                .map(|p| p.0)
                .collect()
        };
        let n1 = finite(4);
        let n2 = finite(5);
        assert!(n1.iter().all(|&d| d >= 30.0 - 1e-9) && n1.first() == Some(&30.0));
        let start = (100.0 * 3f64.sqrt() / 3.0 / 110.0).atan().to_degrees();
        assert!((start - 27.69).abs() < 0.01);
        assert!(!n2.is_empty());
        assert!(n2.iter().all(|&d| d > start && d < 30.0), "{n2:?}");
    }

    /// The paper's curve (Barroso's fall-off, Eq 16 with Eq 18) is the bold one (issue 25); (a)
    /// draws no angle lines (review: 0.5° apart they fused into one dash-dot line there), (b)
    /// draws θ = 30° and γ_lim (Eq 15, 30.5°) as lines named in the key, with no label of its
    /// own in the plot.
    #[test]
    fn the_papers_curve_is_bold_and_the_angle_lines_are_in_the_key() {
        let fig = fig7().map_err(|e| e.named("barroso-fig7")).unwrap();
        let (a, b) = (&fig.charts.charts[0], &fig.charts.charts[1]);
        let bold = &a.series[0];
        assert!(bold.label.as_deref().unwrap().ends_with("(Barroso)"));
        assert!(a.series[1..].iter().all(|s| s.width < bold.width));
        // (a)'s one note is on the curves clipped at its top, not an angle's; (b)'s one note
        // names its two angle lines together (R7-B7-1).
        assert_eq!(a.notes.len(), 1, "{:?}", a.notes);
        assert!(a.notes[0].text.contains("clipped"), "{:?}", a.notes);
        assert_eq!(b.notes.len(), 1, "{:?}", b.notes);
        assert_eq!(b.notes[0].text, "θ, γ_{lim}");
        // (a)'s series are its six curves; no vertical line (two points at one γ).
        assert_eq!(a.series.len(), 6);
        assert!(a.series.iter().all(|s| s.points.len() > 2));
        let verticals: Vec<(f64, String)> = b
            .series
            .iter()
            .filter(|s| s.points.len() == 2 && s.points[0].0 == s.points[1].0)
            .map(|s| (s.points[0].0, s.label.clone().unwrap()))
            .collect();
        assert_eq!(verticals.len(), 2, "{verticals:?}");
        // γ_lim (Eq 15, `analytic::tilted`'s value, printed 30.5°) and θ = 30°.
        let view = ViewFrustum::new(1.0, 100.0, std::f64::consts::FRAC_PI_6).unwrap();
        let gl = gamma_lim(&view).to_degrees();
        assert!((gl - 30.5).abs() < 0.05 + 1e-9, "{gl}");
        assert!((verticals[0].0 - 30.0).abs() < 1e-9, "{verticals:?}");
        assert_eq!(verticals[0].1, "θ = 30°");
        assert!((verticals[1].0 - gl).abs() < 1e-9, "{verticals:?}");
        assert_eq!(verticals[1].1, "γ_{lim} = 30.5°");
    }

    /// The sixth review: R6-barroso-fig7-1 ("least M_z" did not say which m_z), -2 (one column
    /// fitted (a)'s four decades into 70 pt) and -4 (θ's and γ_lim's labels pressed against
    /// lines 0.5° apart). Read from the drawn SVGs: in both layouts the key names "n′ of least
    /// max m_z", "θ = 30°" and "γ_lim = 30.5°", and no text points at a line with an arrow but
    /// (a)'s note on its clipped curves; one column draws (b) alone, its plot (the y axis line)
    /// at least 110 pt tall (137.5 units at 0.8 pt a unit), under the same title as two columns,
    /// and its caption names no panel it does not draw (R11-barroso-fig7-1).
    #[test]
    fn key_names_least_max_m_z_and_the_angles_and_one_column_is_a_alone() {
        use super::super::chart::read_svg::{points, texts};
        use super::super::hemisphere::svg_in;
        let fig = fig7().map_err(|e| e.named("barroso-fig7")).unwrap();
        for column in [Column::Double, Column::Single] {
            let svg = svg_in(&fig, column);
            let all: Vec<String> = texts(&svg).into_iter().map(|t| t.1).collect();
            // (b)'s angle lines are keyed where (b) is drawn, two columns.
            let angles: &[&str] = if column == Column::Double {
                &["θ = 30°", "γlim = 30.5°"]
            } else {
                &[]
            };
            for want in ["n′ of least max mz", TITLE].iter().chain(angles) {
                assert!(
                    all.iter().any(|t| t == want),
                    "{column:?}: no {want:?} in {all:?}"
                );
            }
            assert!(!all.iter().any(|t| t.contains("least M")), "{column:?}");
            let arrows: Vec<&String> = all
                .iter()
                .filter(|t| t.contains('→') || t.contains('←'))
                .collect();
            // (a)'s note on its clipped curves, in both layouts.
            assert_eq!(arrows.len(), 1, "{column:?}: {arrows:?}");
            let spines: Vec<f64> = svg
                .lines()
                .filter(|l| l.starts_with("<polyline") && l.contains("stroke=\"#000000\""))
                .filter_map(points)
                .filter(|p| p.len() == 2 && p[0].0 == p[1].0)
                .map(|p| (p[0].1 - p[1].1).abs())
                .filter(|&h| h > 40.0)
                .collect();
            if column == Column::Single {
                assert_eq!(spines.len(), 1, "{spines:?}");
                assert!(spines[0] * 0.8 >= 110.0, "{spines:?}");
                // (a), the paper's figure, without an orphan letter (R8-barroso-fig7-1).
                assert!(
                    !all.iter()
                        .any(|t| t.starts_with("(a)") || t.starts_with("(b)")),
                    "{all:?}"
                );
                assert!(all.iter().any(|t| t == "γ from 0° to 90°"), "{all:?}");
                // The caption describes only what one column draws (R11-barroso-fig7-1), and
                // gives γ_lim, by hand arctan((a + b)/(f − n)) = 30.499° (R11's Python).
                let caption = all.join(" ");
                assert!(!caption.contains("(b)"), "{caption}");
                assert!(!caption.contains("left out"), "{caption}");
                assert!(
                    caption.contains("γlim\u{a0}=\u{a0}30.5° (Eq\u{a0}15),"),
                    "{caption}"
                );
            } else {
                assert_eq!(spines.len(), 2, "{spines:?}");
            }
        }
    }

    /// (a)'s note on its clipped curves (figure review 3): two curves, Barroso's and least M_z's,
    /// leave the frame at its top, n′ = 10⁴, as γ → 0 (LiSPSM's n′ = 11/sin γ passes 10⁴ only
    /// below 11/10⁴ rad = 0.063°, by hand, left of its first sample at 0.25°), and the note
    /// stands right of where they leave (every curve below 10⁴ from the note's γ on), in the top
    /// decade, naming the frame's value.
    #[test]
    fn panel_a_says_its_curves_are_clipped() {
        let fig = fig7().map_err(|e| e.named("barroso-fig7")).unwrap();
        let a = &fig.charts.charts[0];
        let note = &a.notes[0];
        assert_eq!(note.text, "← clipped at 10⁴");
        let over: Vec<&str> = a
            .series
            .iter()
            .filter(|s| s.points.iter().any(|p| p.1 > 1e4))
            .map(|s| s.label.as_deref().unwrap())
            .collect();
        assert_eq!(over, [LABELS[0], LABELS[3]]);
        assert!(note.at.1 > 1e3 && note.at.1 < 1e4);
        for s in &a.series {
            for p in s
                .points
                .iter()
                .filter(|p| p.0 >= note.at.0 && p.1.is_finite())
            {
                assert!(p.1 < 1e4, "{:?} at {p:?}", s.label);
            }
        }
        // LiSPSM by hand: 11/sin(0.25°) = 2521 < 10⁴, and its first plotted γ is 0.25°.
        let lispsm = &a.series[2].points;
        assert!((lispsm[0].1 - 11.0 / 0.25f64.to_radians().sin()).abs() < 1e-6);
    }

    /// Degrees everywhere (figure review 3, X2): both captions give the half field of view θ
    /// (the paper's φ_y, written θ as in the Lloyd figures: the fourth review) as "30°", none
    /// "π/6".
    #[test]
    fn captions_give_phi_in_degrees() {
        let fig = fig7().map_err(|e| e.named("barroso-fig7")).unwrap();
        for c in [&fig.charts.caption[0], &fig.single_caption] {
            assert!(c.contains("θ\u{a0}=\u{a0}30°"), "{c}");
            assert!(!c.contains('φ'), "{c}");
            assert!(!c.contains("π"), "{c}");
        }
    }

    /// In greyscale LiSPSM (green) and least M_z (reddish purple) are one grey (review), so
    /// they differ in dash: LiSPSM dashed, least M_z dotted, and so do n′₂ and least M_z
    /// (figure review 5); and the caption says n′₁ is Barroso's curve (Eq 18) above γ_lim,
    /// where it is drawn over it.
    #[test]
    fn lispsm_and_least_mz_differ_in_dash() {
        use super::super::chart::Dash;
        let fig = fig7().map_err(|e| e.named("barroso-fig7")).unwrap();
        let s = &fig.charts.charts[0].series;
        let by = |l: &str| {
            s.iter()
                .find(|x| x.label.as_deref().unwrap_or("").starts_with(l))
        };
        assert_eq!(by("LiSPSM").unwrap().dash, Dash::Dashed);
        assert_eq!(by("n′ of least").unwrap().dash, Dash::Dotted);
        // Figure review 5, X6: n′₂ (olive, L* 60) and least M_z (pink, L* 61) print as one grey
        // and meet at γ ≈ 28°: they differ in dash.
        assert_ne!(by("n′_{2}").unwrap().dash, by("n′ of least").unwrap().dash);
        assert!(fig.charts.caption[0].contains("n′_{1} is Eq\u{a0}18's curve above γ_{lim}"));
    }

    /// The fall-offs' key entries name the equations by this paper's numbers (the fourth
    /// review: "Zhang, Eq 17" read as Zhang's own Eq 17, where Eq 17 is Barroso and Celes'
    /// equation quoting Zhang et al.'s function): each entry starts with its equation, then
    /// whose r(γ) it is, in both forms; and the curves are those equations. Below γ_lim both
    /// are n′₁(γ_lim)/r(γ) (Eq 16), so their ratio is the fall-offs' inverse ratio, by hand
    /// from Eq 17, r = sin(u π/2), and Eq 18, r = (1 + sin((u − 1) π/2))², u = γ/γ_lim: at
    /// γ = 15°, Zhang's n′ over Barroso's is r₁₈/r₁₇.
    #[test]
    fn fall_offs_are_named_by_the_papers_equations() {
        let fig = fig7().map_err(|e| e.named("barroso-fig7")).unwrap();
        let a = &fig.charts.charts[0];
        let label = |i: usize| a.series[i].label.clone().unwrap();
        assert!(label(0).starts_with("Eq 18 (Barroso"), "{}", label(0));
        assert!(label(1).starts_with("Eq 17 (Zhang's"), "{}", label(1));
        for s in a.series.iter().chain(&fig.charts.charts[1].series) {
            let l = s.label.as_deref().unwrap_or("");
            assert!(!l.contains("Zhang, Eq"), "{l}");
        }
        let at = |i: usize| {
            a.series[i]
                .points
                .iter()
                .find(|p| (p.0 - 15.0).abs() < 1e-9)
                .unwrap()
                .1
        };
        let view = ViewFrustum::new(1.0, 100.0, std::f64::consts::FRAC_PI_6).unwrap();
        let u = 15f64.to_radians() / gamma_lim(&view);
        let half_pi = std::f64::consts::FRAC_PI_2;
        let r17 = (u * half_pi).sin();
        let r18 = (1.0 + ((u - 1.0) * half_pi).sin()).powi(2);
        let (zhang, barroso) = (at(1), at(0));
        assert!(
            (zhang / barroso - r18 / r17).abs() < 1e-9,
            "{zhang} / {barroso} against {}",
            r18 / r17
        );
    }

    /// Issue 25: a second panel magnifies γ from 20° to 45°, where the curves separate: every
    /// curve of (a) is there, cut to the window (the four rules sampled every 0.25°: 101
    /// points each), and the four rules lie within n′ ∈ [1, 100] (the axis reaches down to 0.3
    /// for Eq 13's n′₂, which falls to 0 at 27.69°, by hand in
    /// `eq13_branches_only_on_their_domains`, and up to 100, above every curve).
    #[test]
    fn panel_b_magnifies_20_to_45_degrees() {
        let fig = fig7().map_err(|e| e.named("barroso-fig7")).unwrap();
        assert_eq!(fig.charts.charts.len(), 2);
        let (a, b) = (&fig.charts.charts[0], &fig.charts.charts[1]);
        assert_eq!((b.x.min, b.x.max), (20.0, 45.0));
        assert_eq!((b.y.min, b.y.max), (0.3, 100.0));
        assert_eq!(a.series.len() + 2, b.series.len());
        for s in &b.series[..4] {
            assert_eq!(s.points.len(), 101, "{:?}", s.label);
            assert!(s.points.iter().all(|p| (20.0..=45.0).contains(&p.0)));
            assert!(
                s.points.iter().all(|p| (1.0..=100.0).contains(&p.1)),
                "{:?}",
                s.points
            );
        }
        // Where they separate: at γ = 25° LiSPSM's n′ is (n + √(fn))/sin γ = 11/sin 25° = 26.03
        // (by hand), more than three times Zhang's.
        let at = |k: usize, g: f64| b.series[k].points.iter().find(|p| p.0 == g).unwrap().1;
        assert!((at(2, 25.0) - 26.028).abs() < 1e-3, "{}", at(2, 25.0));
        assert!(at(2, 25.0) > 3.0 * at(1, 25.0), "{}", at(1, 25.0));
        // (a)'s γ axis is labelled at its end, 90° (overhead), and at θ = 30° (the ninth
        // review, R9-barroso-fig7-3: 0, 20 … 80 left 90° unlabelled).
        let labels: Vec<String> = a.x.ticks().0.iter().map(|&t| a.x.tick_label(t)).collect();
        assert_eq!(labels, ["0", "15", "30", "45", "60", "75", "90"]);
    }

    /// R7-B7-1, read from the SVG in both layouts: (b)'s θ = 30° and γ_lim = 30.5° lines, two
    /// units apart, are named once at their top: the text "θ, γ" with the subscript "lim"
    /// starts right of the right one (γ_lim's dashed vertical) and within 12 units of it, and
    /// stands in the top fifth of the plots' height.
    #[test]
    fn the_angle_lines_are_named_once_at_their_top() {
        use super::super::chart::read_svg::{attr, points, texts};
        use super::super::hemisphere::svg_in;
        let fig = fig7().map_err(|e| e.named("barroso-fig7")).unwrap();
        // One column draws (a) alone, without the angle lines (R8-barroso-fig7-1).
        {
            let column = Column::Double;
            let svg = svg_in(&fig, column);
            // Vertical pieces: the long ones (spines, grid lines) span the plots' height; the
            // short ones near the name are the angle lines' dashes and dots.
            let verticals: Vec<Vec<(f64, f64)>> = svg
                .lines()
                .filter(|l| l.starts_with("<polyline"))
                .filter_map(points)
                .filter(|p| p.len() == 2 && p[0].0 == p[1].0)
                .collect();
            let long = verticals.iter().filter(|p| (p[0].1 - p[1].1).abs() > 100.0);
            let top = long
                .clone()
                .map(|p| p[0].1.min(p[1].1))
                .fold(f64::INFINITY, f64::min);
            let bottom = long.map(|p| p[0].1.max(p[1].1)).fold(0.0, f64::max);
            let all = texts(&svg);
            let note = all
                .iter()
                .find(|t| t.1 == "θ, γlim")
                .unwrap_or_else(|| panic!("{column:?}: no \"θ, γ_lim\" in (b)"));
            let x = attr(note.0, "x").unwrap();
            // The right angle line (γ_lim's dashes): the rightmost short vertical piece near it
            // in the plots' upper half (the x ticks are short vertical pieces at the bottom).
            let mid = 0.5 * (top + bottom);
            let gl = verticals
                .iter()
                .filter(|p| (p[0].1 - p[1].1).abs() < 100.0 && (x - p[0].0).abs() < 40.0)
                .filter(|p| p[0].1.max(p[1].1) < mid)
                .map(|p| p[0].0)
                .fold(f64::NEG_INFINITY, f64::max);
            assert!(
                x > gl && x - gl <= 12.0,
                "{column:?}: the name starts at {x}, the γ_lim line at {gl}"
            );
            assert!(
                note.2 - top <= 0.2 * (bottom - top),
                "{column:?}: the name at y {} in a plot from {top} to {bottom}",
                note.2
            );
        }
    }
}
