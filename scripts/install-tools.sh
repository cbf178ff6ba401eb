#!/usr/bin/env bash
# Installs the npm packages photowalk builds and tests with, from each folder's
# package.json / package-lock.json (npm ci, versions locked): tools/ (the Khronos glTF
# validator) and web/ (three.js and esbuild for the web page's viewer, playwright-core
# for its tests). Quiet when present. The build itself never reaches the network.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
for dir in tools web; do
  cd "$root/$dir"
  [[ -f package.json ]] || continue
  if [[ ! -d node_modules ]] || [[ package-lock.json -nt node_modules ]]; then
    command -v npm >/dev/null || { echo "install-tools: npm not found; run scripts/install-deps.sh --with-extras"; exit 1; }
    npm ci --silent --no-audit --no-fund >/dev/null
    touch node_modules
  fi
done
