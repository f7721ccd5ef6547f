// acutemesh/worker in Node: mesh() in a worker_threads Worker, the same API as in browsers.
import { Worker } from 'node:worker_threads';
import { makeWorkerHelper } from './worker-client.js';

export { AcuteMeshError } from './api.js';

function spawn() {
  const w = new Worker(new URL('./mesh-worker-node.js', import.meta.url));
  // An idle worker must not keep the process alive; a busy one must, or a script awaiting
  // its result would exit early.
  w.unref();
  return {
    post: (message) => w.postMessage(message),
    onMessage: (handle) => w.on('message', handle),
    onError: (handle) => {
      w.on('error', handle);
      w.on('exit', (code) => handle(new Error(`acutemesh worker exited (code ${code})`)));
    },
    terminate: () => { void w.terminate(); },
    busy: (flag) => (flag ? w.ref() : w.unref()),
  };
}

export const { createMeshWorker, meshInWorker } = makeWorkerHelper(spawn);
