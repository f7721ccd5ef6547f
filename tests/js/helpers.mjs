// Shared by the JavaScript tests: where the fixtures are, and loading them through the API.
import { readFileSync, readdirSync, existsSync, statSync, appendFileSync } from 'node:fs';
import { join, dirname, basename, extname, relative, isAbsolute } from 'node:path';
import { fileURLToPath } from 'node:url';
import assert from 'node:assert/strict';

export const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
export const testData = join(root, 'tests', 'data');
// The synthetic CG:SHOP 2025 instances (tests/data/cgshop/make.mjs).
export const syntheticCgshop = join(testData, 'cgshop');

// The external reference data (the 150 CG:SHOP 2025 instances, Lake Superior, ...), by the
// rule every test follows (tests/cpp/reference_data.h): $ACUTEMESH_DATA when set (relative to
// the repository root; empty: none), else ../shared/data beside the repository, else none.
// { dir, error }: dir is null when there is none; error says when ACUTEMESH_DATA names a
// directory that is not there.
export const reference = (() => {
  const isDir = (p) => existsSync(p) && statSync(p).isDirectory();
  const env = process.env.ACUTEMESH_DATA;
  if (env !== undefined) {
    if (env === '') return { dir: null };
    const dir = isAbsolute(env) ? env : join(root, env);
    return isDir(dir) ? { dir } : { dir: null, error: `ACUTEMESH_DATA=${env}: no such directory` };
  }
  const beside = join(root, '..', 'shared', 'data');
  return { dir: isDir(beside) ? beside : null };
})();

// Options for test() when it needs the reference data: none when it is there, else a skip
// with the reason (noted in $ACUTEMESH_TEST_SKIPS for scripts/test.sh). A missing
// ACUTEMESH_DATA directory lets the test run, and fail on referenceFile().
export function needsReference(name) {
  if (reference.dir || reference.error) return {};
  if (process.env.ACUTEMESH_TEST_SKIPS) appendFileSync(process.env.ACUTEMESH_TEST_SKIPS, `JS ${name}\n`);
  return {
    skip: process.env.ACUTEMESH_DATA === ''
      ? 'needs the reference data, and ACUTEMESH_DATA is set empty (none)'
      : `needs the reference data: set ACUTEMESH_DATA to its directory, or put it at ${join(root, '..', 'shared', 'data')}`,
  };
}

// A path inside the reference data (in a test given needsReference()'s options).
export function referenceFile(...parts) {
  if (reference.error) throw new Error(reference.error);
  return join(reference.dir, ...parts);
}

// Every mesh-able fixture in the repository: tests/data/*.poly|.json, tests/data/io/*.poly|.node.
export function fixtures() {
  const list = [];
  for (const f of readdirSync(testData).sort())
    if (/\.(poly|json)$/.test(f)) list.push(join(testData, f));
  const io = join(testData, 'io');
  for (const f of readdirSync(io).sort()) if (/\.(poly|node)$/.test(f)) list.push(join(io, f));
  return list;
}

// The reference .poly inputs (Triangle's A, Lake Superior), in a test given needsReference().
export function referencePolys() {
  const polyDir = referenceFile('poly');
  return readdirSync(polyDir).filter((f) => f.endsWith('.poly')).sort().map((f) => join(polyDir, f));
}

// The CG:SHOP instance files in dir, sorted.
export function instanceFiles(dir) {
  return readdirSync(dir).filter((f) => f.endsWith('.instance.json')).sort().map((f) => join(dir, f));
}

// Reads a fixture with the parser its extension calls for.
export function load(am, path) {
  const text = readFileSync(path, 'utf8');
  const name = basename(path);
  switch (extname(path)) {
    case '.poly': {
      // A .poly may keep its vertices in BASE.node beside it (vertex count 0).
      const node = path.replace(/\.poly$/, '.node');
      return am.parsePoly(text, existsSync(node) ? { name, nodeText: readFileSync(node, 'utf8') } : { name });
    }
    case '.node': return am.parseNode(text, { name });
    case '.json': return am.parseJson(text, { name });
    default: throw new Error(`no parser for ${path}`);
  }
}

// A fixture's name for test titles: its path from the directory holding the repository.
export const label = (path) => relative(join(root, '..'), path);

// What a cancel during optimize's search answers (the anytime contract): the best mesh so far,
// status 'cancelled', certified, meeting the target, valid for `pslg`, and no more Steiner
// points than `plain` (the same options without the search).
export function assertBestSoFar(am, pslg, m, plain) {
  assert.equal(m.status, 'cancelled');
  assert.ok(m.stats.certified && m.stats.targetMet);
  assert.ok(am.validate(pslg, m).ok);
  assert.ok(m.stats.steiner <= plain.stats.steiner, `${m.stats.steiner} > ${plain.stats.steiner}`);
}
