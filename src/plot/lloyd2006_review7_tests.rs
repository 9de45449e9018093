//! Tests of the seventh figure review's findings on the storage-factor figures (issue 35,
//! R7-X-1, R7-X-2, R7-X-4, R7-2006f5-1, -f6-1, -f12-1/-2/-3, -f13-1, -wc-1/-2), each read from
//! the rendered SVG or the figures' own axes.

use super::forms_tests::svg_of;
use super::*;
use crate::plot::chart::read_svg::{attr, points, texts};
use crate::plot::chart::Scale;

/// How a key entry's sample is drawn, read from the SVG: the colour of its strokes and fills,
/// the number of pieces of its line (0: markers only, 1: solid, more: dashed), whether its
/// marker is filled (a `<polygon>`) or hollow (a closed `<polyline>`), and the marker's corners.
#[derive(Debug, PartialEq)]
struct Sample {
    colour: String,
    pieces: usize,
    filled: bool,
    corners: usize,
}

/// The sample left of the key text `label` of `svg`: every `<polyline>` and `<polygon>` whose
/// points all lie within the sample's length and the gap (40 units) left of the text's start
/// and within 9 units of its line.
fn sample(svg: &str, label: &str) -> Sample {
    let t = texts(svg);
    let found: Vec<_> = t.iter().filter(|t| t.1 == label).collect();
    assert_eq!(found.len(), 1, "{label:?} written {} times", found.len());
    let (x, y) = (attr(found[0].0, "x").unwrap(), found[0].2);
    let mut colours = Vec::new();
    let (mut pieces, mut marker) = (0, None);
    for l in svg
        .lines()
        .filter(|l| l.starts_with("<polyline") || l.starts_with("<polygon"))
    {
        let Some(p) = points(l) else { continue };
        let inside = !p.is_empty()
            && p.iter()
                .all(|q| q.0 < x && q.0 > x - 40.0 && (q.1 - y).abs() <= 9.0);
        if !inside {
            continue;
        }
        let key = if l.starts_with("<polygon") {
            "fill=\""
        } else {
            "stroke=\""
        };
        let at = l.find(key).unwrap() + key.len();
        colours.push(l[at..at + 7].to_string());
        if l.starts_with("<polygon") {
            marker = Some((true, p.len()));
        } else if p.len() >= 4 && p.first() == p.last() {
            marker = Some((false, corners(&p[1..])));
        } else {
            pieces += 1;
        }
    }
    colours.dedup();
    assert_eq!(colours.len(), 1, "{label}: {colours:?}");
    let (filled, corners) = marker.unwrap_or_else(|| panic!("{label}: no marker"));
    Sample {
        colour: colours.remove(0),
        pieces,
        filled,
        corners,
    }
}

/// The corners of a closed outline given once round (its first point not repeated): the points
/// where it turns, so that a point halfway along a side (where a hollow marker's stroke starts
/// and ends) is not one.
fn corners(p: &[(f64, f64)]) -> usize {
    let n = p.len();
    (0..n)
        .filter(|&i| {
            let (a, b, c) = (p[(i + n - 1) % n], p[i], p[(i + 1) % n]);
            ((b.0 - a.0) * (c.1 - b.1) - (b.1 - a.1) * (c.0 - b.0)).abs() > 0.01
        })
        .count()
}

/// `c` as an SVG writes it.
fn hex(c: RGBColor) -> String {
    format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2)
}

/// R7-X-2, R7-2006f12-3, R7-2006wc-2: one encoding per scheme in lloyd2006-fig12 and
/// lloyd2006-worst-case, read from the keys' samples in the SVGs: the same key text
/// "ZP = ZP+W, behind" is drawn alike in both (it was teal dashed with hollow circles in one,
/// grey dashed with filled hexagons in the other), each scheme's overhead (fig12) and worst
/// (worst-case) entries alike, and FP+ZP+W's behind entries alike; and by hand the rule: ZP
/// teal circles (12 corners), ZP+W rose squares (4), FP+ZP+W brown triangles (3) and markers
/// only; behind dashed (two pieces or more) and hollow, the others solid and filled.
#[test]
fn fig12_and_worst_case_draw_each_scheme_alike() {
    let (f12, wc) = (
        svg_of("lloyd2006-fig12", Column::Double, false),
        svg_of("lloyd2006-worst-case", Column::Double, false),
    );
    let zp_behind = sample(&f12, "ZP = ZP+W, behind");
    assert_eq!(zp_behind, sample(&wc, "ZP = ZP+W, behind"));
    assert_eq!(
        sample(&f12, "FP+ZP+W, behind"),
        sample(&wc, "FP+ZP+W, worst = behind")
    );
    for scheme in ["ZP", "ZP+W"] {
        assert_eq!(
            sample(&f12, &format!("{scheme}, overhead")),
            sample(&wc, &format!("{scheme}, worst")),
            "{scheme}"
        );
    }
    let by_hand = [
        ("ZP, overhead", Look::Zp, 1, true, 12),
        ("ZP+W, overhead", Look::ZpW, 1, true, 4),
        ("FP+ZP+W, overhead", Look::FpZpW, 0, true, 3),
        ("FP+ZP+W, behind", Look::FpZpW, 0, false, 3),
    ];
    for (label, look, pieces, filled, corners) in by_hand {
        assert_eq!(
            sample(&f12, label),
            Sample {
                colour: hex(look.colour()),
                pieces,
                filled,
                corners
            },
            "{label}"
        );
    }
    assert_eq!(zp_behind.colour, hex(Look::Zp.colour()));
    assert!(zp_behind.pieces >= 2 && !zp_behind.filled && zp_behind.corners == 12);
}

/// R7-X-1: every logarithmic y axis of lloyd2006-fig5, -fig6, -fig10, -fig12 and -worst-case,
/// in both forms, says so: its name ends "log scale)", or, where a one-column name has no room,
/// its panel's title says "log scale" or, for a page of one panel, its caption "on a log
/// scale"; a linear axis never does. Read from the charts' axes.
#[test]
fn every_log_axis_says_so_in_both_forms() {
    let figures = [
        ("lloyd2006-fig5", fig5()),
        ("lloyd2006-fig6", fig6()),
        ("lloyd2006-fig10", fig10()),
        ("lloyd2006-fig12", fig12()),
        ("lloyd2006-worst-case", super::super::worst::worst_case()),
    ];
    let mut logs = 0;
    for (name, fig) in figures {
        let fig = fig.map_err(|e| e.named(name)).unwrap();
        let single = fig.single.as_ref().unwrap();
        for (form, page) in [("two columns", &fig.page), ("one column", &single.page)] {
            for c in &page.charts {
                // A one-panel page whose caption says it (lloyd2006-fig6, whose y name has no
                // room for the scale beside "(ratios)").
                let captioned = page.charts.len() == 1
                    && page.caption.iter().any(|l| l.contains("on a log scale"));
                let said =
                    c.y.label.ends_with("log scale)") || c.title.contains("log scale") || captioned;
                match c.y.scale {
                    Scale::Log(_) => {
                        logs += 1;
                        assert!(said, "{name}, {form}: {:?} / {:?}", c.title, c.y.label);
                    }
                    _ => assert!(!said, "{name}, {form}: {:?}", c.y.label),
                }
            }
        }
    }
    // fig5 2 + 2, fig6 1 + 1, fig10 2 + 1, fig12 1 + 1, worst-case 2 + 1.
    assert_eq!(logs, 14);
    // lloyd2006-fig13's f/n axis (10⁰ to 10⁶), in the SVG of each form.
    for column in [Column::Double, Column::Single] {
        let svg = svg_of("lloyd2006-fig13", column, false);
        assert!(
            texts(&svg)
                .iter()
                .any(|t| t.1 == "depth ratio f/n (log scale)"),
            "{column:?}"
        );
    }
}

/// R7-X-4, R7-2006f6-1: lloyd2006-fig6 names S̄ in words ("storage factor S̄" in its title) and
/// its y axis gives S̄'s unit as lloyd2006-fig10, -fig12 and -worst-case do ("texels per image
/// pixel") and M_x's and M_z's as ratios (R16-, R17-lloyd2006-fig6-1), in every form; R7-2006f6-2: S̄'s markers are squares (four corners), not its
/// colour's tall bar. Read from the SVG.
#[test]
fn fig6_names_the_storage_factor_and_its_unit() {
    for (column, bare) in [
        (Column::Double, false),
        (Column::Double, true),
        (Column::Single, false),
    ] {
        let svg = svg_of("lloyd2006-fig6", column, bare);
        let t = texts(&svg);
        // S̄ as the SVG writes it: an S under a drawn bar.
        let joined: Vec<&str> = t.iter().map(|t| t.1.as_str()).collect();
        if !bare {
            assert!(
                joined.iter().any(|s| s.contains("storage factor S")),
                "{column:?}: {joined:?}"
            );
        }
        assert!(
            // M_x, M_z ratios, without S̄'s unit (R16-, R17-lloyd2006-fig6-1: "M_x, M_z;
            // S̄ (texels per image pixel, …)" read as the unit of all three).
            joined.contains(&"Mx, Mz (ratios); S (texels per image pixel)"),
            "{column:?} bare {bare}: {joined:?}"
        );
        // S̄'s markers: black polygons, each a square.
        let squares = svg
            .lines()
            .filter(|l| l.starts_with("<polygon fill=\"#000000\""))
            .filter_map(points)
            .filter(|p| p.len() == 4)
            .count();
        assert!(squares >= 4, "{column:?}: {squares} black squares");
    }
}
