//! lloyd2006-fig7 after the seventh figure review (R7-2006f7-1): (a)'s two contour line
//! styles, dotted and dashed, are keyed in the figure, read back from its SVGs in the two
//! forms that draw them (two columns and bare).
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::{attr_str, forms, points, render_svg, texts, Font, Text};

/// (a)'s disk lies left of this x (the first of three columns across 520 units).
const A_RIGHT: f64 = 173.0;

/// A polyline's length along its points.
fn length(p: &[(f64, f64)]) -> f64 {
    p.windows(2)
        .map(|w| (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1))
        .sum()
}

/// The 1.5-unit black lines of `svg` (the contours' dashes and the key's samples, since the
/// eleventh review on white lines: R11-lloyd2006-fig7-1).
fn dashes(svg: &str) -> Vec<Vec<(f64, f64)>> {
    svg.lines()
        .filter(|l| l.starts_with("<polyline"))
        .filter(|l| {
            attr_str(l, "stroke-width") == Some("1.5") && attr_str(l, "stroke") == Some("#000000")
        })
        .map(points)
        .collect()
}

/// The commonest whole length, in units, of the dashes among `ds` that `on` keeps: a dash
/// style's on-length (the dashes cut short at a line's end or at a break are fewer).
fn dash_length(ds: &[Vec<(f64, f64)>], on: impl Fn(&[(f64, f64)]) -> bool) -> Option<f64> {
    let mut counts: Vec<(i64, usize)> = Vec::new();
    for d in ds.iter().filter(|d| d.len() >= 2 && on(d)) {
        let l = length(d).round() as i64;
        match counts.iter_mut().find(|c| c.0 == l) {
            Some(c) => c.1 += 1,
            None => counts.push((l, 1)),
        }
    }
    counts
        .into_iter()
        .max_by_key(|c| (c.1, c.0))
        .map(|c| c.0 as f64)
}

fn centre(t: &Text) -> (f64, f64) {
    (0.5 * (t.bbox[0] + t.bbox[2]), 0.5 * (t.bbox[1] + t.bbox[3]))
}

/// (a)'s disk: its centre and radius, from its horizon (the largest ring, grey #808080 since
/// the eleventh review, left of [`A_RIGHT`] and in the first row, above y = 270).
fn a_disk(svg: &str) -> ((f64, f64), f64) {
    let horizon = svg
        .lines()
        .filter(|l| l.starts_with("<polyline") && attr_str(l, "stroke") == Some("#808080"))
        .map(points)
        .filter(|p| p.iter().all(|q| q.0 < A_RIGHT && q.1 < 270.0))
        .max_by(|a, b| span(a).total_cmp(&span(b)))
        .expect("(a)'s horizon");
    let (x0, x1) = extent(horizon.iter().map(|q| q.0));
    let (y0, y1) = extent(horizon.iter().map(|q| q.1));
    ((0.5 * (x0 + x1), 0.5 * (y0 + y1)), 0.5 * (x1 - x0))
}

fn extent(v: impl Iterator<Item = f64> + Clone) -> (f64, f64) {
    (
        v.clone().fold(f64::INFINITY, f64::min),
        v.fold(f64::NEG_INFINITY, f64::max),
    )
}

fn span(p: &[(f64, f64)]) -> f64 {
    let (x0, x1) = extent(p.iter().map(|q| q.0));
    x1 - x0
}

/// R7-2006f7-1: (a) drew dotted and dashed black lines over its field, each labelled only with
/// a number ("10⁶", "1.5×10⁶"); what they were was in neither the figure nor (bare) anywhere.
/// Now a key row stands for each: a level sample of black dashes (1.5 units) with the text
/// "(a) S̄ = <its level>" right of it, on its row, dashed as (a)'s contour at that level.
/// Which of (a)'s two dash styles is 10⁶ is read from the data's shape, not from the code:
/// with the light in the vertical plane through the view direction (the disk's horizontal
/// diameter) S̄ dips in a valley (8.66×10⁵ at 30° elevation) between (f/n)² = 10⁶ at the horizon
/// behind and in front (Lloyd 2006 Eq 20) and 8.65×10⁵ overhead, so the only contour along the
/// diameter's middle is the one at 10⁶ (the 1.5×10⁶ loops ring the bright arms off it): the
/// dashes crossing the band 6 units either side of the diameter, within 0.6 of the radius of
/// the centre, have its length; the other style is the commonest other length in (a).
#[test]
fn fig7_keys_both_contour_styles() {
    let font = Font::dejavu();
    for (form, opts) in forms().into_iter().take(2) {
        let svg = render_svg("lloyd2006-fig7", &opts);
        let all = texts(&font, &svg);
        let ds = dashes(&svg);
        let ((cx, cy), r) = a_disk(&svg);
        let (in_a, outside): (Vec<_>, Vec<_>) = ds
            .iter()
            .cloned()
            .partition(|d| d.iter().all(|q| q.0 < A_RIGHT));
        let valley = dash_length(&in_a, |d| {
            d.iter()
                .any(|q| (q.1 - cy).abs() <= 6.0 && (q.0 - cx).abs() <= 0.6 * r)
        })
        .unwrap_or_else(|| panic!("{form}: no contour along (a)'s diameter"));
        let other = dash_length(&in_a, |d| (length(d).round() - valley).abs() >= 1.0)
            .unwrap_or_else(|| panic!("{form}: one dash style in (a)"));
        assert!(
            (valley - other).abs() >= 3.0,
            "{form}: (a)'s two styles' dashes {valley} and {other} units"
        );
        // The labels as read: the superscript 6 joins the text ("106", "1.5×106").
        for (level, want) in [("106", valley), ("1.5×106", other)] {
            // Named by the key only, not on their lines (R12-, R13-lloyd2006-fig7-1).
            assert!(
                !all.iter().any(|t| t.content == level && t.x < A_RIGHT),
                "{form}: a contour label {level} in (a)"
            );
            let key = all
                .iter()
                .find(|t| t.content == format!("(a) S = {level}"))
                .unwrap_or_else(|| panic!("{form}: no key row \"(a) S̄ = {level}\""));
            let (_, ky) = centre(key);
            let sample: Vec<Vec<(f64, f64)>> = outside
                .iter()
                .filter(|d| {
                    d.iter()
                        .all(|q| (q.1 - ky).abs() <= 3.0 && q.0 < key.bbox[0])
                })
                .cloned()
                .collect();
            assert!(
                sample.len() >= 2,
                "{form}: {level}'s key has {} dashes left of its text",
                sample.len()
            );
            let key_len = dash_length(&sample, |_| true).unwrap();
            assert!(
                (key_len - want).abs() < 1.0,
                "{form}: {level}: key dashes {key_len} units, (a)'s {want}"
            );
        }
    }
}
