// What the canvas shows: Steiner dots sized by the zoom and their triangles, the fit framing
// the main part of the input, and the smaller things a user noticed (the link and a file,
// missing glyphs, a dropped drawing, the SVG download's colours, the histogram's legend).
// Run: node --test tests/web/.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { artifacts, startServer, launch, openPage, waitForRun } from './browser.mjs';

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
  await waitForRun(p.page, 1, 60000);
  return p;
}

// After the next two frames: the share of the canvas in the Steiner dots' colour, and the
// dots drawn as [count, smallest radius, largest radius] in CSS pixels.
function steinerDots(page) {
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
  await page.waitForTimeout(400);  // the full frame after the gesture
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
