// The walkthrough as a mode of the app shell (editor/app): a person walking through a
// scene (avatar.h) at the shell's fixed step, with the viewpoints (PageUp/PageDown,
// Home: a half-second glide), the headlight (H), screenshots (F12), an overlay (Tab)
// and the keys (F1). README "The walkthrough" lists the keys.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include <GLFW/glfw3.h>

#include "editor/app/app_mode.h"
#include "editor/walk/avatar.h"
#include "engine/gpu/view.h"
#include "engine/scene/collision.h"
#include "engine/scene/scene.h"

namespace pw::walk {

struct WalkModeOptions {
  double speedScale = 1.0;                     // times the NavigationInfo speed
  std::filesystem::path screenshotDir = ".";  // F12
  bool showOverlay = true;
  // Esc with the cursor free: switch to this mode (the editor), or, when empty, quit
  // (not while a replay plays: scripts end with `quit`).
  std::string escapeTo;
};

class WalkMode : public app::AppMode {
 public:
  // The walk starts at the scene's first viewpoint (else a default one). `scene` is
  // borrowed and must outlive the mode.
  WalkMode(const engine::Scene& scene, const WalkModeOptions& options);

  std::string_view name() const override { return "walk"; }
  Status open(app::Shell& shell) override;  // uploads the scene (Renderer::addScene)
  void onLeave(app::Shell& shell) override;
  void onInput(app::Shell& shell, const app::InputEvent& event) override;
  Status onReplayEvent(app::Shell& shell, const app::ModeEvent& event) override;  // viewpoint N
  void update(app::Shell& shell, double stepS) override;
  void traceRow(app::TraceRow& row) const override;  // x, y, z, yaw_deg, pitch_deg
  void drawUi(app::Shell& shell) override;
  app::FrameContent frame(app::Shell& shell) override;
  // Rendered offscreen from the walk's camera: the scene without the overlay.
  std::optional<Result<engine::Image>> capture(app::Shell& shell, int width, int height) override;

  // The camera the walk draws with now (mid-glide between viewpoints too).
  engine::Camera currentCamera() const;
  int viewpoint() const { return viewpoint_; }  // from 0
  // The scene uploaded by open(), for an owner that replaces the walk to remove.
  engine::SceneHandle sceneHandle() const { return sceneHandle_; }

 private:
  struct Transition {
    engine::Camera from, to;
    int frame = 0;
    int viewpoint = 0;
  };

  void onKey(app::Shell& shell, int key, bool down);
  void goToViewpoint(int index);
  void takeScreenshot(app::Shell& shell);
  void releaseCursor(app::Shell& shell);
  engine::SceneView view() const;  // the scene from currentCamera(), over the whole frame

  const engine::Scene& scene_;
  engine::SceneHandle sceneHandle_;
  WalkModeOptions options_;
  engine::CollisionWorld world_;
  Avatar avatar_;
  bool headlight_;
  bool showOverlay_;
  bool showHelp_ = false;
  std::string boundsLine_;  // the model's size, for the overlay

  std::array<bool, GLFW_KEY_LAST + 1> keys_{};
  double mouseDx_ = 0, mouseDy_ = 0;
  std::optional<glm::dvec2> lastCursor_;
  bool captured_ = false;
  int viewpoint_ = 0;
  std::optional<Transition> transition_;
  int screenshotCount_ = 0;
};

}  // namespace pw::walk
