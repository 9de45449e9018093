//! zhang-fig3's tests (moved out of zhang.rs, which stays under 800 lines).

use super::*;
use crate::analytic::global::{zhang_ep, zhang_eq};
use crate::LightAngle;

/// The measured side view at γ = 90° and 60° (LiSPSM row) equals Zhang's global
/// representation (Eq 13, 14 with the corrected Appendix, `analytic::global`) at every
/// cell centre inside the frustum; E_p × E_q is their product.
/// A horizontal colour bar is one embedded image (abutting rectangles left seams, issue
/// 25), its lowest band at the left and its highest at the right.
#[test]
fn colour_bar_is_one_seamless_raster() {
    use super::super::chart::read_svg::{draw_svg, embedded_images};
    use super::super::chart::SMOOTH_LEVELS;
    let scale = ColourScale::smooth(Axis::log10("E", 2.0, 16400.0));
    let svg = draw_svg((160, BAR), |area| {
        draw_colour_bar_across(area, &scale).unwrap()
    });
    assert!(!svg
        .lines()
        .any(|l| l.starts_with("<rect") && !l.contains("fill=\"none\"")));
    let images = embedded_images(&svg);
    assert_eq!(images.len(), 1);
    let img = &images[0].rgba;
    let (w, h) = img.dimensions();
    let at = |x: u32| {
        let p = img.get_pixel(x, h / 2).0;
        RGBColor(p[0], p[1], p[2])
    };
    assert_eq!(at(0), scale.level_colour(0));
    assert_eq!(at(w - 1), scale.level_colour(SMOOTH_LEVELS - 1));
}

/// The depth axis under each block's first column reads 0 and 100 (the far plane f, review:
/// "0, 50" left f unreadable), "0" and "100" centred on their ticks, "100" on the panel's
/// right edge (the nineteenth review, R19-zhang-fig3-1: ending there, it stood under the
/// unlabelled 50); the height has its axis title, "height y",
/// once; every row's first panel of (a) has a y scale, −40, 0, 40; and rows are apart: a
/// row's "−40" and the next row's "40" (13 units tall) keep at least 9 units between them
/// (review: about 4 pt, touching).
#[test]
fn depth_reads_0_to_100_the_height_is_named_and_rows_are_apart() {
    use super::super::chart::read_svg::{attr, draw_svg, texts};
    let fig = fig3().map_err(|e| e.named("zhang-fig3")).unwrap();
    let svg = draw_svg(SIZE, |area| fig.draw(area).unwrap());
    let all = texts(&svg);
    let named = |t: &str| all.iter().filter(|x| x.1 == t).count();
    assert_eq!(named("depth z"), 3);
    assert_eq!(named("height y"), 1);
    assert_eq!(named("50"), 0);
    // The panels' grey frames (n to f across): their right edges.
    let frames: Vec<f64> = svg
        .lines()
        .filter(|l| l.starts_with("<rect") && l.contains("stroke=\"#969696\""))
        .map(|l| attr(l, "x").unwrap() + attr(l, "width").unwrap())
        .collect();
    assert_eq!(frames.len(), 27);
    // The depth's "100", not a bar's 10⁰ (read as 100 with its raised 0).
    let hundreds: Vec<&(&str, String, f64)> = all
        .iter()
        .filter(|x| x.1 == "100" && !x.0.contains("<tspan"))
        .collect();
    assert_eq!(hundreds.len(), 3, "{hundreds:?}");
    for (line, _, _) in hundreds {
        assert!(line.contains("text-anchor=\"middle\""), "{line}");
        let x = attr(line, "x").unwrap();
        assert!(
            frames.iter().any(|r| (x - r).abs() <= 1.0),
            "\"100\" centred at {x}, no frame edge there: {frames:?}"
        );
    }
    assert!(named("0") >= 3 + 3);
    // The y scale: in the first block's rows, by height.
    let at = |t: &str| -> Vec<f64> {
        let mut v: Vec<f64> = all.iter().filter(|x| x.1 == t).map(|x| x.2).collect();
        v.sort_by(f64::total_cmp);
        v
    };
    let (top, bottom) = (at("40"), at("−40"));
    assert_eq!((top.len(), bottom.len()), (3, 3), "{top:?} {bottom:?}");
    for r in 0..2 {
        // A tick label's y is its middle: the next row's "40" at least 22 units under this
        // row's "−40", their 13-unit boxes 9 apart (with rows 4 units apart, 18.7 and 5.7).
        assert!(top[r + 1] - bottom[r] >= 22.0, "{top:?} {bottom:?}");
    }
}

/// The colour bars are ticked at whole powers of ten, in both layouts (review X3: they
/// read 0.04, 1, 25 and 1, 125, 15625, powers of 5), and each bar's range holds every
/// value of its nine panels, its ends whole decades (review: SSM's E_p at the apex,
/// (f − n)/(n tan φ) = 99/tan 30° = 171.5 by Zhang's Eq 9, stood above the top tick of
/// (a)'s bar, its end unlabelled): read back from both SVGs, every number written is a
/// power of ten 10<sup>n</sup> or one of the axes' 0, ±40 (two columns), ±30 (one), 100;
/// E_p's bar reaches 10³ ≥ 171.5.
#[test]
fn colour_bars_are_ticked_at_powers_of_ten_and_hold_every_value() {
    use super::super::chart::read_svg::texts;
    let fig = fig3().map_err(|e| e.named("zhang-fig3")).unwrap();
    for (q, scale) in fig.scales.iter().enumerate() {
        let (lo, hi) = scale.axis.range();
        let whole = |a: f64| (a - a.round()).abs() < 1e-9;
        assert!(whole(lo) && whole(hi), "{q}: {lo} {hi}");
        for row in &fig.rows {
            for scheme in row {
                for v in scheme[q].grid.values.iter().flatten() {
                    let a = v.log10();
                    assert!(a >= lo - 1e-9 && a <= hi + 1e-9, "{q}: {v} outside");
                }
            }
        }
    }
    let apex = 99.0 / 30f64.to_radians().tan();
    assert!((apex - 171.47).abs() < 0.01);
    assert!(10f64.powf(fig.scales[0].axis.range().1) >= apex);
    for column in [Column::Double, Column::Single] {
        let svg = super::super::hemisphere::svg_in(&fig, column);
        let mut powers = 0;
        for (line, text, _) in texts(&svg) {
            if !text.chars().any(|c| c.is_ascii_digit())
                || text.chars().any(|c| c.is_alphabetic() || c == '°')
            {
                continue;
            }
            if line.contains(">10<tspan dy=\"-") {
                let exp = text.trim_start_matches("10").replace('−', "-");
                assert!(exp.parse::<i32>().is_ok(), "{column:?}: {text}");
                powers += 1;
            } else {
                assert!(
                    ["0", "40", "−40", "30", "−30", "100"].contains(&text.as_str()),
                    "{column:?}: {text} is no power of ten"
                );
            }
        }
        assert!(powers >= 9, "{column:?}: {powers} powers of ten");
    }
}

/// One column keeps the text of the other figures' one-column forms (review X9: the angle
/// and "z (eye depth)" were 8.871 units, 7.1 pt printed, against 10.48, 8.4 pt): read from
/// its SVG, no text of the figure is set smaller than 10.48 units but its sub- and
/// superscripts; the captions give the light–view angle's values as γ, the crate's symbol
/// (the fourth review: Zhang's θ clashed with the other figures' half field of view θ),
/// and say what θ is (X2); the two-column one names Zhang's symbols and defines the n′ it
/// prints (review: λ undefined), and both explain the factor 2 of E_p = 2 m_z.
#[test]
fn one_column_text_is_full_size_and_the_caption_defines_its_symbols() {
    use super::super::chart::read_svg::attr;
    let fig = fig3().map_err(|e| e.named("zhang-fig3")).unwrap();
    let svg = super::super::hemisphere::svg_in(&fig, Column::Single);
    let smallest = svg
        .lines()
        .filter(|l| l.starts_with("<text"))
        .filter_map(|l| attr(l, "font-size"))
        .fold(f64::INFINITY, f64::min);
    assert!(smallest >= 10.48, "{smallest}");
    // One column: the same set-up in fewer words, and the LiSPSM and TSM columns' rules (the
    // eighth review, R8-zhang-fig3-1).
    for want in [
        "f/n\u{a0}=\u{a0}100",
        // θ defined (the twenty-first review, R21-zhang-fig3-1).
        "half field of view θ\u{a0}=\u{a0}30°, light at γ from the view.",
        // SSM defined by its n′ (the thirteenth review, R13-zhang-fig3-1).
        "n′: SSM ∞, LiSPSM (n\u{a0}+\u{a0}√(fn))/sin\u{a0}γ",
        "TSM: 80\u{a0}% rule, focus depth δ\u{a0}=\u{a0}10",
    ] {
        assert!(
            fig.single_caption.contains(want),
            "{want}: {}",
            fig.single_caption
        );
    }
    for c in [&fig.caption, &fig.single_caption] {
        if std::ptr::eq(c, &fig.caption) {
            assert!(
                c.contains("γ\u{a0}=\u{a0}90°, 60°, 30° from the view (Zhang's θ)"),
                "{c}"
            );
            assert!(c.contains("half field of view θ\u{a0}=\u{a0}30°"), "{c}");
        }
        // The factor 2 written out (the eleventh review, R11-zhang-fig3-1: "(×2: span [−1, 1])"
        // was shorthand); one column, whose caption starts with Zhang's figure, gave "Zhang's"
        // to θ's definition (the twenty-first review, R21-zhang-fig3-1).
        assert!(c.contains("×2 for "), "{c}");
        assert!(c.contains("[−1,\u{a0}1]"), "{c}");
        assert!(!c.contains("π/6"), "{c}");
        // δ is named (the ninth review, R9-zhang-fig3-1: Martin & Tan's focus depth, undefined).
        assert!(c.contains("focus depth δ\u{a0}=\u{a0}10"), "{c}");
        assert_eq!(
            c.matches('θ').count(),
            1 + c.matches("Zhang's θ").count(),
            "{c}"
        );
    }
    for symbol in [
        "(Zhang's φ)",
        "(Zhang's θ)",
        "LiSPSM's n′\u{a0}=",
        "(Zhang's λ)",
        "SSM: n′\u{a0}=\u{a0}∞",
    ] {
        assert!(fig.caption.contains(symbol), "{symbol}: {}", fig.caption);
    }
    assert_eq!(fig.caption.matches('λ').count(), 1, "{}", fig.caption);
}

#[test]
fn lispsm_cells_equal_zhangs_global_representation() {
    let fig = fig3().map_err(|e| e.named("zhang-fig3")).unwrap();
    let view = ViewFrustum::new(1.0, 100.0, FRAC_PI_6).unwrap();
    for (r, theta_deg) in [(0usize, 90.0f64), (1, 60.0)] {
        let theta = LightAngle::new(theta_deg.to_radians()).unwrap();
        // LiSPSM's n′ (Zhang's λ) = (n + √(fn))/sin γ.
        let lambda = NPrime::finite(11.0 / theta_deg.to_radians().sin()).unwrap();
        let panels = &fig.rows[r][1];
        let g = &panels[0].grid;
        let nx = g.x_edges.len() - 1;
        let mut checked = 0;
        for (k, v) in g.values.iter().enumerate() {
            let Some(ep) = *v else { continue };
            let (z, y) = g.sample_point(k % nx, k / nx).unwrap();
            let want_p = zhang_ep(&view, lambda, theta, y, z).unwrap();
            let want_q = zhang_eq(&view, lambda, theta, y, z).unwrap();
            let eq = panels[1].grid.values[k].unwrap();
            let epq = panels[2].grid.values[k].unwrap();
            assert!(
                (ep - want_p).abs() < 1e-9 * want_p,
                "E_p at ({y}, {z}): {ep} vs {want_p}"
            );
            assert!(
                (eq - want_q).abs() < 1e-9 * want_q,
                "E_q at ({y}, {z}): {eq} vs {want_q}"
            );
            assert!((epq - ep * eq).abs() < 1e-12 * epq);
            checked += 1;
        }
        assert!(checked > 1000, "{checked} cells");
    }
}

/// The side views sample the near plane: the first column of cells is [n, n + 1] (99 cells
/// over [1, 100]), its (cut) cells are sampled inside it, where
/// the old grid over [0, f] first sampled z = 1.875; the cells along the slanted sides end
/// on the frustum's border |y| = z tan φ.
#[test]
fn side_view_cells_start_at_the_near_plane_and_follow_the_border() {
    let t = FRAC_PI_6.tan();
    let g = frustum_grid(1.0, 100.0, t);
    assert_eq!(g.x_edges[0], 1.0);
    let nx = g.x_edges.len() - 1;
    let first: Vec<(f64, f64)> = (0..g.y_edges.len() - 1)
        .filter_map(|j| g.sample_point(0, j))
        .collect();
    assert!(!first.is_empty());
    for &(z, y) in &first {
        assert!(z > 1.0 && z < 2.0, "z = {z}");
        assert!(y.abs() <= z * t);
    }
    for j in 0..g.y_edges.len() - 1 {
        for i in 0..nx {
            let (poly, _) = g.cell(i, j);
            for p in poly {
                assert!(p.1.abs() <= p.0 * t * (1.0 + 1e-12) + 1e-12, "{p:?}");
            }
        }
    }
}

/// The panels' aspect, read from the SVGs' grey frames (depth n to f across, 99; height
/// ±f tan θ up, 115.47): two columns draw them to scale (height over width 1.166), one
/// column at exactly half the heights' scale (0.583), as its caption and its turned axis
/// name "height y (drawn at ½ the scale of z)" say (the fifth review: "about half", stated nowhere). (Two
/// columns' upright "height y": `height_named_upright_single_ticks_on_middle_rows_and_scales_stated`.)
#[test]
fn panels_are_to_scale_or_at_half_height_as_stated() {
    use super::super::chart::read_svg::{attr, texts};
    let fig = fig3().map_err(|e| e.named("zhang-fig3")).unwrap();
    let true_ratio = 2.0 * 100.0 * FRAC_PI_6.tan() / 99.0;
    assert!((true_ratio - 1.1664).abs() < 1e-3);
    for (column, scale, name) in [
        (Column::Double, 1.0, "height y"),
        (Column::Single, 0.5, "height y (drawn at ½ the scale of z)"),
    ] {
        let svg = super::super::hemisphere::svg_in(&fig, column);
        let frames: Vec<(f64, f64)> = svg
            .lines()
            .filter(|l| l.starts_with("<rect") && l.contains("stroke=\"#969696\""))
            .map(|l| (attr(l, "width").unwrap(), attr(l, "height").unwrap()))
            .collect();
        assert_eq!(frames.len(), 27, "{column:?}");
        for (w, h) in frames {
            let r = h / w / (scale * true_ratio);
            assert!((r - 1.0).abs() < 0.05, "{column:?}: frame {w} × {h}, {r}");
        }
        let named: Vec<(&str, String, f64)> =
            texts(&svg).into_iter().filter(|t| t.1 == name).collect();
        assert_eq!(named.len(), 1, "{column:?}: {name}");
        if column == Column::Single {
            assert!(named[0].0.contains("rotate(270"), "{}", named[0].0);
        }
    }
    // The half scale of heights is in the axis name, "height y (drawn at ½ the scale of z)" (the seventh review,
    // R7-Z3-2), no longer also in the one-column caption, which needed the room to write m out
    // (the eleventh, R11-zhang-fig3-1 and -3: the axis' name is enough); no caption says it.
    assert!(!fig.single_caption.contains("depth scale"));
    assert!(!fig.single_caption.contains("halved"));
    assert!(!fig.caption.contains("halved"));
    // E_p and E_q: two columns' caption; one column's blocks' titles ("(a) E_p = 2 m_z").
    assert!(
        fig.caption
            .contains("E_p, E_q: aliasing along screen y, x; m: "),
        "{}",
        fig.caption
    );
}

/// Figure review 6 (R6-zhang-fig3-0): the m_z and m_x of E_p = 2 m_z and E_q = 2 m_x are
/// measured across the light (Lloyd 2006 §4.4), not along the view axis as Barroso's m_z (Eq 12),
/// which is 1/sin γ larger; the figure says so. By hand: SSM's map is uniform in the light-space
/// coordinate a·p along the view direction projected across the light, a = (v − (v·l) l)/|…|,
/// over the frustum's extent Δ = max − min of a·p at its eight corners, so its t texel is Δ wide
/// across the light and E_p = 2 Δ/(2 z tan θ) at depth z; at γ = 30° Barroso's would be twice
/// that. Each SSM cell at γ = 30° has the former (within 10⁻⁹), not the latter; both captions
/// say so in words ("m: Lloyd 2006's error (Eq 7, 8) … facing the light": a texel's width
/// perpendicular to the light, R11-zhang-fig3-1), and no title writes "⊥" (R7-Z3-1).
#[test]
fn m_is_measured_across_the_light_and_the_figure_says_so() {
    use super::super::chart::read_svg::texts;
    let fig = fig3().map_err(|e| e.named("zhang-fig3")).unwrap();
    let g = 30f64.to_radians();
    let l = DVec3::new(0.0, -g.sin(), g.cos());
    let v = DVec3::NEG_Z;
    let a = (v - v.dot(l) * l).normalize();
    let t = (30f64.to_radians()).tan();
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for z in [1.0, 100.0] {
        for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            let d = a.dot(DVec3::new(sx * z * t, sy * z * t, -z));
            lo = lo.min(d);
            hi = hi.max(d);
        }
    }
    let delta = hi - lo;
    let grid = frustum_grid(1.0, 100.0, t);
    let nx = grid.x_edges.len() - 1;
    let ssm_ep = &fig.rows[2][0][0].grid.values;
    let mut checked = 0;
    for (k, v) in ssm_ep.iter().enumerate() {
        let (Some(v), Some((z, _))) = (v, grid.sample_point(k % nx, k / nx)) else {
            continue;
        };
        let across = delta / (z * t);
        assert!(
            (v / across - 1.0).abs() < 1e-9,
            "z {z}: {v} against {across}"
        );
        assert!((v / (across / g.sin()) - 0.5).abs() < 1e-9);
        checked += 1;
    }
    assert!(checked > 100, "{checked} cells");
    // The seventh review (R7-Z3-1): "(⊥ light)" in the titles was unexplained notation; the
    // captions say in words what m is, the titles no longer write "⊥".
    for column in [Column::Double, Column::Single] {
        let svg = super::super::hemisphere::svg_in(&fig, column);
        let marked = texts(&svg).iter().filter(|t| t.1.contains('⊥')).count();
        assert_eq!(marked, 0, "{column:?}: {marked} texts say ⊥");
    }
    assert!(
        fig.caption
            .contains("m: Lloyd 2006's error (Eq 7, 8) facing the light"),
        "{}",
        fig.caption
    );
    assert!(
        fig.single_caption
            .contains("m: Lloyd 2006's error facing the light"),
        "{}",
        fig.single_caption
    );
}

/// The sixth review: R6-zhang-fig3-4 (two columns: "height y", turned beside the turned
/// "γ = 60°", read as one label "height y γ = 60°"), -3 (one column: ±30 on all nine rows,
/// 2.7 pt apart, read as one column of numbers) and -2 (three colour bars of different ranges,
/// unstated). Read from the drawn SVGs: in two columns "height y" is set once, upright (no
/// rotation), over the first row of panels (above every panel frame's top); in one column the
/// y ticks "40" and "−40" appear once per block (3 each, not 9), on its middle row (between
/// the block's first and last row frames); the two-column caption says the blocks have their
/// own colour scales (one column's bars stand beside their blocks).
#[test]
fn height_named_upright_single_ticks_on_middle_rows_and_scales_stated() {
    use super::super::chart::read_svg::{attr, texts};
    use super::super::hemisphere::svg_in;
    let fig = fig3().map_err(|e| e.named("zhang-fig3")).unwrap();
    let frames = |svg: &str| -> Vec<(f64, f64)> {
        svg.lines()
            .filter(|l| l.starts_with("<rect") && l.contains("stroke=\"#969696\""))
            .map(|l| {
                let y = attr(l, "y").unwrap();
                (y, y + attr(l, "height").unwrap())
            })
            .collect()
    };
    let svg = svg_in(&fig, Column::Double);
    let all = texts(&svg);
    let named: Vec<_> = all.iter().filter(|t| t.1 == "height y").collect();
    assert_eq!(named.len(), 1, "{named:?}");
    assert!(!named[0].0.contains("rotate("), "{}", named[0].0);
    let top = frames(&svg)
        .iter()
        .map(|f| f.0)
        .fold(f64::INFINITY, f64::min);
    assert!(
        named[0].2 <= top,
        "{} under the panels' top {top}",
        named[0].2
    );
    let svg = svg_in(&fig, Column::Single);
    let all = texts(&svg);
    let mut rows: Vec<(f64, f64)> = frames(&svg);
    rows.sort_by(|a, b| a.0.total_cmp(&b.0));
    rows.dedup_by(|a, b| (a.0 - b.0).abs() < 0.5);
    assert_eq!(rows.len(), 9, "{rows:?}");
    for tick in ["40", "−40"] {
        let ys: Vec<f64> = all.iter().filter(|t| t.1 == tick).map(|t| t.2).collect();
        assert_eq!(ys.len(), 3, "{tick}: {ys:?}");
        for (block, y) in ys.iter().enumerate() {
            let (first, last) = (rows[3 * block], rows[3 * block + 2]);
            assert!(
                *y > first.1 && *y < last.0,
                "{tick} at {y}: {first:?} {last:?}"
            );
        }
    }
    // Two columns say where the figure departs from the paper (issue 25); the colour scale per
    // block, drawn beside each block, is no longer also written (R11-zhang-fig3-1 took the room).
    assert!(fig.caption.contains("Unlike the paper: no scene insets."));
}
