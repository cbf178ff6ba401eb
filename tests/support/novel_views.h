// Views from cameras a photo was not taken from (issue 14): the ground truth's novel
// views (tests/groundtruth/make_corridors.py `views`: POV-Ray renders of each scene from
// inside the corridor) and the scores a model's frame from the same camera gets against
// them. Shared by bench/novel_view_bench.cpp (the table) and
// tests/pipeline/novel_view_test.cpp (the floor under it).
#pragma once

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "engine/gpu/renderer.h"
#include "engine/scene/camera.h"

namespace pw::test {

// The kinds make_corridors.py renders: mid-corridor looking ahead; a quarter in, turned
// 35 degrees to the left wall; near the far wall, looking back towards the camera.
inline const std::vector<std::string>& novelViewKinds() {
  static const std::vector<std::string> kinds = {"ahead", "turned", "back"};
  return kinds;
}

struct NovelView {
  std::string scene, kind;
  engine::Camera camera;  // in the scene's model frame (corridor_frame.h), with intrinsics
  cv::Mat truth;          // POV-Ray's frame, BGR
};

// worldFromCamera = Ry(yaw) Rx(pitch) Rz(roll), as make_corridors.py places cameras.
inline glm::quat orientationFromYawPitchRoll(double yawDeg, double pitchDeg, double rollDeg) {
  const glm::dquat q = glm::angleAxis(glm::radians(yawDeg), glm::dvec3(0, 1, 0)) *
                       glm::angleAxis(glm::radians(pitchDeg), glm::dvec3(1, 0, 0)) *
                       glm::angleAxis(glm::radians(rollDeg), glm::dvec3(0, 0, 1));
  return glm::quat(q);
}

// Throws std::runtime_error when the view's files are not there (the build renders
// them: target groundtruth).
inline NovelView loadNovelView(const std::filesystem::path& dir, const std::string& scene, const std::string& kind) {
  const std::filesystem::path base = dir / (scene + "_view_" + kind);
  std::ifstream in(base.string() + ".json");
  if (!in) throw std::runtime_error("no " + base.string() + ".json (the build renders it: target groundtruth)");
  const nlohmann::json j = nlohmann::json::parse(in);
  NovelView view{scene, kind, {}, cv::imread(base.string() + ".png", cv::IMREAD_COLOR)};
  if (view.truth.empty()) throw std::runtime_error("cannot read " + base.string() + ".png");
  const int width = j.at("image_size")[0], height = j.at("image_size")[1];
  const double focal = j.at("focal_px");
  view.camera.position = glm::vec3(j.at("eye_m")[0], j.at("eye_m")[1], j.at("eye_m")[2]);
  view.camera.orientation = orientationFromYawPitchRoll(j.at("yaw_deg"), j.at("pitch_deg"), j.at("roll_deg"));
  view.camera.intrinsics = engine::Intrinsics{focal, focal, j.at("principal_point")[0], j.at("principal_point")[1],
                                              width, height};
  view.camera.fieldOfViewRad = engine::fieldOfViewOf(*view.camera.intrinsics);
  return view;
}

struct ViewScores {
  double psnrDb = 0;
  double ssim = 0;
  double highFrequencyRatio = 0;  // mean |Laplacian| of ours over the truth's: 1 as detailed, < 1 blurred
};

inline cv::Mat grayFloat(const cv::Mat& bgr) {
  cv::Mat gray, out;
  cv::cvtColor(bgr, gray, cv::COLOR_BGR2GRAY);
  gray.convertTo(out, CV_32F);
  return out;
}

// Mean SSIM (Wang et al. 2004: 11x11 Gaussian window, sigma 1.5, K1 0.01, K2 0.03) of
// two grey images, 0..255.
inline double meanSsim(const cv::Mat& a, const cv::Mat& b) {
  const double c1 = std::pow(0.01 * 255, 2), c2 = std::pow(0.03 * 255, 2);
  const auto blur = [](const cv::Mat& m) {
    cv::Mat out;
    cv::GaussianBlur(m, out, {11, 11}, 1.5);
    return out;
  };
  const cv::Mat muA = blur(a), muB = blur(b);
  const cv::Mat muA2 = muA.mul(muA), muB2 = muB.mul(muB), muAB = muA.mul(muB);
  const cv::Mat varA = blur(a.mul(a)) - muA2, varB = blur(b.mul(b)) - muB2, cov = blur(a.mul(b)) - muAB;
  cv::Mat num = (2 * muAB + c1).mul(2 * cov + c2), den = (muA2 + muB2 + c1).mul(varA + varB + c2), ssim;
  cv::divide(num, den, ssim);
  return cv::mean(ssim)[0];
}

inline double meanAbsLaplacian(const cv::Mat& gray) {
  cv::Mat lap;
  cv::Laplacian(gray, lap, CV_32F);
  return cv::mean(cv::abs(lap))[0];
}

// Scores of `ours` (BGR, 8 bit) against `truth` over the whole frame.
inline ViewScores scoreView(const cv::Mat& ours, const cv::Mat& truth) {
  if (ours.size() != truth.size() || ours.type() != truth.type()) throw std::runtime_error("frames differ in size");
  ViewScores s;
  const double mse = cv::norm(ours, truth, cv::NORM_L2SQR) / double(ours.total() * ours.channels());
  s.psnrDb = mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : 99.0;
  const cv::Mat a = grayFloat(ours), b = grayFloat(truth);
  s.ssim = meanSsim(a, b);
  const double truthEnergy = meanAbsLaplacian(b);
  s.highFrequencyRatio = truthEnergy > 0 ? meanAbsLaplacian(a) / truthEnergy : 0.0;
  return s;
}

// `scene` drawn from the view's camera at the truth's size, BGR; empty on failure,
// with `error` set.
inline cv::Mat renderView(engine::Renderer& renderer, const engine::Scene& scene, const NovelView& view,
                          std::string& error) {
  if (auto s = renderer.setScene(scene); !s) return error = s.message(), cv::Mat();
  auto frame = renderer.renderToImage(view.camera, view.truth.cols, view.truth.rows);
  if (!frame) return error = frame.message(), cv::Mat();
  cv::Mat rgba(frame->height, frame->width, CV_8UC4, frame->rgba.data()), bgr;
  cv::cvtColor(rgba, bgr, cv::COLOR_RGBA2BGR);
  return bgr;
}

}  // namespace pw::test
