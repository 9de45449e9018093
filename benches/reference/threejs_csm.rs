//! A Rust port of three.js's cascaded shadow maps (`examples/jsm/csm`), for the engines' defaults
//! (examples/engine_defaults.rs, docs/planning.md) and tests/engine_ports.rs (issue 31 item 9).
//!
//! Follows mrdoob/three.js as stored in the public-code index:
//!
//! - `examples/jsm/csm/CSMShadowNode.js` at commit `03009769f17ef624dca31d472ec176a984aac6ab`
//!   (the WebGPU node): `getBreaks` (its `uniformSplit`, `logarithmicSplit`, `practicalSplit`),
//!   `initCascades`, `updateShadowBounds` and `updateBefore` (each cascade's light placed on the
//!   world-anchored texel grid of the light's orientation);
//! - `examples/jsm/csm/CSM.js` at commit `014d454ba21db8dc1eb8f1b9d8dfa48dcf0763ba` (the WebGL
//!   class): its defaults, [`CsmOptions::default`] (3 cascades, `maxFar` 100 000, `practical`,
//!   `shadowMapSize` 2048, `lightNear` 1, `lightFar` 2000, `lightMargin` 200, no fade). Its
//!   `getBreaks` and `updateShadowBounds` are the node's, line for line. Its `update` places the
//!   lights in the frame of the previous frame's shadow camera, not at the world origin: the same
//!   orientation and square, the texel grid anchored elsewhere (less than a texel's shift, which
//!   changes no texel size and no error);
//! - `examples/jsm/csm/CSMFrustum.js` at commit `0255e15dd1d46b5f00e51398b5052d88720eba9a`:
//!   `setFromProjectionMatrix` (WebGL clip, far vertices pulled in to `maxFar`), `split` (vertices
//!   lerped along the frustum's edges by the breaks) and `toSpace`;
//! - three.js core: `PerspectiveCamera.updateProjectionMatrix` with `Matrix4.makePerspective`
//!   (WebGL clip, no zoom, film offset or view offset), `OrthographicCamera.updateProjectionMatrix`
//!   with `Matrix4.makeOrthographic`, `Matrix4.lookAt` (rotation only, its degenerate-up nudge
//!   included), `Object3D.lookAt` for a camera (`lookAt(position, target, up)`, up (0, 1, 0)) and
//!   `LightShadow.updateMatrices` (the shadow camera at the light looking at its target;
//!   `shadowMatrix` = bias · projection · matrixWorldInverse, WebGL depth).
//!
//! Arithmetic is `f64`, as JavaScript's numbers; the shadow matrix reaches the GPU as a
//! `Float32Array` uniform. Not ported: the fade option (off by default), the shader-side cascade
//! choice (the cascade whose `[breaks[i − 1], breaks[i])` holds the fragment's linear depth
//! `(d − near)/(far − near)`), the lights' colour, intensity and bias, and the scene graph: the
//! quaternion round trip of `Object3D.lookAt` (the matrix world is composed from a quaternion, not
//! copied) and `Matrix4.invert` of the matrix world, which the port forms as the rigid inverse
//! directly (equal up to rounding).

use glam::{DMat4, DVec3, DVec4};

/// At most this many cascades (the fixed arrays of this port; three.js has no limit).
pub const MAX_CASCADES: usize = 4;

/// The fields of three.js's `PerspectiveCamera` that the cascades read.
#[derive(Debug, Clone, Copy)]
pub struct PerspectiveCamera {
    /// Full vertical field of view, degrees.
    pub fov: f64,
    /// Width / height.
    pub aspect: f64,
    pub near: f64,
    pub far: f64,
    /// `matrixWorld`: world from camera.
    pub matrix_world: DMat4,
}

impl PerspectiveCamera {
    /// `updateProjectionMatrix` then `makePerspective(left, right, top, bottom, near, far)`,
    /// WebGL clip (zoom 1, no film or view offset).
    pub fn projection_matrix(&self) -> DMat4 {
        let near = self.near;
        let top = near * (std::f64::consts::PI / 180.0 * 0.5 * self.fov).tan();
        let height = 2.0 * top;
        let width = self.aspect * height;
        let left = -0.5 * width;
        let (right, bottom, far) = (left + width, top - height, self.far);
        let x = 2.0 * near / (right - left);
        let y = 2.0 * near / (top - bottom);
        let a = (right + left) / (right - left);
        let b = (top + bottom) / (top - bottom);
        let c = -(far + near) / (far - near);
        let d = (-2.0 * far * near) / (far - near);
        DMat4::from_cols(
            DVec4::new(x, 0.0, 0.0, 0.0),
            DVec4::new(0.0, y, 0.0, 0.0),
            DVec4::new(a, b, c, -1.0),
            DVec4::new(0.0, 0.0, d, 0.0),
        )
    }
}

/// `Vector3.applyMatrix4`: `m · (v, 1)` divided by w.
fn apply_matrix4(v: DVec3, m: &DMat4) -> DVec3 {
    let h = *m * v.extend(1.0);
    h.truncate() / h.w
}

/// `CSMFrustum`: the four near and four far vertices (order: (1, 1), (1, −1), (−1, −1),
/// (−1, 1) in clip x, y).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct CsmFrustum {
    pub near: [DVec3; 4],
    pub far: [DVec3; 4],
}

impl CsmFrustum {
    /// `setFromProjectionMatrix(projectionMatrix, maxFar)` for a perspective projection: the
    /// clip corners through the inverse projection, the far ones scaled by min(maxFar/|z|, 1).
    pub fn from_projection_matrix(projection: &DMat4, max_far: f64) -> CsmFrustum {
        let inverse = projection.inverse();
        let xy = [(1.0, 1.0), (1.0, -1.0), (-1.0, -1.0), (-1.0, 1.0)];
        let mut f = CsmFrustum::default();
        for (j, (x, y)) in xy.into_iter().enumerate() {
            f.near[j] = apply_matrix4(DVec3::new(x, y, -1.0), &inverse);
            let v = apply_matrix4(DVec3::new(x, y, 1.0), &inverse);
            f.far[j] = v * (max_far / v.z.abs()).min(1.0);
        }
        f
    }

    /// `split(breaks, target)`: cascade i runs from the vertices lerped by `breaks[i − 1]` (the
    /// main frustum's near vertices for i = 0) to those lerped by `breaks[i]` (its far vertices
    /// for the last).
    pub fn split(&self, breaks: &[f64], target: &mut [CsmFrustum]) {
        let n = breaks.len();
        for (i, cascade) in target.iter_mut().enumerate().take(n) {
            for j in 0..4 {
                cascade.near[j] = if i == 0 {
                    self.near[j]
                } else {
                    self.near[j].lerp(self.far[j], breaks[i - 1])
                };
                cascade.far[j] = if i == n - 1 {
                    self.far[j]
                } else {
                    self.near[j].lerp(self.far[j], breaks[i])
                };
            }
        }
    }

    /// `toSpace(cameraMatrix, target)`.
    pub fn in_space(&self, m: &DMat4) -> CsmFrustum {
        CsmFrustum {
            near: self.near.map(|v| apply_matrix4(v, m)),
            far: self.far.map(|v| apply_matrix4(v, m)),
        }
    }
}

/// `CSM`'s split modes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Mode {
    Uniform,
    Logarithmic,
    /// three.js fixes λ at 0.5 in `getBreaks`.
    Practical,
}

/// `CSM`'s constructor options that the geometry reads, with CSM.js's defaults.
#[derive(Debug, Clone, Copy)]
pub struct CsmOptions {
    pub cascades: usize,
    pub max_far: f64,
    pub mode: Mode,
    pub shadow_map_size: u32,
    pub light_near: f64,
    pub light_far: f64,
    pub light_margin: f64,
}

impl Default for CsmOptions {
    fn default() -> Self {
        CsmOptions {
            cascades: 3,
            max_far: 100_000.0,
            mode: Mode::Practical,
            shadow_map_size: 2048,
            light_near: 1.0,
            light_far: 2000.0,
            light_margin: 200.0,
        }
    }
}

/// `getBreaks`: `cascades` fractions of `far = min(camera.far, maxFar)`, the last 1. They are
/// used as lerp factors between the frustum's near and far vertices (`CSMFrustum.split`), so
/// cascade i ends at view depth `near + breaks[i] · (far − near)`.
pub fn get_breaks(camera: &PerspectiveCamera, options: &CsmOptions) -> [f64; MAX_CASCADES] {
    let (amount, near) = (options.cascades, camera.near);
    let far = camera.far.min(options.max_far);
    let uniform = |i: usize| (near + (far - near) * i as f64 / amount as f64) / far;
    let log = |i: usize| (near * (far / near).powf(i as f64 / amount as f64)) / far;
    let mut breaks = [0.0; MAX_CASCADES];
    for (i, b) in breaks.iter_mut().enumerate().take(amount - 1) {
        *b = match options.mode {
            Mode::Uniform => uniform(i + 1),
            Mode::Logarithmic => log(i + 1),
            // MathUtils.lerp(uniform, log, 0.5)
            Mode::Practical => {
                let (x, y) = (uniform(i + 1), log(i + 1));
                x + (y - x) * 0.5
            }
        };
    }
    breaks[amount - 1] = 1.0;
    breaks
}

/// `updateShadowBounds` for one cascade: the side of its square, the larger of the far plane's
/// diagonal (far[0] to far[2]) and the body diagonal (far[0] to near[2]), not rounded.
pub fn squared_bb_width(frustum: &CsmFrustum) -> f64 {
    let point1 = frustum.far[0];
    let point2 = if point1.distance(frustum.far[2]) > point1.distance(frustum.near[2]) {
        frustum.far[2]
    } else {
        frustum.near[2]
    };
    point1.distance(point2)
}

/// `Matrix4.lookAt(eye, target, up)`: the rotation whose +Z points from `target` to `eye`.
pub fn look_at_rotation(eye: DVec3, target: DVec3, up: DVec3) -> DMat4 {
    let mut z = eye - target;
    if z.length_squared() == 0.0 {
        z.z = 1.0;
    }
    z = z.normalize();
    let mut x = up.cross(z);
    if x.length_squared() == 0.0 {
        if up.z.abs() == 1.0 {
            z.x += 0.0001;
        } else {
            z.z += 0.0001;
        }
        z = z.normalize();
        x = up.cross(z);
    }
    let x = x.normalize();
    let y = z.cross(x);
    DMat4::from_cols(x.extend(0.0), y.extend(0.0), z.extend(0.0), DVec4::W)
}

/// `Matrix4.makeOrthographic(left, right, top, bottom, near, far)`, WebGL clip.
fn make_orthographic(left: f64, right: f64, top: f64, bottom: f64, near: f64, far: f64) -> DMat4 {
    let w = 1.0 / (right - left);
    let h = 1.0 / (top - bottom);
    let p = 1.0 / (far - near);
    let x = (right + left) * w;
    let y = (top + bottom) * h;
    let z = (far + near) * p;
    DMat4::from_cols(
        DVec4::new(2.0 * w, 0.0, 0.0, 0.0),
        DVec4::new(0.0, 2.0 * h, 0.0, 0.0),
        DVec4::new(0.0, 0.0, -2.0 * p, 0.0),
        DVec4::new(-x, -y, -z, 1.0),
    )
}

/// One cascade's light and shadow camera after `updateBefore` and the renderer's
/// `LightShadow.updateMatrices`.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Cascade {
    /// `squaredBBWidth`: the square's side in world units (`right − left`).
    pub width: f64,
    /// The light's (and its shadow camera's) world position.
    pub position: DVec3,
    /// The shadow camera's `projectionMatrix` (orthographic, WebGL clip).
    pub projection: DMat4,
    /// The shadow camera's `matrixWorldInverse`: light view from world.
    pub view: DMat4,
    /// `projection · view`: world → light clip (`_projScreenMatrix`).
    pub clip_from_world: DMat4,
    /// `shadowMatrix`: world → shadow texture coordinates (x, y, depth in [0, 1]).
    pub shadow_matrix: DMat4,
    /// The cascade's view-depth range `[near + b_{i−1} (far − near), near + b_i (far − near)]`
    /// (where the shader selects it).
    pub depths: (f64, f64),
}

/// The whole CSM for one camera and light direction (`lightDirection`, the direction light
/// travels): `updateFrustums` (`getBreaks`, `initCascades`, `updateShadowBounds`), then
/// `updateBefore`, then each light's `LightShadow.updateMatrices`. Fills
/// `out[..options.cascades]`.
pub fn update(
    camera: &PerspectiveCamera,
    light_direction: DVec3,
    options: &CsmOptions,
    out: &mut [Cascade; MAX_CASCADES],
) {
    let count = options.cascades;
    // getBreaks, initCascades
    let breaks = get_breaks(camera, options);
    let main = CsmFrustum::from_projection_matrix(&camera.projection_matrix(), options.max_far);
    let mut frustums = [CsmFrustum::default(); MAX_CASCADES];
    main.split(&breaks[..count], &mut frustums);
    let far = camera.far.min(options.max_far);
    // updateBefore: _lightDirection from the light's target and position; _lightOrientationMatrix
    // is a rotation (Matrix4.lookAt writes no translation into the module's fresh Matrix4).
    let dir = light_direction.normalize();
    let orientation = look_at_rotation(DVec3::ZERO, dir, DVec3::Y);
    let orientation_inverse = orientation.transpose();
    let camera_to_light = orientation_inverse * camera.matrix_world;
    for (i, (slot, frustum)) in out.iter_mut().zip(&frustums).enumerate().take(count) {
        // updateShadowBounds
        let width = squared_bb_width(frustum);
        let (left, right, top, bottom) = (-width / 2.0, width / 2.0, width / 2.0, -width / 2.0);
        let texel_width = (right - left) / f64::from(options.shadow_map_size);
        let texel_height = (top - bottom) / f64::from(options.shadow_map_size);
        let ls = frustum.in_space(&camera_to_light);
        let (mut min, mut max) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
        for v in ls.near.iter().chain(&ls.far) {
            min = min.min(*v);
            max = max.max(*v);
        }
        let mut center = (min + max) * 0.5;
        center.z = max.z + options.light_margin;
        center.x = (center.x / texel_width).floor() * texel_width;
        center.y = (center.y / texel_height).floor() * texel_height;
        let position = apply_matrix4(center, &orientation);
        // LightShadow.updateMatrices: the shadow camera at the light, looking at its target
        // (position + _lightDirection), up (0, 1, 0).
        let target = position + dir;
        let rotation = look_at_rotation(position, target, DVec3::Y);
        let matrix_world = DMat4::from_cols(
            rotation.x_axis,
            rotation.y_axis,
            rotation.z_axis,
            position.extend(1.0),
        );
        let r_t = rotation.transpose();
        let view = DMat4::from_cols(
            r_t.x_axis,
            r_t.y_axis,
            r_t.z_axis,
            (-(r_t * matrix_world.w_axis).truncate()).extend(1.0),
        );
        let projection = make_orthographic(
            left,
            right,
            top,
            bottom,
            options.light_near,
            options.light_far,
        );
        let clip_from_world = projection * view;
        let bias = DMat4::from_cols(
            DVec4::new(0.5, 0.0, 0.0, 0.0),
            DVec4::new(0.0, 0.5, 0.0, 0.0),
            DVec4::new(0.0, 0.0, 0.5, 0.0),
            DVec4::new(0.5, 0.5, 0.5, 1.0),
        );
        let b0 = if i == 0 { 0.0 } else { breaks[i - 1] };
        *slot = Cascade {
            width,
            position,
            projection,
            view,
            clip_from_world,
            shadow_matrix: bias * clip_from_world,
            depths: (
                camera.near + b0 * (far - camera.near),
                camera.near + breaks[i] * (far - camera.near),
            ),
        };
    }
}
