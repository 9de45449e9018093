//! One type scale across the two-column figures (the eighth figure review, R8-X-3): zhang-fig3's
//! block titles "(a) E_p = 2 m_z" … and lloyd2005-fig8's table title "(d) Eq 6's shares …"
//! were set at 10.5 pt where every other panel title is 12.1, and lloyd2005-fig8's axis names
//! "light-view x/y" at 10.5 where lloyd2006-fig11, martin-tan-fig3 and barroso-fig5 set the
//! same names at 12.1. Read from the SVGs: each size is compared with the size another figure
//! gives the same kind of text, not with a constant of the crate.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::*;

/// The upright texts of figure `name` (two columns, captioned) whose content is `content`, or
/// starts with it where `prefix`.
fn sizes(name: &str, content: &str, prefix: bool) -> Vec<f64> {
    let font = Font::dejavu();
    let (_, _, svg) = all_svgs()
        .iter()
        .find(|(n, layout, _)| n == name && layout == "Double")
        .unwrap_or_else(|| panic!("no two-column {name}"));
    texts(&font, svg)
        .into_iter()
        .filter(|t| {
            if prefix {
                t.content.starts_with(content)
            } else {
                t.content == content
            }
        })
        .map(|t| t.fs)
        .collect()
}

/// The one size of the texts `content` in `name`, asserting there is at least one and one size.
fn one_size(name: &str, content: &str, prefix: bool) -> f64 {
    let all = sizes(name, content, prefix);
    assert!(!all.is_empty(), "{name}: no text {content:?}");
    let first = all[0];
    assert!(
        all.iter().all(|s| (s - first).abs() < 1e-3),
        "{name}: {content:?} at sizes {all:?}"
    );
    first
}

#[test]
fn panel_titles_share_one_size_with_the_other_figures() {
    // The reference: the panel titles of a line chart and of a diagram.
    let reference = one_size("lloyd2006-fig12", "(b) ", true);
    for (name, title) in [
        ("zhang-fig3", "(a) E"),
        ("zhang-fig3", "(b) E"),
        ("zhang-fig3", "(c) E"),
        ("lloyd2005-fig8", "(a) from the light"),
        ("lloyd2005-fig8", "(d) Eq 6"),
    ] {
        let size = one_size(name, title, true);
        assert!(
            (size - reference).abs() < 1e-3,
            "{name}: {title:?} at {size}, lloyd2006-fig12's (b) at {reference}"
        );
    }
}

#[test]
fn light_view_axis_names_share_one_size() {
    let reference = one_size("lloyd2006-fig11", "light-view x", false);
    for name in ["lloyd2005-fig8", "martin-tan-fig3", "barroso-fig5"] {
        for axis in ["light-view x", "light-view y"] {
            let size = one_size(name, axis, false);
            assert!(
                (size - reference).abs() < 1e-3,
                "{name}: {axis:?} at {size}, lloyd2006-fig11's at {reference}"
            );
        }
    }
}
