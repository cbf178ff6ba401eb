#!/usr/bin/env python3
"""Kill check: does a build or a tour killed with SIGKILL at any moment leave the
previous output whole, and no temporary file behind once the next run is done?

On a 12 MP photo (assets/corridor.png enlarged 3.6x to 4608x2592, its shot scaled with
it) as two shots, A and B (another focal length: every texture differs, not only the
scale), in a scratch folder:

  build  `build SHOT -o out/m.wrl --gltf out/m.glb`, alternating A and B, each trial
         killed (SIGKILL, then waited for) at a random moment between its start and
         1.2x a whole build's time. After each: the folder holds model A or model B
         whole (m.wrl, every m_* texture it names, m.glb, byte for byte; a changed
         texture takes a name of its own, so names may differ), and every hidden entry
         in it belongs to the run just killed (its process id in the name, or in its
         lock's): what an earlier killed run left was removed by the next run as it
         started (unless that one too was killed within 0.5 s of its start).
  tour   `tour MODEL -o frames --video out/v.avi --frames N --size 320x180 --cpu` of
         that model, alternating 16 and 20 frames (two different videos), killed the
         same way. After each: out/v.avi is one of the two whole videos (or absent
         before the first whole tour), every frame in `frames` is a whole PNG, and the
         hidden entries belong to the run just killed.

At the end one whole run of each leaves no hidden entry at all, and no texture that
the model does not name. Prints a line per
failure and a summary; exits non-zero when any trial failed.

Run it on demand, not in CI, and niced on a shared machine:
  nice -n 10 python3 scripts/kill-check.py build/photowalk                 # 200 of each
  python3 scripts/kill-check.py build/photowalk --trials 20 --only build
Options: --trials N (per command, default 200), --only build|tour, --dir DIR (scratch
folder, default a fresh one under /tmp, removed when all passed), --seed S.
"""
import argparse
import hashlib
import json
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import zlib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SCALE = 3.6  # 1280x720 -> 4608x2592, 11.9 MP


def digest(path):
    return hashlib.sha256(path.read_bytes()).hexdigest()


def make_photo(folder):
    """The sample photo at 12 MP and shots A and B of it."""
    from PIL import Image

    with Image.open(ROOT / "assets" / "corridor.png") as small:
        big = small.convert("RGB").resize((round(small.width * SCALE), round(small.height * SCALE)), Image.BICUBIC)
    big.save(folder / "corridor12.png", compress_level=1)
    shot = json.loads((ROOT / "assets" / "corridor.json").read_text())
    shot["image"] = "corridor12.png"
    shot["focal_px"] *= SCALE
    shot["principal_point"] = [(c + 0.5) * SCALE - 0.5 for c in shot["principal_point"]]
    shot["corners_px"] = {k: [(c + 0.5) * SCALE - 0.5 for c in v] for k, v in shot["corners_px"].items()}
    # Both shots are s.json (in folders a/ and b/), so both models name their textures m_s_*.
    for name, focal_scale in (("a", 1.0), ("b", 0.94)):
        (folder / name).mkdir()
        s = dict(shot, image="../corridor12.png", focal_px=shot["focal_px"] * focal_scale)
        (folder / name / "s.json").write_text(json.dumps(s, indent=1))


def run(args, timeout=600):
    r = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=timeout)
    if r.returncode != 0:
        sys.exit("kill-check: " + " ".join(map(str, args)) + " failed:\n" + r.stdout)


def killed_run(args, delay):
    """Starts the command, kills it with SIGKILL after `delay` s (unless it ended), waits
    for it (reaped: its process is gone). Returns (pid, whether it finished by itself)."""
    p = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        p.wait(timeout=delay)
        return p.pid, True
    except subprocess.TimeoutExpired:
        p.send_signal(signal.SIGKILL)
        p.wait()
        return p.pid, False


def hidden(folder):
    return sorted(e.name for e in folder.iterdir() if e.name.startswith("."))


def model_files(folder):
    """The model as it reads: m.wrl's text with each texture's name (an m_* file it
    names) replaced by the file's digest, so that one model compares equal whatever
    names its textures took (a texture that changed takes a name of its own), and
    m.glb's digest. A texture named but missing keeps its name, and so differs."""
    files = {e.name: e for e in folder.iterdir() if e.is_file()}
    model = {}
    if "m.wrl" in files:
        text = files["m.wrl"].read_text(errors="replace")
        for name in sorted((n for n in files if n.startswith("m_")), key=len, reverse=True):
            text = text.replace(name, "#" + digest(files[name]))
        model["m.wrl"] = text
    if "m.glb" in files:
        model["m.glb"] = digest(files["m.glb"])
    return model


def unnamed_textures(folder):
    """The m_* files that m.wrl does not name: what no model uses."""
    text = (folder / "m.wrl").read_text(errors="replace") if (folder / "m.wrl").exists() else ""
    return sorted(e.name for e in folder.iterdir()
                  if e.name.startswith("m_") and f'"{e.name}"' not in text and "_detail." not in e.name)


def whole_png(path):
    """A PNG whose chunks are all there, each with its CRC, ending in IEND."""
    data = path.read_bytes()
    if not data.startswith(b"\x89PNG\r\n\x1a\n"):
        return False
    at = 8
    while at + 12 <= len(data):
        length = int.from_bytes(data[at:at + 4], "big")
        kind = data[at + 4:at + 8]
        end = at + 12 + length
        if end > len(data):
            return False
        if zlib.crc32(data[at + 4:end - 4]) != int.from_bytes(data[end - 4:end], "big"):
            return False
        if kind == b"IEND":
            return end == len(data)
        at = end
    return False


def owner_pids(folder, name):
    """The process ids a hidden entry's name (or a lock folder's files) carry."""
    path = folder / name
    if name.endswith(".photowalk-lock") and path.is_dir():
        return {e.name for e in path.iterdir()}
    return set(re.findall(r"\d+", name))


def check_hidden(folder, pids, what, trial, failures):
    """Every hidden entry belongs to one of `pids` (None: there must be none)."""
    strays = [n for n in hidden(folder) if pids is None or not owner_pids(folder, n) & {str(p) for p in pids}]
    if strays:
        failures.append(f"{what} trial {trial}: left behind in {folder.name}/: {', '.join(strays)}")


# A run removes what killed runs left as it starts (base/staging.h: removeLeftoversOf);
# one killed within this long of its start may not have got that far, and then what
# the runs before it left may still be there.
STARTED_S = 0.5


def allowed_pids(previous, pid, delay):
    """The runs whose leftovers may be in the folder after this one was killed: its own,
    and, if it was killed before it could clean up, those the previous trial allowed."""
    return {pid} | (previous if delay < STARTED_S else set())


def check_build(photowalk, work, trials, rng, failures):
    out = work / "out"
    out.mkdir()
    models = {}
    times = []
    for name in ("a", "b"):
        alone = work / ("alone_" + name)
        alone.mkdir()
        started = time.monotonic()
        run([photowalk, "build", work / name / "s.json", "-o", alone / "m.wrl", "--gltf", alone / "m.glb"])
        times.append(time.monotonic() - started)
        models[name] = model_files(alone)
    assert digest(work / "alone_a" / "m_s_floor.png") != digest(work / "alone_b" / "m_s_floor.png")
    run([photowalk, "build", work / "a" / "s.json", "-o", out / "m.wrl", "--gltf", out / "m.glb"])
    whole = max(times)
    print(f"build: a whole build takes {whole:.2f} s; {trials} trials killed within 0-{1.2 * whole:.2f} s", flush=True)
    finished = 0
    allowed = set()
    for trial in range(trials):
        shot = "b" if trial % 2 == 0 else "a"
        delay = rng.uniform(0, 1.2 * whole)
        pid, done = killed_run([photowalk, "build", work / shot / "s.json", "-o", out / "m.wrl", "--gltf", out / "m.glb"],
                               delay)
        finished += done
        allowed = allowed_pids(allowed, pid, delay)
        now = model_files(out)
        if now not in (models["a"], models["b"]):
            parts = {n: "A" if d == models["a"].get(n) else "B" if d == models["b"].get(n) else "neither" for n, d in now.items()}
            failures.append(f"build trial {trial}: neither model whole ({parts})")
        check_hidden(out, allowed, "build", trial, failures)
    run([photowalk, "build", work / "b" / "s.json", "-o", out / "m.wrl", "--gltf", out / "m.glb"])
    check_hidden(out, None, "build", "after the whole run", failures)
    if unnamed_textures(out):
        failures.append(f"build: textures no model names left after the whole run: {', '.join(unnamed_textures(out))}")
    if model_files(out) != models["b"]:
        failures.append("build: the whole run after the trials did not leave model B")
    return finished


def check_tour(photowalk, work, trials, rng, failures):
    model = work / "alone_a" / "m.wrl"
    out = work / "tour"
    out.mkdir()
    frames = out / "frames"
    videos, times = {}, []
    for count in (16, 20):
        started = time.monotonic()
        run([photowalk, "tour", model, "-o", frames, "--video", out / "v.avi", "--frames", str(count), "--size", "320x180",
             "--cpu"])
        times.append(time.monotonic() - started)
        videos[count] = digest(out / "v.avi")
    assert videos[16] != videos[20]
    whole = max(times)
    print(f"tour: a whole tour takes {whole:.2f} s; {trials} trials killed within 0-{1.2 * whole:.2f} s", flush=True)
    finished = 0
    allowed = set()
    for trial in range(trials):
        count = 16 if trial % 2 == 0 else 20
        delay = rng.uniform(0, 1.2 * whole)
        pid, done = killed_run([photowalk, "tour", model, "-o", frames, "--video", out / "v.avi", "--frames", str(count),
                                "--size", "320x180", "--cpu"], delay)
        finished += done
        allowed = allowed_pids(allowed, pid, delay)
        if digest(out / "v.avi") not in videos.values():
            failures.append(f"tour trial {trial}: v.avi is neither whole video")
        broken = [f.name for f in sorted(frames.iterdir()) if not f.name.startswith(".") and not whole_png(f)]
        if broken:
            failures.append(f"tour trial {trial}: frames not whole: {', '.join(broken)}")
        check_hidden(out, allowed, "tour", trial, failures)
        check_hidden(frames, allowed, "tour (frames)", trial, failures)
    run([photowalk, "tour", model, "-o", frames, "--video", out / "v.avi", "--frames", "16", "--size", "320x180", "--cpu"])
    check_hidden(out, None, "tour", "after the whole run", failures)
    check_hidden(frames, None, "tour (frames)", "after the whole run", failures)
    return finished


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("photowalk")
    parser.add_argument("--trials", type=int, default=200)
    parser.add_argument("--only", choices=("build", "tour"))
    parser.add_argument("--dir")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    photowalk = str(Path(args.photowalk).resolve())
    work = Path(args.dir) if args.dir else Path(tempfile.mkdtemp(prefix="pw-kill-check-"))
    if args.dir:
        shutil.rmtree(work, ignore_errors=True)
        work.mkdir(parents=True)
    rng = random.Random(args.seed)
    started = time.monotonic()
    # A copy: a rebuild during the run (minutes) must not swap the program under test.
    shutil.copy2(photowalk, work / "photowalk")
    photowalk = str(work / "photowalk")
    make_photo(work)
    failures = []
    summary = []
    if args.only in (None, "build"):
        finished = check_build(photowalk, work, args.trials, rng, failures)
        summary.append(f"build: {args.trials} trials ({args.trials - finished} killed, {finished} ended first)")
    if args.only in (None, "tour"):
        finished = check_tour(photowalk, work, args.trials, rng, failures)
        summary.append(f"tour: {args.trials} trials ({args.trials - finished} killed, {finished} ended first)")
    for line in failures:
        print("FAIL " + line)
    print("; ".join(summary) + f"; {len(failures)} failures; {time.monotonic() - started:.0f} s")
    if failures:
        print(f"kept {work}")
        return 1
    if not args.dir:
        shutil.rmtree(work)
    return 0


if __name__ == "__main__":
    sys.exit(main())
