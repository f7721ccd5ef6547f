#!/usr/bin/env bash
# Installs what building and testing acutemesh needs, and nothing when it is all there.
#
#   bash scripts/setup.sh                   the project's requirements + npm packages
#   bash scripts/setup.sh --only REQ...     just the given requirements (bench/run.sh uses this)
#
# Idempotent and quick when everything is present: one summary line, no apt, no npm.
# Missing Debian packages are installed with one `apt-get update` + one `apt-get install`;
# npm packages with `npm install` only when node_modules is missing or older than
# package-lock.json. Never prompts (CI runs with no stdin).
set -euo pipefail

# ---------------------------------------------------------------------------------------------
# Requirements, one per line: "WHAT:DEBIAN_PACKAGE". WHAT is a command name (looked up on PATH)
# or an absolute file path; "a|b" means either one will do. To require something new, add a line.
REQUIREMENTS=(
  "cmake:cmake"
  "g++:g++"
  "make|ninja:make"
  "/usr/include/gtest/gtest.h:libgtest-dev"
  "clang++:clang"                     # libFuzzer harnesses (scripts/fuzz.sh)
  "/usr/lib/llvm-14/lib/clang/14.0.6/lib/linux/libclang_rt.fuzzer-x86_64.a|/usr/lib/llvm-14/lib/clang/14/lib/linux/libclang_rt.fuzzer-x86_64.a:libclang-rt-14-dev"
  "emcc:emscripten"                   # the WebAssembly build (npm package)
  "chromium:chromium"                 # the browser tests (tests/web, playwright-core)
  "/usr/lib/python3/dist-packages/meshio/__init__.py:python3-meshio"  # .msh/.vtu read back (tests/formats)
)
# ---------------------------------------------------------------------------------------------

cd "$(dirname "${BASH_SOURCE[0]}")/.."

do_npm=1
if [[ "${1:-}" == "--only" ]]; then
  shift
  REQUIREMENTS=("$@")
  do_npm=0
fi

have() {  # have WHAT: WHAT may be "a|b|c"; each is a command or an absolute path
  local alt
  IFS='|' read -r -a alts <<<"$1"
  for alt in "${alts[@]}"; do
    if [[ "$alt" == /* ]]; then
      [[ -e "$alt" ]] && return 0
    else
      command -v "$alt" >/dev/null 2>&1 && return 0
    fi
  done
  return 1
}

missing_pkgs=()
missing_what=()
for req in "${REQUIREMENTS[@]}"; do
  what="${req%:*}"
  pkg="${req##*:}"
  if ! have "$what"; then
    missing_pkgs+=("$pkg")
    missing_what+=("$what")
  fi
done

installed=0
if ((${#missing_pkgs[@]})); then
  # Deduplicate while keeping order.
  mapfile -t missing_pkgs < <(printf '%s\n' "${missing_pkgs[@]}" | awk '!seen[$0]++')
  apt_cmd="apt-get update && apt-get install -y --no-install-recommends ${missing_pkgs[*]}"
  if [[ "$(id -u)" != 0 ]]; then
    echo "setup: missing: ${missing_what[*]}" >&2
    echo "setup: not root, so not installing. Run as root:" >&2
    echo "  sudo sh -c '$apt_cmd'" >&2
    exit 1
  fi
  for i in "${!missing_pkgs[@]}"; do echo "setup: installing ${missing_pkgs[$i]}"; done
  export DEBIAN_FRONTEND=noninteractive
  log="$(mktemp)"
  if ! { apt-get update -q && apt-get install -y -q --no-install-recommends "${missing_pkgs[@]}"; } \
      >"$log" 2>&1 </dev/null; then
    tail -n 30 "$log" >&2
    rm -f "$log"
    echo "setup: apt-get failed (command: $apt_cmd)" >&2
    exit 1
  fi
  rm -f "$log"
  for i in "${!missing_what[@]}"; do
    if ! have "${missing_what[$i]}"; then
      echo "setup: ${missing_pkgs[$i]} installed but ${missing_what[$i]} is still missing" >&2
      exit 1
    fi
  done
  installed=${#missing_pkgs[@]}
fi

# npm packages: only when package.json declares some (an empty lock has no "node_modules/"
# entries, and then npm creates no node_modules to compare against).
if ((do_npm)) && [[ -f package.json ]]; then
  needs_npm=0
  if [[ ! -f package-lock.json ]]; then
    needs_npm=1
  elif grep -q '"node_modules/' package-lock.json; then
    if [[ ! -d node_modules || package-lock.json -nt node_modules ]]; then needs_npm=1; fi
  fi
  if ((needs_npm)); then
    if ! command -v npm >/dev/null 2>&1; then
      echo "setup: npm is missing (install Node.js 20 with npm)" >&2
      exit 1
    fi
    echo "setup: installing npm packages"
    log="$(mktemp)"
    if ! npm install --no-audit --no-fund </dev/null >"$log" 2>&1; then
      tail -n 30 "$log" >&2
      rm -f "$log"
      echo "setup: npm install failed" >&2
      exit 1
    fi
    rm -f "$log"
    [[ -d node_modules ]] && touch node_modules
    installed=$((installed + 1))
  fi
fi

if ((installed == 0)); then
  echo "setup: all requirements present"
else
  echo "setup: done"
fi
