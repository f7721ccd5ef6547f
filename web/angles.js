// Per-triangle angles for colouring and the histogram. Floating point is enough here: the
// mesher certifies acuteness exactly and the page reports its verdict; these numbers only pick
// colours and bars.

// Classes of a triangle's largest angle, shown in the legend. `hi` is exclusive except for the
// right-angle class, which holds triangles whose largest corner has a dot product of exactly 0
// in floating point (grid-aligned right angles are exact there).
export const CLASSES = [
  { label: '< 70°', hi: 70, color: '#3a5fcd' },
  { label: '70–75°', hi: 75, color: '#2f8fd0' },
  { label: '75–80°', hi: 80, color: '#27b7c2' },
  { label: '80–85°', hi: 85, color: '#7fd49a' },
  { label: '85–88°', hi: 88, color: '#d9e36b' },
  { label: '88–90°', hi: 90, color: '#f5b342' },
  { label: '= 90°', hi: 90, color: '#ef7b2d', right: true },
  { label: '90–120°', hi: 120, color: '#d7301f' },
  { label: '≥ 120°', hi: Infinity, color: '#7f0000' },
];
const RIGHT = CLASSES.findIndex((c) => c.right);

const DEG = 180 / Math.PI;

// Returns { angles: Float64Array(3T) in degrees (single precision would turn 89.99999 into 90),
// cls: Uint8Array(T) class index per triangle, counts per class }.
// `bound` is the mesher's exact verdict, when it certified one: 'acute' (every corner's dot
// product > 0) or 'nonobtuse' (>= 0). Floating point can put a corner a hair on the wrong side
// of 90; with a bound, such angles are clamped to it. `below`: a bound under 90 that every
// angle is certified below (acute mode's max angle), clamped to the same way.
const BELOW_90 = 90 - 1e-9;
export function analyse(points, triangles, bound = null, below = null) {
  const T = triangles.length / 3;
  const angles = new Float64Array(3 * T);
  const cls = new Uint8Array(T);
  const counts = new Array(CLASSES.length).fill(0);
  for (let t = 0; t < T; t++) {
    const a = 2 * triangles[3 * t], b = 2 * triangles[3 * t + 1], c = 2 * triangles[3 * t + 2];
    const ax = points[a], ay = points[a + 1], bx = points[b], by = points[b + 1];
    const cx = points[c], cy = points[c + 1];
    const abx = bx - ax, aby = by - ay, bcx = cx - bx, bcy = cy - by, cax = ax - cx, cay = ay - cy;
    // The cross product is the same (twice the area) at every corner.
    const cross = Math.abs(abx * cay - aby * cax);
    const da = -(abx * cax + aby * cay), db = -(bcx * abx + bcy * aby), dc = -(cax * bcx + cay * bcy);
    let A = Math.atan2(cross, da) * DEG, B = Math.atan2(cross, db) * DEG, C = Math.atan2(cross, dc) * DEG;
    if (bound) {
      const cap = bound === 'acute' ? Math.min(BELOW_90, (below ?? 90) - 1e-9) : 90;
      A = Math.min(A, cap); B = Math.min(B, cap); C = Math.min(C, cap);
    }
    angles[3 * t] = A; angles[3 * t + 1] = B; angles[3 * t + 2] = C;
    let k;
    if (bound !== 'acute' && (da === 0 || db === 0 || dc === 0 || (bound === 'nonobtuse' && Math.max(A, B, C) === 90))) k = RIGHT;
    else {
      const m = Math.max(A, B, C);
      k = 0;
      while (m >= CLASSES[k].hi || CLASSES[k].right) k++;
    }
    cls[t] = k;
    counts[k]++;
  }
  return { angles, cls, counts };
}
