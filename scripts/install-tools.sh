#!/usr/bin/env bash
# Installs the npm tools the tests use (the Khronos glTF validator) into
# tools/node_modules, from package.json / package-lock.json. Quiet when present.
set -euo pipefail
cd "$(dirname "$0")/../tools"
[[ -f package.json ]] || exit 0
if [[ ! -d node_modules ]] || [[ package-lock.json -nt node_modules ]]; then
  command -v npm >/dev/null || { echo "install-tools: npm not found; run scripts/install-deps.sh --with-extras"; exit 1; }
  npm ci --silent --no-audit --no-fund >/dev/null
fi
