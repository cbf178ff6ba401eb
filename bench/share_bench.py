#!/usr/bin/env python3
"""The web page's load time and frame rate (photowalk share), in Debian's Chromium (headless,
WebGL on SwiftShader: the CPU, as a machine without a GPU draws it): on demand, not in CI.

usage: bench/share_bench.py PHOTOWALK [--runs N] [--size WxH] [--big]
(--big needs PIL: Debian's /usr/bin/python3 with python3-pil)

Writes pages for the built-in sample room (the baseline: a few shapes, no photo) and the
sample corridor (and with --big the sample photo enlarged to 12 MP), then opens each N
times (default 5) with web/test/page_check.mjs and prints the medians of: the load time
(navigation to the model shown), the frames drawn in the last second at the end (after
stepping through the viewpoints), and the page's size. Compare rows within one run only:
the machine is shared.
"""
import argparse, json, os, statistics, subprocess, sys, tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("photowalk")
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--size", default="1280x720")
    ap.add_argument("--big", action="store_true")
    a = ap.parse_args()
    work = tempfile.mkdtemp(prefix="pw_share_bench_")
    pages = [("sample room (baseline)", "sample"), ("sample corridor", os.path.join(ROOT, "assets", "corridor.json"))]
    if a.big:
        sys.path.insert(0, os.path.join(ROOT, "scripts"))
        import importlib
        kc = importlib.import_module("kill-check")
        from pathlib import Path
        kc.make_photo(Path(work))
        pages.append(("12 MP corridor", os.path.join(work, "a", "s.json")))
    print(f"{'page':24} {'MB':>6} {'load ms (median)':>17} {'fps (median)':>13}")
    for name, source in pages:
        html = os.path.join(work, name.split()[0] + "_" + str(len(name)) + ".html")
        subprocess.run([a.photowalk, "share", source, "-o", html], check=True, stdout=subprocess.DEVNULL)
        loads, fps = [], []
        for _ in range(a.runs):
            out = subprocess.run(["node", os.path.join(ROOT, "web", "test", "page_check.mjs"), html, "--size", a.size],
                                 check=True, stdout=subprocess.PIPE, text=True).stdout
            r = json.loads(out.strip().splitlines()[-1])
            loads.append(r["loadMs"])
            fps.append(r["fps"])
        print(f"{name:24} {os.path.getsize(html) / 1e6:6.1f} {statistics.median(loads):17.0f} {statistics.median(fps):13.0f}")


if __name__ == "__main__":
    main()
