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
//
// Random scenes (issues 22 and 25): novel_view_bench --random DIR --seeds A-B[,C-D...]
// reads each seed's scene from DIR (tests/groundtruth/random_corridors.py's files:
// seed_NNNNN.json, a shot with exact corners, and its views seed_NNNNN_view_KIND) and,
// where bench/standing_views.py wrote one, seed_NNNNN_standing.json (the same shot with
// its floor objects' outlines as cutouts). Each is built as `build` makes it (objects
// painted flat) and, with cutouts, with them stood up; each frame is scored against
// POV-Ray's, and each model's view from the photo's own camera against the photo.
// bench/standing_views.py renders what is missing and runs this.
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
#include "modeling/shot_file.h"
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

std::vector<int> parseSeeds(const std::string& text) {
  std::vector<int> seeds;
  size_t at = 0;
  while (at < text.size()) {
    const size_t comma = text.find(',', at);
    const std::string part = text.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    const size_t dash = part.find('-');
    const int a = std::stoi(part.substr(0, dash)), b = dash == std::string::npos ? a : std::stoi(part.substr(dash + 1));
    for (int s = a; s <= b; ++s) seeds.push_back(s);
    if (comma == std::string::npos) break;
    at = comma + 1;
  }
  return seeds;
}

// PSNR of the model seen from the photo's camera against the photo (the model should
// give the photo back).
double photoPsnr(pw::engine::Renderer& renderer, const pw::engine::Scene& scene, const fs::path& shot) {
  auto camera = pw::modeling::shotCamera(shot);
  auto file = pw::modeling::readShotFile(shot);
  if (!camera || !file) return 0;
  const cv::Mat photo = cv::imread(file->imagePath, cv::IMREAD_COLOR);
  if (photo.empty()) return 0;
  pw::test::NovelView view{"", "photo", *camera, photo};
  std::string error;
  const cv::Mat ours = pw::test::renderView(renderer, scene, view, error);
  return ours.empty() ? 0 : pw::test::scoreView(ours, photo).psnrDb;
}

int randomScenes(pw::engine::Renderer& renderer, const fs::path& dir, const std::vector<int>& seeds, const fs::path& saveDir) {
  std::map<std::string, std::vector<double>> flatAll, flatWith, standing;  // PSNR per view kind
  std::vector<double> photoFlat, photoStanding;
  std::map<std::string, int> better;
  std::vector<std::string> refused;
  size_t leftPainted = 0;
  int withObjects = 0;
  std::printf("%-10s %-7s | %-16s | %-16s\n", "scene", "view", "flat: PSNR SSIM", "stood up");
  for (const int seed : seeds) {
    char name[32];
    std::snprintf(name, sizeof name, "seed_%05d", seed);
    const fs::path flatShot = dir / (std::string(name) + ".json"), standingShot = dir / (std::string(name) + "_standing.json");
    bool hasObjects = fs::exists(standingShot);
    pw::engine::Scene scenes[2];
    for (int m = 0; m < (hasObjects ? 2 : 1); ++m) {
      auto built = pw::modeling::buildModel(pw::modeling::chainLayout({m == 0 ? flatShot : standingShot}), {});
      if (!built) return fail(built.message());
      if (m == 1) {
        // Objects the model cannot stand up (GrabCut kept too little of one, a hanging
        // one's top not on the ceiling) are left painted and said; a scene with none
        // stood up counts as flat only.
        leftPainted += built->corridors[0].leftPainted.size();
        for (const std::string& why : built->corridors[0].leftPainted) std::printf("%-10s left painted: %s\n", name, why.c_str());
        if (built->corridors[0].standing.empty() && built->corridors[0].rooms.empty()) {
          refused.push_back(name);
          hasObjects = false;
          break;
        }
      }
      scenes[m] = std::move(built->scene);
    }
    if (hasObjects) {
      ++withObjects;
      photoFlat.push_back(photoPsnr(renderer, scenes[0], flatShot));
      photoStanding.push_back(photoPsnr(renderer, scenes[1], standingShot));
      std::printf("%-10s %-7s | %6.2f dB        | %6.2f dB\n", name, "photo", photoFlat.back(), photoStanding.back());
    }
    for (const std::string& kind : pw::test::novelViewKinds()) {
      pw::test::NovelView view;
      try {
        view = pw::test::loadNovelView(dir, name, kind);
      } catch (const std::exception& e) {
        return fail(std::string(e.what()) + " (bench/standing_views.py renders it)");
      }
      ViewScores row[2];
      for (int m = 0; m < (hasObjects ? 2 : 1); ++m) {
        std::string error;
        const cv::Mat ours = pw::test::renderView(renderer, scenes[m], view, error);
        if (ours.empty()) return fail(error);
        row[m] = pw::test::scoreView(ours, view.truth);
        if (!saveDir.empty()) {
          cv::imwrite((saveDir / (std::string(name) + "_" + kind + (m ? "_standing" : "_flat") + ".png")).string(), ours);
          if (m == 0) cv::imwrite((saveDir / (std::string(name) + "_" + kind + "_povray.png")).string(), view.truth);
        }
      }
      flatAll[kind].push_back(row[0].psnrDb);
      std::printf("%-10s %-7s | %6.2f dB %5.3f", name, kind.c_str(), row[0].psnrDb, row[0].ssim);
      if (hasObjects) {
        flatWith[kind].push_back(row[0].psnrDb);
        standing[kind].push_back(row[1].psnrDb);
        better[kind] += row[1].psnrDb > row[0].psnrDb;
        std::printf(" | %6.2f dB %5.3f", row[1].psnrDb, row[1].ssim);
      }
      std::printf("\n");
    }
  }
  std::printf("\nmedian PSNR over %zu scenes (objects painted flat):", seeds.size());
  for (const std::string& kind : pw::test::novelViewKinds()) std::printf("  %s %.2f dB", kind.c_str(), pw::bench::median(flatAll[kind]));
  std::printf("\n");
  if (withObjects > 0) {
    std::printf("the %d scenes with objects stood up, median PSNR flat -> stood up (scenes better):\n", withObjects);
    for (const std::string& kind : pw::test::novelViewKinds()) {
      std::printf("  %-7s %.2f -> %.2f dB (%d of %d)\n", kind.c_str(), pw::bench::median(flatWith[kind]),
                  pw::bench::median(standing[kind]), better[kind], withObjects);
    }
    std::printf("  photo's camera: %.2f -> %.2f dB\n", pw::bench::median(photoFlat), pw::bench::median(photoStanding));
  }
  std::printf("objects left painted (the model could not stand them up): %zu; scenes with none stood up: %zu\n",
              leftPainted, refused.size());
  return 0;
}

int main(int argc, char** argv) {
  fs::path saveDir, randomDir;
  std::string only, seedText;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--save" && i + 1 < argc) {
      saveDir = argv[++i];
    } else if (a == "--only" && i + 1 < argc) {
      only = argv[++i];
    } else if (a == "--random" && i + 1 < argc) {
      randomDir = argv[++i];
    } else if (a == "--seeds" && i + 1 < argc) {
      seedText = argv[++i];
    } else {
      return fail("usage: novel_view_bench [--save DIR] [--only corridor_a,...] | --random DIR --seeds A-B[,C-D...]");
    }
  }
  if (!saveDir.empty()) fs::create_directories(saveDir);
  pw::engine::RendererOptions rendererOptions;
  rendererOptions.forceCpu = true;
  rendererOptions.validation = pw::engine::RendererOptions::Validation::kOff;
  auto renderer = pw::engine::Renderer::create(rendererOptions);
  if (!renderer) return fail(renderer.message());
  if (!randomDir.empty()) {
    if (seedText.empty()) return fail("--random needs --seeds A-B");
    return randomScenes(**renderer, randomDir, parseSeeds(seedText), saveDir);
  }

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
