#!/usr/bin/env python3
"""Cabinets stood up as boxes (issue 25, part 3): their width, depth and height against the truth.

usage: bench/standing_boxes.py PHOTOWALK --seeds A-B[,C-D...] [--cache DIR] [-j N] [--json OUT]

For each seed (tests/groundtruth/random_corridors.py; cache default build/random-scenes/;
renders the photo and its object-id mask where the cache lacks them), every cabinet whose
eight corners are in the photo, 80 px high or more, with its foot in view and 85% or more
of its outline showing in the mask (not behind another object): a shot with the scene's
exact corners and camera height and a cutout around the cabinet's pixels in the mask,
4 px beyond them as a person draws one, "shape": "box" and, for comparison, "flat"; each
built with `photowalk build`, whose model says how wide (across the corridor), deep
(along it) and high it stood the box up, and how high the flat cut-out. Prints each
cabinet and the median relative errors and the share within 10%.

The ranges are detect_heldout.py's: TUNE 0-599 (look at these while working), HELD_OUT
100000-100299 (report on these). A scene's photo and mask cost about 2-5 s of povray.
"""
import argparse, json, os, re, statistics, subprocess, sys, tempfile, time
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "groundtruth"))
import random_corridors as rc  # noqa: E402
from detect_heldout import parse_seeds  # noqa: E402  (the same seed ranges)

MARGIN_PX = 4
MIN_HEIGHT_PX = 80
MIN_SHOWN = 0.85


def hull_area(points):
    """Area of the convex hull of 2-D points."""
    return rc.polygon_area(rc.convex_hull([tuple(p) for p in points]))


def cabinets(seed, cache):
    """The seed's cabinets to stand up: (object, outline) for each that shows whole enough."""
    base = os.path.join(cache, "seed_%05d" % seed)
    if not os.path.exists(base + ".json"):
        rc.make_one(seed, cache, 1.0, True, True, 1)
    ans = json.load(open(base + ".json"))
    wanted = []
    w, h = ans["image_size"]
    for ob in ans["objects"]:
        if ob["kind"] != "cabinet":
            continue
        k = list(ob["keypoints_px"].values())
        us, vs = [p[0] for p in k], [p[1] for p in k]
        if min(us) < 5 or min(vs) < 5 or max(us) > w - 5 or max(vs) > h - 5 or max(vs) - min(vs) < MIN_HEIGHT_PX:
            continue
        x, _, z = ob["place_m"]
        if abs(x) > ans["width_m"] / 2 or z < -ans["length_m"]:
            continue
        wanted.append(ob)
    if not wanted:
        return ans, []
    if not os.path.exists(base + "_mask.ppm"):
        rc.make_one(seed, cache, 1.0, False, True, 1)
    mw, mh, ids = rc.read_mask_ids(base + "_mask.ppm")
    out = []
    for ob in wanted:
        pix = [(i % mw, i // mw) for i, v in enumerate(ids) if v == ob["mask_id"]]
        if not pix:
            continue
        shown = len(pix) / max(1.0, hull_area(ob["keypoints_px"].values()))
        bottom = max(p[1] for p in pix)
        if shown < MIN_SHOWN or bottom < max(p[1] for p in ob["keypoints_px"].values()) - 1.5:
            continue
        x0, y0 = max(0, min(p[0] for p in pix) - MARGIN_PX), max(0, min(p[1] for p in pix) - MARGIN_PX)
        x1, y1 = min(mw - 1, max(p[0] for p in pix) + MARGIN_PX), min(mh - 1, bottom + MARGIN_PX)
        if y1 >= mh - 1:
            continue
        out.append((ob, [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]))
    return ans, out


def stand(photowalk, cache, seed, ans, ob, outline, shape):
    """What the model says of the cabinet stood up with `shape`: (width, depth, height) or the error."""
    shot = dict(ans)
    shot["image"] = os.path.join(cache, "seed_%05d.png" % seed)
    shot["cutouts"] = [{"name": "cabinet", "outline_px": outline, "shape": shape}]
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "shot.json")
        json.dump(shot, open(path, "w"))
        r = subprocess.run([photowalk, "build", path, "-o", os.path.join(d, "m.wrl")], capture_output=True, text=True)
        if r.returncode != 0:
            return r.stderr.strip().splitlines()[-1] if r.stderr.strip() else "exit %d" % r.returncode
        text = open(os.path.join(d, "m.wrl")).read()
    m = re.search(r"a box ([\d.]+) m wide, ([\d.]+) m deep and ([\d.]+) m high \(its depth (\u00b1 ([\d.]+)|not)", text)
    if m:
        return (float(m.group(1)), float(m.group(2)), float(m.group(3)), m.group(4) != "not",
                float(m.group(5)) if m.group(5) else None)
    m = re.search(r"a cut-out ([\d.]+) m wide and ([\d.]+) m high", text)
    return (float(m.group(1)), None, float(m.group(2))) if m else "no stood-up line in the model"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("photowalk")
    ap.add_argument("--seeds", required=True)
    ap.add_argument("--cache", default=os.path.join(ROOT, "build", "random-scenes"))
    ap.add_argument("-j", "--jobs", type=int, default=2)
    ap.add_argument("--json")
    args = ap.parse_args()
    os.makedirs(args.cache, exist_ok=True)
    t0 = time.time()
    seeds = parse_seeds(args.seeds)
    with ThreadPoolExecutor(args.jobs) as pool:
        found = list(pool.map(lambda s: (s, cabinets(s, args.cache)), seeds))
    jobs = [(s, ans, ob, outline) for s, (ans, obs) in found for ob, outline in obs]

    def one(job):
        s, ans, ob, outline = job
        box = stand(args.photowalk, args.cache, s, ans, ob, outline, "box")
        flat = stand(args.photowalk, args.cache, s, ans, ob, outline, "flat")
        xs = [p[0] for p in ob["keypoints_m"].values()]
        zs = [p[2] for p in ob["keypoints_m"].values()]
        truth = (max(xs) - min(xs), max(zs) - min(zs), ob["size_m"][1])
        return {"seed": s, "object": ob["id"], "truth_m": truth, "box_m": box, "flat_m": flat}

    with ThreadPoolExecutor(args.jobs) as pool:
        rows = list(pool.map(one, jobs))
    errors = {"width": [], "depth (where seen)": [], "height": [], "flat height": []}
    unseen, covered = 0, []
    for r in rows:
        t, b, f = r["truth_m"], r["box_m"], r["flat_m"]
        line = "seed %d cabinet %d: truth %.2f x %.2f x %.2f m (wide, deep, high)" % (r["seed"], r["object"], *t)
        if isinstance(b, tuple):
            line += "; box %.2f x %.2f x %.2f" % b[:3] + ("" if b[3] else " (depth not seen)")
            for i, name in enumerate(("width", "depth (where seen)", "height")):
                if i != 1 or b[3]:
                    errors[name].append(abs(b[i] / t[i] - 1))
            unseen += not b[3]
            if b[3]:
                line += " (depth \u00b1 %.2f)" % b[4]
                covered.append(abs(b[1] - t[1]) <= 2 * b[4])
        else:
            line += "; box refused: " + b
        if isinstance(f, tuple):
            line += "; flat %.2f high" % f[2]
            errors["flat height"].append(abs(f[2] / t[2] - 1))
        print(line)
    summary = {"seeds": args.seeds, "cabinets": len(rows), "depth_not_seen": unseen, "seconds": round(time.time() - t0, 1)}
    for name, e in errors.items():
        if e:
            summary[name] = {"median_relative_error": round(statistics.median(e), 4),
                             "within_10_percent": sum(x <= 0.1 for x in e), "of": len(e)}
            print("%s: median relative error %.1f%%, within 10%% in %d of %d" % (
                name, 100 * statistics.median(e), summary[name]["within_10_percent"], len(e)))
    if covered:
        summary["depth_within_2_sigma"] = sum(covered)
        print("depth (where seen) within twice its \u00b1 in %d of %d" % (sum(covered), len(covered)))
    print("%d cabinets (%d with their depth not seen) in %.0f s" % (len(rows), unseen, summary["seconds"]))
    if args.json:
        json.dump({"summary": summary, "cabinets": rows}, open(args.json, "w"), indent=1)


if __name__ == "__main__":
    main()
