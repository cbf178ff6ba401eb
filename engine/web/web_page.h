// A model as one self-contained web page (photowalk share): the viewer (web/src,
// three.js, bundled at build time), the model as binary glTF with JPEG textures no
// larger than the screen needs, and what photowalk knows beyond glTF (each viewpoint's
// exact lens, the avatar, the tour, the dimensions), all inside one HTML file that
// opens from file:// and from any static server, with no network.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "base/result.h"
#include "engine/scene/scene.h"

namespace pw::engine {

struct WebPageOptions {
  int maxTexturePx = 2048;  // a texture's longer side at most this (scaled down, area-averaged)
  int jpegQuality = 85;     // opaque textures as JPEG of this quality; textures with alpha stay PNG
  std::string title;        // empty: the scene's title, else "photowalk"
  std::vector<std::string> dimensions;  // lines the page shows (a corridor's width, height, length)
  // The tour as the page plays it: eye (x, y, z) and heading (yaw, radians, 0 along -Z)
  // every `tourStepS` seconds; empty: no tour button.
  std::vector<std::array<double, 4>> tourSamples;
  double tourStepS = 0.05;
};

struct WebPageReport {
  size_t pageBytes = 0;
  size_t modelBytes = 0;     // the binary glTF inside it (before base64)
  int texturesScaled = 0;    // textures made smaller to fit maxTexturePx
};

// Whether this photowalk carries the viewer (built with node and web/node_modules).
bool hasWebViewer();

// The page's HTML. Errors: no viewer built in, a scene glTF cannot hold.
Result<std::string> webPageHtml(const Scene& scene, const WebPageOptions& options, WebPageReport* report = nullptr);

// The scene with every texture's image no larger than `maxPx` on its longer side
// (area-averaged in linear light); `scaled` counts the images made smaller.
Scene withTexturesAtMost(const Scene& scene, int maxPx, int* scaled = nullptr);

}  // namespace pw::engine
