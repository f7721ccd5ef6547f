// acutemesh/worker for browsers and bundlers: mesh() in a module Worker. The worker's URL is
// written as `new URL('./mesh-worker.js', import.meta.url)` inside `new Worker(...)` so that
// Vite and webpack bundle it; other bundlers (esbuild) leave it pointing beside their output,
// where createMeshWorker({ workerUrl }) can say where it really is.
import { makeWorkerHelper } from './worker-client.js';

export { AcuteMeshError } from './api.js';

const resolveUrl = (url) => new URL(url, globalThis.location?.href).href;

function spawn(workerUrl) {
  const w = workerUrl === undefined
    ? new Worker(new URL('./mesh-worker.js', import.meta.url), { type: 'module' })
    : new Worker(workerUrl, { type: 'module' });
  // Not `new URL(...)` again: bundlers would take that for another file to copy.
  const url = workerUrl ?? import.meta.url.replace(/[^/]*$/, 'mesh-worker.js');
  return {
    post: (message) => w.postMessage(message),
    onMessage: (handle) => w.addEventListener('message', (event) => handle(event.data)),
    onError: (handle) => {
      w.addEventListener('error', (event) => {
        event.preventDefault();
        // A script that cannot be loaded gives a bare Event, with no message.
        handle(new Error(event.message
          ? `acutemesh worker failed: ${event.message}`
          : `acutemesh: could not start the mesh worker from ${url} (missing, or not served as ` +
            'JavaScript): bundle node_modules/acutemesh/dist/mesh-worker.js as an entry of its own ' +
            '(a bundler such as esbuild does not) and pass its URL as createMeshWorker({ workerUrl })'));
      });
      w.addEventListener('messageerror', () => handle(new Error('acutemesh worker: a message could not be read')));
    },
    terminate: () => w.terminate(),
    busy: () => {},
  };
}

export const { createMeshWorker, meshInWorker } = makeWorkerHelper(spawn, resolveUrl);
