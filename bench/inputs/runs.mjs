// What the bench reports share: their arguments, the runs the bench scripts keep
// (BASE.rc, BASE.json with --stats, BASE.err), and the machine they ran on.
import { execSync } from 'node:child_process';
import { existsSync, readFileSync, readdirSync } from 'node:fs';
import os from 'node:os';
import { join } from 'node:path';

const argv = process.argv.slice(2);
// The value after a command-line option (--work DIR), or undefined.
export const opt = (name) => {
  const i = argv.indexOf(name);
  return i >= 0 ? argv[i + 1] : undefined;
};

export const readText = (f) => (existsSync(f) ? readFileSync(f, 'utf8') : null);

// One run: { rc, stats (the --stats object or null), err, parseError? }, or null if it did not run.
export function readRun(base) {
  const rcText = readText(`${base}.rc`);
  if (rcText === null) return null;
  const run = { rc: Number(rcText.trim()), stats: null, err: (readText(`${base}.err`) || '').trim() };
  const json = readText(`${base}.json`);
  if (json && json.trim()) {
    try {
      run.stats = JSON.parse(json);
    } catch (e) {
      run.parseError = String(e.message);
    }
  }
  return run;
}

// A shell command's output, or '?' if it fails.
export const sh = (cmd) => {
  try {
    return execSync(cmd, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] }).trim();
  } catch {
    return '?';
  }
};

export const cpu = (readText('/proc/cpuinfo') || '').match(/^model name\s*:\s*(.*)$/m)?.[1] ?? os.cpus()[0]?.model ?? '?';

// The rows of a Triangle-format file (.node, .ele, .poly): numbers, comments and blank lines gone.
export const triangleRows = (file) => readFileSync(file, 'utf8').split('\n').map((l) => l.replace(/#.*/, '').trim())
  .filter(Boolean).map((l) => l.split(/\s+/).map(Number));

// Triangle's FILE.1.node / FILE.1.ele in dir (aCute's output), or null: its vertex and triangle
// counts, its smallest and largest angles, and the triangles with an angle of 90 or more
// (floating point).
export function readTriangleOutput(dir) {
  const files = readdirSync(dir);
  const node = files.find((f) => f.endsWith('.1.node'));
  const ele = files.find((f) => f.endsWith('.1.ele'));
  if (!node || !ele) return null;
  const nodes = triangleRows(join(dir, node)), eles = triangleRows(join(dir, ele));
  const pts = new Map(nodes.slice(1).map((r) => [r[0], [r[1], r[2]]]));
  let min = Infinity, max = 0, nonAcute = 0, triangles = 0;
  for (const r of eles.slice(1)) {
    const [a, b, c] = [pts.get(r[1]), pts.get(r[2]), pts.get(r[3])];
    if (!a || !b || !c) continue;
    triangles++;
    let worst = 0;
    for (const [p, q, s] of [[a, b, c], [b, c, a], [c, a, b]]) {
      const ux = q[0] - p[0], uy = q[1] - p[1], vx = s[0] - p[0], vy = s[1] - p[1];
      const angle = Math.atan2(Math.abs(ux * vy - uy * vx), ux * vx + uy * vy) * (180 / Math.PI);
      worst = Math.max(worst, angle);
      min = Math.min(min, angle);
    }
    if (worst >= 90) nonAcute++;
    max = Math.max(max, worst);
  }
  return { vertices: nodes[0][0], triangles, min, max, nonAcute };
}
