// Errors: bad input is an AcuteMeshError naming the item, wrong argument types are
// TypeErrors, cancellation is an AbortError, running out of wasm memory is an AcuteMeshError;
// after each the same API object keeps working and its heap holds nothing from the failed call.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import init, { AcuteMeshError, createInstance } from 'acutemesh';

const am = await init();
const square = { points: [0, 0, 1, 0, 1, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0] };

function stillWorks(api) {
  const m = api.mesh(square, { mode: 'acute' });
  assert.ok(m.stats.certified);
  assert.ok(api.validate(square, m).ok);
}

function rejects(f, code, pattern) {
  assert.throws(f, (e) => {
    assert.ok(e instanceof AcuteMeshError, `${e && e.name}: ${e && e.message}`);
    assert.equal(e.name, 'AcuteMeshError');
    assert.equal(e.code, code);
    assert.match(e.message, pattern);
    return true;
  });
}

test('bad input: AcuteMeshError BAD_INPUT naming the item, and the module stays usable', () => {
  const before = am.memory().allocated;
  rejects(() => am.parsePoly('3 2 0 0\n0 0 0\n1 1 x\n2 0 1\n'), 'BAD_INPUT', /^input\.poly:3: expected y coordinate/);
  rejects(() => am.parsePoly('4 2 0 0\n0 0 0\n', { name: 'plate.poly' }), 'BAD_INPUT', /^plate\.poly:\d+: /);
  rejects(() => am.parseJson('{"rings": [[[0,0],[1,0]]]}'), 'BAD_INPUT', /ring of at least 3/);
  rejects(() => am.parseJson('{"vertices": [[0,0],[1,0]'), 'BAD_INPUT', /^input\.json:1: /);
  rejects(() => am.mesh({ points: [0, 0, 1, 0, 0, 1], segments: [0, 7] }), 'BAD_INPUT',
    /segment 0 refers to vertex 7, but there are only 3 vertices/);
  rejects(() => am.mesh({ points: [0, 0, 1, NaN, 0, 1] }), 'BAD_INPUT', /vertex 1 has a non-finite coordinate/);
  rejects(() => am.mesh({ points: [0, 0, 1, 0, 2, 0] }), 'BAD_INPUT', /collinear/);
  rejects(() => am.mesh({ points: [0, 0, 1, 0, 0, 1], segments: [0, -1] }), 'BAD_INPUT', /segments\[1\] is -1/);
  rejects(() => am.mesh({ points: [0, 0, 1, 0, 0] }), 'BAD_INPUT', /odd length 5/);
  rejects(() => am.mesh(square, { mode: 'obtuse' }), 'BAD_INPUT', /unknown mode 'obtuse' \(delaunay, cdt/);
  rejects(() => am.mesh(square, { fill: 'holes' }), 'BAD_INPUT', /unknown fill rule 'holes'/);
  rejects(() => am.mesh(square, { mode: 'acute', maxAngle: 50 }), 'BAD_INPUT', /maxAngle/);
  for (const bad of ['autox', 59, 90.5, 60, 0, NaN, 'Auto'])
    rejects(() => am.mesh(square, { mode: 'acute', maxAngle: bad }), 'BAD_INPUT',
      /^maxAngle must be above 60 and at most 90 degrees, or 'auto', not /);
  rejects(() => am.mesh(square, { mode: 'nonobtuse', maxAngle: 'auto' }), 'BAD_INPUT', /maxAngle auto needs mode acute/);
  assert.throws(() => am.mesh(square, { mode: 'acute', maxAngle: true }), TypeError);
  rejects(() => am.mesh(square, { mode: 'quality', minAngle: 61 }), 'BAD_INPUT', /minAngle/);
  rejects(() => am.mesh(square, { maxSteiner: 1.5 }), 'BAD_INPUT', /maxSteiner/);
  rejects(() => am.mesh(square, { timeLimit: -1 }), 'BAD_INPUT', /timeLimit/);
  rejects(() => am.fromRings([[[0, 0], [1, 1], [0, 0]]]), 'BAD_INPUT', /rings\[0\] has 2 distinct points/);
  rejects(() => am.toSVG({ points: [0, 0, 1, 0, 0, 1], triangles: [0, 1, 3] }), 'BAD_INPUT',
    /mesh\.triangles\[2\] refers to vertex 3, but there are only 3 vertices/);
  assert.equal(am.memory().allocated, before);
  stillWorks(am);
});

test('wrong argument types: TypeError naming the argument', () => {
  const typeError = (f, pattern) => assert.throws(f, (e) => e instanceof TypeError && pattern.test(e.message));
  typeError(() => am.mesh(), /pslg must be an object, not undefined/);
  typeError(() => am.mesh('0 0 1 0 0 1'), /pslg must be an object, not string/);
  typeError(() => am.mesh({ segments: [] }), /pslg\.points is missing/);
  typeError(() => am.mesh({ points: 'abc' }), /pslg\.points must be a Float64Array or an array of numbers/);
  typeError(() => am.mesh({ points: [0, 0, '1', 0, 0, 1] }), /pslg\.points\[2\] must be a number, not string/);
  typeError(() => am.mesh({ points: [[0, 0], [1], [0, 1]] }), /pslg\.points\[1\] must be an \[x, y\] pair/);
  typeError(() => am.mesh({ points: [0, 0, 1, 0, 0, 1], segments: {} }), /pslg\.segments must be a Uint32Array/);
  typeError(() => am.mesh(square, { mode: 4 }), /mode must be a string, not number/);
  typeError(() => am.mesh(square, { maxArea: '1' }), /options\.maxArea must be a number, not string/);
  typeError(() => am.mesh(square, { convexHull: 1 }), /options\.convexHull must be a boolean/);
  typeError(() => am.mesh(square, { exactSegments: 'yes' }), /options\.exactSegments must be a boolean/);
  typeError(() => am.mesh(square, { exactFeet: 1 }), /options\.exactFeet must be a boolean/);
  typeError(() => am.toJson({ points: [0, 0, 1, 0, 0, 1], triangles: [0, 1, 2], exactPoints: {} }),
            /mesh\.exactPoints must be an array/);
  rejects(() => am.toJson({ points: [0, 0, 1, 0, 0, 1], triangles: [0, 1, 2], exactPoints: [{ vertex: 1, x: '1/0', y: '0' }] }),
          'BAD_INPUT', /mesh\.exactPoints\[0\]\.x must be a rational "p\/q" or "p"/);
  typeError(() => am.mesh(square, { onProgress: 1 }), /options\.onProgress must be a function/);
  typeError(() => am.mesh(square, { signal: {} }), /options\.signal must be an AbortSignal/);
  typeError(() => am.parsePoly(42), /text must be a string, not number/);
  typeError(() => am.fromRings({}), /rings must be an array of rings/);
  typeError(() => am.toOBJ({ points: [] }), /mesh\.triangles is missing/);
  typeError(() => am.validate(square, null), /mesh must be an object, not null/);
  stillWorks(am);
});

test('cancellation: an aborted signal stops mesh() with its reason; onProgress errors propagate', () => {
  const fine = { mode: 'quality', maxArea: 1e-5 };  // about 200,000 triangles: several reports
  const aborted = AbortSignal.abort();
  assert.throws(() => am.mesh(square, { ...fine, signal: aborted }), (e) => e.name === 'AbortError');

  // Reports come about every 40 ms of work: a run of a few hundred ms, cut at its second.
  const longer = { mode: 'quality', maxArea: 2e-6 };
  const controller = new AbortController();
  let reports = 0;
  const t0 = performance.now();
  assert.throws(() => am.mesh(square, {
    ...longer,
    signal: controller.signal,
    onProgress: (p) => { if (p.phase === 'refine' && ++reports === 2) controller.abort(); },
  }), (e) => e.name === 'AbortError');
  const cancelledAfter = performance.now() - t0;
  const full = am.mesh(square, longer);
  assert.ok(full.stats.triangles > 500000, `${full.stats.triangles} triangles`);
  assert.ok(cancelledAfter < full.stats.seconds * 1000, `cancelled after ${cancelledAfter} ms, full run ${full.stats.seconds * 1000} ms`);

  const reason = new Error('stop here');
  const c2 = new AbortController();
  assert.throws(() => am.mesh(square, { ...fine, signal: c2.signal, onProgress: () => c2.abort(reason) }),
    (e) => e === reason);

  const oops = new RangeError('callback failed');
  assert.throws(() => am.mesh(square, { ...fine, onProgress: () => { throw oops; } }), (e) => e === oops);
  stillWorks(am);
});

test('out of memory: AcuteMeshError OUT_OF_MEMORY, then the same object works again', async () => {
  // A 64 MB heap cannot hold the Delaunay triangulation of 10^6 points (about 140 MB).
  const small = await createInstance({ maxMemory: 64 * 2 ** 20 });
  const start = small.memory();
  const points = new Float64Array(2e6);
  let seed = 1;
  for (let i = 0; i < points.length; ++i) points[i] = (seed = (seed * 48271) % 2147483647) / 2147483647;
  rejects(() => small.mesh({ points }, { mode: 'delaunay' }), 'OUT_OF_MEMORY', /out of memory.*64 MB/);
  // A fresh instance: the heap is back to where it started, and meshing works.
  assert.deepEqual(small.memory(), start);
  stillWorks(small);
  // 10^5 points fit.
  const m = small.mesh({ points: points.subarray(0, 2e5) }, { mode: 'delaunay' });
  assert.ok(m.stats.triangles > 190000);
  rejects(() => small.mesh({ points }, { mode: 'delaunay' }), 'OUT_OF_MEMORY', /out of memory/);
  stillWorks(small);
  // A text too big for the heap: the parser's copy of it cannot be allocated.
  const lines = ['3000000 2 0 0'];
  for (let i = 0; i < 3e6; ++i) lines.push(`${i} ${points[i % points.length]} ${points[(i + 1) % points.length]}`);
  rejects(() => small.parseNode(lines.join('\n')), 'OUT_OF_MEMORY', /out of memory/);
  assert.deepEqual(small.memory(), start);
  stillWorks(small);
  stillWorks(am);  // other instances were never affected
});
