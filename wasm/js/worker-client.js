// The calling side of acutemesh/worker, shared by worker.js (browsers: Worker) and
// worker-node.js (Node: worker_threads); `spawn()` returns a Worker-like object adapted to
// { post(message), onMessage(handler), onError(handler), terminate(), busy(flag) } (busy: Node
// keeps the process alive only while a job runs).
//
// Cancellation: a worker busy in mesh() runs synchronous wasm and reads no messages, and
// sharing a flag with it would need SharedArrayBuffer (cross-origin isolation in browsers).
// So aborting terminates the worker, rejects the call with the signal's reason (an AbortError
// by default), and the next call starts a fresh worker. Works everywhere, costs one worker
// start (tens of milliseconds) after an abort.
import { AcuteMeshError } from './api.js';

function abortReason(signal) {
  return signal.reason !== undefined ? signal.reason : new DOMException('The operation was aborted', 'AbortError');
}

function rebuildError(e) {
  if (e.name === 'AcuteMeshError') return new AcuteMeshError(e.code, e.message);
  if (e.name === 'TypeError') return new TypeError(e.message);
  if (e.name === 'AbortError') return new DOMException(e.message, 'AbortError');
  const error = new Error(e.message);
  error.name = e.name;
  return error;
}

export function makeWorkerHelper(spawn) {
  function createMeshWorker(workerOptions = {}) {
    if (typeof workerOptions !== 'object' || workerOptions === null)
      throw new TypeError('options must be an object');
    const initOptions = workerOptions.init;
    let worker = null;
    let nextId = 1;
    let active = null;  // { id, resolve, reject, onProgress, cleanup }
    const queue = [];
    let closed = false;

    function stopWorker() {
      if (worker) worker.terminate();
      worker = null;
    }

    function ensureWorker() {
      if (worker) return worker;
      const w = spawn();
      w.onMessage((message) => {
        if (w !== worker || !active || message.id !== active.id) return;
        if (message.type === 'progress') {
          if (active.onProgress) {
            try {
              active.onProgress(message.progress);
            } catch (e) {
              finish(active, null, e);
              stopWorker();  // the job cannot be told to stop any other way
            }
          }
        } else if (message.type === 'result') {
          finish(active, message.mesh, null);
        } else if (message.type === 'error') {
          finish(active, null, rebuildError(message.error));
        }
      });
      w.onError((error) => {
        if (w !== worker) return;
        worker = null;
        w.terminate();
        if (active) finish(active, null, error instanceof Error ? error : new Error(String(error)));
      });
      worker = w;
      return w;
    }

    function finish(job, mesh, error) {
      if (active !== job) return;
      active = null;
      if (worker) worker.busy(false);
      job.cleanup();
      if (error) job.reject(error);
      else job.resolve(mesh);
      startNext();
    }

    function startNext() {
      if (active || queue.length === 0) return;
      const job = queue.shift();
      active = job;
      const w = ensureWorker();
      w.busy(true);
      w.post({ id: job.id, pslg: job.pslg, options: job.options, initOptions });
    }

    function mesh(pslg, options = {}) {
      if (closed) return Promise.reject(new Error('acutemesh: this mesh worker was terminated'));
      if (typeof options !== 'object' || options === null)
        return Promise.reject(new TypeError('options must be an object'));
      const { signal, onProgress, ...rest } = options;
      if (onProgress !== undefined && typeof onProgress !== 'function')
        return Promise.reject(new TypeError('options.onProgress must be a function'));
      if (signal !== undefined && (typeof signal !== 'object' || signal === null || typeof signal.aborted !== 'boolean'))
        return Promise.reject(new TypeError('options.signal must be an AbortSignal'));
      if (signal && signal.aborted) return Promise.reject(abortReason(signal));
      return new Promise((resolve, reject) => {
        const job = {
          id: nextId++, pslg, options: { ...rest, progress: onProgress !== undefined },
          resolve, reject, onProgress, cleanup: () => {},
        };
        if (signal) {
          const onAbort = () => {
            const i = queue.indexOf(job);
            if (i >= 0) {
              queue.splice(i, 1);
              job.cleanup();
              reject(abortReason(signal));
            } else if (active === job) {
              stopWorker();
              finish(job, null, abortReason(signal));
            }
          };
          signal.addEventListener('abort', onAbort, { once: true });
          job.cleanup = () => signal.removeEventListener('abort', onAbort);
        }
        queue.push(job);
        startNext();
      });
    }

    function terminate() {
      closed = true;
      stopWorker();
      const error = new Error('acutemesh: the mesh worker was terminated');
      if (active) finish(active, null, error);
      for (const job of queue.splice(0)) {
        job.cleanup();
        job.reject(error);
      }
    }

    return { mesh, terminate };
  }

  // One shared worker for meshInWorker(), started on first use.
  let shared = null;
  function meshInWorker(pslg, options) {
    if (!shared) shared = createMeshWorker();
    return shared.mesh(pslg, options);
  }

  return { createMeshWorker, meshInWorker };
}
