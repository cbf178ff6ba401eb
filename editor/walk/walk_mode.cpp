#include "editor/walk/walk_mode.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>

#include <glm/gtc/quaternion.hpp>

#include "editor/app/shell.h"
#include "editor/walk/replay.h"

namespace pw::walk {
namespace {

using app::Overloaded;

constexpr int kTransitionFrames = 30;  // viewpoint changes glide for half a second

glm::dvec2 yawPitchOf(const glm::quat& q) {
  const glm::vec3 f = q * glm::vec3(0, 0, -1);
  return {std::atan2(-f.x, -f.z), std::asin(std::clamp(f.y, -1.0f, 1.0f))};
}


}  // namespace

WalkMode::WalkMode(const engine::Scene& scene, const WalkModeOptions& options)
    : scene_(scene),
      options_(options),
      world_(engine::CollisionWorld::fromScene(scene)),
      avatar_(scene.navigation, &world_, options.speedScale),
      headlight_(scene.navigation.headlight),
      showOverlay_(options.showOverlay) {
  keys_.fill(false);
  if (const engine::Bounds bounds = engine::sceneBounds(scene); !bounds.empty()) {
    char text[128];
    const glm::vec3 size = bounds.size();
    std::snprintf(text, sizeof text, "model bounds %.2f x %.2f x %.2f m", size.x, size.y, size.z);
    boundsLine_ = text;
  }
  avatar_.placeAt(scene.viewpoints.empty() ? engine::defaultViewpoint(scene) : scene.viewpoints[0]);
}

Status WalkMode::open(app::Shell& shell) {
  auto handle = shell.renderer().addScene(scene_);
  if (!handle) return handle.error();
  sceneHandle_ = *handle;
  return {};
}

void WalkMode::onLeave(app::Shell& shell) {
  // Nothing stays held while another mode runs: coming back, the person stands still.
  keys_.fill(false);
  mouseDx_ = mouseDy_ = 0;
  releaseCursor(shell);
}

void WalkMode::releaseCursor(app::Shell& shell) {
  if (captured_) shell.window().setCursorCaptured(false);
  captured_ = false;
  lastCursor_.reset();
}

void WalkMode::onInput(app::Shell& shell, const app::InputEvent& event) {
  std::visit(Overloaded{
                 [&](const app::KeyEvent& e) {
                   if (e.uiWantsIt && !captured_) return;  // typing into an ImGui field
                   onKey(shell, e.key, e.down);
                 },
                 [&](const app::CursorEvent& e) {
                   if (captured_ && lastCursor_) {
                     mouseDx_ += e.positionPx.x - lastCursor_->x;
                     mouseDy_ += e.positionPx.y - lastCursor_->y;
                   }
                   lastCursor_ = e.positionPx;
                 },
                 [&](const app::PointerMotionEvent& e) {
                   mouseDx_ += e.dxPx;
                   mouseDy_ += e.dyPx;
                 },
                 [&](const app::MouseButtonEvent& e) {
                   if (!e.down || e.button != GLFW_MOUSE_BUTTON_LEFT || e.uiWantsIt || captured_) return;
                   // A click into the view captures the cursor for mouse look.
                   shell.window().setCursorCaptured(true);
                   captured_ = true;
                   lastCursor_.reset();
                 },
                 [](const auto&) {}},
             event);
}

Status WalkMode::onReplayEvent(app::Shell& shell, const app::ModeEvent& event) {
  const auto* viewpoint = std::any_cast<ViewpointEvent>(&event.value);
  if (!viewpoint) return AppMode::onReplayEvent(shell, event);
  if (viewpoint->number < 1 || viewpoint->number > static_cast<int>(scene_.viewpoints.size())) {
    return makeError("viewpoint " + std::to_string(viewpoint->number) + " does not exist; the model has " +
                     std::to_string(scene_.viewpoints.size()));
  }
  goToViewpoint(viewpoint->number - 1);
  return {};
}

void WalkMode::onKey(app::Shell& shell, int key, bool down) {
  if (key < 0 || key > GLFW_KEY_LAST) return;
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
    case GLFW_KEY_F12:
      takeScreenshot(shell);
      break;
    case GLFW_KEY_ESCAPE:
      if (captured_) {
        releaseCursor(shell);
      } else if (!options_.escapeTo.empty()) {
        shell.requestMode(options_.escapeTo);
      } else if (!shell.replaying()) {
        shell.requestQuit();
      }
      break;
    default:
      break;
  }
}

// photowalk-YYYYMMDD-HHMMSS-N.png in the screenshot folder; a failure is a message,
// and the walk goes on.
void WalkMode::takeScreenshot(app::Shell& shell) {
  char name[64];
  const std::time_t now = std::time(nullptr);
  std::strftime(name, sizeof name, "photowalk-%Y%m%d-%H%M%S", std::localtime(&now));
  const std::filesystem::path path =
      options_.screenshotDir / (std::string(name) + "-" + std::to_string(++screenshotCount_) + ".png");
  const glm::ivec2 size = shell.window().framebufferSize();
  Status saved = size.x > 0 && size.y > 0
                     ? Status{}
                     : Status(makeError(path.string() + ": the window is minimised; nothing to capture"));
  if (saved) {
    auto image = *capture(shell, size.x, size.y);
    saved = image ? engine::saveImage(path, *image) : Status(image.error());
  }
  if (saved) {
    std::printf("screenshot: %s\n", path.string().c_str());
  } else {
    shell.showMessage("warning: screenshot not saved: " + saved.message());
  }
}

void WalkMode::goToViewpoint(int index) {
  Transition t;
  t.from = currentCamera();
  t.to = engine::cameraFromViewpoint(scene_.viewpoints[index]);
  t.viewpoint = index;
  transition_ = t;
  viewpoint_ = index;
}

engine::Camera WalkMode::currentCamera() const {
  const engine::Viewpoint* at = scene_.viewpoints.empty() ? nullptr : &scene_.viewpoints[viewpoint_];
  const float fov = at ? at->fieldOfViewRad : engine::kDefaultFieldOfViewRad;
  if (transition_) {
    const float u = static_cast<float>(transition_->frame) / kTransitionFrames;
    const float ease = u * u * (3 - 2 * u);
    engine::Camera c = transition_->to;
    c.position = glm::mix(transition_->from.position, transition_->to.position, ease);
    c.orientation = glm::slerp(transition_->from.orientation, transition_->to.orientation, ease);
    c.fieldOfViewRad = glm::mix(transition_->from.fieldOfViewRad, transition_->to.fieldOfViewRad, ease);
    c.intrinsics.reset();  // the glide blends fields of view; the viewpoint's lens comes on arrival
    c.nearM = avatar_.camera(fov).nearM;
    return c;
  }
  engine::Camera c = avatar_.camera(fov);
  if (at) {
    // The viewpoint's lens: a photo's exact intrinsics (principal point included) when it
    // has them. Standing where it put the eye, looking its way, the view is the
    // viewpoint's own, roll included (the avatar keeps none): at "Photo", the photo.
    c.intrinsics = at->intrinsics;
    const engine::Camera exact = engine::cameraFromViewpoint(*at);
    if (glm::vec3(avatar_.eye()) == exact.position &&
        glm::dot(engine::forwardOf(c), engine::forwardOf(exact)) > 1.0f - 1e-6f) {
      c.orientation = exact.orientation;
    }
  }
  return c;
}

void WalkMode::update(app::Shell&, double stepS) {
  if (transition_) {
    if (++transition_->frame >= kTransitionFrames) {
      avatar_.placeAt(scene_.viewpoints[transition_->viewpoint]);
      transition_.reset();
    }
    mouseDx_ = mouseDy_ = 0;
    return;
  }
  MoveInput input;
  input.forward = (keys_[GLFW_KEY_W] || keys_[GLFW_KEY_UP] ? 1 : 0) - (keys_[GLFW_KEY_S] || keys_[GLFW_KEY_DOWN] ? 1 : 0);
  input.strafe = (keys_[GLFW_KEY_D] || keys_[GLFW_KEY_RIGHT] ? 1 : 0) - (keys_[GLFW_KEY_A] || keys_[GLFW_KEY_LEFT] ? 1 : 0);
  input.run = keys_[GLFW_KEY_LEFT_SHIFT] || keys_[GLFW_KEY_RIGHT_SHIFT];
  input.lookDxPx = mouseDx_;
  input.lookDyPx = mouseDy_;
  mouseDx_ = mouseDy_ = 0;
  avatar_.step(stepS, input);
}

void WalkMode::traceRow(app::TraceRow& row) const {
  const engine::Camera c = currentCamera();
  const glm::dvec2 yp = yawPitchOf(c.orientation);
  row.add("x", c.position.x);
  row.add("y", c.position.y);
  row.add("z", c.position.z);
  row.add("yaw_deg", glm::degrees(yp.x), 4);
  row.add("pitch_deg", glm::degrees(yp.y), 4);
}

void WalkMode::drawUi(app::Shell& shell) {
  if (showOverlay_) {
    const engine::Renderer& renderer = shell.renderer();
    ImGui::SetNextWindowPos({10, 10}, ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.6f);
    ImGui::Begin("photowalk", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
    const double meanMs = shell.recentFrameMs();
    ImGui::Text("%.0f fps  %.2f ms/frame  %s", meanMs > 0 ? 1000.0 / meanMs : 0.0, meanMs, renderer.deviceName().c_str());
    // What the frame rate costs in looks (the interactive profile on a CPU device).
    ImGui::Text("%dx MSAA, %s filtering, lit per %s", renderer.msaaSamples(),
                renderer.anisotropicFiltering() ? "anisotropic" : "trilinear",
                renderer.perVertexLighting() ? "vertex" : "pixel");
    const engine::Camera c = currentCamera();
    const glm::dvec2 yp = yawPitchOf(c.orientation);
    ImGui::Text("position %.2f %.2f %.2f m  heading %.0f deg", c.position.x, c.position.y, c.position.z, glm::degrees(yp.x));
    if (!scene_.viewpoints.empty()) {
      ImGui::Text("viewpoint %d/%zu: %s", viewpoint_ + 1, scene_.viewpoints.size(),
                  scene_.viewpoints[viewpoint_].description.c_str());
    }
    if (!boundsLine_.empty()) ImGui::TextUnformatted(boundsLine_.c_str());
    ImGui::Text("headlight %s   F1: keys", headlight_ ? "on" : "off");
    ImGui::End();
  }
  if (showHelp_) {
    ImGui::Begin("Keys", &showHelp_, ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::TextUnformatted("click      capture the mouse (look around)");
    ImGui::Text("Esc        release the mouse; again: %s",
                options_.escapeTo.empty() ? "quit" : ("back to " + options_.escapeTo).c_str());
    ImGui::TextUnformatted(
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
}

engine::SceneView WalkMode::view() const {
  engine::SceneView view;
  view.scene = sceneHandle_;
  view.camera = currentCamera();
  view.settings.headlight = headlight_;
  return view;
}

app::FrameContent WalkMode::frame(app::Shell&) { return {{view()}}; }

std::optional<Result<engine::Image>> WalkMode::capture(app::Shell& shell, int width, int height) {
  return shell.renderer().renderViews({view()}, width, height);
}

}  // namespace pw::walk
