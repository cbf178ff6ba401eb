#include "editor/edit/building_preview.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "editor/app/shell.h"
#include "editor/edit/building.h"
#include "editor/edit/document.h"
#include "editor/edit/plan.h"
#include "editor/edit/preview.h"
#include "editor/edit/preview_build.h"

namespace pw::edit {
namespace {

using nlohmann::ordered_json;

const glm::vec3 kPaneBackground(0.13f, 0.14f, 0.16f);

std::vector<metrology::Shot> shotsOf(const std::vector<modeling::MeasuredShot>& shots) {
  std::vector<metrology::Shot> out;
  for (const modeling::MeasuredShot& s : shots) out.push_back(s.loaded.shot);
  return out;
}

}  // namespace

engine::Camera overviewCamera(const engine::Bounds& bounds, double aspect, float fieldOfViewRad) {
  engine::Camera camera;
  camera.fieldOfViewRad = fieldOfViewRad;
  if (bounds.empty()) return camera;
  const glm::vec3 centre = bounds.center();
  const glm::vec3 from = glm::normalize(glm::vec3(0.8f, 0.75f, 0.3f));
  camera.orientation = engine::lookAtOrientation(centre + from, centre);
  const glm::vec3 right = camera.orientation * glm::vec3(1, 0, 0), up = camera.orientation * glm::vec3(0, 1, 0);
  // The field of view is across the smaller side of the pane.
  const float tanHalf = std::tan(0.5f * fieldOfViewRad);
  const float tanX = aspect >= 1 ? tanHalf * float(aspect) : tanHalf;
  const float tanY = aspect >= 1 ? tanHalf : tanHalf / float(std::max(aspect, 1e-3));
  // Each corner of the bounds inside the view: d >= its depth towards the camera plus
  // its offset over the tangent.
  float distance = 0.5f;
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 corner((k & 1) ? bounds.max.x : bounds.min.x, (k & 2) ? bounds.max.y : bounds.min.y,
                           (k & 4) ? bounds.max.z : bounds.min.z);
    const glm::vec3 q = corner - centre;
    distance = std::max(distance, glm::dot(q, from) + std::max(std::abs(glm::dot(q, right)) / tanX,
                                                                std::abs(glm::dot(q, up)) / tanY));
  }
  distance *= 1.08f;  // a margin
  camera.position = centre + from * distance;
  camera.nearM = std::max(0.05f, 0.01f * distance);
  camera.farM = 4.0f * distance + 100.0f;
  return camera;
}

BuildingPreview::BuildingPreview() = default;

BuildingPreview::~BuildingPreview() = default;

void BuildingPreview::update(app::Shell& shell) {
  if (!worker_) {
    const engine::Renderer* renderer = &shell.renderer();
    worker_ = std::make_unique<LatestWorker<Request, Done>>(
        [renderer](Request& request, const auto& emit, const auto&) { emit(build(*renderer, request)); });
  }
  for (Done& d : worker_->takeDone()) take(shell, std::move(d));
}

void BuildingPreview::ask(const modeling::Layout& layout, std::vector<modeling::MeasuredShot> shots, std::string title) {
  if (!worker_) return;
  std::vector<metrology::Shot> plain = shotsOf(shots);
  if (askedLayout_ && sameLayout(*askedLayout_, layout) && askedShots_ == plain) return;
  askedLayout_ = layout;
  askedShots_ = std::move(plain);
  worker_->request(Request{nextId_++, layout, std::move(shots), std::move(title)});
}

void BuildingPreview::cannotBuild(std::string why) {
  askedLayout_.reset();
  askedShots_.clear();
  error_ = std::move(why);
}

bool BuildingPreview::showsCurrent(const modeling::Layout& layout, const std::vector<modeling::MeasuredShot>& shots) const {
  return scene_ && error_.empty() && sameLayout(shownLayout_, layout) && shownShots_ == shotsOf(shots);
}

bool BuildingPreview::busy() const {
  return worker_ && (worker_->busy() || worker_->hasDone());
}

Status BuildingPreview::waitIdle(app::Shell& shell, double timeoutS) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutS);
  while (busy()) {
    update(shell);
    if (std::chrono::steady_clock::now() > deadline) {
      return makeError("the building's model was not built within " + std::to_string(int(timeoutS)) + " s");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  update(shell);
  return {};
}

BuildingPreview::Done BuildingPreview::build(const engine::Renderer& renderer, const Request& request) {
  const auto start = std::chrono::steady_clock::now();
  Done done{request.id, request.layout, shotsOf(request.shots), makeError("not built")};
  auto model = buildBuildingModel(request.layout, request.shots, previewModelOptions(PreviewResolution::kReduced),
                                  request.title);
  if (!model) {
    done.built = model.error();
  } else if (auto staged = renderer.stageScene(model->scene); !staged) {
    done.built = staged.error();
  } else {
    Built built{std::move(*staged), engine::sceneBounds(model->scene), 0.0};
    built.buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    done.built = std::move(built);
  }
  return done;
}

void BuildingPreview::take(app::Shell& shell, Done done) {
  if (done.id <= shownId_) return;
  if (!done.built) {
    error_ = done.built.message();
    return;
  }
  Built& built = *done.built;
  if (Status shown = showStagedScene(shell.renderer(), scene_, std::move(built.staged)); !shown) {
    error_ = "the model cannot be shown: " + shown.message();
    return;
  }
  error_.clear();
  shownId_ = done.id;
  shownLayout_ = std::move(done.layout);
  shownShots_ = std::move(done.shots);
  bounds_ = built.bounds;
  buildMs_ = built.buildMs;
  if (overview_) camera_ = overviewCamera(bounds_, rect_.empty() ? 1.0 : rect_.size().x / std::max(1.0, rect_.size().y));
}

bool BuildingPreview::onInput(const app::InputEvent& event) {
  bool moved = false;
  const glm::vec3 centre = bounds_.empty() ? glm::vec3(0.0f) : bounds_.center();
  const bool taken = orbit_.onInput(event, rect_, bool(scene_), camera_, centre, &moved);
  if (moved) overview_ = false;
  return taken;
}

void BuildingPreview::drawUi() const {
  if (rect_.empty()) return;
  char status[160];
  const bool building = busy();
  if (!error_.empty()) {
    std::snprintf(status, sizeof status, "no model: %s", error_.c_str());
  } else if (scene_) {
    std::snprintf(status, sizeof status, "the building, built in %.0f ms%s (drag: orbit)", buildMs_,
                  building ? "; building a newer one..." : "");
  } else {
    std::snprintf(status, sizeof status, "the building's model is being built...");
  }
  ImDrawList* list = ImGui::GetBackgroundDrawList();
  list->PushClipRect({float(rect_.min.x), float(rect_.min.y)}, {float(rect_.max.x), float(rect_.max.y)}, true);
  list->AddText(nullptr, 0.0f, {float(rect_.min.x) + 6, float(rect_.min.y) + 4},
                error_.empty() ? IM_COL32(220, 220, 230, 255) : IM_COL32(230, 200, 120, 255), status, nullptr,
                float(rect_.size().x) - 12);
  list->PopClipRect();
}

std::optional<engine::SceneView> BuildingPreview::view() const {
  if (!scene_ || rect_.empty()) return std::nullopt;
  engine::SceneView view;
  view.scene = scene_;
  view.camera = camera_;
  view.rect = pixelRect(rect_);
  view.settings.backgroundColor = kPaneBackground;
  return view;
}

ordered_json BuildingPreview::trace(bool current) const {
  const glm::dvec2 size = rect_.size();
  return ordered_json{{"model", bool(scene_)},
                      {"current", current},
                      {"building", busy()},
                      {"camera", overview_ ? "overview" : "orbit"},
                      {"rect", ordered_json::array({rect_.min.x, rect_.min.y, size.x, size.y})},
                      {"build_ms", scene_ ? ordered_json(buildMs_) : ordered_json(nullptr)},
                      {"error", error_.empty() ? ordered_json(nullptr) : ordered_json(error_)}};
}

}  // namespace pw::edit
