// What the core's results mean, as the package hands them on: an empty domain is an error that
// says why, written meshes read back as the same domain, and progress reports a fraction that
// moves, often enough to cancel from.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

import init, { AcuteMeshError } from 'acutemesh';
import { testData } from './helpers.mjs';

const am = await init();

// A small deterministic generator (the same points every run).
function randomPoints(n, seed) {
  let s = seed;
  const next = () => ((s = (s * 1103515245 + 12345) % 2147483648) / 2147483648);
  return Array.from({ length: 2 * n }, next);
}

test('an empty domain is BAD_INPUT naming the fill rule and convexHull', () => {
  const pslg = { points: randomPoints(100, 24), segments: [0, 1] };
  assert.throws(() => am.mesh(pslg), (e) => {
    assert.ok(e instanceof AcuteMeshError);
    assert.equal(e.code, 'BAD_INPUT');
    assert.match(e.message, /the domain is empty/);
    assert.match(e.message, /convexHull/);
    return true;
  });
  assert.equal(am.mesh(pslg, { convexHull: true }).status, 'ok');
});

test('toPoly and toJSON read back as the same domain (an enclave holding an island)', () => {
  const input = am.parsePoly(readFileSync(join(testData, 'io', 'enclave.poly'), 'utf8'));
  for (const options of [{ mode: 'acute' }, { mode: 'cdt', convexHull: true }]) {
    const m = am.mesh(input, options);
    const area = (r) => {
      let a = 0;
      for (let t = 0; t < r.triangles.length; t += 3) {
        const [i, j, k] = [r.triangles[t], r.triangles[t + 1], r.triangles[t + 2]];
        const p = r.points;
        a += ((p[2 * j] - p[2 * i]) * (p[2 * k + 1] - p[2 * i + 1]) - (p[2 * j + 1] - p[2 * i + 1]) * (p[2 * k] - p[2 * i])) / 2;
      }
      return a;
    };
    for (const back of [am.parsePoly(am.toPoly(m)), am.parseJson(am.write(m, 'json'))]) {
      assert.equal(back.holes.length, 2, 'one hole point');
      const again = am.mesh(back, { mode: 'cdt' });
      assert.equal(again.triangles.length, m.triangles.length, JSON.stringify(options));
      assert.ok(Math.abs(area(again) - area(m)) <= 1e-12 * area(m));
    }
  }
});
