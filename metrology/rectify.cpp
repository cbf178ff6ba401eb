#include "metrology/rectify.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "metrology/homography.h"

namespace pw::metrology {

namespace {

constexpr int kTilePx = 64;
constexpr int kMaxLevel = 12;

// The photo and its Gaussian pyramid, grown on demand (before any parallel use).
class Pyramid {
 public:
  explicit Pyramid(const cv::Mat& photo) { levels_.push_back(photo); }
  int deepest() const {
    int level = 0;
    for (cv::Size s = levels_[0].size(); level < kMaxLevel && std::min(s.width, s.height) >= 4; ++level) {
      s = cv::Size((s.width + 1) / 2, (s.height + 1) / 2);
    }
    return level;
  }
  void ensure(int level) {
    while (static_cast<int>(levels_.size()) <= level) {
      cv::Mat next;
      cv::pyrDown(levels_.back(), next);
      levels_.push_back(next);
    }
  }
  const cv::Mat& level(int i) const { return levels_[i]; }
  cv::Size size() const { return levels_[0].size(); }

 private:
  std::vector<cv::Mat> levels_;
};

cv::Matx33d mul(const cv::Matx33d& a, const cv::Matx33d& b) { return a * b; }

// Photo pixels per texture pixel at texture point p.
double shrinkAt(const cv::Matx33d& photoFromTexture, const glm::dvec2& p) {
  return largestStretch(homographyJacobian(photoFromTexture, p));
}

// Photo pixels per texture pixel along the texture's x and y axes at p (the lengths
// of the Jacobian's columns).
glm::dvec2 axisShrinkAt(const cv::Matx33d& photoFromTexture, const glm::dvec2& p) {
  const glm::dmat2 j = homographyJacobian(photoFromTexture, p);
  return {glm::length(j[0]), glm::length(j[1])};
}

struct Tile {
  cv::Rect rect;
  int level = 0;
  int supersampleX = 1;
  int supersampleY = 1;
};

constexpr int kMaxSupersample = 8;

bool insidePhoto(const glm::dvec2& p, cv::Size size) {
  return p.x >= -0.5 && p.y >= -0.5 && p.x <= size.width - 0.5 && p.y <= size.height - 0.5;
}

Status checkQuad(const std::array<glm::dvec2, 4>& q) {
  int positive = 0, negative = 0;
  for (int i = 0; i < 4; ++i) {
    const glm::dvec2 e1 = q[(i + 1) % 4] - q[i], e2 = q[(i + 2) % 4] - q[(i + 1) % 4];
    const double l1 = glm::length(e1), l2 = glm::length(e2);
    if (!std::isfinite(l1) || !std::isfinite(l2)) return makeError("a corner of the plane is not finite");
    if (l1 < 0.5) return makeError("two corners of the plane coincide");
    const double sine = (e1.x * e2.y - e1.y * e2.x) / (l1 * l2);
    if (std::abs(sine) < 1e-3) return makeError("three corners of the plane are collinear");
    (sine > 0 ? positive : negative)++;
  }
  if (positive != 4 && negative != 4) return makeError("the plane's corners cross or do not form a convex quad");
  return {};
}

Result<RectifiedPlane> rectifyWith(Pyramid& pyramid, const std::array<glm::dvec2, 4>& quadPx, double widthM,
                                   double heightM, const RectifyOptions& options) {
  if (!(widthM > 0) || !(heightM > 0) || !std::isfinite(widthM) || !std::isfinite(heightM)) {
    return makeError("the plane's true width and height must be positive");
  }
  if (!(options.pxPerM >= 0) || !std::isfinite(options.pxPerM)) return makeError("px per metre must be a number >= 0");
  if (options.maxSidePx < 1 || options.maxSidePx > 32768) return makeError("the texture size cap must be 1..32768 px");
  PW_TRY(checkQuad(quadPx));
  const cv::Size photoSize = pyramid.size();

  // Metric plane coordinates (x right, y down, metres, origin at TL) to photo pixels.
  auto metric = homographyFromCorners({glm::dvec2(0, 0), glm::dvec2(widthM, 0), glm::dvec2(widthM, heightM),
                                       glm::dvec2(0, heightM)},
                                      quadPx);
  if (!metric) return metric.error();

  // The photo's own best resolution: the most photo pixels per metre anywhere on
  // the part of the plane the photo shows.
  constexpr int kSamples = 17;
  double best = 0;
  for (int j = 0; j < kSamples; ++j) {
    for (int i = 0; i < kSamples; ++i) {
      const glm::dvec2 m(widthM * i / (kSamples - 1), heightM * j / (kSamples - 1));
      if (!insidePhoto(applyHomography(*metric, m), photoSize)) continue;
      best = std::max(best, largestStretch(homographyJacobian(*metric, m)));
    }
  }
  if (!(best > 0)) return makeError("the plane lies entirely outside the photo");
  double pxPerM = options.pxPerM > 0 ? options.pxPerM : best;
  pxPerM = std::min(pxPerM, options.maxSidePx / std::max(widthM, heightM));
  const int widthPx = std::clamp(static_cast<int>(std::lround(widthM * pxPerM)), 1, options.maxSidePx);
  const int heightPx = std::clamp(static_cast<int>(std::lround(heightM * pxPerM)), 1, options.maxSidePx);

  // 2^28 texels (768 MiB of BGR) is far beyond any photo's detail; refuse rather
  // than fail to allocate.
  if (static_cast<double>(widthPx) * heightPx > static_cast<double>(1 << 28)) {
    return makeError("the texture would be " + std::to_string(widthPx) + "x" + std::to_string(heightPx) +
                     " px; lower the px per metre or the size cap");
  }
  RectifiedPlane out;
  out.widthM = widthM;
  out.heightM = heightM;
  out.pxPerM = pxPerM;
  // Texture pixel centre (i, j) sits at ((i + 0.5) W / widthPx, (j + 0.5) H / heightPx) metres.
  const double sx = widthM / widthPx, sy = heightM / heightPx;
  out.photoFromTexture = mul(*metric, cv::Matx33d(sx, 0, 0.5 * sx, 0, sy, 0.5 * sy, 0, 0, 1));

  // Plan the tiles: pyramid level and supersampling from the local shrink.
  std::vector<Tile> tiles;
  const int deepest = pyramid.deepest();
  int levelNeeded = 0;
  for (int y0 = 0; y0 < heightPx; y0 += kTilePx) {
    for (int x0 = 0; x0 < widthPx; x0 += kTilePx) {
      Tile t;
      t.rect = cv::Rect(x0, y0, std::min(kTilePx, widthPx - x0), std::min(kTilePx, heightPx - y0));
      const double xa = x0 - 0.5, ya = y0 - 0.5, xb = xa + t.rect.width, yb = ya + t.rect.height;
      double shrink = 0;
      glm::dvec2 axes(0.0);
      for (const glm::dvec2& p : {glm::dvec2(xa, ya), glm::dvec2(xb, ya), glm::dvec2(xa, yb), glm::dvec2(xb, yb),
                                  glm::dvec2(0.5 * (xa + xb), 0.5 * (ya + yb))}) {
        shrink = std::max(shrink, shrinkAt(out.photoFromTexture, p));
        axes = glm::max(axes, axisShrinkAt(out.photoFromTexture, p));
      }
      out.maxShrink = std::max(out.maxShrink, shrink);
      // Anisotropic filtering along the texture's axes (a receding plane shrinks far
      // more along its length than across it): the pyramid level follows the lesser
      // shrink, so it blurs no axis more than that axis needs; what remains on each
      // axis is averaged from that many bilinear supersamples.
      const double lesser = std::min(axes.x, axes.y);
      t.level = lesser >= 2 ? std::min(deepest, static_cast<int>(std::floor(std::log2(lesser)))) : 0;
      const glm::dvec2 rest = axes / std::ldexp(1.0, t.level);
      auto samples = [](double r) { return r > 1.05 ? std::clamp(static_cast<int>(std::ceil(r)), 2, kMaxSupersample) : 1; };
      t.supersampleX = samples(rest.x);
      t.supersampleY = samples(rest.y);
      levelNeeded = std::max(levelNeeded, t.level);
      tiles.push_back(t);
    }
  }
  pyramid.ensure(levelNeeded);

  const cv::Mat& photo = pyramid.level(0);
  out.image.create(heightPx, widthPx, photo.type());
  cv::parallel_for_(cv::Range(0, static_cast<int>(tiles.size())), [&](const cv::Range& range) {
    cv::Mat fine;
    for (int n = range.start; n < range.end; ++n) {
      const Tile& t = tiles[n];
      const int kx = t.supersampleX, ky = t.supersampleY;
      // Supersample (a, b) -> texture (x0 - 0.5 + (a + 0.5)/kx, ...) -> photo -> level
      // pixel ((p + 0.5) / 2^l - 0.5).
      const cv::Matx33d textureFromFine(1.0 / kx, 0, t.rect.x - 0.5 + 0.5 / kx, 0, 1.0 / ky, t.rect.y - 0.5 + 0.5 / ky, 0,
                                        0, 1);
      const double ls = std::ldexp(1.0, -t.level);
      const cv::Matx33d levelFromPhoto(ls, 0, 0.5 * ls - 0.5, 0, ls, 0.5 * ls - 0.5, 0, 0, 1);
      const cv::Matx33d levelFromFine = levelFromPhoto * out.photoFromTexture * textureFromFine;
      cv::Mat target = out.image(t.rect);
      if (kx == 1 && ky == 1) {
        cv::warpPerspective(pyramid.level(t.level), target, cv::Mat(levelFromFine), t.rect.size(),
                            cv::INTER_LINEAR | cv::WARP_INVERSE_MAP, cv::BORDER_REPLICATE);
      } else {
        cv::warpPerspective(pyramid.level(t.level), fine, cv::Mat(levelFromFine),
                            cv::Size(t.rect.width * kx, t.rect.height * ky), cv::INTER_LINEAR | cv::WARP_INVERSE_MAP,
                            cv::BORDER_REPLICATE);
        cv::resize(fine, target, t.rect.size(), 0, 0, cv::INTER_AREA);
      }
    }
  });

  // Coverage on a coarse grid of texture pixel centres.
  constexpr int kGrid = 64;
  int inside = 0;
  for (int j = 0; j < kGrid; ++j) {
    for (int i = 0; i < kGrid; ++i) {
      const glm::dvec2 t((i + 0.5) * widthPx / kGrid - 0.5, (j + 0.5) * heightPx / kGrid - 0.5);
      inside += insidePhoto(applyHomography(out.photoFromTexture, t), photoSize) ? 1 : 0;
    }
  }
  out.coverage = static_cast<double>(inside) / (kGrid * kGrid);
  return out;
}

Status checkPhoto(const cv::Mat& photo) {
  if (photo.empty() || photo.cols < 1 || photo.rows < 1) return makeError("the photo is empty");
  if (photo.depth() != CV_8U || photo.channels() > 4) return makeError("the photo must have 8-bit channels (1 to 4)");
  return {};
}

}  // namespace

Result<RectifiedPlane> rectifyPlane(const cv::Mat& photo, const std::array<glm::dvec2, 4>& quadPx, double widthM,
                                    double heightM, const RectifyOptions& options) {
  PW_TRY(checkPhoto(photo));
  Pyramid pyramid(photo);
  return rectifyWith(pyramid, quadPx, widthM, heightM, options);
}

glm::dvec2 planeSizeM(Plane plane, const Dimensions& d) {
  switch (plane) {
    case Plane::kFarWall: return {d.widthM, d.heightM};
    case Plane::kLeftWall:
    case Plane::kRightWall: return {d.lengthM, d.heightM};
    case Plane::kFloor:
    case Plane::kCeiling: return {d.widthM, d.lengthM};
  }
  return {0, 0};
}

std::array<glm::dvec3, 4> planeCornersM(Plane plane, const Dimensions& d) {
  const auto corners = corridorCorners(d.widthM, d.heightM, d.lengthM);
  const auto& q = kPlaneCorners[static_cast<int>(plane)];
  return {corners[q[0]], corners[q[1]], corners[q[2]], corners[q[3]]};
}

Result<std::array<RectifiedPlane, kPlaneCount>> rectifyCorridor(const cv::Mat& photo, const Measurement& measurement,
                                                                const RectifyOptions& options) {
  PW_TRY(checkPhoto(photo));
  Pyramid pyramid(photo);
  std::array<RectifiedPlane, kPlaneCount> out;
  for (int p = 0; p < kPlaneCount; ++p) {
    const Plane plane = static_cast<Plane>(p);
    const auto& q = kPlaneCorners[p];
    const std::array<glm::dvec2, 4> quad{measurement.reprojectedPx[q[0]], measurement.reprojectedPx[q[1]],
                                         measurement.reprojectedPx[q[2]], measurement.reprojectedPx[q[3]]};
    const glm::dvec2 size = planeSizeM(plane, measurement.size);
    auto rectified = rectifyWith(pyramid, quad, size.x, size.y, options);
    if (!rectified) return makeError(std::string(planeName(plane)) + ": " + rectified.message());
    out[p] = std::move(*rectified);
  }
  return out;
}

}  // namespace pw::metrology
