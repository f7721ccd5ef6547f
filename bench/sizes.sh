#!/usr/bin/env bash
# `npm run bench:sizes`: meshes sized for a solver (--max-edge, a graded --size grid), acutemesh
# in each refinement mode next to Gmsh 2D on the same domains and sizes, every mesh measured
# the same way by bench/sizes.py; writes bench/results/sizes-YYYY-MM-DD.md. Lake Superior comes
# from the reference data ($ACUTEMESH_DATA, else ../shared/data) and is skipped, said, without it.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash scripts/setup.sh                                  # the CLI's toolchain and python3-meshio
bash scripts/setup.sh --only "/usr/bin/gmsh:gmsh"      # the peer
[[ -f build/CMakeCache.txt ]] || bash scripts/build.sh >/dev/null
cmake --build build --target acutemesh -j"$(nproc)" >/dev/null
/usr/bin/python3 bench/sizes.py
