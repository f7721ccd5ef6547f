// acutemesh for Node (the "node" condition of package.json's exports): the .wasm is read from
// beside this file. Emscripten 3.1.6's own Node loader does not work in ES modules, and
// Node's global fetch cannot read file: URLs, so this entry reads the bytes itself.
import { readFile } from 'node:fs/promises';
import createAcuteMesh from './acutemesh.mjs';
import { makeEntry } from './api.js';

export { AcuteMeshError } from './api.js';

async function compile(options) {
  let bytes = options.wasmBinary;
  if (bytes === undefined) {
    let url = new URL('./acutemesh.wasm', import.meta.url);
    if (options.locateFile !== undefined) {
      if (typeof options.locateFile !== 'function') throw new TypeError('options.locateFile must be a function');
      url = options.locateFile('acutemesh.wasm', new URL('./', import.meta.url).href);
    }
    bytes = await readFile(typeof url === 'string' && !/^file:/.test(url) ? url : new URL(url));
  }
  return WebAssembly.compile(bytes);
}

const entry = makeEntry(createAcuteMesh, compile);
export const createInstance = entry.createInstance;
export default entry.init;
