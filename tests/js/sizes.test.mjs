// Sizes through the npm package (issue 26): maxEdge, size (a function, a grid, scattered
// points, an area function), grading and the regions' maxArea reach the core and the mesh
// meets them, measured here from the triangles; what the caller's function throws or returns
// wrong comes back as an error; a worker takes grids and points but refuses functions. The
// rules themselves are tested in C++ (tests/cpp/test_sizes.cpp).
import { test } from 'node:test';
import assert from 'node:assert/strict';

import init, { AcuteMeshError } from 'acutemesh';
import { meshInWorker } from 'acutemesh/worker';

const am = await init();

// A 10 x 4 rectangle with a square hole.
const plate = () => ({
  points: [[0, 0], [10, 0], [10, 4], [0, 4], [4, 1], [6, 1], [6, 3], [4, 3]],
  segments: [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]],
  holes: [[5, 2]],
});

// The largest ratio over the triangles of the longest edge to h at the centroid.
function worstRatio(m, h) {
  const p = m.points;
  let worst = 0;
  for (let t = 0; t < m.triangles.length; t += 3) {
    const v = [m.triangles[t], m.triangles[t + 1], m.triangles[t + 2]];
    let longest = 0;
    for (let k = 0; k < 3; ++k) {
      const a = v[k], b = v[(k + 1) % 3];
      longest = Math.max(longest, Math.hypot(p[2 * a] - p[2 * b], p[2 * a + 1] - p[2 * b + 1]));
    }
    const cx = (p[2 * v[0]] + p[2 * v[1]] + p[2 * v[2]]) / 3;
    const cy = (p[2 * v[0] + 1] + p[2 * v[1] + 1] + p[2 * v[2] + 1]) / 3;
    worst = Math.max(worst, longest / h(cx, cy));
  }
  return worst;
}

function expectMet(m, what) {
  assert.equal(m.status, 'ok', `${what}: ${m.message}`);
  assert.ok(m.stats.targetMet, what);
  assert.ok(m.stats.sizeRatio > 0 && m.stats.sizeRatio <= 1, `${what}: sizeRatio ${m.stats.sizeRatio}`);
  assert.ok(am.validate(plate(), m).ok, what);
}

test('maxEdge bounds every edge in every refining mode', () => {
  for (const mode of ['quality', 'nonobtuse', 'acute']) {
    const m = am.mesh(plate(), { mode, maxEdge: 0.4 });
    expectMet(m, mode);
    const worst = worstRatio(m, () => 0.4);
    assert.ok(worst <= 1 && worst > 0.7, `${mode}: ${worst}`);
    assert.equal(m.options.maxEdge, 0.4);
    if (mode !== 'quality') assert.ok(m.stats.certified, mode);
  }
});

test('a size function is called at the caller\'s coordinates and met', () => {
  let calls = 0;
  let inBox = true;
  const h = (x, y) => {
    ++calls;
    if (!(x >= 0 && x <= 10 && y >= 0 && y <= 4)) inBox = false;
    return 0.1 + 0.1 * x;
  };
  const m = am.mesh(plate(), { mode: 'acute', size: h });
  expectMet(m, 'function');
  assert.ok(calls > 0);
  assert.ok(inBox, 'called outside the input\'s box');
  assert.ok(worstRatio(m, (x) => 0.1 + 0.1 * x) <= 1);
  assert.equal(m.options.size.function, h);
  const again = am.mesh(plate(), { mode: 'acute', size: { function: h } });
  assert.deepEqual(again.triangles, m.triangles);
});

test('a grid, scattered points and grading', () => {
  // 2 x 2 nodes over the box, bilinear: h = 0.2 + 0.1 x.
  const grid = { x0: 0, y0: 0, dx: 10, dy: 4, nx: 2, ny: 2, h: [0.2, 1.2, 0.2, 1.2] };
  const g = am.mesh(plate(), { mode: 'nonobtuse', size: { grid } });
  expectMet(g, 'grid');
  assert.ok(worstRatio(g, (x) => 0.2 + 0.1 * x) <= 1);
  assert.ok(g.options.size.grid.h instanceof Float64Array);
  // Three points around the box, linear between them: h = 0.3 + 0.05 x + 0.05 y.
  const s = am.mesh(plate(), {
    mode: 'acute',
    size: { points: [[-1, -1], [20, -1], [-1, 20]], sizes: new Float64Array([0.2, 1.25, 1.25]) },
  });
  expectMet(s, 'points');
  assert.ok(worstRatio(s, (x, y) => 0.3 + 0.05 * (x + y)) <= 1 + 1e-9);
  // A small size at the left edge only, maxEdge 2: grading 0.2 makes more triangles.
  const sharp = { mode: 'acute', maxEdge: 2, size: { grid: { x0: 0, y0: 0, dx: 1, dy: 4, nx: 2, ny: 2, h: [0.05, 2, 0.05, 2] } } };
  const a = am.mesh(plate(), sharp);
  const b = am.mesh(plate(), { ...sharp, grading: 0.2 });
  expectMet(a, 'no grading');
  expectMet(b, 'grading');
  assert.ok(b.triangles.length > 1.5 * a.triangles.length, `${b.triangles.length} vs ${a.triangles.length}`);
  assert.equal(b.options.grading, 0.2);
});

test('each region\'s maxArea and an area function', () => {
  const input = { ...plate(), regions: [{ x: 1, y: 2, attribute: 1, maxArea: 0.01 }] };
  const m = am.mesh(input, { mode: 'acute' });
  assert.equal(m.status, 'ok', m.message);
  const p = m.points;
  for (let t = 0; t < m.triangles.length; t += 3) {
    const [a, b, c] = [m.triangles[t], m.triangles[t + 1], m.triangles[t + 2]];
    const area = ((p[2 * b] - p[2 * a]) * (p[2 * c + 1] - p[2 * a + 1]) -
      (p[2 * c] - p[2 * a]) * (p[2 * b + 1] - p[2 * a + 1])) / 2;
    assert.ok(area <= 0.01 * (1 + 1e-12), `triangle ${t / 3}: ${area}`);
  }
  const f = am.mesh(plate(), { mode: 'acute', size: { maxArea: (x) => 0.001 + 0.01 * x } });
  expectMet(f, 'area function');
});

test('bad sizes are errors that name what is wrong', () => {
  const boom = new Error('boom');
  assert.throws(() => am.mesh(plate(), { mode: 'acute', size: () => { throw boom; } }), (e) => e === boom);
  assert.throws(() => am.mesh(plate(), { mode: 'acute', size: () => 'big' }),
    { name: 'TypeError', message: /options\.size\.function must return a number, not string \(at / });
  assert.throws(() => am.mesh(plate(), { mode: 'acute', size: () => -1 }),
    (e) => e instanceof AcuteMeshError && e.code === 'BAD_INPUT' && /the size function returned -1 at \(/.test(e.message));
  assert.throws(() => am.mesh(plate(), { mode: 'acute', size: { maxArea: () => 0 } }),
    /the maxArea function returned 0 at \(/);
  assert.throws(() => am.mesh(plate(), { mode: 'acute', maxEdge: -1 }),
    (e) => e.code === 'BAD_INPUT' && /maxEdge must be a finite number >= 0/.test(e.message));
  assert.throws(() => am.mesh(plate(), { mode: 'acute', grading: Infinity }), /grading must be a finite number >= 0/);
  assert.throws(() => am.mesh(plate(), { mode: 'acute', maxEdge: '1' }), { name: 'TypeError', message: /options\.maxEdge must be a number/ });
  assert.throws(() => am.mesh(plate(), { maxedge: 1 }), /did you mean 'maxEdge'/);
  assert.throws(() => am.mesh(plate(), { size: { grid: {} } }), /options\.size\.grid\.x0 must be a number/);
  assert.throws(() => am.mesh(plate(), { size: { grid: { x0: 0, y0: 0, dx: 1, dy: 1, nx: 1.5, ny: 1, h: [1] } } }),
    (e) => e.code === 'BAD_INPUT' && /options\.size\.grid\.nx must be a whole number/.test(e.message));
  assert.throws(() => am.mesh(plate(), { mode: 'acute', size: { grid: { x0: 0, y0: 0, dx: 1, dy: 1, nx: 2, ny: 2, h: [1, 1, 1] } } }),
    /h must hold nx \* ny = 4 values, found 3/);
  assert.throws(() => am.mesh(plate(), { mode: 'acute', size: { points: [0, 0, 1, 1], sizes: [1] } }),
    /size points: 4 coordinates for 1 sizes/);
  assert.throws(() => am.mesh(plate(), { size: { grdi: {} } }), /did you mean 'grid'/);
  assert.throws(() => am.mesh(plate(), { size: 3 }), { name: 'TypeError', message: /options\.size must be an object/ });
  // A size in a mode that does not refine is said, not silently dropped.
  const cdt = am.mesh(plate(), { maxEdge: 1 });
  assert.ok(cdt.stats.warnings.some((w) => w.includes('sizes have no effect in mode cdt')));
});

test('a worker takes grids and points, and refuses functions', { timeout: 120000 }, async () => {
  const size = { grid: { x0: 0, y0: 0, dx: 10, dy: 4, nx: 2, ny: 2, h: [0.2, 1.2, 0.2, 1.2] } };
  const here = am.mesh(plate(), { mode: 'acute', size, grading: 0.3 });
  const there = await meshInWorker(plate(), { mode: 'acute', size, grading: 0.3 });
  assert.deepEqual(there.triangles, here.triangles);
  assert.deepEqual(there.points, here.points);
  await assert.rejects(meshInWorker(plate(), { mode: 'acute', size: () => 1 }),
    { name: 'TypeError', message: /a function cannot be sent to a worker/ });
  await assert.rejects(meshInWorker(plate(), { mode: 'acute', size: { maxArea: () => 1 } }),
    /a function cannot be sent to a worker/);
});
