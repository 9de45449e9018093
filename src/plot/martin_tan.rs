//! Martin & Tan 2004 Fig 6: the area of the focus region in the shadow map against the light
//! direction, measured on the crate's TSM matrices.
//!
//! The focus region is the eye's frustum truncated at δ beyond the near plane (Martin & Tan
//! §6.2). For each light direction the trapezoidal map is built by [`crate::maps::tsm::tsm`]
//! (the 80 % rule, and the iterative variant over the map's lines), which reports the fraction of
//! the map the focus region covers ([`crate::maps::tsm::TsmMap::focus_area`]).

use super::chart::{
    column, draw_colour_bar_across, draw_hemisphere_keyed, draw_line_chart, linspace, Axis,
    ColourScale, LineChart, Marker, PolarGrid, Series, PALETTE,
};
use super::hemisphere::{draw_bar, frame_by_column, BAR_WIDTH};
use super::Column;
use super::{Fail, Figure};
use crate::maps::tsm::{tsm, TsmOptions, TsmSearch};
use crate::ViewFrustum;
use glam::DVec3;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::f64::consts::{FRAC_PI_2, TAU};

/// The focus distance δ beyond the near plane (as in Zhang Fig 3).
const FOCUS: f64 = super::zhang::TSM_FOCUS;

/// Hemisphere grid: elevation rows (both ends) and azimuth columns, every 1° (at 3° the cells
/// showed as steps along the dueling-frusta bands).
const ELEVATIONS: usize = 91;
const AZIMUTHS: usize = 360;

/// The shape that marks the 80 % rule's values exactly behind and in front (0° and 180°), as
/// the caption and the legend say; no line of the profile carries it (the 80 % rule's line
/// has circles, the iterative one's squares).
const JUMP_MARKER: Marker = Marker::Diamond;
/// The profile's colours: neither is a scheme's (both lines are TSM's): the 80 % rule black,
/// the iterative variant reddish purple (apart in greyscale, and by dash and marker).
const EIGHTY: RGBColor = PALETTE[6];
const ITERATIVE: RGBColor = PALETTE[3];
/// How far (a)'s panel starts below (b)'s, in units, so that their titles stand level: a line
/// chart's title sits under its 8-unit margin and plotters' own 5 (`chart::build_chart`), a
/// hemisphere's 4 units from its top (`chart::draw_hemisphere`).
const TITLE_ALIGN: u32 = 8 + 5 - 4;
/// The same shape in the caption's text.
const JUMP_GLYPH: &str = "◆";

/// The direction light travels for elevation `el` and azimuth `az` (radians), as in
/// [`crate::scheme::sweep`]: the source lies towards (cos el · sin az, sin el, cos el · cos az);
/// az = 0 behind the viewer, π in front, el = π/2 overhead.
fn light_dir(el: f64, az: f64) -> DVec3 {
    let (se, ce) = el.sin_cos();
    let (sa, ca) = az.sin_cos();
    -DVec3::new(ce * sa, se, ce * ca)
}

/// The fraction of the shadow map the focus region covers for a light travelling along `dir`.
fn focus_area(view: &ViewFrustum, dir: DVec3, search: TsmSearch) -> Result<f64, crate::Error> {
    Ok(tsm(
        view,
        dir,
        TsmOptions {
            focus: FOCUS,
            search,
        },
    )?
    .focus_area)
}

pub(super) struct Fig6 {
    grid: PolarGrid,
    scale: ColourScale,
    profile: LineChart,
    caption: Vec<String>,
    /// The shorter caption of a single column.
    single_caption: String,
}

pub(super) fn fig6() -> Result<Fig6, Fail> {
    let view = ViewFrustum::new(1.0, 100.0, 30f64.to_radians())?;
    let de = FRAC_PI_2 / (ELEVATIONS - 1) as f64;
    let da = TAU / AZIMUTHS as f64;
    let mut values = Vec::with_capacity(ELEVATIONS * AZIMUTHS);
    for i in 0..ELEVATIONS {
        for j in 0..AZIMUTHS {
            let dir = light_dir(i as f64 * de, j as f64 * da);
            values.push(Some(focus_area(&view, dir, TsmSearch::EightyPercent)?));
        }
    }
    let (lo, hi) = values
        .iter()
        .flatten()
        .fold((f64::INFINITY, 0.0f64), |(a, b), &v| (a.min(v), b.max(v)));
    let grid = PolarGrid {
        elev_edges: (0..=ELEVATIONS)
            .map(|i| (i as f64 * de - 0.5 * de).clamp(0.0, FRAC_PI_2))
            .collect(),
        az_edges: (0..=AZIMUTHS).map(|j| j as f64 * da - 0.5 * da).collect(),
        values,
    };
    // The vertical plane: from behind the viewer (0°) over the top (90°) to in front (180°).
    let angles = linspace(0.0, 180.0, 361);
    let mut eighty = Vec::with_capacity(angles.len());
    let mut iterative = Vec::with_capacity(angles.len());
    for &a in &angles {
        let r = a.to_radians();
        let dir = DVec3::new(0.0, -r.sin(), -r.cos());
        eighty.push((a, focus_area(&view, dir, TsmSearch::EightyPercent)?));
        iterative.push((
            a,
            focus_area(&view, dir, TsmSearch::Iterative { map_lines: 1024 })?,
        ));
    }
    // One range for the share in both panels, whole decades round every value: the colour
    // bar and the profile's axis carry the same ticks, 10⁻³ … 10⁰ (review: the bar wrote
    // 0.491, 0.1, 0.01, 0.00268 beside the axis's powers of ten).
    let floor = profile_floor(&eighty, &iterative).min(10f64.powf(lo.log10().floor()));
    let ceil = 10f64.powf(hi.log10().ceil()).max(1.0);
    let mut profile = LineChart::new(
        "(b) in the view's vertical plane",
        // A tick every 45°: behind, overhead and in front are ticks; the axis reaches 6° past
        // both ends, so that the marks at 0° and 180° stand inside the frame, not on it.
        // The angle is the light's elevation in that plane, from behind on the horizon (fifth
        // review: "angle from behind" did not say what it measures).
        // Labelled 0, 45, 90, 45, 0, behind on the left, in front on the right, as the
        // captions say (sixth review: 135 and 180 read as elevations, which end at 90).
        Axis::every(X_NAME, -6.0, 186.0, 0.0, 45.0).folded_at(90.0),
        Axis::log10("share of the map (log scale)", floor, ceil).in_powers(),
    );
    // Which 0 is which, in every form (the tenth review, R10-martin-tan-fig6-1: only the
    // two-column caption said so): "behind" under the first 0, "in front" under the last.
    profile.x_ends = Some([(0.0, "behind".into()), (180.0, "in front".into())]);
    // The figure's one key, under the profile, the only panel with lines.
    profile.legend_below = true;
    // The 80 % rule jumps back to the dueling-frusta value exactly behind and in front (0° and
    // 180°): those two points marked with a shape of their own (the lines carry theirs along
    // them), unjoined, drawn last (over the lines' markers).
    let (first, last) = (eighty[0], eighty[eighty.len() - 1]);
    let dueling = first.1;
    // Just off behind the 80 % rule collapses the trapezoid: its share falls below the
    // exact-behind value up to this elevation (the sixth review, R6-martin-tan-fig6-4: the
    // jump read as a plotting glitch).
    let collapse = collapse_end(&eighty, dueling);
    profile.series.push(Series {
        shape: Some(Marker::Circle),
        ..Series::line("80 % rule", eighty, EIGHTY)
    });
    profile.series.push(Series {
        shape: Some(Marker::Square),
        ..Series::line("iterative", iterative, ITERATIVE).dashed()
    });
    profile.series.push(Series {
        shape: Some(JUMP_MARKER),
        ..Series::line(
            "80 % rule exactly behind, in front",
            vec![first, (90.0, f64::NAN), last],
            EIGHTY,
        )
        .with_markers()
    });
    let (n, f, theta) = (view.near(), view.far(), view.half_fov().to_degrees());
    Ok(Fig6 {
        grid,
        // Logarithmic, as the profile: the dueling-frusta band near the horizon (0.003 to
        // 0.01) is two decades below overhead (0.49) and would be one colour on a linear bar.
        scale: ColourScale::smooth(
            Axis::log10("(a) share of the map (log scale)", floor, ceil).in_powers(),
        ),
        profile,
        caption: vec![format!(
            "Martin & Tan 2004, Fig. 6: the focus region's (n to n\u{a0}+\u{a0}δ) share of \
             the trapezoidal map. (a) The paper's 80\u{a0}% rule (rings: elevation 10°, 20°, \
             30°, 60°; line: (b)'s plane); (b) in the view's vertical plane (0° behind, 90° \
             overhead, 0° in front), also the iterative variant (1024 lines). \
             n\u{a0}=\u{a0}{n}, f\u{a0}=\u{a0}{f}, θ\u{a0}=\u{a0}{theta:.0}°, \
             δ\u{a0}=\u{a0}{FOCUS}. {JUMP_GLYPH}: behind or in front, {dueling:.4}; the \
             80\u{a0}% rule collapses below {JUMP_GLYPH} up to {collapse:.0}° from behind.",
        )],
        single_caption: format!(
            "Martin & Tan 2004, Fig. 6: the focus region's (n to n\u{a0}+\u{a0}δ) share of \
             the trapezoidal map; (a) the 80\u{a0}% rule; rings: elevation 10°, 20°, 30°, \
             60°; line: (b)'s plane (90° overhead); n\u{a0}=\u{a0}{n}, f\u{a0}=\u{a0}{f}, \
             θ\u{a0}=\u{a0}{theta:.0}°, δ\u{a0}=\u{a0}{FOCUS}; {JUMP_GLYPH}: {dueling:.4}."
        ),
    })
}

/// The largest elevation from behind (the profile's angle up to 90°) at which the 80 % rule's
/// share is below `exact`, its value exactly behind; 0 where none is.
fn collapse_end(eighty: &[(f64, f64)], exact: f64) -> f64 {
    eighty
        .iter()
        .filter(|&&(a, v)| a > 0.0 && a <= 90.0 && v < exact)
        .map(|&(a, _)| a)
        .fold(0.0, f64::max)
}

/// The bottom of the profile's logarithmic axis: a power of ten below the smallest area.
fn profile_floor(a: &[(f64, f64)], b: &[(f64, f64)]) -> f64 {
    let min = a
        .iter()
        .chain(b)
        .map(|p| p.1)
        .filter(|&v| v > 0.0)
        .fold(1.0f64, f64::min);
    10f64.powf(min.log10().floor())
}

impl Figure for Fig6 {
    fn size(&self) -> (u32, u32) {
        (520, 470 + BAR_CAPTION_GAP)
    }

    /// One column: the hemisphere with its bar beside it, over the profile.
    fn single_size(&self) -> Option<(u32, u32)> {
        Some((Column::Single.width(), 520))
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let single = column() == Column::Single;
        // One column sets a title that keeps one line.
        let body = frame_by_column(
            root,
            [
                "Area of the focus region in the trapezoidal map",
                "Focus region's share of the map",
            ],
            &self.caption,
            &self.single_caption,
        )?;
        let (w, h) = body.dim_in_pixel();
        if single {
            // The hemisphere with its bar upright beside it (its name right of its ticks,
            // nothing beside it); the profile under them, its key in one column.
            // (b) has the larger share (the fifth review: 0.8 in for three decades, its markers
            // crowded; the disk needs less).
            let (top, bottom) = body.split_vertically(h * 33 / 100);
            let (tw, th) = top.dim_in_pixel();
            let (disk, _) = top.split_horizontally(tw.saturating_sub(BAR_WIDTH));
            let rows =
                draw_hemisphere_keyed(&disk, PANEL_A_SINGLE, &self.grid, &self.scale, true, true)?;
            // The bar's name no taller than the disk.
            let mut scale = self.scale.clone();
            scale.axis.label = "(a) share (log scale)".into();
            // As tall as the disk: the bar's chart keeps 30 units under the disk's bottom for
            // its end label, more than (a)'s share of the height leaves under a disk that
            // fills it, so its column reaches into the profile's (empty there: the profile's
            // title stands lower, its plot right of its y ticks).
            let bar = body.clone().shrink(
                (tw.saturating_sub(BAR_WIDTH), 0),
                (BAR_WIDTH, (th + 30).min(h)),
            );
            draw_bar(&bar, &scale, rows)?;
            let mut profile = self.profile.clone();
            profile.legend_columns = Some(1);
            // The axis's name no longer than the shorter axis.
            profile.y.label = "share (log scale)".into();
            draw_line_chart(&bottom, &profile)?;
        } else {
            // The hemisphere at the top of its column, its title level with the profile's
            // beside it, and its bar across under it, named under its ticks (upright beside
            // the disk, its name stood next to the profile's y name and read as one with it).
            let (left, right) = body.split_horizontally(w * 27 / 50);
            let left = left.margin(TITLE_ALIGN, 0, 0, 0);
            let (lw, lh) = left.dim_in_pixel();
            let side = lw.min(lh.saturating_sub(28 + BAR_ACROSS + BAR_CAPTION_GAP));
            let (disk, rest) = left.split_vertically(28 + side);
            draw_hemisphere_keyed(&disk, PANEL_A, &self.grid, &self.scale, true, true)?;
            let (bar, _) = rest.split_vertically(BAR_ACROSS);
            draw_colour_bar_across(&bar.margin(4, 0, 16, 16), &self.scale)?;
            draw_line_chart(&right, &self.profile)?;
        }
        Ok(())
    }
}

/// (b)'s x axis's name: the light's elevation in the view's vertical plane, from 0° behind on
/// the horizon through 90° overhead to 0° in front (the captions say so).
const X_NAME: &str = "light's elevation (°)";

/// (a)'s title.
const PANEL_A: &str = "(a) 80 % rule over the hemisphere";
/// (a)'s title in one column, as wide as its disk's panel allows.
const PANEL_A_SINGLE: &str = "(a) 80 % rule";

/// The height of a colour bar laid across, with its tick labels and name, in units.
const BAR_ACROSS: u32 = 58;

/// The room left under the bar laid across (two columns), in units: its name "(a) share of the
/// map (log scale)" stood 5 units over the caption and read as the caption's first line
/// (R7-MT6-1); the figure is that much taller, the disk as large as before.
const BAR_CAPTION_GAP: u32 = 12;

#[cfg(test)]
mod tests {
    use super::*;

    /// The caption's marker claim is what the profile draws (figure review: it said
    /// "markers: exactly behind and in front" while the lines carry markers all along), and
    /// the marks stand inside the frame and in the legend (review: on the frame, and in no
    /// key). Read back from the profile's SVG: exactly three polygons are diamonds (four
    /// corners, the top and bottom on one vertical, the left and right on one horizontal), the
    /// shape the caption names: one in the legend, below the plot, and two at the 80 % rule's
    /// line's left and right ends (0° and 180°), at one height (the same share, ((n + δ)/f)² =
    /// (11/100)² = 0.0121 by hand, which the caption prints), each at least 4 units inside the
    /// plot's left and right axes (their tick marks' ends); the lines' own markers are other
    /// shapes.
    #[test]
    fn the_caption_names_the_marks_exactly_behind_and_in_front() {
        use super::super::chart::read_svg::draw_svg;
        let fig = fig6().map_err(|e| e.named("martin-tan-fig6")).unwrap();
        let caption = fig.caption.join(" ");
        assert!(
            caption.contains("◆: behind or in front, 0.0121;"),
            "{caption}"
        );
        let svg = draw_svg((300, 300), |area| {
            draw_line_chart(area, &fig.profile).unwrap();
        });
        let points = |l: &str| crate::plot::chart::read_svg::points(l).unwrap();
        let polygons: Vec<Vec<(f64, f64)>> = svg
            .lines()
            .filter(|l| l.starts_with("<polygon"))
            .map(points)
            .collect();
        let diamond = |p: &Vec<(f64, f64)>| {
            p.len() == 4
                && (p[0].0 - p[2].0).abs() < 0.01
                && (p[1].1 - p[3].1).abs() < 0.01
                && (p[0].1 - p[1].1).abs() > 1.0
        };
        let mut diamonds: Vec<(f64, f64)> = polygons
            .iter()
            .filter(|p| diamond(p))
            .map(|p| (p[0].0, p[1].1))
            .collect();
        assert_eq!(diamonds.len(), 3, "{diamonds:?}");
        assert!(polygons.len() > 6, "the lines carry markers of their own");
        // The lowest is the legend's.
        diamonds.sort_by(|a, b| a.1.total_cmp(&b.1));
        let key = diamonds.pop().unwrap();
        // The ends of the 80 % rule's line (black, hundreds of points; the legend's sample has
        // two).
        let xs: Vec<f64> = svg
            .lines()
            .filter(|l| l.starts_with("<polyline") && l.contains("stroke=\"#000000\""))
            .filter(|l| l.matches(',').count() > 50)
            .flat_map(|l| points(l).into_iter().map(|p| p.0).collect::<Vec<_>>())
            .collect();
        let (left, right) = (
            xs.iter().copied().fold(f64::INFINITY, f64::min),
            xs.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        );
        diamonds.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (a, b) = (diamonds[0], diamonds[1]);
        assert!(
            (a.0 - left).abs() < 1.0 && (b.0 - right).abs() < 1.0,
            "{diamonds:?} {left} {right}"
        );
        assert!((a.1 - b.1).abs() < 0.01, "{diamonds:?}");
        assert!(
            key.1 > a.1 + 30.0,
            "the key's mark {key:?}, the plot's {diamonds:?}"
        );
        // The plot's left and right edges: the y axis's tick marks (5 units, horizontal) end
        // at the left axis; the x axis's (vertical) lie from the first to the last tick, and
        // the frame runs 6° beyond them: the axis ends are found from the ticks at 0° and 180°
        // and the axis range, −6° to 186°.
        let ticks: Vec<Vec<(f64, f64)>> = svg
            .lines()
            .filter(|l| l.starts_with("<polyline"))
            .map(points)
            .filter(|p| p.len() == 2)
            .collect();
        let axis_x = ticks
            .iter()
            .filter(|p| p[0].1 == p[1].1 && (p[1].0 - p[0].0).abs() == 5.0)
            .map(|p| p[0].0.max(p[1].0))
            .fold(f64::INFINITY, f64::min);
        assert!(a.0 - axis_x >= 4.0, "{a:?}, the axis at {axis_x}");
        let per_degree = (right - left) / 180.0;
        let frame_right = right + 6.0 * per_degree;
        assert!(
            frame_right - b.0 >= 4.0,
            "{b:?}, the frame at {frame_right}"
        );
    }

    #[test]
    fn dueling_frusta_area_by_hand() {
        let fig = fig6().map_err(|e| e.named("martin-tan-fig6")).unwrap();
        let want = (11.0f64 / 100.0).powi(2);
        for s in &fig.profile.series {
            let first = s.points[0];
            let last = *s.points.last().unwrap();
            assert_eq!((first.0, last.0), (0.0, 180.0));
            assert!((first.1 - want).abs() < 1e-9, "{}", first.1);
            assert!((last.1 - want).abs() < 1e-9, "{}", last.1);
        }
        // The same directions in the hemisphere grid: horizon row, azimuth 0 and π.
        let behind = fig.grid.values[0].unwrap();
        let front = fig.grid.values[AZIMUTHS / 2].unwrap();
        assert!((behind - want).abs() < 1e-9 && (front - want).abs() < 1e-9);
    }

    /// The hemisphere's colour bar is logarithmic (issue 25): the dueling-frusta value 0.0121
    /// and the overhead one (about 0.49) lie 1.6 decades apart, and on the bar's log₁₀ axis the
    /// dueling value sits at (log 0.0121 − log lo)/(log hi − log lo) of its height (a linear bar
    /// would put it in the bottom 3 %, one colour with everything below). Its range is the
    /// whole decades round the values, 10⁻³ to 10⁰ (the smallest share, about 0.0027 near the
    /// horizon, by `dueling_frusta_area_by_hand`'s neighbours; the largest below 1), the same as
    /// the profile's axis, and both write their ticks as powers of ten (review: the bar wrote
    /// 0.491, 0.1, 0.01, 0.00268).
    #[test]
    fn hemisphere_colour_bar_is_logarithmic_and_shares_the_profiles_ticks() {
        use super::super::chart::colour_bar_ticks;
        let fig = fig6().map_err(|e| e.named("martin-tan-fig6")).unwrap();
        let v: Vec<f64> = fig.grid.values.iter().flatten().copied().collect();
        let (lo, hi) = v
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(a, b), &x| (a.min(x), b.max(x)));
        assert!(
            (0.001..0.01).contains(&lo) && (0.1..1.0).contains(&hi),
            "{lo} {hi}"
        );
        let axis = &fig.scale.axis;
        for (a, b) in [axis.range(), fig.profile.y.range()] {
            assert!((a + 3.0).abs() < 1e-12 && b.abs() < 1e-12, "{a} {b}");
        }
        let t = (0.0121f64.log10() + 3.0) / 3.0;
        let level = fig.scale.level(0.0121).unwrap() as f64 / fig.scale.levels as f64;
        assert!(
            (level - t).abs() < 1.5 / fig.scale.levels as f64,
            "{level} vs {t}"
        );
        assert!(t > 0.2, "{t}");
        let bar: Vec<String> = colour_bar_ticks(axis).into_iter().map(|t| t.1).collect();
        assert_eq!(bar, ["10⁻³", "10⁻²", "10⁻¹", "10⁰"]);
        let y = &fig.profile.y;
        let profile: Vec<String> = y.ticks().0.iter().map(|&a| y.tick_label(a)).collect();
        assert_eq!(profile, bar);
    }

    /// The panels' titles stand level in two columns (review: (a)'s was about 10 units above
    /// (b)'s), and the x axis's name is no wider than its axis (review: it ran past the axis's
    /// end): read from the figure's SVG, the two titles' y are equal, and the name's width
    /// (DejaVu Sans measured by the backend at its size) is at most the axis's length, −6° to
    /// 186° (from the ticks at 0° and 180°).
    #[test]
    fn titles_are_level_and_the_x_name_fits_its_axis() {
        use super::super::chart::read_svg::{draw_svg, texts};
        let fig = fig6().map_err(|e| e.named("martin-tan-fig6")).unwrap();
        let mut name_w = 0.0;
        let svg = draw_svg(fig.size(), |area| {
            fig.draw(area).unwrap();
            let style = TextStyle::from((super::super::chart::FONT, 15).into_font());
            name_w = f64::from(
                area.estimate_text_size(&fig.profile.x.label, &style)
                    .unwrap()
                    .0,
            );
        });
        let all = texts(&svg);
        let y = |start: &str| all.iter().find(|t| t.1.starts_with(start)).unwrap().2;
        assert_eq!(y("(a) 80"), y("(b) in the"));
        let x = |label: &str| -> f64 {
            let (line, _, _) = all
                .iter()
                .rev()
                .find(|t| t.1 == label && t.0.contains("text-anchor=\"middle\""))
                .unwrap();
            super::super::chart::read_svg::attr(line, "x").unwrap()
        };
        // The axis runs 6° past both end ticks (both labelled "0"): 192° in all.
        let zeros: Vec<f64> = all
            .iter()
            .filter(|t| t.1 == "0" && t.0.contains("text-anchor=\"middle\""))
            .map(|t| super::super::chart::read_svg::attr(t.0, "x").unwrap())
            .collect();
        let ends = zeros.iter().copied().fold(f64::NEG_INFINITY, f64::max)
            - zeros.iter().copied().fold(f64::INFINITY, f64::min);
        let axis = ends * 192.0 / 180.0;
        let _ = x;
        assert!(name_w > 50.0 && name_w <= axis, "{name_w} vs {axis}");
    }

    /// The fifth review on martin-tan-fig6: (b)'s x axis names the angle as the light's
    /// elevation (it read "angle from behind"), and the captions say where 90° is; in one
    /// column (b)'s plot is at least 80 units tall (it was 68: three decades in 0.8 in), read
    /// from the SVG as the distance between its top and bottom y tick labels (the leftmost
    /// powers of ten; the bar's stand right of the disk).
    #[test]
    fn profile_names_the_elevation_and_is_taller_in_one_column() {
        use super::super::chart::read_svg::{attr, texts};
        use super::super::hemisphere::svg_in;
        let fig = fig6().map_err(|e| e.named("martin-tan-fig6")).unwrap();
        assert!(fig.profile.x.label.contains("elevation"));
        assert!(fig.caption.join(" ").contains("90° overhead"));
        // The x axis names the elevation; the caption where it is 0 and 90.
        assert!(fig
            .caption
            .join(" ")
            .contains("(0° behind, 90° overhead, 0° in front)"));
        assert!(fig.single_caption.contains("90° overhead"));
        let svg = svg_in(&fig, Column::Single);
        let all = texts(&svg);
        // The name as drawn (the SVG escapes its apostrophe).
        assert!(all.iter().any(|t| t.1.contains("elevation (°)")));
        let ticks: Vec<(f64, f64)> = all
            .iter()
            .filter(|t| t.0.contains(">10<tspan"))
            .map(|t| (attr(t.0, "x").unwrap(), t.2))
            .collect();
        let left = ticks.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
        let ys: Vec<f64> = ticks
            .iter()
            .filter(|p| p.0 < left + 10.0)
            .map(|p| p.1)
            .collect();
        assert_eq!(ys.len(), 4, "{ticks:?}");
        let span = ys.iter().copied().fold(0.0, f64::max)
            - ys.iter().copied().fold(f64::INFINITY, f64::min);
        assert!(span >= 80.0, "(b) spans {span} units");
    }

    /// The sixth review (R6-martin-tan-fig6-1): (b)'s axis ran 0 to 180 under the name
    /// "elevation", which ends at 90°. Its tick labels, left to right, now read 0, 45, 90, 45,
    /// 0 (behind to in front: elevations 180 − a past overhead) and no label reads 135 or 180,
    /// in both forms; the two-column caption says which 0 is behind.
    #[test]
    fn profile_elevations_fold_at_overhead() {
        use super::super::chart::read_svg::{attr, texts};
        use super::super::hemisphere::svg_in;
        let fig = fig6().map_err(|e| e.named("martin-tan-fig6")).unwrap();
        for column in [Column::Double, Column::Single] {
            let svg = svg_in(&fig, column);
            let all = texts(&svg);
            let name = all
                .iter()
                .find(|t| t.1.contains("elevation (°)"))
                .unwrap_or_else(|| panic!("{column:?}: no axis name"));
            assert!(name.1.ends_with("elevation (°)"), "{column:?}: {}", name.1);
            // Which 0 is which: the two-column caption says; one column's (a) writes
            // "← behind" and "in front →" over its disk, above (b).
            let caption = fig.caption.join(" ");
            assert!(
                caption.contains("0° behind, 90° overhead, 0° in front"),
                "{caption}"
            );
            // The x tick labels: centred numbers on the lowest row of numbers under (b).
            let ticks: Vec<(f64, f64, &str)> = all
                .iter()
                .filter(|t| {
                    t.0.contains("text-anchor=\"middle\"")
                        && !t.0.contains("<tspan")
                        && t.1.parse::<f64>().is_ok()
                })
                .map(|t| (attr(t.0, "x").unwrap(), t.2, t.1.as_str()))
                .collect();
            let base = ticks.iter().map(|t| t.1).fold(f64::NEG_INFINITY, f64::max);
            let mut row: Vec<(f64, f64, &str)> = ticks
                .into_iter()
                .filter(|t| (t.1 - base).abs() < 0.5)
                .collect();
            row.sort_by(|a, b| a.0.total_cmp(&b.0));
            let read: Vec<&str> = row.iter().map(|t| t.2).collect();
            assert_eq!(read, ["0", "45", "90", "45", "0"], "{column:?}");
            assert!(
                !all.iter().any(|t| t.1 == "135" || t.1 == "180"),
                "{column:?}"
            );
        }
    }

    /// R7-MT6-1, read from the two-column SVG: the colour bar's name "(a) share of the map (log
    /// scale)" (anchored at its bottom) stands at least 12 units plus its descent (a quarter of
    /// its size) over the caption's first line (anchored at its top): it was 7 units, and read
    /// as the caption's first line.
    #[test]
    fn bar_name_stands_clear_of_the_caption() {
        use super::super::chart::read_svg::{attr, draw_svg, texts};
        let fig = fig6().map_err(|e| e.named("martin-tan-fig6")).unwrap();
        let svg = draw_svg(fig.size(), |area| fig.draw(area).unwrap());
        let all = texts(&svg);
        let name = all
            .iter()
            .find(|t| t.1 == "(a) share of the map (log scale)")
            .expect("the bar's name");
        assert!(name.0.contains("dy=\"-0.5ex\""), "{}", name.0);
        let caption = all
            .iter()
            .filter(|t| t.0.contains("fill=\"#323232\""))
            .map(|t| t.2)
            .fold(f64::INFINITY, f64::min);
        let descent = 0.25 * attr(name.0, "font-size").unwrap();
        assert!(
            caption - name.2 >= 12.0 + descent,
            "the bar's name at y {} (bottom), the caption from {caption}",
            name.2
        );
    }
}
