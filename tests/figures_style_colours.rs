//! One colour per scheme in every figure (issue 35 item 6: lloyd2006-fig13's palette differed
//! from fig12's and worst-case's; the review: the uniform map was orange in one figure and sky
//! blue in another). Every key entry of every figure, in every layout (a legend's or key's black
//! text naming a scheme, with its sample or swatch just left of it on its row), gives the
//! scheme's colour; each scheme must have one colour across all figures.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::*;
use std::collections::BTreeMap;

/// The reading itself: a legend row "ZP+W, overhead" with a vermillion sample left of it and
/// a row "ZP = ZP+W, behind" (two schemes: not counted); the names are read as whole tokens.
#[test]
fn key_entries_are_read_with_their_samples() {
    assert_eq!(scheme_of("ZP+W, overhead"), Some("ZP+W"));
    assert_eq!(scheme_of("ZP, worst (measured)"), Some("ZP"));
    assert_eq!(scheme_of("FP+ZP+W lowest"), Some("FP+ZP+W"));
    assert_eq!(scheme_of("n′ ≈ 5.47 (LiSPSM)"), Some("LiSPSM"));
    assert_eq!(scheme_of("n′ = n = 1 (PSM)"), Some("PSM"));
    assert_eq!(scheme_of("ZP = ZP+W, behind"), None);
    assert_eq!(scheme_of("n′ = 20"), None);
    let font = Font::dejavu();
    let svg = "<svg width=\"200pt\" height=\"100pt\" viewBox=\"0 0 200 100\">\n\
               <polyline fill=\"none\" stroke=\"#D55E00\" points=\"10,20 34,20\"/>\n\
               <text x=\"40\" y=\"20\" dy=\"0.5ex\" font-size=\"10\" fill=\"#000000\">ZP+W, overhead</text>\n\
               <polyline fill=\"none\" stroke=\"#5A5A5A\" points=\"10,40 34,40\"/>\n\
               <text x=\"40\" y=\"40\" dy=\"0.5ex\" font-size=\"10\" fill=\"#000000\">ZP = ZP+W, behind</text>\n\
               <rect x=\"10\" y=\"53\" width=\"14\" height=\"14\" fill=\"#009E73\"/>\n\
               <text x=\"30\" y=\"60\" dy=\"0.5ex\" font-size=\"10\" fill=\"#000000\">FP+ZP+W lowest</text>\n\
               </svg>";
    assert_eq!(
        key_colours(&font, svg),
        vec![
            ("ZP+W", "#D55E00".to_string()),
            ("FP+ZP+W", "#009E73".to_string())
        ]
    );
}

/// Every figure in every layout: each scheme named in a key has one colour everywhere, and
/// the schemes of lloyd2006-fig12, fig13, worst-case and barroso-fig7 are all found
/// (ZP, ZP+W and FP+ZP+W in at least two figures each).
#[test]
fn one_colour_per_scheme_in_every_figure() {
    let font = Font::dejavu();
    let mut seen: BTreeMap<&str, BTreeMap<String, Vec<String>>> = BTreeMap::new();
    for (name, layout, svg) in all_svgs() {
        for (scheme, colour) in key_colours(&font, svg) {
            seen.entry(scheme)
                .or_default()
                .entry(colour)
                .or_default()
                .push(format!("{name} ({layout})"));
        }
    }
    let figures = |s: &str| -> usize {
        let mut names: Vec<String> = seen
            .get(s)
            .into_iter()
            .flat_map(|m| m.values().flatten())
            .map(|w| w.split(' ').next().unwrap().to_string())
            .collect();
        names.sort();
        names.dedup();
        names.len()
    };
    for s in ["ZP", "ZP+W", "FP+ZP+W"] {
        assert!(figures(s) >= 2, "{s} in {} figures: {seen:?}", figures(s));
    }
    // PSM and the uniform map are named by direct labels only (lloyd2006-fig5 has no key
    // since its labels in (b) name both panels), which this reader of keys does not read;
    // their colours are Look's (src/plot/chart/scheme.rs, by hand).
    for s in ["LiSPSM", "Zhang", "Barroso"] {
        assert!(figures(s) >= 1, "{s} not found: {seen:?}");
    }
    let bad: Vec<String> = seen
        .iter()
        .filter(|(_, colours)| colours.len() > 1)
        .map(|(s, colours)| format!("{s}: {colours:?}"))
        .collect();
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
