//! The sixth figure review's remaining items on barroso-fig5 and lloyd2006-fig7, read back
//! from the rendered SVGs:
//! - lloyd2006-fig7 (R6-lloyd2006-fig7-2): panel (a) (no warping, S̄ from 8.65×10⁵ to 2.0×10⁶)
//!   was one flat green under the shared 10²–10⁷ bar; it now carries dashed contour lines at
//!   10⁶ and 1.5×10⁶, each labelled inside the disk, in the two-column and bare forms;
//! - barroso-fig5 (R6-barroso-fig5-4): the far face's thick edge is named in the overview (e)
//!   as in its detail (f), in the two-column and bare forms.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read as read;
use figures_style_read::forms;
use shadow_aliasing::plot::{render_with, Format, Options};
use std::path::Path;

fn svg(name: &str, form: &str, opts: &Options) -> String {
    // A directory of its own for each call: tests run in parallel.
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "figures-p2b-{name}-{form}-{}-{call}",
        std::process::id()
    ));
    let files = render_with(name, &dir, Format::Svg, opts).unwrap();
    let s = std::fs::read_to_string(&files[0]).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    s
}

/// The opening tags of one kind of element.
fn elements<'a>(svg: &'a str, kind: &str) -> Vec<&'a str> {
    svg.split('<')
        .filter(|e| e.starts_with(kind))
        .map(|e| &e[..e.find('>').unwrap_or(e.len())])
        .collect()
}

/// The points of the polylines of one stroke colour and width.
fn strokes(svg: &str, colour: &str, width: &str) -> Vec<Vec<(f64, f64)>> {
    elements(svg, "polyline")
        .into_iter()
        .filter(|e| {
            read::attr_str(e, "stroke") == Some(colour)
                && read::attr_str(e, "stroke-width") == Some(width)
        })
        .map(read::points)
        .collect()
}

/// lloyd2006-fig7 (R6-lloyd2006-fig7-2), two columns and bare: (a)'s disk (the largest ring,
/// #1E1E1E, left of x = 173 and above y = 270: the first of three disks across 520 units, in
/// the first of two rows) holds dashed black
/// contour lines 2 units wide, at least 100 dashes, every point within the disk (half a line
/// width outside the horizon at most), and none in any other panel; their labels "10⁶" and
/// "1.5×10⁶" (a `<tspan>` superscript 6, read "106" and "1.5×106") are set at 10.5 units, black,
/// their centres at most 0.85 of the radius from the disk's centre. The old figure drew no
/// line 2 units wide and no such label.
#[test]
fn fig7_a_has_labelled_contours_inside_its_disk() {
    let font = read::Font::dejavu();
    for (form, opts) in forms().into_iter().take(2) {
        let s = svg("lloyd2006-fig7", form, &opts);
        let rings: Vec<[f64; 4]> = strokes(&s, "#1E1E1E", "1")
            .iter()
            .map(|p| read::bbox(p))
            .filter(|b| b[2] < 173.0 && b[3] < 270.0)
            .collect();
        let horizon = rings
            .iter()
            .copied()
            .max_by(|a, b| (a[2] - a[0]).total_cmp(&(b[2] - b[0])))
            .unwrap_or_else(|| panic!("{form}: no ring in (a)"));
        let (cx, cy) = (
            0.5 * (horizon[0] + horizon[2]),
            0.5 * (horizon[1] + horizon[3]),
        );
        let r = 0.5 * (horizon[2] - horizon[0]);
        assert!(r > 40.0, "{form}: (a)'s radius {r}");
        let dashes = strokes(&s, "#000000", "2");
        let in_a: Vec<&Vec<(f64, f64)>> = dashes
            .iter()
            .filter(|p| p.iter().all(|q| q.0 < 173.0))
            .collect();
        assert!(in_a.len() >= 100, "{form}: {} dashes in (a)", in_a.len());
        for p in &in_a {
            for q in p.iter() {
                let d = (q.0 - cx).hypot(q.1 - cy);
                assert!(
                    d <= r + 1.0,
                    "{form}: a contour at {q:?}, {d} from the centre"
                );
            }
        }
        // The other panels' dashes: barroso-style 2-unit black lines are the contours only.
        assert_eq!(in_a.len(), dashes.len(), "{form}: contours outside (a)");
        let texts = read::texts(&font, &s);
        for want in ["10", "1.5×10"] {
            let t = texts
                .iter()
                .find(|t| t.content == format!("{want}6") && t.x < 173.0)
                .unwrap_or_else(|| panic!("{form}: no contour label {want}⁶ in (a)"));
            assert!(
                (t.fs - 13.0 / 1.24).abs() < 0.01,
                "{form}: {want}⁶ at {}",
                t.fs
            );
            assert_eq!(read::attr_str(&t.tag, "fill"), Some("#000000"), "{form}");
            let d = (t.x - cx).hypot(t.y - cy);
            assert!(
                d <= 0.85 * r,
                "{form}: {want}⁶ {d} from the centre, radius {r}"
            );
        }
    }
}

/// barroso-fig5 (R6-barroso-fig5-4), two columns and bare: "far face" is written twice, once
/// in the left column's gutter (the overview (e), left of the page's middle, 260 units) and
/// once in the right's ((f)); both in the bottom row, below every "f = 100" but the last
/// (the overviews (a), (c) label f = 100 above it). The old figure named it in (f) only.
#[test]
fn barroso_far_face_named_in_e_and_f() {
    let font = read::Font::dejavu();
    for (form, opts) in forms().into_iter().take(2) {
        let s = svg("barroso-fig5", form, &opts);
        let texts = read::texts(&font, &s);
        let far: Vec<&read::Text> = texts.iter().filter(|t| t.content == "far face").collect();
        assert_eq!(far.len(), 2, "{form}: {} far face labels", far.len());
        assert!(far.iter().any(|t| t.x < 260.0), "{form}: none in (e)");
        assert!(far.iter().any(|t| t.x > 260.0), "{form}: none in (f)");
        let f100: Vec<f64> = texts
            .iter()
            .filter(|t| t.content == "f = 100")
            .map(|t| t.y)
            .collect();
        assert_eq!(f100.len(), 3, "{form}: {f100:?}");
        let e_label = far.iter().find(|t| t.x < 260.0).unwrap();
        let mut ys = f100.clone();
        ys.sort_by(f64::total_cmp);
        assert!(
            e_label.y > ys[2],
            "{form}: (e)'s far face at {} above (e)'s f = 100 at {}",
            e_label.y,
            ys[2]
        );
    }
}
