// The worker_threads Worker that acutemesh/worker starts in Node.
import { parentPort } from 'node:worker_threads';
import init from './node.js';
import { serve } from './worker-serve.js';

serve(init, (message, transfer) => parentPort.postMessage(message, transfer || []),
  (handle) => parentPort.on('message', handle));
