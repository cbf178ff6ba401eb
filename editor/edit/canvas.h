// The photo canvas's pan and zoom: where the photo lies in the window. A photo pixel
// (u, v) (centre of the top-left pixel at (0, 0)) is drawn at window position
// offset + scale * (u, v), as engine::ImageView draws it (engine/gpu/view.h).
// Pure arithmetic, tested headless (tests/edit/canvas_test.cpp).
#pragma once

#include <glm/glm.hpp>

#include "engine/gpu/view.h"

namespace pw::edit {

// A rectangle in window pixels, [min, max).
struct WindowRect {
  glm::dvec2 min{0.0};
  glm::dvec2 max{0.0};
  glm::dvec2 size() const { return max - min; }
  glm::dvec2 centre() const { return 0.5 * (min + max); }
  bool contains(const glm::dvec2& p) const { return p.x >= min.x && p.y >= min.y && p.x < max.x && p.y < max.y; }
  bool empty() const { return max.x <= min.x || max.y <= min.y; }
};

class Canvas {
 public:
  // Screen pixels per photo pixel at most; at least kMaxScale / 2 = 32 is promised.
  static constexpr double kMaxScale = 64.0;
  // One wheel step zooms by this factor (four steps: 2.44x).
  static constexpr double kWheelFactor = 1.25;
  // The smallest scale is this fraction of the fitted one, so that corners far beyond
  // the photo's edges can be brought into view.
  static constexpr double kMinOfFit = 0.25;

  // The canvas's rectangle in the window and the photo's size in pixels; the view
  // fits when first given a size.
  void setArea(const WindowRect& area, glm::ivec2 photoSize);
  const WindowRect& area() const { return area_; }

  // The whole photo in the area, centred, with a margin of 2% on its tighter side.
  void fit();
  // True until the person zooms or pans: a resize then fits again.
  bool fitted() const { return fitted_; }
  double fitScale() const;
  double minScale() const { return kMinOfFit * fitScale(); }

  // Zooms by kWheelFactor^steps (clamped to [minScale, kMaxScale]) about `anchor`
  // (window pixels): the photo point under the anchor stays where it is.
  void zoomAbout(const glm::dvec2& anchor, double steps);
  // Sets the scale (clamped) about `anchor`: 1 shows one photo pixel per screen pixel.
  void setScaleAbout(const glm::dvec2& anchor, double scale);
  void pan(const glm::dvec2& deltaWindowPx);

  const engine::ImageTransform& transform() const { return transform_; }
  double scale() const { return transform_.scale; }
  glm::dvec2 toWindow(const glm::dvec2& photoPx) const { return transform_.offset + transform_.scale * photoPx; }
  glm::dvec2 toPhoto(const glm::dvec2& windowPx) const { return (windowPx - transform_.offset) / transform_.scale; }

 private:
  WindowRect area_;
  glm::ivec2 photoSize_{0};
  engine::ImageTransform transform_;
  bool fitted_ = true;
  bool sized_ = false;
};

// engine::PixelRect from a window rectangle (rounded outwards to whole pixels).
engine::PixelRect pixelRect(const WindowRect& rect);

}  // namespace pw::edit
