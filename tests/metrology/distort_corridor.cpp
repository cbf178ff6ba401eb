// Test photos through a distorting lens, from the POV-Ray ground truth: OpenCV's radial
// model (metrology/distortion.h) applied to a wider render of the same scene, so that
// what the lens squeezes in from beyond the original frame is really there.
//
//   distort_corridor plan TRUTH.json K1
//       prints "W H OX OY": the wider render (same focal length and camera) to make,
//       its principal point OX, OY pixels right of and below the photo's
//   distort_corridor warp TRUTH.json K1 WIDE.png OX OY OUT_STEM
//       WIDE.png is that render at S times its size (S = 1, 2, ...: its focal length S
//       times the truth's; S = 2 gives each photo pixel the average of four samples, as
//       a camera's pixel integrates, rather than one resampled value);
//       writes OUT_STEM.png (the photo as the lens shows it, the truth's size) and
//       OUT_STEM.json (the truth with that image, the corners where the lens puts them
//       and "distortion": {"k1": K1, "k2": 0})
//
// tests/metrology/make_distorted.py runs both around make_corridors.py's `view`.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "metrology/corridor_frame.h"
#include "metrology/distortion.h"

namespace {

using nlohmann::json;
using pw::metrology::Intrinsics;

int usage() {
  std::fprintf(stderr,
               "usage: distort_corridor plan TRUTH.json K1\n"
               "       distort_corridor warp TRUTH.json K1 WIDE.png OX OY OUT_STEM\n");
  return 2;
}

struct Truth {
  json doc;
  Intrinsics lens;
  cv::Size size;
};

Truth readTruth(const std::string& path, double k1) {
  Truth t;
  std::ifstream in(path);
  t.doc = json::parse(in);
  t.size = cv::Size(t.doc.at("image_size")[0], t.doc.at("image_size")[1]);
  t.lens.focalPx = t.doc.at("focal_px");
  t.lens.principalPointPx = {t.doc.at("principal_point")[0], t.doc.at("principal_point")[1]};
  t.lens.distortion.k1 = k1;
  return t;
}

// The wider render: its principal point at its own centre (make_corridors.py's view
// puts it there), OX, OY whole pixels from the photo's, and big enough to hold every
// pinhole pixel the lens brings into the photo.
void plan(const Truth& t) {
  glm::dvec2 lo(0.0), hi(t.size.width - 1.0, t.size.height - 1.0);
  for (int y = 0; y < t.size.height; ++y) {
    for (int x = 0; x < t.size.width; ++x) {
      if (x != 0 && y != 0 && x != t.size.width - 1 && y != t.size.height - 1) continue;
      if (auto p = pw::metrology::undistortPixel(t.lens, glm::dvec2(x, y))) lo = glm::min(lo, *p), hi = glm::max(hi, *p);
    }
  }
  const glm::dvec2 pp = t.lens.principalPointPx;
  // W = 2 (pp.x + OX) + 1 must hold pinhole x up to hi.x + OX (+ a bicubic margin).
  const double ox = std::ceil(std::max(-lo.x, hi.x - 2 * pp.x) + 3), oy = std::ceil(std::max(-lo.y, hi.y - 2 * pp.y) + 3);
  const double w = 2 * (pp.x + ox) + 1, h = 2 * (pp.y + oy) + 1;
  std::printf("%d %d %d %d\n", static_cast<int>(std::lround(w)), static_cast<int>(std::lround(h)),
              static_cast<int>(ox), static_cast<int>(oy));
}

int warp(Truth t, const std::string& widePath, double ox, double oy, const std::string& stem) {
  const cv::Mat wide = cv::imread(widePath, cv::IMREAD_COLOR);
  if (wide.empty()) {
    std::fprintf(stderr, "distort_corridor: cannot read %s\n", widePath.c_str());
    return 1;
  }
  // The render's scale: pixel centres map as q = S p + (S - 1) / 2, so the lens at S
  // times the size has S times the focal length and that principal point.
  const int s = static_cast<int>(std::lround(wide.cols / (2 * (t.lens.principalPointPx.x + ox) + 1)));
  if (s < 1 || wide.cols != s * static_cast<int>(std::lround(2 * (t.lens.principalPointPx.x + ox) + 1))) {
    std::fprintf(stderr, "distort_corridor: %s is not the planned render at a whole scale\n", widePath.c_str());
    return 1;
  }
  Intrinsics fine = t.lens;
  fine.focalPx *= s;
  fine.principalPointPx = double(s) * t.lens.principalPointPx + 0.5 * (s - 1);
  cv::Mat mapX, mapY, finePhoto, photo;
  pw::metrology::distortionMaps(fine, t.size * s, double(s) * glm::dvec2(ox, oy), mapX, mapY);
  cv::remap(wide, finePhoto, mapX, mapY, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar::all(0));
  cv::resize(finePhoto, photo, t.size, 0, 0, cv::INTER_AREA);
  const std::string pngPath = stem + ".png";
  if (!cv::imwrite(pngPath, photo)) return 1;
  json out = t.doc;
  const size_t slash = pngPath.find_last_of('/');
  out["image"] = slash == std::string::npos ? pngPath : pngPath.substr(slash + 1);
  for (auto& [name, corner] : out.at("corners_px").items()) {
    const glm::dvec2 p = pw::metrology::distortPixel(t.lens, glm::dvec2(corner[0], corner[1]));
    corner = {p.x, p.y};
  }
  out["distortion"] = {{"k1", t.lens.distortion.k1}, {"k2", 0.0}};
  std::ofstream(stem + ".json") << out.dump(1) << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) return usage();
  const std::string mode = argv[1];
  try {
    const Truth t = readTruth(argv[2], std::stod(argv[3]));
    if (mode == "plan" && argc == 4) {
      plan(t);
      return 0;
    }
    if (mode == "warp" && argc == 8) return warp(t, argv[4], std::stod(argv[5]), std::stod(argv[6]), argv[7]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "distort_corridor: %s\n", e.what());
    return 1;
  }
  return usage();
}
