// The editor's Walk: the walkthrough (editor/walk) of the model the editor's shot makes
// now, built in memory (no file written), as the shell's mode "walk". Each switch to it
// with changed corners builds the model anew and walks it from its Photo viewpoint;
// Esc (with the cursor free) goes back to the editor (WalkModeOptions::escapeTo).
#pragma once

#include <functional>
#include <memory>
#include <optional>

#include <opencv2/core/mat.hpp>

#include "editor/app/app_mode.h"
#include "editor/walk/walk_mode.h"
#include "engine/scene/scene.h"
#include "metrology/measure.h"
#include "metrology/shot.h"
#include "modeling/corridor_model.h"

namespace pw::edit {

// The one corridor of `shot` as a scene: modeling's corridor model (textures cut from
// `photo`, BGR), placed at the origin as `build` places a first corridor. `options`:
// the texture budget (the preview's reduced model asks for less).
Result<engine::Scene> buildCorridorScene(const metrology::Shot& shot, const cv::Mat& photo,
                                         const metrology::Measurement& measurement,
                                         const modeling::ModelOptions& options = {});

class ModelWalk : public app::AppMode {
 public:
  // `backTo`: the mode Esc returns to. `extraTrace` adds fields to each trace row (the
  // editor's document), after the walk's own.
  ModelWalk(std::string backTo, std::function<void(app::TraceRow&)> extraTrace);
  ~ModelWalk() override;  // the scene on the GPU goes with the renderer

  // Makes the model of `shot` the one walked: builds it (unless it is the shot walked
  // last) and uploads it, starting at its Photo viewpoint. Errors: the model cannot be
  // built (the message says why), the upload failing; the last model then stays.
  // `built`: the model of `shot` already built (the 3D preview's full one), walked
  // instead of building it again.
  Status show(app::Shell& shell, const metrology::Shot& shot, const cv::Mat& photo,
              const metrology::Measurement& measurement, std::shared_ptr<const engine::Scene> built = nullptr);
  // Makes `scene` (a whole building: modeling::buildModel) the one walked, from its
  // first viewpoint; Esc then goes back to the mode `backTo`. Errors: the upload.
  Status showScene(app::Shell& shell, engine::Scene scene, std::string backTo);
  bool hasModel() const { return walk_ != nullptr; }
  // Whether `shot`'s model is the one walked (show() then only goes back to it).
  bool walks(const metrology::Shot& shot) const { return walk_ && shot_ && *shot_ == shot && backTo_ == editorMode_; }

  std::string_view name() const override { return "walk"; }
  void onEnter(app::Shell& shell) override;
  void onLeave(app::Shell& shell) override;
  void onInput(app::Shell& shell, const app::InputEvent& event) override;
  Status onReplayEvent(app::Shell& shell, const app::ModeEvent& event) override;
  void update(app::Shell& shell, double stepS) override;
  void traceRow(app::TraceRow& row) const override;
  void drawUi(app::Shell& shell) override;
  app::FrameContent frame(app::Shell& shell) override;
  std::optional<Result<engine::Image>> capture(app::Shell& shell, int width, int height) override;

 private:
  void release(app::Shell& shell);

  std::string backTo_;
  std::string editorMode_;  // the mode that walks a shot (the constructor's backTo)
  std::function<void(app::TraceRow&)> extraTrace_;
  // The walk borrows the scene: declared after it, so destroyed first.
  std::unique_ptr<engine::Scene> scene_;
  std::unique_ptr<walk::WalkMode> walk_;
  std::optional<metrology::Shot> shot_;  // the shot the model was built from
};

}  // namespace pw::edit
