//! Lloyd, Tuft, Yoon, Manocha 2006, *Warping and Partitioning for Low Error Shadow Maps*:
//! the closed-form figures (Fig 5, 6, 10, 12, 13). Fig 7 is in [`super::hemisphere`].

use super::chart::{linspace, Axis, Charts, LineChart, Series, PALETTE};
use super::Fail;
use crate::analytic::overhead::{max_mx, max_mz, mx, mz, storage_factor};
use crate::warp::{n_prime_from_eta, n_prime_lispsm};
use crate::{NPrime, Resolutions, ViewFrustum};
use plotters::prelude::SeriesLabelPosition;

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
    cz.legend = SeriesLabelPosition::LowerRight;
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
        cz.series.push(Series::line(label.clone(), pz, PALETTE[i]));
    }
    Ok(Charts {
        size: (1300, 620),
        title: "Error distribution along the view frustum, light overhead".into(),
        caption: vec![
            "Lloyd et al. 2006, Fig. 5 (n = 1, f = 20), from Eq 7 and 8 (analytic::overhead::mx, mz). m_x is the largest at z = n;".into(),
            "m_z at z = f for n′ ≤ n + √(fn) and at z = n beyond it. Unit image and shadow-map resolutions.".into(),
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
        Axis::linear("warp parameter η (−1: n′ = ∞, 0: n′ = n + √(fn), 1: n′ = n)", -1.0, 1.0),
        Axis::linear("value / its maximum over η", 0.0, 1.05),
    );
    c.legend = SeriesLabelPosition::UpperMiddle;
    c.series.push(Series::line(
        format!("M_x (max {top_x:.4})"),
        m_x,
        PALETTE[0],
    ));
    c.series.push(Series::line(
        format!("M_z (max {top_z:.4} at θ = 30°)"),
        m_z,
        PALETTE[1],
    ));
    c.series
        .push(Series::line(format!("S̄ = M_x M_z (max {top_s:.4} at θ = 30°)"), s, PALETTE[2]).dashed());
    Ok(Charts {
        size: (1000, 640),
        title: "Maximum error and storage factor against the warp parameter η".into(),
        caption: vec![
            "Lloyd et al. 2006, Fig. 6 (n = 1, f = 100), from Eq 9, 10, 11, 12 (analytic::overhead, warp::n_prime_from_eta).".into(),
            "Each curve is divided by its own maximum; after that θ cancels. Unit resolutions.".into(),
        ],
        charts: vec![c],
    })
}
