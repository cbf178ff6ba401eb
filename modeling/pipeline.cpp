#include "modeling/pipeline.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <opencv2/imgproc.hpp>

#include "metrology/distortion.h"
#include "metrology/input_sigma.h"

#include "modeling/tour.h"

namespace pw::modeling {

Result<MeasuredShot> measureShotFile(const std::filesystem::path& path, const metrology::MeasureOptions& options) {
  auto loaded = loadShot(path);
  if (!loaded) return loaded.error();
  // The ± of every input by where it came from (metrology/input_sigma.h), as measure's.
  metrology::InputOrigins origins;
  origins.focal = metrology::focalOriginOf(loaded->focalSource);
  auto measurement = metrology::measureCorridor(loaded->shot, metrology::withInputSigmas(options, loaded->shot, origins));
  if (!measurement) return makeError(path.string() + ": " + measurement.message());
  return MeasuredShot{std::move(*loaded), std::move(*measurement)};
}

Result<engine::Camera> shotCamera(const std::filesystem::path& path, metrology::Intrinsics* lens) {
  auto measured = measureShotFile(path);
  if (!measured) return measured.error();
  const cv::Mat& photo = measured->loaded.image;
  if (lens) *lens = measured->measurement.camera;
  return photoCamera(measured->measurement, photo.cols, photo.rows, glm::dmat4(1.0));
}

LensFrame lensFrame(const engine::Camera& photoCamera, const metrology::Intrinsics& lens, int photoWidth,
                    int photoHeight) {
  // The pinhole pixels of the photo's outline bound what the lens shows.
  glm::dvec2 lo(0.0), hi(photoWidth - 1.0, photoHeight - 1.0);
  constexpr int kSteps = 64;
  for (int i = 0; i <= kSteps; ++i) {
    const double u = (photoWidth - 1.0) * i / kSteps, v = (photoHeight - 1.0) * i / kSteps;
    for (const glm::dvec2 p : {glm::dvec2(u, 0), glm::dvec2(u, photoHeight - 1.0), glm::dvec2(0, v),
                               glm::dvec2(photoWidth - 1.0, v)}) {
      if (const std::optional<glm::dvec2> q = metrology::undistortPixel(lens, p)) {
        lo = glm::min(lo, *q);
        hi = glm::max(hi, *q);
      }
    }
  }
  LensFrame frame;
  // Whole photo pixels, two to spare for the filter.
  frame.offsetPx = glm::ceil(-lo) + 2.0;
  const int s = frame.supersample;
  frame.width = s * (static_cast<int>(std::ceil(hi.x + frame.offsetPx.x)) + 3);
  frame.height = s * (static_cast<int>(std::ceil(hi.y + frame.offsetPx.y)) + 3);
  // Photo pixel p (offset) is frame pixel s p + (s - 1) / 2: pixel centres at integers.
  frame.camera = photoCamera;
  engine::Intrinsics k = *photoCamera.intrinsics;
  k.focalXPx *= s;
  k.focalYPx *= s;
  k.principalU = s * (k.principalU + frame.offsetPx.x) + 0.5 * (s - 1);
  k.principalV = s * (k.principalV + frame.offsetPx.y) + 0.5 * (s - 1);
  k.imageWidth = frame.width;
  k.imageHeight = frame.height;
  frame.camera.intrinsics = k;
  frame.camera.supersample = static_cast<float>(s);
  return frame;
}

engine::Image distortFrame(const engine::Image& pinhole, const LensFrame& frame, const metrology::Intrinsics& lens,
                           int photoWidth, int photoHeight) {
  // The lens at the frame's resolution: s times the focal length, its principal point.
  const int s = frame.supersample;
  metrology::Intrinsics fine = lens;
  fine.focalPx *= s;
  fine.principalPointPx = static_cast<double>(s) * lens.principalPointPx + 0.5 * (s - 1);
  cv::Mat mapX, mapY, samples;
  metrology::distortionMaps(fine, cv::Size(s * photoWidth, s * photoHeight), static_cast<double>(s) * frame.offsetPx, mapX,
                            mapY);
  const cv::Mat source(pinhole.height, pinhole.width, CV_8UC4, const_cast<uint8_t*>(pinhole.rgba.data()));
  cv::remap(source, samples, mapX, mapY, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(0, 0, 0, 255));
  engine::Image out = engine::makeImage(photoWidth, photoHeight);
  cv::Mat target(photoHeight, photoWidth, CV_8UC4, out.rgba.data());
  cv::resize(samples, target, target.size(), 0, 0, cv::INTER_AREA);
  return out;
}

Result<BuiltModel> buildModel(const modeling::Layout& layout, const modeling::ModelOptions& options,
                              const metrology::MeasureOptions& measureOptions) {
  std::vector<MeasuredShot> shots;
  for (const modeling::LayoutEntry& entry : layout.corridors) {
    auto measured = measureShotFile(entry.shot, measureOptions);
    if (!measured) return measured.error();
    shots.push_back(std::move(*measured));
  }
  return buildModel(layout, shots, options);
}

Result<BuiltModel> buildModel(const Layout& layout, const std::vector<MeasuredShot>& shots,
                                      const ModelOptions& options) {
  if (shots.size() != layout.corridors.size() || shots.empty()) {
    return makeError("the model needs one measured shot per corridor (" + std::to_string(layout.corridors.size()) +
                     " corridors, " + std::to_string(shots.size()) + " shots)");
  }
  BuiltModel model;
  model.layout = layout;
  std::vector<metrology::Dimensions> boxes;
  for (size_t i = 0; i < layout.corridors.size(); ++i) {
    const modeling::LayoutEntry& entry = layout.corridors[i];
    const MeasuredShot& measured = shots[i];
    model.warnings.insert(model.warnings.end(), measured.loaded.warnings.begin(), measured.loaded.warnings.end());
    if (auto large = metrology::implausibleSize(measured.loaded.shot, measured.measurement)) {
      model.warnings.push_back(entry.name + ": " + *large);
    }
    auto corridor = modeling::makeCorridorModel(entry.name, measured.loaded.image, measured.measurement,
                                                measured.loaded.shot.cutouts, entry.attach.has_value(), options);
    if (!corridor) return corridor.error();
    boxes.push_back(corridor->box);
    model.corridors.push_back(std::move(*corridor));
  }
  auto plan = modeling::planBuilding(layout, boxes);
  if (!plan) return plan.error();
  model.plan = std::move(*plan);
  model.scene = modeling::makeBuildingScene(model.corridors, model.plan, options);

  // The model carries its own tour, so that `photowalk tour MODEL.wrl` can walk it.
  const modeling::CorridorModel& first = model.corridors.front();
  modeling::TourOptions tour;
  tour.eyeHeightM = first.measurement.cameraHeightM;
  tour.startZ = std::max(0.0, std::min(first.measurement.pose.positionM.z, first.untexturedNearM - 0.5));
  for (const glm::dvec3& p : modeling::tourWaypoints(model.layout, boxes, model.plan, tour)) {
    model.scene.tour.emplace_back(p);
  }
  return model;
}

}  // namespace pw::modeling
