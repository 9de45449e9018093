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
