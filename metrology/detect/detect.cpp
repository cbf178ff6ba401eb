#include "metrology/detect/detect.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <vector>

#include <opencv2/core.hpp>

#include "metrology/detect/boundaries.h"
#include "metrology/detect/cross_sections.h"
#include "metrology/detect/distortion.h"
#include "metrology/detect/geometry.h"
#include "metrology/detect/layout_net.h"
#include "metrology/detect/line_segments.h"
#include "metrology/detect/refine.h"
#include "metrology/detect/room_box.h"
#include "metrology/detect/working_image.h"
#include "metrology/shot.h"

namespace pw::metrology::detect {
namespace {

constexpr double kMinSegmentLengthOfDiagonal = 0.02;
// A corridor's vanishing point has receding lines arriving from most directions
// (floor, both walls, ceiling): below this (see estimateManhattanFrame) it is the
// meeting point of a few unrelated lines.
constexpr double kMinCorridorConfidence = 0.15;
constexpr int kMinPhotoSidePx = 32;
// Inlier segments of a true vanishing point agree with it to a degree or so (the
// five test corridors: 0.2-1.1); a "point" fitted to unrelated lines does not.
// Up to the loose limit (noise and JPEG blocks bend short segments) it is a doubt.
constexpr double kMaxCorridorRmsAngleDeg = 2.0;
constexpr double kMaxLooseCorridorRmsAngleDeg = 3.0;
// Each far-wall side must be an edge over this share of its middle stretch.
constexpr double kMinFarSideCoverage = 0.3;
// Boundaries other than the set the angular profile took (RecedingBoundaries::
// alternatives) are taken where their far wall scores this much more (findFarWall's
// score: the sides' edge coverage and how the boundaries run on beyond the corners).
constexpr double kAlternativeFarWallGain = 0.1;
// A sure answer: the far wall's top and sides seen along most of their length, its
// foot (which clutter hides first) along half, and at least three of the four
// boundaries running on from its corners.
constexpr double kSureFarSideCoverage = 0.6;
constexpr double kSureBottomSideCoverage = 0.5;
constexpr double kSureBoundaryCoverage = 0.5;
constexpr int kSureBoundaries = 3;
// A room's box divides surfaces along two of its four boundaries at least: an answer
// along fewer is a rectangle among other edges (tests/data/detect/camera.png: a lawn
// behind a tripod). TUNE 0-599: none of the 18 clean and 17 noisy answers with 0 or 1
// was right (with 2, 6 of 40 and 4 of 38).
constexpr int kMinDividingBoundaries = 2;
constexpr double kRunOnCoverage = 0.5;  // of the stretch just inside a far corner
// A focal length from a second vanishing point: the corridor's point at least this
// share of the long side from the principal point along the second one's direction,
// and the estimate settled to this share within kFocalIterations refits.
constexpr double kMinSecondPointOffsetOfLongSide = 0.02;
constexpr double kFocalSettledShare = 0.005;
constexpr int kFocalIterations = 5;
// With the focal length withheld, the finite points are refitted in the image to the
// segments pointing at them within these angles, coarse to fine (York Urban training
// half, york_urban_bench: the focal length's median error 21.4% -> 5.7%, 24 of 51
// within 5%; through the CLI on the photos as PNG, 4.8% and 26 against 6.0% and 22 at
// Lu et al.'s fixed 6 degrees).
constexpr std::array<double, 3> kPointClusterDeg = {10.0, 6.0, 3.0};
// An end's corners where the boundaries meet the far wall's sides (completeFromFarWall):
// the boundaries looked for within this of the rays through the corners found, and the
// corners moved when both of a side's are beyond it by more than kEndBeyondSidePx and
// less than this share of the far wall's height (farther is another wall's line).
constexpr double kEndSearchRad = 6.0 * 3.14159265358979 / 180;
constexpr double kEndBeyondSidePx = 1.0;
constexpr double kEndBeyondSideOfSide = 0.3;
// A person's box whose two ends' boundaries meet the sides further apart than this is
// levelled to the farther (completeFromFarWall).
constexpr double kEndDisagreePx = 5.0;
// Two fits whose far walls are within this (pixels, worst corner) agree.
constexpr double kAgreementPx = 2.0;
// The layout network (layout_net.h) against an answer of the edges that is not sure:
// within kLayoutAgreesPx (worst far corner) the answer is made sure. Where the edges
// found no box, the network's box fitted to the edges is taken as a guess where it lands
// within kLayoutFittedWithinPx of the network's (median far corner). Chosen on TUNE
// 450-599, seeds the networks were not trained on (trained on 0-449): agreeing within
// 2.5 px made 3 wrong answers sure, within 2 px none (14 right ones).
constexpr double kLayoutAgreesPx = 2.0;
constexpr double kLayoutFittedWithinPx = 20.0;
// The network's box as it put it: its far corners' error (median of four) on TUNE
// 450-599, 68th percentile (its median 3.5 px).
constexpr double kLayoutGuessSigmaPx = 7.0;
// The network's far wall as put, each side moved onto the photo's edge within
// kLayoutSnapPx of it where one shows along kLayoutSnapCoverage of the side or more, and
// the box so where three of its four sides or more are (layoutSnapped). Seeds 600-1399
// (tuning data), the 64 answers that were the network's box as put: right 1 -> 9, none
// lost, within 3 px 6 -> 13 (4 px: 5 right; 8 px with two sides: 9; four sides needed
// at 0.5: 7).
constexpr double kLayoutSnapPx = 6.0;
constexpr double kLayoutSnapCoverage = 0.3;
constexpr int kLayoutSnapSides = 3;
// An unsure answer of the edges against the network's box fitted to the edges, each side
// looked for within kLayoutFitReachPx of where the network put it (TUNE 450-599, the 132
// scenes the network looked at: that fit within 2 px on 74, against 70 at a person's 25
// px and 56 at 6 px). The fitted box, or where it strays more than kLayoutFitStraysPx
// (median far corner) from the network's, the network's box as it put it, replaces the
// edges' answer where the network finds that answer's far wall less likely than it by
// kLayoutPrefersBy or more (mean log-probability per pixel in the far wall's
// neighbourhood) and less likely in the whole photo too (layoutOverEdges). Chosen on
// TUNE 450-599 (0.2-0.4 tried: 0.3 mends 8 clean and 3 noisy answers there, breaks none);
// checked on seeds 600-1399 (498 -> 518 right: +21, -1).
constexpr double kLayoutFitReachPx = 12.0;
constexpr double kLayoutFitStraysPx = 12.0;
constexpr double kLayoutPrefersBy = 0.3;
// The fitted box (where it holds near the network's) replaces the edges' answer also
// where the network finds that answer less likely than it by kLayoutFitPrefersBy near
// the far wall, and no likelier in the whole photo: two looks at the photo, the
// network's and the edges' near where it put the box, against the edges' alone. Chosen
// on seeds 600-1399 (0.12: +5 -0 clean, the edges' answers it replaced 8-133 px off;
// 0.08: one more right answer moved off); with kSkirtingFirstStepShare, +8 -3 noisy there,
// and TUNE 450-599 +1 -1 clean, +2 -1 noisy (529: a glazed end's frame taken, 18 px off,
// where the edges were right).
constexpr double kLayoutFitPrefersBy = 0.12;
// Where the edges do not bear the network's box out (the fit strays or finds nothing),
// the whole photo's look has to find the edges' far wall less likely by this too: on the
// tests' synthetic corridor with a door in its far wall (another renderer), the network
// puts the far wall on the door, 40 px inside the edges' right answer, 0.33 likelier near
// it and only 0.03 in the whole photo (DetectParts.ABoundaryThatDoesNotShowIsWhereTheOtherThreePutIt);
// on TUNE 450-599 the answers it mends there differ by 0.18 to 3.1.
constexpr double kLayoutAloneWholeBy = 0.1;
// The whole photo's fit (LayoutFit::wholeScore) at or above which the network's box is a
// guess whatever the edges' reason for finding none: the photo looks like a room to the
// network. Seeds 600-1399 (neither trained nor tuned on before): 98% of the rooms above
// it, every "no corridor" with the box in view (15) among them; the tests' drawn road,
// outdoor scene and camera.png, and the York Urban streets that reach the guess, below it.
constexpr double kLayoutRoomScore = -0.25;
// A person's rough box fitted to the photo (detect --hint) and detection's own answer
// agree where their far corners lie within this of each other (fitRoughBox): the fit's
// corners then stand, with detection's verdict. (Detection's own near corners, on rays
// through far corners a fifth of a pixel off, can lie 2 px across the boundary ten times
// farther out: corridor_e's, against 0.3 px for the fit's.)
constexpr double kHintAgreesPx = 1.0;
// P5..P8 at the nearest cross-section this share of the photo's short side inside it.
constexpr double kNearMarginOfShortSide = 0.01;
// A corridor's end is no more than this many times as high as it is wide, nor as wide as
// it is high: a passage 0.8 m wide is under 5 m high; a hall 15 m wide over 2.5 m.
// Beyond it a "far wall" is a sliver between two edges (York Urban's P1040853, a door's
// frame: 0.08; P1080092, a shelf's edge: 49). TUNE 0-599 (true 0.20-2.83): the right
// answers 0.22-2.67; six wrong ones beyond (0.13-27).
constexpr double kMaxFarWallAspect = 6.0;
// Where the angular profile found no far wall, one of the box fit's next best boxes is
// taken over its best with this much more support (and as many boundaries dividing
// surfaces).
constexpr double kAlternativeSupportGain = 0.05;
// A guess's far-wall foot searched afresh (bestFoot): taken where it scores this many
// times the one found, and moved at least this far (working pixels). The foot's own
// step weighs this much against each floor boundary's (a glazed end's bars, a door's
// sill and a window's foot divide surfaces as consistently as the floor does). Chosen
// on the random TUNE seeds 0-299 (the weight on 0-129, then checked on 130-299).
constexpr double kFootGain = 2.0;
constexpr double kFootMovedPx = 1.5;
constexpr double kFootStepWeight = 0.25;
// A floor boundary's step in bestFoot is taken over its whole length, but no more than
// this many times its inner half's (from the far wall's corner): a line that meets an
// edge only far out, a side opening's foot near the photo's border, is no evidence for
// that corner (TUNE 278, by a copy of the score: a ray 9 px above the true foot scored
// 72 against 20 along a bright opening's foot, 4 in its inner half). Objects along the
// walls near the camera hide the outer half (DetectParts.RoomBoxFindsTheFarWallBehindClutter's
// cabinets; held to the second-weakest quarter, that foot moved 122 px). TUNE 0-599:
// +2/-0 clean, +2/-1 noisy.
constexpr double kBoundaryOfInnerHalf = 2.0;
// A skirting board under a far-wall foot found (skirtingBelow): the wall above runs on
// within this of one colour, or within half the board's own edge for a guess (a textured
// wall or a lamp's gradient above a board with a strong foot), and the board's band
// differs from the floor beyond by more (grey levels, about an edge's step); a band under
// this many working pixels is the found edge's own blur (TUNE seeds 0-299: at 2 px it
// moved 6 right answers off, at 3 none), and a place whose band is that narrow shows none
// (counted as disagreeing, it kept 1 clean and 2 noisy TUNE feet on a board's top). The
// places that show a board agree within kSkirtingAgreePx (two of three agreeing took the
// fixed scene clutter_1's darker first row of floor tiles for one; the far wall's own
// foot alone, where neither boundary shows a board, gained 5 TUNE answers but lost 12).
constexpr double kSkirtingUniformGrey = 12.0;
constexpr double kSkirtingPlainOfStep = 0.5;
constexpr double kMinSkirtingPx = 3.0;
constexpr double kSkirtingAgreePx = 1.5;
// A board's foot is the first step below its top at least this share of the largest
// within reach: a floor's first row of tiles beyond the board can step more than the
// board's foot does (seeds 600-1399, 640: the board's foot found 9 px below the foot
// along the far wall, at the tiles' edge, and 5 px along both floor boundaries, so the
// places disagreed; with the first step all three say 5 px, the answer right and sure).
// Seeds 600-1399 +1 -0 clean, TUNE 450-599 unchanged (one sure right answer a guess). Not
// for the band under the ceiling (aboveCeilingBand): there it moved 4 right tops off
// (seeds 600-1399) and mended none.
constexpr double kSkirtingFirstStepShare = 0.5;
// A far wall reaching into its reflection (reflectedFoot): the share of the floor's lines
// half way down that must divide surfaces.
constexpr double kMirrorFootShare = 0.5;
// A camera held 1-2 m above the floor of a corridor 2.2-6 m high sees the horizon
// (through the corridor's vanishing point) cross the far wall between these shares of
// its height, from its foot up (the random scenes: 0.17-0.82).
constexpr double kMinHorizonShareOfFarWall = 0.12, kMaxHorizonShareOfFarWall = 0.9;

// A far wall of this width over height is a corridor's end (kMaxFarWallAspect).
bool isCorridorEndAspect(double aspect) { return aspect <= kMaxFarWallAspect && aspect >= 1.0 / kMaxFarWallAspect; }

// The corridor's vanishing point of `d` lies inside a photo of `size`.
bool corridorMeetsInside(const CorridorDetection& d, cv::Size size) {
  if (!d.corridor.isFinite()) return false;
  const glm::dvec2 vp = d.corridor.pixel();
  return vp.x >= 0 && vp.y >= 0 && vp.x <= size.width - 1 && vp.y <= size.height - 1;
}

CorridorDetection notFound(CorridorDetection d, const std::string& reason) {
  d.found = false;
  d.notFoundReason = reason;
  return d;
}

// The quad's corners are in the order top-left, top-right, bottom-left,
// bottom-right; it must be convex and contain `inside`.
bool convexAround(const Quad& q, glm::dvec2 inside) {
  const std::array<glm::dvec2, 4> ring = {q[0], q[1], q[3], q[2]};  // clockwise on screen
  for (int i = 0; i < 4; ++i) {
    const glm::dvec2 a = ring[i], b = ring[(i + 1) % 4];
    const double cross = (b.x - a.x) * (inside.y - a.y) - (b.y - a.y) * (inside.x - a.x);
    if (!(cross > 0)) return false;
  }
  return true;
}

bool allFinite(const std::array<CornerEstimate, 8>& corners) {
  for (const CornerEstimate& c : corners)
    if (!std::isfinite(c.px.x) || !std::isfinite(c.px.y) || !std::isfinite(c.confidence)) return false;
  return true;
}

// The frame with a known focal length (its directions held orthogonal), or with one
// that is a guess or being estimated (each direction alone: see FrameRefinement).
Result<ManhattanFrame> frameWithFocal(const std::vector<LineSegment>& segments, double focalPx, glm::dvec2 pp,
                                      cv::Size size, bool focalKnown) {
  return estimateManhattanFrame(segments, PinholeCamera{focalPx, pp}, size,
                                focalKnown ? FrameRefinement::kJointOrthogonal : FrameRefinement::kIndependent);
}

// The segments whose lines pass within `tolDeg` of the homogeneous point `v` (the
// angle at their midpoint between the segment and the line to v) and nearer, by that
// angle, to it than to any of `others`.
std::vector<int> pointingAt(const glm::dvec3& v, const std::array<glm::dvec3, 2>& others,
                            const std::vector<LineSegment>& segments, double tolDeg) {
  const auto angleTo = [](const LineSegment& s, const glm::dvec3& p) {
    const glm::dvec2 mid = 0.5 * (s.a + s.b);
    const glm::dvec2 to(p.x - p.z * mid.x, p.y - p.z * mid.y), along = s.b - s.a;
    const double n = glm::length(to) * glm::length(along);
    if (!(n > 0)) return 90.0;
    return glm::degrees(std::acos(std::min(1.0, std::abs(glm::dot(to, along)) / n)));
  };
  std::vector<int> members;
  for (size_t i = 0; i < segments.size(); ++i) {
    const double a = angleTo(segments[i], v);
    if (a <= tolDeg && a < angleTo(segments[i], others[0]) && a < angleTo(segments[i], others[1])) {
      members.push_back(static_cast<int>(i));
    }
  }
  return members;
}

// The focal length from the corridor's vanishing point and a second finite one
// (focalFromOrthogonalPoints), with the frame found with it. The frame's labels
// depend on the focal length it was found with, so the two are iterated to a fixed
// point; nullopt (the default then) when no second point fixes it: none is finite,
// the corridor's point lies too near the principal point along the second one's
// direction (f^2 = D d is then the product of a large and a noisy number: a camera
// turned by under a degree or so), the value is not a lens's, or it does not settle.
std::optional<std::pair<double, ManhattanFrame>> focalFromSecondPoint(const std::vector<LineSegment>& segments,
                                                                      ManhattanFrame frame, glm::dvec2 pp, cv::Size size) {
  const double longSide = std::max(size.width, size.height), diagonal = std::hypot(size.width, size.height);
  double previous = 0;
  for (int iteration = 0; iteration < kFocalIterations; ++iteration) {
    std::optional<double> f;
    // Found on the sphere with a focal length that is only a guess, the finite points
    // are refitted in the image, each to the segments pointing at it (Lu et al.'s
    // clustering), where they do not depend on it.
    std::array<VanishingPoint, 3> points = {frame.corridor, frame.horizontal, frame.vertical};
    for (double tolDeg : kPointClusterDeg) {
      for (int role = 0; role < 3; ++role) {
        if (!points[role].isFinite()) continue;
        const std::vector<int> members =
            pointingAt(points[role].point, {points[(role + 1) % 3].point, points[(role + 2) % 3].point}, segments, tolDeg);
        if (members.size() < 2) continue;
        points[role].point = glm::normalize(homogeneous(refineFinitePoint(points[role].pixel(), segments, members)));
      }
    }
    // The corridor's point and the second one farther from it along the second one's
    // direction.
    double bestOffset = 0;
    for (int role : {1, 2}) {
      const std::optional<double> candidate = focalFromOrthogonalPoints(points[0], points[role], pp, diagonal);
      if (!candidate) continue;
      const double offset = std::abs(glm::dot(points[0].pixel() - pp, glm::normalize(points[role].pixel() - pp)));
      if (offset >= kMinSecondPointOffsetOfLongSide * longSide && offset > bestOffset) f = candidate, bestOffset = offset;
    }
    if (!f || !(*f > 0.3 * longSide && *f < 5.0 * longSide)) return std::nullopt;
    auto refitted = frameWithFocal(segments, *f, pp, size, false);
    if (!refitted) return std::nullopt;
    frame = std::move(*refitted);
    if (std::abs(*f - previous) <= kFocalSettledShare * *f) return std::pair{*f, std::move(frame)};
    previous = *f;
  }
  return std::nullopt;
}

// What the far-wall searches share.
struct FarWallSearch {
  const PinholeView& photo;
  const WorkingImage& work;
  const DetectOptions& options;
  glm::dvec2 vp, vpWork;  // the corridor's vanishing point, full-resolution and working pixels
};

// A detection and how well the image bears out its box: the mean edge coverage of
// the far wall's four sides and of the four boundaries beyond it.
struct Candidate {
  CorridorDetection detection;
  double support = 0;
  // Why the box's surfaces do not show a room (assess): its boundaries, or its far
  // wall's top or foot, divide surfaces alike; nullopt when they do.
  std::optional<std::string> surfacesAlike;
  int dividingBoundaries = 0;  // of the four, those that divide two surfaces (assess)
};

void doubt(CorridorDetection& d, const std::string& why) {
  d.confident = false;
  d.doubts.push_back(why);
}

std::array<glm::dvec2, 8> cornerPixels(const CorridorDetection& d) {
  std::array<glm::dvec2, 8> px{};
  for (int k = 0; k < kCornerCount; ++k) px[k] = d.corners[k].px;
  return px;
}

// The far-wall corners' (P1..P4) largest distance between two sets of corners.
double farWallDistancePx(const std::array<glm::dvec2, 8>& a, const std::array<glm::dvec2, 8>& b) {
  double worst = 0;
  for (int k = P1; k <= P4; ++k) worst = std::max(worst, glm::length(a[k] - b[k]));
  return worst;
}

double farWallDistancePx(const CorridorDetection& a, const CorridorDetection& b) {
  return farWallDistancePx(cornerPixels(a), cornerPixels(b));
}

// The same, the median of the four corners' distances.
double farWallMedianDistancePx(const std::array<glm::dvec2, 8>& a, const std::array<glm::dvec2, 8>& b) {
  std::array<double, 4> d{};
  for (int k = P1; k <= P4; ++k) d[k] = glm::length(a[k] - b[k]);
  std::sort(d.begin(), d.end());
  return 0.5 * (d[1] + d[2]);
}

// Share of the ray from the vanishing point through `corner` (working pixels) that
// runs along an edge just before the corner, over the far wall.
double edgeBeforeCorner(const WorkingImage& work, glm::dvec2 vp, glm::dvec2 corner) {
  const double radius = glm::length(corner - vp);
  const glm::dvec2 along = (corner - vp) / radius, normal(-along.y, along.x);
  // Stopping short of the corner keeps the far wall's own sides (a pixel wide, met
  // at an angle) out of the stretch.
  int samples = 0, covered = 0;
  for (double t = radius - std::max(10.0, 0.25 * radius); t <= radius - 5; t += 1.0, ++samples) {
    double across = 0;
    for (double k = -1; k <= 1; k += 1)
      across = std::max(across, std::abs(glm::dot(work.gradient(vp + t * along + k * normal), normal)));
    covered += across > kEdgeGreyPerPx;
  }
  return samples >= 4 ? static_cast<double>(covered) / samples : 0.0;
}

// Bilinear colour of the working copy at p (BGR, grey levels); p inside it.
glm::dvec3 colourAt(const cv::Mat& bgr, glm::dvec2 p) {
  const double x = std::clamp(p.x, 0.0, bgr.cols - 1.001), y = std::clamp(p.y, 0.0, bgr.rows - 1.001);
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const double fx = x - x0, fy = y - y0;
  const auto at = [&](int xx, int yy) {
    const cv::Vec3b& c = bgr.at<cv::Vec3b>(std::min(yy, bgr.rows - 1), std::min(xx, bgr.cols - 1));
    return glm::dvec3(c[0], c[1], c[2]);
  };
  return (1 - fx) * (1 - fy) * at(x0, y0) + fx * (1 - fy) * at(x0 + 1, y0) + (1 - fx) * fy * at(x0, y0 + 1) +
         fx * fy * at(x0 + 1, y0 + 1);
}

// How the surfaces either side of the segment a-b (working pixels) differ: at each
// pixel along its middle 80%, the mean colour 3-7 px to one side against the other's.
// `median`: the median difference (grey levels); `share`: the share of the samples
// differing by more than kSurfaceStepGrey. A corridor's boundary divides two surfaces
// (wall and floor, wall and ceiling); a line drawn over one wall's bricks or tiles
// follows edges as well, but the same surface lies on both sides of it.
constexpr double kSurfaceStepGrey = 10.0;
struct SurfaceStep {
  double median = 0, share = 0;
};
SurfaceStep surfaceStep(const WorkingImage& work, glm::dvec2 a, glm::dvec2 b) {
  const double length = glm::length(b - a);
  if (!(length >= 5)) return {};
  const glm::dvec2 along = (b - a) / length, normal(-along.y, along.x);
  std::vector<double> diffs;
  for (double t = 0.1 * length; t <= 0.9 * length; t += 1.0) {
    const glm::dvec2 p = a + t * along;
    glm::dvec3 one(0), other(0);
    int n = 0;
    for (double o = 3; o <= 7; o += 1, ++n) {
      one += colourAt(work.bgr, p + o * normal);
      other += colourAt(work.bgr, p - o * normal);
    }
    if (!work.contains(p + 7.0 * normal) || !work.contains(p - 7.0 * normal)) continue;
    diffs.push_back(glm::length(one - other) / n);
  }
  if (diffs.empty()) return {};
  SurfaceStep step;
  step.share = static_cast<double>(std::count_if(diffs.begin(), diffs.end(), [](double v) { return v > kSurfaceStepGrey; })) /
               diffs.size();
  std::nth_element(diffs.begin(), diffs.begin() + diffs.size() / 2, diffs.end());
  step.median = diffs[diffs.size() / 2];
  return step;
}

// Below these a sure answer's evidence is thin: its boundaries divide surfaces (three
// of four over half their length), and so do its far wall's top and foot (the random
// TUNE scenes, seeds 0-299: the wrong exit-0 answers on brick walls, a glazed end's
// bars, a cabinet's front, where every line drawn has edges along it).
constexpr double kSureBoundaryStepShare = 0.5;
constexpr double kSureFarStepGrey = 8.0;
constexpr double kSureBoxFitSupport = 0.92;
constexpr const char* kBoxFitOnlyDoubt =
    "the far wall was found by fitting the room's box to the edges, not where the four boundaries begin";
// A boundary shorter than this share of the photo's short side (a near section barely
// nearer than the far wall) holds too few samples to say whether it divides two
// surfaces, and does not count as dividing them (tests/data/detect/camera.png, focal
// withheld: a tripod's legs meeting in a "vanishing point", with a rectangle around
// it whose boundaries are 1-4% of the short side; the random TUNE scenes 0-299 keep
// every answer).
constexpr double kMinJudgedBoundaryOfShortSide = 0.03;
// Below these (shares of the photo's short side) the box is too small in the photo
// for its checks to mean anything: a far wall a few dozen pixels across (a long
// corridor's end, a person before it) has edges along any rectangle drawn on it, and
// boundaries seen over a sliver between the far wall and the near section (a box
// whose near end is barely nearer than its far wall) run on from anything. TUNE
// seeds 0-149: the right exit-0 answers' far walls are 8% of the short side or more
// across, and two of their boundaries 17% or more long; the wrong ones 3%, and 14%
// or less.
constexpr double kSureFarSideOfShortSide = 0.05;
constexpr double kSureBoundaryStretchOfShortSide = 0.15;
constexpr int kSureLongBoundaries = 2;

// Why an answer whose boundaries divide surfaces in fewer than kMinDividingBoundaries
// places is no corridor.
std::string noRoomBox(int dividing) {
  return "only " + std::to_string(dividing) + " of the four boundaries of the box found divide two surfaces: no room's box";
}

// The doubt where `runOn` boundaries run on inside the far wall's corners (assess).
std::string runsOnInside(int runOn) {
  return std::to_string(runOn) + (runOn == 1 ? " boundary runs" : " boundaries run") + " on inside the far wall's corners";
}

// What assess says of a box's surfaces (Candidate's fields of the same names).
struct SurfacesSeen {
  std::optional<std::string> surfacesAlike;
  int dividingBoundaries = 0;
};

// The doubts a found corridor leaves: where the box's evidence is thin. A wrong far
// wall (a cabinet's front, a doorway nearer the camera) has the sides of a rectangle,
// but the boundaries do not run on from its corners across the walls. Returns the
// first doubt about its surfaces and how many boundaries divide two surfaces.
SurfacesSeen assess(CorridorDetection& d, const FarWallSearch& s, const RefinedSection& far,
                    const std::array<RefinedBoundary, kBoundaryCount>& rays) {
  std::optional<std::string> surfacesAlike;
  // The boundaries start at the far wall's corners; where they run on inside it the
  // rectangle is a section nearer the camera (a band, a doorway, a lamp's light).
  int runOn = 0;
  for (int k = 0; k < 4; ++k) runOn += edgeBeforeCorner(s.work, s.vpWork, s.work.toWorking(far.corners[k])) >= kRunOnCoverage;
  if (runOn >= 1) d.doubts.push_back(runsOnInside(runOn));
  static const char* const kSideNames[4] = {"top", "bottom", "left", "right"};
  for (int side = 0; side < 4; ++side) {
    const double need = side == kBottomSide ? kSureBottomSideCoverage : kSureFarSideCoverage;
    if (far.sides[side].coverage < need) {
      d.doubts.push_back(std::string("the far wall's ") + kSideNames[side] + " edge is seen along " +
                         std::to_string(static_cast<int>(std::lround(100 * far.sides[side].coverage))) + "% of it");
    }
  }
  int strongRays = 0;
  for (int b = 0; b < kBoundaryCount; ++b) strongRays += rays[b].fit && rays[b].fit->coverage >= kSureBoundaryCoverage;
  if (strongRays < kSureBoundaries) {
    d.doubts.push_back("only " + std::to_string(strongRays) + " of the four boundaries run on from the far wall's corners");
  }
  // The surfaces: boundaries from each far corner to its near one, the far wall's top
  // and foot.
  const auto w = [&](int k) { return s.work.toWorking(d.corners[k].px); };
  constexpr std::array<std::array<int, 2>, kBoundaryCount> kBoundaryEnds{{{P3, P5}, {P4, P6}, {P1, P7}, {P2, P8}}};
  const double shortSide = std::min(s.photo.size().width, s.photo.size().height);
  int dividing = 0;
  for (const auto& [farCorner, nearCorner] : kBoundaryEnds) {
    dividing += glm::length(d.corners[farCorner].px - d.corners[nearCorner].px) >= kMinJudgedBoundaryOfShortSide * shortSide &&
                surfaceStep(s.work, w(farCorner), w(nearCorner)).share >= kSureBoundaryStepShare;
  }
  if (dividing < kSureBoundaries) {
    d.doubts.push_back("only " + std::to_string(dividing) + " of the four boundaries divide two surfaces");
    surfacesAlike = d.doubts.back();
  }
  const double farSide = std::min({glm::length(d.corners[P1].px - d.corners[P2].px), glm::length(d.corners[P3].px - d.corners[P4].px),
                                   glm::length(d.corners[P1].px - d.corners[P3].px), glm::length(d.corners[P2].px - d.corners[P4].px)});
  if (farSide < kSureFarSideOfShortSide * shortSide) {
    d.doubts.push_back("the far wall is " + std::to_string(std::lround(farSide)) +
                       " px across: too small in the photo to place its corners surely");
  }
  int longBoundaries = 0;
  for (const auto& [farCorner, nearCorner] : kBoundaryEnds) {
    longBoundaries += glm::length(d.corners[farCorner].px - d.corners[nearCorner].px) >= kSureBoundaryStretchOfShortSide * shortSide;
  }
  if (longBoundaries < kSureLongBoundaries) {
    d.doubts.push_back("the box is shallow in the photo: " + std::to_string(longBoundaries) +
                       " of its four boundaries run " + std::to_string(std::lround(100 * kSureBoundaryStretchOfShortSide)) +
                       "% of the photo's short side or more from the far wall (" + std::to_string(kSureLongBoundaries) +
                       " needed)");
  }
  const std::array<std::pair<const char*, std::array<int, 2>>, 2> kTopAndFoot{{{"top", {P1, P2}}, {"foot", {P3, P4}}}};
  for (const auto& [name, ends] : kTopAndFoot) {
    const double step = surfaceStep(s.work, w(ends[0]), w(ends[1])).median;
    if (step < kSureFarStepGrey) {
      d.doubts.push_back(std::string("the far wall's ") + name + " divides surfaces alike (" +
                         std::to_string(static_cast<int>(std::lround(step))) + " grey levels)");
      if (!surfacesAlike) surfacesAlike = d.doubts.back();
    }
  }
  d.confident = d.doubts.empty();
  return {surfacesAlike, dividing};
}

// Each far corner (P1..P4, the Quad's order): the boundary that runs on from it and the
// far wall's vertical side it lies on.
constexpr std::array<int, 4> kBoundaryOfCorner = {kCeilingLeft, kCeilingRight, kFloorLeft, kFloorRight};
constexpr std::array<int, 4> kVerticalOf = {kLeftSide, kRightSide, kLeftSide, kRightSide};

// The doubt of a foot taken at a band's foot (footOfBand): never a sure one (a lit strip of
// floor before a glazed end can pass for a board, TUNE 544).
constexpr const char* kFootAtBandFoot = "the far wall's foot was taken at the foot of a band along the walls, a skirting board's";

// The depth of P5..P8 along `family` (the boundaries from the corridor's vanishing point
// through the far corners, the photo's pixels; the far wall at `farT`): the nearest
// section whose four corners lie inside the photo or, where a person put them
// (`nearHint`, P7 P8 P5 P6) beyond `reachPx` of it, the section nearest theirs.
std::pair<double, NearDepth> nearSectionDepth(const CrossSectionFamily& family, double farT, cv::Size size,
                                              const std::optional<Quad>& nearHint, double reachPx) {
  const double t = family.largestInside(size, kNearMarginOfShortSide * std::min(size.width, size.height));
  if (!nearHint) return {t, NearDepth::kImageEdge};
  // The depth the person gave, unless the section nearest the photo's edge is within
  // reach of it (the convention a careful person follows too).
  const double given = nearestSection(family, *nearHint, farT + 1.0, 2.0 * t);
  const auto edge = family.at(t), atGiven = family.at(given);
  double apart = std::numeric_limits<double>::infinity();
  if (edge && atGiven) {
    apart = 0;
    for (int k = 0; k < 4; ++k) apart = std::max(apart, glm::length((*edge)[k] - (*nearHint)[k]));
  }
  return apart > reachPx ? std::pair{given, NearDepth::kGiven} : std::pair{t, NearDepth::kImageEdge};
}

// From a far wall found on the working copy (corners in working pixels, `farT` its
// depth in the cross-section family's terms) to the detection: the far wall's sides
// and the boundaries beyond it fitted at full resolution, then P5..P8, and the
// doubts it leaves. The error is the reason no corridor is there.
// `nearHint` (full-resolution, the Quad's order: P7 P8 P5 P6): the near section a person
// put, kept at its depth unless it lies within reach of the nearest depth inside the photo.
// `hiddenSide`: one far-wall side may show no edge (a cabinet before its foot, a person
// before a corner); its corners are then where its neighbouring sides meet the fitted
// boundaries (a corner behind a person is still where its two edges meet).
Result<Candidate> completeFromFarWall(const FarWallSearch& s, CorridorDetection d, const Quad& farWork, double farT,
                                      const std::optional<Quad>& nearHint = std::nullopt, bool allowHiddenSide = false) {
  const PinholeView& photo = s.photo;
  const WorkingImage& work = s.work;
  const cv::Size size = photo.size();
  const glm::dvec2 vp = s.vp;
  // Full resolution: far wall sides, then the boundaries beyond it.
  const double searchPx = 2.0 / work.scale + 2.0;
  const double stepHalfWidthPx = std::max(2.0, 1.0 / work.scale);
  Quad coarseFar;
  for (int k = 0; k < 4; ++k) coarseFar[k] = work.toFull(farWork[k]);
  // Its top and bottom take their innermost edge: a floor's tile joint a pixel or three
  // beyond the foot is often the stronger, and blur merges the two.
  RefinedSection far = refineCrossSection(photo, coarseFar, d.horizontal.point, d.vertical.point, searchPx,
                                          stepHalfWidthPx, 0.5, vp);
  static const char* const kSideNames[4] = {"top", "bottom", "left", "right"};
  int hidden = -1;
  for (int side = 0; side < 4; ++side) {
    if (!far.sideFitted[side] || far.sides[side].coverage < kMinFarSideCoverage) {
      if (!allowHiddenSide || hidden >= 0) {
        // (In the photo or not: where it was looked for, the photo shows no edge.)
        return makeError(std::string("the far wall's ") + kSideNames[side] +
                         (hidden >= 0 ? std::string(" and ") + kSideNames[hidden] + " show" : std::string(" shows")) +
                         " no edge");
      }
      hidden = side;
    }
  }
  if (!convexAround(far.corners, vp)) return makeError("the far wall's corners do not surround the vanishing point");
  for (int k = 0; k < 4; ++k) {
    d.corners[k] = {far.corners[k], far.cornerConfidence[k], far.cornerSigmaPx[k]};
    if (!(far.corners[k].x >= 0 && far.corners[k].y >= 0 && far.corners[k].x <= size.width - 1 &&
          far.corners[k].y <= size.height - 1)) {
      return makeError("the far wall's corners fall outside the photo");
    }
  }
  // The boundaries run from the vanishing point through the far wall's corners:
  // those corners, fitted to a tenth of a pixel about a hundred pixels out, fix the
  // rays' angles better than the angular profile did (a mortar joint one course
  // below the ceiling can pull that by half a degree).
  constexpr std::array<int, kBoundaryCount> kFarCornerOf = {2, 3, 0, 1};  // P3 P4 P1 P2
  RecedingBoundaries throughCorners;
  std::array<glm::dvec2, kBoundaryCount> cornerDirection{};
  std::array<double, kBoundaryCount> fromRadius{};
  for (int b = 0; b < kBoundaryCount; ++b) {
    const glm::dvec2 corner = far.corners[kFarCornerOf[b]];
    cornerDirection[b] = glm::normalize(corner - vp);
    throughCorners.angle[b] = std::atan2(cornerDirection[b].y, cornerDirection[b].x);
    fromRadius[b] = 1.1 * glm::length(corner - vp) + 2.0;
  }
  // Fitted beyond the far wall, the rays say how well the image bears them out.
  const auto rays = refineBoundaries(photo, vp, cornerDirection, fromRadius, searchPx, stepHalfWidthPx);
  // The boundaries looked for afresh near the rays through the far corners as they stand:
  // in each, the sharpest colour step of the angular profile within kEndSearchRad
  // (boundariesNear: a floor's found on a band along the walls taken at its foot), fitted
  // at full resolution. Looked for once: the hidden foot's search moves only the floor
  // boundaries, which the open end's search then does not use (it skips the hidden side).
  std::optional<std::pair<RecedingBoundaries, std::array<RefinedBoundary, kBoundaryCount>>> lookedAfresh;
  const auto boundariesAfresh = [&]() -> const auto& {
    if (lookedAfresh) return *lookedAfresh;
    std::array<double, kBoundaryCount> around{}, reach{};
    for (int b = 0; b < kBoundaryCount; ++b) around[b] = throughCorners.angle[b], reach[b] = kEndSearchRad;
    const glm::dvec2 horizonDir = directionTowards(work.toWorking(d.horizontal.point), s.vpWork);
    RecedingBoundaries steps = boundariesNear(work, s.vpWork, around, reach, std::atan2(horizonDir.y, horizonDir.x));
    std::array<glm::dvec2, kBoundaryCount> stepDirection{};
    for (int b = 0; b < kBoundaryCount; ++b) stepDirection[b] = steps.direction(b);
    lookedAfresh.emplace(std::move(steps), refineBoundaries(photo, vp, stepDirection, fromRadius, searchPx, stepHalfWidthPx));
    return *lookedAfresh;
  };
  if (hidden >= 0) {
    // The hidden side's corners where the boundary through each meets the side beside it.
    // Each boundary through a corner of the hidden side: the ray fitted through it. With the
    // foot hidden (a person before it), a floor's ray through the corner guessed is often a
    // skirting board's top; looked for afresh, as at an open end (below), one found at a
    // band's foot is taken instead.
    std::array<std::optional<EdgeLine>, kBoundaryCount> line;
    for (int b = 0; b < kBoundaryCount; ++b) line[b] = rays[b].fit;
    bool atBandFoot = false;
    if (hidden == kBottomSide) {
      const auto& [steps, afresh] = boundariesAfresh();
      for (int b : {kFloorLeft, kFloorRight}) {
        if (steps.belowBand[b] && afresh[b].fit && afresh[b].fit->coverage >= kSureBoundaryCoverage) {
          line[b] = afresh[b].fit;
          atBandFoot = true;
        }
      }
    }
    for (int k : kSideCorners[hidden]) {
      const int b = kBoundaryOfCorner[k];
      const int other = kCornerSides[k][0] == hidden ? kCornerSides[k][1] : kCornerSides[k][0];
      if (!line[b]) return makeError(std::string("the far wall's ") + kSideNames[hidden] + " edge is hidden and so is its " +
                                     boundaryName(b) + " boundary");
      auto p = intersect(line[b]->line, far.sides[other].line);
      if (!p) return makeError(std::string("the far wall's ") + kSideNames[hidden] + " corners cannot be found");
      far.corners[k] = *p;
      far.cornerConfidence[k] = 0.5 * far.cornerConfidence[k] + 0.2;
      d.corners[k] = {*p, far.cornerConfidence[k], std::hypot(line[b]->positionSigmaPx(), far.sides[other].positionSigmaPx())};
      throughCorners.angle[b] = std::atan2(p->y - vp.y, p->x - vp.x);
    }
    if (atBandFoot) doubt(d, kFootAtBandFoot);
    doubt(d, std::string("the far wall's ") + kSideNames[hidden] + " edge is hidden: its corners are where the boundaries meet its sides");
  }
  // Where the walls end before the wall seen beyond them (an open end: a hall's far wall,
  // the floor running on under the opening) or a trim runs along the far wall's foot or
  // top (a skirting board, a cornice), the top and foot found are a few pixels inside the
  // box's end: its corners are where the boundaries, the wall meeting the floor or the
  // ceiling along the corridor, meet the far wall's sides. The boundaries for that are
  // looked for afresh (the rays above were put through the corners found): the sharpest
  // colour step of the angular profile within kEndSearchRad of each, fitted at full
  // resolution (TUNE seeds 0-149: open ends right in 2 of 32 before). The rays through
  // the corners found stay the evidence the box is judged by (assess): where the corners
  // moved far, they no longer run on from them, and the answer is not a sure one.
  {
    const auto& [steps, afresh] = boundariesAfresh();
    const double sideLength = std::min(glm::length(far.corners[P1] - far.corners[P3]), glm::length(far.corners[P2] - far.corners[P4]));
    for (int side : {kTopSide, kBottomSide}) {
      if (side == hidden) continue;
      std::array<glm::dvec2, 2> at{};
      double least = std::numeric_limits<double>::infinity(), most = 0;
      bool met = true;
      for (int n = 0; n < 2 && met; ++n) {
        const int k = kSideCorners[side][n], b = kBoundaryOfCorner[k];
        const std::optional<EdgeLine>& ray = afresh[b].fit;
        std::optional<glm::dvec2> p;
        if (ray && ray->coverage >= kSureBoundaryCoverage) p = intersect(ray->line, far.sides[kVerticalOf[k]].line);
        if (!p) {
          met = false;
          break;
        }
        // How far beyond the side found, away from the vanishing point.
        const glm::dvec3 l = far.sides[side].line;
        const double beyond = glm::dot(l, homogeneous(*p)) * (glm::dot(l, homogeneous(vp)) > 0 ? -1.0 : 1.0);
        least = std::min(least, beyond), most = std::max(most, beyond);
        at[n] = *p;
      }
      // (Both corners are moved, each onto its boundary: the two need not be beyond the
      // side by as much; with noise, one end's boundary is often found farther than the
      // other's (TUNE seeds 0-299, JPEG q70 and noise: requiring them to agree within
      // 2.5 px lost 4 right answers).)
      if (!met || !(least > kEndBeyondSidePx && most < kEndBeyondSideOfSide * sideLength)) continue;
      // A box a person put is a box: where its two ends' boundaries disagree (one found on
      // a trim below the ceiling's white-on-white edge: the York Urban corridor P1040826),
      // both corners go to the farther one's level. (Not for detection's own answers: on
      // the noisy TUNE scenes a boundary found too far out is as common: 7 right answers
      // lost, 1 gained.)
      if (s.options.hintPx && most - least > kEndDisagreePx) {
        const glm::dvec3 l = far.sides[side].line;
        const double out = glm::dot(l, homogeneous(vp)) > 0 ? -1.0 : 1.0;
        const int farther = out * glm::dot(l, homogeneous(at[0])) >= out * glm::dot(l, homogeneous(at[1])) ? 0 : 1;
        const int k = kSideCorners[side][1 - farther];
        const glm::dvec3 level = glm::cross(homogeneous(at[farther]), d.horizontal.point);
        if (auto q = intersect(level, far.sides[kVerticalOf[k]].line)) at[1 - farther] = *q;
      }
      if (steps.belowBand[kBoundaryOfCorner[kSideCorners[side][0]]] || steps.belowBand[kBoundaryOfCorner[kSideCorners[side][1]]]) {
        doubt(d, kFootAtBandFoot);
      }
      for (int n = 0; n < 2; ++n) {
        const int k = kSideCorners[side][n], b = kBoundaryOfCorner[k];
        far.corners[k] = at[n];
        d.corners[k].px = at[n];
        d.corners[k].sigmaPx = std::hypot(afresh[b].fit->positionSigmaPx(), far.sides[kVerticalOf[k]].positionSigmaPx());
        throughCorners.angle[b] = std::atan2(at[n].y - vp.y, at[n].x - vp.x);
      }
    }
  }
  if (const double aspect = farWallAspect(d); !isCorridorEndAspect(aspect)) {
    const bool wide = aspect > 1;
    char times[32];
    std::snprintf(times, sizeof times, "%.1f", wide ? aspect : 1.0 / aspect);
    return makeError(std::string("the far wall found would be ") + times + " times as " +
                     (wide ? "wide as it is high" : "high as it is wide") + ": not a corridor's end");
  }
  const CrossSectionFamily nearFamily(s.vpWork, work.toWorking(d.horizontal.point), work.toWorking(d.vertical.point),
                                      throughCorners);

  // P5..P8: on a marked cross-section (band, frame) when asked to look for one and
  // there is one, else at the nearest depth where all four stay inside the photo (the
  // editor moves them).
  std::optional<CrossSectionMatch> marked;
  if (nearHint) {
    const Quad givenWork = {work.toWorking((*nearHint)[0]), work.toWorking((*nearHint)[1]), work.toWorking((*nearHint)[2]),
                            work.toWorking((*nearHint)[3])};
    const double tGiven = nearestSection(nearFamily, givenWork, 1.05 * farT, 2.0 * glm::length(givenWork[2] - s.vpWork) + 2.0);
    marked = findMarkedCrossSectionNear(work, nearFamily, tGiven, s.options.hintReachPx * work.scale);
  } else if (s.options.nearAtMarkedCrossSection) {
    marked = findMarkedCrossSection(work, nearFamily, farT);
  }
  constexpr std::array<int, 4> kNearCornerOfQuad = {6, 7, 4, 5};  // P7 P8 P5 P6
  if (marked) {
    Quad coarseNear;
    for (int k = 0; k < 4; ++k) coarseNear[k] = work.toFull(marked->corners[k]);
    // A band has two edges a few pixels apart and the scan stops at the first, its
    // far (inner) one: a one-pixel step keeps the two apart, and a low bar keeps the
    // inner edge where it borders a tile nearly as dark as the band.
    const RefinedSection nearSection = refineCrossSection(photo, coarseNear, d.horizontal.point, d.vertical.point,
                                                          searchPx, std::max(1.0, 1.0 / work.scale), 0.25);
    for (int k = 0; k < 4; ++k) {
      d.corners[kNearCornerOfQuad[k]] = {nearSection.corners[k], nearSection.cornerConfidence[k], nearSection.cornerSigmaPx[k]};
    }
    d.nearDepth = NearDepth::kMarkedCrossSection;
  } else {
    const CrossSectionFamily fullFamily(vp, d.horizontal.point, d.vertical.point, throughCorners);
    const auto [t, depth] = nearSectionDepth(fullFamily, glm::length(far.corners[2] - vp), size, nearHint, s.options.hintReachPx);
    d.nearDepth = depth;
    auto q = fullFamily.at(t);
    if (!q || t <= glm::length(far.corners[2] - vp)) return makeError("no room between the far wall and the photo's edge");
    for (int k = 0; k < 4; ++k) {
      const int b = std::array{kCeilingLeft, kCeilingRight, kFloorLeft, kFloorRight}[k];
      // On a fitted boundary the corner's sideways position is measured; its depth is
      // a convention, so it gets half that line's confidence.
      const double confidence = rays[b].fit ? 0.5 * std::min(1.0, rays[b].fit->coverage) : 0.1;
      const double sigma = rays[b].fit ? rays[b].fit->positionSigmaPx() : searchPx;
      d.corners[kNearCornerOfQuad[k]] = {(*q)[k], confidence, sigma};
    }
  }
  if (!allFinite(d.corners)) return makeError("the fitted corners are degenerate");
  d.found = true;
  SurfacesSeen seen = assess(d, s, far, rays);
  Candidate c{std::move(d), 0.0, std::move(seen.surfacesAlike), seen.dividingBoundaries};
  for (int k = 0; k < 4; ++k) c.support += far.sides[k].coverage / 8 + (rays[k].fit ? rays[k].fit->coverage : 0.0) / 8;
  return c;
}

// How consistently the surfaces either side of the segment a-b (working pixels)
// differ: the length of the mean colour difference, 3-7 px to one side against the
// other, over its samples (grey levels). A wall meeting the floor differs the same
// way all along; a tile joint on a checkered or patterned floor, whose sides swap,
// averages out.
double consistentStep(const WorkingImage& work, glm::dvec2 a, glm::dvec2 b) {
  const double length = glm::length(b - a);
  if (!(length >= 5)) return 0;
  const glm::dvec2 along = (b - a) / length, normal(-along.y, along.x);
  glm::dvec3 sum(0);
  int n = 0;
  for (double t = 0; t <= length; t += 1.0) {
    const glm::dvec2 p = a + t * along;
    if (!work.contains(p + 7.0 * normal) || !work.contains(p - 7.0 * normal)) continue;
    for (double o = 3; o <= 7; o += 1) sum += colourAt(work.bgr, p + o * normal) - colourAt(work.bgr, p - o * normal);
    n += 5;
  }
  return n > 0 ? glm::length(sum) / n : 0.0;
}

// consistentStep over a floor boundary from a (by the far wall) to b, held to
// kBoundaryOfInnerHalf times its inner half's.
double boundaryStep(const WorkingImage& work, glm::dvec2 a, glm::dvec2 b) {
  return std::min(consistentStep(work, a, b), kBoundaryOfInnerHalf * consistentStep(work, a, 0.5 * (a + b)));
}

// The far wall's foot where the floor meets the walls (working pixels). The far wall's
// top and sides stand above most clutter and are found more often than its foot (the
// random TUNE scenes 0-129: of the wrong answers, 13 of 56 had the top right and the
// foot wrong: a tile row, a checkered floor's joint taken for a boundary, a glossy
// floor's reflection; 4 the other way, and searching the top likewise gained as many
// as it lost on 0-299). With the top and sides kept, each foot (through the horizontal
// point, its corners on the sides, the horizon within the shares above) is scored by
// how consistently the two floor boundaries through its corners divide surfaces, over
// their length to the photo's border (short ones count less; each held to its inner
// half, boundaryStep), and the foot itself a
// little. Returns the best foot's corners (P3, P4), its score and `current`'s.
struct FootSearch {
  glm::dvec2 left, right;
  double score = 0, currentScore = 0;
};
std::optional<FootSearch> bestFoot(const WorkingImage& work, glm::dvec2 vp, glm::dvec3 horizontal, glm::dvec3 vertical,
                                   const Quad& current) {
  const glm::dvec3 rightSide = lineThrough(homogeneous(current[1]), vertical);
  const auto horizonOnSide = intersect(lineThrough(homogeneous(vp), horizontal), lineThrough(homogeneous(current[0]), vertical));
  if (!horizonOnSide) return std::nullopt;
  const glm::dvec2 down = directionTowards(vertical, current[0], {0, 1});
  const double fullReach = 0.3 * std::min(work.bgr.cols, work.bgr.rows);
  const auto score = [&](glm::dvec2 left, glm::dvec2 right) {
    double s = kFootStepWeight * consistentStep(work, left, right);
    for (glm::dvec2 corner : {left, right}) {
      const glm::dvec2 out = glm::normalize(corner - vp);
      const double reach = distanceToBorder(work, corner, out);
      if (reach > 10) s += boundaryStep(work, corner + 3.0 * out, corner + (reach - 2) * out) * std::min(1.0, reach / fullReach);
    }
    return s;
  };
  const double fromPx = std::max(4.0, 0.2 * glm::length(current[1] - current[0]));
  std::optional<FootSearch> best;
  for (double h = fromPx;; h += 1.0) {
    const glm::dvec2 left = current[0] + h * down;
    const auto right = intersect(lineThrough(homogeneous(left), horizontal), rightSide);
    if (!right || !work.contains(left, 2) || !work.contains(*right, 2)) break;
    // The horizon's share of the far wall's height, from its foot up: grows as the foot falls.
    const double share = glm::dot(left - *horizonOnSide, down) / h;
    if (share > kMaxHorizonShareOfFarWall) break;
    if (share < kMinHorizonShareOfFarWall) continue;
    const double sc = score(left, *right);
    if (!best || sc > best->score) best = FootSearch{left, *right, sc, 0};
  }
  if (best) best->currentScore = score(current[2], current[3]);
  return best;
}

// The doubt where the angular profile's far wall and the room's box fit's lie `apartPx`
// apart (photo pixels, worst corner).
std::string fitsDisagree(double apartPx) {
  return "two fits of the room disagree on the far wall (by " + std::to_string(static_cast<int>(std::lround(apartPx))) +
         " px)";
}

// The far wall's corners P1..P4 in working pixels.
Quad farInWorking(const CorridorDetection& d, const WorkingImage& work) {
  Quad far;
  for (int k = 0; k < 4; ++k) far[k] = work.toWorking(d.corners[k].px);
  return far;
}

// The cross-sections along the boundaries from the corridor's vanishing point through
// the far corners `far` (P1..P4, photo pixels).
CrossSectionFamily sectionsThroughFarWall(const CorridorDetection& d, const Quad& far) {
  const glm::dvec2 vp = d.corridor.pixel();
  RecedingBoundaries rays;
  const std::array<glm::dvec2, kBoundaryCount> farCorner = {far[P3], far[P4], far[P1], far[P2]};  // floor-left ... ceiling-right
  for (int b = 0; b < kBoundaryCount; ++b) rays.angle[b] = std::atan2(farCorner[b].y - vp.y, farCorner[b].x - vp.x);
  return CrossSectionFamily(vp, d.horizontal.point, d.vertical.point, rays);
}

// P5..P8 as a cross-section (Quad's order: top-left, top-right, bottom-left,
// bottom-right), and back.
constexpr std::array<int, 4> kNearCornersOfQuad = {P7, P8, P5, P6};
Quad nearQuadOf(const std::array<glm::dvec2, 8>& corners) {
  return {corners[P7], corners[P8], corners[P5], corners[P6]};
}
void setNearCorners(std::array<glm::dvec2, 8>& corners, const Quad& near) {
  for (int k = 0; k < 4; ++k) corners[kNearCornersOfQuad[k]] = near[k];
}
void setNearCorners(CorridorDetection& d, const Quad& near) {
  for (int k = 0; k < 4; ++k) d.corners[kNearCornersOfQuad[k]].px = near[k];
}

// The nearest cross-section whose four corners lie inside the photo (1% of its short side
// from the border), along the boundaries through the far corners `far`: its corners in
// the order P7, P8, P5, P6.
std::optional<Quad> nearestSectionInside(const CorridorDetection& d, const Quad& far, cv::Size size) {
  const CrossSectionFamily family = sectionsThroughFarWall(d, far);
  return family.at(family.largestInside(size, kNearMarginOfShortSide * std::min(size.width, size.height)));
}

// `d` (an answer of detection's own) with P5..P8 on its boundaries at the depth a person
// put theirs (`hint`, P5..P8 of it; nearSectionDepth), each corner keeping its confidence.
std::optional<CorridorDetection> withNearAsPut(CorridorDetection d, const std::array<glm::dvec2, 8>& hint, cv::Size size,
                                               double reachPx) {
  const CrossSectionFamily family =
      sectionsThroughFarWall(d, {d.corners[P1].px, d.corners[P2].px, d.corners[P3].px, d.corners[P4].px});
  const double farT = glm::length(d.corners[P3].px - d.corridor.pixel());
  const auto [t, depth] = nearSectionDepth(family, farT, size, nearQuadOf(hint), reachPx);
  const auto near = family.at(t);
  if (!near || t <= farT) return std::nullopt;
  setNearCorners(d, *near);
  if (!allFinite(d.corners)) return std::nullopt;
  d.nearDepth = depth;
  return d;
}

// A skirting board below the far wall's foot found: the foot found is the board's top
// when the wall above it runs on plain, and a band unlike the floor beyond lies below it,
// ending in an edge within 8% of the far wall's height (a board 6-15 cm high on a wall
// 2.2-6 m high: 1-7%). Looked at in three places, each a colour profile across the foot
// (along the foot itself, and along each floor boundary beyond its corner); returns, for
// each place that shows a board, how far down (working pixels, along the far wall's
// sides) its foot lies, and whether the wall above it is plain by the strict test (within
// kSkirtingUniformGrey; a place counts where it is within kSkirtingPlainOfStep times the
// board's own edge).
struct SkirtingPlace {
  double move = 0;
  bool wallPlain = false;
};
std::vector<SkirtingPlace> skirtingBelow(const WorkingImage& work, glm::dvec2 vp, glm::dvec3 horizontal,
                                         glm::dvec3 vertical, const Quad& far, glm::dvec2 downHint = {0, 1},
                                         bool firstEdge = true) {
  // (`downHint` {0, -1} with `far` flipped, its foot first: the band above its top.)
  const glm::dvec3 rightSide = lineThrough(homogeneous(far[1]), vertical);
  const glm::dvec2 down = directionTowards(vertical, far[0], downHint);
  const double height = glm::dot(far[2] - far[0], down);
  if (!(height > 20)) return {};
  const double h0 = height, reach = std::max(3.0, 0.08 * height);
  const double shortSide = std::min(work.bgr.cols, work.bgr.rows);
  // Each of the three pieces with the foot at h (nullopt: off the photo).
  const auto pieceAt = [&](int piece, double h) -> std::optional<std::pair<glm::dvec2, glm::dvec2>> {
    const glm::dvec2 p3 = far[0] + h * down;
    const auto p4 = intersect(lineThrough(homogeneous(p3), horizontal), rightSide);
    if (!p4) return std::nullopt;
    glm::dvec2 a, b;
    if (piece == 0) {
      a = p3 + 0.15 * (*p4 - p3), b = p3 + 0.85 * (*p4 - p3);
    } else {
      const glm::dvec2 corner = piece == 1 ? p3 : *p4, out = glm::normalize(corner - vp);
      const double length = std::min(0.3 * shortSide, distanceToBorder(work, corner, out) - 2);
      if (!(length > 10)) return std::nullopt;
      a = corner + 3.0 * out, b = corner + length * out;
    }
    return std::pair{a, b};
  };
  // The mean colour along a piece.
  const auto profileAt = [&](int piece, double h) -> std::optional<glm::dvec3> {
    const auto ends = pieceAt(piece, h);
    if (!ends) return std::nullopt;
    const auto [a, b] = *ends;
    const double n = glm::length(b - a);
    glm::dvec3 sum(0);
    int count = 0;
    for (double t = 0; t <= n; t += 1.0) {
      const glm::dvec2 q = a + (t / std::max(n, 1.0)) * (b - a);
      if (!work.contains(q)) continue;
      sum += colourAt(work.bgr, q), ++count;
    }
    if (count < 8) return std::nullopt;
    return sum / static_cast<double>(count);
  };
  std::vector<SkirtingPlace> places;
  for (int piece = 0; piece < 3; ++piece) {
    std::vector<glm::dvec3> c;
    bool ok = true;
    const double from = h0 - reach - 3, to = h0 + 2 * reach + 4;
    for (double h = from; h <= to && ok; h += 1.0) {
      const auto colour = profileAt(piece, h);
      ok = colour.has_value();
      if (ok) c.push_back(*colour);
    }
    if (!ok) continue;
    const auto at = [&](double h) { return c[static_cast<size_t>(std::lround(h - from))]; };
    const glm::dvec3 wall = at(h0 - 2);
    double above = 0;
    for (double h = h0 - 2 - reach; h <= h0 - 2; h += 1.0) above = std::max(above, glm::length(at(h) - wall));
    // The board's foot: the largest step within reach, or (`firstEdge`) the first step
    // down to it at least kSkirtingFirstStepShare of it, where the step peaks.
    const auto stepAt = [&](double h) { return glm::length(at(h + 1) - at(h - 1)); };
    double bestStep = 0, edge = 0;
    for (double h = h0 + 2; h <= h0 + reach; h += 1.0) {
      if (stepAt(h) > bestStep) bestStep = stepAt(h), edge = h;
    }
    for (double h = h0 + 2; firstEdge && h < edge; h += 1.0) {
      const double step = stepAt(h);
      if (step >= std::max(kSkirtingUniformGrey, kSkirtingFirstStepShare * bestStep) && step >= stepAt(h + 1)) {
        edge = h;
        break;
      }
    }
    if (above > std::max(kSkirtingUniformGrey, kSkirtingPlainOfStep * bestStep)) continue;
    if (bestStep < kSkirtingUniformGrey) continue;
    glm::dvec3 band(0);
    int n = 0;
    for (double h = h0 + 1; h <= edge - 1; h += 1.0) band += at(h), ++n;
    if (n == 0) continue;
    band /= n;
    // The band is not the floor beyond, over as wide a stretch (a floor's first row of
    // tiles is the floor's colour). It may be the wall's colour: a board painted as the
    // wall, the foot found on the line along its top (seeds 600-1399: 1090 and 1313 moved
    // right, none moved wrong; the sure 1259, 2.7 px off, and 1149, right, made guesses;
    // TUNE 450-599 unchanged; stop 57).
    glm::dvec3 beyond(0);
    for (double h = edge + 2; h <= edge + 1 + n; h += 1.0) beyond += at(h);
    if (glm::length(band - beyond / static_cast<double>(n)) < kSkirtingUniformGrey) continue;
    // A band narrower than the least is the found edge's own blur here: this place
    // shows no board (so it does not vote against the others).
    if (edge - h0 < kMinSkirtingPx) continue;
    places.push_back({edge - h0, above <= kSkirtingUniformGrey});
  }
  return places;
}

// The far wall's foot (`top` false) or top of `d` moved `shift` working pixels away from
// the wall along its sides (farWork: its corners in working pixels), and P5..P8 along the
// boundaries through the new corners where they are at the nearest depth inside the photo;
// false, `d` untouched, where that depth or a corner cannot be had.
bool moveFarSide(CorridorDetection& d, const WorkingImage& work, const Quad& farWork, bool top, double shift,
                 cv::Size size) {
  const glm::dvec3 horizontal = work.toWorking(d.horizontal.point), vertical = work.toWorking(d.vertical.point);
  // The side's left corner moves along the left side; its right one is where the
  // horizontal through it meets the right side.
  const int left = top ? 0 : 2, right = top ? 1 : 3;
  const glm::dvec2 moved = farWork[left] + shift * directionTowards(vertical, farWork[2 - left], {0, top ? -1.0 : 1.0});
  const auto other =
      intersect(lineThrough(homogeneous(moved), horizontal), lineThrough(homogeneous(farWork[top ? 3 : 1]), vertical));
  if (!other) return false;
  std::array<glm::dvec2, 8> corners = cornerPixels(d);
  corners[left] = work.toFull(moved), corners[right] = work.toFull(*other);
  if (d.nearDepth == NearDepth::kImageEdge) {
    const auto near = nearestSectionInside(d, {corners[P1], corners[P2], corners[P3], corners[P4]}, size);
    if (!near) return false;
    setNearCorners(corners, *near);
  }
  for (const glm::dvec2& p : corners)
    if (!(std::isfinite(p.x) && std::isfinite(p.y))) return false;
  for (int k = 0; k < kCornerCount; ++k) d.corners[k].px = corners[k];
  return true;
}

// How far a guess's foot moves onto a skirting board's foot: where two or three places
// show the board and all of them agree (it runs all around).
std::optional<double> skirtingShift(const std::vector<double>& moves) {
  if (moves.size() < 2) return std::nullopt;
  const auto [least, most] = std::minmax_element(moves.begin(), moves.end());
  if (*most - *least > kSkirtingAgreePx) return std::nullopt;
  return 0.5 * (*least + *most);
}

// A far-wall foot that may be a skirting board's top (skirtingBelow). A sure answer
// where any place shows a board becomes unsure, its foot kept: on the random TUNE
// scenes 0-299 (clean) all 6 sure answers with their foot on a board's top (2-4 px above
// the truth, one of them wrong by the median of its corners) showed one, as did 4 sure
// answers with the foot right; moving the foot where only one place shows a board lost
// 18 right answers. A guess's P3 and P4 move down onto the board's foot where the places
// agree (skirtingShift), and P5..P8 along the boundaries through them at the nearest
// depth inside the photo, as before. A sure answer moves, and stays sure, only where all
// three places show the board and agree, and is otherwise a guess where any place shows
// one with the wall above it plain (the strict test, SkirtingPlace::wallPlain): the project's
// clutter_4 has a sure right foot above a band of shadow on the floor that two places
// agree on. TUNE 0-599, against moving a sure answer where two agree: the same right
// answers, 58 sure (56 right) against 61 (59) clean, 55 (52) against 55 (52) noisy.
// A sure answer so made a guess moves as a guess does where the places agree: seeds
// 600-1399, 2 more right (feet 4-9 px up on a board's top), none fewer; TUNE 450-599
// unchanged, clean and noisy (stop 57).
// (Fitting the far wall again would put the foot back on the board's top: its top and
// foot take their innermost edge.)
void belowSkirting(CorridorDetection& d, const WorkingImage& work, glm::dvec2 vpWork, cv::Size size) {
  const Quad farWork = farInWorking(d, work);
  const glm::dvec3 horizontal = work.toWorking(d.horizontal.point), vertical = work.toWorking(d.vertical.point);
  std::vector<double> moves, plain;  // every place that shows a board; those with the wall above plain
  for (const SkirtingPlace& place : skirtingBelow(work, vpWork, horizontal, vertical, farWork)) {
    moves.push_back(place.move);
    if (place.wallPlain) plain.push_back(place.move);
  }
  const std::optional<double> shift = skirtingShift(moves);
  if (d.confident && !(shift && moves.size() == 3)) {
    if (plain.empty()) return;
    const int px = static_cast<int>(std::lround(*std::max_element(plain.begin(), plain.end()) / work.scale));
    doubt(d, "a band like a skirting board's ends " + std::to_string(px) +
                 " px below the far wall's foot: the foot found may be the board's top");
    // Now a guess: it moves as a guess does (below), where the places agree.
  }
  if (!shift || !moveFarSide(d, work, farWork, /*top=*/false, *shift, size)) return;
  if (!d.confident) doubt(d, "the far wall's foot was taken below a skirting board, at the board's foot");
}

// A guess's far-wall top that may be the lower edge of a band under the ceiling (a
// strip of the wall in the ceiling's shadow, a pipe or a trim along the top): the
// skirting board's test turned upside down (skirtingBelow on the far wall flipped, the
// ceiling's boundaries for the floor's), and the top moved up onto the band's upper edge
// where the places that show one agree (skirtingShift). Guesses only: a sure answer is
// left as it is. Seeds 600-1399 (tuning data): +5/-1 right (601, 633, 831, 869, 1096:
// tops 3-8 px low; 972 moved off), and 601, a wrong answer the network had made sure
// (2.8 px), a right guess; TUNE 450-599: -1 clean (587, right and made sure by the
// network, moved 2.6 px off), +1 noisy (stop 57).
void aboveCeilingBand(CorridorDetection& d, const WorkingImage& work, glm::dvec2 vpWork, cv::Size size) {
  if (d.confident) return;
  const Quad farWork = farInWorking(d, work);
  const Quad flipped = {farWork[2], farWork[3], farWork[0], farWork[1]};
  const glm::dvec3 horizontal = work.toWorking(d.horizontal.point), vertical = work.toWorking(d.vertical.point);
  std::vector<double> moves;
  for (const SkirtingPlace& place : skirtingBelow(work, vpWork, horizontal, vertical, flipped, {0, -1},
                                                 /*firstEdge=*/false)) {
    moves.push_back(place.move);
  }
  const std::optional<double> shift = skirtingShift(moves);
  if (!shift || !moveFarSide(d, work, farWork, /*top=*/true, *shift, size)) return;
  doubt(d, "the far wall's top was taken at the upper edge of a band under the ceiling");
}

// The far wall `far` (P1 P2 P3 P4) with its foot half way up, where it is at least
// `minHeight` high along its sides and the horizon (through `vp` and the horizontal point)
// crosses it more than `minHorizonShare` of its height up from its foot: the true far wall
// were `far` a far wall and its reflection in the floor (that puts the horizon above its
// middle). Points homogeneous or not in one frame; nullopt otherwise.
std::optional<Quad> halfWayFoot(const Quad& far, glm::dvec2 vp, glm::dvec3 horizontal, glm::dvec3 vertical,
                                double minHorizonShare, double minHeight) {
  const glm::dvec2 down = directionTowards(vertical, far[0], {0, 1});
  const double height = glm::dot(far[2] - far[0], down);
  if (!(height > minHeight)) return std::nullopt;
  const auto horizon = intersect(lineThrough(homogeneous(vp), horizontal), lineThrough(homogeneous(far[0]), vertical));
  if (!horizon || !(glm::dot(far[2] - *horizon, down) > minHorizonShare * height)) return std::nullopt;
  const glm::dvec2 p3 = far[0] + 0.5 * height * down;
  const auto p4 = intersect(lineThrough(homogeneous(p3), horizontal), lineThrough(homogeneous(far[1]), vertical));
  if (!p4) return std::nullopt;
  return Quad{far[0], far[1], p3, *p4};
}

// A far wall found together with its reflection in a glossy floor: the walls mirror
// about their foot, so the box drawn from the ceiling's lines down to their reflections
// has its foot at the reflection of its top, and the true foot half way down (between
// a side wall's ceiling line and its reflection, its floor line lies half way, with the
// vertical's vanishing point far). Two things tell it from a true box. The camera's
// horizon crosses a reflected box above its middle, from its foot (the camera's height
// plus the wall's, over twice the wall's), and a true one at the camera's height over
// the wall's (the random scenes: 0.17-0.82; 15 of the 16 reflected boxes of TUNE 0-599:
// 0.61-0.82, the 3 right answers there that showed the next sign: 0.25-0.30). And the
// foot's line half way up divides surfaces, as do both lines through its ends from the
// corridor's vanishing point out to the photo's border (the floor's true boundaries),
// each over kMirrorFootShare of their length. Returns the far wall with its foot there
// (working pixels), or nullopt.
std::optional<Quad> reflectedFoot(const WorkingImage& work, glm::dvec2 vp, glm::dvec3 horizontal, glm::dvec3 vertical,
                                  const Quad& far) {
  const auto half = halfWayFoot(far, vp, horizontal, vertical, 0.5, 20);
  if (!half) return std::nullopt;
  const glm::dvec2 p3 = (*half)[2], p4 = (*half)[3];
  if (surfaceStep(work, p3, p4).share < kMirrorFootShare) return std::nullopt;
  const double shortSide = std::min(work.bgr.cols, work.bgr.rows);
  for (const glm::dvec2& corner : {p3, p4}) {
    const glm::dvec2 out = glm::normalize(corner - vp);
    const double length = std::min(0.3 * shortSide, distanceToBorder(work, corner, out) - 8);
    if (!(length > 10) || surfaceStep(work, corner + 3.0 * out, corner + length * out).share < kMirrorFootShare) {
      return std::nullopt;
    }
  }
  return half;
}

// Below this share of its length with edges along it, a boundary found near where a
// person put it is not seen (the project's scenes, cluttered too: 0.79 and more; the York
// Urban corridor P1040811: 0.36 and 0.00 for its ceiling's, white on white).
constexpr double kSeenBoundaryCoverage = 0.5;

// The box a person placed roughly (`hint`, pinhole pixels), fitted to the photo: each
// boundary put on the edge nearest the person's line (from the vanishing point to the
// near corner, the longer lever), the far wall at the best-edged section within reach
// of where they put it (or, where a boundary does not show, its sides fitted first:
// fitFarWallNear), then the full-resolution fits of a detection, with P5..P8 at
// the depth given. Where the photo does not bear the box out, the person's corners
// come back as they were, with no confidence and the reason as a doubt.
CorridorDetection fromHint(const FarWallSearch& s, CorridorDetection d, const std::array<glm::dvec2, 8>& hint) {
  const WorkingImage& work = s.work;
  const double reach = s.options.hintReachPx;
  constexpr std::array<int, kBoundaryCount> kFarOf = {P3, P4, P1, P2}, kNearOf = {P5, P6, P7, P8};
  const auto asGiven = [&](CorridorDetection out, const std::string& why) {
    for (int k = 0; k < kCornerCount; ++k) out.corners[k] = {hint[k], 0.0, reach};
    out.found = true;
    out.nearDepth = NearDepth::kGiven;
    doubt(out, why);
    return out;
  };
  // Each far corner within reach of the ray from the photo's vanishing point through its
  // near corner, as a box placed within reach of the photo's corners is. (Not where the
  // four receding lines meet: a boundary seen nearly end-on, its two corners a few
  // dozen pixels apart, swings by tens of degrees with a 15 px slip of either.)
  for (int b = 0; b < kBoundaryCount; ++b) {
    const glm::dvec2 far = hint[kFarOf[b]], out = hint[kNearOf[b]] - s.vp;
    const double off = glm::length(out) < 1 ? glm::length(far - s.vp)
                                            : std::abs(glm::dot(lineThrough(s.vp, hint[kNearOf[b]]), homogeneous(far)));
    if (off > 2.0 * reach) {
      return asGiven(d, std::string(cornerName(kFarOf[b])) + " lies " + std::to_string(std::lround(off)) +
                            " px off the line from the photo's vanishing point through " + cornerName(kNearOf[b]));
    }
  }
  std::array<double, kBoundaryCount> angle{}, angleReach{};
  for (int b = 0; b < kBoundaryCount; ++b) {
    const glm::dvec2 out = hint[kNearOf[b]] - s.vp;
    const double radius = glm::length(out);
    if (radius < 1) return asGiven(d, "a near corner lies on the vanishing point");
    angle[b] = std::atan2(out.y, out.x);
    angleReach[b] = std::max(reach / radius, 0.2 * 3.14159265358979 / 180);
  }
  const RecedingBoundaries boundaries = boundariesNear(work, s.vpWork, angle, angleReach);
  const CrossSectionFamily family(s.vpWork, work.toWorking(d.horizontal.point), work.toWorking(d.vertical.point),
                                  boundaries);
  const Quad farGiven = {work.toWorking(hint[P1]), work.toWorking(hint[P2]), work.toWorking(hint[P3]),
                         work.toWorking(hint[P4])};
  // The far wall as a section on the boundaries found, where they show; where one of
  // them does not (a white wall meeting a white ceiling, the boundary then taken on a
  // trim or on nothing), its four sides first, each near where it was put.
  const double tGiven = nearestSection(family, farGiven, 1.0, 2.0 * glm::length(farGiven[2] - s.vpWork) + 2.0);
  std::optional<CrossSectionMatch> far;
  if (*std::min_element(boundaries.edgeCoverage.begin(), boundaries.edgeCoverage.end()) < kSeenBoundaryCoverage) {
    d.hintBoundaryUnseen = true;
    far = fitFarWallNear(work, s.vpWork, work.toWorking(d.horizontal.point), work.toWorking(d.vertical.point), farGiven,
                         reach * work.scale);
  }
  if (!far) far = findFarWallNear(work, family, tGiven, reach * work.scale);
  const std::optional<Quad> farWork = far ? std::optional<Quad>(far->corners) : family.at(tGiven);
  if (!farWork) return asGiven(d, "the far wall's corners do not lie on the boundaries");
  const Quad nearGiven = nearQuadOf(hint);
  auto done = completeFromFarWall(s, d, *farWork, far ? far->t : tGiven,
                                  s.options.hintNearDepthGiven ? std::optional<Quad>(nearGiven) : std::nullopt,
                                  /*allowHiddenSide=*/true);
  if (!done) return asGiven(d, done.message());
  CorridorDetection fitted = std::move(done->detection);
  if (!far) doubt(fitted, "no far wall with edges on all four sides near where it was put");
  for (int k = 0; k < kCornerCount; ++k) {
    // A near corner slides along its boundary to the depth convention's place; only how
    // far it moved across the boundary counts.
    const bool isNear = k >= P5;
    const glm::dvec3 boundary = lineThrough(s.vp, fitted.corners[k].px);
    const double moved = isNear ? std::abs(glm::dot(boundary, homogeneous(hint[k])))
                                : glm::length(fitted.corners[k].px - hint[k]);
    if (moved > 2 * reach) {
      return asGiven(d, std::string(cornerName(k)) + " would move " + std::to_string(std::lround(moved)) +
                            " px from where it was put");
    }
  }
  return fitted;
}

}  // namespace

const char* focalSourceName(FocalSource source) {
  switch (source) {
    case FocalSource::kGiven: return "given";
    case FocalSource::kVanishingPoints: return "vanishing_points";
    case FocalSource::kDefault: return "default";
  }
  return "?";
}

const char* nearDepthName(NearDepth depth) {
  switch (depth) {
    case NearDepth::kMarkedCrossSection: return "marked_cross_section";
    case NearDepth::kImageEdge: return "image_edge";
    case NearDepth::kGiven: return "given";
  }
  return "?";
}

namespace {

// The focal length given, else the 28 mm-equivalent default.
double givenOrDefaultFocal(const DetectOptions& options, cv::Size size) {
  return options.focalPx.value_or(kDefaultFocalOverLongSide * std::max(size.width, size.height));
}

// Detection on the pinhole image `photo` (the photo itself, or the photo seen
// through its lens), whose working copy is `work` and its segments `segments`.
Result<CorridorDetection> findCorridorByEdges(const PinholeView& photo, const WorkingImage& work,
                                              const std::vector<LineSegment>& segments, const DetectOptions& options,
                                              glm::dvec2 pp) {
  const cv::Size size = photo.size();
  CorridorDetection d;
  d.principalPointPx = pp;
  d.segmentCount = static_cast<int>(segments.size());

  // Vanishing points, and the focal length when it is not given.
  d.focalSource = options.focalPx ? FocalSource::kGiven : FocalSource::kDefault;
  d.focalPx = givenOrDefaultFocal(options, size);
  auto frame = frameWithFocal(segments, d.focalPx, pp, size, options.focalPx.has_value());
  if (!frame) return notFound(d, frame.message());
  if (!options.focalPx) {
    if (auto second = focalFromSecondPoint(segments, *frame, pp, size)) {
      d.focalPx = second->first;
      d.focalSource = FocalSource::kVanishingPoints;
      frame = std::move(second->second);
    } else {
      d.warnings.push_back("focal length not given and the photo has no second finite vanishing point: assumed " +
                           std::to_string(static_cast<int>(std::lround(d.focalPx))) +
                           " px (a 28 mm-equivalent lens); lengths along the corridor scale with it");
    }
  }
  d.corridor = frame->corridor;
  d.horizontal = frame->horizontal;
  d.vertical = frame->vertical;
  d.hasVanishingPoints = true;
  const glm::dvec2 vp = d.corridor.pixel();
  if (!(vp.x >= 0 && vp.y >= 0 && vp.x <= size.width - 1 && vp.y <= size.height - 1)) {
    return notFound(d, "the lines meet outside the photo, not at a corridor's end");
  }
  // Beyond the loose limit the receding lines may still be a corridor's, scattered by
  // clutter's short edges (TUNE seeds 0-149: 19 of the 31 scenes with a box in view
  // and "no corridor" stopped here, at rms 3.0-10.9 degrees): the box is looked for
  // all the same (see `finish` below), and it is never a sure one.
  std::optional<std::string> scatteredLines;
  if (d.corridor.rmsAngleDeg > kMaxLooseCorridorRmsAngleDeg) {
    scatteredLines = "the receding lines do not meet in one point (rms " +
                     std::to_string(d.corridor.rmsAngleDeg).substr(0, 4) + " degrees)";
  }
  std::optional<std::string> looseVanishingPoint = scatteredLines;
  if (!looseVanishingPoint && d.corridor.rmsAngleDeg > kMaxCorridorRmsAngleDeg) {
    looseVanishingPoint = "the receding lines meet loosely (rms " + std::to_string(d.corridor.rmsAngleDeg).substr(0, 4) +
                          " degrees)";
  }
  if (d.corridor.confidence < kMinCorridorConfidence) {
    return notFound(d, "too few receding lines around the vanishing point (confidence " +
                           std::to_string(d.corridor.confidence).substr(0, 4) + ")");
  }

  // The far wall on the working copy: first where the angular profile puts the four
  // boundaries (the clean corridors), then, when that fails or leaves doubts, from the
  // room's box fitted to all the edges (clutter hides boundaries).
  const FarWallSearch search{photo, work, options, vp, work.toWorking(vp)};
  // A far wall that reaches down into its reflection (reflectedFoot): completed again
  // with its foot half way down; the answer a guess.
  const auto unreflected = [&](const Candidate& c) -> std::optional<Candidate> {
    const Quad farWork = farInWorking(c.detection, work);
    const auto foot = reflectedFoot(work, search.vpWork, work.toWorking(d.horizontal.point), work.toWorking(d.vertical.point), farWork);
    if (!foot) return std::nullopt;
    auto done = completeFromFarWall(search, d, *foot, glm::length((*foot)[2] - search.vpWork), std::nullopt, true);
    // (The full-resolution fit may find the foot where it was: then it stands.)
    if (!done || glm::length(work.toWorking(done->detection.corners[P3].px) - farWork[2]) <
                     0.25 * glm::length(farWork[2] - farWork[0])) {
      return std::nullopt;
    }
    if (looseVanishingPoint) doubt(done->detection, *looseVanishingPoint);
    doubt(done->detection, "the far wall found reached down into its reflection in a glossy floor: its foot was taken half way down");
    return std::move(*done);
  };
  if (options.hintPx) {
    CorridorDetection fitted = fromHint(search, d, *options.hintPx);
    if (looseVanishingPoint) doubt(fitted, *looseVanishingPoint);
    return fitted;
  }
  std::string profileReason;
  std::optional<Candidate> fromProfile;
  // Each search's far wall that was found but not completed (working pixels, its depth).
  std::optional<std::pair<Quad, double>> profileFar, boxFar;
  const glm::dvec2 horizon = directionTowards(d.horizontal.point, vp);
  auto boundaries = findRecedingBoundaries(work, search.vpWork, std::atan2(horizon.y, horizon.x),
                                           std::pair{work.toWorking(d.horizontal.point), work.toWorking(d.vertical.point)});
  if (!boundaries) profileReason = boundaries.message();
  for (int b = 0; boundaries && b < kBoundaryCount && profileReason.empty(); ++b) {
    if (b != boundaries->implied && boundaries->edgeCoverage[b] < kMinBoundaryEdgeCoverage) {
      profileReason = std::string("no edge along the ") + boundaryName(b) + " boundary";
    }
  }
  if (profileReason.empty()) {
    const auto familyOf = [&](const RecedingBoundaries& rays) {
      return CrossSectionFamily(search.vpWork, work.toWorking(d.horizontal.point), work.toWorking(d.vertical.point), rays);
    };
    auto farWall = findFarWall(work, familyOf(*boundaries));
    // Where the set taken finds no far wall, or one with a side hidden, its boundaries
    // may be a wrong box's (a person's outline before the far wall's corners) and a lighter
    // set the true one: each (heaviest first) is taken where its far wall scores
    // clearly better, or where the set taken found none. Not where the set taken
    // found all four sides: there a far wall along a cabinet's or a band's edges can score
    // better than the true one (DetectParts.RoomBoxFindsTheFarWallBehindClutter, the
    // project's clutter_5; see docs/detection-accuracy.md for the TUNE figures).
    if (!farWall || farWall->hiddenSide >= 0) {
      const std::vector<RecedingBoundaries> alternatives = std::move(boundaries->alternatives);  // taking one replaces *boundaries
      for (const RecedingBoundaries& alternative : alternatives) {
        auto wall = findFarWall(work, familyOf(alternative));
        if (wall && (!farWall || wall->score > farWall->score + kAlternativeFarWallGain)) {
          farWall = std::move(wall);
          *boundaries = alternative;
        }
      }
    }
    const bool thin = farWall && farWall->score < kClearFarWallScore;
    const std::string thinly = thin ? "the far wall's sides and the boundaries beyond it are seen thinly (score " +
                                          std::to_string(farWall->score).substr(0, 4) + ")"
                                    : std::string();
    if (!farWall) {
      profileReason = farWall.message();
    } else if (thin && scatteredLines) {
      // Scattered lines and a thin far wall together are not taken (York Urban's
      // training half: a pole in a subway car, a stairway outdoors; TUNE 0-299: 4 of
      // 6 such answers wrong, the other 2 found right by the room's box fit as well).
      profileReason = "no far wall: " + thinly;
    } else if (auto done = completeFromFarWall(search, d, farWall->corners, farWall->t, std::nullopt,
                                               /*allowHiddenSide=*/farWall->hiddenSide >= 0);
               !done) {
      profileReason = done.message();
      profileFar = std::pair{farWall->corners, farWall->t};
    } else {
      fromProfile = std::move(*done);
      if (thin) doubt(fromProfile->detection, thinly);
      if (boundaries->implied >= 0) {
        doubt(fromProfile->detection, std::string("the ") + boundaryName(boundaries->implied) +
                                          " boundary does not show: it was taken where the other three put it");
      }
    }
  }
  if (fromProfile && looseVanishingPoint) doubt(fromProfile->detection, *looseVanishingPoint);
  // The room's box fitted to all the edges: the second search (clutter hides the
  // boundaries), and the check a sure answer from the profile must pass.
  std::string boxReason;
  std::optional<Candidate> fromBox;
  auto box = fitRoomBox(work, search.vpWork, work.toWorking(d.horizontal.point), work.toWorking(d.vertical.point),
                        segments, frame->labels);
  if (!box) {
    boxReason = box.message();
  } else if (auto done = completeFromFarWall(search, d, box->corners, glm::length(box->corners[2] - search.vpWork));
             !done) {
    boxReason = done.message();
    boxFar = std::pair{box->corners, glm::length(box->corners[2] - search.vpWork)};
  } else {
    fromBox = std::move(*done);
  }
  if (fromProfile && fromProfile->detection.confident) {
    // Sure only where the box fit completes the same far wall within kAgreementPx (TUNE
    // 0-599: sure answers 58 -> 41, one of the two wrong ones caught, 384; noisy 55 -> 37,
    // all three wrong ones caught. 589, a far wall taken with its reflection, is found so
    // by both fits).
    if (!fromBox) {
      doubt(fromProfile->detection,
            "the room's box fitted to all the edges, the second fit a sure answer needs, found none (" + boxReason + ")");
    } else if (const double apartPx = farWallDistancePx(fromProfile->detection, fromBox->detection); apartPx > kAgreementPx) {
      doubt(fromProfile->detection, fitsDisagree(apartPx));
    }
    if (auto mirrored = unreflected(*fromProfile)) return mirrored->detection;
    belowSkirting(fromProfile->detection, work, search.vpWork, photo.size());
    aboveCeilingBand(fromProfile->detection, work, search.vpWork, photo.size());
    return fromProfile->detection;
  }
  // Where the angular profile found no far wall, the box fit's best box may be a nearer
  // rectangle of clutter's edges (a person before a far corner, a bench along the foot)
  // and one of its next best the far wall. Those completed are guesses; one whose
  // surfaces are not alike (assess) is taken over the best where the best's are and its
  // support is no more than kAlternativeSupportGain lower, or where its support is that
  // much higher with as many boundaries dividing surfaces. TUNE 0-599: +5/-0 clean,
  // +4/-0 noisy. Taking the best of them by support alone moved 48 of the box fit's own
  // answers right and 26 wrong; taking one where the profile's answer stood too lost more
  // than it gained (the box fit's best is what that answer is checked against); an
  // alternative with alike surfaces lost clutter_8, one with much less support TUNE 495
  // and 167. Not with scattered lines: York Urban's P1020819, a building's front seen
  // from the street, got a box that way.
  if (fromBox && !fromProfile && !scatteredLines) {
    std::vector<Candidate> alternatives;
    for (const RoomBox& alt : box->alternatives) {
      auto done = completeFromFarWall(search, d, alt.corners, glm::length(alt.corners[2] - search.vpWork));
      if (done) alternatives.push_back(std::move(*done));
    }
    const Candidate* chosen = &*fromBox;
    for (const Candidate& alt : alternatives) {
      const bool chosenAlike = chosen->surfacesAlike.has_value(), altAlike = alt.surfacesAlike.has_value();
      if (!altAlike && (chosenAlike ? alt.support >= chosen->support - kAlternativeSupportGain
                                    : alt.support >= chosen->support + kAlternativeSupportGain &&
                                          alt.dividingBoundaries >= chosen->dividingBoundaries)) {
        chosen = &alt;
      }
    }
    if (chosen != &*fromBox) {
      fromBox = *chosen;
      doubt(fromBox->detection, "the far wall is another of the rectangles the room's box fit found, not its best");
    }
  }
  if (fromBox && looseVanishingPoint) doubt(fromBox->detection, *looseVanishingPoint);
  // The room's box fitted to the edges stands where the boundaries are partly hidden,
  // and its answers are sure only where its edges are seen along nearly all their
  // length: the random TUNE scenes 0-299 (clean and noisy) had 37 of its 47 sure
  // answers right, against 55 of 59 where the four boundaries were found in the angular
  // profile; its wrong ones had a support of 0.65-0.90, its right ones 0.76-0.98.
  if (fromBox && fromBox->detection.confident && fromBox->support < kSureBoxFitSupport) doubt(fromBox->detection, kBoxFitOnlyDoubt);
  // Neither far wall completed: one side of it may be hidden (a person before a corner,
  // a cabinet before its foot; TUNE seeds 0-299: 57% of the scenes have a far corner
  // hidden). Its corners are then where the boundaries meet its other sides, as for a
  // person's rough box, and the answer is a guess at best.
  if (!fromProfile && !fromBox) {
    for (const auto& far : {profileFar, boxFar}) {
      if (!far) continue;
      auto done = completeFromFarWall(search, d, far->first, far->second, std::nullopt, /*allowHiddenSide=*/true);
      if (done && (!fromBox || done->support > fromBox->support)) fromBox = std::move(*done);
    }
    if (fromBox && looseVanishingPoint) doubt(fromBox->detection, *looseVanishingPoint);
  }
  // (The vanishing point may be right with its lines scattered (clutter's short edges):
  // the far wall's reason is said too.)
  if (!fromProfile && !fromBox) return notFound(d, scatteredLines ? *scatteredLines + "; " + profileReason : profileReason);
  // With scattered lines, a box is believed (as a guess: exit 3) only where its
  // boundaries and its far wall's top and foot divide surfaces: a photo of something
  // else (tests/data/detect/camera.png) finds a rectangle among its many edges, but not
  // a room's box around it. That its boundaries run on from its corners is not asked:
  // the clutter that scatters the lines hides them (TUNE 0-299: 14 of the 43 clean
  // scenes with "no corridor" and the box in view stopped there; asked no more, 7 right
  // answers, 4 near misses and 7 wrong guesses, clean and noisy). The angular profile's
  // answer is not asked either: its boundaries are where the profile's colour steps
  // are, and the test along them, a second look, refused right answers (TUNE 0-599: of
  // its 15 answers so refused, clean and noisy, 8 right and 7 off by 4.8-12.7 px but one;
  // the box fit's, 2 right of 54).
  // A guess's foot searched afresh (bestFoot), taken where it scores clearly better;
  // the answer stays a guess.
  const auto refooted = [&](const Candidate& c) -> std::optional<Candidate> {
    if (c.detection.confident) return std::nullopt;
    Quad farWork = farInWorking(c.detection, work);
    const auto foot = bestFoot(work, search.vpWork, work.toWorking(d.horizontal.point), work.toWorking(d.vertical.point), farWork);
    if (!foot || glm::length(foot->left - farWork[2]) < kFootMovedPx || !(foot->score > kFootGain * foot->currentScore)) {
      return std::nullopt;
    }
    farWork[2] = foot->left, farWork[3] = foot->right;
    auto done = completeFromFarWall(search, d, farWork, glm::length(farWork[2] - search.vpWork), std::nullopt, true);
    if (!done) return std::nullopt;
    if (looseVanishingPoint) doubt(done->detection, *looseVanishingPoint);
    doubt(done->detection, "the far wall's foot was put where the floor's boundaries divide surfaces best");
    return std::move(*done);
  };
  const auto finish = [&](const Candidate& found) {
    const bool profiled = fromProfile && &found == &*fromProfile;
    if (scatteredLines && found.surfacesAlike && !profiled) return notFound(d, *scatteredLines + "; " + *found.surfacesAlike);
    std::optional<Candidate> better = unreflected(found);
    if (!better) better = refooted(found);
    // (A foot that shows no room where the one found did is not taken.)
    if (better && scatteredLines && better->surfacesAlike) better.reset();
    const Candidate& chosen = better ? *better : found;
    if (chosen.dividingBoundaries < kMinDividingBoundaries) return notFound(d, noRoomBox(chosen.dividingBoundaries));
    CorridorDetection out = chosen.detection;
    belowSkirting(out, work, search.vpWork, photo.size());
    aboveCeilingBand(out, work, search.vpWork, photo.size());
    return out;
  };
  if (!fromProfile) return finish(*fromBox);
  if (!fromBox) return finish(*fromProfile);
  // A profile with a boundary taken where the other three put it does not gainsay a sure
  // box fit, nor stand for it where the two agree.
  const double apartPx = farWallDistancePx(fromProfile->detection, fromBox->detection);
  if (boundaries->implied >= 0 && (fromBox->detection.confident || apartPx <= kAgreementPx)) return finish(*fromBox);
  // Both found and agreeing: the profile's answer, with its own doubts. Where its one
  // doubt is a single boundary running on inside the far wall's corners (a doorway's or
  // a band's line reaching the far wall), and finishing it added none, the two fits
  // agreeing make it sure (TUNE 0-599: 18 of 18 such answers right clean, 14 of 14 noisy).
  if (apartPx <= kAgreementPx) {
    CorridorDetection out = finish(*fromProfile);
    if (out.found && out.doubts == std::vector<std::string>{runsOnInside(1)}) {
      out.doubts.clear();
      out.confident = true;
      belowSkirting(out, work, search.vpWork, photo.size());  // as for a sure answer: a board below its foot doubts it
    }
    return out;
  }
  // Where they disagree, a fit whose boundaries, or whose far wall's top or foot, divide
  // surfaces alike (assess) has not found a room's box: the other is taken; else the one
  // with the better support. (TUNE 0-599, the answers where the two disagree: by support
  // alone 92 right clean, 97 noisy; the alike one refused, 100 and 107. The box fit's alike
  // answers are a cabinet's front or a doorway nearer, taken over a right profile for
  // their many edges.)
  const bool boxAlike = fromBox->surfacesAlike.has_value(), profileAlike = fromProfile->surfacesAlike.has_value();
  Candidate& better = boxAlike != profileAlike ? (boxAlike ? *fromProfile : *fromBox)
                      : fromBox->support >= fromProfile->support ? *fromBox
                                                                  : *fromProfile;
  doubt(better.detection, fitsDisagree(apartPx));
  return finish(better);
}

// The network's far wall as put in `guess`, each side refitted to the photo's edge within
// kLayoutSnapPx (refineCrossSection) where one shows along kLayoutSnapCoverage of it, the
// others left where they are; where kLayoutSnapSides sides or more moved so, the far
// corners where the sides meet and P5..P8 along the boundaries through them at the
// nearest depth inside the photo. The network puts a far wall's sides a few pixels off
// (its far corners' median 3.5 px on TUNE 450-599); the edges its sides lie along are in
// the photo, where the edges' own search, which needs the boundaries too, found no box.
// Returns how many sides moved (0: `guess` untouched).
int layoutSnapped(CorridorDetection& guess, const PinholeView& photo) {
  const Quad put = {guess.corners[P1].px, guess.corners[P2].px, guess.corners[P3].px, guess.corners[P4].px};
  const std::optional<glm::dvec2> vp =
      guess.corridor.isFinite() ? std::optional<glm::dvec2>(guess.corridor.pixel()) : std::nullopt;
  const RefinedSection far =
      refineCrossSection(photo, put, guess.horizontal.point, guess.vertical.point, kLayoutSnapPx, 2.0, 0.5, vp);
  // Each side's line: fitted, or through the corners as put (top, bottom, left, right).
  std::array<glm::dvec3, 4> line{};
  std::array<bool, 4> moved{};
  for (int side = 0; side < 4; ++side) {
    moved[side] = far.sideFitted[side] && far.sides[side].coverage >= kLayoutSnapCoverage;
    line[side] = moved[side] ? far.sides[side].line
                             : lineThrough(put[kSideCorners[side][0]], put[kSideCorners[side][1]]);
  }
  const int sidesMoved = static_cast<int>(std::count(moved.begin(), moved.end(), true));
  if (sidesMoved < kLayoutSnapSides) return 0;
  CorridorDetection out = guess;
  for (int k = 0; k < 4; ++k) {
    const auto p = intersect(line[kCornerSides[k][0]], line[kCornerSides[k][1]]);
    if (!p) return 0;
    const bool bothFitted = moved[kCornerSides[k][0]] && moved[kCornerSides[k][1]];
    out.corners[k] = {*p, bothFitted ? far.cornerConfidence[k] : 0.0, bothFitted ? far.cornerSigmaPx[k] : kLayoutGuessSigmaPx};
  }
  const auto near = nearestSectionInside(out, {out.corners[P1].px, out.corners[P2].px, out.corners[P3].px, out.corners[P4].px},
                                         photo.size());
  if (!near) return 0;
  setNearCorners(out, *near);
  if (!allFinite(out.corners)) return 0;
  guess = std::move(out);
  return sidesMoved;
}

// The network's box as it put it, a guess for a person to start from (exit 3) in place of
// `edges` (whose vanishing points and focal length it keeps), with `why` its one doubt;
// its far wall's sides moved onto the edges near them where they show (layoutSnapped);
// nullopt where its far wall is no corridor's end (farWallAspect). Each corner's sigma is
// the network's error on scenes it was not trained on (kLayoutGuessSigmaPx), or the fitted
// sides' where both through it were moved.
std::optional<CorridorDetection> layoutAsPut(const CorridorDetection& edges, const std::array<glm::dvec2, 8>& layout,
                                             const std::string& why, const PinholeView& photo) {
  CorridorDetection guess = edges;
  for (int k = 0; k < kCornerCount; ++k) guess.corners[k] = {layout[k], 0.0, kLayoutGuessSigmaPx};
  guess.found = true;
  guess.nearDepth = NearDepth::kImageEdge;
  const int sidesMoved = layoutSnapped(guess, photo);
  if (!isCorridorEndAspect(farWallAspect(guess))) return std::nullopt;
  guess.notFoundReason.clear();
  guess.doubts.clear();
  doubt(guess, sidesMoved ? why + "; " + std::to_string(sidesMoved) + " of its far wall's sides moved onto the edges within " +
                                std::to_string(static_cast<int>(kLayoutSnapPx)) + " px of them"
                          : why);
  return guess;
}

// The network's box fitted to the edges (`fitted`), a guess in place of `edges`, with
// `why` its one doubt.
CorridorDetection layoutFitted(const CorridorDetection& edges, CorridorDetection fitted, const std::string& why) {
  fitted.doubts.clear();
  doubt(fitted, why);
  fitted.warnings = edges.warnings;
  fitted.focalSource = edges.focalSource;
  return fitted;
}

// Whether a fit of the network's box to the edges found it in the photo (where it did
// not, fromHint gives the box back as put, with no confidence).
bool fitHolds(const Result<CorridorDetection>& fitted) {
  return fitted && fitted->found &&
         std::any_of(fitted->corners.begin(), fitted->corners.end(), [](const CornerEstimate& c) { return c.confidence > 0; });
}

// Where the edges found no box and do not bear the network's far wall out either: the
// network's box as it put it (layoutAsPut), where the photo looks like a room to the
// network (kLayoutRoomScore) or the edges found the room's four boundaries but no far
// wall where they begin (kNoFarWallAcrossBoundaries: its foot or its corners hidden), and
// the corridor's lines meet inside the photo. Not otherwise: a road, a street or a
// portrait gives the edges' other reasons (too few receding lines, boundaries that divide
// no surfaces) too, and the network a box all the same, though one it fits less well.
CorridorDetection layoutGuess(const CorridorDetection& edges, const LayoutFit& fit, const std::array<glm::dvec2, 8>& layout,
                              const PinholeView& photo) {
  const bool boundariesFound = edges.notFoundReason == kNoFarWallAcrossBoundaries;
  if (!boundariesFound && !(fit.wholeScore >= kLayoutRoomScore)) return edges;
  if (!corridorMeetsInside(edges, photo.size())) return edges;
  auto guess = layoutAsPut(edges, layout,
                           "the far wall is where the layout network put it; the photo's edges do not bear it out, and alone found " +
                               (boundariesFound ? std::string("the room's four boundaries but no far wall")
                                                : "no box: " + edges.notFoundReason),
                           photo);
  return guess ? std::move(*guess) : edges;
}

// An unsure answer of the edges whose far wall the network finds far less likely than
// its own box fitted to the edges (kLayoutPrefersBy in the far wall's neighbourhood, and
// less likely in the whole photo too), on a photo that looks like a room to it
// (kLayoutRoomScore): that box in its place, or the network's box as it put it where the
// fit strays from it (kLayoutFitStraysPx) or found nothing; and the fitted box where the
// network finds the edges' answer less likely than that box by kLayoutFitPrefersBy, and
// no likelier in the whole photo. The edges' answers it replaces are mostly a nearer
// cross-section, a door or a cabinet's front taken for the far wall, tens of pixels off.
// A guess still (exit 3): where the two looks disagree, neither is sure.
std::optional<CorridorDetection> layoutOverEdges(const CorridorDetection& edges,
                                                 const std::function<Result<CorridorDetection>()>& fitToEdges,
                                                 const LayoutFit& fit, const std::array<glm::dvec2, 8>& layout,
                                                 double focalPx, glm::dvec2 pp, const CorridorAxes& axes,
                                                 const PinholeView& photo) {
  if (!(fit.wholeScore >= kLayoutRoomScore)) return std::nullopt;
  const auto score = [&](const std::array<glm::dvec2, 8>& c, bool zoomed) {
    return boxScore(fit, {c[P1], c[P2], c[P3], c[P4]}, focalPx, pp, axes, zoomed);
  };
  const std::array<glm::dvec2, 8> ours = cornerPixels(edges);
  const auto ourNear = score(ours, true);
  // (The network's own box is the likeliest near it: where the edges' is not less likely
  // than that one, it is not less likely than the fitted one; no fit needed.)
  const auto layoutNear = score(layout, true);
  if (!ourNear || !layoutNear || *ourNear > *layoutNear - kLayoutFitPrefersBy) return std::nullopt;
  const Result<CorridorDetection> fitted = fitToEdges();
  const bool holds = fitHolds(fitted) && farWallMedianDistancePx(cornerPixels(*fitted), layout) <= kLayoutFitStraysPx;
  const std::array<glm::dvec2, 8> theirs = holds ? cornerPixels(*fitted) : layout;
  const auto theirNear = holds ? score(theirs, true) : layoutNear;
  const auto ourWhole = score(ours, false), theirWhole = score(theirs, false);
  if (!ourNear || !theirNear || !ourWhole || !theirWhole) return std::nullopt;
  const bool farLessLikely =
      *ourNear <= *theirNear - kLayoutPrefersBy && *ourWhole < *theirWhole - (holds ? 0.0 : kLayoutAloneWholeBy);
  const bool lessLikelyThanFitted = holds && *ourNear <= *theirNear - kLayoutFitPrefersBy && *ourWhole <= *theirWhole;
  if (!farLessLikely && !lessLikelyThanFitted) return std::nullopt;
  char figures[160];
  std::snprintf(figures, sizeof figures, "log-probability per pixel %.2f against %.2f", *ourNear, *theirNear);
  if (!farLessLikely) {
    return layoutFitted(edges, *fitted,
                        "the far wall the edges found is less likely to the layout network than its box fitted to the "
                        "edges (" + std::string(figures) + "): that box instead");
  }
  const std::string why = "the far wall the edges found is unlikely to the layout network (" + std::string(figures) + "): ";
  if (holds) return layoutFitted(edges, *fitted, why + "its box fitted to the edges instead");
  return layoutAsPut(edges, layout, why + "its box as it put it instead (the edges do not bear it out)", photo);
}

Result<CorridorDetection> findCorridor(const PinholeView& photo, const WorkingImage& work,
                                       const std::vector<LineSegment>& segments, const DetectOptions& options,
                                       glm::dvec2 pp);

// A far wall and its reflection in the floor, taken for one far wall, has the horizon at
// (c + h) / 2h of its height up from its foot (c the camera's height, h the wall's): with
// the camera at least a sixth of the way up (every random scene; 1 m in a 6 m corridor),
// at 0.58 or more. (The random TUNE scenes' 13 such boxes: 0.59-0.85. A true far wall has
// the horizon at c / h: 0.54 in the project's corridor_a, 1.5 m in 2.8 m.)
constexpr double kMinReflectedHorizonShare = 0.58;

// The far wall of `d` with its foot half way up (full-resolution pixels, P1..P8; P5..P8
// at the nearest section inside the photo), where the horizon crosses the far wall
// more than kMinReflectedHorizonShare of the way up: what the true far wall would be were
// the one found a far wall and its reflection in a glossy floor; nullopt otherwise.
std::optional<std::array<glm::dvec2, 8>> halfFootBox(const CorridorDetection& d, cv::Size size) {
  std::array<glm::dvec2, 8> c = cornerPixels(d);
  const auto half = halfWayFoot({c[P1], c[P2], c[P3], c[P4]}, d.corridor.pixel(), d.horizontal.point, d.vertical.point,
                                kMinReflectedHorizonShare, 0);
  if (!half) return std::nullopt;
  c[P3] = (*half)[2], c[P4] = (*half)[3];
  const auto near = nearestSectionInside(d, *half, size);
  if (!near) return std::nullopt;
  setNearCorners(c, *near);
  for (const glm::dvec2& p : c)
    if (!(std::isfinite(p.x) && std::isfinite(p.y))) return std::nullopt;
  return c;
}

// A sure answer of the edges that may be a far wall and its reflection in a mirror-like
// floor: there the reflection is as plain as the wall, so the floor's true boundaries and
// the foot half way down divide no surfaces and reflectedFoot does not see it, and both
// fits find the same doubled far wall (the random TUNE scenes' two sure answers tens of
// pixels off: 589 and 1394, of 340 sure answers, clean and noisy). Where the horizon
// crosses the far wall high enough for that (halfFootBox: 18 of the 340), the layout
// network looks at the whole photo, and where it finds the far wall with its foot half way
// up likelier than the one found, that box, fitted to the edges as a person's rough box is
// (`fitToEdges`; as put where the fit strays from it), replaces the answer, a guess. On
// TUNE the two reflections had the half-foot box likelier by 0.27 and 1.71 (mean
// log-probability per pixel), every right sure answer with the horizon above the far
// wall's middle less likely by 0.47 or more. (The far wall's neighbourhood's look agreed,
// 0.23 and 1.22 against -0.23 or less; it is not asked: the whole photo's look alone is
// half the networks' time, some 40 ms at 12 MP on two cores.)
std::optional<CorridorDetection> unreflectedSure(
    const CorridorDetection& edges, const std::function<Result<CorridorDetection>(const std::array<glm::dvec2, 8>&)>& fitToEdges,
    const WorkingImage& work, glm::dvec2 pp, const PinholeView& photo) {
  const auto half = halfFootBox(edges, photo.size());
  if (!half) return std::nullopt;
  const CorridorAxes axes = corridorAxes(edges.horizontal.point, edges.vertical.point, edges.corridor.point, edges.focalPx, pp);
  const auto looked = lookAtWholePhoto(work.bgr, work.scale, edges.focalPx, pp, axes);
  if (!looked) return std::nullopt;
  const auto score = [&](const std::array<glm::dvec2, 8>& c) {
    return boxScore(*looked, {c[P1], c[P2], c[P3], c[P4]}, edges.focalPx, pp, axes, /*zoomed=*/false);
  };
  const auto foundScore = score(cornerPixels(edges)), halfScore = score(*half);
  if (!foundScore || !halfScore || !(*halfScore > *foundScore)) return std::nullopt;
  char figures[160];
  std::snprintf(figures, sizeof figures, "log-probability per pixel %.2f against %.2f", *halfScore, *foundScore);
  const std::string why = "the far wall found may reach down into its reflection in a glossy floor: the layout network "
                          "finds it likelier with its foot half way down (" + std::string(figures) + "): that box";
  const Result<CorridorDetection> fitted = fitToEdges(*half);
  if (fitHolds(fitted) && farWallMedianDistancePx(cornerPixels(*fitted), *half) <= kLayoutFitStraysPx) {
    return layoutFitted(edges, *fitted, why + " fitted to the edges");
  }
  CorridorDetection out = edges;
  for (int k = 0; k < kCornerCount; ++k) out.corners[k] = {(*half)[k], 0.0, kLayoutGuessSigmaPx};
  out.confident = false;
  out.doubts.clear();
  doubt(out, why + " (the edges do not bear it out)");
  return out;
}

// A person's rough box (options.hintPx) fitted to the photo's edges (fromHint), weighed
// against detection's own answer where that answer's far corners each lie within reach
// of the person's: where the two far walls agree within kHintAgreesPx, the fit's corners
// with detection's verdict (sure only where detection is); where the fit found nothing
// (the person's corners came back as put) or disagrees, detection's answer, with P5..P8
// at the person's depth (withNearAsPut): it looks at the whole photo (the far wall's
// alternatives, the layout network), the fit only at the edges near each line put. But
// where a receding boundary did not show near the person's line (a white ceiling on
// white walls), the fit's far wall, fitted side by side, stays, doubted: detection hangs
// its far wall on those boundaries (DetectHint.AFarWallWhoseCeilingEdgesDoNotShowIsFittedSideBySide:
// detection's own answer 16 px off on 9 of its 30 rough boxes). Seeds 600-1399, one rough
// box per scene: far wall right 53.0% -> 63.2% clean, 48.8% -> 58.4% noisy.
Result<CorridorDetection> fitRoughBox(const PinholeView& photo, const WorkingImage& work,
                                      const std::vector<LineSegment>& segments, const DetectOptions& options, glm::dvec2 pp) {
  auto fitted = findCorridorByEdges(photo, work, segments, options, pp);
  if (!options.hintWeighsDetection || !fitted || !fitted->hasVanishingPoints) return fitted;
  DetectOptions alone = options;
  alone.hintPx.reset();
  auto own = findCorridor(photo, work, segments, alone, pp);
  if (!own || !own->found || farWallDistancePx(cornerPixels(*own), *options.hintPx) > options.hintReachPx) return fitted;
  const bool holds = fitHolds(fitted);
  const double apart = holds ? farWallDistancePx(cornerPixels(*own), cornerPixels(*fitted)) : 0.0;
  const std::string apartPx = std::to_string(std::lround(apart));
  if (holds && apart <= kHintAgreesPx) {
    fitted->confident = own->confident;
    fitted->doubts = own->doubts;
    return fitted;
  }
  if (holds && fitted->hintBoundaryUnseen) {
    doubt(*fitted, "the far wall detection finds on its own lies " + apartPx + " px from it");
    return fitted;
  }
  own->warnings.push_back("the far wall is the one detection finds on its own, within reach of the box put (the fit near "
                          "the lines put " +
                          (holds ? "lay " + apartPx + " px from it)" : std::string("found none)")));
  if (!options.hintNearDepthGiven) return own;
  auto asPut = withNearAsPut(std::move(*own), *options.hintPx, photo.size(), options.hintReachPx);
  return asPut ? std::move(*asPut) : fitted;
}

// Detection by the photo's edges (findCorridorByEdges); where that is unsure, the room's
// layout as the layout network sees it (layout_net.h) makes it sure where the two agree,
// takes the place of the edges' answer where it finds that answer far less likely than
// its own box, or less likely than its box fitted to the edges (layoutOverEdges), and
// starts a rough box's fit where the edges found none, or, where that fit fails, is itself
// the guess (layoutGuess: where the photo looks like a room to it, or the edges found the
// room's boundaries but no far wall).
Result<CorridorDetection> findCorridor(const PinholeView& photo, const WorkingImage& work,
                                       const std::vector<LineSegment>& segments, const DetectOptions& options,
                                       glm::dvec2 pp) {
  if (options.hintPx) return fitRoughBox(photo, work, segments, options, pp);
  auto byEdges = findCorridorByEdges(photo, work, segments, options, pp);
  if (!byEdges || !byEdges->hasVanishingPoints) return byEdges;
  // A rough box fitted to the edges as a person's is (detect --hint), P5..P8 at the
  // nearest depth inside the photo.
  const auto fitBoxToEdges = [&](const std::array<glm::dvec2, 8>& box, double reachPx) {
    DetectOptions fromBox = options;
    fromBox.hintPx = box;
    fromBox.hintReachPx = reachPx;
    fromBox.focalPx = byEdges->focalPx;
    fromBox.hintNearDepthGiven = false;
    return findCorridorByEdges(photo, work, segments, fromBox, pp);
  };
  if (byEdges->found && byEdges->confident) {
    auto unreflected = unreflectedSure(
        *byEdges, [&](const std::array<glm::dvec2, 8>& box) { return fitBoxToEdges(box, kLayoutFitReachPx); }, work, pp,
        photo);
    return unreflected ? std::move(*unreflected) : std::move(*byEdges);
  }
  const CorridorAxes axes =
      corridorAxes(byEdges->horizontal.point, byEdges->vertical.point, byEdges->corridor.point, byEdges->focalPx, pp);
  const auto fit = fitLayout(work.bgr, work.scale, byEdges->focalPx, pp, axes);
  if (!fit) return byEdges;
  const auto layout = layoutCorners(*fit, byEdges->focalPx, pp, axes, photo.size(),
                                    kNearMarginOfShortSide * std::min(photo.size().width, photo.size().height));
  if (!layout) return byEdges;
  // An unsure answer of the edges whose far wall the network puts within a few pixels
  // of it: two independent looks at the room agree.
  if (byEdges->found && farWallDistancePx(cornerPixels(*byEdges), *layout) <= kLayoutAgreesPx) {
    byEdges->confident = true;
    byEdges->doubts.clear();
    return byEdges;
  }
  // The network's box fitted to the edges as a person's rough box is.
  const auto fitToEdges = [&](double reachPx) { return fitBoxToEdges(*layout, reachPx); };
  // Over an unsure answer of the edges, only where the network finds that answer's far
  // wall far less likely than its own: where a photo is unlike the scenes it learnt
  // from, the network can take a door at the far end for the far wall, and the door's
  // edges bear that out (DetectParts.RoomBoxFindsTheFarWallBehindClutter: 60 px off).
  if (byEdges->found) {
    auto over = layoutOverEdges(
        *byEdges, [&] { return fitToEdges(kLayoutFitReachPx); }, *fit, *layout, byEdges->focalPx, pp, axes, photo);
    return over ? std::move(*over) : std::move(*byEdges);
  }
  // Where the edges found no box, the network's box fitted to the edges is a guess where
  // the fit keeps it near where the network put it.
  auto fitted = fitToEdges(options.hintReachPx);
  if (!fitHolds(fitted) || farWallMedianDistancePx(cornerPixels(*fitted), *layout) > kLayoutFittedWithinPx) {
    return layoutGuess(*byEdges, *fit, *layout, photo);
  }
  return layoutFitted(*byEdges, std::move(*fitted),
                      "the far wall is where the layout network put it, fitted to the edges; the edges alone found none (" +
                          byEdges->notFoundReason + ")");
}

}  // namespace

Result<CorridorDetection> detectCorridor(const cv::Mat& photo, const DetectOptions& options) {
  if (photo.empty() || photo.type() != CV_8UC3) return makeError("detect needs an 8-bit colour photo");
  if (photo.cols < kMinPhotoSidePx || photo.rows < kMinPhotoSidePx) {
    return makeError("the photo is " + std::to_string(photo.cols) + "x" + std::to_string(photo.rows) +
                     " pixels; detection needs at least " + std::to_string(kMinPhotoSidePx) + " on each side");
  }
  if (options.focalPx && !(*options.focalPx > 0 && std::isfinite(*options.focalPx))) {
    return makeError("the focal length must be a positive number of pixels");
  }
  if (options.hintPx) {
    for (int k = 0; k < kCornerCount; ++k) {
      const glm::dvec2 p = (*options.hintPx)[k];
      if (!(std::isfinite(p.x) && std::isfinite(p.y))) return makeError(std::string("the hint's ") + cornerName(k) + " is not a number");
    }
    if (!(options.hintReachPx > 0 && std::isfinite(options.hintReachPx))) return makeError("the hint's reach must be positive");
  }
  if (options.lens) {
    if (Status lens = checkDistortion(*options.lens); !lens) return makeError("the lens given: " + lens.message());
  }
  const cv::Size size = photo.size();
  const glm::dvec2 pp = options.principalPointPx.value_or(glm::dvec2((size.width - 1) * 0.5, (size.height - 1) * 0.5));
  if (!(pp.x >= 0 && pp.y >= 0 && pp.x <= size.width - 1 && pp.y <= size.height - 1)) {
    return makeError("the principal point must lie inside the " + std::to_string(size.width) + "x" +
                     std::to_string(size.height) + " photo");
  }
  const double diagonal = std::hypot(size.width, size.height);
  const double minSegmentPx = kMinSegmentLengthOfDiagonal * diagonal;
  const WorkingImage work = makeWorkingImage(photo, std::max(kMinPhotoSidePx, options.workingMaxSidePx));
  const std::vector<LineSegment> segments = detectLineSegments(work.gray, work.scale, minSegmentPx);
  const double focalPx = givenOrDefaultFocal(options, size);
  // The lens: the one given, else the one the photo's straight lines show, if any.
  std::optional<PlumbLineFit> lens;
  if (options.lens) {
    if (!options.lens->isNone()) lens = PlumbLineFit{Intrinsics{focalPx, pp, *options.lens}};
  } else if (options.estimateDistortion) {
    lens = fitPlumbLines(work, segments, pp, focalPx);
  }
  if (!lens) return findCorridor(PinholeView(photo), work, segments, options, pp);

  // Through the lens: the working copy undistorted (cheap at its size), the
  // full-resolution fits reading the photo through the lens, the corners taken back
  // into the photo. The vanishing points stay the pinhole image's.
  const WorkingImage pinholeWork = undistortWorkingImage(work, lens->lens);
  DetectOptions pinholeOptions = options;
  if (options.hintPx) {
    // The person's corners are the photo's pixels: where the pinhole image has them.
    for (glm::dvec2& corner : *pinholeOptions.hintPx) corner = undistortPixel(lens->lens, corner).value_or(corner);
  }
  auto d = findCorridor(PinholeView(photo, lens->lens), pinholeWork,
                        detectLineSegments(pinholeWork.gray, pinholeWork.scale, minSegmentPx), pinholeOptions, pp);
  if (!d) return d;
  if (options.lens) {
    d->distortion = *options.lens;
  } else {
    // k1 fixes the bend in pixels as k1 / f²: the same bend for the focal length found.
    const double rescale = d->focalPx / lens->lens.focalPx;
    d->distortion.k1 = lens->lens.distortion.k1 * rescale * rescale;
    d->plumbLineCount = lens->lineCount;
  }
  if (!d->found) return d;
  for (CornerEstimate& corner : d->corners) corner.px = distortPixel(lens->lens, corner.px);
  return d;
}

double farWallAspect(const CorridorDetection& d) {
  const glm::dvec3 h = d.corridor.point;
  const glm::dvec3 along(h.x - d.principalPointPx.x * h.z, h.y - d.principalPointPx.y * h.z, d.focalPx * h.z);
  std::array<glm::dvec3, 4> onPlane{};
  for (int k = 0; k < 4; ++k) {
    const glm::dvec3 ray((d.corners[k].px - d.principalPointPx) / d.focalPx, 1.0);
    onPlane[k] = ray / glm::dot(along, ray);
  }
  const double width = glm::length(onPlane[P2] - onPlane[P1]) + glm::length(onPlane[P4] - onPlane[P3]);
  const double height = glm::length(onPlane[P3] - onPlane[P1]) + glm::length(onPlane[P4] - onPlane[P2]);
  return width / height;
}

std::optional<std::array<glm::dvec2, 8>> boxAlongVanishingPoints(const CorridorDetection& d, cv::Size size) {
  if (!d.hasVanishingPoints || !corridorMeetsInside(d, size)) return std::nullopt;
  const glm::dvec2 vp = d.corridor.pixel();
  const double half = 0.1 * std::min(size.width, size.height);
  const glm::dvec2 across = directionTowards(d.horizontal.point, vp, {1, 0});
  const glm::dvec2 down = directionTowards(d.vertical.point, vp, {0, 1});
  const glm::dvec3 left = lineThrough(homogeneous(vp - half * across), d.vertical.point);
  const glm::dvec3 right = lineThrough(homogeneous(vp + half * across), d.vertical.point);
  const glm::dvec3 top = lineThrough(homogeneous(vp - half * down), d.horizontal.point);
  const glm::dvec3 bottom = lineThrough(homogeneous(vp + half * down), d.horizontal.point);
  const auto p1 = intersect(top, left), p2 = intersect(top, right), p3 = intersect(bottom, left),
             p4 = intersect(bottom, right);
  if (!p1 || !p2 || !p3 || !p4) return std::nullopt;
  const auto near = nearestSectionInside(d, {*p1, *p2, *p3, *p4}, size);
  if (!near) return std::nullopt;
  std::array<glm::dvec2, 8> box{};
  box[P1] = *p1, box[P2] = *p2, box[P3] = *p3, box[P4] = *p4;
  setNearCorners(box, *near);
  for (const glm::dvec2& p : box)
    if (!(std::isfinite(p.x) && std::isfinite(p.y))) return std::nullopt;
  return box;
}

}  // namespace pw::metrology::detect
