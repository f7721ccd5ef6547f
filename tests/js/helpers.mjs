// Shared by the JavaScript tests: where the fixtures are, and loading them through the API.
import { readFileSync, readdirSync, existsSync } from 'node:fs';
import { join, dirname, basename, extname, relative } from 'node:path';
import { fileURLToPath } from 'node:url';

export const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
export const testData = join(root, 'tests', 'data');
// The reference inputs live next to the repository (CI clones it beside `shared`).
export const sharedData = join(root, '..', 'shared', 'data');

// Every mesh-able fixture: tests/data/*.poly|.json and ../shared/data/poly/*.poly.
export function fixtures() {
  const list = [];
  for (const f of readdirSync(testData).sort())
    if (/\.(poly|json)$/.test(f)) list.push(join(testData, f));
  const polyDir = join(sharedData, 'poly');
  if (!existsSync(polyDir)) throw new Error(`${polyDir} is missing (the shared data beside the repository)`);
  for (const f of readdirSync(polyDir).sort()) if (f.endsWith('.poly')) list.push(join(polyDir, f));
  return list;
}

export function sharedPolys() {
  const polyDir = join(sharedData, 'poly');
  return readdirSync(polyDir).filter((f) => f.endsWith('.poly')).sort().map((f) => join(polyDir, f));
}

// Reads a fixture with the parser its extension calls for.
export function load(am, path) {
  const text = readFileSync(path, 'utf8');
  const name = basename(path);
  switch (extname(path)) {
    case '.poly': return am.parsePoly(text, { name });
    case '.node': return am.parseNode(text, { name });
    case '.json': return am.parseJson(text, { name });
    default: throw new Error(`no parser for ${path}`);
  }
}

// A fixture's name for test titles: its path from the directory holding the repository.
export const label = (path) => relative(join(root, '..'), path);
