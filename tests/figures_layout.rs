//! Figure layout (issue 25, second review): martin-tan-fig3's panels (b) and (c) side by side
//! under (a), not a 1 : 2.8 strip; lloyd2006-fig4's top row names its axis "eye x" like
//! "depth z". Checked on the SVGs as written.
#![cfg(feature = "plot")]

use shadow_aliasing::plot::{render, Format};

fn svg(name: &str) -> String {
    let dir = std::env::temp_dir().join(format!("figures-r2-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let files = render(name, &dir, Format::Svg).unwrap();
    let text = std::fs::read_to_string(&files[0]).unwrap();
    std::fs::remove_dir_all(&dir).ok();
    text
}

fn attr(text: &str, name: &str) -> f64 {
    let key = format!(" {name}=\"");
    let at = text.find(&key).unwrap() + key.len();
    text[at..at + text[at..].find('"').unwrap()]
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

#[test]
fn lloyd2006_fig4_names_the_eyes_x_axis() {
    let s = svg("lloyd2006-fig4");
    assert!(s.contains(">eye x</text>"), "no \"eye x\" axis label");
    assert!(!s.contains(">x</text>"), "a bare \"x\" axis label remains");
}
