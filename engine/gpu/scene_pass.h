// Recording the scene into colour + depth targets with dynamic rendering: frame
// uniforms, per-shape frustum culling, opaque draws in pipeline/texture order, then
// transparent draws back to front. Shared by offscreen frames and the Presenter.
#pragma once

#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "engine/gpu/frame_slot.h"
#include "engine/gpu/gpu_scene.h"
#include "engine/gpu/pipelines.h"
#include "engine/gpu/renderer.h"
#include "engine/scene/camera.h"

namespace pw::engine::gpu {

struct SceneTargets {
  VkImage color = VK_NULL_HANDLE;  // drawn into; multisampled when samples > 1
  VkImageView colorView = VK_NULL_HANDLE;
  VkImage resolve = VK_NULL_HANDLE;  // single-sampled result when samples > 1, else null
  VkImageView resolveView = VK_NULL_HANDLE;
  VkImage depth = VK_NULL_HANDLE;
  VkImageView depthView = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_R8G8B8A8_SRGB;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  VkExtent2D extent{0, 0};
  bool encodeSrgbInShader = false;  // a UNORM target: the clear colour is encoded here (pipelines do it by format)
};

// Reused between frames so that recording allocates nothing once warmed up.
struct DrawScratch {
  std::vector<std::pair<float, const DrawItem*>> transparent;
};

// Records the pass into slot.commands (already begun) and writes slot.uniforms. The
// targets' previous contents are discarded. Afterwards the result (resolve, or colour
// when single-sampled) is in COLOR_ATTACHMENT_OPTIMAL, written at the colour-output stage.
Status recordScenePass(VkCommandBuffer cmd, PipelineLibrary& pipelines, const GpuScene& scene, FrameSlot& slot,
                       const SceneTargets& targets, const Camera& camera, const FrameSettings& settings,
                       DrawScratch& scratch, FrameStats& stats);

}  // namespace pw::engine::gpu
