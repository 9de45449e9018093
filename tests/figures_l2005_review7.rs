//! lloyd2005-fig8 after the sixth figure review's one-column and inset findings
//! (R6-lloyd2005-fig8-1, -2, -3, -4), read back from its SVGs in all three forms.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::{attr, attr_str, forms, render_svg, texts, Font, Text};

const TAGS: [&str; 7] = ["R1", "R2", "T1", "T2", "L1", "L2", "N"];

fn all_texts(svg: &str) -> Vec<Text> {
    texts(&Font::dejavu(), svg)
}

/// The `<rect>`s of `svg` with stroke `colour` and no fill: (x0, y0, x1, y1).
fn outlines(svg: &str, colour: &str) -> Vec<[f64; 4]> {
    svg.lines()
        .filter(|l| l.starts_with("<rect"))
        .filter(|l| attr_str(l, "stroke") == Some(colour) && attr_str(l, "fill") == Some("none"))
        .filter_map(|l| {
            let (x, y) = (attr(l, "x")?, attr(l, "y")?);
            Some([x, y, x + attr(l, "width")?, y + attr(l, "height")?])
        })
        .collect()
}

fn inside(b: &[f64; 4], r: &[f64; 4]) -> bool {
    b[0] >= r[0] && b[1] >= r[1] && b[2] <= r[2] && b[3] <= r[3]
}

/// R6-lloyd2005-fig8-4: one column set a nine-line paragraph ("R, L, T, N: right, left, top,
/// near face; …") beside (a), body text inside the figure. Now no black text says it; the
/// caption (#323232, at most five lines) names the faces and the parts' depths, and the
/// table's last header says what "error after" is (M_x/w, M_z/h).
#[test]
fn single_has_no_paragraph_the_caption_says_what_the_tags_are() {
    let svg = render_svg("lloyd2005-fig8", &forms()[2].1);
    let all = all_texts(&svg);
    let black: Vec<&str> = all
        .iter()
        .filter(|t| t.tag.contains("fill=\"#000000\""))
        .map(|t| t.content.as_str())
        .collect();
    assert!(
        black
            .iter()
            .all(|t| !t.contains("right, left") && !t.contains("R, L, T")),
        "{black:?}"
    );
    let caption: Vec<&str> = all
        .iter()
        .filter(|t| t.tag.contains("fill=\"#323232\""))
        .map(|t| t.content.as_str())
        .collect();
    assert!((1..=5).contains(&caption.len()), "{caption:?}");
    let text = caption.join(" ").replace('\u{a0}', " ");
    for want in [
        "R, L, T, N: right, left, top, near face",
        "parts 1, 2: z 1–3.16, 3.16–10",
    ] {
        assert!(text.contains(want), "no {want:?} in {text}");
    }
    let header: Vec<&str> = all
        .iter()
        .filter(|t| t.tag.contains("fill=\"#5A5A5A\""))
        .map(|t| t.content.as_str())
        .collect();
    assert!(header.contains(&"(Mx/w, Mz/h)"), "{header:?}");
}

/// (a)'s x tick labels: the numbers on the row just above the "light-view x" nearest to the
/// title "(a) from the light" and under it.
fn a_x_ticks(all: &[Text]) -> Vec<String> {
    let title = all
        .iter()
        .find(|t| t.content == "(a) from the light")
        .expect("(a)'s title");
    let name = all
        .iter()
        .filter(|t| t.content == "light-view x" && t.y > title.y)
        .min_by(|a, b| (a.x - title.x).abs().total_cmp(&(b.x - title.x).abs()))
        .expect("(a)'s x axis name");
    let mut ticks: Vec<&Text> = all
        .iter()
        .filter(|t| !t.rotated && t.content.replace('−', "-").parse::<f64>().is_ok())
        .filter(|t| t.y < name.y && t.y > name.y - 45.0 && (t.x - name.x).abs() < 80.0)
        .collect();
    ticks.sort_by(|a, b| a.x.total_cmp(&b.x));
    ticks.iter().map(|t| t.content.clone()).collect()
}

/// R6-lloyd2005-fig8-2: (a)'s x range was −10…10 in one column, −5…5 across two. Its x tick
/// labels are now the same in every form.
#[test]
fn a_has_one_x_range_in_every_form() {
    let ticks: Vec<(&str, Vec<String>)> = forms()
        .iter()
        .map(|(form, opts)| {
            (
                *form,
                a_x_ticks(&all_texts(&render_svg("lloyd2005-fig8", opts))),
            )
        })
        .collect();
    assert!(ticks[0].1.len() >= 3, "{ticks:?}");
    for (form, t) in &ticks[1..] {
        assert_eq!(t, &ticks[0].1, "{form} against double: {ticks:?}");
    }
}

/// R6-lloyd2005-fig8-3: one column's (c) set "L1" and "L2" across the line between their
/// rectangles. In every form no tag of (c) (a tag right of (c)'s title's left end) crosses a
/// rectangle's outline (black, unfilled): each stands inside its rectangle or outside the
/// texture, and one column's L1 and L2 stand left of the texture.
#[test]
fn texture_tags_cross_no_outline() {
    for (form, opts) in forms() {
        let svg = render_svg("lloyd2005-fig8", &opts);
        let all = all_texts(&svg);
        let rects = outlines(&svg, "#000000");
        let left = rects.iter().map(|r| r[0]).fold(f64::INFINITY, f64::min);
        let top = rects.iter().map(|r| r[1]).fold(f64::INFINITY, f64::min);
        let bottom = rects.iter().map(|r| r[3]).fold(f64::NEG_INFINITY, f64::max);
        assert!(rects.len() >= 7, "{form}: {rects:?}");
        let tags: Vec<&Text> = all
            .iter()
            .filter(|t| TAGS.contains(&t.content.as_str()))
            .filter(|t| t.y >= top - 8.0 && t.y <= bottom + 8.0 && t.bbox[2] > left - 40.0)
            .collect();
        assert_eq!(
            tags.len(),
            7,
            "{form}: {:?}",
            tags.iter().map(|t| &t.content).collect::<Vec<_>>()
        );
        for t in &tags {
            let b = t.bbox;
            for r in &rects {
                let crosses =
                    b[0] < r[2] && b[2] > r[0] && b[1] < r[3] && b[3] > r[1] && !inside(&b, r);
                assert!(!crosses, "{form}: {} {b:?} crosses {r:?}", t.content);
            }
        }
        if form == "single" {
            for name in ["L1", "L2"] {
                let t = tags.iter().find(|t| t.content == name).unwrap();
                assert!(
                    t.bbox[2] <= left,
                    "{form}: {name} {:?} not left of {left}",
                    t.bbox
                );
            }
        }
    }
}

/// R6-lloyd2005-fig8-1: L1, N and T1 are parts a few units across round (a)'s apex. In every
/// form an inset (a grey frame holding the enlargement "×k", k ≥ 3) shows the apex region
/// enlarged with T1 and N tagged inside it, and the frame is clear of (a)'s plot: it lies
/// wholly under (a)'s x axis name.
#[test]
fn apex_inset_holds_t1_and_n() {
    for (form, opts) in forms() {
        let svg = render_svg("lloyd2005-fig8", &opts);
        let all = all_texts(&svg);
        let zoom = all
            .iter()
            .find(|t| t.content.starts_with('×'))
            .unwrap_or_else(|| panic!("{form}: no inset"));
        let k: f64 = zoom.content.trim_start_matches('×').parse().unwrap();
        assert!(k >= 3.0, "{form}: {}", zoom.content);
        let frame = outlines(&svg, "#5A5A5A")
            .into_iter()
            .find(|r| inside(&zoom.bbox, r))
            .unwrap_or_else(|| panic!("{form}: no frame round {:?}", zoom.bbox));
        for name in ["T1", "N"] {
            assert!(
                all.iter()
                    .any(|t| t.content == name && inside(&t.bbox, &frame)),
                "{form}: no {name} in the inset {frame:?}"
            );
        }
        let title = all
            .iter()
            .find(|t| t.content == "(a) from the light")
            .unwrap();
        let name = all
            .iter()
            .filter(|t| t.content == "light-view x" && t.y > title.y)
            .min_by(|a, b| (a.x - title.x).abs().total_cmp(&(b.x - title.x).abs()))
            .unwrap();
        assert!(
            frame[1] >= name.bbox[3],
            "{form}: inset {frame:?} over (a)'s axis name {:?}",
            name.bbox
        );
    }
}
