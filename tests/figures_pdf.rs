//! PDF export of the figures (issue 25): with the feature `pdf` a figure's PDF is a one-page
//! vector PDF of the SVG's size with its font embedded and its heat map kept as an image;
//! without it, asking for a PDF is a typed error naming the feature.
#![cfg(feature = "plot")]

use shadow_aliasing::plot::{render, Format, PlotError};

fn scratch(tag: &str) -> std::path::PathBuf {
    std::env::temp_dir().join(format!("sa-figures-pdf-{tag}-{}", std::process::id()))
}

#[test]
fn pdf_is_parsed_and_refused_without_the_feature() {
    assert_eq!("PDF".parse::<Format>().unwrap(), Format::Pdf);
    assert_eq!(Format::Pdf.extensions(), &["pdf"]);
    assert_eq!(Format::Pdf.to_string(), "pdf");
    if cfg!(feature = "pdf") {
        return;
    }
    let dir = scratch("off");
    let e = render("lloyd2005-fig4", &dir, Format::Pdf).unwrap_err();
    assert!(matches!(e, PlotError::PdfDisabled), "{e:?}");
    assert!(e.to_string().contains("--features pdf"), "{e}");
    // Nothing is written.
    assert!(!dir.join("lloyd2005-fig4.pdf").exists());
}

/// The page's `/MediaBox [x0 y0 x1 y1]`.
#[cfg(feature = "pdf")]
fn media_box(pdf: &str) -> [f64; 4] {
    let at = pdf.find("/MediaBox [").expect("a MediaBox") + "/MediaBox [".len();
    let nums: Vec<f64> = pdf[at..at + pdf[at..].find(']').unwrap()]
        .split_whitespace()
        .map(|v| v.parse().unwrap())
        .collect();
    [nums[0], nums[1], nums[2], nums[3]]
}

#[cfg(feature = "pdf")]
#[test]
fn pdf_has_the_svgs_page_an_embedded_font_and_the_heat_map() {
    let dir = scratch("on");
    // zhang-fig3: text, lines and heat maps (embedded images in the SVG).
    let name = "zhang-fig3";
    let svg_file = render(name, &dir, Format::Svg).unwrap();
    let svg = std::fs::read_to_string(&svg_file[0]).unwrap();
    let files = render(name, &dir, Format::Pdf).unwrap();
    assert_eq!(files, vec![dir.join(format!("{name}.pdf"))]);
    let bytes = std::fs::read(&files[0]).unwrap();
    assert!(bytes.starts_with(b"%PDF-"), "not a PDF");
    let text = String::from_utf8_lossy(&bytes);
    assert!(text.trim_end().ends_with("%%EOF"));
    // One page, of the SVG's width and height (in points).
    let attr = |a: &str| -> f64 {
        let key = format!(" {a}=\"");
        let at = svg.find(&key).unwrap() + key.len();
        let v = &svg[at..at + svg[at..].find('"').unwrap()];
        v.strip_suffix("pt")
            .expect("a length in points")
            .parse()
            .unwrap()
    };
    let [x0, y0, x1, y1] = media_box(&text);
    assert_eq!((x0, y0), (0.0, 0.0));
    assert!((x1 - attr("width")).abs() < 1e-3, "width {x1}");
    assert!((y1 - attr("height")).abs() < 1e-3, "height {y1}");
    let pages = text.matches("/Type /Page").count() - text.matches("/Type /Pages").count();
    assert_eq!(pages, 1, "pages");
    // The font is embedded (a TrueType or CFF font program), and it is DejaVu Sans.
    assert!(
        text.contains("/FontFile2") || text.contains("/FontFile3"),
        "no embedded font"
    );
    assert!(text.contains("DejaVuSans"), "font name");
    // The heat maps survive as images: as many image XObjects as the SVG has <image>s.
    let images = svg.matches("<image ").count();
    assert!(images > 0);
    assert!(
        text.matches("/Subtype /Image").count() >= images,
        "{} images in the PDF, {images} in the SVG",
        text.matches("/Subtype /Image").count()
    );
    let _ = std::fs::remove_dir_all(&dir);
}
