// shadow-aliasing's shadow lookup for the frame's maps. The Rust constant
// shadow_aliasing::frame::SHADOW_WGSL is GPU_SHADOW_MAP_WGSL (the GpuShadowMap record and its
// clip_depth codes) followed by this text; concatenate it before your own shader.
//
// The including shader declares these three functions, over whatever bindings it has:
//
//   fn sa_map(i: u32) -> GpuShadowMap          // map i's record (FrameMap::gpu or gpu_relative)
//   fn sa_map_count() -> u32                   // how many maps (at least 1)
//   fn sa_stored_depth(i: u32, texel: vec2<i32>) -> f32
//       // the depth map i stores at a texel (x from s = 0, y down from t = 1: texture rows),
//       // as its depth attachment holds it (textureLoad of a texture_depth_2d_array); texel
//       // runs over map i's own m.resolution texels a side (a map smaller than its texture
//       // layer, drawn with a viewport at the layer's origin, reads the layer's texel as it is)
//
// Points p are in the space the records' world_to_clip takes (world space, or relative to the
// upload origin with gpu_relative); n is the surface's unit normal and l the direction the light
// travels, both in that space's axes.

// Bias flags of sa_visibility: SA_NORMAL_OFFSET moves the lookup point by the record's normal
// offset (the maximum over the map's focus body, set by its coarsest texels),
// SA_LOCAL_NORMAL_OFFSET by what the point itself needs (sa_local_normal_offset; it takes
// precedence over SA_NORMAL_OFFSET), SA_DEPTH_BIAS adds the record's depth bias.
const SA_NORMAL_OFFSET: u32 = 1u;
const SA_DEPTH_BIAS: u32 = 2u;
const SA_LOCAL_NORMAL_OFFSET: u32 = 4u;

// Texels added to a kernel's reach r + 1/2 by sa_local_normal_offset: the f32 lookup may take the
// neighbouring texel near a texel's edge (shadow_aliasing::frame::bias::TEXEL_SLACK).
const SA_TEXEL_SLACK: f32 = 0.015625;

// Where p falls in map m: xy = (s, t) in [0, 1] across the map (t up), z = the depth the depth
// attachment stores for it (OpenGL's [-1, 1] mapped to [0, 1], as glDepthRange(0, 1) does; the
// other conventions as they are), w = clip w (> 0 in front of the map's centre of projection; a
// warped map's lookup divides by it).
fn sa_project(m: GpuShadowMap, p: vec3<f32>) -> vec4<f32> {
    let h = m.world_to_clip * vec4<f32>(p, 1.0);
    let ndc = h.xyz / h.w;
    var depth = ndc.z;
    if (m.clip_depth == CLIP_DEPTH_NEG_ONE_TO_ONE) {
        depth = 0.5 * depth + 0.5;
    }
    return vec4<f32>(0.5 * ndc.xy + vec2<f32>(0.5), depth, h.w);
}

// Whether a projected point (sa_project) lies on its map: in front of the centre of projection,
// s and t in [0, 1).
fn sa_on_map(q: vec4<f32>) -> bool {
    return q.w > 0.0 && all(q.xy >= vec2<f32>(0.0)) && all(q.xy < vec2<f32>(1.0));
}

// The texel of map m holding map position st (texture rows run down from t = 1; m.resolution
// texels a side).
fn sa_texel(m: GpuShadowMap, st: vec2<f32>) -> vec2<i32> {
    let res = f32(m.resolution);
    return vec2<i32>(i32(floor(st.x * res)), i32(floor((1.0 - st.y) * res)));
}

// Whether a receiver at `depth` (depth-attachment units) is lit against the stored depth:
// less-equal, greater-equal for reversed depth. The receiver's depth is clamped to [0, 1] first:
// a receiver beyond the map's far depth counts as at it (lit where nothing was drawn).
fn sa_depth_lit(m: GpuShadowMap, depth: f32, stored: f32) -> bool {
    let d = clamp(depth, 0.0, 1.0);
    if (m.clip_depth == CLIP_DEPTH_REVERSED) {
        return d >= stored;
    }
    return d <= stored;
}

// The factor of a record's depth bias for a PCF kernel of radius r texels: the record holds it
// for a kernel of radius m.bias_radius (0: FrameMap::gpu, gpu_relative; r: gpu_with_pcf), and it
// is proportional to r + 1/2, so a kernel of radius r needs s = (2r + 1)/(2 bias_radius + 1)
// times it; never less than the record's own (GpuShadowMap's docs). A record from
// gpu_with_pcf(r) filtered with the same r is used as it is: the kernel is counted once.
fn sa_kernel_scale(m: GpuShadowMap, r: i32) -> f32 {
    return max(f32(2 * max(r, 0) + 1) / (2.0 * max(m.bias_radius, 0.0) + 1.0), 1.0);
}

// The factor of a record's normal offset for a PCF kernel of radius r texels: s (1 - t)/(1 - s t),
// s = sa_kernel_scale(m, r), t = m.normal_offset_growth (shadow_aliasing::frame::bias, "Normal
// offset": the offset point's own footprint makes a perspective map's offset grow faster than the
// kernel's reach; t = 0, the factor s, for an orthographic map). Where s t >= 1 no offset is
// certified: the factor is 1e30, the offset as the record's own +inf.
fn sa_offset_scale(m: GpuShadowMap, r: i32) -> f32 {
    let s = sa_kernel_scale(m, r);
    let t = max(m.normal_offset_growth, 0.0);
    let d = 1.0 - s * t;
    if (!(d > 0.0)) {
        return 1e30;
    }
    return s * (1.0 - t) / d;
}

// The lookup point: p moved along its unit normal n by the record's normal offset (world units)
// for a kernel of radius r.
fn sa_offset_point(m: GpuShadowMap, p: vec3<f32>, n: vec3<f32>, r: i32) -> vec3<f32> {
    return p + n * (m.normal_offset * sa_offset_scale(m, r));
}

// The normal offset (world units) the point p with unit normal n needs in map m for a kernel of
// radius r, from the map matrix's local Jacobian at p (shadow_aliasing::frame::bias, "Per point";
// FrameMap::normal_offset_at in f64): on the lit plane through p the stored depth is affine in
// the map position, and the lookup point p + o n must lie above the plane by the depth step
// across the kernel's reach plus the f32 rounding of the two depths. 0 for a surface turned away
// from the light; the record's normal offset for the kernel where no offset suffices.
fn sa_local_normal_offset(m: GpuShadowMap, p: vec3<f32>, n: vec3<f32>, l: vec3<f32>, r: i32) -> f32 {
    let cos_a = -dot(n, l);
    if (cos_a <= 0.0) {
        return 0.0;
    }
    let fallback = m.normal_offset * sa_offset_scale(m, r);
    let h = m.world_to_clip * vec4<f32>(p, 1.0);
    if (!(h.w > 0.0)) {
        return fallback;
    }
    let rows = transpose(m.world_to_clip);
    let r3 = rows[3].xyz;
    let iw2 = 1.0 / (h.w * h.w);
    // The gradients of s and t across the light, and the texel's edge vectors E_s, E_t (per unit
    // of clip s, t) in the plane perpendicular to it.
    var gs = (rows[0].xyz * h.w - r3 * h.x) * iw2;
    var gt = (rows[1].xyz * h.w - r3 * h.y) * iw2;
    gs = gs - dot(gs, l) * l;
    gt = gt - dot(gt, l) * l;
    let det = dot(cross(gs, gt), l);
    let es = cross(gt, l) / det;
    let et = cross(l, gs) / det;
    // The stored depth's gradient (OpenGL's [-1, 1] is stored halved) and its rate along the light.
    var scale = 1.0;
    if (m.clip_depth == CLIP_DEPTH_NEG_ONE_TO_ONE) {
        scale = 0.5;
    }
    let grad = (rows[2].xyz * h.w - r3 * h.z) * (scale * iw2);
    let k = dot(grad, l);
    let reach = (f32(max(r, 0)) + 0.5 + SA_TEXEL_SLACK) * 2.0 / f32(m.resolution);
    let y = reach * (abs(dot(grad, es) * cos_a + k * dot(n, es))
        + abs(dot(grad, et) * cos_a + k * dot(n, et))) + 9.536743e-7 * cos_a;
    let den = abs(k) - y * dot(r3, n) / h.w;
    let o = y / den;
    if (!(den > 0.0) || !(o >= 0.0) || !(o < 3.4e38)) {
        return fallback;
    }
    return o;
}

// The error lens (shadow_aliasing::frame::lens; FrameMap::error_lens_at in f64): the size in
// screen pixels of map m's texel on the surface through p with unit normal n, the light
// travelling along l: the texel's edges (per texel, in the plane perpendicular to l, from the map
// matrix's local Jacobian at p) projected along the light onto the surface (the projection
// factor), then seen by the camera at `eye` looking along the unit `forward`, with
// focal_pixels = image height / (2 tan(half vertical field of view)) (pixels per unit across the
// view at unit view depth); the larger singular value of the two pixel vectors. 3.4e38 where the
// surface is edge-on to the light, -1 where p is not in front of the camera or of the map's
// centre of projection. eye is in the records' space (the upload origin's offset, 0 for
// gpu_relative(camera position)).
fn sa_error_lens(
    m: GpuShadowMap,
    p: vec3<f32>,
    n: vec3<f32>,
    l: vec3<f32>,
    eye: vec3<f32>,
    forward: vec3<f32>,
    focal_pixels: f32,
) -> f32 {
    let d = p - eye;
    let z = dot(d, forward);
    let h = m.world_to_clip * vec4<f32>(p, 1.0);
    if (!(z > 0.0) || !(h.w > 0.0)) {
        return -1.0;
    }
    let nl = dot(n, l);
    if (nl == 0.0) {
        return 3.4e38;
    }
    let rows = transpose(m.world_to_clip);
    let r3 = rows[3].xyz;
    let iw2 = 1.0 / (h.w * h.w);
    var gs = (rows[0].xyz * h.w - r3 * h.x) * iw2;
    var gt = (rows[1].xyz * h.w - r3 * h.y) * iw2;
    gs = gs - dot(gs, l) * l;
    gt = gt - dot(gt, l) * l;
    // One texel's edges (2/res of clip s, t) on the plane perpendicular to the light.
    let texel = 2.0 / (f32(m.resolution) * dot(cross(gs, gt), l));
    let es = cross(gt, l) * texel;
    let et = cross(l, gs) * texel;
    // Along the light onto the surface, then along the view ray onto the plane of constant view
    // depth, in pixels.
    let k = focal_pixels / z;
    let ps = es - (dot(n, es) / nl) * l;
    let pt = et - (dot(n, et) / nl) * l;
    let a = k * (ps - (dot(ps, forward) / z) * d);
    let b = k * (pt - (dot(pt, forward) / z) * d);
    let aa = dot(a, a);
    let bb = dot(b, b);
    let ab = dot(a, b);
    return sqrt(0.5 * (aa + bb + sqrt((aa - bb) * (aa - bb) + 4.0 * ab * ab)));
}

// The error lens's colour (shadow_aliasing::frame::lens::lens_colour): viridis's ten colours at
// 1/16, 1/8, ..., 32 pixels, linear in log2 between them, clamped at both ends; 1 pixel is
// #26828e; not finite (or 3.4e38 and above) the last colour. sRGB components in [0, 1].
fn sa_lens_colour(value: f32) -> vec3<f32> {
    var ramp = array<vec3<f32>, 10>(
        vec3<f32>(68.0, 1.0, 84.0), vec3<f32>(72.0, 40.0, 120.0), vec3<f32>(62.0, 73.0, 137.0),
        vec3<f32>(49.0, 104.0, 142.0), vec3<f32>(38.0, 130.0, 142.0), vec3<f32>(31.0, 158.0, 137.0),
        vec3<f32>(53.0, 183.0, 121.0), vec3<f32>(110.0, 206.0, 88.0), vec3<f32>(181.0, 222.0, 43.0),
        vec3<f32>(253.0, 231.0, 37.0));
    var x = 9.0;
    if (value < 3.4e38) {
        x = clamp(log2(max(value, 1e-30)) + 4.0, 0.0, 9.0);
    }
    let i = min(u32(floor(x)), 8u);
    let f = x - f32(i);
    return (ramp[i] + f * (ramp[i + 1u] - ramp[i])) / 255.0;
}

// The depth bias to add to the receiver's depth (depth-attachment units, signed for the
// convention) at a surface of unit normal n under light l, for a kernel of radius r:
// sa_kernel_scale(m, r) (constant_depth + slope_scaled_depth tan a), a the angle between n and the direction
// to the light (cos a clamped at 1e-3; a surface turned away from the light is dark anyway).
fn sa_depth_bias(m: GpuShadowMap, n: vec3<f32>, l: vec3<f32>, r: i32) -> f32 {
    let c = clamp(dot(n, -l), 1e-3, 1.0);
    let tan_a = sqrt(max(1.0 - c * c, 0.0)) / c;
    var b = (m.constant_depth + m.slope_scaled_depth * tan_a) * sa_kernel_scale(m, r);
    if (m.clip_depth == CLIP_DEPTH_NEG_ONE_TO_ONE) {
        b = 0.5 * b;
    }
    return b;
}

// The fraction of the (2r + 1)^2 taps of map i (whole-texel offsets -r..r in s and t around the
// lookup point's texel, clamped to the map) that find p lit: 1 lit, 0 in shadow. `bias` says
// which biases to apply: SA_NORMAL_OFFSET or SA_LOCAL_NORMAL_OFFSET, SA_DEPTH_BIAS, or 0u for maps
// that keep a surface from shadowing itself otherwise (second-depth maps). 1 where the lookup
// point is not on the map: no shadow is known there.
fn sa_visibility(i: u32, p: vec3<f32>, n: vec3<f32>, l: vec3<f32>, r: i32, bias: u32) -> f32 {
    let m = sa_map(i);
    var q = p;
    if ((bias & SA_LOCAL_NORMAL_OFFSET) != 0u) {
        q = p + n * sa_local_normal_offset(m, p, n, l, r);
    } else if ((bias & SA_NORMAL_OFFSET) != 0u) {
        q = sa_offset_point(m, p, n, r);
    }
    let pos = sa_project(m, q);
    if (!sa_on_map(pos)) {
        return 1.0;
    }
    var depth = pos.z;
    if ((bias & SA_DEPTH_BIAS) != 0u) {
        depth = depth + sa_depth_bias(m, n, l, r);
    }
    let centre = sa_texel(m, pos.xy);
    let last = vec2<i32>(i32(m.resolution) - 1);
    let k = max(r, 0);
    var lit = 0.0;
    for (var dy = -k; dy <= k; dy++) {
        for (var dx = -k; dx <= k; dx++) {
            let t = clamp(centre + vec2<i32>(dx, dy), vec2<i32>(0), last);
            if (sa_depth_lit(m, depth, sa_stored_depth(i, t))) {
                lit = lit + 1.0;
            }
        }
    }
    let taps = f32(2 * k + 1);
    return lit / (taps * taps);
}

// A choice of maps: `first`, with `second` cross-faded in at `weight` (0: `first` alone).
struct SaPick {
    first: u32,
    second: u32,
    weight: f32,
}

// Cascades (z-partitions, stable cascades): the first map whose split ends beyond the view depth
// (positive distance along the view direction; the last map beyond them all), and the cross-fade
// over the blend band that holds the depth, the selected map's own (a band inside its split's far
// end, Bevy's overlap) or the previous map's (a band beyond its split's far end, the frame's
// overlap), the later map's weight rising linearly across the band.
fn sa_pick_cascade(view_depth: f32) -> SaPick {
    let n = sa_map_count();
    var i = 0u;
    loop {
        if (i + 1u >= n || view_depth < sa_map(i).split.y) {
            break;
        }
        i = i + 1u;
    }
    var j = i;
    if (i > 0u) {
        j = i - 1u;
    }
    for (; j <= i && j + 1u < n; j++) {
        let b = sa_map(j).blend;
        if (b.y > b.x && view_depth >= b.x && view_depth < b.y) {
            return SaPick(j, j + 1u, (view_depth - b.x) / (b.y - b.x));
        }
    }
    return SaPick(i, i, 0.0);
}

// Clipmaps (FrameScheme::Clipmap): the level at eye depth `depth` > 0, the coarsest level whose
// texel is at most 2^bias pixels there, clamp(floor(log2(depth) + offset), first, last), with
// `offset` = LevelChoice::offset and the clipmap's first and last level (LevelChoice::level in
// f32). The frame's map of that level is slot `level - (the first map's FrameMap::clipmap_level)`.
fn sa_clipmap_level(depth: f32, offset: f32, first_level: i32, last_level: i32) -> i32 {
    let l = floor(log2(depth) + offset);
    return i32(clamp(l, f32(first_level), f32(last_level)));
}

// The visibility (sa_visibility) of a cascaded frame at a view depth, cross-faded over the blend
// bands (sa_pick_cascade).
fn sa_cascaded_visibility(
    view_depth: f32,
    p: vec3<f32>,
    n: vec3<f32>,
    l: vec3<f32>,
    r: i32,
    bias: u32,
) -> f32 {
    let pick = sa_pick_cascade(view_depth);
    let v = sa_visibility(pick.first, p, n, l, r, bias);
    if (pick.weight <= 0.0) {
        return v;
    }
    return mix(v, sa_visibility(pick.second, p, n, l, r, bias), pick.weight);
}

// Face partitions: the face of the view frustum that the light ray through the eye-space point
// p_eye passes (index in Face::ALL: bottom 0, right 1, top 2, left 3, near 4, far 5), entering the
// frustum when the light travels along the view (light_eye.z < 0) and leaving it otherwise, and
// the view depth where it crosses that face; x = -1 when the ray meets none. frustum = (near,
// far, tan of the half field of view in y, the same in x).
fn sa_face_crossing(p_eye: vec3<f32>, light_eye: vec3<f32>, frustum: vec4<f32>) -> vec2<f32> {
    var d = light_eye;
    if (d.z < 0.0) {
        d = -d;
    }
    let ty = frustum.z;
    let tx = frustum.w;
    // Outward normals N and offsets c, inside where N.x + c <= 0, in Face::ALL's order.
    var normals = array<vec3<f32>, 6>(
        vec3<f32>(0.0, -1.0, ty), vec3<f32>(1.0, 0.0, tx), vec3<f32>(0.0, 1.0, ty),
        vec3<f32>(-1.0, 0.0, tx), vec3<f32>(0.0, 0.0, 1.0), vec3<f32>(0.0, 0.0, -1.0));
    var offsets = array<f32, 6>(0.0, 0.0, 0.0, 0.0, frustum.x, -frustum.y);
    var best = 3.4e38;
    var face = -1;
    for (var k = 0; k < 6; k++) {
        let nd = dot(normals[k], d);
        if (nd > 0.0) {
            let t = -(dot(normals[k], p_eye) + offsets[k]) / nd;
            if (t < best) {
                best = t;
                face = k;
            }
        }
    }
    if (face < 0) {
        return vec2<f32>(-1.0, 0.0);
    }
    return vec2<f32>(f32(face), -(p_eye.z + best * d.z));
}

// Face partitions: the map of the face the point's light ray passes (sa_face_crossing) whose
// split holds the crossing's depth (a split with split.x == split.y, the near or far face's one
// map, holds every depth; where none holds it, the face's map nearest to it); where no map has
// that face, the first map p lies on; sa_map_count() where there is none. p is in the records'
// space, p_eye the same point in eye space.
fn sa_pick_face(p: vec3<f32>, p_eye: vec3<f32>, light_eye: vec3<f32>, frustum: vec4<f32>) -> u32 {
    let n = sa_map_count();
    let crossing = sa_face_crossing(p_eye, light_eye, frustum);
    var pick = n;
    if (crossing.x >= 0.0) {
        let face = u32(crossing.x);
        var gap = 3.4e38;
        for (var i = 0u; i < n; i++) {
            let m = sa_map(i);
            if (m.face == face) {
                var g = 0.0;
                if (m.split.x != m.split.y) {
                    g = max(max(m.split.x - crossing.y, crossing.y - m.split.y), 0.0);
                }
                if (g < gap) {
                    gap = g;
                    pick = i;
                }
            }
        }
    }
    if (pick < n) {
        return pick;
    }
    for (var i = 0u; i < n; i++) {
        if (sa_on_map(sa_project(sa_map(i), p))) {
            return i;
        }
    }
    return n;
}
