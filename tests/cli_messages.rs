//! The command line's messages (issue 31, defect 5): numbers in docs/cli.md's number format,
//! negative numbers reaching the domain's message, the clipmap's options refused where they are
//! not used, the PDF refusal's install command, and docs/cli.md's count of the planner's
//! candidates.
#![cfg(feature = "cli")]

mod common;
use common::cli::run;

/// Runs `args`, asserts exit status 1 (a value the library refuses) and one line on standard
/// error, and returns that line.
fn refused(args: &[&str]) -> String {
    let (code, out, err) = run(args);
    assert_eq!(code, 1, "{args:?}: {out}{err}");
    assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
    err
}

/// `command` at n = 1, f = 100, θ = 0.5, the light straight down, then `own` and `extra`.
fn with_camera<'a>(command: &'a str, own: [&'a str; 2], extra: &[&'a str]) -> Vec<&'a str> {
    let camera = [
        "--near",
        "1",
        "--far",
        "100",
        "--half-fov",
        "0.5",
        "--light-dir",
        "0,-1,0",
    ];
    let mut v = vec![command];
    v.extend(camera);
    v.extend(own);
    v.extend_from_slice(extra);
    v
}

/// `plan` with H = 1080, then `extra`.
fn plan<'a>(extra: &[&'a str]) -> Vec<&'a str> {
    with_camera("plan", ["--image-height", "1080"], extra)
}

/// `warp`, unwarped, then `extra`.
fn warp<'a>(extra: &[&'a str]) -> Vec<&'a str> {
    with_camera("warp", ["--warp", "uniform"], extra)
}

/// docs/cli.md: numbers in messages are the shortest decimal that round-trips, in exponent form
/// below 10⁻⁵ and from 10¹⁶. The expected strings are written by hand.
#[test]
fn numbers_in_messages_have_the_docs_format() {
    let dir = std::env::temp_dir().join(format!("sa-cli-messages-{}", std::process::id()));
    let out = dir.to_str().unwrap();
    for (args, expected) in [
        (plan(&["--max-error", "1e-20"]), "(got 1e-20 px)"),
        (plan(&["--max-error", "-1e-300"]), "(got -1e-300)"),
        (plan(&["--max-error", "-0.00001"]), "(got -0.00001)"),
        (
            vec!["figures", "--out", out, "--dpi", "1e-300"],
            "dpi 1e-300 is outside",
        ),
        (
            vec!["figures", "--out", out, "--dpi", "1e300"],
            "dpi 1e300 is outside",
        ),
        (
            vec!["figures", "--out", out, "--dpi", "10000.5"],
            "dpi 10000.5 is outside",
        ),
        (
            warp(&["--receivers", "1e300,0,0,0,1,1.00000001"]),
            "(got 1e300,0,0,0,1,1.00000001)",
        ),
        (warp(&["--bevy", "1e-20,0.1,10,150,0.2"]), "(got 1e-20)"),
        (
            warp(&["--partition", "clipmap", "--levels", "6.5,1e20"]),
            "got 6.5,1e20)",
        ),
    ] {
        let err = refused(&args);
        assert!(err.contains(expected), "{args:?}: {err}");
        // No number of more than 24 characters (1e-300 positional has 302).
        let longest = err
            .split(|c: char| !(c.is_ascii_digit() || c == '.'))
            .map(str::len)
            .max()
            .unwrap_or(0);
        assert!(longest <= 24, "{args:?}: {err}");
    }
    assert!(!dir.exists(), "a refused call wrote {}", dir.display());
}

/// docs/cli.md: negative numbers are values wherever a number is expected, so that a value
/// outside its domain gets the domain's message (every option: `args::tests::
/// every_numeric_option_takes_a_negative_number` in the binary's unit tests).
#[test]
fn negative_scale_and_dpi_get_the_domains_message() {
    let dir = std::env::temp_dir().join(format!("sa-cli-negative-{}", std::process::id()));
    let out = dir.to_str().unwrap();
    for (flag, expected) in [
        (
            "--scale",
            "error: invalid option: scale -1 is outside 1..=8: give a whole number",
        ),
        (
            "--dpi",
            "error: invalid option: dpi -1 is outside 1..=10000",
        ),
    ] {
        let err = refused(&["figures", "--out", out, flag, "-1"]);
        assert!(err.starts_with(expected), "{flag}: {err}");
        assert!(!err.contains("unexpected argument"), "{flag}: {err}");
    }
    // Beyond u32 and i64's reach of the old type alike.
    let err = refused(&["figures", "--out", out, "--scale", "-4294967297"]);
    assert!(err.contains("scale -4294967297 is outside 1..=8"), "{err}");
    assert!(!dir.exists(), "a refused call wrote {}", dir.display());
}

/// The clipmap's options (`--lod-bias`, `--levels`, `--page-texels`, `--virtual-resolution`,
/// `--level-unit`, `--image-height`) without `--partition clipmap` are refused by name, valid or
/// not, with the frustum alone, with a scene and with cascades; with `--partition clipmap` the
/// valid values build it.
#[test]
fn clipmap_options_are_refused_without_the_clipmap() {
    let view = [
        "warp",
        "--near",
        "0.1",
        "--far",
        "100",
        "--half-fov",
        "0.5",
        "--light-dir",
        "0.3,-0.8,-0.4",
        "--warp",
        "uniform",
    ];
    let options = [
        ("--lod-bias", "lod_bias", "-1", "nan"),
        ("--levels", "levels", "6,20", "9,6"),
        ("--page-texels", "page_texels", "64", "-3"),
        ("--virtual-resolution", "virtual_resolution", "8192", "1"),
        ("--level-unit", "level_unit", "0.02", "0"),
        ("--image-height", "image_height", "720", "0"),
    ];
    let schemes: [&[&str]; 4] = [
        &[],
        &["--receivers", "-50,-5,-100,50,0,0"],
        &["--partition", "log", "--k", "3"],
        &["--partition", "equal-error", "--k", "2"],
    ];
    for (flag, name, valid, invalid) in options {
        for scheme in schemes {
            for value in [valid, invalid] {
                let mut args = view.to_vec();
                args.extend_from_slice(scheme);
                args.extend([flag, value]);
                let err = refused(&args);
                assert!(
                    err.starts_with(&format!(
                        "error: {name} is only used by --partition clipmap"
                    )),
                    "{args:?}: {err}"
                );
            }
        }
        let mut args = view.to_vec();
        args.extend(["--partition", "clipmap", flag, valid]);
        let (code, _, err) = run(&args);
        assert_eq!(code, 0, "{args:?}: {err}");
    }
}

/// The PDF refusal installs from the clone, as the README does, not from a registry.
#[test]
fn the_pdf_refusal_installs_from_the_clone() {
    let message = shadow_aliasing::plot::PlotError::PdfDisabled.to_string();
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md"))
        .expect("README.md");
    assert!(
        !message.contains("cargo install shadow-aliasing"),
        "{message}"
    );
    // The README's install and in-place commands, with the feature pdf added.
    for readme_form in [
        "cargo install --path . --features cli --locked",
        "cargo run --release --locked --features cli --",
    ] {
        assert!(readme.contains(readme_form), "README: {readme_form}");
        let with_pdf = readme_form.replace("--features cli", "--features cli,pdf");
        assert!(message.contains(&with_pdf), "{message} lacks {with_pdf}");
    }
}

/// docs/cli.md's count of the planner's candidates ("…; N in all", and the example's
/// "candidates (N):") is the library's list's length and what `plan` prints.
#[test]
fn the_docs_count_the_planners_candidates() {
    use glam::{DMat4, DVec3};
    use shadow_aliasing::frame::{Camera, FrameInput};
    use shadow_aliasing::plan::candidates::candidates;
    let md = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/cli.md"))
        .expect("docs/cli.md");
    let number_before = |tail: &str| -> usize {
        let at = md
            .find(tail)
            .unwrap_or_else(|| panic!("docs/cli.md has no {tail:?}"));
        let digits: String = md[..at]
            .chars()
            .rev()
            .take_while(char::is_ascii_digit)
            .collect::<Vec<_>>()
            .into_iter()
            .rev()
            .collect();
        digits
            .parse()
            .unwrap_or_else(|_| panic!("no number before {tail:?}"))
    };
    let in_all = number_before(" in all) is built and measured");
    let listed = number_before("):\n  single uniform");
    let cam = Camera::new(DMat4::IDENTITY, 1.0, 100.0, 0.5, 1.0).unwrap();
    let input = FrameInput::new(cam, DVec3::new(0.0, -1.0, 0.0), 2048, 1080);
    let library = candidates(&input).len();
    let (code, out, err) = run(&plan(&["--max-error", "1"]));
    assert_eq!(code, 0, "{err}");
    let printed = format!("\ncandidates ({library}):\n");
    assert!(out.contains(&printed), "plan prints another count:\n{out}");
    assert_eq!(in_all, library, "docs/cli.md: \"{in_all} in all\"");
    assert_eq!(listed, library, "docs/cli.md: \"candidates ({listed}):\"");
}
