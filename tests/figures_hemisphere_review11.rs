//! lloyd2006-fig7 after the eleventh figure review (R11-lloyd2006-fig7-1), read back from its
//! SVGs in the two forms that draw (a)'s contours (two columns and bare): (a)'s two S̄ contours
//! were black, of the weight of the black rings under them, and ran unseen along the disk's rim;
//! the label "1.5×10⁶" stood on an opaque patch between two lobes, naming no contour.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::{
    forms, render_svg, strokes as lines, texts, to_polyline as distance, Font, Stroke as Line, Text,
};

/// (a)'s disk lies left of this x and above this y (the first of three cells across 520 units,
/// in the first of two rows).
const A_RIGHT: f64 = 173.0;
const A_BOTTOM: f64 = 270.0;

fn in_a(l: &Line) -> bool {
    l.points.iter().all(|q| q.0 < A_RIGHT && q.1 < A_BOTTOM)
}

fn length(p: &[(f64, f64)]) -> f64 {
    p.windows(2)
        .map(|w| (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1))
        .sum()
}

/// The commonest whole length of `dashes`: a dash style's on-length (dashes cut short at a
/// line's end or under a label are fewer).
fn dash_length<'a>(dashes: impl Iterator<Item = &'a Line>) -> Option<i64> {
    let mut counts: Vec<(i64, usize)> = Vec::new();
    for d in dashes {
        let l = length(&d.points).round() as i64;
        match counts.iter_mut().find(|c| c.0 == l) {
            Some(c) => c.1 += 1,
            None => counts.push((l, 1)),
        }
    }
    counts.into_iter().max_by_key(|c| (c.1, c.0)).map(|c| c.0)
}

/// WCAG's relative luminance of an SVG colour "#RRGGBB".
fn luminance(hex: &str) -> f64 {
    let c = |i: usize| {
        let v = f64::from(u8::from_str_radix(&hex[i..i + 2], 16).unwrap()) / 255.0;
        if v <= 0.04045 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    0.2126 * c(1) + 0.7152 * c(3) + 0.0722 * c(5)
}

/// R11-lloyd2006-fig7-1 (1): in (a) every contour dash is black, at least 1.2 units wide, and
/// lies on a white line (its halo) at least a unit wider (half a unit or more each side), so
/// that it shows on the green field, on the grey rings and along the disk's rim, where the
/// white shows against the dashes; there are at least 100 dashes and both styles. The rings,
/// in every disk of the figure (the circles: polylines of over 100 points, the contours'
/// white lines aside), are one style: at most half a unit wide and not black (relative
/// luminance at least 0.1; grey, its three channels equal). The old figure drew 2-unit black
/// dashes on no white, over near-black rings (#1E1E1E) a unit wide.
#[test]
fn fig7_contours_are_black_on_white_over_thin_grey_rings() {
    for (form, opts) in forms().into_iter().take(2) {
        let svg = render_svg("lloyd2006-fig7", &opts);
        let all = lines(&svg);
        let white: Vec<&Line> = all
            .iter()
            .filter(|l| in_a(l) && l.stroke == "#FFFFFF")
            .collect();
        let black: Vec<&Line> = all
            .iter()
            .filter(|l| in_a(l) && l.stroke == "#000000")
            .collect();
        assert!(black.len() >= 100, "{form}: {} dashes in (a)", black.len());
        assert!(!white.is_empty(), "{form}: no white line in (a)");
        for d in &black {
            assert!(d.width >= 1.2, "{form}: a contour dash {} wide", d.width);
            let mid = d.points[d.points.len() / 2];
            let halo = white
                .iter()
                .filter(|w| d.points.iter().all(|&p| distance(p, &w.points) <= 0.2))
                .map(|w| w.width)
                .fold(0.0, f64::max);
            assert!(
                halo >= d.width + 1.0,
                "{form}: the dash at {mid:?} ({} wide) on a white line {halo} wide",
                d.width
            );
        }
        // Both styles: short and long dashes.
        let lengths: Vec<f64> = black.iter().map(|d| length(&d.points)).collect();
        assert!(
            lengths.iter().any(|&l| l < 4.0) && lengths.iter().any(|&l| l > 6.0),
            "{form}: one dash style"
        );
        let rings: Vec<&Line> = all
            .iter()
            .filter(|l| l.points.len() > 100 && l.stroke != "#FFFFFF" && l.stroke != "#000000")
            .collect();
        // Five rings a disk, six disks (the key's included).
        assert!(rings.len() >= 30, "{form}: {} rings", rings.len());
        for r in &rings {
            assert!(r.width <= 0.5, "{form}: a ring {} wide", r.width);
            assert_eq!(r.stroke, rings[0].stroke, "{form}: rings in two colours");
        }
        let ink = &rings[0].stroke;
        assert!(
            ink[1..3] == ink[3..5] && ink[3..5] == ink[5..7],
            "{form}: rings {ink}, not grey"
        );
        assert!(luminance(ink) >= 0.1, "{form}: rings {ink}, near black");
        // No black circle under the contours: the old rings.
        assert!(
            !all.iter()
                .any(|l| l.points.len() > 100 && l.stroke == "#000000"),
            "{form}: a black ring"
        );
    }
}

fn centre(t: &Text) -> (f64, f64) {
    (0.5 * (t.bbox[0] + t.bbox[2]), 0.5 * (t.bbox[1] + t.bbox[3]))
}

/// R11-lloyd2006-fig7-1 (2), R12-lloyd2006-fig7-1 and R13-lloyd2006-fig7-1: a label on its
/// own contour had the line through its glyphs, and no lobe holds a gap in the line for
/// "1.5×10⁶" at 2 % of the page's width; so no contour is labelled in (a): each is named by
/// its style in the key, the row "(a) S̄ = <level>" with a sample of its dashes left of its
/// text, and that dash length (the commonest) is the one lying on one of (a)'s white lines,
/// a different one for each level. No text in (a)'s panel writes a level.
#[test]
fn fig7_contours_are_named_by_their_styles_in_the_key() {
    let font = Font::dejavu();
    for (form, opts) in forms().into_iter().take(2) {
        let svg = render_svg("lloyd2006-fig7", &opts);
        let all = lines(&svg);
        let words = texts(&font, &svg);
        let dashes: Vec<&Line> = all
            .iter()
            .filter(|l| l.stroke == "#000000" && l.width > 1.0 && l.width < 2.0)
            .collect();
        let white: Vec<&Line> = all
            .iter()
            .filter(|l| in_a(l) && l.stroke == "#FFFFFF")
            .collect();
        // Each white line's dash length: the commonest of the dashes lying on it.
        let styled: Vec<(i64, &Line)> = white
            .iter()
            .filter_map(|w| {
                let on = dashes
                    .iter()
                    .copied()
                    .filter(|d| in_a(d) && d.points.iter().all(|&p| distance(p, &w.points) <= 0.2));
                Some((dash_length(on)?, *w))
            })
            .collect();
        // The key as read joins its superscript: "106", "1.5×106".
        let mut keyed = Vec::new();
        for level in ["106", "1.5×106"] {
            let key = words
                .iter()
                .find(|t| t.content == format!("(a) S = {level}"))
                .unwrap_or_else(|| panic!("{form}: no key row for {level}"));
            let ky = centre(key).1;
            let sample = dashes.iter().copied().filter(|d| {
                !in_a(d)
                    && d.points
                        .iter()
                        .all(|q| (q.1 - ky).abs() <= 3.0 && q.0 < key.bbox[0])
            });
            let want = dash_length(sample).unwrap_or_else(|| panic!("{form}: {level} keyed"));
            assert!(
                styled.iter().any(|(l, _)| *l == want),
                "{form}: {level}'s key dashes ({want}) on no contour in (a)"
            );
            keyed.push(want);
            let written: Vec<&str> = words
                .iter()
                .filter(|t| t.x < A_RIGHT && t.y < A_BOTTOM && t.content.contains(level))
                .map(|t| t.content.as_str())
                .collect();
            assert!(written.is_empty(), "{form}: {written:?} in (a)");
        }
        assert!(keyed[0] != keyed[1], "{form}: both levels keyed alike");
    }
}
