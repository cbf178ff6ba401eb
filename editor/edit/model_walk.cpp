#include "editor/edit/model_walk.h"

#include <imgui.h>

#include <filesystem>

#include "editor/app/shell.h"
#include "editor/edit/document.h"
#include "modeling/corridor_model.h"
#include "modeling/layout.h"

namespace pw::edit {

Result<engine::Scene> buildCorridorScene(const metrology::Shot& shot, const cv::Mat& photo,
                                         const metrology::Measurement& measurement,
                                         const modeling::ModelOptions& options) {
  const std::string name = std::filesystem::path(shot.imagePath).stem().string();
  auto corridor =
      modeling::makeCorridorModel(name.empty() ? "corridor" : name, photo, measurement, shot.cutouts, false, options);
  if (!corridor) return corridor.error();
  modeling::Layout layout;
  modeling::LayoutEntry entry;
  entry.name = corridor->name;
  entry.shot = shot.imagePath;
  layout.corridors.push_back(entry);
  auto plan = modeling::planBuilding(layout, {corridor->box});
  if (!plan) return plan.error();
  std::vector<modeling::CorridorModel> corridors;
  corridors.push_back(std::move(*corridor));
  engine::Scene scene = modeling::makeBuildingScene(corridors, *plan, options);
  scene.title = corridors.front().name;
  return scene;
}

ModelWalk::ModelWalk(std::string backTo, std::function<void(app::TraceRow&)> extraTrace)
    : backTo_(backTo), editorMode_(std::move(backTo)), extraTrace_(std::move(extraTrace)) {}

ModelWalk::~ModelWalk() = default;

void ModelWalk::release(app::Shell& shell) {
  if (walk_ && walk_->sceneHandle()) (void)shell.renderer().removeScene(walk_->sceneHandle());
  walk_.reset();
  scene_.reset();
  shot_.reset();
}

Status ModelWalk::show(app::Shell& shell, const metrology::Shot& shot, const cv::Mat& photo,
                       const metrology::Measurement& measurement, std::shared_ptr<const engine::Scene> built) {
  if (walks(shot)) return {};  // walk on where it was left
  if (built) {
    PW_TRY(showScene(shell, *built, editorMode_));  // a copy: the textures are shared
  } else {
    auto scene = buildCorridorScene(shot, photo, measurement);
    if (!scene) return scene.error();
    PW_TRY(showScene(shell, std::move(*scene), editorMode_));
  }
  shot_ = shot;
  return {};
}

Status ModelWalk::showScene(app::Shell& shell, engine::Scene scene, std::string backTo) {
  auto owned = std::make_unique<engine::Scene>(std::move(scene));
  walk::WalkModeOptions options;
  options.escapeTo = backTo;
  auto walk = std::make_unique<walk::WalkMode>(*owned, options);
  PW_TRY(walk->open(shell));  // uploads the scene
  release(shell);
  scene_ = std::move(owned);
  walk_ = std::move(walk);
  backTo_ = std::move(backTo);
  return {};
}

void ModelWalk::onEnter(app::Shell& shell) {
  if (!walk_) {
    shell.showMessage("walk: no model yet: press W in the editor once the corners measure");
    shell.requestMode(backTo_);
    return;
  }
  walk_->onEnter(shell);
}

void ModelWalk::onLeave(app::Shell& shell) {
  if (walk_) walk_->onLeave(shell);
}

void ModelWalk::onInput(app::Shell& shell, const app::InputEvent& event) {
  if (walk_) walk_->onInput(shell, event);
}

Status ModelWalk::onReplayEvent(app::Shell& shell, const app::ModeEvent& event) {
  if (!walk_) return AppMode::onReplayEvent(shell, event);
  return walk_->onReplayEvent(shell, event);
}

void ModelWalk::update(app::Shell& shell, double stepS) {
  if (walk_) walk_->update(shell, stepS);
}

void ModelWalk::traceRow(app::TraceRow& row) const {
  if (walk_) walk_->traceRow(row);
  if (extraTrace_) extraTrace_(row);
}

void ModelWalk::drawUi(app::Shell& shell) {
  if (!walk_) return;
  walk_->drawUi(shell);
  // What brings the editor back, where a person looks for it.
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos({viewport->WorkPos.x + viewport->WorkSize.x - 10, viewport->WorkPos.y + 10}, ImGuiCond_Always,
                          {1.0f, 0.0f});
  ImGui::SetNextWindowBgAlpha(0.6f);
  ImGui::Begin("##back-to-editor", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
  if (ImGui::Button("Back to the editor (Esc)")) shell.requestMode(backTo_);
  ImGui::End();
}

app::FrameContent ModelWalk::frame(app::Shell& shell) {
  if (!walk_) return {};
  return walk_->frame(shell);
}

std::optional<Result<engine::Image>> ModelWalk::capture(app::Shell& shell, int width, int height) {
  if (!walk_) return std::nullopt;
  return walk_->capture(shell, width, height);
}

}  // namespace pw::edit
