#!/usr/bin/env python3
"""The deliberate bugs of scripts/mutation-check.sh, and the file work it needs.

Each mutation is one exact text replacement in one source file: the slip a person
could really make at that place. The text to replace must occur exactly once in the
file, so that the list stays true as the code changes: `check` fails loudly (naming
the bug and the file) when it no longer does.

Usage (mutation-check.sh calls these; `check` is also useful on its own):
  mutations.py list                      name, file and what each bug does
  mutations.py names [--only A,B]        the names to run, one a line (unknown names fail)
  mutations.py check ROOT [--only A,B]   every replacement's text occurs once under ROOT
  mutations.py apply ROOT NAME BACKUP    write the bug into ROOT's file; keep the original in BACKUP
  mutations.py restore ROOT NAME BACKUP  put the original back (with a new mtime, so make rebuilds it)
  mutations.py sync SRC DEST             copy SRC's working tree (tracked files and untracked ones
                                         git does not ignore) to DEST, rewriting only files whose
                                         content differs and removing files SRC no longer has
  mutations.py sync-head SRC DEST        the same from SRC's last commit (git archive HEAD)
"""

import os
import shutil
import subprocess
import sys
import tarfile
import tempfile
from dataclasses import dataclass


@dataclass(frozen=True)
class Mutation:
    name: str
    path: str  # relative to the repository root
    find: str  # exact text, must occur exactly once in the file
    replace: str
    what: str  # the slip, in words


MUTATIONS = [
    Mutation(
        "focal-x1.009", "metrology/shot_check.cpp",
        "  k.focalPx = shot.focalPx;\n",
        "  k.focalPx = shot.focalPx * 1.009;\n",
        "the shot's focal length read 0.9% long (length +0.9%, width and height exact)"),
    Mutation(
        "principal-point-ignored", "metrology/shot_check.cpp",
        "  k.principalPointPx = shot.principalPoint();\n",
        "  k.principalPointPx = glm::dvec2((shot.imageWidth - 1) * 0.5, (shot.imageHeight - 1) * 0.5);\n",
        "the image centre used instead of the shot's principal point"),
    Mutation(
        "texture-s-mirrored", "modeling/corridor_model.cpp",
        "metrology::photoFromPlane(m.camera, m.pose, panel.point(r.s0, r.t1), panel.sAxis, -panel.tAxis);",
        "metrology::photoFromPlane(m.camera, m.pose, panel.point(r.s1, r.t1), -panel.sAxis, -panel.tAxis);",
        "a corridor surface's texture cut from the photo with s reversed (mirrored left-right)"),
    Mutation(
        "rectify-t-mirrored", "metrology/rectify.cpp",
        "cv::Matx33d(sx, 0, 0.5 * sx, 0, sy, 0.5 * sy, 0, 0, 1)",
        "cv::Matx33d(sx, 0, 0.5 * sx, 0, -sy, heightM - 0.5 * sy, 0, 0, 1)",
        "the rectifier's texture rows run bottom to top (upside down; rectify and build)"),
    Mutation(
        "rectify-size-off-by-one", "metrology/rectify.cpp",
        "cv::Size(std::clamp(static_cast<int>(std::lround(widthM * d.x)), 1, options.maxSidePx),",
        "cv::Size(std::clamp(static_cast<int>(std::lround(widthM * d.x)) + 1, 1, options.maxSidePx),",
        "a rectified texture one pixel wider than its width times its px per metre"),
    Mutation(
        "normals-flipped", "engine/vrml/polygon_mesh.cpp",
        "faceNormals[f] = newellNormal(soup.points, corners) * (soup.ccw ? 1.0 : -1.0);",
        "faceNormals[f] = newellNormal(soup.points, corners) * (soup.ccw ? -1.0 : 1.0);",
        "VRML face sets' generated normals point inwards (ccw read backwards)"),
    Mutation(
        "smooth-normals-flipped", "engine/scene/scene.cpp",
        "glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);",
        "glm::cross(mesh.positions[c] - mesh.positions[a], mesh.positions[b] - mesh.positions[a]);",
        "computeSmoothNormals (meshes without normals: glTF, packing) crosses the edges in the wrong order"),
    Mutation(
        "attenuation-dropped", "shaders/lighting.glsl",
        "return d > light.attenuationRadius.w ? 0.0 : 1.0 / max(a.x + a.y * d + a.z * d * d, 1.0);",
        "return d > light.attenuationRadius.w ? 0.0 : 1.0;",
        "point and spot lights ignore their attenuation (VRML97 4.14.4)"),
    Mutation(
        "collision-radius-halved", "editor/walk/avatar.cpp",
        "world_->slideSphere(start, static_cast<float>(radiusM_), glm::vec3(allowed));",
        "world_->slideSphere(start, static_cast<float>(0.5 * radiusM_), glm::vec3(allowed));",
        "the walk avatar collides with walls at half its radius"),
    Mutation(
        "vrml-diffuse-default", "engine/vrml/vrml_builtin_nodes.cpp",
        "  exposedField SFColor diffuseColor 0.8 0.8 0.8\n",
        "  exposedField SFColor diffuseColor 0.7 0.7 0.7\n",
        "VRML Material.diffuseColor defaults to 0.7 instead of 0.8"),
    Mutation(
        "vrml-cylinder-radius-default", "engine/vrml/vrml_builtin_nodes.cpp",
        "Cylinder [\n  field SFBool bottom TRUE\n  field SFFloat height 2\n  field SFFloat radius 1\n",
        "Cylinder [\n  field SFBool bottom TRUE\n  field SFFloat height 2\n  field SFFloat radius 0.5\n",
        "VRML Cylinder.radius defaults to 0.5 instead of 1"),
    Mutation(
        "png-filter-byte", "engine/scene/png_encoder.cpp",
        "    out[0] = 4;\n",
        "    out[0] = 2;\n",
        "PNG rows filtered with Paeth but labelled Up (filter type 2)"),
    Mutation(
        "vanishing-point-sign", "metrology/vanishing.cpp",
        "glm::dvec3 x(xn.x / scale + centroid.x * xn.z,",
        "glm::dvec3 x(xn.x / scale - centroid.x * xn.z,",
        "the vanishing-point fit undoes the normalisation with the wrong sign in x"),
    Mutation(
        "pinhole-view-ignores-lens", "metrology/detect/edge_fit.cpp",
        "  if (lens_) p = distortPixel(*lens_, p);\n",
        "",
        "detect's sub-pixel fits read a photo taken through a lens as if it were a pinhole's"),
    Mutation(
        "edge-fit-outermost", "metrology/detect/edge_fit.cpp",
        "    const bool better = !chosen || inward * centre > inward * *chosen;\n",
        "    const bool better = !chosen || inward * centre < inward * *chosen;\n",
        "where a far wall's foot runs beside a floor joint, the fit starts from the outer edge"),
    Mutation(
        "working-lens-unscaled", "metrology/detect/working_image.cpp",
        "  scaled.focalPx = lens.focalPx * work.scale;\n",
        "  scaled.focalPx = lens.focalPx;\n",
        "the working copy is undistorted with the full-resolution focal length (too little bend)"),
    Mutation(
        "detail-never-faded", "shaders/scene.frag",
        "  return texel.rgb * exp2(detail * octaves);\n",
        "  return texel.rgb * exp2(octaves);\n",
        "the detail layer is drawn at every footprint, from the photo's camera too"),
    Mutation(
        "period-not-refined", "modeling/synthesis.cpp",
        "        period = *peak / k;\n",
        "",
        "the lattice's period is taken from its first peak only (a fraction of a texel off)"),
]

BY_NAME = {m.name: m for m in MUTATIONS}


def fail(message):
    print(f"mutations.py: error: {message}", file=sys.stderr)
    sys.exit(1)


def selected(only):
    if not only:
        return list(MUTATIONS)
    names = [n for n in only.split(",") if n]
    unknown = [n for n in names if n not in BY_NAME]
    if unknown:
        fail(f"unknown bug name(s): {', '.join(unknown)} (--list shows the names)")
    return [BY_NAME[n] for n in names]


def read(root, m):
    path = os.path.join(root, m.path)
    if not os.path.isfile(path):
        return None, f"{m.name}: {m.path} does not exist"
    with open(path, encoding="utf-8", newline="") as f:
        text = f.read()
    count = text.count(m.find)
    if count != 1:
        how = "is not found" if count == 0 else f"occurs {count} times"
        return None, f"{m.name}: the text to replace {how} in {m.path}: {m.find!r}"
    return text, None


def write(path, text):
    # A fresh file (new mtime): make must see a change both when the bug goes in and
    # when it comes out, or it would keep a stale object file.
    tmp = path + ".mutation-tmp"
    with open(tmp, "w", encoding="utf-8", newline="") as f:
        f.write(text)
    shutil.copymode(path, tmp)
    os.replace(tmp, path)


def cmd_check(root, only):
    problems = [p for m in selected(only) for _, p in [read(root, m)] if p]
    for p in problems:
        print(f"NOT APPLICABLE  {p}", file=sys.stderr)
    n = len(selected(only))
    if problems:
        print(f"{len(problems)} of {n} mutations do not apply to {root}: update scripts/mutations.py", file=sys.stderr)
        sys.exit(1)
    print(f"all {n} mutations apply to {root}")


def cmd_apply(root, name, backup):
    m = selected(name)[0]
    text, problem = read(root, m)
    if problem:
        fail(problem)
    os.makedirs(os.path.dirname(os.path.abspath(backup)), exist_ok=True)
    with open(backup, "w", encoding="utf-8", newline="") as f:
        f.write(text)
    write(os.path.join(root, m.path), text.replace(m.find, m.replace))


def cmd_restore(root, name, backup):
    m = selected(name)[0]
    if not os.path.isfile(backup):
        fail(f"{name}: no backup of {m.path} at {backup}")
    with open(backup, encoding="utf-8", newline="") as f:
        write(os.path.join(root, m.path), f.read())
    os.remove(backup)


# Paths in the copy that are not part of the tree and that sync must leave alone: the
# copy's build folders (.gitignore's /build*/ and /out/) and node_modules links.
def kept(rel):
    top = rel.split(os.sep, 1)[0]
    return top.startswith("build") or top == "out" or "node_modules" in rel.split(os.sep)


def tree_files(src):
    out = subprocess.run(["git", "-C", src, "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                         check=True, capture_output=True).stdout
    files = sorted({p for p in out.decode().split("\0") if p})
    # Tracked files deleted in the working tree are not part of it.
    return [p for p in files if os.path.lexists(os.path.join(src, p)) and not os.path.isdir(os.path.join(src, p))]


def same_content(a, b):
    if os.path.islink(a) or os.path.islink(b):
        return os.path.islink(a) and os.path.islink(b) and os.readlink(a) == os.readlink(b)
    if not os.path.isfile(b) or os.path.getsize(a) != os.path.getsize(b):
        return False
    with open(a, "rb") as fa, open(b, "rb") as fb:
        return fa.read() == fb.read()


def sync(src, dest, files):
    os.makedirs(dest, exist_ok=True)
    wanted = set(files)
    changed = 0
    for rel in files:
        s, d = os.path.join(src, rel), os.path.join(dest, rel)
        if same_content(s, d):
            continue  # unchanged files keep their mtime: make rebuilds only what changed
        os.makedirs(os.path.dirname(d), exist_ok=True)
        if os.path.lexists(d) or os.path.isdir(d):
            shutil.rmtree(d) if os.path.isdir(d) and not os.path.islink(d) else os.remove(d)
        if os.path.islink(s):
            os.symlink(os.readlink(s), d)
        else:
            shutil.copyfile(s, d)
            shutil.copymode(s, d)
        changed += 1
    removed = 0
    for dirpath, dirnames, filenames in os.walk(dest, topdown=True):
        reldir = os.path.relpath(dirpath, dest)
        reldir = "" if reldir == "." else reldir
        dirnames[:] = [n for n in dirnames if not kept(os.path.join(reldir, n))]
        for n in filenames:
            rel = os.path.join(reldir, n)
            if rel not in wanted and not kept(rel):
                os.remove(os.path.join(dirpath, n))
                removed += 1
    print(f"synced {len(files)} files to {dest}: {changed} written, {removed} removed")


def cmd_sync_head(src, dest):
    with tempfile.TemporaryDirectory(prefix="photowalk-head-") as tmp:
        archive = subprocess.run(["git", "-C", src, "archive", "--format=tar", "HEAD"], check=True,
                                 capture_output=True).stdout
        tar_path = os.path.join(tmp, "head.tar")
        with open(tar_path, "wb") as f:
            f.write(archive)
        tree = os.path.join(tmp, "tree")
        with tarfile.open(tar_path) as t:
            members = [m for m in t.getmembers() if m.isfile() or m.issym()]
            t.extractall(tree, members=members)
        sync(tree, dest, sorted(m.name for m in members))


def main(argv):
    if len(argv) < 2:
        fail("usage: see the header of scripts/mutations.py")
    cmd, args = argv[1], argv[2:]
    only = None
    if "--only" in args:
        i = args.index("--only")
        if i + 1 >= len(args):
            fail("--only needs a comma-separated list of names")
        only = args[i + 1]
        args = args[:i] + args[i + 2:]
    if cmd == "list" and not args:
        for m in selected(only):
            print(f"{m.name:30} {m.path:38} {m.what}")
    elif cmd == "names" and not args:
        for m in selected(only):
            print(m.name)
    elif cmd == "file" and len(args) == 1:
        print(selected(args[0])[0].path)
    elif cmd == "check" and len(args) == 1:
        cmd_check(args[0], only)
    elif cmd == "apply" and len(args) == 3:
        cmd_apply(*args)
    elif cmd == "restore" and len(args) == 3:
        cmd_restore(*args)
    elif cmd == "sync" and len(args) == 2:
        sync(args[0], args[1], tree_files(args[0]))
    elif cmd == "sync-head" and len(args) == 2:
        cmd_sync_head(*args)
    else:
        fail(f"bad command line: {' '.join(argv[1:])} (see the header of scripts/mutations.py)")


if __name__ == "__main__":
    main(sys.argv)
