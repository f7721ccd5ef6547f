#!/usr/bin/env bash
# `npm run bench:quality`: quality mode (`--mode quality --min-angle A`) against aCute (Erten &
# Üngör's code on Triangle) at the min angles 30, 34, 38, 40 and 42, both tools on the same file:
# per input and angle the Steiner points, whether the angle was met (else the smallest angle
# reached) and the best time; totals where both met the angle, and issue 27's target.
#
#  1. builds our CLI in build/ (as bench/max-angle.sh does: just the acutemesh target when build/
#     is configured);
#  2. the inputs: the issue's four (NACA 0012 in a box, the plate, A.poly, 1000 random points)
#     and the held-out ones (not used when tuning): the two text outlines and, from the reference
#     data, Lake Superior and one CG:SHOP 2025 instance per category (the middle size). The text
#     outlines and the CG:SHOP instances are JSON, which aCute cannot read: each is converted
#     first with `build/acutemesh --mode cdt [--fill nonzero] --format poly -o
#     bench/work/quality/inputs/NAME FILE`, and the NAME.poly it writes renumbered from 0 to 1
#     (both allowed by the format; the aCute build this bench was written against carves the whole
#     domain away when a .poly counts from 0); both tools then mesh that .poly;
#  3. ours, per input and angle, one run at a time: `build/acutemesh --mode quality --min-angle A
#     --time-limit T --stats --no-output FILE`, killed at 2 T + 10 s, $QUALITY_RUNS runs (the mesh
#     is deterministic: the first run's stats are kept, with the smallest seconds.total); a run
#     that did not exit 0 is not repeated;
#  4. aCute next to ours when $ACUTE_BIN names a built binary: `-Qpq<A>` on a .poly (`-Qq<A>` on a
#     .node; one argument, the binary reads only the first as switches) on a copy of the file in a
#     scratch folder, timeout 60 s, wall time by date +%s%N, as many runs (a run that did not
#     exit 0 is not repeated); FILE.1.node / FILE.1.ele are read by the report. Otherwise the
#     report says it was not run and quotes the figures issue 27 recorded by hand;
#  5. bench/inputs/quality_report.mjs writes bench/results/quality-YYYY-MM-DD.md (and
#     bench/work/quality/results.csv, one line per input, angle and tool), then it is printed.
#
# Inputs not found (the reference data: $ACUTEMESH_DATA, else ../shared/data, the tests' rule)
# are skipped and the report says so. Each run's stdout, stderr and exit status are kept in
# bench/work/quality/runs/ (aCute's in runs/acute/ID.A/).
#
# Options: --quick: the issue's four inputs at 30 and 40, one run each (checks the script).
# Environment: QUALITY_ANGLES (default "30 34 38 40 42"), QUALITY_TIME_LIMIT (default 60) seconds
# per run of ours, QUALITY_RUNS (default 3) runs per input and angle for the best time. The full
# run takes a few minutes on 2 cores, more when runs hit their limits.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
# shellcheck source=bench/common.sh
source bench/common.sh

QUICK=0
for a in "$@"; do
  case "$a" in
    --quick) QUICK=1 ;;
    *) echo "usage: bash bench/quality.sh [--quick]" >&2; exit 2 ;;
  esac
done
ANGLES="${QUALITY_ANGLES:-30 34 38 40 42}"
TIME_LIMIT="${QUALITY_TIME_LIMIT:-60}"
RUNS="${QUALITY_RUNS:-3}"
if ((QUICK)); then ANGLES="30 40" RUNS=1; fi
ACUTE_TIMEOUT=60
note() { echo "bench:quality: $*" >&2; }
for a in $ANGLES; do
  [[ "$a" =~ ^[0-9]+(\.[0-9]+)?$ ]] || { note "QUALITY_ANGLES: '$a' is not an angle in degrees"; exit 2; }
done
[[ -n "${ANGLES// /}" ]] || { note "QUALITY_ANGLES is empty"; exit 2; }
[[ "$TIME_LIMIT" =~ ^[1-9][0-9]*$ ]] || { note "QUALITY_TIME_LIMIT: '$TIME_LIMIT' is not a whole number of seconds"; exit 2; }
[[ "$RUNS" =~ ^[1-9][0-9]*$ ]] || { note "QUALITY_RUNS: '$RUNS' is not a count"; exit 2; }
SHARED="${ACUTEMESH_DATA-../shared/data}"
if [[ -n "$SHARED" && "$SHARED" != /* ]]; then SHARED="$PWD/$SHARED"; fi

WORK=bench/work/quality
RUNDIR="$WORK/runs"
CONV="$WORK/inputs"
mkdir -p "$WORK" bench/results build
rm -rf "$RUNDIR" "$CONV"
mkdir -p "$RUNDIR" "$CONV"

# --- build ------------------------------------------------------------------------------------
build_cli bench-quality

# --- inputs -----------------------------------------------------------------------------------
# id | label | group (issue, held) | file | the file converted from (JSON), or nothing
CASES=(
  "naca0012|NACA 0012 in a box|issue|bench/inputs/data/naca0012.poly|"
  "plate|plate|issue|bench/inputs/data/plate.poly|"
  "A|A.poly|issue|tests/data/A.poly|"
  "random|1000 random points|issue|bench/inputs/data/random.node|"
  "acute-text|\"Acute\" (text outline)|held|$CONV/acute-text.poly|bench/inputs/data/acute-text.json"
  "acutemesh-text|\"acutemesh\" (text outline)|held|$CONV/acutemesh-text.poly|bench/inputs/data/acutemesh-text.json"
  "superior|Lake Superior|held|$SHARED/poly/superior.poly|"
)
if ((QUICK)); then CASES=("${CASES[@]:0:4}"); fi
if ((!QUICK)); then
  if [[ -d "$SHARED/cgshop2025" ]]; then
    while IFS=$'\t' read -r _ _ f; do
      id="$(basename "$f" .instance.json)"
      CASES+=("$id|$id|held|$CONV/$id.poly|$f")
    done < <(select_cgshop "$SHARED/cgshop2025" 1)
  else
    CASES+=("cgshop|CG:SHOP 2025 instances (one per category)|held|$SHARED/cgshop2025|")
  fi
fi

# one_based POLY: rewrites a .poly that counts from 0 (vertices, segments, holes, regions) to count
# from 1, comments and blank lines dropped.
one_based() {
  awk '
    { sub(/#.*/, "") }
    NF == 0 { next }
    sec == 0 { nv = $1; i = 0; sec = nv > 0 ? 1 : 2; print; next }
    sec == 1 { $1 += 1; print; if (++i == nv) sec = 2; next }
    sec == 2 { ns = $1; i = 0; sec = ns > 0 ? 3 : 4; print; next }
    sec == 3 { $1 += 1; $2 += 1; $3 += 1; print; if (++i == ns) sec = 4; next }
    sec == 4 { nh = $1; i = 0; sec = nh > 0 ? 5 : 6; print; next }
    sec == 5 { $1 += 1; print; if (++i == nh) sec = 6; next }
    sec == 6 { sec = 7; print; next }
    { $1 += 1; print }' "$1" >"$1.tmp" && mv "$1.tmp" "$1"
}

: >"$WORK/cases.txt"
: >"$WORK/skipped.txt"
: >"$WORK/converted.txt"
for c in "${CASES[@]}"; do
  IFS='|' read -r id label group file source <<<"$c"
  src="${source:-$file}"
  if [[ ! -f "$src" ]]; then
    note "skipped: $label (needs the reference data: set ACUTEMESH_DATA, or put it at ../shared/data)"
    echo "$label" >>"$WORK/skipped.txt"
    continue
  fi
  if [[ -n "$source" ]]; then
    conv=(./build/acutemesh --mode cdt)
    case "$source" in *.instance.json) ;; *) conv+=(--fill nonzero) ;; esac
    conv+=(--format poly -o "$CONV/$id" "$source")
    rc=0
    "${conv[@]}" >"$CONV/$id.convert.out" 2>"$CONV/$id.convert.err" </dev/null || rc=$?
    echo "$rc" >"$CONV/$id.convert.rc"
    printf '%s|%s\n' "$id" "${conv[*]#./}" >>"$WORK/converted.txt"
    if ((rc == 0)) && [[ -f "$file" ]]; then
      one_based "$file"
    else
      rm -f "$file"
      note "$id: the conversion failed (exit $rc): $(head -n1 "$CONV/$id.convert.err")"
    fi
  fi
  printf '%s|%s|%s|%s|%s\n' "$id" "$label" "$group" "$file" "$source" >>"$WORK/cases.txt"
done

# --- ours -------------------------------------------------------------------------------------
load_start=$(cut -d' ' -f1-3 /proc/loadavg)
started=$(date +%s)

# run_one OUT KILL_AFTER_S ARGS...: OUT.json (stdout), OUT.err, OUT.rc (124: killed by timeout)
run_one() {
  local out="$1" kill_after="$2" rc=0
  shift 2
  timeout "$kill_after" ./build/acutemesh "$@" >"$out.json" 2>"$out.err" </dev/null || rc=$?
  echo "$rc" >"$out.rc"
}

kill_after=$((2 * TIME_LIMIT + 10))
while IFS='|' read -r id _ _ file _; do
  [[ -f "$file" ]] || continue
  for a in $ANGLES; do
    for ((r = 1; r <= RUNS; r++)); do
      base="$RUNDIR/$id.$a.$r"
      run_one "$base" "$kill_after" --mode quality --min-angle "$a" --time-limit "$TIME_LIMIT" \
        --stats --no-output "$file"
      [[ "$(cat "$base.rc")" == 0 ]] || break
    done
    note "$id at $a: exit $(cat "$RUNDIR/$id.$a.1.rc")"
  done
done <"$WORK/cases.txt"

# --- aCute ------------------------------------------------------------------------------------
# Only with a binary named by ACUTE_BIN (none is built here by default). Per input and angle the
# file is copied to runs/acute/ID.A/, and each run appends "exit-status milliseconds" to its rc.
acute_bin="${ACUTE_BIN:-}"
if [[ -n "$acute_bin" && -x "$acute_bin" ]]; then
  while IFS='|' read -r id _ _ file _; do
    [[ -f "$file" ]] || continue
    sw=-Qpq
    case "$file" in *.node) sw=-Qq ;; esac
    for a in $ANGLES; do
      dir="$RUNDIR/acute/$id.$a"
      mkdir -p "$dir"
      cp "$file" "$dir/"
      : >"$dir/rc"
      for ((r = 1; r <= RUNS; r++)); do
        rc=0
        start_ns=$(date +%s%N)
        (cd "$dir" && timeout "$ACUTE_TIMEOUT" "$acute_bin" "$sw$a" "$(basename "$file")" \
          >stdout.txt 2>stderr.txt </dev/null) || rc=$?
        echo "$rc $((($(date +%s%N) - start_ns) / 1000000))" >>"$dir/rc"
        ((rc == 0)) || break
      done
      note "aCute: $id at $a: exit $(head -n1 "$dir/rc" | cut -d' ' -f1)"
    done
  done <"$WORK/cases.txt"
  echo "$acute_bin" >"$RUNDIR/acute/binary.txt"
elif [[ -n "$acute_bin" ]]; then
  note "ACUTE_BIN=$acute_bin is not an executable: aCute not run"
else
  note "ACUTE_BIN is not set: aCute not run"
fi

# --- report -----------------------------------------------------------------------------------
out="$(report_path quality)"
LOAD_START="$load_start" ELAPSED=$(($(date +%s) - started)) TIME_LIMIT="$TIME_LIMIT" \
  ACUTE_TIMEOUT="$ACUTE_TIMEOUT" RUNS="$RUNS" QUICK="$QUICK" ANGLES="$ANGLES" ACUTE_BIN="$acute_bin" \
  node bench/inputs/quality_report.mjs --work "$WORK" --out "$out"
echo
cat "$out"
echo
echo "bench:quality: wrote $out (per input, angle and tool: $WORK/results.csv)"
