// Writes the max-angle report from the runs bench/max-angle.sh kept.
//
//   node bench/inputs/max_angle_report.mjs --work bench/work/max-angle [--cgshop DIR] --out FILE.md
//
// Reads WORK/cases.txt (id|label|file|extra arguments), WORK/skipped.txt, WORK/cgshop-selected.txt
// (category, size, file), WORK/runs/auto.tsv, WORK/runs/ID.BOUND.{json,err,rc} for BOUND in
// $BOUNDS, floor3 and auto, WORK/runs/ID.floor3 (the floor + 3 bound, then "same" when it is
// one of $BOUNDS), the same under WORK/runs/cgshop/UID.*, and WORK/runs/acute/ID.BOUND/ when
// aCute ran. Writes the Markdown report and WORK/cgshop.csv. Environment from max-angle.sh:
// LOAD_START, ELAPSED, TIME_LIMIT, CGSHOP_LIMIT, PER_CATEGORY, QUICK, BOUNDS.
import { existsSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';

import { cpu, opt, readRun, readText, readTriangleOutput, sh } from './runs.mjs';

const work = opt('--work');
const cgshopDir = opt('--cgshop') || '';
const out = opt('--out');
if (!work || !out) {
  console.error('usage: node bench/inputs/max_angle_report.mjs --work DIR [--cgshop DIR] --out FILE.md');
  process.exit(2);
}
const env = process.env;
const runDir = path.join(work, 'runs');
const BOUNDS = (env.BOUNDS || '90 85 80 75').split(' ').map(Number);
const KEYS = [...BOUNDS.map(String), 'floor3', 'auto'];

// aCute's figures measured before on this project's machines (../shared/data/README.md), shown
// when no aCute binary ran here.
const ACUTE_MEASURED = {
  A: [
    { sw: '-pq20U90', steiner: 86, max: '89.97', result: 'acute', ms: '~10' },
    { sw: '-pq30U80', result: 'crashed' },
  ],
  superior: [
    { sw: '-pq20U90', steiner: 440, max: '96.1', result: '1 obtuse triangle left', ms: '~15' },
    { sw: '-pq30U85', steiner: 1128, max: '110.2', result: '2 obtuse triangles left' },
  ],
};

// --- reading runs ------------------------------------------------------------------------------
// The runs of one input: { floor, corner, inputVertices, floor3: { bound, same }, runs: { key: run } }.
function readInput(base) {
  const runs = {};
  for (const k of KEYS) runs[k] = readRun(`${base}.${k}`);
  const s90 = runs['90']?.stats;
  const f3 = (readText(`${base}.floor3`) || '').split('\n').filter(Boolean);
  const floor3 = f3.length ? { bound: Number(f3[0]), same: f3[1] === 'same' } : null;
  if (floor3?.same) runs.floor3 = runs[String(floor3.bound)];
  return {
    floor: s90?.angleFloor, corner: s90?.smallestDomainAngle, inputVertices: s90?.inputVertices,
    floor3, runs,
  };
}
const autoLine = (readText(path.join(runDir, 'auto.tsv')) || '0\t').split('\t');
const autoAvailable = autoLine[0] === '1';
const autoMessage = (autoLine[1] || '').trim();

// --- formatting --------------------------------------------------------------------------------
const fmtInt = (v) => (typeof v === 'number' && Number.isFinite(v) ? v.toLocaleString('en-US') : '—');
const fmtDeg = (v, d = 2) => (typeof v === 'number' ? String(Number(v.toFixed(d))) : '—');
// Largest angle, cut (not rounded) to 3 decimals so 84.9997 never reads 85.000; --stats rounds
// too, so at or above a bound every angle is certified below, the exact verdict decides ("B−").
function fmtAngle(v, bound) {
  if (typeof v !== 'number') return '—';
  if (bound != null && v >= bound) return `${fmtDeg(bound, 3)}−`;
  return (Math.floor(v * 1000) / 1000).toFixed(3);
}
const ms = (s) => (typeof s?.seconds?.total === 'number' ? (s.seconds.total * 1000).toFixed(s.seconds.total < 1 ? 1 : 0) : '—');
const firstLine = (t) => (t || '').split('\n')[0].replace(/^acutemesh: /, '').replace(/\|/g, '\\|').slice(0, 140);
// The bound every angle is certified below: stats.angleBound when this CLI reports it; else
// 90 for a certified acute mesh (the bound asked for is then judged by targetMet alone).
const certifiedBelow = (s) => (typeof s.angleBound === 'number' ? s.angleBound : s.certified ? 90 : null);
const hasAngleBound = (s) => typeof s?.angleBound === 'number';

function cells(run, limit, bound, floor) {
  if (!run) return ['—', '—', '—', '—', '—', 'not run'];
  if (run.rc === 124 || run.rc === 137) return ['—', '—', '—', '—', '—', `killed after ${2 * limit + 10} s (time limit ${limit} s not honoured)`];
  const s = run.stats;
  if (!s) return ['—', '—', '—', '—', '—', `failed (exit ${run.rc}): ${firstLine(run.err) || 'no output'}`];
  const below = certifiedBelow(s);
  const cert = below == null ? 'no' : hasAngleBound(s) ? `< ${fmtDeg(below, 3)}` : 'acute';
  const under = typeof bound === 'number' && typeof floor === 'number' && bound < floor;
  const met = s.targetMet ? 'yes' : under ? 'no (below the floor)' : 'no';
  // Exit 1 goes with a status other than ok (target not met, cancelled): said by the status.
  const note = [s.status && s.status !== 'ok' ? s.status : '', run.rc > 1 ? `exit ${run.rc}` : '',
    s.warnings?.length ? firstLine(s.warnings[0]) : run.rc && run.err ? firstLine(run.err) : ''].filter(Boolean).join('; ');
  return [fmtInt(s.steiner), fmtAngle(s.maxAngle, below), cert, met, ms(s), note];
}

// --- the bench inputs ----------------------------------------------------------------------------
const cases = (readText(path.join(work, 'cases.txt')) || '').split('\n').filter(Boolean).map((l) => {
  const [id, label, file, args] = l.split('|');
  return { id, label, file, args };
});
const skipped = (readText(path.join(work, 'skipped.txt')) || '').split('\n').filter(Boolean);
const TIME_LIMIT = Number(env.TIME_LIMIT || 20);
const CGSHOP_LIMIT = Number(env.CGSHOP_LIMIT || 5);
let sawAngleBound = false;

function acuteRows(c, nInput) {
  const rows = [];
  const dir = path.join(runDir, 'acute');
  if (existsSync(path.join(dir, 'binary.txt'))) {
    for (const b of BOUNDS) {
      const d = path.join(dir, `${c.id}.${b}`);
      const rc = readText(path.join(d, 'rc'));
      if (rc === null) continue;
      const [code, msText] = rc.trim().split(' ').map(Number);
      const m = readTriangleOutput(d);
      const result = code === 124 ? 'killed (no result)' : code >= 128 || code === 134 || code === 139 ? 'crashed'
        : code !== 0 ? `failed (exit ${code})` : m ? (m.max < 90 ? 'acute (floating point)' : `${m.nonAcute} non-acute left`) : 'no output';
      rows.push([`*aCute -pq20U${b}*`, m && code === 0 ? fmtInt(m.vertices - nInput) : '—', m && code === 0 ? m.max.toFixed(3) : '—',
        '—', m && code === 0 ? (m.max < b ? 'yes (floating point)' : 'no') : '—', String(msText), result]);
    }
  } else {
    for (const a of ACUTE_MEASURED[c.id] || []) {
      rows.push([`*aCute ${a.sw} (measured before, not run here)*`, a.steiner === undefined ? '—' : fmtInt(a.steiner),
        a.max || '—', '—', '—', a.ms || '—', a.result]);
    }
  }
  return rows;
}


const inputSections = [];
for (const c of cases) {
  const r = readInput(path.join(runDir, c.id));
  const head = `### ${c.label}\n\n\`${c.file}\`${c.args ? ` (${c.args})` : ''}: ${fmtInt(r.inputVertices)} input vertices; ` +
    `smallest corner ${fmtDeg(r.corner)}°, **floor ${fmtDeg(r.floor)}°**.\n`;
  const table = ['| bound | Steiner | largest angle | certified | bound met | ms | notes |', '|---|---:|---:|---|---|---:|---|'];
  for (const k of KEYS) {
    let label = k, bound = Number(k), run = r.runs[k];
    if (k === 'floor3') {
      if (!r.floor3) continue;
      bound = r.floor3.bound;
      label = `floor + 3 = ${fmtDeg(bound)}${r.floor3.same ? ` (the ${bound} row)` : ''}`;
    }
    if (k === 'auto') {
      if (!autoAvailable) {
        table.push(`| auto | — | — | — | — | — | n/a: this CLI does not take --max-angle auto (${firstLine(autoMessage)}) |`);
        continue;
      }
      bound = null;
    }
    if (hasAngleBound(run?.stats)) sawAngleBound = true;
    table.push(`| ${label} | ${cells(run, TIME_LIMIT, bound, r.floor).join(' | ')} |`);
  }
  for (const row of acuteRows(c, r.inputVertices)) table.push(`| ${row.join(' | ')} |`);
  inputSections.push(`${head}\n${table.join('\n')}\n`);
}

// --- CG:SHOP, by category ------------------------------------------------------------------------
const selected = (readText(path.join(work, 'cgshop-selected.txt')) || '').split('\n').filter(Boolean).map((l) => {
  const [category, size, file] = l.split('\t');
  return { category, size: Number(size), uid: path.basename(file, '.instance.json') };
});
const csv = ['instance,category,bound,floor,steiner,max_angle,certified,angle_bound,target_met,ms,exit'];
const byCat = new Map();
for (const inst of selected) {
  const r = readInput(path.join(runDir, 'cgshop', inst.uid));
  if (!byCat.has(inst.category)) byCat.set(inst.category, []);
  byCat.get(inst.category).push(r);
  for (const k of KEYS) {
    const run = r.runs[k], s = run?.stats;
    if (!run) continue;
    if (hasAngleBound(s)) sawAngleBound = true;
    const bound = k === 'floor3' ? r.floor3?.bound : k;
    csv.push([inst.uid, inst.category, bound, r.floor ?? '', s?.steiner ?? '', s?.maxAngle ?? '', s?.certified ?? '',
      s?.angleBound ?? '', s?.targetMet ?? '', s?.seconds?.total != null ? (s.seconds.total * 1000).toFixed(1) : '', run.rc].join(','));
  }
}
const cgTable = ['| category | instances | floor (min–max) | bound | met | certified acute | Steiner (total) | largest angle (median / worst) | ms (total) | not finished |',
  '|---|---:|---|---|---:|---:|---:|---|---:|---:|'];
for (const [cat, list] of [...byCat].sort()) {
  const floors = list.map((r) => r.floor).filter((v) => typeof v === 'number');
  let first = true;
  for (const k of KEYS) {
    if (k === 'auto' && !autoAvailable) {
      cgTable.push(`| | | | auto | n/a (this CLI does not take --max-angle auto) | | | | | |`);
      continue;
    }
    const runs = list.map((r) => r.runs[k]).filter(Boolean);
    const stats = runs.map((r) => r.stats).filter(Boolean);
    // Each run's largest angle, capped just below the bound it is certified below (the
    // rounded figure of --stats can reach it): a median or worst at the cap reads "B−".
    const angles = stats.filter((s) => typeof s.maxAngle === 'number').map((s) => {
      const below = certifiedBelow(s);
      return { v: below != null ? Math.min(s.maxAngle, below) : s.maxAngle, below };
    }).sort((a, b) => a.v - b.v);
    const fmtSummary = (a) => fmtAngle(a.v, a.below != null && a.v >= a.below ? a.below : null);
    const totalMs = stats.reduce((t, s) => t + (s.seconds?.total || 0) * 1000, 0);
    const label = k === 'floor3' ? 'floor + 3' : k;
    cgTable.push(`| ${first ? cat : ''} | ${first ? list.length : ''} | ${first && floors.length ? `${fmtDeg(Math.min(...floors))}–${fmtDeg(Math.max(...floors))}` : ''} | ` +
      `${label} | ${stats.filter((s) => s.targetMet && s.certified).length}/${list.length} | ${stats.filter((s) => s.certified).length}/${list.length} | ` +
      `${fmtInt(stats.reduce((t, s) => t + (s.steiner || 0), 0))} | ${angles.length ? `${fmtSummary(angles[(angles.length - 1) >> 1])} / ${fmtSummary(angles[angles.length - 1])}` : '—'} | ` +
      `${totalMs.toFixed(0)} | ${runs.length - stats.length + (list.length - runs.length)} |`);
    first = false;
  }
}
writeFileSync(path.join(work, 'cgshop.csv'), `${csv.join('\n')}\n`);

// --- the machine and the report ------------------------------------------------------------------
const commit = sh('git rev-parse --short HEAD') + (sh('git status --porcelain --untracked-files=no') ? ' (with uncommitted changes)' : '');
const perCat = env.PER_CATEGORY === 'all' ? 'all instances' : `${env.PER_CATEGORY} per category, spread over its sizes`;
const lines = [
  `# Max-angle dial: acute meshes at bounds below 90 (${new Date().toISOString().slice(0, 10)})`,
  '',
  env.QUICK === '1' ? '**Quick run (--quick): a reduced set to check the bench, not figures to quote.**\n' : '',
  `Machine: ${sh('uname -srm')}; ${cpu}, ${os.cpus().length} cores, ${(os.totalmem() / 2 ** 30).toFixed(1)} GiB RAM; ` +
    `load average at the start ${env.LOAD_START || '?'}; the bench took ${env.ELAPSED || '?'} s. Commit ${commit}.`,
  '',
  `Each row: one \`build/acutemesh --mode acute --max-angle B --stats --no-output --time-limit T\` run (T = ${TIME_LIMIT} s ` +
    `for the inputs below, ${CGSHOP_LIMIT} s per CG:SHOP instance), one at a time. **floor**: stats.angleFloor, ` +
    '90 − min(36, smallest corner)/2 (Bishop 2021): no mesh of the input has every angle below it. **largest angle**: ' +
    'stats.maxAngle (rounded by --stats; "B−" when every angle is certified below B but the rounded figure reaches B). ' +
    '**certified**: "< B" is stats.angleBound, the bound every angle is certified strictly below; "acute" where this CLI ' +
    'reports no angleBound and only acuteness (every angle < 90) is certified, exactly. **bound met**: stats.targetMet. ' +
    '**ms**: the CLI\'s seconds.total.',
  '',
  sawAngleBound ? '' : '*This CLI reports no stats.angleBound: "certified" says only whether the mesh is certified acute.*\n',
  existsSync(path.join(runDir, 'acute', 'binary.txt'))
    ? `aCute: \`${readText(path.join(runDir, 'acute', 'binary.txt')).trim()}\`, \`-pq20U<B>\` on the .poly/.node inputs; its largest angle in floating point from its .1.node/.1.ele.`
    : 'aCute: not run (no aCute binary is built on this machine; set ACUTE_BIN to one to add its rows). Its rows below are ' +
      'the figures measured before (../shared/data/README.md); -U80 crashed.',
  '',
  skipped.length ? `Skipped (reference data not found; set ACUTEMESH_DATA or put it at ../shared/data): ${skipped.join('; ')}.\n` : '',
  '## Inputs',
  '',
  ...inputSections,
  '## CG:SHOP 2025 instances, by category',
  '',
  cgshopDir && selected.length
    ? `${selected.length} of the 150 instances (${perCat}; MAXANGLE_CGSHOP_PER_CATEGORY=all runs every one). **met**: bound met ` +
      'and certified; **not finished**: runs without stats (killed, crashed). Per instance and bound: bench/work/max-angle/cgshop.csv.\n\n' +
      cgTable.join('\n')
    : 'Skipped: the CG:SHOP 2025 instances were not found (set ACUTEMESH_DATA or put them at ../shared/data/cgshop2025).',
  '',
];
writeFileSync(out, lines.filter((l, i) => l !== '' || lines[i - 1] !== '').join('\n'));
