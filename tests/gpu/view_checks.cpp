#include "tests/gpu/view_checks.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace pw::test {

engine::Image crop(const engine::Image& image, int x, int y, int w, int h) {
  engine::Image out = engine::makeImage(w, h);
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const uint8_t* from = image.pixel(x + i, y + j);
      std::copy(from, from + 4, out.pixel(i, j));
    }
  }
  return out;
}

engine::Image patternImage(int width, int height) {
  engine::Image image = engine::makeImage(width, height);
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      uint8_t* p = image.pixel(u, v);
      p[0] = uint8_t(4 * u);
      p[1] = uint8_t(4 * v);
      p[2] = (u + v) % 2 ? 255 : 0;
      p[3] = 255;
    }
  }
  return image;
}

std::string checkImageLayout(const engine::Image& frame, const engine::Image& image, const engine::ImageTransform& t,
                             const engine::PixelRect& rect, const std::array<uint8_t, 3>& background, int tolerance,
                             double margin) {
  std::ostringstream errors;
  int mismatches = 0, checked = 0;
  for (int y = rect.y; y < rect.y + rect.height; ++y) {
    for (int x = rect.x; x < rect.x + rect.width; ++x) {
      // The pixel centre in image pixels; image pixel u covers [u - 0.5, u + 0.5).
      const double px = (x + 0.5 - t.offset.x) / t.scale, py = (y + 0.5 - t.offset.y) / t.scale;
      const double fx = px + 0.5 - std::floor(px + 0.5), fy = py + 0.5 - std::floor(py + 0.5);
      if (std::min(fx, 1 - fx) < margin || std::min(fy, 1 - fy) < margin) continue;
      const int u = int(std::floor(px + 0.5)), v = int(std::floor(py + 0.5));
      const bool inside = u >= 0 && v >= 0 && u < image.width && v < image.height;
      const uint8_t* want = inside ? image.pixel(u, v) : background.data();
      const uint8_t* got = frame.pixel(x, y);
      ++checked;
      int worst = 0;
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(got[c]) - int(want[c])));
      if (worst > tolerance && mismatches++ < 5) {
        errors << "frame (" << x << ", " << y << ") shows " << int(got[0]) << "," << int(got[1]) << "," << int(got[2])
               << " where " << (inside ? "image pixel (" + std::to_string(u) + ", " + std::to_string(v) + ")" : "the background")
               << " is " << int(want[0]) << "," << int(want[1]) << "," << int(want[2]) << "; ";
      }
    }
  }
  if (checked == 0) return "no frame pixel was checked";
  if (mismatches == 0) return "";
  errors << mismatches << " of " << checked << " pixels differ by more than " << tolerance << "/255";
  return errors.str();
}

PixelBox findColor(const engine::Image& frame, const engine::PixelRect& rect, const std::array<uint8_t, 3>& rgb) {
  PixelBox box{rect.x + rect.width, rect.y + rect.height, rect.x, rect.y};
  for (int y = rect.y; y < rect.y + rect.height; ++y) {
    for (int x = rect.x; x < rect.x + rect.width; ++x) {
      const uint8_t* p = frame.pixel(x, y);
      if (p[0] != rgb[0] || p[1] != rgb[1] || p[2] != rgb[2]) continue;
      box.x0 = std::min(box.x0, x);
      box.y0 = std::min(box.y0, y);
      box.x1 = std::max(box.x1, x + 1);
      box.y1 = std::max(box.y1, y + 1);
    }
  }
  if (box.x1 <= box.x0) return {};
  return box;
}

}  // namespace pw::test
