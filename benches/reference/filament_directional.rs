//! A Rust port of Filament's directional shadow focus with LiSPSM, for side-by-side benchmarks
//! (issue 23 item 9) and for the engines' defaults (examples/engine_defaults.rs).
//!
//! Follows `filament/src/ShadowMap.cpp` at google/filament commit
//! `0362f36ef6e6017426730cbbb68e7af1fda2f38c`, the revision docs/errata.md calls current (read
//! from the public-code index, which records no commit date for it; its two-edge
//! `texelSizeWorldSpaceAt` is what google/filament pull request #9734, "Improve shadow normal
//! bias calculation", opened 2026-02-20, describes, so the revision is of 2026). Each function
//! names the lines of that file it ports (`ShadowMap.cpp:L1–L2`). This revision keeps the light's
//! view matrix at the world origin (near = −max z, far = −min z of the light-space bounds; no
//! shift of the clipped volume's 64 vertices) and computes the texel size with
//! `texelSizeWorldSpaceAt(S, {0, 0, 0}, shadowDimension)` (the Jacobian of `inverse(S)`, a 4×4
//! inverse, at the world origin's NDC: both texel edges). Ported:
//!
//! - `ShadowMap::updateDirectional` (not stable: light frustum alignment `L`, LiSPSM, focus,
//!   texture mapping, texel size, the shadow camera's projection and model matrix);
//! - `ShadowMap::computeDirectionalShadowBounds`, `computeLightFrustumBounds` (receivers'
//!   light-space bounds ∩ casters', far from receivers, near from casters),
//!   `intersectFrustumWithBox` (steps a–d), `intersectFrustum`,
//!   `intersectSegmentWithPlanarQuad`, `intersectSegmentWithTriangle`;
//! - `ShadowMap::applyLISPSM`, `computeLightRotation`, `computeFocusParams`, `warpFrustum`,
//!   `directionalLightFrustum`, `computeNearFar`, `computeNearFarOfWarpSpace`,
//!   `compute2DBounds` (points and box), `computeFrustumCorners`, `getTextureCoordsMapping`,
//!   `getViewport`, the file's static `jacobian` and `texelSizeWorldSpaceAt`;
//! - `ShadowMap::SceneInfo::SceneInfo` and `updateSceneInfoDirectional` (scene bounds,
//!   light-space near/far of casters and receivers);
//! - `ShadowMapManager::updateCascadeShadowMaps` (the culling pass over the whole frustum, then one
//!   `updateDirectional` per cascade) and `ShadowMapManager::updateNearFarPlanes`, from the index's
//!   `filament/src/ShadowMapManager.cpp` (commit `003e5005713cba55cbd3f3a423c472000b96b868`; the
//!   index holds no ShadowMapManager.cpp at `0362f36e`: the geometry ported here, the splits and
//!   the per-cascade near/far, is the same in both);
//! - helpers: `Frustum::setProjection` (normalised planes), `Aabb::getCorners`,
//!   `Aabb::transform` (Arvo), `mat4f::project`, `mat4f * float3` (`{v, 1}`, libs/math mat4.h),
//!   `FCamera::rigidTransformInverse`, the 4×4 `inverse` (`gaussJordanInverse`, libs/math
//!   TMatHelpers.h). `mat4::lookTo` is `lookAt`'s body with `direction` in place of
//!   `center − eye` (in `double`, as Filament calls it); `getDirectionalLightViewMatrix`'s
//!   `position` defaults to `{}` (filament/src/ShadowMap.h).
//!
//! Options are Filament's defaults: `shadowNearHint` 1, `shadowFarHint` 100, `stable` false,
//! `shadowFar` 0, debug `focus_shadowcasters` and `far_uses_shadowcasters` true,
//! `disable_light_frustum_align` false; `lispsm` true by default (the LiSPSM path this port exists
//! for; [`ShadowOptions::lispsm`] false gives the orthographic, view-aligned map). Depth clamp is a
//! parameter (Filament uses it for cascades where the device supports it). Not ported (no value of
//! the map depends on them): the debug-build `dzn`/`dzf` overrides, the stable mode, VSM, the
//! debug camera's matrix, `FCamera::setCustomProjection`'s own bookkeeping, the renderable culling,
//! the clamp-to-edge scissor and the uniform-buffer writes; every renderable counts as visible to
//! the camera (`updateSceneInfoDirectional` skips receivers the camera culled). Arithmetic is
//! `float` as Filament's (`double` where Filament uses `mat4`: `lookTo`, `highPrecisionMultiply`).

use glam::{DMat4, DVec3, DVec4, Mat3, Mat4, Vec2, Vec3, Vec4};

/// Filament's `Aabb` (an empty box has min = +max float, max = lowest float).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aabb {
    pub min: Vec3,
    pub max: Vec3,
}

impl Default for Aabb {
    fn default() -> Self {
        Aabb {
            min: Vec3::splat(f32::MAX),
            max: Vec3::splat(f32::MIN),
        }
    }
}

impl Aabb {
    /// `Aabb::isEmpty`.
    pub fn is_empty(&self) -> bool {
        self.min.x >= self.max.x || self.min.y >= self.max.y || self.min.z >= self.max.z
    }

    /// `Aabb::getCorners`: corner i has x from bit 0, y from bit 1, z from bit 2 (0: min).
    pub fn corners(&self) -> [Vec3; 8] {
        let (a, b) = (self.min, self.max);
        [
            Vec3::new(a.x, a.y, a.z),
            Vec3::new(b.x, a.y, a.z),
            Vec3::new(a.x, b.y, a.z),
            Vec3::new(b.x, b.y, a.z),
            Vec3::new(a.x, a.y, b.z),
            Vec3::new(b.x, a.y, b.z),
            Vec3::new(a.x, b.y, b.z),
            Vec3::new(b.x, b.y, b.z),
        ]
    }

    /// `Aabb::transform(m, t, box)` (Arvo, Graphics Gems 1990).
    fn transform(m: &Mat3, t: Vec3, b: &Aabb) -> Aabb {
        let mut r = Aabb { min: t, max: t };
        for col in 0..3 {
            for row in 0..3 {
                let a = m.col(col)[row] * b.min[col];
                let bb = m.col(col)[row] * b.max[col];
                r.min[row] += if a < bb { a } else { bb };
                r.max[row] += if a < bb { bb } else { a };
            }
        }
        r
    }
}

/// A renderable's world bounds and shadow flags (Filament's `visitScene` input).
#[derive(Debug, Clone, Copy)]
pub struct Renderable {
    pub aabb: Aabb,
    pub cast_shadows: bool,
    pub receive_shadows: bool,
}

/// `ShadowMap::SceneInfo` (the fields the directional path reads).
#[derive(Debug, Clone, Copy, Default)]
pub struct SceneInfo {
    pub ls_casters_near_far: Vec2,
    pub ls_receivers_near_far: Vec2,
    pub ws_shadow_casters_volume: Aabb,
    pub ws_shadow_receivers_volume: Aabb,
}

impl SceneInfo {
    /// `SceneInfo::SceneInfo(scene, visibleLayers)` (ShadowMap.cpp:1177–1202) then
    /// `updateSceneInfoDirectional(Mv, …)` (1204–1230), every renderable visible to the camera.
    pub fn directional(renderables: &[Renderable], mv: &Mat4) -> SceneInfo {
        let mut s = SceneInfo::default();
        for r in renderables {
            if r.cast_shadows {
                s.ws_shadow_casters_volume.min = s.ws_shadow_casters_volume.min.min(r.aabb.min);
                s.ws_shadow_casters_volume.max = s.ws_shadow_casters_volume.max.max(r.aabb.max);
            }
            if r.receive_shadows {
                s.ws_shadow_receivers_volume.min = s.ws_shadow_receivers_volume.min.min(r.aabb.min);
                s.ws_shadow_receivers_volume.max = s.ws_shadow_receivers_volume.max.max(r.aabb.max);
            }
        }
        s.ls_casters_near_far = Vec2::new(f32::MIN, f32::MAX);
        s.ls_receivers_near_far = Vec2::new(f32::MIN, f32::MAX);
        let ul = Mat3::from_mat4(*mv);
        let t = mv.w_axis.truncate();
        for r in renderables {
            if r.cast_shadows {
                let b = Aabb::transform(&ul, t, &r.aabb);
                s.ls_casters_near_far.x = s.ls_casters_near_far.x.max(b.max.z);
                s.ls_casters_near_far.y = s.ls_casters_near_far.y.min(b.min.z);
            }
            if r.receive_shadows {
                let b = Aabb::transform(&ul, t, &r.aabb);
                s.ls_receivers_near_far.x = s.ls_receivers_near_far.x.max(b.max.z);
                s.ls_receivers_near_far.y = s.ls_receivers_near_far.y.min(b.min.z);
            }
        }
        s
    }
}

/// The fields of Filament's `CameraInfo` the directional path reads.
#[derive(Debug, Clone, Copy)]
pub struct CameraInfo {
    /// `cullingProjection` (OpenGL clip, finite far).
    pub culling_projection: Mat4,
    /// World from camera.
    pub model: Mat4,
    /// Camera from world (`inverse(model)`).
    pub view: Mat4,
    /// `worldTransform[0].xyz` (the world origin's x axis: (1, 0, 0) without a floating origin).
    pub world_x: Vec3,
    /// Near and far distances (positive).
    pub zn: f32,
    pub zf: f32,
}

impl CameraInfo {
    /// A camera `model` (world from camera) with `mat4f::perspective`'s vertical field of view
    /// (`fov_deg` full angle) and aspect, near `zn`, far `zf`.
    pub fn perspective(model: Mat4, fov_deg: f32, aspect: f32, zn: f32, zf: f32) -> CameraInfo {
        let h = (fov_deg * std::f32::consts::PI / 360.0).tan() * zn;
        let w = h * aspect;
        CameraInfo {
            culling_projection: frustum(-w, w, -h, h, zn, zf),
            model,
            view: model.inverse(),
            world_x: Vec3::X,
            zn,
            zf,
        }
    }

    fn position(&self) -> Vec3 {
        self.model.w_axis.truncate()
    }

    fn forward(&self) -> Vec3 {
        (-self.model.z_axis.truncate()).normalize()
    }
}

/// `mat4f::frustum`.
fn frustum(l: f32, r: f32, b: f32, t: f32, n: f32, f: f32) -> Mat4 {
    Mat4::from_cols(
        Vec4::new(2.0 * n / (r - l), 0.0, 0.0, 0.0),
        Vec4::new(0.0, 2.0 * n / (t - b), 0.0, 0.0),
        Vec4::new(
            (r + l) / (r - l),
            (t + b) / (t - b),
            -(f + n) / (f - n),
            -1.0,
        ),
        Vec4::new(0.0, 0.0, -(2.0 * f * n) / (f - n), 0.0),
    )
}

/// `LightManager::ShadowOptions` (the fields read here).
#[derive(Debug, Clone, Copy)]
pub struct ShadowOptions {
    pub shadow_near_hint: f32,
    pub shadow_far_hint: f32,
    pub lispsm: bool,
    /// `constantBias` (world units, applied along the light in the shadow camera's model).
    pub constant_bias: f32,
}

impl Default for ShadowOptions {
    fn default() -> Self {
        ShadowOptions {
            shadow_near_hint: 1.0,
            shadow_far_hint: 100.0,
            lispsm: true,
            constant_bias: 0.001,
        }
    }
}

/// `ShadowMap::ShadowMapInfo` for one map of `map_size` texels alone in its atlas layer, OpenGL
/// texture space (`textureSpaceFlipped` false), no VSM.
#[derive(Debug, Clone, Copy)]
pub struct ShadowMapInfo {
    pub atlas_dimension: u16,
    pub texture_dimension: u16,
    pub shadow_dimension: u16,
}

impl ShadowMapInfo {
    pub fn new(map_size: u16) -> ShadowMapInfo {
        ShadowMapInfo {
            atlas_dimension: map_size,
            texture_dimension: map_size,
            shadow_dimension: map_size - 2,
        }
    }

    /// `ShadowMap::getViewport()` (ShadowMap.cpp:1258–1274): the map inside a 1-texel border
    /// (left, bottom, width, height).
    fn viewport(&self) -> [f32; 4] {
        let dim = f32::from(self.texture_dimension);
        [1.0, 1.0, dim - 2.0, dim - 2.0]
    }
}

/// What `updateDirectional` produces for one map (`ShaderParameters` and the shadow camera).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DirectionalMap {
    /// `lightSpace`: world → shadow texture coordinates (u, v, depth), homogeneous.
    pub light_space: Mat4,
    /// `texelSizeAtOneMeterWs`: `texelSizeWorldSpaceAt(S, {0, 0, 0}, shadowDimension)`, the
    /// world-space lengths of one texel's two edges (along u, along v) at the world origin.
    pub texel_size_at_one_meter_ws: Vec2,
    /// The shadow camera's projection `Mn · F · W · L · Mp` (light view → clip).
    pub projection: Mat4,
    /// The shadow camera's model matrix (world from light view, constant bias applied).
    pub model: DMat4,
    /// `S = F · W · L · Mp · Mv`: world → light clip.
    pub s: Mat4,
    /// LiSPSM's `Wp` (identity when LiSPSM was cancelled); `Wp[0][0]` is n_opt.
    pub wp: Mat4,
    pub znear: f32,
    pub zfar: f32,
}

/// 8 corners, 12 segments with 2 intersections at most, twice (Filament's
/// `FrustumBoxIntersection`).
pub type FrustumBoxIntersection = [Vec3; 64];

/// `mat4f::project`.
#[inline]
fn project(m: &Mat4, v: Vec3) -> Vec3 {
    let r = *m * v.extend(1.0);
    r.truncate() * (1.0 / r.w)
}

/// `FCamera::rigidTransformInverse`.
fn rigid_transform_inverse(v: &Mat4) -> Mat4 {
    let rt = Mat3::from_mat4(*v).transpose();
    let t = rt * v.w_axis.truncate();
    Mat4::from_cols(
        rt.x_axis.extend(0.0),
        rt.y_axis.extend(0.0),
        rt.z_axis.extend(0.0),
        (-t).extend(1.0),
    )
}

/// `FCamera::rigidTransformInverse` in double.
fn rigid_transform_inverse_d(v: &DMat4) -> DMat4 {
    let rt = glam::DMat3::from_mat4(*v).transpose();
    let t = rt * v.w_axis.truncate();
    DMat4::from_cols(
        rt.x_axis.extend(0.0),
        rt.y_axis.extend(0.0),
        rt.z_axis.extend(0.0),
        (-t).extend(1.0),
    )
}

/// `mat4::lookTo(direction, position, up)` in double.
fn look_to(direction: DVec3, position: DVec3, up: DVec3) -> DMat4 {
    let z_axis = direction.normalize();
    let mut norm_up = up.normalize();
    if z_axis.dot(norm_up).abs() > 0.999 {
        norm_up = DVec3::new(norm_up.z, norm_up.x, norm_up.y);
    }
    let x_axis = z_axis.cross(norm_up).normalize();
    let y_axis = x_axis.cross(z_axis);
    DMat4::from_cols(
        x_axis.extend(0.0),
        y_axis.extend(0.0),
        (-z_axis).extend(0.0),
        DVec4::new(position.x, position.y, position.z, 1.0),
    )
}

/// `ShadowMap::getDirectionalLightViewMatrix(direction, up, position)` (ShadowMap.cpp:104–111).
pub fn directional_light_view_matrix(direction: Vec3, up: Vec3, position: Vec3) -> Mat4 {
    let mm = look_to(direction.as_dvec3(), position.as_dvec3(), up.as_dvec3()).as_mat4();
    rigid_transform_inverse(&mm)
}

/// `gaussJordanInverse` (libs/math TMatHelpers.h), column-major as Filament's.
fn inverse(src: &Mat4) -> Mat4 {
    let mut tmp = src.to_cols_array_2d();
    let mut inv = Mat4::IDENTITY.to_cols_array_2d();
    for i in 0..4 {
        let mut swap = i;
        let mut t = tmp[i][i].abs();
        for (j, c) in tmp.iter().enumerate().skip(i + 1) {
            let t2 = c[i].abs();
            if t2 > t {
                swap = j;
                t = t2;
            }
        }
        if swap != i {
            tmp.swap(i, swap);
            inv.swap(i, swap);
        }
        let denom = tmp[i][i];
        for k in 0..4 {
            tmp[i][k] /= denom;
            inv[i][k] /= denom;
        }
        for j in 0..4 {
            if j != i {
                let t = tmp[j][i];
                for k in 0..4 {
                    tmp[j][k] -= tmp[i][k] * t;
                    inv[j][k] -= inv[i][k] * t;
                }
            }
        }
    }
    Mat4::from_cols_array_2d(&inv)
}

/// `Frustum::setProjection`: normalised planes l, r, b, t, f, n (inside: negative distance).
fn frustum_planes(pv: &Mat4) -> [Vec4; 6] {
    let m = pv.transpose();
    let (m0, m1, m2, m3) = (m.x_axis, m.y_axis, m.z_axis, m.w_axis);
    let norm = |p: Vec4| p * (1.0 / p.truncate().length());
    [
        norm(-m3 - m0),
        norm(-m3 + m0),
        norm(-m3 - m1),
        norm(-m3 + m1),
        norm(-m3 + m2),
        norm(-m3 - m2),
    ]
}

/// `computeFrustumCorners(projectionInverse)` (ShadowMap.cpp:795–823): NDC corners, far (z = 1)
/// first.
fn compute_frustum_corners(projection_inverse: &Mat4) -> [Vec3; 8] {
    let c = [
        Vec3::new(-1.0, -1.0, 1.0),
        Vec3::new(1.0, -1.0, 1.0),
        Vec3::new(-1.0, 1.0, 1.0),
        Vec3::new(1.0, 1.0, 1.0),
        Vec3::new(-1.0, -1.0, -1.0),
        Vec3::new(1.0, -1.0, -1.0),
        Vec3::new(-1.0, 1.0, -1.0),
        Vec3::new(1.0, 1.0, -1.0),
    ];
    c.map(|p| project(projection_inverse, p))
}

/// `sBoxSegments` (filament/src/ShadowMap.h).
const BOX_SEGMENTS: [(usize, usize); 12] = [
    (0, 1),
    (1, 3),
    (3, 2),
    (2, 0),
    (4, 5),
    (5, 7),
    (7, 6),
    (6, 4),
    (0, 4),
    (1, 5),
    (3, 7),
    (2, 6),
];

/// `sBoxQuads` (filament/src/ShadowMap.h): far, near, left, right, bottom, top.
const BOX_QUADS: [[usize; 4]; 6] = [
    [2, 0, 1, 3],
    [6, 4, 5, 7],
    [2, 0, 4, 6],
    [3, 1, 5, 7],
    [0, 4, 5, 1],
    [2, 6, 7, 3],
];

/// `intersectSegmentWithTriangle` (ShadowMap.cpp:1050–1086; Real-Time Rendering's
/// segment/triangle test), with `intersectSegmentWithPlanarQuad` (1088–1093) at its call.
#[inline(always)]
fn intersect_segment_with_triangle(
    s0: Vec3,
    s1: Vec3,
    t0: Vec3,
    t1: Vec3,
    t2: Vec3,
) -> Option<Vec3> {
    const EPSILON: f32 = 1.0 / 65536.0;
    let e1 = t1 - t0;
    let e2 = t2 - t0;
    let d = s1 - s0;
    let q = d.cross(e2);
    let a = e1.dot(q);
    if a.abs() < EPSILON {
        return None;
    }
    let sign_a = if a < 0.0 { -1.0 } else { 1.0 };
    let s = s0 - t0;
    let u = s.dot(q) * sign_a;
    let r = s.cross(e1);
    let v = d.dot(r) * sign_a;
    if u < 0.0 || v < 0.0 || u + v > a.abs() {
        return None;
    }
    let t = e2.dot(r) * sign_a;
    if t < 0.0 || t > a.abs() {
        return None;
    }
    Some(s0 + d * (t / a.abs()))
}

/// `intersectFrustum` (ShadowMap.cpp:1023–1048): each segment of `segments` against the quads
/// of `quads`, at most two hits per segment, appended at `out[count..]`.
#[inline(never)]
fn intersect_frustum(
    out: &mut FrustumBoxIntersection,
    mut count: usize,
    segments: &[Vec3; 8],
    quads: &[Vec3; 8],
) -> usize {
    for &(v0, v1) in &BOX_SEGMENTS {
        let (s0, s1) = (segments[v0], segments[v1]);
        let max_count = count + 2;
        let mut j = 0;
        while j < 6 && count < max_count {
            let q = BOX_QUADS[j];
            let (t0, t1, t2, t3) = (quads[q[0]], quads[q[1]], quads[q[2]], quads[q[3]]);
            if let Some(p) = intersect_segment_with_triangle(s0, s1, t0, t1, t2)
                .or_else(|| intersect_segment_with_triangle(s0, s1, t0, t2, t3))
            {
                out[count] = p;
                count += 1;
            }
            j += 1;
        }
    }
    count
}

/// `ShadowMap::intersectFrustumWithBox(out, projection, box)` (ShadowMap.cpp:894–1021): points
/// on the hull of the frustum of `projection` (OpenGL clip) ∩ `bx`, in the space `projection`
/// maps from.
pub fn intersect_frustum_with_box(
    out: &mut FrustumBoxIntersection,
    projection: &Mat4,
    bx: &Aabb,
) -> usize {
    let planes = frustum_planes(projection);
    let frustum_vertices = compute_frustum_corners(&inverse(projection));
    const EPSILON: f32 = 1.0 / 8192.0;
    let mut count = 0;
    let box_corners = bx.corners();
    // a) the frustum's vertices inside the box (920–930)
    for p in frustum_vertices {
        out[count] = p;
        if p.x >= bx.min.x
            && p.x <= bx.max.x
            && p.y >= bx.min.y
            && p.y <= bx.max.y
            && p.z >= bx.min.z
            && p.z <= bx.max.z
        {
            count += 1;
        }
    }
    if count < 8 {
        let frustum_inside_box = count;
        // b) the box's vertices inside the frustum, with a small tolerance (933–956)
        for p in box_corners {
            out[count] = p;
            if planes
                .iter()
                .all(|pl| pl.truncate().dot(p) + pl.w <= EPSILON)
            {
                count += 1;
            }
        }
        if count - frustum_inside_box < 8 {
            // c) the box's edges against the frustum's faces (998–1003)
            count = intersect_frustum(out, count, &box_corners, &frustum_vertices);
            // d) the frustum's edges against the box's faces (1005–1007)
            count = intersect_frustum(out, count, &frustum_vertices, &box_corners);
        }
    }
    count
}

/// `compute2DBounds(lightView, vertices)` (ShadowMap.cpp:771–781).
fn compute_2d_bounds(light_view: &Mat4, vertices: &[Vec3]) -> Aabb {
    let mut b = Aabb::default();
    for &v in vertices {
        let p = project(light_view, v);
        b.min = Vec3::new(b.min.x.min(p.x), b.min.y.min(p.y), b.min.z);
        b.max = Vec3::new(b.max.x.max(p.x), b.max.y.max(p.y), b.max.z);
    }
    b
}

/// `compute2DBounds(lightView, volume)` (ShadowMap.cpp:783–793; all three axes).
fn compute_2d_bounds_box(light_view: &Mat4, volume: &Aabb) -> Aabb {
    let mut b = Aabb::default();
    for c in volume.corners() {
        let p = project(light_view, c);
        b.min = b.min.min(p);
        b.max = b.max.max(p);
    }
    b
}

/// `computeLightFrustumBounds` (ShadowMap.cpp:825–856; not stable, focus on casters, far from
/// casters).
fn compute_light_frustum_bounds(light_view: &Mat4, scene: &SceneInfo) -> Aabb {
    let receivers_far = scene.ls_receivers_near_far.y;
    let casters_near = scene.ls_casters_near_far.x;
    let casters_far = scene.ls_casters_near_far.y;
    let r = compute_2d_bounds_box(light_view, &scene.ws_shadow_receivers_volume);
    let mut b = Aabb {
        min: Vec3::new(r.min.x, r.min.y, receivers_far),
        max: Vec3::new(r.max.x, r.max.y, casters_near),
    };
    let c = compute_2d_bounds_box(light_view, &scene.ws_shadow_casters_volume);
    b.min.x = b.min.x.max(c.min.x);
    b.min.y = b.min.y.max(c.min.y);
    b.max.x = b.max.x.min(c.max.x);
    b.max.y = b.max.y.min(c.max.y);
    b.min.z = b.min.z.max(casters_far);
    b
}

/// `computeNearFar(view, vertices)` (ShadowMap.cpp:733–743): (max z, min z).
fn compute_near_far(view: &Mat4, vertices: &[Vec3]) -> Vec2 {
    let mut nf = Vec2::new(f32::MIN, f32::MAX);
    for &v in vertices {
        let c = project(view, v).z;
        nf.x = nf.x.max(c);
        nf.y = nf.y.min(c);
    }
    nf
}

/// `computeNearFarOfWarpSpace(lightView, vertices)` (ShadowMap.cpp:745–756): (min y, max y).
fn compute_near_far_of_warp_space(light_view: &Mat4, vertices: &[Vec3]) -> Vec2 {
    let mut nf = Vec2::new(f32::MAX, f32::MIN);
    for &v in vertices {
        let c = project(light_view, v).y;
        nf.x = nf.x.min(c);
        nf.y = nf.y.max(c);
    }
    nf
}

/// `warpFrustum(n, f)` (ShadowMap.cpp:709–723): a frustum looking down +y.
fn warp_frustum(n: f32, f: f32) -> Mat4 {
    let d = 1.0 / (f - n);
    let a = (f + n) * d;
    let b = -2.0 * n * f * d;
    // row major: (n 0 0 0), (0 A 0 B), (0 0 n 0), (0 1 0 0)
    Mat4::from_cols(
        Vec4::new(n, 0.0, 0.0, 0.0),
        Vec4::new(0.0, a, 0.0, 1.0),
        Vec4::new(0.0, 0.0, n, 0.0),
        Vec4::new(0.0, b, 0.0, 0.0),
    )
}

/// `directionalLightFrustum(near, far)` (ShadowMap.cpp:725–731).
fn directional_light_frustum(near: f32, far: f32) -> Mat4 {
    let d = far - near;
    let mut m = Mat4::IDENTITY;
    m.z_axis.z = -2.0 / d;
    m.w_axis.z = -(far + near) / d;
    m
}

/// `computeLightRotation(lsDirection)` (ShadowMap.cpp:591–607).
fn compute_light_rotation(ls_direction: Vec3) -> Mat4 {
    if ls_direction.z.abs() < 0.9997 {
        let vp = ls_direction.truncate().normalize().extend(0.0);
        let l = Mat4::from_cols(
            vp.cross(Vec3::Z).extend(0.0),
            vp.extend(0.0),
            Vec3::Z.extend(0.0),
            Vec4::W,
        );
        l.transpose()
    } else {
        Mat4::IDENTITY
    }
}

/// `computeDirectionalShadowBounds`' result.
struct DirectionalShadowBounds {
    mv: Mat4,
    znear: f32,
    zfar: f32,
    ls_clipped_shadow_volume: FrustumBoxIntersection,
    vertex_count: usize,
}

/// `ShadowMap::computeDirectionalShadowBounds` (ShadowMap.cpp:387–506; not stable, debug flags
/// at their defaults).
// `!(znear < zfar)` is Filament's NaN-safe test, kept as written.
#[allow(clippy::neg_cmp_op_on_partial_ord)]
fn compute_directional_shadow_bounds(
    direction: Vec3,
    camera: &CameraInfo,
    scene: &SceneInfo,
    use_depth_clamp: bool,
) -> Option<DirectionalShadowBounds> {
    // 399–414: no receivers, no casters, or an empty volume: no shadows.
    if scene.ls_receivers_near_far.x <= scene.ls_receivers_near_far.y {
        return None;
    }
    if scene.ls_casters_near_far.x <= scene.ls_casters_near_far.y {
        return None;
    }
    if scene.ws_shadow_casters_volume.is_empty() || scene.ws_shadow_receivers_volume.is_empty() {
        return None;
    }
    // 431–445: the light's view at the origin, the light-frustum bounds, NaN-safe emptiness.
    let up = camera.world_x.normalize();
    let mv_at_origin = directional_light_view_matrix(direction, up, Vec3::ZERO);
    let mut b = compute_light_frustum_bounds(&mv_at_origin, scene);
    if !(b.min.x < b.max.x && b.min.y < b.max.y) {
        return None;
    }
    // 447–453: the view volume ∩ that box, in the light's space at the origin.
    let projection =
        camera.culling_projection * (camera.view * rigid_transform_inverse(&mv_at_origin));
    let mut v = [Vec3::ZERO; 64];
    let n = intersect_frustum_with_box(&mut v, &projection, &b);
    if n < 4 {
        return None;
    }
    // 473–489: far to the farthest clipped vertex (and, with depth clamp, near to the nearest);
    // far_uses_shadowcasters.
    let mut farthest = f32::MAX;
    let mut nearest = f32::MIN;
    for p in &v[..n] {
        farthest = farthest.min(p.z);
        nearest = nearest.max(p.z);
    }
    b.min.z = b.min.z.max(farthest);
    if use_depth_clamp {
        b.max.z = b.max.z.min(nearest);
    }
    b.min.z = b.min.z.max(scene.ls_casters_near_far.y);
    // 491–498: near and far along the light's −z; none when znear ≥ zfar (or NaN).
    let znear = -b.max.z;
    let zfar = -b.min.z;
    if !(znear < zfar) {
        // handles NaNs
        return None;
    }
    // 500–505: Mv is the light's view at the origin again (`position` defaults to {}); the 64
    // vertices stay as `intersectFrustumWithBox` wrote them.
    let mv = directional_light_view_matrix(direction, up, Vec3::ZERO);
    Some(DirectionalShadowBounds {
        mv,
        znear,
        zfar,
        ls_clipped_shadow_volume: v,
        vertex_count: n,
    })
}

/// `ShadowMap::applyLISPSM` (ShadowMap.cpp:508–589): W, and `Wp` (identity when LiSPSM is
/// cancelled).
#[allow(clippy::too_many_arguments)]
fn apply_lispsm(
    camera: &CameraInfo,
    options: &ShadowOptions,
    lmp: &Mat4,
    mv: &Mat4,
    lmpmv: &Mat4,
    ls_shadow_volume: &[Vec3],
    dir: Vec3,
) -> (Mat4, Mat4) {
    // 516–523: sin γ and the hints' dzn, dzf.
    let lov = camera.forward().dot(dir);
    let sin_lv = (1.0 - lov * lov).max(0.0).sqrt();
    let dzn = (options.shadow_near_hint - camera.zn).max(0.0);
    let dzf = (camera.zf - options.shadow_far_hint).max(0.0);
    // 527–533: the shadow volume's view-depth range, clamped to the camera's.
    let znf = -compute_near_far(
        &(camera.view * rigid_transform_inverse(mv)),
        ls_shadow_volume,
    );
    let zn = camera.zn.max(znf.x);
    let zf = camera.zf.min(znf.y);
    // 539–546: the warp axis's extent n, f, d; z₀, z₁.
    let nf = compute_near_far_of_warp_space(lmp, ls_shadow_volume);
    let (n, f) = (nf.x, nf.y);
    let d = (f - n).abs();
    let z0 = zn;
    let z1 = z0 + d * sin_lv;
    // 548–552: LiSPSM only where it helps (else W and Wp stay the identity).
    const EPSILON: f32 = 0.02;
    if f > n && sin_lv > EPSILON && 3.0 * (dzn / (zf - zn)) < 2.0 {
        // 556–568: the virtual planes and n_opt = max(nopt0, nopt1).
        let vz0 = zn.max(camera.zn + dzn).max(z0).max(0.0);
        let vz1 = zf.min(camera.zf - dzf).min(z1).max(0.0);
        let nopt0 = (1.0 / sin_lv) * (z0 + (vz0 * vz1).sqrt());
        let nopt1 = dzn / (2.0 - 3.0 * (dzn / (zf - zn)));
        let nopt = nopt0.max(nopt1);
        // 570–586: the centre of projection and W = Wp · Wv.
        let ls_camera_position = project(lmpmv, camera.position());
        let p = Vec3::new(ls_camera_position.x, n - nopt, 0.0);
        let wv = Mat4::from_translation(-p);
        let wp = warp_frustum(nopt, nopt + d);
        (wp * wv, wp)
    } else {
        (Mat4::IDENTITY, Mat4::IDENTITY)
    }
}

/// `getTextureCoordsMapping(info, viewport)` (ShadowMap.cpp:651–688): (clip → texture, clip →
/// the viewport's NDC).
fn texture_coords_mapping(info: &ShadowMapInfo) -> (Mat4, Mat4) {
    // Mt: x, y from [−1, 1] to [0, 1], depth to [1, 0]; its inverse is a `constexpr` in Filament.
    let mt = Mat4::from_cols(
        Vec4::new(0.5, 0.0, 0.0, 0.0),
        Vec4::new(0.0, 0.5, 0.0, 0.0),
        Vec4::new(0.0, 0.0, -0.5, 0.0),
        Vec4::new(0.5, 0.5, 0.5, 1.0),
    );
    let mt_inverse = Mat4::from_cols(
        Vec4::new(2.0, 0.0, 0.0, 0.0),
        Vec4::new(0.0, 2.0, 0.0, 0.0),
        Vec4::new(0.0, 0.0, -2.0, 0.0),
        Vec4::new(-1.0, -1.0, 1.0, 1.0),
    );
    let vp = info.viewport();
    let atlas = f32::from(info.atlas_dimension);
    let o = Vec2::new(vp[0], vp[1]) / atlas;
    let s = Vec2::new(vp[2], vp[3]) / atlas;
    let mvp = Mat4::from_cols(
        Vec4::new(s.x, 0.0, 0.0, 0.0),
        Vec4::new(0.0, s.y, 0.0, 0.0),
        Vec4::Z,
        Vec4::new(o.x, o.y, 0.0, 1.0),
    );
    // Mf is the identity (OpenGL texture space)
    let vmt = mvp * mt;
    (vmt, mt_inverse * vmt)
}

/// The static `jacobian(M, p)` of ShadowMap.cpp (1124–1134): J = ∂(X/W, Y/W, Z/W)/∂(x, y, z) of
/// `M · (p, 1)`, `(M_sub − (T ⊗ w_grad)/T.w)/T.w` with `T = M · (p, 1)`, `M_sub` M's upper-left
/// 3×3 and `w_grad` the first three entries of M's last row; column j is ∂/∂(x, y, z)ⱼ.
fn jacobian(m: &Mat4, p: Vec3) -> Mat3 {
    let t = *m * p.extend(1.0);
    let m_sub = Mat3::from_mat4(*m);
    let w_grad = Vec3::new(m.x_axis.w, m.y_axis.w, m.z_axis.w);
    let t3 = t.truncate();
    let t_cross_w = Mat3::from_cols(w_grad.x * t3, w_grad.y * t3, w_grad.z * t3);
    (m_sub - t_cross_w / t.w) / t.w
}

/// `ShadowMap::texelSizeWorldSpaceAt(S, p, shadowDimension)` (ShadowMap.cpp:1143–1153): the
/// world-space lengths of one texel's edges along u and v at the world point `p`, from the
/// Jacobian of `inverse(S)` (clip → world) at `p`'s NDC, times one texel, 2/shadowDimension.
fn texel_size_world_space_at(s: &Mat4, p: Vec3, shadow_dimension: u16) -> Vec2 {
    let p_ndc = project(s, p);
    let one_texel = 2.0 / f32::from(shadow_dimension);
    let j = jacobian(&inverse(s), p_ndc);
    Vec2::new(j.x_axis.length(), j.y_axis.length()) * one_texel
}

/// `ShadowMap::updateDirectional` (ShadowMap.cpp:128–266) with `camera` the cascade's (its `zn`,
/// `zf` and culling projection), `None` when the map has no visible shadows.
pub fn update_directional(
    direction: Vec3,
    camera: &CameraInfo,
    options: &ShadowOptions,
    info: &ShadowMapInfo,
    scene: &SceneInfo,
    use_depth_clamp: bool,
) -> Option<DirectionalMap> {
    // 145–150
    let bounds = compute_directional_shadow_bounds(direction, camera, scene, use_depth_clamp)?;
    let mv = bounds.mv;
    let verts = &bounds.ls_clipped_shadow_volume[..bounds.vertex_count];
    // 152–156: Filament applies Mv to the (already light-space) vertices for this emptiness test.
    let b = compute_2d_bounds(&mv, verts);
    if !(b.min.x < b.max.x && b.min.y < b.max.y) {
        return None;
    }
    // 164–166
    let mp = directional_light_frustum(bounds.znear, bounds.zfar);
    // 172–182: useLispsm || !disable_light_frustum_align: align the map with the view.
    let ls_camera_fwd = Mat3::from_mat4(mv) * camera.forward();
    let l = compute_light_rotation(ls_camera_fwd);
    let lmp = l * mp;
    let lmpmv = lmp * mv;
    // 184–186
    let (w, wp) = if options.lispsm {
        apply_lispsm(camera, options, &lmp, &mv, &lmpmv, verts, direction)
    } else {
        (Mat4::IDENTITY, Mat4::IDENTITY)
    };
    // 192: WLMp; 199–200 and 609–649: computeFocusParams (not stable).
    let wlmp = w * lmp;
    let fb = compute_2d_bounds(&wlmp, verts);
    let s = Vec2::new(2.0 / (fb.max.x - fb.min.x), 2.0 / (fb.max.y - fb.min.y));
    let o = -s * (Vec2::new(fb.max.x + fb.min.x, fb.max.y + fb.min.y) * 0.5);
    // 207–212
    let f = Mat4::from_cols(
        Vec4::new(s.x, 0.0, 0.0, 0.0),
        Vec4::new(0.0, s.y, 0.0, 0.0),
        Vec4::Z,
        Vec4::new(o.x, o.y, 0.0, 1.0),
    );
    // 219: S = F · (W · LMpMv)
    let s_mat = f * (w * lmpmv);
    // 223–226: St = highPrecisionMultiply(Mt, S)
    let (mt, mn) = texture_coords_mapping(info);
    let st = (mt.as_dmat4() * s_mat.as_dmat4()).as_mat4();
    // 234: the texel size at the world origin, both edges.
    let texel = texel_size_world_space_at(&s_mat, Vec3::ZERO, info.shadow_dimension);
    // 246–247, 257–258: the constant bias in the shadow camera's model; its projection.
    let bias = DMat4::from_translation((direction * options.constant_bias).as_dvec3());
    let model = rigid_transform_inverse_d(&(mv.as_dmat4() * bias));
    Some(DirectionalMap {
        light_space: st,
        texel_size_at_one_meter_ws: texel,
        projection: mn * f * wlmp,
        model,
        s: s_mat,
        wp,
        znear: bounds.znear,
        zfar: bounds.zfar,
    })
}

/// `ShadowMapManager::updateNearFarPlanes`: new near/far planes of a projection.
fn update_near_far_planes(p: &mut Mat4, near: f32, far: f32) {
    let (nz, nw) = (1.0f32, near);
    let (fz, fw) = (-1.0f32, -far);
    let sn = -2.0 * (p.z_axis.w * fw - p.w_axis.w * fz) / (nz * fw - nw * fz);
    let sf = -2.0 * (p.z_axis.w * nw - p.w_axis.w * nz) / (fz * nw - fw * nz);
    p.z_axis.z = (sf * fz - sn * nz) * 0.5;
    p.w_axis.z = (sf * fw - sn * nw) * 0.5;
}

/// The geometry of `ShadowMapManager::updateCascadeShadowMaps` for the directional light:
/// scene info, the culling pass over the whole frustum (`culling_pass`; Filament always runs it,
/// it decides whether any cascade is built), then one [`update_directional`] per cascade over
/// `near + (far − near) · split_positions`. Fills `out[..count]`; returns how many maps have
/// visible shadows.
#[allow(clippy::too_many_arguments)]
pub fn update_cascade_shadow_maps(
    direction: Vec3,
    camera: &CameraInfo,
    options: &ShadowOptions,
    info: &ShadowMapInfo,
    renderables: &[Renderable],
    split_positions: &[f32],
    culling_pass: bool,
    use_depth_clamp: bool,
    out: &mut [Option<DirectionalMap>; 4],
) -> usize {
    let count = split_positions.len() + 1;
    let mv_at_origin =
        directional_light_view_matrix(direction, camera.world_x.normalize(), Vec3::ZERO);
    let scene = SceneInfo::directional(renderables, &mv_at_origin);
    if culling_pass && update_directional(direction, camera, options, info, &scene, false).is_none()
    {
        for slot in out.iter_mut() {
            *slot = None;
        }
        return 0;
    }
    let mut pct = [0.0f32; 5];
    pct[count] = 1.0;
    pct[1..count].copy_from_slice(split_positions);
    let (near, far) = (-camera.zn, -camera.zf);
    let mut splits = [0.0f32; 5];
    for (s, p) in splits.iter_mut().zip(pct).take(count + 1) {
        *s = near + (far - near) * p;
    }
    let mut cam = *camera;
    let mut visible = 0;
    for (i, slot) in out.iter_mut().enumerate().take(count) {
        cam.zn = -splits[i];
        cam.zf = -splits[i + 1];
        update_near_far_planes(&mut cam.culling_projection, cam.zn, cam.zf);
        *slot = update_directional(direction, &cam, options, info, &scene, use_depth_clamp);
        visible += usize::from(slot.is_some());
    }
    visible
}
