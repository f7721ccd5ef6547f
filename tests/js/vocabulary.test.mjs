// One vocabulary and one policy: the package's names, types and writers are the core's tables
// (vocabulary.h, exported as am.vocabulary), and a CG:SHOP instance meshes the same through the
// CLI, mesh() and the worker (the core's input policy, applied for every caller).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { readFileSync, writeFileSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

import init, { AcuteMeshError } from 'acutemesh';
import { createMeshWorker } from 'acutemesh/worker';
import { root } from './helpers.mjs';
import { generatedInstance } from './generated-instance.mjs';

const am = await init();
const { vocabulary } = am;
const names = (table) => table.map((e) => e.name);
const square = { points: [0, 0, 1, 0, 1, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0] };

// The string literals of `export type NAME = ...;` in the package's index.d.ts.
const dts = readFileSync(join(root, 'dist', 'index.d.ts'), 'utf8');
function union(name) {
  const m = new RegExp(`export type ${name} =([^;]*);`).exec(dts);
  assert.ok(m, `index.d.ts declares no type ${name}`);
  return [...m[1].replace(/\/\*[\s\S]*?\*\//g, '').matchAll(/'([^']*)'/g)].map((x) => x[1]);
}

test('the .d.ts string unions are the core\'s tables, in the same order', () => {
  assert.deepEqual(union('Mode'), names(vocabulary.modes));
  assert.deepEqual(union('FillRule'), names(vocabulary.fillRules));
  assert.deepEqual(union('Status'), names(vocabulary.statuses));
  assert.deepEqual(union('VertexKindName'), names(vocabulary.vertexKinds));
  assert.deepEqual(union('InputFormat'), names(vocabulary.inputFormats));
  assert.deepEqual(union('OutputFormat'), names(vocabulary.outputFormats));
  assert.match(dts, /status: Extract<Status, 'ok' \| 'target-not-met'>;/);
  // vertexKind's numbers index the table, as the .d.ts says.
  vocabulary.vertexKinds.forEach((k, i) => {
    assert.equal(k.value, i);
    assert.ok(dts.includes(`${i} '${k.name}'`), `index.d.ts does not name vertex kind ${i} '${k.name}'`);
  });
});

test('the vocabulary: names, values, descriptions, defaults; frozen', () => {
  for (const table of ['modes', 'fillRules', 'statuses', 'vertexKinds', 'inputFormats', 'outputFormats']) {
    vocabulary[table].forEach((e, i) => {
      assert.equal(e.value, i, `${table}[${i}]`);
      assert.ok(e.name && e.description, `${table}[${i}]`);
    });
  }
  assert.ok(Object.isFrozen(vocabulary) && Object.isFrozen(vocabulary.modes[0]) && Object.isFrozen(vocabulary.defaults));
  assert.throws(() => { 'use strict'; vocabulary.modes.push({}); }, TypeError);
  const { qualityMinAngle, ringsFill, ...defaults } = vocabulary.defaults;
  assert.equal(qualityMinAngle, 20);
  assert.equal(ringsFill, 'evenodd');
  assert.deepEqual(am.mesh(square).options, defaults);
  assert.equal(am.fromRings([[[0, 0], [1, 0], [0, 1]]]).fill, ringsFill);
  const cgshop = vocabulary.outputFormats.find((f) => f.name === 'cgshop');
  assert.equal(cgshop.extension, '.solution.json');
  assert.equal(cgshop.needsInstance, true);
});

test('every output format has its writer, and write(mesh, name) is it', () => {
  const m = am.mesh(square, { mode: 'acute' });
  const writers = Object.keys(am).filter((k) => /^to[A-Z]/.test(k));
  const formats = vocabulary.outputFormats.map((f) => f.name);
  assert.deepEqual(writers.map((k) => k.slice(2).toLowerCase()).sort(), [...formats].sort());
  for (const method of writers) assert.ok(dts.includes(`  ${method}(mesh: MeshInput`), `index.d.ts lacks ${method}`);
  const instance = am.parseJson(generatedInstance());
  const cg = am.mesh(instance);
  for (const f of vocabulary.outputFormats) {
    const method = writers.find((k) => k.slice(2).toLowerCase() === f.name);
    if (f.needsInstance) assert.equal(am.write(cg, f.name, instance), am[method](cg, instance));
    else assert.equal(am.write(m, f.name), am[method](m));
  }
  assert.throws(() => am.write(m, 'stl'), (e) => e instanceof AcuteMeshError && e.code === 'BAD_INPUT' &&
    e.message === "unknown format 'stl' (node, ele, poly, edge, neigh, json, off, obj, svg, msh, msh2, vtu, cgshop)");
  assert.throws(() => am.write(m, 'jsno'), /did you mean 'json'\?/);
  assert.throws(() => am.write(m), TypeError);
});

test('a name that is none of the core\'s: its message, with the nearest name', () => {
  const bad = (options, pattern) => assert.throws(() => am.mesh(square, options),
    (e) => e instanceof AcuteMeshError && e.code === 'BAD_INPUT' && pattern.test(e.message));
  bad({ mode: 'non-obtuse' }, /^unknown mode 'non-obtuse' \(delaunay, cdt, quality, nonobtuse, acute\): did you mean 'nonobtuse'\?$/);
  bad({ fill: 'even-odd' }, /^unknown fill rule 'even-odd' \(triangle, evenodd, nonzero\): did you mean 'evenodd'\?$/);
  assert.throws(() => am.mesh({ ...square, format: 'cgshop2025' }), /unknown input format 'cgshop2025'/);
  assert.throws(() => am.mesh({ ...square, format: 1 }), (e) => e instanceof TypeError && /pslg\.format must be a string/.test(e.message));
});

// The CLI (build/acutemesh, beside the package as native.test.mjs uses it), mesh() and the
// worker, on an instance made here: the same vertices, triangles and exact points.
test('a CG:SHOP instance meshes the same from the CLI, mesh() and the worker', async (t) => {
  const dir = mkdtempSync(join(tmpdir(), 'acutemesh-policy-'));
  t.after(() => rmSync(dir, { recursive: true, force: true }));
  const text = generatedInstance();
  const path = join(dir, 'generated.instance.json');
  writeFileSync(path, text);
  const instance = am.parseJson(text, { name: 'generated.instance.json' });
  assert.equal(instance.format, 'cgshop');
  const worker = createMeshWorker();
  t.after(() => worker.terminate());
  for (const [mode, extra, cliArgs] of [
    ['nonobtuse', {}, []],
    ['acute', {}, []],
    ['nonobtuse', { exactFeet: false }, ['--no-exact-feet']],
  ]) {
    const base = join(dir, `${mode}${cliArgs.join('')}`);
    const run = spawnSync(join(root, 'build', 'acutemesh'), ['--mode', mode, ...cliArgs, '--format', 'json', '-o', base, path], { encoding: 'utf8' });
    assert.equal(run.status, 0, run.stderr);
    const native = JSON.parse(readFileSync(`${base}.json`, 'utf8'));
    const what = `${mode} ${JSON.stringify(extra)}`;
    for (const m of [am.mesh(instance, { mode, ...extra }), await worker.mesh(instance, { mode, ...extra })]) {
      assert.deepEqual(m.points, Float64Array.from(native.vertices.flat()), `${what}: vertices differ`);
      assert.deepEqual(m.triangles, Uint32Array.from(native.triangles.flat()), `${what}: triangles differ`);
      assert.deepEqual(m.exactPoints.map((p) => [p.vertex, p.x, p.y]), native.exactPoints ?? [], `${what}: exact points differ`);
      assert.equal(m.options.exactSegments, true);
      assert.equal(m.options.exactFeet, extra.exactFeet ?? true);
      assert.ok(am.validate(instance, m).ok);
    }
    if (mode === 'nonobtuse' && extra.exactFeet === undefined) assert.ok(native.exactPoints.length > 0);
  }
  // The same points without the parser's format: the policy does not apply.
  const plain = am.mesh({ points: instance.points, segments: instance.segments }, { mode: 'nonobtuse' });
  assert.equal(plain.options.exactFeet, false);
  assert.deepEqual(plain.exactPoints, []);
  // validate() checks a mesh with the options it was made with, whatever its input's format.
  assert.ok(am.validate(instance, plain).ok);
});
