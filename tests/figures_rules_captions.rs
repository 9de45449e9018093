//! The lead's caption and title rules for every figure (issue 35; the review's cross-figure
//! issues 5 and 6: one-column captions of 7 to 10 lines, formulas broken across lines such as
//! "f =" / "100", "(2" / "tan θ)", "4k" / "+ 1", a one-word last line "name.", and every
//! one-column title on two lines). Read from each figure's SVG in the two-column and the
//! one-column layout:
//! - a caption (the lines written at the page's left margin in the caption's grey) has at most
//!   five lines;
//! - no caption line ends with "=", "(", "+", "−" or "×", nor starts with "=", "+" or "×" (a
//!   formula's parts are joined by no-break spaces, at which the wrapper never breaks);
//! - the last line is no widow: at least 10 characters;
//! - a two-column title is one line, a one-column title at most two (it prints at 10.3 pt
//!   there, above 8.4-pt tick labels; the review asked it be no larger than needed, and the titles of
//!   the figures run to 45 characters, which one line of 240 pt cannot hold at
//!   that size).
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::*;
use shadow_aliasing::plot::{Column, Options, FIGURES, SINGLE_COLUMN};

/// The most lines a caption may take.
const MAX_LINES: usize = 5;

/// A caption's last line shorter than this many characters is a widow ("name.", "panels.",
/// "behind.": the review's examples are 5 to 7); a formula kept whole by no-break spaces
/// ("g_0 = 1/√α = 0.316.") or two words tied by one ("least maximum.") is not.
const WIDOW: usize = 10;

/// The caption's lines of `svg`: texts at x = 14 anchored at their start in the caption's grey
/// (#323232), top to bottom.
fn caption_lines(font: &Font, svg: &str) -> Vec<String> {
    let mut lines: Vec<(f64, String)> = texts(font, svg)
        .into_iter()
        .filter(|t| {
            t.x == 14.0
                && t.tag.contains("fill=\"#323232\"")
                && t.tag.contains("text-anchor=\"start\"")
        })
        .map(|t| (t.y, t.content))
        .collect();
    lines.sort_by(|a, b| a.0.total_cmp(&b.0));
    lines.into_iter().map(|l| l.1).collect()
}

/// The page title's lines of `svg`: texts centred on the page at a page title's size (plotters'
/// 20 across two columns, 16 in one, written s/1.24), in the top 80 units.
fn title_lines(font: &Font, svg: &str, column: Column) -> Vec<String> {
    let size = match column {
        Column::Double => 20.0,
        Column::Single => 16.0,
    } / 1.24;
    // The page's middle: the view box's (the single-plot figures are narrower than the
    // column's page across two columns).
    let head = &svg[..svg.find('>').unwrap_or(0)];
    let centre = attr_str(head, "viewBox")
        .and_then(|v| v.split_whitespace().nth(2)?.parse::<f64>().ok())
        .unwrap_or(f64::from(column.width()))
        / 2.0;
    texts(font, svg)
        .into_iter()
        .filter(|t| {
            (t.fs - size).abs() < 0.01
                && t.tag.contains("text-anchor=\"middle\"")
                && (t.x - centre).abs() < 1.0
                && t.y < 80.0
        })
        .map(|t| t.content)
        .collect()
}

/// What breaks the rules in a caption of `lines`, one entry each.
fn caption_faults(lines: &[String]) -> Vec<String> {
    let mut bad = Vec::new();
    if lines.len() > MAX_LINES {
        bad.push(format!(
            "{} caption lines (at most {MAX_LINES})",
            lines.len()
        ));
    }
    for l in lines {
        let t = l.trim();
        if let Some(end) = ["=", "(", "+", "−", "×"].iter().find(|e| t.ends_with(**e)) {
            bad.push(format!("a line ends with {end:?}: {t:?}"));
        }
        if let Some(start) = ['=', '+', '×'].iter().find(|s| t.starts_with(**s)) {
            bad.push(format!("a line starts with {start:?}: {t:?}"));
        }
    }
    if let Some(last) = lines.last() {
        let t = last.trim();
        if lines.len() > 1 && t.chars().count() < WIDOW {
            bad.push(format!("a widow, a last line of {:?}", t));
        }
    }
    bad
}

/// The checks on captions and titles written by hand: each rule caught once, and a caption
/// that keeps them passes.
#[test]
fn the_rules_catch_what_they_name() {
    let own = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    let good = own(&[
        "Lloyd et al. 2006, Fig. 5, f\u{a0}=\u{a0}20:",
        "the terms that vary.",
    ]);
    assert!(caption_faults(&good).is_empty());
    assert_eq!(
        caption_faults(&own(&["a", "b", "c", "d", "e", "f g h i j k l m"])).len(),
        1
    );
    assert_eq!(
        caption_faults(&own(&["at f =", "100 here and there"])).len(),
        1
    );
    assert_eq!(caption_faults(&own(&["over (", "2 tan θ) here"])).len(), 1);
    assert_eq!(
        caption_faults(&own(&["with 4k", "+ 1 maps and more"])).len(),
        1
    );
    assert_eq!(
        caption_faults(&own(&["with 4k +", "1 maps and more"])).len(),
        1
    );
    assert_eq!(
        caption_faults(&own(&["with θ", "= 30° from the view"])).len(),
        1
    );
    assert_eq!(caption_faults(&own(&["the paper's", "name."])).len(), 1);
    assert_eq!(
        caption_faults(&own(&["the paper's", "own\u{a0}name."])).len(),
        1
    );
    assert!(caption_faults(&own(&[
        "Dotted:",
        "g_0\u{a0}=\u{a0}1/√α\u{a0}=\u{a0}0.316."
    ]))
    .is_empty());
    assert!(caption_faults(&own(&["Dotted: the", "least\u{a0}maximum."])).is_empty());
    assert_eq!(
        caption_faults(&own(&["2.15 ×", "gain over one map"])).len(),
        1
    );
    // A caption on a page of the figures' form: read back from a written SVG line.
    let font = Font::dejavu();
    let svg = "<svg viewBox=\"0 0 300 400\">\n\
        <text x=\"150\" y=\"8\" dy=\"0.76em\" text-anchor=\"middle\" font-size=\"12.903\" fill=\"#000000\">A title</text>\n\
        <text x=\"150\" y=\"27\" dy=\"0.76em\" text-anchor=\"middle\" font-size=\"12.903\" fill=\"#000000\">that wraps</text>\n\
        <text x=\"14\" y=\"380\" dy=\"0.76em\" text-anchor=\"start\" font-size=\"11.29\" fill=\"#323232\">second line</text>\n\
        <text x=\"14\" y=\"362\" dy=\"0.76em\" text-anchor=\"start\" font-size=\"11.29\" fill=\"#323232\">first line, f =</text>\n\
        </svg>\n";
    assert_eq!(
        caption_lines(&font, svg),
        ["first line, f =", "second line"]
    );
    assert_eq!(title_lines(&font, svg, Column::Single).len(), 2);
    assert!(title_lines(&font, svg, Column::Double).is_empty());
}

/// Every figure's caption keeps the rules in both layouts, and its title takes one line (two
/// in one column).
#[test]
fn captions_and_titles_keep_the_rules() {
    let font = Font::dejavu();
    let mut faults = Vec::new();
    let mut captions = 0;
    for (column, names) in [(Column::Double, FIGURES), (Column::Single, SINGLE_COLUMN)] {
        let opts = Options {
            column,
            ..Options::default()
        };
        for name in names {
            let svg = render_svg(name, &opts);
            let lines = caption_lines(&font, &svg);
            captions += usize::from(!lines.is_empty());
            for f in caption_faults(&lines) {
                faults.push(format!("{name} ({column:?}): {f}"));
            }
            let title = title_lines(&font, &svg, column);
            if title.is_empty() {
                faults.push(format!("{name} ({column:?}): no title found"));
            }
            let most = if column == Column::Single { 2 } else { 1 };
            if title.len() > most {
                faults.push(format!(
                    "{name} ({column:?}): the title takes {} lines: {title:?}",
                    title.len()
                ));
            }
        }
    }
    assert_eq!(
        captions,
        FIGURES.len() + SINGLE_COLUMN.len(),
        "a figure without a caption"
    );
    assert!(faults.is_empty(), "{}", faults.join("\n"));
}
