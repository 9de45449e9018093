//! Figure layout (issue 25, second review; issue 35): martin-tan-fig3's panels (b) and (c) one
//! above the other right of (a), not a 1 : 2.8 strip; lloyd2006-fig4's top row names its axis "eye x" like
//! "depth z". Checked on the SVGs as written.
#![cfg(feature = "plot")]

use shadow_aliasing::plot::{render, Format};

fn svg(name: &str) -> String {
    // One folder per call: two tests rendering the same figure at once must not share it.
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!(
        "figures-layout-{}-{call}-{name}",
        std::process::id()
    ));
    std::fs::create_dir_all(&dir).unwrap();
    let files = render(name, &dir, Format::Svg).unwrap();
    let text = std::fs::read_to_string(&files[0]).unwrap();
    std::fs::remove_dir_all(&dir).ok();
    text
}

/// The number of the attribute `name` (a length's unit `pt` dropped).
fn attr(text: &str, name: &str) -> f64 {
    let key = format!(" {name}=\"");
    let at = text.find(&key).unwrap() + key.len();
    text[at..at + text[at..].find('"').unwrap()]
        .trim_end_matches("pt")
        .parse()
        .unwrap()
}

/// Two square panels side by side are each half the width, so the figure is at most about
/// (a) plus half its width tall: height ≤ 2.3 × width (it was 1460/520 = 2.8).
#[test]
fn martin_tan_fig3_is_not_a_tall_strip() {
    let s = svg("martin-tan-fig3");
    let (w, h) = (attr(&s, "width"), attr(&s, "height"));
    assert!(h / w <= 2.3, "{w} × {h}");
}

/// The (x, y) of the `<text>` element whose content starts with `label`.
fn text_position(svg: &str, label: &str) -> (f64, f64) {
    let at = svg
        .find(&format!(">{label}"))
        .unwrap_or_else(|| panic!("no text {label:?}"));
    let open = svg[..at].rfind("<text").expect("a <text> element");
    let tag = &svg[open..at];
    (attr(tag, "x"), attr(tag, "y"))
}

/// Panels (b) and (c) of martin-tan-fig3 are one column right of (a) (issue 35: under (a), the
/// figure was 960 units tall): their titles start within 40 units of each other across, (c)'s
/// below (b)'s, both at least a third of the figure's width right of (a)'s, and (a)'s title level
/// with (b)'s.
#[test]
fn martin_tan_fig3_panels_b_and_c_are_right_of_a() {
    let s = svg("martin-tan-fig3");
    let w = attr(&s, "width");
    let (a, b, c) = (
        text_position(&s, "(a)"),
        text_position(&s, "(b)"),
        text_position(&s, "(c)"),
    );
    assert!(
        (b.0 - c.0).abs() <= 40.0,
        "(b) at {b:?}, (c) at {c:?}: not one column"
    );
    assert!(c.1 > b.1, "(c) at {c:?} is not under (b) at {b:?}");
    assert!(
        b.0 - a.0 >= w / 3.0 && c.0 - a.0 >= w / 3.0,
        "(a) at {a:?}, (b) at {b:?}, (c) at {c:?}: not right of (a)"
    );
    assert_eq!(a.1, b.1, "(a) at {a:?}, (b) at {b:?}: not level");
}

#[test]
fn lloyd2006_fig4_names_the_eyes_x_axis() {
    let s = svg("lloyd2006-fig4");
    assert!(s.contains(">eye x</text>"), "no \"eye x\" axis label");
    assert!(!s.contains(">x</text>"), "a bare \"x\" axis label remains");
}
