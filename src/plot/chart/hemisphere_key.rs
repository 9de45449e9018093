//! The rings of a hemisphere panel and their key, written inside its disk: each elevation
//! ring's angle on the ring and 90° at the centre (overhead), so that a figure without its
//! caption still says what the rings and the centre are.

use super::super::canvas::FineWidth;
use super::super::Fail;
use super::heat::hemisphere_xy;
use super::FONT;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters_backend::BackendColor;

/// The elevation rings of a hemisphere panel (degrees): the horizon, every 10° over the
/// horizon band, then 60°.
pub(crate) const RINGS: [f64; 5] = [0.0, 10.0, 20.0, 30.0, 60.0];

/// The one style of every ring and of the diameter: a line one unit wide, near black.
pub(crate) const RING_INK: (u8, u8, u8) = (30, 30, 30);

/// The style of a figure's rings and diameter: their colour and width (tenths of a unit).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct RingStyle {
    pub rgb: (u8, u8, u8),
    pub tenths: u32,
}

/// The rings' usual style: [`RING_INK`], one unit wide.
pub(crate) const RINGS_DARK: RingStyle = RingStyle {
    rgb: RING_INK,
    tenths: 10,
};

/// Thin grey rings, half a unit wide, for a figure that draws its own lines over a panel
/// (lloyd2006-fig7's contours: the eleventh review, R11-lloyd2006-fig7-1, found them hard to
/// tell from black rings of their weight). The grey, #808080 (relative luminance 0.216), stands
/// 3.1 : 1 against viridis' lightest yellow (#FDE725), 3.9 : 1 against its darkest purple
/// (#440154) and 3.9 : 1 against white, so that a ring shows at either end of a map (the first
/// figure review: rings vanished on the dark colours); on mid-tones, where any one grey must
/// fade, it keeps about 2 : 1 (lloyd2006-fig7's (a) green and (c) blue).
pub(crate) const RINGS_GREY: RingStyle = RingStyle {
    rgb: (128, 128, 128),
    tenths: 5,
};

/// Draws the rings of [`RINGS`], each once in one style (`style`: no light halo, which
/// printed as a second ring beside each ring), and where `diameter` the horizontal
/// diameter, the vertical plane through the view direction (light straight behind, overhead,
/// straight in front), in the same style; `abs` places a disk point (radius 1) in absolute
/// backend units, at sub-unit positions, so that the rings are round, not stepped. Each line
/// is interrupted where it would run through one of the boxes `gaps` (absolute backend units
/// [x min, y min, x max, y max]: the ring key's labels, [`key_boxes`]), as a contour label
/// interrupts its contour.
pub(crate) fn draw_rings<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    abs: &dyn Fn((f64, f64)) -> (f64, f64),
    diameter: bool,
    gaps: &[[f64; 4]],
    style: RingStyle,
) -> Result<(), Fail> {
    let stroke = |points: Vec<(f64, f64)>| {
        let inside = |p: &(f64, f64)| {
            gaps.iter()
                .any(|g| p.0 >= g[0] && p.0 <= g[2] && p.1 >= g[1] && p.1 <= g[3])
        };
        for run in points.split(inside).filter(|r| r.len() >= 2) {
            area.draw(&FineWidth {
                points: run.to_vec(),
                colour: BackendColor {
                    alpha: 1.0,
                    rgb: style.rgb,
                },
                width: style.tenths,
            })?;
        }
        Ok::<(), Fail>(())
    };
    for deg in RINGS {
        let el = deg.to_radians();
        stroke(
            (0..=360)
                .map(|k| abs(hemisphere_xy(el, f64::from(k).to_radians())))
                .collect(),
        )?;
    }
    if diameter {
        // In pieces of a fiftieth of the radius where a label may interrupt it.
        let n = if gaps.is_empty() { 1 } else { 100 };
        stroke(
            (0..=n)
                .map(|k| abs((2.0 * f64::from(k) / f64::from(n) - 1.0, 0.0)))
                .collect(),
        )?;
    }
    Ok(())
}

/// The size of the key's text (plotters' size; 10.5 units in the SVG, the least any figure sets).
pub(crate) const KEY_TEXT: u32 = 13;

/// The key's text in one column, where a disk is about 38 units across its radius (plotters'
/// size; 8.1 units, printed 6.5 pt): at [`KEY_TEXT`] the five labels' boxes covered a quarter
/// of the disk (the fourth figure review: "a third").
pub(crate) const KEY_TEXT_SINGLE: u32 = 10;

/// The key's labels: the text, the light direction where it is centred (elevation, and the
/// angle around the disk's centre, degrees anticlockwise from the in-front side), so that
/// neighbouring labels stand apart on a disk of 40 units' radius: 10°, 20° and 30° fan out on
/// the viewer's right, 60° on top of its ring, 90° (overhead) at the centre.
pub(crate) const KEY: [(&str, f64, f64); 5] = [
    ("10°", 10.0, -120.0),
    ("20°", 20.0, -60.0),
    ("30°", 30.0, -30.0),
    ("60°", 60.0, 90.0),
    ("90°", 90.0, 0.0),
];

/// The text style of the key's labels: smaller in one column.
fn key_style() -> TextStyle<'static> {
    let size = if super::column() == super::super::Column::Single {
        KEY_TEXT_SINGLE
    } else {
        KEY_TEXT
    };
    TextStyle::from((FONT, size).into_font())
}

/// A ring label: its text, its centre and its box (units of its area).
type KeyLabel = (&'static str, (i32, i32), [i32; 4]);

/// Each label of [`KEY`] in a hemisphere panel whose disk point `(x, y)` (radius 1) lies at
/// `to_px((x, y))` of `area`: its text, its centre and the box [x min, y min, x max, y max]
/// (units of `area`) its glyphs take and a unit round them, from 0.77 h above the centre to
/// 0.32 h below (the digits and ° have no descent, and the PNG sets the text up to 3 units
/// higher than the SVG: this covers them in both).
fn key_labels<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    to_px: impl Fn((f64, f64)) -> (i32, i32),
) -> Result<Vec<KeyLabel>, Fail> {
    let style = key_style();
    let mut out = Vec::new();
    for (text, elevation, around) in KEY {
        // hemisphere_xy draws azimuth az at angle az − π around the centre (anticlockwise
        // from +x, in front; the viewer's right, az = π/2, at −y).
        let azimuth = std::f64::consts::PI + around.to_radians();
        let (x, y) = to_px(hemisphere_xy(elevation.to_radians(), azimuth));
        let (w, h) = area.estimate_text_size(text, &style)?;
        let hw = (w as i32 + 1) / 2 + 1;
        let (up, down) = (
            (0.77 * h as f64).round() as i32,
            (0.32 * h as f64).round() as i32,
        );
        out.push((text, (x, y), [x - hw, y - up, x + hw, y + down]));
    }
    Ok(out)
}

/// The boxes of [`key_labels`] in absolute backend units, for [`draw_rings`]' `gaps`.
pub(crate) fn key_boxes<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    to_px: impl Fn((f64, f64)) -> (i32, i32),
) -> Result<Vec<[f64; 4]>, Fail> {
    let (bx, by) = area.get_base_pixel();
    Ok(key_labels(area, to_px)?
        .into_iter()
        .map(|(_, _, b)| [b[0] + bx, b[1] + by, b[2] + bx, b[3] + by].map(f64::from))
        .collect())
}

/// Writes [`KEY`] into a hemisphere panel whose disk point `(x, y)` (radius 1) lies at
/// `to_px((x, y))` of `area`: each label on its ring, which [`draw_rings`] interrupts there
/// (with the gaps of [`key_boxes`]), as a contour label does, and with no box under it, so
/// that the panel's colours show round and between its glyphs (the fifth figure review: the
/// labels' white boxes hid a noticeable share of (a)'s data in one column).
pub(crate) fn draw_ring_key<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    to_px: impl Fn((f64, f64)) -> (i32, i32),
) -> Result<(), Fail> {
    let style = key_style();
    for (text, at, _) in key_labels(area, to_px)? {
        area.draw(&Text::new(
            text,
            at,
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
                rows = draw_hemisphere_keyed(area, "t", &grid, &scale, key, true).unwrap();
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
