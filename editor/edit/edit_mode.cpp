#include "editor/edit/edit_mode.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "editor/app/shell.h"
#include "editor/edit/building.h"
#include "editor/edit/model_walk.h"
#include "editor/edit/live_measurement.h"
#include "modeling/corridor_model.h"

namespace pw::edit {
namespace fs = std::filesystem;
using app::Overloaded;
using metrology::kCornerCount;
using metrology::Shot;
using nlohmann::ordered_json;

namespace {

constexpr double kGrabRadiusPx = 12;   // a press this near a handle takes it
constexpr double kSlowFactor = 0.1;    // Shift while dragging
constexpr double kSnapReachScreenPx = 12;  // a dragged corner snaps to a junction this near
constexpr double kNudgePx = 1.0;       // arrow keys; Shift: a tenth
constexpr long kNudgeLoupeSteps = 60;  // the loupe stays a second after a nudge
constexpr double kPreviewToolbarPx = 30;  // the 3D preview's toolbar, over its pane

ordered_json pair(const glm::dvec2& p) { return ordered_json::array({p.x, p.y}); }

}  // namespace

EditMode::EditMode(EditModeOptions options, ModelWalk& walk) : options_(std::move(options)), walk_(walk) {
  files_.recent = RecentFiles::load(options_.recentFilesPath.value_or(defaultRecentFilesPath()));
}

std::vector<app::ReplayVerb> EditMode::replayVerbs(const fs::path& scriptDir) {
  std::vector<app::ReplayVerb> verbs = {{"save-copy", [scriptDir](std::istream& words) -> Result<std::any> {
             std::string file;
             if (!(words >> file)) return makeError("expected 'save-copy FILE.json'");
             fs::path path(file);
             if (path.is_relative()) path = scriptDir / path;
             return std::any(SaveCopyEvent{path});
           }},
          {"preview-wait", [](std::istream&) -> Result<std::any> { return std::any(PreviewWaitEvent{}); }},
          {"boxes-wait", [](std::istream&) -> Result<std::any> { return std::any(BoxesWaitEvent{}); }}};
  for (app::ReplayVerb& verb : filesReplayVerbs(scriptDir)) verbs.push_back(std::move(verb));
  return verbs;
}

Status EditMode::open(app::Shell& shell) {
  if (options_.file) openFile(shell, *options_.file);
  return {};
}

void EditMode::openFile(app::Shell& shell, const fs::path& path) {
  if (layoutOpener_ && isLayoutFile(path)) {
    layoutOpener_(shell, path);
    return;
  }
  auto doc = Document::open(path, options_.open);
  if (!doc) {
    openError_ = doc.message();
    shell.showMessage("error: " + openError_);
    return;
  }
  showDocument(shell, std::move(*doc));
  if (openError_.empty()) afterOpen(shell, path);  // recent files; a crash's autosave offered back
}

std::optional<Document> EditMode::takeDocument(app::Shell& shell) {
  if (drag_) endDrag(true);
  updateFiles(shell, Autosave::kIntervalS);  // its unsaved edits autosaved as they are now
  leaveDocument();
  std::optional<Document> doc = std::move(doc_);
  doc_.reset();
  if (photo_) (void)shell.renderer().removeImage(photo_);
  photo_ = {};
  selected_ = -1;
  measuredShot_.reset();
  live_ = {};
  return doc;
}

void EditMode::showDocument(app::Shell& shell, Document doc) {
  const fs::path path = doc.path();
  auto uploaded = shell.renderer().addImage(modeling::imageFromBgr(doc.photo()));
  if (!uploaded) {
    openError_ = path.string() + ": the photo cannot be shown: " + uploaded.message();
    shell.showMessage("error: " + openError_);
    return;
  }
  if (photo_) (void)shell.renderer().removeImage(photo_);
  photo_ = *uploaded;
  openError_.clear();
  leaveDocument();
  doc_ = std::move(doc);
  preview_.setDocument(doc_->photo());
  for (const std::string& note : doc_->notes()) shell.showMessage("note: " + note);
  canvas_ = Canvas();  // fits the new photo
  selected_ = -1;
  drag_.reset();
  snapShown_.reset();
  lastMoved_ = -1;
  panFrom_.reset();
  measuredShot_.reset();
  layOut(shell);
  remeasure();
}

void EditMode::layOut(app::Shell& shell) {
  windowSize_ = shell.window().framebufferSize();
  const double width = windowSize_.x;
  panelWidthPx_ = std::floor(std::min(std::clamp(0.3 * width, 260.0, 380.0), 0.6 * width));
  const glm::ivec2 photoSize = doc_ ? glm::ivec2(doc_->photo().cols, doc_->photo().rows) : glm::ivec2(0);
  canvas_.setArea({{0.0, 0.0}, {std::max(1.0, width - panelWidthPx_), std::max(1.0, double(windowSize_.y))}},
                  photoSize);
  // The 3D preview: the lower part of the panel's column, its toolbar above it.
  const double height = windowSize_.y;
  panelHeightPx_ = height;
  preview_.setRect({});
  previewToolbar_ = {};
  if (doc_ && preview_.shown()) {
    // A 4:3 pane at most, and at most 45% of the height; in a short window (720 px) it
    // gives way, down to 30% of it, so that the panel above keeps kMinPanelAbovePreviewPx
    // (the Camera fields within reach without a scroll).
    constexpr double kMinPanelAbovePreviewPx = 520;
    const double paneHeight = std::floor(std::min({0.75 * panelWidthPx_, 0.45 * height,
                                                   std::max(0.3 * height, height - kMinPanelAbovePreviewPx)}));
    const double left = width - panelWidthPx_;
    preview_.setRect({{left, height - paneHeight}, {width, height}});
    previewToolbar_ = {{left, height - paneHeight - kPreviewToolbarPx}, {width, height - paneHeight}};
    panelHeightPx_ = std::max(0.0, height - paneHeight - kPreviewToolbarPx);
  }
}

void EditMode::onEnter(app::Shell& shell) {
  keys_.fill(false);
  layOut(shell);
}

void EditMode::onLeave(app::Shell& shell) {
  // Nothing stays held while another mode runs: a drag ends where it was.
  if (drag_) endDrag(true);
  updateFiles(shell, Autosave::kIntervalS);  // autosave now: the editor is not updated while away
  panFrom_.reset();
  preview_.endOrbit();
  keys_.fill(false);
}

bool EditMode::overCanvas(const glm::dvec2& p) const {
  if (!canvas_.area().contains(p) || dialogOpen()) return false;
  return std::none_of(uiRects_.begin(), uiRects_.end(), [&](const WindowRect& r) { return r.contains(p); });
}

void EditMode::onInput(app::Shell& shell, const app::InputEvent& event) {
  layOut(shell);
  if (preview_.onInput(event)) {  // an orbit or the wheel over the 3D preview
    if (const auto* cursor = std::get_if<app::CursorEvent>(&event)) cursorPx_ = cursor->positionPx;
    return;
  }
  std::visit(Overloaded{[&](const app::KeyEvent& e) { onKey(shell, e); },
                        [&](const app::MouseButtonEvent& e) { onButton(shell, e); },
                        [&](const app::CursorEvent& e) { onCursor(e.positionPx); },
                        [&](const app::ScrollEvent& e) {
                          if (doc_ && overCanvas(cursorPx_) && e.offset.y != 0) canvas_.zoomAbout(cursorPx_, e.offset.y);
                        },
                        [&](const app::DropEvent& e) { onDrop(shell, e); }, [](const auto&) {}},
             event);
}

void EditMode::onKey(app::Shell& shell, const app::KeyEvent& e) {
  if (e.key < 0 || e.key > GLFW_KEY_LAST) return;
  keys_[e.key] = e.down;
  if (!e.down) return;
  if (onFilesKey(shell, e)) return;  // a dialog's keys; Ctrl+O, Ctrl+Shift+S
  if (ImGui::GetCurrentContext() && ImGui::GetIO().WantTextInput) return;  // typing into a panel's field
  const bool ctrl = ctrlHeld() || (e.mods & GLFW_MOD_CONTROL);
  const bool shift = shiftHeld() || (e.mods & GLFW_MOD_SHIFT);
  const bool alt = altHeld() || (e.mods & GLFW_MOD_ALT);
  if (ctrl) {
    if (e.key == GLFW_KEY_Z) shift ? redo(shell) : undo(shell);
    else if (e.key == GLFW_KEY_Y) redo(shell);
    else if (e.key == GLFW_KEY_S) save(shell);
    return;
  }
  if (e.key == GLFW_KEY_F1) showKeys_ = !showKeys_;
  if (!doc_) return;
  if (alt && e.key >= GLFW_KEY_1 && e.key <= GLFW_KEY_8) {
    select(e.key - GLFW_KEY_1);
    return;
  }
  if (outlining_ && outlineKey(shell, e.key)) return;  // a polygon being clicked: Enter, Backspace, Esc
  const double nudgePx = shift ? kSlowFactor * kNudgePx : kNudgePx;
  switch (e.key) {
    case GLFW_KEY_TAB:
      select(selected_ < 0 ? (shift ? kCornerCount - 1 : 0) : (selected_ + (shift ? kCornerCount - 1 : 1)) % kCornerCount);
      break;
    case GLFW_KEY_1:
      canvas_.setScaleAbout(overCanvas(cursorPx_) ? cursorPx_ : canvas_.area().centre(), 1.0);
      break;
    case GLFW_KEY_F:
      canvas_.fit();
      break;
    case GLFW_KEY_E:
      fitCorners(shell);
      break;
    case GLFW_KEY_H:
      showOverlay_ = !showOverlay_;
      break;
    case GLFW_KEY_P:
      preview_.setShown(!preview_.shown());
      layOut(shell);
      break;
    case GLFW_KEY_LEFT: nudge({-nudgePx, 0}); break;
    case GLFW_KEY_RIGHT: nudge({nudgePx, 0}); break;
    case GLFW_KEY_UP: nudge({0, -nudgePx}); break;
    case GLFW_KEY_DOWN: nudge({0, nudgePx}); break;
    case GLFW_KEY_W:
      walk(shell);
      break;
    case GLFW_KEY_B:
      if (!planMode_.empty()) shell.requestMode(planMode_);
      break;
    case GLFW_KEY_M:
      setOutlining(shell, false);
      setMeasuring(shell, !measuring_);
      break;
    case GLFW_KEY_U:
      setOutlining(shell, !(outlining_ && outlineShape_ == metrology::CutoutShape::kFlat));
      break;
    case GLFW_KEY_O:
      setOutlining(shell, !(outlining_ && outlineShape_ == metrology::CutoutShape::kOpening), metrology::CutoutShape::kOpening);
      break;
    case GLFW_KEY_ESCAPE:
      if (drag_) endDrag(false);  // the corner goes back to where the drag began
      pickingReference_ = false;
      measuring_ = false;
      measureFrom_.reset();
      setOutlining(shell, false);
      break;
    default:
      break;
  }
}

void EditMode::onButton(app::Shell& shell, const app::MouseButtonEvent& e) {
  if (!e.down) {
    if (outlining_ && e.button == GLFW_MOUSE_BUTTON_LEFT) (void)outlineButton(shell, false);
    if (drag_ && e.button == GLFW_MOUSE_BUTTON_LEFT) endDrag(true);
    if (panFrom_ && e.button == panButton_) panFrom_.reset();
    return;
  }
  if (!doc_ || drag_ || panFrom_ || !overCanvas(cursorPx_)) return;
  if (e.button == GLFW_MOUSE_BUTTON_MIDDLE || e.button == GLFW_MOUSE_BUTTON_RIGHT ||
      (e.button == GLFW_MOUSE_BUTTON_LEFT && held(GLFW_KEY_SPACE))) {
    panFrom_ = cursorPx_;
    panButton_ = e.button;
    return;
  }
  if (e.button != GLFW_MOUSE_BUTTON_LEFT) return;
  if (measuring_ && measureClick(shell)) return;  // measuring: clicks place points, not grab corners
  if (outlining_ && outlineButton(shell, true)) return;  // outlining: a drag is a rectangle, clicks a polygon
  const int corner = handleAt(canvas_, doc_->shot(), cursorPx_, kGrabRadiusPx);
  if (pickingReference_ && pickReference(shell, corner)) return;
  select(corner);
  if (corner >= 0) {
    drag_ = Drag{corner, doc_->shot(), cursorPx_};
    lastMoved_ = corner;
  } else if (principalHandleAt(cursorPx_) >= 0) {
    drag_ = Drag{kPrincipalPointHandle, doc_->shot(), cursorPx_};
  }
}

void EditMode::onCursor(const glm::dvec2& p) {
  cursorPx_ = p;
  if (panFrom_) {
    canvas_.pan(p - *panFrom_);
    panFrom_ = p;
  }
  if (drag_ && doc_) {
    Shot shot = doc_->shot();
    const bool principal = drag_->corner == kPrincipalPointHandle;
    glm::dvec2 principalPx = shot.principalPoint();
    glm::dvec2& corner = principal ? principalPx : shot.cornersPx[drag_->corner];
    corner += (p - drag_->lastCursorPx) / canvas_.scale() * (shiftHeld() ? kSlowFactor : 1.0);
    // Corners may lie beyond the photo's edges, but not so far that the shot file would
    // be refused (modeling::loadShot: within one image size).
    const glm::dvec2 size(shot.imageWidth, shot.imageHeight);
    corner = glm::clamp(corner, -size, 2.0 * size);
    if (principal) shot.principalPointPx = principalPx;
    drag_->lastCursorPx = p;
    doc_->setLive(shot);
    updateSnap();
  }
}

std::optional<EditMode::SnapRequest> EditMode::snapRequest() {
  if (!drag_ || !doc_ || drag_->corner < 0 || drag_->corner >= kCornerCount || altHeld()) return std::nullopt;
  const Shot& shot = doc_->shot();
  SnapRequest r;
  r.corner = drag_->corner;
  r.box = shot.cornersPx;
  r.at = shot.cornersPx[drag_->corner];
  // Within a dozen screen pixels of where it is dropped, whatever the zoom.
  r.reachPx = std::clamp(kSnapReachScreenPx / canvas_.scale(), 1.0, 25.0);
  r.snapper = std::make_shared<const metrology::detect::CornerSnapper>(doc_->photo(), shot.focalPx, shot.principalPoint(),
                                                                       shot.distortion);
  return r;
}

void EditMode::updateSnap() {
  auto request = snapRequest();
  if (!request) return;
  if (!snapWorker_) {
    snapWorker_ = std::make_unique<LatestWorker<SnapRequest, SnapDone>>(
        [](SnapRequest& r, const auto& emit, const auto&) {
          auto snap = r.snapper->snap(r.corner, r.box, r.at, r.reachPx);
          emit(SnapDone{std::move(r), snap});
        });
  }
  snapWorker_->request(std::move(*request));
}

std::optional<glm::dvec2> EditMode::currentSnap() const {
  if (!drag_ || !doc_ || !snapShown_ || !snapShown_->snap || altHeld()) return std::nullopt;
  const SnapRequest& r = snapShown_->request;
  if (r.corner != drag_->corner || r.box != doc_->shot().cornersPx) return std::nullopt;  // for an older position
  return snapShown_->snap->px;
}

void EditMode::onDrop(app::Shell& shell, const app::DropEvent& e) {
  if (e.paths.empty()) return;
  const fs::path& path = e.paths.front();
  if (layoutOpener_ && isLayoutFile(path)) {  // a building: its mode asks about unsaved changes
    layoutOpener_(shell, path);
    return;
  }
  requestOpen(shell, path);  // asks first when unsaved edits would be lost
}

void EditMode::select(int corner) { selected_ = (corner >= 0 && corner < kCornerCount) ? corner : -1; }

void EditMode::endDrag(bool keep) {
  if (!drag_ || !doc_) return;
  if (keep) {
    // Released by its edge junction (Alt: where it is): the worker's answer for this very
    // position, else worked out now, so a replay's release snaps however fast it ran.
    if (auto request = snapRequest()) {
      std::optional<metrology::detect::CornerSnap> snap;
      if (snapShown_ && snapShown_->request.sameAs(*request)) {
        snap = snapShown_->snap;
      } else {
        snap = request->snapper->snap(request->corner, request->box, request->at, request->reachPx);
      }
      if (snap) {
        Shot snapped = doc_->shot();
        snapped.cornersPx[drag_->corner] = snap->px;
        doc_->setLive(snapped);
      }
    }
    doc_->commitLive(drag_->before, drag_->corner == kPrincipalPointHandle
                                        ? std::string("move the principal point")
                                        : std::string("move ") + metrology::cornerName(drag_->corner));
  } else {
    doc_->setLive(drag_->before);
  }
  drag_.reset();
  snapShown_.reset();
}

void EditMode::nudge(const glm::dvec2& delta) {
  if (!doc_ || drag_ || selected_ < 0) return;
  Shot shot = doc_->shot();
  shot.cornersPx[selected_] += delta;
  lastMoved_ = selected_;
  doc_->apply(shot, std::string("nudge ") + metrology::cornerName(selected_));
  nudgeLoupeUntil_ = step_ + kNudgeLoupeSteps;
}

void EditMode::applyEdit(app::Shell&, const Shot& after, const std::string& label) {
  if (!doc_) return;
  if (drag_) endDrag(true);
  doc_->apply(after, label);
}

void EditMode::undo(app::Shell& shell) {
  if (!doc_ || drag_) return;
  if (!doc_->undo()) shell.showMessage("nothing to undo");
}

void EditMode::redo(app::Shell& shell) {
  if (!doc_ || drag_) return;
  if (!doc_->redo()) shell.showMessage("nothing to redo");
}

void EditMode::fitCorners(app::Shell& shell) {
  if (!doc_) return;
  if (drag_) endDrag(true);
  shell.showMessage(doc_->fitCorners().message);
}

void EditMode::save(app::Shell& shell) {
  if (!doc_) {
    shell.showMessage("nothing to save: no file is open");
    return;
  }
  if (drag_) endDrag(true);
  if (Status saved = doc_->save(); !saved) {
    shell.showMessage("error: not saved: " + saved.message());
    return;
  }
  shell.showMessage("saved " + doc_->path().string());
  afterSave(shell);
}

void EditMode::walk(app::Shell& shell) {
  if (!doc_) return;
  if (drag_) endDrag(true);
  remeasure();
  if (!live_.measurement) {
    shell.showMessage("walk: the corners cannot be measured yet: " + live_.error);
    return;
  }
  if (pendingWalk_) {
    shell.showMessage("walk: its model is being built; the walk starts when it is done");
    return;
  }
  // The preview's full model when it is of the corners as they are: W then only uploads it.
  std::shared_ptr<const engine::Scene> built = preview_.fullSceneOf(doc_->modelShot());
  if (!built && !walk_.walks(doc_->modelShot())) {
    // Built on a thread of its own (seconds on a large photo): the window draws on, and
    // the panel says so; finishWalk starts the walk.
    pendingWalk_ = PendingWalk{doc_->modelShot(), *live_.measurement,
                               std::async(std::launch::async,
                                          [shot = doc_->modelShot(), photo = doc_->photo(), m = *live_.measurement] {
                                            return buildCorridorScene(shot, photo, m);
                                          }),
                               std::chrono::steady_clock::now()};
    shell.showMessage("walk: building its model ...");
    // A replay waits for it here, so that W walks in the frame it was pressed in,
    // whatever the machine's speed.
    if (shell.replaying()) finishWalk(shell, true);
    return;
  }
  if (Status shown = walk_.show(shell, doc_->modelShot(), doc_->photo(), *live_.measurement, built); !shown) {
    shell.showMessage("walk: no model: " + shown.message());
    return;
  }
  walkModelFrom_ = built ? "preview" : "built";
  shell.requestMode(std::string(walk_.name()));
}

void EditMode::finishWalk(app::Shell& shell, bool wait) {
  if (!pendingWalk_) return;
  if (!wait && pendingWalk_->scene.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  PendingWalk done = std::move(*pendingWalk_);
  pendingWalk_.reset();
  Result<engine::Scene> scene = done.scene.get();
  if (!scene) {
    shell.showMessage("walk: no model: " + scene.message());
    return;
  }
  if (!doc_ || doc_->modelShot() != done.shot) {
    shell.showMessage("walk: the corners changed while its model was built; press W to walk them");
    return;
  }
  auto shared = std::make_shared<const engine::Scene>(std::move(*scene));
  if (Status shown = walk_.show(shell, done.shot, doc_->photo(), done.measurement, shared); !shown) {
    shell.showMessage("walk: no model: " + shown.message());
    return;
  }
  walkModelFrom_ = "built";
  shell.requestMode(std::string(walk_.name()));
}

Status EditMode::onReplayEvent(app::Shell& shell, const app::ModeEvent& event) {
  if (onFilesReplayEvent(shell, event)) return {};
  if (std::any_cast<PreviewWaitEvent>(&event.value)) {
    if (!doc_) return makeError("preview-wait: no file is open");
    remeasure();
    if (Status built = preview_.waitForFull(shell, doc_->modelShot(), live_.measurement.has_value(), 120.0); !built) {
      return makeError("preview-wait: " + built.message());
    }
    return {};
  }
  if (std::any_cast<BoxesWaitEvent>(&event.value)) {
    if (!doc_) return makeError("boxes-wait: no file is open");
    remeasure();
    updateBoxFits();
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (boxFitWorker_ && boxFitWorker_->busy()) {
      if (std::chrono::steady_clock::now() > until) return makeError("boxes-wait: no boxes after 120 s");
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    updateBoxFits();
    return {};
  }
  const auto* copy = std::any_cast<SaveCopyEvent>(&event.value);
  if (!copy) return AppMode::onReplayEvent(shell, event);
  if (!doc_) return makeError("save-copy: no file is open");
  return doc_->saveCopy(copy->path);
}

void EditMode::remeasure() {
  if (!doc_) {
    measuredShot_.reset();
    live_ = {};
    return;
  }
  if (measuredShot_ && *measuredShot_ == doc_->shot()) return;
  measuredShot_ = doc_->shot();
  live_ = measureLive(*measuredShot_, doc_->inputOrigins(), lastMoved_);
  if (doc_->isPlaceholderBox()) {
    // Its numbers would be the placeholder's, not the corridor's: none are shown, and
    // Walk, Export and the preview say why.
    live_.measurement.reset();
    live_.error = "the box is a placeholder (no corridor was detected): drag its corners onto the corridor's corners first";
  }
  remeasureObjects();
}

void EditMode::update(app::Shell& shell, double stepS) {
  layOut(shell);
  remeasure();
  if (snapWorker_) {
    for (SnapDone& done : snapWorker_->takeDone()) snapShown_ = std::move(done);
  }
  updateBoxFits();
  if (doc_) preview_.update(shell, doc_->modelShot(), live_.measurement ? std::string() : live_.error.empty() ? std::string("the corners cannot be measured") : live_.error,
                              drag_.has_value());
  updateFiles(shell, stepS);
  finishWalk(shell, shell.replaying());
  ++step_;
}

std::optional<Loupe> EditMode::loupe() const {
  if (!doc_) return std::nullopt;
  const Shot& shot = doc_->shot();
  if (drag_ && drag_->corner < kCornerCount) return placeLoupe(canvas_, shot.cornersPx[drag_->corner], drag_->corner, cursorPx_);
  if (selected_ >= 0 && step_ <= nudgeLoupeUntil_) {
    return placeLoupe(canvas_, shot.cornersPx[selected_], selected_, canvas_.toWindow(shot.cornersPx[selected_]));
  }
  return std::nullopt;
}

void EditMode::addDocumentTrace(app::TraceRow& row) const {
  if (!doc_) {
    row.add("document", ordered_json{{"path", nullptr}, {"dirty", false}});
    return;
  }
  row.add("document", ordered_json{{"path", doc_->path().string()}, {"dirty", doc_->dirty()}});
}

void EditMode::traceRow(app::TraceRow& row) const {
  const engine::ImageTransform& t = canvas_.transform();
  row.add("image_to_window", ordered_json{{"scale", t.scale}, {"offset", pair(t.offset)}});
  if (doc_) {
    ordered_json corners = ordered_json::object();
    for (int k = 0; k < kCornerCount; ++k) corners[metrology::cornerName(k)] = pair(doc_->shot().cornersPx[k]);
    row.add("corners_px", corners);
  } else {
    row.add("corners_px", ordered_json(nullptr));
  }
  row.add("selected", selected_ >= 0 ? ordered_json(metrology::cornerName(selected_)) : ordered_json(nullptr));
  const std::optional<glm::dvec2> snap = currentSnap();
  row.add("snap_px", snap ? pair(*snap) : ordered_json(nullptr));
  if (live_.measurement) {
    const metrology::Dimensions& size = live_.measurement->size;
    const metrology::Dimensions& sigma = live_.measurement->sigma;
    row.add("measurement",
            ordered_json{{"width_m", size.widthM},
                         {"height_m", size.heightM},
                         {"length_m", size.lengthM},
                         {"sigma_m", {{"width_m", sigma.widthM}, {"height_m", sigma.heightM}, {"length_m", sigma.lengthM}}},
                         {"text",
                          {{"width_m", metrology::dimensionWithSource(*live_.measurement, 0)},
                           {"height_m", metrology::dimensionWithSource(*live_.measurement, 1)},
                           {"length_m", metrology::dimensionWithSource(*live_.measurement, 2)}}}});
  } else {
    row.add("measurement", ordered_json(nullptr));
  }
  row.add("box", !doc_                       ? ordered_json(nullptr)
                 : doc_->isPlaceholderBox()   ? ordered_json("placeholder")
                 : doc_->isSuggestedBox()     ? ordered_json("suggested")
                                              : ordered_json("placed"));
  addDocumentTrace(row);
  traceFiles(row);
  if (const std::optional<Loupe> l = loupe()) {
    const glm::dvec2 size = l->rect.size();
    row.add("loupe", ordered_json{{"corner", metrology::cornerName(l->corner)},
                                  {"rect", ordered_json::array({l->rect.min.x, l->rect.min.y, size.x, size.y})},
                                  {"scale", l->transform.scale},
                                  {"offset", pair(l->transform.offset)}});
  } else {
    row.add("loupe", ordered_json(nullptr));
  }
  addCameraTrace(row);
  addObjectsTrace(row);
  addCutoutsTrace(row);
  const std::optional<Shot> modelShot = doc_ ? std::optional<Shot>(doc_->modelShot()) : std::nullopt;
  row.add("preview", preview_.trace(modelShot ? &*modelShot : nullptr));
  row.add("walk_model", walkModelFrom_.empty() ? ordered_json(nullptr) : ordered_json(walkModelFrom_));
  row.add("walk_building", pendingWalk_.has_value());
}

app::FrameContent EditMode::frame(app::Shell&) {
  app::FrameContent content;
  content.clearColor = glm::vec3(0.10f, 0.10f, 0.11f);
  if (!doc_ || !photo_) return content;
  engine::ImageView canvas;
  canvas.image = photo_;
  canvas.transform = canvas_.transform();
  canvas.rect = pixelRect(canvas_.area());
  canvas.background = glm::vec4(0.17f, 0.17f, 0.19f, 1.0f);
  content.views.push_back(canvas);
  if (const std::optional<engine::SceneView> model = preview_.view()) content.views.push_back(*model);
  if (const std::optional<Loupe> l = loupe()) {
    engine::ImageView view;
    view.image = photo_;
    view.transform = l->transform;
    view.rect = pixelRect(l->rect);
    view.filter = engine::ImageFilter::kNearest;
    view.background = glm::vec4(0.05f, 0.05f, 0.05f, 1.0f);
    content.views.push_back(view);
  }
  return content;
}

}  // namespace pw::edit
