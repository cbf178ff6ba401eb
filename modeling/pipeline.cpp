#include "modeling/pipeline.h"

#include <algorithm>

#include "modeling/tour.h"

namespace pw::modeling {

Result<MeasuredShot> measureShotFile(const std::filesystem::path& path, const metrology::MeasureOptions& options) {
  auto loaded = loadShot(path);
  if (!loaded) return loaded.error();
  auto measurement = metrology::measureCorridor(loaded->shot, options);
  if (!measurement) return makeError(path.string() + ": " + measurement.message());
  return MeasuredShot{std::move(*loaded), std::move(*measurement)};
}

Result<engine::Camera> shotCamera(const std::filesystem::path& path) {
  auto measured = measureShotFile(path);
  if (!measured) return measured.error();
  const cv::Mat& photo = measured->loaded.image;
  return photoCamera(measured->measurement, photo.cols, photo.rows, glm::dmat4(1.0));
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
    auto corridor = modeling::makeCorridorModel(entry.name, measured.loaded.image, measured.measurement,
                                                entry.attach.has_value(), options);
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
