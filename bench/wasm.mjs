// bench/wasm.sh's measuring and report: the npm package (dist/, as `import 'acutemesh'`
// resolves it) against the native library call (bench_acutemesh) on the same inputs, and
// delaunator on the same 10^6 points.
//
//   node bench/wasm.mjs NATIVE_DRIVER OUT.md
import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync, writeFileSync, readdirSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import os from 'node:os';
import { createRequire } from 'node:module';

import init from 'acutemesh';
import Delaunator from 'delaunator';

const [nativeDriver, out] = process.argv.slice(2);
const runs = Number(process.env.WASM_BENCH_RUNS || 10);
// The reference data by the tests' rule: $ACUTEMESH_DATA, else ../shared/data.
const shared = process.env.ACUTEMESH_DATA ?? '../shared/data';
const note = (s) => process.stderr.write(`bench:wasm: ${s}\n`);

// label, file, fill (mode: acute and nonobtuse for each, then the Delaunay case)
const inputs = [
  ['"Acute" (DejaVu Sans outline)', 'bench/inputs/data/acute-text.json', 'nonzero'],
  ['"acutemesh" (DejaVu Sans outline)', 'bench/inputs/data/acutemesh-text.json', 'nonzero'],
  ['A.poly', 'tests/data/A.poly', 'triangle'],
  ['superior.poly (Lake Superior)', `${shared}/poly/superior.poly`, 'triangle'],
  ['Random: 1000 points + 4 corners', 'bench/inputs/data/random.node', 'triangle'],
  ['plate', 'bench/inputs/data/plate.poly', 'triangle'],
  ['NACA 0012 airfoil', 'bench/inputs/data/naca0012.poly', 'triangle'],
];
const cases = [];
for (const mode of ['acute', 'nonobtuse'])
  for (const [label, file, fill] of inputs) {
    if (existsSync(file)) cases.push({ label, file, mode, fill, repeat: runs });
    else if (mode === 'acute') note(`skipped: ${label} (needs the reference data: set ACUTEMESH_DATA, or put it at ../shared/data)`);
  }
cases.push({ label: '10^6 uniform points', file: 'bench/work/uniform-1e6.node', mode: 'delaunay', fill: 'triangle', repeat: 3 });

const kv = (line, key) => (line.match(new RegExp(`(?:^| )${key}=(\\S+)`)) || [])[1];

const am = await init();
function load(file) {
  const text = readFileSync(file, 'utf8');
  if (file.endsWith('.poly')) return am.parsePoly(text, { name: file });
  if (file.endsWith('.node')) return am.parseNode(text, { name: file });
  return am.parseJson(text, { name: file });
}

// One untimed pass over the refinement inputs first: V8 runs new wasm code on its baseline
// compiler and optimizes the hot functions in the background, which would otherwise be
// charged to whichever input comes first.
for (const c of cases) if (c.mode !== 'delaunay') am.mesh(load(c.file), { mode: c.mode, fill: c.fill });

const loadStart = os.loadavg();
const rows = [];
for (const c of cases) {
  note(`${c.mode} ${c.file}`);
  const line = execFileSync(nativeDriver, ['--mode', c.mode, '--fill', c.fill, '--repeat', String(c.repeat), c.file],
    { encoding: 'utf8' });
  const native = { ms: Number(kv(line, 'best_ms')), triangles: Number(kv(line, 'triangles')), certified: kv(line, 'certified') === '1' };
  const pslg = load(c.file);
  let best = Infinity, bestCore = Infinity, m;
  for (let r = 0; r < c.repeat; ++r) {
    const t = performance.now();
    m = am.mesh(pslg, { mode: c.mode, fill: c.fill });
    best = Math.min(best, performance.now() - t);
    bestCore = Math.min(bestCore, m.stats.seconds * 1000);
  }
  const row = { ...c, native, wasm: { ms: best, coreMs: bestCore, triangles: m.stats.triangles, certified: m.stats.certified } };
  if (c.mode === 'delaunay') {
    let d = Infinity, tris = 0;
    for (let r = 0; r < c.repeat; ++r) {
      const t = performance.now();
      const del = new Delaunator(pslg.points);
      d = Math.min(d, performance.now() - t);
      tris = del.triangles.length / 3;
    }
    row.delaunator = { ms: d, triangles: tris };
  }
  m = null;
  rows.push(row);
}
const loadEnd = os.loadavg();

const wasmBytes = readFileSync('dist/acutemesh.wasm');
const glueBytes = readFileSync('dist/acutemesh.mjs');
const facade = readdirSync('dist').filter((f) => f.endsWith('.js') && f !== 'wasm-inline.js')
  .reduce((s, f) => s + readFileSync(`dist/${f}`).length, 0);
const gz = (b) => gzipSync(b, { level: 9 }).length;
const kb = (n) => `${(n / 1024).toFixed(1)} KB`;
const require = createRequire(import.meta.url);
const delaunatorVersion = require('delaunator/package.json').version;

const fmt = (ms) => (ms >= 100 ? `${(ms / 1000).toFixed(3)} s` : `${ms.toFixed(2)} ms`);
const ratio = (a, b) => (a / b).toFixed(2);
const lines = [];
lines.push(`# WebAssembly vs native, ${new Date().toISOString().slice(0, 10)}`);
lines.push('');
lines.push('Made by `npm run bench:wasm` (bench/wasm.sh, bench/wasm.mjs).');
lines.push('');
lines.push(`- Machine: ${os.cpus()[0].model}, ${os.cpus().length} cores, ${(os.totalmem() / 2 ** 30).toFixed(1)} GB, ${os.type()} ${os.release()}; shared with other jobs.`);
lines.push(`- Load average (1, 5, 15 min) at the start: ${loadStart.map((x) => x.toFixed(2)).join(', ')}; at the end: ${loadEnd.map((x) => x.toFixed(2)).join(', ')}.`);
lines.push(`- Native: g++ -O3 (Release), bench_acutemesh, best of N library calls (mesh() only).`);
lines.push(`- WASM: emcc ${process.env.EMCC_VERSION || ''} -O3, Node ${process.version}; best of N calls of \`am.mesh()\` from dist/ timed in JS (includes copying input and output across the JS/wasm boundary), after one untimed warm-up pass over the refinement inputs; "core" is the same call's own clock (\`stats.seconds\`).`);
lines.push(`- delaunator ${delaunatorVersion}: best of 3 of \`new Delaunator(points)\` on the same Float64Array.`);
lines.push('');
lines.push('| input | mode | triangles | native | wasm (JS call) | wasm (core) | wasm / native | certified native / wasm |');
lines.push('|---|---|---:|---:|---:|---:|---:|---|');
for (const r of rows) {
  lines.push(`| ${r.label} | ${r.mode} | ${r.wasm.triangles} | ${fmt(r.native.ms)} | ${fmt(r.wasm.ms)} | ${fmt(r.wasm.coreMs)} | ${ratio(r.wasm.ms, r.native.ms)} | ${r.mode === 'delaunay' ? '-' : `${r.native.certified} / ${r.wasm.certified}`} |`);
  if (r.native.triangles !== r.wasm.triangles) lines.push(`|  | (native made ${r.native.triangles} triangles) | | | | | | |`);
}
const del = rows.find((r) => r.delaunator);
const refine = rows.filter((r) => r.mode !== 'delaunay');
const geo = Math.exp(refine.reduce((s, r) => s + Math.log(r.wasm.ms / r.native.ms), 0) / refine.length);
lines.push('');
lines.push(`Refinement inputs: wasm / native geometric mean ${geo.toFixed(2)} (min ${Math.min(...refine.map((r) => r.wasm.ms / r.native.ms)).toFixed(2)}, max ${Math.max(...refine.map((r) => r.wasm.ms / r.native.ms)).toFixed(2)}).`);
lines.push('');
lines.push('| Delaunay of 10^6 uniform points | time | triangles |');
lines.push('|---|---:|---:|');
lines.push(`| native acutemesh | ${fmt(del.native.ms)} | ${del.native.triangles} |`);
lines.push(`| acutemesh wasm in Node (JS call) | ${fmt(del.wasm.ms)} | ${del.wasm.triangles} |`);
lines.push(`| delaunator ${delaunatorVersion} in Node | ${fmt(del.delaunator.ms)} | ${del.delaunator.triangles} |`);
lines.push('');
lines.push(`wasm / native ${ratio(del.wasm.ms, del.native.ms)}; wasm / delaunator ${ratio(del.wasm.ms, del.delaunator.ms)}.`);
lines.push('');
lines.push('| file | bytes | gzip -9 |');
lines.push('|---|---:|---:|');
lines.push(`| dist/acutemesh.wasm | ${kb(wasmBytes.length)} | ${kb(gz(wasmBytes))} |`);
lines.push(`| dist/acutemesh.mjs (Emscripten glue) | ${kb(glueBytes.length)} | ${kb(gz(glueBytes))} |`);
lines.push(`| the facade's .js files (without wasm-inline.js) | ${kb(facade)} | |`);
lines.push('');
const worst = Math.max(...refine.map((r) => r.wasm.ms / r.native.ms), del.wasm.ms / del.native.ms);
const met = (ok) => (ok ? 'met' : '**not met**');
lines.push('Targets (issue 4):');
lines.push(`- wasm within 1.5x of native on every case above: ${met(worst <= 1.5)} (worst ${worst.toFixed(2)}).`);
lines.push(`- Delaunay of 10^6 points faster than delaunator: ${met(del.wasm.ms < del.delaunator.ms)}.`);
lines.push(`- .wasm at most 150 KB gzipped: ${met(gz(wasmBytes) <= 150 * 1024)}.`);
lines.push('');
writeFileSync(out, lines.join('\n'));
