#!/usr/bin/env python3
"""Measuring objects on the random corridor scenes (issue 25): on demand, not in CI.

usage: bench/object_accuracy.py PHOTOWALK [--seeds A-B] [--trials N] [-j N] [--json OUT]

For each seed's scene (tests/groundtruth/random_corridors.py's make_scene: no render is
needed, only the scene's camera and its objects' true points), a shot with the exact
corners (the generator's own projection, unrounded) and the scene's focal length,
principal point and camera height, and for every door, picture and person whose key
points are all inside the photo:
  door     width:  bottom_near and bottom_far on the floor, their distance
           height: top_near on the vertical above bottom_near
  picture  width and height: its corners on its wall (wall:left, wall:right, wall:far):
           as they are (its face 1.5 cm off the wall) and taken onto the wall's plane
  person   height: head_top on the vertical above the feet on the floor
measured by `PHOTOWALK measure SHOT --point ... --distance/--height ...` against the
distance between the true points. Prints, per kind and in total: the worst relative
error from the exact pixels (target 1e-6), and, over --trials runs with 1 px of
Gaussian noise on every corner and every point, the share of values within 2 sigma
(target 95 +- 3) and the median relative error.
Default seeds: HELD_OUT 100000-100199 (the measurement is tuned on no scene; these are
the ones the README reports).
"""
import argparse, json, math, os, random, statistics, subprocess, sys, tempfile
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "groundtruth"))
import random_corridors as rc  # noqa: E402
from make_corridors import Camera, CORNERS  # noqa: E402

WALL = {"left_wall": "wall:left", "right_wall": "wall:right", "far_wall": "wall:far"}


def png(path, w, h):
    """A blank PNG of w x h (measure reads the photo for its size only)."""
    import struct, zlib
    raw = b"".join(b"\0" + b"\0" * w for _ in range(h))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 0, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def dist(a, b):
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))


def tasks_of(s, cam):
    """(kind, what, [(name, keypoint, surface)], quantity, from, to, truth) for the scene's measurable objects."""
    w, h = s["size"]
    inside = lambda p: (lambda u, v, d: d > 0 and 0 <= u <= w - 1 and 0 <= v <= h - 1)(*cam.project(p))
    out = []
    for k, ob in enumerate(s["objects"]):
        kp = ob["keypoints_m"]
        if not all(inside(p) for p in kp.values()):
            continue
        tag = "o%d_" % k
        if ob["kind"] == "door" and ob["on"] in ("left_wall", "right_wall") and {"bottom_near", "bottom_far", "top_near"} <= set(kp):
            pts = [(tag + "bn", kp["bottom_near"], "floor"), (tag + "bf", kp["bottom_far"], "floor"),
                   (tag + "tn", kp["top_near"], "above:" + tag + "bn")]
            out.append(("door", "width", pts, "distance", tag + "bn", tag + "bf", dist(kp["bottom_near"], kp["bottom_far"])))
            out.append(("door", "height", pts, "height", tag + "bn", tag + "tn", kp["top_near"][1] - kp["bottom_near"][1]))
        elif ob["kind"] == "picture" and ob["on"] in WALL and len(kp) == 4:
            names = sorted(kp)
            bottoms = [n for n in names if n.startswith("bottom")]
            tops = [n for n in names if n.startswith("top")]
            a, b = bottoms[0], bottoms[1]
            top = [t for t in tops if t.split("_", 1)[1] == a.split("_", 1)[1]][0]
            # Its front face, where a person clicks, stands its thickness (1.5 cm) off the
            # wall; "on the wall" takes the same corners onto the wall's plane, where the
            # measurement is exact.
            axis, value = {"left_wall": (0, -s["width"] / 2), "right_wall": (0, s["width"] / 2),
                           "far_wall": (2, -s["length"])}[ob["on"]]
            onwall = {n: [value if i == axis else c for i, c in enumerate(p)] for n, p in kp.items()}
            for variant, points, tg in (("picture", kp, tag), ("picture on the wall", onwall, tag + "w")):
                pts = [(tg + n, points[n], WALL[ob["on"]]) for n in names]
                out.append((variant, "width", pts, "distance", tg + a, tg + b, dist(points[a], points[b])))
                out.append((variant, "height", pts, "distance", tg + a, tg + top, dist(points[a], points[top])))
        elif ob["kind"] == "person" and {"feet", "head_top"} <= set(kp):
            pts = [(tag + "feet", kp["feet"], "floor"), (tag + "head", kp["head_top"], "above:" + tag + "feet")]
            out.append(("person", "height", pts, "height", tag + "feet", tag + "head", kp["head_top"][1] - kp["feet"][1]))
    return out


def run_scene(photowalk, seed, trials, tmp):
    s = rc.make_scene(seed)
    cam = Camera(s["eye"], s["ypr"], s["size"], s["focal_px"], s["principal"])
    w2, H, L = s["width"] / 2, s["height"], s["length"]
    corners_m = [(-w2, H, -L), (w2, H, -L), (-w2, 0, -L), (w2, 0, -L), (-w2, 0, 0), (w2, 0, 0), (-w2, H, 0), (w2, H, 0)]
    exact = {n: cam.project(p)[:2] for n, p in zip(CORNERS, corners_m)}
    tasks = tasks_of(s, cam)
    if not tasks:
        return []
    folder = os.path.join(tmp, "s%d" % seed)
    os.makedirs(folder, exist_ok=True)
    png(os.path.join(folder, "photo.png"), *s["size"])
    rng = random.Random(seed)
    rows = []
    for trial in range(trials + 1):
        noise = (lambda: (rng.gauss(0, 1), rng.gauss(0, 1))) if trial else (lambda: (0.0, 0.0))
        shot = {"image": "photo.png", "focal_px": s["focal_px"], "principal_point": list(s["principal"]),
                "camera_height_m": s["eye"][1],
                "corners_px": {n: [u + du, v + dv] for (n, (u, v)), (du, dv) in ((x, noise()) for x in exact.items())}}
        path = os.path.join(folder, "shot.json")
        with open(path, "w") as f:
            json.dump(shot, f)
        args, seen = [photowalk, "measure", path], set()
        for (_, _, pts, quantity, a, b, _) in tasks:
            for name, p, surface in pts:
                if name in seen:
                    continue
                seen.add(name)
                u, v, _ = cam.project(p)
                du, dv = noise()
                args += ["--point", "%s=%r,%r@%s" % (name, u + du, v + dv, surface)]
            args += ["--" + quantity, "%s,%s" % (a, b)]
        r = subprocess.run(args, capture_output=True, text=True, timeout=300)
        if r.returncode != 0:
            rows.append({"seed": seed, "trial": trial, "error": r.stderr.strip()})
            continue
        objects = {(o["quantity"], o["from"], o["to"]): o for o in json.loads(r.stdout)["objects"]}
        for (kind, what, _, quantity, a, b, truth) in tasks:
            o = objects[(quantity, a, b)]
            rows.append({"seed": seed, "trial": trial, "kind": kind, "what": what, "truth": truth,
                         "value": o["value_m"], "sigma": o["sigma_m"]})
    return rows


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("photowalk")
    p.add_argument("--seeds", default="100000-100199")
    p.add_argument("--trials", type=int, default=5)
    p.add_argument("-j", type=int, default=2)
    p.add_argument("--json")
    a = p.parse_args()
    lo, _, hi = a.seeds.partition("-")
    seeds = list(range(int(lo), int(hi or lo) + 1))
    photowalk = os.path.abspath(a.photowalk)
    with tempfile.TemporaryDirectory() as tmp, ThreadPoolExecutor(a.j) as ex:
        rows = [r for rs in ex.map(lambda seed: run_scene(photowalk, seed, a.trials, tmp), seeds) for r in rs]
    errors = [r for r in rows if "error" in r]
    good = [r for r in rows if "error" not in r]
    print("%d scenes, %d objects' values measured (%d runs failed)" %
          (len(seeds), sum(1 for r in good if r["trial"] == 0), len(errors)))
    for e in errors[:5]:
        print("  failed: seed %d trial %d: %s" % (e["seed"], e["trial"], e["error"]))
    groups = sorted({(r["kind"], r["what"]) for r in good}) + [("all", "")]
    print("%-28s %6s %14s %12s %14s" % ("", "values", "exact: worst", "2 sigma", "noisy: median"))
    summary = {}
    for kind, what in groups:
        sel = [r for r in good if kind == "all" or (r["kind"], r["what"]) == (kind, what)]
        exact = [abs(r["value"] / r["truth"] - 1) for r in sel if r["trial"] == 0]
        noisy = [r for r in sel if r["trial"] > 0]
        cover = 100.0 * sum(abs(r["value"] - r["truth"]) <= 2 * r["sigma"] for r in noisy) / max(1, len(noisy))
        med = statistics.median([abs(r["value"] / r["truth"] - 1) for r in noisy]) if noisy else float("nan")
        label = kind + (" " + what if what else "")
        print("%-28s %6d %14.2e %11.1f%% %13.2f%%" % (label, len(exact), max(exact) if exact else float("nan"), cover,
                                                       100 * med))
        summary[label] = {"values": len(exact), "exact_worst_relative": max(exact) if exact else None,
                          "noisy_within_2_sigma_percent": cover, "noisy_median_relative": med}
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"summary": summary, "rows": rows}, f, indent=1)


if __name__ == "__main__":
    main()
