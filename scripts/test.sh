#!/usr/bin/env bash
# Everything CI checks: setup, build, C++ tests. Exits non-zero on the first failure.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/setup.sh
bash scripts/build.sh

# --- C++ tests (native) ----------------------------------------------------------------------
ctest --test-dir build --output-on-failure -j2

# --- JavaScript / WebAssembly tests (node) ---------------------------------------------------
# (to come: build the wasm package, then `node --test tests/js`)

# --- Browser tests (headless Chromium) -------------------------------------------------------
# The web page under playwright-core with Debian's chromium; screenshots in build/web-artifacts/.
node --test --test-concurrency=1 tests/web/
