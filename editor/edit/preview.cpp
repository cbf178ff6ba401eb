#include "editor/edit/preview.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <thread>

#include <glm/gtc/quaternion.hpp>

#include "editor/app/shell.h"
#include "editor/edit/document.h"

namespace pw::edit {
namespace {

using nlohmann::ordered_json;

// A quarter of a degree a pixel: a drag across a 400 px pane turns the model 100
// degrees, slowly enough to follow (it was 0.57 degrees a pixel).
constexpr float kOrbitRadPerPx = 0.0045f;
constexpr float kWheelFactor = 0.85f;            // one wheel step away from the user: 15% nearer
constexpr float kMaxElevationRad = 1.4835299f;   // 85 degrees
constexpr float kMinDistanceM = 0.1f;
// A light neutral sky: the model stands out against it (the near black it had read as a void).
const glm::vec3 kPaneBackground(0.62f, 0.66f, 0.72f);
constexpr float kFramedElevationRad = 0.5235988f;  // 30 degrees

}  // namespace

void orbitCamera(engine::Camera& camera, const glm::vec3& centre, float yawRad, float pitchRad) {
  const glm::vec3 forward = engine::forwardOf(camera);
  const float elevation = std::asin(std::clamp(forward.y, -1.0f, 1.0f));
  // Rising by pitchRad lowers the view's elevation by as much.
  pitchRad = std::clamp(pitchRad, elevation - kMaxElevationRad, elevation + kMaxElevationRad);
  const glm::vec3 right = glm::normalize(camera.orientation) * glm::vec3(1, 0, 0);
  const glm::quat turn = glm::angleAxis(yawRad, glm::vec3(0, 1, 0)) * glm::angleAxis(-pitchRad, right);
  camera.position = centre + turn * (camera.position - centre);
  // Level: the photo's roll (a camera held askew) is not kept once the model turns.
  const glm::vec3 turnedForward = turn * forward;
  camera.orientation = engine::lookAtOrientation(camera.position, camera.position + turnedForward);
}

engine::Camera framedCamera(const engine::Bounds& bounds, const engine::Camera& from) {
  engine::Camera camera = from;
  camera.intrinsics.reset();
  if (bounds.empty()) return camera;
  const glm::vec3 centre = bounds.center();
  glm::vec3 away = from.position - centre;
  away.y = 0;
  if (glm::length(away) < 1e-4f) away = -engine::forwardOf(from), away.y = 0;
  if (glm::length(away) < 1e-4f) away = glm::vec3(0, 0, 1);
  away = glm::normalize(away);
  const glm::vec3 direction =
      glm::normalize(std::cos(kFramedElevationRad) * away + glm::vec3(0, std::sin(kFramedElevationRad), 0));
  const float radius = 0.5f * glm::length(bounds.size());
  const float distance = 1.05f * radius / std::sin(0.5f * camera.fieldOfViewRad);
  // The bounding sphere's distance, then nearer until the box's corners span 85% of
  // a square frame (a long corridor is far smaller than its sphere).
  float d = distance;
  for (int iteration = 0; iteration < 4; ++iteration) {
    camera.position = centre + direction * d;
    camera.orientation = engine::lookAtOrientation(camera.position, centre);
    double span = 0;
    for (int k = 0; k < 8; ++k) {
      const glm::vec3 corner(k & 1 ? bounds.max.x : bounds.min.x, k & 2 ? bounds.max.y : bounds.min.y,
                             k & 4 ? bounds.max.z : bounds.min.z);
      const glm::dvec3 p = engine::projectToPixel(camera, 480, 480, corner);
      if (!(p.z > 0)) return camera;  // a corner behind: keep the sphere's distance
      span = std::max({span, std::abs(p.x - 240.0) / 240.0, std::abs(p.y - 240.0) / 240.0});
    }
    if (!(span > 0)) break;
    d = std::max(radius * 0.5f, d * static_cast<float>(span / 0.85));
  }
  camera.position = centre + direction * d;
  camera.orientation = engine::lookAtOrientation(camera.position, centre);
  camera.nearM = std::max(0.05f, 0.01f * d);
  return camera;
}

void dollyCamera(engine::Camera& camera, const glm::vec3& centre, float factor) {
  glm::vec3 fromCentre = camera.position - centre;
  float distance = glm::length(fromCentre);
  if (distance < 1e-4f) {
    fromCentre = -engine::forwardOf(camera);
    distance = 1.0f;
  }
  camera.position = centre + fromCentre / distance * std::max(kMinDistanceM, distance * factor);
}

Preview::Preview() = default;
Preview::~Preview() = default;

void Preview::setDocument(const cv::Mat& photo) {
  photo_ = photo;
  ++documentId_;
  askedShot_.reset();
  askedFull_ = false;
  followPhoto_ = true;
  orbit_.end();
  error_.clear();
}

void Preview::update(app::Shell& shell, const metrology::Shot& shot, const std::string& unmeasurable, bool dragging) {
  const auto now = std::chrono::steady_clock::now();
  frameIntervalMs_ = lastUpdate_ == std::chrono::steady_clock::time_point{}
                         ? 0.0
                         : std::chrono::duration<double, std::milli>(now - lastUpdate_).count();
  lastUpdate_ = now;
  poll(shell, shot);
  unmeasurable_ = unmeasurable;
  if (unmeasurable.empty()) ask(shot, dragging);
}

void Preview::poll(app::Shell& shell, const metrology::Shot& shot) {
  if (photo_.empty()) return;
  if (!builder_) builder_ = std::make_unique<PreviewBuilder>(shell.renderer());
  for (PreviewBuilder::Done& done : builder_->takeDone()) take(shell, std::move(done), shot);
}

void Preview::ask(const metrology::Shot& shot, bool dragging) {
  if (!builder_ || !shown_) return;
  const bool asked = askedShot_ && *askedShot_ == shot;
  PreviewBuilder::Request request{nextRequest_, documentId_, shot, photo_, false, false};
  if (dragging) {
    if (asked) return;
    request.reducedOnly = true;
  } else {
    if (fullAndCurrent(shot) || (asked && askedFull_)) return;
    // A shot changed at once (a nudge, an undo, a file opened) gets a reduced model
    // first; after a drag, the reduced model of its last step is there or on its way.
    request.reducedFirst = !asked;
  }
  ++nextRequest_;
  askedShot_ = shot;
  askedFull_ = !request.reducedOnly;
  builder_->request(std::move(request));
}

bool Preview::fullAndCurrent(const metrology::Shot& shot) const {
  return scene_ && builtShot_ && shownDocument_ == documentId_ && builtFrom_ == PreviewResolution::kFull &&
         *builtShot_ == shot;
}

Status Preview::waitForFull(app::Shell& shell, const metrology::Shot& shot, bool measurable, double timeoutS) {
  if (!shown_) return makeError("the 3D preview is hidden (P shows it)");
  if (!measurable) return makeError("the corners cannot be measured, so no model is built");
  if (photo_.empty()) return makeError("no photo is open");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutS);
  for (;;) {
    poll(shell, shot);
    ask(shot, false);
    if (fullAndCurrent(shot)) return {};
    if (!builder_->busy()) {
      poll(shell, shot);  // what finished between the two looks
      if (fullAndCurrent(shot)) return {};
      if (!error_.empty()) return makeError("no model: " + error_);
    }
    if (std::chrono::steady_clock::now() > deadline) {
      return makeError("the full model was not built within " + std::to_string(int(timeoutS)) + " s");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

std::shared_ptr<const engine::Scene> Preview::fullSceneOf(const metrology::Shot& shot) const {
  if (!builtScene_ || !fullAndCurrent(shot)) return nullptr;
  return builtScene_;
}

void Preview::take(app::Shell& shell, PreviewBuilder::Done done, const metrology::Shot& shot) {
  std::optional<ShownBuild> shown;
  if (scene_) shown = ShownBuild{shownDocument_, shownRequest_, builtFrom_};
  if (!takesPlaceOf(done, documentId_, shown, shot)) return;
  if (!done.model) {
    error_ = done.model.message();
    return;
  }
  PreviewModel& model = *done.model;
  if (Status shown = showStagedScene(shell.renderer(), scene_, std::move(model.staged)); !shown) {
    error_ = "the model cannot be shown: " + shown.message();
    return;
  }
  error_.clear();
  shownRequest_ = done.id;
  shownDocument_ = done.documentId;
  builtShot_ = std::move(done.shot);
  builtFrom_ = done.from;
  builtPhotoPx_ = model.photoSizePx;
  builtScene_ = model.scene;
  buildMs_ = model.buildMs;
  photoCamera_ = model.photoCamera;
  centre_ = model.bounds.empty() ? photoCamera_.position : model.bounds.center();
  bounds_ = model.bounds;
  if (followPhoto_) camera_ = photoCamera_;
}

void Preview::toPhotoCamera() {
  followPhoto_ = true;
  camera_ = photoCamera_;
}

Status showStagedScene(engine::Renderer& renderer, engine::SceneHandle& scene, engine::StagedScene staged) {
  if (scene) return renderer.replaceScene(scene, std::move(staged));
  auto added = renderer.addScene(std::move(staged));
  if (!added) return added.error();
  scene = *added;
  return {};
}

bool OrbitControl::onInput(const app::InputEvent& event, const WindowRect& rect, bool active, engine::Camera& camera,
                           const glm::vec3& centre, bool* moved) {
  const bool over = !rect.empty() && rect.contains(cursorPx_);
  return std::visit(app::Overloaded{[&](const app::CursorEvent& e) {
                                      cursorPx_ = e.positionPx;
                                      if (!from_) return false;
                                      const glm::dvec2 by = e.positionPx - *from_;
                                      from_ = e.positionPx;
                                      if (by == glm::dvec2(0.0)) return true;
                                      orbitCamera(camera, centre, -kOrbitRadPerPx * float(by.x), kOrbitRadPerPx * float(by.y));
                                      *moved = true;
                                      return true;
                                    },
                                    [&](const app::MouseButtonEvent& e) {
                                      if (e.button != GLFW_MOUSE_BUTTON_LEFT) return over && e.down && !from_;
                                      if (!e.down) {
                                        if (!from_) return false;
                                        from_.reset();
                                        return true;
                                      }
                                      if (!over) return false;
                                      if (active) from_ = cursorPx_;
                                      return true;
                                    },
                                    [&](const app::ScrollEvent& e) {
                                      if (!over) return false;
                                      if (active && e.offset.y != 0) {
                                        dollyCamera(camera, centre, std::pow(kWheelFactor, float(e.offset.y)));
                                        *moved = true;
                                      }
                                      return true;
                                    },
                                    [](const auto&) { return false; }},
                    event);
}

bool Preview::onInput(const app::InputEvent& event) {
  bool moved = false;
  const bool taken = orbit_.onInput(event, shown_ ? rect_ : WindowRect{}, scene_ && shownDocument_ == documentId_,
                                    camera_, centre_, &moved);
  if (moved && followPhoto_) {
    // The first turn away from the photo's camera: from outside, the whole model in view.
    camera_ = framedCamera(bounds_, camera_);
  }
  if (moved) followPhoto_ = false;
  return taken;
}

bool Preview::drawUi(const WindowRect& toolbar, bool showBox) {
  if (!shown_ || toolbar.empty()) return true;
  ImGui::SetNextWindowPos({float(toolbar.min.x), float(toolbar.min.y)}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({float(toolbar.size().x), float(toolbar.size().y)}, ImGuiCond_Always);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {4.0f, 4.0f});
  ImGui::Begin("##preview-toolbar", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoNav |
                   ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse);
  ImGui::PopStyleVar();
  bool keep = true;
  if (showBox) {
    ImGui::Checkbox("3D preview (P)", &keep);
    ImGui::SameLine();
  }
  const bool haveModel = scene_ && shownDocument_ == documentId_;
  ImGui::BeginDisabled(!haveModel);
  if (ImGui::Button("Photo camera")) toPhotoCamera();
  photoButton_ = {{ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y},
                  {ImGui::GetItemRectMax().x, ImGui::GetItemRectMax().y}};
  ImGui::EndDisabled();
  ImGui::SameLine();
  char status[96];
  const bool building = builder_ && builder_->busy();
  if (haveModel) {
    std::snprintf(status, sizeof status, "%s %dx%d%s", resolutionName(builtFrom_), builtPhotoPx_.x, builtPhotoPx_.y,
                  building ? " ..." : "");
  } else {
    std::snprintf(status, sizeof status, building ? "building..." : "no model yet");
  }
  ImGui::TextDisabled("%s", status);
  if (haveModel && ImGui::IsItemHovered()) {
    ImGui::SetTooltip("cut from the %s photo (%d x %d) in %.0f ms on the worker thread%s", resolutionName(builtFrom_),
                      builtPhotoPx_.x, builtPhotoPx_.y, buildMs_, building ? "; a newer model is being built" : "");
  }
  ImGui::End();

  // Why there is no model, or that the one shown is not the corners' as they are, in the pane.
  const bool stale = haveModel && askedShot_ && builtShot_ && *askedShot_ != *builtShot_;
  const std::string why = !error_.empty() ? "no model: " + error_
                          : !haveModel && !unmeasurable_.empty() ? "no model: " + unmeasurable_
                          : !haveModel    ? "the model is being built"
                          : stale         ? "out of date: the corners have moved; the new model is being built"
                                          : "";
  if (!why.empty() && !rect_.empty()) {
    ImDrawList* list = ImGui::GetBackgroundDrawList();
    const ImVec2 at(float(rect_.min.x) + 8, float(rect_.min.y) + 8);
    list->PushClipRect({float(rect_.min.x), float(rect_.min.y)}, {float(rect_.max.x), float(rect_.max.y)}, true);
    list->AddText(nullptr, 0.0f, at, IM_COL32(230, 200, 120, 255), why.c_str(), nullptr,
                  float(rect_.size().x) - 16);
    list->PopClipRect();
  }
  return keep;
}

std::optional<engine::SceneView> Preview::view() const {
  if (!shown_ || !scene_ || shownDocument_ != documentId_ || rect_.empty()) return std::nullopt;
  engine::SceneView view;
  view.scene = scene_;
  view.camera = camera_;
  view.rect = pixelRect(rect_);
  view.settings.backgroundColor = kPaneBackground;
  return view;
}

ordered_json Preview::trace(const metrology::Shot* shot) const {
  const bool haveModel = scene_ && shownDocument_ == documentId_ && builtShot_;
  const glm::dvec2 size = rect_.size();
  ordered_json row{{"shown", shown_},
                   {"built_from", haveModel ? ordered_json(resolutionName(builtFrom_)) : ordered_json(nullptr)},
                   {"current", haveModel && shot && *builtShot_ == *shot},
                   {"building", builder_ && builder_->busy()},
                   {"camera", followPhoto_ ? "photo" : "orbit"},
                   {"rect", ordered_json::array({rect_.min.x, rect_.min.y, size.x, size.y})}};
  row["photo_px"] = haveModel ? ordered_json::array({builtPhotoPx_.x, builtPhotoPx_.y}) : ordered_json(nullptr);
  row["build_ms"] = haveModel ? ordered_json(buildMs_) : ordered_json(nullptr);
  row["error"] = error_.empty() ? ordered_json(nullptr) : ordered_json(error_);
  row["frame_interval_ms"] = frameIntervalMs_;
  const glm::dvec2 button = photoButton_.size();
  row["photo_button"] = ordered_json::array({photoButton_.min.x, photoButton_.min.y, button.x, button.y});
  return row;
}

}  // namespace pw::edit
