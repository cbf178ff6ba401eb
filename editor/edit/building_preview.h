// Building mode's 3D preview pane: the whole building's model (Building::buildModel's,
// what W walks, with the editor preview's reduced texture budget) drawn by the engine
// in a window rectangle under ImGui, seen from above at an angle. Each plan edit, once
// released (never during a drag), asks for a new model; one worker thread builds and
// stages it (a request waiting is replaced by a newer one), and the frame only swaps a
// finished model in (Renderer::replaceScene), so no frame waits for a build. Left drag
// over the pane orbits about the building's centre, the wheel moves nearer or farther.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/result.h"
#include "editor/app/app_mode.h"
#include "editor/edit/canvas.h"
#include "editor/edit/latest_worker.h"
#include "editor/edit/preview.h"
#include "engine/gpu/renderer.h"
#include "engine/gpu/view.h"
#include "engine/scene/camera.h"
#include "modeling/layout.h"
#include "modeling/pipeline.h"

namespace pw::edit {

// A camera that sees all of `bounds` from above at an angle (from the right of the
// corridors, which run along -z, a little behind their near ends), for a
// view `aspect` (width / height) wide with `fieldOfViewRad` across its smaller side.
engine::Camera overviewCamera(const engine::Bounds& bounds, double aspect,
                              float fieldOfViewRad = engine::kDefaultFieldOfViewRad);

class BuildingPreview {
 public:
  BuildingPreview();
  ~BuildingPreview();  // the worker finishes its build first

  void setRect(const WindowRect& rect) { rect_ = rect; }
  const WindowRect& rect() const { return rect_; }

  // Once a step: takes a finished model (swaps it in). Then either ask() for the
  // building as it is now (it builds only when that differs from what was asked
  // last), or cannotBuild() with why it cannot be built.
  void update(app::Shell& shell);
  void ask(const modeling::Layout& layout, std::vector<modeling::MeasuredShot> shots, std::string title);
  void cannotBuild(std::string why);
  // The model shown is of `layout` with these shots (the building as it is now).
  bool showsCurrent(const modeling::Layout& layout, const std::vector<modeling::MeasuredShot>& shots) const;
  bool busy() const;
  // Blocks until no build is waiting or running and what finished is swapped in
  // (replay's `preview-wait`; never in a person's session). Errors: `timeoutS` passing.
  Status waitIdle(app::Shell& shell, double timeoutS);

  // Input for the pane; true when it was the pane's (an orbit, the wheel over it).
  bool onInput(const app::InputEvent& event);
  void endOrbit() { orbit_.end(); }

  void drawUi() const;  // the pane's status line, over it
  std::optional<engine::SceneView> view() const;
  // The trace's "preview" field; `current`: showsCurrent() for the building as it is.
  nlohmann::ordered_json trace(bool current) const;

 private:
  struct Request {
    uint64_t id = 0;
    modeling::Layout layout;
    std::vector<modeling::MeasuredShot> shots;
    std::string title;
  };
  struct Built {
    engine::StagedScene staged;
    engine::Bounds bounds;
    double buildMs = 0;
  };
  struct Done {
    uint64_t id = 0;
    modeling::Layout layout;
    std::vector<metrology::Shot> shots;
    Result<Built> built = makeError("not built");
  };
  static Done build(const engine::Renderer& renderer, const Request& request);  // the worker's
  void take(app::Shell& shell, Done done);

  WindowRect rect_;
  // Made with the first update (it needs the renderer).
  std::unique_ptr<LatestWorker<Request, Done>> worker_;

  uint64_t nextId_ = 1;
  std::optional<modeling::Layout> askedLayout_;
  std::vector<metrology::Shot> askedShots_;

  engine::SceneHandle scene_;
  uint64_t shownId_ = 0;
  modeling::Layout shownLayout_;
  std::vector<metrology::Shot> shownShots_;
  engine::Bounds bounds_;
  double buildMs_ = 0;
  std::string error_;  // why the last build failed or none can be asked (the last model stays)

  engine::Camera camera_;
  bool overview_ = true;  // the camera is the overview until the pane is orbited or zoomed
  OrbitControl orbit_;
};

}  // namespace pw::edit
