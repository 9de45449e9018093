//! Label halos never hide a marker (issue 35, the review's cross-figure issue 8: the white boxes
//! of direct labels clipped the tops of the markers at k = 9 in lloyd2005-fig7, and a marker in
//! lloyd2005-fig4's one-column layout). Checked on every figure's SVG in the two-column, bare
//! and one-column layouts: no label box (a white, translucent `<rect>` that is not a legend's)
//! overlaps a marker (a small filled `<polygon>`) drawn before it, whichever series the marker
//! belongs to, its own label's included; and no label's text (the `<text>` after its box,
//! measured with DejaVu Sans) overlaps a marker drawn before or after it.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::*;

/// How far a box and a marker may overlap before it counts (half a unit: the SVG writes the
/// boxes at whole units).
const TOL: f64 = 0.5;

/// The largest marker, in units across: r = width + 2 with lines up to 5 wide, so at most
/// 2·(7 + 1) + 1 = 17; larger polygons are fills (regions, hatching, colour cells).
const MARKER_MAX: f64 = 18.0;

/// The bounding box of a polygon's points.
fn extent(points: &[(f64, f64)]) -> Box4 {
    points.iter().fold(
        [f64::INFINITY, f64::INFINITY, -f64::INFINITY, -f64::INFINITY],
        |b, p| [b[0].min(p.0), b[1].min(p.1), b[2].max(p.0), b[3].max(p.1)],
    )
}

/// The label boxes of `svg` in document order, each with its line number: white `<rect>`s
/// drawn translucent (an `opacity`) that are not a legend's box.
fn label_boxes(svg: &str) -> Vec<(usize, Box4)> {
    let legends = legend_boxes(svg);
    svg.lines()
        .enumerate()
        .filter(|(_, l)| {
            l.starts_with("<rect") && l.contains("fill=\"#FFFFFF\"") && l.contains(" opacity=\"")
        })
        .filter_map(|(i, l)| {
            let (x, y) = (attr(l, "x")?, attr(l, "y")?);
            let b = [x, y, x + attr(l, "width")?, y + attr(l, "height")?];
            (!legends.contains(&b)).then_some((i, b))
        })
        .collect()
}

/// The markers of `svg`, each with its line number: filled polygons no larger than
/// [`MARKER_MAX`] across, with their colour and extent.
fn markers(svg: &str) -> Vec<(usize, String, Box4)> {
    svg.lines()
        .enumerate()
        .filter(|(_, l)| l.starts_with("<polygon"))
        .filter_map(|(i, l)| {
            let shape = &polygons(l)[0];
            let e = extent(&shape.points);
            (shape.points.len() >= 3 && e[2] - e[0] <= MARKER_MAX && e[3] - e[1] <= MARKER_MAX)
                .then(|| (i, shape.colour.clone(), e))
        })
        .collect()
}

/// Whether two boxes overlap by more than [`TOL`] both ways.
fn overlap(a: &Box4, b: &Box4) -> bool {
    a[2].min(b[2]) - a[0].max(b[0]) > TOL && a[3].min(b[3]) - a[1].max(b[1]) > TOL
}

/// Each label box of `svg` that overlaps a marker drawn before it, and each label text that
/// overlaps any marker, one line each; and how many label boxes there were.
fn halo_faults(font: &Font, svg: &str) -> (Vec<String>, usize) {
    let lines: Vec<&str> = svg.lines().collect();
    let boxes = label_boxes(svg);
    let marks = markers(svg);
    let mut bad = Vec::new();
    for (i, b) in &boxes {
        for (j, colour, m) in marks.iter().filter(|(j, _, m)| j < i && overlap(b, m)) {
            bad.push(format!(
                "the label box {b:?} (line {}) covers a {colour} marker {m:?} (line {})",
                i + 1,
                j + 1
            ));
        }
        let Some(text) = lines[i + 1..]
            .iter()
            .find(|l| l.starts_with("<text"))
            .and_then(|l| texts(font, l).pop())
        else {
            continue;
        };
        for (j, colour, m) in marks.iter().filter(|(_, _, m)| overlap(&text.bbox, m)) {
            bad.push(format!(
                "the label {:?} {:?} (line {}) touches a {colour} marker {m:?} (line {})",
                text.content,
                text.bbox,
                i + 2,
                j + 1
            ));
        }
    }
    (bad, boxes.len())
}

/// The reader on a page written by hand: a label box over a marker drawn before it is caught,
/// one drawn after it (on top) or 1 unit clear is not, and a legend's box is no label box; a
/// label's text over a marker is caught whichever comes first.
#[test]
fn a_box_over_an_earlier_marker_is_caught() {
    let font = Font::dejavu();
    let page = |marker_y: f64, after: bool| {
        let m = format!(
            "<polygon fill=\"#0072B2\" points=\"50,{y0} 54,{y1} 46,{y1}\"/>",
            y0 = marker_y,
            y1 = marker_y + 8.0
        );
        let r = "<rect x=\"40\" y=\"20\" width=\"40\" height=\"14\" fill=\"#FFFFFF\" stroke=\"none\" opacity=\"0.8\"/>";
        let legend = "<rect x=\"100\" y=\"20\" width=\"40\" height=\"14\" fill=\"#FFFFFF\" stroke=\"none\" opacity=\"0.9\"/>\n<rect x=\"100\" y=\"20\" width=\"40\" height=\"14\" fill=\"none\" stroke=\"#000000\"/>";
        let body = if after {
            format!("{r}\n{m}")
        } else {
            format!("{m}\n{r}")
        };
        format!("<svg viewBox=\"0 0 200 100\">\n{body}\n{legend}\n</svg>\n")
    };
    // The marker spans y 30–38 against the box's 20–34: 4 units inside.
    let (bad, n) = halo_faults(&font, &page(30.0, false));
    assert_eq!((bad.len(), n), (1, 1), "{bad:?}");
    assert!(halo_faults(&font, &page(30.0, true)).0.is_empty());
    // Spanning 35–43: 1 unit below the box.
    assert!(halo_faults(&font, &page(35.0, false)).0.is_empty());
    // A text "ab" at size 10 from (42, 32) (baseline; capitals up to 32 − 7.3, descent to
    // 34.4), about 13 units wide: a marker drawn after it at y 30–38 over x 46–54 touches it;
    // one at y 36–44 clears the descent.
    let text = |marker_y: f64| {
        format!(
            "<svg viewBox=\"0 0 200 100\">\n<rect x=\"40\" y=\"20\" width=\"40\" height=\"16\" fill=\"#FFFFFF\" stroke=\"none\" opacity=\"0.8\"/>\n<text x=\"42\" y=\"32\" font-size=\"10\">ab</text>\n<polygon fill=\"#0072B2\" points=\"50,{} 54,{} 46,{}\"/>\n</svg>\n",
            marker_y,
            marker_y + 8.0,
            marker_y + 8.0
        )
    };
    let (bad, _) = halo_faults(&font, &text(30.0));
    assert_eq!(bad.len(), 1, "{bad:?}");
    assert!(halo_faults(&font, &text(36.0)).0.is_empty());
}

/// No label box of any figure, in any layout, hides a marker.
#[test]
fn label_halos_cover_no_marker() {
    let mut faults = Vec::new();
    let mut checked = 0;
    let font = Font::dejavu();
    for (name, layout, svg) in all_svgs() {
        let (bad, n) = halo_faults(&font, svg);
        checked += n;
        faults.extend(bad.into_iter().map(|b| format!("{name} ({layout}): {b}")));
    }
    // The line charts' direct labels alone give dozens of boxes; none would pass vacuously.
    assert!(checked >= 30, "only {checked} label boxes");
    assert!(faults.is_empty(), "{}", faults.join("\n"));
}
