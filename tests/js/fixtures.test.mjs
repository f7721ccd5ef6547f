// The committed test inputs that scripts make: tests/data/cgshop is what its make.mjs writes
// (so the synthetic CG:SHOP instances stay reproducible, and nothing else lands there).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { join } from 'node:path';

import { syntheticCgshop } from './helpers.mjs';

test('tests/data/cgshop is what make.mjs writes', () => {
  const run = spawnSync(process.execPath, [join(syntheticCgshop, 'make.mjs'), '--check'], { encoding: 'utf8' });
  assert.equal(run.status, 0, run.stderr);
});
