#!/usr/bin/env bash
# Mutation check: does the test suite catch deliberate bugs?
#
# Copies the working tree (tracked files and untracked ones git does not ignore; no
# build folders; tools/node_modules linked, not copied) to a scratch folder, builds it
# there in its own build folder (the default preset, without the benchmarks, as CI
# builds it), runs the whole ctest suite once unmutated (it must pass), then for each
# bug in scripts/mutations.py: writes the bug into the copy (one exact text
# replacement in one file), rebuilds incrementally, runs the whole suite (ctest -j2,
# a timeout per test), records whether any test failed, and puts the file back.
# Prints a table (bug, file, caught/SURVIVED, the tests that caught it, time) and exits
# non-zero if any bug survived (or could not be applied or built).
#
# Run it on demand, not in CI, and niced on a shared machine:
#   nice -n 10 scripts/mutation-check.sh                  # every bug
#   scripts/mutation-check.sh --only focal-x1.009,png-filter-byte
#   scripts/mutation-check.sh --list                       # the bugs
#   scripts/mutation-check.sh --check                      # does every bug's text still apply here? (seconds)
# Options:
#   --dir DIR      scratch folder (default /tmp/photowalk-mutants); kept between runs, so a
#                  second run rebuilds only what changed
#   --head         copy the last commit (git archive HEAD) instead of the working tree
#   --only A,B     only these bugs (names as --list prints them)
#   --timeout S    per-test timeout for ctest (default 300 s)
#   --jobs N       build and ctest parallelism (default 2)
#   --allow-baseline-failures
#                  go on when tests fail unmutated (others' work in progress in a shared tree):
#                  they are listed, and a bug counts as caught only by tests that passed
#   --fast         stop each suite run at its first failure (ctest --stop-on-failure): quicker,
#                  but names only the first tests that caught a bug
# Logs: DIR/logs/NAME.build.log and NAME.ctest.log; the table also goes to DIR/report.txt.
#
# How long (measured 2026-11-29 on the 2-core development machine, shared, load 4-5):
# a full pass of the 13 bugs took 51 min: building the copy 10-11 min (the first run
# or after a change low in the graph; a run after small changes rebuilds in seconds),
# the unmutated suite 3 min (406 tests), then each bug 1.7-4.2 min (its rebuild
# 11-24 s, the rest the suite). --only with one or two bugs on a built copy: 5-10 min.
# See also DEVELOPERS.md, "Mutation check".
set -uo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
helper=(python3 "$root/scripts/mutations.py")
dir=/tmp/photowalk-mutants
only=""
timeout=300
jobs=2
from_head=0
stop=()
allow_baseline=0
mode=run

die() { echo "mutation-check: error: $*" >&2; exit 2; }
usage() { sed -n '2,/^set -uo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; }

while [[ $# -gt 0 ]]; do
  case $1 in
    --dir) [[ $# -ge 2 ]] || die "--dir needs a folder"; dir=$2; shift 2 ;;
    --only) [[ $# -ge 2 ]] || die "--only needs names"; only=$2; shift 2 ;;
    --timeout) [[ $# -ge 2 && $2 =~ ^[0-9]+$ ]] || die "--timeout needs seconds"; timeout=$2; shift 2 ;;
    --jobs) [[ $# -ge 2 && $2 =~ ^[0-9]+$ ]] || die "--jobs needs a number"; jobs=$2; shift 2 ;;
    --head) from_head=1; shift ;;
    --allow-baseline-failures) allow_baseline=1; shift ;;
    --fast) stop=(--stop-on-failure); shift ;;
    --list) mode=list; shift ;;
    --check | --dry-run) mode=check; shift ;;
    -h | --help) usage; exit 0 ;;
    *) die "unknown option $1 (--help)" ;;
  esac
done
[[ $allow_baseline == 1 && ${#stop[@]} -gt 0 ]] && die "--fast would stop at a test that fails unmutated; drop one of --fast, --allow-baseline-failures"
only_args=()
[[ -n $only ]] && only_args=(--only "$only")

case $mode in
  list) exec "${helper[@]}" list "${only_args[@]}" ;;
  check) exec "${helper[@]}" check "$root" "${only_args[@]}" ;;
esac

start=$SECONDS
names=$("${helper[@]}" names "${only_args[@]}") || exit 2
copy=$dir/tree
build=$copy/build
logs=$dir/logs
backups=$dir/backup
mkdir -p "$dir" "$logs" "$backups" || die "cannot create $dir"
exec 9>"$dir/.lock"
flock -n 9 || die "another mutation check is using $dir (choose another with --dir)"

# 1. The copy.
if [[ $from_head == 1 ]]; then
  "${helper[@]}" sync-head "$root" "$copy" || die "could not copy HEAD to $copy"
else
  "${helper[@]}" sync "$root" "$copy" || die "could not copy the working tree to $copy"
fi
# A run interrupted between a bug and its repair left the bug in; the sync put the
# original back, so old backups are stale.
rm -f "$backups"/*
if [[ -d $root/tools/node_modules ]]; then
  ln -sfn "$root/tools/node_modules" "$copy/tools/node_modules"
fi
"${helper[@]}" check "$copy" "${only_args[@]}" || die "fix scripts/mutations.py first"

# 2. Configure once, build, and the unmutated suite must pass.
if [[ ! -f $build/CMakeCache.txt ]]; then
  echo "configuring $build (preset default, no benchmarks)"
  (cd "$copy" && cmake --preset default -DPW_BUILD_BENCH=OFF) >"$logs/configure.log" 2>&1 ||
    die "configure failed; see $logs/configure.log"
fi

# run_suite NAME: runs every test; sets `failed` (names, one a line) and `suite_rc`.
run_suite() {
  local name=$1 list=$build/Testing/Temporary/LastTestsFailed.log
  rm -f "$list"
  (cd "$build" && ctest -j "$jobs" --timeout "$timeout" --no-tests=error "${stop[@]}") >"$logs/$name.ctest.log" 2>&1
  suite_rc=$?
  failed=""
  # Value-parameterised tests carry "  # GetParam() = ..." in their names: drop it.
  [[ -f $list ]] && failed=$(sed -n 's/^[0-9]*://p' "$list" | sed 's/  *# GetParam().*//')
}

t0=$SECONDS
echo "building the unmutated copy"
cmake --build "$build" -j "$jobs" >"$logs/baseline.build.log" 2>&1 ||
  die "the unmutated copy does not build; see $logs/baseline.build.log"
build_s=$((SECONDS - t0))
echo "running the unmutated suite (built in ${build_s} s)"
t0=$SECONDS
run_suite baseline
baseline_failed=$failed
if [[ $suite_rc != 0 || -n $failed ]]; then
  if [[ $allow_baseline == 1 && -n $failed ]]; then
    echo "note: $(wc -l <<<"$failed") tests fail unmutated and will not count as catching a bug:"
    sed 's/^/  /' <<<"$failed"
  else
    echo "the unmutated suite fails; no bug can be judged until it passes:" >&2
    [[ -n $failed ]] && sed 's/^/  /' <<<"$failed" >&2
    die "see $logs/baseline.ctest.log (--head copies the last commit instead of others' work in progress)"
  fi
fi
total=$(grep -oE 'tests failed out of [0-9]+' "$logs/baseline.ctest.log" | grep -oE '[0-9]+$')
skipped=$(sed -nE 's/^[[:space:]]*[0-9]+ - ([^ ]+) \(Skipped\).*/\1/p' "$logs/baseline.ctest.log" | sort -u)
echo "unmutated: ${total:-?} tests run in $((SECONDS - t0)) s"
if [[ -n $skipped ]]; then
  echo "note: $(wc -l <<<"$skipped") tests were skipped and can catch nothing: $(tr '\n' ' ' <<<"$skipped")"
fi

# 3. Each bug in turn.
applied=""
restore() {
  if [[ -n $applied ]]; then
    "${helper[@]}" restore "$copy" "$applied" "$backups/$applied" || echo "could not restore $applied" >&2
    applied=""
  fi
}
trap 'restore; exit 130' INT TERM

rows=()
bad=0
for name in $names; do
  file=$("${helper[@]}" file "$name")
  t0=$SECONDS
  echo "--- $name ($file)"
  if ! "${helper[@]}" apply "$copy" "$name" "$backups/$name"; then
    rows+=("$name|$file|NOT APPLIED|see above|0")
    bad=1
    continue
  fi
  applied=$name
  if ! cmake --build "$build" -j "$jobs" >"$logs/$name.build.log" 2>&1; then
    restore
    rows+=("$name|$file|BUILD FAILED|$logs/$name.build.log|$((SECONDS - t0))")
    bad=1
    echo "    the bug does not compile; see $logs/$name.build.log"
    continue
  fi
  tb=$((SECONDS - t0))
  run_suite "$name"
  restore
  if [[ -n $baseline_failed && -n $failed ]]; then
    failed=$(grep -vxF -f <(printf '%s\n' "$baseline_failed") <<<"$failed")
  fi
  if [[ -n $failed ]]; then
    n=$(wc -l <<<"$failed")
    by=$(head -n 3 <<<"$failed" | paste -sd, - | sed 's/,/, /g')
    [[ $n -gt 3 ]] && by="$by, ..."
    result="caught ($n)"
  elif [[ $suite_rc != 0 ]]; then
    result="ERROR"
    by="ctest exit $suite_rc without failed tests; see $logs/$name.ctest.log"
    bad=1
  else
    result="SURVIVED"
    by="-"
    bad=1
  fi
  rows+=("$name|$file|$result|$by|$((SECONDS - t0))")
  echo "    $result in $((SECONDS - t0)) s (build ${tb} s): $by"
done
trap - INT TERM

# 4. The table.
{
  echo
  printf '%-29s %-35s %-12s %6s  %s\n' bug file result time "caught by"
  for row in "${rows[@]}"; do
    IFS='|' read -r name file result by secs <<<"$row"
    printf '%-29s %-35s %-12s %3d:%02d  %s\n' "$name" "$file" "$result" $((secs / 60)) $((secs % 60)) "$by"
  done
  echo
  [[ -n $baseline_failed ]] && echo "failing unmutated, not counted: $(paste -sd' ' <<<"$baseline_failed")"
  echo "total $(((SECONDS - start) / 60)) min $(((SECONDS - start) % 60)) s (unmutated build ${build_s} s)"
} | tee "$dir/report.txt"
exit $bad
