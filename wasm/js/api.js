// The JavaScript API over the Embind module (bindings.cpp): argument checks, defaults, errors,
// and one wasm instance per API object. Shared by every entry point (index.js for browsers and
// bundlers, node.js, single.js); each entry supplies how to get the compiled
// WebAssembly.Module, this file does the rest. The names of modes, fill rules, formats and
// statuses, and the options' defaults, come from the core (core_vocabulary, exported as
// `vocabulary`): none is written here.
import { checkKeys, searchAsked, MESH_OPTION_KEYS, INIT_OPTION_KEYS } from './keys.js';

/** Errors from acutemesh itself; `code` says what kind (see index.d.ts). */
export class AcuteMeshError extends Error {
  constructor(code, message) {
    super(message);
    this.name = 'AcuteMeshError';
    this.code = code;
  }
}

const WASM_PAGE = 65536;
const INITIAL_MEMORY = 16 * 1024 * 1024;  // -sINITIAL_MEMORY in wasm/CMakeLists.txt

const utf8 = new TextEncoder();  // texts go to wasm as UTF-8 bytes (see bindings.cpp)

const describe = (v) => (v === null ? 'null' : Array.isArray(v) ? 'an array' : typeof v);

function badInput(message) {
  return new AcuteMeshError('BAD_INPUT', message);
}

function abortError(signal) {
  if (signal && signal.reason !== undefined) return signal.reason;
  return new DOMException('The operation was aborted', 'AbortError');
}

// --- argument conversion ------------------------------------------------------------------

// Coordinates: a Float64Array as is; any other typed array or an array of numbers copied; an
// array of [x, y] pairs flattened. Non-numbers are TypeErrors naming the item; non-finite
// numbers pass through (the core reports them as BAD_INPUT with the vertex index).
function toCoordinates(value, what) {
  if (value instanceof Float64Array) return value;
  if (ArrayBuffer.isView(value) && !(value instanceof DataView)) return Float64Array.from(value);
  if (!Array.isArray(value))
    throw new TypeError(`${what} must be a Float64Array or an array of numbers, not ${describe(value)}`);
  if (value.length > 0 && Array.isArray(value[0])) {
    const out = new Float64Array(2 * value.length);
    for (let i = 0; i < value.length; ++i) {
      const p = value[i];
      if (!Array.isArray(p) || typeof p[0] !== 'number' || typeof p[1] !== 'number')
        throw new TypeError(`${what}[${i}] must be an [x, y] pair of numbers`);
      // [x, y, z] would otherwise be meshed as its projection without a word.
      if (p.length !== 2)
        throw new TypeError(`${what}[${i}] has ${p.length} numbers; a point is an [x, y] pair (the mesh is planar)`);
      out[2 * i] = p[0];
      out[2 * i + 1] = p[1];
    }
    return out;
  }
  return toNumbers(value, what);
}

// Numbers (a typed array or an array of numbers) as a Float64Array.
function toNumbers(value, what) {
  if (value instanceof Float64Array) return value;
  if (ArrayBuffer.isView(value) && !(value instanceof DataView)) return Float64Array.from(value);
  if (!Array.isArray(value))
    throw new TypeError(`${what} must be a Float64Array or an array of numbers, not ${describe(value)}`);
  for (let i = 0; i < value.length; ++i)
    if (typeof value[i] !== 'number')
      throw new TypeError(`${what}[${i}] must be a number, not ${describe(value[i])}`);
  return Float64Array.from(value);
}

// Indices: a Uint32Array as is; other arrays (flat, or of [a, b] / [a, b, c] tuples) checked
// item by item, since a Uint32Array would silently wrap -1 or 2.5 into another vertex.
function toIndices(value, what, arity) {
  if (value instanceof Uint32Array) return value;
  let flat = value;
  if (Array.isArray(value) && value.length > 0 && Array.isArray(value[0])) {
    flat = new Array(arity * value.length);
    for (let i = 0; i < value.length; ++i) {
      const t = value[i];
      if (!Array.isArray(t) || t.length !== arity)
        throw new TypeError(`${what}[${i}] must be an array of ${arity} vertex indices`);
      for (let k = 0; k < arity; ++k) flat[arity * i + k] = t[k];
    }
  } else if (!Array.isArray(value) && !(ArrayBuffer.isView(value) && !(value instanceof DataView))) {
    throw new TypeError(`${what} must be a Uint32Array or an array of vertex indices, not ${describe(value)}`);
  }
  const out = new Uint32Array(flat.length);
  for (let i = 0; i < flat.length; ++i) {
    const v = flat[i];
    if (typeof v !== 'number' && typeof v !== 'bigint')
      throw new TypeError(`${what}[${i}] must be a vertex index (a number), not ${describe(v)}`);
    const n = Number(v);
    if (!Number.isInteger(n) || n < 0 || n > 0xffffffff)
      throw badInput(`${what}[${i}] is ${v}, not a vertex index (an integer >= 0)`);
    out[i] = n;
  }
  return out;
}

// Boundary markers: an Int32Array as is; other arrays checked item by item (an Int32Array
// would silently wrap 2^31 or truncate 2.5 into another marker).
function toMarkers(value, what) {
  if (value instanceof Int32Array) return value;
  if (!Array.isArray(value) && !(ArrayBuffer.isView(value) && !(value instanceof DataView)))
    throw new TypeError(`${what} must be an Int32Array or an array of integers, not ${describe(value)}`);
  const out = new Int32Array(value.length);
  for (let i = 0; i < value.length; ++i) {
    const v = value[i];
    if (typeof v !== 'number' && typeof v !== 'bigint')
      throw new TypeError(`${what}[${i}] must be a marker (a number), not ${describe(v)}`);
    const n = Number(v);
    if (!Number.isInteger(n) || n < -0x80000000 || n > 0x7fffffff)
      throw badInput(`${what}[${i}] is ${v}, not a marker (a 32-bit integer)`);
    out[i] = n;
  }
  return out;
}

const REGION_KEYS = ['x', 'y', 'attribute', 'maxArea'];

// MeshResult's arrays with options.adjacency (Adjacency in acutemesh.h).
export const ADJACENCY_KEYS = ['halfedges', 'neighbors', 'edges', 'edgeMarkers', 'hull', 'hullStarts'];

// Regions [{ x, y, attribute, maxArea? }] into the Float64Array the module takes: x, y,
// attribute, maxArea (0: none) per region. Values must be numbers; the core checks that they
// are finite (and maxArea >= 0), naming the region.
function toRegions(value, what) {
  if (!Array.isArray(value))
    throw new TypeError(`${what} must be an array of { x, y, attribute, maxArea? }, not ${describe(value)}`);
  const out = new Float64Array(4 * value.length);
  value.forEach((r, i) => {
    checkObject(r, `${what}[${i}]`);
    checkKeys(r, REGION_KEYS, `${what}[${i}]`);
    REGION_KEYS.forEach((key, k) => {
      const v = r[key];
      if (v === undefined && (key === 'maxArea' || key === 'attribute')) return;
      if (typeof v !== 'number')
        throw new TypeError(`${what}[${i}].${key} must be a number, not ${describe(v)}`);
      out[4 * i + k] = v;
    });
  });
  return out;
}

// The module's regions (x, y, attribute, maxArea per region) as the API gives them.
function fromRegions(flat) {
  const regions = [];
  for (let i = 0; i + 3 < flat.length; i += 4)
    regions.push({ x: flat[i], y: flat[i + 1], attribute: flat[i + 2], maxArea: flat[i + 3] });
  return regions;
}

function checkObject(value, what) {
  if (typeof value !== 'object' || value === null || Array.isArray(value))
    throw new TypeError(`${what} must be an object, not ${describe(value)}`);
}

// `names` checks names against the core's vocabulary (makeNames below).
function toPslg(pslg, names, what = 'pslg') {
  checkObject(pslg, what);
  if (pslg.points === undefined) throw new TypeError(`${what}.points is missing`);
  return {
    points: toCoordinates(pslg.points, `${what}.points`),
    segments: pslg.segments == null ? new Uint32Array(0) : toIndices(pslg.segments, `${what}.segments`, 2),
    holes: pslg.holes == null ? new Float64Array(0) : toCoordinates(pslg.holes, `${what}.holes`),
    // Markers and regions, as the module takes them (bindings.cpp, pslgFromJs).
    labels: {
      vertexMarkers: pslg.vertexMarkers == null ? new Int32Array(0) : toMarkers(pslg.vertexMarkers, `${what}.vertexMarkers`),
      segmentMarkers: pslg.segmentMarkers == null ? new Int32Array(0) : toMarkers(pslg.segmentMarkers, `${what}.segmentMarkers`),
      regions: pslg.regions == null ? new Float64Array(0) : toRegions(pslg.regions, `${what}.regions`),
    },
    fill: pslg.fill,
    // What a parser read it from (ParsedPslg.format): the core's input policy applies to it.
    format: names.check(pslg.format, 'inputFormat', `${what}.format`, undefined),
  };
}

// A mesh as mesh() returns it (or any object with points and triangles), for the writers
// and validate().
function toMesh(m, what = 'mesh') {
  checkObject(m, what);
  if (m.points === undefined) throw new TypeError(`${what}.points is missing`);
  if (m.triangles === undefined) throw new TypeError(`${what}.triangles is missing`);
  const mesh = {
    points: toCoordinates(m.points, `${what}.points`),
    triangles: toIndices(m.triangles, `${what}.triangles`, 3),
    segments: m.segments == null ? new Uint32Array(0) : toIndices(m.segments, `${what}.segments`, 2),
    vertexKind: m.vertexKind instanceof Uint8Array ? m.vertexKind : new Uint8Array(0),
    exactPoints: toExactPoints(m.exactPoints, `${what}.exactPoints`),
    // Markers and region attributes for the writers, as mesh() returns them; the writers use
    // an array only when it has one entry per item (else Triangle's defaults, no attributes).
    vertexMarkers: m.vertexMarkers instanceof Int32Array ? m.vertexMarkers : new Int32Array(0),
    segmentMarkers: m.segmentMarkers instanceof Int32Array ? m.segmentMarkers : new Int32Array(0),
    triangleAttributes:
      m.triangleAttributes instanceof Float64Array ? m.triangleAttributes : new Float64Array(0),
  };
  // The labels mesh() returns, for the writers that carry them (kept when of their type).
  for (const [key, type] of [['segmentInput', Uint32Array], ['vertexMarkers', Int32Array],
    ['segmentMarkers', Int32Array], ['triangleAttributes', Float64Array]])
    if (m[key] instanceof type) mesh[key] = m[key];
  return mesh;
}

// A mesh's exact points (options.exactFeet): [{ vertex, x, y }] with rationals "p/q" or "p".
function toExactPoints(list, what) {
  if (list == null) return [];
  if (!Array.isArray(list)) throw new TypeError(`${what} must be an array, not ${describe(list)}`);
  const rational = /^-?\d+(\/[1-9]\d*)?$/;
  return list.map((p, i) => {
    checkObject(p, `${what}[${i}]`);
    if (!Number.isInteger(p.vertex) || p.vertex < 0 || p.vertex > 0xffffffff)
      throw badInput(`${what}[${i}].vertex must be a vertex index, not ${describe(p.vertex)}`);
    for (const key of ['x', 'y'])
      if (typeof p[key] !== 'string' || !rational.test(p[key]))
        throw badInput(`${what}[${i}].${key} must be a rational "p/q" or "p", not ${describe(p[key])}`);
    return { vertex: p.vertex, x: p.x, y: p.y };
  });
}

// The writers index points by the triangles and segments: check every index first, so a bad
// mesh is a BAD_INPUT naming the item rather than garbage read from the wasm heap.
function checkMeshIndices(mesh, what = 'mesh') {
  if (mesh.points.length % 2) throw badInput(`${what}.points has odd length ${mesh.points.length}`);
  if (mesh.triangles.length % 3)
    throw badInput(`${what}.triangles has length ${mesh.triangles.length}, not a multiple of 3`);
  if (mesh.segments.length % 2) throw badInput(`${what}.segments has odd length ${mesh.segments.length}`);
  const n = mesh.points.length / 2;
  for (const key of ['triangles', 'segments']) {
    const a = mesh[key];
    for (let i = 0; i < a.length; ++i)
      if (a[i] >= n)
        throw badInput(`${what}.${key}[${i}] refers to vertex ${a[i]}, but there are only ${n} vertices`);
  }
  if (mesh.vertexKind.length !== n) mesh.vertexKind = new Uint8Array(0);
  // Labels of another mesh's size are dropped, as vertexKind is (writers then leave them out).
  const sizes = { segmentInput: mesh.segments.length / 2, vertexMarkers: n,
    segmentMarkers: mesh.segments.length / 2, triangleAttributes: mesh.triangles.length / 3 };
  for (const key of Object.keys(sizes))
    if (mesh[key] !== undefined && mesh[key].length !== sizes[key]) delete mesh[key];
  mesh.exactPoints.forEach((p, i) => {
    if (p.vertex >= n)
      throw badInput(`${what}.exactPoints[${i}] refers to vertex ${p.vertex}, but there are only ${n} vertices`);
  });
}

// Checks of names (modes, fill rules, formats) against the vocabulary's tables; an unknown one
// is a BAD_INPUT with the core's message (the choices, and the nearest name when one is close).
function makeNames(vocabulary, unknownName) {
  const sets = {
    mode: new Set(vocabulary.modes.map((e) => e.name)),
    fill: new Set(vocabulary.fillRules.map((e) => e.name)),
    inputFormat: new Set(vocabulary.inputFormats.map((e) => e.name)),
    outputFormat: new Set(vocabulary.outputFormats.map((e) => e.name)),
  };
  return {
    check(value, kind, what, fallback) {
      if (value === undefined) return fallback;
      if (typeof value !== 'string') throw new TypeError(`${what} must be a string, not ${describe(value)}`);
      if (!sets[kind].has(value)) throw badInput(unknownName(kind, value));
      return value;
    },
  };
}

function numberOption(options, key, fallback) {
  const v = options[key];
  if (v === undefined) return fallback;
  if (typeof v !== 'number') throw new TypeError(`options.${key} must be a number, not ${describe(v)}`);
  return v;
}

// 'auto' (the lowest bound the run can certify: acute mode only, which the core checks) or a
// number of degrees, 60 < maxAngle <= 90. Checked here rather than by the core, whose 0 stands
// for 'auto'.
function maxAngleOption(options, fallback) {
  const v = options.maxAngle;
  if (v === undefined || v === 'auto') return v === undefined ? fallback : v;
  if (typeof v !== 'number' && typeof v !== 'string')
    throw new TypeError(`options.maxAngle must be a number or 'auto', not ${describe(v)}`);
  if (!(typeof v === 'number' && v > 60 && v <= 90))
    throw badInput(`maxAngle must be above 60 and at most 90 degrees, or 'auto', not ${typeof v === 'string' ? `'${v}'` : v}`);
  return v;
}

const SIZE_KEYS = ['function', 'grid', 'points', 'sizes', 'maxArea'];
const GRID_KEYS = ['x0', 'y0', 'dx', 'dy', 'nx', 'ny', 'h'];

// options.size: a function (x, y) => size, or { function, grid, points, sizes, maxArea } with
// any of them (SizeField in acutemesh.h). Checked for shape here; the core checks the values
// (sizes > 0, h holding nx * ny of them, one size per point) and names the one that is wrong.
function sizeOption(size) {
  if (size === undefined) return undefined;
  if (typeof size === 'function') return { function: size };
  checkObject(size, 'options.size');
  checkKeys(size, SIZE_KEYS, 'options.size');
  const out = {};
  for (const key of ['function', 'maxArea']) {
    if (size[key] === undefined) continue;
    if (typeof size[key] !== 'function')
      throw new TypeError(`options.size.${key} must be a function (x, y) => number, not ${describe(size[key])}`);
    out[key] = size[key];
  }
  if (size.grid !== undefined) {
    const g = size.grid;
    checkObject(g, 'options.size.grid');
    checkKeys(g, GRID_KEYS, 'options.size.grid');
    out.grid = {};
    for (const key of GRID_KEYS.slice(0, 6)) {
      if (typeof g[key] !== 'number')
        throw new TypeError(`options.size.grid.${key} must be a number, not ${describe(g[key])}`);
      if ((key === 'nx' || key === 'ny') && !(Number.isInteger(g[key]) && g[key] >= 1 && g[key] <= 0xffffffff))
        throw badInput(`options.size.grid.${key} must be a whole number of nodes >= 1, not ${g[key]}`);
      out.grid[key] = g[key];
    }
    out.grid.h = toNumbers(g.h, 'options.size.grid.h');
  }
  if (size.points !== undefined) out.points = toCoordinates(size.points, 'options.size.points');
  if (size.sizes !== undefined) out.sizes = toNumbers(size.sizes, 'options.size.sizes');
  return out;
}

// The size and area functions as the module calls them: what the caller's function throws, or
// a value that is not a number, stops the run (the progress callback's answer) and is thrown
// from mesh(); a number out of range the core reports itself.
function sizeBridge(size) {
  let error;
  const wrap = (f, key) => (x, y) => {
    if (error !== undefined) return NaN;
    try {
      const h = f(x, y);
      if (typeof h === 'number') return h;
      error = new TypeError(`options.size.${key} must return a number, not ${describe(h)} (at ${x}, ${y})`);
    } catch (e) {
      error = e;
    }
    return NaN;
  };
  if (size === undefined || (size.function === undefined && size.maxArea === undefined))
    return { size, failed: undefined, rethrow() {} };
  const wrapped = { ...size };
  for (const key of ['function', 'maxArea'])
    if (size[key] !== undefined) wrapped[key] = wrap(size[key], key);
  return {
    size: wrapped,
    failed: () => error !== undefined,
    rethrow() { if (error !== undefined) throw error; },
  };
}

// The options that describe the job, as names (what a mesh result carries, and what
// validate() reads back); functions and signals are handled by mesh() itself. `core` holds the
// names' checks and the defaults (makeApi); `input` is toPslg's result.
function toOptions(options, input, core, where) {
  if (options === undefined) options = {};
  checkObject(options, 'options');
  checkKeys(options, MESH_OPTION_KEYS, where);
  const { names, defaults } = core;
  const mode = names.check(options.mode, 'mode', 'mode', defaults.mode);
  const fill = names.check(options.fill, 'fill', 'fill rule', input.fill === undefined ? defaults.fill : input.fill);
  for (const key of ['convexHull', 'exactSegments', 'exactFeet', 'adjacency'])
    if (options[key] !== undefined && typeof options[key] !== 'boolean')
      throw new TypeError(`options.${key} must be a boolean, not ${describe(options[key])}`);
  const maxSteiner = numberOption(options, 'maxSteiner', defaults.maxSteiner);
  if (!Number.isInteger(maxSteiner) || maxSteiner < 0 || maxSteiner > 0xffffffff)
    throw badInput(`maxSteiner must be an integer from 0 (automatic) to 4294967295, not ${maxSteiner}`);
  const timeLimit = numberOption(options, 'timeLimit', defaults.timeLimit);
  if (!(timeLimit >= 0) || timeLimit === Infinity)
    throw badInput(`timeLimit must be a number of seconds >= 0 (0: none), not ${timeLimit}`);
  const optimize = numberOption(options, 'optimize', defaults.optimize);
  if (!(optimize >= 0) || optimize === Infinity)
    throw badInput(`optimize must be a number of seconds >= 0 (0: none), not ${optimize}`);
  const optimizeTries = numberOption(options, 'optimizeTries', defaults.optimizeTries);
  if (!Number.isSafeInteger(optimizeTries) || optimizeTries < 0)
    throw badInput(`optimizeTries must be an integer from 0 (no cap) to 2^53 - 1, not ${optimizeTries}`);
  const seed = numberOption(options, 'seed', defaults.seed);
  if (!Number.isSafeInteger(seed) || seed < 0)
    throw badInput(`seed must be an integer from 0 to 2^53 - 1, not ${seed}`);
  const flag = (key) => (options[key] === undefined ? defaults[key] : options[key]);
  return {
    mode,
    fill,
    convexHull: flag('convexHull'),
    exactSegments: flag('exactSegments'),
    exactFeet: flag('exactFeet'),
    adjacency: flag('adjacency'),
    maxAngle: maxAngleOption(options, defaults.maxAngle),
    // The core checks the ranges of these and names the option when one is wrong.
    minAngle: numberOption(options, 'minAngle', defaults.minAngle),
    maxArea: numberOption(options, 'maxArea', defaults.maxArea),
    maxEdge: numberOption(options, 'maxEdge', defaults.maxEdge),
    grading: numberOption(options, 'grading', defaults.grading),
    maxSteiner,
    timeLimit,
    optimize,
    optimizeTries,
    seed,
    ...(options.size === undefined ? {} : { size: sizeOption(options.size) }),
  };
}

// mesh()'s options for a parsed input: the core's input policy, as the CLI applies it (a
// CG:SHOP instance meshed with exact segments, and exact feet unless options.exactFeet is
// given). validate() takes the options a mesh was made with as they are.
function withInputPolicy(resolved, input, options, core) {
  if (input.format === undefined) return resolved;
  const exactFeetChosen = options !== undefined && options.exactFeet !== undefined;
  return { ...resolved, ...core.inputPolicy(input.format, exactFeetChosen, resolved) };
}

function checkSignal(signal) {
  if (signal === undefined) return;
  if (typeof signal !== 'object' || signal === null || typeof signal.aborted !== 'boolean')
    throw new TypeError(`options.signal must be an AbortSignal, not ${describe(signal)}`);
}

function checkText(text, what) {
  if (typeof text !== 'string') throw new TypeError(`${what} must be a string, not ${describe(text)}`);
}

// A parser's result: the fill rule comes when the input policy implies one (JSON rings).
function parsed(r) {
  if (!r.ok) throw badInput(r.message);
  const out = { points: r.points, segments: r.segments, holes: r.holes };
  // Markers and regions when the text has them.
  if (r.vertexMarkers.length) out.vertexMarkers = r.vertexMarkers;
  if (r.segmentMarkers.length) out.segmentMarkers = r.segmentMarkers;
  if (r.regions.length) out.regions = fromRegions(r.regions);
  if (r.fill !== undefined) out.fill = r.fill;
  out.format = r.format;
  if (r.format === 'cgshop') out.instanceUid = r.instanceUid;
  out.warnings = r.warnings;
  return out;
}

// --- rings --------------------------------------------------------------------------------

// Closed outlines (GeoJSON polygon rings, font contours) into a PSLG: each ring's points
// become vertices and consecutive points segments, closing back to the first. A last point
// equal to the first (GeoJSON repeats it) is dropped. The same rules as the core's JSON
// reader for {"rings": ...}, whose fill rule the input policy gives (core.defaults.ringsFill).
function ringsToPslg(rings, options, core) {
  if (!Array.isArray(rings)) throw new TypeError(`rings must be an array of rings, not ${describe(rings)}`);
  if (options === undefined) options = {};
  checkObject(options, 'options');
  checkKeys(options, ['fill', 'ringMarkers'], 'fromRings()');
  const fill = core.names.check(options.fill, 'fill', 'fill rule', core.defaults.ringsFill);
  const ringMarkers = options.ringMarkers === undefined ? undefined : toMarkers(options.ringMarkers, 'options.ringMarkers');
  if (ringMarkers !== undefined && ringMarkers.length !== rings.length)
    throw badInput(`options.ringMarkers has ${ringMarkers.length} markers; expected one per ring (${rings.length})`);
  const flat = rings.map((ring, r) => toCoordinates(ring, `rings[${r}]`));
  let total = 0;
  const counts = flat.map((xy, r) => {
    let n = xy.length / 2;
    if (xy.length % 2) throw badInput(`rings[${r}] has an odd number of coordinates (${xy.length})`);
    if (n >= 2 && xy[0] === xy[2 * n - 2] && xy[1] === xy[2 * n - 1]) --n;
    if (n < 3) throw badInput(`rings[${r}] has ${n} distinct points; a ring needs at least 3`);
    total += n;
    return n;
  });
  const points = new Float64Array(2 * total);
  const segments = new Uint32Array(2 * total);
  let base = 0;
  flat.forEach((xy, r) => {
    const n = counts[r];
    points.set(xy.subarray(0, 2 * n), 2 * base);
    for (let i = 0; i < n; ++i) {
      segments[2 * (base + i)] = base + i;
      segments[2 * (base + i) + 1] = base + ((i + 1) % n);
    }
    base += n;
  });
  const out = { points, segments, holes: new Float64Array(0), fill };
  // Each ring's segments take its marker (as the core's "ringMarkers").
  if (ringMarkers !== undefined) {
    out.segmentMarkers = new Int32Array(total);
    base = 0;
    counts.forEach((n, r) => { out.segmentMarkers.fill(ringMarkers[r], base, base + n); base += n; });
  }
  return out;
}

// The vocabulary is shared by every API object: read-only all the way down.
function deepFreeze(value) {
  if (typeof value === 'object' && value !== null) {
    for (const v of Object.values(value)) deepFreeze(v);
    Object.freeze(value);
  }
  return value;
}

// --- instances ----------------------------------------------------------------------------

// Arguments for the Emscripten factory that instantiate `compiled` ourselves: synchronously
// (`new WebAssembly.Instance`, for restarts) or not. An asynchronous instantiation error goes
// to `onFailure` (the glue's own promise would never settle).
function moduleArgs(compiled, memoryLimit, sync, onFailure) {
  const args = {
    instantiateWasm(imports, receive) {
      if (sync) {
        receive(new WebAssembly.Instance(compiled, imports), compiled);
      } else {
        WebAssembly.instantiate(compiled, imports).then(
          (instance) => receive(instance, compiled),
          onFailure);
      }
      return {};
    },
    // The core prints nothing; the glue prints only an abort's reason, which the API turns
    // into the error it throws.
    print() {},
    printErr() {},
  };
  // The tests (and embedders) may cap the heap below the build's 2 GB: the glue then grows
  // this memory, and growth failing past the cap is an ordinary out-of-memory.
  if (memoryLimit) {
    args.wasmMemory = new WebAssembly.Memory({
      initial: INITIAL_MEMORY / WASM_PAGE,
      maximum: Math.ceil(Math.max(INITIAL_MEMORY, memoryLimit) / WASM_PAGE),
    });
  }
  return args;
}

function instantiate(factory, compiled, memoryLimit) {
  let fail;
  const failed = new Promise((resolve, reject) => { fail = reject; });
  return Promise.race([factory(moduleArgs(compiled, memoryLimit, false, (e) => fail(e))), failed]);
}

// Synchronously, or null where the platform refuses (browsers limit synchronous compilation
// on the main thread; instantiating an already compiled module works in Node, in workers and
// on Chromium's main thread). After new WebAssembly.Instance the glue starts the runtime
// before the factory returns, so the bindings are on `args` at once.
function instantiateNow(factory, compiled, memoryLimit) {
  try {
    const args = moduleArgs(compiled, memoryLimit, true);
    factory(args).catch(() => {});
    return typeof args.core_mesh === 'function' ? args : null;
  } catch (_) {
    return null;
  }
}

// Every call into a wasm instance goes through the function this returns. After the instance
// aborts (out of memory: the heap cannot grow past 2 GB or options.maxMemory; or an internal
// error), its memory is lost to leaked allocations and a half-finished call, so the caller
// replaces it with a fresh instance of the same compiled module and throws an AcuteMeshError:
// the API stays usable, at the cost of a re-instantiation (milliseconds).
function makeCaller(factory, compiled, memoryLimit, M) {
  // Replaces the dead instance, synchronously where possible; otherwise calls made before the
  // asynchronous restart finishes throw RESTARTING.
  function restart() {
    M = instantiateNow(factory, compiled, memoryLimit);
    if (M) return;
    instantiate(factory, compiled, memoryLimit).then((m) => { M = m; }, () => {});
  }

  return function call(f) {
    if (!M) {
      throw new AcuteMeshError('RESTARTING',
        'the wasm instance is restarting after an earlier failure; try again shortly');
    }
    const instance = M;
    try {
      return f(instance);
    } catch (e) {
      if (e instanceof AcuteMeshError || e instanceof TypeError) throw e;
      const outOfMemory = instance.outOfMemory === true;
      restart();
      if (outOfMemory) {
        const limit = memoryLimit || 2 ** 31;
        throw new AcuteMeshError('OUT_OF_MEMORY',
          `out of memory: the job needs more than the wasm heap's ${Math.round(limit / 2 ** 20)} MB ` +
          `(the module was reset and can be used again)`);
      }
      throw new AcuteMeshError('INTERNAL',
        `internal error in the wasm module (${e && e.message ? e.message : e}); the module was reset ` +
        `and can be used again`);
    }
  };
}

// The core calls progress back synchronously; a true return asks it to stop. An exception from
// the user's callback is kept and rethrown (rethrow()) after the core has returned, so it never
// unwinds through C++ frames.
function progressBridge(onProgress, signal, sizeFailed) {
  let callbackError;
  let failed = false;
  const callback = onProgress || signal || sizeFailed ? (phase, fraction, vertices) => {
    if (onProgress && !failed) {
      try {
        onProgress({ phase, fraction, vertices });
      } catch (e) {
        callbackError = e;
        failed = true;
      }
    }
    return failed || (sizeFailed !== undefined && sizeFailed()) || (signal !== undefined && signal.aborted);
  } : undefined;
  return { callback, rethrow() { if (failed) throw callbackError; } };
}

// The readers, each returning a PSLG that carries its format (parsed()).
function makeParsers(call) {
  const nameOr = (options, fallback) => (options.name === undefined ? fallback : String(options.name));
  return {
    parsePoly(text, options = {}) {
      checkText(text, 'text');
      checkObject(options, 'options');
      checkKeys(options, ['name', 'nodeText'], 'parsePoly()');
      const name = nameOr(options, 'input.poly');
      const nodeText = options.nodeText === undefined ? '' : options.nodeText;
      checkText(nodeText, 'options.nodeText');
      const nodeName = name.replace(/\.poly$/i, '') + '.node';
      return parsed(call((I) => I.core_parsePoly(utf8.encode(text), name, utf8.encode(nodeText), nodeName)));
    },

    parseNode(text, options = {}) {
      checkText(text, 'text');
      checkObject(options, 'options');
      checkKeys(options, ['name'], 'parseNode()');
      return parsed(call((I) => I.core_parseNode(utf8.encode(text), nameOr(options, 'input.node'))));
    },

    // JSON in any of the core's three shapes: a PSLG, {"rings": ...} (fill 'evenodd' unless
    // the caller says otherwise) or a CG:SHOP 2025 instance (format 'cgshop', instanceUid set).
    parseJson(text, options = {}) {
      checkText(text, 'text');
      checkObject(options, 'options');
      checkKeys(options, ['name'], 'parseJson()');
      return parsed(call((I) => I.core_parseJson(utf8.encode(text), nameOr(options, 'input.json'))));
    },
  };
}

// The writers: any format by its name (write), and one function per format.
function makeWriters(call, names) {
  const formatter = (format) => (m) => {
    const mesh = toMesh(m);
    checkMeshIndices(mesh);
    return call((I) => I.core_format(format, mesh));
  };
  // The CG:SHOP 2025 solution of a mesh of `instance` (parseJson's result for an instance).
  const toCgshop = (m, instance) => {
    const mesh = toMesh(m);
    checkMeshIndices(mesh);
    checkObject(instance, 'instance');
    if (typeof instance.instanceUid !== 'string')
      throw new TypeError('instance.instanceUid must be a string (parseJson of a CG:SHOP 2025 instance)');
    const n = toCoordinates(instance.points, 'instance.points').length / 2;
    return call((I) => I.core_formatCgshop(mesh, instance.instanceUid, n));
  };
  return {
    // Any writer by its format's name (vocabulary.outputFormats); 'cgshop' needs the instance.
    write(m, format, instance) {
      if (names.check(format, 'outputFormat', 'format', undefined) === undefined)
        throw new TypeError('format must be a string, not undefined');
      return format === 'cgshop' ? toCgshop(m, instance) : formatter(format)(m);
    },
    toNode: formatter('node'),
    toEle: formatter('ele'),
    toPoly: formatter('poly'),
    toJson: formatter('json'),
    toOFF: formatter('off'),
    toOBJ: formatter('obj'),
    toSVG: formatter('svg'),
    toEdge: formatter('edge'),
    toNeigh: formatter('neigh'),
    toMSH: formatter('msh'),
    toMSH2: formatter('msh2'),
    toVTU: formatter('vtu'),
    toCgshop,
  };
}

// The API object over one wasm instance M of `compiled` (makeCaller keeps it alive).
function makeApi(factory, compiled, memoryLimit, M) {
  const call = makeCaller(factory, compiled, memoryLimit, M);
  // The core's names and defaults (the same in every instance of the module), and its input
  // policy, for the argument checks.
  const vocabulary = deepFreeze(M.core_vocabulary());
  const core = {
    names: makeNames(vocabulary, (kind, name) => call((I) => I.core_unknownName(kind, name))),
    defaults: vocabulary.defaults,
    inputPolicy: (format, exactFeetChosen, options) =>
      call((I) => I.core_inputPolicy(format, exactFeetChosen, options)),
  };

  const api = {
    version: M.core_version(),

    // Modes, fill rules, statuses, vertex kinds, input and output formats ({name, value,
    // description, ...} each, in the core's order) and the options' defaults.
    vocabulary,

    ...makeParsers(call),

    fromRings: (rings, options) => ringsToPslg(rings, options, core),

    mesh(pslg, options = {}) {
      const input = toPslg(pslg, core.names);
      const opts = withInputPolicy(toOptions(options, input, core, 'mesh()'), input, options, core);
      const { onProgress, signal } = options;
      if (onProgress !== undefined && typeof onProgress !== 'function')
        throw new TypeError(`options.onProgress must be a function, not ${describe(onProgress)}`);
      checkSignal(signal);
      if (signal && signal.aborted) throw abortError(signal);
      const sizes = sizeBridge(opts.size);
      const progress = progressBridge(onProgress, signal, sizes.failed);
      const r = call((I) => I.core_mesh(input.points, input.segments, input.holes, input.labels,
        { ...opts, size: sizes.size }, progress.callback));
      progress.rethrow();
      sizes.rethrow();
      // A cancel while optimize searches (anytime) keeps the best mesh so far, which meets the
      // target: it is the answer, with status 'cancelled'. Any other cancel has no answer.
      if (r.status === 'cancelled' && !(searchAsked(opts) && r.stats.targetMet)) throw abortError(signal);
      if (r.status === 'bad-input') throw badInput(r.message);
      const result = {
        points: r.points,
        triangles: r.triangles,
        segments: r.segments,
        segmentInput: r.segmentInput,
        vertexKind: r.vertexKind,
        vertexMarkers: r.vertexMarkers,
        segmentMarkers: r.segmentMarkers,
        triangleAttributes: r.triangleAttributes,
        exactPoints: r.exactPoints,
        stats: r.stats,
        status: r.status,
        message: r.message,
        options: opts,
      };
      if (opts.adjacency)
        for (const key of ADJACENCY_KEYS) result[key] = r[key];
      return result;
    },

    validate(pslg, m, options) {
      const input = toPslg(pslg, core.names);
      const mesh = toMesh(m);
      if (options === undefined) options = m.options === undefined ? {} : m.options;
      const opts = toOptions(options, input, core, 'validate()');
      return call((I) => I.core_validate(input.points, input.segments, input.holes, mesh, opts));
    },

    ...makeWriters(call, core.names),

    // The wasm heap: its size in bytes (grows, never shrinks) and the bytes allocated in it.
    memory() {
      return call((I) => I.core_memory());
    },
  };
  // The JSON writer was called toJSON before toJson, and JSON.stringify calls an object's
  // toJSON with a property key (a string): the key gets the API's data, a mesh the writer.
  // Not enumerable: the writers are the enumerable to* functions.
  Object.defineProperty(api, 'toJSON', {
    value: (meshOrKey) =>
      (typeof meshOrKey === 'string' ? { version: api.version, vocabulary } : api.toJson(meshOrKey)),
  });
  return api;
}

// Entry points call this with the glue's factory and a function that resolves the
// WebAssembly.Module for the given init options.
export function makeEntry(factory, compile) {
  async function createInstance(options = {}) {
    checkObject(options, 'options');
    checkKeys(options, INIT_OPTION_KEYS, 'init()');
    const { maxMemory } = options;
    if (maxMemory !== undefined && (typeof maxMemory !== 'number' || !(maxMemory > 0)))
      throw new TypeError('options.maxMemory must be a positive number of bytes');
    const compiled = options.wasmModule instanceof WebAssembly.Module ? options.wasmModule : await compile(options);
    const M = await instantiate(factory, compiled, maxMemory);
    const api = makeApi(factory, compiled, maxMemory, M);
    api.wasmModule = compiled;
    return api;
  }
  let memo = null;
  function init(options) {
    if (!memo) {
      memo = createInstance(options);
      memo.catch(() => { memo = null; });  // a failed load may be retried
    }
    return memo;
  }
  return { init, createInstance };
}
