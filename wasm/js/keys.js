// Option objects are checked key by key: a misspelt option would otherwise be ignored in
// silence and the default used. Unknown keys are TypeErrors in the core's style for unknown
// names (vocabulary.cpp): the choices, and the nearest when one explains the slip.

// The keys of mesh()'s options (validate() takes the same object); the resolved options a
// mesh carries (MeshResult.options) are a subset.
export const MESH_OPTION_KEYS = ['mode', 'fill', 'convexHull', 'exactSegments', 'exactFeet',
  'maxAngle', 'minAngle', 'maxArea', 'maxEdge', 'size', 'grading', 'maxSteiner', 'timeLimit',
  'onProgress', 'signal', 'adjacency', 'optimize', 'optimizeTries', 'seed'];

// mesh()'s optimize search was asked for, in seconds or tries (the core's searchAsked).
export const searchAsked = (options) => options.optimize > 0 || options.optimizeTries > 0;

// init() and createInstance(); a worker's init options are these less locateFile.
export const INIT_OPTION_KEYS = ['wasmUrl', 'locateFile', 'wasmBinary', 'wasmModule', 'maxMemory'];

// Edits (insert, delete or replace a letter, swap two neighbours) from a to b, ignoring case.
function editDistance(a, b) {
  a = a.toLowerCase();
  b = b.toLowerCase();
  const w = b.length + 1;
  const d = new Array((a.length + 1) * w);
  for (let i = 0; i <= a.length; ++i) d[i * w] = i;
  for (let j = 0; j <= b.length; ++j) d[j] = j;
  for (let i = 1; i <= a.length; ++i) {
    for (let j = 1; j <= b.length; ++j) {
      let best = Math.min(d[(i - 1) * w + j] + 1, d[i * w + j - 1] + 1,
        d[(i - 1) * w + j - 1] + (a[i - 1] === b[j - 1] ? 0 : 1));
      if (i > 1 && j > 1 && a[i - 1] === b[j - 2] && a[i - 2] === b[j - 1])
        best = Math.min(best, d[(i - 2) * w + j - 2] + 1);
      d[i * w + j] = best;
    }
  }
  return d[d.length - 1];
}

// The one key within two edits that change less than half of it ('maxangle' suggests
// 'maxAngle', 'threads' nothing), else undefined.
export function nearestKey(key, allowed) {
  let nearest;
  let best = 3;
  let tie = false;
  for (const candidate of allowed) {
    const d = editDistance(key, candidate);
    if (2 * d >= Math.max(key.length, candidate.length)) continue;
    if (d < best) {
      best = d;
      nearest = candidate;
      tie = false;
    } else if (d === best) {
      tie = true;
    }
  }
  return tie ? undefined : nearest;
}

// Throws a TypeError for the first own key of `options` not in `allowed`:
//   unknown option 'maxangle' of mesh() (mode, fill, ...): did you mean 'maxAngle'?
export function checkKeys(options, allowed, where) {
  for (const key of Object.keys(options)) {
    if (allowed.includes(key)) continue;
    const nearest = nearestKey(key, allowed);
    throw new TypeError(`unknown option '${key}' of ${where} (${allowed.join(', ')})` +
      (nearest === undefined ? '' : `: did you mean '${nearest}'?`));
  }
}
