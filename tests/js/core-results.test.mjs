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

// A gear: 40 teeth around a round hole (as tests/cpp/test_progress.cpp). Below 90 degrees its
// descent runs for seconds.
function gear() {
  const points = [], segments = [];
  for (let i = 0; i < 40; ++i)
    for (const [f, r] of [[0, 9], [0.2, 10], [0.5, 10], [0.7, 9]]) {
      const a = 2 * Math.PI * (i + f) / 40;
      points.push(r * Math.cos(a), r * Math.sin(a));
    }
  for (let k = 0; k < 30; ++k) points.push(3 * Math.cos(2 * Math.PI * k / 30), 3 * Math.sin(2 * Math.PI * k / 30));
  for (let k = 0; k < 160; ++k) segments.push(k, (k + 1) % 160);
  for (let k = 0; k < 30; ++k) segments.push(160 + k, 160 + (k + 1) % 30);
  return { points, segments, holes: [0, 0] };
}

const refining = (phase) => phase === 'refine' || phase === 'improve';

test('progress: a fraction in [0, 1] that never goes down, reported often', () => {
  const reports = [];
  const start = performance.now();
  am.mesh({ points: randomPoints(5000, 7) }, {
    mode: 'acute',
    onProgress: (p) => reports.push({ at: (performance.now() - start) / 1000, ...p }),
  });
  const seconds = (performance.now() - start) / 1000;
  const during = reports.filter((p) => refining(p.phase));
  let last = 0;
  for (const p of during) {
    assert.ok(p.fraction >= last && p.fraction <= 1, `${p.phase} ${p.fraction} after ${last}`);
    last = p.fraction;
  }
  assert.ok(new Set(during.map((p) => p.fraction)).size >= 5, 'the fraction moves');
  // One report per 40 ms of work; a busy machine may stretch that, so ask for a fifth of it.
  assert.ok(during.length >= 0.2 * seconds / 0.04, `${during.length} reports in ${seconds} s`);
});

test('progress: an abort from onProgress lands soon, also below 90 degrees', () => {
  for (const [pslg, maxAngle] of [[{ points: randomPoints(10000, 5) }, 90], [gear(), 80]]) {
    const controller = new AbortController();
    const start = performance.now();
    const since = () => (performance.now() - start) / 1000;
    assert.throws(() => am.mesh(pslg, {
      mode: 'acute',
      maxAngle,
      signal: controller.signal,
      // The user decides to stop 0.3 s into the refinement.
      onProgress: (p) => { if (refining(p.phase) && since() > 0.3) controller.abort(); },
    }), { name: 'AbortError' });
    // Reports every 40 ms and a stop at the next poll; 0.5 s leaves room for a busy machine.
    assert.ok(since() - 0.3 < 0.5, `max angle ${maxAngle}: ended at ${since()} s`);
  }
});
