// shadow-aliasing for JavaScript: the Rust crate's frame, per-frame controller, error lens and
// closed forms, compiled to WebAssembly (docs/web.md). Types: index.d.ts.
//
// The module answers JSON requests through four raw exports (web/src/abi.rs); this file turns
// arguments into requests (three.js's Vector3, Box3 and Matrix4 included), answers into objects
// with typed arrays, and errors into ShadowAliasingError exceptions with the crate's messages.

let wasm = null;
const encoder = new TextEncoder();
const decoder = new TextDecoder();

/** An error of the crate (or of a request), thrown with the crate's own message. */
export class ShadowAliasingError extends Error {
  constructor(kind, argument, message) {
    super(message);
    this.name = 'ShadowAliasingError';
    /** "InvalidArgument", "NoSolution", "NoClosedForm", "Degenerate" or "Request". */
    this.kind = kind;
    /** The argument named by an InvalidArgument error, else null. */
    this.argument = argument ?? null;
  }
}

/** Loads the module: from `source` (bytes, a Response, a URL) or the package's own file. */
export async function init(source) {
  if (wasm) return;
  let bytes = source;
  if (bytes === undefined) {
    const url = new URL('./shadow_aliasing.wasm', import.meta.url);
    if (url.protocol === 'file:') {
      const fs = await import('node:fs/promises');
      bytes = await fs.readFile(url);
    } else {
      bytes = url;
    }
  }
  if (typeof bytes === 'string' || bytes instanceof URL) {
    bytes = await fetch(bytes);
  }
  if (typeof Response !== 'undefined' && bytes instanceof Response) {
    if (!bytes.ok) {
      throw new Error(`shadow-aliasing: loading ${bytes.url} failed: HTTP ${bytes.status}`);
    }
    bytes = await bytes.arrayBuffer();
  }
  const { instance } = await WebAssembly.instantiate(bytes, {});
  wasm = instance.exports;
}

/** Loads the module from its bytes, synchronously. */
export function initSync(bytes) {
  if (wasm) return;
  wasm = new WebAssembly.Instance(new WebAssembly.Module(bytes), {}).exports;
}

// Arguments to JSON: typed arrays as arrays, three.js vectors, boxes and matrices as the crate
// reads them, non-finite numbers as strings (JSON has none; the crate names them in its errors).
function replacer(_key, v) {
  if (typeof v === 'number') return Number.isFinite(v) ? v : String(v);
  if (v !== null && typeof v === 'object') {
    if (ArrayBuffer.isView(v)) return Array.from(v);
    if (v.isVector3) return [v.x, v.y, v.z];
    if (v.isMatrix4) return Array.from(v.elements);
    if (v.isBox3) return { min: v.min, max: v.max };
  }
  return v;
}

// The module writes non-finite numbers as the strings "NaN", "Infinity", "-Infinity";
// Number() reads them back. Applied to the numeric fields alone (a JSON.parse reviver would
// visit every value and cost more than the frame itself).
const num = (v) => (typeof v === 'number' ? v : v === null ? v : Number(v));
const f64 = (a) => Float64Array.from(a, num);
function numbers(o) {
  for (const k of Object.keys(o)) {
    const v = o[k];
    if (typeof v === 'string' && (v === 'NaN' || v === 'Infinity' || v === '-Infinity')) o[k] = Number(v);
    else if (Array.isArray(v) && v.length > 0 && typeof v[0] !== 'object') o[k] = v.map(num);
  }
  return o;
}

/** One request to the module: its answer, or a ShadowAliasingError. */
export function call(fn, args = {}) {
  if (!wasm) {
    throw new Error('shadow-aliasing: the module is not loaded: await init() first');
  }
  const bytes = encoder.encode(JSON.stringify({ ...args, fn }, replacer));
  const ptr = wasm.saw_alloc(bytes.length) >>> 0;
  new Uint8Array(wasm.memory.buffer, ptr, bytes.length).set(bytes);
  const status = wasm.saw_call(ptr, bytes.length);
  const out = new Uint8Array(wasm.memory.buffer, wasm.saw_out_ptr() >>> 0, wasm.saw_out_len() >>> 0);
  const answer = JSON.parse(decoder.decode(out));
  if (status !== 0) {
    const e = answer.error;
    throw new ShadowAliasingError(e.kind, e.name, e.message);
  }
  return answer.ok;
}

function typedMap(m) {
  numbers(m);
  numbers(m.bias);
  m.world_to_clip = f64(m.world_to_clip);
  m.world_to_clip_f32 = Float32Array.from(m.world_to_clip_f32, num);
  m.eye_to_clip = f64(m.eye_to_clip);
  m.body = f64(m.body);
  m.casters_volume = f64(m.casters_volume);
  m.receivers_volume = f64(m.receivers_volume);
  return m;
}

function typedFrame(f) {
  numbers(f);
  f.light_dir_eye = f64(f.light_dir_eye);
  f.maps.forEach(typedMap);
  return f;
}

/** The frame's maps for one light (the crate's `frame::frame`). */
export function frame(input) {
  return typedFrame(call('frame', { input }));
}

/**
 * The error lens of map `map` of the frame of `input` at world points (3 numbers each) with
 * surface normals (3 numbers for all, or 3 per point): texel size in screen pixels.
 */
export function errorLens(input, points, normals, map = 0) {
  const r = call('error_lens', { input, points, normals, map });
  const n = r.values.length;
  const values = new Float64Array(n);
  const valid = new Uint8Array(n);
  for (let i = 0; i < n; i++) {
    const v = num(r.values[i]);
    values[i] = v === null ? NaN : v;
    valid[i] = v === null ? 0 : 1;
  }
  return { values, valid, reasons: r.reasons };
}

/**
 * The crate's measurement of any world → clip matrix (another engine's cascade) over the view
 * slice `cover` = [z0, z1] ∩ the receivers: {max_error_pixels, max_mx, max_mz, storage_factor}
 * at the input's map_resolution (its map_resolutions are not read), or null where the slice
 * holds no receiver.
 */
export function measureMap(input, cover, worldToClip) {
  const r = call('measure_map', { input, cover, world_to_clip: worldToClip });
  return r === null ? null : numbers(r);
}

/** The lens ramp's sRGB colour of a lens value (pixels), each channel in [0, 1]. */
export function lensColour(value) {
  return call('lens_colour', { value });
}

/** The crate's version. */
export function version() {
  return call('version');
}

const registry =
  typeof FinalizationRegistry !== 'undefined'
    ? new FinalizationRegistry((id) => {
        try {
          call('controller_free', { id });
        } catch {
          // Freed already.
        }
      })
    : null;

/** The per-frame controller (`plan::Controller`): one target error or texel budget in, each
 * frame the set-up it chose with its maps. */
export class Controller {
  constructor(options) {
    this.id = call('controller_new', { options }).id;
    this.freed = false;
    registry?.register(this, this.id, this);
  }

  /** The decision for this frame (the input's scheme, map_resolution and map_resolutions are the
   * controller's to choose). */
  frame(input) {
    const d = numbers(call('controller_frame', { id: this.id, input }));
    d.frame = typedFrame(d.frame);
    return d;
  }

  /** The next frame searches afresh (a camera cut). */
  cut() {
    call('controller_cut', { id: this.id });
  }

  /** Frees the controller now (it is also freed when collected). */
  free() {
    if (this.freed) return;
    registry?.unregister(this);
    call('controller_free', { id: this.id });
    this.freed = true;
  }
}

function closedForm(name) {
  return (args) => {
    const v = call('closed', { name, args });
    return Array.isArray(v) ? f64(v) : num(v);
  };
}

/** The papers' closed forms, the light overhead (Lloyd et al. 2006). */
export const closed = {
  mx: closedForm('mx'),
  mz: closedForm('mz'),
  storageFactor: closedForm('storage_factor'),
  nPrimeLispsm: closedForm('n_prime_lispsm'),
  nPrimeFromEta: closedForm('n_prime_from_eta'),
  etaFromNPrime: closedForm('eta_from_n_prime'),
};
