#!/usr/bin/env node
// Copies the web page's third-party ES modules from node_modules into web/vendor/ (not
// committed: package-lock.json pins them), so the page needs no bundler and works from any
// static host that serves the repository's web/ and dist/ folders.
import { cpSync, existsSync, mkdirSync, readdirSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const vendor = join(root, 'web', 'vendor');
const copies = [
  ['node_modules/opentype.js/dist/opentype.min.mjs', 'opentype.min.mjs'],
  ['node_modules/opentype.js/LICENSE', 'opentype.LICENSE'],
  ['node_modules/topojson-client/src', 'topojson-client'],
  ['node_modules/topojson-client/LICENSE', 'topojson-client/LICENSE'],
];
mkdirSync(vendor, { recursive: true });
for (const [from, to] of copies) {
  const src = join(root, from);
  if (!existsSync(src)) {
    console.error(`build-web: ${from} is missing (run: bash scripts/setup.sh)`);
    process.exit(1);
  }
  cpSync(src, join(vendor, to), { recursive: true });
}
console.log(`build-web: web/vendor/ has ${readdirSync(vendor).join(', ')}`);
