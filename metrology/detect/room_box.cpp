#include "metrology/detect/room_box.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "metrology/detect/geometry.h"

namespace pw::metrology::detect {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kCandidatesPerSource = 6;  // per side, from each of three sources
constexpr int kCornerCandidates = 16;    // per quadrant
constexpr double kRayStepDeg = 0.2;
constexpr double kCornerApartDeg = 1.0;
constexpr int kSnapPx = 3;
constexpr size_t kUpperBoxes = 10;
constexpr double kMinSideGapPx = 3.0;       // candidates closer than this are one
constexpr double kMinTopSideCoverage = 0.3;  // the far wall's top and sides stand above most clutter
constexpr double kMinBottomSideCoverage = 0.15;
constexpr size_t kAlternatives = 5;  // the next best boxes fitRoomBox returns
constexpr int kDistinctBoxPx = 3;    // boxes whose four sides are all within this are one
constexpr size_t kKept = kAlternatives + 3;  // kept while searching: a kept box can be displaced

// The homography from the rectified plane (origin at the vanishing point, x towards
// the horizontal point, y towards the vertical one, one unit = one working pixel at
// the origin) to the working image: columns a·h, b·w, v.
cv::Matx33d rectifiedToImage(glm::dvec2 vp, glm::dvec3 horizontal, glm::dvec3 vertical) {
  const auto axis = [&](glm::dvec3 p, bool alongX) {
    glm::dvec2 d(p.x - p.z * vp.x, p.y - p.z * vp.y);  // derivative at the origin, up to scale
    double a = 1.0 / std::max(glm::length(d), 1e-12);
    if ((alongX ? d.x : d.y) < 0) a = -a;  // x right, y down on screen
    return glm::dvec3(a * p.x, a * p.y, a * p.z);
  };
  const glm::dvec3 hx = axis(horizontal, true), vy = axis(vertical, false);
  return cv::Matx33d(hx.x, vy.x, vp.x, hx.y, vy.y, vp.y, hx.z, vy.z, 1.0);
}

glm::dvec2 apply(const cv::Matx33d& m, glm::dvec2 p) {
  const cv::Vec3d q = m * cv::Vec3d(p.x, p.y, 1.0);
  return {q[0] / q[2], q[1] / q[2]};
}

// The rectified photo and its edge evidence, over the rectified bounding box of the
// photo (clipped to twice the photo's size around the vanishing point).
struct Rectified {
  cv::Matx33d toImage;  // rectified pixel (column, row) -> working pixel
  glm::dvec2 origin;    // the vanishing point's rectified pixel
  cv::Mat gradX, gradY;  // CV_32F colour gradient
  cv::Mat valid;         // CV_8U: inside the photo, away from its border
  cv::Mat sumX, sumY;    // integral images of the vertical-edge and horizontal-edge maps

  bool inside(glm::dvec2 p) const {
    const int x = static_cast<int>(p.x + 0.5), y = static_cast<int>(p.y + 0.5);
    return x >= 0 && y >= 0 && x < valid.cols && y < valid.rows && valid.at<uchar>(y, x);
  }
  // Share of the column x (rows y0..y1) on a vertical edge.
  double columnCoverage(int x, int y0, int y1) const {
    if (y1 <= y0 || x < 0 || x >= sumX.cols - 1) return 0;
    y0 = std::clamp(y0, 0, sumX.rows - 1), y1 = std::clamp(y1, 0, sumX.rows - 1);
    if (y1 <= y0) return 0;
    const int s = sumX.at<int>(y1, x + 1) - sumX.at<int>(y0, x + 1) - sumX.at<int>(y1, x) + sumX.at<int>(y0, x);
    return static_cast<double>(s) / (y1 - y0);
  }
  double rowCoverage(int y, int x0, int x1) const {
    if (x1 <= x0 || y < 0 || y >= sumY.rows - 1) return 0;
    x0 = std::clamp(x0, 0, sumY.cols - 1), x1 = std::clamp(x1, 0, sumY.cols - 1);
    if (x1 <= x0) return 0;
    const int s = sumY.at<int>(y + 1, x1) - sumY.at<int>(y, x1) - sumY.at<int>(y + 1, x0) + sumY.at<int>(y, x0);
    return static_cast<double>(s) / (x1 - x0);
  }
};

Result<Rectified> rectify(const WorkingImage& image, glm::dvec2 vp, glm::dvec3 horizontal, glm::dvec3 vertical) {
  const cv::Matx33d h = rectifiedToImage(vp, horizontal, vertical);
  const cv::Matx33d inv = h.inv();
  double x0 = -image.bgr.cols, x1 = image.bgr.cols, y0 = -image.bgr.rows, y1 = image.bgr.rows;
  double bx0 = 1e30, bx1 = -1e30, by0 = 1e30, by1 = -1e30;
  for (glm::dvec2 c : {glm::dvec2(0, 0), glm::dvec2(image.bgr.cols - 1, 0), glm::dvec2(0, image.bgr.rows - 1),
                       glm::dvec2(image.bgr.cols - 1, image.bgr.rows - 1)}) {
    const cv::Vec3d q = inv * cv::Vec3d(c.x, c.y, 1.0);
    if (!(q[2] > 0)) {  // the photo reaches the line at infinity: keep the clip box
      bx0 = x0, bx1 = x1, by0 = y0, by1 = y1;
      break;
    }
    bx0 = std::min(bx0, q[0] / q[2]), bx1 = std::max(bx1, q[0] / q[2]);
    by0 = std::min(by0, q[1] / q[2]), by1 = std::max(by1, q[1] / q[2]);
  }
  x0 = std::floor(std::max(x0, bx0)), x1 = std::ceil(std::min(x1, bx1));
  y0 = std::floor(std::max(y0, by0)), y1 = std::ceil(std::min(y1, by1));
  if (!(x0 < -4 && x1 > 4 && y0 < -4 && y1 > 4)) return makeError("the vanishing point is at the photo's edge");

  Rectified r;
  r.origin = {-x0, -y0};
  r.toImage = h * cv::Matx33d(1, 0, x0, 0, 1, y0, 0, 0, 1);
  const cv::Size size(static_cast<int>(x1 - x0) + 1, static_cast<int>(y1 - y0) + 1);
  cv::Mat bgr;
  cv::warpPerspective(image.bgr, bgr, cv::Mat(r.toImage), size, cv::INTER_LINEAR | cv::WARP_INVERSE_MAP,
                      cv::BORDER_REPLICATE);
  cv::warpPerspective(cv::Mat(image.bgr.size(), CV_8U, cv::Scalar(255)), r.valid, cv::Mat(r.toImage), size,
                      cv::INTER_NEAREST | cv::WARP_INVERSE_MAP, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::erode(r.valid, r.valid, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(5, 5)));
  colourGradient(bgr, r.gradX, r.gradY);
  cv::Mat edgeX, edgeY;
  cv::compare(cv::abs(r.gradX), kEdgeGreyPerPx, edgeX, cv::CMP_GT);
  cv::compare(cv::abs(r.gradY), kEdgeGreyPerPx, edgeY, cv::CMP_GT);
  // A pixel either side: the sides are found to the pixel, the edges are a pixel wide.
  cv::dilate(edgeX, edgeX, cv::Mat::ones(1, 3, CV_8U));
  cv::dilate(edgeY, edgeY, cv::Mat::ones(3, 1, CV_8U));
  edgeX &= r.valid, edgeY &= r.valid;
  cv::integral(edgeX / 255, r.sumX, CV_32S);
  cv::integral(edgeY / 255, r.sumY, CV_32S);
  return r;
}

// Every ray from the origin (the corridor's vanishing point), one per kRayStepDeg:
// whether an edge runs along it at each whole radius, and which side is brighter, as
// prefix sums. A boundary
// starts at a far-wall corner: edges beyond it, none over the far wall before it.
class RayTable {
 public:
  explicit RayTable(const Rectified& r) : origin_(r.origin) {
    const int count = static_cast<int>(std::lround(360.0 / kRayStepDeg));
    for (auto* prefix : {&rising_, &falling_}) prefix->resize(count);
    for (int a = 0; a < count; ++a) {
      const double angle = a * kRayStepDeg * kPi / 180.0;
      const glm::dvec2 d(std::cos(angle), std::sin(angle)), n(-d.y, d.x);
      std::vector<int>& rising = rising_[a];
      std::vector<int>& falling = falling_[a];
      rising.push_back(0), falling.push_back(0);
      for (double t = 0;; t += 1.0) {
        const glm::dvec2 q = origin_ + t * d;
        if (t > 3 && !r.inside(q)) break;
        if (t > 4 * (r.valid.cols + r.valid.rows)) break;
        double strongest = 0;  // the gradient across the ray, signed, strongest within a pixel
        for (int k = -1; k <= 1; ++k) {
          const glm::dvec2 e = q + static_cast<double>(k) * n;
          const int x = static_cast<int>(e.x + 0.5), y = static_cast<int>(e.y + 0.5);
          if (x < 0 || y < 0 || x >= r.gradX.cols || y >= r.gradX.rows) continue;
          const double across = r.gradX.at<float>(y, x) * n.x + r.gradY.at<float>(y, x) * n.y;
          if (std::abs(across) > std::abs(strongest)) strongest = across;
        }
        rising.push_back(rising.back() + (strongest > kEdgeGreyPerPx));
        falling.push_back(falling.back() + (strongest < -kEdgeGreyPerPx));
      }
    }
  }
  int angleIndex(glm::dvec2 p) const {
    const double angle = wrapAngle(std::atan2(p.y - origin_.y, p.x - origin_.x)) * 180.0 / kPi;
    return static_cast<int>(std::lround(angle / kRayStepDeg)) % angles();
  }
  // Edge share beyond `radius` (to the photo's border) and over its inner half.
  double outside(int a, double radius) const { return coverage(a, radius + 2, 1e9); }
  double inside(int a, double radius) const { return coverage(a, radius - std::max(10.0, 0.2 * radius), radius - 2); }
  double start(int a, double radius) const { return outside(a, radius) - inside(a, radius); }
  int length(int a) const { return static_cast<int>(rising_[a].size()) - 1; }
  int angles() const { return static_cast<int>(rising_.size()); }
  glm::dvec2 at(int a, double radius) const {
    const double angle = a * kRayStepDeg * kPi / 180.0;
    return origin_ + radius * glm::dvec2(std::cos(angle), std::sin(angle));
  }

 private:
  // A boundary is one edge between two surfaces: the same side brighter along it. A
  // texture's edges (wood grain, tiles, noise) along the ray flip from one to the
  // other, so only the commoner sign counts.
  double coverage(int a, double from, double to) const {
    const int n = length(a);
    const int i = std::clamp(static_cast<int>(from), 0, n), j = std::clamp(static_cast<int>(to), 0, n);
    if (j - i < 8) return 0.0;
    const int rising = rising_[a][j] - rising_[a][i], falling = falling_[a][j] - falling_[a][i];
    return (std::max(rising, falling) + 0.5 * std::min(rising, falling)) / (j - i);
  }
  glm::dvec2 origin_;
  std::vector<std::vector<int>> rising_, falling_;  // per ray, prefix counts of edges by sign
};

// The likeliest far-wall corners in one quadrant: on each ray, the radius where a
// boundary best starts; of those, the strongest local maxima over the angle.
std::vector<glm::dvec2> cornerCandidates(const RayTable& rays, double fromDeg, double toDeg) {
  struct Start {
    int angle;
    double radius, score;
  };
  std::vector<Start> starts;
  for (double deg = fromDeg; deg <= toDeg; deg += kRayStepDeg) {
    const int a = static_cast<int>(std::lround(wrapAngle(deg * kPi / 180.0) * 180.0 / kPi / kRayStepDeg)) % rays.angles();
    Start best{a, 0, 0};
    for (int radius = 6; radius + 10 < rays.length(a); ++radius) {
      const double score = rays.start(a, radius);
      if (score > best.score) best = {a, static_cast<double>(radius), score};
    }
    starts.push_back(best);
  }
  // Greedy: the strongest start, then the strongest more than kCornerApartDeg from
  // every one taken (a boundary's ray is a plateau of equal starts a degree wide).
  std::vector<int> order(starts.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return starts[x].score > starts[y].score; });
  const int apart = static_cast<int>(std::lround(kCornerApartDeg / kRayStepDeg));
  std::vector<int> taken;
  std::vector<glm::dvec2> out;
  for (int i : order) {
    if (static_cast<int>(out.size()) >= kCornerCandidates || starts[i].score < 0.2) break;
    bool far = true;
    for (int j : taken) far &= std::abs(i - j) > apart;
    if (!far) continue;
    taken.push_back(i);
    out.push_back(rays.at(starts[i].angle, starts[i].radius));
  }
  return out;
}

// Adds position i to `out` unless one there is within kMinSideGapPx of it.
void addApart(std::vector<int>& out, int i) {
  for (int j : out)
    if (std::abs(i - j) < kMinSideGapPx) return;
  out.push_back(i);
}

// The strongest `count` positions of a weight profile in [from, to), kMinSideGapPx apart.
std::vector<int> strongest(const std::vector<double>& weight, int from, int to, int count) {
  std::vector<int> order;
  for (int i = std::max(0, from); i < std::min<int>(to, static_cast<int>(weight.size())); ++i)
    if (weight[i] > 0) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return weight[a] > weight[b]; });
  std::vector<int> out;
  for (int i : order) {
    if (static_cast<int>(out.size()) >= count) break;
    addApart(out, i);
  }
  return out;
}

// Each position moves to the strongest of the profile within kSnapPx of it (a
// corner's ray start is found to a few pixels); the position itself is kept too.
std::vector<int> snapped(const std::vector<int>& in, const std::vector<double>& profile) {
  std::vector<int> out;
  for (int i : in) {
    int best = i;
    for (int k = std::max(0, i - kSnapPx); k <= std::min<int>(i + kSnapPx, static_cast<int>(profile.size()) - 1); ++k)
      if (profile[k] > profile[best]) best = k;
    if (std::find(out.begin(), out.end(), best) == out.end()) out.push_back(best);
    if (best != i && std::find(out.begin(), out.end(), i) == out.end()) out.push_back(i);
  }
  return out;
}

// Candidate positions of the far wall's sides on the rectified photo: columns for
// the left and right sides, rows for the top and bottom.
struct SideCandidates {
  std::vector<int> lefts, rights, tops, bottoms;
};

// Three sources for each side, and the corners' ray starts. Segments towards the
// horizontal and vertical points are the sides themselves (their length per column
// or row); segments towards the corridor's point (wall joints, floor tiles, the
// boundaries) start at the far wall's perimeter, so their inner ends mark its sides
// too; and the edge profile of bands beside the vanishing point at a few reaches.
SideCandidates candidateSides(const Rectified& r, const RayTable& rays, const WorkingImage& image,
                              const std::vector<LineSegment>& segments, const std::vector<int>& labels) {
  const int ox = static_cast<int>(std::lround(r.origin.x)), oy = static_cast<int>(std::lround(r.origin.y));
  const cv::Matx33d toRect = r.toImage.inv();
  std::vector<double> columnWeight(r.valid.cols, 0.0), rowWeight(r.valid.rows, 0.0);
  std::vector<double> columnStarts(r.valid.cols, 0.0), rowStarts(r.valid.rows, 0.0);
  const auto add = [](std::vector<double>& profile, double at, double weight) {
    const int i = static_cast<int>(std::lround(at));
    if (i >= 0 && i < static_cast<int>(profile.size())) profile[i] += weight;
  };
  for (size_t i = 0; i < segments.size() && i < labels.size(); ++i) {
    const glm::dvec2 a = apply(toRect, image.toWorking(segments[i].a)), b = apply(toRect, image.toWorking(segments[i].b));
    const double length = glm::length(b - a);
    if (!std::isfinite(length)) continue;
    if (labels[i] == 2) add(columnWeight, 0.5 * (a.x + b.x), length);
    if (labels[i] == 1) add(rowWeight, 0.5 * (a.y + b.y), length);
    if (labels[i] == 0) {
      const glm::dvec2 inner = glm::length(a - r.origin) < glm::length(b - r.origin) ? a : b;
      add(columnStarts, inner.x, length);
      add(rowStarts, inner.y, length);
    }
  }
  // Ends scatter by a pixel or so: a side's support is what falls within one of it.
  for (std::vector<double>* profile : {&columnWeight, &rowWeight, &columnStarts, &rowStarts}) {
    std::vector<double> smooth(profile->size(), 0.0);
    for (size_t i = 0; i < smooth.size(); ++i)
      for (int k = -1; k <= 1; ++k)
        if (i + k < smooth.size()) smooth[i] += (*profile)[i + k];
    *profile = std::move(smooth);
  }
  std::vector<double> columnProfile(r.valid.cols, 0.0), rowProfile(r.valid.rows, 0.0);
  for (int reach : {8, 24, 64, 160}) {
    for (int x = 0; x < r.valid.cols; ++x) {
      columnProfile[x] = std::max({columnProfile[x], r.columnCoverage(x, oy - reach, oy - 2),
                                   r.columnCoverage(x, oy + 2, oy + reach)});
    }
    for (int y = 0; y < r.valid.rows; ++y) {
      rowProfile[y] = std::max({rowProfile[y], r.rowCoverage(y, ox - reach, ox - 2), r.rowCoverage(y, ox + 2, ox + reach)});
    }
  }
  // Quadrants on screen (y down): top-left from 180 to 270 degrees, and so on.
  const std::vector<glm::dvec2> topLeft = cornerCandidates(rays, 181, 269), topRight = cornerCandidates(rays, 271, 359);
  const std::vector<glm::dvec2> bottomLeft = cornerCandidates(rays, 91, 179), bottomRight = cornerCandidates(rays, 1, 89);
  const auto side = [&](bool column, int from, int to, const std::vector<glm::dvec2>& cornersA,
                        const std::vector<glm::dvec2>& cornersB) {
    std::vector<int> out;
    for (const std::vector<double>* source : column ? std::array{&columnWeight, &columnStarts, &columnProfile}
                                                    : std::array{&rowWeight, &rowStarts, &rowProfile}) {
      for (int i : strongest(*source, from, to, kCandidatesPerSource)) addApart(out, i);
    }
    for (const std::vector<glm::dvec2>* corners : {&cornersA, &cornersB}) {
      for (glm::dvec2 c : *corners) addApart(out, static_cast<int>(std::lround(column ? c.x : c.y)));
    }
    return snapped(out, column ? columnProfile : rowProfile);
  };
  return {side(true, 0, ox - 3, topLeft, bottomLeft), side(true, ox + 4, r.valid.cols, topRight, bottomRight),
          side(false, 0, oy - 3, topLeft, topRight), side(false, oy + 4, r.valid.rows, bottomLeft, bottomRight)};
}

// The boundary through a corner (rectified pixels): the (outside, inside) edge
// shares of its ray. A corner found to the pixel fixes the ray's angle only to
// 1/radius: the ray within a pixel and a half of it that starts most clearly there.
using RayStart = std::pair<double, double>;
RayStart boundaryThrough(const Rectified& r, const RayTable& rays, int x, int y) {
  const glm::dvec2 c(x, y);
  const int a0 = rays.angleIndex(c);
  const double radius = glm::length(c - r.origin);
  const int reach = std::min(15, static_cast<int>(std::ceil(1.5 / std::max(radius, 1.0) * 180 / kPi / kRayStepDeg)));
  RayStart best{0, 0};
  for (int k = -reach; k <= reach; ++k) {
    const int a = (a0 + k + rays.angles()) % rays.angles();
    const double out = rays.outside(a, radius), in = rays.inside(a, radius);
    if (out - in > best.first - best.second) best = {out, in};
  }
  return best;
}

// The best boxes of the candidates. Their score: the four sides' edge shares, and
// more, the four boundaries' starts at its corners, the weakest counted again.
class BoxSearch {
 public:
  BoxSearch(const Rectified& r, const RayTable& rays) : r_(r), rays_(rays) {}

  // Boundaries: floor-left (bottom-left corner), floor-right, ceiling-left, ceiling-right.
  void consider(int x0, int x1, int y0, int y1, const std::array<RayStart, 4>& boundary) {
    const int xm = static_cast<int>(0.1 * (x1 - x0)), ym = static_cast<int>(0.1 * (y1 - y0));
    const std::array<double, 4> side = {r_.rowCoverage(y0, x0 + xm, x1 - xm), r_.rowCoverage(y1, x0 + xm, x1 - xm),
                                        r_.columnCoverage(x0, y0 + ym, y1 - ym), r_.columnCoverage(x1, y0 + ym, y1 - ym)};
    if (side[0] < kMinTopSideCoverage || side[1] < kMinBottomSideCoverage || side[2] < kMinTopSideCoverage ||
        side[3] < kMinTopSideCoverage) {
      return;
    }
    // The boundaries weigh most: a cabinet's front or a doorway has the four sides of
    // a rectangle too, but the walls' edges do not run on from all its corners.
    // Edges just before a corner count half against it: clutter before the far wall
    // has edges there too.
    double starts = 0, weakest = 1;
    for (auto [out, in] : boundary) starts += out - 0.5 * in, weakest = std::min(weakest, out - 0.5 * in);
    const double score = (side[0] + side[1] + side[2] + side[3]) / 8 + starts / 4 + weakest / 2;
    keep({score, seen_++, {x0, x1, y0, y1}, side, boundary});
  }

  // Every combination of the candidates; then, for the upper boxes (top and the
  // sides' upper halves, the ceiling's boundaries) that score best, every row as the
  // foot: the far wall's top and upper sides stand above most clutter, its foot may
  // be hidden but for a few stretches, or found only by where the floor's boundaries
  // run to.
  std::optional<RoomBox> search(const SideCandidates& c) {
    const int oy = static_cast<int>(std::lround(r_.origin.y));
    // Each corner's boundary once: [side candidate][row candidate].
    const auto table = [&](const std::vector<int>& xs, const std::vector<int>& ys) {
      std::vector<std::vector<RayStart>> t(xs.size(), std::vector<RayStart>(ys.size()));
      for (size_t i = 0; i < xs.size(); ++i)
        for (size_t j = 0; j < ys.size(); ++j) t[i][j] = boundaryThrough(r_, rays_, xs[i], ys[j]);
      return t;
    };
    const auto floorLeft = table(c.lefts, c.bottoms), floorRight = table(c.rights, c.bottoms);
    const auto ceilingLeft = table(c.lefts, c.tops), ceilingRight = table(c.rights, c.tops);
    struct Upper {
      int x0, x1, y0;
      double score;
    };
    std::vector<Upper> uppers;
    for (size_t il = 0; il < c.lefts.size(); ++il) {
      for (size_t ir = 0; ir < c.rights.size(); ++ir) {
        const int x0 = c.lefts[il], x1 = c.rights[ir];
        const int xm = static_cast<int>(0.1 * (x1 - x0));
        for (size_t it = 0; it < c.tops.size(); ++it) {
          const int y0 = c.tops[it];
          const double top = r_.rowCoverage(y0, x0 + xm, x1 - xm);
          if (top < kMinTopSideCoverage) continue;
          const int upperEnd = std::max(oy - 2, y0 + 10);
          const double left = r_.columnCoverage(x0, y0 + 2, upperEnd), right = r_.columnCoverage(x1, y0 + 2, upperEnd);
          const auto [leftOut, leftIn] = ceilingLeft[il][it];
          const auto [rightOut, rightIn] = ceilingRight[ir][it];
          uppers.push_back({x0, x1, y0, (top + left + right) / 3 + (leftOut - 0.5 * leftIn + rightOut - 0.5 * rightIn) / 2});
          for (size_t ib = 0; ib < c.bottoms.size(); ++ib) {
            consider(x0, x1, y0, c.bottoms[ib],
                     {floorLeft[il][ib], floorRight[ir][ib], ceilingLeft[il][it], ceilingRight[ir][it]});
          }
        }
      }
    }
    std::sort(uppers.begin(), uppers.end(), [](const Upper& a, const Upper& b) { return a.score > b.score; });
    for (size_t i = 0; i < uppers.size() && i < kUpperBoxes; ++i) {
      const Upper& u = uppers[i];
      const RayStart ceilingLeftRay = boundaryThrough(r_, rays_, u.x0, u.y0);
      const RayStart ceilingRightRay = boundaryThrough(r_, rays_, u.x1, u.y0);
      for (int y1 = oy + 4; y1 < r_.valid.rows; ++y1) {
        consider(u.x0, u.x1, u.y0, y1,
                 {boundaryThrough(r_, rays_, u.x0, y1), boundaryThrough(r_, rays_, u.x1, y1), ceilingLeftRay, ceilingRightRay});
      }
    }
    if (kept_.empty()) return std::nullopt;
    std::sort(kept_.begin(), kept_.end(), [](const Kept& a, const Kept& b) { return better(a, b); });
    RoomBox best = boxOf(kept_.front());
    for (size_t i = 1; i < kept_.size() && best.alternatives.size() < kAlternatives; ++i) {
      best.alternatives.push_back(boxOf(kept_[i]));
    }
    return best;
  }

 private:
  struct Kept {
    double score;
    long order;                  // of consideration: of equal scores the first is better
    std::array<int, 4> sides;    // x0, x1, y0, y1 on the rectified photo
    std::array<double, 4> coverage;
    std::array<RayStart, 4> boundary;
  };
  static bool better(const Kept& a, const Kept& b) { return a.score > b.score || (a.score == b.score && a.order < b.order); }

  // The best boxes, each a few pixels from the others: one near a kept box replaces it
  // when better; else it is kept while there is room or when it beats the worst kept.
  void keep(const Kept& box) {
    for (Kept& k : kept_) {
      bool near = true;
      for (int i = 0; i < 4; ++i) near &= std::abs(box.sides[i] - k.sides[i]) <= kDistinctBoxPx;
      if (!near) continue;
      if (better(box, k)) k = box;
      return;
    }
    if (kept_.size() < kKept) {
      kept_.push_back(box);
      return;
    }
    auto worst = std::min_element(kept_.begin(), kept_.end(), [](const Kept& a, const Kept& b) { return better(b, a); });
    if (better(box, *worst)) *worst = box;
  }

  RoomBox boxOf(const Kept& k) const {
    RoomBox box;
    box.score = k.score;
    box.sideCoverage = k.coverage;
    for (int b = 0; b < 4; ++b) box.rayOutside[b] = k.boundary[b].first, box.rayInside[b] = k.boundary[b].second;
    const auto [x0, x1, y0, y1] = k.sides;
    const std::array<glm::dvec2, 4> corners = {glm::dvec2(x0, y0), glm::dvec2(x1, y0), glm::dvec2(x0, y1),
                                               glm::dvec2(x1, y1)};
    for (int c = 0; c < 4; ++c) box.corners[c] = apply(r_.toImage, corners[c]);
    return box;
  }

  const Rectified& r_;
  const RayTable& rays_;
  std::vector<Kept> kept_;
  long seen_ = 0;
};

}  // namespace

Result<RoomBox> fitRoomBox(const WorkingImage& image, glm::dvec2 vp, glm::dvec3 horizontal, glm::dvec3 vertical,
                           const std::vector<LineSegment>& segments, const std::vector<int>& labels) {
  auto rect = rectify(image, vp, horizontal, vertical);
  if (!rect) return makeError(rect.message());
  const RayTable rays(*rect);
  const SideCandidates sides = candidateSides(*rect, rays, image, segments, labels);
  if (sides.lefts.empty() || sides.rights.empty() || sides.tops.empty() || sides.bottoms.empty()) {
    return makeError("no far wall: no rectangle of edges around the vanishing point");
  }
  std::optional<RoomBox> best = BoxSearch(*rect, rays).search(sides);
  if (!best) return makeError("no far wall: no rectangle of edges around the vanishing point");
  return *best;
}

}  // namespace pw::metrology::detect
