#!/usr/bin/env bash
# `npm run bench`: acutemesh against CGAL on Delaunay and constrained Delaunay triangulation.
#
#  1. installs what only the bench needs (libcgal-dev, GNU time); never a core dependency;
#  2. builds our CLI in build/ (Release) and bench_acutemesh + bench_cgal in build-bench/;
#  3. generates inputs into bench/work/ (gitignored; kept between runs);
#  4. per case: whole-process wall time and peak RSS of our CLI (--no-output) and of
#     `bench_cgal --once` (best of 3), and the library call alone (bench_acutemesh, bench_cgal:
#     best of 3 inside one process);
#  5. writes bench/results/core-YYYY-MM-DD.md and prints it.
#
# BENCH_QUICK=1 skips the 10^6-point case. A part that cannot run (our CLI or mesh() not
# built yet, a run that fails) shows as "n/a" and the rest still runs.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
# shellcheck source=bench/common.sh
source bench/common.sh

RUNS=3
BENCH_REQUIREMENTS=(
  "/usr/include/CGAL/Delaunay_triangulation_2.h:libcgal-dev"  # pulls libgmp-dev, libmpfr-dev
  "/usr/include/mpfr.h:libmpfr-dev"
  "/usr/bin/time:time"
  "node:nodejs"
)
bash scripts/setup.sh
bash scripts/setup.sh --only "${BENCH_REQUIREMENTS[@]}"

jobs="$(nproc)"
note() { echo "bench: $*" >&2; }

# --- build ------------------------------------------------------------------------------------
# Our CLI alone (not the tests, which may be mid-change), in build/ as scripts/build.sh makes it.
have_cli=1
mkdir -p build
if ! { [[ -f build/CMakeCache.txt && ( -f build/Makefile || -f build/build.ninja ) ]] || cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DACUTEMESH_WERROR=ON; } >build/bench-cli.log 2>&1 ||
   ! cmake --build build --target acutemesh -j"$jobs" >>build/bench-cli.log 2>&1 || [[ ! -x build/acutemesh ]]; then
  have_cli=0
  note "our CLI did not build (see build/bench-cli.log); its columns will be n/a"
fi

if [[ ! -f build-bench/CMakeCache.txt || ! ( -f build-bench/Makefile || -f build-bench/build.ninja ) ]]; then
  cmake -S . -B build-bench -DCMAKE_BUILD_TYPE=Release -DACUTEMESH_BENCH=ON \
    -DACUTEMESH_TESTS=OFF -DACUTEMESH_CLI=OFF -DACUTEMESH_INSTALL=OFF >/dev/null
fi
cmake --build build-bench --target bench_cgal -j"$jobs" >/dev/null
BENCH_CGAL=build-bench/bench/bench_cgal
BENCH_OURS=build-bench/bench/bench_acutemesh
have_lib=1
if ! cmake --build build-bench --target bench_acutemesh -j"$jobs" >build-bench/bench_acutemesh.log 2>&1; then
  have_lib=0
  note "bench_acutemesh did not build (see build-bench/bench_acutemesh.log); its column will be n/a"
fi

# --- inputs -----------------------------------------------------------------------------------
# name | file | mode | generator arguments
CASES=(
  "uniform 10^5 points, Delaunay|bench/work/uniform-1e5.node|delaunay|points 100000"
  "uniform 10^6 points, Delaunay|bench/work/uniform-1e6.node|delaunay|points 1000000"
  "star polygon 10^5 edges, CDT|bench/work/star-1e5.poly|cdt|star 100000"
)
if [[ "${BENCH_QUICK:-0}" == 1 ]]; then
  CASES=("${CASES[0]}" "${CASES[2]}")
fi
mkdir -p bench/work bench/results
for c in "${CASES[@]}"; do
  IFS='|' read -r name file mode gen <<<"$c"
  if [[ ! -s "$file" ]]; then
    note "generating $file"
    read -r kind n <<<"$gen"
    node bench/gen.mjs "$kind" "$n" "$file.tmp"
    mv "$file.tmp" "$file"
  fi
done

# --- measuring --------------------------------------------------------------------------------
load_start=$(cut -d' ' -f1-3 /proc/loadavg)
# key=value from a result line
kv() { tr ' ' '\n' <<<"$2" | sed -n "s/^$1=//p" | head -n1; }

# whole CMD...: runs it RUNS times; prints "best_wall_seconds peak_rss_kb", or nothing on failure
whole() {
  local best="" rss="" i t0 t1 wall r
  local tf
  tf="$(mktemp)"
  for ((i = 0; i < RUNS; i++)); do
    t0=$(date +%s%N)
    if ! timeout 900 /usr/bin/time -f '%M' -o "$tf" "$@" >/dev/null 2>"$tf.err"; then
      note "failed: $* ($(tail -n 3 "$tf.err" | tr '\n' ' '))"
      rm -f "$tf" "$tf.err"
      return 0
    fi
    t1=$(date +%s%N)
    wall=$(((t1 - t0) / 1000))  # microseconds
    r=$(tail -n1 "$tf")
    if [[ -z "$best" || $wall -lt $best ]]; then best=$wall; fi
    if [[ -z "$rss" || $r -gt $rss ]]; then rss=$r; fi
  done
  rm -f "$tf" "$tf.err"
  awk -v w="$best" -v r="$rss" 'BEGIN { printf "%.3f %d\n", w / 1e6, r }'
}

fmt_s() { [[ -n "$1" ]] && awk -v x="$1" 'BEGIN { printf "%.3f", x }' || echo "n/a"; }
fmt_ms_as_s() { [[ -n "$1" ]] && awk -v x="$1" 'BEGIN { printf "%.3f", x / 1000 }' || echo "n/a"; }
fmt_mb() { [[ -n "$1" ]] && awk -v x="$1" 'BEGIN { printf "%.1f", x / 1024 }' || echo "n/a"; }

rows=()
details=()
for c in "${CASES[@]}"; do
  IFS='|' read -r name file mode gen <<<"$c"
  note "$name"

  ours_whole="" ours_rss="" cgal_whole="" cgal_rss="" ours_lib="" cgal_lib="" tris="" bpt="n/a"
  if ((have_cli)); then
    read -r ours_whole ours_rss < <(whole ./build/acutemesh --mode "$mode" --no-output "$file"; echo) || true
  fi
  read -r cgal_whole cgal_rss < <(whole "$BENCH_CGAL" --once "$file"; echo) || true

  if ((have_lib)); then
    if line=$(timeout 1800 "$BENCH_OURS" --mode "$mode" --repeat "$RUNS" "$file" 2>&1); then
      ours_lib=$(kv best_ms "$line")
      tris=$(kv triangles "$line")
      details+=("$line")
    else
      note "bench_acutemesh failed on $file: $line"
    fi
  fi
  if line=$("$BENCH_CGAL" --mode "$mode" --repeat "$RUNS" "$file" 2>&1); then
    cgal_lib=$(kv best_ms "$line")
    details+=("$line")
  else
    note "bench_cgal failed on $file: $line"
  fi
  if [[ -n "$ours_rss" && -n "$tris" && "$tris" -gt 0 ]]; then
    bpt=$(awk -v r="$ours_rss" -v t="$tris" 'BEGIN { printf "%.0f", r * 1024 / t }')
  fi
  rows+=("| $name | $(fmt_s "$ours_whole") | $(fmt_s "$cgal_whole") | $(fmt_ms_as_s "$ours_lib") | $(fmt_ms_as_s "$cgal_lib") | $(fmt_mb "$ours_rss") | $bpt | $(fmt_mb "$cgal_rss") |")
done

# --- report -----------------------------------------------------------------------------------
load_end=$(cut -d' ' -f1-3 /proc/loadavg)
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n1)
ram=$(awk '/^MemTotal/ { printf "%.1f GiB", $2 / 1048576 }' /proc/meminfo)
gxx=$(g++ --version | head -n1)
cgal_v=$(sed -n 's/^#define CGAL_VERSION \(.*\)/\1/p' /usr/include/CGAL/version.h)
cgal_pkg=$(dpkg-query -W -f '${Version}' libcgal-dev 2>/dev/null || echo "?")
commit=$(git rev-parse --short HEAD 2>/dev/null || echo "?")
if [[ -n "$(git status --porcelain -- core 2>/dev/null)" ]]; then commit="$commit + uncommitted core changes"; fi
today=$(date +%F)
out="$(report_path core)"

{
  echo "# acutemesh vs CGAL: Delaunay and constrained Delaunay ($today)"
  echo
  echo "Machine: $cpu, $(nproc) cores, $ram RAM; $gxx; CGAL $cgal_v (Debian libcgal-dev $cgal_pkg, header-only);"
  echo "$(uname -sr); acutemesh $commit. Both built with CMake Release (-O3 -DNDEBUG)."
  echo "Load average before / after the runs: $load_start / $load_end (other work on a 2-core machine skews timings)."
  echo
  echo "| case | ours whole-process s | CGAL whole-process s | ours library s | CGAL library s | our peak RSS MB | our bytes/triangle | CGAL peak RSS MB |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|"
  printf '%s\n' "${rows[@]}"
  echo
  echo "- Whole process: read the file, triangulate, write nothing: \`build/acutemesh --mode MODE --no-output FILE\`"
  echo "  vs \`bench_cgal --once FILE\`; wall time best of $RUNS runs, peak RSS from GNU time (%M)."
  echo "- Library: the triangulation call alone on input already in memory, best of $RUNS in one process:"
  echo "  \`acutemesh::mesh(pslg, {Mode::Delaunay or Mode::Cdt})\` vs CGAL \`Delaunay_triangulation_2\` range insert"
  echo "  (spatial sort) / \`Constrained_Delaunay_triangulation_2::insert_constraint(first, last, close)\` on the"
  echo "  polygon's vertices in order (3x faster here than \`insert_constraints(points, index pairs)\`), plus the"
  echo "  nesting-level flood fill that marks the polygon's inside (acutemesh's Cdt mode also restricts to"
  echo "  the domain; domain_ms below), Epick kernel."
  echo "- Bytes/triangle: our whole-process peak RSS / output triangles (includes the parsed input)."
  echo "- Inputs (bench/gen.mjs, fixed seed): uniform random points in the unit square; a star-shaped"
  echo "  polygon with sorted random angles and radii in [0.5, 1]."
  echo
  echo "Raw library lines:"
  echo
  echo '```'
  printf '%s\n' "${details[@]}"
  echo '```'
} >"$out"

echo
cat "$out"
echo
echo "bench: wrote $out"
