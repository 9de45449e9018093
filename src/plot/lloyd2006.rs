//! Lloyd, Tuft, Yoon, Manocha 2006, *Warping and Partitioning for Low Error Shadow Maps*:
//! the closed-form figures (Fig 5, 6, 10, 12, 13). Fig 7 is in [`super::hemisphere`].

use super::chart::FONT;
use super::chart::{
    build_chart, fmt_plain, frame, linspace, Axis, Charts, LineChart, Look, Marker, Note, Series,
    PALETTE, SHARED,
};
use super::{Column, Fail, Figure};
use crate::analytic::eta::{n_prime_from_eta, n_prime_lispsm};
use crate::analytic::overhead::{max_mx, max_mz, mx, mz, storage_factor};
use crate::analytic::partition::{scheme_storage_factor, shadow_map_count, Scheme, SchemeLight};
use crate::{NPrime, Resolutions, ViewFrustum};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The half field of view θ of Fig 6, 10 and 12, in degrees.
const THETA_DEG: f64 = 30.0;

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
    // PSM, LiSPSM and the uniform map in their colours of every figure (Look); the other
    // parameters in the palette's colours no scheme of the figure has.
    let warps = [
        (
            NPrime::finite(1.0)?,
            "n′ = n = 1 (PSM)".to_string(),
            Look::Psm.colour(),
        ),
        (NPrime::finite(2.0)?, "n′ = 2".to_string(), PALETTE[1]),
        (
            NPrime::finite(lispsm)?,
            format!("n′ ≈ {lispsm:.2} (LiSPSM)"),
            Look::Lispsm.colour(),
        ),
        (NPrime::finite(20.0)?, "n′ = 20".to_string(), PALETTE[3]),
        (NPrime::finite(100.0)?, "n′ = 100".to_string(), PALETTE[5]),
        (
            NPrime::UNWARPED,
            "n′ = ∞ (uniform)".to_string(),
            Look::Uniform.colour(),
        ),
    ];
    let zs = linspace(n, f, 160);
    let z_factor = (f - n) / (2.0 * view.tan_half_fov());
    let mut cx = LineChart::new(
        "(a) x error: m_x(z) / f",
        Axis::linear("depth z (eye-space units, n = 1)", n, f),
        // Short enough for a panel shortened by a legend below it (Eq 7's term is in the title).
        Axis::log10("m_x / f", 0.03, 1.3),
    );
    let mut cz = LineChart::new(
        "(b) z error: m_z(z) · 2 tan θ / (f − n)",
        Axis::linear("depth z (eye-space units, n = 1)", n, f),
        Axis::log10("m_z · 2 tan θ / (f − n)", 0.03, 1.3),
    );
    cx.legend = SeriesLabelPosition::UpperRight;
    for (np, label, colour) in &warps {
        let px = zs
            .iter()
            .map(|&z| Ok((z, mx(n, f, *np, z, res)? / f)))
            .collect::<Result<Vec<_>, crate::Error>>()?;
        let pz = zs
            .iter()
            .map(|&z| Ok((z, mz(&view, *np, z, res)? / z_factor)))
            .collect::<Result<Vec<_>, crate::Error>>()?;
        cx.series.push(Series::line(label.clone(), px, *colour));
        // The lower panel's curves labelled directly at the far plane with their n′ (and with
        // the upper panel's markers, so that both read in greyscale).
        let short = label.split(" (").next().unwrap_or(label).to_string();
        cz.series.push(Series::line(short, pz, *colour).direct());
    }
    Ok(Charts {
        size: (520, 540),
        title: "Error distribution along the view frustum, light overhead".into(),
        caption: vec![format!(
            "Lloyd et al. 2006, Fig. 5 (Eq 7, 8), n = {n}, f = {f}, unit resolutions: the terms \
             that vary with z, m_x over f and m_z over (f − n)/(2 tan θ), as the paper plots \
             them. m_x is largest at z = n; m_z at z = f for n′ ≤ n + √(fn) and at z = n beyond. \
             The legend of (a) holds for both panels."
        )],
        charts: vec![cx, cz],
    })
}

/// Fig 6: M_x, M_z and S̄ against η ∈ [−1, 1] (n = 1, f = 100, θ = 30°, unit resolutions), as
/// they are, on a logarithmic axis (the paper normalises each to fit one linear scale, which puts
/// M_x under M_z for η ≤ 0 and the flat S̄ for η ≥ 0 on the x axis).
pub(super) fn fig6() -> Result<Charts, Fail> {
    let (n, f) = (1.0, 100.0);
    let view = ViewFrustum::new(n, f, THETA_DEG.to_radians())?;
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
        Axis::linear("η (−1: n′ = ∞, 1: n′ = n)", -1.0, 1.0),
        Axis::log10("M_x, M_z, S̄ (log scale)", 0.5, 2e4),
    );
    c.legend = SeriesLabelPosition::LowerLeft;
    c.series.push(Series::line(
        format!("M_x (maximum {})", fmt_plain(top_x)),
        m_x,
        PALETTE[0],
    ));
    c.series.push(Series::line(
        format!("M_z (maximum {})", fmt_plain(top_z)),
        m_z.clone(),
        PALETTE[1],
    ));
    // (b): M_z on a linear axis, where its V (linear in η on each side of 0, App. B) shows.
    let mut v = LineChart::new(
        "(b) M_z, linear: the V",
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
            format!("S̄ = M_x M_z (max. {})", fmt_plain(top_s)),
            s,
            PALETTE[2],
        )
        .dashed(),
    );
    Ok(Charts {
        size: (520, 540),
        title: "Maximum error and storage factor against η".into(),
        caption: vec![format!(
            "Lloyd et al. 2006, Fig. 6 (Eq 9–12), n = {n}, f = {f}, θ = {theta}°, unit \
             resolutions. (a) Unlike the paper, which scales each curve to one linear axis, the \
             values as they are, logarithmic: for η ≤ 0, M_x and M_z run parallel; for η ≥ 0, S̄ \
             is constant while M_x falls and M_z rises (§4.3). (b) M_z on a linear axis: the \
             paper's V, least at η = 0.",
            theta = THETA_DEG
        )],
        charts: vec![c, v],
    })
}

/// Fig 10: S̄ of ZP+W with the light overhead against the number of z-partitions k, for several
/// f/n, each with the optimal logarithmic S̄ (App. C) it tends to.
pub(super) fn fig10() -> Result<Charts, Fail> {
    let theta = THETA_DEG.to_radians();
    let mut c = LineChart::new(
        "(a) S̄; dashed: its optimum",
        // To k = 20: right of the curves' ends (k = 16) each optimum carries its value.
        Axis::integer("number of z-partitions k", 1.0, 20.0),
        Axis::log10("storage factor S̄ (texels per image pixel)", 1.0, 1e4),
    );
    c.legend = SeriesLabelPosition::UpperRight;
    let mut r = LineChart::new(
        "(b) S̄ over its optimum",
        Axis::integer("number of z-partitions k", 1.0, 16.0),
        Axis::log10("S̄ / S̄_{opt}", 0.8, 2000.0),
    );
    r.legend = SeriesLabelPosition::UpperRight;
    let mut optima = Vec::new();
    let ratios = [10.0, 100.0, 1000.0, 10_000.0];
    for (i, ratio) in ratios.into_iter().enumerate() {
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
        let label = format!("f/n = {}", fmt_plain(ratio));
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
        // The asymptote, labelled with its value right of the curves' ends (k = 16), where
        // only the dashed lines run; the legend's last entry says what they are.
        let asymptote = Series::line(
            format!("{opt:.2}"),
            linspace(1.0, 20.0, 77)
                .into_iter()
                .map(|k| (k, opt))
                .collect(),
            PALETTE[i],
        )
        .dashed()
        .reference()
        .direct_at(20.0);
        c.series.push(asymptote);
        optima.push(format!("{opt:.2}"));
    }
    c.series.push(
        Series::line("optimum", Vec::new(), SHARED)
            .dashed()
            .reference(),
    );
    r.series.push(
        Series::line("optimum", vec![(1.0, 1.0), (16.0, 1.0)], SHARED)
            .dashed()
            .reference(),
    );
    Ok(Charts {
        size: (520, 560),
        title: "Storage factor of ZP+W against the number of partitions, light overhead".into(),
        caption: vec![format!(
            "Lloyd et al. 2006, Fig. 10 (Eq 18, App. C), θ = {THETA_DEG}°: S̄ of ZP+W, \
             k((f/n)^{{1/k}} − 1)/(2 tan θ), falls with k towards the optimal logarithmic S̄, \
             ln(f/n)/(2 tan θ) (dashed, its value on it): {} for f/n = {} to {}. (b), not in the \
             paper, divides each curve by its optimum. The paper plots one frustum it does not \
             name.",
            optima.join(", "),
            fmt_plain(ratios[0]),
            fmt_plain(ratios[ratios.len() - 1])
        )],
        charts: vec![c, r],
    })
}

/// Fig 12: S̄ against the number of shadow maps for ZP, ZP+W and FP+ZP+W, light overhead and
/// behind (f/n = 1000, θ = 30°).
///
/// The number of maps of FP+ZP+W is 4k + 1 for both light directions
/// ([`shadow_map_count`] for the light behind): a scheme keeps its maps whatever the light, which
/// is how §5.3 counts them ("only one z-partitioning for every four shadow maps", Eq 23).
/// The depth ratio f/n of Fig 12.
const FIG12_RATIO: f64 = 1000.0;

pub(super) fn fig12() -> Result<Charts, Fail> {
    let ratio = FIG12_RATIO;
    let view = ViewFrustum::new(1.0, ratio, THETA_DEG.to_radians())?;
    // The light-behind crossover: ZP with as many maps as FP+ZP+W with k = 3 and 4 per face.
    let behind = |scheme: Scheme, k: usize| -> Result<f64, crate::Error> {
        scheme_storage_factor(scheme, SchemeLight::Behind, &view, k)
    };
    let (j3, j4) = (
        shadow_map_count(Scheme::FpZpW, SchemeLight::Behind, 3)?,
        shadow_map_count(Scheme::FpZpW, SchemeLight::Behind, 4)?,
    );
    let (zp3, fp3) = (behind(Scheme::Zp, j3)?, behind(Scheme::FpZpW, 3)?);
    let (zp4, fp4) = (behind(Scheme::Zp, j4)?, behind(Scheme::FpZpW, 4)?);
    let mut c = LineChart::new(
        "",
        Axis::integer("number of shadow maps", 0.0, 40.0),
        // To the data: 6.5 (ZP+W at 40 maps) to 10⁶ (ZP behind with one map).
        Axis::log10("S̄ (texels per image pixel)", 3.0, 3e6),
    );
    c.legend = SeriesLabelPosition::UpperRight;
    let schemes = [
        (Scheme::Zp, "ZP", Look::Zp.colour()),
        (Scheme::ZpW, "ZP+W", Look::ZpW.colour()),
        (Scheme::FpZpW, "FP+ZP+W", Look::FpZpW.colour()),
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
                // Defined only at 4k + 1 maps: markers, not joined across the counts between,
                // in FP+ZP+W's green of Fig 13 and the worst-case figure for both lights:
                // triangles overhead, hexagons behind.
                let shape = match light {
                    SchemeLight::Overhead => None,
                    SchemeLight::Behind => Some(Marker::Hexagon),
                };
                Series {
                    width: 3,
                    shape,
                    ..Series::line(format!("{name}, {light_name}"), unjoined(&pts), colour)
                        .with_markers()
                }
            } else {
                // Every count: a line, with a few markers along it (not one per count).
                // Behind, one curve for two schemes: in the neutral colour of shared curves.
                let (name, colour) = match light {
                    SchemeLight::Behind => ("ZP = ZP+W", SHARED),
                    SchemeLight::Overhead => (name, colour),
                };
                Series::line(format!("{name}, {light_name}"), pts, colour)
            };
            c.series.push(match light {
                SchemeLight::Overhead => s,
                SchemeLight::Behind => s.dashed(),
            });
        }
    }
    // (b): the light-behind crossover enlarged, ZP (equal to ZP+W there) against FP+ZP+W.
    let mut zoom = LineChart::new(
        "(b) behind, at the crossover",
        // Padded by half a count, so that the markers at 11 and 23 maps are whole.
        Axis::integer("number of shadow maps", 10.5, 23.5),
        // The data's range (30.8 at 21 maps to 55.0 at 13), a little padded.
        Axis::linear("S̄ (texels per image pixel)", 28.0, 58.0),
    );
    zoom.legend = SeriesLabelPosition::UpperRight;
    for (scheme, name, colour) in [
        (Scheme::Zp, "ZP = ZP+W, behind", SHARED),
        (Scheme::FpZpW, "FP+ZP+W, behind", Look::FpZpW.colour()),
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
            let s = Series::line(name, pts, colour).dashed().with_markers();
            zoom.series.push(Series {
                width: 3,
                shape: Some(Marker::Hexagon),
                ..s
            });
        } else {
            // ZP without markers (at 17 maps its marker lay under FP+ZP+W's, 38.32 against
            // 37.99): the line unlabelled, its legend key a line sample; the values are written.
            zoom.series.push(Series {
                label: None,
                ..Series::line(name, pts, colour).dashed()
            });
            zoom.series
                .push(Series::line(name, Vec::new(), colour).dashed().reference());
        }
    }
    zoom.notes.push(Note {
        // Under the 17-map pair it states, inside the plot in both layouts.
        at: (11.0, 35.0),
        text: format!("{j4} maps: {fp4:.2} < {zp4:.2}"),
        colour: PALETTE[6],
    });
    c.title = "(a) overhead, behind (dashed)".into();
    Ok(Charts {
        size: (520, 560),
        title: "Storage factor against the number of shadow maps".into(),
        caption: vec![format!(
            "Lloyd et al. 2006, Fig. 12 (Eq 17–21), f/n = {ratio}, θ = {THETA_DEG}°. k \
             z-partitions use k maps, FP+ZP+W 4k + 1 (the side faces and the near face; markers \
             only). Behind, ZP+W equals ZP (a square frustum is not warped) and FP+ZP+W is Eq 21 \
             with each face at 45°. (b), not in the paper, enlarges §5.3's crossover: at {j3} maps \
             ZP is lower ({zp3:.1} against {fp3:.1}), at {j4} FP+ZP+W ({fp4:.2} against {zp4:.2})."
        )],
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
            // k, the z-partitions per face, is named in the caption.
            "shadow maps j = 4k + 1",
            3.0,
            43.0,
            5.0,
            4.0,
        ),
        y: Axis::log10("depth ratio f/n", 1.0, 1e6),
    })
}

/// Fig 13's fills, in the colours every figure gives the schemes ([`Look`]): ZP's where
/// z-partitioning is lowest, FP+ZP+W's where face partitioning is, the latter hatched in white
/// ([`HATCH`]) so that the two also read apart in greyscale.
const ZP_FILL: RGBColor = Look::Zp.colour();
const FP_FILL: RGBColor = Look::FpZpW.colour();

/// The spacing of the white diagonal hatching over FP+ZP+W's fill, in units.
const HATCH: i32 = 10;

/// Hatches the pixel rectangle `[x0, x1] × [y0, y1]` of `area` (backend units) with white
/// lines at 45°, [`HATCH`] units apart.
fn hatch<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    (x0, y0): (i32, i32),
    (x1, y1): (i32, i32),
) -> Result<(), Fail> {
    let (bx, by) = area.get_base_pixel();
    let (w, h) = (x1 - x0, y1 - y0);
    if w <= 0 || h <= 0 {
        return Ok(());
    }
    // Lines x − x0 + (y1 − y) = c for c along the diagonal, each clipped to the rectangle.
    let mut c = HATCH / 2;
    while c < w + h {
        let (a, b) = ((c - h).max(0), c.min(w));
        let p = (x0 + a - bx, y1 - (c - a) - by);
        let q = (x0 + b - bx, y1 - (c - b) - by);
        area.draw(&PathElement::new(vec![p, q], WHITE.stroke_width(2)))?;
        c += HATCH;
    }
    Ok(())
}

/// Fig 13's key entries: text and fill (none: the crossover dot).
const FIG13_KEY: [(&str, Option<RGBColor>); 3] = [
    ("ZP lowest", Some(ZP_FILL)),
    ("FP+ZP+W lowest", Some(FP_FILL)),
    ("equal S̄", None),
];

/// Fig 13's key laid out on a row `width` units wide: the entries' widths and the rows (ranges
/// of entries), as many on a row as fit.
fn fig13_key_rows<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    width: i32,
) -> Result<(Vec<i32>, Vec<std::ops::Range<usize>>), Fail> {
    let style = TextStyle::from((FONT, 13).into_font());
    let (swatch, gap, between) = (14, 5, 18);
    let widths = FIG13_KEY
        .iter()
        .map(|(t, _)| {
            area.estimate_text_size(t, &style)
                .map(|s| swatch + gap + s.0 as i32)
        })
        .collect::<Result<Vec<_>, _>>()?;
    let mut rows = Vec::new();
    let (mut start, mut used) = (0, 0);
    for (i, w) in widths.iter().enumerate() {
        if i > start && used + between + w > width {
            rows.push(start..i);
            (start, used) = (i, 0);
        }
        used += if i > start { between } else { 0 } + w;
    }
    rows.push(start..widths.len());
    Ok((widths, rows))
}

/// Height of one row of Fig 13's key.
const KEY_ROW: u32 = 22;

/// Fig 13's key: a swatch of each fill and the crossover dot, each with its meaning, in as few
/// rows as fit, centred, above the chart (it was two boxes inside the chart, over the fills).
fn draw_fig13_key<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
    let style = TextStyle::from((FONT, 13).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
    let (w, _) = area.dim_in_pixel();
    let (widths, rows) = fig13_key_rows(area, w as i32 - 8)?;
    let (swatch, gap, between) = (14, 5, 18);
    for (r, row) in rows.into_iter().enumerate() {
        let y = 4 + (KEY_ROW as i32) * r as i32 + KEY_ROW as i32 / 2;
        let total: i32 = widths[row.clone()].iter().sum::<i32>() + between * (row.len() as i32 - 1);
        let mut x = (w as i32 - total) / 2;
        for i in row {
            let (text, fill) = FIG13_KEY[i];
            match fill {
                Some(c) => {
                    area.draw(&Rectangle::new(
                        [(x, y - swatch / 2), (x + swatch, y + swatch / 2)],
                        c.filled(),
                    ))?;
                    if c == FP_FILL {
                        let (bx, by) = area.get_base_pixel();
                        hatch(
                            area,
                            (x + bx, y - swatch / 2 + by),
                            (x + swatch + bx, y + swatch / 2 + by),
                        )?;
                    }
                    area.draw(&Rectangle::new(
                        [(x, y - swatch / 2), (x + swatch, y + swatch / 2)],
                        RGBColor(120, 120, 120).stroke_width(1),
                    ))?;
                }
                None => area.draw(&Circle::new((x + swatch / 2, y), 4, PALETTE[6].filled()))?,
            }
            area.draw(&Text::new(text, (x + swatch + gap, y), style.clone()))?;
            x += widths[i] + between;
        }
    }
    Ok(())
}

impl Figure for Fig13 {
    fn size(&self) -> (u32, u32) {
        (520, 570)
    }

    /// One column: the chart under a key of two rows, above a caption of about ten lines.
    fn single_size(&self) -> Option<(u32, u32)> {
        Some((Column::Single.width(), 720))
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        // The crossover at k = 4 (17 maps), Fig 12's.
        let j4 = shadow_map_count(Scheme::FpZpW, SchemeLight::Behind, 4)? as f64;
        let (j, at) = self
            .crossover
            .iter()
            .copied()
            .find(|p| p.0 == j4)
            .ok_or_else(|| Fail::Draw(format!("Fig 13 has no crossover at {j4} maps")))?;
        let caption = format!(
            "Lloyd et al. 2006, Fig. 13 (Eq 20, 21), light behind: z-partitioning (ZP, equal to \
             ZP+W behind) with j maps against face partitioning with k warped z-partitions per \
             face, at j = 4k + 1, where both exist: one column per j (the paper draws continuous \
             regions). FP+ZP+W is lower below the dot (equal S̄), ZP above; at {j} maps the dot \
             is at f/n = {at:.0}, just above Fig. 12's {FIG12_RATIO}."
        );
        let body = frame(
            root,
            "Lowest-error partitioning, light behind",
            &[caption.as_str()],
        )?;
        // The key above the chart, where it covers nothing, in as many rows as it needs.
        let rows = fig13_key_rows(&body, body.dim_in_pixel().0 as i32 - 8)?
            .1
            .len() as u32;
        let (key, plot) = body.split_vertically(KEY_ROW * rows + 8);
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
            let (a, b) = (
                chart.backend_coord(&(j - half, mid)),
                chart.backend_coord(&(j + half, y0)),
            );
            hatch(&chart.plotting_area().strip_coord_spec(), a, b)?;
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
#[path = "lloyd2006_tests.rs"]
mod tests;
