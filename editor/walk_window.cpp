#include "editor/walk_window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <deque>
#include <fstream>
#include <memory>

#include <glm/gtc/quaternion.hpp>

#include "editor/walk/avatar.h"
#include "engine/gpu/presenter.h"
#include "engine/gpu/renderer.h"
#include "engine/gpu/vk_owner.h"
#include "engine/scene/collision.h"

namespace pw::editor {
namespace {

constexpr double kStepS = 1.0 / 60.0;
constexpr int kTransitionFrames = 30;  // viewpoint changes glide for half a second

std::string glfwLastError() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown GLFW error";
}

// GLFW's global state, torn down last.
struct GlfwSession {
  bool ok = false;
  GlfwSession() { ok = glfwInit() == GLFW_TRUE; }
  ~GlfwSession() {
    if (ok) glfwTerminate();
  }
};

struct WindowDeleter {
  void operator()(GLFWwindow* w) const { glfwDestroyWindow(w); }
};

// ImGui's context and its two backends, shut down in reverse order of creation.
struct ImGuiSession {
  bool glfw = false, vulkan = false;
  ImGuiSession() { ImGui::CreateContext(); }
  ~ImGuiSession() {
    if (vulkan) ImGui_ImplVulkan_Shutdown();
    if (glfw) ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
};

struct Transition {
  engine::Camera from, to;
  int frame = 0;
  int viewpoint = 0;
};

glm::dvec2 yawPitchOf(const glm::quat& q) {
  const glm::vec3 f = q * glm::vec3(0, 0, -1);
  return {std::atan2(-f.x, -f.z), std::asin(std::clamp(f.y, -1.0f, 1.0f))};
}

class WalkApp {
 public:
  WalkApp(const engine::Scene& scene, const WalkOptions& options)
      : scene_(scene),
        options_(options),
        world_(engine::CollisionWorld::fromScene(scene)),
        avatar_(scene.navigation, &world_, options.speedScale),
        headlight_(scene.navigation.headlight),
        showOverlay_(options.showOverlay) {
    keys_.fill(false);
    for (const std::string& line : scene.info) {
      if (line.rfind("corridor ", 0) == 0) dimensionLines_.push_back(line);
    }
    const engine::Bounds bounds = engine::sceneBounds(scene);
    if (dimensionLines_.empty() && !bounds.empty()) {
      char text[128];
      const glm::vec3 size = bounds.size();
      std::snprintf(text, sizeof text, "model bounds %.2f x %.2f x %.2f m", size.x, size.y, size.z);
      dimensionLines_.push_back(text);
    }
  }

  Result<WalkReport> run();

 private:
  Status open();
  void onKey(int key, bool down);
  void goToViewpoint(int index);
  void simulate();
  engine::Camera currentCamera() const;
  Status capture(const std::filesystem::path& path);
  void drawOverlay();
  Status applyReplayEvents();

  static WalkApp* self_;
  static void keyCallback(GLFWwindow*, int key, int, int action, int);
  static void cursorCallback(GLFWwindow*, double x, double y);
  static void mouseButtonCallback(GLFWwindow*, int button, int action, int);
  static void framebufferCallback(GLFWwindow*, int width, int height);

  const engine::Scene& scene_;
  WalkOptions options_;
  engine::CollisionWorld world_;
  walk::Avatar avatar_;
  bool headlight_;
  bool showOverlay_;
  bool showHelp_ = false;
  std::vector<std::string> dimensionLines_;

  std::array<bool, GLFW_KEY_LAST + 1> keys_{};
  double mouseDx_ = 0, mouseDy_ = 0;
  std::optional<glm::dvec2> lastCursor_;
  bool captured_ = false;
  bool quit_ = false;
  int viewpoint_ = 0;
  std::optional<Transition> transition_;
  long frame_ = 0;  // simulated frames
  size_t nextEvent_ = 0;
  int screenshotCount_ = 0;
  std::deque<double> recentFrameMs_;
  std::vector<double> frameMs_;
  std::unique_ptr<std::ofstream> trace_;
  std::string pendingError_;

  // Teardown in reverse: ImGui, presenter, surface, renderer, window, GLFW.
  GlfwSession glfw_;
  std::unique_ptr<GLFWwindow, WindowDeleter> window_;
  std::unique_ptr<engine::Renderer> renderer_;
  struct SurfaceOwner {
    VkInstance instance = VK_NULL_HANDLE;
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    ~SurfaceOwner() {
      if (surface) vkDestroySurfaceKHR(instance, surface, nullptr);
    }
  } surface_;
  std::unique_ptr<engine::Presenter> presenter_;
  engine::gpu::OwnedDescriptorPool imguiPool_;
  std::unique_ptr<ImGuiSession> imgui_;
};

WalkApp* WalkApp::self_ = nullptr;

void WalkApp::keyCallback(GLFWwindow*, int key, int, int action, int) {
  if (!self_ || self_->options_.replay || key < 0 || key > GLFW_KEY_LAST || action == GLFW_REPEAT) return;
  if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureKeyboard && !self_->captured_) return;
  self_->onKey(key, action == GLFW_PRESS);
}

void WalkApp::cursorCallback(GLFWwindow*, double x, double y) {
  if (!self_ || self_->options_.replay) return;
  if (self_->captured_ && self_->lastCursor_) {
    self_->mouseDx_ += x - self_->lastCursor_->x;
    self_->mouseDy_ += y - self_->lastCursor_->y;
  }
  self_->lastCursor_ = glm::dvec2(x, y);
}

void WalkApp::mouseButtonCallback(GLFWwindow* window, int button, int action, int) {
  if (!self_ || self_->options_.replay || action != GLFW_PRESS || button != GLFW_MOUSE_BUTTON_LEFT) return;
  if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse) return;
  if (!self_->captured_) {  // click into the view: capture the cursor for mouse look
    glfwSetInputMode(window, GLFW_CURSOR, GLFW_CURSOR_DISABLED);
    self_->captured_ = true;
    self_->lastCursor_.reset();
  }
}

void WalkApp::framebufferCallback(GLFWwindow*, int width, int height) {
  if (self_ && self_->presenter_) self_->presenter_->resize(width, height);
}

Status WalkApp::open() {
  if (!glfw_.ok) {
    return makeError("cannot open a window: " + glfwLastError() +
                     " (no display? run on a desktop, or under xvfb-run for tests)");
  }
  if (!glfwVulkanSupported()) return makeError("cannot open a window: GLFW finds no Vulkan loader");
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  window_.reset(glfwCreateWindow(options_.width, options_.height, options_.title.c_str(), nullptr, nullptr));
  if (!window_) return makeError("cannot open a window: " + glfwLastError());

  engine::RendererOptions rendererOptions;
  rendererOptions.forceCpu = options_.forceCpu;
  rendererOptions.profile = engine::RenderProfile::kInteractive;
  rendererOptions.msaaSamples = options_.msaaSamples;
  if (options_.perPixelLighting) rendererOptions.perVertexLighting = false;
  uint32_t count = 0;
  const char** extensions = glfwGetRequiredInstanceExtensions(&count);
  if (!extensions) return makeError("cannot open a window: this display cannot show Vulkan (" + glfwLastError() + ")");
  rendererOptions.instanceExtensions.assign(extensions, extensions + count);
  auto renderer = engine::Renderer::create(rendererOptions);
  if (!renderer) return renderer.error();
  renderer_ = std::move(*renderer);
  for (const std::string& note : renderer_->notes()) std::fprintf(stderr, "note: %s\n", note.c_str());
  PW_TRY(renderer_->setScene(scene_));

  surface_.instance = renderer_->instance();
  if (glfwCreateWindowSurface(surface_.instance, window_.get(), nullptr, &surface_.surface) != VK_SUCCESS) {
    return makeError("cannot open a window: no Vulkan surface for it (" + glfwLastError() + ")");
  }
  int fbw = 0, fbh = 0;
  glfwGetFramebufferSize(window_.get(), &fbw, &fbh);
  engine::PresenterOptions presenterOptions;
  presenterOptions.mode = options_.vsync ? engine::PresentMode::kVsync : engine::PresentMode::kLowLatency;
  auto presenter = engine::Presenter::create(*renderer_, surface_.surface, fbw, fbh, presenterOptions);
  if (!presenter) return presenter.error();
  presenter_ = std::move(*presenter);

  glfwSetKeyCallback(window_.get(), keyCallback);
  glfwSetCursorPosCallback(window_.get(), cursorCallback);
  glfwSetMouseButtonCallback(window_.get(), mouseButtonCallback);
  glfwSetFramebufferSizeCallback(window_.get(), framebufferCallback);

  // ImGui 1.86: its Vulkan backend draws inside the presenter's overlay render pass.
  const VkDescriptorPoolSize poolSize{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 16};
  const VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO, nullptr,
                                            VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT, 16, 1, &poolSize};
  VkDescriptorPool pool = VK_NULL_HANDLE;
  if (vkCreateDescriptorPool(renderer_->device(), &poolInfo, nullptr, &pool) != VK_SUCCESS) {
    return makeError("cannot create the overlay's descriptor pool");
  }
  imguiPool_ = engine::gpu::OwnedDescriptorPool(renderer_->device(), pool);
  imgui_ = std::make_unique<ImGuiSession>();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui::StyleColorsDark();
  imgui_->glfw = ImGui_ImplGlfw_InitForVulkan(window_.get(), true);
  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = renderer_->instance();
  info.PhysicalDevice = renderer_->physicalDevice();
  info.Device = renderer_->device();
  info.QueueFamily = renderer_->queueFamily();
  info.Queue = renderer_->queue();
  info.DescriptorPool = imguiPool_.get();
  info.MinImageCount = std::max(2u, presenter_->minImageCount());
  info.ImageCount = std::max(info.MinImageCount, presenter_->imageCount());
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  imgui_->vulkan = ImGui_ImplVulkan_Init(&info, presenter_->overlayRenderPass());
  if (!imgui_->glfw || !imgui_->vulkan) return makeError("cannot start the ImGui overlay");
  PW_TRY(renderer_->submitAndWait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); }));
  ImGui_ImplVulkan_DestroyFontUploadObjects();
  return {};
}

void WalkApp::onKey(int key, bool down) {
  keys_[key] = down;
  if (!down) return;
  const int count = static_cast<int>(scene_.viewpoints.size());
  switch (key) {
    case GLFW_KEY_PAGE_DOWN:
      if (count > 0) goToViewpoint((viewpoint_ + 1) % count);
      break;
    case GLFW_KEY_PAGE_UP:
      if (count > 0) goToViewpoint((viewpoint_ + count - 1) % count);
      break;
    case GLFW_KEY_HOME:
      if (count > 0) goToViewpoint(0);
      break;
    case GLFW_KEY_H:
      headlight_ = !headlight_;
      break;
    case GLFW_KEY_TAB:
      showOverlay_ = !showOverlay_;
      break;
    case GLFW_KEY_F1:
      showHelp_ = !showHelp_;
      break;
    case GLFW_KEY_F12: {
      char name[64];
      const std::time_t now = std::time(nullptr);
      std::strftime(name, sizeof name, "photowalk-%Y%m%d-%H%M%S", std::localtime(&now));
      const std::filesystem::path path = options_.screenshotDir / (std::string(name) + "-" + std::to_string(++screenshotCount_) + ".png");
      if (Status s = capture(path); !s) pendingError_ = s.message();
      else std::printf("screenshot: %s\n", path.string().c_str());
      break;
    }
    case GLFW_KEY_ESCAPE:
      if (captured_ && window_) {
        glfwSetInputMode(window_.get(), GLFW_CURSOR, GLFW_CURSOR_NORMAL);
        captured_ = false;
      } else if (!options_.replay) {
        quit_ = true;
      }
      break;
    default:
      break;
  }
}

void WalkApp::goToViewpoint(int index) {
  Transition t;
  t.from = currentCamera();
  t.to = engine::cameraFromViewpoint(scene_.viewpoints[index]);
  t.viewpoint = index;
  transition_ = t;
  viewpoint_ = index;
}

engine::Camera WalkApp::currentCamera() const {
  const float fov = scene_.viewpoints.empty() ? 0.785398f : scene_.viewpoints[viewpoint_].fieldOfViewRad;
  if (transition_) {
    const float u = static_cast<float>(transition_->frame) / kTransitionFrames;
    const float ease = u * u * (3 - 2 * u);
    engine::Camera c = transition_->to;
    c.position = glm::mix(transition_->from.position, transition_->to.position, ease);
    c.orientation = glm::slerp(transition_->from.orientation, transition_->to.orientation, ease);
    c.fieldOfViewRad = glm::mix(transition_->from.fieldOfViewRad, transition_->to.fieldOfViewRad, ease);
    c.nearM = avatar_.camera(fov).nearM;
    return c;
  }
  return avatar_.camera(fov);
}

void WalkApp::simulate() {
  if (transition_) {
    if (++transition_->frame >= kTransitionFrames) {
      avatar_.placeAt(scene_.viewpoints[transition_->viewpoint]);
      transition_.reset();
    }
    mouseDx_ = mouseDy_ = 0;
  } else {
    walk::MoveInput input;
    input.forward = (keys_[GLFW_KEY_W] || keys_[GLFW_KEY_UP] ? 1 : 0) - (keys_[GLFW_KEY_S] || keys_[GLFW_KEY_DOWN] ? 1 : 0);
    input.strafe = (keys_[GLFW_KEY_D] || keys_[GLFW_KEY_RIGHT] ? 1 : 0) - (keys_[GLFW_KEY_A] || keys_[GLFW_KEY_LEFT] ? 1 : 0);
    input.run = keys_[GLFW_KEY_LEFT_SHIFT] || keys_[GLFW_KEY_RIGHT_SHIFT];
    input.lookDxPx = mouseDx_;
    input.lookDyPx = mouseDy_;
    mouseDx_ = mouseDy_ = 0;
    avatar_.step(kStepS, input);
  }
  if (trace_) {
    const engine::Camera c = currentCamera();
    const glm::dvec2 yp = yawPitchOf(c.orientation);
    char row[160];
    std::snprintf(row, sizeof row, "%ld,%.6f,%.6f,%.6f,%.4f,%.4f\n", frame_, c.position.x, c.position.y, c.position.z,
                  glm::degrees(yp.x), glm::degrees(yp.y));
    *trace_ << row;
  }
  ++frame_;
}

Status WalkApp::capture(const std::filesystem::path& path) {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_.get(), &w, &h);
  if (w <= 0 || h <= 0) return makeError(path.string() + ": the window is minimised; nothing to capture");
  engine::FrameSettings settings;
  settings.headlight = headlight_;
  auto image = renderer_->renderToImage(currentCamera(), w, h, settings);
  if (!image) return image.error();
  return engine::saveImage(path, *image);
}

Status WalkApp::applyReplayEvents() {
  const auto& events = *options_.replay;
  while (nextEvent_ < events.size() && events[nextEvent_].frame <= frame_) {
    const walk::ReplayEvent& e = events[nextEvent_++];
    switch (e.kind) {
      case walk::ReplayEvent::Kind::kKey:
        onKey(walk::keyCodeFromName(e.name), e.down);
        break;
      case walk::ReplayEvent::Kind::kMouse:
        mouseDx_ += e.dx;
        mouseDy_ += e.dy;
        break;
      case walk::ReplayEvent::Kind::kViewpoint:
        if (e.index < 1 || e.index > static_cast<int>(scene_.viewpoints.size())) {
          return makeError("replay: viewpoint " + std::to_string(e.index) + " does not exist; the model has " +
                           std::to_string(scene_.viewpoints.size()));
        }
        goToViewpoint(e.index - 1);
        break;
      case walk::ReplayEvent::Kind::kResize: {
        const int w = static_cast<int>(e.dx), h = static_cast<int>(e.dy);
        glfwSetWindowSize(window_.get(), w, h);
        // Let the window system catch up so that what follows sees the new size.
        for (int i = 0; i < 50; ++i) {
          glfwPollEvents();
          int fw = 0, fh = 0;
          glfwGetFramebufferSize(window_.get(), &fw, &fh);
          if (fw == w && fh == h) break;
          glfwWaitEventsTimeout(0.01);
        }
        int fw = 0, fh = 0;
        glfwGetFramebufferSize(window_.get(), &fw, &fh);
        presenter_->resize(fw, fh);
        break;
      }
      case walk::ReplayEvent::Kind::kCapture:
        break;  // after this frame is simulated
      case walk::ReplayEvent::Kind::kQuit:
        quit_ = true;
        break;
    }
  }
  return {};
}

void WalkApp::drawOverlay() {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  if (showOverlay_) {
    ImGui::SetNextWindowPos({10, 10}, ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.6f);
    ImGui::Begin("photowalk", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
    double meanMs = 0;
    for (double ms : recentFrameMs_) meanMs += ms;
    if (!recentFrameMs_.empty()) meanMs /= recentFrameMs_.size();
    ImGui::Text("%.0f fps  %.2f ms/frame  %s", meanMs > 0 ? 1000.0 / meanMs : 0.0, meanMs, renderer_->deviceName().c_str());
    // What the frame rate costs in looks (the interactive profile on a CPU device).
    ImGui::Text("%dx MSAA, %s filtering, lit per %s", renderer_->msaaSamples(),
                renderer_->anisotropicFiltering() ? "anisotropic" : "trilinear",
                renderer_->perVertexLighting() ? "vertex" : "pixel");
    const engine::Camera c = currentCamera();
    const glm::dvec2 yp = yawPitchOf(c.orientation);
    ImGui::Text("position %.2f %.2f %.2f m  heading %.0f deg", c.position.x, c.position.y, c.position.z, glm::degrees(yp.x));
    if (!scene_.viewpoints.empty()) {
      ImGui::Text("viewpoint %d/%zu: %s", viewpoint_ + 1, scene_.viewpoints.size(),
                  scene_.viewpoints[viewpoint_].description.c_str());
    }
    for (const std::string& line : dimensionLines_) ImGui::TextUnformatted(line.c_str());
    ImGui::Text("headlight %s   F1: keys", headlight_ ? "on" : "off");
    ImGui::End();
  }
  if (showHelp_) {
    ImGui::Begin("Keys", &showHelp_, ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::TextUnformatted(
        "click      capture the mouse (look around)\n"
        "Esc        release the mouse; again: quit\n"
        "W/S, Up/Down     walk forward / back\n"
        "A/D, Left/Right  step left / right\n"
        "Shift      run\n"
        "PageDown/PageUp  next / previous viewpoint\n"
        "Home       first viewpoint\n"
        "H          headlight on/off\n"
        "F12        screenshot (PNG)\n"
        "Tab        this overlay on/off\n"
        "F1         this help");
    if (!scene_.viewpoints.empty() && ImGui::CollapsingHeader("Viewpoints")) {
      for (size_t i = 0; i < scene_.viewpoints.size(); ++i) {
        const std::string label = std::to_string(i + 1) + ". " + scene_.viewpoints[i].description;
        if (ImGui::Selectable(label.c_str(), static_cast<int>(i) == viewpoint_)) goToViewpoint(static_cast<int>(i));
      }
    }
    ImGui::End();
  }
  ImGui::Render();
}

Result<WalkReport> WalkApp::run() {
  self_ = this;
  struct ClearSelf {
    ~ClearSelf() { WalkApp::self_ = nullptr; }
  } clearSelf;
  PW_TRY(open());
  if (options_.tracePath) {
    trace_ = std::make_unique<std::ofstream>(*options_.tracePath, std::ios::trunc);
    if (!*trace_) return makeError(options_.tracePath->string() + ": cannot write the trace");
    *trace_ << "frame,x,y,z,yaw_deg,pitch_deg\n";
  }
  if (!scene_.viewpoints.empty()) {
    avatar_.placeAt(scene_.viewpoints[0]);
  } else {
    avatar_.placeAt(engine::defaultViewpoint(scene_));
  }
  const long lastReplayFrame = options_.replay && !options_.replay->empty() ? options_.replay->back().frame : 0;

  using Clock = std::chrono::steady_clock;
  Clock::time_point previous = Clock::now();
  double accumulatorS = 0;
  Clock::time_point lastFrameEnd = Clock::now();
  while (!quit_ && !glfwWindowShouldClose(window_.get())) {
    glfwPollEvents();
    int fbw = 0, fbh = 0;
    glfwGetFramebufferSize(window_.get(), &fbw, &fbh);
    if ((fbw == 0 || fbh == 0) && !options_.replay) {  // minimised: sleep until restored
      glfwWaitEvents();
      previous = Clock::now();
      continue;
    }
    if (options_.replay) {
      PW_TRY(applyReplayEvents());
      simulate();
      for (const auto& e : *options_.replay) {
        if (e.kind == walk::ReplayEvent::Kind::kCapture && e.frame == frame_ - 1) PW_TRY(capture(e.name));
      }
      if (frame_ > lastReplayFrame + 1) quit_ = true;
    } else {
      const Clock::time_point now = Clock::now();
      accumulatorS = std::min(accumulatorS + std::chrono::duration<double>(now - previous).count(), 5 * kStepS);
      previous = now;
      while (accumulatorS >= kStepS) {
        simulate();
        accumulatorS -= kStepS;
      }
    }
    if (!pendingError_.empty()) return makeError(pendingError_);

    drawOverlay();
    engine::FrameSettings settings;
    settings.headlight = headlight_;
    PW_TRY(presenter_->drawFrame(currentCamera(), settings,
                                 [](VkCommandBuffer cmd) { ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd); }));
    const Clock::time_point end = Clock::now();
    const double ms = std::chrono::duration<double, std::milli>(end - lastFrameEnd).count();
    lastFrameEnd = end;
    if (frameMs_.size() < 1000000) frameMs_.push_back(ms);
    recentFrameMs_.push_back(ms);
    if (recentFrameMs_.size() > 30) recentFrameMs_.pop_front();
  }
  PW_TRY(presenter_->waitIdle());

  WalkReport report;
  report.framesSimulated = frame_;
  report.framesDrawn = static_cast<long>(frameMs_.size());
  report.deviceName = renderer_->deviceName();
  report.msaaSamples = renderer_->msaaSamples();
  report.anisotropicFiltering = renderer_->anisotropicFiltering();
  report.perVertexLighting = renderer_->perVertexLighting();
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

}  // namespace

Result<WalkReport> runWalkWindow(const engine::Scene& scene, const WalkOptions& options) {
  WalkApp app(scene, options);
  return app.run();
}

}  // namespace pw::editor
