// photowalk's Vulkan renderer: draws a Scene (engine/scene/scene.h) with the VRML97
// lighting model, offscreen to an Image here, or to a window through Presenter
// (presenter.h). Vulkan 1.3 with dynamic rendering; a discrete or integrated GPU when
// there is one, else the CPU device (lavapipe), which PW_DEVICE=cpu or
// RendererOptions::forceCpu select explicitly.
//
//   auto renderer = Renderer::create({});          // Result<std::unique_ptr<Renderer>>
//   renderer.value()->setScene(scene);              // uploads meshes and textures once
//   auto image = renderer.value()->renderToImage(cameraFromViewpoint(vp), 1280, 720, {});
//
// One thread at a time: a Renderer and its Presenter are used from one thread.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "engine/scene/camera.h"
#include "engine/scene/image.h"
#include "engine/scene/scene.h"

namespace pw::engine {

// kQuality: still frames and tours. kInteractive: a window that must keep its frame
// rate; on CPU devices (lavapipe, two cores, 1280x720) it lights per vertex, not per
// pixel (each light cost about 9 ms a frame), drops anisotropic filtering (15 ms) and,
// unless msaaSamples says otherwise, multisampling (20 ms). GPUs draw the same either way.
enum class RenderProfile { kQuality, kInteractive };

struct RendererOptions {
  bool forceCpu = false;  // lavapipe even when a GPU exists (as PW_DEVICE=cpu)
  RenderProfile profile = RenderProfile::kQuality;
  // 1, 2, 4, 8...; an error when the device does not have it. 0: 4, or 1 for
  // kInteractive on a CPU device.
  int msaaSamples = 0;
  // Unset: per vertex for kInteractive on a CPU device, else per pixel. Per vertex is
  // what VRML97 browsers did (Gouraud): large faces lose the pools of point and spot lights.
  std::optional<bool> perVertexLighting;
  enum class Validation { kDefault, kOn, kOff };
  // kDefault: PW_VALIDATION=1 turns it on and PW_VALIDATION=0 off, a missing layer
  // then being an error (tests, CI); unset, on in Debug builds, where a missing layer
  // is a note. kOn: on, and a missing layer is an error (tests).
  Validation validation = Validation::kDefault;
  // Instance extensions a window needs (the caller passes GLFW's list; pw_gpu never
  // includes GLFW). With VK_KHR_surface among them the device enables VK_KHR_swapchain.
  std::vector<std::string> instanceExtensions;
};

struct FrameSettings {
  std::optional<bool> headlight;  // unset: the scene's NavigationInfo.headlight
  std::optional<glm::vec3> backgroundColor;  // sRGB-encoded like scene colours; unset: the scene's
};

// What the last frame drew (for tests and the walkthrough's statistics).
struct FrameStats {
  uint32_t drawCalls = 0;
  uint32_t culledShapes = 0;  // outside the view frustum
};

class Renderer {
 public:
  static Result<std::unique_ptr<Renderer>> create(const RendererOptions& options);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Uploads the scene's meshes, textures and lights (blocking); later frames draw it.
  // The Scene may be destroyed afterwards. On error the previous scene stays.
  // Errors name the shape or texture at fault (a texture without pixels, bad indices).
  Status setScene(const Scene& scene);

  // Draws the current scene (an empty one before setScene) from `camera` into a
  // width x height frame and reads it back: RGBA8, sRGB-encoded, opaque, rows top
  // to bottom. Sizes must be 1..the device's maximum (16384 on lavapipe) and the
  // targets must fit in 2 GiB; else an error says which limit was hit.
  Result<Image> renderToImage(const Camera& camera, int width, int height, const FrameSettings& settings = {});

  // Validation-layer messages of severity warning or error since creation. Tests
  // turn validation on and assert the count is zero.
  size_t validationMessageCount() const;
  std::vector<std::string> validationMessages() const;
  bool validationEnabled() const;
  // Ok while the layers have reported nothing (always, with validation off); else an
  // error of one line naming how many messages there were and the first. Rendering
  // commands end their work with it, so that a run with validation on exits non-zero
  // on any message. Messages from the renderer's own teardown come too late for it.
  Status validationStatus() const;

  std::string deviceName() const;
  bool isCpuDevice() const;
  int msaaSamples() const;
  bool anisotropicFiltering() const;  // for textures not cut from a photo
  bool perVertexLighting() const;
  FrameStats lastFrameStats() const;
  std::vector<std::string> notes() const;  // non-fatal remarks, e.g. "validation layer not installed"

  // Records commands with `record`, submits them on the renderer's queue and waits
  // (one-off work such as ImGui_ImplVulkan_CreateFontsTexture).
  Status submitAndWait(const std::function<void(VkCommandBuffer)>& record);

  // For window code (surface creation, ImGui's Vulkan backend); borrowed handles.
  VkInstance instance() const;
  VkPhysicalDevice physicalDevice() const;
  VkDevice device() const;
  VkQueue queue() const;
  uint32_t queueFamily() const;

  struct Impl;  // engine/gpu/renderer_impl.h; Presenter shares it
  Impl& impl() { return *impl_; }

 private:
  explicit Renderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace pw::engine
