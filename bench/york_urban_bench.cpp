// Vanishing points on real photos (issue 22, part 2): the training half of the York
// Urban Database (../shared/real-photos/york-urban-train: 51 calibrated 640x480 photos
// with ground-truth Manhattan frames), for photowalk's detectCorridor and, in the same
// run, the literature's 2-line exhaustive search (Lu et al., WACV 2017; bench/lu_manhattan.h).
//
// Per photo and method: the error of the worst of the three ground-truth directions
// (`vps_orthogonal`; each against the nearest detected direction, sign-free, as
// ../shared/tools/vp-accuracy scores it) and of the corridor (depth) direction, with the
// calibrated focal length and principal point given; then the focal length found with
// it withheld (principal point given). Totals: the share within 1/2/5 degrees, the
// median, the mean time; all photos and the indoor ones (corridor, corridor_partial,
// indoor_other). Times are medians of kRuns runs per photo, wall-clock ms.
//
// usage: york_urban_bench [DATASET_DIR] [--json OUT] [--quick]
//   --quick: photowalk's frame stage alone (LSD + estimateManhattanFrame, scored as the
//   figures), one run per time, no focal-withheld runs: for tuning, not for reporting.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "bench/bench_timing.h"
#include "bench/lu_manhattan.h"
#include "metrology/detect/detect.h"
#include "metrology/detect/line_segments.h"
#include "metrology/detect/vanishing_points.h"
#include "metrology/input_sigma.h"

namespace {

namespace fs = std::filesystem;
using pw::bench::median;
using pw::bench::medianMs;
using namespace pw::metrology::detect;
namespace lu = pw::bench::lu;

constexpr int kRuns = 3;
constexpr double kPi = 3.14159265358979323846;

double angleDeg(glm::dvec3 a, glm::dvec3 b) {
  const double c = std::abs(glm::dot(a, b)) / (glm::length(a) * glm::length(b));
  return std::acos(std::min(1.0, c)) * 180.0 / kPi;
}

// The worst over the truth's directions of the angle to the nearest detected one.
double worstOfThree(const std::vector<glm::dvec3>& truth, const std::vector<glm::dvec3>& found) {
  double worst = 0;
  for (const glm::dvec3& t : truth) {
    double nearest = 180;
    for (const glm::dvec3& f : found) nearest = std::min(nearest, angleDeg(t, f));
    worst = std::max(worst, nearest);
  }
  return worst;
}

glm::dvec3 directionOf(glm::dvec3 homogeneousPx, double f, glm::dvec2 pp) {
  return {homogeneousPx.x - pp.x * homogeneousPx.z, homogeneousPx.y - pp.y * homogeneousPx.z, f * homogeneousPx.z};
}

glm::dvec3 vec3(const nlohmann::json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

struct MethodRow {
  bool found = false;
  double worstDeg = NAN, corridorDeg = NAN, ms = 0;  // focal given
  double focalPx = NAN, focalErrPct = NAN, focalMs = 0;  // focal withheld
  std::string focalSource;
  double frameMs = 0;  // photowalk only: segments + estimateManhattanFrame alone
};

struct Row {
  std::string name, scene;
  MethodRow pw, lu;
};

bool indoor(const std::string& scene) { return scene != "outdoor"; }

void printTotals(const char* title, const std::vector<Row>& rows, bool indoorOnly) {
  std::printf("\n%s\n", title);
  std::printf("  %-22s %5s %13s %13s %13s %9s %9s %10s | %s\n", "method", "n", "<=1 deg", "<=2 deg", "<=5 deg", "median",
              "corr.med", "mean ms", "focal withheld: median |err|, within 5%");
  for (int m = 0; m < 2; ++m) {
    std::vector<double> worst, corridor, ms, focalErr, frameMs;
    int n = 0, w1 = 0, w2 = 0, w5 = 0, f5 = 0, fn = 0;
    for (const Row& r : rows) {
      if (indoorOnly && !indoor(r.scene)) continue;
      const MethodRow& x = m == 0 ? r.pw : r.lu;
      ++n;
      ms.push_back(x.ms);
      frameMs.push_back(x.frameMs);
      // A photo without a frame counts as beyond every threshold (error 180).
      const double e = std::isfinite(x.worstDeg) ? x.worstDeg : 180.0;
      worst.push_back(e);
      w1 += e <= 1, w2 += e <= 2, w5 += e <= 5;
      corridor.push_back(std::isfinite(x.corridorDeg) ? x.corridorDeg : 180.0);
      ++fn;
      const double fe = std::isfinite(x.focalErrPct) ? std::abs(x.focalErrPct) : 100.0;
      focalErr.push_back(fe);
      f5 += fe <= 5;
    }
    double meanMs = 0, meanFrameMs = 0;
    for (double t : ms) meanMs += t / std::max<size_t>(1, ms.size());
    for (double t : frameMs) meanFrameMs += t / std::max<size_t>(1, frameMs.size());
    const auto share = [n](int k) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%2d (%3.0f%%)", k, n ? 100.0 * k / n : 0.0);
      return std::string(buf);
    };
    std::printf("  %-22s %5d %13s %13s %13s %8.2f° %8.2f° %10.1f | %6.1f%%, %d of %d\n",
                m == 0 ? "photowalk detectCorridor" : "Lu et al. 2017", n, share(w1).c_str(), share(w2).c_str(),
                share(w5).c_str(), median(worst), median(corridor), meanMs, median(focalErr), f5, fn);
    if (m == 0) std::printf("  %-22s %75.1f  (LSD + estimateManhattanFrame alone)\n", "", meanFrameMs);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string dir = PW_YORK_URBAN_DIR, jsonOut;
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick") {
      quick = true;
    } else if (a == "--json" && i + 1 < argc) {
      jsonOut = argv[++i];
    } else if (a == "--help" || a == "-h") {
      std::printf("usage: york_urban_bench [DATASET_DIR] [--json OUT] [--quick]\n");
      return 0;
    } else {
      dir = a;
    }
  }
  if (!fs::is_directory(fs::path(dir) / "gt") || !fs::exists(fs::path(dir) / "camera.json")) {
    std::fprintf(stderr, "error: no York Urban training half at %s (expected camera.json and gt/; see ../shared/real-photos/README.md)\n",
                 dir.c_str());
    return 1;
  }
  const nlohmann::json camera = nlohmann::json::parse(std::ifstream(fs::path(dir) / "camera.json"));
  const double f = camera["focal_px"].get<double>();
  const glm::dvec2 pp(camera["principal_point"][0].get<double>(), camera["principal_point"][1].get<double>());

  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(fs::path(dir) / "gt"))
    if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());

  std::printf("york_urban_bench: %zu photos in %s; focal %.3f px, principal point (%.3f, %.3f); %d OpenCV threads\n",
              files.size(), dir.c_str(), f, pp.x, pp.y, cv::getNumThreads());
  std::printf("errors in degrees: worst of the three directions (vps_orthogonal) / the corridor (depth) direction; "
              "times: median of %d runs, ms\n\n", kRuns);
  std::printf("%-9s %-16s | %-34s | %-34s\n", "", "", "photowalk detectCorridor", "Lu et al. 2017 (2-line exhaustive)");
  std::printf("%-9s %-16s | %6s %6s %6s %6s %7s %-9s | %6s %6s %6s %7s\n", "photo", "scene", "worst", "corr.", "ms",
              "frame", "f err%", "f source", "worst", "corr.", "ms", "f err%");

  std::vector<Row> rows;
  nlohmann::json out = nlohmann::json::array();
  for (const fs::path& file : files) {
    const nlohmann::json g = nlohmann::json::parse(std::ifstream(file));
    Row row;
    row.name = g["name"].get<std::string>();
    row.scene = g["scene"].get<std::string>();
    std::vector<glm::dvec3> truth;
    for (const auto& v : g["vps_orthogonal"]) truth.push_back(vec3(v["direction_xright_ydown_zfwd"]));
    glm::dvec3 depth{0, 0, 1};
    for (const auto& v : g["vps"])
      if (v["index"] == g["depth_vp_index"]) depth = vec3(v["direction_xright_ydown_zfwd"]);
    const cv::Mat photo = cv::imread((fs::path(dir) / g["image"].get<std::string>()).string(), cv::IMREAD_COLOR);
    if (photo.empty()) {
      std::fprintf(stderr, "error: cannot read %s\n", g["image"].get<std::string>().c_str());
      return 1;
    }

    // photowalk, focal given.
    DetectOptions given;
    given.focalPx = f;
    given.principalPointPx = pp;
    const int runs = quick ? 1 : kRuns;
    const auto score = [&](const VanishingPoint& corridor, const VanishingPoint& horizontal, const VanishingPoint& vertical) {
      row.pw.found = true;
      std::vector<glm::dvec3> dirs;
      for (const VanishingPoint* vp : {&corridor, &horizontal, &vertical}) dirs.push_back(directionOf(vp->point, f, pp));
      row.pw.worstDeg = worstOfThree(truth, dirs);
      row.pw.corridorDeg = angleDeg(depth, dirs[0]);
    };
    if (!quick) {
      pw::Result<CorridorDetection> d = pw::makeError("not run");
      row.pw.ms = medianMs(runs, [&] { d = detectCorridor(photo, given); });
      // A frame was found when the vanishing points are set (detectCorridor fills them
      // in even when no corridor's box is, once a frame is found).
      if (d && d->corridor.inlierCount + d->horizontal.inlierCount + d->vertical.inlierCount > 0) {
        score(d->corridor, d->horizontal, d->vertical);
      }
    }
    // The frame stage alone, as detectCorridor runs it on a photo of this size (the
    // working copy is the photo itself below 1280 px).
    {
      cv::Mat gray;
      cv::cvtColor(photo, gray, cv::COLOR_BGR2GRAY);
      const double minLength = 0.02 * std::hypot(photo.cols, photo.rows);
      pw::Result<ManhattanFrame> frame = pw::makeError("not run");
      row.pw.frameMs = medianMs(runs, [&] {
        frame = estimateManhattanFrame(detectLineSegments(gray, 1.0, minLength), PinholeCamera{f, pp}, photo.size());
      });
      if (quick && frame) score(frame->corridor, frame->horizontal, frame->vertical);
    }
    // photowalk, focal withheld.
    DetectOptions withheld;
    withheld.principalPointPx = pp;
    pw::Result<CorridorDetection> dn = pw::makeError("not run");
    if (!quick) row.pw.focalMs = medianMs(1, [&] { dn = detectCorridor(photo, withheld); });
    if (dn) {
      row.pw.focalPx = dn->focalPx;
      row.pw.focalErrPct = 100.0 * (dn->focalPx / f - 1.0);
      row.pw.focalSource = focalSourceName(dn->focalSource);
    }

    // Lu et al., focal given.
    cv::Mat gray;
    cv::cvtColor(photo, gray, cv::COLOR_BGR2GRAY);
    lu::Frame frame;
    row.lu.ms = medianMs(runs, [&] { frame = lu::estimateFrame(lu::detectLines(gray), f, pp); });
    if (frame.found) {
      row.lu.found = true;
      const std::vector<glm::dvec3> dirs(frame.directions.begin(), frame.directions.end());
      row.lu.worstDeg = worstOfThree(truth, dirs);
      // Its corridor: the direction most nearly along the optical axis (photowalk's rule).
      glm::dvec3 corridor = dirs[0];
      for (const glm::dvec3& x : dirs)
        if (std::abs(x.z) > std::abs(corridor.z)) corridor = x;
      row.lu.corridorDeg = angleDeg(depth, corridor);
    }
    lu::FocalSearch search;
    if (!quick) row.lu.focalMs = medianMs(1, [&] { search = lu::estimateFrameAndFocal(lu::detectLines(gray), pp, photo.size()); });
    if (search.frame.found) {
      row.lu.focalPx = search.focalPx;
      row.lu.focalErrPct = 100.0 * (search.focalPx / f - 1.0);
      row.lu.focalSource = "two_points";
    }

    const auto num = [](double x, const char* fmt) {
      if (!std::isfinite(x)) return std::string("-");
      char buf[32];
      std::snprintf(buf, sizeof buf, fmt, x);
      return std::string(buf);
    };
    std::printf("%-9s %-16s | %6s %6s %6.1f %6.1f %7s %-9s | %6s %6s %6.1f %7s\n", row.name.c_str(), row.scene.c_str(),
                num(row.pw.worstDeg, "%.2f").c_str(), num(row.pw.corridorDeg, "%.2f").c_str(), row.pw.ms, row.pw.frameMs,
                num(row.pw.focalErrPct, "%+.1f").c_str(), row.pw.focalSource.substr(0, 9).c_str(),
                num(row.lu.worstDeg, "%.2f").c_str(), num(row.lu.corridorDeg, "%.2f").c_str(), row.lu.ms,
                num(row.lu.focalErrPct, "%+.1f").c_str());
    std::fflush(stdout);

    const auto methodJson = [](const MethodRow& x) {
      const auto orNull = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
      return nlohmann::json{{"found", x.found}, {"worst_deg", orNull(x.worstDeg)}, {"corridor_deg", orNull(x.corridorDeg)},
                            {"ms", x.ms}, {"focal_withheld_px", orNull(x.focalPx)},
                            {"focal_withheld_err_pct", orNull(x.focalErrPct)}, {"focal_source", x.focalSource},
                            {"focal_withheld_ms", x.focalMs}};
    };
    nlohmann::json pwJson = methodJson(row.pw);
    pwJson["frame_ms"] = row.pw.frameMs;
    out.push_back({{"name", row.name}, {"scene", row.scene}, {"photowalk", pwJson}, {"lu2017", methodJson(row.lu)}});
    rows.push_back(std::move(row));
  }

  printTotals("All photos (a photo without a frame counts as 180 degrees; focal: 100% off)", rows, false);
  printTotals("Indoor photos (corridor, corridor_partial, indoor_other)", rows, true);
  std::printf("\nfocal withheld: photowalk as detect runs it (second finite vanishing point, else the 28 mm default); "
              "Lu: from two finite points fitted to its line clusters, iterated from f = long side\n");

  // Issue 22 part 6: the EXIF's focal length (the camera's FocalLengthIn35mmFilm 35 mm,
  // by the diagonal: 4.1% short of the calibration) weighed with a second finite
  // vanishing point's (metrology/input_sigma.h's weighFocal), at the sigma each is
  // given. photowalk's where detect found one (focal_source vanishing_points), Lu's
  // wherever it gives one.
  {
    const double exifPx = 35.0 / std::hypot(36.0, 24.0) * std::hypot(640.0, 480.0);
    const auto report = [&](const char* name, bool lu, double secondSigma) {
      std::vector<double> errors;
      int used = 0, within5 = 0;
      for (const Row& r : rows) {
        const MethodRow& x = lu ? r.lu : r.pw;
        double weighed = exifPx;
        if (std::isfinite(x.focalPx) && (lu || x.focalSource == "vanishing_points")) {
          const auto w = pw::metrology::weighFocal(exifPx, pw::metrology::kExif35mmFocalSigmaRelative, x.focalPx, secondSigma);
          weighed = w.focalPx;
          used += w.usedSecond;
        }
        errors.push_back(std::abs(100.0 * (weighed / f - 1.0)));
        within5 += errors.back() <= 5.0;
      }
      std::printf("  %-44s median |err| %5.1f%%, within 5%%: %2d of %zu, the second used in %d\n", name, median(errors),
                  within5, rows.size(), used);
    };
    std::printf("\nfocal length from the EXIF (35 mm equivalent: %.1f px, %+.1f%%), weighed with a second point's:\n", exifPx,
                100.0 * (exifPx / f - 1.0));
    report("EXIF alone", false, 0.0);
    report("EXIF + photowalk's point (sigma 0.22)", false, pw::metrology::kVanishingFocalSigmaRelative);
    report("EXIF + Lu's two points (sigma 0.13)", true, 0.13);
  }

  if (!jsonOut.empty()) {
    std::ofstream o(jsonOut);
    o << nlohmann::json{{"dataset", dir}, {"focal_px", f}, {"principal_point", {pp.x, pp.y}}, {"runs_per_time", kRuns},
                        {"photos", out}}
             .dump(1)
      << "\n";
    if (!o) {
      std::fprintf(stderr, "error: cannot write %s\n", jsonOut.c_str());
      return 1;
    }
    std::printf("per-photo rows written to %s\n", jsonOut.c_str());
  }
  return 0;
}
