//! Lloyd, Tuft, Yoon, Manocha 2006, *Warping and Partitioning for Low Error Shadow Maps*:
//! the closed-form figures (Fig 5, 6, 10, 12, 13). Fig 7 is in [`super::hemisphere`].

use super::chart::FONT;
use super::chart::{
    build_chart, column, fmt_plain, frame, linspace, sweep, Axis, Charts, LineChart, Look, Marker,
    Note, Series, PALETTE, SHARED,
};
use super::keyed::Keyed;
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
pub(super) fn fig5() -> Result<Keyed, Fail> {
    let (n, f) = (1.0, 20.0);
    let view = ViewFrustum::new(n, f, 45f64.to_radians())?;
    let res = Resolutions::default();
    let lispsm = n_prime_lispsm(n, f)?;
    // PSM, LiSPSM and the uniform map in their colours of every figure (Look); the other n′,
    // a sweep, in the sweep's colours.
    let warps = [
        (
            NPrime::finite(1.0)?,
            "n′ = n = 1 (PSM)".to_string(),
            Look::Psm.colour(),
        ),
        (NPrime::finite(2.0)?, "n′ = 2".to_string(), sweep(0, 3)),
        (
            NPrime::finite(lispsm)?,
            format!("n′ ≈ {lispsm:.2} (LiSPSM)"),
            Look::Lispsm.colour(),
        ),
        (NPrime::finite(20.0)?, "n′ = 20".to_string(), sweep(1, 3)),
        (NPrime::finite(100.0)?, "n′ = 100".to_string(), sweep(2, 3)),
        (
            NPrime::UNWARPED,
            "n′ = ∞ (uniform)".to_string(),
            Look::Uniform.colour(),
        ),
    ];
    let zs = linspace(n, f, 160);
    let z_factor = (f - n) / (2.0 * view.tan_half_fov());
    let depth = || Axis::linear("depth z", n, f);
    let mut cx = LineChart::new(
        "(a) x error: m_x(z) / f",
        depth(),
        Axis::log10("m_x / f (log scale)", 0.04, 1.25),
    );
    let mut cz = LineChart::new(
        "(b) z error: m_z(z) · 2 tan θ / (f − n)",
        depth(),
        Axis::log10("m_z · 2 tan θ / (f − n) (log scale)", 0.04, 1.25),
    );
    for (i, (np, label, colour)) in warps.iter().enumerate() {
        let x = |z: f64| Ok((z, mx(n, f, *np, z, res)? / f));
        let y = |z: f64| Ok((z, mz(&view, *np, z, res)? / z_factor));
        let line = |g: &dyn Fn(f64) -> Result<(f64, f64), crate::Error>| {
            zs.iter().map(|&z| g(z)).collect::<Result<Vec<_>, _>>()
        };
        // Each curve's shape at three depths of its own (staggered, so that the shapes of
        // curves that meet do not coincide) and none beyond z = 15, where all of (a) meet.
        let at: Vec<f64> = FIG5_MARKS.iter().map(|z| z + 0.5 * i as f64).collect();
        let marks = |g: &dyn Fn(f64) -> Result<(f64, f64), crate::Error>| -> Result<Series, Fail> {
            let pts = at.iter().map(|&z| g(z)).collect::<Result<Vec<_>, _>>()?;
            Ok(Series {
                label: None,
                ..Series::line("", unjoined(&pts), *colour).with_markers()
            })
        };
        cx.series.push(Series {
            label: None,
            ..Series::line("", line(&x)?, *colour)
        });
        cx.series.push(marks(&x)?);
        // The curves labelled once, in (b), at the far plane: the labels name (a)'s curves
        // of the same colour and shape too. n′ = 100 runs too near n′ = ∞ there for a label
        // between them: its label goes above it, under n′ = 20, near z = f.
        let z_line = Series::line(label.clone(), line(&y)?, *colour).reference();
        if *label == "n′ = 100" {
            // The note's top left: a little under n′ = 20, which lies at 1.5 times n′ = 100
            // there (0.1 against 0.066).
            let own = y(FIG5_NOTE_Z)?.1;
            cz.notes.push(Note {
                at: (FIG5_NOTE_Z - 1.5, own * 1.4),
                text: label.clone(),
                colour: *colour,
            });
            cz.series.push(Series {
                label: None,
                ..z_line
            });
        } else {
            cz.series.push(z_line.direct());
        }
        cz.series.push(marks(&y)?);
    }
    let nb = |t: &str| t.replace(' ', "\u{a0}");
    Ok(Keyed {
        page: Charts {
            size: (520, 540),
            title: "Error distribution along the view frustum, light overhead".into(),
            caption: vec![format!(
                "Lloyd et al. 2006, Fig. 5 (Eq 7, 8), {}, {}: the terms that vary with z, m_x \
                 over f and m_z over {}, as the paper plots them; the labels in (b) name the \
                 curves of both panels. m_x is largest at {}; m_z at {} for {} and at {} \
                 beyond.",
                nb(&format!("n = {n}")),
                nb(&format!("f = {f}")),
                nb("(f − n)/(2 tan θ)"),
                nb("z = n"),
                nb("z = f"),
                nb("n′ ≤ n + √(fn)"),
                nb("z = n"),
            )],
            charts: vec![cx, cz],
        },
        key: None,
        single_caption: Some(format!(
            "Lloyd et al. 2006, Fig. 5 (Eq 7, 8), {}, {}: the terms of m_x and m_z that vary \
             with z; the labels in (b) also name the curves\u{a0}of\u{a0}(a).",
            nb(&format!("n = {n}")),
            nb(&format!("f = {f}")),
        )),
    })
}

/// The depths of Fig 5 where the first curve carries its marker (each next curve's half a
/// unit further).
const FIG5_MARKS: [f64; 3] = [1.8, 4.5, 11.5];

/// The depth near which Fig 5 (b) writes the label of n′ = 100.
const FIG5_NOTE_Z: f64 = 17.5;

/// Fig 6: M_x, M_z and S̄ against η ∈ [−1, 1] (n = 1, f = 100, θ = 30°, unit resolutions), as
/// they are, on a logarithmic axis (the paper normalises each to fit one linear scale, which puts
/// M_x under M_z for η ≤ 0 and the flat S̄ for η ≥ 0 on the x axis).
pub(super) fn fig6() -> Result<Keyed, Fail> {
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
        Axis::log10("M_x, M_z, S̄ (log scale)", 0.5, 2e4).in_powers(),
    );
    c.legend = SeriesLabelPosition::LowerLeft;
    // M_x, M_z and S̄ are quantities of one scheme: a sweep's colours, not schemes'; M_z and S̄
    // dashed and dotted, so that the lines that meet differ in more than hue.
    let quantity = |i: usize| sweep(i, 3);
    c.series.push(Series::line(
        format!("M_x (maximum {})", fmt_plain(top_x)),
        m_x,
        quantity(0),
    ));
    c.series.push(
        Series::line(
            format!("M_z (maximum {})", fmt_plain(top_z)),
            m_z.clone(),
            quantity(1),
        )
        .dashed(),
    );
    // (b): M_z on a linear axis, where its V (linear in η on each side of 0, App. B) shows.
    let mut v = LineChart::new(
        "(b) M_z, linear: the V",
        c.x.clone(),
        Axis::linear("M_z", 0.0, 1.05 * top_z),
    );
    // No legend: the panel's title names its one curve.
    v.series.push(Series {
        label: None,
        ..Series::line("M_z", m_z, quantity(1)).dashed()
    });
    v.legend = SeriesLabelPosition::UpperMiddle;
    c.title = "(a) as they are, logarithmic".into();
    c.series.push(
        Series::line(
            format!("S̄ = M_x M_z (maximum {})", fmt_plain(top_s)),
            s,
            quantity(2),
        )
        .dotted(),
    );
    let config = format!(
        "{}, {}, {}°",
        format!("n = {n}").replace(' ', "\u{a0}"),
        format!("f = {f}").replace(' ', "\u{a0}"),
        format!("θ = {THETA_DEG}").replace(' ', "\u{a0}"),
    );
    Ok(Keyed {
        page: Charts {
            size: (520, 540),
            title: "Maximum error and storage factor against η".into(),
            caption: vec![format!(
                "Lloyd et al. 2006, Fig. 6 (Eq 9–12), {config}, image and shadow map of equal \
                 resolution. (a) Unlike the paper, which scales each curve to one linear axis, \
                 the values as they are: for η\u{a0}≤\u{a0}0, M_x and M_z run parallel; for \
                 η\u{a0}≥\u{a0}0, S̄ is constant while M_x falls and M_z rises (§4.3). (b) M_z \
                 on a linear axis: the paper's V, least at η\u{a0}=\u{a0}0."
            )],
            charts: vec![c, v],
        },
        key: Some(0),
        single_caption: Some(format!(
            "Lloyd et al. 2006, Fig. 6 (Eq 9–12), {config}: (a) the values as they are (the \
             paper scales each to one linear axis); (b) M_z, least at η\u{a0}=\u{a0}0."
        )),
    })
}

/// Fig 10: S̄ of ZP+W with the light overhead against the number of z-partitions k, for several
/// f/n (a sweep: [`sweep`]'s colours), each with the optimal logarithmic S̄ (App. C) it tends
/// to, drawn grey and dashed and given in the key.
pub(super) fn fig10() -> Result<Keyed, Fail> {
    let theta = THETA_DEG.to_radians();
    // Both panels over the same k, with the same ticks.
    let k_axis = || Axis::integer("number of z-partitions k", 1.0, 16.0);
    let mut c = LineChart::new(
        "(a) S̄, dashed: its optimum",
        k_axis(),
        Axis::log10("S̄ (texels per image pixel, log scale)", 1.0, 1e4).in_powers(),
    );
    let mut r = LineChart::new(
        "(b) S̄ over its optimum",
        k_axis(),
        Axis::log10("S̄ / S̄_{opt} (log scale)", 0.8, 2000.0).in_powers(),
    );
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
        let colour = sweep(i, ratios.len());
        // A marker on a few k of each line (one on every k ran together into a chain).
        let label = format!(
            "f/n\u{a0}=\u{a0}{}, S̄_{{opt}}\u{a0}=\u{a0}{opt:.2}",
            fmt_plain(ratio)
        );
        c.series
            .push(Series::line(label.clone(), pts.clone(), colour));
        r.series.push(Series::line(
            label,
            pts.iter().map(|&(k, v)| (k, v / opt)).collect(),
            colour,
        ));
        // The optimum the curve tends to, grey: its value is in the key.
        c.series.push(Series {
            label: None,
            ..Series::line("", vec![(1.0, opt), (16.0, opt)], SHARED)
                .dashed()
                .reference()
        });
        optima.push(format!("{opt:.2}"));
    }
    c.series.push(
        Series::line("optimum S̄_{opt}", Vec::new(), SHARED)
            .dashed()
            .reference(),
    );
    r.series.push(Series {
        label: None,
        ..Series::line("", vec![(1.0, 1.0), (16.0, 1.0)], SHARED)
            .dashed()
            .reference()
    });
    let (lo, hi) = (fmt_plain(ratios[0]), fmt_plain(ratios[ratios.len() - 1]));
    Ok(Keyed {
        page: Charts {
            size: (520, 560),
            title: "S̄ of ZP+W against the number of z-partitions".into(),
            caption: vec![format!(
                "Lloyd et al. 2006, Fig. 10 (Eq 18, App. C), θ\u{a0}=\u{a0}{THETA_DEG}°, light \
                 overhead: S̄ of ZP+W, k((f/n)^{{1/k}}\u{a0}−\u{a0}1)/(2\u{a0}tan\u{a0}θ), falls \
                 with k towards the optimal logarithmic S̄_{{opt}}\u{a0}=\u{a0}ln(f/n)/\
                 (2\u{a0}tan\u{a0}θ) (grey, dashed): {} for f/n\u{a0}=\u{a0}{lo} to {hi}. \
                 (b), not in the paper, divides each curve by its S̄_{{opt}}. The paper plots \
                 one frustum it does not name.",
                optima.join(", "),
            )],
            charts: vec![c, r],
        },
        key: Some(0),
        single_caption: Some(format!(
            "Lloyd et al. 2006, Fig. 10 (Eq 18, App. C), θ\u{a0}=\u{a0}{THETA_DEG}°: S̄ of ZP+W \
             falls with k towards S̄_{{opt}}\u{a0}=\u{a0}ln(f/n)/(2\u{a0}tan\u{a0}θ) (dashed). \
             (b), not in the paper: S̄/S̄_{{opt}}."
        )),
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

pub(super) fn fig12() -> Result<Keyed, Fail> {
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
    // ZP with one map, far above the rest (10⁶ behind): off the scale, its value written.
    let zp1 = (
        scheme_storage_factor(Scheme::Zp, SchemeLight::Overhead, &view, 1)?,
        behind(Scheme::Zp, 1)?,
    );
    let mut c = LineChart::new(
        "(a) overhead, behind (dashed)",
        Axis::integer("number of shadow maps", 0.0, 40.0),
        // To the data from 2 maps on: 6.5 (ZP+W at 40 maps) to 2000 (ZP behind with 2 maps).
        Axis::log10("S̄ (texels per image pixel, log scale)", 4.0, 1e4).in_powers(),
    );
    let schemes = [
        (Scheme::Zp, "ZP", Look::Zp.colour()),
        (Scheme::ZpW, "ZP+W", Look::ZpW.colour()),
        (Scheme::FpZpW, "FP+ZP+W", Look::FpZpW.colour()),
    ];
    // Behind, ZP+W equals ZP (a square frustum cannot be warped): one line. It comes last, so
    // that its few markers fall on other counts than ZP overhead's.
    let series = [
        (Scheme::Zp, SchemeLight::Overhead),
        (Scheme::ZpW, SchemeLight::Overhead),
        (Scheme::FpZpW, SchemeLight::Overhead),
        (Scheme::FpZpW, SchemeLight::Behind),
        (Scheme::Zp, SchemeLight::Behind),
    ];
    for (scheme, light) in series {
        let (_, name, colour) = schemes
            .into_iter()
            .find(|s| s.0 == scheme)
            .ok_or_else(|| Fail::Draw(format!("Fig 12 has no {scheme:?}")))?;
        let light_name = match light {
            SchemeLight::Behind => "behind",
            SchemeLight::Overhead => "overhead",
        };
        let mut pts = Vec::new();
        for k in 1..=40usize {
            let maps = shadow_map_count(scheme, SchemeLight::Behind, k)?;
            if maps > 40 {
                break;
            }
            pts.push((maps as f64, scheme_storage_factor(scheme, light, &view, k)?));
        }
        let s = if scheme == Scheme::FpZpW {
            // Defined only at 4k + 1 maps: markers, not joined across the counts between, in
            // FP+ZP+W's green of Fig 13 and the worst-case figure for both lights: triangles
            // overhead, hexagons behind.
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
        } else if light == SchemeLight::Behind {
            // One curve for two schemes, in the neutral colour of shared curves, dashed and
            // without markers, as in (b): its key is a line sample.
            c.series.push(Series {
                label: None,
                ..Series::line("", pts, SHARED).dashed()
            });
            Series::line("ZP = ZP+W, behind", Vec::new(), SHARED).reference()
        } else {
            // Every count: a line, with a few markers along it (not one per count).
            Series::line(format!("{name}, {light_name}"), pts, colour)
        };
        c.series.push(match light {
            SchemeLight::Overhead => s,
            SchemeLight::Behind => s.dashed(),
        });
    }
    // (b): the light-behind crossover enlarged, ZP (equal to ZP+W there) against FP+ZP+W.
    let mut zoom = LineChart::new(
        "(b) behind, at the crossover",
        // Padded by half a count, so that the markers at 11 and 23 maps are whole.
        Axis::integer("number of shadow maps", 10.5, 23.5),
        // The data's range (30.8 at 21 maps to 55.0 at 13), a little padded.
        Axis::linear("S̄ (texels per image pixel)", 28.0, 58.0),
    );
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
        if scheme == Scheme::FpZpW {
            let s = Series::line(name, unjoined(&pts), colour)
                .dashed()
                .with_markers();
            zoom.series.push(Series {
                width: 3,
                shape: Some(Marker::Hexagon),
                ..s
            });
        } else {
            // ZP without markers, as in (a) (at 17 maps its marker lay under FP+ZP+W's, 38.32
            // against 37.99): the values are written.
            zoom.series.push(Series {
                label: None,
                ..Series::line(name, pts, colour).dashed()
            });
        }
    }
    zoom.notes.push(Note {
        // Under the 17-map pair it states, inside the plot in both layouts.
        at: (11.0, 35.0),
        text: format!("{j4} maps: {fp4:.2} < {zp4:.2}"),
        colour: PALETTE[6],
    });
    let nb = |t: &str| t.replace(' ', "\u{a0}");
    Ok(Keyed {
        page: Charts {
            size: (520, 560),
            title: "Storage factor against the number of shadow maps".into(),
            caption: vec![format!(
                "Lloyd et al. 2006, Fig. 12 (Eq 17–21), {}, {}°. k z-partitions use k maps, \
                 FP+ZP+W {} (markers only). Behind, ZP+W equals ZP (a square frustum is not \
                 warped); FP+ZP+W is Eq 21, each face at 45°. Off the scale: ZP with 1 map, {} \
                 ({} behind). (b), not in the paper: at {j3} maps ZP is lower ({zp3:.1} against \
                 {fp3:.1}), at {j4} FP+ZP+W ({fp4:.2} against {zp4:.2}).",
                nb(&format!("f/n = {ratio}")),
                nb(&format!("θ = {THETA_DEG}")),
                nb("4k + 1"),
                sci(zp1.0),
                sci(zp1.1),
            )],
            charts: vec![c, zoom],
        },
        key: Some(0),
        single_caption: Some(format!(
            "Lloyd et al. 2006, Fig. 12 (Eq 17–21), {}, {}°. FP+ZP+W uses {} maps. (b), not in \
             the paper: at {j4} maps FP+ZP+W is lower ({fp4:.2} against {zp4:.2}).",
            nb(&format!("f/n = {ratio}")),
            nb(&format!("θ = {THETA_DEG}")),
            nb("4k + 1"),
        )),
    })
}

/// `v` as a caption prints it: m×10^{e} with three significant digits, or 10^{e} for a power
/// of ten.
fn sci(v: f64) -> String {
    let e = v.log10().floor();
    let m = v / 10f64.powf(e);
    if (m - 1.0).abs() < 5e-4 {
        format!("10^{{{e}}}")
    } else {
        format!("{m:.2}×10^{{{e}}}")
    }
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

/// The spacing of the white diagonal hatching over FP+ZP+W's fill, in units (coarse, so that
/// print halftoning keeps it), and its lines' width.
const HATCH: i32 = 16;
const HATCH_WIDTH: u32 = 3;

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
        area.draw(&PathElement::new(
            vec![p, q],
            WHITE.stroke_width(HATCH_WIDTH),
        ))?;
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
/// rows as fit, centred, below the chart (it was two boxes inside the chart, over the fills).
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
        // The first j whose crossover lies above the axis (its column is FP+ZP+W's to the top).
        let above = self
            .crossover
            .iter()
            .find(|p| self.y.to_axis(p.1).is_some_and(|a| a > self.y.range().1))
            .map(|p| p.0);
        let beyond = |prefix: &str| match above {
            Some(j) => format!(
                "{prefix}from j\u{a0}=\u{a0}{j} on, the dot lies above f/n\u{a0}=\u{a0}{}.",
                sci(self.y.max)
            ),
            None => ".".into(),
        };
        let caption = match column() {
            Column::Double => format!(
                "Lloyd et al. 2006, Fig. 13 (Eq 20, 21), light behind: z-partitioning (ZP; ZP+W \
                 equals it behind) with j maps against face partitioning, k warped z-partitions \
                 per face, at j\u{a0}=\u{a0}4k\u{a0}+\u{a0}1 (one column per j; the paper \
                 draws regions). FP+ZP+W is lower below the dot (equal S̄), ZP above; at {j} \
                 maps the dot is at f/n\u{a0}=\u{a0}{at:.0}, just above Fig. 12's \
                 {FIG12_RATIO}{}",
                beyond("; ")
            ),
            Column::Single => format!(
                "Lloyd et al. 2006, Fig. 13 (Eq 20, 21), light behind: ZP with j maps against \
                 FP+ZP+W with j\u{a0}=\u{a0}4k\u{a0}+\u{a0}1, lower below the dot \
                 ({j} maps: f/n\u{a0}=\u{a0}{at:.0}){}",
                beyond("; ")
            ),
        };
        let body = frame(
            root,
            "Lowest-error partitioning, light behind",
            &[caption.as_str()],
        )?;
        // The key below the chart, where every figure has its key, in as many rows as it needs.
        let rows = fig13_key_rows(&body, body.dim_in_pixel().0 as i32 - 8)?
            .1
            .len() as u32;
        let h = body.dim_in_pixel().1;
        let (plot, key) = body.split_vertically(h.saturating_sub(KEY_ROW * rows + 8));
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
