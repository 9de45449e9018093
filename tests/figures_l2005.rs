//! The Lloyd et al. 2005 figures (lloyd2005-fig4, fig7, fig8) after the third figure review,
//! read back from their SVGs in all three forms (two columns, bare, one column): what the
//! captions said is written in the figures too (fig4's g₀ line, fig8's tags and "error after"),
//! labels stand where they read as their lines' (fig4), fig7 (a)'s log axis is labelled
//! between its decades, and fig8's leaders do not cross, its axes say "in light space" and
//! its partitions are filled in no scheme's colour.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::{attr, attr_str, forms, points, render_svg, texts, Font, Text};
use shadow_aliasing::plot::{Column, Options};

fn all_texts(svg: &str) -> Vec<Text> {
    texts(&Font::dejavu(), svg)
}

/// The figure's words as one string, no-break spaces read as spaces.
fn words(svg: &str) -> String {
    all_texts(svg)
        .iter()
        .map(|t| t.content.replace('\u{a0}', " "))
        .collect::<Vec<_>>()
        .join(" | ")
}

/// The third review (bare: B): the dotted line at 1/√(f/n) was explained only in the caption.
/// Each form names it in the figure itself: a text "g0 = 1/√(f/n)" (the 0 a subscript; the
/// report's α is written f/n, as in the Lloyd 2006 figures, since the fourth review).
#[test]
fn fig4_names_its_g0_line_in_every_form() {
    for (form, opts) in forms() {
        let svg = render_svg("lloyd2005-fig4", &opts);
        let all = all_texts(&svg);
        let g0: Vec<&Text> = all
            .iter()
            .filter(|t| t.content.starts_with("g0 = 1/√(f/n)"))
            .collect();
        assert_eq!(g0.len(), 1, "{form}: {}", words(&svg));
        assert!(
            g0[0].tag.contains("fill=\"#5A5A5A\""),
            "{form}: the g0 label is not the line's grey: {}",
            g0[0].tag
        );
    }
}

/// Two columns: every curve's label ends at least 10 units inside the x axis' end (the labels
/// ran to the frame; then ended about 3–6 units inside it), the ξ = 0 curve's 1; the ξ = 0 curve's label stands
/// under its curve by the far plane (the g₀ line's label is over the curve there since the
/// sixth review, R6-lloyd2005-fig4-1), and no nearer another curve than its own (the third
/// review: it stood between two markers, 4 pt under the curve, at the middle of the axis).
#[test]
fn fig4_labels_sit_by_their_curves_and_inside_the_axis() {
    for (form, opts) in &forms()[..2] {
        let svg = render_svg("lloyd2005-fig4", opts);
        let all = all_texts(&svg);
        let end = all
            .iter()
            .find(|t| t.content == "10" && attr_str(&t.tag, "text-anchor") == Some("middle"))
            .map(|t| t.x)
            .expect("the x axis' last tick label");
        let labels: Vec<&Text> = all
            .iter()
            .filter(|t| t.content.starts_with("n′ = "))
            .collect();
        assert_eq!(labels.len(), 5, "{form}");
        // The ξ = 0 label, under its curve by the far plane, which rises towards it, ends 2
        // units inside (a box under the rising curve further left would cross it).
        for t in &labels {
            let inside = if t.content.starts_with("n′ = 4.162") {
                1.0
            } else {
                10.0
            };
            assert!(
                t.bbox[2] <= end - inside,
                "{form}: {} ends at {:.1}, the axis at {end}",
                t.content,
                t.bbox[2]
            );
        }
        let green = labels
            .iter()
            .find(|t| t.content.starts_with("n′ = 4.162"))
            .unwrap();
        // The curves: polylines in a colour that is no grey (a dashed curve in many pieces);
        // the ξ = 0 one is the solid curve (one polyline of many points) equal on both planes
        // (g(1) = g(f/n) = g₀, Eq 3), whatever its colour.
        let curves: Vec<Vec<(f64, f64)>> = svg
            .lines()
            .filter(|l| l.starts_with("<polyline"))
            .filter(|l| {
                let c = attr_str(l, "stroke").unwrap_or("#000000");
                c.len() == 7 && !(c[1..3] == c[3..5] && c[3..5] == c[5..7])
            })
            .map(points)
            .filter(|p| p.len() >= 2)
            .collect();
        let flat: Vec<&Vec<(f64, f64)>> = curves
            .iter()
            .filter(|c| c.len() > 20 && (c[0].1 - c[c.len() - 1].1).abs() < 1.0)
            .collect();
        assert_eq!(flat.len(), 1, "{form}: the ξ = 0 curve");
        let at = |c: &[(f64, f64)], x: f64| {
            c.windows(2)
                .find(|w| (w[0].0 - x) * (w[1].0 - x) <= 0.0 && w[1].0 != w[0].0)
                .map(|w| w[0].1 + (w[1].1 - w[0].1) * (x - w[0].0) / (w[1].0 - w[0].0))
        };
        let mid = 0.5 * (green.bbox[0] + green.bbox[2]);
        let y = at(flat[0], mid).expect("the ξ = 0 curve under its label");
        assert!(
            green.bbox[1] > y,
            "{form}: the ξ = 0 label's top {:.1} is not under its curve at {y:.1}",
            green.bbox[1]
        );
        // Its own curve the nearest at its middle: every other curve farther from the
        // label's middle height.
        let centre = 0.5 * (green.bbox[1] + green.bbox[3]);
        for c in curves.iter().filter(|c| !std::ptr::eq(*c, flat[0])) {
            if let Some(o) = at(c, mid) {
                assert!(
                    (o - centre).abs() > (y - centre).abs(),
                    "{form}: a curve at {o:.1} is nearer the ξ = 0 label at {centre:.1} than its own at {y:.1}"
                );
            }
        }
    }
}

/// The third review: fig7 (a)'s log axis spans about 1.3 decades but carried only 10⁰ and
/// 10⁻¹, so the caption's 0.575 could not be read off. (a) is labelled at 2×10⁻¹ and 5×10⁻¹
/// too (powers of ten, as (b)), in every form.
#[test]
fn fig7_a_is_labelled_between_its_decades() {
    for (form, opts) in forms() {
        let svg = render_svg("lloyd2005-fig7", &opts);
        let words = words(&svg);
        for label in ["2×10−1", "5×10−1", "10−1", "100"] {
            assert!(
                words.split(" | ").any(|w| w == label),
                "{form}: no tick label {label}: {words}"
            );
        }
    }
}

/// X6: "light −x" read as "light minus x"; fig8's axes are named as in every figure (the fifth
/// review, X3: "z in light space" clashed with the eye depth z, and one column's (b) said "z"):
/// "light-view x" and "light-view y" on both (a) and (b), in every form, and no text says
/// "light −x", "light z", "z in light space" or a bare "z".
#[test]
fn fig8_axes_are_named_in_light_space() {
    for (form, opts) in forms() {
        let svg = render_svg("lloyd2005-fig8", &opts);
        let all = all_texts(&svg);
        let count = |name: &str| all.iter().filter(|t| t.content == name).count();
        for name in ["light-view x", "light-view y"] {
            assert!(count(name) >= 2, "{form}: {name} not on (a) and (b)");
        }
        for name in [
            "light −x",
            "light z",
            "z in light space",
            "−x in light space",
            "z",
        ] {
            assert_eq!(count(name), 0, "{form}: {name}");
        }
    }
}

/// The third review: panel (b)'s purple grid and thick outline were explained only by the
/// caption. Its title names the grid ("R2's texel grid") and the tag R2 stands inside the
/// outline, in every form (the bare one included): one more "R2" than the other panels have.
#[test]
fn fig8_b_names_its_texel_grid_and_its_part() {
    for (form, opts) in forms() {
        let svg = render_svg("lloyd2005-fig8", &opts);
        let all = all_texts(&svg);
        assert!(
            all.iter().any(|t| t.content == "(b) R2's texel grid"),
            "{form}: {}",
            words(&svg)
        );
        // R2 in (a), (b), (c), and in the two-column table (the one-column one writes R1, R2).
        let r2 = all.iter().filter(|t| t.content == "R2").count();
        let want = if form == "single" { 3 } else { 4 };
        assert_eq!(r2, want, "{form}");
    }
}

/// The leaders under fig8 (a): the grey two-point polylines that run downwards (the table's
/// rule is level). Each as (top, bottom).
fn leaders(svg: &str) -> Vec<((f64, f64), (f64, f64))> {
    svg.lines()
        .filter(|l| l.starts_with("<polyline") && attr_str(l, "stroke") == Some("#5A5A5A"))
        .map(points)
        .filter(|p| p.len() == 2 && (p[1].1 - p[0].1).abs() > 1.0)
        .map(|p| {
            if p[0].1 < p[1].1 {
                (p[0], p[1])
            } else {
                (p[1], p[0])
            }
        })
        .collect()
}

/// The third review: the leaders from the parts at the apex to their tags crossed (the tags
/// ordered by the parts' centres, T1 before N). In every form no two grey lines (leaders, and
/// the lines joining (a)'s window to its inset, which since the sixth review holds the apex's
/// tags, so that one leader or more is left) cross.
#[test]
fn fig8_leaders_do_not_cross() {
    let cross = |a: ((f64, f64), (f64, f64)), b: ((f64, f64), (f64, f64))| {
        let side = |p: (f64, f64), q: (f64, f64), r: (f64, f64)| {
            (q.0 - p.0) * (r.1 - p.1) - (q.1 - p.1) * (r.0 - p.0)
        };
        side(b.0, b.1, a.0) * side(b.0, b.1, a.1) < 0.0
            && side(a.0, a.1, b.0) * side(a.0, a.1, b.1) < 0.0
    };
    for (form, opts) in forms() {
        let svg = render_svg("lloyd2005-fig8", &opts);
        let l = leaders(&svg);
        assert!(l.len() >= 2, "{form}: {l:?}");
        for (i, a) in l.iter().enumerate() {
            for b in &l[..i] {
                assert!(!cross(*a, *b), "{form}: leaders {a:?} and {b:?} cross");
            }
        }
    }
}

/// Rule 4 of the figures (scheme colours mean schemes only): fig8's partition fills (its
/// translucent polygons) use none of the scheme colours (Okabe–Ito blue, vermillion, green,
/// pink, orange, sky blue); they were the palette's, one a partition.
#[test]
fn fig8_fills_use_no_scheme_colour() {
    let schemes = [
        "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9",
    ];
    for (form, opts) in forms() {
        let svg = render_svg("lloyd2005-fig8", &opts);
        let fills: Vec<String> = svg
            .split('<')
            .filter(|e| e.starts_with("polygon ") || e.starts_with("rect "))
            .filter(|e| attr(e, "opacity").is_some_and(|o| o < 1.0))
            .filter_map(|e| attr_str(e, "fill").map(str::to_string))
            .collect();
        assert!(fills.len() >= 14, "{form}: {} fills", fills.len());
        for f in &fills {
            assert!(!schemes.contains(&f.as_str()), "{form}: a fill in {f}");
        }
    }
}

/// The third review: what "error after" means must be in the figure (issue 35). Every form's
/// figure (the bare ones without their captions) says what the error after allocation is,
/// the pair (M_x/w, M_z/h) (the fifth review: "M_x/w × M_z/h" read as a product), in the
/// table's header; two columns' table writes the faces' names and the depths of 1 and 2 (one
/// column's caption does: the paragraph beside (a) that did in the figure was body text, the
/// sixth review's R6-lloyd2005-fig8-4).
#[test]
fn fig8_decodes_its_tags_and_the_error_after_in_the_figure() {
    for (form, opts) in [
        forms()[1],
        (
            "single bare",
            Options {
                bare: true,
                column: Column::Single,
                ..Options::default()
            },
        ),
    ] {
        let svg = render_svg("lloyd2005-fig8", &opts);
        // The key's lines joined as one text (it wraps to its area).
        let w = words(&svg).replace(" | ", " ");
        let has = |s: &str| w.contains(s);
        if form == "single bare" {
            assert!(has("error after (Mx/w, Mz/h)"), "{form}: {w}");
        } else {
            assert!(has("error after allocation (Mx/w, Mz/h)"), "{form}: {w}");
            for d in ["right, z 1–3.16", "left, z 3.16–10", "near face"] {
                assert!(has(d), "{form}: no {d}: {w}");
            }
        }
    }
}
