// photowalk's Vulkan renderer: draws Scenes (engine/scene/scene.h) with the VRML97
// lighting model and 2D images (photos) as views (view.h), offscreen to an Image here,
// or to a window through Presenter (presenter.h). Vulkan 1.3 with dynamic rendering; a
// discrete or integrated GPU when there is one, else the CPU device (lavapipe), which
// PW_DEVICE=cpu or RendererOptions::forceCpu select explicitly.
//
//   auto renderer = Renderer::create({});          // Result<std::unique_ptr<Renderer>>
//   renderer.value()->setScene(scene);              // uploads meshes and textures once
//   auto image = renderer.value()->renderToImage(cameraFromViewpoint(vp), 1280, 720, {});
//
// Several scenes and images live on the GPU at once, named by handles:
//   SceneHandle model = *renderer->addScene(scene);
//   ImageHandle photo = *renderer->addImage(photoImage);      // mip chain made on the GPU
//   renderer->replaceScene(model, reducedScene);               // frames in flight keep the old one
//   presenter->drawFrame({ImageView{photo, {zoom, pan}, canvasRect},
//                         SceneView{model, orbitCamera, previewRect}}, imguiOverlay);
// setScene/renderToImage work on the default scene (defaultScene()).
//
// Uploads (addScene, replaceScene, addImage) block the calling thread for their CPU
// part only (packing the scene, copying into a staging buffer); the GPU copies and
// mip blits are submitted without waiting for them or for the GPU to go idle, and
// frames submitted afterwards see the result (one queue: submission order). So a
// replacement never stalls the frames in flight, which keep the data they draw
// alive until their fences signal. The CPU part of a scene's upload can move to a
// worker thread (stageScene), leaving the renderer's thread a swap of a few ms.
//
// One thread at a time: a Renderer and its Presenter are used from one thread, but
// for stageScene, which any thread may call.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "engine/gpu/view.h"
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

namespace gpu {
struct SceneStaging;  // gpu_scene.h
}

// The CPU half of a scene's upload (Renderer::stageScene), to be swapped in with
// Renderer::addScene or replaceScene. Move-only; it must not outlive its Renderer.
class StagedScene {
 public:
  StagedScene(StagedScene&&) noexcept;
  StagedScene& operator=(StagedScene&&) noexcept;
  ~StagedScene();

 private:
  friend class Renderer;
  explicit StagedScene(std::unique_ptr<gpu::SceneStaging> staging);
  std::unique_ptr<gpu::SceneStaging> staging_;
};

// What the last frame drew, summed over its scene views (for tests and the
// walkthrough's statistics).
struct FrameStats {
  uint32_t drawCalls = 0;
  uint32_t culledShapes = 0;  // outside the view frustum
  uint32_t views = 0;         // scene and image views drawn (not those wholly outside the frame)
};

class Renderer {
 public:
  static Result<std::unique_ptr<Renderer>> create(const RendererOptions& options);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Uploads the scene's meshes, textures and lights as the default scene (see the
  // top of this file for what blocks); later frames draw it. The Scene may be
  // destroyed afterwards. On error the previous scene stays. Errors name the shape or
  // texture at fault (a texture without pixels, bad indices).
  Status setScene(const Scene& scene);

  // Draws the default scene (an empty one before setScene) from `camera` into a
  // width x height frame and reads it back: RGBA8, sRGB-encoded, opaque, rows top
  // to bottom. Sizes must be 1..the device's maximum (16384 on lavapipe) and the
  // targets must fit in 2 GiB; else an error says which limit was hit.
  Result<Image> renderToImage(const Camera& camera, int width, int height, const FrameSettings& settings = {});

  // Scenes by handle. addScene uploads another scene beside the ones there are;
  // replaceScene uploads `scene` in the place of `handle`'s (a reduced model while a
  // corner is dragged, the full one after): frames in flight finish with the old one,
  // later frames draw the new one, and on error the old one stays. removeScene frees
  // the scene once no frame in flight uses it. Errors as setScene's, or an unknown
  // handle; the default scene cannot be removed.
  Result<SceneHandle> addScene(const Scene& scene);
  Status replaceScene(SceneHandle handle, const Scene& scene);
  Status removeScene(SceneHandle handle);
  SceneHandle defaultScene() const;

  // An upload in two halves, so that its slow part leaves the renderer's thread:
  // stageScene does the CPU work (packing the scene, copying meshes and textures into a
  // staging buffer: 33 ms for a scene with a 12-megapixel texture, bench/views_bench) and,
  // alone among the Renderer's functions, may run on any thread, also while this one
  // draws. addScene/replaceScene then make the GPU objects and submit the copies (a few
  // ms, never waiting for the GPU). Errors as setScene's (from stageScene), or an
  // unknown handle.
  Result<StagedScene> stageScene(const Scene& scene) const;
  Result<SceneHandle> addScene(StagedScene staged);
  Status replaceScene(SceneHandle handle, StagedScene staged);

  // A 2D image for ImageViews (a photo, up to the device's image size limit: 16384 on
  // lavapipe): RGBA8, sRGB-encoded as engine::Image is, stored with a full mip chain
  // made on the GPU (vkCmdBlitImage, filtered in linear light). Its pixels are copied;
  // `image` may be destroyed afterwards.
  Result<ImageHandle> addImage(const Image& image);
  // A width x height texture that SceneViews draw into (SceneView::target) and
  // ImageViews show, at the renderer's MSAA; transparent black until drawn into. One
  // mip level. To resize it, add another and remove this one.
  Result<ImageHandle> addRenderTarget(int width, int height);
  // Frees the image (photo or render target) once no frame in flight uses it.
  Status removeImage(ImageHandle handle);
  // An image's size in pixels; an error for an unknown handle.
  Result<glm::ivec2> imageSize(ImageHandle handle) const;
  // Reads an image back (level 0; a render target as its last frame left it), waiting
  // for the GPU work queued before: for tests and screenshots, not for every frame.
  Result<Image> readImage(ImageHandle handle);

  // Draws `views` in order into a width x height frame (pixels no view covers are
  // `clearColor`, sRGB-encoded, opaque) and reads it back as renderToImage does. The
  // views' render targets are updated as in a presented frame. Errors: as
  // renderToImage's, an unknown handle, a camera that cannot project.
  Result<Image> renderViews(const std::vector<View>& views, int width, int height,
                            const glm::vec3& clearColor = glm::vec3(0.0f));

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
