#include "editor/edit/building_mode.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "editor/app/shell.h"
#include "editor/edit/edit_mode.h"
#include "editor/edit/model_walk.h"

namespace pw::edit {
namespace fs = std::filesystem;
using app::Overloaded;
using modeling::Layout;
using nlohmann::ordered_json;

namespace {

constexpr double kWheelFactor = 1.25;
constexpr double kMinScale = 2, kMaxScale = 2000;  // window pixels per metre
constexpr double kSnapPx = 24;                     // snapping reaches this far on screen...
constexpr double kMinSnapM = 0.1, kMaxSnapM = 2.0;  // ...within these bounds
constexpr double kDragStartPx = 3;                  // a press that moves less is a click
constexpr double kTurnHandlePx = 22;                // the turn handle beyond the far wall
constexpr double kGrabRadiusPx = 9;
constexpr double kTurnStepDeg = 15;                 // Shift while turning

const char* sideName(modeling::Side side) {
  return side == modeling::Side::kFar ? "far" : side == modeling::Side::kLeft ? "left" : "right";
}

ordered_json attachJson(const Layout& layout, const modeling::Attachment& a) {
  const std::string to = a.to >= 0 && size_t(a.to) < layout.corridors.size() ? layout.corridors[a.to].name : "";
  return ordered_json{{"to", to}, {"side", sideName(a.side)}, {"offset_m", a.offsetM}};
}

// The angle of the corridor direction pointing from its near end towards `v` (plan).
double headingDeg(const glm::dvec2& v) { return glm::degrees(std::atan2(-v.x, -v.y)); }

}  // namespace

BuildingMode::BuildingMode(EditMode& editor, ModelWalk& walk, std::optional<fs::path> layout)
    : editor_(editor), walk_(walk), file_(std::move(layout)) {}

Status BuildingMode::open(app::Shell& shell) {
  if (file_) openLayout(shell, *file_);
  return {};
}

bool BuildingMode::dirty() const {
  if (!building_) return false;
  const Document* lent = lentShot();
  return building_->dirty() || (lent && lent->dirty());
}

void BuildingMode::openLayout(app::Shell& shell, const fs::path& path) {
  auto building = Building::open(path);
  if (!building) {
    openError_ = building.message();
    shell.showMessage("error: " + openError_);
    return;
  }
  if (editor_.document()) (void)editor_.takeDocument(shell);  // the caller asked about its changes
  building_ = std::move(*building);
  openError_.clear();
  selected_.clear();
  drag_.reset();
  editor_.setPlanMode(kName);
  for (size_t i = 0; i < building_->layout().corridors.size(); ++i) {
    const std::string problem = building_->problem(int(i));
    if (!problem.empty()) shell.showMessage("warning: corridor \"" + building_->layout().corridors[i].name + "\": " + problem);
  }
  boxes_ = building_->boxes();
  world_ = placeCorridors(building_->layout(), boxes_);
  viewTouched_ = false;
  layOut(shell);
  fit();
}

Document* BuildingMode::lentShot() {
  if (!building_ || !building_->lent()) return nullptr;
  Document* doc = editor_.document();
  return doc && doc->path() == *building_->lent() ? doc : nullptr;
}

const Document* BuildingMode::lentShot() const {
  if (!building_ || !building_->lent()) return nullptr;
  const Document* doc = editor_.document();
  return doc && doc->path() == *building_->lent() ? doc : nullptr;
}

void BuildingMode::reconcileLent(app::Shell& shell) {
  // The editor may have opened another file over the lent shot (a drop, after asking):
  // the shot comes back from its file.
  if (!building_ || !building_->lent() || lentShot()) return;
  const fs::path path = *building_->lent();
  auto doc = Document::open(path);
  if (!doc) {
    shell.showMessage("error: " + doc.message());
    return;
  }
  building_->giveBack(path, std::move(*doc));
  shell.showMessage("note: " + path.filename().string() + " was closed in the editor; read again from its file");
}

void BuildingMode::layOut(app::Shell& shell) {
  const glm::ivec2 size = shell.window().framebufferSize();
  const bool resized = size != windowSize_;
  windowSize_ = size;
  const double width = windowSize_.x;
  panelWidthPx_ = std::floor(std::min(std::clamp(0.3 * width, 260.0, 380.0), 0.6 * width));
  planArea_ = {{0.0, 0.0}, {std::max(1.0, width - panelWidthPx_), std::max(1.0, double(windowSize_.y))}};
  // The 3D preview: the lower part of the panel's column.
  const double height = windowSize_.y;
  const double paneHeight = building_ ? std::floor(std::min(0.75 * panelWidthPx_, 0.4 * height)) : 0.0;
  panelHeightPx_ = std::max(0.0, height - paneHeight);
  preview_.setRect(paneHeight > 0 ? WindowRect{{width - panelWidthPx_, height - paneHeight}, {width, height}} : WindowRect{});
  if (resized && !viewTouched_) fit();
}

void BuildingMode::fit() {
  std::vector<glm::dvec2> points;
  for (size_t i = 0; i < world_.size() && i < boxes_.size(); ++i) {
    for (const glm::dvec2& p : footprintCorners(world_[i], boxes_[i])) points.push_back(p);
  }
  view_ = fitPlan(points, planArea_.min, planArea_.max);
}

void BuildingMode::zoomAbout(const glm::dvec2& anchor, double steps) {
  const double scale = std::clamp(view_.scale * std::pow(kWheelFactor, steps), kMinScale, kMaxScale);
  view_.offset = anchor - (anchor - view_.offset) * (scale / view_.scale);
  view_.scale = scale;
  viewTouched_ = true;
}

void BuildingMode::onEnter(app::Shell& shell) {
  keys_.fill(false);
  reconcileLent(shell);
  layOut(shell);
}

void BuildingMode::onLeave(app::Shell&) {
  if (drag_) endDrag(true);
  preview_.endOrbit();
  panFrom_.reset();
  keys_.fill(false);
}

bool BuildingMode::overPlan(const glm::dvec2& p) const {
  if (!planArea_.contains(p)) return false;
  return std::none_of(uiRects_.begin(), uiRects_.end(), [&](const WindowRect& r) { return r.contains(p); });
}

int BuildingMode::selectedIndex() const {
  if (!building_ || selected_.empty()) return -1;
  const auto& corridors = building_->layout().corridors;
  for (size_t i = 0; i < corridors.size(); ++i) {
    if (corridors[i].name == selected_) return int(i);
  }
  return -1;
}

double BuildingMode::snapDistanceM() const { return std::clamp(kSnapPx / view_.scale, kMinSnapM, kMaxSnapM); }

std::optional<glm::dvec2> BuildingMode::turnHandle(int i) const {
  if (i < 0 || size_t(i) >= world_.size() || size_t(i) >= boxes_.size()) return std::nullopt;
  const glm::dvec4 ahead = world_[i] * glm::dvec4(0, 0, -boxes_[i].lengthM - kTurnHandlePx / view_.scale, 1);
  return view_.toWindow({ahead.x, ahead.z});
}

void BuildingMode::onInput(app::Shell& shell, const app::InputEvent& event) {
  layOut(shell);
  if (!question_ && !drag_ && !panFrom_ && preview_.onInput(event)) {  // an orbit or the wheel over the 3D preview
    if (const auto* cursor = std::get_if<app::CursorEvent>(&event)) cursorPx_ = cursor->positionPx;
    return;
  }
  std::visit(Overloaded{[&](const app::KeyEvent& e) { onKey(shell, e); },
                        [&](const app::MouseButtonEvent& e) { onButton(e); },
                        [&](const app::CursorEvent& e) { onCursor(e.positionPx); },
                        [&](const app::ScrollEvent& e) {
                          if (building_ && !question_ && overPlan(cursorPx_) && e.offset.y != 0) zoomAbout(cursorPx_, e.offset.y);
                        },
                        [&](const app::DropEvent& e) {
                          if (!question_) onDrop(shell, e);
                        },
                        [](const auto&) {}},
             event);
}

void BuildingMode::onKey(app::Shell& shell, const app::KeyEvent& e) {
  if (e.key < 0 || e.key > GLFW_KEY_LAST) return;
  keys_[e.key] = e.down;
  if (!e.down) return;
  if (onQuestionKey(shell, e)) return;
  if (ImGui::GetCurrentContext() && ImGui::GetIO().WantTextInput) return;  // typing into a panel's field
  if (!building_) return;
  const bool ctrl = ctrlHeld() || (e.mods & GLFW_MOD_CONTROL);
  const bool shift = shiftHeld() || (e.mods & GLFW_MOD_SHIFT);
  if (ctrl) {
    if (e.key == GLFW_KEY_Z) shift ? redo(shell) : undo(shell);
    else if (e.key == GLFW_KEY_Y) redo(shell);
    else if (e.key == GLFW_KEY_S) save(shell);
    return;
  }
  switch (e.key) {
    case GLFW_KEY_R: turnSelected(shift ? -90.0 : 90.0); break;
    case GLFW_KEY_F: fit(); viewTouched_ = false; break;
    case GLFW_KEY_W: walk(shell); break;
    case GLFW_KEY_E:
    case GLFW_KEY_ENTER:
      if (selectedIndex() >= 0) editShot(shell, selectedIndex());
      break;
    case GLFW_KEY_TAB: {
      const int n = int(building_->layout().corridors.size());
      const int next = selectedIndex() < 0 ? 0 : (selectedIndex() + (shift ? n - 1 : 1)) % n;
      selected_ = building_->layout().corridors[next].name;
      break;
    }
    case GLFW_KEY_DELETE:
      removeSelected(shell);
      break;
    case GLFW_KEY_ESCAPE:
      if (drag_) endDrag(false);
      break;
    default: break;
  }
}

void BuildingMode::removeSelected(app::Shell& shell) {
  const int i = selectedIndex();
  if (!building_ || i < 0 || drag_) return;
  if (building_->layout().corridors.size() < 2) {
    shell.showMessage("the building's last corridor stays: a layout has one at least");
    return;
  }
  applyLayout(removeCorridor(building_->layout(), world_, i), "remove " + selected_);
  shell.showMessage("removed \"" + selected_ + "\" from the layout (Ctrl+Z brings it back; its shot file stays)");
  selected_.clear();
}

void BuildingMode::onButton(const app::MouseButtonEvent& e) {
  if (!e.down) {
    if (drag_ && e.button == GLFW_MOUSE_BUTTON_LEFT) endDrag(true);
    if (panFrom_ && e.button == panButton_) panFrom_.reset();
    return;
  }
  if (!building_ || drag_ || panFrom_ || question_ || !overPlan(cursorPx_)) return;
  if (e.button == GLFW_MOUSE_BUTTON_MIDDLE || e.button == GLFW_MOUSE_BUTTON_RIGHT) {
    panFrom_ = cursorPx_;
    panButton_ = e.button;
    return;
  }
  if (e.button != GLFW_MOUSE_BUTTON_LEFT) return;
  Drag drag;
  drag.before = building_->layout();
  drag.pressPlan = view_.toPlan(cursorPx_);
  drag.pressWindowPx = cursorPx_;
  const int selected = selectedIndex();
  const std::optional<glm::dvec2> handle = turnHandle(selected);
  if (handle && glm::length(*handle - cursorPx_) <= kGrabRadiusPx) {
    drag.kind = Drag::Kind::kTurn;
    drag.indexBefore = selected;
  } else {
    drag.kind = Drag::Kind::kMove;
    drag.indexBefore = corridorAt(world_, boxes_, drag.pressPlan);
  }
  if (drag.indexBefore < 0) {
    selected_.clear();
    return;
  }
  drag.name = drag.before.corridors[drag.indexBefore].name;
  drag.poseBefore = poseOf(world_[drag.indexBefore]);
  selected_ = drag.name;
  drag_ = std::move(drag);
}

void BuildingMode::onCursor(const glm::dvec2& p) {
  cursorPx_ = p;
  if (panFrom_) {
    view_.offset += p - *panFrom_;
    panFrom_ = p;
    viewTouched_ = true;
  }
  if (drag_) dragTo(p);
}

void BuildingMode::dragTo(const glm::dvec2& p) {
  if (!building_ || !drag_) return;
  Drag& d = *drag_;
  if (!d.moved && glm::length(p - d.pressWindowPx) < kDragStartPx) return;
  d.moved = true;
  const glm::dvec2 at = view_.toPlan(p);
  Layout live;
  d.snap.reset();
  if (d.kind == Drag::Kind::kTurn) {
    double turn = headingDeg(at - d.poseBefore.nearCentre) - headingDeg(d.pressPlan - d.poseBefore.nearCentre);
    double rotation = d.poseBefore.rotationDeg + turn;
    if (shiftHeld()) rotation = kTurnStepDeg * std::round(rotation / kTurnStepDeg);
    live = placeCorridor(d.before, d.indexBefore, {d.poseBefore.nearCentre, rotation});
  } else {
    const PlanPose pose{d.poseBefore.nearCentre + (at - d.pressPlan), d.poseBefore.rotationDeg};
    const std::vector<metrology::Dimensions> boxes = building_->boxesFor(d.before);
    if (!altHeld()) {
      d.snap = findSnap(d.before, boxes, placeCorridors(d.before, boxes), d.indexBefore, pose, snapDistanceM());
    }
    live = d.snap ? attachCorridor(d.before, d.indexBefore, d.snap->attach, nullptr)
                  : placeCorridor(d.before, d.indexBefore, pose);
  }
  building_->setLive(live);
  boxes_ = building_->boxes();
  world_ = placeCorridors(building_->layout(), boxes_);
}

void BuildingMode::endDrag(bool keep) {
  if (!drag_ || !building_) return;
  if (keep && drag_->moved) {
    std::string label = (drag_->kind == Drag::Kind::kTurn ? "turn " : "move ") + drag_->name;
    if (drag_->snap) {
      label = "attach " + drag_->name + " to " + drag_->before.corridors[drag_->snap->attach.to].name + " " +
              sideName(drag_->snap->attach.side);
    }
    building_->commitLive(drag_->before, label);
  } else {
    building_->setLive(drag_->before);
  }
  drag_.reset();
  boxes_ = building_->boxes();
  world_ = placeCorridors(building_->layout(), boxes_);
}

void BuildingMode::applyLayout(const Layout& after, const std::string& label) {
  if (!building_) return;
  if (drag_) endDrag(true);
  building_->apply(after, label);
  boxes_ = building_->boxes();
  world_ = placeCorridors(building_->layout(), boxes_);
}

void BuildingMode::turnSelected(double deltaDeg) {
  const int i = selectedIndex();
  if (!building_ || i < 0 || drag_) return;
  applyLayout(rotateCorridor(building_->layout(), world_, i, deltaDeg), "turn " + selected_);
}

void BuildingMode::undo(app::Shell& shell) {
  if (!building_ || drag_) return;
  if (!building_->undo()) shell.showMessage("nothing to undo in the plan");
}

void BuildingMode::redo(app::Shell& shell) {
  if (!building_ || drag_) return;
  if (!building_->redo()) shell.showMessage("nothing to redo in the plan");
}

void BuildingMode::save(app::Shell& shell) {
  if (!building_) return;
  if (drag_) endDrag(true);
  if (Status saved = building_->save(lentShot()); !saved) {
    shell.showMessage("error: not saved: " + saved.message());
    return;
  }
  shell.showMessage("saved " + building_->path().string() + " and its shots");
}

void BuildingMode::walk(app::Shell& shell) {
  if (!building_) return;
  if (drag_) endDrag(true);
  building_->remeasure(lentShot());
  auto model = building_->buildModel(lentShot());
  if (!model) {
    shell.showMessage("walk: no model: " + model.message());
    return;
  }
  for (const std::string& warning : planWarnings_) shell.showMessage("warning: " + warning);
  if (Status shown = walk_.showScene(shell, std::move(model->scene), kName); !shown) {
    shell.showMessage("walk: no model: " + shown.message());
    return;
  }
  shell.requestMode("walk");
}

void BuildingMode::editShot(app::Shell& shell, int corridor) {
  if (!building_ || corridor < 0 || size_t(corridor) >= building_->layout().corridors.size()) return;
  if (drag_) endDrag(true);
  const fs::path path = building_->layout().corridors[corridor].shot;
  if (building_->lent() != path) {
    if (!building_->shot(path)) {
      shell.showMessage("error: corridor \"" + building_->layout().corridors[corridor].name +
                        "\": " + building_->problem(corridor));
      return;
    }
    if (building_->lent()) {
      std::optional<Document> back = editor_.takeDocument(shell);
      if (back) building_->giveBack(*building_->lent(), std::move(*back));
    } else if (editor_.document() && editor_.document()->dirty()) {
      shell.showMessage("unsaved changes in " + editor_.document()->path().string() +
                        ": save them in the editor (Ctrl+S) before editing a shot of the building");
      return;
    }
    std::optional<Document> doc = building_->lend(path);
    if (!doc) return;
    editor_.showDocument(shell, std::move(*doc));
  }
  shell.requestMode("edit");
}

void BuildingMode::addShot(app::Shell& shell, const fs::path& given) {
  if (!building_) return;
  fs::path path = given;
  std::error_code ec;
  if (path.is_relative() && !fs::exists(path, ec)) path = building_->path().parent_path() / given;
  if (drag_) endDrag(true);
  auto added = building_->addShot(path);
  if (!added) {
    shell.showMessage("error: not added: " + added.message());
    return;
  }
  boxes_ = building_->boxes();
  world_ = placeCorridors(building_->layout(), boxes_);
  selected_ = building_->layout().corridors[*added].name;
  shell.showMessage("added \"" + selected_ + "\" (" + building_->layout().corridors[*added].shot.string() + ")");
}

void BuildingMode::onDrop(app::Shell& shell, const app::DropEvent& e) {
  for (const fs::path& path : e.paths) {
    if (!isLayoutFile(path)) {
      if (building_) addShot(shell, path);
      continue;
    }
    openFromEditor(shell, path);
    return;
  }
}

void BuildingMode::openFromEditor(app::Shell& shell, const fs::path& path) {
  const Document* shot = editor_.document();
  if (dirty() || (shot && shot->dirty())) {
    ask(shell, path);
    shell.requestMode(kName);
    return;
  }
  openLayout(shell, path);
  if (building_ && building_->path() == path) shell.requestMode(kName);
}

void BuildingMode::update(app::Shell& shell, double) {
  layOut(shell);
  if (!building_) return;
  building_->remeasure(lentShot());
  if (!drag_) {
    boxes_ = building_->boxes();
    world_ = placeCorridors(building_->layout(), boxes_);
  }
  auto plan = modeling::planBuilding(building_->layout(), boxes_);
  planError_ = plan ? std::string() : plan.message();
  planWarnings_.clear();
  if (plan) {
    for (const modeling::CorridorOverlap& o : plan->overlaps) {
      planWarnings_.push_back(modeling::overlapText(building_->layout(), o));
    }
  }
  updatePreview(shell);
}

void BuildingMode::updatePreview(app::Shell& shell) {
  preview_.update(shell);
  previewCurrent_ = false;
  if (!building_ || drag_) return;  // a drag's steps are not built: its release is
  auto shots = building_->measuredShots(lentShot());
  if (!shots) {
    preview_.cannotBuild(shots.message());
    return;
  }
  if (!planError_.empty()) {
    preview_.cannotBuild(planError_);
    return;
  }
  previewCurrent_ = preview_.showsCurrent(building_->layout(), *shots);
  preview_.ask(building_->layout(), std::move(*shots), building_->path().stem().string());
}

Status BuildingMode::onReplayEvent(app::Shell& shell, const app::ModeEvent& event) {
  if (!std::any_cast<PreviewWaitEvent>(&event.value)) return AppMode::onReplayEvent(shell, event);
  if (!building_) return makeError("preview-wait: no layout is open");
  update(shell, 0.0);  // asks for the building as it is now
  if (Status waited = preview_.waitIdle(shell, 120.0); !waited) return makeError("preview-wait: " + waited.message());
  return {};
}

void BuildingMode::traceRow(app::TraceRow& row) const {
  row.add("plan_to_window", ordered_json{{"scale", view_.scale}, {"offset", ordered_json::array({view_.offset.x, view_.offset.y})}});
  if (!building_) {
    row.add("building", ordered_json(nullptr));
    editor_.addDocumentTrace(row);
    traceQuestion(row);
    return;
  }
  const Layout& layout = building_->layout();
  ordered_json corridors = ordered_json::array();
  for (size_t i = 0; i < layout.corridors.size() && i < world_.size(); ++i) {
    const PlanPose pose = poseOf(world_[i]);
    const modeling::LayoutEntry& entry = layout.corridors[i];
    corridors.push_back(ordered_json{
        {"name", entry.name},
        {"shot", entry.shot.string()},
        {"position", ordered_json::array({pose.nearCentre.x, pose.nearCentre.y})},
        {"rotation_deg", pose.rotationDeg},
        {"size_m", ordered_json::array({boxes_[i].widthM, boxes_[i].lengthM})},
        {"attach", entry.attach ? attachJson(layout, *entry.attach) : ordered_json(nullptr)}});
  }
  ordered_json building{{"path", building_->path().string()},
                        {"dirty", dirty()},
                        {"corridors", corridors},
                        {"selected", selected_.empty() ? ordered_json(nullptr) : ordered_json(selected_)},
                        {"snap", drag_ && drag_->snap ? attachJson(drag_->before, drag_->snap->attach) : ordered_json(nullptr)},
                        {"error", planError_.empty() ? ordered_json(nullptr) : ordered_json(planError_)},
                        {"warnings", planWarnings_}};
  row.add("building", building);
  editor_.addDocumentTrace(row);
  traceQuestion(row);
  row.add("preview", preview_.trace(previewCurrent_));
}

app::FrameContent BuildingMode::frame(app::Shell&) {
  app::FrameContent content;
  content.clearColor = glm::vec3(0.12f, 0.13f, 0.15f);
  if (building_) {
    if (const std::optional<engine::SceneView> model = preview_.view()) content.views.push_back(*model);
  }
  return content;
}

}  // namespace pw::edit
