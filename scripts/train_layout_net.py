#!/usr/bin/env python3
"""Trains the layout network that detection builds in (assets/models/layout_net.onnx;
metrology/detect/layout_net.h says what it is for).

usage: scripts/train_layout_net.py SCENES --view whole|zoom --seeds 0-449 [--val 450-599] [--epochs 30] [-o FILE.onnx]

--view whole: the whole photo (assets/models/layout_net.onnx); --view zoom: the far wall's
neighbourhood, a square 1/0.25-1/0.6 times the far wall's extent around it, shifted up to
15% of its side (assets/models/layout_zoom_net.onnx).

SCENES is a folder of random corridor scenes (tests/groundtruth/random_corridors.py;
bench/detect_heldout.py keeps them in build/random-scenes). Train on TUNE seeds only
(docs/detection-accuracy.md): never on the held-out range 100000-100299. The whole
photo is learnt from the scenes as rendered; the far wall's neighbourhood from them and
their noisy JPEGs (seed_NNNNN_q70n3.jpg), one or the other at random. The label of a pixel is
the surface of the scene's true box its ray meets first (the far wall, the left or
right wall, the floor, the ceiling), from the scene's corners and vanishing points:
what the room's box is behind people and furniture too.

Needs python3-torch (Debian 12: apt-get install python3-torch) and python3-opencv; two
cores train the 30 epochs of either in about 25-30 minutes. The networks' input, the
neighbourhood and the box fit are mirrored in metrology/detect/layout_net.cpp: change them
together. Training again gives networks of the same kind, not the same bytes.
"""
import argparse, json, os, sys, time

import cv2
import numpy as np
import torch
import torch.nn as nn
import torch.nn.functional as F

SIDE = 192  # the input's long side (layout_net.cpp: kInputSide)
FAR, LEFT, RIGHT, FLOOR, CEILING, PAD = 0, 1, 2, 3, 4, 255


def seeds_of(text):
    """Seeds written A-B[,C-D...]."""
    seeds = []
    for part in text.split(","):
        a, _, b = part.partition("-")
        seeds += range(int(a), int(b or a) + 1)
    return seeds


def pixel_frame(direction_camera):
    """A direction in the scene's camera frame (x right, y up, z back) in the pixel
    camera's (x right, y down, z forward)."""
    return np.array([direction_camera[0], -direction_camera[1], -direction_camera[2]], float)


def labels(dx, dy, dz, left, right, bottom, top):
    """The surface each ray meets first (layout_net.cpp: labelOf)."""
    never = 1e30
    t_far = np.where(dz > 1e-9, 1.0 / np.maximum(dz, 1e-9), never)
    t_side = np.where(dx < -1e-12, left / np.where(dx < -1e-12, dx, -1.0),
                      np.where(dx > 1e-12, right / np.where(dx > 1e-12, dx, 1.0), never))
    t_fc = np.where(dy < -1e-12, bottom / np.where(dy < -1e-12, dy, -1.0),
                    np.where(dy > 1e-12, top / np.where(dy > 1e-12, dy, 1.0), never))
    side = np.where(dx < 0, LEFT, RIGHT)
    fc = np.where(dy < 0, FLOOR, CEILING)
    return np.where((t_far <= t_side) & (t_far <= t_fc), FAR, np.where(t_side <= t_fc, side, fc)).astype(np.uint8)


def squash(x):
    return np.arctan(2.0 * x) / (np.pi / 2)


def load(folder, seed):
    base = os.path.join(folder, "seed_%05d" % seed)
    scene = json.load(open(base + ".json"))
    images = []
    for suffix in (".png", "_q70n3.jpg"):
        img = cv2.imread(base + suffix)
        if img is None:
            sys.exit("error: %s%s: cannot be read (bench/detect_heldout.py renders the scenes)" % (base, suffix))
        images.append(img)
    vp = scene["vanishing_points"]
    axes = tuple(pixel_frame(vp[k]["direction_camera"]) for k in ("horizontal", "vertical", "corridor"))
    focal, pp = scene["focal_px"], scene["principal_point"]
    right, up, away = axes

    def far_plane(p):
        d = np.array([(p[0] - pp[0]) / focal, (p[1] - pp[1]) / focal, 1.0])
        return d @ right / (d @ away), d @ up / (d @ away)
    c = {k: far_plane(scene["corners_px"][k]) for k in ("P1", "P2", "P3", "P4")}
    box = ((c["P1"][0] + c["P3"][0]) / 2, (c["P2"][0] + c["P4"][0]) / 2,
           (c["P3"][1] + c["P4"][1]) / 2, (c["P1"][1] + c["P2"][1]) / 2)
    far_px = np.array([scene["corners_px"][k] for k in ("P1", "P2", "P3", "P4")], float)
    return dict(images=images, focal=focal, pp=pp, axes=axes, box=box, far_px=far_px)


def view(scene, x0, y0, zoom, image):
    """The 192 x 192 view whose top-left corner is (x0, y0) in the photo's pixels, `zoom`
    input pixels per photo pixel (layout_net.cpp: look): the input and the labels."""
    H, W = image.shape[:2]
    if zoom < 1:
        small = cv2.resize(image, None, fx=zoom, fy=zoom, interpolation=cv2.INTER_AREA)
        shift = np.array([[1, 0, -zoom * x0], [0, 1, -zoom * y0]])
        patch = cv2.warpAffine(small, shift, (SIDE, SIDE), flags=cv2.INTER_LINEAR, borderMode=cv2.BORDER_CONSTANT, borderValue=0)
    else:
        m = np.array([[zoom, 0, -zoom * x0 + 0.5 * zoom - 0.5], [0, zoom, -zoom * y0 + 0.5 * zoom - 0.5]])
        patch = cv2.warpAffine(image, m, (SIDE, SIDE), flags=cv2.INTER_LINEAR, borderMode=cv2.BORDER_CONSTANT, borderValue=0)
    ys, xs = np.mgrid[0:SIDE, 0:SIDE].astype(np.float64)
    fx = x0 + (xs + 0.5) / zoom - 0.5
    fy = y0 + (ys + 0.5) / zoom - 0.5
    inside = (fx >= -0.5) & (fy >= -0.5) & (fx <= W - 0.5) & (fy <= H - 0.5)
    right, up, away = scene["axes"]
    focal, pp = scene["focal"], scene["pp"]
    d = np.stack([(fx - pp[0]) / focal, (fy - pp[1]) / focal, np.ones_like(fx)], -1)
    dx, dy, dz = d @ right, d @ up, d @ away
    y = labels(dx, dy, dz, *scene["box"])
    y[~inside] = PAD
    x = np.zeros((5, SIDE, SIDE), np.float32)
    x[:3] = patch.transpose(2, 0, 1).astype(np.float32) / 255.0
    sdz = np.where(np.abs(dz) > 1e-6, dz, 1e-6)
    x[3] = squash(dx / sdz)
    x[4] = squash(dy / sdz)
    x[:, ~inside] = 0
    return x, y


def whole_view(scene):
    image = scene["images"][0]
    H, W = image.shape[:2]
    return view(scene, 0.0, 0.0, SIDE / max(W, H), image)


def zoom_view(scene, rng, noisy=None):
    """The far wall's neighbourhood (layout_net.cpp: kNeighbourhoodShare 0.4 and
    kMinNeighbourhoodPx at detection; here 0.25-0.6 and the centre shifted)."""
    image = scene["images"][int(rng.integers(2)) if noisy is None else int(noisy)]
    lo, hi = scene["far_px"].min(0), scene["far_px"].max(0)
    side = max(max(hi - lo) / rng.uniform(0.25, 0.6), 24.0)
    centre = (lo + hi) / 2 + rng.uniform(-0.15, 0.15, 2) * side
    return view(scene, centre[0] - side / 2, centre[1] - side / 2, SIDE / side, image)


def cbr(i, o, stride=1, dilation=1):
    return nn.Sequential(nn.Conv2d(i, o, 3, stride, padding=dilation, dilation=dilation, bias=False),
                         nn.BatchNorm2d(o), nn.ReLU(inplace=True))


class LayoutNet(nn.Module):
    """A small U-Net: 5 x 192 x 192 in, 5 labels' logits at 96 x 96 out."""

    def __init__(self):
        super().__init__()
        self.stem = nn.Sequential(cbr(5, 16), cbr(16, 24, 2), cbr(24, 24))
        self.e2 = nn.Sequential(cbr(24, 48, 2), cbr(48, 48))
        self.e3 = nn.Sequential(cbr(48, 64, 2), cbr(64, 64))
        self.e4 = nn.Sequential(cbr(64, 96, 2), cbr(96, 96, dilation=2), cbr(96, 96, dilation=4))
        self.d3 = cbr(96 + 64, 64)
        self.d2 = cbr(64 + 48, 48)
        self.d1 = cbr(48 + 24, 32)
        self.head = nn.Conv2d(32, 5, 1)

    def forward(self, x):
        a = self.stem(x)
        b = self.e2(a)
        c = self.e3(b)
        d = self.e4(c)
        up = lambda t: F.interpolate(t, scale_factor=2.0, mode="nearest")
        y = self.d3(torch.cat([up(d), c], 1))
        y = self.d2(torch.cat([up(y), b], 1))
        y = self.d1(torch.cat([up(y), a], 1))
        return self.head(y)


MIRROR = torch.tensor([FAR, RIGHT, LEFT, FLOOR, CEILING])


def augment(x, y, rng):
    """Mirrored left to right (the walls swap), colour and brightness changed, noise added."""
    x = x.clone(); y = y.clone()
    for i in range(x.shape[0]):
        if rng.random() < 0.5:
            x[i] = torch.flip(x[i], [2]); x[i, 3] = -x[i, 3]
            yi = torch.flip(y[i], [1])
            y[i] = torch.where(yi == PAD, yi, MIRROR[yi.clamp(max=4)])
        gain = torch.tensor(rng.uniform(0.6, 1.4, 3) * rng.uniform(0.8, 1.2), dtype=torch.float32).view(3, 1, 1)
        x[i, :3] = (x[i, :3] * gain + float(rng.normal(0, 0.03))).clamp(0, 1)
        if rng.random() < 0.5:
            x[i, :3] += torch.randn_like(x[i, :3]) * float(rng.uniform(0, 0.03))
    return x, y


def pixel_error(net, X, Y):
    net.eval(); wrong = seen = 0
    with torch.no_grad():
        for k in range(0, len(X), 32):
            p = F.interpolate(net(X[k:k + 32]), scale_factor=2.0, mode="bilinear", align_corners=False).argmax(1)
            m = Y[k:k + 32] != PAD
            wrong += ((p != Y[k:k + 32]) & m).sum().item(); seen += m.sum().item()
    return wrong / max(seen, 1)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scenes")
    ap.add_argument("--view", choices=("whole", "zoom"), required=True)
    ap.add_argument("--seeds", required=True, help="training seeds, e.g. 0-449 (TUNE only)")
    ap.add_argument("--val", help="seeds to report the pixel error on, e.g. 450-599")
    ap.add_argument("--epochs", type=int, default=30)
    ap.add_argument("-o", "--output")
    a = ap.parse_args()
    models = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "assets", "models")
    output = a.output or os.path.join(models, "layout_net.onnx" if a.view == "whole" else "layout_zoom_net.onnx")
    for s in list(seeds_of(a.seeds)) + (list(seeds_of(a.val)) if a.val else []):
        if 100000 <= s <= 100299:
            sys.exit("error: seed %d is in the held-out range 100000-100299: train and validate on TUNE seeds" % s)
    torch.set_num_threads(os.cpu_count() or 1)
    torch.manual_seed(0)
    rng = np.random.default_rng(0)
    train = [load(a.scenes, s) for s in seeds_of(a.seeds)]
    val_scenes = [load(a.scenes, s) for s in seeds_of(a.val)] if a.val else []
    if a.view == "whole":
        fixed = [whole_view(sc) for sc in train]
        draw = lambda i: fixed[i]
        val = [whole_view(sc) for sc in val_scenes]
    else:
        draw = lambda i: zoom_view(train[i], rng)
        val_rng = np.random.default_rng(1)
        val = [zoom_view(sc, val_rng, noisy=False) for sc in val_scenes]
    VX = torch.from_numpy(np.stack([v[0] for v in val])) if val else None
    VY = torch.from_numpy(np.stack([v[1] for v in val]).astype(np.int64)) if val else None
    net = LayoutNet()
    batch = 16
    opt = torch.optim.AdamW(net.parameters(), 2e-3, weight_decay=1e-4)
    sched = torch.optim.lr_scheduler.OneCycleLR(opt, 3e-3, total_steps=a.epochs * ((len(train) + batch - 1) // batch))
    for epoch in range(a.epochs):
        net.train(); t0 = time.time(); total = 0.0
        order = rng.permutation(len(train))
        for k in range(0, len(train), batch):
            views = [draw(i) for i in order[k:k + batch]]
            x = torch.from_numpy(np.stack([v[0] for v in views]))
            y = torch.from_numpy(np.stack([v[1] for v in views]).astype(np.int64))
            x, y = augment(x, y, rng)
            logits = F.interpolate(net(x), scale_factor=2.0, mode="bilinear", align_corners=False)
            loss = F.cross_entropy(logits, y, ignore_index=PAD)
            opt.zero_grad(); loss.backward(); opt.step(); sched.step()
            total += loss.item() * len(views)
        line = "epoch %d: loss %.4f" % (epoch, total / len(train))
        if VX is not None:
            line += ", pixels mislabelled on the validation seeds %.2f%%" % (100 * pixel_error(net, VX, VY))
        print(line + " (%.0f s)" % (time.time() - t0), flush=True)
    net.eval()
    tmp = output + ".tmp"
    torch.onnx.export(net, torch.zeros(1, 5, SIDE, SIDE), tmp, opset_version=11, input_names=["input"],
                      output_names=["logits"])
    # What OpenCV's importer makes of it must be what torch computes.
    probe = torch.from_numpy(draw(0)[0][None])
    check = cv2.dnn.readNetFromONNX(tmp)
    check.setInput(probe.numpy())
    with torch.no_grad():
        diff = float(np.abs(check.forward() - net(probe).numpy()).max())
    if diff > 1e-3:
        os.unlink(tmp)
        sys.exit("error: OpenCV's dnn reads the exported network differently (%.2g): not written" % diff)
    os.replace(tmp, output)
    print("wrote %s (OpenCV's dnn agrees within %.1g)" % (output, diff))


if __name__ == "__main__":
    main()
