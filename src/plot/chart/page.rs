//! The page: title on top, the caption naming the paper and figure at the bottom, and the
//! common page of line charts side by side.

use super::super::Fail;
use super::line::{draw_line_chart, LineChart};
use super::FONT;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Fills the page white, writes the title at the top and the caption lines at the bottom, and
/// returns the area left between them.
pub(crate) fn frame<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    title: &str,
    caption: &[&str],
) -> Result<DrawingArea<DB, Shift>, Fail> {
    root.fill(&WHITE)?;
    let (w, h) = root.dim_in_pixel();
    root.draw(&Text::new(
        title.to_string(),
        (w as i32 / 2, 10),
        TextStyle::from((FONT, 22).into_font()).pos(Pos::new(HPos::Center, VPos::Top)),
    ))?;
    let line_h = 18;
    let bottom = caption.len() as i32 * line_h + 10;
    for (k, line) in caption.iter().enumerate() {
        // Shrink a long line until it fits the page width.
        let mut size = 14.0;
        while size > 9.0 {
            let (tw, _) =
                root.estimate_text_size(line, &TextStyle::from((FONT, size).into_font()))?;
            if tw as f64 <= f64::from(w) - 28.0 {
                break;
            }
            size -= 0.5;
        }
        root.draw(&Text::new(
            (*line).to_string(),
            (14, h as i32 - bottom + 4 + k as i32 * line_h),
            TextStyle::from((FONT, size).into_font())
                .color(&RGBColor(50, 50, 50))
                .pos(Pos::new(HPos::Left, VPos::Top)),
        ))?;
    }
    Ok(root.margin(44, bottom, 6, 6))
}

/// A page of line charts side by side: the common shape of the closed-form figures.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Charts {
    pub size: (u32, u32),
    pub title: String,
    pub caption: Vec<String>,
    pub charts: Vec<LineChart>,
}

impl super::super::Figure for Charts {
    fn size(&self) -> (u32, u32) {
        self.size
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let caption: Vec<&str> = self.caption.iter().map(String::as_str).collect();
        let body = frame(root, &self.title, &caption)?;
        let panels = body.split_evenly((1, self.charts.len().max(1)));
        for (panel, chart) in panels.iter().zip(&self.charts) {
            draw_line_chart(panel, chart)?;
        }
        Ok(())
    }
}
