#!/usr/bin/env python3
"""photowalk share in a real browser: Debian's Chromium, headless, driven by playwright-core
(web/test/page_check.mjs). For the sample corridor, a three-corridor building made of it,
a corridor of the POV-Ray ground truth (corridor_c) and an imported VRML scene, each page

  - loads with no console error, no page error and no request beyond its own bytes;
  - at each viewpoint draws what `photowalk render` draws there at the same size: PSNR
    over RGB at least the floor below (each floor is the figure measured when it was set,
    less 2 dB: JPEG textures, no detail layer and three.js's sampling against photowalk's);

and on the corridor a walk with key events (W, then Shift+W) moves the eye forward,
keeps it at the avatar's eye height and stops it at the far wall, one avatar radius
before it; touch: a drag on the view turns it and a thumb on the pad walks forward;
PageDown, PageUp and the list go to the viewpoints; the tour button plays the tour; in the building, walking left through the
opening into the wing passes, and beside it the hall's wall stops the eye.

usage: check_share.py PHOTOWALK REPO_ROOT WORK_DIR GROUNDTRUTH_DIR
Skipped (exit 77) without node, Chromium or web/node_modules (scripts/install-tools.sh).
"""
import json, math, os, shutil, subprocess, sys

# (scene, viewpoint number) -> PSNR floor in dB, measured 2026-12-03 at 480x270 less 2 dB.
FLOORS = {
    ("corridor", 1): 29.2, ("corridor", 2): 29.2, ("corridor", 3): 23.9, ("corridor", 4): 31.9,
    ("building", 1): 29.3, ("building", 2): 29.3, ("building", 3): 23.9, ("building", 4): 32.8,
    ("corridor_c", 1): 40.4, ("corridor_c", 2): 41.2, ("corridor_c", 3): 41.0, ("corridor_c", 4): 33.3,
    ("vrml", 1): 19.5,
}
SIZE = "480x270"
failures = []


def run(args, **kw):
    r = subprocess.run([str(a) for a in args], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, **kw)
    if r.returncode != 0:
        sys.exit(f"FAILED: {' '.join(map(str, args))} (exit {r.returncode}):\n{r.stdout}")
    return r.stdout


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what, flush=True)
    if not ok:
        failures.append(what)


def page(photowalk, root, work, name, source, model, extra=()):
    html = os.path.join(work, name + ".html")
    print(run([photowalk, "share", source, "-o", html]).strip().splitlines()[-1])
    refs = []
    for n in range(1, 5):
        ref = os.path.join(work, f"{name}_ref_{n}.png")
        r = subprocess.run([photowalk, "render", model, "-o", ref, "--size", SIZE, "--viewpoint", str(n)],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if r.returncode != 0:
            break  # no such viewpoint
        refs += ["--reference", f"{n}={ref}"]
    shots = os.path.join(work, name + "_shots")
    os.makedirs(shots, exist_ok=True)
    out = run(["node", os.path.join(root, "web", "test", "page_check.mjs"), html, "--size", SIZE, "--screenshot-dir", shots,
               *refs, *extra], timeout=600)
    report = json.loads(out.strip().splitlines()[-1])
    check(not report["errors"], f"{name}: no console error, page error or outside request ({report['errors'][:3]})")
    print(f"      {name}: loaded in {report['loadMs']} ms, {report['fps']} frames in the last second")
    for i, v in enumerate(report["viewpoints"], start=1):
        floor = FLOORS.get((name, i))
        if "psnr" in v and floor is not None:
            check(v["psnr"] >= floor, f"{name} viewpoint {i} '{v['name']}': PSNR {v['psnr']:.2f} dB (floor {floor})")
        elif "psnr" in v:
            print(f"      {name} viewpoint {i} '{v['name']}': PSNR {v['psnr']:.2f} dB (no floor)")
    return report


def main():
    photowalk, root, work, groundtruth = sys.argv[1:5]
    photowalk = os.path.abspath(photowalk)
    if not shutil.which("node") or not os.path.exists("/usr/bin/chromium") or \
            not os.path.isdir(os.path.join(root, "web", "node_modules", "playwright-core")):
        print("skipped: needs node, /usr/bin/chromium and web/node_modules (scripts/install-deps.sh --with-extras, "
              "scripts/install-tools.sh)")
        return 77
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    for f in ("corridor.json", "corridor.png"):
        shutil.copy(os.path.join(root, "assets", f), work)
    shot = os.path.join(work, "corridor.json")
    model = os.path.join(work, "corridor.wrl")
    run([photowalk, "build", shot, "-o", model])

    report = page(photowalk, root, work, "corridor", shot, model, ["--walk", "2", "--tour", "--touch", "2"])
    keys = report["viewpointKeys"]
    check(keys["afterPageDown"] == 1 and keys["afterPageUp"] == 0 and keys["afterClickingThird"] == 2 and keys["fixed"],
          f"PageDown, PageUp and a click on the list go to the viewpoints ({keys})")
    walk = report["walk"]
    check(walk["afterWalking"][2] < walk["before"][2] - 0.9, f"W walks forward (z {walk['before'][2]:.2f} -> {walk['afterWalking'][2]:.2f})")
    check(abs(walk["stopped"][1] - walk["before"][1]) < 1e-3, f"the eye keeps its height ({walk['stopped'][1]:.3f} m)")
    # The sample corridor's far wall is at z = -19 (entrance at z = 6, 19 m long); the avatar's radius 0.25 m.
    check(walk["stoppedStill"] and abs(walk["stopped"][2] - (-19 + 0.25)) < 0.05,
          f"the far wall stops the walk one radius before it (z {walk['stopped'][2]:.3f}, expected -18.75)")
    check(abs(walk["stopped"][0]) < 0.05, f"the walk stays on the centre line (x {walk['stopped'][0]:.3f})")
    touch = report["touch"]
    check(touch["padShown"], "a touch shows the thumb pad")
    check(abs(touch["yawAfterDrag"] - touch["yawBefore"]) > 0.05,
          f"a drag on the view turns it (yaw {touch['yawBefore']:.3f} -> {touch['yawAfterDrag']:.3f})")
    ahead = [-math.sin(touch["yawAfterDrag"]), -math.cos(touch["yawAfterDrag"])]
    moved = [touch["eyeAfterPad"][0] - touch["eyeBefore"][0], touch["eyeAfterPad"][2] - touch["eyeBefore"][2]]
    check(moved[0] * ahead[0] + moved[1] * ahead[1] > 0.9, f"the thumb on the pad's upper half walks forward ({moved})")
    check(report["tour"]["started"] and report["tour"]["moved"] > 0.9, f"the tour button plays the tour ({report['tour']})")

    layout = {"corridors": [
        {"name": "hall", "shot": "corridor.json"},
        {"name": "wing", "shot": "corridor.json", "attach": {"to": "hall", "side": "left", "offset_m": 6.0}},
        {"name": "end", "shot": "corridor.json", "attach": {"to": "hall", "side": "far", "offset_m": 0.0}}]}
    with open(os.path.join(work, "layout.json"), "w") as f:
        json.dump(layout, f)
    building = os.path.join(work, "building.wrl")
    run([photowalk, "build", "--layout", os.path.join(work, "layout.json"), "-o", building])
    # The wing opens off the hall's left wall (x = -2) about z = -6; elsewhere the wall stands.
    report = page(photowalk, root, work, "building", os.path.join(work, "layout.json"), building,
                  ["--place-walk", "0,1.7,-6,1.5708,4", "--place-walk", "0,1.7,0,1.5708,4"])
    through, wall = report["placeWalks"]
    check(through[0] < -3.0, f"the building: walking left at z = -6 passes through the opening into the wing (x {through[0]:.2f})")
    check(abs(wall[0] - (-2 + 0.25)) < 0.05, f"the building: walking left at z = 0 stops at the hall's wall (x {wall[0]:.2f}, expected -1.75)")

    # A corridor of the project's POV-Ray ground truth (narrow, short: corridor_c).
    for ext in (".json", ".png"):
        shutil.copy(os.path.join(groundtruth, "corridor_c" + ext), work)
    narrow = os.path.join(work, "corridor_c.wrl")
    run([photowalk, "build", os.path.join(work, "corridor_c.json"), "-o", narrow])
    page(photowalk, root, work, "corridor_c", os.path.join(work, "corridor_c.json"), narrow)

    vrml = os.path.join(root, "tests", "data", "vrml-samples", "vrml_2", "kings_head.wrl")
    page(photowalk, root, work, "vrml", vrml, vrml)

    print(f"{len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
