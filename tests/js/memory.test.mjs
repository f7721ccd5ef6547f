// 1000 calls in a loop leave the wasm heap where it started: nothing allocated by a call
// survives it (the results are JS-owned copies), whether it succeeded or failed.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

import { createInstance } from 'acutemesh';
import { testData } from './helpers.mjs';

test('1000 calls leave the wasm heap where it started', async () => {
  const am = await createInstance();
  const text = readFileSync(join(testData, 'A.poly'), 'utf8');
  const pslg = am.parsePoly(text);
  // One round first: the heap grows to its working size once and keeps it.
  const round = (i) => {
    const p = am.parsePoly(text);
    const m = am.mesh(p, { mode: i % 10 === 0 ? 'acute' : 'cdt', onProgress: () => {} });
    if (i % 50 === 0) assert.ok(am.validate(pslg, m).ok);
    if (i % 100 === 0) am.toSVG(m);
    try {
      am.mesh({ points: [0, 0, 1, 0, 2, 0] });
    } catch (e) {
      assert.equal(e.code, 'BAD_INPUT');
    }
  };
  round(0);
  const start = am.memory();
  for (let i = 1; i <= 1000; ++i) round(i);
  const end = am.memory();
  assert.equal(end.allocated, start.allocated, `allocated ${start.allocated} -> ${end.allocated} bytes`);
  assert.equal(end.heapSize, start.heapSize, `heap ${start.heapSize} -> ${end.heapSize} bytes`);
});

test('the probe sees an allocation that is kept', async () => {
  // memory() must be able to fail the test above: a mesh with many more vertices grows the
  // heap, and `allocated` counts live bytes only while the core holds them (here: none after).
  const am = await createInstance();
  const before = am.memory();
  const square = { points: [0, 0, 1, 0, 1, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0] };
  let during = 0;
  am.mesh(square, { mode: 'quality', maxArea: 1e-5, onProgress: () => { during = Math.max(during, am.memory().allocated); } });
  assert.ok(during > before.allocated + 1e6, `${during} bytes during the call`);
  assert.equal(am.memory().allocated, before.allocated);
  assert.ok(am.memory().heapSize > before.heapSize);
});
