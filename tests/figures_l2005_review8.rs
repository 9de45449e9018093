//! lloyd2005-fig7 and -fig8 after the seventh figure review's one-column findings
//! (R7-2005f7-1: a log axis says so; R7-2005f8-3: (c)'s tags crowded the t axis' "2048"),
//! read back from their SVGs in all three forms.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::{attr, attr_str, forms, render_svg, texts, Font, Text};

/// R7-2005f7-1 (the figures' rule since R7-X-1: every log axis says "(log scale)" in every
/// form, in its name or, where a one-column rotated name has no room, in its panel's title).
/// Fig 7's two panels both have a log y axis: each form writes "log scale" once per panel,
/// either in the rotated y name or in the title "(a) ξ = 0, log scale" over the panel.
#[test]
fn fig7_says_log_scale_for_each_panel_in_every_form() {
    for (form, opts) in forms() {
        let svg = render_svg("lloyd2005-fig7", &opts);
        let all = texts(&Font::dejavu(), &svg);
        for panel in ["(a) ξ = 0", "(b) |ξ| = 1"] {
            let title = all
                .iter()
                .find(|t| t.content.replace('\u{a0}', " ").starts_with(panel))
                .unwrap_or_else(|| panic!("{form}: no title {panel:?}"));
            // The panel's y name: the rotated text nearest under its title.
            let name = all
                .iter()
                .filter(|t| t.rotated && t.y > title.y)
                .min_by(|a, b| a.y.total_cmp(&b.y))
                .unwrap_or_else(|| panic!("{form}: no y name under {panel:?}"));
            let said = title.content.contains("log scale") || name.content.contains("(log scale)");
            assert!(
                said,
                "{form}: {panel:?}'s log axis is not said to be one: title {:?}, y name {:?}",
                title.content, name.content
            );
        }
    }
}

/// Whether `t` is a tick label: a number (a minus sign allowed).
fn is_tick_label(t: &Text) -> bool {
    let s = t.content.replace('−', "-");
    !t.rotated && !s.is_empty() && s.parse::<f64>().is_ok()
}

/// The gap between two boxes (0 where they meet or overlap).
fn gap(a: &[f64; 4], b: &[f64; 4]) -> f64 {
    let dx = (b[0] - a[2]).max(a[0] - b[2]).max(0.0);
    let dy = (b[1] - a[3]).max(a[1] - b[3]).max(0.0);
    dx.hypot(dy)
}

/// The black outlines of (c)'s parts: `<rect>`s with a black stroke and no fill.
fn parts(svg: &str) -> Vec<[f64; 4]> {
    svg.lines()
        .filter(|l| l.starts_with("<rect"))
        .filter(|l| attr_str(l, "stroke") == Some("#000000") && attr_str(l, "fill") == Some("none"))
        .filter_map(|l| {
            let (x, y) = (attr(l, "x")?, attr(l, "y")?);
            Some([x, y, x + attr(l, "width")?, y + attr(l, "height")?])
        })
        .collect()
}

/// R7-2005f8-3: one column set (c)'s tags "L2" and "L1" between the t axis and the texture,
/// "L2" on the row of the tick label "2048", 12.5 units right of it ("2048 | L2 -"). Now, in
/// every form, no part's tag lies within 3 units of any tick label, nor, where it stands outside
/// the parts' outlines (a tag with a leader), on a tick label's row (their heights
/// overlapping) within 30 units across: a tag is not read as a tick's.
#[test]
fn fig8_tags_keep_clear_of_the_tick_labels() {
    const TAGS: [&str; 7] = ["R1", "R2", "T1", "T2", "L1", "L2", "N"];
    for (form, opts) in forms() {
        let svg = render_svg("lloyd2005-fig8", &opts);
        let all = texts(&Font::dejavu(), &svg);
        let ticks: Vec<&Text> = all.iter().filter(|t| is_tick_label(t)).collect();
        // The table's rows (black text "R1, R2", numbers) are not ticks: the table starts at
        // its header "(d) …"; only what lies above it is checked.
        let table = all
            .iter()
            .find(|t| t.content.starts_with("(d)"))
            .map_or(f64::INFINITY, |t| t.bbox[1]);
        let tags: Vec<&Text> = all
            .iter()
            .filter(|t| TAGS.contains(&t.content.as_str()) && t.bbox[3] < table)
            .collect();
        assert!(tags.len() >= 11, "{form}: tags {}", tags.len());
        let parts = parts(&svg);
        assert_eq!(parts.len(), 7, "{form}: (c)'s outlines {parts:?}");
        for tag in &tags {
            for tick in ticks.iter().filter(|k| k.bbox[3] < table) {
                let d = gap(&tag.bbox, &tick.bbox);
                assert!(
                    d >= 3.0,
                    "{form}: tag {:?} {:?} is {d:.1} units from tick label {:?} {:?}",
                    tag.content,
                    tag.bbox,
                    tick.content,
                    tick.bbox
                );
                let (cx, cy) = (
                    0.5 * (tag.bbox[0] + tag.bbox[2]),
                    0.5 * (tag.bbox[1] + tag.bbox[3]),
                );
                let outside = !parts
                    .iter()
                    .any(|r| cx > r[0] && cx < r[2] && cy > r[1] && cy < r[3]);
                let same_row = tag.bbox[1] < tick.bbox[3] && tick.bbox[1] < tag.bbox[3];
                assert!(
                    !(outside && same_row && d < 30.0),
                    "{form}: tag {:?} {:?} on the row of tick label {:?} {:?}, {d:.1} units across",
                    tag.content,
                    tag.bbox,
                    tick.content,
                    tick.bbox
                );
            }
        }
    }
}
