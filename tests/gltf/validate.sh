#!/usr/bin/env bash
# ctest: writes every sample scene and the files the gtests wrote through the
# Khronos glTF-Validator (tools/validate-gltf.mjs). Exits 77 (skipped) when node or
# tools/node_modules is missing; scripts/install-tools.sh installs them.
# Usage: validate.sh WRITE_SAMPLES_EXE OUT_DIR REPO_ROOT
set -euo pipefail
writer=$1 out=$2 root=$3
if ! command -v node >/dev/null 2>&1; then
  echo "skipped: node is not installed (scripts/install-deps.sh --with-extras)"; exit 77
fi
if [[ ! -d "$root/tools/node_modules/gltf-validator" ]]; then
  echo "skipped: the glTF validator is not installed (scripts/install-tools.sh)"; exit 77
fi
mkdir -p "$out"
"$writer" "$out"
shopt -s nullglob
files=("$out"/*.glb "$out"/*.gltf)
[[ ${#files[@]} -gt 0 ]] || { echo "error: no glTF files in $out"; exit 1; }
node "$root/tools/validate-gltf.mjs" "${files[@]}"
