// Option objects and numbers as users slip on them: an unknown option key is a TypeError
// naming it and the nearest valid one (mesh(), validate(), the parsers, fromRings(), init(),
// createMeshWorker() and the worker's mesh()); maxAngle's range is the one the types and the
// docs state; points of three numbers are refused naming the item; JSON.stringify of the API
// object works, and the JSON writer is toJson (toJSON still writes a mesh).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

import init, { createInstance } from 'acutemesh';
import { createMeshWorker } from 'acutemesh/worker';
import { root } from './helpers.mjs';

const am = await init();
const square = { points: [0, 0, 1, 0, 1, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0] };

// A TypeError whose message names `key` and `where`, and suggests `nearest` (or nothing).
function unknownKey(key, where, nearest) {
  return (e) => {
    assert.ok(e instanceof TypeError, `${e && e.name}: ${e && e.message}`);
    assert.match(e.message, new RegExp(`^unknown option '${key}' of ${where.replace(/[()]/g, '\\$&')} \\(`));
    if (nearest) assert.ok(e.message.endsWith(`: did you mean '${nearest}'?`), e.message);
    else assert.doesNotMatch(e.message, /did you mean/);
    return true;
  };
}

test('a misspelt mesh() option is a TypeError naming it and the nearest option', () => {
  assert.throws(() => am.mesh(square, { mode: 'acute', maxangle: 60 }), unknownKey('maxangle', 'mesh()', 'maxAngle'));
  assert.throws(() => am.mesh(square, { minangle: 20 }), unknownKey('minangle', 'mesh()', 'minAngle'));
  assert.throws(() => am.mesh(square, { convexhull: true }), unknownKey('convexhull', 'mesh()', 'convexHull'));
  assert.throws(() => am.mesh(square, { timelimit: 1 }), unknownKey('timelimit', 'mesh()', 'timeLimit'));
  assert.throws(() => am.mesh(square, { onprogress: () => {} }), unknownKey('onprogress', 'mesh()', 'onProgress'));
  assert.throws(() => am.mesh(square, { mdoe: 'acute' }), unknownKey('mdoe', 'mesh()', 'mode'));
  // Nothing near: the choices only.
  assert.throws(() => am.mesh(square, { threads: 2 }), unknownKey('threads', 'mesh()'));
  // The message lists every option.
  assert.throws(() => am.mesh(square, { x: 1 }), (e) => e.message === "unknown option 'x' of mesh() " +
    '(mode, fill, convexHull, exactSegments, exactFeet, maxAngle, minAngle, maxArea, maxEdge, size, grading, maxSteiner, timeLimit, onProgress, signal, adjacency, optimize, optimizeTries, seed)');
  // Present but undefined is still a slip.
  assert.throws(() => am.mesh(square, { maxangle: undefined }), unknownKey('maxangle', 'mesh()', 'maxAngle'));
});

test('every option mesh() documents is accepted, and a result\'s options go back in', () => {
  const { qualityMinAngle, ringsFill, ...defaults } = am.vocabulary.defaults;
  void [qualityMinAngle, ringsFill];
  const controller = new AbortController();
  const m = am.mesh(square, { ...defaults, mode: 'acute', onProgress: () => {}, signal: controller.signal });
  assert.ok(m.stats.certified);
  assert.deepEqual(Object.keys(m.options).sort(), Object.keys(defaults).sort());
  assert.ok(am.mesh(square, m.options).stats.certified);
  assert.ok(am.validate(square, m, m.options).ok);
  assert.throws(() => am.validate(square, m, { mode: 'acute', exactsegments: true }),
    unknownKey('exactsegments', 'validate()', 'exactSegments'));
});

test('the parsers, fromRings() and init() refuse unknown options too', async () => {
  assert.throws(() => am.parsePoly('3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n', { nodetext: '' }),
    unknownKey('nodetext', 'parsePoly()', 'nodeText'));
  assert.throws(() => am.parseJson('{"rings": [[[0,0],[1,0],[0,1]]]}', { nmae: 'x.json' }),
    unknownKey('nmae', 'parseJson()', 'name'));
  assert.throws(() => am.parseNode('3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n', { fill: 'evenodd' }),
    unknownKey('fill', 'parseNode()'));
  assert.throws(() => am.fromRings([[[0, 0], [1, 0], [0, 1]]], { fil: 'nonzero' }),
    unknownKey('fil', 'fromRings()', 'fill'));
  await assert.rejects(createInstance({ maxmemory: 2 ** 28 }), unknownKey('maxmemory', 'init()', 'maxMemory'));
  await assert.rejects(createInstance({ wasmURL: 'x.wasm' }), unknownKey('wasmURL', 'init()', 'wasmUrl'));
});

test('createMeshWorker() and the worker\'s mesh() refuse unknown options', async () => {
  assert.throws(() => createMeshWorker({ workerURL: 'w.js' }), unknownKey('workerURL', 'createMeshWorker()', 'workerUrl'));
  assert.throws(() => createMeshWorker({ init: { wasmurl: 'x.wasm' } }),
    unknownKey('wasmurl', 'createMeshWorker() init', 'wasmUrl'));
  assert.throws(() => createMeshWorker({ init: { locateFile: () => 'x.wasm' } }),
    /^TypeError: options\.init\.locateFile cannot be sent to a worker \(it is a function\): pass the URL as init\.wasmUrl$/);
  const worker = createMeshWorker();
  try {
    await assert.rejects(worker.mesh(square, { mode: 'acute', maxangle: 80 }), unknownKey('maxangle', 'mesh()', 'maxAngle'));
    assert.ok((await worker.mesh(square, { mode: 'acute', maxAngle: 80 })).stats.certified);
  } finally {
    worker.terminate();
  }
});

test('maxAngle: 60 < maxAngle <= 90 at run time, in the types and in the docs', () => {
  for (const ok of [60.001, 75, 89.999, 90, 'auto'])
    assert.doesNotThrow(() => am.mesh(square, { mode: 'acute', maxAngle: ok }), `maxAngle ${ok}`);
  for (const bad of [60, 59.999, 90.001, 120, -80])
    assert.throws(() => am.mesh(square, { mode: 'acute', maxAngle: bad }),
      (e) => e.code === 'BAD_INPUT' && e.message === `maxAngle must be above 60 and at most 90 degrees, or 'auto', not ${bad}`);
  // The range the message states is the one the types and docs/js.md state.
  const dts = readFileSync(join(root, 'wasm', 'types', 'index.d.ts'), 'utf8');
  const docs = readFileSync(join(root, 'docs', 'js.md'), 'utf8');
  assert.match(dts, /every angle < maxAngle, 60 < maxAngle <= 90 \(default 90\)/);
  assert.match(docs, /\| `maxAngle` \| 90 \| acute: every angle below it, 60 < maxAngle <= 90,/);
});

test('a point of three numbers is refused, naming the item', () => {
  const planar = (f, what, n) => assert.throws(f, (e) => e instanceof TypeError &&
    e.message === `${what} has ${n} numbers; a point is an [x, y] pair (the mesh is planar)`);
  planar(() => am.mesh({ points: [[0, 0, 0], [1, 0, 0], [0, 1, 0]] }), 'pslg.points[0]', 3);
  planar(() => am.mesh({ points: [[0, 0], [1, 0], [0, 1, 5]] }), 'pslg.points[2]', 3);
  planar(() => am.mesh({ ...square, holes: [[0.5, 0.5, 0]] }), 'pslg.holes[0]', 3);
  planar(() => am.fromRings([[[0, 0], [1, 0], [0, 1, 2, 3]]]), 'rings[0][2]', 4);
  planar(() => am.validate(square, { points: [[0, 0, 1], [1, 0], [0, 1]], triangles: [0, 1, 2] }), 'mesh.points[0]', 3);
  assert.throws(() => am.mesh({ points: [[0, 0], [1], [0, 1]] }), /^TypeError: pslg\.points\[1\] must be an \[x, y\] pair of numbers$/);
  assert.equal(am.mesh({ points: [[0, 0], [1, 0], [0, 1]] }).stats.triangles, 1);
});

test('JSON.stringify of the API object works; the JSON writer is toJson', () => {
  const data = JSON.parse(JSON.stringify(am));
  assert.equal(data.version, am.version);
  assert.deepEqual(data.vocabulary, JSON.parse(JSON.stringify(am.vocabulary)));
  assert.deepEqual(JSON.parse(JSON.stringify({ am })).am, data);
  const m = am.mesh(square, { mode: 'acute' });
  const json = am.toJson(m);
  assert.equal(json, am.write(m, 'json'));
  assert.equal(am.toJSON(m), json);  // the earlier name still writes a mesh
  assert.ok(!Object.keys(am).includes('toJSON'));
  assert.throws(() => am.toJson('x'), /^TypeError: mesh must be an object, not string$/);
});
