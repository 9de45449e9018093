//! Every target of render-check, in one place: [`violations`] is what the binary's exit status,
//! `--self-test` and `cargo test -p render-check` hold each case to (docs/rendered.md,
//! "Targets").

use crate::run::CaseSummary;

/// Median of ‖J_rendered − J_predicted‖_F / ‖J_predicted‖_F, at most. The issue asked for 1 %;
/// the exact derivatives ([`crate::perspective`]) leave only the GPU's `f32` rounding (medians
/// up to 2.2·10⁻⁵ measured), so the target is ten times tighter: a matrix 1 % off on the GPU alone
/// fails it.
pub const MEDIAN_REL_DIFF: f64 = 1e-3;
/// 99th percentile of the same, at most (the 5 %, tightened likewise: measured up to
/// 2.8·10⁻⁴ at 640 × 480, 1.4·10⁻⁴ at 320 × 240; central differences gave 1.8 % and 3.7 %).
pub const P99_REL_DIFF: f64 = 5e-3;
/// The rendered and predicted maximum errors agree to this, relatively.
pub const MAX_ERROR_REL_DIFF: f64 = 0.05;
/// At least this fraction of the visible pixels has its Jacobian compared (a comparison over
/// almost nothing would pass vacuously).
pub const MIN_COMPARED_FRACTION: f64 = 0.5;
/// At least this fraction of the pixels the ray cast shadows is compared with the render.
pub const MIN_SHADOW_CHECKED_FRACTION: f64 = 0.8;
/// The rendered perspective error's maximum exceeds the frame's reported M_x or M_z by at most
/// this, relatively.
pub const FRAME_EXCESS: f64 = 0.01;
/// Where the body's worst point is visible, the rendered maximum reaches at least this fraction
/// of the reported one.
pub const FRAME_REACH: f64 = 0.95;
/// Lloyd 2006 Eq 7–10 against the rendered m_x, m_z over the ground (level set-up), relatively.
pub const LLOYD_REL_DIFF: f64 = 0.01;
/// Stable cascades: at most this fraction of the shadow-edge points' states change between
/// frames.
pub const STABLE_SHIMMER: f64 = 0.001;
/// The error lens the GPU drew (`sa_error_lens`) against the pixels one texel step spans by the
/// rendered Jacobian ([`crate::lens`]): the median of |lens / rendered − 1|, at most. The issue
/// asked for 1 %; the reference is exact ([`crate::perspective`]), the GPU's `f32` rounding
/// leaves medians up to 9.7·10⁻⁵ (measured, 640 × 480), so the target is ten times tighter: a lens 1 % off
/// fails it.
pub const LENS_MEDIAN_REL_DIFF: f64 = 1e-3;
/// The 99th percentile of the same, at most (the 5 %, tightened likewise: measured up
/// to 7.4·10⁻⁴).
pub const LENS_P99_REL_DIFF: f64 = 5e-3;
/// The GPU's lens with the projection factor 1 exceeds a map's reported `max_error_pixels` times
/// the map's largest rendered texel shear over its visible pixels by at most this, relatively
/// (`f32` rounding and the shear measured on the compared pixels only). The lens is the texel's
/// largest extent (the larger singular value of its two edges), the reported maximum Lloyd's
/// widths along the light-space axes (M_x, M_z), and a texel sheared by a warp is larger than
/// both by up to its shear ([`crate::perspective::texel_shear`]): face partitions under twenty
/// slats and an 8° sun, 1.47 × the reported maximum with a shear of 1.62 (docs/rendered.md,
/// "What is measured", 7). The lens itself, projection factor included, is no bound.
pub const LENS_FRAME_EXCESS: f64 = 0.01;
/// Where a map's worst body vertex is visible, its largest lens with the projection factor 1
/// reaches at least this fraction of its reported `max_error_pixels` (the 5 %).
pub const LENS_FRAME_REACH: f64 = 0.95;
/// At least this fraction of the visible pixels has its lens compared.
pub const MIN_LENS_COMPARED_FRACTION: f64 = 0.5;
/// At least this fraction of the pixels the ray cast lights is compared with the render (as for
/// the shadowed ones).
pub const MIN_LIT_CHECKED_FRACTION: f64 = 0.8;
/// The 99th percentile of the GPU's texel position against the exact point's under the map's
/// matrix in `f64`, texels, at most, for maps of up to [`TEXEL_POSITION_RES`] texels a side: the
/// GPU's `f32` leaves at most 1.4·10⁻³ (measured over every built-in case at 320 × 240 and
/// 640 × 480); an upload origin off by 0.003 world units 10⁵ from the origin moves it by 0.014
/// to 0.62 (measured at 320 × 240). Finer maps: × res / [`TEXEL_POSITION_RES`]
/// ([`texel_position_limit`]).
pub const TEXEL_POSITION_P99: f64 = 5e-3;
/// The map side up to which [`TEXEL_POSITION_P99`] holds as it is.
pub const TEXEL_POSITION_RES: u32 = 1024;

/// The limit on `texel_position_p99` for maps of `res` texels a side. The GPU's `f32` rounds the
/// light clip position to a fixed fraction of the map, so in texels its error grows with res:
/// `overhead` at `--res 4096` gives 4.0 × the 99th percentiles at 1024 in every scheme (face
/// partitions 1.33·10⁻³ → 5.31·10⁻³); an upload origin off by a fixed world length moves the
/// texels in proportion to res too.
pub fn texel_position_limit(res: u32) -> f64 {
    TEXEL_POSITION_P99 * (f64::from(res) / f64::from(TEXEL_POSITION_RES)).max(1.0)
}
/// LiSPSM's and PSM's w ratio along the warp axis, fitted from the GPU's texel coordinates,
/// against `1 + Δ/n′` with the paper's n′, relatively, at most.
pub const WARP_REL_DIFF: f64 = 1e-3;
/// TSM's focus fraction fitted from the GPU's texel coordinates against Martin & Tan's 0.8,
/// absolutely, at most (measured within 10⁻⁷).
pub const TSM_FOCUS_TOLERANCE: f64 = 1e-3;
/// The rendered m_x, m_z against the paper's map at each compared pixel
/// ([`crate::paper_error`]): the 99th percentile of the relative difference, at most, as for the
/// rendered Jacobian ([`P99_REL_DIFF`]): measured at most 1.1·10⁻³ (`level_side`'s uniform map at
/// 640 × 480, whose texels span up to 170 pixels, so that the GPU's `f32` texel coordinates
/// differ by little over the derivatives' steps), 3.8·10⁻⁴ at 320 × 240; a map 1 % too wide or
/// narrow misses it at every pixel.
pub const PAPER_ERROR_P99: f64 = 5e-3;
/// The largest of the same, at most (measured at most 4.5·10⁻³, the same map).
pub const PAPER_ERROR_MAX: f64 = 2e-2;
/// The frame's reported M_x, M_z against Lloyd 2006 §4.4's maxima of the paper's maps over the
/// body's vertices, and its S̄ against their product (§4.2), relatively, at most (measured at
/// most 2.4·10⁻¹⁴ before S̄ joined).
pub const PAPER_FRAME_REL_DIFF: f64 = 1e-6;
/// Each cascade's split range against the paper's planes for the λ asked
/// ([`crate::options::split_rel_diff`]), relatively, at most (every case; measured 0 to
/// rounding).
pub const SPLIT_REL_DIFF: f64 = 1e-9;
/// The minimax map's S̄ = M_x M_z over the least S̄ over n′ of the paper's maps, at most
/// (measured at most 1 + 10⁻⁹).
pub const MINIMAX_STORAGE_EXCESS: f64 = 1e-3;
/// Stable cascades: a fixed world point's move between shimmer frames in each map, from a whole
/// number of texels, at most ([`crate::snap`]; measured at most 4.0·10⁻⁹ texel, in the
/// set-ups 10⁵ from the world origin; a grid step 2/res off its texel moves points by 2·10⁻³ at
/// 1024²).
pub const STABLE_GRID_TEXELS: f64 = 1e-6;
/// The shimmer test follows at least this many shadow-edge points.
pub const MIN_SHIMMER_POINTS: usize = 100;

/// `FrameMap::body` against the focus body rebuilt by render-check ([`crate::geometry`]): the
/// largest distance of a vertex of either outside the other, over B's diameter, at most
/// (measured at most 1.5·10⁻¹³, `far_tilted`, where eye space is 10⁵ from the world origin;
/// every built-in case at 320 × 240 and 640 × 480, both clip-depth conventions, as below).
pub const BODY_REL_DIFF: f64 = 1e-9;
/// A fitted map's s, t over the rebuilt B reach ±1 on all four sides to within this, clip units
/// (measured at most 1.6·10⁻¹³); a window 0.1 % too wide or narrow misses it.
pub const WINDOW_FILL: f64 = 1e-6;
/// A stable cascade's half-width against the least sphere's radius padded by one texel each
/// side, relatively (measured at most 2.0·10⁻¹⁵).
pub const STABLE_HALF_WIDTH_REL_DIFF: f64 = 1e-9;
/// A stable cascade's centre against the least sphere's, texels along s or t: the snap to whole
/// texels moves it by at most half a texel (measured at most 0.494).
pub const STABLE_CENTRE_TEXELS: f64 = 0.5 + 1e-6;
/// A clipmap's levels against the rule derived from the camera frustum: the uploaded offset L
/// (log₂ units), the first level, and each level's texel and depth range (relatively) (measured
/// at most 2.2·10⁻¹⁶).
pub const CLIPMAP_REL_DIFF: f64 = 1e-9;
/// The records' normal offset over every sampled need, at least (the record bounds every point
/// of B: measured at least 1.00001).
pub const NORMAL_OFFSET_LEAST: f64 = 1.0 - 1e-6;
/// The records' normal offset over the largest need (the footprint followed to the offset
/// point), at most 2. The record takes the texel's depth step and its diagonal each at its own
/// worst vertex as a hypotenuse (at most √2 over their largest at one vertex), and bounds the
/// offset point's footprint by B's least w and the largest texel-per-w jointly over α
/// (`frame/bias.rs`), which a perspective map's worst point does not reach at once: measured at
/// most 1.811 (PSM, `parallel_1`, r = 1), 1.253 for every other scheme, over every built-in
/// case at 320 × 240 and 640 × 480 in both clip-depth conventions. The least ratio is at least
/// 1 − 10⁻⁶ ([`NORMAL_OFFSET_LEAST`]; measured at least 1.0001), so a record doubled reads at
/// least 2.0002 and fails.
pub const NORMAL_OFFSET_MOST: f64 = 2.0;
/// The records' depth bias (constant + slope · tan α) over every sampled need, at least (the
/// records' `f32` values: measured at least 1 − 6·10⁻⁸).
pub const DEPTH_BIAS_LEAST: f64 = 1.0 - 1e-6;
/// Each term of the records' depth bias over its own largest need, at most: the constant over the
/// need at α = 0, the slope term over the need at α = 89° (measured at most 1.0017 over every
/// built-in case at 320 × 240 and 640 × 480 in both clip-depth conventions: the grid of normals
/// comes within 3.75° of the texel's diagonal); a term doubled misses it.
pub const DEPTH_BIAS_MOST: f64 = 1.01;
/// The record's `texel_world` against the largest texel edge measured over the rebuilt B,
/// relatively (the record's `f32`: measured within 5.3·10⁻⁸).
pub const TEXEL_WORLD_REL_DIFF: f64 = 1e-5;

/// `FrameMap::receivers_volume` against the rebuilt B ([`crate::volumes::volume_distance`]),
/// over the camera frustum's size, at most: the crate pushes each plane 10⁻⁹ of the frustum's
/// size outward (src/frame/culling.rs) plus its offset's rounding, so every facet's exit lies
/// there (measured 1.0000–1.0004·10⁻⁹ over every built-in case, `far_tilted` the largest).
pub const RECEIVERS_VOLUME_REL_DIFF: f64 = 2e-9;

/// Under `depth_clamp` the map's depth over the rebuilt B against 0 and 1, at most (B alone
/// fills the depth range; measured below).
pub const DEPTH_CLAMP_FILL: f64 = 1e-6;

/// `FrameMap::casters_volume` against the rebuilt B swept toward the light and cut by the map's
/// depth range ([`crate::volumes::casters_volume_distance`]), over the camera frustum's size, at
/// most: with the crate's documented push-out of 10⁻⁹ taken back, what is left is rounding
/// (measured at most 3.5·10⁻¹³, in `far_1e5` and `far_tilted` 10⁵ from the world origin; 3·10⁻¹⁵
/// elsewhere), so a volume whose planes are not pushed out (1·10⁻⁹ short) fails as well as one
/// that cuts the sweep or reaches past it.
pub const CASTERS_VOLUME_REL_DIFF: f64 = 1e-10;

/// The geometry targets ([`crate::geometry::Geometry`]) `g` violates.
pub fn geometry_violations(g: &crate::geometry::Geometry) -> Vec<String> {
    // Each row: the target's name, the value (`None` where it does not apply), the limit.
    let at_most = [
        (
            "body_rel_diff (FrameMap::body against the focus body rebuilt here)",
            Some(g.body_rel_diff),
            BODY_REL_DIFF,
        ),
        (
            "window_fill (the rebuilt body's s, t extremes against ±1)",
            g.window_fill,
            WINDOW_FILL,
        ),
        (
            "stable_half_width_rel_diff (the window against the least sphere of the slice)",
            g.stable_half_width_rel_diff,
            STABLE_HALF_WIDTH_REL_DIFF,
        ),
        (
            "stable_centre_texels (the window's centre against the least sphere's)",
            g.stable_centre_texels,
            STABLE_CENTRE_TEXELS,
        ),
        (
            "clipmap_rel_diff (the levels against the rule derived from the frustum)",
            g.clipmap_rel_diff,
            CLIPMAP_REL_DIFF,
        ),
        (
            "normal_offset_ratio[1] (the records' normal offset over the largest need)",
            Some(g.normal_offset_ratio[1]),
            NORMAL_OFFSET_MOST,
        ),
        (
            "depth_bias_ratio[1] (each depth-bias term over its own largest need)",
            Some(g.depth_bias_ratio[1]),
            DEPTH_BIAS_MOST,
        ),
        (
            "|texel_world_ratio − 1| (the record's texel_world against the measured texel)",
            Some((g.texel_world_ratio - 1.0).abs()),
            TEXEL_WORLD_REL_DIFF,
        ),
        (
            "receivers_volume_rel_diff (FrameMap::receivers_volume against the focus body rebuilt here)",
            Some(g.receivers_volume_rel_diff),
            RECEIVERS_VOLUME_REL_DIFF,
        ),
        (
            "casters_volume_rel_diff (FrameMap::casters_volume against the rebuilt body swept toward the light)",
            Some(g.casters_volume_rel_diff),
            CASTERS_VOLUME_REL_DIFF,
        ),
        (
            "split_rel_diff (the maps' split ranges against the paper's planes)",
            g.split_rel_diff,
            SPLIT_REL_DIFF,
        ),
        (
            "depth_clamp_fill (under depth clamp the rebuilt body's depths against 0 and 1)",
            g.depth_clamp_fill,
            DEPTH_CLAMP_FILL,
        ),
    ];
    let at_least = [
        (
            "normal_offset_ratio[0] (the records' normal offset over every need)",
            g.normal_offset_ratio[0],
            NORMAL_OFFSET_LEAST,
        ),
        (
            "depth_bias_ratio[0] (the records' depth bias over every need)",
            g.depth_bias_ratio[0],
            DEPTH_BIAS_LEAST,
        ),
    ];
    // NaN fails both kinds (a measurement that is not a number meets no target).
    let over = at_most.iter().filter_map(|&(name, got, limit)| {
        let got = got?;
        (got.is_nan() || got > limit).then(|| format!("{name} = {got:.4e}, limit ≤ {limit:e}"))
    });
    let under = at_least
        .iter()
        .filter(|&&(_, got, limit)| got.is_nan() || got < limit)
        .map(|&(name, got, limit)| format!("{name} = {got:.6}, limit ≥ {limit}"));
    over.chain(under).collect()
}

/// The targets `case` violates, one line each naming the target, the measured value and the
/// limit; empty when it meets them all.
pub fn violations(case: &CaseSummary) -> Vec<String> {
    let m = &case.measured;
    let mut v = Vec::new();
    let mut empty = Vec::new();
    let mut at_least_one = |name: &str, got: usize| {
        if got == 0 {
            empty.push(format!("{name} = 0, limit ≥ 1"));
        }
    };
    let mut at_most = |name: &str, got: f64, limit: f64| {
        // NaN fails (a measurement that is not a number meets no target).
        if got.is_nan() || got > limit {
            v.push(format!("{name} = {got:.4e}, limit ≤ {limit:e}"));
        }
    };
    at_most("median_rel_diff", m.median_rel_diff, MEDIAN_REL_DIFF);
    at_most("p99_rel_diff", m.p99_rel_diff, P99_REL_DIFF);
    at_most(
        "|max_rendered_error / max_predicted_error − 1|",
        (m.max_rendered_error / m.max_predicted_error - 1.0).abs(),
        MAX_ERROR_REL_DIFF,
    );
    at_most("shadow_misses", m.shadow_misses as f64, 0.0);
    at_most("false_shadows", m.false_shadows as f64, 0.0);
    at_most("uncovered_pixels", m.uncovered_pixels as f64, 0.0);
    at_most(
        "frame_error_ratio − 1 (rendered M_x, M_z over the frame's reported)",
        m.frame_error_ratio - 1.0,
        FRAME_EXCESS,
    );
    at_most(
        "lens_median_rel_diff (the GPU's sa_error_lens against the rendered Jacobian's)",
        m.lens_median_rel_diff,
        LENS_MEDIAN_REL_DIFF,
    );
    at_most(
        "lens_p99_rel_diff (the GPU's sa_error_lens against the rendered Jacobian's)",
        m.lens_p99_rel_diff,
        LENS_P99_REL_DIFF,
    );
    at_most(
        "lens_frame_ratio − 1 (the lens at projection factor 1 over the reported max_error_pixels)",
        m.lens_frame_ratio - 1.0,
        LENS_FRAME_EXCESS,
    );
    if let Some(n) = m.blend_mismatches {
        at_most(
            "blend_mismatches (the cross-fade against the band the requested overlap makes)",
            n as f64,
            0.0,
        );
    }
    at_most(
        "texel_position_p99 (the GPU's texel position against the exact point's, texels)",
        m.texel_position_p99,
        texel_position_limit(case.map_resolution),
    );
    if let Some(d) = m.warp_rel_diff {
        at_most(
            "warp_rel_diff (w's ratio fitted from the texels against 1 + Δ/n′ of the paper)",
            d,
            WARP_REL_DIFF,
        );
    }
    if let Some(f) = m.tsm_focus_fraction {
        at_most(
            "|tsm_focus_fraction − 0.8| (the focus line fitted from the texels, Martin & Tan)",
            (f - crate::papers::TSM_FOCUS_FRACTION).abs(),
            TSM_FOCUS_TOLERANCE,
        );
    }
    if let Some((p99, max)) = m.paper_error_rel_diff {
        at_most(
            "paper_error_p99 (rendered m_x, m_z against the paper's map, Lloyd 2006 §4.4)",
            p99,
            PAPER_ERROR_P99,
        );
        at_most(
            "paper_error_max (rendered m_x, m_z against the paper's map, Lloyd 2006 §4.4)",
            max,
            PAPER_ERROR_MAX,
        );
    }
    if let Some(d) = m.paper_frame_rel_diff {
        at_most(
            "paper_frame_rel_diff (reported M_x, M_z against the paper's map's §4.4 maxima)",
            d,
            PAPER_FRAME_REL_DIFF,
        );
    }
    if let Some(r) = m.minimax_storage_ratio {
        at_most(
            "minimax_storage_ratio − 1 (S̄ at the minimax n′ over the least S̄ of the paper's maps)",
            r - 1.0,
            MINIMAX_STORAGE_EXCESS,
        );
    }
    if let Some(n) = m.split_mismatches {
        at_most(
            "split_mismatches (the map picked against the paper's split planes)",
            n as f64,
            0.0,
        );
    }
    if case.scheme == crate::schemes::Scheme::BlendedCascades.name() {
        at_least_one(
            "blend_pixels (a blended scheme with no pixel in its requested band)",
            m.blend_pixels.unwrap_or(0),
        );
    }
    if let Some(d) = m.lloyd_rel_diff {
        at_most(
            "lloyd_rel_diff (rendered m_x, m_z against Lloyd 2006 Eq 7-10)",
            d,
            LLOYD_REL_DIFF,
        );
    }
    if case.scheme == crate::schemes::Scheme::StableCascades.name() {
        // Not measured (null) reads NaN: no pass.
        at_most(
            "stable_grid_texels (fixed world points' moves between frames off whole texels)",
            case.stable_grid_texels.unwrap_or(f64::NAN),
            STABLE_GRID_TEXELS,
        );
        match case.shimmer_changed_fraction {
            Some(f) => at_most(
                "shimmer_changed_fraction (stable cascades)",
                f,
                STABLE_SHIMMER,
            ),
            None => v.push("shimmer_changed_fraction: not measured (stable cascades)".into()),
        }
    }
    v.append(&mut empty);
    let mut at_least = |name: &str, got: f64, limit: f64| {
        if got.is_nan() || got < limit {
            v.push(format!("{name} = {got:.4}, limit ≥ {limit}"));
        }
    };
    at_least(
        "pixels_compared / visible_pixels",
        m.pixels_compared as f64 / m.visible_pixels.max(1) as f64,
        MIN_COMPARED_FRACTION,
    );
    if m.shadow_pixels > 0 {
        at_least(
            "shadow_pixels_checked / shadow_pixels",
            m.shadow_pixels_checked as f64 / m.shadow_pixels as f64,
            MIN_SHADOW_CHECKED_FRACTION,
        );
    }
    if m.lit_pixels > 0 {
        at_least(
            "lit_pixels_checked / lit_pixels",
            m.lit_pixels_checked as f64 / m.lit_pixels as f64,
            MIN_LIT_CHECKED_FRACTION,
        );
    }
    at_least(
        "lens_pixels_compared / visible_pixels",
        m.lens_pixels_compared as f64 / m.visible_pixels.max(1) as f64,
        MIN_LENS_COMPARED_FRACTION,
    );
    if let Some(r) = m.lens_frame_ratio_worst_visible {
        at_least(
            "lens_frame_ratio_worst_visible (the lens at projection factor 1 where the worst vertex shows)",
            r,
            LENS_FRAME_REACH,
        );
    }
    match m.frame_error_ratio_worst_visible {
        Some(r) => at_least(
            "frame_error_ratio_worst_visible (rendered over reported where the worst point shows)",
            r,
            FRAME_REACH,
        ),
        // A set-up built to show every scheme's worst point, whose worst point is not on
        // screen: the frame's body or its reported maximum moved off the visible ground.
        None if crate::schemes::WORST_POINT_ON_SCREEN.contains(&case.setup.as_str()) => at_least(
            "frame_error_ratio_worst_visible (null, not measured where the set-up puts every \
                 scheme's worst body point on screen)",
            f64::NAN,
            FRAME_REACH,
        ),
        None => {}
    }
    if let Some(n) = case.shimmer_points {
        at_least("shimmer_points", n as f64, MIN_SHIMMER_POINTS as f64);
    }
    for p in case.paths.iter().flatten() {
        v.extend(path_violations(p));
    }
    v.extend(geometry_violations(&case.geometry));
    if case.overlay.lens_colour_mismatches > 0 {
        v.push(format!(
            "lens_colour_mismatches (the GPU's lens overlay against the Rust lens_colour) = {}, \
             limit ≤ 0",
            case.overlay.lens_colour_mismatches
        ));
    }
    if case.overlay.lens_colour_pixels == 0 {
        v.push("lens_colour_pixels (overlay pixels compared) = 0, limit ≥ 1".into());
    }
    v
}

/// The targets that ask for enough of the frame to be decided (compared, checked, followed):
/// a case that misses only these is inconclusive (too little decidable), not wrong.
pub const DECIDABILITY_TARGETS: [&str; 6] = [
    "pixels_compared / visible_pixels",
    "shadow_pixels_checked / shadow_pixels",
    "lit_pixels_checked / lit_pixels",
    "lens_pixels_compared / visible_pixels",
    "shimmer_points",
    "taps_checked / lookups",
];

/// Whether a line of [`violations`] is one of the [`DECIDABILITY_TARGETS`]: the case is
/// inconclusive there (too little decidable), where any other line is a wrong pixel or number.
pub fn is_inconclusive(violation: &str) -> bool {
    DECIDABILITY_TARGETS
        .iter()
        .any(|t| violation.starts_with(&format!("{t} ")))
}

/// At least this fraction of a shader path's lookups has its taps decided by render-check's
/// model ([`crate::paths`]).
pub const MIN_TAPS_CHECKED_FRACTION: f64 = 0.8;

/// The targets one shader path ([`crate::paths::PathSummary`]) violates.
fn path_violations(p: &crate::paths::PathSummary) -> Vec<String> {
    let mut v = Vec::new();
    let name = p.path;
    if p.tap_mismatches > 0 {
        v.push(format!(
            "tap_mismatches in path {name} (the GPU's shaded fraction against the taps \
             re-evaluated from the read-back maps) = {}, limit ≤ 0",
            p.tap_mismatches
        ));
    }
    if p.acne > 0 {
        v.push(format!(
            "acne in path {name} (lit pixels shaded below 1 on their own lit face) = {}, limit ≤ 0",
            p.acne
        ));
    }
    let local = crate::paths::PATHS
        .iter()
        .any(|q| q.name == name && q.local());
    if local && p.detached > 0 {
        v.push(format!(
            "detached in path {name} (shadowed pixels lit by a lookup lifted beyond the need) = {}, \
             limit ≤ 0",
            p.detached
        ));
    }
    let path = crate::paths::PATHS.iter().find(|q| q.name == name);
    if path.is_some_and(|q| q.offset()) {
        let slack = crate::paths::LIFT_SLACK;
        match p.lift_over_need {
            None => v.push(format!(
                "lift_over_need in path {name} (the GPU's lookup point's lift over the need) \
                 not measured: no lookup with a finite offset"
            )),
            Some([lo, hi]) => {
                let d = p.offset_rel_diff.unwrap_or(f64::NAN);
                if d.is_nan() || d > slack {
                    v.push(format!(
                        "offset_rel_diff in path {name} (the GPU's normal offset against the one \
                         it is defined to be) = {d:.6}, limit ≤ {slack:.6}"
                    ));
                }
                if lo.is_nan() || lo < 1.0 - slack {
                    v.push(format!(
                        "lift_over_need in path {name} (the least lift of the GPU's lookup point \
                         over the need) = {lo:.6}, limit ≥ {:.6}",
                        1.0 - slack
                    ));
                }
                if local && (hi.is_nan() || hi > 1.0 + slack) {
                    v.push(format!(
                        "lift_over_need in path {name} (the largest lift of the GPU's lookup \
                         point over the need) = {hi:.6}, limit ≤ {:.6}",
                        1.0 + slack
                    ));
                }
            }
        }
    }
    let f = p.taps_checked as f64 / p.lookups.max(1) as f64;
    if f.is_nan() || f < MIN_TAPS_CHECKED_FRACTION {
        v.push(format!(
            "taps_checked / lookups in path {name} = {f:.4}, limit ≥ {MIN_TAPS_CHECKED_FRACTION}"
        ));
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    /// By hand: 5·10⁻³ texel up to 1024 texels a side, 4 × that at 4096.
    #[test]
    fn texel_position_limit_by_hand() {
        assert_eq!(texel_position_limit(256), 5e-3);
        assert_eq!(texel_position_limit(1024), 5e-3);
        assert!((texel_position_limit(4096) - 2e-2).abs() < 1e-15);
    }
}
