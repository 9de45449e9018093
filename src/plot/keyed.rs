//! A page of line charts that share one key: the panels side by side (two columns) or stacked
//! (one column), all of the same height, and the key of one panel written once, below them all
//! (lloyd2006-fig5, fig6, fig10, fig12 and worst-case, whose panels draw the same series), or
//! inside its panel where it covers no data. The one-column page may be a page of its own, at
//! most 525 units (420 pt printed) tall: a shorter caption, fewer panels, labels placed for its
//! narrower plots.

use super::chart::{column, draw_line_chart_over, frame, legend_below, Charts};
use super::{Column, Fail, Figure};
use plotters::coord::Shift;
use plotters::prelude::*;

/// Line charts with one key for them all.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Keyed {
    /// The page: size, title, caption and panels.
    pub page: Charts,
    /// The panel whose legend is the figure's key; `None`: no key (the curves are labelled).
    pub key: Option<usize>,
    /// The key goes inside its panel's plot where a place there covers no data (below the
    /// panels otherwise); `false`: always below the panels.
    pub key_inside: bool,
    /// The one-column page, where it is not `page` laid out in one column: its own size (at
    /// most [`SINGLE_HEIGHT`] units tall), caption and panels (fewer, or with labels placed
    /// for its narrower plots).
    pub single: Option<Box<Keyed>>,
}

/// The tallest one-column page, in units: 420 pt printed at one column's 0.8 scale.
pub(crate) const SINGLE_HEIGHT: u32 = 525;

impl Keyed {
    /// A page of `charts` with the key of panel `key`, below the panels, and no one-column
    /// page of its own.
    pub fn new(page: Charts, key: Option<usize>) -> Self {
        Self {
            page,
            key,
            key_inside: false,
            single: None,
        }
    }

    /// Draws this page's panels (not its one-column page).
    fn draw_page<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let caption: Vec<&str> = self.page.caption.iter().map(String::as_str).collect();
        let body = frame(root, &self.page.title, &caption)?;
        let (w, h) = body.dim_in_pixel();
        // Side by side where each panel gets at least 250 units (two columns), else stacked.
        let n = self.page.charts.len().max(1);
        let columns = (w as usize / 250).clamp(1, n);
        let rows = n.div_ceil(columns);
        let charts: Vec<_> = self
            .page
            .charts
            .iter()
            .enumerate()
            .map(|(i, c)| {
                let mut c = c.clone();
                c.show_legend = self.key == Some(i);
                c.legend_below = !self.key_inside;
                c
            })
            .collect();
        let cell = (w / columns as u32, h / rows as u32);
        let strip = match self.key.and_then(|k| charts.get(k)) {
            Some(c) => legend_below(cell, c, f64::from(w))?,
            None => 0,
        };
        let (top, bottom) = body.split_vertically(h.saturating_sub(strip));
        let panels = top.split_evenly((rows, columns));
        for (i, (panel, chart)) in panels.iter().zip(&charts).enumerate() {
            let strip = (self.key == Some(i)).then_some(&bottom);
            draw_line_chart_over(panel, chart, strip)?;
        }
        Ok(())
    }
}

impl Figure for Keyed {
    fn size(&self) -> (u32, u32) {
        self.page.size
    }

    fn single_size(&self) -> Option<(u32, u32)> {
        match &self.single {
            Some(s) => Some(s.page.size),
            None => self.page.single_size(),
        }
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        match (&self.single, column()) {
            (Some(single), Column::Single) => single.draw_page(root),
            _ => self.draw_page(root),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::chart::read_svg::draw_svg;
    use super::super::chart::with_page;
    use super::*;

    /// The lengths of the y axes drawn in an SVG: its vertical black lines longer than 80
    /// units (tick marks are 5).
    fn y_axes(svg: &str) -> Vec<f64> {
        svg.lines()
            .filter(|l| l.starts_with("<polyline") && l.contains("stroke=\"#000000\""))
            .filter_map(|l| {
                let pts = crate::plot::chart::read_svg::points(l)?;
                match pts[..] {
                    [a, b] if a.0 == b.0 && (b.1 - a.1).abs() > 80.0 => Some((b.1 - a.1).abs()),
                    _ => None,
                }
            })
            .collect()
    }

    /// Stacked panels of the same kind get the same plot height in one column (issue 35
    /// review: a legend under the upper panel took its height, lloyd2006-fig5 (a) 62 pt
    /// against 162 pt for (b), worst-case (a) 66 pt): each figure's two y axes, read from its
    /// one-column SVG, differ by at most a unit, and the figure with a key has it once.
    #[test]
    fn stacked_panels_have_equal_plot_heights() {
        let figs: [(&str, Keyed); 4] = [
            ("fig5", super::super::lloyd2006::fig5().ok().unwrap()),
            ("fig10", super::super::lloyd2006::fig10().ok().unwrap()),
            ("fig12", super::super::lloyd2006::fig12().ok().unwrap()),
            ("worst", super::super::worst::worst_case().ok().unwrap()),
        ];
        for (name, fig) in figs {
            let size = fig.single_size().unwrap();
            let svg = with_page(false, Column::Single, || {
                draw_svg(size, |area| fig.draw(area).unwrap())
            });
            // One column keeps fig5's two panels; fig10, fig12 and worst-case keep one.
            let panels = fig.single.as_ref().map_or(2, |s| s.page.charts.len());
            let axes = y_axes(&svg);
            assert_eq!(axes.len(), panels, "{name}: {axes:?}");
            assert!(
                axes.iter().all(|a| (a - axes[0]).abs() <= 1.0),
                "{name}: {axes:?}"
            );
        }
    }
}
