#!/usr/bin/env bash
# Everything CI checks: setup, build, C++ tests (native, and built with emcc under node),
# JavaScript tests of the npm package. Exits non-zero on the first failure.
# Tests on the reference data (ACUTEMESH_DATA, else ../shared/data beside the repository: the
# 150 CG:SHOP instances, Lake Superior) run when it is there and are skipped when it is not;
# the last line counts them (each suite notes its skips in $ACUTEMESH_TEST_SKIPS).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

skips=$(mktemp -d)
trap 'rm -rf "$skips"' EXIT
skips_to() { export ACUTEMESH_TEST_SKIPS=$skips/$1; }
# Each stage's time, so that the 20-minute target can be kept where it is spent.
stage_start=$SECONDS
stage() { echo "test.sh: $1 took $((SECONDS - stage_start)) s (total $SECONDS s)"; stage_start=$SECONDS; }

bash scripts/setup.sh
bash scripts/build.sh
stage "setup and build"

# --- C++ tests (native) ----------------------------------------------------------------------
skips_to native
ctest --test-dir build --output-on-failure -j2
stage "native C++ tests"
# The same suite under ASan + UBSan (build-asan/), and each libFuzzer harness for a bounded
# time (build-fuzz/; FUZZ_SECONDS, default 60 in all). Both build once, then only rebuild.
skips_to sanitized
bash scripts/test-sanitize.sh
stage "ASan + UBSan"
bash scripts/fuzz.sh
stage "fuzzing"

# --- JavaScript / WebAssembly tests (node) ---------------------------------------------------
# The C++ suite built with emcc, each test run by node (the toolchain's emulator).
NODE_PATH=/usr/share/nodejs cmake --build build-wasm -j"$(nproc)"
skips_to wasm
ctest --test-dir build-wasm --output-on-failure -j2
stage "wasm build and C++ tests"
# The npm package in dist/ (built by build.sh): API, modes, errors, heap, types, worker, pack.
skips_to js
node --test tests/js/
stage "JavaScript tests"

# --- Browser tests (headless Chromium) -------------------------------------------------------
# The web page under playwright-core with Debian's chromium; screenshots in build/web-artifacts/.
node --test --test-concurrency=1 tests/web/
stage "browser tests"

# --- What did not run ------------------------------------------------------------------------
count() {  # count STAGE SUITE: the skips a suite noted in one stage
  if [[ -f $skips/$1 ]]; then grep -c "^$2 " "$skips/$1" || true; else echo 0; fi
}
total=0
for f in "$skips"/*; do
  if [[ -f $f ]]; then total=$((total + $(wc -l <"$f"))); fi
done
if ((total)); then
  echo "skipped: $total tests need reference data (ACUTEMESH_DATA or ../shared/data):" \
    "C++ $(count native 'C++') native + $(count sanitized 'C++') sanitized + $(count wasm 'C++') wasm," \
    "CLI checks $(count native CLI) + $(count sanitized CLI) sanitized, JavaScript $(count js JS)"
else
  echo "skipped: none (reference data found)"
fi
