//! The view frustum as seen from the light, with its z-partitions: Barroso & Celes 2007 Fig 5
//! (a light above and in front, self-similar partitions of their Eq 5 and the adaptive ones of
//! their Eq 19) and Lloyd et al. 2006 Fig 11 (the light behind the viewer: the frustum looks
//! square, the near face inside the far one, and the side faces are trapezoids).
//!
//! The frustum's edges and the split planes' cross-sections are projected along the light with
//! the crate's light space ([`crate::maps::light_space`], the view direction as its axis); the
//! split depths come from [`crate::analytic::partition::z_splits`]. Each partition's orthographic
//! map (ZP) is the light-space bounding rectangle of its corners, its outline drawn exactly on
//! it, dashed, so that the overlap of the maps shows.

use super::Fail;
use crate::analytic::partition::{z_splits, SplitScheme};
use crate::maps::light_space;
use crate::scheme::ADAPTIVE_RATIO;
use crate::ViewFrustum;
use glam::{DVec2, DVec3};

mod draw;

/// One panel: a light, its split depths and what it shows.
pub(super) struct Panel {
    pub title: String,
    /// Cross-sections of the frustum at each split depth (4 light-space corners each), near first.
    pub sections: Vec<[DVec2; 4]>,
    /// Each partition's bounding rectangle in light space (min, max).
    pub maps: Vec<(DVec2, DVec2)>,
    pub planes: Vec<f64>,
    /// The light-space window shown (min, max); `None`: the whole frustum.
    pub window: Option<(DVec2, DVec2)>,
    /// Each split plane's label (its depth z by default).
    pub plane_labels: Vec<String>,
    /// Dimension lines: from, to, the label, and whether the label is set in a break of the
    /// line (centred on it) rather than under it; such a line is given at the edge it
    /// measures and drawn below it, its label clear of the edge and of a map's outline on it.
    pub dims: Vec<(DVec2, DVec2, String, bool)>,
    /// Whether each labelled plane's leader starts at its section's top right corner only
    /// (lloyd2006-fig11: the sixth review, R6-lloyd2006-fig11-1, read "n = 1"'s leader from
    /// the near square's lower corner as the dimension's).
    pub top_leaders: bool,
    /// Whether the window grows only downward to hold the dimension lines' labels (by default
    /// it grows alike above, so that the drawing stays centred).
    pub grow_down: bool,
    /// Extension lines from the measured feature to its dimension line.
    pub extensions: Vec<[DVec2; 2]>,
    /// A point on a line and the line's name: a label in the gutter, its leader from the point
    /// (two columns only).
    pub notes: Vec<(DVec2, String)>,
    /// Whether the panel after this one (beside it, on its right) enlarges a region of it: that
    /// panel's axis limits, as drawn, outlined in grey here.
    pub enlarged: bool,
    /// Whether the maps' outlines are drawn fine (at most 2 units wide, each side dashed with
    /// whole periods of its map's pattern as they fit and print, or solid: `draw_maps.rs`) over
    /// the frustum's lines (barroso-fig5, R9-barroso-fig5-1), rather than wide, under them
    /// (lloyd2006-fig11).
    pub fine: bool,
    /// Whether each map is numbered, "1" to "4", at a corner of its rectangle (barroso-fig5's
    /// details (b), (d), (f); the eleventh review, R11-barroso-fig5-1).
    pub numbered: bool,
}

pub(super) struct FromLight {
    pub title: &'static str,
    /// The title of the one-column layout: one line there (about 36 characters).
    pub single_title: &'static str,
    pub caption: String,
    /// The caption of the one-column layout (at most five lines 300 units wide).
    pub single_caption: String,
    pub panels: Vec<Panel>,
    pub size: (u32, u32),
    /// The size of the one-column layout.
    pub single_size: (u32, u32),
}

/// The cross-section of the (square) view frustum at eye depth z, projected along the light.
fn section(view: &ViewFrustum, to: &impl Fn(DVec3) -> DVec2, z: f64) -> [DVec2; 4] {
    let t = view.tan_half_fov();
    let s = z * t;
    [
        to(DVec3::new(-s, -s, -z)),
        to(DVec3::new(s, -s, -z)),
        to(DVec3::new(s, s, -z)),
        to(DVec3::new(-s, s, -z)),
    ]
}

fn panel(view: &ViewFrustum, light: DVec3, planes: &[f64], title: String) -> Result<Panel, Fail> {
    let ls = light_space(light, DVec3::NEG_Z)?;
    let to = |p: DVec3| seen_from_light(ls.to_light(p));
    let sections: Vec<[DVec2; 4]> = planes.iter().map(|&z| section(view, &to, z)).collect();
    let maps = sections
        .windows(2)
        .map(|w| {
            let pts = w[0].iter().chain(&w[1]);
            let lo = pts
                .clone()
                .fold(DVec2::splat(f64::INFINITY), |a, &p| a.min(p));
            let hi = pts.fold(DVec2::splat(f64::NEG_INFINITY), |a, &p| a.max(p));
            (lo, hi)
        })
        .collect();
    Ok(Panel {
        title,
        sections,
        maps,
        plane_labels: plane_labels(planes),
        planes: planes.to_vec(),
        window: None,
        dims: Vec::new(),
        top_leaders: false,
        grow_down: false,
        extensions: Vec::new(),
        notes: Vec::new(),
        enlarged: false,
        fine: false,
        numbered: false,
    })
}

/// Each plane's label as Lloyd et al.'s Fig 11 writes them: the near and far planes by name,
/// "n = 1" and "f = 100", the split planes by depth, "z = 3.162" ([`fmt_planes`]).
fn plane_labels(planes: &[f64]) -> Vec<String> {
    let last = planes.len().saturating_sub(1);
    planes
        .iter()
        .enumerate()
        .map(|(i, &z)| {
            let z = fmt_planes(&[z]);
            match i {
                0 => format!("n = {z}"),
                i if i == last => format!("f = {z}"),
                _ => format!("z = {z}"),
            }
        })
        .collect()
}

/// Leaves the labels of the planes nearer than the `from`-th unlabelled: an overview panel
/// labels only its far planes, its detail panel the near ones.
fn label_from(p: &mut Panel, from: usize) {
    for l in &mut p.plane_labels[..from] {
        l.clear();
    }
}

/// A light-space point as the light sees it: `(−x, z)`, right and up in the light's view.
///
/// Light space's `x = y × z` with `y` toward the light, so an observer at the light looking
/// along `−y` with `z` up has `z × y = −x` on their right: drawing `x` to the right would show
/// the mirror image (figure review 2). Every diagram "seen from the light" draws this.
pub(super) fn seen_from_light(l: DVec3) -> DVec2 {
    DVec2::new(-l.x, l.z)
}

/// The labels of the axes of a diagram drawn by [`seen_from_light`]: right and up in the
/// light's view (figure review 5, X3: "light z" read as the eye depth z that the split planes'
/// labels give, and "−x in light space" named its partner in another form).
pub(super) const SEEN_X: &str = "light-view x";
pub(super) const SEEN_Y: &str = "light-view y";

/// lloyd2006-fig11's width in the two-column form: the page's 520 units, printed 520 pt, as
/// every two-column figure (the eighteenth review, R18-lloyd2006-fig11-1: at 346, the fifth
/// review's narrowing for X2, it was printed scaled 1.5× at 520 pt, its text 15.8 pt and its
/// page 676 pt tall). The diagram keeps the size it had on the 346-unit page, centred.
pub(crate) const FROM_BEHIND_WIDTH: u32 = 520;

/// lloyd2006-fig11's height in the two-column form: the 346-unit page's 450 less the rows that
/// the wider page saves, one of the key's two (19 units) and one of the caption's five (18),
/// so that the diagram's plot is as tall, and as large, as on that page.
pub(crate) const FROM_BEHIND_HEIGHT: u32 = 450 - 19 - 18;

/// The light-space bounding box (min, max) of some cross-sections.
fn bounds(sections: &[[DVec2; 4]]) -> (DVec2, DVec2) {
    sections.iter().flatten().fold(
        (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
        |(lo, hi), &p| (lo.min(p), hi.max(p)),
    )
}

/// Depths to 4 significant figures, trailing zeros dropped (31.62, 3.162, 1, 100).
fn fmt_planes(p: &[f64]) -> String {
    p.iter()
        .map(|&z| {
            let digits = 3 - z.abs().max(1e-300).log10().floor().clamp(-20.0, 3.0) as i32;
            let d = digits.max(0) as usize;
            let s = format!("{z:.d$}");
            if s.contains('.') {
                s.trim_end_matches('0').trim_end_matches('.').to_string()
            } else {
                s
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// Barroso & Celes 2007 Fig 5: k = 4 self-similar z-partitions (Eq 5) of n = 1, f = 100,
/// θ = 30° (half field of view), seen by (a) a light perpendicular to the view direction
/// (overhead) and (c) one parallel to it (behind the viewer); (e) the adaptive partitions of
/// Eq 19 for a light 45° above the view direction, which the paper's figure does not have; (b),
/// (d), (f) the near partitions of (a), (c), (e) enlarged: (b) maps 1 to 3 (z ≤ 31.62), (d)
/// maps 1 and 2 (z ≤ 10), (f) maps 1 to 3 (z ≤ 40.81).
pub(super) fn barroso_fig5() -> Result<FromLight, Fail> {
    let view = ViewFrustum::new(1.0, 100.0, 30f64.to_radians())?;
    let k = 4;
    let ss = z_splits(view.near(), view.far(), k, SplitScheme::SelfSimilar)?;
    let gamma = 45f64.to_radians();
    let ad = z_splits(
        view.near(),
        view.far(),
        k,
        SplitScheme::Adaptive {
            light_angle: gamma,
            ratio: ADAPTIVE_RATIO,
        },
    )?;
    // Light directions are the direction light travels; the view looks down −Z.
    let overhead = DVec3::NEG_Y;
    let behind = DVec3::NEG_Z;
    let tilted = DVec3::new(0.0, -gamma.sin(), -gamma.cos());
    // Each overview beside its detail, a row each (figure review 5: (a) over (c) and (d) beside
    // (c) sent the reader across the page for each detail): (a), (c), (e) the whole frustum,
    // (b), (d), (f) its near partitions enlarged, the region each enlarges a grey box in its
    // overview.
    // The titles say to what the light is perpendicular or parallel (the thirteenth review,
    // R13-barroso-fig5-2: "(c) parallel light" read as a directional light); ⊥ (U+22A5), as
    // DejaVu Sans has no ⟂ (U+27C2).
    let mut perpendicular = panel(&view, overhead, ss.planes(), "(a) light ⊥ view".into())?;
    // (b): the three nearest partitions of (a), enlarged (the ninth review, R9-barroso-fig5-1:
    // out to z = 10 only, no panel showed map 3, z = 10–31.62, larger than (a)'s 20 × 12 units).
    let (lo, hi) = bounds(&perpendicular.sections[..4]);
    let mut zoom = panel(
        &view,
        overhead,
        ss.planes(),
        format!("(b) detail of (a): z ≤ {}", fmt_planes(&ss.planes()[3..4])),
    )?;
    zoom.window = Some((lo, hi));
    let mut parallel = panel(&view, behind, ss.planes(), "(c) light ∥ view".into())?;
    let mut eq19 = panel(
        &view,
        tilted,
        ad.planes(),
        "(e) Eq 19, not in the paper".into(),
    )?;
    // (d), (f): (c) and (e) near the eye, where their inner partitions are sub-pixel or their
    // maps overlap in a tangle (figure review 2): the windows round the nearest three and four
    // planes (z ≤ 10 and z ≤ 40.81).
    let mut zoom_b = panel(
        &view,
        behind,
        ss.planes(),
        "(d) detail of (c): z ≤ 10".into(),
    )?;
    zoom_b.window = Some(bounds(&parallel.sections[..3]));
    let mut zoom_c = panel(
        &view,
        tilted,
        ad.planes(),
        format!("(f) detail of (e): z ≤ {}", fmt_planes(&ad.planes()[3..4])),
    )?;
    zoom_c.window = Some(bounds(&eq19.sections[..4]));
    // Each overview outlines, in grey, exactly the range its detail's axes show (the eighth
    // review, R8-barroso-fig5-1: the box was the detail's window grown by the maps' reach, up to
    // three times the detail's range).
    for overview in [&mut perpendicular, &mut parallel, &mut eq19] {
        overview.enlarged = true;
    }
    // (f): the far face's lower edge, seen from a light 45° up as a thick line across the
    // detail at light-view y = (f − f tan θ)/√2 = 29.9, named where it could read as a split
    // plane (figure review 3), by a leader (figure review 5); its middle lies between the side
    // edges, clear of every line.
    // The note's point is where the line leaves the detail's window on the right, so that its
    // leader runs to the gutter as the planes' do.
    let far = zoom_c.sections[zoom_c.sections.len() - 1];
    let low = far.iter().map(|q| q.y).fold(f64::INFINITY, f64::min);
    let right = zoom_c.window.map_or(0.0, |(_, hi)| hi.x);
    zoom_c.notes = vec![(DVec2::new(right, low), "far face".into())];
    // (e) names the same edge (the sixth review, R6-barroso-fig5-4: only (f) did, so that the
    // caption's "thick line across" had no name in the overview): its leader from the edge's
    // right end, the far face's lower right corner.
    let far_e = eq19.sections[eq19.sections.len() - 1];
    let corner = far_e
        .iter()
        .copied()
        .filter(|q| (q.y - low).abs() <= 1e-9 * (1.0 + low.abs()))
        .fold(DVec2::new(f64::NEG_INFINITY, low), |a, q| {
            if q.x > a.x {
                q
            } else {
                a
            }
        });
    eq19.notes = vec![(corner, "far face".into())];
    // The overviews label the planes their details leave out or show small (figure review 3:
    // labels spread apart with kinked leaders crowded (b)): z ≥ 31.62 in (a) and (c), z ≥ 16.13
    // in (e).
    label_from(&mut perpendicular, 3);
    label_from(&mut parallel, 3);
    label_from(&mut eq19, 2);
    // The details number their maps at a corner (R11-barroso-fig5-1: which rectangle is which
    // partition's could not be read from the maps' purples).
    for detail in [&mut zoom, &mut zoom_b, &mut zoom_c] {
        detail.numbered = true;
    }
    let mut panels = vec![perpendicular, zoom, parallel, zoom_b, eq19, zoom_c];
    // Every panel's maps fine (R9-barroso-fig5-1: in the overviews the wide outlines and their
    // dashes were larger than maps 1 to 3), so that the key's strokes are each panel's.
    for p in &mut panels {
        p.fine = true;
    }
    // Formulas joined by no-break spaces (U+00A0), so that the caption breaks none of them.
    // Barroso's α is his target ratio f_i/n_i, not Lloyd's f/n (figure review 3, X2).
    let caption = format!(
        "Barroso & Celes 2007, Fig. 5: the frustum seen from the light, k\u{a0}=\u{a0}{k} \
         z-partitions, n\u{a0}=\u{a0}{n}, f\u{a0}=\u{a0}{f}, θ\u{a0}=\u{a0}{phi:.0}°. (a) \
         Light perpendicular to the view, (c) parallel: Eq\u{a0}5's splits \
         z\u{a0}=\u{a0}{}. (e), not in the paper: light {gamma_deg:.0}° from the view, \
         target ratio α\u{a0}=\u{a0}{ADAPTIVE_RATIO} (Barroso's Eq\u{a0}19), \
         z\u{a0}=\u{a0}{}; the thick line is the far face's edge. (b), (d), (f) enlarge \
         the grey boxes, same units.",
        fmt_planes(ss.planes()),
        fmt_planes(ad.planes()),
        n = view.near(),
        f = view.far(),
        phi = view.half_fov().to_degrees(),
        gamma_deg = gamma.to_degrees(),
    );
    // One column: (e) said not to be the paper's, as two columns title it (the sixteenth review,
    // R16-barroso-fig5-1); the far face's edge named as in two (figure review 4: it was left out); the
    // split depths here, as the overviews label no plane (figure review 6: their gutter left
    // every plot about 40 units wide).
    let single_caption = format!(
        "Barroso & Celes 2007, Fig. 5: f/n\u{a0}=\u{a0}{f}, \
         θ\u{a0}=\u{a0}{phi:.0}°. (a), (c): Eq\u{a0}5, z\u{a0}=\u{a0}{}; \
         (e), not in the paper: Eq\u{a0}19, light {gamma_deg:.0}°, target ratio \
         α\u{a0}=\u{a0}{ADAPTIVE_RATIO}, z\u{a0}=\u{a0}{}; thick: far face. (b), (d), \
         (f) enlarge grey boxes.",
        fmt_planes(&ss.planes()[1..k]),
        fmt_planes(&ad.planes()[1..k]),
        f = view.far(),
        phi = view.half_fov().to_degrees(),
        gamma_deg = gamma.to_degrees(),
    );
    Ok(FromLight {
        title: "The view frustum seen from the light, with z-partitions",
        single_title: "Z-partitions seen from the light",
        caption,
        single_caption,
        panels,
        size: (520, 600),
        single_size: (300, 525),
    })
}

/// Lloyd et al. 2006 Fig 11: the light behind the viewer, k = 3 self-similar partitions.
pub(super) fn lloyd2006_fig11() -> Result<FromLight, Fail> {
    let view = ViewFrustum::new(1.0, 8.0, 30f64.to_radians())?;
    let k = 3;
    let ss = z_splits(view.near(), view.far(), k, SplitScheme::SelfSimilar)?;
    // The light travels along the view direction (−Z): it is behind the viewer.
    // No panel title: the figure's title says it.
    let mut p = panel(&view, DVec3::NEG_Z, ss.planes(), String::new())?;
    // The near and far faces' sides 2n tan θ and 2f tan θ as dimension lines under them.
    let (sn, sf) = (
        view.near() * view.tan_half_fov(),
        view.far() * view.tan_half_fov(),
    );
    // The near face's dimension line lies below the square of z = 4 and outside map 2's
    // outline, carried there by extension lines from the face's corners, so that its label
    // covers no line (issue 25: under the face it sat on the frustum's edges and the nearest
    // map; figure review 3: between z = 2 and z = 4 its box covered the z = 4 map's edge in one
    // column; the sixth review, R6-lloyd2006-fig11-3: its bars ran up to map 2's outline; 0.8
    // under the square since map 2's outline is a band on it, R7-X-3, 4.5 units under it).
    let near_dim = -(4.0 * view.tan_half_fov() + 0.8);
    p.extensions = vec![
        [DVec2::new(-sn, -sn), DVec2::new(-sn, near_dim)],
        [DVec2::new(sn, -sn), DVec2::new(sn, near_dim)],
    ];
    // The far face's dimension drawn under the face (given at the face: the drawing sets it
    // clear of map 3's outline), its label in a break of the line, so that the frame reaches
    // less far below the far face (the sixth review, R6-lloyd2006-fig11-2: the label under
    // the line made the frame 13 units tall and 10 wide).
    p.dims = vec![
        (
            DVec2::new(-sn, near_dim),
            DVec2::new(sn, near_dim),
            "2n tan θ".into(),
            false,
        ),
        (
            DVec2::new(-sf, -sf),
            DVec2::new(sf, -sf),
            "2f tan θ".into(),
            true,
        ),
    ];
    p.top_leaders = true;
    // The window the far face, grown down only for the dimensions (the sixth review,
    // R6-lloyd2006-fig11-2: the frame ran 2 units above and below the drawing).
    p.grow_down = true;
    p.window = Some((DVec2::splat(-sf), DVec2::splat(sf)));
    let caption = format!(
        "Lloyd et al. 2006, Fig. 11, to scale: n\u{a0}=\u{a0}{n}, f\u{a0}=\u{a0}{f}, \
         θ\u{a0}=\u{a0}{theta:.0}°, k\u{a0}=\u{a0}{k} self-similar z-partitions \
         (z\u{a0}=\u{a0}{}). Each map is the square of its far plane, so nearer maps lie \
         inside farther ones: §5.3's overlap behind. The paper's sketch writes the sides 2n, \
         2f (θ\u{a0}=\u{a0}45°).",
        fmt_planes(p.planes.as_slice()),
        n = view.near(),
        f = view.far(),
        theta = view.half_fov().to_degrees(),
    );
    let single_caption = format!(
        "Lloyd et al. 2006, Fig. 11: from a light behind the viewer, n\u{a0}=\u{a0}{n}, \
         f\u{a0}=\u{a0}{f}, θ\u{a0}=\u{a0}{theta:.0}°, k\u{a0}=\u{a0}{k} self-similar \
         z-partitions. Each map is the square of its far plane, so the nearer maps lie inside \
         the farther ones.",
        n = view.near(),
        f = view.far(),
        theta = view.half_fov().to_degrees(),
    );
    Ok(FromLight {
        title: "The frustum from a light behind",
        single_title: "The frustum from a light behind",
        caption,
        single_caption,
        panels: vec![p],
        size: (FROM_BEHIND_WIDTH, FROM_BEHIND_HEIGHT),
        single_size: (300, 410),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Light behind: the cross-sections are centred squares of side 2 z tan θ (Lloyd Fig 11:
    /// 2n and 2f up to the factor tan θ), and each partition's map is the square of its far plane,
    /// so every map contains the nearer ones. Barroso's planes are Eq 5's n (f/n)^{i/k} in (a).
    #[test]
    fn sections_and_planes_by_hand() {
        let fig = lloyd2006_fig11()
            .map_err(|e| e.named("lloyd2006-fig11"))
            .unwrap();
        let p = &fig.panels[0];
        let t = 30f64.to_radians().tan();
        for (s, &z) in p.sections.iter().zip(&p.planes) {
            for c in s {
                assert!((c.x.abs() - z * t).abs() < 1e-9, "{c} at z = {z}");
            }
        }
        for w in p.maps.windows(2) {
            assert!(w[1].0.x <= w[0].0.x + 1e-12 && w[1].1.x >= w[0].1.x - 1e-12);
        }
        let b = barroso_fig5().map_err(|e| e.named("barroso-fig5")).unwrap();
        for (i, &z) in b.panels[0].planes.iter().enumerate() {
            let want = 100f64.powf(i as f64 / 4.0);
            assert!((z - want).abs() < 1e-9 * want, "{z} vs {want}");
        }
        // The paper's panels: (a) light perpendicular to the view (overhead): each split
        // plane's cross-section is seen edge-on, a segment at light depth ∝ z, half as long as
        // 2 z tan φ; (b) light parallel (behind): centred squares of half-side z tan φ.
        let t = 30f64.to_radians().tan();
        for (s, &z) in b.panels[0].sections.iter().zip(&b.panels[0].planes) {
            let ys: Vec<f64> = s.iter().map(|c| c.y).collect();
            let xs: Vec<f64> = s.iter().map(|c| c.x.abs()).collect();
            assert!(
                ys.iter().all(|&y| (y.abs() - z).abs() < 1e-9),
                "{ys:?} at z = {z}"
            );
            assert!(
                xs.iter().all(|&x| (x - z * t).abs() < 1e-9),
                "{xs:?} at z = {z}"
            );
        }
        for (s, &z) in b.panels[2].sections.iter().zip(&b.panels[2].planes) {
            for c in s {
                assert!((c.x.abs() - z * t).abs() < 1e-9 && (c.y.abs() - z * t).abs() < 1e-9);
            }
        }
        assert_eq!(b.panels[0].planes, b.panels[2].planes);
        // (e): the adaptive planes start at n and end at f, and differ from the self-similar
        // ones; (b) is (a) shown in a window around the four nearest planes, z ≤ 100^{3/4} =
        // 31.623 (R9-barroso-fig5-1: map 3 in it), x to ±31.623 tan 30° = ±18.257.
        let ad = &b.panels[4].planes;
        assert_eq!((ad[0], ad[4]), (1.0, 100.0));
        assert!((ad[1] - b.panels[0].planes[1]).abs() > 1e-3);
        let (lo, hi) = b.panels[1].window.unwrap();
        assert!(
            (hi.y.abs().max(lo.y.abs()) - 31.6228).abs() < 1e-4,
            "{lo} {hi}"
        );
        assert!((hi.x - 18.2574).abs() < 1e-4 && (lo.x + 18.2574).abs() < 1e-4);
        assert_eq!(b.panels[1].title, "(b) detail of (a): z ≤ 31.62");
    }

    /// Lloyd Fig 11's labels (issue 25): the near and far planes by name and the middle split
    /// planes by depth (self-similar: 1, 2, 4, 8 for f/n = 8, k = 3), and dimension lines as
    /// long as the near and far faces' sides, 2n tan θ = 1.1547 and 2f tan θ = 9.2376 (by hand,
    /// tan 30° = 0.57735), each under its face.
    #[test]
    fn fig11_labels_name_n_f_and_the_faces_sides() {
        let fig = lloyd2006_fig11()
            .map_err(|e| e.named("lloyd2006-fig11"))
            .unwrap();
        let p = &fig.panels[0];
        assert_eq!(p.plane_labels, ["n = 1", "z = 2", "z = 4", "f = 8"]);
        let dims: Vec<(f64, f64, &str)> = p
            .dims
            .iter()
            .map(|(a, b, t, _)| ((*b - *a).length(), a.y, t.as_str()))
            .collect();
        assert_eq!(dims.len(), 2);
        assert!((dims[0].0 - 1.1547).abs() < 1e-4 && dims[0].2 == "2n tan θ");
        assert!((dims[1].0 - 9.2376).abs() < 1e-4 && dims[1].2 == "2f tan θ");
        // Under their faces: below the near face's lower edge (−0.577) and the far face's
        // (−4.619), and inside the window.
        assert!(dims[0].1 < -0.5774 && (dims[1].1 + 4.6188).abs() < 1e-4);
        let (lo, hi) = p.window.unwrap();
        assert!(lo.y <= dims[1].1 && p.grow_down);
        // The window the far face, centred on 0 (the drawing grows it down only, for the
        // dimensions' labels: the sixth review, R6-lloyd2006-fig11-2).
        assert!(
            (lo.y + hi.y).abs() < 1e-12 && (lo.x + hi.x).abs() < 1e-12,
            "{lo} {hi}"
        );
    }

    /// The light's view is not mirrored (figure review 2): for a light behind, right of and
    /// above the eye, travelling along (−1, −1, −1), an observer at the light looking along it
    /// with the view direction −Z up has d × up ∝ (−1, −1, −1) × (1, 1, −2) = (3, −3, 0) on
    /// their right, by hand. So the far section's corner (s, −s, −z) lies √2 s right of the
    /// centre and (−s, s, −z) √2 s left (s = z tan θ); the old (x, z) drawing had them swapped.
    #[test]
    fn the_light_sees_the_eyes_right_on_its_right() {
        let view = ViewFrustum::new(1.0, 10.0, 30f64.to_radians()).unwrap();
        let p = panel(
            &view,
            DVec3::new(-1.0, -1.0, -1.0),
            &[1.0, 10.0],
            String::new(),
        )
        .map_err(|e| e.named("panel"))
        .unwrap();
        let s = 10.0 * 30f64.to_radians().tan();
        let far = p.sections[1];
        assert!((far[1].x - 2f64.sqrt() * s).abs() < 1e-9, "{far:?}");
        assert!((far[3].x + 2f64.sqrt() * s).abs() < 1e-9, "{far:?}");
    }

    /// Barroso Fig 5's split depths to 4 significant figures (figure review 2): Eq 5's
    /// 100^{i/4} = 3.162, 10, 31.62 and Eq 19's (the paper's f₁..f₃ by hand: 6.0405, 16.1297,
    /// 40.8114); and (d), (f) enlarge (c) and (e) near the eye, to z ≤ 10 and z ≤ 40.81.
    #[test]
    fn barroso_split_labels_have_four_significant_figures() {
        let b = barroso_fig5().map_err(|e| e.named("barroso-fig5")).unwrap();
        // Named as Lloyd's Fig 11 names them (figure review 3: bare depths read as nothing in
        // `--bare`); an overview labels only its far planes, its detail the near ones.
        assert_eq!(
            b.panels[0].plane_labels,
            ["", "", "", "z = 31.62", "f = 100"]
        );
        assert_eq!(
            b.panels[4].plane_labels,
            ["", "", "z = 16.13", "z = 40.81", "f = 100"]
        );
        assert_eq!(
            b.panels[1].plane_labels,
            ["n = 1", "z = 3.162", "z = 10", "z = 31.62", "f = 100"]
        );
        assert_eq!(
            b.panels[5].plane_labels,
            ["n = 1", "z = 6.041", "z = 16.13", "z = 40.81", "f = 100"]
        );
        assert_eq!(b.panels.len(), 6);
        let t = 30f64.to_radians().tan();
        let (lo, hi) = b.panels[3].window.unwrap();
        assert!((hi.x - 10.0 * t).abs() < 1e-9 && (lo.y + 10.0 * t).abs() < 1e-9);
        // (f): light z of the corner (z tan θ, z tan θ, −z) at z = 40.8114 is
        // z (1 + tan θ)/√2 = 45.519 (light 45° up: light z = (Y + z)/√2).
        let (_, hi) = b.panels[5].window.unwrap();
        assert!(
            (hi.y - 40.8114 * (1.0 + t) / 2f64.sqrt()).abs() < 1e-3,
            "{hi}"
        );
    }
}
