//! Lloyd, Tuft, Yoon, Manocha 2006, *Warping and Partitioning for Low Error Shadow Maps*:
//! the closed-form figures (Fig 5, 6, 10, 12, 13). Fig 7 is in [`super::hemisphere`].

use super::chart::FONT;
use super::chart::{
    build_chart, fmt_plain, frame, linspace, Axis, Charts, LineChart, Note, Series, PALETTE,
};
use super::{Fail, Figure};
use crate::analytic::eta::{n_prime_from_eta, n_prime_lispsm};
use crate::analytic::overhead::{max_mx, max_mz, mx, mz, storage_factor};
use crate::analytic::partition::{scheme_storage_factor, shadow_map_count, Scheme, SchemeLight};
use crate::{NPrime, Resolutions, ViewFrustum};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Fig 5: m_x and the distribution term of m_z along the frustum for several n′ (n = 1, f = 20).
///
/// Both are divided by their constant factors, leaving the last terms of Lloyd 2006 Eq 7 and 8,
/// which is what the paper plots: m_x by f (unit resolutions), m_z by (f − n)/(2 tan θ). The
/// factors are computed from the frustum; m_x and m_z themselves come from
/// [`crate::analytic::overhead::mx`] and [`crate::analytic::overhead::mz`].
pub(super) fn fig5() -> Result<Charts, Fail> {
    let (n, f) = (1.0, 20.0);
    let view = ViewFrustum::new(n, f, 45f64.to_radians())?;
    let res = Resolutions::default();
    let lispsm = n_prime_lispsm(n, f)?;
    let warps = [
        (NPrime::finite(1.0)?, "n′ = n = 1 (PSM, η = 1)".to_string()),
        (NPrime::finite(2.0)?, "n′ = 2".to_string()),
        (
            NPrime::finite(lispsm)?,
            format!("n′ = n + √(fn) ≈ {lispsm:.2} (LiSPSM, η = 0)"),
        ),
        (NPrime::finite(20.0)?, "n′ = 20".to_string()),
        (NPrime::finite(100.0)?, "n′ = 100".to_string()),
        (NPrime::UNWARPED, "n′ = ∞ (uniform, η = −1)".to_string()),
    ];
    let zs = linspace(n, f, 160);
    let z_factor = (f - n) / (2.0 * view.tan_half_fov());
    let mut cx = LineChart::new(
        "x error: m_x(z) / f",
        Axis::linear("depth z (eye-space units, n = 1)", n, f),
        Axis::log10("m_x / f = (n′ + z − n)/(z(n′ + f − n))", 0.03, 1.3),
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
            .map(|&z| Ok((z, mx(n, f, *np, z, res)? / f)))
            .collect::<Result<Vec<_>, crate::Error>>()?;
        let pz = zs
            .iter()
            .map(|&z| Ok((z, mz(&view, *np, z, res)? / z_factor)))
            .collect::<Result<Vec<_>, crate::Error>>()?;
        cx.series.push(Series::line(label.clone(), px, PALETTE[i]));
        // The lower panel's curves labelled directly at the far plane with their n′ (and with
        // the upper panel's markers, so that both read in greyscale).
        let short = label.split(" (").next().unwrap_or(label).to_string();
        cz.series.push(Series::line(short, pz, PALETTE[i]).direct());
    }
    Ok(Charts {
        size: (520, 860),
        title: "Error distribution along the view frustum, light overhead".into(),
        caption: vec![
            "Lloyd et al. 2006, Fig. 5 (n = 1, f = 20), from Eq 7 and 8 (analytic::overhead::mx, mz): the last term of each, as the paper plots, i.e. m_x divided by f and m_z by (f − n)/(2 tan θ).".into(),
            "m_x is the largest at z = n; m_z at z = f for n′ ≤ n + √(fn) and at z = n beyond it. Unit image and shadow-map resolutions; the legend of the upper panel holds for both, the lower panel's curves carry the same markers and their n′ at the far plane.".into(),
        ],
        charts: vec![cx, cz],
    })
}

/// Fig 6: M_x, M_z and S̄ against η ∈ [−1, 1] (n = 1, f = 100, θ = 30°, unit resolutions), as
/// they are, on a logarithmic axis (the paper normalises each to fit one linear scale, which puts
/// M_x under M_z for η ≤ 0 and the flat S̄ for η ≥ 0 on the x axis).
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
    let top = |v: &[(f64, f64)]| v.iter().map(|p| p.1).fold(0.0, f64::max);
    let (top_x, top_z, top_s) = (top(&m_x), top(&m_z), top(&s));
    let mut c = LineChart::new(
        "",
        Axis::linear(
            "warp parameter η (−1: n′ = ∞, 0: n′ = n + √(fn), 1: n′ = n)",
            -1.0,
            1.0,
        ),
        Axis::log10("M_x, M_z (unit resolutions), S̄ (log scale)", 0.5, 2e4),
    );
    c.legend = SeriesLabelPosition::LowerLeft;
    c.series.push(Series::line(
        format!("M_x (maximum {})", fmt_plain(top_x)),
        m_x,
        PALETTE[0],
    ));
    c.series.push(Series::line(
        format!("M_z (maximum {} at θ = 30°)", fmt_plain(top_z)),
        m_z.clone(),
        PALETTE[1],
    ));
    // (b): M_z on a linear axis, where its V (linear in η on each side of 0, App. B) shows.
    let mut v = LineChart::new(
        "(b) M_z on a linear axis: the V",
        c.x.clone(),
        Axis::linear("M_z (unit resolutions)", 0.0, 1.05 * top_z),
    );
    // No legend: the panel's title names its one curve.
    v.series.push(Series {
        label: None,
        ..Series::line("M_z", m_z, PALETTE[1])
    });
    v.legend = SeriesLabelPosition::UpperMiddle;
    c.title = "(a) as they are, logarithmic".into();
    c.series.push(
        Series::line(
            format!("S̄ = M_x M_z (maximum {} at θ = 30°)", fmt_plain(top_s)),
            s,
            PALETTE[2],
        )
        .dashed(),
    );
    Ok(Charts {
        size: (520, 900),
        title: "Maximum error and storage factor against the warp parameter η".into(),
        caption: vec![
            "Lloyd et al. 2006, Fig. 6 (n = 1, f = 100), from Eq 9, 10, 11, 12 (analytic::overhead, analytic::eta::n_prime_from_eta).".into(),
            "θ = 30°, unit resolutions. Unlike the paper, which normalises each curve to fit one linear scale, the values are drawn as they are on a logarithmic axis: for η ≤ 0 M_x and M_z are both proportional to n′/(n′ + f − n) and run parallel; for η ≥ 0 S̄ stays constant while M_x falls and M_z rises (§4.3). (b) M_z alone on a linear axis: the paper's V, falling linearly to its minimum at η = 0 and rising linearly to η = 1.".into(),
        ],
        charts: vec![c, v],
    })
}

/// Fig 10: S̄ of ZP+W with the light overhead against the number of z-partitions k, for several
/// f/n, each with the optimal logarithmic S̄ (App. C) it tends to.
pub(super) fn fig10() -> Result<Charts, Fail> {
    let theta = 30f64.to_radians();
    let mut c = LineChart::new(
        "(a) S̄, as in the paper; dashed: each optimum",
        Axis::integer("number of z-partitions k", 1.0, 16.0),
        Axis::log10("storage factor S̄ (texels per image pixel)", 1.0, 1e4),
    );
    c.legend = SeriesLabelPosition::UpperRight;
    let mut r = LineChart::new(
        "(b) S̄ over the optimum: every curve tends to 1",
        Axis::integer("number of z-partitions k", 1.0, 16.0),
        Axis::log10("S̄ / S̄_{opt}", 0.8, 2000.0),
    );
    r.legend = SeriesLabelPosition::UpperRight;
    let mut optima = Vec::new();
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
        let opt = scheme_storage_factor(Scheme::Optimal, SchemeLight::Overhead, &view, 1)?;
        let label = format!("ZP+W, f/n = {}", fmt_plain(ratio));
        r.series.push(
            Series::line(
                label.clone(),
                pts.iter().map(|&(k, v)| (k, v / opt)).collect(),
                PALETTE[i],
            )
            .with_markers(),
        );
        c.series
            .push(Series::line(label, pts, PALETTE[i]).with_markers());
        // The asymptote, labelled on the line with its value (placed clear of the curves; the
        // legend's last entry says what the dashed lines are).
        let asymptote = Series::line(
            format!("{opt:.2}"),
            linspace(1.0, 16.0, 61)
                .into_iter()
                .map(|k| (k, opt))
                .collect(),
            PALETTE[i],
        )
        .dashed()
        .reference()
        .direct_at(3.0);
        c.series.push(asymptote);
        optima.push(format!("{opt:.2} (f/n = {})", fmt_plain(ratio)));
    }
    c.series.push(
        Series::line(
            "optimum ln(f/n)/(2 tan θ)",
            Vec::new(),
            RGBColor(90, 90, 90),
        )
        .dashed()
        .reference(),
    );
    r.series.push(
        Series::line(
            "optimum",
            vec![(1.0, 1.0), (16.0, 1.0)],
            RGBColor(90, 90, 90),
        )
        .dashed()
        .reference(),
    );
    Ok(Charts {
        size: (520, 980),
        title: "Storage factor of warped z-partitions against the number of partitions, light overhead".into(),
        caption: vec![
            "Lloyd et al. 2006, Fig. 10 (θ = 30°), from Eq 18 and App. C (analytic::partition::scheme_storage_factor with Scheme::ZpW and Scheme::Optimal).".into(),
            format!("S̄ = k((f/n)^{{1/k}} − 1)/(2 tan θ) decreases with k towards the optimal logarithmic parameterisation ln(f/n)/(2 tan θ) (dashed, in each curve's colour, its value written on it): {}. Panel (b), not in the paper, divides each curve by its optimum so that the approach shows on one scale; the paper plots one frustum it does not name, we plot four.", optima.join(", ")),
        ],
        charts: vec![c, r],
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
        Axis::integer("number of shadow maps", 0.0, 40.0),
        Axis::log10("storage factor S̄ (texels per image pixel)", 1.0, 1e7),
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
            if light == SchemeLight::Behind && scheme == Scheme::ZpW {
                // Equal to ZP behind (a square frustum cannot be warped): one line, one entry.
                continue;
            }
            let mut pts = Vec::new();
            for k in 1..=40usize {
                let maps = shadow_map_count(scheme, SchemeLight::Behind, k)?;
                if maps > 40 {
                    break;
                }
                pts.push((maps as f64, scheme_storage_factor(scheme, light, &view, k)?));
            }
            let s = if scheme == Scheme::FpZpW {
                // Defined only at 4k + 1 maps: markers, not joined across the counts between
                // (overhead green triangles, behind olive hexagons).
                let colour = match light {
                    SchemeLight::Overhead => PALETTE[colour],
                    SchemeLight::Behind => PALETTE[7],
                };
                Series {
                    width: 3,
                    ..Series::line(
                        format!("{name}, light {light_name} (4k + 1 maps only)"),
                        unjoined(&pts),
                        colour,
                    )
                    .with_markers()
                }
            } else {
                // Every count: a line, with a few markers along it (not one per count).
                let name = match light {
                    SchemeLight::Behind => "ZP = ZP+W",
                    SchemeLight::Overhead => name,
                };
                Series::line(format!("{name}, light {light_name}"), pts, PALETTE[colour])
            };
            c.series.push(match light {
                SchemeLight::Overhead => s,
                SchemeLight::Behind => s.dashed(),
            });
        }
    }
    // (b): the light-behind crossover enlarged, ZP (equal to ZP+W there) against FP+ZP+W.
    let mut zoom = LineChart::new(
        "(b) light behind, enlarged around the crossover",
        // Padded by half a count, so that the markers at 11 and 23 maps are whole.
        Axis::integer("number of shadow maps", 10.5, 23.5),
        Axis::linear("S̄ (texels per image pixel)", 25.0, 65.0),
    );
    zoom.legend = SeriesLabelPosition::UpperRight;
    for (scheme, name, colour) in [
        (Scheme::Zp, "ZP = ZP+W, light behind", 0),
        (Scheme::FpZpW, "FP+ZP+W, light behind (4k + 1 maps only)", 7),
    ] {
        let mut pts = Vec::new();
        for k in 1..=23usize {
            let maps = shadow_map_count(scheme, SchemeLight::Behind, k)?;
            if (11..=23).contains(&maps) {
                pts.push((
                    maps as f64,
                    scheme_storage_factor(scheme, SchemeLight::Behind, &view, k)?,
                ));
            }
        }
        let pts = if scheme == Scheme::FpZpW {
            unjoined(&pts)
        } else {
            pts
        };
        if scheme == Scheme::FpZpW {
            let s = Series::line(name, pts, PALETTE[colour])
                .dashed()
                .with_markers();
            zoom.series.push(Series { width: 3, ..s });
        } else {
            // ZP without markers (at 17 maps its marker lay under FP+ZP+W's, 38.32 against
            // 37.99): the line unlabelled, its legend key a line sample; the values are written.
            zoom.series.push(Series {
                label: None,
                ..Series::line(name, pts, PALETTE[colour]).dashed()
            });
            zoom.series.push(
                Series::line(name, Vec::new(), PALETTE[colour])
                    .dashed()
                    .reference(),
            );
        }
    }
    zoom.notes.push(Note {
        at: (11.4, 33.0),
        text: "from 17 maps FP+ZP+W is lower: 37.99 against ZP's 38.32".into(),
        colour: PALETTE[6],
    });
    c.title = "(a) overhead (solid) and behind (dashed)".into();
    Ok(Charts {
        size: (520, 980),
        title: "Storage factor against the number of shadow maps".into(),
        caption: vec![
            "Lloyd et al. 2006, Fig. 12 (f/n = 1000, θ = 30°), from Eq 17–21 (analytic::partition::scheme_storage_factor). k z-partitions use k maps; FP+ZP+W uses 4k + 1".into(),
            "(four side faces and the near face), so its values are markers, not joined across the counts between. Behind, ZP+W equals ZP (a square frustum cannot be warped); FP+ZP+W behind is Eq 21 with each face at 45° whatever θ (docs/errata.md). Up to 40 maps, so that the light-behind crossover of §5.3 shows; (b), not in the paper, enlarges it: at 13 maps ZP is lower (37.6 against 55.0), at 17 FP+ZP+W (37.99 against 38.32).".into(),
        ],
        charts: vec![c, zoom],
    })
}

/// Points of a quantity defined only at its own x values (FP+ZP+W at 4k + 1 maps), drawn as
/// markers without a line: a gap (a non-finite y, which a line chart never joins across)
/// between each two.
fn unjoined(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(2 * points.len());
    for (i, &p) in points.iter().enumerate() {
        if i > 0 {
            out.push((0.5 * (points[i - 1].0 + p.0), f64::NAN));
        }
        out.push(p);
    }
    out
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
    // The search interval of the crossover; the plot shows the depth ratios of real scenes.
    let (lo, hi) = (1.5, 1e12);
    let mut pts = Vec::new();
    for k in 1..=10usize {
        let maps = shadow_map_count(Scheme::FpZpW, SchemeLight::Behind, k)?;
        if let Some(r) = crossover(maps, k, lo, hi)? {
            pts.push((maps as f64, r));
        }
    }
    Ok(Fig13 {
        crossover: pts,
        x: Axis::every(
            "number of shadow maps j = 4k + 1 (k z-partitions per face)",
            3.0,
            43.0,
            5.0,
            4.0,
        ),
        y: Axis::log10("depth ratio f/n", 1.0, 1e6),
    })
}

/// Fig 13's fills: dark blue where z-partitioning is lowest, light orange where face
/// partitioning is, so that the two read apart in greyscale too.
const ZP_FILL: RGBColor = RGBColor(62, 122, 178);
const FP_FILL: RGBColor = RGBColor(246, 214, 170);

/// Height of Fig 13's key row, above the chart.
const KEY_HEIGHT: u32 = 30;

/// Fig 13's key: a swatch of each fill and the crossover dot, each with its meaning, in one row
/// (it was two boxes inside the chart, over the fills).
fn draw_fig13_key<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
    let style = TextStyle::from((FONT, 13).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
    let (w, h) = area.dim_in_pixel();
    let y = h as i32 / 2;
    let entries: [(&str, Option<RGBColor>); 3] = [
        ("ZP / ZP+W lowest", Some(ZP_FILL)),
        ("FP+ZP+W lowest", Some(FP_FILL)),
        ("equal S̄", None),
    ];
    let widths = entries
        .iter()
        .map(|(t, _)| area.estimate_text_size(t, &style).map(|s| s.0 as i32))
        .collect::<Result<Vec<_>, _>>()?;
    let (swatch, gap, between) = (14, 5, 18);
    let total: i32 = widths.iter().map(|t| swatch + gap + t).sum::<i32>() + between * 2;
    let mut x = (w as i32 - total) / 2;
    for ((text, fill), tw) in entries.into_iter().zip(widths) {
        match fill {
            Some(c) => {
                area.draw(&Rectangle::new(
                    [(x, y - swatch / 2), (x + swatch, y + swatch / 2)],
                    c.filled(),
                ))?;
                area.draw(&Rectangle::new(
                    [(x, y - swatch / 2), (x + swatch, y + swatch / 2)],
                    RGBColor(120, 120, 120).stroke_width(1),
                ))?;
            }
            None => area.draw(&Circle::new((x + swatch / 2, y), 4, PALETTE[6].filled()))?,
        }
        area.draw(&Text::new(text, (x + swatch + gap, y), style.clone()))?;
        x += swatch + gap + tw + between;
    }
    Ok(())
}

impl Figure for Fig13 {
    fn size(&self) -> (u32, u32) {
        (520, 570)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let body = frame(
            root,
            "Which partitioning has the lowest error, light behind the viewer",
            &[
                "Lloyd et al. 2006, Fig. 13, from Eq 20 and 21 (analytic::partition::scheme_storage_factor, light behind): at equal numbers of maps, j = 4k + 1,",
                "z-partitioning (ZP, or ZP+W: the same behind) with j maps against face partitioning with k warped z-partitions per face. The comparison exists only at j = 4k + 1, so each j is a column: FP+ZP+W is lowest below the dot (where S̄ is equal), ZP above it (the paper draws continuous regions). f/n up to 10⁶ (the dot at 17 maps is just above f/n = 1000, Fig 12's crossover).",
            ],
        )?;
        // The key above the chart, where it covers nothing.
        let (key, plot) = body.split_vertically(KEY_HEIGHT);
        draw_fig13_key(&key)?;
        let mut chart = build_chart(&plot, "", &self.x, &self.y, true)?;
        let (y0, y1) = self.y.range();
        let half = 1.3;
        for &(j, r) in &self.crossover {
            let Some(ry) = self.y.to_axis(r) else {
                continue;
            };
            let mid = ry.clamp(y0, y1);
            chart.draw_series([
                Rectangle::new([(j - half, mid), (j + half, y1)], ZP_FILL.filled()),
                Rectangle::new([(j - half, y0), (j + half, mid)], FP_FILL.filled()),
            ])?;
            if ry <= y1 {
                chart.draw_series(std::iter::once(Circle::new(
                    (j, ry),
                    4,
                    PALETTE[6].filled(),
                )))?;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
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
        for key in ["ZP / ZP+W lowest", "FP+ZP+W lowest"] {
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
    /// "ZP = ZP+W, light behind", drawn at the normal width in (a) (a second entry with a width-5
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
            assert_eq!(behind, ["ZP = ZP+W, light behind"], "{}", chart.title);
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
    /// 7.98) is written once in its curve's colour, level with its dashed line (within 20
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
            let colour = {
                let c = PALETTE[i];
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
}
