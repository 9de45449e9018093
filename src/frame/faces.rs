//! Face partitions of the visible frustum: each face part's focus body B_i (B cut by the prism of
//! the part along the light) and its map.

use super::body::{depth_extent, BodyClip};
use super::casters::Prism;
use super::input::check_resolutions;
use super::output::{Focus, Frame, FrameMap};
use super::{Built, Ctx, Slice, MAX_BODY_VERTICES, MAX_FACE_BOUND_PLANES, MAX_FACE_K};
use crate::analytic::partition::{z_splits, SplitScheme, MAX_PARTITIONS};
use crate::error::{Error, Result};
use crate::frustum::LightDir;
use crate::maps::faces::{face_spaces, visible_with, Face, FaceSpaces, FaceWarp, PartFitter};
use crate::maps::fit::FrustumInLight;
use crate::maps::lightspace::light_space_unit;
use crate::maps::ShadowMatrix;
use crate::numeric::EDGE_ON;
use glam::{DVec3, DVec4};

impl Ctx<'_, '_> {
    /// The face partitions of the visible frustum `[zn, zf]` (see [`FrameScheme::Faces`]).
    pub(super) fn faces_into(
        &self,
        rule: FaceWarp,
        k: usize,
        (zn, zf): (f64, f64),
        out: &mut Frame,
    ) -> Result<()> {
        if !(1..=MAX_FACE_K).contains(&k) {
            return Err(Error::invalid(
                "k",
                format!(
                    "must be in 1..={MAX_FACE_K} for face partitions (4k + 1 maps fill at most \
                     the frame's {MAX_PARTITIONS} slots; got {k})"
                ),
            ));
        }
        if self.planes.n > MAX_FACE_BOUND_PLANES {
            return Err(Error::invalid(
                "receivers",
                format!(
                    "must be a polytope of at most {MAX_FACE_BOUND_PLANES} planes for face \
                     partitions (got {})",
                    self.planes.n
                ),
            ));
        }
        let view = self.view.with_depth_range(zn, zf)?;
        let splits = z_splits(zn, zf, k, SplitScheme::SelfSimilar)?;
        let l = self.l;
        let light = LightDir::from_unit_unchecked(l);
        let tan = view.tan_half_fov();
        let ta = tan * view.aspect();
        let faces = visible_with(tan, ta, zn / zf, l);
        if faces.faces().is_empty() {
            return Err(Error::Degenerate(format!(
                "no face of the view frustum is seen by the light {l}"
            )));
        }
        let slots = faces
            .faces()
            .iter()
            .map(|f| if f.is_side() { k } else { 1 })
            .sum();
        check_resolutions(self.input, slots)?;
        // B of the whole visible range (its extent along the light is every part's depth range)
        // and its clipper, cut by the receivers once for every part (each part adds its prism).
        let receivers = self.receivers_clip(&view.corners())?;
        let whole = self.body_cut(receivers, zf, &[])?;
        if whole.focus == Focus::Empty || whole.n == 0 {
            return Ok(());
        }
        let (mut y_lo, mut y_hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for p in &whole.v[..whole.n] {
            let y = -l.dot(*p);
            y_lo = y_lo.min(y);
            y_hi = y_hi.max(y);
        }
        for &face in faces.faces() {
            let spaces = face_spaces(face, tan, ta, light);
            let count = if face.is_side() { k } else { 1 };
            for j in 0..count {
                let (a, b) = if face.is_side() {
                    splits.range(j)
                } else {
                    (zn, zn)
                };
                let part = FacePart {
                    face,
                    quad: face.vertices_with(&view, tan, ta, a, b),
                    depths: (a, b),
                    far: zf,
                    spaces: &spaces,
                };
                let res = self.input.resolution_at(out.k);
                out.push_with(|dst| {
                    self.face_part(&part, &receivers, (y_lo, y_hi), (rule, res), dst)
                })?;
            }
        }
        out.settle();
        Ok(())
    }

    /// One face part's map: B_i = B ∩ the prism of the part's quad along the light (B of the
    /// visible range, `receivers` its clipper cut by the receivers' planes), fitted with the
    /// face's candidate axes over B's extent `y` along the light and the casters of B_i.
    fn face_part(
        &self,
        part: &FacePart<'_>,
        receivers: &BodyClip,
        (y_lo, y_hi): (f64, f64),
        (rule, res): (FaceWarp, u32),
        dst: &mut Option<FrameMap>,
    ) -> Result<Built> {
        let FacePart {
            face,
            quad,
            depths: (a, b),
            far,
            spaces,
        } = *part;
        let l = self.l;
        let prism = quad_prism(&quad, l);
        let body = self.body_cut(*receivers, far, prism.as_slice())?;
        if body.focus == Focus::Empty || body.n == 0 {
            return Ok(Built::None(Focus::Empty));
        }
        let pts = &body.v[..body.n];
        // Any light space with y toward the light serves the casters' prism and depth.
        let ls = light_space_unit(LightDir::from_unit_unchecked(l), DVec3::NEG_Z);
        let mut fl = FrustumInLight::blank(ls);
        if !self.in_light(pts, body.unit, ls, &mut fl)? {
            return Ok(Built::None(Focus::EdgeOn));
        }
        let mut y_hi = y_hi;
        let mut sides = None;
        if let Some(p) = self.caster_extreme(&fl, body.n, |_| 1.0, 0.0, &mut sides)? {
            y_hi = y_hi.max(ls.y.dot(p));
        }
        let fitter = PartFitter {
            rule,
            y_range: (y_lo, y_hi),
            l,
            tan: self.view.tan_half_fov(),
        };
        // The fit measures each candidate over B_i's vertices with the frame's light and tan θ:
        // the chosen one's error is the map's.
        let (matrix, n_prime, err) =
            fitter.best::<{ 3 * MAX_BODY_VERTICES }>(spaces, pts, pts, face, (a, b))?;
        let (n_b, f_b) = depth_extent(pts);
        let shadow = ShadowMatrix::new(matrix, LightDir::from_unit_unchecked(l), n_prime, n_b, f_b);
        let slice = Slice {
            cover: (n_b, f_b),
            split: (a, b),
            blend: (b, b),
            res,
        };
        // The fit measured the map anyway: its figures are reported with measurement off too.
        // `ls` is the casters' volume's light space: the prism of B_i's footprint is its sides.
        let sides = sides.get_or_insert_with(|| Prism::new(&fl, body.n));
        self.finish_measured(
            shadow,
            Some(err),
            pts,
            &slice,
            body.focus,
            prism.as_slice(),
            Some(sides),
            dst,
        )?
        .face = Some(face);
        Ok(Built::Map)
    }
}

/// The side planes of the prism of a planar quad along the light: each contains an edge and the
/// light direction, outward from the quad. An edge within [`EDGE_ON`] of parallel to the light
/// gives no plane (its neighbours bound the quad's projection, a triangle then).
fn quad_prism(quad: &[DVec3; 4], l: DVec3) -> PlaneList<4> {
    let centre = 0.25 * (quad[0] + quad[1] + quad[2] + quad[3]);
    let mut out = PlaneList {
        p: [DVec4::ZERO; 4],
        n: 0,
    };
    for i in 0..4 {
        let (p, q) = (quad[i], quad[(i + 1) % 4]);
        let e = q - p;
        let n = e.cross(l);
        if n.length() <= EDGE_ON * e.length() {
            continue;
        }
        let n = if n.dot(centre - p) > 0.0 { -n } else { n };
        out.p[out.n] = n.extend(-n.dot(p));
        out.n += 1;
    }
    out
}

/// One part of a frustum face to map: the face, its quad between the part's depths, and the
/// face's candidate light spaces.
#[derive(Clone, Copy)]
struct FacePart<'s> {
    face: Face,
    quad: [DVec3; 4],
    depths: (f64, f64),
    /// The far depth of the visible range (B's slice).
    far: f64,
    spaces: &'s FaceSpaces,
}

/// Up to `N` planes.
struct PlaneList<const N: usize> {
    p: [DVec4; N],
    n: usize,
}

impl<const N: usize> PlaneList<N> {
    fn as_slice(&self) -> &[DVec4] {
        &self.p[..self.n]
    }
}
