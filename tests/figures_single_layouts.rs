//! The one-column layouts (issue 35 item 4) of the figures with heat maps: lloyd2006-fig7,
//! martin-tan-fig6 and zhang-fig3, and lloyd2005-fig7's line chart, read back from the SVGs
//! that `--column single` writes (300 units wide, printed 240 pt): where their panels go, and
//! that a hemisphere's colour bar is as tall as its disk in both layouts (it spanned the whole
//! panel, taller than the disk, figure review of martin-tan-fig6).
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::render_svg;
use shadow_aliasing::plot::{Column, Options};

fn svg(name: &str, column: Column) -> String {
    render_svg(
        name,
        &Options {
            column,
            ..Options::default()
        },
    )
}

/// The number in the attribute `name` of `tag`.
fn attr(tag: &str, name: &str) -> f64 {
    let key = format!(" {name}=\"");
    let at = tag
        .find(&key)
        .unwrap_or_else(|| panic!("no {name} in {tag}"))
        + key.len();
    tag[at..at + tag[at..].find('"').unwrap()]
        .trim_end_matches("pt")
        .parse()
        .unwrap()
}

/// The view box's width.
fn width(svg: &str) -> f64 {
    let head = &svg[..svg.find('>').unwrap()];
    let at = head.find("viewBox=\"").unwrap() + "viewBox=\"".len();
    head[at..at + head[at..].find('"').unwrap()]
        .split_whitespace()
        .nth(2)
        .unwrap()
        .parse()
        .unwrap()
}

/// The (x, y) of the first `<text>` whose content starts with `label`.
fn text_at(svg: &str, label: &str) -> (f64, f64) {
    let mut rest = svg;
    while let Some(i) = rest.find("<text ") {
        let tag_end = i + rest[i..].find('>').unwrap();
        if rest[tag_end + 1..].starts_with(label) {
            let tag = &rest[i..tag_end];
            return (attr(tag, "x"), attr(tag, "y"));
        }
        rest = &rest[tag_end..];
    }
    panic!("no text {label:?}")
}

/// The embedded rasters: (x, y, width, height) of each `<image>`.
fn images(svg: &str) -> Vec<(f64, f64, f64, f64)> {
    svg.match_indices("<image ")
        .map(|(i, _)| {
            let tag = &svg[i..i + svg[i..].find('>').unwrap()];
            (
                attr(tag, "x"),
                attr(tag, "y"),
                attr(tag, "width"),
                attr(tag, "height"),
            )
        })
        .collect()
}

/// zhang-fig3 in one column: the three blocks (a), (b), (c) stacked, their titles centred on
/// one vertical and each at least 90 units under the one before (three rows of panels about
/// 23 units tall, their gaps and the block's title, within
/// the 525-unit page of tests/figures_g_single_height.rs); in
/// two columns they stand in one row, each at least 150 units right of the one before.
#[test]
fn zhang_fig3_stacks_its_blocks_in_one_column() {
    let s = svg("zhang-fig3", Column::Single);
    assert_eq!(width(&s), 300.0);
    let t: Vec<(f64, f64)> = ["(a)", "(b)", "(c)"]
        .iter()
        .map(|l| text_at(&s, l))
        .collect();
    for w in t.windows(2) {
        assert!((w[0].0 - w[1].0).abs() <= 1.0, "{t:?}");
        assert!(w[1].1 - w[0].1 >= 90.0, "{t:?}");
    }
    let d = svg("zhang-fig3", Column::Double);
    let t: Vec<(f64, f64)> = ["(a)", "(b)", "(c)"]
        .iter()
        .map(|l| text_at(&d, l))
        .collect();
    for w in t.windows(2) {
        assert!((w[0].1 - w[1].1).abs() <= 1.0, "{t:?}");
        assert!(w[1].0 - w[0].0 >= 150.0, "{t:?}");
    }
}

/// lloyd2006-fig7 in one column: two hemispheres a row, (a) beside (b), (c) beside (d) under
/// them, and (e) under (c).
#[test]
fn lloyd2006_fig7_has_two_hemispheres_a_row_in_one_column() {
    let s = svg("lloyd2006-fig7", Column::Single);
    assert_eq!(width(&s), 300.0);
    let [a, b, c, d, e] = ["(a)", "(b)", "(c)", "(d)", "(e)"].map(|l| text_at(&s, l));
    assert!(
        (a.1 - b.1).abs() <= 1.0 && b.0 - a.0 >= 120.0,
        "{a:?} {b:?}"
    );
    assert!(
        (c.1 - d.1).abs() <= 1.0 && d.0 - c.0 >= 120.0,
        "{c:?} {d:?}"
    );
    assert!(
        (a.0 - c.0).abs() <= 1.0 && c.1 - a.1 >= 120.0,
        "{a:?} {c:?}"
    );
    assert!(e.1 - c.1 >= 120.0, "{c:?} {e:?}");
}

/// martin-tan-fig6 in one column: the profile (b) under the hemisphere (a), its title below
/// the bottom of (a)'s disk (the one square raster) and of (a)'s "viewer's right" under it.
/// (The fifth review gave (b) the larger share of the height, so (b)'s title no longer lies a
/// fixed 150 units under (a)'s; the disk's own extent is what (b) must clear.)
#[test]
fn martin_tan_fig6_has_its_profile_under_the_hemisphere_in_one_column() {
    let s = svg("martin-tan-fig6", Column::Single);
    assert_eq!(width(&s), 300.0);
    let (a, b) = (text_at(&s, "(a)"), text_at(&s, "(b)"));
    let disks: Vec<_> = images(&s)
        .into_iter()
        .filter(|i| (i.2 - i.3).abs() <= 2.0)
        .collect();
    assert_eq!(disks.len(), 1, "{disks:?}");
    let disk = disks[0];
    assert!(a.1 < disk.1, "(a)'s title {a:?}, the disk {disk:?}");
    let right = text_at(&s, "viewer");
    assert!(right.1 > disk.1 + disk.3 - 10.0, "{right:?} {disk:?}");
    assert!(
        b.1 > right.1 && b.1 > disk.1 + disk.3,
        "{a:?} {b:?} {right:?} {disk:?}"
    );
}

/// A hemisphere's colour bar is about the size of its disk, in both layouts (it spanned the
/// whole panel, taller than the disk, figure review of martin-tan-fig6): of the embedded rasters,
/// the disks are square and the bars narrow. An upright bar starts within 2 units of the top of
/// the disk nearest it and is 75 % to 100 % of its height (its chart keeps room at each end for
/// the end labels); a bar lying across (martin-tan-fig6 in two columns, under its disk;
/// lloyd2006-fig7 in one column, in the sixth cell) is 85 % to 150 % of a disk's diameter long.
#[test]
fn hemisphere_colour_bars_are_as_tall_as_their_disks() {
    for name in ["martin-tan-fig6", "lloyd2006-fig7"] {
        for column in [Column::Double, Column::Single] {
            let s = svg(name, column);
            let all = images(&s);
            let disks: Vec<_> = all.iter().filter(|i| (i.2 - i.3).abs() <= 2.0).collect();
            let upright: Vec<_> = all.iter().filter(|i| i.3 > 3.0 * i.2).collect();
            let across: Vec<_> = all.iter().filter(|i| i.2 > 3.0 * i.3).collect();
            assert!(
                !disks.is_empty() && upright.len() + across.len() >= 1,
                "{name} {column:?}: {all:?}"
            );
            for bar in &upright {
                // The disk whose top is nearest the bar's.
                let disk = disks
                    .iter()
                    .min_by(|p, q| (p.1 - bar.1).abs().total_cmp(&(q.1 - bar.1).abs()))
                    .unwrap();
                assert!(
                    (bar.1 - disk.1).abs() <= 2.0,
                    "{name} {column:?}: bar {bar:?}, disk {disk:?}"
                );
                let ratio = bar.3 / disk.3;
                assert!(
                    (0.75..=1.0).contains(&ratio),
                    "{name} {column:?}: bar {bar:?}, disk {disk:?}"
                );
            }
            for bar in &across {
                let ratio = bar.2 / disks[0].2;
                assert!(
                    (0.85..=1.5).contains(&ratio),
                    "{name} {column:?}: bar {bar:?}, disk {:?}",
                    disks[0]
                );
            }
        }
    }
}

/// lloyd2005-fig7 in one column stacks its two panels, (a) ξ = 0 over (b) |ξ| = 1, each tall
/// enough for its labels within the 525-unit page (tests/figures_g_single_height.rs): (b)'s
/// title lies at least 200 units below (a)'s.
#[test]
fn lloyd2005_fig7_keeps_its_height_in_one_column() {
    let s = svg("lloyd2005-fig7", Column::Single);
    assert_eq!(width(&s), 300.0);
    let (_, a) = text_at(&s, "(a) ξ = 0");
    let (_, b) = text_at(&s, "(b) |ξ| = 1");
    assert!(b - a >= 200.0, "(a) at {a}, (b) at {b}");
}
