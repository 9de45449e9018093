//! Issue 25 (G3): in every figure of line charts, no direct label's or legend's white box covers
//! a line or marker of another series. Checked on the SVGs as written: each white box (a `rect`
//! filled white, translucent) against every series polyline and marker polygon of a colour
//! other than the box's own text, except what is drawn after the box inside it (the legend's
//! own samples).
#![cfg(feature = "plot")]

use shadow_aliasing::plot::{render, Format};

/// The figures drawn as pages of line charts.
const LINE_CHARTS: &[&str] = &[
    "lloyd2005-fig4",
    "lloyd2005-fig7",
    "lloyd2006-fig5",
    "lloyd2006-fig6",
    "lloyd2006-fig10",
    "lloyd2006-fig12",
    "barroso-fig7",
    "lloyd2006-worst-case",
];

fn attr<'a>(line: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let at = line.find(&key)? + key.len();
    Some(&line[at..at + line[at..].find('"')?])
}

fn num(line: &str, name: &str) -> f64 {
    attr(line, name).unwrap().parse().unwrap()
}

fn points(line: &str) -> Vec<(f64, f64)> {
    attr(line, "points")
        .unwrap()
        .split_whitespace()
        .map(|p| {
            let (x, y) = p.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect()
}

/// Whether the segment a–b enters the open box (x0, x1) × (y0, y1) (Liang–Barsky).
fn crosses(a: (f64, f64), b: (f64, f64), (x0, y0, x1, y1): (f64, f64, f64, f64)) -> bool {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-dx, a.0 - x0),
        (dx, x1 - a.0),
        (-dy, a.1 - y0),
        (dy, y1 - a.1),
    ] {
        if p == 0.0 {
            if q <= 0.0 {
                return false;
            }
        } else if p < 0.0 {
            t0 = t0.max(q / p);
        } else {
            t1 = t1.min(q / p);
        }
    }
    t0 < t1
}

/// Whether the text colour `text` (`#RRGGBB`) is the line colour `line` or that colour darkened
/// (its channels scaled down together, to within rounding), as a direct label's text is where
/// its line's colour is too light to read on white.
fn same_hue(line: &str, text: &str) -> bool {
    let rgb = |h: &str| -> [f64; 3] {
        [1, 3, 5].map(|i| f64::from(u8::from_str_radix(&h[i..i + 2], 16).unwrap()))
    };
    let (l, t) = (rgb(line), rgb(text));
    let lmax = l.iter().copied().fold(0.0, f64::max);
    if lmax == 0.0 {
        return t == l;
    }
    let k = t.iter().copied().fold(0.0, f64::max) / lmax;
    k <= 1.0 && l.iter().zip(&t).all(|(a, b)| (a * k - b).abs() <= 1.5)
}

#[derive(Debug)]
enum Shape {
    Line(Vec<(f64, f64)>),
    Marker(Vec<(f64, f64)>),
}

/// The covered series elements of one SVG: (box, its text's colour, what it covers).
fn covered(svg: &str) -> Vec<String> {
    let lines: Vec<&str> = svg.lines().collect();
    // Series: polylines of any colour but the axes' black, and marker polygons.
    let mut series = Vec::new();
    for (i, l) in lines.iter().enumerate() {
        if l.starts_with("<polyline") && attr(l, "stroke") != Some("#000000") {
            series.push((i, attr(l, "stroke").unwrap(), Shape::Line(points(l))));
        } else if l.starts_with("<polygon") {
            series.push((i, attr(l, "fill").unwrap(), Shape::Marker(points(l))));
        }
    }
    let mut bad = Vec::new();
    for (i, l) in lines.iter().enumerate() {
        if !(l.starts_with("<rect")
            && attr(l, "fill") == Some("#FFFFFF")
            && attr(l, "opacity").is_some())
        {
            continue;
        }
        let (x, y) = (num(l, "x"), num(l, "y"));
        let b = (
            x + 0.5,
            y + 0.5,
            x + num(l, "width") - 0.5,
            y + num(l, "height") - 0.5,
        );
        let own = lines[i..]
            .iter()
            .find(|t| t.starts_with("<text"))
            .and_then(|t| attr(t, "fill"))
            .unwrap();
        let inside = |p: &(f64, f64)| p.0 >= b.0 && p.0 <= b.2 && p.1 >= b.1 && p.1 <= b.3;
        for (j, colour, shape) in &series {
            if same_hue(colour, own) {
                continue;
            }
            let pts = match shape {
                Shape::Line(p) | Shape::Marker(p) => p,
            };
            if *j > i && pts.iter().all(inside) {
                continue;
            }
            let hit = match shape {
                Shape::Line(p) => p.windows(2).any(|w| crosses(w[0], w[1], b)),
                Shape::Marker(p) => {
                    let (mut lo, mut hi) = (p[0], p[0]);
                    for q in p {
                        lo = (lo.0.min(q.0), lo.1.min(q.1));
                        hi = (hi.0.max(q.0), hi.1.max(q.1));
                    }
                    lo.0 < b.2 && b.0 < hi.0 && lo.1 < b.3 && b.1 < hi.1
                }
            };
            if hit {
                bad.push(format!(
                    "box {b:?} (text {own}) covers a {} of {colour}",
                    match shape {
                        Shape::Line(_) => "line",
                        Shape::Marker(_) => "marker",
                    }
                ));
            }
        }
    }
    bad
}

#[test]
fn labels_and_legends_cover_no_other_series() {
    let dir = std::env::temp_dir().join(format!("sa-figures-labels-{}", std::process::id()));
    let mut failures = Vec::new();
    for name in LINE_CHARTS {
        let files = render(name, &dir, Format::Svg).unwrap();
        let svg = std::fs::read_to_string(&files[0]).unwrap();
        assert!(
            svg.contains("fill=\"#FFFFFF\""),
            "{name}: no label or legend box"
        );
        for b in covered(&svg) {
            failures.push(format!("{name}: {b}"));
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
