// The max-angle dial of acute mode: the bound asked for (degrees, or 'auto': the lowest bound
// the run can certify), the input's floor beside it, and what a run reached, in words.
//
// The floor (Bishop 2021): no mesh of a domain whose smallest corner is theta has every angle
// below 90 - min(36, theta) / 2. The mesher reports it after a refinement (stats.angleFloor);
// before one, the page measures the corners on a constrained Delaunay triangulation of the
// input, the same way (inside the domain, between walls), in floating point: it only labels
// the dial.

export const AUTO = 'auto';

export function angleFloor(corner) {
  return 90 - Math.min(36, corner) / 2;
}

// The smallest corner of the domain (degrees) of a mesh of it: at each vertex, the triangles'
// corners are joined across edges that are not walls (an input segment, or an edge with a
// triangle on one side only); each group is one corner of the domain. A group that goes all
// the way round (360) is no corner. 360 when there is none.
export function smallestDomainCorner(points, triangles, segments) {
  const n = points.length / 2;
  const key = (a, b) => (a < b ? a * n + b : b * n + a);
  const walls = new Set();
  for (let i = 0; i < segments.length; i += 2) walls.add(key(segments[i], segments[i + 1]));
  const parent = new Int32Array(triangles.length).map((_, i) => i);
  const root = (i) => {
    while (parent[i] !== i) i = parent[i] = parent[parent[i]];
    return i;
  };
  const join = (a, b) => { parent[root(a)] = root(b); };
  const seen = new Map();  // edge -> its corners in the first triangle: [at lower vertex, at higher]
  for (let c = 0; c < triangles.length; c++) {
    const d = c % 3 === 2 ? c - 2 : c + 1;  // the next corner of the same triangle
    const u = triangles[c], w = triangles[d];
    const k = key(u, w);
    const corners = u < w ? [c, d] : [d, c];
    const other = seen.get(k);
    if (other === undefined) seen.set(k, corners);
    else if (!walls.has(k)) { join(other[0], corners[0]); join(other[1], corners[1]); }
  }
  const sums = new Map();
  for (let c = 0; c < triangles.length; c++) {
    const t = c - (c % 3);
    const a = 2 * triangles[c], b = 2 * triangles[t + ((c - t + 1) % 3)], e = 2 * triangles[t + ((c - t + 2) % 3)];
    const ux = points[b] - points[a], uy = points[b + 1] - points[a + 1];
    const vx = points[e] - points[a], vy = points[e + 1] - points[a + 1];
    const angle = Math.atan2(Math.abs(ux * vy - uy * vx), ux * vx + uy * vy) * (180 / Math.PI);
    const r = root(c);
    sums.set(r, (sums.get(r) || 0) + angle);
  }
  let smallest = 360;
  for (const s of sums.values()) if (s < 360 - 1e-6 && s < smallest) smallest = s;
  return smallest;
}

// The input's corner and floor from a constrained Delaunay triangulation (milliseconds even
// for large inputs), or null when it cannot be triangulated.
export function measureFloor(am, pslg) {
  try {
    const m = am.mesh(pslg, { mode: 'cdt' });
    const corner = smallestDomainCorner(m.points, m.triangles, m.segments);
    return { corner, floor: angleFloor(corner), from: 'input' };
  } catch {
    return null;
  }
}

// The bound every angle of the mesh is certified strictly below (stats.angleBound), or null
// when none is.
export function certifiedBound(stats, options) {
  if (!stats.certified || options.mode !== 'acute') return null;
  return stats.angleBound;
}

const deg = (v, digits = 1) => `${Number(v.toFixed(digits))}°`;

// One sentence on the bound of an acute run: met, reached (auto), or missed and by how much.
export function boundSentence(r) {
  if (r.mode !== 'acute') return '';
  const floor = r.angleFloor == null ? '' : ` (this input's floor: ${deg(r.angleFloor)})`;
  const reached = r.maxAngle == null ? 'unknown' : `${truncateDeg(r.maxAngle, 3)}`;
  if (r.askedMaxAngle === AUTO) {
    return r.angleBound == null
      ? `auto: no bound certified; the largest angle is ${reached}${floor}.`
      : `auto: every angle below ${deg(r.angleBound)}${floor}.`;
  }
  const asked = r.askedMaxAngle ?? 90;
  // At 90 the verdict (certified acute or not) says it all.
  if (asked >= 90) return '';
  if (r.targetMet) return `Every angle below ${deg(asked, 2)}${floor}.`;
  const below = r.angleBound != null ? `; certified below ${deg(r.angleBound)}` : '';
  const impossible = r.angleFloor != null && asked < r.angleFloor ? ', below what the input allows' : '';
  return `The bound of ${deg(asked, 2)} was not met${impossible}: the largest angle is ${reached}${below}${floor}.`;
}

// Degrees cut (not rounded) to `digits` decimals: 89.99996 must not read as 90.000.
export function truncateDeg(v, digits) {
  const f = 10 ** digits;
  return `${(Math.trunc(v * f) / f).toFixed(digits)}°`;
}
