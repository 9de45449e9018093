//! Heat maps as one bitmap: their cells are filled polygons, rasterised together (with 4 × 4
//! supersampling for smooth slanted borders) into one image that is drawn in one piece, so that
//! the SVG embeds one PNG `<image>` instead of thousands of shapes whose anti-aliased edges
//! leave hairline seams between neighbouring cells.

use super::super::canvas::downsample;
use super::super::Fail;
use plotters::coord::Shift;
use plotters::prelude::*;

/// Supersampling of the raster in each direction.
const RASTER_SCALE: u32 = 4;

/// Fills `cells` (polygons in `area`'s pixels, fractional, each with its colour) into one bitmap over their
/// bounding box on a white background, and draws it into `area`. Pixels of the bounding box
/// that no cell covers are white, so the area below must be white there too (heat maps are
/// drawn on a white page without a grid mesh).
pub(crate) fn draw_cells<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    cells: &[(Vec<(f64, f64)>, RGBColor)],
) -> Result<(), Fail> {
    let (aw, ah) = area.dim_in_pixel();
    let pts = || cells.iter().flat_map(|(p, _)| p.iter().copied());
    let (Some(x0), Some(y0), Some(x1), Some(y1)) = (
        pts().map(|p| p.0.floor() as i32).min(),
        pts().map(|p| p.1.floor() as i32).min(),
        pts().map(|p| p.0.ceil() as i32).max(),
        pts().map(|p| p.1.ceil() as i32).max(),
    ) else {
        return Ok(());
    };
    let (x0, y0) = (x0.max(0), y0.max(0));
    let (x1, y1) = (x1.min(aw as i32), y1.min(ah as i32));
    if x1 <= x0 || y1 <= y0 {
        return Ok(());
    }
    let (w, h) = ((x1 - x0) as u32, (y1 - y0) as u32);
    let s = RASTER_SCALE;
    let mut big = vec![255u8; (w * s) as usize * (h * s) as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut big, (w * s, h * s)).into_drawing_area();
        let f = f64::from(s);
        for (poly, colour) in cells {
            let moved: Vec<(i32, i32)> = poly
                .iter()
                .map(|&(x, y)| {
                    (
                        ((x - f64::from(x0)) * f).round() as i32,
                        ((y - f64::from(y0)) * f).round() as i32,
                    )
                })
                .collect();
            root.draw(&Polygon::new(moved, colour.filled()))?;
        }
        root.present()?;
    }
    let small = downsample(&big, w, h, s);
    let image = BitMapElement::with_owned_buffer((x0, y0), (w, h), small)
        .ok_or_else(|| Fail::Draw("heat-map raster of the wrong size".into()))?;
    area.draw(&image)?;
    Ok(())
}
