// The error lens pass (src/lens_render.rs; docs/bevy.md, "The error lens"): a full-screen pass
// after tone mapping that draws, over the view's image, the crate's error lens (sa_error_lens,
// sa_lens_colour of shadow_aliasing::frame::SHADOW_WGSL, which lens_render.rs concatenates after
// this file's imports) for the cascade Bevy's shader selects at each pixel, and its legend.

@group(0) @binding(0) var screen: texture_2d<f32>;
#ifdef MULTISAMPLED
@group(0) @binding(1) var depth_prepass: texture_depth_multisampled_2d;
@group(0) @binding(2) var normal_prepass: texture_multisampled_2d<f32>;
#else
@group(0) @binding(1) var depth_prepass: texture_depth_2d;
@group(0) @binding(2) var normal_prepass: texture_2d<f32>;
#endif
@group(0) @binding(3) var<uniform> view: View;
@group(0) @binding(4) var<uniform> lens: ErrorLensUniform;

// ErrorLensMaps::uniform_bytes (src/lens.rs).
struct ErrorLensUniform {
    maps: array<GpuShadowMap, 4>,
    // The direction the light travels (world space, unit).
    light: vec3<f32>,
    count: u32,
    opacity: f32,
    legend: u32,
}

// The module's interface (SHADOW_WGSL's header). This pass calls sa_error_lens and
// sa_lens_colour, which read the records alone; sa_stored_depth serves the module's shadow
// lookup (sa_visibility), which this pass never calls, so it binds no shadow map.
fn sa_map(i: u32) -> GpuShadowMap {
    return lens.maps[min(i, 3u)];
}
fn sa_map_count() -> u32 {
    return max(lens.count, 1u);
}
fn sa_stored_depth(i: u32, texel: vec2<i32>) -> f32 {
    return 0.0;
}

// The lens at the pixel, or -1 where there is none: the sky, an orthographic view, a surface
// beyond the last far bound or off the map of its cascade (Bevy draws both unshadowed).
fn lens_at(frag: vec2<f32>) -> f32 {
    let pixel = vec2<i32>(floor(frag));
    // Level 0, or sample 0 of a multisampled prepass.
    let depth = textureLoad(depth_prepass, pixel, 0);
    let encoded = textureLoad(normal_prepass, pixel, 0).xyz;
    // Reversed depth: 0 is the far plane at infinity (nothing drawn).
    if (depth <= 0.0 || view.clip_from_view[3][3] == 1.0 || lens.count == 0u) {
        return -1.0;
    }
    // The surface point from the depth, through Bevy's world_from_clip.
    let uv = (frag - view.viewport.xy) / view.viewport.zw;
    let ndc = vec4<f32>(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, depth, 1.0);
    let h = view.world_from_clip * ndc;
    let p = h.xyz / h.w;
    // Bevy's prepass stores the world normal as n / 2 + 1/2 (bevy_pbr's pbr_prepass.wgsl).
    let n = normalize(encoded * 2.0 - vec3<f32>(1.0));
    let eye = view.world_position;
    let forward = -normalize(view.world_from_view[2].xyz);
    let z = dot(p - eye, forward);
    // Bevy's cascade (get_cascade_index, bevy_pbr/src/render/shadows.wgsl): the first whose far
    // bound lies beyond the view depth; none beyond the last.
    var i = 0u;
    loop {
        if (i >= lens.count || z < sa_map(i).split.y) {
            break;
        }
        i = i + 1u;
    }
    if (i >= lens.count) {
        return -1.0;
    }
    let m = sa_map(i);
    // Off the map: Bevy's world_to_directional_light_local (w > 0, NDC x, y in [-1, 1], z in
    // [0, 1]) finds no shadow there.
    let c = m.world_to_clip * vec4<f32>(p, 1.0);
    let q = c.xyz / c.w;
    if (!(c.w > 0.0) || any(q.xy < vec2<f32>(-1.0)) || q.z < 0.0 || any(q > vec3<f32>(1.0))) {
        return -1.0;
    }
    // Pixels per unit across the view at unit view depth: image height / (2 tan(fov / 2)),
    // clip_from_view[1][1] = 1 / tan(fov / 2).
    let focal_pixels = 0.5 * view.viewport.w * view.clip_from_view[1][1];
    return sa_error_lens(m, p, n, lens.light, eye, forward, focal_pixels);
}

// The legend's glyphs, 3 x 5 cells, row by row from the top, the first cell in bit 14: the digits,
// then "/" (10), "p" (11) and "x" (12).
fn glyph(g: u32) -> u32 {
    var glyphs = array<u32, 13>(
        0x7B6Fu, 0x2C97u, 0x73E7u, 0x73CFu, 0x5BC9u, 0x79CFu, 0x79EFu, 0x7249u, 0x7BEFu, 0x7BCFu,
        0x12A4u, 0x6BA4u, 0x0AA8u);
    return glyphs[min(g, 12u)];
}

// Label k of the legend (the ramp's values at its ten colours, 1/16 ... 32 pixels; k = 10 the
// unit, "px"): its glyphs, four bits each from bit 0, and its length.
fn label(k: u32) -> vec2<u32> {
    var glyphs = array<u32, 11>(
        0x61A1u, 0x8A1u, 0x4A1u, 0x2A1u, 0x1u, 0x2u, 0x4u, 0x8u, 0x61u, 0x23u, 0xCBu);
    var lengths = array<u32, 11>(4u, 3u, 3u, 3u, 1u, 1u, 1u, 1u, 2u, 2u, 2u);
    return vec2<u32>(glyphs[k], lengths[k]);
}

// Whether the point (x, y) (pixels from the label's top-left corner) is inked in label k drawn
// with cells of s pixels (glyphs 3 cells wide, 1 cell apart).
fn label_ink(k: u32, x: f32, y: f32, s: f32) -> bool {
    let l = label(k);
    let col = i32(floor(x / s));
    let row = i32(floor(y / s));
    if (x < 0.0 || y < 0.0 || row > 4 || col >= i32(l.y) * 4 || col % 4 == 3) {
        return false;
    }
    let g = glyph((l.x >> (4u * u32(col / 4))) & 15u);
    let bit = 14u - u32(row * 3 + col % 4);
    return ((g >> bit) & 1u) == 1u;
}

// The legend's geometry for a view `height` pixels high, in pixels from the view's lower-left
// corner: the unit u (1 up to 540 pixels, then one per further 360), the ramp's left end and
// width (nine steps of 40 u between the ten colours), its bottom and height.
struct Legend {
    u: f32,
    x0: f32,
    width: f32,
    bottom: f32,
    height: f32,
}

fn legend_geometry(height: f32) -> Legend {
    let u = max(1.0, floor(height / 360.0 + 0.5));
    return Legend(u, 24.0 * u, 360.0 * u, 28.0 * u, 10.0 * u);
}

// The legend's colour over `scene` at the pixel (x, y from the view's lower-left corner), and
// whether the legend covers the pixel (w = 1).
fn legend_at(x: f32, y: f32, scene: vec3<f32>) -> vec4<f32> {
    let g = legend_geometry(view.viewport.w);
    let u = g.u;
    let s = 2.0 * u;
    // The panel: the ramp, the labels under it, the unit after it.
    let left = g.x0 - 20.0 * u;
    let right = g.x0 + g.width + 34.0 * u;
    let bottom = g.bottom - 20.0 * u;
    let top = g.bottom + g.height + 6.0 * u;
    if (x < left || x >= right || y < bottom || y >= top) {
        return vec4<f32>(scene, 0.0);
    }
    let white = vec3<f32>(1.0);
    // The ramp: pixel column c shows the value at 2^(-4 + 9 (c - x0) / width), so the ten
    // colours fall on whole columns, x0 + 40 u k.
    let c = floor(x);
    if (y >= g.bottom && y < g.bottom + g.height && c >= g.x0 && c <= g.x0 + g.width) {
        let v = exp2(-4.0 + 9.0 * (c - g.x0) / g.width);
        return vec4<f32>(srgb_to_linear(sa_lens_colour(v)), 1.0);
    }
    // The labels, centred under their colours, 4 u below the ramp.
    let label_top = g.bottom - 4.0 * u;
    for (var k = 0u; k < 10u; k++) {
        let w = (f32(label(k).y) * 4.0 - 1.0) * s;
        let lx = g.x0 + 40.0 * u * f32(k) - floor(0.5 * w);
        if (label_ink(k, x - lx, label_top - y, s)) {
            return vec4<f32>(white, 1.0);
        }
    }
    if (label_ink(10u, x - (g.x0 + g.width + 12.0 * u), g.bottom + g.height - y, s)) {
        return vec4<f32>(white, 1.0);
    }
    return vec4<f32>(mix(scene, vec3<f32>(0.0), 0.6), 1.0);
}

// sRGB-encoded components to linear (the view's colour before the target's sRGB encoding).
fn srgb_to_linear(c: vec3<f32>) -> vec3<f32> {
    let lo = c / 12.92;
    let hi = pow((c + vec3<f32>(0.055)) / 1.055, vec3<f32>(2.4));
    return select(hi, lo, c <= vec3<f32>(0.04045));
}

@fragment
fn fragment(in: FullscreenVertexOutput) -> @location(0) vec4<f32> {
    let frag = in.position.xy;
    let scene = textureLoad(screen, vec2<i32>(floor(frag)), 0);
    var out = scene.rgb;
    let v = lens_at(frag);
    if (v > 0.0) {
        out = mix(out, srgb_to_linear(sa_lens_colour(v)), lens.opacity);
    }
    if (lens.legend != 0u) {
        let x = frag.x - view.viewport.x;
        let y = view.viewport.w - (frag.y - view.viewport.y);
        let l = legend_at(x, y, out);
        if (l.w > 0.0) {
            out = l.rgb;
        }
    }
    return vec4<f32>(out, scene.a);
}
