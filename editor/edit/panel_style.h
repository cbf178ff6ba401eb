// What the editor's ImGui panels share (panels.cpp, camera_panel.cpp, files_ui.cpp,
// building_panel.cpp, building_question.cpp): the fixed side-panel window, the
// colours of notes, warnings and errors, and small helpers.
#pragma once

#include <imgui.h>

#include <array>
#include <cstdio>
#include <optional>
#include <string>

#include "editor/edit/canvas.h"

namespace pw::edit::ui {

// A panel laid out from the window's size (ImGui 1.86 has no docking).
inline constexpr ImGuiWindowFlags kFixedWindow = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                                 ImGuiWindowFlags_NoNavInputs |
                                                 ImGuiWindowFlags_NoBringToFrontOnFocus;
inline const ImVec4 kWarningColour(1.0f, 0.80f, 0.30f, 1.0f);
inline const ImVec4 kErrorColour(1.0f, 0.45f, 0.40f, 1.0f);
inline const ImVec4 kNoteColour(0.70f, 0.75f, 0.80f, 1.0f);

// Wrapped text in `colour`.
inline void wrapped(const ImVec4& colour, const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
}

// The current ImGui window in window pixels (what covers the canvas or the plan).
inline WindowRect currentWindowRect() {
  const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  return {{pos.x, pos.y}, {pos.x + size.x, pos.y + size.y}};
}

// A label drawn on the photo at `at` (window pixels), on a dark plate so that it reads
// over the photo and over the box's own lines.
inline void labelOnPlate(ImDrawList* list, ImVec2 at, const std::string& text, ImU32 colour) {
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  list->AddRectFilled({at.x - 3, at.y - 1}, {at.x + size.x + 3, at.y + size.y + 1}, IM_COL32(0, 0, 0, 170), 3.0f);
  list->AddText(at, colour, text.c_str());
}

// A name typed in place (a measurement's, a standing object's): the field shows `current`
// whenever it is not being typed into (`typingInto`: which of a list's fields is, or -1;
// this one is `index`), and gives the typed text once, when the field is left or Enter
// ends an edit that changed it.
inline std::optional<std::string> nameField(const char* id, const std::string& current, std::array<char, 64>& buffer,
                                            int& typingInto, int index, float width) {
  if (typingInto != index) std::snprintf(buffer.data(), buffer.size(), "%s", current.c_str());
  ImGui::SetNextItemWidth(width);
  ImGui::InputTextWithHint(id, "name", buffer.data(), buffer.size());
  if (ImGui::IsItemActivated()) typingInto = index;
  if (!ImGui::IsItemDeactivated()) return std::nullopt;
  typingInto = -1;
  const std::string typed = buffer.data();
  if (!ImGui::IsItemDeactivatedAfterEdit() || typed == current) return std::nullopt;
  return typed;
}

}  // namespace pw::edit::ui
