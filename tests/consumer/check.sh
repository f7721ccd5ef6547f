#!/usr/bin/env bash
# Installs acutemesh into a temporary prefix and builds a downstream project against it with
# find_package(), then builds it again with add_subdirectory(); runs both. The project's
# program is README.md's C++ example (its first ```cpp block), so that example stays right.
#
#   bash tests/consumer/check.sh [BUILD_DIR]
set -euo pipefail
src=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
jobs=$(nproc)

mkdir -p "$work/consumer"
cp "$src/tests/consumer/CMakeLists.txt" "$work/consumer/"
awk '/^```cpp$/ { on = 1; next } on && /^```$/ { exit } on' "$src/README.md" >"$work/consumer/main.cpp"
grep -q 'int main' "$work/consumer/main.cpp" || { echo "consumer: no C++ example in README.md" >&2; exit 1; }

# The installed copy: from the build ctest runs in when given (already built), else built here
# without optimisation (this checks the packaging and the example, not speed; -O0 compiles
# several times faster).
if [[ $# -ge 1 ]]; then
  cmake --install "$1" --prefix "$work/prefix" >/dev/null
else
  cmake -S "$src" -B "$work/lib" -DACUTEMESH_TESTS=OFF -DACUTEMESH_CLI=OFF -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_INSTALL_PREFIX="$work/prefix" >/dev/null
  cmake --build "$work/lib" -j"$jobs" >/dev/null
  cmake --install "$work/lib" >/dev/null
fi
cmake -S "$work/consumer" -B "$work/installed" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/installed" -j"$jobs" >/dev/null
"$work/installed/consumer"

cmake -S "$work/consumer" -B "$work/subdir" -DACUTEMESH_SOURCE_DIR="$src" -DCMAKE_BUILD_TYPE=Debug >/dev/null
cmake --build "$work/subdir" -j"$jobs" >/dev/null
"$work/subdir/consumer"
echo "consumer: find_package and add_subdirectory both work"
