//! A y axis' name is no longer than its axis (the fourth figure review, one column: the names of
//! lloyd2005-fig7's, fig10's and fig12's S̄ and m_max axes, "… (texels per image pixel, log
//! scale)", ran past both ends of plots about 110 to 200 units tall, into the panel's title and
//! the x axis' name). Read from the SVG of each line and bar chart of the Lloyd papers and of
//! barroso-fig7, in every form: each turned text (an axis' name) lies, along its length, within
//! the y axis right of it (a vertical black line at least 40 units long, whose span it overlaps),
//! to 2 units.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::*;

/// The figures read.
const CHARTS: [&str; 10] = [
    "lloyd2005-fig4",
    "lloyd2005-fig7",
    "lloyd2005-fig8",
    "lloyd2006-fig5",
    "lloyd2006-fig6",
    "lloyd2006-fig10",
    "lloyd2006-fig12",
    "lloyd2006-fig13",
    "lloyd2006-worst-case",
    "barroso-fig7",
];

/// The y axes of `svg`: vertical black polylines of two points at least 40 units long (tick
/// marks are 5), as
/// (x, top, bottom).
fn y_axes(svg: &str) -> Vec<(f64, f64, f64)> {
    polylines(svg)
        .into_iter()
        .filter(|s| s.colour == "#000000")
        .filter_map(|s| match s.points[..] {
            [a, b] if (a.0 - b.0).abs() < 0.01 && (a.1 - b.1).abs() >= 40.0 => {
                Some((a.0, a.1.min(b.1), a.1.max(b.1)))
            }
            _ => None,
        })
        .collect()
}

/// The turned texts of `svg` that run past the axis right of them: (text, its span, the axis').
fn overruns(font: &Font, svg: &str) -> Vec<String> {
    let axes = y_axes(svg);
    let mut out = Vec::new();
    for t in texts(font, svg).into_iter().filter(|t| t.rotated) {
        let [_, y0, x1, y1] = t.bbox;
        // The axis right of the name; or, for an axis drawn on a plot's right (lloyd2005-fig8's
        // one-column t axis, right of its texture), the one left of it.
        let x0 = t.bbox[0];
        let axis = axes
            .iter()
            .filter(|a| a.0 > x1 && a.1 < y1 && a.2 > y0)
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .or_else(|| {
                axes.iter()
                    .filter(|a| a.0 < x0 && a.1 < y1 && a.2 > y0)
                    .max_by(|a, b| a.0.total_cmp(&b.0))
            });
        match axis {
            Some(&(_, top, bottom)) if y0 >= top - 2.0 && y1 <= bottom + 2.0 => {}
            Some(&(_, top, bottom)) => out.push(format!(
                "{:?} spans {y0:.1}–{y1:.1}, its axis {top:.1}–{bottom:.1}",
                t.content
            )),
            None => out.push(format!("{:?}: no y axis beside it", t.content)),
        }
    }
    out
}

/// The reading on a page written by hand: an axis from 20 to 120, a name 50 units long
/// centred on it fits, one 130 units long does not.
#[test]
fn names_are_measured_against_their_axes() {
    let font = Font::dejavu();
    let page = |name: &str| {
        format!(
            "<svg viewBox=\"0 0 200 200\">\n\
             <polyline fill=\"none\" stroke=\"#000000\" points=\"40,20 40,120\"/>\n\
             <text x=\"20\" y=\"70\" dy=\"0.76em\" font-size=\"10\" text-anchor=\"middle\" \
             transform=\"rotate(270, 20, 70)\">{name}</text>\n</svg>"
        )
    };
    assert!(overruns(&font, &page("short name")).is_empty());
    let long = "a name far longer than the axis it names";
    assert_eq!(overruns(&font, &page(long)).len(), 1);
}

/// Every y axis' name in every form of these figures within its axis.
#[test]
fn y_axis_names_fit_their_axes() {
    let font = Font::dejavu();
    let mut bad = Vec::new();
    let mut read = 0;
    for (name, layout, svg) in all_svgs() {
        if !CHARTS.contains(&name.as_str()) {
            continue;
        }
        read += 1;
        for o in overruns(&font, svg) {
            bad.push(format!("{name} ({layout}): {o}"));
        }
    }
    assert_eq!(read, 3 * CHARTS.len());
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
