#!/usr/bin/env bash
# Installs what is missing, builds photowalk and runs the whole test suite.
# Usage: scripts/test.sh [PRESET]    PRESET: default (build/), asan (build-asan/), debug
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-default}
scripts/install-deps.sh --with-extras
scripts/install-tools.sh
# CI has 30 minutes on 2 cores: it builds everything but the benchmarks, with line tables
# for debug information (-g1) instead of full debug information: the same code (GCC's -g
# never changes it), backtraces keep their file and line, and a clean build on 2 cores
# takes 13.0 minutes instead of 15.6 (compiling 1292 s instead of 1584; Ninja, 2026-12-05).
extra=()
[[ "${CI:-}" == "true" ]] && extra+=(-DPW_BUILD_BENCH=OFF "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG")
cmake --preset "$preset" "${extra[@]}" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
# CI, and PW_REQUIRE_ALL_TESTS=1: a test that did not run (Skipped: no display, a tool
# missing) fails the run, by name; elsewhere ctest lists such tests and the run passes.
junit=$(mktemp)
trap 'rm -f "$junit"' EXIT
ctest --preset "$preset" --output-junit "$junit"
if [[ "${CI:-}" == "true" || "${PW_REQUIRE_ALL_TESTS:-}" == "1" ]]; then
  python3 - "$junit" <<'EOF'
import sys, xml.etree.ElementTree as ET
cases = list(ET.parse(sys.argv[1]).getroot().iter("testcase"))
notrun = [c for c in cases if c.get("status") in ("notrun", "disabled") or c.find("skipped") is not None]
for c in notrun:
    # The reason: GTEST_SKIP's message (the line after "file:line: Skipped"), or a
    # script's "skipped: ..." line.
    lines = (c.findtext("system-out") or "").splitlines()
    after = [lines[i + 1] for i in range(len(lines) - 1) if lines[i].endswith(": Skipped")]
    said = [l for l in lines if l.lower().startswith("skipped:")]
    print(f"  not run: {c.get('name')}: {(after + said + [c.get('status')])[0].strip()}")
if not cases or notrun:
    sys.exit(f"error: {len(notrun)} of {len(cases)} tests did not run; here every test must run "
             "(scripts/install-deps.sh --with-extras, scripts/install-tools.sh)")
EOF
fi
