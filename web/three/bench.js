// The same scene with three.js's own CSMShadowNode (?node=three) or the crate's cascades
// (?node=crate, CrateCSMShadowNode.js): renders once, reads the image back, and leaves in
// window.bench each cascade's error as the crate measures it, and the rendered shadow against a
// ray cast at sample pixels. web/three/run.mjs drives it in headless Chromium.
import * as THREE from 'three/webgpu';
import { CSMShadowNode } from 'three/addons/csm/CSMShadowNode.js';
import { init, measureMap } from 'shadow-aliasing';
import { CrateCSMShadowNode } from './CrateCSMShadowNode.js';

const params = new URLSearchParams(location.search);
const which = params.get('node') ?? 'crate';
const rule = params.get('rule') ?? 'uniform';
const [W, H] = [960, 540];
const K = 4;
const RES = Number(params.get('res') ?? 1024);

try {
  await init();
  const renderer = new THREE.WebGPURenderer({ antialias: false });
  renderer.setPixelRatio(1);
  renderer.setSize(W, H);
  renderer.shadowMap.enabled = true;
  renderer.shadowMap.type = THREE.BasicShadowMap;
  document.body.appendChild(renderer.domElement);
  await renderer.init();

  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x000000);
  const camera = new THREE.PerspectiveCamera(60, W / H, 0.5, 300);
  camera.position.set(0, 8, 30);
  camera.lookAt(0, 0, -40);
  camera.updateMatrixWorld();

  const material = new THREE.MeshLambertMaterial({ color: 0xffffff });
  const ground = new THREE.Mesh(new THREE.BoxGeometry(400, 1, 400), material);
  ground.position.set(0, -0.5, 0);
  ground.receiveShadow = true;
  ground.castShadow = true;
  scene.add(ground);
  // Boxes [min, max], as the ray cast below sees them.
  const boxes = [[-200, -1, -200, 200, 0, 200]];
  const posts = [
    [-6, 0, 10, 1, 6, 1], [4, 0, 0, 2, 3, 2], [-3, 0, -20, 1, 8, 6], [10, 0, -45, 6, 5, 1],
    [-14, 0, -70, 2, 12, 2], [2, 0, -110, 8, 6, 8], [20, 0, -160, 3, 15, 3], [-30, 0, -220, 10, 10, 2],
  ];
  for (const [x, y, z, sx, sy, sz] of posts) {
    const m = new THREE.Mesh(new THREE.BoxGeometry(sx, sy, sz), material);
    m.position.set(x, y + sy / 2, z);
    m.castShadow = true;
    m.receiveShadow = true;
    scene.add(m);
    boxes.push([x - sx / 2, y, z - sz / 2, x + sx / 2, y + sy, z + sz / 2]);
  }
  scene.updateMatrixWorld();
  const bounds = [new THREE.Box3(new THREE.Vector3(-200, -1, -200), new THREE.Vector3(200, 15, 200))];

  scene.add(new THREE.AmbientLight(0xffffff, 0.25));
  const light = new THREE.DirectionalLight(0xffffff, 1.0);
  light.position.set(40, 20, 10);
  light.target.position.set(0, 0, 0);
  light.castShadow = true;
  light.shadow.mapSize.set(RES, RES);
  scene.add(light, light.target);
  light.updateMatrixWorld();
  light.target.updateMatrixWorld();

  const node =
    which === 'three'
      ? new CSMShadowNode(light, { cascades: K, maxFar: camera.far, mode: 'practical', lightMargin: 100 })
      : new CrateCSMShadowNode(light, {
          cascades: K, receivers: bounds, casters: bounds, rule, imageHeight: H,
          maxError: params.has('maxError') ? Number(params.get('maxError')) : undefined,
          footprintBias: params.get('bias') !== 'light',
        });
  if (which === 'three') light.shadow.bias = -0.0005;
  light.shadow.shadowNode = node;

  const rt = new THREE.RenderTarget(W, H, { samples: 0 });
  renderer.setRenderTarget(rt);
  renderer.render(scene, camera);
  renderer.render(scene, camera); // the cascades' placement settles after the first frame
  const pixels = await renderer.readRenderTargetPixelsAsync(rt, 0, 0, W, H);
  renderer.setRenderTarget(null);
  renderer.render(scene, camera);

  // Each cascade's world → clip matrix and the view depths it is selected for.
  const near = camera.near;
  const far = camera.far;
  const input = {
    world_to_eye: camera.matrixWorldInverse,
    near, far, half_fov: (camera.fov * Math.PI) / 360, aspect: camera.aspect,
    light_dir_world: new THREE.Vector3().subVectors(light.target.position, light.position),
    receivers: bounds, casters: bounds, map_resolution: node.decision ? node.decision.resolution : RES,
    image_height: H,
  };
  const cascades = node.lights.map((lw, i) => {
    const cam = lw.shadow.camera;
    const m = new THREE.Matrix4().multiplyMatrices(cam.projectionMatrix, cam.matrixWorldInverse);
    const c = node._cascades[i];
    const cover = [near + (far - near) * c.x, near + (far - near) * c.y];
    const e = measureMap(input, cover, m.elements);
    return { cover, max_error_pixels: e ? e.max_error_pixels : null };
  });

  // The rendered shadow against a ray cast at sample pixels: the surface the eye ray hits first,
  // then whether a ray from it toward the light meets a box. A lit pixel is brighter than the
  // ambient term alone by N·L/π; pixels with N·L < 0.3 (dim even when lit) are skipped.
  const toLight = new THREE.Vector3().subVectors(light.position, light.target.position).normalize();
  const hit = (o, d, skip) => {
    let best = null;
    for (let b = 0; b < boxes.length; b++) {
      if (b === skip) continue;
      const bx = boxes[b];
      let t0 = 0, t1 = Infinity, axis = -1, sign = 0;
      for (let a = 0; a < 3; a++) {
        const oa = o.getComponent(a), da = d.getComponent(a);
        if (Math.abs(da) < 1e-12) { if (oa < bx[a] || oa > bx[a + 3]) { t0 = Infinity; break; } continue; }
        let ta = (bx[a] - oa) / da, tb = (bx[a + 3] - oa) / da, s = -1;
        if (ta > tb) { [ta, tb] = [tb, ta]; s = 1; }
        if (ta > t0) { t0 = ta; axis = a; sign = s; }
        t1 = Math.min(t1, tb);
      }
      if (t0 <= t1 && t0 > 1e-6 && (best === null || t0 < best.t)) best = { t: t0, b, axis, sign };
    }
    return best;
  };
  const invProj = camera.projectionMatrixInverse;
  let [agree, disagree, skipped, inShadow] = [0, 0, 0, 0];
  const mismatches = [];
  for (let py = 3; py < H; py += 6) {
    for (let px = 3; px < W; px += 6) {
      const ndc = new THREE.Vector3(((px + 0.5) / W) * 2 - 1, 1 - ((py + 0.5) / H) * 2, 0.5);
      const dir = ndc.applyMatrix4(invProj).applyMatrix4(camera.matrixWorld).sub(camera.position).normalize();
      const h = hit(camera.position, dir, -1);
      if (!h) { skipped++; continue; }
      const p = camera.position.clone().addScaledVector(dir, h.t);
      const n = new THREE.Vector3();
      n.setComponent(h.axis, h.sign);
      const ndl = n.dot(toLight);
      if (ndl < 0.3 || h.t > far) { skipped++; continue; }
      const shadowed = hit(p.clone().addScaledVector(n, 1e-4), toLight, -1) !== null;
      if (shadowed) inShadow++;
      // The render target's rows: WebGPU's first row is the top.
      const r = pixels[4 * (py * W + px)] / 255;
      // Lambert in three.js: (ambient + N·L) · albedo / π; the ambient term alone in shadow.
      const renderedShadow = r < (0.25 + ndl / 2) / Math.PI;
      if (renderedShadow === shadowed) agree++;
      else { disagree++; if (mismatches.length < 20) mismatches.push([px, py, shadowed, r]); }
    }
  }
  // The image read back, for the screenshots (run.mjs with SCREENSHOTS).
  const c2 = document.createElement('canvas');
  [c2.width, c2.height] = [W, H];
  const img = new ImageData(W, H);
  for (let i = 0; i < W * H; i++) {
    for (let ch = 0; ch < 3; ch++) img.data[4 * i + ch] = pixels[4 * i + ch];
    img.data[4 * i + 3] = 255;
  }
  c2.getContext('2d').putImageData(img, 0, 0);
  window.benchImage = c2.toDataURL('image/png');
  window.bench = {
    node: which,
    rule,
    cascades,
    crate: node.result ? node.result.maps.map((m) => ({ split: m.split, max_error_pixels: m.max_error_pixels })) : null,
    rayCast: { agree, disagree, skipped, inShadow, mismatches },
    resolution: node.decision ? node.decision.resolution : RES,
  };
} catch (e) {
  window.bench = { error: String(e && e.stack ? e.stack : e) };
}
