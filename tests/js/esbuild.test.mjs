// esbuild, which copies neither the .wasm nor the worker that `new URL(..., import.meta.url)`
// names (Vite and webpack do): in Chromium, a zero-configuration bundle fails with errors that
// name the missing file and the fix; the recipe of docs/js.md (the worker as an entry of its
// own, the .wasm copied beside) works with no option; other places work with init({ wasmUrl })
// and createMeshWorker({ workerUrl, init: { wasmUrl } }). For Node, a bundle that keeps the
// package external works, and one that swallows it says so.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { createServer } from 'node:http';
import { mkdtempSync, mkdirSync, writeFileSync, readFileSync, copyFileSync, symlinkSync, rmSync, existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, extname, basename, normalize } from 'node:path';

import { root } from './helpers.mjs';
import { launch } from '../web/browser.mjs';

const esbuild = await import('esbuild').catch(() => {
  throw new Error('esbuild is missing: it is a devDependency, run `npm install`');
});

// A project with the package in node_modules (a link to this checkout, whose dist/ ships).
const app = mkdtempSync(join(tmpdir(), 'acutemesh-esbuild-'));
mkdirSync(join(app, 'node_modules'));
symlinkSync(root, join(app, 'node_modules', 'acutemesh'), 'dir');
mkdirSync(join(app, 'src'));
const pkg = join(app, 'node_modules', 'acutemesh', 'dist');

// The page's script: meshes on the main thread and in the worker, with the options the page
// sets in window.INIT and window.WORKER, and publishes what happened in window.results.
writeFileSync(join(app, 'src', 'app.js'), `
import init from 'acutemesh';
import { createMeshWorker } from 'acutemesh/worker';
const square = { points: [0, 0, 1, 0, 1, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0] };
window.results = (async () => {
  const out = {};
  try {
    out.main = (await init(window.INIT)).mesh(square, { mode: 'acute' }).stats.certified;
  } catch (e) {
    out.mainError = e.message;
  }
  const worker = createMeshWorker(window.WORKER);
  try {
    out.worker = (await worker.mesh(square, { mode: 'acute' })).stats.certified;
  } catch (e) {
    out.workerError = e.message;
  }
  worker.terminate();
  return out;
})();
`);

// A page in `dir` (relative to app) that sets the options and loads `script`.
function page(dir, script, { init, worker } = {}) {
  writeFileSync(join(app, dir, 'index.html'), `<!doctype html><meta charset="utf-8">
<script>window.INIT = ${JSON.stringify(init)}; window.WORKER = ${JSON.stringify(worker)};</script>
<script type="module" src="${script}"></script>`);
}

const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm' };
const server = createServer((req, res) => {
  const path = join(app, normalize(decodeURIComponent(new URL(req.url, 'http://x').pathname)));
  if (!path.startsWith(app) || !existsSync(path) || !types[extname(path)]) {
    res.writeHead(404, { 'content-type': 'text/plain' }).end('not found');
    return;
  }
  res.writeHead(200, { 'content-type': types[extname(path)] }).end(readFileSync(path));
});
await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
const origin = `http://127.0.0.1:${server.address().port}`;

const browser = await launch();
test.after(async () => {
  await browser.close();
  server.close();
  rmSync(app, { recursive: true, force: true });
});

async function resultsOf(dir) {
  const context = await browser.browser.newContext();
  try {
    const p = await context.newPage();
    await p.goto(`${origin}/${dir}/index.html`);
    return await p.evaluate(() => window.results);
  } finally {
    await context.close();
  }
}

const bundle = (options) => esbuild.build({ absWorkingDir: app, bundle: true, format: 'esm', logLevel: 'silent', ...options });

test('zero configuration: the errors name the missing files and the fix', { timeout: 60000 }, async () => {
  await bundle({ entryPoints: ['src/app.js'], outdir: 'zero' });
  page('zero', 'app.js');
  const r = await resultsOf('zero');
  assert.ok(r.mainError.startsWith(`acutemesh: cannot load the WebAssembly module from ${origin}/zero/acutemesh.wasm (HTTP 404): `), r.mainError);
  assert.match(r.mainError, /serve node_modules\/acutemesh\/dist\/acutemesh\.wasm there .* init\(\{ wasmUrl \}\), or import 'acutemesh\/single'/);
  assert.ok(r.workerError.startsWith(`acutemesh: could not start the mesh worker from ${origin}/zero/mesh-worker.js (`), r.workerError);
  assert.match(r.workerError, /bundle node_modules\/acutemesh\/dist\/mesh-worker\.js as an entry of its own .* createMeshWorker\(\{ workerUrl \}\)$/);
});

test('the recipe of docs/js.md: the worker an entry of its own, the .wasm beside', { timeout: 60000 }, async () => {
  // docs/js.md's build script, run as it is: public/assets/{app.js,mesh-worker.js,acutemesh.wasm}.
  const docs = readFileSync(join(root, 'docs', 'js.md'), 'utf8');
  const recipe = /```js\n(\/\/ build\.mjs [^]*?)```/.exec(docs);
  assert.ok(recipe, 'docs/js.md has no build.mjs block');
  writeFileSync(join(app, 'build.mjs'), recipe[1]);
  symlinkSync(join(root, 'node_modules', 'esbuild'), join(app, 'node_modules', 'esbuild'), 'dir');
  execFileSync(process.execPath, ['build.mjs'], { cwd: app, stdio: 'pipe' });
  page('public', 'assets/app.js');
  assert.deepEqual(await resultsOf('public'), { main: true, worker: true });
});

test('files elsewhere: init({ wasmUrl }) and createMeshWorker({ workerUrl, init: { wasmUrl } })', { timeout: 60000 }, async () => {
  const built = await bundle({
    entryPoints: ['src/app.js', 'node_modules/acutemesh/dist/mesh-worker.js'],
    entryNames: '[name]-[hash]', outdir: 'hashed/js', metafile: true,
  });
  const outputs = Object.keys(built.metafile.outputs).map((p) => basename(p));
  const appJs = outputs.find((f) => f.startsWith('app-'));
  const workerJs = outputs.find((f) => f.startsWith('mesh-worker-'));
  mkdirSync(join(app, 'hashed', 'static'));
  copyFileSync(join(pkg, 'acutemesh.wasm'), join(app, 'hashed', 'static', 'acutemesh.wasm'));
  // Relative to the page, in the worker too (not to the worker's script).
  page('hashed', `js/${appJs}`, {
    init: { wasmUrl: 'static/acutemesh.wasm' },
    worker: { workerUrl: `js/${workerJs}`, init: { wasmUrl: 'static/acutemesh.wasm' } },
  });
  assert.deepEqual(await resultsOf('hashed'), { main: true, worker: true });
});

test('Node: a bundle keeping acutemesh external works; one that swallows it says how to fix it', { timeout: 60000 }, async () => {
  writeFileSync(join(app, 'src', 'node-app.mjs'), `
import init from 'acutemesh';
const am = await init();
console.log(am.mesh({ points: [[0, 0], [1, 0], [0, 1]] }, { mode: 'acute' }).stats.certified);
`);
  await bundle({ entryPoints: ['src/node-app.mjs'], platform: 'node', packages: 'external', outfile: 'node/external.mjs' });
  assert.equal(execFileSync(process.execPath, [join(app, 'node', 'external.mjs')], { encoding: 'utf8' }).trim(), 'true');
  await bundle({ entryPoints: ['src/node-app.mjs'], platform: 'node', outfile: 'node/inside.mjs' });
  assert.throws(() => execFileSync(process.execPath, [join(app, 'node', 'inside.mjs')], { encoding: 'utf8', stdio: 'pipe' }),
    (e) => /acutemesh: cannot read the WebAssembly module file:\/\/\S+\/node\/acutemesh\.wasm \(ENOENT\): keep acutemesh out of the bundle \(esbuild --packages=external\)/.test(e.stderr));
});
