#!/usr/bin/env bash
# Installs acutemesh into a temporary prefix and builds tests/consumer against it with
# find_package(), then builds it again with add_subdirectory(); runs both.
set -euo pipefail
src=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
jobs=$(nproc)

cmake -S "$src" -B "$work/lib" -DACUTEMESH_TESTS=OFF -DACUTEMESH_CLI=OFF \
  -DCMAKE_INSTALL_PREFIX="$work/prefix" >/dev/null
cmake --build "$work/lib" -j"$jobs" >/dev/null
cmake --install "$work/lib" >/dev/null
cmake -S "$src/tests/consumer" -B "$work/installed" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/installed" -j"$jobs" >/dev/null
"$work/installed/consumer"

cmake -S "$src/tests/consumer" -B "$work/subdir" -DACUTEMESH_SOURCE_DIR="$src" >/dev/null
cmake --build "$work/subdir" -j"$jobs" >/dev/null
"$work/subdir/consumer"
echo "consumer: find_package and add_subdirectory both work"
