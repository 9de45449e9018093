//! The page: title on top, the caption naming the paper and figure at the bottom, and the
//! common page of line charts side by side.

use super::super::{Column, Fail};
use super::line::{draw_line_chart_over, draw_line_chart_reserving, legend_below, LineChart};
use super::FONT;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::cell::Cell;

thread_local! {
    /// Whether the figure being drawn on this thread is bare (see [`with_page`]).
    static BARE: Cell<bool> = const { Cell::new(false) };
    /// The box a bare page keeps (see [`bare_crop`]), set by [`set_bare_crop`].
    static CROP: Cell<Option<Crop>> = const { Cell::new(None) };
    /// The width the figure being drawn on this thread is laid out for (see [`with_page`]).
    static COLUMN: Cell<Column> = const { Cell::new(Column::Double) };
}

/// A box of the page `[left, top, right, bottom)`, in units.
pub(crate) type Crop = [u32; 4];

/// The white a bare page keeps around its ink on each of its four sides, in units (at least
/// this, less than one unit more: the crop is whole units). It was 6 units above the body and
/// the page's full width (the sixth figure review, R6-X-7: about 14 pt of white above the panel
/// titles and the full left margin); 2 below since text at the body's bottom edge (a colour bar's
/// or an axis's name) kept as little as 0.3 units of white under it; 3 since the ninth and
/// eleventh reviews (R9-X-5, R11-X-6: a text's box, ascenders included, lay 1 pt or less from
/// the crop, too tight for typesetting).
pub(crate) const BARE_PAD: u32 = 3;

/// A pixel darker than this in any channel is ink (the page is white, 255).
const INK_BELOW: u8 = 250;

/// Runs `draw` with every page it draws bare (no title, no caption) or not, and laid out for
/// `column`: the page options of `Options::bare` and `Options::column`, set for the one figure
/// being drawn on this thread and restored afterwards.
pub(crate) fn with_page<R>(bare: bool, column: Column, draw: impl FnOnce() -> R) -> R {
    let before = BARE.with(|b| b.replace(bare));
    let crop = CROP.with(|r| r.replace(None));
    let col = COLUMN.with(|c| c.replace(column));
    let out = draw();
    BARE.with(|b| b.set(before));
    CROP.with(|r| r.set(crop));
    COLUMN.with(|c| c.set(col));
    out
}

/// The width the figure drawn on this thread is laid out for (see [`with_page`]).
pub(crate) fn column() -> Column {
    COLUMN.with(Cell::get)
}

/// The box of the page that the figure drawn on this thread in [`with_page`] keeps: for a bare
/// page, its ink with [`BARE_PAD`] units of white on each side (see [`ink_crop`]); `None` for a
/// captioned page (all of it is kept).
pub(crate) fn bare_crop() -> Option<Crop> {
    CROP.with(Cell::get)
}

/// Sets the box [`bare_crop`] returns until [`with_page`] returns.
pub(crate) fn set_bare_crop(crop: Option<Crop>) {
    CROP.with(|r| r.set(crop));
}

/// The box a bare page of `page` units keeps, from its drawing `rgb` at `k` pixels a unit (RGB
/// rows of `k` × the page's width): the bounding box of its ink (pixels darker than white),
/// widened to whole units and by [`BARE_PAD`] on each side, inside the page; `None` for a page
/// without ink.
pub(crate) fn ink_crop(rgb: &[u8], k: u32, (w, h): (u32, u32)) -> Option<Crop> {
    let pw = (w * k) as usize;
    let ink = |p: &[u8]| p.iter().any(|&c| c < INK_BELOW);
    let (mut x0, mut y0, mut x1, mut y1) = (usize::MAX, usize::MAX, 0, 0);
    for (y, row) in rgb.chunks_exact(pw * 3).enumerate() {
        for (x, p) in row.chunks_exact(3).enumerate() {
            if ink(p) {
                (x0, y0) = (x0.min(x), y0.min(y));
                (x1, y1) = (x1.max(x + 1), y1.max(y + 1));
            }
        }
    }
    if x0 == usize::MAX {
        return None;
    }
    let k = k as usize;
    let unit = |v: usize| u32::try_from(v).unwrap_or(u32::MAX);
    let (l, t) = (unit(x0 / k), unit(y0 / k));
    let (r, b) = (unit(x1.div_ceil(k)), unit(y1.div_ceil(k)));
    Some([
        l.saturating_sub(BARE_PAD),
        t.saturating_sub(BARE_PAD),
        (r + BARE_PAD).min(w),
        (b + BARE_PAD).min(h),
    ])
}

/// Fills the page white, writes the title at the top and the caption (its lines joined into one
/// paragraph, wrapped to the page width) at the bottom, and returns the area left between them.
/// A bare page (see [`with_page`]) is laid out the same, with the same area returned, but the
/// title and caption are not drawn (and the page is cropped to its ink, [`bare_crop`]).
pub(crate) fn frame<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    title: &str,
    caption: &[&str],
) -> Result<DrawingArea<DB, Shift>, Fail> {
    root.fill(&WHITE)?;
    let bare = BARE.with(Cell::get);
    let (w, h) = root.dim_in_pixel();
    let width = f64::from(w) - 28.0;
    // The title, wrapped to the page like the caption; one column sets it smaller, so that a
    // title of up to about 36 characters keeps one line.
    let (title_size, title_line) = title_size(column());
    let title_style =
        TextStyle::from((FONT, title_size).into_font()).pos(Pos::new(HPos::Center, VPos::Top));
    let title_lines = wrap(title, width, |t| {
        root.estimate_text_size(t, &title_style)
            .map(|(tw, _)| f64::from(tw))
            .unwrap_or(f64::INFINITY)
    });
    let top = 20 + title_line * title_lines.len() as u32;
    let line_h = 18;
    let style = TextStyle::from((FONT, 14).into_font());
    // The caption is one paragraph, wrapped to the page.
    let lines = wrap(&caption.join(" "), width, |t| {
        root.estimate_text_size(t, &style)
            .map(|(tw, _)| f64::from(tw))
            .unwrap_or(f64::INFINITY)
    });
    let bottom = lines.len() as i32 * line_h + 10;
    let body = root.margin(top, bottom as u32, 6, 6);
    if bare {
        return Ok(body);
    }
    for (k, line) in title_lines.iter().enumerate() {
        root.draw(&Text::new(
            line.clone(),
            (w as i32 / 2, 8 + (title_line * k as u32) as i32),
            title_style.clone(),
        ))?;
    }
    for (k, line) in lines.iter().enumerate() {
        root.draw(&Text::new(
            line.clone(),
            // 7 units under the body: a bar over the first line's S̄ rises above its text box.
            (14, h as i32 - bottom + 7 + k as i32 * line_h),
            style
                .color(&RGBColor(50, 50, 50))
                .pos(Pos::new(HPos::Left, VPos::Top)),
        ))?;
    }
    Ok(body)
}

/// The page title's size (plotters' size: the SVG's `font-size` is s/1.24) and line height, in
/// units: 20 across two columns (16.1 units, printed 16.1 pt); 16 in one column (12.9 units,
/// printed 10.3 pt at 0.8 pt a unit: above the panel titles' 9.7 pt and the ticks' 8.4 pt,
/// where 20 printed 12.9 pt and wrapped every title of the set).
pub(crate) fn title_size(column: Column) -> (u32, u32) {
    match column {
        Column::Double => (20, 24),
        Column::Single => (16, 19),
    }
}

/// Breaks `text` at spaces into lines no wider than `width` (as measured by `measure`); a single
/// word wider than the page keeps a line of its own.
pub(crate) fn wrap(text: &str, width: f64, measure: impl Fn(&str) -> f64) -> Vec<String> {
    let mut lines = Vec::new();
    let mut cur = String::new();
    for word in text.split(' ') {
        let candidate = if cur.is_empty() {
            word.to_string()
        } else {
            format!("{cur} {word}")
        };
        if !cur.is_empty() && measure(&candidate) > width {
            lines.push(std::mem::replace(&mut cur, word.to_string()));
        } else {
            cur = candidate;
        }
    }
    if !cur.is_empty() || lines.is_empty() {
        lines.push(cur);
    }
    lines
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

    /// One column: the charts stacked, 290 units each, under a title and caption of up to
    /// 220 units, at most 800 units (640 points) tall.
    fn single_size(&self) -> Option<(u32, u32)> {
        let n = self.charts.len().max(1) as u32;
        Some((Column::Single.width(), (220 + 290 * n).min(800)))
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let caption: Vec<&str> = self.caption.iter().map(String::as_str).collect();
        let body = frame(root, &self.title, &caption)?;
        // Side by side where each chart gets at least 250 units of width (a pair on a
        // double-column page), stacked otherwise (a single-column page).
        let n = self.charts.len().max(1);
        let (w, h) = body.dim_in_pixel();
        let columns = (w as usize / 250).clamp(1, n);
        let rows: Vec<&[LineChart]> = self.charts.chunks(columns).collect();
        // Each row is one plot height and the strip its legend needs below it, the plot height
        // the same for every row: stacked panels of the same kind get equal plots (split evenly,
        // a row whose legend goes below had a plot shorter by the legend).
        let even = (w, h / rows.len().max(1) as u32);
        let strips = rows
            .iter()
            .map(|charts| row_strip(even, charts, columns))
            .collect::<Result<Vec<_>, _>>()?;
        let plot = h.saturating_sub(strips.iter().sum::<u32>()) / rows.len().max(1) as u32;
        let mut rest = body;
        for (charts, strip) in rows.iter().zip(&strips) {
            let (row, below) = rest.split_vertically(plot + strip);
            match charts {
                // One panel a row: its legend's strip as measured at the even height, kept
                // even where the taller row would let the legend inside (so that the plots
                // stay equal).
                [chart] if rows.len() > 1 => {
                    draw_line_chart_reserving(&row, chart, *strip)?;
                }
                _ => draw_row(&row, charts, columns)?,
            }
            rest = below;
        }
        Ok(())
    }
}

/// The height a row of `charts`, `columns` wide, on an area of `size` keeps below its plots for
/// legends that find no clear place inside (as [`draw_row`] lays it out): 0 where every legend
/// goes inside.
fn row_strip(size: (u32, u32), charts: &[LineChart], columns: usize) -> Result<u32, Fail> {
    let (w, h) = size;
    let cell = (w / columns as u32, h);
    let mut keep = 0;
    for c in charts {
        keep = keep.max(legend_below(cell, c, f64::from(w))?);
    }
    Ok(keep)
}

/// Draws `charts` side by side in `row`, `columns` wide. A legend that finds no clear place in
/// its plot goes below: where one chart of the row needs that, a strip under the whole row
/// holds it (a legend shared by the panels is centred under them all); where several do, each
/// panel keeps the same height under its own plot, so that the plots line up.
fn draw_row<DB: DrawingBackend>(
    row: &DrawingArea<DB, Shift>,
    charts: &[LineChart],
    columns: usize,
) -> Result<(), Fail> {
    let (w, h) = row.dim_in_pixel();
    let cell = (w / columns as u32, h);
    let across = charts
        .iter()
        .map(|c| legend_below(cell, c, f64::from(w)))
        .collect::<Result<Vec<_>, _>>()?;
    let keep = across.iter().copied().max().unwrap_or(0);
    // One legend below, and still one once the plots are shorter by the strip.
    let one = keep > 0 && {
        let shorter = (cell.0, h.saturating_sub(keep));
        let mut needing = 0;
        for c in charts {
            needing += usize::from(legend_below(shorter, c, f64::from(w))? > 0);
        }
        needing == 1
    };
    if one {
        let (top, strip) = row.split_vertically(h.saturating_sub(keep));
        let panels = top.split_evenly((1, columns));
        for (panel, chart) in panels.iter().zip(charts) {
            draw_line_chart_over(panel, chart, Some(&strip))?;
        }
        return Ok(());
    }
    let own = charts
        .iter()
        .map(|c| legend_below(cell, c, f64::from(cell.0)))
        .collect::<Result<Vec<_>, _>>()?;
    let keep = own.iter().copied().max().unwrap_or(0);
    for (panel, chart) in row.split_evenly((1, columns)).iter().zip(charts) {
        draw_line_chart_reserving(panel, chart, keep)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A page title of 36 characters ("Storage factor against the map count") keeps one line
    /// on a one-column page (300 units, 272 for the text), at `font-size` 16/1.24 = 12.90 units,
    /// printed 12.90 · 0.8 = 10.3 pt (≥ 6 pt); at the two-column size (20: 16.13 units, 36
    /// characters of about 0.55 em = 319 units) it took two lines. Two columns keep 16.13.
    #[test]
    fn a_one_column_title_of_36_characters_keeps_one_line() {
        super::super::super::ensure_font().unwrap();
        let title = "Storage factor against the map count";
        let page = |column: Column| {
            let mut svg = String::new();
            with_page(false, column, || {
                let area = super::super::super::svg::Svg::new(&mut svg, (column.width(), 400), 1)
                    .into_drawing_area();
                frame(&area, title, &["c"]).unwrap();
                area.present().unwrap();
            });
            svg
        };
        let single = page(Column::Single);
        let line = single
            .lines()
            .find(|l| l.ends_with(&format!(">{title}</text>")))
            .unwrap_or_else(|| panic!("the title wraps: {single}"));
        let at = line.find("font-size=\"").unwrap() + "font-size=\"".len();
        let fs: f64 = line[at..at + line[at..].find('"').unwrap()]
            .parse()
            .unwrap();
        assert!((fs - 12.9).abs() < 0.01 && fs * 0.8 >= 6.0, "{fs}");
        let double = page(Column::Double);
        assert!(double.contains(&format!(">{title}</text>")), "{double}");
        assert!(double.contains("font-size=\"16.1"), "{double}");
    }

    /// Two stacked panels in one column, (a) with a legend that finds no clear place inside
    /// its plot (ten labelled lines across the whole plot) and so goes below it, (b) with none:
    /// their y axes (the vertical black spines in the SVG) are equally long, to within 2 units.
    /// Split evenly, (a)'s plot was shorter by its legend (the review: lloyd2006-fig5(a) 62 pt
    /// against (b)'s 162 pt).
    #[test]
    fn stacked_panels_get_equal_plots_whatever_their_legends() {
        use super::super::super::Figure;
        use super::super::{Axis, Series, PALETTE};
        super::super::super::ensure_font().unwrap();
        let line = |y: f64| {
            (0..=20)
                .map(|i| (f64::from(i) / 20.0, y))
                .collect::<Vec<_>>()
        };
        let mut a = LineChart::new(
            "(a)",
            Axis::linear("x", 0.0, 1.0),
            Axis::linear("y", 0.0, 1.0),
        );
        for k in 0..10 {
            let y = 0.05 + 0.1 * f64::from(k);
            let colour = PALETTE[k as usize % PALETTE.len()];
            a.series
                .push(Series::line(format!("a long legend entry {k}"), line(y), colour).dashed());
        }
        let mut b = LineChart::new(
            "(b)",
            Axis::linear("x", 0.0, 1.0),
            Axis::linear("y", 0.0, 1.0),
        );
        let mut only = Series::line("", line(0.5), PALETTE[0]);
        only.label = None;
        b.series.push(only);
        let page = Charts {
            size: (520, 400),
            title: "t".into(),
            caption: vec!["c".into()],
            charts: vec![a, b],
        };
        let size = page.single_size().unwrap();
        let mut svg = String::new();
        with_page(false, Column::Single, || {
            let area = super::super::super::svg::Svg::new(&mut svg, size, 1).into_drawing_area();
            page.draw(&area).unwrap();
            area.present().unwrap();
        });
        let spines: Vec<f64> = svg
            .lines()
            .filter(|l| l.starts_with("<polyline") && l.contains("stroke=\"#000000\""))
            .filter_map(|l| {
                let pts = crate::plot::chart::read_svg::points(l)?;
                match pts[..] {
                    [(x0, y0), (x1, y1)] if x0 == x1 && (y1 - y0).abs() > 50.0 => {
                        Some((y1 - y0).abs())
                    }
                    _ => None,
                }
            })
            .collect();
        assert_eq!(spines.len(), 2, "{spines:?}");
        assert!((spines[0] - spines[1]).abs() <= 2.0, "{spines:?}");
        // (a)'s legend did go below its plot: a legend box lies under (a)'s spine.
        assert!(svg.contains("opacity=\"0.9\""), "no legend");
    }

    #[test]
    fn captions_wrap_at_spaces_within_the_width() {
        // One unit per character: "aaa bb" is 6 wide.
        let m = |t: &str| t.chars().count() as f64;
        assert_eq!(wrap("aaa bb cc d", 6.0, m), vec!["aaa bb", "cc d"]);
        assert_eq!(wrap("short", 60.0, m), vec!["short"]);
        assert_eq!(wrap("toolongword x", 4.0, m), vec!["toolongword", "x"]);
    }
}
