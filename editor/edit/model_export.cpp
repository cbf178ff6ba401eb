#include "editor/edit/model_export.h"

#include "editor/edit/file_browser.h"
#include "engine/gltf/gltf_writer.h"
#include "base/atomic_file.h"
#include "engine/vrml/vrml_writer.h"
#include "modeling/tour.h"

#include <cstdio>

namespace pw::edit {
namespace fs = std::filesystem;

Status exportModel(const metrology::Shot& shot, const cv::Mat& photo, const metrology::Measurement& measurement,
                   const fs::path& out) {
  const std::string name = out.filename().string();
  const bool vrml = matchesEndings(name, {".wrl", ".wrl.gz", ".wrz"});
  const bool gltf = matchesEndings(name, {".glb", ".gltf"});
  const bool page = matchesEndings(name, {".html", ".htm"});
  if (!vrml && !gltf && !page) {
    return makeError(out.string() + ": export writes VRML97 (.wrl, .wrl.gz, .wrz), glTF 2.0 (.glb, .gltf) or a web page (.html)");
  }
  modeling::Layout layout;
  modeling::LayoutEntry entry;
  const std::string stem = fs::path(shot.imagePath).stem().string();
  entry.name = stem.empty() ? "corridor" : stem;
  entry.shot = shot.imagePath;
  layout.corridors.push_back(entry);
  std::vector<modeling::MeasuredShot> shots(1);
  shots[0].loaded.shot = shot;
  shots[0].loaded.image = photo;
  shots[0].measurement = measurement;
  auto model = modeling::buildModel(layout, shots, modeling::ModelOptions{});
  if (!model) return makeError("export: " + model.message());
  if (gltf) return engine::writeGltf(model->scene, out);
  if (page) {
    auto html = engine::webPageHtml(model->scene, webPageOptionsFor(model->scene, model->corridors));
    if (!html) return makeError(out.string() + ": " + html.message());
    return writeFileAtomic(out, *html);
  }
  return engine::writeVrml(model->scene, out);
}

engine::WebPageOptions webPageOptionsFor(const engine::Scene& scene, const std::vector<modeling::CorridorModel>& corridors) {
  engine::WebPageOptions options;
  for (const modeling::CorridorModel& corridor : corridors) {
    const auto& m = corridor.measurement;
    char line[256];
    std::snprintf(line, sizeof line, "%s: width %.2f ± %.2f m, height %.2f ± %.2f m, length %.2f ± %.2f m",
                  corridor.name.c_str(), m.size.widthM, m.sigma.widthM, m.size.heightM, m.sigma.heightM, m.size.lengthM,
                  m.sigma.lengthM);
    options.dimensions.push_back(line);
  }
  if (scene.tour.size() >= 2) {
    const std::vector<glm::dvec3> waypoints(scene.tour.begin(), scene.tour.end());
    const modeling::TourPath path(waypoints, modeling::TourOptions{});
    for (double t = 0; t < path.durationS() + options.tourStepS; t += options.tourStepS) {
      glm::dvec3 eye;
      double yaw = 0;
      path.sample(std::min(t, path.durationS()), eye, yaw);
      options.tourSamples.push_back({eye.x, eye.y, eye.z, yaw});
    }
  }
  return options;
}

}  // namespace pw::edit
