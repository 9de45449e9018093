//! Lloyd, Tuft, Yoon, Manocha 2006, *Warping and Partitioning for Low Error Shadow Maps*:
//! the closed-form figures (Fig 5, 6, 10, 12, 13). Fig 7 is in [`super::hemisphere`].

use super::chart::{
    fmt_plain, linspace, sweep, Axis, Charts, LineChart, Look, Marker, Note, Series, PALETTE,
    SHARED,
};
use super::keyed::{Keyed, SINGLE_HEIGHT};
#[cfg(test)]
use super::Figure;
use super::{Column, Fail};
use crate::analytic::eta::{n_prime_from_eta, n_prime_lispsm};
use crate::analytic::overhead::{max_mx, max_mz, mx, mz, storage_factor};
use crate::analytic::partition::{scheme_storage_factor, Scheme, SchemeLight};
use crate::{NPrime, Resolutions, ViewFrustum};
use plotters::prelude::*;

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
    let nb = |t: &str| t.replace(' ', "\u{a0}");
    let lispsm = n_prime_lispsm(n, f)?;
    let (cx, cz) = fig5_panels(n, f, Column::Double)?;
    let double = Charts {
        size: (520, 570),
        title: "Error distribution along the view frustum, light overhead".into(),
        caption: vec![format!(
            "Lloyd et al. 2006, Fig. 5 (Eq 7, 8), {}, {}, image and shadow map of equal \
             resolution: the terms that vary with z, m_x \
             over f and m_z over {}, as the paper plots them. m_x is largest at {}; m_z at \
             {} for {} (LiSPSM's) and at {} beyond.",
            nb(&format!("n = {n}")),
            nb(&format!("f = {f}")),
            nb("(f − n)/(2 tan θ)"),
            nb("z = n"),
            nb("z = f"),
            nb(&format!("n′ ≤ n + √(fn) ≈ {lispsm:.2}")),
            nb("z = n"),
        )],
        charts: vec![cx, cz],
    };
    let (cx, cz) = fig5_panels(n, f, Column::Single)?;
    let single = Charts {
        size: (Column::Single.width(), SINGLE_HEIGHT),
        title: "Error along the view frustum".into(),
        caption: vec![format!(
            "Lloyd et al. 2006, Fig. 5 (Eq 7, 8), light overhead, {}, {}, image and map of \
             equal resolution: m_x over f, m_z \
             over {}. PSM has {}, LiSPSM {}.",
            nb(&format!("n = {n}")),
            nb(&format!("f = {f}")),
            nb("(f − n)/(2 tan θ)"),
            nb("n′ = n"),
            nb(&format!("n′ = n + √(fn) ≈ {lispsm:.2}")),
        )],
        charts: vec![cx, cz],
    };
    Ok(Keyed {
        single: Some(Box::new(Keyed::new(single, Some(1)))),
        ..Keyed::new(double, Some(1))
    })
}

/// Fig 5's panels (a), m_x / f, and (b), m_z · 2 tan θ / (f − n), for the page `layout`: (b)
/// carries the key of both, which the page writes below them.
fn fig5_panels(n: f64, f: f64, layout: Column) -> Result<(LineChart, LineChart), Fail> {
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
    // Labelled at 5×10⁻², 10⁻¹, 2×10⁻¹ and 10⁰ (the fifth review: at the decades alone the
    // 1.3 decades drawn could not be read, PSM's level 0.05 included).
    let y = |name: &str, lo: f64, hi: f64| {
        Axis::log10(name, lo, hi)
            .labelled_at(&FIG5_Y_LABELS)
            .in_powers()
    };
    let mut cx = LineChart::new(
        "(a) x error: m_x(z) / f",
        depth(),
        y("m_x / f (log scale)", 0.04, 1.25),
    );
    let mut cz = LineChart::new(
        "(b) z error: m_z(z) · 2 tan θ / (f − n)",
        depth(),
        y("m_z · 2 tan θ / (f − n) (log scale)", 0.04, 1.25),
    );
    cx.y_label_area = Some(FIG5_Y_LABEL_AREA);
    cz.y_label_area = Some(FIG5_Y_LABEL_AREA);
    // The key's six entries in two rows of three, in the curves' order at z = f, top to
    // bottom (PSM, n′ = 2, LiSPSM; n′ = 20, n′ = 100, n′ = ∞).
    cz.legend_columns = Some(3);
    if layout == Column::Single {
        // The panels' titles give the quantities, the axes' names no longer than their plots,
        // each with its scale (seventh review, R7-X-1, R7-2006f5-1); the data's range (0.05
        // to 1) a little padded. The margins are small: the plots' height for the names.
        cx.y = y(FIG5_SINGLE_Y[0], 0.045, 1.1);
        cz.y = y(FIG5_SINGLE_Y[1], 0.045, 1.1);
        for c in [&mut cx, &mut cz] {
            c.title.push_str(", log scale");
        }
        cx.margin = Some(FIG5_SINGLE_MARGIN);
        cz.margin = Some(FIG5_SINGLE_MARGIN);
    }
    let mut keys = Vec::new();
    for (i, (np, label, colour)) in warps.iter().enumerate() {
        let x = |z: f64| Ok((z, mx(n, f, *np, z, res)? / f));
        let y = |z: f64| Ok((z, mz(&view, *np, z, res)? / z_factor));
        let line = |g: &dyn Fn(f64) -> Result<(f64, f64), crate::Error>| {
            zs.iter().map(|&z| g(z)).collect::<Result<Vec<_>, _>>()
        };
        // The sweep (n′ = 2, 20, 100) dashed, the warps solid: each sweep step lies within
        // 15 L* of a warp's colour (n′ = 2 by PSM, 20 by LiSPSM, 100 by the uniform map; sixth
        // review, X-10, R6-lloyd2006-fig5-1). n′ = 100 with diamonds (it had left-pointing
        // triangles against ∞'s downward ones).
        let dashed = FIG5_SWEEP.contains(&i);
        let style = |s: Series| {
            let s = if dashed { s.dashed() } else { s };
            Series {
                shape: (i == FIG5_DIAMONDS).then_some(Marker::Diamond).or(s.shape),
                ..s
            }
        };
        // Each curve's shape at three depths of its own in each panel ([`FIG5_MARKS`]).
        let marks = |g: &dyn Fn(f64) -> Result<(f64, f64), crate::Error>,
                     at: &[f64]|
         -> Result<Series, Fail> {
            let pts = at.iter().map(|&z| g(z)).collect::<Result<Vec<_>, _>>()?;
            Ok(Series {
                label: None,
                ..Series::line("", unjoined(&pts), *colour).with_markers()
            })
        };
        let marks = |g: &dyn Fn(f64) -> Result<(f64, f64), crate::Error>, panel: usize| {
            marks(g, FIG5_MARKS[panel][i]).map(style)
        };
        cx.series.push(style(Series {
            label: None,
            ..Series::line("", line(&x)?, *colour)
        }));
        cx.series.push(marks(&x, 0)?);
        // One key below both panels names the curves of both, each entry with its curve's
        // line and marker: near z = f, LiSPSM, n′ = 20, n′ = 100 and n′ = ∞ run too close for
        // labels by the curves (the fourth review: "n′ = 100" read as n′ = 20's). Across two
        // columns the entries give PSM's and LiSPSM's n′; one column names them short (their
        // n′ in the caption).
        cz.series.push(style(Series {
            label: None,
            ..Series::line("", line(&y)?, *colour).reference()
        }));
        let name = match layout {
            Column::Double => label.as_str(),
            Column::Single => FIG5_SHORT[i],
        };
        keys.push(style(Series {
            sample: true,
            ..Series::line(name, Vec::new(), *colour)
        }));
        cz.series.push(marks(&y, 1)?);
    }
    cz.series.extend(keys);
    Ok((cx, cz))
}

/// Fig 5's curves as the one-column key names them.
const FIG5_SHORT: [&str; 6] = ["PSM", "n′ = 2", "LiSPSM", "n′ = 20", "n′ = 100", "n′ = ∞"];

/// The depths of Fig 5's markers, (a) and (b), for each curve (PSM, n′ = 2, LiSPSM, n′ = 20,
/// n′ = 100, n′ = ∞): one or two where the curves are far apart (z < 3.6), the others at
/// least 1.5 units of z from any other curve's where the curves run close. None in (b)'s
/// crossings (z from 4 to 8.5, where the fifth review found five markers on one another), and
/// none in (a) beyond z = 13, where all of (a) meet 1/f.
const FIG5_MARKS: [[&[f64]; 6]; 2] = [
    [
        &[1.3, 13.0],
        &[1.75, 4.0],
        &[2.2, 5.5],
        &[2.65, 8.5],
        &[2.0, 7.0],
        &[3.5, 10.0, 11.5],
    ],
    [
        &[1.3, 8.6, 11.8],
        &[1.6, 9.05, 12.25],
        &[2.3, 9.5, 12.7],
        &[2.65, 13.5, 17.5],
        &[2.0, 15.0, 18.0],
        &[3.8, 16.5, 19.5],
    ],
];

/// Fig 5's sweep curves, drawn dashed: n′ = 2, 20 and 100.
const FIG5_SWEEP: [usize; 3] = [1, 3, 4];

/// The curve of Fig 5 with diamonds: n′ = 100 (its colour and n′ = ∞'s print as one grey).
const FIG5_DIAMONDS: usize = 4;

/// Where Fig 5's log axes are labelled: 5×10⁻² (PSM's level), 10⁻¹, 2×10⁻¹ and 10⁰.
const FIG5_Y_LABELS: [f64; 4] = [0.05, 0.1, 0.2, 1.0];

/// Room for "5×10⁻²" beside Fig 5's axis names, in units.
const FIG5_Y_LABEL_AREA: u32 = 76;

/// Fig 5's y names in one column, as short as the plots need (the normalised names, "m_x / f"
/// and "m_z 2 tan θ / (f − n)", are longer than the one-column axes; the panels' titles give
/// them, and the caption what each is divided by); the titles say that the scale is log, where
/// the names have no room for it (seventh review, R7-X-1, R7-2006f5-1).
const FIG5_SINGLE_Y: [&str; 2] = ["x error", "z error"];

/// The margin round each of Fig 5's one-column panels, in units (the default's 8 left the
/// plots shorter than their axes' names).
const FIG5_SINGLE_MARGIN: u32 = 2;

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
        Axis::log10(FIG6_Y, 0.5, 2e4).in_powers(),
    );
    c.legend = SeriesLabelPosition::LowerLeft;
    // Three quantities, three hues (the fifth review: M_x and M_z were two dark purples that
    // overlap for η ≤ 0, S̄ a pale dotted lilac), none a scheme's ([`FIG6_LOOKS`]); the key in
    // the axis name's order, M_x, M_z, S̄. Each line carries its markers at η values of its own
    // ([`FIG6_MARKS`]), so that where two lines meet (M_x and M_z for η ≤ 0, M_z and S̄ for
    // η ≥ 0.8) their markers do not.
    let lines = [("M_x", m_x), ("M_z", m_z), ("S̄ = M_x M_z", s)];
    let mut keys = Vec::new();
    for (((name, pts), (colour, dash)), marks) in lines.into_iter().zip(FIG6_LOOKS).zip(FIG6_MARKS)
    {
        let style = |s: Series| match dash {
            0 => s,
            1 => s.dashed(),
            _ => s.dotted(),
        };
        let at: Vec<(f64, f64)> = marks
            .iter()
            .filter_map(|&eta| {
                pts.iter()
                    .min_by(|a, b| (a.0 - eta).abs().total_cmp(&(b.0 - eta).abs()))
                    .copied()
            })
            .collect();
        c.series.push(style(Series {
            label: None,
            ..Series::line("", pts, colour)
        }));
        // S̄'s markers squares (seventh review, R7-2006f6-2: its colour's tall bar read as a
        // tick or an error bar).
        let shape = (name.starts_with("S̄")).then_some(Marker::Square);
        c.series.push(Series {
            label: None,
            shape,
            ..Series::line("", unjoined(&at), colour).with_markers()
        });
        keys.push(style(Series {
            sample: true,
            shape,
            ..Series::line(name, Vec::new(), colour)
        }));
    }
    c.series.extend(keys);
    let nb = |t: String| t.replace(' ', "\u{a0}");
    let config = format!(
        "{}, {}, {}°",
        nb(format!("n = {n}")),
        nb(format!("f = {f}")),
        nb(format!("θ = {THETA_DEG}")),
    );
    let maxima = format!(
        "{}, {} and {}",
        nb(format!("M_x = {}", fmt_plain(top_x))),
        nb(format!("M_z = {}", fmt_plain(top_z))),
        nb(format!("S̄ = {}", fmt_plain(top_s))),
    );
    // One panel in both forms (the fifth review: a second panel of M_z on a linear axis took
    // half the figure to show the V that the log scale shows), no letter; its axis names the
    // scale. One title in both forms, S̄ as in the key (sixth review: "storage factor" in one).
    let double = Charts {
        size: FIG6_SIZE,
        title: FIG6_TITLE.into(),
        caption: vec![format!(
            "Lloyd et al. 2006, Fig. 6 (Eq 9–12), {config}, image and shadow map of equal \
             resolution, on a log scale (the paper scales each curve to one linear axis); \
             largest at η\u{a0}=\u{a0}−1: {maxima}. M_x and M_z run parallel for \
             η\u{a0}≤\u{a0}0; beyond, M_x falls as M_z rises, and S̄ stays constant (§4.3). \
             M_z is least at η\u{a0}=\u{a0}0."
        )],
        charts: vec![c.clone()],
    };
    let single = Charts {
        size: (Column::Single.width(), SINGLE_HEIGHT),
        title: FIG6_TITLE.into(),
        caption: vec![format!(
            "Lloyd et al. 2006, Fig. 6 (Eq 9–12), {config}, equal resolutions, on a log scale \
             (the paper scales each to one linear axis); largest at η\u{a0}=\u{a0}−1: {maxima}; M_z \
             least at η\u{a0}=\u{a0}0."
        )],
        charts: vec![c],
    };
    Ok(Keyed {
        key_inside: true,
        single: Some(Box::new(Keyed {
            key_inside: true,
            ..Keyed::new(single, Some(0))
        })),
        ..Keyed::new(double, Some(0))
    })
}

/// Fig 6's size across two columns: one panel, its plot about 0.7 as tall as wide (as tall
/// as its axis' name).
const FIG6_SIZE: (u32, u32) = (520, 490);

/// Fig 6's title, one in both forms: S̄ named in words (seventh review, R7-X-4, R7-2006f6-1).
const FIG6_TITLE: &str = "Maximum error and storage factor S̄ against η";

/// Fig 6's y axis, one in both forms: the errors, per-axis size ratios without a unit (the
/// sixteenth and seventeenth reviews, R16-, R17-lloyd2006-fig6-1: "M_x, M_z; S̄ (texels per
/// image pixel, log scale)" gave them S̄'s unit), and S̄ with its unit as lloyd2006-fig10,
/// -fig12 and -worst-case give it (R7-2006f6-1). The scale, for which the name has no room
/// beside "(ratios)" (it ran past the axis' ends), is in the powers of ten and in the caption,
/// "on a log scale" (R7-X-1).
const FIG6_Y: &str = "M_x, M_z (ratios); S̄ (texels per image pixel)";

/// Fig 6's lines M_x, M_z and S̄: colour and dash (0 solid, 1 dashed, 2 dotted). M_x the
/// sweep's darkest purple (L* 18), M_z pink (L* 61, as barroso-fig7's least M_z), S̄ black: three
/// hues, and where two lines meet (M_x and M_z, M_z and S̄) their greys are 43 and 61 L* apart.
const FIG6_LOOKS: [(RGBColor, u8); 3] = [
    (super::chart::SWEEP[0], 0),
    (PALETTE[3], 1),
    (PALETTE[6], 2),
];

/// The η of Fig 6's markers on M_x, M_z and S̄: M_x's and M_z's apart where they run together
/// (η ≤ 0), and S̄'s none where it meets M_z (η ≥ 0.8; R7-2006f6-2: at 0.95 its marker lay on
/// M_z's line), between M_z's.
const FIG6_MARKS: [[f64; 4]; 3] = [
    [-0.9, -0.45, 0.3, 0.8],
    [-0.7, -0.25, 0.45, 0.7],
    [-0.8, -0.35, 0.15, 0.6],
];

/// Fig 10: S̄ of ZP+W with the light overhead against the number of z-partitions k, for several
/// f/n (a sweep: [`sweep`]'s colours), each with the optimal logarithmic S̄ (App. C) it tends
/// to, dashed in its curve's colour and given in the key.
pub(super) fn fig10() -> Result<Keyed, Fail> {
    let (a, b, optima) = fig10_panels()?;
    let ratios = FIG10_RATIOS;
    let (lo, hi) = (ratio_text(ratios[0]), ratio_text(ratios[ratios.len() - 1]));
    let double = Charts {
        size: (520, 540),
        title: "S̄ of ZP+W against the number of z-partitions".into(),
        caption: vec![format!(
            "Lloyd et al. 2006, Fig. 10 (Eq 18, App. C), θ\u{a0}=\u{a0}{THETA_DEG}°, light \
             overhead: S̄ of ZP+W, k((f/n)^{{1/k}}\u{a0}−\u{a0}1)/(2\u{a0}tan\u{a0}θ), falls \
             with k towards the optimal S̄_{{opt}}\u{a0}=\u{a0}ln(f/n)/\
             (2\u{a0}tan\u{a0}θ) (dashed, same colour): {} for \
             f/n\u{a0}=\u{a0}{lo} to {hi}. (b), not in the paper: S̄/S̄_{{opt}}, and \
             S̄\u{a0}=\u{a0}S̄_{{opt}} dashed. The paper does not state the f/n of its curve.",
            optima.join(", "),
        )],
        charts: vec![a, b],
    };
    // One column: (a) alone, on the same axes (the fourth review: cut at 10³, f/n = 10⁴'s
    // curve left the plot at k = 1, 8.66×10³); its caption describes only what it draws (the
    // eleventh review, R11-lloyd2006-fig10-1, R11-X-3: no "(b) … left out").
    let (mut a, _, _) = fig10_panels()?;
    // The y axis' name no longer than its plot; the title says that the scale is log (seventh
    // review, R7-X-1, R7-2006f10-1: the one-column form did not).
    a.y.label = SINGLE_S_AXIS.into();
    // One panel: no letter.
    a.title = "S̄, log scale; dashed: its optimum".into();
    let single = Charts {
        size: (Column::Single.width(), SINGLE_HEIGHT),
        title: "S̄ of ZP+W against k".into(),
        caption: vec![format!(
            "Lloyd et al. 2006, Fig. 10 (Eq 18, App. C), θ\u{a0}=\u{a0}{THETA_DEG}°, light \
             overhead: S̄ of ZP+W falls with the number of z-partitions k towards \
             S̄_{{opt}}\u{a0}=\u{a0}ln(f/n)/(2\u{a0}tan\u{a0}θ) (dashed)."
        )],
        charts: vec![a],
    };
    Ok(Keyed {
        single: Some(Box::new(Keyed::new(single, Some(0)))),
        ..Keyed::new(double, Some(0))
    })
}

/// The S̄ axis' name on the one-column page of Fig 10, short enough for its plot (the
/// two-column name, "… (texels per image pixel, log scale)", ran past the plot's ends; the
/// panel's title says that the scale is log).
const SINGLE_S_AXIS: &str = "S̄ (texels per image pixel)";

/// The depth ratios f/n of Fig 10.
const FIG10_RATIOS: [f64; 4] = [10.0, 100.0, 1000.0, 10_000.0];

/// Fig 10's panels, (a) S̄ and (b) S̄ over its optimum, and the optima as the key writes them.
fn fig10_panels() -> Result<(LineChart, LineChart, Vec<String>), Fail> {
    let theta = THETA_DEG.to_radians();
    // Both panels over the same k, with the same ticks.
    let k_axis = || Axis::integer("number of z-partitions k", 1.0, 16.0);
    let mut c = LineChart::new(
        "(a) S̄; dashed: its optimum",
        k_axis(),
        // To the data: 1.99 (f/n = 10's optimum) to 8.66×10³ (f/n = 10⁴ at k = 1).
        Axis::log10("S̄ (texels per image pixel, log scale)", 1.0, 1e4).in_powers(),
    );
    let mut r = LineChart::new(
        "(b) S̄ over its optimum",
        k_axis(),
        Axis::log10("S̄ / S̄_{opt} (log scale)", 0.8, 2000.0).in_powers(),
    );
    // The key's four entries in two rows of two where they fit (seventh review, R7-2006f10-3:
    // the fourth wrapped alone onto a second row).
    c.legend_columns = Some(2);
    let mut optima = Vec::new();
    let ratios = FIG10_RATIOS;
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
        let label = format!(
            "f/n\u{a0}=\u{a0}{}, S̄_{{opt}}\u{a0}=\u{a0}{opt:.2}",
            ratio_text(ratio)
        );
        // The optimum the curve tends to, dashed in the curve's colour (its value is in the
        // curve's key entry), under the curve.
        c.series.push(Series {
            label: None,
            ..Series::line("", vec![(1.0, opt), (16.0, opt)], colour)
                .dashed()
                .reference()
        });
        c.series
            .push(Series::line(label.clone(), pts.clone(), colour));
        r.series.push(Series::line(
            label,
            pts.iter().map(|&(k, v)| (k, v / opt)).collect(),
            colour,
        ));
        optima.push(format!("{opt:.2}"));
    }
    r.series.push(Series {
        label: None,
        ..Series::line("", vec![(1.0, 1.0), (16.0, 1.0)], SHARED)
            .dashed()
            .reference()
    });
    // The dashed line named in the plot (the fifth review: it was in no key), in its empty
    // upper right (under the line the note ran across the x axis).
    r.notes.push(Note {
        at: FIG10_NOTE_AT,
        text: FIG10_NOTE.into(),
        colour: SHARED,
    });
    Ok((c, r, optima))
}

/// The note naming Fig 10 (b)'s dashed line, and where it starts (k, S̄/S̄_opt).
const FIG10_NOTE: &str = "dashed: S̄\u{a0}=\u{a0}S̄_{opt}";
const FIG10_NOTE_AT: (f64, f64) = (6.5, 300.0);

/// A depth ratio as the figures write it: plain below 10⁴ (10, 100, 1000), a power of ten from
/// 10⁴ on (the fifth review: "f/n = 10000" against lloyd2005-fig7's "f/n = 10⁴").
fn ratio_text(ratio: f64) -> String {
    if ratio >= 1e4 {
        super::chart::fmt_power(ratio)
    } else {
        fmt_plain(ratio)
    }
}

/// The schemes' letters in words, as Fig 12's and 13's captions give them.
pub(super) const SCHEME_WORDS: &str = "ZP: z-partitioning, FP: face partitioning, W: warping.";

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
pub(super) fn unjoined(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(2 * points.len());
    for (i, &p) in points.iter().enumerate() {
        if i > 0 {
            out.push((0.5 * (points[i - 1].0 + p.0), f64::NAN));
        }
        out.push(p);
    }
    out
}

#[path = "lloyd2006_fig12.rs"]
mod fig12;
pub(super) use fig12::{fig12, FIG12_RATIO};

#[path = "lloyd2006_fig13.rs"]
mod fig13;
pub(super) use fig13::fig13;

#[cfg(test)]
#[path = "lloyd2006_tests.rs"]
mod tests;

#[cfg(test)]
#[path = "lloyd2006_forms_tests.rs"]
mod forms_tests;

#[cfg(test)]
#[path = "lloyd2006_review5_tests.rs"]
mod review5_tests;

#[cfg(test)]
#[path = "lloyd2006_review6_tests.rs"]
mod review6_tests;

#[cfg(test)]
#[path = "lloyd2006_review7_tests.rs"]
mod review7_tests;
