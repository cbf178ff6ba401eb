#!/usr/bin/env python3
"""`detect --hint` on real photos (issue 22 part 5): each careful box of
bench/data/york_careful_boxes.json (York Urban training half, ../shared/real-photos;
built from the database's hand-labelled segments by bench/york_careful_boxes.py) with
every corner moved 15 px in a random direction, fitted back; prints per trial the
worst far-wall corner's distance from the careful box and the worst near corner's
distance across the careful box's boundary through it (P5..P8 slide along their boundary
to the nearest depth inside the photo, a convention, not a fit), and
per photo and in all how many come back within 2 px.
usage: york_hint.py PHOTOWALK [--trials N] [--k1 K] [--dataset DIR] [--boxes FILE]

--k1 K: the rough shots carry the lens (distortion {k1: K, k2: 0}, as a calibrated camera's
would; the careful boxes' file has the k1 fitted to all 51 photos' labelled segments), and
`detect --hint` reads the photos through it instead of fitting a lens of its own."""
import argparse, json, math, os, random, statistics, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("photowalk")
    ap.add_argument("--trials", type=int, default=20)
    ap.add_argument("--k1", type=float, default=None)
    ap.add_argument("--dataset", default=os.path.join(HERE, "..", "..", "shared", "real-photos", "york-urban-train"))
    ap.add_argument("--boxes", default=os.path.join(HERE, "data", "york_careful_boxes.json"))
    a = ap.parse_args()
    if not os.path.isdir(a.dataset):
        sys.exit("error: %s: no York Urban dataset there (--dataset DIR)" % a.dataset)
    cam = json.load(open(os.path.join(a.dataset, "camera.json")))
    boxes = json.load(open(a.boxes))["boxes"]
    far_all, near_all, per_photo = [], [], {}
    with tempfile.TemporaryDirectory() as d:
        for name, careful in sorted(boxes.items()):
            rng = random.Random(name)
            for trial in range(a.trials):
                rough = {}
                for k, (u, v) in careful.items():
                    t = rng.uniform(0, 2 * math.pi)
                    rough[k] = [u + 15 * math.cos(t), v + 15 * math.sin(t)]
                shot = {"image": os.path.join(a.dataset, "images", name + ".jpg"), "focal_px": cam["focal_px"],
                        "principal_point": cam["principal_point"], "camera_height_m": 1.6, "corners_px": rough}
                if a.k1 is not None:
                    shot["distortion"] = {"k1": a.k1, "k2": 0}
                rp, fp = os.path.join(d, "rough.json"), os.path.join(d, "fit.json")
                json.dump(shot, open(rp, "w"))
                r = subprocess.run([a.photowalk, "detect", "--hint", rp, "-o", fp], capture_output=True, text=True)
                if r.returncode not in (0, 3):
                    print("%s trial %d: exit %d %s" % (name, trial, r.returncode, r.stderr.strip()))
                    continue
                fit = json.load(open(fp))["corners_px"]
                err = {k: math.dist(fit[k], careful[k]) for k in careful}
                far = max(err["P%d" % i] for i in range(1, 5))
                # P5..P8 at the nearest depth inside the photo slide along their boundary with
                # the far corner; across it (the careful boundary, far corner to near) they count.
                near = 0.0
                for f, n in (("P3", "P5"), ("P4", "P6"), ("P1", "P7"), ("P2", "P8")):
                    (ax, ay), (bx, by), (px, py) = careful[f], careful[n], fit[n]
                    near = max(near, abs((bx - ax) * (py - ay) - (by - ay) * (px - ax)) / math.hypot(bx - ax, by - ay))
                far_all.append(far); near_all.append(near)
                per_photo.setdefault(name, []).append((far, near))
                print("%s trial %2d exit %d  far worst %.2f px  near worst %.2f px across its boundary" % (name, trial, r.returncode, far, near))
    for name, fits in sorted(per_photo.items()):
        print("%s: far-wall corners within 2 px in %d of %d, near corners in %d" % (
            name, sum(f <= 2 for f, _ in fits), len(fits), sum(n <= 2 for _, n in fits)))
    print("%d fits: far-wall corners within 2 px in %d (median worst %.2f px); near corners within 2 px of their boundary in %d (median worst %.2f px)" % (
        len(far_all), sum(x <= 2 for x in far_all), statistics.median(far_all), sum(x <= 2 for x in near_all),
        statistics.median(near_all)))

if __name__ == "__main__":
    main()
