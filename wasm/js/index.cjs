'use strict';
// acutemesh for CommonJS: `const init = require('acutemesh')` (package.json's "require"
// condition under "node"), for every Node the package supports. The package itself is ES
// modules, which Node before 20.19 cannot require(), so this loads node.js with import() on
// the first call of init() or createInstance(); the API comes from their promise, as it does
// in ES modules. init is the export itself, and also its `default` and `init`.
let loaded;
const load = () => (loaded = loaded || import('./node.js'));

function init(options) {
  return load().then((m) => m.default(options));
}

function createInstance(options) {
  return load().then((m) => m.createInstance(options));
}

// The ES module's AcuteMeshError cannot be had synchronously here. This class stands in for
// it: `instanceof` recognises acutemesh's errors by their name, from whichever module they came.
class AcuteMeshError extends Error {
  constructor(code, message) {
    super(message);
    this.name = 'AcuteMeshError';
    this.code = code;
  }

  static [Symbol.hasInstance](value) {
    return value instanceof Error && value.name === 'AcuteMeshError';
  }
}

module.exports = init;
init.default = init;
init.init = init;
init.createInstance = createInstance;
init.AcuteMeshError = AcuteMeshError;
