// The calling side of acutemesh/worker, shared by worker.js (browsers: Worker) and
// worker-node.js (Node: worker_threads); `spawn(workerUrl)` starts the package's worker, or the
// one at workerUrl (an absolute URL) when given, and returns a Worker-like object adapted to
// { post(message), onMessage(handler), onError(handler), terminate(), busy(flag) } (busy: Node
// keeps the process alive only while a job runs). `resolveUrl(url)` makes the URLs a user
// gives absolute, relative to the page (browsers) or the working directory (Node).
//
// Cancellation: a worker busy in mesh() runs synchronous wasm and reads no messages. So
// aborting terminates the worker, rejects the call with the signal's reason (an AbortError
// by default), and the next call starts a fresh worker. Works everywhere, costs one worker
// start (tens of milliseconds) after an abort. A job with optimize is the exception where
// SharedArrayBuffer exists (Node; browsers on a cross-origin isolated page): its abort sets a
// flag the worker's mesh() reads as its signal, so a cancel while the search runs still
// answers with the best mesh so far (api.js); a worker that has not answered kCancelGraceMs
// later is terminated.
import { AcuteMeshError } from './api.js';
import { checkKeys, searchAsked, MESH_OPTION_KEYS, INIT_OPTION_KEYS } from './keys.js';

const kCancelGraceMs = 1000;
const canShareFlag = () => typeof SharedArrayBuffer === 'function' && globalThis.crossOriginIsolated !== false;

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

// One worker and its queue of jobs: mesh() calls run one after another; the worker starts on
// the first and again after an abort or a crash.
class MeshWorker {
  constructor(spawn, initOptions, workerUrl) {
    this.spawn = () => spawn(workerUrl);
    this.initOptions = initOptions;
    this.worker = null;
    this.nextId = 1;
    this.active = null;  // { id, resolve, reject, onProgress, cleanup }
    this.queue = [];
    this.closed = false;
  }

  stopWorker() {
    if (this.worker) this.worker.terminate();
    this.worker = null;
  }

  ensureWorker() {
    if (this.worker) return this.worker;
    const w = this.spawn();
    w.onMessage((message) => {
      const job = this.active;
      if (w !== this.worker || !job || message.id !== job.id) return;
      if (message.type === 'progress') {
        if (!job.onProgress) return;
        try {
          job.onProgress(message.progress);
        } catch (e) {
          // The job cannot be told to stop any other way; stop the worker before the next
          // job is posted to it.
          this.stopWorker();
          this.finish(job, null, e);
        }
      } else if (message.type === 'result') {
        this.finish(job, message.mesh, null);
      } else if (message.type === 'error') {
        const error = rebuildError(message.error);
        this.finish(job, null, job.aborted && error.name === 'AbortError' ? job.aborted : error);
      }
    });
    w.onError((error) => {
      if (w !== this.worker) return;
      this.worker = null;
      w.terminate();
      if (this.active) this.finish(this.active, null, error instanceof Error ? error : new Error(String(error)));
    });
    this.worker = w;
    return w;
  }

  finish(job, mesh, error) {
    if (this.active !== job) return;
    this.active = null;
    if (this.worker) this.worker.busy(false);
    job.cleanup();
    if (error) job.reject(error);
    else job.resolve(mesh);
    this.startNext();
  }

  startNext() {
    if (this.active || this.queue.length === 0) return;
    const job = this.queue.shift();
    this.active = job;
    try {
      const w = this.ensureWorker();
      w.busy(true);
      w.post({ id: job.id, pslg: job.pslg, options: job.options, initOptions: this.initOptions,
        cancelFlag: job.cancelFlag });
    } catch (e) {
      // No worker (the platform refused one), or input that cannot be cloned (functions,
      // say): this job fails, the queue goes on.
      this.finish(job, null, e);
    }
  }

  mesh(pslg, options = {}) {
    if (this.closed) return Promise.reject(new Error('acutemesh: this mesh worker was terminated'));
    if (typeof options !== 'object' || options === null)
      return Promise.reject(new TypeError('options must be an object'));
    try {
      checkKeys(options, MESH_OPTION_KEYS, 'mesh()');
    } catch (e) {
      return Promise.reject(e);
    }
    const { signal, onProgress, ...rest } = options;
    const { size } = options;
    if (typeof size === 'function' || (typeof size === 'object' && size !== null &&
        (typeof size.function === 'function' || typeof size.maxArea === 'function'))) {
      return Promise.reject(new TypeError('options.size: a function cannot be sent to a worker ' +
        '(functions do not clone); give the sizes as a grid { x0, y0, dx, dy, nx, ny, h } or as ' +
        'points and sizes, or call mesh() on this thread'));
    }
    if (onProgress !== undefined && typeof onProgress !== 'function')
      return Promise.reject(new TypeError('options.onProgress must be a function'));
    if (signal !== undefined && (typeof signal !== 'object' || signal === null || typeof signal.aborted !== 'boolean'))
      return Promise.reject(new TypeError('options.signal must be an AbortSignal'));
    if (signal && signal.aborted) return Promise.reject(abortReason(signal));
    return new Promise((resolve, reject) => {
      const job = {
        id: this.nextId++, pslg, options: { ...rest, progress: onProgress !== undefined },
        resolve, reject, onProgress, cleanup: () => {},
        cancelFlag: signal && searchAsked(options) && canShareFlag()
          ? new Int32Array(new SharedArrayBuffer(4)) : undefined,
        aborted: null,  // the signal's reason, once the flag is set
      };
      if (signal) this.cancelOnAbort(job, signal);
      this.queue.push(job);
      this.startNext();
    });
  }

  // An abort takes a waiting job off the queue, or stops the worker running it (through its
  // flag first, where it has one).
  cancelOnAbort(job, signal) {
    let grace;
    const stop = () => {
      if (this.active !== job) return;
      this.stopWorker();
      this.finish(job, null, abortReason(signal));
    };
    const onAbort = () => {
      const i = this.queue.indexOf(job);
      if (i >= 0) {
        this.queue.splice(i, 1);
        job.cleanup();
        job.reject(abortReason(signal));
      } else if (this.active === job && job.cancelFlag) {
        job.aborted = abortReason(signal);
        Atomics.store(job.cancelFlag, 0, 1);
        grace = setTimeout(stop, kCancelGraceMs);
      } else {
        stop();
      }
    };
    signal.addEventListener('abort', onAbort, { once: true });
    job.cleanup = () => {
      signal.removeEventListener('abort', onAbort);
      clearTimeout(grace);
    };
  }

  terminate() {
    this.closed = true;
    this.stopWorker();
    const error = new Error('acutemesh: the mesh worker was terminated');
    if (this.active) this.finish(this.active, null, error);
    for (const job of this.queue.splice(0)) {
      job.cleanup();
      job.reject(error);
    }
  }
}

// init() inside the worker gets what can be posted to it; a relative wasmUrl is made absolute
// here, so that it means the same as in init() on this side.
function workerInitOptions(init, resolveUrl) {
  if (init === undefined) return undefined;
  if (typeof init !== 'object' || init === null) throw new TypeError('options.init must be an object');
  if (init.locateFile !== undefined)
    throw new TypeError('options.init.locateFile cannot be sent to a worker (it is a function): pass the URL as init.wasmUrl');
  checkKeys(init, INIT_OPTION_KEYS.filter((k) => k !== 'locateFile'), 'createMeshWorker() init');
  if (init.wasmUrl === undefined) return init;
  if (typeof init.wasmUrl !== 'string' && !(init.wasmUrl instanceof URL))
    throw new TypeError('options.init.wasmUrl must be a string or a URL');
  return { ...init, wasmUrl: resolveUrl(init.wasmUrl) };
}

export function makeWorkerHelper(spawn, resolveUrl) {
  function createMeshWorker(workerOptions = {}) {
    if (typeof workerOptions !== 'object' || workerOptions === null)
      throw new TypeError('options must be an object');
    checkKeys(workerOptions, ['workerUrl', 'init'], 'createMeshWorker()');
    const { workerUrl } = workerOptions;
    if (workerUrl !== undefined && typeof workerUrl !== 'string' && !(workerUrl instanceof URL))
      throw new TypeError('options.workerUrl must be a string or a URL');
    const w = new MeshWorker(spawn, workerInitOptions(workerOptions.init, resolveUrl),
      workerUrl === undefined ? undefined : resolveUrl(workerUrl));
    return { mesh: (pslg, options) => w.mesh(pslg, options), terminate: () => w.terminate() };
  }

  // One shared worker for meshInWorker(), started on first use.
  let shared = null;
  function meshInWorker(pslg, options) {
    if (!shared) shared = createMeshWorker();
    return shared.mesh(pslg, options);
  }

  return { createMeshWorker, meshInWorker };
}
