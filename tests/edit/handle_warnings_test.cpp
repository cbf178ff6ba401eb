// Warnings on the handles (editor/edit/handle_warnings.h), without a window: each kind
// on a corner set made for it, degenerate sets that must neither crash nor print a NaN,
// and none on a real corridor's exact corners.
#include "editor/edit/handle_warnings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "editor/edit/live_measurement.h"
#include "tests/support/groundtruth.h"

namespace pw::edit {
namespace {

using metrology::P1;
using metrology::P2;
using metrology::P3;
using metrology::P4;
using metrology::P5;
using metrology::P6;
using metrology::P7;
using metrology::P8;

metrology::Shot corridorShot() {
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
  metrology::Shot shot;
  shot.imageWidth = truth.imageWidth;
  shot.imageHeight = truth.imageHeight;
  shot.focalPx = truth.focalPx;
  shot.principalPointPx = truth.principalPointPx;
  shot.cameraHeightM = truth.cameraHeightM;
  shot.cornersPx = truth.cornersPx;
  return shot;
}

const HandleWarning* findLabel(const std::vector<HandleWarning>& warnings, const std::string& label) {
  for (const HandleWarning& w : warnings) {
    if (w.label == label) return &w;
  }
  return nullptr;
}

std::string all(const std::vector<HandleWarning>& warnings) {
  std::string s;
  for (const HandleWarning& w : warnings) s += "[" + w.label + "] " + w.text + "\n";
  return s.empty() ? "none" : s;
}

// No "nan" or "inf" in any text a person reads.
void expectReadable(const LiveMeasurement& live) {
  const auto bad = [](const std::string& s) {
    std::string lower = s;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    return lower.find("nan") != std::string::npos || lower.find("inf") != std::string::npos;
  };
  for (const HandleWarning& w : live.handleWarnings) {
    EXPECT_FALSE(bad(w.text)) << w.text;
    EXPECT_FALSE(w.label.empty());
    EXPECT_FALSE(w.handles.empty()) << w.text;
  }
  for (const std::string& w : live.warnings) EXPECT_FALSE(bad(w)) << w;
  EXPECT_FALSE(bad(live.error)) << live.error;
  if (live.measurement) {
    EXPECT_TRUE(std::isfinite(live.measurement->size.widthM) && std::isfinite(live.measurement->size.lengthM));
  }
}

TEST(HandleWarnings, NoneOnAnExactCorridor) {
  const metrology::Shot shot = corridorShot();
  const LiveMeasurement live = measureLive(shot);
  ASSERT_TRUE(live.measurement) << live.error;
  EXPECT_TRUE(live.handleWarnings.empty()) << all(live.handleWarnings);
}

TEST(HandleWarnings, AllCornersEqualIsOneBlockingWarningOnEveryHandle) {
  metrology::Shot shot = corridorShot();
  shot.cornersPx.fill(glm::dvec2(300, 200));
  const LiveMeasurement live = measureLive(shot);
  EXPECT_FALSE(live.measurement);
  expectReadable(live);
  ASSERT_EQ(live.handleWarnings.size(), 1u) << all(live.handleWarnings);
  EXPECT_TRUE(live.handleWarnings[0].blocking);
  EXPECT_EQ(live.handleWarnings[0].handles.size(), 8u);
  EXPECT_NE(live.handleWarnings[0].text.find("lie on one point"), std::string::npos);
}

TEST(HandleWarnings, TwoCornersOnOnePoint) {
  metrology::Shot shot = corridorShot();
  shot.cornersPx[P6] = shot.cornersPx[P5] + glm::dvec2(0.2, 0.1);
  const LiveMeasurement live = measureLive(shot);
  expectReadable(live);
  const HandleWarning* w = findLabel(live.handleWarnings, "P5 = P6");
  ASSERT_TRUE(w) << all(live.handleWarnings);
  EXPECT_TRUE(w->blocking);
  EXPECT_EQ(w->handles, (std::vector<int>{P5, P6}));
}

TEST(HandleWarnings, ACornerOnAFarWallLineNamesItAndTheLine) {
  metrology::Shot shot = corridorShot();
  // P5 on the line through P3 and P4, beyond P3.
  shot.cornersPx[P5] = shot.cornersPx[P3] + 1.5 * (shot.cornersPx[P3] - shot.cornersPx[P4]);
  const LiveMeasurement live = measureLive(shot);
  EXPECT_FALSE(live.measurement);
  expectReadable(live);
  const HandleWarning* w = findLabel(live.handleWarnings, "on P3-P4");
  ASSERT_TRUE(w) << all(live.handleWarnings);
  EXPECT_TRUE(w->blocking);
  EXPECT_EQ(w->handles, std::vector<int>{P5});
  EXPECT_EQ(w->related, (std::vector<int>{P3, P4}));
  EXPECT_EQ(w->text.rfind("P5 is on the line P3-P4 (0.0 px from it)", 0), 0u) << w->text;
}

TEST(HandleWarnings, AlmostOnALineSaysHowUncertainTheLengthIs) {
  metrology::Shot shot = corridorShot();
  auto measured = metrology::measureCorridor(shot);
  ASSERT_TRUE(measured) << measured.message();
  metrology::Measurement m = *measured;
  // P5 1.5 degrees off the line P3-P4, seen from P3; a length uncertain to 40%.
  const glm::dvec2 along = shot.cornersPx[P3] - shot.cornersPx[P4];
  const double angle = glm::radians(1.5);
  const glm::dvec2 turned(along.x * std::cos(angle) + along.y * std::sin(angle),
                          -along.x * std::sin(angle) + along.y * std::cos(angle));
  shot.cornersPx[P5] = shot.cornersPx[P3] + 1.5 * turned;
  // The corners' share of the sigma is what moving a corner changes (metrology::cornerSigma).
  ASSERT_FALSE(m.sigmaSources.empty());
  ASSERT_EQ(m.sigmaSources[0].key, "corners");
  m.sigma.lengthM = m.sigmaSources[0].sigma.lengthM = 0.4 * m.size.lengthM;
  const std::vector<HandleWarning> warnings = handleWarnings(shot, &m);
  const HandleWarning* w = findLabel(warnings, "on P3-P4");
  ASSERT_TRUE(w) << all(warnings);
  EXPECT_FALSE(w->blocking);
  EXPECT_EQ(w->dimension, "length");
  EXPECT_EQ(w->text.rfind("P5 is almost on the line P3-P4 (", 0), 0u) << w->text;
  EXPECT_NE(w->text.find("the length is uncertain to +-40%"), std::string::npos) << w->text;
  // The same corners with a length known to 2%: nothing to act on.
  m.sigma.lengthM = m.sigmaSources[0].sigma.lengthM = 0.02 * m.size.lengthM;
  EXPECT_FALSE(findLabel(handleWarnings(shot, &m), "on P3-P4")) << all(handleWarnings(shot, &m));
  // A length uncertain to 40% from an assumed focal length, the corners' share 2%: the
  // corners are not what to move.
  m.sigma.lengthM = 0.4 * m.size.lengthM;
  EXPECT_FALSE(findLabel(handleWarnings(shot, &m), "on P3-P4")) << all(handleWarnings(shot, &m));
}

TEST(HandleWarnings, ACameraNearTheFloorMakesTheLengthUncertainOnTheHandleToMove) {
  // corridor_b seen from nearer the floor, exactly: the camera looks straight ahead, so
  // a corner's v - cy scales with its height over the camera's (floor: h'/h, ceiling:
  // (H - h')/(H - h)). Near the floor, P5 and P6 come close to the line P3-P4.
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
  ASSERT_TRUE(truth.straightAhead());
  std::string said;
  // Measured: the length +-6.8% at 0.12 m (no warning), +-14% at 0.06 m.
  for (const double heightM : {0.12, 0.06}) {
    metrology::Shot s = corridorShot();
    s.cameraHeightM = heightM;
    const double cy = truth.principalPointPx.y;
    for (int k : {P3, P4, P5, P6}) s.cornersPx[k].y = cy + (s.cornersPx[k].y - cy) * heightM / truth.cameraHeightM;
    for (int k : {P1, P2, P7, P8}) {
      s.cornersPx[k].y = cy + (s.cornersPx[k].y - cy) * (truth.heightM - heightM) / (truth.heightM - truth.cameraHeightM);
    }
    const LiveMeasurement live = measureLive(s);
    expectReadable(live);
    ASSERT_TRUE(live.measurement) << heightM << ": " << live.error;
    EXPECT_NEAR(live.measurement->size.lengthM, truth.lengthM, 1e-6 * truth.lengthM);
    const double sigma = live.measurement->sigma.lengthM / live.measurement->size.lengthM;
    const HandleWarning* w = findLabel(live.handleWarnings, "on P3-P4");
    if (heightM > 0.1) {  // a length still known to 10%: nothing to act on
      EXPECT_LE(sigma, 0.10) << heightM;
      EXPECT_FALSE(w) << heightM << ": " << all(live.handleWarnings);
      said += "camera at " + std::to_string(heightM) + " m: length known to " + std::to_string(100 * sigma) + "%\n";
      continue;
    }
    EXPECT_GT(sigma, 0.10) << heightM;
    ASSERT_TRUE(w) << heightM << " m, length +-" << 100 * sigma << "%: " << all(live.handleWarnings);
    EXPECT_FALSE(w->blocking);
    EXPECT_TRUE(w->handles[0] == P5 || w->handles[0] == P6);
    EXPECT_EQ(w->dimension, "length");
    char percent[48];
    std::snprintf(percent, sizeof percent, "the length is uncertain to +-%.0f%%", 100 * sigma);
    EXPECT_NE(w->text.find(percent), std::string::npos) << w->text;
    // Said once, on the handle, not again among the general warnings.
    for (const std::string& line : live.warnings) EXPECT_EQ(line.find("the length is uncertain"), std::string::npos);
    said += w->text + "\n";
  }
  std::printf("%s", said.c_str());
}

TEST(HandleWarnings, CrossedQuadNamesTheCornersThatLookSwapped) {
  metrology::Shot shot = corridorShot();
  std::swap(shot.cornersPx[P5], shot.cornersPx[P6]);
  const LiveMeasurement live = measureLive(shot);
  EXPECT_FALSE(live.measurement);
  expectReadable(live);
  bool namedFloor = false;
  for (const HandleWarning& w : live.handleWarnings) {
    if (w.label != "crossed") continue;
    EXPECT_TRUE(w.blocking);
    if (w.text.find("floor quad P3-P4-P6-P5 crosses itself: P6 and P5 look swapped") != std::string::npos) namedFloor = true;
  }
  EXPECT_TRUE(namedFloor) << all(live.handleWarnings);
}

TEST(HandleWarnings, NearAndFarSwappedPutsTheVanishingPointBehindTheCamera) {
  metrology::Shot shot = corridorShot();
  for (int k = 0; k < 4; ++k) std::swap(shot.cornersPx[k], shot.cornersPx[k + 4]);
  // P1..P4 <-> P5..P8 keeps top/bottom and left/right: P1<->P5 would swap top and bottom.
  std::swap(shot.cornersPx[P1], shot.cornersPx[P3]);
  std::swap(shot.cornersPx[P2], shot.cornersPx[P4]);
  std::swap(shot.cornersPx[P5], shot.cornersPx[P7]);
  std::swap(shot.cornersPx[P6], shot.cornersPx[P8]);
  const LiveMeasurement live = measureLive(shot);
  EXPECT_FALSE(live.measurement);
  expectReadable(live);
  const HandleWarning* w = findLabel(live.handleWarnings, "VP behind");
  ASSERT_TRUE(w) << all(live.handleWarnings);
  EXPECT_TRUE(w->blocking);
  EXPECT_EQ(w->handles, (std::vector<int>{P1, P2, P3, P4}));
  EXPECT_NE(w->text.find("behind the camera"), std::string::npos);
}

TEST(HandleWarnings, PrincipalPointOutsideThePhoto) {
  metrology::Shot shot = corridorShot();
  shot.principalPointPx = glm::dvec2(-40, 100);
  const LiveMeasurement live = measureLive(shot);
  expectReadable(live);
  const HandleWarning* w = findLabel(live.handleWarnings, "outside");
  ASSERT_TRUE(w) << all(live.handleWarnings);
  EXPECT_FALSE(w->blocking);
  EXPECT_EQ(w->handles, std::vector<int>{kPrincipalPointHandle});
}

TEST(HandleWarnings, TheCornerOffTheBoxIsMarked) {
  metrology::Shot shot = corridorShot();
  shot.cornersPx[P6] += glm::dvec2(25, -20);
  const LiveMeasurement live = measureLive(shot);
  ASSERT_TRUE(live.measurement) << live.error;
  const HandleWarning* w = findLabel(live.handleWarnings, "off the box");
  ASSERT_TRUE(w) << all(live.handleWarnings);
  EXPECT_EQ(w->handles, std::vector<int>{P6});
  EXPECT_NE(w->text.find("check P6 first"), std::string::npos) << w->text;
  for (const std::string& line : live.warnings) EXPECT_EQ(line.find("one box"), std::string::npos) << line;
}

TEST(HandleWarnings, DegenerateCornerSetsNeverCrashNorPrintNaN) {
  const metrology::Shot base = corridorShot();
  std::mt19937 random(13);
  std::uniform_real_distribution<double> u(-0.2 * base.imageWidth, 1.2 * base.imageWidth);
  std::uniform_real_distribution<double> v(-0.2 * base.imageHeight, 1.2 * base.imageHeight);
  std::uniform_int_distribution<int> corner(0, 7);
  for (int trial = 0; trial < 300; ++trial) {
    metrology::Shot shot = base;
    switch (trial % 4) {
      case 0:  // random corners
        for (auto& p : shot.cornersPx) p = {u(random), v(random)};
        break;
      case 1:  // all on one line
        for (int k = 0; k < 8; ++k) shot.cornersPx[k] = glm::dvec2(10.0 + 37.0 * k, 20.0 + 11.0 * k);
        break;
      case 2:  // some corners on others
        for (int i = 0; i < 3; ++i) shot.cornersPx[corner(random)] = shot.cornersPx[corner(random)];
        break;
      case 3:  // one corner anywhere
        shot.cornersPx[corner(random)] = {u(random), v(random)};
        break;
    }
    const LiveMeasurement live = measureLive(shot);
    expectReadable(live);
    EXPECT_TRUE(live.measurement || !live.error.empty()) << trial;
  }
}

// The warnings name the corner that moved (issue 23's findings: P1 dragged onto P2 said
// "P5 is almost on the line P1-P3"; P3 dragged above P1 said "P2 and P4 look swapped").
// Every warning whose corners include the one moved tells a person to move that one.
void expectEveryWarningNames(const metrology::Shot& shot, int moved) {
  const LiveMeasurement live = measureLive(shot, {}, moved);
  ASSERT_FALSE(live.handleWarnings.empty()) << metrology::cornerName(moved);
  for (const HandleWarning& w : live.handleWarnings) {
    const bool concerns = std::find(w.handles.begin(), w.handles.end(), moved) != w.handles.end() ||
                          std::find(w.related.begin(), w.related.end(), moved) != w.related.end();
    if (!concerns) continue;
    EXPECT_EQ(w.handles, std::vector<int>{moved}) << w.text;
    EXPECT_NE(w.text.find(metrology::cornerName(moved)), std::string::npos) << w.text;
    EXPECT_LT(w.text.find(metrology::cornerName(moved)), 12u) << "names " << metrology::cornerName(moved)
                                                              << " first: " << w.text;
  }
}

TEST(HandleWarnings, TheyNameTheCornerThatMoved) {
  metrology::Shot ontoP2 = corridorShot();
  ontoP2.cornersPx[P1] = ontoP2.cornersPx[P2] + glm::dvec2(-1, 20);  // onto the line P2-P4
  expectEveryWarningNames(ontoP2, P1);

  metrology::Shot aboveP1 = corridorShot();
  aboveP1.cornersPx[P3] = aboveP1.cornersPx[P1] + glm::dvec2(0, -30);
  expectEveryWarningNames(aboveP1, P3);
  const LiveMeasurement live = measureLive(aboveP1, {}, P3);
  const HandleWarning* crossedWarning = findLabel(live.handleWarnings, "crossed");
  ASSERT_TRUE(crossedWarning) << all(live.handleWarnings);
  EXPECT_EQ(crossedWarning->text.find("P2 and P4"), std::string::npos) << crossedWarning->text;
}

}  // namespace
}  // namespace pw::edit
