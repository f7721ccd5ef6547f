// Writes the synthetic CG:SHOP 2025 instances beside this script: small inputs in the
// challenge's JSON format, of its five kinds, made from a seeded random generator (the same
// files every run), so the CG:SHOP reader, the solution writer and the exact verifier
// (tests/cli/verify_cgshop.mjs) are tested without the 150 official instances.
//   node tests/data/cgshop/make.mjs            rewrite the files
//   node tests/data/cgshop/make.mjs --check    exit 1 if a file differs from what it would write
// Like the official instances: integer coordinates, the region boundary counter-clockwise,
// constraints that touch only at their ends. Each generator checks that its polygon is simple.
import { readFileSync, writeFileSync, existsSync, readdirSync } from 'node:fs';

// A small seeded generator (mulberry32): numbers in [0, 1).
function random(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

// Coordinates stay below 2^20, so these products are exact in doubles.
const orient = (a, b, c) => Math.sign((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));

// Do segments i = [a, b] and j = [c, d] (index pairs) meet anywhere but at a shared end?
function meet(pts, [a, b], [c, d]) {
  const ends = [a, b].filter((v) => v === c || v === d).length;
  if (ends === 2) return true;  // the same segment twice
  const [A, B, C, D] = [pts[a], pts[b], pts[c], pts[d]];
  if (ends === 1) {  // meeting at the shared end is fine unless they run along each other
    const s = a === c || a === d ? A : B, p = s === A ? B : A, q = c === a || c === b ? D : C;
    return orient(s, p, q) === 0 && (p[0] - s[0]) * (q[0] - s[0]) + (p[1] - s[1]) * (q[1] - s[1]) > 0;
  }
  const within = (p, q, r) => Math.min(p[0], q[0]) <= r[0] && r[0] <= Math.max(p[0], q[0]) &&
    Math.min(p[1], q[1]) <= r[1] && r[1] <= Math.max(p[1], q[1]);
  const o1 = orient(A, B, C), o2 = orient(A, B, D), o3 = orient(C, D, A), o4 = orient(C, D, B);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 === 0 && within(A, B, C)) || (o2 === 0 && within(A, B, D)) ||
    (o3 === 0 && within(C, D, A)) || (o4 === 0 && within(C, D, B));
}

// Throws unless the points are distinct and the segments meet only at shared ends.
function checkSimple(name, pts, segs) {
  if (new Set(pts.map((p) => `${p[0]},${p[1]}`)).size !== pts.length) throw new Error(`${name}: duplicate points`);
  for (let i = 0; i < segs.length; ++i)
    for (let j = i + 1; j < segs.length; ++j)
      if (meet(pts, segs[i], segs[j])) throw new Error(`${name}: segments ${segs[i]} and ${segs[j]} meet`);
}

const ring = (idx) => idx.map((v, i) => [v, idx[(i + 1) % idx.length]]);
const twiceArea = (pts, idx) => idx.reduce((s, v, i) => {
  const p = pts[v], q = pts[idx[(i + 1) % idx.length]];
  return s + p[0] * q[1] - p[1] * q[0];
}, 0);

// The convex hull's vertices (Andrew's monotone chain), counter-clockwise, without collinear ones.
function hull(pts) {
  const idx = pts.map((_, i) => i).sort((i, j) => pts[i][0] - pts[j][0] || pts[i][1] - pts[j][1]);
  const half = (order) => {
    const h = [];
    for (const i of order) {
      while (h.length >= 2 && orient(pts[h[h.length - 2]], pts[h[h.length - 1]], pts[i]) <= 0) h.pop();
      h.push(i);
    }
    h.pop();
    return h;
  };
  return [...half(idx), ...half([...idx].reverse())];
}

// A star-shaped polygon of n vertices around (cx, cy): angles in order, radii varied.
function starPolygon(rand, n, cx, cy, radius) {
  const pts = [];
  for (let i = 0; i < n; ++i) {
    const angle = ((i + 0.8 * rand()) / n) * 2 * Math.PI;
    const r = radius * (0.35 + 0.65 * rand());
    pts.push([Math.round(cx + r * Math.cos(angle)), Math.round(cy + r * Math.sin(angle))]);
  }
  return pts;
}

// Distinct points in [0, size]^2 on a grid of the given step (as the official point sets are,
// with their collinear and cocircular runs).
function gridPoints(rand, n, size, step) {
  const seen = new Set();
  const pts = [];
  while (pts.length < n) {
    const p = [step * Math.floor(rand() * (size / step + 1)), step * Math.floor(rand() * (size / step + 1))];
    if (!seen.has(`${p[0]},${p[1]}`)) seen.add(`${p[0]},${p[1]}`), pts.push(p);
  }
  return pts;
}

function instance(uid, pts, boundary, constraints) {
  checkSimple(uid, pts, [...ring(boundary), ...constraints]);
  if (twiceArea(pts, boundary) <= 0) throw new Error(`${uid}: boundary not counter-clockwise`);
  return {
    instance_uid: uid,
    num_points: pts.length,
    points_x: pts.map((p) => p[0]),
    points_y: pts.map((p) => p[1]),
    region_boundary: boundary,
    num_constraints: constraints.length,
    additional_constraints: constraints,
  };
}

// An orthogonal polygon of 10 vertices: a square with a notch in its top side.
function ortho10() {
  const pts = [[0, 0], [100000, 0], [100000, 100000], [78000, 100000], [78000, 86000],
    [59000, 86000], [59000, 75000], [40000, 75000], [40000, 100000], [0, 100000]];
  return instance('ortho_10_synthetic', pts, pts.map((_, i) => i), []);
}

// An orthogonal staircase polygon: steps of random width and height up, then back.
function orthoStairs(seed, steps) {
  const rand = random(seed);
  const pts = [[0, 0]];
  let x = 0, y = 0;
  for (let i = 0; i < steps; ++i) {
    x += 100 * (1 + Math.floor(rand() * 20));
    pts.push([x, y]);
    y += 100 * (1 + Math.floor(rand() * 20));
    pts.push([x, y]);
  }
  pts.push([0, y]);
  return instance(`ortho_${pts.length}_synthetic`, pts, pts.map((_, i) => i), []);
}

// Grid points; the region is their convex hull.
function pointSet(seed, n) {
  const rand = random(seed);
  const pts = gridPoints(rand, n, 10000, 25);
  return instance(`point-set_${n}_synthetic`, pts, hull(pts), []);
}

// Points near tilted hull edges, as in the official point sets whose hull edges run a few
// units off the grid lines: the altitude feet on those edges are rationals, not doubles, so
// meshing with exact feet (Options::exactFeet) needs far fewer points than without.
function tiltedPointSet(seed, n) {
  const rand = random(seed);
  const corners = [[0, 0], [4000, 9], [4011, 3000], [-7, 3013]];
  const pts = corners.map((p) => [...p]);
  // Rows just inside the bottom and top edges, from under a unit to a few units from them.
  for (let x = 150; x < 3900; x += 50 * (1 + Math.floor(rand() * 4))) {
    pts.push([x, Math.ceil((9 * x) / 4000) + Math.floor(rand() * 3)]);
    pts.push([x, Math.floor(3013 - (13 * (x + 7)) / 4018) - Math.floor(rand() * 3)]);
  }
  // The rest on a grid well inside.
  const seen = new Set(pts.map((p) => `${p[0]},${p[1]}`));
  while (pts.length < n) {
    const p = [300 + 50 * Math.floor(rand() * 69), 200 + 50 * Math.floor(rand() * 53)];
    if (!seen.has(`${p[0]},${p[1]}`)) seen.add(`${p[0]},${p[1]}`), pts.push(p);
  }
  return instance(`point-set_${n}_tilted`, pts, hull(pts), []);
}

// A simple polygon is the region.
function simplePolygon(seed, n) {
  const rand = random(seed);
  const pts = starPolygon(rand, n, 5000, 5000, 5000);
  return instance(`simple-polygon_${n}_synthetic`, pts, pts.map((_, i) => i), []);
}

// A simple polygon drawn as constraints inside the convex hull of it and of points around it;
// `share` of its edges are kept (the official "-20" instances leave some out).
function polygonWithExterior(seed, n, outside, share, kind) {
  const rand = random(seed);
  const poly = starPolygon(rand, n, 5000, 5000, 3500);
  const pts = [...poly];
  // Points outside the polygon (beyond its largest radius), inside the square.
  while (pts.length < n + outside) {
    const angle = rand() * 2 * Math.PI, r = 3600 + rand() * 1400;
    const p = [Math.round(5000 + r * Math.cos(angle)), Math.round(5000 + r * Math.sin(angle))];
    if (!pts.some((q) => q[0] === p[0] && q[1] === p[1])) pts.push(p);
  }
  const boundary = hull(pts);
  const onHull = new Set(ring(boundary).map(([a, b]) => `${Math.min(a, b)},${Math.max(a, b)}`));
  const constraints = ring(poly.map((_, i) => i))
    .filter(([a, b]) => !onHull.has(`${Math.min(a, b)},${Math.max(a, b)}`))
    .filter(() => rand() < share);
  return instance(`${kind}_${pts.length}_synthetic`, pts, boundary, constraints);
}

const INSTANCES = [
  ortho10(),
  orthoStairs(11, 9),
  pointSet(21, 60),
  tiltedPointSet(31, 120),
  simplePolygon(41, 40),
  polygonWithExterior(51, 30, 20, 1, 'simple-polygon-exterior'),
  polygonWithExterior(61, 50, 30, 0.8, 'simple-polygon-exterior-20'),
  polygonWithExterior(71, 90, 60, 1, 'simple-polygon-exterior'),
];

// The official files' layout: one key per line, each constraint on a line of its own.
function format(inst) {
  const lines = Object.entries(inst).map(([k, v]) => {
    if (k !== 'additional_constraints') return ` ${JSON.stringify(k)}: ${JSON.stringify(v)}`;
    if (!v.length) return ` ${JSON.stringify(k)}: []`;
    return ` ${JSON.stringify(k)}: [\n${v.map((c) => `  ${JSON.stringify(c)}`).join(',\n')}\n ]`;
  });
  return `{\n${lines.join(',\n')}\n}\n`;
}

const check = process.argv.includes('--check');
let differ = 0;
for (const inst of INSTANCES) {
  const file = new URL(`./${inst.instance_uid}.instance.json`, import.meta.url);
  const text = format(inst);
  if (!check) {
    writeFileSync(file, text);
    console.log(`${inst.instance_uid}.instance.json: ${inst.num_points} points, ` +
      `${inst.region_boundary.length} on the boundary, ${inst.num_constraints} constraints`);
  } else if (!existsSync(file) || readFileSync(file, 'utf8') !== text) {
    console.error(`make.mjs --check: ${inst.instance_uid}.instance.json differs from what make.mjs writes`);
    differ = 1;
  }
}
const made = new Set(INSTANCES.map((inst) => `${inst.instance_uid}.instance.json`));
for (const f of readdirSync(new URL('.', import.meta.url)))
  if (f.endsWith('.instance.json') && !made.has(f)) {
    console.error(`make.mjs: ${f} is not one make.mjs writes (delete it)`);
    differ = 1;
  }
process.exit(differ);
