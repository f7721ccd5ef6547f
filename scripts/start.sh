#!/usr/bin/env bash
# Builds acutemesh and makes a certified acute mesh of the bundled letter "A" (Triangle's A.poly).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/setup.sh
bash scripts/build.sh

out=build/sample/A.1
mkdir -p "$(dirname "$out")"
rm -f "$out".node "$out".ele "$out".svg
echo
echo "$ ./build/acutemesh --mode acute --stats --format node,ele,svg -o $out tests/data/A.poly"
./build/acutemesh --mode acute --stats --format node,ele,svg -o "$out" tests/data/A.poly
echo
echo "Wrote:"
for ext in node ele svg; do
  if [[ -f "$out.$ext" ]]; then
    printf '  %s  (%s bytes)\n' "$out.$ext" "$(wc -c <"$out.$ext")"
  else
    echo "  $out.$ext is missing" >&2
    exit 1
  fi
done
echo "Open $out.svg in a browser to see the mesh."
