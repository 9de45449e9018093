//! Barroso & Celes 2007 Fig 7: the generalised LiSPSM parameter n′ against the angle γ between
//! the light and view directions (n = 1, f = 100, φ_y = π/6), with both fall-offs r(γ), the
//! branches of their Eq 13, LiSPSM's 1/sin γ rule and the crate's n′ that minimises M_z over the
//! whole frustum (`WarpRule::MinimaxMz`, the frustum-wide version of Barroso's objective).

use super::chart::{linspace, Axis, Charts, LineChart, Look, Marker, Note, Series, PALETTE};
use super::Fail;
use crate::analytic::tilted::{gamma_lim, generalized_n_prime, n_prime_1, n_prime_2, Falloff};
use crate::maps::{n_prime_for, WarpRule};
use crate::{LightAngle, NPrime, ViewFrustum};
use glam::DVec3;
use plotters::prelude::{RGBColor, SeriesLabelPosition};

/// The light travelling at angle γ to the view direction, above and in front of the viewer.
fn light_at(gamma: f64) -> DVec3 {
    DVec3::new(0.0, -gamma.sin(), gamma.cos())
}

pub(super) fn fig7() -> Result<Charts, Fail> {
    let (n, f) = (1.0, 100.0);
    let view = ViewFrustum::new(n, f, std::f64::consts::FRAC_PI_6)?;
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
        // Eq 13's branches, each on its own domain (n′₁ for φ_y ≤ γ ≤ π/2, n′₂ for
        // 0 < γ < φ_y) and where it is positive (the plot is logarithmic).
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
    let mut c = LineChart::new(
        "",
        Axis::linear("light–view angle γ (degrees)", 0.0, 90.0),
        Axis::log10("warp parameter n′ (n = 1)", 1.0, 1e4),
    );
    // Short legend labels, so that the legend fits above the curves' common tail (γ > 35°).
    c.legend = SeriesLabelPosition::UpperRight;
    // The paper's curve, bold.
    let mut paper = Series::line("Barroso, Eq 18 (paper)", barroso, Look::Barroso.colour());
    paper.width = 4;
    c.series.push(paper);
    c.series
        .push(Series::line("Zhang, Eq 17", zhang, Look::Zhang.colour()));
    c.series
        .push(Series::line("LiSPSM, 1/sin γ", lispsm, Look::Lispsm.colour()).dashed());
    c.series
        .push(Series::line("least M_z", minimax, PALETTE[3]).dashed());
    // n′₁ with a small square (its colour's own marker, a tall bar, read as part of the line).
    c.series.push(Series {
        shape: Some(Marker::Square),
        ..Series::line("n′_{1}, Eq 13", n1, PALETTE[6]).dotted()
    });
    let mut s2 = Series::line("n′_{2}, Eq 13", n2, PALETTE[7]).dotted();
    s2.width = 3;
    c.series.push(s2);
    let gl_deg = gl.to_degrees();
    let phi_deg = view.half_fov().to_degrees();
    // The two angles, 0.5° apart: γ_lim dashed with its label to the right, φ_y dotted with its
    // label to the left.
    let grey = RGBColor(110, 110, 110);
    let mut gl_line = Series::line(
        String::new(),
        vec![(gl_deg, 1.0), (gl_deg, 1e4)],
        PALETTE[6],
    )
    .dashed();
    gl_line.label = None;
    gl_line.width = 1;
    c.series.push(gl_line);
    let mut phi_line =
        Series::line(String::new(), vec![(phi_deg, 1.0), (phi_deg, 1e4)], grey).dotted();
    phi_line.label = None;
    phi_line.width = 1;
    c.series.push(phi_line);
    // Each angle labelled beside its line, with an arrow pointing at it: γ_lim near the bottom,
    // φ_y near the top, clear of n′₂ (which falls to 0 left of φ_y).
    c.notes.push(Note {
        at: (gl_deg + 0.6, 2.6),
        text: format!("← γ_{{lim}} = {gl_deg:.1}° (Eq 15)"),
        colour: PALETTE[6],
    });
    c.notes.push(Note {
        at: (phi_deg - 19.0, 2500.0),
        text: format!("φ_y = {phi_deg:.0}° →"),
        colour: grey,
    });
    let window = (20.0, 40.0);
    let zoom = magnified(&c, window, (0.3, 100.0), gl_deg, phi_deg, grey);
    // (b)'s key, in its empty lower right, holds for both panels: in (a) every corner has a
    // curve.
    c.show_legend = false;
    c.title = "(a) γ from 0° to 90°".into();
    Ok(Charts {
        size: (520, 540),
        title: "Generalised LiSPSM parameter against the light angle".into(),
        caption: vec![format!(
            "Barroso & Celes 2007, Fig. 7 (Eq 13–18), n = {n}, f = {f}, φ_y = π/6. Bold: the \
             paper's curve (Barroso's fall-off r(γ)); for comparison Zhang's fall-off, LiSPSM's \
             rule and the n′ of least M_z over the frustum; Eq 13's branches each on its domain. \
             (b) enlarges γ from {}° to {}°: the least-M_z curve turns near γ = φ_y, where the \
             frustum corner of largest m_z changes.",
            window.0, window.1
        )],
        charts: vec![c, zoom],
    })
}

/// `c` magnified to γ in `x` and n′ in `y`, where the curves separate (issue 25): the same
/// series (each cut to the window, so that its markers fall inside it) with short legend labels,
/// and the two angles labelled at the top, where no curve runs.
fn magnified(
    c: &LineChart,
    x: (f64, f64),
    y: (f64, f64),
    gl_deg: f64,
    phi_deg: f64,
    grey: RGBColor,
) -> LineChart {
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
    // Short legend labels, in the empty lower right (the curves run above n′ = 5 there).
    let short = [
        "Barroso (paper)",
        "Zhang",
        "LiSPSM",
        "least M_z",
        "n′_{1}",
        "n′_{2}",
    ];
    z.legend = SeriesLabelPosition::LowerRight;
    z.series = c
        .series
        .iter()
        .enumerate()
        .map(|(k, s)| {
            let mut s = s.clone();
            s.label = short.get(k).map(|l| (*l).to_string());
            s.points.retain(|p| p.0 >= x.0 && p.0 <= x.1);
            s
        })
        .collect();
    z.notes = vec![
        Note {
            at: (gl_deg + 0.3, 0.6 * y.1),
            text: format!("← γ_{{lim}} = {gl_deg:.1}°"),
            colour: PALETTE[6],
        },
        Note {
            at: (phi_deg - 9.0, 0.6 * y.1),
            text: format!("φ_y = {phi_deg:.0}° →"),
            colour: grey,
        },
    ];
    z
}

#[cfg(test)]
mod tests {
    use super::*;

    /// With the light overhead (γ = 90°) every rule is LiSPSM's n + √(fn) = 1 + 10 = 11; both
    /// fall-offs meet n′₁(γ_lim) at γ_lim; at γ = 0 no finite n′ is plotted.
    #[test]
    fn fig7_curves_meet_lispsm_overhead() {
        let fig = fig7().map_err(|e| e.named("barroso-fig7")).unwrap();
        let s = &fig.charts[0].series;
        for curve in &s[..4] {
            let (d, v) = *curve.points.last().unwrap();
            assert_eq!(d, 90.0);
            assert!((v - 11.0).abs() < 1e-6, "{v}");
        }
        assert!(s[0].points[0].0 > 0.0 && s[1].points[0].0 > 0.0);
    }

    /// Eq 13's branches are drawn only on their domains: n′₁ for φ_y = 30° ≤ γ, n′₂ for γ < 30°
    /// and, being positive only above atan(b/(f + √(fn))) = atan(57.735/110) = 27.69° (by
    /// hand), only between 27.69° and 30°.
    #[test]
    fn eq13_branches_only_on_their_domains() {
        let fig = fig7().map_err(|e| e.named("barroso-fig7")).unwrap();
        let s = &fig.charts[0].series;
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

    /// The paper's curve (Barroso's fall-off, Eq 16 with Eq 18) is the bold one (issue 25), and
    /// each angle's label ends at its line with an arrow pointing at it: γ_lim's starts just
    /// right of γ_lim = 30.5° with "←", φ_y's ends left of 30° with "→".
    #[test]
    fn the_papers_curve_is_bold_and_labels_point_at_their_lines() {
        let fig = fig7().map_err(|e| e.named("barroso-fig7")).unwrap();
        let c = &fig.charts[0];
        let bold = &c.series[0];
        assert!(bold.label.as_deref().unwrap().ends_with("(paper)"));
        assert!(c.series[1..].iter().all(|s| s.width < bold.width));
        let gl = c.notes.iter().find(|n| n.text.contains("lim")).unwrap();
        assert!(gl.text.starts_with('←') && gl.at.0 > 30.5 && gl.at.0 < 32.0);
        let phi = c.notes.iter().find(|n| n.text.contains("φ")).unwrap();
        assert!(phi.text.ends_with('→') && phi.at.0 < 30.0);
    }

    /// Issue 25: a second panel magnifies γ from 20° to 40°, where the curves separate: every
    /// curve of (a) is there, cut to the window (the four rules sampled every 0.25°: 81 points
    /// each), and the four rules lie within n′ ∈ [1, 100] (the axis reaches down to 0.3 for Eq
    /// 13's n′₂, which falls to 0 at 27.69°, by hand in `eq13_branches_only_on_their_domains`).
    #[test]
    fn panel_b_magnifies_20_to_40_degrees() {
        let fig = fig7().map_err(|e| e.named("barroso-fig7")).unwrap();
        assert_eq!(fig.charts.len(), 2);
        let (a, b) = (&fig.charts[0], &fig.charts[1]);
        assert_eq!((b.x.min, b.x.max), (20.0, 40.0));
        assert_eq!(a.series.len(), b.series.len());
        for s in &b.series[..4] {
            assert_eq!(s.points.len(), 81, "{:?}", s.label);
            assert!(s.points.iter().all(|p| (20.0..=40.0).contains(&p.0)));
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
    }
}
