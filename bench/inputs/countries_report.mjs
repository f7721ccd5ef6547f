// Writes the countries report from the runs bench/countries.sh kept.
//
//   node bench/inputs/countries_report.mjs --work bench/work/countries --out bench/results/countries-DATE.md
//
// Reads WORK/cases.txt (id|label|ISO code|file|runs|time limit) and WORK/runs/ID.MODE.K.{json,
// err,rc,time,wall} plus ID.MODE.load (the 1-minute load average before that mode's runs);
// MODE wasm-acute is the npm package in Node. Environment from countries.sh: LOAD_START, LOAD_END.
import { writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';

import { cpu, opt, readRun, readText, sh } from './runs.mjs';

const work = opt('--work');
const out = opt('--out');
if (!work || !out) {
  console.error('usage: node bench/inputs/countries_report.mjs --work DIR --out FILE.md');
  process.exit(2);
}
const runDir = path.join(work, 'runs');
const MODES = ['cdt', 'quality', 'acute', 'nonobtuse'];
// Issue 25's targets.
const TARGET = { throughput: 300000, bytesPerTriangle: 150, bigVertices: 1e5, coastlineSeconds: 30, wasmSeconds: 60 };

const cases = (readText(path.join(work, 'cases.txt')) || '')
  .split('\n')
  .filter(Boolean)
  .map((l) => {
    const [id, label, code, file, runs, limit] = l.split('|');
    return { id, label, code, file, runs: Number(runs), limit: Number(limit) };
  });

// One run with its wall time (ms) and peak RSS (KB; GNU time's last line "%e %M").
function run(base) {
  const r = readRun(base);
  if (!r) return null;
  r.wallMs = Number((readText(`${base}.wall`) || '').trim()) || null;
  const time = (readText(`${base}.time`) || '').trim().split('\n');
  const [, rss] = (time.at(-1) || '').split(' ');
  r.rssKb = Number(rss) || null;
  r.timeNote = time.length > 1 ? time.slice(0, -1).join(' ') : ''; // "Command terminated by signal N"
  return r;
}
// N runs: the one with the least wall time, the largest peak RSS of them all.
function measure(id, mode, n) {
  const runs = [];
  for (let k = 1; k <= n; ++k) {
    const r = run(path.join(runDir, `${id}.${mode}.${k}`));
    if (r) runs.push(r);
  }
  if (!runs.length) return null;
  const timed = runs.filter((r) => r.wallMs !== null);
  const best = timed.length ? timed.reduce((a, r) => (r.wallMs < a.wallMs ? r : a)) : runs[0];
  const rss = Math.max(...runs.map((r) => r.rssKb || 0)) || null;
  const load = (readText(path.join(runDir, `${id}.${mode}.load`)) || '?').trim();
  return { ...best, rssKb: rss, n: runs.length, load };
}
// Input vertices once the duplicates are merged (DCW repeats many points: a third of Canada's).
const distinct = (s) => s.inputVertices - (s.duplicates || 0);
const totalSeconds = (s) => (typeof s?.seconds === 'number' ? s.seconds : s?.seconds?.total);

// --- formatting --------------------------------------------------------------------------------
const fmtInt = (v) => (typeof v === 'number' && Number.isFinite(v) ? Math.round(v).toLocaleString('en-US') : '—');
const fmtS = (s) => (typeof s !== 'number' ? '—' : s < 1 ? s.toFixed(3) : s < 100 ? s.toFixed(2) : s.toFixed(0));
// "Norway (fjords)" with code NO: "Norway (NO, fjords)".
const inputLabel = (c) => { const m = c.label.match(/^(.*) \((.*)\)$/); return m ? `${m[1]} (${c.code}, ${m[2]})` : `${c.label} (${c.code})`; };
const fmtDeg = (v) => (typeof v !== 'number' ? '—' : v >= 0.01 || v === 0 ? `${v.toFixed(2)}°` : `${v.toExponential(1)}°`);
const fmtMb = (kb) => (kb ? (kb / 1024).toFixed(kb < 102400 ? 1 : 0) : '—');
// The first line that is not a warning, cut at 160 characters (an ellipsis says so).
const firstLine = (t) => {
  const line = (t || '').split('\n').find((l) => !/warning:/.test(l))?.replace(/\|/g, '\\|') ?? '';
  return line.length > 160 ? `${line.slice(0, 160).replace(/[;,]?\s*$/, '')}…` : line;
};
const cutByLimit = (r) => /time limit/i.test(r.err || '') || /time limit/i.test(r.stats?.message || '');

// status, certified, targetMet, in words; cut runs and failures said as such.
function result(mode, r, limit) {
  if (!r) return 'n/a (not run)';
  if (r.rc === 124) return `**killed** at ${2 * limit + 60} s (--time-limit ${limit} not honoured)`;
  const s = r.stats;
  if (!s) return `**failed** (exit ${r.rc}${r.timeNote ? `, ${r.timeNote}` : ''}): ${firstLine(r.err) || 'no message'}`;
  const parts = [s.status ?? (r.rc === 0 ? 'ok' : '?')];
  if (mode === 'acute' || mode === 'nonobtuse') parts.push(s.certified ? 'certified' : 'not certified');
  parts.push(s.targetMet ? 'targetMet' : 'targetMet false');
  let text = parts.join(', ');
  if (mode === 'cdt') text += ` (${fmtInt(s.obtuse)} obtuse)`;
  if (mode === 'quality') text += ` (min angle ${fmtDeg(s.minAngle)}; smallest input angle ${fmtDeg(s.smallestInputAngle)})`;
  if (s.targetMet === false || r.rc !== 0) {
    const left = mode === 'acute' ? `${fmtInt(s.nonAcute)} non-acute left` : mode === 'nonobtuse' ? `${fmtInt(s.obtuse)} obtuse left` : '';
    text = `${cutByLimit(r) ? `**cut** at ${limit} s` : `**exit ${r.rc}**: ${firstLine(r.err).replace(/^acutemesh: /, '')}`}` +
      `${left ? `, ${left}` : ''}; ${text}`;
  }
  return text;
}

// --- the table ---------------------------------------------------------------------------------
const table = [
  '| input | input vertices (distinct) | mode | load | wall s | CLI s | triangles | triangles/s | peak RSS MB | bytes/triangle | Steiner / input vertex | result | warnings | WASM (Node) s |',
  '|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---|',
];
const figures = []; // { c, mode, s, wall, tps, bpt, r }
const warningsOf = {};
for (const c of cases) {
  let first = true;
  for (const mode of MODES) {
    const r = measure(c.id, mode, c.runs);
    const s = r?.stats;
    const total = totalSeconds(s);
    const tps = s && total ? s.triangles / total : null;
    const bpt = s && r.rssKb && s.triangles ? (r.rssKb * 1024) / s.triangles : null;
    const spv = s && distinct(s) ? (s.steiner ?? s.vertices - s.inputVertices) / distinct(s) : null;
    if (s && !warningsOf[c.id]) warningsOf[c.id] = s.warnings || [];
    figures.push({ c, mode, s, wall: r?.wallMs ? r.wallMs / 1000 : null, tps, bpt, r });
    let wasmCell = '';
    if (mode === 'acute') {
      const w = measure(c.id, 'wasm-acute', 1);
      if (!w) wasmCell = c.runs === 1 ? 'not run (COUNTRIES_WASM_ALL=1)' : 'n/a (dist/ not built)';
      else {
        const ws = w.stats;
        const secs = ws ? ws.jsSeconds : null;
        figures.push({ c, mode: 'wasm-acute', s: ws, wall: secs, tps: ws && secs ? ws.triangles / secs : null, r: w });
        wasmCell = ws ? `${fmtS(secs)} (${result('acute', w, c.limit)}; load ${w.load})` : result('acute', w, c.limit);
        if (ws && s && ws.triangles !== s.triangles) wasmCell += `, ${fmtInt(ws.triangles)} triangles`;
      }
    }
    const label = first ? inputLabel(c) : '';
    const nv = first && s ? `${fmtInt(s.inputVertices)} (${fmtInt(distinct(s))})` : '';
    first = false;
    const runs = c.runs > 1 ? ` (best of ${r?.n ?? 0})` : '';
    table.push(`| ${label} | ${nv} | ${mode} | ${r?.load ?? '—'} | ${fmtS(r?.wallMs ? r.wallMs / 1000 : null)}${runs} | ${fmtS(total)} | ` +
      `${fmtInt(s?.triangles)} | ${fmtInt(tps)} | ${fmtMb(r?.rssKb)} | ${bpt ? bpt.toFixed(0) : '—'} | ` +
      `${spv === null ? '—' : spv.toFixed(2)} | ${result(mode, r, c.limit)} | ${s ? (s.warnings || []).length : '—'} | ${wasmCell} |`);
  }
}

// --- the targets -------------------------------------------------------------------------------
const refined = figures.filter((f) => (f.mode === 'acute' || f.mode === 'nonobtuse') && f.s);
const big = refined.filter((f) => distinct(f.s) >= TARGET.bigVertices);
const okRun = (f) => f.r.rc === 0 && f.s.certified;
const name = (f) => `${f.c.code} ${f.mode}`;
const say = (met) => (met ? '**met**' : '**not met**');
const targets = [];
if (!big.length) {
  targets.push(`- ${fmtInt(TARGET.throughput)} triangles/s acute and non-obtuse at >= 10^5 input vertices, and <= ${TARGET.bytesPerTriangle} bytes/triangle there: not measured (no input of 10^5 vertices in this run; BENCH_QUICK?).`);
} else {
  const tputMet = big.every((f) => okRun(f) && f.tps >= TARGET.throughput);
  targets.push(`- At least ${fmtInt(TARGET.throughput)} triangles/s, acute and non-obtuse, at >= 10^5 input vertices: ${say(tputMet)} ` +
    `(${big.map((f) => `${name(f)} ${fmtInt(f.tps)}${okRun(f) ? '' : ', not certified'}`).join('; ')}; ` +
    `smaller inputs: ${refined.filter((f) => !big.includes(f)).map((f) => `${name(f)} ${fmtInt(f.tps)}`).join(', ')}).`);
  const memMet = big.every((f) => f.bpt !== null && f.bpt <= TARGET.bytesPerTriangle);
  targets.push(`- At most ${TARGET.bytesPerTriangle} bytes of peak memory per output triangle (acute and non-obtuse, >= 10^5 input vertices): ${say(memMet)} ` +
    `(${big.map((f) => `${name(f)} ${f.bpt === null ? '—' : f.bpt.toFixed(0)}`).join('; ')}; ` +
    `smaller inputs: ${refined.filter((f) => !big.includes(f)).map((f) => `${name(f)} ${f.bpt === null ? '—' : f.bpt.toFixed(0)}`).join(', ')}).`);
}
// Every coastline of 10^6 input vertices (as given, duplicates too): the target holds if one
// of them meets it.
const coasts = figures.filter((f) => f.mode === 'acute' && f.s && f.s.inputVertices >= 1e6);
if (coasts.length) {
  const fast = (f) => okRun(f) && f.wall < TARGET.coastlineSeconds;
  targets.push(`- A 10^6-vertex coastline acute, certified, in under ${TARGET.coastlineSeconds} s natively: ${say(coasts.some(fast))} (` +
    coasts.map((f) => `${f.c.label}, ${fmtInt(f.s.inputVertices)} vertices (${fmtInt(distinct(f.s))} distinct): ${fmtS(f.wall)} s wall, ${f.s.certified ? 'certified' : 'not certified'}`).join('; ') + ').');
  const wasm = coasts.map((f) => ({ f, w: figures.find((x) => x.mode === 'wasm-acute' && x.c === f.c) })).filter((x) => x.w && x.w.s);
  targets.push(`- The same in under a minute in Node (WASM): ${wasm.length ? `${say(wasm.some(({ w }) => w.r.rc === 0 && w.s.certified && w.wall < TARGET.wasmSeconds))} (` +
    wasm.map(({ f, w }) => `${f.c.code} ${fmtS(w.wall)} s`).join('; ') + ')' : 'not measured'}.`);
} else {
  targets.push(`- A 10^6-vertex coastline acute, certified, in under ${TARGET.coastlineSeconds} s natively (under a minute in WASM): not measured (no input of 10^6 vertices in this run).`);
}

// --- the search (COUNTRIES_OPTIMIZE=S: ID.acute-optimize.1 and ID.nonobtuse-optimize.1) -----------
const optimizeSeconds = Number(process.env.COUNTRIES_OPTIMIZE) || null;
const searchRows = [];
for (const c of cases) {
  for (const mode of ['acute', 'nonobtuse']) {
    const r = measure(c.id, `${mode}-optimize`, 1);
    if (!r) continue;
    const plain = figures.find((f) => f.c === c && f.mode === mode)?.s;
    const s = r.stats;
    const change = s && plain ? `${(((s.steiner - plain.steiner) / plain.steiner) * 100).toFixed(1)}%` : '—';
    searchRows.push(`| ${inputLabel(c)} | ${mode} | ${r.load} | ${fmtInt(plain?.steiner)} | ${fmtS(totalSeconds(plain))} | ` +
      `${fmtInt(s?.steiner)} | ${change} | ${fmtS(totalSeconds(s))} | ${result(mode, r, c.limit)} |`);
  }
}
const search = searchRows.length
  ? [
      `## \`--optimize ${optimizeSeconds ?? '?'}\` (the search for fewer points, part by part)`,
      '',
      '| input | mode | load | Steiner without | CLI s | Steiner with | change | CLI s | result |',
      '|---|---|---:|---:|---:|---:|---:|---:|---|',
      ...searchRows,
      '',
      'The same command as the table\'s with `--optimize S` (one run; its --time-limit raised by S): each part of the domain ' +
        'searches on its own mesh with its share of the seconds (docs/algorithm.md). "without": the table\'s best run above.',
      '',
    ]
  : [];

// --- machine and provenance --------------------------------------------------------------------
const cache = readText('build/CMakeCache.txt') || '';
const cacheVar = (k) => cache.match(new RegExp(`^${k}:[A-Z]+=(.*)$`, 'm'))?.[1] ?? '?';
const compiler = cacheVar('CMAKE_CXX_COMPILER');
// (As bench/countries.sh found the tree before building the CLI; else as it is now.)
const builtFrom = (readText(path.join(runDir, 'built-from.txt')) || '').trim().split('\n');
let commit = builtFrom[0] || sh('git rev-parse --short HEAD');
const dirty = builtFrom[0] ? builtFrom.length > 1 : sh('git status --porcelain -- core') !== '';
if (dirty) commit += ' + uncommitted core changes';
const pkg = (p) => sh(`dpkg-query -W -f '\${Version}' ${p}`);
const today = new Date().toISOString().slice(0, 10);
const limits = cases.map((c) => `${c.code} ${c.limit} s`).join(', ');
const runsText = cases.map((c) => `${c.code} ${c.runs}`).join(', ');

// The CLI's warnings with their FILE:LINE and segment numbers taken out, alike ones counted once
// (the per-segment lines are summed up by a count line of their own, and so are a reader's
// alike lines past the first few: "FILE: N times in all (the first K listed): TEXT").
function warningSummary(ws) {
  const count = new Map();
  for (const w of ws) {
    if (/^segment \d+ has zero length/.test(w)) continue;
    const all = /^[^ ]*: (\d+) times in all \(the first (\d+) listed\): (.*)$/.exec(w);
    if (all) {
      count.set(all[3], (count.get(all[3]) || 0) + Number(all[1]) - Number(all[2]));
      continue;
    }
    const m = w.replace(/^[^ ]*:\d+: /, '');
    count.set(m, (count.get(m) || 0) + 1);
  }
  return [...count].map(([m, n]) => (n > 1 ? `${m} (${n} times)` : m)).join('; ');
}
const warnLines = cases
  .filter((c) => warningsOf[c.id]?.length)
  .map((c) => `  - ${c.code}: ${warningSummary(warningsOf[c.id])}`);

const lines = [
  `# Whole countries: CDT, quality, acute and non-obtuse at 10^4 to 10^6 vertices (${today})`,
  '',
  'Made by `npm run bench:countries` (bench/countries.sh, bench/inputs/countries*.mjs); issue 25.',
  '',
  `Machine: ${cpu}, ${os.cpus().length} cores (\`lscpu\`: ${sh("lscpu | sed -n 's/^Model name: *//p'")}, ` +
    `${sh("lscpu | sed -n 's/^Thread(s) per core: *//p'")} thread(s) per core), ${(os.totalmem() / 2 ** 30).toFixed(1)} GiB RAM; ` +
    `${compiler !== '?' ? sh(`${compiler} --version | head -n1`) : sh('g++ --version | head -n1')} (CMake ${cacheVar('CMAKE_BUILD_TYPE')}); ` +
    `${sh('uname -sr')}; node ${process.version}.`,
  `acutemesh ${commit} (\`${sh('./build/acutemesh --version')}\`). Load average (1, 5, 15 min) at the start / end: ` +
    `${process.env.LOAD_START || '?'} / ${process.env.LOAD_END || '?'}; the cores are shared with other sessions, ` +
    'so the "load" column (1-minute load average before each mode\'s runs) says how disturbed a figure may be.',
  '',
  ...table,
  '',
  ...targets,
  '',
  ...search,
  `- Runs: \`build/acutemesh --mode MODE --stats --no-output --threads 2 --time-limit L INPUT\` (quality: the default minimum angle, 20°), ` +
    `each under GNU time; L: ${limits}; runs per mode: ${runsText}. "wall s": the process's wall time, best of the runs; "CLI s": ` +
    'that run\'s `seconds.total` from `--stats` (read, mesh, figures). triangles/s: output triangles / CLI s. Peak RSS: GNU time\'s ' +
    '%M, the largest over the runs; bytes/triangle: peak RSS / output triangles (includes the parsed input and the process). ' +
    'input vertices: `inputVertices`, and in brackets without the `duplicates` the CLI merged (the figure issue 25 quotes); ' +
    'Steiner / input vertex: `steiner` / distinct input vertices. warnings: entries of `--stats` `warnings` (the CLI lists the first few of a kind, then a count).',
  '- result: `status`, `certified` (acute and non-obtuse: every angle checked exactly), `targetMet`; "cut": the run reached its ' +
    '--time-limit and gave back its mesh so far (exit 1); "killed": it ran past twice the limit + 60 s.',
  '- Quality refinement cannot reach 20° next to an input angle below 20° (Norway\'s and Indonesia\'s coasts have them: ' +
    '"smallest input angle"); it ends with those triangles left, `target-not-met`, exit 1 (as Lake Superior in the refine reports).',
  '- WASM (Node): acute through the npm package (dist/, `am.parseJson` + `am.mesh(pslg, { mode: \'acute\', timeLimit: L })`, ' +
    'one run, timed in JS; bench/inputs/countries_wasm.mjs). WebAssembly runs the strategies one after another (no threads).',
  `- Inputs: \`gmt coast -E<ISO code> -M\` (GMT ${pkg('gmt')}, DCW polygons gmt-dcw ${pkg('gmt-dcw')}, gmt-gshhg-full ${pkg('gmt-gshhg-full')}), ` +
    'every ring with its closing repeat of the first point dropped, as JSON rings (even-odd fill: lakes are holes, islands in lakes ' +
    'are in) in bench/work/countries/. Longitude and latitude in degrees are meshed as plane coordinates (no projection), so angles ' +
    'are those of the plate carrée, not of the ground.',
  '- What the CLI said of the inputs (the same in every mode):',
  ...warnLines,
];
writeFileSync(out, `${lines.join('\n')}\n`);
