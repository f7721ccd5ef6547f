// The worker side of acutemesh/worker: one job at a time, progress and the result posted
// back (the result's arrays transferred, not copied). Shared by mesh-worker.js (browsers) and
// mesh-worker-node.js (worker_threads); `post` and `listen` are the platform's.
export function serve(init, post, listen) {
  let api = null;
  listen(async (message) => {
    const { id, pslg, options, initOptions, cancelFlag } = message;
    try {
      if (!api) api = await init(initOptions);
      const opts = { ...options };
      // The caller's abort, through memory both threads see (worker-client.js).
      if (cancelFlag) opts.signal = { get aborted() { return Atomics.load(cancelFlag, 0) !== 0; } };
      if (options.progress) {
        opts.onProgress = (p) => post({ id, type: 'progress', progress: p });
      }
      delete opts.progress;
      const m = api.mesh(pslg, opts);
      // Every typed array of the result, each buffer once.
      const buffers = new Set(Object.values(m)
        .filter((v) => ArrayBuffer.isView(v))
        .map((v) => v.buffer));
      post({ id, type: 'result', mesh: m }, [...buffers]);
    } catch (e) {
      const error = e instanceof Error
        ? { name: e.name, code: e.code, message: e.message }
        : { name: 'Error', message: String(e) };
      post({ id, type: 'error', error });
    }
  });
}
