#!/usr/bin/env bash
# `npm run bench:refine`: acute and non-obtuse refinement on the seed paper's kinds of input and
# on the 150 CG:SHOP 2025 instances, next to the published and measured figures to beat.
#
#  1. installs what only this bench needs (fonts-dejavu-core for the text outlines, opentype.js
#     through package.json's devDependencies); never a core dependency;
#  2. builds our CLI in build/ (scripts/build.sh when build/ is not configured yet, otherwise
#     just the acutemesh target, so tests being edited elsewhere do not block it);
#  3. generates the inputs into bench/work/refine/ (bench/inputs/text.mjs, shapes.mjs) and
#     notes any that differ from the committed copies in bench/inputs/data/;
#  4. per input: `build/acutemesh --mode cdt|acute|nonobtuse --stats --no-output INPUT` (text
#     outlines with --fill nonzero), best of $REFINE_RUNS by the CLI's own seconds.total, and
#     `--mode quality --min-angle A` once for A in 30, 35, 40, 42; the unit square refined to an
#     area bound of 1e-6 (throughput, best of $REFINE_RUNS); per
#     CG:SHOP instance: cdt once, nonobtuse and acute best of $CGSHOP_RUNS (the meshes are the
#     same each time; the best time is the one least disturbed by whatever else the machine
#     runs). Each run's stdout, stderr and exit status are kept in bench/work/refine/runs/;
#  5. bench/inputs/report.mjs reads them and writes bench/results/refine-YYYY-MM-DD.md (and
#     bench/work/refine/cgshop.csv, one line per instance), then it is printed.
#
# A mode the CLI does not offer yet (exit 2, "not available") is probed once and shows as
# "n/a"; the cdt rows are the plain constrained Delaunay starting point, not a refinement.
#
# Environment: REFINE_RUNS (default 3) runs per table input, CGSHOP_RUNS (default 3) per
# CG:SHOP instance and refinement mode; REFINE_TIME_LIMIT (default 60) and
# CGSHOP_TIME_LIMIT (default 10) seconds passed as --time-limit to the refinement modes (a run
# is killed at twice that + 10 s); REFINE_QUICK=1: one run each, no CG:SHOP section.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
# shellcheck source=bench/common.sh
source bench/common.sh

RUNS="${REFINE_RUNS:-3}"
CGSHOP_RUNS="${CGSHOP_RUNS:-3}"
TIME_LIMIT="${REFINE_TIME_LIMIT:-60}"
CGSHOP_LIMIT="${CGSHOP_TIME_LIMIT:-10}"
QUICK="${REFINE_QUICK:-0}"
QUALITY_ANGLES="30 35 40 42"
if [[ "$QUICK" == 1 ]]; then RUNS=1; fi
FONT=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
# The reference data (Lake Superior, the CG:SHOP instances), by the tests' rule: $ACUTEMESH_DATA,
# else ../shared/data; without it those rows are left out and the report says so.
SHARED="${ACUTEMESH_DATA-../shared/data}"
if [[ -n "$SHARED" && "$SHARED" != /* ]]; then SHARED="$PWD/$SHARED"; fi
REFINE_REQUIREMENTS=(
  "$FONT:fonts-dejavu-core"
  "node:nodejs"
)
bash scripts/setup.sh  # the project's requirements and npm packages (opentype.js)
bash scripts/setup.sh --only "${REFINE_REQUIREMENTS[@]}"

jobs="$(nproc)"
note() { echo "bench:refine: $*" >&2; }
WORK=bench/work/refine
RUNDIR="$WORK/runs"
mkdir -p "$WORK" bench/results build
rm -rf "$RUNDIR"
mkdir -p "$RUNDIR"

# --- build ------------------------------------------------------------------------------------
have_cli=1
if [[ ! -f build/CMakeCache.txt || ! ( -f build/Makefile || -f build/build.ninja ) ]]; then
  note "configuring and building build/ (scripts/build.sh)"
  bash scripts/build.sh >build/bench-refine.log 2>&1 ||
    cmake --build build --target acutemesh -j"$jobs" >>build/bench-refine.log 2>&1 || have_cli=0
else
  cmake --build build --target acutemesh -j"$jobs" >build/bench-refine.log 2>&1 || have_cli=0
fi
if ((have_cli == 0)) || [[ ! -x build/acutemesh ]]; then
  have_cli=0
  note "our CLI did not build (see build/bench-refine.log); every row will be n/a"
fi

# --- inputs -----------------------------------------------------------------------------------
# id | label | file | extra CLI arguments | reference key (report.mjs) | generator
CASES=(
  "acute-text|\"Acute\" (DejaVu Sans outline)|$WORK/acute-text.json|--fill nonzero|acute-text|text Acute"
  "acutemesh-text|\"acutemesh\" (DejaVu Sans outline)|$WORK/acutemesh-text.json|--fill nonzero||text acutemesh"
  "A|A.poly (Triangle's letter A)|tests/data/A.poly||A|"
  "superior|superior.poly (Lake Superior, 6 islands)|$SHARED/poly/superior.poly||superior|"
  "random|Random: 1000 uniform points + 4 corners|$WORK/random.node||random|shapes random"
  "plate|plate: 3 round holes and a slot|$WORK/plate.poly||plate|shapes plate"
  "naca0012|NACA 0012 airfoil in a far-field box|$WORK/naca0012.poly|||shapes naca"
)
: >"$WORK/inputs-differ.txt"
: >"$WORK/cases.txt"
for c in "${CASES[@]}"; do
  IFS='|' read -r id label file args ref gen <<<"$c"
  if [[ -z "$gen" && ! -f "$file" ]]; then
    note "skipped: $label (needs the reference data: set ACUTEMESH_DATA, or put it at ../shared/data)"
    continue
  fi
  if [[ -n "$gen" ]]; then
    read -r kind arg <<<"$gen"
    if [[ "$kind" == text ]]; then
      node bench/inputs/text.mjs "$arg" "$file.tmp" "$FONT"
    else
      node bench/inputs/shapes.mjs "$arg" "$file.tmp"
    fi
    mv "$file.tmp" "$file"
    committed="bench/inputs/data/$(basename "$file")"
    if [[ -f "$committed" ]] && ! cmp -s "$file" "$committed"; then
      note "$file differs from $committed (another font version?)"
      echo "$(basename "$file")" >>"$WORK/inputs-differ.txt"
    fi
  fi
  printf '%s|%s|%s|%s|%s\n' "$id" "$label" "$file" "$args" "$ref" >>"$WORK/cases.txt"
done

# --- measuring --------------------------------------------------------------------------------
load_start=$(cut -d' ' -f1-3 /proc/loadavg)

# run_one OUT KILL_AFTER_S ARGS...: OUT.json (stdout), OUT.err, OUT.rc (124: killed by timeout)
run_one() {
  local out="$1" kill_after="$2" rc=0
  shift 2
  timeout "$kill_after" ./build/acutemesh "$@" >"$out.json" 2>"$out.err" </dev/null || rc=$?
  echo "$rc" >"$out.rc"
}

# Which modes this CLI offers: a mode it rejects with exit 2 on A.poly is "not available".
: >"$RUNDIR/modes.tsv"
for mode in cdt acute nonobtuse; do
  state=available
  if ((have_cli)); then
    run_one "$RUNDIR/probe-$mode" 60 --mode "$mode" --stats --no-output tests/data/A.poly
    if [[ "$(cat "$RUNDIR/probe-$mode.rc")" == 2 ]]; then
      state=unavailable
      note "mode $mode: $(head -n1 "$RUNDIR/probe-$mode.err")"
    fi
  else
    state=unavailable
  fi
  printf '%s\t%s\t%s\n' "$mode" "$state" "$(head -n1 "$RUNDIR/probe-$mode.err" 2>/dev/null || true)" >>"$RUNDIR/modes.tsv"
done
available() { grep -q "^$1	available" "$RUNDIR/modes.tsv"; }

while IFS='|' read -r id label file args ref; do
  for mode in cdt acute nonobtuse; do
    available "$mode" || continue
    note "$id: $mode"
    limit=()
    [[ "$mode" == cdt ]] || limit=(--time-limit "$TIME_LIMIT")
    for ((k = 1; k <= RUNS; k++)); do
      # shellcheck disable=SC2086  # args: a few words, no spaces inside
      run_one "$RUNDIR/$id.$mode.$k" $((2 * TIME_LIMIT + 10)) --mode "$mode" "${limit[@]}" $args \
        --stats --no-output "$file"
    done
  done
  # Quality refinement at high minimum angles (where circumcentre insertion stops
  # terminating): one run each, at the bounds QUALITY_ANGLES lists.
  for angle in $QUALITY_ANGLES; do
    note "$id: quality $angle"
    # shellcheck disable=SC2086
    run_one "$RUNDIR/$id.quality$angle.1" $((2 * TIME_LIMIT + 10)) --mode quality --min-angle "$angle" \
      --time-limit "$TIME_LIMIT" $args --stats --no-output "$file"
  done
done <"$WORK/cases.txt"

# Throughput: the unit square refined to an area bound of 1e-6 (about 1.5M triangles, default
# minimum angle 20), best of $RUNS.
printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' >"$WORK/square.poly"
if ((have_cli)); then
  note "throughput: unit square, --max-area 1e-6"
  for ((k = 1; k <= RUNS; k++)); do
    run_one "$RUNDIR/throughput.$k" $((2 * TIME_LIMIT + 10)) --mode quality --max-area 1e-6 \
      --time-limit "$TIME_LIMIT" --stats --no-output "$WORK/square.poly"
  done
fi

cgshop_dir=""
if [[ "$QUICK" != 1 && ! -d "$SHARED/cgshop2025" ]]; then
  note "skipped: the CG:SHOP 2025 instances (needs the reference data: set ACUTEMESH_DATA, or put it at ../shared/data)"
fi
if [[ "$QUICK" != 1 && -d "$SHARED/cgshop2025" ]]; then
  cgshop_dir="$SHARED/cgshop2025"
  mkdir -p "$RUNDIR/cgshop"
  for mode in cdt nonobtuse acute; do
    available "$mode" || continue
    note "CG:SHOP 2025, 150 instances: $mode"
    limit=() runs=1
    [[ "$mode" == cdt ]] || limit=(--time-limit "$CGSHOP_LIMIT") runs=$CGSHOP_RUNS
    for ((k = 1; k <= runs; k++)); do
      for f in "$cgshop_dir"/*.instance.json; do
        run_one "$RUNDIR/cgshop/$(basename "$f" .instance.json).$mode.$k" $((2 * CGSHOP_LIMIT + 10)) \
          --mode "$mode" "${limit[@]}" --stats --no-output "$f"
      done
    done
  done
  # The non-obtuse solutions written and checked on their own: tests/cli/verify_cgshop.mjs
  # (BigInt rationals; the triangles from the .ele of the same run). Not timed.
  if available nonobtuse; then
    note "CG:SHOP 2025: non-obtuse solutions, verified"
    for f in "$cgshop_dir"/*.instance.json; do
      base="$RUNDIR/cgshop/$(basename "$f" .instance.json).solution"
      rc=0
      timeout $((2 * CGSHOP_LIMIT + 10)) ./build/acutemesh --mode nonobtuse --time-limit "$CGSHOP_LIMIT" \
        --format cgshop,ele -o "$base" "$f" >/dev/null 2>&1 || rc=$?
      if ((rc == 0)); then
        node tests/cli/verify_cgshop.mjs "$f" "$base.solution.json" "$base.ele" >"$base.verify" 2>&1 || rc=$?
      fi
      echo "$rc" >"$base.verify.rc"
      rm -f "$base.ele"
    done
  fi
fi

# --- report -----------------------------------------------------------------------------------
out="$(report_path refine)"
QUALITY_ANGLES="$QUALITY_ANGLES" LOAD_START="$load_start" RUNS="$RUNS" CGSHOP_RUNS="$CGSHOP_RUNS" \
  TIME_LIMIT="$TIME_LIMIT" CGSHOP_LIMIT="$CGSHOP_LIMIT" \
  node bench/inputs/report.mjs --work "$WORK" --cgshop "$cgshop_dir" --out "$out"
echo
cat "$out"
echo
echo "bench:refine: wrote $out (per instance: $WORK/cgshop.csv)"
