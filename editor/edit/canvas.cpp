#include "editor/edit/canvas.h"

#include <algorithm>
#include <cmath>

namespace pw::edit {

void Canvas::setArea(const WindowRect& area, glm::ivec2 photoSize) {
  const bool changed = area.min != area_.min || area.max != area_.max || photoSize != photoSize_;
  area_ = area;
  photoSize_ = photoSize;
  if (!sized_ || (changed && fitted_)) fit();
  sized_ = true;
}

double Canvas::fitScale() const {
  if (photoSize_.x <= 0 || photoSize_.y <= 0 || area_.empty()) return 1.0;
  const glm::dvec2 size = area_.size();
  return 0.98 * std::min(size.x / photoSize_.x, size.y / photoSize_.y);
}

void Canvas::fit() {
  transform_.scale = fitScale();
  // The photo covers [-0.5, size - 0.5] in photo pixels; its centre goes to the area's.
  const glm::dvec2 photoCentre = 0.5 * glm::dvec2(photoSize_ - 1);
  transform_.offset = area_.centre() - transform_.scale * photoCentre;
  fitted_ = true;
}

void Canvas::setScaleAbout(const glm::dvec2& anchor, double scale) {
  const double clamped = std::clamp(scale, minScale(), std::max(minScale(), kMaxScale));
  // offset' = m - (m - offset) * s' / s: the point under m stays at m.
  transform_.offset = anchor - (anchor - transform_.offset) * (clamped / transform_.scale);
  transform_.scale = clamped;
  fitted_ = false;
}

void Canvas::zoomAbout(const glm::dvec2& anchor, double steps) {
  setScaleAbout(anchor, transform_.scale * std::pow(kWheelFactor, steps));
}

void Canvas::pan(const glm::dvec2& delta) {
  transform_.offset += delta;
  fitted_ = false;
}

engine::PixelRect pixelRect(const WindowRect& rect) {
  const int x0 = static_cast<int>(std::floor(rect.min.x)), y0 = static_cast<int>(std::floor(rect.min.y));
  const int x1 = static_cast<int>(std::ceil(rect.max.x)), y1 = static_cast<int>(std::ceil(rect.max.y));
  return {x0, y0, std::max(1, x1 - x0), std::max(1, y1 - y0)};
}

}  // namespace pw::edit
