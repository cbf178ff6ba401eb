#!/usr/bin/env python3
"""`photowalk measure` on the ground-truth corridors (tests/groundtruth), exact corners.

usage: corridor_accuracy.py GROUNDTRUTH_DIR PHOTOWALK --method general|seed

Prints one row per scene and fails when any value is off by more than its threshold:
width, height, length and the distance from the camera to the far wall within 0.01 %
each; the camera's position within 0.1 mm; yaw, pitch and roll within 0.001 deg. The
general method measures every scene; the seed method (the paper's one-point
perspective) only those whose camera looks straight down the corridor (a-e).
Measured 2026-11-29: every value within 1e-6 % / 1e-5 mm / 1e-6 deg of the truth.
"""
import glob, json, os, subprocess, sys

MAX_PCT, MAX_POSITION_M, MAX_DEG = 0.01, 1e-4, 1e-3


def main():
    gt_dir, photowalk = sys.argv[1], sys.argv[2]
    method = sys.argv[sys.argv.index("--method") + 1]
    # The scenes, not their novel views (NAME_view_KIND.json: cameras, no answers).
    scenes = sorted(p for p in glob.glob(os.path.join(gt_dir, "corridor_*.json")) if "_view_" not in p)
    if len(scenes) < 8:
        print("only %d ground-truth scenes in %s (the build renders 8)" % (len(scenes), gt_dir))
        return 1
    failures, measured = [], 0
    print("%-11s %9s %9s %9s %9s %9s %9s %9s %9s" % ("scene", "width %", "height %", "length %", "far %",
                                                      "pos mm", "yaw deg", "pitch", "roll"))
    for path in scenes:
        truth = json.load(open(path))
        name = truth["name"]
        if method == "seed" and (truth["yaw_deg"], truth["pitch_deg"], truth["roll_deg"]) != (0, 0, 0):
            print("%-11s (turned camera: the seed method assumes one-point perspective)" % name)
            continue
        r = subprocess.run([photowalk, "measure", path, "--method", method], capture_output=True, text=True)
        if r.returncode != 0:
            failures.append("%s: measure failed: %s" % (name, r.stderr.strip()))
            continue
        m = json.loads(r.stdout)
        cam = m["camera"]
        pct = lambda got, want: 100.0 * (got - want) / want
        # The far wall is at z = -length; the camera's distance to it along the corridor.
        far = pct(cam["position_m"][2] + m["length_m"], truth["far_wall_distance_m"])
        errors = {
            "width %": pct(m["width_m"], truth["width_m"]), "height %": pct(m["height_m"], truth["height_m"]),
            "length %": pct(m["length_m"], truth["length_m"]), "far %": far,
            "pos mm": 1000 * max(abs(a - b) for a, b in zip(cam["position_m"], truth["camera_position_m"])),
            "yaw deg": cam["yaw_deg"] - truth["yaw_deg"], "pitch": cam["pitch_deg"] - truth["pitch_deg"],
            "roll": cam["roll_deg"] - truth["roll_deg"],
        }
        print("%-11s " % name + " ".join("%+9.5f" % v for v in errors.values()))
        limits = {"width %": MAX_PCT, "height %": MAX_PCT, "length %": MAX_PCT, "far %": MAX_PCT,
                  "pos mm": MAX_POSITION_M * 1000, "yaw deg": MAX_DEG, "pitch": MAX_DEG, "roll": MAX_DEG}
        for key, value in errors.items():
            if not abs(value) <= limits[key]:  # also catches NaN
                failures.append("%s: %s off by %g (at most %g)" % (name, key, value, limits[key]))
        measured += 1
    for f in failures:
        print("FAIL " + f)
    if measured == 0:
        print("FAIL no scene measured")
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
