#include "metrology/detect/edge_fit.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "metrology/detect/geometry.h"
#include "metrology/distortion.h"

namespace pw::metrology::detect {

glm::dvec3 PinholeView::colour(glm::dvec2 p) const {
  if (lens_) p = distortPixel(*lens_, p);
  const cv::Mat& photo = photo_;
  const double x = std::clamp(p.x, 0.0, photo.cols - 1.001), y = std::clamp(p.y, 0.0, photo.rows - 1.001);
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const int x1 = std::min(x0 + 1, photo.cols - 1), y1 = std::min(y0 + 1, photo.rows - 1);
  const double fx = x - x0, fy = y - y0;
  const cv::Vec3b& a = photo.at<cv::Vec3b>(y0, x0);
  const cv::Vec3b& b = photo.at<cv::Vec3b>(y0, x1);
  const cv::Vec3b& c = photo.at<cv::Vec3b>(y1, x0);
  const cv::Vec3b& d = photo.at<cv::Vec3b>(y1, x1);
  glm::dvec3 out;
  for (int k = 0; k < 3; ++k) out[k] = (a[k] * (1 - fx) + b[k] * fx) * (1 - fy) + (c[k] * (1 - fx) + d[k] * fx) * fy;
  return out;
}

namespace {

constexpr double kMinStep = 8.0;  // grey levels between the two sides' mean colours

struct EdgePoint {
  glm::dvec2 p;
  double weight;
};

// The edge across one normal: Haar step response at every half-pixel between
// samples one pixel apart; of its peaks at least `relative` times the strongest, the
// one nearest the centre, placed by a parabola.
std::optional<EdgePoint> findEdge(const PinholeView& photo, glm::dvec2 centre, glm::dvec2 normal, double searchPx, int half,
                                  double relative, double inward) {
  const int reach = static_cast<int>(std::ceil(searchPx)) + half;
  std::vector<glm::dvec3> colour(2 * reach + 1);
  for (int k = -reach; k <= reach; ++k) colour[k + reach] = photo.colour(centre + static_cast<double>(k) * normal);
  // Response between sample j and j+1 (offset j + 0.5 from the centre).
  const int first = -reach + half - 1, last = reach - half;
  std::vector<double> response;
  for (int j = first; j < last; ++j) {
    glm::dvec3 before(0), after(0);
    for (int i = 0; i < half; ++i) before += colour[j - i + reach], after += colour[j + 1 + i + reach];
    response.push_back(glm::length(after - before) / half);
  }
  const auto offsetOf = [&](int i) { return first + i + 0.5; };
  double strongest = 0;
  for (int i = 1; i + 1 < static_cast<int>(response.size()); ++i) {
    if (std::abs(offsetOf(i)) <= searchPx) strongest = std::max(strongest, response[i]);
  }
  if (strongest < kMinStep) return std::nullopt;
  int best = -1;
  for (int i = 1; i + 1 < static_cast<int>(response.size()); ++i) {
    const double offset = offsetOf(i);
    const bool peak = response[i] >= response[i - 1] && response[i] >= response[i + 1];
    if (std::abs(offset) > searchPx || !peak || response[i] < std::max(kMinStep, relative * strongest)) continue;
    const bool better = inward != 0 ? inward * offset > inward * offsetOf(best) : std::abs(offset) < std::abs(offsetOf(best));
    if (best < 0 || better) best = i;
  }
  if (best < 0) return std::nullopt;
  const double l = response[best - 1], c = response[best], r = response[best + 1];
  const double denom = l - 2 * c + r;
  const double delta = denom < 0 ? std::clamp(0.5 * (l - r) / denom, -0.5, 0.5) : 0.0;
  const double offset = offsetOf(best) + delta;
  return EdgePoint{centre + offset * normal, c};
}

// The line through `q` minimising sum w (l·x)^2 / (a^2 + b^2): lines through q are
// l = E c with E an orthonormal basis of q's orthogonal complement, which turns the
// problem into the smallest generalised eigenvalue of (E^T X E, E^T diag(1,1,0) E).
std::optional<glm::dvec3> fitLineThrough(glm::dvec3 q, const std::vector<EdgePoint>& points,
                                         const std::vector<bool>& use, glm::dvec2 origin) {
  // Work relative to `origin` so the homogeneous coordinates stay well scaled.
  q = glm::dvec3(q.x - origin.x * q.z, q.y - origin.y * q.z, q.z);
  q = glm::normalize(q);
  glm::dvec3 helper = std::abs(q.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 e1 = glm::normalize(glm::cross(q, helper));
  const glm::dvec3 e2 = glm::cross(q, e1);
  double a11 = 0, a12 = 0, a22 = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!use[i]) continue;
    const glm::dvec3 x(points[i].p.x - origin.x, points[i].p.y - origin.y, 1.0);
    const double p1 = glm::dot(e1, x), p2 = glm::dot(e2, x), w = points[i].weight;
    a11 += w * p1 * p1, a12 += w * p1 * p2, a22 += w * p2 * p2;
  }
  const double b11 = e1.x * e1.x + e1.y * e1.y, b12 = e1.x * e2.x + e1.y * e2.y, b22 = e2.x * e2.x + e2.y * e2.y;
  // det(A - λB) = 0: (b11 b22 - b12^2) λ^2 - (a11 b22 + a22 b11 - 2 a12 b12) λ + (a11 a22 - a12^2) = 0.
  const double qa = b11 * b22 - b12 * b12, qb = -(a11 * b22 + a22 * b11 - 2 * a12 * b12), qc = a11 * a22 - a12 * a12;
  double lambda;
  if (std::abs(qa) < 1e-15) {
    if (std::abs(qb) < 1e-15) return std::nullopt;
    lambda = -qc / qb;
  } else {
    const double disc = std::max(0.0, qb * qb - 4 * qa * qc);
    lambda = (-qb - std::sqrt(disc)) / (2 * qa);
  }
  // (A - λB) c = 0: c is perpendicular to the better-conditioned row.
  const double r1x = a11 - lambda * b11, r1y = a12 - lambda * b12;
  const double r2x = a12 - lambda * b12, r2y = a22 - lambda * b22;
  glm::dvec2 c = (std::hypot(r1x, r1y) > std::hypot(r2x, r2y)) ? glm::dvec2(-r1y, r1x) : glm::dvec2(-r2y, r2x);
  if (glm::length(c) == 0) return std::nullopt;
  glm::dvec3 l = c.x * e1 + c.y * e2;
  // Back to image coordinates: l·(x - origin) = l·x - l.xy·origin.
  l.z -= l.x * origin.x + l.y * origin.y;
  const glm::dvec3 n = normalizedLine(l);
  if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z)) return std::nullopt;
  return n;
}

// The edge points the fit starts from. Beside an edge, another may run a pixel or
// three away (a checker floor's next joint beyond the far wall's foot, a band's second
// edge), and where the first is faint the samples split between the two: a least-squares
// line through all of them falls between, on neither. So the points are grouped by the
// line through `search.through` each lies on (within kModeHalfWidthPx). When two or
// more groups, kDistinctEdgesPx apart, each hold kMinModeShare of the points, the fit
// starts from the one farthest towards `search.innerPoint` (`split`); else from all
// the points, as any other fit.
constexpr double kModeHalfWidthPx = 0.5;
constexpr double kMinModeShare = 0.25;
constexpr double kDistinctEdgesPx = 1.5;
constexpr double kSplitLimitPx = 1.0;  // the outlier limit when the points split between edges

std::vector<bool> startingPoints(const std::vector<EdgePoint>& points, const EdgeSearch& search, glm::dvec2 normal,
                                 glm::dvec2 origin, bool& split) {
  split = false;
  // Each point's line through `through`, as its offset along the normal at `origin`.
  const glm::dvec3 q(search.through.x - origin.x * search.through.z, search.through.y - origin.y * search.through.z,
                     search.through.z);
  std::vector<double> offset;
  for (const EdgePoint& e : points) {
    glm::dvec3 l = normalizedLine(glm::cross(q, glm::dvec3(e.p - origin, 1.0)));
    if (!std::isfinite(l.z)) return std::vector<bool>(points.size(), true);
    if (l.x * normal.x + l.y * normal.y < 0) l = -l;
    offset.push_back(-l.z);
  }
  const size_t n = points.size();
  const auto near = [&](double centre, size_t j, double halfWidth) { return std::abs(offset[j] - centre) <= halfWidth; };
  std::vector<bool> taken(n, false);
  std::optional<double> chosen;
  int groups = 0;
  const double inward = glm::dot(*search.innerPoint - origin, normal) >= 0 ? 1.0 : -1.0;
  for (;;) {
    // The densest line among the points not yet grouped.
    size_t best = n, bestCount = 0;
    for (size_t i = 0; i < n; ++i) {
      if (taken[i]) continue;
      size_t count = 0;
      for (size_t j = 0; j < n; ++j) count += !taken[j] && near(offset[i], j, kModeHalfWidthPx);
      if (count > bestCount) best = i, bestCount = count;
    }
    if (best == n || bestCount < kMinModeShare * n) break;
    double sum = 0;
    for (size_t j = 0; j < n; ++j) {
      if (!taken[j] && near(offset[best], j, kModeHalfWidthPx)) sum += offset[j];
    }
    const double centre = sum / bestCount;
    ++groups;
    const bool better = !chosen || inward * centre > inward * *chosen;
    if (better) chosen = centre;
    // Its neighbours within kDistinctEdgesPx are the same edge (a sharp edge's
    // sub-pixel positions cluster by the pixel grid's phase).
    for (size_t j = 0; j < n; ++j) taken[j] = taken[j] || near(centre, j, kDistinctEdgesPx);
  }
  std::vector<bool> use(n, true);
  if (groups < 2) return use;  // one edge (or none a quarter agree on): start from all, as always
  split = true;
  for (size_t j = 0; j < n; ++j) use[j] = near(*chosen, j, kDistinctEdgesPx);
  return use;
}

}  // namespace

double EdgeLine::positionSigmaPx() const { return std::max(0.05, rmsPx / std::sqrt(std::max(1, inliers))); }

std::optional<EdgeLine> fitEdgeLine(const PinholeView& photo, const EdgeSearch& search) {
  const double length = glm::length(search.to - search.from);
  if (length < 2 || photo.empty()) return std::nullopt;
  const glm::dvec2 along = (search.to - search.from) / length;
  const glm::dvec2 normal(-along.y, along.x);
  const int half = std::max(1, static_cast<int>(std::lround(search.stepHalfWidthPx)));
  const int samples = std::clamp(static_cast<int>(length), 2, search.maxSamples);

  std::vector<EdgePoint> points;
  for (int i = 0; i < samples; ++i) {
    const glm::dvec2 centre = search.from + (length * (i + 0.5) / samples) * along;
    if (centre.x < 0 || centre.y < 0 || centre.x > photo.size().width - 1 || centre.y > photo.size().height - 1) continue;
    const double window = search.searchPx + search.searchGrowPx * (i + 0.5) / samples;
    const double inward = search.innerPoint ? (glm::dot(*search.innerPoint - centre, normal) >= 0 ? 1.0 : -1.0) : 0.0;
    if (auto e = findEdge(photo, centre, normal, window, half, search.minRelativeStrength, inward)) points.push_back(*e);
  }
  if (points.size() < 5) return std::nullopt;

  const glm::dvec2 origin = 0.5 * (search.from + search.to);
  // Beside another edge (innerPoint): start from the section's own, and keep the
  // outlier limit below the distance between the two.
  bool split = false;
  std::vector<bool> use(points.size(), true);
  if (search.innerPoint) use = startingPoints(points, search, normal, origin, split);
  std::optional<glm::dvec3> line;
  double rms = 0;
  int inliers = 0, agreeing = 0;
  for (int round = 0; round < 4; ++round) {
    line = fitLineThrough(search.through, points, use, origin);
    if (!line) return std::nullopt;
    std::vector<double> residuals;
    for (size_t i = 0; i < points.size(); ++i) residuals.push_back(std::abs(glm::dot(*line, homogeneous(points[i].p))));
    std::vector<double> sorted = residuals;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double sigma = 1.4826 * sorted[sorted.size() / 2];
    // The usual limit says which samples bear the line out (its coverage); where the
    // points split between edges, the line follows those nearer than kSplitLimitPx.
    const double limit = std::max(2.5 * sigma, 0.35);
    const double follow = split ? std::min(limit, kSplitLimitPx) : limit;
    double sum2 = 0;
    inliers = 0;
    agreeing = 0;
    for (size_t i = 0; i < points.size(); ++i) {
      use[i] = residuals[i] <= follow;
      if (use[i]) sum2 += residuals[i] * residuals[i], ++inliers;
      agreeing += residuals[i] <= limit;
    }
    if (inliers < 5) return std::nullopt;
    rms = std::sqrt(sum2 / inliers);
  }
  line = fitLineThrough(search.through, points, use, origin);
  if (!line) return std::nullopt;
  EdgeLine out;
  out.line = *line;
  out.rmsPx = rms;
  out.inliers = inliers;
  out.coverage = static_cast<double>(agreeing) / samples;
  return out;
}

}  // namespace pw::metrology::detect
