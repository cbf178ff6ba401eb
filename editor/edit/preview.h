// The editor's 3D preview pane: the corridor model of the corners as they are, drawn
// by the engine (a SceneView in a window rectangle, under ImGui) from an orbit camera,
// rebuilt as the corners move. While a corner is dragged the model is cut from a
// reduced photo (preview_build.h, about 1024 px), once let go from the full photo;
// both are built and staged on a worker thread (PreviewBuilder), and the frame only
// swaps a finished model in (Renderer::replaceScene), so no frame waits for a build.
// A result is shown only when it is newer than the one shown and of the document
// open; a full-resolution result for a shot that has changed since is dropped.
//
// Mouse over the pane: left drag orbits about the model's centre, the wheel moves
// nearer or farther; the "Photo camera" button puts the camera back at the photo's
// (the model's Photo viewpoint), which it then follows as the model is rebuilt.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>
#include <opencv2/core/mat.hpp>

#include "editor/app/app_mode.h"
#include "editor/edit/canvas.h"
#include "editor/edit/preview_build.h"
#include "engine/gpu/view.h"
#include "engine/scene/camera.h"
#include "metrology/shot.h"

namespace pw::edit {

// Turns `camera` about `centre` (world): `yawRad` about the world's +Y, then `pitchRad`
// about the camera's right axis (positive: the camera rises and looks down), its
// orientation turning with it, so that `centre` stays where it is in the picture. The
// pitch is limited so that the camera never looks more than 85 degrees up or down.
void orbitCamera(engine::Camera& camera, const glm::vec3& centre, float yawRad, float pitchRad);
// Moves `camera` towards `centre` (factor < 1) or away from it, keeping its
// orientation; it stays at least 0.1 m from the centre.
void dollyCamera(engine::Camera& camera, const glm::vec3& centre, float factor);
// A level camera (no roll) looking at the middle of `bounds` from outside it, from the
// side `from` stands on, 30 degrees above it, as near as shows all of it in its field of
// view: where an orbit starts from when it leaves the photo's camera (inside the model,
// a turn would look at a wall from behind).
engine::Camera framedCamera(const engine::Bounds& bounds, const engine::Camera& from);

// A pane's camera moved by the mouse about a centre: left drag over the pane orbits
// (orbitCamera), the wheel over it moves nearer or farther (dollyCamera). The shot
// editor's preview and building mode's share it.
class OrbitControl {
 public:
  // Input for a pane at `rect` (empty: not shown); true when it was the pane's.
  // `active`: there is a model to move about. `*moved`: set when the camera moved.
  bool onInput(const app::InputEvent& event, const WindowRect& rect, bool active, engine::Camera& camera,
               const glm::vec3& centre, bool* moved);
  bool orbiting() const { return from_.has_value(); }
  void end() { from_.reset(); }

 private:
  glm::dvec2 cursorPx_{-1.0};
  std::optional<glm::dvec2> from_;
};

// Puts `staged` on the GPU as `*scene`: replaced when there is one (frames in flight
// keep the old), else added. Errors: the renderer's, with the scene left as it was.
Status showStagedScene(engine::Renderer& renderer, engine::SceneHandle& scene, engine::StagedScene staged);

class Preview {
 public:
  Preview();
  ~Preview();  // the worker finishes its build first

  bool shown() const { return shown_; }
  void setShown(bool shown) {
    shown_ = shown;
    endOrbit();
  }
  // Lets go of an orbit in progress (the editor left for the walk, the pane hidden).
  void endOrbit() { orbit_.end(); }

  // A new document: its photo (BGR, shared, never written); what was shown is of
  // the old one until the new one's first model arrives.
  void setDocument(const cv::Mat& photo);
  // The pane's rectangle in the window (window pixels); empty: not laid out.
  void setRect(const WindowRect& rect) { rect_ = rect; }
  const WindowRect& rect() const { return rect_; }

  // Once a step: takes finished models (swaps them in), and asks for a build when the
  // shot differs from the one built or asked for. `unmeasurable`: empty when the
  // corners measure, else why not (nothing is asked, and the pane says why while it
  // has no model). `dragging`: a corner is being dragged (reduced builds).
  void update(app::Shell& shell, const metrology::Shot& shot, const std::string& unmeasurable, bool dragging);
  // Blocks until the full-resolution model of `shot` is shown (replay's
  // `preview-wait`, for tests that capture it; never in a person's session). Errors:
  // hidden, not measurable, the build failing, `timeoutS` passing.
  Status waitForFull(app::Shell& shell, const metrology::Shot& shot, bool measurable, double timeoutS);

  // Input for the pane; true when it was the pane's (an orbit, the wheel over it).
  bool onInput(const app::InputEvent& event);
  bool orbiting() const { return orbit_.orbiting(); }

  // The pane's toolbar (over the top of `toolbar`) and its status text. With
  // `showBox`, it starts with the "3D preview (P)" box, ticked: false when it was
  // unticked this frame (the caller hides the pane and lays the window out again).
  bool drawUi(const WindowRect& toolbar, bool showBox = false);
  // The scene view to draw, when there is a model and the pane is shown.
  std::optional<engine::SceneView> view() const;

  // The trace's "preview" field (README "The editor's test interface").
  nlohmann::ordered_json trace(const metrology::Shot* shot) const;

  void toPhotoCamera();

  // The model shown, when it is of the full photo and of `shot` as it is (the walk's
  // model, already built); null otherwise.
  std::shared_ptr<const engine::Scene> fullSceneOf(const metrology::Shot& shot) const;

 private:
  void poll(app::Shell& shell, const metrology::Shot& shot);  // takes what the worker finished
  void ask(const metrology::Shot& shot, bool dragging);        // a build, when the shot needs one
  void take(app::Shell& shell, PreviewBuilder::Done done, const metrology::Shot& shot);
  bool fullAndCurrent(const metrology::Shot& shot) const;

  bool shown_ = true;
  WindowRect rect_;
  std::unique_ptr<PreviewBuilder> builder_;  // made with the first document (it needs the renderer)
  cv::Mat photo_;
  uint64_t documentId_ = 0;
  uint64_t nextRequest_ = 1;

  // What was asked last, for the document open.
  std::optional<metrology::Shot> askedShot_;
  bool askedFull_ = false;

  // What is shown.
  engine::SceneHandle scene_;
  uint64_t shownRequest_ = 0;
  uint64_t shownDocument_ = 0;
  std::optional<metrology::Shot> builtShot_;
  PreviewResolution builtFrom_ = PreviewResolution::kFull;
  glm::ivec2 builtPhotoPx_{0};
  std::shared_ptr<const engine::Scene> builtScene_;
  double buildMs_ = 0;
  std::string error_;  // why the last build failed (the last model stays)
  std::string unmeasurable_;  // why the corners do not measure now (update's)
  engine::Camera photoCamera_;
  glm::vec3 centre_{0.0f};
  engine::Bounds bounds_;

  engine::Camera camera_;
  bool followPhoto_ = true;  // the camera is the photo's until the pane is orbited or zoomed
  OrbitControl orbit_;

  std::chrono::steady_clock::time_point lastUpdate_{};
  double frameIntervalMs_ = 0;  // wall clock between the last two steps
  WindowRect photoButton_;      // the toolbar's "Photo camera" button as last drawn (the trace's)
};

}  // namespace pw::edit
