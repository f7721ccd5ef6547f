// The hand-written .d.ts files: tsc --noEmit --strict on a consumer that imports the package by
// name (so the exports map's "types" conditions are what resolve), with misuses marked
// @ts-expect-error that must stay errors; and the .d.ts files alone without the DOM library.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { join } from 'node:path';

import { root } from './helpers.mjs';

const tsc = join(root, 'node_modules', 'typescript', 'bin', 'tsc');

function run(args) {
  try {
    execFileSync(process.execPath, [tsc, ...args], { cwd: root, encoding: 'utf8', stdio: 'pipe' });
    return '';
  } catch (e) {
    return (e.stdout || '') + (e.stderr || '') || String(e);
  }
}

test('tsc --strict accepts the documented use and rejects the misuses', () => {
  assert.equal(run(['-p', join('tests', 'js', 'types', 'tsconfig.json')]), '');
});

test('the .d.ts files need neither the DOM library nor @types/node', () => {
  assert.equal(run(['-p', join('tests', 'js', 'types', 'tsconfig.nodom.json')]), '');
});
