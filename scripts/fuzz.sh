#!/usr/bin/env bash
# Builds the libFuzzer harnesses (tests/fuzz) with clang, ASan and UBSan into build-fuzz/ and
# runs each for a bounded time; fails on any crash, leak, sanitizer report or failed check.
#
#   bash scripts/fuzz.sh                       about 60 s in all (FUZZ_SECONDS=60)
#   FUZZ_SECONDS=3600 bash scripts/fuzz.sh     an hour, split between the harnesses
#   FUZZ_ONLY=fuzz_mesh bash scripts/fuzz.sh   one harness
#   FUZZ_SEED=0 bash scripts/fuzz.sh           a random seed (default 1: CI explores the same
#                                              inputs each run, so main stays green unless a
#                                              change breaks them; hunt with other seeds)
#
# Each harness starts from its seed corpus in tests/fuzz/corpus/<harness>/ (in the repo) plus
# what earlier runs found (build-fuzz/corpus/<harness>/, kept between runs). A finding is
# saved as build-fuzz/artifacts/<harness>-crash-*: reproduce it with
#   build-fuzz/<harness> build-fuzz/artifacts/<harness>-crash-...
# then fix the bug and copy the input into tests/fuzz/corpus/<harness>/ (or tests/data/bad).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

total=${FUZZ_SECONDS:-60}
harnesses=(${FUZZ_ONLY:-fuzz_triangle fuzz_json fuzz_mesh})
jobs=${FUZZ_JOBS:-2}
seed=${FUZZ_SEED:-1}

if ! command -v clang++ >/dev/null 2>&1; then
  echo "fuzz: clang++ is missing (bash scripts/setup.sh installs it)" >&2
  exit 1
fi
flags="-O1 -gline-tables-only -fno-omit-frame-pointer -fsanitize=fuzzer-no-link,address,undefined"
flags+=" -fno-sanitize-recover=all"
# Configured each time, so that an older build-fuzz/ gets these flags too. (They are the build
# type's own: in CMAKE_CXX_FLAGS, its -O2 -g would come after them and win.)
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS= -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$flags" -DACUTEMESH_FUZZ=ON \
  -DACUTEMESH_TESTS=OFF -DACUTEMESH_CLI=OFF -DACUTEMESH_INSTALL=OFF -DACUTEMESH_WERROR=ON >/dev/null
log=build-fuzz/build.log
if ! cmake --build build-fuzz -j"$jobs" --target "${harnesses[@]}" >"$log" 2>&1; then
  grep -E "error|Error" "$log" | head -n 30 >&2
  echo "fuzz: the build failed (build-fuzz/build.log)" >&2
  exit 1
fi

each=$(( total / ${#harnesses[@]} ))
((each >= 1)) || each=1
mkdir -p build-fuzz/artifacts
status=0
for h in "${harnesses[@]}"; do
  mkdir -p "build-fuzz/corpus/$h"
  log="build-fuzz/$h.log"
  # New inputs go to the first corpus directory (build-fuzz), never into the repo's seeds.
  if ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 \
     UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
     "build-fuzz/$h" -seed="$seed" -max_total_time="$each" -timeout=20 -rss_limit_mb=2048 -max_len=4096 \
       -print_final_stats=1 -artifact_prefix="build-fuzz/artifacts/$h-" \
       "build-fuzz/corpus/$h" "tests/fuzz/corpus/$h" >"$log" 2>&1; then
    execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')
    cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo '?')
    echo "fuzz: $h: ${each} s, $execs runs, coverage $cov, no finding"
  else
    status=1
    echo "fuzz: $h: FINDING (log: $log)" >&2
    grep -E 'ERROR|fuzz finding|SUMMARY|Test unit written' "$log" | head -n 10 >&2 || tail -n 30 "$log" >&2
  fi
done
exit $status
