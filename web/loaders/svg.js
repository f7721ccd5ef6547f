// SVG -> rings and a fill rule. Reads <path>, <polygon>, <polyline>, <rect>, <circle> and
// <ellipse> (outside <defs>, <clipPath>, <mask>, <symbol>, <pattern>, <marker>), applies
// their `transform` attributes and those of their ancestors, and flattens curves and arcs
// within `tolerance` thousandths of the drawing's size. The document is parsed with
// DOMParser and never attached to the page, so nothing in it runs.
import { flattenQuad, flattenCubic, flattenArc, cleanRings } from '../geometry.js';

const SKIP = new Set(['defs', 'clipPath', 'mask', 'symbol', 'pattern', 'marker', 'metadata', 'title', 'desc']);

// --- transforms: [a, b, c, d, e, f] as in matrix(a b c d e f) -------------------------------
const IDENTITY = [1, 0, 0, 1, 0, 0];

function multiply(m, n) {
  return [m[0] * n[0] + m[2] * n[1], m[1] * n[0] + m[3] * n[1],
    m[0] * n[2] + m[2] * n[3], m[1] * n[2] + m[3] * n[3],
    m[0] * n[4] + m[2] * n[5] + m[4], m[1] * n[4] + m[3] * n[5] + m[5]];
}

export function parseTransform(text) {
  let m = IDENTITY;
  const re = /(matrix|translate|scale|rotate|skewX|skewY)\s*\(([^)]*)\)/g;
  let t;
  while ((t = re.exec(text || ''))) {
    const v = (t[2].match(/[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?/g) || []).map(Number);
    const rad = ((v[0] || 0) * Math.PI) / 180;
    let n;
    switch (t[1]) {
      case 'matrix': n = v.length === 6 ? v : IDENTITY; break;
      case 'translate': n = [1, 0, 0, 1, v[0] || 0, v[1] || 0]; break;
      case 'scale': n = [v[0] ?? 1, 0, 0, v[1] ?? v[0] ?? 1, 0, 0]; break;
      case 'rotate': {
        const c = Math.cos(rad), s = Math.sin(rad), cx = v[1] || 0, cy = v[2] || 0;
        n = multiply(multiply([1, 0, 0, 1, cx, cy], [c, s, -s, c, 0, 0]), [1, 0, 0, 1, -cx, -cy]);
        break;
      }
      case 'skewX': n = [1, 0, Math.tan(rad), 1, 0, 0]; break;
      case 'skewY': n = [1, Math.tan(rad), 0, 1, 0, 0]; break;
    }
    m = multiply(m, n);
  }
  return m;
}

// --- path data ----------------------------------------------------------------------------
// Tokens are command letters and numbers. Arc flags may be written without separators
// ("a5 5 0 015 5"), so they are read one character at a time where the grammar expects them.
function* pathTokens(d) {
  const re = /([MmLlHhVvCcSsQqTtAaZz])|([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)|([\s,]+)|(.)/g;
  let t;
  while ((t = re.exec(d))) {
    if (t[1]) yield { cmd: t[1] };
    else if (t[2]) yield { num: t[2] };
    else if (t[4]) throw new Error(`SVG path: unexpected '${t[4]}' at ${t.index}`);
  }
}

const ARITY = { M: 2, L: 2, H: 1, V: 1, C: 6, S: 4, Q: 4, T: 2, A: 7, Z: 0 };

function splitArcFlags(tokens) {
  // Re-split numbers in flag positions (4th and 5th argument of each arc) into single digits.
  const out = [];
  let cmd = null, argi = 0;
  for (const t of tokens) {
    if (t.cmd) { cmd = t.cmd.toUpperCase(); argi = 0; out.push(t); continue; }
    let s = t.num;
    while (s.length) {
      const k = cmd === 'A' ? argi % 7 : -1;
      if ((k === 3 || k === 4) && (s[0] === '0' || s[0] === '1')) {
        out.push({ num: s[0] });
        s = s.slice(1);
      } else {
        out.push({ num: s });
        s = '';
      }
      argi++;
    }
  }
  return out;
}

// Endpoint arc -> centre form (SVG 1.1 appendix F.6.5), then flattened.
function arcTo(ring, x1, y1, rx, ry, phiDeg, large, sweep, x2, y2, tol) {
  if (x1 === x2 && y1 === y2) return;
  rx = Math.abs(rx); ry = Math.abs(ry);
  if (!rx || !ry) { ring.push([x2, y2]); return; }
  const phi = (phiDeg * Math.PI) / 180, c = Math.cos(phi), s = Math.sin(phi);
  const dx = (x1 - x2) / 2, dy = (y1 - y2) / 2;
  const xp = c * dx + s * dy, yp = -s * dx + c * dy;
  const lambda = (xp * xp) / (rx * rx) + (yp * yp) / (ry * ry);
  if (lambda > 1) { rx *= Math.sqrt(lambda); ry *= Math.sqrt(lambda); }
  const num = rx * rx * ry * ry - rx * rx * yp * yp - ry * ry * xp * xp;
  const den = rx * rx * yp * yp + ry * ry * xp * xp;
  let k = Math.sqrt(Math.max(0, num / den));
  if (large === sweep) k = -k;
  const cxp = (k * rx * yp) / ry, cyp = (-k * ry * xp) / rx;
  const cx = c * cxp - s * cyp + (x1 + x2) / 2, cy = s * cxp + c * cyp + (y1 + y2) / 2;
  const angle = (ux, uy, vx, vy) => Math.atan2(ux * vy - uy * vx, ux * vx + uy * vy);
  const t0 = angle(1, 0, (xp - cxp) / rx, (yp - cyp) / ry);
  let dt = angle((xp - cxp) / rx, (yp - cyp) / ry, (-xp - cxp) / rx, (-yp - cyp) / ry);
  if (!sweep && dt > 0) dt -= 2 * Math.PI;
  if (sweep && dt < 0) dt += 2 * Math.PI;
  flattenArc(ring, cx, cy, rx, ry, phi, t0, dt, tol);
  ring[ring.length - 1] = [x2, y2];  // land exactly on the endpoint the next command starts from
}

export function pathToRings(d, tol) {
  const tokens = splitArcFlags([...pathTokens(d)]);
  const rings = [];
  let ring = null, cmd = null, i = 0;
  let x = 0, y = 0, sx = 0, sy = 0, cx = 0, cy = 0, prev = '';
  const num = () => {
    const t = tokens[i++];
    if (!t || t.num === undefined) throw new Error(`SVG path: command ${cmd} is missing numbers`);
    return Number(t.num);
  };
  const finish = () => { if (ring && ring.length > 1) rings.push(ring); ring = null; };
  while (i < tokens.length) {
    if (tokens[i].cmd) cmd = tokens[i++].cmd;
    else if (!cmd) throw new Error('SVG path: data must start with a command');
    const C = cmd.toUpperCase(), rel = cmd !== C;
    const ox = rel ? x : 0, oy = rel ? y : 0;
    if (C === 'Z') {
      finish();
      x = sx; y = sy; prev = 'Z';
      if (i < tokens.length && !tokens[i].cmd) cmd = 'L';  // numbers after Z: an implicit lineto
      continue;
    }
    if (!ring) ring = [[x, y]];
    switch (C) {
      case 'M':
        finish();
        x = ox + num(); y = oy + num(); sx = x; sy = y;
        ring = [[x, y]];
        cmd = rel ? 'l' : 'L';  // further pairs after a moveto are linetos
        break;
      case 'L': x = ox + num(); y = oy + num(); ring.push([x, y]); break;
      case 'H': x = ox + num(); ring.push([x, y]); break;
      case 'V': y = oy + num(); ring.push([x, y]); break;
      case 'C': case 'S': {
        let x1, y1;
        if (C === 'C') { x1 = ox + num(); y1 = oy + num(); } else if ('CS'.includes(prev)) { x1 = 2 * x - cx; y1 = 2 * y - cy; } else { x1 = x; y1 = y; }
        const x2 = ox + num(), y2 = oy + num(), x3 = ox + num(), y3 = oy + num();
        flattenCubic(ring, x, y, x1, y1, x2, y2, x3, y3, tol);
        cx = x2; cy = y2; x = x3; y = y3;
        break;
      }
      case 'Q': case 'T': {
        let x1, y1;
        if (C === 'Q') { x1 = ox + num(); y1 = oy + num(); } else if ('QT'.includes(prev)) { x1 = 2 * x - cx; y1 = 2 * y - cy; } else { x1 = x; y1 = y; }
        const x2 = ox + num(), y2 = oy + num();
        flattenQuad(ring, x, y, x1, y1, x2, y2, tol);
        cx = x1; cy = y1; x = x2; y = y2;
        break;
      }
      case 'A': {
        const rx = num(), ry = num(), rot = num(), large = num(), sweep = num();
        const x2 = ox + num(), y2 = oy + num();
        arcTo(ring, x, y, rx, ry, rot, !!large, !!sweep, x2, y2, tol);
        x = x2; y = y2;
        break;
      }
      default: throw new Error(`SVG path: unknown command ${cmd}`);
    }
    prev = C === 'M' ? 'L' : C;
  }
  finish();
  return rings;
}

// --- elements -----------------------------------------------------------------------------
const attrNum = (el, name, dflt = 0) => {
  const v = parseFloat(el.getAttribute(name));
  return Number.isFinite(v) ? v : dflt;
};

function ellipseRing(cx, cy, rx, ry, tol) {
  const ring = [[cx + rx, cy]];
  flattenArc(ring, cx, cy, rx, ry, 0, 0, 2 * Math.PI, tol);
  ring.pop();  // the arc ends where it started
  return ring;
}

function elementRings(el, tol) {
  switch (el.localName) {
    case 'path': return pathToRings(el.getAttribute('d') || '', tol);
    case 'polygon': case 'polyline': {
      const v = (el.getAttribute('points') || '').match(/[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?/g) || [];
      const ring = [];
      for (let k = 0; k + 1 < v.length; k += 2) ring.push([+v[k], +v[k + 1]]);
      return [ring];  // a filled polyline closes implicitly, like a polygon
    }
    case 'rect': {
      const x = attrNum(el, 'x'), y = attrNum(el, 'y'), w = attrNum(el, 'width'), h = attrNum(el, 'height');
      return [[[x, y], [x + w, y], [x + w, y + h], [x, y + h]]];
    }
    case 'circle': {
      const r = attrNum(el, 'r');
      return [ellipseRing(attrNum(el, 'cx'), attrNum(el, 'cy'), r, r, tol)];
    }
    case 'ellipse':
      return [ellipseRing(attrNum(el, 'cx'), attrNum(el, 'cy'), attrNum(el, 'rx'), attrNum(el, 'ry'), tol)];
    default: return [];
  }
}

function styleProp(el, name) {
  const m = (el.getAttribute('style') || '').match(new RegExp(`(?:^|;)\\s*${name}\\s*:\\s*([^;]+)`));
  return (m && m[1].trim()) || el.getAttribute(name);
}

// Returns { rings, fill, mixed } (fill 'nonzero' or 'evenodd'; mixed when elements disagree,
// since one mesh domain has one rule) or throws.
export function svgToRings(text, tolerance) {
  const doc = new DOMParser().parseFromString(text, 'image/svg+xml');
  const root = doc.documentElement;
  if (!root || root.localName !== 'svg' || doc.getElementsByTagName('parsererror').length) {
    throw new Error('not an SVG document (XML parse error or no <svg> root)');
  }
  const vb = (root.getAttribute('viewBox') || '').split(/[\s,]+/).map(Number);
  const size = vb.length === 4 && vb.every(Number.isFinite) ? Math.max(vb[2], vb[3])
    : Math.max(attrNum(root, 'width', 0), attrNum(root, 'height', 0)) || 1000;
  const rings = [], rules = new Set();
  const walk = (el, m, rule) => {
    if (SKIP.has(el.localName)) return;
    const mm = multiply(m, parseTransform(el.getAttribute('transform')));
    const r = styleProp(el, 'fill-rule') || rule;
    // Flatten in the element's own units with the tolerance scaled by the transform, so a
    // small path drawn scaled up is not under-sampled.
    const scale = Math.sqrt(Math.abs(mm[0] * mm[3] - mm[1] * mm[2])) || 1;
    const own = elementRings(el, (tolerance / 1000) * size / scale);
    if (own.length) rules.add(r === 'evenodd' ? 'evenodd' : 'nonzero');
    for (const ring of own) {
      // SVG is y down; the mesher's frame is y up.
      rings.push(ring.map(([x, y]) => [mm[0] * x + mm[2] * y + mm[4], -(mm[1] * x + mm[3] * y + mm[5])]));
    }
    for (const child of el.children) walk(child, mm, r);
  };
  walk(root, IDENTITY, 'nonzero');
  const clean = cleanRings(rings);
  if (!clean.length) throw new Error('no filled shape (path, polygon, rect, circle, ellipse) in this SVG');
  return { rings: clean, fill: rules.size === 1 ? [...rules][0] : 'nonzero', mixed: rules.size > 1 };
}
