#include "editor/edit/edit_window.h"

#include <utility>

#include "base/atomic_file.h"
#include "editor/app/shell.h"
#include "editor/edit/building_mode.h"
#include "editor/edit/edit_mode.h"
#include "editor/edit/model_walk.h"
#include "editor/walk/replay.h"

namespace pw::edit {

Result<std::vector<app::ReplayEvent>> readEditReplay(const std::filesystem::path& path) {
  auto text = readFile(path);
  if (!text) return text.error();
  std::vector<app::ReplayVerb> verbs = EditMode::replayVerbs(path.parent_path());
  for (app::ReplayVerb& verb : walk::replayVerbs()) verbs.push_back(std::move(verb));
  return app::parseReplay(*text, path.string(), path.parent_path(), verbs);
}

Result<EditReport> runEditWindow(const EditWindowOptions& options) {
  app::ShellOptions shellOptions;
  shellOptions.window = {options.width, options.height, "photowalk edit"};
  shellOptions.vsync = options.vsync;
  shellOptions.renderer.forceCpu = options.forceCpu;
  shellOptions.renderer.profile = engine::RenderProfile::kInteractive;
  shellOptions.replay = options.replay;
  shellOptions.tracePath = options.tracePath;
  shellOptions.traceFormat = app::TraceFormat::kJsonLines;
  auto shell = app::Shell::create(shellOptions);
  if (!shell) return shell.error();

  // The walk's trace rows carry the editor's document too; the editor outlives the run.
  EditMode* editor = nullptr;
  ModelWalk walk("edit", [&editor](app::TraceRow& row) {
    if (editor) editor->addDocumentTrace(row);
  });
  EditModeOptions editOptions;
  editOptions.file = options.file;
  editOptions.open = options.open;
  // A layout file opens the building's plan (building_mode.h), which lends its shots to the editor.
  std::optional<std::filesystem::path> layout;
  if (options.file && isLayoutFile(*options.file)) layout = std::exchange(editOptions.file, std::nullopt);
  EditMode edit(editOptions, walk);
  editor = &edit;
  BuildingMode building(edit, walk, layout);
  edit.setLayoutOpener([&building](app::Shell& shell, const std::filesystem::path& path) {
    building.openFromEditor(shell, path);
  });
  edit.setCloseAsker([&building](app::Shell& shell) { return building.askBeforeEditorCloses(shell); });
  PW_TRY((*shell)->addMode(edit));
  PW_TRY((*shell)->addMode(walk));
  PW_TRY((*shell)->addMode(building));
  auto run = (*shell)->run(layout ? building.name() : edit.name());
  if (!run) return run.error();

  EditReport report;
  report.framesDrawn = run->framesDrawn;
  report.framesSimulated = run->framesSimulated;
  report.medianFrameMs = run->medianFrameMs;
  report.deviceName = (*shell)->renderer().deviceName();
  return report;
}

}  // namespace pw::edit
