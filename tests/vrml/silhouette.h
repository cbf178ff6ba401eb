// Coarse comparison of two renders of the same scene from the same viewpoint: the
// masks of pixels that differ from each frame's background, and their overlap.
#pragma once

#include <cstdlib>
#include <vector>

#include "engine/scene/image.h"

namespace pw::engine {

// Object pixels: those whose largest channel difference from the background colour
// (taken from the top-left pixel) exceeds `tolerance`.
inline std::vector<bool> silhouette(const Image& image, int tolerance) {
  std::vector<bool> mask(static_cast<size_t>(image.width) * image.height);
  const uint8_t* bg = image.pixel(0, 0);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* p = image.pixel(x, y);
      int d = 0;
      for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(p[c]) - int(bg[c])));
      mask[static_cast<size_t>(y) * image.width + x] = d > tolerance;
    }
  }
  return mask;
}

// |A and B| / |A or B|; 0 when both are empty: two empty frames are no evidence that
// two renderers agree (nothing was drawn, or both drew outside the view).
inline double intersectionOverUnion(const std::vector<bool>& a, const std::vector<bool>& b) {
  size_t both = 0, either = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) {
    both += a[i] && b[i];
    either += a[i] || b[i];
  }
  return either ? double(both) / double(either) : 0.0;
}

// The fraction of the frame a mask covers, 0 to 1.
inline double coverage(const std::vector<bool>& mask) {
  size_t set = 0;
  for (const bool b : mask) set += b;
  return mask.empty() ? 0.0 : double(set) / double(mask.size());
}

}  // namespace pw::engine
