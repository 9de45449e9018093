//! Tests of the sixth figure review's findings on the storage-factor figures (issue 35,
//! R6-lloyd2006-fig5, -fig6, -fig10, -fig12, -fig13, -worst-case), each read from the rendered
//! SVG or the figure's computed data.

use super::forms_tests::svg_of;
use super::*;
use crate::plot::chart::read_svg::texts;

/// `c` as an SVG writes it.
fn hex(c: RGBColor) -> String {
    format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2)
}

/// The closed outlines stroked in `colour` (open markers: the first point repeated last) and
/// the polygons filled in it (filled markers) of `svg`.
fn open_and_filled(svg: &str, colour: RGBColor) -> (usize, usize) {
    let c = hex(colour);
    let mut open = 0;
    for l in svg.lines() {
        if l.contains("<polyline") && l.contains(&format!("stroke=\"{c}\"")) {
            let pts: Vec<&str> = l
                .split("points=\"")
                .nth(1)
                .and_then(|p| p.split('"').next())
                .unwrap_or("")
                .split_whitespace()
                .collect();
            if pts.len() >= 4 && pts.first() == pts.last() {
                open += 1;
            }
        }
    }
    let filled = svg.matches(&format!("<polygon fill=\"{c}\"")).count();
    (open, filled)
}

/// Fig 12 (R6-lloyd2006-fig12-1/-2): colour is the scheme, the light the line and the markers'
/// fill, in every form: ZP's colour draws both ZP overhead (solid, filled markers) and the
/// ZP = ZP+W behind curve (dashed, open markers), FP+ZP+W's colour both its overhead
/// (filled) and behind (open) markers; nothing is drawn in the neutral grey the behind curve
/// had. Counted in the SVG: both colours have open and filled markers.
#[test]
fn fig12_colour_is_the_scheme_fill_is_the_light() {
    for column in [Column::Double, Column::Single] {
        let svg = svg_of("lloyd2006-fig12", column, false);
        assert!(
            !svg.contains(&hex(SHARED)),
            "{column:?}: the neutral grey drawn"
        );
        for look in [Look::Zp, Look::FpZpW] {
            let (open, filled) = open_and_filled(&svg, look.colour());
            assert!(open >= 2, "{column:?} {look:?}: {open} open markers");
            assert!(filled >= 2, "{column:?} {look:?}: {filled} filled markers");
        }
    }
    // The chart data: every behind series dashed or open, every overhead one solid and filled.
    let fig = fig12().map_err(|e| e.named("lloyd2006-fig12")).unwrap();
    for chart in &fig.page.charts {
        for s in chart.series.iter().filter(|s| s.label.is_some()) {
            let l = s.label.as_deref().unwrap();
            if l.ends_with("behind") {
                assert!(
                    s.hollow && s.dash == super::super::chart::Dash::Dashed,
                    "{l}"
                );
            } else {
                assert!(
                    !s.hollow && s.dash == super::super::chart::Dash::Solid,
                    "{l}"
                );
            }
        }
    }
}

/// Fig 12 (b)'s note (R6-lloyd2006-fig12-3): off the curves and gridlines' crowd, in the empty
/// band between S̄ = 50 and the points below (by hand the highest of them, ZP at 23 maps,
/// 23 · 1000^{2/23} = 41.9) and right of and below FP+ZP+W's 13-map marker
/// (8(1000^{1/3} − 1) + 1 = 55.0), which beside the note read as its key symbol (the ninth review,
/// R9-lloyd2006-fig12-1): in the bare SVG the note's three lines lie between the y axis' texts
/// "50" and "40" and start right of "14", each value in its scheme's colour.
#[test]
fn fig12_note_in_the_empty_band() {
    let (fp, zp) = (
        8.0 * (1000f64.powf(0.25) - 1.0) + 1.0,
        17.0 * 1000f64.powf(2.0 / 17.0),
    );
    let svg = svg_of("lloyd2006-fig12", Column::Double, true);
    let t = texts(&svg);
    let find = |label: &str| {
        t.iter()
            .find(|x| x.1 == label)
            .unwrap_or_else(|| panic!("no {label:?}"))
    };
    let tick = |label: &str| {
        t.iter()
            .filter(|x| x.1 == label)
            .map(|x| x.2)
            .next()
            .unwrap()
    };
    let (fifty, forty) = (tick("50"), tick("40"));
    for (label, colour) in [
        (format!("FP+ZP+W {fp:.2}"), Look::FpZpW.colour()),
        (format!("ZP = ZP+W {zp:.2}"), Look::Zp.colour()),
    ] {
        let (tag, _, y) = find(&label);
        assert!(
            fifty < *y && *y < forty,
            "{label} at {y}, not between S̄ = 50 ({fifty}) and 40 ({forty})"
        );
        let x = |t: &str| crate::plot::chart::read_svg::attr(t, "x").unwrap();
        assert!(tag.contains("text-anchor=\"start\""), "{tag}");
        assert!(x(tag) > x(find("14").0), "{label} at {}", x(tag));
        let ink = super::super::chart::legible(colour);
        assert!(tag.contains(&hex(ink)), "{label}: {tag}");
    }
    let at = find("at 17 maps:").2;
    assert!(fifty < at && at < forty, "{at}");
}

/// Fig 13's caption (R6-lloyd2006-fig13-2): the telegraphic "Any θ: Eq 20 has none" written
/// out, read from the rendered SVG's caption lines (#323232).
#[test]
fn fig13_caption_says_why_theta_does_not_matter() {
    let svg = svg_of("lloyd2006-fig13", Column::Double, false);
    let caption: String = texts(&svg)
        .iter()
        .filter(|t| t.0.contains("#323232"))
        .map(|t| t.1.clone())
        .collect::<Vec<_>>()
        .join(" ")
        .replace('\u{a0}', " ");
    assert!(
        caption.contains("The boundary does not depend on θ: Eq 20 has no θ, and Eq 21"),
        "{caption}"
    );
    assert!(!caption.contains("Any θ"), "{caption}");
}
