//! The builders' result: a shadow matrix with what a renderer and the measurement need.
//!
//! # Conventions
//!
//! | space | convention |
//! |---|---|
//! | eye space (input) | right-handed, camera at the origin looking down −Z, Y up (glam `dcamera::rh::view::look_at_mat4`) |
//! | light clip space (output) | x, y ∈ [−1, 1] span the map after the divide by w; s = (x/w + 1)/2 along light-space x, t = (y/w + 1)/2 along the warp axis |
//! | clip depth, [`ClipDepth::NegOneToOne`] | z/w ∈ [−1, 1], −1 nearest the light (OpenGL) |
//! | clip depth, [`ClipDepth::ZeroToOne`] | z/w ∈ [0, 1], 0 nearest the light (Vulkan, wgpu, Direct3D, Metal) |
//! | clip depth, [`ClipDepth::Reversed`] | z/w ∈ [0, 1], 1 nearest the light, 0 farthest (reversed depth: Bevy's cascades; compare greater-equal, clear to 0) |
//!
//! The stored matrix is always the OpenGL one; [`ShadowMatrix::with_clip_depth`] converts, by
//! `z₀₁ = (z + w)/2` (row 2 becomes (row 2 + row 3)/2) or `z_rev = (w − z)/2 = w − z₀₁` (row 2
//! becomes (row 3 − row 2)/2), which leave x, y and w, hence the texel a point lands in,
//! unchanged.

use crate::measure::ShadowMap;
use crate::{LightDir, NPrime};
use glam::{DMat4, DVec3, DVec4, Mat4};

/// The depth range of light clip space after the perspective divide.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum ClipDepth {
    /// z/w ∈ [−1, 1] (OpenGL). The crate's internal convention.
    #[default]
    NegOneToOne,
    /// z/w ∈ [0, 1] (Vulkan, wgpu, Direct3D, Metal).
    ZeroToOne,
    /// Reversed depth: z/w ∈ [0, 1] with 1 nearest the light and 0 farthest (Bevy's cascades and
    /// most engines' reversed-Z passes): the depth test compares greater-equal and the map is
    /// cleared to 0; a caster nearer the light than the map's range has z/w > 1 (clamped to 1 by
    /// depth clamping).
    Reversed,
}

impl ClipDepth {
    /// Every convention.
    pub const ALL: [ClipDepth; 3] = [
        ClipDepth::NegOneToOne,
        ClipDepth::ZeroToOne,
        ClipDepth::Reversed,
    ];

    /// An OpenGL-depth matrix (any → light clip, such as [`ShadowMatrix::matrix`] or a
    /// command-line answer's `matrix`) in this convention: its depth row replaced by
    /// `(row 2 + row 3)/2` for [`ClipDepth::ZeroToOne`], `(row 3 − row 2)/2` for
    /// [`ClipDepth::Reversed`]; x, y and w unchanged.
    #[must_use]
    pub fn convert(self, opengl: &DMat4) -> DMat4 {
        in_clip_depth(opengl, self)
    }
}

/// A shadow matrix for one directional light and one view (sub)frustum, as a builder made it:
/// the fields are private, so a `ShadowMatrix` is always a builder's checked output.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShadowMatrix {
    /// The matrix and the unit light direction, in the form the measurement takes.
    map: ShadowMap,
    n_prime: NPrime,
    near: f64,
    far: f64,
}

impl ShadowMatrix {
    /// A builder's result: `matrix` finite and checked against the clip volume by the builder.
    #[inline]
    pub(crate) fn new(
        matrix: DMat4,
        light_dir: LightDir,
        n_prime: NPrime,
        near: f64,
        far: f64,
    ) -> Self {
        Self {
            map: ShadowMap::from_parts(matrix, light_dir),
            n_prime,
            near,
            far,
        }
    }

    /// Eye space → light clip space, OpenGL depth [−1, 1]; x, y span the map
    /// ([`ShadowMap::matrix`]).
    #[inline]
    #[must_use]
    pub fn matrix(&self) -> DMat4 {
        self.map.matrix()
    }

    /// Unit eye-space direction the light travels ([`ShadowMap::light_dir`]).
    #[inline]
    #[must_use]
    pub fn light_dir(&self) -> DVec3 {
        self.map.light_dir()
    }

    /// The warp parameter used ([`NPrime::UNWARPED`] for an orthographic map).
    #[inline]
    #[must_use]
    pub fn n_prime(&self) -> NPrime {
        self.n_prime
    }

    /// Near end of the view-depth range the map covers.
    #[inline]
    #[must_use]
    pub fn near(&self) -> f64 {
        self.near
    }

    /// Far end of the view-depth range the map covers.
    #[inline]
    #[must_use]
    pub fn far(&self) -> f64 {
        self.far
    }

    /// The matrix in the requested clip-depth convention (eye space → light clip space).
    ///
    /// ```
    /// # use shadow_aliasing::maps::{warp, ClipDepth, WarpRule};
    /// # use shadow_aliasing::ViewFrustum;
    /// # use glam::{DVec3, DVec4};
    /// let view = ViewFrustum::new(1.0, 50.0, 0.6)?;
    /// let s = warp(&view, DVec3::new(0.2, -1.0, 0.1), WarpRule::Lispsm)?;
    /// let m = s.with_clip_depth(ClipDepth::ZeroToOne);
    /// for c in view.corners() {
    ///     let h = m * DVec4::new(c.x, c.y, c.z, 1.0);
    ///     assert!(h.z >= -1e-9 * h.w && h.z <= h.w * (1.0 + 1e-9));
    /// }
    /// # Ok::<(), shadow_aliasing::Error>(())
    /// ```
    #[must_use]
    pub fn with_clip_depth(&self, depth: ClipDepth) -> DMat4 {
        in_clip_depth(&self.matrix(), depth)
    }

    /// The matrix in single precision for the GPU.
    #[must_use]
    pub fn to_mat4(&self, depth: ClipDepth) -> Mat4 {
        self.with_clip_depth(depth).as_mat4()
    }

    /// [`ShadowMatrix::to_mat4`] as plain column-major arrays (`[column][row]`), for a renderer on
    /// any math library.
    #[must_use]
    pub fn to_cols(&self, depth: ClipDepth) -> [[f32; 4]; 4] {
        self.to_mat4(depth).to_cols_array_2d()
    }

    /// World space → light clip space for a renderer: `S · view`, where `view` is the camera's
    /// world → eye matrix (glam `dcamera::rh::view::look_at_mat4`).
    #[must_use]
    pub fn world_to_clip(&self, view: DMat4, depth: ClipDepth) -> DMat4 {
        self.with_clip_depth(depth) * view
    }

    /// The map in the form [`crate::measure::point_error`] and [`crate::measure::frustum_max`]
    /// take.
    #[must_use]
    pub fn shadow_map(&self) -> ShadowMap {
        self.map
    }

    /// Light clip coordinates `(x/w, y/w, z/w)` of an eye-space point, OpenGL depth, or `None`
    /// when `w ≤ 0` (the point is behind the warp's centre of projection).
    #[must_use]
    pub fn project(&self, p: DVec3) -> Option<DVec3> {
        project(&self.matrix(), p)
    }
}

/// `(x/w, y/w, z/w)` of `m (p, 1)`, or `None` when `w` is not positive and finite.
#[must_use]
pub(crate) fn project(m: &DMat4, p: DVec3) -> Option<DVec3> {
    let h = *m * DVec4::new(p.x, p.y, p.z, 1.0);
    if h.w > 0.0 && h.is_finite() {
        Some(h.truncate() / h.w)
    } else {
        None
    }
}

/// An OpenGL-depth map `m` in the clip-depth convention `depth`: [`zero_to_one`] or
/// [`reversed`] of it, or `m` itself.
#[inline]
pub(crate) fn in_clip_depth(m: &DMat4, depth: ClipDepth) -> DMat4 {
    match depth {
        ClipDepth::NegOneToOne => *m,
        ClipDepth::ZeroToOne => zero_to_one(m),
        ClipDepth::Reversed => reversed(m),
    }
}

/// The reversed-depth form of an OpenGL-depth map: depth row `(M₃ − M₂)/2`, so that
/// `z_rev = (w − z)/2`, 1 at the near end (z = −w) and 0 at the far end (z = w). Every builder
/// checks this form too (`maps::fit::verify_clip`, `clip_at_slices`), as it does the `[0, 1]` one.
#[inline]
pub(crate) fn reversed(m: &DMat4) -> DMat4 {
    let z = 0.5 * (m.row(3) - m.row(2));
    let mut t = m.transpose();
    t.z_axis = z;
    t.transpose()
}

/// The `[0, 1]`-depth form of an OpenGL-depth map: depth row `(M₂ + M₃)/2`. Every builder checks
/// its matrix in both forms before returning it (`maps::warp::verify_clip`): where the map's w
/// spans many orders of magnitude the entrywise sum rounds differently from the rows it
/// combines, and the `[0, 1]` form can leave the clip volume while the OpenGL form does not.
#[inline]
pub(crate) fn zero_to_one(m: &DMat4) -> DMat4 {
    let z = 0.5 * (m.row(2) + m.row(3));
    let mut t = m.transpose();
    t.z_axis = z;
    t.transpose()
}
