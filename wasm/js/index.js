// acutemesh for browsers, module workers and bundlers: the .wasm is fetched from beside this
// file. `new URL('./acutemesh.wasm', import.meta.url)` is written out literally so that Vite
// and webpack see it, copy the .wasm into the build and rewrite the URL. Elsewhere pass
// `locateFile` (a function returning the .wasm's URL), `wasmBinary` (its bytes) or
// `wasmModule` (an already compiled WebAssembly.Module) to init().
import createAcuteMesh from './acutemesh.mjs';
import { makeEntry } from './api.js';

export { AcuteMeshError } from './api.js';

async function compile(options) {
  if (options.wasmBinary !== undefined) return WebAssembly.compile(options.wasmBinary);
  let url = new URL('./acutemesh.wasm', import.meta.url);
  if (options.locateFile !== undefined) {
    if (typeof options.locateFile !== 'function') throw new TypeError('options.locateFile must be a function');
    url = options.locateFile('acutemesh.wasm', new URL('./', import.meta.url).href);
  }
  const response = await fetch(url);
  if (!response.ok) throw new Error(`acutemesh: cannot load ${url} (HTTP ${response.status})`);
  // Streaming compilation needs the server to send application/wasm; fall back to the bytes.
  if (WebAssembly.compileStreaming && response.headers.get('content-type') === 'application/wasm')
    return WebAssembly.compileStreaming(response);
  return WebAssembly.compile(await response.arrayBuffer());
}

const entry = makeEntry(createAcuteMesh, compile);
export const createInstance = entry.createInstance;
export default entry.init;
