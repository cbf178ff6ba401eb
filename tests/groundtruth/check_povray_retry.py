#!/usr/bin/env python3
"""make_corridors.run_povray against stand-in povray commands (no rendering): one whose
render thread fails to start twice and then succeeds is run three times and succeeds; one
that always fails so is given up after POVRAY_TRIES runs; one that fails otherwise (a scene
error) is run once. Exits non-zero with the failed check's line."""
import os, stat, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_corridors import POVRAY_STARTUP_TIMEOUT, POVRAY_TRIES, run_povray  # noqa: E402

# A stand-in povray: counts its runs in ./runs, fails with `message` (exit 1) on the first
# `failures` runs, then exits 0.
STAND_IN = """#!/bin/sh
n=$(cat runs 2>/dev/null || echo 0); n=$((n + 1)); echo $n > runs
if [ $n -le {failures} ]; then echo "{message}" >&2; exit 1; fi
exit 0
"""


def runs_of(failures, message):
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "povray")
        with open(path, "w") as f:
            f.write(STAND_IN.format(failures=failures, message=message))
        os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR)
        r = run_povray([path, "+Iscene.pov"], d, pause_s=0.0)
        with open(os.path.join(d, "runs")) as f:
            return r.returncode, int(f.read())


def main():
    checks = [
        ("render thread late twice, then renders", runs_of(2, POVRAY_STARTUP_TIMEOUT), (0, 3)),
        ("render thread never starts", runs_of(99, POVRAY_STARTUP_TIMEOUT), (1, POVRAY_TRIES)),
        ("a scene error", runs_of(99, "Parse Error: No matching } in object"), (1, 1)),
    ]
    failed = 0
    for what, got, want in checks:
        ok = got == want
        failed += not ok
        print("%-40s exit %d after %d runs (want exit %d after %d)%s" % ((what,) + got + want + ("" if ok else "  FAILED",)))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
