// The Renderer's state, shared with Presenter (internal to pw_gpu).
#pragma once

#include <map>
#include <memory>
#include <optional>

#include "engine/gpu/context.h"
#include "engine/gpu/frame_slot.h"
#include "engine/gpu/gpu_scene.h"
#include "engine/gpu/image_pass.h"
#include "engine/gpu/pipelines.h"
#include "engine/gpu/renderer.h"
#include "engine/gpu/resources.h"
#include "engine/gpu/scene_pass.h"
#include "engine/gpu/upload_queue.h"
#include "engine/gpu/view_image.h"
#include "engine/gpu/view_recorder.h"

namespace pw::engine {

// Offscreen frame targets plus the read-back buffer, for one frame size; remade when
// the size changes.
struct OffscreenTargets {
  gpu::GpuImage color;                // single-sampled: what views draw into and is read back
  std::optional<gpu::GpuImage> msaa;  // multisampled colour for scene views, resolved into `color`
  gpu::GpuImage depth;
  gpu::Buffer readback;
  uint32_t width = 0;
  uint32_t height = 0;
};

// Member order is teardown order, reversed: everything goes before the Context.
struct Renderer::Impl {
  std::unique_ptr<gpu::Context> context;
  std::unique_ptr<gpu::PipelineLibrary> pipelines;
  std::unique_ptr<gpu::ImagePipelines> imagePipelines;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  // What the handles name, by id; frames in flight and running uploads hold their own
  // references, so replacing or removing one never frees what the GPU still reads.
  std::map<uint64_t, std::shared_ptr<const gpu::GpuScene>> scenes;
  std::map<uint64_t, std::shared_ptr<const gpu::ViewImage>> images;
  uint64_t nextHandle = 1;
  SceneHandle defaultScene;  // setScene's
  std::unique_ptr<gpu::UploadQueue> uploads;
  gpu::OwnedDescriptorPool framePool;
  gpu::FrameSlot frame;  // offscreen frames are synchronous: one slot
  std::optional<OffscreenTargets> offscreen;
  ViewRecorder recorder;  // offscreen frames'
  FrameStats stats;
};

// Image sizes and the render-target memory budget shared by offscreen frames and the
// Presenter: an error naming the limit when width x height cannot be drawn.
Status checkFrameSize(const gpu::Context& context, int width, int height, VkSampleCountFlagBits samples);

// A camera whose numbers would make NaN matrices is refused before drawing.
Status checkCamera(const Camera& camera);

}  // namespace pw::engine
