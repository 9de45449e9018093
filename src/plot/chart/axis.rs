//! Axes: linear or logarithmic scales with chosen tick marks and labels, and the chart builder
//! that draws them.

use super::super::Fail;
use super::FONT;
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint};
use plotters::coord::Shift;
use plotters::prelude::*;

/// The chart type of every panel: both axes linear in axis space, with explicit ticks.
pub(crate) type Chart2d<'a, DB> = ChartContext<'a, DB, Cartesian2d<Ticked, Ticked>>;

/// A linear plotters coordinate over `[lo, hi]` whose bold (labelled) and light (grid) tick
/// positions are given, not computed by plotters.
#[derive(Debug, Clone)]
pub(crate) struct Ticked {
    lo: f64,
    hi: f64,
    bold: Vec<f64>,
    light: Vec<f64>,
}

impl Ticked {
    pub(crate) fn new(lo: f64, hi: f64, bold: Vec<f64>, light: Vec<f64>) -> Self {
        Self {
            lo,
            hi,
            bold,
            light,
        }
    }
}

impl Ranged for Ticked {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, v: &f64, limit: (i32, i32)) -> i32 {
        if self.hi == self.lo {
            return (limit.0 + limit.1) / 2;
        }
        let t = (v - self.lo) / (self.hi - self.lo);
        let len = f64::from(limit.1 - limit.0);
        let px = f64::from(limit.0) + (len * t).round();
        // Keep pixel positions finite and inside i32 even for wild values.
        px.clamp(-1e6, 1e6) as i32
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.light.clone()
        } else {
            self.bold.clone()
        }
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.lo..self.hi
    }
}

/// How an axis maps data to position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Scale {
    /// Position proportional to the value.
    Linear,
    /// Linear, for a count: labelled and grid ticks only at whole numbers.
    Integer,
    /// Linear, labelled and grid ticks only at `first + i · step` (a count defined only there,
    /// such as 4k + 1 maps).
    Every { first: f64, step: f64 },
    /// Position proportional to log_b of the value (b > 1).
    Log(f64),
}

/// One axis: its label (with the unit), its data range and its scale.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Axis {
    pub label: String,
    pub min: f64,
    pub max: f64,
    pub scale: Scale,
    /// A base-10 axis of less than a decade writes its labels as powers of ten (m×10ⁿ) too
    /// ([`Axis::in_powers`]), so that a quantity keeps one format across panels.
    pub powers: bool,
    /// The values labelled, where the automatic choice is not wanted ([`Axis::labelled_at`]).
    pub labelled: Option<Vec<f64>>,
    /// A log axis's grid only at 2 and 5 of each decade ([`Axis::sparse_grid`]).
    pub sparse: bool,
    /// A linear axis whose labels past this value read back down ([`Axis::folded_at`]).
    pub fold: Option<f64>,
}

impl Axis {
    /// A linear axis over `[min, max]`.
    pub fn linear(label: impl Into<String>, min: f64, max: f64) -> Self {
        Self {
            label: label.into(),
            min,
            max,
            scale: Scale::Linear,
            powers: false,
            labelled: None,
            sparse: false,
            fold: None,
        }
    }

    /// A linear axis of a count over `[min, max]`: ticks and grid lines only at whole numbers.
    pub fn integer(label: impl Into<String>, min: f64, max: f64) -> Self {
        Self {
            label: label.into(),
            min,
            max,
            scale: Scale::Integer,
            powers: false,
            labelled: None,
            sparse: false,
            fold: None,
        }
    }

    /// A linear axis over `[min, max]` with ticks and grid lines only at `first + i · step`.
    pub fn every(label: impl Into<String>, min: f64, max: f64, first: f64, step: f64) -> Self {
        Self {
            label: label.into(),
            min,
            max,
            scale: Scale::Every { first, step },
            powers: false,
            labelled: None,
            sparse: false,
            fold: None,
        }
    }

    /// A base-10 logarithmic axis over `[min, max]`, `0 < min < max`.
    pub fn log10(label: impl Into<String>, min: f64, max: f64) -> Self {
        Self {
            label: label.into(),
            min,
            max,
            scale: Scale::Log(10.0),
            powers: false,
            labelled: None,
            sparse: false,
            fold: None,
        }
    }

    /// A logarithmic axis of base `b`.
    #[cfg(test)]
    pub fn log_base(label: impl Into<String>, min: f64, max: f64, b: f64) -> Self {
        Self {
            label: label.into(),
            min,
            max,
            scale: Scale::Log(b),
            powers: false,
            labelled: None,
            sparse: false,
            fold: None,
        }
    }

    /// The same axis labelled at the data values `at` only (those inside its range), each also
    /// a grid line; its other grid lines stay.
    pub fn labelled_at(mut self, at: &[f64]) -> Self {
        self.labelled = Some(at.to_vec());
        self
    }

    /// The same axis with a log scale's grid lines at 2 and 5 of each decade only, not at every
    /// 2…9: on a small plot the eight lines a decade run together into a grey ground. No
    /// figure uses it now (barroso-fig7's one column, its one user, draws its panel (b) alone).
    #[cfg(test)]
    pub fn sparse_grid(mut self) -> Self {
        self.sparse = true;
        self
    }

    /// The same linear axis with each label past `at` reading `2 at − v` (an angle through
    /// overhead: 0, 45, 90, 45, 0 for an elevation from behind to in front, figure review 6:
    /// 135 and 180 read as elevations no light has); its positions and ticks unchanged.
    pub fn folded_at(mut self, at: f64) -> Self {
        self.fold = Some(at);
        self
    }

    /// The same axis with its labels written as powers of ten (10ⁿ, m×10ⁿ) even where it spans
    /// less than a decade (which writes plain numbers: 900, 1000, 1200), so that a quantity
    /// another panel writes in powers keeps that format. An axis of a decade or more writes
    /// its decades as powers anyway.
    pub fn in_powers(mut self) -> Self {
        self.powers = true;
        self
    }

    /// Whether a base-10 axis writes its labels as plain numbers (900, 1000, 1200) rather than
    /// powers of ten: where it spans less than a decade and is not [`Axis::in_powers`].
    pub fn writes_plain(&self) -> bool {
        matches!(self.scale, Scale::Log(b) if (b - 10.0).abs() < 1e-12)
            && self.labels_mantissas()
            && !self.powers
    }

    /// Data value → axis space; `None` for values the axis cannot show at all (non-finite, or
    /// ≤ 0 on a logarithmic axis). Values outside `[min, max]` are mapped, not dropped: the
    /// drawing code clips.
    pub fn to_axis(&self, v: f64) -> Option<f64> {
        if !v.is_finite() {
            return None;
        }
        match self.scale {
            Scale::Linear | Scale::Integer | Scale::Every { .. } => Some(v),
            Scale::Log(b) => (v > 0.0).then(|| v.ln() / b.ln()),
        }
    }

    /// Axis space → data value.
    pub fn to_data(&self, a: f64) -> f64 {
        match self.scale {
            Scale::Linear | Scale::Integer | Scale::Every { .. } => a,
            Scale::Log(b) => b.powf(a),
        }
    }

    /// The axis range in axis space.
    pub fn range(&self) -> (f64, f64) {
        let lo = self.to_axis(self.min).unwrap_or(0.0);
        let hi = self.to_axis(self.max).unwrap_or(1.0);
        (lo, hi)
    }

    /// Bold (labelled) and light (grid only) tick positions, in axis space.
    pub fn ticks(&self) -> (Vec<f64>, Vec<f64>) {
        let (bold, mut light) = self.auto_ticks();
        let Some(at) = &self.labelled else {
            return (bold, light);
        };
        let (lo, hi) = self.range();
        let eps = 1e-9 * (hi - lo).abs().max(1e-300);
        let bold: Vec<f64> = at
            .iter()
            .filter_map(|&v| self.to_axis(v))
            .filter(|&a| a >= lo - eps && a <= hi + eps)
            .collect();
        light.extend(bold.iter().copied());
        light.sort_by(f64::total_cmp);
        (bold, light)
    }

    /// The ticks chosen for the axis's scale and range: (labelled, grid lines).
    fn auto_ticks(&self) -> (Vec<f64>, Vec<f64>) {
        let (lo, hi) = self.range();
        let eps = 1e-9 * (hi - lo).abs().max(1e-300);
        let inside = |v: f64| v >= lo - eps && v <= hi + eps;
        match self.scale {
            Scale::Every { first, step } => {
                let ticks: Vec<f64> = multiples(lo - first, hi - first, step, eps)
                    .into_iter()
                    .map(|v| v + first)
                    .collect();
                (ticks.clone(), ticks)
            }
            Scale::Integer => {
                let step = nice_step((hi - lo) / 8.0).max(1.0);
                let bold = multiples(lo, hi, step, eps);
                let light = multiples(lo, hi, 1.0, eps);
                (bold, light)
            }
            Scale::Linear => {
                // About five labelled ticks: at text 2 % of the page, a panel half the page wide
                // has room for five numbers such as −60, not for eight.
                let step = nice_step((hi - lo) / 5.0);
                let bold = multiples(lo, hi, step, eps);
                let mantissa = step / 10f64.powf(step.log10().floor());
                let minor = if (mantissa - 2.0).abs() < 1e-9 {
                    2.0
                } else {
                    5.0
                };
                let light = multiples(lo, hi, step / minor, eps);
                (bold, light)
            }
            Scale::Log(b) => {
                let decades = hi - lo;
                let first = (lo - eps).ceil() as i64;
                let last = (hi + eps).floor() as i64;
                let every = if decades > 12.0 {
                    3
                } else if decades > 7.0 {
                    2
                } else {
                    1
                };
                let mut bold: Vec<f64> = (first..=last)
                    .filter(|e| e.rem_euclid(every) == 0)
                    .map(|e| e as f64)
                    .collect();
                let mut light = Vec::new();
                if (b - 10.0).abs() < 1e-12 && decades <= 6.0 {
                    let lf = (lo - eps).floor() as i64;
                    // One rule for every figure's log grid (sixth figure review, X-8): the
                    // decades, and 2 and 5 of each decade too where the axis spans fewer than
                    // two decades (docs/figures.md); never every 2…9, whose eight lines a
                    // decade ran together into a grey ground on small plots.
                    let grid: &[u32] = if self.sparse || decades < 2.0 - 1e-9 {
                        &[2, 5]
                    } else {
                        &[]
                    };
                    for e in lf..=last {
                        for &m in grid {
                            let v = e as f64 + f64::from(m).log10();
                            if inside(v) {
                                light.push(v);
                            }
                        }
                    }
                    if self.labels_mantissas() || bold.len() < 2 {
                        // Only the decades are labelled, except on an axis of less than one
                        // decade: every mantissa; less than half a decade (a colour bar over
                        // one panel's own range): 1.2, 1.5 and 2.5 too, so that its upper part
                        // has labels. An axis of a decade or more that holds fewer than two
                        // decades labels 2 and 5 as well (one label cannot give a scale).
                        let mantissas: &[f64] = if decades < 0.5 - 1e-9 {
                            &[1.2, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]
                        } else if decades < 1.0 - 1e-9 {
                            &[2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]
                        } else {
                            &[2.0, 5.0]
                        };
                        for e in lf..=last {
                            for &m in mantissas {
                                let v = e as f64 + m.log10();
                                if inside(v) {
                                    bold.push(v);
                                }
                            }
                        }
                        bold.sort_by(f64::total_cmp);
                    }
                } else if bold.len() < 2 {
                    let step = nice_step((hi - lo) / 5.0);
                    bold = multiples(lo, hi, step, eps);
                }
                light.extend(bold.iter().copied());
                light.sort_by(f64::total_cmp);
                (bold, light)
            }
        }
    }

    /// Whether a base-10 axis labels mantissas between its decades: where it spans less than
    /// one decade.
    fn labels_mantissas(&self) -> bool {
        let (lo, hi) = self.range();
        hi - lo < 1.0 - 1e-9
    }

    /// The label of a tick at axis-space position `a`, negative numbers with the minus sign
    /// U+2212 (not the hyphen-minus).
    pub fn tick_label(&self, a: f64) -> String {
        self.tick_text(a).replace('-', "\u{2212}")
    }

    fn tick_text(&self, a: f64) -> String {
        let a = match self.fold {
            Some(at) if a > at && !matches!(self.scale, Scale::Log(_)) => 2.0 * at - a,
            _ => a,
        };
        match self.scale {
            Scale::Every { step, .. } => fmt_linear(a, step),
            Scale::Linear | Scale::Integer => {
                let (lo, hi) = self.range();
                fmt_linear(a, nice_step((hi - lo) / 8.0))
            }
            Scale::Log(b) if (b - 10.0).abs() < 1e-12 => {
                // One rule for every base-10 axis and colour bar: a decade is 10ⁿ, any other
                // value m×10ⁿ; an axis of less than a decade (its labels mantissas, at most
                // one decade among them) writes them all as plain numbers (900, 1000, 1200)
                // unless it is to match a panel in powers ([`Axis::in_powers`]).
                let v = self.to_data(a);
                if self.labels_mantissas() && !self.powers {
                    fmt_times_ten(v)
                } else {
                    fmt_power(v)
                }
            }
            Scale::Log(b) => {
                let e = a.round();
                if (a - e).abs() < 1e-9 {
                    format!("{}{}", fmt_plain(b), superscript(e as i64))
                } else {
                    fmt_plain(self.to_data(a))
                }
            }
        }
    }
}

/// 1, 2 or 5 times a power of ten, at least `raw`.
fn nice_step(raw: f64) -> f64 {
    if raw.is_nan() || raw <= 0.0 || raw.is_infinite() {
        return 1.0;
    }
    let p = 10f64.powf(raw.log10().floor());
    for m in [1.0, 2.0, 5.0, 10.0] {
        if m * p >= raw * (1.0 - 1e-12) {
            return m * p;
        }
    }
    10.0 * p
}

fn multiples(lo: f64, hi: f64, step: f64, eps: f64) -> Vec<f64> {
    let first = ((lo - eps) / step).ceil() as i64;
    let last = ((hi + eps) / step).floor() as i64;
    (first..=last).map(|i| i as f64 * step).collect()
}

/// A tick label on a linear axis with the decimals the step needs.
fn fmt_linear(v: f64, step: f64) -> String {
    let decimals = (0..12)
        .find(|&d| {
            let scaled = step * 10f64.powi(d);
            (scaled - scaled.round()).abs() < 1e-9 * scaled.max(1.0)
        })
        .unwrap_or(12) as usize;
    let s = format!(
        "{:.*}",
        decimals,
        if v.abs() < 1e-12 * step { 0.0 } else { v }
    );
    trim_zeros(&s)
}

/// A number without trailing zeros, up to four significant decimals.
pub(crate) fn fmt_plain(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    let mag = v.abs().log10().floor();
    let decimals = (3.0 - mag).clamp(0.0, 12.0) as usize;
    trim_zeros(&format!("{v:.decimals$}"))
}

fn trim_zeros(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

/// A number as m×10ᵉ with up to four significant digits ("8.652×10⁵"); plain between 0.01 and
/// 1000.
pub(crate) fn fmt_times_ten(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return fmt_plain(v);
    }
    let e = v.abs().log10().floor();
    if (-2.0..=3.0).contains(&e) {
        return fmt_plain(v);
    }
    fmt_power(v)
}

/// A number as m×10ⁿ with up to four significant digits ("8.652×10⁵", "2.68×10⁻³"), a power of
/// ten alone as 10ⁿ ("10⁰", "10³"), whatever its size.
pub(crate) fn fmt_power(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return fmt_plain(v);
    }
    let e = v.abs().log10().floor();
    let m = v / 10f64.powf(e);
    // Rounding can carry the mantissa to 10.
    let (m, e) = if (m.abs() * 1000.0).round() >= 10_000.0 {
        (m / 10.0, e + 1.0)
    } else {
        (m, e)
    };
    let mant = trim_zeros(&format!("{m:.3}"));
    if mant == "1" {
        format!("10{}", superscript(e as i64))
    } else {
        format!("{mant}×10{}", superscript(e as i64))
    }
}

/// An integer in Unicode superscript digits (DejaVu Sans has them all).
pub(crate) fn superscript(e: i64) -> String {
    let digits = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut s = String::new();
    if e < 0 {
        s.push('⁻');
    }
    for c in e.unsigned_abs().to_string().chars() {
        s.push(digits[c as usize - '0' as usize]);
    }
    s
}

/// The size of every panel's title, in pixels (one size in every figure).
pub(crate) const PANEL_TITLE: u32 = 15;

/// The space kept between a panel title and the top of its plot, in units: the top tick
/// label rises about 8 units above the plot's edge (half its height and a raised exponent),
/// and at least 4 pt (5 units in one column) must remain under the title
/// (`top_tick_labels_keep_clear_of_panel_titles`, tests/figures_style_axes.rs).
pub(crate) const TITLE_GAP: u32 = 8;

/// The length of a tick mark, in units, in every chart.
pub(crate) const TICK: u32 = 5;

/// Sizes of a chart's text and label areas, in pixels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct ChartStyle {
    pub title_size: u32,
    pub x_label_area: u32,
    pub y_label_area: u32,
    pub tick_size: u32,
    pub desc_size: u32,
    pub margin: u32,
}

impl Default for ChartStyle {
    fn default() -> Self {
        Self {
            title_size: PANEL_TITLE,
            x_label_area: 46,
            y_label_area: 64,
            tick_size: 13,
            desc_size: 15,
            margin: 8,
        }
    }
}

/// Builds a chart over two axes with the mesh and axis labels drawn.
pub(crate) fn build_chart<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    title: &str,
    x: &Axis,
    y: &Axis,
    grid_lines: bool,
) -> Result<Chart2d<'a, DB>, Fail> {
    build_chart_styled(area, title, x, y, grid_lines, &ChartStyle::default())
}

/// [`build_chart`] with explicit text and label-area sizes (for small panels).
pub(crate) fn build_chart_styled<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    title: &str,
    x: &Axis,
    y: &Axis,
    grid_lines: bool,
    style: &ChartStyle,
) -> Result<Chart2d<'a, DB>, Fail> {
    let (x0, x1) = x.range();
    let (y0, y1) = y.range();
    let (xb, xl) = x.ticks();
    let (yb, yl) = y.ticks();
    // The margins, then the title, then [`TITLE_GAP`] under it, as plotters' own caption
    // would lay them out without the gap.
    let m = style.margin;
    let mut inner = area.margin(m, m, m, 2 * m);
    if !title.is_empty() {
        // A title of several lines ('\n' between them; lloyd2006-fig12's panels), each line
        // under the one before; a title of one line as before.
        for line in title.split('\n') {
            inner = inner.titled(line, (FONT, style.title_size))?;
        }
        inner = inner.margin(TITLE_GAP, 0, 0, 0);
    }
    let mut builder = ChartBuilder::on(&inner);
    builder
        .x_label_area_size(style.x_label_area)
        .y_label_area_size(style.y_label_area);
    let mut chart =
        builder.build_cartesian_2d(Ticked::new(x0, x1, xb, xl), Ticked::new(y0, y1, yb, yl))?;
    let xf = |v: &f64| x.tick_label(*v);
    let yf = |v: &f64| y.tick_label(*v);
    let mut mesh = chart.configure_mesh();
    mesh.x_desc(x.label.as_str())
        .y_desc(y.label.as_str())
        .x_label_formatter(&xf)
        .y_label_formatter(&yf)
        .axis_desc_style((FONT, style.desc_size))
        .label_style((FONT, style.tick_size))
        .bold_line_style(RGBColor(205, 205, 205))
        .light_line_style(RGBColor(238, 238, 238))
        // One tick length in every panel (plotters' default is 5 % of the plot's size, which
        // moves the tick labels, and the axis labels' distance from them, panel by panel).
        .set_all_tick_mark_size(TICK);
    if !grid_lines {
        mesh.disable_mesh();
    }
    mesh.draw()?;
    Ok(chart)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A sparse grid (one-column barroso-fig7): over 1 … 10⁴ the light lines are the decades
    /// and log₁₀ 2, log₁₀ 5 in each of the four decades, 5 + 8 = 13 lines (the full grid: 37).
    #[test]
    fn a_sparse_log_grid_has_2_and_5_only() {
        let (bold, light) = Axis::log10("n", 1.0, 1e4).sparse_grid().ticks();
        assert_eq!(bold, vec![0.0, 1.0, 2.0, 3.0, 4.0]);
        assert_eq!(light.len(), 13);
        for e in 0..4 {
            for m in [2f64, 5.0] {
                let v = f64::from(e) + m.log10();
                assert!(light.iter().any(|&l| (l - v).abs() < 1e-12), "{v}");
            }
        }
        assert!(!light.iter().any(|&l| (l - 3f64.log10()).abs() < 1e-12));
    }

    /// The grid rule by hand: 0.04 … 1.25 (1.49 decades, lloyd2006-fig5) has lines at 0.05,
    /// 0.1, 0.2, 0.5, 1 (2 and 5 of each decade and the decades: log₁₀ of those), and no 3…9;
    /// 1 … 100 (exactly two decades) the three decades only.
    #[test]
    fn log_grid_is_decades_with_2_and_5_under_two_decades() {
        let (_, light) = Axis::log10("m", 0.04, 1.25).ticks();
        let want = [0.05f64, 0.1, 0.2, 0.5, 1.0];
        for v in want {
            assert!(light.iter().any(|&l| (l - v.log10()).abs() < 1e-12), "{v}");
        }
        assert!(light
            .iter()
            .all(|&l| want.iter().any(|v| (l - v.log10()).abs() < 1e-12)));
        let (bold, light) = Axis::log10("m", 1.0, 100.0).ticks();
        assert_eq!(light, bold);
        assert_eq!(light, vec![0.0, 1.0, 2.0]);
    }

    #[test]
    fn log_axis_ticks_are_decades_and_labels_read_as_numbers() {
        let a = Axis::log10("S", 1.0, 1e4);
        let (bold, light) = a.ticks();
        assert_eq!(bold, vec![0.0, 1.0, 2.0, 3.0, 4.0]);
        // Four decades: the grid is the five decades alone.
        assert_eq!(light, bold);
        // One format per axis: 1 … 10⁴ is all powers.
        assert_eq!(a.tick_label(0.0), "10⁰");
        assert_eq!(a.tick_label(3.0), "10³");
        assert_eq!(a.tick_label(4.0), "10⁴");
        // Less than a decade: every mantissa, written as m×10ᵉ on a large axis.
        let sub = Axis::log10("S", 8.65e5, 2e6);
        let labels: Vec<String> = sub.ticks().0.iter().map(|&t| sub.tick_label(t)).collect();
        assert_eq!(labels, vec!["9×10⁵", "10⁶", "1.2×10⁶", "1.5×10⁶", "2×10⁶"]);
        // Lloyd 2006 Fig 7's face-partition panel (865.2 to 1999): one format, labels up the bar.
        let faces = Axis::log10("S", 865.2, 1999.0);
        let labels: Vec<String> = faces
            .ticks()
            .0
            .iter()
            .map(|&t| faces.tick_label(t))
            .collect();
        assert_eq!(labels, vec!["900", "1000", "1200", "1500"]);
        // Between half a decade and one: every whole mantissa, no 1.2 or 1.5.
        let mid = Axis::log10("S", 2e3, 9e3);
        let labels: Vec<String> = mid.ticks().0.iter().map(|&t| mid.tick_label(t)).collect();
        assert_eq!(
            labels,
            vec!["2000", "3000", "4000", "5000", "6000", "7000", "8000", "9000"]
        );
        assert_eq!(fmt_times_ten(8.6523e5), "8.652×10⁵");
        assert_eq!(fmt_times_ten(9.99999e5), "10⁶");
        assert_eq!(fmt_times_ten(1999.0), "1999");
        assert_eq!(fmt_times_ten(19990.0), "1.999×10⁴");
        assert_eq!(fmt_times_ten(865.2), "865.2");
        // A decade or more: its decades only, as powers of ten, however small the numbers
        // (issue 35: one rule; 0.1 … 1000 used to read 0.1, 1, 10, 100, 1000).
        let plain = Axis::log10("S", 0.1, 1000.0);
        assert_eq!(plain.tick_label(-1.0), "10⁻¹");
        assert_eq!(plain.tick_label(3.0), "10³");
        assert!(!plain.writes_plain() && faces.writes_plain());
        // lloyd2006-fig5's axes, 0.04 to 1.25 (1.49 decades): 10⁻¹ and 10⁰ only (they read
        // 0.05, 0.1, 0.2, 0.5, 1).
        let fig5 = Axis::log10("m", 0.04, 1.25);
        let labels: Vec<String> = fig5.ticks().0.iter().map(|&t| fig5.tick_label(t)).collect();
        assert_eq!(labels, vec!["10⁻¹", "10⁰"]);
        // A decade or more holding one decade only (0.3 to 5): 2 and 5 labelled as well, in
        // powers: 0.5, 1, 2, 5.
        let one = Axis::log10("m", 0.3, 5.0);
        let labels: Vec<String> = one.ticks().0.iter().map(|&t| one.tick_label(t)).collect();
        assert_eq!(labels, vec!["5×10⁻¹", "10⁰", "2×10⁰", "5×10⁰"]);
        // Less than a decade, chosen labels (lloyd2006-worst-case's ratio, 0.8 to 6): plain.
        let ratio = Axis::log10("r", 0.8, 6.0).labelled_at(&[1.0, 2.0, 3.0, 5.0]);
        let labels: Vec<String> = ratio
            .ticks()
            .0
            .iter()
            .map(|&t| ratio.tick_label(t))
            .collect();
        assert_eq!(labels, vec!["1", "2", "3", "5"]);
        // Less than a decade to match a panel in powers: all in powers.
        let matched = Axis::log10("S", 865.2, 1999.0).in_powers();
        let labels: Vec<String> = matched
            .ticks()
            .0
            .iter()
            .map(|&t| matched.tick_label(t))
            .collect();
        assert_eq!(labels, vec!["9×10²", "10³", "1.2×10³", "1.5×10³"]);
        assert!(!matched.writes_plain());
        let powers = Axis::log10("n′", 0.3, 100.0).in_powers();
        assert_eq!(powers.tick_label(0.0), "10⁰");
        assert_eq!(powers.tick_label(2.0), "10²");
        // Values off the decades (a colour bar's ends) on an axis of a decade or more: m×10ⁿ
        // (martin-tan-fig6's bar wrote 0.491 and 0.00268 beside 10⁻¹, 10⁻²).
        let share = Axis::log10("share", 0.00268, 0.491);
        assert_eq!(share.tick_label(0.491f64.log10()), "4.91×10⁻¹");
        assert_eq!(share.tick_label(0.00268f64.log10()), "2.68×10⁻³");
        assert_eq!(fmt_power(1000.0), "10³");
        assert_eq!(fmt_power(9.99999e5), "10⁶");
        assert_eq!(fmt_power(2430.0), "2.43×10³");
        assert_eq!(Axis::log10("S", 1e-6, 1.0).tick_label(-6.0), "10⁻⁶");
        assert_eq!(a.to_axis(100.0), Some(2.0));
        assert_eq!(a.to_axis(0.0), None);
        let five = Axis::log_base("E", 1.0, 625.0, 5.0);
        assert_eq!(five.ticks().0, vec![0.0, 1.0, 2.0, 3.0, 4.0]);
        assert_eq!(five.tick_label(2.0), "5²");
        // Exactly a decade: its two decades only (2 and 5 were labelled too, up to two
        // decades).
        let short = Axis::log10("g", 0.1, 1.0);
        assert_eq!(short.ticks().0, vec![-1.0, 0.0]);
    }

    #[test]
    fn integer_axes_tick_only_whole_numbers() {
        // A count from 1 to 3: a linear axis would label 1.5 and 2.5 (step 0.5).
        assert!(Axis::linear("k", 1.0, 3.0).ticks().0.contains(&1.5));
        let k = Axis::integer("k", 1.0, 3.0);
        assert_eq!(k.ticks(), (vec![1.0, 2.0, 3.0], vec![1.0, 2.0, 3.0]));
        assert_eq!(k.tick_label(2.0), "2");
        // 1 to 8: labels every whole number, and no grid line between them (a linear axis has
        // grid lines between whole numbers).
        let k = Axis::integer("k", 1.0, 8.0);
        let (bold, light) = k.ticks();
        assert_eq!(bold, (1..=8).map(f64::from).collect::<Vec<_>>());
        assert!(light.iter().all(|v| v.fract() == 0.0), "{light:?}");
        assert!(Axis::linear("k", 1.0, 3.0)
            .ticks()
            .1
            .iter()
            .any(|v| v.fract() != 0.0));
        // 0 to 40: labels every 5, grid lines every 1.
        let n = Axis::integer("maps", 0.0, 40.0);
        assert_eq!(
            n.ticks().0,
            vec![0.0, 5.0, 10.0, 15.0, 20.0, 25.0, 30.0, 35.0, 40.0]
        );
        assert_eq!(n.ticks().1.len(), 41);
        // Lloyd 2006 Fig 13's 4k + 1 maps: ticks and grid at 5, 9, …, 41 only.
        let j = Axis::every("maps", 3.0, 43.0, 5.0, 4.0);
        let want: Vec<f64> = (1..=10).map(|k| f64::from(4 * k + 1)).collect();
        assert_eq!(j.ticks(), (want.clone(), want));
        assert_eq!(j.tick_label(13.0), "13");
    }

    #[test]
    fn linear_ticks_are_round_numbers() {
        let a = Axis::linear("z", 1.0, 20.0);
        let (bold, _) = a.ticks();
        assert_eq!(bold, vec![5.0, 10.0, 15.0, 20.0]);
        // About five labels (text at 2 % of the page leaves room for no more): 15/5 = 3 rounds
        // up to a step of 5.
        let k = Axis::linear("k", 1.0, 16.0);
        assert_eq!(k.ticks().0, vec![5.0, 10.0, 15.0]);
        assert_eq!(k.tick_label(10.0), "10");
        let small = Axis::linear("g", 0.0, 1.05);
        assert_eq!(small.tick_label(0.4), "0.4");
        let b = Axis::linear("η", -1.0, 1.0);
        assert_eq!(b.ticks().0, vec![-1.0, -0.5, 0.0, 0.5, 1.0]);
        // The minus sign U+2212, not the hyphen-minus.
        assert_eq!(b.tick_label(-0.5), "\u{2212}0.5");
        assert_eq!(b.tick_label(0.0), "0");
    }
}
