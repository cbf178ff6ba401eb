#!/usr/bin/env bash
# photowalk's main job on the bundled sample, from a fresh Debian 12 machine:
# installs what is missing, builds, measures the sample photo, builds the 3D model
# (VRML97 + glTF), draws the measurement sheet, renders views and a short tour.
# Usage: scripts/demo.sh [OUTPUT_DIR]   (default: out/demo)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/demo}

scripts/install-deps.sh
cmake --preset default >/dev/null
cmake --build --preset default -j "$(nproc)" --target photowalk
pw=build/photowalk
mkdir -p "$out/views"

echo "== Measuring assets/corridor.json (photo assets/corridor.png)"
"$pw" measure assets/corridor.json --sheet "$out/sheet.png" > "$out/measure.json"
python3 - "$out/measure.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1])); s = m["sigma_m"]; c = m["camera"]
print("   width  %.3f m ± %.3f" % (m["width_m"], s["width_m"]))
print("   height %.3f m ± %.3f" % (m["height_m"], s["height_m"]))
print("   length %.3f m ± %.3f" % (m["length_m"], s["length_m"]))
print("   camera %.2f m high, yaw %.2f°, pitch %.2f°, roll %.2f°; reprojection RMS %.2f px"
      % (c["height_m"], c["yaw_deg"], c["pitch_deg"], c["roll_deg"], m["reprojection_rms_px"]))
PY

echo "== Building the model"
"$pw" build assets/corridor.json -o "$out/corridor.wrl" --gltf "$out/corridor.glb"

echo "== Rendering views"
i=0
for vp in "Photo" "Entrance" "Far end looking back" "Overview"; do
  "$pw" render "$out/corridor.wrl" --viewpoint "$vp" --size 1280x720 -o "$out/views/view_$i.png"
  i=$((i + 1))
done
"$pw" render "$out/corridor.wrl" --camera-from assets/corridor.json -o "$out/views/photo_camera.png"

echo "== Rendering a tour"
"$pw" tour "$out/corridor.wrl" -o "$out/tour" --frames 150 --size 960x540 --video "$out/tour.mp4"

cat <<EOF2

Done. In $out:
  measure.json         the measurement (dimensions, ±, camera pose)
  sheet.png            the photo with corners, vanishing point, horizon and dimensions
  corridor.wrl         the model (VRML97, textures beside it); corridor.glb (glTF 2.0)
  views/               four viewpoints, and the photo's camera (compare with assets/corridor.png)
  tour/, tour.mp4      a walk down the corridor and back
Walk through it yourself:  $pw walk $out/corridor.wrl
EOF2
