// The app shell: one window that interactive modes (app_mode.h) run in, the walkthrough
// now and the editor next. It owns, in order of teardown last to first: the Renderer,
// the Window (GLFW window and Vulkan surface), the Presenter, and ImGui (ImGuiLayer);
// it runs the loop at a fixed simulation step (FixedStepClock), plays replay scripts
// (replay.h), writes traces (trace.h), captures frames (the window as shown, ImGui
// included, unless the mode captures otherwise) and shows messages.
//
//   ShellOptions options;  options.window = {1280, 720, "photowalk"};
//   auto shell = Shell::create(options);                  // window, renderer, ImGui
//   WalkMode walk(scene, {});  (*shell)->addMode(walk);   // modes are borrowed
//   auto report = (*shell)->run("walk");
#pragma once

#include <cstdint>
#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/result.h"
#include "editor/app/app_mode.h"
#include "editor/app/imgui_layer.h"
#include "editor/app/input_queue.h"
#include "editor/app/replay.h"
#include "editor/app/trace.h"
#include "editor/app/window.h"
#include "engine/gpu/presenter.h"
#include "engine/gpu/renderer.h"

namespace pw::app {

struct ShellOptions {
  WindowOptions window;
  engine::RendererOptions renderer;  // the shell adds the window's instance extensions
  bool vsync = true;                 // false: draw as fast as possible (frame-rate measurements)
  std::optional<std::vector<ReplayEvent>> replay;  // set: one step per frame, live input ignored
  std::optional<std::filesystem::path> tracePath;
  TraceFormat traceFormat = TraceFormat::kJsonLines;
};

struct ShellReport {
  long framesDrawn = 0;
  long framesSimulated = 0;
  double meanFrameMs = 0;  // wall clock per drawn frame, the first (start-up) left out
  double medianFrameMs = 0;
  size_t validationMessages = 0;
};

class Shell {
 public:
  // Opens the window and its renderer. Errors: no display, no Vulkan device that can
  // present to it, ImGui's backend failing to start.
  // (Neither copied nor moved: the window's handlers hold its address.)
  static Result<std::unique_ptr<Shell>> create(const ShellOptions& options);
  ~Shell();

  // Adds a mode (borrowed: it must live until run() returns) and opens it (AppMode::open).
  // Errors: a name already taken, the mode's open failing.
  Status addMode(AppMode& mode);

  // Runs, starting in the mode named `firstMode`, until the window is closed, a mode
  // asks to quit, or the replay ends (one frame after its last event). Errors: an
  // unknown mode, a replay event that cannot be done (a capture that cannot be
  // written, a mode's event it refuses), the renderer failing, and, with validation on,
  // any validation message.
  Result<ShellReport> run(std::string_view firstMode);

  // For modes.
  engine::Renderer& renderer() { return *renderer_; }
  Window& window() { return *window_; }
  bool replaying() const { return replay_.has_value(); }
  long simulatedFrames() const { return frame_; }  // steps simulated so far
  double recentFrameMs() const;                    // mean of the last 30 drawn frames
  AppMode* activeMode() { return active_; }
  // Switches to the named mode after the event or step being handled (a replay's
  // `mode NAME` switches at once). An unknown name ends the run with an error.
  void requestMode(std::string name) { pendingMode_ = std::move(name); }
  void requestQuit() { quit_ = true; }
  // What the window's close button does: asks the modes (AppMode::onCloseRequest) and
  // quits when none objects.
  void requestClose();
  // A message a person should see without the run ending: a line on stderr and, for
  // five seconds (300 steps), a line in the window over any mode.
  void showMessage(const std::string& text);

 private:
  explicit Shell(const ShellOptions& options);
  Status open();
  void onWindowInput(const InputEvent& event);
  void dispatch(InputEvent event);
  Status switchTo(const std::string& name);
  Status applyPendingMode();
  Status playEventsDue(std::vector<std::filesystem::path>& captures);
  Status resize(int width, int height);
  Status step();
  Status capture(const std::filesystem::path& path);
  Status saveWindowCaptures(uint64_t presentedBefore);
  Status drawFrame();
  void drawMessages();

  ShellOptions options_;
  std::optional<std::vector<ReplayEvent>> replay_;
  size_t nextEvent_ = 0;
  InputQueue input_;  // the window's or the replay's input and characters, for ImGui
  std::vector<AppMode*> modes_;
  AppMode* active_ = nullptr;
  std::optional<std::string> pendingMode_;
  bool quit_ = false;
  long frame_ = 0;
  struct Message {
    std::string text;
    long untilFrame;
  };
  std::deque<Message> messages_;
  std::vector<std::filesystem::path> windowCaptures_;  // to save when the next frame is drawn
  std::unique_ptr<Trace> trace_;
  std::deque<double> recentFrameMs_;
  std::vector<double> frameMs_;

  // Torn down last to first: ImGui, presenter, window (its surface), renderer.
  std::unique_ptr<engine::Renderer> renderer_;
  std::unique_ptr<Window> window_;
  std::unique_ptr<engine::Presenter> presenter_;
  std::unique_ptr<ImGuiLayer> imgui_;
};

}  // namespace pw::app
