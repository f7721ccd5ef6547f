// The npm package's API on dist/ (imported by its own name, so package.json's exports map is
// what resolves it): every mode on every fixture, each result checked by the core's validate()
// and, independently, by the properties the mode promises computed here in JavaScript.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

import init, { AcuteMeshError, createInstance } from 'acutemesh';
import initSingle from 'acutemesh/single';
import {
  fixtures, load, label, reference, testData, needsReference, referenceFile, referencePolys, instanceFiles, syntheticCgshop,
  assertBestSoFar,
} from './helpers.mjs';

const am = await init();

// Cosine of the angle at corner k of triangle t (floating point: an independent sanity check,
// the exact certificate is the core's).
function cornerCosines(m, t) {
  const p = m.points, tri = m.triangles;
  const out = [];
  for (let k = 0; k < 3; ++k) {
    const a = tri[3 * t + k], b = tri[3 * t + (k + 1) % 3], c = tri[3 * t + (k + 2) % 3];
    const ux = p[2 * b] - p[2 * a], uy = p[2 * b + 1] - p[2 * a + 1];
    const vx = p[2 * c] - p[2 * a], vy = p[2 * c + 1] - p[2 * a + 1];
    out.push((ux * vx + uy * vy) / Math.hypot(ux, uy) / Math.hypot(vx, vy));
  }
  return out;
}

// What every mesh must satisfy whatever the mode: typed arrays of consistent sizes, indices in
// range, input vertices kept at their indices, counter-clockwise triangles.
function checkShape(pslg, m) {
  assert.ok(m.points instanceof Float64Array);
  assert.ok(m.triangles instanceof Uint32Array);
  assert.ok(m.segments instanceof Uint32Array);
  assert.ok(m.vertexKind instanceof Uint8Array);
  const n = m.points.length / 2;
  assert.equal(m.vertexKind.length, n);
  assert.equal(m.stats.vertices, n);
  assert.equal(m.stats.triangles, m.triangles.length / 3);
  assert.ok(m.triangles.length > 0, 'no triangles');
  for (const i of m.triangles) assert.ok(i < n);
  for (const i of m.segments) assert.ok(i < n);
  assert.deepEqual(m.points.subarray(0, pslg.points.length), pslg.points);
  for (let t = 0; t < m.triangles.length / 3; ++t) {
    const [a, b, c] = m.triangles.subarray(3 * t, 3 * t + 3);
    const p = m.points;
    const cross = (p[2 * b] - p[2 * a]) * (p[2 * c + 1] - p[2 * a + 1]) -
                  (p[2 * b + 1] - p[2 * a + 1]) * (p[2 * c] - p[2 * a]);
    assert.ok(cross > 0, `triangle ${t} is not counter-clockwise`);
  }
}

function checkValid(pslg, m) {
  const v = am.validate(pslg, m);
  assert.deepEqual(v, { ok: true, errors: [] });
}

// Every mode on one input, each result checked.
function everyMode(path) {
  const pslg = load(am, path);
  for (const mode of ['delaunay', 'cdt', 'quality', 'nonobtuse', 'acute']) {
    const m = am.mesh(pslg, { mode });
    checkShape(pslg, m);
    checkValid(pslg, m);
    assert.equal(m.options.mode, mode);
    if (mode === 'delaunay' || mode === 'cdt') {
      assert.equal(m.status, 'ok');
      continue;
    }
    assert.equal(m.status, m.stats.targetMet ? 'ok' : 'target-not-met');
    if (mode === 'quality') {
      // Triangle's default bound of 20 degrees, where the input's own angles allow it (a
      // point set's hull corners are not counted in smallestInputAngle).
      if (m.stats.smallestInputAngle >= 40 && pslg.segments.length > 0) {
        assert.ok(m.stats.targetMet, m.message);
        assert.ok(m.stats.minAngle >= 20 - 1e-9, `min angle ${m.stats.minAngle}`);
      }
      continue;
    }
    // Acute and non-obtuse: certified on every fixture, and the float angles agree.
    assert.ok(m.stats.certified, `${mode}: ${m.message}`);
    assert.equal(m.stats.obtuse, 0);
    if (mode === 'acute') assert.equal(m.stats.nonAcute, 0);
    for (let t = 0; t < m.triangles.length / 3; ++t)
      for (const c of cornerCosines(m, t)) assert.ok(c > -1e-9, `${mode}: triangle ${t} has an obtuse corner`);
  }
}

for (const path of fixtures()) test(`every mode on ${label(path)}`, () => everyMode(path));
if (reference.dir || reference.error) {
  for (const path of referencePolys()) test(`every mode on ${label(path)}`, () => everyMode(path));
} else {
  const title = 'every mode on the reference .poly inputs';
  test(title, needsReference(title), () => {});
}

// Whether (x, y) lies exactly on one of pslg's segments: cross products in BigInt, of the
// coordinates scaled by 2^64 (exact for the dyadic Steiner points of integer inputs).
function onSomeSegmentExactly(pslg, x, y) {
  const big = (v) => BigInt(v * 2 ** 64);
  const p = [big(x), big(y)];
  for (let s = 0; s < pslg.segments.length; s += 2) {
    const a = pslg.segments[s], b = pslg.segments[s + 1];
    const A = [big(pslg.points[2 * a]), big(pslg.points[2 * a + 1])];
    const B = [big(pslg.points[2 * b]), big(pslg.points[2 * b + 1])];
    const cross = (B[0] - A[0]) * (p[1] - A[1]) - (B[1] - A[1]) * (p[0] - A[0]);
    const dot = (p[0] - A[0]) * (B[0] - A[0]) + (p[1] - A[1]) * (B[1] - A[1]);
    const len2 = (B[0] - A[0]) ** 2n + (B[1] - A[1]) ** 2n;
    if (cross === 0n && dot > 0n && dot < len2) return true;
  }
  return false;
}

// Instance files meshed non-obtuse with exact segments: on their segments exactly, and written
// as CG:SHOP solutions.
function meshInstances(files) {
  for (const f of files) {
    const inst = load(am, f);
    assert.equal(typeof inst.instanceUid, 'string');
    // The input policy (as the CLI's): exact segments and exact feet for an instance.
    const m = am.mesh(inst, { mode: 'nonobtuse', timeLimit: 10 });
    checkShape(inst, m);
    checkValid(inst, m);
    assert.equal(m.options.exactSegments, true);
    assert.equal(m.options.exactFeet, true);
    // The verifier is exact: every Steiner point on a segment lies exactly on it.
    for (let v = 0; v < m.vertexKind.length; ++v)
      if (m.vertexKind[v] === 2)
        assert.ok(onSomeSegmentExactly(inst, m.points[2 * v], m.points[2 * v + 1]), `${f}: vertex ${v} is off its segment`);
    assert.equal(m.stats.obtuse === 0, m.stats.certified);
    const solution = JSON.parse(am.toCgshop(m, inst));
    assert.equal(solution.instance_uid, inst.instanceUid);
    assert.equal(solution.steiner_points_x.length, m.stats.steiner);
  }
}

test('the synthetic CG:SHOP 2025 instances: parsed, constrained, non-obtuse or honestly not', () => {
  const files = instanceFiles(syntheticCgshop);
  assert.equal(files.length, 8);
  meshInstances(files);
});

const official = 'a few official CG:SHOP 2025 instances: parsed, constrained, non-obtuse or honestly not';
test(official, needsReference(official), () => {
  const files = instanceFiles(referenceFile('cgshop2025'));
  assert.equal(files.length, 150);
  meshInstances(files.filter((_, i) => i % 15 === 0));
});

// Exact feet on an instance with tilted hull edges and input vertices within a unit of them:
// rationals in the mesh and the CG:SHOP solution, non-obtuse exactly.
function exactFeet(path) {
  const inst = load(am, path);
  // Exact feet are the input policy's default for an instance; exactFeet: false turns them off.
  const plain = am.mesh(inst, { mode: 'nonobtuse', exactFeet: false });
  const m = am.mesh(inst, { mode: 'nonobtuse' });
  checkShape(inst, m);
  checkValid(inst, m);
  assert.equal(m.options.exactFeet, true);
  assert.deepEqual(plain.exactPoints, []);
  assert.ok(m.exactPoints.length > 10, `${m.exactPoints.length} exact points`);
  assert.ok(m.stats.certified && m.stats.obtuse === 0);
  assert.ok(2 * m.stats.steiner < plain.stats.steiner, `${m.stats.steiner} vs ${plain.stats.steiner}`);
  // Exactly, with BigInt: every triangle counter-clockwise and non-obtuse at the exact places.
  const pow2 = (e) => (e >= 0 ? [2n ** BigInt(e), 1n] : [1n, 2n ** BigInt(-e)]);
  const fromDouble = (v) => {  // [numerator, denominator] of a double, exactly
    if (v === 0) return [0n, 1n];
    let e = Math.floor(Math.log2(Math.abs(v))) - 52, m = v / 2 ** e;
    while (!Number.isInteger(m)) m *= 2, e -= 1;
    const [a, b] = pow2(e);
    return [BigInt(m) * a, b];
  };
  const fromText = (s) => { const [p, q] = s.split('/'); return [BigInt(p), BigInt(q ?? '1')]; };
  const at = [];  // [X, Y, W]
  for (let v = 0; v < m.points.length / 2; ++v) {
    const [xp, xq] = fromDouble(m.points[2 * v]), [yp, yq] = fromDouble(m.points[2 * v + 1]);
    at.push([xp * yq, yp * xq, xq * yq]);
  }
  for (const p of m.exactPoints) {
    const [xp, xq] = fromText(p.x), [yp, yq] = fromText(p.y);
    assert.ok(Math.abs(Number(xp) / Number(xq) - m.points[2 * p.vertex]) < 1e-6);
    at[p.vertex] = [xp * yq, yp * xq, xq * yq];
  }
  const minus = (b, a) => [b[0] * a[2] - a[0] * b[2], b[1] * a[2] - a[1] * b[2]];
  for (let t = 0; t < m.triangles.length / 3; ++t) {
    const [a, b, c] = [...m.triangles.subarray(3 * t, 3 * t + 3)].map((v) => at[v]);
    const ab = minus(b, a), ac = minus(c, a);
    assert.ok(ab[0] * ac[1] - ab[1] * ac[0] > 0n, `triangle ${t} not counter-clockwise`);
    for (const [p, q, r] of [[a, b, c], [b, c, a], [c, a, b]]) {
      const u = minus(q, p), w = minus(r, p);
      assert.ok(u[0] * w[0] + u[1] * w[1] >= 0n, `triangle ${t} obtuse`);
    }
  }
  // The solution writes them as they are; the JSON mesh lists them.
  const solution = JSON.parse(am.toCgshop(m, inst));
  const n0 = inst.points.length / 2;
  for (const p of m.exactPoints) {
    const expect = (s) => (s.includes('/') ? s : Number(s));
    assert.equal(solution.steiner_points_x[p.vertex - n0], expect(p.x));
    assert.equal(solution.steiner_points_y[p.vertex - n0], expect(p.y));
  }
  assert.deepEqual(JSON.parse(am.toJson(m)).exactPoints, m.exactPoints.map((p) => [p.vertex, p.x, p.y]));
}

test('exact feet on the synthetic tilted point set', () => {
  exactFeet(`${syntheticCgshop}/point-set_120_tilted.instance.json`);
});

const officialFeet = 'exact feet on an official tilted point set';
test(officialFeet, needsReference(officialFeet), () => {
  exactFeet(referenceFile('cgshop2025', 'point-set_250_3c338713.instance.json'));
});

test('parameters reach the core: maxArea, minAngle, maxAngle, convexHull, fill', () => {
  const square = { points: [0, 0, 1, 0, 1, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0] };
  const coarse = am.mesh(square, { mode: 'quality' });
  const fine = am.mesh(square, { mode: 'quality', maxArea: 0.001 });
  assert.ok(fine.stats.triangles >= 1000, `${fine.stats.triangles} triangles`);
  assert.ok(fine.stats.triangles > 10 * coarse.stats.triangles);
  for (let t = 0; t < fine.triangles.length / 3; ++t) {
    const [a, b, c] = fine.triangles.subarray(3 * t, 3 * t + 3);
    const p = fine.points;
    const area = ((p[2 * b] - p[2 * a]) * (p[2 * c + 1] - p[2 * a + 1]) -
                  (p[2 * b + 1] - p[2 * a + 1]) * (p[2 * c] - p[2 * a])) / 2;
    assert.ok(area <= 0.001 * (1 + 1e-9), `triangle ${t} has area ${area}`);
  }
  const q30 = am.mesh(square, { mode: 'quality', minAngle: 30 });
  assert.ok(q30.stats.minAngle >= 30 - 1e-9);
  const a85 = am.mesh(square, { mode: 'acute', maxAngle: 85 });
  assert.ok(a85.stats.targetMet && a85.stats.maxAngle < 85, `max angle ${a85.stats.maxAngle}`);
  // 80, well above the square's floor of 72: met, every angle below it (floating point, with
  // the certificate's exactness left to the C++ tests).
  const a80 = am.mesh(square, { mode: 'acute', maxAngle: 80 });
  assert.equal(a80.status, 'ok', a80.message);
  assert.ok(a80.stats.targetMet && a80.stats.certified);
  assert.equal(a80.stats.angleBound, 80);
  for (let t = 0; t < a80.triangles.length / 3; ++t)
    for (const c of cornerCosines(a80, t)) assert.ok(Math.acos(c) * 180 / Math.PI < 80, `triangle ${t}`);
  checkValid(square, a80);
  // 70, below the floor no domain goes under: not an error, the best mesh comes back acute and
  // certified, with the miss stated (as the C++ API and the CLI do).
  const a70 = am.mesh(square, { mode: 'acute', maxAngle: 70 });
  assert.equal(a70.status, 'target-not-met');
  assert.ok(!a70.stats.targetMet && a70.stats.certified && a70.message.length > 0);
  assert.ok(a70.stats.angleBound > 72 && a70.stats.angleBound < 90, `${a70.stats.angleBound}`);
  for (let t = 0; t < a70.triangles.length / 3; ++t)
    for (const c of cornerCosines(a70, t)) assert.ok(Math.acos(c) * 180 / Math.PI < a70.stats.angleBound);
  checkValid(square, a70);
  // 'auto': the lowest bound certified, a tenth of a degree, every angle below it.
  const auto = am.mesh(square, { mode: 'acute', maxAngle: 'auto' });
  assert.equal(auto.status, 'ok');
  assert.equal(auto.options.maxAngle, 'auto');
  assert.ok(auto.stats.certified && auto.stats.targetMet);
  assert.ok(auto.stats.angleBound > auto.stats.maxAngle && auto.stats.angleBound <= 90, `${auto.stats.angleBound}`);
  assert.equal(Math.round(auto.stats.angleBound * 10) / 10, auto.stats.angleBound);
  for (let t = 0; t < auto.triangles.length / 3; ++t)
    for (const c of cornerCosines(auto, t)) assert.ok(Math.acos(c) * 180 / Math.PI < auto.stats.angleBound);
  assert.equal(a85.stats.angleBound, 85);
  assert.equal(a85.stats.smallestDomainAngle, 90);
  assert.equal(a85.stats.angleFloor, 72);
  // Both a minimum and a maximum: both reach the core and both are reported.
  const both = am.mesh(square, { mode: 'acute', minAngle: 30, maxAngle: 80 });
  assert.equal(both.options.minAngle, 30);
  assert.equal(both.options.maxAngle, 80);
  assert.ok(both.stats.minAngle >= 30 * (1 - 1e-9), `min angle ${both.stats.minAngle}`);
  assert.equal(both.stats.targetMet, both.stats.angleBound === 80);
  // A 20-degree corner: a floor of 80, so 75 is said to be impossible and meshed as 'auto'.
  const wedge = { points: [0, 0, 10, 0, 10 * Math.cos(Math.PI / 9), 10 * Math.sin(Math.PI / 9)], segments: [0, 1, 1, 2, 2, 0] };
  const low = am.mesh(wedge, { mode: 'acute', maxAngle: 75 });
  assert.equal(low.status, 'target-not-met');
  assert.ok(Math.abs(low.stats.angleFloor - 80) < 1e-9);
  assert.match(low.stats.warnings.join('\n'), /sets a floor of 80 degrees: no mesh has every angle below it/);
  assert.match(low.message, /a maximum angle of 75 degrees is at or below the floor of 80 degrees/);
  assert.ok(low.stats.certified && low.stats.angleBound > 80 && !low.stats.targetMet);
  checkValid(wedge, low);
  const budget = am.mesh(square, { mode: 'acute', maxArea: 1e-4, maxSteiner: 10 });
  assert.equal(budget.status, 'target-not-met');
  checkValid(square, budget);

  // A square with a square hole given by a hole point (Triangle's rule), then by nesting.
  const frame = {
    points: [0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 3, 1, 3, 3, 1, 3],
    segments: [0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4],
    holes: [2, 2],
  };
  const holed = am.mesh(frame);
  const areaOf = (m) => {
    let s = 0;
    for (let t = 0; t < m.triangles.length / 3; ++t) {
      const [a, b, c] = m.triangles.subarray(3 * t, 3 * t + 3);
      const p = m.points;
      s += ((p[2 * b] - p[2 * a]) * (p[2 * c + 1] - p[2 * a + 1]) -
            (p[2 * b + 1] - p[2 * a + 1]) * (p[2 * c] - p[2 * a])) / 2;
    }
    return s;
  };
  assert.equal(areaOf(holed), 12);
  assert.equal(areaOf(am.mesh({ ...frame, holes: [] }, { fill: 'evenodd' })), 12);
  assert.equal(areaOf(am.mesh({ ...frame, holes: [] })), 16);
  // Point set on a concave outline: the hull is kept with convexHull.
  const notch = { points: [0, 0, 2, 0, 2, 2, 1, 0.5, 0, 2], segments: [0, 1, 1, 2, 2, 3, 3, 4, 4, 0] };
  assert.equal(areaOf(am.mesh(notch)), 4 - 1.5);
  const hull = am.mesh(notch, { convexHull: true });
  assert.equal(areaOf(hull), 4);
  checkValid(notch, hull);
});

test('fromRings: a GeoJSON polygon with a hole, and a multipolygon', () => {
  const polygon = {
    type: 'Polygon',
    coordinates: [
      [[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]],
      [[3, 3], [3, 7], [7, 7], [7, 3], [3, 3]],  // the hole, either orientation
    ],
  };
  const pslg = am.fromRings(polygon.coordinates);
  assert.equal(pslg.fill, 'evenodd');
  assert.equal(pslg.points.length, 16);  // repeated closing points dropped
  assert.equal(pslg.segments.length, 16);
  const m = am.mesh(pslg, { mode: 'acute' });
  assert.ok(m.stats.certified);
  assert.equal(m.options.fill, 'evenodd');
  checkValid(pslg, m);
  for (let t = 0; t < m.triangles.length / 3; ++t) {
    let cx = 0, cy = 0;
    for (const v of m.triangles.subarray(3 * t, 3 * t + 3)) { cx += m.points[2 * v] / 3; cy += m.points[2 * v + 1] / 3; }
    assert.ok(!(cx > 3 && cx < 7 && cy > 3 && cy < 7), `triangle ${t} lies in the hole`);
  }
  const multi = [[[[0, 0], [1, 0], [0, 1]]], [[[2, 0], [3, 0], [3, 1]]]];
  const two = am.fromRings(multi.flat(), { fill: 'nonzero' });
  const m2 = am.mesh(two, { mode: 'nonobtuse' });
  assert.ok(m2.stats.certified);
  assert.equal(m2.options.fill, 'nonzero');
  checkValid(two, m2);
  // Flat rings (font contours) work too, and agree with the core's own rings reader.
  const flat = am.fromRings([new Float64Array([0, 0, 1, 0, 1, 1, 0, 1])]);
  const viaJson = am.parseJson(JSON.stringify({ rings: [[[0, 0], [1, 0], [1, 1], [0, 1]]] }));
  assert.deepEqual([...flat.points], [...viaJson.points]);
  assert.deepEqual([...flat.segments], [...viaJson.segments]);
  assert.equal(viaJson.fill, 'evenodd');
});

test('writers: each format reads back or has the right counts', () => {
  const pslg = am.parsePoly(`4 2 0 0\n0 0 0\n1 3 0\n2 3 2\n3 0 2\n4 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n0\n`);
  const m = am.mesh(pslg, { mode: 'acute' });
  const n = m.points.length / 2, t = m.triangles.length / 3;

  const node = am.parseNode(am.toNode(m));
  assert.deepEqual(node.points, m.points);
  const poly = am.parsePoly(am.toPoly(m));
  assert.deepEqual(poly.points, m.points);
  assert.deepEqual(poly.segments, m.segments);
  const json = am.parseJson(am.toJson(m));
  assert.deepEqual(json.points, m.points);
  const parsedJson = JSON.parse(am.toJson(m));
  assert.deepEqual(parsedJson.triangles.flat(), [...m.triangles]);

  const ele = am.toEle(m).split('\n').filter((l) => l && !l.startsWith('#'));
  assert.equal(ele[0].split(/\s+/)[0], String(t));
  assert.deepEqual(ele.slice(1).map((l) => l.trim().split(/\s+/).slice(1).map(Number)).flat(), [...m.triangles]);
  const obj = am.toOBJ(m).split('\n');
  assert.equal(obj.filter((l) => l.startsWith('v ')).length, n);
  assert.equal(obj.filter((l) => l.startsWith('f ')).length, t);
  const off = am.toOFF(m).split('\n').filter((l) => l && !l.startsWith('#'));
  assert.equal(off[0], 'OFF');
  assert.deepEqual(off[1].split(/\s+/).slice(0, 2).map(Number), [n, t]);
  const svg = am.toSVG(m);
  assert.match(svg, /^<svg[\s\S]*<\/svg>\s*$/);
  // Plain arrays are accepted as meshes too.
  assert.equal(am.toOBJ({ points: [...m.points], triangles: [...m.triangles] }), am.toOBJ({ ...m, segments: null }));
});

// The solver formats: well-formed for a mesh of the package, and with markers and attributes
// passed in typed arrays the very text of the C++ writers' golden files (tests/cpp/test_formats).
test('writers: edge, neigh, msh, msh2, vtu', () => {
  const m = am.mesh(am.parsePoly(readFileSync(join(testData, 'plate.poly'), 'utf8')), { mode: 'acute' });
  const n = m.points.length / 2, t = m.triangles.length / 3;
  const lines = (text) => text.split('\n').filter((l) => l && !l.startsWith('#'));
  const edge = lines(am.write(m, 'edge'));
  assert.equal(edge[0], `${edge.length - 1} 1`);
  assert.equal(edge.length - 1, n + t + 4 - 1, 'Euler: V - E + T = 1 - holes (the plate has 4)');
  assert.equal(am.write(m, 'edge'), am.toEdge(m));
  const neigh = lines(am.toNeigh(m));
  assert.equal(neigh[0], `${t} 3`);
  assert.equal(neigh.length, t + 1);
  const msh = am.toMSH(m);
  assert.match(msh, /^\$MeshFormat\n4\.1 0 8\n\$EndMeshFormat\n\$PhysicalNames\n[\s\S]*\$EndElements\n$/);
  assert.equal(am.write(m, 'msh'), msh);
  assert.match(am.toMSH2(m), /^\$MeshFormat\n2\.2 0 8\n[\s\S]*\$EndElements\n$/);
  assert.equal(am.write(m, 'msh2'), am.toMSH2(m));
  const vtu = am.toVTU(m);
  assert.match(vtu, new RegExp(`<Piece NumberOfPoints="${n}" NumberOfCells="\\d+">`));
  assert.match(vtu, /<\/VTKFile>\n$/);
  assert.equal(am.write(m, 'vtu'), vtu);

  // Two squares split by a segment, markers and attributes by hand, vertex 6 unused.
  const squares = {
    points: [0, 0, 1, 0, 2, 0, 2, 1, 1, 1, 0, 1, 5, 5],
    triangles: [0, 1, 4, 0, 4, 5, 1, 2, 3, 1, 3, 4],
    segments: [0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 0, 1, 4],
    vertexMarkers: Int32Array.of(5, 5, 0, -2, 7, 7, 0),
    segmentMarkers: Int32Array.of(5, 5, 0, -2, 7, 7, 3),
    triangleAttributes: Float64Array.of(1, 1, 2.5, 2.5),
  };
  const golden = (ext) => readFileSync(join(testData, 'io', 'two-squares', `marked${ext}`), 'utf8');
  for (const f of ['node', 'ele', 'edge', 'neigh', 'msh', 'msh2', 'vtu']) {
    const info = am.vocabulary.outputFormats.find((e) => e.name === f);
    assert.equal(am.write(squares, f), golden(info.extension), f);
  }
  // Arrays of the wrong kind or length are Triangle's defaults, not an error.
  const plain = { ...squares, vertexMarkers: [5, 5, 0, -2, 7, 7, 0], segmentMarkers: Int32Array.of(1) };
  assert.match(am.toNode(plain), /\n2 2 0 1\n3 2 1 1\n/);
});

test('acutemesh/single gives the same meshes', async () => {
  const single = await initSingle();
  assert.notEqual(single, am);
  const pslg = load(am, fixtures()[0]);
  const a = am.mesh(pslg, { mode: 'acute' });
  const b = single.mesh(pslg, { mode: 'acute' });
  assert.deepEqual(b.points, a.points);
  assert.deepEqual(b.triangles, a.triangles);
});

test('init is memoised; createInstance is not; progress reports', async () => {
  assert.equal(await init(), am);
  const other = await createInstance();
  assert.notEqual(other, am);
  const phases = [];
  const pslg = load(am, fixtures()[0]);
  other.mesh(pslg, { mode: 'acute', onProgress: (p) => phases.push(p.phase) });
  for (const phase of ['delaunay', 'segments', 'domain', 'refine', 'output']) assert.ok(phases.includes(phase), phase);
  assert.equal(typeof am.version, 'string');
  assert.ok(new AcuteMeshError('BAD_INPUT', 'x') instanceof Error);
});

// options.optimize: the search takes its seconds and returns a certified mesh with no more
// Steiner points than refinement's; bad seconds and seeds are bad input naming the option.
test('optimize spends its time on fewer points and never returns more', () => {
  const plate = am.parsePoly(readFileSync(join(testData, 'plate.poly'), 'utf8'));
  const plain = am.mesh(plate, { mode: 'nonobtuse' });
  const start = performance.now();
  const m = am.mesh(plate, { mode: 'nonobtuse', optimize: 0.4, seed: 3 });
  assert.ok(performance.now() - start >= 400, 'the search ended before its time');
  assert.equal(m.status, 'ok');
  assert.ok(m.stats.certified && m.stats.targetMet);
  assert.ok(m.stats.steiner <= plain.stats.steiner, `${m.stats.steiner} > ${plain.stats.steiner}`);
  assert.equal(m.options.optimize, 0.4);
  assert.equal(m.options.seed, 3);
  assert.equal(am.mesh(plate, { mode: 'nonobtuse' }).options.optimize, 0);
  for (const [options, message] of [
    [{ optimize: -1 }, /^optimize must be a number of seconds >= 0/],
    [{ optimize: Infinity }, /^optimize must be a number of seconds >= 0/],
    [{ seed: 1.5 }, /^seed must be an integer from 0 to 2\^53 - 1/],
    [{ seed: -2 }, /^seed must be an integer/],
  ])
    assert.throws(() => am.mesh(plate, { mode: 'nonobtuse', ...options }),
      (e) => e.name === 'AcuteMeshError' && message.test(e.message));
  assert.throws(() => am.mesh(plate, { mode: 'nonobtuse', optimize: '1' }), TypeError);
});

// options.optimizeTries: the same seed and tries make the same mesh (seconds would not); it
// caps a search given seconds; a bad count is bad input naming the option.
test('optimizeTries makes the same mesh every time', () => {
  const plate = am.parsePoly(readFileSync(join(testData, 'plate.poly'), 'utf8'));
  const plain = am.mesh(plate, { mode: 'nonobtuse' });
  const a = am.mesh(plate, { mode: 'nonobtuse', optimizeTries: 15, seed: 5 });
  const b = am.mesh(plate, { mode: 'nonobtuse', optimizeTries: 15, seed: 5 });
  assert.equal(a.options.optimizeTries, 15);
  assert.ok(a.stats.certified && a.stats.targetMet);
  assert.ok(a.stats.steiner <= plain.stats.steiner);
  assert.deepEqual(a.points, b.points);
  assert.deepEqual(a.triangles, b.triangles);
  const start = performance.now();
  am.mesh(plate, { mode: 'nonobtuse', optimize: 60, optimizeTries: 3 });
  assert.ok(performance.now() - start < 30000, '3 tries did not end a 60 s search');
  for (const bad of [-1, 2.5])
    assert.throws(() => am.mesh(plate, { mode: 'nonobtuse', optimizeTries: bad }),
      (e) => e.name === 'AcuteMeshError' && /^optimizeTries must be an integer from 0/.test(e.message));
});

// The anytime contract: a cancel while optimize searches returns the best mesh so far (status
// 'cancelled', certified, meets the target, no more Steiner points than refinement's) long
// before the time asked for; a cancel before the search has a mesh still rejects.
test('a cancel during optimize returns the best mesh so far; before it, an AbortError', () => {
  const plate = am.parsePoly(readFileSync(join(testData, 'plate.poly'), 'utf8'));
  const t0 = performance.now();
  const plain = am.mesh(plate, { mode: 'nonobtuse' });
  const plainMs = performance.now() - t0;
  const c = new AbortController();
  const start = performance.now();
  const m = am.mesh(plate, {
    mode: 'nonobtuse', optimize: 60, signal: c.signal,
    // Once the search runs: the polish before it reports 'improve' too, and a cancel there
    // returns its mesh so far, which may have more points than its end. The search starts
    // from that end (`plain`), well within twice plain's time.
    onProgress: (p) => {
      if (p.phase === 'improve' && performance.now() - start > 2 * plainMs + 300) c.abort();
    },
  });
  assert.ok(performance.now() - start < 30000, 'the cancel did not stop the search');
  assert.ok(c.signal.aborted);
  assertBestSoFar(am, plate, m, plain);

  const reason = new Error('stop');
  const early = new AbortController();
  assert.throws(() => am.mesh(plate, {
    mode: 'nonobtuse', optimize: 60, signal: early.signal,
    onProgress: (p) => { if (p.phase === 'domain') early.abort(reason); },  // before refinement
  }), (e) => e === reason);
});
