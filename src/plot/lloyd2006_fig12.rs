//! Lloyd et al. 2006 Fig 12: the storage factor S̄ of ZP, ZP+W and FP+ZP+W against the number
//! of shadow maps, with the light overhead and behind (f/n = 1000, θ = 30°).

use super::super::chart::{fmt_plain, Axis, Charts, LineChart, Look, Note, Series, PALETTE};
use super::super::keyed::{Keyed, SINGLE_HEIGHT};
use super::super::worst::{scheme_series, ZP_BEHIND};
use super::super::{Column, Fail};
use super::{sci, unjoined, SCHEME_WORDS, THETA_DEG};
use crate::analytic::partition::{scheme_storage_factor, shadow_map_count, Scheme, SchemeLight};
use crate::ViewFrustum;

/// Where Fig 12 (b)'s note on the 17-map pair starts: its left end (maps) and its top (S̄), in
/// the empty band between S̄ = 50 and ZP's curve (which rises to 41.9 at 23 maps), under
/// FP+ZP+W's 13-map marker (55.0) and right of it: level with the marker and two maps right of
/// it, the marker read as the note's key symbol (the ninth review, R9-lloyd2006-fig12-1; the
/// lower left put its last line beside the 21-map marker instead); and the step between its
/// lines, in S̄.
const FIG12_NOTE_LEFT: f64 = 15.3;
const FIG12_NOTE_TOP: f64 = 49.6;
const FIG12_NOTE_STEP: f64 = 2.2;

/// The depth ratio f/n of Fig 12.
pub(in crate::plot) const FIG12_RATIO: f64 = 1000.0;

/// Fig 12: S̄ against the number of shadow maps for ZP, ZP+W and FP+ZP+W, light overhead and
/// behind (f/n = 1000, θ = 30°).
///
/// The number of maps of FP+ZP+W is 4k + 1 for both light directions
/// ([`shadow_map_count`] for the light behind): a scheme keeps its maps whatever the light, which
/// is how §5.3 counts them ("only one z-partitioning for every four shadow maps", Eq 23).
pub(in crate::plot) fn fig12() -> Result<Keyed, Fail> {
    let ratio = FIG12_RATIO;
    let view = ViewFrustum::new(1.0, ratio, THETA_DEG.to_radians())?;
    // The light-behind crossover: ZP with as many maps as FP+ZP+W with k = 3 and 4 per face.
    let behind = |scheme: Scheme, k: usize| -> Result<f64, crate::Error> {
        scheme_storage_factor(scheme, SchemeLight::Behind, &view, k)
    };
    let (j3, j4) = (
        shadow_map_count(Scheme::FpZpW, SchemeLight::Behind, 3)?,
        shadow_map_count(Scheme::FpZpW, SchemeLight::Behind, 4)?,
    );
    let (zp3, fp3) = (behind(Scheme::Zp, j3)?, behind(Scheme::FpZpW, 3)?);
    let (zp4, fp4) = (behind(Scheme::Zp, j4)?, behind(Scheme::FpZpW, 4)?);
    // ZP with one map, far above the rest (10⁶ behind): off the scale, its value written.
    let zp1 = (
        scheme_storage_factor(Scheme::Zp, SchemeLight::Overhead, &view, 1)?,
        behind(Scheme::Zp, 1)?,
    );
    // The half field of view of each face's sub-frustum in Eq 21, read back from FP+ZP+W's S̄
    // behind: S̄ = 4k((f/n)^{1/k} − 1)/(2 tan θ_eff) + 1 (Eq 21 with the k z-partitions of each
    // face, Eq 18, and the one map of the near plane), whatever the frustum's θ.
    let k = 4.0;
    let tan_eff = 4.0 * k * (ratio.powf(1.0 / k) - 1.0) / (2.0 * (fp4 - 1.0));
    let eff = format!(
        "tan\u{a0}θ_{{eff}}\u{a0}=\u{a0}{} ({:.0}°)",
        fmt_plain(tan_eff),
        tan_eff.atan().to_degrees()
    );
    let nb = |t: &str| t.replace(' ', "\u{a0}");
    let (a, zoom) = fig12_panels(&view, Column::Double)?;
    let mut zoom = zoom;
    // The 17-map pair's values, inside the plot (the bare figure has no caption to say which
    // is which), each in its scheme's colour, in the empty upper right (sixth review,
    // R6-lloyd2006-fig12-3: it sat on the gridlines between the points).
    for (at, text, colour) in [
        (FIG12_NOTE_TOP, format!("at {j4} maps:"), PALETTE[6]),
        (
            FIG12_NOTE_TOP - FIG12_NOTE_STEP,
            format!("FP+ZP+W {fp4:.2}"),
            Look::FpZpW.colour(),
        ),
        (
            FIG12_NOTE_TOP - 2.0 * FIG12_NOTE_STEP,
            format!("ZP = ZP+W {zp4:.2}"),
            Look::Zp.colour(),
        ),
    ] {
        zoom.notes.push(Note {
            at: (FIG12_NOTE_LEFT, at),
            text,
            colour,
        });
    }
    let double = Charts {
        size: (520, 575),
        title: FIG12_TITLE.into(),
        caption: vec![format!(
            "Lloyd et al. 2006, Fig. 12 (Eq 17–21), {}, {}°. {SCHEME_WORDS} FP+ZP+W uses {} \
             maps. Behind, ZP+W equals ZP, and FP+ZP+W's face sub-frusta have {eff} \
             (Eq 21, any θ). ZP with one map, off the scale: {} overhead, {} behind. \
             (b): with {j3} maps ZP is lower ({zp3:.1} against {fp3:.1}); \
             with {j4}, FP+ZP+W ({fp4:.2} against {zp4:.2}).",
            nb(&format!("f/n = {ratio}")),
            nb(&format!("θ = {THETA_DEG}")),
            nb("4k + 1"),
            sci(zp1.0),
            sci(zp1.1),
        )],
        charts: vec![a, zoom],
    };
    let (mut a, _) = fig12_panels(&view, Column::Single)?;
    // One panel: no letter; the axis' name has no room for its scale, which the title gives
    // (seventh review, R7-X-1).
    a.title = format!("{}; log scale", &FIG12_A_TITLE[4..]);
    a.y.label = FIG12_S_AXIS.into();
    let single = Charts {
        size: (Column::Single.width(), SINGLE_HEIGHT),
        title: FIG12_TITLE.into(),
        caption: vec![format!(
            "Lloyd et al. 2006, Fig. 12 (Eq 17–21), {}, {}°. {SCHEME_WORDS} FP+ZP+W uses {} \
             maps, its faces behind {}.",
            nb(&format!("f/n = {ratio}")),
            nb(&format!("θ = {THETA_DEG}")),
            nb("4k + 1"),
            // Without the angle (45°) the two-column caption adds: five lines.
            nb(&format!("tan θ_{{eff}} = {}", fmt_plain(tan_eff))),
        )],
        charts: vec![a],
    };
    Ok(Keyed {
        single: Some(Box::new(Keyed::new(single, Some(0)))),
        ..Keyed::new(double, Some(0))
    })
}

/// Fig 12's title, one in both forms (sixth review, R6-X-5: the two-column form said "storage
/// factor", the one-column "S̄").
const FIG12_TITLE: &str = "S̄ against the number of shadow maps";

/// Fig 12 (a)'s title: each light's drawing (the sixth review, R6-lloyd2006-fig12-1/-2: colour
/// is the scheme, line and marker fill the light).
const FIG12_A_TITLE: &str = "(a) overhead: solid, filled;\nbehind: dashed, hollow";

/// Fig 12 (b)'s title, two lines as (a)'s, so that the plots' tops align.
const FIG12_B_TITLE: &str = "(b) behind, at the crossover;\nlinear scale";

/// Fig 12's panels for the page `layout`: (a) every scheme for both lights, its key grouped
/// by light (two columns, overhead and behind, across two page columns; one column, overhead
/// first, in one), and (b) the light-behind crossover enlarged.
///
/// One rule in both panels (sixth review, R6-lloyd2006-fig12-1/-2): the colour is the scheme's
/// ([`Look`]), the light is the line and the markers' fill: overhead solid with filled markers,
/// behind dashed with open ones. Behind, ZP+W equals ZP (a square frustum cannot be warped):
/// one curve, in ZP's colour, its key "ZP = ZP+W, behind".
fn fig12_panels(view: &ViewFrustum, layout: Column) -> Result<(LineChart, LineChart), Fail> {
    let mut c = LineChart::new(
        FIG12_A_TITLE,
        Axis::integer("number of shadow maps", 0.0, 40.0),
        // To the data from 2 maps on: 6.5 (ZP+W at 40 maps) to 2000 (ZP behind with 2 maps).
        Axis::log10(FIG12_S_LOG_AXIS, 4.0, 1e4).in_powers(),
    );
    let schemes = [
        (Scheme::Zp, "ZP"),
        (Scheme::ZpW, "ZP+W"),
        (Scheme::FpZpW, "FP+ZP+W"),
    ];
    // The key's order: entries row by row, so two columns of overhead | behind, or overhead's
    // three above behind's two.
    use SchemeLight::{Behind, Overhead};
    let series = match layout {
        Column::Double => {
            c.legend_columns = Some(2);
            [
                (Scheme::Zp, Overhead),
                (Scheme::Zp, Behind),
                (Scheme::ZpW, Overhead),
                (Scheme::FpZpW, Behind),
                (Scheme::FpZpW, Overhead),
            ]
        }
        // One column: one entry a row, each naming its light (the tenth review,
        // R10-lloyd2006-fig12-1: the scheme alone gave two "FP+ZP+W" and a "ZP = ZP+W" that is
        // false overhead), overhead's three over behind's two.
        Column::Single => {
            c.legend_columns = Some(1);
            [
                (Scheme::Zp, Overhead),
                (Scheme::ZpW, Overhead),
                (Scheme::FpZpW, Overhead),
                (Scheme::Zp, Behind),
                (Scheme::FpZpW, Behind),
            ]
        }
    };
    for (scheme, light) in series {
        let (_, name) = schemes
            .into_iter()
            .find(|s| s.0 == scheme)
            .ok_or_else(|| Fail::Draw(format!("Fig 12 has no {scheme:?}")))?;
        let behind = light == Behind;
        let label = match (scheme, light) {
            (Scheme::Zp, Behind) => ZP_BEHIND.to_string(),
            (_, Behind) => format!("{name}, behind"),
            (_, Overhead) => format!("{name}, overhead"),
        };
        let mut pts = Vec::new();
        for k in 1..=40usize {
            let maps = shadow_map_count(scheme, Behind, k)?;
            if maps > 40 {
                break;
            }
            pts.push((maps as f64, scheme_storage_factor(scheme, light, view, k)?));
        }
        // Each scheme and light as every figure draws it ([`scheme_series`]): FP+ZP+W,
        // defined only at 4k + 1 maps, markers only.
        if scheme == Scheme::FpZpW {
            c.series
                .push(scheme_series(scheme, behind, Some(label), pts)?);
            continue;
        }
        // Every count: a line, with a few markers along it (not one per count), at counts
        // 4k + 3 ([`FIG12_ZP_MARKS`]), two counts from every FP+ZP+W marker at 4k + 1
        // (the fifth review: ZP's circle at 36 lay under FP+ZP+W's triangle at 37).
        let counts: &[f64] = match (scheme, light) {
            (Scheme::Zp, Overhead) => &FIG12_ZP_MARKS,
            (_, Behind) => &FIG12_BEHIND_MARKS,
            _ => &FIG12_ZP_W_MARKS,
        };
        let marks: Vec<(f64, f64)> = pts
            .iter()
            .copied()
            .filter(|p| counts.contains(&p.0))
            .collect();
        c.series.push(Series {
            markers: false,
            ..scheme_series(scheme, behind, None, pts)?
        });
        c.series
            .push(scheme_series(scheme, behind, None, unjoined(&marks))?);
        c.series
            .push(scheme_series(scheme, behind, Some(label), Vec::new())?);
    }
    // (b): the light-behind crossover enlarged, ZP (equal to ZP+W there) against FP+ZP+W, drawn
    // as in (a).
    let mut zoom = LineChart::new(
        FIG12_B_TITLE,
        // Padded by half a count, so that the markers at 11 and 23 maps are whole.
        Axis::integer("number of shadow maps", 10.5, 23.5),
        // The data's range (30.8 at 21 maps to 55.0 at 13), a little padded.
        Axis::linear(FIG12_S_AXIS, 28.0, 58.0),
    );
    for (scheme, name) in [(Scheme::Zp, ZP_BEHIND), (Scheme::FpZpW, "FP+ZP+W, behind")] {
        let mut pts = Vec::new();
        for k in 1..=23usize {
            let maps = shadow_map_count(scheme, Behind, k)?;
            if (11..=23).contains(&maps) {
                pts.push((maps as f64, scheme_storage_factor(scheme, Behind, view, k)?));
            }
        }
        if scheme == Scheme::FpZpW {
            zoom.series
                .push(scheme_series(scheme, true, Some(name.into()), pts)?);
        } else {
            // ZP's open markers at the counts between FP+ZP+W's (at 17 maps one lay under
            // FP+ZP+W's, 38.32 against 37.99): the values there are written.
            let marks: Vec<(f64, f64)> = pts
                .iter()
                .copied()
                .filter(|p| FIG12_ZOOM_ZP_MARKS.contains(&p.0))
                .collect();
            zoom.series.push(Series {
                markers: false,
                ..scheme_series(scheme, true, None, pts)?
            });
            zoom.series
                .push(scheme_series(scheme, true, None, unjoined(&marks))?);
        }
    }
    Ok((c, zoom))
}

/// Fig 12's S̄ axes, one name in both forms: (a)'s logarithmic (seventh review, R7-X-1,
/// R7-2006f12-1), (b)'s linear.
const FIG12_S_LOG_AXIS: &str = "S̄ (texels per image pixel, log scale)";
const FIG12_S_AXIS: &str = "S̄ (texels per image pixel)";

/// The counts of maps where (a)'s ZP = ZP+W behind line carries its open markers: 4k + 3, away
/// from ZP's overhead markers and FP+ZP+W's at 4k + 1.
const FIG12_BEHIND_MARKS: [f64; 3] = [11.0, 23.0, 35.0];

/// The counts where (b)'s ZP = ZP+W line carries its open markers: between FP+ZP+W's.
const FIG12_ZOOM_ZP_MARKS: [f64; 4] = [11.0, 15.0, 19.0, 23.0];

/// The counts of maps where Fig 12 (a)'s ZP and ZP+W overhead lines carry their markers:
/// 4k + 3, two counts from FP+ZP+W's triangles at 4k + 1, ZP's and ZP+W's alternating (and no
/// ZP marker beyond 11 maps, where its line runs within a marker of FP+ZP+W's triangles).
const FIG12_ZP_MARKS: [f64; 2] = [3.0, 11.0];
const FIG12_ZP_W_MARKS: [f64; 3] = [7.0, 15.0, 23.0];
