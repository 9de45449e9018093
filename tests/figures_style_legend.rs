//! Legends never cover data and their texts never run past their boxes (issue 35; the review
//! found the legend over curves in lloyd2006-fig5, lloyd2006-fig6, lloyd2006-worst-case and
//! barroso-fig7, and "(max. 8574)", "(measured)" and "behind" past the box's border). Checked
//! on every figure's SVG in every layout: no plotted polyline enters a legend box and no
//! marker overlaps one (a legend's own samples lie wholly inside it), and every text anchored
//! inside a legend box lies inside it, measured with DejaVu Sans' advances at the PNG's size.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::*;

/// How far a line or text may reach into or past a box before it counts (half a unit: the
/// SVG's box is written at whole units).
const TOL: f64 = 0.5;

/// What covers a legend of `svg` or runs past it, one line each.
fn legend_faults(font: &Font, svg: &str) -> Vec<String> {
    let mut bad = Vec::new();
    let lines = polylines(svg);
    let marks = polygons(svg);
    let words = texts(font, svg);
    for b in legend_boxes(svg) {
        for l in lines.iter().filter(|l| !within(&l.points, &b)) {
            if let Some(w) = l
                .points
                .windows(2)
                .find(|w| segment_enters(w[0], w[1], &b, TOL))
            {
                bad.push(format!(
                    "a {} line {:?}–{:?} crosses the legend {b:?}",
                    l.colour, w[0], w[1]
                ));
            }
        }
        for m in marks.iter().filter(|m| !within(&m.points, &b)) {
            let xs = m.points.iter().map(|p| p.0);
            let ys = m.points.iter().map(|p| p.1);
            let r = [
                xs.clone().fold(f64::INFINITY, f64::min),
                ys.clone().fold(f64::INFINITY, f64::min),
                xs.fold(f64::NEG_INFINITY, f64::max),
                ys.fold(f64::NEG_INFINITY, f64::max),
            ];
            let across = r[2].min(b[2]) - r[0].max(b[0]);
            let down = r[3].min(b[3]) - r[1].max(b[1]);
            if across > TOL && down > TOL {
                bad.push(format!(
                    "a {} marker {r:?} under the legend {b:?}",
                    m.colour
                ));
            }
        }
        for t in words
            .iter()
            .filter(|t| t.x > b[0] && t.x < b[2] && t.y > b[1] && t.y < b[3])
        {
            let r = t.bbox;
            if r[0] < b[0] - TOL || r[2] > b[2] + TOL || r[1] < b[1] - TOL || r[3] > b[3] + TOL {
                bad.push(format!(
                    "{:?} spans {:.1}..{:.1} × {:.1}..{:.1}, its legend {b:?}",
                    t.content, r[0], r[2], r[1], r[3]
                ));
            }
        }
    }
    bad
}

/// The check itself, on hand-made SVGs: a legend box 10..110 × 10..40 with its own sample
/// inside; a data line through it, a marker under it and a text too long for it are each found
/// ("MMMMMMMM" at font size 10 is 8 × 0.8628 em × 10 × 1.24/1.164 = 73.5 wide, so from x = 40
/// it ends at 113.5, past 110), and the same figure without them is clean.
#[test]
fn covered_and_overflowing_legends_are_found() {
    let font = Font::dejavu();
    let svg = |extra: &str, text_x: f64| {
        format!(
            "<svg viewBox=\"0 0 200 100\">\n\
             <polyline fill=\"none\" stroke=\"#0072B2\" points=\"0,80 200,80\"/>\n\
             <rect x=\"10\" y=\"10\" width=\"100\" height=\"30\" fill=\"#FFFFFF\" opacity=\"0.9\"/>\n\
             <rect x=\"10\" y=\"10\" width=\"100\" height=\"30\" fill=\"none\" stroke=\"#787878\"/>\n\
             <polyline fill=\"none\" stroke=\"#0072B2\" points=\"15,25 35,25\"/>\n\
             <polygon fill=\"#0072B2\" points=\"23,23 27,23 27,27 23,27\"/>\n\
             <text x=\"{text_x}\" y=\"25\" dy=\"0.5ex\" font-size=\"10\">MMMMMMMM</text>\n\
             {extra}</svg>"
        )
    };
    assert_eq!(legend_faults(&font, &svg("", 30.0)), Vec::<String>::new());
    let crossing = "<polyline fill=\"none\" stroke=\"#D55E00\" points=\"0,0 200,60\"/>\n";
    assert_eq!(legend_faults(&font, &svg(crossing, 30.0)).len(), 1);
    let marker = "<polygon fill=\"#D55E00\" points=\"100,35 106,35 106,45 100,45\"/>\n";
    assert_eq!(legend_faults(&font, &svg(marker, 30.0)).len(), 1);
    assert_eq!(legend_faults(&font, &svg("", 40.0)).len(), 1);
    // A line that only runs along the box's outside does not count.
    let beside = "<polyline fill=\"none\" stroke=\"#D55E00\" points=\"0,41 200,41\"/>\n";
    assert!(legend_faults(&font, &svg(beside, 30.0)).is_empty());
}

/// Every figure, captioned across two columns and in one, and bare: no legend covers data and
/// every legend's text fits its box. Four figures with keys have legends in both layouts (so
/// the check has something to check).
#[test]
fn no_legend_covers_data_or_overflows() {
    let font = Font::dejavu();
    let mut bad = Vec::new();
    let mut found = Vec::new();
    for (name, layout, svg) in all_svgs() {
        if !legend_boxes(svg).is_empty() {
            found.push(format!("{name} {layout}"));
        }
        for b in legend_faults(&font, svg) {
            bad.push(format!("{name} ({layout}): {b}"));
        }
    }
    // lloyd2006-fig5 has no legend since its labels in (b) name both panels' curves.
    for name in [
        "lloyd2006-fig12",
        "lloyd2006-fig6",
        "lloyd2006-worst-case",
        "barroso-fig7",
    ] {
        for layout in ["Double", "Single"] {
            assert!(
                found.contains(&format!("{name} {layout}")),
                "{name} ({layout}) has no legend box: {found:?}"
            );
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
