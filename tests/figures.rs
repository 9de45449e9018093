//! Renders every figure into a temporary directory under target/ and checks that each file is a
//! valid, non-trivial image: PNGs are decoded here (chunk CRCs, zlib stream, Adler-32, scanline
//! filters) and must have the promised size and many distinct colours, neither blank nor flooded;
//! SVGs must be well-formed enough to parse as XML elements, hold many drawing elements, and carry
//! the figure's title and the paper's figure number in the caption.
#![cfg(feature = "plot")]

mod figures_style_read;

use shadow_aliasing::plot::{render, render_all, Format, PlotError, FIGURES};
use std::collections::HashSet;
use std::path::{Path, PathBuf};

/// The paper and figure number each figure's caption must name.
fn citation(name: &str) -> &'static str {
    match name {
        "lloyd2005-fig4" => "Lloyd et al. 2005, Fig. 4",
        "lloyd2005-fig7" => "Lloyd et al. 2005, Fig. 7",
        "lloyd2006-fig5" => "Lloyd et al. 2006, Fig. 5",
        "lloyd2006-fig6" => "Lloyd et al. 2006, Fig. 6",
        "lloyd2006-fig7" => "Lloyd et al. 2006, Fig. 7",
        "lloyd2006-fig10" => "Lloyd et al. 2006, Fig. 10",
        "lloyd2006-fig12" => "Lloyd et al. 2006, Fig. 12",
        "lloyd2006-fig13" => "Lloyd et al. 2006, Fig. 13",
        "barroso-fig7" => "Barroso &amp; Celes 2007, Fig. 7",
        "zhang-fig3" => "Zhang et al. 2009, Fig. 3",
        "martin-tan-fig6" => "Martin &amp; Tan 2004, Fig. 6",
        "lloyd2006-worst-case" => "Lloyd et al. 2006, §5.3",
        "lloyd2006-fig4" => "Lloyd et al. 2006, Fig. 4",
        "martin-tan-fig3" => "Martin &amp; Tan 2004, Figs. 3 and 4",
        "barroso-fig5" => "Barroso &amp; Celes 2007, Fig. 5",
        "lloyd2006-fig11" => "Lloyd et al. 2006, Fig. 11",
        "lloyd2005-fig8" => "Lloyd et al. 2005, Fig. 8",
        other => panic!("no citation known for {other}"),
    }
}

/// A fresh directory per test and per process, so that two test runs at once (CI's two seeds on
/// one machine, a developer's run beside it) never delete each other's figures.
fn out_dir(sub: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("{sub}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

#[test]
fn every_figure_renders_to_valid_png_and_svg() {
    let dir = out_dir("figures-all");
    let mut seen = Vec::new();
    let files = render_all(&dir, Format::Both, &[], |n| seen.push(n.to_string())).unwrap();
    assert_eq!(seen, FIGURES);
    assert_eq!(files.len(), 2 * FIGURES.len());
    for name in FIGURES {
        let png = dir.join(format!("{name}.png"));
        let svg = dir.join(format!("{name}.svg"));
        assert!(files.contains(&png) && files.contains(&svg), "{name}");
        check_png(&png);
        check_svg(&svg, name);
    }
}

/// Regenerates the gallery's SVGs in docs/figures (run explicitly, see docs/figures.md):
/// `cargo test --release --features plot,parallel --test figures -- --ignored regenerate_docs_figures`.
#[test]
#[ignore = "writes into docs/figures; run explicitly to regenerate the gallery"]
fn regenerate_docs_figures() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/figures");
    let files = render_all(&dir, Format::Svg, &[], |_| {}).unwrap();
    for name in FIGURES {
        check_svg(&dir.join(format!("{name}.svg")), name);
    }
    assert_eq!(files.len(), FIGURES.len());
}

#[test]
fn only_and_format_select_the_files() {
    let dir = out_dir("figures-only");
    let name = FIGURES[0];
    let files = render_all(&dir, Format::Svg, &[name], |_| {}).unwrap();
    assert_eq!(files, vec![dir.join(format!("{name}.svg"))]);
    let files = render(name, &dir, Format::Png).unwrap();
    assert_eq!(files, vec![dir.join(format!("{name}.png"))]);
    check_png(&files[0]);
    let n = std::fs::read_dir(&dir).unwrap().count();
    assert_eq!(n, 2, "only the two requested files are written");
    let err = render_all(&dir, Format::Png, &[name, "lloyd2006-fig99"], |_| {}).unwrap_err();
    assert!(matches!(err, PlotError::UnknownFigure(ref n) if n == "lloyd2006-fig99"));
    assert!(
        err.to_string().contains(name),
        "the message lists the known names: {err}"
    );
}

#[test]
fn each_figure_has_its_own_function() {
    use shadow_aliasing::plot;
    let dir = out_dir("figures-functions");
    type F = fn(&Path, Format) -> Result<Vec<PathBuf>, PlotError>;
    let funcs: [(&str, F); 17] = [
        ("lloyd2005-fig4", plot::lloyd2005_fig4),
        ("lloyd2005-fig7", plot::lloyd2005_fig7),
        ("lloyd2006-fig5", plot::lloyd2006_fig5),
        ("lloyd2006-fig6", plot::lloyd2006_fig6),
        ("lloyd2006-fig7", plot::lloyd2006_fig7),
        ("lloyd2006-fig10", plot::lloyd2006_fig10),
        ("lloyd2006-fig12", plot::lloyd2006_fig12),
        ("lloyd2006-fig13", plot::lloyd2006_fig13),
        ("barroso-fig7", plot::barroso_fig7),
        ("zhang-fig3", plot::zhang_fig3),
        ("martin-tan-fig6", plot::martin_tan_fig6),
        ("lloyd2006-worst-case", plot::lloyd2006_worst_case),
        ("lloyd2006-fig4", plot::lloyd2006_fig4),
        ("martin-tan-fig3", plot::martin_tan_fig3),
        ("barroso-fig5", plot::barroso_fig5),
        ("lloyd2006-fig11", plot::lloyd2006_fig11),
        ("lloyd2005-fig8", plot::lloyd2005_fig8),
    ];
    assert_eq!(funcs.len(), FIGURES.len());
    for (name, f) in funcs {
        let files = f(&dir, Format::Svg).unwrap();
        assert_eq!(files, vec![dir.join(format!("{name}.svg"))]);
    }
}

#[test]
fn the_figure_list_is_the_issue_list() {
    let expected = [
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
    assert_eq!(FIGURES, expected);
    let unique: HashSet<_> = FIGURES.iter().collect();
    assert_eq!(unique.len(), FIGURES.len());
}

fn check_svg(path: &Path, name: &str) {
    let text = std::fs::read_to_string(path).unwrap();
    check_text_contrast(&text, name);
    let start = text
        .find("<svg")
        .unwrap_or_else(|| panic!("{name}: no <svg"));
    assert!(text.trim_end().ends_with("</svg>"), "{name}: not closed");
    // Walk the tags: every element is opened and closed in order.
    let mut stack: Vec<&str> = Vec::new();
    let mut elements = 0usize;
    let mut rest = &text[start..];
    while let Some(lt) = rest.find('<') {
        rest = &rest[lt + 1..];
        let gt = rest
            .find('>')
            .unwrap_or_else(|| panic!("{name}: unterminated tag"));
        let tag = &rest[..gt];
        rest = &rest[gt + 1..];
        if let Some(closing) = tag.strip_prefix('/') {
            assert_eq!(
                stack.pop(),
                Some(closing.trim()),
                "{name}: mismatched </{closing}>"
            );
        } else if !tag.starts_with('?') && !tag.starts_with('!') {
            elements += 1;
            let tag_name = tag.split_whitespace().next().unwrap_or("");
            assert!(
                tag_name.chars().all(|c| c.is_ascii_alphanumeric()),
                "{name}: bad tag {tag_name}"
            );
            if !tag.ends_with('/') {
                stack.push(tag_name);
            }
        }
    }
    assert!(stack.is_empty(), "{name}: unclosed {stack:?}");
    assert!(elements > 60, "{name}: only {elements} SVG elements");
    assert!(
        text.contains(citation(name)),
        "{name}: the caption does not cite {}",
        citation(name)
    );
    assert!(
        text.matches("<text").count() >= 10,
        "{name}: too few labels"
    );
    // Text at least 2 % of the figure's width (issue 25): every <text>'s font-size against the
    // view box's width, both read from the SVG. (Sub- and superscripts are <tspan>s at 72 % of
    // their line, as in TeX.)
    let view_width: f64 = text
        .split("viewBox=\"0 0 ")
        .nth(1)
        .and_then(|v| v.split(' ').next())
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("{name}: no view box"));
    for (attrs, content) in texts(&text) {
        let size: f64 = attrs
            .split("font-size=\"")
            .nth(1)
            .and_then(|v| v.split('"').next())
            .and_then(|v| v.parse().ok())
            .unwrap_or_else(|| panic!("{name}: a <text> without font-size: {attrs}"));
        assert!(
            size >= 0.02 * view_width,
            "{name}: text {:?} of {size} px is {:.2} % of the width {view_width} (at least 2 %)",
            visible(content),
            100.0 * size / view_width
        );
    }
    for (attrs, _) in texts(&text) {
        assert!(
            attrs.contains("xml:space=\"preserve\""),
            "{name}: a <text> collapses spaces: {attrs}"
        );
        assert!(
            attrs.contains("font-family=\"'DejaVu Sans', ") && attrs.contains("sans-serif\""),
            "{name}: a <text> without the family list: {attrs}"
        );
    }
}

/// Every `<text>` element of an SVG: its attributes and its content (with any `<tspan>`s).
fn texts(svg: &str) -> Vec<(&str, &str)> {
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(at) = rest.find("<text ") {
        rest = &rest[at + 6..];
        let gt = rest.find('>').unwrap();
        let end = rest.find("</text>").unwrap();
        out.push((&rest[..gt], &rest[gt + 1..end]));
        rest = &rest[end..];
    }
    out
}

/// The characters a reader sees: the content without its tags, entities decoded.
fn visible(content: &str) -> String {
    let mut s = String::new();
    let mut in_tag = false;
    for c in content.chars() {
        match c {
            '<' => in_tag = true,
            '>' => in_tag = false,
            c if !in_tag => s.push(c),
            _ => {}
        }
    }
    s.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&apos;", "'")
        .replace("&amp;", "&")
}

#[test]
fn svg_labels_are_one_text_each_with_tspan_subscripts_and_bars() {
    let dir = out_dir("figures-svg-text");
    render_all(&dir, Format::Svg, &["lloyd2006-fig6"], |_| {}).unwrap();
    let svg = std::fs::read_to_string(dir.join("lloyd2006-fig6.svg")).unwrap();
    let all = texts(&svg);
    // The legend's labels, as written in src/plot/lloyd2006.rs: each is one <text> whose
    // subscripts are <tspan>s shifted down and whose S̄ is an overlined <tspan>.
    let find = |seen: &str| {
        all.iter()
            .find(|(_, c)| visible(c) == seen)
            .unwrap_or_else(|| panic!("no single <text> reads {seen:?}"))
            .1
    };
    // (The key names the quantities only; their maxima are in the caption.)
    let mx = find("Mx");
    assert!(mx.starts_with("M<tspan dy=\""), "{mx}");
    let s = find("S = Mx Mz");
    assert!(
        s.starts_with("<tspan text-decoration=\"overline\">S</tspan>"),
        "{s}"
    );
    // Two subscripts, the text between them shifted back up: three shifted tspans.
    assert_eq!(s.matches("<tspan dy=\"").count(), 3, "{s}");
    // No <text> is a subscript alone (the old layout placed each subscript by itself).
    for (attrs, c) in &all {
        assert!(
            !c.starts_with("<tspan dy="),
            "a lone subscript: {attrs} {c}"
        );
        assert!(!visible(c).trim().is_empty(), "an empty <text>: {attrs}");
    }
}

#[test]
fn heat_maps_are_one_embedded_image_per_panel() {
    let dir = out_dir("figures-svg-heat");
    // (figure, heat-map panels and colour bars: each bar is one image too, no seams)
    let heat = [
        // (a)–(d) and the ratio panel (e), their two bars.
        ("lloyd2006-fig7", 5 + 2),
        ("zhang-fig3", 27 + 3),
        ("martin-tan-fig6", 1 + 1),
    ];
    let names: Vec<&str> = heat.iter().map(|(n, _)| *n).collect();
    render_all(&dir, Format::Svg, &names, |_| {}).unwrap();
    for (name, panels) in heat {
        let svg = std::fs::read_to_string(dir.join(format!("{name}.svg"))).unwrap();
        assert_eq!(
            svg.matches("<image ").count(),
            panels,
            "{name}: one image per heat map"
        );
        assert_eq!(
            svg.matches("href=\"data:image/png;base64,iVBORw0KGgo")
                .count(),
            panels,
            "{name}: embedded PNGs"
        );
        // Formerly thousands of cells (17 380 polygons in lloyd2006-fig7, 1.6–2 MB files).
        let shapes = svg.matches("<polygon").count() + svg.matches("<rect").count();
        assert!(shapes < 1500, "{name}: {shapes} shapes");
        assert!(svg.len() < 700_000, "{name}: {} bytes", svg.len());
    }
}

fn check_png(path: &Path) {
    let bytes = std::fs::read(path).unwrap();
    let img = decode_png(&bytes).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert!(
        img.width >= 600 && img.height >= 400,
        "{}x{}",
        img.width,
        img.height
    );
    let px = img.width * img.height;
    let mut colours = HashSet::new();
    let mut white = 0usize;
    for p in img.rgb.chunks_exact(3) {
        colours.insert((p[0], p[1], p[2]));
        if p == [255, 255, 255] {
            white += 1;
        }
    }
    assert!(
        colours.len() >= 16,
        "{}: {} colours",
        path.display(),
        colours.len()
    );
    let ink = 1.0 - white as f64 / px as f64;
    assert!(
        (0.02..0.98).contains(&ink),
        "{}: {:.1}% of the pixels are not white",
        path.display(),
        100.0 * ink
    );
}

// ---------------------------------------------------------------------------------------------
// A small PNG decoder (8-bit RGB / RGBA, non-interlaced), enough to check what plotters writes
// without adding a dependency.

struct Image {
    width: usize,
    height: usize,
    rgb: Vec<u8>,
}

fn be32(b: &[u8]) -> u32 {
    u32::from_be_bytes([b[0], b[1], b[2], b[3]])
}

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

fn decode_png(bytes: &[u8]) -> Result<Image, String> {
    if bytes.len() < 8 || &bytes[..8] != b"\x89PNG\r\n\x1a\n" {
        return Err("no PNG signature".into());
    }
    let mut pos = 8;
    let (mut width, mut height, mut channels) = (0usize, 0usize, 0usize);
    let mut idat = Vec::new();
    let mut ended = false;
    while pos + 12 <= bytes.len() {
        let len = be32(&bytes[pos..]) as usize;
        let kind = &bytes[pos + 4..pos + 8];
        let data = bytes.get(pos + 8..pos + 8 + len).ok_or("truncated chunk")?;
        let crc = be32(&bytes[pos + 8 + len..]);
        if crc32(&bytes[pos + 4..pos + 8 + len]) != crc {
            return Err(format!("bad CRC in {}", String::from_utf8_lossy(kind)));
        }
        match kind {
            b"IHDR" => {
                width = be32(data) as usize;
                height = be32(&data[4..]) as usize;
                if data[8] != 8 || data[12] != 0 {
                    return Err("only 8-bit non-interlaced images are decoded".into());
                }
                channels = match data[9] {
                    2 => 3,
                    6 => 4,
                    t => return Err(format!("colour type {t}")),
                };
            }
            b"IDAT" => idat.extend_from_slice(data),
            b"IEND" => {
                ended = true;
                break;
            }
            _ => {}
        }
        pos += 12 + len;
    }
    if !ended || width == 0 {
        return Err("missing IHDR or IEND".into());
    }
    let raw = zlib_decompress(&idat)?;
    let stride = width * channels;
    if raw.len() != height * (stride + 1) {
        return Err(format!(
            "decoded {} bytes, expected {}",
            raw.len(),
            height * (stride + 1)
        ));
    }
    let mut out = vec![0u8; height * stride];
    for y in 0..height {
        let filter = raw[y * (stride + 1)];
        let line = &raw[y * (stride + 1) + 1..(y + 1) * (stride + 1)];
        for x in 0..stride {
            let a = if x >= channels {
                out[y * stride + x - channels]
            } else {
                0
            };
            let b = if y > 0 { out[(y - 1) * stride + x] } else { 0 };
            let c = if y > 0 && x >= channels {
                out[(y - 1) * stride + x - channels]
            } else {
                0
            };
            let pred = match filter {
                0 => 0,
                1 => a,
                2 => b,
                3 => ((u16::from(a) + u16::from(b)) / 2) as u8,
                4 => {
                    let p = i16::from(a) + i16::from(b) - i16::from(c);
                    let (pa, pb, pc) = (
                        (p - i16::from(a)).abs(),
                        (p - i16::from(b)).abs(),
                        (p - i16::from(c)).abs(),
                    );
                    if pa <= pb && pa <= pc {
                        a
                    } else if pb <= pc {
                        b
                    } else {
                        c
                    }
                }
                f => return Err(format!("filter {f}")),
            };
            out[y * stride + x] = line[x].wrapping_add(pred);
        }
    }
    let rgb = if channels == 3 {
        out
    } else {
        out.chunks_exact(4)
            .flat_map(|p| [p[0], p[1], p[2]])
            .collect()
    };
    Ok(Image { width, height, rgb })
}

struct Bits<'a> {
    data: &'a [u8],
    pos: usize,
    bit: u32,
}

impl Bits<'_> {
    fn bit(&mut self) -> Result<u32, String> {
        let byte = *self
            .data
            .get(self.pos)
            .ok_or("deflate stream ended early")?;
        let v = (u32::from(byte) >> self.bit) & 1;
        self.bit += 1;
        if self.bit == 8 {
            self.bit = 0;
            self.pos += 1;
        }
        Ok(v)
    }
    fn bits(&mut self, n: u32) -> Result<u32, String> {
        let mut v = 0;
        for i in 0..n {
            v |= self.bit()? << i;
        }
        Ok(v)
    }
    fn align(&mut self) {
        if self.bit != 0 {
            self.bit = 0;
            self.pos += 1;
        }
    }
}

/// A canonical Huffman code: symbols by code length.
struct Huffman {
    counts: [u16; 16],
    symbols: Vec<u16>,
}

impl Huffman {
    fn new(lengths: &[u8]) -> Self {
        let mut counts = [0u16; 16];
        for &l in lengths {
            counts[l as usize] += 1;
        }
        counts[0] = 0;
        let mut offs = [0u16; 16];
        for i in 1..16 {
            offs[i] = offs[i - 1] + counts[i - 1];
        }
        let mut symbols = vec![0u16; lengths.len()];
        for (s, &l) in lengths.iter().enumerate() {
            if l != 0 {
                symbols[offs[l as usize] as usize] = s as u16;
                offs[l as usize] += 1;
            }
        }
        Self { counts, symbols }
    }
    fn decode(&self, b: &mut Bits<'_>) -> Result<u16, String> {
        let (mut code, mut first, mut index) = (0i32, 0i32, 0i32);
        for len in 1..16 {
            code |= b.bit()? as i32;
            let count = i32::from(self.counts[len]);
            if code - count < first {
                return Ok(self.symbols[(index + code - first) as usize]);
            }
            index += count;
            first += count;
            first <<= 1;
            code <<= 1;
        }
        Err("bad Huffman code".into())
    }
}

const LEN_BASE: [u16; 29] = [
    3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31, 35, 43, 51, 59, 67, 83, 99, 115, 131,
    163, 195, 227, 258,
];
const LEN_EXTRA: [u8; 29] = [
    0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0,
];
const DIST_BASE: [u16; 30] = [
    1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193, 257, 385, 513, 769, 1025, 1537,
    2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577,
];
const DIST_EXTRA: [u8; 30] = [
    0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13,
    13,
];

fn zlib_decompress(data: &[u8]) -> Result<Vec<u8>, String> {
    if data.len() < 6
        || data[0] & 0x0F != 8
        || (u16::from(data[0]) << 8 | u16::from(data[1])) % 31 != 0
    {
        return Err("bad zlib header".into());
    }
    let mut b = Bits {
        data: &data[2..],
        pos: 0,
        bit: 0,
    };
    let mut out: Vec<u8> = Vec::new();
    loop {
        let last = b.bit()?;
        match b.bits(2)? {
            0 => {
                b.align();
                let d = &b.data[b.pos..];
                let len = u16::from_le_bytes([d[0], d[1]]) as usize;
                let nlen = u16::from_le_bytes([d[2], d[3]]) as usize;
                if len != !nlen & 0xFFFF {
                    return Err("bad stored block".into());
                }
                out.extend_from_slice(d.get(4..4 + len).ok_or("truncated stored block")?);
                b.pos += 4 + len;
            }
            1 => {
                let mut l = [0u8; 288];
                l[..144].fill(8);
                l[144..256].fill(9);
                l[256..280].fill(7);
                l[280..].fill(8);
                inflate_block(
                    &mut b,
                    &mut out,
                    &Huffman::new(&l),
                    &Huffman::new(&[5u8; 30]),
                )?;
            }
            2 => {
                let hlit = b.bits(5)? as usize + 257;
                let hdist = b.bits(5)? as usize + 1;
                let hclen = b.bits(4)? as usize + 4;
                const ORDER: [usize; 19] = [
                    16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15,
                ];
                let mut cl = [0u8; 19];
                for &o in ORDER.iter().take(hclen) {
                    cl[o] = b.bits(3)? as u8;
                }
                let clh = Huffman::new(&cl);
                let mut lengths = Vec::with_capacity(hlit + hdist);
                while lengths.len() < hlit + hdist {
                    match clh.decode(&mut b)? {
                        s @ 0..=15 => lengths.push(s as u8),
                        16 => {
                            let prev = *lengths.last().ok_or("repeat with no previous length")?;
                            for _ in 0..3 + b.bits(2)? {
                                lengths.push(prev);
                            }
                        }
                        17 => lengths.extend(std::iter::repeat_n(0, 3 + b.bits(3)? as usize)),
                        _ => lengths.extend(std::iter::repeat_n(0, 11 + b.bits(7)? as usize)),
                    }
                }
                let lit = Huffman::new(&lengths[..hlit]);
                let dist = Huffman::new(&lengths[hlit..]);
                inflate_block(&mut b, &mut out, &lit, &dist)?;
            }
            _ => return Err("reserved block type".into()),
        }
        if last == 1 {
            break;
        }
    }
    b.align();
    let tail = b.data.get(b.pos..b.pos + 4).ok_or("missing Adler-32")?;
    let (mut s1, mut s2) = (1u32, 0u32);
    for &x in &out {
        s1 = (s1 + u32::from(x)) % 65521;
        s2 = (s2 + s1) % 65521;
    }
    if be32(tail) != (s2 << 16 | s1) {
        return Err("Adler-32 mismatch".into());
    }
    Ok(out)
}

fn inflate_block(
    b: &mut Bits<'_>,
    out: &mut Vec<u8>,
    lit: &Huffman,
    dist: &Huffman,
) -> Result<(), String> {
    loop {
        let sym = lit.decode(b)? as usize;
        if sym < 256 {
            out.push(sym as u8);
        } else if sym == 256 {
            return Ok(());
        } else {
            let i = sym - 257;
            let len = *LEN_BASE.get(i).ok_or("bad length symbol")? as usize
                + b.bits(u32::from(LEN_EXTRA[i]))? as usize;
            let d = dist.decode(b)? as usize;
            let back = *DIST_BASE.get(d).ok_or("bad distance symbol")? as usize
                + b.bits(u32::from(DIST_EXTRA[d]))? as usize;
            if back > out.len() {
                return Err("distance before the start".into());
            }
            let start = out.len() - back;
            for k in 0..len {
                out.push(out[start + k]);
            }
        }
    }
}

#[test]
fn the_png_decoder_reads_a_hand_made_image() {
    // A 2×1 RGB image, one stored deflate block: filter 0, red pixel, blue pixel.
    let raw = [0u8, 255, 0, 0, 0, 0, 255];
    let mut z = vec![0x78, 0x01, 0x01, 7, 0, !7u8, 0xFF];
    z.extend_from_slice(&raw);
    let (mut s1, mut s2) = (1u32, 0u32);
    for &x in &raw {
        s1 = (s1 + u32::from(x)) % 65521;
        s2 = (s2 + s1) % 65521;
    }
    z.extend_from_slice(&(s2 << 16 | s1).to_be_bytes());
    let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
    let mut chunk = |kind: &[u8], data: &[u8]| {
        png.extend_from_slice(&(data.len() as u32).to_be_bytes());
        let mut body = kind.to_vec();
        body.extend_from_slice(data);
        png.extend_from_slice(&body);
        png.extend_from_slice(&crc32(&body).to_be_bytes());
    };
    chunk(b"IHDR", &[0, 0, 0, 2, 0, 0, 0, 1, 8, 2, 0, 0, 0]);
    chunk(b"IDAT", &z);
    chunk(b"IEND", &[]);
    let img = decode_png(&png).unwrap();
    assert_eq!((img.width, img.height), (2, 1));
    assert_eq!(img.rgb, vec![255, 0, 0, 0, 0, 255]);
    // A flipped bit is caught by the CRC.
    let mut bad = png.clone();
    bad[40] ^= 1;
    assert!(decode_png(&bad).is_err());
    // The CRC of "IEND" is the well-known AE 42 60 82.
    assert_eq!(crc32(b"IEND"), 0xAE42_6082);
}

/// A file that cannot be written is `PlotError::Io` naming that file (a directory stands where
/// the PNG should go), not a backend's debug dump; the SVG beside it is still written.
#[test]
fn an_unwritable_file_is_io_with_its_path() {
    let dir = out_dir("figures-unwritable");
    let blocked = dir.join("lloyd2006-fig5.png");
    std::fs::create_dir_all(&blocked).unwrap();
    match render("lloyd2006-fig5", &dir, Format::Png) {
        Err(PlotError::Io { path, .. }) => assert_eq!(path, blocked),
        other => panic!("{other:?}"),
    }
    let files = render("lloyd2006-fig5", &dir, Format::Svg).unwrap();
    assert_eq!(files, vec![dir.join("lloyd2006-fig5.svg")]);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Where a figure deliberately departs from the paper, its caption says so (issue 25): the
/// departures as the papers show them (Barroso & Celes' Fig 5 panels are perpendicular and
/// parallel light; Zhang et al.'s rows have scene insets); martin-tan-fig3, whose B is the
/// paper's smallest (rotated) box, says it is as in the paper (the fifth review: "Unlike the
/// paper, B may be rotated" contradicted the paper's §3 and §5).
#[test]
fn captions_say_where_a_figure_differs_from_the_paper() {
    let dir = out_dir("figures-differ");
    // barroso-fig5 now draws the paper's panels (a) and (b); its panel (c) is marked.
    let says = [
        ("barroso-fig5", "(e) Eq 19, not in the paper"),
        ("zhang-fig3", "scene insets"),
    ];
    let mut names: Vec<&str> = says.iter().map(|(n, _)| *n).collect();
    names.push("martin-tan-fig3");
    render_all(&dir, Format::Svg, &names, |_| {}).unwrap();
    let svg = std::fs::read_to_string(dir.join("martin-tan-fig3.svg")).unwrap();
    let caption: String = texts(&svg)
        .iter()
        .map(|(_, c)| visible(c))
        .collect::<Vec<_>>()
        .join(" ");
    assert!(!caption.contains("Unlike the paper"), "{caption}");
    assert!(
        caption.contains("As in the paper (§3, §5), B is the smallest (rotated) box"),
        "{caption}"
    );
    for (name, phrase) in says {
        let svg = std::fs::read_to_string(dir.join(format!("{name}.svg"))).unwrap();
        let caption: String = texts(&svg)
            .iter()
            .map(|(_, c)| visible(c))
            .collect::<Vec<_>>()
            .join(" ");
        if name == "barroso-fig5" {
            for panel in ["(a) light ⊥ view", "(c) light ∥ view"] {
                assert!(caption.contains(panel), "{name}: no {panel:?}");
            }
        } else {
            assert!(caption.contains("Unlike the paper"), "{name}");
        }
        assert!(caption.contains(phrase), "{name}: no {phrase:?}");
    }
}

/// Geometric diagrams have equal aspect (issue 25: lloyd2006-fig11 was stretched 1.27×,
/// lloyd2006-fig4 1.16×), measured on shapes that are squares in the data: lloyd2006-fig11's
/// partition maps (each the square of its far plane, seen from a light behind the viewer) and
/// lloyd2006-fig4's shadow-map outline [−1, 1]².
#[test]
fn geometric_diagrams_have_equal_aspect() {
    let dir = out_dir("figures-aspect");
    render_all(
        &dir,
        Format::Svg,
        &["lloyd2006-fig11", "lloyd2006-fig4"],
        |_| {},
    )
    .unwrap();
    let attr = |tag: &str, name: &str| -> f64 {
        let at = tag.find(&format!(" {name}=\"")).unwrap() + name.len() + 3;
        tag[at..at + tag[at..].find('"').unwrap()].parse().unwrap()
    };
    let svg = std::fs::read_to_string(dir.join("lloyd2006-fig11.svg")).unwrap();
    // Each map's outline: the box round the dashes of its colour drawn 3 or more units wide (the
    // key's samples, under the plot, left out; the maps are unfilled since the fifth review, and
    // lines 5 wide or light bands 9 wide under the frustum's since the seventh, R7-X-3).
    let key_top = svg
        .find("Maps, nearest first:")
        .and_then(|i| svg[..i].rfind("<text "))
        .map(|i| attr(&svg[i..], "y"))
        .unwrap();
    let mut boxes: std::collections::BTreeMap<String, [f64; 4]> = Default::default();
    for line in svg.lines().filter(|l| l.starts_with("<polyline")) {
        let stroke = line
            .split("stroke=\"")
            .nth(1)
            .map(|r| &r[..7])
            .unwrap_or("");
        let width: f64 = line
            .split("stroke-width=\"")
            .nth(1)
            .and_then(|r| r[..r.find('"')?].parse().ok())
            .unwrap_or(0.0);
        if width < 3.0 || stroke == "#000000" {
            continue;
        }
        let pts = line.split("points=\"").nth(1).unwrap();
        for p in pts[..pts.find('"').unwrap()].split_whitespace() {
            let (x, y) = p.split_once(',').unwrap();
            let (x, y): (f64, f64) = (x.parse().unwrap(), y.parse().unwrap());
            if y >= key_top - 10.0 {
                continue;
            }
            let b = boxes.entry(stroke.to_string()).or_insert([
                f64::INFINITY,
                f64::INFINITY,
                f64::NEG_INFINITY,
                f64::NEG_INFINITY,
            ]);
            *b = [b[0].min(x), b[1].min(y), b[2].max(x), b[3].max(y)];
        }
    }
    let maps: Vec<(f64, f64)> = boxes.values().map(|b| (b[2] - b[0], b[3] - b[1])).collect();
    assert_eq!(maps.len(), 3, "three partition maps");
    for (w, h) in maps {
        // Each side is rounded to the unit: a 47-unit square may read 47 × 48.
        assert!(
            (w / h - 1.0).abs() < 0.02 || (w - h).abs() <= 1.0,
            "lloyd2006-fig11: a square map drawn {w} × {h}"
        );
    }
    let svg = std::fs::read_to_string(dir.join("lloyd2006-fig4.svg")).unwrap();
    let mut squares = 0;
    for t in svg.split("<polyline ").skip(1) {
        let pts = figures_style_read::points(t);
        // The map's outline: a closed axis-aligned rectangle of five points.
        let rect = pts.len() == 5
            && pts[0] == pts[4]
            && pts[0].1 == pts[1].1
            && pts[1].0 == pts[2].0
            && pts[2].1 == pts[3].1
            && pts[3].0 == pts[0].0;
        if rect {
            let (w, h) = ((pts[1].0 - pts[0].0).abs(), (pts[2].1 - pts[1].1).abs());
            assert!(
                (w / h - 1.0).abs() < 0.02,
                "lloyd2006-fig4: the map drawn {w} × {h}"
            );
            squares += 1;
        }
    }
    assert_eq!(squares, 4, "one map outline per column");
}

/// The SVGs of the figures `names`, rendered into a fresh directory `sub`.
fn svgs(sub: &str, names: &[&'static str]) -> Vec<(&'static str, String)> {
    let dir = out_dir(sub);
    render_all(&dir, Format::Svg, names, |_| {}).unwrap();
    names
        .iter()
        .map(|n| {
            (
                *n,
                std::fs::read_to_string(dir.join(format!("{n}.svg"))).unwrap(),
            )
        })
        .collect()
}

/// A number attribute of an element's attributes (`x="12.5"`).
fn attr_num(attrs: &str, name: &str) -> Option<f64> {
    let key = format!(" {name}=\"");
    let at = format!(" {attrs}").find(&key)? + key.len() - 1;
    let rest = &attrs[at..];
    rest[..rest.find('"')?].parse().ok()
}

/// The SVG's elements in order, each its tag and attributes; a text's `tspan`s (a superscript's
/// raised run) are part of the text, not elements after it.
fn elements(svg: &str) -> Vec<(&str, &str)> {
    svg.split('<')
        .skip(1)
        .filter(|e| !e.starts_with('/') && !e.starts_with("tspan"))
        .map(|e| {
            let end = e.find(['>', '/']).unwrap_or(e.len());
            let (tag, attrs) = e[..end].split_once(' ').unwrap_or((&e[..end], ""));
            (tag, attrs)
        })
        .collect()
}

/// Colour-bar tick labels clear the bar (issue 25: they started 4 units right of its edge,
/// after a 2-unit tick mark, and read as touching it): in every heat-map figure each label
/// right of a vertical axis, followed by its tick mark, starts at least 8 units right of the
/// axis.
#[test]
fn colour_bar_labels_clear_the_bar() {
    // zhang-fig3's bars are horizontal: checked in zhang_fig3_landscape_with_bars_under_blocks;
    // martin-tan-fig6's lies across under its disk in two columns (upright beside the disk its
    // name read as one with the profile's y name, review X8).
    let names = ["lloyd2006-fig7"];
    for (name, svg) in svgs("figures-colour-bars", &names) {
        let els = elements(&svg);
        let mut labels = 0;
        for w in els.windows(2) {
            let ((t, text), (p, line)) = (w[0], w[1]);
            let start = text.contains("text-anchor=\"start\"");
            if t != "text" || p != "polyline" || !(start || text.contains("text-anchor=\"end\"")) {
                continue;
            }
            let pts = figures_style_read::points(line);
            let y = attr_num(text, "y").unwrap();
            // A tick mark: short, horizontal, pointing right, at the label's height, the label's
            // anchor right of it (a left axis's labels are left of their ticks).
            if pts.len() == 2
                && attr_num(text, "x").unwrap() > pts[1].0
                && pts[0].1 == y
                && pts[1].1 == y
                && (1.0..=8.0).contains(&(pts[1].0 - pts[0].0))
            {
                // The label's left edge: its x, or for a right-aligned label (plotters aligns
                // some by their right edge) its x less its width, DejaVu Sans' digits being
                // 0.636 em.
                let mut x = attr_num(text, "x").unwrap();
                if !start {
                    let after = &svg[svg.find(text).unwrap() + text.len()..];
                    let content =
                        &after[after.find('>').unwrap() + 1..after.find("</text>").unwrap()];
                    let chars = visible(content).chars().count() as f64;
                    x -= 0.636 * attr_num(text, "font-size").unwrap() * chars;
                }
                assert!(
                    x - pts[0].0 >= 8.0,
                    "{name}: a colour-bar label {} from the bar: {text}",
                    x - pts[0].0
                );
                labels += 1;
            }
        }
        assert!(labels >= 2, "{name}: {labels} colour-bar labels found");
    }
}

/// zhang-fig3 (issue 25): landscape, the three quantity blocks side by side (the page was
/// 520 × 1900, 1 : 3.65, the blocks stacked), each quantity's colour bar under its own block
/// (centred under the block's title; the bars once sat beside the blocks of light angles θ),
/// its tick labels clear of the bar (their tops at least 8 units below it), the panels to scale
/// (the frustum's outline 99 across and 2 · 100 tan 30° = 115.47 up), and the z tick labels of a
/// row apart (they read "80100"): between neighbouring labels at least 3 units, with DejaVu
/// Sans' digit width (0.636 em).
#[test]
fn zhang_fig3_landscape_with_bars_under_blocks() {
    let dir = out_dir("figures-zhang");
    render_all(&dir, Format::Svg, &["zhang-fig3"], |_| {}).unwrap();
    let svg = std::fs::read_to_string(dir.join("zhang-fig3.svg")).unwrap();
    let all = texts(&svg);
    let view = view_box(svg.as_str());
    assert!(
        view[2] / view[3] >= 0.85,
        "zhang-fig3 is {} × {}",
        view[2],
        view[3]
    );
    let at = |pred: &dyn Fn(&str, &str) -> bool| -> Vec<(f64, f64)> {
        all.iter()
            .filter(|(a, c)| pred(a, &visible(c)))
            .map(|(a, _)| (attr_num(a, "x").unwrap(), attr_num(a, "y").unwrap()))
            .collect()
    };
    let quantities = ["Ep", "Eq", "Ep × Eq"];
    let mut blocks = Vec::new();
    for (k, q) in quantities.iter().enumerate() {
        let block = at(&|_, v| {
            v.starts_with(&format!("({}) {q}", ['a', 'b', 'c'][k])) && (k == 2 || !v.contains('×'))
        });
        let bar = at(&|a, v| !a.contains("rotate(") && v == format!("{q} (log scale)"));
        assert_eq!((block.len(), bar.len()), (1, 1), "{q}: {block:?} {bar:?}");
        assert!(
            (block[0].0 - bar[0].0).abs() < 40.0 && bar[0].1 > block[0].1,
            "{q}: {block:?} {bar:?}"
        );
        blocks.push(block[0]);
    }
    assert!(
        blocks
            .windows(2)
            .all(|w| w[1].0 > w[0].0 + 100.0 && (w[1].1 - w[0].1).abs() < 1.0),
        "{blocks:?}"
    );
    // The bars' outlines (dark grey, unfilled) and the tick labels under them.
    let els = elements(&svg);
    let bars: Vec<(f64, f64, f64)> = els
        .iter()
        .filter(|(t, a)| *t == "rect" && a.contains("fill=\"none\" stroke=\"#3C3C3C\""))
        .map(|(_, a)| {
            let n = |k: &str| attr_num(a, k).unwrap();
            (n("x"), n("x") + n("width"), n("y") + n("height"))
        })
        .collect();
    assert_eq!(bars.len(), 3, "{bars:?}");
    for (x0, x1, bottom) in &bars {
        let labels: Vec<f64> = all
            .iter()
            .filter(|(a, _)| a.contains("dy=\"0.76em\"") && a.contains("text-anchor=\"middle\""))
            .map(|(a, _)| (attr_num(a, "x").unwrap(), attr_num(a, "y").unwrap()))
            .filter(|(x, y)| x >= x0 && x <= x1 && *y > *bottom && *y < bottom + 30.0)
            .map(|p| p.1)
            .collect();
        assert!(labels.len() >= 3, "{labels:?}");
        assert!(
            labels.iter().all(|y| y - bottom >= 8.0),
            "{labels:?} under {bottom}"
        );
    }
    // The panels to scale: each frustum outline (five points, closed) 99 : 115.47.
    let mut frusta = 0;
    for (t, a) in &els {
        if *t != "polyline" || !a.contains("stroke=\"#282828\"") {
            continue;
        }
        let pts = figures_style_read::points(a);
        let xs = pts.iter().map(|p| p.0);
        let ys = pts.iter().map(|p| p.1);
        let w = xs.clone().fold(f64::MIN, f64::max) - xs.fold(f64::MAX, f64::min);
        let h = ys.clone().fold(f64::MIN, f64::max) - ys.fold(f64::MAX, f64::min);
        let want = 99.0 / (200.0 * 30f64.to_radians().tan());
        assert!(
            (w / h / want - 1.0).abs() < 0.04,
            "a frustum drawn {w} × {h}"
        );
        frusta += 1;
    }
    assert_eq!(frusta, 27);
    let all = texts(&svg);
    // The z labels: numbers centred under the panels, grouped by row.
    let mut rows: std::collections::BTreeMap<i64, Vec<(f64, f64)>> = Default::default();
    for (a, c) in &all {
        let v = visible(c);
        if a.contains("text-anchor=\"middle\"")
            && !a.contains("rotate(")
            && v.parse::<f64>().is_ok()
        {
            let half = 0.5 * 0.636 * attr_num(a, "font-size").unwrap() * v.chars().count() as f64;
            let x = attr_num(a, "x").unwrap();
            rows.entry(attr_num(a, "y").unwrap().round() as i64)
                .or_default()
                .push((x - half, x + half));
        }
    }
    assert!(rows.values().map(Vec::len).sum::<usize>() >= 9, "{rows:?}");
    for labels in rows.values_mut() {
        labels.sort_by(|a, b| a.0.total_cmp(&b.0));
        for w in labels.windows(2) {
            assert!(
                w[1].0 - w[0].1 >= 3.0,
                "z labels {:?} and {:?} run together",
                w[0],
                w[1]
            );
        }
    }
}

/// The storage factor's unit is texels per image pixel (issue 25: figs 10 and 12 wrote
/// "texels per image pixel²"; S̄ = M_x M_z is a ratio of texel counts per pixel).
#[test]
fn storage_factor_is_in_texels_per_image_pixel() {
    let names = ["lloyd2006-fig7", "lloyd2006-fig10", "lloyd2006-fig12"];
    for (name, svg) in svgs("figures-units", &names) {
        let all: Vec<String> = texts(&svg).iter().map(|(_, c)| visible(c)).collect();
        assert!(
            all.iter().any(|t| t.contains("(texels per image pixel")),
            "{name}: no axis in texels per image pixel"
        );
        // A superscript ² is written as a raised plain digit (a `<tspan>`), so the visible
        // text reads "pixel2".
        assert!(
            !all.iter()
                .any(|t| t.contains("pixel²") || t.contains("pixel2")),
            "{name}: per pixel²"
        );
    }
}

/// lloyd2005-fig4 labels each curve directly at its right end (issue 25: direct labels instead
/// of a legend over the curves), right-aligned, with the minus sign U+2212 in ξ = −½ and −1.
#[test]
fn lloyd2005_fig4_labels_its_curves_directly() {
    let dir = out_dir("figures-direct");
    render_all(&dir, Format::Svg, &["lloyd2005-fig4"], |_| {}).unwrap();
    let svg = std::fs::read_to_string(dir.join("lloyd2005-fig4.svg")).unwrap();
    let all = texts(&svg);
    for label in [
        "n′ = 1 (ξ = 1, PSM)",
        "n′ = 1.613 (ξ = ½)",
        "n′ = 4.162 (ξ = 0, LiSPSM)",
        "n′ = 17.325 (ξ = \u{2212}½)",
        "n′ = ∞ (ξ = \u{2212}1, uniform)",
    ] {
        let (attrs, _) = all
            .iter()
            .find(|(_, c)| visible(c) == label)
            .unwrap_or_else(|| panic!("no label {label:?}"));
        assert!(attrs.contains("text-anchor=\"end\""), "{label}: {attrs}");
    }
}

/// An SVG's view box: x, y, width, height.
fn view_box(svg: &str) -> Vec<f64> {
    svg.split("viewBox=\"")
        .nth(1)
        .unwrap()
        .split('"')
        .next()
        .unwrap()
        .split(' ')
        .map(|v| v.parse().unwrap())
        .collect()
}

/// A text's box in SVG units (x0, y0, x1, y1) from its anchor, baseline shift and size, with
/// DejaVu Sans' advances (digits 0.636 em, a space 0.318 em, other characters about 0.6 em) and
/// the line from 0.76 em above the baseline to 0.24 em below it.
fn text_box(attrs: &str, content: &str) -> (f64, f64, f64, f64) {
    let fs = attr_num(attrs, "font-size").unwrap();
    let (x, y) = (attr_num(attrs, "x").unwrap(), attr_num(attrs, "y").unwrap());
    let base = y + match attrs
        .split("dy=\"")
        .nth(1)
        .and_then(|v| v.split('"').next())
    {
        Some("0.76em") => 0.76 * fs,
        Some("0.5ex") => 0.27 * fs,
        Some("-0.5ex") => -0.27 * fs,
        other => panic!("unknown baseline shift {other:?}"),
    };
    let w: f64 = content
        .chars()
        .map(|c| match c {
            '0'..='9' => 0.636,
            // A space is half a digit (651 against 1303 font units).
            ' ' => 0.636 / 2.0,
            _ => 0.6,
        })
        .sum::<f64>()
        * fs;
    let x0 = if attrs.contains("text-anchor=\"middle\"") {
        x - w / 2.0
    } else if attrs.contains("text-anchor=\"end\"") {
        x - w
    } else {
        x
    };
    (x0, base - 0.76 * fs, x0 + w, base + 0.24 * fs)
}

/// Every straight piece of line an SVG draws: its polylines' segments and its lines.
fn line_segments(svg: &str) -> Vec<((f64, f64), (f64, f64))> {
    let mut out = Vec::new();
    for (tag, attrs) in elements(svg) {
        if tag == "polyline" {
            let pts = figures_style_read::points(attrs);
            out.extend(pts.windows(2).map(|w| (w[0], w[1])));
        } else if tag == "line" {
            let n = |k: &str| attr_num(attrs, k).unwrap();
            out.push(((n("x1"), n("y1")), (n("x2"), n("y2"))));
        }
    }
    out
}

/// Whether the segment meets the box (Liang–Barsky clipping).
fn crosses(((x1, y1), (x2, y2)): ((f64, f64), (f64, f64)), b: (f64, f64, f64, f64)) -> bool {
    let (dx, dy) = (x2 - x1, y2 - y1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-dx, x1 - b.0),
        (dx, b.2 - x1),
        (-dy, y1 - b.1),
        (dy, b.3 - y1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else if p < 0.0 {
            t0 = t0.max(q / p);
        } else {
            t1 = t1.min(q / p);
        }
    }
    t0 <= t1
}

/// The boxes of the texts of `svg` that read as one of `labels` (not rotated), with the text;
/// with `left_aligned`, only those anchored at their start (not the axes' tick labels, which
/// are centred or right-aligned).
fn label_boxes(
    svg: &str,
    labels: &[&str],
    left_aligned: bool,
) -> Vec<(String, (f64, f64, f64, f64))> {
    texts(svg)
        .into_iter()
        .filter(|(a, _)| !a.contains("rotate("))
        .filter(|(a, _)| !left_aligned || a.contains("text-anchor=\"start\""))
        .filter_map(|(a, c)| {
            let v = visible(c);
            labels
                .contains(&v.trim())
                .then(|| (v.trim().to_string(), text_box(a, &v)))
        })
        .collect()
}

/// Issue 25: labels cover no line and no other label. lloyd2006-fig11's plane and dimension
/// labels (2n tan θ sat on the nearest map's outline and the frustum's edges, the planes'
/// labels on the edges at the sections' corners), barroso-fig5's plane labels (on the maps'
/// outlines), and martin-tan-fig3's legend entries (drawn over panel (a), the axis-aligned
/// box's dotted outline ran under them).
#[test]
fn labels_cover_no_line_and_no_label() {
    let cases: [(&str, &[&str]); 3] = [
        (
            "lloyd2006-fig11",
            &["n = 1", "z = 2", "z = 4", "f = 8", "2n tan θ", "2f tan θ"],
        ),
        (
            "barroso-fig5",
            &[
                "z = 31.62",
                "z = 10",
                "z = 3.162",
                "z = 40.81",
                "z = 16.13",
                "z = 6.041",
                "n = 1",
                "f = 100",
            ],
        ),
        (
            "martin-tan-fig3",
            &[
                "frustum E",
                "hull C",
                "focus region",
                "trapezoid T",
                "min-area box B",
                "axis-aligned box",
            ],
        ),
    ];
    let names: Vec<&'static str> = cases.iter().map(|c| c.0).collect();
    for ((name, svg), (_, labels)) in svgs("figures-label-lines", &names).iter().zip(cases) {
        // barroso-fig5's labels are numbers: only the left-aligned ones, not the tick labels.
        let boxes = label_boxes(svg, labels, *name == "barroso-fig5");
        assert!(boxes.len() >= labels.len(), "{name}: {boxes:?}");
        let segments = line_segments(svg);
        for (text, b) in &boxes {
            for s in &segments {
                assert!(
                    !crosses(*s, *b),
                    "{name}: {text:?} at {b:?} covers the line {s:?}"
                );
            }
        }
        for (i, (t, a)) in boxes.iter().enumerate() {
            for (u, b) in &boxes[i + 1..] {
                let apart = a.2 <= b.0 || b.2 <= a.0 || a.3 <= b.1 || b.3 <= a.1;
                assert!(apart, "{name}: {t:?} {a:?} overlaps {u:?} {b:?}");
            }
        }
    }
}

/// Issue 25: lloyd2005-fig8's 2048 × 2048 texture is drawn square (it was 1.46 : 1): the
/// partitions' outlined rectangles tile a region as wide as it is high.
#[test]
fn lloyd2005_fig8_texture_is_square() {
    let (_, svg) = &svgs("figures-fig8", &["lloyd2005-fig8"])[0];
    let rects: Vec<(f64, f64, f64, f64)> = elements(svg)
        .into_iter()
        .filter(|(t, a)| *t == "rect" && a.contains("fill=\"none\" stroke=\"#000000\""))
        .map(|(_, a)| {
            let n = |k: &str| attr_num(a, k).unwrap();
            (n("x"), n("y"), n("x") + n("width"), n("y") + n("height"))
        })
        .collect();
    assert!(rects.len() >= 7, "{rects:?}");
    let x0 = rects.iter().map(|r| r.0).fold(f64::INFINITY, f64::min);
    let y0 = rects.iter().map(|r| r.1).fold(f64::INFINITY, f64::min);
    let x1 = rects.iter().map(|r| r.2).fold(f64::NEG_INFINITY, f64::max);
    let y1 = rects.iter().map(|r| r.3).fold(f64::NEG_INFINITY, f64::max);
    let ratio = (x1 - x0) / (y1 - y0);
    assert!((ratio - 1.0).abs() < 0.01, "the texture drawn {ratio} : 1");
}

/// Issue 25: no ASCII hyphen-minus stands for a minus sign ("η = -0.6" in lloyd2006-fig4): in
/// these figures no text has a hyphen-minus before a digit; and barroso-fig5's panel titles
/// carry one letter each (its zoom was titled "(d) (a) …").
#[test]
fn minus_signs_and_panel_letters() {
    let names = [
        "lloyd2005-fig8",
        "lloyd2006-fig4",
        "martin-tan-fig3",
        "lloyd2006-fig11",
        "barroso-fig5",
        "barroso-fig7",
        "zhang-fig3",
    ];
    for (name, svg) in svgs("figures-minus", &names) {
        for (_, c) in texts(&svg) {
            let v = visible(c);
            let chars: Vec<char> = v.chars().collect();
            assert!(
                !chars
                    .windows(2)
                    .any(|w| w[0] == '-' && w[1].is_ascii_digit()),
                "{name}: {v:?} has a hyphen-minus for a minus sign"
            );
        }
        if name == "barroso-fig5" {
            let titles: Vec<String> = texts(&svg)
                .iter()
                .map(|(_, c)| visible(c))
                .filter(|v| v.starts_with('('))
                .collect();
            for letter in ["(a)", "(b)", "(c)", "(d)"] {
                let n = titles.iter().filter(|t| t.starts_with(letter)).count();
                assert_eq!(n, 1, "{letter}: {titles:?}");
            }
            assert!(titles.iter().all(|t| !t.contains(") (")), "{titles:?}");
        }
    }
}

/// Issue 25: lloyd2006-fig4 in two rows of four (the paper's arrangement; it was four rows of
/// two, 520 × 1560): the four maps' square outlines side by side in one row, the page no taller
/// than 1.2 times its width.
#[test]
fn lloyd2006_fig4_two_rows_of_four() {
    let (_, svg) = &svgs("figures-fig4", &["lloyd2006-fig4"])[0];
    let view = view_box(svg.as_str());
    assert!(view[3] <= 1.2 * view[2], "{view:?}");
    let mut tops = Vec::new();
    for t in svg.split("<polyline ").skip(1) {
        let pts = figures_style_read::points(t);
        let square = pts.len() == 5
            && pts[0] == pts[4]
            && pts[0].1 == pts[1].1
            && pts[1].0 == pts[2].0
            && (pts[1].0 - pts[0].0).abs() > 40.0;
        if square {
            tops.push((pts[0].0.min(pts[1].0), pts[0].1.min(pts[2].1)));
        }
    }
    assert_eq!(tops.len(), 4, "{tops:?}");
    assert!(
        tops.iter().all(|t| (t.1 - tops[0].1).abs() < 1.0),
        "{tops:?}"
    );
    assert!(tops.windows(2).all(|w| w[1].0 > w[0].0 + 40.0), "{tops:?}");
}

/// WCAG 2's contrast of an sRGB colour `#RRGGBB` against white: (1.05)/(L + 0.05), L the
/// relative luminance 0.2126 R + 0.7152 G + 0.0722 B of the linearised channels.
fn contrast_on_white(hex: &str) -> f64 {
    let ch = |i: usize| {
        let v = f64::from(u8::from_str_radix(&hex[i..i + 2], 16).unwrap()) / 255.0;
        if v <= 0.04045 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    let l = 0.2126 * ch(1) + 0.7152 * ch(3) + 0.0722 * ch(5);
    1.05 / (l + 0.05)
}

/// Every text of a figure has at least WCAG AA's 4.5 : 1 against white (issue 35: direct labels
/// in #E69F00 and #56B4E9 had 2.2–2.3 : 1): its fill, the page's or a label's white box behind it.
fn check_text_contrast(svg: &str, name: &str) {
    let mut texts = 0;
    for tag in svg.split("<text ").skip(1) {
        let tag = &tag[..tag.find('>').unwrap()];
        let at = tag.find(" fill=\"#").map(|i| i + " fill=\"".len());
        let fill = &tag[at.unwrap_or_else(|| panic!("{name}: a text without a fill"))..][..7];
        let c = contrast_on_white(fill);
        assert!(c >= 4.5, "{name}: text in {fill} has {c:.2} : 1 on white");
        texts += 1;
    }
    assert!(texts > 0, "{name}: no text");
}

#[test]
fn contrast_is_measured_as_wcag_defines_it() {
    // Black on white is 21 : 1; #767676 is the lightest grey with 4.5 : 1; the review's
    // #E69F00 and #56B4E9 are 2.2–2.3 : 1.
    assert!((contrast_on_white("#000000") - 21.0).abs() < 1e-9);
    assert!((contrast_on_white("#767676") - 4.54).abs() < 0.01);
    assert!((contrast_on_white("#E69F00") - 2.25).abs() < 0.01);
    assert!((contrast_on_white("#56B4E9") - 2.31).abs() < 0.01);
}
