//! Greyscale (issue 35, item 8): in the diagrams whose parts are told apart by colour, two parts
//! that touch and print as nearly the same grey also differ by something that survives
//! greyscale. Read from the SVGs as written, with the grey computed here (CIE L* of the colour
//! as printed on white, sRGB linearised by its standard formula):
//! - lloyd2005-fig8: the partitions' fills (panels (a) and (c)): two fills that share a piece of
//!   an edge and are within [`SAME_GREY`] in L* carry different hatches (the directions of the
//!   thin lines drawn inside them).
//!
//! barroso-fig5's and lloyd2006-fig11's maps (each its own dash pattern, in every form) are
//! checked in tests/figures_f_from_light.rs.
#![cfg(feature = "plot")]

use shadow_aliasing::plot::{render, Format};
use std::path::Path;

/// Two greys closer than this in CIE L* (0 black … 100 white) count as the same grey.
const SAME_GREY: f64 = 10.0;

fn svg(name: &str) -> String {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "figures-layouts-greyscale-{name}-{}",
        std::process::id()
    ));
    let files = render(name, &dir, Format::Svg).unwrap();
    let s = std::fs::read_to_string(&files[0]).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    s
}

fn attr<'a>(el: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let at = el.find(&key)? + key.len();
    Some(&el[at..at + el[at..].find('"')?])
}

fn points(el: &str) -> Vec<(f64, f64)> {
    attr(el, "points")
        .unwrap()
        .split_whitespace()
        .map(|p| {
            let (x, y) = p.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect()
}

/// The CIE L* of `#RRGGBB` drawn at `opacity` over white.
fn lightness(hex: &str, opacity: f64) -> f64 {
    let lin = |i: usize| {
        let c = f64::from(u8::from_str_radix(&hex[i..i + 2], 16).unwrap());
        let v = (255.0 * (1.0 - opacity) + c * opacity) / 255.0;
        if v <= 0.04045 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    let y = 0.2126 * lin(1) + 0.7152 * lin(3) + 0.0722 * lin(5);
    if y > 216.0 / 24389.0 {
        116.0 * y.cbrt() - 16.0
    } else {
        y * 24389.0 / 27.0
    }
}

#[test]
fn lightness_by_hand() {
    // White 100, black 0, mid grey #777777 (sRGB 119: Y = 0.1845) 50.0; the review's orange
    // #E69F00 and sky blue #56B4E9 both about 70, so they count as one grey.
    assert!((lightness("#FFFFFF", 1.0) - 100.0).abs() < 1e-9);
    assert!(lightness("#000000", 1.0).abs() < 1e-9);
    assert!((lightness("#777777", 1.0) - 50.0).abs() < 0.1);
    assert!((lightness("#E69F00", 1.0) - lightness("#56B4E9", 1.0)).abs() < SAME_GREY);
    // Black at 35 % over white is #A6A6A6.
    assert!((lightness("#000000", 0.35) - lightness("#A6A6A6", 1.0)).abs() < 0.3);
}

/// Whether the point `p` lies inside the convex polygon `poly`, at least `margin` from its
/// edges (either orientation).
fn inside(poly: &[(f64, f64)], p: (f64, f64), margin: f64) -> bool {
    let n = poly.len();
    let mut sign = 0.0;
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        let (ex, ey) = (b.0 - a.0, b.1 - a.1);
        let len = (ex * ex + ey * ey).sqrt();
        if len < 1e-9 {
            continue;
        }
        let d = (ex * (p.1 - a.1) - ey * (p.0 - a.0)) / len;
        if sign == 0.0 {
            sign = d.signum();
        }
        if d * sign < margin {
            return false;
        }
    }
    true
}

/// Whether two polygons share a piece of an edge longer than 2 units: a pair of collinear
/// edges whose projections overlap.
fn touch(a: &[(f64, f64)], b: &[(f64, f64)]) -> bool {
    let edges = |p: &[(f64, f64)]| -> Vec<((f64, f64), (f64, f64))> {
        (0..p.len()).map(|i| (p[i], p[(i + 1) % p.len()])).collect()
    };
    for (p, q) in edges(a) {
        let (dx, dy) = (q.0 - p.0, q.1 - p.1);
        let len = (dx * dx + dy * dy).sqrt();
        if len < 2.0 {
            continue;
        }
        let (ux, uy) = (dx / len, dy / len);
        for (r, s) in edges(b) {
            let off = |z: (f64, f64)| (ux * (z.1 - p.1) - uy * (z.0 - p.0)).abs();
            if off(r) > 1.5 || off(s) > 1.5 {
                continue;
            }
            let t = |z: (f64, f64)| ux * (z.0 - p.0) + uy * (z.1 - p.1);
            let (lo, hi) = (t(r).min(t(s)), t(r).max(t(s)));
            if hi.min(len) - lo.max(0.0) > 2.0 {
                return true;
            }
        }
    }
    false
}

/// A filled part: its outline, colour, L* and the directions (degrees mod 180, to 45°) of the
/// hatch lines inside it.
struct Part {
    outline: Vec<(f64, f64)>,
    colour: String,
    grey: f64,
    hatch: Vec<i64>,
}

/// The translucent fills of an SVG (polygons, and rects turned into their four corners) with
/// the hatches inside them: thin translucent lines at least 6 units long whose both ends lie on
/// or in the outline and whose middle lies inside it.
fn parts(svg: &str) -> Vec<Part> {
    let mut out = Vec::new();
    let mut lines = Vec::new();
    for el in svg.split('<').skip(1) {
        let el = &el[..el.find('>').unwrap_or(el.len())];
        let opacity: f64 = attr(el, "opacity").map_or(1.0, |o| o.parse().unwrap());
        if el.starts_with("polygon ") && opacity < 1.0 {
            let colour = attr(el, "fill").unwrap().to_string();
            out.push(Part {
                outline: points(el),
                grey: lightness(&colour, opacity),
                colour,
                hatch: Vec::new(),
            });
        } else if el.starts_with("polyline ") && opacity < 1.0 {
            let p = points(el);
            if p.len() == 2 {
                lines.push((p[0], p[1]));
            }
        }
    }
    for part in &mut out {
        let mut dirs = Vec::new();
        for &(a, b) in &lines {
            let (dx, dy) = (b.0 - a.0, b.1 - a.1);
            if (dx * dx + dy * dy).sqrt() < 6.0 {
                continue;
            }
            let mid = (0.5 * (a.0 + b.0), 0.5 * (a.1 + b.1));
            let ends_in = inside(&part.outline, a, -1.5) && inside(&part.outline, b, -1.5);
            if ends_in && inside(&part.outline, mid, 1.0) {
                let deg = dy.atan2(dx).to_degrees().rem_euclid(180.0);
                let d = ((deg / 45.0).round() as i64 * 45) % 180;
                if !dirs.contains(&d) {
                    dirs.push(d);
                }
            }
        }
        dirs.sort_unstable();
        part.hatch = dirs;
    }
    out
}

/// lloyd2005-fig8: every pair of touching partitions that print as one grey differs in hatch;
/// there are such pairs (the pastels are all L* 80–89), so the check is not vacuous.
#[test]
fn fig8_touching_fills_differ_by_hatch() {
    let s = svg("lloyd2005-fig8");
    let parts = parts(&s);
    assert!(parts.len() >= 14, "{} fills", parts.len());
    let mut checked = 0;
    let mut bad = Vec::new();
    for (i, a) in parts.iter().enumerate() {
        for b in &parts[i + 1..] {
            if !touch(&a.outline, &b.outline) || (a.grey - b.grey).abs() >= SAME_GREY {
                continue;
            }
            checked += 1;
            if a.hatch == b.hatch {
                bad.push(format!(
                    "{} (L* {:.1}, hatch {:?}) and {} (L* {:.1}, hatch {:?}) touch",
                    a.colour, a.grey, a.hatch, b.colour, b.grey, b.hatch
                ));
            }
        }
    }
    assert!(checked >= 8, "only {checked} touching pairs of one grey");
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
