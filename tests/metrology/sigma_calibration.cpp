// Calibration of the measurement's ± (issue 23): over ground-truth scenes, how often
// the 2σ interval of each dimension holds the truth, with the inputs a new user has
// and with everything given.
//
// usage: sigma_calibration DIR [--seeds FROM-TO] [--min-coverage P] [--max-coverage P]
//                              [--noise-px S] [--table]
//
// DIR holds scene truths: tests/groundtruth's corridor_*.json / clutter_*.json, or
// random_corridors.py's seed_NNNNN.json (--seeds picks a range of those). Each scene is
// measured twice from its true corners moved by Gaussian noise of --noise-px (default
// 1, the detector's figure when it finds the corner; seeded by the scene's name):
//   new user:   no focal length (a 28 mm-equivalent lens assumed), camera height
//               assumed 1.6 m, principal point and distortion not given;
//   all given:  the true focal length, camera height and principal point, no
//               distortion: only the corners are uncertain (today's ±).
// It prints the coverage per dimension and the median 2σ width relative to the
// dimension for both, and fails when the new user's coverage of any dimension, or of
// all together, is outside [--min-coverage, --max-coverage] (percent; default 92-98).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "metrology/input_sigma.h"
#include "metrology/measure.h"

namespace fs = std::filesystem;
using namespace pw::metrology;

namespace {

struct Scene {
  std::string name;
  Shot shot;  // everything true
  double truth[3] = {0, 0, 0};
};

std::optional<Scene> readScene(const fs::path& path) {
  std::ifstream in(path);
  nlohmann::json j;
  try {
    in >> j;
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (!j.contains("corners_px") || !j.contains("width_m") || !j.contains("focal_px")) return std::nullopt;
  Scene s;
  s.name = j.value("name", path.stem().string());
  s.shot.imageWidth = j["image_size"][0].get<int>();
  s.shot.imageHeight = j["image_size"][1].get<int>();
  s.shot.focalPx = j["focal_px"].get<double>();
  if (j.contains("principal_point")) {
    s.shot.principalPointPx = glm::dvec2(j["principal_point"][0].get<double>(), j["principal_point"][1].get<double>());
  }
  s.shot.cameraHeightM = j["camera_height_m"].get<double>();
  for (int i = 0; i < kCornerCount; ++i) {
    const auto& c = j["corners_px"][cornerName(i)];
    s.shot.cornersPx[i] = glm::dvec2(c[0].get<double>(), c[1].get<double>());
  }
  s.truth[0] = j["width_m"].get<double>();
  s.truth[1] = j["height_m"].get<double>();
  s.truth[2] = j["length_m"].get<double>();
  return s;
}

struct Tally {
  int dims[3] = {0, 0, 0};
  int covered[3] = {0, 0, 0};
  std::vector<double> relWidth[3];  // 2σ / value
  int failed = 0;
  void add(const Measurement& m, const double truth[3]) {
    for (int d = 0; d < 3; ++d) {
      const double v = dimensionOf(m.size, d), s = dimensionOf(m.sigma, d);
      ++dims[d];
      if (std::abs(v - truth[d]) <= 2 * s) ++covered[d];
      relWidth[d].push_back(2 * s / v);
    }
  }
  double coverage(int d) const { return dims[d] ? 100.0 * covered[d] / dims[d] : 0; }
  double coverageAll() const {
    const int n = dims[0] + dims[1] + dims[2];
    return n ? 100.0 * (covered[0] + covered[1] + covered[2]) / n : 0;
  }
  static double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: sigma_calibration DIR [--seeds FROM-TO] [--min-coverage P] [--max-coverage P] "
                         "[--noise-px S]\n");
    return 2;
  }
  const fs::path dir = argv[1];
  long seedFrom = -1, seedTo = -1;
  double minCoverage = 92, maxCoverage = 98, noisePx = 1.0;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--seeds") {
      const size_t dash = value.find('-');
      seedFrom = std::stol(value.substr(0, dash));
      seedTo = std::stol(value.substr(dash + 1));
    } else if (flag == "--min-coverage") {
      minCoverage = std::stod(value);
    } else if (flag == "--max-coverage") {
      maxCoverage = std::stod(value);
    } else if (flag == "--noise-px") {
      noisePx = std::stod(value);
    } else {
      std::fprintf(stderr, "unknown option %s\n", flag.c_str());
      return 2;
    }
  }
  std::vector<fs::path> paths;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (e.path().extension() != ".json" || name.find("_view_") != std::string::npos) continue;
    if (seedFrom >= 0) {
      if (name.rfind("seed_", 0) != 0) continue;
      const long seed = std::stol(name.substr(5));
      if (seed < seedFrom || seed > seedTo) continue;
    } else if (name.rfind("corridor_", 0) != 0 && name.rfind("clutter_", 0) != 0 && name.rfind("seed_", 0) != 0) {
      continue;
    }
    paths.push_back(e.path());
  }
  std::sort(paths.begin(), paths.end());

  Tally user, given;
  int scenes = 0;
  double widestOverToday = 0;  // all given: the largest sigma over today's
  for (const fs::path& path : paths) {
    auto scene = readScene(path);
    if (!scene) continue;
    ++scenes;
    std::mt19937 rng(static_cast<unsigned>(std::hash<std::string>{}(scene->name) & 0xffffffffu));
    std::normal_distribution<double> noise(0.0, noisePx);
    Shot noisy = scene->shot;
    for (auto& c : noisy.cornersPx) c += glm::dvec2(noise(rng), noise(rng));

    // Everything given: the truth's camera, a pinhole.
    Shot all = noisy;
    all.distortion = RadialDistortion{};
    InputOrigins allOrigins;
    auto mAll = measureCorridor(all, withInputSigmas({}, all, allOrigins));
    // A new user: nothing but the photo and the corners.
    Shot fresh = noisy;
    fresh.focalPx = kAssumedFocalOverLongSide * std::max(fresh.imageWidth, fresh.imageHeight);
    fresh.principalPointPx.reset();
    fresh.cameraHeightM = kAssumedCameraHeightM;
    fresh.distortion.reset();
    InputOrigins freshOrigins;
    freshOrigins.focal = FocalOrigin::kAssumed;
    freshOrigins.cameraHeightAssumed = true;
    MeasureOptions freshOptions = withInputSigmas({}, fresh, freshOrigins);
    // For the calibration's sweep: the assumed focal length's and camera height's sigma.
    if (const char* v = std::getenv("PW_SIGMA_FOCAL")) freshOptions.focalSigmaRelative = std::atof(v);
    if (const char* v = std::getenv("PW_SIGMA_HEIGHT")) freshOptions.cameraHeightSigmaM = std::atof(v);
    auto mFresh = measureCorridor(fresh, freshOptions);
    if (mAll) given.add(*mAll, scene->truth);
    else ++given.failed;
    // Today's ± (the corners only, MeasureOptions' defaults) of the same shot.
    if (auto today = measureCorridor(all); today && mAll) {
      for (int d = 0; d < 3; ++d) {
        widestOverToday = std::max(widestOverToday, dimensionOf(mAll->sigma, d) / dimensionOf(today->sigma, d));
      }
    }
    if (mFresh) user.add(*mFresh, scene->truth);
    else ++user.failed;
    if (std::getenv("PW_SIGMA_CALIBRATION_ROWS") && mFresh) {
      std::printf("%s", scene->name.c_str());
      for (int d = 0; d < 3; ++d) {
        std::printf(" %.4f %.4f %.4f", scene->truth[d], dimensionOf(mFresh->size, d), dimensionOf(mFresh->sigma, d));
      }
      std::printf("\n");
    }
  }
  const char* const names[3] = {"width", "height", "length"};
  std::printf("%d scenes from %s (corners: truth + %.1f px noise)\n", scenes, dir.string().c_str(), noisePx);
  std::printf("%-10s %-22s %-22s %-20s\n", "dimension", "new user: 2s covers", "2s width (median)",
              "all given: covers, 2s width");
  for (int d = 0; d < 3; ++d) {
    std::printf("%-10s %5.1f%% (%3d of %3d)     %6.1f%%                %5.1f%%, %.2f%%\n", names[d], user.coverage(d),
                user.covered[d], user.dims[d], 100 * Tally::median(user.relWidth[d]), given.coverage(d),
                100 * Tally::median(given.relWidth[d]));
  }
  std::printf("%-10s %5.1f%%                                          %5.1f%%\n", "all", user.coverageAll(),
              given.coverageAll());
  std::printf("not measured: new user %d, all given %d\n", user.failed, given.failed);
  std::printf("all given: sigma at most %.6f times today's (the corners only)\n", widestOverToday);
  bool ok = scenes > 0;
  if (!(widestOverToday <= 1.0 + 1e-9)) {
    std::printf("FAIL all given: a sigma %.6f times today's\n", widestOverToday);
    ok = false;
  }
  for (int d = 0; d < 3; ++d) {
    if (!(user.coverage(d) >= minCoverage && user.coverage(d) <= maxCoverage)) {
      std::printf("FAIL %s: the new user's 2 sigma covers %.1f%%, outside %.0f-%.0f%%\n", names[d], user.coverage(d),
                  minCoverage, maxCoverage);
      ok = false;
    }
  }
  if (!(user.coverageAll() >= minCoverage && user.coverageAll() <= maxCoverage)) ok = false;
  return ok ? 0 : 1;
}
