// Writes the --optimize report from the runs bench/optimize.sh kept.
//
//   node bench/inputs/optimize_report.mjs --work bench/work/optimize --cgshop DIR --out FILE.md
//
// Reads WORK/selected.txt (category, size, file), WORK/runs/UID.MODE.S.{json,err,rc,wall} (the
// run: --stats, stderr, exit status, wall milliseconds) and WORK/runs/UID.MODE.S.verify{,.rc}
// (tests/cli/verify_cgshop.mjs on the solution; rc 3: no solution written) for MODE in $MODES
// and S in $SECONDS_LIST, and DIR/best_known_steiner.csv (column winner_best_steiner, found by
// its header). Writes the Markdown report and WORK/instances.csv. Environment from
// optimize.sh: LOAD_START, LOAD_END, ELAPSED, SECONDS_LIST, PER_CATEGORY, MODES.
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';

import { cpu, opt, readRun, readText, sh } from './runs.mjs';

const work = opt('--work');
const cgshopDir = opt('--cgshop') || '';
const out = opt('--out');
if (!work || !out) {
  console.error('usage: node bench/inputs/optimize_report.mjs --work DIR --cgshop DIR --out FILE.md');
  process.exit(2);
}
const env = process.env;
const runDir = path.join(work, 'runs');
const SECONDS = (env.SECONDS_LIST || '0 0.1 1 10').split(/\s+/).filter(Boolean);
const MODES = (env.MODES || 'nonobtuse acute').split(/\s+/).filter(Boolean);
const CATEGORIES = ['ortho', 'point-set', 'simple-polygon', 'simple-polygon-exterior', 'simple-polygon-exterior-20'];
const TOTAL_INSTANCES = 150;

// --- the best known ------------------------------------------------------------------------------
function readCsv(file) {
  const text = readText(file);
  if (text === null) return [];
  const [head, ...lines] = text.trim().split(/\r?\n/);
  const cols = head.split(',').map((c) => c.trim());
  return lines.map((l) => Object.fromEntries(l.split(',').map((v, i) => [cols[i], v.trim()])));
}
const bestCsv = path.join(cgshopDir, 'best_known_steiner.csv');
const bestKnown = Object.fromEntries(readCsv(bestCsv).map((r) => [r.instance_uid, r]));
const haveBest = Object.keys(bestKnown).length > 0;

// --- reading runs ----------------------------------------------------------------------------------
// The verifier's line: "UID: T triangles, S Steiner points, R right angles, none obtuse, exact".
const VERIFY_LINE = /: (\d+) triangles, (\d+) Steiner points, (\d+) right angles, none obtuse, exact$/m;
const firstLine = (t) => (t || '').split('\n').find((l) => l.trim())?.replace(/^acutemesh: /, '').replace(/\|/g, '\\|').slice(0, 140) ?? '';

// One run: { steiner, right, ok, problem, rc, wallMs, cliSeconds, statsSteiner, warnings }.
function readResult(uid, mode, s) {
  const base = path.join(runDir, `${uid}.${mode}.${s}`);
  const run = readRun(base);
  if (!run) return null;
  const r = {
    rc: run.rc, wallMs: Number((readText(`${base}.wall`) || '').trim() || NaN),
    cliSeconds: run.stats?.seconds?.total, statsSteiner: run.stats?.steiner, warnings: run.stats?.warnings || [],
    steiner: null, right: null, ok: false, problem: '',
  };
  const vText = readText(`${base}.verify`) || '';
  const vRc = Number((readText(`${base}.verify.rc`) || '').trim() || NaN);
  const m = VERIFY_LINE.exec(vText);
  if (vRc === 0 && m) {
    r.steiner = Number(m[2]);
    r.right = Number(m[3]);
    r.ok = mode !== 'acute' || r.right === 0;
    if (!r.ok) r.problem = `${r.right} right angles: not acute`;
  } else if (run.rc === 124 || run.rc === 137) {
    r.problem = `killed after ${2 * Number(s) + 60} s`;
  } else if (vRc === 3) {
    r.problem = `no solution written (exit ${run.rc}${run.err ? `: ${firstLine(run.err)}` : ''})`;
  } else {
    r.problem = `verifier failed (exit ${Number.isNaN(vRc) ? '?' : vRc}): ${firstLine(vText) || 'no output'}`;
  }
  // A verified solution from a run that exited non-zero is kept, with the exit said.
  if (r.ok && run.rc !== 0) r.problem = `exit ${run.rc}${run.err ? `: ${firstLine(run.err)}` : ''}`;
  if (typeof r.statsSteiner === 'number' && r.steiner !== null && r.statsSteiner !== r.steiner)
    r.problem = [r.problem, `--stats says ${r.statsSteiner} Steiner points`].filter(Boolean).join('; ');
  return r;
}

const selected = (readText(path.join(work, 'selected.txt')) || '').split('\n').filter(Boolean).map((l) => {
  const [category, size, file] = l.split('\t');
  const uid = path.basename(file, '.instance.json');
  const best = Number(bestKnown[uid]?.winner_best_steiner ?? NaN);
  const inst = { uid, category, size: Number(size), file, best, runs: {} };
  for (const mode of MODES) for (const s of SECONDS) inst.runs[`${mode}.${s}`] = readResult(uid, mode, s);
  return inst;
});
const ranAll = selected.length === TOTAL_INSTANCES;

// --- figures ---------------------------------------------------------------------------------------
const fmtInt = (v) => (typeof v === 'number' && Number.isFinite(v) ? v.toLocaleString('en-US') : '—');
const ratio = (a, b, d = 2) => (b > 0 ? (a / b).toFixed(d) : '—');
const sum = (list, f) => list.reduce((t, x) => t + f(x), 0);

// The figures of a list of instances for one mode and S.
function figures(list, mode, s) {
  const results = list.map((i) => ({ inst: i, r: i.runs[`${mode}.${s}`] }));
  const ok = results.filter((x) => x.r?.ok);
  const withBest = ok.filter((x) => Number.isFinite(x.inst.best));
  // Against the first S (0 by default), on the instances verified at both.
  const firstKey = `${mode}.${SECONDS[0]}`;
  const both = s === SECONDS[0] ? [] : ok.filter((x) => x.inst.runs[firstKey]?.ok);
  return {
    n: list.length,
    ran: results.filter((x) => x.r).length,
    verified: ok.length,
    steiner: sum(ok, (x) => x.r.steiner),
    withBest: withBest.length,
    ours: sum(withBest, (x) => x.r.steiner),
    best: sum(withBest, (x) => x.inst.best),
    beatOrTie: withBest.filter((x) => x.r.steiner <= x.inst.best).length,
    beat: withBest.filter((x) => x.r.steiner < x.inst.best).length,
    wall: sum(results, (x) => (Number.isFinite(x.r?.wallMs) ? x.r.wallMs : 0)) / 1000,
    vsFirst: both.length
      ? { now: sum(both, (x) => x.r.steiner), first: sum(both, (x) => x.inst.runs[firstKey].steiner), n: both.length }
      : null,
  };
}
// The change against the first S: "−12.3%" (fewer points) or "±0".
function change(f) {
  if (!f.vsFirst || !(f.vsFirst.first > 0)) return '—';
  const d = (f.vsFirst.now / f.vsFirst.first - 1) * 100;
  return d === 0 ? '±0' : `${d < 0 ? '−' : '+'}${Math.abs(d).toFixed(1)}%`;
}
function row(f) {
  return [
    `${f.verified}/${f.n}`, fmtInt(f.steiner),
    f.withBest ? fmtInt(f.best) : '—', f.withBest ? ratio(f.ours, f.best) : '—',
    f.withBest ? `${f.beatOrTie}${f.beat ? ` (${f.beat} beat)` : ''}` : '—',
    change(f), f.wall.toFixed(1),
  ];
}
const HEAD = '| instances verified | Steiner (verified) | best known, same instances | ours / best | ≤ best known | vs ' +
  `${SECONDS[0]} s, same instances | wall s (total) |`;
const ALIGN = '---:|---:|---:|---:|---:|---:|---:|';

const table1 = [`| mode | --optimize s ${HEAD}`, `|---|---:|${ALIGN}`];
for (const mode of MODES) {
  for (const s of SECONDS) table1.push(`| ${mode} | ${s} | ${row(figures(selected, mode, s)).join(' | ')} |`);
}

const categories = [...CATEGORIES, ...[...new Set(selected.map((i) => i.category))].filter((c) => !CATEGORIES.includes(c)).sort()];
const table2 = [`| category | mode | --optimize s ${HEAD}`, `|---|---|---:|${ALIGN}`];
for (const cat of categories) {
  const list = selected.filter((i) => i.category === cat);
  if (!list.length) continue;
  let first = true;
  for (const mode of MODES) {
    let firstMode = true;
    for (const s of SECONDS) {
      table2.push(`| ${first ? `${cat} (${list.length})` : ''} | ${firstMode ? mode : ''} | ${s} | ${row(figures(list, mode, s)).join(' | ')} |`);
      first = firstMode = false;
    }
  }
}

// --- targets (issue 27) ----------------------------------------------------------------------------
const hasS = (v) => SECONDS.find((s) => Number(s) === v);
const subset = ranAll ? 'all 150 instances' : `the ${selected.length} selected instances only, not all 150`;
const unverified = (f) => (f.verified < f.n ? `; ${f.n - f.verified} of ${f.n} without a verified solution, so not met` : '');
function ratioTarget(label, seconds, limit) {
  const s = hasS(seconds);
  if (!s || !MODES.includes('nonobtuse')) {
    return `- ${label}: **not measured** (OPTIMIZE_SECONDS has no ${seconds}; ` +
      `run \`OPTIMIZE_SECONDS="0 ${seconds}" OPTIMIZE_PER_CATEGORY=all npm run bench:optimize\`).`;
  }
  const f = figures(selected, 'nonobtuse', s);
  if (!f.withBest) return `- ${label}: **not measured** (no best known figures, or no verified solution).`;
  const r = f.ours / f.best;
  const met = r <= limit && f.verified === f.n && f.withBest === f.n;
  return `- ${label}: **${met ? 'met' : 'not met'}**: ${fmtInt(f.ours)} Steiner points against the best known ${fmtInt(f.best)} ` +
    `on ${f.withBest} instances, ${r.toFixed(3)}x (target at most ${limit.toFixed(2)}x)${unverified(f)}.`;
}
function acuteTarget() {
  const label = 'Acute, 10 s per instance: at least 30% fewer Steiner points than with 0 s';
  const s10 = hasS(10), s0 = hasS(0);
  if (!s10 || !s0 || !MODES.includes('acute')) {
    return `- ${label}: **not measured** (OPTIMIZE_SECONDS needs both 0 and 10).`;
  }
  const both = selected.filter((i) => i.runs[`acute.${s0}`]?.ok && i.runs[`acute.${s10}`]?.ok);
  const t0 = sum(both, (i) => i.runs[`acute.${s0}`].steiner), t10 = sum(both, (i) => i.runs[`acute.${s10}`].steiner);
  if (!t0) return `- ${label}: **not measured** (no instance verified at both 0 and 10 s).`;
  const cut = 1 - t10 / t0;
  const missing = selected.length - both.length;
  const met = cut >= 0.3 && missing === 0;
  return `- ${label}: **${met ? 'met' : 'not met'}**: ${fmtInt(t10)} against ${fmtInt(t0)} on ${both.length} instances, ` +
    `${(cut * 100).toFixed(1)}% fewer (target at least 30%)` +
    (missing ? `; ${missing} of ${selected.length} without a verified acute solution at 0 or 10 s, so not met` : '') + '.';
}
const targets = [
  ratioTarget('Non-obtuse, 10 s per instance: at most 1.25x the best known', 10, 1.25),
  ratioTarget('Non-obtuse, 120 s per instance: at most 1.0x the best known', 120, 1.0),
  acuteTarget(),
];

// --- what went wrong, and what looks odd ---------------------------------------------------------
const failures = [];
const nonMonotone = [];
const warnings = new Map();
let overrun = null;
for (const inst of selected) {
  for (const mode of MODES) {
    let prev = null;
    for (const s of SECONDS) {
      const r = inst.runs[`${mode}.${s}`];
      if (!r) {
        failures.push(`${inst.uid} ${mode} ${s} s: not run`);
        continue;
      }
      if (!r.ok) failures.push(`${inst.uid} ${mode} ${s} s: ${r.problem}`);
      for (const w of r.warnings) warnings.set(w, (warnings.get(w) || 0) + 1);
      if (r.ok && prev && r.steiner > prev.r.steiner)
        nonMonotone.push(`${inst.uid} ${mode}: ${r.steiner} at ${s} s, ${prev.r.steiner} at ${prev.s} s`);
      if (r.ok) prev = { r, s };
      const over = r.wallMs / 1000 - Number(s);
      if (Number.isFinite(over) && (!overrun || over > overrun.over)) overrun = { over, uid: inst.uid, mode, s, wall: r.wallMs / 1000 };
    }
  }
}

// --- the per-instance CSV --------------------------------------------------------------------------
const csv = ['instance,category,size,best_known,mode,seconds,steiner,verified,right_angles,stats_steiner,exit,wall_ms,cli_seconds,problem'];
for (const inst of selected) {
  for (const mode of MODES) {
    for (const s of SECONDS) {
      const r = inst.runs[`${mode}.${s}`];
      csv.push([inst.uid, inst.category, inst.size, Number.isFinite(inst.best) ? inst.best : '', mode, s,
        r?.steiner ?? '', r ? r.ok : '', r?.right ?? '', r?.statsSteiner ?? '', r?.rc ?? '',
        Number.isFinite(r?.wallMs) ? r.wallMs : '', r?.cliSeconds ?? '',
        r ? `"${r.problem.replace(/"/g, '""')}"` : '"not run"'].join(','));
    }
  }
}
writeFileSync(path.join(work, 'instances.csv'), `${csv.join('\n')}\n`);

// --- the machine and the report --------------------------------------------------------------------
const dirty = sh('git status --porcelain --untracked-files=no');
const commit = `${sh('git rev-parse --short HEAD')} (${dirty === '?' ? 'state unknown' : dirty ? 'with uncommitted changes' : 'clean'})`;
const perCat = env.PER_CATEGORY === 'all' ? 'all instances' : `${env.PER_CATEGORY} per category, spread over its sizes`;
const envLine = `OPTIMIZE_PER_CATEGORY=${env.PER_CATEGORY} OPTIMIZE_SECONDS="${SECONDS.join(' ')}" npm run bench:optimize`;
const lines = [
  `# --optimize: Steiner points against seconds on the CG:SHOP 2025 instances (${new Date().toISOString().slice(0, 10)})`,
  '',
  `Machine: ${sh('uname -srm')}; ${cpu}, ${os.cpus().length} cores, ${(os.totalmem() / 2 ** 30).toFixed(1)} GiB RAM; ` +
    `load average at the start ${env.LOAD_START || '?'}, at the end ${env.LOAD_END || '?'}; the bench took ${env.ELAPSED || '?'} s. ` +
    `Commit ${commit}.`,
  '',
  'Commands:',
  '',
  `- the bench: \`${envLine}\``,
  `- each run, one at a time: \`build/acutemesh --mode MODE --optimize S --stats --format cgshop,ele -o bench/work/optimize/runs/ID.MODE.S INSTANCE\` ` +
    '(S = 0: without --optimize; --seed left at 1; the CLI applies the CG:SHOP input policy itself, exact segments and exact feet), ' +
    'killed at 2 S + 60 s',
  '- each solution: `node tests/cli/verify_cgshop.mjs INSTANCE ID.MODE.S.solution.json ID.MODE.S.ele` (exact, rational arithmetic)',
  '',
  `Instances: ${selected.length} of the ${TOTAL_INSTANCES} (${perCat}; OPTIMIZE_PER_CATEGORY=all runs every one). ` +
    '**verified**: the verifier passes the solution (non-obtuse, covering the region, every segment a chain of edges) and, ' +
    'acute, it has no right angle either. **Steiner**: the verified solutions\' Steiner points. **best known**: ' +
    `\`best_known_steiner.csv\`, column \`winner_best_steiner\` (non-obtuse; no acute reference exists, so the acute rows show ` +
    'how far an acute mesh is from the non-obtuse optimum), summed over the instances with a verified solution, which ' +
    '**ours / best** compares. **≤ best known**: instances with at most the best known count. ' +
    `**vs ${SECONDS[0]} s**: the Steiner total against the ${SECONDS[0]} s row's on the instances verified at both. ` +
    '**wall s**: the runs\' whole-process wall time, summed (the verifier not included).',
  '',
  haveBest ? null : `*No best known figures: ${bestCsv} was not found.*\n`,
  '## By mode and seconds',
  '',
  ...table1,
  '',
  '## By category',
  '',
  ...table2,
  '',
  '## Targets (issue 27)',
  '',
  `Computed from the rows above, on ${subset}${ranAll ? '' : ' (the targets are for all 150: OPTIMIZE_PER_CATEGORY=all)'}.`,
  '',
  ...targets,
  '',
  '## Notes',
  '',
  failures.length
    ? `- Runs without a verified solution (${failures.length}):\n${failures.map((f) => `  - ${f}`).join('\n')}`
    : `- Every run wrote a solution the verifier passed (${selected.length * MODES.length * SECONDS.length} runs).`,
  nonMonotone.length
    ? `- More seconds, more Steiner points (the search should keep the best mesh):\n${nonMonotone.map((f) => `  - ${f}`).join('\n')}`
    : '- More seconds never gave more Steiner points on any instance.',
  overrun ? `- Longest run past its --optimize seconds: ${overrun.over.toFixed(2)} s (${overrun.uid} ${overrun.mode} at ${overrun.s} s: ` +
    `${overrun.wall.toFixed(2)} s in all, refinement and writing included).` : null,
  warnings.size ? `- Warnings from --stats: ${[...warnings].map(([w, n]) => `"${firstLine(w)}" (${n} runs)`).join('; ')}.` : null,
  '- Per instance, mode and seconds: bench/work/optimize/instances.csv; the runs, solutions and verifier outputs: bench/work/optimize/runs/.',
  '',
];
// null: a line left out; no two blank lines in a row.
const kept = lines.filter((l) => l !== null);
writeFileSync(out, kept.filter((l, i) => l !== '' || kept[i - 1] !== '').join('\n'));
