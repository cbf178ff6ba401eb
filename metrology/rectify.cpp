#include "metrology/rectify.h"

#include <algorithm>
#include <cstring>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "metrology/homography.h"

namespace pw::metrology {

namespace {

constexpr int kTilePx = 64;
constexpr int kMaxLevel = 12;
constexpr int kMaxSupersample = 8;
constexpr double kSupersampleAbove = 1.15;  // shrinks up to this alias too little to see
constexpr int kDensitySamples = 25;  // per axis, over the plane, for its best resolution

bool insidePhoto(const glm::dvec2& p, cv::Size size) {
  return p.x >= -0.5 && p.y >= -0.5 && p.x <= size.width - 0.5 && p.y <= size.height - 0.5;
}

// True where the photo shows plane point p: in front of the camera and, through the
// lens's distortion, inside the photo.
bool shows(const cv::Matx33d& h, const glm::dvec2& p, cv::Size size, const Intrinsics& lens) {
  const cv::Vec3d q = h * cv::Vec3d(p.x, p.y, 1.0);
  if (!(q[2] > 0)) return false;
  const glm::dvec2 pinhole(q[0] / q[2], q[1] / q[2]);
  return insideFold(lens, pinhole) && insidePhoto(distortPixel(lens, pinhole), size);
}

// Photo pixels per texture pixel along the texture's x and y axes at p (the lengths
// of the Jacobian's columns).
glm::dvec2 axisShrinkAt(const cv::Matx33d& photoFromTexture, const glm::dvec2& p) {
  const glm::dmat2 j = homographyJacobian(photoFromTexture, p);
  return {glm::length(j[0]), glm::length(j[1])};
}

// The texels of each row the photo shows, [first, last] (first > last: none). Each
// condition (w > 0, -0.5 <= u <= W - 0.5, -0.5 <= v <= H - 0.5) is linear in the
// texel's x along a row once multiplied by w, so each row is one interval.
struct RowSpan {
  int first = 0, last = -1;
  int count() const { return std::max(0, last - first + 1); }
};

// Through a distorting lens the photo's outline is curved on the plane: each row's
// first and last shown texel, found texel by texel (a row is taken as one interval
// between them).
std::vector<RowSpan> shownSpansThroughLens(const cv::Matx33d& m, cv::Size texture, cv::Size photo, const Intrinsics& lens) {
  std::vector<RowSpan> spans(texture.height);
  cv::parallel_for_(cv::Range(0, texture.height), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      int first = 0, last = texture.width - 1;
      while (first <= last && !shows(m, glm::dvec2(first, y), photo, lens)) ++first;
      while (last >= first && !shows(m, glm::dvec2(last, y), photo, lens)) --last;
      spans[y] = {first, last};
    }
  });
  return spans;
}

std::vector<RowSpan> shownSpans(const cv::Matx33d& m, cv::Size texture, cv::Size photo, const Intrinsics& lens) {
  if (!lens.distortion.isNone()) return shownSpansThroughLens(m, texture, photo, lens);
  std::vector<RowSpan> spans(texture.height);
  const double pw = photo.width - 0.5, ph = photo.height - 0.5;
  for (int y = 0; y < texture.height; ++y) {
    // u w = au x + bu, v w = av x + bv, w = aw x + bw.
    const double au = m(0, 0), bu = m(0, 1) * y + m(0, 2);
    const double av = m(1, 0), bv = m(1, 1) * y + m(1, 2);
    const double aw = m(2, 0), bw = m(2, 1) * y + m(2, 2);
    double lo = 0, hi = texture.width - 1;
    const auto atLeastZero = [&](double a, double b, double margin) {  // a x + b >= margin
      if (a > 0) {
        lo = std::max(lo, (margin - b) / a);
      } else if (a < 0) {
        hi = std::min(hi, (margin - b) / a);
      } else if (b < margin) {
        hi = -1;
      }
    };
    const double wScale = std::max({std::abs(aw) * texture.width, std::abs(bw), 1e-300});
    atLeastZero(aw, bw, 1e-12 * wScale);
    atLeastZero(au + 0.5 * aw, bu + 0.5 * bw, 0);
    atLeastZero(pw * aw - au, pw * bw - bu, 0);
    atLeastZero(av + 0.5 * aw, bv + 0.5 * bw, 0);
    atLeastZero(ph * aw - av, ph * bw - bv, 0);
    if (!(lo <= hi)) continue;
    spans[y].first = static_cast<int>(std::ceil(lo - 1e-9));
    spans[y].last = static_cast<int>(std::floor(hi + 1e-9));
  }
  return spans;
}

struct Tile {
  cv::Rect rect;
  int level = 0;
  int supersampleX = 1;
  int supersampleY = 1;
  bool shown = true;  // some texel's source is in the photo
};

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

Status checkPhoto(const cv::Mat& photo) {
  if (photo.empty() || photo.cols < 1 || photo.rows < 1) return makeError("the photo is empty");
  if (photo.depth() != CV_8U || photo.channels() > 4) return makeError("the photo must have 8-bit channels (1 to 4)");
  return {};
}

// The texture's size and resolution: the photo's best where it shows the plane (or
// the one asked for), within the caps.
struct Resolution {
  glm::dvec2 pxPerM{0.0};
  cv::Size size;
};

// (The density is the pinhole's: a lens's distortion changes it by a few percent.)
Result<Resolution> resolutionFor(const cv::Matx33d& metric, double widthM, double heightM, cv::Size photoSize,
                                 const Intrinsics& lens, const RectifyOptions& options) {
  double bestAny = 0;
  glm::dvec2 bestAxes(0.0);
  for (int j = 0; j < kDensitySamples; ++j) {
    for (int i = 0; i < kDensitySamples; ++i) {
      const glm::dvec2 m(widthM * i / (kDensitySamples - 1), heightM * j / (kDensitySamples - 1));
      if (!shows(metric, m, photoSize, lens)) continue;
      const glm::dmat2 jacobian = homographyJacobian(metric, m);
      bestAny = std::max(bestAny, largestStretch(jacobian));
      bestAxes = glm::max(bestAxes, glm::dvec2(glm::length(jacobian[0]), glm::length(jacobian[1])));
    }
  }
  const bool automatic = !(options.pxPerM > 0);
  if (!(bestAny > 0) && (options.outside == OutsidePhoto::kRepeatBorder || (automatic && !(options.minPxPerM > 0)))) {
    return makeError("the plane lies entirely outside the photo");
  }
  const bool square = !automatic || !options.perAxisDensity;
  glm::dvec2 d = !automatic ? glm::dvec2(options.pxPerM) : square ? glm::dvec2(bestAny) : bestAxes;
  if (automatic) d = glm::max(d, glm::dvec2(options.minPxPerM));
  const glm::dvec2 cap(options.maxSidePx / widthM, options.maxSidePx / heightM);
  d = square ? glm::dvec2(std::min({d.x, cap.x, cap.y})) : glm::min(d, cap);
  if (options.maxPixels > 0 && d.x * widthM * d.y * heightM > options.maxPixels) {
    d *= std::sqrt(options.maxPixels / (d.x * widthM * d.y * heightM));
  }
  Resolution r;
  r.pxPerM = d;
  r.size = cv::Size(std::clamp(static_cast<int>(std::lround(widthM * d.x)), 1, options.maxSidePx),
                    std::clamp(static_cast<int>(std::lround(heightM * d.y)), 1, options.maxSidePx));
  // 2^28 texels (768 MiB of BGR) is far beyond any photo's detail; refuse rather
  // than fail to allocate.
  if (static_cast<double>(r.size.width) * r.size.height > static_cast<double>(1 << 28)) {
    return makeError("the texture would be " + std::to_string(r.size.width) + "x" + std::to_string(r.size.height) +
                     " px; lower the px per metre or the size cap");
  }
  return r;
}

// Plans one tile: the pyramid level and supersampling from the local shrink where the
// photo shows the tile (elsewhere the photo has nothing to filter).
Tile planTile(const cv::Rect& rect, const cv::Matx33d& photoFromTexture, const std::vector<RowSpan>& spans,
              cv::Size photoSize, const Intrinsics& lens, int deepest, double& maxShrink) {
  Tile t;
  t.rect = rect;
  const int x1 = rect.x + rect.width - 1, y1 = rect.y + rect.height - 1;
  t.shown = false;
  std::vector<glm::dvec2> points;
  for (int y : {rect.y, rect.y + rect.height / 2, y1}) {
    const int first = std::max(spans[y].first, rect.x), last = std::min(spans[y].last, x1);
    if (first <= last) points.insert(points.end(), {glm::dvec2(first, y), glm::dvec2(last, y), glm::dvec2(0.5 * (first + last), y)});
  }
  for (int y = rect.y; y <= y1 && !t.shown; ++y) t.shown = std::max(spans[y].first, rect.x) <= std::min(spans[y].last, x1);
  const double xa = rect.x - 0.5, ya = rect.y - 0.5, xb = xa + rect.width, yb = ya + rect.height;
  for (const glm::dvec2& p : {glm::dvec2(xa, ya), glm::dvec2(xb, ya), glm::dvec2(xa, yb), glm::dvec2(xb, yb),
                              glm::dvec2(0.5 * (xa + xb), 0.5 * (ya + yb))}) {
    if (shows(photoFromTexture, p, photoSize, lens)) points.push_back(p);
  }
  double shrink = 0;
  glm::dvec2 axes(0.0);
  for (const glm::dvec2& p : points) {
    shrink = std::max(shrink, largestStretch(homographyJacobian(photoFromTexture, p)));
    axes = glm::max(axes, axisShrinkAt(photoFromTexture, p));
  }
  maxShrink = std::max(maxShrink, shrink);
  // Anisotropic filtering along the texture's axes (a receding plane shrinks far
  // more along its length than across it): the pyramid level follows the lesser
  // shrink, so it blurs no axis more than that axis needs; what remains on each
  // axis is averaged from that many supersamples.
  const double lesser = std::min(axes.x, axes.y);
  t.level = lesser >= 2 ? std::min(deepest, static_cast<int>(std::floor(std::log2(lesser)))) : 0;
  const glm::dvec2 rest = axes / std::ldexp(1.0, t.level);
  auto samples = [](double r) { return r > kSupersampleAbove ? std::clamp(static_cast<int>(std::ceil(r)), 2, kMaxSupersample) : 1; };
  t.supersampleX = samples(rest.x);
  t.supersampleY = samples(rest.y);
  return t;
}

// Mean of the shown texels; with `fill`, the others set to it (rounded).
cv::Scalar fillOutside(cv::Mat& image, const std::vector<RowSpan>& spans, bool fill) {
  const int channels = image.channels();
  std::vector<double> sums(static_cast<size_t>(image.rows) * channels, 0.0);
  long count = 0;
  for (const RowSpan& s : spans) count += s.count();
  cv::parallel_for_(cv::Range(0, image.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const uint8_t* row = image.ptr<uint8_t>(y);
      for (int x = spans[y].first; x <= spans[y].last; ++x) {
        for (int c = 0; c < channels; ++c) sums[static_cast<size_t>(y) * channels + c] += row[x * channels + c];
      }
    }
  });
  cv::Scalar mean = cv::Scalar::all(128);
  if (count > 0) {
    for (int c = 0; c < channels; ++c) {
      double sum = 0;
      for (int y = 0; y < image.rows; ++y) sum += sums[static_cast<size_t>(y) * channels + c];
      mean[c] = sum / count;
    }
  }
  if (fill && count < static_cast<long>(image.rows) * image.cols) {
    uint8_t pixel[4];
    for (int c = 0; c < channels; ++c) pixel[c] = cv::saturate_cast<uint8_t>(mean[c]);
    cv::parallel_for_(cv::Range(0, image.rows), [&](const cv::Range& rows) {
      for (int y = rows.start; y < rows.end; ++y) {
        uint8_t* row = image.ptr<uint8_t>(y);
        const int first = spans[y].count() > 0 ? spans[y].first : image.cols;
        const int last = spans[y].count() > 0 ? spans[y].last : image.cols - 1;
        for (int x = 0; x < image.cols; ++x) {
          if (x == first) x = last + 1;
          if (x >= image.cols) break;
          std::memcpy(row + x * channels, pixel, channels);
        }
      }
    });
  }
  return mean;
}

// Samples `source` (a pyramid level, `levelFromPhoto` from photo pixels) at
// levelFromPhoto(distort(pinholeFromTarget · (x, y, 1))) for each target pixel.
void remapThroughLens(const cv::Mat& source, cv::Mat& target, cv::Size size, const cv::Matx33d& pinholeFromTarget,
                      const cv::Matx33d& levelFromPhoto, const Intrinsics& lens, int interpolation) {
  cv::Mat mapX(size, CV_32FC1), mapY(size, CV_32FC1);
  for (int y = 0; y < size.height; ++y) {
    float* mx = mapX.ptr<float>(y);
    float* my = mapY.ptr<float>(y);
    for (int x = 0; x < size.width; ++x) {
      const cv::Vec3d q = pinholeFromTarget * cv::Vec3d(x, y, 1.0);
      // Behind the camera or beyond the lens's fold: outside the photo (such texels are
      // not shown, and filled).
      const glm::dvec2 pinhole = q[2] > 0 ? glm::dvec2(q[0] / q[2], q[1] / q[2]) : glm::dvec2(0.0);
      const glm::dvec2 d = q[2] > 0 && insideFold(lens, pinhole) ? distortPixel(lens, pinhole) : glm::dvec2(-1e6);
      const cv::Vec3d l = levelFromPhoto * cv::Vec3d(d.x, d.y, 1.0);
      mx[x] = static_cast<float>(l[0]);
      my[x] = static_cast<float>(l[1]);
    }
  }
  cv::remap(source, target, mapX, mapY, interpolation, cv::BORDER_REPLICATE);
}

}  // namespace

PhotoPyramid::PhotoPyramid(const cv::Mat& photo, const Intrinsics& lens) : lens_(lens) { levels_.push_back(photo); }

int PhotoPyramid::deepest() const {
  int level = 0;
  for (cv::Size s = levels_[0].size(); level < kMaxLevel && std::min(s.width, s.height) >= 4; ++level) {
    s = cv::Size((s.width + 1) / 2, (s.height + 1) / 2);
  }
  return level;
}

const cv::Mat& PhotoPyramid::level(int i) {
  while (static_cast<int>(levels_.size()) <= i) {
    cv::Mat next;
    cv::pyrDown(levels_.back(), next);
    levels_.push_back(next);
  }
  return levels_[i];
}

Result<RectifiedPlane> rectifyPlane(PhotoPyramid& pyramid, const cv::Matx33d& metric, double widthM, double heightM,
                                    const RectifyOptions& options) {
  PW_TRY(checkPhoto(pyramid.photo()));
  if (!(widthM > 0) || !(heightM > 0) || !std::isfinite(widthM) || !std::isfinite(heightM)) {
    return makeError("the plane's true width and height must be positive");
  }
  if (!(options.pxPerM >= 0) || !std::isfinite(options.pxPerM)) return makeError("px per metre must be a number >= 0");
  if (!(options.minPxPerM >= 0) || !std::isfinite(options.minPxPerM)) return makeError("the least px per metre must be >= 0");
  if (options.maxSidePx < 1 || options.maxSidePx > 32768) return makeError("the texture size cap must be 1..32768 px");
  if (!(options.maxPixels >= 0)) return makeError("the texel cap must be >= 0");
  for (int i = 0; i < 9; ++i) {
    if (!std::isfinite(metric.val[i])) return makeError("the plane's homography is not finite");
  }
  const cv::Size photoSize = pyramid.photo().size();
  const Intrinsics& lens = pyramid.lens();
  auto resolution = resolutionFor(metric, widthM, heightM, photoSize, lens, options);
  if (!resolution) return resolution.error();
  const int widthPx = resolution->size.width, heightPx = resolution->size.height;

  RectifiedPlane out;
  out.widthM = widthM;
  out.heightM = heightM;
  out.pxPerMAxes = resolution->pxPerM;
  out.pxPerM = std::min(out.pxPerMAxes.x, out.pxPerMAxes.y);
  // Texture pixel centre (i, j) sits at ((i + 0.5) W / widthPx, (j + 0.5) H / heightPx) metres.
  const double sx = widthM / widthPx, sy = heightM / heightPx;
  out.photoFromTexture = metric * cv::Matx33d(sx, 0, 0.5 * sx, 0, sy, 0.5 * sy, 0, 0, 1);
  const std::vector<RowSpan> spans = shownSpans(out.photoFromTexture, resolution->size, photoSize, lens);
  long shownTexels = 0;
  for (const RowSpan& s : spans) shownTexels += s.count();
  out.coverage = static_cast<double>(shownTexels) / (static_cast<double>(widthPx) * heightPx);

  // Plan the tiles; grow the pyramid as deep as they need before sampling in parallel.
  std::vector<Tile> tiles;
  const int deepest = pyramid.deepest();
  int levelNeeded = 0;
  for (int y0 = 0; y0 < heightPx; y0 += kTilePx) {
    for (int x0 = 0; x0 < widthPx; x0 += kTilePx) {
      const cv::Rect rect(x0, y0, std::min(kTilePx, widthPx - x0), std::min(kTilePx, heightPx - y0));
      Tile t = planTile(rect, out.photoFromTexture, spans, photoSize, lens, deepest, out.maxShrink);
      if (!t.shown && options.outside == OutsidePhoto::kMeanColor) continue;  // filled below
      levelNeeded = std::max(levelNeeded, t.level);
      tiles.push_back(t);
    }
  }
  std::vector<cv::Mat> levels;  // shallow copies: the pyramid does not change while tiles read it
  for (int level = 0; level <= levelNeeded; ++level) levels.push_back(pyramid.level(level));

  const cv::Mat& photo = pyramid.photo();
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
      const cv::Mat& source = levels[t.level];
      cv::Mat target = out.image(t.rect);
      if (!lens.distortion.isNone()) {
        // The photo coordinate goes through the lens before it is sampled.
        const cv::Matx33d pinholeFromFine = out.photoFromTexture * textureFromFine;
        if (kx == 1 && ky == 1) {
          remapThroughLens(source, target, t.rect.size(), pinholeFromFine, levelFromPhoto, lens, cv::INTER_CUBIC);
        } else {
          remapThroughLens(source, fine, cv::Size(t.rect.width * kx, t.rect.height * ky), pinholeFromFine, levelFromPhoto,
                           lens, cv::INTER_LINEAR);
          cv::resize(fine, target, t.rect.size(), 0, 0, cv::INTER_AREA);
        }
      } else if (kx == 1 && ky == 1) {
        cv::warpPerspective(source, target, cv::Mat(levelFromFine), t.rect.size(), cv::INTER_CUBIC | cv::WARP_INVERSE_MAP,
                            cv::BORDER_REPLICATE);
      } else {
        // Bilinear: the supersamples are averaged, and that average is the filter here.
        cv::warpPerspective(source, fine, cv::Mat(levelFromFine), cv::Size(t.rect.width * kx, t.rect.height * ky),
                            cv::INTER_LINEAR | cv::WARP_INVERSE_MAP, cv::BORDER_REPLICATE);
        cv::resize(fine, target, t.rect.size(), 0, 0, cv::INTER_AREA);
      }
    }
  });
  out.meanColor = fillOutside(out.image, spans, options.outside == OutsidePhoto::kMeanColor);
  return out;
}

Result<RectifiedPlane> rectifyPlane(const cv::Mat& photo, const std::array<glm::dvec2, 4>& quadPx, double widthM,
                                    double heightM, const RectifyOptions& options) {
  PW_TRY(checkPhoto(photo));
  if (!(widthM > 0) || !(heightM > 0) || !std::isfinite(widthM) || !std::isfinite(heightM)) {
    return makeError("the plane's true width and height must be positive");
  }
  PW_TRY(checkQuad(quadPx));
  // Metric plane coordinates (x right, y down, metres, origin at TL) to photo pixels.
  auto metric = homographyFromCorners({glm::dvec2(0, 0), glm::dvec2(widthM, 0), glm::dvec2(widthM, heightM),
                                       glm::dvec2(0, heightM)},
                                      quadPx);
  if (!metric) return metric.error();
  // The corners are in front of the camera: w > 0 there (H is known up to its sign).
  const cv::Vec3d centre = *metric * cv::Vec3d(0.5 * widthM, 0.5 * heightM, 1.0);
  const cv::Matx33d inFront = centre[2] < 0 ? cv::Matx33d(*metric * -1.0) : *metric;
  PhotoPyramid pyramid(photo);
  return rectifyPlane(pyramid, inFront, widthM, heightM, options);
}

cv::Matx33d photoFromPlane(const Intrinsics& camera, const CameraPose& pose, const glm::dvec3& origin,
                           const glm::dvec3& xAxis, const glm::dvec3& yAxis) {
  const glm::dmat3 cameraFromWorld = glm::transpose(pose.worldFromCamera);
  const glm::dvec3 xc = cameraFromWorld * xAxis, yc = cameraFromWorld * yAxis;
  const glm::dvec3 oc = cameraFromWorld * (origin - pose.positionM);
  const double f = camera.focalPx, cu = camera.principalPointPx.x, cv = camera.principalPointPx.y;
  // The camera looks along -Z and v grows downwards: u w = f x - cu z, v w = -f y - cv z,
  // w = -z (projectToPixel).
  const cv::Matx33d k(f, 0, -cu, 0, -f, -cv, 0, 0, -1);
  const cv::Matx33d columns(xc.x, yc.x, oc.x, xc.y, yc.y, oc.y, xc.z, yc.z, oc.z);
  return k * columns;
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
  PhotoPyramid pyramid(photo, measurement.camera);
  std::array<RectifiedPlane, kPlaneCount> out;
  for (int p = 0; p < kPlaneCount; ++p) {
    const Plane plane = static_cast<Plane>(p);
    const std::array<glm::dvec3, 4> c = planeCornersM(plane, measurement.size);
    const cv::Matx33d h = photoFromPlane(measurement.camera, measurement.pose, c[0], glm::normalize(c[1] - c[0]),
                                         glm::normalize(c[3] - c[0]));
    const glm::dvec2 size = planeSizeM(plane, measurement.size);
    auto rectified = rectifyPlane(pyramid, h, size.x, size.y, options);
    if (!rectified) return makeError(std::string(planeName(plane)) + ": " + rectified.message());
    out[p] = std::move(*rectified);
  }
  return out;
}

}  // namespace pw::metrology
