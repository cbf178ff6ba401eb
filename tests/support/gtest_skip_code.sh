#!/usr/bin/env bash
# Usage: gtest_skip_code.sh [LAUNCHER...] GTEST_BINARY [ARGS...]
# Runs a GoogleTest binary (after a launcher such as xvfb-run, if any) and exits 77 when
# it succeeded but skipped tests (GTEST_SKIP exits 0): with SKIP_RETURN_CODE 77 ctest
# then says Skipped, not Passed. A failure stays a failure, whatever was skipped.
set -o pipefail
log=$(mktemp) || exit 1
trap 'rm -f "$log"' EXIT
"$@" 2>&1 | tee "$log"
status=$?
if [[ $status -eq 0 ]] && grep -q '^\[  SKIPPED \]' "$log"; then
  exit 77
fi
exit "$status"
