// The mesher, from the npm package's build output (`npm run build` writes dist/). The page
// uses the package exactly as a user of `acutemesh` and `acutemesh/worker` would; only the
// paths differ, relative so that any static host serving web/ beside dist/ works.
//   init():           the WebAssembly module on this thread (parsers, fromRings, writers)
//   meshInWorker():   mesh() in a module Worker: a promise, progress, AbortSignal
import init from '../dist/index.js';
import { meshInWorker as meshInPackageWorker } from '../dist/worker.js';

export function loadEngine() {
  return init();
}

export function meshInWorker(pslg, options, { signal, onProgress } = {}) {
  return meshInPackageWorker(pslg, { ...options, signal, onProgress });
}

// The worker loads and compiles its own copy of the module on its first job. Giving it a
// trivial job as soon as the page starts overlaps that with the page's own loading, which
// takes a few hundred milliseconds off the first mesh.
export function warmUp() {
  const triangle = { points: new Float64Array([0, 0, 1, 0, 0, 1]), segments: new Uint32Array(0), holes: new Float64Array(0) };
  return meshInPackageWorker(triangle, { mode: 'cdt' }).catch(() => {});
}
