//! Tests of the Lloyd et al. 2006 closed-form figures' three forms (the third figure review of
//! issue 35): labels in their curves' order, keys sized to and placed by their content, the
//! one-column pages at most 525 units tall, and the captions' computed statements.

use super::*;
use crate::plot::chart::read_svg::{attr, texts};
use crate::plot::Figure;

/// The figure `name` as the command writes its SVG, in the form `column`, captioned or `bare`.
pub(super) fn svg_of(name: &str, column: Column, bare: bool) -> String {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static CALLS: AtomicUsize = AtomicUsize::new(0);
    let dir = std::env::temp_dir().join(format!(
        "lloyd2006-forms-{name}-{}-{}",
        std::process::id(),
        CALLS.fetch_add(1, Ordering::Relaxed)
    ));
    let opts = crate::plot::Options {
        bare,
        column,
        ..crate::plot::Options::default()
    };
    let files = crate::plot::render_with(name, &dir, crate::plot::Format::Svg, &opts).unwrap();
    let svg = std::fs::read_to_string(&files[0]).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    svg
}

/// The centre of every `<polygon>` filled in `fill` (a marker), in SVG units.
fn markers(svg: &str, fill: &str) -> Vec<(f64, f64)> {
    let fill = format!("fill=\"{fill}\"");
    super::tests::polygon_centres_where(svg, |l| l.contains(&fill))
}

/// `c` as an SVG writes it.
fn hex(c: RGBColor) -> String {
    format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2)
}

/// The x and y of the one text of `svg` that reads `label`.
fn text_at(svg: &str, label: &str) -> (f64, f64) {
    let t = texts(svg);
    let found: Vec<_> = t.iter().filter(|t| t.1 == label).collect();
    assert_eq!(found.len(), 1, "{label:?} written {} times", found.len());
    (attr(found[0].0, "x").unwrap(), found[0].2)
}

/// Fig 5 (the fourth review: across two columns "n′ = 100" sat against n′ = 20's curve, with
/// no marker to tell them apart): in both forms one key under both panels names the six
/// curves, each name once, in their order at z = f top to bottom (by hand from Eq 8's last
/// term (z − n + n′)²/(z (f − n + n′) n′) at z = 20: PSM 1, n′ = 2 0.525, LiSPSM 0.224,
/// n′ = 20 0.098, n′ = 100 0.059, n′ = ∞ 0.05), row by row in rows of three, every entry
/// below both x axes' tick labels (outside the plots); (a) has no note of its own.
#[test]
fn fig5_one_key_below_both_panels_in_the_curves_order() {
    for (column, names) in [
        (
            Column::Double,
            [
                "n′ = n = 1 (PSM)",
                "n′ = 2",
                "n′ ≈ 5.47 (LiSPSM)",
                "n′ = 20",
                "n′ = 100",
                "n′ = ∞ (uniform)",
            ],
        ),
        (
            Column::Single,
            ["PSM", "n′ = 2", "LiSPSM", "n′ = 20", "n′ = 100", "n′ = ∞"],
        ),
    ] {
        let svg = svg_of("lloyd2006-fig5", column, false);
        let key: Vec<(f64, f64)> = names.iter().map(|l| text_at(&svg, l)).collect();
        // Rows of three: each row level and left to right, the second under the first.
        for row in key.chunks(3) {
            assert!(
                row.iter().all(|p| (p.1 - row[0].1).abs() < 0.5),
                "{column:?}: {key:?}"
            );
            assert!(
                row.windows(2).all(|w| w[1].0 > w[0].0),
                "{column:?}: {key:?}"
            );
        }
        assert!(key[3].1 > key[0].1 + 5.0, "{column:?}: {key:?}");
        // Both panels' tick labels "20" (the far plane) lie above the key.
        let ticks: Vec<f64> = texts(&svg)
            .iter()
            .filter(|t| t.1 == "20")
            .map(|t| t.2)
            .collect();
        assert_eq!(ticks.len(), 2, "{column:?}");
        assert!(ticks.iter().all(|&y| y < key[0].1), "{column:?}: {ticks:?}");
        assert!(!svg.contains("curves as in (b)"), "{column:?}");
    }
}

/// Fig 6 (the third review): the key, three entries, sits inside the plot (between the
/// tick labels "−1" and "1" of its x axis, above them) in one column of three rows (it was a
/// two-column box below, 40 % empty); where M_z and S̄ meet for η ≥ 0 (both
/// (f − n)/(2 tan θ) = 85.74 at η = 1), their markers lie at least 12 units apart (✚ and ◀
/// lay on each other at η ≈ 0.85); one panel, untitled (its axis names the scale).
#[test]
fn fig6_key_inside_and_markers_apart() {
    let fig = fig6().map_err(|e| e.named("lloyd2006-fig6")).unwrap();
    assert_eq!(fig.page.charts.len(), 1);
    assert_eq!(fig.page.charts[0].title, "");
    let svg = svg_of("lloyd2006-fig6", Column::Double, false);
    let boxes: Vec<(f64, f64, f64)> = svg
        .lines()
        .filter(|l| l.starts_with("<rect") && l.contains("stroke=\"#787878\""))
        .map(|l| {
            (
                attr(l, "x").unwrap(),
                attr(l, "x").unwrap() + attr(l, "width").unwrap(),
                attr(l, "y").unwrap() + attr(l, "height").unwrap(),
            )
        })
        .collect();
    assert_eq!(boxes.len(), 1, "{boxes:?}");
    let tick = |label: &str| {
        let t = texts(&svg);
        let t = t.iter().find(|t| t.1 == label).unwrap();
        (attr(t.0, "x").unwrap(), t.2)
    };
    let ((left, axis_y), (right, _)) = (tick("−1"), tick("1"));
    let (x0, x1, bottom) = boxes[0];
    assert!(
        x0 > left && x1 < right && bottom < axis_y,
        "{boxes:?} {left} {right} {axis_y}"
    );
    let (x, y) = text_at(&svg, "Mx");
    assert!(x > x0 && x < x1 && y < bottom, "M_x outside the key");
    let inside = texts(&svg)
        .iter()
        .filter(|t| {
            let x = attr(t.0, "x").unwrap();
            x > x0 && x < x1 && t.2 > bottom - 70.0 && t.2 < bottom
        })
        .count();
    assert_eq!(inside, 3, "the key's three entries");
    let (mz, s) = (
        markers(&svg, &hex(FIG6_LOOKS[1].0)),
        markers(&svg, &hex(FIG6_LOOKS[2].0)),
    );
    let plot = |p: &&(f64, f64)| p.1 < axis_y && !(p.0 > x0 && p.0 < x1 && p.1 < bottom);
    let mut closest = f64::INFINITY;
    for p in mz.iter().filter(plot) {
        for q in s.iter().filter(plot) {
            closest = closest.min((p.0 - q.0).hypot(p.1 - q.1));
        }
    }
    assert!(
        closest.is_finite() && closest >= 12.0,
        "M_z and S̄ markers {closest} apart"
    );
}

/// Fig 10 in one column (the fourth review: its axis ended at 10³, which cut off f/n = 10⁴'s
/// curve, 8.66×10³ at k = 1): one panel whose y range holds every point of every curve,
/// S̄ from 1 to 10⁴ as across two columns. By hand, Eq 18 at k = 1 is the unpartitioned
/// (f/n − 1)/(2 tan θ) = 9999/(2 tan 30°) = 8659.4, the largest value drawn, and the least is
/// f/n = 10's optimum ln 10/(2 tan 30°) = 1.994; the page is at most 525 units tall; and the
/// caption names no panel one column does not draw (the eleventh review, R11-lloyd2006-fig10-1,
/// reversing R8-X-6's "say what is left out").
#[test]
fn fig10_one_column_holds_the_data() {
    let fig = fig10().map_err(|e| e.named("lloyd2006-fig10")).unwrap();
    let single = fig.single.as_ref().unwrap();
    assert_eq!(single.page.charts.len(), 1);
    let c = &single.page.charts[0];
    let (lo, hi) = c
        .series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.1))
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    let tan = 30f64.to_radians().tan();
    assert!((hi - 9999.0 / (2.0 * tan)).abs() < 1e-6, "{hi}");
    assert!((lo - 10f64.ln() / (2.0 * tan)).abs() < 1e-9, "{lo}");
    assert!(
        c.y.min <= lo && hi <= c.y.max,
        "{:?} for {lo} … {hi}",
        (c.y.min, c.y.max)
    );
    assert!(fig.single_size().unwrap().1 <= 525);
    // The caption describes only what one column draws (R11-lloyd2006-fig10-1).
    let caption = single.page.caption.join(" ");
    assert!(!caption.contains("(b)"), "{caption}");
    assert!(!caption.contains("left"), "{caption}");
}

/// Fig 12 (a)'s title (the fourth review: "(a) overhead, behind (dashed)", but FP+ZP+W behind
/// had no dashed line; the sixth: colour is the scheme, the light its line and fill):
/// "overhead solid, behind dashed" in both forms, and what it claims is drawn: every
/// "…, overhead" entry a solid line or filled markers, every "…, behind" entry a dashed line
/// or open markers.
#[test]
fn fig12_titles_claim_only_what_is_drawn() {
    use crate::plot::chart::Dash;
    let fig = fig12().map_err(|e| e.named("lloyd2006-fig12")).unwrap();
    let single = &fig.single.as_ref().unwrap().page.charts[0];
    for (c, title) in [
        (
            &fig.page.charts[0],
            "(a) overhead: solid, filled;\nbehind: dashed, hollow",
        ),
        (
            single,
            "overhead: solid, filled;\nbehind: dashed, hollow; log scale",
        ),
    ] {
        assert_eq!(c.title, title);
        // Every key entry names its light, in both forms, and no two entries read alike (the
        // tenth review, R10-lloyd2006-fig12-1: one column's key gave the scheme alone, two
        // "FP+ZP+W" and a "ZP = ZP+W" that is false overhead).
        let labels: Vec<&str> = c.series.iter().filter_map(|s| s.label.as_deref()).collect();
        assert_eq!(labels.len(), 5, "{labels:?}");
        for (i, l) in labels.iter().enumerate() {
            assert!(l.ends_with(", overhead") || l.ends_with(", behind"), "{l}");
            assert!(!labels[..i].contains(l), "{l} twice");
        }
        for (light, dash, open) in [
            ("overhead", Dash::Solid, false),
            ("behind", Dash::Dashed, true),
        ] {
            let family: Vec<&Series> = c
                .series
                .iter()
                .filter(|s| s.label.as_deref().is_some_and(|l| l.ends_with(light)))
                .collect();
            assert!(family.len() >= 2, "{light}: {:?}", c.series);
            for s in &family {
                let joined = !s.markers && s.points.iter().all(|p| p.1.is_finite());
                assert_eq!(s.hollow, open, "{light}: {:?}", s.label);
                assert!(
                    s.markers || (s.dash == dash && (joined || s.sample || s.reference)),
                    "{light}: {:?} is not {dash:?}",
                    s.label
                );
            }
        }
    }
}

/// Fig 12 (the third review: "55.0 needs tan θ = 1 while the figure states θ = 30°"): the
/// caption says that Eq 21's face sub-frusta have tan θ_eff = 1 whatever θ. By hand: from
/// behind a face's triangle has base 2f tan θ and height f tan θ, so tan θ_eff =
/// (f tan θ)/(f tan θ) = 1; with it Eq 21 at k = 4, f/n = 1000 gives 8(1000^{1/4} − 1) + 1 =
/// 37.987, Fig 12's point; with tan 30° it would be 64.4. The key groups its entries by
/// light: overhead in one column, behind in the other.
#[test]
fn fig12_caption_gives_theta_eff_and_key_grouped_by_light() {
    let fig = fig12().map_err(|e| e.named("lloyd2006-fig12")).unwrap();
    let caption = fig.page.caption.join(" ").replace('\u{a0}', " ");
    assert!(caption.contains("tan θ_{eff} = 1 (45°)"), "{caption}");
    let single = fig.single.as_ref().unwrap().page.caption.join(" ");
    assert!(single.replace('\u{a0}', " ").contains("tan θ_{eff} = 1"));
    let behind = fig.page.charts[0]
        .series
        .iter()
        .find(|s| s.label.as_deref() == Some("FP+ZP+W, behind"))
        .unwrap();
    let at17 = behind.points.iter().find(|p| p.0 == 17.0).unwrap().1;
    let by_hand = 8.0 * (1000f64.powf(0.25) - 1.0) + 1.0;
    assert!((at17 - by_hand).abs() < 1e-9, "{at17} vs {by_hand}");
    let svg = svg_of("lloyd2006-fig12", Column::Double, false);
    let x = |l: &str| text_at(&svg, l).0;
    let over = [
        x("ZP, overhead"),
        x("ZP+W, overhead"),
        x("FP+ZP+W, overhead"),
    ];
    let back = [x("ZP = ZP+W, behind"), x("FP+ZP+W, behind")];
    assert!(over.iter().all(|v| (v - over[0]).abs() < 0.5), "{over:?}");
    assert!(back.iter().all(|v| (v - back[0]).abs() < 0.5), "{back:?}");
    assert!(back[0] > over[0] + 20.0);
}

/// Fig 12 (b)'s note names the scheme of each value it gives (the bare figure has no caption to
/// say which of "37.99 < 38.32" was which): in the bare SVG, "FP+ZP+W 37.99" over
/// "ZP = ZP+W 38.32", by hand Eq 21 at k = 4, 8(1000^{1/4} − 1) + 1 = 37.987, and Eq 20 with
/// 17 maps, 17 · 1000^{2/17} = 38.317.
#[test]
fn fig12_note_names_each_value() {
    let (fp, zp) = (
        8.0 * (1000f64.powf(0.25) - 1.0) + 1.0,
        17.0 * 1000f64.powf(2.0 / 17.0),
    );
    let svg = svg_of("lloyd2006-fig12", Column::Double, true);
    let first = text_at(&svg, &format!("FP+ZP+W {fp:.2}"));
    let second = text_at(&svg, &format!("ZP = ZP+W {zp:.2}"));
    assert!(second.1 > first.1 && (second.0 - first.0).abs() < 0.5);
}

/// Fig 13's caption says why θ does not matter (Eq 20 has none, Eq 21's faces have
/// tan θ_eff = 1, as by hand in the test above) and how the regions read.
#[test]
fn fig13_caption_says_any_theta() {
    let svg = svg_of("lloyd2006-fig13", Column::Double, false);
    let caption: String = texts(&svg)
        .iter()
        .filter(|t| t.0.contains("#323232"))
        .map(|t| t.1.clone())
        .collect::<Vec<_>>()
        .join(" ")
        .replace('\u{a0}', " ");
    assert!(caption.contains("tan θeff = 1"), "{caption}");
    assert!(caption.contains("FP+ZP+W needs less storage"), "{caption}");
}

/// Every one of these figures' one-column pages is at most 525 units (420 pt printed) tall
/// (the third review: 640 pt, a whole column).
#[test]
fn one_column_pages_fit_420_pt() {
    let keyed = [
        ("fig5", fig5().ok().unwrap()),
        ("fig6", fig6().ok().unwrap()),
        ("fig10", fig10().ok().unwrap()),
        ("fig12", fig12().ok().unwrap()),
    ];
    for (name, fig) in &keyed {
        let (w, h) = fig.single_size().unwrap();
        assert!(w == 300 && h <= 525, "{name}: {w} × {h}");
    }
    let (w, h) = fig13().ok().unwrap().single_size().unwrap();
    assert!(w == 300 && h <= 525, "fig13: {w} × {h}");
}

/// Fig 5's captions say that the image and the shadow map have equal resolution (the eleventh
/// review, R11-lloyd2006-fig5-1): Eq 7, 8 carry res_i/res_s and res_i/res_t, which the plotted
/// m_x/f and m_z·2 tan θ/(f − n) leave out, so without it the values are ambiguous.
#[test]
fn fig5_captions_state_equal_resolution() {
    let fig = fig5().map_err(|e| e.named("lloyd2006-fig5")).unwrap();
    let single = fig.single.as_ref().unwrap();
    for (caption, want) in [
        (
            &fig.page.caption,
            "image and shadow map of equal resolution",
        ),
        (&single.page.caption, "image and map of equal resolution"),
    ] {
        let text = caption.join(" ");
        assert!(text.contains(want), "{want:?} in {text}");
    }
}
