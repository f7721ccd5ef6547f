# What the bench scripts share; sourced by them (each defines note(), its own way of saying things).

# build_cli NAME: our CLI in build/: configured and built by scripts/build.sh the first time,
# else just the acutemesh target; the log in build/NAME.log. Exits when there is no CLI.
build_cli() {
  local log="build/$1.log" jobs
  jobs="$(nproc)"
  mkdir -p build
  if [[ ! -f build/CMakeCache.txt || ! ( -f build/Makefile || -f build/build.ninja ) ]]; then
    note "configuring and building build/ (scripts/build.sh)"
    bash scripts/build.sh >"$log" 2>&1 ||
      cmake --build build --target acutemesh -j"$jobs" >>"$log" 2>&1 || true
  else
    cmake --build build --target acutemesh -j"$jobs" >"$log" 2>&1 || true
  fi
  if [[ ! -x build/acutemesh ]]; then
    note "our CLI did not build (see $log)"
    exit 1
  fi
}

# select_cgshop DIR K: per category (the name before _SIZE_HASH), K of DIR's instances spread
# evenly over the category's sizes (K = 1: the middle one; "all": every one), as lines of
# category, size and file, tab-separated, sorted by category and size.
select_cgshop() {
  local dir="$1" k="$2" f b
  for f in "$dir"/*.instance.json; do
    b="$(basename "$f" .instance.json)"
    printf '%s\t%s\t%s\n' "${b%_*_*}" "$(echo "$b" | awk -F_ '{print $(NF-1)}')" "$f"
  done | sort -k1,1 -k2,2n -k3,3 | awk -F'\t' -v k="$k" '
    { cat[NR] = $1; line[NR] = $0; n[$1]++ }
    END {
      for (i = 1; i <= NR; i++) {
        c = cat[i]; j = seen[c]++;
        if (k == "all" || n[c] <= k) { print line[i]; continue }
        if (k == 1) { if (j == int((n[c] - 1) / 2)) print line[i]; continue }
        # keep rank j when it is the nearest to one of k evenly spaced ranks
        for (m = 0; m < k; m++) if (j == int(m * (n[c] - 1) / (k - 1) + 0.5)) { print line[i]; break }
      }
    }'
}

# report_path NAME: bench/results/NAME-YYYY-MM-DD.md, or -2, -3, ... when a report of that name
# and day exists already (reports are kept as they were written).
report_path() {
  local out="bench/results/$1-$(date +%F).md" k=2
  while [[ -e "$out" ]]; do
    out="bench/results/$1-$(date +%F)-$k.md"
    k=$((k + 1))
  done
  echo "$out"
}
