//! The strokes of every figure in every layout, read from the SVGs as written (sixth figure
//! review, X-10, X-11 and X-4):
//! - every line (a `<polyline>`: data lines, their dashes, key samples, leaders, hollow
//!   markers; not the light 10-unit bands behind them) has at least 3 : 1 against white;
//! - two line colours of one figure whose CIE L* are within 15 of each other (one grey in
//!   print) differ both in dash (solid, dashed, dotted: the lengths of their pieces) and in
//!   marker (the outlines of their markers);
//! - no figure shows two marker shapes that are each other's mirror image (▲ and ▼, ▶ and ◀) or
//!   each other turned by a quarter (a wide and a tall bar).
//!
//! Luminance and L* are computed here from the sRGB formula, not by the crate.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::*;
use std::collections::{BTreeMap, BTreeSet};

/// WCAG relative luminance of `#RRGGBB`.
fn luminance(hex: &str) -> f64 {
    let lin = |i: usize| {
        let v = f64::from(u8::from_str_radix(&hex[i..i + 2], 16).unwrap()) / 255.0;
        if v <= 0.04045 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    0.2126 * lin(1) + 0.7152 * lin(3) + 0.0722 * lin(5)
}

/// Contrast against white (WCAG: (1 + 0.05) / (L + 0.05)).
fn contrast(hex: &str) -> f64 {
    1.05 / (luminance(hex) + 0.05)
}

/// CIE L* of `#RRGGBB`.
fn lightness(hex: &str) -> f64 {
    let y = luminance(hex);
    if y > 216.0 / 24389.0 {
        116.0 * y.cbrt() - 16.0
    } else {
        y * 24389.0 / 27.0
    }
}

/// Two colours closer than this in L* print as one grey (the review's rule).
const SAME_GREY: f64 = 15.0;

/// Strokes this wide or wider are bands behind the lines (worst-case's light range band).
const BAND: f64 = 8.0;

#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Dash {
    Solid,
    Dashed,
    Dotted,
}

/// Every `<polyline>` of `svg` with its stroke width, the colour in capitals.
fn upper_strokes(svg: &str) -> Vec<Stroke> {
    strokes(svg)
        .into_iter()
        .map(|s| Stroke {
            stroke: s.stroke.to_uppercase(),
            ..s
        })
        .collect()
}

fn length(p: &[(f64, f64)]) -> f64 {
    p.windows(2)
        .map(|w| (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1))
        .sum()
}

fn closed(p: &[(f64, f64)]) -> bool {
    p.len() > 3 && p.first() == p.last()
}

/// The dashes a colour is drawn with: pieces longer than a dash (9 units) are solid lines,
/// pieces of 4.5 to 10.5 dashes, shorter ones dots (a dashed line's clipped ends are short too:
/// dotted only where dots outnumber dashes).
fn dashes(pieces: &[f64]) -> BTreeSet<Dash> {
    let mut out = BTreeSet::new();
    if pieces.iter().any(|&l| l > 10.5) {
        out.insert(Dash::Solid);
    }
    let dash = pieces.iter().filter(|&&l| l > 4.5 && l <= 10.5).count();
    let dot = pieces.iter().filter(|&&l| l <= 4.5).count();
    if dash >= 2 && dash >= dot {
        out.insert(Dash::Dashed);
    }
    if dot >= 2 && dot > dash {
        out.insert(Dash::Dotted);
    }
    out
}

/// A marker's outline about its box's centre, scaled to a half-extent of 1 and rounded to
/// 1/4 (its shape, whatever its size), its corners sorted.
type Outline = Vec<(i32, i32)>;

fn outline(p: &[(f64, f64)]) -> Option<Outline> {
    let b = bbox(p);
    let (w, h) = (b[2] - b[0], b[3] - b[1]);
    if p.len() < 3 || w > 16.0 || h > 16.0 || w < 2.0 || h < 2.0 {
        return None;
    }
    let (cx, cy, s) = (0.5 * (b[0] + b[2]), 0.5 * (b[1] + b[3]), 0.5 * w.max(h));
    let mut o: Outline = p
        .iter()
        .map(|q| {
            (
                (4.0 * (q.0 - cx) / s).round() as i32,
                (4.0 * (q.1 - cy) / s).round() as i32,
            )
        })
        .collect();
    o.sort_unstable();
    o.dedup();
    Some(o)
}

/// The markers of `svg` by colour: filled `<polygon>`s and closed `<polyline>`s (hollow
/// markers) no wider than 16 units.
fn markers(svg: &str) -> BTreeMap<String, BTreeSet<Outline>> {
    let mut out: BTreeMap<String, BTreeSet<Outline>> = BTreeMap::new();
    for p in polygons(svg) {
        if let Some(o) = outline(&p.points) {
            out.entry(p.colour.to_uppercase()).or_default().insert(o);
        }
    }
    for s in upper_strokes(svg).into_iter().filter(|s| closed(&s.points)) {
        if let Some(o) = outline(&s.points[1..]) {
            out.entry(s.stroke).or_default().insert(o);
        }
    }
    out
}

fn mirrors(o: &Outline) -> [Outline; 4] {
    let map = |f: &dyn Fn((i32, i32)) -> (i32, i32)| {
        let mut m: Outline = o.iter().map(|&p| f(p)).collect();
        m.sort_unstable();
        m
    };
    [
        map(&|(x, y)| (-x, y)),
        map(&|(x, y)| (x, -y)),
        map(&|(x, y)| (y, x)),
        map(&|(x, y)| (-y, x)),
    ]
}

/// The readers by hand: a 3 : 1 grey (#949494: 148/255 → 0.2961, 3.05 : 1) passes and #969696
/// (0.3005, 2.996 : 1) does not; the review's #E69F00 is 2.3 : 1; mid grey #777777 is L* 50.0;
/// a dashed line's pieces (9, 9, 9, 3) are dashed, a dotted one's (2, 2, 2) dotted, a 40-unit
/// piece solid; ▲ and ▼ outlines mirror each other and a square mirrors only itself.
#[test]
fn readers_by_hand() {
    assert!(contrast("#949494") >= 3.0 && contrast("#969696") < 3.0);
    assert!((contrast("#E69F00") - 2.3).abs() < 0.05);
    assert!((lightness("#777777") - 50.0).abs() < 0.1);
    assert_eq!(
        dashes(&[9.0, 9.0, 9.0, 3.0]),
        BTreeSet::from([Dash::Dashed])
    );
    assert_eq!(dashes(&[2.0, 2.0, 2.0]), BTreeSet::from([Dash::Dotted]));
    assert_eq!(dashes(&[40.0]), BTreeSet::from([Dash::Solid]));
    let up = outline(&[(0.0, -5.0), (5.0, 4.0), (-5.0, 4.0)]).unwrap();
    let down = outline(&[(0.0, 5.0), (5.0, -4.0), (-5.0, -4.0)]).unwrap();
    assert_ne!(up, down);
    assert!(mirrors(&up).contains(&down));
    let square = outline(&[(-4.0, -4.0), (4.0, -4.0), (4.0, 4.0), (-4.0, 4.0)]).unwrap();
    assert!(mirrors(&square).iter().all(|m| *m == square));
}

/// Every line of every figure, in every layout, has at least 3 : 1 against white.
#[test]
fn every_line_has_three_to_one_on_white() {
    let mut bad = BTreeSet::new();
    let mut seen = BTreeSet::new();
    for (name, layout, svg) in all_svgs() {
        // White strokes are the separators drawn over fills (lloyd2006-fig13's bars), not lines
        // on white.
        for s in upper_strokes(svg)
            .into_iter()
            .filter(|s| s.width < BAND && s.stroke != "#FFFFFF")
        {
            seen.insert(s.stroke.clone());
            if contrast(&s.stroke) < 3.0 {
                bad.insert(format!(
                    "{name} ({layout}): {} at {:.2} : 1",
                    s.stroke,
                    contrast(&s.stroke)
                ));
            }
        }
    }
    assert!(
        bad.is_empty(),
        "{}",
        bad.into_iter().collect::<Vec<_>>().join("\n")
    );
    // The warps' and schemes' colours are among those read (the reader sees the figures' lines).
    for c in LOOKS {
        assert!(seen.contains(c), "{c} not drawn: {seen:?}");
    }
}

/// The warps' and schemes' colours (src/plot/chart/scheme.rs `Look`), by hand.
const LOOKS: [&str; 6] = [
    "#00306E", "#00664B", "#D55E00", "#009CA6", "#A82E66", "#4D2E00",
];

/// The pairs of line colours of `svg` one grey apart (L* within 15), one of them a warp's or
/// a scheme's, that do not differ both in dash and in marker.
fn greys_alike(svg: &str) -> Vec<String> {
    let mut pieces: BTreeMap<String, Vec<f64>> = BTreeMap::new();
    for s in strokes(svg) {
        // Axes and ticks (1 unit), hollow markers and bands are not data lines.
        if s.width < 2.0 || s.width >= BAND || closed(&s.points) {
            continue;
        }
        pieces
            .entry(s.stroke.clone())
            .or_default()
            .push(length(&s.points));
    }
    let marks = markers(svg);
    let colours: Vec<(&String, BTreeSet<Dash>)> =
        pieces.iter().map(|(c, p)| (c, dashes(p))).collect();
    let mut bad = Vec::new();
    for (i, (a, da)) in colours.iter().enumerate() {
        for (b, db) in &colours[..i] {
            let dl = (lightness(a) - lightness(b)).abs();
            if dl >= SAME_GREY || !(LOOKS.contains(&a.as_str()) || LOOKS.contains(&b.as_str())) {
                continue;
            }
            let dash_apart = da.is_disjoint(db);
            let marker_apart = match (marks.get(*a), marks.get(*b)) {
                (Some(x), Some(y)) => x.is_disjoint(y),
                // A colour without markers differs by having none.
                (None, Some(_)) | (Some(_), None) => true,
                (None, None) => false,
            };
            if !(dash_apart && marker_apart) {
                bad.push(format!(
                    "{a} {da:?} and {b} {db:?}, {dl:.1} L* apart, dashes apart {dash_apart}, \
                     markers apart {marker_apart}"
                ));
            }
        }
    }
    bad
}

/// In every figure and layout, a warp's or scheme's line colour and any other line colour one
/// grey apart (L* within 15) differ both in dash and in marker, so that they stay apart in
/// greyscale (sixth figure review, X-10: lloyd2005-fig4, lloyd2006-fig5, barroso-fig7 mix the
/// warps with the purple sweep; lloyd2006-worst-case sets the schemes beside the grey of ZP =
/// ZP+W behind). No colour keeps a warp 15 L* from all three sweep steps (18, 39, 60) at once,
/// so a sweep beside warps is dashed: lloyd2006-fig5's n′ = 2, 20, 100, and lloyd2005-fig4's
/// ξ = ±½ (ξ = ½ #3F007D, L* 18, by PSM's 21; ξ = −½ #9589C0, 60, by the uniform map's 54; solid
/// until the nineteenth review, R19-lloyd2005-fig4-1).
#[test]
fn colours_one_grey_apart_differ_in_dash_and_marker() {
    let mut bad = Vec::new();
    for (name, layout, svg) in all_svgs() {
        let alike = greys_alike(svg);
        bad.extend(alike.into_iter().map(|a| format!("{name} ({layout}): {a}")));
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

/// No figure shows a marker shape beside its mirror image or quarter turn (▲/▼, ▶/◀), and the
/// figures do show markers (the reader finds them).
#[test]
fn no_mirrored_marker_pairs() {
    let mut bad = Vec::new();
    let mut count = 0;
    for (name, layout, svg) in all_svgs() {
        let shapes: BTreeSet<Outline> = markers(svg).into_values().flatten().collect();
        count += shapes.len();
        for a in &shapes {
            for b in &shapes {
                if a < b && mirrors(a).contains(b) {
                    bad.push(format!("{name} ({layout}): {a:?} and {b:?}"));
                }
            }
        }
    }
    assert!(count > 50, "only {count} marker shapes read");
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

/// A hollow marker's closed outline starts and ends halfway along a side, not at a corner: a
/// stroke that starts and ends at a corner meets itself there in two square ends, which leave a
/// notch at a sharp corner (a triangle's apex). Read from every SVG: the first point of each
/// closed marker-sized polyline in a colour lies on the line through its two neighbours (within
/// 0.15 unit), and the figures do draw such markers. Black and grey ones are left out: they are
/// the diagrams' small plane rectangles and enlargement boxes (barroso-fig5's apex,
/// lloyd2005-fig8's), square-cornered outlines drawn as lines, not markers.
#[test]
fn hollow_markers_start_on_a_side() {
    let mut bad = Vec::new();
    let mut count = 0;
    for (name, layout, svg) in all_svgs() {
        for s in upper_strokes(svg).into_iter().filter(|s| closed(&s.points)) {
            let p = &s.points;
            let grey = s.stroke.len() == 7
                && s.stroke[1..3] == s.stroke[3..5]
                && s.stroke[3..5] == s.stroke[5..7];
            if grey || outline(&p[1..]).is_none() {
                continue;
            }
            count += 1;
            let (a, m, b) = (p[p.len() - 2], p[0], p[1]);
            let cross = (b.0 - a.0) * (m.1 - a.1) - (b.1 - a.1) * (m.0 - a.0);
            let off = cross.abs() / (b.0 - a.0).hypot(b.1 - a.1).max(1e-9);
            if off > 0.15 {
                bad.push(format!(
                    "{name} ({layout}): {} starts at a corner ({off:.2} off)",
                    s.stroke
                ));
            }
        }
    }
    assert!(count > 100, "only {count} hollow markers read");
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
