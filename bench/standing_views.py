#!/usr/bin/env python3
"""Novel views of random corridor scenes, with their objects painted flat and stood up (issues 22, 25).

usage: bench/standing_views.py NOVEL_VIEW_BENCH --seeds A-B[,C-D...] [--cache DIR] [-j N]
                               [--kinds person,plant,bin[,cabinet][,opening]] [--save DIR]

For each seed (tests/groundtruth/random_corridors.py; cache default build/random-scenes/):
renders what the cache lacks (the photo, its object-id mask, the novel views from inside
the corridor), writes seed_NNNNN_standing.json: the scene's shot (its exact corners) with a
cutout for each object of the kinds asked (default: the floor's free-standing ones, people,
plants and bins) that the photo shows over 150 px or more with its foot in view (not off
the photo's edge, nor behind another object): a rectangle 4 px beyond the
object's pixels in the mask, as a person draws one around it (GrabCut finds the object
inside); with the kind "opening", a cutout of shape "opening" for each side opening into a
room that the photo shows over 400 px, its outline the part of it inside the photo, as a
person clicks a doorway's corners; then runs NOVEL_VIEW_BENCH --random on them, which builds each scene with its
objects painted flat and, where it has cutouts, stood up, and scores the views against
POV-Ray's. A scene with no such object gets no standing file and counts in the flat
figures only.

The ranges are detect_heldout.py's: TUNE 0-299 (look at these while working), HELD_OUT
100000-100299 (report on these). A scene's mask costs about 1 s of povray, its three views
5-10 s.
"""
import argparse, os, subprocess, sys, time
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "groundtruth"))
import random_corridors as rc  # noqa: E402
from detect_heldout import parse_seeds  # noqa: E402  (the same seed ranges)

def prepare(seed, cache, kinds):
    """Renders what is missing for the seed and writes its standing shot (or removes a stale one)."""
    base = os.path.join(cache, "seed_%05d" % seed)
    pov = rc.scene_pov(rc.make_scene(seed))
    fresh = all(os.path.exists(base + e) for e in (".pov", ".json", ".png")) and open(base + ".pov").read() == pov
    if not fresh:
        rc.make_one(seed, cache, 1.0, True, True, 1)
    elif not os.path.exists(base + "_mask.ppm") or os.path.getmtime(base + "_mask.ppm") < os.path.getmtime(base + ".pov"):
        rc.make_one(seed, cache, 1.0, False, True, 1)
    rc.make_views(seed, cache, 1)
    return rc.write_standing(seed, cache, kinds)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("bench")
    ap.add_argument("--seeds", required=True)
    ap.add_argument("--cache", default=os.path.join(ROOT, "build", "random-scenes"))
    ap.add_argument("-j", "--jobs", type=int, default=2)
    ap.add_argument("--kinds", default=",".join(sorted(rc.STANDING_KINDS)))
    ap.add_argument("--save")
    args = ap.parse_args()
    seeds = parse_seeds(args.seeds)
    os.makedirs(args.cache, exist_ok=True)
    kinds = set(args.kinds.split(","))
    t0 = time.time()
    with ThreadPoolExecutor(args.jobs) as pool:
        counts = list(pool.map(lambda s: prepare(s, args.cache, kinds), seeds))
    print("standing_views: %d seeds, %d with objects stood up (%d objects); prepared in %.0f s"
          % (len(seeds), sum(1 for c in counts if c), sum(counts), time.time() - t0), flush=True)
    cmd = [args.bench, "--random", args.cache, "--seeds", args.seeds] + (["--save", args.save] if args.save else [])
    t0 = time.time()
    r = subprocess.run(cmd)
    print("standing_views: the bench took %.0f s" % (time.time() - t0))
    sys.exit(r.returncode)


if __name__ == "__main__":
    main()
