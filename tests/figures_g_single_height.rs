//! A one-column figure leaves room for text on its page: printed at one column's width (240 pt,
//! 3.3 in) every figure of `--column single` is at most 420 pt (5.8 in) tall with its title and
//! caption, about two thirds of a journal's 650-pt text column. (The third figure review found
//! eleven of the seventeen 576–640 pt tall: a whole column, with no room for a line of text or a
//! float separator.) The printed size is read from the SVG's own `width` and `height` in points,
//! as a typesetter places it.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::{attr_str, render_svg};
use shadow_aliasing::plot::{Column, Options, SINGLE_COLUMN};

/// The tallest a one-column figure may print, in points.
const MAX_HEIGHT_PT: f64 = 420.0;
/// One column's width, in points (3.3 in).
const COLUMN_PT: f64 = 240.0;

/// The SVG's printed `width` and `height`, in points.
fn printed(svg: &str) -> (f64, f64) {
    let head = &svg[..svg.find('>').unwrap()];
    let pt = |name: &str| -> f64 {
        attr_str(head, name)
            .unwrap_or_else(|| panic!("no {name} on the <svg> element"))
            .trim_end_matches("pt")
            .parse()
            .unwrap()
    };
    (pt("width"), pt("height"))
}

#[test]
fn every_one_column_figure_prints_at_most_420_pt_tall() {
    let opts = Options {
        column: Column::Single,
        ..Options::default()
    };
    let mut over = Vec::new();
    for name in SINGLE_COLUMN {
        let (w, h) = printed(&render_svg(name, &opts));
        assert!(
            (w - COLUMN_PT).abs() < 0.5,
            "{name}: prints {w} pt wide, not one column's {COLUMN_PT}"
        );
        if h > MAX_HEIGHT_PT {
            over.push(format!("{name}: {h:.0} pt"));
        }
    }
    assert!(
        over.is_empty(),
        "one-column figures taller than {MAX_HEIGHT_PT} pt: {}",
        over.join(", ")
    );
}

#[test]
fn every_figure_has_a_one_column_layout() {
    // The height rule above covers every figure only if every figure has a one-column form.
    for name in shadow_aliasing::plot::FIGURES {
        assert!(
            SINGLE_COLUMN.contains(name),
            "{name} has no one-column layout"
        );
    }
}
