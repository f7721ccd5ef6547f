// One mesh through the npm package (dist/, WebAssembly in Node) for bench/countries.sh: prints
// the stats as the CLI's --stats does, plus "jsSeconds" (parse + mesh, timed in JS).
//
//   node bench/inputs/countries_wasm.mjs INPUT.json MODE TIME_LIMIT_S
import { readFileSync } from 'node:fs';

import init from 'acutemesh';

const [file, mode, limit] = process.argv.slice(2);
if (!file || !mode) {
  console.error('usage: node bench/inputs/countries_wasm.mjs INPUT.json MODE [TIME_LIMIT_S]');
  process.exit(2);
}
const am = await init();
const text = readFileSync(file, 'utf8');
const t0 = performance.now();
const pslg = am.parseJson(text, { name: file });
const m = am.mesh(pslg, { mode, timeLimit: Number(limit || 0) });
const jsSeconds = (performance.now() - t0) / 1000;
const { stats } = m;
console.log(JSON.stringify({ mode, status: m.status, ...stats, jsSeconds, heapBytes: am.memory().heapSize }));
if (m.status !== 'ok') console.error(`countries_wasm: ${m.message}`);
process.exit(m.status === 'ok' ? 0 : 1);
