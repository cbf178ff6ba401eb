// The editor's stand-up tool (issue 25, part 3): U, then a rectangle dragged around an
// object on the photo (a person, a plant, a bin), down to where it stands on the floor,
// stands it up in the model as a cut-out (modeling/stand_up.h: GrabCut finds the object
// inside the rectangle) instead of painting it flat on the floor and the wall behind it.
// Each is kept in the shot's "cutouts" (one undo step), drawn on the photo with its
// name, listed in the panel's "Standing objects" with a name field and a delete button,
// and traced ("cutouts", "outlining"); the 3D preview and W's model stand it up. A
// rectangle the model cannot stand up (its foot off the photo, above the horizon, beyond
// the corridor's floor) is refused with the reason, and nothing changes.
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>

#include "editor/app/shell.h"
#include "editor/edit/edit_mode.h"
#include "editor/edit/panel_style.h"
#include "modeling/stand_up.h"

namespace pw::edit {
namespace {

using metrology::Cutout;
using metrology::Shot;
using nlohmann::ordered_json;

const ImU32 kCutoutColour = IM_COL32(120, 255, 170, 255);
const ImU32 kCutoutShadow = IM_COL32(0, 0, 0, 200);
constexpr double kMinCutoutPx = 4;  // a rectangle at least this wide and high (photo pixels)

ImVec2 im(const glm::dvec2& p) { return {float(p.x), float(p.y)}; }

// "object N" with the first N no cutout is called.
std::string freeCutoutName(const Shot& shot) {
  for (int n = 1;; ++n) {
    const std::string name = "object " + std::to_string(n);
    if (std::none_of(shot.cutouts.begin(), shot.cutouts.end(), [&](const Cutout& c) { return c.name == name; })) return name;
  }
}

std::array<glm::dvec2, 4> rectangle(glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 lo = glm::min(a, b), hi = glm::max(a, b);
  return {lo, glm::dvec2(hi.x, lo.y), hi, glm::dvec2(lo.x, hi.y)};
}

}  // namespace

void EditMode::setOutlining(app::Shell& shell, bool on) {
  outlining_ = on && doc_.has_value();
  outlineFrom_.reset();
  if (outlining_) {
    measuring_ = false;
    measureFrom_.reset();
    pickingReference_ = false;
    shell.showMessage("stand up: drag a rectangle around an object, down to where it stands on the floor; Esc: stop");
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
  const std::array<glm::dvec2, 4> corners = rectangle(from, at);
  if (corners[2].x - corners[0].x < kMinCutoutPx || corners[2].y - corners[0].y < kMinCutoutPx) {
    shell.showMessage("stand up: drag a rectangle around the object (this one is too small)");
    return true;
  }
  if (!live_.measurement) {
    shell.showMessage("stand up: the corners do not measure yet: " + live_.error);
    return true;
  }
  Shot after = doc_->shot();
  Cutout cutout{freeCutoutName(after), {corners.begin(), corners.end()}};
  // Stood up now, alone, for its errors (the model stands them all up again).
  auto stood = modeling::standUpObjects(doc_->photo(), *live_.measurement, {cutout});
  if (!stood) {
    shell.showMessage("stand up: " + stood.message());
    return true;
  }
  const modeling::StandingObject& object = stood->objects.front();
  char said[160];
  std::snprintf(said, sizeof said, "stood up %s: %.2f m high, %.2f m wide, %.1f m from the camera", cutout.name.c_str(),
                object.heightM, object.widthM, object.distanceM);
  after.cutouts.push_back(std::move(cutout));
  applyEdit(shell, after, "stand up " + after.cutouts.back().name);
  shell.showMessage(said);
  return true;
}

void EditMode::deleteCutout(app::Shell& shell, size_t index) {
  if (!doc_ || index >= doc_->shot().cutouts.size()) return;
  Shot after = doc_->shot();
  const std::string name = after.cutouts[index].name;
  after.cutouts.erase(after.cutouts.begin() + static_cast<long>(index));
  applyEdit(shell, after, "delete " + name);
}

void EditMode::drawCutoutOverlay(ImDrawList* list) const {
  if (!doc_) return;
  for (const Cutout& cutout : doc_->shot().cutouts) {
    std::vector<ImVec2> ring;
    for (const glm::dvec2& p : cutout.outlinePx) ring.push_back(im(canvas_.toWindow(p)));
    list->AddPolyline(ring.data(), static_cast<int>(ring.size()), kCutoutShadow, ImDrawFlags_Closed, 3.5f);
    list->AddPolyline(ring.data(), static_cast<int>(ring.size()), kCutoutColour, ImDrawFlags_Closed, 1.5f);
    glm::dvec2 top = cutout.outlinePx.front();
    for (const glm::dvec2& p : cutout.outlinePx) top = p.y < top.y ? p : top;
    ui::labelOnPlate(list, im(canvas_.toWindow(top) + glm::dvec2(4, -18)), cutout.name, kCutoutColour);
  }
  if (!outlining_ || !outlineFrom_) return;
  const std::array<glm::dvec2, 4> corners = rectangle(*outlineFrom_, canvas_.toPhoto(cursorPx_));
  std::array<ImVec2, 4> ring{};
  for (int i = 0; i < 4; ++i) ring[i] = im(canvas_.toWindow(corners[i]));
  list->AddPolyline(ring.data(), 4, kCutoutShadow, ImDrawFlags_Closed, 3.0f);
  list->AddPolyline(ring.data(), 4, (kCutoutColour & 0x00ffffff) | (200u << 24), ImDrawFlags_Closed, 1.0f);
}

void EditMode::drawCutouts(app::Shell& shell) {
  const Shot& shot = doc_->shot();
  if (!ImGui::CollapsingHeader("Standing objects (U)", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (ImGui::SmallButton(outlining_ ? "standing up: drag a rectangle (Esc)" : "stand up (U)")) setOutlining(shell, !outlining_);
  rememberWidget("stand up");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("a person, a plant, a bin: drag a rectangle around it, down to its foot;\n"
                      "the model stands it up on the floor instead of painting it on the wall");
  }
  if (shot.cutouts.empty()) {
    ImGui::TextDisabled("none: U, then drag a rectangle around an object");
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
    ImGui::PopID();
  }
}

void EditMode::addCutoutsTrace(app::TraceRow& row) const {
  ordered_json cutouts = ordered_json::array();
  if (doc_) {
    for (const Cutout& c : doc_->shot().cutouts) {
      ordered_json outline = ordered_json::array();
      for (const glm::dvec2& p : c.outlinePx) outline.push_back({p.x, p.y});
      cutouts.push_back({{"name", c.name}, {"outline_px", outline}});
    }
  }
  row.add("cutouts", cutouts);
  row.add("outlining", ordered_json{{"active", outlining_},
                                    {"from_px", outlineFrom_ ? ordered_json::array({outlineFrom_->x, outlineFrom_->y})
                                                             : ordered_json(nullptr)}});
}

}  // namespace pw::edit
