// three.js cascades from shadow-aliasing: a CSMShadowNode whose cascades come from the crate's
// frame each frame (docs/web.md, "three.js"). The splits are the crate's (equal-error by
// default, or the per-frame controller's choice for an error budget), each cascade's matrix is
// fitted to the scene's receivers (any warp rule: the node divides by w), the bias comes from the
// map's footprint, and `errors` reports each cascade's measured error in pixels.
import { Vector2, Vector3, WebGLCoordinateSystem } from 'three/webgpu';
import { CSMShadowNode } from 'three/addons/csm/CSMShadowNode.js';
import { Controller, frame } from 'shadow-aliasing';

const _dir = new Vector3();

export class CrateCSMShadowNode extends CSMShadowNode {
  /**
   * @param light a DirectionalLight (its shadow's mapSize is each cascade's resolution)
   * @param data `cascades` (k, default 4), `receivers` and `casters` (Box3s; casters default to
   *   the receivers), `rule` ('uniform', 'lispsm', … default 'uniform'), `partition`
   *   ('equal-error' by default, or any of the crate's), `maxError` (pixels: the controller
   *   chooses the resolution, with cascades of this count and rule), `pcfRadius` (texels, 1),
   *   `imageHeight` (pixels; default the renderer's drawing-buffer height), `footprintBias`
   *   (true: each cascade's normal offset and depth bias from its footprint, `frame::bias`;
   *   false: the light shadow's own).
   */
  constructor(light, data = {}) {
    super(light, { cascades: data.cascades ?? 4, maxFar: Infinity });
    this.receivers = data.receivers;
    this.casters = data.casters ?? data.receivers;
    this.rule = data.rule ?? 'uniform';
    this.partition = data.partition ?? 'equal-error';
    this.pcfRadius = data.pcfRadius ?? 1;
    this.imageHeight = data.imageHeight ?? null;
    /** Whether the bias comes from the footprint (else the light shadow's own bias). */
    this.footprintBias = data.footprintBias ?? true;
    this.controller = null;
    if (data.maxError !== undefined) {
      this.controller = new Controller({
        max_error: data.maxError,
        max_maps: this.cascades,
        candidates: [this.scheme()],
      });
    }
    /** The crate's last frame (maps with their errors, splits, texel sizes, bias). */
    this.result = null;
    /** The last decision of the controller, when there is one. */
    this.decision = null;
  }

  scheme() {
    return { kind: 'cascades', rule: this.rule, partition: this.partition, k: this.cascades };
  }

  /** Each cascade's largest measured error, pixels per texel (the crate's). */
  get errors() {
    return this.result ? this.result.maps.map((m) => m.max_error_pixels) : [];
  }

  _init(builder) {
    super._init(builder);
    this.webGL = builder.renderer.coordinateSystem === WebGLCoordinateSystem;
    this.renderer = builder.renderer;
    for (const lw of this.lights) {
      const shadow = lw.shadow;
      // The crate's world → clip matrix as the shadow camera's projection, its view the
      // identity: the shadow pass and the lookup (shadow.matrix) both use it as it is.
      shadow.updateMatrices = function updateMatrices() {
        const cam = this.camera;
        if (!this.crateMatrix) return;
        cam.position.set(0, 0, 0);
        cam.quaternion.identity();
        cam.scale.set(1, 1, 1);
        cam.updateMatrixWorld(true);
        cam.projectionMatrix.fromArray(this.crateMatrix);
        cam.projectionMatrixInverse.copy(cam.projectionMatrix).invert();
        this._updateMatrix(cam, this.matrix, this._frustum);
      };
    }
  }

  // The splits and fits are the crate's, made each frame in updateBefore.
  updateFrustums() {
    this._getBreaks();
    this._initCascades();
    this._setLightBreaks();
  }

  input() {
    const camera = this.camera;
    camera.updateMatrixWorld();
    const light = this.light;
    _dir.subVectors(light.target.position, light.position).normalize();
    const height = this.imageHeight ?? this.renderer.getDrawingBufferSize(new Vector2()).y;
    return {
      world_to_eye: camera.matrixWorldInverse,
      near: camera.near,
      far: camera.far,
      half_fov: (camera.fov * Math.PI) / 360,
      aspect: camera.aspect,
      light_dir_world: _dir,
      receivers: this.receivers,
      casters: this.casters,
      map_resolution: light.shadow.mapSize.width,
      image_height: height,
      pcf_radius: this.pcfRadius,
      clip_depth: this.webGL ? 'neg-one-to-one' : 'zero-to-one',
      scheme: this.scheme(),
    };
  }

  updateBefore() {
    const light = this.light;
    for (const lw of this.lights) {
      if (lw.parent === null) {
        light.parent.add(lw.target);
        light.parent.add(lw);
      }
    }
    const input = this.input();
    if (this.controller) {
      this.decision = this.controller.frame(input);
      this.result = this.decision.frame;
    } else {
      this.result = frame(input);
    }
    const { near, far } = this.camera;
    const maps = this.result.maps;
    for (let i = 0; i < this.cascades; i++) {
      const shadow = this.lights[i].shadow;
      const m = maps[Math.min(i, maps.length - 1)];
      // three.js selects a cascade by (depth − near)/(far − near) in [x, y].
      const lo = i < maps.length ? (m.split[0] - near) / (far - near) : 2;
      const hi = i < maps.length ? (m.split[1] - near) / (far - near) : 2;
      this._cascades[i].set(lo, hi);
      shadow.crateMatrix = m.world_to_clip;
      if (this.footprintBias) {
        shadow.normalBias = m.bias.normal_offset;
        shadow.bias = m.bias.constant_depth;
      }
      if (this.decision) shadow.mapSize.set(this.decision.resolution, this.decision.resolution);
    }
  }

  dispose() {
    this.controller?.free();
    super.dispose();
  }
}
