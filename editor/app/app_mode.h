// What runs in the shell's window (shell.h): the walkthrough, the editor. The shell
// owns the loop and calls the active mode; modes can be switched at run time, and each
// keeps its state while another runs (a mode left is not updated or drawn).
//
// Per drawn frame the shell: polls input (to onInput), plays the replay's events due
// (input to onInput, the mode's own kinds to onReplayEvent), simulates the steps due
// (update, then a trace row each), then drawUi (ImGui), frame() (what the renderer
// draws under the UI) and presents.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "base/result.h"
#include "editor/app/input.h"
#include "editor/app/replay.h"
#include "editor/app/trace.h"
#include "engine/gpu/renderer.h"
#include "engine/gpu/view.h"
#include "engine/scene/camera.h"
#include "engine/scene/image.h"

namespace pw::app {

class Shell;

// What the renderer draws under the UI this frame: views (engine/gpu/view.h) in order,
// each over what the ones before left; pixels none covers are `clearColor`.
struct FrameContent {
  std::vector<engine::View> views;
  glm::vec3 clearColor{0.0f};  // sRGB-encoded
};

class AppMode {
 public:
  virtual ~AppMode() = default;

  // "walk", "edit": replay scripts' `mode NAME`, JSON traces' "mode".
  virtual std::string_view name() const = 0;

  // Once, when added to the shell (Shell::addMode): GPU uploads and the like. Errors
  // end the shell's start.
  virtual Status open(Shell&) { return {}; }
  // When the mode becomes the active one, and when another takes its place (release
  // what is held: keys down, a captured cursor).
  virtual void onEnter(Shell&) {}
  virtual void onLeave(Shell&) {}

  // Input while active: live from the window (not while a replay plays), or replayed.
  virtual void onInput(Shell& shell, const InputEvent& event) = 0;
  // A replay event of one of the mode's own kinds (its ReplayVerbs). Errors end the run.
  virtual Status onReplayEvent(Shell&, const ModeEvent& event) {
    return makeError("replay: mode '" + std::string(name()) + "' has no event '" + event.verb + "'");
  }

  // The window's close button (or a replay's `close`): true (the default) lets the window
  // close; false keeps it open while the mode asks the person (unsaved changes: Save /
  // Discard / Cancel), and the mode calls Shell::requestQuit() once they agree. The
  // shell asks every mode, the active one first; the first that asks becomes active.
  virtual bool onCloseRequest(Shell&) { return true; }

  // One simulation step of `stepS` seconds (FixedStepClock::kStepS).
  virtual void update(Shell& shell, double stepS) = 0;
  // The fields of the trace row written after each step (the shell adds the frame).
  virtual void traceRow(TraceRow&) const {}

  // The shell's messages (Shell::showMessage) stay left of this window x (0: the whole
  // width), so that they do not cover a mode's panel.
  virtual double messagesMaxX() const { return 0; }

  // ImGui windows, between ImGui::NewFrame and ImGui::Render.
  virtual void drawUi(Shell&) {}
  virtual FrameContent frame(Shell& shell) = 0;

  // The picture a replay `capture` saves, width x height pixels; nullopt (the default):
  // the window as it shows this frame, ImGui included (Presenter::captureNextFrame).
  virtual std::optional<Result<engine::Image>> capture(Shell&, int /*width*/, int /*height*/) { return std::nullopt; }
};

}  // namespace pw::app
