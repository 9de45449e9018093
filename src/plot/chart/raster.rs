//! Heat maps as one bitmap: the field is sampled at every pixel of a raster of [`DENSITY`]
//! pixels per unit of the figure ([`SUB`] × [`SUB`] samples per pixel, averaged), so that cells
//! meet exactly (no seams: nothing is rasterised polygon by polygon). The raster is RGBA: where the field is not defined (outside a hemisphere's disk,
//! outside a clip region) it is transparent, so nothing bleeds past the border. It is handed to
//! the backend in one piece, so that the SVG embeds one PNG `<image>` instead of thousands of
//! shapes.
//!
//! The backends learn of the density through [`bitmap_density`]: while a raster is drawn it is
//! [`DENSITY`] and the bitmap is RGBA; the SVG writes the image at `1/DENSITY` units per pixel
//! ([`super::super::svg`]), the PNG canvas fits it to its own pixels over white
//! ([`fit_to_scale`]).

use super::super::Fail;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::cell::Cell;

/// Pixels of a heat-map raster per unit of the figure (an SVG unit; at least 4, issue 25).
pub(crate) const DENSITY: u32 = 4;

/// Samples per raster pixel in each direction. One, at the pixel's centre: at 4 pixels per unit
/// a border's steps are a quarter unit, under the outline every heat map draws over its border,
/// and a PNG (4 canvas pixels per unit at `--scale 1`, averaged 2 × 2) is anti-aliased anyway;
/// more samples would blend band edges into colours of their own and make the embedded PNGs
/// larger (zhang-fig3: 0.68 MB with 2 × 2 against 0.21 MB).
const SUB: u32 = 1;

thread_local! {
    static DRAWING: Cell<u32> = const { Cell::new(1) };
}

/// Pixels per unit of the bitmap now being handed to a backend: [`DENSITY`] while a heat map's
/// raster is drawn (its pixels then RGBA, four bytes each), 1 for any other bitmap (RGB).
pub(crate) fn bitmap_density() -> u32 {
    DRAWING.with(Cell::get)
}

/// A field rasterised over a box of whole units of a drawing area.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Raster {
    /// The box's top-left corner, in the area's units.
    pub origin: (i32, i32),
    /// Its size in pixels: [`DENSITY`] times its size in units.
    pub size: (u32, u32),
    /// Row-major RGBA pixels; alpha is the share of the pixel's samples where the field is
    /// defined (0 or 255 with one sample), the colour their average.
    pub rgba: Vec<u8>,
}

impl Raster {
    /// Samples `colour_at(x, y)` (the area's units, fractional; `None`: nothing there) over the
    /// box `[x0, x1] × [y0, y1]` of whole units.
    pub fn sample(
        (x0, y0, x1, y1): (i32, i32, i32, i32),
        colour_at: impl Fn(f64, f64) -> Option<RGBColor>,
    ) -> Self {
        let d = DENSITY;
        let (w, h) = ((x1 - x0).max(0) as u32 * d, (y1 - y0).max(0) as u32 * d);
        let mut rgba = vec![0u8; (w * h * 4) as usize];
        let step = 1.0 / f64::from(d * SUB);
        let n = f64::from(SUB * SUB);
        for py in 0..h {
            for px in 0..w {
                let (mut r, mut g, mut b, mut hits) = (0.0, 0.0, 0.0, 0.0);
                for sy in 0..SUB {
                    for sx in 0..SUB {
                        let x = f64::from(x0) + (f64::from(px * SUB + sx) + 0.5) * step;
                        let y = f64::from(y0) + (f64::from(py * SUB + sy) + 0.5) * step;
                        if let Some(c) = colour_at(x, y) {
                            r += f64::from(c.0);
                            g += f64::from(c.1);
                            b += f64::from(c.2);
                            hits += 1.0;
                        }
                    }
                }
                if hits > 0.0 {
                    let k = ((py * w + px) * 4) as usize;
                    rgba[k] = (r / hits).round() as u8;
                    rgba[k + 1] = (g / hits).round() as u8;
                    rgba[k + 2] = (b / hits).round() as u8;
                    rgba[k + 3] = (255.0 * hits / n).round() as u8;
                }
            }
        }
        Self {
            origin: (x0, y0),
            size: (w, h),
            rgba,
        }
    }

    /// The pixel at `(px, py)`, RGBA.
    #[cfg(test)]
    pub fn pixel(&self, px: u32, py: u32) -> [u8; 4] {
        let k = ((py * self.size.0 + px) * 4) as usize;
        [
            self.rgba[k],
            self.rgba[k + 1],
            self.rgba[k + 2],
            self.rgba[k + 3],
        ]
    }

    /// Draws the raster into `area` in one piece.
    pub fn draw<DB: DrawingBackend>(self, area: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        if self.size.0 == 0 || self.size.1 == 0 {
            return Ok(());
        }
        let image = BitMapElement::with_owned_buffer(self.origin, self.size, self.rgba)
            .ok_or_else(|| Fail::Draw("heat-map raster of the wrong size".into()))?;
        DRAWING.with(|c| c.set(DENSITY));
        let drawn = area.draw(&image);
        DRAWING.with(|c| c.set(1));
        drawn?;
        Ok(())
    }
}

/// A raster of `d` pixels per unit (`w × h` RGBA pixels) fitted to a bitmap of `s` pixels per
/// unit and laid over white (the page under every heat map): RGB, `(w s/d) × (h s/d)` pixels.
/// Each pixel takes the average of the raster's pixels it covers (or the one it lies in, where
/// the bitmap is the finer).
pub(crate) fn fit_to_scale(
    src: &[u8],
    (w, h): (u32, u32),
    d: u32,
    s: u32,
) -> (Vec<u8>, (u32, u32)) {
    let (tw, th) = (w * s / d.max(1), h * s / d.max(1));
    let mut out = vec![255u8; (tw * th * 3) as usize];
    // The raster's pixels under one bitmap pixel: a block of b × b, or one.
    let b = (d / s.max(1)).max(1);
    for ty in 0..th {
        for tx in 0..tw {
            let (sx, sy) = (tx * d / s, ty * d / s);
            let mut acc = [0.0f64; 3];
            let mut cover = 0.0;
            for y in sy..(sy + b).min(h) {
                for x in sx..(sx + b).min(w) {
                    let k = ((y * w + x) * 4) as usize;
                    let a = f64::from(src[k + 3]) / 255.0;
                    for c in 0..3 {
                        acc[c] += a * f64::from(src[k + c]) + (1.0 - a) * 255.0;
                    }
                    cover += 1.0;
                }
            }
            let k = ((ty * tw + tx) * 3) as usize;
            for c in 0..3 {
                out[k + c] = (acc[c] / cover).round() as u8;
            }
        }
    }
    (out, (tw, th))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A disk of radius 2 units about (2, 2) in a 4 × 4 box: [`DENSITY`] pixels per unit (at
    /// least 4, issue 25), opaque inside, zero alpha outside (nothing bleeds), partial on the
    /// border; and laid over white for a bitmap of 8 pixels per unit, the corner is white.
    #[test]
    fn rasters_are_dense_and_transparent_outside_the_field() {
        let red = RGBColor(200, 0, 0);
        let r = Raster::sample((0, 0, 4, 4), |x, y| {
            ((x - 2.0).powi(2) + (y - 2.0).powi(2) <= 4.0).then_some(red)
        });
        const { assert!(DENSITY >= 4) };
        assert_eq!(r.size, (4 * DENSITY, 4 * DENSITY));
        let c = 2 * DENSITY;
        assert_eq!(r.pixel(c, c), [200, 0, 0, 255]);
        assert_eq!(r.pixel(0, 0)[3], 0, "a corner outside the disk");
        // Along the diagonal, each pixel is opaque exactly when its sampled point, its centre,
        // lies in the disk (the circle crosses the diagonal at 2 + √2 = 3.414 units).
        for p in 0..4 * DENSITY {
            let centre = (f64::from(p) + 0.5) / f64::from(DENSITY);
            let inside = 2.0 * (centre - 2.0).powi(2) <= 4.0;
            assert_eq!(r.pixel(p, p)[3], if inside { 255 } else { 0 }, "pixel {p}");
        }
        let (rgb, (w, h)) = fit_to_scale(&r.rgba, r.size, DENSITY, 8);
        assert_eq!((w, h), (32, 32));
        assert_eq!(&rgb[..3], &[255, 255, 255]);
        let k = ((16 * 32 + 16) * 3) as usize;
        assert_eq!(&rgb[k..k + 3], &[200, 0, 0]);
        // Fitted to 2 pixels per unit: blocks of 2 × 2 averaged.
        let (_, size) = fit_to_scale(&r.rgba, r.size, DENSITY, 2);
        assert_eq!(size, (8, 8));
    }

    /// A rectangular grid's heat map (issue 25, G2: zhang-fig3 draws its panels so) is one
    /// dense RGBA image too, transparent outside its clip region: a 4 × 4 grid over [0, 2]² cut
    /// to y ≤ x, drawn on a chart into an SVG and decoded, has at least 4 pixels per unit,
    /// zero alpha above the diagonal and full alpha below it (more than a pixel away).
    #[test]
    fn grid_rasters_are_dense_and_clipped() {
        use super::super::read_svg::{draw_svg, embedded_images, Image};
        use super::super::{build_chart, draw_grid, Axis, ColourScale, Grid};
        let grid = Grid::sample_clipped(
            (0.0, 2.0, 4),
            (0.0, 2.0, 4),
            vec![(-1.0, 1.0, 0.0)],
            |x, y| Some(1.0 + x + y),
        );
        let scale = ColourScale::smooth(Axis::linear("v", 1.0, 5.0));
        let (x, y) = (Axis::linear("x", 0.0, 2.0), Axis::linear("y", 0.0, 2.0));
        let svg = draw_svg((300, 300), |area| {
            let mut chart = build_chart(area, "", &x, &y, false).unwrap();
            draw_grid(&mut chart, &grid, &scale).unwrap();
        });
        let images = embedded_images(&svg);
        assert_eq!(images.len(), 1);
        let Image {
            density,
            rgba: ref img,
            colour_type,
            ..
        } = images[0];
        assert!(density >= 4.0 - 1e-9, "{density}");
        assert_eq!(colour_type, 6);
        // The image spans the grid: its pixel (i, j) lies at data (2(i + ½)/w, 2(1 − (j + ½)/h)).
        let (w, h) = (f64::from(img.width()), f64::from(img.height()));
        let margin = 2.0 * 2.0 / w.min(h);
        let (mut above, mut below) = (0, 0);
        for (i, j, p) in img.enumerate_pixels() {
            let dx = 2.0 * (f64::from(i) + 0.5) / w;
            let dy = 2.0 * (1.0 - (f64::from(j) + 0.5) / h);
            if dy > dx + margin {
                assert_eq!(p[3], 0, "({dx}, {dy}) above the diagonal");
                above += 1;
            } else if dy < dx - margin {
                assert_eq!(p[3], 255, "({dx}, {dy}) below the diagonal");
                below += 1;
            }
        }
        assert!(above > 1000 && below > 1000, "{above} {below}");
    }
}
