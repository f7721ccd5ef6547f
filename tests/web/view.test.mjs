// What the canvas shows: Steiner dots sized by the zoom and their triangles, the fit framing
// the main part of the input, and the smaller things a user noticed (the link and a file,
// missing glyphs, a dropped drawing, the SVG download's colours, the histogram's legend).
// Run: node --test tests/web/.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { root, artifacts, pageSession, openPage, waitForRun, result, runAndWait } from './browser.mjs';

const { open, url, browser } = pageSession({ firstRunTimeout: 60000 });

// Until the mesh is on the canvas and its frame is whole (a large one is built and drawn in
// slices, between frames).
function drawn(page) {
  return page.waitForFunction(() => {
    const c = document.getElementById('view');
    return c.dataset.content === 'mesh' && c.dataset.frame === 'done';
  });
}

// Once the frame is whole: the share of the canvas in the Steiner dots' colour, and the dots
// drawn as [count, smallest radius, largest radius] in CSS pixels.
async function steinerDots(page) {
  await drawn(page);
  return page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(() => {
    const c = document.getElementById('view');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - 194) + Math.abs(d[i + 1] - 24) + Math.abs(d[i + 2] - 91) < 60) n++;
    resolve({ share: n / (d.length / 4), dots: (c.dataset.steiner || '').split(',').map(Number) });
  }))));
}

async function zoomIn(page, presses) {
  await page.focus('[data-testid=mesh-canvas]');
  for (let i = 0; i < presses; i++) await page.keyboard.press('+');
  await page.waitForTimeout(400);  // the gesture is over: the full frame starts
  await drawn(page);
}

test('Steiner dots are sized by their triangles and the zoom: they never swamp a dense mesh', async () => {
  // About 100,000 triangles: at fit no dot is drawn, zoomed in (x3.8) they cover little.
  const big = await open('?sample=turkey&mode=quality&maxArea=12');
  let s = await steinerDots(big.page);
  assert.equal(s.dots[0], 0, 'dots drawn over a dense mesh at fit');
  await zoomIn(big.page, 6);
  s = await steinerDots(big.page);
  assert.ok(s.share < 0.06, `the dots cover ${(100 * s.share).toFixed(1)}% of the view`);
  assert.ok(s.dots[0] > 1000, `${s.dots[0]} dots`);
  await big.page.screenshot({ path: join(artifacts, 'steiner-dense-zoomed.png') });
  assert.deepEqual(big.errors, []);
  await big.context.close();
  // A coarse mesh: dots of several sizes at fit; zoomed in, all grow, up to a cap.
  const coarse = await open('');
  const fit = await steinerDots(coarse.page);
  assert.ok(fit.dots[0] > 50 && fit.dots[1] < fit.dots[2], `at fit: ${fit.dots}`);
  await zoomIn(coarse.page, 8);
  const zoomed = await steinerDots(coarse.page);
  assert.ok(zoomed.dots[1] > fit.dots[1], `smallest dot ${fit.dots[1]} -> ${zoomed.dots[1]} px`);
  assert.ok(zoomed.dots[2] <= 3, `largest dot ${zoomed.dots[2]} px`);
  assert.deepEqual(coarse.errors, []);
  await coarse.context.close();
});

test('a large mesh arrives in slices: the page answers meanwhile, the picture ends whole, newer input wins', async () => {
  const { page, errors, context } = await open('?sample=turkey&mode=quality&maxArea=12');
  await drawn(page);
  // What the canvas says it shows, and the longest gap of a 10 ms timer, while Mesh runs again.
  const watch = () => page.evaluate(() => {
    const c = document.getElementById('view');
    window.shown = [];
    window.longestGap = 0;
    let last = performance.now();
    window.ticker = setInterval(() => {
      const now = performance.now();
      window.longestGap = Math.max(window.longestGap, now - last);
      last = now;
    }, 10);
    const note = () => {
      const state = `${c.dataset.content}/${c.dataset.frame}`;
      if (window.shown.at(-1) !== state) window.shown.push(state);
      if (window.onShown) window.onShown(state);
    };
    new MutationObserver(note).observe(c, { attributes: true, attributeFilter: ['data-content', 'data-frame'] });
  });
  await watch();
  const triangles = (await runAndWait(page)).triangles;
  assert.ok(triangles > 50000, `${triangles} triangles: not a large mesh`);
  await drawn(page);
  const { shown, gap } = await page.evaluate(() => ({ shown: window.shown, gap: window.longestGap }));
  const since = shown.slice(shown.indexOf('building/done'));
  assert.ok(since.length > 1 && since.includes('mesh/drawing') && since.at(-1) === 'mesh/done' &&
    since.slice(1).every((x) => ['building/drawing', 'mesh/drawing', 'mesh/done'].includes(x)),
  `the canvas went through ${shown.join(' -> ')}`);
  // A picture of the whole mesh: triangle colours over most of the turkey's frame.
  const coloured = await page.evaluate(() => {
    const c = document.getElementById('view');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) n += d[i] + d[i + 1] + d[i + 2] < 3 * 250;
    return n / (d.length / 4);
  });
  assert.ok(coloured > 0.2, `${(100 * coloured).toFixed(1)}% of the canvas drawn`);
  console.log(`# ${triangles} triangles arrived in slices; a 10 ms timer's longest gap ${gap.toFixed(0)} ms`);
  // Another sample chosen while the mesh is being built: its preview stays, the mesh never
  // comes back.
  await page.evaluate(() => {
    window.shown = [];
    window.onShown = (state) => {
      if (state !== 'building/done') return;
      window.onShown = null;
      const sample = document.getElementById('sample');
      sample.value = 'italy';
      sample.dispatchEvent(new Event('change'));
    };
  });
  await page.click('[data-testid=run-button]');
  await page.waitForFunction(() => /Press Mesh\./.test(document.getElementById('source').textContent), null, { timeout: 60000 });
  await page.waitForTimeout(1500);  // what a build left running would have shown by now
  const after = await page.evaluate(() => window.shown);
  assert.equal(after.at(-1).split('/')[0], 'preview', `the canvas went through ${after.join(' -> ')}`);
  assert.ok(after.includes('building/done') && !after.includes('mesh/drawing'),
    `the mesh being built was drawn after all: ${after.join(' -> ')}`);
  assert.deepEqual(errors, []);
  await context.close();
});

test('fit frames the main part: South Africa, not the Prince Edward Islands 1,700 km away', async () => {
  const { page, errors, context } = await open('?sample=south-africa');
  const [fit, extent] = await page.$eval('[data-testid=mesh-canvas]', (c) => [c.dataset.fit, c.dataset.extent].map((s) => s.split(',').map(Number)));
  const height = (b) => b[3] - b[1];
  // The islands are far south-east: the whole extent is about twice as tall as the country.
  assert.ok(height(extent) > 1.5 * height(fit), `fit ${fit}, extent ${extent}`);
  assert.ok(fit[1] > extent[1] && fit[2] < extent[2], 'the frame still reaches to the far islands');
  await page.screenshot({ path: join(artifacts, 'fit-south-africa.png') });
  // Italy's islands (Sicily, Sardinia) are part of the picture.
  await page.selectOption('#sample', 'italy');
  await page.waitForFunction(() => /Press Mesh\./.test(document.getElementById('source').textContent));
  await runAndWait(page);
  const [ifit, iextent] = await page.$eval('[data-testid=mesh-canvas]', (c) => [c.dataset.fit, c.dataset.extent].map((s) => s.split(',').map(Number)));
  assert.ok(height(ifit) >= 0.95 * height(iextent), `Italy: fit ${ifit}, extent ${iextent}`);
  assert.deepEqual(errors, []);
  await context.close();
});

test('a file is not in the link, a missing glyph and a dropped drawing are said', async () => {
  const { page, errors, context } = await open('?text=Hi%E6%BC%A2');
  assert.match(await page.textContent('#source'), /TeX Gyre Pagella has no glyph for "漢": left out\./);
  const withGlyph = await result(page);
  await page.fill('[data-testid=text-input]', 'Hi');
  const plain = await runAndWait(page);
  assert.equal(withGlyph.inputVertices, plain.inputVertices, 'the missing glyph\'s box was meshed');
  // A file: the link cannot carry it, and the page says so.
  await page.setInputFiles('[data-testid=file-input]', join(root, 'tests', 'data', 'A.poly'));
  await page.waitForFunction(() => /Press Mesh\./.test(document.getElementById('source').textContent));
  assert.match(await page.textContent('#source'), /A link to this page cannot carry the file: it opens the default text\./);
  // A symmetric bow-tie has no area: dropped, with the reason.
  await page.click('#draw');
  const press = async (key, n = 1) => { for (let i = 0; i < n; i++) await page.keyboard.press(key); };
  await press('ArrowLeft', 5); await press('ArrowUp', 5); await press(' ');
  await press('ArrowRight', 10); await press('ArrowDown', 10); await press(' ');
  await press('ArrowUp', 10); await press(' ');
  await press('ArrowLeft', 10); await press('ArrowDown', 10); await press(' ');
  await press('Enter');
  assert.match(await page.textContent('#source'), /drawing: 0 rings/);
  const s = await page.$eval('#status', (e) => [e.textContent, e.className]);
  assert.match(s[0], /The ring just closed was dropped: it encloses no area \(it crosses itself so that its halves cancel/);
  assert.equal(s[1], 'status warn');
  assert.deepEqual(errors, []);
  await context.close();
});

test('the SVG download is coloured like the view; the histogram\'s grey bars are in the legend; no readback warning', async () => {
  const warnings = [];
  const p = await openPage(browser(), url('?text=Hi'));
  p.page.on('console', (m) => { if (m.type() === 'warning') warnings.push(m.text()); });
  const { page, errors, context } = p;
  await waitForRun(page, 1);
  const r = await result(page);
  const [dl] = await Promise.all([page.waitForEvent('download'), page.click('[data-testid=download-svg]')]);
  const svg = readFileSync(await dl.path(), 'utf8');
  const fills = [...svg.matchAll(/<path data-class="[^"]+" fill="(#[0-9a-f]{6})"/g)].map((m) => m[1]);
  const legend = await page.$$eval('#legend i', (is) => is.map((i) => i.style.background));
  assert.ok(fills.length >= 3, `${fills.length} colours in the SVG`);
  const hex = (rgb) => `#${rgb.match(/\d+/g).map((v) => Number(v).toString(16).padStart(2, '0')).join('')}`;
  for (const f of fills) assert.ok(legend.filter(Boolean).map(hex).includes(f), `${f} is not a legend colour`);
  assert.equal((svg.match(/<circle /g) || []).length, r.steiner, 'one dot per Steiner point');
  // Well-formed XML (the class "< 70°" escaped in its attribute), so viewers open it.
  const parseError = await page.evaluate((text) => new DOMParser().parseFromString(text, 'image/svg+xml')
    .querySelector('parsererror')?.textContent ?? '', svg);
  assert.equal(parseError, '');
  // The grey of the bars below 60 degrees has its legend entry.
  const small = await page.$eval('#legend .mark-small', (e) => [e.textContent, e.querySelector('i').style.background]);
  assert.match(small[0], /angles < 60°/);
  assert.equal(hex(small[1]), '#8a94a6');
  await zoomIn(page, 4);
  assert.deepEqual(warnings.filter((w) => /willReadFrequently|readback/.test(w)), []);
  assert.deepEqual(errors, []);
  await context.close();
});
