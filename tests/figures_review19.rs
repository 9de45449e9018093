//! The figures after the eighteenth and nineteenth figure reviews, read back from the SVGs of
//! every figure in every form:
//! - R19-X-1 (R19-lloyd2005-fig8-1, R19-zhang-fig3-1): a tick label hanging under its tick
//!   ended at it ("2048" under the texture's end, "100" under the far plane), so it stood over
//!   the tick before; every tick label under a tick is centred on it.
//! - R19-lloyd2005-fig8-2: in one column the white box of the "N" tag, in a column of the
//!   texture narrower than the box, covered the black outline between two parts.
//! - R18-lloyd2006-fig7-1: the bar of (a)–(d) named S̄ without its unit, which every other S̄
//!   axis gives.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::{all_svgs, attr, attr_str, forms, points, render_svg, texts, Font, Text};

/// The short vertical black lines of `svg` (tick marks, at most 8 units long): (x, top, bottom).
fn ticks(svg: &str) -> Vec<(f64, f64, f64)> {
    svg.lines()
        .filter(|l| l.starts_with("<polyline") && attr_str(l, "stroke") == Some("#000000"))
        .map(points)
        .filter_map(|p| match p[..] {
            [a, b] if (a.0 - b.0).abs() < 0.01 && (a.1 - b.1).abs() > 2.0 => {
                let (top, bottom) = (a.1.min(b.1), a.1.max(b.1));
                (bottom - top <= 8.0).then_some((a.0, top, bottom))
            }
            _ => None,
        })
        .collect()
}

/// Whether the text `t` hangs under one of the tick marks `marks`: anchored within a unit of
/// its x, its top from half a unit over the mark's lower end to 12 units under it.
fn under_a_tick(marks: &[(f64, f64, f64)], t: &Text) -> bool {
    marks
        .iter()
        .any(|m| (m.0 - t.x).abs() <= 1.0 && t.bbox[1] >= m.2 - 0.5 && t.bbox[1] - m.2 <= 12.0)
}

/// R19-X-1: no upright text hanging under a tick mark (its top within 12 units under the
/// mark's lower end) ends or starts at the tick's x: it is centred there. The old figures had
/// four such labels a form (lloyd2005-fig8's "2048", zhang-fig3's three "100"), which this test
/// finds (checked by anchoring them at their ends again).
#[test]
fn labels_under_ticks_are_centred_on_them() {
    let font = Font::dejavu();
    let mut bad = Vec::new();
    let mut centred = 0;
    for (name, layout, svg) in all_svgs() {
        let marks = ticks(svg);
        for t in texts(&font, svg).iter().filter(|t| !t.rotated) {
            if !under_a_tick(&marks, t) {
                continue;
            }
            match attr_str(&t.tag, "text-anchor") {
                Some("middle") => centred += 1,
                anchor => bad.push(format!(
                    "{name} ({layout}): {:?} anchored {anchor:?} at its tick x = {}",
                    t.content, t.x
                )),
            }
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
    // The reader finds the figures' tick labels (hundreds of them).
    assert!(centred > 300, "{centred} labels under ticks");
}

/// zhang-fig3's depth axis reads 0 and 100 under one panel of each block's last row (one
/// column: of the last block's), each centred on its tick and clear (2 units) of every other
/// text; in one column the last row's other two panels keep their ticks unnumbered (numbered,
/// "100" centred ran into the next panel's "0").
#[test]
fn zhang_depth_labels_stand_on_their_ticks_apart() {
    let font = Font::dejavu();
    for (form, opts) in forms() {
        let svg = render_svg("zhang-fig3", &opts);
        let all = texts(&font, &svg);
        let marks = ticks(&svg);
        // The texts written with a raised part (a bar's 10⁰ reads "100"), by their tags.
        let raised: Vec<&str> = svg
            .lines()
            .filter(|l| l.starts_with("<text") && l.contains("<tspan"))
            .map(|l| &l[..l.find('>').unwrap()])
            .collect();
        let depth: Vec<_> = all
            .iter()
            .filter(|t| !t.rotated && !raised.contains(&t.tag.as_str()))
            .filter(|t| ["0", "100"].contains(&t.content.as_str()))
            .filter(|t| under_a_tick(&marks, t))
            .collect();
        // A numbered panel under each block across two columns; under the last block only in
        // one column, whose blocks stand one over another.
        let blocks = if form == "single" { 1 } else { 3 };
        let hundreds = depth.iter().filter(|t| t.content == "100").count();
        assert_eq!(hundreds, blocks, "{form}: {hundreds} depth labels 100");
        assert_eq!(
            depth.len(),
            2 * blocks,
            "{form}: {} depth labels",
            depth.len()
        );
        for d in &depth {
            assert_eq!(attr_str(&d.tag, "text-anchor"), Some("middle"), "{form}");
            for o in all.iter().filter(|o| !std::ptr::eq(*o, *d)) {
                let apart = o.bbox[0] >= d.bbox[2] + 2.0
                    || d.bbox[0] >= o.bbox[2] + 2.0
                    || o.bbox[1] >= d.bbox[3] + 2.0
                    || d.bbox[1] >= o.bbox[3] + 2.0;
                assert!(
                    apart,
                    "{form}: {:?} at {:?} by {:?} at {:?}",
                    d.content, d.bbox, o.content, o.bbox
                );
            }
        }
    }
}

/// R19-lloyd2005-fig8-2: every tag's white box in the texture (c) (a white `<rect>` at 0.8
/// opacity, followed by its text) lies inside the outline of the part it names (the black
/// unfilled `<rect>` holding the text's anchor), a unit clear of each side, so that it covers
/// no part's outline, in every form. One column's "N" box ran 0.5 units over its part's side.
#[test]
fn fig8_tag_boxes_leave_the_parts_outlines_uncovered() {
    for (form, opts) in forms() {
        let svg = render_svg("lloyd2005-fig8", &opts);
        let lines: Vec<&str> = svg.lines().collect();
        let rect = |l: &str| -> Option<[f64; 4]> {
            let (x, y) = (attr(l, "x")?, attr(l, "y")?);
            Some([x, y, x + attr(l, "width")?, y + attr(l, "height")?])
        };
        let parts: Vec<[f64; 4]> = lines
            .iter()
            .filter(|l| {
                l.starts_with("<rect")
                    && l.contains("fill=\"none\"")
                    && attr_str(l, "stroke") == Some("#000000")
            })
            .filter_map(|l| rect(l))
            .collect();
        let mut boxes = 0;
        for w in lines.windows(2) {
            if !(w[0].starts_with("<rect")
                && w[0].contains("fill=\"#FFFFFF\"")
                && w[0].contains("opacity=\"0.8\"")
                && w[1].starts_with("<text"))
            {
                continue;
            }
            let b = rect(w[0]).unwrap();
            let at = (attr(w[1], "x").unwrap(), attr(w[1], "y").unwrap());
            let Some(part) = parts
                .iter()
                .filter(|p| p[0] <= at.0 && at.0 <= p[2] && p[1] <= at.1 && at.1 <= p[3])
                .min_by(|a, b| {
                    ((a[2] - a[0]) * (a[3] - a[1])).total_cmp(&((b[2] - b[0]) * (b[3] - b[1])))
                })
            else {
                continue;
            };
            boxes += 1;
            assert!(
                b[0] >= part[0] + 0.5
                    && b[1] >= part[1] + 0.5
                    && b[2] <= part[2] - 0.5
                    && b[3] <= part[3] - 0.5,
                "{form}: the box {b:?} of {} covers its part's outline {part:?}",
                w[1]
            );
        }
        // The tags written inside their parts (T1, T2, N, R1, R2 at least).
        assert!(boxes >= 5, "{form}: {boxes} tag boxes in parts");
    }
}

/// R18-lloyd2006-fig7-1: every form of lloyd2006-fig7 gives S̄'s unit in its drawing (the bare
/// form has no caption): the bar of (a)–(d) named "(a)–(d) S̄ (texels per image pixel)" across
/// two columns, and over one column's bar (named "(a)–(d) S̄ (log scale)" under it) the unit
/// "texels per image pixel".
#[test]
fn fig7_gives_the_storage_factors_unit_in_every_form() {
    let font = Font::dejavu();
    for (form, opts) in forms() {
        let svg = render_svg("lloyd2006-fig7", &opts);
        let all = texts(&font, &svg);
        let has = |s: &str| all.iter().any(|t| t.content == s);
        if form == "single" {
            assert!(has("texels per image pixel"), "{form}");
            assert!(has("(a)–(d) S (log scale)"), "{form}");
        } else {
            assert!(has("(a)–(d) S (texels per image pixel)"), "{form}");
        }
    }
}
