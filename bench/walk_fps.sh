#!/usr/bin/env bash
# Walkthrough frame rate (issue 6), not a test: `photowalk walk --no-vsync` over a
# scripted walk at 1280x720 on lavapipe under xvfb-run, for one corridor and for a
# building of 20 corridors (made with a layout file from the shared corridor shots),
# photo-lit (the default look) and --lit (47 point lights), and the built-in lit
# sample room, each against the same walk through an empty scene (clear + present).
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
# A spine of long corridors (b, d, e: 14.5 to 26 m) joined end to end, each with a
# narrow wing (a, c: 2.4 and 1.8 m wide) off its left and right walls: 20 corridors.
spine_shots, wing_shots = ["corridor_b", "corridor_d", "corridor_e"], ["corridor_a", "corridor_c"]
corridors, spine, n = [], None, 0
while n < 20:
    name = f"c{n}"
    entry = {"name": name, "shot": f"{sys.argv[1]}/{spine_shots[n % 3]}.json"}
    if spine is not None:
        entry["attach"] = {"to": spine, "side": "far", "offset_m": 0}
    corridors.append(entry); spine = name; n += 1
    for side, offset in (("left", 3.0), ("right", 8.0)):
        if n < 20:
            corridors.append({"name": f"c{n}", "shot": f"{sys.argv[1]}/{wing_shots[n % 2]}.json",
                              "attach": {"to": spine, "side": side, "offset_m": offset}})
            n += 1
json.dump({"corridors": corridors}, open(sys.argv[2], "w"), indent=1)
PY

"$pw" build assets/corridor.json -o "$out/one.wrl" --px-per-m 60 >/dev/null
"$pw" build --layout "$out/building.json" -o "$out/building.wrl" --px-per-m 60 >/dev/null
"$pw" build --layout "$out/building.json" -o "$out/building_lit.wrl" --px-per-m 60 --lit >/dev/null
printf '#VRML V2.0 utf8\nViewpoint { position 0 1.6 0 }\n' > "$out/empty.wrl"
{
  echo "0 key W down"
  echo "$((frames / 2)) mouse 400 0"
  echo "$frames quit"
} > "$out/walk.replay"

for model in empty one building building_lit sample; do
  file="$out/$model.wrl"
  [ "$model" = sample ] && file=sample
  line=$(xvfb-run -a -s "-screen 0 1920x1080x24" "$pw" walk "$file" --size 1280x720 --no-vsync \
         --replay "$out/walk.replay" --no-overlay | grep '^walk:')
  echo "$model: $line"
done
