//! One style for the axes of every figure (issue 35):
//! - a panel's top tick label never touches the panel title above it (the review found "10⁴"
//!   in lloyd2006-fig10 (a) and barroso-fig7 (a), and "10⁷" in lloyd2006-worst-case (a), 1–3 pt
//!   under the title): at least 4 pt between them as printed;
//! - the y-axis label stands at the same distance from the axis in every panel of a figure
//!   (issue item 6, "keep the axis-label offset the same across panels").
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::*;

/// The least space between a panel title and a text under it, in points as printed.
const TITLE_GAP_PT: f64 = 4.0;

/// plotters' panel-title size (15) as the SVG writes it (`font-size` = s/1.24).
const TITLE_FS: f64 = 15.0 / 1.24;

/// A y tick label: anchored at its end, centred on its tick.
fn is_y_tick(t: &Text) -> bool {
    !t.rotated && t.tag.contains("text-anchor=\"end\"") && t.tag.contains("dy=\"0.5ex\"")
}

/// The tick labels of `svg` that come within [`TITLE_GAP_PT`] of a panel title above them
/// (their boxes overlapping across): "title / tick: gap".
fn crowded_titles(font: &Font, svg: &str) -> Vec<String> {
    let gap = TITLE_GAP_PT / points_per_unit(svg);
    let all = texts(font, svg);
    let titles = all
        .iter()
        .filter(|t| !t.rotated && (t.fs - TITLE_FS).abs() < 0.01);
    let mut bad = Vec::new();
    for title in titles {
        for t in all.iter().filter(|t| is_y_tick(t)) {
            let (a, b) = (title.bbox, t.bbox);
            let across = a[2].min(b[2]) - a[0].max(b[0]);
            if across > 0.0 && b[1] > a[1] && b[1] - a[3] < gap {
                bad.push(format!(
                    "{:?} is {:.1} units under {:?} (at least {gap:.1})",
                    t.content,
                    b[1] - a[3],
                    title.content
                ));
            }
        }
    }
    bad
}

/// The distance from each y-axis label (a text read upwards) to its axis's tick labels (their
/// anchor, at the axis): the nearest y tick labels to its right, within its height.
fn y_label_offsets(font: &Font, svg: &str) -> Vec<(String, f64)> {
    let all = texts(font, svg);
    let ticks: Vec<&Text> = all.iter().filter(|t| is_y_tick(t)).collect();
    all.iter()
        .filter(|t| t.tag.contains("rotate(270"))
        // An empty text draws nothing: no label (barroso-fig5 names its y axes in its left
        // column only).
        .filter(|t| !t.content.trim().is_empty())
        .filter_map(|l| {
            ticks
                .iter()
                .filter(|t| t.x > l.x && t.x - l.x < 150.0)
                .filter(|t| t.y >= l.bbox[1] && t.y <= l.bbox[3])
                .map(|t| t.x - l.x)
                .min_by(f64::total_cmp)
                .map(|d| (l.content.clone(), d))
        })
        .collect()
}

/// The measures themselves, on hand-made SVGs: a tick label "10⁴" (its superscript raised 3.6
/// units) whose capitals are 3 units under a title's descent is crowded, 8 units under it is
/// not; two panels whose y labels stand 54 and 40 units left of their ticks differ.
#[test]
fn crowding_and_offsets_are_measured() {
    let font = Font::dejavu();
    // Title at y = 10, top anchor: baseline 10 + 0.76·12.097 = 19.19, descent to 22.09.
    // Tick, centred: baseline y + 0.27·10.484, superscript top at baseline − 3.6 − 0.73·7.2.
    let page = |tick_y: f64| {
        format!(
            "<svg width=\"200pt\" height=\"100pt\" viewBox=\"0 0 200 100\">\n\
             <text x=\"100\" y=\"10\" dy=\"0.76em\" text-anchor=\"middle\" font-size=\"{TITLE_FS}\">\
             (a) a panel title</text>\n\
             <text x=\"60\" y=\"{tick_y}\" dy=\"0.5ex\" text-anchor=\"end\" font-size=\"10.484\">\
             10<tspan dy=\"-3.6\" font-size=\"7.2\">4</tspan></text>\n</svg>"
        )
    };
    let top = |y: f64| y + 0.27 * 10.484 - 3.6 - 0.73 * 7.2;
    let descent = 10.0 + 0.76 * TITLE_FS + 0.24 * TITLE_FS;
    // Solve top(y) = descent + 3 and + 8.
    let at = |d: f64| descent + d - top(0.0);
    assert_eq!(crowded_titles(&font, &page(at(3.0))).len(), 1);
    assert!(crowded_titles(&font, &page(at(8.0))).is_empty());
    let two = |x2: f64| {
        format!(
            "<svg width=\"300pt\" height=\"100pt\" viewBox=\"0 0 300 100\">\n\
             <text x=\"10\" y=\"50\" dy=\"0.76em\" text-anchor=\"middle\" font-size=\"12\" \
             transform=\"rotate(270, 10, 50)\">M</text>\n\
             <text x=\"64\" y=\"50\" dy=\"0.5ex\" text-anchor=\"end\" font-size=\"10\">1</text>\n\
             <text x=\"{x2}\" y=\"50\" dy=\"0.76em\" text-anchor=\"middle\" font-size=\"12\" \
             transform=\"rotate(270, {x2}, 50)\">M</text>\n\
             <text x=\"200\" y=\"50\" dy=\"0.5ex\" text-anchor=\"end\" font-size=\"10\">1</text>\n\
             </svg>"
        )
    };
    let offsets = |x2: f64| {
        y_label_offsets(&font, &two(x2))
            .iter()
            .map(|o| o.1)
            .collect::<Vec<_>>()
    };
    assert_eq!(offsets(146.0), vec![54.0, 54.0]);
    assert_eq!(offsets(160.0), vec![54.0, 40.0]);
}

/// No y tick label of any figure, in any layout, comes within 4 pt of a panel title above it.
#[test]
fn top_tick_labels_keep_clear_of_panel_titles() {
    let font = Font::dejavu();
    let mut bad = Vec::new();
    let mut titled = 0;
    for (name, layout, svg) in all_svgs() {
        titled += usize::from(
            texts(&font, svg)
                .iter()
                .any(|t| (t.fs - TITLE_FS).abs() < 0.01),
        );
        for b in crowded_titles(&font, svg) {
            bad.push(format!("{name} ({layout}): {b}"));
        }
    }
    assert!(titled > 10, "only {titled} figures have panel titles");
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

/// Figures whose panels set their own label areas (src/plot/layout.rs: lloyd2005-fig8's
/// texture panel (c) has wider tick labels, texel counts to 2048): not yet held to one offset.
const OWN_LABEL_AREAS: [&str; 1] = ["lloyd2005-fig8"];

/// Figures with a second, outer column of turned y text: zhang-fig3 names each row by its γ
/// beside the row's panels and, farther out, the height axis once for all rows ("height y",
/// the fifth review: it stood in the row of scheme names). The row labels are held to one
/// offset; the height name must stand farther out than every one of them. In two columns
/// zhang-fig3's "height y" is upright over its ticks' column (the sixth review,
/// R6-zhang-fig3-4: turned beside the turned "γ = 60°" it read as one label), so only the one
/// column's turned name is held to this.
const OUTER_NAME: [(&str, &str); 1] = [("zhang-fig3", "height y")];

/// In every figure, in every layout, the y-axis labels of its panels stand at one distance
/// from their axes (within half a unit).
#[test]
fn y_axis_labels_stand_alike_in_a_figure() {
    let font = Font::dejavu();
    let mut bad = Vec::new();
    let mut pairs = 0;
    for (name, layout, svg) in all_svgs() {
        if OWN_LABEL_AREAS.contains(&name.as_str()) {
            continue;
        }
        let mut o = y_label_offsets(&font, svg);
        if let Some((_, outer)) = OUTER_NAME.iter().find(|(n, _)| *n == name.as_str()) {
            let (names, rows): (Vec<_>, Vec<_>) =
                o.into_iter().partition(|(l, _)| l.starts_with(outer));
            if names.is_empty() && layout == "Single" {
                bad.push(format!("{name} ({layout}): no {outer:?} name"));
            }
            for (l, d) in &names {
                if let Some((r, dr)) = rows.iter().find(|(_, dr)| dr + 0.5 > *d) {
                    bad.push(format!(
                        "{name} ({layout}): {l:?} at {d} is not outside {r:?} at {dr}"
                    ));
                }
            }
            o = rows;
        }
        pairs += o.len().saturating_sub(1);
        if let Some((first, d0)) = o.first() {
            for (label, d) in &o[1..] {
                if (d - d0).abs() > 0.5 {
                    bad.push(format!(
                        "{name} ({layout}): {label:?} stands {d} from its axis, {first:?} {d0}"
                    ));
                }
            }
        }
    }
    assert!(pairs > 10, "only {pairs} pairs of panels compared");
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
