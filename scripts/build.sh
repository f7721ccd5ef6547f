#!/usr/bin/env bash
# Release build of the library, the CLI and the C++ tests into build/, and the web page's
# vendored modules into web/vendor/.
# Configures only when build/CMakeCache.txt is missing, or when an earlier configure failed
# before writing the build files (cmake re-runs itself when a CMakeLists.txt changes); extra
# arguments go to that configure, e.g.
#   bash scripts/build.sh -DACUTEMESH_TESTS=OFF
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

if [[ ! -f build/CMakeCache.txt || ! ( -f build/Makefile || -f build/build.ninja ) ]]; then
  gen=()
  if ! command -v make >/dev/null 2>&1 && command -v ninja >/dev/null 2>&1; then
    gen=(-G Ninja)
  fi
  cmake -S . -B build "${gen[@]}" -DCMAKE_BUILD_TYPE=Release "$@"
fi
cmake --build build -j"$(nproc)"

# The web page's third-party ES modules (opentype.js, topojson-client) into web/vendor/.
node scripts/build-web.mjs
