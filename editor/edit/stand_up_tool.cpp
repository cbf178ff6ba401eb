// The editor's stand-up tool (issue 25, part 3): U, then a rectangle dragged around an
// object on the photo (a person, a plant, a bin), down to where it stands on the floor,
// or a polygon clicked around it (the first point again, or Enter, closes it), stands it
// up in the model as a cut-out (modeling/stand_up.h: GrabCut finds the object inside the
// outline) instead of painting it flat on the floor and the wall behind it.
// Each is kept in the shot's "cutouts" (one undo step), drawn on the photo with its
// name, listed in the panel's "Standing objects" with a name field and a delete button,
// and traced ("cutouts", "outlining"); the 3D preview and W's model stand it up. A
// rectangle the model cannot stand up (its foot off the photo, above the horizon, beyond
// the corridor's floor) is refused with the reason, and nothing changes.
// O, then the same around a doorway or an opening in a side wall, opens the wall there
// with a room behind it (modeling/side_room.h); its "opening" box in the list makes any
// cutout one, or an object again.
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>
#include <utility>

#include "editor/app/shell.h"
#include "editor/edit/edit_mode.h"
#include "editor/edit/panel_style.h"
#include "modeling/corridor_model.h"
#include "modeling/side_room.h"
#include "modeling/stand_up.h"

namespace pw::edit {
namespace {

using metrology::Cutout;
using metrology::Shot;
using nlohmann::ordered_json;

const ImU32 kCutoutColour = IM_COL32(120, 255, 170, 255);
const ImU32 kCutoutShadow = IM_COL32(0, 0, 0, 200);
const ImU32 kOpeningColour = IM_COL32(255, 190, 90, 255);  // an opening, not an object
constexpr double kMinCutoutPx = 4;  // an outline at least this wide and high (photo pixels)
constexpr double kClickPx = 4;      // a press and release nearer than this (window pixels) is a click: a polygon's point
constexpr double kCloseRadiusPx = 8;  // a click this near a polygon's first point (window pixels) closes it
const char* const kOutliningHelp =
    "stand up: drag a rectangle around an object, down to where it stands on the floor, or click a polygon around it; "
    "Esc: stop";
const char* const kOpeningHelp =
    "open: drag a rectangle around a doorway or an opening in a side wall, or click its corners; Esc: stop";

// The shapes a cutout's line in the list can be given besides a flat cut-out.
struct ShapeChoice {
  metrology::CutoutShape shape;
  const char* label;  // the checkbox's, and its widget's name after "cutout N "
  const char* tooltip;
};
const ShapeChoice kShapeChoices[] = {
    {metrology::CutoutShape::kBox, "box",
     "a box on the floor (a cabinet, a bench, a radiator): its front, the side the photo\n"
     "sees and its top, at their measured width, depth and height; off: a flat cut-out"},
    {metrology::CutoutShape::kHanging, "hanging",
     "hanging from the ceiling (a lamp on a rod, a sign): a flat cut-out whose top is where the\n"
     "outline's top meets the ceiling; draw the outline up to where it hangs; off: standing"},
    {metrology::CutoutShape::kOpening, "opening",
     "a doorway or an opening in a side wall: the model opens the wall there, with a room\n"
     "behind it that shows what the photo sees through it; off: an object stood up"},
};

ImVec2 im(const glm::dvec2& p) { return {float(p.x), float(p.y)}; }

// "object N" ("opening N") with the first N no cutout is called.
std::string freeCutoutName(const Shot& shot, metrology::CutoutShape shape) {
  for (int n = 1;; ++n) {
    const std::string name = (shape == metrology::CutoutShape::kOpening ? "opening " : "object ") + std::to_string(n);
    if (std::none_of(shot.cutouts.begin(), shot.cutouts.end(), [&](const Cutout& c) { return c.name == name; })) return name;
  }
}

// The outline's lowest point in the photo (the largest v).
glm::dvec2 lowestPoint(const std::vector<glm::dvec2>& outline) {
  return *std::max_element(outline.begin(), outline.end(), [](const glm::dvec2& a, const glm::dvec2& b) { return a.y < b.y; });
}

std::array<glm::dvec2, 4> rectangle(glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 lo = glm::min(a, b), hi = glm::max(a, b);
  return {lo, glm::dvec2(hi.x, lo.y), hi, glm::dvec2(lo.x, hi.y)};
}

}  // namespace

void EditMode::setOutlining(app::Shell& shell, bool on, metrology::CutoutShape shape) {
  outlining_ = on && doc_.has_value();
  outlineShape_ = shape;
  outlineFrom_.reset();
  outlinePolygon_.clear();
  if (outlining_) {
    measuring_ = false;
    measureFrom_.reset();
    pickingReference_ = false;
    shell.showMessage(shape == metrology::CutoutShape::kOpening ? kOpeningHelp : kOutliningHelp);
  }
}

bool EditMode::outlineButton(app::Shell& shell, bool down) {
  if (!outlining_ || !doc_) return false;
  const glm::dvec2 at = canvas_.toPhoto(cursorPx_);
  if (down) {
    outlineFrom_ = at;
    return true;
  }
  if (!outlineFrom_) return false;
  const glm::dvec2 from = *outlineFrom_;
  outlineFrom_.reset();
  if (!outlinePolygon_.empty()) {
    // A polygon being clicked: its first point again closes it, any other adds one.
    if (outlinePolygon_.size() >= 3 && glm::length(canvas_.toWindow(at) - canvas_.toWindow(outlinePolygon_.front())) <= kCloseRadiusPx) {
      standUpOutline(shell, std::exchange(outlinePolygon_, {}));
    } else {
      outlinePolygon_.push_back(at);
    }
    return true;
  }
  if (glm::length(canvas_.toWindow(at) - canvas_.toWindow(from)) < kClickPx) {  // a click: a polygon's first point
    outlinePolygon_.push_back(at);
    shell.showMessage(outlineShape_ == metrology::CutoutShape::kOpening
                          ? "open: click the opening's corners; the first point again (or Enter) closes it; "
                            "Backspace: the last point back; Esc: drop it"
                          : "stand up: click around the object, down to its foot; the first point again (or Enter) closes it; "
                            "Backspace: the last point back; Esc: drop it");
    return true;
  }
  const std::array<glm::dvec2, 4> corners = rectangle(from, at);
  standUpOutline(shell, {corners.begin(), corners.end()});
  return true;
}

bool EditMode::outlineKey(app::Shell& shell, int key) {
  if (outlinePolygon_.empty()) return false;
  switch (key) {
    case GLFW_KEY_ENTER:
    case GLFW_KEY_KP_ENTER:
      if (outlinePolygon_.size() < 3) {
        shell.showMessage("stand up: a polygon needs three points or more (Esc drops it)");
      } else {
        standUpOutline(shell, std::exchange(outlinePolygon_, {}));
      }
      return true;
    case GLFW_KEY_BACKSPACE:
      outlinePolygon_.pop_back();
      if (outlinePolygon_.empty()) shell.showMessage(outlineShape_ == metrology::CutoutShape::kOpening ? kOpeningHelp : kOutliningHelp);
      return true;
    case GLFW_KEY_ESCAPE:
      outlinePolygon_.clear();
      shell.showMessage(std::string("polygon dropped; ") + (outlineShape_ == metrology::CutoutShape::kOpening ? kOpeningHelp : kOutliningHelp));
      return true;
    default:
      return false;
  }
}

// Stands the outline (photo pixels) up as a new cutout, one undo step, or says why not
// and changes nothing.
// `cutout` stood up now, alone and without the fill behind it, for its errors (the model
// stands them all up again, on the preview's worker): the object, or nothing with the
// reason said.
std::optional<modeling::StandingObject> EditMode::checkStandUp(app::Shell& shell, const Cutout& cutout) {
  if (!live_.measurement) {
    shell.showMessage("stand up: the corners do not measure yet: " + live_.error);
    return std::nullopt;
  }
  auto stood = modeling::standUpObjects(doc_->photo(), *live_.measurement, {cutout}, nullptr,
                                        modeling::StandUpParts::kObjectsOnly);
  if (!stood || stood->objects.empty()) {
    shell.showMessage("stand up: " + (stood ? stood->leftPainted.front() : stood.message()));
    return std::nullopt;
  }
  return std::move(stood->objects.front());
}

// `cutout` placed as an opening now, for its errors (the model builds its room on the
// preview's worker): the opening, or nothing with the reason said.
std::optional<modeling::SideRoom> EditMode::checkOpening(app::Shell& shell, const Cutout& cutout) {
  if (!live_.measurement) {
    shell.showMessage("open: the corners do not measure yet: " + live_.error);
    return std::nullopt;
  }
  const double nearM = std::max(0.0, live_.measurement->pose.positionM.z) + modeling::kClosedBehindCameraM;
  auto opening = modeling::placeOpening(*live_.measurement, cutout, nearM);
  if (!opening) {
    shell.showMessage("open: " + opening.message());
    return std::nullopt;
  }
  return std::move(*opening);
}

namespace {

std::string openingText(const std::string& name, const modeling::SideRoom& room) {
  char said[200];
  std::snprintf(said, sizeof said, "%s opens the %s: %.2f m wide, %.2f m high, a room %.0f m deep behind it", name.c_str(),
                room.wall == modeling::Surface::kLeftWall ? "left wall" : "right wall", room.opening.s1 - room.opening.s0,
                room.opening.t1 - room.opening.t0, room.depthM);
  return said;
}

}  // namespace

void EditMode::standUpOutline(app::Shell& shell, const std::vector<glm::dvec2>& outline) {
  glm::dvec2 lo = outline.front(), hi = outline.front();
  for (const glm::dvec2& p : outline) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const bool opening = outlineShape_ == metrology::CutoutShape::kOpening;
  if (hi.x - lo.x < kMinCutoutPx || hi.y - lo.y < kMinCutoutPx) {
    shell.showMessage(opening ? "open: outline the whole opening (this outline is too small)"
                              : "stand up: outline the whole object (this outline is too small)");
    return;
  }
  Shot after = doc_->shot();
  Cutout cutout{freeCutoutName(after, outlineShape_), outline, outlineShape_};
  if (opening) {
    const std::optional<modeling::SideRoom> room = checkOpening(shell, cutout);
    if (!room) return;
    after.cutouts.push_back(std::move(cutout));
    applyEdit(shell, after, "open " + after.cutouts.back().name);
    shell.showMessage(openingText(after.cutouts.back().name, *room));
    return;
  }
  // An outline whose lowest point is on or above the horizon cannot stand on the floor
  // the photo shows: it hangs from the ceiling (a lamp, a sign), as "hanging" would make it.
  if (live_.measurement && !modeling::onPlane(*live_.measurement, lowestPoint(outline), glm::dvec3(0.0), glm::dvec3(0, 1, 0))) {
    cutout.shape = metrology::CutoutShape::kHanging;
  }
  const std::optional<modeling::StandingObject> object = checkStandUp(shell, cutout);
  if (!object) return;
  const bool hangs = cutout.shape == metrology::CutoutShape::kHanging;
  char said[200];
  std::snprintf(said, sizeof said, "stood up %s: %s%.2f m high, %.2f m wide, %.1f m from the camera", cutout.name.c_str(),
                hangs ? "it hangs from the ceiling (above the horizon), " : "", object->heightM, object->widthM,
                object->distanceM);
  after.cutouts.push_back(std::move(cutout));
  applyEdit(shell, after, "stand up " + after.cutouts.back().name);
  shell.showMessage(said);
}

// A standing object made a box or a flat cut-out again, one undo step, checked as a new
// one is (its size said), or left as it was with the reason.
void EditMode::setCutoutShape(app::Shell& shell, size_t index, metrology::CutoutShape shape) {
  Shot after = doc_->shot();
  Cutout& cutout = after.cutouts.at(index);
  cutout.shape = shape;
  if (shape == metrology::CutoutShape::kOpening) {
    const std::optional<modeling::SideRoom> room = checkOpening(shell, cutout);
    if (!room) return;
    applyEdit(shell, after, "opening " + cutout.name);
    shell.showMessage(openingText(cutout.name, *room));
    return;
  }
  const std::optional<modeling::StandingObject> object = checkStandUp(shell, cutout);
  if (!object) return;
  char said[200];
  if (shape == metrology::CutoutShape::kBox) {
    std::snprintf(said, sizeof said, "%s stands as a box: %.2f m wide, %.2f m deep, %.2f m high, %.1f m from the camera",
                  cutout.name.c_str(), object->widthM, object->depthM, object->heightM, object->distanceM);
  } else if (shape == metrology::CutoutShape::kHanging) {
    std::snprintf(said, sizeof said, "%s hangs from the ceiling: %.2f m high, %.2f m wide, %.1f m from the camera",
                  cutout.name.c_str(), object->heightM, object->widthM, object->distanceM);
  } else {
    std::snprintf(said, sizeof said, "%s stands as a flat cut-out: %.2f m high, %.2f m wide, %.1f m from the camera",
                  cutout.name.c_str(), object->heightM, object->widthM, object->distanceM);
  }
  applyEdit(shell, after,
            (shape == metrology::CutoutShape::kBox ? "box " : shape == metrology::CutoutShape::kHanging ? "hang " : "flat ") +
                cutout.name);
  shell.showMessage(said);
}

void EditMode::deleteCutout(app::Shell& shell, size_t index) {
  if (!doc_ || index >= doc_->shot().cutouts.size()) return;
  Shot after = doc_->shot();
  const std::string name = after.cutouts[index].name;
  after.cutouts.erase(after.cutouts.begin() + static_cast<long>(index));
  applyEdit(shell, after, "delete " + name);
}

void EditMode::updateBoxFits() {
  if (boxFitWorker_) {
    for (BoxFitDone& done : boxFitWorker_->takeDone()) boxFitShown_ = std::move(done);
  }
  if (!doc_ || !live_.measurement) return;
  const Shot& shot = doc_->shot();
  if (std::none_of(shot.cutouts.begin(), shot.cutouts.end(), [](const Cutout& c) { return c.shape == metrology::CutoutShape::kBox; })) return;
  if (boxFitAsked_ && *boxFitAsked_ == shot) return;
  boxFitAsked_ = shot;
  if (!boxFitWorker_) {
    // The worker's own cut-outs: GrabCut once per outline, so that a corner dragged only
    // fits the boxes again.
    auto cutOuts = std::make_shared<modeling::CutOutCache>();
    boxFitWorker_ = std::make_unique<LatestWorker<BoxFitRequest, BoxFitDone>>([cutOuts](BoxFitRequest& r, const auto& emit, const auto&) {
      BoxFitDone done{std::move(r.shot), {}};
      for (const Cutout& cutout : done.shot.cutouts) {
        if (cutout.shape != metrology::CutoutShape::kBox) continue;
        // Each alone: one that cannot stand up (its message came at the check) draws nothing.
        auto stood = modeling::standUpObjects(r.photo, r.measurement, {cutout}, cutOuts.get());
        if (!stood || stood->objects.empty() || stood->objects.front().faces.size() < 2) continue;
        const auto& front = stood->objects.front().faces[0].cornersM;
        const auto& back = stood->objects.front().faces[1].cornersM;  // seen from behind: mirrored
        done.boxes.push_back({cutout.name, {front[0], front[1], front[2], front[3], back[1], back[0], back[3], back[2]}});
      }
      emit(std::move(done));
    });
  }
  boxFitWorker_->request({shot, doc_->photo(), *live_.measurement});
}

std::optional<std::array<glm::dvec2, 8>> EditMode::shownBoxPx(const std::string& name) const {
  if (!doc_ || !live_.measurement || !boxFitShown_ || !(boxFitShown_->shot == doc_->shot())) return std::nullopt;
  for (const auto& [boxName, corners] : boxFitShown_->boxes) {
    if (boxName != name) continue;
    std::array<glm::dvec2, 8> px{};
    for (int k = 0; k < 8; ++k) {
      const glm::dvec3 q = metrology::projectToPixel(live_.measurement->camera, live_.measurement->pose, corners[k]);
      if (!(q.z > 0)) return std::nullopt;
      px[k] = metrology::distortPixel(live_.measurement->camera, glm::dvec2(q));
    }
    return px;
  }
  return std::nullopt;
}

void EditMode::drawCutoutOverlay(ImDrawList* list) const {
  if (!doc_) return;
  // Each box as fitted: its twelve edges.
  for (const Cutout& cutout : doc_->shot().cutouts) {
    const auto box = cutout.shape == metrology::CutoutShape::kBox ? shownBoxPx(cutout.name) : std::nullopt;
    if (!box) continue;
    for (int k = 0; k < 4; ++k) {
      for (const auto& [a, b] : {std::pair{k, (k + 1) % 4}, std::pair{4 + k, 4 + (k + 1) % 4}, std::pair{k, 4 + k}}) {
        const ImVec2 from = im(canvas_.toWindow((*box)[a])), to = im(canvas_.toWindow((*box)[b]));
        list->AddLine(from, to, kCutoutShadow, 2.5f);
        list->AddLine(from, to, kCutoutColour, 1.0f);
      }
    }
  }
  for (const Cutout& cutout : doc_->shot().cutouts) {
    // One the model could not stand up: in the warnings' colour, and said on its label.
    const bool painted = leftPainted(cutout.name).has_value();
    const ImU32 colour = painted ? ImGui::ColorConvertFloat4ToU32(ui::kWarningColour)
                         : cutout.shape == metrology::CutoutShape::kOpening ? kOpeningColour
                                                                             : kCutoutColour;
    std::vector<ImVec2> ring;
    for (const glm::dvec2& p : cutout.outlinePx) ring.push_back(im(canvas_.toWindow(p)));
    list->AddPolyline(ring.data(), static_cast<int>(ring.size()), kCutoutShadow, ImDrawFlags_Closed, 3.5f);
    list->AddPolyline(ring.data(), static_cast<int>(ring.size()), colour, ImDrawFlags_Closed, 1.5f);
    glm::dvec2 top = cutout.outlinePx.front();
    for (const glm::dvec2& p : cutout.outlinePx) top = p.y < top.y ? p : top;
    ui::labelOnPlate(list, im(canvas_.toWindow(top) + glm::dvec2(4, -18)), painted ? cutout.name + " (left painted)" : cutout.name,
                     colour);
  }
  if (!outlining_) return;
  if (!outlinePolygon_.empty()) {
    std::vector<ImVec2> line;
    for (const glm::dvec2& p : outlinePolygon_) line.push_back(im(canvas_.toWindow(p)));
    line.push_back(im(cursorPx_));
    list->AddPolyline(line.data(), static_cast<int>(line.size()), kCutoutShadow, ImDrawFlags_None, 3.0f);
    list->AddPolyline(line.data(), static_cast<int>(line.size()), (kCutoutColour & 0x00ffffff) | (200u << 24), ImDrawFlags_None, 1.0f);
    const ImVec2 first = line.front();
    const bool closes = outlinePolygon_.size() >= 3 && glm::length(cursorPx_ - glm::dvec2(first.x, first.y)) <= kCloseRadiusPx;
    for (size_t i = 0; i + 1 < line.size(); ++i) list->AddCircleFilled(line[i], 2.5f, kCutoutColour);
    list->AddCircle(first, float(kCloseRadiusPx), closes ? kCutoutColour : kCutoutShadow, 0, closes ? 2.5f : 1.5f);
    return;
  }
  if (!outlineFrom_) return;
  const std::array<glm::dvec2, 4> corners = rectangle(*outlineFrom_, canvas_.toPhoto(cursorPx_));
  std::array<ImVec2, 4> ring{};
  for (int i = 0; i < 4; ++i) ring[i] = im(canvas_.toWindow(corners[i]));
  list->AddPolyline(ring.data(), 4, kCutoutShadow, ImDrawFlags_Closed, 3.0f);
  list->AddPolyline(ring.data(), 4, (kCutoutColour & 0x00ffffff) | (200u << 24), ImDrawFlags_Closed, 1.0f);
}

void EditMode::drawCutouts(app::Shell& shell) {
  const Shot& shot = doc_->shot();
  if (!ImGui::CollapsingHeader("Standing objects (U) and openings (O)", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const bool standingUp = outlining_ && outlineShape_ != metrology::CutoutShape::kOpening;
  const bool opening = outlining_ && outlineShape_ == metrology::CutoutShape::kOpening;
  if (ImGui::SmallButton(standingUp ? "standing up: drag a rectangle or click a polygon (Esc)" : "stand up (U)")) {
    setOutlining(shell, !standingUp);
  }
  rememberWidget("stand up");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("a person, a plant, a bin: drag a rectangle around it, down to its foot,\n"
                      "or click a polygon around it (the first point again, or Enter, closes it);\n"
                      "the model stands it up on the floor instead of painting it on the wall");
  }
  ImGui::SameLine();
  if (ImGui::SmallButton(opening ? "opening: drag a rectangle or click its corners (Esc)" : "open (O)")) {
    setOutlining(shell, !opening, metrology::CutoutShape::kOpening);
  }
  rememberWidget("open");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("a doorway or an opening in a side wall: drag a rectangle around it, or click its corners;\n"
                      "the model opens the wall there, with a room behind it, instead of painting it on the wall");
  }
  if (shot.cutouts.empty()) {
    ImGui::TextDisabled("none: U (an object) or O (a doorway), then drag a rectangle or click a polygon");
    return;
  }
  cutoutNameBuffers_.resize(shot.cutouts.size());
  for (size_t i = 0; i < shot.cutouts.size(); ++i) {
    const Cutout& cutout = shot.cutouts[i];
    ImGui::PushID(static_cast<int>(1000 + i));
    if (ImGui::SmallButton("x")) deleteCutout(shell, i);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("paint it flat again (Ctrl+Z brings it back)");
    ImGui::SameLine();
    const std::optional<std::string> typed =
        ui::nameField("##cutout", cutout.name, cutoutNameBuffers_[i], renamingCutout_, static_cast<int>(i), 140.0f);
    rememberWidget(("cutout " + std::to_string(i + 1)).c_str());
    if (typed) {
      const bool taken = std::any_of(shot.cutouts.begin(), shot.cutouts.end(), [&](const Cutout& c) { return c.name == *typed; });
      if (typed->empty() || taken) {
        shell.showMessage(typed->empty() ? "stand up: a standing object needs a name"
                                         : "stand up: another standing object is called \"" + *typed + "\"");
      } else {
        Shot after = shot;
        after.cutouts[i].name = *typed;
        applyEdit(shell, after, "name " + *typed);
      }
    }
    // Its shape: each box ticked makes it that shape, unticked a flat cut-out again.
    for (const ShapeChoice& choice : kShapeChoices) {
      ImGui::SameLine();
      bool on = cutout.shape == choice.shape;
      if (ImGui::Checkbox(choice.label, &on)) setCutoutShape(shell, i, on ? choice.shape : metrology::CutoutShape::kFlat);
      rememberWidget(("cutout " + std::to_string(i + 1) + " " + choice.label).c_str());
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", choice.tooltip);
    }
    if (const std::optional<std::string> why = leftPainted(cutout.name)) ui::wrapped(ui::kWarningColour, "left painted: " + *why);
    ImGui::PopID();
  }
}

std::optional<std::string> EditMode::leftPainted(const std::string& cutoutName) const {
  if (!doc_) return std::nullopt;
  const std::shared_ptr<const engine::Scene> built = preview_.fullSceneOf(doc_->modelShot());
  return built ? modeling::leftPaintedReason(*built, cutoutName) : std::nullopt;
}

void EditMode::addCutoutsTrace(app::TraceRow& row) const {
  ordered_json cutouts = ordered_json::array();
  if (doc_) {
    for (const Cutout& c : doc_->shot().cutouts) {
      ordered_json outline = ordered_json::array();
      for (const glm::dvec2& p : c.outlinePx) outline.push_back({p.x, p.y});
      ordered_json entry = {{"name", c.name}, {"outline_px", outline},
                            {"shape", c.shape == metrology::CutoutShape::kBox       ? "box"
                                      : c.shape == metrology::CutoutShape::kOpening ? "opening"
                                      : c.shape == metrology::CutoutShape::kHanging ? "hanging"
                                                                                    : "flat"}};
      if (const auto box = c.shape == metrology::CutoutShape::kBox ? shownBoxPx(c.name) : std::nullopt) {
        ordered_json corners = ordered_json::array();
        for (const glm::dvec2& p : *box) corners.push_back({p.x, p.y});
        entry["box_px"] = corners;  // as drawn: the front's four, then the back's
      }
      const std::optional<std::string> why = leftPainted(c.name);
      entry["left_painted"] = why ? ordered_json(*why) : ordered_json(nullptr);
      cutouts.push_back(std::move(entry));
    }
  }
  row.add("cutouts", cutouts);
  ordered_json polygon = ordered_json::array();
  for (const glm::dvec2& p : outlinePolygon_) polygon.push_back({p.x, p.y});
  row.add("outlining", ordered_json{{"active", outlining_},
                                    {"from_px", outlineFrom_ ? ordered_json::array({outlineFrom_->x, outlineFrom_->y})
                                                             : ordered_json(nullptr)},
                                    {"polygon_px", polygon}});
}

}  // namespace pw::edit
