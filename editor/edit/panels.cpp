// The editor's ImGui: the side panel (document, measurement, warnings, camera,
// corners, keys), the overlay on the canvas, and the hint when nothing is open.
#include <imgui.h>

#include <cmath>
#include <cstdio>

#include "editor/edit/panel_style.h"
#include "editor/app/shell.h"
#include "editor/edit/edit_mode.h"

namespace pw::edit {
namespace {

using namespace ui;  // panel_style.h

using metrology::kCornerCount;
using metrology::Shot;


const char* const kKeys =
    "wheel              zoom about the cursor\n"
    "middle/right drag  pan (or Space + left drag)\n"
    "F, 1               fit the photo; 1:1\n"
    "H                  hide/show the handles and guides\n"
    "drag a handle      move the corner (Shift: 10x slower); released by an edge\n"
    "                   junction (the ring), it snaps there (Alt: stays put)\n"
    "Tab, Shift+Tab     next, previous corner\n"
    "Alt+1..8           select P1..P8\n"
    "arrow keys         nudge 1 px (Shift: 0.1 px)\n"
    "E                  fit the corners to the photo's edges\n"
    "M                  measure: two clicks (Shift: a height)\n"
    "U                  stand up: drag a rectangle around an object\n"
    "O                  open: drag a rectangle around a doorway in a side wall\n"
    "Esc                cancel a drag\n"
    "Ctrl+Z             undo\n"
    "Ctrl+Shift+Z, Ctrl+Y  redo\n"
    "Ctrl+S             save\n"
    "Ctrl+Shift+S       save as (the file browser)\n"
    "Ctrl+O             open a photo or shot file\n"
    "W                  walk through the model (Esc: back)\n"
    "B                  back to the building's plan (a layout open)\n"
    "P                  show/hide the 3D preview\n"
    "drag, wheel on it  orbit the preview; zoom it\n"
    "F1                 keys";

ImVec4 roleColourVec(int corner) {
  const glm::u8vec4 c = roleColour(cornerRole(corner));
  return ImVec4(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, 1.0f);
}

// The canvas less the loupe: up to four rectangles around it.
std::vector<WindowRect> around(const WindowRect& area, const WindowRect& hole) {
  const WindowRect h{glm::max(hole.min - 1.0, area.min), glm::min(hole.max + 1.0, area.max)};
  std::vector<WindowRect> pieces = {{area.min, {area.max.x, h.min.y}},
                                    {{area.min.x, h.max.y}, area.max},
                                    {{area.min.x, h.min.y}, {h.min.x, h.max.y}},
                                    {{h.max.x, h.min.y}, {area.max.x, h.max.y}}};
  std::erase_if(pieces, [](const WindowRect& r) { return r.empty(); });
  return pieces;
}

}  // namespace

void EditMode::drawUi(app::Shell& shell) {
  layOut(shell);
  uiRects_.clear();
  if (doc_) drawCanvasOverlay();
  else drawEmptyHint(shell);
  drawPanel(shell);
  if (!preview_.drawUi(previewToolbar_, /*showBox=*/true)) {
    preview_.setShown(false);
    layOut(shell);
  }
  drawFiles(shell);
  if (showKeys_) {
    ImGui::SetNextWindowPos({16, 40}, ImGuiCond_Appearing);
    ImGui::Begin("Keys", &showKeys_, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
    ImGui::TextUnformatted(kKeys);
    uiRects_.push_back(currentWindowRect());
    ImGui::End();
  }
}

void EditMode::drawEmptyHint(app::Shell& shell) {
  const glm::dvec2 centre = canvas_.area().centre();
  ImGui::SetNextWindowPos({float(centre.x), float(centre.y)}, ImGuiCond_Always, {0.5f, 0.5f});
  ImGui::SetNextWindowSizeConstraints({0, 0}, {float(canvas_.area().size().x - 20), 1e6f});
  ImGui::Begin("##empty", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoFocusOnAppearing);
  ImGui::TextUnformatted("No photo open.");
  drawOpenChoices(shell);
  if (!openError_.empty()) wrapped(kErrorColour, "error: " + openError_);
  uiRects_.push_back(currentWindowRect());
  ImGui::End();
}

void EditMode::drawPanel(app::Shell& shell) {
  ImGui::SetNextWindowPos({float(windowSize_.x - panelWidthPx_), 0.0f}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({float(panelWidthPx_), float(panelHeightPx_)}, ImGuiCond_Always);
  ImGui::Begin("photowalk edit", nullptr, kFixedWindow);
  uiRects_.push_back(currentWindowRect());
  if (!doc_) {
    ImGui::TextWrapped("No file open. F1: keys.");
    if (!openError_.empty()) wrapped(kErrorColour, "error: " + openError_);
    ImGui::End();
    return;
  }
  const bool dirty = doc_->dirty();
  // The file's name; where it saves (its whole path) when the name is hovered.
  ImGui::Text("%s%s", doc_->path().filename().string().c_str(), dirty ? "  (unsaved)" : "");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("saves to %s", doc_->path().string().c_str());
  // Three rows: the file, the edits and the views, the exports and the preview.
  if (ImGui::Button("Save")) save(shell);
  ImGui::SameLine();
  if (ImGui::Button("Save As...")) openBrowser(shell, BrowserPurpose::kSaveAs);
  ImGui::SameLine();
  if (ImGui::Button("Open...")) openBrowser(shell, BrowserPurpose::kOpen);
  ImGui::BeginDisabled(!doc_->history().canUndo());
  if (ImGui::Button("Undo")) undo(shell);
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!doc_->history().canRedo());
  if (ImGui::Button("Redo")) redo(shell);
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Fit (E)")) fitCorners(shell);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("fit the eight corners to the photo's edges from where they are");
  ImGui::SameLine();
  ImGui::BeginDisabled(!live_.measurement || pendingWalk_.has_value());
  if (ImGui::Button("Walk (W)")) walk(shell);
  ImGui::EndDisabled();
  if (!planMode_.empty()) {
    ImGui::SameLine();
    if (ImGui::Button("Plan (B)")) shell.requestMode(planMode_);
  }
  drawExportButtons(shell);
  // The preview's box: in its toolbar while it is shown; else beside the exports when it
  // fits in the panel, else below them.
  if (!preview_.shown()) {
    const float boxWidth = ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x +
                           ImGui::CalcTextSize("3D preview (P)").x;
    if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + boxWidth <=
        ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) {
      ImGui::SameLine();
    }
    bool preview = false;
    if (ImGui::Checkbox("3D preview (P)", &preview)) {
      preview_.setShown(preview);
      layOut(shell);
    }
  }
  if (files_.exporting) ImGui::TextDisabled("exporting %s...", files_.exporting->path.filename().string().c_str());
  if (pendingWalk_) {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - pendingWalk_->started).count();
    ImGui::TextDisabled("building the walk's model... %.1f s", s);
  }
  if (!openError_.empty()) wrapped(kErrorColour, "error: " + openError_);
  for (const std::string& note : doc_->notes()) wrapped(kNoteColour, note);
  drawMeasurement();
  drawCamera(shell);
  drawMeasurements(shell);
  drawCutouts(shell);
  drawCorners(shell);
  if (ImGui::CollapsingHeader("Keys")) ImGui::TextUnformatted(kKeys);
  ImGui::End();
}

void EditMode::drawMeasurement() {
  if (!ImGui::CollapsingHeader("Measurement", ImGuiTreeNodeFlags_DefaultOpen)) return;
  // The dimensions (or why there are none) and the warnings, in a block of one height
  // whatever it holds (it scrolls when they are more): the panel below it, the Camera
  // fields, does not move when a measurement appears or fails or a warning comes, so a
  // second click at the same place hits the same widget.
  // (An unsure detection's box is said to be a suggestion above it, until a corner moves.)
  const metrology::Measurement* m = live_.measurement ? &*live_.measurement : nullptr;
  if (m && doc_->isSuggestedBox()) {
    wrapped(kWarningColour, "a suggestion, not a result: detection was unsure of this box (the notes say why); "
                            "check each corner");
  }
  const float lines = 5.0f;
  ImGui::BeginChild("##dimensions", ImVec2(0.0f, lines * ImGui::GetTextLineHeightWithSpacing()), false);
  if (m) {
    // Where one input is most of all three ±, it is said once, under them (a line each
    // instead of two).
    const metrology::SigmaSource* top = metrology::dominantSigmaSource(*m, 0);
    bool shared = top && m->sigmaSources.size() > 1;
    for (int which = 1; shared && which < 3; ++which) {
      const metrology::SigmaSource* other = metrology::dominantSigmaSource(*m, which);
      shared = other && other->name == top->name;
    }
    static const char* const kNames[3] = {"width   ", "height  ", "length  "};
    for (int which = 0; which < 3; ++which) {
      wrapped(ImGui::GetStyleColorVec4(ImGuiCol_Text),
              kNames[which] + (shared ? metrology::dimensionText(metrology::dimensionOf(m->size, which),
                                                                 metrology::dimensionOf(m->sigma, which))
                                      : metrology::dimensionWithSource(*m, which)));
    }
    wrapped(ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled),
            shared ? "(\xc2\xb1 1 sigma, mostly: " + top->name + ")" : "(\xc2\xb1 one sigma of every input)");
  } else {
    wrapped(kErrorColour, "cannot measure: " + live_.error);
  }
  for (const HandleWarning& w : live_.handleWarnings) {  // handle_warnings.h: also on the handles
    wrapped(w.blocking ? kErrorColour : kWarningColour, w.label + ": " + w.text);
  }
  if (m) {
    for (const std::string& warning : live_.warnings) wrapped(kWarningColour, "warning: " + warning);
  }
  ImGui::EndChild();
  // The rest folded by default: the Camera fields stay within reach of a 720-pixel window.
  if (ImGui::TreeNode("vanishing point, pose, residuals")) {
    if (!m) {
      ImGui::TextDisabled("(no measurement)");
      ImGui::TreePop();
      return;
    }
    const metrology::VanishingPoint& vp = m->vanishing.corridor;
    ImGui::Text("vanishing point (%.1f, %.1f) px", vp.px.x, vp.px.y);
    ImGui::Text("  residual %.2f px", vp.residualPx);
    ImGui::Text("yaw %.2f\xc2\xb0 pitch %.2f\xc2\xb0 roll %.2f\xc2\xb0", m->pose.yawDeg, m->pose.pitchDeg, m->pose.rollDeg);
    ImGui::Text("camera at (%.2f, %.2f, %.2f) m", m->pose.positionM.x, m->pose.positionM.y, m->pose.positionM.z);
    ImGui::Text("reprojection error %.2f px RMS", m->reprojectionRmsPx);
    if (m->reference) {
      ImGui::Text("reference %s-%s %.3f m (given %.3f)", metrology::cornerName(m->reference->from),
                  metrology::cornerName(m->reference->to), m->reference->measuredM, m->reference->givenM);
    }
    ImGui::TreePop();
  }
}

void EditMode::drawCorners(app::Shell& shell) {
  if (!ImGui::CollapsingHeader("Corners", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const Shot& shot = doc_->shot();
  for (int k = 0; k < kCornerCount; ++k) {
    char line[96];
    const std::optional<double> confidence = doc_->detectionConfidence(k);
    if (confidence) {
      std::snprintf(line, sizeof line, "%s  %9.2f %9.2f  detected %.2f", metrology::cornerName(k), shot.cornersPx[k].x,
                    shot.cornersPx[k].y, *confidence);
    } else {
      std::snprintf(line, sizeof line, "%s  %9.2f %9.2f", metrology::cornerName(k), shot.cornersPx[k].x,
                    shot.cornersPx[k].y);
    }
    ImGui::PushStyleColor(ImGuiCol_Text, roleColourVec(k));
    if (ImGui::Selectable(line, selected_ == k)) select(k);
    ImGui::PopStyleColor();
  }
  // The selected corner typed in (one undo step each, range-checked as every field).
  if (selected_ < 0 || selected_ >= kCornerCount) {
    ImGui::TextDisabled("click a corner to type its position");
    return;
  }
  Shot after = shot;
  double v = 0;
  bool edited = false;
  for (int axis = 0; axis < 2; ++axis) {
    const char* label = axis == 0 ? "corner u px" : "corner v px";
    const double side = axis == 0 ? shot.imageWidth : shot.imageHeight;
    if (fields_.field(shell, label, shot.cornersPx[selected_][axis], &v, "%.2f", side)) {
      after.cornersPx[selected_][axis] = v;
      edited = true;
    }
    rememberWidget(label);
    fields_.drawRefusal(label);
  }
  if (edited) {
    lastMoved_ = selected_;
    applyEdit(shell, after, std::string("type ") + metrology::cornerName(selected_));
  }
}

void EditMode::drawCanvasOverlay() {
  ImDrawList* list = ImGui::GetBackgroundDrawList();
  const Shot& shot = doc_->shot();
  OverlayInput input;
  input.canvas = &canvas_;
  input.shot = &shot;
  input.selected = selected_;
  input.vanishing = live_.vanishing ? &*live_.vanishing : nullptr;
  input.measurement = live_.measurement ? &*live_.measurement : nullptr;
  for (int k = 0; k < kCornerCount; ++k) input.confidence[k] = doc_->detectionConfidence(k);
  const std::optional<Loupe> magnifier = loupe();
  const std::vector<WindowRect> pieces =
      magnifier ? around(canvas_.area(), magnifier->rect) : std::vector<WindowRect>{canvas_.area()};
  if (showOverlay_) {
    const MeasuringNow measuring = measuringNow();
    for (const WindowRect& piece : pieces) {
      list->PushClipRect({float(piece.min.x), float(piece.min.y)}, {float(piece.max.x), float(piece.max.y)}, false);
      drawOverlay(list, input);
      drawCameraOverlay(list);
      drawMeasureOverlay(list, measuring);
      drawCutoutOverlay(list);
      list->PopClipRect();
    }
  }
  if (const std::optional<glm::dvec2> snap = currentSnap()) {
    // Where the corner goes on release: a ring on the edge junction, joined to the handle.
    const glm::dvec2 at = canvas_.toWindow(*snap), handle = canvas_.toWindow(shot.cornersPx[drag_->corner]);
    const ImU32 colour = IM_COL32(80, 230, 255, 255);
    list->AddLine({float(handle.x), float(handle.y)}, {float(at.x), float(at.y)}, colour, 1.0f);
    list->AddCircle({float(at.x), float(at.y)}, 7.0f, colour, 16, 2.0f);
    list->AddLine({float(at.x) - 4, float(at.y)}, {float(at.x) + 4, float(at.y)}, colour, 1.0f);
    list->AddLine({float(at.x), float(at.y) - 4}, {float(at.x), float(at.y) + 4}, colour, 1.0f);
  }
  if (magnifier) drawLoupe(list, *magnifier, shot);

  // A status line: the zoom, the selected corner, the photo pixel under the cursor.
  char status[160];
  int used = std::snprintf(status, sizeof status, "zoom %.3gx", canvas_.scale());
  if (selected_ >= 0 && used > 0 && size_t(used) < sizeof status) {
    used += std::snprintf(status + used, sizeof status - used, "   %s (%.2f, %.2f) px", metrology::cornerName(selected_),
                          shot.cornersPx[selected_].x, shot.cornersPx[selected_].y);
  }
  if (canvas_.area().contains(cursorPx_) && used > 0 && size_t(used) < sizeof status) {
    const glm::dvec2 p = canvas_.toPhoto(cursorPx_);
    std::snprintf(status + used, sizeof status - used, "   cursor (%.1f, %.1f) px", p.x, p.y);
  }
  const ImVec2 at(float(canvas_.area().min.x) + 8, float(canvas_.area().min.y) + 6);
  const ImVec2 size = ImGui::CalcTextSize(status);
  list->AddRectFilled({at.x - 4, at.y - 2}, {at.x + size.x + 4, at.y + size.y + 2}, IM_COL32(0, 0, 0, 150), 3.0f);
  list->AddText(at, IM_COL32(255, 255, 255, 255), status);
}

}  // namespace pw::edit
