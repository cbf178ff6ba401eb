// Recording a scene view (view.h) into colour + depth targets with dynamic rendering:
// the view's uniforms, per-shape frustum culling, opaque draws in pipeline/texture
// order, then transparent draws back to front. Shared by offscreen frames, render
// targets and the Presenter (through view_recorder.h).
#pragma once

#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "engine/gpu/frame_slot.h"
#include "engine/gpu/gpu_scene.h"
#include "engine/gpu/pipelines.h"
#include "engine/gpu/renderer.h"
#include "engine/gpu/view.h"
#include "engine/scene/camera.h"

namespace pw::engine::gpu {

struct SceneTargets {
  VkImage color = VK_NULL_HANDLE;  // drawn into; multisampled when samples > 1
  VkImageView colorView = VK_NULL_HANDLE;
  VkImage resolve = VK_NULL_HANDLE;  // the single-sampled result when samples > 1, else null
  VkImageView resolveView = VK_NULL_HANDLE;
  VkImage depth = VK_NULL_HANDLE;
  VkImageView depthView = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_R8G8B8A8_SRGB;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  VkExtent2D extent{0, 0};
  bool encodeSrgbInShader = false;  // a UNORM target: the clear colour is encoded here (pipelines do it by format)
  // The single-sampled result starts UNDEFINED (its contents discarded, last used at
  // the colour-output or copy stage) and is taken to COLOR_ATTACHMENT_OPTIMAL in the
  // view's own barrier: a frame whose first view covers it all needs no other.
  bool discardResult = false;
};

// Reused between frames so that recording allocates nothing once warmed up.
struct DrawScratch {
  std::vector<std::pair<float, const DrawItem*>> transparent;
};

// Where a view draws: `rect` is its whole rectangle (the viewport: the projection
// is the rectangle's), `area` the part of it inside the target (render area and
// scissor; not empty).
struct ViewArea {
  PixelRect rect;
  VkRect2D area{};
};

// Records the view into `cmd` (begun) and writes its uniforms to slot view
// `viewIndex` (reserved). Unless targets.discardResult, the single-sampled result
// (resolve, or colour when single-sampled) must be in COLOR_ATTACHMENT_OPTIMAL with
// earlier writes to it ordered before (the caller's barriers); the depth and
// multisampled colour images' contents are discarded (each view clears its area).
// Within `area` the result is cleared to the background and drawn; outside it is
// kept. Adds to `stats`.
Status recordSceneView(VkCommandBuffer cmd, PipelineLibrary& pipelines, const GpuScene& scene, FrameSlot& slot,
                       uint32_t viewIndex, const SceneTargets& targets, const ViewArea& where, const Camera& camera,
                       const FrameSettings& settings, DrawScratch& scratch, FrameStats& stats);

}  // namespace pw::engine::gpu
