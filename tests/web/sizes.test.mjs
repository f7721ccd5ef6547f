// Sizes and regions on the page: max edge and grading go to the mesher as plain numbers, the
// link keeps them, bad values are refused like the other fields', the verdict says whether the
// sizes were met, and a sample with regional attributes is drawn in one colour per region.
// The mesh is read back from the page's own downloads. Run: node --test tests/web/.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { artifacts, pageSession, result, runAndWait, status, waitForRun } from './browser.mjs';
import { join } from 'node:path';

const { open } = pageSession();

async function download(page, testid) {
  const [dl] = await Promise.all([page.waitForEvent('download'), page.click(`[data-testid=${testid}]`)]);
  return readFileSync(await dl.path(), 'utf8');
}

// The longest edge of every triangle of the JSON download.
async function longestEdges(page) {
  const j = JSON.parse(await download(page, 'download-json'));
  return j.triangles.map((t) => Math.max(...[0, 1, 2].map((k) => {
    const [ax, ay] = j.vertices[t[k]], [bx, by] = j.vertices[t[(k + 1) % 3]];
    return Math.hypot(ax - bx, ay - by);
  })));
}

// The stats' Sizes row.
const sizesRow = (page) => page.$eval('#stats', (dl) =>
  [...dl.querySelectorAll('dt')].find((dt) => dt.textContent === 'Sizes')?.nextElementSibling.textContent ?? 'no Sizes row');

test('max edge: every triangle\'s longest edge within it, the verdict says so, the link keeps it', async () => {
  const { page, errors, context } = await open('?sample=plate&mode=acute');
  const before = Math.max(...await longestEdges(page));
  const maxEdge = 5;
  assert.ok(before > maxEdge, `without a max edge the plate already has every edge below ${maxEdge} (${before})`);
  assert.equal((await result(page)).sizeRatio <= 1, true, 'the region\'s area bound is a size, met');

  await page.fill('[data-testid=max-edge]', String(maxEdge));
  await page.dispatchEvent('[data-testid=max-edge]', 'change');
  await page.fill('[data-testid=grading]', '0.3');
  await page.dispatchEvent('[data-testid=grading]', 'change');
  assert.match(page.url(), /maxEdge=5/);
  assert.match(page.url(), /grading=0\.3/);
  const r = await runAndWait(page);
  assert.deepEqual(r.options, { mode: 'acute', maxAngle: 90, maxEdge: 5, grading: 0.3 });
  assert.equal(r.certified, true);
  assert.ok(r.sizeRatio > 0 && r.sizeRatio <= 1, `sizeRatio ${r.sizeRatio}`);
  const edges = await longestEdges(page);
  assert.equal(edges.length, r.triangles);
  const worst = Math.max(...edges);
  assert.ok(worst <= maxEdge, `a triangle's longest edge is ${worst} > ${maxEdge}`);
  const s = await status(page);
  assert.equal(s.kind, '');
  assert.match(s.text, /Sizes met: every edge at most 5, every region's area bound \(ratio 0\.\d\d\)\./);
  assert.match(await sizesRow(page), /^met \(0\.\d\d\)$/);
  await page.screenshot({ path: join(artifacts, 'sizes-plate-max-edge.png') });

  // The link keeps them (a link's values are read like the other fields': the next test).
  assert.equal(new URL(page.url()).searchParams.get('maxEdge'), '5');
  assert.equal(new URL(page.url()).searchParams.get('grading'), '0.3');

  // Sizes beyond the Steiner budget: the mesh meets the angle target alone, and the page says
  // the sizes were missed, by how much.
  await page.fill('[data-testid=max-edge]', '1');
  await page.fill('#maxSteiner', '300');
  const missed = await runAndWait(page);
  assert.ok(missed.sizeRatio > 1, `sizeRatio ${missed.sizeRatio}`);
  const m = await status(page);
  assert.equal(m.kind, 'warn');
  assert.match(m.text, /^Meshed in .*: Target not met \(the sizes asked for need more Steiner points/);
  assert.match(m.text, new RegExp(`Sizes missed: ratio ${(Math.ceil(missed.sizeRatio * 100) / 100).toFixed(2)} \\(`));
  assert.match(await sizesRow(page), /^missed \(\d+\.\d\d\)$/);
  assert.deepEqual(errors, []);
  await context.close();
});

// The slider's position of a max edge: 0..100 from extent/1000 to extent/4, log scale.
const sliderPos = (v, lo, hi) => Math.round(100 * Math.log(v / lo) / Math.log(hi / lo));

test('the max edge slider: arrows write a rounded max edge the next mesh keeps, typing moves it, a new input rescales it', async () => {
  const { page, errors, context } = await open('?sample=plate');
  const slider = '[data-testid=max-edge-slider]';
  const attrs = () => page.$eval(slider, (s) => ({ value: Number(s.value), min: Number(s.dataset.min), max: Number(s.dataset.max),
    text: s.getAttribute('aria-valuetext'), label: s.getAttribute('aria-label'), disabled: s.disabled }));
  let a = await attrs();
  // The plate is 120 mm wide: the scale runs from 0.12 to 30, then none.
  assert.deepEqual(a, { value: 101, min: 0.12, max: 30, text: 'none', label: 'Max edge', disabled: false });
  assert.equal(await page.getByRole('slider', { name: 'Max edge' }).count(), 1);

  await page.focus(slider);
  for (let i = 0; i < 30; i++) await page.keyboard.press('ArrowLeft');
  const text = await page.inputValue('[data-testid=max-edge]');
  const v = Number(text);
  assert.ok(v >= a.min && v <= a.max, `the slider wrote ${JSON.stringify(text)}, outside ${a.min}..${a.max}`);
  assert.match(text, /^\d*\.?\d+$/);
  assert.ok(Number(v.toPrecision(3)) === v, `${text} has more than 3 significant digits`);
  a = await attrs();
  assert.equal(a.value, 71);
  assert.ok(Math.abs(sliderPos(v, a.min, a.max) - a.value) <= 1, `${text} is not at position ${a.value}`);
  assert.equal(a.text, `${text} units`);
  assert.equal(new URL(page.url()).searchParams.get('maxEdge'), text, 'the link does not keep the slider\'s value');
  const r = await runAndWait(page);
  assert.equal(r.options.maxEdge, v);
  const worst = Math.max(...await longestEdges(page));
  assert.ok(worst <= v, `a triangle's longest edge is ${worst} > ${v}`);

  // Typing moves it; an empty field is none, at the right end.
  await page.fill('[data-testid=max-edge]', '0.5');
  a = await attrs();
  assert.equal(a.value, sliderPos(0.5, 0.12, 30));
  assert.equal(a.text, '0.5 units');
  await page.fill('[data-testid=max-edge]', '');
  assert.deepEqual([(await attrs()).value, (await attrs()).text], [101, 'none']);

  // A new input: the scale follows its size, the field keeps its value.
  await page.fill('[data-testid=max-edge]', '2');
  await page.fill('[data-testid=text-input]', 'Hi');
  await page.waitForFunction(() => document.getElementById('maxEdgeSlider').dataset.max !== '30');
  a = await attrs();
  assert.equal(await page.inputValue('[data-testid=max-edge]'), '2');
  assert.ok(a.max > 30 && Math.abs(a.max / a.min - 250) < 1, `the text's scale ${a.min}..${a.max}`);
  assert.equal(a.value, sliderPos(2, a.min, a.max));

  // Constrained Delaunay: off like the field.
  await page.selectOption('[data-testid=mode-select]', 'cdt');
  assert.equal(await page.isDisabled(slider), true);
  await page.selectOption('[data-testid=mode-select]', 'acute');
  assert.equal(await page.isDisabled(slider), false);
  await page.screenshot({ path: join(artifacts, 'sizes-slider.png') });
  assert.deepEqual(errors, []);
  await context.close();
});

test('max edge and grading: negative or not a number is refused at the field, in a link falls back to none', async () => {
  const { page, errors, context } = await open('?text=Hi&maxEdge=-2&grading=abc');
  const r = await result(page);
  assert.deepEqual(r.options, { mode: 'acute', maxAngle: 90 }, 'a bad value in the link was sent');
  assert.equal(await page.inputValue('[data-testid=max-edge]'), '');
  const note = await page.textContent('[data-testid=link-note]');
  assert.match(note, /The link's maxEdge=-2 is out of range \(max edge: 0 \(none\) or more\): none is used instead\./);
  assert.match(note, /The link's grading=abc is out of range \(grading: 0 \(none\) or more\): none is used instead\./);

  await page.fill('[data-testid=max-edge]', '-1');
  await page.dispatchEvent('[data-testid=max-edge]', 'input');
  assert.equal(await page.getAttribute('[data-testid=max-edge]', 'aria-invalid'), 'true');
  assert.equal(await page.textContent('[data-testid=form-error]'), 'Max edge -1 is out of range: it must be 0 (none) or more.');
  await page.dispatchEvent('[data-testid=max-edge]', 'change');
  assert.doesNotMatch(page.url(), /maxEdge/, 'an invalid value went into the link');
  await page.click('[data-testid=run-button]');
  let s = await status(page);
  assert.equal(s.kind, 'error');
  assert.match(s.text, /^Not meshed: Max edge -1 is out of range/);
  assert.equal(await page.evaluate(() => document.activeElement.id), 'maxEdge');
  await page.fill('[data-testid=max-edge]', '');

  // Text: a number field holds no letters, but "1e" is not a number (validity.badInput).
  await page.focus('[data-testid=grading]');
  await page.keyboard.type('1e');
  await page.dispatchEvent('[data-testid=grading]', 'input');
  assert.equal(await page.getAttribute('[data-testid=grading]', 'aria-invalid'), 'true');
  assert.equal(await page.textContent('[data-testid=form-error]'), 'Grading: not a number; it must be 0 (none) or more (0.2 to 0.5 is usual).');
  await page.click('[data-testid=run-button]');
  s = await status(page);
  assert.match(s.text, /^Not meshed: Grading: not a number/);
  assert.equal(await page.getAttribute('[data-testid=stats]', 'data-runs'), '1', 'an invalid form was meshed');

  await page.fill('[data-testid=grading]', '');
  await page.dispatchEvent('[data-testid=grading]', 'input');
  assert.equal(await page.isHidden('[data-testid=form-error]'), true);
  // In constrained Delaunay mode nothing is refined: the fields are off and not sent.
  await page.selectOption('[data-testid=mode-select]', 'cdt');
  assert.equal(await page.isDisabled('[data-testid=max-edge]'), true);
  assert.equal(await page.isDisabled('[data-testid=grading]'), true);
  assert.equal(await page.isDisabled('[data-testid=max-edge-slider]'), true);
  assert.deepEqual(errors, []);
  await context.close();
});

// Per palette colour (exact fill, so interior pixels only), its share of the canvas.
async function colourShares(page) {
  await page.waitForFunction(() => document.getElementById('view').dataset.frame === 'done');
  return page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(() => {
    const c = document.getElementById('view');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    const colors = c.dataset.colors.split(',');
    const rgb = colors.map((h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16)));
    const n = new Array(colors.length).fill(0);
    for (let i = 0; i < d.length; i += 4) {
      const k = rgb.findIndex(([r, g, b]) => Math.abs(d[i] - r) + Math.abs(d[i + 1] - g) + Math.abs(d[i + 2] - b) < 6);
      if (k >= 0) n[k]++;
    }
    resolve({ fill: c.dataset.fill, colors, shares: n.map((k) => k / (d.length / 4)) });
  }))));
}

test('the regions sample: one colour per region, a legend that says so, area bounds kept, a toggle back to angles', async () => {
  const { page, errors, context } = await open('?sample=plate');
  const r = await result(page);
  assert.equal(r.regions, 3);
  assert.deepEqual(r.regionAttributes, [1, 2, 3]);
  assert.equal(r.certified, true);
  const regions = await colourShares(page);
  assert.equal(regions.fill, 'regions');
  assert.deepEqual(regions.colors, ['#56b4e9', '#e69f00', '#009e73']);
  // Steel (left, 80 x 80 less the inclusion), aluminium (40 x 80 less the hole), the inclusion
  // (r = 16): each covers a visible share of the canvas in its own colour.
  for (const [k, share] of regions.shares.entries()) assert.ok(share > 0.01, `region ${k + 1}'s colour covers ${share} of the canvas`);
  assert.ok(regions.shares[0] > regions.shares[2] && regions.shares[1] > regions.shares[2], JSON.stringify(regions.shares));
  assert.equal(await page.textContent('[data-testid=regions-line]'), '3 regions, by the input\'s regional attribute');
  assert.equal(await page.getAttribute('#legend', 'aria-label'), 'Triangle colours by region');
  await page.screenshot({ path: join(artifacts, 'regions-plate.png') });

  // The inclusion's area bound (4): every triangle of attribute 3, from the .node/.ele downloads.
  const rows = (text) => text.split('\n').filter((l) => l.trim() && !l.trim().startsWith('#')).map((l) => l.trim().split(/\s+/).map(Number));
  const node = rows(await download(page, 'download-node'));
  const ele = rows(await download(page, 'download-ele'));
  const xy = new Map(node.slice(1).map((v) => [v[0], [v[1], v[2]]]));
  assert.equal(ele[0][2], 1, '.ele has one attribute per triangle');
  let inclusion = 0;
  for (const [, a, b, c, attribute] of ele.slice(1)) {
    if (attribute !== 3) continue;
    inclusion++;
    const [p, q, s] = [a, b, c].map((i) => xy.get(i));
    const area = Math.abs((q[0] - p[0]) * (s[1] - p[1]) - (s[0] - p[0]) * (q[1] - p[1])) / 2;
    assert.ok(area <= 4 + 1e-9, `an inclusion triangle has area ${area} > 4`);
  }
  assert.ok(inclusion > 150, `${inclusion} inclusion triangles for a disc of ${Math.round(Math.PI * 256)} mm² at most 4 each`);
  // The SVG download is coloured like the view: by region.
  const svg = await download(page, 'download-svg');
  for (const color of regions.colors) assert.match(svg, new RegExp(`data-class="attribute \\d" fill="${color}"`));

  await page.click('#show-regions');
  const angles = await colourShares(page);
  assert.equal(angles.fill, 'angles');
  assert.ok(!angles.colors.includes('#56b4e9'), 'the angle classes share a colour with the regions');
  assert.equal(await page.$('[data-testid=regions-line]'), null);
  // Another input: the toggle and the regions' legend go with the result.
  await page.fill('[data-testid=text-input]', 'Hi');
  await page.waitForFunction(() => document.getElementById('regions-toggle').hidden);
  assert.equal(await page.$('[data-testid=regions-line]'), null);
  assert.deepEqual(errors, []);
  await context.close();
});

// "Spend more time" (the mesher's optimize): its seconds go to the mesher and are spent, the
// mesh is certified and no larger than without them, the link keeps them, and out of range is
// refused at the field.
test('spend more time: the seconds go to the mesher, the mesh no larger, the link keeps them', async () => {
  const { page, errors, context } = await open('?sample=plate&mode=nonobtuse');
  const plain = await result(page);
  assert.equal(plain.certified, true);
  await page.fill('[data-testid=optimize]', '1');
  await page.dispatchEvent('[data-testid=optimize]', 'change');
  assert.equal(new URL(page.url()).searchParams.get('optimize'), '1');
  const r = await runAndWait(page);
  assert.deepEqual(r.options, { mode: 'nonobtuse', optimize: 1 });
  assert.equal(r.certified, true);
  assert.ok(r.milliseconds >= 1000, `the search ended after ${r.milliseconds} ms, before its second`);
  assert.ok(r.steiner <= plain.steiner, `${r.steiner} Steiner points, ${plain.steiner} without the search`);

  await page.fill('[data-testid=optimize]', '-3');
  await page.dispatchEvent('[data-testid=optimize]', 'input');
  assert.equal(await page.getAttribute('[data-testid=optimize]', 'aria-invalid'), 'true');
  assert.match(await page.textContent('[data-testid=form-error]'), /^Spend more time -3 s is out of range: it must be from 0 \(none\) to 600 seconds/);
  await page.selectOption('[data-testid=mode-select]', 'cdt');
  assert.equal(await page.isDisabled('[data-testid=optimize]'), true);
  assert.deepEqual(errors, []);
  await context.close();
});

// Cancel while spending more time keeps the best mesh the search has found: the page is
// cross-origin isolated (scripts/serve.mjs), so the worker hears the cancel through shared
// memory and answers with that mesh, certified and no larger than without the search.
test('cancel during "spend more time" shows the best mesh found', async () => {
  const { page, errors, context } = await open('?sample=plate&mode=nonobtuse');
  const plain = await result(page);
  assert.equal(await page.evaluate(() => globalThis.crossOriginIsolated), true);
  await page.fill('[data-testid=optimize]', '120');
  await page.dispatchEvent('[data-testid=optimize]', 'change');
  const before = Number(await page.getAttribute('[data-testid=stats]', 'data-runs'));
  const t0 = Date.now();
  await page.click('[data-testid=run-button]');
  await page.waitForFunction(() => /improve/.test(document.getElementById('status').textContent), null, { timeout: 30000 });
  // Cancel once the search runs, not in the polish before it (which reports "improve" too, and
  // whose mesh so far may have more points than its end, where the search starts).
  await page.waitForTimeout(2 * plain.milliseconds + 1000);
  await page.click('[data-testid=cancel-button]');
  const r = await waitForRun(page, before + 1, 10000);
  assert.ok(Date.now() - t0 < 60000, 'the cancel did not end the search');
  assert.equal(r.status, 'cancelled');
  assert.equal(r.certified, true);
  assert.ok(r.steiner <= plain.steiner, `${r.steiner} Steiner points, ${plain.steiner} without the search`);
  const line = await status(page);
  assert.match(line.text, /the search for fewer points was cancelled; the best mesh it found is shown, certified non-obtuse/);
  assert.equal(line.kind, '');
  await page.screenshot({ path: join(artifacts, 'optimize-cancelled.png') });
  assert.equal(await page.isDisabled('[data-testid=cancel-button]'), true);
  assert.deepEqual(errors, []);
  await context.close();
});
