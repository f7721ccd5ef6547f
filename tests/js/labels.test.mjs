// Regions and boundary markers through the npm package (issue 26): mesh() takes them in and
// gives them back (segmentInput, vertexMarkers, segmentMarkers, triangleAttributes), with
// options.adjacency the adjacency arrays; the parsers carry them; the worker transfers them;
// bad items are refused naming the item. The rules themselves are tested in C++
// (tests/cpp/test_labels.cpp); here, that everything arrives, checked against the geometry.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import init, { AcuteMeshError } from 'acutemesh';
import { meshInWorker, createMeshWorker } from 'acutemesh/worker';

const am = await init();

// A 4 x 3 rectangle split by the segment 1-4 ((1, 0)-(3, 3)): left region 7 (a later region
// over an earlier 1), right 2, and one outside. Markers per segment (the top's 0 becomes 1).
const split = () => ({
  points: [[0, 0], [1, 0], [4, 0], [4, 3], [3, 3], [0, 3]],
  segments: [[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0], [1, 4]],
  vertexMarkers: [5, 0, 0, 0, 0, 0],
  segmentMarkers: [11, 12, 13, 14, 0, 16, 20],
  regions: [{ x: 3.5, y: 1, attribute: 2 }, { x: 0.5, y: 1.5, attribute: 1, maxArea: 0.5 },
    { x: 10, y: 10, attribute: 9 }, { x: 0.2, y: 2.5, attribute: 7 }],
});
const segmentMarkers = [11, 12, 13, 14, 1, 16, 20];

// The side of the splitting line the triangle's farthest corner is on.
function left(m, t) {
  let best = 0;
  for (let k = 0; k < 3; ++k) {
    const v = m.triangles[3 * t + k];
    const o = 2 * (m.points[2 * v + 1] - 0) - 3 * (m.points[2 * v] - 1);  // (b - a) x (p - a)
    if (Math.abs(o) > Math.abs(best)) best = o;
  }
  return best > 0;
}

function checkLabels(m, what) {
  assert.ok(m.segmentInput instanceof Uint32Array, what);
  assert.ok(m.vertexMarkers instanceof Int32Array, what);
  assert.ok(m.segmentMarkers instanceof Int32Array, what);
  assert.ok(m.triangleAttributes instanceof Float64Array, what);
  assert.equal(m.segmentInput.length, m.segments.length / 2, what);
  assert.equal(m.segmentMarkers.length, m.segments.length / 2, what);
  assert.equal(m.vertexMarkers.length, m.points.length / 2, what);
  assert.equal(m.triangleAttributes.length, m.triangles.length / 3, what);
  for (let s = 0; s < m.segmentInput.length; ++s)
    assert.equal(m.segmentMarkers[s], segmentMarkers[m.segmentInput[s]], `${what}: edge ${s}`);
  for (let t = 0; t < m.triangles.length / 3; ++t)
    assert.equal(m.triangleAttributes[t], left(m, t) ? 7 : 2, `${what}: triangle ${t}`);
  assert.equal(m.vertexMarkers[0], 5, what);
  assert.equal(m.vertexMarkers[1], 11, what);  // (the lowest-numbered marked segment at it)
  assert.ok(m.stats.warnings.some((w) => w.includes('region 2 at (10, 10)')), what);
}

test('mesh() returns segmentInput, markers and attributes in every mode', () => {
  for (const mode of ['cdt', 'quality', 'acute', 'nonobtuse']) {
    const m = am.mesh(split(), { mode, maxArea: mode === 'cdt' ? 0 : 0.1 });
    checkLabels(m, mode);
    if (mode !== 'cdt') assert.ok(m.vertexKind.includes(2), `${mode}: Steiner points on segments`);
  }
  // Typed arrays in.
  const typed = split();
  typed.vertexMarkers = Int32Array.from(typed.vertexMarkers);
  typed.segmentMarkers = Int32Array.from(typed.segmentMarkers);
  checkLabels(am.mesh(typed, { mode: 'acute' }), 'typed');
  // Without regions: no attributes; without markers the boundary's are 1.
  const plain = am.mesh({ points: split().points, segments: split().segments });
  assert.equal(plain.triangleAttributes, undefined);
  assert.ok(plain.vertexMarkers.every((x) => x === 1));
});

test('options.adjacency returns the adjacency arrays', () => {
  const m = am.mesh(split(), { mode: 'quality', maxArea: 0.2, adjacency: true });
  assert.equal(m.options.adjacency, true);
  assert.ok(m.halfedges instanceof Int32Array);
  assert.equal(m.halfedges.length, m.triangles.length);
  for (let e = 0; e < m.halfedges.length; ++e) {
    const twin = m.halfedges[e];
    if (twin < 0) continue;
    assert.equal(m.halfedges[twin], e);
    const next = (h) => h - (h % 3) + ((h % 3) + 1) % 3;
    assert.equal(m.triangles[twin], m.triangles[next(e)]);
  }
  assert.ok(m.neighbors instanceof Int32Array);
  assert.equal(m.neighbors.length, m.triangles.length);
  assert.ok(m.edges instanceof Uint32Array);
  assert.ok(m.edgeMarkers instanceof Int32Array);
  assert.equal(m.edgeMarkers.length, m.edges.length / 2);
  // Every segment edge's marker is on its edge.
  const markerOf = new Map();
  for (let e = 0; e < m.edgeMarkers.length; ++e) markerOf.set(`${m.edges[2 * e]},${m.edges[2 * e + 1]}`, m.edgeMarkers[e]);
  for (let s = 0; s < m.segmentMarkers.length; ++s) {
    const a = m.segments[2 * s], b = m.segments[2 * s + 1];
    assert.equal(markerOf.get(`${Math.min(a, b)},${Math.max(a, b)}`), m.segmentMarkers[s]);
  }
  assert.ok(m.hull instanceof Uint32Array && m.hullStarts instanceof Uint32Array);
  assert.deepEqual(Array.from(m.hullStarts), [0, m.hull.length]);
  // Not asked: not there.
  assert.equal(am.mesh(split()).halfedges, undefined);
  assert.throws(() => am.mesh(split(), { adjacency: 1 }), TypeError);
});

test('the parsers carry markers and regions, and mesh() takes them back', () => {
  const poly = am.parsePoly(`6 2 0 1
0 0 0 5
1 1 0 0
2 4 0
3 4 3 0
4 3 3 0
5 0 3 0
7 1
0 0 1 11
1 1 2 12
2 2 3 13
3 3 4 14
4 4 5
5 5 0 16
6 1 4 20
0
4
0 3.5 1 2 0.5
1 0.5 1.5 1 -1
2 10 10 9
3 0.2 2.5 7
`);
  assert.deepEqual(Array.from(poly.vertexMarkers), [5, 0, 0, 0, 0, 0]);
  assert.deepEqual(Array.from(poly.segmentMarkers), [11, 12, 13, 14, 0, 16, 20]);
  assert.deepEqual(poly.regions[0], { x: 3.5, y: 1, attribute: 2, maxArea: 0.5 });
  assert.equal(poly.regions[1].maxArea, 0);
  checkLabels(am.mesh(poly, { mode: 'nonobtuse' }), 'poly');

  const { points, segments, vertexMarkers, regions } = split();
  const json = am.parseJson(JSON.stringify({
    vertices: points, segments, vertexMarkers, segmentMarkers: split().segmentMarkers,
    regions: regions.map((r) => (r.maxArea === undefined ? [r.x, r.y, r.attribute] : [r.x, r.y, r.attribute, r.maxArea])),
  }));
  assert.equal(json.regions.length, 4);
  checkLabels(am.mesh(json), 'json');

  const rings = am.parseJson('{"rings": [[[0,0],[4,0],[4,4],[0,4]], [[1,1],[2,1],[2,2]]], "ringMarkers": [3, -4], "regions": [[3, 3, 1.5]]}');
  assert.deepEqual(Array.from(rings.segmentMarkers), [3, 3, 3, 3, -4, -4, -4]);
  const fromRings = am.fromRings([[[0, 0], [4, 0], [4, 4], [0, 4]], [[1, 1], [2, 1], [2, 2]]], { ringMarkers: [3, -4] });
  assert.deepEqual(Array.from(fromRings.segmentMarkers), [3, 3, 3, 3, -4, -4, -4]);
  const m = am.mesh({ ...fromRings, regions: rings.regions });
  assert.ok(Array.from(m.segmentMarkers).every((x) => x === 3 || x === -4));
  assert.ok(Array.from(m.triangleAttributes).every((x) => x === 1.5));

  // A plain input keeps its old shape.
  const bare = am.parsePoly('3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n3 0\n0 0 1\n1 1 2\n2 2 0\n0\n');
  assert.equal(bare.vertexMarkers, undefined);
  assert.equal(bare.regions, undefined);
});

test('bad markers and regions are refused naming the item', () => {
  const bad = (change) => ({ ...split(), ...change });
  assert.throws(() => am.mesh(bad({ vertexMarkers: [1, 2] })),
    (e) => e instanceof AcuteMeshError && e.code === 'BAD_INPUT' && /vertexMarkers has 2 markers; expected one per vertex \(6\)/.test(e.message));
  assert.throws(() => am.mesh(bad({ segmentMarkers: [1, 2, 3, 4, 5, 6, 2.5] })),
    (e) => e.code === 'BAD_INPUT' && /pslg\.segmentMarkers\[6\] is 2\.5/.test(e.message));
  assert.throws(() => am.mesh(bad({ vertexMarkers: [1, 2, 3, 4, 5, 2 ** 31] })),
    (e) => e.code === 'BAD_INPUT' && /pslg\.vertexMarkers\[5\]/.test(e.message));
  assert.throws(() => am.mesh(bad({ segmentMarkers: [1, 2, 3, 4, 5, 6, '7'] })),
    (e) => e instanceof TypeError && /pslg\.segmentMarkers\[6\]/.test(e.message));
  assert.throws(() => am.mesh(bad({ regions: [{ x: 1, y: NaN, attribute: 1 }] })),
    (e) => e.code === 'BAD_INPUT' && /region 0 has a non-finite coordinate/.test(e.message));
  assert.throws(() => am.mesh(bad({ regions: [{ x: 1, y: 1 }, { x: 1, y: 1, maxArea: -2 }] })),
    (e) => e.code === 'BAD_INPUT' && /region 1 has maxArea -2/.test(e.message));
  assert.throws(() => am.mesh(bad({ regions: [{ x: 1, y: 1, attribute: '3' }] })),
    (e) => e instanceof TypeError && /pslg\.regions\[0\]\.attribute must be a number/.test(e.message));
  assert.throws(() => am.mesh(bad({ regions: [{ x: 1, y: 1, area: 3 }] })),
    (e) => e instanceof TypeError && /'area' of pslg\.regions\[0\]/.test(e.message));
  assert.throws(() => am.mesh(bad({ regions: [[1, 1, 3]] })),
    (e) => e instanceof TypeError && /pslg\.regions\[0\] must be an object/.test(e.message));
  assert.throws(() => am.fromRings([[[0, 0], [1, 0], [0, 1]]], { ringMarkers: [1, 2] }),
    (e) => e.code === 'BAD_INPUT' && /ringMarkers has 2 markers; expected one per ring \(1\)/.test(e.message));
});

test('the worker carries markers, regions and adjacency', { timeout: 120000 }, async () => {
  const here = am.mesh(split(), { mode: 'acute', adjacency: true });
  const there = await meshInWorker(split(), { mode: 'acute', adjacency: true });
  for (const key of ['segmentInput', 'vertexMarkers', 'segmentMarkers', 'triangleAttributes',
    'halfedges', 'neighbors', 'edges', 'edgeMarkers', 'hull', 'hullStarts']) {
    assert.ok(ArrayBuffer.isView(there[key]), key);
    assert.deepEqual(there[key], here[key], key);
  }
  checkLabels(there, 'worker');
  const w = createMeshWorker();
  try {
    await assert.rejects(w.mesh(split(), { adjacncy: true }), /did you mean 'adjacency'/);
  } finally {
    w.terminate();
  }
});
