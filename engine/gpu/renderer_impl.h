// The Renderer's state, shared with Presenter (internal to pw_gpu).
#pragma once

#include <memory>
#include <optional>

#include "engine/gpu/context.h"
#include "engine/gpu/frame_slot.h"
#include "engine/gpu/gpu_scene.h"
#include "engine/gpu/pipelines.h"
#include "engine/gpu/renderer.h"
#include "engine/gpu/resources.h"
#include "engine/gpu/scene_pass.h"

namespace pw::engine {

// Offscreen colour (multisampled), resolve and depth targets plus the read-back
// buffer, for one frame size; remade when the size changes.
struct OffscreenTargets {
  gpu::GpuImage color;
  std::optional<gpu::GpuImage> resolve;  // when multisampled
  gpu::GpuImage depth;
  gpu::Buffer readback;
  uint32_t width = 0;
  uint32_t height = 0;
};

// Member order is teardown order, reversed: everything goes before the Context.
struct Renderer::Impl {
  std::unique_ptr<gpu::Context> context;
  std::unique_ptr<gpu::PipelineLibrary> pipelines;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  std::shared_ptr<const gpu::GpuScene> scene;  // frames in flight hold their own reference
  gpu::OwnedDescriptorPool framePool;
  gpu::FrameSlot frame;  // offscreen frames are synchronous: one slot
  std::optional<OffscreenTargets> offscreen;
  gpu::DrawScratch scratch;
  FrameStats stats;
};

// Image sizes and the render-target memory budget shared by offscreen frames and the
// Presenter: an error naming the limit when width x height cannot be drawn.
Status checkFrameSize(const gpu::Context& context, int width, int height, VkSampleCountFlagBits samples);

// A camera whose numbers would make NaN matrices is refused before drawing.
Status checkCamera(const Camera& camera);

}  // namespace pw::engine
