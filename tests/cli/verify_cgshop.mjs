// An exact check of a CG:SHOP 2025 solution, independent of the C++ code: rational arithmetic
// on BigInt, coordinates as the solution file gives them.
// Usage: node verify_cgshop.mjs INSTANCE.json SOLUTION.json MESH.ele
// The .ele (written by the same run) names the triangles; the solution's coordinates and
// edges are what is checked:
//  - the solution's edges are exactly the edges of those triangles;
//  - every triangle is counter-clockwise and has no obtuse angle (dot-product signs);
//  - every edge lies on one or two triangles, on two with opposite directions inside, and the
//    edges on one triangle only are exactly the pieces of the region boundary;
//  - every boundary and constraint segment is a chain of edges through points on it;
//  - the triangles' areas add up to the region's.
// All triangles counter-clockwise with that boundary cover the region once. Prints a one-line
// summary; exit status 1 and the first problems found otherwise.
import { readFileSync } from 'node:fs';

const [instancePath, solutionPath, elePath] = process.argv.slice(2);
const instance = JSON.parse(readFileSync(instancePath, 'utf8'));
const solution = JSON.parse(readFileSync(solutionPath, 'utf8'));
const problems = [];
const fail = (message) => {
  if (problems.length < 10) problems.push(message);
};

// A rational as [numerator, denominator] (BigInt, denominator > 0).
function rational(value) {
  if (typeof value === 'number') {
    if (!Number.isInteger(value)) throw new Error(`non-integer number ${value}`);
    return [BigInt(value), 1n];
  }
  const m = /^(-?\d+)(?:\/(\d+))?$/.exec(value);
  if (!m) throw new Error(`not a rational: ${value}`);
  const q = BigInt(m[2] ?? '1');
  if (q === 0n) throw new Error(`zero denominator: ${value}`);
  return [BigInt(m[1]), q];
}
// Points as [X, Y, W] with x = X / W, y = Y / W, W > 0.
const points = instance.points_x.map((x, i) => [BigInt(x), BigInt(instance.points_y[i]), 1n]);
solution.steiner_points_x.forEach((x, k) => {
  const [px, qx] = rational(x);
  const [py, qy] = rational(solution.steiner_points_y[k]);
  points.push([px * qy, py * qx, qx * qy]);
});
const sign = (v) => (v > 0n ? 1 : v < 0n ? -1 : 0);
// (b - a) scaled by a.W * b.W > 0.
const minus = (b, a) => [b[0] * a[2] - a[0] * b[2], b[1] * a[2] - a[1] * b[2]];
const cross = (u, v) => u[0] * v[1] - u[1] * v[0];
const dot = (u, v) => u[0] * v[0] + u[1] * v[1];
const orient = (a, b, c) => sign(cross(minus(b, a), minus(c, a)));
// Twice the signed area as a rational [numerator, denominator].
function area2(a, b, c) {
  const u = minus(b, a), v = minus(c, a);  // scaled by aW bW and aW cW
  return [cross(u, v), a[2] * a[2] * b[2] * c[2]];
}
const abs = (v) => (v < 0n ? -v : v);
const gcd = (a, b) => {
  [a, b] = [abs(a), abs(b)];
  while (b) [a, b] = [b, a % b];
  return a;
};
// r + s in lowest terms (the denominators stay small: powers of two times a few others).
function add(r, s) {
  const num = r[0] * s[1] + s[0] * r[1], den = r[1] * s[1];
  const g = gcd(num, den) || 1n;
  return [num / g, den / g];
}

const eleLines = readFileSync(elePath, 'utf8').split('\n').filter((l) => l.trim() && !l.startsWith('#'));
const triangles = eleLines.slice(1).map((l) => l.trim().split(/\s+/).slice(1, 4).map(Number));
// .ele numbers vertices as the mesh does: instance vertices first, then every Steiner point
// the solution lists, in index order (the solution leaves out unused ones: none here).
const n = points.length;
const key = (a, b) => (a < b ? `${a},${b}` : `${b},${a}`);
const directed = new Map();  // "a>b" -> count
const triangleEdges = new Set();
let total = [0n, 1n];
let obtuse = 0, right = 0;
for (const [a, b, c] of triangles) {
  if (![a, b, c].every((v) => v >= 0 && v < n)) {
    fail(`triangle ${a} ${b} ${c}: vertex out of range (${n} points)`);
    continue;
  }
  const [A, B, C] = [points[a], points[b], points[c]];
  if (orient(A, B, C) <= 0) fail(`triangle ${a} ${b} ${c} is not counter-clockwise`);
  for (const [p, q, r] of [[A, B, C], [B, C, A], [C, A, B]]) {
    const d = sign(dot(minus(q, p), minus(r, p)));
    if (d < 0) obtuse++;
    if (d === 0) right++;
  }
  total = add(total, area2(A, B, C));
  for (const [u, v] of [[a, b], [b, c], [c, a]]) {
    directed.set(`${u}>${v}`, (directed.get(`${u}>${v}`) ?? 0) + 1);
    triangleEdges.add(key(u, v));
  }
}
if (obtuse) fail(`${obtuse} obtuse angles`);
for (const [d, count] of directed) if (count > 1) fail(`directed edge ${d} on ${count} triangles`);

const solutionEdges = new Set(solution.edges.map(([a, b]) => key(a, b)));
if (solutionEdges.size !== solution.edges.length) fail('an edge is listed twice');
for (const e of triangleEdges) if (!solutionEdges.has(e)) fail(`edge ${e} of a triangle is missing`);
for (const e of solutionEdges) if (!triangleEdges.has(e)) fail(`edge ${e} is on no triangle`);

// Boundary edges (one triangle) and the segments: each segment a chain of edges along it.
const onOne = new Set();
for (const d of directed.keys()) {
  const [u, v] = d.split('>').map(Number);
  if (!directed.has(`${v}>${u}`)) onOne.add(key(u, v));
}
const neighbours = new Map();
for (const e of triangleEdges) {
  const [u, v] = e.split(',').map(Number);
  for (const [s, t] of [[u, v], [v, u]]) {
    if (!neighbours.has(s)) neighbours.set(s, []);
    neighbours.get(s).push(t);
  }
}
// The chain of edges from a to b through points on the segment, as edge keys (null if none).
function chain(a, b) {
  const A = points[a], B = points[b], dir = minus(B, A);
  const edges = [];
  let at = a, guard = 0;
  while (at !== b && guard++ < n) {
    let next = -1;
    for (const w of neighbours.get(at) ?? []) {
      const W = points[w];
      if (orient(A, B, W) !== 0) continue;
      // Strictly ahead of `at` along a -> b, and not beyond b.
      if (sign(dot(minus(W, points[at]), dir)) > 0 && sign(dot(minus(B, W), dir)) >= 0) next = w;
    }
    if (next < 0) return null;
    edges.push(key(at, next));
    at = next;
  }
  return at === b ? edges : null;
}
const boundary = instance.region_boundary;
const boundaryEdges = new Set();
for (let i = 0; i < boundary.length; i++) {
  const a = boundary[i], b = boundary[(i + 1) % boundary.length];
  const edges = chain(a, b);
  if (!edges) fail(`boundary segment ${a}-${b} is not a chain of edges`);
  else edges.forEach((e) => boundaryEdges.add(e));
}
for (const [a, b] of instance.additional_constraints ?? [])
  if (!chain(a, b)) fail(`constraint ${a}-${b} is not a chain of edges`);
for (const e of onOne) if (!boundaryEdges.has(e)) fail(`edge ${e} bounds one triangle but is not on the boundary`);
for (const e of boundaryEdges) if (!onOne.has(e)) fail(`boundary edge ${e} does not bound exactly one triangle`);

// The region's area (shoelace, twice, integers) against the triangles'.
let region = 0n;
for (let i = 0; i < boundary.length; i++) {
  const p = points[boundary[i]], q = points[boundary[(i + 1) % boundary.length]];
  region += p[0] * q[1] - q[0] * p[1];
}
if (region < 0n) region = -region;
if (total[0] !== region * total[1]) fail('the triangles do not cover the region exactly (areas differ)');

if (problems.length) {
  console.error(problems.join('\n'));
  process.exit(1);
}
console.log(`${instance.instance_uid}: ${triangles.length} triangles, ` +
            `${solution.steiner_points_x.length} Steiner points, ${right} right angles, none obtuse, exact`);
