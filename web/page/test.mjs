// The live page in headless Chromium (docs/web.md, "The live page"): it loads in under 2 s with
// no console error; the numbers it shows are those of the package's frame() for the input it
// reports, computed here in Node.js and formatted here; its lens at sample points equals finite
// differences of the map it used and the page's camera (computed here); every scheme renders,
// and SCREENSHOTS=DIR writes one image per scheme. Needs Debian's chromium and `npm install` in
// web/ (playwright-core); web/build.sh first.
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { join } from 'node:path';
import { chromium } from 'playwright-core';
import { serve } from '../serve.mjs';
import { Controller, frame, init } from '../npm/index.js';

await init();
const { server, base } = await serve();
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox'],
});
const apply = (m, p) => [0, 1, 2, 3].map((i) => m[i] * p[0] + m[4 + i] * p[1] + m[8 + i] * p[2] + m[12 + i]);

// `shadow-aliasing warp --json` for the page's input: the page's camera is level, so eye space is
// world space moved by −eye, and the boxes and the light go to the command line as they are.
const cli = process.env.SHADOW_ALIASING_BIN ?? join(import.meta.dirname ?? new URL('.', import.meta.url).pathname, '..', '..', 'target', 'debug', 'shadow-aliasing');
function warpJson(input) {
  const v = input.world_to_eye;
  const t = [v[12], v[13], v[14]];
  assert.deepEqual([v[0], v[1], v[2], v[4], v[5], v[6], v[8], v[9], v[10]].map((x) => x + 0), [1, 0, 0, 0, 1, 0, 0, 0, 1], 'a level camera');
  const box = (b) => [...b.min.map((x, i) => x + t[i]), ...b.max.map((x, i) => x + t[i])].join(',');
  const s = input.scheme;
  const args = ['warp', '--near', input.near, '--far', input.far, '--half-fov', input.half_fov, '--aspect', input.aspect,
    `--light-dir=${input.light_dir_world.join(',')}`, `--receivers=${box(input.receivers[0])}`, `--casters=${box(input.casters[0])}`, '--json'];
  if (s.kind === 'single') args.push('--warp', s.rule);
  else if (s.kind === 'cascades') args.push('--warp', s.rule, '--partition', s.partition, '--k', s.k);
  else if (s.kind === 'clipmap') {
    args.push('--warp', 'uniform', '--partition', 'clipmap', '--levels', `${s.first_level},${s.last_level}`,
      '--virtual-resolution', input.map_resolution, '--image-height', input.image_height);
  } else return null;
  return JSON.parse(execFileSync(cli, args.map(String)).toString());
}
const rel = (a, b) => Math.abs(a - b) <= 1e-9 * Math.max(Math.abs(a), Math.abs(b));

// The lens by finite differences (as web/test/checks.mjs): σ_max of pixels per texel along the
// surface, from the map's matrix and the page's camera (world → eye, column-major).
function lensByDifferences(input, m, p, n) {
  const v = input.world_to_eye;
  const focal = input.image_height / (2 * Math.tan(input.half_fov));
  const res = input.map_resolution;
  const texel = (q) => { const c = apply(m, q); return [(res / 2) * (c[0] / c[3]), (res / 2) * (c[1] / c[3])]; };
  const pixel = (q) => { const e = apply(v, q); return [(focal * e[0]) / -e[2], (focal * e[1]) / -e[2]]; };
  const axis = n.findIndex((x) => x !== 0);
  const [u, w] = [[0, 1, 2].filter((a) => a !== axis)].flat().map((a) => [0, 1, 2].map((k) => (k === a ? 1 : 0)));
  const h = 1e-3;
  const d = (g, t) => {
    const a = g(p.map((x, k) => x + h * t[k]));
    const b = g(p.map((x, k) => x - h * t[k]));
    return [(a[0] - b[0]) / (2 * h), (a[1] - b[1]) / (2 * h)];
  };
  const [au, av, bu, bv] = [d(texel, u), d(texel, w), d(pixel, u), d(pixel, w)];
  const det = au[0] * av[1] - av[0] * au[1];
  const P = [(bu[0] * av[1] - bv[0] * au[1]) / det, (-bu[0] * av[0] + bv[0] * au[0]) / det,
    (bu[1] * av[1] - bv[1] * au[1]) / det, (-bu[1] * av[0] + bv[1] * au[0]) / det];
  const s1 = P.reduce((s, x) => s + x * x, 0);
  const dp = P[0] * P[3] - P[1] * P[2];
  return Math.sqrt((s1 + Math.sqrt(Math.max(0, s1 * s1 - 4 * dp * dp))) / 2);
}

let checks = 0;
try {
  const page = await browser.newPage({ viewport: { width: 1000, height: 720 } });
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  const t0 = Date.now();
  await page.goto(`${base}/page/index.html`);
  await page.waitForFunction(() => window.saPageLoadMs !== undefined, null, { timeout: 20000 });
  const loadMs = Date.now() - t0;
  console.log(`loaded in ${loadMs} ms (the page's own module: ${(await page.evaluate(() => window.saPageLoadMs)).toFixed(0)} ms)`);
  assert.ok(loadMs < 2000, `the page took ${loadMs} ms to load`);
  for (const scheme of ['equal-error', 'uniform', 'lispsm', 'cascades', 'clipmap', 'budget']) {
    await page.selectOption('#scheme', scheme);
    const s = await page.evaluate(() => window.saPage);
    // The numbers shown, against frame() here for the input the page reports.
    let f;
    let resolution = s.input.map_resolution;
    if (scheme === 'budget') {
      // A controller's first frame is a search: the same decision from a fresh one here.
      const c = new Controller({ max_error: 2, max_maps: 4, max_resolution: 4096 });
      const d = c.frame({ ...s.input, scheme: undefined });
      assert.deepEqual(d.scheme, s.input.scheme);
      f = d.frame;
      resolution = d.resolution;
      c.free();
    } else {
      f = frame(s.input);
    }
    const largest = Math.max(...f.maps.map((m) => m.max_error_pixels));
    assert.ok(Math.abs(largest - s.largest) <= 1e-9 * largest, `${scheme}: ${s.largest} vs ${largest}`);
    const shown = await page.$$eval('#numbers tr', (rows) => rows.map((r) => [...r.cells].map((c) => c.textContent)));
    const expect = [
      ['maps', String(f.maps.length)],
      ['resolution', `${resolution}²`],
      ['texels', (f.maps.length * resolution * resolution).toLocaleString('en')],
      ['largest error', `${largest.toFixed(3)} px`],
      ...f.maps.map((m, i) => [`map ${i}`, `z ${m.split[0].toFixed(2)}–${m.split[1].toFixed(2)}: ${m.max_error_pixels.toFixed(3)} px, texel ${m.texel_world.toPrecision(3)}`]),
    ];
    assert.deepEqual(shown.slice(1), expect, `${scheme}: the numbers shown`);
    // The command line's numbers for the same camera, light and scene.
    const w = warpJson(s.input);
    if (w) {
      assert.equal(w.partitions.length, f.maps.length, `${scheme}: maps`);
      w.partitions.forEach((p, i) => {
        const m = s.frame.maps[i];
        for (const k of ['max_mx', 'max_mz', 'storage_factor']) {
          assert.ok(rel(p[k], m[k]), `${scheme}: map ${i} ${k}: page ${m[k]}, warp --json ${p[k]}`);
        }
        // warp's maps have 2048 texels a side (a clipmap's, --virtual-resolution).
        const cliRes = s.input.scheme.kind === 'clipmap' ? resolution : 2048;
        assert.ok(rel(p.texel_world * cliRes, m.texel_world * resolution), `${scheme}: map ${i} texel_world`);
        assert.ok(rel(p.split[0], m.split[0]) && rel(p.split[1], m.split[1]), `${scheme}: map ${i} split`);
        const px = (Math.max(p.max_mx, p.max_mz) * s.input.image_height) / resolution;
        assert.ok(rel(px, m.max_error_pixels), `${scheme}: map ${i}: ${px} px by warp --json, ${m.max_error_pixels} shown`);
      });
    }
    // The lens at sample pixels, against finite differences here.
    assert.ok(s.samples.length >= 20, `${scheme}: ${s.samples.length} samples`);
    for (const c of s.samples) {
      const m = f.maps[c.map].world_to_clip;
      const e = lensByDifferences(s.input, m, c.p, c.n);
      assert.ok(Math.abs(e - c.lens) <= 1e-5 * e, `${scheme}: lens ${c.lens} vs ${e} at ${c.p}`);
    }
    if (process.env.SCREENSHOTS) await page.screenshot({ path: join(process.env.SCREENSHOTS, `page-${scheme}.png`) });
    console.log(`ok ${scheme}: ${f.maps.length} maps, ${largest.toFixed(3)} px, ${s.samples.length} lens samples${w ? ', equal to warp --json' : ''}`);
    checks += 1;
  }
  assert.deepEqual(errors, [], 'console errors');
} finally {
  await browser.close();
  server.close();
}
console.log(`${checks} schemes checked`);
