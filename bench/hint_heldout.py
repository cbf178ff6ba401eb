#!/usr/bin/env python3
"""`detect --hint` on random corridor scenes it was never tuned on (issue 22 part 5): on
demand, not in CI.

usage: bench/hint_heldout.py PHOTOWALK --seeds A-B[,C-D...] [--trials N] [--cache DIR]
                             [-j N] [--json OUT] [--timeout S]

A person's rough box: each scene's true corners (P1..P8), every one moved 15 px in a
random direction (seeded by the scene and the trial), written as a shot and fitted back by
  PHOTOWALK detect --hint ROUGH.json -o FIT.json
on the scene's PNG and on its noisy JPEG (sensor noise sigma 3, JPEG quality 70). Scenes
whose answers say the box is not in view are left out. Prints, for each of the two, how
many fits come back right: the far wall's corners (P1..P4) within 2 px by the median of
the four (as bench/detect_heldout.py scores detection) and by the worst of the four (as
bench/york_hint.py scores the real photos); the exit codes, and how many exit-0 fits are
right; the median time of one `detect --hint`. Renders the seeds the cache lacks (as
bench/detect_heldout.py does). The ranges are detect_heldout.py's: tune on TUNE, report
on HELD_OUT (100000-100299).
"""
import argparse, json, math, os, random, shutil, statistics, subprocess, sys, tempfile, time
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import detect_heldout as dh  # noqa: E402

CORNERS = ("P1", "P2", "P3", "P4", "P5", "P6", "P7", "P8")
SLIP_PX = 15.0


def rough_box(truth, seed, trial):
    rng = random.Random("%d-%d" % (seed, trial))
    rough = {}
    for k in CORNERS:
        t = rng.uniform(0, 2 * math.pi)
        rough[k] = [truth[k][0] + SLIP_PX * math.cos(t), truth[k][1] + SLIP_PX * math.sin(t)]
    return rough


def fit(photowalk, photo, ans, rough, timeout):
    """One `detect --hint`: (exit code, seconds, fitted corners or None)."""
    with tempfile.TemporaryDirectory() as d:
        shot, out = os.path.join(d, "rough.json"), os.path.join(d, "fit.json")
        with open(shot, "w") as f:
            json.dump({"image": photo, "focal_px": ans["focal_px"], "principal_point": ans["principal_point"],
                       "camera_height_m": ans["camera_height_m"], "corners_px": rough}, f)
        t0 = time.time()
        try:
            code = subprocess.run([photowalk, "detect", "--hint", shot, "-o", out], capture_output=True, text=True,
                                  timeout=timeout).returncode
        except subprocess.TimeoutExpired:
            code = 124
        took = time.time() - t0
        corners = None
        if code in (0, 3) and os.path.exists(out):
            with open(out) as f:
                corners = json.load(f).get("corners_px")
    return code, took, corners


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("photowalk")
    ap.add_argument("--seeds", required=True, help="A-B[,C-D...], e.g. %d-%d (HELD_OUT)" % dh.HELD_OUT)
    ap.add_argument("--trials", type=int, default=2, help="rough boxes per scene and photo")
    ap.add_argument("--cache", default=os.path.join(dh.ROOT, "build", "random-scenes"))
    ap.add_argument("-j", "--jobs", type=int, default=2)
    ap.add_argument("--json")
    ap.add_argument("--timeout", type=float, default=120.0, help="seconds for one detect --hint")
    args = ap.parse_args()
    photowalk = shutil.which(args.photowalk) or args.photowalk
    seeds = dh.parse_seeds(args.seeds)
    os.makedirs(args.cache, exist_ok=True)
    todo = [s for s in seeds if not dh.cached(s, args.cache)]
    with ThreadPoolExecutor(args.jobs) as pool:
        list(pool.map(lambda sd: dh.rc.make_one(sd, args.cache, 1.0, True, False, 1 if args.jobs > 1 else 2), todo))
    if todo:
        print("rendered %d scenes" % len(todo), flush=True)

    jobs = []
    for seed in seeds:
        with open(os.path.join(args.cache, "seed_%05d.json" % seed)) as f:
            ans = json.load(f)
        if ans["box_visible"]:
            jobs += [(seed, ans, key, trial) for key in ("clean", "noisy") for trial in range(args.trials)]

    def one(job):
        seed, ans, key, trial = job
        base = os.path.join(args.cache, "seed_%05d" % seed)
        photo = base + (".png" if key == "clean" else "_q70n3.jpg")
        code, took, found = fit(photowalk, photo, ans, rough_box(ans["corners_px"], seed, trial), args.timeout)
        errs = dh.corner_errors(found, ans["corners_px"])
        far = [errs[c] for c in dh.FAR] if errs else None
        return {"seed": seed, "photo": key, "trial": trial, "exit": code, "seconds": round(took, 3),
                "far_median_px": None if not far else round(statistics.median(far), 3),
                "far_worst_px": None if not far else round(max(far), 3)}

    t0 = time.time()
    with ThreadPoolExecutor(args.jobs) as pool:
        rows = list(pool.map(one, jobs))
    wall = time.time() - t0

    def within(x):
        return x is not None and x <= dh.RIGHT_PX

    summary = {"date": time.strftime("%Y-%m-%d"), "photowalk": photowalk, "seeds": args.seeds,
               "trials": args.trials, "slip_px": SLIP_PX, "wall_s": round(wall, 1), "jobs": args.jobs}
    print("hint_heldout: %d scenes with the box in view, %d rough boxes each per photo, every corner %g px off"
          % (len({r["seed"] for r in rows}), args.trials, SLIP_PX))
    for key, label in (("clean", "as rendered (PNG)"), ("noisy", "noise sigma 3 + JPEG q70")):
        res = [r for r in rows if r["photo"] == key]
        n = len(res)
        exit0 = [r for r in res if r["exit"] == 0]
        s = {"fits": n,
             "exit_counts": {str(c): sum(1 for r in res if r["exit"] == c) for c in sorted({r["exit"] for r in res})},
             "right_by_median": sum(within(r["far_median_px"]) for r in res),
             "right_by_worst": sum(within(r["far_worst_px"]) for r in res),
             "exit0": len(exit0), "exit0_right_by_median": sum(within(r["far_median_px"]) for r in exit0),
             "median_s": statistics.median(r["seconds"] for r in res) if res else None}
        summary[key] = s
        print("%s, %d fits: far wall within %g px by the median corner %d (%.1f%%), by the worst %d (%.1f%%); "
              "exits %s; exit 0 %d, %d of them right; %.2f s per fit (median, %d at a time)"
              % (label, n, dh.RIGHT_PX, s["right_by_median"], 100.0 * s["right_by_median"] / max(n, 1),
                 s["right_by_worst"], 100.0 * s["right_by_worst"] / max(n, 1),
                 ", ".join("%s: %d" % kv for kv in s["exit_counts"].items()), s["exit0"], s["exit0_right_by_median"],
                 s["median_s"] or 0, args.jobs))
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"summary": summary, "fits": rows}, f, indent=1)


if __name__ == "__main__":
    main()
