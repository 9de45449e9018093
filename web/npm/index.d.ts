// Types of shadow-aliasing's JavaScript API (index.js; docs/web.md).

/** Three numbers, or a three.js Vector3. */
export type Vec3 = readonly [number, number, number] | ArrayLike<number> | { x: number; y: number; z: number; isVector3: true };

/** A world-space box, or a three.js Box3. */
export type Box = { min: Vec3; max: Vec3 };

/** A warp rule: its name, or an object with its parameter. */
export type Rule =
  | 'uniform' | 'psm' | 'lispsm' | 'lispsm-fixed' | 'lispsm-reference' | 'barroso'
  | 'barroso-zhang' | 'minimax' | 'minimax-mz' | 'filament' | 'ogre' | 'tsm' | 'ogre-ortho'
  | { name: 'eta'; eta: number }
  | { name: 'tsm'; focus?: number }
  | { name: 'filament'; near_hint: number; far_hint: number }
  | { name: 'ogre-ortho'; shadow_distance?: number };

/** Bevy's CascadeShadowConfigBuilder fields. */
export interface BevySplits {
  num_cascades: number;
  minimum_distance: number;
  maximum_distance: number;
  first_cascade_far_bound: number;
  overlap_proportion: number;
}

/** How cascades split the view: one of partition (with k), splits, fractions or bevy. */
export interface SplitFields {
  partition?: 'log' | 'self-similar' | 'uniform' | 'practical' | 'adaptive' | 'exponent' | 'equal-error';
  k?: number;
  lambda?: number;
  exponent?: number;
  splits?: ArrayLike<number>;
  fractions?: ArrayLike<number>;
  bevy?: BevySplits;
  overlap?: number;
}

/** Every scheme of the crate's frame. */
export type Scheme =
  | { kind: 'single'; rule?: Rule }
  | ({ kind: 'cascades'; rule?: Rule } & SplitFields)
  | ({ kind: 'stable' } & SplitFields)
  | { kind: 'tsm'; focus?: number; xi?: number; iterative?: number; exhaustive?: boolean }
  | { kind: 'faces'; rule?: 'uniform' | 'psm' | 'lispsm'; k: number }
  | {
      kind: 'clipmap';
      first_level?: number;
      last_level?: number;
      lod_bias?: number;
      unit?: number;
      page_texels?: number;
    };

/** One light's frame: the camera, the light, the scene's bounds and the scheme. */
export interface FrameInput {
  /** World → eye, 16 numbers column-major (three.js camera.matrixWorldInverse), or a Matrix4. */
  world_to_eye: ArrayLike<number> | { elements: ArrayLike<number>; isMatrix4: true };
  near: number;
  far: number;
  /** Half the vertical field of view, radians. */
  half_fov: number;
  /** Width over height (default 1). */
  aspect?: number;
  /** The direction light travels, world space. */
  light_dir_world: Vec3;
  /** The receivers' boxes (absent: unbounded). */
  receivers?: Box[];
  /** The casters' boxes (absent: unbounded; empty: none). */
  casters?: Box[];
  depth_range?: readonly [number, number];
  depth_clamp?: boolean;
  /** Measure each map's error (default true). */
  measure?: boolean;
  /** Texels per map side (default 2048). */
  map_resolution?: number;
  /** Each partition's own texels per side, in slot order (cascade i, face part i, the single
   * map's slot 0), instead of map_resolution for all (not with a clipmap). A Decision's
   * resolutions. The controller ignores it. */
  map_resolutions?: ArrayLike<number>;
  /** Image height in pixels (default 2048). */
  image_height?: number;
  /** PCF radius in texels, for the bias values (default 0). */
  pcf_radius?: number;
  /** Default "neg-one-to-one" (WebGL); WebGPU is "zero-to-one". */
  clip_depth?: 'neg-one-to-one' | 'zero-to-one' | 'reversed';
  centre?: 'rule' | 'eye' | 'nearest-vertex';
  /** Default a single minimax map. */
  scheme?: Scheme;
}

/** The footprint's bias values of one map (frame::bias). */
export interface Bias {
  normal_offset: number;
  slope_scaled_depth: number;
  constant_depth: number;
  texel_extent: [number, number];
}

/** One shadow map of a frame. */
export interface FrameMap {
  /** The slot (cascade index, face, level). */
  slot: number;
  /** World → light clip, column-major (three.js Matrix4.elements order). */
  world_to_clip: Float64Array;
  /** The same in f32, for the GPU. */
  world_to_clip_f32: Float32Array;
  /** Eye → light clip, column-major. */
  eye_to_clip: Float64Array;
  n_prime: number;
  depth: [number, number];
  /** The eye depths this map is selected for. */
  split: [number, number];
  blend: [number, number];
  /** World size of a texel at the body. */
  texel_world: number;
  max_mx: number;
  max_mz: number;
  storage_factor: number;
  /** The largest perspective aliasing error over the focus body, pixels per texel. */
  max_error_pixels: number;
  /** The map's texels per side. */
  resolution: number;
  bias: Bias;
  focus: string;
  face: string | null;
  clipmap_level: number | null;
  /** The focus body's vertices, eye space, 3 numbers each. */
  body: Float64Array;
  /** World planes (a, b, c, d), inside where a x + b y + c z + d ≤ 0. */
  casters_volume: Float64Array;
  receivers_volume: Float64Array;
}

export interface Frame {
  focus: string;
  light: string;
  light_dir_eye: Float64Array;
  /** The frame's storage factor, null when not every map is measured. */
  storage_factor: number | null;
  maps: FrameMap[];
}

export interface ErrorLens {
  /** Pixels per texel at each point; NaN where `valid` is 0. */
  values: Float64Array;
  valid: Uint8Array;
  /** The crate's message at each invalid point, else null. */
  reasons: (string | null)[];
}

export interface ControllerOptions {
  /** The target error, pixels. */
  max_error?: number;
  /** A texel budget for all maps together. */
  max_texels?: number;
  max_maps?: number;
  rounding?: 'whole' | 'power-of-two' | { multiple: number };
  max_resolution?: number;
  /** Every map at one resolution (default true); false: each map its own, sized by its own
   * error. */
  shared_resolution?: boolean;
  candidates?: Scheme[];
  patience?: number;
  margin?: number;
  neighbour_every?: number;
  retry_every?: number;
  cut_move?: number;
  cut_turn?: number;
  cut_light?: number;
}

export interface Decision {
  /** The set-up chosen, in the form FrameInput.scheme takes. */
  scheme: Scheme;
  /** The largest map's texels per side (every map's with a shared resolution). */
  resolution: number;
  /** Each slot's texels per side, in slot order: FrameInput.map_resolutions for these maps. */
  resolutions: number[];
  max_error_pixels: number;
  /** The maps' texels together (the sum of each map's resolution²). */
  texels: number;
  meets_target: boolean;
  within_budget: boolean;
  switched: boolean;
  cut: boolean;
  frame: Frame;
}

export class ShadowAliasingError extends Error {
  readonly kind: 'InvalidArgument' | 'NoSolution' | 'NoClosedForm' | 'Degenerate' | 'Request';
  readonly argument: string | null;
}

export function init(source?: BufferSource | Response | URL | string): Promise<void>;
export function initSync(bytes: BufferSource): void;
export function call(fn: string, args?: object): unknown;
export function frame(input: FrameInput): Frame;
export function errorLens(
  input: FrameInput,
  points: ArrayLike<number>,
  normals: ArrayLike<number>,
  map?: number,
): ErrorLens;
export interface MapError {
  max_error_pixels: number;
  max_mx: number;
  max_mz: number;
  storage_factor: number;
}
/** The crate's measurement of any world → clip matrix over the view slice `cover` ∩ receivers, at
 * the input's map_resolution (its map_resolutions are not read). */
export function measureMap(
  input: FrameInput,
  cover: readonly [number, number],
  worldToClip: ArrayLike<number> | { elements: ArrayLike<number>; isMatrix4: true },
): MapError | null;
export function lensColour(value: number): [number, number, number];
export function version(): string;

export class Controller {
  constructor(options: ControllerOptions);
  readonly id: number;
  frame(input: FrameInput): Decision;
  cut(): void;
  free(): void;
}

/** n′: a number, Infinity for the uniform map. */
export const closed: {
  mx(args: { near: number; far: number; n_prime: number; z: number; res_image?: number; res_s?: number }): number;
  mx(args: { near: number; far: number; n_prime: number; z: ArrayLike<number>; res_image?: number; res_s?: number }): Float64Array;
  mz(args: { near: number; far: number; half_fov: number; n_prime: number; z: number; res_image?: number; res_t?: number }): number;
  mz(args: { near: number; far: number; half_fov: number; n_prime: number; z: ArrayLike<number>; res_image?: number; res_t?: number }): Float64Array;
  storageFactor(args: { near: number; far: number; half_fov: number; n_prime: number }): number;
  nPrimeLispsm(args: { near: number; far: number }): number;
  nPrimeFromEta(args: { near: number; far: number; eta: number }): number;
  etaFromNPrime(args: { near: number; far: number; n_prime: number }): number;
};
