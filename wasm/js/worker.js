// acutemesh/worker for browsers and bundlers: mesh() in a module Worker. The worker's URL is
// written as `new URL('./mesh-worker.js', import.meta.url)` inside `new Worker(...)` so that
// Vite and webpack bundle it.
import { makeWorkerHelper } from './worker-client.js';

export { AcuteMeshError } from './api.js';

function spawn() {
  const w = new Worker(new URL('./mesh-worker.js', import.meta.url), { type: 'module' });
  return {
    post: (message) => w.postMessage(message),
    onMessage: (handle) => w.addEventListener('message', (event) => handle(event.data)),
    onError: (handle) => {
      w.addEventListener('error', (event) => {
        event.preventDefault();
        handle(new Error(`acutemesh worker failed: ${event.message || 'could not start the worker'}`));
      });
      w.addEventListener('messageerror', () => handle(new Error('acutemesh worker: a message could not be read')));
    },
    terminate: () => w.terminate(),
    busy: () => {},
  };
}

export const { createMeshWorker, meshInWorker } = makeWorkerHelper(spawn);
