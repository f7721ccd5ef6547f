// The WebAssembly build makes the same meshes as the native CLI (build/acutemesh, built by
// scripts/build.sh before the tests): same vertices to the bit, same triangles, every mode on
// every fixture. Both compile the core without fused multiply-add, so every rounded
// construction agrees; a difference here means the two builds diverged.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { readFileSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

import init from 'acutemesh';
import { fixtures, load, label, root, needsReference, referencePolys } from './helpers.mjs';

const cli = join(root, 'build', 'acutemesh');
const am = await init();

function expectSameMeshes(t, paths) {
  const dir = mkdtempSync(join(tmpdir(), 'acutemesh-native-'));
  t.after(() => rmSync(dir, { recursive: true, force: true }));
  for (const path of paths) {
    const pslg = load(am, path);
    for (const mode of ['delaunay', 'cdt', 'quality', 'nonobtuse', 'acute']) {
      const base = join(dir, 'out');
      const args = ['--mode', mode, '--format', 'json', '-o', base, path];
      if (pslg.fill) args.unshift('--fill', pslg.fill);
      const run = spawnSync(cli, args, { encoding: 'utf8' });
      assert.ok(run.status === 0 || run.status === 1, `${cli} ${args.join(' ')}: ${run.stderr}`);
      const native = JSON.parse(readFileSync(`${base}.json`, 'utf8'));
      const m = am.mesh(pslg, { mode });
      const what = `${label(path)} ${mode}`;
      assert.deepEqual(m.points, Float64Array.from(native.vertices.flat()), `${what}: vertices differ`);
      assert.deepEqual(m.triangles, Uint32Array.from(native.triangles.flat()), `${what}: triangles differ`);
      assert.equal(m.status, run.status === 0 ? 'ok' : 'target-not-met', what);
    }
  }
}

test('wasm and native meshes are identical', (t) => expectSameMeshes(t, fixtures()));

const title = 'wasm and native meshes are identical on the reference .poly inputs';
test(title, needsReference(title), (t) => expectSameMeshes(t, referencePolys()));

// The package's writers write what the CLI writes for the same mesh, byte for byte: every
// format of the vocabulary (but the CG:SHOP solution), on a plate and on a fixture with
// segment markers and regions.
test('every writer writes what the CLI writes', (t) => {
  const dir = mkdtempSync(join(tmpdir(), 'acutemesh-native-'));
  t.after(() => rmSync(dir, { recursive: true, force: true }));
  const formats = am.vocabulary.outputFormats.filter((f) => !f.needsInstance);
  for (const path of [join(root, 'tests', 'data', 'plate.poly'), join(root, 'tests', 'data', 'io', 'marked-regions.poly')]) {
    const base = join(dir, 'out');
    const args = ['--mode', 'acute', '--format', formats.map((f) => f.name).join(','), '-o', base, path];
    const run = spawnSync(cli, args, { encoding: 'utf8' });
    assert.equal(run.status, 0, `${cli} ${args.join(' ')}: ${run.stderr}`);
    const m = am.mesh(load(am, path), { mode: 'acute' });
    for (const f of formats)
      assert.equal(am.write(m, f.name), readFileSync(base + f.extension, 'utf8'), `${label(path)}: ${f.name}`);
  }
});
