// Novel-view benchmark (not a test; issue 14): how close a model's views from cameras
// the photo was not taken from come to the scene itself. For each ground-truth scene
// (tests/groundtruth), the model is built from the scene's exact corners (so metrology
// plays no part) three times: as `build --photo-only` makes it (today's model, the baseline),
// as `build` makes it (what the photo did not see synthesized, the corridor closed
// behind the camera, detail added where it saw coarsely) and as `build --no-detail`
// makes it (the same without the detail), rendered on the CPU
// device from each novel-view camera (make_corridors.py `views`) and scored against
// POV-Ray's frame from the same camera: PSNR, SSIM and the high-frequency energy ratio
// (tests/support/novel_views.h). Prints each scene's row and the medians per view kind,
// and the time each build took.
// Usage: novel_view_bench [--save DIR] [--only corridor_a,...]   (DIR: the frames as PNG)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "bench/bench_timing.h"
#include "engine/gpu/renderer.h"
#include "modeling/pipeline.h"
#include "tests/support/groundtruth.h"
#include "tests/support/novel_views.h"

namespace {
namespace fs = std::filesystem;
using pw::test::ViewScores;

int fail(const std::string& message) {
  std::fprintf(stderr, "novel_view_bench: %s\n", message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  fs::path saveDir;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--save" && i + 1 < argc) {
      saveDir = argv[++i];
    } else if (a == "--only" && i + 1 < argc) {
      only = argv[++i];
    } else {
      return fail("usage: novel_view_bench [--save DIR] [--only corridor_a,...]");
    }
  }
  if (!saveDir.empty()) fs::create_directories(saveDir);
  pw::engine::RendererOptions rendererOptions;
  rendererOptions.forceCpu = true;
  rendererOptions.validation = pw::engine::RendererOptions::Validation::kOff;
  auto renderer = pw::engine::Renderer::create(rendererOptions);
  if (!renderer) return fail(renderer.message());

  constexpr int kModelCount = 3;
  const char* kModels[kModelCount] = {"photo-only", "build", "no-detail"};
  std::map<std::string, std::vector<ViewScores>> scores[kModelCount];  // per model, per kind, one per scene
  std::vector<double> buildMs[kModelCount];
  std::printf("%-11s %-7s | %-24s | %-24s | %-24s\n", "scene", "view", "photo-only: PSNR SSIM HF", "build",
              "build --no-detail");
  for (const std::string& name : pw::groundtruth::groundTruthNames()) {
    if (!only.empty() && only.find(name) == std::string::npos) continue;
    const fs::path shot = pw::groundtruth::groundTruthShot(name);
    pw::engine::Scene scenes[kModelCount];
    for (int m = 0; m < kModelCount; ++m) {
      pw::modeling::ModelOptions options;
      options.photoOnly = m == 0;
      options.detail = m == 1;
      const auto start = std::chrono::steady_clock::now();
      auto built = pw::modeling::buildModel(pw::modeling::chainLayout({shot}), options);
      buildMs[m].push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      if (!built) return fail(built.message());
      scenes[m] = std::move(built->scene);
    }
    for (const std::string& kind : pw::test::novelViewKinds()) {
      pw::test::NovelView view;
      try {
        view = pw::test::loadNovelView(PW_GROUNDTRUTH_DIR, name, kind);
      } catch (const std::exception& e) {
        return fail(e.what());
      }
      ViewScores row[kModelCount];
      for (int m = 0; m < kModelCount; ++m) {
        std::string error;
        const cv::Mat ours = pw::test::renderView(**renderer, scenes[m], view, error);
        if (ours.empty()) return fail(error);
        row[m] = pw::test::scoreView(ours, view.truth);
        scores[m][kind].push_back(row[m]);
        if (!saveDir.empty()) {
          cv::imwrite((saveDir / (name + "_" + kind + "_" + kModels[m] + ".png")).string(), ours);
          if (m == 0) cv::imwrite((saveDir / (name + "_" + kind + "_povray.png")).string(), view.truth);
        }
      }
      std::printf("%-11s %-7s", name.c_str(), kind.c_str());
      for (const ViewScores& v : row) std::printf(" | %6.2f dB %5.3f %5.2f    ", v.psnrDb, v.ssim, v.highFrequencyRatio);
      std::printf("\n");
    }
  }
  std::printf("\nmedians over %zu scenes:\n", buildMs[0].size());
  for (const std::string& kind : pw::test::novelViewKinds()) {
    double med[kModelCount][3];
    for (int m = 0; m < kModelCount; ++m) {
      std::vector<double> p, s, h;
      for (const ViewScores& v : scores[m][kind]) p.push_back(v.psnrDb), s.push_back(v.ssim), h.push_back(v.highFrequencyRatio);
      med[m][0] = pw::bench::median(p), med[m][1] = pw::bench::median(s), med[m][2] = pw::bench::median(h);
    }
    std::printf("%-19s", kind.c_str());
    for (const auto& m : med) std::printf(" | %6.2f dB %5.3f %5.2f    ", m[0], m[1], m[2]);
    std::printf("\n");
  }
  std::printf("build (median over scenes): photo-only %.0f ms, build %.0f ms, --no-detail %.0f ms\n",
              pw::bench::median(buildMs[0]), pw::bench::median(buildMs[1]), pw::bench::median(buildMs[2]));
  return 0;
}
