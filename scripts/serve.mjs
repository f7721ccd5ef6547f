#!/usr/bin/env node
// A small static file server for the web page: no dependencies, the right MIME types
// (application/wasm lets browsers compile the mesher while it downloads), GET and HEAD only,
// nothing outside the repository root. `/` redirects to the page in web/, which loads the
// package from ../dist/ by relative URL, exactly as it would from any static host.
//
//   PORT=8080 node scripts/serve.mjs [ROOT]
import { createServer } from 'node:http';
import { createReadStream, promises as fs } from 'node:fs';
import { extname, join, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = resolve(process.argv[2] || join(fileURLToPath(import.meta.url), '..', '..'));
const PORT = Number(process.env.PORT || 8080);
const HOST = process.env.HOST || '127.0.0.1';

const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8', '.css': 'text/css; charset=utf-8',
  '.json': 'application/json', '.geojson': 'application/geo+json', '.topojson': 'application/json',
  '.wasm': 'application/wasm', '.svg': 'image/svg+xml', '.png': 'image/png', '.ico': 'image/x-icon',
  '.otf': 'font/otf', '.ttf': 'font/ttf', '.woff': 'font/woff', '.woff2': 'font/woff2',
  '.txt': 'text/plain; charset=utf-8', '.md': 'text/plain; charset=utf-8',
  '.poly': 'text/plain; charset=utf-8', '.node': 'text/plain; charset=utf-8', '.ele': 'text/plain; charset=utf-8',
  '.map': 'application/json',
};

async function handle(req, res) {
  if (req.method !== 'GET' && req.method !== 'HEAD') {
    res.writeHead(405, { Allow: 'GET, HEAD' }).end();
    return;
  }
  const url = new URL(req.url, 'http://localhost');
  if (url.pathname === '/') {
    res.writeHead(302, { Location: `/web/${url.search}` }).end();
    return;
  }
  let path;
  try {
    path = resolve(ROOT, '.' + decodeURIComponent(url.pathname));
  } catch {
    res.writeHead(400).end('bad path');
    return;
  }
  if (path !== ROOT && !path.startsWith(ROOT + sep)) {
    res.writeHead(403).end('forbidden');
    return;
  }
  let stat = await fs.stat(path).catch(() => null);
  if (stat && stat.isDirectory()) {
    if (!url.pathname.endsWith('/')) {
      res.writeHead(301, { Location: `${url.pathname}/${url.search}` }).end();
      return;
    }
    path = join(path, 'index.html');
    stat = await fs.stat(path).catch(() => null);
  }
  if (!stat || !stat.isFile()) {
    res.writeHead(404, { 'Content-Type': 'text/plain' }).end(`not found: ${url.pathname}`);
    return;
  }
  res.writeHead(200, {
    'Content-Type': TYPES[extname(path).toLowerCase()] || 'application/octet-stream',
    'Content-Length': stat.size,
    // Development server: always revalidate, so a rebuild shows up on reload.
    'Cache-Control': 'no-cache',
    // Cross-origin isolation: the page may share memory with its mesh worker, which lets a
    // cancel during "spend more time" keep the best mesh found (wasm/js/worker-client.js).
    'Cross-Origin-Opener-Policy': 'same-origin',
    'Cross-Origin-Embedder-Policy': 'require-corp',
  });
  if (req.method === 'HEAD') res.end();
  else createReadStream(path).pipe(res);
}

const server = createServer((req, res) => {
  handle(req, res).catch((e) => {
    if (!res.headersSent) res.writeHead(500, { 'Content-Type': 'text/plain' });
    res.end(String(e && e.message));
  });
});
server.listen(PORT, HOST, () => {
  const { port } = server.address();
  console.log(`acutemesh web page: http://${HOST === '0.0.0.0' ? 'localhost' : HOST}:${port}/web/`);
});
