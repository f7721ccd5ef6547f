// acutemesh/worker: mesh() in a module Worker (browsers) or a worker_threads Worker (Node).
import type { AbortSignalLike, InitOptions, MeshOptions, MeshResult, PslgInput } from './index.js';

export { AcuteMeshError } from './index.js';

export interface WorkerMeshOptions extends Omit<MeshOptions, 'onProgress' | 'signal'> {
  /** Called on the calling thread for each progress report the worker sends. */
  onProgress?: MeshOptions['onProgress'];
  /**
   * Aborting terminates the worker and rejects with signal.reason (an AbortError by default);
   * the next call starts a fresh worker. A queued call is just dropped.
   */
  signal?: AbortSignalLike;
}

export interface MeshWorker {
  /** Runs mesh() in the worker; calls queue, one runs at a time. */
  mesh(pslg: PslgInput, options?: WorkerMeshOptions): Promise<MeshResult>;
  /** Stops the worker; pending calls reject. */
  terminate(): void;
}

export interface MeshWorkerOptions {
  /**
   * Where the worker script is (default: mesh-worker.js beside acutemesh/worker's JS, which
   * Vite and webpack bundle; esbuild does not): relative to the page, in Node a path or a file:
   * URL. A bundle of acutemesh/dist/mesh-worker.js (mesh-worker-node.js in Node).
   */
  workerUrl?: string | { readonly href: string };
  /**
   * Passed to init() inside the worker (structured-cloneable values only: no locateFile; a
   * relative wasmUrl is taken relative to the page, as for init() here).
   */
  init?: Omit<InitOptions, 'locateFile'>;
}

export declare function createMeshWorker(options?: MeshWorkerOptions): MeshWorker;

/** mesh() in one shared worker, started on first use. */
export declare function meshInWorker(pslg: PslgInput, options?: WorkerMeshOptions): Promise<MeshResult>;
