//! Figures after the sixth figure review (issue 35), F6's half, read back from their SVGs:
//! - barroso-fig5 in one column: the overviews (a), (c), (e) label no plane (their depths are
//!   in the caption), so that the detail beside each gets the row's width: each plot about 1.5
//!   times as wide as before (R6-barroso-fig5-2); the labels "z = 10" with thin spaces, as the
//!   two columns write them (R6-barroso-fig5-3);
//! - lloyd2006-fig6: one title in both forms (R6-lloyd2006-fig6-1).
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read as read;
use shadow_aliasing::plot::{Column, Options};

fn single() -> Options {
    Options {
        column: Column::Single,
        ..Options::default()
    }
}

/// The horizontal distance between the centres of the first tick labels `a` and `b` that share
/// a baseline: the page length of their data distance.
fn tick_span(all: &[read::Text], a: &str, b: &str) -> f64 {
    let centre = |t: &read::Text| 0.5 * (t.bbox[0] + t.bbox[2]);
    let ta = all
        .iter()
        .find(|t| t.content == a && !t.rotated)
        .unwrap_or_else(|| panic!("no tick {a:?}"));
    let tb = all
        .iter()
        .find(|t| t.content == b && (t.y - ta.y).abs() < 0.5)
        .unwrap_or_else(|| panic!("no tick {b:?} beside {a:?}"));
    centre(tb) - centre(ta)
}

/// R6-barroso-fig5-2: in one column the overview (a) drew x = −50…50 over 23 units and the
/// detail (b) x = −5…5 over 36 (each plot about 40 units wide in a 300-unit column, its gutter
/// of labels as wide as the plot). With the overviews unlabelled and as wide as the row's
/// height allows, (a)'s −50…50 spans at least 32 units and (b)'s −5…5 spanned 49 (its window
/// x = ±10 tan 30° = ±5.77, z ≤ 10); (d)'s, over the same x window and a square one, spans at
/// least 40 units (42 drawn). (b) holds z ≤ 31.62 since the ninth review (R9-barroso-fig5-1),
/// about 33 by 39 data units in a row whose plots are about 51 units tall: its −10…10 spans at
/// least 28 units (31 drawn).
#[test]
fn barroso_fig5_single_plots_take_the_row() {
    let font = read::Font::dejavu();
    let all = read::texts(&font, &read::render_svg("barroso-fig5", &single()));
    let a = tick_span(&all, "−50", "50");
    let b = tick_span(&all, "−10", "10");
    assert!(a >= 32.0, "(a) −50…50 over {a:.1} units");
    assert!(b >= 28.0, "(b) −10…10 over {b:.1} units");
    // (d)'s x ticks −5 and 5, under its plot: the first "−5" with a "5" on its baseline.
    let d = all
        .iter()
        .filter(|t| t.content == "−5" && !t.rotated)
        .filter_map(|ta| {
            let tb = all
                .iter()
                .find(|t| t.content == "5" && (t.y - ta.y).abs() < 0.5)?;
            Some(0.5 * (tb.bbox[0] + tb.bbox[2]) - 0.5 * (ta.bbox[0] + ta.bbox[2]))
        })
        .next()
        .expect("(d)'s ticks −5 and 5 on one baseline");
    assert!(d >= 40.0, "(d) −5…5 over {d:.1} units");
}

/// R6-barroso-fig5-2/-3 (and the fifth review's §4.12.5): in one column only the details label
/// their planes, each "z = 10"
/// with thin spaces (U+2009) round "=", never set close ("z=10") nor a bare depth; the
/// overviews' depths (z = 3.162, 10, 31.62 for Eq 5 and 6.041, 16.13, 40.81 for Eq 19,
/// recomputed here: 100^(i/4) and the figure's other labels) are in the caption.
#[test]
fn barroso_fig5_single_labels_in_the_details_with_thin_spaces() {
    let font = read::Font::dejavu();
    let svg = read::render_svg("barroso-fig5", &single());
    let all = read::texts(&font, &svg);
    let has = |c: &str| all.iter().any(|t| t.content == c);
    for want in [
        "n = 1",
        "z = 3.162",
        "z = 10",
        "z = 6.041",
        "z = 16.13",
        "z = 40.81",
    ] {
        let thin = want.replace(' ', "\u{2009}");
        assert!(has(&thin), "no label {thin:?}");
        assert!(!has(&want.replace(' ', "")), "{want:?} set close");
    }
    // The overviews' far planes are not labelled: no "f = 100" (z = 31.62 is (b)'s far plane
    // since the ninth review, R9-barroso-fig5-1, labelled there); and no label is a bare depth
    // that reads as a tick value (fifth review §4.12.5).
    assert!(!has("f\u{2009}=\u{2009}100"), "a label f = 100");
    assert!(has("z\u{2009}=\u{2009}31.62"), "no label z = 31.62 in (b)");
    for bare in ["3.162", "31.62", "6.041", "16.13", "40.81"] {
        assert!(!has(bare), "a bare depth {bare:?}");
    }
    let caption: String = all
        .iter()
        .filter(|t| t.tag.contains("#323232"))
        .map(|t| t.content.as_str())
        .collect::<Vec<_>>()
        .join(" ")
        .replace('\u{a0}', " ");
    let eq5: Vec<String> = (1..4)
        .map(|i| {
            let z = 100f64.powf(f64::from(i) / 4.0);
            let s = format!("{:.*}", 3 - z.log10().floor() as usize, z);
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        })
        .collect();
    assert_eq!(eq5, ["3.162", "10", "31.62"]);
    let want = format!("z = {}", eq5.join(", "));
    assert!(caption.contains(&want), "{want:?} not in {caption:?}");
    assert!(
        caption.contains("z = 6.041, 16.13, 40.81"),
        "Eq 19's depths not in {caption:?}"
    );
}

/// The page title of a figure: its text of the largest font size.
fn page_title(all: &[read::Text]) -> String {
    let top = all.iter().map(|t| t.fs).fold(0.0, f64::max);
    all.iter()
        .filter(|t| (t.fs - top).abs() < 1e-6)
        .map(|t| t.content.clone())
        .collect::<Vec<_>>()
        .join(" ")
}

/// R6-lloyd2006-fig6-1: the one-column figure is the two-column one re-laid-out, under the same
/// title (two columns said "storage factor", one column "S̄", the key's symbol).
#[test]
fn lloyd2006_fig6_has_one_title_in_both_forms() {
    let font = read::Font::dejavu();
    let double = page_title(&read::texts(
        &font,
        &read::render_svg("lloyd2006-fig6", &Options::default()),
    ));
    let one = page_title(&read::texts(
        &font,
        &read::render_svg("lloyd2006-fig6", &single()),
    ));
    assert_eq!(double, one);
    // S̄ is an overlined S (a tspan the reader flattens to "S").
    // S̄ named in words (seventh review, R7-2006f6-1).
    assert_eq!(double, "Maximum error and storage factor S against η");
}
