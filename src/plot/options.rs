//! How a figure is written for publication: without its title and caption (`bare`), at an
//! integer multiple of its pixel size (`scale`), with the PNG's physical size recorded (`dpi`,
//! as a PNG `pHYs` chunk; by default the size the SVG and the PDF give), and for a page's two
//! columns or one (`column`).

use super::PlotError;
use crate::error::fmt_num;
use std::str::FromStr;

/// The width a figure is laid out for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Column {
    /// Across a page's two columns: 520 units wide, one unit a point (7.22 inches).
    #[default]
    Double,
    /// One column of a two-column page: 300 units wide, printed 240 points (3.33 inches) wide,
    /// so that a unit is 0.8 points and the smallest text (a subscript, 7.55 units) prints at
    /// 6.04 points. The panels of a figure are stacked. Only the figures of
    /// [`super::SINGLE_COLUMN`] have this layout.
    Single,
}

impl Column {
    /// The page's width in units.
    #[must_use]
    pub fn width(self) -> u32 {
        match self {
            Column::Double => 520,
            Column::Single => 300,
        }
    }

    /// Points per unit when printed: the SVG's `width` and `height` over its view box, the PDF's
    /// page likewise.
    #[must_use]
    pub fn points_per_unit(self) -> f64 {
        match self {
            Column::Double => 1.0,
            Column::Single => 0.8,
        }
    }
}

impl FromStr for Column {
    type Err = PlotError;

    /// Parses `double` or `single` (case-insensitive).
    fn from_str(s: &str) -> Result<Self, PlotError> {
        match s.to_ascii_lowercase().as_str() {
            "double" => Ok(Column::Double),
            "single" => Ok(Column::Single),
            _ => Err(PlotError::InvalidOption(format!(
                "column {s:?} is neither double nor single: give double (a figure across both \
                 columns of a page, 7.22 in) or single (one column, 3.33 in)"
            ))),
        }
    }
}

/// Options of the written files; [`Options::default`] is what [`super::render`] uses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// No title and no caption in the figure (for a document that sets its own caption): the
    /// figure is laid out as the captioned one and cut to the plot area between its title and
    /// caption (the PNG's rows, the SVG's view box and so the PDF's page).
    pub bare: bool,
    /// The PNG's pixel size is `scale` × [`super::PNG_ZOOM`] times the figure's (lines and text
    /// scale with it); the SVG's `width` and `height` are `scale` times its view box. 1 to
    /// [`MAX_SCALE`].
    pub scale: u32,
    /// Pixels per inch recorded in the PNG (`pHYs`), so that the printed size is the pixel size
    /// divided by `dpi`. Finite, 1 to 10 000. `None` (the default) records the density that
    /// prints the PNG at the size of the SVG and the PDF at any `scale` ([`Options::dpi`]).
    pub dpi: Option<f64>,
    /// The width the figure is laid out for.
    pub column: Column,
}

/// The density [`Options::dpi`] records for a [`Column::Double`] figure: 72 ×
/// [`super::PNG_ZOOM`] = 432 pixels per inch. Such a figure's unit is a point (1/72 inch) in
/// the SVG (`width` and `height` in `pt`) and the PDF (its page), and its PNG has `PNG_ZOOM` ×
/// `scale` pixels per unit, so at this density all three have the same printed size: a
/// 520-unit figure is 7.22 inches wide (times `scale`). A [`Column::Single`] figure's unit is
/// 0.8 points, so its density is 432 / 0.8 = 540.
pub const DEFAULT_DPI: f64 = 72.0 * super::PNG_ZOOM as f64;

/// The largest [`Options::scale`].
pub const MAX_SCALE: u32 = 8;

impl Default for Options {
    fn default() -> Self {
        Self {
            bare: false,
            scale: 1,
            dpi: None,
            column: Column::Double,
        }
    }
}

impl Options {
    /// Checks the ranges.
    ///
    /// # Errors
    /// [`PlotError::InvalidOption`] naming the option and its accepted range.
    pub fn validate(&self) -> Result<(), PlotError> {
        scale(i64::from(self.scale))?;
        if let Some(dpi) = self.dpi {
            if !(dpi.is_finite() && (1.0..=10_000.0).contains(&dpi)) {
                return Err(PlotError::InvalidOption(format!(
                    "dpi {} is outside 1..=10000: give the pixels per inch of the printed \
                     figure, for instance 300",
                    fmt_num(dpi)
                )));
            }
        }
        Ok(())
    }

    /// The pixels per inch the PNG records: [`Options::dpi`] where given, else the density that
    /// prints it at the SVG's and the PDF's size ([`DEFAULT_DPI`] for a double-column figure,
    /// 540 for a single-column one).
    #[must_use]
    pub fn dpi(&self) -> f64 {
        self.dpi
            .unwrap_or(DEFAULT_DPI / self.column.points_per_unit())
    }

    /// Pixels per metre, as the `pHYs` chunk records them.
    pub(crate) fn pixels_per_metre(&self) -> u32 {
        (self.dpi() / 0.0254).round() as u32
    }
}

/// A scale given as any whole number (the command line reads negative ones too), as
/// [`Options::scale`].
///
/// # Errors
/// [`PlotError::InvalidOption`] naming `scale` and its range when `v` is outside 1 to
/// [`MAX_SCALE`].
pub fn scale(v: i64) -> Result<u32, PlotError> {
    u32::try_from(v)
        .ok()
        .filter(|s| (1..=MAX_SCALE).contains(s))
        .ok_or_else(|| {
            PlotError::InvalidOption(format!(
                "scale {v} is outside 1..={MAX_SCALE}: give a whole number from 1 to {MAX_SCALE}"
            ))
        })
}

/// CRC-32 (ISO-HDLC, as PNG uses) of `data`.
fn crc32(data: &[u8]) -> u32 {
    let mut c = 0xFFFF_FFFFu32;
    for &b in data {
        c ^= u32::from(b);
        for _ in 0..8 {
            c = if c & 1 != 0 {
                0xEDB8_8320 ^ (c >> 1)
            } else {
                c >> 1
            };
        }
    }
    !c
}

/// Inserts a `pHYs` chunk (`ppm` pixels per metre in both directions) right after the IHDR
/// chunk of an encoded PNG (the encoder writes none).
pub(crate) fn with_phys(png: &[u8], ppm: u32) -> Vec<u8> {
    // Signature (8) and IHDR (length 4, type 4, data 13, CRC 4).
    let at = 8 + 25;
    let mut chunk = Vec::with_capacity(21);
    chunk.extend_from_slice(&9u32.to_be_bytes());
    let mut body = b"pHYs".to_vec();
    body.extend_from_slice(&ppm.to_be_bytes());
    body.extend_from_slice(&ppm.to_be_bytes());
    body.push(1); // unit: metre
    chunk.extend_from_slice(&body);
    chunk.extend_from_slice(&crc32(&body).to_be_bytes());
    let mut out = Vec::with_capacity(png.len() + chunk.len());
    out.extend_from_slice(&png[..at]);
    out.extend_from_slice(&chunk);
    out.extend_from_slice(&png[at..]);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crc32_of_the_check_string() {
        // The standard check value of CRC-32/ISO-HDLC.
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
        // PNG's IEND chunk, whose CRC every PNG carries: AE 42 60 82.
        assert_eq!(crc32(b"IEND"), 0xAE42_6082);
    }

    #[test]
    fn three_hundred_dpi_is_11811_pixels_per_metre() {
        let o = Options {
            dpi: Some(300.0),
            ..Options::default()
        };
        assert_eq!(o.pixels_per_metre(), 11_811); // 300 / 0.0254 = 11 811.02
        assert!(o.validate().is_ok());
        for bad in [
            Options { scale: 0, ..o },
            Options { scale: 9, ..o },
            Options {
                dpi: Some(f64::NAN),
                ..o
            },
            Options {
                dpi: Some(0.5),
                ..o
            },
        ] {
            assert!(matches!(bad.validate(), Err(PlotError::InvalidOption(_))));
        }
    }

    /// The densities that print a PNG (6 pixels per unit) at the SVG's size: 432 per inch for
    /// a point a unit (6 × 72), 540 for 0.8 points a unit (6 / (0.8 / 72) = 540), both at least
    /// the 300 per inch journals ask (issue 35, X1: they were 144 and 180); the column's names.
    #[test]
    fn default_density_follows_the_column() {
        let single = Options {
            column: Column::Single,
            ..Options::default()
        };
        assert_eq!(Options::default().dpi(), 432.0);
        assert!((single.dpi() - 540.0).abs() < 1e-9);
        assert_eq!("Single".parse::<Column>().unwrap(), Column::Single);
        assert!(matches!(
            "triple".parse::<Column>(),
            Err(PlotError::InvalidOption(m)) if m.contains("triple")
        ));
    }
}
