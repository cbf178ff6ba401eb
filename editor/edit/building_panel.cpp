// Building mode's ImGui: the side panel (layout, corridors, placement, adding a shot,
// keys) and the plan drawn on the window's background draw list.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <cmath>
#include <cstdio>

#include "editor/edit/panel_style.h"
#include "editor/app/shell.h"
#include "editor/edit/building_mode.h"
#include "editor/edit/overlay.h"

namespace pw::edit {
namespace {

using namespace ui;  // panel_style.h

using modeling::Layout;
using modeling::Side;


const char* const kPlanKeys =
    "left drag a corridor  move it; its near end snaps to\n"
    "                      a far wall or a side wall (Alt: no snap)\n"
    "drag the round handle turn it (Shift: 15-degree steps)\n"
    "R, Shift+R            turn the selected one 90 degrees left, right (an attached\n"
    "                      one: the corridor it hangs from turns, carrying it)\n"
    "wheel                 zoom about the cursor\n"
    "middle/right drag     pan\n"
    "F                     fit the building\n"
    "Tab, Shift+Tab        next, previous corridor\n"
    "E, Enter, dbl-click   edit its shot's corners (B: back)\n"
    "Delete                remove it from the layout\n"
    "Esc                   cancel a drag\n"
    "Ctrl+Z; Ctrl+Shift+Z, Ctrl+Y  undo; redo (plan edits)\n"
    "Ctrl+S                save the layout and its shots\n"
    "W                     walk the whole building (Esc: back)\n"
    "drag, wheel on the 3D preview  orbit, nearer or farther";

ImU32 colour(const glm::u8vec4& c, int alpha = 255) { return IM_COL32(c.r, c.g, c.b, alpha); }
ImVec2 im(const glm::dvec2& p) { return {float(p.x), float(p.y)}; }

const char* const kSides[] = {"far", "left", "right"};

}  // namespace

void BuildingMode::drawUi(app::Shell& shell) {
  layOut(shell);
  uiRects_.clear();
  if (building_) drawPlan();
  drawPanel(shell);
  if (building_) preview_.drawUi();
  drawQuestion(shell);
}

void BuildingMode::drawPanel(app::Shell& shell) {
  ImGui::SetNextWindowPos({float(windowSize_.x - panelWidthPx_), 0.0f}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({float(panelWidthPx_), float(panelHeightPx_)}, ImGuiCond_Always);
  ImGui::Begin("photowalk building", nullptr, kFixedWindow);
  uiRects_.push_back(currentWindowRect());
  if (!building_) {
    ImGui::TextWrapped("No layout open: photowalk edit LAYOUT.json, or drop one on this window.");
    if (!openError_.empty()) wrapped(kErrorColour, "error: " + openError_);
    ImGui::End();
    return;
  }
  ImGui::Text("%s%s", building_->path().filename().string().c_str(), dirty() ? "  (unsaved)" : "");
  ImGui::PushStyleColor(ImGuiCol_Text, kNoteColour);
  ImGui::TextWrapped("saves to %s", building_->path().string().c_str());
  ImGui::PopStyleColor();
  if (ImGui::Button("Save")) save(shell);
  ImGui::SameLine();
  ImGui::BeginDisabled(!building_->canUndo());
  if (ImGui::Button("Undo")) undo(shell);
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!building_->canRedo());
  if (ImGui::Button("Redo")) redo(shell);
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Walk (W)")) walk(shell);
  if (!openError_.empty()) wrapped(kErrorColour, "error: " + openError_);
  if (!planError_.empty()) wrapped(kErrorColour, planError_);
  for (const std::string& warning : planWarnings_) wrapped(kWarningColour, "warning: " + warning);
  drawCorridorList(shell);
  drawPlacement(shell);
  drawAddShot(shell);
  if (ImGui::CollapsingHeader("Keys")) ImGui::TextUnformatted(kPlanKeys);
  ImGui::End();
}

void BuildingMode::drawCorridorList(app::Shell& shell) {
  if (!ImGui::CollapsingHeader("Corridors", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const Layout& layout = building_->layout();
  for (size_t i = 0; i < layout.corridors.size(); ++i) {
    const modeling::LayoutEntry& entry = layout.corridors[i];
    const Document* doc = building_->lent() == entry.shot ? lentShot() : building_->shot(entry.shot);
    char line[256];
    std::snprintf(line, sizeof line, "%s%s  %.2f x %.2f m%s", entry.name.c_str(), doc && doc->dirty() ? " *" : "",
                  i < boxes_.size() ? boxes_[i].widthM : 0.0, i < boxes_.size() ? boxes_[i].lengthM : 0.0,
                  building_->measured(int(i)) ? "" : " (not measured)");
    ImGui::PushID(int(i));
    if (ImGui::Selectable(line, entry.name == selected_, ImGuiSelectableFlags_AllowDoubleClick)) {
      selected_ = entry.name;
      if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) editShot(shell, int(i));
    }
    ImGui::PopID();
    ImGui::PushStyleColor(ImGuiCol_Text, kNoteColour);
    ImGui::Text("   %s", entry.shot.filename().string().c_str());
    if (entry.attach && entry.attach->to >= 0 && size_t(entry.attach->to) < layout.corridors.size()) {
      ImGui::SameLine();
      ImGui::Text(" on %s's %s wall", layout.corridors[entry.attach->to].name.c_str(), kSides[int(entry.attach->side)]);
    }
    ImGui::PopStyleColor();
    const std::string problem = building_->problem(int(i));
    if (!problem.empty()) wrapped(kErrorColour, "   " + problem);
  }
  ImGui::BeginDisabled(selectedIndex() < 0);
  if (ImGui::Button("Edit its corners (E)")) editShot(shell, selectedIndex());
  ImGui::EndDisabled();
}

void BuildingMode::drawPlacement(app::Shell& shell) {
  const int i = selectedIndex();
  if (i < 0 || size_t(i) >= world_.size()) return;
  if (!ImGui::CollapsingHeader("Placement", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const Layout& layout = building_->layout();
  const modeling::LayoutEntry& entry = layout.corridors[i];
  ImGui::Text("%s", entry.name.c_str());
  // Attached to: "(placed)" or a corridor that does not move with this one.
  const std::vector<bool> moving = movesWith(layout, i);
  const std::string current = entry.attach ? layout.corridors[entry.attach->to].name : "(placed)";
  ImGui::SetNextItemWidth(160.0f);
  if (ImGui::BeginCombo("attached to", current.c_str())) {
    if (ImGui::Selectable("(placed)", !entry.attach)) {
      applyLayout(placeCorridor(layout, i, poseOf(world_[i])), "place " + entry.name);
    }
    for (size_t h = 0; h < layout.corridors.size(); ++h) {
      if (moving[h]) continue;
      if (ImGui::Selectable(layout.corridors[h].name.c_str(), entry.attach && entry.attach->to == int(h))) {
        const std::string name = entry.name;
        applyLayout(attachCorridor(layout, i, {int(h), Side::kFar, 0.0}, nullptr), "attach " + name);
        ImGui::EndCombo();
        return;  // the layout (and its order) changed under `entry`
      }
    }
    ImGui::EndCombo();
  }
  double v = 0;
  if (entry.attach) {
    int side = int(entry.attach->side);
    ImGui::SetNextItemWidth(120.0f);
    if (ImGui::Combo("wall", &side, kSides, 3) && side != int(entry.attach->side)) {
      Layout after = layout;
      modeling::Attachment& a = *after.corridors[i].attach;
      a.side = Side(side);
      if (a.side == Side::kFar) {
        a.offsetM = 0;
      } else {
        const double half = i < int(boxes_.size()) ? boxes_[i].widthM / 2 : 0.0;
        const double hostLength = boxes_[a.to].lengthM;
        a.offsetM = std::max(half, std::min(a.offsetM, hostLength - half));
      }
      applyLayout(after, "wall of " + entry.name);
      return;
    }
    if (fields_.field(shell, "offset m", entry.attach->offsetM, &v, "%.3f")) {
      Layout after = layout;
      after.corridors[i].attach->offsetM = v;
      applyLayout(after, "offset of " + entry.name);
      return;
    }
    fields_.drawRefusal("offset m");
    ImGui::TextDisabled(entry.attach->side == Side::kFar ? "(along its far wall, from the centre)"
                                                          : "(from its near end to this one's centre line)");
  } else {
    if (fields_.field(shell, "x m", entry.position.x, &v, "%.3f")) {
      Layout after = layout;
      after.corridors[i].position.x = v;
      applyLayout(after, "x of " + entry.name);
      return;
    }
    fields_.drawRefusal("x m");
    if (fields_.field(shell, "z m", entry.position.z, &v, "%.3f")) {
      Layout after = layout;
      after.corridors[i].position.z = v;
      applyLayout(after, "z of " + entry.name);
      return;
    }
    fields_.drawRefusal("z m");
    if (fields_.field(shell, "rotation deg", entry.rotationDeg, &v, "%.2f")) {
      applyLayout(placeCorridor(layout, i, {{entry.position.x, entry.position.z}, v}), "rotation of " + entry.name);
      return;
    }
    fields_.drawRefusal("rotation deg");
  }
}

void BuildingMode::drawAddShot(app::Shell& shell) {
  if (!ImGui::CollapsingHeader("Add a shot or photo", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::SetNextItemWidth(float(panelWidthPx_) - 80.0f);
  const bool entered = ImGui::InputText("##add-path", &addPath_, ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if ((ImGui::Button("Add") || entered) && !addPath_.empty()) {
    addShot(shell, addPath_);
    addPath_.clear();
  }
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("(a path, or drop the file on the plan)");
  ImGui::PopStyleColor();
}

void BuildingMode::drawPlan() {
  ImDrawList* list = ImGui::GetBackgroundDrawList();
  list->PushClipRect(im(planArea_.min), im(planArea_.max), false);
  // The grid: the smallest of 0.5, 1, 2, 5, 10... metres that is 30 pixels or more.
  double step = 0.5;
  for (const double s : {0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0}) {
    step = s;
    if (s * view_.scale >= 30) break;
  }
  const glm::dvec2 lo = view_.toPlan(planArea_.min), hi = view_.toPlan(planArea_.max);
  for (double x = std::floor(lo.x / step) * step; x <= hi.x; x += step) {
    const double wx = view_.toWindow({x, 0}).x;
    list->AddLine({float(wx), float(planArea_.min.y)}, {float(wx), float(planArea_.max.y)},
                  std::abs(x) < 1e-9 ? IM_COL32(110, 110, 125, 255) : IM_COL32(55, 58, 66, 255));
  }
  for (double z = std::floor(lo.y / step) * step; z <= hi.y; z += step) {
    const double wz = view_.toWindow({0, z}).y;
    list->AddLine({float(planArea_.min.x), float(wz)}, {float(planArea_.max.x), float(wz)},
                  std::abs(z) < 1e-9 ? IM_COL32(110, 110, 125, 255) : IM_COL32(55, 58, 66, 255));
  }

  const ImU32 farColour = colour(roleColour(CornerRole::kFarWall));
  const ImU32 nearColour = colour(roleColour(CornerRole::kNearFloor));
  const int selected = selectedIndex();
  const auto& corridors = building_->layout().corridors;
  for (size_t i = 0; i < world_.size() && i < boxes_.size() && i < corridors.size(); ++i) {
    const std::array<glm::dvec2, 4> c = footprintCorners(world_[i], boxes_[i]);
    std::array<ImVec2, 4> w;
    for (int k = 0; k < 4; ++k) w[k] = im(view_.toWindow(c[k]));
    const bool isSelected = int(i) == selected;
    const bool measured = building_->measured(int(i));
    list->AddQuadFilled(w[0], w[1], w[2], w[3], isSelected ? IM_COL32(90, 120, 170, 150) : IM_COL32(80, 85, 100, 120));
    list->AddQuad(w[0], w[1], w[2], w[3], measured ? IM_COL32(200, 200, 210, 255) : IM_COL32(255, 110, 100, 255),
                  isSelected ? 2.0f : 1.0f);
    list->AddLine(w[0], w[1], nearColour, 3.0f);  // the near end (P5-P6)
    list->AddLine(w[2], w[3], farColour, 3.0f);   // the far wall
    const glm::dvec2 centre = view_.toWindow(0.25 * (c[0] + c[1] + c[2] + c[3]));
    char label[160];
    std::snprintf(label, sizeof label, "%s\n%.2f x %.2f m%s", corridors[i].name.c_str(), boxes_[i].widthM,
                  boxes_[i].lengthM, measured ? "" : "\n(not measured)");
    const ImVec2 size = ImGui::CalcTextSize(label);
    list->AddText({float(centre.x) - size.x / 2, float(centre.y) - size.y / 2}, IM_COL32(255, 255, 255, 255), label);
  }
  // The openings: where an attached corridor's near end opens the wall of its host.
  for (size_t i = 0; i < corridors.size(); ++i) {
    if (const auto opening = openingInHost(building_->layout(), boxes_, world_, int(i))) {
      list->AddLine(im(view_.toWindow((*opening)[0])), im(view_.toWindow((*opening)[1])), IM_COL32(255, 255, 255, 255),
                    4.0f);
    }
  }
  // The wall a drag snaps to.
  if (drag_ && drag_->snap) {
    const int host = drag_->snap->attach.to;
    const std::vector<metrology::Dimensions> boxes = building_->boxesFor(drag_->before);
    const std::vector<glm::dmat4> world = placeCorridors(drag_->before, boxes);
    if (host >= 0 && size_t(host) < world.size()) {
      const std::array<glm::dvec2, 4> c = footprintCorners(world[host], boxes[host]);
      const Side side = drag_->snap->attach.side;
      const glm::dvec2 a = side == Side::kFar ? c[2] : side == Side::kLeft ? c[0] : c[1];
      const glm::dvec2 b = side == Side::kFar ? c[3] : side == Side::kLeft ? c[3] : c[2];
      list->AddLine(im(view_.toWindow(a)), im(view_.toWindow(b)), IM_COL32(80, 230, 255, 255), 5.0f);
    }
  }
  if (const std::optional<glm::dvec2> handle = turnHandle(selected)) {
    const glm::dvec4 far = world_[selected] * glm::dvec4(0, 0, -boxes_[selected].lengthM, 1);
    list->AddLine(im(view_.toWindow({far.x, far.z})), im(*handle), IM_COL32(255, 255, 255, 200), 1.5f);
    list->AddCircleFilled(im(*handle), 6.0f, IM_COL32(255, 255, 255, 230));
    list->AddCircle(im(*handle), 6.0f, IM_COL32(40, 40, 40, 255));
  }

  // A status line: the scale, the cursor in metres, the drag's snap.
  char status[200];
  int used = std::snprintf(status, sizeof status, "plan: %.3g px per m, grid %.3g m", view_.scale, step);
  if (planArea_.contains(cursorPx_) && used > 0 && size_t(used) < sizeof status) {
    const glm::dvec2 p = view_.toPlan(cursorPx_);
    used += std::snprintf(status + used, sizeof status - used, "   cursor (%.2f, %.2f) m", p.x, p.y);
  }
  if (drag_ && drag_->snap && used > 0 && size_t(used) < sizeof status) {
    std::snprintf(status + used, sizeof status - used, "   snaps: %s wall of %s, offset %.2f m",
                  kSides[int(drag_->snap->attach.side)], drag_->before.corridors[drag_->snap->attach.to].name.c_str(),
                  drag_->snap->attach.offsetM);
  }
  const ImVec2 at(float(planArea_.min.x) + 8, float(planArea_.min.y) + 6);
  const ImVec2 size = ImGui::CalcTextSize(status);
  list->AddRectFilled({at.x - 4, at.y - 2}, {at.x + size.x + 4, at.y + size.y + 2}, IM_COL32(0, 0, 0, 150), 3.0f);
  list->AddText(at, IM_COL32(255, 255, 255, 255), status);
  list->PopClipRect();
}

}  // namespace pw::edit
