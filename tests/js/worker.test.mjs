// acutemesh/worker in Node (worker_threads): results, progress on the calling thread, errors
// rebuilt as AcuteMeshError, an AbortSignal that terminates a busy worker, and the next call
// on a fresh worker; workerUrl and init.wasmUrl, and the errors when the files are not there.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, mkdtempSync, copyFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, relative as relativePath } from 'node:path';
import { pathToFileURL } from 'node:url';

import init from 'acutemesh';
import { createMeshWorker, meshInWorker, AcuteMeshError } from 'acutemesh/worker';
import { assertBestSoFar, root, testData } from './helpers.mjs';

const am = await init();
const pslg = am.parsePoly(readFileSync(join(testData, 'A.poly'), 'utf8'));
const square = { points: [0, 0, 1, 0, 1, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0] };
const slow = { mode: 'quality', maxArea: 4e-6 };  // about 500,000 triangles: a second or more of work

test('a mesh from the worker equals the one made here, with progress', { timeout: 120000 }, async () => {
  const worker = createMeshWorker();
  try {
    const phases = [];
    const m = await worker.mesh(pslg, { mode: 'acute', onProgress: (p) => phases.push(p.phase) });
    const here = am.mesh(pslg, { mode: 'acute' });
    assert.deepEqual(m.points, here.points);
    assert.deepEqual(m.triangles, here.triangles);
    assert.ok(m.points instanceof Float64Array && m.triangles instanceof Uint32Array);
    assert.ok(m.stats.certified);
    assert.ok(am.validate(pslg, m).ok);
    assert.deepEqual(phases.filter((p) => p !== 'refine' && p !== 'improve'), ['delaunay', 'segments', 'domain', 'output']);
    // Calls queue and run one after another on the same worker.
    const [a, b] = await Promise.all([worker.mesh(pslg), worker.mesh(square, { mode: 'nonobtuse' })]);
    assert.equal(a.options.mode, 'cdt');
    assert.ok(b.stats.certified);
  } finally {
    worker.terminate();
  }
});

test('errors come back as AcuteMeshError / TypeError', { timeout: 120000 }, async () => {
  const worker = createMeshWorker();
  try {
    await assert.rejects(worker.mesh({ points: [0, 0, 1, 0], segments: [0, 9] }),
      (e) => e instanceof AcuteMeshError && e.code === 'BAD_INPUT' && /segment 0 refers to vertex 9/.test(e.message));
    await assert.rejects(worker.mesh({ points: 'x' }), (e) => e instanceof TypeError);
    await assert.rejects(worker.mesh(square, { onProgress: 3 }), TypeError);
    // Input that cannot be posted to a worker is rejected, and the queue goes on.
    await assert.rejects(worker.mesh({ points: [0, 0, 1, 0, 0, 1], extra: () => {} }), (e) => e.name === 'DataCloneError');
    assert.ok((await worker.mesh(square)).stats.triangles > 0);  // still usable
  } finally {
    worker.terminate();
  }
});

test('abort terminates the busy worker promptly; the next call gets a fresh one', { timeout: 120000 }, async () => {
  const worker = createMeshWorker();
  try {
    // How long the slow job takes to run through.
    const t0 = performance.now();
    const full = await worker.mesh(square, slow);
    const fullMs = performance.now() - t0;
    assert.ok(full.stats.triangles > 250000);

    const controller = new AbortController();
    let sawRefine = false;
    const t1 = performance.now();
    const job = worker.mesh(square, {
      ...slow,
      signal: controller.signal,
      onProgress: (p) => {
        if (p.phase === 'refine' && !sawRefine) {
          sawRefine = true;
          controller.abort();
        }
      },
    });
    const queued = worker.mesh(square, { mode: 'acute' });  // waits behind the aborted job
    await assert.rejects(job, (e) => e.name === 'AbortError');
    const abortedMs = performance.now() - t1;
    assert.ok(sawRefine);
    assert.ok(abortedMs < fullMs / 2, `aborted after ${abortedMs} ms; the whole job takes ${fullMs} ms`);
    assert.ok((await queued).stats.certified);

    // Aborted before it starts: rejected at once, the worker is untouched.
    await assert.rejects(worker.mesh(square, { signal: AbortSignal.abort() }), (e) => e.name === 'AbortError');
    const reason = new Error('user cancelled');
    const c = new AbortController();
    const p = worker.mesh(square, { ...slow, signal: c.signal });
    setTimeout(() => c.abort(reason), 50);
    await assert.rejects(p, (e) => e === reason);
    assert.ok((await worker.mesh(pslg, { mode: 'acute' })).stats.certified);
  } finally {
    worker.terminate();
  }
});

// optimize in a worker: an abort while the search runs reaches the worker through shared
// memory (Node has SharedArrayBuffer), which answers with the best mesh so far; an abort before
// the search still rejects with the signal's reason; the worker stays usable.
test('abort during optimize answers with the best mesh so far', { timeout: 120000 }, async () => {
  const worker = createMeshWorker();
  try {
    const t = performance.now();
    const plain = am.mesh(pslg, { mode: 'nonobtuse' });
    const plainMs = performance.now() - t;
    const controller = new AbortController();
    const t0 = performance.now();
    const m = await worker.mesh(pslg, {
      mode: 'nonobtuse', optimize: 60, signal: controller.signal,
      // (Once the search runs, not in the polish before it: see api.test.mjs.)
      onProgress: (p) => {
        if (p.phase === 'improve' && performance.now() - t0 > 2 * plainMs + 300) controller.abort();
      },
    });
    assert.ok(performance.now() - t0 < 30000, 'the abort did not stop the search');
    assertBestSoFar(am, pslg, m, plain);

    // (The slow job's refinement takes a second or more: the abort comes before its end.)
    const reason = new Error('user cancelled');
    const early = new AbortController();
    await assert.rejects(worker.mesh(square, {
      ...slow, optimize: 60, signal: early.signal,
      onProgress: (p) => { if (p.phase === 'refine') early.abort(reason); },
    }), (e) => e === reason);
    assert.ok((await worker.mesh(square, { mode: 'acute' })).stats.certified);
  } finally {
    worker.terminate();
  }
});

test('an exception in onProgress rejects the call; the next queued call still runs', { timeout: 120000 }, async () => {
  const worker = createMeshWorker();
  try {
    const oops = new RangeError('progress handler failed');
    const failing = worker.mesh(square, { ...slow, onProgress: () => { throw oops; } });
    const next = worker.mesh(pslg, { mode: 'acute' });
    await assert.rejects(failing, (e) => e === oops);
    assert.ok((await next).stats.certified);
  } finally {
    worker.terminate();
  }
});

test('meshInWorker uses one shared worker; terminate rejects pending calls', { timeout: 120000 }, async () => {
  const m = await meshInWorker(square, { mode: 'acute' });
  assert.ok(m.stats.certified);
  const worker = createMeshWorker();
  const pending = worker.mesh(square, slow);
  worker.terminate();
  await assert.rejects(pending, /terminated/);
  await assert.rejects(worker.mesh(square), /terminated/);
});

test('workerUrl and init.wasmUrl say where the worker and the .wasm are; when missing, the error names the file and the fix', { timeout: 120000 }, async () => {
  const dir = mkdtempSync(join(tmpdir(), 'acutemesh-worker-url-'));
  try {
    // The package's files where a bundler's output would put them, under other names.
    copyFileSync(join(root, 'dist', 'acutemesh.wasm'), join(dir, 'module.wasm'));
    const relative = (p) => './' + relativePath(process.cwd(), p);
    const placed = createMeshWorker({
      workerUrl: relative(join(root, 'dist', 'mesh-worker-node.js')),  // a path, as in Node
      init: { wasmUrl: relative(join(dir, 'module.wasm')) },
    });
    try {
      assert.ok((await placed.mesh(square, { mode: 'acute' })).stats.certified);
    } finally {
      placed.terminate();
    }

    const missing = join(dir, 'no-such-worker.js');
    const noWorker = createMeshWorker({ workerUrl: pathToFileURL(missing) });
    await assert.rejects(noWorker.mesh(square), (e) => {
      assert.ok(e.message.startsWith(`acutemesh: could not start the mesh worker from ${pathToFileURL(missing).href} (`), e.message);
      assert.match(e.message, /createMeshWorker\(\{ workerUrl \}\)$/);
      return true;
    });
    noWorker.terminate();

    const noWasm = createMeshWorker({ init: { wasmUrl: join(dir, 'acutemesh.wasm') } });
    await assert.rejects(noWasm.mesh(square), (e) => {
      assert.ok(e.message.startsWith(`acutemesh: cannot read the WebAssembly module ${pathToFileURL(join(dir, 'acutemesh.wasm')).href} (ENOENT): `), e.message);
      assert.match(e.message, /init\(\{ wasmUrl \}\)$/);
      return true;
    });
    noWasm.terminate();
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
