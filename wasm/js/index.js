// acutemesh for browsers, module workers and bundlers: the .wasm is fetched from beside this
// file. `new URL('./acutemesh.wasm', import.meta.url)` is written out literally so that Vite
// and webpack see it, copy the .wasm into the build and rewrite the URL. Elsewhere (esbuild
// copies nothing) pass `wasmUrl` (its URL), `locateFile` (a function returning it),
// `wasmBinary` (its bytes) or `wasmModule` (an already compiled WebAssembly.Module) to init().
import createAcuteMesh from './acutemesh.mjs';
import { makeEntry } from './api.js';

export { AcuteMeshError } from './api.js';

// Where the .wasm is: options.wasmUrl, else what options.locateFile says, else beside this file.
function wasmUrl(options) {
  if (options.wasmUrl !== undefined) {
    if (typeof options.wasmUrl !== 'string' && !(options.wasmUrl instanceof URL))
      throw new TypeError('options.wasmUrl must be a string or a URL');
    return new URL(options.wasmUrl, globalThis.location?.href);
  }
  if (options.locateFile !== undefined) {
    if (typeof options.locateFile !== 'function') throw new TypeError('options.locateFile must be a function');
    return options.locateFile('acutemesh.wasm', new URL('./', import.meta.url).href);
  }
  return new URL('./acutemesh.wasm', import.meta.url);
}

// What to do when the .wasm is not at `url`: said in every load error, since the usual cause
// is a bundler that did not copy it.
const cannotLoad = (url) => `acutemesh: cannot load the WebAssembly module from ${url}`;
const remedy = 'serve node_modules/acutemesh/dist/acutemesh.wasm there (a bundler such as esbuild ' +
  "does not copy it), pass its URL as init({ wasmUrl }), or import 'acutemesh/single' (the .wasm inside the JavaScript)";

async function compile(options) {
  if (options.wasmBinary !== undefined) return WebAssembly.compile(options.wasmBinary);
  const url = wasmUrl(options);
  let response;
  try {
    response = await fetch(url);
  } catch (e) {
    throw new Error(`${cannotLoad(url)} (${e.message}): ${remedy}`);
  }
  if (!response.ok) throw new Error(`${cannotLoad(url)} (HTTP ${response.status}): ${remedy}`);
  // Streaming compilation needs the server to send application/wasm; fall back to the bytes.
  const type = response.headers.get('content-type') || '';
  try {
    if (WebAssembly.compileStreaming && type.startsWith('application/wasm'))
      return await WebAssembly.compileStreaming(response);
    return await WebAssembly.compile(await response.arrayBuffer());
  } catch (e) {
    // A server's fallback page (an HTML 200 for any path) lands here.
    throw new Error(`${cannotLoad(url)}: it is not WebAssembly (${type || 'no content type'}; ${e.message}): ${remedy}`);
  }
}

const entry = makeEntry(createAcuteMesh, compile);
export const createInstance = entry.createInstance;
export default entry.init;
