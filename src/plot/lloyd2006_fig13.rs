//! Lloyd et al. 2006 Fig 13: for each number of shadow maps j = 4k + 1, the depth ratio f/n
//! below which face partitioning (FP+ZP+W) needs less storage than z-partitioning (ZP) with
//! the light behind (Eq 20, 21), drawn as a column per j.

use super::super::chart::FONT;
use super::super::chart::{build_chart, column, fmt_plain, frame, Axis, Look, PALETTE};
use super::super::{Column, Fail, Figure};
use super::{FIG12_RATIO, SCHEME_WORDS, SINGLE_HEIGHT, THETA_DEG};
use crate::analytic::partition::{scheme_storage_factor, shadow_map_count, Scheme, SchemeLight};
use crate::ViewFrustum;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Fig 13 data: for each number of maps 4k + 1, the f/n above which z-partitioning (ZP, ZP+W)
/// has the lower storage factor than FP+ZP+W with the light behind.
pub(in crate::plot) struct Fig13 {
    /// (number of maps, crossover f/n)
    pub(super) crossover: Vec<(f64, f64)>,
    pub(super) y: Axis,
    pub(super) x: Axis,
}

/// The f/n at which ZP with `maps` maps and FP+ZP+W with `k` z-partitions per face have equal S̄
/// with the light behind (bisection on ln(f/n); FP+ZP+W is lower below it, ZP above).
fn crossover(maps: usize, k: usize, lo: f64, hi: f64) -> Result<Option<f64>, crate::Error> {
    let diff = |ratio: f64| -> Result<f64, crate::Error> {
        let v = ViewFrustum::new(1.0, ratio, std::f64::consts::FRAC_PI_4)?;
        let zp = scheme_storage_factor(Scheme::Zp, SchemeLight::Behind, &v, maps)?;
        let fp = scheme_storage_factor(Scheme::FpZpW, SchemeLight::Behind, &v, k)?;
        Ok((zp / fp).ln())
    };
    let (mut a, mut b) = (lo.ln(), hi.ln());
    let (da, db) = (diff(a.exp())?, diff(b.exp())?);
    if da.signum() == db.signum() {
        return Ok(None);
    }
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if diff(m.exp())?.signum() == da.signum() {
            a = m;
        } else {
            b = m;
        }
    }
    Ok(Some((0.5 * (a + b)).exp()))
}

pub(in crate::plot) fn fig13() -> Result<Fig13, Fail> {
    // The search interval of the crossover; the plot shows the depth ratios of real scenes.
    let (lo, hi) = (1.5, 1e12);
    let mut pts = Vec::new();
    for k in 1..=10usize {
        let maps = shadow_map_count(Scheme::FpZpW, SchemeLight::Behind, k)?;
        if let Some(r) = crossover(maps, k, lo, hi)? {
            pts.push((maps as f64, r));
        }
    }
    Ok(Fig13 {
        crossover: pts,
        x: Axis::every(
            // k, the z-partitions per face, is named in the caption.
            "shadow maps j = 4k + 1",
            3.0,
            43.0,
            5.0,
            4.0,
        ),
        // Its scale named, as on every log axis (seventh review, R7-X-1, R7-2006f13-1).
        y: Axis::log10("depth ratio f/n (log scale)", 1.0, 1e6),
    })
}

/// Fig 13's fills, in the colours every figure gives the schemes ([`Look`]): ZP's where
/// z-partitioning is lowest, FP+ZP+W's where face partitioning is, the latter hatched in white
/// ([`HATCH`]) so that the two also read apart in greyscale.
const ZP_FILL: RGBColor = Look::Zp.colour();
const FP_FILL: RGBColor = Look::FpZpW.colour();

/// The spacing of the white diagonal hatching over FP+ZP+W's fill, in units (coarse, so that
/// print halftoning keeps it), and its lines' width.
const HATCH: i32 = 16;
const HATCH_WIDTH: u32 = 3;

/// Hatches the pixel rectangle `[x0, x1] × [y0, y1]` of `area` (backend units) with white
/// lines at 45°, [`HATCH`] units apart.
fn hatch<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    (x0, y0): (i32, i32),
    (x1, y1): (i32, i32),
) -> Result<(), Fail> {
    let (bx, by) = area.get_base_pixel();
    let (w, h) = (x1 - x0, y1 - y0);
    if w <= 0 || h <= 0 {
        return Ok(());
    }
    // Lines x − x0 + (y1 − y) = c for c along the diagonal, each clipped to the rectangle.
    let mut c = HATCH / 2;
    while c < w + h {
        let (a, b) = ((c - h).max(0), c.min(w));
        let p = (x0 + a - bx, y1 - (c - a) - by);
        let q = (x0 + b - bx, y1 - (c - b) - by);
        area.draw(&PathElement::new(
            vec![p, q],
            WHITE.stroke_width(HATCH_WIDTH),
        ))?;
        c += HATCH;
    }
    Ok(())
}

/// Fig 13's key entries: text and fill (none: the crossover dot).
const FIG13_KEY: [(&str, Option<RGBColor>); 3] = [
    // ZP's name as lloyd2006-fig12 and -worst-case key it behind, where ZP+W equals it
    // (seventh review, R7-X-2).
    ("ZP = ZP+W lowest", Some(ZP_FILL)),
    ("FP+ZP+W lowest", Some(FP_FILL)),
    ("equal S̄", None),
];

/// Fig 13's key laid out on a row `width` units wide: the entries' widths and the rows (ranges
/// of entries), as many on a row as fit.
fn fig13_key_rows<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    width: i32,
) -> Result<(Vec<i32>, Vec<std::ops::Range<usize>>), Fail> {
    let style = TextStyle::from((FONT, 13).into_font());
    let (swatch, gap, between) = (14, 5, 18);
    let widths = FIG13_KEY
        .iter()
        .map(|(t, _)| {
            area.estimate_text_size(t, &style)
                .map(|s| swatch + gap + s.0 as i32)
        })
        .collect::<Result<Vec<_>, _>>()?;
    let mut rows = Vec::new();
    let (mut start, mut used) = (0, 0);
    for (i, w) in widths.iter().enumerate() {
        if i > start && used + between + w > width {
            rows.push(start..i);
            (start, used) = (i, 0);
        }
        used += if i > start { between } else { 0 } + w;
    }
    rows.push(start..widths.len());
    Ok((widths, rows))
}

/// Height of one row of Fig 13's key.
const KEY_ROW: u32 = 22;

/// Fig 13's key: a swatch of each fill and the crossover dot, each with its meaning, in as few
/// rows as fit, centred, below the chart (it was two boxes inside the chart, over the fills).
fn draw_fig13_key<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
    let style = TextStyle::from((FONT, 13).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
    let (w, _) = area.dim_in_pixel();
    let (widths, rows) = fig13_key_rows(area, w as i32 - 8)?;
    let (swatch, gap, between) = (14, 5, 18);
    for (r, row) in rows.into_iter().enumerate() {
        let y = 4 + (KEY_ROW as i32) * r as i32 + KEY_ROW as i32 / 2;
        let total: i32 = widths[row.clone()].iter().sum::<i32>() + between * (row.len() as i32 - 1);
        let mut x = (w as i32 - total) / 2;
        for i in row {
            let (text, fill) = FIG13_KEY[i];
            match fill {
                Some(c) => {
                    area.draw(&Rectangle::new(
                        [(x, y - swatch / 2), (x + swatch, y + swatch / 2)],
                        c.filled(),
                    ))?;
                    if c == FP_FILL {
                        let (bx, by) = area.get_base_pixel();
                        hatch(
                            area,
                            (x + bx, y - swatch / 2 + by),
                            (x + swatch + bx, y + swatch / 2 + by),
                        )?;
                    }
                    area.draw(&Rectangle::new(
                        [(x, y - swatch / 2), (x + swatch, y + swatch / 2)],
                        RGBColor(120, 120, 120).stroke_width(1),
                    ))?;
                }
                None => area.draw(&Circle::new((x + swatch / 2, y), 4, PALETTE[6].filled()))?,
            }
            area.draw(&Text::new(text, (x + swatch + gap, y), style.clone()))?;
            x += widths[i] + between;
        }
    }
    Ok(())
}

impl Figure for Fig13 {
    fn size(&self) -> (u32, u32) {
        (520, 570)
    }

    /// One column: the chart under a key of two rows, above a caption of five lines.
    fn single_size(&self) -> Option<(u32, u32)> {
        Some((Column::Single.width(), SINGLE_HEIGHT))
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        // The crossover at k = 4 (17 maps), Fig 12's.
        let j4 = shadow_map_count(Scheme::FpZpW, SchemeLight::Behind, 4)? as f64;
        let (j, at) = self
            .crossover
            .iter()
            .copied()
            .find(|p| p.0 == j4)
            .ok_or_else(|| Fail::Draw(format!("Fig 13 has no crossover at {j4} maps")))?;
        // From j = 33 on the crossover lies above the axis (its column is FP+ZP+W's to the
        // top): the plot shows it, docs/figures.md says it (the caption has five lines at most).
        // Eq 21's faces: tan θ_eff of each face's sub-frustum read back from FP+ZP+W's S̄
        // behind for the frustum of Fig 12 (θ = 30°), 4k((f/n)^{1/k} − 1)/(2 tan θ_eff) + 1.
        let view = ViewFrustum::new(1.0, FIG12_RATIO, THETA_DEG.to_radians())?;
        let k = 4.0;
        let fp = scheme_storage_factor(Scheme::FpZpW, SchemeLight::Behind, &view, 4)?;
        let tan_eff = 4.0 * k * (FIG12_RATIO.powf(1.0 / k) - 1.0) / (2.0 * (fp - 1.0));
        let caption = match column() {
            Column::Double => format!(
                "Lloyd et al. 2006, Fig. 13 (Eq 20, 21). {SCHEME_WORDS} ZP (= ZP+W) \
                 with j maps against FP+ZP+W with k z-partitions per face, \
                 j\u{a0}=\u{a0}4k\u{a0}+\u{a0}1. Below the dot FP+ZP+W needs less storage; above it, ZP. With {j} maps the dot is \
                 at f/n\u{a0}=\u{a0}{at:.0}. The boundary does not depend on θ: Eq 20 has \
                 no θ, and Eq 21's face sub-frusta always have \
                 tan\u{a0}θ_{{eff}}\u{a0}=\u{a0}{}.",
                fmt_plain(tan_eff),
            ),
            Column::Single => format!(
                "Lloyd et al. 2006, Fig. 13 (Eq 20, 21). {SCHEME_WORDS} \
                 ZP with j maps, FP+ZP+W with k z-partitions per face, \
                 j\u{a0}=\u{a0}4k\u{a0}+\u{a0}1; FP+ZP+W needs less below the dot \
                 (f/n\u{a0}=\u{a0}{at:.0} at {j})."
            ),
        };
        let body = frame(
            root,
            "Lowest-error partitioning, light behind",
            &[caption.as_str()],
        )?;
        // The key below the chart, where every figure has its key, in as many rows as it needs.
        let rows = fig13_key_rows(&body, body.dim_in_pixel().0 as i32 - 8)?
            .1
            .len() as u32;
        let h = body.dim_in_pixel().1;
        let (plot, key) = body.split_vertically(h.saturating_sub(KEY_ROW * rows + 8));
        draw_fig13_key(&key)?;
        let mut chart = build_chart(&plot, "", &self.x, &self.y, true)?;
        let (y0, y1) = self.y.range();
        let half = 1.3;
        for &(j, r) in &self.crossover {
            let Some(ry) = self.y.to_axis(r) else {
                continue;
            };
            let mid = ry.clamp(y0, y1);
            chart.draw_series([
                Rectangle::new([(j - half, mid), (j + half, y1)], ZP_FILL.filled()),
                Rectangle::new([(j - half, y0), (j + half, mid)], FP_FILL.filled()),
            ])?;
            let (a, b) = (
                chart.backend_coord(&(j - half, mid)),
                chart.backend_coord(&(j + half, y0)),
            );
            hatch(&chart.plotting_area().strip_coord_spec(), a, b)?;
            if ry <= y1 {
                chart.draw_series(std::iter::once(Circle::new(
                    (j, ry),
                    4,
                    PALETTE[6].filled(),
                )))?;
            }
        }
        Ok(())
    }
}
