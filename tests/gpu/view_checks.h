// Checks shared by the view tests (offscreen in views_offscreen_test.cpp, in a window
// in views_test.cpp): cropping a frame, a test pattern whose every pixel can be told
// from its neighbours, and where an image drawn under a pan/zoom transform must put
// each of its pixels (engine/gpu/view.h).
#pragma once

#include <array>
#include <string>

#include "engine/gpu/view.h"
#include "engine/scene/image.h"

namespace pw::test {

// The w x h part of `image` from (x, y); it must lie inside.
engine::Image crop(const engine::Image& image, int x, int y, int w, int h);

// width x height (each at most 64), pixel (u, v) = (4u, 4v, 255 when u + v is odd else
// 0): each pixel differs from its neighbours by 4/255 or more in red or green and by
// 255 in blue, so a pixel shifted by one, or blended with a neighbour, shows.
engine::Image patternImage(int width, int height);

// Compares the frame's pixels in `rect` with where `view` says `image` lies: each frame
// pixel whose centre maps into image pixel (u, v) must have (u, v)'s colour within
// `tolerance` (or be the opaque background beyond the image). Frame pixels whose centre
// falls within `margin` image pixels of a boundary between image pixels are skipped
// (bilinear filtering blends there; with kNearest use margin 0). Returns "" when all
// match, else the first mismatches.
std::string checkImageLayout(const engine::Image& frame, const engine::Image& image, const engine::ImageTransform& t,
                             const engine::PixelRect& rect, const std::array<uint8_t, 3>& background, int tolerance,
                             double margin);

// The bounding box [x0, x1) x [y0, y1) of the frame pixels of exactly `rgb` inside
// `rect`; x1 == x0 when there are none.
struct PixelBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
PixelBox findColor(const engine::Image& frame, const engine::PixelRect& rect, const std::array<uint8_t, 3>& rgb);

}  // namespace pw::test
