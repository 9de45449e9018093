// three.js's own CSMShadowNode against the crate's cascades (CrateCSMShadowNode.js), on the same
// scene in headless Chromium with WebGPU on SwiftShader: each cascade's error as the crate
// measures it, and the shadows against a ray cast at sample pixels (bench.js). Serves web/ on
// 127.0.0.1 only (web/serve.mjs). Needs Debian's chromium and `npm install` in web/ (three,
// playwright-core).
import { writeFile } from 'node:fs/promises';
import { join } from 'node:path';
import { chromium } from 'playwright-core';
import { serve } from '../serve.mjs';

const { server, base } = await serve();
const out = [];
try {
  for (const query of (process.argv[2] ?? 'node=three,node=crate').split(',')) {
    // A browser per page: a page opened after another one closed lost its WebGPU device
    // ("A valid external Instance reference no longer exists") on SwiftShader.
    const browser = await chromium.launch({
      executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
      args: ['--headless', '--no-sandbox', '--enable-unsafe-webgpu', '--use-webgpu-adapter=swiftshader'],
    });
    const page = await browser.newPage({ viewport: { width: 960, height: 540 } });
    const errors = [];
    // Dawn on SwiftShader rejects one of three.js's WebGPU error scopes ("Instance dropped in
    // popErrorScope", uncaught in three.js) in about one page load of five, with three.js's own
    // node as with the crate's, the image unaffected; it is counted apart (docs/web.md). Any
    // other console error or page error fails the run.
    const dawn = [];
    page.on('console', (m) => {
      if (m.type() !== 'error') return;
      if (m.text() === 'OperationError: Instance dropped in popErrorScope') dawn.push(m.text());
      else errors.push(m.text());
    });
    page.on('pageerror', (e) => {
      if (String(e) === 'OperationError: Instance dropped in popErrorScope') dawn.push(String(e));
      else errors.push(String(e));
    });

    const t0 = Date.now();
    await page.goto(`${base}/three/bench.html?${query}`);
    await page.waitForFunction(() => window.bench !== undefined, null, { timeout: 240000 });
    const bench = await page.evaluate(() => window.bench);
    bench.seconds = (Date.now() - t0) / 1000;
    bench.consoleErrors = errors;
    bench.dawnPopErrorScope = dawn.length;
    if (process.env.SCREENSHOTS && !bench.error) {
      const url = await page.evaluate(() => window.benchImage);
      const name = `three-${query.replace(/node=/, '').replace(/[=&]/g, '-')}.png`;
      await writeFile(join(process.env.SCREENSHOTS, name), Buffer.from(url.split(',')[1], 'base64'));
    }
    out.push({ query, ...bench });
    await browser.close();
  }
} finally {
  server.close();
}
console.log(JSON.stringify(out, null, 1));

// The checks (any run): the page ran without an error; the crate's cascades report the error
// that the crate's measurement of the matrices three.js rendered with gives (the node handed
// them over unchanged); fewer than 1 % of the compared pixels disagree with the ray cast.
const failures = [];
for (const r of out) {
  if (r.error) failures.push(`${r.query}: ${r.error}`);
  if (r.consoleErrors.length) failures.push(`${r.query}: console errors ${JSON.stringify(r.consoleErrors)}`);
  if (r.crate) {
    r.crate.forEach((m, i) => {
      const e = r.cascades[i].max_error_pixels;
      if (!(Math.abs(e - m.max_error_pixels) <= 1e-9 * m.max_error_pixels)) {
        failures.push(`${r.query}: cascade ${i} reports ${m.max_error_pixels} px, its rendered matrix measures ${e}`);
      }
    });
  }
  const c = r.rayCast;
  if (c && !(c.disagree < 0.01 * (c.agree + c.disagree))) {
    failures.push(`${r.query}: ${c.disagree} of ${c.agree + c.disagree} pixels disagree with the ray cast`);
  }
}
if (failures.length) {
  console.error(failures.join('\n'));
  process.exit(1);
}
