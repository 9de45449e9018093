//! lloyd2005-fig4 after the tenth figure review (R10-lloyd2005-fig4-1: the label
//! "n′ = 4.162 (ξ = 0, LiSPSM)" touched the ▲ marker at z ≈ 7.05, the prime of "n′" merging
//! with the marker's base), read back from its SVGs in all three forms.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::{
    attr, attr_str, forms, points, polygons, render_svg, texts, to_box, to_segment, Box4, Font,
    Text,
};

/// The white a curve label must keep from every marker and every curve, in units.
const CLEAR: f64 = 2.0;

/// The curves' labels: the texts drawn in a curve's colour (not the black axes' and title's,
/// not the caption's dark grey), "n′ = …" and the g₀ line's "g0 = 1/√(f/n)".
fn curve_labels(all: &[Text]) -> Vec<&Text> {
    all.iter()
        .filter(|t| !t.rotated)
        .filter(|t| !t.tag.contains("fill=\"#000000\"") && !t.tag.contains("fill=\"#323232\""))
        .collect()
}

/// Whether the segment `a`–`b` meets the box `r` (sampled every 0.1 unit: the segments here are
/// a few units long).
fn meets(a: (f64, f64), b: (f64, f64), r: &Box4) -> bool {
    let n = ((b.0 - a.0).hypot(b.1 - a.1) / 0.1).ceil().max(1.0) as usize;
    (0..=n).any(|i| {
        let t = i as f64 / n as f64;
        to_box((a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)), r) == 0.0
    })
}

/// The distance between the segment `a`–`b` and the box `r`: 0 where it meets the box, else
/// the least of its ends' distances to the box and the box's corners' distances to it.
fn segment_to_box(a: (f64, f64), b: (f64, f64), r: &Box4) -> f64 {
    if meets(a, b, r) {
        return 0.0;
    }
    let corners = [(r[0], r[1]), (r[2], r[1]), (r[0], r[3]), (r[2], r[3])];
    corners
        .iter()
        .map(|&c| to_segment(c, a, b))
        .chain([to_box(a, r), to_box(b, r)])
        .fold(f64::INFINITY, f64::min)
}

/// The curves: the stroked `<polyline>`s that are no axis or tick (black) with their stroke
/// widths, the data curves (2 wide) and the g₀ line's dots (1 wide, grey).
fn curves(svg: &str) -> Vec<(Vec<(f64, f64)>, f64)> {
    svg.lines()
        .filter(|l| l.starts_with("<polyline"))
        .filter(|l| attr_str(l, "stroke").is_some_and(|s| s != "#000000" && s != "none"))
        .map(|l| (points(l), attr(l, "stroke-width").unwrap_or(1.0)))
        .collect()
}

/// The least white between a label's text and the marks, and what it is nearest.
fn clearance(
    label: &Text,
    markers: &[Vec<(f64, f64)>],
    lines: &[(Vec<(f64, f64)>, f64)],
) -> (f64, String) {
    let r = &label.bbox;
    let mut least = (f64::INFINITY, String::new());
    for m in markers {
        // The polygon's own ink: its corners and edges.
        let d = m
            .iter()
            .zip(m.iter().cycle().skip(1))
            .map(|(&a, &b)| segment_to_box(a, b, r))
            .fold(f64::INFINITY, f64::min);
        if d < least.0 {
            least = (d, format!("the marker at {:?}", m[0]));
        }
    }
    for (p, w) in lines {
        for s in p.windows(2) {
            let d = segment_to_box(s[0], s[1], r) - 0.5 * w;
            if d < least.0 {
                least = (
                    d,
                    format!("a curve ({w} wide) from {:?} to {:?}", s[0], s[1]),
                );
            }
        }
    }
    least
}

/// R10-lloyd2005-fig4-1 (required): every curve label of Fig 4 (the five "n′ = …" and the g₀
/// line's) keeps at least 2 units of white round its text from every marker and every curve,
/// in every form. The text's box is read with DejaVu Sans' own advance widths and its cap
/// height and descent (tests/figures_style_read), the markers as their `<polygon>`s' edges,
/// the curves as their `<polyline>`s' segments less half their stroke. In the reviewed figure
/// the ξ = 0 label's text began 1.3 units under the ▲ at z ≈ 7.05 (its top at y 288.3, the
/// marker's base at 287).
#[test]
fn fig4_labels_keep_2_units_from_every_marker_and_curve() {
    let font = Font::dejavu();
    let mut short = Vec::new();
    for (form, opts) in forms() {
        let svg = render_svg("lloyd2005-fig4", &opts);
        let all = texts(&font, &svg);
        let labels = curve_labels(&all);
        let names: Vec<&str> = labels.iter().map(|t| t.content.as_str()).collect();
        assert_eq!(labels.len(), 6, "{form}: {names:?}");
        assert_eq!(
            labels
                .iter()
                .filter(|t| t.content.starts_with("n′ = "))
                .count(),
            5,
            "{form}: {names:?}"
        );
        let markers: Vec<Vec<(f64, f64)>> = polygons(&svg).into_iter().map(|s| s.points).collect();
        // Five markers along each of the five curves.
        assert_eq!(markers.len(), 25, "{form}");
        let lines = curves(&svg);
        for label in labels {
            let (d, what) = clearance(label, &markers, &lines);
            if d < CLEAR {
                short.push(format!(
                    "{form}: {:?} (text {:?}) keeps only {d:.2} units from {what}",
                    label.content, label.bbox
                ));
            }
        }
    }
    assert!(short.is_empty(), "{short:#?}");
}
