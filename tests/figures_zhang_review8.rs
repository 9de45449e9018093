//! zhang-fig3 after the seventh figure review (R7-Z3-1: "⊥ light" unexplained; R7-Z3-2: one
//! column's rows without ticks beside bare axis bars, the half scale said on the axis only),
//! read back from its SVGs.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::{attr, attr_str, forms, points, render_svg, texts, Font, Text};

/// The caption's lines (#323232) as one text, no-break spaces read as spaces.
fn caption(all: &[Text]) -> String {
    all.iter()
        .filter(|t| attr_str(&t.tag, "fill") == Some("#323232"))
        .map(|t| t.content.replace('\u{a0}', " "))
        .collect::<Vec<_>>()
        .join(" ")
}

/// R7-Z3-1: the blocks' titles wrote "(a) E_p = 2 m_z (⊥ light)", notation no text explained.
/// In no form does any text of the figure write "⊥"; the titles read "(a) E_p = 2 m_z" and
/// "(b) E_q = 2 m_x" (subscripts read inline); each captioned form says in words what m is,
/// Lloyd 2006's error on a surface facing the light ("m: Lloyd 2006's error … facing the light",
/// written out since the eleventh review, R11-zhang-fig3-1), and the factor 2 ("×2 for Zhang's …
/// [−1, 1]"), in at most five lines.
#[test]
fn m_is_explained_in_words_not_marked_in_the_titles() {
    let font = Font::dejavu();
    for (form, opts) in forms() {
        let svg = render_svg("zhang-fig3", &opts);
        let all = texts(&font, &svg);
        let marked: Vec<&str> = all
            .iter()
            .filter(|t| t.content.contains('⊥'))
            .map(|t| t.content.as_str())
            .collect();
        assert!(marked.is_empty(), "{form}: {marked:?}");
        // One column's titles also say what E_p and E_q are (R14-Z3-1).
        let titles: [&str; 2] = if form == "single" {
            [
                "(a) Ep = 2 mz, along screen y",
                "(b) Eq = 2 mx, along screen x",
            ]
        } else {
            ["(a) Ep = 2 mz", "(b) Eq = 2 mx"]
        };
        for title in titles {
            assert!(
                all.iter().any(|t| t.content == title),
                "{form}: no title {title:?}"
            );
        }
        if form == "bare" {
            continue;
        }
        let lines = all
            .iter()
            .filter(|t| attr_str(&t.tag, "fill") == Some("#323232"))
            .count();
        assert!((1..=5).contains(&lines), "{form}: {lines} caption lines");
        let text = caption(&all);
        // Two columns cite Lloyd 2006's Eq 7, 8; one column has no room (R13-zhang-fig3-1 took it
        // for SSM's n′).
        // Two columns name the span Zhang's; one column, whose caption starts with Zhang's
        // figure, gave those words to θ's definition (R21-zhang-fig3-1).
        let factor = if form == "single" {
            "×2 for [−1, 1]"
        } else {
            "×2 for Zhang's span [−1, 1]"
        };
        for want in [
            "m: Lloyd 2006's error",
            "facing the light",
            factor,
            "half field of view θ",
        ] {
            assert!(text.contains(want), "{form}: no {want:?} in {text}");
        }
    }
}

/// R7-Z3-2 (the decision: every row ticked, "(½ scale)" kept on the axis; the caption's
/// "vertical scale halved" gave its room to m written out, R11-zhang-fig3-1 and -3). One column draws its nine rows of panels at half the heights'
/// scale: the first column's frames (grey, #969696, the leftmost of each row) each have two
/// tick marks left of them, 5 units long and level, at the same heights in the row as the
/// labelled middle rows' ±40 (within 0.6 units), symmetric about the row's middle; the caption
/// the turned axis name says "height y (drawn at ½ the scale of z)".
#[test]
fn one_column_ticks_every_row_and_says_the_half_scale() {
    let opts = &forms()[2].1;
    let svg = render_svg("zhang-fig3", opts);
    let all = texts(&Font::dejavu(), &svg);
    // The first column's frames: the leftmost grey frame of each row.
    let mut frames: Vec<[f64; 4]> = svg
        .lines()
        .filter(|l| l.starts_with("<rect") && attr_str(l, "stroke") == Some("#969696"))
        .filter_map(|l| {
            let (x, y) = (attr(l, "x")?, attr(l, "y")?);
            Some([x, y, x + attr(l, "width")?, y + attr(l, "height")?])
        })
        .collect();
    let left = frames.iter().map(|f| f[0]).fold(f64::INFINITY, f64::min);
    frames.retain(|f| (f[0] - left).abs() < 0.5);
    frames.sort_by(|a, b| a[1].total_cmp(&b[1]));
    assert_eq!(frames.len(), 9, "{frames:?}");
    // Level black marks 5 units long, ending left of the frames, within 12 units of them.
    let ticks: Vec<(f64, f64)> = svg
        .lines()
        .filter(|l| l.starts_with("<polyline") && attr_str(l, "stroke") == Some("#000000"))
        .map(points)
        .filter(|p| {
            p.len() == 2
                && (p[0].1 - p[1].1).abs() < 0.01
                && ((p[1].0 - p[0].0).abs() - 5.0).abs() < 0.01
        })
        .map(|p| (p[0].0.max(p[1].0), p[0].1))
        .filter(|(x1, _)| *x1 <= left && *x1 >= left - 12.0)
        .collect();
    // The offsets of each row's marks from its middle.
    let offsets: Vec<Vec<f64>> = frames
        .iter()
        .map(|f| {
            let mid = 0.5 * (f[1] + f[3]);
            let mut o: Vec<f64> = ticks
                .iter()
                .filter(|t| t.1 >= f[1] - 0.5 && t.1 <= f[3] + 0.5)
                .map(|t| t.1 - mid)
                .collect();
            o.sort_by(f64::total_cmp);
            o
        })
        .collect();
    // The labelled middle row of the first block: its marks stand by "40" and "−40".
    let reference = &offsets[1];
    assert_eq!(reference.len(), 2, "the middle row's marks {reference:?}");
    for (row, o) in offsets.iter().enumerate() {
        assert_eq!(o.len(), 2, "row {row}: marks at {o:?}");
        for (a, b) in o.iter().zip(reference) {
            assert!(
                (a - b).abs() <= 0.6,
                "row {row}: {o:?} against {reference:?}"
            );
        }
        assert!((o[0] + o[1]).abs() <= 1.0, "row {row}: {o:?} not symmetric");
    }
    assert!(
        all.iter()
            .any(|t| t.rotated && t.content == "height y (drawn at ½ the scale of z)"),
        "no turned \"height y (drawn at ½ the scale of z)\""
    );
}
