// What the bench reports share: their arguments, the runs the bench scripts keep
// (BASE.rc, BASE.json with --stats, BASE.err), and the machine they ran on.
import { execSync } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import os from 'node:os';

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
