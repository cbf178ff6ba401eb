#!/usr/bin/env bash
# A/B of the walkthrough's frame cost for two builds of photowalk on the same machine
# state, as bench/walk_fps.sh walks (1280x720, --no-vsync, lavapipe under xvfb-run):
# an empty scene, one corridor and the built-in sample room. Runs alternate A B A B ...
# so that load from elsewhere falls on both, and each is measured two ways:
#   wall: the walk's own median frame time;
#   CPU:  CPU time of the walk and its X server per frame (a run of FRAMES frames minus
#         a run of 30, over the difference), which other people's load on a shared
#         machine disturbs far less than the wall clock.
# Prints per model the median over rounds of each, and B - A. Not a test.
# Usage: bench/walk_fps_ab.sh BUILD_A BUILD_B [FRAMES] [ROUNDS]   (defaults: 300, 3)
#   e.g. git worktree add /tmp/pw-base HEAD~1, build photowalk there, then
#        bench/walk_fps_ab.sh /tmp/pw-base/build build
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$2/photowalk" build assets/corridor.json -o "$out/one.wrl" --px-per-m 60 >/dev/null
printf '#VRML V2.0 utf8\nViewpoint { position 0 1.6 0 }\n' > "$out/empty.wrl"
python3 - "$1/photowalk" "$2/photowalk" "${3:-300}" "${4:-3}" "$out" <<'PY'
import re, resource, statistics, subprocess, sys
binaries = {"A": sys.argv[1], "B": sys.argv[2]}
frames, rounds, out = int(sys.argv[3]), int(sys.argv[4]), sys.argv[5]
models = {"empty": f"{out}/empty.wrl", "one": f"{out}/one.wrl", "sample": "sample"}

def walk(binary, model, n):
    """(median frame ms, CPU ms of the run with its X server)"""
    with open(f"{out}/walk.replay", "w") as f:
        f.write(f"0 key W down\n{n // 2} mouse 400 0\n{n} quit\n")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    run = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1920x1080x24", binary, "walk", models[model],
                          "--size", "1280x720", "--no-vsync", "--replay", f"{out}/walk.replay", "--no-overlay"],
                         capture_output=True, text=True, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime) * 1e3
    return float(re.search(r"frame time median ([0-9.]+) ms", run.stdout).group(1)), cpu

wall, cpu = {}, {}
for r in range(rounds):
    for model in models:
        for side in "AB":
            median, long_cpu = walk(binaries[side], model, frames)
            _, short_cpu = walk(binaries[side], model, 30)
            per_frame = (long_cpu - short_cpu) / (frames - 30)
            wall.setdefault((model, side), []).append(median)
            cpu.setdefault((model, side), []).append(per_frame)
            print(f"round {r + 1} {side} {model}: wall median {median:.2f} ms, CPU {per_frame:.2f} ms per frame", flush=True)
print(f"\nmedians over {rounds} rounds of {frames} frames   wall A   wall B  B - A |  CPU A    CPU B   B - A (ms per frame)")
for model in models:
    wa, wb = statistics.median(wall[model, "A"]), statistics.median(wall[model, "B"])
    ca, cb = statistics.median(cpu[model, "A"]), statistics.median(cpu[model, "B"])
    print(f"{model:40s} {wa:7.2f} {wb:7.2f} {wb - wa:+6.2f} | {ca:7.2f} {cb:7.2f} {cb - ca:+6.2f}")
PY
