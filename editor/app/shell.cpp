#include "editor/app/shell.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <type_traits>

#include "editor/app/fixed_step_clock.h"
#include "editor/app/glfw_session.h"

namespace pw::app {
namespace {

constexpr long kMessageSteps = 300;  // five seconds
constexpr size_t kRecentFrames = 30;


}  // namespace

Shell::Shell(const ShellOptions& options) : options_(options), replay_(options.replay) {}

Shell::~Shell() {
  // Frames in flight may still use ImGui's buffers; an error here has nowhere to go.
  if (presenter_) (void)presenter_->waitIdle();
}

Result<std::unique_ptr<Shell>> Shell::create(const ShellOptions& options) {
  std::unique_ptr<Shell> shell(new Shell(options));
  PW_TRY(shell->open());
  return shell;
}

Status Shell::open() {
  auto extensions = windowInstanceExtensions();
  if (!extensions) return extensions.error();
  engine::RendererOptions rendererOptions = options_.renderer;
  for (const std::string& extension : *extensions) {
    if (std::find(rendererOptions.instanceExtensions.begin(), rendererOptions.instanceExtensions.end(), extension) ==
        rendererOptions.instanceExtensions.end()) {
      rendererOptions.instanceExtensions.push_back(extension);
    }
  }
  auto renderer = engine::Renderer::create(rendererOptions);
  if (!renderer) return renderer.error();
  renderer_ = std::move(*renderer);
  for (const std::string& note : renderer_->notes()) std::fprintf(stderr, "note: %s\n", note.c_str());

  auto window = Window::create(options_.window, renderer_->instance());
  if (!window) return window.error();
  window_ = std::move(*window);
  const glm::ivec2 size = window_->framebufferSize();
  engine::PresenterOptions presenterOptions;
  presenterOptions.mode = options_.vsync ? engine::PresentMode::kVsync : engine::PresentMode::kLowLatency;
  auto presenter = engine::Presenter::create(*renderer_, window_->surface(), size.x, size.y, presenterOptions);
  if (!presenter) return presenter.error();
  presenter_ = std::move(*presenter);
  window_->setInputHandler([this](const InputEvent& event) { onWindowInput(event); });
  window_->setCharHandler([this](unsigned codepoint) {
    if (!replaying()) input_.push(CharEvent{codepoint});
  });
  window_->setFramebufferSizeHandler([this](glm::ivec2 fb) { presenter_->resize(fb.x, fb.y); });

  auto imgui = ImGuiLayer::create(*window_, *renderer_, *presenter_);
  if (!imgui) return imgui.error();
  imgui_ = std::move(*imgui);
  return {};
}

Status Shell::addMode(AppMode& mode) {
  for (const AppMode* other : modes_) {
    if (other->name() == mode.name()) {
      return makeError("a mode named '" + std::string(mode.name()) + "' is there already");
    }
  }
  PW_TRY(mode.open(*this));
  modes_.push_back(&mode);
  return {};
}

double Shell::recentFrameMs() const {
  if (recentFrameMs_.empty()) return 0;
  double sum = 0;
  for (double ms : recentFrameMs_) sum += ms;
  return sum / recentFrameMs_.size();
}

void Shell::showMessage(const std::string& text) {
  std::fprintf(stderr, "%s\n", text.c_str());
  messages_.push_back({text, frame_ + kMessageSteps});
}

// Live input: to the active mode at once (as GLFW reports it), and into the queue that
// hands it to ImGui a frame's worth at a time (InputQueue, taken in drawFrame).
void Shell::onWindowInput(const InputEvent& event) {
  if (replaying()) return;  // a replay plays its own input
  input_.push(event);
  if (!active_) return;
  dispatch(event);
  if (Status switched = applyPendingMode(); !switched) {
    showMessage("error: " + switched.message());
  }
}

// Marks what ImGui wants (as of the last frame) and hands the event to the active mode.
void Shell::dispatch(InputEvent event) {
  if (!replaying() && ImGui::GetCurrentContext()) {
    const ImGuiIO& io = ImGui::GetIO();
    std::visit(Overloaded{[&](KeyEvent& e) { e.uiWantsIt = io.WantCaptureKeyboard; },
                          [&](MouseButtonEvent& e) { e.uiWantsIt = io.WantCaptureMouse; },
                          [&](ScrollEvent& e) { e.uiWantsIt = io.WantCaptureMouse; }, [](auto&) {}},
               event);
  }
  active_->onInput(*this, event);
}

void Shell::requestClose() {
  std::vector<AppMode*> order = modes_;
  if (active_) std::stable_partition(order.begin(), order.end(), [&](const AppMode* m) { return m == active_; });
  for (AppMode* mode : order) {
    if (mode->onCloseRequest(*this)) continue;
    if (mode != active_) pendingMode_ = std::string(mode->name());
    return;
  }
  quit_ = true;
}

Status Shell::switchTo(const std::string& name) {
  for (AppMode* mode : modes_) {
    if (mode->name() != name) continue;
    if (mode == active_) return {};
    if (active_) active_->onLeave(*this);
    active_ = mode;
    active_->onEnter(*this);
    return {};
  }
  std::string known;
  for (const AppMode* mode : modes_) known += (known.empty() ? "" : ", ") + std::string(mode->name());
  return makeError("no mode named '" + name + "' (there are: " + known + ")");
}

Status Shell::applyPendingMode() {
  if (!pendingMode_) return {};
  const std::string name = std::move(*pendingMode_);
  pendingMode_.reset();
  return switchTo(name);
}

Status Shell::resize(int width, int height) {
  const glm::ivec2 size = window_->resizeAndWait(width, height);
  presenter_->resize(size.x, size.y);
  return {};
}

// Plays the replay's events up to this frame; captures are done after the step.
Status Shell::playEventsDue(std::vector<std::filesystem::path>& captures) {
  const std::vector<ReplayEvent>& events = *replay_;
  while (nextEvent_ < events.size() && events[nextEvent_].frame <= frame_) {
    const ReplayEvent& e = events[nextEvent_++];
    if (std::optional<InputEvent> input = inputOf(e.what)) {  // as live input: the mode now, ImGui queued
      input_.push(*input);
      dispatch(*input);
      PW_TRY(applyPendingMode());
      continue;
    }
    if (const auto* text = std::get_if<TypeRequest>(&e.what)) {
      for (unsigned codepoint : text->codepoints) input_.push(CharEvent{codepoint});
      continue;
    }
    Status done = std::visit(
        Overloaded{[&](const ResizeRequest& r) { return resize(r.width, r.height); },
                   [&](const CaptureRequest& c) {
                     captures.push_back(c.path);
                     return Status{};
                   },
                   [&](const ModeRequest& m) { return switchTo(m.mode); },
                   [&](const QuitRequest&) {
                     quit_ = true;
                     return Status{};
                   },
                   [&](const CloseRequest&) {
                     requestClose();
                     return applyPendingMode();
                   },
                   [&](const ModeEvent& m) {
                     Status status = active_->onReplayEvent(*this, m);
                     if (status) status = applyPendingMode();
                     return status;
                   },
                   [](const auto&) { return Status{}; }},
        e.what);
    if (!done) return makeError("replay, frame " + std::to_string(e.frame) + ": " + done.message());
  }
  return {};
}

Status Shell::step() {
  active_->update(*this, FixedStepClock::kStepS);
  if (trace_) {
    TraceRow row;
    active_->traceRow(row);
    PW_TRY(trace_->write(frame_, active_->name(), row));
  }
  ++frame_;
  return applyPendingMode();
}

Status Shell::capture(const std::filesystem::path& path) {
  const glm::ivec2 size = window_->framebufferSize();
  if (size.x <= 0 || size.y <= 0) return makeError(path.string() + ": the window is minimised; nothing to capture");
  std::optional<Result<engine::Image>> image = active_->capture(*this, size.x, size.y);
  if (!image) {  // the window as shown: taken when this frame is drawn
    windowCaptures_.push_back(path);
    presenter_->captureNextFrame();
    return {};
  }
  if (!*image) return image->error();
  return engine::saveImage(path, **image);
}

// After a frame: saves the window captures it was asked for. A frame the swapchain
// skipped (it was being remade) leaves them for the next one.
Status Shell::saveWindowCaptures(uint64_t presentedBefore) {
  if (windowCaptures_.empty() || presenter_->framesPresented() == presentedBefore) return {};
  auto image = presenter_->takeCapture();
  if (!image) return image.error();
  for (const std::filesystem::path& path : windowCaptures_) PW_TRY(engine::saveImage(path, *image));
  windowCaptures_.clear();
  return {};
}

void Shell::drawMessages() {
  while (!messages_.empty() && messages_.front().untilFrame <= frame_) messages_.pop_front();
  if (messages_.empty()) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos({viewport->WorkPos.x + 10, viewport->WorkPos.y + viewport->WorkSize.y - 10}, ImGuiCond_Always,
                          {0.0f, 1.0f});
  ImGui::SetNextWindowBgAlpha(0.75f);
  const double maxX = active_ ? active_->messagesMaxX() : 0.0;
  const float maxWidth = maxX > 40 ? float(maxX - 20) : viewport->WorkSize.x - 20;
  ImGui::SetNextWindowSizeConstraints({0, 0}, {maxWidth, viewport->WorkSize.y});
  ImGui::Begin("##messages", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs);
  ImGui::PushTextWrapPos(maxWidth - ImGui::GetStyle().WindowPadding.x);
  for (const Message& message : messages_) ImGui::TextUnformatted(message.text.c_str());
  ImGui::PopTextWrapPos();
  ImGui::End();
}

Status Shell::drawFrame() {
  input_.takeFrame();  // ImGui's share of the input queued: at most one transition of a key
  imgui_->beginFrame(input_.state(), !replaying());
  active_->drawUi(*this);
  drawMessages();
  imgui_->endFrame();
  const FrameContent content = active_->frame(*this);
  const uint64_t presentedBefore = presenter_->framesPresented();
  PW_TRY(presenter_->drawFrame(content.views, [this](VkCommandBuffer cmd) { imgui_->record(cmd); }, content.clearColor));
  PW_TRY(imgui_->status());
  return saveWindowCaptures(presentedBefore);
}

Result<ShellReport> Shell::run(std::string_view firstMode) {
  PW_TRY(switchTo(std::string(firstMode)));
  if (options_.tracePath) {
    auto trace = Trace::open(*options_.tracePath, options_.traceFormat);
    if (!trace) return trace.error();
    trace_ = std::move(*trace);
  }
  const long lastReplayFrame = replay_ && !replay_->empty() ? replay_->back().frame : 0;

  using Clock = std::chrono::steady_clock;
  FixedStepClock clock(replaying());
  Clock::time_point lastFrameEnd = Clock::now();
  while (!quit_) {
    glfwPollEvents();
    if (window_->closeRequested()) {  // the close button: the modes may ask first
      window_->cancelClose();
      requestClose();
      PW_TRY(applyPendingMode());
      if (quit_) break;
    }
    const glm::ivec2 size = window_->framebufferSize();
    if ((size.x == 0 || size.y == 0) && !replaying()) {  // minimised: sleep until restored
      glfwWaitEvents();
      clock.restart();
      continue;
    }
    if (replaying()) {
      std::vector<std::filesystem::path> captures;
      PW_TRY(playEventsDue(captures));
      PW_TRY(step());
      for (const std::filesystem::path& path : captures) PW_TRY(capture(path));
      if (frame_ > lastReplayFrame + 1 && input_.empty()) quit_ = true;
    } else {
      for (int steps = clock.stepsFor(); steps > 0; --steps) PW_TRY(step());
    }

    PW_TRY(drawFrame());
    const Clock::time_point end = Clock::now();
    const double ms = std::chrono::duration<double, std::milli>(end - lastFrameEnd).count();
    lastFrameEnd = end;
    if (frameMs_.size() < 1000000) frameMs_.push_back(ms);
    recentFrameMs_.push_back(ms);
    if (recentFrameMs_.size() > kRecentFrames) recentFrameMs_.pop_front();
  }
  PW_TRY(presenter_->waitIdle());
  if (trace_) {
    PW_TRY(trace_->close());
    trace_.reset();
  }
  if (!windowCaptures_.empty()) {
    return makeError(windowCaptures_.front().string() + ": the run ended before a frame was drawn to capture");
  }

  ShellReport report;
  report.framesSimulated = frame_;
  report.framesDrawn = static_cast<long>(frameMs_.size());
  if (frameMs_.size() > 1) {
    std::vector<double> sorted(frameMs_.begin() + 1, frameMs_.end());  // the first includes start-up
    double sum = 0;
    for (double ms : sorted) sum += ms;
    report.meanFrameMs = sum / sorted.size();
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    report.medianFrameMs = sorted[sorted.size() / 2];
  }
  report.validationMessages = renderer_->validationMessageCount();
  PW_TRY(renderer_->validationStatus());
  return report;
}

}  // namespace pw::app
