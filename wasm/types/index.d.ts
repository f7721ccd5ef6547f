// Types of the acutemesh npm package (written by hand: Emscripten 3.1.6 has no --emit-tsd).
// The same API comes from 'acutemesh' (Node, browsers, bundlers) and 'acutemesh/single'.

/** Which job mesh() does. */
export type Mode =
  /** Delaunay triangulation of the points (segments and holes ignored). */
  | 'delaunay'
  /** Constrained Delaunay triangulation of the PSLG, restricted to its domain (default). */
  | 'cdt'
  /** Refine until every angle >= minAngle and every area <= maxArea (minAngle 20 when none of minAngle, maxArea and the sizes is given). */
  | 'quality'
  /** Refine until every angle <= 90 degrees (certified exactly). */
  | 'nonobtuse'
  /** Refine until every angle < maxAngle (default 90: certified exactly). */
  | 'acute';

/**
 * Which triangles form the domain: 'triangle' (Triangle's rule: the convex hull minus what is
 * reachable from outside or from a hole point without crossing a segment), 'evenodd' or
 * 'nonzero' (by the winding number of the directed segments).
 */
export type FillRule = 'triangle' | 'evenodd' | 'nonzero';

/**
 * What a parser read (ParsedPslg.format): 'poly', 'node', 'json' (a PSLG or rings) or 'cgshop'
 * (a CG:SHOP 2025 instance); 'unknown' for input not read from a text.
 */
export type InputFormat = 'unknown' | 'poly' | 'node' | 'json' | 'cgshop';

/** What a mesh can be written as (write(), vocabulary.outputFormats); 'cgshop' needs the instance. */
export type OutputFormat =
  | 'node' | 'ele' | 'poly' | 'edge' | 'neigh' | 'json' | 'off' | 'obj' | 'svg' | 'msh' | 'msh2' | 'vtu'
  | 'cgshop';

/**
 * The core's statuses: mesh() returns 'ok' and 'target-not-met' (MeshResult.status), and
 * throws for the other two (AcuteMeshError 'BAD_INPUT'; the signal's reason when cancelled).
 */
export type Status = 'ok' | 'target-not-met' | 'bad-input' | 'cancelled';

/** The names of MeshResult.vertexKind's numbers (vocabulary.vertexKinds[k].name for k). */
export type VertexKindName = 'input' | 'unused' | 'segment' | 'free';

/** A planar straight-line graph: flat arrays, x/y interleaved, 0-based vertex indices. */
export interface Pslg {
  /** x0, y0, x1, y1, ... */
  points: Float64Array;
  /** a0, b0, a1, b1, ...: a segment from vertex a to vertex b. */
  segments: Uint32Array;
  /** x, y of a point inside each hole ('triangle' fill rule only). */
  holes: Float64Array;
  /** Boundary markers per vertex, when the source has them (Triangle's .poly/.node, JSON "vertexMarkers"). */
  vertexMarkers?: Int32Array;
  /** Boundary markers per segment, when the source has them (.poly, JSON "segmentMarkers", rings' "ringMarkers"). */
  segmentMarkers?: Int32Array;
  /** Regions, when the source has them (.poly regional attributes, JSON "regions"). */
  regions?: Region[];
  /** The fill rule the source implies (fromRings, parseJson of rings); mesh() uses it unless options.fill says otherwise. */
  fill?: FillRule;
}

/**
 * A region of the domain (Triangle's regional attributes): every triangle reachable from
 * (x, y) without crossing a segment gets `attribute` (MeshResult.triangleAttributes). A later
 * region reaching the same triangles wins; a point in no triangle is ignored with a warning in
 * stats.warnings naming it ("region 2 at (x, y) ...").
 */
export interface Region {
  x: number;
  y: number;
  /** Default 0. Must be finite. */
  attribute?: number;
  /** Area bound inside the region (0 or left out: none); must be finite and >= 0. */
  maxArea?: number;
}

/** What mesh() and validate() accept: typed arrays, flat number arrays, or arrays of pairs. */
export interface PslgInput {
  points: Float64Array | ArrayLike<number> | ReadonlyArray<readonly [number, number]>;
  segments?: Uint32Array | ArrayLike<number> | ReadonlyArray<readonly [number, number]> | null;
  holes?: Float64Array | ArrayLike<number> | ReadonlyArray<readonly [number, number]> | null;
  /**
   * Boundary markers (Triangle's): none, or one 32-bit integer per vertex. They come back in
   * MeshResult.vertexMarkers. A wrong count is an AcuteMeshError('BAD_INPUT') naming the array.
   */
  vertexMarkers?: Int32Array | ArrayLike<number> | null;
  /** None, or one 32-bit integer per segment; they come back in MeshResult.segmentMarkers. */
  segmentMarkers?: Int32Array | ArrayLike<number> | null;
  /** Regions with attributes (and area bounds), as objects; see Region. */
  regions?: ReadonlyArray<Region> | null;
  fill?: FillRule;
  /** What it was read from (ParsedPslg.format): mesh() applies the input policy for it. */
  format?: InputFormat;
}

/** A parser's result: the PSLG and what the parser tolerated ("NAME:LINE: ..."). */
export interface ParsedPslg extends Pslg {
  /**
   * What the text was. mesh() applies the core's input policy to it, as the CLI does: a
   * 'cgshop' instance is meshed with exactSegments, and with exactFeet unless options.exactFeet
   * is given (MeshResult.options says so, and validate() checks with them).
   */
  format: InputFormat;
  warnings: string[];
  /** CG:SHOP 2025 instances only (parseJson). */
  instanceUid?: string;
}

export interface Progress {
  /** 'delaunay', 'segments', 'domain', 'refine', 'improve' or 'output'. */
  phase: string;
  /** 0..1 within the phase, or -1 when unknown; 'refine' and 'improve' share one fraction of the refinement, which never goes down. */
  fraction: number;
  /** Current vertex count (0 when not known). */
  vertices: number;
}

/**
 * An AbortSignal (written structurally so that the types need neither the DOM library nor
 * @types/node).
 */
export interface AbortSignalLike {
  readonly aborted: boolean;
  readonly reason?: unknown;
  addEventListener(type: 'abort', listener: () => void, options?: { once?: boolean }): void;
  removeEventListener(type: 'abort', listener: () => void): void;
}

/** A compiled WebAssembly.Module (typed loosely for the same reason). */
export type WasmModule = object;

export interface MeshOptions {
  /** Default 'cdt'. */
  mode?: Mode;
  /** Default: the PSLG's own fill, else 'triangle'. */
  fill?: FillRule;
  /** Keep every triangle of the convex hull (hole points still apply). */
  convexHull?: boolean;
  /**
   * Steiner points on segments exactly on their lines where a representable point is near
   * (integer coordinates), not within rounding of them: for exact checkers such as the
   * CG:SHOP 2025 verifier; costs points. Default false; always on for a parsed CG:SHOP instance.
   */
  exactSegments?: boolean;
  /**
   * Non-obtuse: Steiner points on segments may stand for exact altitude feet, rationals no
   * double holds (see MeshResult.exactPoints): far fewer points next to tilted segments. For
   * outputs that hold rationals (toCgshop, toJson). Default false; true for a parsed CG:SHOP
   * instance unless given.
   */
  exactFeet?: boolean;
  /**
   * Degrees; acute mode: every angle < maxAngle, 60 < maxAngle <= 90 (default 90), certified
   * exactly. 'auto': the lowest bound the run can certify (acute mode only), said in
   * stats.angleBound. A bound at or below the domain's floor (stats.angleFloor) is said in
   * stats.warnings and meshed as 'auto', status 'target-not-met'. Other modes ignore a number.
   */
  maxAngle?: number | 'auto';
  /** Degrees; smallest angle wanted (quality mode: 20 when none of minAngle, maxArea and the sizes is given; 0 <= minAngle < 60; terminates up to 40, and above 40 a run that wanders is meshed to 40 instead, status 'target-not-met'). */
  minAngle?: number;
  /** Largest triangle area wanted (0: none). */
  maxArea?: number;
  /** Longest edge wanted (0: none), in every refinement mode; acute and non-obtuse meshes stay so. */
  maxEdge?: number;
  /**
   * Edge sizes over the plane: a triangle is split while its longest edge exceeds the size at
   * its centroid. A function (x, y) => size, or any of a function, a grid, scattered points
   * with sizes and an area function; where several apply the smallest holds. Sizes > 0
   * (Infinity: no bound there). Functions run on this thread (not through acutemesh/worker).
   */
  size?: SizeFunction | SizeField;
  /**
   * How fast sizes may grow with distance, |grad size| <= grading (0.2-0.5 is usual; 0: no
   * limit). Grades maxEdge and size away from them and from the input's small features
   * (each vertex's shortest edge); needs maxEdge or size.
   */
  grading?: number;
  /** Steiner point budget (0: automatic, 50 per input vertex and at least 20000). */
  maxSteiner?: number;
  /** Seconds (0: none). When it ends, the best mesh so far comes back with stats.targetMet false. */
  timeLimit?: number;
  /**
   * Seconds to spend after refinement looking for a mesh with fewer Steiner points (0: none):
   * an anytime search that keeps the best mesh meeting the target and returns it when the time
   * is up (or at timeLimit), never one with more points. Acute (at 90, a bound below it or
   * 'auto', keeping the bound), non-obtuse, and quality with a minAngle (sized too); on the
   * threads of a native build, one chain in WebAssembly.
   */
  optimize?: number;
  /**
   * At most this many tries of that search (0: no cap; alone, it starts the search too): the
   * same seed and tries make the same mesh on any machine, which seconds do not.
   */
  optimizeTries?: number;
  /** The optimize search's random choices (default 1): the same seed, the same tries. */
  seed?: number;
  /**
   * Also return how the triangles connect (MeshResult.halfedges, neighbors, edges, edgeMarkers,
   * hull, hullStarts). Default false.
   */
  adjacency?: boolean;
  /** Called synchronously from inside mesh() after each phase and now and then while refining. */
  onProgress?: (progress: Progress) => void;
  /**
   * Checked at each progress report: once aborted, mesh() stops and throws signal.reason (an
   * AbortError by default). In the calling thread only code run from onProgress can abort it;
   * use acutemesh/worker to cancel from outside.
   */
  signal?: AbortSignalLike;
}

/** A size at (x, y): the longest an edge may be there (> 0; Infinity: no bound). */
export type SizeFunction = (x: number, y: number) => number;

/** Sizes from several sources (SizeField in acutemesh.h); each optional. */
export interface SizeField {
  function?: SizeFunction;
  /** h[i + nx * j] at (x0 + i * dx, y0 + j * dy), bilinear in between, the nearest border value outside. */
  grid?: { x0: number; y0: number; dx: number; dy: number; nx: number; ny: number; h: ArrayLike<number> };
  /** Scattered sizes: points (x, y flat, or [x, y] pairs) with one size each, linear between them. */
  points?: Float64Array | ArrayLike<number> | [number, number][];
  sizes?: Float64Array | ArrayLike<number>;
  /** The largest area a triangle may have at its centroid (> 0). */
  maxArea?: SizeFunction;
}

/** The options a mesh was made with, as mesh() normalised them. */
export interface ResolvedOptions {
  mode: Mode;
  fill: FillRule;
  convexHull: boolean;
  exactSegments: boolean;
  exactFeet: boolean;
  maxAngle: number | 'auto';
  minAngle: number;
  maxArea: number;
  maxEdge: number;
  grading: number;
  /** options.size as given (a function as { function }), the arrays as Float64Arrays. */
  size?: SizeField;
  maxSteiner: number;
  timeLimit: number;
  adjacency: boolean;
  optimize: number;
  optimizeTries: number;
  seed: number;
}

export interface MeshStats {
  inputVertices: number;
  inputSegments: number;
  inputHoles: number;
  vertices: number;
  triangles: number;
  segments: number;
  /** Vertices added (segment crossings count too). */
  steiner: number;
  /** Input vertices merged into an earlier equal one. */
  duplicates: number;
  /** Degrees, over all output triangles. */
  minAngle: number;
  maxAngle: number;
  /** Triangles with a corner >= 90 degrees (exact). */
  nonAcute: number;
  /** Triangles with a corner > 90 degrees (exact). */
  obtuse: number;
  /** Refinement modes: every triangle meets the target. */
  targetMet: boolean;
  /**
   * Checked exactly for the mesh's doubles: acute, every angle < angleBound; non-obtuse, every
   * angle <= 90.
   */
  certified: boolean;
  /**
   * With sizes (maxEdge, size, a region's maxArea): the largest ratio over the triangles of
   * the longest edge to the size at the centroid (area bounds as sqrt(area / bound)); at most
   * 1 when every size is met. 0 without sizes.
   */
  sizeRatio: number;
  /**
   * Acute: the bound every angle is certified strictly below (degrees): maxAngle when the mesh
   * meets it; otherwise ('auto', or a bound not reached) the largest angle rounded up to the
   * next tenth of a degree, at most 90. 0 when some angle is 90 or more, and in other modes.
   */
  angleBound: number;
  /**
   * Smallest angle between two input segments on either side of them, outside the domain too
   * (degrees; 180 when none meet). smallestDomainAngle is the one that limits meshes.
   */
  smallestInputAngle: number;
  /**
   * The domain's smallest corner, measured inside it (degrees; a reflex corner is over 180; 360
   * when there is none). Every mode but delaunay.
   */
  smallestDomainAngle: number;
  /**
   * 90 - min(36, smallestDomainAngle) / 2: the lowest maximum angle acutemesh aims for. Above 72
   * no mesh of the domain has every angle below it; every domain has one with every angle at
   * most it (Bishop 2021).
   */
  angleFloor: number;
  /** Wall time per phase, seconds. */
  phases: Record<string, number>;
  /** Wall time of the whole call, seconds. */
  seconds: number;
  warnings: string[];
}

/**
 * A mesh. Vertex i is input vertex i for every input vertex; Steiner points follow. Triangles
 * are counter-clockwise.
 */
export interface MeshResult {
  points: Float64Array;
  /** a, b, c per triangle. */
  triangles: Uint32Array;
  /** a, b per mesh edge lying on an input segment. */
  segments: Uint32Array;
  /** Per mesh segment edge (segments[2i], segments[2i+1]): the input segment it lies on. */
  segmentInput: Uint32Array;
  /**
   * Per vertex, Triangle's rule: an input vertex keeps its marker; a Steiner point on a
   * segment, and an input vertex with marker 0 on a segment with one, take the segment's (the
   * lowest-numbered such segment's); a zero marker on the mesh's boundary becomes 1.
   */
  vertexMarkers: Int32Array;
  /** Per mesh segment edge: its input segment's marker (a zero one on the boundary: 1). */
  segmentMarkers: Int32Array;
  /** Per triangle: the attribute of its region (0 outside every region); undefined when the input has no regions. */
  triangleAttributes?: Float64Array;
  /** options.adjacency: per half-edge 3t + k (corner k to corner k + 1 of triangle t), its twin; -1 on the boundary (Delaunator's halfedges). */
  halfedges?: Int32Array;
  /** options.adjacency: 3 per triangle, the triangle opposite corner k; -1 none. */
  neighbors?: Int32Array;
  /** options.adjacency: a, b (a < b) per undirected edge, sorted. */
  edges?: Uint32Array;
  /** options.adjacency: per edge, the marker of the input segment it lies on; 0 inside, and a zero one on the boundary 1. */
  edgeMarkers?: Int32Array;
  /** options.adjacency: the boundary as closed loops of vertices, the mesh on the left (outer loops counter-clockwise, holes clockwise); loop i is hull[hullStarts[i] .. hullStarts[i + 1]). */
  hull?: Uint32Array;
  /** options.adjacency: where each loop of hull starts, and its length at the end. */
  hullStarts?: Uint32Array;
  /**
   * Per vertex, a number whose name is vocabulary.vertexKinds[number].name: 0 'input', 1 'unused'
   * (an input vertex no triangle uses: a duplicate, or outside), 2 'segment' (a Steiner point
   * on an input segment), 3 'free' (a Steiner point on none).
   */
  vertexKind: Uint8Array;
  /**
   * With options.exactFeet: the vertices whose exact place no double holds, by vertex; points
   * has a double on the same segment within rounding. stats.certified is about the exact mesh.
   */
  exactPoints: ExactPoint[];
  stats: MeshStats;
  /**
   * 'target-not-met': a budget (maxSteiner, timeLimit) ended first, an angle bound below 90 or
   * a minimum angle above 40 could not be reached (the mesh is then acute, or refined to 40), or
   * input angles below the minimum angle stay. Not an error: the best mesh so far, with
   * stats.targetMet false.
   */
  status: Extract<Status, 'ok' | 'target-not-met'>;
  /** Empty when status is 'ok'; otherwise why. */
  message: string;
  options: ResolvedOptions;
}

/** What the writers and validate() accept as a mesh. */
export interface MeshInput {
  points: Float64Array | ArrayLike<number> | ReadonlyArray<readonly [number, number]>;
  triangles: Uint32Array | ArrayLike<number> | ReadonlyArray<readonly [number, number, number]>;
  segments?: Uint32Array | ArrayLike<number> | ReadonlyArray<readonly [number, number]> | null;
  vertexKind?: Uint8Array;
  exactPoints?: ExactPoint[];
  /** mesh()'s input segment per segment edge (dropped when not one per edge). */
  segmentInput?: Uint32Array;
  /**
   * For the writers: markers per vertex and per segment edge, attributes per triangle (used
   * when there is one per item; else markers are 1 on the boundary and 0 inside, and no
   * attributes are written).
   */
  vertexMarkers?: Int32Array;
  segmentMarkers?: Int32Array;
  triangleAttributes?: Float64Array;
  options?: Partial<ResolvedOptions>;
}

/** A vertex's exact place: decimal rationals "p/q" in lowest terms, or integers "p". */
export interface ExactPoint {
  vertex: number;
  x: string;
  y: string;
}

export interface Validation {
  ok: boolean;
  /** The first few problems found, each naming the item. */
  errors: string[];
}

/** The options the mesh was made with (validate() takes mesh.options when none are given). */
export interface ValidateOptions {
  mode?: Mode;
  fill?: FillRule;
  convexHull?: boolean;
  /** Split points lie exactly on their segments (no rounding allowance); as meshed. */
  exactSegments?: boolean;
}

export interface ParseOptions {
  /** Name used in messages ("NAME:LINE: ..."). */
  name?: string;
}

export interface ParsePolyOptions extends ParseOptions {
  /** The .node text, for a .poly whose vertex count is 0. */
  nodeText?: string;
}

export type Ring = Float64Array | ArrayLike<number> | ReadonlyArray<readonly [number, number]>;

export interface RingsOptions {
  /** Default 'evenodd'. */
  fill?: FillRule;
  /** One marker per ring, given to its segments (Pslg.segmentMarkers), as JSON's "ringMarkers". */
  ringMarkers?: Int32Array | ArrayLike<number>;
}

/** An entry of a vocabulary table: the name, the core's enum value, one line about it. */
export interface Named<Name extends string> {
  readonly name: Name;
  readonly value: number;
  readonly description: string;
}

export interface OutputFormatInfo extends Named<OutputFormat> {
  /** Appended to a base name, dot included ('.node', '.solution.json'). */
  readonly extension: string;
  /** For downloads ('text/plain', 'image/svg+xml', ...). */
  readonly mediaType: string;
  /** Holds coordinates as doubles: exact points (options.exactFeet) come out rounded. */
  readonly roundsExactPoints: boolean;
  /** Written from the CG:SHOP instance too (toCgshop), not from the mesh alone. */
  readonly needsInstance: boolean;
}

/** The core's names (the CLI spells them the same) and the options' defaults. */
export interface Vocabulary {
  readonly modes: ReadonlyArray<Named<Mode>>;
  readonly fillRules: ReadonlyArray<Named<FillRule>>;
  readonly statuses: ReadonlyArray<Named<Status>>;
  readonly vertexKinds: ReadonlyArray<Named<VertexKindName>>;
  readonly inputFormats: ReadonlyArray<Named<InputFormat>>;
  readonly outputFormats: ReadonlyArray<OutputFormatInfo>;
  /**
   * mesh()'s defaults; qualityMinAngle is what quality mode aims at when neither minAngle nor
   * maxArea is given, ringsFill the fill rule of rings (fromRings, JSON rings).
   */
  readonly defaults: Readonly<ResolvedOptions> & { readonly qualityMinAngle: number; readonly ringsFill: FillRule };
}

export interface MemoryInfo {
  /** Bytes of wasm memory (grows, never shrinks). */
  heapSize: number;
  /** Bytes currently allocated by the C++ heap. */
  allocated: number;
}

export interface AcuteMesh {
  readonly version: string;
  /** The compiled module (can be posted to workers and passed to init as wasmModule). */
  readonly wasmModule: WasmModule;
  /** The core's names of modes, fill rules, statuses, vertex kinds and formats, and the defaults. */
  readonly vocabulary: Vocabulary;
  /** Triangle's .poly format. */
  parsePoly(text: string, options?: ParsePolyOptions): ParsedPslg;
  /** Triangle's .node format: a point set. */
  parseNode(text: string, options?: ParseOptions): ParsedPslg;
  /** acutemesh JSON: a PSLG, {"rings": ...} (fill 'evenodd') or a CG:SHOP 2025 instance. */
  parseJson(text: string, options?: ParseOptions): ParsedPslg;
  /** Closed rings (GeoJSON polygon coordinates, font contours) into a PSLG; a repeated last point is dropped. */
  fromRings(rings: ReadonlyArray<Ring>, options?: RingsOptions): Pslg & { fill: FillRule };
  /** Throws AcuteMeshError('BAD_INPUT') for bad input and for an empty domain (the message says what removed every triangle); a missed target is not an error (see MeshResult.status). */
  mesh(pslg: PslgInput, options?: MeshOptions): MeshResult;
  /** The core's exact checks of a mesh against its input (options default to the mesh's). */
  validate(pslg: PslgInput, mesh: MeshInput, options?: ValidateOptions): Validation;
  toNode(mesh: MeshInput): string;
  toEle(mesh: MeshInput): string;
  toPoly(mesh: MeshInput): string;
  /** acutemesh's JSON (exact points as rationals); write(mesh, 'json'). */
  toJson(mesh: MeshInput): string;
  /** @deprecated The JSON writer's earlier name: use toJson(mesh). */
  toJSON(mesh: MeshInput): string;
  /** What JSON.stringify(api) writes: the version and the vocabulary. */
  toJSON(key: string): { version: string; vocabulary: Vocabulary };
  toOFF(mesh: MeshInput): string;
  toOBJ(mesh: MeshInput): string;
  toSVG(mesh: MeshInput): string;
  /** Triangle's .edge: every edge with its marker (1 on the boundary when none is given). */
  toEdge(mesh: MeshInput): string;
  /** Triangle's .neigh: per triangle the one opposite each corner, -1 for none. */
  toNeigh(mesh: MeshInput): string;
  /** Gmsh MSH 4.1: region attributes and markers as physical groups; write(mesh, 'msh'). */
  toMSH(mesh: MeshInput): string;
  /** Gmsh MSH 2.2 (for older tools), the same groups; write(mesh, 'msh2'). */
  toMSH2(mesh: MeshInput): string;
  /** VTK XML unstructured grid (ParaView): markers and attributes as cell and point data. */
  toVTU(mesh: MeshInput): string;
  /** The CG:SHOP 2025 solution of a mesh of `instance` (parseJson of the instance file). */
  toCgshop(mesh: MeshInput, instance: CgshopInstance): string;
  /** The writer of a format by its name (the same text as toNode ... toVTU, toCgshop). */
  write(mesh: MeshInput, format: Exclude<OutputFormat, 'cgshop'>): string;
  write(mesh: MeshInput, format: 'cgshop', instance: CgshopInstance): string;
  memory(): MemoryInfo;
}

/** What toCgshop needs of the instance: parseJson's result for it. */
export interface CgshopInstance {
  /** Set by parseJson for a CG:SHOP 2025 instance; toCgshop throws a TypeError without it. */
  instanceUid?: string;
  points: Pslg['points'] | ArrayLike<number>;
}

export interface InitOptions {
  /**
   * Where acutemesh.wasm is (default: beside the package's JS), relative to the page; in Node a
   * path or a file: URL. For bundlers that do not copy it (esbuild).
   */
  wasmUrl?: string | { readonly href: string };
  /** Returns the URL of acutemesh.wasm (default: beside the package's JS). */
  locateFile?: (path: string, prefix: string) => string | { readonly href: string };
  /** The bytes of acutemesh.wasm. */
  wasmBinary?: ArrayBuffer | Uint8Array;
  /** acutemesh.wasm already compiled (e.g. posted from another thread). */
  wasmModule?: WasmModule;
  /** Cap the wasm heap below its 2 GB, in bytes. */
  maxMemory?: number;
}

export type ErrorCode =
  /** Malformed input or options; the message names the item. */
  | 'BAD_INPUT'
  /** The heap could not grow; the instance was reset and stays usable. */
  | 'OUT_OF_MEMORY'
  /** An unexpected failure inside wasm; the instance was reset and stays usable. */
  | 'INTERNAL'
  /** A reset after a failure has not finished yet (browsers' main thread only); try again. */
  | 'RESTARTING';

export declare class AcuteMeshError extends Error {
  constructor(code: ErrorCode, message: string);
  readonly name: 'AcuteMeshError';
  readonly code: ErrorCode;
}

/** Loads acutemesh once (later calls return the same promise; the first call's options apply). */
declare function init(options?: InitOptions): Promise<AcuteMesh>;
export default init;

/** A separate instance with its own heap (not memoised). */
export declare function createInstance(options?: InitOptions): Promise<AcuteMesh>;
