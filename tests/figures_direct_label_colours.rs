//! One colour per scheme in the line charts' direct labels too (the fourth figure review:
//! tests/figures_style_colours.rs reads key entries only, so the colours of PSM's and the
//! uniform map's labels, which name their curves beside them, went untested). Every direct
//! label of every figure, in every layout (a text in a colour, not the black of keys and axes
//! nor the grey of captions and notes, naming one scheme), gives that scheme's label colour;
//! each scheme must have one label colour across all figures, the hue of its key samples (a
//! label may be its line's colour darkened, all channels scaled by one factor, to reach 4.5 : 1
//! on white).
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::*;
use std::collections::BTreeMap;

/// `#RRGGBB` as its three channels.
fn rgb(hex: &str) -> [f64; 3] {
    let c = |i: usize| f64::from(u8::from_str_radix(&hex[i..i + 2], 16).unwrap());
    [c(1), c(3), c(5)]
}

/// WCAG 2's contrast of `hex` against white.
fn contrast(hex: &str) -> f64 {
    let lin = |v: f64| {
        let v = v / 255.0;
        if v <= 0.04045 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    let [r, g, b] = rgb(hex);
    let l = 0.2126 * lin(r) + 0.7152 * lin(g) + 0.0722 * lin(b);
    1.05 / (l + 0.05)
}

/// Whether `label` is `line` with its channels scaled by one factor at most 1 (each channel
/// within a unit of rounding): the same hue, as dark or darker.
fn same_hue(label: &str, line: &str) -> bool {
    let (l, k) = (rgb(label), rgb(line));
    let s = (l[0] * k[0] + l[1] * k[1] + l[2] * k[2]) / (k[0] * k[0] + k[1] * k[1] + k[2] * k[2]);
    s <= 1.0 + 1e-9 && (0..3).all(|i| (l[i] - s * k[i]).abs() <= 1.0)
}

/// The direct labels of `svg` naming one scheme: (scheme, the text's fill).
fn label_colours(font: &Font, svg: &str) -> Vec<(&'static str, String)> {
    texts(font, svg)
        .into_iter()
        .filter(|t| !t.rotated)
        .filter_map(|t| {
            let fill = attr_str(&t.tag, "fill")?.to_string();
            // Keys and axes are black, captions #323232, notes and reference lines greys.
            let [r, g, b] = rgb(&fill);
            let grey = (r - g).abs() < 1.0 && (g - b).abs() < 1.0;
            (!grey).then_some((scheme_of(&t.content)?, fill))
        })
        .collect()
}

/// The readers themselves, on a page written by hand: a darkened orange label naming the
/// uniform map, a grey note naming none, a black key entry naming PSM beside its blue sample;
/// and the hue test: #A77300 is #E69F00 scaled by 0.725, #009E73 is not #0072B2 scaled.
#[test]
fn labels_and_keys_are_read_with_their_colours() {
    let font = Font::dejavu();
    let svg = "<svg width=\"200pt\" height=\"100pt\" viewBox=\"0 0 200 100\">\n\
               <text x=\"150\" y=\"20\" dy=\"0.5ex\" font-size=\"10\" fill=\"#A77300\" text-anchor=\"end\">n′ = ∞ (ξ = −1, uniform)</text>\n\
               <text x=\"150\" y=\"40\" dy=\"0.5ex\" font-size=\"10\" fill=\"#5A5A5A\">g0 = 1/√(f/n)</text>\n\
               <polyline fill=\"none\" stroke=\"#0072B2\" points=\"10,60 34,60\"/>\n\
               <text x=\"40\" y=\"60\" dy=\"0.5ex\" font-size=\"10\" fill=\"#000000\">n′ = n = 1 (PSM)</text>\n\
               </svg>";
    assert_eq!(
        label_colours(&font, svg),
        vec![("uniform", "#A77300".to_string())]
    );
    assert_eq!(
        key_colours(&font, svg),
        vec![("PSM", "#0072B2".to_string())]
    );
    assert!(same_hue("#A77300", "#E69F00"));
    assert!(same_hue("#0072B2", "#0072B2"));
    assert!(!same_hue("#009E73", "#0072B2"));
    assert!(!same_hue("#E69F00", "#A77300"), "lighter than the line");
}

/// Every figure in every layout: each scheme's direct labels have one colour everywhere, at
/// least 4.5 : 1 on white, of the hue of that scheme's key samples in every key; PSM, LiSPSM
/// and the uniform map are among the schemes labelled directly (lloyd2005-fig4 names them),
/// and each of them is in a key too (lloyd2006-fig5's), so that the comparison is made.
#[test]
fn one_label_colour_per_scheme_in_every_figure() {
    let font = Font::dejavu();
    let mut labels: BTreeMap<&str, BTreeMap<String, Vec<String>>> = BTreeMap::new();
    let mut keys: BTreeMap<&str, BTreeMap<String, Vec<String>>> = BTreeMap::new();
    for (name, layout, svg) in all_svgs() {
        let at = format!("{name} ({layout})");
        for (scheme, colour) in label_colours(&font, svg) {
            let at = at.clone();
            labels
                .entry(scheme)
                .or_default()
                .entry(colour)
                .or_default()
                .push(at);
        }
        for (scheme, colour) in key_colours(&font, svg) {
            let at = at.clone();
            keys.entry(scheme)
                .or_default()
                .entry(colour)
                .or_default()
                .push(at);
        }
    }
    for s in ["PSM", "LiSPSM", "uniform"] {
        assert!(
            labels.contains_key(s),
            "no direct label names {s}: {labels:?}"
        );
        assert!(keys.contains_key(s), "no key names {s}: {keys:?}");
    }
    let mut bad = Vec::new();
    for (scheme, colours) in &labels {
        if colours.len() > 1 {
            bad.push(format!("{scheme}: labels in {colours:?}"));
        }
        for (colour, at) in colours {
            if contrast(colour) < 4.5 - 1e-9 {
                bad.push(format!(
                    "{scheme}: {colour} at {:.2} : 1 in {at:?}",
                    contrast(colour)
                ));
            }
            for (key, key_at) in keys.get(scheme).into_iter().flatten() {
                if !same_hue(colour, key) {
                    bad.push(format!(
                        "{scheme}: label {colour} ({at:?}) not the hue of key {key} ({key_at:?})"
                    ));
                }
            }
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
