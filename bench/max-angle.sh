#!/usr/bin/env bash
# `npm run bench:max-angle`: acute mode's max-angle dial on the bench inputs and the CG:SHOP 2025
# instances: per input its floor (stats.angleFloor, Bishop's 90 - min(36, smallest corner) / 2)
# and, for the bounds 90, 85, 80, 75, floor + 3 and auto, the Steiner points, the largest angle
# reached, what was certified, whether the bound was met, and the time.
#
#  1. builds our CLI in build/ (as bench/refine.sh does: just the acutemesh target when build/ is
#     configured);
#  2. per input: `build/acutemesh --mode acute --max-angle B --stats --no-output --time-limit T`
#     once per bound, one run at a time (acute runs use every core for their strategies); the
#     90 run gives the floor, and floor + 3 (two decimals) is run unless it equals a fixed bound;
#     `--max-angle auto` is probed once and shows as n/a when this CLI does not take it;
#  3. aCute (Erten & Üngör's code on Triangle) next to ours when $ACUTE_BIN names a built binary:
#     `-pq20U<B>` on the .poly/.node inputs (a crash is recorded as such); otherwise the report
#     says it was not run and quotes the figures measured before (../shared/data/README.md);
#  4. bench/inputs/max_angle_report.mjs writes bench/results/max-angle-YYYY-MM-DD.md (and
#     bench/work/max-angle/cgshop.csv, one line per instance and bound), then it is printed.
#
# Inputs: the committed bench inputs (bench/inputs/data: the text outlines with --fill nonzero),
# tests/data/A.poly, and from the reference data ($ACUTEMESH_DATA, else ../shared/data, the
# tests' rule) superior.poly and the CG:SHOP instances; without the data those are skipped and
# the report says so; Greece (bench/work/countries/gr.json) when `npm run bench:countries` has
# made it. Each run's stdout, stderr and exit status are kept in bench/work/max-angle/runs/.
#
# Options: --quick: A.poly, plate and one CG:SHOP instance per category, 5 s limits (checks the
# script, not the mesher). Environment: MAXANGLE_TIME_LIMIT (default 20) seconds per run on the
# bench inputs, MAXANGLE_CGSHOP_TIME_LIMIT (default 5) per CG:SHOP run (a run is killed at twice
# its limit + 10 s), MAXANGLE_CGSHOP_PER_CATEGORY (default 6; "all" for the 150): the instances
# run per category, spread over its sizes, so the bench stays within about 15 minutes on 2 cores
# even when many runs use their whole time limit.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
# shellcheck source=bench/common.sh
source bench/common.sh

QUICK=0
for a in "$@"; do
  case "$a" in
    --quick) QUICK=1 ;;
    *) echo "usage: bash bench/max-angle.sh [--quick]" >&2; exit 2 ;;
  esac
done
TIME_LIMIT="${MAXANGLE_TIME_LIMIT:-20}"
CGSHOP_LIMIT="${MAXANGLE_CGSHOP_TIME_LIMIT:-5}"
PER_CATEGORY="${MAXANGLE_CGSHOP_PER_CATEGORY:-6}"
if ((QUICK)); then TIME_LIMIT=5 CGSHOP_LIMIT=5 PER_CATEGORY=1; fi
BOUNDS="90 85 80 75"
SHARED="${ACUTEMESH_DATA-../shared/data}"
if [[ -n "$SHARED" && "$SHARED" != /* ]]; then SHARED="$PWD/$SHARED"; fi

note() { echo "bench:max-angle: $*" >&2; }
WORK=bench/work/max-angle
RUNDIR="$WORK/runs"
mkdir -p "$WORK" bench/results build
rm -rf "$RUNDIR"
mkdir -p "$RUNDIR/cgshop"

# --- build ------------------------------------------------------------------------------------
build_cli bench-max-angle

# --- inputs -----------------------------------------------------------------------------------
# id | label | file | extra CLI arguments
CASES=(
  "acute-text|\"Acute\" (DejaVu Sans outline)|bench/inputs/data/acute-text.json|--fill nonzero"
  "acutemesh-text|\"acutemesh\" (DejaVu Sans outline)|bench/inputs/data/acutemesh-text.json|--fill nonzero"
  "naca0012|NACA 0012 airfoil in a far-field box|bench/inputs/data/naca0012.poly|"
  "plate|plate: 3 round holes and a slot|bench/inputs/data/plate.poly|"
  "random|Random: 1000 uniform points + 4 corners|bench/inputs/data/random.node|"
  "A|A.poly (Triangle's letter A)|tests/data/A.poly|"
  "superior|superior.poly (Lake Superior, 6 islands)|$SHARED/poly/superior.poly|"
)
if ((QUICK)); then CASES=("${CASES[3]}" "${CASES[5]}"); fi
: >"$WORK/cases.txt"
: >"$WORK/skipped.txt"
for c in "${CASES[@]}"; do
  IFS='|' read -r id label file args <<<"$c"
  if [[ ! -f "$file" ]]; then
    note "skipped: $label (needs the reference data: set ACUTEMESH_DATA, or put it at ../shared/data)"
    echo "$label" >>"$WORK/skipped.txt"
    continue
  fi
  printf '%s|%s|%s|%s\n' "$id" "$label" "$file" "$args" >>"$WORK/cases.txt"
done
# A whole country (every island and lake), when bench:countries has made it.
country=bench/work/countries/gr.json
if ((QUICK)); then
  :
elif [[ -f "$country" ]]; then
  printf '%s|%s|%s|%s\n' greece "Greece (GMT's DCW outline, 14,455 vertices)" "$country" "" >>"$WORK/cases.txt"
else
  note "skipped: Greece ($country is made by npm run bench:countries)"
  echo "Greece ($country, made by npm run bench:countries)" >>"$WORK/skipped.txt"
fi

# The CG:SHOP instances: per category (the name before _SIZE_HASH), PER_CATEGORY of them spread
# evenly over the category's sizes.
cgshop_dir=""
: >"$WORK/cgshop-selected.txt"
if [[ -d "$SHARED/cgshop2025" ]]; then
  cgshop_dir="$SHARED/cgshop2025"
  select_cgshop "$cgshop_dir" "$PER_CATEGORY" >"$WORK/cgshop-selected.txt"
else
  note "skipped: the CG:SHOP 2025 instances (needs the reference data: set ACUTEMESH_DATA, or put it at ../shared/data)"
fi

# --- measuring --------------------------------------------------------------------------------
load_start=$(cut -d' ' -f1-3 /proc/loadavg)
started=$(date +%s)

# run_one OUT KILL_AFTER_S ARGS...: OUT.json (stdout), OUT.err, OUT.rc (124: killed by timeout)
run_one() {
  local out="$1" kill_after="$2" rc=0
  shift 2
  timeout "$kill_after" ./build/acutemesh "$@" >"$out.json" 2>"$out.err" </dev/null || rc=$?
  echo "$rc" >"$out.rc"
}

# Whether this CLI takes --max-angle auto (exit 2: an option it rejects).
auto=1
run_one "$RUNDIR/probe-auto" 60 --mode acute --max-angle auto --time-limit 2 --stats --no-output tests/data/A.poly
if [[ "$(cat "$RUNDIR/probe-auto.rc")" == 2 ]]; then
  auto=0
  note "--max-angle auto: $(head -n1 "$RUNDIR/probe-auto.err")"
fi
printf '%s\t%s\n' "$auto" "$(head -n1 "$RUNDIR/probe-auto.err")" >"$RUNDIR/auto.tsv"

# floor_of RUN.json: stats.angleFloor, or nothing.
floor_of() { grep -o '"angleFloor": [0-9.e+-]*' "$1" 2>/dev/null | head -n1 | cut -d' ' -f2; }

# run_bounds BASE LIMIT FILE ARGS...: the runs of one input, BASE.B.* for each bound, and
# BASE.floor3 holding the floor + 3 bound ("same" when it equals a fixed bound).
run_bounds() {
  local base="$1" limit="$2" file="$3" kill=$((2 * $2 + 10))
  shift 3
  for b in $BOUNDS; do
    run_one "$base.$b" "$kill" --mode acute --max-angle "$b" --time-limit "$limit" "$@" --stats --no-output "$file"
  done
  local floor f3
  floor="$(floor_of "$base.90.json")"
  if [[ -n "$floor" ]]; then
    f3="$(awk -v f="$floor" 'BEGIN { b = f + 3; if (b > 90) b = 90; printf "%.2f", b }')"
    echo "$f3" >"$base.floor3"
    if ! awk -v b="$f3" -v list="$BOUNDS" 'BEGIN { n = split(list, a, " "); for (i = 1; i <= n; i++) if (a[i] + 0 == b + 0) exit 1 }'; then
      echo "same" >>"$base.floor3"
    else
      run_one "$base.floor3" "$kill" --mode acute --max-angle "$f3" --time-limit "$limit" "$@" --stats --no-output "$file"
    fi
  fi
  if ((auto)); then
    run_one "$base.auto" "$kill" --mode acute --max-angle auto --time-limit "$limit" "$@" --stats --no-output "$file"
  fi
}

while IFS='|' read -r id label file args; do
  note "$id"
  # shellcheck disable=SC2086  # args: a few words, no spaces inside
  run_bounds "$RUNDIR/$id" "$TIME_LIMIT" "$file" $args
done <"$WORK/cases.txt"

if [[ -s "$WORK/cgshop-selected.txt" ]]; then
  note "CG:SHOP 2025: $(wc -l <"$WORK/cgshop-selected.txt") instances ($PER_CATEGORY per category)"
  while IFS=$'\t' read -r _ _ f; do
    run_bounds "$RUNDIR/cgshop/$(basename "$f" .instance.json)" "$CGSHOP_LIMIT" "$f"
  done <"$WORK/cgshop-selected.txt"
fi

# --- aCute ------------------------------------------------------------------------------------
# Only with a binary named by ACUTE_BIN (none is built here by default): Triangle-style
# switches, the input copied to a scratch folder, FILE.1.node / FILE.1.ele read by the report.
acute_bin="${ACUTE_BIN:-}"
if [[ -n "$acute_bin" && -x "$acute_bin" ]]; then
  mkdir -p "$RUNDIR/acute"
  while IFS='|' read -r id label file args; do
    case "$file" in *.poly | *.node) ;; *) continue ;; esac
    for b in $BOUNDS; do
      dir="$RUNDIR/acute/$id.$b"
      mkdir -p "$dir"
      cp "$file" "$dir/"
      rc=0
      start_ns=$(date +%s%N)
      (cd "$dir" && timeout $((2 * TIME_LIMIT + 10)) "$acute_bin" -Qpq20U"$b" "$(basename "$file")" \
        >stdout.txt 2>stderr.txt </dev/null) || rc=$?
      echo "$rc $(( ($(date +%s%N) - start_ns) / 1000000 ))" >"$dir/rc"
    done
  done <"$WORK/cases.txt"
  echo "$acute_bin" >"$RUNDIR/acute/binary.txt"
elif [[ -n "$acute_bin" ]]; then
  note "ACUTE_BIN=$acute_bin is not an executable: aCute not run"
fi

# --- report -----------------------------------------------------------------------------------
out="$(report_path max-angle)"
LOAD_START="$load_start" ELAPSED=$(($(date +%s) - started)) TIME_LIMIT="$TIME_LIMIT" \
  CGSHOP_LIMIT="$CGSHOP_LIMIT" PER_CATEGORY="$PER_CATEGORY" QUICK="$QUICK" BOUNDS="$BOUNDS" \
  node bench/inputs/max_angle_report.mjs --work "$WORK" --cgshop "$cgshop_dir" --out "$out"
echo
cat "$out"
echo
echo "bench:max-angle: wrote $out (per instance and bound: $WORK/cgshop.csv)"
