//! martin-tan-fig3 after the thirteenth figure review (R13-martin-tan-fig3-1: in (c) the
//! white-backed word "focus" covered part of a frustum edge and touched box B's dashed side),
//! read back from its SVGs in all three forms.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::{
    attr, attr_str, forms, polygons, polylines, render_svg, segment_enters, texts, to_box,
    to_segment, Box4, Font, Text,
};

/// Whether two boxes [x0, y0, x1, y1] overlap.
fn overlap(a: &Box4, b: &Box4) -> bool {
    a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]
}

/// (c)'s map square [0, 1]² on the page, [x(s = 0), y(t = 1), x(s = 1), y(t = 0)], from its
/// tick labels: the centred "0" and "1" under (c)'s title (s) and the right-aligned ones (t),
/// each written at its tick.
fn c_square(all: &[Text], form: &str) -> Box4 {
    let title = all
        .iter()
        .find(|t| t.content.starts_with("(c)"))
        .unwrap_or_else(|| panic!("{form}: no (c) title"));
    let tick = |content: &str, anchor: &str| -> &Text {
        let found: Vec<&Text> = all
            .iter()
            .filter(|t| {
                t.content == content
                    && !t.rotated
                    && attr_str(&t.tag, "text-anchor") == Some(anchor)
                    && t.y > title.y
                    && t.bbox[0] > title.bbox[0] - 40.0
            })
            .collect();
        assert_eq!(
            found.len(),
            1,
            "{form}: (c)'s {anchor} {content:?}: {found:?}"
        );
        found[0]
    };
    let square = [
        tick("0", "middle").x,
        tick("1", "end").y,
        tick("1", "middle").x,
        tick("0", "end").y,
    ];
    assert!(
        square[2] - square[0] > 40.0
            && (square[2] - square[0] - (square[3] - square[1])).abs() < 2.0,
        "{form}: (c)'s square {square:?} is not a square"
    );
    square
}

/// R13-martin-tan-fig3-1 (required): in every form the word "focus" is written once (not in
/// (b)), its text box outside (c)'s map square; no polyline but its leader, no polygon's edge
/// and no `<rect>` but the page's passes within 1 unit of the box, and no other text overlaps
/// it; its leader (grey #5A5A5A, two points) starts within 3 units of the box and ends within 2
/// units of the focus region's outline in (c) (the wine #882255 lines inside the square).
#[test]
fn focus_label_outside_the_map_joined_to_the_region() {
    let font = Font::dejavu();
    for (form, opts) in forms() {
        let svg = render_svg("martin-tan-fig3", &opts);
        let all = texts(&font, &svg);
        let words: Vec<&Text> = all.iter().filter(|t| t.content == "focus").collect();
        assert_eq!(
            words.len(),
            1,
            "{form}: \"focus\" written {} times",
            words.len()
        );
        let word = words[0];
        let b = word.bbox;
        let sq = c_square(&all, form);
        assert!(
            b[2] <= sq[0] || b[0] >= sq[2] || b[3] <= sq[1] || b[1] >= sq[3],
            "{form}: \"focus\" {b:?} inside (c)'s map square {sq:?}"
        );
        let lines = polylines(&svg);
        let leaders: Vec<usize> = (0..lines.len())
            .filter(|&i| {
                let l = &lines[i];
                l.colour == "#5A5A5A"
                    && l.points.len() == 2
                    && l.points.iter().any(|&p| to_box(p, &b) <= 3.0)
            })
            .collect();
        assert_eq!(
            leaders.len(),
            1,
            "{form}: leaders at \"focus\": {leaders:?}"
        );
        let leader = &lines[leaders[0]].points;
        let (near, far) = if to_box(leader[0], &b) <= to_box(leader[1], &b) {
            (leader[0], leader[1])
        } else {
            (leader[1], leader[0])
        };
        assert!(to_box(near, &b) <= 3.0, "{form}: {near:?}");
        for (i, l) in lines.iter().enumerate().filter(|&(i, _)| i != leaders[0]) {
            for s in l.points.windows(2) {
                assert!(
                    !segment_enters(s[0], s[1], &b, -1.0),
                    "{form}: polyline {i} {} {:?} within 1 unit of \"focus\" {b:?}",
                    l.colour,
                    l.points
                );
            }
        }
        for p in polygons(&svg) {
            let n = p.points.len();
            for k in 0..n {
                let (a, c) = (p.points[k], p.points[(k + 1) % n]);
                assert!(
                    !segment_enters(a, c, &b, -1.0),
                    "{form}: polygon {} {:?} within 1 unit of \"focus\" {b:?}",
                    p.colour,
                    p.points
                );
            }
        }
        // Boxes: the page's own white background (the biggest) aside, none near the word.
        let rects: Vec<Box4> = svg
            .lines()
            .filter(|l| l.starts_with("<rect"))
            .filter_map(|l| {
                let (x, y) = (attr(l, "x")?, attr(l, "y")?);
                Some([x, y, x + attr(l, "width")?, y + attr(l, "height")?])
            })
            .collect();
        let page = rects
            .iter()
            .copied()
            .fold(0.0, |m: f64, r| m.max((r[2] - r[0]) * (r[3] - r[1])));
        let grown = [b[0] - 1.0, b[1] - 1.0, b[2] + 1.0, b[3] + 1.0];
        for r in rects
            .iter()
            .filter(|r| (r[2] - r[0]) * (r[3] - r[1]) < page)
        {
            assert!(!overlap(r, &grown), "{form}: box {r:?} at \"focus\" {b:?}");
        }
        for t in all.iter().filter(|t| !std::ptr::eq(*t, word)) {
            assert!(
                !overlap(&t.bbox, &b),
                "{form}: \"focus\" {b:?} overlaps {:?} {:?}",
                t.content,
                t.bbox
            );
        }
        // The focus region in (c): the wine lines within its square (2 units' slack).
        let inside = |p: &(f64, f64)| {
            p.0 >= sq[0] - 2.0 && p.0 <= sq[2] + 2.0 && p.1 >= sq[1] - 2.0 && p.1 <= sq[3] + 2.0
        };
        let region: Vec<&Vec<(f64, f64)>> = lines
            .iter()
            .filter(|l| l.colour == "#882255" && l.points.iter().all(inside))
            .map(|l| &l.points)
            .collect();
        assert!(!region.is_empty(), "{form}: no focus region in (c)");
        let gap = region
            .iter()
            .flat_map(|l| l.windows(2).map(|s| to_segment(far, s[0], s[1])))
            .fold(f64::INFINITY, f64::min);
        assert!(
            gap <= 2.0,
            "{form}: the leader ends at {far:?}, {gap:.2} units from the focus region's outline"
        );
    }
}
