#!/usr/bin/env bash
# Release builds:
#  - native: the library, the CLI and the C++ tests into build/;
#  - WebAssembly: the same CMakeLists.txt through emcmake into build-wasm/ (the Embind module
#    and the C++ tests for node), then the npm package's dist/ (wasm/assemble.mjs);
#  - the web page's vendored modules into web/vendor/.
# Each configures only when its CMakeCache.txt is missing, or when an earlier configure failed
# before writing the build files (cmake re-runs itself when a CMakeLists.txt changes); extra
# arguments go to the native configure, e.g.
#   bash scripts/build.sh -DACUTEMESH_TESTS=OFF
# ACUTEMESH_WASM_TARGETS (default: the module only) picks what build-wasm/ builds; test.sh
# builds everything there. With nothing changed the whole script takes a few seconds.
#   bash scripts/build.sh --package    only the npm package: build-wasm's module and dist/
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
package_only=0
if [[ "${1:-}" == "--package" ]]; then
  package_only=1
  shift
fi

configured() { [[ -f "$1/CMakeCache.txt" && ( -f "$1/Makefile" || -f "$1/build.ninja" ) ]]; }
gen=()
if ! command -v make >/dev/null 2>&1 && command -v ninja >/dev/null 2>&1; then
  gen=(-G Ninja)
fi

if ((!package_only)); then
  if ! configured build; then
    cmake -S . -B build "${gen[@]}" -DCMAKE_BUILD_TYPE=Release -DACUTEMESH_WERROR=ON "$@"
  fi
  cmake --build build -j"$(nproc)"
fi

# --- WebAssembly --------------------------------------------------------------------------
# Debian's emcc runs its JS optimizer with node, which finds acorn only in /usr/share/nodejs.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
if ! command -v emcmake >/dev/null 2>&1; then
  echo "build: emcmake not found (bash scripts/setup.sh installs emscripten)" >&2
  exit 1
fi
if ! configured build-wasm; then
  # emcmake would set the emulator (ctest's runner for the C++ tests) to
  # "node --experimental-wasm-threads", a flag Node 20 rejects: plain node it is.
  emcmake cmake -S . -B build-wasm "${gen[@]}" -DCMAKE_BUILD_TYPE=Release -DACUTEMESH_WERROR=ON \
    -DCMAKE_CROSSCOMPILING_EMULATOR="$(command -v node)"
fi
# shellcheck disable=SC2086  # a list of target names
cmake --build build-wasm -j"$(nproc)" --target ${ACUTEMESH_WASM_TARGETS:-wasm_acutemesh}
node wasm/assemble.mjs build-wasm dist
if ((package_only)); then exit 0; fi

# The web page's third-party ES modules (opentype.js, topojson-client) into web/vendor/.
node scripts/build-web.mjs
