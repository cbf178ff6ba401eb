// The shared POV-Ray corridors: detection against the exact ground truth, and the
// dimensions `measure` gets from the detected shot. Prints the table (ctest -V).
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "metrology/detect/detect.h"
#include "metrology/measure.h"
#include "tests/detect/corridor_cases.h"

namespace pw::metrology::detect {
namespace {

using testing::CorridorCase;
using testing::medianOf;

// Issue 7's targets with the focal length given.
constexpr double kMaxFarCornerMedianPx = 2.0;
constexpr double kMaxVanishingPointPx = 1.0;
constexpr double kMaxWidthHeightPercent = 2.0;

struct Row {
  double farMedianPx = 0, farMaxPx = 0, nearMedianPx = 0, vpPx = 0;
  double widthPct = NAN, heightPct = NAN, lengthPct = NAN;
  std::string status;
};

Shot shotFrom(const CorridorCase& c, const CorridorDetection& d) {
  Shot shot;
  shot.imagePath = c.imagePath;
  shot.imageWidth = c.image.cols;
  shot.imageHeight = c.image.rows;
  shot.focalPx = d.focalPx;
  shot.principalPointPx = d.principalPointPx;
  shot.cameraHeightM = c.cameraHeightM;
  for (int k = 0; k < kCornerCount; ++k) shot.cornersPx[k] = d.corners[k].px;
  return shot;
}

Row evaluate(const CorridorCase& c, const DetectOptions& options) {
  Row row;
  auto d = detectCorridor(c.image, options);
  if (!d) return row.status = "error: " + d.message(), row;
  if (!d->found) return row.status = "not found: " + d->notFoundReason, row;
  std::vector<double> far, near;
  for (int k = 0; k < 4; ++k) far.push_back(glm::length(d->corners[k].px - c.corners[k]));
  for (int k = 4; k < 8; ++k) near.push_back(glm::length(d->corners[k].px - c.corners[k]));
  row.farMedianPx = medianOf(far);
  row.farMaxPx = *std::max_element(far.begin(), far.end());
  row.nearMedianPx = medianOf(near);
  row.vpPx = glm::length(d->corridor.pixel() - c.vanishingPoint);
  auto m = measureCorridor(shotFrom(c, *d));
  if (!m) return row.status = "measure: " + m.message(), row;
  row.widthPct = 100 * (m->size.widthM - c.widthM) / c.widthM;
  row.heightPct = 100 * (m->size.heightM - c.heightM) / c.heightM;
  row.lengthPct = 100 * (m->size.lengthM - c.lengthM) / c.lengthM;
  row.status = std::string("ok, focal ") + focalSourceName(d->focalSource) + " " +
               std::to_string(static_cast<int>(std::lround(d->focalPx))) + " px";
  return row;
}

void printHeader(const char* title) {
  std::printf("\n%s\n%-11s %8s %8s %8s %8s %8s %8s %8s  %s\n", title, "corridor", "P1-4 med", "P1-4 max", "P5-8 med",
              "VP px", "width %", "height %", "length %", "status");
}
void printRow(const std::string& name, const Row& r) {
  std::printf("%-11s %8.3f %8.3f %8.3f %8.3f %+8.2f %+8.2f %+8.2f  %s\n", name.c_str(), r.farMedianPx, r.farMaxPx,
              r.nearMedianPx, r.vpPx, r.widthPct, r.heightPct, r.lengthPct, r.status.c_str());
}

TEST(DetectCorridors, FocalGivenMeetsIssueTargets) {
  const auto cases = testing::loadCorridorCases();
  if (cases.empty()) GTEST_SKIP() << "../shared/corridors is not beside the checkout";
  printHeader("focal length given; P5..P8 on the marked band (default)");
  for (const CorridorCase& c : cases) {
    DetectOptions options;
    options.focalPx = c.focalPx;
    options.principalPointPx = c.principalPoint;
    const Row r = evaluate(c, options);
    printRow(c.name, r);
    ASSERT_EQ(r.status.rfind("ok", 0), 0u) << c.name << ": " << r.status;
    EXPECT_LE(r.farMedianPx, kMaxFarCornerMedianPx) << c.name;
    EXPECT_LE(r.vpPx, kMaxVanishingPointPx) << c.name;
    EXPECT_LE(std::abs(r.widthPct), kMaxWidthHeightPercent) << c.name;
    EXPECT_LE(std::abs(r.heightPct), kMaxWidthHeightPercent) << c.name;
    // The band marks the ground truth's near corners, so length follows too.
    EXPECT_LE(r.nearMedianPx, 2.0) << c.name;
    EXPECT_LE(std::abs(r.lengthPct), 2.0) << c.name;
  }
}

TEST(DetectCorridors, NearCornersAtImageEdgeRule) {
  const auto cases = testing::loadCorridorCases();
  if (cases.empty()) GTEST_SKIP() << "../shared/corridors is not beside the checkout";
  printHeader("focal length given; P5..P8 at the nearest depth inside the photo (--near-at-image-edge)");
  for (const CorridorCase& c : cases) {
    DetectOptions options;
    options.focalPx = c.focalPx;
    options.principalPointPx = c.principalPoint;
    options.nearAtImageEdge = true;
    const Row r = evaluate(c, options);
    printRow(c.name, r);
    ASSERT_EQ(r.status.rfind("ok", 0), 0u) << c.name << ": " << r.status;
    // P1..P4 and so width and height do not depend on where P5..P8 go.
    EXPECT_LE(r.farMedianPx, kMaxFarCornerMedianPx) << c.name;
    EXPECT_LE(std::abs(r.widthPct), kMaxWidthHeightPercent) << c.name;
    EXPECT_LE(std::abs(r.heightPct), kMaxWidthHeightPercent) << c.name;
    // Length is then to an arbitrary depth: nearer the camera than the band.
    EXPECT_GT(r.lengthPct, 0.0) << c.name;
  }
}

TEST(DetectCorridors, FocalWithheldReport) {
  const auto cases = testing::loadCorridorCases();
  if (cases.empty()) GTEST_SKIP() << "../shared/corridors is not beside the checkout";
  printHeader("focal length withheld (a figure, not a target): these views have no second finite vanishing point");
  for (const CorridorCase& c : cases) {
    const Row r = evaluate(c, DetectOptions{});
    printRow(c.name, r);
    ASSERT_EQ(r.status.rfind("ok", 0), 0u) << c.name << ": " << r.status;
    // The image-plane answers do not need the focal length.
    EXPECT_LE(r.farMedianPx, kMaxFarCornerMedianPx) << c.name;
    EXPECT_LE(r.vpPx, kMaxVanishingPointPx) << c.name;
  }
}

}  // namespace
}  // namespace pw::metrology::detect
