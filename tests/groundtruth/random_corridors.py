#!/usr/bin/env python3
"""Random corridor scenes with exact answers (issue 22): ground truth nobody can tune to.

usage:
  random_corridors.py scene SEED OUTDIR [--size-scale S] [--no-render] [--mask]
      writes OUTDIR/seed_NNNNN.pov, .json (shot part + answers, the form of
      ../shared/corridors), renders seed_NNNNN.png with povray and makes
      seed_NNNNN_q70n3.jpg (Gaussian sensor noise, sigma 3 grey levels, then JPEG
      quality 70). --mask also renders seed_NNNNN_mask.ppm: every surface in a flat
      colour of its own (SURFACE ids below; object k in colour OBJECT_ID0 + k), no
      anti-aliasing, one ray through each pixel centre (check_random_corridors.py reads it).
  random_corridors.py range FIRST LAST OUTDIR [-j N] [--size-scale S] [--no-render]
      the same for every seed FIRST..LAST (inclusive), N povray runs at a time;
      prints the mean render time per scene.

  random_corridors.py views SEED OUTDIR
      renders the seed's scene from the novel-view cameras (NOVEL_VIEWS below: cameras
      the photo was not taken from, on the corridor's centre line at the photo's eye
      height, 640 px wide with the photo's field of view) as
      seed_NNNNN_view_KIND.png with seed_NNNNN_view_KIND.json (the camera, in the form
      make_corridors.py's views have); an unchanged view is not rendered again.

  random_corridors.py standing SEED OUTDIR
      writes seed_NNNNN_standing.json from the seed's answers and mask (scene --mask
      first): the shot with a cutout (a rectangle around it) for each person, plant
      and bin whose foot the photo shows (write_standing).

A seed fully determines its scene (random.Random(seed); the noise of the JPEG is
seeded by it too). The scenes have what real corridors have and make_corridors.py's
scenes lack: no painted band; floors glossy with reflections or matte; ceiling lamps,
windows and bright light in view; far ends closed, glazed (glass with the bright
outdoors behind) or open (the walls stop, a hall beyond); near ends closed behind the
camera, open behind it, or a portal the camera looks into from a hall; side openings
with rooms behind, doors, skirting boards, radiators, pipes; people, cabinets,
benches, tables, plants, bins, signs and pictures anywhere, some before the far
corners; 1.2-8 m wide, 2.2-6 m high; portrait and landscape frames; 26-50 mm
(35 mm-equivalent, by the diagonal) lenses; pitch up to +-15 deg, roll up to +-10 deg.

Frames (make_corridors.py's, whose Camera and world_from_camera are used here):
  model frame: right-handed, Y up, metres; floor y = 0; x from -width/2 to +width/2;
  the far end's cross-section (P1..P4) at z = -length; z = 0 is the cross-section of
  P5..P8, the NEAREST one whose four corners are all inside the photo (1% of the short
  side from its border); the camera stands at z > 0 (before it, or inside the box).
  POV-Ray frame: left-handed, the same x and y, Z = -z.
  camera: worldFromCamera = Ry(yaw) Rx(pitch) Rz(roll) (columns right, up, back);
  pixel centres at integer coordinates, u right, v down.
The answers are computed here by that projection (no photowalk code). Hidden flags and
the boundaries' shown shares come from ray casting against the objects' primitives
(boxes, cylinders, spheres); trim (skirting boards, glazing bars, lamp panels flush
with the ceiling) is not an object and hides nothing here (it covers a junction by 2 cm
at most). check_random_corridors.py checks all of it against the object-id mask.
"""
import argparse, json, math, os, random, subprocess, sys, tempfile, time
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_corridors import Camera, CORNERS, PLANES, run_povray  # noqa: E402  (the shared projection, povray)

# Surface ids of the mask render (flat colours, see mask_rgb).
SURFACE = {"left_wall": 1, "right_wall": 2, "floor": 3, "ceiling": 4, "far_end": 5, "beyond": 6, "hall": 7}
OBJECT_ID0 = 16  # object k (its index in "objects") has id 16 + k
NEAR_MARGIN = 0.01  # P5..P8: all four corners at least 1% of the short side inside the border


def mask_rgb(i):
    """The mask colour of id i (0..63), exact in an 8-bit file written with gamma 1."""
    return ((i % 8) * 32 + 16) / 255.0, (((i // 8) % 8) * 32 + 16) / 255.0, 200 / 255.0


def mask_id(r, g):
    """The id of a mask pixel's red and green bytes."""
    return int(round((r - 16) / 32.0)) + 8 * int(round((g - 16) / 32.0))


def v3(x, y, z):
    """A model-frame point in POV-Ray's frame."""
    return "<%.5f, %.5f, %.5f>" % (x, y, -z)


def tex(real, sid):
    """A texture: the real one, or in the mask pass the flat colour of id sid."""
    r, g, b = mask_rgb(sid)
    return ("#if (Mask) texture { pigment { color rgb <%.6f,%.6f,%.6f> } finish { ambient 1 diffuse 0 } } #else %s #end"
            % (r, g, b, real))


def rgb(c):
    return "color rgb <%.3f,%.3f,%.3f>" % tuple(c)


# ---------------------------------------------------------------------------------
# Materials: each a function of the scene's rng giving a POV-Ray texture (real pass).

def pale_colour(rng, lo=0.45, hi=0.9, sat=0.12):
    """A paint colour: mostly greys, creams, pale greens and blues."""
    base = rng.uniform(lo, hi)
    return [min(1.0, max(0.02, base * (1 + rng.uniform(-sat, sat)))) for _ in range(3)]


def wall_material(rng):
    kind = rng.choice(["paint", "paint", "paint", "brick", "tile", "concrete", "wood"])
    fin = "finish { diffuse 0.75 ambient 0.1 specular %.2f roughness 0.05 }" % rng.uniform(0, 0.15)
    if kind == "paint":
        c = pale_colour(rng, 0.3, 0.9, 0.2)
        d = [x * 0.94 for x in c]
        return kind, ("texture { pigment { bozo color_map { [0 %s] [1 %s] } scale %.3f } normal { bumps 0.04 scale 0.01 } %s }"
                      % (rgb(c), rgb(d), rng.uniform(0.05, 0.4), fin))
    if kind == "brick":
        c1, c2 = pale_colour(rng, 0.6, 0.85, 0.05), [rng.uniform(0.35, 0.6), rng.uniform(0.15, 0.3), rng.uniform(0.1, 0.2)]
        return kind, ("texture { pigment { brick %s %s brick_size <0.25,0.075,0.125> mortar 0.01 } %s }"
                      % (rgb(c1), rgb(c2), fin))
    if kind == "tile":
        t = rng.choice([0.1, 0.15, 0.2, 0.3])
        c = pale_colour(rng, 0.6, 0.92, 0.15)
        return kind, ("texture { pigment { brick %s %s brick_size <%.2f,%.2f,%.2f> mortar 0.006 } "
                      "finish { diffuse 0.7 ambient 0.1 specular 0.4 roughness 0.01 reflection 0.04 } }"
                      % (rgb([x * 0.6 for x in c]), rgb(c), t, t, t))
    if kind == "concrete":
        c = pale_colour(rng, 0.4, 0.7, 0.05)
        return kind, ("texture { pigment { granite color_map { [0 %s] [1 %s] } scale 0.5 } %s }"
                      % (rgb(c), rgb([x * 0.85 for x in c]), fin))
    c = [rng.uniform(0.45, 0.65), rng.uniform(0.3, 0.42), rng.uniform(0.15, 0.25)]
    return kind, ("texture { pigment { wood color_map { [0 %s] [1 %s] } turbulence 0.08 scale <0.04,0.04,1> } %s }"
                  % (rgb(c), rgb([x * 0.7 for x in c]), fin))


def floor_material(rng):
    kind = rng.choice(["tiles", "tiles", "vinyl", "wood", "carpet", "terrazzo"])
    gloss = rng.random() < 0.6 and kind != "carpet"
    refl = rng.uniform(0.08, 0.3) if gloss else 0.0
    fin = ("finish { diffuse 0.7 ambient 0.1 specular %.2f roughness 0.005 reflection { %.3f } }" % (rng.uniform(0.3, 0.8), refl)
           if gloss else "finish { diffuse 0.8 ambient 0.1 }")
    if kind == "tiles":
        t = rng.choice([0.3, 0.4, 0.5, 0.6])
        c1 = pale_colour(rng, 0.3, 0.85, 0.15)
        c2 = [x * rng.uniform(0.55, 1.0) for x in c1] if rng.random() < 0.6 else pale_colour(rng, 0.1, 0.8, 0.2)
        if rng.random() < 0.5:
            pig = "checker %s %s scale %.2f" % (rgb(c1), rgb(c2), t)
        else:
            pig = "brick %s %s brick_size <%.2f,%.2f,%.2f> mortar 0.008" % (rgb([x * 0.5 for x in c1]), rgb(c1), t, t, t)
        tx = "pigment { %s }" % pig
    elif kind == "vinyl":
        c = pale_colour(rng, 0.25, 0.75, 0.25)
        tx = "pigment { granite color_map { [0 %s] [1 %s] } scale 0.6 }" % (rgb(c), rgb([x * 0.8 for x in c]))
    elif kind == "wood":
        c = [rng.uniform(0.45, 0.7), rng.uniform(0.28, 0.45), rng.uniform(0.12, 0.25)]
        tx = ("pigment { wood color_map { [0 %s] [1 %s] } turbulence 0.1 scale <0.05,0.05,1> }"
              % (rgb(c), rgb([x * 0.6 for x in c])))
    elif kind == "carpet":
        c = pale_colour(rng, 0.12, 0.5, 0.35)
        tx = "pigment { granite color_map { [0 %s] [1 %s] } scale 0.05 }" % (rgb(c), rgb([x * 0.7 for x in c]))
    else:
        c = pale_colour(rng, 0.5, 0.8, 0.1)
        tx = ("pigment { granite color_map { [0 %s] [0.7 %s] [1 %s] } scale 0.08 }"
              % (rgb(c), rgb([x * 0.9 for x in c]), rgb([x * 0.5 for x in c])))
    return kind + (" glossy" if gloss else ""), "texture { %s %s }" % (tx, fin)


def ceiling_material(rng):
    c = pale_colour(rng, 0.7, 0.95, 0.05)
    base = "texture { pigment { %s } finish { diffuse 0.7 ambient 0.35 } }" % rgb(c)
    if rng.random() < 0.5:
        return "plain", base
    g = rng.choice([0.6, 1.2])
    line = rgb([x * 0.6 for x in c])
    grid = lambda axis: ("texture { pigment { gradient %s color_map { [0 %s] [0.012 %s] [0.012 color rgbt 1] [1 color rgbt 1] } "
                         "scale %.2f } finish { diffuse 0.7 ambient 0.35 } }" % (axis, line, line, g))
    return "acoustic tiles", base + " " + grid("x") + " " + grid("z")


# ---------------------------------------------------------------------------------
# Primitives: what objects are made of, for POV-Ray and for ray casting alike.

def prim_box(lo, hi):
    return ("box", tuple(min(a, b) for a, b in zip(lo, hi)), tuple(max(a, b) for a, b in zip(lo, hi)))


def prim_cyl(axis, centre, r, a0, a1):
    """An axis-aligned cylinder: axis 'x', 'y' or 'z'; centre = the other two coordinates."""
    return ("cyl", axis, tuple(centre), r, min(a0, a1), max(a0, a1))


def prim_sph(c, r):
    return ("sph", tuple(c), r)


def prim_pov(p, texture):
    if p[0] == "box":
        return "box { %s, %s %s }\n" % (v3(*p[1]), v3(*p[2]), texture)
    if p[0] == "sph":
        return "sphere { %s, %.4f %s }\n" % (v3(*p[1]), p[2], texture)
    _, axis, c, r, a0, a1 = p
    ends = []
    for a in (a0, a1):
        pt = {"x": (a, c[0], c[1]), "y": (c[0], a, c[1]), "z": (c[0], c[1], a)}[axis]
        ends.append(v3(*pt))
    return "cylinder { %s, %s, %.4f %s }\n" % (ends[0], ends[1], r, texture)


def ray_hit(p, o, d, tmax):
    """Whether the ray o + t d hits primitive p for some 1e-9 < t < tmax."""
    if p[0] == "box":
        t0, t1 = 1e-9, tmax
        for i in range(3):
            if abs(d[i]) < 1e-15:
                if o[i] < p[1][i] or o[i] > p[2][i]:
                    return False
                continue
            a, b = (p[1][i] - o[i]) / d[i], (p[2][i] - o[i]) / d[i]
            if a > b:
                a, b = b, a
            t0, t1 = max(t0, a), min(t1, b)
            if t0 > t1:
                return False
        return True
    if p[0] == "sph":
        c, r = p[1], p[2]
        oc = [o[i] - c[i] for i in range(3)]
        a = sum(x * x for x in d)
        b = 2 * sum(oc[i] * d[i] for i in range(3))
        cc = sum(x * x for x in oc) - r * r
        disc = b * b - 4 * a * cc
        if disc < 0:
            return False
        s = math.sqrt(disc)
        return any(1e-9 < t < tmax for t in ((-b - s) / (2 * a), (-b + s) / (2 * a)))
    _, axis, c, r, a0, a1 = p
    k = "xyz".index(axis)
    j = [i for i in range(3) if i != k]
    # The side: |(o + t d)_j - c| = r, with the axial coordinate within [a0, a1].
    ox, oy, dx, dy = o[j[0]] - c[0], o[j[1]] - c[1], d[j[0]], d[j[1]]
    a, b, cc = dx * dx + dy * dy, 2 * (ox * dx + oy * dy), ox * ox + oy * oy - r * r
    ts = []
    if a > 1e-15:
        disc = b * b - 4 * a * cc
        if disc >= 0:
            s = math.sqrt(disc)
            ts += [(-b - s) / (2 * a), (-b + s) / (2 * a)]
    ts = [t for t in ts if a0 <= o[k] + t * d[k] <= a1]
    # The caps.
    if abs(d[k]) > 1e-15:
        for a_ in (a0, a1):
            t = (a_ - o[k]) / d[k]
            x, y = o[j[0]] + t * d[j[0]] - c[0], o[j[1]] + t * d[j[1]] - c[1]
            if x * x + y * y <= r * r:
                ts.append(t)
    return any(1e-9 < t < tmax for t in ts)


def occluded(eye, x, objects):
    """Whether an object hides model point x from the eye (ray cast, the point itself excluded)."""
    d = [x[i] - eye[i] for i in range(3)]
    return any(ray_hit(p, eye, d, 1.0 - 1e-7) for ob in objects for p in ob["prims"])


# ---------------------------------------------------------------------------------
# The scene.

class Reject(Exception):
    """The draw made a scene the generator does not keep (the far end out of view...)."""


def draw_camera(rng, size_scale):
    portrait = rng.random() < 0.35
    long_side = rng.choice([640, 720, 800, 896, 960, 1024])
    aspect = rng.choice([4 / 3.0, 3 / 2.0, 16 / 9.0])
    w, h = long_side, int(round(long_side / aspect / 2)) * 2
    if portrait:
        w, h = h, w
    w, h = int(round(w * size_scale / 2)) * 2, int(round(h * size_scale / 2)) * 2
    lens_mm = rng.uniform(26.0, 50.0)  # 35 mm-equivalent, by the diagonal (43.27 mm)
    focal = lens_mm / math.hypot(36.0, 24.0) * math.hypot(w, h)
    principal = [(w - 1) / 2.0, (h - 1) / 2.0]
    if rng.random() < 0.4:  # a phone's principal point is a little off centre
        principal = [principal[0] + rng.gauss(0, 0.006 * w), principal[1] + rng.gauss(0, 0.006 * h)]
    return dict(size=(w, h), portrait=portrait, lens_mm=lens_mm, focal_px=focal, principal=principal)


def small_or_wide(rng, wide):
    """An angle: within +-2 deg half the time (a photo taken with care), else up to +-wide."""
    return rng.gauss(0, 1.0) if rng.random() < 0.5 else rng.uniform(-wide, wide)


def in_photo(uv, size, margin):
    return margin - 0.5 <= uv[0] <= size[0] - 0.5 - margin and margin - 0.5 <= uv[1] <= size[1] - 0.5 - margin


def draw_scene(rng, size_scale):
    """One try at a scene in the camera's frame along the corridor (camera at z' = 0);
    raises Reject when it is not kept. Returns the scene dict in the model frame."""
    cam = draw_camera(rng, size_scale)
    width = 1.2 + 6.8 * rng.random() ** 1.8
    height = 2.2 + 3.8 * rng.random() ** 1.6
    if width > 4:
        height = min(6.0, height + rng.uniform(0, 0.3 * (width - 4)))
    eye_y = rng.uniform(1.0, min(1.9, height - 0.4))
    eye_x = rng.uniform(-1, 1) * max(0.0, width / 2 - 0.35) * 0.8
    yaw = max(-25.0, min(25.0, small_or_wide(rng, 25.0)))
    pitch = max(-15.0, min(15.0, small_or_wide(rng, 15.0)))
    roll = max(-10.0, min(10.0, small_or_wide(rng, 10.0)))
    far_dist = rng.uniform(max(4.0, 1.5 * width), 40.0)  # camera to the far end's cross-section
    near_end = rng.choices(["closed", "open", "portal"], [0.45, 0.3, 0.25])[0]
    far_end = rng.choices(["closed", "glass", "open"], [0.6, 0.2, 0.2])[0]
    if near_end == "portal":
        box_near = -rng.uniform(0.5, min(4.0, far_dist - 2.0))  # the corridor's mouth before the camera
    elif near_end == "closed":
        box_near = rng.uniform(0.5, 6.0)  # an end wall behind the camera
    else:
        box_near = 40.0  # runs on behind the camera
    probe = Camera([eye_x, eye_y, 0.0], [yaw, pitch, roll], cam["size"], cam["focal_px"], cam["principal"])
    # The corridor's vanishing point well inside the photo (a photo down a corridor).
    vp = probe.project([eye_x, eye_y, -1e6])
    w, h = cam["size"]
    if not (0.12 * w <= vp[0] <= 0.88 * w and 0.12 * h <= vp[1] <= 0.88 * h):
        raise Reject("vanishing point")
    margin = NEAR_MARGIN * min(w, h)

    def section_inside(z):
        pts = [probe.project((x, y, z)) for x in (-width / 2, width / 2) for y in (0.0, height)]
        return all(p[2] > 0.05 and in_photo(p, cam["size"], margin) for p in pts)

    if not section_inside(-far_dist):
        raise Reject("far end out of the photo")
    # P5..P8: the nearest cross-section with all four corners inside (bisection: a
    # corner's image runs monotonically towards the vanishing point, inside the photo).
    lo, hi = -far_dist, min(box_near, 0.0)
    if section_inside(hi):
        zstar = hi
    else:
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if section_inside(mid) else (lo, mid)
        zstar = lo
    length = zstar + far_dist
    if length < 1.5:
        raise Reject("too short a box between P5..P8 and the far end")
    # Shift to the model frame: z = z' - zstar.
    s = dict(cam, width=width, height=height, length=length, eye=[eye_x, eye_y, -zstar], ypr=[yaw, pitch, roll],
             near_end=near_end, far_end=far_end, box_near=box_near - zstar, near_distance=-zstar)
    return s


def furnish(rng, s):
    """Openings, windows, lamps, trim and objects, in the model frame."""
    w2, h, L = s["width"] / 2, s["height"], s["length"]
    cam_z = s["eye"][2]
    z_near = min(s["box_near"], cam_z + 3.0)  # where things may stand, towards the camera
    zmin, zmax = -L, min(z_near, cam_z - 1.0)
    objects, openings, lamps, trim = [], [], [], []
    colour = lambda: [rng.uniform(0.08, 0.85) for _ in range(3)]

    def free_span(side, length_):
        """A span along the wall `side` (-1 left, +1 right) not used by an opening or a
        wall object so far; None after a few tries."""
        for _ in range(12):
            z1 = rng.uniform(zmin + 0.1, max(zmin + 0.2, zmax - length_))
            z0 = z1 + length_
            if z0 > zmax:
                continue
            if all(o["side"] != side or z0 < o["z"][1] - 0.15 or z1 > o["z"][0] + 0.15 for o in openings + wall_uses):
                wall_uses.append(dict(side=side, z=(z0, z1)))
                return z0, z1
        return None

    wall_uses = []
    # Side openings (a room or a corridor beyond) and windows.
    for _ in range(rng.choice([0, 0, 1, 1, 2, 3])):
        side = rng.choice((-1, 1))
        span = free_span(side, rng.uniform(0.9, min(4.0, 0.4 * L)))
        if span:
            full = rng.random() < 0.3
            openings.append(dict(kind="opening", side=side, z=span, y=(0.0, h if full else min(h - 0.2, rng.uniform(2.0, 2.6))),
                                 depth=rng.uniform(1.5, 5.0), colour=pale_colour(rng, 0.3, 0.8, 0.2),
                                 glow=rng.uniform(0.05, 0.6)))
    for _ in range(rng.choice([0, 0, 0, 1, 2])):
        side = rng.choice((-1, 1))
        span = free_span(side, rng.uniform(0.8, 2.5))
        if span:
            sill = rng.uniform(0.8, 1.2)
            openings.append(dict(kind="window", side=side, z=span, y=(sill, min(h - 0.2, sill + rng.uniform(1.0, 1.8))),
                                 sun=rng.uniform(0.5, 1.1) if rng.random() < 0.5 else 0.0))

    def add(kind, prims, colour_, size, place, keypoints, on, **extra):
        objects.append(dict(kind=kind, prims=prims, colour=colour_, size_m=[round(x, 4) for x in size],
                            place_m=[round(x, 4) for x in place], on=on, keypoints_m=keypoints, **extra))

    # Doors on the side walls (closed; a leaf 3 cm proud of the wall).
    for _ in range(rng.choice([0, 1, 2, 3, 4])):
        side = rng.choice((-1, 1))
        dw, dh = rng.uniform(0.8, 1.0), rng.uniform(2.0, min(2.3, h - 0.1))
        span = free_span(side, dw)
        if span:
            x = side * w2
            z0, z1 = span
            add("door", [prim_box((x, 0, z0), (x - side * 0.03, dh, z1))], colour(), (dw, dh, 0.03),
                (x - side * 0.03, 0, 0.5 * (z0 + z1)), {"bottom_near": (x - side * 0.03, 0, z0), "bottom_far": (x - side * 0.03, 0, z1),
                                                         "top_near": (x - side * 0.03, dh, z0), "top_far": (x - side * 0.03, dh, z1)},
                "left_wall" if side < 0 else "right_wall")
    # Pictures and notices on the side walls.
    for _ in range(rng.choice([0, 1, 2, 3, 5])):
        side = rng.choice((-1, 1))
        pw, ph = rng.uniform(0.3, 1.2), rng.uniform(0.3, 0.9)
        span = free_span(side, pw)
        if span:
            x, (z0, z1), y0 = side * w2, span, rng.uniform(1.0, min(1.8, h - ph - 0.1))
            xf = x - side * 0.015
            add("picture", [prim_box((x, y0, z0), (xf, y0 + ph, z1))], colour(), (pw, ph, 0.015), (xf, y0, 0.5 * (z0 + z1)),
                {"bottom_near": (xf, y0, z0), "bottom_far": (xf, y0, z1), "top_near": (xf, y0 + ph, z0), "top_far": (xf, y0 + ph, z1)},
                "left_wall" if side < 0 else "right_wall", colour2=colour())
    # Radiators under the windows or anywhere on a wall.
    for _ in range(rng.choice([0, 0, 0, 1, 2])):
        side = rng.choice((-1, 1))
        rw = rng.uniform(0.6, 1.6)
        span = free_span(side, rw)
        if span:
            x, (z0, z1) = side * w2, span
            rd, rh = rng.uniform(0.06, 0.12), rng.uniform(0.4, 0.7)
            add("radiator", [prim_box((x, 0.12, z0), (x - side * rd, 0.12 + rh, z1))], pale_colour(rng, 0.7, 0.9, 0.05),
                (rw, rh, rd), (x - side * rd / 2, 0.12, 0.5 * (z0 + z1)), {}, "left_wall" if side < 0 else "right_wall")
    # Pipes along a wall under the ceiling, and one up a corner.
    for _ in range(rng.choice([0, 0, 0, 0, 1, 2])):
        side, r = rng.choice((-1, 1)), rng.uniform(0.015, 0.06)
        x, y = side * (w2 - r - rng.uniform(0.02, 0.1)), h - r - rng.uniform(0.05, 0.4)
        z0 = min(s["box_near"], cam_z + 1.0)
        add("pipe", [prim_cyl("z", (x, y), r, -L, z0)], pale_colour(rng, 0.3, 0.9, 0.1), (2 * r, 2 * r, L + z0), (x, y, -L),
            {}, "left_wall" if side < 0 else "right_wall")
    if rng.random() < 0.15:
        side, r = rng.choice((-1, 1)), rng.uniform(0.02, 0.06)
        x, z = side * (w2 - r - 0.02), -L + r + 0.02
        add("pipe", [prim_cyl("y", (x, z), r, 0.0, h)], pale_colour(rng, 0.3, 0.9, 0.1), (2 * r, h, 2 * r), (x, 0, z), {},
            "far_corner")

    def box_object(kind, x0, x1, z0, z1, top, colour_, on):
        """An upright box standing on the floor, with its eight corners as key points."""
        kp = {"%s_%s_%s" % (a, b, c): (x, y, z) for a, x in (("left", min(x0, x1)), ("right", max(x0, x1)))
              for b, y in (("bottom", 0.0), ("top", top)) for c, z in (("near", max(z0, z1)), ("far", min(z0, z1)))}
        add(kind, [prim_box((x0, 0, z0), (x1, top, z1))], colour_, (abs(x1 - x0), top, abs(z1 - z0)),
            (0.5 * (x0 + x1), 0, 0.5 * (z0 + z1)), kp, on)

    # Furniture against the side walls.
    for _ in range(rng.choice([0, 0, 0, 1, 1, 2, 3])):
        kind = rng.choice(["cabinet", "cabinet", "bench", "table", "plant", "bin"])
        side = rng.choice((-1, 1))
        x = side * w2
        if kind == "cabinet":
            span = free_span(side, rng.uniform(0.4, 2.0))
            if span:
                dep = rng.uniform(0.35, 0.6)
                box_object("cabinet", x, x - side * dep, span[0], span[1], rng.uniform(0.7, min(2.1, h - 0.1)), colour(),
                           "left_wall" if side < 0 else "right_wall")
        elif kind == "bench":
            span = free_span(side, rng.uniform(1.0, 2.2))
            if span:
                dep, col = rng.uniform(0.35, 0.5), colour()
                z0, z1 = span
                prims = [prim_box((x, 0.4, z0), (x - side * dep, 0.46, z1))]
                for zl in (z0 - 0.1, z1 + 0.15):
                    prims.append(prim_box((x - side * 0.05, 0, zl), (x - side * (dep - 0.05), 0.4, zl - 0.05)))
                add("bench", prims, col, (z0 - z1, 0.46, dep), (x - side * dep / 2, 0, 0.5 * (z0 + z1)),
                    {"seat_near_inner": (x - side * dep, 0.46, z0), "seat_far_inner": (x - side * dep, 0.46, z1)},
                    "left_wall" if side < 0 else "right_wall")
        elif kind == "table":
            span = free_span(side, rng.uniform(0.8, 1.6))
            if span:
                dep, z0, z1 = rng.uniform(0.6, 0.9), span[0], span[1]
                xi = x - side * dep
                prims = [prim_box((x, 0.7, z0), (xi, 0.74, z1))]
                for xa in (x - side * 0.05, xi + side * 0.05):
                    for za in (z0 - 0.05, z1 + 0.05):
                        prims.append(prim_cyl("y", (xa, za), 0.025, 0.0, 0.7))
                add("table", prims, colour(), (z0 - z1, 0.74, dep), (0.5 * (x + xi), 0, 0.5 * (z0 + z1)),
                    {"top_near_inner": (xi, 0.74, z0), "top_far_inner": (xi, 0.74, z1)},
                    "left_wall" if side < 0 else "right_wall")
        else:
            span = free_span(side, 0.5)
            if span:
                zc = 0.5 * (span[0] + span[1])
                r = 0.2 if kind == "plant" else 0.18
                xc = x - side * (r + 0.03)
                tall = 0.45 if kind == "plant" else rng.uniform(0.5, 0.9)
                prims = [prim_cyl("y", (xc, zc), r, 0.0, tall)]
                top = tall
                if kind == "plant":
                    fr = rng.uniform(0.3, 0.5)
                    prims.append(prim_sph((xc, tall + fr * 0.8, zc), fr))
                    top = tall + 1.8 * fr
                add(kind, prims, colour() if kind == "bin" else [0.45, 0.3, 0.2], (2 * r, top, 2 * r), (xc, 0, zc),
                    {"top": (xc, top, zc), "base": (xc, 0, zc)}, "floor", foliage=[0.15, 0.4, 0.12])

    def person(x, z):
        """A person: legs, a torso, arms and a head (cylinders and a sphere)."""
        tall = rng.uniform(1.5, 1.95)
        hip, shoulder, r = 0.47 * tall, 0.82 * tall, rng.uniform(0.15, 0.21)
        prims = [prim_cyl("y", (x - 0.09, z), 0.07, 0.0, hip), prim_cyl("y", (x + 0.09, z), 0.07, 0.0, hip),
                 prim_cyl("y", (x, z), r, hip - 0.02, shoulder), prim_cyl("y", (x - r - 0.05, z), 0.05, hip, shoulder),
                 prim_cyl("y", (x + r + 0.05, z), 0.05, hip, shoulder), prim_sph((x, tall - 0.11, z), 0.11)]
        add("person", prims, colour(), (2 * r + 0.2, tall, 2 * r), (x, 0, z), {"head_top": (x, tall, z), "feet": (x, 0, z)},
            "floor", legs=colour(), head=[rng.uniform(0.4, 0.9), rng.uniform(0.3, 0.7), rng.uniform(0.2, 0.55)])

    # People anywhere in the corridor.
    for _ in range(rng.choice([0, 0, 0, 0, 1, 1, 2, 3])):
        z = rng.uniform(zmin + 0.3, min(zmax, cam_z - 2.0))
        if z > zmin + 0.3:  # mostly walking along the middle
            person(max(-w2 + 0.3, min(w2 - 0.3, rng.gauss(0, 0.25 * w2))), z)
    # Before the far end: a person or a cabinet at one of its corners (hiding it), sometimes.
    if rng.random() < 0.2:
        side = rng.choice((-1, 1))
        if rng.random() < 0.5:
            person(side * (w2 - rng.uniform(0.25, 0.7)), -L + rng.uniform(0.3, 2.0))
        else:
            wid, dep = rng.uniform(0.5, min(1.5, w2)), rng.uniform(0.4, 0.6)
            box_object("cabinet", side * w2, side * (w2 - wid), -L, -L + dep, rng.uniform(0.8, min(2.0, h - 0.2)), colour(),
                       "far_corner")
    # Signs: hanging from the ceiling across the corridor, or sticking out of a wall.
    for _ in range(rng.choice([0, 0, 1, 2])):
        z = rng.uniform(zmin + 0.5, zmax)
        sw, sh = rng.uniform(0.3, 1.0), rng.uniform(0.15, 0.35)
        if rng.random() < 0.5:
            x = rng.uniform(-w2 + sw / 2 + 0.1, w2 - sw / 2 - 0.1)
            y0 = min(h - 0.3 - sh, rng.uniform(2.1, 2.5))
            prims = [prim_box((x - sw / 2, y0, z), (x + sw / 2, y0 + sh, z - 0.03))]
            hang = h - (y0 + sh)
            if hang > 0.01:
                prims.append(prim_cyl("y", (x, z - 0.015), 0.006, y0 + sh, h))
            add("sign", prims, [0.1, 0.55, 0.25] if rng.random() < 0.5 else colour(), (sw, sh, 0.03), (x, y0, z),
                {"top_left": (x - sw / 2, y0 + sh, z), "top_right": (x + sw / 2, y0 + sh, z),
                 "bottom_left": (x - sw / 2, y0, z), "bottom_right": (x + sw / 2, y0, z)}, "ceiling", lit=rng.random() < 0.5)
        else:
            side = rng.choice((-1, 1))
            x0, x1 = side * w2, side * (w2 - sw)
            y0 = rng.uniform(2.0, max(2.05, h - sh - 0.2))
            add("sign", [prim_box((x0, y0, z), (x1, y0 + sh, z - 0.03))], colour(), (sw, sh, 0.03), (0.5 * (x0 + x1), y0, z),
                {"top_wall": (x0, y0 + sh, z), "top_end": (x1, y0 + sh, z), "bottom_wall": (x0, y0, z), "bottom_end": (x1, y0, z)},
                "left_wall" if side < 0 else "right_wall", lit=False)
    # On the far wall (closed far end): a door and a picture or notice board.
    if s["far_end"] == "closed":
        if rng.random() < 0.6:
            dw, dh = rng.uniform(0.8, min(1.8, 1.6 * w2)), rng.uniform(2.0, min(2.4, h - 0.1))
            x = rng.uniform(-w2 + dw / 2 + 0.05, w2 - dw / 2 - 0.05)
            add("door", [prim_box((x - dw / 2, 0, -L), (x + dw / 2, dh, -L + 0.03))], colour(), (dw, dh, 0.03), (x, 0, -L + 0.03),
                {"bottom_left": (x - dw / 2, 0, -L + 0.03), "bottom_right": (x + dw / 2, 0, -L + 0.03),
                 "top_left": (x - dw / 2, dh, -L + 0.03), "top_right": (x + dw / 2, dh, -L + 0.03)}, "far_wall")
        if rng.random() < 0.5:
            pw, ph = rng.uniform(0.3, min(1.2, w2)), rng.uniform(0.3, 0.8)
            x, y0 = rng.uniform(-w2 + pw / 2 + 0.05, w2 - pw / 2 - 0.05), rng.uniform(1.0, max(1.05, h - ph - 0.3))
            add("picture", [prim_box((x - pw / 2, y0, -L), (x + pw / 2, y0 + ph, -L + 0.015))], colour(), (pw, ph, 0.015),
                (x, y0, -L + 0.015), {"bottom_left": (x - pw / 2, y0, -L + 0.015), "bottom_right": (x + pw / 2, y0, -L + 0.015),
                                      "top_left": (x - pw / 2, y0 + ph, -L + 0.015), "top_right": (x + pw / 2, y0 + ph, -L + 0.015)},
                "far_wall", colour2=colour())
    # Ceiling lamps: panels or downlights in one or two rows, flush with the ceiling
    # (trim, hiding nothing), or lamps hanging on a rod (objects).
    style = rng.choice(["panel", "panel", "downlight", "hanging", "none"])
    spacing, rows = rng.uniform(2.0, 5.0), (1 if s["width"] < 3 or rng.random() < 0.5 else 2)
    z = -L + rng.uniform(0.5, spacing)
    while z < min(s["box_near"], cam_z + 3.0) and style != "none":
        for row in range(rows):
            x = 0.0 if rows == 1 else (-1 if row == 0 else 1) * w2 * 0.45
            if style == "hanging":
                drop = rng.uniform(0.3, min(1.0, h - 2.2)) if h > 2.6 else 0.2
                prims = [prim_cyl("y", (x, z), 0.008, h - drop, h), prim_cyl("y", (x, z), 0.18, h - drop - 0.12, h - drop)]
                add("lamp", prims, [0.2, 0.2, 0.2], (0.36, drop + 0.12, 0.36), (x, h - drop - 0.12, z),
                    {"bottom": (x, h - drop - 0.12, z)}, "ceiling")
                lamps.append((x, h - drop - 0.15, z))
            else:
                lamps.append((x, h - 0.02, z))
                trim.append(("lamp_" + style, x, z))
        z += spacing
    return objects, openings, lamps, trim, style


def make_scene(seed, size_scale=1.0):
    """The scene of a seed: the camera and the box (kept draws only), then the rest."""
    rng = random.Random(seed)
    for attempt in range(500):
        try:
            s = draw_scene(rng, size_scale)
            break
        except Reject:
            continue
    else:
        raise RuntimeError("seed %d: no scene kept in 500 draws" % seed)
    s["seed"], s["draws"] = seed, attempt + 1
    s["walls_kind"], s["walls_tex"] = wall_material(rng)
    s["far_tex"] = s["walls_tex"] if rng.random() < 0.5 else wall_material(rng)[1]
    s["floor_kind"], s["floor_tex"] = floor_material(rng)
    s["ceiling_kind"], s["ceiling_tex"] = ceiling_material(rng)
    s["hall_tex"] = wall_material(rng)[1]
    s["skirting"] = None if rng.random() < 0.3 else (rng.uniform(0.06, 0.15), rng.choice(
        [[0.9, 0.9, 0.88], [0.15, 0.15, 0.15], [0.4, 0.26, 0.15], pale_colour(rng, 0.2, 0.8, 0.2)]))
    s["light_colour"] = [1.0, rng.uniform(0.85, 1.0), rng.uniform(0.65, 1.0)] if rng.random() < 0.6 else \
        [rng.uniform(0.85, 1.0), rng.uniform(0.95, 1.0), 1.0]
    s["exposure"] = rng.uniform(0.6, 1.4)
    s["ambient"] = rng.uniform(0.4, 1.2)
    s["hall_light"] = rng.uniform(0.3, 2.0)
    s["outdoor"] = [rng.uniform(0.8, 1.6), rng.uniform(0.85, 1.6), rng.uniform(1.0, 1.8)]
    s["glass_bays"] = rng.choice([1, 2, 3, 4])
    s["objects"], s["openings"], s["lamps"], s["trim"], s["lamp_style"] = furnish(rng, s)
    return s


# ---------------------------------------------------------------------------------
# POV-Ray.

def scene_pov(s):
    w2, h, L = s["width"] / 2, s["height"], s["length"]
    t = 0.2  # wall thickness
    zn = s["box_near"]  # the corridor box's near end (the portal, or the end wall behind the camera)
    cam = Camera(s["eye"], s["ypr"], s["size"], s["focal_px"], s["principal"])
    E, lc = s["exposure"], s["light_colour"]
    out = ["// generated by tests/groundtruth/random_corridors.py (seed %d); ground truth in the JSON beside it\n" % s["seed"],
           "#version 3.7;\n#ifndef (Mask) #declare Mask = 0; #end\n",
           "global_settings { assumed_gamma 1.0 max_trace_level 4 #if (Mask) ambient_light 1 #else ambient_light %.3f #end }\n"
           % s["ambient"], cam.pov(0.0)]
    wall = lambda sid: tex(s["walls_tex"], sid)
    t_end = t if s["far_end"] == "closed" else 0.0  # the walls stop at z = -L unless a far wall closes them
    # The side walls, with their openings cut out.
    for side, name in ((-1, "left_wall"), (1, "right_wall")):
        x0, x1 = side * w2, side * (w2 + t)
        cuts = [o for o in s["openings"] if o["side"] == side]
        body = "box { %s, %s }" % (v3(x0, 0, -L - t_end), v3(x1, h, zn))
        if cuts:
            holes = "".join("box { %s, %s }" % (v3(x0 - side * 0.01, o["y"][0] - (0.01 if o["y"][0] == 0 else 0), o["z"][0]),
                                                v3(x1 + side * 0.01, o["y"][1] + (0.01 if o["y"][1] >= h else 0), o["z"][1]))
                            for o in cuts)
            out.append("difference { %s %s %s }\n" % (body, holes, wall(SURFACE[name])))
        else:
            out.append(body[:-1] + " %s }\n" % wall(SURFACE[name]))
    # Floor (running on under the hall, the side rooms and beyond the far end) and ceiling.
    out.append("box { %s, %s %s }\n" % (v3(-w2 - 12, -0.2, -L - 30), v3(w2 + 12, 0, zn), tex(s["floor_tex"], SURFACE["floor"])))
    out.append("box { %s, %s %s }\n" % (v3(-w2 - t, h, -L - t_end), v3(w2 + t, h + t, zn), tex(s["ceiling_tex"], SURFACE["ceiling"])))
    # The floor beyond the box's two ends in the mask: another id (the box ends there).
    out.append("#if (Mask) box { %s, %s %s } #end\n" % (v3(-w2 - 12.01, -0.2, -L - 30), v3(w2 + 12.01, 0.0001, -L),
                                                        tex("", SURFACE["beyond"])))
    # Beside the box (seen through the side openings) the floor is another id too.
    for side in (-1, 1):
        out.append("#if (Mask) box { %s, %s %s } #end\n" % (v3(side * (w2 + 0.0001), -0.2, -L - 30), v3(side * (w2 + 12.01), 0.0001, zn + 30),
                                                            tex("", SURFACE["beyond"])))
    if s["near_end"] == "portal":
        out.append("#if (Mask) box { %s, %s %s } #end\n" % (v3(-w2 - 12.01, -0.2, zn), v3(w2 + 12.01, 0.0001, zn + 30),
                                                            tex("", SURFACE["hall"])))
    else:
        out.append("box { %s, %s %s }\n" % (v3(-w2 - 12, -0.2, zn), v3(w2 + 12, 0, zn + 0.5), tex(s["floor_tex"], SURFACE["floor"])))
    # The far end.
    far = s["far_end"]
    if far == "closed":
        out.append("box { %s, %s %s }\n" % (v3(-w2 - t, -0.2, -L - t), v3(w2 + t, h + t, -L), tex(s["far_tex"], SURFACE["far_end"])))
    else:
        # A hall (open end) or the outdoors (glass) beyond; the walls stop at z = -L.
        hw, hh, hd = w2 + rng_hall(s, 0), h + rng_hall(s, 1), rng_hall(s, 2)
        if far == "glass":
            sky = tex("texture { pigment { gradient y color_map { [0 %s] [1 %s] } scale %.2f } finish { ambient %.2f diffuse 0 } }"
                      % (rgb([c * 0.8 for c in s["outdoor"]]), rgb(s["outdoor"]), h + 6, 1.0 / max(0.4, s["ambient"])),
                      SURFACE["beyond"])
            out.append("box { %s, %s %s }\n" % (v3(-w2 - 60, -0.1, -L - 40), v3(w2 + 60, 40, -L - 40.5), sky))
            out.append("box { %s, %s %s }\n" % (v3(-w2 - 60, -0.05, -L - 0.01), v3(w2 + 60, 0.001, -L - 40),
                                                tex("texture { pigment { granite color_map { [0 rgb 0.35] [1 rgb 0.5] } scale 0.5 } "
                                                    "finish { ambient 0.6 diffuse 0.3 } }", SURFACE["beyond"])))
            # The glass across the end, with its glazing bars (trim: not in the mask).
            glass = tex("texture { pigment { color rgbf <0.85,0.92,0.92,0.85> } finish { ambient 0 diffuse 0.05 "
                        "reflection 0.08 specular 0.6 roughness 0.005 } }", SURFACE["far_end"])
            out.append("box { %s, %s %s no_shadow }\n" % (v3(-w2 - 0.01, -0.01, -L), v3(w2 + 0.01, h + 0.01, -L - 0.02), glass))
            bar = "texture { pigment { color rgb 0.12 } finish { ambient 0.1 specular 0.3 } }"
            out.append("#if (!Mask)\n")
            for i in range(1, s["glass_bays"]):
                x = -w2 + 2 * w2 * i / s["glass_bays"]
                out.append("box { %s, %s %s }\n" % (v3(x - 0.03, 0, -L + 0.04), v3(x + 0.03, h, -L - 0.06), bar))
            out.append("box { %s, %s %s }\n" % (v3(-w2, min(2.2, h - 0.1), -L + 0.04), v3(w2, min(2.2, h - 0.1) + 0.06, -L - 0.06), bar))
            out.append("#end\n")
            out.append("light_source { %s color rgb %s parallel point_at %s }\n"
                       % (v3(rng_hall(s, 3) * 10, 25, -L - 30), "<%.2f,%.2f,%.2f>" % tuple(0.5 * c for c in s["outdoor"]),
                          v3(0, 0, -L + 2)))
        else:
            hall = tex(s["hall_tex"], SURFACE["beyond"])
            out.append("box { %s, %s %s }\n" % (v3(-hw, 0, -L - hd), v3(hw, hh, -L - hd - t), hall))  # its far wall
            out.append("box { %s, %s %s }\n" % (v3(-hw - t, 0, -L), v3(-hw, hh, -L - hd), hall))
            out.append("box { %s, %s %s }\n" % (v3(hw, 0, -L), v3(hw + t, hh, -L - hd), hall))
            out.append("box { %s, %s %s }\n" % (v3(-hw - t, hh, -L), v3(hw + t, hh + t, -L - hd - t), tex(s["ceiling_tex"], SURFACE["beyond"])))
            out.append("box { %s, %s %s }\n" % (v3(-hw - t, 0, -L), v3(-w2 - t, hh + t, -L + 0.01), hall))  # its near wall
            out.append("box { %s, %s %s }\n" % (v3(w2 + t, 0, -L), v3(hw + t, hh + t, -L + 0.01), hall))
            out.append("box { %s, %s %s }\n" % (v3(-w2 - t, h + t, -L), v3(w2 + t, hh + t, -L + 0.01), hall))
            out.append("light_source { %s color rgb %.3f fade_distance %.2f fade_power 1 }\n"
                       % (v3(0, hh - 0.3, -L - hd / 2), 0.5 * s["hall_light"] * E, max(2.0, hd / 2)))
    # The near end: a wall behind the camera, the corridor running on, or a hall with the portal.
    if s["near_end"] == "closed":
        out.append("box { %s, %s %s }\n" % (v3(-w2 - t, -0.2, zn), v3(w2 + t, h + t, zn + t), tex(s["far_tex"], SURFACE["hall"])))
    elif s["near_end"] == "open":
        out.append("box { %s, %s %s }\n" % (v3(-w2 - t, -0.2, zn), v3(w2 + t, h + t, zn + t),
                                            tex("texture { pigment { rgb 0.05 } }", SURFACE["hall"])))
    else:
        hw, hh, hd = w2 + 1.5 + rng_hall(s, 4), h + rng_hall(s, 5), s["eye"][2] - zn + 3.0
        hall = tex(s["hall_tex"], SURFACE["hall"])
        pt = 0.3  # the portal wall's thickness, behind the box's mouth (the box's walls run through it)
        out.append("box { %s, %s %s }\n" % (v3(-hw, 0, zn - pt), v3(-w2 - t, hh, zn), hall))
        out.append("box { %s, %s %s }\n" % (v3(w2 + t, 0, zn - pt), v3(hw, hh, zn), hall))
        out.append("box { %s, %s %s }\n" % (v3(-w2 - t, h + t, zn - pt), v3(w2 + t, hh, zn), hall))
        out.append("box { %s, %s %s }\n" % (v3(-hw, hh, zn), v3(hw, hh + t, zn + hd), tex(s["ceiling_tex"], SURFACE["hall"])))
        out.append("box { %s, %s %s }\n" % (v3(-hw - t, 0, zn), v3(-hw, hh, zn + hd), hall))
        out.append("box { %s, %s %s }\n" % (v3(hw, 0, zn), v3(hw + t, hh, zn + hd), hall))
        out.append("box { %s, %s %s }\n" % (v3(-hw, 0, zn + hd), v3(hw, hh, zn + hd + t), hall))
        out.append("light_source { %s color rgb %.3f fade_distance 3 fade_power 1 }\n"
                   % (v3(0, hh - 0.2, zn + hd / 2), 0.4 * E))
    # Side openings: a room behind each (its walls, ceiling; the floor runs on), dimly lit.
    for o in s["openings"]:
        side, (z0, z1), (y0, y1) = o["side"], o["z"], o["y"]
        xw = side * (w2 + t)
        if o["kind"] == "opening":
            room = tex("texture { pigment { %s } finish { diffuse 0.6 ambient %.2f } }" % (rgb(o["colour"]), 0.1 + o["glow"]),
                       SURFACE["beyond"])
            xb = xw + side * o["depth"]
            out.append("box { %s, %s %s }\n" % (v3(xb, 0, z0 + 2), v3(xb + side * t, h + 0.5, z1 - 2), room))
            out.append("box { %s, %s %s }\n" % (v3(xw, 0, z0 + 2), v3(xb, h + 0.5, z0 + 2 - t), room))
            out.append("box { %s, %s %s }\n" % (v3(xw, 0, z1 - 2), v3(xb, h + 0.5, z1 - 2 + t), room))
            out.append("box { %s, %s %s }\n" % (v3(xw, h + 0.5, z0 + 2), v3(xb, h + 0.5 + t, z1 - 2), room))
            out.append("box { %s, %s %s }\n" % (v3(xw, y1, z0), v3(xw + side * 0.2, h + 0.5, z1), room))  # lintel's back
        else:
            # A window: the bright outdoors behind it, and sometimes the sun through it.
            sky = tex("texture { pigment { %s } finish { ambient %.2f diffuse 0 } }"
                      % (rgb(s["outdoor"]), 1.0 / max(0.4, s["ambient"])), SURFACE["beyond"])
            out.append("box { %s, %s %s no_shadow }\n" % (v3(xw + side * 0.6, y0 - 3, z0 + 6), v3(xw + side * 0.7, y1 + 8, z1 - 6), sky))
            if o["sun"]:
                zc = 0.5 * (z0 + z1)
                out.append("light_source { %s color rgb <%.3f,%.3f,%.3f> spotlight point_at %s radius 12 falloff 16 }\n"
                           % (v3(side * (w2 + 6), y1 + 4, zc + 2), o["sun"], 0.93 * o["sun"], 0.8 * o["sun"], v3(0, 0, zc)))
    # Skirting boards along the side walls and the far wall (trim).
    if s["skirting"]:
        sh, sc = s["skirting"]
        sk = "texture { pigment { %s } finish { diffuse 0.7 ambient 0.1 specular 0.2 } }" % rgb(sc)
        out.append("#if (!Mask)\n")
        for side in (-1, 1):
            cuts = sorted([o["z"] for o in s["openings"] if o["side"] == side and o["y"][0] == 0], key=lambda zz: -zz[0])
            z = min(zn, s["eye"][2] + 2)
            for z0, z1 in cuts + [(-L, -L)]:
                if z > z0 + 0.01:
                    out.append("box { %s, %s %s }\n" % (v3(side * w2, 0, z), v3(side * (w2 - 0.012), sh, z0), sk))
                z = z1
        if far == "closed":
            out.append("box { %s, %s %s }\n" % (v3(-w2, 0, -L), v3(w2, sh, -L + 0.012), sk))
        out.append("#end\n")
    # Lamps: panels or downlights flush with the ceiling (trim) or hanging ones; the
    # nearest few give light, the others glow only (render time).
    glow = "texture { pigment { %s } finish { ambient %.2f diffuse 0 } }" % (rgb(lc), 1.6 / max(0.4, s["ambient"]))
    out.append("#if (!Mask)\n")
    for kind, x, z in s["trim"]:
        if kind == "lamp_panel":
            out.append("box { %s, %s %s no_shadow }\n" % (v3(x - 0.3, h - 0.015, z - 0.6), v3(x + 0.3, h + 0.001, z + 0.6), glow))
        else:
            out.append("cylinder { %s, %s, 0.09 %s no_shadow }\n" % (v3(x, h - 0.01, z), v3(x, h + 0.001, z), glow))
    out.append("#end\n")
    cam_z = s["eye"][2]
    lit = sorted(s["lamps"], key=lambda p: abs(p[2] - (cam_z - 4.0)))[:5]
    for x, y, z in lit:
        out.append("light_source { %s color rgb <%.3f,%.3f,%.3f> fade_distance %.2f fade_power 1 }\n"
                   % ((v3(x, y - min(0.4, 0.15 * h), z),) + tuple(0.55 * E * c for c in lc) + (max(2.0, h - 0.5),)))
    out.append("light_source { %s color rgb %.3f shadowless }\n" % (v3(s["eye"][0], s["eye"][1] + 0.3, cam_z + 0.5), 0.18 * E))
    # The objects.
    for k, ob in enumerate(s["objects"]):
        out.append("// object %d: %s\n" % (k, ob["kind"]))
        sid = OBJECT_ID0 + k
        plain = lambda c, amb=0.1: tex("texture { pigment { %s } finish { diffuse 0.75 ambient %.2f specular 0.1 } }"
                                       % (rgb(c), amb), sid)
        kind = ob["kind"]
        for i, p in enumerate(ob["prims"]):
            if kind == "person":
                t_ = plain(ob["head"]) if p[0] == "sph" else plain(ob["legs"] if i < 2 else ob["colour"])
            elif kind == "picture":
                t_ = tex("texture { pigment { gradient y color_map { [0 %s] [0.5 %s] [1 %s] } scale %.3f translate <0,%.3f,0> } "
                         "finish { ambient 0.15 specular 0.3 } }" % (rgb(ob["colour"]), rgb(ob["colour2"]), rgb(ob["colour"]),
                                                                     ob["size_m"][1], p[1][1]), sid)
            elif kind == "plant" and p[0] == "sph":
                t_ = tex("texture { pigment { bozo color_map { [0 %s] [1 rgb <0.05,0.2,0.05>] } scale 0.08 } "
                         "normal { wrinkles 1 scale 0.05 } finish { ambient 0.1 } }" % rgb(ob["foliage"]), sid)
            elif kind == "radiator":
                t_ = tex("texture { pigment { gradient %s color_map { [0 %s] [0.7 %s] [0.7 rgb 0.2] [1 rgb 0.2] } scale 0.06 } "
                         "finish { ambient 0.1 specular 0.3 } }" % ("z", rgb(ob["colour"]), rgb(ob["colour"])), sid)
            elif kind == "sign":
                t_ = plain(ob["colour"], 0.9 if ob.get("lit") and i == 0 else 0.15)
            elif kind == "lamp" and i == 1:
                t_ = tex(glow, sid)
            else:
                t_ = plain(ob["colour"])
            out.append(prim_pov(p, t_))
    return "".join(out)


def rng_hall(s, i):
    """The hall's and the outdoors' few numbers: from the seed, but apart from the
    scene's main draw (so adding one of them does not change the other scenes)."""
    r = random.Random(s["seed"] * 1000003 + i)
    return [r.uniform(2.0, 9.0), r.uniform(0.0, 3.0), r.uniform(5.0, 18.0), r.uniform(-1, 1), r.uniform(0.0, 4.0),
            r.uniform(0.0, 2.0)][i]


# ---------------------------------------------------------------------------------
# Answers.

def homogeneous_vp(cam, d_world):
    """The vanishing point of a world direction: homogeneous pixel (unit norm, w >= 0)
    and the direction in the camera frame (x right, y up, z back)."""
    xc, yc, zc = (sum(cam.rot[k][j] * d_world[k] for k in range(3)) for j in range(3))
    f, (cu, cv) = cam.focal_px, cam.principal
    hom = [f * xc - cu * zc, -f * yc - cv * zc, -zc]
    n = math.sqrt(sum(x * x for x in hom))
    hom = [x / n for x in hom]
    if hom[2] < 0 or (hom[2] == 0 and hom[0] < 0):
        hom = [-x for x in hom]
    out = {"homogeneous_px": [round(x, 9) for x in hom], "direction_camera": [round(x, 9) for x in (xc, yc, zc)],
           "direction_model": list(d_world)}
    if abs(hom[2]) > 1e-9:
        out["px"] = [round(hom[0] / hom[2], 4), round(hom[1] / hom[2], 4)]
    return out


BOUNDARIES = {  # the four receding edges: the far corner they start at, their x and y, the two surfaces
    "left_floor": ("P3", -1, 0, ("left_wall", "floor")),
    "right_floor": ("P4", 1, 0, ("right_wall", "floor")),
    "left_ceiling": ("P1", -1, 1, ("left_wall", "ceiling")),
    "right_ceiling": ("P2", 1, 1, ("right_wall", "ceiling")),
}


def boundary_samples(s, cam, name, spacing=2.0):
    """Points along a boundary's part inside the photo, from its far corner towards the
    camera, `spacing` px apart in the image: [(model point, (u, v), True, None)] and the
    spacing. The boundary runs from the far corner to where the box ends or nears the
    camera's plane; its image is affine in inverse depth, so it is clipped to the photo
    in the image (Liang-Barsky) and sampled uniformly in inverse depth."""
    _, side, top, _ = BOUNDARIES[name]
    x, y = side * s["width"] / 2, top * s["height"]
    zf = -s["length"]
    zn = min(s["box_near"], s["eye"][2] + 50.0)
    depth = lambda z: cam.project((x, y, z))[2]
    d0, d1 = depth(zf), depth(zn)
    if d1 < 0.05:  # clip where it passes the camera's plane
        zn = zf + (0.05 - d0) / (d1 - d0) * (zn - zf)
        d1 = 0.05
    mu0, mu1 = 1 / d0, 1 / d1
    z_of = lambda mu: zf + (1 / mu - d0) / (d1 - d0) * (zn - zf) if d1 != d0 else zf
    a, b = cam.project((x, y, zf))[:2], cam.project((x, y, zn))[:2]
    t0, t1 = 0.0, 1.0
    w, h = s["size"]
    for pk, qk in ((-(b[0] - a[0]), a[0] + 0.5), (b[0] - a[0], w - 0.5 - a[0]),
                   (-(b[1] - a[1]), a[1] + 0.5), (b[1] - a[1], h - 0.5 - a[1])):
        if abs(pk) < 1e-12:
            if qk < 0:
                return [], spacing
            continue
        r = qk / pk
        if pk < 0:
            t0 = max(t0, r)
        else:
            t1 = min(t1, r)
    if t0 >= t1:
        return [], spacing
    length = (t1 - t0) * math.hypot(b[0] - a[0], b[1] - a[1])
    n = max(2, int(length / spacing))
    out = []
    for i in range(n):
        t_ = t0 + (t1 - t0) * (i + 0.5) / n
        p = (x, y, z_of(mu0 + (mu1 - mu0) * t_))
        u, v, _ = cam.project(p)
        out.append([p, (u, v), True, None])
    return out, length / n


def in_opening(s, p, side):
    """Whether a point on the wall `side` (or on its edge) lies where the wall has an opening."""
    return any(o["side"] == side and o["z"][1] <= p[2] <= o["z"][0] and o["y"][0] - 1e-9 <= p[1] <= o["y"][1] + 1e-9
               for o in s["openings"])


def pixel_on_plane(cam, u, v, axis, value):
    """The model point seen at pixel (u, v) on the plane where coordinate `axis` = value
    (None when the ray runs parallel to it or away from it)."""
    dc = ((u - cam.principal[0]) / cam.focal_px, -(v - cam.principal[1]) / cam.focal_px, -1.0)
    d = [sum(cam.rot[i][j] * dc[j] for j in range(3)) for i in range(3)]
    if abs(d[axis]) < 1e-12:
        return None
    t = (value - cam.eye[axis]) / d[axis]
    return None if t <= 0 else tuple(cam.eye[i] + t * d[i] for i in range(3))


def boundary_shown(s, cam, name, p, offset_px=1.5):
    """Whether a boundary point shows: the point itself and the two surfaces beside it,
    offset_px to each side of its image (where those pixels' rays meet the wall and the
    floor or ceiling), all seen: no object before them, no opening in the wall there."""
    _, side, top, _ = BOUNDARIES[name]
    if in_opening(s, p, side) or occluded(s["eye"], p, s["objects"]):
        return False
    u, v, _ = cam.project(p)
    u2, v2, _ = cam.project((p[0], p[1], p[2] - 0.01))
    n = math.hypot(u2 - u, v2 - v) or 1.0
    nx, ny = -(v2 - v) / n, (u2 - u) / n
    wu, wv, _ = cam.project((p[0], p[1] + (0.05 if top == 0 else -0.05), p[2]))
    ws = 1 if (wu - u) * nx + (wv - v) * ny > 0 else -1  # the wall's side of the line in the image
    on_wall = pixel_on_plane(cam, u + ws * offset_px * nx, v + ws * offset_px * ny, 0, p[0])
    on_plane = pixel_on_plane(cam, u - ws * offset_px * nx, v - ws * offset_px * ny, 1, p[1])
    if on_wall is None or on_plane is None or in_opening(s, on_wall, side):
        return False
    return not any(occluded(s["eye"], q, s["objects"]) for q in (on_wall, on_plane))


def opening_corners_px(cam, s, o):
    """An opening's corners in the photo: bottom and top at its larger z, top and bottom at
    its smaller (null where one is behind the camera)."""
    x = o["side"] * s["width"] / 2
    (za, zb), (ya, yb) = sorted(o["z"]), o["y"]
    out = []
    for y, z in ((ya, zb), (yb, zb), (yb, za), (ya, za)):
        u, v, depth = cam.project((x, y, z))
        if depth <= 0.01:
            return None
        out.append([round(u, 3), round(v, 3)])
    return out


def answers(s):
    w, h = s["size"]
    cam = Camera(s["eye"], s["ypr"], s["size"], s["focal_px"], s["principal"])
    w2, H, L = s["width"] / 2, s["height"], s["length"]
    pts = [(-w2, H, -L), (w2, H, -L), (-w2, 0, -L), (w2, 0, -L), (-w2, 0, 0), (w2, 0, 0), (-w2, H, 0), (w2, H, 0)]
    corners, hidden, in_frame = {}, {}, {}
    for name, p in zip(CORNERS, pts):
        u, v, depth = cam.project(p)
        assert depth > 0
        corners[name] = [round(u, 6), round(v, 6)]
        in_frame[name] = in_photo((u, v), s["size"], 0.0)
        if name in ("P1", "P2", "P3", "P4"):
            hidden[name] = occluded(s["eye"], p, s["objects"])
    short = min(w, h)
    bounds, showing = {}, 0
    for name, (corner, side, top, surfaces) in BOUNDARIES.items():
        samples, step = boundary_samples(s, cam, name)
        inside = shown = 0
        for smp in samples:
            if smp[2]:
                inside += 1
                smp[3] = boundary_shown(s, cam, name, smp[0])
                shown += smp[3]
        share = shown / inside if inside else 0.0
        bounds[name] = {"from": corner, "surfaces": list(surfaces), "inside_px": round(inside * step, 1),
                        "shown_px": round(shown * step, 1), "shown_share": round(share, 4)}
        if share >= 0.25 and shown * step >= 0.05 * short:
            showing += 1
    far_in = all(in_frame[c] for c in ("P1", "P2", "P3", "P4"))
    objects = []
    for k, ob in enumerate(s["objects"]):
        kp = {}
        for name, p in ob["keypoints_m"].items():
            u, v, depth = cam.project(p)
            kp[name] = [round(u, 3), round(v, 3)] if depth > 0 else None
        objects.append({"id": k, "mask_id": OBJECT_ID0 + k, "kind": ob["kind"], "size_m": ob["size_m"],
                        "place_m": ob["place_m"], "on": ob["on"],
                        "keypoints_m": {n: [round(x, 4) for x in p] for n, p in ob["keypoints_m"].items()},
                        "keypoints_px": kp})
    base = "seed_%05d" % s["seed"]
    return {
        "name": base, "image": base + ".png", "image_noisy": base + "_q70n3.jpg", "image_size": [w, h],
        "orientation": "portrait" if h > w else "landscape",
        "pixel_convention": "pixel centers at integer coordinates (OpenCV)",
        "generator": "tests/groundtruth/random_corridors.py", "seed": s["seed"],
        "focal_px": round(s["focal_px"], 6), "lens_mm_35mm_equivalent": round(s["lens_mm"], 3),
        "principal_point": [round(x, 6) for x in s["principal"]],
        "camera_height_m": round(s["eye"][1], 6), "camera_offset_x_m": round(s["eye"][0], 6),
        "camera_position_m": [round(x, 6) for x in s["eye"]],
        "yaw_deg": round(s["ypr"][0], 6), "pitch_deg": round(s["ypr"][1], 6), "roll_deg": round(s["ypr"][2], 6),
        "width_m": round(s["width"], 6), "height_m": round(s["height"], 6), "length_m": round(L, 6),
        "far_wall_distance_m": round(s["eye"][2] + L, 6), "near_corners_distance_m": round(s["eye"][2], 6),
        "near_cross_section": "P5..P8: the nearest cross-section whose four corners are all inside the photo, "
                              "%g of the short side from its border (no mark on it)" % NEAR_MARGIN,
        "far_end": s["far_end"], "near_end": s["near_end"],
        "box_near_end_z_m": round(s["box_near"], 4),
        "corners_px": corners, "corners_m": dict(zip(CORNERS, [list(p) for p in pts])), "planes": PLANES,
        "far_corners_in_frame": {c: in_frame[c] for c in ("P1", "P2", "P3", "P4")},
        "far_corners_hidden": hidden,
        "hidden_test": "ray cast from the camera against the objects' boxes, cylinders and spheres (trim excluded)",
        "boundaries": bounds,
        "box_visible": far_in and showing >= 3,
        "box_visible_rule": "P1..P4 inside the photo and >= 3 of the 4 boundaries shown over >= 25% of their "
                            "in-photo length and >= 5% of the short side",
        "vanishing_points": {"corridor": homogeneous_vp(cam, (0, 0, -1)), "horizontal": homogeneous_vp(cam, (1, 0, 0)),
                             "vertical": homogeneous_vp(cam, (0, 1, 0))},
        "vanishing_point_frame": "camera frame x right, y up, z back (looking along -z); homogeneous pixels (u w, v w, w)",
        "materials": {"walls": s["walls_kind"], "floor": s["floor_kind"], "ceiling": s["ceiling_kind"],
                      "skirting": bool(s["skirting"]), "lamps": s["lamp_style"]},
        "openings": [dict({"kind": o["kind"], "wall": "left_wall" if o["side"] < 0 else "right_wall",
                           "z_m": [round(x, 4) for x in o["z"]], "y_m": [round(x, 4) for x in o["y"]],
                           "corners_px": opening_corners_px(cam, s, o)},
                          **({"room_depth_m": round(o["depth"], 4)} if o["kind"] == "opening" else {}))
                     for o in s["openings"]],
        "objects": objects,
    }


# ---------------------------------------------------------------------------------
# Files.

def write_atomic(path, data, mode="w"):
    tmp = path + ".tmp"
    with open(tmp, mode) as f:
        f.write(data)
    os.replace(tmp, path)


def povray(pov, out, size, extra, threads):
    """nice'd povray into a temporary file, renamed into place when it succeeded."""
    w, h = size
    fd, tmp = tempfile.mkstemp(suffix=os.path.splitext(out)[1], dir=os.path.dirname(os.path.abspath(out)))
    os.close(fd)
    cmd = ["nice", "-n", "10", "povray", "+I" + os.path.abspath(pov), "+O" + tmp, "+W%d" % w, "+H%d" % h, "-D", "-GA",
           "+WT%d" % threads] + extra
    r = run_povray(cmd, os.path.dirname(os.path.abspath(out)))
    if r.returncode != 0 or os.path.getsize(tmp) == 0:
        os.unlink(tmp)
        raise RuntimeError("povray failed on %s: %s" % (pov, (r.stderr or r.stdout).strip().splitlines()[-3:]))
    os.replace(tmp, out)


def noisy_jpeg(png, jpg, seed):
    """The photo with Gaussian sensor noise (sigma 3 grey levels, per channel) and then
    JPEG quality 70 (PIL's default 4:2:0 chroma subsampling); the noise seeded by the seed."""
    try:
        import numpy as np
        from PIL import Image
    except ImportError:
        # CMake's Python may be another one than Debian's, which has python3-numpy and python3-pil.
        if os.path.exists("/usr/bin/python3") and os.path.realpath(sys.executable) != os.path.realpath("/usr/bin/python3"):
            subprocess.run(["/usr/bin/python3", os.path.abspath(__file__), "noisy", png, jpg, str(seed)], check=True)
            return
        raise SystemExit("random_corridors: the noisy JPEG needs python3-numpy and python3-pil (scripts/install-deps.sh)")
    img = np.asarray(Image.open(png).convert("RGB"), dtype=np.float64)
    img = img + np.random.default_rng(seed).normal(0.0, 3.0, img.shape)
    out = Image.fromarray(np.clip(np.rint(img), 0, 255).astype(np.uint8))
    tmp = jpg + ".tmp"
    out.save(tmp, format="JPEG", quality=70)
    os.replace(tmp, jpg)


def make_one(seed, outdir, size_scale=1.0, render=True, mask=False, threads=2):
    """Writes one seed's files; returns the seconds its photo's render took (0 without)."""
    s = make_scene(seed, size_scale)
    base = os.path.join(outdir, "seed_%05d" % seed)
    write_atomic(base + ".pov", scene_pov(s))
    write_atomic(base + ".json", json.dumps(answers(s), indent=1) + "\n")
    took = 0.0
    if render:
        t0 = time.time()
        # +A0.3: adaptive anti-aliasing (fixed jitter seed: the same pixels every time).
        povray(base + ".pov", base + ".png", s["size"], ["+FN8", "+A0.3"], threads)
        took = time.time() - t0
        noisy_jpeg(base + ".png", base + "_q70n3.jpg", seed)
    if mask:
        # One ray through each pixel centre, flat colours, written with gamma 1.
        povray(base + ".pov", base + "_mask.ppm", s["size"], ["+FP", "-A", "Declare=Mask=1", "File_Gamma=1.0"], threads)
    return took


# Cameras the photo was not taken from, in the model frame (make_corridors.py's kinds):
# mid-corridor looking ahead; a quarter in, turned 35 degrees to the left wall; near the
# far end, looking back. At the photo's eye height, on the centre line, where a person
# could stand: a place within VIEW_CLEARANCE_M of a free-standing or hanging object's box
# (a person, a cabinet, a hanging lamp at eye height) moves along the corridor to the
# nearest clear one (until 2026-12-05 it did not: 119 of TUNE 0-599's 1800 views stood
# in or against an object, 15 inside one, and POV-Ray's frame was the object's inside).
NOVEL_VIEW_WIDTH = 640
VIEW_CLEARANCE_M = 0.5


def clear_eye(s, eye):
    """The nearest eye along the corridor (z) to `eye` that is VIEW_CLEARANCE_M or more from
    every object not on a wall, kept 0.3 m inside the box's far end and before its near end."""
    boxes = []
    for ob in s["objects"]:
        if ob["on"] in ("left_wall", "right_wall", "far_wall"):
            continue
        (w, h, d), (x, y, z) = ob["size_m"], ob["place_m"]
        boxes.append((x, z, w / 2 + VIEW_CLEARANCE_M, d / 2 + VIEW_CLEARANCE_M, y - 0.1, y + h + 0.1))

    def clear(z):
        return not any(abs(eye[0] - x) <= hx and abs(z - bz) <= hz and y0 <= eye[1] <= y1 for x, bz, hx, hz, y0, y1 in boxes)

    lo, hi = -s["length"] + 0.3, min(s["box_near"], 0.0) - 0.3
    for step in range(0, 121):
        for z in (eye[2] + 0.05 * step, eye[2] - 0.05 * step):
            if lo <= z <= hi and clear(z):
                return [eye[0], eye[1], z]
    return eye


NOVEL_VIEWS = {
    "ahead": lambda s: (clear_eye(s, [0.0, s["eye"][1], -s["length"] / 2.0]), [0.0, 0.0, 0.0]),
    "turned": lambda s: (clear_eye(s, [0.0, s["eye"][1], -s["length"] / 4.0]), [35.0, 0.0, 0.0]),
    "back": lambda s: (clear_eye(s, [0.0, s["eye"][1], -s["length"] + 1.0]), [180.0, 0.0, 0.0]),
}


def make_views(seed, outdir, threads=2):
    """Renders the seed's novel views into outdir (each only when its .pov changed)."""
    s = make_scene(seed)
    photo_cam = Camera(s["eye"], s["ypr"], s["size"], s["focal_px"], s["principal"])
    pov = scene_pov(s)
    if photo_cam.pov(0.0) not in pov:
        raise RuntimeError("seed %d: the scene's camera block is not where views expect it" % seed)
    w, h = s["size"]
    vw = NOVEL_VIEW_WIDTH
    vh = int(round(vw * h / w / 2)) * 2
    for kind, place in NOVEL_VIEWS.items():
        eye, ypr = place(s)
        cam = Camera(eye, ypr, (vw, vh), s["focal_px"] * vw / w)
        base = os.path.join(outdir, "seed_%05d_view_%s" % (seed, kind))
        view_pov = pov.replace(photo_cam.pov(0.0), cam.pov(0.0), 1)
        same = os.path.exists(base + ".png") and os.path.exists(base + ".pov") and open(base + ".pov").read() == view_pov
        if not same:
            write_atomic(base + ".pov", view_pov)
            povray(base + ".pov", base + ".png", (vw, vh), ["+FN8", "+A0.3"], threads)
        write_atomic(base + ".json", json.dumps({"scene": "seed_%05d" % seed, "image_size": [vw, vh], "focal_px": cam.focal_px,
                                                 "principal_point": cam.principal, "eye_m": cam.eye, "yaw_deg": ypr[0],
                                                 "pitch_deg": ypr[1], "roll_deg": ypr[2]}, indent=1) + "\n")


# The objects a person stands up by default (bench/standing_views.py, the groundtruth
# target): the floor's free-standing ones.
STANDING_KINDS = {"person", "plant", "bin"}
# Kinds stood up as boxes when asked for (standing_views.py --kinds ...,cabinet).
BOX_KINDS = {"cabinet"}
# Kinds hung from the ceiling when asked for (--kinds ...,lamp,sign): those on the ceiling
# (a lamp on a rod, a sign; a sign on a wall is left painted).
HANGING_KINDS = {"lamp", "sign"}
STANDING_MIN_PIXELS = 150
STANDING_MARGIN_PX = 4


def read_mask_ids(path):
    """(width, height, the id of every pixel) of a mask render (a binary PPM)."""
    with open(path, "rb") as f:
        data = f.read()
    tokens, pos = [], 0
    while len(tokens) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        tokens.append(data[pos:end])
        pos = end
    w, h = int(tokens[1]), int(tokens[2])
    pix = data[pos + 1:pos + 1 + 3 * w * h]
    return w, h, [mask_id(pix[3 * i], pix[3 * i + 1]) for i in range(w * h)]


OPENING_MIN_AREA_PX = 400


def convex_hull(points):
    """The convex hull of 2D points, counter-clockwise (Andrew's monotone chain)."""
    pts = sorted(set(points))
    if len(pts) < 3:
        return pts

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def polygon_area(poly):
    """The area of a simple polygon (shoelace); 0 for fewer than three points."""
    if len(poly) < 3:
        return 0.0
    return 0.5 * abs(sum(poly[k][0] * poly[k - 1][1] - poly[k - 1][0] * poly[k][1] for k in range(len(poly))))


def opening_outlines(ans):
    """A cutout of shape "opening" for each side opening (a room beyond, not a window) the
    photo shows over OPENING_MIN_AREA_PX: the outline of the part of it inside the photo, as a
    person clicks a doorway's corners (where the opening runs off the photo, along the
    photo's edge)."""
    w, h = ans["image_size"]
    cam = Camera(ans["camera_position_m"], [ans["yaw_deg"], ans["pitch_deg"], ans["roll_deg"]], (w, h),
                 ans["focal_px"], ans["principal_point"])
    out = []
    for i, o in enumerate(ans["openings"]):
        if o["kind"] != "opening":
            continue
        x = ans["width_m"] / 2 * (-1 if o["wall"] == "left_wall" else 1)
        (za, zb), (ya, yb) = sorted(o["z_m"]), o["y_m"]
        n = 60
        pts = []
        for i_z in range(n + 1):
            for i_y in range(n + 1):
                u, v, depth = cam.project([x, ya + (yb - ya) * i_y / n, za + (zb - za) * i_z / n])
                if depth > 0.05 and 0 <= u <= w - 1 and 0 <= v <= h - 1:
                    pts.append((round(u, 2), round(v, 2)))
        hull = convex_hull(pts)
        if polygon_area(hull) < OPENING_MIN_AREA_PX:
            continue
        out.append({"name": "opening_%d" % i, "outline_px": [list(p) for p in hull], "shape": "opening"})
    return out


def write_standing(seed, outdir, kinds=STANDING_KINDS):
    """Writes seed_NNNNN_standing.json beside the seed's files (its .json and _mask.ppm):
    the shot with a cutout for each object of `kinds` the photo shows over 150 px with its
    foot in view (its rectangle not reaching the photo's bottom edge, nor cut off above its footprint's middle
    by another object before it) on the corridor's floor, a rectangle 4 px beyond its pixels in the mask, as a
    person draws one around it. No such object: no file (a stale one is removed).
    Returns the number of cutouts."""
    base = os.path.join(outdir, "seed_%05d" % seed)
    with open(base + ".json") as f:
        ans = json.load(f)
    w, h = ans["image_size"]
    ids = read_mask_ids(base + "_mask.ppm")[2] if set(kinds) - {"opening"} else []
    boxes = {}
    for i, v in enumerate(ids):
        if v >= OBJECT_ID0:
            u, y = i % w, i // w
            b = boxes.setdefault(v, [u, y, u, y, 0])
            b[0], b[1], b[2], b[3], b[4] = min(b[0], u), min(b[1], y), max(b[2], u), max(b[3], y), b[4] + 1
    cutouts = []
    for ob in ans["objects"]:
        b = boxes.get(ob["mask_id"])
        if ob["on"] == "ceiling":  # a lamp on a rod, a sign: hanging, its top (where it hangs) in view
            if ob["kind"] in kinds and b and b[4] >= STANDING_MIN_PIXELS and b[1] - STANDING_MARGIN_PX > 0:
                m = STANDING_MARGIN_PX
                x0, y0, x1, y1 = max(0, b[0] - m), b[1] - m, min(w - 1, b[2] + m), min(h - 1, b[3] + m)
                cutouts.append({"name": "%s_%d" % (ob["kind"], ob["id"]), "shape": "hanging",
                                "outline_px": [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]})
            continue
        if ob["kind"] not in kinds or ob["kind"] in HANGING_KINDS or not b or b[4] < STANDING_MIN_PIXELS or \
                b[3] + STANDING_MARGIN_PX >= h - 1:
            continue
        kp = ob["keypoints_px"]
        foot = kp.get("feet") or kp.get("base") or max((p for k, p in kp.items() if "bottom" in k), key=lambda p: p[1])
        if b[3] < foot[1] - 1:
            continue
        x, _, z = ob["place_m"]  # on this corridor's floor (not in a hall beyond its end)
        if abs(x) > ans["width_m"] / 2 or z < -ans["length_m"]:
            continue
        m = STANDING_MARGIN_PX
        x0, y0, x1, y1 = max(0, b[0] - m), max(0, b[1] - m), min(w - 1, b[2] + m), min(h - 1, b[3] + m)
        cutout = {"name": "%s_%d" % (ob["kind"], ob["id"]), "outline_px": [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]}
        if ob["kind"] in BOX_KINDS:
            cutout["shape"] = "box"
        cutouts.append(cutout)
    if "opening" in kinds:
        cutouts += opening_outlines(ans)
    standing = base + "_standing.json"
    if cutouts:
        shot = dict(ans)
        shot["cutouts"] = cutouts
        write_atomic(standing, json.dumps(shot, indent=1) + "\n")
    elif os.path.exists(standing):
        os.unlink(standing)
    return len(cutouts)


def cmd_standing(args):
    print("%d cutouts" % write_standing(args.seed, args.out))


def cmd_views(args):
    os.makedirs(args.out, exist_ok=True)
    make_views(args.seed, args.out)


def cmd_scene(args):
    os.makedirs(args.out, exist_ok=True)
    took = make_one(args.seed, args.out, args.size_scale, not args.no_render, args.mask)
    if took:
        print("seed %d rendered in %.1f s" % (args.seed, took))


def cmd_range(args):
    os.makedirs(args.out, exist_ok=True)
    seeds = list(range(args.first, args.last + 1))
    t0 = time.time()
    threads = 1 if args.jobs > 1 else 2
    with ThreadPoolExecutor(args.jobs) as pool:
        times = list(pool.map(lambda sd: make_one(sd, args.out, args.size_scale, not args.no_render, args.mask, threads), seeds))
    if not args.no_render:
        print("%d scenes in %.1f s wall; mean render %.1f s per scene (%d at a time)"
              % (len(seeds), time.time() - t0, sum(times) / len(times), args.jobs))


def main():
    if len(sys.argv) == 5 and sys.argv[1] == "noisy":  # internal: noisy_jpeg in Debian's Python
        noisy_jpeg(sys.argv[2], sys.argv[3], int(sys.argv[4]))
        return
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("scene")
    p.add_argument("seed", type=int)
    p.add_argument("out")
    p.set_defaults(func=cmd_scene)
    r = sub.add_parser("range")
    r.add_argument("first", type=int)
    r.add_argument("last", type=int)
    r.add_argument("out")
    r.add_argument("-j", "--jobs", type=int, default=1)
    r.set_defaults(func=cmd_range)
    v = sub.add_parser("views")
    v.add_argument("seed", type=int)
    v.add_argument("out")
    v.set_defaults(func=cmd_views)
    st = sub.add_parser("standing")
    st.add_argument("seed", type=int)
    st.add_argument("out")
    st.set_defaults(func=cmd_standing)
    for q in (p, r):
        q.add_argument("--size-scale", type=float, default=1.0)
        q.add_argument("--no-render", action="store_true")
        q.add_argument("--mask", action="store_true", help="also render the flat-colour id mask (NAME_mask.ppm)")
    args = parser.parse_args()
    args.func(args)


if __name__ == "__main__":
    main()
