//! martin-tan-fig6 after the tenth figure review (R10-martin-tan-fig6-1: panel (b)'s x axis
//! read 0, 45, 90, 45, 0 with nothing in the figure saying which 0 is behind; only the
//! two-column caption said so), read back from its SVGs in all three forms.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::{attr_str, forms, render_svg, texts, Font, Text};

/// Whether two boxes [x0, y0, x1, y1] overlap.
fn overlap(a: &[f64; 4], b: &[f64; 4]) -> bool {
    a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]
}

/// R10-martin-tan-fig6-1 (required): in every form (b) writes "behind" under its left 0 tick
/// and "in front" under its right one. Read from the SVG: (b)'s x tick labels are the row of
/// centred "0", "45", "90", "45", "0" (the lowest such row; the hemisphere's bar writes powers
/// of ten); the word "behind" (not (a)'s "← behind") has its centre within 10 units across of
/// the left 0's and nearer it than the right 0; "in front" (not (a)'s "in front →") the same
/// for the right 0; each word's text box lies under its tick label's and over the axis' name
/// "light's elevation (°)", overlaps no other text and stays inside the page.
#[test]
fn profile_says_which_zero_is_behind_and_which_in_front() {
    let font = Font::dejavu();
    for (form, opts) in forms() {
        let svg = render_svg("martin-tan-fig6", &opts);
        let all = texts(&font, &svg);
        let centred = |t: &Text| attr_str(&t.tag, "text-anchor") == Some("middle") && !t.rotated;
        // (b)'s tick row: the numbers 0, 45, 90 centred on one row.
        let row_y = all
            .iter()
            .filter(|t| centred(t) && ["0", "45", "90"].contains(&t.content.as_str()))
            .map(|t| t.y)
            .fold(f64::NEG_INFINITY, f64::max);
        let mut row: Vec<&Text> = all
            .iter()
            .filter(|t| centred(t) && (t.y - row_y).abs() < 0.5)
            .filter(|t| t.content.parse::<f64>().is_ok())
            .collect();
        row.sort_by(|a, b| a.x.total_cmp(&b.x));
        let read: Vec<&str> = row.iter().map(|t| t.content.as_str()).collect();
        assert_eq!(read, ["0", "45", "90", "45", "0"], "{form}");
        let (left, right) = (row[0], row[4]);
        let name = all
            .iter()
            .find(|t| t.content == "light's elevation (°)")
            .unwrap_or_else(|| panic!("{form}: no x axis name"));
        // The page: the view box's left and right (the bare form's is cropped).
        let vb: Vec<f64> = attr_str(&svg[..svg.find('>').unwrap()], "viewBox")
            .expect("a view box")
            .split_whitespace()
            .map(|v| v.parse().unwrap())
            .collect();
        let (page_l, page_r) = (vb[0], vb[0] + vb[2]);
        for (word, own, other) in [("behind", left, right), ("in front", right, left)] {
            let found: Vec<&Text> = all.iter().filter(|t| t.content == word).collect();
            assert_eq!(
                found.len(),
                1,
                "{form}: {word:?} written {} times",
                found.len()
            );
            let t = found[0];
            let centre = 0.5 * (t.bbox[0] + t.bbox[2]);
            assert!(
                (centre - own.x).abs() <= 10.0 && (centre - own.x).abs() < (centre - other.x).abs(),
                "{form}: {word:?} centred at {centre:.1}, its 0 at {:.1}, the other 0 at {:.1}",
                own.x,
                other.x
            );
            assert!(
                t.bbox[1] >= own.bbox[3] && t.bbox[3] <= name.bbox[1],
                "{form}: {word:?} {:?} is not between its tick label {:?} and the axis name {:?}",
                t.bbox,
                own.bbox,
                name.bbox
            );
            assert!(
                t.bbox[0] >= page_l && t.bbox[2] <= page_r,
                "{form}: {word:?} {:?} leaves the page ({page_l} to {page_r})",
                t.bbox
            );
            for o in all.iter().filter(|o| !std::ptr::eq(*o, t)) {
                assert!(
                    !overlap(&t.bbox, &o.bbox),
                    "{form}: {word:?} {:?} overlaps {:?} {:?}",
                    t.bbox,
                    o.content,
                    o.bbox
                );
            }
        }
    }
}
