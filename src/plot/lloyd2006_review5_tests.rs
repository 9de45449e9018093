//! Tests of the fifth figure review's items on the Lloyd et al. 2006 closed-form figures
//! (issue 35: §4.5 fig5, §4.6 fig6, §4.8 fig10, §4.10 fig12, §4.11 fig13, X4, X6, X7), each
//! read from the figure as the command writes it (SVG) or from the data it draws.

use super::*;
use crate::plot::chart::read_svg::{attr, texts};
use crate::plot::Figure;

use super::forms_tests::svg_of;

/// `c` as an SVG writes it.
fn hex(c: RGBColor) -> String {
    format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2)
}

/// Every marker (`<polygon>`) of an SVG: its fill, its centre and its number of corners.
fn markers(svg: &str) -> Vec<(String, (f64, f64), usize)> {
    svg.lines()
        .filter(|l| l.starts_with("<polygon"))
        .filter_map(|l| {
            let f = l.find(" fill=\"")? + 7;
            let fill = l[f..f + l[f..].find('"')?].to_string();
            let pts = crate::plot::chart::read_svg::points(l)?;
            let n = pts.len() as f64;
            let c = (
                pts.iter().map(|p| p.0).sum::<f64>() / n,
                pts.iter().map(|p| p.1).sum::<f64>() / n,
            );
            Some((fill, c, pts.len()))
        })
        .collect()
}

/// The least distance between the centres of two markers of different fills among `m`, and
/// the pair.
fn closest_pair(m: &[(String, (f64, f64), usize)]) -> (f64, String) {
    let mut best = (f64::INFINITY, String::new());
    for (i, a) in m.iter().enumerate() {
        for b in &m[..i] {
            let d = (a.1 .0 - b.1 .0).hypot(a.1 .1 - b.1 .1);
            if a.0 != b.0 && d < best.0 {
                best = (d, format!("{} at {:?} and {} at {:?}", a.0, a.1, b.0, b.1));
            }
        }
    }
    best
}

/// The y of the x axis' name "depth z" lowest on the page: markers above it are the plots'
/// (the key's lie below).
fn lowest_text_y(svg: &str, text: &str) -> f64 {
    texts(svg)
        .iter()
        .filter(|t| t.1 == text)
        .map(|t| t.2)
        .fold(f64::NEG_INFINITY, f64::max)
}

/// Fig 5 (fifth review §4.5.1: in (b) at z ≈ 4–8 the markers of five curves lay on one
/// another): in both forms, captioned, no two markers of different curves in the plots are
/// closer than 11 units centre to centre (a marker reaches at most 5 units from its centre, a
/// triangle's tip, so they do not touch).
#[test]
fn fig5_markers_of_different_curves_apart() {
    for column in [Column::Double, Column::Single] {
        let svg = svg_of("lloyd2006-fig5", column, false);
        let axis = lowest_text_y(&svg, "depth z");
        let plots: Vec<_> = markers(&svg)
            .into_iter()
            .filter(|m| m.1 .1 < axis)
            .collect();
        assert!(plots.len() >= 30, "{column:?}: {} markers", plots.len());
        let (d, pair) = closest_pair(&plots);
        assert!(d >= 11.0, "{column:?}: {pair} are {d:.1} apart");
    }
}

/// Fig 5 (§4.5.2: each axis spans 1.3 decades but was labelled at 10⁰ and 10⁻¹ only): both
/// panels' y axes are labelled 5×10⁻² (PSM's level, f/n · 1/f = 1/20 = 0.05) and 2×10⁻¹, in
/// both forms.
#[test]
fn fig5_axes_labelled_at_two_and_five() {
    for column in [Column::Double, Column::Single] {
        let svg = svg_of("lloyd2006-fig5", column, false);
        let t = texts(&svg);
        for label in ["5×10−2", "2×10−1", "10−1", "100"] {
            let n = t.iter().filter(|t| t.1 == label).count();
            assert_eq!(n, 2, "{column:?}: {label:?} written {n} times");
        }
    }
}

/// Fig 5 (§4.5.3, X6: n′ = 100, the sweep's lightest purple, L* 60, and n′ = ∞, orange L* 71,
/// printed as two pale solid lines with ◄ and ▼; ∞ is now vermillion, L* 54, with squares):
/// n′ = 100's line is dashed and its markers are diamonds (4 corners, as ∞'s squares: the
/// shapes are Marker::of's, src/plot/chart/line.rs), and n′ = ∞'s lines solid.
#[test]
fn fig5_n100_and_uniform_differ_in_greyscale() {
    let svg = svg_of("lloyd2006-fig5", Column::Double, false);
    let (c100, cinf) = (hex(sweep(2, 3)), hex(Look::Uniform.colour()));
    // A dashed line is written as its dashes, one polyline each: n′ = 100's two curves (one a
    // panel) and its key sample in dozens, n′ = ∞'s in one piece each.
    let pieces = |c: &str| {
        svg.lines()
            .filter(|l| l.starts_with("<polyline") && l.contains(&format!("stroke=\"{c}\"")))
            .count()
    };
    assert!(pieces(&c100) > 40, "n′ = 100 in {} pieces", pieces(&c100));
    assert!(pieces(&cinf) <= 4, "n′ = ∞ in {} pieces", pieces(&cinf));
    let corners = |c: &str| -> Vec<usize> {
        markers(&svg)
            .into_iter()
            .filter(|m| m.0 == c)
            .map(|m| m.2)
            .collect()
    };
    assert!(
        corners(&c100).iter().all(|&n| n == 4),
        "{:?}",
        corners(&c100)
    );
    assert!(
        corners(&cinf).iter().all(|&n| n == 4),
        "{:?}",
        corners(&cinf)
    );
}

/// `c`'s hue in degrees and its CIE L* (sRGB, D65), by the standard formulas.
fn hue_and_lightness(c: RGBColor) -> (f64, f64) {
    let (r, g, b) = (
        f64::from(c.0) / 255.0,
        f64::from(c.1) / 255.0,
        f64::from(c.2) / 255.0,
    );
    let (max, min) = (r.max(g).max(b), r.min(g).min(b));
    let d = max - min;
    let hue = if d == 0.0 {
        f64::NAN
    } else if max == r {
        60.0 * ((g - b) / d).rem_euclid(6.0)
    } else if max == g {
        60.0 * ((b - r) / d + 2.0)
    } else {
        60.0 * ((r - g) / d + 4.0)
    };
    let lin = |v: f64| {
        if v <= 0.04045 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    let y = 0.2126 * lin(r) + 0.7152 * lin(g) + 0.0722 * lin(b);
    let l = if y > 216.0 / 24389.0 {
        116.0 * y.cbrt() - 16.0
    } else {
        y * 24389.0 / 27.0
    };
    (hue, l)
}

/// Fig 6 (§4.6.1–4: M_x and M_z were two dark purples, S̄ a pale dotted lilac, the key M_z,
/// M_x, S̄, and a second panel for M_z's V took half the page): the key reads M_x, M_z, S̄ top
/// to bottom in both forms; M_x's and M_z's colours (from the key samples' strokes, read in
/// the SVG) are at least 60° of hue or 30 L* apart and S̄'s L* is at most 20 (by hand: black
/// 0); no scheme's colour is used; and the two-column figure is one panel at most 440 units
/// tall (it was two, 540).
#[test]
fn fig6_three_hues_key_in_axis_order_one_panel() {
    let fig = fig6().map_err(|e| e.named("lloyd2006-fig6")).unwrap();
    assert_eq!(fig.page.charts.len(), 1);
    // 490 since the seventh review (R7-2006f6-1): the axis' name with S̄'s unit needs the
    // plot's height.
    assert!(fig.size().1 <= 490, "{:?}", fig.size());
    let keys: Vec<&Series> = fig.page.charts[0]
        .series
        .iter()
        .filter(|s| s.label.is_some())
        .collect();
    let names: Vec<&str> = keys.iter().filter_map(|s| s.label.as_deref()).collect();
    assert_eq!(names, ["M_x", "M_z", "S̄ = M_x M_z"]);
    let schemes = [
        Look::Psm,
        Look::Lispsm,
        Look::Uniform,
        Look::Zp,
        Look::ZpW,
        Look::FpZpW,
    ];
    for column in [Column::Double, Column::Single] {
        let svg = svg_of("lloyd2006-fig6", column, false);
        let t = texts(&svg);
        let y = |label: &str| {
            t.iter()
                .find(|t| t.1 == label)
                .map(|t| t.2)
                .unwrap_or_else(|| panic!("{column:?}: no {label:?}"))
        };
        let (yx, yz, ys) = (y("Mx"), y("Mz"), y("S = Mx Mz"));
        assert!(yx < yz && yz < ys, "{column:?}: key at {yx}, {yz}, {ys}");
        // The stroke of the key sample beside each name: the polyline whose y is the name's.
        let stroke = |at: f64| -> RGBColor {
            let l = svg
                .lines()
                .filter(|l| l.starts_with("<polyline"))
                .find(|l| {
                    let ys: Vec<f64> = crate::plot::chart::read_svg::points(l)
                        .unwrap()
                        .iter()
                        .map(|p| p.1)
                        .collect();
                    ys.len() >= 2 && ys.iter().all(|v| (v - at).abs() < 3.0)
                })
                .unwrap_or_else(|| panic!("{column:?}: no key sample at y {at}"));
            let s = l.find(" stroke=\"#").unwrap() + 10;
            let v = u32::from_str_radix(&l[s..s + 6], 16).unwrap();
            RGBColor((v >> 16) as u8, (v >> 8) as u8, v as u8)
        };
        let (cx, cz, cs) = (stroke(yx), stroke(yz), stroke(ys));
        let ((hx, lx), (hz, lz), (_, ls)) = (
            hue_and_lightness(cx),
            hue_and_lightness(cz),
            hue_and_lightness(cs),
        );
        let dh = (hx - hz).abs().min(360.0 - (hx - hz).abs());
        assert!(
            dh >= 60.0 || (lx - lz).abs() >= 30.0,
            "{column:?}: M_x {cx:?} and M_z {cz:?}: {dh:.0}° and {:.0} L* apart",
            (lx - lz).abs()
        );
        assert!(ls <= 20.0, "{column:?}: S̄ {cs:?} L* {ls:.0}");
        for c in [cx, cz, cs] {
            assert!(
                schemes.iter().all(|l| l.colour() != c),
                "{c:?} is a scheme's"
            );
        }
    }
}

/// Fig 10 (§4.8, X4: the key said "f/n = 10000", lloyd2005-fig7 "f/n = 10⁴"; the dashed
/// S̄/S̄_opt = 1 line of (b) was in no key): the key writes 10⁴ (a superscript 4) and no 10000,
/// and (b) names its dashed line inside the plot, captioned and bare.
#[test]
fn fig10_writes_ten_to_the_four_and_names_the_dashed_line() {
    for bare in [false, true] {
        let svg = svg_of("lloyd2006-fig10", Column::Double, bare);
        let t: Vec<(&str, String, f64)> = texts(&svg)
            .into_iter()
            .map(|t| (t.0, t.1.replace('\u{a0}', " "), t.2))
            .collect();
        assert!(
            t.iter()
                .any(|t| t.0.contains("\u{a0}10<tspan") && t.1.starts_with("f/n = 104,")),
            "bare {bare}: no f/n = 10⁴ in the key"
        );
        assert!(!svg.contains("10000"), "bare {bare}: 10000 written");
        let note: Vec<_> = t.iter().filter(|t| t.1 == "dashed: S = Sopt").collect();
        assert_eq!(note.len(), 1, "bare {bare}");
        // In (b)'s plot: right of the page's middle, left of (b)'s tick label "12" (the note
        // is about 100 units long, the plot's last 4 k about 55), and more than 20 units above
        // its x axis, the y of (b)'s "100" (the note ran across that axis).
        let (x, y) = (attr(note[0].0, "x").unwrap(), note[0].2);
        let tick = |label: &str| {
            t.iter()
                .filter(|t| t.1 == label)
                .map(|t| (attr(t.0, "x").unwrap(), t.2))
                .fold(
                    (f64::NEG_INFINITY, 0.0),
                    |a, b| if b.0 > a.0 { b } else { a },
                )
        };
        let (twelve, one) = (tick("12"), tick("100"));
        assert!(x > 260.0 && x < twelve.0, "bare {bare}: note at x {x}");
        assert!(
            y < one.1 - 20.0,
            "bare {bare}: note at y {y}, 10⁰ at {}",
            one.1
        );
    }
}

/// Fig 12 (§4.10.1: FP+ZP+W's triangle at 37 maps covered ZP's circle at 36): the markers on
/// ZP's and ZP+W's overhead lines sit at counts 4k + 3 only (from the data), and in the SVG no
/// ZP or ZP+W marker lies within 11 units of an FP+ZP+W marker (FP+ZP+W's reach 6 units from
/// their centres, ZP's 4), in both forms.
#[test]
fn fig12_zp_markers_clear_of_fp_zp_w() {
    let fig = fig12().map_err(|e| e.named("lloyd2006-fig12")).unwrap();
    let a = &fig.page.charts[0];
    let (zp, zpw) = (Look::Zp.colour(), Look::ZpW.colour());
    for s in a
        .series
        .iter()
        .filter(|s| s.markers && !s.points.is_empty() && s.colour != Look::FpZpW.colour())
    {
        assert!(s.colour == zp || s.colour == zpw);
        let counts: Vec<f64> = s
            .points
            .iter()
            .filter(|p| p.1.is_finite())
            .map(|p| p.0)
            .collect();
        assert!(counts.len() >= 2, "{counts:?}");
        assert!(counts.iter().all(|c| c % 4.0 == 3.0), "{counts:?}");
    }
    for column in [Column::Double, Column::Single] {
        let svg = svg_of("lloyd2006-fig12", column, false);
        let axis = lowest_text_y(&svg, "number of shadow maps");
        let m: Vec<_> = markers(&svg)
            .into_iter()
            .filter(|m| m.1 .1 < axis)
            .collect();
        let of = |c: RGBColor| -> Vec<(f64, f64)> {
            m.iter().filter(|m| m.0 == hex(c)).map(|m| m.1).collect()
        };
        let fp = of(Look::FpZpW.colour());
        // The filled ones, overhead (nine, 5 to 37 maps; behind they are open, sixth review).
        assert!(fp.len() >= 9, "{column:?}: {} FP+ZP+W markers", fp.len());
        for p in of(zp).into_iter().chain(of(zpw)) {
            for q in &fp {
                let d = (p.0 - q.0).hypot(p.1 - q.1);
                assert!(
                    d >= 11.0,
                    "{column:?}: marker at {p:?} {d:.1} from FP+ZP+W's {q:?}"
                );
            }
        }
    }
}

/// Fig 12 and 13 (X7: ZP, FP and W never expanded; §4.11: the one-column caption of fig13
/// left k undefined): every caption says what ZP, FP and W stand for, and fig13's define k.
#[test]
fn fig12_and_13_captions_expand_the_schemes_and_define_k() {
    for name in ["lloyd2006-fig12", "lloyd2006-fig13"] {
        for column in [Column::Double, Column::Single] {
            let svg = svg_of(name, column, false);
            let caption: String = texts(&svg)
                .iter()
                .filter(|t| t.0.contains("fill=\"#323232\""))
                .map(|t| t.1.clone())
                .collect::<Vec<_>>()
                .join(" ")
                .replace('\u{a0}', " ");
            for words in ["ZP: z-partitioning", "FP: face partitioning", "W: warping"] {
                assert!(
                    caption.contains(words),
                    "{name} {column:?}: no {words:?}: {caption}"
                );
            }
            if name == "lloyd2006-fig13" {
                assert!(
                    caption.contains("k z-partitions per face"),
                    "{name} {column:?}: {caption}"
                );
            }
        }
    }
}
