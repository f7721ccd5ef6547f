// The form checks its numbers in the page's words before anything is sent, and a link with a
// value the page does not take falls back to the default visibly. Accessibility of the
// controls (WCAG 2.2 AA): axe-core finds nothing, the canvas is named and shows its focus,
// drawing works from the keyboard, and tap targets are at least 24 px.
// Run: node --test tests/web/.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join } from 'node:path';
import { artifacts, pageSession, result, runAndWait, status } from './browser.mjs';

const { open } = pageSession();

test('a link with an out-of-range max angle falls back to the default and says so', async () => {
  const { page, errors, context } = await open('?text=Hi&maxAngle=50&mode=acutest');
  const r = await result(page);
  assert.ok(r.triangles > 0, 'no mesh on load');
  assert.deepEqual(r.options, { mode: 'acute', maxAngle: 90 });
  assert.equal(await page.inputValue('[data-testid=max-angle]'), '90');
  const note = await page.textContent('[data-testid=link-note]');
  assert.equal(await page.isVisible('[data-testid=link-note]'), true);
  assert.match(note, /The link's maxAngle=50 is out of range \(max angle: above 60° and at most 90°\): 90° is used instead\./);
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

// axe-core (a devDependency) in the page, for the WCAG 2.x A and AA rules and best practice.
const axeSource = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');

async function axe(page) {
  await page.evaluate(axeSource);
  return page.evaluate(async () => {
    const r = await window.axe.run(document, { runOnly: { type: 'tag',
      values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22aa', 'best-practice'] } });
    const list = (items) => items.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
    // Incomplete checks that are only about colours over the canvas are left to the eye.
    return { violations: list(r.violations), incomplete: list(r.incomplete.filter((v) => v.id !== 'color-contrast')) };
  });
}

for (const [name, size] of [['desktop', { width: 1200, height: 760 }], ['phone', { width: 390, height: 844 }]]) {
  test(`axe-core finds no WCAG A/AA problem (${name}), nor while a run goes (the progress bar is named)`, async () => {
    const { page, errors, context } = await open('?text=Hi', size);
    assert.deepEqual(await axe(page), { violations: [], incomplete: [] });
    await page.selectOption('[data-testid=mode-select]', 'quality');
    await page.fill('#maxArea', '0.02');
    await page.fill('#maxSteiner', '100000000');
    await page.click('[data-testid=run-button]');
    await page.waitForSelector('#progress', { state: 'visible' });
    assert.deepEqual(await axe(page), { violations: [], incomplete: [] });
    // axe only checks explicit progressbar roles: the <progress> element's name is checked here.
    assert.equal(await page.getByRole('progressbar', { name: 'Meshing progress' }).count(), 1);
    await page.click('[data-testid=cancel-button]');
    assert.deepEqual(errors, []);
    await context.close();
  });
}

test('the canvas is named, reached with Tab, and shows a visible focus ring', async () => {
  const { page, errors, context } = await open('?text=Hi');
  const canvas = await page.$eval('[data-testid=mesh-canvas]', (c) => ({ role: c.getAttribute('role'), label: c.getAttribute('aria-label'),
    described: (c.getAttribute('aria-describedby') || '').split(' ').map((id) => document.getElementById(id)?.textContent || '').join(' ') }));
  assert.equal(canvas.role, 'application');
  assert.equal(canvas.label, 'The mesh');
  assert.match(canvas.described, /arrow keys to pan.*Space places a vertex/);
  let focused = '';
  for (let i = 0; i < 60 && focused !== 'view'; i++) {
    await page.keyboard.press('Tab');
    focused = await page.evaluate(() => document.activeElement.id);
  }
  assert.equal(focused, 'view', 'Tab never reached the canvas');
  const ring = await page.$eval('#view', (c) => { const s = getComputedStyle(c); return [s.outlineStyle, parseFloat(s.outlineWidth)]; });
  assert.equal(ring[0], 'solid');
  assert.ok(ring[1] >= 2, `focus ring ${ring[1]} px`);
  await page.screenshot({ path: join(artifacts, 'canvas-focus.png') });
  assert.deepEqual(errors, []);
  await context.close();
});

test('drawing from the keyboard: arrows move a cross-hair, Space places, Enter closes the ring', async () => {
  const { page, errors, context } = await open('?text=Hi');
  await page.click('#draw');
  assert.equal(await page.evaluate(() => document.activeElement.id), 'view', 'Draw puts the focus on the canvas');
  const press = async (key, n = 1) => { for (let i = 0; i < n; i++) await page.keyboard.press(key); };
  await press('ArrowLeft', 5); await press('ArrowUp', 5); await press(' ');
  await press('ArrowRight', 10); await press(' ');
  assert.match(await page.textContent('#source'), /2 vertices in the open ring/);
  await press('ArrowDown', 10); await press(' ');
  await press('Enter');
  assert.match(await page.textContent('#source'), /drawing: 1 ring\b/);
  assert.match(page.url(), /draw=/);
  const r = await runAndWait(page);
  assert.equal(r.inputVertices, 3);
  assert.ok(r.triangles > 0 && r.certified);
  assert.deepEqual(errors, []);
  await context.close();
});

test('tap targets: at least 24 px on a desktop, 40 px (checkboxes 22 px) on a phone', async () => {
  for (const [size, min, box] of [[{ width: 1200, height: 760 }, 24, 16], [{ width: 390, height: 844 }, 40, 22]]) {
    // The plate sample has regions, so the regions box above the canvas is shown too; a
    // control that is not shown (no box at all) is no tap target.
    const { page, errors, context } = await open('?sample=plate', size);
    assert.equal(await page.isVisible('#show-regions'), true);
    const small = await page.$$eval('button, select, input', (els) => els.filter((e) => e.type !== 'hidden' && e.getClientRects().length).map((e) => {
      const b = e.getBoundingClientRect();
      return { id: e.id || e.dataset.format || e.type, type: e.type, w: b.width, h: b.height };
    }));
    for (const e of small) {
      const [w, h] = e.type === 'checkbox' ? [box, box] : [24, min];
      assert.ok(e.w >= w && e.h >= h, `${size.width} px wide: ${e.id} is ${e.w} x ${e.h} px`);
    }
    assert.deepEqual(errors, []);
    await context.close();
  }
});
