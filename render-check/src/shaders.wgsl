// render-check's two passes. Positions arrive in eye space (transformed on the CPU in f64), so
// the interpolated position is accurate near the camera where pixels are smallest.

struct Part {
    // Eye → light clip, depth in [0, 1] (pulled back to cover the casters).
    m: mat4x4<f32>,
    // x: region (-1 = frustum depth range, 0..5 = frustum face), y: near, z: far.
    region: vec4<f32>,
};

struct Globals {
    proj: mat4x4<f32>,
    // xyz: light direction (eye space, unit, the way light travels); w: selection mode
    // (0 single, 1 z-partitions, 2 faces).
    light: vec4<f32>,
    // near, far, tan(half fov y), tan(half fov y) * aspect.
    frustum: vec4<f32>,
    // x: map resolution, y: number of parts, z: facing threshold.
    misc: vec4<f32>,
};

struct ShadowUniform {
    m: mat4x4<f32>,
    // xyz: light direction (eye space, travel); w: facing threshold.
    light: vec4<f32>,
};

@group(0) @binding(0) var<uniform> su: ShadowUniform;

struct SOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) @interpolate(flat) facing: f32,
};

@vertex
fn vs_shadow(@location(0) pos: vec3<f32>, @location(1) normal: vec3<f32>) -> SOut {
    var o: SOut;
    o.clip = su.m * vec4<f32>(pos, 1.0);
    o.facing = dot(normal, -su.light.xyz);
    return o;
}

// Second-depth shadow maps (Wang & Molnar 1994): only faces turned away from the light (or
// edge-on) are stored, so a lit face is compared with the far side of its own closed box and
// never with itself; faces turned away are dark by the facing test anyway.
@fragment
fn fs_shadow(v: SOut) {
    if (v.facing > su.light.w) {
        discard;
    }
}

@group(0) @binding(0) var<uniform> g: Globals;
@group(0) @binding(1) var<storage, read> parts: array<Part>;
@group(0) @binding(2) var shadow_maps: texture_depth_2d_array;

struct VOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) eye: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) @interpolate(flat) id: u32,
};

@vertex
fn vs_camera(@location(0) pos: vec3<f32>, @location(1) normal: vec3<f32>, @location(2) id: u32) -> VOut {
    var o: VOut;
    o.clip = g.proj * vec4<f32>(pos, 1.0);
    o.eye = pos;
    o.normal = normal;
    o.id = id;
    return o;
}

struct FOut {
    @location(0) texel: vec4<f32>,
    @location(1) id: u32,
    @location(2) color: vec4<f32>,
    // The light clip depth z/w in the selected map, unclamped ([0, 1] inside its depth range;
    // -1e30 behind its centre of projection): the coverage check reads it.
    @location(3) depth: f32,
};

// The face of the frustum where the ray from p along d leaves it (p inside).
fn exit_face(p: vec3<f32>, d: vec3<f32>) -> i32 {
    let t = g.frustum.z;
    let ta = g.frustum.w;
    // Outward normals and offsets: N·x + c <= 0 inside. Order: bottom, right, top, left, near, far.
    var ns = array<vec3<f32>, 6>(
        vec3<f32>(0.0, -1.0, t), vec3<f32>(1.0, 0.0, ta), vec3<f32>(0.0, 1.0, t),
        vec3<f32>(-1.0, 0.0, ta), vec3<f32>(0.0, 0.0, 1.0), vec3<f32>(0.0, 0.0, -1.0));
    var cs = array<f32, 6>(0.0, 0.0, 0.0, 0.0, g.frustum.x, -g.frustum.y);
    var best = 1e30;
    var face = -1;
    for (var i = 0; i < 6; i++) {
        let nd = dot(ns[i], d);
        if (nd > 0.0) {
            let tt = -(dot(ns[i], p) + cs[i]) / nd;
            if (tt < best) {
                best = tt;
                face = i;
            }
        }
    }
    return face;
}

fn inside_map(m: mat4x4<f32>, p: vec3<f32>) -> bool {
    let h = m * vec4<f32>(p, 1.0);
    let st = h.xy / h.w;
    return h.w > 0.0 && all(abs(st) <= vec2<f32>(1.0));
}

fn select_part(p: vec3<f32>) -> u32 {
    let mode = i32(g.light.w);
    let n = u32(g.misc.y);
    if (mode == 0) {
        return 0u;
    }
    if (mode == 1) {
        let z = -p.z;
        for (var i = 0u; i < n; i++) {
            if (z < parts[i].region.z) {
                return i;
            }
        }
        return n - 1u;
    }
    var d = g.light.xyz;
    if (d.z < 0.0) {
        d = -d;
    }
    let face = exit_face(p, d);
    for (var i = 0u; i < n; i++) {
        let r = parts[i].region;
        if (i32(r.x) == face) {
            let z = -p.z;
            if (r.y == r.z || (z >= r.y && z <= r.z)) {
                return i;
            }
        }
    }
    for (var i = 0u; i < n; i++) {
        if (inside_map(parts[i].m, p)) {
            return i;
        }
    }
    return 0u;
}

@fragment
fn fs_camera(v: VOut) -> FOut {
    let p = v.eye;
    let n = normalize(v.normal);
    let part = select_part(p);
    let m = parts[part].m;
    let h = m * vec4<f32>(p, 1.0);
    let st = (h.xy / h.w + vec2<f32>(1.0)) * 0.5;
    let res = g.misc.x;
    let depth = clamp(h.z / h.w, 0.0, 1.0);
    let facing = dot(n, -g.light.xyz);
    var lit = facing > g.misc.z;
    if (lit && h.w > 0.0 && all(st >= vec2<f32>(0.0)) && all(st < vec2<f32>(1.0))) {
        let ix = vec2<i32>(i32(floor(st.x * res)), i32(floor((1.0 - st.y) * res)));
        let stored = textureLoad(shadow_maps, ix, i32(part), 0);
        if (depth > stored) {
            lit = false;
        }
    }
    var o: FOut;
    o.texel = vec4<f32>(st * res, f32(part), select(0.0, 1.0, lit));
    o.depth = select(-1e30, h.z / h.w, h.w > 0.0);
    o.id = v.id + 1u;
    // Shading: a colour per surface kind, Lambert when lit, ambient in shadow.
    var base = vec3<f32>(0.62, 0.6, 0.55);
    if (v.id > 0u) {
        let k = f32((v.id / 6u) % 7u);
        base = vec3<f32>(0.55 + 0.06 * k, 0.45 + 0.04 * (6.0 - k), 0.35 + 0.05 * k);
    }
    let light = 0.25 + select(0.0, 0.75 * max(facing, 0.0), lit);
    // Tint by partition so the seams are visible.
    let tint = 0.9 + 0.1 * vec3<f32>(f32(part % 2u), f32((part / 2u) % 2u), f32((part / 4u) % 2u));
    o.color = vec4<f32>(base * light * tint, 1.0);
    return o;
}
