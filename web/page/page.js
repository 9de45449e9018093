// The live page (docs/web.md, "The live page"): a scene ray-cast on a canvas, its shadows, and
// over it the error lens of the map that shades each point (the crate's errorLens), with the
// sun draggable over the hemisphere, a choice of scheme and budget, the numbers, the view from
// the light and the papers' curves for the current set-up. Plain canvas 2D: no WebGL needed.
import { Controller, closed, errorLens, frame, init, lensColour } from '../npm/index.js';

const t0 = performance.now();
const $ = (id) => document.getElementById(id);
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const add = (a, b, s = 1) => [a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const unit = (a) => { const l = Math.hypot(...a); return [a[0] / l, a[1] / l, a[2] / l]; };
const apply = (m, p) => [0, 1, 2, 3].map((i) => m[i] * p[0] + m[4 + i] * p[1] + m[8 + i] * p[2] + m[12 + i]);

// The scene: a ground box and posts, [min, max] each; the camera.
const boxes = [[-200, -1, -200, 200, 0, 200]];
for (const [x, z, sx, sy, sz] of [[-6, 10, 1, 6, 1], [4, 0, 2, 3, 2], [-3, -20, 1, 8, 6], [10, -45, 6, 5, 1],
  [-14, -70, 2, 12, 2], [2, -110, 8, 6, 8], [20, -160, 3, 15, 3], [-30, -220, 10, 10, 2]]) {
  boxes.push([x - sx / 2, 0, z - sz / 2, x + sx / 2, sy, z + sz / 2]);
}
const bounds = [{ min: [-200, -1, -200], max: [200, 15, 200] }];
const [W, H] = [640, 360];
const CELL = 4;
const eye = [0, 8, 30];
// Level (no pitch), so that eye space is world space moved by −eye, and the command line
// (`shadow-aliasing warp`, eye space) can be given the same scene: web/page/test.mjs.
const fwd = unit(sub([0, 8, -40], eye));
const side = unit(cross(fwd, [0, 1, 0]));
const up = cross(side, fwd);
const view = [side[0], up[0], -fwd[0], 0, side[1], up[1], -fwd[1], 0, side[2], up[2], -fwd[2], 0,
  -dot(side, eye), -dot(up, eye), dot(fwd, eye), 1];
const camera = { near: 0.5, far: 300, half_fov: Math.PI / 6, aspect: W / H };

/** A scheme as the numbers table names it: "3 cascades, equal-error, lispsm". */
function describe(scheme) {
  const parts = Object.entries(scheme)
    .filter(([key]) => key !== 'kind' && key !== 'k')
    .map(([, value]) => (typeof value === 'object' ? JSON.stringify(value) : String(value)));
  const head = scheme.k ? `${scheme.k} ${scheme.kind}` : scheme.kind;
  return [head, ...parts].join(', ');
}

const state = { azimuth: 1.3, elevation: 0.45, scheme: 'equal-error', res: 1024, budget: 2 };
let controller = null;

function schemeOf(name) {
  switch (name) {
    case 'uniform': return { kind: 'single', rule: 'uniform' };
    case 'lispsm': return { kind: 'single', rule: 'lispsm' };
    case 'cascades': return { kind: 'cascades', rule: 'uniform', partition: 'log', k: 4 };
    case 'clipmap': return { kind: 'clipmap', first_level: 6, last_level: 16 };
    default: return { kind: 'cascades', rule: 'uniform', partition: 'equal-error', k: 4 };
  }
}

function sunDir() {
  const { azimuth: a, elevation: e } = state;
  return [Math.cos(e) * Math.sin(a), Math.sin(e), Math.cos(e) * Math.cos(a)];
}

function hit(o, d) {
  let best = null;
  for (const bx of boxes) {
    let t0 = 0, t1 = Infinity, axis = -1, sign = 0;
    for (let a = 0; a < 3; a++) {
      if (Math.abs(d[a]) < 1e-12) { if (o[a] < bx[a] || o[a] > bx[a + 3]) { t0 = Infinity; break; } continue; }
      let ta = (bx[a] - o[a]) / d[a], tb = (bx[a + 3] - o[a]) / d[a], s = -1;
      if (ta > tb) { [ta, tb] = [tb, ta]; s = 1; }
      if (ta > t0) { t0 = ta; axis = a; sign = s; }
      t1 = Math.min(t1, tb);
    }
    if (t0 <= t1 && t0 > 1e-6 && (best === null || t0 < best.t)) best = { t: t0, axis, sign };
  }
  return best;
}

// Eye rays through the cell centres: hit point, normal, view depth, lit or not.
function castScene(toSun) {
  const cells = [];
  const th = Math.tan(camera.half_fov);
  for (let py = CELL / 2; py < H; py += CELL) {
    for (let px = CELL / 2; px < W; px += CELL) {
      const x = ((2 * px) / W - 1) * th * camera.aspect;
      const y = (1 - (2 * py) / H) * th;
      const d = unit(add(add(fwd, side, x), up, y));
      const h = hit(eye, d);
      if (!h || dot(d, fwd) * h.t > camera.far) { cells.push(null); continue; }
      const p = add(eye, d, h.t);
      const n = [0, 0, 0];
      n[h.axis] = h.sign;
      const ndl = dot(n, toSun);
      const lit = ndl > 0 && hit(add(p, n, 1e-4), toSun) === null;
      cells.push({ p, n, z: dot(sub(p, eye), fwd), shade: 0.25 + (lit ? ndl : 0) });
    }
  }
  return cells;
}

// The map that shades a point: among the maps whose split holds its view depth, the finest one
// whose square covers it.
function mapOf(maps, c) {
  let best = -1;
  maps.forEach((m, i) => {
    if (c.z < m.split[0] || c.z > m.split[1]) return;
    const q = apply(m.world_to_clip, c.p);
    if (Math.abs(q[0] / q[3]) > 1 || Math.abs(q[1] / q[3]) > 1) return;
    if (best < 0 || m.texel_world < maps[best].texel_world) best = i;
  });
  return best;
}

function drawLegend() {
  const g = $('legend').getContext('2d');
  g.clearRect(0, 0, W, 40);
  for (let x = 0; x < W - 40; x++) {
    const v = 2 ** (-4 + (9 * x) / (W - 41));
    const c = lensColour(v);
    g.fillStyle = `rgb(${c.map((k) => Math.round(255 * k)).join(',')})`;
    g.fillRect(x + 20, 0, 1, 18);
  }
  g.fillStyle = '#222';
  g.font = '11px system-ui';
  ['1/16', '1/8', '1/4', '1/2', '1 px', '2', '4', '8', '16', '32'].forEach((t, i) => {
    g.fillText(t, 20 + (i * (W - 41)) / 9 - 8, 32);
  });
}

function plot(id, title, xs, series, xlabel, mark) {
  const cv = $(id);
  const g = cv.getContext('2d');
  const [w, h, l, b] = [cv.width, cv.height, 36, 24];
  g.clearRect(0, 0, w, h);
  const ys = series.flatMap((s) => Array.from(s.ys)).filter((v) => v > 0 && Number.isFinite(v));
  const [lo, hi] = [Math.log10(Math.min(...ys)), Math.log10(Math.max(...ys))];
  const span = Math.max(hi - lo, 1e-9);
  const X = (x) => l + ((x - xs[0]) / (xs[xs.length - 1] - xs[0])) * (w - l - 8);
  const Y = (y) => h - b - ((Math.log10(y) - lo) / span) * (h - b - 18);
  g.strokeStyle = '#888';
  g.strokeRect(l, 18, w - l - 8, h - b - 18);
  g.fillStyle = '#222';
  g.font = '11px system-ui';
  g.fillText(title, l, 12);
  g.fillText(xlabel, w / 2, h - 6);
  g.fillText(`${(10 ** hi).toPrecision(3)}`, 2, 24);
  g.fillText(`${(10 ** lo).toPrecision(3)}`, 2, h - b);
  for (const s of series) {
    g.strokeStyle = s.colour;
    g.beginPath();
    s.ys.forEach((y, i) => (i ? g.lineTo(X(xs[i]), Y(y)) : g.moveTo(X(xs[i]), Y(y))));
    g.stroke();
    g.fillStyle = s.colour;
    g.fillText(s.name, w - 60, 30 + 12 * series.indexOf(s));
  }
  if (mark !== undefined) {
    g.strokeStyle = '#c00';
    g.beginPath();
    g.moveTo(X(mark), 18);
    g.lineTo(X(mark), h - b);
    g.stroke();
  }
}

function invert(m) {
  const a = Array.from(m);
  const inv = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
  // Gauss–Jordan on the column-major 4 × 4 (element (r, c) at c * 4 + r).
  for (let c = 0; c < 4; c++) {
    let p = c;
    for (let r = c + 1; r < 4; r++) if (Math.abs(a[c * 4 + r]) > Math.abs(a[c * 4 + p])) p = r;
    for (let k = 0; k < 4; k++) {
      [a[k * 4 + c], a[k * 4 + p]] = [a[k * 4 + p], a[k * 4 + c]];
      [inv[k * 4 + c], inv[k * 4 + p]] = [inv[k * 4 + p], inv[k * 4 + c]];
    }
    const d = a[c * 4 + c];
    for (let k = 0; k < 4; k++) { a[k * 4 + c] /= d; inv[k * 4 + c] /= d; }
    for (let r = 0; r < 4; r++) {
      if (r === c) continue;
      const f = a[c * 4 + r];
      for (let k = 0; k < 4; k++) { a[k * 4 + r] -= f * a[k * 4 + c]; inv[k * 4 + r] -= f * inv[k * 4 + c]; }
    }
  }
  return inv;
}

// The view from the light: light-space axes u, v across the light, the boxes' edges and each
// map's square (its clip square at mid depth, mapped back to the world).
function drawLight(maps, toSun) {
  const g = $('light').getContext('2d');
  g.clearRect(0, 0, 320, 320);
  const u = unit(cross(toSun, Math.abs(toSun[1]) > 0.99 ? [1, 0, 0] : [0, 1, 0]));
  const v = cross(u, toSun);
  const corners = [];
  for (const m of maps) {
    const inv = invert(m.world_to_clip);
    const sq = [[-1, -1], [1, -1], [1, 1], [-1, 1]].map(([x, y]) => {
      const q = apply(inv, [x, y, 0.5]);
      return [q[0] / q[3], q[1] / q[3], q[2] / q[3]];
    });
    corners.push(sq);
  }
  const pts = corners.flat().map((p) => [dot(p, u), dot(p, v)]);
  const minX = Math.min(...pts.map((p) => p[0])), maxX = Math.max(...pts.map((p) => p[0]));
  const minY = Math.min(...pts.map((p) => p[1])), maxY = Math.max(...pts.map((p) => p[1]));
  const s = 300 / Math.max(maxX - minX, maxY - minY, 1e-9);
  const P = (p) => [10 + (dot(p, u) - minX) * s, 310 - (dot(p, v) - minY) * s];
  g.strokeStyle = '#999';
  for (const bx of boxes.slice(1)) {
    const c = [0, 1, 2, 3, 4, 5, 6, 7].map((i) => [bx[i & 1 ? 3 : 0], bx[i & 2 ? 4 : 1], bx[i & 4 ? 5 : 2]]);
    g.beginPath();
    for (const [i, j] of [[0, 1], [2, 3], [4, 5], [6, 7], [0, 2], [1, 3], [4, 6], [5, 7], [0, 4], [1, 5], [2, 6], [3, 7]]) {
      g.moveTo(...P(c[i]));
      g.lineTo(...P(c[j]));
    }
    g.stroke();
  }
  corners.forEach((sq, i) => {
    const c = lensColour(2 ** (i - 2));
    g.strokeStyle = `rgb(${c.map((k) => Math.round(255 * k)).join(',')})`;
    g.lineWidth = 2;
    g.beginPath();
    sq.forEach((p, k) => (k ? g.lineTo(...P(p)) : g.moveTo(...P(p))));
    g.closePath();
    g.stroke();
    g.lineWidth = 1;
  });
  g.fillStyle = '#222';
  g.fillText('the view from the light', 8, 14);
}

function update() {
  const toSun = sunDir();
  const input = {
    world_to_eye: view, ...camera,
    light_dir_world: [-toSun[0], -toSun[1], -toSun[2]],
    receivers: bounds, casters: bounds, map_resolution: state.res, image_height: H,
    clip_depth: 'zero-to-one', scheme: schemeOf(state.scheme),
  };
  let f;
  let resolution = state.res;
  let label = state.scheme;
  if (state.scheme === 'budget') {
    if (!controller || controller.budget !== state.budget) {
      controller?.free();
      controller = new Controller({ max_error: state.budget, max_maps: 4, max_resolution: 4096 });
      controller.budget = state.budget;
    }
    const d = controller.frame(input);
    f = d.frame;
    resolution = d.resolution;
    label = `controller: ${describe(d.scheme)}`;
    input.scheme = d.scheme;
    input.map_resolution = d.resolution;
  } else {
    f = frame(input);
  }
  const maps = f.maps;
  // The scene and the lens over it.
  const cells = castScene(toSun);
  const groups = maps.map(() => []);
  cells.forEach((c, i) => { if (c) { c.map = mapOf(maps, c); if (c.map >= 0) groups[c.map].push(i); } });
  groups.forEach((idx, m) => {
    if (!idx.length) return;
    const lens = errorLens(input, idx.flatMap((i) => cells[i].p), idx.flatMap((i) => cells[i].n), m);
    idx.forEach((i, k) => { cells[i].lens = lens.valid[k] ? lens.values[k] : null; });
  });
  const g = $('scene').getContext('2d');
  const img = g.createImageData(W, H);
  const cw = W / CELL;
  cells.forEach((c, i) => {
    const rgb = !c ? [0.93, 0.95, 1] : c.lens == null ? [0.5, 0.5, 0.5] : lensColour(c.lens);
    const k = c ? Math.min(1, 0.3 + 0.7 * c.shade / 1.25) : 1;
    const [cx, cy] = [(i % cw) * CELL, Math.floor(i / cw) * CELL];
    for (let y = cy; y < cy + CELL; y++) {
      for (let x = cx; x < cx + CELL; x++) {
        const o = 4 * (y * W + x);
        for (let ch = 0; ch < 3; ch++) img.data[o + ch] = Math.round(255 * rgb[ch] * k);
        img.data[o + 3] = 255;
      }
    }
  });
  g.putImageData(img, 0, 0);
  // The numbers.
  const largest = Math.max(...maps.map((m) => m.max_error_pixels));
  const rows = [
    ['scheme', label],
    ['maps', maps.length],
    ['resolution', `${resolution}²`],
    ['texels', (maps.length * resolution * resolution).toLocaleString('en')],
    ['largest error', `${largest.toFixed(3)} px`],
    ...maps.map((m, i) => [`map ${i}`, `z ${m.split[0].toFixed(2)}–${m.split[1].toFixed(2)}: ${m.max_error_pixels.toFixed(3)} px, texel ${m.texel_world.toPrecision(3)}`]),
  ];
  $('numbers').innerHTML = rows.map(([k, v]) => `<tr><td>${k}</td><td class="v">${v}</td></tr>`).join('');
  drawLight(maps, toSun);
  // The papers' curves for this camera and the first map's n′ (Lloyd 2006 Eq 7, 8, 12, 11).
  const { near, far, half_fov } = camera;
  const np = Math.max(maps[0].n_prime, near);
  const zs = Array.from({ length: 100 }, (_, i) => near * (far / near) ** (i / 99));
  const res = { res_image: H, res_s: resolution };
  plot('mxmz', `m_x, m_z along the view (n′ = ${Number.isFinite(np) ? np.toFixed(2) : '∞'})`, zs, [
    { name: 'm_x', colour: '#1f77b4', ys: closed.mx({ near, far, n_prime: np, z: zs, ...res }) },
    { name: 'm_z', colour: '#d62728', ys: closed.mz({ near, far, half_fov, n_prime: np, z: zs, res_image: H, res_t: resolution }) },
  ], 'view depth z');
  const etas = Array.from({ length: 101 }, (_, i) => -1 + i / 50);
  const sbar = etas.map((eta) => closed.storageFactor({ near, far, half_fov, n_prime: closed.nPrimeFromEta({ near, far, eta }) }));
  plot('eta', 'S̄ against η', etas, [{ name: 'S̄', colour: '#2ca02c', ys: sbar }], 'η',
    closed.etaFromNPrime({ near, far, n_prime: np }));
  const samples = cells.filter((c) => c && c.lens != null).filter((_, i) => i % 97 === 0)
    .map((c) => ({ p: c.p, n: c.n, map: c.map, lens: c.lens }));
  window.saPage = { input, frame: f, largest, resolution, rows, cells: cells.length, samples };
}

function drawSun() {
  const g = $('sun').getContext('2d');
  g.clearRect(0, 0, 320, 160);
  g.strokeStyle = '#999';
  g.beginPath();
  g.arc(160, 150, 140, Math.PI, 2 * Math.PI);
  g.stroke();
  const x = 160 + 140 * Math.cos(state.elevation) * Math.sin(state.azimuth) * 1;
  const y = 150 - 140 * Math.sin(state.elevation);
  g.fillStyle = '#e8a400';
  g.beginPath();
  g.arc(x, y, 8, 0, 2 * Math.PI);
  g.fill();
  g.fillStyle = '#222';
  g.fillText(`sun: azimuth ${(state.azimuth * 180 / Math.PI).toFixed(0)}°, elevation ${(state.elevation * 180 / Math.PI).toFixed(0)}°`, 8, 14);
}

function safely(f) {
  try {
    f();
    $('error').textContent = '';
  } catch (e) {
    $('error').textContent = String(e.message ?? e);
    throw e;
  }
}

await init(new URL('../npm/shadow_aliasing.wasm', import.meta.url));
drawLegend();
drawSun();
safely(update);
// Dragging on the hemisphere: x sets the azimuth, height the elevation.
let dragging = false;
const onDrag = (ev) => {
  if (!dragging) return;
  const r = $('sun').getBoundingClientRect();
  const dx = Math.max(-1, Math.min(1, (ev.clientX - r.left - 160) / 140));
  const dy = Math.max(0.05, Math.min(1, (150 - (ev.clientY - r.top)) / 140));
  state.elevation = Math.asin(dy);
  state.azimuth = Math.asin(Math.max(-1, Math.min(1, dx / Math.cos(state.elevation))));
  drawSun();
  safely(update);
};
$('sun').addEventListener('pointerdown', (ev) => { dragging = true; onDrag(ev); });
window.addEventListener('pointerup', () => { dragging = false; });
window.addEventListener('pointermove', onDrag);
for (const id of ['scheme', 'res', 'budget']) {
  $(id).addEventListener('change', () => {
    state.scheme = $('scheme').value;
    state.res = Number($('res').value);
    state.budget = Number($('budget').value);
    safely(update);
  });
}
window.saPageLoadMs = performance.now() - t0;
