// The photo-to-model pipeline shared by build, render --camera-from and tour:
// shot file -> measurement -> textured corridor models -> building scene.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "base/result.h"
#include "modeling/corridor_model.h"
#include "modeling/layout.h"
#include "modeling/shot_file.h"
#include "metrology/measure.h"

namespace pw::modeling {

struct MeasuredShot {
  LoadedShot loaded;
  metrology::Measurement measurement;
};

// Reads the shot file and its photo and measures the corridor, its ± carrying the
// focal length by where it came from, the principal point and the distortion
// (metrology/input_sigma.h) beside `options`' corners and camera height. Errors name the file.
Result<MeasuredShot> measureShotFile(const std::filesystem::path& path, const metrology::MeasureOptions& options = {});

// The camera that took the shot's photo, measured, placed as `build` places a first
// corridor (photoCamera): the model's "Photo" viewpoint when it is built from this shot.
// Its intrinsics are for the photo's size; `lens` (may be null) receives the measured
// lens, its distortion included (none for a pinhole photo).
Result<engine::Camera> shotCamera(const std::filesystem::path& path, metrology::Intrinsics* lens = nullptr);

// A photo's frame through a distorting lens, drawn by a pinhole renderer: the pinhole
// frame to render (`camera`, photoCamera's at `supersample` times the photo's
// resolution with the principal point moved by `offsetPx` photo pixels, in a `width` x
// `height` frame large enough for everything the lens squeezes into the photo), then
// distortFrame takes it through the lens. Supersampled, each photo pixel averages
// supersample² lens samples instead of resampling the frame once more (the ground
// truth through k1 -0.2, PSNR against the photo: 39.4 instead of 36.8 dB for
// corridor_h, 34.9 instead of 32.7 for f, 37.9 instead of 38.7 for a's bricks).
struct LensFrame {
  engine::Camera camera;
  glm::dvec2 offsetPx{0.0};
  int width = 0, height = 0;
  int supersample = 2;
};
LensFrame lensFrame(const engine::Camera& photoCamera, const metrology::Intrinsics& lens, int photoWidth,
                    int photoHeight);
// The pinhole frame rendered for `frame` as the lens shows it, photoWidth x photoHeight
// (bilinear samples, averaged; a pixel the lens does not reach is black).
engine::Image distortFrame(const engine::Image& pinhole, const LensFrame& frame, const metrology::Intrinsics& lens,
                           int photoWidth, int photoHeight);

struct BuiltModel {
  Layout layout;
  BuildingPlan plan;
  std::vector<CorridorModel> corridors;
  engine::Scene scene;
  // What to check before trusting the model, for the caller to show: what the photos'
  // decoder warned of (LoadedShot::warnings), a corridor larger than any interior
  // (metrology::implausibleSize).
  std::vector<std::string> warnings;
};

// Measures every corridor of the layout, cuts its textures, places it, opens the
// walls between corridors and assembles the scene. Nothing is written.
Result<BuiltModel> buildModel(const Layout& layout, const ModelOptions& options,
                              const metrology::MeasureOptions& measureOptions = {});
// The same from shots already measured, one per corridor of the layout, in its order
// (the editor's shots as they are, saved or not: its export, its building's walk).
// Errors: a count that does not match, and the first buildModel's.
Result<BuiltModel> buildModel(const Layout& layout, const std::vector<MeasuredShot>& shots,
                              const ModelOptions& options);

}  // namespace pw::modeling
