#!/usr/bin/env python3
"""The careful boxes of the York Urban corridor photos, from the database's hand-labelled
segments (issue 22 part 5): writes bench/data/york_careful_boxes.json, which
bench/york_hint.py scores `detect --hint` against.

usage: york_careful_boxes.py [--dataset DIR] [--out FILE]

Each box is built from the segments the York Urban authors labelled by hand
(gt/NAME.json "lines"), never from photowalk's own detection:
  - the far wall's corners P1..P4 where its labelled top, bottom and side edges meet
    (each edge the total-least-squares line through its segments), or, where the photo's
    far wall has no labelled edges (P1040826), the labelled receding boundaries (each the
    line through the corridor's vanishing point nearest its segments) cut by the cross-
    section through one labelled segment's far end;
  - P5..P8 the nearest cross-section whose four corners lie inside the photo (1% of its
    short side in from the border, as detect puts them), on the rays from the corridor's
    vanishing point through the far corners, its sides pointing at the other two points.
The camera's radial distortion is fitted to all 51 photos' labelled segments (one k1:
each vanishing point's segments made to meet in one point), the segments undistorted
with it before anything is fitted, and the corners distorted back: the York Urban camera
bows straight lines (k1 about -0.08, normalised by the focal length), which moves the
near corners by several pixels at the photo's border.
"""
import argparse, glob, json, os, sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_DATASET = os.path.join(HERE, "..", "..", "shared", "real-photos", "york-urban-train")

# Per photo, which labelled segments (indices into gt/NAME.json "lines") make the box.
# (P1040853, a corridor ending in a glass wall, is not among them: its labelled far-end
# segments are the glass panes' edges inside their frame, a few pixels inside the far
# wall's own edges, which are not labelled.)
SPEC = {
    # The far wall's four edges are labelled (its foot under the dark kick plate).
    "P1040811": {"far": {"top": [5], "bottom": [3, 4], "left": [6], "right": [7]}},
    # No far-wall edge labelled; the four boundaries are (the ceiling's edges 25 and 24,
    # the floor's 3 and 2), and the far section passes where the right wall's floor edge
    # (2) ends: the walls end there, before the door's recess.
    "P1040826": {"rays": {"P1": [25], "P2": [24], "P3": [3], "P4": [2]}, "far_through": ["P4", 2]},
}


def undistort(points, k1, f, c):
    x = (np.atleast_2d(np.asarray(points, float)) - c) / f
    r = np.linalg.norm(x, axis=1, keepdims=True)
    ru = r.copy()
    for _ in range(30):  # Newton on ru (1 + k1 ru^2) = r
        ru = ru - (ru * (1 + k1 * ru * ru) - r) / (1 + 3 * k1 * ru * ru)
    return np.where(r > 0, x * ru / np.maximum(r, 1e-12), x) * f + c


def distort(p, k1, f, c):
    x = (np.asarray(p, float) - c) / f
    return x * (1 + k1 * (x @ x)) * f + c


def homogeneous(p):
    return np.array([p[0], p[1], 1.0])


def meet(a, b):
    p = np.cross(a, b)
    return p[:2] / p[2]


def fit_line(points):
    centre = points.mean(0)
    normal = np.linalg.svd(points - centre)[2][1]
    return np.array([normal[0], normal[1], -normal @ centre])


def group_points(a, b, groups):
    """Each group's vanishing point (homogeneous): the null vector of its segments' lines."""
    out = {}
    for g in set(groups):
        s = np.where(groups == g)[0]
        lines = np.cross(np.c_[a[s], np.ones(len(s))], np.c_[b[s], np.ones(len(s))])
        lines /= np.linalg.norm(lines[:, :2], axis=1, keepdims=True)
        out[g] = np.linalg.svd(lines)[2][-1]
    return out


def bend(gt, k1, f, c):
    """Summed squared distance of the undistorted segments' ends from the line through
    their midpoint and their group's vanishing point."""
    lines = np.array(gt["lines"], float)
    groups = lines[:, 4].astype(int)
    a, b = undistort(lines[:, 0:2], k1, f, c), undistort(lines[:, 2:4], k1, f, c)
    total = 0.0
    for g, vp in group_points(a, b, groups).items():
        s = np.where(groups == g)[0]
        if len(s) < 3:
            continue
        mid = (a[s] + b[s]) / 2
        through = np.cross(np.c_[mid, np.ones(len(s))], np.tile(vp, (len(s), 1)))
        through /= np.linalg.norm(through[:, :2], axis=1, keepdims=True)
        total += np.sum(np.sum(through * np.c_[a[s], np.ones(len(s))], 1) ** 2)
    return total


def fit_k1(gts, f, c):
    lo, hi = -0.3, 0.2
    cost = lambda k: sum(bend(g, k, f, c) for g in gts)
    for _ in range(40):  # golden section
        m1, m2 = hi - 0.618 * (hi - lo), lo + 0.618 * (hi - lo)
        if cost(m1) < cost(m2):
            hi = m2
        else:
            lo = m1
    k1 = (lo + hi) / 2
    return k1, cost(0.0), cost(k1)


def careful_box(gt, spec, k1, f, c, size):
    lines = np.array(gt["lines"], float)
    groups = lines[:, 4].astype(int)
    a, b = undistort(lines[:, 0:2], k1, f, c), undistort(lines[:, 2:4], k1, f, c)
    vps = group_points(a, b, groups)
    for v in gt["vps_orthogonal"]:  # a point with no segments of its own: the database's
        if v["index"] not in vps:
            vps[v["index"]] = np.array(v["homogeneous_pixel"] or v["pixel"] + [1.0], float)
    role = {v["index"]: v["role"] for v in gt["vps"]}
    depth = vps[gt["depth_vp_index"]]
    vertical = next(vps[i] for i in vps if role[i] == "vertical")
    horizontal = next(vps[i] for i in vps if role[i] == "horizontal" and i != gt["depth_vp_index"])
    centre = depth[:2] / depth[2]
    segments = lambda idx: np.r_[a[idx], b[idx]]
    if "far" in spec:
        edge = {k: fit_line(segments(v)) for k, v in spec["far"].items()}
        far = {"P1": meet(edge["top"], edge["left"]), "P2": meet(edge["top"], edge["right"]),
               "P3": meet(edge["bottom"], edge["left"]), "P4": meet(edge["bottom"], edge["right"])}
        ray = {k: np.cross(homogeneous(p), depth) for k, p in far.items()}
    else:
        ray = {}
        for k, idx in spec["rays"].items():  # the line through the point nearest the segments
            pts = segments(idx) - centre
            normal = np.linalg.svd(pts.T @ pts)[2][1]  # least scatter across
            ray[k] = np.array([normal[0], normal[1], -normal @ centre])
        corner, segment = spec["far_through"]
        p = b[segment] - (ray[corner][:2] @ b[segment] + ray[corner][2]) * ray[corner][:2]
        far = {corner: p}
        far["P3"] = meet(np.cross(homogeneous(far["P4"]), horizontal), ray["P3"])
        far["P1"] = meet(np.cross(homogeneous(far["P3"]), vertical), ray["P1"])
        far["P2"] = meet(np.cross(homogeneous(far["P1"]), horizontal), ray["P2"])

    def section(s):  # P7 at s times P1's distance from the vanishing point
        p7 = centre + s * (far["P1"] - centre)
        p8 = meet(np.cross(homogeneous(p7), horizontal), ray["P2"])
        p5 = meet(np.cross(homogeneous(p7), vertical), ray["P3"])
        p6 = meet(np.cross(homogeneous(p5), horizontal), ray["P4"])
        return {"P5": p5, "P6": p6, "P7": p7, "P8": p8}

    w, h = size
    margin = 0.01 * min(w, h)
    inside = lambda s: all(margin <= q[0] <= w - 1 - margin and margin <= q[1] <= h - 1 - margin
                           for q in (distort(p, k1, f, c) for p in section(s).values()))
    lo, hi = 1.0, 50.0
    for _ in range(60):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if inside(mid) else (lo, mid)
    return {k: [round(float(q[0]), 2), round(float(q[1]), 2)]
            for k, q in sorted((k, distort(p, k1, f, c)) for k, p in {**far, **section(lo)}.items())}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--dataset", default=DEFAULT_DATASET)
    ap.add_argument("--out", default=os.path.join(HERE, "data", "york_careful_boxes.json"))
    a = ap.parse_args()
    if not os.path.isdir(a.dataset):
        sys.exit("error: %s: no York Urban dataset there (--dataset DIR)" % a.dataset)
    cam = json.load(open(os.path.join(a.dataset, "camera.json")))
    f, c = cam["focal_px"], np.array(cam["principal_point"], float)
    gts = [json.load(open(p)) for p in sorted(glob.glob(os.path.join(a.dataset, "gt", "*.json")))]
    k1, straight, bent = fit_k1(gts, f, c)
    print("k1 %.4f fitted to the labelled segments of %d photos (bend %.0f px^2 -> %.0f)" % (k1, len(gts), straight, bent))
    boxes = {}
    for name, spec in sorted(SPEC.items()):
        gt = json.load(open(os.path.join(a.dataset, "gt", name + ".json")))
        boxes[name] = careful_box(gt, spec, k1, f, c, (640, 480))
        print(name, json.dumps(boxes[name]))
    about = ("Careful boxes for York Urban training-half corridor photos (../shared/real-photos), built by "
             "bench/york_careful_boxes.py from the database's hand-labelled segments (which segments: its SPEC), "
             "with the camera's radial distortion k1 %.4f fitted to all 51 photos' labelled segments. P1..P4 where "
             "the far wall's labelled edges (or the labelled boundaries) meet; P5..P8 the nearest cross-section "
             "inside the photo. Coordinates only; the photos stay in ../shared. Used by bench/york_hint.py." % k1)
    tmp = a.out + ".tmp"
    with open(tmp, "w") as out:
        json.dump({"about": about, "k1": round(k1, 4), "boxes": boxes}, out, indent=1)
        out.write("\n")
    os.replace(tmp, a.out)
    print("wrote", a.out)


if __name__ == "__main__":
    main()
