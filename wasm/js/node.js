// acutemesh for Node (the "node" condition of package.json's exports): the .wasm is read from
// beside this file. Emscripten 3.1.6's own Node loader does not work in ES modules, and
// Node's global fetch cannot read file: URLs, so this entry reads the bytes itself.
import { readFile } from 'node:fs/promises';
import createAcuteMesh from './acutemesh.mjs';
import { makeEntry } from './api.js';

export { AcuteMeshError } from './api.js';

// Where the .wasm is: options.wasmUrl (a path or a file: URL), else what options.locateFile
// says, else beside this file.
function wasmPath(options) {
  let url = new URL('./acutemesh.wasm', import.meta.url);
  if (options.wasmUrl !== undefined) {
    if (typeof options.wasmUrl !== 'string' && !(options.wasmUrl instanceof URL))
      throw new TypeError('options.wasmUrl must be a string or a URL');
    url = options.wasmUrl;
  } else if (options.locateFile !== undefined) {
    if (typeof options.locateFile !== 'function') throw new TypeError('options.locateFile must be a function');
    url = options.locateFile('acutemesh.wasm', new URL('./', import.meta.url).href);
  }
  return typeof url === 'string' && !/^file:/.test(url) ? url : new URL(url);
}

async function compile(options) {
  let bytes = options.wasmBinary;
  if (bytes === undefined) {
    const path = wasmPath(options);
    try {
      bytes = await readFile(path);
    } catch (e) {
      // Bundling the package into one file moves import.meta.url away from the .wasm.
      throw new Error(`acutemesh: cannot read the WebAssembly module ${path} (${e.code || e.message}): ` +
        'keep acutemesh out of the bundle (esbuild --packages=external), copy ' +
        'node_modules/acutemesh/dist/acutemesh.wasm there, or pass its path as init({ wasmUrl })');
    }
  }
  return WebAssembly.compile(bytes);
}

const entry = makeEntry(createAcuteMesh, compile);
export const createInstance = entry.createInstance;
export default entry.init;
