// CommonJS users: `const init = require('acutemesh')` (dist/index.cjs, the "require" condition)
// is init itself, on every Node the package supports; `await import('acutemesh')` from
// CommonJS works too. Node before 20.19 cannot require() ES modules at all: each script also
// runs with --no-experimental-require-module, which makes this Node behave the same way.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, mkdirSync, writeFileSync, symlinkSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

import { root } from './helpers.mjs';

// A CommonJS project with the package in its node_modules (a link to this checkout's dist/).
const app = mkdtempSync(join(tmpdir(), 'acutemesh-cjs-'));
mkdirSync(join(app, 'node_modules'));
symlinkSync(root, join(app, 'node_modules', 'acutemesh'), 'dir');
writeFileSync(join(app, 'package.json'), JSON.stringify({ name: 'app', private: true, type: 'commonjs' }));

// Node >= 20.19 (and 22.12) has require(esm) and the flag to turn it off; older Node has neither.
const nodeFlags = process.features.require_module === undefined ? [[]] : [[], ['--no-experimental-require-module']];

function run(script, source) {
  writeFileSync(join(app, script), source);
  return nodeFlags.map((flags) => ({
    flags,
    out: JSON.parse(execFileSync(process.execPath, [...flags, script], { cwd: app, encoding: 'utf8' })),
  }));
}

test.after(() => rmSync(app, { recursive: true, force: true }));

test("require('acutemesh') is init itself, with createInstance and AcuteMeshError", () => {
  const results = run('require.js', `
const init = require('acutemesh');
const { AcuteMeshError, createInstance } = require('acutemesh');
(async () => {
  const am = await init();
  const m = am.mesh({ points: [[0, 0], [1, 0], [0, 1]] }, { mode: 'acute' });
  let error;
  try { am.mesh({ points: [0, 0, 1, 0, 2, 0] }); } catch (e) { error = e; }
  const other = await createInstance();
  console.log(JSON.stringify({
    init: typeof init, same: init.default === init && init.init === init && (await init.default()) === am,
    certified: m.stats.certified, errorIsAcuteMesh: error instanceof AcuteMeshError, code: error.code,
    plainErrorIsNot: !(new Error('x') instanceof AcuteMeshError), separate: other !== am,
  }));
})();
`);
  for (const { flags, out } of results) {
    assert.deepEqual(out, { init: 'function', same: true, certified: true, errorIsAcuteMesh: true,
      code: 'BAD_INPUT', plainErrorIsNot: true, separate: true }, `node ${flags.join(' ')}`);
  }
});

test("await import('acutemesh') and 'acutemesh/worker' from CommonJS", () => {
  const results = run('import.js', `
(async () => {
  const { default: init, AcuteMeshError } = await import('acutemesh');
  const { meshInWorker } = await import('acutemesh/worker');
  const am = await init();
  const m = await meshInWorker({ points: [[0, 0], [1, 0], [0, 1]] }, { mode: 'acute' });
  console.log(JSON.stringify({ certified: m.stats.certified, version: am.version, error: typeof AcuteMeshError }));
})();
`);
  for (const { flags, out } of results)
    assert.deepEqual(out, { certified: true, version: out.version, error: 'function' }, `node ${flags.join(' ')}`);
});
