// render-check's two passes. `gpu::shader_source` puts the crate's module
// (shadow_aliasing::frame::SHADOW_WGSL: the GpuShadowMap record and the sa_ lookup functions)
// before this text: the maps are selected and looked up by the crate's own WGSL.
//
// Positions arrive relative to the upload origin (the camera's position), the f64 difference
// rounded once, and the maps' records are FrameMap::gpu_relative's; `offset` is added to a
// position before a map's matrix (0 on that path; the plain-world fault sets it to the origin).

struct Globals {
    // Relative position -> camera clip (wgpu: depth [0, 1], NDC y up).
    rel_to_clip: mat4x4<f32>,
    // Relative position -> eye space (view depth, face choice).
    rel_to_eye: mat4x4<f32>,
    // xyz: light direction (world axes, unit, the way light travels); w: facing threshold.
    light: vec4<f32>,
    // xyz: the light direction in eye space; w: selection mode (0 single, 1 cascades, 2 faces).
    light_eye: vec4<f32>,
    // near, far, tan(half fov y), tan(half fov y) * aspect.
    frustum: vec4<f32>,
    // x: map resolution, y: number of maps, z: sa_visibility's bias flags (0: second-depth maps;
    // first-surface maps: SA_LOCAL_NORMAL_OFFSET, and in the shader-path passes any of the
    // module's flags), w: sa_error_lens's
    // focal_pixels (image height / (2 tan(half vertical field of view))).
    misc: vec4<f32>,
    // xyz: added to a position before a map's matrix.
    offset: vec4<f32>,
    // Clipmaps (mode 3): sa_clipmap_level's offset, the first and the last map's level.
    clipmap: vec4<f32>,
    // x: 1 for the fault blend-ignored (a cascade shaded by its first map alone in the band);
    // y: sa_visibility's PCF radius r ((2r + 1)^2 taps); z: 1 to skip the error lens (the
    // shader-path passes read only the texel target).
    faults: vec4<f32>,
};

struct ShadowUniform {
    map: GpuShadowMap,
    // xyz: light direction (world axes, travel); w: facing threshold.
    light: vec4<f32>,
    // xyz: added to a position before the map's matrix.
    offset: vec4<f32>,
};

@group(0) @binding(0) var<uniform> su: ShadowUniform;

struct SOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) @interpolate(flat) facing: f32,
};

@vertex
fn vs_shadow(@location(0) pos: vec3<f32>, @location(1) normal: vec3<f32>) -> SOut {
    var o: SOut;
    o.clip = su.map.world_to_clip * vec4<f32>(pos + su.offset.xyz, 1.0);
    o.facing = dot(normal, -su.light.xyz);
    return o;
}

// Second-depth shadow maps (Wang & Molnar 1994): only faces turned away from the light (or
// edge-on) are stored, so a lit face is compared with the far side of its own closed box and
// never with itself; faces turned away are dark by the facing test anyway. (First-surface maps
// have no fragment stage: every face is stored.)
@fragment
fn fs_shadow(v: SOut) {
    if (v.facing > su.light.w) {
        discard;
    }
}

@group(0) @binding(0) var<uniform> g: Globals;
@group(0) @binding(1) var<storage, read> maps: array<GpuShadowMap>;
@group(0) @binding(2) var shadow_maps: texture_depth_2d_array;

// The four functions the crate's module reads the maps through.
fn sa_map(i: u32) -> GpuShadowMap {
    return maps[i];
}

fn sa_map_count() -> u32 {
    return u32(g.misc.y);
}

fn sa_map_resolution() -> f32 {
    return g.misc.x;
}

fn sa_stored_depth(i: u32, texel: vec2<i32>) -> f32 {
    return textureLoad(shadow_maps, texel, i32(i), 0);
}

struct VOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) rel: vec3<f32>,
    @location(1) eye: vec3<f32>,
    @location(2) normal: vec3<f32>,
    @location(3) @interpolate(flat) id: u32,
};

@vertex
fn vs_camera(@location(0) pos: vec3<f32>, @location(1) normal: vec3<f32>, @location(2) id: u32) -> VOut {
    var o: VOut;
    o.clip = g.rel_to_clip * vec4<f32>(pos, 1.0);
    o.rel = pos;
    o.eye = (g.rel_to_eye * vec4<f32>(pos, 1.0)).xyz;
    o.normal = normal;
    o.id = id;
    return o;
}

struct FOut {
    // s·res, t·res in the selected map, the map (the number of maps: none), the visibility
    // shaded (0 in shadow, 1 lit; between them in a cascade's blend band).
    @location(0) texel: vec4<f32>,
    @location(1) id: u32,
    @location(2) color: vec4<f32>,
    // The depth (depth-attachment units) in the selected map, unclamped ([0, 1] inside its depth
    // range; -1e30 behind its centre of projection or with no map): the coverage check reads it.
    @location(3) depth: f32,
    // The second map (sa_pick_cascade's; the first elsewhere), its weight, and the visibility of
    // the first and of the second map alone: the analysis recomputes the cross-fade.
    @location(4) blend: vec4<f32>,
    // The error lens of the selected map at the pixel (sa_error_lens), and the same with the
    // projection factor 1 (the surface facing the light, seen along the light from the same view
    // depth: the texel across the light beam over the pixel across the view beam); -2 with no map.
    @location(5) lens: vec2<f32>,
    // The lens drawn over the scene: sa_lens_colour of the lens, 3/4, over the shaded colour,
    // 1/4 (the shaded colour alone with no map).
    @location(6) overlay: vec4<f32>,
};

@fragment
fn fs_camera(v: VOut) -> FOut {
    let p = v.rel + g.offset.xyz;
    let n = normalize(v.normal);
    let l = g.light.xyz;
    let count = sa_map_count();
    let mode = i32(g.light_eye.w);
    let view_depth = -v.eye.z;
    var pick = SaPick(0u, 0u, 0.0);
    if (mode == 1) {
        pick = sa_pick_cascade(view_depth);
    } else if (mode == 2) {
        let f = sa_pick_face(p, v.eye, g.light_eye.xyz, g.frustum);
        pick = SaPick(f, f, 0.0);
    } else if (mode == 3) {
        let level = sa_clipmap_level(view_depth, g.clipmap.x, i32(g.clipmap.y), i32(g.clipmap.z));
        let slot = u32(level - i32(g.clipmap.y));
        pick = SaPick(slot, slot, 0.0);
    }
    let part = pick.first;
    let facing = dot(n, -l);
    // The visibility shaded (cascades: cross-faded over the band), and each map's alone.
    var vis = select(0.0, 1.0, facing > g.light.w);
    var v1 = vis;
    var v2 = vis;
    var st = vec2<f32>(0.0);
    var depth = -1e30;
    let r = i32(g.faults.y);
    if (part < count) {
        let q = sa_project(sa_map(part), p);
        st = q.xy;
        depth = select(-1e30, q.z, q.w > 0.0);
        if (vis > 0.0) {
            v1 = sa_visibility(part, p, n, l, r, u32(g.misc.z));
            v2 = v1;
            vis = v1;
            if (mode == 1) {
                v2 = sa_visibility(pick.second, p, n, l, r, u32(g.misc.z));
                if (g.faults.x < 0.5) {
                    vis = sa_cascaded_visibility(view_depth, p, n, l, r, u32(g.misc.z));
                }
            }
        }
    }
    var lens = vec2<f32>(-2.0);
    if (part < count && g.faults.z >= 0.5 && facing > g.light.w) {
        // The shader-path passes: the normal offset (world units) sa_visibility moves the lookup
        // point by in the selected map, from the crate's functions as sa_visibility calls them
        // (0 with neither offset flag); render-check measures the lookup point's lift with it.
        let flags = u32(g.misc.z);
        var offset = 0.0;
        if ((flags & SA_LOCAL_NORMAL_OFFSET) != 0u) {
            offset = sa_local_normal_offset(sa_map(part), p, n, l, r);
        } else if ((flags & SA_NORMAL_OFFSET) != 0u) {
            offset = sa_map(part).normal_offset * sa_offset_scale(sa_map(part), r);
        }
        lens = vec2<f32>(offset, 0.0);
    }
    if (part < count && g.faults.z < 0.5) {
        // The camera in the records' space (the upload origin is the camera's position) and its
        // unit view axis (the eye's -z in world axes: minus the third row of rel_to_eye).
        let eye = g.offset.xyz;
        let forward = -normalize(vec3<f32>(g.rel_to_eye[0].z, g.rel_to_eye[1].z, g.rel_to_eye[2].z));
        let focal = g.misc.w;
        let z = dot(p - eye, forward);
        lens = vec2<f32>(
            sa_error_lens(sa_map(part), p, n, l, eye, forward, focal),
            sa_error_lens(sa_map(part), p, -l, l, p - z * l, l, focal),
        );
    }
    let res = g.misc.x;
    var o: FOut;
    o.lens = lens;
    o.texel = vec4<f32>(st * res, f32(part), vis);
    o.blend = vec4<f32>(f32(pick.second), pick.weight, v1, v2);
    o.depth = depth;
    o.id = v.id + 1u;
    // Shading: a colour per surface kind, Lambert when lit, ambient in shadow.
    var base = vec3<f32>(0.62, 0.6, 0.55);
    if (v.id > 0u) {
        let k = f32((v.id / 6u) % 7u);
        base = vec3<f32>(0.55 + 0.06 * k, 0.45 + 0.04 * (6.0 - k), 0.35 + 0.05 * k);
    }
    let light = 0.25 + 0.75 * max(facing, 0.0) * vis;
    // Tint by partition so the seams are visible.
    let tint = 0.9 + 0.1 * vec3<f32>(f32(part % 2u), f32((part / 2u) % 2u), f32((part / 4u) % 2u));
    o.color = vec4<f32>(base * light * tint, 1.0);
    o.overlay = o.color;
    if (part < count) {
        o.overlay = vec4<f32>(mix(o.color.rgb, sa_lens_colour(lens.x), 0.75), 1.0);
    }
    return o;
}
