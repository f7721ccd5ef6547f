#!/usr/bin/env bash
# Everything CI checks: setup, build, C++ tests (native, and built with emcc under node),
# JavaScript tests of the npm package. Exits non-zero on the first failure.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/setup.sh
bash scripts/build.sh

# --- C++ tests (native) ----------------------------------------------------------------------
ctest --test-dir build --output-on-failure -j2
# The same suite under ASan + UBSan (build-asan/), and each libFuzzer harness for a bounded
# time (build-fuzz/; FUZZ_SECONDS, default 60 in all). Both build once, then only rebuild.
bash scripts/test-sanitize.sh
bash scripts/fuzz.sh

# --- JavaScript / WebAssembly tests (node) ---------------------------------------------------
# The C++ suite built with emcc, each test run by node (the toolchain's emulator).
NODE_PATH=/usr/share/nodejs cmake --build build-wasm -j"$(nproc)"
ctest --test-dir build-wasm --output-on-failure -j2
# The npm package in dist/ (built by build.sh): API, modes, errors, heap, types, worker, pack.
node --test tests/js/

# --- Browser tests (headless Chromium) -------------------------------------------------------
# The web page under playwright-core with Debian's chromium; screenshots in build/web-artifacts/.
node --test --test-concurrency=1 tests/web/
