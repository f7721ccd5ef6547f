// A word's outline from a TrueType/OpenType font, as acutemesh JSON rings (deterministic).
//
//   node bench/inputs/text.mjs WORD OUT.json [FONT|-] [TOLERANCE|-]
//
// FONT defaults to Debian's DejaVu Sans (package fonts-dejavu-core); TOLERANCE is the largest
// distance, in font units (DejaVu: 2048 per em), between a curve and the segments replacing it
// (default 4, about 0.2 % of the em). The glyphs are laid out by their advance widths (no
// shaping, no kerning), baseline at y = 0, y pointing up, coordinates in font units rounded to
// 1/100 unit.
//
// Fill rule: fonts use the NON-ZERO winding rule (TrueType outer contours run one way, counters
// the other, and overlapping contours are allowed), so mesh these files with
// `acutemesh --fill nonzero` (the default for JSON rings is even-odd). The ring orientation is
// kept as the font has it (y flipped, so all rings are reversed alike; the winding numbers only
// change sign).
//
// Each quadratic or cubic Bezier piece is replaced by n equal-parameter chords, n the smallest
// count whose chord error bound (|B''|max / (8 n^2)) is within TOLERANCE. Consecutive duplicate
// points (also across the ring's closing edge) are dropped, and so are rings with fewer than
// 3 points or zero area (DejaVu has single-point contours, e.g. in "u").
import { readFileSync, writeFileSync } from 'node:fs';
import opentype from 'opentype.js';

const DEFAULT_FONT = '/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf';
const [word, out, fontArg, tolArg] = process.argv.slice(2);
const fontPath = fontArg && fontArg !== '-' ? fontArg : DEFAULT_FONT;
const tol = Number(tolArg && tolArg !== '-' ? tolArg : 4);
if (!word || !out || !(tol > 0)) {
  console.error('usage: node bench/inputs/text.mjs WORD OUT.json [FONT] [TOLERANCE]');
  process.exit(2);
}

const buf = readFileSync(fontPath);
const font = opentype.parse(buf.buffer.slice(buf.byteOffset, buf.byteOffset + buf.byteLength));
const size = font.unitsPerEm;  // path coordinates in font units

const round = (v) => {
  const x = Math.round(v * 100) / 100;
  return Object.is(x, -0) ? 0 : x;
};

// Number of chords for a curve whose second derivative is at most `d2` in length.
const pieces = (d2) => Math.max(1, Math.ceil(Math.sqrt(d2 / (8 * tol)) - 1e-9));
const len = (x, y) => Math.hypot(x, y);

const rings = [];
let cur = null;
let x0 = 0;
let y0 = 0;
const finish = () => {
  if (cur) rings.push(cur);
  cur = null;
};
const add = (x, y) => {
  cur.push([x, y]);
  x0 = x;
  y0 = y;
};

let penX = 0;
for (const ch of word) {
  const glyph = font.charToGlyph(ch);
  const path = glyph.getPath(penX, 0, size);
  penX += glyph.advanceWidth;
  for (const c of path.commands) {
    switch (c.type) {
      case 'M':
        finish();
        cur = [];
        add(c.x, c.y);
        break;
      case 'L':
        add(c.x, c.y);
        break;
      case 'Q': {
        // B''(t) = 2 (P0 - 2 P1 + P2), constant.
        const n = pieces(2 * len(x0 - 2 * c.x1 + c.x, y0 - 2 * c.y1 + c.y));
        const [ax, ay] = [x0, y0];
        for (let i = 1; i <= n; i++) {
          const t = i / n;
          const s = 1 - t;
          add(s * s * ax + 2 * s * t * c.x1 + t * t * c.x, s * s * ay + 2 * s * t * c.y1 + t * t * c.y);
        }
        break;
      }
      case 'C': {
        // B''(t) = 6 ((1 - t) (P0 - 2 P1 + P2) + t (P1 - 2 P2 + P3)): at most 6 max of the two.
        const d2 = 6 * Math.max(len(x0 - 2 * c.x1 + c.x2, y0 - 2 * c.y1 + c.y2),
          len(c.x1 - 2 * c.x2 + c.x, c.y1 - 2 * c.y2 + c.y));
        const n = pieces(d2);
        const [ax, ay] = [x0, y0];
        for (let i = 1; i <= n; i++) {
          const t = i / n;
          const s = 1 - t;
          add(s * s * s * ax + 3 * s * s * t * c.x1 + 3 * s * t * t * c.x2 + t * t * t * c.x,
            s * s * s * ay + 3 * s * s * t * c.y1 + 3 * s * t * t * c.y2 + t * t * t * c.y);
        }
        break;
      }
      case 'Z':
        finish();
        break;
      default:
        throw new Error(`unexpected path command ${c.type}`);
    }
  }
  finish();
}

const clean = [];
let points = 0;
for (const ring of rings) {
  // Round, flip y (font paths point down), drop consecutive duplicates, cyclically.
  const r = [];
  for (const [x, y] of ring) {
    const p = [round(x), round(-y)];
    const q = r[r.length - 1];
    if (!q || q[0] !== p[0] || q[1] !== p[1]) r.push(p);
  }
  while (r.length > 1 && r[0][0] === r[r.length - 1][0] && r[0][1] === r[r.length - 1][1]) r.pop();
  if (r.length < 3) continue;
  let area2 = 0;
  for (let i = 0; i < r.length; i++) {
    const [ax, ay] = r[i];
    const [bx, by] = r[(i + 1) % r.length];
    area2 += ax * by - bx * ay;
  }
  if (Math.abs(area2) < 1e-6) continue;  // zero area (up to the rounding of the sum)
  clean.push(r);
  points += r.length;
}

// One ring per line: short diffs, easy to read.
const body = clean.map((r) => '  ' + JSON.stringify(r)).join(',\n');
writeFileSync(out, `{"rings": [\n${body}\n]}\n`);
console.error(`text: "${word}": ${clean.length} rings, ${points} points (tolerance ${tol} font units)`);
