#!/usr/bin/env python3
"""Ground-truth corridors photographed through a distorting lens.

usage: make_distorted.py MAKE_CORRIDORS DISTORT_TOOL TRUTH_DIR OUT_DIR NAMES K1S
  NAMES: corridor_a,corridor_f,...   K1S: -0.1,-0.2
For each scene, renders a wider view (make_corridors.py view: the same camera, more
image around it, at twice the resolution so that each photo pixel averages four
samples) once for the strongest k1, then warps it with
distort_corridor into OUT_DIR/NAME_kNNN.png and .json (NNN: 100 |k1|, e.g. k010 for
-0.1): the photo as the lens shows it and its truth (corners through the lens, the
distortion). A scene whose outputs are newer than its truth is not made again.
"""
import json, os, subprocess, sys

SCALE = 2  # the wide render's resolution, in photo pixels per axis


def stem(out_dir, name, k1):
    return os.path.join(out_dir, "%s_k%03d" % (name, round(abs(k1) * 100)))


def main():
    if len(sys.argv) != 7:
        print(__doc__)
        return 2
    make_corridors, tool, truth_dir, out_dir, names, k1s = sys.argv[1:]
    k1s = [float(k) for k in k1s.split(",")]
    os.makedirs(out_dir, exist_ok=True)
    for name in names.split(","):
        truth_path = os.path.join(truth_dir, name + ".json")
        truth = json.load(open(truth_path))
        outputs = [stem(out_dir, name, k) + ext for k in k1s for ext in (".png", ".json")]
        if all(os.path.exists(o) and os.path.getmtime(o) >= os.path.getmtime(truth_path) for o in outputs):
            continue
        strongest = min(k1s)
        plan = subprocess.run([tool, "plan", truth_path, str(strongest)], check=True, capture_output=True, text=True)
        w, h, ox, oy = plan.stdout.split()
        wide = os.path.join(out_dir, name + "_wide.png")
        eye = [str(c) for c in truth["camera_position_m"]]
        ypr = [str(truth[k]) for k in ("yaw_deg", "pitch_deg", "roll_deg")]
        subprocess.run([sys.executable, make_corridors, "view", name, wide, "--eye", *eye, "--ypr", *ypr,
                        "--size", "%dx%d" % (SCALE * int(w), SCALE * int(h)),
                        "--focal-px", repr(SCALE * truth["focal_px"])], check=True)
        for k in k1s:
            subprocess.run([tool, "warp", truth_path, str(k), wide, ox, oy, stem(out_dir, name, k)], check=True)
        print("made %s through k1 %s" % (name, ", ".join(str(k) for k in k1s)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
