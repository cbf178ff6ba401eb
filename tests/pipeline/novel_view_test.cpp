// Views from cameras the photo was not taken from (issue 14), against POV-Ray's frames
// of the same scene from the same cameras (tests/groundtruth: three per scene). Each
// model is built from the scene's exact corners. bench/novel_view_bench prints the
// whole table; this test keeps the floor under it:
//  - `build`'s model (what the photo did not see synthesized, the corridor closed
//    behind the camera, detail added where the photo saw coarsely) and `build
//    --no-detail`'s are nowhere worse than `build --photo-only`'s by more than 0.5 dB,
//    and looking back `build`'s is better in every scene by at least 1.5 dB (the void
//    behind the camera is gone), each scene's back view holds its measured figure less
//    1 dB, and their median the 27 dB;
//  - mid-corridor, `build`'s medians hold the targets: 30 dB, SSIM 0.88, a
//    high-frequency ratio from 0.7 to 1.3 (photo-only: 28.4 dB, 0.82, 0.25), and the
//    ratio is 0.15 more than `--no-detail`'s.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "engine/gpu/renderer.h"
#include "modeling/pipeline.h"
#include "tests/support/groundtruth.h"
#include "tests/support/novel_views.h"

namespace pw::modeling {
namespace {

// Measured 2026-12-02 on lavapipe (bench/novel_view_bench): the back view's PSNR of
// `build`'s model, dB.
const std::map<std::string, double> kBackPsnrDb = {
    {"corridor_a", 24.81}, {"corridor_b", 36.35}, {"corridor_c", 30.98}, {"corridor_d", 23.70},
    {"corridor_e", 23.90}, {"corridor_f", 29.82}, {"corridor_g", 30.70}, {"corridor_h", 33.56},
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

TEST(NovelViews, SynthesisClosesTheCorridorAndNeverCostsAView) {
  engine::RendererOptions options;
  options.forceCpu = true;
  options.validation = engine::RendererOptions::Validation::kOn;
  auto renderer = engine::Renderer::create(options);
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  std::vector<double> detailAhead, noDetailAhead, backPsnr, psnrAhead, ssimAhead;
  for (const std::string& name : groundtruth::groundTruthNames()) {
    SCOPED_TRACE(name);
    const auto shot = groundtruth::groundTruthShot(name);
    engine::Scene scenes[3];
    for (int m = 0; m < 3; ++m) {
      ModelOptions model;
      model.photoOnly = m == 0;
      model.detail = m == 1;
      auto built = buildModel(chainLayout({shot}), model);
      ASSERT_TRUE(built.ok()) << built.message();
      scenes[m] = std::move(built->scene);
    }
    for (const std::string& kind : test::novelViewKinds()) {
      const test::NovelView view = test::loadNovelView(PW_GROUNDTRUTH_DIR, name, kind);
      test::ViewScores scores[3];
      for (int m = 0; m < 3; ++m) {
        std::string error;
        const cv::Mat frame = test::renderView(**renderer, scenes[m], view, error);
        ASSERT_FALSE(frame.empty()) << error;
        scores[m] = test::scoreView(frame, view.truth);
      }
      std::printf("[novel view] %s %-6s PSNR photo-only %.2f, build %.2f, --no-detail %.2f dB; HF %.2f %.2f %.2f\n",
                  name.c_str(), kind.c_str(), scores[0].psnrDb, scores[1].psnrDb, scores[2].psnrDb,
                  scores[0].highFrequencyRatio, scores[1].highFrequencyRatio, scores[2].highFrequencyRatio);
      EXPECT_GE(scores[1].psnrDb, scores[0].psnrDb - 0.5) << kind;
      EXPECT_GE(scores[2].psnrDb, scores[0].psnrDb - 0.5) << kind << " with --no-detail";
      if (kind == "back") {
        EXPECT_GE(scores[1].psnrDb, scores[0].psnrDb + 1.5) << "looking back, the closed corridor";
        EXPECT_GE(scores[1].psnrDb, kBackPsnrDb.at(name) - 1.0);
        backPsnr.push_back(scores[1].psnrDb);
      }
      if (kind == "ahead") psnrAhead.push_back(scores[1].psnrDb), ssimAhead.push_back(scores[1].ssim);
      if (kind == "ahead") detailAhead.push_back(scores[1].highFrequencyRatio), noDetailAhead.push_back(scores[2].highFrequencyRatio);
    }
  }
  EXPECT_GE(median(psnrAhead), 30.0) << "mid-corridor PSNR, the issue's target";
  EXPECT_GE(median(ssimAhead), 0.88) << "mid-corridor SSIM, the issue's target";
  EXPECT_GE(median(detailAhead), 0.7) << "mid-corridor high-frequency energy, the issue's target";
  EXPECT_LE(median(detailAhead), 1.3);
  EXPECT_GE(median(backPsnr), 27.0) << "looking back, the issue's target";
  EXPECT_GT(median(detailAhead), median(noDetailAhead) + 0.15);
  EXPECT_EQ((*renderer)->validationMessageCount(), 0u);
}

}  // namespace
}  // namespace pw::modeling
