//! lloyd2005-fig8's table (d): per partition its face and depths, M_x, M_z, its Eq 6 share of
//! the texture's width and height, and its error after allocation, each row led by a swatch of
//! the partition's fill and hatch.

use super::hatch::{self, HATCHES};
use super::{Fig8, SIZE};
use crate::plot::chart::{FONT, PANEL_TITLE};
use crate::plot::warp_grid::minus;
use crate::plot::Fail;
use glam::DVec2;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The gap between a row's swatch and its tag (7 units: the tag touched a swatch 4 away).
const SWATCH_GAP: i32 = 7;

/// The gap above the table's first line, under the panels above it.
pub(super) const TABLE_TOP: u32 = 6;

/// Two columns: the room the title "(d) …", at every panel title's size, needs beyond one
/// line step of the table's text (eighth review's check of sizes: it was 10.5 pt, the other
/// panels' titles 12.1).
pub(super) const TITLE_EXTRA: u32 = 4;

/// The table's font size and line step: 13 units (its subscripts 6 pt printed in one column)
/// and 18 across two columns, 17 in one.
const TABLE_FONT: u32 = 13;

/// The last column's header, across two columns and in one: the error after allocation and
/// what it is across two columns (the sixth review, R6-lloyd2005-fig8-5: "error after" was
/// cryptic); in one, whose last column is as wide as its numbers, the same on two lines (a key
/// beside (a) said what "error after" was: the sixth review, R6-lloyd2005-fig8-4). Lines split
/// at '\n'.
pub(super) const ERROR_AFTER: [&str; 2] = [
    "error after allocation (M_x/w, M_z/h)",
    "error after\n(M_x/w, M_z/h)",
];

/// The header's lines, [`ERROR_AFTER`]'s.
fn header_lines(single: bool) -> u32 {
    ERROR_AFTER[usize::from(single)].lines().count() as u32
}

pub(super) fn table_step(single: bool) -> u32 {
    TABLE_FONT + if single { 4 } else { 5 }
}

impl Fig8 {
    /// The table's rows: per partition its tag, face and depths, M_x, M_z, its share of the
    /// texture's width w and height h (Eq 6), and its error after the allocation, M_x/w and
    /// M_z/h (Eq 6 makes the first one value across the texture and the second one within a
    /// column).
    pub(super) fn table_rows(&self) -> Vec<[String; 6]> {
        let n = f64::from(SIZE);
        self.cells
            .iter()
            .map(|c| {
                let v = c.viewport;
                let (w, h) = (f64::from(v.width) / n, f64::from(v.height) / n);
                [
                    c.tag.clone(),
                    minus(&c.label),
                    format!("{:.2}", c.mx),
                    format!("{:.2}", c.mz),
                    format!("({:.0} %, {:.0} %)", 100.0 * w, 100.0 * h),
                    format!("({:.2}, {:.2})", c.mx / w, c.mz / h),
                ]
            })
            .collect()
    }

    /// The caption's sentence on (d): the parts whose M_x/w is lower than the others' (Eq 6
    /// gives a column its width by its largest M_x, so every part of a column has that part's
    /// M_x/w but the one with the largest M_x), with both values and the part whose M_x sets
    /// their column's width, computed from the viewports. None where every part has one.
    pub(super) fn lower_after_sentence(&self) -> Option<String> {
        let n = f64::from(SIZE);
        let after = |c: &super::Cell| c.mx / (f64::from(c.viewport.width) / n);
        let most = self
            .cells
            .iter()
            .map(after)
            .fold(f64::NEG_INFINITY, f64::max);
        let lower: Vec<&super::Cell> = self
            .cells
            .iter()
            .filter(|c| after(c) < most - 0.005)
            .collect();
        let first = lower.first()?;
        // The part with the column's largest M_x: the same column (viewport x), the largest.
        let setter = self
            .cells
            .iter()
            .filter(|c| c.viewport.x == first.viewport.x)
            .max_by(|a, b| a.mx.total_cmp(&b.mx))?;
        let tags: Vec<&str> = lower.iter().map(|c| c.tag.as_str()).collect();
        Some(format!(
            "(d) {}: M_x/w\u{a0}=\u{a0}{:.2}\u{a0}<\u{a0}{:.2}; {}'s larger M_x sets their \
             column's width.",
            tags.join(", "),
            after(first),
            most,
            &setter.tag[..1],
        ))
    }

    /// The table's rows as drawn, each with the partitions it stands for: one a partition
    /// across two columns; in one column, the parts of one face whose numbers print alike
    /// (the self-similar z-partitions of a face have one M_x, M_z and share) share a row, "R1,
    /// R2", their face and depths said in the caption.
    pub(super) fn table_groups(&self, single: bool) -> Vec<(Vec<usize>, [String; 6])> {
        let mut out: Vec<(Vec<usize>, [String; 6])> = Vec::new();
        for (i, row) in self.table_rows().into_iter().enumerate() {
            if single {
                if let Some((members, last)) = out.last_mut() {
                    let face = |t: &str| t.chars().next();
                    if face(&last[0]) == face(&row[0]) && last[2..] == row[2..] {
                        members.push(i);
                        last[0] = format!("{}, {}", last[0], row[0]);
                        continue;
                    }
                }
            }
            out.push((vec![i], row));
        }
        out
    }

    /// The table's lines, [`table_step`] apart: across two columns its title, header and a
    /// row a partition; in one column (the title in its header's first cell) its header and its rows.
    pub(super) fn table_lines(&self, single: bool) -> u32 {
        let rows = self.table_groups(single).len() as u32 + header_lines(single);
        if single {
            rows
        } else {
            rows + 1
        }
    }

    /// The depths of the parts numbered `n` ('1', '2'), "z\u{a0}1–3.16", from their labels
    /// (the one-column caption says what the tags' numbers mean).
    pub(super) fn depths(&self, n: char) -> String {
        self.cells
            .iter()
            .find(|c| c.tag.ends_with(n))
            .map(|c| minus(&c.label))
            .and_then(|l| l.split_once(", ").map(|(_, d)| d.replace(' ', "\u{a0}")))
            .unwrap_or_default()
    }

    /// (d): the table of [`Fig8::table_groups`], each row led by the swatches of its
    /// partitions' looks: across two columns under a title that says what its columns are
    /// (one column says it in the key). Its lines are [`table_step`] units apart whatever the
    /// page.
    pub(super) fn draw_table<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        single: bool,
    ) -> Result<(), Fail> {
        let size = TABLE_FONT;
        let step = table_step(single) as i32;
        let text = TextStyle::from((FONT, size).into_font()).pos(Pos::new(HPos::Left, VPos::Top));
        let head = [
            if single { "(d) part" } else { "part" },
            "face, depth",
            "M_x",
            "M_z",
            "share (w, h)",
            ERROR_AFTER[usize::from(single)],
        ];
        // One column writes the face and depths in its key.
        let keep: &[usize] = if single {
            &[0, 2, 3, 4, 5]
        } else {
            &[0, 1, 2, 3, 4, 5]
        };
        let groups = self.table_groups(single);
        // A cell's width: its widest line's.
        let measure = |t: &str| -> Result<i32, Fail> {
            t.lines().try_fold(0, |w, l| {
                area.estimate_text_size(l, &text)
                    .map(|(lw, _)| w.max(lw as i32))
                    .map_err(|e| Fail::Draw(e.to_string()))
            })
        };
        let swatch = (size as i32 + 4, size as i32 - 1);
        // The swatches of a row's partitions, side by side 3 units apart.
        let swatches = |n: usize| n as i32 * (swatch.0 + 3) - 3;
        let most = groups.iter().map(|g| g.0.len()).max().unwrap_or(1);
        // One column leaves out the swatches (the tags name the parts, (c) shows their looks).
        let lead = if single {
            0
        } else {
            swatches(most) + SWATCH_GAP
        };
        let mut widths = Vec::new();
        for &j in keep {
            let mut w = if j == 0 && single {
                0
            } else {
                measure(head[j])?
            };
            for (_, r) in &groups {
                w = w.max(measure(&r[j])?);
            }
            if j == 0 {
                w += lead;
                if single {
                    w = w.max(measure(head[j])?);
                }
            }
            widths.push(w);
        }
        let (aw, _) = area.dim_in_pixel();
        let used: i32 = widths.iter().sum();
        let gap = ((aw as i32 - 8 - used) / (keep.len() as i32 - 1).max(1)).clamp(6, 40);
        let left = ((aw as i32 - used - gap * (keep.len() as i32 - 1)) / 2).max(2);
        let mut xs = Vec::new();
        let mut x = left;
        for w in &widths {
            xs.push(x);
            x += w + gap;
        }
        let top = TABLE_TOP as i32;
        // The header's line: the second across two columns (under the title), the first in one.
        let first = if single {
            top
        } else {
            let title = "(d) Eq 6's shares (w, h) of the texture";
            let title_style = TextStyle::from((FONT, PANEL_TITLE).into_font())
                .pos(Pos::new(HPos::Left, VPos::Top));
            area.draw(&Text::new(title, (left, top), title_style))?;
            top + step + TITLE_EXTRA as i32
        };
        let grey = RGBColor(90, 90, 90);
        // The header's cells top-aligned, a cell of several lines one step a line; the rule and
        // the rows under its last line.
        for (k, &j) in keep.iter().enumerate() {
            let at = xs[k] + if j == 0 && !single { lead } else { 0 };
            for (n, line) in head[j].lines().enumerate() {
                let y = first + n as i32 * step;
                area.draw(&Text::new(line, (at, y), text.color(&grey)))?;
            }
        }
        let first = first + (header_lines(single) as i32 - 1) * step;
        let rule = first + step - 3;
        area.draw(&PathElement::new(
            vec![(left, rule), (x - gap, rule)],
            grey.stroke_width(1),
        ))?;
        for (r, (members, row)) in groups.iter().enumerate() {
            let y = first + (r as i32 + 1) * step;
            if !single {
                for (m, &i) in members.iter().enumerate() {
                    let at = (xs[0] + m as i32 * (swatch.0 + 3), y + 1);
                    self.draw_swatch(area, i, at, swatch)?;
                }
            }
            for (k, &j) in keep.iter().enumerate() {
                let at = xs[k] + if j == 0 { lead } else { 0 };
                area.draw(&Text::new(row[j].clone(), (at, y), text.clone()))?;
            }
        }
        Ok(())
    }

    /// Partition `i`'s swatch: its pastel with its hatch, `size` units at `(sx, sy)`.
    fn draw_swatch<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        i: usize,
        (sx, sy): (i32, i32),
        size: (i32, i32),
    ) -> Result<(), Fail> {
        let colour = self.fill(i);
        area.draw(&Rectangle::new(
            [(sx, sy), (sx + size.0, sy + size.1)],
            colour.mix(0.35).filled(),
        ))?;
        let poly = [
            DVec2::new(f64::from(sx), f64::from(sy)),
            DVec2::new(f64::from(sx + size.0), f64::from(sy)),
            DVec2::new(f64::from(sx + size.0), f64::from(sy + size.1)),
            DVec2::new(f64::from(sx), f64::from(sy + size.1)),
        ];
        for &angle in HATCHES[i % HATCHES.len()].angles() {
            // Pixel rows grow downward: the angle mirrored to look as in the panels.
            for (a, b) in hatch::segments(&poly, -angle, 4.0) {
                area.draw(&PathElement::new(
                    vec![
                        (a.x.round() as i32, a.y.round() as i32),
                        (b.x.round() as i32, b.y.round() as i32),
                    ],
                    colour.mix(0.8).stroke_width(1),
                ))?;
            }
        }
        // Outlined in dark grey: black outlines are the texture's rectangles.
        area.draw(&Rectangle::new(
            [(sx, sy), (sx + size.0, sy + size.1)],
            RGBColor(60, 60, 60).stroke_width(1),
        ))?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::super::fig8;

    /// The table's lines (d) are one [`table_step`] apart whatever the panel's size and in
    /// both columns (item 2 of issue 35: the texture's in-rectangle text, spaced by the axis
    /// range, printed line on line in `--bare`; the table's spacing is in units of the page).
    #[test]
    fn table_lines_are_one_step_apart_on_any_panel() {
        use crate::plot::chart::read_svg::{draw_svg, texts};
        let fig = fig8().map_err(|e| e.named("lloyd2005-fig8")).unwrap();
        for single in [false, true] {
            for size in [(520, 170), (300, 320), (900, 420)] {
                let svg = draw_svg(size, |area| fig.draw_table(area, single).unwrap());
                // A row's first cell: a tag, or in one column the tags of a face's parts whose
                // numbers print alike ("R1, R2").
                let ys: Vec<f64> = texts(&svg)
                    .iter()
                    .filter(|(_, t, _)| {
                        t.split(", ")
                            .all(|part| fig.cells.iter().any(|c| c.tag == part))
                    })
                    .map(|(_, _, y)| *y)
                    .collect();
                // One row a partition; in one column R1, R2 / T1, T2 / L1, L2 / N.
                let rows = if single { 4 } else { fig.cells.len() };
                assert_eq!(ys.len(), rows, "{size:?}: {ys:?}");
                let step = if single { 17.0 } else { 18.0 };
                for w in ys.windows(2) {
                    assert!((w[1] - w[0] - step).abs() < 0.5, "{size:?}: {ys:?}");
                }
            }
        }
    }

    /// What the table prints as "after" is Eq 6's error: Eq 6 gives a column the width share
    /// w = (its largest M_x) / Σ (each column's largest M_x), so a part's M_x/w is
    /// M_x · Σ / (its column's largest), computed here without the viewports: Σ = 1.56 + 1.76 +
    /// 0.98 = 4.30 for the part with its column's largest M_x, less for the others (R1: 4.09);
    /// and the header names it (M_x/w, M_z/h).
    #[test]
    fn table_after_is_the_sum_of_the_columns_m_x() {
        use crate::plot::chart::read_svg::{draw_svg, texts};
        let fig = fig8().map_err(|e| e.named("lloyd2005-fig8")).unwrap();
        // The columns by face pair: left and right share one (Eq 6 pairs opposite faces).
        let pair = |tag: &str| match &tag[..1] {
            "L" | "R" => "LR",
            t => {
                if t == "T" {
                    "T"
                } else {
                    "N"
                }
            }
        };
        let mut col_max: std::collections::BTreeMap<&str, f64> = Default::default();
        for c in &fig.cells {
            let m = col_max.entry(pair(&c.tag)).or_insert(0.0);
            *m = m.max(c.mx);
        }
        assert_eq!(col_max.len(), 3, "{:?}", col_max.keys());
        let sum: f64 = col_max.values().sum();
        assert!((sum - 4.30).abs() < 0.005, "{sum}");
        let rows = fig.table_rows();
        assert_eq!(rows.len(), 7);
        for (r, c) in rows.iter().zip(&fig.cells) {
            // Printed as a pair "(4.09, 2.40)", not "4.09 × 2.40" (the fifth review: read as a
            // product).
            let inner = r[5].strip_prefix('(').and_then(|p| p.strip_suffix(')'));
            let (first, _) = inner.and_then(|p| p.split_once(", ")).expect(&r[5]);
            let printed: f64 = first.parse().unwrap();
            let want = c.mx * sum / col_max[pair(&c.tag)];
            assert!((printed - want).abs() < 0.006, "{r:?} vs {want}");
        }
        let svg = draw_svg((520, 170), |area| fig.draw_table(area, false).unwrap());
        // The header as written (plain SVG: subscripts not typeset).
        assert!(
            texts(&svg)
                .iter()
                .any(|(_, t, _)| t.replace('_', "").ends_with("allocation (Mx/w, Mz/h)")),
            "{svg}"
        );
    }

    /// Figure review 2: a row's tag stands at least 6 units right of its swatch (it touched
    /// it: "▨R1"); and the one-column table (no swatches) keeps M_x and M_z (it dropped
    /// them), read back from the SVG: the swatch outlines (#3C3C3C) and the tags' x, and the
    /// printed M_x of R1 (1.48) and M_z of L1 (0.42) found in either table.
    #[test]
    fn tags_clear_their_swatches_and_one_column_keeps_m_x_and_m_z() {
        use crate::plot::chart::read_svg::{attr, draw_svg, texts};
        let fig = fig8().map_err(|e| e.named("lloyd2005-fig8")).unwrap();
        for (single, size) in [(false, (520, 170)), (true, (300, 170))] {
            let svg = draw_svg(size, |area| fig.draw_table(area, single).unwrap());
            let swatches: Vec<(f64, f64, f64)> = svg
                .lines()
                .filter(|l| l.starts_with("<rect") && l.contains("stroke=\"#3C3C3C\""))
                .map(|l| {
                    let (x, y) = (attr(l, "x").unwrap(), attr(l, "y").unwrap());
                    (
                        x + attr(l, "width").unwrap(),
                        y,
                        y + attr(l, "height").unwrap(),
                    )
                })
                .collect();
            // One column leaves the swatches out (its tags name the parts; (c) shows them).
            let want = if single { 0 } else { fig.cells.len() };
            assert_eq!(swatches.len(), want);
            let all = texts(&svg);
            for (line, t, y) in &all {
                if !single && fig.cells.iter().any(|c| c.tag == *t) {
                    let x = attr(line, "x").unwrap();
                    let beside = swatches
                        .iter()
                        .find(|s| s.1 <= y + 8.0 && *y <= s.2)
                        .unwrap_or_else(|| panic!("{t} at {y}: no swatch"));
                    assert!(
                        x - beside.0 >= 6.0,
                        "single {single}: {t} at {x}, swatch to {}",
                        beside.0
                    );
                }
            }
            for v in ["1.48", "0.42"] {
                assert!(
                    all.iter().any(|(_, t, _)| t == v),
                    "single {single}: no {v}"
                );
            }
        }
    }
}
