// acutemesh/worker in Node: mesh() in a worker_threads Worker, the same API as in browsers.
import { Worker } from 'node:worker_threads';
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { makeWorkerHelper } from './worker-client.js';

export { AcuteMeshError } from './api.js';

// A path (relative to the working directory) or a URL, as a URL's text.
const resolveUrl = (url) =>
  (url instanceof URL || /^[a-z][a-z0-9+.-]+:/i.test(url) ? new URL(url) : pathToFileURL(resolve(url))).href;

function spawn(workerUrl) {
  const url = new URL(workerUrl ?? './mesh-worker-node.js', import.meta.url);
  const w = new Worker(url);
  // An idle worker must not keep the process alive; a busy one must, or a script awaiting
  // its result would exit early.
  w.unref();
  return {
    post: (message) => w.postMessage(message),
    onMessage: (handle) => w.on('message', handle),
    onError: (handle) => {
      // Node says MODULE_NOT_FOUND for a missing worker script, ERR_MODULE_NOT_FOUND for a
      // missing import of it.
      w.on('error', (e) => handle(e && /^(ERR_)?MODULE_NOT_FOUND$/.test(e.code)
        ? new Error(`acutemesh: could not start the mesh worker from ${url.href} (${e.message}): ` +
          'pass the path of node_modules/acutemesh/dist/mesh-worker-node.js, or of a bundle of it, ' +
          'as createMeshWorker({ workerUrl })')
        : e));
      w.on('exit', (code) => handle(new Error(`acutemesh worker exited (code ${code})`)));
    },
    terminate: () => { void w.terminate(); },
    busy: (flag) => (flag ? w.ref() : w.unref()),
  };
}

export const { createMeshWorker, meshInWorker } = makeWorkerHelper(spawn, resolveUrl);
