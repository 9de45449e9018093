//! Depth bias, normal offset and texel extents of a map for a PCF kernel, from the exact texel
//! footprint over the map's focus body B ([`FrameMap::bias`]).
//!
//! # The geometry
//!
//! Every map of the frame projects along the light: its clip w is constant along a light ray, so
//! a texel is a light ray's cross-section, a parallelogram ⊥ l with edge vectors `E_s`, `E_t`
//! (world units per unit of clip s, t; `output::texel_vectors`, the columns of the inverse
//! Jacobian of the plane ⊥ l → (s, t)). A texel of a map of `res` texels spans 2/res of clip.
//!
//! A lookup at a point p reads the texels whose centres lie within ρ = r + ½ texels of p's
//! projection in s and in t (r = 0: the one texel holding p; taps at whole-texel offsets up to r:
//! r + ½; hardware 2×2 comparison filtering reaches ½ texel further, so pass r + ½ for it). The
//! depth a texel stores is that of the surface on the ray through its centre. The map is
//! projective, so the depth d of a plane is affine in (s, t), and a tap (a, b) texels of 2/res
//! away (|a|, |b| ≤ ρ) stores, exactly,
//!
//! ```text
//! d_tap − d(p) = (2/res) · (a · (c_s + ∂d/∂λ · τ_s) + b · (c_t + ∂d/∂λ · τ_t)),
//! c_e = ∇d · E_e,   τ_e = (n · E_e) / cos α,
//! ```
//!
//! with n the surface's unit normal, lit (n · l = −cos α < 0, α the angle between the normal and
//! the direction to the light), `∂d/∂λ = ∇d · l` the depth's rate along the light, and c_e the
//! depth's step across a texel edge at constant distance along the light (not 0 for a warped
//! map, whose depth y/w varies across a plane ⊥ l). The worst tap is at most
//!
//! ```text
//! ρ · (2/res) · ((|c_s| + |c_t|) + |∂d/∂λ| · diag · tan α),   diag = max(|E_s + E_t|, |E_s − E_t|)
//! ```
//!
//! ahead of p, since |n⊥ · E_s| + |n⊥ · E_t| ≤ sin α · diag (|u · a| + |u · b| = max(|u · (a + b)|,
//! |u · (a − b)|) for a unit u): the texel's longer diagonal, reached when n⊥ lies along it and p
//! is at a texel corner. So:
//!
//! - **Depth bias**, `constant_depth + slope_scaled_depth · tan α` with
//!   `constant_depth = ρ · (2/res) · max_B(|c_s| + |c_t|)` (plus 8 `f32` ulps at depth 1 for the
//!   rounding of the two depths compared) and `slope_scaled_depth = ρ · (2/res) · max_B(diag ·
//!   |∂d/∂λ|)`, in the map's depth units.
//! - **Normal offset.** Looking up at p + o n raises the point o / cos α above the surface
//!   along the light, worth `|∂d/∂λ| · o / cos α` of depth; it suffices when
//!   `o ≥ ρ · (2/res) · (A cos α + diag · sin α)`, `A = (|c_s| + |c_t|) / |∂d/∂λ|` (the texel's
//!   depth step as a distance along the light), for every α when
//!   `R = ρ · (2/res) · hypot(max_B A, max_B diag)` with p's footprint held over the offset
//!   (`A cos α + diag sin α ≤ hypot(A, diag)`). The offset point q = p + o n has its own
//!   footprint: the map's w is constant along a light ray, so q's depth above the plane is
//!   `∂d/∂λ(p) · (w(p)/w(q)) · o / cos α` with `w(q) = w(p) + o (row₃ · n)` (as in "Per point"
//!   below), and the least offset at p is `o(p, n) = o_h / (1 − o_h (row₃ · n)/w(p))`, o_h the
//!   offset with the footprint held, `o_h ≤ ρ (2/res) (A cos α + diag sin α)`. Since
//!   `∂d/∂λ = k/w` with `k = row₂ · l` constant (row₃ · l = 0), `A = w · (|c_s| + |c_t|)/|k|` and
//!   `diag = w · (diag |∂d/∂λ|)/|k|`, so `o_h / w(p) ≤ ρ (2/res) (a cos α + b sin α)` with
//!   `a = max_B (|c_s| + |c_t|) / |k|`, `b = max_B diag |∂d/∂λ| / |k|` (both maxima at B's
//!   vertices, as for the depth bias below); and `row₃ · n ≤ |row₃| sin α` (row₃ ⊥ l). Hence over
//!   B and every lit normal at angle α
//!
//!   ```text
//!   o ≤ ρ (2/res) (max_B A cos α + max_B diag sin α) / (1 − ρ (2/res) |row₃| (a cos α + b sin α) sin α),
//!   ```
//!
//!   and the record is this bound's largest over α ∈ [0, π/2], bounded from above on 256
//!   sub-intervals (`offset_bound`: numerator and denominator are sinusoids in α whose extremes
//!   on a sub-interval are known); `+∞` where the denominator reaches 0 (an offset point could
//!   need to reach the map's centre of projection). An offset larger than a point needs is
//!   harmless (the point only rises further above its plane) as long as it does not carry the
//!   point to the map's centre of projection: for a normal toward it at angle α,
//!   `w(q) = w(p) − o |row₃ · n| > 0`, which holds for every normal where `o |row₃| < w(p)` and
//!   otherwise for `sin α < w(p) / (o |row₃|)` only; past that angle no single offset serves
//!   the point (the per-point offset below does). An orthographic
//!   map has row₃ = (0, 0, 0, 1): the bound is R's form. A perspective map whose centre of
//!   projection lies near B needs the denominator: with p's footprint held the record of PSM's
//!   map (n′ = n_B, Lloyd 2006 §4.1) covered only 0.574 of what render-check's set-ups need at
//!   320 × 240 (docs/rendered.md, "What is measured", 13).
//!
//!   The bound is not proportional to ρ: write it `max_α ρ N₁(α) / (1 − ρ T₁(α))`. For a kernel
//!   of reach `s ρ`, s ≥ 1, each α's term is `s · ρ N₁/(1 − ρ T₁) · (1 − x)/(1 − s x)` with
//!   `x = ρ T₁(α) ≤ τ = max_α ρ T₁` ([`Bias::normal_offset_growth`]), and `(1 − x)/(1 − s x)`
//!   grows with x, so the larger kernel needs at most `s (1 − τ)/(1 − s τ)` times the record
//!   (`s` times for an orthographic map, τ = 0). The WGSL module scales an uploaded record by
//!   this factor (`sa_offset_scale`), the depth bias by `s` alone (it is proportional to ρ).
//! - **Texel extents.** `(2/res) · |E_s|` and `(2/res) · |E_t|`, the texel's two world-space
//!   edges, for PCF or PCSS radii in world units (anisotropic for warped maps).
//!
//! # Per point
//!
//! The values above are maxima over B, set by B's coarsest texels; a shader can instead offset each
//! lookup by what its own point needs ([`normal_offset_at`], the WGSL module's
//! `sa_local_normal_offset`). On the lit plane through p with unit normal n the stored depth is
//! affine in (s, t) (a projective map keeps planes), so its step across the kernel is the same
//! anywhere on the plane, `ρ · (2/res) · (|g_s| + |g_t|)` with `g_e = c_e + ∂d/∂λ · τ_e` taken at p
//! itself. The lookup point q = p + o n lies o / cos α above the plane along the light, worth
//! `|∂d/∂λ(q)| · o / cos α` of depth, and `∂d/∂λ = (row₂ · l) / w` is constant along a light ray (w
//! is), with `w(q) = w(p) + o · (row₃ · n)`. Asking that depth to cover the step plus the `f32`
//! rounding δ of the two depths compared gives the least offset in closed form,
//!
//! ```text
//! Y = ρ · (2/res) · (|c_s cos α + ∂d/∂λ (n · E_s)| + |c_t cos α + ∂d/∂λ (n · E_t)|) + δ cos α,
//! o(p, n) = Y / (|∂d/∂λ(p)| − Y · (row₃ · n) / w(p)),
//! ```
//!
//! every quantity at p (the same `E_s`, `E_t`, `c_e` as above), finite and continuous at grazing
//! light (cos α → 0 leaves `ρ (2/res) |∂d/∂λ| (|n · E_s| + |n · E_t|)`). Where the denominator is not
//! positive the lookup point would pass the map's centre of projection: no offset suffices. ρ here
//! is `r + ½ + 1/64`: the 1/64 texel covers the GPU's `f32` choice of texel near a texel's edge.
//! Unlike the maximum it needs no bound over B, so it holds wherever the plane's own texels are the
//! ones read (tests/bias.rs checks it against the depths stored on the texels' rays, and that it is
//! the least offset that leaves the kernel's whole reach lit).
//!
//! # The maximum over B
//!
//! Each value is a maximum over B, taken exactly from B's vertices:
//!
//! - c_e is affine in position (d = (affine in σ) + (row₂ · l) · λ · w′(σ), so ∂d/∂s at constant λ
//!   is affine in λ, a linear function of position): `|c_s| + |c_t|` is convex, its maximum at
//!   a vertex.
//! - Along a light ray nothing else changes, so the rest are maxima over B's projection, the
//!   convex polygon of its vertices' projections. In map coordinates σ = (s, t) the plane ⊥ l is
//!   reached through a homography whose denominator w′ = 1/w is affine in σ: an edge vector is
//!   `N(σ) / w′(σ)²` with N affine in σ, and `∂d/∂λ = (row₂ · l) · w′` is affine. The depth
//!   slope's `diag · |∂d/∂λ| ∝ |N(σ)| / w′(σ)` has convex sublevel sets `|N| ≤ c · w′`: its
//!   maximum is at a vertex.
//! - The edges and the diagonal, `|N| / w′²`, are not quasi-convex (for LiSPSM `|E_t| ∝ z · |(x,
//!   z)|`, whose sublevel sets are not convex beyond 54.7° off the warp axis). Along a level line
//!   of w′ the function is convex, so a maximum is on the polygon's boundary; on a segment
//!   `|N(τ)|² / w′(τ)⁴` has its interior critical points at the roots of a quadratic
//!   (`(dQ/dτ) w′ − 4 Q (dw′/dτ) = 0`, Q = |N|²), taken on every chord between two vertices
//!   (every chord lies in B, and the polygon's edges are among them).
//! - `A = (|c_s| + |c_t|) · w / |row₂ · l|` is the largest of the four products `(±c_s ± c_t) · w`
//!   of affine functions, each a quadratic with no interior maximum in B unless along a whole line
//!   or plane: its maximum is on a chord between two vertices, at an end or the parabola's apex.
//!
//! Signs: each depth value is what to *add* to the receiver's depth in the map's convention
//! before comparing it with the stored depth (less-equal for [`ClipDepth::NegOneToOne`] and
//! [`ClipDepth::ZeroToOne`], whose depth grows away from the light: negative; greater-equal for
//! [`ClipDepth::Reversed`]: positive).

use super::output::{texel_vectors, FrameMap};
use crate::error::{fmt_num, Error, Result};
use crate::maps::matrix::in_clip_depth;
use crate::maps::ClipDepth;
use glam::{DMat4, DVec3};

/// The texels added to a kernel's reach r + ½ by [`normal_offset_at`]: the GPU's `f32` lookup
/// may take the neighbouring texel when the point is within a small fraction of a texel of an
/// edge (`SA_TEXEL_SLACK` in the WGSL module).
pub const TEXEL_SLACK: f64 = 1.0 / 64.0;

/// The `f32` rounding of the two depths a lookup compares, in depth-attachment units (8 ulps at
/// depth 1, as [`Bias::constant_depth`] allows).
const DEPTH_ROUNDING: f64 = 8.0 * f32::EPSILON as f64;

/// A map's bias and filtering values for a PCF kernel ([`FrameMap::bias`]; the module docs
/// derive them).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bias {
    /// World units to move the lookup point along the surface's unit normal: with it alone no
    /// lit surface of B (angle to the light below 90°) shadows itself, the offset point's own
    /// footprint counted (module docs), wherever the offset point does not pass the map's
    /// centre of projection (a normal toward it with `sin α ≥ w(p) / (normal_offset · |row₃|)`;
    /// [`FrameMap::normal_offset_at`] serves such points); `+∞` where no finite offset is
    /// certified.
    pub normal_offset: f64,
    /// The map's depth units per unit of tan α (α the angle between the surface's normal and the
    /// direction to the light), to add to the receiver's depth: `constant_depth +
    /// slope_scaled_depth · tan α` alone keeps a lit surface from shadowing itself. Negative for
    /// [`ClipDepth::NegOneToOne`] and [`ClipDepth::ZeroToOne`], positive for
    /// [`ClipDepth::Reversed`].
    pub slope_scaled_depth: f64,
    /// The map's depth units to add to the receiver's depth at any slope: the depth's largest
    /// step across the kernel's reach at a constant distance along the light (0 for an
    /// orthographic map), and the `f32` rounding of the depths compared (8 ulps at stored depth
    /// 1: 16 of [`ClipDepth::NegOneToOne`]'s clip depth, which a renderer stores halved), signed
    /// as `slope_scaled_depth`.
    pub constant_depth: f64,
    /// The largest world-space extents over B of the texel's two edges, along clip s and t.
    pub texel_extent: (f64, f64),
    /// τ, how fast the normal offset outgrows the kernel's reach ρ = r + ½ (module docs,
    /// "Normal offset"): the largest over α of the bound's denominator term
    /// `ρ (2/res) |row₃| (a cos α + b sin α) sin α`, in [0, 1) where `normal_offset` is finite
    /// (0 for an orthographic map). A kernel of reach `s ρ` (s ≥ 1) needs at most
    /// `s (1 − τ)/(1 − s τ) · normal_offset` (none is certified where `s τ ≥ 1`): the WGSL
    /// module's `sa_offset_scale`, for a record uploaded for a smaller kernel than the shader's.
    pub normal_offset_growth: f64,
}

impl FrameMap {
    /// The normal offset, depth bias and texel extents for a PCF kernel of radius `r` texels
    /// (taps at whole-texel offsets −r..=r in s and t; 0 for a single lookup; add ½ for hardware
    /// comparison filtering), each the maximum over the map's focus body B, the depth values in
    /// `depth`'s convention (see the module [`crate::frame::bias`] for the derivation).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `r` when it is negative or not finite.
    pub fn bias(&self, r: f64, depth: ClipDepth) -> Result<Bias> {
        if !(r.is_finite() && r >= 0.0) {
            return Err(Error::invalid(
                "r",
                format!(
                    "the PCF radius must be finite and ≥ 0 texels (got {}); use 0 for a single \
                     lookup",
                    fmt_num(r)
                ),
            ));
        }
        Ok(self.bias_unchecked(r, depth))
    }

    /// The normal offset this point needs (module docs, "Per point"): world units along the
    /// unit surface normal `n` (world space) at the world point `p` for a PCF kernel of radius
    /// `r` texels, for the map in `depth`'s convention. Much smaller than
    /// [`Bias::normal_offset`], the maximum over B, where the map's texels are finer than its
    /// coarsest. `Some(0.0)` for a surface turned away from the light (in shadow anyway); `None`
    /// where no offset suffices (the lookup point would pass the map's centre of projection, or
    /// `p` is behind it).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `r` (negative or not finite), `p` (not finite) or `n`
    /// (not a finite non-zero vector).
    pub fn normal_offset_at(
        &self,
        p: impl Into<DVec3>,
        n: impl Into<DVec3>,
        r: f64,
        depth: ClipDepth,
    ) -> Result<Option<f64>> {
        let (p, n) = (p.into(), n.into());
        self.bias(r, depth)?;
        if !p.is_finite() {
            return Err(Error::invalid("p", "the surface point must be finite"));
        }
        let n = n.try_normalize().ok_or_else(|| {
            Error::invalid("n", "the surface normal must be a finite, non-zero vector")
        })?;
        let eye_to_world = self.world_to_eye.inverse();
        let l = eye_to_world
            .transform_vector3(self.shadow.light_dir())
            .normalize();
        Ok(normal_offset_at(
            &self.world_to_clip(depth),
            depth,
            self.resolution,
            p,
            n,
            l,
            r,
        ))
    }

    /// [`FrameMap::bias`] for a valid `r`.
    pub(super) fn bias_unchecked(&self, r: f64, depth: ClipDepth) -> Bias {
        let m = self.shadow.matrix();
        let l = self.shadow.light_dir();
        let m_c = in_clip_depth(&m, depth);
        let texel = 2.0 / f64::from(self.resolution);
        let reach = (r + 0.5) * texel;
        // Per vertex: (w, E_s, E_t), the depth's steps across the texel (c_s, c_t) and its rate
        // along the light.
        let mut at = [(0.0, DVec3::ZERO, DVec3::ZERO); super::MAX_BODY_VERTICES];
        let mut steps = [(0.0, 0.0, 0.0); super::MAX_BODY_VERTICES];
        let mut n = 0;
        let (mut slope, mut across, mut k, mut sign) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
        for p in self.body() {
            let Some((es, et)) = texel_vectors(&m, l, *p) else {
                continue;
            };
            let h = m_c * p.extend(1.0);
            let grad = (m_c.row(2).truncate() * h.w - m_c.row(3).truncate() * h.z) / (h.w * h.w);
            let rate = grad.dot(l);
            let (cs, ct) = (grad.dot(es), grad.dot(et));
            slope = slope.max(diagonal(es, et) * rate.abs());
            across = across.max(cs.abs() + ct.abs());
            k = k.max((rate * h.w).abs());
            sign = rate.signum();
            at[n] = (h.w, es, et);
            steps[n] = (h.w, cs, ct);
            n += 1;
        }
        let at = &at[..n];
        let ext_s = chord_max(at, |es, _| es);
        let ext_t = chord_max(at, |_, et| et);
        let diag = chord_max(at, |es, et| es + et).max(chord_max(at, |es, et| es - et));
        // max over B of (|c_s| + |c_t|) / |∂d/∂λ| = (|c_s| + |c_t|) · w / |k|.
        let along = steps_max(&steps[..n]) / k;
        // The need with the offset point's own footprint, bounded over every α (module docs):
        // max_B A/w = (|c_s| + |c_t|)/|k| and max_B diag/w = diag |∂d/∂λ| / |k|, each largest
        // at a vertex.
        let row3 = m_c.row(3).truncate().length();
        let g = reach * row3 / k;
        let bound = offset_bound(
            (reach * along, reach * diag),
            (g * across, g * slope),
            OFFSET_BOUND_PIECES,
        );
        Bias {
            normal_offset: bound,
            normal_offset_growth: offset_growth(g * across, g * slope),
            slope_scaled_depth: -sign * reach * slope,
            // The rounding is the stored depths' (8 ulps at stored depth 1): OpenGL's [−1, 1]
            // clip depth is stored halved, so its record holds twice that.
            constant_depth: -sign * (reach * across + DEPTH_ROUNDING / stored_per_clip(depth)),
            texel_extent: (texel * ext_s, texel * ext_t),
        }
    }
}

/// The normal offset the point `p` with unit normal `n` needs (module docs, "Per point") in a
/// map of `resolution` texels with matrix `m` (any space → clip, `depth`'s convention; a map that
/// projects along `l`, the unit direction light travels, in the same space: clip w constant
/// along it), for a PCF kernel of radius `r` texels. What the WGSL module's
/// `sa_local_normal_offset` computes in `f32`. `Some(0.0)` for a surface turned away from the
/// light; `None` where no offset suffices or p is behind the map's centre of projection.
#[must_use]
pub fn normal_offset_at(
    m: &DMat4,
    depth: ClipDepth,
    resolution: u32,
    p: DVec3,
    n: DVec3,
    l: DVec3,
    r: f64,
) -> Option<f64> {
    let cos_a = -n.dot(l);
    if cos_a <= 0.0 {
        return Some(0.0);
    }
    let (es, et) = texel_vectors(m, l, p)?;
    let h = *m * p.extend(1.0);
    // Depth-attachment units: OpenGL's [−1, 1] is stored as its half plus ½.
    let scale = stored_per_clip(depth);
    let grad = (m.row(2).truncate() * h.w - m.row(3).truncate() * h.z) * (scale / (h.w * h.w));
    let k = grad.dot(l);
    let reach = (r + 0.5 + TEXEL_SLACK) * 2.0 / f64::from(resolution);
    let step = |e: DVec3| (grad.dot(e) * cos_a + k * n.dot(e)).abs();
    let y = reach * (step(es) + step(et)) + DEPTH_ROUNDING * cos_a;
    let den = k.abs() - y * m.row(3).truncate().dot(n) / h.w;
    let o = y / den;
    (den > 0.0 && o.is_finite()).then_some(o)
}

/// Depth-attachment units per unit of `depth`'s clip depth: OpenGL's [−1, 1] is stored as its
/// half plus ½, the other two as they are.
fn stored_per_clip(depth: ClipDepth) -> f64 {
    if depth == ClipDepth::NegOneToOne {
        0.5
    } else {
        1.0
    }
}

/// The sub-intervals of α ∈ [0, π/2] over which [`offset_bound`] bounds the normal offset.
const OFFSET_BOUND_PIECES: u32 = 256;

/// An upper bound of `max_α N(α) / D(α)` over α ∈ [0, π/2], `N = a_n cos α + b_n sin α` and
/// `D = 1 − (a_d cos α + b_d sin α) sin α` (module docs, "Normal offset"; all four ≥ 0), `+∞`
/// where D reaches 0. On each of `pieces` equal sub-intervals, N's largest value over D's least:
/// N = hypot(a_n, b_n) cos(α − atan2(b_n, a_n)) and `(a_d cos α + b_d sin α) sin α = b_d/2 +
/// hypot(a_d, b_d)/2 · sin(2α − atan2(b_d, a_d))` are sinusoids, each largest over a
/// sub-interval at one of its ends or at its crest (N's at atan2(b_n, a_n), D's term's at
/// (π/2 + atan2(b_d, a_d))/2) where that lies inside. The bound exceeds the maximum by at most
/// the variation of N/D over one sub-interval.
fn offset_bound((a_n, b_n): (f64, f64), (a_d, b_d): (f64, f64), pieces: u32) -> f64 {
    let n = |x: f64| a_n * x.cos() + b_n * x.sin();
    let t = |x: f64| (a_d * x.cos() + b_d * x.sin()) * x.sin();
    let crest_n = b_n.atan2(a_n);
    let crest_t = 0.5 * (std::f64::consts::FRAC_PI_2 + b_d.atan2(a_d));
    let step = std::f64::consts::FRAC_PI_2 / f64::from(pieces);
    let mut best = 0.0f64;
    for i in 0..pieces {
        let (lo, hi) = (step * f64::from(i), step * f64::from(i + 1));
        let inside = |c: f64| (lo..=hi).contains(&c);
        let n_max = if inside(crest_n) {
            a_n.hypot(b_n)
        } else {
            n(lo).max(n(hi))
        };
        let t_max = if inside(crest_t) {
            0.5 * (b_d + a_d.hypot(b_d))
        } else {
            t(lo).max(t(hi))
        };
        let d_min = 1.0 - t_max;
        if d_min <= 0.0 {
            return f64::INFINITY;
        }
        best = best.max(n_max / d_min);
    }
    best
}

/// τ = max over α ∈ [0, π/2] of `(a_d cos α + b_d sin α) sin α` (a_d, b_d ≥ 0), the
/// denominator term of [`offset_bound`]: `b_d/2 + hypot(a_d, b_d)/2 · sin(2α − atan2(b_d, a_d))`,
/// whose crest (π/2 + atan2(b_d, a_d))/2 lies in [π/4, π/2].
fn offset_growth(a_d: f64, b_d: f64) -> f64 {
    0.5 * (b_d + a_d.hypot(b_d))
}

/// The largest `(|c_s| + |c_t|) · w` over B from its vertices' `(w, c_s, c_t)`, each affine in
/// position: the maximum of the four products `(±c_s ± c_t) · w`, each a quadratic along a chord
/// whose maximum over B is on a chord between two vertices (module docs), at an end or at the
/// parabola's apex.
fn steps_max(steps: &[(f64, f64, f64)]) -> f64 {
    let mut best = 0.0f64;
    for (i, &(wi, si, ti)) in steps.iter().enumerate() {
        for &(wj, sj, tj) in &steps[i..] {
            for (a, b) in [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)] {
                let (u0, u1) = (a * si + b * ti, a * (sj - si) + b * (tj - ti));
                let (w0, w1) = (wi, wj - wi);
                let q = |t: f64| (u0 + u1 * t) * (w0 + w1 * t);
                best = best.max(q(0.0)).max(q(1.0));
                if u1 * w1 < 0.0 {
                    let apex = -(u0 * w1 + u1 * w0) / (2.0 * u1 * w1);
                    if apex > 0.0 && apex < 1.0 {
                        best = best.max(q(apex));
                    }
                }
            }
        }
    }
    best
}

/// The texel's longer diagonal.
fn diagonal(es: DVec3, et: DVec3) -> f64 {
    (es + et).length().max((es - et).length())
}

/// The largest length of the edge vector `f(E_s, E_t)` over B, from its values at B's vertices
/// `(w, E_s, E_t)`: at the vertices and at the interior critical points of every chord between
/// two (module docs: `N = E / w²` and `w′ = 1 / w` are affine along a chord in map coordinates).
fn chord_max(at: &[(f64, DVec3, DVec3)], f: impl Fn(DVec3, DVec3) -> DVec3) -> f64 {
    let mut best = at
        .iter()
        .map(|&(_, es, et)| f(es, et).length())
        .fold(0.0f64, f64::max);
    for (i, &(wi, esi, eti)) in at.iter().enumerate() {
        for &(wj, esj, etj) in &at[i + 1..] {
            let (li, lj) = (1.0 / wi, 1.0 / wj);
            let (ni, nj) = (f(esi, eti) / (wi * wi), f(esj, etj) / (wj * wj));
            let dn = nj - ni;
            let dl = lj - li;
            // Q(τ) = a τ² + b τ + c = |N(τ)|²; w′(τ) = li + dl τ; roots of Q′ w′ − 4 Q dl.
            let (a, b, c) = (dn.length_squared(), 2.0 * ni.dot(dn), ni.length_squared());
            let (qa, qb, qc) = (
                -2.0 * a * dl,
                2.0 * a * li - 3.0 * b * dl,
                b * li - 4.0 * c * dl,
            );
            for tau in quadratic_roots(qa, qb, qc).into_iter().flatten() {
                if tau > 0.0 && tau < 1.0 {
                    let w = li + dl * tau;
                    best = best.max((ni + dn * tau).length() / (w * w));
                }
            }
        }
    }
    best
}

/// The real roots of `a x² + b x + c` (a linear equation when `a` is 0; none when degenerate).
fn quadratic_roots(a: f64, b: f64, c: f64) -> [Option<f64>; 2] {
    if a == 0.0 {
        return [(b != 0.0).then(|| -c / b), None];
    }
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return [None, None];
    }
    // The cancellation-free pair.
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    [Some(q / a), (q != 0.0).then(|| c / q)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quadratic_roots_are_roots() {
        for (a, b, c) in [
            (1.0, -3.0, 2.0),
            (2.0, 0.0, -8.0),
            (0.0, 2.0, -1.0),
            (1e-9, 1.0, -1.0),
        ] {
            for x in quadratic_roots(a, b, c).into_iter().flatten() {
                let v: f64 = a * x * x + b * x + c;
                assert!(
                    v.abs() < 1e-9 * (1.0 + x.abs() * x.abs()),
                    "{a} {b} {c}: {x} gives {v}"
                );
            }
        }
        assert_eq!(quadratic_roots(1.0, 0.0, 1.0), [None, None]);
    }

    /// The chord maximum finds an interior maximum of |N|/w′² that no vertex has (a dense scan of
    /// the chord agrees).
    #[test]
    fn chord_max_finds_an_interior_maximum() {
        // Vertex values: w and E chosen so that |E(τ)| = |N(τ)| / w′(τ)² peaks inside.
        let at = [
            (1.0, DVec3::new(1.0, 0.0, 0.0), DVec3::ZERO),
            (4.0, DVec3::new(-0.05, 0.1, 0.0), DVec3::ZERO),
        ];
        let got = chord_max(&at, |es, _| es);
        let (li, lj) = (1.0, 0.25);
        let (ni, nj) = (at[0].1, at[1].1 / 16.0);
        let scan = (0..=100_000)
            .map(|k| {
                let t = f64::from(k) / 100_000.0;
                let w = li + (lj - li) * t;
                (ni + (nj - ni) * t).length() / (w * w)
            })
            .fold(0.0f64, f64::max);
        let vertices = at[0].1.length().max(at[1].1.length());
        assert!(
            scan > 1.2 * vertices,
            "the example's maximum is interior ({scan} vs {vertices})"
        );
        assert!((got - scan).abs() <= 1e-6 * scan, "{got} vs scan {scan}");
    }
}
