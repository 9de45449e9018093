//! No data marker lies on a y axis' spine (the eleventh review, R11-lloyd2006-worst-case-2:
//! (b)'s hollow triangle at k = 1, ratio 1, sat on the spine and touched the "1" tick label).
//! Read back from lloyd2006-worst-case's SVG in every form: the spines are the black vertical
//! two-point lines over 40 units long; the markers the coloured polygons (closed outlines)
//! under 16 units a side; no marker's box comes within half a unit of a spine it faces.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::{bbox, forms, polygons, polylines, render_svg};

#[test]
fn worst_case_markers_keep_off_the_spines() {
    for (form, opts) in forms() {
        let svg = render_svg("lloyd2006-worst-case", &opts);
        let spines: Vec<(f64, f64, f64)> = polylines(&svg)
            .into_iter()
            .filter(|s| s.colour == "#000000" && s.points.len() == 2)
            .filter(|s| s.points[0].0 == s.points[1].0)
            .map(|s| {
                let (a, b) = (s.points[0].1, s.points[1].1);
                (s.points[0].0, a.min(b), a.max(b))
            })
            .filter(|s| s.2 - s.1 > 40.0)
            .collect();
        assert_eq!(
            spines.len(),
            if form == "single" { 1 } else { 2 },
            "{form}: {spines:?}"
        );
        let markers: Vec<[f64; 4]> = polygons(&svg)
            .into_iter()
            .filter(|s| s.colour != "#000000" && s.points.len() >= 3)
            .map(|s| bbox(&s.points))
            .filter(|b| b[2] - b[0] < 16.0 && b[3] - b[1] < 16.0)
            .collect();
        assert!(markers.len() >= 15, "{form}: {} markers", markers.len());
        for m in &markers {
            for (x, y0, y1) in &spines {
                let beside = m[3] >= *y0 && m[1] <= *y1;
                assert!(
                    !beside || m[0] > x + 0.5 || m[2] < x - 0.5,
                    "{form}: a marker {m:?} on the spine at x = {x}"
                );
            }
        }
    }
}
