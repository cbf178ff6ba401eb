#!/usr/bin/env python3
"""How long photowalk's commands take from exec to exit, for one or more builds (not a test).

usage: bench/startup.py PHOTOWALK [PHOTOWALK ...] [--runs N]

Runs each command below on each binary in turn (A B A B ..., so that load from elsewhere
falls on all of them), N times (default 15), and prints each one's median wall time and
its ratio to the first binary's. The commands are what a script calls photowalk for:
  help     photowalk --help (the program's start alone: loading its shared libraries)
  measure  photowalk measure assets/corridor.json (reads a shot, no photo)
  detect   photowalk detect assets/corridor.png -o TMP (reads a photo, detects)
  render   photowalk render sample -o TMP.png --size 64x48 --cpu (starts Vulkan)
A baseline for a change to what the program links: the same build relinked as it was
(its link line in build/editor/CMakeFiles/photowalk.dir/link.txt, with the library added).
"""
import os, statistics, subprocess, sys, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def main():
    args = sys.argv[1:]
    runs = 15
    if "--runs" in args:
        i = args.index("--runs")
        runs = int(args[i + 1])
        del args[i:i + 2]
    if not args:
        sys.exit(__doc__)
    binaries = [os.path.abspath(b) for b in args]
    tmp = tempfile.mkdtemp()
    commands = {
        "help": ["--help"],
        "measure": ["measure", "assets/corridor.json"],
        "detect": ["detect", "assets/corridor.png", "-o", os.path.join(tmp, "shot.json")],
        "render": ["render", "sample", "-o", os.path.join(tmp, "view.png"), "--size", "64x48", "--cpu"],
    }
    times = {(b, c): [] for b in binaries for c in commands}
    for _ in range(runs):
        for name, command in commands.items():
            for b in binaries:
                start = time.perf_counter()
                subprocess.run([b] + command, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                times[(b, name)].append(time.perf_counter() - start)
    print("%-8s %s" % ("command", "  ".join("%-22s" % ("median ms (%s)" % chr(65 + i)) for i in range(len(binaries)))))
    for name in commands:
        base = statistics.median(times[(binaries[0], name)])
        cells = []
        for b in binaries:
            m = statistics.median(times[(b, name)])
            cells.append("%-22s" % ("%.1f (x%.2f)" % (1000 * m, m / base)))
        print("%-8s %s" % (name, "  ".join(cells)))
    for i, b in enumerate(binaries):
        print("%s: %s" % (chr(65 + i), b))


if __name__ == "__main__":
    main()
