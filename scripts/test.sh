#!/usr/bin/env bash
# Installs what is missing, builds photowalk and runs the whole test suite.
# Usage: scripts/test.sh [PRESET]    PRESET: default (build/), asan (build-asan/), debug
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-default}
scripts/install-deps.sh --with-extras
scripts/install-tools.sh
# CI has 30 minutes on 2 cores: it builds everything but the benchmarks.
extra=()
[[ "${CI:-}" == "true" ]] && extra+=(-DPW_BUILD_BENCH=OFF)
cmake --preset "$preset" "${extra[@]}" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
ctest --preset "$preset"
