// Linked into the C++ tests built with emcc (--pre-js): Emscripten's getenv sees only its own
// defaults, not node's environment, so the variables the tests read (reference_data.h) are
// copied into it before main() runs.
Module['preRun'] = (Module['preRun'] || []).concat(function () {
  if (typeof process === 'undefined' || typeof ENV === 'undefined') return;
  for (const name of ['ACUTEMESH_DATA', 'ACUTEMESH_TEST_SKIPS'])
    if (process.env[name] !== undefined) ENV[name] = process.env[name];
});
