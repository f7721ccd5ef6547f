// Benchmark inputs in Triangle's formats, deterministic for a given seed.
//
//   node bench/gen.mjs points N OUT.node [SEED]   N uniform random points in the unit square
//   node bench/gen.mjs star   N OUT.poly [SEED]   a random star-shaped polygon with N edges:
//                                                 N random angles, sorted, each at a random
//                                                 radius in [0.5, 1] around the origin
//
// Coordinates are printed with the shortest text that reads back to the same double, so
// every reader sees exactly the same input. Ids are 1-based, as Triangle writes them.
import { writeFileSync } from 'node:fs';
import { uniform } from './random.mjs';

const [kind, nText, out, seedText] = process.argv.slice(2);
const n = Number(nText);
if (!['points', 'star'].includes(kind) || !Number.isInteger(n) || n < 3 || !out) {
  console.error('usage: node bench/gen.mjs points|star N OUT [SEED]');
  process.exit(2);
}
const rand = uniform(seedText === undefined ? 20260101 : Number(seedText));
const lines = [];

if (kind === 'points') {
  lines.push(`# ${n} uniform random points in the unit square (bench/gen.mjs)`);
  lines.push(`${n} 2 0 0`);
  for (let i = 0; i < n; i++) lines.push(`${i + 1} ${rand()} ${rand()}`);
} else {
  const angles = new Float64Array(n);
  for (let i = 0; i < n; i++) angles[i] = rand() * 2 * Math.PI;
  angles.sort();
  lines.push(`# random star-shaped polygon with ${n} edges (bench/gen.mjs)`);
  lines.push(`${n} 2 0 0`);
  for (let i = 0; i < n; i++) {
    const r = 0.5 + 0.5 * rand();
    lines.push(`${i + 1} ${r * Math.cos(angles[i])} ${r * Math.sin(angles[i])}`);
  }
  lines.push(`${n} 0`);
  for (let i = 0; i < n; i++) lines.push(`${i + 1} ${i + 1} ${((i + 1) % n) + 1}`);
  lines.push('0');
}
lines.push('');
writeFileSync(out, lines.join('\n'));
