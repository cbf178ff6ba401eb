// The editor's files (edit_files.h): Open through the browser, the recent files or a
// drop, Save As, Export, autosave and the recovery of what a crash left, and the
// Save / Discard / Cancel question before unsaved edits would be lost.
#include <imgui.h>

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstring>

#include <nlohmann/json.hpp>

#include "editor/edit/panel_style.h"
#include "editor/app/shell.h"
#include "editor/edit/edit_mode.h"
#include "editor/edit/model_export.h"

namespace pw::edit {
namespace fs = std::filesystem;
using nlohmann::ordered_json;

namespace {

using namespace ui;  // panel_style.h

constexpr ImGuiWindowFlags kDialog =
    ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse;

const char* const kOpenTitle = "Open a photo or shot file";
const char* const kSaveAsTitle = "Save the shot as";
const char* const kExportTitle = "Export the model";
const char* const kUnsavedTitle = "Unsaved changes";
const char* const kRecoverTitle = "Recover unsaved changes?";

enum Answer { kSave = 0, kDiscard = 1, kCancel = 2 };

fs::path besideScript(const std::string& file, const fs::path& scriptDir) {
  const fs::path path(file);
  return path.is_relative() ? scriptDir / path : path;
}

// Keeps the modal `title` open exactly while `wanted` (ImGui keeps its own list of
// open popups: one not wanted any more is closed from inside, where ImGui allows it).
// True: it is begun; the caller draws it and calls ImGui::EndPopup().
bool modal(const char* title, bool wanted, const ImVec2& size) {
  const bool open = ImGui::IsPopupOpen(title);
  if (!wanted && !open) return false;
  if (wanted && !open) ImGui::OpenPopup(title);
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos({viewport->WorkPos.x + viewport->WorkSize.x * 0.5f, viewport->WorkPos.y + viewport->WorkSize.y * 0.5f},
                          ImGuiCond_Always, {0.5f, 0.5f});
  ImGui::SetNextWindowSize(size, ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(1.0f);  // opaque: the windows under it do not show through
  if (!ImGui::BeginPopupModal(title, nullptr, kDialog)) return false;
  if (!wanted) {
    ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return false;
  }
  return true;
}

ordered_json rectJson(const WindowRect& r) {
  return ordered_json::array({r.min.x, r.min.y, r.max.x - r.min.x, r.max.y - r.min.y});
}

const char* purposeName(BrowserPurpose purpose) {
  switch (purpose) {
    case BrowserPurpose::kOpen: return "open";
    case BrowserPurpose::kSaveAs: return "save-as";
    case BrowserPurpose::kExportVrml:
    case BrowserPurpose::kExportGltf:
    case BrowserPurpose::kExportPage: return "export";
  }
  return "open";
}

// What a recovered shot changes, in words: "P5, P6, focal length".
std::string differences(const metrology::Shot& from, const metrology::Shot& to) {
  std::string text;
  const auto add = [&](const std::string& what) { text += (text.empty() ? "" : ", ") + what; };
  for (int k = 0; k < metrology::kCornerCount; ++k) {
    if (from.cornersPx[k] != to.cornersPx[k]) add(metrology::cornerName(k));
  }
  if (from.focalPx != to.focalPx || from.focalMm.has_value() != to.focalMm.has_value()) add("focal length");
  if (from.principalPointPx != to.principalPointPx) add("principal point");
  if (from.cameraHeightM != to.cameraHeightM) add("camera height");
  if (from.reference.has_value() != to.reference.has_value() ||
      (from.reference && (from.reference->from != to.reference->from || from.reference->to != to.reference->to ||
                          from.reference->lengthM != to.reference->lengthM))) {
    add("reference length");
  }
  return text.empty() ? "the camera" : text;
}

void setName(std::array<char, 512>& field, const std::string& text) {
  field.fill('\0');
  std::strncpy(field.data(), text.c_str(), field.size() - 1);
}

}  // namespace

std::vector<app::ReplayVerb> EditMode::filesReplayVerbs(const fs::path& scriptDir) {
  return {{"save-as",
           [scriptDir](std::istream& words) -> Result<std::any> {
             std::string file;
             if (!(words >> file)) return makeError("expected 'save-as FILE.json'");
             return std::any(SaveAsEvent{besideScript(file, scriptDir)});
           }},
          {"export", [scriptDir](std::istream& words) -> Result<std::any> {
             std::string file;
             if (!(words >> file)) return makeError("expected 'export FILE.wrl' or 'export FILE.glb'");
             return std::any(ExportEvent{besideScript(file, scriptDir)});
           }}};
}

bool EditMode::onFilesReplayEvent(app::Shell& shell, const app::ModeEvent& event) {
  if (const auto* saveAsEvent = std::any_cast<SaveAsEvent>(&event.value)) {
    saveAs(shell, saveAsEvent->path);
    return true;
  }
  if (const auto* exportEvent = std::any_cast<ExportEvent>(&event.value)) {
    exportTo(shell, exportEvent->path);
    return true;
  }
  return false;
}

void EditMode::requestOpen(app::Shell& shell, const fs::path& path) {
  if (drag_) endDrag(true);
  if (files_.recovered && doc_) {  // its answer decides what becomes of the side file
    shell.showMessage("first answer the question about " + doc_->path().filename().string() +
                      "'s unsaved changes (Recover or Discard)");
    return;
  }
  if (doc_ && doc_->hasUnsavedEdits()) {
    files_.browser.reset();
    files_.unsaved = EditFiles::Unsaved{path};
    return;
  }
  openFile(shell, path);
  if (!openError_.empty() && std::find(files_.recent.paths().begin(), files_.recent.paths().end(),
                                       fs::absolute(path).lexically_normal()) != files_.recent.paths().end()) {
    (void)files_.recent.remove(path);  // a recent file that is gone or unreadable now
  }
}

void EditMode::leaveDocument() {
  // A side file goes with a clean document, unless it is a crash's state still unanswered.
  if (doc_ && !doc_->hasUnsavedEdits() && !files_.recovered) files_.autosave.remove(doc_->path());
  files_.autosave.reset();
  files_.recovered.reset();
}

void EditMode::afterOpen(app::Shell& shell, const fs::path& opened) {
  if (Status added = files_.recent.add(opened); !added) shell.showMessage("warning: recent files: " + added.message());
  auto recovered = recoverableShot(*doc_);
  if (!recovered) {
    shell.showMessage("warning: " + recovered.message());
    return;
  }
  if (*recovered) {
    files_.recovered = **recovered;
  } else {
    files_.autosave.remove(doc_->path());  // none, or one that says what the file says
  }
}

void EditMode::afterSave(app::Shell& shell) {
  files_.autosave.remove(doc_->path());
  if (Status added = files_.recent.add(doc_->path()); !added) {
    shell.showMessage("warning: recent files: " + added.message());
  }
}

bool EditMode::onCloseRequest(app::Shell& shell) {
  if (drag_) endDrag(true);
  if (files_.recovered) return true;  // unanswered: the side file stays for the next start
  if (closeAsker_ && closeAsker_(shell)) return false;
  if (doc_ && doc_->hasUnsavedEdits()) {
    files_.browser.reset();
    files_.unsaved = EditFiles::Unsaved{};
    return false;
  }
  if (doc_) files_.autosave.remove(doc_->path());  // a clean close
  files_.closing = true;
  return true;
}

void EditMode::answerUnsaved(app::Shell& shell, int answer) {
  if (!files_.unsaved) return;
  const EditFiles::Unsaved pending = *files_.unsaved;
  files_.unsaved.reset();
  if (answer == kCancel || !doc_) return;
  if (answer == kSave) {
    save(shell);
    if (doc_->hasUnsavedEdits()) return;  // not saved: the message says why; nothing is lost
  } else {
    files_.autosave.remove(doc_->path());
    shell.showMessage("discarded the unsaved changes to " + doc_->path().string());
  }
  if (pending.open) {
    openFile(shell, *pending.open);
  } else {
    files_.closing = true;  // no autosave in the steps before the window goes
    shell.requestQuit();
  }
}

void EditMode::answerRecovery(app::Shell& shell, bool recover) {
  if (!files_.recovered || !doc_) return;
  const metrology::Shot recovered = *files_.recovered;
  files_.recovered.reset();
  if (recover) {
    applyEdit(shell, recovered, "recover unsaved changes");
    shell.showMessage("recovered the unsaved changes to " + doc_->path().string() + " (Ctrl+Z undoes it)");
  } else {
    files_.autosave.remove(doc_->path());
    shell.showMessage("discarded the recovered changes to " + doc_->path().string());
  }
}

void EditMode::openBrowser(app::Shell& shell, BrowserPurpose purpose) {
  if ((purpose != BrowserPurpose::kOpen) && !doc_) {
    shell.showMessage(purpose == BrowserPurpose::kSaveAs ? "nothing to save: no file is open"
                                                         : "nothing to export: no file is open");
    return;
  }
  if (drag_) endDrag(true);
  const std::vector<std::string>& endings = purpose == BrowserPurpose::kOpen     ? kOpenableEndings
                                            : purpose == BrowserPurpose::kSaveAs ? kShotEndings
                                                                                 : kModelEndings;
  FileBrowser browser(endings);
  std::error_code ec;
  fs::path start = fs::current_path(ec);
  if (doc_) start = fs::absolute(doc_->path(), ec).parent_path();
  else if (!files_.recent.paths().empty()) start = files_.recent.paths().front().parent_path();
  if (!browser.enter(start) && !browser.enter(fs::current_path(ec))) (void)browser.enter("/");
  files_.browser = std::move(browser);
  files_.purpose = purpose;
  files_.browserError.clear();
  std::string name;
  if (doc_) {
    std::string stem = doc_->path().stem().string();  // "hall" of hall.json and of hall.shot.json
    if (stem.size() > 5 && stem.ends_with(".shot")) stem.resize(stem.size() - 5);
    if (purpose == BrowserPurpose::kSaveAs) name = doc_->path().filename().string();
    if (purpose == BrowserPurpose::kExportVrml) name = stem + ".wrl";
    if (purpose == BrowserPurpose::kExportGltf) name = stem + ".glb";
    if (purpose == BrowserPurpose::kExportPage) name = stem + ".html";
  }
  setName(files_.name, name);
}

void EditMode::confirmBrowser(app::Shell& shell, const std::optional<fs::path>& chosen) {
  if (!files_.browser) return;
  const std::string name(files_.name.data());
  if (!chosen && name.empty()) {
    files_.browserError = files_.purpose == BrowserPurpose::kOpen ? "choose a file" : "give the file a name";
    return;
  }
  const fs::path path = chosen ? *chosen : files_.browser->folder() / name;
  std::error_code ec;
  if (!chosen && files_.purpose == BrowserPurpose::kOpen && fs::is_directory(path, ec)) {
    if (Status entered = files_.browser->enter(path); !entered) files_.browserError = entered.message();
    setName(files_.name, "");
    return;
  }
  const BrowserPurpose purpose = files_.purpose;
  files_.browser.reset();
  switch (purpose) {
    case BrowserPurpose::kOpen: requestOpen(shell, path); break;
    case BrowserPurpose::kSaveAs: saveAs(shell, path); break;
    case BrowserPurpose::kExportVrml:
    case BrowserPurpose::kExportGltf:
    case BrowserPurpose::kExportPage: exportTo(shell, path); break;
  }
}

void EditMode::saveAs(app::Shell& shell, const fs::path& path) {
  if (!doc_) {
    shell.showMessage("nothing to save: no file is open");
    return;
  }
  if (drag_) endDrag(true);
  fs::path target = path;
  if (target.extension().empty()) target += ".json";
  if (!matchesEndings(target.filename().string(), kShotEndings)) {
    shell.showMessage("error: not saved: " + target.string() + ": a shot file's name ends in .json");
    return;
  }
  const fs::path before = doc_->path();
  if (Status saved = doc_->saveAs(target); !saved) {
    shell.showMessage("error: not saved: " + saved.message());
    return;
  }
  files_.autosave.remove(before);
  shell.showMessage("saved as " + doc_->path().string());
  afterSave(shell);
}

void EditMode::exportTo(app::Shell& shell, const fs::path& path) {
  if (!doc_) {
    shell.showMessage("nothing to export: no file is open");
    return;
  }
  if (drag_) endDrag(true);
  remeasure();
  if (!live_.measurement) {
    shell.showMessage("error: not exported: the corners cannot be measured: " + live_.error);
    return;
  }
  if (files_.exporting) {
    shell.showMessage("error: not exported: " + files_.exporting->path.filename().string() +
                      " is being exported; try again when it is done");
    return;
  }
  // The export works on copies (the photo is never written to, so sharing its pixels is
  // safe). A replay waits for it in the frame's step (updateFiles), so that the next
  // frame sees the files whatever the machine's speed.
  files_.exporting = EditFiles::Export{
      path, std::async(std::launch::async, [shot = doc_->shot(), photo = doc_->photo(), m = *live_.measurement, path] {
        return exportModel(shot, photo, m, path);
      })};
  shell.showMessage("exporting " + path.string() + " ...");
}

void EditMode::finishExport(app::Shell& shell, bool wait) {
  if (!files_.exporting) return;
  std::future<Status>& done = files_.exporting->done;
  if (!wait && done.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  const fs::path path = files_.exporting->path;
  const Status written = done.get();
  files_.exporting.reset();
  if (!written) {
    shell.showMessage("error: not exported: " + written.message());
    return;
  }
  shell.showMessage("exported " + path.string());
}

bool EditMode::onFilesKey(app::Shell& shell, const app::KeyEvent& e) {
  const bool enter = e.key == GLFW_KEY_ENTER || e.key == GLFW_KEY_KP_ENTER;
  if (files_.recovered) {
    if (e.key == GLFW_KEY_R || enter) answerRecovery(shell, true);
    else if (e.key == GLFW_KEY_D) answerRecovery(shell, false);
    return true;
  }
  if (files_.unsaved) {
    if (e.key == GLFW_KEY_S || enter) answerUnsaved(shell, kSave);
    else if (e.key == GLFW_KEY_D) answerUnsaved(shell, kDiscard);
    else if (e.key == GLFW_KEY_ESCAPE) answerUnsaved(shell, kCancel);
    return true;
  }
  if (files_.browser) {
    if (e.key == GLFW_KEY_ESCAPE) files_.browser.reset();
    else if (enter) confirmBrowser(shell);
    return true;
  }
  const bool ctrl = ctrlHeld() || (e.mods & GLFW_MOD_CONTROL);
  const bool shift = shiftHeld() || (e.mods & GLFW_MOD_SHIFT);
  if (ctrl && e.key == GLFW_KEY_O) {
    openBrowser(shell, BrowserPurpose::kOpen);
    return true;
  }
  if (ctrl && shift && e.key == GLFW_KEY_S) {
    openBrowser(shell, BrowserPurpose::kSaveAs);
    return true;
  }
  return false;
}

void EditMode::updateFiles(app::Shell& shell, double stepS) {
  finishExport(shell, shell.replaying());
  // No autosave while the recovery question is up: the side file is what it asks about.
  if (files_.recovered || files_.closing) return;
  if (Status saved = files_.autosave.step(doc_ ? &*doc_ : nullptr, stepS); !saved) {
    shell.showMessage("warning: " + saved.message());
  }
}

void EditMode::traceFiles(app::TraceRow& row) const {
  ordered_json files;
  const char* dialog = files_.recovered ? "recover"
                       : files_.unsaved ? "unsaved"
                       : files_.browser ? purposeName(files_.purpose)
                                        : nullptr;
  files["dialog"] = dialog ? ordered_json(dialog) : ordered_json(nullptr);
  ordered_json buttons = ordered_json::object();
  for (const auto& [name, rect] : files_.buttons) buttons[name] = rectJson(rect);
  files["buttons"] = buttons;
  if (files_.browser) {
    files["folder"] = files_.browser->folder().string();
    ordered_json entries = ordered_json::array();
    for (const FolderEntry& entry : files_.browser->entries()) entries.push_back(entry.name + (entry.folder ? "/" : ""));
    files["entries"] = entries;
    files["name"] = std::string(files_.name.data());
  }
  ordered_json recent = ordered_json::array();
  for (const fs::path& path : files_.recent.paths()) recent.push_back(path.string());
  files["recent"] = recent;
  const std::optional<fs::path>& autosaved = files_.autosave.writtenFor();
  files["autosave"] = autosaved ? ordered_json(autosavePath(*autosaved).string()) : ordered_json(nullptr);
  row.add("files", files);
}

void EditMode::recordItem(const std::string& name) {
  if (files_.buttonsFrame != ImGui::GetFrameCount()) {  // the first of this frame: the last frame's go
    files_.buttons.clear();
    files_.buttonsFrame = ImGui::GetFrameCount();
  }
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  files_.buttons[name] = {{min.x, min.y}, {max.x, max.y}};
}

bool EditMode::recordedButton(const char* label, const std::string& name) {
  const bool pressed = ImGui::Button(label);
  recordItem(name);
  return pressed;
}

void EditMode::drawFiles(app::Shell& shell) {
  if (files_.buttonsFrame != ImGui::GetFrameCount()) files_.buttons.clear();
  drawRecovery(shell);
  drawUnsaved(shell);
  drawBrowser(shell);
}

void EditMode::drawRecovery(app::Shell& shell) {
  if (!modal(kRecoverTitle, files_.recovered.has_value() && doc_, {480, 0})) return;
  ImGui::TextWrapped("%s has changes that were not saved: the editor did not close cleanly the last time.",
                     doc_->path().filename().string().c_str());
  ImGui::TextWrapped("Changed: %s.", differences(doc_->shot(), *files_.recovered).c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, kNoteColour);
  ImGui::TextWrapped("Kept in %s. Recover makes them the current state (one undo step, not saved yet); Discard "
                     "deletes them.",
                     autosavePath(doc_->path()).string().c_str());
  ImGui::PopStyleColor();
  if (recordedButton("Recover (R)", "Recover")) answerRecovery(shell, true);
  ImGui::SameLine();
  if (recordedButton("Discard (D)", "Discard")) answerRecovery(shell, false);
  ImGui::EndPopup();
}

void EditMode::drawUnsaved(app::Shell& shell) {
  if (!modal(kUnsavedTitle, files_.unsaved.has_value() && doc_, {480, 0})) return;
  const std::string name = doc_->path().filename().string();
  if (files_.unsaved->open) {
    ImGui::TextWrapped("%s has unsaved changes. Save them before opening %s?", name.c_str(),
                       files_.unsaved->open->filename().string().c_str());
  } else {
    ImGui::TextWrapped("%s has unsaved changes. Save them before closing?", name.c_str());
  }
  ImGui::PushStyleColor(ImGuiCol_Text, kNoteColour);
  ImGui::TextWrapped("Save writes %s.", doc_->path().string().c_str());
  ImGui::PopStyleColor();
  if (recordedButton("Save (S)", "Save")) answerUnsaved(shell, kSave);
  ImGui::SameLine();
  if (recordedButton("Discard (D)", "Discard")) answerUnsaved(shell, kDiscard);
  ImGui::SameLine();
  if (recordedButton("Cancel (Esc)", "Cancel")) answerUnsaved(shell, kCancel);
  ImGui::EndPopup();
}

void EditMode::drawBrowser(app::Shell& shell) {
  const bool wanted = files_.browser.has_value();
  const char* title = files_.purpose == BrowserPurpose::kOpen     ? kOpenTitle
                      : files_.purpose == BrowserPurpose::kSaveAs ? kSaveAsTitle
                                                                  : kExportTitle;
  const ImVec2 size(std::min(680.0f, 0.92f * float(windowSize_.x)), std::min(520.0f, 0.92f * float(windowSize_.y)));
  if (!modal(title, wanted, size)) return;
  FileBrowser& browser = *files_.browser;
  const bool open = files_.purpose == BrowserPurpose::kOpen;
  std::optional<fs::path> enter, chosen;

  if (recordedButton("Up", "Up")) enter = browser.folder().parent_path();
  ImGui::SameLine();
  ImGui::TextWrapped("%s", browser.folder().string().c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, kNoteColour);
  ImGui::TextUnformatted(open ? "photos (PNG, JPEG) and shot files (JSON)"
                         : files_.purpose == BrowserPurpose::kSaveAs ? "shot files (JSON)"
                                                                     : "models: VRML97 (.wrl, .wrl.gz) or glTF (.glb, .gltf)");
  ImGui::PopStyleColor();

  const float footer = ImGui::GetFrameHeightWithSpacing() * 2 + ImGui::GetTextLineHeightWithSpacing() *
                                                                    (files_.browserError.empty() ? 0.5f : 1.5f);
  const bool recentShown = open && !files_.recent.paths().empty();
  const float listHeight = ImGui::GetContentRegionAvail().y - footer;
  ImGui::BeginChild("##entries", {0, recentShown ? listHeight * 0.62f : listHeight}, true);
  const std::string selected(files_.name.data());
  for (const FolderEntry& entry : browser.entries()) {
    const std::string label = entry.folder ? entry.name + "/" : entry.name;
    if (ImGui::Selectable(label.c_str(), !entry.folder && entry.name == selected, ImGuiSelectableFlags_AllowDoubleClick)) {
      if (entry.folder) {
        enter = entry.path;
      } else {
        setName(files_.name, entry.name);
        if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) chosen = entry.path;
      }
    }
    recordItem("entry:" + label);
  }
  if (browser.entries().empty()) ImGui::TextDisabled("(nothing here to show)");
  ImGui::EndChild();
  if (recentShown) {
    ImGui::TextUnformatted("Recent files");
    ImGui::BeginChild("##recent", {0, listHeight * 0.38f - ImGui::GetTextLineHeightWithSpacing()}, true);
    for (const fs::path& path : files_.recent.paths()) {
      if (ImGui::Selectable(path.string().c_str())) chosen = path;
      recordItem("recent:" + path.string());
    }
    ImGui::EndChild();
  }

  ImGui::SetNextItemWidth(-1);
  ImGui::InputText("##name", files_.name.data(), files_.name.size());
  if (!files_.browserError.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorColour);
    ImGui::TextWrapped("%s", files_.browserError.c_str());
    ImGui::PopStyleColor();
  }
  std::error_code ec;
  const std::string name(files_.name.data());
  const fs::path target = browser.folder() / name;
  const bool ownFile = doc_ && fs::equivalent(target, doc_->path(), ec);  // Save As onto itself: a Save
  const bool replaces = !open && !name.empty() && !ownFile && fs::exists(target, ec);
  const char* confirm = open ? "Open" : replaces ? "Replace" : files_.purpose == BrowserPurpose::kSaveAs ? "Save" : "Export";
  bool confirmed = recordedButton(confirm, "Confirm");
  ImGui::SameLine();
  if (recordedButton("Cancel", "Cancel")) files_.browser.reset();
  if (replaces) {
    ImGui::SameLine();
    ImGui::TextColored(kErrorColour, "%s exists: %s replaces it", name.c_str(), confirm);
  }
  ImGui::EndPopup();

  if (!files_.browser) return;
  if (enter) {
    if (Status entered = browser.enter(*enter); !entered) files_.browserError = entered.message();
    else files_.browserError.clear();
  }
  if (chosen) confirmBrowser(shell, chosen);
  else if (confirmed) confirmBrowser(shell);
}

void EditMode::drawOpenChoices(app::Shell& shell) {
  if (recordedButton("Open a file... (Ctrl+O)", "Open")) openBrowser(shell, BrowserPurpose::kOpen);
  if (!files_.recent.paths().empty()) {
    ImGui::Spacing();
    ImGui::TextUnformatted("Recent files:");
    std::optional<fs::path> chosen;
    for (const fs::path& path : files_.recent.paths()) {
      if (ImGui::Selectable(path.string().c_str())) chosen = path;
      recordItem("recent:" + path.string());
    }
    if (chosen) requestOpen(shell, *chosen);  // after the loop: opening changes the list
  }
  ImGui::Spacing();
  ImGui::TextUnformatted("Or drop a photo, a shot file or a layout (a building)");
  ImGui::TextUnformatted("on this window, or give one on the command line:");
  ImGui::TextUnformatted("  photowalk edit PHOTO.jpg | SHOT.json | LAYOUT.json");
}

void EditMode::drawExportButtons(app::Shell& shell) {
  ImGui::BeginDisabled(!live_.measurement || files_.exporting.has_value());
  if (recordedButton("Export .wrl", "Export .wrl")) openBrowser(shell, BrowserPurpose::kExportVrml);
  ImGui::SameLine();
  if (recordedButton("Export .glb", "Export .glb")) openBrowser(shell, BrowserPurpose::kExportGltf);
  ImGui::SameLine();
  if (recordedButton("Export web page", "Export web page")) openBrowser(shell, BrowserPurpose::kExportPage);
  ImGui::EndDisabled();
}

}  // namespace pw::edit
