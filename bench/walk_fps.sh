#!/usr/bin/env bash
# Walkthrough frame rate (issue 6), not a test: `photowalk walk --no-vsync` over a
# scripted walk at 1280x720 on lavapipe under xvfb-run, for one corridor and for a
# building of 20 corridors (made with a layout file from the shared corridor shots),
# each against the same walk through an empty scene (clear + present only).
# Usage: bench/walk_fps.sh [BUILD_DIR] [FRAMES]   (defaults: build, 300)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
frames=${2:-300}
pw=$build/photowalk
shared=$(cd .. && pwd)/shared/corridors
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

python3 - "$shared" "$out/building.json" <<'PY'
import json, sys
shots = ["corridor_a", "corridor_b", "corridor_c", "corridor_d", "corridor_e"]
corridors = [{"name": "c0", "shot": f"{sys.argv[1]}/corridor_b.json"}]
# A spine of far-attached corridors with wings off both sides.
spine = 0
for i in range(1, 20):
    shot = f"{sys.argv[1]}/{shots[i % 5]}.json"
    if i % 3 == 0:
        corridors.append({"name": f"c{i}", "shot": shot, "attach": {"to": f"c{spine}", "side": "far", "offset_m": 0}})
        spine = i
    else:
        side = "left" if i % 3 == 1 else "right"
        corridors.append({"name": f"c{i}", "shot": shot, "attach": {"to": f"c{spine}", "side": side, "offset_m": 3.0 if side == "left" else 6.5}})
json.dump({"corridors": corridors}, open(sys.argv[2], "w"), indent=1)
PY

"$pw" build assets/corridor.json -o "$out/one.wrl" --px-per-m 60 >/dev/null
"$pw" build --layout "$out/building.json" -o "$out/building.wrl" --px-per-m 60 >/dev/null
printf '#VRML V2.0 utf8\nViewpoint { position 0 1.6 0 }\n' > "$out/empty.wrl"
{
  echo "0 key W down"
  echo "$((frames / 2)) mouse 400 0"
  echo "$frames quit"
} > "$out/walk.replay"

for model in empty one building; do
  line=$(xvfb-run -a -s "-screen 0 1920x1080x24" "$pw" walk "$out/$model.wrl" --size 1280x720 --no-vsync \
         --replay "$out/walk.replay" --no-overlay | grep '^walk:')
  echo "$model: $line"
done
