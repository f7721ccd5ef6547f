#!/usr/bin/env bash
# `npm run bench:wasm`: the npm package's WebAssembly build against the native library, on the
# refinement inputs of bench/refine.sh (acute and non-obtuse) and on Delaunay of 10^6 uniform
# points, plus delaunator 5.1 in the same Node on the same points, and the .wasm's size.
#
#  1. setup + scripts/build.sh (native build/ and the package's dist/), bench_acutemesh in
#     build-bench/ (the native library call, as bench/run.sh builds it);
#  2. inputs: bench/inputs/data/ (the committed refinement inputs), tests/data/A.poly, Lake Superior
#     from the reference data ($ACUTEMESH_DATA, else ../shared/data; skipped without it),
#     and bench/work/uniform-1e6.node (bench/gen.mjs, the same file bench/run.sh uses);
#  3. bench/wasm.mjs, per input and mode, one right after the other (so load changes on this
#     shared machine hit both alike): native `bench_acutemesh --repeat N` (best of N library
#     calls), the same calls through dist/ (best of N, timed around am.mesh(), so copying the
#     arrays in and out of wasm counts), and delaunator on the 10^6 points;
#  4. it writes bench/results/wasm-YYYY-MM-DD.md (machine, load, versions), printed here.
#
# WASM_BENCH_RUNS (default 10) repeats for the refinement inputs; the 10^6-point case uses 3.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
# shellcheck source=bench/common.sh
source bench/common.sh

RUNS="${WASM_BENCH_RUNS:-10}"
note() { echo "bench:wasm: $*" >&2; }

bash scripts/setup.sh
bash scripts/build.sh >build/bench-wasm-build.log 2>&1 || {
  tail -n 30 build/bench-wasm-build.log >&2
  exit 1
}
if [[ ! -f build-bench/CMakeCache.txt || ! ( -f build-bench/Makefile || -f build-bench/build.ninja ) ]]; then
  cmake -S . -B build-bench -DCMAKE_BUILD_TYPE=Release -DACUTEMESH_BENCH=ON \
    -DACUTEMESH_TESTS=OFF -DACUTEMESH_CLI=OFF -DACUTEMESH_INSTALL=OFF >/dev/null
fi
cmake --build build-bench --target bench_acutemesh -j"$(nproc)" >/dev/null
NATIVE=build-bench/bench/bench_acutemesh

mkdir -p bench/work bench/results
if [[ ! -s bench/work/uniform-1e6.node ]]; then
  note "generating bench/work/uniform-1e6.node"
  node bench/gen.mjs points 1000000 bench/work/uniform-1e6.node.tmp
  mv bench/work/uniform-1e6.node.tmp bench/work/uniform-1e6.node
fi

out="$(report_path wasm)"
EMCC_VERSION="$(emcc --version | head -n1 | grep -oE '[0-9]+\.[0-9]+\.[0-9]+' | head -n1)" WASM_BENCH_RUNS="$RUNS" \
  node bench/wasm.mjs "$NATIVE" "$out"
echo
cat "$out"
echo
echo "bench:wasm: wrote $out"
