//! `shadow-aliasing figures`: the real binary writes the files issue 4 names, as valid,
//! non-trivial PNG and SVG images, with a one-line summary; bad arguments are one line and a
//! non-zero exit.
#![cfg(feature = "cli")]

// The file names issue 4 fixes, so that links and scripts can rely on them: the library's list,
// which tests/figures.rs (`the_figure_list_is_the_issue_list`) pins name by name.
use shadow_aliasing::plot::{FIGURES, SINGLE_COLUMN};
use std::path::{Path, PathBuf};

mod common;
use common::cli::{help, run, run_failing};

/// `figures --out <out>` followed by `extra`; returns (exit code, stdout, stderr).
fn figures(out: &Path, extra: &[&str]) -> (i32, String, String) {
    let mut args = vec!["figures", "--out", out.to_str().unwrap()];
    args.extend_from_slice(extra);
    run(&args)
}

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("sa-cli-figures-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

/// A PNG: signature, an IHDR chunk of a plausible size, an IEND chunk, and more than a few
/// kilobytes (a blank image of that size compresses to far less).
fn check_png(path: &Path) {
    let b = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert_eq!(&b[..8], b"\x89PNG\r\n\x1a\n", "{}", path.display());
    assert_eq!(&b[12..16], b"IHDR");
    let w = u32::from_be_bytes(b[16..20].try_into().unwrap());
    let h = u32::from_be_bytes(b[20..24].try_into().unwrap());
    assert!(w >= 300 && h >= 200, "{}: {w}×{h}", path.display());
    assert_eq!(&b[b.len() - 8..b.len() - 4], b"IEND");
    assert!(
        b.len() > 8_000,
        "{}: only {} bytes",
        path.display(),
        b.len()
    );
}

/// An SVG: an `<svg` root closed at the end, with text (titles and labels) and drawn shapes.
fn check_svg(path: &Path) {
    let s = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert!(s.contains("<svg"), "{}", path.display());
    assert!(s.trim_end().ends_with("</svg>"), "{}", path.display());
    assert!(s.contains("<text"), "{}: no text", path.display());
    let shapes = [
        "<path",
        "<polyline",
        "<rect",
        "<line",
        "<circle",
        "<polygon",
    ]
    .iter()
    .map(|t| s.matches(t).count())
    .sum::<usize>();
    assert!(shapes > 20, "{}: {shapes} shapes", path.display());
}

#[test]
fn only_and_format_select_the_files() {
    let dir = temp_dir("only");
    let (code, out, err) = figures(
        &dir,
        &["--format", "svg", "--only", "zhang-fig3", "barroso-fig7"],
    );
    assert_eq!(code, 0, "{err}");
    let mut files: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    files.sort();
    assert_eq!(files, ["barroso-fig7.svg", "zhang-fig3.svg"]);
    for f in &files {
        check_svg(&dir.join(f));
    }
    // One summary line: files written and time; no progress bar when stderr is not a terminal.
    assert_eq!(out.lines().count(), 1, "{out}");
    assert!(out.contains("2 files"), "{out}");
    assert!(err.is_empty(), "{err}");
    let (code, _, err) = figures(&dir, &["--format", "png", "--only", "barroso-fig7"]);
    assert_eq!(code, 0, "{err}");
    check_png(&dir.join("barroso-fig7.png"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `--format pdf` (issue 25): with the feature `pdf`, one vector PDF per figure with its font
/// embedded; without it, one line naming the feature and a non-zero exit, and no file.
#[test]
fn format_pdf_writes_pdfs_or_names_the_feature() {
    let dir = temp_dir("pdf");
    let (code, out, err) = figures(&dir, &["--format", "pdf", "--only", "lloyd2006-fig6"]);
    let pdf = dir.join("lloyd2006-fig6.pdf");
    if cfg!(feature = "pdf") {
        assert_eq!(code, 0, "{err}");
        assert!(out.contains("1 files"), "{out}");
        let b = std::fs::read(&pdf).unwrap();
        assert!(b.starts_with(b"%PDF-"));
        let text = String::from_utf8_lossy(&b);
        assert!(text.contains("/FontFile2") || text.contains("/FontFile3"));
        assert!(b.len() > 10_000, "{} bytes", b.len());
    } else {
        assert_ne!(code, 0);
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        assert!(
            err.contains("feature `pdf`") && err.contains("--features"),
            "{err}"
        );
        assert!(!pdf.exists());
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_arguments_are_one_line_and_a_non_zero_exit() {
    let dir = temp_dir("bad");
    let d = dir.to_str().unwrap();
    for (args, needle) in [
        (
            vec!["figures", "--out", d, "--only", "lloyd2006-fig99"],
            "lloyd2006-fig99",
        ),
        (vec!["figures", "--out", d, "--format", "gif"], "--format"),
        (vec!["figures", "--out", "/dev/null/x"], "/dev/null/x"),
    ] {
        let (_, err) = run_failing(&args, "");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn every_figure_in_both_formats() {
    let dir = temp_dir("all");
    let (code, out, err) = figures(&dir, &[]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("34 files"), "{out}");
    for name in FIGURES {
        check_png(&dir.join(format!("{name}.png")));
        check_svg(&dir.join(format!("{name}.svg")));
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn help_has_an_example_and_the_names() {
    let out = help("figures");
    assert!(out.contains("shadow-aliasing figures --out"), "{out}");
    for name in FIGURES {
        assert!(out.contains(name), "{name} not in --help");
    }
}

#[test]
fn an_unwritable_file_is_named_with_the_os_error() {
    // The directory exists but the file cannot be created: here a directory stands where the
    // image should go. plotters used to answer a debug dump without the path.
    for (format, ext) in [("png", "png"), ("svg", "svg")] {
        let dir = temp_dir(&format!("blocked-{format}"));
        let blocked = dir.join(format!("zhang-fig3.{ext}"));
        std::fs::create_dir_all(&blocked).unwrap();
        let (code, out, err) = figures(&dir, &["--only", "zhang-fig3", "--format", format]);
        assert_eq!(code, 1, "{err}");
        assert!(out.is_empty(), "{out}");
        let want = format!("error: cannot write {}: ", blocked.display());
        assert!(err.starts_with(&want), "{err}");
        assert!(
            err.trim_end().ends_with(")") && err.contains("os error"),
            "{err}"
        );
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(!err.contains("Os {"), "{err}");
        let _ = std::fs::remove_dir_all(&dir);
    }
    // A path under a regular file.
    let dir = temp_dir("under-file");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("plain");
    std::fs::write(&file, b"x").unwrap();
    let under = file.join("figures");
    let (code, _, err) = figures(&under, &["--only", "zhang-fig3"]);
    assert_eq!(code, 1, "{err}");
    assert!(
        err.starts_with(&format!("error: cannot write {}: ", under.display()))
            && err.contains("os error"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
    // Issue 21 item 4: an existing file as --out is "not a directory", not "File exists".
    let dir = temp_dir("out-is-a-file");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("plain");
    std::fs::write(&file, b"x").unwrap();
    let (code, out, err) = figures(&file, &["--only", "zhang-fig3"]);
    assert_eq!((code, out.as_str()), (1, ""), "{err}");
    assert_eq!(
        err,
        format!(
            "error: out {} is not a directory but an existing file: give --out a directory \
             (created when missing)\n",
            file.display()
        )
    );
    assert_eq!(std::fs::read(&file).unwrap(), b"x");
    let _ = std::fs::remove_dir_all(&dir);
    // procfs accepts no new files, even from root.
    if Path::new("/proc/self").is_dir() {
        let (code, _, err) = figures(Path::new("/proc"), &["--only", "zhang-fig3"]);
        assert_eq!(code, 1, "{err}");
        assert!(
            err.starts_with("error: cannot write /proc/zhang-fig3.png: ")
                && err.contains("os error"),
            "{err}"
        );
    }
}

/// The `pHYs` chunk of a PNG: (pixels per unit x, y, unit), if present.
fn phys(png: &[u8]) -> Option<(u32, u32, u8)> {
    let mut at = 8;
    while at + 8 <= png.len() {
        let len = u32::from_be_bytes(png[at..at + 4].try_into().unwrap()) as usize;
        let kind = &png[at + 4..at + 8];
        let data = &png[at + 8..at + 8 + len];
        if kind == b"pHYs" {
            let x = u32::from_be_bytes(data[0..4].try_into().unwrap());
            let y = u32::from_be_bytes(data[4..8].try_into().unwrap());
            return Some((x, y, data[8]));
        }
        at += 12 + len;
    }
    None
}

#[test]
fn bare_scale_and_dpi_for_publication() {
    let dir = temp_dir("publication");
    let only = ["--only", "lloyd2006-fig6"];
    let (code, _, err) = figures(&dir, &only);
    assert_eq!(code, 0, "{err}");
    let plain_svg = std::fs::read_to_string(dir.join("lloyd2006-fig6.svg")).unwrap();
    let plain_png = std::fs::read(dir.join("lloyd2006-fig6.png")).unwrap();
    // The title and the caption as src/plot/lloyd2006.rs writes them.
    let title =
        [">Maximum error and storage factor <tspan text-decoration=\"overline\">S</tspan> against η</text>"];
    let caption = "Lloyd et al. 2006, Fig. 6";
    assert!(title.iter().all(|t| plain_svg.contains(t)) && plain_svg.contains(caption));
    // 432 dpi by default (the PNG's 6 pixels per unit over the SVG's 1 unit per point × 72
    // points per inch): 432 / 0.0254 = 17 007.87 → 17 008 pixels per metre.
    assert_eq!(phys(&plain_png), Some((17_008, 17_008, 1)));
    // Tick labels of the η axis (−1 to 1) use the minus sign U+2212, never the hyphen-minus.
    assert!(plain_svg.contains(">−1</text>"), "no −1 tick");
    assert!(plain_svg.contains(">−0.5</text>"), "no −0.5 tick");
    assert!(!plain_svg.contains(">-"), "a hyphen-minus label");

    let (code, _, err) = figures(
        &dir,
        &[&only[..], &["--bare", "--scale", "2", "--dpi", "300"]].concat(),
    );
    assert_eq!(code, 0, "{err}");
    let svg = std::fs::read_to_string(dir.join("lloyd2006-fig6.svg")).unwrap();
    let png = std::fs::read(dir.join("lloyd2006-fig6.png")).unwrap();
    assert!(
        !title.iter().any(|t| svg.contains(t)) && !svg.contains(caption),
        "bare keeps title or caption"
    );
    assert!(svg.contains("M<tspan"), "bare lost the axis labels");
    // The figure is 520 × 490 units, drawn at plot::PNG_ZOOM = 6 pixels per unit: 3120 × 2940.
    // Bare, it is cropped to the box of its ink and 3 units around it (tests/figures_bare.rs): a
    // view box narrower and shorter than the page, which the PNG draws at twice the pixels per
    // unit (scale 2), and 300 dpi = 11 811 pixels per metre.
    let size = |b: &[u8]| {
        (
            u32::from_be_bytes(b[16..20].try_into().unwrap()),
            u32::from_be_bytes(b[20..24].try_into().unwrap()),
        )
    };
    assert_eq!(size(&plain_png), (3120, 2940));
    assert!(plain_svg.contains("viewBox=\"0 0 520 490\""));
    let head = &svg[..svg.find('>').unwrap()];
    let vb_at = head.find("viewBox=\"").unwrap() + "viewBox=\"".len();
    let vb: Vec<u32> = head[vb_at..vb_at + head[vb_at..].find('"').unwrap()]
        .split(' ')
        .map(|v| v.parse().unwrap())
        .collect();
    let (cols, rows) = (vb[2], vb[3]);
    assert!(
        vb[0] > 0 && vb[1] > 0 && vb[0] + cols < 520 && vb[1] + rows < 490,
        "{vb:?}"
    );
    assert!(head.starts_with(&format!(
        "<svg width=\"{}pt\" height=\"{}pt\"",
        2 * cols,
        2 * rows
    )));
    assert_eq!(size(&png), (12 * cols, 12 * rows));
    assert_eq!(phys(&png), Some((11_811, 11_811, 1)));
    check_png(&dir.join("lloyd2006-fig6.png"));

    for (flag, value) in [("--scale", "0"), ("--scale", "9"), ("--dpi", "0")] {
        let d = dir.to_str().unwrap();
        let (_, err) = run_failing(&["figures", "--out", d, flag, value], "");
        assert!(err.contains(&flag[2..]), "{flag} {value}: {err}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `--column single` (issue 35) lays a figure out 300 units wide and prints it 240 points
/// (3.3 inches) wide: the SVG's `width`, and the PNG's 1800 pixels at 540 per inch (21 260 per
/// metre: 540 / 0.0254 = 21 259.8); asked of a figure without a single-column layout, it refuses
/// in one line naming it and writes nothing.
#[test]
fn column_single_is_240_points_wide_or_refused_by_name() {
    let dir = temp_dir("single");
    let (code, _, err) = figures(&dir, &["--only", "lloyd2006-fig5", "--column", "single"]);
    assert_eq!(code, 0, "{err}");
    let svg = std::fs::read_to_string(dir.join("lloyd2006-fig5.svg")).unwrap();
    assert!(svg.starts_with("<svg width=\"240pt\""), "{}", &svg[..80]);
    assert!(svg.contains("viewBox=\"0 0 300 "));
    let png = std::fs::read(dir.join("lloyd2006-fig5.png")).unwrap();
    assert_eq!(u32::from_be_bytes(png[16..20].try_into().unwrap()), 1800);
    assert_eq!(phys(&png), Some((21_260, 21_260, 1)));
    // lloyd2006-fig10 has one (it was refused).
    let (code, _, err) = figures(&dir, &["--only", "lloyd2006-fig10", "--column", "single"]);
    assert_eq!(code, 0, "{err}");
    let svg = std::fs::read_to_string(dir.join("lloyd2006-fig10.svg")).unwrap();
    assert!(svg.contains("viewBox=\"0 0 300 "), "{}", &svg[..80]);
    // So has lloyd2006-fig4 (it was refused): 300 units wide, at most 800 tall (640 pt).
    let (code, _, err) = figures(&dir, &["--only", "lloyd2006-fig4", "--column", "single"]);
    assert_eq!(code, 0, "{err}");
    let svg = std::fs::read_to_string(dir.join("lloyd2006-fig4.svg")).unwrap();
    assert!(svg.contains("viewBox=\"0 0 300 "), "{}", &svg[..80]);
    let key = "viewBox=\"0 0 300 ";
    let height: f64 = svg[svg.find(key).unwrap() + key.len()..]
        .split('"')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(height <= 800.0, "{height}");
    let other = temp_dir("single-refused");
    let d = other.to_str().unwrap();
    // A figure without a one-column layout, while one is left (the list shrinks as figures
    // gain one).
    if let Some(name) = FIGURES.iter().find(|n| !SINGLE_COLUMN.contains(n)) {
        let (_, err) = run_failing(
            &["figures", "--out", d, "--column", "single", "--only", name],
            "",
        );
        assert!(
            err.contains(name) && err.contains("single-column") && err.lines().count() == 1,
            "{err}"
        );
    }
    assert!(std::fs::read_dir(&other).map_or(true, |mut r| r.next().is_none()));
    std::fs::remove_dir_all(&dir).unwrap();
    let _ = std::fs::remove_dir_all(&other);
}
