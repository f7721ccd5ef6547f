// acutemesh/single: the same API as 'acutemesh', with the .wasm embedded in the JavaScript.
export * from './index.js';
export { default } from './index.js';
