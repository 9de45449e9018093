//! One map of a slice's focus body with a warp rule, and the trapezoidal map of B.

use super::body::{depth_extent, nearest_vertex};
use super::casters::{casters_too_far, Prism};
use super::input::WarpCentre;
use super::output::{Focus, FrameMap};
use super::{Built, Ctx, Slice};
use crate::error::Result;
use crate::frustum::{LightDir, NPrime};
use crate::maps::fit::{fit_body, FrustumInLight};
use crate::maps::lightspace::light_space_unit;
use crate::maps::tsm::{tsm_on_points, validate as validate_tsm};
use crate::maps::warp::{focus_in_range, rule_axis, rule_n_prime_on, warp_prepared, PreparedLight};
use crate::maps::{ShadowMatrix, TsmOptions, WarpRule};
use glam::{DVec3, DVec4};

impl Ctx<'_, '_> {
    pub(super) fn map(
        &self,
        s: &Slice,
        rule: WarpRule,
        dst: &mut Option<FrameMap>,
    ) -> Result<Built> {
        let body = self.body(s.cover.0, s.cover.1, &[])?;
        if body.focus == Focus::Empty || body.n == 0 {
            return Ok(Built::None(Focus::Empty));
        }
        let pts = &body.v[..body.n];
        let (n_b, f_b) = depth_extent(pts);
        let cam = self.view;
        let sub_full = cam.with_depth_range(s.cover.0, s.cover.1)?;
        let l = self.l;
        let centre_rule = match self.input.centre {
            WarpCentre::Rule => matches!(rule, WarpRule::Ogre | WarpRule::OgreOrtho { .. }),
            WarpCentre::Eye => false,
            WarpCentre::NearestVertex => true,
        };
        // TSM's focus distance, checked against the slice, scaled to B's depth (the slice's own
        // rule is kept for the frustum-only builder below, which scales nothing).
        let slice_rule = rule;
        let rule = match rule {
            WarpRule::Tsm { focus } => {
                let focus = focus_in_range(&sub_full, focus)?;
                WarpRule::Tsm {
                    focus: focus * (f_b - n_b) / (s.cover.1 - s.cover.0),
                }
            }
            r => r,
        };
        let ls = light_space_unit(LightDir::from_unit_unchecked(l), rule_axis(l, rule));
        let mut fl = FrustumInLight::blank(ls);
        // A whole slice is a frustum with volume, never edge-on: where its extents are below
        // the unit the frustum is the cause, and the builders decide (as the frustum-only
        // builder does) whether its map can be represented.
        if !self.in_light(pts, body.unit, ls, &mut fl)? && !body.whole {
            return Ok(Built::None(Focus::EdgeOn));
        }
        let mut focus = body.focus;
        let zero_depth = f_b - n_b <= 1e-9 * f_b;
        if zero_depth {
            focus = Focus::ZeroDepth;
        }
        // The frustum-only builder, exactly, when B is the slice and nothing extends its depth.
        let centre = if centre_rule {
            Some(nearest_vertex(&fl, body.n))
        } else {
            None
        };
        let n_prime = if zero_depth {
            NPrime::UNWARPED
        } else {
            let sub = cam.with_depth_range(n_b, f_b)?;
            match (rule, centre) {
                // Minimax chooses n′ for the map that is built: around a centre off the eye's
                // line the map's s is (x − x_c)/w (`fit_body`), so its search sees each vertex's
                // x from the centre. (For the eye's centre it minimised a map that is not built,
                // up to 6× the uniform map's S̄.) M_z, and so `MinimaxMz`, does not depend on x.
                (WarpRule::Minimax, Some(i)) => {
                    let mut from_centre = fl;
                    let xc = fl.q[i].x;
                    for q in &mut from_centre.q {
                        q.x -= xc;
                    }
                    rule_n_prime_on(&sub_full, &sub, &from_centre, rule)?
                }
                // The engines' rules see the slice's planes as their camera's: Filament's and
                // OGRE's cascades set the cascade camera's near and far to the split planes.
                _ => rule_n_prime_on(&sub_full, &sub, &fl, rule)?,
            }
        };
        let rho = n_prime.recip();
        let w_of = |p: DVec3| 1.0 + rho * (fl.ls.z.dot(p) - fl.z0);
        let y0 = centre.map_or(0.0, |i| fl.q[i].y);
        let mut prism = None;
        let caster = self.caster_extreme(&fl, body.n, w_of, y0, &mut prism)?;
        let default_centre = self.input.centre == WarpCentre::Rule;
        let shadow = if body.whole && caster.is_none() && default_centre {
            // `warp(&slice, l, rule)` itself, l normalised at the entry as `warp` does: B is the
            // slice and nothing extends its depth.
            warp_prepared(
                &sub_full,
                &PreparedLight::new(LightDir::new(l)?),
                slice_rule,
            )?
        } else {
            let fitted = fit_body(&fl, n_prime, centre, caster.as_slice());
            let matrix = match (fitted, caster) {
                (Ok(m), _) => m,
                // The same fit without the casters succeeds: they are the cause.
                (Err(_), Some(p)) if fit_body(&fl, n_prime, centre, &[]).is_ok() => {
                    return Err(casters_too_far(pts, p));
                }
                (Err(e), _) => return Err(e),
            };
            ShadowMatrix::new(matrix, LightDir::from_unit_unchecked(l), n_prime, n_b, f_b)
        };
        // `fl` is in the casters' volume's light space unless the rule chose another axis.
        let prism = (rule_axis(l, rule) == DVec3::NEG_Z)
            .then(|| &*prism.get_or_insert_with(|| Prism::new(&fl, body.n)));
        self.finish(shadow, pts, s, focus, prism, dst)?;
        Ok(Built::Map)
    }

    /// The trapezoidal map of B, its depth row refitted to B and the casters.
    pub(super) fn tsm_map(
        &self,
        s: &Slice,
        opts: TsmOptions,
        dst: &mut Option<FrameMap>,
    ) -> Result<Built> {
        let sub_full = self.view.with_depth_range(s.cover.0, s.cover.1)?;
        validate_tsm(&sub_full, &opts)?;
        let body = self.body(s.cover.0, s.cover.1, &[])?;
        if body.focus == Focus::Empty || body.n == 0 {
            return Ok(Built::None(Focus::Empty));
        }
        let pts = &body.v[..body.n];
        let (n_b, f_b) = depth_extent(pts);
        let l = self.l;
        let ls = light_space_unit(LightDir::from_unit_unchecked(l), DVec3::NEG_Z);
        let mut fl = FrustumInLight::blank(ls);
        // A whole slice is a frustum with volume, never edge-on: where its extents are below
        // the unit the frustum is the cause, and the builders decide (as the frustum-only
        // builder does) whether its map can be represented.
        if !self.in_light(pts, body.unit, ls, &mut fl)? && !body.whole {
            return Ok(Built::None(Focus::EdgeOn));
        }
        let focus = opts.focus * (f_b - n_b) / (s.cover.1 - s.cover.0);
        let focus_depth = n_b + focus;
        let region = self.body(
            s.cover.0,
            s.cover.1,
            &[DVec4::new(0.0, 0.0, -1.0, -focus_depth)],
        )?;
        let focus_region: &[DVec3] = if region.n > 0 {
            &region.v[..region.n]
        } else {
            pts
        };
        let centre_line = (ls.z.z * (f_b - n_b)).abs();
        let t = tsm_on_points(
            ls,
            pts,
            focus_region,
            DVec3::new(0.0, 0.0, -focus_depth),
            centre_line,
            opts.search,
            n_b,
            f_b,
        )?;
        let mut m = t.shadow.matrix();
        // Depth: v = y/w over B and the casters' extreme, −1 nearest the light (the form of the
        // crate's warps; monotonic along each light ray, whose w is constant).
        let row3 = m.row(3);
        let w_of = |p: DVec3| row3.dot(p.extend(1.0));
        let mut prism = None;
        let caster = self.caster_extreme(&fl, body.n, w_of, 0.0, &mut prism)?;
        let mut r = (f64::INFINITY, f64::NEG_INFINITY);
        for p in pts.iter().chain(caster.as_slice()) {
            let v = ls.y.dot(*p) / w_of(*p);
            r = (r.0.min(v), r.1.max(v));
        }
        let v_m = 0.5 * (r.0 + r.1);
        let v_h = (0.5 * (r.1 - r.0)).max(1e-9 * self.scale());
        let mut mt = m.transpose();
        mt.z_axis = (v_m * row3 - ls.y.extend(0.0)) / v_h;
        m = mt.transpose();
        let shadow = ShadowMatrix::new(
            m,
            LightDir::from_unit_unchecked(l),
            t.shadow.n_prime(),
            n_b,
            f_b,
        );
        // `ls` is the casters' volume's light space.
        let prism = prism.get_or_insert_with(|| Prism::new(&fl, body.n));
        self.finish(shadow, pts, s, body.focus, Some(prism), dst)?;
        Ok(Built::Map)
    }
}
