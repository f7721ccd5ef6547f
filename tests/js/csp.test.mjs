// The package runs under a strict Content-Security-Policy: nothing in dist/ evaluates strings
// as code (the Embind glue is linked with -sDYNAMIC_EXECUTION=0), so a page needs only
// 'wasm-unsafe-eval'. The browser tests load the web page under exactly such a policy.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { root } from './helpers.mjs';

test('no eval or new Function anywhere in dist/', () => {
  const dist = join(root, 'dist');
  const scripts = readdirSync(dist).filter((f) => /\.(m?js)$/.test(f));
  assert.ok(scripts.length > 0, 'dist/ has no scripts: run npm run build');
  for (const f of scripts) {
    const text = readFileSync(join(dist, f), 'utf8');
    assert.doesNotMatch(text, /\bnew\s+Function\s*\(/, `${f} builds functions from strings`);
    assert.doesNotMatch(text, /(^|[^.\w$])eval\s*\(/m, `${f} calls eval`);
  }
});
