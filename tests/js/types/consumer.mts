// Type-checked (never run) by types.test.mjs with tsc --strict: the API as the README shows
// it, and, marked @ts-expect-error, misuses the types must reject (tsc fails on a marker
// whose line is not an error, so both directions are checked).
import init, { AcuteMeshError, createInstance } from 'acutemesh';
import type { AcuteMesh, MeshResult, Pslg, MeshStats, ErrorCode, Mode, ParsedPslg, VertexKindName } from 'acutemesh';
import initSingle from 'acutemesh/single';
import { createMeshWorker, meshInWorker } from 'acutemesh/worker';
import type { MeshWorker } from 'acutemesh/worker';

export async function use(text: string): Promise<number> {
  const am: AcuteMesh = await init({ locateFile: (path, prefix) => prefix + path });
  const pslg: Pslg = am.parsePoly(text);
  const rings = am.fromRings([[[0, 0], [10, 0], [10, 10], [0, 0]]], { fill: 'evenodd' });
  const m: MeshResult = am.mesh(pslg, {
    mode: 'acute', maxAngle: 90, minAngle: 0, maxArea: 0, maxSteiner: 1000, timeLimit: 5,
    onProgress: ({ phase, fraction, vertices }) => void [phase.length, fraction + vertices],
  });
  const stats: MeshStats = m.stats;
  const auto = am.mesh(pslg, { mode: 'acute', maxAngle: 'auto' });
  const reached: number = auto.stats.angleBound + auto.stats.angleFloor + auto.stats.smallestDomainAngle;
  const asked: number | 'auto' = auto.options.maxAngle;
  const ok: boolean = am.validate(pslg, m).ok && stats.certified && m.status === 'ok';
  const files: string[] = [am.toNode(m), am.toEle(m), am.toPoly(m), am.toOBJ(m), am.toSVG(m), am.toJson(m), am.toOFF(m)];
  const solverFiles: string[] = [am.toEdge(m), am.toNeigh(m), am.toMSH(m), am.toMSH2(m), am.toVTU(m), am.write(m, 'msh2')];
  am.toMSH({ ...m, vertexMarkers: new Int32Array(0), segmentMarkers: new Int32Array(0), triangleAttributes: new Float64Array(0) });
  const x: number = m.points[0] + m.triangles[0] + m.segments.length + m.vertexKind.length;
  am.mesh({ points: [[0, 0], [1, 0], [0, 1]] }, { mode: 'delaunay' });
  am.mesh(rings);
  const { heapSize, allocated } = am.memory();
  const mode: Mode = am.vocabulary.modes[0].name;
  const svg: string = am.write(m, 'svg');
  const parsed: ParsedPslg = am.parseJson(text);
  const solution: string = am.write(am.mesh(parsed, { mode }), 'cgshop', parsed);
  const kind: VertexKindName = am.vocabulary.vertexKinds[m.vertexKind[0]].name;
  const quality: number = am.vocabulary.defaults.qualityMinAngle;
  void [svg, solution, kind, quality, parsed.format === 'cgshop', solverFiles];
  try {
    am.mesh({ points: [0, 0] });
  } catch (e) {
    if (e instanceof AcuteMeshError) {
      const code: ErrorCode = e.code;
      void code;
    }
  }
  const other = await createInstance({ maxMemory: 2 ** 28, wasmModule: am.wasmModule });
  const single = await initSingle({ wasmBinary: new Uint8Array(8) });
  const located = await createInstance({ wasmUrl: '/assets/acutemesh.wasm' });
  const stringified: string = JSON.stringify(am);
  const worker: MeshWorker = createMeshWorker();
  const placed = createMeshWorker({ workerUrl: new URL('https://example.org/mesh-worker.js'), init: { wasmUrl: '/acutemesh.wasm' } });
  const controller = new AbortController();
  const w: MeshResult = await worker.mesh(pslg, { mode: 'nonobtuse', signal: controller.signal, onProgress: (p) => void p.phase });
  worker.terminate();
  const shared = await meshInWorker(rings, { mode: 'quality', minAngle: 30 });
  void [ok, files, x, heapSize, allocated, other, single, w, shared, reached, asked, located, stringified, placed];

  // @ts-expect-error: not a mode
  am.mesh(pslg, { mode: 'obtuse' });
  // @ts-expect-error: not a fill rule
  am.fromRings([], { fill: 'winding' });
  // @ts-expect-error: points are required
  am.mesh({ segments: [0, 1] });
  // @ts-expect-error: maxArea is a number
  am.mesh(pslg, { maxArea: '1' });
  // @ts-expect-error: maxAngle is a number or 'auto'
  am.mesh(pslg, { maxAngle: 'lowest' });
  // @ts-expect-error: status is 'ok' | 'target-not-met'
  const bad: MeshResult['status'] = 'failed';
  // @ts-expect-error: the result's arrays are typed arrays
  const arr: number[] = m.points;
  // @ts-expect-error: no such writer
  am.toSTL(m);
  // @ts-expect-error: text, not a number
  am.parsePoly(42);
  // @ts-expect-error: no such format
  am.write(m, 'stl');
  // @ts-expect-error: a CG:SHOP solution needs its instance
  am.write(m, 'cgshop');
  // @ts-expect-error: a misspelt option
  am.mesh(pslg, { maxangle: 60 });
  // @ts-expect-error: a function cannot be posted to the worker
  createMeshWorker({ init: { locateFile: () => '/acutemesh.wasm' } });
  // @ts-expect-error: the vocabulary is read-only
  am.vocabulary.defaults.maxAngle = 80;
  void [bad, arr];
  return m.stats.triangles;
}
