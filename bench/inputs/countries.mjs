// A country's outline from `gmt coast -E<ISO code> -M` (multi-segment ASCII: a '>' header
// before each ring, then "lon lat" lines, the ring's first point repeated at its end) to
// acutemesh's JSON rings input. bench/countries.sh makes the inputs with it.
//
//   node bench/inputs/countries.mjs GMT.txt OUT.json
//
// Prints "rings=N vertices=V degenerate=D" (after dropping each closing point; D rings on fewer
// than 3 distinct points left out). Coordinates are copied as GMT printed them (lon/lat
// degrees, meshed as plane coordinates).
import { readFileSync, writeFileSync } from 'node:fs';

const [src, out] = process.argv.slice(2);
if (!src || !out) {
  console.error('usage: node bench/inputs/countries.mjs GMT.txt OUT.json');
  process.exit(2);
}

const JSON_NUMBER = /^-?(0|[1-9]\d*)(\.\d+)?([eE][+-]?\d+)?$/;
const rings = [];
let ring = null;
let degenerate = 0;
const close = () => {
  if (!ring?.length) return;
  const [first, last] = [ring[0], ring[ring.length - 1]];
  if (ring.length > 1 && first[0] === last[0] && first[1] === last[1]) ring.pop();
  // A ring on fewer than 3 distinct points encloses nothing (DCW has a few, e.g. one point
  // three times); acutemesh rejects it, so it is left out.
  if (new Set(ring.map(([x, y]) => `${x} ${y}`)).size >= 3) rings.push(ring);
  else ++degenerate;
  ring = null;
};
const lines = readFileSync(src, 'utf8').split('\n');
lines.forEach((line, i) => {
  const t = line.trim();
  if (!t || t.startsWith('#')) return;
  if (t.startsWith('>')) {
    close();
    ring = [];
    return;
  }
  const [x, y] = t.split(/\s+/);
  if (!JSON_NUMBER.test(x ?? '') || !JSON_NUMBER.test(y ?? '')) {
    console.error(`countries: ${src}:${i + 1}: not "lon lat": ${t}`);
    process.exit(1);
  }
  (ring ??= []).push([x, y]);
});
close();

const vertices = rings.reduce((n, r) => n + r.length, 0);
// One ring per line, the numbers as GMT wrote them.
const body = rings.map((r) => `[${r.map(([x, y]) => `[${x},${y}]`).join(',')}]`).join(',\n');
writeFileSync(out, `{"rings": [\n${body}\n]}\n`);
console.log(`rings=${rings.length} vertices=${vertices} degenerate=${degenerate}`);
