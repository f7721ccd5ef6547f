# Sourced by the bench scripts that run a share of the CG:SHOP 2025 instances.
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
