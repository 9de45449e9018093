//! The hemisphere figures (lloyd2006-fig7, martin-tan-fig6) and zhang-fig3 after the fourth
//! figure review, read back from the SVGs the figures command writes: each ring drawn once in
//! one style (a light halo beside each dark ring printed as a double ring); the line across the
//! disk only where the caption says what it is (martin-tan-fig6: the view's vertical plane, the
//! plane of its (b)); the one-column key covering little of its disk (it covered a third);
//! lloyd2006-fig7's one-column bars in the panels' order; the captions saying that the rings
//! are elevations and which TSM rule (a) shows; zhang-fig3's one-column rows with a scale of
//! two ticks each (one "40" a row).
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::{render_svg, strokes as lines, texts, Font, Stroke as Line, Text};
use shadow_aliasing::plot::{Column, Options};

fn svg(name: &str, column: Column, bare: bool) -> String {
    render_svg(
        name,
        &Options {
            column,
            bare,
            ..Options::default()
        },
    )
}

/// A circle fitted to a closed polyline of many points: centre and mean radius.
fn circle(points: &[(f64, f64)]) -> ((f64, f64), f64) {
    let k = points.len() as f64;
    let c = (
        points.iter().map(|p| p.0).sum::<f64>() / k,
        points.iter().map(|p| p.1).sum::<f64>() / k,
    );
    let r = points
        .iter()
        .map(|p| (p.0 - c.0).hypot(p.1 - c.1))
        .sum::<f64>()
        / k;
    (c, r)
}

/// The circle through three points: centre and radius (none where they lie on a line).
fn circle3(a: (f64, f64), b: (f64, f64), c: (f64, f64)) -> Option<((f64, f64), f64)> {
    let d = 2.0 * (a.0 * (b.1 - c.1) + b.0 * (c.1 - a.1) + c.0 * (a.1 - b.1));
    if d.abs() < 1e-6 {
        return None;
    }
    let n = |p: (f64, f64)| p.0 * p.0 + p.1 * p.1;
    let x = (n(a) * (b.1 - c.1) + n(b) * (c.1 - a.1) + n(c) * (a.1 - b.1)) / d;
    let y = (n(a) * (c.0 - b.0) + n(b) * (a.0 - c.0) + n(c) * (b.0 - a.0)) / d;
    Some(((x, y), (a.0 - x).hypot(a.1 - y)))
}

/// The disks of a figure: each centre with the radii of the circles drawn about it (largest
/// first), from the polylines of over 100 points that close on themselves, and from the arcs
/// (over 10 points, on one circle) into which a ring key's labels interrupt a ring, the arcs of
/// one circle counted once (an arc of under 50 points only where a disk is already found); and those circles' strokes and widths (one a circle).
#[allow(clippy::type_complexity)]
fn disks(svg: &str) -> (Vec<((f64, f64), Vec<f64>)>, Vec<(String, f64)>) {
    let mut out: Vec<((f64, f64), Vec<f64>)> = Vec::new();
    let mut styles = Vec::new();
    // Closed circles, then arcs longest first: an arc joins the disk whose centre lies within
    // 2 units of its fitted one, its radius measured from that centre.
    let mut arcs: Vec<(usize, (f64, f64), Vec<(f64, f64)>, String, f64)> = Vec::new();
    for l in lines(svg) {
        let (first, last) = match (l.points.first(), l.points.last()) {
            (Some(a), Some(b)) => (*a, *b),
            _ => continue,
        };
        if l.points.len() > 100 && (first.0 - last.0).hypot(first.1 - last.1) <= 0.5 {
            // A circle, not another closed line (lloyd2006-fig7's contours in (a)).
            let (c, r) = circle(&l.points);
            if l.points
                .iter()
                .all(|p| ((p.0 - c.0).hypot(p.1 - c.1) - r).abs() < 1.0)
            {
                arcs.push((usize::MAX, c, l.points, l.stroke, l.width));
            }
        } else if l.points.len() > 10 {
            let mid = l.points[l.points.len() / 2];
            if let Some((c, r)) = circle3(first, mid, last) {
                let on = l
                    .points
                    .iter()
                    .all(|p| ((p.0 - c.0).hypot(p.1 - c.1) - r).abs() < 0.3);
                if on && r < 200.0 {
                    arcs.push((l.points.len(), c, l.points, l.stroke, l.width));
                }
            }
        }
    }
    arcs.sort_by_key(|a| std::cmp::Reverse(a.0));
    for (_, fitted, points, stroke, width) in arcs {
        let at = out
            .iter()
            .position(|d| (d.0 .0 - fitted.0).hypot(d.0 .1 - fitted.1) < 2.0);
        let c = at.map_or(fitted, |i| out[i].0);
        let r = points
            .iter()
            .map(|p| (p.0 - c.0).hypot(p.1 - c.1))
            .sum::<f64>()
            / points.len() as f64;
        match at {
            Some(i) if out[i].1.iter().any(|q| (q - r).abs() < 0.6) => continue,
            Some(i) => out[i].1.push(r),
            // A short arc's fitted centre is too loose to start a disk.
            None if points.len() < 50 => continue,
            None => out.push((c, vec![r])),
        }
        styles.push((stroke, width));
    }
    for d in &mut out {
        d.1.sort_by(|a, b| b.total_cmp(a));
    }
    (out, styles)
}

/// The figures with hemispheres and their disks in two columns and in one: lloyd2006-fig7's
/// five panels, and in two columns a sixth disk, the ring key with no data in the sixth cell
/// (fifth review: the key's labels covered (a)'s data); one column keys (a) itself. Last, the
/// width of the rings: lloyd2006-fig7's half a unit (grey, under (a)'s contours: the eleventh
/// review, R11-lloyd2006-fig7-1), martin-tan-fig6's one unit.
const HEMISPHERES: [(&str, usize, usize, f64); 2] = [
    ("lloyd2006-fig7", 6, 5, 0.5),
    ("martin-tan-fig6", 1, 1, 1.0),
];

/// Each ring once, in one style (review: "rings print as double rings"): in both figures and
/// both layouts every disk, lloyd2006-fig7's key disk included, has exactly five circles, at
/// (90° − el)/90° of the horizon's radius for el = 0°, 10°, 20°, 30°, 60° (the azimuthal
/// equidistant projection, by hand), and every circle of the figure has one stroke colour and
/// one width (the figure's: [`HEMISPHERES`]); none is white (the old halo under each inner
/// ring was a white circle three units wide beside the dark one).
#[test]
fn each_ring_is_drawn_once_in_one_style() {
    for (name, double, single, width) in HEMISPHERES {
        for (column, n) in [(Column::Double, double), (Column::Single, single)] {
            let s = svg(name, column, false);
            let (found, styles) = disks(&s);
            assert_eq!(found.len(), n, "{name} {column:?}: {} disks", found.len());
            for (c, radii) in &found {
                assert_eq!(radii.len(), 5, "{name} {column:?} at {c:?}: {radii:?}");
                let horizon = radii[0];
                for (r, el) in radii.iter().zip([0.0, 10.0, 20.0, 30.0, 60.0]) {
                    let want = horizon * (90.0 - el) / 90.0;
                    assert!((r - want).abs() < 0.6, "{name}: the {el}° ring at {r}");
                }
            }
            let (stroke, _) = &styles[0];
            assert_ne!(stroke, "#FFFFFF", "{name} {column:?}");
            for (s, w) in &styles {
                assert_eq!(s, stroke, "{name} {column:?}: rings in two colours");
                assert!(
                    (w - width).abs() < 1e-9,
                    "{name} {column:?}: a ring {w} wide"
                );
            }
        }
    }
}

/// The caption's lines: the grey (#323232) texts, joined, no-break spaces read as spaces.
fn caption(all: &[Text]) -> String {
    all.iter()
        .filter(|t| t.tag.contains("fill=\"#323232\""))
        .map(|t| t.content.as_str())
        .collect::<Vec<_>>()
        .join(" ")
        .replace('\u{a0}', " ")
}

/// The line across the disk (review: "the horizon line is unexplained"): lloyd2006-fig7 draws
/// none; martin-tan-fig6 draws one, in the rings' style, through the disk's centre from rim to
/// rim (2 × the horizon's radius long, by the fitted circle), and its caption says what it is,
/// the view's vertical plane, the plane of (b), in both layouts.
#[test]
fn the_line_across_a_disk_is_explained_or_absent() {
    let font = Font::dejavu();
    for (name, want) in [("lloyd2006-fig7", 0), ("martin-tan-fig6", 1)] {
        for (column, says) in [
            (Column::Double, "line: (b)'s plane"),
            (Column::Single, "line: (b)'s plane"),
        ] {
            let s = svg(name, column, false);
            let (found, styles) = disks(&s);
            let ink = &styles[0].0;
            // Straight horizontal pieces in the rings' ink (a ring key's labels may interrupt
            // the line): their extent is the line.
            let pieces: Vec<Line> = lines(&s)
                .into_iter()
                .filter(|l| {
                    &l.stroke == ink
                        && l.points.len() >= 2
                        && l.points.iter().all(|p| (p.1 - l.points[0].1).abs() < 0.01)
                        && (l.points[l.points.len() - 1].0 - l.points[0].0).abs() > 2.0
                })
                .collect();
            let ys: Vec<f64> = pieces.iter().map(|l| l.points[0].1).collect();
            assert!(
                ys.iter().all(|y| (y - ys[0]).abs() < 0.01),
                "{name} {column:?}: {ys:?}"
            );
            let across = usize::from(!pieces.is_empty());
            assert_eq!(across, want, "{name} {column:?}");
            if want == 0 {
                continue;
            }
            let (c, radii) = &found[0];
            let xs = pieces.iter().flat_map(|l| l.points.iter().map(|p| p.0));
            let (lo, hi) = xs.fold((f64::MAX, f64::MIN), |m, x| (m.0.min(x), m.1.max(x)));
            let (a, b) = ((lo, ys[0]), (hi, ys[0]));
            assert!(
                (a.1 - c.1).abs() < 0.6 && (b.1 - c.1).abs() < 0.6,
                "{a:?} {b:?} {c:?}"
            );
            assert!(
                ((b.0 - a.0).abs() - 2.0 * radii[0]).abs() < 1.0,
                "{a:?} {b:?}"
            );
            let text = caption(&texts(&font, &s));
            assert!(text.contains(says), "{name} {column:?}: {text}");
        }
    }
}

/// The ring key in one column (review: "ring labels cover a third of disc (a)"): the labels'
/// glyph boxes (measured with DejaVu Sans; the labels have no white box under them since the
/// fifth review), their areas summed, cover at most a sixth of the keyed disk's area (π r², r
/// the horizon's fitted radius; 31 % with "overhead" and 10.5-unit labels), and each lies
/// inside its disk.
#[test]
fn the_key_covers_little_of_its_disk_in_one_column() {
    let font = Font::dejavu();
    for (name, _, _, _) in HEMISPHERES {
        let s = svg(name, Column::Single, false);
        let (found, _) = disks(&s);
        let boxes: Vec<[f64; 4]> = texts(&font, &s)
            .into_iter()
            .filter(|t| ["10°", "20°", "30°", "60°", "90°"].contains(&t.content.as_str()))
            .map(|t| {
                let b = t.bbox;
                [b[0], b[1], b[2] - b[0], b[3] - b[1]]
            })
            .collect();
        assert_eq!(boxes.len(), 5, "{name}: {boxes:?}");
        // The keyed disk: the one whose centre lies nearest the boxes' mean.
        let mean = (
            boxes.iter().map(|b| b[0] + b[2] / 2.0).sum::<f64>() / 5.0,
            boxes.iter().map(|b| b[1] + b[3] / 2.0).sum::<f64>() / 5.0,
        );
        let (c, radii) = found
            .iter()
            .min_by(|a, b| {
                let d = |p: &(f64, f64)| (p.0 - mean.0).hypot(p.1 - mean.1);
                d(&a.0).total_cmp(&d(&b.0))
            })
            .unwrap();
        let r = radii[0];
        let covered: f64 = boxes.iter().map(|b| b[2] * b[3]).sum();
        let share = covered / (std::f64::consts::PI * r * r);
        assert!(
            share <= 1.0 / 6.0,
            "{name}: the key covers {share:.3} of its disk"
        );
        for b in &boxes {
            for (x, y) in [(b[0], b[1]), (b[0] + b[2], b[1] + b[3])] {
                assert!(
                    (x - c.0).hypot(y - c.1) <= r,
                    "{name}: {b:?} outside the disk"
                );
            }
        }
    }
}

/// lloyd2006-fig7 in one column puts the bar of (a)–(d) over (e)'s (review: "colour-bar
/// order"): the name of S̄'s bar stands above the ratio's, both right of (e)'s disk.
#[test]
fn fig7_one_column_bars_follow_the_panels() {
    let font = Font::dejavu();
    let all = texts(&font, &svg("lloyd2006-fig7", Column::Single, false));
    let y = |start: &str| {
        all.iter()
            .find(|t| t.content.starts_with(start))
            .unwrap_or_else(|| panic!("no {start}"))
            .y
    };
    assert!(
        y("(a)–(d) S") < y("(e) (b) ÷ (c) (log"),
        "{} {}",
        y("(a)–(d) S"),
        y("(e) (b) ÷ (c) (log")
    );
}

/// The captions say what the rings are (review: fig7's "no longer says the rings are
/// elevations") and which rule martin-tan-fig6's (a) shows (review: "does not say which rule
/// it shows"; Martin & Tan's Fig. 6 plots the 80 % rule, its §6.2); (a)'s title says it in
/// every form, the bare one included.
#[test]
fn captions_say_rings_are_elevations_and_which_rule() {
    let font = Font::dejavu();
    for (name, column, says) in [
        // lloyd2006-fig7's key disk, titled "key: elevation", writes each ring's elevation
        // (`fig7_names_e_and_the_projection_and_keys_the_rings_apart_from_the_data`); its
        // caption has no room for them since it defines (a)'s contours, where n′ should revert
        // (the eighth review) and the panels (c)–(e) (the ninth). One column: (a) writes each
        // ring's elevation on it; the caption keeps four lines.
        (
            "martin-tan-fig6",
            Column::Double,
            "(a) The paper's 80 % rule",
        ),
        ("martin-tan-fig6", Column::Single, "(a) the 80 % rule"),
        (
            "martin-tan-fig6",
            Column::Double,
            "rings: elevation 10°, 20°, 30°, 60°",
        ),
        (
            "martin-tan-fig6",
            Column::Single,
            "rings: elevation 10°, 20°, 30°, 60°",
        ),
    ] {
        let text = caption(&texts(&font, &svg(name, column, false)));
        assert!(text.contains(says), "{name} {column:?}: {text}");
    }
    for (column, bare) in [
        (Column::Double, false),
        (Column::Single, false),
        (Column::Double, true),
    ] {
        let all = texts(&font, &svg("martin-tan-fig6", column, bare));
        assert!(
            all.iter().any(|t| t.content.starts_with("(a) 80 % rule")),
            "{column:?} bare {bare}"
        );
    }
}

/// Whether two boxes [x0, y0, x1, y1] overlap.
fn overlap(a: &[f64; 4], b: &[f64; 4]) -> bool {
    a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]
}

/// zhang-fig3 in one column gives each block a scale (review: "one 40 tick per row, too few to
/// read a scale"; the sixth review, R6-zhang-fig3-3: ±30 on all nine rows read as one column
/// of numbers): each block's middle row has the heights 40 and −40 written left of its first
/// panel, 40 above −40; no two of these labels, nor a label and a row's turned angle (90°,
/// 60°, 30°), overlap (their boxes measured in DejaVu Sans); and the angle is γ, in the
/// heading and the caption, its values the rows' (review: Zhang's θ clashed with the other
/// figures' half field of view θ).
#[test]
fn zhang_one_column_rows_have_two_ticks_each() {
    let font = Font::dejavu();
    let s = svg("zhang-fig3", Column::Single, false);
    let all = texts(&font, &s);
    let ticks: Vec<&Text> = all
        .iter()
        .filter(|t| !t.rotated && (t.content == "40" || t.content == "−40"))
        .collect();
    let up = ticks.iter().filter(|t| t.content == "40").count();
    let down = ticks.iter().filter(|t| t.content == "−40").count();
    assert_eq!(
        (up, down),
        (3, 3),
        "{:?}",
        ticks.iter().map(|t| &t.content).collect::<Vec<_>>()
    );
    let mut by_height: Vec<&&Text> = ticks.iter().collect();
    by_height.sort_by(|a, b| a.y.total_cmp(&b.y));
    for pair in by_height.chunks(2) {
        assert_eq!(
            (pair[0].content.as_str(), pair[1].content.as_str()),
            ("40", "−40")
        );
    }
    let angles: Vec<&Text> = all
        .iter()
        .filter(|t| t.rotated && t.content.ends_with('°'))
        .collect();
    assert_eq!(angles.len(), 9);
    for (i, a) in ticks.iter().enumerate() {
        for b in &ticks[i + 1..] {
            assert!(!overlap(&a.bbox, &b.bbox), "{a:?} {b:?}");
        }
        for g in &angles {
            assert!(!overlap(&a.bbox, &g.bbox), "{a:?} {g:?}");
        }
    }
    assert!(all.iter().any(|t| t.content == "γ"));
    assert!(!all.iter().any(|t| t.content == "θ"));
    // The caption names the angle, the rows give its values (the caption's list gave its room
    // to m written out: the eleventh review, R11-zhang-fig3-1).
    let text = caption(&all);
    assert!(text.contains("light at γ from the view"), "{text}");
    let mut values: Vec<&str> = angles.iter().map(|t| t.content.as_str()).collect();
    values.sort_unstable();
    values.dedup();
    assert_eq!(values, ["30°", "60°", "90°"]);
}
