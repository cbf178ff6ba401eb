#!/usr/bin/env python3
"""End-to-end checks of `photowalk measure` and `photowalk rectify`.

usage: cli_test.py PHOTOWALK
Uses the sample shot in assets/ (a POV-Ray corridor: 4.0 x 3.5 x 19.0 m). Good runs
must print finite JSON and write complete files; every bad input must exit 1 with
exactly one line, starting "error:", on stderr, nothing on stdout, and no file left.
"""
import json, math, os, shutil, struct, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ASSETS = os.path.normpath(os.path.join(HERE, "..", "..", "assets"))
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAIL:", what)


def run(exe, *args):
    return subprocess.run([exe] + list(args), capture_output=True, text=True, timeout=120)


def finite_everywhere(value):
    if isinstance(value, float):
        return math.isfinite(value)
    if isinstance(value, dict):
        return all(finite_everywhere(v) for v in value.values())
    if isinstance(value, list):
        return all(finite_everywhere(v) for v in value)
    return value is not None


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n":
        return None
    return struct.unpack(">II", head[16:24])


def no_temp_files(folder):
    return not any(".tmp" in name for name in os.listdir(folder))


def main():
    exe = os.path.abspath(sys.argv[1])
    base = json.load(open(os.path.join(ASSETS, "corridor.json")))
    base["image"] = os.path.join(ASSETS, base["image"])
    tmp = tempfile.mkdtemp(prefix="pw_cli_test_")
    try:
        good = os.path.join(tmp, "good.json")
        json.dump(base, open(good, "w"))

        # measure: both methods, the figures, no NaN, the documented keys.
        for method in ("general", "seed"):
            r = run(exe, "measure", good, "--method", method)
            check(r.returncode == 0, "measure --method %s exits 0 (%s)" % (method, r.stderr.strip()))
            if r.returncode != 0:
                continue
            doc = json.loads(r.stdout)
            check(finite_everywhere(doc), "measure --method %s prints only finite numbers" % method)
            for key in ("width_m", "height_m", "length_m", "sigma_m", "vanishing_point_px", "camera",
                        "reprojection_rms_px", "corners_m"):
                check(key in doc, "measure prints %s" % key)
            for key in ("height_m", "focal_px", "yaw_deg", "pitch_deg", "roll_deg", "position_m", "world_from_camera"):
                check(key in doc.get("camera", {}), "measure prints camera.%s" % key)
            for key, truth in (("width_m", 4.0), ("height_m", 3.5), ("length_m", 19.0)):
                check(abs(doc[key] / truth - 1) < 0.003, "%s %s within 0.3%% (got %s)" % (method, key, doc[key]))
                check(0 < doc["sigma_m"][key] < 0.05 * truth, "%s sigma of %s is plausible" % (method, key))

        # The ± of every input (issue 23): the shares add up; a shot without a focal
        # length or camera height is refused, and measured with --assume-defaults, the ±
        # then mostly the assumed focal length's or camera height's.
        r = run(exe, "measure", good)
        doc = json.loads(r.stdout) if r.returncode == 0 else {}
        sources = doc.get("sigma_sources", [])
        check(sources and sources[0]["source"] == "corners", "measure prints sigma_sources, the corners first")
        for key in ("width_m", "height_m", "length_m"):
            total = sum(s["sigma_m"][key] ** 2 for s in sources) ** 0.5
            check(abs(total - doc["sigma_m"][key]) < 1e-9, "the sources of %s add up in quadrature" % key)
            check(abs(sum(s["share"][key] for s in sources) - 1) < 1e-9, "the shares of %s add up to 1" % key)
            check(" m \u00b1 " in doc.get("text", {}).get(key, ""), "text.%s says the dimension with its ±" % key)
        bare = dict(base)
        for key in ("focal_px", "focal_mm", "sensor_width_mm", "camera_height_m", "reference"):
            bare.pop(key, None)
        bare_path = os.path.join(tmp, "bare.json")
        json.dump(bare, open(bare_path, "w"))
        r = run(exe, "measure", bare_path)
        check(r.returncode == 1, "measure refuses a shot without focal length or camera height")
        r = run(exe, "measure", bare_path, "--assume-defaults")
        check(r.returncode == 0, "measure --assume-defaults measures it (%s)" % r.stderr.strip())
        if r.returncode == 0:
            doc = json.loads(r.stdout)
            check(len(doc.get("assumptions", [])) == 2, "it says both assumptions in the JSON")
            check(r.stderr.count("measure: assumed") == 2, "and on stderr")
            check(doc["camera"]["focal_source"].startswith("assumed"), "camera.focal_source says assumed")
            check(doc["sigma_mostly"]["length_m"] in ("focal_length", "camera_height"),
                  "the length's sigma is mostly the assumptions' (%s)" % doc["sigma_mostly"]["length_m"])
            check("(mostly: the assumed" in doc["text"]["length_m"], "text says so: %s" % doc["text"]["length_m"])
            for key, truth in (("width_m", 4.0), ("height_m", 3.5), ("length_m", 19.0)):
                check(doc["sigma_m"][key] > 0.05 * truth, "the assumed inputs widen the ± of %s" % key)

        # A camera height given in centimetres (160, not 1.6): measured, 100 times too
        # large, and said so on stderr and in the JSON's warnings; none for the right one.
        r = run(exe, "measure", good)
        check(r.returncode == 0 and "warnings" not in json.loads(r.stdout or "{}") and "warning:" not in r.stderr,
              "a plausible corridor gets no warning (%s)" % r.stderr.strip())
        centimetres = dict(base, camera_height_m=100 * base["camera_height_m"])
        cm_path = os.path.join(tmp, "centimetres.json")
        json.dump(centimetres, open(cm_path, "w"))
        r = run(exe, "measure", cm_path)
        check(r.returncode == 0, "measure measures a camera height in centimetres (%s)" % r.stderr.strip())
        if r.returncode == 0:
            doc = json.loads(r.stdout)
            check(abs(doc["width_m"] / 400.0 - 1) < 0.003, "100 times the width (%s)" % doc["width_m"])
            check(len(doc.get("warnings", [])) == 1 and "in metres (not centimetres" in doc["warnings"][0],
                  "the JSON's warnings say to check the units (%s)" % doc.get("warnings"))
            lines = [l for l in r.stderr.splitlines() if l.startswith("warning: ")]
            check(len(lines) == 1 and "no interior is that large" in lines[0], "stderr says so (%s)" % r.stderr.strip())

        # Objects (issue 25): the far wall's floor corners as floor points are the width
        # apart; its top corner, on the vertical above one of them, the height above it.
        c = base["corners_px"]
        r = run(exe, "measure", good, "--point", "p3=%r,%r" % tuple(c["P3"]), "--point", "p4=%r,%r@floor" % tuple(c["P4"]),
                "--point", "p1=%r,%r@above:p3" % tuple(c["P1"]), "--point", "mid=%r,%r@wall:far" % tuple(
                    0.5 * (a + b) for a, b in zip(c["P1"], c["P4"])),
                "--distance", "p3,p4", "--height", "p3,p1")
        check(r.returncode == 0, "measure --point/--distance/--height exits 0 (%s)" % r.stderr.strip())
        if r.returncode == 0:
            doc = json.loads(r.stdout)
            check(finite_everywhere(doc), "the objects' JSON is finite")
            objects = {o["quantity"]: o for o in doc.get("objects", [])}
            check(abs(objects["distance"]["value_m"] / 4.0 - 1) < 0.003, "P3-P4 is the width (%s)" % objects["distance"])
            check(abs(objects["height"]["value_m"] / 3.5 - 1) < 0.003, "P1 above P3 is the height (%s)" % objects["height"])
            check(" m \u00b1 " in objects["height"]["text"], "an object's text has its ±")
            check(0 < objects["height"]["sigma_m"] < 0.1, "its sigma is plausible")
            check(abs(doc["points"]["mid"]["m"][2] + 19.0) < 0.06, "a far-wall point is on the far wall")
            check(abs(doc["points"]["p3"]["from_far_wall_m"]) < 0.06, "P3 is at the far wall")
        # The same from the shot file's own points and measurements, drawn on the sheet.
        with_points = dict(base, points=[{"name": "p3", "px": c["P3"], "on": "floor"}, {"name": "p4", "px": c["P4"]},
                                         {"name": "p1", "px": c["P1"], "on": "above:p3"}],
                           measurements=[{"distance": ["p3", "p4"]}, {"height": ["p3", "p1"]}])
        points_path = os.path.join(tmp, "points.json")
        json.dump(with_points, open(points_path, "w"))
        points_sheet = os.path.join(tmp, "points_sheet.png")
        r = run(exe, "measure", points_path, "--sheet", points_sheet)
        check(r.returncode == 0, "measure reads a shot's points and measurements (%s)" % r.stderr.strip())
        if r.returncode == 0:
            objects = {o["quantity"]: o for o in json.loads(r.stdout).get("objects", [])}
            check(abs(objects.get("distance", {}).get("value_m", 0) / 4.0 - 1) < 0.003, "the file's distance is the width")
            check(abs(objects.get("height", {}).get("value_m", 0) / 3.5 - 1) < 0.003, "the file's height is the height")
            check(png_size(points_sheet) is not None, "the sheet with the objects is written")
        bad_points = dict(base, points=[{"name": "a", "px": [1]}])
        json.dump(bad_points, open(points_path, "w"))
        r = run(exe, "measure", points_path)
        check(r.returncode == 1 and "points[0]" in r.stderr and r.stderr.count("\n") == 1,
              "a shot's malformed point is one error line naming it (%r)" % r.stderr)
        for args, words in ((["--point", "x=1"], "--point takes NAME=U,V"),
                            (["--point", "x=1,2@roof"], "--point takes NAME=U,V"),
                            (["--height", "a,b"], "measure between points given by --point"),
                            (["--point", "a=600,500", "--distance", "a"], "--distance takes two point names"),
                            (["--point", "a=600,500", "--distance", "a,zz"], "\"zz\": no such point"),
                            (["--point", "sky=600,10"], "point \"sky\"")):
            r = run(exe, "measure", good, *args)
            check(r.returncode == 1 and r.stderr.count("\n") == 1 and r.stderr.startswith("error:") and words in r.stderr,
                  "measure %s: one error line with '%s' (%r)" % (" ".join(args), words, r.stderr))

        # --sheet writes a PNG at least the photo's size.
        sheet = os.path.join(tmp, "sheet.png")
        r = run(exe, "measure", good, "--sheet", sheet)
        check(r.returncode == 0 and png_size(sheet) is not None, "measure --sheet writes a PNG")
        if png_size(sheet):
            w, h = png_size(sheet)
            check(w >= 1280 and h > 720, "the sheet is at least the photo's size (%dx%d)" % (w, h))
        check(no_temp_files(tmp), "measure --sheet leaves no temporary file")

        # rectify: five textures and planes.json that agree with each other.
        out = os.path.join(tmp, "planes")
        r = run(exe, "rectify", good, "-o", out)
        check(r.returncode == 0, "rectify exits 0 (%s)" % r.stderr.strip())
        if r.returncode == 0:
            planes = json.load(open(os.path.join(out, "planes.json")))
            check(finite_everywhere(planes), "planes.json holds only finite numbers")
            for name in ("far_wall", "left_wall", "right_wall", "floor", "ceiling"):
                p = planes["planes"][name]
                size = png_size(os.path.join(out, name + ".png"))
                check(size == (p["width_px"], p["height_px"]), "%s.png is %s as planes.json says" % (name, size))
                aspect = p["width_m"] / p["height_m"]
                check(abs(size[0] / size[1] / aspect - 1) < 0.02, "%s.png has the true aspect ratio" % name)
                check(max(size) <= 4096, "%s.png is capped at 4096 px" % name)
            check(abs(planes["planes"]["floor"]["height_m"] - 19.0) < 0.06, "the floor is as long as the corridor")
            check(no_temp_files(out), "rectify leaves no temporary file")
        r = run(exe, "rectify", good, "-o", os.path.join(tmp, "small"), "--max-side", "256", "--px-per-m", "1000")
        check(r.returncode == 0, "rectify --max-side --px-per-m exits 0")
        if r.returncode == 0:
            check(png_size(os.path.join(tmp, "small", "floor.png"))[1] == 256, "--max-side caps the floor at 256 px")

        # Bad input: one line on stderr, exit 1, nothing on stdout.
        def shot_with(name, change):
            doc = json.loads(json.dumps(base))
            change(doc)
            path = os.path.join(tmp, name + ".json")
            json.dump(doc, open(path, "w"))
            return path

        def swap(a, b):
            def change(doc):
                c = doc["corners_px"]
                c[a], c[b] = c[b], c[a]
            return change

        def swap_near_far(doc):
            c = doc["corners_px"]
            for a, b in (("P1", "P7"), ("P2", "P8"), ("P3", "P5"), ("P4", "P6")):
                c[a], c[b] = c[b], c[a]

        def collinear(doc):
            c = doc["corners_px"]
            c["P2"] = [c["P1"][0] + 0.5 * (c["P1"][0] - c["P3"][0]), c["P1"][1] + 0.5 * (c["P1"][1] - c["P3"][1])]

        junk = os.path.join(tmp, "junk.png")
        open(junk, "wb").write(b"not an image at all")
        empty = os.path.join(tmp, "empty.png")
        open(empty, "wb").close()
        truncated = os.path.join(tmp, "truncated.png")
        open(truncated, "wb").write(open(base["image"], "rb").read()[:5000])
        nan_file = os.path.join(tmp, "nan.json")
        open(nan_file, "w").write(json.dumps(base).replace('"focal_px": 914.014724', '"focal_px": NaN'))
        huge = os.path.join(tmp, "huge.json")
        open(huge, "w").write(json.dumps(base).replace('"focal_px": 914.014724', '"focal_px": 1e999'))
        broken = os.path.join(tmp, "broken.json")
        open(broken, "w").write('{"image": "x.png", ')

        bad = [
            ("missing shot file", ["measure", os.path.join(tmp, "nothere.json")], "no such file"),
            ("corrupt JSON", ["measure", broken], "not valid JSON"),
            ("NaN in JSON", ["measure", nan_file], "not valid JSON"),
            ("huge number", ["measure", huge], "number overflow"),
            ("missing image field", ["measure", shot_with("noimage", lambda d: d.pop("image"))], "image"),
            ("missing image", ["measure", shot_with("gone", lambda d: d.update(image="gone.png"))], "does not exist"),
            ("junk image", ["measure", shot_with("junk", lambda d: d.update(image=junk))], "not a readable"),
            ("empty image", ["measure", shot_with("empty", lambda d: d.update(image=empty))], "is empty"),
            ("truncated image", ["measure", shot_with("trunc", lambda d: d.update(image=truncated))], "not a readable"),
            ("non-numeric focal", ["measure", shot_with("f", lambda d: d.update(focal_px="long"))], "must be a number"),
            ("zero focal", ["measure", shot_with("f0", lambda d: d.update(focal_px=0))], "positive"),
            ("negative height", ["measure", shot_with("h", lambda d: d.update(camera_height_m=-1.7))], "positive"),
            ("no scale", ["measure", shot_with("ns", lambda d: d.pop("camera_height_m"))], "scale is unknown"),
            ("missing corner", ["measure", shot_with("p8", lambda d: d["corners_px"].pop("P8"))], "P8"),
            ("corner far outside", ["measure", shot_with("far", lambda d: d["corners_px"].update(P6=[9000, 10]))],
             "outside"),
            ("crossed far wall", ["measure", shot_with("crossed", swap("P1", "P2"))], "crosses itself"),
            ("collinear corners", ["measure", shot_with("collinear", collinear)], "collinear"),
            ("near and far swapped", ["measure", shot_with("swapped", swap_near_far)], "far and near corners are swapped"),
            ("bad method", ["measure", good, "--method", "magic"], "general or seed"),
            ("negative sigma", ["measure", good, "--sigma-px", "-1"], "sigma"),
            ("unknown option", ["measure", good, "--frobnicate"], "unknown option"),
            ("two shots", ["measure", good, good], "one shot file"),
            ("sheet into a missing folder", ["measure", good, "--sheet", os.path.join(tmp, "no", "s.png")],
             "does not exist"),
            ("rectify without -o", ["rectify", good], "-o"),
            ("rectify bad max side", ["rectify", good, "-o", os.path.join(tmp, "x"), "--max-side", "0"], "max-side"),
            ("rectify crossed", ["rectify", shot_with("crossed2", swap("P5", "P6")), "-o", os.path.join(tmp, "y")],
             "crosses itself"),
        ]
        for what, args, needle in bad:
            r = run(exe, *args)
            lines = r.stderr.strip().splitlines()
            check(r.returncode == 1, "%s: exit 1 (got %d)" % (what, r.returncode))
            check(len(lines) == 1 and lines[0].startswith("error: "), "%s: one error line (got %r)" % (what, r.stderr))
            check(needle in r.stderr, "%s: the error mentions %r (got %r)" % (what, needle, r.stderr.strip()))
            check(r.stdout == "", "%s: nothing on stdout" % what)
        check(not os.path.exists(os.path.join(tmp, "y", "floor.png")), "a failed rectify writes no texture")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    print("%d failures" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
