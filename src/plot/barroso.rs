//! Barroso & Celes 2007 Fig 7: the generalised LiSPSM parameter n′ against the angle γ between
//! the light and view directions (n = 1, f = 100, φ_y = π/6), with both fall-offs r(γ), the
//! branches of their Eq 13, LiSPSM's 1/sin γ rule and the crate's n′ that minimises M_z over the
//! whole frustum (`WarpRule::MinimaxMz`, the frustum-wide version of Barroso's objective).

use super::chart::{linspace, Axis, Charts, LineChart, Note, Series, PALETTE};
use super::Fail;
use crate::analytic::tilted::{gamma_lim, generalized_n_prime, n_prime_1, n_prime_2, Falloff};
use crate::build::{n_prime_for, WarpRule};
use crate::{LightAngle, NPrime, ViewFrustum};
use glam::DVec3;
use plotters::prelude::{RGBColor, SeriesLabelPosition};

/// The light travelling at angle γ to the view direction, above and in front of the viewer.
fn light_at(gamma: f64) -> DVec3 {
    DVec3::new(0.0, -gamma.sin(), gamma.cos())
}

pub(super) fn fig7() -> Result<Charts, Fail> {
    let view = ViewFrustum::new(1.0, 100.0, std::f64::consts::FRAC_PI_6)?;
    let gl = gamma_lim(&view);
    let degrees = linspace(0.0, 90.0, 361);
    let finite = |n: NPrime| match n {
        NPrime::Finite(v) => Some(v),
        NPrime::Unwarped => None,
    };
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
        // Eq 13's branches where they are positive (the plot is logarithmic).
        let (a, b) = (n_prime_1(&view, angle)?, n_prime_2(&view, angle)?);
        n1.push((d, if a > 0.0 { a } else { f64::NAN }));
        n2.push((d, if b > 0.0 { b } else { f64::NAN }));
    }
    let mut c = LineChart::new(
        "",
        Axis::linear(
            "angle γ between light and view directions (degrees)",
            0.0,
            90.0,
        ),
        Axis::log10("warp parameter n′ (eye-space units, n = 1)", 1.0, 1e4),
    );
    c.legend = SeriesLabelPosition::UpperRight;
    c.series.push(Series::line(
        "generalised n′, Barroso fall-off r(γ) (Eq 16, 18)",
        barroso,
        PALETTE[0],
    ));
    c.series.push(Series::line(
        "generalised n′, Zhang fall-off r(γ) (Eq 16, 17)",
        zhang,
        PALETTE[1],
    ));
    c.series
        .push(Series::line("LiSPSM: n′ = (n + √(fn))/sin γ", lispsm, PALETTE[2]).dashed());
    c.series.push(
        Series::line(
            "n′ minimising M_z over the 3D frustum (this crate)",
            minimax,
            PALETTE[3],
        )
        .dashed(),
    );
    c.series
        .push(Series::line("n′₁(γ), Eq 13 (where > 0)", n1, PALETTE[6]).dotted());
    c.series
        .push(Series::line("n′₂(γ), Eq 13 (where > 0)", n2, PALETTE[7]).dotted());
    let gl_deg = gl.to_degrees();
    let phi_deg = view.half_fov().to_degrees();
    let grey = RGBColor(90, 90, 90);
    let mut vline = |x: f64, y: f64, label: String| {
        let mut s = Series::line(String::new(), vec![(x, 1.0), (x, 1e4)], grey).dotted();
        s.label = None;
        s.width = 1;
        c.series.push(s);
        c.notes.push(Note {
            at: (x + 0.8, y),
            text: label,
            colour: grey,
        });
    };
    vline(gl_deg, 1.7, format!("γ_lim = {gl_deg:.1}° (Eq 15)"));
    vline(phi_deg, 1.25, format!("φ_y = {phi_deg:.0}°"));
    Ok(Charts {
        size: (1100, 680),
        title: "Generalised LiSPSM parameter against the light angle".into(),
        caption: vec![
            "Barroso & Celes 2007, Fig. 7 (n = 1, f = 100, φ_y = π/6), from analytic::tilted::generalized_n_prime, n_prime_1, n_prime_2, gamma_lim;".into(),
            "LiSPSM's 1/sin γ rule and the M_z-minimising n′ (WarpRule::MinimaxMz) from build::n_prime_for. Logarithmic n′ axis: every rule tends to n′ = ∞ (no warp) as γ → 0.".into(),
        ],
        charts: vec![c],
    })
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
}
