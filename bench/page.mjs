// `npm run bench:page`: the web page on a large map, as a GIS user would drop it (issue 25):
// a generated archipelago GeoJSON of about 100,000 vertices (49 islands, each a polygon's
// edges split again and again at points pushed off their middles, a fixed seed; lon/lat near
// 55 N) uploaded to the page in Debian's Chromium (playwright-core, as tests/web), meshed in
// the page's default mode (acute) by its worker. Measured: the wall time from pressing Mesh
// to the result, the progress bar's value every quarter second (it must move steadily), how
// long the page's main thread was blocked at most (a 20 ms timer in the page: the largest gap
// between its ticks), and where the main thread spent its time (a CPU profile). Writes
// bench/results/page-YYYY-MM-DD.md and prints it. ISLANDS=n changes the size.
import { writeFileSync, mkdtempSync, existsSync } from 'node:fs';
import { execSync } from 'node:child_process';
import { tmpdir, cpus, loadavg } from 'node:os';
import { join } from 'node:path';
import { root, startServer, launch, openPage, waitForRun, result } from '../tests/web/browser.mjs';

let seed = 7;
const random = () => { seed = (seed * 1103515245 + 12345) % 2147483648; return seed / 2147483648 * 2 - 1; };
function island(cx, cy, radius, corners, levels) {
  let ring = [];
  for (let i = 0; i < corners; i++) {
    const a = 2 * Math.PI * i / corners;
    ring.push([cx + radius * Math.cos(a), cy + radius * Math.sin(a)]);
  }
  for (let level = 0; level < levels; level++) {
    const finer = [];
    for (let i = 0; i < ring.length; i++) {
      const p = ring[i], q = ring[(i + 1) % ring.length], off = 0.12 * random();
      finer.push(p, [(p[0] + q[0]) / 2 - off * (q[1] - p[1]), (p[1] + q[1]) / 2 + off * (q[0] - p[0])]);
    }
    ring = finer;
  }
  return [...ring, ring[0]];  // (GeoJSON rings repeat their first point)
}

const islands = Number(process.env.ISLANDS || 49);
const side = Math.ceil(Math.sqrt(islands));
const features = Array.from({ length: islands }, (_, i) => ({
  type: 'Feature', properties: {},
  geometry: { type: 'Polygon', coordinates: [island(10 + 0.3 * (i % side), 55 + 0.3 * Math.floor(i / side), 0.1, 8, 8)] },
}));
const vertices = islands * 8 * 256;
const path = join(mkdtempSync(join(tmpdir(), 'acutemesh-page-')), 'archipelago.geojson');
writeFileSync(path, JSON.stringify({ type: 'FeatureCollection', features }));

const loadStart = loadavg().map((x) => x.toFixed(2)).join(' ');
const server = await startServer();
const { browser, close } = await launch();
const { page, errors } = await openPage(browser, server.url);
await waitForRun(page, 1, 60000);
await page.setInputFiles('[data-testid=file-input]', path);
await page.waitForFunction(() => /Press Mesh\./.test(document.getElementById('source').textContent), null, { timeout: 60000 });
await page.evaluate(() => {
  window.benchGaps = [];
  let last = performance.now();
  setInterval(() => { const now = performance.now(); window.benchGaps.push([now, now - last]); last = now; }, 20);
});
const cdp = await page.context().newCDPSession(page);
await cdp.send('Profiler.enable');
await cdp.send('Profiler.setSamplingInterval', { interval: 1000 });
await cdp.send('Profiler.start');
const pressed = await page.evaluate(() => performance.now());
const t0 = Date.now();
await page.click('[data-testid=run-button]');
let finished = false;
const done = waitForRun(page, 2, 600000).then(() => { finished = true; });
const bar = [];
while (!finished) {
  const v = await page.evaluate(() => {
    const p = document.getElementById('progress');
    return p.hidden ? null : p.hasAttribute('value') ? p.value : -1;
  });
  if (v !== null) bar.push([(Date.now() - t0) / 1000, v]);
  await new Promise((r) => setTimeout(r, 250));
}
await done;
const seconds = (Date.now() - t0) / 1000;
const { profile } = await cdp.send('Profiler.stop');
const r = await result(page);
const gaps = (await page.evaluate(() => window.benchGaps)).filter(([at]) => at >= pressed);
await close();
server.close();

// Main-thread time by function (self time), busiest first.
const byId = new Map(profile.nodes.map((n) => [n.id, n]));
const self = new Map();
profile.samples.forEach((id, i) => {
  const f = byId.get(id).callFrame;
  if (['(idle)', '(program)', '(garbage collector)'].includes(f.functionName)) return;
  const key = `${f.functionName || '(anonymous)'} ${f.url ? `${f.url.split('/').pop()}:${f.lineNumber + 1}` : '(native)'}`;
  self.set(key, (self.get(key) || 0) + (profile.timeDeltas[i] || 0) / 1000);
});
const busiest = [...self].sort((a, b) => b[1] - a[1]).slice(0, 8);
const worst = gaps.reduce((w, g) => (g[1] > w[1] ? g : w), [0, 0]);
const blockedAt = (worst[0] - pressed) / 1000;
const longGaps = gaps.filter(([, g]) => g > 100);
// The bar: the longest stretch it stood still while the run went on, and its value halfway.
let still = 0, since = bar.length ? bar[0][0] : 0, last = -2, halfway = null;
for (const [t, v] of bar) {
  if (v > last) { since = t; last = v; }
  still = Math.max(still, t - since);
  if (halfway === null && t >= seconds / 2) halfway = v;
}
const commit = execSync('git rev-parse --short HEAD', { cwd: root }).toString().trim();
const dirty = execSync('git status --porcelain core web wasm', { cwd: root }).toString().trim() ? ' + uncommitted changes' : '';
const date = new Date().toISOString().slice(0, 10);
const lines = [
  `# The page on a 100,000-vertex map (${date})`,
  '',
  'Made by `npm run bench:page` (bench/page.mjs); issue 25.',
  '',
  `Machine: ${cpus()[0].model}, ${cpus().length} cores; Debian's Chromium, headless, through playwright-core. acutemesh ${commit}${dirty}. Load average at the start: ${loadStart}.`,
  '',
  '| input | mode | wall s | triangles | Steiner | result | progress bar | main thread blocked at most |',
  '|---|---|---:|---:|---:|---|---|---|',
  `| ${islands} islands, ${vertices.toLocaleString('en')} vertices (GeoJSON, lon/lat) | ${r.mode} | ${seconds.toFixed(1)} | ${r.triangles.toLocaleString('en')} | ${r.steiner.toLocaleString('en')} | ${r.status}${r.certified ? ', certified' : ''} | ${bar.length} readings; ${halfway === null ? '?' : halfway.toFixed(2)} halfway; stood still at most ${still.toFixed(1)} s | ${worst[1].toFixed(0)} ms, ${blockedAt.toFixed(1)} s after Mesh was pressed (${longGaps.length} gaps over 100 ms) |`,
  '',
  `- Main thread, self time by function during the run (idle, "(program)" and GC left out): ${busiest.map(([k, ms]) => `${k} ${ms.toFixed(0)} ms`).join('; ')}.`,
  `- Progress readings (s: value): ${bar.filter((_, i) => i % 8 === 0).map(([t, v]) => `${t.toFixed(1)}: ${v.toFixed(2)}`).join(', ')}.`,
  `- Page errors: ${errors.length ? errors.join('; ') : 'none'}.`,
  '- The mesh is made in the page\'s worker (WebAssembly, one thread: the parts of the domain one after another); the main thread receives it and draws it.',
];
let out = join(root, 'bench', 'results', `page-${date}.md`);
for (let k = 2; existsSync(out); k++) out = join(root, 'bench', 'results', `page-${date}-${k}.md`);
writeFileSync(out, `${lines.join('\n')}\n`);
console.log(lines.join('\n'));
console.log(`\nbench:page: wrote ${out}`);
