//! Tests of Lloyd et al. 2006 Fig 4 ([`super`]) after the seventh review, kept apart so that the
//! figure's file stays under the size rule.

use super::*;
use crate::plot::chart::read_svg::{attr, draw_svg, texts};
use crate::plot::chart::with_page;
use crate::plot::Column as Page;

/// The SVG of the figure in `column`, with or without its title and caption.
fn svg(fig: &Fig4, column: Page, bare: bool) -> String {
    let size = match column {
        Page::Double => fig.size(),
        Page::Single => fig.single_size().expect("a one-column layout"),
    };
    with_page(bare, column, || {
        draw_svg(size, |area| fig.draw(area).unwrap())
    })
}

/// R7-X-7, read from the SVGs: across two columns every panel title (the columns' headings and
/// the maps' titles) and every axis name is set at the size of another figure's panel titles
/// (barroso-fig7's "(a) γ from 0° to 90°", 12.1 units: they were 10.5 here); in one column,
/// where "(e) map of (b)" at that size is wider than a panel, every one of them at one size. In
/// two columns the headings of one row stand at least 12 units apart (their widths measured by
/// the backend at their size), the scheme's name on a line of its own ("(a) η = −1" over "n′ =
/// ∞" over "uniform", as in one column).
#[test]
fn panel_titles_and_axis_names_at_the_common_size() {
    let fig = fig4().map_err(|e| e.named("lloyd2006-fig4")).unwrap();
    let other = super::super::barroso::fig7().unwrap();
    let reference = super::super::hemisphere::svg_in(&other, Page::Double);
    let common = texts(&reference)
        .into_iter()
        .find(|t| t.1 == "(a) γ from 0° to 90°")
        .and_then(|t| attr(t.0, "font-size"))
        .expect("barroso-fig7's panel title");
    let titled = |t: &str| {
        t.starts_with('(') && t.as_bytes().get(2) == Some(&b')')
            || ["depth z", "eye x", "map s", "map t"].contains(&t)
    };
    for (column, bare) in [
        (Page::Double, false),
        (Page::Double, true),
        (Page::Single, false),
    ] {
        let s = svg(&fig, column, bare);
        let all = texts(&s);
        let sizes: Vec<(String, f64)> = all
            .iter()
            .filter(|t| titled(&t.1) && !t.0.contains("fill=\"#323232\""))
            .map(|t| (t.1.clone(), attr(t.0, "font-size").unwrap()))
            .collect();
        let panels = if column == Page::Double { 8 } else { 6 };
        assert_eq!(
            sizes.iter().filter(|t| t.0.starts_with('(')).count(),
            panels,
            "{column:?}: {sizes:?}"
        );
        assert!(sizes.iter().all(|t| t.1 == sizes[0].1), "{sizes:?}");
        if column == Page::Double {
            assert_eq!(sizes[0].1, common, "{column:?} {bare}: {sizes:?}");
            for line in ["(a) η = −1", "n′ = ∞", "uniform", "LiSPSM", "PSM"] {
                assert!(all.iter().any(|t| t.1 == line), "{line}: no such line");
            }
        }
    }
    // The headings' gaps across two columns: each row of centred headings (one y), their
    // widths at their size.
    let s = svg(&fig, Page::Double, false);
    let all = texts(&s);
    let heading: Vec<&(&str, String, f64)> = all
        .iter()
        .filter(|t| t.0.contains("text-anchor=\"middle\""))
        .filter(|t| t.1.starts_with("(a) η") || t.1.starts_with("(b) η"))
        .collect();
    assert_eq!(heading.len(), 2, "{heading:?}");
    let half = |t: &(&str, String, f64)| {
        let style = TextStyle::from((FONT, heading_size(false)).into_font());
        let mut w = 0;
        let _ = draw_svg((10, 10), |area| {
            w = area.estimate_text_size(&t.1, &style).unwrap().0;
        });
        f64::from(w) / 2.0
    };
    let (a, b) = (heading[0], heading[1]);
    let gap = (attr(b.0, "x").unwrap() - half(b)) - (attr(a.0, "x").unwrap() + half(a));
    assert!(gap >= 12.0, "(a)'s and (b)'s headings {gap} apart");
}

/// R7-2006f4-1, read from the SVGs: both captions say that eye x is the light-view x of the
/// other plan views here ("eye x = light-view x", the light overhead), in at most five lines.
#[test]
fn caption_says_eye_x_is_light_view_x() {
    let fig = fig4().map_err(|e| e.named("lloyd2006-fig4")).unwrap();
    for column in [Page::Double, Page::Single] {
        let s = svg(&fig, column, false);
        let lines: Vec<String> = texts(&s)
            .into_iter()
            .filter(|t| t.0.contains("fill=\"#323232\""))
            .map(|t| t.1)
            .collect();
        assert!(lines.len() <= 5, "{column:?}: {lines:?}");
        let text = lines.join(" ").replace('\u{a0}', " ");
        assert!(
            text.contains("light overhead (eye x = light-view x)"),
            "{column:?}: {text}"
        );
    }
}
