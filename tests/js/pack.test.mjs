// The package as users get it: `npm pack` (its prepack step builds dist/, or refuses without
// the toolchain), the tarball holding exactly dist/ as wasm/assemble.mjs makes it,
// package.json, README.md and LICENSE; installed into an empty project, and there: repository
// inputs (and the reference .poly inputs, when that data is there) meshed to certified acute
// meshes through the API, acutemesh/single and acutemesh/worker imported, require('acutemesh')
// from CommonJS, and the types resolved by tsc from node_modules (moduleResolution nodenext,
// bundler and node10; nodenext from CommonJS).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, writeFileSync, rmSync, readdirSync, mkdirSync, symlinkSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

import { root, testData, syntheticCgshop, needsReference, referencePolys } from './helpers.mjs';

const npm = process.platform === 'win32' ? 'npm.cmd' : 'npm';
const sh = (cmd, args, cwd) => execFileSync(cmd, args, { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });

// dist/ as wasm/assemble.mjs writes it: the Emscripten module, its base64 copy, the facade
// and the types.
const distFiles = ['acutemesh.mjs', 'acutemesh.wasm', 'wasm-inline.js',
  ...readdirSync(join(root, 'wasm', 'js')), ...readdirSync(join(root, 'wasm', 'types'))].map((f) => `dist/${f}`);

test('npm pack, install into an empty project, mesh acute there', async (t) => {
  const work = mkdtempSync(join(tmpdir(), 'acutemesh-pack-'));
  t.after(() => rmSync(work, { recursive: true, force: true }));

  const packed = JSON.parse(sh(npm, ['pack', '--json', '--pack-destination', work], root));
  const files = packed[0].files.map((f) => f.path).sort();
  // The files the exports map names, then the whole list.
  for (const f of ['dist/acutemesh.wasm', 'dist/acutemesh.mjs', 'dist/index.js', 'dist/node.js',
    'dist/single.js', 'dist/wasm-inline.js', 'dist/worker.js', 'dist/worker-node.js',
    'dist/mesh-worker.js', 'dist/mesh-worker-node.js', 'dist/index.d.ts', 'dist/single.d.ts',
    'dist/worker.d.ts'])
    assert.ok(files.includes(f), `${f} is not in the tarball`);
  assert.deepEqual(files, ['LICENSE', 'README.md', ...distFiles, 'package.json'].sort());
  for (const f of packed[0].files) assert.ok(f.size > 0, `${f.path} is empty`);
  const tarball = join(work, packed[0].filename);

  const app = join(work, 'app');
  sh('mkdir', ['-p', app]);
  writeFileSync(join(app, 'package.json'), JSON.stringify({ name: 'app', private: true, type: 'module' }));
  sh(npm, ['install', '--no-audit', '--no-fund', tarball], app);
  assert.deepEqual(readdirSync(join(app, 'node_modules')).filter((d) => !d.startsWith('.')), ['acutemesh']);

  writeFileSync(join(app, 'check.mjs'), `
import { readFileSync } from 'node:fs';
import { basename } from 'node:path';
import init from 'acutemesh';
import initSingle from 'acutemesh/single';
import { meshInWorker } from 'acutemesh/worker';
const am = await init();
const out = [];
for (const path of process.argv.slice(2)) {
  const parse = path.endsWith('.poly') ? am.parsePoly : am.parseJson;
  const pslg = parse(readFileSync(path, 'utf8'), { name: basename(path) });
  const m = am.mesh(pslg, { mode: 'acute' });
  const v = am.validate(pslg, m);
  out.push({ path, status: m.status, certified: m.stats.certified, nonAcute: m.stats.nonAcute,
             triangles: m.stats.triangles, valid: v.ok, errors: v.errors });
}
const single = await initSingle();
const square = { points: [0, 0, 1, 0, 1, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0] };
const s = single.mesh(square, { mode: 'acute' });
const w = await meshInWorker(square, { mode: 'acute' });
console.log(JSON.stringify({ out, single: s.stats.certified, worker: w.stats.certified }));
`);
  // Meshes the inputs at paths in the installed package: each certified acute.
  const meshAcute = (paths) => {
    const result = JSON.parse(sh(process.execPath, ['check.mjs', ...paths], app));
    assert.equal(result.out.length, paths.length);
    for (const r of result.out) {
      assert.equal(r.valid, true, `${r.path}: ${r.errors.join('; ')}`);
      assert.equal(r.certified, true, `${r.path} is not certified acute`);
      assert.equal(r.nonAcute, 0);
      assert.equal(r.status, 'ok');
      assert.ok(r.triangles > 0);
    }
    assert.equal(result.single, true);
    assert.equal(result.worker, true);
  };
  // CommonJS: init is require('acutemesh') itself.
  writeFileSync(join(app, 'check.cjs'), `
const init = require('acutemesh');
init().then((am) => console.log(am.mesh({ points: [0, 0, 1, 0, 0, 1] }, { mode: 'acute' }).stats.certified));
`);
  assert.equal(sh(process.execPath, ['check.cjs'], app).trim(), 'true');

  await t.test('repository inputs meshed acute', () => meshAcute([
    join(testData, 'A.poly'), join(testData, 'plate.poly'), join(testData, 'naca0012.poly'),
    join(syntheticCgshop, 'simple-polygon-exterior_50_synthetic.instance.json')]));
  const title = 'reference .poly inputs meshed acute';
  await t.test(title, needsReference(title), () => {
    const polys = referencePolys();
    assert.ok(polys.length >= 2);
    meshAcute(polys);
  });

  // Types from node_modules, as TypeScript users resolve them: through the exports map
  // (nodenext, bundler), or through "types" and "typesVersions" (the older node10).
  writeFileSync(join(app, 'use.mts'), `
import init, { AcuteMeshError, type MeshResult } from 'acutemesh';
import initSingle from 'acutemesh/single';
import { createMeshWorker } from 'acutemesh/worker';
const am = await init();
const m: MeshResult = am.mesh(am.fromRings([[[0, 0], [1, 0], [0, 1]]]), { mode: 'acute' });
const e = new AcuteMeshError('BAD_INPUT', 'x');
void [m.stats.certified, e.code, initSingle, createMeshWorker];
`);
  writeFileSync(join(app, 'use.cts'), `
import init = require('acutemesh');
export async function use(): Promise<boolean> {
  const am: init.AcuteMesh = await init();
  return am.mesh({ points: [0, 0, 1, 0, 0, 1] }, { mode: 'acute' }).stats.certified;
}
`);
  const tsc = join(root, 'node_modules', 'typescript', 'bin', 'tsc');
  for (const resolution of [['nodenext', 'nodenext'], ['esnext', 'bundler'], ['esnext', 'node10']]) {
    let output = '';
    try {
      sh(process.execPath, [tsc, '--noEmit', '--strict', '--target', 'es2022', '--lib', 'es2022,dom',
        '--module', resolution[0], '--moduleResolution', resolution[1], 'use.mts'], app);
    } catch (e) {
      output = e.stdout + e.stderr;
    }
    assert.equal(output, '', `moduleResolution ${resolution[1]}`);
  }
  let output = '';
  try {
    sh(process.execPath, [tsc, '--noEmit', '--strict', '--target', 'es2022', '--lib', 'es2022',
      '--module', 'nodenext', '--moduleResolution', 'nodenext', 'use.cts'], app);
  } catch (e) {
    output = e.stdout + e.stderr;
  }
  assert.equal(output, '', 'CommonJS, moduleResolution nodenext');
});

test('npm pack refuses, packing nothing, without the WebAssembly toolchain', (t) => {
  const work = mkdtempSync(join(tmpdir(), 'acutemesh-pack-refused-'));
  t.after(() => rmSync(work, { recursive: true, force: true }));
  // A PATH with npm and what prepack.sh needs to run, but no cmake or Emscripten.
  const bin = join(work, 'bin');
  mkdirSync(bin);
  for (const tool of [npm, 'node', 'bash', 'sh', 'env', 'dirname'])
    symlinkSync(sh('bash', ['-c', `command -v ${tool}`]).trim(), join(bin, tool));
  const out = join(work, 'out');
  let error;
  try {
    execFileSync(join(bin, npm), ['pack', '--pack-destination', out], {
      cwd: root, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'], env: { ...process.env, PATH: bin },
    });
  } catch (e) {
    error = e;
  }
  assert.ok(error, 'npm pack succeeded without cmake and Emscripten');
  assert.match(error.stderr, /prepack: cannot build the package's dist\/: missing cmake emcmake emcc/);
  assert.match(error.stderr, /Nothing was packed\./);
  assert.deepEqual(readdirSync(work), ['bin']);
});
