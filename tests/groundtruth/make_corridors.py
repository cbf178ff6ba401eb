#!/usr/bin/env python3
"""photowalk's own ground truth: POV-Ray corridor scenes with exact answers.

usage:
  make_corridors.py scenes OUTDIR [--only NAME,...] [--no-render]
      writes NAME.pov, NAME.json (shot part + answers, the form of ../shared/corridors)
      and renders NAME.png with povray for every scene below. A scene whose .pov is
      unchanged and whose .png is there is not rendered again.
  make_corridors.py views OUTDIR [--only NAME,...]
      renders every clean corridor (corridor_*) from the novel-view cameras below (NOVEL_VIEWS: cameras the
      photo was not taken from) as NAME_view_KIND.png with NAME_view_KIND.json (the
      camera, as `view` writes it); unchanged .pov files are not rendered again.
  make_corridors.py view NAME OUT.png --eye X Y Z [--ypr YAW PITCH ROLL] [--size WxH]
                         [--focal-px F]
      renders scene NAME from another camera, given in the model frame (README:
      "Coordinate conventions"; angles as `photowalk measure` reports them), and
      writes OUT.png with OUT.json (the camera).

The answers are computed here, by a projection written for this file alone (no
photowalk code), from the same numbers that place the POV-Ray camera:
  model frame: right-handed, Y up, metres; floor y = 0; near end (the plane of P5..P8)
  at z = 0; far wall at z = -length; x from -width/2 to +width/2.
  POV-Ray frame: left-handed, the same x and y, Z = near_corners_distance - z (the
  photo's camera stands at POV-Ray's Z = 0 before its offset).
  camera: worldFromCamera = Ry(yaw) Rx(pitch) Rz(roll) (columns right, up, back);
  pixel centres at integer coordinates, u right, v down.
"""
import argparse, json, math, os, shutil, subprocess, sys, tempfile, time

# Materials. Each is a POV-Ray texture for a wall, floor or ceiling plane.
MATERIALS = {
    "brick": "texture { pigment { brick color rgb <0.82,0.80,0.74> color rgb <0.55,0.24,0.18> "
             "brick_size <0.25,0.075,0.125> mortar 0.012 } finish { diffuse 0.8 ambient 0.12 } }",
    "granite": "texture { pigment { granite color_map { [0 color rgb <0.78,0.80,0.72>] [1 color rgb <0.70,0.74,0.66>] } "
               "scale 0.3 } finish { diffuse 0.8 ambient 0.12 } }",
    "checker_tile": "texture { pigment { checker color rgb <0.85,0.85,0.88> color rgb <0.55,0.62,0.75> scale 0.3 } "
                    "finish { diffuse 0.8 ambient 0.12 } }",
    "checker_floor": "texture { pigment { checker color rgb <0.82,0.80,0.74> color rgb <0.25,0.25,0.30> scale 0.5 } "
                     "finish { diffuse 0.8 ambient 0.12 } }",
    "wood_floor": "texture { pigment { wood color_map { [0 color rgb <0.55,0.35,0.2>] [1 color rgb <0.35,0.2,0.1>] } "
                  "turbulence 0.1 scale <0.05,0.05,1> } finish { diffuse 0.8 ambient 0.12 } }",
    "stone_floor": "texture { pigment { granite color_map { [0 color rgb 0.5] [0.5 color rgb 0.7] [1 color rgb 0.4] } "
                   "scale 0.2 } finish { diffuse 0.8 ambient 0.12 } }",
    # Square glazed tiles with grout lines, 0.2 m, rows offset by half a tile.
    "tile": "texture { pigment { brick color rgb <0.45,0.45,0.47> color rgb <0.86,0.88,0.90> "
            "brick_size <0.2,0.2,0.2> mortar 0.01 } finish { diffuse 0.8 ambient 0.12 } }",
    # Horizontal wood boards 0.14 m high with dark gaps, the grain along the corridor.
    "wood_boards": "texture { pigment { wood color_map { [0 color rgb <0.62,0.42,0.24>] [0.6 color rgb <0.50,0.32,0.17>] "
                   "[1 color rgb <0.40,0.24,0.12>] } turbulence 0.06 scale <0.03,0.03,1> } finish { diffuse 0.8 ambient 0.12 } } "
                   "texture { pigment { gradient y color_map { [0 color rgbt <0.18,0.10,0.05,0>] [0.07 color rgbt <0.18,0.10,0.05,0>] "
                   "[0.07 color rgbt 1] [1 color rgbt 1] } scale 0.14 } }",
    # Smooth painted plaster: a faint mottling and a little surface relief.
    "plaster": "texture { pigment { bozo color_map { [0 color rgb <0.86,0.83,0.77>] [1 color rgb <0.78,0.75,0.70>] } "
               "scale 0.08 } normal { granite 0.08 scale 0.3 } finish { diffuse 0.8 ambient 0.12 } }",
    "ceiling": "texture { pigment { color rgb <0.92,0.92,0.9> } finish { diffuse 0.7 ambient 0.25 } }",
    "far_wall": "texture { pigment { color rgb <0.52,0.56,0.50> } finish { diffuse 0.7 ambient 0.10 } }",
    # A pale corridor: walls, floor, ceiling and far wall a few grey levels apart.
    "pale_wall": "texture { pigment { bozo color_map { [0 color rgb <0.84,0.83,0.80>] [1 color rgb <0.81,0.80,0.77>] } "
                 "scale 0.1 } finish { diffuse 0.75 ambient 0.2 } }",
    "pale_floor": "texture { pigment { granite color_map { [0 color rgb <0.80,0.79,0.75>] [1 color rgb <0.74,0.73,0.70>] } "
                  "scale 0.3 } finish { diffuse 0.75 ambient 0.2 } }",
    "pale_ceiling": "texture { pigment { color rgb <0.88,0.88,0.86> } finish { diffuse 0.7 ambient 0.25 } }",
    "pale_far": "texture { pigment { color rgb <0.80,0.80,0.77> } finish { diffuse 0.7 ambient 0.2 } }",
}

# The scenes. a-e are the shared corridors' numbers (camera straight down the
# corridor); f-h turn the camera, move it off centre and, for h, off the image centre.
SCENES = [
    dict(name="corridor_a", size=(800, 600), focal_px=692.820323, width=2.4, height=2.8, length=9.5, near=4.5,
         eye_x=0.0, eye_y=1.5, walls="brick", floor="checker_floor", fill_y=1.68),
    dict(name="corridor_b", size=(1024, 768), focal_px=803.679015, width=3.0, height=3.2, length=14.5, near=5.5,
         eye_x=0.4, eye_y=1.6, walls="granite", floor="wood_floor", fill_y=1.92),
    dict(name="corridor_c", size=(800, 600), focal_px=768.392851, width=1.8, height=2.5, length=5.0, near=4.0,
         eye_x=-0.2, eye_y=1.2, walls="checker_tile", floor="stone_floor", fill_y=1.5),
    dict(name="corridor_d", size=(1280, 720), focal_px=914.014724, width=4.0, height=3.5, length=19.0, near=6.0,
         eye_x=0.8, eye_y=1.7, walls="brick", floor="checker_floor", fill_y=2.1),
    dict(name="corridor_e", size=(960, 720), focal_px=625.548179, width=2.2, height=2.6, length=26.0, near=4.0,
         eye_x=0.0, eye_y=1.4, walls="granite", floor="checker_floor", fill_y=1.56),
    dict(name="corridor_f", size=(960, 640), focal_px=700.0, width=2.6, height=2.9, length=12.0, near=5.0,
         eye_x=-0.3, eye_y=1.55, yaw=7.0, pitch=-4.0, walls="wood_boards", floor="tile", fill_y=1.8),
    dict(name="corridor_g", size=(800, 600), focal_px=640.0, width=2.0, height=2.7, length=8.0, near=4.5,
         eye_x=0.25, eye_y=1.45, pitch=5.0, roll=4.0, walls="tile", floor="stone_floor", fill_y=1.7),
    dict(name="corridor_h", size=(1024, 768), focal_px=760.0, width=3.2, height=3.0, length=16.0, near=6.0,
         eye_x=0.5, eye_y=1.65, yaw=-9.0, pitch=3.0, roll=-6.0, principal=(541.5, 360.0),
         walls="plaster", floor="wood_floor", fill_y=1.9),
]

# Cameras the photo was not taken from (issue 14's novel views), in the model frame, at
# the photo's height on the corridor's centre line; 640 px wide, the photo's field of view.
NOVEL_VIEW_WIDTH = 640
NOVEL_VIEWS = {
    "ahead": lambda s: ([0.0, s["eye_y"], -s["length"] / 2.0], [0.0, 0.0, 0.0]),  # mid-corridor, looking ahead
    "turned": lambda s: ([0.0, s["eye_y"], -s["length"] / 4.0], [35.0, 0.0, 0.0]),  # a quarter in, 35 deg to the left wall
    "back": lambda s: ([0.0, s["eye_y"], -s["length"] + 1.0], [180.0, 0.0, 0.0]),  # near the far wall, looking back
}

# Cluttered corridors (issue 15): what people's photos have along the walls. Each is a
# box corridor like those above, furnished by furnish() from its seed: cabinets,
# benches, people (a cylinder and a sphere), posters, side doors, ceiling lamps of
# uneven brightness and a patch of light on a wall; some with the camera rolled, one
# with clutter before the far wall, one pale with little contrast. The answers are the
# room's corners as before: clutter hides some of them, it does not move them.
CLUTTER_SCENES = [
    dict(name="clutter_1", size=(800, 600), focal_px=660.0, width=2.6, height=2.8, length=11.0, near=4.5,
         eye_x=0.2, eye_y=1.55, walls="plaster", floor="tile", fill_y=1.7, seed=1,
         kinds=("cabinet", "cabinet", "person", "poster", "poster", "door", "lamp")),
    dict(name="clutter_2", size=(800, 600), focal_px=700.0, width=3.0, height=3.0, length=14.0, near=5.0,
         eye_x=-0.3, eye_y=1.6, roll=6.0, walls="brick", floor="wood_floor", fill_y=1.8, seed=2,
         kinds=("bench", "bench", "person", "person", "poster", "door", "lamp")),
    dict(name="clutter_3", size=(960, 640), focal_px=720.0, width=2.4, height=2.7, length=9.0, near=4.0,
         eye_x=0.0, eye_y=1.5, roll=-10.0, walls="granite", floor="checker_floor", fill_y=1.6, seed=3,
         kinds=("cabinet", "person", "poster", "poster", "door", "door", "lamp")),
    dict(name="clutter_4", size=(800, 600), focal_px=640.0, width=3.4, height=3.2, length=16.0, near=5.5,
         eye_x=0.5, eye_y=1.65, yaw=5.0, pitch=-3.0, roll=10.0, walls="wood_boards", floor="stone_floor",
         fill_y=1.9, seed=4, kinds=("cabinet", "cabinet", "bench", "person", "person", "poster", "lamp")),
    dict(name="clutter_5", size=(800, 600), focal_px=680.0, width=2.2, height=2.6, length=10.0, near=4.0,
         eye_x=-0.2, eye_y=1.45, walls="tile", floor="wood_floor", fill_y=1.6, seed=5, far_clutter=True,
         kinds=("cabinet", "person", "person", "poster", "door", "lamp")),
    dict(name="clutter_6", size=(960, 640), focal_px=760.0, width=2.8, height=3.0, length=18.0, near=6.0,
         eye_x=0.3, eye_y=1.7, pitch=4.0, roll=-7.0, walls="plaster", floor="checker_floor", fill_y=1.9, seed=6,
         kinds=("bench", "cabinet", "person", "person", "person", "poster", "poster", "lamp")),
    dict(name="clutter_7", size=(800, 600), focal_px=620.0, width=2.0, height=2.6, length=8.0, near=4.0,
         eye_x=0.1, eye_y=1.4, yaw=-6.0, roll=4.0, walls="brick", floor="tile", fill_y=1.6, seed=7,
         kinds=("cabinet", "cabinet", "poster", "door", "door", "lamp")),
    dict(name="clutter_8", size=(800, 600), focal_px=700.0, width=3.2, height=3.0, length=20.0, near=5.0,
         eye_x=-0.4, eye_y=1.6, roll=-4.0, walls="granite", floor="wood_floor", fill_y=1.8, seed=8, far_clutter=True,
         kinds=("bench", "cabinet", "person", "person", "poster", "poster", "door", "lamp")),
    dict(name="clutter_9", size=(800, 600), focal_px=650.0, width=2.6, height=2.8, length=12.0, near=4.5,
         eye_x=0.2, eye_y=1.5, roll=5.0, walls="pale_wall", floor="pale_floor", ceiling="pale_ceiling",
         far_wall="pale_far", fill_y=1.7, seed=9, kinds=("cabinet", "person", "poster", "lamp")),
]
CLUTTER_COLOURS = [(0.62, 0.45, 0.30), (0.30, 0.36, 0.48), (0.70, 0.70, 0.66), (0.25, 0.25, 0.27), (0.55, 0.20, 0.18),
                   (0.35, 0.50, 0.35), (0.80, 0.72, 0.50), (0.15, 0.20, 0.35)]


def furnish(s):
    """The scene's clutter from its seed and kinds, in the model frame (metres): each
    item a dict with its kind, the wall it stands against (side -1 left, +1 right) and
    its extent along the corridor (z0 > z1, both between the far wall and the near end)."""
    import random
    rng = random.Random(s["seed"])
    w2, h, l = s["width"] / 2.0, s["height"], s["length"]
    items, gains = [], [rng.uniform(0.5, 1.5) for _ in range(4)]
    colour = lambda: CLUTTER_COLOURS[rng.randrange(len(CLUTTER_COLOURS))]
    for kind in s["kinds"]:
        side = rng.choice((-1, 1))
        z0 = -rng.uniform(0.3, 0.75 * l)
        if kind == "cabinet":
            items.append(dict(kind=kind, side=side, z=(z0, z0 - rng.uniform(0.8, 2.0)), depth=rng.uniform(0.35, 0.6),
                              top=rng.uniform(0.8, 1.9), colour=colour()))
        elif kind == "bench":
            items.append(dict(kind=kind, side=side, z=(z0, z0 - rng.uniform(1.2, 2.2)), depth=0.4, top=0.45,
                              colour=colour()))
        elif kind == "person":
            x = rng.uniform(-w2 + 0.35, w2 - 0.35)
            items.append(dict(kind=kind, x=x, z=-rng.uniform(1.0, l - 1.0), top=rng.uniform(1.55, 1.9),
                              colour=colour(), head=(0.85, 0.68, 0.55)))
        elif kind == "poster":
            y0 = rng.uniform(1.0, 1.5)
            items.append(dict(kind=kind, side=side, z=(z0, z0 - rng.uniform(0.5, 1.0)), y=(y0, y0 + rng.uniform(0.5, 0.9)),
                              colour=colour(), colour2=colour()))
        elif kind == "door":
            items.append(dict(kind=kind, side=side, z=(z0, z0 - 0.9), y=(0.0, 2.05), colour=colour()))
        elif kind == "lamp":
            items.append(dict(kind=kind, z=-rng.uniform(1.0, 0.6 * l), spot_side=side, spot_z=-rng.uniform(1.0, 0.7 * l)))
    if s.get("far_clutter"):
        # A cabinet against the far wall and a person before it: the far wall's foot hidden in part.
        side = rng.choice((-1, 1))
        items.append(dict(kind="cabinet", side=side, z=(-l + 0.5, -l), depth=0.45, top=1.1, colour=colour(), across=True))
        items.append(dict(kind="person", x=-side * 0.2, z=-l + 1.5, top=1.75, colour=colour(), head=(0.85, 0.68, 0.55)))
    return dict(s, clutter=items, light_gains=gains)


def clutter_pov(s):
    """The clutter items in POV-Ray's frame (Z = near - z)."""
    w2, h, near = s["width"] / 2.0, s["height"], s["near"]
    tex = lambda c, amb=0.12: "texture { pigment { color rgb <%.3f,%.3f,%.3f> } finish { diffuse 0.75 ambient %.2f } }" % (
        c[0], c[1], c[2], amb)
    box = lambda x0, y0, z0, x1, y1, z1, t: "box { <%.4f, %.4f, %.4f>, <%.4f, %.4f, %.4f> %s }\n" % (
        x0, y0, near - z0, x1, y1, near - z1, t)
    out = ["// clutter (make_corridors.py furnish)\n"]
    for it in s["clutter"]:
        k = it["kind"]
        if k in ("cabinet", "bench", "poster", "door"):
            side = it["side"]
            wall = side * w2
            za, zb = it["z"]
        if k == "cabinet":
            if it.get("across"):
                # Against the far wall, from one side wall a third of the way across.
                x0, x1 = (wall, wall - side * 0.35 * 2 * w2)
                out.append(box(min(x0, x1), 0.0, za, max(x0, x1), it["top"], zb, tex(it["colour"])))
            else:
                inner = wall - side * it["depth"]
                out.append(box(min(wall, inner), 0.0, za, max(wall, inner), it["top"], zb, tex(it["colour"])))
                # Doors on its front: a dark line down the middle of the face.
                mid = 0.5 * (za + zb)
                out.append(box(inner - side * 0.005, 0.05, mid + 0.01, inner + side * 0.01, it["top"] - 0.05, mid - 0.01,
                               tex((0.1, 0.1, 0.1))))
        elif k == "bench":
            inner = wall - side * it["depth"]
            out.append(box(min(wall, inner), 0.40, za, max(wall, inner), 0.45, zb, tex(it["colour"])))
            for zl in (za - 0.1, zb + 0.15):
                out.append(box(min(wall, inner) + 0.05, 0.0, zl, max(wall, inner) - 0.05, 0.40, zl - 0.05,
                               tex((0.2, 0.2, 0.2))))
        elif k == "person":
            x, z, top = it["x"], it["z"], it["top"]
            out.append("cylinder { <%.4f, 0, %.4f>, <%.4f, %.4f, %.4f>, 0.19 %s }\n"
                       % (x, near - z, x, top - 0.26, near - z, tex(it["colour"])))
            out.append("sphere { <%.4f, %.4f, %.4f>, 0.12 %s }\n" % (x, top - 0.12, near - z, tex(it["head"])))
        elif k == "poster":
            c1, c2 = it["colour"], it["colour2"]
            y0, y1 = it["y"]
            pig = ("texture { pigment { gradient y color_map { [0 color rgb <%.3f,%.3f,%.3f>] [1 color rgb <%.3f,%.3f,%.3f>] } "
                   "scale %.3f translate <0, %.3f, 0> } finish { ambient 0.15 } }" % (c1 + c2 + (y1 - y0, y0)))
            out.append(box(wall - side * 0.01, y0, za, wall + side * 0.01, y1, zb, pig))
        elif k == "door":
            y0, y1 = it["y"]
            # A frame proud of the wall and a darker panel inside it.
            out.append(box(wall - side * 0.03, 0.0, za + 0.06, wall + side * 0.01, y1 + 0.06, zb - 0.06, tex((0.85, 0.85, 0.82))))
            out.append(box(wall - side * 0.04, 0.0, za, wall + side * 0.01, y1, zb, tex(it["colour"], 0.08)))
        elif k == "lamp":
            z = it["z"]
            out.append("cylinder { <0, %.4f, %.4f>, <0, %.4f, %.4f>, 0.01 %s }\n" % (h, near - z, h - 0.35, near - z, tex((0.2, 0.2, 0.2))))
            out.append("cone { <0, %.4f, %.4f>, 0.05, <0, %.4f, %.4f>, 0.2 open %s }\n"
                       % (h - 0.35, near - z, h - 0.5, near - z, tex((0.9, 0.85, 0.6), 0.6)))
            out.append("light_source { <0, %.4f, %.4f> color rgb <0.45,0.42,0.35> fade_distance 2 fade_power 1 }\n"
                       % (h - 0.55, near - z))
            # A patch of sunlight on one wall (as through a window behind the camera).
            sz = it["spot_z"]
            out.append("light_source { <%.4f, %.4f, %.4f> color rgb <0.9,0.85,0.7> spotlight point_at <%.4f, 1.2, %.4f> "
                       "radius 6 falloff 9 }\n" % (-it["spot_side"] * w2 * 0.8, h - 0.1, near - sz - 2.0,
                                                   it["spot_side"] * w2, near - sz))
    return "".join(out)


SCENES += [furnish(s) for s in CLUTTER_SCENES]

CORNERS = ["P1", "P2", "P3", "P4", "P5", "P6", "P7", "P8"]
PLANES = {"front_wall": ["P1", "P2", "P4", "P3"], "left_wall": ["P7", "P1", "P3", "P5"],
          "right_wall": ["P2", "P8", "P6", "P4"], "floor": ["P3", "P4", "P6", "P5"],
          "ceiling": ["P7", "P8", "P2", "P1"]}


def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def world_from_camera(yaw_deg, pitch_deg, roll_deg):
    """Ry(yaw) Rx(pitch) Rz(roll): columns are the camera's right, up and back axes."""
    y, p, r = (math.radians(a) for a in (yaw_deg, pitch_deg, roll_deg))
    ry = [[math.cos(y), 0, math.sin(y)], [0, 1, 0], [-math.sin(y), 0, math.cos(y)]]
    rx = [[1, 0, 0], [0, math.cos(p), -math.sin(p)], [0, math.sin(p), math.cos(p)]]
    rz = [[math.cos(r), -math.sin(r), 0], [math.sin(r), math.cos(r), 0], [0, 0, 1]]
    return mat_mul(mat_mul(ry, rx), rz)


def column(m, j):
    return [m[0][j], m[1][j], m[2][j]]


class Camera:
    def __init__(self, eye, ypr, size, focal_px, principal=None):
        self.eye = list(eye)
        self.ypr = list(ypr)
        self.size = size
        self.focal_px = focal_px
        w, h = size
        self.principal = list(principal) if principal else [(w - 1) / 2.0, (h - 1) / 2.0]
        self.rot = world_from_camera(*ypr)

    def project(self, p):
        """(u, v, depth) of a model-frame point."""
        d = [p[i] - self.eye[i] for i in range(3)]
        # camera coordinates: rot^T d
        xc, yc, zc = (sum(self.rot[k][j] * d[k] for k in range(3)) for j in range(3))
        depth = -zc
        return (self.principal[0] + self.focal_px * xc / depth, self.principal[1] - self.focal_px * yc / depth, depth)

    def pov(self, near):
        """POV-Ray camera block; model z maps to POV-Ray Z = near - z."""
        w, h = self.size
        flip = lambda v: [v[0], v[1], -v[2]]
        right, up, back = (flip(column(self.rot, j)) for j in range(3))
        forward = [-c for c in back]
        d = self.focal_px / h
        # An off-centre principal point shifts the direction vector within the image plane.
        sx = ((w - 1) / 2.0 - self.principal[0]) / h
        sy = (self.principal[1] - (h - 1) / 2.0) / h
        direction = [forward[i] * d + right[i] * sx + up[i] * sy for i in range(3)]
        location = flip([self.eye[0], self.eye[1], self.eye[2] - near])
        vec = lambda v, s=1.0: "<%.9f, %.9f, %.9f>" % tuple(c * s for c in v)
        return ("camera { perspective location %s direction %s\n  right %s up %s }\n"
                % (vec(location), vec(direction), vec(right, w / h), vec(up)))


def photo_camera(s):
    return Camera([s["eye_x"], s["eye_y"], s["near"]], [s.get("yaw", 0.0), s.get("pitch", 0.0), s.get("roll", 0.0)],
                  s["size"], s["focal_px"], s.get("principal"))


def corners_m(s):
    w2, h, l = s["width"] / 2.0, s["height"], s["length"]
    return [(-w2, h, -l), (w2, h, -l), (-w2, 0, -l), (w2, 0, -l), (-w2, 0, 0), (w2, 0, 0), (-w2, h, 0), (w2, h, 0)]


def scene_pov(s, camera):
    """The scene in POV-Ray's frame: the photo's camera at Z = 0, the near corners at
    Z = near, the far wall at Z = near + length, a closed end 3 m behind the camera."""
    w2, h, near = s["width"] / 2.0, s["height"], s["near"]
    far = near + s["length"]
    t = 0.2  # wall thickness
    walls, floor = MATERIALS[s["walls"]], MATERIALS[s["floor"]]
    out = ["// generated by tests/groundtruth/make_corridors.py; ground truth in the JSON beside it\n",
           "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n", camera.pov(near)]
    gains = s.get("light_gains")  # uneven light: each ceiling lamp's own brightness
    for i, z in enumerate(range(1, int(far) + 2, 3)):
        gain = 0.38 * gains[i % len(gains)] if gains else 0.38
        out.append("light_source { <0, %.3f, %.3f> color rgb %s fade_distance 3 fade_power 1 }\n"
                   % (h - 0.05, z, "%.2f" % gain if gains else "0.38"))
    out.append("light_source { <%.9f, %.9f, -1.000000000> color rgb 0.25 shadowless }\n" % (0.0, s["fill_y"]))
    out.append("// left, right walls, floor, ceiling, far wall, the end behind the camera\n")
    out.append("box { <%r, 0, -3>, <%r, %r, %r> %s }\n" % (-w2 - t, -w2, h, far, walls))
    out.append("box { <%r, 0, -3>, <%r, %r, %r> %s }\n" % (w2, w2 + t, h, far, walls))
    out.append("box { <%r, -0.2, -3>, <%r, 0, %r> %s }\n" % (-w2 - t, w2 + t, far, floor))
    ceiling, far_wall = MATERIALS[s.get("ceiling", "ceiling")], MATERIALS[s.get("far_wall", "far_wall")]
    out.append("box { <%r, %r, -3>, <%r, %r, %r> %s }\n" % (-w2 - t, h, w2 + t, h + t, far, ceiling))
    out.append("box { <%r, -0.2, %r>, <%r, %r, %r> %s }\n" % (-w2 - t, far, w2 + t, h + t, far + t, far_wall))
    out.append("box { <%r, -0.2, -3.2>, <%r, %r, -3> %s }\n" % (-w2 - t, w2 + t, h + t, far_wall))
    out.append("// a door and a picture on the far wall\n")
    out.append("box { <-0.45, 0, %r>, <0.45, 2.1, %r> texture { pigment { color rgb <0.35,0.22,0.12> } finish { ambient 0.12 } } }\n"
               % (far - 0.02, far))
    px, py = w2 - 0.65, 0.45 * h
    out.append("box { <%r, %r, %r>, <%r, %r, %r> texture { pigment { checker color rgb <0.1,0.3,0.7> color rgb <0.9,0.8,0.1> "
               "scale 0.1 } finish { ambient 0.15 } } }\n" % (px, py, far - 0.01, px + 0.5, py + 0.4, far))
    out.append("// the band that marks the near corners (its far edge is at the near end)\n")
    out.append("#declare Band = texture { pigment { color rgb <0.08,0.09,0.12> } finish { ambient 0.1 } };\n")
    z0 = near - 0.06
    out.append("box { <%r, 0.001, %r>, <%r, %r, %r> texture { Band } }\n" % (-w2 + 0.001, z0, -w2 - 0.01, h - 0.001, near))
    out.append("box { <%r, 0.001, %r>, <%r, %r, %r> texture { Band } }\n" % (w2 - 0.001, z0, w2 + 0.01, h - 0.001, near))
    out.append("box { <%r, 0.001, %r>, <%r, -0.01, %r> texture { Band } }\n" % (-w2, z0, w2, near))
    out.append("box { <%r, %r, %r>, <%r, %r, %r> texture { Band } }\n" % (-w2, h - 0.001, z0, w2, h + 0.01, near))
    if s.get("clutter"):
        out.append(clutter_pov(s))
    return "".join(out)


def answers(s, camera):
    w, h = s["size"]
    corners = {}
    for name, p in zip(CORNERS, corners_m(s)):
        u, v, depth = camera.project(p)
        if depth <= 0:
            sys.exit("make_corridors: %s of %s is behind the camera" % (name, s["name"]))
        corners[name] = [round(u, 6), round(v, 6)]
    return {
        "name": s["name"], "image": s["name"] + ".png", "image_size": [w, h],
        "pixel_convention": "pixel centers at integer coordinates (OpenCV)",
        "focal_px": s["focal_px"], "principal_point": camera.principal,
        "camera_height_m": s["eye_y"], "camera_offset_x_m": s["eye_x"],
        "yaw_deg": camera.ypr[0], "pitch_deg": camera.ypr[1], "roll_deg": camera.ypr[2],
        "width_m": s["width"], "height_m": s["height"], "length_m": s["length"],
        "far_wall_distance_m": s["near"] + s["length"], "near_corners_distance_m": s["near"],
        "camera_position_m": camera.eye,
        "materials": {"walls": s["walls"], "floor": s["floor"]},
        "corners_px": corners, "planes": PLANES,
    }


def write_if_changed(path, text):
    if os.path.exists(path):
        with open(path) as f:
            if f.read() == text:
                return False
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)
    return True


# POV-Ray 3.7's front end gives its render thread a few seconds to start and otherwise
# exits 1 with this message: on a loaded machine (CI's two cores running the suite) it
# happens now and then, and the same render started again succeeds.
POVRAY_STARTUP_TIMEOUT = "Timed out waiting for worker thread startup"
POVRAY_TRIES = 5


def run_povray(cmd, cwd, tries=POVRAY_TRIES, pause_s=0.5):
    """subprocess.run of a povray command line, started again (up to `tries` times, waiting
    pause_s, then twice that, ...) where povray's render thread did not start in time; the
    last run's CompletedProcess. (tests/groundtruth/check_povray_retry.py)"""
    for attempt in range(tries):
        r = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
        if r.returncode == 0 or POVRAY_STARTUP_TIMEOUT not in (r.stderr + r.stdout):
            return r
        if attempt + 1 < tries:
            time.sleep(pause_s * (attempt + 1))
    return r


def render(pov_path, png_path, size):
    """povray into a temporary file, renamed into place when it succeeded."""
    w, h = size
    out_dir = os.path.dirname(os.path.abspath(png_path))
    fd, tmp = tempfile.mkstemp(suffix=".png", dir=out_dir)
    os.close(fd)
    # +A0.3: adaptive anti-aliasing (its jitter is pseudo-random with a fixed seed: the
    # same file renders to the same pixels every time); -D: no display.
    cmd = ["povray", "+I" + os.path.abspath(pov_path), "+O" + tmp, "+W%d" % w, "+H%d" % h, "-D", "+A0.3",
           "+FN8", "-GA", "+WT2"]
    r = run_povray(cmd, out_dir)
    if r.returncode != 0 or os.path.getsize(tmp) == 0:
        os.unlink(tmp)
        sys.exit("make_corridors: povray failed on %s: %s" % (pov_path, (r.stderr or r.stdout).strip().splitlines()[-1:]))
    os.replace(tmp, png_path)


def selected_scenes(args, need_povray):
    """The scenes --only names (all without it), with args.out made; exits without povray."""
    if need_povray and not shutil.which("povray"):
        sys.exit("make_corridors: povray is not installed (scripts/install-deps.sh installs it)")
    os.makedirs(args.out, exist_ok=True)
    only = set(args.only.split(",")) if args.only else None
    return [s for s in SCENES if not only or s["name"] in only]


def cmd_scenes(args):
    for s in selected_scenes(args, not args.no_render):
        camera = photo_camera(s)
        base = os.path.join(args.out, s["name"])
        changed = write_if_changed(base + ".pov", scene_pov(s, camera))
        write_if_changed(base + ".json", json.dumps(answers(s, camera), indent=1) + "\n")
        if not args.no_render and (changed or not os.path.exists(base + ".png")):
            render(base + ".pov", base + ".png", s["size"])
            print("rendered %s" % (base + ".png"))


def render_view(scene, camera, out_png, always=True):
    """Renders `scene` from `camera` into out_png, with the camera in a JSON beside it."""
    base = os.path.splitext(out_png)[0]
    changed = write_if_changed(base + ".pov", scene_pov(scene, camera))
    if always or changed or not os.path.exists(out_png):
        render(base + ".pov", out_png, camera.size)
        print("rendered %s" % out_png)
    w, h = camera.size
    write_if_changed(base + ".json", json.dumps({"scene": scene["name"], "image_size": [w, h], "focal_px": camera.focal_px,
                                                 "principal_point": camera.principal, "eye_m": camera.eye,
                                                 "yaw_deg": camera.ypr[0], "pitch_deg": camera.ypr[1],
                                                 "roll_deg": camera.ypr[2]}, indent=1) + "\n")


def cmd_view(args):
    scene = next((s for s in SCENES if s["name"] == args.name), None)
    if not scene:
        sys.exit("make_corridors: no scene %r (have %s)" % (args.name, ", ".join(s["name"] for s in SCENES)))
    w, h = (int(x) for x in args.size.split("x"))
    camera = Camera(args.eye, args.ypr, (w, h), args.focal_px or scene["focal_px"] * w / scene["size"][0])
    render_view(scene, camera, args.out)


def cmd_views(args):
    for s in selected_scenes(args, True):
        if not s["name"].startswith("corridor_"):
            continue  # the clean corridors only
        w = NOVEL_VIEW_WIDTH
        h = int(round(w * s["size"][1] / s["size"][0]))
        for kind, place in NOVEL_VIEWS.items():
            eye, ypr = place(s)
            camera = Camera(eye, ypr, (w, h), s["focal_px"] * w / s["size"][0])
            render_view(s, camera, os.path.join(args.out, "%s_view_%s.png" % (s["name"], kind)), always=False)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("scenes")
    p.add_argument("out")
    p.add_argument("--only")
    p.add_argument("--no-render", action="store_true")
    p.set_defaults(func=cmd_scenes)
    vs = sub.add_parser("views")
    vs.add_argument("out")
    vs.add_argument("--only")
    vs.set_defaults(func=cmd_views)
    v = sub.add_parser("view")
    v.add_argument("name")
    v.add_argument("out")
    v.add_argument("--eye", type=float, nargs=3, required=True)
    v.add_argument("--ypr", type=float, nargs=3, default=[0.0, 0.0, 0.0])
    v.add_argument("--size", default="800x600")
    v.add_argument("--focal-px", type=float)
    v.set_defaults(func=cmd_view)
    args = parser.parse_args()
    args.func(args)


if __name__ == "__main__":
    main()
