// acutemesh with the .wasm inside the JavaScript (base64 in wasm-inline.js, written by the
// build): no file to locate, for any environment and bundler with zero configuration, at
// about a third more bytes to download than the .wasm itself.
import createAcuteMesh from './acutemesh.mjs';
import { makeEntry } from './api.js';
import { wasmBase64 } from './wasm-inline.js';

export { AcuteMeshError } from './api.js';

function decode(base64) {
  if (typeof atob === 'function') {
    const text = atob(base64);
    const bytes = new Uint8Array(text.length);
    for (let i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
    return bytes;
  }
  return Uint8Array.from(Buffer.from(base64, 'base64'));
}

function compile(options) {
  return WebAssembly.compile(options.wasmBinary !== undefined ? options.wasmBinary : decode(wasmBase64));
}

const entry = makeEntry(createAcuteMesh, compile);
export const createInstance = entry.createInstance;
export default entry.init;
