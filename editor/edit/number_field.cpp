#include "editor/edit/number_field.h"

#include <imgui.h>
#include <imgui_internal.h>  // ImGui::ClearActiveID: Tab ends the edit (the panels take no Tab navigation)

#include <algorithm>
#include <cmath>
#include <sstream>

#include "editor/app/shell.h"
#include "editor/edit/panel_style.h"

namespace pw::edit {

const FieldRange* fieldRange(std::string_view label) {
  for (const FieldRange& range : kFieldRanges) {
    if (range.label == label) return &range;
  }
  return nullptr;
}

std::string numberInWords(double value) {
  std::ostringstream out;
  out.precision(12);
  out << value;
  return out.str();
}

std::optional<std::string> refusal(const FieldRange& range, double value, double photoSide) {
  const double scale = range.perPhotoSide ? photoSide : 1.0;
  const double min = range.min * scale, max = range.max * scale;
  if (std::isfinite(value) && value >= min && value <= max) return std::nullopt;
  const std::string unit(range.unit);
  const std::string between = min < 0 ? " to " : "-";
  return std::string(range.name) + " " + numberInWords(value) + " " + unit + ": expected " + numberInWords(min) +
         between + numberInWords(max) + " " + unit;
}

bool NumberFields::field(app::Shell& shell, const char* label, double committed, double* edited, const char* format,
                         double photoSide) {
  const ImGuiID id = ImGui::GetID(label);
  const int frame = ImGui::GetFrameCount();
  // What was typed so far, only while the field was active in the last frame: a field
  // (re)activated starts from the value committed, never from an older text. (The one
  // left for another field keeps its text for the frame it is committed in, whichever
  // of the two is drawn first.)
  std::erase_if(typed_, [&](const Typed& t) { return t.frame < frame - 1; });
  auto mine = std::find_if(typed_.begin(), typed_.end(), [&](const Typed& t) { return t.id == id; });
  double v = mine != typed_.end() ? mine->value : committed;
  ImGui::SetNextItemWidth(120.0f);
  ImGui::InputDouble(label, &v, 0.0, 0.0, format);
  if (ImGui::IsItemActivated() && refusedId_ == id) refused_.reset();  // editing it again
  if (ImGui::IsItemActive()) {
    if (mine == typed_.end()) mine = typed_.insert(typed_.end(), Typed{id, frame, v});
    mine->frame = frame;
    mine->value = v;
  }
  // Tab commits: the panels are ImGuiWindowFlags_NoNavInputs, so ImGui's own Tab
  // focusing does not end the edit.
  const bool tabbed = ImGui::IsItemActive() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Tab), false);
  if (tabbed) ImGui::ClearActiveID();
  bool done = false;
  if ((tabbed || ImGui::IsItemDeactivatedAfterEdit()) && v != committed) {
    const FieldRange* range = fieldRange(label);
    const std::optional<std::string> why =
        range ? refusal(*range, v, photoSide)
              : (std::isfinite(v) ? std::nullopt : std::optional<std::string>(std::string(label) + ": not a number"));
    if (why) {
      refused_ = *why;
      refusedId_ = id;
      shell.showMessage("refused: " + *why + "; kept " + numberInWords(committed));
    } else {
      if (refusedId_ == id) refused_.reset();
      *edited = v;
      done = true;
    }
  }
  if (tabbed || ImGui::IsItemDeactivated()) {
    std::erase_if(typed_, [&](const Typed& t) { return t.id == id; });
  }
  return done;
}

void NumberFields::drawRefusal(const char* label) const {
  if (refused_ && refusedId_ == ImGui::GetID(label)) ui::wrapped(ui::kErrorColour, "refused: " + *refused_);
}

}  // namespace pw::edit
