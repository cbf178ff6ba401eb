// The photo-to-model pipeline shared by build, render --camera-from and tour:
// shot file -> measurement -> textured corridor models -> building scene.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "base/result.h"
#include "editor/modeling/corridor_model.h"
#include "editor/modeling/layout.h"
#include "editor/shot_file.h"
#include "metrology/measure.h"

namespace pw::editor {

struct MeasuredShot {
  LoadedShot loaded;
  metrology::Measurement measurement;
};

// Reads the shot file and its photo and measures the corridor. Errors name the file.
Result<MeasuredShot> measureShotFile(const std::filesystem::path& path, const metrology::MeasureOptions& options = {});

struct BuiltModel {
  modeling::Layout layout;
  modeling::BuildingPlan plan;
  std::vector<modeling::CorridorModel> corridors;
  engine::Scene scene;
};

// Measures every corridor of the layout, cuts its textures, places it, opens the
// walls between corridors and assembles the scene. Nothing is written.
Result<BuiltModel> buildModel(const modeling::Layout& layout, const modeling::ModelOptions& options,
                              const metrology::MeasureOptions& measureOptions = {});

}  // namespace pw::editor
