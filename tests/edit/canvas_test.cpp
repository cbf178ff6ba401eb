// The canvas's pan and zoom, the loupe's placement, handle picking and the warnings,
// without a window.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "editor/edit/canvas.h"
#include "editor/edit/overlay.h"
#include "editor/edit/warnings.h"
#include "metrology/measure.h"
#include "tests/support/groundtruth.h"

namespace pw::edit {
namespace {

Canvas canvasFor(glm::ivec2 photo, WindowRect area = {{0, 0}, {700, 600}}) {
  Canvas canvas;
  canvas.setArea(area, photo);
  return canvas;
}

TEST(Canvas, FitCentresTheWholePhoto) {
  const Canvas canvas = canvasFor({1024, 768});
  EXPECT_DOUBLE_EQ(canvas.scale(), 0.98 * 700.0 / 1024);  // width is the tighter side
  // The photo's edges, half a pixel beyond the outer pixel centres, sit symmetrically.
  const glm::dvec2 topLeft = canvas.toWindow({-0.5, -0.5}), bottomRight = canvas.toWindow({1023.5, 767.5});
  EXPECT_NEAR(topLeft.x, 700 - bottomRight.x, 1e-9);
  EXPECT_NEAR(topLeft.y, 600 - bottomRight.y, 1e-9);
  EXPECT_NEAR(bottomRight.x - topLeft.x, 0.98 * 700, 1e-9);
  EXPECT_TRUE(canvas.fitted());
}

TEST(Canvas, WheelZoomKeepsThePointUnderTheCursor) {
  Canvas canvas = canvasFor({4000, 3000});
  const glm::dvec2 anchors[] = {{10, 20}, {350, 300}, {699, 599}, {600, 5}};
  double steps = 3;
  for (const glm::dvec2& anchor : anchors) {
    const glm::dvec2 under = canvas.toPhoto(anchor);
    const double before = canvas.scale();
    canvas.zoomAbout(anchor, steps);
    EXPECT_NEAR(canvas.scale(), before * std::pow(Canvas::kWheelFactor, steps), 1e-12 * before);
    EXPECT_LT(glm::length(canvas.toWindow(under) - anchor), 1e-9);
    steps = -steps + 1;
  }
  EXPECT_FALSE(canvas.fitted());
}

TEST(Canvas, ZoomStopsAt64xAndAQuarterOfTheFit) {
  Canvas canvas = canvasFor({12000, 9000});  // a 108-megapixel photo: fit is 0.057
  const glm::dvec2 anchor(123, 456);
  const glm::dvec2 under = canvas.toPhoto(anchor);
  canvas.zoomAbout(anchor, 100);
  EXPECT_EQ(canvas.scale(), Canvas::kMaxScale);
  EXPECT_GE(canvas.scale(), 32.0);  // the promise: at least 32 screen px per photo px
  EXPECT_LT(glm::length(canvas.toWindow(under) - anchor), 1e-6);
  canvas.zoomAbout(anchor, -200);
  EXPECT_DOUBLE_EQ(canvas.scale(), Canvas::kMinOfFit * canvas.fitScale());
  EXPECT_LT(glm::length(canvas.toWindow(under) - anchor), 1e-6);
  canvas.setScaleAbout(anchor, 1.0);
  EXPECT_EQ(canvas.scale(), 1.0);
  canvas.fit();
  EXPECT_DOUBLE_EQ(canvas.scale(), canvas.fitScale());
}

TEST(Canvas, ResizeRefitsUntilThePersonZoomsOrPans) {
  Canvas canvas = canvasFor({1000, 1000});
  canvas.setArea({{0, 0}, {400, 400}}, {1000, 1000});
  EXPECT_DOUBLE_EQ(canvas.scale(), 0.98 * 0.4);
  canvas.pan({5, 0});
  const engine::ImageTransform kept = canvas.transform();
  canvas.setArea({{0, 0}, {800, 800}}, {1000, 1000});
  EXPECT_EQ(canvas.transform().scale, kept.scale);
  EXPECT_EQ(canvas.transform().offset, kept.offset);
}

TEST(Loupe, ShowsAtLeast8ScreenPixelsPerPhotoPixelWithTheCornerAtItsCentre) {
  for (const glm::ivec2 photo : {glm::ivec2(640, 480), glm::ivec2(4000, 3000), glm::ivec2(12000, 9000)}) {
    Canvas canvas = canvasFor(photo);
    for (double steps : {0.0, 8.0, 30.0}) {
      canvas.zoomAbout({350, 300}, steps);
      const glm::dvec2 corner(0.3 * photo.x, 0.7 * photo.y);
      const Loupe loupe = placeLoupe(canvas, corner, 4, canvas.toWindow(corner));
      EXPECT_GE(loupe.transform.scale, Loupe::kMinScale) << photo.x << " at " << canvas.scale();
      EXPECT_GE(loupe.transform.scale, std::min(Loupe::kMaxScale, 3.5 * canvas.scale()));
      EXPECT_EQ(loupe.transform.scale, std::round(loupe.transform.scale));  // whole pixels: even squares
      const glm::dvec2 shown = loupe.transform.offset + loupe.transform.scale * corner;
      EXPECT_LT(glm::length(shown - loupe.centre()), 1e-9);
      EXPECT_GE(loupe.rect.min.x, canvas.area().min.x);
      EXPECT_LE(loupe.rect.max.y, canvas.area().max.y);
    }
  }
}

TEST(Loupe, StaysBesideTheCursorAndInsideTheCanvas) {
  const Canvas canvas = canvasFor({1024, 768});
  const Loupe middle = placeLoupe(canvas, {500, 400}, 0, {200, 200});
  EXPECT_EQ(middle.rect.min, glm::dvec2(228, 228));  // below and to the right
  const Loupe corner = placeLoupe(canvas, {500, 400}, 0, {690, 590});
  EXPECT_LE(corner.rect.max.x, 690.0);  // flipped to the left and above
  EXPECT_LE(corner.rect.max.y, 590.0);
  EXPECT_FALSE(corner.rect.contains({690, 590}));
}

TEST(Handles, ThePressTakesTheNearestHandleWithinItsRadius) {
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
  metrology::Shot shot;
  shot.cornersPx = truth.cornersPx;
  const Canvas canvas = canvasFor({truth.imageWidth, truth.imageHeight});
  const glm::dvec2 p5 = canvas.toWindow(shot.cornersPx[metrology::P5]);
  EXPECT_EQ(handleAt(canvas, shot, p5 + glm::dvec2(5, -5), 12), metrology::P5);
  EXPECT_EQ(handleAt(canvas, shot, p5 + glm::dvec2(13, 0), 12), -1);
  EXPECT_EQ(cornerRole(metrology::P5), CornerRole::kNearFloor);
  EXPECT_EQ(cornerRole(metrology::P8), CornerRole::kNearCeiling);
  EXPECT_EQ(cornerRole(metrology::P3), CornerRole::kFarWall);
  // Neighbours are symmetric: an edge seen from both of its ends.
  for (int k = 0; k < metrology::kCornerCount; ++k) {
    for (int n : cornerNeighbours(k)) {
      const auto back = cornerNeighbours(n);
      EXPECT_NE(std::find(back.begin(), back.end(), k), back.end()) << k << " " << n;
    }
  }
}

TEST(Warnings, NoneForExactCornersAndTheMisplacedCornerNamedWhenOneIsOff) {
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
  metrology::Shot shot;
  shot.imageWidth = truth.imageWidth;
  shot.imageHeight = truth.imageHeight;
  shot.focalPx = truth.focalPx;
  shot.principalPointPx = truth.principalPointPx;
  shot.cameraHeightM = truth.cameraHeightM;
  shot.cornersPx = truth.cornersPx;
  auto exact = metrology::measureCorridor(shot);
  ASSERT_TRUE(exact.ok()) << exact.message();
  EXPECT_TRUE(measurementWarnings(shot, *exact).empty());

  for (int k = 0; k < metrology::kCornerCount; ++k) {
    metrology::Shot off = shot;
    off.cornersPx[k] += glm::dvec2(k % 2 ? 25 : -25, k < 4 ? 8 : -20);
    auto measured = metrology::measureCorridor(off);
    ASSERT_TRUE(measured.ok()) << measured.message();
    const std::vector<std::string> warnings = measurementWarnings(off, *measured);
    bool named = false;
    for (const std::string& w : warnings) {
      named |= w.find(std::string("check ") + metrology::cornerName(k) + " first") != std::string::npos;
    }
    EXPECT_TRUE(named) << metrology::cornerName(k) << ": " << (warnings.empty() ? "no warning" : warnings[0]);
  }
}

}  // namespace
}  // namespace pw::edit
