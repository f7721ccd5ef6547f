// Shared setup for the browser tests: the repository's static server on a free port and
// Debian's Chromium driven by playwright-core (no browser download; flags from
// shared/notes/toolchain.md). Screenshots go to build/web-artifacts/.
import { spawn } from 'node:child_process';
import { mkdirSync } from 'node:fs';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { before, after } from 'node:test';
import { chromium } from 'playwright-core';

export const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
export const artifacts = join(root, 'build', 'web-artifacts');
mkdirSync(artifacts, { recursive: true });

export async function startServer() {
  const child = spawn(process.execPath, [join(root, 'scripts', 'serve.mjs')], {
    env: { ...process.env, PORT: '0' }, stdio: ['ignore', 'pipe', 'inherit'],
  });
  const url = await new Promise((resolve, reject) => {
    let out = '';
    child.stdout.on('data', (d) => {
      out += d;
      const m = /(http:\/\/\S+)/.exec(out);
      if (m) resolve(m[1]);
    });
    child.on('exit', (code) => reject(new Error(`serve.mjs exited with ${code}`)));
    setTimeout(() => reject(new Error('serve.mjs printed no URL within 10 s')), 10000);
  });
  return { url, close: () => child.kill() };
}

export async function launch() {
  // playwright-core gives each launch a fresh temporary profile (it refuses --user-data-dir).
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  return {
    browser,
    close: () => browser.close(),
  };
}

// One test file's server and browser, started before its tests and closed after them:
// open(query, options) gives a page of the app once its first mesh is shown (within
// `firstRunTimeout` ms), url(query) and browser() what openPage needs for a page taken earlier.
export function pageSession({ firstRunTimeout = 20000 } = {}) {
  let server, browser;
  before(async () => {
    server = await startServer();
    browser = await launch();
  });
  after(async () => {
    await browser?.close();
    server?.close();
  });
  const url = (query = '') => `${server.url}${query}`;
  return {
    url,
    browser: () => browser.browser,
    async open(query = '', options) {
      const p = await openPage(browser.browser, url(query), options);
      await waitForRun(p.page, 1, firstRunTimeout);
      return p;
    },
  };
}

// A page that records console errors and uncaught exceptions, so a test can assert none.
export async function openPage(browser, url, { dpr = 1, width = 1200, height = 760 } = {}) {
  const context = await browser.newContext({ viewport: { width, height }, deviceScaleFactor: dpr, acceptDownloads: true });
  const page = await context.newPage();
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(`console: ${m.text()}`); });
  page.on('pageerror', (e) => errors.push(`pageerror: ${e.message}`));
  page.on('requestfailed', (r) => errors.push(`request failed: ${r.url()} ${r.failure()?.errorText}`));
  await page.goto(url);
  return { page, context, errors };
}

export async function result(page) {
  const s = await page.getAttribute('[data-testid=stats]', 'data-result');
  return s ? JSON.parse(s) : null;
}

// Waits until the page has shown its `n`-th mesh result (data-runs counts them).
export async function waitForRun(page, n, timeout = 20000) {
  await page.waitForFunction((k) => Number(document.querySelector('[data-testid=stats]').dataset.runs) >= k,
    n, { timeout });
  return result(page);
}

// Presses Mesh and waits for the result it brings.
export async function runAndWait(page, timeout = 60000) {
  const before = Number(await page.getAttribute('[data-testid=stats]', 'data-runs'));
  await page.click('[data-testid=run-button]');
  return waitForRun(page, before + 1, timeout);
}

// The status line: its text and its kind ('', 'warn' or 'error').
export async function status(page) {
  return page.$eval('#status', (s) => ({ text: s.textContent, kind: s.className.replace('status', '').trim() }));
}
