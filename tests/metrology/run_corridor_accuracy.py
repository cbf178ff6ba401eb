#!/usr/bin/env python3
"""ctest wrapper: runs ../shared/tools/corridor-accuracy on a photowalk binary.

usage: run_corridor_accuracy.py SHARED_DIR PHOTOWALK [--max-median PCT] [TOOL_ARGS...]
Exits 77 (ctest SKIP_RETURN_CODE) when the shared tool or scenes are absent. Else
fails when the tool fails (a scene not measured, or an error over its --max-error)
or when the median |error| it reports exceeds --max-median.
"""
import os, re, subprocess, sys

def main():
    shared, photowalk, rest = sys.argv[1], sys.argv[2], sys.argv[3:]
    max_median = None
    if "--max-median" in rest:
        i = rest.index("--max-median")
        max_median = float(rest[i + 1])
        del rest[i:i + 2]
    tool = os.path.join(shared, "tools", "corridor-accuracy")
    corridors = os.path.join(shared, "corridors")
    if not os.path.isfile(tool) or not os.path.isdir(corridors):
        print("skipped: %s (the shared ground-truth scenes) is absent" % shared)
        return 77
    r = subprocess.run([sys.executable, tool, photowalk] + rest, capture_output=True, text=True)
    sys.stdout.write(r.stdout + r.stderr)
    if r.returncode != 0:
        return r.returncode
    if max_median is not None:
        m = re.search(r"median \|error\| ([0-9.]+)%", r.stdout)
        if not m:
            print("no median in the tool's output")
            return 1
        if float(m.group(1)) > max_median:
            print("median |error| %s%% exceeds %s%%" % (m.group(1), max_median))
            return 1
    return 0

if __name__ == "__main__":
    sys.exit(main())
