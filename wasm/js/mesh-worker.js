// The module Worker that acutemesh/worker starts in browsers.
import init from './index.js';
import { serve } from './worker-serve.js';

serve(init, (message, transfer) => self.postMessage(message, transfer || []),
  (handle) => self.addEventListener('message', (event) => handle(event.data)));
