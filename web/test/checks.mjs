// Checks of the installed npm package (web/test/pack.mjs runs this in a fresh folder where
// `shadow-aliasing` is the packed tarball). Every expected value is computed here, in
// JavaScript, independently of the crate: the papers' equations, finite differences of the
// returned matrices, the hand-made camera; or it is the crate's literal message text.
import assert from 'node:assert/strict';
import {
  Controller,
  ShadowAliasingError,
  closed,
  errorLens,
  frame,
  init,
  lensColour,
  measureMap,
  version,
} from 'shadow-aliasing';

await init();
let passed = 0;
function test(name, f) {
  f();
  passed += 1;
  console.log(`ok ${name}`);
}
const close = (a, b, rel, what) =>
  assert.ok(Math.abs(a - b) <= rel * Math.max(Math.abs(a), Math.abs(b)), `${what}: ${a} vs ${b} (rel ${rel})`);

// The camera, built here: eye, target, up → world → eye, column-major (three.js's order).
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const unit = (a) => {
  const l = Math.hypot(...a);
  return [a[0] / l, a[1] / l, a[2] / l];
};
const eye = [0, 10, 20];
const fwd = unit(sub([0, 0, -20], eye));
const side = unit(cross(fwd, [0, 1, 0]));
const up = cross(side, fwd);
const view = [
  side[0], up[0], -fwd[0], 0,
  side[1], up[1], -fwd[1], 0,
  side[2], up[2], -fwd[2], 0,
  -dot(side, eye), -dot(up, eye), dot(fwd, eye), 1,
];
const toEye = (p) => [dot(side, sub(p, eye)), dot(up, sub(p, eye)), -dot(fwd, sub(p, eye))];
const toWorld = (q) => [0, 1, 2].map((i) => eye[i] + side[i] * q[0] + up[i] * q[1] - fwd[i] * q[2]);
const apply = (m, p) => [0, 1, 2, 3].map((i) => m[i] * p[0] + m[4 + i] * p[1] + m[8 + i] * p[2] + m[12 + i]);

const ground = [{ min: [-50, -1, -100], max: [50, 0, 50] }];
const input = {
  world_to_eye: view,
  near: 0.5,
  far: 200,
  half_fov: 0.5,
  aspect: 16 / 9,
  light_dir_world: [0.3, -1, -0.2],
  receivers: ground,
  casters: ground,
  map_resolution: 1024,
  image_height: 1080,
};

test('version', () => assert.equal(version(), '0.1.0'));

test('closed forms equal Lloyd 2006 Eq 7, 8, 11, 12 computed here', () => {
  const [n, f, th] = [1, 100, 0.5];
  const npL = n + Math.sqrt(f * n);
  close(closed.nPrimeLispsm({ near: n, far: f }), npL, 1e-15, 'n′_LSPSM');
  const z = [1, 2.5, 10, 42, 100];
  const mx = closed.mx({ near: n, far: f, n_prime: npL, z, res_image: 1000, res_s: 2000 });
  assert.ok(mx instanceof Float64Array);
  z.forEach((zi, i) => close(mx[i], (1000 / 2000) * (f * (npL + zi - n)) / (zi * (npL + f - n)), 1e-14, `m_x(${zi})`));
  const mz = closed.mz({ near: n, far: f, half_fov: th, n_prime: npL, z });
  z.forEach((zi, i) =>
    close(mz[i], ((f - n) / (2 * Math.tan(th))) * (npL + zi - n) ** 2 / (zi * npL * (npL + f - n)), 1e-14, `m_z(${zi})`),
  );
  close(closed.mx({ near: n, far: f, n_prime: Infinity, z: 4 }), f / 4, 1e-15, 'uniform m_x');
  const base = (f / n - 1) / (2 * Math.tan(th));
  close(closed.storageFactor({ near: n, far: f, half_fov: th, n_prime: npL }), base, 1e-14, 'S̄ LiSPSM');
  close(closed.storageFactor({ near: n, far: f, half_fov: th, n_prime: Infinity }), (base * f) / n, 1e-14, 'S̄ uniform');
  const np2 = 30; // above n′_LSPSM = 11
  close(closed.storageFactor({ near: n, far: f, half_fov: th, n_prime: np2 }), (base * np2 ** 2 * f) / (n * (np2 + f - n) ** 2), 1e-14, 'S̄ n′ = 30');
  const a = f / n;
  close(closed.nPrimeFromEta({ near: n, far: f, eta: 0.5 }), (n * (Math.sqrt(a) + 1)) / (0.5 * Math.sqrt(a) + 1), 1e-14, 'n′(0.5)');
  close(closed.nPrimeFromEta({ near: n, far: f, eta: -0.5 }), (n * (Math.sqrt(a) + 1 + 0.5 * (a - 1))) / 0.5, 1e-14, 'n′(−0.5)');
  close(closed.etaFromNPrime({ near: n, far: f, n_prime: npL }), 0, 1e-12, 'η(n′_LSPSM)');
  assert.ok(Math.abs(closed.etaFromNPrime({ near: n, far: f, n_prime: npL })) < 1e-12);
});

test('matrices are column-major world → clip and fit the focus body', () => {
  for (const scheme of [
    { kind: 'single', rule: 'uniform' },
    { kind: 'single', rule: 'lispsm' },
    { kind: 'cascades', rule: 'lispsm', partition: 'log', k: 3 },
  ]) {
    const f = frame({ ...input, scheme, clip_depth: 'zero-to-one' });
    assert.ok(f.maps.length >= 1);
    for (const m of f.maps) {
      assert.ok(m.world_to_clip instanceof Float64Array && m.world_to_clip.length === 16);
      assert.ok(m.world_to_clip_f32 instanceof Float32Array);
      m.world_to_clip.forEach((v, i) => assert.equal(m.world_to_clip_f32[i], Math.fround(v)));
      let [mx, my] = [0, 0];
      for (let i = 0; i < m.body.length; i += 3) {
        const c = apply(m.world_to_clip, toWorld([m.body[i], m.body[i + 1], m.body[i + 2]]));
        const [x, y, d] = [c[0] / c[3], c[1] / c[3], c[2] / c[3]];
        assert.ok(Math.abs(x) <= 1 + 1e-9 && Math.abs(y) <= 1 + 1e-9, `${scheme.kind}: body vertex at (${x}, ${y})`);
        assert.ok(d >= -1e-9 && d <= 1 + 1e-9, `depth ${d} outside [0, 1]`);
        mx = Math.max(mx, Math.abs(x));
        my = Math.max(my, Math.abs(y));
      }
      close(mx, 1, 1e-9, 'the body reaches the map edge in s');
      close(my, 1, 1e-9, 'the body reaches the map edge in t');
      assert.ok(m.max_error_pixels > 0 && Number.isFinite(m.max_error_pixels));
      assert.ok(m.texel_world > 0 && m.bias.normal_offset > 0);
    }
  }
});

// The lens from finite differences of the returned matrix and the camera built here: texel
// coordinates (s, t) = res/2 · clip xy / w and pixel coordinates = focal · eye xy / depth, both
// differentiated along the surface; the lens is σ_max of (pixels per texel) = B A⁻¹.
function lensByDifferences(m, p, res, imageHeight, halfFov) {
  const focal = imageHeight / (2 * Math.tan(halfFov));
  const texel = (q) => {
    const c = apply(m.world_to_clip, q);
    return [(res / 2) * (c[0] / c[3]), (res / 2) * (c[1] / c[3])];
  };
  const pixel = (q) => {
    const e = toEye(q);
    return [(focal * e[0]) / -e[2], (focal * e[1]) / -e[2]];
  };
  const h = 1e-3;
  const d = (g, t) => {
    const a = g([p[0] + h * t[0], p[1] + h * t[1], p[2] + h * t[2]]);
    const b = g([p[0] - h * t[0], p[1] - h * t[1], p[2] - h * t[2]]);
    return [(a[0] - b[0]) / (2 * h), (a[1] - b[1]) / (2 * h)];
  };
  const [u, v] = [[1, 0, 0], [0, 0, 1]]; // tangents of the ground (normal +y)
  const [au, av, bu, bv] = [d(texel, u), d(texel, v), d(pixel, u), d(pixel, v)];
  const det = au[0] * av[1] - av[0] * au[1];
  // A⁻¹ = [[av1, −av0], [−au1, au0]] / det; P = B A⁻¹.
  const P = [
    (bu[0] * av[1] - bv[0] * au[1]) / det,
    (-bu[0] * av[0] + bv[0] * au[0]) / det,
    (bu[1] * av[1] - bv[1] * au[1]) / det,
    (-bu[1] * av[0] + bv[1] * au[0]) / det,
  ];
  const s1 = P.reduce((s, x) => s + x * x, 0);
  const dp = P[0] * P[3] - P[1] * P[2];
  return Math.sqrt((s1 + Math.sqrt(Math.max(0, s1 * s1 - 4 * dp * dp))) / 2);
}

test('the error lens equals finite differences of the map and the camera', () => {
  const points = [];
  for (const x of [-20, -3, 0, 7, 25]) for (const z of [-150, -60, -10, 5, 12]) points.push(x, 0, z);
  for (const scheme of [{ kind: 'single', rule: 'uniform' }, { kind: 'single', rule: 'lispsm' }]) {
    const inp = { ...input, scheme };
    const m = frame(inp).maps[0];
    const lens = errorLens(inp, points, [0, 1, 0]);
    assert.equal(lens.values.length, points.length / 3);
    let checked = 0;
    for (let i = 0; i < lens.values.length; i++) {
      const p = points.slice(3 * i, 3 * i + 3);
      if (toEye(p)[2] >= -input.near) {
        assert.equal(lens.valid[i], 0, `point ${p} is behind the camera`);
        assert.match(lens.reasons[i], /not in front of the camera/);
        continue;
      }
      assert.equal(lens.valid[i], 1);
      close(lens.values[i], lensByDifferences(m, p, input.map_resolution, input.image_height, input.half_fov), 1e-5, `lens at ${p}`);
      checked += 1;
    }
    assert.ok(checked >= 15, `${checked} points checked`);
  }
});

test("measureMap gives a frame's own error, and half of it with twice the texels", () => {
  const inp = { ...input, scheme: { kind: 'cascades', rule: 'uniform', partition: 'practical', lambda: 0.7, k: 3 } };
  for (const m of frame(inp).maps) {
    const e = measureMap(inp, m.split, m.world_to_clip);
    close(e.max_error_pixels, m.max_error_pixels, 1e-9, `cascade ${m.slot}`);
    // Clip x and y doubled: each texel half as wide, so the error halves (S̄ quarters).
    const twice = Float64Array.from(m.world_to_clip, (v, i) => (i % 4 < 2 ? 2 * v : v));
    const h = measureMap(inp, m.split, twice);
    close(h.max_error_pixels, m.max_error_pixels / 2, 1e-9, `cascade ${m.slot} doubled`);
    close(h.storage_factor, m.storage_factor / 4, 1e-9, `cascade ${m.slot} S̄`);
  }
  assert.equal(measureMap(inp, [300, 400], frame(inp).maps[0].world_to_clip), null);
  throwsNaming(() => measureMap(inp, [5, 1], frame(inp).maps[0].world_to_clip), 'cover', /z0 < z1/);
});

test('the lens colour of 1 px is viridis #26828e', () => {
  const c = lensColour(1);
  [0x26, 0x82, 0x8e].forEach((b, i) => close(c[i], b / 255, 1e-12, `channel ${i}`));
});

test('three.js objects are taken as they are', () => {
  const v3 = (x, y, z) => ({ isVector3: true, x, y, z });
  const three = {
    ...input,
    world_to_eye: { isMatrix4: true, elements: new Float64Array(view) },
    light_dir_world: v3(0.3, -1, -0.2),
    receivers: [{ isBox3: true, min: v3(-50, -1, -100), max: v3(50, 0, 50) }],
  };
  const a = frame(three).maps[0].world_to_clip;
  const b = frame(input).maps[0].world_to_clip;
  assert.deepEqual(Array.from(a), Array.from(b));
});

test('every scheme builds finite matrices', () => {
  const schemes = [
    ...['uniform', 'psm', 'lispsm', 'lispsm-fixed', 'lispsm-reference', 'barroso', 'barroso-zhang', 'minimax',
      'minimax-mz', 'filament', 'ogre', 'tsm', 'ogre-ortho'].map((rule) => ({ kind: 'single', rule })),
    { kind: 'single', rule: { name: 'eta', eta: 0.3 } },
    { kind: 'cascades', rule: 'uniform', partition: 'practical', lambda: 0.5, k: 4, overlap: 0.1 },
    { kind: 'cascades', rule: 'minimax', partition: 'equal-error', k: 3 },
    { kind: 'cascades', rule: 'lispsm', partition: 'adaptive', k: 3 },
    { kind: 'cascades', rule: 'uniform', splits: [0.5, 10, 50, 200] },
    { kind: 'cascades', rule: 'uniform', fractions: [0.1, 0.4] },
    { kind: 'stable', bevy: { num_cascades: 4, minimum_distance: 0.5, maximum_distance: 150, first_cascade_far_bound: 10, overlap_proportion: 0.2 } },
    { kind: 'tsm' },
    { kind: 'tsm', iterative: 64 },
    { kind: 'faces', rule: 'lispsm', k: 1 },
    { kind: 'clipmap', first_level: 6, last_level: 16 },
  ];
  for (const scheme of schemes) {
    const f = frame({ ...input, scheme });
    assert.ok(f.maps.length >= 1, JSON.stringify(scheme));
    for (const m of f.maps) assert.ok(m.world_to_clip.every(Number.isFinite), JSON.stringify(scheme));
  }
});

function throwsNaming(f, argument, message) {
  assert.throws(f, (e) => {
    assert.ok(e instanceof ShadowAliasingError && e instanceof Error);
    assert.equal(e.kind, 'InvalidArgument');
    assert.equal(e.argument, argument);
    if (message instanceof RegExp) assert.match(e.message, message);
    else assert.equal(e.message, message);
    return true;
  });
}

test('bad input throws with the argument named and the crate message', () => {
  throwsNaming(() => frame({ ...input, map_resolution: 2 }), 'map_resolution', 'map_resolution must be at least 3 texels (got 2)');
  throwsNaming(() => frame({ ...input, light_dir_world: [0, 0, 0] }), 'light_dir_world', 'light_dir_world must be a finite, non-zero vector');
  throwsNaming(() => frame({ ...input, near: NaN }), 'near', /^near .*NaN/);
  throwsNaming(() => frame({ ...input, map_res: 4 }), 'input', /unknown key "map_res"/);
  throwsNaming(() => frame({ ...input, scheme: { kind: 'cascade' } }), 'scheme', /must be one of single, cascades/);
  throwsNaming(() => frame({ ...input, receivers: [{ min: [0, 0, 0], max: [-1, 1, 1] }] }), 'receivers', /min not above max/);
  throwsNaming(() => errorLens(input, [0, 0, -10], [0, 0, 0]), 'normals', /non-zero/);
  throwsNaming(() => closed.mx({ near: 1, far: 100, n_prime: 11, z: 0.5 }), 'z', /^z /);
  throwsNaming(() => new Controller({}), 'options', /max_error/);
});

test('the controller meets its target, counts its texels, and its scheme builds the same maps', () => {
  const c = new Controller({ max_error: 2, max_maps: 4 });
  for (let frameNo = 0; frameNo < 3; frameNo++) {
    const d = c.frame(input);
    const maps = d.frame.maps;
    assert.equal(d.texels, maps.length * d.resolution * d.resolution);
    assert.equal(d.max_error_pixels, Math.max(...maps.map((m) => m.max_error_pixels)));
    assert.ok(d.meets_target && d.max_error_pixels <= 2, `${d.max_error_pixels} px`);
    if (frameNo === 0) console.log(`  controller: ${JSON.stringify(d.scheme)} at ${d.resolution}², ${d.max_error_pixels.toFixed(3)} px`);
    const again = frame({ ...input, scheme: d.scheme, map_resolution: d.resolution });
    assert.equal(again.maps.length, maps.length);
    // The first frame searches: the same maps bit for bit. Later frames keep equal-error
    // cascades' planes as fractions of the depth range (docs/planning.md), which the
    // search places again to within rounding.
    again.maps.forEach((m, i) => {
      if (frameNo === 0) assert.deepEqual(Array.from(m.world_to_clip), Array.from(maps[i].world_to_clip));
      const scale = Math.max(...maps[i].world_to_clip.map(Math.abs));
      m.world_to_clip.forEach((v, j) => assert.ok(Math.abs(v - maps[i].world_to_clip[j]) <= 1e-12 * scale, `entry ${j}`));
    });
  }
  c.free();
  throwsNaming(() => c.frame(input), 'id', /names no live controller/);
});

// An orthographic map's texel edge in world units from its world → clip matrix alone
// (column-major): clip s spans 2 over `res` texels, and a world step moves it by the s row's
// (x, y, z); the same for t; the larger of the two.
function orthoTexel(m, res) {
  const row = (i) => Math.hypot(m[i], m[4 + i], m[8 + i]);
  return Math.max(2 / (res * row(0)), 2 / (res * row(1)));
}

const UNIFORM_CASCADES = { kind: 'cascades', rule: 'uniform', partition: 'practical', lambda: 0.5, k: 3 };

test('each map has its own resolution: its texel from the matrix, its error as 1/resolution', () => {
  const each = [2048, 512, 128];
  const own = frame({ ...input, scheme: UNIFORM_CASCADES, map_resolutions: each });
  const one = frame({ ...input, scheme: UNIFORM_CASCADES, map_resolution: 1024 });
  assert.equal(own.maps.length, 3);
  own.maps.forEach((m, i) => {
    assert.equal(m.resolution, each[m.slot]);
    assert.equal(one.maps[i].resolution, 1024);
    close(m.texel_world, orthoTexel(m.world_to_clip, each[m.slot]), 1e-9, `map ${i}'s texel`);
    // The warp and the fit do not depend on the resolution; the error is one texel's size.
    assert.deepEqual(Array.from(m.world_to_clip), Array.from(one.maps[i].world_to_clip));
    close(m.max_error_pixels * each[m.slot], one.maps[i].max_error_pixels * 1024, 1e-12, `map ${i}'s error`);
    // The matrix measured over its slice at its own resolution (the input's map_resolutions
    // are not read there): the frame's own error.
    const inp = { ...input, scheme: UNIFORM_CASCADES, map_resolutions: each, map_resolution: each[m.slot] };
    close(measureMap(inp, m.split, m.world_to_clip).max_error_pixels, m.max_error_pixels, 1e-9, `map ${i} measured`);
  });
  // Stable cascades snap to whole texels of their own resolution: the world origin lands at a
  // whole number of texels from each map's centre (clip s and t span 2 over its texels).
  const stable = frame({ ...input, scheme: { kind: 'stable', partition: 'log', k: 3 }, map_resolutions: [300, 1000, 3000] });
  assert.ok(stable.maps.length >= 2);
  for (const m of stable.maps) {
    const r = [300, 1000, 3000][m.slot];
    assert.equal(m.resolution, r);
    close(m.texel_world, orthoTexel(m.world_to_clip, r), 1e-9, `stable map ${m.slot}'s texel`);
    for (const axis of [0, 1]) {
      const texels = ((m.world_to_clip[12 + axis] / m.world_to_clip[15]) * r) / 2;
      assert.ok(Math.abs(texels - Math.round(texels)) < 1e-6, `stable map ${m.slot}: origin at ${texels} texels`);
    }
  }
});

test("the controller with a resolution per map: each map's own texel, texels the sum of squares, resolutions rebuild the maps", () => {
  const candidates = [
    { kind: 'single', rule: 'uniform' },
    ...[2, 3, 4].map((k) => ({ ...UNIFORM_CASCADES, k })),
  ];
  const each = new Controller({ max_error: 2, max_maps: 4, candidates, shared_resolution: false });
  const shared = new Controller({ max_error: 2, max_maps: 4, candidates });
  // The input's map_resolutions are the controller's to choose: given, they change nothing.
  const ignoring = new Controller({ max_error: 2, max_maps: 4, candidates, shared_resolution: false });
  for (let frameNo = 0; frameNo < 3; frameNo++) {
    const inp = { ...input, world_to_eye: view.map((v, i) => (i === 12 ? v - frameNo : v)) };
    const d = each.frame(inp);
    const s = shared.frame(inp);
    const maps = d.frame.maps;
    assert.ok(d.meets_target && d.max_error_pixels <= 2, `${d.max_error_pixels} px`);
    assert.ok(Array.isArray(d.resolutions) && d.resolutions.length >= Math.max(...maps.map((m) => m.slot)) + 1);
    assert.deepEqual(s.resolutions, s.resolutions.map(() => s.resolution));
    let texels = 0;
    for (const m of maps) {
      assert.equal(m.resolution, d.resolutions[m.slot]);
      assert.ok(m.max_error_pixels <= 2, `map ${m.slot}: ${m.max_error_pixels} px`);
      close(m.texel_world, orthoTexel(m.world_to_clip, m.resolution), 1e-9, `map ${m.slot}'s texel`);
      texels += m.resolution ** 2;
    }
    assert.equal(d.texels, texels);
    assert.equal(d.resolution, Math.max(...maps.map((m) => m.resolution)));
    assert.ok(d.texels <= s.texels, `${d.texels} texels, ${s.texels} shared`);
    if (frameNo === 0) {
      console.log(`  each map: ${JSON.stringify(d.scheme)} at ${d.resolutions.join(', ')}: ${d.texels} texels (shared ${s.resolution}²: ${s.texels})`);
    }
    const again = frame({ ...inp, scheme: d.scheme, map_resolutions: d.resolutions });
    assert.deepEqual(again.maps.map((m) => Array.from(m.world_to_clip)), maps.map((m) => Array.from(m.world_to_clip)));
    assert.deepEqual(again.maps.map((m) => m.max_error_pixels), maps.map((m) => m.max_error_pixels));
    const g = ignoring.frame({ ...inp, map_resolutions: [7] });
    assert.deepEqual(g.resolutions, d.resolutions);
  }
  [each, shared, ignoring].forEach((c) => c.free());
});

test('bad resolutions throw naming map_resolutions and shared_resolution', () => {
  const inp = { ...input, scheme: UNIFORM_CASCADES };
  throwsNaming(() => frame({ ...inp, map_resolutions: 512 }), 'map_resolutions', /^map_resolutions must be an array of whole numbers/);
  throwsNaming(() => frame({ ...inp, map_resolutions: [512, 1.5, 512] }), 'map_resolutions[1]', /must be a whole number/);
  throwsNaming(() => frame({ ...inp, map_resolutions: [512, -1, 512] }), 'map_resolutions[1]', /must be a whole number/);
  throwsNaming(() => frame({ ...inp, map_resolutions: [512, 512] }), 'map_resolutions', /^map_resolutions has 2 entries, and the scheme has 3 partitions/);
  throwsNaming(() => frame({ ...inp, map_resolutions: [512, 2, 512] }), 'map_resolutions', 'map_resolutions must hold resolutions of at least 3 texels each (got 2)');
  throwsNaming(() => frame({ ...input, scheme: { kind: 'clipmap' }, map_resolutions: [512] }), 'map_resolutions', /^map_resolutions cannot be used with a clipmap/);
  throwsNaming(() => new Controller({ max_error: 2, shared_resolution: 'no' }), 'shared_resolution', /must be a boolean/);
});

console.log(`${passed} checks passed`);
