//! A figure's PDF (feature `pdf`): its SVG converted by svg2pdf, text kept as text in the
//! compiled-in DejaVu Sans, embedded as a subset. The font database holds only that font (and
//! its bold), so no system font is looked up and the PDF is the same on every machine. The page
//! is the SVG's size: its `width` and `height` are in points (`pt`).

use std::sync::Arc;
use svg2pdf::usvg;

/// The PDF of an SVG document written by [`super::svg::Svg`].
pub(crate) fn from_svg(svg: &str) -> Result<Vec<u8>, String> {
    let mut fonts = usvg::fontdb::Database::new();
    fonts.load_font_data(dejavu::sans::regular().to_vec());
    fonts.load_font_data(dejavu::sans::bold().to_vec());
    let options = usvg::Options {
        font_family: "DejaVu Sans".into(),
        fontdb: Arc::new(fonts),
        ..usvg::Options::default()
    };
    let tree = usvg::Tree::from_str(svg, &options).map_err(|e| format!("parsing the SVG: {e}"))?;
    svg2pdf::to_pdf(
        &tree,
        svg2pdf::ConversionOptions::default(),
        // usvg reads the SVG's points as CSS pixels, 96 to the inch; converted at 96 pixels per
        // inch, the page is the SVG's size in points.
        svg2pdf::PageOptions { dpi: 96.0 },
    )
    .map_err(|e| format!("converting the SVG to PDF: {e}"))
}
