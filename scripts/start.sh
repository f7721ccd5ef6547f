#!/usr/bin/env bash
# Installs what is missing, builds, and serves the web page (PORT, default 8080): open the
# printed URL, type a word or drop a map, and get its acute mesh. Ctrl-C stops the server.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/setup.sh
bash scripts/build.sh
if [[ ! -f dist/index.js ]]; then
  echo "start: dist/ is missing: the WebAssembly package was not built (see scripts/build.sh)" >&2
  exit 1
fi
exec node scripts/serve.mjs
