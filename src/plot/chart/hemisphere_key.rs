//! The key of a hemisphere panel, written inside its disk: each elevation ring's angle on the
//! ring and "overhead" at the centre, so that a figure without its caption still says what the
//! rings and the centre are.

use super::super::Fail;
use super::heat::hemisphere_xy;
use super::FONT;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The size of the key's text (plotters' size; 10.5 units in the SVG, the least any figure sets).
pub(crate) const KEY_TEXT: u32 = 13;

/// The key's labels: the text, the light direction where it is centred (elevation, and the
/// angle around the disk's centre, degrees anticlockwise from the in-front side), so that
/// neighbouring labels stand apart on a disk of 40 units' radius: 10°, 20° and 30° fan out on
/// the viewer's right, 60° on top of its ring, "overhead" at the centre.
pub(crate) const KEY: [(&str, f64, f64); 5] = [
    ("10°", 10.0, -120.0),
    ("20°", 20.0, -60.0),
    ("30°", 30.0, -30.0),
    ("60°", 60.0, 90.0),
    ("overhead", 90.0, 0.0),
];

/// Writes [`KEY`] into a hemisphere panel whose disk point `(x, y)` (radius 1) lies at
/// `to_px((x, y))` of `area`: each label on a light box that interrupts its ring, as a contour
/// label does.
pub(crate) fn draw_ring_key<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    to_px: impl Fn((f64, f64)) -> (i32, i32),
) -> Result<(), Fail> {
    let style = TextStyle::from((FONT, KEY_TEXT).into_font());
    for (text, elevation, around) in KEY {
        // hemisphere_xy draws azimuth az at angle az − π around the centre (anticlockwise
        // from +x, in front; the viewer's right, az = π/2, at −y).
        let azimuth = std::f64::consts::PI + around.to_radians();
        let (x, y) = to_px(hemisphere_xy(elevation.to_radians(), azimuth));
        let (w, h) = area.estimate_text_size(text, &style)?;
        let (hw, hh) = (w as i32 / 2 + 1, h as i32 / 2);
        area.draw(&Rectangle::new(
            [(x - hw, y - hh), (x + hw, y + hh)],
            RGBAColor(255, 255, 255, 0.8).filled(),
        ))?;
        area.draw(&Text::new(
            text,
            (x, y),
            style.pos(Pos::new(HPos::Center, VPos::Center)),
        ))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::super::heat::{draw_hemisphere_keyed, PolarGrid};
    use super::super::read_svg::{attr, draw_svg, texts};
    use super::super::{Axis, ColourScale};
    use super::*;
    use std::f64::consts::{FRAC_PI_2, TAU};

    /// A keyed panel names its rings and its centre (review X5: only the captions did, so a
    /// bare figure lost them), read back from its SVG on a disk of one column's size: each of
    /// "10°", "20°", "30°", "60°" stands on its ring, at (90° − el)/90 of the horizon's radius
    /// from the centre (the azimuthal equidistant projection, by hand), "overhead" at the
    /// centre; no two labels' boxes (their widths as measured, 11 units tall) overlap; an
    /// unkeyed panel writes none of them.
    #[test]
    fn the_key_names_each_ring_on_it_and_the_centre() {
        let grid = PolarGrid {
            elev_edges: vec![0.0, FRAC_PI_2],
            az_edges: vec![0.0, TAU],
            values: vec![Some(1.0)],
        };
        let scale = ColourScale::smooth(Axis::linear("v", 0.0, 2.0));
        for key in [true, false] {
            let mut rows = (0, 0);
            let mut widths = Vec::new();
            let svg = draw_svg((144, 125), |area| {
                rows = draw_hemisphere_keyed(area, "t", &grid, &scale, key).unwrap();
                let style = TextStyle::from((FONT, KEY_TEXT).into_font());
                for (t, _, _) in KEY {
                    widths.push(f64::from(area.estimate_text_size(t, &style).unwrap().0));
                }
            });
            let all = texts(&svg);
            let found: Vec<(f64, f64, f64)> = KEY
                .iter()
                .zip(&widths)
                .filter_map(|((t, _, _), w)| {
                    let line = all.iter().find(|x| x.1 == *t)?.0;
                    Some((attr(line, "x")?, attr(line, "y")?, *w))
                })
                .collect();
            if !key {
                assert!(found.is_empty(), "{found:?}");
                continue;
            }
            assert_eq!(found.len(), KEY.len(), "{svg}");
            // The disk: its top and bottom rows, its centre half-way, as wide as high.
            let (top, bottom) = (f64::from(rows.0), f64::from(rows.1));
            let radius = (bottom - top) / 2.0;
            assert!(radius > 30.0 && radius < 50.0, "{radius}");
            let centre_y = (top + bottom) / 2.0;
            let centre_x = found[4].0;
            for ((_, el, _), &(x, y, _)) in KEY.iter().zip(&found) {
                let r = (x - centre_x).hypot(y - centre_y);
                let want = radius * (90.0 - el) / 90.0;
                assert!(
                    (r - want).abs() < 1.5,
                    "{el}°: {r} from the centre, want {want}"
                );
            }
            for (i, a) in found.iter().enumerate() {
                for b in &found[i + 1..] {
                    let apart_x = (a.0 - b.0).abs() >= (a.2 + b.2) / 2.0;
                    let apart_y = (a.1 - b.1).abs() >= 11.0;
                    assert!(apart_x || apart_y, "{a:?} and {b:?} overlap");
                }
            }
        }
    }
}
