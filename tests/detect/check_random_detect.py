#!/usr/bin/env python3
"""detect on a few random corridor scenes of the TUNE range (issue 22), per scene (CTest).

usage: check_random_detect.py render OUTDIR
       check_random_detect.py detect PHOTOWALK OUTDIR
       check_random_detect.py hint PHOTOWALK OUTDIR

render: renders the seeds below into OUTDIR (random_corridors.py, full size; a scene is
rendered again only when its .pov changes; CTest runs it once, as the fixture of the other
two). detect: runs
  PHOTOWALK detect PHOTO --focal-px F --principal-point U,V -o OUT.json
on each photo (the PNG as rendered), and checks each against the figures measured on it:
the exit code (0 sure, 3 unsure, 2 no corridor) and, for a written answer, the far-wall
corners' error (the median of P1..P4's distances to the answers), within twice the
measured error or the measured error plus 0.05 px, whichever is larger; an exit-0
answer must be right (within 2 px), and P5..P8 must be at the image edge (near_depth).
Then again without --focal-px: where the focal length comes from (focal_source) and,
from the vanishing points, its error within twice the measured or the measured plus 0.5
percentage points. hint: `detect --hint` on a rough box of each scene (every true corner
moved 15 px), the far-wall error held as detect's is.
The seeds are TUNE seeds (0-599): the held-out range 100000-100299 is for the report
(bench/detect_heldout.py) only.
"""
import json, math, os, random, statistics, subprocess, sys, tempfile, time
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "groundtruth"))
import random_corridors as rc  # noqa: E402

RIGHT_PX = 2.0
# seed: (exit code, far-wall median error px or None when no corridor), measured 2026-12-03
# (commit ef640f3 on branch detect-generalize). Sure and right: 1, 40, 86, 94 (1 and 86
# portrait, 86 a glazed end with a far corner hidden); right but unsure: 4 (portrait), 44
# (glazed, two far corners hidden), 99 and 104 (receding lines scattered, rms 4.7 and
# 6.0 degrees: "no corridor" before); wrong and unsure: 31, 84; no corridor: 125.
# Since the end's corners are where the boundaries meet the far wall's sides: 44 0.214 ->
# 0.798; added 6 (a skirting along the far wall's foot, 1.73 px before), 15 and 70 (open
# ends, the floor running on into a hall: 4.35 and 1.14 px before).
# Since the room's box fit alone is never sure (2026-12-04): 1 and 94 right but unsure.
# Since a guess's far-wall foot is searched where the floor's boundaries divide surfaces
# (2026-12-04): 84 38.373 -> 46.600; added 33 (a glossy floor, people: 15.03 px before)
# and 68 (an open end, a checkered floor: 12.26 px before). Since a guess's foot found
# on a skirting board's top is moved to the board's foot: added 144 (4.39 px before).
# Since a far wall scored 0.8-1.2 is taken as a guess (2026-12-04): 125 "no corridor" ->
# a wrong guess; added 110 ("no corridor" before) and 143 (96.13 px before). Since a far
# wall that reaches down into its reflection in a glossy floor is completed again with
# its foot half way down: added 122 (203.5 px before, the reflection's foot). Since a far
# wall is at least 12 working px across: added 72 (31.76 px before: a few pixels' section
# at the vanishing point won the far wall search). Since the four boundaries are taken
# together where the strongest steps do not make a box: 84 46.600 -> 0.183; added 103
# (13.47 px before). Since a far wall may have one side hidden (2026-12-04): added 205
# ("no corridor" before: the far wall's foot, where the floor runs on, shows no edge) and
# 295 (9.61 px before: a section nearer the camera had four sides). Since a sure answer
# whose places agree on a skirting board moves onto the board's foot (2026-12-05): added
# 508 (3.87 px and exit 3 before: the foot on the board's top; a TUNE 300-599 seed).
# Since a sure answer needs the room's box fit to find the same far wall: 70 exit 0 -> 3
# (the box fit's far wall 4 px off). Since a far wall with a side hidden competes where it
# scores 0.2 more than the best four-sided section: added 402 (an open end, 43.2 px before:
# the hall's wall beyond). Since a fit whose surfaces are alike is refused where the two
# fits disagree (2026-12-05): added 85 (66.2 px before: the box fit's cabinet front).
# Since one boundary that does not show is taken where the other three put it: added 135
# (253 px before). Since two fits agreeing make an answer sure whose one doubt is a single
# boundary running on inside the far wall's corners: 4 and 44 exit 3 -> 0. Since the
# receding lines' spread is measured away from the vanishing point (2026-12-05): 99 exit
# 3 -> 0 (its one doubt was the lines "meeting loosely"); added 495 ("no corridor" before:
# the lines "scattered", rms 9.6 degrees, over short edges near the point). All measured
# again then: 1 0.717 -> 0.68, 15 0.824 -> 1.36, 31 49.53 -> 2.26, 104 0.070 -> 0.10 and
# 125 83.53 -> 84.59 had moved (by stop 37 at the latest) within the 2x this check allows,
# the list keeping the older figures; it holds today's. Since one of the room's box fit's
# next best boxes is taken where the angular profile found no far wall: added 23 (28.4 px
# before: the best a nearer rectangle whose surfaces are alike) and 50 (2.9 px before).
# Since a floor boundary's step in the foot search is held to its inner half's: added 278
# (an open end; 5.60 px before, the foot 11 px high, its right floor boundary along a
# side opening's foot near the photo's border). Since a floor boundary found on a band's
# top along the walls is taken at the band's foot: added 420 (an open end; 2.41 px before,
# the feet on the side walls' skirting boards' tops). Since a hidden foot's floor boundaries
# are taken at a board's foot too: added 500 (a person before the far wall's foot; 2.34 px
# before, the foot on the boards' tops). Since a far wall is no more than 6 times as wide
# as high, nor as high as wide (2026-12-06): 125 a wrong guess 84.6 px off -> "no
# corridor" (its far wall 6.4 times as wide as high); added 166 (124 px before: a far wall
# 27 times as wide as high, a shelf's edge across the corridor, won). Since a nearly as
# strong set of the angular profile's steps that makes a box is taken where its far wall
# scores clearly better, where the strongest set finds none or one with a side hidden
# (2026-12-06): added 337 (a person before the far wall's left
# corners; 10.7 px before, the left side on the person's outline) and 287 (a glazed end,
# its foot's corners hidden; "no corridor" before). Since such sets need only 0.6 of the
# strongest set's strength, not 0.8 (stop 50): added 198 (39.3 px before: its far wall's
# foot hidden, the strongest set's far wall a wrong one). Since a quadrant's steps with an
# edge along less than half their ray are weighed by that share (stop 51): added 361 (77.5
# px before: its floor-right boundary on a step with edges along 33% of its ray, the true
# one 99%), 380 (11.1 px before: its ceiling-right boundary the same, 27% against 70%) and
# 561 (9.6 px before: its floor-left boundary on a step with edges along 25% of its ray).
# Since an unsure answer whose far wall the layout network puts within 2 px is sure (stop
# 53): 1, 23, 31, 84, 110, 143, 198, 402 and 561 exit 3 -> 0; and since the network's box
# fitted to the edges is a guess where the edges found none: 125 "no corridor" -> a guess
# 9.37 px off. 31 is a wrong sure answer (2.26 px: the edges and the network both 2 px
# off); every seed here but 495, 500, 508 and 561 is one the network was trained on
# (0-449), where it agrees with the truth more often than on other scenes. Since the
# network's box as it put it is a guess where the edges found the four boundaries but no
# far wall (stop 54): added 519 ("no corridor" before: its far wall's foot hidden; a TUNE
# 450-599 seed, one the network was not trained on). Since it is a guess too wherever
# the whole photo looks like a room to the network (stop 55): added 516 ("no corridor"
# before: too few receding lines around the vanishing point; a TUNE 450-599 seed). Since an
# unsure answer whose far wall the network finds far less likely than its own box gives
# way to that box (stop 56): added 531 (76.4 px before: a far wall 28 px across taken
# nearer; now the network's box fitted to the edges) and 518 (60.7 px before; now the
# network's box as it put it, the edges not bearing it out); TUNE 450-599 seeds. Since a
# sure answer made a guess by a skirting board below its foot moves onto the board's foot
# where the places looked at agree (stop 57): added 666 (a seed of 600-1399, tuning data;
# 4.66 px before: the foot on the board's top, 9 px above its foot). Since a board the
# wall's colour counts as one (stop 57): added 1313 (4.2 px before, the foot on the line
# along the board's top). Since a guess's top is taken at the upper edge of a band under
# the ceiling (stop 57): added 1096 (3.2 px before, its top on the band's lower edge).
# Since the network's far wall as put has its sides moved onto the edges within 6 px
# (stop 59): added 1032 (a seed of 600-1399: 4.38 px before, the network's box as put);
# 518 1.97 -> 3.17 (its foot moved up onto a skirting board's top: a loss on TUNE, kept).
# Since a board's foot is the first step below its top (stop 60): added 640 (a seed of
# 600-1399: 2.4 px and exit 3 before, the foot on the board's top). Since the network's
# box fitted to the edges replaces an answer of the edges it finds less likely by 0.12
# (stop 60): added 759 (27.6 px before: a nearer section). Since a sure answer the
# layout network finds likelier with its foot half way down is taken as a reflection
# (stop 62): added 589 (a TUNE 450-599 seed: 52.8 px and exit 0 before, a far wall and
# its reflection in a mirror-like floor) and 1394 (a seed of 600-1399: 99.6 px, exit 0).
EXPECTED = {
    1: (0, 0.680), 4: (0, 0.157), 6: (0, 0.251), 15: (3, 1.360), 31: (0, 2.260), 33: (3, 0.545), 40: (0, 0.100),
    44: (0, 0.798), 68: (3, 0.136), 70: (3, 0.185), 72: (3, 0.249), 84: (0, 0.183), 86: (0, 0.235), 94: (3, 0.164), 99: (0, 0.219),
    103: (3, 0.203), 104: (3, 0.100), 110: (0, 0.701), 122: (3, 0.757), 125: (3, 9.370), 143: (0, 0.313), 144: (3, 1.089),
    205: (3, 0.369), 295: (3, 0.316), 402: (0, 0.716), 508: (0, 0.346), 85: (3, 0.446), 135: (3, 0.157), 495: (3, 1.300),
    23: (0, 0.226), 50: (3, 0.543), 278: (3, 0.864), 420: (3, 1.163), 500: (3, 0.224), 166: (3, 0.631),
    337: (3, 0.580), 287: (3, 0.420), 198: (0, 0.126), 361: (3, 0.982), 380: (3, 0.779),
    561: (0, 0.214), 519: (3, 5.650), 516: (3, 4.120), 531: (3, 0.307), 518: (3, 3.174),
    666: (3, 0.504), 1313: (3, 0.208), 1096: (3, 0.489), 1032: (3, 0.529), 640: (0, 0.207), 759: (3, 0.312),
    589: (3, 0.078), 1394: (3, 0.468),
}
# Sure answers measured wrong (the target is 98% of sure answers right, not all): held to
# their measured error like any other, and no other sure answer may be wrong.
WRONG_SURE = {31}
# seed: (focal_source, error %) with the focal length withheld, measured 2026-12-04 (the
# finite points refitted in the image, coarse to fine; the error before in brackets).
# 40 is turned by under 2 degrees both ways: its second point is far and its estimate
# poor (-36%, as before).
FOCAL_EXPECTED = {
    1: ("vanishing_points", 0.70),  # (-3.05)
    4: ("default", None), 6: ("vanishing_points", 0.53), 15: ("default", None), 31: ("default", None),
    33: ("default", None), 68: ("vanishing_points", -0.23), 72: ("vanishing_points", 15.99),
    40: ("vanishing_points", -36.24), 44: ("default", None), 70: ("default", None),
    84: ("vanishing_points", 1.18), 86: ("vanishing_points", 1.52), 94: ("vanishing_points", 0.69), 99: ("default", None),
    103: ("default", None), 104: ("vanishing_points", -0.70), 125: ("vanishing_points", 1.83),  # (+0.14, -0.35)
    110: ("default", None), 122: ("default", None), 143: ("default", None), 144: ("default", None),
    205: ("vanishing_points", -7.10), 295: ("default", None), 402: ("vanishing_points", 2.60),
    508: ("default", None), 85: ("vanishing_points", -2.03), 135: ("vanishing_points", 0.84),
    495: ("vanishing_points", 34.11), 23: ("default", None), 50: ("vanishing_points", -56.61),
    278: ("default", None), 420: ("vanishing_points", 2.40),
    500: ("vanishing_points", -0.57), 166: ("default", None), 337: ("vanishing_points", -2.37),
    287: ("vanishing_points", -1.84), 198: ("default", None), 361: ("default", None),
    380: ("vanishing_points", -11.22), 561: ("vanishing_points", -0.15), 519: ("default", None), 516: ("default", None),
    531: ("default", None), 518: ("default", None), 666: ("default", None),
    1313: ("vanishing_points", -0.30), 1096: ("default", None), 1032: ("default", None), 640: ("default", None),
    759: ("default", None), 589: ("default", None), 1394: ("vanishing_points", -0.28),
}

# detect --hint (issue 22 part 5) on the same scenes: a person's rough box, each scene's
# true corners every one moved 15 px in a direction drawn from the seed (as
# bench/hint_heldout.py draws its first), fitted back. seed: the far-wall corners' error
# (median of P1..P4) measured 2026-12-07, where detection's own answer within reach of
# the box is weighed against the fit (detect.cpp: fitRoughBox). Right (within 2 px) 39 of
# 48, against 30 of 48 by the fit alone; changed by more than 0.1 px (the fit alone's
# first): 31 3.61 -> 2.26, 50 15.00 -> 0.54 (the fit gave the box back as put), 68 5.09 ->
# 0.13, 84 3.36 -> 0.18, 85 1.57 -> 0.45, 110 8.20 -> 0.70, 122 2.69 -> 0.76, 205 0.95 ->
# 0.37, 402 15.00 -> 0.72, 508 1.97 -> 0.35, 516 no corridor -> 4.09, 519 15.00 -> 5.65,
# 561 15.00 -> 0.21, 666 6.32 -> 0.50, 1096 3.12 -> 0.49. 144, 278, 380, 518 and 1313 keep
# the fit's far wall, 2-26 px off, fitted side by side where a boundary did not show.
HINT_EXPECTED = {
    1: 0.714, 4: 0.148, 6: 0.265, 15: 1.231, 23: 0.239, 31: 2.261, 33: 0.539, 40: 0.173, 44: 0.864, 50: 0.543,
    68: 0.128, 70: 0.182, 72: 0.257, 84: 0.183, 85: 0.446, 86: 0.235, 94: 0.193, 99: 0.219, 103: 0.174, 104: 0.331,
    110: 0.701, 122: 0.757, 125: 0.979, 135: 0.205, 143: 0.257, 144: 15.926, 166: 0.613, 198: 0.125, 205: 0.369,
    278: 25.837, 287: 0.393, 295: 0.316, 337: 0.583, 361: 12.431, 380: 4.947, 402: 0.716, 420: 1.162, 495: 0.230,
    500: 0.224, 508: 0.346, 516: 4.088, 518: 22.503, 519: 5.650, 531: 0.307, 561: 0.214, 666: 0.504, 1096: 0.489,
    1313: 4.159,
}
HINT_SLIP_PX = 15.0


def render(seed, outdir):
    base = os.path.join(outdir, "seed_%05d" % seed)
    pov = rc.scene_pov(rc.make_scene(seed))
    if all(os.path.exists(base + e) for e in (".pov", ".json", ".png")):
        with open(base + ".pov") as f:
            if f.read() == pov:
                return 0.0
    return rc.make_one(seed, outdir, 1.0, True, False, 1)


def detect(photowalk, seed, outdir, focal_given=True):
    base = os.path.join(outdir, "seed_%05d" % seed)
    with open(base + ".json") as f:
        ans = json.load(f)
    out = os.path.join(outdir, "seed_%05d_detected%s.json" % (seed, "" if focal_given else "_nofocal"))
    if os.path.exists(out):
        os.unlink(out)
    u, v = ans["principal_point"]
    focal = ["--focal-px", "%.6f" % ans["focal_px"]] if focal_given else []
    r = subprocess.run([photowalk, "detect", base + ".png"] + focal + ["--principal-point", "%.6f,%.6f" % (u, v), "-o", out],
                       capture_output=True, text=True)
    if not focal_given:
        if not os.path.exists(out):
            return None, None
        with open(out) as f:
            shot = json.load(f)
        return shot["focal_source"], 100.0 * (shot["focal_px"] / ans["focal_px"] - 1.0)
    far = near_depth = None
    if r.returncode in (0, 3):
        with open(out) as f:
            shot = json.load(f)
        c, t = shot["corners_px"], ans["corners_px"]
        far = statistics.median(math.hypot(c[k][0] - t[k][0], c[k][1] - t[k][1]) for k in ("P1", "P2", "P3", "P4"))
        near_depth = shot["detection"]["near_depth"]
    return r.returncode, far, near_depth, (r.stderr or r.stdout).strip().splitlines()[-1:]


def fit_rough(photowalk, seed, outdir):
    """detect --hint on the scene's rough box: the far-wall corners' median error, or None."""
    base = os.path.join(outdir, "seed_%05d" % seed)
    with open(base + ".json") as f:
        ans = json.load(f)
    rng = random.Random("%d-0" % seed)
    rough = {}
    for k in ("P1", "P2", "P3", "P4", "P5", "P6", "P7", "P8"):
        a = rng.uniform(0, 2 * math.pi)
        rough[k] = [ans["corners_px"][k][0] + HINT_SLIP_PX * math.cos(a), ans["corners_px"][k][1] + HINT_SLIP_PX * math.sin(a)]
    shot, out = base + "_rough.json", base + "_rough_fitted.json"
    with open(shot, "w") as f:
        json.dump({"image": base + ".png", "focal_px": ans["focal_px"], "principal_point": ans["principal_point"],
                   "camera_height_m": ans["camera_height_m"], "corners_px": rough}, f)
    if os.path.exists(out):
        os.unlink(out)
    r = subprocess.run([photowalk, "detect", "--hint", shot, "-o", out], capture_output=True, text=True)
    if r.returncode not in (0, 3) or not os.path.exists(out):
        return None
    with open(out) as f:
        c = json.load(f)["corners_px"]
    t = ans["corners_px"]
    return statistics.median(math.hypot(c[k][0] - t[k][0], c[k][1] - t[k][1]) for k in ("P1", "P2", "P3", "P4"))


def check_detect(photowalk, outdir, seeds):
    failures = []
    with ThreadPoolExecutor(2) as pool:
        got = dict(zip(seeds, pool.map(lambda s: detect(photowalk, s, outdir), seeds)))
        focal = dict(zip(seeds, pool.map(lambda s: detect(photowalk, s, outdir, focal_given=False), seeds)))
    print("%-6s %-9s %-9s %-12s %s" % ("seed", "exit", "far px", "near_depth", "expected"))
    for s in seeds:
        code, far, near_depth, last = got[s]
        want_code, want_far = EXPECTED[s]
        print("%-6d %-9d %-9s %-12s %d %s  %s" % (s, code, "-" if far is None else "%.2f" % far, near_depth or "-", want_code,
                                                   "-" if want_far is None else "%.2f" % want_far, last[0] if last and code else ""))
        if code != want_code:
            failures.append("seed %d: exit %d, measured %d" % (s, code, want_code))
        if want_far is not None and far is not None and far > max(2 * want_far, want_far + 0.05):
            failures.append("seed %d: far-wall corners %.2f px off, measured %.2f" % (s, far, want_far))
        if code == 0 and s not in WRONG_SURE and not (far is not None and far <= RIGHT_PX):
            failures.append("seed %d: exit 0 but %s px off" % (s, far))
        if code in (0, 3) and near_depth != "image_edge":
            failures.append("seed %d: P5..P8 at %s, not the image edge" % (s, near_depth))
    print("\nfocal length withheld\n%-6s %-17s %-9s %s" % ("seed", "focal_source", "error %", "expected"))
    for s in seeds:
        source, err = focal[s]
        want_source, want_err = FOCAL_EXPECTED[s]
        print("%-6d %-17s %-9s %s %s" % (s, source, "-" if err is None else "%+.2f" % err, want_source,
                                         "" if want_err is None else "%+.2f" % want_err))
        if source != want_source:
            failures.append("seed %d: focal length from %s, measured from %s" % (s, source, want_source))
        elif want_err is not None and abs(err) > max(2 * abs(want_err), abs(want_err) + 0.5):
            failures.append("seed %d: focal length %+.2f%% off, measured %+.2f%%" % (s, err, want_err))
    return failures


def check_hint(photowalk, outdir, seeds):
    failures = []
    with ThreadPoolExecutor(2) as pool:
        hinted = dict(zip(seeds, pool.map(lambda s: fit_rough(photowalk, s, outdir), seeds)))
    print("rough boxes (every corner %g px off) fitted back by detect --hint\n%-6s %-9s %s" % (HINT_SLIP_PX, "seed", "far px",
                                                                                          "measured"))
    for s in seeds:
        far, want = hinted[s], HINT_EXPECTED[s]
        print("%-6d %-9s %.2f" % (s, "-" if far is None else "%.2f" % far, want))
        if far is None or far > max(2 * want, want + 0.05):
            failures.append("seed %d: the rough box fitted back %s px off, measured %.2f" % (s, far, want))
    return failures


def main():
    usage = "usage: check_random_detect.py render OUTDIR | {detect,hint} PHOTOWALK OUTDIR"
    if len(sys.argv) < 3 or sys.argv[1] not in ("render", "detect", "hint") or len(sys.argv) != (3 if sys.argv[1] == "render" else 4):
        sys.exit(usage)
    part, outdir = sys.argv[1], sys.argv[-1]
    t0 = time.time()
    if part == "render":
        os.makedirs(outdir, exist_ok=True)
        with ThreadPoolExecutor(2) as pool:
            list(pool.map(lambda s: render(s, outdir), sorted(set(EXPECTED) | set(HINT_EXPECTED))))
        print("rendered in %.0f s" % (time.time() - t0))
        return 0
    seeds = sorted(EXPECTED if part == "detect" else HINT_EXPECTED)
    missing = [s for s in seeds if not os.path.exists(os.path.join(outdir, "seed_%05d.png" % s))]
    if missing:
        sys.exit("error: %d scenes not rendered in %s (seed %d first): run check_random_detect.py render %s"
                 % (len(missing), outdir, missing[0], outdir))
    failures = (check_detect if part == "detect" else check_hint)(sys.argv[2], outdir, seeds)
    print("%s in %.0f s" % (part, time.time() - t0))
    for f in failures:
        print("FAIL " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
