// The web page in headless Chromium: every input kind meshes through the package's worker,
// Cancel stops a run, downloads read back as valid meshes, and screenshots are kept in
// build/web-artifacts/ to be looked at. Run: node --test tests/web/ (after npm run build).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync, mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { root, artifacts, startServer, launch, openPage, result, waitForRun } from './browser.mjs';

// The target is 1 s from navigation to the first mesh on screen; the measured figure
// is printed (speed is the benchmarks' business). The assertion only guards against a gross
// regression: the same code took 0.74-1.1 s on one 2-core VM and 1.3-1.56 s on another, with
// the mesher itself at 100-160 ms on both, so a tighter bound made the suite flaky.
const FIRST_MESH_BUDGET_MS = Number(process.env.ACUTEMESH_FIRST_MESH_MS || 3000);

let server, chromium, am;
before(async () => {
  server = await startServer();
  chromium = await launch();
  // The package by its own name, as a user's Node code would load it (package.json exports).
  am = await (await import('acutemesh')).default();
});
after(async () => {
  await chromium?.close();
  server?.close();
});

const pageUrl = (query = '') => `${server.url}${query}`;
const shot = (page, name) => page.screenshot({ path: join(artifacts, `${name}.png`) });

async function open(query, options) {
  const p = await openPage(chromium.browser, pageUrl(query), options);
  await waitForRun(p.page, 1);
  return p;
}

async function runAndWait(page) {
  const before = Number(await page.getAttribute('[data-testid=stats]', 'data-runs'));
  await page.click('[data-testid=run-button]');
  return waitForRun(page, before + 1, 60000);
}

async function upload(page, path) {
  await page.setInputFiles('[data-testid=file-input]', path);
  // Choosing a file previews it; the source line names what was read.
  await page.waitForFunction(() => /Press Mesh\./.test(document.getElementById('source').textContent));
}

async function downloadText(page, testid) {
  const [dl] = await Promise.all([page.waitForEvent('download'), page.click(`[data-testid=${testid}]`)]);
  return { name: dl.suggestedFilename(), text: readFileSync(await dl.path(), 'utf8'), path: await dl.path() };
}

// The mesh as the JSON download has it, checked by the package's exact validate() against
// the input it was made from.
function meshFromJson(text) {
  const j = JSON.parse(text);
  return {
    points: Float64Array.from(j.vertices.flat()),
    triangles: Uint32Array.from(j.triangles.flat()),
    segments: Uint32Array.from((j.segments || []).flat()),
  };
}

function assertCertifiedAcute(r, what) {
  assert.ok(r, `${what}: no result`);
  assert.ok(r.triangles > 0, `${what}: no triangles`);
  assert.equal(r.certified, true, `${what}: not certified acute (${JSON.stringify(r)})`);
  // Certification is exact; the float angle of a corner a hair below 90 may print as 90.
  assert.ok(r.maxAngle <= 90, `${what}: max angle ${r.maxAngle}`);
}

test('the default sample ("Acute" in Pagella) meshes acute on load, without console errors', async () => {
  const { page, errors, context } = await open('');
  const r = await result(page);
  assertCertifiedAcute(r, 'default');
  for (const k of ['triangles', 'vertices', 'steiner', 'minAngle', 'maxAngle', 'certified', 'milliseconds']) {
    assert.ok(k in r, `data-result lacks ${k}`);
  }
  assert.equal(r.vertices, r.inputVertices + r.steiner, 'vertices = input + Steiner');
  await page.waitForFunction(() => document.body.dataset.firstMeshMs);
  const firstMs = Number(await page.getAttribute('body', 'data-first-mesh-ms'));
  console.log(`# first mesh on screen ${firstMs} ms after navigation (mesher ${r.milliseconds} ms, round trip ${r.wallMilliseconds} ms)`);
  assert.ok(firstMs < FIRST_MESH_BUDGET_MS, `first mesh after ${firstMs} ms`);
  // The histogram counts every angle of the mesh, three per triangle.
  const bins = (await page.getAttribute('[data-testid=histogram]', 'data-bins')).split(',').map(Number);
  assert.equal(bins.reduce((a, b) => a + b, 0), 3 * r.triangles);
  assert.equal(bins.slice(45).reduce((a, b) => a + b, 0), 0, 'an acute mesh has no angle of 90 degrees or more');
  await shot(page, 'default');
  assert.deepEqual(errors, []);
  await context.close();
});

test('the page is crisp at devicePixelRatio 2: the canvas has twice the CSS pixels', async () => {
  const { page, errors, context } = await open('', { dpr: 2, width: 900, height: 600 });
  const size = await page.$eval('[data-testid=mesh-canvas]', (c) => [c.width, c.height, c.clientWidth, c.clientHeight]);
  assert.equal(size[0], 2 * size[2]);
  assert.equal(size[1], 2 * size[3]);
  await shot(page, 'default-dpr2');
  assert.deepEqual(errors, []);
  await context.close();
});

test('typed text meshes only when Mesh is pressed', async () => {
  const { page, errors, context } = await open('');
  const first = await result(page);
  await page.fill('[data-testid=text-input]', 'Mesh 42');
  await page.waitForTimeout(300);
  assert.equal(await page.getAttribute('[data-testid=stats]', 'data-runs'), '1', 'editing text must not mesh');
  const r = await runAndWait(page);
  assertCertifiedAcute(r, 'typed text');
  assert.notEqual(r.inputVertices, first.inputVertices);
  assert.match(page.url(), /text=Mesh\+42/, 'the text is kept in the URL');
  await shot(page, 'text');
  assert.deepEqual(errors, []);
  await context.close();
});

test('the URL carries text and options: a shared link meshes the same', async () => {
  const { page, errors, context } = await open('?text=Hi&mode=nonobtuse');
  const r = await result(page);
  assert.equal(r.mode, 'nonobtuse');
  assert.equal(r.certified, true);
  assert.ok(r.maxAngle <= 90);
  assert.equal(await page.inputValue('[data-testid=text-input]'), 'Hi');
  assert.equal(await page.inputValue('[data-testid=mode-select]'), 'nonobtuse');
  assert.deepEqual(errors, []);
  await context.close();
});

test('quality beyond 40 degrees: the page says the bound was not reached and why', async () => {
  const { page, errors, context } = await open('?text=Hi&mode=quality&minAngle=44');
  const r = await result(page);
  assert.equal(r.mode, 'quality');
  assert.equal(r.targetMet, false);
  const status = await page.textContent('#status');
  assert.match(status, /Target not met \(a minimum angle of 44 degrees was not reached/);
  assert.match(status, /refined to 40 degrees/);
  assert.deepEqual(errors, []);
  await context.close();
});

test('quality defaults are the mesher\'s: 20 degrees only when neither bound is given', async () => {
  const { qualityMinAngle } = am.vocabulary.defaults;
  // Only an area bound: the page asks for nothing more, and the mesh keeps angles below 20.
  const areaOnly = await open('?text=Hi&mode=quality&maxArea=1e9');
  const a = await result(areaOnly.page);
  assert.deepEqual(a.options, { mode: 'quality', maxArea: 1e9 });
  assert.ok(a.minAngle < qualityMinAngle, `min angle ${a.minAngle}: a minimum angle was imposed`);
  assert.equal(await areaOnly.page.getAttribute('#minAngle', 'placeholder'), '0');
  assert.deepEqual(areaOnly.errors, []);
  await areaOnly.context.close();
  // No bound at all: the mesher's own default minimum angle.
  const none = await open('?text=Hi&mode=quality');
  const n = await result(none.page);
  assert.deepEqual(n.options, { mode: 'quality' });
  assert.ok(n.minAngle >= qualityMinAngle, `min angle ${n.minAngle}`);
  await none.page.fill('#minAngle', '');
  await none.page.dispatchEvent('#minAngle', 'change');
  assert.equal(await none.page.getAttribute('#minAngle', 'placeholder'), String(qualityMinAngle));
  assert.deepEqual(none.errors, []);
  await none.context.close();
});

test('the page\'s modes, downloads and option defaults are the mesher\'s vocabulary', async () => {
  const { page, errors, context } = await open('');
  const { modes, outputFormats, defaults } = am.vocabulary;
  const options = await page.$$eval('[data-testid=mode-select] option', (os) => os.map((o) => [o.value, o.title]));
  for (const [value, title] of options) {
    const mode = modes.find((m) => m.name === value);
    assert.ok(mode, `the page offers mode '${value}', which the mesher does not have`);
    assert.equal(title, mode.description);
  }
  const buttons = await page.$$eval('#downloads [data-format]', (bs) => bs.map((b) => [b.dataset.format, b.disabled]));
  assert.deepEqual(buttons.map(([f]) => f), [...outputFormats.filter((f) => !f.needsInstance).map((f) => f.name), 'png']);
  assert.ok(buttons.every(([, disabled]) => !disabled), 'downloads are enabled once a mesh is shown');
  for (const key of ['maxAngle', 'minAngle', 'maxArea', 'maxSteiner'])
    assert.equal(Number(await page.inputValue(`#${key}`)), defaults[key], `#${key} starts at the mesher's default`);
  // Max edge and grading start empty, "none", the mesher's 0.
  for (const key of ['maxEdge', 'grading']) {
    assert.equal(defaults[key], 0, `the mesher's default ${key}`);
    assert.equal(await page.inputValue(`#${key}`), '');
    assert.equal(await page.getAttribute(`#${key}`, 'placeholder'), 'none');
  }
  const off = await downloadText(page, 'download-off');
  assert.equal(off.name, 'Acute.off');
  assert.match(off.text, /^OFF\n/);
  assert.deepEqual(errors, []);
  await context.close();
});

test('an uploaded CG:SHOP instance meshes as the package and the CLI mesh it (exact feet)', async () => {
  const { generatedInstance } = await import('../js/generated-instance.mjs');
  const dir = mkdtempSync(join(tmpdir(), 'acutemesh-web-'));
  const path = join(dir, 'generated.instance.json');
  writeFileSync(path, generatedInstance());
  const { page, errors, context } = await open('?mode=nonobtuse');
  await upload(page, path);
  const r = await runAndWait(page);
  const expected = am.mesh(am.parseJson(generatedInstance()), { mode: 'nonobtuse' });
  assert.ok(expected.exactPoints.length > 0);
  const m = meshFromJson((await downloadText(page, 'download-json')).text);
  assert.equal(r.triangles, expected.stats.triangles);
  assert.deepEqual(m.triangles, expected.triangles);
  assert.deepEqual(m.points, expected.points);
  assert.deepEqual(errors, []);
  await context.close();
});

test('a file over the size limit is refused with a message; the page meshes on', async () => {
  const { page, errors, context } = await open('');
  const runs = await page.getAttribute('[data-testid=stats]', 'data-runs');
  // 33 MB of a valid-looking .node header and padding: refused by size before it is read.
  const big = Buffer.alloc(33 * 1024 * 1024, 0x20);
  big.write('3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n');
  await page.setInputFiles('[data-testid=file-input]', { name: 'big.node', mimeType: 'text/plain', buffer: big });
  await page.waitForFunction(() => /over 32 MB are refused/.test(document.getElementById('status').textContent));
  assert.equal(await page.getAttribute('[data-testid=stats]', 'data-runs'), runs, 'a refused file must not mesh');
  // The refused file is the current input now: Mesh says the same, and meshes nothing else.
  await page.click('[data-testid=run-button]');
  await page.waitForFunction(() => /over 32 MB are refused/.test(document.getElementById('status').textContent));
  assert.equal(await page.getAttribute('[data-testid=stats]', 'data-runs'), runs, 'Mesh meshed the previous input');
  await page.fill('[data-testid=text-input]', 'Acute');
  const r = await runAndWait(page);  // the page meshes on
  assertCertifiedAcute(r, 'after a refused file');
  assert.deepEqual(errors, []);
  await context.close();
});

test('an uploaded .poly meshes, and its .node/.ele and JSON downloads validate against it', async () => {
  const { page, errors, context } = await open('');
  const polyPath = join(root, 'tests', 'data', 'A.poly');
  await upload(page, polyPath);
  assert.equal(await page.getAttribute('[data-testid=stats]', 'data-runs'), '1', 'choosing a file must not mesh');
  const r = await runAndWait(page);
  assertCertifiedAcute(r, 'A.poly');
  assert.equal(r.inputVertices, 29);
  await shot(page, 'poly');

  const input = am.parsePoly(readFileSync(polyPath, 'utf8'));
  const json = await downloadText(page, 'download-json');
  assert.equal(json.name, 'A.json');
  const fromJson = meshFromJson(json.text);
  assert.equal(fromJson.triangles.length / 3, r.triangles);
  const v = am.validate(input, fromJson, { mode: 'acute' });
  assert.ok(v.ok, `JSON download does not validate: ${JSON.stringify(v.errors)}`);

  const node = await downloadText(page, 'download-node');
  const ele = await downloadText(page, 'download-ele');
  const points = am.parseNode(node.text).points;
  const rows = ele.text.split('\n').filter((l) => l.trim() && !l.trim().startsWith('#'));
  const [count, corners] = rows[0].trim().split(/\s+/).map(Number);
  assert.equal(count, r.triangles);
  assert.equal(corners, 3);
  // .ele indices are 0- or 1-based like the .node's first vertex number.
  const base = Number(node.text.split('\n').filter((l) => l.trim() && !l.trim().startsWith('#'))[1].trim().split(/\s+/)[0]);
  const triangles = Uint32Array.from(rows.slice(1, 1 + count).flatMap((l) => l.trim().split(/\s+/).slice(1, 4).map((x) => Number(x) - base)));
  const w = am.validate(input, { points, triangles, segments: fromJson.segments }, { mode: 'acute' });
  assert.ok(w.ok, `.node/.ele download does not validate: ${JSON.stringify(w.errors)}`);

  const poly = await downloadText(page, 'download-poly');
  assert.equal(am.parsePoly(poly.text).points.length, points.length, '.poly download re-reads with every vertex');
  for (const [id, pattern] of [['download-obj', /^v /m], ['download-svg', /<svg[\s>]/]]) {
    const d = await downloadText(page, id);
    assert.match(d.text, pattern, `${id} content`);
  }
  const png = await downloadText(page, 'download-png');
  const bytes = readFileSync(png.path);
  assert.equal(bytes.subarray(1, 4).toString(), 'PNG');
  const canvasWidth = await page.$eval('[data-testid=mesh-canvas]', (c) => c.width);
  assert.equal(bytes.readUInt32BE(16), canvasWidth, 'the PNG is the canvas at device resolution');
  assert.deepEqual(errors, []);
  await context.close();
});

test('an uploaded GeoJSON (lon/lat, with a hole) meshes, projected so shapes keep their proportions', async () => {
  const dir = mkdtempSync(join(tmpdir(), 'acutemesh-web-'));
  // A 1 x 1 degree cell at 60 N is about half as wide as it is tall on the ground.
  const square = (x0, y0, d) => [[x0, y0], [x0 + d, y0], [x0 + d, y0 + d], [x0, y0 + d], [x0, y0]];
  const geo = { type: 'FeatureCollection', features: [{ type: 'Feature', properties: {},
    geometry: { type: 'Polygon', coordinates: [square(10, 59.5, 1), square(10.3, 59.8, 0.4).reverse()] } }] };
  const path = join(dir, 'cell.geojson');
  writeFileSync(path, JSON.stringify(geo));
  const { page, errors, context } = await open('');
  await upload(page, path);
  const r = await runAndWait(page);
  assertCertifiedAcute(r, 'GeoJSON');
  assert.equal(r.inputVertices, 8);
  const m = meshFromJson((await downloadText(page, 'download-json')).text);
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  for (let i = 0; i < m.points.length; i += 2) {
    x0 = Math.min(x0, m.points[i]); x1 = Math.max(x1, m.points[i]);
    y0 = Math.min(y0, m.points[i + 1]); y1 = Math.max(y1, m.points[i + 1]);
  }
  const aspect = (x1 - x0) / (y1 - y0);
  assert.ok(Math.abs(aspect - Math.cos(Math.PI / 3)) < 0.03, `width/height ${aspect}, expected about 0.5`);
  assert.ok(Math.abs(y1 - y0 - 111.2) < 1, `height ${y1 - y0} km, expected about 111 km`);
  // The hole (0.4 degrees, centred, so about 22 km wide and 44 km tall about the projection's
  // centre) stays empty: no triangle has its centroid inside it.
  let inHole = 0;
  for (let t = 0; t < m.triangles.length; t += 3) {
    const [a, b, c] = [0, 1, 2].map((k) => 2 * m.triangles[t + k]);
    const cx = (m.points[a] + m.points[b] + m.points[c]) / 3, cy = (m.points[a + 1] + m.points[b + 1] + m.points[c + 1]) / 3;
    if (Math.abs(cx) < 10 && Math.abs(cy) < 21) inHole++;
  }
  assert.equal(inHole, 0, 'triangles inside the hole');
  await shot(page, 'geojson');
  assert.deepEqual(errors, []);
  await context.close();
});

test('a bundled map sample (Turkey, Natural Earth) meshes acute', async () => {
  const { page, errors, context } = await open('?sample=turkey');
  const r = await result(page);
  assertCertifiedAcute(r, 'Turkey');
  assert.ok(r.inputVertices > 400);
  await shot(page, 'sample-turkey');
  assert.deepEqual(errors, []);
  await context.close();
});

test('an SVG meshes with its fill rule: the even-odd gear keeps its bore empty', async () => {
  const { page, errors, context } = await open('');
  await upload(page, join(root, 'web', 'samples', 'gear.svg'));
  assert.match(await page.textContent('#source'), /fill-rule evenodd/);
  const r = await runAndWait(page);
  assertCertifiedAcute(r, 'gear.svg');
  const m = meshFromJson((await downloadText(page, 'download-json')).text);
  // The bore is the circle of radius 30 about (120, 120) in SVG units, y flipped: (120, -120).
  let inBore = 0, area = 0;
  for (let t = 0; t < m.triangles.length; t += 3) {
    const [a, b, c] = [0, 1, 2].map((k) => 2 * m.triangles[t + k]);
    const cx = (m.points[a] + m.points[b] + m.points[c]) / 3, cy = (m.points[a + 1] + m.points[b + 1] + m.points[c + 1]) / 3;
    if (Math.hypot(cx - 120, cy + 120) < 29) inBore++;
    area += ((m.points[b] - m.points[a]) * (m.points[c + 1] - m.points[a + 1]) - (m.points[c] - m.points[a]) * (m.points[b + 1] - m.points[a + 1])) / 2;
  }
  assert.equal(inBore, 0, 'triangles inside the bore: the even-odd rule was not applied');
  assert.ok(area > 20000 && area < 30000, `gear area ${area}`);
  await shot(page, 'svg');
  assert.deepEqual(errors, []);
  await context.close();
});

test('drawing: clicks place a ring, clicking its first vertex closes it, Mesh meshes it', async () => {
  const { page, errors, context } = await open('');
  await page.click('#draw');
  const box = await page.$eval('[data-testid=mesh-canvas]', (c) => { const r = c.getBoundingClientRect(); return [r.left, r.top, r.width, r.height]; });
  const at = (fx, fy) => page.mouse.click(box[0] + fx * box[2], box[1] + fy * box[3]);
  for (const [x, y] of [[0.3, 0.3], [0.7, 0.25], [0.75, 0.7], [0.35, 0.75], [0.3, 0.3]]) await at(x, y);
  for (const [x, y] of [[0.45, 0.45], [0.6, 0.45], [0.55, 0.58], [0.45, 0.45]]) await at(x, y);
  assert.match(await page.textContent('#source'), /2 rings/);
  assert.match(page.url(), /draw=/);
  const r = await runAndWait(page);
  assertCertifiedAcute(r, 'drawing');
  assert.equal(r.inputVertices, 7);
  await shot(page, 'drawing');
  assert.deepEqual(errors, []);
  await context.close();
});

test('Cancel stops a long run; the page keeps responding and meshes again afterwards', async () => {
  const { page, errors, context } = await open('');
  await page.selectOption('[data-testid=mode-select]', 'quality');
  await page.fill('#maxArea', '0.02');
  await page.fill('#maxSteiner', '100000000');
  // Frame gaps while the worker meshes: the main thread must stay free.
  await page.evaluate(() => {
    window.__gaps = [];
    let last = performance.now();
    const tick = (t) => { window.__gaps.push(t - last); last = t; if (window.__gaps.length < 100000) requestAnimationFrame(tick); };
    requestAnimationFrame(tick);
  });
  await page.click('[data-testid=run-button]');
  await page.waitForFunction(() => !document.querySelector('[data-testid=cancel-button]').disabled);
  await page.waitForTimeout(1500);
  assert.equal(await page.getAttribute('[data-testid=stats]', 'data-runs'), '1', 'the long run must still be going');
  await shot(page, 'running');
  const gaps = await page.evaluate(() => window.__gaps.slice(2));
  const worst = Math.max(...gaps);
  console.log(`# while meshing: ${gaps.length} frames, longest ${worst.toFixed(1)} ms`);
  // Meshing on the main thread would leave one gap as long as the run (1.5 s here); a busy
  // machine (CI shares its two cores) can stretch single frames to 100 ms, so the bounds are
  // set between the two.
  assert.ok(gaps.length >= 20, `only ${gaps.length} frames in 1.5 s while the worker meshed`);
  assert.ok(worst < 400, `a frame took ${worst} ms while the worker meshed`);
  const t0 = Date.now();
  await page.click('[data-testid=cancel-button]');
  await page.waitForFunction(() => /Cancelled/.test(document.getElementById('status').textContent), null, { timeout: 2000 });
  console.log(`# cancel took effect in ${Date.now() - t0} ms`);
  assert.equal(await page.getAttribute('[data-testid=stats]', 'data-runs'), '1', 'a cancelled run leaves no result');
  assert.equal(await page.isDisabled('[data-testid=cancel-button]'), true);
  await page.selectOption('[data-testid=mode-select]', 'acute');
  await page.fill('#maxArea', '0');
  await page.fill('#maxSteiner', '0');
  const r = await runAndWait(page);
  assertCertifiedAcute(r, 'after cancel');
  assert.deepEqual(errors, []);
  await context.close();
});

test('the progress bar only grows while a run goes (the phases before refinement leave it indeterminate)', async () => {
  const { page, errors, context } = await open('?sample=turkey&mode=acute');
  // Every value the bar takes (-1: indeterminate), seen by an observer, not by sampling.
  await page.evaluate(() => {
    const bar = document.getElementById('progress');
    window.barValues = [];
    new MutationObserver(() => {
      window.barValues.push(bar.hasAttribute('value') ? bar.value : -1);
    }).observe(bar, { attributes: true, attributeFilter: ['value'] });
  });
  await runAndWait(page);
  const values = await page.evaluate(() => window.barValues);
  const shown = values.filter((v) => v >= 0);
  assert.ok(shown.length >= 2, `the bar took ${values.length} values: ${values}`);
  shown.forEach((v, i) => assert.ok(i === 0 || v >= shown[i - 1], `the bar went back from ${shown[i - 1]} to ${v}: ${values}`));
  assert.deepEqual(errors, []);
  await context.close();
});

test('a 100,000-triangle mesh pans and zooms smoothly', async () => {
  // Turkey refined for quality under an area bound (km^2): about 100,000 triangles.
  const { page, errors, context } = await open('?sample=turkey&mode=quality&maxArea=12');
  const r = await result(page);
  assert.ok(r.triangles >= 90000, `only ${r.triangles} triangles`);
  await page.waitForTimeout(600);
  const fullMs = Number(await page.getAttribute('[data-testid=mesh-canvas]', 'data-render-ms'));
  const box = await page.$eval('[data-testid=mesh-canvas]', (c) => { const b = c.getBoundingClientRect(); return [b.left, b.top, b.width, b.height]; });
  await page.evaluate(() => {
    window.__gaps = [];
    let last = performance.now();
    const tick = (t) => { window.__gaps.push(t - last); last = t; if (!window.__stop) requestAnimationFrame(tick); };
    requestAnimationFrame(tick);
  });
  const cx = box[0] + box[2] / 2, cy = box[1] + box[3] / 2;
  await page.mouse.move(cx, cy);
  await page.mouse.down();
  for (let i = 1; i <= 30; i++) { await page.mouse.move(cx + 4 * i, cy + 2 * i); await page.waitForTimeout(16); }
  await page.mouse.up();
  for (let i = 0; i < 10; i++) { await page.mouse.wheel(0, -80); await page.waitForTimeout(16); }
  const gaps = await page.evaluate(() => { window.__stop = true; return window.__gaps.slice(1); });
  gaps.sort((a, b) => a - b);
  const p95 = gaps[Math.floor(0.95 * (gaps.length - 1))];
  console.log(`# ${r.triangles} triangles: full frame ${fullMs} ms; while panning/zooming ${gaps.length} frames, ` +
    `median ${gaps[gaps.length >> 1].toFixed(1)} ms, p95 ${p95.toFixed(1)} ms, longest ${gaps[gaps.length - 1].toFixed(1)} ms`);
  assert.ok(p95 < 50, `p95 frame ${p95} ms while panning`);
  await page.waitForTimeout(600);
  await shot(page, 'big-mesh-zoomed');
  assert.deepEqual(errors, []);
  await context.close();
});

// --- the max-angle dial (acute mode) ------------------------------------------------------------

const histogramMarks = (page) => page.$eval('[data-testid=histogram]', (c) => ({ ...c.dataset }));

test('max angle: the control sets the run\'s bound, the histogram marks it, the URL keeps it', async () => {
  const { page, errors, context } = await open('?text=Hi&maxAngle=85');
  const r = await result(page);
  assert.deepEqual(r.options, { mode: 'acute', maxAngle: 85 });
  assert.equal(r.targetMet, true, `85 is met on "Hi" (${JSON.stringify(r)})`);
  assert.equal(r.angleBound, 85);
  assert.ok(r.maxAngle < 85 + 1e-9, `max angle ${r.maxAngle}`);
  assert.match(await page.textContent('#status'), /Every angle below 85°/);
  let h = await histogramMarks(page);
  assert.equal(h.bound, '85');
  assert.equal(h.over, '0', 'a met bound leaves no angle at or above it');
  assert.equal(Number(h.max), r.maxAngle);
  // Turned to 88 on the page: the next run asks for 88, and so does the link.
  await page.fill('[data-testid=max-angle]', '88');
  await page.dispatchEvent('[data-testid=max-angle]', 'change');
  assert.match(page.url(), /maxAngle=88/);
  const s = await runAndWait(page);
  assert.deepEqual(s.options, { mode: 'acute', maxAngle: 88 });
  assert.equal(s.angleBound, s.targetMet ? 88 : 90);
  h = await histogramMarks(page);
  assert.equal(h.bound, '88');
  assert.equal(Number(h.over) === 0, s.targetMet, 'red (over the bound) exactly when the bound was missed');
  // Outside acute mode the dial is off and nothing is sent.
  await page.selectOption('[data-testid=mode-select]', 'nonobtuse');
  assert.equal(await page.isDisabled('[data-testid=max-angle]'), true);
  assert.deepEqual((await runAndWait(page)).options, { mode: 'nonobtuse' });
  assert.equal((await histogramMarks(page)).bound, '');
  assert.deepEqual(errors, []);
  await context.close();
});

test('max angle: the input\'s floor shows beside the dial before a run, as the mesher measures it', async () => {
  const dir = mkdtempSync(join(tmpdir(), 'acutemesh-web-'));
  // A wedge with a 20-degree corner: floor 90 - 20/2 = 80.
  const t = (20 * Math.PI) / 180;
  const wedge = join(dir, 'wedge.poly');
  writeFileSync(wedge, `3 2 0 0\n1 0 0\n2 10 0\n3 ${10 * Math.cos(t)} ${10 * Math.sin(t)}\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n`);
  const { page, errors, context } = await open('?text=Hi');
  await upload(page, join(root, 'tests', 'data', 'A.poly'));
  // Inside A.poly the smallest corner is 90 (the apex's 45 degrees is outside): floor 72.
  await page.waitForFunction(() => document.getElementById('angleFloor').dataset.from === 'input');
  assert.match(await page.textContent('[data-testid=angle-floor]'), /^floor 72° \(smallest corner 90°\)/);
  await upload(page, wedge);
  await page.waitForFunction(() => /smallest corner 20°/.test(document.getElementById('angleFloor').textContent));
  const shown = Number(await page.getAttribute('[data-testid=angle-floor]', 'data-floor'));
  assert.ok(Math.abs(shown - 80) < 1e-9, `floor ${shown}`);
  // Asking for less than the floor is said at once, beside the dial.
  await page.fill('[data-testid=max-angle]', '75');
  await page.dispatchEvent('[data-testid=max-angle]', 'change');
  assert.match(await page.textContent('[data-testid=angle-floor]'), /75° cannot be met/);
  assert.equal(await page.getAttribute('[data-testid=angle-floor]', 'class'), 'hint floor warn');
  const r = await runAndWait(page);
  assert.ok(Math.abs(r.angleFloor - shown) < 1e-9, `the page measured ${shown}, the mesher ${r.angleFloor}`);
  assert.equal(await page.getAttribute('[data-testid=angle-floor]', 'data-from'), 'run');
  assert.equal((await histogramMarks(page)).floor, String(r.angleFloor));
  assert.deepEqual(errors, []);
  await context.close();
});

test('max angle: a bound that was not met is said in words, with what was reached', async () => {
  // "Hi" in Pagella: its corners allow no better than 72, so 65 cannot be met by any mesher.
  const { page, errors, context } = await open('?text=Hi&maxAngle=65');
  const r = await result(page);
  assert.equal(r.options.maxAngle, 65);
  assert.ok(r.angleFloor > 65, `floor ${r.angleFloor}`);
  assert.equal(r.targetMet, false);
  const status = await page.textContent('#status');
  const reached = /Target not met: the bound of 65° was not met, below what the input allows: the largest angle is (\d+\.\d{3})°/.exec(status);
  assert.ok(reached, `status: ${status}`);
  assert.equal(Number(reached[1]), Math.trunc(r.maxAngle * 1000) / 1000);
  assert.match(status, new RegExp(`this input's floor: ${Number(r.angleFloor.toFixed(1))}°`));
  assert.equal(await page.getAttribute('#status', 'class'), 'status warn');
  const bound = await page.$$eval('#stats dt', (dts) => {
    const dt = dts.find((d) => d.textContent === 'Bound');
    return dt && [dt.nextElementSibling.textContent, dt.nextElementSibling.className];
  });
  assert.deepEqual(bound, ['not met', 'no']);
  // The histogram draws the angles at or above the bound in red: here every triangle's largest.
  const h = await histogramMarks(page);
  assert.equal(h.bound, '65');
  assert.ok(Number(h.over) >= r.triangles, `${h.over} angles marked over the bound, ${r.triangles} triangles`);
  await page.$eval('section[aria-labelledby=h-result]', (s) => s.scrollIntoView());
  await shot(page, 'max-angle-missed');
  assert.deepEqual(errors, []);
  await context.close();
});

test('max angle auto: sent as \'auto\', and the bound reached is shown', async () => {
  const { page, errors, context } = await open('?text=Hi&maxAngle=auto', { width: 390, height: 844 });
  const r = await result(page);
  assert.equal(await page.isChecked('[data-testid=max-angle-auto]'), true);
  assert.deepEqual(r.options, { mode: 'acute', maxAngle: 'auto' });
  assert.equal(await page.isDisabled('[data-testid=max-angle]'), true, 'auto leaves no number to set');
  // Auto goes below the acute mesh's 90 (the text's floor is 72).
  assert.ok(r.certified && Number.isFinite(r.angleBound) && r.angleBound < 89, JSON.stringify(r));
  assert.ok(r.maxAngle < r.angleBound + 1e-9);
  assert.match(await page.textContent('#status'), new RegExp(`auto: every angle below ${Number(r.angleBound.toFixed(1))}°`));
  assert.equal((await histogramMarks(page)).bound, String(r.angleBound));
  await shot(page, 'max-angle-auto-phone');
  assert.deepEqual(errors, []);
  await context.close();
});
