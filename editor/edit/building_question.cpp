// Building mode's question before unsaved changes would be lost (closing the window,
// opening another layout): Save all (S, Enter) / Discard (D) / Cancel (Esc), a modal
// over the plan whose buttons are in the trace ("question") for replays to click. The
// changes it covers: the layout's, each shot's (the one lent to the shot editor too),
// and the editor's own shot when it is not one of the building's.
#include <imgui.h>

#include <GLFW/glfw3.h>

#include <nlohmann/json.hpp>

#include "editor/edit/panel_style.h"
#include "editor/app/shell.h"
#include "editor/edit/autosave.h"
#include "editor/edit/building_mode.h"
#include "editor/edit/edit_mode.h"

namespace pw::edit {
namespace fs = std::filesystem;
using nlohmann::ordered_json;

namespace {

using namespace ui;  // panel_style.h

enum Answer { kSaveAll = 0, kDiscard = 1, kCancel = 2 };

const char* const kQuestionTitle = "Unsaved changes in the building";
constexpr ImGuiWindowFlags kDialog =
    ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse;

// The side files the editor's autosave may have left of shots whose changes are now
// saved or discarded (what they hold is then nobody's).
void removeSideFiles(const std::vector<fs::path>& files) {
  for (const fs::path& file : files) {
    std::error_code ec;
    fs::remove(autosavePath(file), ec);
  }
}

}  // namespace

bool BuildingMode::onCloseRequest(app::Shell& shell) {
  if (drag_) endDrag(true);
  if (question_) return false;  // asked already
  if (unsavedFiles().empty()) return true;
  ask(shell, std::nullopt);
  return false;
}

bool BuildingMode::askBeforeEditorCloses(app::Shell& shell) {
  // The building's changes (its shot in the editor's among them): asked here, with the
  // editor's own shot when it is another file, so that one answer covers them all.
  if (!building_ || !dirty()) return false;
  ask(shell, std::nullopt);
  question_->backToEditor = true;
  shell.requestMode(kName);
  return true;
}

const Document* BuildingMode::foreignShot() const {
  const Document* doc = editor_.document();
  return doc && doc != lentShot() ? doc : nullptr;
}

std::vector<fs::path> BuildingMode::unsavedFiles() const {
  std::vector<fs::path> files;
  if (const Document* other = foreignShot(); other && other->hasUnsavedEdits()) files.push_back(other->path());
  if (building_) {
    for (fs::path& file : building_->unsavedFiles(lentShot())) files.push_back(std::move(file));
  }
  return files;
}

void BuildingMode::ask(app::Shell& shell, std::optional<fs::path> open) {
  if (drag_) endDrag(true);
  question_ = Question{std::move(open), shell.activeMode() == static_cast<app::AppMode*>(&editor_)};
}

bool BuildingMode::onQuestionKey(app::Shell& shell, const app::KeyEvent& e) {
  if (!question_) return false;
  if (e.key == GLFW_KEY_S || e.key == GLFW_KEY_ENTER || e.key == GLFW_KEY_KP_ENTER) answer(shell, kSaveAll);
  else if (e.key == GLFW_KEY_D) answer(shell, kDiscard);
  else if (e.key == GLFW_KEY_ESCAPE) answer(shell, kCancel);
  return true;
}

void BuildingMode::answer(app::Shell& shell, int answer) {
  if (!question_) return;
  const Question asked = *question_;
  question_.reset();
  if (answer == kCancel) {
    if (asked.backToEditor) shell.requestMode("edit");
    return;
  }
  const std::vector<fs::path> files = unsavedFiles();
  if (answer == kSaveAll) {
    if (Document* other = editor_.document(); other && other != lentShot() && other->dirty()) {
      if (Status saved = other->save(); !saved) {
        shell.showMessage("error: not saved: " + saved.message());
        return;  // the question is gone, the changes are all there
      }
    }
    if (building_ && dirty()) {
      if (Status saved = building_->save(lentShot()); !saved) {
        shell.showMessage("error: not saved: " + saved.message());
        return;
      }
    }
    removeSideFiles(files);
    shell.showMessage("saved " + std::to_string(files.size()) + (files.size() == 1 ? " file" : " files"));
  } else {
    shell.showMessage("discarded the unsaved changes to " + std::to_string(files.size()) +
                      (files.size() == 1 ? " file" : " files"));
  }
  if (asked.open) {
    openLayout(shell, *asked.open);  // the editor's shot goes (its autosave written first)
    if (building_ && building_->path() == *asked.open) shell.requestMode(kName);
  } else {
    shell.requestQuit();
  }
  if (answer == kDiscard) removeSideFiles(files);
}

bool BuildingMode::questionButton(const char* label, const std::string& name) {
  const bool pressed = ImGui::Button(label);
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  questionButtons_.push_back({name, {{min.x, min.y}, {max.x, max.y}}});
  return pressed;
}

void BuildingMode::drawQuestion(app::Shell& shell) {
  questionButtons_.clear();
  const bool wanted = question_.has_value();
  const bool open = ImGui::IsPopupOpen(kQuestionTitle);
  if (!wanted && !open) return;
  if (wanted && !open) ImGui::OpenPopup(kQuestionTitle);
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos({viewport->WorkPos.x + viewport->WorkSize.x * 0.5f, viewport->WorkPos.y + viewport->WorkSize.y * 0.5f},
                          ImGuiCond_Always, {0.5f, 0.5f});
  ImGui::SetNextWindowSize({500, 0}, ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(1.0f);
  if (!ImGui::BeginPopupModal(kQuestionTitle, nullptr, kDialog)) return;
  if (!wanted) {
    ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return;
  }
  const std::vector<fs::path> files = unsavedFiles();
  if (question_->open) {
    ImGui::TextWrapped("Save these unsaved changes before opening %s?", question_->open->filename().string().c_str());
  } else {
    ImGui::TextWrapped("Save these unsaved changes before closing?");
  }
  ImGui::PushStyleColor(ImGuiCol_Text, kNoteColour);
  for (const fs::path& file : files) ImGui::BulletText("%s", file.string().c_str());
  ImGui::PopStyleColor();
  std::optional<int> chosen;
  if (questionButton("Save all (S)", "Save all")) chosen = kSaveAll;
  ImGui::SameLine();
  if (questionButton("Discard (D)", "Discard")) chosen = kDiscard;
  ImGui::SameLine();
  if (questionButton("Cancel (Esc)", "Cancel")) chosen = kCancel;
  ImGui::EndPopup();
  if (chosen) answer(shell, *chosen);
}

void BuildingMode::traceQuestion(app::TraceRow& row) const {
  if (!question_) {
    row.add("question", ordered_json(nullptr));
    return;
  }
  ordered_json files = ordered_json::array();
  for (const fs::path& file : unsavedFiles()) files.push_back(file.string());
  ordered_json buttons = ordered_json::object();
  for (const auto& [name, r] : questionButtons_) {
    buttons[name] = ordered_json::array({r.min.x, r.min.y, r.max.x - r.min.x, r.max.y - r.min.y});
  }
  row.add("question", ordered_json{{"about", question_->open ? "open" : "close"},
                                   {"open", question_->open ? ordered_json(question_->open->string()) : ordered_json(nullptr)},
                                   {"files", files},
                                   {"buttons", buttons}});
}

}  // namespace pw::edit
