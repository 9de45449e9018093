//! One symbol, one meaning, across the closed-form line charts (the fourth figure review: n
//! was lloyd2005-fig4's warp parameter and every other figure's near plane; α lloyd2005's depth
//! ratio and barroso-fig5's target ratio; the half field of view θ in the Lloyd figures and φ_y
//! in barroso-fig7). In these figures, in every form, read from the SVG's texts (labels, axis
//! names, titles and captions): the depth ratio is f/n (no α), the half field of view θ (no φ),
//! and a curve's warp parameter n′ (no label "n = …" naming a curve).
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::*;

/// The figures whose notation this file checks: the line charts of Lloyd 2005 and 2006 and
/// Barroso and Celes' Fig 7.
const CHARTS: [&str; 9] = [
    "lloyd2005-fig4",
    "lloyd2005-fig7",
    "lloyd2006-fig5",
    "lloyd2006-fig6",
    "lloyd2006-fig10",
    "lloyd2006-fig12",
    "lloyd2006-fig13",
    "lloyd2006-worst-case",
    "barroso-fig7",
];

/// Every text of the figure `name` in every form it is written in, with the form.
fn forms_of(font: &Font, name: &str) -> Vec<(String, Vec<Text>)> {
    all_svgs()
        .iter()
        .filter(|(n, _, _)| n == name)
        .map(|(_, layout, svg)| (layout.clone(), texts(font, svg)))
        .collect()
}

/// No α and no φ in any of these figures' texts, and each is found in all three forms (so
/// that the reading is not empty).
#[test]
fn depth_ratio_is_f_over_n_and_half_field_of_view_theta() {
    let font = Font::dejavu();
    let mut bad = Vec::new();
    for name in CHARTS {
        let forms = forms_of(&font, name);
        assert_eq!(forms.len(), 3, "{name}: {} forms", forms.len());
        for (layout, texts) in forms {
            for t in texts {
                if t.content.contains('α') || t.content.contains('φ') {
                    bad.push(format!("{name} ({layout}): {:?}", t.content));
                }
            }
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

/// lloyd2005-fig4 names its five curves by their warp parameter n′, as Lloyd 2006's figures
/// do, in every form: five labels "n′ = …" (1, 1.613, 4.162, 17.325 and ∞ by Eq 4 at f/n = 10),
/// none "n = …"; the near plane keeps n (the two-column axis says "near plane n = 1").
#[test]
fn lloyd2005_fig4_names_its_curves_n_prime() {
    let font = Font::dejavu();
    for (layout, texts) in forms_of(&font, "lloyd2005-fig4") {
        let named: Vec<&str> = texts
            .iter()
            .map(|t| t.content.as_str())
            .filter(|c| c.starts_with("n′ = "))
            .collect();
        assert_eq!(named.len(), 5, "{layout}: {named:?}");
        for value in ["1", "1.613", "4.162", "17.325", "∞"] {
            let want = format!("n′ = {value}");
            assert!(
                named
                    .iter()
                    .any(|c| *c == want || c.starts_with(&format!("{want} "))),
                "{layout}: no {want} in {named:?}"
            );
        }
        let old: Vec<&str> = texts
            .iter()
            .map(|t| t.content.as_str())
            .filter(|c| c.starts_with("n = "))
            .collect();
        assert!(old.is_empty(), "{layout}: {old:?}");
    }
}

/// barroso-fig5 writes the half field of view θ as the charts above do (its α, Barroso's target
/// ratio, is the paper's own and stays): no φ in any form, and "θ = 30°" in the captioned ones.
#[test]
fn barroso_fig5_writes_the_half_field_of_view_theta() {
    let font = Font::dejavu();
    let forms = forms_of(&font, "barroso-fig5");
    assert_eq!(forms.len(), 3, "barroso-fig5: {} forms", forms.len());
    for (layout, texts) in forms {
        let words: String = texts
            .iter()
            .map(|t| t.content.replace('\u{a0}', " "))
            .collect::<Vec<_>>()
            .join(" ");
        assert!(!words.contains('φ'), "barroso-fig5 ({layout}): {words}");
        if !layout.ends_with("bare") {
            assert!(
                words.contains("θ = 30°"),
                "barroso-fig5 ({layout}): {words}"
            );
        }
    }
}
