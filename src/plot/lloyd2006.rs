//! Lloyd, Tuft, Yoon, Manocha 2006, *Warping and Partitioning for Low Error Shadow Maps*:
//! the closed-form figures (Fig 5, 6, 10, 12, 13). Fig 7 is in [`super::hemisphere`].

use super::chart::{
    build_chart, clip_polyline, fmt_plain, frame, linspace, Axis, Charts, LineChart, Series, FONT,
    PALETTE,
};
use super::{Fail, Figure};
use crate::analytic::eta::{n_prime_from_eta, n_prime_lispsm};
use crate::analytic::overhead::{max_mx, max_mz, mx, mz, storage_factor};
use crate::analytic::partition::{scheme_storage_factor, shadow_map_count, Scheme, SchemeLight};
use crate::{NPrime, Resolutions, ViewFrustum};
use plotters::coord::Shift;
use plotters::prelude::*;

/// Fig 5: m_x and the distribution term of m_z along the frustum for several n′ (n = 1, f = 20).
///
/// m_x is plotted as it is (unit resolutions; it does not depend on θ). m_z is divided by its
/// constant factor (f − n)/(2 tan θ), leaving the last term of Lloyd 2006 Eq 8, which is what the
/// paper plots; the factor is computed from the frustum, m_z itself comes from
/// [`crate::analytic::overhead::mz`].
pub(super) fn fig5() -> Result<Charts, Fail> {
    let (n, f) = (1.0, 20.0);
    let view = ViewFrustum::new(n, f, 45f64.to_radians())?;
    let res = Resolutions::default();
    let lispsm = n_prime_lispsm(n, f)?;
    let warps = [
        (NPrime::Finite(1.0), "n′ = n = 1 (PSM, η = 1)".to_string()),
        (NPrime::Finite(2.0), "n′ = 2".to_string()),
        (
            NPrime::Finite(lispsm),
            format!("n′ = n + √(fn) ≈ {lispsm:.2} (LiSPSM, η = 0)"),
        ),
        (NPrime::Finite(20.0), "n′ = 20".to_string()),
        (NPrime::Finite(100.0), "n′ = 100".to_string()),
        (NPrime::Unwarped, "n′ = ∞ (uniform, η = −1)".to_string()),
    ];
    let zs = linspace(n, f, 160);
    let z_factor = (f - n) / (2.0 * view.tan_half_fov());
    let mut cx = LineChart::new(
        "x error m_x(z)",
        Axis::linear("depth z (eye-space units, n = 1)", n, f),
        Axis::log10("m_x (unit resolutions)", 0.9, 25.0),
    );
    let mut cz = LineChart::new(
        "z error: m_z(z) · 2 tan θ / (f − n)",
        Axis::linear("depth z (eye-space units, n = 1)", n, f),
        Axis::log10("m_z · 2 tan θ / (f − n)", 0.03, 1.3),
    );
    cx.legend = SeriesLabelPosition::UpperRight;
    for (i, (np, label)) in warps.iter().enumerate() {
        let px = zs
            .iter()
            .map(|&z| Ok((z, mx(n, f, *np, z, res)?)))
            .collect::<Result<Vec<_>, crate::Error>>()?;
        let pz = zs
            .iter()
            .map(|&z| Ok((z, mz(&view, *np, z, res)? / z_factor)))
            .collect::<Result<Vec<_>, crate::Error>>()?;
        cx.series.push(Series::line(label.clone(), px, PALETTE[i]));
        let mut sz = Series::line(String::new(), pz, PALETTE[i]);
        sz.label = None; // one legend, in the left panel, for both
        cz.series.push(sz);
    }
    Ok(Charts {
        size: (1300, 620),
        title: "Error distribution along the view frustum, light overhead".into(),
        caption: vec![
            "Lloyd et al. 2006, Fig. 5 (n = 1, f = 20), from Eq 7 and 8 (analytic::overhead::mx, mz). m_x is the largest at z = n;".into(),
            "m_z at z = f for n′ ≤ n + √(fn) and at z = n beyond it. Unit image and shadow-map resolutions; the legend holds for both panels.".into(),
        ],
        charts: vec![cx, cz],
    })
}

/// Fig 6: M_x, M_z and S̄ against η ∈ [−1, 1] (n = 1, f = 100), each divided by its maximum over η.
pub(super) fn fig6() -> Result<Charts, Fail> {
    let (n, f) = (1.0, 100.0);
    let view = ViewFrustum::new(n, f, 30f64.to_radians())?;
    let res = Resolutions::default();
    let etas = linspace(-1.0, 1.0, 401);
    let mut m_x = Vec::with_capacity(etas.len());
    let mut m_z = Vec::with_capacity(etas.len());
    let mut s = Vec::with_capacity(etas.len());
    for &eta in &etas {
        let np = n_prime_from_eta(n, f, eta)?;
        m_x.push((eta, max_mx(n, f, np, res)?));
        m_z.push((eta, max_mz(&view, np, res)?));
        s.push((eta, storage_factor(&view, np)?));
    }
    let normalise = |v: Vec<(f64, f64)>| -> (Vec<(f64, f64)>, f64) {
        let top = v.iter().map(|p| p.1).fold(0.0, f64::max);
        (v.into_iter().map(|(e, y)| (e, y / top)).collect(), top)
    };
    let (m_x, top_x) = normalise(m_x);
    let (m_z, top_z) = normalise(m_z);
    let (s, top_s) = normalise(s);
    let mut c = LineChart::new(
        "",
        Axis::linear(
            "warp parameter η (−1: n′ = ∞, 0: n′ = n + √(fn), 1: n′ = n)",
            -1.0,
            1.0,
        ),
        Axis::linear("value / its maximum over η", 0.0, 1.05),
    );
    c.legend = SeriesLabelPosition::UpperMiddle;
    c.series.push(Series::line(
        format!("M_x (maximum {})", fmt_plain(top_x)),
        m_x,
        PALETTE[0],
    ));
    c.series.push(Series::line(
        format!("M_z (maximum {} at θ = 30°)", fmt_plain(top_z)),
        m_z,
        PALETTE[1],
    ));
    c.series.push(
        Series::line(
            format!("S̄ = M_x M_z (maximum {} at θ = 30°)", fmt_plain(top_s)),
            s,
            PALETTE[2],
        )
        .dashed(),
    );
    Ok(Charts {
        size: (1000, 640),
        title: "Maximum error and storage factor against the warp parameter η".into(),
        caption: vec![
            "Lloyd et al. 2006, Fig. 6 (n = 1, f = 100), from Eq 9, 10, 11, 12 (analytic::overhead, analytic::eta::n_prime_from_eta).".into(),
            "Each curve is divided by its own maximum, after which θ cancels. For η ≤ 0 the normalised M_x and M_z coincide (both ∝ n′/(n′ + f − n)); S̄ is constant for η ≥ 0.".into(),
        ],
        charts: vec![c],
    })
}

/// Fig 10: S̄ of ZP+W with the light overhead against the number of z-partitions k, for several
/// f/n, each with the optimal logarithmic S̄ (App. C) it tends to.
pub(super) fn fig10() -> Result<Charts, Fail> {
    let theta = 30f64.to_radians();
    let mut c = LineChart::new(
        "",
        Axis::linear("number of z-partitions k", 1.0, 16.0),
        Axis::log10("storage factor S̄ (texels per image pixel²)", 1.0, 1e4),
    );
    c.legend = SeriesLabelPosition::UpperRight;
    for (i, ratio) in [10.0, 100.0, 1000.0, 10_000.0].into_iter().enumerate() {
        let view = ViewFrustum::new(1.0, ratio, theta)?;
        let pts = (1..=16usize)
            .map(|k| {
                Ok((
                    k as f64,
                    scheme_storage_factor(Scheme::ZpW, SchemeLight::Overhead, &view, k)?,
                ))
            })
            .collect::<Result<Vec<_>, crate::Error>>()?;
        c.series
            .push(Series::line(format!("ZP+W, f/n = {ratio}"), pts, PALETTE[i]).with_markers());
        let opt = scheme_storage_factor(Scheme::Optimal, SchemeLight::Overhead, &view, 1)?;
        c.series.push(
            Series::line(
                format!("optimal ln(f/n)/(2 tan θ) = {opt:.2}"),
                vec![(1.0, opt), (16.0, opt)],
                PALETTE[i],
            )
            .dashed(),
        );
    }
    Ok(Charts {
        size: (1000, 660),
        title: "Storage factor of warped z-partitions against the number of partitions, light overhead".into(),
        caption: vec![
            "Lloyd et al. 2006, Fig. 10 (θ = 30°), from Eq 18 and App. C (analytic::partition::scheme_storage_factor with Scheme::ZpW and Scheme::Optimal).".into(),
            "S̄ = k((f/n)^{1/k} − 1)/(2 tan θ) decreases with k towards the optimal logarithmic parameterisation (dashed).".into(),
        ],
        charts: vec![c],
    })
}

/// Fig 12: S̄ against the number of shadow maps for ZP, ZP+W and FP+ZP+W, light overhead and
/// behind (f/n = 1000, θ = 30°).
///
/// The number of maps of FP+ZP+W is 4k + 1 for both light directions
/// ([`shadow_map_count`] for the light behind): a scheme keeps its maps whatever the light, which
/// is how §5.3 counts them ("only one z-partitioning for every four shadow maps", Eq 23).
pub(super) fn fig12() -> Result<Charts, Fail> {
    let view = ViewFrustum::new(1.0, 1000.0, 30f64.to_radians())?;
    let mut c = LineChart::new(
        "",
        Axis::linear("number of shadow maps", 0.0, 40.0),
        Axis::log10("storage factor S̄ (texels per image pixel²)", 1.0, 1e7),
    );
    c.legend = SeriesLabelPosition::UpperRight;
    let schemes = [
        (Scheme::Zp, "ZP", 0),
        (Scheme::ZpW, "ZP+W", 1),
        (Scheme::FpZpW, "FP+ZP+W", 2),
    ];
    for (light, light_name) in [
        (SchemeLight::Overhead, "overhead"),
        (SchemeLight::Behind, "behind"),
    ] {
        for (scheme, name, colour) in schemes {
            let mut pts = Vec::new();
            for k in 1..=16usize {
                let maps = shadow_map_count(scheme, SchemeLight::Behind, k)?;
                if maps > 40 {
                    break;
                }
                pts.push((maps as f64, scheme_storage_factor(scheme, light, &view, k)?));
            }
            let s = Series::line(format!("{name}, light {light_name}"), pts, PALETTE[colour])
                .with_markers();
            let mut s = match light {
                SchemeLight::Overhead => s,
                SchemeLight::Behind => s.dashed(),
            };
            if light == SchemeLight::Behind && scheme == Scheme::Zp {
                // ZP+W equals ZP behind and is drawn over it: keep ZP visible around it.
                s.width = 5;
            }
            c.series.push(s);
        }
    }
    Ok(Charts {
        size: (1000, 660),
        title: "Storage factor against the number of shadow maps".into(),
        caption: vec![
            "Lloyd et al. 2006, Fig. 12 (f/n = 1000, θ = 30°), from Eq 17–21 (analytic::partition::scheme_storage_factor). k z-partitions use k maps; FP+ZP+W uses 4k + 1".into(),
            "(four side faces and the near face). Behind, ZP+W equals ZP (a square frustum cannot be warped); FP+ZP+W behind is Eq 21 with each face at 45° whatever θ (docs/errata.md).".into(),
        ],
        charts: vec![c],
    })
}

/// Fig 13 data: for each number of maps 4k + 1, the f/n above which z-partitioning (ZP, ZP+W)
/// has the lower storage factor than FP+ZP+W with the light behind.
pub(super) struct Fig13 {
    /// (number of maps, crossover f/n)
    crossover: Vec<(f64, f64)>,
    y: Axis,
    x: Axis,
}

/// The f/n at which ZP with `maps` maps and FP+ZP+W with `k` z-partitions per face have equal S̄
/// with the light behind (bisection on ln(f/n); FP+ZP+W is lower below it, ZP above).
fn crossover(maps: usize, k: usize, lo: f64, hi: f64) -> Result<Option<f64>, crate::Error> {
    let diff = |ratio: f64| -> Result<f64, crate::Error> {
        let v = ViewFrustum::new(1.0, ratio, std::f64::consts::FRAC_PI_4)?;
        let zp = scheme_storage_factor(Scheme::Zp, SchemeLight::Behind, &v, maps)?;
        let fp = scheme_storage_factor(Scheme::FpZpW, SchemeLight::Behind, &v, k)?;
        Ok((zp / fp).ln())
    };
    let (mut a, mut b) = (lo.ln(), hi.ln());
    let (da, db) = (diff(a.exp())?, diff(b.exp())?);
    if da.signum() == db.signum() {
        return Ok(None);
    }
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if diff(m.exp())?.signum() == da.signum() {
            a = m;
        } else {
            b = m;
        }
    }
    Ok(Some((0.5 * (a + b)).exp()))
}

pub(super) fn fig13() -> Result<Fig13, Fail> {
    let (lo, hi) = (1.5, 1e12);
    let mut pts = Vec::new();
    for k in 1..=12usize {
        let maps = shadow_map_count(Scheme::FpZpW, SchemeLight::Behind, k)?;
        if let Some(r) = crossover(maps, k, lo, hi)? {
            pts.push((maps as f64, r));
        }
    }
    Ok(Fig13 {
        crossover: pts,
        x: Axis::linear("number of shadow maps (4k + 1)", 5.0, 49.0),
        y: Axis::log10("depth ratio f/n", lo, hi),
    })
}

impl Figure for Fig13 {
    fn size(&self) -> (u32, u32) {
        (1000, 660)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let body = frame(
            root,
            "Which partitioning has the lowest error, light behind the viewer",
            &[
                "Lloyd et al. 2006, Fig. 13, from Eq 20 and 21 (analytic::partition::scheme_storage_factor, light behind): at equal numbers of maps, j = 4k + 1,",
                "z-partitioning (ZP, or ZP+W: the same behind) with j maps against face partitioning with k warped z-partitions per face. The curve is where S̄ is equal.",
            ],
        )?;
        let mut chart = build_chart(&body, "", &self.x, &self.y, true)?;
        let (x0, x1) = self.x.range();
        let (y0, y1) = self.y.range();
        let curve: Vec<(f64, f64)> = self
            .crossover
            .iter()
            .filter_map(|&(x, y)| Some((self.x.to_axis(x)?, self.y.to_axis(y)?)))
            .collect();
        if let (Some(first), Some(last)) = (curve.first(), curve.last()) {
            let mut above = vec![(first.0, y1)];
            above.extend(curve.iter().copied());
            above.push((last.0, y1));
            let mut below = vec![(first.0, y0)];
            below.extend(curve.iter().copied());
            below.push((last.0, y0));
            chart.draw_series(std::iter::once(Polygon::new(
                above,
                PALETTE[0].mix(0.18).filled(),
            )))?;
            chart.draw_series(std::iter::once(Polygon::new(
                below,
                PALETTE[1].mix(0.18).filled(),
            )))?;
        }
        let clipped = clip_polyline(
            &curve.iter().map(|&p| Some(p)).collect::<Vec<_>>(),
            (x0, x1, y0, y1),
        );
        for piece in clipped {
            chart.draw_series(LineSeries::new(piece, PALETTE[6].stroke_width(2)))?;
        }
        chart.draw_series(
            curve
                .iter()
                .map(|&p| Circle::new(p, 4, PALETTE[6].filled())),
        )?;
        let label = |text: &str, x: f64, y: f64, colour: &'static RGBColor| {
            Text::new(
                text.to_string(),
                (x, y),
                TextStyle::from((FONT, 18).into_font()).color(colour),
            )
        };
        let xm = x0 + 0.35 * (x1 - x0);
        chart.draw_series(std::iter::once(label(
            "ZP / ZP+W lowest (high depth range, few maps)",
            xm,
            y0 + 0.85 * (y1 - y0),
            &PALETTE[0],
        )))?;
        chart.draw_series(std::iter::once(label(
            "FP+ZP+W lowest",
            x0 + 0.6 * (x1 - x0),
            y0 + 0.12 * (y1 - y0),
            &PALETTE[1],
        )))?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
        // The crossover depth ratio grows with the number of maps.
        assert!(fig
            .crossover
            .windows(2)
            .all(|w| w[1].1 > w[0].1 && w[1].0 > w[0].0));
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
        let x_curve = &fig.charts[0].series[2].points;
        assert!((x_curve[0].1 - 20.0 * np / (np + 19.0)).abs() < 1e-12);
    }

    /// Fig 6, by hand from Eq 8 (n = 1, α = f/n = 100, c = (α − 1)/(2 tan θ)): at η = −1
    /// (n′ = ∞) M_z = m_z(n) = c, at η = 1 (n′ = n) M_z = m_z(f) = c, and at η = 0
    /// (n′ = 1 + √α) M_z = c (1 + √α)/(√α + α) = c/√α. Normalised: 1, 1 and 1/√α = 0.1.
    #[test]
    fn fig6_m_z_is_smallest_at_eta_zero_and_equal_at_both_ends() {
        let fig = fig6().map_err(|e| e.named("lloyd2006-fig6")).unwrap();
        let m_z = &fig.charts[0].series[1].points;
        let (first, last) = (m_z[0].1, m_z.last().unwrap().1);
        assert!((first - 1.0).abs() < 1e-12 && (last - 1.0).abs() < 1e-12);
        let min = m_z
            .iter()
            .copied()
            .fold((0.0, f64::INFINITY), |a, p| if p.1 < a.1 { p } else { a });
        assert!(min.0.abs() < 1e-12, "minimum at η = {}", min.0);
        assert!((min.1 - 0.1).abs() < 1e-12, "{}", min.1);
    }
}
