#!/usr/bin/env bash
# ctest gltf_validator: runs the Khronos glTF-Validator (tools/validate-gltf.mjs) on
# every sample scene and on every file the GltfWriter tests write. Exits 77 (skipped)
# when node or tools/node_modules is missing; scripts/install-tools.sh installs them.
# Usage: validate.sh WRITE_SAMPLES_EXE GLTF_TESTS_EXE OUT_DIR REPO_ROOT
set -euo pipefail
writer=$1 tests=$2 out=$3 root=$4
if ! command -v node >/dev/null 2>&1; then
  echo "skipped: node is not installed (scripts/install-deps.sh --with-extras)"; exit 77
fi
if [[ ! -d "$root/tools/node_modules/gltf-validator" ]]; then
  echo "skipped: the glTF validator is not installed (scripts/install-tools.sh)"; exit 77
fi
# Start from an empty folder so that no file from an older build is judged.
rm -rf "$out"
mkdir -p "$out"
"$writer" "$out"
# The writer tests report their own failures as separate ctests; here only their files matter.
PW_GLTF_TEST_OUT="$out" "$tests" --gtest_filter='GltfWriter.*' >/dev/null 2>&1 || echo "note: some GltfWriter tests failed; validating what they wrote"
shopt -s nullglob
files=("$out"/*.glb "$out"/*.gltf)
[[ ${#files[@]} -gt 0 ]] || { echo "error: no glTF files in $out"; exit 1; }
node "$root/tools/validate-gltf.mjs" "${files[@]}"
