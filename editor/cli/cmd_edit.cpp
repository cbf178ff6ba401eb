// photowalk edit: place the corners on a photo and see the measurement live (issue 13).
#include <cstdio>
#include <string>

#include "editor/cli/command.h"
#include "editor/edit/edit_window.h"

namespace pw::editor {
namespace {

constexpr const char* kUsage =
    "usage: photowalk edit [PHOTO | SHOT.json | LAYOUT.json] [-o SHOT.json] [--size WxH] [--no-vsync] [--cpu]\n"
    "                      [--replay SCRIPT] [--trace OUT.jsonl]\n\n"
    "Opens the editor: the photo on a canvas that pans and zooms, the corridor's eight\n"
    "corners P1..P8 as handles to drag (with a loupe), the measurement (width, height,\n"
    "length with their +-, vanishing point, camera pose, reprojection error) updated\n"
    "as they move, the camera's focal length, principal point and height, undo/redo,\n"
    "Save (Ctrl+S) and a walk through the model (W; Esc comes back). A photo without a\n"
    "shot file gets its corners from automatic detection (or a default box). Open\n"
    "(Ctrl+O) and Save As (Ctrl+Shift+S) use an in-window file browser with the recent\n"
    "files ($PW_RECENT_FILES, else $XDG_CONFIG_HOME or ~/.config/photowalk/recent.json);\n"
    "Export writes VRML97 or glTF; unsaved edits are autosaved to .NAME.json.autosave\n"
    "beside the shot and offered back after a crash. F1 in the window lists the keys;\n"
    "README \"The editor\" too. A layout file (a building) opens its plan: move, turn\n"
    "and snap the corridors, edit each shot, walk the building, save (README \"Building\n"
    "mode\").\n\n"
    "  -o, --output SHOT.json  where Save writes the shot of a photo opened alone\n"
    "                          (default: beside the photo, as PHOTO-STEM.shot.json)\n"
    "  --size WxH              window size (default 1280x720)\n"
    "  --no-vsync              draw as fast as possible\n"
    "  --cpu                   use the CPU renderer (lavapipe) even if a GPU exists\n"
    "  --replay SCRIPT         play a script of input events at a fixed 1/60 s per frame,\n"
    "                          real input ignored (README: The editor)\n"
    "  --trace OUT.jsonl       write one JSON object per simulated frame: the canvas's\n"
    "                          image_to_window transform, corners_px, selected,\n"
    "                          measurement, document {path, dirty}, loupe\n\n"
    "A file that cannot be opened is a message in the window; the editor stays open.\n"
    "With Vulkan validation on (PW_VALIDATION=1, or a Debug build) any validation message\n"
    "fails the command (exit 1) when the window closes.\n";

int runEdit(Args& args) {
  edit::EditWindowOptions options;
  const auto output = args.value("--output", "-o");
  const auto sizeText = args.value("--size");
  const auto replayPath = args.value("--replay");
  const auto tracePath = args.value("--trace");
  options.vsync = !args.flag("--no-vsync");
  options.forceCpu = args.flag("--cpu");
  const std::vector<std::string> positionals = args.positionals();
  if (auto finished = args.finish(); !finished) return fail(finished.message());
  if (positionals.size() > 1) return fail("edit takes at most one photo, shot or layout file; see photowalk edit --help");
  if (!positionals.empty()) options.file = positionals[0];
  if (output) options.open.photoShotPath = *output;
  if (sizeText) {
    auto size = parseSize(*sizeText, "--size");
    if (!size) return fail(size.message());
    options.width = size->first;
    options.height = size->second;
  }
  if (replayPath) {
    auto replay = edit::readEditReplay(*replayPath);
    if (!replay) return fail(replay.message());
    options.replay = std::move(*replay);
  }
  if (tracePath) options.tracePath = *tracePath;

  auto report = edit::runEditWindow(options);
  if (!report) return fail(report.message());
  std::printf("edit: %ld frames drawn, %ld simulated; frame time median %.2f ms; %s\n", report->framesDrawn,
              report->framesSimulated, report->medianFrameMs, report->deviceName.c_str());
  return kExitOk;
}

}  // namespace

PW_COMMAND(edit, "edit", "place a photo's corners in a window; see the measurement live; walk the model", kUsage,
           runEdit);

}  // namespace pw::editor
