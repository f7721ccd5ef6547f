// The SVG download: the mesh as the view draws it, triangles coloured by their largest angle
// (the legend's classes), edges, input segments in black and Steiner points as dots sized by
// their shortest edge; y up, as in the view. The mesher's own SVG writer draws every triangle
// in one colour, so the page writes this one.
import { CLASSES } from './angles.js';

const STEINER_COLOR = '#c2185b';

// m: { points, triangles, segments }; cls: class index per triangle; nInput: the input's
// vertex count (Steiner points follow it); fills: [{ color, label }] per class (the largest
// angle's classes by default, or the regions' colours when the view shows regions).
export function meshToSvg(m, cls, nInput, fills = CLASSES.map((c) => ({ color: c.color, label: c.label }))) {
  const { points: p, triangles: t, segments: seg } = m;
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (let i = 0; i < t.length; i++) {
    const x = p[2 * t[i]], y = p[2 * t[i] + 1];
    x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y);
  }
  if (!(x1 >= x0)) { x0 = y0 = 0; x1 = y1 = 1; }
  const size = Math.max(x1 - x0, y1 - y0) || 1;
  const pad = size / 100, line = size / 1600;
  // Coordinates relative to the drawing's corner, y flipped, to a 1e-6 share of its size.
  const f = (v) => String(+v.toFixed(Math.max(0, 6 - Math.ceil(Math.log10(size)))));
  const X = (i) => f(p[2 * i] - x0), Y = (i) => f(y1 - p[2 * i + 1]);
  const byClass = fills.map(() => []);
  const edges = [];
  const shortest = new Float64Array(p.length / 2).fill(Infinity);
  for (let k = 0; k < t.length / 3; k++) {
    const [a, b, c] = [t[3 * k], t[3 * k + 1], t[3 * k + 2]];
    byClass[cls[k]].push(`M${X(a)} ${Y(a)}L${X(b)} ${Y(b)}L${X(c)} ${Y(c)}Z`);
    for (const [u, v] of [[a, b], [b, c], [c, a]]) {
      if (u < v) edges.push(`M${X(u)} ${Y(u)}L${X(v)} ${Y(v)}`);
      const d = Math.hypot(p[2 * u] - p[2 * v], p[2 * u + 1] - p[2 * v + 1]);
      shortest[u] = Math.min(shortest[u], d);
      shortest[v] = Math.min(shortest[v], d);
    }
  }
  const segments = [];
  for (let i = 0; i + 1 < seg.length; i += 2) segments.push(`M${X(seg[i])} ${Y(seg[i])}L${X(seg[i + 1])} ${Y(seg[i + 1])}`);
  const dots = [];
  for (let v = nInput; v < p.length / 2; v++) {
    if (Number.isFinite(shortest[v])) dots.push(`<circle cx="${X(v)}" cy="${Y(v)}" r="${f(Math.min(0.15 * shortest[v], size / 250))}"/>`);
  }
  const w = f(x1 - x0 + 2 * pad), h = f(y1 - y0 + 2 * pad);
  return [
    `<svg xmlns="http://www.w3.org/2000/svg" viewBox="${f(-pad)} ${f(-pad)} ${w} ${h}">`,
    ...fills.map((c, k) => (byClass[k].length
      ? `<path data-class="${xmlAttribute(c.label)}" fill="${c.color}" d="${byClass[k].join('')}"/>` : '')).filter(Boolean),
    `<path fill="none" stroke="#5d6675" stroke-opacity="0.55" stroke-width="${f(line)}" d="${edges.join('')}"/>`,
    `<path fill="none" stroke="#111" stroke-width="${f(3.5 * line)}" stroke-linecap="round" d="${segments.join('')}"/>`,
    `<g fill="${STEINER_COLOR}">${dots.join('')}</g>`,
    '</svg>',
    '',
  ].join('\n');
}

// A label as an XML attribute value: the class "< 70°" would otherwise make the file
// malformed (no '<' in an attribute), and an SVG viewer refuse it.
function xmlAttribute(text) {
  return String(text).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');
}
