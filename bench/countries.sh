#!/usr/bin/env bash
# `npm run bench:countries`: whole countries from the Digital Chart of the World (every island
# and lake): CDT, quality, acute and non-obtuse refinement at 10^4 to 10^6 input vertices
# (issue 25's targets).
#
#  1. installs what only this bench needs (GMT with its DCW country polygons, gmt-dcw, and the
#     GSHHG shorelines it reads them with, gmt-gshhg-full; GNU time); never a core dependency;
#  2. builds our CLI in build/ (the acutemesh target, as bench/run.sh does);
#  3. inputs, into bench/work/countries/ (kept between runs, made again when missing):
#     `gmt coast -E<ISO code> -M` (one '>' header per ring, lon/lat lines, each ring closed by
#     repeating its first point) turned into JSON rings by bench/inputs/countries.mjs (the
#     closing point dropped; even-odd fill, the rings' default: lakes and islands in lakes
#     come from nesting). Lon/lat degrees are meshed as plane coordinates;
#  4. per country and mode (cdt, quality at the default 20 degrees, acute, nonobtuse):
#     `build/acutemesh --mode MODE --stats --no-output --threads 2 --time-limit L INPUT`,
#     N runs (3 for the small countries, 1 for Canada and the United States), each under GNU
#     time (peak RSS) with its wall time, stdout, stderr and exit status kept in
#     bench/work/countries/runs/; acute also once through the npm package (dist/, WebAssembly
#     in Node; bench/inputs/countries_wasm.mjs) when dist/ is built (`bash scripts/build.sh
#     --package`), not for the one-run inputs (those two) unless COUNTRIES_WASM_ALL=1;
#  5. bench/inputs/countries_report.mjs writes bench/results/countries-YYYY-MM-DD.md (-2, -3, ...
#     for a later run the same day), printed here.
#
# BENCH_QUICK=1 skips Canada and the United States; COUNTRIES="gr no" runs just those;
# COUNTRIES_OPTIMIZE=S (whole seconds) adds one acute and one non-obtuse run with
# `--optimize S` per country (issue 27: the search by parts). A run cut by its --time-limit
# shows as "cut"; one killed (at twice the limit + 60 s) or failing shows its exit status and
# first error line.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
# shellcheck source=bench/common.sh
source bench/common.sh

note() { echo "bench:countries: $*" >&2; }
if [[ -n "${COUNTRIES_OPTIMIZE:-}" && ! "$COUNTRIES_OPTIMIZE" =~ ^[1-9][0-9]*$ ]]; then
  note "COUNTRIES_OPTIMIZE must be whole seconds, 1 or more, not '$COUNTRIES_OPTIMIZE'"
  exit 2
fi

COUNTRIES_REQUIREMENTS=(
  "/usr/bin/gmt:gmt"
  "/usr/share/gmt-dcw/dcw-gmt.nc:gmt-dcw"
  "/usr/share/gmt-gshhg/binned_GSHHS_f.nc:gmt-gshhg-full"
  "/usr/bin/time:time"
  "node:nodejs"
)
bash scripts/setup.sh --only "${COUNTRIES_REQUIREMENTS[@]}"

WORK=bench/work/countries
RUNDIR="$WORK/runs"
mkdir -p "$WORK" bench/results build
rm -rf "$RUNDIR"
mkdir -p "$RUNDIR"

# --- build ------------------------------------------------------------------------------------
# What the CLI is built from, taken now: the report comes minutes later, when the tree may have
# moved on.
{ git rev-parse --short HEAD && git status --porcelain -- core; } >"$RUNDIR/built-from.txt" 2>/dev/null || true
if ! { [[ -f build/CMakeCache.txt && ( -f build/Makefile || -f build/build.ninja ) ]] ||
       cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DACUTEMESH_WERROR=ON; } >build/bench-countries.log 2>&1 ||
   ! cmake --build build --target acutemesh -j"$(nproc)" >>build/bench-countries.log 2>&1 || [[ ! -x build/acutemesh ]]; then
  note "our CLI did not build (see build/bench-countries.log)"
  exit 1
fi

# --- inputs -----------------------------------------------------------------------------------
# id | label | ISO code | runs | time limit (s) for every run
CASES=(
  "gr|Greece|GR|3|60"
  "no|Norway (fjords)|NO|3|120"
  "id|Indonesia (archipelago)|ID|3|300"
  "ca|Canada|CA|1|600"
  "us|United States|US|1|600"
)
if [[ "${BENCH_QUICK:-0}" == 1 ]]; then CASES=("${CASES[@]:0:3}"); fi
: >"$WORK/cases.txt"
for c in "${CASES[@]}"; do
  IFS='|' read -r id label code runs limit <<<"$c"
  if [[ -n "${COUNTRIES:-}" && " $COUNTRIES " != *" $id "* ]]; then continue; fi
  file="$WORK/$id.json"
  if [[ ! -s "$file" ]]; then
    note "generating $file (gmt coast -E$code -M)"
    (cd "$WORK" && gmt coast -E"$code" -M >"$id.gmt.txt")  # in WORK: gmt leaves a gmt.history there
    note "$id: $(node bench/inputs/countries.mjs "$WORK/$id.gmt.txt" "$file.tmp")"
    mv "$file.tmp" "$file"
    rm -f "$WORK/$id.gmt.txt"
  fi
  printf '%s|%s|%s|%s|%s|%s\n' "$id" "$label" "$code" "$file" "$runs" "$limit" >>"$WORK/cases.txt"
done

# --- measuring --------------------------------------------------------------------------------
export LOAD_START
LOAD_START=$(cut -d' ' -f1-3 /proc/loadavg)

# timed OUT KILL_AFTER_S CMD...: OUT.json (stdout), OUT.err, OUT.rc (124: killed), OUT.time
# (GNU time: "%e %M"), OUT.wall (ms, from the clock around the process).
timed() {
  local out="$1" kill_after="$2" rc=0 t0 t1
  shift 2
  t0=$(date +%s%N)
  timeout "$kill_after" /usr/bin/time -f '%e %M' -o "$out.time" "$@" >"$out.json" 2>"$out.err" </dev/null || rc=$?
  t1=$(date +%s%N)
  echo "$rc" >"$out.rc"
  echo $(((t1 - t0) / 1000000)) >"$out.wall"
}

wasm=0
if [[ -f dist/acutemesh.wasm ]]; then wasm=1; else note "dist/ not built: the WASM column is n/a (bash scripts/build.sh --package)"; fi
while IFS='|' read -r id label code file runs limit; do
  for mode in cdt quality acute nonobtuse; do
    cut -d' ' -f1 /proc/loadavg >"$RUNDIR/$id.$mode.load"
    note "$id ($label): $mode x$runs, limit ${limit}s, load $(cat "$RUNDIR/$id.$mode.load")"
    for ((k = 1; k <= runs; k++)); do
      timed "$RUNDIR/$id.$mode.$k" $((2 * limit + 60)) ./build/acutemesh --mode "$mode" --stats --no-output \
        --threads 2 --time-limit "$limit" "$file"
    done
  done
  if [[ -n "${COUNTRIES_OPTIMIZE:-}" ]]; then
    for mode in acute nonobtuse; do
      cut -d' ' -f1 /proc/loadavg >"$RUNDIR/$id.$mode-optimize.load"
      note "$id ($label): $mode --optimize $COUNTRIES_OPTIMIZE, load $(cat "$RUNDIR/$id.$mode-optimize.load")"
      timed "$RUNDIR/$id.$mode-optimize.1" $((2 * limit + 60 + 2 * COUNTRIES_OPTIMIZE)) ./build/acutemesh --mode "$mode" \
        --stats --no-output --threads 2 --time-limit "$((limit + COUNTRIES_OPTIMIZE))" --optimize "$COUNTRIES_OPTIMIZE" "$file"
    done
  fi
  if ((wasm)) && [[ "$runs" -gt 1 || "${COUNTRIES_WASM_ALL:-0}" == 1 ]]; then
    cut -d' ' -f1 /proc/loadavg >"$RUNDIR/$id.wasm-acute.load"
    note "$id ($label): acute in Node (WASM), load $(cat "$RUNDIR/$id.wasm-acute.load")"
    timed "$RUNDIR/$id.wasm-acute.1" $((2 * limit + 60)) node bench/inputs/countries_wasm.mjs "$file" acute "$limit"
  fi
done <"$WORK/cases.txt"
export LOAD_END
LOAD_END=$(cut -d' ' -f1-3 /proc/loadavg)

# --- report -----------------------------------------------------------------------------------
out="$(report_path countries)"
node bench/inputs/countries_report.mjs --work "$WORK" --out "$out"
echo
cat "$out"
echo
echo "bench:countries: wrote $out"
