#include "editor/edit/model_export.h"

#include "editor/edit/file_browser.h"
#include "engine/gltf/gltf_writer.h"
#include "engine/vrml/vrml_writer.h"
#include "modeling/pipeline.h"

namespace pw::edit {
namespace fs = std::filesystem;

Status exportModel(const metrology::Shot& shot, const cv::Mat& photo, const metrology::Measurement& measurement,
                   const fs::path& out) {
  const std::string name = out.filename().string();
  const bool vrml = matchesEndings(name, {".wrl", ".wrl.gz", ".wrz"});
  const bool gltf = matchesEndings(name, {".glb", ".gltf"});
  if (!vrml && !gltf) {
    return makeError(out.string() + ": export writes VRML97 (.wrl, .wrl.gz, .wrz) or glTF 2.0 (.glb, .gltf)");
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
  return engine::writeVrml(model->scene, out);
}

}  // namespace pw::edit
