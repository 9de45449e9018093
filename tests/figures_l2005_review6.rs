//! The Lloyd et al. 2005 figures after the sixth figure review (R6), read back from their SVGs
//! in all three forms (two columns, bare, one column): fig4's g₀ label clear of every curve,
//! fig7's k = 1 markers inside the frame, and fig8's table header, texture ticks, inset and
//! caption.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::{attr_str, forms, points, render_svg, segment_enters, texts, Font, Text};

fn all_texts(svg: &str) -> Vec<Text> {
    texts(&Font::dejavu(), svg)
}

/// R6-lloyd2005-fig4-1: the label "g0 = 1/√(f/n)" stood between the ξ = ½ and ξ = −1 curves,
/// each within 1 unit of its text. In every form no curve (a polyline of another colour than
/// the g₀ line's grey #5A5A5A, the gridlines and axes excluded; a dashed curve's every piece)
/// passes within 3 units of its text.
#[test]
fn fig4_g0_label_has_no_curve_within_3_units() {
    for (form, opts) in forms() {
        let svg = render_svg("lloyd2005-fig4", &opts);
        let all = all_texts(&svg);
        let g0 = all
            .iter()
            .find(|t| t.content.starts_with("g0 = 1/√(f/n)"))
            .unwrap_or_else(|| panic!("{form}: no g0 label"));
        // The curves: polylines in a colour that is no grey (grid greys, black axes, the g₀
        // line's grey and white halos are not curves), a dashed curve in many pieces.
        let curves: Vec<(String, Vec<(f64, f64)>)> = svg
            .lines()
            .filter(|l| l.starts_with("<polyline"))
            .filter_map(|l| {
                let c = attr_str(l, "stroke")?;
                (c.len() == 7 && !(c[1..3] == c[3..5] && c[3..5] == c[5..7]))
                    .then(|| (c.to_string(), points(l)))
            })
            .collect();
        let mut colours: Vec<&str> = curves.iter().map(|c| c.0.as_str()).collect();
        colours.sort_unstable();
        colours.dedup();
        assert_eq!(colours.len(), 5, "{form}: {colours:?}");
        for (_, c) in &curves {
            for w in c.windows(2) {
                assert!(
                    !segment_enters(w[0], w[1], &g0.bbox, -3.0),
                    "{form}: a curve passes within 3 units of the g0 label {:?}: {:?}",
                    g0.bbox,
                    w
                );
            }
        }
    }
}

/// R6-lloyd2005-fig7-5: every line starts at (1, 1), and with the x axis from k = 1 the four
/// k = 1 markers lay on the y axis and covered its tick. In every form each panel's markers
/// (the polygons) lie right of its y axis (the long vertical black line left of them) by at
/// least 1 unit.
#[test]
fn fig7_k_1_markers_sit_inside_the_frame() {
    for (form, opts) in forms() {
        let svg = render_svg("lloyd2005-fig7", &opts);
        let spines: Vec<(f64, f64, f64)> = svg
            .lines()
            .filter(|l| l.starts_with("<polyline") && attr_str(l, "stroke") == Some("#000000"))
            .map(points)
            .filter(|p| p.len() == 2 && p[0].0 == p[1].0 && (p[1].1 - p[0].1).abs() > 60.0)
            .map(|p| (p[0].0, p[0].1.min(p[1].1), p[0].1.max(p[1].1)))
            .collect();
        assert_eq!(spines.len(), 2, "{form}: {spines:?}");
        let markers: Vec<Vec<(f64, f64)>> = svg
            .lines()
            .filter(|l| l.starts_with("<polygon"))
            .map(points)
            .collect();
        assert!(markers.len() >= 80, "{form}: {} markers", markers.len());
        for m in &markers {
            let x0 = m.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
            let y = m.iter().map(|p| p.1).sum::<f64>() / m.len() as f64;
            // The panel's axis: the nearest spine left of the marker at its height.
            let spine = spines
                .iter()
                .filter(|s| s.0 < x0 + 20.0 && s.1 <= y && y <= s.2)
                .map(|s| s.0)
                .fold(f64::NEG_INFINITY, f64::max);
            assert!(
                x0 >= spine + 1.0,
                "{form}: a marker from x {x0} on the y axis at {spine}"
            );
        }
    }
}

/// R6-lloyd2005-fig8-5: the table's last column was headed "error after", its meaning in the
/// (d) title line. Across two columns (captioned and bare) its header (grey #5A5A5A) reads
/// "error after allocation (Mx/w, Mz/h)" (subscripts are tspans) and the (d) title no longer
/// says it.
#[test]
fn fig8_table_header_says_error_after_allocation() {
    for (form, opts) in &forms()[..2] {
        let svg = render_svg("lloyd2005-fig8", opts);
        let all = all_texts(&svg);
        let header = all
            .iter()
            .filter(|t| t.tag.contains("fill=\"#5A5A5A\""))
            .map(|t| t.content.as_str())
            .collect::<Vec<_>>();
        assert!(
            header.contains(&"error after allocation (Mx/w, Mz/h)"),
            "{form}: {header:?}"
        );
        let title = all
            .iter()
            .find(|t| t.content.starts_with("(d) "))
            .expect("the (d) title");
        assert!(
            !title.content.contains("error after"),
            "{form}: {}",
            title.content
        );
    }
}

/// R6-lloyd2005-fig8-3: (c)'s s tick labels "1024" and "2048" were centred on their ticks,
/// 3.5 units apart in one column (which now labels s at its ends only). In every form the s
/// axis' "2048" is centred (text-anchor middle) on its tick (a black vertical line down from the
/// axis line above it; R19-lloyd2005-fig8-1: right-aligned to it, it read as a label of
/// s ≈ 1730), inside the page, and the s labels on its row keep at least 6 units apart.
#[test]
fn fig8_texture_s_labels_centred_on_their_ticks_and_apart() {
    for (form, opts) in forms() {
        let svg = render_svg("lloyd2005-fig8", &opts);
        let all = all_texts(&svg);
        // The x axes: level black lines longer than 40 units.
        let axes: Vec<(f64, f64, f64)> = svg
            .lines()
            .filter(|l| l.starts_with("<polyline") && attr_str(l, "stroke") == Some("#000000"))
            .map(points)
            .filter(|p| p.len() == 2 && p[0].1 == p[1].1 && (p[1].0 - p[0].0).abs() > 40.0)
            .map(|p| (p[0].0.min(p[1].0), p[0].0.max(p[1].0), p[0].1))
            .collect();
        // The s axis' 2048: the "2048" below an axis line (the t axis' one is beside it).
        let last = all
            .iter()
            .filter(|t| t.content == "2048" && !t.rotated)
            .find(|t| {
                axes.iter()
                    .any(|a| t.bbox[1] > a.2 && t.bbox[1] - a.2 < 15.0)
            })
            .unwrap_or_else(|| panic!("{form}: no 2048 under an axis"));
        assert_eq!(
            attr_str(&last.tag, "text-anchor"),
            Some("middle"),
            "{form}: {}",
            last.tag
        );
        let axis = axes
            .iter()
            .filter(|a| last.bbox[1] > a.2 && a.0 <= last.x && last.x <= a.1 + 0.5)
            .min_by(|a, b| (last.bbox[1] - a.2).total_cmp(&(last.bbox[1] - b.2)))
            .unwrap();
        // Its tick: a vertical black line down from the axis at the label's centre (the
        // texture's end; the equal aspect may draw the axis further).
        let tick = svg
            .lines()
            .filter(|l| l.starts_with("<polyline") && attr_str(l, "stroke") == Some("#000000"))
            .map(points)
            .any(|p| {
                p.len() == 2
                    && p[0].0 == p[1].0
                    && (p[0].0 - last.x).abs() <= 0.5
                    && (p[0].1.min(p[1].1) - axis.2).abs() <= 0.5
            });
        assert!(tick, "{form}: no tick at 2048's centre {}", last.x);
        // The page's right edge in its units: the view box's x and width (bare: the crop).
        let view_box: Vec<f64> = attr_str(svg.lines().next().unwrap(), "viewBox")
            .unwrap()
            .split(' ')
            .map(|v| v.parse().unwrap())
            .collect();
        let right = view_box[0] + view_box[2];
        assert!(
            last.bbox[2] <= right,
            "{form}: {:?} past {right}",
            last.bbox
        );
        let mut row: Vec<&Text> = all
            .iter()
            .filter(|t| {
                (t.y - last.y).abs() < 0.5 && ["0", "1024", "2048"].contains(&t.content.as_str())
            })
            .filter(|t| t.bbox[0] > axis.0 - 20.0)
            .collect();
        row.sort_by(|a, b| a.bbox[0].total_cmp(&b.bbox[0]));
        assert!(row.len() >= 2, "{form}: {} s labels", row.len());
        for w in row.windows(2) {
            assert!(
                w[1].bbox[0] - w[0].bbox[2] >= 6.0,
                "{form}: {} and {} {:.1} apart",
                w[0].content,
                w[1].content,
                w[1].bbox[0] - w[0].bbox[2]
            );
        }
    }
}

/// R6-lloyd2005-fig8-5: the caption's "(d) M_x/w is lower below a column's largest M_x" was
/// not understandable. The two-column caption names the parts whose M_x/w is lower and both
/// values, as the table prints them (its "error after" pairs' first numbers, read from the
/// SVG: the least and the greatest), and why ("larger M").
#[test]
fn fig8_caption_says_which_error_after_is_lower_and_why() {
    let svg = render_svg("lloyd2005-fig8", &forms()[0].1);
    let all = all_texts(&svg);
    let firsts: Vec<f64> = all
        .iter()
        .filter_map(|t| {
            let inner = t.content.strip_prefix('(')?.strip_suffix(')')?;
            let (a, _) = inner.split_once(", ")?;
            if a.contains('%') {
                return None;
            }
            a.parse().ok()
        })
        .collect();
    assert_eq!(firsts.len(), 7, "{firsts:?}");
    let lo = firsts.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = firsts.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    assert!(lo < hi, "{firsts:?}");
    let caption = all
        .iter()
        .filter(|t| t.tag.contains("fill=\"#323232\""))
        .map(|t| t.content.replace('\u{a0}', " "))
        .collect::<Vec<_>>()
        .join(" ");
    let want = format!("{lo:.2} < {hi:.2}");
    assert!(caption.contains(&want), "no {want} in {caption}");
    assert!(caption.contains("(d) R1, R2:"), "{caption}");
    assert!(caption.contains("larger M"), "{caption}");
}
