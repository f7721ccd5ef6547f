// Outline helpers shared by the loaders: curve flattening with a bounded error, and ring
// clean-up. A ring is an array of [x, y] points, implicitly closed (the last point is not a
// repeat of the first), in y-up coordinates (the view flips y for the screen).

// Number of equal parameter steps that keep a quadratic Bézier within `tol` of its chords:
// the second derivative is the constant 2(p0 - 2p1 + p2), and a chord spanning a parameter
// interval h deviates from the curve by at most |B''| h^2 / 8.
function quadSteps(x0, y0, x1, y1, x2, y2, tol) {
  const d = Math.hypot(x0 - 2 * x1 + x2, y0 - 2 * y1 + y2);
  return Math.max(1, Math.ceil(Math.sqrt(d / (4 * tol))));
}

// Same bound for a cubic: |B''| <= 6 max(|p0 - 2p1 + p2|, |p1 - 2p2 + p3|).
function cubicSteps(x0, y0, x1, y1, x2, y2, x3, y3, tol) {
  const d = Math.max(Math.hypot(x0 - 2 * x1 + x2, y0 - 2 * y1 + y2),
    Math.hypot(x1 - 2 * x2 + x3, y1 - 2 * y2 + y3));
  return Math.max(1, Math.ceil(Math.sqrt((3 * d) / (4 * tol))));
}

// A steps cap keeps a silly tolerance (or a huge curve) from producing millions of points.
const MAX_STEPS = 256;

// Appends the flattened quadratic (without its start point) to `ring`.
export function flattenQuad(ring, x0, y0, x1, y1, x2, y2, tol) {
  const n = Math.min(MAX_STEPS, quadSteps(x0, y0, x1, y1, x2, y2, tol));
  for (let i = 1; i <= n; i++) {
    const t = i / n, s = 1 - t;
    ring.push([s * s * x0 + 2 * s * t * x1 + t * t * x2, s * s * y0 + 2 * s * t * y1 + t * t * y2]);
  }
}

// Appends the flattened cubic (without its start point) to `ring`.
export function flattenCubic(ring, x0, y0, x1, y1, x2, y2, x3, y3, tol) {
  const n = Math.min(MAX_STEPS, cubicSteps(x0, y0, x1, y1, x2, y2, x3, y3, tol));
  for (let i = 1; i <= n; i++) {
    const t = i / n, s = 1 - t;
    const a = s * s * s, b = 3 * s * s * t, c = 3 * s * t * t, d = t * t * t;
    ring.push([a * x0 + b * x1 + c * x2 + d * x3, a * y0 + b * y1 + c * y2 + d * y3]);
  }
}

// Appends points of an elliptical arc given in centre form (radii rx, ry, x-axis rotation phi,
// start angle t0, sweep dt) so that no chord strays more than `tol` from it. The sagitta of a
// chord spanning angle a on radius r is r (1 - cos(a/2)).
export function flattenArc(ring, cx, cy, rx, ry, phi, t0, dt, tol) {
  const r = Math.max(rx, ry);
  const step = r > tol ? 2 * Math.acos(Math.max(-1, 1 - tol / r)) : Math.PI / 2;
  const n = Math.min(MAX_STEPS, Math.max(1, Math.ceil(Math.abs(dt) / step)));
  const cos = Math.cos(phi), sin = Math.sin(phi);
  for (let i = 1; i <= n; i++) {
    const t = t0 + (dt * i) / n;
    const x = rx * Math.cos(t), y = ry * Math.sin(t);
    ring.push([cx + cos * x - sin * y, cy + sin * x + cos * y]);
  }
}

export function signedArea(ring) {
  let a = 0;
  for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
    a += (ring[j][0] - ring[i][0]) * (ring[j][1] + ring[i][1]);
  }
  return a / 2;
}

// Drops repeated consecutive points and the closing repeat, then rings too small to bound
// anything. The mesher would merge duplicates itself, but with a warning per point, and a
// degenerate ring is never what the user meant.
export function cleanRings(rings) {
  const out = [];
  for (const ring of rings) {
    const r = [];
    for (const p of ring) {
      if (!Number.isFinite(p[0]) || !Number.isFinite(p[1])) continue;
      const q = r[r.length - 1];
      if (!q || q[0] !== p[0] || q[1] !== p[1]) r.push([p[0], p[1]]);
    }
    while (r.length > 1 && r[0][0] === r[r.length - 1][0] && r[0][1] === r[r.length - 1][1]) r.pop();
    if (r.length >= 3 && signedArea(r) !== 0) out.push(r);
  }
  return out;
}

export function ringsBounds(rings) {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const ring of rings) {
    for (const [x, y] of ring) {
      if (x < x0) x0 = x;
      if (x > x1) x1 = x;
      if (y < y0) y0 = y;
      if (y > y1) y1 = y;
    }
  }
  return { x0, y0, x1, y1 };
}

export function pointsBounds(points) {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (let i = 0; i + 1 < points.length; i += 2) {
    const x = points[i], y = points[i + 1];
    if (x < x0) x0 = x;
    if (x > x1) x1 = x;
    if (y < y0) y0 = y;
    if (y > y1) y1 = y;
  }
  return { x0, y0, x1, y1 };
}

export function countPoints(rings) {
  return rings.reduce((n, r) => n + r.length, 0);
}
