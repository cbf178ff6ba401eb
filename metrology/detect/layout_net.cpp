#include "metrology/detect/layout_net.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <vector>

#include <opencv2/dnn.hpp>
#include <opencv2/imgproc.hpp>

// The networks' ONNX files, built into the program (layout_model.cpp).
extern "C" const char pw_layout_net_onnx_begin[];
extern "C" const char pw_layout_net_onnx_end[];
extern "C" const char pw_layout_zoom_net_onnx_begin[];
extern "C" const char pw_layout_zoom_net_onnx_end[];

namespace pw::metrology::detect {
namespace {

constexpr int kInputSide = 192;  // the network's input: the photo's long side, zero-padded square
constexpr int kLabels = 5;       // far wall, left wall, right wall, floor, ceiling
enum Label : int { kFar = 0, kLeft, kRight, kFloor, kCeiling };

// The view around the far wall: the far wall's extent over its side (the crops the
// zoomed network was trained on: 0.25-0.6), and its least side in the photo's pixels.
constexpr double kNeighbourhoodShare = 0.4;
constexpr double kMinNeighbourhoodPx = 24;

// The networks, one each for the process; cv::dnn::Net::forward is not reentrant.
std::mutex netMutex;

cv::dnn::Net& wholeNet() {
  static cv::dnn::Net net = cv::dnn::readNetFromONNX(pw_layout_net_onnx_begin,
                                                     static_cast<size_t>(pw_layout_net_onnx_end - pw_layout_net_onnx_begin));
  return net;
}

cv::dnn::Net& zoomNet() {
  static cv::dnn::Net net = cv::dnn::readNetFromONNX(
      pw_layout_zoom_net_onnx_begin, static_cast<size_t>(pw_layout_zoom_net_onnx_end - pw_layout_zoom_net_onnx_begin));
  return net;
}

// A ray's coordinates in the corridor's frame (dx across, dy up, dz along).
struct Ray {
  float dx, dy, dz;
};

// The surface a ray meets first, from when it meets the far plane, the side wall it
// heads for (the left one where `toLeft`) and the floor or ceiling it heads for.
int firstSurface(double tFar, double tSide, double tFloorCeiling, bool toLeft, bool toFloor) {
  if (tFar <= tSide && tFar <= tFloorCeiling) return kFar;
  if (tSide <= tFloorCeiling) return toLeft ? kLeft : kRight;
  return toFloor ? kFloor : kCeiling;
}

// Which surface of the box (left, right, bottom, top on the far plane z = 1) a ray
// meets first.
int labelOf(const Ray& r, double left, double right, double bottom, double top) {
  constexpr double kNever = 1e30;
  const double tFar = r.dz > 1e-9 ? 1.0 / r.dz : kNever;
  const double tSide = r.dx < -1e-12 ? left / r.dx : r.dx > 1e-12 ? right / r.dx : kNever;
  const double tFloorCeiling = r.dy < -1e-12 ? bottom / r.dy : r.dy > 1e-12 ? top / r.dy : kNever;
  return firstSurface(tFar, tSide, tFloorCeiling, r.dx < 0, r.dy < 0);
}

float squash(double x) { return static_cast<float>(std::atan(2.0 * x) / (0.5 * CV_PI)); }

double percentile(std::vector<double> v, double q) {
  const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(v.size() - 1) + 0.5);
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[static_cast<size_t>(k)];
}

}  // namespace

namespace {

// What one network sees: a 192 x 192 view of the working image (x0, y0 its top-left
// corner in working pixels, `zoom` input pixels per working pixel; beyond the image,
// black), each input pixel's ray, and the log-probability of each label there.
struct View {
  std::vector<Ray> rays;                          // per input pixel inside the image
  std::vector<std::array<float, kLabels>> logp;   // the same pixels
  std::vector<double> farU, farV;                 // where the network's likeliest label is the far wall
};

// The ray through a full-resolution pixel in the corridor's frame: its components across
// the corridor, up and along it (the network's coordinates; the far plane's where divided
// by the last).
glm::dvec3 corridorRay(glm::dvec2 fullPx, double focalPx, glm::dvec2 principalPx, const CorridorAxes& axes) {
  const glm::dvec3 d((fullPx.x - principalPx.x) / focalPx, (fullPx.y - principalPx.y) / focalPx, 1.0);
  return {glm::dot(d, axes.right), glm::dot(d, axes.up), glm::dot(d, axes.away)};
}

}  // namespace

struct LayoutLooks {
  View whole, zoomed;
};

namespace {

View look(cv::dnn::Net& net, const cv::Mat& bgr, double workScale, double x0, double y0, double zoom, double focalPx,
          glm::dvec2 principalPx, const CorridorAxes& axes) {
  // The view's colours: area-averaged where it shrinks, bilinear where it enlarges.
  cv::Mat patch;
  if (zoom < 1) {
    cv::Mat small;
    cv::resize(bgr, small, cv::Size(), zoom, zoom, cv::INTER_AREA);
    const cv::Matx23d shift(1, 0, -zoom * x0, 0, 1, -zoom * y0);
    cv::warpAffine(small, patch, shift, cv::Size(kInputSide, kInputSide), cv::INTER_LINEAR, cv::BORDER_CONSTANT);
  } else {
    const cv::Matx23d map(zoom, 0, -zoom * x0 + 0.5 * zoom - 0.5, 0, zoom, -zoom * y0 + 0.5 * zoom - 0.5);
    cv::warpAffine(bgr, patch, map, cv::Size(kInputSide, kInputSide), cv::INTER_LINEAR, cv::BORDER_CONSTANT);
  }
  // Input: blue, green, red in 0..1, then the ray's far-plane coordinates squashed.
  const int dims[] = {1, 5, kInputSide, kInputSide};
  cv::Mat blob(4, dims, CV_32F, cv::Scalar(0));
  std::vector<int> pixelOf;  // input pixel index per ray
  View view;
  for (int y = 0; y < kInputSide; ++y) {
    for (int x = 0; x < kInputSide; ++x) {
      const glm::dvec2 working = glm::dvec2(x0, y0) + (glm::dvec2(x, y) + 0.5) / zoom - 0.5;
      if (!(working.x >= -0.5 && working.y >= -0.5 && working.x <= bgr.cols - 0.5 && working.y <= bgr.rows - 0.5)) continue;
      const glm::dvec3 along = corridorRay((working + 0.5) / workScale - 0.5, focalPx, principalPx, axes);
      const Ray r{static_cast<float>(along.x), static_cast<float>(along.y), static_cast<float>(along.z)};
      view.rays.push_back(r);
      pixelOf.push_back(y * kInputSide + x);
      const cv::Vec3b c = patch.at<cv::Vec3b>(y, x);
      for (int ch = 0; ch < 3; ++ch) blob.ptr<float>(0, ch, y)[x] = c[ch] / 255.0f;
      const double dz = std::abs(r.dz) > 1e-6 ? r.dz : 1e-6;
      blob.ptr<float>(0, 3, y)[x] = squash(r.dx / dz);
      blob.ptr<float>(0, 4, y)[x] = squash(r.dy / dz);
    }
  }
  cv::Mat logits;
  {
    const std::lock_guard lock(netMutex);
    net.setInput(blob);
    logits = net.forward().clone();  // 1 x 5 x 96 x 96
  }
  // Per label, up to the input's size (bilinear, as the network was trained), then the
  // log-probabilities over the view's pixels in the image.
  const int outSide = logits.size[2];
  std::vector<cv::Mat> planes(kLabels);
  for (int k = 0; k < kLabels; ++k) {
    const cv::Mat plane(outSide, outSide, CV_32F, logits.ptr<float>(0, k));
    cv::resize(plane, planes[k], cv::Size(kInputSide, kInputSide), 0, 0, cv::INTER_LINEAR);
  }
  view.logp.resize(view.rays.size());
  for (size_t i = 0; i < view.rays.size(); ++i) {
    std::array<float, kLabels>& p = view.logp[i];
    float most = -1e30f;
    for (int k = 0; k < kLabels; ++k) most = std::max(most, p[k] = planes[k].ptr<float>()[pixelOf[i]]);
    double sum = 0;
    for (int k = 0; k < kLabels; ++k) sum += std::exp(p[k] - most);
    const float norm = most + static_cast<float>(std::log(sum));
    int best = 0;
    for (int k = 0; k < kLabels; ++k) {
      p[k] -= norm;
      if (p[k] > p[best]) best = k;
    }
    const Ray& r = view.rays[i];
    if (best == kFar && r.dz > 1e-6) view.farU.push_back(r.dx / r.dz), view.farV.push_back(r.dy / r.dz);
  }
  return view;
}

// labelOf for box after box (fitBox labels the view's every ray for each of a few
// hundred boxes): a ray going away from the camera meets a plane at the time labelOf
// finds times dz, the far plane at 1, the side walls' at left or right times dz / dx,
// the floor's and ceiling's at bottom or top times dz / dy; the ratios are worked out
// once, and a box costs no division. (A ray that does not go away: labelOf itself.)
class BoxLabeller {
 public:
  explicit BoxLabeller(const std::vector<Ray>& rays) : rays_(rays) {
    constexpr double kNever = std::numeric_limits<double>::infinity();
    scaled_.reserve(rays.size());
    for (const Ray& r : rays) {
      scaled_.push_back({std::abs(r.dx) > 1e-12 ? static_cast<double>(r.dz) / r.dx : kNever,
                         std::abs(r.dy) > 1e-12 ? static_cast<double>(r.dz) / r.dy : kNever, r.dx < 0, r.dy < 0,
                         r.dz > 1e-9});
    }
  }

  int label(size_t i, const std::array<double, 4>& box) const {
    const Scaled& s = scaled_[i];
    if (!s.away) return labelOf(rays_[i], box[0], box[1], box[2], box[3]);
    const double side = std::isinf(s.sideOverFar) ? s.sideOverFar : (s.toLeft ? box[0] : box[1]) * s.sideOverFar;
    const double flat = std::isinf(s.flatOverFar) ? s.flatOverFar : (s.toFloor ? box[2] : box[3]) * s.flatOverFar;
    return firstSurface(1.0, side, flat, s.toLeft, s.toFloor);
  }

 private:
  struct Scaled {
    double sideOverFar, flatOverFar;  // dz / dx and dz / dy (infinite where the ray runs along those planes)
    bool toLeft, toFloor, away;
  };
  const std::vector<Ray>& rays_;
  std::vector<Scaled> scaled_;
};

// The sum over the view's pixels of the log-probability of the label `box` gives each.
double summedScore(const View& view, const BoxLabeller& labeller, const std::array<double, 4>& box) {
  double sum = 0;
  for (size_t i = 0; i < view.rays.size(); ++i) sum += view.logp[i][labeller.label(i, box)];
  return sum;
}

// The box (left, right, bottom, top) whose labels the view finds likeliest: coordinate
// search from `box`, steps halving.
LayoutFit fitBox(const View& view, std::array<double, 4> box) {
  const BoxLabeller labeller(view.rays);
  const auto score = [&](const std::array<double, 4>& b) {
    return b[0] < b[1] && b[2] < b[3] ? summedScore(view, labeller, b) : -1e300;
  };
  double best = score(box);
  const std::array<double, 2> span = {std::max(box[1] - box[0], 0.02), std::max(box[3] - box[2], 0.02)};
  for (int round = 0; round < 6; ++round) {
    const double step = 0.25 * std::pow(0.5, round);
    for (bool improved = true; improved;) {
      improved = false;
      for (int k = 0; k < 4; ++k) {
        for (const double sign : {-1.0, 1.0}) {
          for (const double times : {4.0, 2.0, 1.0}) {
            std::array<double, 4> candidate = box;
            candidate[k] += sign * times * step * span[k < 2 ? 0 : 1];
            if (const double s = score(candidate); s > best) {
              best = s, box = candidate, improved = true;
              break;
            }
          }
        }
      }
    }
  }
  return LayoutFit{box[0], box[1], box[2], box[3], best / static_cast<double>(std::max<size_t>(view.rays.size(), 1))};
}

glm::dvec2 projectFar(glm::dvec2 uv, double focalPx, glm::dvec2 principalPx, const CorridorAxes& axes) {
  const glm::dvec3 d = uv.x * axes.right + uv.y * axes.up + axes.away;
  return principalPx + focalPx * glm::dvec2(d.x, d.y) / d.z;
}

std::optional<LayoutFit> fitLayoutOrThrow(const cv::Mat& bgr, double workScale, double focalPx, glm::dvec2 principalPx,
                                          const CorridorAxes& axes) {
  // The whole photo first, then the far wall's neighbourhood zoomed.
  const double shrink = static_cast<double>(kInputSide) / std::max(bgr.cols, bgr.rows);
  auto looks = std::make_shared<LayoutLooks>();
  const View& whole = looks->whole = look(wholeNet(), bgr, workScale, 0, 0, shrink, focalPx, principalPx, axes);
  if (whole.farU.size() < 4) return std::nullopt;
  LayoutFit fit = fitBox(whole, {percentile(whole.farU, 0.02), percentile(whole.farU, 0.98), percentile(whole.farV, 0.02),
                                 percentile(whole.farV, 0.98)});
  fit.wholeScore = fit.score;
  fit.looks = looks;
  // The far wall's corners in working pixels, and a view around them 2.5 times their extent.
  glm::dvec2 lo(1e300), hi(-1e300);
  for (const glm::dvec2 uv : {glm::dvec2(fit.left, fit.top), {fit.right, fit.top}, {fit.left, fit.bottom}, {fit.right, fit.bottom}}) {
    const glm::dvec2 p = (projectFar(uv, focalPx, principalPx, axes) + 0.5) * workScale - 0.5;
    lo = glm::min(lo, p), hi = glm::max(hi, p);
  }
  if (!(std::isfinite(lo.x) && std::isfinite(hi.x) && std::isfinite(lo.y) && std::isfinite(hi.y))) return fit;
  const double side = std::max(std::max(hi.x - lo.x, hi.y - lo.y) / kNeighbourhoodShare, kMinNeighbourhoodPx * workScale);
  const glm::dvec2 centre = 0.5 * (lo + hi);
  View zoomed = look(zoomNet(), bgr, workScale, centre.x - 0.5 * side, centre.y - 0.5 * side, kInputSide / side, focalPx,
                     principalPx, axes);
  if (zoomed.rays.size() < 16) return fit;
  LayoutFit closer = fitBox(zoomed, {fit.left, fit.right, fit.bottom, fit.top});
  closer.wholeScore = fit.wholeScore;
  looks->zoomed = std::move(zoomed);
  closer.looks = looks;
  return closer;
}

}  // namespace

std::optional<double> boxScore(const LayoutFit& fit, const std::array<glm::dvec2, 4>& farPx, double focalPx,
                               glm::dvec2 principalPx, const CorridorAxes& axes, bool zoomed) {
  if (!fit.looks) return std::nullopt;
  const View& view = zoomed ? fit.looks->zoomed : fit.looks->whole;
  if (view.rays.empty()) return std::nullopt;
  // Each corner's ray on the far plane; each side of the box where its two corners put
  // it on average (an answer of the edges is a box up to its fitting's pixel or so).
  std::array<glm::dvec2, 4> uv{};
  for (int k = 0; k < 4; ++k) {
    const glm::dvec3 c = corridorRay(farPx[k], focalPx, principalPx, axes);
    if (!(c.z > 1e-9)) return std::nullopt;
    uv[k] = glm::dvec2(c.x, c.y) / c.z;
  }
  const std::array<double, 4> box = {0.5 * (uv[0].x + uv[2].x), 0.5 * (uv[1].x + uv[3].x), 0.5 * (uv[2].y + uv[3].y),
                                     0.5 * (uv[0].y + uv[1].y)};
  if (!(box[0] < box[1] && box[2] < box[3])) return std::nullopt;
  return summedScore(view, BoxLabeller(view.rays), box) / static_cast<double>(view.rays.size());
}

CorridorAxes corridorAxes(glm::dvec3 horizontal, glm::dvec3 vertical, glm::dvec3 corridor, double focalPx,
                          glm::dvec2 principalPx) {
  const auto direction = [&](glm::dvec3 h) {
    return glm::normalize(
        glm::dvec3((h.x - principalPx.x * h.z) / focalPx, (h.y - principalPx.y * h.z) / focalPx, h.z));
  };
  CorridorAxes axes{direction(horizontal), direction(vertical), direction(corridor)};
  if (axes.right.x < 0) axes.right = -axes.right;
  if (axes.up.y > 0) axes.up = -axes.up;
  if (axes.away.z < 0) axes.away = -axes.away;
  return axes;
}

std::optional<LayoutFit> fitLayout(const cv::Mat& bgr, double workScale, double focalPx, glm::dvec2 principalPx,
                                   const CorridorAxes& axes) {
  if (bgr.empty() || bgr.type() != CV_8UC3) return std::nullopt;
  // (OpenCV's dnn throws where it cannot run, out of memory say: then no layout, and
  // detection goes on by the edges alone.)
  try {
    return fitLayoutOrThrow(bgr, workScale, focalPx, principalPx, axes);
  } catch (const cv::Exception&) {
    return std::nullopt;
  }
}

std::optional<LayoutFit> lookAtWholePhoto(const cv::Mat& bgr, double workScale, double focalPx, glm::dvec2 principalPx,
                                          const CorridorAxes& axes) {
  if (bgr.empty() || bgr.type() != CV_8UC3) return std::nullopt;
  try {
    const double shrink = static_cast<double>(kInputSide) / std::max(bgr.cols, bgr.rows);
    auto looks = std::make_shared<LayoutLooks>();
    looks->whole = look(wholeNet(), bgr, workScale, 0, 0, shrink, focalPx, principalPx, axes);
    LayoutFit fit;
    fit.looks = looks;
    return fit;
  } catch (const cv::Exception&) {
    return std::nullopt;
  }
}

std::optional<std::array<glm::dvec2, 8>> layoutCorners(const LayoutFit& fit, double focalPx, glm::dvec2 principalPx,
                                                       const CorridorAxes& axes, cv::Size size, double marginPx) {
  // P1 P2 P3 P4, and the near section's P5 P6 P7 P8 on the same rays.
  const std::array<glm::dvec2, 4> farUv = {glm::dvec2(fit.left, fit.top), {fit.right, fit.top}, {fit.left, fit.bottom},
                                           {fit.right, fit.bottom}};
  const auto project = [&](glm::dvec2 uv, double nearer) -> std::optional<glm::dvec2> {
    const glm::dvec3 d = nearer * (uv.x * axes.right + uv.y * axes.up) + axes.away;
    if (!(d.z > 1e-9)) return std::nullopt;
    return principalPx + focalPx * glm::dvec2(d.x, d.y) / d.z;
  };
  const auto inside = [&](double nearer) {
    for (const glm::dvec2& uv : farUv) {
      const auto p = project(uv, nearer);
      if (!p || !(p->x >= marginPx && p->y >= marginPx && p->x <= size.width - 1 - marginPx &&
                  p->y <= size.height - 1 - marginPx)) {
        return false;
      }
    }
    return true;
  };
  if (!inside(1.0)) return std::nullopt;
  double lo = 1.0, hi = 2.0;
  while (inside(hi) && hi < 1e4) lo = hi, hi *= 2;
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (lo + hi);
    (inside(mid) ? lo : hi) = mid;
  }
  std::array<glm::dvec2, 8> corners{};
  constexpr std::array<int, 4> kNearOf = {6, 7, 4, 5};  // P1->P7, P2->P8, P3->P5, P4->P6
  for (int k = 0; k < 4; ++k) {
    corners[k] = *project(farUv[k], 1.0);
    corners[kNearOf[k]] = *project(farUv[k], lo);
  }
  return corners;
}

}  // namespace pw::metrology::detect
