// The page says what happened and shows nothing stale: a target that was not met is said in
// every mode, an empty mesh is an error, one time figure, and a new input (or an unreadable
// one) leaves nothing of the previous result on screen. Run: node --test tests/web/.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { writeFileSync, mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pageSession, result, runAndWait, status } from './browser.mjs';

const { open } = pageSession();

function tempFile(name, text) {
  const path = join(mkdtempSync(join(tmpdir(), 'acutemesh-web-')), name);
  writeFileSync(path, text);
  return path;
}

const shown = (page) => page.$eval('[data-testid=mesh-canvas]', (c) => c.dataset.content);
const statsRows = (page) => page.$$eval('#stats dd', (dd) => dd.length);
const downloadsEnabled = (page) => page.$$eval('#downloads [data-format]', (bs) => bs.filter((b) => !b.disabled).length);

test('an empty mesh is an error that says why, in any mode', async () => {
  // One segment among points: the default fill rule keeps no triangle.
  const path = tempFile('one-segment.poly', '5 2 0 0\n1 0 0\n2 10 0\n3 10 10\n4 0 10\n5 3 4\n1 0\n1 1 5\n0\n');
  const { page, errors, context } = await open('?mode=cdt');
  await page.setInputFiles('[data-testid=file-input]', path);
  await page.waitForFunction(() => /Press Mesh\./.test(document.getElementById('source').textContent));
  // The mesher refuses an empty domain (BAD_INPUT, saying why): the page shows that error.
  await page.click('[data-testid=run-button]');
  await page.waitForFunction(() => /error/.test(document.getElementById('status').className), null, { timeout: 60000 });
  const s = await status(page);
  assert.equal(s.kind, 'error', s.text);
  assert.match(s.text, /the domain is empty.*convexHull/);
  assert.equal((await result(page))?.triangles ?? 0, 0);
  assert.deepEqual(errors, []);
  await context.close();
});

test('a status the page does not know, and a met target with corners it cannot hold, are said plainly', async () => {
  const { page, errors, context } = await open('?text=Hi');
  const said = await page.evaluate(async () => {
    const { verdict } = await import('./verdict.js');
    const base = { triangles: 10, certified: true, targetMet: true, minAngle: 20, maxAngle: 80, milliseconds: 12 };
    return {
      unknown: verdict({ ...base, mode: 'acute', askedMaxAngle: 90, options: { mode: 'acute' } },
        { status: 'budget-exhausted', message: 'a reason' }),
      corners: verdict({ ...base, mode: 'quality', certified: false, smallestDomainAngle: 20, options: { mode: 'quality', minAngle: 28 } },
        { status: 'ok' }, ["the domain's smallest corner (20 degrees) is below the minimum angle asked for (28 degrees): triangles there cannot meet it"]),
    };
  });
  assert.equal(said.unknown.kind, 'warn');
  assert.match(said.unknown.text, /Not met \(status 'budget-exhausted'\) \(a reason\)/);
  // "Met" is qualified by the corners, so the mesher's note does not contradict it.
  assert.match(said.corners.text, /Quality target met\. Every angle at least 28° except in the input's corners below it \(the smallest is 20°\)/);
  assert.deepEqual(errors, []);
  await context.close();
});

test('a missed target is said first, in words, with what was reached (budget, quality)', async () => {
  const { page, errors, context } = await open('?text=Hi&maxSteiner=10');
  let s = await status(page);
  assert.equal((await result(page)).status, 'target-not-met');
  assert.equal(s.kind, 'warn');
  // (The mesher's reason names where the target was missed, so that the data can be fixed.)
  assert.match(s.text, /^Meshed in [\d,.]+ ms: Target not met: not certified acute \(Steiner point budget used up before every triangle met the target; missed triangles at \([\d.]+, [\d.]+\).*\)\. The best mesh so far is shown; its largest angle is \d+\.\d{3}°/);
  await page.fill('#maxSteiner', '0');
  await page.selectOption('[data-testid=mode-select]', 'quality');
  await page.fill('#minAngle', '44');
  await runAndWait(page);
  s = await status(page);
  assert.equal(s.kind, 'warn');
  assert.match(s.text, /Target not met \(a minimum angle of 44 degrees was not reached.*\)\. The smallest angle reached is \d+\.\d\d° \(asked: 44°\)/);
  assert.doesNotMatch(s.text, /target met/);
  assert.deepEqual(errors, []);
  await context.close();
});

test('the status line and the stats give one time figure', async () => {
  const { page, errors, context } = await open('?text=Hi');
  const s = await status(page);
  const time = await page.$$eval('#stats dt', (dts) => dts.find((d) => d.textContent === 'Time').nextElementSibling.textContent);
  const inStatus = /^Meshed in ([\d,.]+ ms)/.exec(s.text);
  assert.ok(inStatus, s.text);
  assert.equal(inStatus[1], time);
  assert.equal((s.text.match(/\d+ ms/g) || []).length, 1, `one figure: ${s.text}`);
  assert.deepEqual(errors, []);
  await context.close();
});

test('after an unreadable file nothing of the previous input stays, and Mesh does not mesh it', async () => {
  const { page, errors, context } = await open('?text=Hi');
  assert.equal(await shown(page), 'mesh');
  const bad = tempFile('broken.poly', '4 2 0 0\n1 0 0\n2 x 0\n');
  await page.setInputFiles('[data-testid=file-input]', bad);
  await page.waitForFunction(() => document.getElementById('status').className.includes('error'));
  const message = (await status(page)).text;
  assert.match(message, /broken\.poly/);
  assert.match(await page.textContent('#source'), /^broken\.poly: cannot be meshed/);
  assert.equal(await shown(page), '', 'the previous mesh is still on the canvas');
  assert.equal(await statsRows(page), 0, 'the previous stats are still shown');
  assert.equal(await downloadsEnabled(page), 0, 'the previous mesh can still be downloaded');
  await page.click('[data-testid=run-button]');
  await page.waitForFunction(() => document.getElementById('status').className.includes('error'));
  await page.waitForTimeout(300);
  assert.equal(await page.getAttribute('[data-testid=stats]', 'data-runs'), '1', 'Mesh meshed the previous input');
  assert.equal((await status(page)).text, message);
  assert.deepEqual(errors, []);
  await context.close();
});

test('typing while a run goes stops it: its mesh does not replace the new preview', async () => {
  const { page, errors, context } = await open('?text=Hi');
  await page.selectOption('[data-testid=mode-select]', 'quality');
  await page.fill('#maxArea', '0.02');
  await page.fill('#maxSteiner', '100000000');
  await page.click('[data-testid=run-button]');
  await page.waitForFunction(() => !document.querySelector('[data-testid=cancel-button]').disabled);
  await page.waitForTimeout(500);
  await page.fill('[data-testid=text-input]', 'Ho');
  await page.waitForFunction(() => /^"Ho"/.test(document.getElementById('source').textContent));
  assert.equal(await page.isDisabled('[data-testid=cancel-button]'), true, 'the old run still goes');
  assert.equal(await page.isHidden('#progress'), true);
  await page.waitForTimeout(2000);
  assert.equal(await shown(page), 'preview');
  assert.equal(await page.getAttribute('[data-testid=stats]', 'data-runs'), '1', 'the old run\'s mesh was shown');
  assert.doesNotMatch((await status(page)).text, /Meshing|Cancelled/);
  assert.deepEqual(errors, []);
  await context.close();
});

test('a new sample clears the previous result\'s stats, histogram and downloads', async () => {
  const { page, errors, context } = await open('?text=Hi');
  assert.ok(await statsRows(page) > 0);
  assert.notEqual(await page.getAttribute('[data-testid=histogram]', 'data-bins'), '');
  await page.selectOption('#sample', 'iceland');
  await page.waitForFunction(() => /Press Mesh\./.test(document.getElementById('source').textContent));
  assert.equal(await shown(page), 'preview');
  assert.equal(await statsRows(page), 0);
  assert.equal(await page.getAttribute('[data-testid=histogram]', 'data-bins'), '');
  assert.equal(await downloadsEnabled(page), 0);
  assert.equal(await result(page), null);
  const r = await runAndWait(page);
  assert.ok(r.triangles > 0);
  assert.ok(await statsRows(page) > 0);
  assert.deepEqual(errors, []);
  await context.close();
});

test('a min and a max angle together: the status says both were met', async () => {
  const { page, errors, context } = await open('?text=Hi&minAngle=35&maxAngle=80');
  const r = await result(page);
  assert.equal(r.status, 'ok');
  const s = await status(page);
  assert.equal(s.kind, '');
  assert.match(s.text, /Certified acute\. Every angle below 80° \(this input's floor: 72°\)\. Every angle at least 35° \(smallest 35\.\d\d°\)\./);
  assert.deepEqual(errors, []);
  await context.close();
});
