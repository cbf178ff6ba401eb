#!/usr/bin/env bash
# Installs the Debian 12 packages photowalk needs to build, test and run.
# Idempotent: prints nothing and does nothing when everything is there.
# Usage: scripts/install-deps.sh [--with-extras]   (extras: view3dscene, chromium, node for the
# glTF validator and the web page's viewer)
set -euo pipefail

packages=(
  build-essential cmake pkg-config python3
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslc
  libglfw3-dev libglm-dev libopencv-dev libimgui-dev libstb-dev
  libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev libtinygltf-dev zlib1g-dev
  libexif-dev
  xvfb xauth fonts-dejavu-core povray
  # tests/groundtruth/random_corridors.py's noisy JPEG (sensor noise, then JPEG quality 70)
  python3-numpy python3-pil
)
if [[ "${1:-}" == "--with-extras" || "${CI:-}" == "true" ]]; then
  packages+=(view3dscene)
  # photowalk share's tests open the page in Debian's Chromium (driven by npm's playwright-core).
  packages+=(chromium)
  # The glTF validator, the web viewer's three.js and esbuild come from npm; use the
  # machine's Node.js when it has one.
  command -v npm >/dev/null 2>&1 || packages+=(nodejs npm)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

sudo=""
if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
echo "photowalk: installing ${#missing[@]} missing package(s): ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
