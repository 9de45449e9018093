//! A caption describes only what its figure draws (the eleventh review, R11-X-3, with
//! R11-lloyd2006-fig10-1 and R11-barroso-fig7-1: one column's captions said "(b), … left out"
//! of a panel the figure did not have). Read back from every captioned SVG, two columns and
//! one: every panel letter a caption names, "(b)" or a range "(a)–(c)", is the letter of a
//! panel drawn in that figure (a text starting with it outside the caption), and no caption
//! says that something is "left out".
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::{all_svgs, attr_str, texts, Font};

/// The panel letters named in `text`: "(x)" for a single letter x (not a function's argument,
/// "f(x)"), and every letter of a range "(x)–(y)".
fn letters(text: &str) -> Vec<char> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i + 2 < chars.len() {
        let after_word = i > 0 && chars[i - 1].is_alphanumeric();
        if chars[i] == '('
            && !after_word
            && chars[i + 1].is_ascii_lowercase()
            && chars[i + 2] == ')'
        {
            let first = chars[i + 1];
            out.push(first);
            // "(a)–(c)": the letters between, too.
            if i + 6 < chars.len()
                && chars[i + 3] == '–'
                && chars[i + 4] == '('
                && chars[i + 5].is_ascii_lowercase()
                && chars[i + 6] == ')'
            {
                let last = chars[i + 5];
                out.extend((first..=last).skip(1));
                i += 7;
                continue;
            }
            i += 3;
        } else {
            i += 1;
        }
    }
    out
}

#[test]
fn letters_reads_single_letters_and_ranges() {
    assert_eq!(
        letters("(a) x, (b)'s, (d)–(f) and f(x)"),
        ['a', 'b', 'd', 'e', 'f']
    );
    assert!(letters("(ab) (1) ( a )").is_empty());
}

#[test]
fn captions_name_only_panels_their_figure_draws() {
    let font = Font::dejavu();
    let mut captions = 0;
    for (name, layout, svg) in all_svgs() {
        if layout.contains("bare") {
            continue;
        }
        let all = texts(&font, svg);
        let (caption, rest): (Vec<_>, Vec<_>) = all
            .iter()
            .partition(|t| attr_str(&t.tag, "fill") == Some("#323232"));
        let caption: String = caption
            .iter()
            .map(|t| t.content.replace('\u{a0}', " "))
            .collect::<Vec<_>>()
            .join(" ");
        assert!(!caption.is_empty(), "{name} ({layout}): no caption");
        captions += 1;
        assert!(
            !caption.contains("left out"),
            "{name} ({layout}): {caption}"
        );
        // The panels drawn: texts outside the caption that start with a letter, "(b) …".
        let drawn: Vec<char> = rest
            .iter()
            .filter_map(|t| {
                let c: Vec<char> = t.content.chars().take(3).collect();
                (c.len() == 3 && c[0] == '(' && c[1].is_ascii_lowercase() && c[2] == ')')
                    .then(|| c[1])
            })
            .collect();
        for l in letters(&caption) {
            assert!(
                drawn.contains(&l),
                "{name} ({layout}): the caption names ({l}), the figure draws {drawn:?}\n{caption}"
            );
        }
    }
    // Every figure, across two columns and in one.
    assert_eq!(captions, 2 * 17, "{captions} captions read");
}

/// What two columns attribute, one column attributes too (the sixteenth review, R16-X-1:
/// lloyd2006-fig7's and barroso-fig5's one-column forms dropped "not in the paper", crediting
/// panels the paper does not have to it): wherever two columns' texts (caption and titles) say
/// that a panel is "not in the paper" ("(e), not in the paper", "(d), (e) not in the paper",
/// the letters in the 30 characters before it) and one column draws that panel, one column
/// says "not in the paper" too.
#[test]
fn one_column_keeps_what_is_not_in_the_paper() {
    const PHRASE: &str = "not in the paper";
    let font = Font::dejavu();
    let joined = |svg: &str| -> String {
        texts(&font, svg)
            .iter()
            .map(|t| t.content.replace('\u{a0}', " "))
            .collect::<Vec<_>>()
            .join(" ")
    };
    let drawn = |svg: &str| -> Vec<char> {
        texts(&font, svg)
            .iter()
            .filter(|t| attr_str(&t.tag, "fill") != Some("#323232"))
            .filter_map(|t| {
                let c: Vec<char> = t.content.chars().take(3).collect();
                (c.len() == 3 && c[0] == '(' && c[1].is_ascii_lowercase() && c[2] == ')')
                    .then(|| c[1])
            })
            .collect()
    };
    let all = all_svgs();
    let mut checked = 0;
    for (name, _, svg) in all.iter().filter(|(_, l, _)| l == "Double") {
        let text = joined(svg);
        let mut attributed = Vec::new();
        for (at, _) in text.match_indices(PHRASE) {
            let before: String = text[..at]
                .chars()
                .rev()
                .take(30)
                .collect::<Vec<_>>()
                .into_iter()
                .rev()
                .collect();
            attributed.extend(letters(&before));
        }
        let single = all
            .iter()
            .find(|(n, l, _)| n == name && l == "Single")
            .unwrap_or_else(|| panic!("{name}: no one-column form"));
        let shown = drawn(&single.2);
        if attributed.iter().any(|l| shown.contains(l)) {
            checked += 1;
            assert!(
                joined(&single.2).contains(PHRASE),
                "{name}: one column draws {attributed:?} but does not say they are {PHRASE}"
            );
        }
    }
    // lloyd2006-fig7 ((d), (e)) and barroso-fig5 ((e)) at least.
    assert!(checked >= 2, "{checked} figures checked");
}
