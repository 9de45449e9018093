//! The papers' figures, rendered with plotters from the crate's own functions (feature `plot`).
//!
//! Every figure is computed from the crate itself: the closed forms of [`crate::analytic`] and
//! [`crate::analytic::eta`] for the analytic plots, and the measurement of built matrices
//! ([`crate::measure`], [`crate::maps`]) for the hemisphere and side-view plots. Nothing is
//! re-derived here; this module only samples, lays out and draws.
//!
//! Text is drawn with DejaVu Sans, compiled into the binary (the `dejavu` crate) and registered
//! once with plotters' `ab_glyph` backend, so no system font library is needed. Its licence is in
//! `licenses/DejaVu-LICENSE`.
//!
//! | name | figure |
//! |---|---|
//! | `lloyd2005-fig4` | Lloyd et al. 2005, Fig 4: the error distribution g(z) for several n (and ξ) |
//! | `lloyd2005-fig7` | Lloyd et al. 2005, Fig 7: maximum error against the number of face subdivisions |
//! | `lloyd2006-fig5` | Lloyd et al. 2006, Fig 5: m_x and m_z along the frustum for several n′ |
//! | `lloyd2006-fig6` | Lloyd et al. 2006, Fig 6: M_x, M_z and S̄ against η |
//! | `lloyd2006-fig7` | Lloyd et al. 2006, Fig 7: S̄ over the hemisphere of light directions |
//! | `lloyd2006-fig10` | Lloyd et al. 2006, Fig 10: S̄ of ZP+W against k, and the logarithmic optimum |
//! | `lloyd2006-fig12` | Lloyd et al. 2006, Fig 12: S̄ against the number of shadow maps |
//! | `lloyd2006-fig13` | Lloyd et al. 2006, Fig 13: where face partitioning overtakes z-partitioning |
//! | `barroso-fig7` | Barroso & Celes 2007, Fig 7: the generalised LiSPSM n′ against γ |
//! | `zhang-fig3` | Zhang et al. 2009, Fig 3: side views of E_p, E_q, E_p×E_q for SSM, LiSPSM, TSM |
//! | `martin-tan-fig6` | Martin & Tan 2004, Fig 6: area of the focus region in the shadow map |
//! | `lloyd2006-fig4` | Lloyd et al. 2006, Fig 4: the warped grids as n′ varies |
//! | `martin-tan-fig3` | Martin & Tan 2004, Figs 3–4: the trapezoid against the bounding box |
//! | `barroso-fig5` | Barroso & Celes 2007, Fig 5: the frustum seen from the light with z-partitions |
//! | `lloyd2006-fig11` | Lloyd et al. 2006, Fig 11: the frustum seen from a light behind the viewer |
//! | `lloyd2005-fig8` | Lloyd et al. 2005, Fig 8: the partitions seen from the light, one partition's warped map, the texture layout |
//! | `lloyd2006-worst-case` | Lloyd et al. 2006, §5.3: worst case over all light directions against the light-behind value |
//!
//! ```no_run
//! use shadow_aliasing::plot::{render_all, Format, FIGURES};
//! let out = std::env::temp_dir().join("shadow-aliasing-figures");
//! let files = render_all(&out, Format::Both, &[], |name| eprintln!("{name} done"))?;
//! assert_eq!(files.len(), 2 * FIGURES.len());
//! # Ok::<(), shadow_aliasing::plot::PlotError>(())
//! ```

mod barroso;
mod canvas;
mod chart;
mod from_light;
mod grids;
mod hemisphere;
mod keyed;
mod layout;
mod lloyd2005;
mod lloyd2006;
mod martin_tan;
mod options;
#[cfg(feature = "pdf")]
mod pdf;
mod svg;
mod trapezoid;
mod warp_grid;
mod worst;
mod zhang;

use image::ImageEncoder;
pub use options::{scale, Column, Options, DEFAULT_DPI, MAX_SCALE};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::fmt;
use std::path::{Path, PathBuf};
use std::str::FromStr;
use std::sync::OnceLock;

/// Which files to write for each figure.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Format {
    /// `NAME.png` only.
    Png,
    /// `NAME.svg` only.
    Svg,
    /// Both `NAME.png` and `NAME.svg`.
    #[default]
    Both,
    /// `NAME.pdf` only: the SVG as a vector PDF with its font embedded. Needs the crate's
    /// feature `pdf`; without it, rendering refuses with [`PlotError::PdfDisabled`].
    Pdf,
}

impl Format {
    /// The file extensions this format writes, in order.
    #[must_use]
    pub fn extensions(self) -> &'static [&'static str] {
        match self {
            Format::Png => &["png"],
            Format::Svg => &["svg"],
            Format::Both => &["png", "svg"],
            Format::Pdf => &["pdf"],
        }
    }
}

impl FromStr for Format {
    type Err = PlotError;

    /// Parses `png`, `svg`, `both` or `pdf` (case-insensitive).
    fn from_str(s: &str) -> Result<Self, PlotError> {
        match s.to_ascii_lowercase().as_str() {
            "png" => Ok(Format::Png),
            "svg" => Ok(Format::Svg),
            "both" => Ok(Format::Both),
            "pdf" => Ok(Format::Pdf),
            _ => Err(PlotError::UnknownFormat(s.to_string())),
        }
    }
}

impl fmt::Display for Format {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Format::Png => "png",
            Format::Svg => "svg",
            Format::Both => "both",
            Format::Pdf => "pdf",
        })
    }
}

/// The names of all figures, in the order [`render_all`] writes them. Each is also the stem of
/// its files (`NAME.png`, `NAME.svg`).
pub const FIGURES: &[&str] = &[
    "lloyd2005-fig4",
    "lloyd2005-fig7",
    "lloyd2006-fig5",
    "lloyd2006-fig6",
    "lloyd2006-fig7",
    "lloyd2006-fig10",
    "lloyd2006-fig12",
    "lloyd2006-fig13",
    "barroso-fig7",
    "zhang-fig3",
    "martin-tan-fig6",
    "lloyd2006-worst-case",
    "lloyd2006-fig4",
    "martin-tan-fig3",
    "barroso-fig5",
    "lloyd2006-fig11",
    "lloyd2005-fig8",
];

/// The figures that have a single-column layout ([`Column::Single`]), their panels stacked:
/// every figure (lloyd2006-fig4 as four rows of two panels sharing their axes). A name missing
/// here is refused in one column with [`PlotError::InvalidOption`].
pub const SINGLE_COLUMN: &[&str] = &[
    "lloyd2005-fig4",
    "lloyd2006-fig5",
    "lloyd2006-fig6",
    "lloyd2006-fig12",
    "barroso-fig7",
    "lloyd2006-worst-case",
    "lloyd2005-fig8",
    "barroso-fig5",
    "lloyd2006-fig11",
    "martin-tan-fig3",
    "lloyd2006-fig7",
    "martin-tan-fig6",
    "lloyd2005-fig7",
    "zhang-fig3",
    "lloyd2006-fig13",
    "lloyd2006-fig10",
    "lloyd2006-fig4",
];

/// What went wrong while rendering a figure.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum PlotError {
    /// The name is not one of [`FIGURES`]. Fix: use one of the names listed in the message.
    #[error("unknown figure {0:?} (known figures: {known})", known = FIGURES.join(", "))]
    UnknownFigure(String),
    /// An [`Options`] value is out of range; the message names it and its range.
    #[error("invalid option: {0}")]
    InvalidOption(String),
    /// The format is not `png`, `svg`, `both` or `pdf`.
    #[error("unknown format {0:?} (expected png, svg, both or pdf)")]
    UnknownFormat(String),
    /// [`Format::Pdf`] was asked of a build without the feature `pdf`. Fix: build with it
    /// (`--features pdf`, or `--features cli,pdf` for the command line, from the clone as the
    /// README installs it).
    #[error(
        "PDF output needs the crate's feature `pdf`: build with `--features pdf` (the command \
         line, in the clone: `cargo install --path . --features cli,pdf --locked`, or \
         `cargo run --release --locked --features cli,pdf -- figures --format pdf`)"
    )]
    PdfDisabled,
    /// The output directory could not be created or a file could not be written.
    /// Fix: choose a writable directory.
    #[error("cannot write {path}: {source}")]
    Io {
        /// The directory or file.
        path: PathBuf,
        /// The underlying error.
        source: std::io::Error,
    },
    /// The compiled-in font could not be registered with plotters (a build problem, not an input
    /// problem).
    #[error("the compiled-in DejaVu Sans font could not be loaded")]
    Font,
    /// Computing the figure's data failed: a closed form or measurement refused its input.
    #[error("computing the data of {figure} failed: {source}")]
    Data {
        /// The figure's name.
        figure: &'static str,
        /// The crate's error.
        source: crate::Error,
    },
    /// plotters failed while drawing or encoding the figure.
    #[error("drawing {figure} failed: {message}")]
    Drawing {
        /// The figure's name.
        figure: &'static str,
        /// plotters' message.
        message: String,
    },
}

/// An error inside a figure's code, before the figure's name is attached.
#[derive(Debug)]
pub(crate) enum Fail {
    Draw(String),
    Data(crate::Error),
}

impl From<crate::Error> for Fail {
    fn from(e: crate::Error) -> Self {
        Fail::Data(e)
    }
}

impl<E: std::error::Error + Send + Sync> From<DrawingAreaErrorKind<E>> for Fail {
    fn from(e: DrawingAreaErrorKind<E>) -> Self {
        Fail::Draw(e.to_string())
    }
}

impl Fail {
    fn named(self, figure: &'static str) -> PlotError {
        match self {
            Fail::Draw(message) => PlotError::Drawing { figure, message },
            Fail::Data(source) => PlotError::Data { figure, source },
        }
    }
}

/// A figure: its data computed once, drawn on any plotters backend.
pub(crate) trait Figure {
    /// Pixel size of the PNG (and of the SVG's view box), across a page's two columns.
    fn size(&self) -> (u32, u32);
    /// The same in one column ([`Column::Single`], [`Column::width`] wide), for a figure with
    /// that layout.
    fn single_size(&self) -> Option<(u32, u32)> {
        None
    }
    /// Draws the whole figure on `root`.
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail>;
}

/// Registers DejaVu Sans as plotters' "sans-serif" once per process.
fn ensure_font() -> Result<(), PlotError> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        plotters::style::register_font(chart::FONT, FontStyle::Normal, dejavu::sans::regular())
            .is_ok()
    });
    if ok {
        Ok(())
    } else {
        Err(PlotError::Font)
    }
}

/// The PNG is drawn at this many times its size in each direction and averaged down.
const SUPERSAMPLE: u32 = 2;

/// A bare page's ink is found in a drawing of this many pixels a unit (its box to a quarter of
/// a unit, then widened to whole units).
const INK_ZOOM: u32 = 4;

/// A PNG has this many pixels per unit of the figure's size (the SVG's view box) in each
/// direction, before [`Options::scale`]: 6 pixels a point, 432 pixels per inch for a two-column
/// figure (a unit a point) and 540 for a one-column one (a unit 0.8 points) at the size the SVG
/// and the PDF print, above the 300 per inch journals ask of halftones (it was 2, 144 and 180
/// per inch).
pub const PNG_ZOOM: u32 = 6;

/// The outline of a map's normalised space [−1, 1]², closed, for the figures that draw it.
pub(crate) const UNIT_SQUARE: [(f64, f64); 5] = [
    (-1.0, -1.0),
    (1.0, -1.0),
    (1.0, 1.0),
    (-1.0, 1.0),
    (-1.0, -1.0),
];

/// Writes `fig` as `out_dir/name.{png,svg}`.
fn emit<F: Figure>(
    name: &'static str,
    fig: &F,
    out_dir: &Path,
    out: &Output,
) -> Result<Vec<PathBuf>, PlotError> {
    // Each figure is drawn into memory and written with `std::fs`, so that a file that cannot be
    // created or written is reported with its path and the operating system's error (plotters'
    // own file backends report it as a debug dump without the path), and nothing is written
    // for a figure whose drawing fails.
    let mut written = Vec::new();
    let opts = out.options;
    let (w, h) = match opts.column {
        Column::Double => fig.size(),
        Column::Single => SINGLE_COLUMN
            .contains(&name)
            .then(|| fig.single_size())
            .flatten()
            .ok_or_else(|| {
                PlotError::InvalidOption(format!(
                    "column single: {name} has no single-column layout; give --column double, or \
                     one of {}",
                    SINGLE_COLUMN.join(", ")
                ))
            })?,
    };
    // A bare page keeps its ink's box and a little white around it (`chart::ink_crop`), the
    // same box for every format: the ink as drawn at INK_ZOOM pixels a unit.
    let crop = if opts.bare {
        chart::with_page(true, opts.column, || -> Result<_, PlotError> {
            let mut big = vec![0u8; (INK_ZOOM * INK_ZOOM) as usize * w as usize * h as usize * 3];
            {
                let bitmap = BitMapBackend::with_buffer(&mut big, (INK_ZOOM * w, INK_ZOOM * h));
                let root =
                    canvas::Canvas::new(bitmap, INK_ZOOM, canvas::BITMAP_TEXT).into_drawing_area();
                fig.draw(&root).map_err(|e| e.named(name))?;
                root.present().map_err(|e| Fail::from(e).named(name))?;
            }
            Ok(chart::ink_crop(&big, INK_ZOOM, (w, h)))
        })?
    } else {
        None
    };
    for ext in out.format.extensions() {
        let path = out_dir.join(format!("{name}.{ext}"));
        let bytes = chart::with_page(opts.bare, opts.column, || -> Result<Vec<u8>, PlotError> {
            chart::set_bare_crop(crop);
            if *ext == "png" {
                // Drawn at twice the (scaled) size and box-filtered down: anti-aliased lines
                // and edges.
                let zoom = PNG_ZOOM * opts.scale;
                let k = SUPERSAMPLE * zoom;
                let (pw, ph) = (w * zoom, h * zoom);
                let mut big = vec![0u8; (k * k) as usize * w as usize * h as usize * 3];
                {
                    let bitmap = BitMapBackend::with_buffer(&mut big, (k * w, k * h));
                    let root =
                        canvas::Canvas::new(bitmap, k, canvas::BITMAP_TEXT).into_drawing_area();
                    fig.draw(&root).map_err(|e| e.named(name))?;
                    root.present().map_err(|e| Fail::from(e).named(name))?;
                }
                let mut rgb = canvas::downsample(&big, pw, ph, SUPERSAMPLE);
                // A bare page keeps only its box.
                let (mut pw, mut ph) = (pw, ph);
                if let Some([l, t, r, b]) = crop {
                    let row = pw as usize * 3;
                    let (l, r) = (l as usize * zoom as usize, r as usize * zoom as usize);
                    let (t, b) = (t * zoom, b * zoom);
                    rgb = (t..b)
                        .flat_map(|y| {
                            let at = y as usize * row;
                            rgb[at + 3 * l..at + 3 * r].iter().copied()
                        })
                        .collect();
                    (pw, ph) = (u32::try_from(r - l).unwrap_or(pw), b - t);
                }
                let mut png = Vec::new();
                image::codecs::png::PngEncoder::new(&mut png)
                    .write_image(&rgb, pw, ph, image::ExtendedColorType::Rgb8)
                    .map_err(|e| PlotError::Io {
                        path: path.clone(),
                        source: std::io::Error::other(e),
                    })?;
                Ok(options::with_phys(&png, opts.pixels_per_metre()))
            } else {
                let mut svg = String::new();
                {
                    // Drawn at SUBUNIT units per view-box unit, so that shapes placed finer
                    // than a unit (curves, rims) keep their positions in the file.
                    let k = canvas::SUBUNIT as u32;
                    let doc = svg::Svg::new(&mut svg, (w, h), opts.scale).units(k);
                    let root = canvas::Canvas::new(doc, k, canvas::SVG_TEXT)
                        .vector()
                        .into_drawing_area();
                    fig.draw(&root).map_err(|e| e.named(name))?;
                    root.present().map_err(|e| Fail::from(e).named(name))?;
                }
                if *ext == "pdf" {
                    to_pdf(&svg).map_err(|message| PlotError::Drawing {
                        figure: name,
                        message,
                    })
                } else {
                    Ok(svg.into_bytes())
                }
            }
        })?;
        std::fs::write(&path, bytes).map_err(|source| PlotError::Io {
            path: path.clone(),
            source,
        })?;
        written.push(path);
    }
    Ok(written)
}

/// A PDF of the SVG `svg` ([`pdf::from_svg`]).
#[cfg(feature = "pdf")]
fn to_pdf(svg: &str) -> Result<Vec<u8>, String> {
    pdf::from_svg(svg)
}

/// Never called: [`render_with`] refuses [`Format::Pdf`] first without the feature.
#[cfg(not(feature = "pdf"))]
fn to_pdf(_: &str) -> Result<Vec<u8>, String> {
    Err(PlotError::PdfDisabled.to_string())
}

/// Renders one figure by name into `out_dir` (created if missing) and returns the files written.
///
/// # Errors
/// [`PlotError::UnknownFigure`] for a name not in [`FIGURES`]; [`PlotError::Io`] when the
/// directory cannot be created; [`PlotError::Data`] or [`PlotError::Drawing`] when computing or
/// drawing the figure fails.
pub fn render(name: &str, out_dir: &Path, format: Format) -> Result<Vec<PathBuf>, PlotError> {
    render_with(name, out_dir, format, &Options::default())
}

/// [`render`] with publication [`Options`]: bare (no title or caption), scaled, with the PNG's
/// physical size.
///
/// # Errors
/// As [`render`], and [`PlotError::InvalidOption`] for an option out of range.
pub fn render_with(
    name: &str,
    out_dir: &Path,
    format: Format,
    options: &Options,
) -> Result<Vec<PathBuf>, PlotError> {
    options.validate()?;
    if format == Format::Pdf && !cfg!(feature = "pdf") {
        return Err(PlotError::PdfDisabled);
    }
    let Some(&name) = FIGURES.iter().find(|&&n| n == name) else {
        return Err(PlotError::UnknownFigure(name.to_string()));
    };
    ensure_font()?;
    std::fs::create_dir_all(out_dir).map_err(|source| PlotError::Io {
        path: out_dir.to_path_buf(),
        source,
    })?;
    dispatch(
        name,
        out_dir,
        &Output {
            format,
            options: *options,
        },
    )
}

/// What [`emit`] writes.
struct Output {
    format: Format,
    options: Options,
}

/// Computes and writes the figure `name` (one of [`FIGURES`]).
fn dispatch(name: &'static str, out_dir: &Path, out: &Output) -> Result<Vec<PathBuf>, PlotError> {
    let data = |e: Fail| e.named(name);
    match name {
        "lloyd2005-fig4" => emit(name, &lloyd2005::fig4().map_err(data)?, out_dir, out),
        "lloyd2005-fig7" => emit(name, &lloyd2005::fig7().map_err(data)?, out_dir, out),
        "lloyd2006-fig5" => emit(name, &lloyd2006::fig5().map_err(data)?, out_dir, out),
        "lloyd2006-fig6" => emit(name, &lloyd2006::fig6().map_err(data)?, out_dir, out),
        "lloyd2006-fig7" => emit(name, &hemisphere::fig7().map_err(data)?, out_dir, out),
        "lloyd2006-fig10" => emit(name, &lloyd2006::fig10().map_err(data)?, out_dir, out),
        "lloyd2006-fig12" => emit(name, &lloyd2006::fig12().map_err(data)?, out_dir, out),
        "lloyd2006-fig13" => emit(name, &lloyd2006::fig13().map_err(data)?, out_dir, out),
        "barroso-fig7" => emit(name, &barroso::fig7().map_err(data)?, out_dir, out),
        "zhang-fig3" => emit(name, &zhang::fig3().map_err(data)?, out_dir, out),
        "martin-tan-fig6" => emit(name, &martin_tan::fig6().map_err(data)?, out_dir, out),
        "lloyd2006-worst-case" => emit(name, &worst::worst_case().map_err(data)?, out_dir, out),
        "lloyd2006-fig4" => emit(name, &warp_grid::fig4().map_err(data)?, out_dir, out),
        "martin-tan-fig3" => emit(name, &trapezoid::fig3().map_err(data)?, out_dir, out),
        "barroso-fig5" => emit(
            name,
            &from_light::barroso_fig5().map_err(data)?,
            out_dir,
            out,
        ),
        "lloyd2006-fig11" => emit(
            name,
            &from_light::lloyd2006_fig11().map_err(data)?,
            out_dir,
            out,
        ),
        "lloyd2005-fig8" => emit(name, &layout::fig8().map_err(data)?, out_dir, out),
        _ => Err(PlotError::UnknownFigure(name.to_string())),
    }
}

/// One public function per figure: each writes `out_dir/NAME.{png,svg}` as [`render`] does.
macro_rules! figure_fns {
    ($($(#[$doc:meta])* $func:ident => $name:literal;)*) => {
        $(
            $(#[$doc])*
            ///
            /// # Errors
            /// As [`render`].
            pub fn $func(out_dir: &Path, format: Format) -> Result<Vec<PathBuf>, PlotError> {
                render($name, out_dir, format)
            }
        )*
    };
}

figure_fns! {
    /// Lloyd et al. 2005 Fig 4 (`lloyd2005-fig4`): the error distribution g(z) over z ∈ [1, α]
    /// for the n of ξ = 1, ½, 0, −½, −1 (α = 10).
    lloyd2005_fig4 => "lloyd2005-fig4";
    /// Lloyd et al. 2005 Fig 7 (`lloyd2005-fig7`): the maximum error with k face subdivisions,
    /// normalised at k = 1, for α = 10 … 10⁴.
    lloyd2005_fig7 => "lloyd2005-fig7";
    /// Lloyd et al. 2006 Fig 5 (`lloyd2006-fig5`): m_x and the z-error distribution along the
    /// frustum for several n′ (n = 1, f = 20).
    lloyd2006_fig5 => "lloyd2006-fig5";
    /// Lloyd et al. 2006 Fig 6 (`lloyd2006-fig6`): M_x, M_z and S̄ against η, normalised
    /// (n = 1, f = 100).
    lloyd2006_fig6 => "lloyd2006-fig6";
    /// Lloyd et al. 2006 Fig 7 (`lloyd2006-fig7`): the measured S̄ over the hemisphere of light
    /// directions without warping, with LiSPSM warping, with face partitioning and with the
    /// crate's minimax n′ (log₁₀ colour scale).
    lloyd2006_fig7 => "lloyd2006-fig7";
    /// Lloyd et al. 2006 Fig 10 (`lloyd2006-fig10`): S̄ of ZP+W against k with the optimal
    /// logarithmic S̄.
    lloyd2006_fig10 => "lloyd2006-fig10";
    /// Lloyd et al. 2006 Fig 12 (`lloyd2006-fig12`): S̄ against the number of shadow maps for ZP,
    /// ZP+W, FP+ZP+W, light overhead and behind (f/n = 1000, θ = 30°).
    lloyd2006_fig12 => "lloyd2006-fig12";
    /// Lloyd et al. 2006 Fig 13 (`lloyd2006-fig13`): where face partitioning overtakes
    /// z-partitioning with the light behind.
    lloyd2006_fig13 => "lloyd2006-fig13";
    /// Barroso & Celes 2007 Fig 7 (`barroso-fig7`): the generalised LiSPSM n′ against γ with both
    /// fall-offs (n = 1, f = 100, φ_y = π/6).
    barroso_fig7 => "barroso-fig7";
    /// Zhang et al. 2009 Fig 3 (`zhang-fig3`): measured side views of E_p, E_q and E_p×E_q for
    /// SSM, LiSPSM and TSM at θ = 90°, 60°, 30° (log₅ colour scale).
    zhang_fig3 => "zhang-fig3";
    /// Martin & Tan 2004 Fig 6 (`martin-tan-fig6`): the area of the focus region in the
    /// trapezoidal map against the light direction.
    martin_tan_fig6 => "martin-tan-fig6";
    /// Lloyd et al. 2006 §5.3 (`lloyd2006-worst-case`): the measured worst S̄ over all light
    /// directions against the light-behind closed form, per scheme and number of partitions.
    lloyd2006_worst_case => "lloyd2006-worst-case";
    /// Lloyd et al. 2006 Fig 4 (`lloyd2006-fig4`): the warped shadow-map grid over the view
    /// frustum and the frustum's grid in the map, as n′ decreases from ∞ to n (light overhead).
    lloyd2006_fig4 => "lloyd2006-fig4";
    /// Martin & Tan 2004 Figs 3–4 (`martin-tan-fig3`): the eye's frustum seen from the light
    /// with the trapezoid and the bounding box, and the frustum in both normalised spaces.
    martin_tan_fig3 => "martin-tan-fig3";
    /// Barroso & Celes 2007 Fig 5 (`barroso-fig5`): the view frustum seen from the light with
    /// self-similar and adaptive z-partitions.
    barroso_fig5 => "barroso-fig5";
    /// Lloyd et al. 2006 Fig 11 (`lloyd2006-fig11`): the view frustum seen from a light behind
    /// the viewer, with z-partitions and their overlapping maps.
    lloyd2006_fig11 => "lloyd2006-fig11";
    /// Lloyd et al. 2005 Fig 8 (`lloyd2005-fig8`): (a) face partitions with z-partitions seen
    /// from the light, (b) one partition's warped texel grid, (c) their texture layout by Eq 6.
    lloyd2005_fig8 => "lloyd2005-fig8";
}

/// Renders every figure, or only those named in `only` when it is not empty, into `out_dir`, in
/// the order of [`FIGURES`]. `progress` is called with each figure's name once its files are
/// written. Returns all files written.
///
/// # Errors
/// [`PlotError::UnknownFigure`] before anything is drawn when a name in `only` is unknown;
/// otherwise the first error of [`render`].
pub fn render_all(
    out_dir: &Path,
    format: Format,
    only: &[&str],
    mut progress: impl FnMut(&str),
) -> Result<Vec<PathBuf>, PlotError> {
    if let Some(bad) = only.iter().find(|n| !FIGURES.contains(n)) {
        return Err(PlotError::UnknownFigure((*bad).to_string()));
    }
    let mut written = Vec::new();
    for &name in FIGURES {
        if only.is_empty() || only.contains(&name) {
            written.extend(render(name, out_dir, format)?);
            progress(name);
        }
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::chart::*;
    use super::*;

    /// A figure of made-up data exercising every helper: log axes, clipping, legend, a grid heat
    /// map with a log colour bar, and a hemisphere panel.
    struct Demo;

    impl Figure for Demo {
        fn size(&self) -> (u32, u32) {
            (1200, 800)
        }
        fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
            let body = frame(
                root,
                "Self-test of the drawing helpers",
                &["Made-up data: y = x² and y = 10/x on log axes, clipped at the border; a log₅ heat map; a hemisphere."],
            )?;
            let panels = body.split_evenly((2, 2));
            let mut c = LineChart::new(
                "log-log",
                Axis::log10("x (units)", 0.1, 100.0),
                Axis::log10("y (units)", 0.01, 1000.0),
            );
            let xs: Vec<f64> = linspace(-2.0, 3.0, 50)
                .into_iter()
                .map(|e| 10f64.powf(e))
                .collect();
            c.series.push(Series::line(
                "x²",
                xs.iter().map(|&x| (x, x * x)).collect(),
                PALETTE[0],
            ));
            c.series.push(
                Series::line(
                    "10/x",
                    xs.iter().map(|&x| (x, 10.0 / x)).collect(),
                    PALETTE[1],
                )
                .dashed()
                .with_markers(),
            );
            draw_line_chart(&panels[0], &c)?;
            let mut l = LineChart::new(
                "linear",
                Axis::linear("η", -1.0, 1.0),
                Axis::linear("value", 0.0, 1.0),
            );
            l.series.push(
                Series::line(
                    "η²",
                    linspace(-1.0, 1.0, 41)
                        .into_iter()
                        .map(|e| (e, e * e))
                        .collect(),
                    PALETTE[2],
                )
                .dotted(),
            );
            draw_line_chart(&panels[1], &l)?;
            let scale = ColourScale {
                axis: Axis::log_base("E", 1.0, 625.0, 5.0),
                levels: 40,
                map: ColourMap::Viridis,
            };
            let (left, bar) = panels[2].split_horizontally(panels[2].dim_in_pixel().0 - 90);
            let mut chart = build_chart(
                &left,
                "side view",
                &Axis::linear("z", 0.0, 100.0),
                &Axis::linear("y", -60.0, 60.0),
                false,
            )?;
            let t = 30f64.to_radians().tan();
            let grid = Grid::sample((0.0, 100.0, 60), (-60.0, 60.0, 40), |z, y| {
                (z >= 1.0 && y.abs() <= z * t).then(|| 1.0 + z * (1.0 + y.abs()) / 10.0)
            });
            draw_grid(&mut chart, &grid, &scale)?;
            draw_colour_bar(&bar, &scale)?;
            let n_el = 10;
            let n_az = 36;
            let polar = PolarGrid {
                elev_edges: linspace(0.0, std::f64::consts::FRAC_PI_2, n_el + 1),
                az_edges: linspace(0.0, std::f64::consts::TAU, n_az + 1),
                values: (0..n_el * n_az)
                    .map(|k| Some(1.0 + (k % n_az) as f64 * 10.0))
                    .collect(),
            };
            let hs = ColourScale {
                axis: Axis::log10("S̄", 1.0, 1000.0),
                levels: 30,
                map: ColourMap::Viridis,
            };
            draw_hemisphere(&panels[3], "hemisphere", &polar, &hs)?;
            Ok(())
        }
    }

    #[test]
    fn helpers_render_png_and_svg() {
        ensure_font().unwrap();
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/plot-selftest");
        std::fs::create_dir_all(&dir).unwrap();
        let out = Output {
            format: Format::Both,
            options: Options::default(),
        };
        let files = emit("demo", &Demo, &dir, &out).unwrap();
        assert_eq!(files.len(), 2);
        let png = std::fs::read(&files[0]).unwrap();
        assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
        assert!(png.len() > 20_000, "PNG of {} bytes", png.len());
        let svg = std::fs::read_to_string(&files[1]).unwrap();
        // The grid and the hemisphere heat maps are one embedded image each, and so is the
        // colour bar.
        assert!(svg.contains("<svg") && svg.matches("<image ").count() == 3);
        assert!(svg.contains("Self-test of the drawing helpers"));
    }

    #[test]
    fn format_parses_and_unknown_names_are_refused() {
        assert_eq!("SVG".parse::<Format>().unwrap(), Format::Svg);
        assert_eq!(Format::Both.extensions(), &["png", "svg"]);
        assert!(matches!(
            "jpeg".parse::<Format>(),
            Err(PlotError::UnknownFormat(_))
        ));
        let dir = std::env::temp_dir();
        assert!(matches!(
            render("no-such-figure", &dir, Format::Png),
            Err(PlotError::UnknownFigure(_))
        ));
        assert!(matches!(
            render_all(&dir, Format::Png, &["no-such-figure"], |_| {}),
            Err(PlotError::UnknownFigure(_))
        ));
    }
}
