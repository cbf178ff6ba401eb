// The parts of detection on inputs with exact answers.
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "metrology/detect/boundaries.h"
#include "metrology/detect/cross_sections.h"
#include "metrology/detect/detect.h"
#include "metrology/detect/edge_fit.h"
#include "metrology/detect/geometry.h"
#include "metrology/detect/line_segments.h"
#include "metrology/detect/room_box.h"
#include "metrology/detect/vanishing_points.h"
#include "metrology/detect/working_image.h"
#include "tests/detect/synthetic_corridor.h"

namespace pw::metrology::detect {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Dark left of x = 99.5, light right of it (pixel centres at integers).
cv::Mat verticalStep() {
  cv::Mat g(200, 200, CV_8U, cv::Scalar(30));
  g(cv::Rect(100, 0, 100, 200)).setTo(210);
  return g;
}

double meanX(const std::vector<LineSegment>& segments) {
  EXPECT_EQ(segments.size(), 1u);
  return segments.empty() ? -1 : 0.5 * (segments[0].a.x + segments[0].b.x);
}

TEST(DetectParts, LineSegmentsAreInFullResolutionPixelCentres) {
  const cv::Mat full = verticalStep();
  EXPECT_NEAR(meanX(detectLineSegments(full, 1.0, 20)), 99.5, 0.05);
  cv::Mat half;
  cv::resize(full, half, cv::Size(), 0.5, 0.5, cv::INTER_AREA);
  EXPECT_NEAR(meanX(detectLineSegments(half, 0.5, 20)), 99.5, 0.1);
}

TEST(DetectParts, LineSegmentsNeedContrast) {
  EXPECT_TRUE(detectLineSegments(cv::Mat(200, 200, CV_8U, cv::Scalar(90)), 1.0, 10).empty());
}

// An antialiased straight edge (8x8 supersampled area coverage) along `line`.
cv::Mat slantedEdge(glm::dvec3 line) {
  cv::Mat img(240, 320, CV_8UC3);
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) {
      int inside = 0;
      for (int sy = 0; sy < 8; ++sy)
        for (int sx = 0; sx < 8; ++sx) inside += glm::dot(line, glm::dvec3(x - 0.4375 + sx / 8.0, y - 0.4375 + sy / 8.0, 1)) > 0;
      const double a = inside / 64.0;
      img.at<cv::Vec3b>(y, x) = cv::Vec3b(cv::saturate_cast<uchar>(40 + 150 * a), cv::saturate_cast<uchar>(60 + 120 * a),
                                          cv::saturate_cast<uchar>(200 - 100 * a));
    }
  return img;
}

// A far wall's foot on a checker floor (corridor_a): the wall (grey) ends at row 100;
// beyond it the floor's first row of tiles, 3 px deep, alternates dark (a strong edge
// at the foot) with a light one nearly the wall's shade (a faint edge), and the next
// row's joint at row 103 is strong everywhere. Half the samples take that joint; the
// fit must still follow the foot, not fall between the two.
TEST(DetectParts, EdgeFitBesideAStrongerEdgeKeepsTheInnerOne) {
  cv::Mat img(200, 320, CV_8UC3, cv::Scalar(170, 175, 170));
  for (int x = 0; x < img.cols; ++x) {
    const bool dark = (x / 40) % 2 == 0;
    img(cv::Rect(x, 100, 1, 3)).setTo(dark ? cv::Scalar(90, 80, 80) : cv::Scalar(200, 205, 205));
    img(cv::Rect(x, 103, 1, 97)).setTo(dark ? cv::Scalar(200, 205, 205) : cv::Scalar(90, 80, 80));
  }
  cv::GaussianBlur(img, img, {0, 0}, 0.5);
  EdgeSearch search;
  search.from = {20, 100.5};
  search.to = {300, 100.5};
  search.through = glm::dvec3(1, 0, 0);  // horizontal
  search.searchPx = 4;
  search.innerPoint = glm::dvec2(160, 40);  // the wall's side
  auto fit = fitEdgeLine(PinholeView(img), search);
  ASSERT_TRUE(fit.has_value());
  // The foot lies between rows 99 and 100: v = 99.5.
  EXPECT_NEAR(-fit->line.z / fit->line.y, 99.5, 0.25);
  // Where the tile is light the foot is too faint beside the joint: half the samples.
  EXPECT_GT(fit->coverage, 0.45);
}

TEST(DetectParts, EdgeFitIsSubPixel) {
  const glm::dvec2 p(160.3, 120.0), dir = glm::normalize(glm::dvec2(0.3, 1.0));
  const glm::dvec3 truth = lineThrough(p, p + dir);
  const cv::Mat img = slantedEdge(truth);
  EdgeSearch search;
  // Start 2 px off, constrained through a far point of the true line.
  const glm::dvec2 offset(2.0 * -dir.y, 2.0 * dir.x);
  search.from = p - 90.0 * dir + offset;
  search.to = p + 90.0 * dir + offset;
  search.through = homogeneous(p + 5000.0 * dir);
  search.searchPx = 4;
  auto fit = fitEdgeLine(PinholeView(img), search);
  ASSERT_TRUE(fit.has_value());
  EXPECT_LT(std::abs(glm::dot(fit->line, homogeneous(p))), 0.05);
  EXPECT_LT(std::abs(glm::dot(fit->line, homogeneous(p + 80.0 * dir))), 0.05);
  EXPECT_GT(fit->coverage, 0.9);
  // Nothing to find on a flat image.
  EXPECT_FALSE(fitEdgeLine(PinholeView(cv::Mat(240, 320, CV_8UC3, cv::Scalar(90, 90, 90))), search).has_value());
}

struct Camera {
  glm::dmat3 worldToCamera;
  glm::dvec3 centre;
  double f;
  glm::dvec2 pp;
  glm::dvec2 project(glm::dvec3 w) const {
    const glm::dvec3 c = worldToCamera * (w - centre);
    return {pp.x + f * c.x / c.z, pp.y - f * c.y / c.z};
  }
  glm::dvec2 vanishing(glm::dvec3 dir) const {
    const glm::dvec3 c = worldToCamera * dir;
    return {pp.x + f * c.x / c.z, pp.y - f * c.y / c.z};
  }
};

Camera turnedCamera() {
  const double y = 10 * kPi / 180, p = -6 * kPi / 180;
  const glm::dmat3 yaw(std::cos(y), 0, -std::sin(y), 0, 1, 0, std::sin(y), 0, std::cos(y));
  const glm::dmat3 pitch(1, 0, 0, 0, std::cos(p), std::sin(p), 0, -std::sin(p), std::cos(p));
  return Camera{glm::transpose(yaw * pitch), {0.2, 1.5, 0}, 600.0, {320, 240}};
}

// Forty lines of each family of a box seen by `cam`: across the corridor, along it,
// vertical, at places drawn from `rng`.
std::vector<LineSegment> projectedBoxLines(const Camera& cam, std::mt19937& rng) {
  std::vector<LineSegment> segments;
  std::uniform_real_distribution<double> u(-1, 1);
  const auto add = [&](glm::dvec3 a, glm::dvec3 b) {
    const glm::dvec2 pa = cam.project(a), pb = cam.project(b);
    segments.push_back({pa, pb, glm::length(pb - pa)});
  };
  for (int i = 0; i < 40; ++i) {
    const double z = 6 + 4 * u(rng), x = 1.2 * u(rng), y = 1.5 + 1.4 * u(rng);
    add({-1.0, y, z}, {1.0, y, z});
    add({x, y, z}, {x, y, z + 2});
    add({x, 0.2, z}, {x, 2.6, z});
  }
  return segments;
}

TEST(DetectParts, ManhattanFrameOfProjectedBoxLines) {
  const Camera cam = turnedCamera();
  std::mt19937 rng(3);
  const std::vector<LineSegment> segments = projectedBoxLines(cam, rng);
  auto frame = estimateManhattanFrame(segments, PinholeCamera{cam.f, cam.pp}, cv::Size(640, 480));
  ASSERT_TRUE(frame.ok()) << frame.message();
  EXPECT_LT(glm::length(frame->corridor.pixel() - cam.vanishing({0, 0, 1})), 0.01);
  EXPECT_LT(glm::length(frame->horizontal.pixel() - cam.vanishing({1, 0, 0})), 1.0);
  EXPECT_LT(glm::length(frame->vertical.pixel() - cam.vanishing({0, 1, 0})), 1.0);
  EXPECT_GT(frame->corridor.confidence, 0.5);
  auto f = focalFromOrthogonalPoints(frame->corridor, frame->horizontal, cam.pp, 800);
  ASSERT_TRUE(f.has_value());
  EXPECT_NEAR(*f, 600.0, 0.5);
}

// A corridor's lines meet in one point even where short edges crowd around it at odd
// angles (a lamp row, a far door's trim): within a few dozen pixels of the point such an
// edge's line to it is ill-defined, and on the Gaussian sphere it is an inlier anyway.
// The spread (rmsAngleDeg) is measured away from the point, so it stays the long
// lines' (before: 4-10 degrees on such corridors, "scattered", and no corridor found).
TEST(DetectParts, ShortEdgesAtTheVanishingPointDoNotScatterItsLines) {
  const Camera cam = turnedCamera();
  std::mt19937 rng(5);
  std::vector<LineSegment> segments = projectedBoxLines(cam, rng);
  std::uniform_real_distribution<double> u(-1, 1);
  const glm::dvec2 vp = cam.vanishing({0, 0, 1});
  auto clean = estimateManhattanFrame(segments, PinholeCamera{cam.f, cam.pp}, cv::Size(640, 480));
  ASSERT_TRUE(clean.ok()) << clean.message();
  EXPECT_LT(clean->corridor.rmsAngleDeg, 0.1);
  // Sixty 10 px edges 12-30 px from the point, each turned 12 degrees from the line
  // to it (the point 2.5-6 px off their lines: within 0.6 degrees on the sphere).
  for (int i = 0; i < 60; ++i) {
    const double around = kPi * u(rng), distance = 21 + 9 * u(rng), turn = (i % 2 ? 12.0 : -12.0) * kPi / 180;
    const glm::dvec2 m = vp + distance * glm::dvec2(std::cos(around), std::sin(around));
    const glm::dvec2 along(std::cos(around + turn), std::sin(around + turn));
    segments.push_back({m - 5.0 * along, m + 5.0 * along, 10.0});
  }
  auto crowded = estimateManhattanFrame(segments, PinholeCamera{cam.f, cam.pp}, cv::Size(640, 480));
  ASSERT_TRUE(crowded.ok()) << crowded.message();
  EXPECT_GT(crowded->corridor.inlierCount, clean->corridor.inlierCount + 40) << "the short edges are inliers";
  EXPECT_LT(glm::length(crowded->corridor.pixel() - vp), 0.5);
  EXPECT_LT(crowded->corridor.rmsAngleDeg, 0.5);
}

// The room's box on a rolled synthetic corridor whose floor boundaries are hidden
// near the camera by two cabinets and whose far wall stands behind a person: the far
// wall's corners to within the full-resolution fit's search (3 px; the box is found
// to the pixel on a rectified copy), the boundaries' support beyond them; and
// detection, which refines it, to within half a pixel.
TEST(DetectParts, RoomBoxFindsTheFarWallBehindClutter) {
  testing::CorridorSpec spec;
  spec.rollDeg = 8;
  spec.yawDeg = 3;
  testing::SyntheticCorridor c = testing::renderCorridor(spec);
  // The cabinets: dark blocks over each floor-wall edge from the image's bottom up to
  // halfway to the far wall's foot; the person: a grey column before the far wall.
  const glm::dvec2 vp = c.vanishingPoint;
  for (int corner : {2, 3}) {
    const glm::dvec2 foot = c.farWall[corner], outer = vp + 3.0 * (foot - vp);
    const glm::dvec2 mid = vp + 1.6 * (foot - vp);
    const std::vector<cv::Point> block = {cv::Point(mid.x - 25, mid.y - 60), cv::Point(mid.x + 25, mid.y - 60),
                                          cv::Point(outer.x + 60, outer.y), cv::Point(outer.x - 60, outer.y)};
    cv::fillConvexPoly(c.image, block, cv::Scalar(60, 70, 90), cv::LINE_AA);
  }
  const glm::dvec2 foot = 0.5 * (c.farWall[2] + c.farWall[3]);
  cv::rectangle(c.image, cv::Rect(static_cast<int>(foot.x) - 8, static_cast<int>(vp.y), 16,
                                  static_cast<int>(foot.y - vp.y) + 60), cv::Scalar(150, 150, 150), cv::FILLED);

  const WorkingImage work = makeWorkingImage(c.image, 1280);
  const std::vector<LineSegment> segments = detectLineSegments(work.gray, work.scale, 0.02 * std::hypot(800, 600));
  auto frame = estimateManhattanFrame(segments, PinholeCamera{spec.focalPx, c.principalPoint}, c.image.size());
  ASSERT_TRUE(frame.ok()) << frame.message();
  auto box = fitRoomBox(work, work.toWorking(frame->corridor.pixel()), frame->horizontal.point, frame->vertical.point,
                        segments, frame->labels);
  ASSERT_TRUE(box.ok()) << box.message();
  for (int k = 0; k < 4; ++k) EXPECT_LT(glm::length(box->corners[k] - c.farWall[k]), 3.0) << "P" << k + 1;
  EXPECT_GT(box->rayOutside[kCeilingLeft], 0.6);
  EXPECT_GT(box->rayOutside[kCeilingRight], 0.6);
  EXPECT_GT(box->rayOutside[kFloorLeft], 0.2);  // the cabinets hide most of the floor's
  EXPECT_GT(box->rayOutside[kFloorRight], 0.2);

  auto d = detectCorridor(c.image, DetectOptions{.focalPx = spec.focalPx, .principalPointPx = c.principalPoint});
  ASSERT_TRUE(d.ok()) << d.message();
  ASSERT_TRUE(d->found) << d->notFoundReason;
  for (int k = 0; k < 4; ++k) EXPECT_LT(glm::length(d->corners[k].px - c.farWall[k]), 0.5) << "P" << k + 1;
}

TEST(DetectParts, ManhattanFrameNeedsSegments) {
  EXPECT_FALSE(estimateManhattanFrame({}, PinholeCamera{600, {320, 240}}, cv::Size(640, 480)).ok());
}

// The worst corner error of the cross-section family through the far wall (z = 14 m) of
// a 2.4 x 2.8 m box seen by `cam`, each boundary's angle `angleOffRad` off, over the
// sections at 14, 8 and 4.5 m.
double worstSectionErrorPx(const Camera& cam, glm::dvec3 horizontal, glm::dvec3 vertical, double angleOffRad) {
  const auto section = [&](double z) {
    return Quad{cam.project({-1.2, 2.8, z}), cam.project({1.2, 2.8, z}), cam.project({-1.2, 0, z}), cam.project({1.2, 0, z})};
  };
  const glm::dvec2 vp = cam.vanishing({0, 0, 1});
  const Quad far = section(14);
  RecedingBoundaries rays;
  for (int b = 0; b < kBoundaryCount; ++b) {
    const glm::dvec2 d = far[std::array{2, 3, 0, 1}[b]] - vp;
    rays.angle[b] = std::atan2(d.y, d.x) + angleOffRad;
  }
  const CrossSectionFamily family(vp, horizontal, vertical, rays);
  double worst = 0;
  for (double z : {14.0, 8.0, 4.5}) {
    const Quad truth = section(z);
    const auto q = family.at(glm::length(truth[2] - vp));
    if (!q) return std::numeric_limits<double>::infinity();
    for (int k = 0; k < 4; ++k) worst = std::max(worst, glm::length((*q)[k] - truth[k]));
  }
  return worst;
}

TEST(DetectParts, CrossSectionFamilyFollowsTheBoxInDepth) {
  const Camera cam = turnedCamera();
  const auto homogeneousVp = [&](glm::dvec3 dir) { return homogeneous(cam.vanishing(dir)); };
  EXPECT_LT(worstSectionErrorPx(cam, homogeneousVp({1, 0, 0}), homogeneousVp({0, 1, 0}), 0.0), 1e-6);
}

// The camera 2 cm from the left wall (the York Urban corridor P1040853): the corridor's
// vanishing point lies on the far wall's left side, and the left boundaries cross the
// verticals through their corners at under a degree. With each boundary found a tenth of
// a degree off, the top corners taken where the verticals through the feet cross the
// ceiling's rays land 15-50 px off; taken round the right side and the top, within 2 px
// (about what the tenth of a degree moves a corner 500 px from the vanishing point).
TEST(DetectParts, CrossSectionFamilyWithAWallSeenEndOnTakesTheCornerRoundTheOtherSide) {
  const Camera endOn{glm::dmat3(1.0), {-1.18, 1.5, 0}, 600.0, {320, 240}};
  // Looking straight down the corridor: the horizontal and vertical points at infinity.
  EXPECT_LT(worstSectionErrorPx(endOn, glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), 0.1 * kPi / 180), 2.0);
}

// Any three of a box's receding boundaries fix the fourth: its cross-section is a
// rectangle whose top and bottom point at the horizontal point and sides at the vertical.
TEST(DetectParts, ThreeBoundariesImplyTheFourth) {
  const Camera cam = turnedCamera();
  const glm::dvec2 vp = cam.vanishing({0, 0, 1});
  const Quad far{cam.project({-1.2, 2.8, 14}), cam.project({1.2, 2.8, 14}), cam.project({-1.2, 0, 14}),
                 cam.project({1.2, 0, 14})};
  RecedingBoundaries rays;
  for (int b = 0; b < kBoundaryCount; ++b) {
    const glm::dvec2 d = far[std::array{2, 3, 0, 1}[b]] - vp;
    rays.angle[b] = std::atan2(d.y, d.x);
  }
  const glm::dvec3 horizontal = homogeneous(cam.vanishing({1, 0, 0})), vertical = homogeneous(cam.vanishing({0, 1, 0}));
  for (int b = 0; b < kBoundaryCount; ++b) {
    RecedingBoundaries off = rays;
    off.angle[b] += 0.3;  // this one on another line: the other three put it back
    const auto implied = impliedBoundaryAngle(off, b, vp, horizontal, vertical);
    ASSERT_TRUE(implied.has_value()) << b;
    EXPECT_NEAR(std::remainder(*implied - rays.angle[b], 2 * kPi), 0.0, 1e-9) << b;
  }
}

// A corridor whose floor and left wall are one colour up to the far wall (no step between
// them in the angular profile): the floor-left boundary is taken where the other three
// put it, within half a degree; detect finds the far wall within a pixel, never sure.
TEST(DetectParts, ABoundaryThatDoesNotShowIsWhereTheOtherThreePutIt) {
  testing::CorridorSpec spec;
  spec.yawDeg = 4;
  spec.pitchDeg = -3;
  spec.noiseSigma = 0;
  testing::SyntheticCorridor c = testing::renderCorridor(spec);
  const cv::Mat original = c.image.clone();
  const glm::dvec2 vp = c.vanishingPoint;
  const glm::dvec2 wallPoint = c.farWall[2] + glm::dvec2(-0.6 * (c.farWall[3].x - c.farWall[2].x), -10);
  const cv::Vec3b wall = original.at<cv::Vec3b>(static_cast<int>(wallPoint.y), static_cast<int>(wallPoint.x));
  // The lower-left quadrant about the vanishing point painted the left wall's colour...
  const std::vector<cv::Point> wedge = {cv::Point(vp.x, vp.y), cv::Point(0, vp.y), cv::Point(0, c.image.rows),
                                        cv::Point(vp.x, c.image.rows)};
  cv::fillConvexPoly(c.image, wedge, cv::Scalar(wall[0], wall[1], wall[2]));
  // ...but for the far wall, as it was.
  cv::Mat inside(c.image.size(), CV_8U, cv::Scalar(0));
  std::vector<cv::Point> far;
  for (int k : {0, 1, 3, 2}) far.emplace_back(std::lround(c.farWall[k].x), std::lround(c.farWall[k].y));
  cv::fillConvexPoly(inside, far, cv::Scalar(255));
  original.copyTo(c.image, inside);

  const WorkingImage work = makeWorkingImage(c.image, 1280);
  const std::vector<LineSegment> segments = detectLineSegments(work.gray, work.scale, 0.02 * std::hypot(800, 600));
  auto frame = estimateManhattanFrame(segments, PinholeCamera{spec.focalPx, c.principalPoint}, c.image.size());
  ASSERT_TRUE(frame.ok()) << frame.message();
  const glm::dvec2 vpWork = work.toWorking(frame->corridor.pixel());
  const glm::dvec2 horizon = directionTowards(frame->horizontal.point, frame->corridor.pixel());
  const double horizonAngle = std::atan2(horizon.y, horizon.x);
  // Alone, the profile finds no floor-left boundary (as before three fixed the fourth)...
  EXPECT_FALSE(findRecedingBoundaries(work, vpWork, horizonAngle).ok());
  // ...and with the box's section points, takes it where the other three put it.
  auto rays = findRecedingBoundaries(work, vpWork, horizonAngle,
                                     std::pair{work.toWorking(frame->horizontal.point), work.toWorking(frame->vertical.point)});
  ASSERT_TRUE(rays.ok()) << rays.message();
  EXPECT_EQ(rays->implied, kFloorLeft);
  const glm::dvec2 truth = work.toWorking(c.farWall[2]) - vpWork;
  EXPECT_LT(std::abs(std::remainder(rays->angle[kFloorLeft] - std::atan2(truth.y, truth.x), 2 * kPi)), 0.5 * kPi / 180);

  auto d = detectCorridor(c.image, DetectOptions{.focalPx = spec.focalPx, .principalPointPx = c.principalPoint});
  ASSERT_TRUE(d.ok()) << d.message();
  ASSERT_TRUE(d->found) << d->notFoundReason;
  for (int k = 0; k < 4; ++k) EXPECT_LT(glm::length(d->corners[k].px - c.farWall[k]), 1.0) << "P" << k + 1;
  EXPECT_FALSE(d->confident);
}

TEST(DetectParts, DetectRejectsInputThatMakesNoSense) {
  const cv::Mat photo(480, 640, CV_8UC3, cv::Scalar(100, 100, 100));
  EXPECT_FALSE(detectCorridor(cv::Mat(), {}).ok());
  EXPECT_FALSE(detectCorridor(cv::Mat(480, 640, CV_8UC1, cv::Scalar(1)), {}).ok());
  EXPECT_FALSE(detectCorridor(cv::Mat(10, 10, CV_8UC3, cv::Scalar(1, 1, 1)), {}).ok());
  EXPECT_FALSE(detectCorridor(photo, DetectOptions{.focalPx = -5.0}).ok());
  EXPECT_FALSE(detectCorridor(photo, DetectOptions{.focalPx = std::nan("")}).ok());
  EXPECT_FALSE(detectCorridor(photo, DetectOptions{.principalPointPx = glm::dvec2(-3, 10)}).ok());
  auto blank = detectCorridor(photo, {});
  ASSERT_TRUE(blank.ok());
  EXPECT_FALSE(blank->found);
}

}  // namespace
}  // namespace pw::metrology::detect
