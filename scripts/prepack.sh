#!/usr/bin/env bash
# npm's "prepack" step (npm pack, npm publish): builds what the tarball ships, dist/ (the
# WebAssembly module and the JavaScript facade), with `bash scripts/build.sh --package`, and
# refuses when the toolchain is missing rather than let npm pack a package without dist/.
# Its messages go to stderr: `npm pack --json` prints its result on stdout.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
exec 1>&2

missing=()
for tool in cmake emcmake emcc node; do
  command -v "$tool" >/dev/null 2>&1 || missing+=("$tool")
done
# build-wasm/ also holds the C++ tests (compiled from GoogleTest's sources): configuring it
# needs them, as scripts/test.sh does.
if [[ ! -f build-wasm/CMakeCache.txt && ! -f /usr/src/googletest/CMakeLists.txt ]]; then
  missing+=("/usr/src/googletest")
fi
if ((${#missing[@]})); then
  echo "prepack: cannot build the package's dist/: missing ${missing[*]}."
  echo "prepack: the WebAssembly build needs cmake, Emscripten (emcc, emcmake) and GoogleTest's"
  echo "prepack: sources (Debian: cmake emscripten libgtest-dev; bash scripts/setup.sh installs"
  echo "prepack: them as root). Nothing was packed."
  exit 1
fi

bash scripts/build.sh --package

# What the package's exports name must be there (assemble.mjs writes all of dist/).
for f in acutemesh.wasm acutemesh.mjs index.js node.js single.js worker.js worker-node.js \
  index.d.ts single.d.ts worker.d.ts; do
  if [[ ! -s dist/$f ]]; then
    echo "prepack: dist/$f is missing after the build. Nothing was packed."
    exit 1
  fi
done
echo "prepack: dist/ is built"
